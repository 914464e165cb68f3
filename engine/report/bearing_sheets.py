"""Workbook sheets of the bearing loads (openpyxl, imported when used).

:func:`add_bearing_sheets` appends to the force-table workbook of
:func:`engine.report.build_workbook` a summary sheet (pin and journal loads: max, mean,
min with their angles, χ; the most loaded pin and journal; the torques carried by the
journals; the oil-hole directions; the rigid rod's differences; the conventions) and one
sheet per bearing table, with the CSV column names as headers and every value at full
precision (saved by :func:`engine.report.save_workbook`).  Nothing here computes physics.
"""
from __future__ import annotations

from crankbase.workbook import Words

from ..bearings.loads import load_stats

__all__ = ["add_bearing_sheets", "SHEET_NAMES"]

#: The bearing tables (by CSV file name) and the summary: their sheets' titles are
#: ``sheet.bearings.sheet.<name>`` of the catalogue.
SHEET_KEYS = ("crankpins.csv", "journals.csv", "journal_torques.csv", "rod_bearings.csv",
              "wear.csv", "rod_model.csv", "summary")


class _SheetNames(dict):
    def __missing__(self, lang):
        from crankbase.workbook import words

        self[lang] = words(lang, "sheet.bearings", {"sheet": ("dict", SHEET_KEYS)})["sheet"]
        return self[lang]


#: Sheet title of each bearing table (by CSV file name), per language:
#: ``SHEET_NAMES[lang][csv]``.
SHEET_NAMES = _SheetNames()

#: The shape of the words (crankbase.workbook.words); the words are in the catalogue
#: crankbase/locale/<lang>/sheet.po under ``sheet.bearings.*``.
_T_SHAPE = {'amax': 'str',
 'amin': 'str',
 'be': 'str',
 'chi': 'str',
 'conv': ('tuple', 3),
 'half': 'str',
 'hole': 'str',
 'hole_j': 'str',
 'hole_pin': 'str',
 'jr': 'str',
 'max': 'str',
 'mean': 'str',
 'min': 'str',
 'most_j': 'str',
 'most_pin': 'str',
 'most_t': 'str',
 'pin': 'str',
 'pp': 'str',
 'rod': 'str',
 'swing': 'str',
 'title': 'str',
 'tq': 'str',
 'what': 'str'}

_T = Words('sheet.bearings', _T_SHAPE)



def _put(ws, row, col, value):
    cell = ws.cell(row, col)
    cell.value = value
    if isinstance(value, str):
        cell.data_type = "s"
    return cell


def add_bearing_sheets(wb, tables, analysis, lang="ru"):
    """Append the bearing sheets to a workbook.

    Parameters
    ----------
    wb : openpyxl.Workbook
    tables : dict of {str: pandas.DataFrame}
        The bearing tables by CSV file name (as written beside the workbook).
    analysis : engine.bearings.analysis.BearingAnalysis
        On the fine grid: the statistics, oil holes and the rod comparison.
    lang : {"ru", "en"}

    Returns
    -------
    openpyxl.Workbook
        ``wb``, with the summary sheet and one sheet per table appended.
    """
    from openpyxl.styles import Font

    t, names = _T[lang], SHEET_NAMES[lang]
    loads = analysis.loads
    ws = wb.create_sheet(names["summary"])
    _put(ws, 1, 1, t["title"]).font = Font(bold=True, size=12)
    head = (t["what"], t["max"], t["amax"], t["min"], t["amin"], t["mean"], t["chi"])
    for c, h in enumerate(head, start=1):
        _put(ws, 3, c, h).font = Font(bold=True)
    row = 4
    stats = [(t["pin"].format(k=k + 1), s) for k, s in enumerate(loads.pin_stats)]
    stats += [(t["jr"].format(j=j + 1), s) for j, s in enumerate(loads.journal_stats)]
    rb = analysis.rod_bearings
    cyc = 720.0 if rb["alpha_deg"].iloc[-1] - rb["alpha_deg"].iloc[0] > 360.0 else 360.0
    for col, label in (("Rbe_N", t["be"]), ("Pp_N", t["pp"])):
        if not rb[col].isna().any():
            stats.append((label, load_stats(rb["alpha_deg"], rb[col], cyc)))
    for label, s in stats:
        for c, v in enumerate((label, s.max_N, s.alpha_max_deg, s.min_N, s.alpha_min_deg,
                               s.mean_N, s.chi), start=1):
            _put(ws, row, c, v)
        row += 1
    for j, s in enumerate(loads.torque_stats):
        for c, v in enumerate((t["tq"].format(j=j + 1), s["max_Nm"], None, s["min_Nm"],
                               None, None, None), start=1):
            _put(ws, row, c, v)
        _put(ws, row, 8, t["swing"])
        _put(ws, row, 9, s["swing_Nm"])
        row += 1
    row += 1
    for label, v in ((t["most_pin"], loads.most_loaded_pin),
                     (t["most_j"], loads.most_loaded_journal),
                     (t["most_t"], loads.most_twisted_journal),
                     (t["half"], analysis.options.wear_half_angle_deg)):
        _put(ws, row, 1, label)
        _put(ws, row, 2, v)
        row += 1
    _put(ws, row, 1, t["hole"]).font = Font(bold=True)
    row += 1
    pins = analysis.pin_wear if isinstance(analysis.pin_wear, list) else [analysis.pin_wear]
    holes = [(t["hole_pin"].format(k=k + 1), w.oil_hole_deg) for k, w in enumerate(pins)]
    holes += [(t["hole_j"].format(j=j + 1), w.oil_hole_deg)
              for j, w in enumerate(analysis.journal_wear)]
    for label, v in holes:
        _put(ws, row, 1, label)
        _put(ws, row, 2, v)
        row += 1
    if analysis.rod_comparison is not None:
        row += 1
        _put(ws, row, 1, t["rod"]).font = Font(bold=True)
        row += 1
        for col, (mx, amx, mn, amn) in analysis.rod_comparison.extremes.items():
            for c, v in enumerate((col, mx, amx, mn, amn), start=1):
                _put(ws, row, c, v)
            row += 1
    row += 1
    for line in t["conv"]:
        _put(ws, row, 1, line)
        row += 1
    from .workbook import readable_numbers

    readable_numbers(ws, {"A": 46}, default_width=14, per_column=False)

    from crankbase.workbook import put_numbers, sheet_rows, thinned_note

    for fname, df in tables.items():
        sh = wb.create_sheet(names[fname])
        for c, name in enumerate(df.columns, start=1):
            _put(sh, 1, c, name).font = Font(bold=True)
        shown = sheet_rows(df)                   # a fine table step: every k-th row, the CSV all
        if len(shown) < len(df):
            _put(sh, 1, len(df.columns) + 2, thinned_note(df, shown, fname, lang))
            sh.merge_cells(start_row=1, start_column=len(df.columns) + 2, end_row=1,
                           end_column=len(df.columns) + 7)
        put_numbers(sh, 2, 1, shown.to_numpy(dtype=float).tolist())
        sh.freeze_panes = "B2"
        readable_numbers(sh, default_width=12)
    return wb
