"""The Excel report of the engine force table, filled from a template.

The template (``templates/engine_<lang>.xlsx``, built by
``templates/build_engine_templates.py``) owns the look and the text; this module only
writes numbers (never formulas) at full precision into it, matched by the keys in the
hidden column A of the Inputs and Summary sheets, copies the prototype row's style to every
table row, and adds native Excel charts.  It consumes a computed
:class:`engine.EngineResult`; it computes no physics.

Sheets, by position: 0 Inputs, 1 Table 2, 2 Summary, 3 Data (the CSV columns), 4 Charts.
"""
from __future__ import annotations

import copy
import math

import numpy as np

from crankbase.errors import OutputError, Problem

from .forces import COLUMNS, SUMMARY_QUANTITIES
from .spec import EngineSpecError

__all__ = ["build_workbook", "save_workbook", "input_values", "TABLE2_FORCES", "LANGS"]

LANGS = ("ru", "en")

#: Table 2 force pairs (mm, N), in the textbook order: (column of the force table).
TABLE2_FORCES = ("dPg_N", "Pj_N", "P_N", "S_N", "N_N", "K_N", "T_N", "R_N")

_T2_FIRST_ROW = 5     # first data row of Table 2 (rows 3–4: the two-row header)
_DATA_FIRST_ROW = 4   # first data row of the Data sheet (row 3: the CSV header)


def _text(value):
    return "—" if value is None else value


def input_values(result, lang="ru"):
    """The values of the Inputs sheet, by key (numbers in the report's units)."""
    spec, settings, summary = result.spec, result.settings, result.summary
    cyc = spec.cycle
    yes, no = ("да", "нет") if lang == "ru" else ("yes", "no")
    if spec.pressure_source == "cycle":
        src = ("расчёт по тепловому расчёту ([pressure.cycle])" if lang == "ru"
               else "computed from the thermal calculation ([pressure.cycle])")
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
    mass_input = "; ".join(f"{k} = {v:g}" for k, v in spec.mass_source.items())
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
        v.update(cycle_kind=cyc.kind, pa=cyc.pa / 1e6, pr=cyc.pr / 1e6, n1=cyc.n1,
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


def _copy_style(src, dst):
    dst._style = copy.copy(src._style)


def _check_finite(values, where):
    for key, val in values.items():
        if isinstance(val, float) and not math.isfinite(val):
            raise OutputError(f"{where}: {key} is not finite ({val!r})")


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
        raise EngineSpecError(Problem("lang", f"got {lang!r}; valid: {', '.join(LANGS)}"))
    spec, table, summary = result.spec, result.table, result.summary
    mu = result.settings.force_scale
    if mu is None:
        raise EngineSpecError(Problem("force_scale", "the report needs the force scale μP "
                                                     "(TableSettings.force_scale)"))
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
        if isinstance(row[3].value, str):
            # long text wraps: give the row the height of its lines
            width = ws_in.column_dimensions["D"].width or 10
            lines = math.ceil(len(row[3].value) * 1.1 / width)
            if lines > 1:
                ws_in.row_dimensions[row[3].row].height = 15 * lines

    # Table 2
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
    last = _T2_FIRST_ROW + len(data) - 1

    # Summary
    extremes = {col for col, _ in SUMMARY_QUANTITIES}
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

    # Charts over α, from Table 2's N columns
    xref = Reference(ws_t2, min_col=1, min_row=_T2_FIRST_ROW, max_row=last)
    force_col = {name: 3 + 2 * k for k, name in enumerate(TABLE2_FORCES)}
    m_col = 2 * len(TABLE2_FORCES) + 2
    ru = lang == "ru"
    charts = [
        (("Силы ΔPг, Pj, P" if ru else "Forces ΔPг, Pj, P"), ("Н" if ru else "N"),
         [force_col[k] for k in ("dPg_N", "Pj_N", "P_N")]),
        (("Силы N, K, T" if ru else "Forces N, K, T"), ("Н" if ru else "N"),
         [force_col[k] for k in ("N_N", "K_N", "T_N")]),
        (("Крутящий момент цилиндра Mкр" if ru else "Torque of one cylinder Mкр"),
         ("Н·м" if ru else "N·m"), [m_col]),
        (("Сила на шатунную шейку Rшш" if ru else "Crank-pin load Rшш"),
         ("Н" if ru else "N"), [force_col["S_N"], force_col["R_N"]]),
    ]
    for k, (title, unit, ycols) in enumerate(charts):
        ch = ScatterChart()
        ch.title = title
        ch.style = 13
        ch.x_axis.title = "α, °"
        ch.y_axis.title = unit
        ch.x_axis.scaling.min = 0
        ch.x_axis.scaling.max = spec.cycle_deg
        ch.x_axis.majorUnit = 90 if spec.cycle_deg > 360 else 30
        ch.x_axis.tickLblPos = "low"        # α labels below the plot, not on y = 0
        ch.x_axis.delete = False
        ch.y_axis.delete = False
        ch.legend.position = "b"
        for col in ycols:
            label = ws_t2.cell(3, col - 1).value if col != m_col else "Mкр"
            yref = Reference(ws_t2, min_col=col, min_row=_T2_FIRST_ROW, max_row=last)
            s = Series(yref, xref, title=str(label))
            s.marker.symbol = "none"
            s.smooth = False
            ch.series.append(s)
        ch.width, ch.height = 18, 8.5
        ws_ch.add_chart(ch, f"A{3 + 18 * k}")
    return wb


def save_workbook(wb, path):
    """Save a workbook atomically (temporary file in the target folder, then rename)."""
    from crankbase.output import atomic_path, full_precision_xlsx

    with atomic_path(path) as tmp, full_precision_xlsx():
        wb.save(tmp)
