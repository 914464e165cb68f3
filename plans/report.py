"""Write the plans of chosen positions into a folder (the caller stages it, see
``crankbase.output.staged_output``).

Files
-----
Every file is named after the mechanism, ``<name>_…`` (``<name>`` = the spec's name as a
file stem, :func:`crankbase.output.safe_name`, as the other linkage outputs), so the
plans of two mechanisms written into one folder never mix:

``<name>_plans_<pos>.svg``, ``<name>_plans_<pos>.pdf``
    All plans of a position at true scale (1 mm of a plan = 1 mm of paper at 100 %).
``<name>_plans_<pos>.png``
    Preview of the same (150 dpi).
``<name>_plans.csv``
    ``position, plan, segment, length_mm, value, unit, scale`` (the lever's arrows too).
``<name>_lever.csv``
    ``position, M_lever_Nm, M_kinetostatic_Nm, difference_percent, F_lever_N,
    F_kinetostatic_N, scale_N_per_mm``.
``<name>_lever_forces.csv``
    Every force on the lever with its point, magnitude, arm, moment and arrow length.
``<name>_student_table.csv``
    The table a student fills from the plans (segments, labels, lengths, values, ω and ε).
``<name>_plan_errors.csv``
    With measurements: the error of the plan method in % per measured segment.
``<name>_sheet.pdf``, ``<name>_sheet.dxf`` (``<name>_sheet_2.dxf`` … when the plans need
more sheets), ``<name>_sheet.png`` (``<name>_sheet_2.png`` …)
    The drawing sheet(s) A1 or A3 landscape; the PDF has one page per sheet.
"""
from __future__ import annotations

from pathlib import Path

from crankbase.output import safe_name, save_figure

from .drawing import layout_fitted, position_figure, sheet_figure, title_fields
from .dxf import write_dxf
from .tables import (error_table, lever_forces_table, lever_table, plans_table,
                     student_table)

__all__ = ["write_plans", "output_names", "summary_lines"]


def _csv(df, path):
    # full precision (shortest round-trip repr), as crankdyn's other CSV files
    df.to_csv(path, index=False, float_format=None, lineterminator="\n")


def output_names(name, tags, sheets=1, measurements=False, previews=True):
    """The file names :func:`write_plans` writes for mechanism file stem ``name``,
    position tags ``tags`` (``5``, ``phi37.5``) and ``sheets`` drawing sheets."""
    out = []
    for tag in tags:
        out += [f"{name}_plans_{tag}.svg", f"{name}_plans_{tag}.pdf"]
        if previews:
            out.append(f"{name}_plans_{tag}.png")
    out += [f"{name}_{t}.csv" for t in ("plans", "lever", "lever_forces", "student_table")]
    if measurements:
        out.append(f"{name}_plan_errors.csv")
    out.append(f"{name}_sheet.pdf")
    for k in range(sheets):
        sfx = "" if k == 0 else f"_{k + 1}"
        out.append(f"{name}_sheet{sfx}.dxf")
        if previews:
            out.append(f"{name}_sheet{sfx}.png")
    return out


def write_plans(result, plans, folder, *, name=None, lang="ru", sheet="A1",
                measurements=None, previews=True):
    """Write every output of the plans into ``folder``.

    Parameters
    ----------
    result : linkage.AnalysisResult
    plans : list of PositionPlans
    folder : path-like
        An existing (staging) folder.
    name : str, optional
        File stem of the outputs, ``<name>_plans.csv`` … (default: the spec's name via
        :func:`crankbase.output.safe_name`, as ``crankdyn linkage`` names its files).
    lang : {"ru", "en"}
    sheet : {"A1", "A3"}
    measurements : DataFrame, optional
        :func:`plans.tables.read_measurements`; adds ``<name>_plan_errors.csv``.
    previews : bool
        Also write the PNG previews.

    Returns
    -------
    dict
        ``{"sheets": number of sheets, "errors": the error table or None, "name": the
        file stem, "plans": the plans as drawn}``: a diagram too large for the sheet at
        its default scale is drawn at a coarser round one (:func:`plans.drawing.fit_plans`)
        and every file (the CSVs, each position's figure, the sheets) holds that scale.
    """
    from matplotlib.backends.backend_pdf import PdfPages

    folder = Path(folder)
    stem = name if name is not None else safe_name(result.spec.name, "linkage")
    fields = title_fields(result.spec)
    # raises before writing; the plans at the scales drawn
    sheets, plans = layout_fitted(result, plans, lang, sheet, fields)
    for pp in plans:
        fig = position_figure(pp, lang)
        save_figure(fig, folder / f"{stem}_plans_{pp.tag}", formats=("svg", "pdf"))
        if previews:
            save_figure(fig, folder / f"{stem}_plans_{pp.tag}", formats=("png",), dpi=150)
    _csv(plans_table(plans), folder / f"{stem}_plans.csv")
    if all(pp.lever is not None for pp in plans):
        _csv(lever_table(plans), folder / f"{stem}_lever.csv")
        _csv(lever_forces_table(plans), folder / f"{stem}_lever_forces.csv")
    st = student_table(plans)
    _csv(st, folder / f"{stem}_student_table.csv")
    errors = None
    if measurements is not None:
        errors = error_table(st, measurements)
        _csv(errors, folder / f"{stem}_plan_errors.csv")

    def sheet_file(k, ext):
        return folder / f"{stem}_sheet{'' if k == 0 else f'_{k + 1}'}.{ext}"

    from crankbase.plot_texts import cjk_texts

    with PdfPages(folder / f"{stem}_sheet.pdf") as pdf:
        for k, sh in enumerate(sheets):
            fig = sheet_figure(sh)
            cjk_texts(fig)
            pdf.savefig(fig)
            if previews:
                fig.savefig(sheet_file(k, "png"), dpi=60)
    for k, sh in enumerate(sheets):
        write_dxf(sh, sheet_file(k, "dxf"))
    return {"sheets": len(sheets), "errors": errors, "name": stem, "plans": plans}


def _lever_plan(t, pp, size):
    """The line that says a lever is drawn on a coarser copy of the velocity plan (to fit
    the sheet, :func:`plans.drawing.fit_plans`), or none."""
    mv = pp.lever.plan_scale
    if mv is None or mv == pp.plans["velocity"].scale:
        return []
    return ["      " + t("plans.summary.lever_plan", mv=f"{mv:g}", size=size)]


def summary_lines(plans, size, sheets, lang="ru", errors=None):
    """The graphical method's lines of the terminal summary in ``lang``: the positions
    and drawing sheets, then per position Mb by Zhukovsky's lever against the
    kinetostatics and the balancing force at A; with ``errors``
    (:func:`plans.tables.error_table`) the largest error of the plan method.  Words from
    the catalogue (``plans.po``); every number formatted once, the same in both
    languages, never as a negative zero."""
    import numpy as np

    from crankbase.texts import texts
    from crankbase.tolerances import format_snapped

    t = texts(lang)
    chain = any(pp.kind == "chain" for pp in plans)
    lines = ["  " + t("plans.summary.plans_chain" if chain else "plans.summary.plans",
                      positions=t.n("plans.summary.positions", len(plans)),
                      sheets=t.n("plans.summary.sheets", sheets, size=size))]
    for pp in plans:
        L = pp.lever
        if pp.kind == "chain":                         # a chain: scales and closure
            err = max([0.0] + [e for p in pp.plans.values() for e in p.closure()])
            lines.append("    " + t("plans.summary.chain", tag=pp.tag,
                                     mv=f"{pp.plans['velocity'].scale:g}",
                                     ma=f"{pp.plans['acceleration'].scale:g}",
                                     err=f"{err:.0e}"))
            if L is not None:
                scale = max(abs(L.M_lever_Nm), abs(L.M_kinetostatic_Nm))
                lines.append("      " + t("plans.summary.chain_lever",
                                           lever=format_snapped(L.M_lever_Nm, ".4f", scale),
                                           kin=format_snapped(L.M_kinetostatic_Nm, ".4f",
                                                              scale),
                                           diff=format_snapped(L.difference_percent, ".1e"),
                                           Fb=format_snapped(L.balancing_force_N, ".3f"),
                                           mf=f"{L.scale:g}", pivot=pp.driver[0],
                                           pin=pp.driver[1]))
                lines += _lever_plan(t, pp, size)
            continue
        scale = max(abs(L.M_lever_Nm), abs(L.M_kinetostatic_Nm))
        lines.append("    " + t("plans.summary.lever", tag=pp.tag,
                                 lever=format_snapped(L.M_lever_Nm, ".4f", scale),
                                 kin=format_snapped(L.M_kinetostatic_Nm, ".4f", scale),
                                 diff=format_snapped(L.difference_percent, ".1e"),
                                 Fb=format_snapped(L.balancing_force_N, ".3f"),
                                 pivot=pp.driver[0], pin=pp.driver[1]))
        lines += _lever_plan(t, pp, size)
    if errors is not None and len(errors):
        err = errors["error_percent"].to_numpy(float)
        if np.isfinite(err).any():
            i = int(np.nanargmax(np.abs(err)))
            lines.append("  " + t.n("plans.summary.measured", len(errors),
                                    err=format_snapped(err[i], ".2f"),
                                    pos=errors["position"].iat[i]))
    return lines
