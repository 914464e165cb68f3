"""Render a workbook as LibreOffice prints it (for the A4 tests, marked slow; skipped where
LibreOffice or poppler-utils are not installed)."""
from __future__ import annotations

import re
import shutil
import subprocess

import pytest

#: The first bytes of a figure saved unrendered, followed by its format and ")" (the text
#: tests/conftest.py writes: ``unrendered_figures``, the shared reports of its
#: ``UNRENDERED_REPORTS``).
UNRENDERED_HEAD = b"figure not rendered ("


def unrendered(path):
    """Whether the figure file ``path`` was saved unrendered, as its own format (the text
    names the format of its suffix: a PNG saved as PNG)."""
    return path.read_bytes().startswith(UNRENDERED_HEAD + path.suffix[1:].encode() + b")")


#: Skip marker of the rendering tests.
needs_office = pytest.mark.skipif(
    shutil.which("soffice") is None or shutil.which("pdfinfo") is None,
    reason="LibreOffice or poppler-utils not installed")


#: Rows of each sheet a render for its pages' size keeps (``xlsx_edit.thinned_copy``): a
#: sheet's page setup is the same on each of its pages, and these rows still run over
#: several pages of every long sheet.
RENDER_ROWS = 100


def page_sizes(xlsx, outdir):
    """The pages of ``xlsx`` converted to PDF by LibreOffice in ``outdir``: a list of
    (short side, long side) in points, one per page (A4 is (595, 842))."""
    outdir.mkdir(parents=True, exist_ok=True)
    subprocess.run(["soffice", "--headless", "--convert-to", "pdf", "--outdir", str(outdir),
                    str(xlsx)], check=True, capture_output=True, timeout=300)
    pdf = next(outdir.glob("*.pdf"))
    info = subprocess.run(["pdfinfo", "-f", "1", "-l", "10000", str(pdf)], check=True,
                          capture_output=True, text=True).stdout
    pages = re.findall(r"Page\s+\d+ size:\s+([\d.]+) x ([\d.]+) pts", info)
    return [tuple(sorted((round(float(w)), round(float(h))))) for w, h in pages]


def page_sizes_many(named, outdir):
    """:func:`page_sizes` of several workbooks with one start of LibreOffice (it costs
    seconds): ``named`` maps a key to a workbook; returns key → list of page sizes."""
    src = outdir / "src"
    src.mkdir(parents=True, exist_ok=True)
    copies = {}
    for i, (key, xlsx) in enumerate(named.items()):
        copies[key] = src / f"w{i}.xlsx"              # distinct names, one PDF each
        shutil.copyfile(xlsx, copies[key])
    subprocess.run(["soffice", "--headless", "--convert-to", "pdf", "--outdir", str(outdir),
                    *map(str, copies.values())], check=True, capture_output=True,
                   timeout=300 + 60 * len(copies))
    sizes = {}
    for key, copy in copies.items():
        info = subprocess.run(["pdfinfo", "-f", "1", "-l", "10000",
                               str(outdir / f"{copy.stem}.pdf")], check=True,
                              capture_output=True, text=True).stdout
        pages = re.findall(r"Page\s+\d+ size:\s+([\d.]+) x ([\d.]+) pts", info)
        sizes[key] = [tuple(sorted((round(float(w)), round(float(h))))) for w, h in pages]
    return sizes


def save_through_savefig(fig, path, fmt, dpi, **kwargs):
    """:func:`crankbase.plot_layout.save_laid_out` while ``Figure.savefig`` is a test's
    stand-in (a figure saved unrendered, or laid out and not encoded): straight to it,
    without the layout ``save_laid_out`` runs for the one draw it saves (a figure not
    drawn needs none; one rendered for real is laid out by ``savefig``)."""
    fig.savefig(path, format=fmt, dpi=dpi, **kwargs)
