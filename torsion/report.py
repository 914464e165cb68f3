"""The workbook of a torsional-vibration report (``<name>_torsion.xlsx``).

One sheet per table: the chain, the natural modes, the Holzer tables in the course's form
(one block per frequency: mass, J, θ, Jω²θ, ΣJω²θ, k, ΣJω²θ/k, and the residual torque
after the last mass), the torque harmonics, the critical speeds and the forced response;
each table with two header rows (the quantity in the report's language over the CSV
column name) and the house look and A4 print setup of :func:`crankbase.workbook.finish`.
openpyxl is imported only here.
"""
from __future__ import annotations

import math
import re

import numpy as np

from crankbase.texts import texts

__all__ = ["build_workbook", "column_label", "mass_label", "PARTS"]

#: The parts of one cylinder's torque (the harmonics' ``part`` column), each a catalogue
#: entry ``torsion.part.<part>``.
PARTS = ("gas", "inertia", "total")

_THROW = re.compile(r"(?<![\w])throw(\d+)(?![\w])")

#: Rows an A4 portrait page holds at the default height (the wrapped two-line headers
#: taken into account): the Holzer sheet starts a page before a block that would not fit.
ROWS_PER_PAGE = 44

#: Columns whose label is a catalogue entry ``torsion.col.<column>``.
FIXED_COLUMNS = ("mass", "J_kgm2", "k_Nm_rad", "throw", "mode", "f_Hz", "omega_rad_s",
                 "nodes", "theta_rad", "inertia_torque_Nm", "sum_torque_Nm", "twist_rad",
                 "part", "order", "a_Nm", "b_Nm", "amplitude_Nm", "phase_deg", "speed_rpm",
                 "major", "sum_relative_amplitude")


def mass_label(name: str, lang: str = "ru") -> str:
    """A mass's (or a shaft section's, ``throw1-throw2``) name in ``lang``: a throw the
    chain names itself (``throw<N>``, a name no spec may give by hand) in the words of the
    language (колено 1, 曲拐1), any name the spec gives (``damper``, ``flywheel``) as given."""
    t = texts(lang)
    return _THROW.sub(lambda m: t("torsion.mass.throw", n=int(m.group(1))), name)


def column_label(column: str, lang: str = "ru") -> str:
    """The quantity of a CSV column in ``lang`` (``theta_damper`` → "θ damper",
    ``M_throw1-throw2_Nm`` → "M throw1-throw2, N·m"; a throw in the language's words,
    :func:`mass_label`)."""
    t = texts(lang)
    if column in FIXED_COLUMNS:
        return t(f"torsion.col.{column}")
    if column.startswith("theta_") and column.endswith("_deg"):
        return t("torsion.col.theta_deg_of", mass=mass_label(column[6:-4], lang))
    if column.startswith("theta_"):
        return t("torsion.col.theta_of", mass=mass_label(column[6:], lang))
    if column.startswith("swing_") and column.endswith("_deg"):
        return t("torsion.col.swing_deg_of", mass=mass_label(column[6:-4], lang))
    if column.startswith("M_") and column.endswith("_Nm"):
        return t("torsion.col.M_of", section=mass_label(column[2:-3], lang))
    if column.startswith("tau_") and column.endswith("_MPa"):
        return t("torsion.col.tau_of", section=mass_label(column[4:-4], lang))
    return column


def _word(column, value, lang):
    """A text cell of a table in ``lang``: a mass's name (:func:`mass_label`) or a part of
    the torque (``torsion.part.*``); the CSV keeps the names as they are."""
    if column == "mass":
        return mass_label(value, lang)
    if column == "part" and value in PARTS:
        return texts(lang)(f"torsion.part.{value}")
    return value


def _cell(v):
    if isinstance(v, (bool, np.bool_)):
        return int(v)
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        return None if not math.isfinite(v) else float(v)
    return v


def _table(ws, row, df, lang):
    """``df`` with its two header rows from ``row``; returns the row after it."""
    from crankbase.workbook import CellStyles, header_rows, put_numbers, sheet_rows

    from openpyxl.styles import Alignment

    first = header_rows(ws, row, [column_label(c, lang) for c in df.columns],
                        list(df.columns))
    # a text cell (a mass's name, the nodes "1.203; 3.428") stands indented from the
    # right-aligned number before it: "2467.2 6.604" would read as one row of numbers
    text = Alignment(horizontal="left", indent=1)
    rows, words = [], []            # the cells' values; the (row, column) of each text
    for r, rec in enumerate(sheet_rows(df).itertuples(index=False), start=first):
        values = []
        for j, (column, v) in enumerate(zip(df.columns, rec), start=1):
            if isinstance(v, str):
                v = _word(column, v, lang)
            if isinstance(v, str):
                words.append((r, j))
            values.append(_cell(v))
        rows.append(values)
    put_numbers(ws, first, 1, rows)     # what ws.cell(r, j, value) makes, the numbers at once
    styles = CellStyles(ws.parent)
    for key in words:
        styles(ws.cell(*key), alignment=text)
    return first + len(rows)


def _title(ws, text, row=1):
    from crankbase.workbook import font

    ws.cell(row, 1, text).font = font(bold=True, size=12)


def _holzer_sheet(wb, report, t, lang):
    """The Holzer tables as the course writes them: a block per ω, the residual torque
    ΣJω²θ after the last mass under it (0 at a natural frequency)."""
    from crankbase.workbook import font

    ws = wb.create_sheet(t("torsion.sheet.holzer"))
    _title(ws, t("torsion.sheet.holzer_title"))
    cols = ["mass", "J_kgm2", "theta_rad", "inertia_torque_Nm", "sum_torque_Nm",
            "k_Nm_rad", "twist_rad"]
    from openpyxl.worksheet.pagebreak import Break

    row = 3
    h = report.holzer
    n_modes = len(report.modes.omega_rad_s)
    page_top = 1
    for i, (w, block) in enumerate(h.groupby("omega_rad_s", sort=False)):
        if row + len(block) + 4 - page_top > ROWS_PER_PAGE and row > page_top + 2:
            ws.row_breaks.append(Break(id=row - 1))     # a block never split by a page
            page_top = row
        kind = (t("torsion.sheet.holzer_mode", mode=i + 1) if i < n_modes
                else t("torsion.sheet.holzer_trial"))
        ws.cell(row, 1, t("torsion.sheet.holzer_omega", omega=float(w),
                          f=float(w) / (2 * math.pi), kind=kind)).font = font(bold=True)
        row = _table(ws, row + 1, block[cols], lang)
        ws.cell(row, 1, t("torsion.sheet.holzer_residual",
                          M=float(block["sum_torque_Nm"].iloc[-1]))).font = font(italic=True)
        row += 2
    ws.page_setup.orientation = "portrait"


def build_workbook(report, lang: str = "ru"):
    """The report's workbook, built in memory (:func:`crankbase.workbook.save` writes
    it)."""
    from crankbase.workbook import finish, new_workbook

    t = texts(lang)
    wb = new_workbook()
    ws = wb.active
    ws.title = t("torsion.sheet.chain")
    _title(ws, t("torsion.sheet.chain_title", name=report.study.name))
    row = _table(ws, 3, report.chain.table(), lang)
    for note in report.notes:
        ws.cell(row + 1, 1, note.render(lang))
        row += 1
    ws = wb.create_sheet(t("torsion.sheet.modes"))
    _title(ws, t("torsion.sheet.modes_title"))
    _table(ws, 3, report.tables["torsion_modes.csv"], lang)
    _holzer_sheet(wb, report, t, lang)
    if report.harmonics is not None:
        ws = wb.create_sheet(t("torsion.sheet.harmonics"))
        h = report.harmonics["total"]
        _title(ws, t("torsion.sheet.harmonics_title", speed=report.speed_ref_rpm,
                     err=100.0 * h.reconstruction_rms_Nm / h.rms_Nm if h.rms_Nm else 0.0))
        _table(ws, 3, report.tables["torque_harmonics.csv"], lang)
        ws = wb.create_sheet(t("torsion.sheet.critical"))
        _title(ws, t("torsion.sheet.critical_title"))
        _table(ws, 3, report.tables["critical_speeds.csv"], lang)
        ws = wb.create_sheet(t("torsion.sheet.response"))
        _title(ws, t("torsion.sheet.response_title",
                     zeta=report.study.inputs.damping_ratio))
        _table(ws, 3, report.tables["torsion_response.csv"], lang)
        ws.freeze_panes = "B5"
        ws.print_title_rows = "3:4"
        ws.print_title_cols = "A:A"
    return finish(wb)
