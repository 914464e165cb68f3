"""Typed errors of crankdyn: the one hierarchy that every package raises and the CLI catches.

Every error is a :class:`CrankdynError`, itself a :class:`ValueError` subclass, so a caller may catch the built-in
generically.  A :class:`SpecError` carries *all* the problems found in one spec at once,
each naming the key path, the bad value and what would be valid; the CLI prints them one
per line and exits with status 2.

Every message is a text key of the ``errors`` catalogue with its fields (:class:`Text`):
a :class:`Problem` carries one (``Problem(key, Text("errors.…", {...}))`` or
:meth:`Problem.keyed`), and so may any other error (``OutputError(Text(...))``,
:meth:`CrankdynError.keyed`).  :meth:`CrankdynError.lines` renders the message in the
run's language (``lines("ru")``), English by default; ``str(error)`` is always English.
A test (``tests/test_error_language.py``) scans the code for an error written in words.
"""
from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["Problem", "Text", "SpecError", "AssemblyError", "OutputError", "CrankdynError",
           "os_reason"]

#: ``errno`` names whose reason the ``errors`` catalogue words (``errors.os.EACCES`` …).
OS_REASONS = ("EACCES", "EPERM", "ENOENT", "ENOTDIR", "EISDIR", "EEXIST", "ENOSPC",
              "EROFS", "ENAMETOOLONG", "ENOTEMPTY", "EBUSY", "EXDEV", "EDQUOT", "ELOOP")


def os_reason(exc: BaseException):
    """The reason of a file-system error as a keyed :class:`Text` for the common ``errno``
    values (so that it is given in the run's language), else the system's own words."""
    import errno

    code = errno.errorcode.get(getattr(exc, "errno", None))
    if code in OS_REASONS:
        return Text(f"errors.os.{code}")
    return getattr(exc, "strerror", None) or str(exc)


class CrankdynError(ValueError):
    """Base class of every error crankdyn raises on bad input.

    The message may be a keyed :class:`Text` of the ``errors`` catalogue
    (``OutputError(Text("errors.output.exists", path=p))``): ``str(error)`` is then its
    English text and :meth:`lines` gives it in the run's language."""

    def __init__(self, *args):
        self.text = args[0] if args and isinstance(args[0], Text) else None
        if self.text is not None:
            args = (self.text.render("en"),) + args[1:]
        super().__init__(*args)

    @classmethod
    def keyed(cls, text_key: str, /, *args, **fields):
        """The error told by the catalogue text ``text_key`` with ``fields`` (``args``
        follow the message, e.g. the crank angles of an :class:`AssemblyError`)."""
        return cls(Text(text_key, fields), *args)

    def lines(self, lang: str = "en") -> list[str]:
        """The message as a list of one-line problems (for the CLI), in ``lang`` where
        it is a keyed text (else its English words)."""
        msg = self.text.render(lang) if self.text is not None else str(self)
        return [line for line in msg.splitlines() if line.strip()]


@dataclass(frozen=True)
class Text:
    """A keyed text of the catalogues (``crankbase/locale/<lang>/<area>.po``) with its
    fields, rendered in a language on demand; a field may itself be a :class:`Text`
    (``valid=Text("errors.bound.gt", bound=0)``) or a tuple of them (joined by ``; ``)."""

    key: str
    fields: dict = field(default_factory=dict, compare=False, hash=False)

    def render(self, lang: str = "en") -> str:
        from .texts import texts

        t = texts(lang)
        return t(self.key, **{k: _render(v, lang) for k, v in self.fields.items()})

    def __str__(self) -> str:
        return self.render("en")


def _render(value, lang):
    if isinstance(value, Text):
        return value.render(lang)
    if isinstance(value, list) and value and all(isinstance(v, Text) for v in value):
        return "; ".join(v.render(lang) for v in value)
    return value


@dataclass(frozen=True)
class Problem:
    """One problem in a spec: where (dotted key path), what was given, what is valid.

    ``key`` is a key path or option name, or a keyed :class:`Text` where it holds words
    (``row 3 (v1): engine.bore_mm``).

    ``message`` is the English text; ``text``, when given, is the same problem as a
    keyed :class:`Text` of the ``errors`` catalogue, so that :meth:`render` can give it in
    another language (``message`` is then derived from it when left empty)."""

    key: str
    message: str = ""
    text: Text | None = field(default=None, compare=False)

    def __post_init__(self):
        if isinstance(self.message, Text):     # Problem(key, Text(...))
            object.__setattr__(self, "text", self.message)
            object.__setattr__(self, "message", "")
        if not self.message and self.text is not None:
            object.__setattr__(self, "message", self.text.render("en"))

    @classmethod
    def keyed(cls, key: str, text_key: str, /, **fields) -> "Problem":
        """A problem of ``key`` told by the catalogue text ``text_key`` with ``fields``."""
        return cls(key, text=Text(text_key, fields))

    def render(self, lang: str = "en") -> str:
        """The problem in ``lang`` (English, or a problem without a text key: its
        ``message``)."""
        from .texts import REFERENCE

        # the message is written in the reference language (English)
        msg = self.message if self.text is None or lang == REFERENCE \
            else self.text.render(lang)
        key = self.key.render(lang) if isinstance(self.key, Text) else self.key
        return f"{key}: {msg}" if key else msg

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
        if isinstance(problems, (str, Problem, Text)):
            problems = [problems]
        self.problems = [p if isinstance(p, Problem)
                         else Problem("", p) if isinstance(p, Text)
                         else Problem("", str(p)) for p in problems]
        self.text = None
        ValueError.__init__(self, "\n".join(str(p) for p in self.problems))

    def lines(self, lang: str = "en") -> list[str]:
        """One line per problem, in ``lang`` where the problem has a text key (else its
        English message)."""
        return [p.render(lang) for p in self.problems]

    def renamed(self, names: dict):
        """The same error with the problems' keys renamed by ``names`` (``{"positions":
        "--plans"}``): a command line names its options where the library names its
        arguments (the library never names a command-line option)."""
        new = type(self).__new__(type(self))
        SpecError.__init__(new, [Problem(names.get(p.key, p.key), p.message, p.text)
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
        Why, in English words (:meth:`lines` gives it in the run's language when it is a
        keyed :class:`Text`).
    """

    def __init__(self, reason, crank_angles_deg=()):
        self.crank_angles_deg = [float(a) for a in crank_angles_deg]
        super().__init__(reason)
        self.reason = str(self.args[0]) if self.args else ""


class OutputError(CrankdynError):
    """An output cannot be written safely: it would overwrite an input, holds a non-finite
    number, or the file system refused it (the path and the reason are in the message)."""
