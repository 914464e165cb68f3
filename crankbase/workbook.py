"""The one workbook helper: how every workbook crankdyn writes looks and prints.

Every writer (engine, bearings, linkage, synthesis, dynamics, the variants summary, the
checked copy of a student's workbook) builds its sheets and then calls :func:`finish`,
which gives the whole workbook

* one font family (:data:`FONT`) for titles, headers and data, whatever the writer or the
  template used;
* one number format per column of each table (a block of rows with two or more numbers),
  about six significant digits of the column's largest value (a whole-number column
  ``0``); a number alone in its row (a value of a list of results) gets its own six
  digits.  The cells keep every digit (:func:`save` writes floats at full precision);
* column widths measured from the text and the numbers they hold (Cyrillic letters are
  wider than Latin ones, bold wider than regular); a text longer than
  :data:`MAX_WIDTH` wraps, and its row grows to its lines;
* A4 page setup: the sheet's orientation (landscape where none is set), as many pages
  wide as its columns need (at most :data:`WIDTH_PER_PAGE` width units a page), as many
  tall as needed, the header rows repeated (``title_rows``).

:func:`save` writes atomically with every float bit for bit; :func:`bounded` thins a table
longer than :data:`MAX_ROWS` rows for a sheet (the CSV keeps every row);
:func:`summary_workbook` writes a one-table workbook (the variants summary).  Writers fill
their tables with :func:`put_numbers` (number cells made at once), :func:`header_rows` and
:class:`CellStyles` (a style object looked up in the workbook once, not at every cell).

openpyxl is imported inside the functions only.
"""
from __future__ import annotations

import copy
import functools
import itertools
import math
import operator
import re

from .output import paused_gc

__all__ = ["A4_LANDSCAPE_PRINT_CM", "FONT", "HEAD_FILL", "MAX_ROWS", "MAX_WIDTH", "WIDTH_PER_PAGE", "LINE_PT",
           "text_width", "wrapped_lines", "columns_cm", "number_format", "shown", "font",
           "style_header",
           "table_blocks", "unify_fonts", "fit_numbers", "fit_columns", "fit_rows",
           "page_setup", "finish", "save", "set_number_format", "put_numbers", "bounded", "filled_cells", "sheet_rows", "thinned_note", "summary_workbook", "new_workbook",
           "words", "Words", "header_rows", "CellStyles"]

#: The one font family of every workbook (metric twin: Liberation Sans).
FONT = "Arial"
#: Fill of header cells.
HEAD_FILL = "DDE4EE"
#: Rows of one table a sheet holds; a longer table is thinned (:func:`bounded`) and the
#: CSV beside the workbook keeps every row.
MAX_ROWS = 2000
#: Widest column (Excel width units); a longer text wraps.
MAX_WIDTH = 45
#: Narrowest column of a value.
MIN_WIDTH = 6
#: Column width printed on one A4 page (landscape at ~70 % scale at most).
WIDTH_PER_PAGE = 190
#: Height of a line of text [pt].
LINE_PT = 12.75

# Widths of characters in Excel column-width units (one '0' of the 11 pt font), from
# Arial's (Liberation Sans's) advance widths in em over the '0''s 0.556 em, rounded up a
# little for LibreOffice's and Excel's rendering.
_W_CLASSES = (
    ("il.,:;'|!ıj", 0.45), ("ftrI()[]{}/\\- ·", 0.6), ("mwMWШЩЖЮшщжюыЫфФ", 1.6),
    ("ABCDEGHKNOPQRSUVXYZ&%@#ДЛМНОПУФЦЧЪЭЯБВГЕЁЗИЙКРСТХЬ", 1.28),
    ("дмлнпцчъэяб", 1.12), ("=+<>~^×−±÷", 1.05))
_W = {ch: w for chars, w in _W_CLASSES for ch in chars}
_W_DEFAULT = 1.02
_PAD = 1.8          # a column's margin around its widest text


#: The printed width of an A4 landscape page between openpyxl's default margins
#: (29.7 cm − 2 × 0.75 in) [cm]: a chart anchored at column A is no wider.
A4_LANDSCAPE_PRINT_CM = 29.7 - 2 * 0.75 * 2.54 - 0.5

def text_width(s, bold=False, size=11) -> float:
    """Printed width of a one-line text in Excel column-width units."""
    w = sum(_W.get(ch, _W_DEFAULT) for ch in str(s))
    return w * (1.08 if bold else 1.0) * (size or 11) / 11


#: :func:`text_width` of the texts a workbook repeats (labels, units, the shapes of its
#: numbers), each measured once.
_text_width = functools.lru_cache(maxsize=1 << 16)(text_width)

#: Every digit to ``0``: the digits are equally wide, so a number's shown text measures as
#: its shape (``-000.000``), and a column of numbers is measured a few shapes at a time.
_DIGITS_TO_0 = str.maketrans("123456789", "000000000")


def wrapped_lines(s, width, bold=False, size=11) -> int:
    """Lines a wrapped text takes in a column ``width`` units wide (words put on a line
    while they fit; a word longer than a line is broken), as a spreadsheet does."""
    width = max(1.0, width - 0.8)
    sp = text_width(" ", bold, size)
    lines = 0
    for para in str(s).split("\n"):
        lines += 1
        used = 0.0
        for word in para.split(" "):
            w = text_width(word, bold, size)
            if used and used + sp + w > width:
                lines += 1
                used = 0.0
            elif used:
                used += sp
            if w > width:
                lines += math.ceil(w / width) - 1
                w = w % width
            used += w
    return lines


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


#: The types of a number :func:`_is_number` takes at a glance (a bool is no number; a
#: subclass of int or float, numpy's float64, goes the long way).
_PLAIN = frozenset((float, int))


def _finite(values) -> bool:
    """Every value of ``values`` (Python floats and ints) finite, their sum found in C (a
    sum past the largest float, or an int too large for a float, says False: the caller
    then looks value by value)."""
    try:
        return math.isfinite(sum(values))
    except OverflowError:
        return False


def number_format(values) -> str:
    """One display format for ``values``: about six significant digits of the largest
    magnitude (``0.000`` for 123.456…; at most eight decimals), fewer when fewer show
    every value exactly (``0.0`` for angles on a 0.5° grid, ``0`` for whole numbers)."""
    values = values if isinstance(values, list) else list(values)
    nums = [v for v in values if type(v) is float]
    if len(nums) != len(values):        # ints, a bool, a text, numpy's scalars
        nums = [float(v) for v in values if _is_number(v) and math.isfinite(v)]
    elif not _finite(nums):
        nums = [v for v in nums if math.isfinite(v)]
    if not nums or all(map(float.is_integer, nums)):
        return "0"
    top = max(map(abs, nums))
    if top == 0:
        return "0"
    most = max(0, min(8, 5 - math.floor(math.log10(top))))
    for decimals in range(most):        # fewer when they show every value exactly
        k = 10.0 ** decimals
        if all(abs(v * k - round(v * k)) <= 1e-9 * max(1.0, abs(v * k)) for v in nums):
            break
    else:
        decimals = most
    return "0." + "0" * decimals if decimals else "0"


@functools.lru_cache(maxsize=256)
def _decimals(fmt):
    """(decimals, optional decimals) of a simple number format ``0.00#``."""
    m = re.fullmatch(r"[#,]*0(?:\.(0*)(#*))?", fmt or "")
    if not m:
        return None
    return len(m.group(1) or ""), len(m.group(2) or "")


def shown(value, fmt="General") -> str:
    """The text a spreadsheet shows for a number in format ``fmt`` (simple ``0.00``,
    ``0.0##`` and General formats)."""
    d = _decimals(fmt)
    if d is None:
        return f"{value:.10g}" if isinstance(value, float) else str(value)
    fixed, optional = d
    s = f"{value:.{fixed + optional}f}"
    if optional:
        s = s.rstrip("0") if "." in s else s
        head, _, tail = s.partition(".")
        tail = tail.ljust(fixed, "0")
        s = head + ("." + tail if tail else "")
    return "0" if s in ("-0", "-0.0") else s


def font(bold=False, italic=False, size=11, color=None):
    """A :class:`openpyxl.styles.Font` of the one family."""
    from openpyxl.styles import Font

    return Font(name=FONT, bold=bold, italic=italic, size=size, color=color)


def style_header(cell, wrap=True):
    """Bold, filled, framed, centred: a table's header cell."""
    from openpyxl.styles import Alignment, Border, PatternFill, Side

    thin = Side(style="thin", color="999999")
    cell.font = font(bold=True)
    cell.fill = PatternFill("solid", fgColor=HEAD_FILL)
    cell.border = Border(left=thin, right=thin, top=thin, bottom=thin)
    cell.alignment = Alignment(horizontal="center", vertical="center", wrap_text=wrap)


def header_rows(ws, row, labels, names, col=1):
    """The two header rows of a table: the quantity in the report's language (bold,
    wrapped, filled) over the CSV column name (small grey italic), from ``(row, col)``.
    Returns the first data row."""
    from openpyxl.styles import Alignment

    head = sub = None               # the style ids of the first header cells
    for j, (label, name) in enumerate(zip(labels, names), start=col):
        c = ws.cell(row, j, label)
        if head is None:
            style_header(c)
            head = c._style
        else:                       # the same font, fill, border and alignment
            _same_style(c, head, (0, 1, 2, 5))
        c = ws.cell(row + 1, j, str(name))
        if sub is None:
            c.font = font(italic=True, size=8, color="555555")
            c.alignment = Alignment(horizontal="center")
            sub = c._style
        else:
            _same_style(c, sub, (0, 5))
    return row + 2


def _same_style(cell, ids, fields):
    """Give ``cell`` the style ``ids`` (a StyleArray) has in ``fields`` (0 font, 1 fill,
    2 border, 5 alignment …): what ``cell.font = …`` and the like set, each style object
    looked up (hashed) in the workbook's styles once for all cells, not once a cell."""
    from openpyxl.styles.cell_style import StyleArray

    st = cell._style
    if not st:
        st = cell._style = StyleArray()
    for k in fields:
        st[k] = ids[k]


class CellStyles:
    """``styles(cell, font=…, border=…, number_format=…)`` does what ``cell.font = …;
    cell.border = …; cell.number_format = …`` do, each style object looked up in the
    workbook's styles once, then known by its identity: openpyxl hashes a font, fill,
    border or alignment at every assignment, most of the time a writer spends styling a
    table cell by cell.  The style objects given must not change while in use."""

    #: The StyleArray index and the workbook's collection of each style (openpyxl's
    #: StyleableObject descriptors).
    FIELDS = {"font": (0, "_fonts"), "fill": (1, "_fills"), "border": (2, "_borders"),
              "protection": (4, "_protections"), "alignment": (5, "_alignments")}

    def __init__(self, wb):
        self.wb = wb
        self._ids = {}              # {(name, id(style)): (style, its index)}

    def _index(self, name, value):
        from openpyxl.styles.numbers import BUILTIN_FORMATS_MAX_SIZE, BUILTIN_FORMATS_REVERSE

        key = (name, id(value))
        got = self._ids.get(key)
        if got is None:
            if name == "number_format":
                idx = BUILTIN_FORMATS_REVERSE.get(value)
                if idx is None:
                    idx = self.wb._number_formats.add(value) + BUILTIN_FORMATS_MAX_SIZE
            else:
                idx = getattr(self.wb, self.FIELDS[name][1]).add(value)
            got = self._ids[key] = (value, idx)     # the style kept: its id stays its own
        return got[1]

    def __call__(self, cell, **styles):
        from openpyxl.styles.cell_style import StyleArray

        st = cell._style
        if not st:
            st = cell._style = StyleArray()
        for name, value in styles.items():
            st[_NUM_FMT if name == "number_format" else self.FIELDS[name][0]] = \
                self._index(name, value)
        return cell


def new_workbook():
    """An empty :class:`openpyxl.Workbook` whose default font is :data:`FONT`."""
    from openpyxl import Workbook

    wb = Workbook()
    unify_fonts(wb)
    return wb


def unify_fonts(wb):
    """Every font of ``wb`` (cells, the default and the named styles) in the family
    :data:`FONT`, keeping size, weight, slant and colour."""
    from openpyxl.utils.indexed_list import IndexedList

    new = IndexedList()
    for f in wb._fonts:
        g = copy.copy(f)
        g.name, g.scheme, g.family = FONT, None, 2
        list.append(new, g)
        new._dict.setdefault(g, len(new) - 1)
    new.clean = True
    wb._fonts = new
    for st in wb._named_styles:
        g = copy.copy(st.font)
        g.name, g.scheme, g.family = FONT, None, 2
        st.font = g
    return wb


def _merged(ws):
    """{(row, col) of a merged range's first cell: range}, and the set of covered cells."""
    first, covered = {}, set()
    for r in ws.merged_cells.ranges:
        first[(r.min_row, r.min_col)] = r
        for row in range(r.min_row, r.max_row + 1):
            for col in range(r.min_col, r.max_col + 1):
                if (row, col) != (r.min_row, r.min_col):
                    covered.add((row, col))
    return first, covered


def filled_cells(ws):
    """The cells of ``ws`` that hold a value, row by row, each row left to right.

    (``ws.iter_rows()`` visits every cell of the used rectangle and creates each empty one
    it visits: on a long table most of a sheet's cells, and most of a workbook's build and
    save time.)"""
    # {(row, column): cell}: its keys sorted alone (pairs of ints), several times
    # cheaper than its items sorted (pairs of a pair and a cell), in the same order
    cells = ws._cells
    return [c for c in map(cells.__getitem__, sorted(cells)) if c._value is not None]


_ROW = operator.attrgetter("row")
_COLUMN = operator.itemgetter(1)


def _max_column(ws):
    """``ws.max_column`` (the last column of a cell of ``ws``, 1 without one), the keys
    read in C."""
    cells = ws._cells
    return max(map(_COLUMN, cells)) if cells else 1


class _Scan:
    """What the passes of :func:`finish` read of a sheet's filled cells, found in one
    walk over them (row by row, as :func:`filled_cells` gives them):

    ``blocks``
        the table columns of :func:`table_blocks`, ``[column, first row, last row,
        its cells]``, sorted by column and first row;
    ``lone``
        the numbers outside every table (in rows that are no table row), in order;
    ``plain``
        the cells of a Python float or int (the bulk of a sheet), in order;
    ``other``
        every other filled cell (texts, bools, numpy's scalars …), in order;
    ``texts``
        the cells of a text, in order;
    ``shown_in_row``
        {row: its columns not hidden} of each row that holds a text."""

    __slots__ = ("blocks", "lone", "plain", "other", "texts", "shown_in_row")

    def __init__(self, ws, cells=None):
        cells = filled_cells(ws) if cells is None else cells
        width = _col_widths(ws)
        blocks, lone, plain, other, texts, shown_in_row = [], [], [], [], [], {}
        runs = {}                       # {column: its open block}
        for r, group in itertools.groupby(cells, _ROW):
            row = list(group)
            nums = [c for c in row if type(c._value) in _PLAIN]
            plain += nums
            if len(nums) != len(row):
                rest = [c for c in row if type(c._value) not in _PLAIN]
                other += rest
                words = [c for c in rest if isinstance(c._value, str)]
                if words:
                    texts += words
                    shown_in_row[r] = {c.column for c in row if width(c.column)}
                nums = [c for c in row if _is_number(c._value)]   # numpy's floats too
            # a table row: two numbers or more, fewer than three shown texts before the
            # first (quantity, unit and key make a list of one quantity a row)
            if len(nums) < 2:
                lone += nums
                continue
            lead = 0
            head = nums[0]
            for c in row:
                if c is head:
                    break
                if isinstance(c._value, str):
                    lead += width(c.column) > 0
            if lead >= 3:
                lone += nums
                continue
            for c in nums:
                col = c.column
                run = runs.get(col)
                if run is not None and run[2] == r - 1:
                    run[2] = r
                    run[3].append(c)
                else:
                    if run is not None:
                        blocks.append(run)
                    runs[col] = [col, r, r, [c]]
        blocks += runs.values()
        blocks.sort(key=lambda b: (b[0], b[1]))
        self.blocks, self.lone, self.plain, self.other = blocks, lone, plain, other
        self.texts, self.shown_in_row = texts, shown_in_row


def table_blocks(ws, cells=None):
    """The table columns of a sheet: ``[(column, first row, last row)]``, each a run of
    consecutive rows that hold a number in that column and at least two numbers in the
    row (a list of single values with labels is not a table, nor a list of one quantity
    a row: numbers after three texts such as quantity, unit and key).  ``cells``: the
    sheet's :func:`filled_cells`, when the caller has them."""
    return [(col, r0, r1) for col, r0, r1, _ in _Scan(ws, cells).blocks]


def fit_numbers(ws, cells=None):
    """One number format per column of each table (:func:`table_blocks`), and each number
    alone in its row its own six digits; text formats (``@``) are kept.  ``cells``: the
    sheet's :func:`filled_cells`, when the caller has them."""
    _fit_numbers(ws, _Scan(ws, cells))


def _fit_numbers(ws, scan):
    for _, _, _, block in scan.blocks:                   # each cell holds a number
        set_number_format(block, number_format([c._value for c in block]))
    for c in scan.lone:
        if c.number_format != "@":
            c.number_format = number_format([c._value])


def set_number_format(cells, fmt):
    """``c.number_format = fmt`` for every cell of ``cells`` (of one workbook), the
    format looked up (or added to the workbook's formats) once: what openpyxl's setter
    does per cell."""
    from array import array

    from openpyxl.styles.cell_style import StyleArray
    from openpyxl.styles.numbers import BUILTIN_FORMATS_MAX_SIZE, BUILTIN_FORMATS_REVERSE

    idx = None
    for c in cells:
        if idx is None:
            idx = BUILTIN_FORMATS_REVERSE.get(fmt)
            if idx is None:
                idx = c.parent.parent._number_formats.add(fmt) + BUILTIN_FORMATS_MAX_SIZE
            # a cell without a style gets openpyxl's StyleArray() with the format set,
            # a copy of this one made in C (StyleArray's own constructor is Python)
            blank = StyleArray()
            blank[_NUM_FMT] = idx
            new = array.__new__
        st = c._style
        if not st:
            c._style = new(StyleArray, "i", blank)
        else:
            st[_NUM_FMT] = idx                  # st.numFmtId = idx, without the descriptor


#: The index of ``numFmtId`` in openpyxl's StyleArray (fontId, fillId, borderId,
#: numFmtId, protectionId, alignmentId, pivotButton, quotePrefix, xfId).
_NUM_FMT = 3


@paused_gc()
def put_numbers(ws, r0, c0, rows):
    """Write ``rows`` (lists of Python ints and floats, or None) into ``ws`` from cell
    ``(r0, c0)``: what ``ws.cell(r, c).value = v`` does, new cells made at once (a
    table's body is most of a workbook's cells); a cell already there is set as usual."""
    from openpyxl.cell.cell import Cell

    cells = ws._cells
    new = Cell.__new__
    r = r0 - 1
    for r, values in enumerate(rows, start=r0):
        for j, v in enumerate(values, start=c0):
            kind = type(v)
            key = (r, j)
            if key in cells or not (v is None or kind is float or kind is int):
                ws.cell(r, j).value = v
                continue
            # the state Cell(ws, row=r, column=j, value=v) gives a number (data type
            # "n", as openpyxl binds one) or None, without its two constructors' calls
            c = new(Cell)
            c.parent, c._style, c.row, c.column = ws, None, r, j
            c._value, c._hyperlink, c.data_type, c._comment = v, None, "n", None
            cells[key] = c
    if r >= r0:
        ws._current_row = max(ws._current_row, r)


def _cell_style(c):
    """(bold, size, wraps, number format) of a cell: what its width depends on besides
    its value."""
    f, al = c.font, c.alignment
    return (bool(f and f.b), (f.sz if f and f.sz else 11), bool(al and al.wrap_text),
            c.number_format)


def _need(value, style):
    """(width needed, wraps) of ``value`` shown on one line in ``style``
    (:func:`_cell_style`)."""
    bold, size, wrap, fmt = style
    if _is_number(value):
        return _text_width(shown(value, fmt).translate(_DIGITS_TO_0), bold, size), False
    text = str(value)
    if wrap and "\n" not in text and len(text.split()) > 1 and bold:
        # a wrapped header: its longest word, or a third of it, sets the width
        return max(max(_text_width(w, bold, size) for w in text.split()),
                   _text_width(text, bold, size) / 3), True
    return max(_text_width(p, bold, size) for p in text.split("\n")), wrap


def _cell_need(c):
    """(width needed, wraps) of one cell's shown text on one line."""
    return _need(c.value, _cell_style(c))


def _style_key(c):
    """What :func:`_cell_style` depends on, cheap to read (openpyxl builds a new font,
    alignment and format object at each access)."""
    st = c._style
    return None if st is None else (st[0], st[5], st[3])   # fontId, alignmentId, numFmtId


def fit_columns(ws, max_width=MAX_WIDTH, fixed=None, min_width=MIN_WIDTH, cells=None):
    """Column widths from the text and the numbers they hold; a text longer than
    ``max_width`` wraps.  ``fixed``: {column letter: width} kept as given.  Titles (the
    only value of their row) and merged cells do not widen a column.  ``cells``: the
    sheet's :func:`filled_cells`, when the caller has them.

    Each cell is visited once per pass, its style read once per distinct style and each
    text (each shape of a number) measured once."""
    _fit_columns(ws, _Scan(ws, cells), max_width, fixed, min_width)


def _extremes(values):
    """The numbers of ``values`` (finite Python floats and ints, one format) whose shown
    text is the widest: the largest of those not below +0 and the most negative of those
    below or at -0.0 (rounding keeps the order, every digit is as wide as 0)."""
    hi, lo = max(values), min(values)
    out = []
    if hi > 0:
        out.append(hi)
    elif hi == 0 and max(map(math.copysign, itertools.repeat(1.0), values)) > 0:
        out.append(0.0)                             # a +0 (or an int 0): "0.000"
    if lo < 0:
        out.append(lo)
    elif lo == 0 and min(map(math.copysign, itertools.repeat(1.0), values)) < 0:
        out.append(-0.0)                            # a -0.0: "-0.000"
    return out


def _fit_columns(ws, scan, max_width=MAX_WIDTH, fixed=None, min_width=MIN_WIDTH):
    from openpyxl.styles import Alignment
    from openpyxl.utils import get_column_letter

    fixed = fixed or {}
    first, covered = _merged(ws)
    skip = covered.union(first) if first else None       # merged cells: no width
    shown_in_row = scan.shown_in_row     # {row: columns of its values, hidden ones left out}

    def lone(c):                    # the only value of its row (a hidden key aside)
        return shown_in_row.get(c.row, set()) <= {c.column}

    styles = {}

    def style(c):
        key = _style_key(c)
        st = styles.get(key)
        if st is None:
            st = styles[key] = _cell_style(c)
        return st

    need = {}

    def widen(col, w):
        need[col] = max(need.get(col, 0.0), w)

    # the numbers (Python floats and ints) by column and style: in a fixed format
    # (0.000) the widest shown is that of the largest or the most negative one
    # (:func:`_extremes`); in another each is measured
    groups = {}                     # {(column, style ids): (a cell, [values])}
    for c in scan.plain:
        if skip is not None and (c.row, c.column) in skip:
            continue
        st = c._style
        key = (c.column, None) if st is None else (c.column, st[0], st[5], st[3])
        g = groups.get(key)
        if g is None:
            groups[key] = (c, [c._value])
        else:
            g[1].append(c._value)
    for (col, *_), (c, values) in groups.items():
        st = style(c)
        d = _decimals(st[3])
        if d is None or d[1]:
            for v in values:
                widen(col, _need(v, st)[0])
            continue
        if not _finite(values):                         # inf, nan: measured each
            for v in values:
                if type(v) is float and not math.isfinite(v):
                    widen(col, _need(v, st)[0])
            values = [v for v in values if type(v) is not float or math.isfinite(v)]
            if not values:
                continue
        for v in _extremes(values):
            widen(col, _need(v, st)[0])
    # every other value: texts, bools, numpy's numbers …
    extremes = {}
    for c in scan.other:
        if skip is not None and (c.row, c.column) in skip:
            continue
        st = style(c)
        v = c._value
        if _is_number(v) and (not isinstance(v, float) or math.isfinite(v)):
            d = _decimals(st[3])
            if d is not None and not d[1]:
                e = extremes.get((c.column, st))
                if e is None:
                    e = extremes[(c.column, st)] = [None, None]
                if v > 0 or v == 0 and math.copysign(1, v) > 0:     # not -0.0
                    if e[0] is None or v > e[0]:
                        e[0] = v
                elif e[1] is None or v < e[1] or (v == e[1] == 0):
                    e[1] = v
                continue
        elif isinstance(v, str) and lone(c) and not st[2]:
            continue                # a title runs over the empty cells beside it
        widen(c.column, _need(v, st)[0])
    for (col, st), pair in extremes.items():
        for v in pair:
            if v is not None:
                widen(col, _need(v, st)[0])
    for col, w in need.items():
        letter = get_column_letter(col)
        if letter in fixed or ws.column_dimensions[letter].hidden:
            continue
        width = min(max_width, max(min_width, w + _PAD))
        ws.column_dimensions[letter].width = round(width, 1)
    for letter, w in fixed.items():
        ws.column_dimensions[letter].width = w
    # texts wider than their column wrap
    col_width = _col_widths(ws)
    last = max(_max_column(ws), _last_print_col(ws))
    for c in scan.texts:
        if (c.row, c.column) in covered or not col_width(c.column):
            continue
        m = first.get((c.row, c.column))
        width = sum(col_width(j) for j in (range(m.min_col, m.max_col + 1) if m
                                           else [c.column]))
        st = style(c)
        if st[2]:
            continue
        if m is None and lone(c):
            used = sum(col_width(j) for j in range(c.column, max(last, c.column) + 1))
            if _need(c.value, st)[0] <= used:
                continue
            width = used
            ws.merge_cells(start_row=c.row, start_column=c.column, end_row=c.row,
                           end_column=max(_max_column(ws), c.column))
        if _need(c.value, st)[0] > width:
            al = copy.copy(c.alignment) if c.alignment else Alignment()
            c.alignment = Alignment(horizontal=al.horizontal, vertical="top",
                                    wrap_text=True)


def _col_width(ws, col):
    from openpyxl.utils import get_column_letter

    d = ws.column_dimensions[get_column_letter(col)]
    return 0.0 if d.hidden else (d.width or 8.43)


def _col_widths(ws):
    """:func:`_col_width` of ``ws`` as a function of the column, each column's read once
    (for a pass over a sheet whose widths it does not change)."""
    widths = {}

    def width(col):
        w = widths.get(col)
        if w is None:
            w = widths[col] = _col_width(ws, col)
        return w

    return width


def _last_print_col(ws):
    """The last column of the sheet's print area (0 when it has none)."""
    if not ws.print_area:
        return 0
    area = ws.print_area[0] if isinstance(ws.print_area, (list, tuple)) else ws.print_area
    m = re.search(r":\$?([A-Z]+)\$?\d+$", str(area))
    if not m:
        return 0
    from openpyxl.utils import column_index_from_string

    return column_index_from_string(m.group(1))


def _used_width(ws, col):
    last = max(_max_column(ws), col, _last_print_col(ws))
    return sum(_col_width(ws, j) for j in range(col, last + 1))


def columns_cm(ws, first, last):
    """Printed width of columns ``first`` … ``last`` (1-based) at 100 % [cm] (a column
    ``w`` units wide is 7·w + 5 pixels at 96 dpi)."""
    return sum((7 * _col_width(ws, j) + 5) * 2.54 / 96 for j in range(first, last + 1))


def _span_width(ws, c, first=None):
    first = first if first is not None else _merged(ws)[0]
    m = first.get((c.row, c.column))
    cols = range(m.min_col, m.max_col + 1) if m else [c.column]
    return sum(_col_width(ws, j) for j in cols)


def fit_rows(ws, cells=None):
    """Rows of wrapped text exactly as tall as their most lines (at their columns'
    width); other rows keep their height.  ``cells``: the sheet's :func:`filled_cells`,
    when the caller has them."""
    _fit_rows(ws, [c for c in (filled_cells(ws) if cells is None else cells)
                   if isinstance(c._value, str)])


#: :func:`wrapped_lines` of the texts a workbook repeats (headers, notes), each once.
_wrapped_lines = functools.lru_cache(maxsize=1 << 12)(wrapped_lines)


def _fit_rows(ws, texts):
    """:func:`fit_rows` over ``texts``, the sheet's filled cells of a text, in order."""
    first, covered = _merged(ws)
    need = {}
    col_width = _col_widths(ws)

    from openpyxl.styles.cell_style import StyleArray

    looks = {}                  # {(font id, alignment id): (wraps, bold, size)}
    for c in texts:
        st = c._style
        if st is None:          # as reading c.alignment does: every text has its style ids
            st = c._style = StyleArray()
        key = (st[0], st[5])
        look = looks.get(key)
        if look is None:
            font, al = c.font, c.alignment
            look = looks[key] = (bool(al and al.wrap_text), bool(font and font.b),
                                 font.sz if font and font.sz else 11)
        wraps, bold, size = look
        if not wraps or (c.row, c.column) in covered or not col_width(c.column):
            continue
        m = first.get((c.row, c.column))
        width = sum(col_width(j) for j in (range(m.min_col, m.max_col + 1) if m
                                           else [c.column]))
        lines = _wrapped_lines(c._value, width, bold, size)
        need[c.row] = max(need.get(c.row, 0.0), lines * LINE_PT * size / 11 + 2)
    for r, h in need.items():
        ws.row_dimensions[r].height = round(max(h, 15.0), 1)


def page_setup(ws, orientation=None, title_rows=None, title_cols=None):
    """A4 in ``orientation`` (the sheet's own, else landscape), as many pages wide as its
    visible columns need, as many tall as needed; ``title_rows`` ("3:4") repeated on every
    page."""
    ps = ws.page_setup
    ps.paperSize = ws.PAPERSIZE_A4
    ps.orientation = orientation or ps.orientation or "landscape"
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    ps.fitToHeight = 0
    last = _last_print_col(ws) or _max_column(ws)
    width = sum(_col_width(ws, j) for j in range(1, last + 1))
    ps.fitToWidth = max(1, math.ceil(width / WIDTH_PER_PAGE))
    if title_rows:
        ws.print_title_rows = title_rows
    if title_cols:
        ws.print_title_cols = title_cols


@paused_gc()
def finish(wb, fixed=None, max_width=MAX_WIDTH):
    """Give every sheet of ``wb`` the house look: one font family, one number format per
    table column, widths from the content, wrapped rows tall enough, A4 setup.

    ``fixed``: {sheet title: {column letter: width}} for columns a writer sizes itself
    (a chart's anchor columns).  Returns ``wb``."""
    unify_fonts(wb)
    hidden = [ws for ws in wb.worksheets if ws.sheet_state != "visible"]
    for ws in hidden:                    # data of charts: after every visible sheet
        wb.move_sheet(ws, len(wb.worksheets) - 1 - wb.worksheets.index(ws))
    for ws in wb.worksheets:
        if ws.sheet_state != "visible":
            page_setup(ws)
            continue
        scan = _Scan(ws)                     # the sheet's values, found once
        merged = len(ws.merged_cells.ranges)
        _fit_numbers(ws, scan)
        _fit_columns(ws, scan, max_width=max_width, fixed=(fixed or {}).get(ws.title))
        # a title fit_columns merged over its row took the cells it covers
        if len(ws.merged_cells.ranges) == merged:
            _fit_rows(ws, scan.texts)
        else:
            fit_rows(ws)
        page_setup(ws)
    return wb


def save(wb, path):
    """Save ``wb`` atomically (a temporary file beside ``path``, then renamed), every
    float at full precision (:func:`crankbase.output.full_precision_xlsx`)."""
    from .output import atomic_path, full_precision_xlsx

    with atomic_path(path) as tmp, full_precision_xlsx():
        wb.save(tmp)
    return path


def bounded(n, bound=MAX_ROWS, keep=()):
    """Row indices a sheet holds of a table of ``n`` rows: every row when ``n <= bound``,
    else every k-th row (k the smallest that brings it under ``bound``) with the last row
    and the rows ``keep`` (the extremes a chart must show) added.  Returns (indices, k)."""
    import numpy as np

    if n <= bound:
        return np.arange(n), 1
    k = math.ceil(n / bound)
    idx = np.union1d(np.arange(0, n, k), np.asarray([n - 1, *keep], dtype=int))
    return idx, k


def summary_workbook(df, path, title, sheet="summary"):
    """A one-table workbook: ``title`` in A1, the column names (the CSV header) in row 3,
    the rows of ``df`` below, finished (:func:`finish`) and saved (:func:`save`); the
    header row and the first column repeat on every printed page."""
    wb = new_workbook()
    ws = wb.active
    ws.title = sheet
    ws["A1"] = title
    ws["A1"].font = font(bold=True, size=12)
    for j, name in enumerate(df.columns, start=1):
        style_header(ws.cell(3, j, str(name)))
    for i, row in enumerate(df.itertuples(index=False), start=4):
        for j, val in enumerate(row, start=1):
            v = val.item() if hasattr(val, "item") else val
            if v is not None and isinstance(v, float) and not math.isfinite(v):
                v = None
            c = ws.cell(i, j, v)
            if isinstance(v, str):
                c.data_type = "s"           # a name stays text, never a formula
    ws.freeze_panes = "B4"
    finish(wb)
    page_setup(ws, "landscape", title_rows="3:3", title_cols="A:A")
    return save(wb, path)


def words(lang, prefix, shape):
    """The words of a sheet writer in ``lang`` from the catalogue (``sheet.po``), in the
    ``shape`` the writer reads them: {name: "str" | ("tuple", n) | ("dict", keys) |
    ("rows", {key: unit})} → a text ``<prefix>.<name>``, a tuple of ``<prefix>.<name>.<i>``,
    a dict of ``<prefix>.<name>.<key>``, or rows (key, label, unit): the label
    ``<prefix>.<name>.<key>``, the unit (a key of :data:`crankbase.texts.UNITS`, "" for
    none) spelled by :meth:`crankbase.texts.Texts.unit`."""
    from .texts import texts

    t = texts(lang)
    out = {}
    for k, kind in shape.items():
        base = f"{prefix}.{k}"
        if kind == "str":
            out[k] = t(base)
        elif kind[0] == "tuple":
            out[k] = tuple(t(f"{base}.{i}") for i in range(kind[1]))
        elif kind[0] == "dict":
            out[k] = {sk: t(f"{base}.{sk}") for sk in kind[1]}
        else:
            out[k] = [(key, t(f"{base}.{key}"), t.unit(unit))
                      for key, unit in kind[1].items()]
    return out


class Words(dict):
    """``Words(prefix, shape)[lang]``: :func:`words` of each language, read when first
    asked (a module's word table without reading the catalogue at import)."""

    def __init__(self, prefix, shape):
        super().__init__()
        self.prefix, self.shape = prefix, shape

    def __missing__(self, lang):
        self[lang] = words(lang, self.prefix, self.shape)
        return self[lang]


def sheet_rows(df):
    """The rows of ``df`` a sheet holds: all, or every k-th (and the last) of a table
    longer than :data:`MAX_ROWS` (a fine table step); the CSV beside the workbook keeps
    every row."""
    idx, k = bounded(len(df))
    return df if k == 1 else df.iloc[idx]


def thinned_note(full, shown, csv, lang):
    """The note over a thinned table: which rows it holds, where the rest are."""
    import math

    from .texts import texts

    return texts(lang)("sheet.thinned", k=math.ceil(len(full) / MAX_ROWS),
                       shown=len(shown), n=len(full), csv=csv)
