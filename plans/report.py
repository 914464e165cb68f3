"""Write the plans of chosen positions into a folder (the caller stages it, see
``crankbase.output.staged_output``).

Files
-----
``plans_<pos>.svg``, ``plans_<pos>.pdf``
    All plans of a position at true scale (1 mm of a plan = 1 mm of paper at 100 %).
``plans_<pos>.png``
    Preview of the same (150 dpi).
``plans.csv``
    ``position, plan, segment, length_mm, value, unit, scale``.
``lever.csv``
    ``position, M_lever_Nm, M_kinetostatic_Nm, difference_percent``.
``lever_forces.csv``
    Every force on the lever with its point, magnitude, arm and moment.
``student_table.csv``
    The table a student fills from the plans (segments, labels, lengths, values, ω and ε).
``plan_errors.csv``
    With measurements: the error of the plan method in % per measured segment.
``sheet.pdf``, ``sheet.dxf`` (``sheet_2.dxf`` … when the plans need more sheets),
``sheet.png``
    The drawing sheet(s) A1 or A3 landscape; the PDF has one page per sheet.
"""
from __future__ import annotations

from pathlib import Path

from .drawing import layout_sheets, position_figure, sheet_figure, title_fields
from .dxf import write_dxf
from .tables import (error_table, lever_forces_table, lever_table, plans_table,
                     student_table)

__all__ = ["write_plans"]


def _csv(df, path):
    # full precision (shortest round-trip repr), as crankdyn's other CSV files
    df.to_csv(path, index=False, float_format=None, lineterminator="\n")


def write_plans(result, plans, folder, *, lang="ru", sheet="A1", measurements=None,
                previews=True):
    """Write every output of the plans into ``folder``.

    Parameters
    ----------
    result : linkage.AnalysisResult
    plans : list of PositionPlans
    folder : path-like
        An existing (staging) folder.
    lang : {"ru", "en"}
    sheet : {"A1", "A3"}
    measurements : DataFrame, optional
        :func:`plans.tables.read_measurements`; adds ``plan_errors.csv``.
    previews : bool
        Also write the PNG previews.

    Returns
    -------
    dict
        ``{"sheets": number of sheets, "errors": the error table or None}``.
    """
    from matplotlib.backends.backend_pdf import PdfPages

    folder = Path(folder)
    fields = title_fields(result.spec)
    sheets = layout_sheets(result, plans, lang, sheet, fields)   # raises before writing
    for pp in plans:
        fig = position_figure(pp, lang)
        fig.savefig(folder / f"plans_{pp.tag}.svg")
        fig.savefig(folder / f"plans_{pp.tag}.pdf")
        if previews:
            fig.savefig(folder / f"plans_{pp.tag}.png", dpi=150)
    _csv(plans_table(plans), folder / "plans.csv")
    _csv(lever_table(plans), folder / "lever.csv")
    _csv(lever_forces_table(plans), folder / "lever_forces.csv")
    st = student_table(plans)
    _csv(st, folder / "student_table.csv")
    errors = None
    if measurements is not None:
        errors = error_table(st, measurements)
        _csv(errors, folder / "plan_errors.csv")
    with PdfPages(folder / "sheet.pdf") as pdf:
        for k, sh in enumerate(sheets):
            fig = sheet_figure(sh)
            pdf.savefig(fig)
            if previews:
                fig.savefig(folder / ("sheet.png" if k == 0 else f"sheet_{k + 1}.png"),
                            dpi=60)
    for k, sh in enumerate(sheets):
        write_dxf(sh, folder / ("sheet.dxf" if k == 0 else f"sheet_{k + 1}.dxf"))
    return {"sheets": len(sheets), "errors": errors}
