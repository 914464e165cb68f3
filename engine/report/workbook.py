"""The Excel report of the engine force table, filled from a template.

The template (``templates/engine_<lang>.xlsx``, built by
``templates/build_engine_templates.py`` from the words of the catalogue
``crankbase/locale/<lang>/sheet.po``) owns the look and the text; this module only
writes numbers (never formulas) at full precision into it, matched by the keys in the
hidden column A of the Inputs and Summary sheets, copies the prototype row's style to every
table row, and adds native Excel charts.  It consumes a computed
:class:`engine.EngineResult`; it computes no physics.

Sheets, by position: 0 Inputs, 1 Table 2, 2 Summary, 3 Data (the CSV columns), 4 Charts;
with the whole engine (:func:`add_engine_sheets`) also 5 Layout, 6 Total torque, 7 Balance,
8 Flywheel; last, hidden, the charts' data: the native charts are drawn from the fine grid
of the summary (their extremes are the summary's), not from the table rows.  A table
longer than :data:`crankbase.workbook.MAX_ROWS` rows (a fine table step) is thinned on its
sheet, with a note; the CSVs keep every row.  :func:`a4_setup` gives the workbook the
house look (:func:`crankbase.workbook.finish`).
"""
from __future__ import annotations


import itertools
import math
import operator
from array import array

import numpy as np

from crankbase.errors import OutputError, Problem, Text
from crankbase.texts import OFFERED
from crankbase.output import paused_gc
from crankbase.workbook import A4_LANDSCAPE_PRINT_CM, filled_cells, sheet_rows, thinned_note

from ..forces import COLUMNS, SUMMARY_QUANTITIES
from ..spec import EngineSpecError
from ..symbols import mass_inputs, sym, symbol_set

__all__ = ["build_workbook", "add_engine_sheets", "save_workbook", "input_values",
           "TABLE2_FORCES", "LANGS"]

LANGS = OFFERED              # every offered language (crankbase.texts.languages)

#: Table 2 force pairs (mm, N), in the textbook order: (column of the force table).
TABLE2_FORCES = ("dPg_N", "Pj_N", "P_N", "S_N", "N_N", "K_N", "T_N", "R_N")

#: Column keys of the Table 2 sheet (its hidden row 5): α, (mm, N) × 8 forces, Mкр, Ψ.
TABLE2_KEYS = (("alpha_deg",) + tuple(k for f in TABLE2_FORCES for k in (f[:-2] + "_mm", f))
               + ("M_Nm", "psi_deg"))

#: Name of the sheet of Table 2 in Kolchin's form (``[table] form = "kolchin"``).
class _KolchinSheet(dict):
    def __missing__(self, lang):
        from crankbase.texts import texts

        self[lang] = texts(lang)("sheet.engine.kolchin_sheet")
        return self[lang]


KOLCHIN_SHEET = _KolchinSheet()

_T2_KEY_ROW = 5       # hidden row of column keys (inserted into the template's Table 2)
_T2_FIRST_ROW = 6     # first data row of Table 2 (rows 3–4: the two-row header)
_DATA_FIRST_ROW = 4   # first data row of the Data sheet (row 3: the CSV header)


def _text(value):
    return "—" if value is None else value


def input_values(result, lang="ru"):
    """The values of the Inputs sheet, by key (numbers in the report's units)."""
    from crankbase.texts import texts

    t = texts(lang)
    spec, settings, summary = result.spec, result.settings, result.summary
    cyc = spec.cycle
    yes, no = t("sheet.engine.yes"), t("sheet.engine.no")
    if spec.pressure_source == "cycle":
        src = t("sheet.engine.source.cycle")
    elif spec.pressure_source == "file":
        src = t("sheet.engine.source.file", name=spec.pressure_file.name)
    else:
        src = t.n("sheet.engine.source.inline", len(spec.pressure.angle_deg))
    accel = t(f"sheet.engine.acceleration.{spec.acceleration}")
    mass_input = mass_inputs(spec.mass_source, lang)
    v = {
        "name": spec.name, "strokes": spec.strokes, "cylinders": spec.cylinders,
        "bore_mm": spec.bore * 1e3, "stroke_mm": spec.stroke * 1e3, "R_mm": spec.R * 1e3,
        "L_mm": spec.L * 1e3, "lam": spec.lam, "speed_rpm": spec.speed_rpm,
        "omega": spec.omega, "v_mean": spec.piston_speed_mean, "p0_MPa": spec.p0 / 1e6,
        "area_cm2": spec.area * 1e4, "Vh_l": spec.Vh * 1e3,
        "compression_ratio": spec.epsilon, "acceleration": accel,
        "mass_input": mass_input, "mj": spec.mj, "m_rod_rot": spec.m_rod_rot,
        "m_crank_rot": spec.m_crank_rot, "Kr": spec.Kr, "mu_P": settings.force_scale,
        "step_deg": settings.step_deg,
        "extra_angles": ", ".join(f"{a:g}" for a in settings.extra_angles_deg) or None,
        "pressure_source": src, "pi": summary.pi_MPa, "power_i": summary.power_i_kW,
    }
    if cyc is not None:
        v.update(cycle_kind=t(f"sheet.engine.cycle.{cyc.kind}"), pa=cyc.pa / 1e6,
                 pr=cyc.pr / 1e6, n1=cyc.n1,
                 n2=cyc.n2, pc=cyc.pc / 1e6, pz=cyc.pz / 1e6, lambda_z=cyc.lambda_z,
                 rho=cyc.rho if cyc.kind == "diesel" else None,
                 rounding=(yes if cyc.rounding else no),
                 pi_theory=summary.pi_theory_MPa)
        if cyc.rounding:
            v["advance_deg"] = cyc.advance
            v.update({k: getattr(cyc, k) for k in (
                "pc_factor", "peak_factor", "peak_after_tdc_deg",
                "exhaust_opening_deg", "intake_opening_deg", "exhaust_closing_deg")})
    return v


def _put(cell, value):
    """Store ``value`` in ``cell``; a string always as text, never as a formula (a name
    may start with "=").  Floats keep every bit when the workbook is saved by
    :func:`save_workbook` (:func:`crankbase.output.full_precision_xlsx`)."""
    cell.value = value
    if isinstance(value, str):
        cell.data_type = "s"


def _fit_row(ws, cell, width=None):
    """Give the row of ``cell`` the height of its wrapped text (15 pt a line), from the
    text's length and the column's width (or ``width``, for merged cells) [characters]."""
    if not isinstance(cell.value, str):
        return
    width = width or ws.column_dimensions[cell.column_letter].width or 10
    lines = math.ceil(len(cell.value) * 1.1 / width)
    if lines > 1:
        ws.row_dimensions[cell.row].height = max(ws.row_dimensions[cell.row].height or 0,
                                                 15 * lines)


_new_array = array.__new__

#: {template path: ((its modification time, size), the workbook read from it, pickled)}.
_TEMPLATES = {}


def _template(path):
    """A fresh workbook of the template ``path``: read by openpyxl once per version of the
    file (its parse is most of the time of a report's build), then a copy unpickled from
    that (a tenth of the time; the same workbook, saved byte for byte the same)."""
    import os
    import pickle

    from openpyxl import load_workbook

    st = os.stat(path)
    stamp = (st.st_mtime_ns, st.st_size)
    got = _TEMPLATES.get(str(path))
    if got is None or got[0] != stamp:
        got = _TEMPLATES[str(path)] = (stamp, pickle.dumps(load_workbook(path),
                                                           pickle.HIGHEST_PROTOCOL))
    wb = pickle.loads(got[1])
    for ws in wb.worksheets:
        # a pickled defaultdict keeps its items, not its factory: openpyxl's own
        # (Worksheet._setup), which makes a row's or column's dimensions when first asked
        ws.row_dimensions.default_factory = ws._add_row
        ws.column_dimensions.default_factory = ws._add_column
    return wb


def _copy_style(src, dst):
    st = src._style         # copy.copy(st), the copy made in C (StyleArray's is Python)
    dst._style = None if st is None else _new_array(type(st), "i", st)


def _put_table(ws, r0, rows, proto):
    """Write ``rows`` from row ``r0``, column A, each cell (:func:`_put`) below the first
    row styled as the cell of ``proto`` (the template's first table row) of its column.
    Rows of numbers go in at once (:func:`crankbase.workbook.put_numbers`), their styles
    copied in C."""
    from openpyxl.styles.cell_style import StyleArray

    from crankbase.workbook import put_numbers

    if not all(v is None or type(v) in _PLAIN for row in rows for v in row):
        for i, rowvals in enumerate(rows):
            for j, val in enumerate(rowvals):
                c = ws.cell(r0 + i, j + 1)
                _put(c, val)
                if i:
                    _copy_style(proto[j], c)
        return
    put_numbers(ws, r0, 1, rows)
    cells = ws._cells
    styles = [p._style for p in proto]
    for i in range(1, len(rows)):
        r = r0 + i
        for j, st in zip(range(1, len(rows[i]) + 1), styles):
            cells[(r, j)]._style = None if st is None else _new_array(StyleArray, "i", st)


def _check_finite(values, where):
    for key, val in values.items():
        if isinstance(val, float) and not math.isfinite(val):
            raise OutputError(Text("errors.engine.report.not_finite",
                                   {"where": where, "key": key, "val": val}))


@paused_gc()            # tens of thousands of cells: no collection scans them
def build_workbook(result, lang="ru"):
    """Fill the report template with a computed force table.

    Parameters
    ----------
    result : EngineResult
        From :func:`engine.analyze` (its table must be finite; its settings must give
        the force scale μP).
    lang : {"ru", "en"}
        Template language (headers, labels, conventions).

    Returns
    -------
    openpyxl.Workbook
        In memory; write it with :func:`save_workbook`.
    """
    from openpyxl.chart import Reference, ScatterChart, Series

    from crankbase.output import ensure_finite
    from crankbase.resources import template_path

    if lang not in LANGS:
        raise EngineSpecError(Problem("lang", Text("errors.engine.report.valid",
                                                   {"lang": lang, "items": ', '.join(LANGS)})))
    spec, table, summary = result.spec, result.table, result.summary
    mu = result.settings.force_scale
    if mu is None:
        raise EngineSpecError(Problem("force_scale",
                                      Text("errors.engine.report.report_needs_force")))
    ensure_finite(table, "force table")
    full = table
    table = sheet_rows(table)          # at most MAX_ROWS rows (the CSV keeps every row)
    wb = _template(template_path(f"engine_{lang}.xlsx"))
    ws_in, ws_t2, ws_sum, ws_data, ws_ch = wb.worksheets[:5]

    # Inputs: fill column D by the key in column A
    values = input_values(result, lang)
    _check_finite(values, "inputs")
    for row in ws_in.iter_rows(min_row=4, max_col=4):
        key = row[0].value
        if key is None:
            continue
        _put(row[3], _text(values.get(key)))
        _fit_row(ws_in, row[3])

    # Table 2 (the seed's form, mm and N): a hidden row 5 holds the column keys, so that
    # `crankdyn check` reads a filled-in copy of this sheet; data start on row 6
    ws_t2.insert_rows(_T2_KEY_ROW)
    for j, key in enumerate(TABLE2_KEYS, start=1):
        _put(ws_t2.cell(_T2_KEY_ROW, j), key)
    ws_t2.row_dimensions[_T2_KEY_ROW].hidden = True
    _put(ws_t2["C2"], float(mu))
    proto = [ws_t2.cell(_T2_FIRST_ROW, c) for c in range(1, 2 * len(TABLE2_FORCES) + 4)]
    cols = [table["alpha_deg"].to_numpy()]
    for name in TABLE2_FORCES:
        n = table[name].to_numpy()
        cols += [n / mu, n]
    cols += [table["M_Nm"].to_numpy(), table["psi_deg"].to_numpy()]
    data = np.column_stack(cols)
    _put_table(ws_t2, _T2_FIRST_ROW, data.tolist(), proto)

    if len(table) < len(full):
        _put(ws_t2["E2"], thinned_note(full, table, "forces.csv", lang))
        ws_t2.merge_cells("E2:S2")

    # Summary
    extremes = set(SUMMARY_QUANTITIES)
    for row in ws_sum.iter_rows(min_row=4, max_col=7):
        key = row[0].value
        if key in extremes:
            e = summary.extreme(key)
            for cell, val in zip(row[3:7], (e.max, e.alpha_max_deg, e.min,
                                            e.alpha_min_deg)):
                _put(cell, float(val))
        elif key is not None and getattr(summary, key, None) is not None:
            _put(row[3], float(getattr(summary, key)))

    # Data: the CSV columns at full precision
    proto = [ws_data.cell(_DATA_FIRST_ROW, c) for c in range(1, len(COLUMNS) + 1)]
    if len(table) < len(full):
        _put(ws_data["A2"], thinned_note(full, table, "forces.csv", lang))
    for j, name in enumerate(COLUMNS):
        ws_data.cell(_DATA_FIRST_ROW - 1, j + 1, name)
    _put_table(ws_data, _DATA_FIRST_ROW, table[list(COLUMNS)].to_numpy().tolist(), proto)

    # Charts over α, from the fine grid (the summary's grid: the charts' extremes are
    # the summary's) on a hidden sheet, each series in its own colour and dash; two
    # charts per A4 page, none split by a page break
    from openpyxl.worksheet.pagebreak import Break

    cd = _chart_data(wb, lang)
    col, first, last = _put_columns(cd, result.curves, _CURVE_COLUMNS, 1)
    xref = Reference(cd, min_col=col["alpha_deg"], min_row=first, max_row=last)
    from crankbase.texts import texts

    tx = texts(lang)
    y = _CHART_SYMBOLS[symbol_set(lang)]
    N, Nm = tx("sheet.engine.newton"), tx("sheet.engine.newton_metre")
    charts = [
        (tx("sheet.engine.chart.forces_gas", dPg=y["dPg"]), N,
         [("dPg_N", y["dPg"]), ("Pj_N", "Pj"), ("P_N", "P")]),
        (tx("sheet.engine.chart.forces_crank"), N,
         [("N_N", "N"), ("K_N", "K"), ("T_N", "T")]),
        (tx("sheet.engine.chart.torque", M=y["M"]), Nm, [("M_Nm", y["M"])]),
        (tx("sheet.engine.chart.rod_pin", S=y["S"], R=y["R"]), N,
         [("S_N", y["S"]), ("R_N", y["R"])]),
    ]
    rows_per_chart = 20
    for k, (title, unit, series) in enumerate(charts):
        ch = ScatterChart()
        ch.title = title
        ch.x_axis.title = "α, °"
        ch.y_axis.title = unit
        ch.x_axis.scaling.min = 0
        ch.x_axis.scaling.max = spec.cycle_deg
        ch.x_axis.majorUnit = 90 if spec.cycle_deg > 360 else 30
        ch.x_axis.tickLblPos = "low"        # α labels below the plot, not on y = 0
        ch.x_axis.delete = False
        ch.y_axis.delete = False
        ch.legend.position = "b"
        ch.x_axis.number_format = "0"
        ch.y_axis.number_format = "0"
        for m, (name, label) in enumerate(series):
            yref = Reference(cd, min_col=col[name], min_row=first, max_row=last)
            s = Series(yref, xref, title=label)
            s.marker.symbol = "none"
            s.smooth = False
            _style_series(s, m)
            ch.series.append(s)
        ch.width, ch.height = 17, 8.5
        ws_ch.add_chart(ch, f"A{3 + rows_per_chart * k}")
        if k % 2 == 1:                              # two charts per A4 page, none split
            ws_ch.row_breaks.append(Break(id=2 + rows_per_chart * (k + 1)))
    row = 3 + rows_per_chart * len(charts)
    _polar_chart(ws_ch, cd, col, first, last, result.curves, spec, lang, row)
    # the print area: the title and the charts (17 cm ≈ 9 default columns; the polar
    # chart 17 × 19 cm ≈ 38 rows)
    ws_ch.print_area = f"A1:J{row + 38}"
    if result.settings.form == "kolchin":
        _kolchin_sheet(wb, result, lang)
    return wb


def _kolchin_sheet(wb, result, lang):
    """Table 2 in Kolchin's form (specific forces in MPa with tg β, 1/cos β,
    cos(α+β)/cos β, sin(α+β)/cos β; :func:`engine.table2.table2`) as the last sheet: row 3
    the column keys, data from row 4."""
    from openpyxl.styles import Font

    from ..table2 import table2

    t2 = sheet_rows(table2(result.table, result.spec, result.settings, "kolchin"))
    ws = wb.create_sheet(KOLCHIN_SHEET[lang])
    from crankbase.texts import texts

    tx = texts(lang)
    ws["A1"] = tx("sheet.engine.kolchin_title")
    ws["A1"].font = Font(bold=True, size=12)
    ws["A2"] = tx("sheet.engine.kolchin_area", area=result.spec.area * 1e4)
    for j, key in enumerate(t2.columns, start=1):
        c = ws.cell(3, j, key)
        c.font = Font(bold=True)
        ws.column_dimensions[c.column_letter].width = max(9, len(key) + 2)
    for i, rowvals in enumerate(t2.to_numpy().tolist(), start=4):
        for j, val in enumerate(rowvals, start=1):
            _put(ws.cell(i, j), val)
            ws.cell(i, j).number_format = "0.0000"
    ws.print_title_rows = "3:3"
    ws.freeze_panes = "B4"


#: Line colour, dash and width [EMU] of the 1st, 2nd, 3rd … series of every native chart:
#: colours of distinct lightness (Okabe–Ito blue, vermilion, black, green) and distinct
#: dash patterns, so the curves stay apart in grey-scale print.
CHART_STYLES = (("0072B2", "solid", 28575), ("D55E00", "dash", 28575),
                ("000000", "lgDashDot", 22225), ("009E73", "sysDot", 31750))

#: Colours and dashes of the thin per-cylinder series under a bold total.
_CYL_COLOURS = ("D55E00", "009E73", "CC79A7", "E69F00", "56B4E9", "000000", "7F7F7F",
                "4D4D4D", "F0E442", "999999", "8C510A", "01665E")
_CYL_DASHES = ("sysDot", "dash", "lgDashDot", "sysDash", "dashDot", "lgDash",
               "lgDashDotDot", "sysDashDot", "sysDashDotDot", "dot", "lgDashDot", "dash")

#: Symbols in the native charts: Russian textbook ones, English ones without Cyrillic.
_CHART_SYMBOLS = {lang: dict(dPg=sym("dPg", lang), M=sym("M", lang), S=sym("S", lang),
                             R=sym("R", lang), pole=sym("pole_R", lang))
                  for lang in ("ru", "en")}


def _style_series(s, m):
    """Give chart series number ``m`` its colour, dash and width (:data:`CHART_STYLES`)."""
    colour, dash, width = CHART_STYLES[m % len(CHART_STYLES)]
    s.graphicalProperties.line.solidFill = colour
    s.graphicalProperties.line.prstDash = dash
    s.graphicalProperties.line.width = width


#: Columns of the one-cylinder fine curves the native charts draw (hidden sheet).
_CURVE_COLUMNS = ("alpha_deg", "dPg_N", "Pj_N", "P_N", "N_N", "K_N", "T_N", "M_Nm", "S_N",
                  "R_N")


def _chart_data(wb, lang):
    """The hidden sheet of the native charts' data (the fine grid), created once."""
    from crankbase.texts import texts

    t = texts(lang)
    title = t("sheet.engine.chart_data")
    if title in wb.sheetnames:
        return wb[title]
    ws = wb.create_sheet(title)
    ws.sheet_state = "hidden"
    return ws


def _put_columns(ws, df, names, c0):
    """Write the columns ``names`` of ``df`` into ``ws`` from column ``c0`` (row 1 the
    CSV names, data from row 2), at most :data:`crankbase.workbook.MAX_ROWS` rows: a
    longer curve is thinned, its every column's largest and smallest row kept (so a chart
    drawn from it peaks where the summary says).  Returns ({name: column}, first row,
    last row)."""
    from crankbase.workbook import bounded, put_numbers

    arr = df[list(names)].to_numpy(float)
    keep = np.r_[np.argmax(arr, axis=0), np.argmin(arr, axis=0)]
    idx, _ = bounded(len(arr), keep=keep)
    col = {name: c0 + j for j, name in enumerate(names)}
    for j, name in enumerate(names):
        ws.cell(1, c0 + j, name)
    put_numbers(ws, 2, c0, arr[idx].tolist())
    return col, 2, 1 + len(idx)


def _polar_chart(ws_ch, cd, col, first, last, curves, spec, lang, row):
    """The polar diagram of the crank-pin load as a native, editable scatter chart: the
    locus of S = (T, K) on the fine grid (hidden sheet), +K downwards (reversed axis), the
    poles O and Oш = (0, −Kr.ш) as markers from the hidden sheet; both axes get the same
    span and the plot area is square (a manual layout of the chart's inner area), so the
    diagram keeps its shape."""
    from openpyxl.chart import Reference, ScatterChart, Series
    from openpyxl.chart.axis import ChartLines
    from openpyxl.chart.layout import Layout, ManualLayout
    from openpyxl.chart.marker import Marker
    from openpyxl.chart.shapes import GraphicalProperties

    from crankbase.texts import texts

    tx = texts(lang)
    y = _CHART_SYMBOLS[symbol_set(lang)]
    T = curves["T_N"].to_numpy(float)
    K = curves["K_N"].to_numpy(float)
    kr = spec.Kr
    # the poles, on the hidden sheet right of the curves
    pc = max(col.values()) + 2
    _put(cd.cell(1, pc), "T_N")
    _put(cd.cell(1, pc + 1), "K_N")
    for i, (name, tt, k) in enumerate((("O", 0.0, 0.0), (y["pole"], 0.0, -kr)), start=2):
        _put(cd.cell(i, pc), tt)
        _put(cd.cell(i, pc + 1), float(k))
        _put(cd.cell(i, pc + 2), name)
    ch = ScatterChart()
    ch.title = tx("sheet.engine.chart.polar", pole=y["pole"], R=y["R"])
    ch.x_axis.title = tx("sheet.engine.chart.polar_x")
    ch.y_axis.title = tx("sheet.engine.chart.polar_y")
    ch.y_axis.scaling.orientation = "maxMin"            # +K downwards, as in the textbook
    # a square inner plot area on a chart 17 cm wide: the title above, the legend below
    ch.width, ch.height = 17, 19
    side = 0.72
    ch.layout = Layout(manualLayout=ManualLayout(          # the plot area, without
        layoutTarget="inner", xMode="edge", yMode="edge",   # the axes' labels
        x=0.16, y=0.17, w=side, h=side * ch.width / ch.height))
    # equal scales: the same span on both axes, centred on the data, the same grid step
    xs_all, ys_all = np.r_[T, 0.0], np.r_[K, 0.0, -kr]
    span = 1.1 * max(np.ptp(xs_all), np.ptp(ys_all))
    step = 10 ** np.floor(np.log10(span / 4))
    while span / step > 7:          # at most nine labels an axis: six-digit
        step *= 2                   # newtons side by side ran into each other
    n_steps = np.ceil(span / step) + 1
    for ax, vals in ((ch.x_axis, xs_all), (ch.y_axis, ys_all)):
        mid = 0.5 * (vals.min() + vals.max())
        lo = float(np.floor((mid - n_steps * step / 2) / step) * step)
        if lo + n_steps * step < vals.max():
            lo += step
        ax.scaling.min = lo
        ax.scaling.max = float(lo + n_steps * step)
        ax.majorUnit = float(step)
        ax.majorGridlines = ChartLines()
        ax.number_format = "0"
        ax.delete = False
    ch.x_axis.tickLblPos = "high"        # the y axis is reversed: "high" is the bottom
    ch.y_axis.tickLblPos = "low"
    ch.legend.position = "b"
    xs = Reference(cd, min_col=col["T_N"], min_row=first, max_row=last)
    ys = Reference(cd, min_col=col["K_N"], min_row=first, max_row=last)
    s = Series(ys, xs, title=f"{y['S']} (T, K)")
    s.marker.symbol = "none"
    s.smooth = False
    _style_series(s, 0)
    ch.series.append(s)
    px = Reference(cd, min_col=pc, min_row=2, max_row=3)
    py = Reference(cd, min_col=pc + 1, min_row=2, max_row=3)
    poles = Series(py, px, title=f"O, {y['pole']}")
    colour = CHART_STYLES[2][0]
    poles.marker = Marker(symbol="square", size=8)
    poles.marker.graphicalProperties = GraphicalProperties(solidFill=colour)
    poles.marker.graphicalProperties.line.solidFill = colour
    poles.graphicalProperties.line.noFill = True          # markers only
    ch.series.append(poles)
    ws_ch.add_chart(ch, f"A{row}")


def a4_setup(wb):
    """The house look and print setup of every sheet of ``wb``
    (:func:`crankbase.workbook.finish`: one font family, one number format per table
    column, widths from the content, wrapped rows tall enough, A4).  Returns ``wb``."""
    from crankbase.workbook import finish

    return finish(wb)


def save_workbook(wb, path):
    """Save a workbook atomically, every float bit for bit (:func:`crankbase.workbook.save`)."""
    from crankbase.workbook import save

    save(wb, path)


# ------------------------------------------------------------------ the whole engine

#: The shape of the words of the whole engine's sheets; the words are in the catalogue
#: ``crankbase/locale/<lang>/sheet.po`` under ``sheet.engine.<name>``: a text, a tuple
#: (``.<i>``), a mapping (``.<key>``) or rows of (key, label, unit) (the label
#: ``.<key>``; the unit given here, a key of :data:`crankbase.texts.UNITS`: "deg" is the
#: degree of a unit column, "" none).
_TR_SHAPE = {'alpha': 'str',
 'arrangements': ('dict', ('inline', 'vee', 'boxer')),
 'bal_cols': ('tuple', 5),
 'bal_data': 'str',
 'bal_title': 'str',
 'balance': 'str',
 'chart': 'str',
 'conv': ('tuple', 4),
 'cw_cols': ('tuple', 3),
 'cw_designs': ('dict', ('none', 'throws', 'throws+first_order')),
 'cw_given': 'str',
 'cw_none': 'str',
 'cw_title': 'str',
 'cyl': 'str',
 'data_title': 'str',
 'default_throws': 'str',
 'flywheel': 'str',
 'fw_none': 'str',
 'fw_note': 'str',
 'fw_rows': ('rows',
             {'L_excess_J': 'J', 'delta': '', 'omega': 'rad/s', 'J0_kgm2': 'kg·m²',
              'share': '', 'J_flywheel_kgm2': 'kg·m²', 'mD2_kgm2': 'kg·m²',
              'diameter_m': 'm', 'mass_kg': 'kg', 'rim_speed_m_s': 'm/s'}),
 'fw_title': 'str',
 'given': 'str',
 'inputs': 'str',
 'layout': 'str',
 'layout_cols': ('tuple', 7),
 'layout_title': 'str',
 'no': 'str',
 'parts': ('dict', ('1', '2', 'j', 'r', 'cw', 'before', 'after')),
 'summary': ('rows',
             {'M_mean_Nm': 'N·m', 'M_max_Nm': 'N·m', 'alpha_M_max_deg': 'deg',
              'M_min_Nm': 'N·m', 'alpha_M_min_deg': 'deg', 'mu': '', 'Mi_Nm': 'N·m',
              'Me_Nm': 'N·m', 'Ni_kW': 'kW', 'Ne_kW': 'kW', 'diff_pct': '%'}),
 'torque': 'str',
 'torque_title': 'str',
 'torque_title_odd': 'str',
 'total': 'str',
 'train_items': ('rows',
                 {'arrangement': '', 'vee_angle_deg': 'deg', 'firing_order': '',
                  'throw_angles_deg': 'deg', 'cylinder_spacing_mm': 'mm',
                  'bank_offset_mm': 'mm', 'mechanical_efficiency': '', 'delta': '',
                  'counterweights': ''}),
 'yes': 'str'}


class _Lazy(dict):
    """The words of :data:`_TR_SHAPE` by language, read from the catalogue when first
    asked (:func:`crankbase.workbook.words`, ``sheet.engine.*``)."""

    def __missing__(self, lang):
        from crankbase.workbook import words

        self[lang] = words(lang, "sheet.engine", _TR_SHAPE)
        return self[lang]


_TR = _Lazy()

def _write_rows(ws, r0, c0, rows, bold=False):
    from openpyxl.styles import Font
    from openpyxl.styles.cell_style import StyleArray

    from crankbase.workbook import put_numbers

    font_id = None
    plain = []                  # a run of rows of numbers (and None): one put_numbers
    for i, row in enumerate(rows):
        values = [float(v) if isinstance(v, (np.floating, np.integer)) and not
                  isinstance(v, np.bool_) else v for v in row]
        if not bold and all(v is None or type(v) in _PLAIN for v in values):
            plain.append(values)                    # the cells _put makes, at once
            continue
        if plain:
            put_numbers(ws, r0 + i - len(plain), c0, plain)
            plain = []
        for j, v in enumerate(values):
            cell = ws.cell(r0 + i, c0 + j)
            _put(cell, v)
            if bold:
                if font_id is None:
                    cell.font = Font(bold=True)
                    font_id = cell._style[0]
                else:               # the same font: its id, as openpyxl's setter sets it
                    st = cell._style
                    if not st:
                        st = cell._style = StyleArray()
                    st[0] = font_id
    if plain:
        put_numbers(ws, r0 + len(rows) - len(plain), c0, plain)
    return r0 + len(rows)


#: The types a value of :func:`_write_rows` goes to :func:`crankbase.workbook.put_numbers`
#: with (a bool is no number there; a text is stored by :func:`_put`).
_PLAIN = (float, int)


def readable_numbers(ws, widths=None, default_width=None, per_column=True):
    """Display every number of ``ws`` with the digits a reader needs; the stored value
    keeps full precision, so a sheet read back still equals the CSV.

    ``per_column``: one format for a whole column, from its largest magnitude (a table
    reads with aligned decimals; a round-off residue such as 1e-11 N of a balanced force
    shows as 0); else each number by its own magnitude (a list of results).  Bold header
    cells wrap; ``widths`` maps column letters to widths, ``default_width`` applies to
    every other used column."""
    from openpyxl.styles import Alignment
    from openpyxl.utils import get_column_letter

    from openpyxl.styles.cell_style import StyleArray

    from crankbase.workbook import CellStyles, set_number_format

    def fmt(a):
        return "0" if a >= 1e5 else "0.0" if a >= 1e3 else "0.00" if a >= 1 else "0.0000"

    cells = filled_cells(ws)
    by_column = {}                  # {column: its numbers}, columns in the order first met
    for c in cells:
        v = c._value
        if type(v) in _PLAIN or (isinstance(v, (int, float)) and not isinstance(v, bool)):
            got = by_column.get(c.column)
            if got is None:
                by_column[c.column] = [c]
            else:
                got.append(c)
    top, whole = {}, {}
    for col, group in by_column.items():
        values = [c._value for c in group]
        top[col] = max(itertools.chain((0.0,), map(abs, values)))
        whole[col] = all(map(float.is_integer, map(float, values)))
    by_format = {}                  # {format: cells}, formats in the order first met
    if per_column:                  # a column's first number comes first in its format
        for col, group in by_column.items():
            by_format.setdefault("0" if whole[col] else fmt(top[col]), []).extend(group)
    else:
        for c in cells:
            v = c._value
            if c.column not in by_column or not (type(v) in _PLAIN or (
                    isinstance(v, (int, float)) and not isinstance(v, bool))):
                continue
            if whole[c.column] or float(v).is_integer():
                by_format.setdefault("0", []).append(c)
            else:
                by_format.setdefault(fmt(abs(v)), []).append(c)
    for f, group in by_format.items():
        set_number_format(group, f)
    heads = {}                      # {font id: a header's font (bold, not a title's)}
    styles = CellStyles(ws.parent)
    wrap = Alignment(wrap_text=True, vertical="top")
    for c in cells:
        if isinstance(c._value, str):
            st = c._style
            if st is None:          # as reading c.font does: the text gets its style ids
                st = c._style = StyleArray()
            head = heads.get(st[0])
            if head is None:
                f = c.font
                head = heads[st[0]] = bool(f.b and not (f.sz and f.sz > 11))
            if head:                # headers, not titles
                styles(c, alignment=wrap)
    if default_width:
        last = max(map(operator.itemgetter(1), ws._cells), default=1)   # ws.max_column
        for j in range(1, last + 1):
            ws.column_dimensions[get_column_letter(j)].width = default_width
    for col, w in (widths or {}).items():
        ws.column_dimensions[col].width = w


@paused_gc()
def add_engine_sheets(wb, tr, lang="ru"):
    """Add the whole engine's sheets to a report workbook: the layout, the total-torque
    table (one firing interval, or the cycle for an odd-firing engine) with the summary
    and a native chart, the balance table and its data, and the flywheel.  The Inputs
    sheet gains the crank train and its conventions.

    Parameters
    ----------
    wb : openpyxl.Workbook
        From :func:`build_workbook`.
    tr : EngineTrainResult
        From :func:`engine.analyze_engine`.
    lang : {"ru", "en"}
    """
    from openpyxl.chart import Reference, ScatterChart, Series
    from openpyxl.styles import Alignment, Font

    from crankbase.output import ensure_finite
    from crankbase.texts import texts

    if lang not in LANGS:
        raise EngineSpecError(Problem("lang", Text("errors.engine.report.valid",
                                                   {"lang": lang, "items": ', '.join(LANGS)})))
    t = _TR[lang]
    for df, what in ((tr.torque, "torque"), (tr.balance, "balance"),
                     (tr.layout.cylinders, "layout")):
        ensure_finite(df, what)
    lay, s = tr.layout, tr.summary
    yes, no = t["yes"], t["no"]

    # Inputs: the crank train and the conventions, below the template's rows
    ws_in = wb.worksheets[0]
    r = ws_in.max_row + 2
    proto = [ws_in.cell(4, c) for c in range(2, 6)]      # the template's first input row
    ws_in.cell(r, 2, t["inputs"]).font = Font(name=proto[0].font.name, bold=True)
    train = tr.train
    how = {"given": t["given"], "default for even firing": t["default_throws"]}
    cw = (t["cw_designs"][train.counterweights] if not train.counterweight_list
          else t["cw_given"].format(n=len(train.counterweight_list)))
    values = dict(
        arrangement=t["arrangements"][train.arrangement],
        vee_angle_deg=train.vee_angle_deg,
        firing_order="-".join(map(str, lay.firing_order)),
        throw_angles_deg=(", ".join(f"{x:g}" for x in lay.throw_angles_deg)
                          + f" ({how[lay.crankshaft]})"),
        cylinder_spacing_mm=(None if train.cylinder_spacing is None
                             else train.cylinder_spacing * 1e3),
        bank_offset_mm=train.bank_offset * 1e3,
        mechanical_efficiency=train.mechanical_efficiency,
        delta=train.delta, counterweights=cw)
    items = t["train_items"]
    for i, (key, label, unit) in enumerate(items, start=1):
        ws_in.cell(r + i, 1, key)
        for j, v in enumerate((label, None, _text(values[key]), unit or None)):
            c = ws_in.cell(r + i, 2 + j)
            _copy_style(proto[j], c)
            _put(c, v)
        _fit_row(ws_in, ws_in.cell(r + i, 4))
    r += len(items) + 2
    widths = sum(ws_in.column_dimensions[c].width or 10 for c in "BCDE")
    for i, line in enumerate(t["conv"]):
        c = ws_in.cell(r + i, 2)
        _put(c, line)
        c.font = Font(name=proto[0].font.name, italic=True, size=10)
        c.alignment = Alignment(wrap_text=True, vertical="top")
        ws_in.merge_cells(start_row=r + i, start_column=2, end_row=r + i, end_column=5)
        _fit_row(ws_in, c, width=widths)

    # Layout
    ws = wb.create_sheet(t["layout"])
    ws["A1"] = t["layout_title"]
    ws["A1"].font = Font(bold=True, size=12)
    _write_rows(ws, 3, 1, [t["layout_cols"]], bold=True)
    _write_rows(ws, 4, 1, lay.cylinders.to_numpy().tolist())
    readable_numbers(ws, dict(zip("ABCDEFG", (10, 8, 8, 12, 16, 18, 12))))

    # Total torque: the textbook table, the summary, the whole-cycle data and a chart
    ws = wb.create_sheet(t["torque"])
    n = lay.n
    ws["A1"] = (t["torque_title"].format(th=lay.firing_interval_deg) if lay.even_firing
                else t["torque_title_odd"])
    ws["A1"].font = Font(bold=True, size=12)
    head = [t["alpha"]] + [t["cyl"].format(j=j) for j in range(1, n + 1)] + [t["total"]]
    _write_rows(ws, 3, 1, [head], bold=True)
    end = _write_rows(ws, 4, 1, sheet_rows(tr.torque_table).to_numpy().tolist())
    rows = []
    for key, label, unit in t["summary"]:
        v = getattr(s, key)
        rows.append((label, v if v is None or isinstance(v, str) else float(v), unit))
    _write_rows(ws, end + 1, 1, [(lab, _text(v), u) for lab, v, u in rows])
    c0 = n + 4
    ws.cell(2, c0, t["data_title"]).font = Font(bold=True)
    ws.merge_cells(start_row=2, start_column=c0, end_row=2,
                   end_column=c0 + len(tr.torque.columns) - 1)
    _write_rows(ws, 3, c0, [list(tr.torque.columns)], bold=True)
    torque = sheet_rows(tr.torque)
    if len(torque) < len(tr.torque):
        _put(ws.cell(1, c0), thinned_note(tr.torque, torque, "torque.csv", lang))
        ws.merge_cells(start_row=1, start_column=c0, end_row=1,
                       end_column=c0 + len(tr.torque.columns) - 1)
    _write_rows(ws, 4, c0, torque.to_numpy().tolist())
    # the chart: from the fine grid (the summary's), on the hidden sheet right of the
    # one-cylinder curves
    cd = _chart_data(wb, lang)
    names = [c for c in tr.curves.columns if c.startswith("M_") or c == "alpha_deg"]
    last_col = max(map(operator.itemgetter(1), cd._cells), default=1)    # cd.max_column
    col, first, last = _put_columns(cd, tr.curves, names, last_col + 2)
    ch = ScatterChart()
    ch.title = t["chart"]
    ch.x_axis.title = t["alpha"]
    ch.y_axis.title = texts(lang).unit("N·m")
    ch.x_axis.scaling.min, ch.x_axis.scaling.max = 0, lay.cycle_deg
    ch.x_axis.majorUnit = 90 if lay.cycle_deg > 360 else 45
    ch.x_axis.tickLblPos = "low"
    ch.x_axis.delete = ch.y_axis.delete = False
    ch.legend.position = "b"
    xref = Reference(cd, min_col=col["alpha_deg"], min_row=first, max_row=last)
    for j in [n + 1] + list(range(1, n + 1)):
        name = str(tr.torque.columns[j])
        yref = Reference(cd, min_col=col[name], min_row=first, max_row=last)
        ser = Series(yref, xref, title=head[j])      # ΣMкр, Н·м; Mкр 1, Н·м …
        ser.marker.symbol = "none"
        ser.smooth = False
        if j == n + 1:                       # the total: bold, the first chart style
            _style_series(ser, 0)
        else:                                # each cylinder: thin, its own colour and dash
            ser.graphicalProperties.line.solidFill = _CYL_COLOURS[(j - 1) % len(_CYL_COLOURS)]
            ser.graphicalProperties.line.prstDash = _CYL_DASHES[(j - 1) % len(_CYL_DASHES)]
            ser.graphicalProperties.line.width = 9525
        ch.series.append(ser)
    # as wide as the columns left of the torque.csv block (the widths measured as
    # finish() will measure them)
    from crankbase.workbook import columns_cm, fit_columns, fit_numbers

    fit_numbers(ws)
    fit_columns(ws)
    # no wider than an A4 landscape page prints (a wider chart was cut at the page's edge)
    ch.width = min(A4_LANDSCAPE_PRINT_CM, max(16.0, columns_cm(ws, 1, c0 - 2)))
    ch.height = 10
    at = end + len(rows) + 3
    ws.add_chart(ch, f"A{at}")
    from openpyxl.worksheet.pagebreak import Break

    ws.row_breaks.append(Break(id=at - 1))        # the chart starts a page: never split
    readable_numbers(ws, {"A": 34, "C": 12}, default_width=11)

    # Balance: amplitudes, counterweights, the data of balance.csv
    ws = wb.create_sheet(t["balance"])
    ws["A1"] = t["bal_title"]
    ws["A1"].font = Font(bold=True, size=12)
    _write_rows(ws, 3, 1, [t["bal_cols"]], bold=True)
    amp = [(t["parts"][p], f, m, yes if fb else no, yes if mb else no)
           for p, f, m, fb, mb in tr.balance_amplitudes.itertuples(index=False)]
    r = _write_rows(ws, 4, 1, amp) + 1
    ws.cell(r, 1, t["cw_title"]).font = Font(bold=True)
    if s.counterweights:
        _write_rows(ws, r + 1, 1, [t["cw_cols"]], bold=True)
        r = _write_rows(ws, r + 2, 1, [(c.z * 1e3, c.mr * 1e3, c.angle_deg)
                                       for c in s.counterweights]) + 1
    else:
        _put(ws.cell(r + 1, 1), t["cw_none"])
        r += 3
    ws.cell(r, 1, t["bal_data"]).font = Font(bold=True)
    _write_rows(ws, r + 1, 1, [list(tr.balance.columns)], bold=True)
    balance = sheet_rows(tr.balance)
    if len(balance) < len(tr.balance):
        _put(ws.cell(r, 1), t["bal_data"] + "; " + thinned_note(tr.balance, balance,
                                                            "balance.csv", lang))
    _write_rows(ws, r + 2, 1, balance.to_numpy().tolist())
    readable_numbers(ws, {"A": 40}, default_width=12)

    # Flywheel
    ws = wb.create_sheet(t["flywheel"])
    ws["A1"] = t["fw_title"]
    ws["A1"].font = Font(bold=True, size=12)
    fw = s.flywheel
    if fw is None:
        _put(ws["A3"], t["fw_none"])
        _write_rows(ws, 4, 1, [(t["fw_rows"][0][1], s.L_excess_J, t["fw_rows"][0][2])])
    else:
        vals = dict(fw.__dict__, omega=tr.cylinder.spec.omega)
        _write_rows(ws, 3, 1, [(lab, _text(vals[key]), unit)
                               for key, lab, unit in t["fw_rows"]])
        _put(ws.cell(4 + len(t["fw_rows"]), 1), t["fw_note"])
    readable_numbers(ws, {"A": 55, "B": 16}, per_column=False)
    return wb
