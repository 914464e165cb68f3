"""Copies of a workbook edited in the file itself, every other part of the file the same
bytes: a few number cells changed, as a student's spreadsheet leaves them
(:func:`altered_copy`, for the tests of ``crankdyn check``: no load and save of a whole
report with openpyxl, a report's workbook holds ~40,000 cells, to alter three of them); each
sheet cut to its first rows (:func:`thinned_copy`, for the renders that look at the pages a
sheet's page setup gives)."""
from __future__ import annotations

import re
import zipfile


def altered_copy(src, dst, changes):
    """Copy the workbook ``src`` to ``dst`` with cells changed.

    ``changes``: ``{sheet: {coordinate: change}}``; ``sheet`` the sheet's place in the
    workbook, from 1 (its part ``xl/worksheets/sheet<sheet>.xml``, as openpyxl and our
    reports name them); ``change`` is ``value`` (the cell's new number) or ``(formula,
    value)`` (a formula without its ``=`` and the value a spreadsheet last computed for
    it, as Excel and LibreOffice save them).  Each cell must be a number cell of
    ``src`` (``<c r="B6" …><v>x</v></c>``).  Returns ``dst``."""
    parts = {f"xl/worksheets/sheet{n}.xml": cells for n, cells in changes.items()}

    def edit(name, text):
        for coord, change in parts.pop(name).items():
            formula, value = change if isinstance(change, tuple) else (None, change)
            f = "" if formula is None else f"<f>{formula}</f>"
            text, n = re.subn(rf'(<c r="{coord}"(?: [^>]*)?>)<v>[^<]*</v>',
                              lambda m: f"{m[1]}{f}<v>{float(value)!r}</v>", text)
            assert n == 1, (name, coord)
        return text

    _sheets_rewritten(src, dst, lambda name: name in parts, edit)
    assert not parts, f"no such sheet in {src}: {sorted(parts)}"
    return dst


def thinned_copy(src, dst, rows):
    """Copy the workbook ``src`` to ``dst`` with every worksheet cut to its first ``rows``
    rows: the rows below removed from the sheet's XML and its ``<dimension>`` cut to match,
    the sheet's other elements (page setup, margins, columns, views) unchanged, every other
    part the same bytes.  For the tests that have LibreOffice print a workbook only to see
    the pages its page setup gives: a sheet's paper and orientation are the same on each of
    its pages, so its first pages show them, without laying out thousands of rows.
    Returns ``dst``."""
    row = re.compile(r'<row r="(\d+)"[^>]*?(?:/>|>.*?</row>)', re.S)
    dim = re.compile(r'(<dimension ref="[A-Z]+\d+:[A-Z]+)(\d+)"')

    def edit(name, text):
        text = row.sub(lambda m: m[0] if int(m[1]) <= rows else "", text)
        return dim.sub(lambda m: f'{m[1]}{min(int(m[2]), rows)}"', text)

    _sheets_rewritten(src, dst, lambda name: True, edit)
    return dst


def _sheets_rewritten(src, dst, chosen, edit):
    """Copy the workbook ``src`` to ``dst``, the XML text of each worksheet part whose name
    ``chosen(name)`` accepts replaced by ``edit(name, text)``; every other part the same
    bytes."""
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) \
            as zout:
        for item in zin.infolist():
            data = zin.read(item)
            if re.fullmatch(r"xl/worksheets/sheet\d+\.xml", item.filename) \
                    and chosen(item.filename):
                data = edit(item.filename, data.decode("utf-8")).encode("utf-8")
            zout.writestr(item, data)
