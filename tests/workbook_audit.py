"""One automatic check of a workbook as a reader sees it (issue 23): no text cut off and
no number shown as ####, wrapped rows tall enough for their lines, one number format per
column of each table, one font family.  Used by tests/test_workbooks_audit.py over every
workbook the tool writes."""
from __future__ import annotations

from crankbase.workbook import (LINE_PT, _cell_style, _col_width, _is_number, _merged, _need,
                                _span_width, _used_width, filled_cells, table_blocks,
                                wrapped_lines)


def _styles():
    """A memo of what the check reads of a cell's style, per distinct style: (font,
    alignment, crankbase.workbook's width measure (bold, size, wraps, format)).  openpyxl
    builds a new font, alignment and format object at each access; a long table holds a
    few styles over many thousand cells."""
    memo = {}

    def style(c):
        key = c._style.tobytes()            # the cell's style ids (openpyxl's StyleArray)
        got = memo.get(key)
        if got is None:
            got = memo[key] = (c.font, c.alignment, _cell_style(c))
        return got
    return style


def _number_formats():
    """``formats(cells)``: the set of the cells' number formats, each format id looked up
    once (what openpyxl's ``Cell.number_format`` reads from the cell's style ids)."""
    memo = {}

    def formats(cells):
        out = set()
        for c in {c._style.numFmtId: c for c in cells}.values():
            key = c._style.numFmtId
            if key not in memo:
                memo[key] = c.number_format
            out.add(memo[key])
        return out
    return formats


def problems(wb, name=""):
    """Every defect of ``wb`` as a list of strings (empty: the workbook is clean).

    Reads the workbook without changing it (no cell is created: ``ws.cell`` and
    ``ws[row]`` would create the empty ones they visit), so a workbook shared by several
    tests can be audited."""
    out = []
    families = {}
    style = _styles()
    number_formats = _number_formats()
    for ws in wb.worksheets:
        if ws.sheet_state != "visible":
            continue
        cells = ws._cells
        first, covered = _merged(ws)
        widths = {}
        filled = filled_cells(ws)               # every cell that holds a value
        last_in_row = {}                        # row → its last column holding a value
        for cell in filled:
            last_in_row[cell.row] = cell.column
        for cell in filled:
            row, col = cell.row, cell.column
            if (row, col) in covered:
                continue
            if col not in widths:
                widths[col] = _col_width(ws, col)
            if not widths[col]:                                  # a hidden column
                continue
            font, alignment, measure = style(cell)
            value = cell.value
            family = font.name if font else None
            if family not in families:
                families[family] = f"{name} {ws.title}!{cell.coordinate}"
            need, wrap = _need(value, measure)          # as _cell_need(cell)
            width = (_span_width(ws, cell, first) if (row, col) in first
                     else widths[col])
            if _is_number(value):
                if need > width:
                    out.append(f"{name} {ws.title}!{cell.coordinate}: number {value!r} "
                               f"shown as ### ({need:.1f} > {width:.1f})")
                continue
            if wrap:
                size = font.sz or 11
                lines = wrapped_lines(value, width, bool(font.b), size)
                height = ws.row_dimensions[row].height or 15 * size / 11
                if height < lines * LINE_PT * size / 11 * 0.95:
                    out.append(f"{name} {ws.title}!{cell.coordinate}: {lines} lines in a "
                               f"row {height} pt tall: {value[:40]!r}")
                continue
            right = cells.get((row, (first[(row, col)].max_col if (row, col) in first
                                     else col) + 1))
            # nothing on its right in its row (the cell next to it included): it may
            # spill over the columns up to the sheet's last one
            room = (_used_width(ws, col) if (right is None or right.value is None)
                    and last_in_row[row] <= col else width)
            if need > room:
                out.append(f"{name} {ws.title}!{cell.coordinate}: text cut off "
                           f"({need:.1f} > {room:.1f}): {value[:40]!r}")
        for col, r0, r1 in table_blocks(ws):
            fmts = number_formats(cells[(r, col)] for r in range(r0, r1 + 1))
            if len(fmts) > 1:
                out.append(f"{name} {ws.title}!{cells[(r0, col)].coordinate}:"
                           f"{cells[(r1, col)].coordinate}: formats {sorted(fmts)}")
    if len(families) > 1:
        out.append(f"{name}: font families {families}")
    return out
