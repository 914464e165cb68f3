"""The Excel report of the engine force table, filled from a template.

The template (``templates/engine_<lang>.xlsx``, built by
``templates/build_engine_templates.py``) owns the look and the text; this module only
writes numbers (never formulas) at full precision into it, matched by the keys in the
hidden column A of the Inputs and Summary sheets, copies the prototype row's style to every
table row, and adds native Excel charts.  It consumes the computed table and summary; it
computes no physics.

Sheets, by position: 0 Inputs, 1 Table 2 (in the spec's textbook form, ``table.form``:
the seed's mm|N or Kolchin's MPa with the coefficient columns, :mod:`engine.table2`),
2 Summary, 3 Data (the CSV columns), 4 Charts.  Row 5 of Table 2 (hidden) holds the column
keys of :func:`engine.table2.table2_columns`; data start on row 6.
"""
from __future__ import annotations

import copy
import math

import numpy as np

from .forces import COLUMNS
from .symbols import sym

__all__ = ["build_workbook", "save_workbook", "input_values", "TABLE2_FORCES", "LANGS"]

LANGS = ("ru", "en")

#: Table 2 force pairs (mm, N), in the textbook order: (column of the force table).
TABLE2_FORCES = ("dPg_N", "Pj_N", "P_N", "S_N", "N_N", "K_N", "T_N", "R_N")

_T2_FIRST_ROW = 6     # first data row of Table 2 (rows 3–4: header; 5: hidden keys)
_T2_KEY_ROW = 5

#: Line colour and dash of the 1st, 2nd, 3rd … series of every native chart: colours
#: of distinct lightness (Okabe–Ito blue, vermilion, black, green) and distinct dash
#: patterns, so the curves stay apart in grey-scale print.
CHART_STYLES = (("0072B2", "solid", 28575), ("D55E00", "dash", 28575),
                ("000000", "lgDashDot", 22225), ("009E73", "sysDot", 31750))
_DATA_FIRST_ROW = 4   # first data row of the Data sheet (row 3: the CSV header)


def _text(value):
    return "—" if value is None else value


def input_values(spec, summary, lang="ru"):
    """The values of the Inputs sheet, by key (numbers in the report's units)."""
    cyc = spec.cycle
    yes, no = ("да", "нет") if lang == "ru" else ("yes", "no")
    if spec.pressure_source == "cycle":
        src = ("по данным теплового расчёта ([pressure.cycle])" if lang == "ru"
               else "computed from the thermal calculation ([pressure.cycle])")
    elif spec.pressure_source == "file":
        src = (f"таблица давлений {spec.pressure_file.name}" if lang == "ru"
               else f"pressure table {spec.pressure_file.name}")
    else:
        src = (f"таблица давлений в спецификации ({len(spec.angle_deg)} точек)"
               if lang == "ru" else f"inline pressure table ({len(spec.angle_deg)} points)")
    accel = {"two-term": ("двучленная: j = Rω²(cos α + λ cos 2α)" if lang == "ru"
                          else "two-term: j = Rω²(cos α + λ cos 2α)"),
             "exact": ("точная (группа Ассура RRP)" if lang == "ru"
                       else "exact (RRP Assur group)")}[spec.acceleration]
    mass_input = "; ".join(_mass_text(k, v, lang) for k, v in spec.mass_source.items())
    v = {
        "name": spec.name, "strokes": spec.strokes, "cylinders": spec.cylinders,
        "bore_mm": spec.bore * 1e3, "stroke_mm": spec.stroke * 1e3, "R_mm": spec.R * 1e3,
        "L_mm": spec.L * 1e3, "lam": spec.lam, "speed_rpm": spec.speed_rpm,
        "omega": spec.omega, "v_mean": spec.piston_speed_mean, "p0_MPa": spec.p0 / 1e6,
        "area_cm2": spec.area * 1e4, "Vh_l": spec.Vh * 1e3,
        "compression_ratio": spec.compression_ratio, "acceleration": accel,
        "mass_input": mass_input, "mj": spec.mj, "m_rod_rot": spec.m_rod_rot,
        "m_crank_rot": spec.m_crank_rot, "Kr": spec.Kr, "mu_P": spec.force_scale,
        "step_deg": spec.step_deg,
        "extra_angles": ", ".join(f"{a:g}" for a in spec.extra_angles_deg) or None,
        "pressure_source": src, "pi": summary["pi_MPa"], "power_i": summary["power_i_kW"],
    }
    from .diagram_points import fullness
    v["fullness"] = fullness(summary)
    if cyc is not None:
        kinds = {"ru": {"otto": "Отто (искровое зажигание)", "diesel": "дизель"},
                 "en": {"otto": "Otto (spark ignition)", "diesel": "Diesel"}}
        v.update(cycle_kind=kinds[lang].get(cyc.kind, cyc.kind), pa=cyc.pa / 1e6, pr=cyc.pr / 1e6, n1=cyc.n1,
                 n2=cyc.n2, pc=cyc.pc / 1e6, pz=cyc.pz / 1e6, lambda_z=cyc.lambda_z,
                 rho=cyc.rho if cyc.kind == "diesel" else None,
                 rounding=(yes if cyc.rounding else no),
                 pi_theory=summary.get("pi_theory_MPa"))
        if cyc.rounding:
            v.update({k: getattr(cyc, k) for k in (
                "advance_deg", "pc_factor", "peak_factor", "peak_after_tdc_deg",
                "exhaust_opening_deg", "intake_opening_deg", "exhaust_closing_deg")})
    return v


#: The mass keys of the spec as the report shows them: (symbol key or text, unit).
_MASS_TEXT = {
    "reciprocating_kg": ("mj", "kg"), "rod_rotating_kg": ("m_rod_rot", "kg"),
    "piston_group_kg": ("m_piston", "kg"), "rod_kg": ("m_rod", "kg"),
    "piston_group_kg_m2": ("m_piston", "kg/m2"), "rod_kg_m2": ("m_rod", "kg/m2"),
    "rod_small_end_fraction": ("fraction", ""), "crank_rotating_kg": ("m_crank", "kg"),
}
_UNITS = {"ru": {"kg": "кг", "kg/m2": "кг/м²", "": ""},
          "en": {"kg": "kg", "kg/m2": "kg/m²", "": ""}}


def _mass_text(key, value, lang):
    """One given mass as "symbol = value unit" in the report's language."""
    name, unit = _MASS_TEXT.get(key, (None, ""))
    if name is None:
        text = key
    elif name == "fraction":
        text = "mш.п/mш" if lang == "ru" else "mrod,rec/mrod"
    else:
        text = sym(name, lang)
    if unit == "kg/m2":
        text += "/Fп" if lang == "ru" else "/Ap"
    u = _UNITS[lang][unit]
    return f"{text} = {value:g}" + (f" {u}" if u else "")


def _put(cell, value):
    """Store ``value`` in ``cell``; a string always as text, never as a formula (a name
    may start with "=").  Floats keep every bit when the workbook is saved by
    :func:`save_workbook` (:func:`crankbase.output.full_precision_xlsx`)."""
    if isinstance(value, float) and value == 0.0:
        value = 0.0                      # never show "-0" (the value is the same)
    cell.value = value
    if isinstance(value, str):
        cell.data_type = "s"


def _copy_style(src, dst):
    dst._style = copy.copy(src._style)


def _check_finite(values, where):
    for key, val in values.items():
        if isinstance(val, float) and not math.isfinite(val):
            raise ValueError(f"{where}: {key} is not finite ({val!r})")


def build_workbook(table, summary, spec, lang="ru"):
    """Fill the report template with a computed force table.

    Parameters
    ----------
    table : pandas.DataFrame
        From :func:`engine.force_table` (every value finite).
    summary : dict
        From :func:`engine.summarize`.
    spec : EngineSpec
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
        raise ValueError(f"--lang: got {lang!r}; valid: {', '.join(LANGS)}")
    ensure_finite(table, "force table")
    wb = load_workbook(template_path(f"engine_{lang}.xlsx"))
    ws_in, ws_t2, ws_sum, ws_data, ws_ch = wb.worksheets[:5]

    # Inputs: fill column D by the key in column A
    values = input_values(spec, summary, lang)
    _check_finite(values, "inputs")
    for row in ws_in.iter_rows(min_row=4, max_col=4):
        key = row[0].value
        if key is None or key == "symbols":
            continue
        _put(row[3], _text(values.get(key)))
        if isinstance(row[3].value, str):
            # long text wraps: give the row the height of its lines
            width = ws_in.column_dimensions["D"].width or 10
            lines = math.ceil(len(row[3].value) * 1.1 / width)
            if lines > 1:
                ws_in.row_dimensions[row[3].row].height = 15 * lines

    # Table 2 in the spec's textbook form (the other form's sheet is dropped)
    from .table2 import table2

    form = getattr(spec, "table_form", "seed")
    ws_k = wb.worksheets[5]
    if form == "kolchin":
        wb.remove(ws_t2)
        wb.move_sheet(ws_k, offset=1 - wb.index(ws_k))
        ws_t2 = ws_k
        _put(ws_t2["C2"], float(spec.area * 1e4))
    else:
        wb.remove(ws_k)
        _put(ws_t2["D2"], float(spec.force_scale))
    t2 = table2(table, spec, form)
    keys = [ws_t2.cell(_T2_KEY_ROW, j).value for j in range(1, len(t2.columns) + 1)]
    if keys != list(t2.columns):
        raise RuntimeError(f"template engine_{lang}.xlsx is out of date: Table 2 keys "
                           f"{keys} != {list(t2.columns)}; run templates/"
                           "build_engine_templates.py")
    proto = [ws_t2.cell(_T2_FIRST_ROW, c) for c in range(1, len(keys) + 1)]
    for i, rowvals in enumerate(t2.to_numpy().tolist()):
        r = _T2_FIRST_ROW + i
        for j, val in enumerate(rowvals):
            c = ws_t2.cell(r, j + 1)
            _put(c, val)
            if i:
                _copy_style(proto[j], c)

    # Summary
    ext = summary["extremes"]
    for row in ws_sum.iter_rows(min_row=4, max_col=7):
        key = row[0].value
        if key in ext:
            for cell, val in zip(row[3:7], ext[key]):
                _put(cell, float(val))
        elif key in summary:
            _put(row[3], float(summary[key]))

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

    # Charts over α, from the Data sheet (the CSV columns, whatever the Table 2 form)
    from openpyxl.worksheet.pagebreak import Break

    n = len(table)
    col = {name: j + 1 for j, name in enumerate(COLUMNS)}
    xref = Reference(ws_data, min_col=col["alpha_deg"], min_row=_DATA_FIRST_ROW,
                     max_row=_DATA_FIRST_ROW + n - 1)
    ru = lang == "ru"
    N, Nm = ("Н", "Н·м") if ru else ("N", "N·m")
    dpg, M, S, R = (sym(k, lang) for k in ("dPg", "M", "S", "R"))
    charts = [
        ((f"Силы {dpg}, Pj, P" if ru else f"Forces {dpg}, Pj, P"), N,
         [("dPg_N", dpg), ("Pj_N", "Pj"), ("P_N", "P")]),
        (("Силы N, K, T" if ru else "Forces N, K, T"), N,
         [("N_N", "N"), ("K_N", "K"), ("T_N", "T")]),
        ((f"Крутящий момент цилиндра {M}" if ru else f"Torque of one cylinder {M}"), Nm,
         [("M_Nm", M)]),
        ((f"Сила по шатуну {S} и сила на шатунную шейку {R}" if ru
          else f"Rod force {S} and crank-pin load {R}"), N, [("S_N", S), ("R_N", R)]),
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
            colour, dash, width = CHART_STYLES[m]
            s.graphicalProperties.line.solidFill = colour
            s.graphicalProperties.line.prstDash = dash
            s.graphicalProperties.line.width = width
            ch.series.append(s)
        ch.width, ch.height = 17, 8.5
        ws_ch.add_chart(ch, f"A{3 + rows_per_chart * k}")
        if k % 2 == 1:                              # two charts per A4 page, none split
            ws_ch.row_breaks.append(Break(id=2 + rows_per_chart * (k + 1)))
    _polar_chart(ws_ch, ws_data, col, n, spec, lang, 3 + rows_per_chart * len(charts))
    return wb


def _polar_chart(ws_ch, ws_data, col, n, spec, lang, row):
    """The polar diagram of the crank-pin load as a native, editable scatter chart: the
    locus of S = (T, K) from the Data sheet, +K downwards (reversed axis), the poles O and
    Oш = (0, −Kr.ш) as markers from a small table beside the chart; both axes get the same
    span on a square chart, so the diagram keeps its shape."""
    from openpyxl.chart import Reference, ScatterChart, Series
    from openpyxl.chart.marker import Marker
    from openpyxl.chart.shapes import GraphicalProperties

    ru = lang == "ru"
    T = np.asarray([ws_data.cell(_DATA_FIRST_ROW + i, col["T_N"]).value for i in range(n)])
    K = np.asarray([ws_data.cell(_DATA_FIRST_ROW + i, col["K_N"]).value for i in range(n)])
    kr = spec.Kr
    # the poles, in a small table right of the chart (columns M:O)
    _put(ws_ch.cell(row, 13), "T, Н" if ru else "T, N")
    _put(ws_ch.cell(row, 14), "K, Н" if ru else "K, N")
    for i, (name, t, k) in enumerate((("O", 0.0, 0.0), (sym("pole_R", lang), 0.0, -kr)),
                                     start=1):
        _put(ws_ch.cell(row + i, 13), t)
        _put(ws_ch.cell(row + i, 14), float(k))
        _put(ws_ch.cell(row + i, 15), name)
        ws_ch.cell(row + i, 14).number_format = "0"
    ch = ScatterChart()
    ch.title = (f"Полярная диаграмма нагрузки на шатунную шейку ({sym('pole_R', lang)} – "
                f"полюс {sym('R', lang)})" if ru else
                f"Polar diagram of the crank-pin load ({sym('pole_R', lang)}: pole of "
                f"{sym('R', lang)})")
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
    s = Series(ys, xs, title=f"{sym('S', lang)} (T, K)")
    s.marker.symbol = "none"
    s.smooth = False
    colour, dash, width = CHART_STYLES[0]
    s.graphicalProperties.line.solidFill = colour
    s.graphicalProperties.line.prstDash = dash
    s.graphicalProperties.line.width = width
    ch.series.append(s)
    px = Reference(ws_ch, min_col=13, min_row=row + 1, max_row=row + 2)
    py = Reference(ws_ch, min_col=14, min_row=row + 1, max_row=row + 2)
    poles = Series(py, px, title=f"O, {sym('pole_R', lang)}")
    colour, dash, _ = CHART_STYLES[2]
    poles.marker = Marker(symbol="square", size=8)
    poles.marker.graphicalProperties = GraphicalProperties(solidFill=colour)
    poles.marker.graphicalProperties.line.solidFill = colour
    poles.graphicalProperties.line.noFill = True          # markers only
    ch.series.append(poles)
    ws_ch.add_chart(ch, f"A{row}")


def save_workbook(wb, path):
    """Save a workbook atomically (temporary file in the target folder, then rename)."""
    from crankbase.output import atomic_path, full_precision_xlsx

    with atomic_path(path) as tmp, full_precision_xlsx():
        wb.save(tmp)
