"""Workbook of a dynamics run (openpyxl): summary, motion table, forces under the true
motion beside the constant-speed ones, start-up.  Consumes computed results only."""
from __future__ import annotations

import math

from crankbase.output import paused_gc

__all__ = ["summary_rows", "summary_lines", "build_workbook", "column_label"]


def summary_rows(result, lang="en"):
    """(label, value, unit) rows of the summary, in the report language (``"ru"``: the
    Russian textbook symbols; ``"en"``: English, no Cyrillic letter); the same rows and
    values in both.  Words from the catalogue: the labels ``dynamics.row.<key>`` (Russian
    Jп, Mд, Mс, ΔT, Jм, ωср; English Jred, Md, Mc, ΔE, JF, ωm: the symbols of the plots;
    no Cyrillic in English), the units (:data:`crankbase.texts.UNITS`) by
    :meth:`~crankbase.texts.Texts.unit`."""
    from crankbase.texts import texts

    t = texts(lang)
    m, fly = result["motion"], result["flywheel"]
    keys = [("w_max", m.omega_max, "rad/s"), ("w_min", m.omega_min, "rad/s"),
            ("w_m", m.omega_mean, "rad/s"), ("w_t", m.omega_time_mean, "rad/s"),
            ("delta", m.delta, "-"), ("dT", m.dW_max, "J"), ("JF", m.J_flywheel, "kg·m²"),
            ("cycle", m.cycle_time, "s")]
    if m.M_drive_const is not None:
        if m.constant_role == "resist":
            keys.append(("Mc", -m.M_drive_const, "N·m"))
        else:
            keys.append(("Md", m.M_drive_const, "N·m"))
    if fly is not None:
        keys += [("delta_asked", fly.delta, "-"), ("dT_const", fly.dW_max, "J"),
                 ("Jc", fly.J_c, "kg·m²"), ("J_classic", fly.J_classic, "kg·m²"),
                 ("J_exact", fly.J_exact, "kg·m²")]
    if result.get("startup") is not None:
        keys.append(("startup", result["startup"].t_steady, "s"))
    return [(t(f"dynamics.row.{k}"), float(v), t.unit(u)) for k, v, u in keys]


def summary_lines(result, name=None, kind=None, driving=None, lang="en"):
    """The terminal summary of a dynamics run in ``lang``: the machine (``name``,
    ``kind``: machine, linkage or engine; ``driving``: constant, table or motor; taken
    from ``result`` when it is a :class:`dynamics.study.DynamicsReport`), the grid, then
    one line per row of :func:`summary_rows`, then what the run assumed (an engine spec
    without a [dynamics] δ).  Every number is formatted once, the same in both languages
    (a round-off zero never as −0); ru speaks Russian with the textbook symbols, en has
    no Cyrillic letter."""
    from crankbase.texts import texts
    from crankbase.tolerances import format_snapped

    t = texts(lang)
    name = name if name is not None else result.name
    kind = kind if kind is not None else result.kind
    driving = driving if driving is not None else result.driving
    m = result["motion"]
    span = f"{float(m.table['phi_rad'].iloc[-1]) * 180.0 / math.pi:g}"
    grid = t("dynamics.summary.grid", points=len(m.table), span=span)
    lines = [t("dynamics.summary.head", name=name, kind=t(f"dynamics.kind.{kind}"),
               driving=t(f"dynamics.driving.{driving}"), grid=grid)]
    lines += [f"  {label:<36} {format_snapped(value, '14.6g'):>14} {unit}"
              for label, value, unit in summary_rows(result, lang)]
    for note in getattr(result, "notes", ()):
        fly = result["flywheel"]
        lines.append("  " + t(f"dynamics.note.{note}",
                              delta=f"{fly.delta:g}" if fly is not None else ""))
    return lines


#: Column symbols of the tables: the CSV name without its unit → its catalogue key
#: (``dynamics.symbol.<name>``: Jп, Mд, Mс in Russian, J_red, M_d, M_c in English; a
#: language chooses its own by filling them).  A column not listed keeps its CSV symbol
#: (``R12_x``, ``M14``): the same in every language.
_SYMBOL = {name: f"dynamics.symbol.{name}" for name in (
    "phi", "alpha", "omega", "eps", "t", "J_red", "dJ_red_dphi", "M_drive", "M_resist",
    "W", "E", "j", "Pj", "P", "T", "K", "M", "R")}
#: Columns named by a symbol of :data:`_SYMBOL` in words (``dynamics.column.*``): "Mс от
#: нагрузок", "M_c of the loads".
_WORDED = {"M_resist_loads": ("M_resist", "dynamics.column.of_loads"),
           "M_resist_weights": ("M_resist", "dynamics.column.of_weights")}
#: The linkage's forces sheet: its M_drive is the balancing moment Mур (M_b) of the core.
_SYMBOL_FORCES = {"M_drive": "dynamics.symbol.M_balancing"}


def _unit_suffix(base: str):
    """``(name, unit)`` of a CSV column name without ``_const``: its unit suffix of
    :data:`linkage.report.COLUMN_UNITS` (the one column-suffix table, read by its one rule
    :func:`linkage.report.unit_suffix`) taken off, the unit a key of
    :data:`crankbase.texts.UNITS`; ``(base, None)`` without one.  The degree of a
    one-cell header ``φ [deg]`` is the table's ``"deg"`` (a word in English, the sign in
    Russian and Chinese), where the linkage's separate unit cell writes "°"."""
    from linkage.report import COLUMN_UNITS, unit_suffix

    split = unit_suffix(base)
    if split is None:
        return base, None
    name, suffix = split
    si = COLUMN_UNITS[suffix]
    return name, "deg" if si == "°" else si


def column_label(column: str, lang="en", symbols=None) -> str:
    """The header of a table column in the report language: ``omega_rad_s`` →
    ``ω, рад/с`` (ru) or ``ω [rad/s]`` (en); a ``_const`` column is the same quantity at
    ω = const.  ``symbols`` overrides :data:`_SYMBOL` entries (a catalogue key, or a
    ``(ru, en)`` pair chosen by :meth:`crankbase.texts.Texts.symbol`)."""
    from crankbase.texts import texts

    t = texts(lang)
    const = column.endswith("_const")
    base, si = _unit_suffix(column[:-len("_const")] if const else column)
    unit = None if si is None else t.unit(si)
    table = {**_SYMBOL, **(symbols or {})}

    def symbol(name):
        given = table[name]
        return t.symbol(*given) if isinstance(given, tuple) else t(given)

    if base in _WORDED:
        of, key = _WORDED[base]
        sym = t(key, symbol=symbol(of))
    else:
        sym = symbol(base) if base in table else base
    text = sym if unit is None else t("common.format.quantity_unit", symbol=sym, unit=unit)
    return text + (" (ω = const)" if const else "")


def _value_format(v: float) -> str:
    """An Excel number format showing ``v`` with about six significant digits."""
    if v == 0 or not math.isfinite(v):
        return "0"
    decimals = max(0, min(10, 5 - math.floor(math.log10(abs(v)))))
    return "0." + "0" * decimals if decimals else "0"


@paused_gc()                # tens of thousands of cells: no collection scans them
def build_workbook(result: dict, lang="en", name=None):
    """An openpyxl Workbook: a summary sheet (``name`` as its title when given), then the
    motion, forces and start-up tables with two header rows (the quantity in the report
    language, then the CSV column name); every sheet set up for A4.  Raises ValueError if
    any number is not finite."""
    from openpyxl import Workbook
    from openpyxl.styles import Font
    from openpyxl.utils import get_column_letter

    from crankbase.texts import texts
    from crankbase.workbook import header_rows

    tx = texts(lang)
    wb = Workbook()
    ws = wb.active
    ws.title = tx("sheet.dynamics.summary")
    if name is not None:
        ws.append([tx("sheet.dynamics.title", name=name)])
        ws["A1"].font = Font(bold=True, size=12)
    ws.append([tx("sheet.dynamics.quantity"), tx("sheet.dynamics.value"),
               tx("sheet.dynamics.unit")])
    head = ws.max_row
    for row in summary_rows(result, lang):
        if not math.isfinite(row[1]):
            raise ValueError(f"summary value {row[0]} is not finite")
        ws.append(list(row))
        ws.cell(ws.max_row, 2).number_format = _value_format(row[1])
    for c in ws[head]:
        c.font = Font(bold=True)
    ws.column_dimensions["A"].width = 38
    ws.column_dimensions["B"].width = 16
    ws.column_dimensions["C"].width = 10
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = "portrait"

    import numpy as np

    from crankbase.workbook import put_numbers, set_number_format

    def sheet(title, df, symbols=None):
        num = df.select_dtypes("number")
        if not np.all(np.isfinite(num.to_numpy())):
            raise ValueError(f"sheet {title}: a value is not finite")
        s = wb.create_sheet(title)
        header_rows(s, 1, [column_label(c, lang, symbols) for c in df.columns], df.columns)
        put_numbers(s, 3, 1, df.to_numpy(float).tolist())     # Python floats
        at, rows = s._cells, range(3, 3 + len(df))
        for j, col in enumerate(df.columns, start=1):
            letter = get_column_letter(j)
            s.column_dimensions[letter].width = 13
            # about six significant digits of the column's largest value (the cells keep
            # every digit: the CSV's numbers)
            fmt = _value_format(float(np.abs(df[col].to_numpy(float)).max()))
            set_number_format([at[(r, j)] for r in rows], fmt)   # put_numbers' cells
        # the labels wrap at the column width (13): room for their longest
        s.row_dimensions[1].height = 13 * max(math.ceil(len(c.value) / 9) for c in s[1])
        s.freeze_panes = "B3"
        s.print_title_rows = "1:2"
        s.print_title_cols = "A:A"          # φ (α) on every page of a wide sheet
        s.page_setup.paperSize = s.PAPERSIZE_A4
        s.page_setup.orientation = "landscape" if len(df.columns) > 8 else "portrait"

    sheet(tx("sheet.dynamics.motion"), result["motion"].table)
    if result.get("forces") is not None:
        sheet(tx("sheet.dynamics.forces"), result["forces"], _SYMBOL_FORCES)
    if result.get("startup") is not None:
        sheet(tx("sheet.dynamics.startup"), result["startup"].table)
    from crankbase.workbook import finish   # the one look and print setup of every workbook

    return finish(wb)
