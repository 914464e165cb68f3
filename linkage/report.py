"""Reports of a linkage analysis: CSV tables and the Excel workbook.

Reports only consume an :class:`~linkage.analysis.AnalysisResult`; they compute no
physics.  The workbook has the sheets ``inputs`` (spec values and the cycle geometry),
``positions``, ``velocities``, ``accelerations``, ``loads`` (weights, inertia forces and
moments, resistance), ``forces`` (reactions, driving moment) -- one row per position, the
CSV columns regrouped -- and ``extremes`` (the two extreme positions).  Every sheet has
three header rows: the textbook symbol, the unit, and the CSV column name; numbers are
stored at full precision (number formats only change how they are shown).
"""
from __future__ import annotations

import copy

import math
import re

import numpy as np

from crankbase.tolerances import SAME_ANGLE_DEG

__all__ = ["column_label", "write_csvs", "write_workbook", "sheet_columns",
           "force_sheet_columns", "summary_lines"]

_UNITS = {"m": "m", "m_s": "m/s", "m_s2": "m/s²", "deg": "°", "rad_s": "rad/s",
          "rad_s2": "rad/s²", "N": "N", "Nm": "N·m"}
_SIMPLE = {
    "position": ("№", ""), "phi_deg": ("φ", "°"), "theta3_deg": ("θ3", "°"),
    "theta4_deg": ("θ4", "°"), "omega3_rad_s": ("ω3", "rad/s"), "omega4_rad_s": ("ω4", "rad/s"),
    "eps3_rad_s2": ("ε3", "rad/s²"), "eps4_rad_s2": ("ε4", "rad/s²"), "s4_m": ("s4", "m"),
    "v4_m_s": ("v4", "m/s"), "a4_m_s2": ("a4", "m/s²"), "mu_deg": ("μ", "°"),
    "M_drive_Nm": ("Mур", "N·m"), "M_res_Nm": ("Mпс", "N·m"), "F_res_N": ("Fпс", "N"),
    "M14_Nm": ("M14", "N·m"), "N14_N": ("N14", "N"), "label": ("", ""),
    "R23_n_N": ("R23n", "N"), "R23_t_N": ("R23t", "N"), "R14_n_N": ("R14n", "N"),
    "R14_t_N": ("R14t", "N"),
}
_POINT_Q = {"x": ("x_{P}", ""), "y": ("y_{P}", ""), "vx": ("V_{P}x", ""), "vy": ("V_{P}y", ""),
            "ax": ("a_{P}x", ""), "ay": ("a_{P}y", "")}


def column_label(col: str):
    """Textbook symbol and unit of a table column, e.g. ``"B_vx_m_s"`` → ("VBx", "m/s")."""
    if col in _SIMPLE:
        return _SIMPLE[col]
    m = re.fullmatch(r"R(\d\d)_([xy])_N", col)
    if m:
        return f"R{m.group(1)}{m.group(2)}", "N"
    m = re.fullmatch(r"(R\d\d|G\d)_N", col)
    if m:
        return m.group(1), "N"
    m = re.fullmatch(r"Fu(\d)(_[xy])?_N", col)
    if m:
        return f"Fu{m.group(1)}{(m.group(2) or '')[1:]}", "N"
    m = re.fullmatch(r"Mu(\d)_Nm", col)
    if m:
        return f"Mu{m.group(1)}", "N·m"
    m = re.fullmatch(r"v_(\w\w)_m_s", col)
    if m:
        return f"V{m.group(1)}", "m/s"
    m = re.fullmatch(r"a_(\w\w)(_[nt])?_m_s2", col)
    if m:
        sup = {"_n": "ⁿ", "_t": "ᵗ"}.get(m.group(2), "")
        return f"a{m.group(1)}{sup}", "m/s²"
    m = re.fullmatch(r"(.+?)_(v|a)_(m_s|m_s2)", col)
    if m:
        p, q, unit = m.groups()
        return f"{'V' if q == 'v' else 'a'}{p}", _UNITS[unit]
    m = re.fullmatch(r"(.+?)_(x|y|vx|vy|ax|ay)_(m|m_s|m_s2)", col)
    if m:
        p, q, unit = m.groups()
        sym = {"x": f"x{p}", "y": f"y{p}", "vx": f"V{p}x", "vy": f"V{p}y",
               "ax": f"a{p}x", "ay": f"a{p}y"}[q]
        return sym, _UNITS[unit]
    return col, ""


def sheet_columns(kinematics_cols):
    """Split the kinematics columns into the positions, velocities and accelerations sheets:
    on the last two, the link rates first, then the course table's magnitudes (speeds of
    the points, relative motion of B), then the x/y components."""
    head = ["position", "phi_deg"]
    pos, vel, acc = list(head), [], []
    for c in kinematics_cols:
        if c in head:
            continue
        if c.endswith("_m_s") or c in ("omega3_rad_s", "omega4_rad_s"):
            vel.append(c)
        elif c.endswith("_m_s2") or c in ("eps3_rad_s2", "eps4_rad_s2"):
            acc.append(c)
        else:
            pos.append(c)

    def order(c):
        return 2 if re.search(r"_(vx|vy|ax|ay)_m_s2?$", c) else \
            1 if re.search(r"_(v_m_s|a_m_s2)$", c) or c.startswith(("v_B", "a_B")) else 0
    return pos, head + sorted(vel, key=order), head + sorted(acc, key=order)


def force_sheet_columns(force_cols):
    """Split the force columns into the loads sheet (weights, inertia forces and moments,
    useful resistance: the inputs of the kinetostatics) and the forces sheet (reactions
    and the driving moment)."""
    head = ["position", "phi_deg"]
    loads = [c for c in force_cols
             if re.fullmatch(r"(G\d|Fu\d(_[xy])?)_N|Mu\d_Nm|M_res_Nm|F_res_N", c)]
    rest = [c for c in force_cols if c not in head and c not in loads]
    return head + loads, head + rest


def write_csvs(result, folder):
    """Write ``kinematics.csv`` and ``forces.csv`` (comma, '.', header, full precision)."""
    from crankbase.output import write_csv

    write_csv(result.kinematics, folder / "kinematics.csv")
    write_csv(result.forces, folder / "forces.csv")


def summary_lines(result):
    """The cycle geometry as (label, value, unit) rows for the inputs sheet and terminal."""
    s = result.summary
    rows = [("Grashof type", str(s.grashof), "")]
    if s.has_extremes:
        rows += [("crank angle, working-stroke start (position 1)", s.phi_working_start_deg, "°"),
                 ("crank angle, working-stroke end", s.phi_working_end_deg, "°"),
                 ("crank rotation in the working stroke", s.working_crank_angle_deg, "°"),
                 ("crank rotation in the idle stroke", s.idle_crank_angle_deg, "°"),
                 ("time-ratio coefficient K = φwork/φidle", s.time_ratio, "")]
        if s.swing_deg is not None:
            rows += [("rocker angle at working-stroke start", s.theta4_working_start_deg, "°"),
                     ("rocker angle at working-stroke end", s.theta4_working_end_deg, "°"),
                     ("rocker swing", s.swing_deg, "°")]
        else:
            rows += [("slider position at working-stroke start", s.s4_working_start_m, "m"),
                     ("slider position at working-stroke end", s.s4_working_end_m, "m"),
                     ("slider stroke", s.stroke_m, "m")]
    rows += [("minimum transmission angle μmin", s.mu_min_deg, "°"),
             ("crank angle of μmin", s.mu_min_phi_deg, "°")]
    if s.singular_phi_deg:
        rows.append(("singular crank angles (change point)",
                     ", ".join(f"{a:.6g}" for a in s.singular_phi_deg), "°"))
    return rows


def _spec_rows(raw, prefix=""):
    """Flatten the spec as given into (key path, value) rows."""
    rows = []
    for key, value in raw.items():
        path = f"{prefix}.{key}" if prefix else key
        if isinstance(value, dict):
            rows += _spec_rows(value, path)
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for i, item in enumerate(value):
                rows += _spec_rows(item, f"{path}[{i}]")
        else:
            if isinstance(value, (list, tuple)):
                value = ", ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in value)
            rows.append((path, value))
    return rows


def write_workbook(result, path):
    """Write the Excel workbook of a linkage analysis (atomically).

    Raises :class:`crankbase.output.OutputError` if a table holds a non-finite number outside
    the rows of singular positions of a change-point mechanism (those are left empty
    and flagged).
    """
    from openpyxl import Workbook
    from openpyxl.styles import Alignment, Border, Font, PatternFill, Side
    from openpyxl.utils import get_column_letter

    from crankbase.output import atomic_path, full_precision_xlsx

    wb = Workbook()
    bold = Font(bold=True)
    grey = Font(italic=True, size=8, color="808080")
    head_fill = PatternFill("solid", fgColor="DDEBF7")
    thin = Side(style="thin", color="999999")
    box = Border(left=thin, right=thin, top=thin, bottom=thin)
    center = Alignment(horizontal="center", vertical="center")

    # -- inputs
    ws = wb.active
    ws.title = "inputs"
    spec = result.spec
    ws["A1"] = f"crankdyn linkage — {spec.name} ({spec.kind})"
    ws["A1"].font = Font(bold=True, size=12)
    ws.append([])
    ws.append(["spec key", "value", "unit"])
    for c in ws[3]:
        c.font = bold
        c.fill = head_fill
    for key, value in _spec_rows(dict(spec.raw)):
        ws.append([key, value, _spec_unit(key)])
    ws.append([])
    ws.append(["cycle geometry", "value", "unit"])
    for c in ws[ws.max_row]:
        c.font = bold
        c.fill = head_fill
    for label, value, unit in summary_lines(result):
        ws.append([label, value, unit])
        if isinstance(value, float):
            ws.cell(ws.max_row, 2).number_format = "0.0000"
    if result.warnings:
        ws.append([])
        for w in result.warnings:
            ws.append(["warning", w])
            ws.cell(ws.max_row, 1).font = Font(bold=True, color="C00000")
    ws.append([])
    ws.append(["conventions"])
    ws.cell(ws.max_row, 1).font = bold
    for line in CONVENTIONS:
        ws.append([line])
    ws.column_dimensions["A"].width = 46
    ws.column_dimensions["B"].width = 24
    ws.column_dimensions["C"].width = 8

    pos_cols, vel_cols, acc_cols = sheet_columns(list(result.kinematics.columns))
    load_cols, force_cols = force_sheet_columns(list(result.forces.columns))
    tables = [("positions", result.kinematics, pos_cols),
              ("velocities", result.kinematics, vel_cols),
              ("accelerations", result.kinematics, acc_cols),
              ("loads", result.forces, load_cols),
              ("forces", result.forces, force_cols)]
    if result.extremes is not None:
        tables.append(("extremes", result.extremes, list(result.extremes.columns)))
    for title, df, cols in tables:
        ws = wb.create_sheet(title)
        if title == "extremes":
            _extremes_sheet(ws, df, cols, bold, grey, head_fill, box, center)
            continue
        for j, col in enumerate(cols, start=1):
            sym, unit = column_label(col)
            for i, text in enumerate((sym, unit, col), start=1):
                cell = ws.cell(i, j, text)
                cell.alignment = center
                cell.border = box
                cell.font = grey if i == 3 else bold
                if i < 3:
                    cell.fill = head_fill
            ws.column_dimensions[get_column_letter(j)].width = max(11, len(col) + 2)
        for j, col in enumerate(cols, start=1):
            values = _cell_values(df[col])
            fmt = _number_format(col, values)
            proto = None
            for i, value in enumerate(values, start=4):
                cell = ws.cell(i, j, value)
                if proto is None:      # style one cell, share its style array with the rest
                    cell.border = box  # (setting styles cell by cell costs ~10 ms a row)
                    cell.number_format = fmt
                    proto = cell._style
                else:
                    cell._style = copy.copy(proto)
        ws.freeze_panes = "C4" if "phi_deg" in cols else "B4"
        ws.print_title_rows = "1:3"
        if "phi_deg" in cols:
            ws.print_title_cols = "A:B"      # position and φ repeated on every page
        width = sum(ws.column_dimensions[get_column_letter(j)].width
                    for j in range(1, len(cols) + 1))
        _page_setup(ws, landscape=True, pages_wide=math.ceil(width / _WIDTH_PER_PAGE))
    _page_setup(wb["inputs"], landscape=False)
    _check_finite_tables(result)
    with atomic_path(path) as tmp, full_precision_xlsx():
        wb.save(tmp)


#: Conventions printed on the inputs sheet.
CONVENTIONS = (
    "SI units; angles in degrees, counter-clockwise from +x; O at the origin.",
    "Rij = force of link i on link j (1 ground, 2 crank, 3 coupler/rod, 4 rocker/slider).",
    "Mур (M_drive) = driving (balancing) moment applied to the crank, + counter-clockwise.",
    "R23n, R23t: along A→B and 90° ccw from it; R14n, R14t: along C→B and 90° ccw from it.",
    "Position 1 = extreme position where the working stroke starts; then every 360°/N "
    "in the direction of rotation.",
)


#: Column width (Excel units) printed on one landscape A4 page: at most ~70 % scale,
#: so the numbers stay readable (a wider sheet prints on more pages, titles repeated).
_WIDTH_PER_PAGE = 190


def _extremes_sheet(ws, df, cols, bold, grey, head_fill, box, center):
    """The extreme positions, one quantity per row (quantity, unit, CSV key, one value
    column per extreme position): two positions of ~100 quantities print as a readable
    portrait list instead of a strip 100 columns wide."""
    from openpyxl.styles import Alignment

    heads = ["quantity", "unit", "column"] + [f"extreme {i + 1}" for i in range(len(df))]
    for j, text in enumerate(heads, start=1):
        c = ws.cell(1, j, text)
        c.font, c.fill, c.border, c.alignment = bold, head_fill, box, center
    for i, col in enumerate(cols, start=2):
        sym, unit = column_label(col)
        values = _cell_values(df[col])
        fmt = _number_format(col, values)
        for j, v in enumerate([sym, unit, col] + values, start=1):
            c = ws.cell(i, j, v)
            c.border = box
            if j == 3:
                c.font = grey
            if j > 3:
                c.number_format = fmt
                c.alignment = Alignment(horizontal="right")
    ws.column_dimensions["A"].width = 14
    ws.column_dimensions["B"].width = 8
    ws.column_dimensions["C"].width = 22
    for j in range(len(df)):
        ws.column_dimensions[chr(ord("D") + j)].width = 16
    ws.freeze_panes = "D2"
    ws.print_title_rows = "1:1"
    _page_setup(ws, landscape=False)


#: Units of the spec keys, by the key's suffix (the spec's naming rule) or its name.
_UNIT_SUFFIXES = (("_kg_m2", "kg·m²"), ("_rad_s2", "rad/s²"), ("_rad_s", "rad/s"),
                  ("_m_s2", "m/s²"), ("_deg", "°"), ("_kg", "kg"), ("_Nm", "N·m"),
                  ("_N", "N"), ("_m", "m"))
_LENGTH_KEYS = {"crank", "coupler", "rocker", "ground", "offset", "cg", "at", "rod"}


def _spec_unit(key):
    """The unit of a spec key as shown on the inputs sheet ('' for a word or a count)."""
    last = re.sub(r"\[\d+\]$", "", key.split(".")[-1])
    for suffix, unit in _UNIT_SUFFIXES:
        if last.endswith(suffix):
            return unit
    if last in _LENGTH_KEYS or key.split(".")[-2:-1] == ["points"]:
        return "m"
    return ""


def _page_setup(ws, landscape, pages_wide=1):
    """Print on A4, ``pages_wide`` pages wide, as many tall as needed."""
    ws.page_setup.orientation = "landscape" if landscape else "portrait"
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.fitToWidth = max(1, int(pages_wide))
    ws.page_setup.fitToHeight = 0
    ws.sheet_properties.pageSetUpPr.fitToPage = True


def _number_format(col, values):
    """One display format per column (the stored value keeps full precision)."""
    if col == "position":
        return "0"
    if col.endswith("_deg"):
        return "0.00"
    big = max((abs(v) for v in values if isinstance(v, float)), default=0.0)
    return "0.00" if big >= 100 else "0.000" if big >= 1 else "0.0000"


def _cell_values(series):
    """Python values for openpyxl: floats, ints, strings; missing or non-finite → None."""
    if series.dtype.kind == "f":
        return [float(v) if math.isfinite(v) else None for v in series.to_numpy()]
    return [None if v is None or v is getattr(series.dtype, "na_value", None)
            or (isinstance(v, float) and not math.isfinite(v))
            else (v.item() if hasattr(v, "item") else v)
            for v in series.astype(object).where(series.notna(), None)]


def _check_finite_tables(result):
    """Refuse to write non-finite values except on flagged singular positions."""
    from crankbase.output import OutputError

    sing = result.summary.singular_phi_deg
    for name, df in (("kinematics", result.kinematics), ("forces", result.forces)):
        num = df.drop(columns=["position"]).to_numpy(dtype=float)
        bad_rows = np.flatnonzero(~np.isfinite(num).all(axis=1))
        for r in bad_rows:
            phi = float(df["phi_deg"].iat[r])
            if not any(abs((phi - a + 180.0) % 360.0 - 180.0) < SAME_ANGLE_DEG for a in sing):
                raise OutputError(f"{name}: row {r + 1} (φ = {phi:g}°) is not finite")
