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

__all__ = ["Checker", "read_toml", "name_problem", "rows_problem", "angles_argument",
           "step_argument", "magnitude_problem",
           "MAX_NAME_CHARS", "MAX_NAME_BYTES", "MAX_ROWS", "MIN_MAGNITUDE", "MAX_MAGNITUDE"]

#: Longest accepted name of an engine or mechanism [characters]: the name heads plot
#: titles and report sheets, which stay on one line up to about this length.
MAX_NAME_CHARS = 64
#: Longest accepted name in UTF-8 bytes: the workbook is called ``<name>.xlsx`` and is
#: written through a temporary file ``.<name>.<random>.tmp.xlsx``; 160 bytes keep that
#: below the 255-byte file-name limit of common file systems (ext4, XFS, btrfs, NTFS).
MAX_NAME_BYTES = 160


def name_problem(value) -> str | None:
    """Why ``value`` cannot be a name (of an engine, a mechanism), or None if it can.

    A name is text of 1 to :data:`MAX_NAME_CHARS` characters and at most
    :data:`MAX_NAME_BYTES` bytes in UTF-8, without control characters (tab, newline, ...,
    which neither a file name nor an Excel cell can hold), line separators or unpaired
    surrogates.
    """
    import unicodedata

    if not isinstance(value, str):
        return f"must be a string, got {value!r}"
    if not value.strip():
        return "must not be empty"
    bad = [ch for ch in value if unicodedata.category(ch) in ("Cc", "Cs", "Zl", "Zp")]
    if bad:
        return (f"contains the control character U+{ord(bad[0]):04X} at position "
                f"{value.index(bad[0]) + 1}; a name is one line of printable text")
    if len(value) > MAX_NAME_CHARS:
        return f"has {len(value)} characters; at most {MAX_NAME_CHARS} are allowed"
    size = len(value.encode("utf-8"))
    if size > MAX_NAME_BYTES:
        return f"is {size} bytes in UTF-8; at most {MAX_NAME_BYTES} are allowed"
    return None


def read_toml(path_or_dict):
    """Return ``(dict, base_dir)`` from a TOML path or an already-parsed dict.

    ``base_dir`` is the folder of the file (relative paths inside a spec are resolved
    against it), or ``None`` for a dict.  A missing or unreadable file, a TOML syntax
    error, nesting too deep for the parser, or an argument that is neither a path nor a
    dict is a :class:`SpecError` naming the file (or the argument).
    """
    import os

    if isinstance(path_or_dict, dict):
        return path_or_dict, None
    if not isinstance(path_or_dict, (str, os.PathLike)) or str(path_or_dict) == "":
        raise SpecError(Problem("spec", f"expected a TOML file path or a dict, got "
                                        f"{path_or_dict!r:.60}"))
    path = Path(path_or_dict)
    try:
        if not path.is_file():
            raise SpecError(Problem(str(path), "spec file does not exist"))
        if path.stat().st_size > MAX_SPEC_BYTES:
            raise SpecError(Problem(str(path), f"spec file has {path.stat().st_size:,} "
                                               f"bytes; at most {MAX_SPEC_BYTES:,} are read"))
        with open(path, "rb") as f:
            return tomllib.load(f), path.resolve().parent
    except tomllib.TOMLDecodeError as exc:
        raise SpecError(Problem(str(path), f"not valid TOML: {exc}")) from None
    except UnicodeDecodeError as exc:
        raise SpecError(Problem(str(path), f"not UTF-8 text: {exc}")) from None
    except RecursionError:
        raise SpecError(Problem(str(path), "arrays or tables nested too deeply to read"))\
            from None
    except OSError as exc:
        raise SpecError(Problem(str(path), f"cannot read: {exc.strerror or exc}")) from None


#: Largest spec file read [bytes]: a spec is a page of keys; 16 MB still holds an explicit
#: angle list of MAX_ROWS numbers with room to spare.
MAX_SPEC_BYTES = 16 * 1024 * 1024

#: Most table rows a spec or a command-line option may ask for (crank positions, angles
#: of a table or of a full-turn sweep).  A report writes every row to CSV and to an Excel
#: sheet; at ~120 columns (the linkage course tables) that is ~100 MB of workbook and a
#: minute or two of writing at this limit.  Larger sweeps: the Python API (arrays of
#: angles passed to ``analyze`` / ``force_table`` are not limited).
MAX_ROWS = 100_000

#: Every number of a spec has a magnitude of at most MAX_MAGNITUDE, and a number the
#: models divide by (a length, a ratio, a pressure) one of at least MIN_MAGNITUDE: the
#: models multiply at most about six inputs (m·ω²·L·length for a moment), so results stay
#: within 1e±72, far inside the float range (1e±308): nothing overflows to inf, and
#: nothing that is divided by underflows to 0.  Physical bounds of single keys are tighter.
MIN_MAGNITUDE = 1e-12
MAX_MAGNITUDE = 1e12


def rows_problem(rows: float, key: str) -> Problem | None:
    """A :class:`Problem` naming ``key`` when ``rows`` (a float, possibly huge) exceeds
    :data:`MAX_ROWS`, else None."""
    if rows <= MAX_ROWS:
        return None
    shown = f"{rows:,.0f}" if rows < 1e15 else f"{rows:.3g}" if rows < math.inf \
        else "more than 1e308"
    return Problem(key, f"would make {shown} rows; at most {MAX_ROWS:,} are allowed")


def step_argument(value, key: str, span: float, rows_span: float | None = None,
                  error=SpecError) -> float:
    """A step argument of a public function [deg]: a real number with
    0 < step <= ``span`` that makes at most :data:`MAX_ROWS` rows over ``rows_span``
    (default ``span``); else ``error`` (a :class:`SpecError` class) naming ``key``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(float(value)) or not 0 < value <= span:
        raise error(Problem(key, f"got {value!r:.40}; must be a number > 0 and "
                                     f"<= {span:g}"))
    too_many = rows_problem((rows_span or span) / float(value) + 1, key)
    if too_many:
        raise error(too_many)
    return float(value)


def angles_argument(value, key: str, *, max_abs: float = 1e6, error=SpecError):
    """An angle argument of a public function as a 1-D float array.

    A scalar becomes one row.  Refused (:class:`SpecError` naming ``key``): complex or
    non-numeric values, more than one dimension, an empty list, non-finite values, and
    magnitudes above ``max_abs`` (where a double no longer resolves a fraction of a
    degree... 1e6° keeps ~1e-10° resolution).  ``error`` is the :class:`SpecError`
    subclass raised (a package's own, e.g. the engine's).
    """
    import numpy as np

    try:
        arr = np.asarray(value)
    except (TypeError, ValueError) as exc:           # ragged nested lists
        raise error(Problem(key, f"must be a number or a 1-D list of numbers: {exc}"))\
            from None
    if arr.dtype.kind == "c":
        raise error(Problem(key, "must be real numbers, got complex values"))
    if arr.dtype.kind not in "biuf":
        try:
            if arr.dtype.kind == "b" or any(v is None or isinstance(v, (bool, complex, str,
                                                                          bytes))
                                            for v in arr.ravel().tolist()):
                raise TypeError
            arr = arr.astype(float)
        except (TypeError, ValueError):
            raise error(Problem(key, f"must be real numbers, got {value!r:.60}")) from None
    if arr.dtype.kind == "b":
        raise error(Problem(key, "must be real numbers, got booleans"))
    arr = np.atleast_1d(arr.astype(float))
    if arr.ndim != 1:
        raise error(Problem(key, f"must be one number or a 1-D list, got an array of "
                                     f"shape {arr.shape}"))
    if arr.size == 0:
        raise error(Problem(key, "needs at least one angle"))
    bad = np.flatnonzero(~np.isfinite(arr) | (np.abs(arr) > max_abs))
    if bad.size:
        i = int(bad[0])
        more = f" (and {bad.size - 1} more)" if bad.size > 1 else ""
        raise error(Problem(f"{key}[{i}]", f"got {float(arr[i])!r}; every angle must be "
                                               f"finite, |angle| <= {max_abs:g}{more}"))
    return arr


#: At most this many bad items of one list are reported one by one (then a count).
MAX_ITEM_PROBLEMS = 10


def magnitude_problem(value) -> str | None:
    """Why a number of a spec is refused (not finite, or outside the magnitudes the models
    keep finite), or None."""
    try:
        x = float(value)
    except OverflowError:                       # an integer literal of hundreds of digits
        return f"got an integer of {len(str(abs(value)))} digits; the magnitude must be " \
               f"at most {MAX_MAGNITUDE:g}"
    if not math.isfinite(x):
        return f"must be finite, got {x!r}"
    if abs(x) > MAX_MAGNITUDE:
        return f"got {x:g}; every number must be at most {MAX_MAGNITUDE:g} in magnitude"
    return None


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
               gt=None, ge=None, lt=None, le=None, integer=False, what="", divisor=False):
        """A finite real number within the given bounds, at most :data:`MAX_MAGNITUDE` in
        magnitude; with ``divisor`` (the models divide by it) 0 or at least
        :data:`MIN_MAGNITUDE`."""
        full, value = self._lookup(data, key, path, required, what or "a number")
        if value is _MISSING:
            return default
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.add(full, f"must be a number, got {value!r:.60}")
            return default
        why = magnitude_problem(value)
        if why:
            self.add(full, why)
            return default
        value = float(value)
        if divisor and 0 < abs(value) < MIN_MAGNITUDE:
            self.add(full, f"got {value:g}; must be at least {MIN_MAGNITUDE:g} in magnitude "
                           f"(it is divided by)")
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

    def name(self, data, key, path="", *, default):
        """An optional name (see :func:`name_problem`), stripped of outer blanks."""
        full, value = self._lookup(data, key, path, False, "a name")
        if value is _MISSING:
            return default
        why = name_problem(value)
        if why:
            shown = value if not isinstance(value, str) or len(value) <= 40 \
                else value[:40] + "..."
            self.add(full, f"{shown!r} {why}" if isinstance(value, str) else why)
            return default
        return value.strip()

    def numbers(self, data, key, path="", *, required=True, default=None, length=None,
                min_length=None, max_length=None, gt=None, ge=None):
        """A list of finite numbers (fixed ``length`` if given; at most ``max_length``,
        checked before the items); at most :data:`MAX_ITEM_PROBLEMS` bad items are listed."""
        full, value = self._lookup(data, key, path, required, "a list of numbers")
        if value is _MISSING:
            return default
        if not isinstance(value, (list, tuple)):
            self.add(full, f"must be a list of numbers, got {value!r}")
            return default
        out, ok = [], True
        if max_length is not None and len(value) > max_length:
            self.add(full, f"has {len(value):,} numbers; at most {max_length:,} are allowed")
            return default
        shown = 0
        for i, item in enumerate(value):
            why = "must be a number" if isinstance(item, bool) or not isinstance(
                item, (int, float)) else magnitude_problem(item)
            if why:
                if shown < MAX_ITEM_PROBLEMS:
                    self.add(f"{full}[{i}]", f"{why}, got {item!r:.60}"
                             if why == "must be a number" else why)
                shown += 1
                ok = False
                continue
            item = float(item)
            if (gt is not None and not item > gt) or (ge is not None and not item >= ge):
                bound = f"> {gt:g}" if gt is not None else f">= {ge:g}"
                self.add(f"{full}[{i}]", f"got {item:g}; must be {bound}")
                ok = False
            out.append(item)
        if shown > MAX_ITEM_PROBLEMS:
            self.add(full, f"... and {shown - MAX_ITEM_PROBLEMS} more bad numbers")
        if length is not None and len(value) != length:
            self.add(full, f"must have exactly {length} numbers, got {len(value)}")
            ok = False
        if min_length is not None and len(value) < min_length:
            self.add(full, f"needs at least {min_length} numbers, got {len(value)}")
            ok = False
        return out if ok else default
