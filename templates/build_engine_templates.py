"""Build the Excel templates of the engine report: ``engine_<lang>.xlsx`` (ru, en, zh: every
offered language, :func:`crankbase.texts.languages`).

The templates own the look (fonts, borders, merged two-row headers "мм | Н" per force as
in the textbook's Table 2, column widths, number formats) and every word of text (taken
from the catalogue ``crankbase/locale/<lang>/sheet.po``, keys ``sheet.engine.*``); the
code (:mod:`engine.report`) only fills values, matched by the keys in the hidden column
A of the Inputs and Summary sheets, and adds the charts.

Run from the repository root after changing the layout::

    python templates/build_engine_templates.py
"""
from __future__ import annotations

from pathlib import Path

from openpyxl import Workbook
from openpyxl.styles import Alignment, Border, Font, PatternFill, Side
from openpyxl.utils import get_column_letter

HERE = Path(__file__).resolve().parent

#: Sheets, by position (the report looks sheets up by position); their names are
#: ``sheet.engine.sheet.<name>`` of the catalogue.
SHEET_KEYS = ("inputs", "table2", "summary", "data", "charts")

#: Rows of the Inputs sheet: (key, symbol, unit, number format); the label is
#: ``sheet.engine.input.<key>`` of the catalogue (crankbase/locale/<lang>/sheet.po), the
#: unit a key of :data:`crankbase.texts.UNITS` ("deg": the degree of a unit column; ""
#: none) spelled by :meth:`crankbase.texts.Texts.unit`; the English symbols by
#: :func:`english_symbols`.
INPUTS = [
    ('name', '', '', '@'),
    ('strokes', 'τ', '', '0'),
    ('cylinders', 'i', '', '0'),
    ('bore_mm', 'D', 'mm', '0.0##'),
    ('stroke_mm', 'S', 'mm', '0.0##'),
    ('R_mm', 'R = S/2', 'mm', '0.0##'),
    ('L_mm', 'Lш', 'mm', '0.0##'),
    ('lam', 'λ = R/Lш', '', '0.0000'),
    ('speed_rpm', 'n', 'rpm', '0'),
    ('omega', 'ω = πn/30', 'rad/s', '0.00'),
    ('v_mean', 'vп.ср = Sn/30', 'm/s', '0.00'),
    ('p0_MPa', 'p0', 'MPa', '0.000'),
    ('area_cm2', 'Fп = πD²/4', 'cm²', '0.00'),
    ('Vh_l', 'Vh = Fп·S', 'l', '0.0000'),
    ('compression_ratio', 'ε', '', '0.00'),
    ('acceleration', 'j', '', '@'),
    ('mass_input', '', '', '@'),
    ('mj', 'mj = mп + mш.п', 'kg', '0.000'),
    ('m_rod_rot', 'mш.к', 'kg', '0.000'),
    ('m_crank_rot', 'mк', 'kg', '0.000'),
    ('Kr', 'Kr.ш = −mш.к·R·ω²', 'N', '0.0'),
    ('mu_P', 'μP', 'N/mm', '0.###'),
    ('step_deg', 'Δα', 'deg', '0.###'),
    ('extra_angles', '', 'deg', '@'),
    ('pressure_source', 'pг(α)', '', '@'),
    ('cycle_kind', '', '', '@'),
    ('pa', 'pa', 'MPa', '0.000'),
    ('pr', 'pr', 'MPa', '0.000'),
    ('n1', 'n1', '', '0.000'),
    ('n2', 'n2', '', '0.000'),
    ('pc', 'pc = pa·ε^n1', 'MPa', '0.000'),
    ('pz', 'pz', 'MPa', '0.000'),
    ('lambda_z', 'λz = pz/pc', '', '0.000'),
    ('rho', 'ρ', '', '0.000'),
    ('rounding', '', '', '@'),
    ('advance_deg', 'θ', 'deg', '0.#'),
    ('pc_factor', 'pc″/pc', '', '0.00'),
    ('peak_factor', 'pzд/pz', '', '0.00'),
    ('peak_after_tdc_deg', '', 'deg', '0.#'),
    ('exhaust_opening_deg', '', 'deg', '0.#'),
    ('intake_opening_deg', '', 'deg', '0.#'),
    ('exhaust_closing_deg', '', 'deg', '0.#'),
    ('pi_theory', 'p′i', 'MPa', '0.0000'),
    ('pi', 'pi = ∮p dV / Vh', 'MPa', '0.0000'),
    ('power_i', 'Ni = pi·Vh·n/(30τ)', 'kW', '0.00'),
]

#: Lines of the conventions under the inputs: ``sheet.engine.conventions.<i>``.
N_CONVENTIONS = 12

# Table 2: the force symbols
FORCES = ['ΔPг', 'Pj', 'P', 'Sш', 'N', 'K', 'T', 'Rшш']

#: Summary rows with extremes: (key, symbol, unit); the label ``sheet.engine.extreme.<key>``
SUMMARY_EXTREMES = [
    ('P_N', 'P', 'N'),
    ('S_N', 'Sш', 'N'),
    ('N_N', 'N', 'N'),
    ('K_N', 'K', 'N'),
    ('T_N', 'T', 'N'),
    ('M_Nm', 'Mкр', 'N·m'),
    ('R_N', 'Rшш', 'N'),
]
#: Summary rows of one value: (key, symbol, unit, format); the label
#: ``sheet.engine.value.<key>``
SUMMARY_VALUES = [
    ('p_max_MPa', 'pг max', 'MPa', '0.000'),
    ('alpha_p_max_deg', 'α(pг max)', 'deg', '0.0'),
    ('M_mean_Nm', 'Mкр.ср', 'N·m', '0.00'),
    ('R_mean_N', 'Rшш.ср', 'N', '0'),
    ('chi', 'χ = Rшш.max/Rшш.ср', '', '0.000'),
    ('pi_MPa', 'pi', 'MPa', '0.0000'),
    ('power_i_kW', 'Ni', 'kW', '0.00'),
]


def _words(lang):
    """The catalogue's texts of ``lang`` (:func:`crankbase.texts.texts`)."""
    from crankbase.texts import texts

    return texts(lang)


def english_symbols(text):
    """An English template string with the Russian symbols replaced by the English ones of
    :mod:`engine.symbols` (the one table of symbols; imported here, in the build script,
    not at run time)."""
    from engine.symbols import to_english
    return to_english(text)


def _check_no_cyrillic(wb):
    import re

    cyrillic = re.compile("[\u0400-\u04ff]")
    for ws in wb.worksheets:
        for row in ws.iter_rows():
            for c in row:
                if isinstance(c.value, str) and cyrillic.search(c.value):
                    raise ValueError(f"Cyrillic left in the English template: {ws.title}!"
                                     f"{c.coordinate} {c.value!r}")


THIN = Side(style="thin", color="000000")
BORDER = Border(left=THIN, right=THIN, top=THIN, bottom=THIN)
HEAD_FILL = PatternFill("solid", fgColor="DDE4EE")
CENTER = Alignment(horizontal="center", vertical="center", wrap_text=True)
LEFT = Alignment(horizontal="left", vertical="center", wrap_text=True)


def _fonts(lang):
    """Body, bold, title and note fonts: the one family of every workbook
    (:data:`crankbase.workbook.FONT`) in both languages."""
    from crankbase.workbook import FONT as family

    return (Font(name=family, size=11), Font(name=family, size=11, bold=True),
            Font(name=family, size=13, bold=True), Font(name=family, size=10, italic=True))


def _fit_width(ws, orientation):
    """A4, one page wide, as many pages tall as needed."""
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = orientation
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    ws.page_setup.fitToWidth = 1
    ws.page_setup.fitToHeight = 0


def _symbol_table(ws, r, lang, bold, body):
    """The table of symbols below the conventions: in the Russian template the Russian
    textbook symbol, the English report's symbol and the meaning; in the English one the
    English symbol and its meaning (no Cyrillic), every symbol of :mod:`engine.symbols`
    whose two forms differ."""
    from engine.symbols import correspondence

    from openpyxl.worksheet.pagebreak import Break

    ws.row_breaks.append(Break(id=r - 1))      # the table starts a page, with its title
    t = _words(lang)
    ru = t.symbol(True, False)       # the Russian textbook's symbols: a column of each set
    title = t("sheet.engine.symbols_title")
    c = ws.cell(r, 2, title)
    c.font = bold
    c.alignment = Alignment(wrap_text=True, vertical="top")
    ws.merge_cells(start_row=r, start_column=2, end_row=r, end_column=5)
    ws.row_dimensions[r].height = 15 if ru else 30
    head = tuple(t(f"sheet.engine.head.{k}") for k in (
        ("quantity", "ru_report", "en_report") if ru else ("quantity", "symbol")))
    for j, h in enumerate(head, start=2):
        c = ws.cell(r + 1, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    for i, (en, rus, what) in enumerate(correspondence(lang), start=r + 2):
        row = (what, rus, en) if ru else (what, en)
        for j, v in enumerate(row, start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j == 2 else CENTER
        # a meaning longer than column B (50 characters wide) wraps onto a second line
        ws.row_dimensions[i].height = 15 if len(what) <= 55 else 30


def build(lang: str, path: Path) -> None:
    body, bold, title, note = _fonts(lang)
    t = _words(lang)

    def heads(*keys):
        return tuple(t(f"sheet.engine.head.{k}") for k in keys)
    wb = Workbook()
    ws_in = wb.active
    ws_in.title = t("sheet.engine.sheet.inputs")
    ws_t2, ws_sum, ws_data, ws_ch = (wb.create_sheet(t(f"sheet.engine.sheet.{k}"))
                                     for k in SHEET_KEYS[1:])

    # ---------------------------------------------------------------- Inputs
    ws = ws_in
    ws["B1"] = t("sheet.engine.title.inputs")
    ws["B1"].font = title
    ws["A3"] = "key"
    for j, h in enumerate(heads("quantity", "symbol", "value", "unit"), start=2):
        c = ws.cell(3, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    for i, (key, sym, unit, fmt) in enumerate(INPUTS, start=4):
        ws.cell(i, 1, key)
        for j, v in enumerate((t(f"sheet.engine.input.{key}"), sym, None, t.unit(unit)),
                              start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j in (2, 4) else CENTER
        ws.cell(i, 4).number_format = fmt
        ws.cell(i, 4).alignment = Alignment(horizontal="right", vertical="center",
                                            wrap_text=True)
    r = 4 + len(INPUTS) + 1
    for k, line in enumerate(t(f"sheet.engine.conventions.{i}")
                             for i in range(N_CONVENTIONS)):
        c = ws.cell(r + k, 2, line)
        c.font = bold if k == 0 else note
        c.alignment = Alignment(wrap_text=True, vertical="top")
        ws.merge_cells(start_row=r + k, start_column=2, end_row=r + k, end_column=5)
        ws.row_dimensions[r + k].height = 15 if k == 0 else 30
    r += N_CONVENTIONS + 1
    _symbol_table(ws, r, lang, bold, body)
    ws.column_dimensions["A"].hidden = True
    for col, w in zip("BCDE", (50, 20, 40, 10)):
        ws.column_dimensions[col].width = w
    ws.freeze_panes = "B4"
    _fit_width(ws, "portrait")

    # ---------------------------------------------------------------- Table 2
    ws = ws_t2
    ws["A1"] = t("sheet.engine.title.table2")
    ws["A1"].font = title
    ws["A2"] = t("sheet.engine.mu_p")
    ws["A2"].font = bold
    ws["C2"].number_format = "0.###"
    ws["C2"].font = bold
    ws.merge_cells("A2:B2")
    mm, nn = t("sheet.engine.mm"), t("sheet.engine.newton")
    ws.cell(3, 1, "α, °")
    ws.merge_cells(start_row=3, start_column=1, end_row=4, end_column=1)
    col = 2
    for sym in FORCES:
        ws.cell(3, col, sym)
        ws.merge_cells(start_row=3, start_column=col, end_row=3, end_column=col + 1)
        ws.cell(4, col, mm)
        ws.cell(4, col + 1, nn)
        col += 2
    ws.cell(3, col, t("sheet.engine.torque_head"))
    ws.merge_cells(start_row=3, start_column=col, end_row=4, end_column=col)
    ws.cell(3, col + 1, "Ψ, °")
    ws.merge_cells(start_row=3, start_column=col + 1, end_row=4, end_column=col + 1)
    ncol = col + 1
    for rr in (3, 4):
        for cc in range(1, ncol + 1):
            c = ws.cell(rr, cc)
            c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    # prototype data row (row 5): the report copies its styles to every row
    formats = ["0.##"] + ["0.0", "0"] * len(FORCES) + ["0.0", "0.0"]
    for cc in range(1, ncol + 1):
        c = ws.cell(5, cc)
        c.font, c.border = body, BORDER
        c.alignment = Alignment(horizontal="right")
        c.number_format = formats[cc - 1]
    ws.column_dimensions["A"].width = 8
    for cc in range(2, ncol + 1):
        ws.column_dimensions[get_column_letter(cc)].width = 9 if cc % 2 == 0 else 10
    ws.column_dimensions[get_column_letter(ncol - 1)].width = 10
    ws.column_dimensions[get_column_letter(ncol)].width = 8
    ws.freeze_panes = "B5"
    ws.print_title_rows = "3:4"
    _fit_width(ws, "landscape")

    # ---------------------------------------------------------------- Summary
    ws = ws_sum
    ws["B1"] = t("sheet.engine.title.summary")
    ws["B1"].font = title
    ws["A3"] = "key"
    for j, h in enumerate(heads("quantity", "symbol", "maximum", "alpha_max", "minimum",
                                "alpha_min", "unit"), start=2):
        c = ws.cell(3, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    for i, (key, sym, unit) in enumerate(SUMMARY_EXTREMES, start=4):
        ws.cell(i, 1, key)
        vals = (t(f"sheet.engine.extreme.{key}"), sym, None, None, None, None, t.unit(unit))
        for j, v in enumerate(vals, start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j == 2 else CENTER
        for j, fmt in zip((4, 5, 6, 7), ("0.0", "0.##", "0.0", "0.##")):
            ws.cell(i, j).number_format = fmt
            ws.cell(i, j).alignment = Alignment(horizontal="right")
    r0 = 4 + len(SUMMARY_EXTREMES) + 1
    for j, h in enumerate(heads("quantity", "symbol", "value", "unit"), start=2):
        c = ws.cell(r0, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    ws.cell(r0, 1, "key")
    for i, (key, sym, unit, fmt) in enumerate(SUMMARY_VALUES, start=r0 + 1):
        ws.cell(i, 1, key)
        for j, v in enumerate((t(f"sheet.engine.value.{key}"), sym, None, t.unit(unit)),
                              start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j == 2 else CENTER
        ws.cell(i, 4).number_format = fmt
        ws.cell(i, 4).alignment = Alignment(horizontal="right")
    note_row = r0 + len(SUMMARY_VALUES) + 2
    c = ws.cell(note_row, 2, t("sheet.engine.summary_note"))
    c.font = note
    c.alignment = Alignment(wrap_text=True, vertical="top")
    ws.merge_cells(start_row=note_row, start_column=2, end_row=note_row, end_column=8)
    ws.row_dimensions[note_row].height = 45
    ws.column_dimensions["A"].hidden = True
    for col, w in zip("BCDEFGH", (44, 20, 13, 13, 13, 13, 9)):
        ws.column_dimensions[col].width = w
    _fit_width(ws, "landscape")

    # ---------------------------------------------------------------- Data
    ws = ws_data
    ws["A1"] = t("sheet.engine.title.data")
    ws["A1"].font = title
    # row 3: the CSV header (filled by the code, styled here); row 4: prototype data row
    for cc in range(1, 18):
        c = ws.cell(3, cc)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
        d = ws.cell(4, cc)
        d.font, d.border = body, BORDER
        d.number_format = "0.000"
        ws.column_dimensions[get_column_letter(cc)].width = 12
    ws.freeze_panes = "B4"
    ws.print_title_rows = "3:3"
    _fit_width(ws, "landscape")

    # ---------------------------------------------------------------- Charts
    ws_ch["A1"] = t("sheet.engine.charts_title")
    ws_ch["A1"].font = title
    ws_ch.merge_cells("A1:J1")
    _fit_width(ws_ch, "portrait")

    if not t.symbol(True, False):     # a language of the Latin symbols (its catalogue says)
        for ws in wb.worksheets:
            for row in ws.iter_rows():
                for c in row:
                    if isinstance(c.value, str):
                        c.value = english_symbols(c.value)
        _check_no_cyrillic(wb)
    wb.properties.title = t("sheet.engine.title.table2")
    wb.properties.creator = "crankdyn"
    wb.save(path)


def main():
    from crankbase.texts import languages

    for lang in languages():
        out = HERE / f"engine_{lang}.xlsx"
        build(lang, out)
        print("wrote", out)


if __name__ == "__main__":
    main()
