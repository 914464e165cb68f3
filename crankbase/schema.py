"""The one spec schema: every key of every spec file, described once.

A package declares its keys once (``engine/schema.py``, ``linkage/schema.py``,
``dynamics/schema.py``) as :class:`Key`, :class:`Table` and :class:`ArrayOfTables`
descriptions: path, type, unit and its factor to SI, allowed range, default, required or
not.  Every loader reads through one validator, :class:`SpecReader`, so that the checks of
a key, the unit conversion, the bounds on every count and size (:data:`MAX_CYLINDERS`,
:data:`MAX_TABLE_ROWS`, :data:`~crankbase.validation.MAX_ROWS`) and "unknown key; did you
mean 'bore_mm'?" are written once, and every problem of a file is reported at once
(:class:`~crankbase.errors.SpecError`, each problem naming the key path, the bad value and
what is valid, in English or Russian: :meth:`~crankbase.errors.SpecError.lines`).

The words (label, one-line help, symbol, unit names) are not here: they live in the
``spec`` catalogue (``crankbase/locale/<lang>/spec.po``) under ``spec.<table>.<key>.label``,
``.help`` and ``.symbol`` (:meth:`Key.label`, :meth:`Key.help`, :meth:`Key.symbol`).  The
README's spec reference is rendered from the schema by :func:`markdown_reference`
(``python -m crankbase.schema update-readme`` rewrites it between the
``<!-- spec-reference:start -->`` and ``<!-- spec-reference:end -->`` markers; a test keeps
them equal).

Examples
--------
>>> from crankbase.schema import Key, Table, SpecReader
>>> ENGINE = Table("engine", (Key("bore_mm", unit="mm", si=1e-3, gt=0, required=True),))
>>> r = SpecReader()
>>> e = r.sub({"engine": {"bore": 92}}, ENGINE)
>>> r.get(e, ENGINE, "bore_mm") is None
True
>>> [str(p) for p in r.problems]  # doctest: +NORMALIZE_WHITESPACE
["engine.bore: unknown key; did you mean 'bore_mm'? valid keys here: bore_mm",
 'engine.bore_mm: missing; bore_mm [mm] is required']
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from .errors import Text
from .validation import MAX_ROWS, Checker, join_words, shown_value

__all__ = ["Key", "Table", "ArrayOfTables", "Schema", "SpecReader", "markdown_reference",
           "key_texts", "MAX_CYLINDERS", "MAX_TABLE_ROWS", "SCHEMA_MODULES",
           "README_START", "README_END"]

#: Most cylinders of an engine spec: the largest piston engines built (marine two-stroke
#: diesels, W-engines) have 14 to 24; the count sizes the crank-train arrays, so it is
#: bounded before anything is allocated.
MAX_CYLINDERS = 24

#: Most tables of one array of tables (``[[load]]``, ``[[machine.moment]]``,
#: ``[[balance.counterweight]]``, ``[[rotor.mass]]`` ...): a page of a course project holds
#: a dozen; each table becomes a row of a report.
MAX_TABLE_ROWS = 1000

#: The modules that declare the schemas of the bundled spec files, in the order of the
#: README (imported by name by :func:`markdown_reference`: the base package imports no
#: other package of the project).
SCHEMA_MODULES = ("engine.schema", "linkage.schema", "dynamics.schema")

README_START = "<!-- spec-reference:start -->"
README_END = "<!-- spec-reference:end -->"

#: Kinds of key: how the value is read.
KINDS = ("number", "integer", "choice", "string", "name", "numbers", "bool", "path",
         "points", "names")

_UNSET = object()


@dataclass(frozen=True)
class Key:
    """One key of a spec table.

    Parameters
    ----------
    name : str
        The key as written in the file (``bore_mm``).
    kind : str
        One of :data:`KINDS`: a ``number``; an ``integer`` (a whole number; with ``le`` a
        count bounded before anything is sized by it); a ``choice`` of ``choices``; a
        ``string``; a ``name`` (:func:`crankbase.validation.name_problem`); a list of
        ``numbers`` (``length``, ``min_length``, at most ``max_length``, default
        :data:`~crankbase.validation.MAX_ROWS`); a ``bool``; a file ``path``; a table of
        named ``points`` ``name = [x, y]``; a list of ``names`` (each a ``name``; ``length``
        of them when set, at most ``max_length``).
    unit : str
        The unit of the value as written, in its international spelling, one of
        :data:`crankbase.texts.UNITS` (``mm``, ``MPa``, ``°`` ...; "" for none); shown
        in the user's language by :meth:`crankbase.texts.Texts.unit`.
    si : float
        Factor from ``unit`` to SI (``mm`` → m: 1e-3; ``MPa`` → Pa: 1e6); 1 when the
        value is kept as written (degrees, rpm).
    gt, ge, lt, le : float, optional
        Bounds of a number, or of every item of a list of numbers (``gt``, ``ge``).
    default : optional
        The value when the key is absent (in the file's unit).
    required : bool or str
        True, False, or a condition in words' place: ``"cond"`` (required in some cases
        only, told by the help text; the loader decides).
    divisor : bool
        The models divide by it: 0 or at least :data:`~crankbase.validation.MIN_MAGNITUDE`.
    symbol : bool
        The catalogue holds a symbol for it (``spec.<table>.<key>.symbol``).
    shown_default : str, optional
        The default as the reference shows it, when it is not a constant (``"360"``).
    """

    name: str
    kind: str = "number"
    unit: str = ""
    si: float = 1.0
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    default: object = None
    required: bool | str = False
    choices: tuple = ()
    divisor: bool = False
    length: int | None = None
    min_length: int | None = None
    max_length: int | None = None
    symbol: bool = False
    shown_default: str | None = None
    table: str = field(default="", compare=False)       # set by the Table

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"Key {self.name!r}: kind {self.kind!r} not in {KINDS}")

    # ---- words (the spec catalogue)
    @property
    def text_key(self) -> str:
        """The catalogue key of this key's words, ``spec.<table>.<key>``."""
        return f"spec.{self.table}.{self.name}"

    def label(self, lang: str = "en") -> str:
        """Its label in ``lang`` (``spec.<table>.<key>.label``)."""
        from .texts import texts

        return texts(lang)(self.text_key + ".label")

    def help(self, lang: str = "en") -> str:
        """Its one-line help in ``lang`` (``spec.<table>.<key>.help``)."""
        from .texts import texts

        return texts(lang)(self.text_key + ".help")

    def symbol_text(self, lang: str = "en") -> str:
        """Its symbol in ``lang`` ("" when it has none)."""
        from .texts import texts

        return texts(lang)(self.text_key + ".symbol") if self.symbol else ""

    def unit_text(self, lang: str = "en") -> str:
        """Its unit in ``lang`` ("" when it has none)."""
        from .texts import texts

        return texts(lang).unit(self.unit)

    def wanted(self) -> Text:
        """What a missing value must be, for the "missing; ... is required" problem."""
        if self.unit:
            from .texts import unit_key

            return Text("errors.wanted.key", {"label": Text(self.text_key + ".label"),
                                              "unit": Text(unit_key(self.unit))})
        return Text("errors.wanted.label", {"label": Text(self.text_key + ".label")})

    def to_si(self, value):
        """``value`` (in :attr:`unit`) in SI; lists item by item; None stays None.

        A factor below 1 whose inverse is whole (mm → m: 1e-3) divides by that whole
        number (``92 / 1000``, the correctly rounded value, not ``92 * 0.001``)."""
        if value is None or self.si == 1.0:
            return value
        inv = 1.0 / self.si
        if self.si < 1 and inv == round(inv):
            def conv(v):
                return v / round(inv)
        else:
            def conv(v):
                return v * self.si
        if isinstance(value, (list, tuple)):
            return type(value)(conv(v) for v in value)
        return conv(value)

    # ---- the reference
    def range_text(self, lang: str = "en") -> str:
        """The allowed values as the reference shows them (``(0, 1)``, ``≥ 1``,
        ``'two-term', 'exact'``; a list: how many numbers, each in its range)."""
        if self.kind == "choice" or self.kind == "bool":
            return ", ".join(_literal(c) for c in (self.choices or (True, False)))
        lo = (f"({self.gt:g}" if self.gt is not None else
              f"[{self.ge:g}" if self.ge is not None else None)
        hi = (f"{self.lt:g})" if self.lt is not None else
              f"{self.le:g}]" if self.le is not None else None)
        if lo and hi:
            text = f"{lo}, {hi}"
        elif lo:
            text = ("> " if lo[0] == "(" else "≥ ") + lo[1:]
        elif hi:
            text = ("< " if hi[-1] == ")" else "≤ ") + hi[:-1]
        else:
            text = ""
        if self.kind == "numbers":
            from .texts import texts

            t = texts(lang)
            n = (t.n("spec.range.exactly", self.length) if self.length else
                 t.n("spec.range.at_most", self.max_length or MAX_ROWS))
            return f"{n}, {text}" if text else n
        return text

    def default_text(self, lang: str = "en") -> str:
        """The default as the reference shows it ("" when none)."""
        if self.shown_default is not None:
            if self.shown_default.startswith("spec."):
                from .texts import texts

                return texts(lang)(self.shown_default)
            return self.shown_default
        if self.default is None or self.default == ():
            return ""
        return _literal(self.default)


def _literal(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return f'"{v}"'
    if isinstance(v, float):
        return f"{v:g}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_literal(x) for x in v) + "]"
    return str(v)


def _bind(entries, path):
    out = []
    for e in entries:
        if isinstance(e, Key):
            object.__setattr__(e, "table", path)
        out.append(e)
    return tuple(out)


@dataclass(frozen=True)
class Table:
    """A table of a spec (``[engine]``, ``[pressure.cycle]``).

    Parameters
    ----------
    path : str
        Dotted path of the table in the file (``pressure.cycle``).  A table that stands
        for several of one shape (``[links.crank]``, ``[links.coupler]`` ...) is declared
        once with a placeholder last part (``links.<link>``) and read with ``path=``.
    entries : tuple of Key, Table, ArrayOfTables
    required : bool
    extra : tuple of str
        Further names allowed in it, read by another module (``drawing``).
    """

    path: str
    entries: tuple = ()
    required: bool = False
    extra: tuple = ()

    def __post_init__(self):
        object.__setattr__(self, "entries", _bind(self.entries, self.text_path))

    @property
    def name(self) -> str:
        return self.path.rsplit(".", 1)[-1]

    @property
    def text_path(self) -> str:
        """The path in catalogue keys (a placeholder ``<link>`` becomes ``link``)."""
        return self.path.replace("<", "").replace(">", "")

    @property
    def names(self) -> tuple:
        """Every name allowed in the table."""
        return tuple(e.name for e in self.entries) + tuple(self.extra)

    def key(self, name: str) -> Key:
        for e in self.entries:
            if isinstance(e, Key) and e.name == name:
                return e
        raise KeyError(f"{self.path}: no key {name!r} in the schema")

    def child(self, name: str):
        for e in self.entries:
            if e.name == name:
                return e
        raise KeyError(f"{self.path}: no entry {name!r} in the schema")

    def keys(self):
        return [e for e in self.entries if isinstance(e, Key)]


@dataclass(frozen=True)
class ArrayOfTables(Table):
    """An array of tables (``[[balance.counterweight]]``): at most ``max_items``
    (default :data:`MAX_TABLE_ROWS`), at least ``min_items``."""

    min_items: int = 0
    max_items: int = MAX_TABLE_ROWS


@dataclass(frozen=True)
class Schema:
    """Every table of one kind of spec file.

    ``name`` names the file kind in the reference (``spec.file.<name>`` in the
    catalogue); ``tables`` are the top-level tables; ``extra`` further top-level names
    read by another module.
    """

    name: str
    tables: tuple
    extra: tuple = ()

    @property
    def names(self) -> tuple:
        return tuple(t.name for t in self.tables) + tuple(self.extra)

    def table(self, path: str) -> Table:
        """The (sub-)table at a dotted ``path``."""
        parts = path.split(".")
        node = next(t for t in self.tables if t.name == parts[0])
        for p in parts[1:]:
            node = node.child(p)
        return node

    def key(self, path: str) -> Key:
        """The key at a dotted ``path`` (``"engine.bore_mm"``, ``"pressure.cycle.n1"``)."""
        table, _, name = path.rpartition(".")
        return self.table(table).key(name)

    def key_of(self, path: str):
        """The :class:`Key` that describes the value at ``path`` as a spec file writes it
        (``"links.crank.mass_kg"``: a placeholder table ``<link>`` stands for any name;
        ``"load[0].at"``: an array's index; ``"links.crank.points.B"``: one point of a
        ``points`` key), None for a path outside the schema (an ``extra`` table such as
        ``[drawing]``, an unknown key): what a sheet of the values as given asks for a
        row's unit (:attr:`Key.unit`)."""
        parts = [re.sub(r"\[\d+\]$", "", p) for p in path.split(".")]
        node = next((t for t in self.tables if t.name == parts[0]), None)
        for i, name in enumerate(parts[1:], start=1):
            if node is None:
                return None
            entry = next((e for e in node.entries if e.name == name), None) or next(
                (e for e in node.entries if isinstance(e, Table) and e.name.startswith("<")),
                None)
            if isinstance(entry, Key):
                rest = parts[i + 1:]
                return entry if not rest or (entry.kind == "points" and len(rest) == 1) \
                    else None
            node = entry
        return None

    def describe(self, path: str, lang: str = "en") -> dict:
        """Everything a form or a sheet shows of the key at ``path``, in ``lang``:
        ``label``, ``help``, ``symbol``, ``unit``, ``range``, ``default`` (text) and
        ``required`` (True, False or "cond"), e.g. for the Inputs sheets of the workbook
        templates: ``engine.schema.SCHEMA.describe("engine.bore_mm", "ru")``."""
        k = self.key(path)
        return {"key": k.name, "label": k.label(lang), "help": k.help(lang),
                "symbol": k.symbol_text(lang), "unit": k.unit_text(lang),
                "range": k.range_text(lang), "default": k.default_text(lang),
                "required": k.required}


class SpecReader(Checker):
    """The one validator of spec files: reads tables and keys by their schema.

    A :class:`~crankbase.validation.Checker` (every problem collected, then raised at once
    by :meth:`raise_if_any`) that knows the keys: :meth:`top` checks the top-level tables,
    :meth:`sub` returns a table's dict after reporting its unknown keys (with "did you
    mean"), :meth:`get` reads one key by its description (type, bounds, default, unit
    conversion), :meth:`rows` the tables of an array, bounded.
    """

    def top(self, data, schema: Schema) -> None:
        """Report every unknown top-level table of ``data``."""
        self.unknown(data, schema.names)

    def sub(self, data, table: Table, *, path: str | None = None, required=None) -> dict:
        """The dict of ``table`` inside its parent ``data`` ({} when absent or not a
        table, a problem recorded when required), its unknown keys reported."""
        path = path or table.path
        parent, _, name = path.rpartition(".")
        req = table.required if required is None else required
        raw = self.table(data, name, parent, required=req)
        self.unknown(raw, table.names, path)
        return raw

    def get(self, raw, table: Table, name: str, *, path: str | None = None, si=False,
            required=None, **override):
        """The value of key ``name`` of ``table`` in its dict ``raw`` (None or the default
        on a problem, which is recorded), in the file's unit, or in SI with ``si``.

        ``required`` and the bounds (``gt``...) may be overridden where the loader knows
        more (a conditionally required key)."""
        key = table.key(name)
        if override:
            from dataclasses import replace

            key = replace(key, **override)
            object.__setattr__(key, "table", table.text_path)
        path = path or table.path
        req = key.required is True if required is None else bool(required)
        kind = key.kind
        if kind in ("number", "integer"):
            value = self.number(raw, name, path, required=req, default=key.default,
                                gt=key.gt, ge=key.ge, lt=key.lt, le=key.le,
                                integer=kind == "integer", divisor=key.divisor,
                                what=key.wanted())
        elif kind == "choice":
            value = self.choice(raw, name, key.choices, path, required=req,
                                default=key.default)
        elif kind == "bool":
            value = self.choice(raw, name, (True, False), path, required=req,
                                default=key.default)
        elif kind in ("string", "path"):
            value = self.string(raw, name, path, required=req, default=key.default)
        elif kind == "name":
            value = self.name(raw, name, path, default=key.default)
        elif kind == "names":
            value = self.names(raw, name, path, required=req, default=key.default,
                               length=key.length, max_length=key.max_length or MAX_ROWS,
                               what=key.wanted())
        elif kind == "numbers":
            value = self.numbers(raw, name, path, required=req, default=key.default,
                                 length=key.length, min_length=key.min_length,
                                 max_length=key.max_length or MAX_ROWS, gt=key.gt,
                                 ge=key.ge)
            if value is not None and (key.lt is not None or key.le is not None):
                full = join_words(path, name)
                for i, x in enumerate(value):
                    if (key.lt is not None and not x < key.lt) or \
                            (key.le is not None and not x <= key.le):
                        from .validation import bounds_text

                        self.addk(f"{full}[{i}]", "errors.number.bounds", value=x,
                                  valid=bounds_text(lt=key.lt, le=key.le))
                        value = key.default
                        break
        else:                                  # points: read by the loader
            value = raw.get(name, key.default) if isinstance(raw, dict) else key.default
        return key.to_si(value) if si else value

    def values(self, raw, table: Table, *, path: str | None = None, si=False) -> dict:
        """Every key of ``table`` (:meth:`get`), absent optional keys at their default."""
        return {k.name: self.get(raw, table, k.name, path=path, si=si)
                for k in table.keys()}

    def rows(self, raw, array: ArrayOfTables, *, path: str | None = None,
             required=None) -> list:
        """The tables of ``array`` in its parent dict ``raw`` as ``[(path, dict)]``:
        a missing required array, a value that is not an array of tables, more than
        ``max_items`` tables (checked before any is read) and an item that is not a table
        are problems; each table's unknown keys are reported."""
        path = path or array.path
        name = path.rsplit(".", 1)[-1]
        req = array.required if required is None else required
        value = raw.get(name, None) if isinstance(raw, dict) else None
        if value is None or (isinstance(value, list) and not value):
            if req or (value is not None and array.min_items):
                self.addk(path, "errors.missing", wanted=Text(
                    "errors.wanted.tables", {"path": path,
                                             "keys": ", ".join(array.names)}))
            return []
        if not isinstance(value, list):
            self.addk(path, "errors.array.type", path=path, value=shown_value(value))
            return []
        if len(value) > array.max_items:
            self.addk(path, "errors.array.too_many", n=len(value), max=array.max_items)
            return []
        out = []
        for i, item in enumerate(value):
            where = f"{path}[{i}]"
            if not isinstance(item, dict):
                self.addk(where, "errors.array.item", value=shown_value(item))
                continue
            self.unknown(item, array.names, where)
            out.append((where, item))
        return out


# ----------------------------------------------------------------------------- reference

def _schemas(schemas=None):
    if schemas is not None:
        return list(schemas)
    import importlib

    out = []
    for name in SCHEMA_MODULES:
        mod = importlib.import_module(name)
        out += list(getattr(mod, "SCHEMAS", (mod.SCHEMA,)))
    return out


def _walk(tables):
    for t in tables:
        yield t
        yield from _walk([e for e in t.entries if isinstance(e, Table)])


def key_texts(schemas=None) -> list[str]:
    """Every catalogue key the schemas need (labels, help, symbols, units, file titles):
    the catalogue test checks that each one exists."""
    from .texts import unit_key

    out = []
    for s in _schemas(schemas):
        out.append(f"spec.file.{s.name}")
        for t in _walk(s.tables):
            out.append(f"spec.{t.text_path}.title")
            for k in t.keys():
                out += [k.text_key + ".label", k.text_key + ".help"]
                if k.symbol:
                    out.append(k.text_key + ".symbol")
                if k.unit:
                    out.append(unit_key(k.unit))
    return list(dict.fromkeys(out))


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def markdown_reference(lang: str = "en", schemas=None) -> str:
    """The spec reference as Markdown: for every spec file kind and each of its tables,
    a table of its keys (key, type, unit, range, default, required, meaning), rendered
    from the schemas (default: those of :data:`SCHEMA_MODULES`) in ``lang``."""
    from .texts import texts

    t = texts(lang)
    head = [t("spec.column.key"), t("spec.column.type"), t("spec.column.unit"),
            t("spec.column.range"), t("spec.column.default"), t("spec.column.required"),
            t("spec.column.meaning")]
    lines = []
    for s in _schemas(schemas):
        file_key = f"spec.file.{s.name}"
        lines += [f"#### {t(file_key)}", ""]
        for tab in _walk(s.tables):
            brackets = "[[{}]]" if isinstance(tab, ArrayOfTables) else "[{}]"
            title_key = f"spec.{tab.text_path}.title"
            lines += [f"`{brackets.format(tab.path)}` — {t(title_key)}", ""]
            if not tab.keys():
                continue
            lines.append("| " + " | ".join(head) + " |")
            lines.append("|" + "---|" * len(head))
            for k in tab.keys():
                req = (t("spec.required.yes") if k.required is True else
                       t("spec.required.cond") if k.required else t("spec.required.no"))
                sym = k.symbol_text(lang)
                label = k.label(lang) + (f" {sym}" if sym and sym not in
                                         k.label(lang).split() else "")
                meaning = f"{label}: {k.help(lang)}"
                type_key = f"spec.type.{k.kind}"
                lines.append("| " + " | ".join(_cell(c) for c in (
                    f"`{k.name}`", t(type_key), k.unit_text(lang),
                    k.range_text(lang), k.default_text(lang), req, meaning)) + " |")
            lines.append("")
    return "\n".join(lines).rstrip() + "\n"


def readme_block(lang: str = "en", schemas=None) -> str:
    """The README's generated block, markers included."""
    return (f"{README_START}\n<!-- generated by `python -m crankbase.schema "
            f"update-readme` from the spec schema; do not edit by hand -->\n\n"
            f"{markdown_reference(lang, schemas)}\n{README_END}")


def update_readme(path) -> bool:
    """Rewrite the block between the markers of the README at ``path``; True if it
    changed."""
    from pathlib import Path

    path = Path(path)
    text = path.read_text(encoding="utf-8")
    i, j = text.index(README_START), text.index(README_END) + len(README_END)
    new = text[:i] + readme_block() + text[j:]
    if new != text:
        path.write_text(new, encoding="utf-8")
    return new != text


def readme_reference(path) -> str:
    """The block between the markers of the README at ``path`` (markers included)."""
    from pathlib import Path

    text = Path(path).read_text(encoding="utf-8")
    i, j = text.index(README_START), text.index(README_END) + len(README_END)
    return text[i:j]


def main(argv=None) -> int:
    """``python -m crankbase.schema [LANG]`` prints the spec reference in ``LANG`` (en,
    ru); ``python -m crankbase.schema update-readme [README.md]`` rewrites the README's
    block.  (Positional words, not options: a library names no command-line option.)"""
    import sys
    from pathlib import Path

    args = list(sys.argv[1:] if argv is None else argv)
    if args[:1] == ["update-readme"]:
        path = args[1] if len(args) > 1 else str(
            Path(__file__).resolve().parent.parent / "README.md")
        changed = update_readme(path)
        print(f"{path}: {'updated' if changed else 'already up to date'}")
        return 0
    print(markdown_reference(args[0] if args else "en"), end="")
    return 0


if __name__ == "__main__":      # pragma: no cover
    # run the imported module's main: the schema modules' Tables are instances of
    # crankbase.schema's classes, not of this __main__ copy's
    from crankbase.schema import main as _main

    raise SystemExit(_main())

