"""The cheap ways of writing a workbook give what the plain ways give.

crankbase.workbook.put_numbers makes its cells without openpyxl's constructor; finish finds
a sheet's filled cells once for all its passes; crankbase.output.full_precision_xlsx writes
a row's number cells as one text; crankbase.output.paused_gc keeps the garbage collector
off while the cells are made.  Each is compared here with the plain way, cell by cell or
part by part of the saved file."""
from __future__ import annotations

import gc
import io
import zipfile

import pytest

from crankbase import workbook as wbk
from crankbase.output import full_precision_xlsx, paused_gc

_SLOTS = ("row", "column", "_value", "data_type", "_hyperlink", "_comment", "_style")


def test_put_numbers_makes_the_cells_ws_cell_makes():
    """Every slot of every cell equal to the cell ``ws.cell(r, c).value = v`` makes
    (rows and columns not swapped, data type "n"), a cell already there (a text) set
    through openpyxl, a non-number through openpyxl, and the sheet's current row."""
    from openpyxl import Workbook

    rows = [[1.5, -0.0, None, 7], [2 ** 60, 5e-324, float("nan"), "x"], [], [3.25]]
    a, b = Workbook().active, Workbook().active
    for ws in (a, b):
        ws.cell(3, 2, "there")                        # an existing cell is overwritten
    wbk.put_numbers(a, 2, 2, rows)
    for i, values in enumerate(rows, start=2):
        for j, v in enumerate(values, start=2):
            b.cell(i, j).value = v
    assert sorted(a._cells) == sorted(b._cells)
    assert (2, 2) in a._cells and a._cells[(2, 3)].value == 0.0       # row 2, column 3
    assert a._cells[(3, 2)].value == 2 ** 60 and a._cells[(2, 5)].value == 7
    for key, c in a._cells.items():
        d = b._cells[key]
        for slot in _SLOTS:
            x, y = getattr(c, slot), getattr(d, slot)
            assert x == y or (x != x and y != y), (key, slot, x, y)
        assert c.parent is a
    assert a._cells[(3, 5)].data_type == "s"           # text set the usual way
    assert a._current_row == b._current_row == 5


def test_paused_gc_restores_the_collector():
    assert gc.isenabled()
    with paused_gc():
        assert not gc.isenabled()
        with paused_gc():                              # nested: still off after
            assert not gc.isenabled()
        assert not gc.isenabled()
    assert gc.isenabled()
    with pytest.raises(ZeroDivisionError):
        with paused_gc():
            1 / 0
    assert gc.isenabled()

    @paused_gc()
    def off():
        return gc.isenabled()

    assert off() is False and off() is False and gc.isenabled()
    gc.disable()                                       # a caller that had it off
    try:
        with paused_gc():
            pass
        assert not gc.isenabled()
    finally:
        gc.enable()


def _sheet_with_everything():
    """A workbook with a table, a list of values, a long title over a row whose hidden
    key column holds a value, wrapped headers, a merged header and a text format."""
    from openpyxl.styles import Font

    wb = wbk.new_workbook()
    ws = wb.active
    ws.column_dimensions["A"].hidden = True
    ws["A1"] = "key_of_the_title"
    ws.column_dimensions["H"].hidden = True          # a hidden value the title's row covers
    ws["H1"] = "hidden"
    ws["B1"] = "A title much longer than its column, which runs over the empty cells " * 2
    ws["B1"].font = Font(bold=True, size=12)
    wbk.header_rows(ws, 3, ["Угол поворота кривошипа, °", "Сила, Н", "Момент, Н·м"],
                    ["phi_deg", "F_N", "M_Nm"], col=2)
    wbk.put_numbers(ws, 5, 2, [[float(k), 1234.5678 * k - 3.0, -0.001 * k] for k in
                               range(40)])
    ws.merge_cells("F3:G3")
    ws["F3"] = "merged header"
    for r, (label, v) in enumerate((("ω", 104.71975511965977), ("n", 1000),
                                    ("δ", 0.0125)), start=50):
        ws.cell(r, 2, label)
        ws.cell(r, 3, v)
    ws["C55"] = 12.5
    ws["C55"].number_format = "@"
    ws2 = wb.create_sheet("second")
    wbk.put_numbers(ws2, 1, 1, [[1.0, 2.0], [3.5, 4.25]])
    return wb


def _parts(wb):
    buf = io.BytesIO()
    with full_precision_xlsx():
        wb.save(buf)
    z = zipfile.ZipFile(buf)
    return {n: z.read(n) for n in z.namelist() if n != "docProps/core.xml"}


def test_finish_equals_its_passes_one_by_one():
    """finish (the filled cells found once, shared by its passes) writes the file its
    passes write one by one, each finding the cells itself."""
    shared = wbk.finish(_sheet_with_everything())
    plain = _sheet_with_everything()
    wbk.unify_fonts(plain)
    for ws in plain.worksheets:
        wbk.fit_numbers(ws)
        wbk.fit_columns(ws)
        wbk.fit_rows(ws)
        wbk.page_setup(ws)
    a, b = _parts(shared), _parts(plain)
    assert list(a) == list(b)
    for part in a:
        assert a[part] == b[part], part
    ws = shared.active
    assert ws["C6"].number_format == "0.0" and ws["D6"].number_format == "0.000"  # 48 k, 0.039
    assert ws["C51"].number_format == "0" and ws["C55"].number_format == "@"
    assert any(str(r) == "B1:H1" for r in ws.merged_cells.ranges)    # the title's row


def test_row_writer_equals_openpyxls_writer(monkeypatch):
    """A row's number cells written as one text: the file openpyxl's own writer gives,
    for the cells the short way leaves to it between them (a comment on a number, a
    hyperlink, a merged range's styled cells, a bool, a NaN, a text, a huge int), rows
    with a height, hidden rows and rows of no cell."""
    from openpyxl.comments import Comment
    from openpyxl.styles import Border, Font, Side

    def build():
        wb = wbk.finish(_sheet_with_everything())
        ws = wb.create_sheet("odd")
        thin = Side(style="thin")
        for j, v in enumerate([1.0, True, float("nan"), "t<&>", 2 ** 70, -0.0, 3, None],
                              start=1):
            ws.cell(1, j, v)
            ws.cell(2, j, v).font = Font(bold=True)
        ws["B3"] = 4.5
        ws["B3"].comment = Comment("a note on a number", "t")
        ws["C3"] = 1.25
        ws["C3"].hyperlink = "https://example.org"
        ws["D3"] = 2.5
        ws.merge_cells("E4:G5")
        ws["E4"].border = Border(left=thin, right=thin, top=thin, bottom=thin)
        ws["F5"].border = Border(bottom=thin)
        ws.row_dimensions[6].height = 30
        ws.row_dimensions[7].hidden = True
        ws["A7"] = 9.0
        ws.row_dimensions[9].height = 20                 # a row of no cell
        return wb

    fast = _parts(build())
    with monkeypatch.context() as m:                     # openpyxl's writer, every cell
        m.setattr("crankbase.output._number_cell_writer", lambda write_cell, text: write_cell)
        own = _parts(build())
    assert list(fast) == list(own)
    for part in fast:
        assert fast[part] == own[part], part
    sheet = fast["xl/worksheets/sheet3.xml"].decode()
    assert '<c r="B3" t="n"><v>4.5</v></c>' in sheet and '<c r="F1" t="n"><v>-0.0</v></c>' \
        in sheet
    assert '<row r="9" ht="20" customHeight="1"></row>' in sheet
