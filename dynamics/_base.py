"""The project's error and spec-validation layer (:mod:`crankbase`), imported in this one
place for the whole :mod:`dynamics` package."""
from crankbase.errors import CrankdynError, Problem, SpecError  # noqa: F401
from crankbase.validation import Checker, read_toml  # noqa: F401

__all__ = ["CrankdynError", "Problem", "SpecError", "Checker", "read_toml",
           "MotionError"]


class MotionError(SpecError):
    """The machine cannot run the asked cycle: the drive cannot sustain it (ω reaches
    zero), or a motor stalls.  A :class:`SpecError` so the CLI reports it like bad input."""
