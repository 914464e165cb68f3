"""Workbooks a student hands in (issue 14): chart series told apart in grey-scale print,
English workbooks without Cyrillic (Russian ones with every textbook symbol), every sheet
of every workbook set up for A4 with readable row heights and charts kept on one page,
Table 2 in both textbook forms with the same numbers behind them."""
import math
import re
import zipfile

import numpy as np
import pandas as pd
import pytest
from rendering import needs_office, page_sizes_many

import engine
from crankbase.resources import example_path
from crankdyn.cli import main
from engine.table2 import coefficients, table2, table2_columns

CYRILLIC = re.compile("[\u0400-\u04FF]")
EXAMPLES = {"petrol": "petrol_vaz2106.toml", "diesel": "diesel_d240.toml"}
RUSSIAN_SYMBOLS = ("ΔPг", "Pj", "Sш", "Mкр", "Kr.ш", "Rшш", "Ψ", "Lш", "Fп", "mш.к", "pг",
                   "β", "α", "μP", "Mкр.ср", "Rшш.ср", "vп.ср")


def study_workbook(ex, lang, form, folder):
    """The workbook and ``_table2.csv`` of ``crankdyn engine --example ex --lang lang
    --form form``, written through the study layer (engine.run_study, report_workbook,
    the table's CSV), without the plots: (xlsx path, table2 path)."""
    from crankbase.output import write_csv
    from engine.report import save_workbook
    from engine.study import report_workbook

    report = engine.run_study(engine.load(example_path(EXAMPLES[ex])), form=form)
    folder.mkdir(parents=True, exist_ok=True)
    xlsx = folder / f"{report.name}.xlsx"
    save_workbook(report_workbook(report, lang), xlsx)
    table2 = folder / report.file_names["table2.csv"]
    write_csv(report.tables["table2.csv"], table2)
    return xlsx, table2


#: The Kolchin-form report the CLI writes for these tests (the teacher's check reads the
#: same shared run); the other Kolchin-form workbooks are the study layer's, and
#: test_the_study_layer_writes_the_cli_workbook proves the two write the same.
KOLCHIN_BY_CLI = ("diesel", "ru")


@pytest.fixture(scope="module")
def runs(tmp_path_factory, cli_report):
    """Every workbook the CLI writes: engine (both examples × languages × forms),
    linkage (two examples), synthesis.  The engine reports in the seed's form, the
    examples' own ([table] form absent), are the session's shared ones; of the other
    form, one is the CLI's (shared) and the rest the study layer's (no plots drawn); the
    linkage workbooks are the session's shared ``--no-plots`` runs."""
    out = {}
    for ex in ("petrol", "diesel"):
        for lang in ("ru", "en"):
            for form in ("seed", "kolchin"):
                study = engine.load(example_path(EXAMPLES[ex]))
                own = () if study.settings.form == form else ("--form", form)
                if own and (ex, lang) != KOLCHIN_BY_CLI:
                    out[("engine", ex, lang, form)], out[("table2", ex, lang, form)] = \
                        study_workbook(ex, lang, form,
                                       tmp_path_factory.mktemp(f"{ex}_{lang}_{form}"))
                    continue
                rep = cli_report("engine", "--example", ex, "--lang", lang, *own)
                assert rep.rc == 0
                d = rep.folder
                out[("engine", ex, lang, form)] = next(d.glob("*.xlsx"))
                out[("table2", ex, lang, form)] = next(d.glob("*_table2.csv"))
    for ex in ("ratchet", "press"):         # the session's shared runs (read-only; the
        for lang, key in (("ru", ("linkage", ex)), ("en", ("linkage", ex, "en"))):
            rep = cli_report("linkage", "--example", ex, "--no-plots", "--lang", lang)
            assert rep.rc == 0, rep.err       # inputs' units test reads the ratchet's)
            out[key] = next(rep.folder.glob("*.xlsx"))
    for lang in ("ru", "en"):
        d = tmp_path_factory.mktemp(f"synth_{lang}")
        assert main(["synth", "--phi0", "30", "--l1", "0.15", "--ground", "0.4", "-o",
                     str(d), "--no-plots", "--lang", lang]) == 0
        out[("synth", lang)] = next(d.glob("*.xlsx"))
    return out


@pytest.fixture(scope="module")
def book(loaded_workbook):
    """``book(path)``: the workbook at ``path`` loaded once per worker for the tests that
    only read it (the session's :func:`loaded_workbook`, shared with the other modules
    reading the same shared reports; read-only: a test that changes a workbook loads its
    own copy)."""
    return loaded_workbook


def test_the_study_layer_writes_the_cli_workbook(runs, tmp_path):
    """The study layer (:func:`study_workbook`) writes the Kolchin-form workbook and
    Table 2 the CLI writes: every part of the workbook byte for byte (every cell, style
    and chart of every sheet), its creation time aside, and the CSV byte for byte."""
    ex, lang = KOLCHIN_BY_CLI
    xlsx, table2 = study_workbook(ex, lang, "kolchin", tmp_path)
    assert table2.read_bytes() == runs[("table2", ex, lang, "kolchin")].read_bytes()
    with zipfile.ZipFile(runs[("engine", ex, lang, "kolchin")]) as cli, \
            zipfile.ZipFile(xlsx) as study:
        names = cli.namelist()
        assert names == study.namelist() and "xl/worksheets/sheet2.xml" in names
        differ = [n for n in names if cli.read(n) != study.read(n)]
    assert differ in ([], ["docProps/core.xml"])        # its created/modified times


def _chart_series(path):
    """(chart file, [(colour, dash, title)]) of every native chart, from the XML."""
    ns = {"c": "http://schemas.openxmlformats.org/drawingml/2006/chart",
          "a": "http://schemas.openxmlformats.org/drawingml/2006/main"}
    import xml.etree.ElementTree as ET

    charts = []
    with zipfile.ZipFile(path) as z:
        for name in sorted(n for n in z.namelist() if n.startswith("xl/charts/chart")):
            root = ET.fromstring(z.read(name))
            series = []
            for ser in root.iter(f"{{{ns['c']}}}ser"):
                ln = ser.find("c:spPr/a:ln", ns)
                clr = ln.find("a:solidFill/a:srgbClr", ns) if ln is not None else None
                dash = ln.find("a:prstDash", ns) if ln is not None else None
                if ln is not None and ln.find("a:noFill", ns) is not None:
                    assert ser.find("c:marker/c:symbol", ns).get("val") != "none"
                    continue                   # markers only (the poles): no line
                series.append((None if clr is None else clr.get("val"),
                               None if dash is None else dash.get("val")))
            charts.append((name, series))
    return charts


def _grey(hex_rgb):
    r, g, b = (int(hex_rgb[i:i + 2], 16) for i in (0, 2, 4))
    return 0.299 * r + 0.587 * g + 0.114 * b


def test_every_chart_series_has_its_own_colour_and_dash(runs):
    for key, path in runs.items():
        if key[0] != "engine":
            continue
        charts = _chart_series(path)
        assert len(charts) == 6      # 4 over α, the polar diagram, the total torque
        for name, series in charts:
            colours = [c for c, _ in series]
            dashes = [d for _, d in series]
            assert None not in colours and None not in dashes, (key, name, series)
            assert len(set(colours)) == len(colours), (key, name, series)
            assert len(set(dashes)) == len(dashes), (key, name, series)
            # told apart in grey-scale print as well: lightness differs by > 10 % (the
            # thin per-cylinder series under a total are told apart by their dashes)
            if len(series) <= 4:
                greys = sorted(_grey(c) for c in colours)
                assert all(b - a > 25 for a, b in zip(greys, greys[1:])), (key, name, greys)


def _strings(wb, skip_symbol_table=True):
    """Every text in a workbook (cells, sheet names) except the symbol table rows."""
    for ws in wb.worksheets:
        yield ws.title, "sheet name", ws.title
        for row in ws.iter_rows():
            if skip_symbol_table and row[0].value == "symbols":
                continue
            for c in row:
                if isinstance(c.value, str):
                    yield ws.title, c.coordinate, c.value


def test_english_workbooks_have_no_cyrillic(runs, book):
    for key, path in runs.items():
        if key[0] not in ("engine", "linkage") or key[2:3] != ("en",):
            continue
        wb = book(path)
        bad = [(s, where, v) for s, where, v in _strings(wb) if CYRILLIC.search(v)]
        assert not bad, (key, bad[:5])
        with zipfile.ZipFile(path) as z:            # chart titles and series names
            for name in z.namelist():
                if name.startswith("xl/charts/"):
                    assert not CYRILLIC.search(z.read(name).decode()), (key, name)


def test_english_synthesis_workbook_has_cyrillic_only_in_its_russian_headers(runs, book):
    """The synthesis workbook keeps a Russian and an English header row in both languages
    (and a Russian and an English name of each quantity); everything else of the English
    one (title, sheet names, the Grashof type, the design task) has no Cyrillic letter,
    the Russian one names the family ККМ-30° and its sheets in Russian."""
    from crankbase.texts import keys, texts

    russian = {texts("ru")(k) for k in keys("ru") if k.startswith("synth.book.")}
    en = book(runs[("synth", "en")])
    bad = [(s, at, v) for s, at, v in _strings(en) if CYRILLIC.search(v) and v not in russian]
    assert not bad, bad
    ru = book(runs[("synth", "ru")])
    assert ru.sheetnames == ["Таблица 1", "Механизм"] and en.sheetnames == ["table1",
                                                                           "mechanism"]
    text = "\n".join(v for _, _, v in _strings(ru))
    for term in ("ККМ-30°", "Н. И. Колчина", "выбранный механизм", "кривошипно-коромысловый",
                 "задано λ1; λ2 = λ3 по ур. (6)", "значение"):
        assert term in text, term
    # the same numbers in the same cells
    nums = [[(c.coordinate, c.value) for ws in wb.worksheets for row in ws.iter_rows()
             for c in row if isinstance(c.value, (int, float))] for wb in (ru, en)]
    assert nums[0] == nums[1]


def test_russian_workbooks_carry_every_textbook_symbol(runs, book):
    for key, path in runs.items():
        if key[0] != "engine" or key[2] != "ru" or key[3] != "seed":
            continue
        text = "\n".join(v for _, _, v in _strings(book(path)))
        with zipfile.ZipFile(path) as z:
            text += "".join(z.read(n).decode() for n in z.namelist()
                            if n.startswith("xl/charts/"))
        missing = [s for s in RUSSIAN_SYMBOLS if s not in text]
        assert not missing, (key, missing)
    # the linkage workbook (Russian, the default): seed 000's symbols and Russian units
    for ex, extra in (("ratchet", ("Mпс", "ω4", "ε4", "aBCⁿ")), ("press", ("Fпс",))):
        text = "\n".join(v for _, _, v in _strings(book(runs[("linkage", ex)])))
        missing = [s for s in ("Mур", "Fи3", "Mи3", "VB", "VBA", "aBAⁿ", "aBAᵗ", "R23n",
                               "R12", "G3", "Н·м", "Н", "м/с", "м/с²", "рад/с", "кг")
                   + extra if s not in text]
        assert not missing, (ex, missing)


def test_one_set_of_english_symbols():
    """engine.symbols is the one table: the workbook template, the native charts and the
    plots print the same English symbol for each quantity (the plots as mathtext)."""
    from engine.plots import SYMBOLS as PLOT_SYMBOLS
    from engine.report.workbook import _CHART_SYMBOLS
    from engine.symbols import SYMBOLS, math_symbol, sym, to_english

    def plain(math):
        return (math.replace("$", "").replace("\\Delta ", "Δ").replace("_", "")
                .replace("{", "").replace("}", ""))
    for key, ru_en_what in SYMBOLS.items():
        assert plain(math_symbol(key)) == ru_en_what[1], key
        assert to_english(ru_en_what[0]) == ru_en_what[1], key
    keys = dict(p="p_gas", dPg="dPg", Pj="Pj", P="P", S="S", N="N", K="K", T="T", M="M",
                R="R", Kr="Kr", Osh="pole_R")
    assert {k: plain(PLOT_SYMBOLS["en"][k]) for k in keys} == {
        k: sym(v, "en") for k, v in keys.items()}
    assert {k: PLOT_SYMBOLS["ru"][k] for k in keys} == {k: sym(v, "ru")
                                                      for k, v in keys.items()}
    assert _CHART_SYMBOLS["en"] == dict(dPg="ΔPg", M="M", S="S", R="Rcp", pole="Or")
    assert _CHART_SYMBOLS["ru"] == dict(dPg="ΔPг", M="Mкр", S="Sш", R="Rшш", pole="Oш")


def _inputs_rows(wb):
    ws = wb.worksheets[0]
    return [[c.value for c in row] for row in ws.iter_rows(min_col=1, max_col=5)]


def test_inputs_sheet_lists_the_symbols_of_both_reports(runs, book):
    """The Russian Inputs sheet maps every Russian textbook symbol to the English report's
    one; the English sheet lists the English symbols with their meanings (no Cyrillic)."""
    from engine.symbols import correspondence

    for lang in ("ru", "en"):
        rows = _inputs_rows(book(runs[("engine", "petrol", lang, "seed")]))
        table = {tuple(r[1:4]) if lang == "ru" else tuple(r[1:3]) for r in rows}
        for en, rus, what in correspondence(lang):
            assert ((what, rus, en) if lang == "ru" else (what, en)) in table, (lang, en)
    rows = _inputs_rows(book(runs[("engine", "petrol", "ru", "seed")]))
    assert ("результирующая сила на шатунную шейку", "Rшш", "Rcp") in {
        tuple(r[1:4]) for r in rows}


def test_inputs_sheet_speaks_the_report_language(runs, book):
    """No raw spec key (``rod_kg_m2``, ``arrangement``…) and no untranslated spec value
    (``otto``, ``inline``) on the Inputs sheet; the masses as given in textbook symbols
    with units (Kolchin's m′п, m′ш per unit piston area for the petrol engine)."""
    for ex in ("petrol", "diesel"):
        for lang in ("ru", "en"):
            key_like = re.compile(r"\b[a-z]+_[a-z0-9_]+\b|\b(otto|diesel|throws"
                                  + ("|inline" if lang == "ru" else "") + r")\b")
            rows = _inputs_rows(book(runs[("engine", ex, lang, "seed")]))
            for r in rows:
                for v in r[1:] if r[0] != "name" else r[1:2]:    # not the engine's name
                    if isinstance(v, str):
                        text = re.sub(r"\[[^]]*\]|\S+\.csv", "", v)   # file names, [table]s
                        assert not key_like.search(text), (ex, lang, v)
            values = {r[1]: r[3] for r in rows if r[1]}
            masses = values["Массы (как заданы)" if lang == "ru" else "Masses (as given)"]
            if ex == "petrol":                       # petrol_vaz2106.toml: per unit area
                assert masses == ("m′п = 100 кг/м²; m′ш = 150 кг/м²; mш.п/mш = 0.275"
                                  if lang == "ru" else
                                  "m′p = 100 kg/m²; m′r = 150 kg/m²; mr,rec/mr = 0.275")
                assert values["Цикл" if lang == "ru" else "Cycle"].endswith(
                    "(Отто)" if lang == "ru" else "(Otto)")
            train = values["Расположение цилиндров" if lang == "ru" else
                           "Cylinder arrangement"]
            assert train == ("рядное" if lang == "ru" else "inline")


def test_every_sheet_has_an_a4_print_setup(runs, book):
    for key, path in runs.items():
        if key[0] == "table2":
            continue
        wb = book(path)
        for ws in wb.worksheets:
            ps = ws.page_setup
            assert int(ps.paperSize) == 9, (key, ws.title)          # A4
            assert ps.orientation in ("portrait", "landscape"), (key, ws.title)
            assert ws.sheet_properties.pageSetUpPr.fitToPage, (key, ws.title)
            assert int(ps.fitToHeight) == 0 and int(ps.fitToWidth) >= 1, (key, ws.title)
            # a sheet wider than ~190 width units prints on more than one page width
            from openpyxl.utils import get_column_letter
            letters = [get_column_letter(j) for j in range(1, ws.max_column + 1)]
            widths = [ws.column_dimensions[c].width or 8.43 for c in letters
                      if not ws.column_dimensions[c].hidden]
            assert sum(widths) / int(ps.fitToWidth) <= 200, (key, ws.title, sum(widths))


def test_wrapped_text_rows_are_tall_enough(runs, book):
    """A wrapped label never overlaps the next row: each row with wrapped text has a
    height of at least its number of lines (words put on lines at the column's width, as
    a spreadsheet does: :func:`crankbase.workbook.wrapped_lines`) × 12 pt."""
    from crankbase.workbook import wrapped_lines

    for key, path in runs.items():
        if key[0] != "engine":
            continue
        wb = book(path)
        for ws in (wb.worksheets[0], wb.worksheets[2]):
            merged = {r.min_row: r for r in ws.merged_cells.ranges}
            for row in ws.iter_rows(min_row=3):
                for c in row:
                    if not (isinstance(c.value, str) and c.alignment.wrap_text) \
                            or ws.column_dimensions[c.column_letter].hidden:
                        continue
                    if c.row in merged and merged[c.row].min_col == c.column:
                        m = merged[c.row]
                        width = sum(ws.column_dimensions[ws.cell(1, j).column_letter].width
                                    for j in range(m.min_col, m.max_col + 1))
                    else:
                        width = ws.column_dimensions[c.column_letter].width
                    lines = wrapped_lines(c.value, width, bool(c.font.b), c.font.sz or 11)
                    height = ws.row_dimensions[c.row].height
                    if lines > 1:
                        assert height and height >= 12 * lines, (key, ws.title,
                                                                 c.coordinate, c.value)


def test_charts_are_not_split_by_page_breaks():
    from engine.report import build_workbook

    study = engine.load(example_path("petrol_vaz2106.toml"))
    result = engine.analyze(study.spec, study.settings)
    wb = build_workbook(result, "ru")
    ws = wb.worksheets[4]
    breaks = sorted(b.id for b in ws.row_breaks.brk)
    assert breaks                                    # four charts: two pages
    for ch in ws._charts:
        # a break with id b ends a page after row b (1-based); the chart covers rows
        # first … last (its height in cm over rows of 15 pt = 0.529 cm)
        first = int(re.sub(r"[A-Z]", "", ch.anchor))
        last = first + math.ceil(ch.height / 0.529)
        assert not any(first <= b < last for b in breaks), (ch.anchor, breaks)


# ----------------------------------------------------------------------- Table 2 forms
@pytest.mark.parametrize("name", ["petrol_vaz2106.toml", "diesel_d240.toml"])
def test_kolchin_coefficients_reproduce_the_dyad_forces(name):
    """Kolchin's route (p × coefficient × Fп) equals the Assur-dyad forces: an independent
    check of N, Sш, K, T (Колчин & Демидов 2008, § "Силы, действующие в КШМ")."""
    study = engine.load(example_path(name))
    spec = study.spec
    t = engine.force_table(spec, settings=study.settings)
    k = table2(t, spec, study.settings, "kolchin")
    P = t["P_N"].to_numpy()
    scale = np.abs(P).max()
    np.testing.assert_allclose(k["P_MPa"] * k["tg_beta"] * spec.area * 1e6, t["N_N"],
                               atol=1e-9 * scale)
    np.testing.assert_allclose(k["P_MPa"] * k["inv_cos_beta"] * spec.area * 1e6, t["S_N"],
                               atol=1e-9 * scale)
    np.testing.assert_allclose(k["P_MPa"] * k["K_coef"] * spec.area * 1e6, t["K_N"],
                               atol=1e-9 * scale)
    np.testing.assert_allclose(k["P_MPa"] * k["T_coef"] * spec.area * 1e6, t["T_N"],
                               atol=1e-9 * scale)
    np.testing.assert_allclose(k["K_MPa"] * spec.area * 1e6, t["K_N"], rtol=1e-12)
    # β = arcsin(λ sin α) for the central mechanism (domain brief § 5)
    a = np.radians(t["alpha_deg"])
    np.testing.assert_allclose(np.radians(t["beta_deg"]), np.arcsin(spec.lam * np.sin(a)),
                               atol=1e-12)


def test_coefficients_at_known_angles():
    """At α = 90° with λ = 0.25: tg β = 0.25/√(1 − 0.0625); sin(α+β)/cos β = 1;
    cos(α+β)/cos β = −tg β (hand computation)."""
    beta = np.degrees(np.arcsin(0.25))
    c = coefficients([90.0], [beta])
    assert c["tg_beta"][0] == pytest.approx(0.25 / math.sqrt(1 - 0.0625), rel=1e-14)
    assert c["inv_cos_beta"][0] == pytest.approx(1 / math.sqrt(1 - 0.0625), rel=1e-14)
    assert c["T_coef"][0] == pytest.approx(1.0, rel=1e-14)
    assert c["K_coef"][0] == pytest.approx(-c["tg_beta"][0], rel=1e-13)


def test_both_forms_share_the_numbers(runs):
    """<name>_table2.csv in either form: the columns of the form, the numbers of the
    force table (bit for bit where both hold a column)."""
    for ex, spec_name in (("petrol", "petrol_vaz2106.toml"), ("diesel", "diesel_d240.toml")):
        study = engine.load(example_path(spec_name))
        t = engine.force_table(study.spec, settings=study.settings)
        for form in ("seed", "kolchin"):
            got = pd.read_csv(runs[("table2", ex, "ru", form)])
            assert list(got.columns) == table2_columns(form)
            want = table2(t, study.spec, study.settings, form)
            np.testing.assert_array_equal(got.to_numpy(), want.to_numpy())
            for col in ("T_N", "M_Nm", "alpha_deg", "beta_deg"):
                np.testing.assert_array_equal(got[col], t[col])
    mm = pd.read_csv(runs[("table2", "petrol", "ru", "seed")])
    mu = engine.load(example_path("petrol_vaz2106.toml")).settings.force_scale
    np.testing.assert_allclose(mm["P_mm"] * mu, mm["P_N"], rtol=1e-12)


def test_table_form_in_the_spec_and_refused_when_unknown(tmp_path, capsys):
    d, _ = engine.spec.read_toml(example_path("petrol_vaz2106.toml"))
    d["table"]["form"] = "kolchin"
    assert engine.load(d).settings.form == "kolchin"
    d["table"]["form"] = "pretty"
    with pytest.raises(engine.EngineSpecError) as e:
        engine.load(d)
    assert "table.form" in str(e.value) and "kolchin" in str(e.value)


# ----------------------------------------------------------------------- render on A4
@pytest.mark.slow
@needs_office
def test_workbooks_render_on_a4_pages(runs, tmp_path, book):
    """LibreOffice prints every workbook to PDF: every page is A4 (either orientation)
    and every sheet yields at least one page."""
    chosen = [("engine", "petrol", "ru", "seed"), ("engine", "diesel", "en", "kolchin"),
              ("linkage", "ratchet"), ("linkage", "press", "en"),
              ("synth", "ru"), ("synth", "en")]           # every layout, each language
    sizes = page_sizes_many({key: runs[key] for key in chosen}, tmp_path)
    for key in chosen:
        path, pages = runs[key], sizes[key]
        assert set(pages) == {(595, 842)}, (key, set(pages))        # A4, either way
        assert len(pages) >= len(book(path).worksheets), key


def test_native_polar_chart():
    """The polar diagram as an editable Excel scatter chart: K downwards (reversed axis),
    equal spans and grid steps on both axes of a square plot area (the shape is kept),
    the locus of (T, K) from the fine grid on the hidden chart-data sheet and the poles O
    and Oш = (0, −Kr.ш) as markers from that sheet (not on the printed Charts sheet)."""
    from engine.report import build_workbook

    study = engine.load(example_path("petrol_vaz2106.toml"))
    result = engine.analyze(study.spec, study.settings)
    spec, table = result.spec, result.curves
    wb = build_workbook(result, "ru")
    ws = wb.worksheets[4]
    polar = ws._charts[-1]
    assert polar.y_axis.scaling.orientation == "maxMin"
    lay = polar.layout.manualLayout
    assert lay.layoutTarget == "inner"
    assert lay.w * polar.width == pytest.approx(lay.h * polar.height)      # square
    xs = polar.x_axis.scaling.max - polar.x_axis.scaling.min
    ys = polar.y_axis.scaling.max - polar.y_axis.scaling.min
    assert xs == pytest.approx(ys) and polar.x_axis.majorUnit == polar.y_axis.majorUnit
    curve, poles = polar.series
    cd = wb["Данные графиков"]
    assert cd.sheet_state == "hidden"
    head = {}
    for c in cd[1]:                     # the curves' columns first, then the poles'
        if c.value:
            head.setdefault(c.value, c.column_letter)
    assert f"!${head['T_N']}$" in curve.xVal.numRef.f and "Данные графиков" in curve.xVal.numRef.f
    assert f"!${head['K_N']}$" in curve.yVal.numRef.f
    pole_k = poles.yVal.numRef.f.split("!")[1].replace("$", "")
    assert [c.value for row in cd[pole_k] for c in row] == [0.0, -spec.Kr]
    assert not [c for row in ws.iter_rows(min_row=2) for c in row if c.value is not None]
    assert polar.x_axis.scaling.min <= table["T_N"].min()
    assert polar.x_axis.scaling.max >= table["T_N"].max()
    assert polar.y_axis.scaling.min <= min(table["K_N"].min(), -spec.Kr)
    assert polar.y_axis.scaling.max >= max(table["K_N"].max(), -spec.Kr)
