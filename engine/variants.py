"""Course variants: one base engine spec plus a table with one row per student variant.

The table (CSV or .xlsx, header in the first row) has a ``variant`` (or ``name``) column
and one column per spec key as a dotted path (``engine.bore_mm``, ``masses.rod_kg``,
``table.form`` …).  Each row overrides those keys of the base spec; an empty cell keeps
the base value.  A cell is read as a TOML value when it is one (``79``, ``0.275``,
``true``, ``[372, 375]``, ``"text"``) and as text otherwise.  Every problem of a row is
reported with its row number (as a spreadsheet shows it: the header is row 1) and key; a
bad row never stops the good ones.  Reports are written by the CLI
(``crankdyn engine --variants``); this module reads, applies and summarises only.
"""
from __future__ import annotations

import copy
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from crankbase.errors import Problem, SpecError

__all__ = ["VariantRow", "read_variants", "parse_cell", "apply_variant", "load_variant",
           "SUMMARY_FIELDS", "summary_record", "NAME_COLUMNS"]

#: Column names that name a variant (case-insensitive), in order of preference.
NAME_COLUMNS = ("variant", "name")


@dataclass
class VariantRow:
    """One variant: its row in the file (header = row 1), its name and the overrides."""

    row: int
    variant: str
    values: dict = field(default_factory=dict)


def parse_cell(value):
    """A table cell as a spec value: numbers stay numbers (integral floats from a
    spreadsheet become ints), text is parsed as a TOML value when it is one, else kept
    as text; an empty cell is ``None`` (keep the base value)."""
    if value is None:
        return None
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, float)):
        if isinstance(value, float) and math.isfinite(value) and value.is_integer():
            return int(value)
        return value
    text = str(value).strip()
    if not text:
        return None
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def _read_rows(path: Path):
    """Header and rows of the first sheet (.xlsx) or of a CSV (``,`` or ``;``)."""
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        from openpyxl import load_workbook

        wb = load_workbook(path, read_only=True, data_only=True)
        rows = [list(r) for r in wb.worksheets[0].iter_rows(values_only=True)]
        wb.close()
    else:
        import csv

        text = path.read_text(encoding="utf-8-sig")
        head = text.splitlines()[0] if text.strip() else ""
        delim = ";" if head.count(";") > head.count(",") else ","
        rows = list(csv.reader(text.splitlines(), delimiter=delim))
    rows = [r for r in rows if any(v not in (None, "") for v in r)]
    if not rows:
        raise SpecError(Problem(str(path), "the variants table is empty"))
    return [("" if h is None else str(h).strip()) for h in rows[0]], rows[1:]


def read_variants(path) -> list[VariantRow]:
    """Read a variants table.

    Parameters
    ----------
    path : str or Path
        CSV (UTF-8, ``,`` or ``;`` separated) or .xlsx (first sheet).

    Returns
    -------
    list of VariantRow

    Raises
    ------
    SpecError
        The file is missing or empty, has no ``variant``/``name`` column, a column header
        is empty or repeated, or a variant name is empty or repeated (all at once).
    """
    path = Path(path)
    if not path.is_file():
        raise SpecError(Problem(str(path), "variants file does not exist"))
    header, rows = _read_rows(path)
    problems = []
    lower = [h.lower() for h in header]
    name_col = next((lower.index(n) for n in NAME_COLUMNS if n in lower), None)
    if name_col is None:
        problems.append(Problem(str(path), "no 'variant' (or 'name') column; columns: "
                                + ", ".join(header)))
    for j, h in enumerate(header):
        if not h:
            problems.append(Problem(str(path), f"column {j + 1} has no header"))
        elif lower.count(h.lower()) > 1 and lower.index(h.lower()) == j:
            problems.append(Problem(str(path), f"column {h!r} appears more than once"))
    if problems:
        raise SpecError(problems)
    out, seen = [], {}
    for i, r in enumerate(rows, start=2):
        r = list(r) + [None] * (len(header) - len(r))
        name = "" if r[name_col] is None else str(r[name_col]).strip()
        if isinstance(r[name_col], float) and r[name_col].is_integer():
            name = str(int(r[name_col]))
        if not name:
            problems.append(Problem(f"row {i}", f"column {header[name_col]!r} is empty"))
            continue
        if name in seen:
            problems.append(Problem(f"row {i}", f"variant {name!r} repeats row {seen[name]}"))
            continue
        seen[name] = i
        values = {}
        for j, h in enumerate(header):
            if j == name_col:
                continue
            v = parse_cell(r[j])
            if v is not None:
                values[h] = v
        out.append(VariantRow(i, name, values))
    if problems:
        raise SpecError(problems)
    return out


def apply_variant(base: dict, variant: VariantRow) -> dict:
    """The base spec dict with the variant's dotted keys set (a deep copy).  Without an
    ``engine.name`` column the engine is named after the variant.

    Raises
    ------
    SpecError
        A dotted path runs through a value that is not a table (``row N: key: …``).
    """
    spec = copy.deepcopy(base)
    problems = []
    values = dict(variant.values)
    values.setdefault("engine.name", variant.variant)
    for key, value in values.items():
        parts = key.split(".")
        node = spec
        for k, part in enumerate(parts[:-1]):
            nxt = node.setdefault(part, {})
            if not isinstance(nxt, dict):
                problems.append(Problem(f"row {variant.row}: {key}", f"{'.'.join(parts[:k + 1])}"
                                        " is a value, not a table"))
                break
            node = nxt
        else:
            node[parts[-1]] = value
    if problems:
        raise SpecError(problems)
    return spec


def load_variant(base: dict, variant: VariantRow, base_dir=None):
    """Apply a variant and validate it: an :class:`~engine.EngineStudy`, or a
    :class:`SpecError` whose every problem starts with ``row N (variant): key``."""
    from .spec import load

    try:
        return load(apply_variant(base, variant), base_dir=base_dir)
    except SpecError as exc:
        raise SpecError([Problem(f"row {variant.row} ({variant.variant})"
                                 + (f": {p.key}" if p.key and not p.key.startswith("row ")
                                    else ""), p.message) for p in exc.problems]) from None


#: Columns of the variants summary: (column, how it is obtained from spec and summary).
SUMMARY_FIELDS = ("variant", "name", "bore_mm", "stroke_mm", "lambda", "speed_rpm",
                  "mj_kg", "m_rod_rot_kg", "Kr_N", "p_max_MPa", "alpha_p_max_deg",
                  "P_max_N", "alpha_P_max_deg", "T_max_N", "alpha_T_max_deg", "T_min_N",
                  "M_mean_Nm", "R_max_N", "alpha_R_max_deg", "R_mean_N", "chi", "pi_MPa",
                  "power_i_kW")


def summary_record(variant: str, spec, summary) -> dict:
    """The key inputs and results of one variant, side by side with the others (values
    taken from the spec and from its :class:`~engine.EngineSummary`, nothing
    recomputed)."""
    s = summary
    return dict(
        variant=variant, name=spec.name, bore_mm=spec.bore * 1e3, stroke_mm=spec.stroke * 1e3,
        **{"lambda": spec.lam}, speed_rpm=spec.speed_rpm, mj_kg=spec.mj,
        m_rod_rot_kg=spec.m_rod_rot, Kr_N=spec.Kr, p_max_MPa=s.p_max_MPa,
        alpha_p_max_deg=s.alpha_p_max_deg, P_max_N=s.P_N.max,
        alpha_P_max_deg=s.P_N.alpha_max_deg, T_max_N=s.T_N.max,
        alpha_T_max_deg=s.T_N.alpha_max_deg, T_min_N=s.T_N.min, M_mean_Nm=s.M_mean_Nm,
        R_max_N=s.R_N.max, alpha_R_max_deg=s.R_N.alpha_max_deg, R_mean_N=s.R_mean_N,
        chi=s.chi, pi_MPa=s.pi_MPa, power_i_kW=s.power_i_kW)
