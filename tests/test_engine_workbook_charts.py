"""The engine workbook's native charts and print areas (issue 23): every chart drawn from
the fine grid of the summary (its extremes are the summary's: the diesel's total torque
peaks at 1176.1 N·m at 130°, not the 30° rows' 1097.6 N·m at 120°), its helper cells off
the printed sheets, the polar chart with equal x and y scales as LibreOffice renders it,
and a fine --step thinned on the sheets instead of writing millions of cells."""
from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest
from rendering import needs_office

import engine
from crankbase.resources import example_path


def _whole(name="diesel_d240.toml", **settings):
    study = engine.load(example_path(name))
    s = dataclasses.replace(study.settings, **settings) if settings else study.settings
    return engine.analyze_engine(study.spec, study.train, s)


def _workbook(whole, lang):
    from engine.report import a4_setup, add_engine_sheets, build_workbook

    return a4_setup(add_engine_sheets(build_workbook(whole.cylinder, lang), whole, lang))


def _values(wb, ref):
    """The numbers of a chart reference such as 'chart data'!$G$2:$G$1442."""
    sheet, rng = ref.rsplit("!", 1)
    ws = wb[sheet.strip("'")]
    return np.array([c.value for row in ws[rng.replace("$", "")] for c in row], float)


def _charts(wb):
    return [(ws, ch) for ws in wb.worksheets for ch in ws._charts]


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_chart_extremes_are_the_summary_extremes(lang):
    """The total-torque chart's data peak where the summary says (Mкр.max = 1176.1 N·m
    at θ = 130° for the D-240 example: the summary's fine grid), and every one-cylinder
    chart's series peaks at the summary's extreme of its column."""
    whole = _whole()
    s, cyl = whole.summary, whole.cylinder.summary
    assert s.M_max_Nm == pytest.approx(1176.1, abs=0.05) and s.alpha_M_max_deg == 130.0
    wb = _workbook(whole, lang)
    charts = _charts(wb)
    assert len(charts) == 6
    total = charts[-1][1].series[0]              # the total torque: first, bold series
    y, x = _values(wb, total.yVal.numRef.f), _values(wb, total.xVal.numRef.f)
    assert y.max() == s.M_max_Nm and x[np.argmax(y)] == s.alpha_M_max_deg
    assert y.min() == s.M_min_Nm and x[np.argmin(y)] == s.alpha_M_min_deg
    checked = 0
    for ws, ch in charts[:4]:
        for ser in ch.series:
            yv = _values(wb, ser.yVal.numRef.f)
            head = wb[ser.yVal.numRef.f.rsplit("!", 1)[0].strip("'")]
            col = re.search(r"\$([A-Z]+)\$", ser.yVal.numRef.f.rsplit("!", 1)[1]).group(1)
            name = head[f"{col}1"].value
            if name in ("P_N", "S_N", "N_N", "K_N", "T_N", "M_Nm", "R_N"):
                e = cyl.extreme(name)
                assert yv.max() == e.max and yv.min() == e.min, name
                checked += 1
    assert checked == 7


def test_chart_helper_cells_are_outside_the_print_areas():
    """The Charts sheet prints its title and charts only: the poles of the polar diagram
    and every chart's data are on a hidden sheet, and every value of a printed sheet is
    inside its print area."""
    from openpyxl.utils import range_boundaries

    wb = _workbook(_whole(), "ru")
    ws_ch = wb.worksheets[4]
    assert ws_ch.print_area
    for ws, ch in _charts(wb):
        for ser in ch.series:
            sheet = ser.yVal.numRef.f.rsplit("!", 1)[0].strip("'")
            assert wb[sheet].sheet_state == "hidden", (ws.title, sheet)
    for ws in wb.worksheets:
        if ws.sheet_state != "visible" or not ws.print_area:
            continue
        c0, r0, c1, r1 = range_boundaries(ws.print_area.split("!")[-1].replace("$", ""))
        outside = [c.coordinate for row in ws.iter_rows() for c in row
                   if c.value is not None and not (c0 <= c.column <= c1 and r0 <= c.row <= r1)]
        assert not outside, (ws.title, outside)
    area = range_boundaries(ws_ch.print_area.split("!")[-1].replace("$", ""))
    for ch in ws_ch._charts:                  # every chart inside it (rows of 0.529 cm)
        row = int(re.sub(r"[A-Z]", "", ch.anchor))
        assert row + ch.height / 0.529 <= area[3] + 1, (row, area)


def test_a_fine_step_is_thinned_on_the_sheets():
    """--step 0.05 (14 401 rows of Table 2): every sheet holds at most MAX_ROWS rows of a
    table and says so; the charts still peak at the summary's extremes."""
    from crankbase.workbook import MAX_ROWS

    whole = _whole("petrol_vaz2106.toml", step_deg=0.05)
    assert len(whole.cylinder.table) == 14401
    wb = _workbook(whole, "en")
    for ws in wb.worksheets:
        assert ws.max_row <= MAX_ROWS + 60, (ws.title, ws.max_row)
    t2 = wb.worksheets[1]
    assert "every row is in forces.csv" in t2["E2"].value and "14401" in t2["E2"].value
    alphas = [r[0] for r in t2.iter_rows(min_row=6, max_col=1, values_only=True)
              if isinstance(r[0], float)]
    assert alphas[0] == 0.0 and alphas[-1] == 720.0 and alphas[1] == 0.05 * 8
    total = _charts(wb)[-1][1].series[0]
    assert _values(wb, total.yVal.numRef.f).max() == whole.summary.M_max_Nm


@pytest.fixture(scope="module")
def polar_pngs(tmp_path_factory):
    """The first page of each language's polar chart alone on its sheet, as LibreOffice
    renders it (one start of LibreOffice for both workbooks): lang → (PNG path, chart)."""
    import subprocess

    from engine.report import a4_setup, build_workbook, save_workbook

    tmp = tmp_path_factory.mktemp("polar")
    res = _whole().cylinder
    charts, books = {}, []
    for lang in ("ru", "en"):
        wb = build_workbook(res, lang)
        ws = wb.worksheets[4]
        polar = ws._charts[-1]
        ws._charts = [polar]
        polar.anchor = "A3"
        ws.row_breaks.brk = []
        for s in list(wb.worksheets):
            if s is not ws and s.sheet_state == "visible":
                wb.remove(s)
        a4_setup(wb)
        save_workbook(wb, tmp / f"polar_{lang}.xlsx")
        books.append(tmp / f"polar_{lang}.xlsx")
        charts[lang] = polar
    subprocess.run(["soffice", "--headless", "--convert-to", "pdf", "--outdir", str(tmp),
                    *map(str, books)], check=True, capture_output=True, timeout=420)
    out = {}
    for lang in ("ru", "en"):
        subprocess.run(["pdftoppm", "-png", "-r", "100", "-f", "1", "-l", "1",
                        str(tmp / f"polar_{lang}.pdf"), str(tmp / f"p_{lang}")], check=True)
        out[lang] = (next(tmp.glob(f"p_{lang}*.png")), charts[lang])
    return out


@pytest.mark.slow
@needs_office
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_polar_chart_renders_with_equal_scales(lang, polar_pngs):
    """LibreOffice renders the polar chart with square grid cells (the same step on both
    axes at the same length): a circle stays a circle."""
    from PIL import Image

    png, polar = polar_pngs[lang]
    im = np.asarray(Image.open(png).convert("RGB")).astype(int)
    grid = np.abs(im - 135).max(axis=2) <= 12          # LibreOffice's grey grid lines

    def lines(counts):
        idx = np.flatnonzero(counts > 0.6 * counts.max())
        return [g.mean() for g in np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)]
    xs, ys = lines(grid.sum(axis=0)), lines(grid.sum(axis=1))
    n = round((polar.x_axis.scaling.max - polar.x_axis.scaling.min)
              / polar.x_axis.majorUnit) + 1
    assert len(xs) == len(ys) == n, (xs, ys)
    dx, dy = np.diff(xs).mean(), np.diff(ys).mean()
    assert dx == pytest.approx(dy, rel=0.03), (dx, dy)


@pytest.mark.parametrize("example", ["diesel_kamaz740.toml", "petrol_bmw_m54.toml"])
def test_every_chart_fits_the_printed_page_width(example):
    """No native chart is wider than its sheet's printed A4 page (the V8's total-torque
    chart, as wide as the columns beside it, ran past the page's edge and was cut)."""
    from crankbase.resources import example_path
    from engine.study import report_workbook

    wb = report_workbook(engine.run_study(example_path(example)), "en")
    for ws in wb.worksheets:
        paper = 29.7 if ws.page_setup.orientation == "landscape" else 21.0
        m = ws.page_margins
        printable = paper - ((m.left or 0.7) + (m.right or 0.7)) * 2.54
        for ch in ws._charts:
            assert ch.width <= printable, (ws.title, ch.width, printable)


@pytest.mark.parametrize("example", ["diesel_kamaz740.toml", "petrol_vaz2106.toml"])
def test_polar_chart_axes_carry_few_enough_labels_to_read(example):
    """At most nine tick labels an axis on the polar chart (the V8's eleven six-digit
    labels, -50000 … 50000, ran into each other in LibreOffice's render), and the same
    step on both axes (equal scales)."""
    from crankbase.resources import example_path
    from engine.study import report_workbook

    wb = report_workbook(engine.run_study(example_path(example)), "en")
    polar = [ch for ws in wb.worksheets for ch in ws._charts
             if ch.y_axis.scaling.orientation == "maxMin"]
    assert polar
    for ch in polar:
        steps = {ch.x_axis.majorUnit, ch.y_axis.majorUnit}
        assert len(steps) == 1
        for ax in (ch.x_axis, ch.y_axis):
            n = round((ax.scaling.max - ax.scaling.min) / ax.majorUnit) + 1
            assert n <= 9, (example, n)


# ----------------------------------------------------------- saving: the number cells
def _members(data):
    import io
    import zipfile

    z = zipfile.ZipFile(io.BytesIO(data))
    # docProps/core.xml holds the time of the save, the one part two saves differ in
    return {i.filename: z.read(i.filename) for i in z.infolist()
            if i.filename != "docProps/core.xml"}


def _odd_cells_workbook():
    """A workbook with every kind of cell next to numbers: ints past 16 digits, −0.0,
    subnormal and huge floats, an empty styled cell, text with spaces and markup, a
    formula, a bool, a date, a hyperlink, a comment on an empty cell, NaN."""
    import datetime

    from openpyxl import Workbook
    from openpyxl.comments import Comment
    from openpyxl.styles import Font

    wb = Workbook()
    ws = wb.active
    for r, v in enumerate([1, -5, 2 ** 60, 12345678901234567, 0.1 + 0.2, -0.0, 5e-324,
                           1e-320, 1e300, -1.5e-7, 3.0, float("nan"), True,
                           " text <&> ", "=A1+A2", datetime.date(2026, 11, 26)], start=1):
        ws.cell(r, 1, v)
        ws.cell(r, 2, v).font = Font(bold=True)
    ws["C1"].font = Font(italic=True)                               # styled, empty
    ws["C2"].comment = Comment("a note", "t")                       # commented, empty
    ws["C3"] = 7.25
    ws["C3"].hyperlink = "https://example.org"
    return wb


@pytest.mark.parametrize("case", ["odd cells", "v8 bearings ru"])
def test_number_cells_are_saved_as_openpyxl_writes_them(case, tmp_path, monkeypatch):
    """crankbase.output.full_precision_xlsx writes number cells without openpyxl's element
    per cell: the saved file is the one openpyxl's own cell writer gives, part for part
    and byte for byte (but the save time in docProps/core.xml), for an engine workbook
    (the V8 with its bearing sheets) and for every odd kind of cell; and it reads back
    to the same values."""
    import math

    from openpyxl import load_workbook

    from crankbase.output import full_precision_xlsx

    def build():
        if case == "odd cells":
            return _odd_cells_workbook()
        from engine.study import report_workbook       # the engine's and bearings' sheets

        return report_workbook(engine.run_study(engine.load(example_path(
            "diesel_kamaz740.toml")), bearings=True), "ru")

    def save(path):
        with full_precision_xlsx():
            build().save(path)
        return path

    fast = save(tmp_path / "fast.xlsx")
    with monkeypatch.context() as m:                 # openpyxl's own writer, every cell
        m.setattr("crankbase.output._number_cell_writer", lambda write_cell, text: write_cell)
        own = save(tmp_path / "own.xlsx")
    a, b = _members(fast.read_bytes()), _members(own.read_bytes())
    assert list(a) == list(b)
    for part in a:
        assert a[part] == b[part], part
    sheet = a["xl/worksheets/sheet1.xml"].decode()
    if case == "odd cells":
        assert '<c r="A6" t="n"><v>-0.0</v></c>' in sheet            # full precision
        assert '<c r="A4" t="n"><v>1.234567890123457e+16</v></c>' in sheet
        ws = load_workbook(fast).active
        assert ws["A5"].value == 0.1 + 0.2 and ws["A7"].value == 5e-324
        assert math.copysign(1, ws["B6"].value) == -1.0 and ws["A14"].value == " text <&> "
        assert ws["C3"].hyperlink.target == "https://example.org"
    else:
        assert sum(v.count(b' t="n"><v>') for k, v in a.items()
                   if k.startswith("xl/worksheets/")) > 10000      # the tables' numbers
