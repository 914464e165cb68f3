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


# ------------------------------------------------- finish's grouped passes, cell by cell

def _number_format_cell_by_cell(values):
    """crankbase.workbook.number_format as it read every value (before the floats were
    filtered by type and their sum)."""
    import math

    nums = [float(v) for v in values if wbk._is_number(v) and math.isfinite(v)]
    if not nums or all(v.is_integer() for v in nums):
        return "0"
    top = max(abs(v) for v in nums)
    if top == 0:
        return "0"
    most = max(0, min(8, 5 - math.floor(math.log10(top))))
    for decimals in range(most):
        k = 10.0 ** decimals
        if all(abs(v * k - round(v * k)) <= 1e-9 * max(1.0, abs(v * k)) for v in nums):
            break
    else:
        decimals = most
    return "0." + "0" * decimals if decimals else "0"


@pytest.mark.parametrize("values", [
    [0.0, 0.5, 1.0, 359.5], [1, 2, 3], [1.0, 2.0, float("nan")], [float("inf"), 2.5],
    [1e308, 1e308, 0.25], [True, 0.125], [-0.0, 0.0], [], ["x", 3.25, None],
    [2 ** 60, 0.5], [123.456789, -0.001], [1e-9, 2e-9], [0.1 + 0.2, 0.3]])
def test_number_format_equals_the_cell_by_cell_one(values):
    """A column's format from its floats at a glance: the one value by value gives (a NaN,
    an infinity, a sum past the largest float, a bool, ints, texts and None among them)."""
    import numpy as np

    assert wbk.number_format(values) == _number_format_cell_by_cell(values)
    assert wbk.number_format(iter(values)) == _number_format_cell_by_cell(values)
    floats = [float(v) for v in values if isinstance(v, (int, float))
              and not isinstance(v, bool)]
    assert wbk.number_format(list(np.float64(floats))) == _number_format_cell_by_cell(floats)


def _needs_cell_by_cell(ws):
    """The widths crankbase.workbook.fit_columns measured cell by cell (each number's
    extremes kept per column and style as it met them): {column: width needed}."""
    import math

    first, covered = wbk._merged(ws)
    cells = wbk.filled_cells(ws)
    hidden = {c.column: not wbk._col_width(ws, c.column) for c in cells}
    shown_in_row = {}
    for c in cells:
        if not hidden[c.column]:
            shown_in_row.setdefault(c.row, set()).add(c.column)
    need, extremes = {}, {}
    for c in cells:
        if (c.row, c.column) in covered or (c.row, c.column) in first:
            continue
        st = wbk._cell_style(c)
        v = c.value
        if wbk._is_number(v) and (not isinstance(v, float) or math.isfinite(v)):
            d = wbk._decimals(st[3])
            if d is not None and not d[1]:
                e = extremes.setdefault((c.column, st), [None, None])
                if v > 0 or v == 0 and math.copysign(1.0, v) > 0:
                    if e[0] is None or v > e[0]:
                        e[0] = v
                elif e[1] is None or v < e[1] or (v == e[1] == 0):
                    e[1] = v
                continue
        elif isinstance(v, str) and shown_in_row.get(c.row, set()) <= {c.column} \
                and not st[2]:
            continue
        need[c.column] = max(need.get(c.column, 0.0), wbk._need(v, st)[0])
    for (col, st), pair in extremes.items():
        for v in pair:
            if v is not None:
                need[col] = max(need.get(col, 0.0), wbk._need(v, st)[0])
    return need


def _odd_columns_workbook(seed):
    """Columns whose widest shown number is a -0.0 among positive ones, a +0 among negative
    numbers, an int 0, a negative number of one digit more, an infinity or NaN, a number
    in General or text format, a bool, numpy's float; a merged cell, a hidden column,
    two styles in one column."""
    import numpy as np
    from openpyxl.styles import Font

    rng = np.random.default_rng(seed)
    wb = wbk.new_workbook()
    ws = wb.active
    wbk.header_rows(ws, 1, list("ABCDEFGH"), list("abcdefgh"))    # column I: no header
    rows = []
    for i in range(60):
        rows.append([float(rng.choice([0.0, -0.0, 0.000125, 0.5])) if i else -0.0,
                     -float(rng.integers(0, 10 ** rng.integers(1, 5))) - 0.0,
                     int(rng.integers(-5, 5)) if i % 7 else 0,
                     float(rng.normal() * 10.0 ** rng.integers(-3, 6)),
                     {0: float("nan"), 11: float("inf"), 22: -float("inf")}.get(
                         i, 2.5 * i * (1 + (i == 30))),      # 150.0 between infinities
                     float(rng.uniform(-1, 1)) * 999.0,
                     float(i), float(-i), 0.0])             # I: +0 only
    wbk.put_numbers(ws, 3, 1, rows)
    ws["A70"], ws["B70"] = -0.0, 0                       # a list's lone numbers
    ws["C71"], ws["D71"] = True, np.float64(-12345.678)  # a bool, numpy's float
    ws["E72"], ws["F72"] = 98765.4321, 1e-7
    ws["E72"].number_format = "General"
    ws["F72"].number_format = "@"
    for r in range(40, 50):                              # a second style in column F
        ws.cell(r, 6).font = Font(bold=True)
    ws.merge_cells("G10:H10")                            # a merged value
    ws.column_dimensions["H"].hidden = True
    return wb


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_fit_columns_measures_what_it_measured_cell_by_cell(seed):
    """Column widths from a column's numbers grouped by style, their largest and most
    negative found at once (and ±0 by their sign): the widths the cell-by-cell measure
    gives, and the same table blocks and number formats as a sheet's passes one by one."""
    wb = _odd_columns_workbook(seed)
    ws = wb.active
    wbk.fit_numbers(ws)
    need = _needs_cell_by_cell(ws)
    wbk.fit_columns(ws)
    for col, w in need.items():
        letter = chr(ord("A") + col - 1)
        if ws.column_dimensions[letter].hidden:
            continue
        expected = round(min(wbk.MAX_WIDTH, max(wbk.MIN_WIDTH, w + wbk._PAD)), 1)
        assert ws.column_dimensions[letter].width == expected, (letter, w)
    assert set(need) >= set(range(1, 10))
    # column A: 0.000125, 0.5, +0 and -0.0 in "0.000000", its widest "-0.000000"
    assert ws["A3"].number_format == "0.000000"
    assert need[1] == wbk._need(-0.0, wbk._cell_style(ws["A3"]))[0]


def test_engine_template_read_once_builds_the_same_workbook(monkeypatch):
    """The engine's template unpickled from the copy read once: the workbook (every part
    but the save time) of the template read by openpyxl for each report, whatever was
    built before from the same copy."""
    import engine
    from crankbase.resources import example_path
    from engine.report import workbook as ew
    from engine.study import report_workbook

    report = engine.run_study(engine.load(example_path("petrol_vaz2106.toml")))
    first = _parts(report_workbook(report, "ru"))
    again = _parts(report_workbook(report, "ru"))        # from the cached copy
    with monkeypatch.context() as m:
        from openpyxl import load_workbook

        m.setattr(ew, "_template", load_workbook)
        own = _parts(report_workbook(report, "ru"))
    assert list(first) == list(own) == list(again)
    for part in own:
        assert first[part] == own[part] and again[part] == own[part], part


def test_cell_styles_set_what_the_cells_setters_set():
    """CellStyles (each style object looked up once, then by identity): the workbook
    ``cell.font = …`` and the like give, part by part, with equal styles in distinct
    objects, a built-in and a custom number format, and a cell styled before."""
    from openpyxl.styles import Alignment, Border, Font, PatternFill, Side

    def build(fast):
        wb = wbk.new_workbook()
        ws = wb.active
        bold, box = Font(bold=True), Border(bottom=Side(style="thin"))
        fill = PatternFill("solid", fgColor="DDEBF7")
        styles = wbk.CellStyles(wb)
        ws["C2"] = 1.0
        ws["C2"].font = Font(italic=True)                   # styled before
        for r in range(1, 6):
            for j in range(1, 5):
                c = ws.cell(r, j, r * j + 0.5 if j > 1 else f"row {r}")
                spec = dict(font=bold if j % 2 else Font(bold=True, size=9),
                            border=box, number_format="0.000" if r % 2 else "0.0##",
                            alignment=Alignment(horizontal="right"))
                if r == 1:
                    spec["fill"] = fill
                if fast:
                    styles(c, **spec)
                else:
                    for name, value in spec.items():
                        setattr(c, name, value)
        return wb

    a, b = _parts(build(True)), _parts(build(False))
    assert list(a) == list(b)
    for part in a:
        assert a[part] == b[part], part
    ws = build(True).active
    assert ws["B1"].font.b and ws["B3"].font.sz == 9 and ws["C3"].font.sz is None
    assert ws["C2"].number_format == "0.0##" and ws["C3"].number_format == "0.000"
    assert ws["D1"].fill.fgColor.rgb.endswith("DDEBF7") and ws["D2"].fill.fill_type is None
