"""The one place where :mod:`plans` imports the project's error and output helpers.

The base layer is moving to the package ``crankbase`` (``crankbase.errors``); only the
import lines below change at that merge.
"""
from __future__ import annotations

from linkage.errors import CrankdynError, Problem, SpecError  # noqa: F401

__all__ = ["PlanError", "SpecError", "Problem", "CrankdynError"]


class PlanError(SpecError):
    """The plans cannot be built as asked (statics, an unknown position, a bad scale, a bad
    measurements file).  A :class:`~linkage.errors.SpecError`, hence a ``ValueError``; each
    problem names the option or key, the bad value and what is valid."""
