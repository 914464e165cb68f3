"""The engine form, generated from the spec schema (:data:`engine.schema.SCHEMA`).

Every key of every table of the engine spec becomes one field named by its dotted path
(``engine.bore_mm``, ``pressure.cycle.n1``); its label, symbol, unit, allowed range,
default and help come from the schema and the ``spec`` catalogue in the page's language.
:func:`values_from_spec` turns a spec dict (a bundled example, an uploaded TOML) into the
field texts; :func:`spec_from_values` turns the posted field texts back into the dict that
:func:`engine.load` reads, so that every check is the library's: nothing is validated here
beyond reading a number, and a text that is not a number is passed on as text for the
library to name.  The pressure comes from one source chosen on the form: the cycle
parameters, a pasted table, or the uploaded file (kept by the server under its own name).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Field", "Section", "sections", "values_from_spec", "spec_from_values",
           "problem_field", "PRESSURE_SOURCES", "FILE_KEY", "PLACEHOLDERS"]

#: The three ways of giving the pressure (radio ``pressure_source``).
PRESSURE_SOURCES = ("cycle", "table", "file")
#: The one key of the schema that names a file: never a form field (the upload is).
FILE_KEY = "pressure.file"

_INT = re.compile(r"[+-]?\d+")
_SPLIT = re.compile(r"[\s,;]+")


@dataclass(frozen=True)
class Field:
    """One field of the form: the key's path and everything the page shows of it."""

    path: str
    kind: str
    label: str
    symbol: str
    unit: str
    range: str
    default: str
    help: str
    choices: tuple = ()
    required: object = False
    multiline: bool = False


@dataclass(frozen=True)
class Section:
    """One table of the spec (a fieldset of the form)."""

    path: str
    title: str
    fields: tuple


#: Names a placeholder table stands for (``[links.<link>]`` of the linkage spec is one
#: table per link: ``[links.crank]`` ...).
PLACEHOLDERS = {"<link>": ("crank", "coupler", "rocker", "slider")}


def _link_names(schema, names=None) -> dict:
    """The names a placeholder table stands for: a chain's links are named by its spec
    (``names``, found in the spec or the posted fields; the crank at least), a four-bar's
    are :data:`PLACEHOLDERS`'."""
    if getattr(schema, "name", "") != "chain":
        return PLACEHOLDERS
    return {"<link>": tuple(dict.fromkeys(names or ())) or ("crank",)}


def _names_in_values(values) -> list:
    """The link names of the posted fields ``links.<name>.<key>``."""
    return [k.split(".")[1] for k in values or () if k.startswith("links.")
            and k.count(".") == 2]


def _names_in_spec(data) -> list:
    """The link names of a spec dict: its ``[links.<name>]`` tables, the crank and the
    groups' links (a link without a table gets empty fields)."""
    out = []
    if isinstance(data, dict):
        mech = data.get("mechanism") if isinstance(data.get("mechanism"), dict) else {}
        crank = mech.get("crank_link", "crank")
        out += [crank] if isinstance(crank, str) else []
        for g in data.get("group") or () if isinstance(data.get("group"), list) else ():
            if isinstance(g, dict) and isinstance(g.get("links"), list):
                out += [n for n in g["links"] if isinstance(n, str)]
        links = data.get("links")
        out += [n for n in links if isinstance(n, str)] if isinstance(links, dict) else []
    return out


def _tables(schema, placeholders=None):
    """``[(path, table)]`` of every table of ``schema`` in order, a placeholder table once
    per name it stands for."""
    from crankbase.schema import Table

    placeholders = PLACEHOLDERS if placeholders is None else placeholders

    def walk(tables, prefix):
        for t in tables:
            last = t.path.rsplit(".", 1)[-1]
            names = placeholders.get(last, (last,))
            for n in names:
                path = f"{prefix}{n}"
                yield path, t
                yield from walk([e for e in t.entries if isinstance(e, Table)], path + ".")
    return list(walk(schema.tables, ""))


def _schema(schema=None):
    if schema is not None:
        return schema
    from engine.schema import SCHEMA

    return SCHEMA


def _plain_rows(array) -> bool:
    """An array of tables whose keys are all required single numbers is written as number
    columns (``z, mr, angle``); any other as one inline table per line (``link = "rocker",
    resistance_Nm = 1500``)."""
    return all(k.kind in ("number", "integer") and k.required is True for k in array.keys())


def sections(lang: str, schema=None, values=None) -> list[Section]:
    """The form's sections in ``lang``: one per table of the schema (the engine's by
    default), in order (a chain's links: those named in the field texts ``values``)."""
    from crankbase.schema import ArrayOfTables
    from crankbase.texts import texts

    t = texts(lang)
    out = []
    schema = _schema(schema)
    for tpath, tab in _tables(schema, _link_names(schema, _names_in_values(values))):
        fields = []
        if isinstance(tab, ArrayOfTables):
            keys = tab.keys()
            cols = ", ".join(f"{k.name} [{k.unit_text(lang)}]" if k.unit else k.name
                             for k in keys)
            plain = _plain_rows(tab)
            fields.append(Field(path=tpath, kind="rows", label=t(f"spec.{tab.text_path}.title"),
                                symbol="", unit="", range=t("web.form.rows", columns=cols)
                                if plain else t("web.form.inline_rows"),
                                default="", help=t("web.form.rows_help", columns=cols)
                                if plain else t("web.form.inline_help", columns=cols),
                                multiline=True))
        else:
            for k in tab.keys():
                path = f"{tpath}.{k.name}"
                if path == FILE_KEY:
                    continue
                fields.append(Field(path=path, kind=k.kind, label=k.label(lang),
                                    symbol=k.symbol_text(lang), unit=k.unit_text(lang),
                                    range=k.range_text(lang), default=k.default_text(lang),
                                    help=k.help(lang), required=k.required,
                                    choices=tuple(k.choices or ((True, False)
                                                                if k.kind == "bool" else ())),
                                    multiline=((k.kind == "numbers" and tpath == "pressure")
                                               or k.kind == "points")))
        if fields:
            out.append(Section(tpath, t(f"spec.{tab.text_path}.title"), tuple(fields)))
    return out


# ----------------------------------------------------------------------------- dict -> texts
def _text(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return ", ".join(_text(v) for v in value)
    return str(value)


def _get(data, path):
    node = data
    for part in path.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node


_BARE = re.compile(r"[A-Za-z0-9_-]+")


def _inline(v) -> str:
    """A value as TOML writes it on one line (an array or table inline)."""
    import json
    import math

    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")) \
            if not math.isfinite(v) else repr(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_inline(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k if _BARE.fullmatch(str(k)) else json.dumps(str(k))} = "
                               f"{_inline(x)}" for k, x in v.items()) + "}"
    return json.dumps(str(v), ensure_ascii=False)


def values_from_spec(data: dict, schema=None) -> tuple[dict, str]:
    """``(field texts, pressure source)`` of a spec dict: every key of the schema found in
    it as the text its field shows (floats by ``repr``, so they read back exactly)."""
    from crankbase.schema import ArrayOfTables

    values = {}
    schema = _schema(schema)
    for tpath, tab in _tables(schema, _link_names(schema, _names_in_spec(data))):
        if isinstance(tab, ArrayOfTables):
            rows = _get(data, tpath)
            if isinstance(rows, list):
                names = [k.name for k in tab.keys()]
                if _plain_rows(tab):
                    values[tpath] = "\n".join(
                        ", ".join(_text(r.get(n, "")) for n in names) if isinstance(r, dict)
                        else _text(r) for r in rows)
                else:
                    values[tpath] = "\n".join(
                        ", ".join(f"{k} = {_inline(v)}" for k, v in r.items())
                        if isinstance(r, dict) else _text(r) for r in rows)
            continue
        for k in tab.keys():
            path = f"{tpath}.{k.name}"
            v = _get(data, path)
            if v is None or path == FILE_KEY:
                continue
            if k.kind == "points" and isinstance(v, dict):
                values[path] = "\n".join(f"{n} = {_text(xy)}" for n, xy in v.items())
            else:
                values[path] = _text(v)
    pr = data.get("pressure") if isinstance(data.get("pressure"), dict) else {}
    source = ("file" if "file" in pr else "cycle" if "cycle" in pr or not pr else "table")
    return values, source


# ----------------------------------------------------------------------------- texts -> dict
def _number(text: str):
    """A number read as TOML would (``4`` an integer, ``4.0`` a float); a decimal comma
    is a point; anything else stays text, for the library to name."""
    s = text.strip()
    if _INT.fullmatch(s):
        return int(s)
    try:
        return float(s.replace(",", "."))
    except ValueError:
        return s


def _numbers(text: str) -> list:
    return [_number(s) for s in _SPLIT.split(text.strip()) if s]


def _put(data, path, value):
    *parents, name = path.split(".")
    node = data
    for p in parents:
        node = node.setdefault(p, {})
    node[name] = value


def _inline_row(line: str):
    """One line of an array of tables: the inside of a TOML inline table; a line that is
    not one stays text (the library names it: not a table)."""
    import tomllib

    try:
        return tomllib.loads("x = {" + line + "}")["x"]
    except tomllib.TOMLDecodeError:
        return line


def _points(text: str):
    """``name = x, y`` lines as ``{name: [x, y]}`` (a line without ``=`` stays text)."""
    out = {}
    for line in text.splitlines():
        if not line.strip():
            continue
        name, eq, rest = line.partition("=")
        if not eq:
            return text
        out[name.strip()] = _numbers(rest)
    return out


def spec_from_values(values: dict, source: str = "cycle", pressure_file: str | None = None,
                     schema=None) -> dict:
    """The spec dict of the posted field texts (empty fields left out, so the library's
    defaults and "missing" problems apply); the pressure keys of the chosen ``source``
    only, with ``pressure.file`` the server's own name of the uploaded file for "file"."""
    from crankbase.schema import ArrayOfTables

    data: dict = {}
    schema = _schema(schema)
    engine = schema.name == "engine"
    for tpath, tab in _tables(schema, _link_names(schema, _names_in_values(values))):
        in_pressure = engine and (tpath == "pressure" or tpath.startswith("pressure."))
        if isinstance(tab, ArrayOfTables):
            text = (values.get(tpath) or "").strip()
            if text:
                names = [k.name for k in tab.keys()]
                rows = []
                for line in text.splitlines():
                    if not line.strip():
                        continue
                    if _plain_rows(tab):
                        rows.append(dict(zip(names, _numbers(line))))
                    else:
                        rows.append(_inline_row(line))
                _put(data, tpath, rows)
            continue
        for k in tab.keys():
            path = f"{tpath}.{k.name}"
            if engine and path == FILE_KEY:
                continue
            if in_pressure:
                if tpath == "pressure.cycle" and source != "cycle":
                    continue
                if tpath == "pressure" and (
                        (source == "table" and k.name == "firing_tdc_deg")
                        or (source == "file" and k.name != "firing_tdc_deg")
                        or source == "cycle"):
                    continue
            text = (values.get(path) or "").strip()
            if not text:
                continue
            if k.kind in ("number", "integer"):
                value = _number(text)
            elif k.kind == "numbers":
                value = _numbers(text)
            elif k.kind == "bool":
                value = {"true": True, "false": False}.get(text.lower(), text)
            elif k.kind == "choice":
                value = next((c for c in k.choices if str(c) == text), text)
            elif k.kind == "points":
                value = _points(text)
            else:
                value = text
            _put(data, path, value)
    if engine and source == "file" and pressure_file:
        _put(data, FILE_KEY, pressure_file)
    return data


def problem_field(key, fields: set) -> str | None:
    """The form field a problem's key path belongs to (``engine.firing_order[2]`` →
    ``engine.firing_order``; ``balance.counterweight[0].z_mm`` → the counterweight rows),
    or None when it is no field's (it is then shown above the form)."""
    if not isinstance(key, str) or not key:
        return None
    path = key
    while path:
        plain = re.sub(r"\[\d+\]", "", path)
        if plain in fields:
            return plain
        for a in fields:
            if plain.startswith(a + ".") or plain == a:
                return a
        path = path.rpartition(".")[0]
    return None
