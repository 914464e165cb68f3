"""Spec validation helpers shared by every spec loader (linkage, engine, synthesis).

A :class:`Checker` walks a nested dict read from TOML and collects *all* problems, each
with its dotted key path, the bad value and what is valid; :meth:`Checker.raise_if_any`
raises one :class:`~crankbase.errors.SpecError` holding them.  Unknown keys are problems.
"""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

from .errors import Problem, SpecError, Text, os_reason

K = Problem.keyed      # a problem told by a text of the errors catalogue


def shown_value(value, width=60):
    """``repr(value)`` cut to ``width`` characters (a value shown in a message)."""
    return f"{value!r:.{width}}"

__all__ = ["Checker", "read_toml", "name_problem", "name_text", "rows_problem", "join_words", "shown_value", "bounds_text",
           "check_lang",
           "angles_argument", "step_argument", "magnitude_problem", "magnitude_text",
           "did_you_mean",
           "MAX_NAME_CHARS", "MAX_NAME_BYTES", "MAX_ROWS", "MIN_MAGNITUDE", "MAX_MAGNITUDE"]

#: Longest accepted name of an engine or mechanism [characters]: the name heads plot
#: titles and report sheets, which stay on one line up to about this length.
MAX_NAME_CHARS = 64
#: Longest accepted name in UTF-8 bytes: the workbook is called ``<name>.xlsx`` and is
#: written through a temporary file ``.<name>.<random>.tmp.xlsx``; 160 bytes keep that
#: below the 255-byte file-name limit of common file systems (ext4, XFS, btrfs, NTFS).
MAX_NAME_BYTES = 160


def name_problem(value) -> str | None:
    """Why ``value`` cannot be a name (English), or None; see :func:`name_text`."""
    why = name_text(value)
    return None if why is None else str(why)


def name_text(value) -> Text | None:
    """Why ``value`` cannot be a name (of an engine, a mechanism), or None if it can.

    A name is text of 1 to :data:`MAX_NAME_CHARS` characters and at most
    :data:`MAX_NAME_BYTES` bytes in UTF-8, without control characters (tab, newline, ...,
    which neither a file name nor an Excel cell can hold), line separators or unpaired
    surrogates.
    """
    import unicodedata

    if not isinstance(value, str):
        return Text("errors.string.type", {"value": shown_value(value)})
    if not value.strip():
        return Text("errors.name.empty")
    bad = [ch for ch in value if unicodedata.category(ch) in ("Cc", "Cs", "Zl", "Zp")]
    if bad:
        return Text("errors.name.control", {"code": f"U+{ord(bad[0]):04X}",
                                            "position": value.index(bad[0]) + 1})
    if len(value) > MAX_NAME_CHARS:
        return Text("errors.name.chars", {"n": len(value), "max": MAX_NAME_CHARS})
    size = len(value.encode("utf-8"))
    if size > MAX_NAME_BYTES:
        return Text("errors.name.bytes", {"n": size, "max": MAX_NAME_BYTES})
    return None


def read_toml(path_or_dict):
    """Return ``(dict, base_dir)`` from a TOML path or an already-parsed dict.

    ``base_dir`` is the folder of the file (relative paths inside a spec are resolved
    against it), or ``None`` for a dict.  A missing or unreadable file, a TOML syntax
    error, nesting too deep for the parser, or an argument that is neither a path nor a
    dict is a :class:`SpecError` naming the file (or the argument); so is an integer
    literal longer than Python converts (4,300 digits): no number of a spec may exceed
    :data:`MAX_MAGNITUDE` anyway.
    """
    import os

    if isinstance(path_or_dict, dict):
        return path_or_dict, None
    if not isinstance(path_or_dict, (str, os.PathLike)) or str(path_or_dict) == "":
        raise SpecError(K("spec", "errors.toml.argument", value=shown_value(path_or_dict)))
    path = Path(path_or_dict)
    name = str(path)
    try:
        if not path.is_file():
            raise SpecError(K(name, "errors.toml.no_file"))
        if path.stat().st_size > MAX_SPEC_BYTES:
            raise SpecError(K(name, "errors.toml.too_big", n=path.stat().st_size,
                              max=MAX_SPEC_BYTES))
        with open(path, "rb") as f:
            return tomllib.load(f), path.resolve().parent
    except tomllib.TOMLDecodeError as exc:
        raise SpecError(K(name, "errors.toml.syntax", why=str(exc))) from None
    except UnicodeDecodeError as exc:
        raise SpecError(K(name, "errors.toml.encoding", why=str(exc))) from None
    except RecursionError:
        raise SpecError(K(name, "errors.toml.nested")) from None
    except OSError as exc:
        raise SpecError(K(name, "errors.toml.unreadable", why=os_reason(exc)))\
            from None
    except ValueError as exc:
        # Python refuses to convert an integer literal of more than 4,300 digits
        # (sys.int_info.str_digits_check_threshold) while parsing
        if "digits" not in str(exc):
            raise
        raise SpecError(K(name, "errors.toml.digits", max=MAX_MAGNITUDE)) from None


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
        else "> 1e308"
    return K(key, "errors.rows", n=shown, max=MAX_ROWS)


def step_argument(value, key: str, span: float, rows_span: float | None = None,
                  error=SpecError) -> float:
    """A step argument of a public function [deg]: a real number with
    0 < step <= ``span`` that makes at most :data:`MAX_ROWS` rows over ``rows_span``
    (default ``span``); else ``error`` (a :class:`SpecError` class) naming ``key``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(float(value)) or not 0 < value <= span:
        raise error(K(key, "errors.step", value=shown_value(value, 40), span=span))
    too_many = rows_problem((rows_span or span) / float(value) + 1, key)
    if too_many:
        raise error(too_many)
    return float(value)


def angles_argument(value, key: str, *, max_abs: float = 1e6, error=SpecError, copy=True):
    """An angle argument of a public function as a 1-D float array.

    A scalar becomes one row.  Refused (:class:`SpecError` naming ``key``): complex or
    non-numeric values, more than one dimension, an empty list, non-finite values, and
    magnitudes above ``max_abs`` (where a double no longer resolves a fraction of a
    degree... 1e6° keeps ~1e-10° resolution).  ``error`` is the :class:`SpecError`
    subclass raised (a package's own, e.g. the engine's).  ``copy=False``: a 1-D float
    array given is returned itself, not a copy (for a caller that only reads it).

    The range is checked by the array's minimum and maximum (two passes, no temporary
    array: a NaN makes both comparisons false); only a refused array is searched for its
    first bad item.
    """
    import numpy as np

    try:
        arr = np.asarray(value)
    except (TypeError, ValueError) as exc:           # ragged nested lists
        raise error(K(key, "errors.angles.ragged", why=str(exc))) from None
    if arr.dtype.kind == "c":
        raise error(K(key, "errors.angles.complex"))
    if arr.dtype.kind not in "biuf":
        try:
            if arr.dtype.kind == "b" or any(v is None or isinstance(v, (bool, complex, str,
                                                                          bytes))
                                            for v in arr.ravel().tolist()):
                raise TypeError
            arr = arr.astype(float)
        except (TypeError, ValueError):
            raise error(K(key, "errors.angles.type", value=shown_value(value))) from None
    if arr.dtype.kind == "b":
        raise error(K(key, "errors.angles.bool"))
    arr = np.atleast_1d(arr.astype(float, copy=copy))
    if arr.ndim != 1:
        raise error(K(key, "errors.angles.shape", shape=str(arr.shape)))
    if arr.size == 0:
        raise error(K(key, "errors.angles.empty"))
    if arr.min() >= -max_abs and arr.max() <= max_abs:     # all finite and in range
        return arr
    bad = np.flatnonzero(~np.isfinite(arr) | (np.abs(arr) > max_abs))
    if bad.size:
        i = int(bad[0])
        if bad.size > 1:
            raise error(K(f"{key}[{i}]", "errors.angles.bad_more", value=float(arr[i]),
                          max=max_abs, more=bad.size - 1))
        raise error(K(f"{key}[{i}]", "errors.angles.bad", value=float(arr[i]), max=max_abs))
    return arr


#: At most this many bad items of one list are reported one by one (then a count).
MAX_ITEM_PROBLEMS = 10


def magnitude_problem(value) -> str | None:
    """Why a number of a spec is refused (not finite, or outside the magnitudes the models
    keep finite), or None (English; :func:`magnitude_text` gives the keyed text)."""
    why = magnitude_text(value)
    return None if why is None else str(why)


def magnitude_text(value) -> Text | None:
    """:func:`magnitude_problem` as a keyed :class:`~crankbase.errors.Text`."""
    try:
        x = float(value)
    except OverflowError:                       # an integer literal of hundreds of digits
        return Text("errors.magnitude.digits", {"digits": len(str(abs(value))),
                                                "max": MAX_MAGNITUDE})
    if not math.isfinite(x):
        return Text("errors.magnitude.finite", {"value": repr(x)})
    if abs(x) > MAX_MAGNITUDE:
        return Text("errors.magnitude.max", {"value": x, "max": MAX_MAGNITUDE})
    return None


def _scalar(value):
    """A spec value as a Python scalar: a 0-d numpy array or numpy scalar becomes its
    item; anything else (an array of several values, a list) is returned as is, to be
    refused by the getter naming its key (never "truth value of an array is
    ambiguous")."""
    item = getattr(value, "item", None)
    if item is not None and getattr(value, "shape", None) == ():
        try:
            return item()
        except (TypeError, ValueError):
            return value
    return value


def _is_array(value) -> bool:
    return hasattr(value, "shape") and hasattr(value, "dtype") and value.shape != ()


def join_words(path, key):
    return f"{path}.{key}" if path else str(key)


_MISSING = object()


def bounds_text(gt=None, ge=None, lt=None, le=None):
    """What a bounded number must be, e.g. ``> 0 and < 1`` (the joining word keyed)."""
    parts = [f"{op} {b:g}" for b, op in ((gt, ">"), (ge, ">="), (lt, "<"), (le, "<="))
             if b is not None]
    if len(parts) == 1:
        return parts[0]
    return Text("errors.and", {"a": parts[0], "b": " ".join(parts[1:])}) \
        if len(parts) == 2 else " ".join(parts)


def did_you_mean(key, allowed) -> str | None:
    """The allowed key closest to a mistyped ``key`` (difflib), or None."""
    import difflib

    if not isinstance(key, str):
        return None
    allowed = [a for a in allowed if isinstance(a, str)]
    close = difflib.get_close_matches(key, allowed, n=1, cutoff=0.6)
    if not close:     # a unit suffix left out or mistyped: 'bore' for 'bore_mm'
        close = [a for a in allowed if a.startswith(key + "_") or key.startswith(a + "_")]
    return close[0] if close else None


class Checker:
    """Collects spec problems; every getter returns a usable value (or None) and records
    a :class:`Problem` when the input is bad, so all problems are reported at once.

    Problems are keyed texts of the ``errors`` catalogue (``errors.po``), so that
    :meth:`SpecError.lines` can give them in the run's language."""

    def __init__(self):
        self.problems: list[Problem] = []

    # -- recording
    def add(self, key: str, message) -> None:
        """Record a problem of ``key``: an English message, or a keyed :class:`Text`."""
        if isinstance(message, Text):
            self.problems.append(Problem(key, text=message))
        else:
            self.problems.append(Problem(key, message))

    def addk(self, key: str, text_key: str, /, **fields) -> None:
        """Record a problem of ``key`` told by the catalogue text ``text_key``."""
        self.problems.append(K(key, text_key, **fields))

    def raise_if_any(self, error=SpecError) -> None:
        if self.problems:
            raise error(self.problems)

    # -- structure
    def table(self, data, key, path="", required=True):
        """A sub-table (dict); returns {} when missing (recording a problem if required)."""
        value = data.get(key, _MISSING) if isinstance(data, dict) else _MISSING
        full = join_words(path, key)
        if value is _MISSING:
            if required:
                self.addk(full, "errors.table.missing")
            return {}
        if not isinstance(value, dict):
            self.addk(full, "errors.table.type", value=shown_value(value))
            return {}
        return value

    def unknown(self, data, allowed, path="") -> None:
        """Record every key of ``data`` not in ``allowed``, with the closest valid key
        when there is one (``unknown key; did you mean 'bore_mm'?``)."""
        if not isinstance(data, dict):
            return
        allowed = list(allowed)
        for key in data:
            if key not in allowed:
                guess = did_you_mean(key, allowed)
                if guess is not None:
                    self.addk(join_words(path, key), "errors.unknown.guess", guess=repr(guess),
                              valid=", ".join(allowed))
                else:
                    self.addk(join_words(path, key), "errors.unknown", valid=", ".join(allowed))

    def _lookup(self, data, key, path, required, wanted):
        """``(full key path, value)``; value is ``_MISSING`` when absent (a problem is
        recorded if the key is required, naming what is ``wanted``)."""
        full = join_words(path, key)
        value = data.get(key, _MISSING) if isinstance(data, dict) else _MISSING
        if value is _MISSING and required:
            self.addk(full, "errors.missing", wanted=wanted)
        return full, (value if value is _MISSING else _scalar(value))

    # -- scalars
    def number(self, data, key, path="", *, required=True, default=None,
               gt=None, ge=None, lt=None, le=None, integer=False, what="", divisor=False):
        """A finite real number within the given bounds, at most :data:`MAX_MAGNITUDE` in
        magnitude; with ``divisor`` (the models divide by it) 0 or at least
        :data:`MIN_MAGNITUDE`.  ``what`` (str or :class:`Text`) names it when missing."""
        full, value = self._lookup(data, key, path, required,
                                   what or Text("errors.wanted.number"))
        if value is _MISSING:
            return default
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.addk(full, "errors.number.type", value=shown_value(value))
            return default
        why = magnitude_text(value)
        if why:
            self.add(full, why)
            return default
        value = float(value)
        if divisor and 0 < abs(value) < MIN_MAGNITUDE:
            self.addk(full, "errors.number.divisor", value=value, min=MIN_MAGNITUDE)
            return default
        if integer and value != int(value):
            self.addk(full, "errors.number.whole", value=repr(value))
            return default
        checks = [(gt, lambda b: value > b), (ge, lambda b: value >= b),
                  (lt, lambda b: value < b), (le, lambda b: value <= b)]
        if not all(ok(b) for b, ok in checks if b is not None):
            self.addk(full, "errors.number.bounds", value=value,
                      valid=bounds_text(gt, ge, lt, le))
            return default
        return int(value) if integer else value

    def choice(self, data, key, choices, path="", *, required=True, default=None):
        """One of a fixed set of values."""
        shown = ", ".join(map(repr, choices))
        full, value = self._lookup(data, key, path, required,
                                   Text("errors.wanted.choice", {"choices": shown}))
        if value is _MISSING:
            return default
        bool_mismatch = isinstance(value, bool) and not any(isinstance(c, bool) for c in choices)
        if bool_mismatch or _is_array(value) or value not in choices:
            self.addk(full, "errors.choice", value=shown_value(value), choices=shown)
            return default
        return value

    def string(self, data, key, path="", *, required=True, default=None):
        full, value = self._lookup(data, key, path, required, Text("errors.wanted.string"))
        if value is _MISSING:
            return default
        if not isinstance(value, str):
            self.addk(full, "errors.string.type", value=shown_value(value))
            return default
        return value

    def name(self, data, key, path="", *, default):
        """An optional name (see :func:`name_problem`), stripped of outer blanks."""
        full, value = self._lookup(data, key, path, False, "")
        if value is _MISSING:
            return default
        why = name_text(value)
        if why:
            shown = value if not isinstance(value, str) or len(value) <= 40 \
                else value[:40] + "..."
            if isinstance(value, str):
                self.addk(full, "errors.name.shown", shown=repr(shown), why=why)
            else:
                self.add(full, why)
            return default
        return value.strip()

    def names(self, data, key, path="", *, required=False, default=None, length=None,
              max_length=MAX_ROWS, what=None):
        """A list of names (each as :meth:`name`, stripped), ``length`` of them when set, at
        most ``max_length`` (checked before the items); a tuple, or ``default`` on a
        problem.  ``what`` (a :class:`Text`) names it when missing."""
        full, value = self._lookup(data, key, path, required,
                                   what or Text("errors.wanted.names"))
        if value is _MISSING:
            return default
        if not isinstance(value, (list, tuple)) or not value:
            self.addk(full, "common.names.type", value=shown_value(value))
            return default
        if len(value) > max_length:
            self.addk(full, "common.names.too_many", n=len(value), max=max_length)
            return default
        if length is not None and len(value) != length:
            self.addk(full, "errors.names.type", n=length, value=shown_value(value))
            return default
        out = []
        for i, item in enumerate(value):
            why = name_text(item)
            if why:
                self.add(f"{full}[{i}]", why)
                return default
            out.append(item.strip())
        return tuple(out)

    def numbers(self, data, key, path="", *, required=True, default=None, length=None,
                min_length=None, max_length=None, gt=None, ge=None):
        """A list of finite numbers (fixed ``length`` if given; at most ``max_length``,
        checked before the items); at most :data:`MAX_ITEM_PROBLEMS` bad items are listed.
        A 1-D numpy array is taken as its list."""
        full, value = self._lookup(data, key, path, required,
                                   Text("errors.wanted.numbers"))
        if value is _MISSING:
            return default
        if _is_array(value) and len(value.shape) == 1:
            value = value.tolist()
        if not isinstance(value, (list, tuple)):
            self.addk(full, "errors.numbers.type", value=shown_value(value))
            return default
        out, ok = [], True
        if max_length is not None and len(value) > max_length:
            self.addk(full, "errors.numbers.too_many", n=len(value), max=max_length)
            return default
        shown = 0
        for i, item in enumerate(value):
            item = _scalar(item)
            if isinstance(item, bool) or not isinstance(item, (int, float)):
                why = Text("errors.number.type", {"value": shown_value(item)})
            else:
                why = magnitude_text(item)
            if why:
                if shown < MAX_ITEM_PROBLEMS:
                    self.add(f"{full}[{i}]", why)
                shown += 1
                ok = False
                continue
            item = float(item)
            if (gt is not None and not item > gt) or (ge is not None and not item >= ge):
                self.addk(f"{full}[{i}]", "errors.number.bounds", value=item,
                          valid=bounds_text(gt=gt) if gt is not None else bounds_text(ge=ge))
                ok = False
            out.append(item)
        if shown > MAX_ITEM_PROBLEMS:
            self.addk(full, "errors.numbers.more", n=shown - MAX_ITEM_PROBLEMS)
        if length is not None and len(value) != length:
            self.addk(full, "errors.numbers.length", length=length, n=len(value))
            ok = False
        if min_length is not None and len(value) < min_length:
            self.addk(full, "errors.numbers.min_length", min=min_length, n=len(value))
            ok = False
        return out if ok else default


def check_lang(lang, key: str = "lang") -> str:
    """``lang`` if it is an offered language, else a :class:`~crankbase.errors.SpecError`
    naming ``key``, the value and the valid choices."""
    from .texts import languages, offered

    if offered(lang):                  # reads this language's catalogue only, not all
        return lang
    raise SpecError(Problem(key, Text("errors.validation.one",
                                      {"lang": lang, "items": ', '.join(languages())})))
