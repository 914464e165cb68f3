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

from crankbase.errors import OutputError, Problem

from .forces import COLUMNS, SUMMARY_QUANTITIES
from .spec import EngineSpecError

__all__ = ["build_workbook", "add_engine_sheets", "save_workbook", "input_values",
           "TABLE2_FORCES", "LANGS"]

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

    # Charts over α, from Table 2's N columns
    xref = Reference(ws_t2, min_col=1, min_row=_T2_FIRST_ROW, max_row=last)
    force_col = {name: 3 + 2 * k for k, name in enumerate(TABLE2_FORCES)}
    m_col = 2 * len(TABLE2_FORCES) + 2
    ru = lang == "ru"
    charts = [
        (("Силы ΔPг, Pj, P" if ru else "Forces ΔPg, Pj, P"), ("Н" if ru else "N"),
         [force_col[k] for k in ("dPg_N", "Pj_N", "P_N")]),
        (("Силы N, K, T" if ru else "Forces N, K, T"), ("Н" if ru else "N"),
         [force_col[k] for k in ("N_N", "K_N", "T_N")]),
        (("Крутящий момент цилиндра Mкр" if ru else "Torque of one cylinder M"),
         ("Н·м" if ru else "N·m"), [m_col]),
        (("Сила на шатунную шейку Rшш" if ru else "Crank-pin load Rcp"),
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
            label = ws_t2.cell(3, col - 1).value if col != m_col else ("Mкр" if ru else "M")
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
        conv=("Frame: seen from the flywheel end, x right, y up, z along the crankshaft "
              "from cylinder 1 to the flywheel; the crankshaft turns counter-clockwise in "
              "this view (clockwise seen from the front).",
              "Numbering: inline 1…i from the front; vee and boxer: first bank 1…i/2 (right, "
              "gamma = -V/2), second bank i/2+1…i; on a common pin the first bank reaches TDC "
              "V deg earlier.",
              "Throw k carries cylinders k and k + i/2 (vee); throw angles are from throw 1, "
              "in the direction of rotation.",
              "Phase phi: the lag of a cylinder's cycle behind cylinder 1's: alpha = theta - "
              "phi.")),
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
    from openpyxl.styles import Font

    from crankbase.output import ensure_finite

    if lang not in LANGS:
        raise EngineSpecError(Problem("lang", f"got {lang!r}; valid: {', '.join(LANGS)}"))
    t = _TR[lang]
    for df, what in ((tr.torque, "torque"), (tr.balance, "balance"),
                     (tr.layout.cylinders, "layout")):
        ensure_finite(df, what)
    lay, s = tr.layout, tr.summary
    yes, no = t["yes"], t["no"]

    # Inputs: the crank train and the conventions, below the template's rows
    ws_in = wb.worksheets[0]
    r = ws_in.max_row + 2
    ws_in.cell(r, 2, t["inputs"]).font = Font(bold=True)
    train = tr.train
    items = [("arrangement", train.arrangement), ("vee_angle_deg", train.vee_angle_deg),
             ("firing_order", "-".join(map(str, lay.firing_order))),
             ("throw_angles_deg", ", ".join(f"{x:g}" for x in lay.throw_angles_deg)
              + f" ({lay.crankshaft})"),
             ("cylinder_spacing_mm", None if train.cylinder_spacing is None
              else train.cylinder_spacing * 1e3),
             ("bank_offset_mm", train.bank_offset * 1e3),
             ("mechanical_efficiency", train.mechanical_efficiency),
             ("flywheel.delta", train.delta), ("balance.counterweights",
                                               train.counterweights)]
    for i, (key, val) in enumerate(items, start=1):
        ws_in.cell(r + i, 1, key)
        _put(ws_in.cell(r + i, 2), key)
        _put(ws_in.cell(r + i, 4), _text(val))
    r += len(items) + 2
    for i, line in enumerate(t["conv"]):
        _put(ws_in.cell(r + i, 2), line)

    # Layout
    ws = wb.create_sheet(t["layout"])
    ws["A1"] = t["layout_title"]
    ws["A1"].font = Font(bold=True, size=12)
    _write_rows(ws, 3, 1, [t["layout_cols"]], bold=True)
    _write_rows(ws, 4, 1, lay.cylinders.to_numpy().tolist())
    for col, w in zip("ABCDEFG", (10, 8, 8, 12, 16, 18, 12)):
        ws.column_dimensions[col].width = w

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
    ch.style = 13
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
        ser.graphicalProperties.line.width = 28000 if j == n + 1 else 6000
        ch.series.append(ser)
    ch.width, ch.height = 24, 10
    ws.add_chart(ch, f"A{end + len(rows) + 3}")

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
    ws.column_dimensions["A"].width = 40
    for col in "BCDE":
        ws.column_dimensions[col].width = 16

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
    ws.column_dimensions["A"].width = 55
    ws.column_dimensions["B"].width = 16
    return wb
