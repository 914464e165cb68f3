"""The errors of :mod:`plans`: part of the one hierarchy of :mod:`crankbase.errors`."""
from __future__ import annotations

from crankbase.errors import CrankdynError, Problem, SpecError, Text  # noqa: F401

__all__ = ["PlanError", "SpecError", "Problem", "Text", "CrankdynError"]


class PlanError(SpecError):
    """The plans cannot be built as asked (statics, an unknown position, a bad scale, a bad
    measurements file).  A :class:`~crankbase.errors.SpecError`, hence a ``ValueError``; each
    problem names the option or key, the bad value and what is valid."""
