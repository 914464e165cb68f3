"""One automatic check of a workbook as a reader sees it (issue 23): no text cut off and
no number shown as ####, wrapped rows tall enough for their lines, one number format per
column of each table, one font family.  Used by tests/test_workbooks_audit.py over every
workbook the tool writes."""
from __future__ import annotations

from collections import namedtuple

from crankbase.workbook import (LINE_PT, _cell_style, _col_width, _is_number, _merged, _need,
                                _span_width, _used_width, filled_cells, table_blocks,
                                wrapped_lines)


#: What the check reads of a cell: its value and the style it shares with every cell of
#: the same style (openpyxl builds a new font, alignment and format object at each
#: access; a long table holds a few styles over many thousand cells), with what its
#: width depends on (``measure``: crankbase.workbook's (bold, size, wraps, format)).
_Cell = namedtuple("_Cell", "value row column coordinate font alignment number_format "
                            "measure")


def _styled(c, styles):
    """``c`` as a :data:`_Cell`, its style objects looked up once per distinct style."""
    key = tuple(c._style) if c.has_style else None
    style = styles.get(key)
    if style is None:
        style = styles[key] = (c.font, c.alignment, c.number_format, _cell_style(c))
    return _Cell(c.value, c.row, c.column, c.coordinate, *style)


def problems(wb, name=""):
    """Every defect of ``wb`` as a list of strings (empty: the workbook is clean)."""
    out = []
    families = {}
    styles = {}
    for ws in wb.worksheets:
        if ws.sheet_state != "visible":
            continue
        first, covered = _merged(ws)
        widths = {}
        for cell in filled_cells(ws):           # every cell that holds a value
            if (cell.row, cell.column) in covered:
                continue
            if cell.column not in widths:
                widths[cell.column] = _col_width(ws, cell.column)
            if not widths[cell.column]:                          # a hidden column
                continue
            c = _styled(cell, styles)
            where = f"{name} {ws.title}!{c.coordinate}"
            families.setdefault(c.font.name if c.font else None, where)
            need, wrap = _need(c.value, c.measure)        # as _cell_need(c)
            width = (_span_width(ws, c, first) if (c.row, c.column) in first
                     else widths[c.column])
            if _is_number(c.value):
                if need > width:
                    out.append(f"{where}: number {c.value!r} shown as ### "
                               f"({need:.1f} > {width:.1f})")
                continue
            if wrap:
                size = c.font.sz or 11
                lines = wrapped_lines(c.value, width, bool(c.font.b), size)
                height = ws.row_dimensions[c.row].height or 15 * size / 11
                if height < lines * LINE_PT * size / 11 * 0.95:
                    out.append(f"{where}: {lines} lines in a row {height} pt tall: "
                               f"{c.value[:40]!r}")
                continue
            right = ws.cell(c.row, (first[(c.row, c.column)].max_col
                                    if (c.row, c.column) in first else c.column) + 1)
            room = (_used_width(ws, c.column) if right.value is None and all(
                d.value is None for d in ws[c.row] if d.column > c.column) else width)
            if need > room:
                out.append(f"{where}: text cut off ({need:.1f} > {room:.1f}): "
                           f"{c.value[:40]!r}")
        for col, r0, r1 in table_blocks(ws):
            fmts = {ws.cell(r, col).number_format for r in range(r0, r1 + 1)}
            if len(fmts) > 1:
                out.append(f"{name} {ws.title}!{ws.cell(r0, col).coordinate}:"
                           f"{ws.cell(r1, col).coordinate}: formats {sorted(fmts)}")
    if len(families) > 1:
        out.append(f"{name}: font families {families}")
    return out
