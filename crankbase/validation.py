"""Spec validation helpers shared by every spec loader (linkage, engine, synthesis).

A :class:`Checker` walks a nested dict read from TOML and collects *all* problems, each
with its dotted key path, the bad value and what is valid; :meth:`Checker.raise_if_any`
raises one :class:`~crankbase.errors.SpecError` holding them.  Unknown keys are problems.
"""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

from .errors import Problem, SpecError

__all__ = ["Checker", "read_toml"]


def read_toml(path_or_dict):
    """Return ``(dict, base_dir)`` from a TOML path or an already-parsed dict.

    ``base_dir`` is the folder of the file (relative paths inside a spec are resolved
    against it), or ``None`` for a dict.  A missing file or a TOML syntax error is a
    :class:`SpecError` naming the file.
    """
    if isinstance(path_or_dict, dict):
        return path_or_dict, None
    path = Path(path_or_dict)
    if not path.is_file():
        raise SpecError(Problem(str(path), "spec file does not exist"))
    try:
        with open(path, "rb") as f:
            return tomllib.load(f), path.resolve().parent
    except tomllib.TOMLDecodeError as exc:
        raise SpecError(Problem(str(path), f"not valid TOML: {exc}")) from None
    except UnicodeDecodeError as exc:
        raise SpecError(Problem(str(path), f"not UTF-8 text: {exc}")) from None


def _join(path, key):
    return f"{path}.{key}" if path else str(key)


_MISSING = object()


class Checker:
    """Collects spec problems; every getter returns a usable value (or None) and records
    a :class:`Problem` when the input is bad, so all problems are reported at once."""

    def __init__(self):
        self.problems: list[Problem] = []

    # -- recording
    def add(self, key: str, message: str) -> None:
        self.problems.append(Problem(key, message))

    def raise_if_any(self) -> None:
        if self.problems:
            raise SpecError(self.problems)

    # -- structure
    def table(self, data, key, path="", required=True):
        """A sub-table (dict); returns {} when missing (recording a problem if required)."""
        value = data.get(key, _MISSING) if isinstance(data, dict) else _MISSING
        full = _join(path, key)
        if value is _MISSING:
            if required:
                self.add(full, "missing (a table is required)")
            return {}
        if not isinstance(value, dict):
            self.add(full, f"must be a table, got {value!r}")
            return {}
        return value

    def unknown(self, data, allowed, path="") -> None:
        """Record every key of ``data`` not in ``allowed``."""
        if not isinstance(data, dict):
            return
        allowed = list(allowed)
        for key in data:
            if key not in allowed:
                self.add(_join(path, key),
                         f"unknown key; valid keys here: {', '.join(allowed)}")

    def _lookup(self, data, key, path, required, wanted):
        """``(full key path, value)``; value is ``_MISSING`` when absent (a problem is
        recorded if the key is required, naming what is ``wanted``)."""
        full = _join(path, key)
        value = data.get(key, _MISSING) if isinstance(data, dict) else _MISSING
        if value is _MISSING and required:
            self.add(full, f"missing; {wanted} is required")
        return full, value

    # -- scalars
    def number(self, data, key, path="", *, required=True, default=None,
               gt=None, ge=None, lt=None, le=None, integer=False, what=""):
        """A finite real number within the given bounds."""
        full, value = self._lookup(data, key, path, required, what or "a number")
        if value is _MISSING:
            return default
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.add(full, f"must be a number, got {value!r}")
            return default
        value = float(value)
        if not math.isfinite(value):
            self.add(full, f"must be finite, got {value!r}")
            return default
        if integer and value != int(value):
            self.add(full, f"must be a whole number, got {value!r}")
            return default
        checks = [(gt, ">", lambda b: value > b), (ge, ">=", lambda b: value >= b),
                  (lt, "<", lambda b: value < b), (le, "<=", lambda b: value <= b)]
        given = [(b, op, ok) for b, op, ok in checks if b is not None]
        if not all(ok(b) for b, _, ok in given):
            valid = " and ".join(f"{op} {b:g}" for b, op, _ in given)
            self.add(full, f"got {value:g}; must be {valid}")
            return default
        return int(value) if integer else value

    def choice(self, data, key, choices, path="", *, required=True, default=None):
        """One of a fixed set of values."""
        full, value = self._lookup(data, key, path, required,
                                   f"one of {', '.join(map(repr, choices))}")
        if value is _MISSING:
            return default
        bool_mismatch = isinstance(value, bool) and not any(isinstance(c, bool) for c in choices)
        if bool_mismatch or value not in choices:
            self.add(full, f"got {value!r}; valid: {', '.join(map(repr, choices))}")
            return default
        return value

    def string(self, data, key, path="", *, required=True, default=None):
        full, value = self._lookup(data, key, path, required, "a string")
        if value is _MISSING:
            return default
        if not isinstance(value, str):
            self.add(full, f"must be a string, got {value!r}")
            return default
        return value

    def numbers(self, data, key, path="", *, required=True, default=None, length=None,
                min_length=None, gt=None, ge=None):
        """A list of finite numbers (fixed ``length`` if given)."""
        full, value = self._lookup(data, key, path, required, "a list of numbers")
        if value is _MISSING:
            return default
        if not isinstance(value, (list, tuple)):
            self.add(full, f"must be a list of numbers, got {value!r}")
            return default
        out, ok = [], True
        for i, item in enumerate(value):
            if isinstance(item, bool) or not isinstance(item, (int, float)) \
                    or not math.isfinite(float(item)):
                self.add(f"{full}[{i}]", f"must be a finite number, got {item!r}")
                ok = False
                continue
            item = float(item)
            if (gt is not None and not item > gt) or (ge is not None and not item >= ge):
                bound = f"> {gt:g}" if gt is not None else f">= {ge:g}"
                self.add(f"{full}[{i}]", f"got {item:g}; must be {bound}")
                ok = False
            out.append(item)
        if length is not None and len(value) != length:
            self.add(full, f"must have exactly {length} numbers, got {len(value)}")
            ok = False
        if min_length is not None and len(value) < min_length:
            self.add(full, f"needs at least {min_length} numbers, got {len(value)}")
            ok = False
        return out if ok else default
