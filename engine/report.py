"""The Excel report of the engine force table, filled from a template.

The template (``templates/engine_<lang>.xlsx``, built by
``templates/build_engine_templates.py``) owns the look and the text; this module only
writes numbers (never formulas) at full precision into it, matched by the keys in the
hidden column A of the Inputs and Summary sheets, copies the prototype row's style to every
table row, and adds native Excel charts.  It consumes a computed
:class:`engine.EngineResult`; it computes no physics.

Sheets, by position: 0 Inputs, 1 Table 2, 2 Summary, 3 Data (the CSV columns), 4 Charts;
with the whole engine (:func:`add_engine_sheets`) also 5 Layout, 6 Total torque, 7 Balance,
8 Flywheel.
"""
from __future__ import annotations

import copy
import math

import numpy as np

from crankbase.errors import OutputError, Problem, Text

from .forces import COLUMNS, SUMMARY_QUANTITIES
from .spec import EngineSpecError
from .symbols import mass_inputs, sym

__all__ = ["build_workbook", "add_engine_sheets", "save_workbook", "input_values",
           "TABLE2_FORCES", "LANGS"]

LANGS = ("ru", "en")

#: Table 2 force pairs (mm, N), in the textbook order: (column of the force table).
TABLE2_FORCES = ("dPg_N", "Pj_N", "P_N", "S_N", "N_N", "K_N", "T_N", "R_N")

#: Column keys of the Table 2 sheet (its hidden row 5): α, (mm, N) × 8 forces, Mкр, Ψ.
TABLE2_KEYS = (("alpha_deg",) + tuple(k for f in TABLE2_FORCES for k in (f[:-2] + "_mm", f))
               + ("M_Nm", "psi_deg"))

#: Name of the sheet of Table 2 in Kolchin's form (``[table] form = "kolchin"``).
KOLCHIN_SHEET = {"ru": "Таблица 2 (Колчин)", "en": "Table 2 (Kolchin)"}

_T2_KEY_ROW = 5       # hidden row of column keys (inserted into the template's Table 2)
_T2_FIRST_ROW = 6     # first data row of Table 2 (rows 3–4: the two-row header)
_DATA_FIRST_ROW = 4   # first data row of the Data sheet (row 3: the CSV header)


def _text(value):
    return "—" if value is None else value


#: The kind of the thermal cycle ([pressure.cycle] kind) in words.
_CYCLE_KINDS = {
    "ru": {"otto": "с подводом теплоты при V = const (Отто)",
           "diesel": "смешанный, подвод теплоты при V = const и p = const (Тринклер)"},
    "en": {"otto": "heat added at constant volume (Otto)",
           "diesel": "dual: heat added at constant volume and pressure (Sabathé)"},
}


def input_values(result, lang="ru"):
    """The values of the Inputs sheet, by key (numbers in the report's units)."""
    spec, settings, summary = result.spec, result.settings, result.summary
    cyc = spec.cycle
    yes, no = ("да", "нет") if lang == "ru" else ("yes", "no")
    if spec.pressure_source == "cycle":
        src = ("по тепловому расчёту ([pressure.cycle])" if lang == "ru"
               else "from the thermal calculation ([pressure.cycle])")
    elif spec.pressure_source == "file":
        src = (f"таблица давлений {spec.pressure_file.name}" if lang == "ru"
               else f"pressure table {spec.pressure_file.name}")
    else:
        n = len(spec.pressure.angle_deg)
        src = (f"таблица давлений в спецификации ({n} точек)"
               if lang == "ru" else f"inline pressure table ({n} points)")
    accel = {"two-term": ("двучленная: j = Rω²(cos α + λ cos 2α)" if lang == "ru"
                          else "two-term: j = Rω²(cos α + λ cos 2α)"),
             "exact": ("точная (группа Ассура RRP)" if lang == "ru"
                       else "exact (RRP Assur group)")}[spec.acceleration]
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
        v.update(cycle_kind=_CYCLE_KINDS[lang][cyc.kind], pa=cyc.pa / 1e6,
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


def _copy_style(src, dst):
    dst._style = copy.copy(src._style)


def _check_finite(values, where):
    for key, val in values.items():
        if isinstance(val, float) and not math.isfinite(val):
            raise OutputError(Text("errors.engine.report.not_finite",
                                   {"where": where, "key": key, "val": val}))


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
    from openpyxl import load_workbook
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
    wb = load_workbook(template_path(f"engine_{lang}.xlsx"))
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
    for i, rowvals in enumerate(data.tolist()):
        r = _T2_FIRST_ROW + i
        for j, val in enumerate(rowvals):
            c = ws_t2.cell(r, j + 1)
            _put(c, val)
            if i:
                _copy_style(proto[j], c)

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
    for j, name in enumerate(COLUMNS):
        ws_data.cell(_DATA_FIRST_ROW - 1, j + 1, name)
    for i, rowvals in enumerate(table[list(COLUMNS)].to_numpy().tolist()):
        for j, val in enumerate(rowvals):
            c = ws_data.cell(_DATA_FIRST_ROW + i, j + 1)
            _put(c, val)
            if i:
                _copy_style(proto[j], c)

    # Charts over α, from the Data sheet (the CSV columns), each series in its own colour
    # and dash; two charts per A4 page, none split by a page break
    from openpyxl.worksheet.pagebreak import Break

    n = len(table)
    col = {name: j + 1 for j, name in enumerate(COLUMNS)}
    xref = Reference(ws_data, min_col=col["alpha_deg"], min_row=_DATA_FIRST_ROW,
                     max_row=_DATA_FIRST_ROW + n - 1)
    ru = lang == "ru"
    y = _CHART_SYMBOLS[lang]
    N, Nm = ("Н", "Н·м") if ru else ("N", "N·m")
    charts = [
        ((f"Силы {y['dPg']}, Pj, P" if ru else f"Forces {y['dPg']}, Pj, P"), N,
         [("dPg_N", y["dPg"]), ("Pj_N", "Pj"), ("P_N", "P")]),
        (("Силы N, K, T" if ru else "Forces N, K, T"), N,
         [("N_N", "N"), ("K_N", "K"), ("T_N", "T")]),
        ((f"Крутящий момент цилиндра {y['M']}" if ru else
          f"Torque of one cylinder {y['M']}"), Nm, [("M_Nm", y["M"])]),
        ((f"Сила по шатуну {y['S']} и сила на шатунную шейку {y['R']}" if ru
          else f"Rod force {y['S']} and crank-pin load {y['R']}"), N,
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
            yref = Reference(ws_data, min_col=col[name], min_row=_DATA_FIRST_ROW,
                             max_row=_DATA_FIRST_ROW + n - 1)
            s = Series(yref, xref, title=label)
            s.marker.symbol = "none"
            s.smooth = False
            _style_series(s, m)
            ch.series.append(s)
        ch.width, ch.height = 17, 8.5
        ws_ch.add_chart(ch, f"A{3 + rows_per_chart * k}")
        if k % 2 == 1:                              # two charts per A4 page, none split
            ws_ch.row_breaks.append(Break(id=2 + rows_per_chart * (k + 1)))
    _polar_chart(ws_ch, ws_data, col, n, spec, lang, 3 + rows_per_chart * len(charts))
    if result.settings.form == "kolchin":
        _kolchin_sheet(wb, result, lang)
    return wb


def _kolchin_sheet(wb, result, lang):
    """Table 2 in Kolchin's form (specific forces in MPa with tg β, 1/cos β,
    cos(α+β)/cos β, sin(α+β)/cos β; :func:`engine.table2.table2`) as the last sheet: row 3
    the column keys, data from row 4."""
    from openpyxl.styles import Font

    from .table2 import table2

    t2 = table2(result.table, result.spec, result.settings, "kolchin")
    ws = wb.create_sheet(KOLCHIN_SHEET[lang])
    ws["A1"] = ("Таблица 2 в форме Колчина: удельные силы, МПа, и коэффициенты "
                "(Колчин и Демидов)" if lang == "ru" else
                "Table 2 in Kolchin's form: specific forces, MPa, and the coefficients "
                "(Kolchin & Demidov)")
    ws["A1"].font = Font(bold=True, size=12)
    ws["A2"] = (f"Fп = {result.spec.area * 1e4:.6g} см²" if lang == "ru"
                else f"Ap = {result.spec.area * 1e4:.6g} cm²")
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
                             R=sym("R", lang), pole=sym("pole_R", lang)) for lang in LANGS}


def _style_series(s, m):
    """Give chart series number ``m`` its colour, dash and width (:data:`CHART_STYLES`)."""
    colour, dash, width = CHART_STYLES[m % len(CHART_STYLES)]
    s.graphicalProperties.line.solidFill = colour
    s.graphicalProperties.line.prstDash = dash
    s.graphicalProperties.line.width = width


def _polar_chart(ws_ch, ws_data, col, n, spec, lang, row):
    """The polar diagram of the crank-pin load as a native, editable scatter chart: the
    locus of S = (T, K) from the Data sheet, +K downwards (reversed axis), the poles O and
    Oш = (0, −Kr.ш) as markers from a small table beside the chart; both axes get the same
    span on a square chart, so the diagram keeps its shape."""
    from openpyxl.chart import Reference, ScatterChart, Series
    from openpyxl.chart.marker import Marker
    from openpyxl.chart.shapes import GraphicalProperties

    ru = lang == "ru"
    y = _CHART_SYMBOLS[lang]
    T = np.asarray([ws_data.cell(_DATA_FIRST_ROW + i, col["T_N"]).value for i in range(n)])
    K = np.asarray([ws_data.cell(_DATA_FIRST_ROW + i, col["K_N"]).value for i in range(n)])
    kr = spec.Kr
    # the poles, in a small table right of the chart (columns M:O)
    _put(ws_ch.cell(row, 13), "T, Н" if ru else "T, N")
    _put(ws_ch.cell(row, 14), "K, Н" if ru else "K, N")
    for i, (name, tt, k) in enumerate((("O", 0.0, 0.0), (y["pole"], 0.0, -kr)), start=1):
        _put(ws_ch.cell(row + i, 13), tt)
        _put(ws_ch.cell(row + i, 14), float(k))
        _put(ws_ch.cell(row + i, 15), name)
        ws_ch.cell(row + i, 14).number_format = "0"
    ch = ScatterChart()
    ch.title = (f"Полярная диаграмма нагрузки на шатунную шейку ({y['pole']} – "
                f"полюс {y['R']})" if ru else
                f"Polar diagram of the crank-pin load ({y['pole']}: pole of {y['R']})")
    ch.x_axis.title = "T, Н" if ru else "T, N"
    ch.y_axis.title = "K, Н (вниз)" if ru else "K, N (downwards)"
    ch.y_axis.scaling.orientation = "maxMin"            # +K downwards, as in the textbook
    ch.width, ch.height = 17, 17
    # equal scales: the same span on both axes of a square chart, centred on the data
    xs_all, ys_all = np.r_[T, 0.0], np.r_[K, 0.0, -kr]
    span = 1.1 * max(np.ptp(xs_all), np.ptp(ys_all))
    step = 10 ** np.floor(np.log10(span / 4))
    for ax, vals in ((ch.x_axis, xs_all), (ch.y_axis, ys_all)):
        mid = 0.5 * (vals.min() + vals.max())
        ax.scaling.min = float(np.floor((mid - span / 2) / step) * step)
        ax.scaling.max = float(np.floor((mid - span / 2) / step) * step
                               + np.ceil(span / step) * step)
        ax.majorUnit = float(step * (2 if span / step > 12 else 1))
        ax.number_format = "0"
        ax.delete = False
    ch.x_axis.tickLblPos = "high"        # the y axis is reversed: "high" is the bottom
    ch.y_axis.tickLblPos = "low"
    ch.legend.position = "b"
    xs = Reference(ws_data, min_col=col["T_N"], min_row=_DATA_FIRST_ROW,
                   max_row=_DATA_FIRST_ROW + n - 1)
    ys = Reference(ws_data, min_col=col["K_N"], min_row=_DATA_FIRST_ROW,
                   max_row=_DATA_FIRST_ROW + n - 1)
    s = Series(ys, xs, title=f"{y['S']} (T, K)")
    s.marker.symbol = "none"
    s.smooth = False
    _style_series(s, 0)
    ch.series.append(s)
    px = Reference(ws_ch, min_col=13, min_row=row + 1, max_row=row + 2)
    py = Reference(ws_ch, min_col=14, min_row=row + 1, max_row=row + 2)
    poles = Series(py, px, title=f"O, {y['pole']}")
    colour = CHART_STYLES[2][0]
    poles.marker = Marker(symbol="square", size=8)
    poles.marker.graphicalProperties = GraphicalProperties(solidFill=colour)
    poles.marker.graphicalProperties.line.solidFill = colour
    poles.graphicalProperties.line.noFill = True          # markers only
    ch.series.append(poles)
    ws_ch.add_chart(ch, f"A{row}")


def a4_setup(wb):
    """Print setup of every sheet of ``wb``: A4 (landscape where the sheet has none of its
    own), as many pages down as needed, as many pages wide as its columns need (at most
    ~190 width units a page); rows of wrapped text as tall as their lines."""
    import math

    from openpyxl.utils import get_column_letter

    for ws in wb.worksheets:
        ps = ws.page_setup
        if ps.paperSize is None:
            ps.paperSize = ws.PAPERSIZE_A4
            ps.orientation = "landscape"
        ws.sheet_properties.pageSetUpPr.fitToPage = True
        ps.fitToHeight = 0
        widths = [ws.column_dimensions[get_column_letter(j)].width or 8.43
                  for j in range(1, ws.max_column + 1)
                  if not ws.column_dimensions[get_column_letter(j)].hidden]
        ps.fitToWidth = max(int(ps.fitToWidth or 1), math.ceil(sum(widths) / 190))
        merged = {(r.min_row, r.min_col): r for r in ws.merged_cells.ranges}
        for row in ws.iter_rows(min_row=1):
            for c in row:
                if not (isinstance(c.value, str) and c.alignment.wrap_text):
                    continue
                m = merged.get((c.row, c.column))
                cols = range(m.min_col, m.max_col + 1) if m else [c.column]
                width = sum(ws.column_dimensions[get_column_letter(j)].width or 8.43
                            for j in cols)
                lines = sum(math.ceil(len(p) * 1.1 / width) or 1 for p in c.value.split("\n"))
                if lines > 1 and (ws.row_dimensions[c.row].height or 15) < 13 * lines:
                    ws.row_dimensions[c.row].height = 13 * lines
    return wb


def save_workbook(wb, path):
    """Save a workbook atomically (temporary file in the target folder, then rename)."""
    from crankbase.output import atomic_path, full_precision_xlsx

    with atomic_path(path) as tmp, full_precision_xlsx():
        wb.save(tmp)


# ------------------------------------------------------------------ the whole engine

_TR = {
    "ru": dict(
        layout="Схема", torque="Суммарный момент", balance="Уравновешивание",
        flywheel="Маховик",
        layout_title="Расположение цилиндров (как в cylinders.csv)",
        layout_cols=("Цилиндр", "Ряд", "Колено", "z, мм", "γ ряда, °", "Угол колена, °",
                     "Фаза φ, °"),
        torque_title="Суммарный крутящий момент за интервал между вспышками θ = {th:g}°",
        torque_title_odd="Суммарный крутящий момент за цикл (неравномерное чередование)",
        data_title="Данные torque.csv (весь цикл)",
        alpha="θ, °", total="ΣMкр, Н·м", cyl="Mкр {j}, Н·м",
        summary=[("M_mean_Nm", "Средний крутящий момент Mкр.ср", "Н·м"),
                 ("M_max_Nm", "Mкр.max", "Н·м"), ("alpha_M_max_deg", "угол Mкр.max", "°"),
                 ("M_min_Nm", "Mкр.min", "Н·м"), ("alpha_M_min_deg", "угол Mкр.min", "°"),
                 ("mu", "Неравномерность μ = (Mкр.max − Mкр.min)/Mкр.ср", ""),
                 ("Mi_Nm", "Индикаторный момент Mi = pi·Vh·i/(π·τ)", "Н·м"),
                 ("Me_Nm", "Эффективный момент Me = ηм·Mi", "Н·м"),
                 ("Ni_kW", "Индикаторная мощность Ni", "кВт"),
                 ("Ne_kW", "Эффективная мощность Ne = ηм·Ni", "кВт"),
                 ("diff_pct", "Расхождение (Mкр.ср − Mi)/Mi", "%")],
        bal_title="Свободные силы и моменты: наибольшие за оборот",
        bal_cols=("Часть", "Fmax, Н", "Mmax, Н·м", "Силы уравновешены", "Моменты "
                  "уравновешены"),
        parts={"1": "силы инерции 1-го порядка", "2": "силы инерции 2-го порядка",
               "j": "возвратно-поступательные массы (сумма)",
               "r": "вращающиеся массы", "cw": "противовесы",
               "before": "всего без противовесов", "after": "всего с противовесами"},
        cw_title="Противовесы", cw_cols=("z от цилиндра 1, мм", "m·r, кг·мм",
                                          "угол от 1-го колена по вращению, °"),
        cw_none="противовесов нет", yes="да", no="нет",
        bal_data="Данные balance.csv (один оборот)",
        fw_title="Маховик (оценка по избыточной работе при постоянной ω)",
        fw_rows=[("L_excess_J", "Избыточная работа Lизб", "Дж"),
                 ("delta", "Коэффициент неравномерности хода δ", ""),
                 ("omega", "Угловая скорость ω", "рад/с"),
                 ("J0_kgm2", "Момент инерции J0 = Lизб/(δ·ω²)", "кг·м²"),
                 ("share", "Доля маховика Jм/J0", ""),
                 ("J_flywheel_kgm2", "Момент инерции маховика Jм", "кг·м²"),
                 ("mD2_kgm2", "Маховой момент mм·Dср² = 4·Jм", "кг·м²"),
                 ("diameter_m", "Средний диаметр обода Dср", "м"),
                 ("mass_kg", "Масса маховика mм", "кг"),
                 ("rim_speed_m_s", "Окружная скорость обода", "м/с")],
        fw_note="Допущения: ω постоянна (частота вращения спецификации); J0 — все "
                "вращающиеся части, приведённые к валу; маховик берёт долю Jм/J0; обод — "
                "тонкое кольцо (J = m·Dср²/4).",
        fw_none="δ не задан ([flywheel] delta): маховик не рассчитан",
        chart="Суммарный крутящий момент", inputs="Коленчатый вал и соглашения",
        train_items=[("arrangement", "Расположение цилиндров", ""),
                     ("vee_angle_deg", "Угол развала цилиндров γ", "°"),
                     ("firing_order", "Порядок работы цилиндров", ""),
                     ("throw_angles_deg", "Углы колен от 1-го по вращению", "°"),
                     ("cylinder_spacing_mm", "Расстояние между осями цилиндров", "мм"),
                     ("bank_offset_mm", "Смещение второго ряда вдоль вала", "мм"),
                     ("mechanical_efficiency", "Механический КПД ηм", ""),
                     ("delta", "Коэффициент неравномерности хода δ", ""),
                     ("counterweights", "Противовесы", "")],
        arrangements={"inline": "рядное", "vee": "V-образное", "boxer": "оппозитное"},
        given="заданы", default_throws="по умолчанию для равномерного чередования вспышек",
        cw_designs={"none": "нет", "throws": "на каждом колене (вращающиеся массы)",
                    "throws+first_order": "на каждом колене и два концевых (силы и "
                                          "моменты 1-го порядка)"},
        cw_given="заданы списком ({n})",
        conv=("Система координат: вид со стороны маховика, x вправо, y вверх, z вдоль вала "
              "от цилиндра 1 к маховику; вал вращается против часовой стрелки на этом виде "
              "(по часовой — со стороны носка).",
              "Нумерация: рядный — 1…i от носка; V и оппозитный — первый ряд 1…i/2 (справа, "
              "γ = −V/2), второй i/2+1…i; на общей шейке первый ряд достигает ВМТ на V° "
              "раньше.",
              "Колено k несёт цилиндры k и k + i/2 (V); углы колен — от 1-го по вращению.",
              "Фаза φ — запаздывание цикла цилиндра относительно цилиндра 1: α = θ − φ.")),
    "en": dict(
        layout="Layout", torque="Total torque", balance="Balance", flywheel="Flywheel",
        layout_title="Cylinder layout (as in cylinders.csv)",
        layout_cols=("Cylinder", "Bank", "Throw", "z, mm", "Bank angle, deg",
                     "Throw angle, deg", "Phase, deg"),
        torque_title="Total torque over one firing interval of {th:g} deg",
        torque_title_odd="Total torque over the cycle (uneven firing)",
        data_title="torque.csv data (whole cycle)",
        alpha="theta, deg", total="Total M, N·m", cyl="M {j}, N·m",
        summary=[("M_mean_Nm", "Mean torque M_mean", "N·m"),
                 ("M_max_Nm", "M_max", "N·m"), ("alpha_M_max_deg", "angle of M_max", "deg"),
                 ("M_min_Nm", "M_min", "N·m"), ("alpha_M_min_deg", "angle of M_min", "deg"),
                 ("mu", "Non-uniformity mu = (M_max - M_min)/M_mean", ""),
                 ("Mi_Nm", "Indicated torque Mi = pi·Vh·i/(pi·tau)", "N·m"),
                 ("Me_Nm", "Effective torque Me = eta_m·Mi", "N·m"),
                 ("Ni_kW", "Indicated power Ni", "kW"),
                 ("Ne_kW", "Effective power Ne = eta_m·Ni", "kW"),
                 ("diff_pct", "Difference (M_mean - Mi)/Mi", "%")],
        bal_title="Free forces and moments: largest over a revolution",
        bal_cols=("Part", "F max, N", "M max, N·m", "Forces balanced", "Moments balanced"),
        parts={"1": "first-order inertia forces", "2": "second-order inertia forces",
               "j": "reciprocating masses (exact sum)", "r": "rotating masses",
               "cw": "counterweights", "before": "total without counterweights",
               "after": "total with counterweights"},
        cw_title="Counterweights", cw_cols=("z from cylinder 1, mm", "m·r, kg·mm",
                                            "angle from throw 1 in rotation, deg"),
        cw_none="no counterweights", yes="yes", no="no",
        bal_data="balance.csv data (one revolution)",
        fw_title="Flywheel (estimate from the excess work at constant omega)",
        fw_rows=[("L_excess_J", "Excess work L_exc", "J"),
                 ("delta", "Coefficient of cyclic irregularity delta", ""),
                 ("omega", "Angular velocity omega", "rad/s"),
                 ("J0_kgm2", "Moment of inertia J0 = L_exc/(delta·omega²)", "kg·m²"),
                 ("share", "Flywheel share J_f/J0", ""),
                 ("J_flywheel_kgm2", "Flywheel moment of inertia J_f", "kg·m²"),
                 ("mD2_kgm2", "Flywheel moment m·D² = 4·J_f", "kg·m²"),
                 ("diameter_m", "Mean rim diameter D", "m"),
                 ("mass_kg", "Flywheel mass m", "kg"),
                 ("rim_speed_m_s", "Rim peripheral speed", "m/s")],
        fw_note="Assumptions: constant omega (the spec's speed); J0 is all rotating parts "
                "reduced to the crankshaft; the flywheel takes the share J_f/J0; the rim "
                "is a thin ring (J = m·D²/4).",
        fw_none="delta not given ([flywheel] delta): no flywheel computed",
        chart="Total engine torque", inputs="Crank train and conventions",
        train_items=[("arrangement", "Cylinder arrangement", ""),
                     ("vee_angle_deg", "Vee angle between the banks", "deg"),
                     ("firing_order", "Firing order", ""),
                     ("throw_angles_deg", "Throw angles from throw 1 in rotation", "deg"),
                     ("cylinder_spacing_mm", "Cylinder spacing along the crankshaft", "mm"),
                     ("bank_offset_mm", "Axial offset of the second bank", "mm"),
                     ("mechanical_efficiency", "Mechanical efficiency ηm", ""),
                     ("delta", "Coefficient of cyclic irregularity δ", ""),
                     ("counterweights", "Counterweights", "")],
        arrangements={"inline": "inline", "vee": "vee", "boxer": "boxer"},
        given="given", default_throws="default for even firing",
        cw_designs={"none": "none", "throws": "one per throw (rotating masses)",
                    "throws+first_order": "one per throw and two end ones (first-order "
                                          "forces and moments)"},
        cw_given="given one by one ({n})",
        conv=("Frame: seen from the flywheel end, x right, y up, z along the crankshaft "
              "from cylinder 1 to the flywheel; the crankshaft turns counter-clockwise in "
              "this view (clockwise seen from the front).",
              "Numbering: inline 1…i from the front; vee and boxer: first bank 1…i/2 (right, "
              "γ = −V/2), second bank i/2+1…i; on a common pin the first bank reaches TDC "
              "V° earlier.",
              "Throw k carries cylinders k and k + i/2 (vee); throw angles are from throw 1, "
              "in the direction of rotation.",
              "Phase φ: the lag of a cylinder's cycle behind cylinder 1's: α = θ − φ.")),
}


def _write_rows(ws, r0, c0, rows, bold=False):
    from openpyxl.styles import Font

    for i, row in enumerate(rows):
        for j, v in enumerate(row):
            cell = ws.cell(r0 + i, c0 + j)
            _put(cell, float(v) if isinstance(v, (np.floating, np.integer)) and not
                 isinstance(v, np.bool_) else v)
            if bold:
                cell.font = Font(bold=True)
    return r0 + len(rows)


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

    def fmt(a):
        return "0" if a >= 1e5 else "0.0" if a >= 1e3 else "0.00" if a >= 1 else "0.0000"

    cells = [c for row in ws.iter_rows() for c in row]
    numbers = [c for c in cells if isinstance(c.value, (int, float))
               and not isinstance(c.value, bool)]
    top, whole = {}, {}
    for c in numbers:
        top[c.column] = max(top.get(c.column, 0.0), abs(c.value))
        whole[c.column] = whole.get(c.column, True) and float(c.value).is_integer()
    for c in numbers:
        if whole[c.column] or float(c.value).is_integer() and not per_column:
            c.number_format = "0"
        else:
            c.number_format = fmt(top[c.column] if per_column else abs(c.value))
    for c in cells:
        if (isinstance(c.value, str) and c.font.b
                and not (c.font.sz and c.font.sz > 11)):   # headers, not titles
            c.alignment = Alignment(wrap_text=True, vertical="top")
    if default_width:
        for j in range(1, ws.max_column + 1):
            ws.column_dimensions[get_column_letter(j)].width = default_width
    for col, w in (widths or {}).items():
        ws.column_dimensions[col].width = w


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
    end = _write_rows(ws, 4, 1, tr.torque_table.to_numpy().tolist())
    rows = []
    for key, label, unit in t["summary"]:
        v = getattr(s, key)
        rows.append((label, v if v is None or isinstance(v, str) else float(v), unit))
    _write_rows(ws, end + 1, 1, [(lab, _text(v), u) for lab, v, u in rows])
    c0 = n + 4
    ws.cell(2, c0, t["data_title"]).font = Font(bold=True)
    _write_rows(ws, 3, c0, [list(tr.torque.columns)], bold=True)
    last = _write_rows(ws, 4, c0, tr.torque.to_numpy().tolist()) - 1
    ch = ScatterChart()
    ch.title = t["chart"]
    ch.x_axis.title = t["alpha"]
    ch.y_axis.title = "N·m" if lang == "en" else "Н·м"
    ch.x_axis.scaling.min, ch.x_axis.scaling.max = 0, lay.cycle_deg
    ch.x_axis.majorUnit = 90 if lay.cycle_deg > 360 else 45
    ch.x_axis.tickLblPos = "low"
    ch.x_axis.delete = ch.y_axis.delete = False
    ch.legend.position = "b"
    xref = Reference(ws, min_col=c0, min_row=4, max_row=last)
    for j in [n + 1] + list(range(1, n + 1)):
        yref = Reference(ws, min_col=c0 + j, min_row=4, max_row=last)
        ser = Series(yref, xref, title=str(tr.torque.columns[j]))
        ser.marker.symbol = "none"
        ser.smooth = False
        if j == n + 1:                       # the total: bold, the first chart style
            _style_series(ser, 0)
        else:                                # each cylinder: thin, its own colour and dash
            ser.graphicalProperties.line.solidFill = _CYL_COLOURS[(j - 1) % len(_CYL_COLOURS)]
            ser.graphicalProperties.line.prstDash = _CYL_DASHES[(j - 1) % len(_CYL_DASHES)]
            ser.graphicalProperties.line.width = 9525
        ch.series.append(ser)
    ch.width, ch.height = 24, 10
    ws.add_chart(ch, f"A{end + len(rows) + 3}")
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
    _write_rows(ws, r + 2, 1, tr.balance.to_numpy().tolist())
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
