"""Typed errors of crankdyn: the one hierarchy that every package raises and the CLI catches.

Every error is a :class:`CrankdynError`, itself a :class:`ValueError` subclass, so a caller may catch the built-in
generically.  A :class:`SpecError` carries *all* the problems found in one spec at once,
each naming the key path, the bad value and what would be valid; the CLI prints them one
per line and exits with status 2.
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Problem", "SpecError", "AssemblyError", "OutputError", "CrankdynError"]


class CrankdynError(ValueError):
    """Base class of every error crankdyn raises on bad input."""

    def lines(self) -> list[str]:
        """The message as a list of one-line problems (for the CLI)."""
        return [line for line in str(self).splitlines() if line.strip()]


@dataclass(frozen=True)
class Problem:
    """One problem in a spec: where (dotted key path), what was given, what is valid."""

    key: str
    message: str

    def __str__(self) -> str:
        return f"{self.key}: {self.message}" if self.key else self.message


class SpecError(CrankdynError):
    """A spec (file, dict or argument) is invalid.

    Parameters
    ----------
    problems : list of Problem or str
        Every problem found; a plain string is taken as a problem without a key path.
    """

    def __init__(self, problems):
        if isinstance(problems, (str, Problem)):
            problems = [problems]
        self.problems = [p if isinstance(p, Problem) else Problem("", str(p)) for p in problems]
        super().__init__("\n".join(str(p) for p in self.problems))

    def lines(self) -> list[str]:
        return [str(p) for p in self.problems]

    def renamed(self, names: dict):
        """The same error with the problems' keys renamed by ``names`` (``{"positions":
        "--plans"}``): a command line names its options where the library names its
        arguments (the library never names a command-line option)."""
        new = type(self).__new__(type(self))
        SpecError.__init__(new, [Problem(names.get(p.key, p.key), p.message)
                                 for p in self.problems])
        return new


class AssemblyError(CrankdynError):
    """The linkage cannot be assembled, or its crank cannot turn fully.

    Attributes
    ----------
    crank_angles_deg : list of float
        Crank angles (absolute, degrees, counter-clockwise from +x) where assembly fails,
        or the ends of the intervals where it does.
    reason : str
        Why, in words.
    """

    def __init__(self, reason: str, crank_angles_deg=()):
        self.reason = reason
        self.crank_angles_deg = [float(a) for a in crank_angles_deg]
        super().__init__(reason)


class OutputError(CrankdynError):
    """An output cannot be written safely: it would overwrite an input, holds a non-finite
    number, or the file system refused it (the path and the reason are in the message)."""
