"""Teacher tools (issue 14): ``crankdyn engine --variants`` (one complete report per
variant, a summary equal to the individual reports, bad rows reported by row and key
without stopping the good ones) and ``crankdyn check`` (a workbook we wrote, altered by
known amounts, is flagged at exactly those cells; an unaltered one passes)."""
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from openpyxl import load_workbook

import engine
from crankbase.checking import parse_mapping
from crankbase.errors import SpecError
from crankbase.resources import example_path
from crankdyn.cli import main
from engine.plots import PLOT_NAMES, TRAIN_PLOT_NAMES
from engine.report import KOLCHIN_SHEET
from engine.variants import VariantRow, apply_variant, parse_cell, read_variants
from xlsx_edit import altered_copy

PETROL = example_path("petrol_vaz2106.toml")


# ----------------------------------------------------------------------------- variants
def _variants_table(n, broken_row_index):
    """n petrol variants (bore, stroke, rod mass per area, speed, form); one broken."""
    rng = np.random.default_rng(14)
    rows = []
    for i in range(n):
        rows.append({"variant": f"V{i + 1:02d}",
                     "engine.bore_mm": round(float(rng.uniform(72, 92)), 1),
                     "engine.stroke_mm": round(float(rng.uniform(70, 90)), 1),
                     "masses.rod_kg_m2": round(float(rng.uniform(120, 180)), 1),
                     "engine.speed_rpm": int(rng.integers(4000, 6000)),
                     "table.form": "kolchin" if i % 3 == 0 else "seed"})
    rows[broken_row_index]["engine.bore_mm"] = -5          # a deliberately broken row
    return pd.DataFrame(rows)


def _check_variant_reports(out, table, summary, pngs, lang):
    """The summary equals the individual reports, variant by variant: the workbook's
    results and inputs, the form asked for, a direct computation of that variant; and
    ``pngs(variant)`` (the PNG files of its report) are the engine's plots (``pngs``
    None: a report written with ``formats=()`` has no figure file)."""
    for rec in summary.itertuples(index=False):
        folder = out / rec.variant
        files = sorted(p.name for p in folder.iterdir())
        assert f"{rec.variant}.xlsx" in files and f"{rec.variant}_forces.csv" in files
        if pngs is None:
            assert not [f for f in files if f.endswith((".png", ".svg", ".pdf"))]
        else:
            assert sorted(pngs(rec.variant)) == sorted(f"{rec.variant}_{n}.png" for n in
                                                       PLOT_NAMES + TRAIN_PLOT_NAMES)
        wb = load_workbook(folder / f"{rec.variant}.xlsx", read_only=True)
        rows = {r[0]: r for r in wb.worksheets[2].iter_rows(min_row=4, values_only=True)
                if r[0]}
        assert rows["T_N"][3] == rec.T_max_N and rows["T_N"][4] == rec.alpha_T_max_deg
        assert rows["R_N"][3] == rec.R_max_N and rows["P_N"][3] == rec.P_max_N
        assert rows["M_mean_Nm"][3] == rec.M_mean_Nm and rows["chi"][3] == rec.chi
        inputs = {r[0]: r[3] for r in wb.worksheets[0].iter_rows(min_row=4, values_only=True)
                  if r[0]}
        src = table[table["variant"] == rec.variant].iloc[0]
        assert inputs["bore_mm"] == pytest.approx(src["engine.bore_mm"], rel=1e-12)
        assert inputs["speed_rpm"] == src["engine.speed_rpm"] == rec.speed_rpm
        form = src["table.form"]
        assert (KOLCHIN_SHEET[lang] in wb.sheetnames) == (form == "kolchin")
        wb.close()
        # and equals a direct computation of that variant
        d = apply_variant(engine.spec.read_toml(PETROL)[0],
                          VariantRow(0, rec.variant, {k: parse_cell(src[k].item() if
                                                                hasattr(src[k], "item")
                                                                else src[k])
                                                      for k in table.columns
                                                      if k != "variant"}))
        st = engine.load(d)
        s = engine.analyze(st.spec, st.settings).summary
        assert s.M_mean_Nm == rec.M_mean_Nm and s.R_N.max == rec.R_max_N


@pytest.mark.slow
def test_thirty_variants_end_to_end(tmp_path):
    """Thirty variants, one broken, through the library's batch
    (:func:`engine.variants.run_variants`, one process) with ``formats=()``: every
    report's tables and workbook are written and named, the summary and the errors file
    are checked, the bad row is reported by row and key without stopping the others.
    No figure is built here: a variants run's figures (every plot, PNG and SVG, by name)
    are proven by the three-variant run below (--jobs 2), the command line's report of
    a bad row (exit 1, stderr, summary) by :func:`test_a_bad_row_on_the_command_line`."""
    from engine.variants import run_variants

    n, broken = 30, 16
    table = _variants_table(n, broken)
    path = tmp_path / "variants.csv"
    table.to_csv(path, index=False)
    out = tmp_path / "out"
    seen = []
    done = run_variants(PETROL, path, out, "en", jobs=1, formats=(),
                        progress=lambda outcome, total: seen.append((outcome, total)))
    assert len(seen) == n and {total for _, total in seen} == {n}
    bad_row = broken + 2                                     # header is row 1
    assert [o.variant.row for o in done.failures] == [bad_row]
    assert any(f"row {bad_row} (V{broken + 1:02d}): engine.bore_mm: got -5" in ln
               for ln in done.failures[0].problems)
    head = done.summary_lines("en")[0]
    assert f"{n - 1} written" in head and "1 failed" in head
    summary = pd.read_csv(out / "variants_summary.csv")
    assert len(summary) == n - 1
    assert list(summary["variant"]) == [f"V{i:02d}" for i in range(1, n + 1)
                                        if i != broken + 1]          # the table's order
    assert [r["variant"] for r in done.records] == list(summary["variant"])
    assert not (out / f"V{broken + 1:02d}").exists()
    errors = pd.read_csv(out / "variants_errors.csv")
    assert errors["row"].tolist() == [bad_row]
    _check_variant_reports(out, table, summary, None, "en")


def test_a_bad_row_on_the_command_line(tmp_path, capsys, unrendered_figures):
    """``crankdyn engine --variants`` with one good and one broken row (--jobs 1): exit
    status 1, the bad row named on stderr by row and key, the summary printed, the good
    variant's report complete (its 13 figures built and saved as PNG and SVG; not
    rendered: the three-variant run below renders them)."""
    table = _variants_table(2, 1)
    path = tmp_path / "variants.csv"
    table.to_csv(path, index=False)
    out = tmp_path / "out"
    assert main(["engine", str(PETROL), "--variants", str(path), "-o", str(out),
                 "--lang", "en", "--jobs", "1"]) == 1        # one row failed
    cap = capsys.readouterr()
    assert "row 3 (V02): engine.bore_mm: got -5" in cap.err
    assert "1 written" in cap.out and "1 failed" in cap.out
    assert unrendered_figures == ["png", "svg"] * len(PLOT_NAMES + TRAIN_PLOT_NAMES)
    summary = pd.read_csv(out / "variants_summary.csv")
    assert list(summary["variant"]) == ["V01"] and not (out / "V02").exists()
    assert pd.read_csv(out / "variants_errors.csv")["row"].tolist() == [3]

    def pngs(variant):
        assert len(list((out / variant).glob("*.svg"))) == 13
        return [p.name for p in (out / variant).glob("*.png")]

    _check_variant_reports(out, table, summary, pngs, "en")


def test_a_report_without_figures(tmp_path, unrendered_figures):
    """``engine.write_report(..., formats=())``: the tables and the workbook, no figure
    built or written, and the figures of an earlier run of this engine removed as stale;
    the tables are those of a report with figures, byte for byte."""
    from crankbase.output import verify_report
    from engine.report.summary import written_line

    report = engine.run_study(engine.load(PETROL))
    full = engine.write_report(report, tmp_path / "full", "en")
    assert len(full.plots) == 2 * len(PLOT_NAMES + TRAIN_PLOT_NAMES) == \
        len(unrendered_figures)
    again = tmp_path / "bare"
    shutil.copytree(tmp_path / "full", again)                   # an earlier run's files
    del unrendered_figures[:]
    bare = engine.write_report(report, again, "en", formats=())
    assert unrendered_figures == []                             # nothing saved
    assert bare.plots == () and bare.plot_count == 0 and bare.formats == ()
    assert sorted(p.name for p in again.iterdir() if not p.name.startswith(".")) == \
        sorted([p.name for p in full.tables] + [full.workbook.name])  # old figures gone
    verify_report(again)                                        # its manifest agrees
    for p in full.tables:
        assert (again / p.name).read_bytes() == p.read_bytes()
    line = written_line(bare, "en")
    assert "plot" not in line and full.workbook.name in line
    assert "13 plots (PNG, SVG)" in written_line(full, "en")
    with pytest.raises(SpecError):
        engine.write_report(report, tmp_path / "x", "en", formats=("png", "png"))


def test_variants_from_xlsx_rerun_and_all_good(tmp_path, capsys):
    """Three variants from an .xlsx table, end to end with every plot rendered, written
    by two processes (--jobs 2): all good, the summary in the table's order and equal to
    the reports."""
    table = _variants_table(3, 0)
    table.loc[0, "engine.bore_mm"] = 80.0
    path = tmp_path / "variants.xlsx"
    table.to_excel(path, index=False, engine="openpyxl")
    out = tmp_path / "out"
    assert main(["engine", "--example", "petrol", "--variants", str(path), "-o",
                 str(out), "--jobs", "2"]) == 0
    assert "вариантов: 3; записано 3" in capsys.readouterr().out
    s1 = pd.read_csv(out / "variants_summary.csv")
    assert list(s1["variant"]) == ["V01", "V02", "V03"]
    assert not (out / "variants_errors.csv").exists()

    def pngs(variant):
        found = [p.name for p in (out / variant).glob("*.png")]
        assert all((out / variant / p).stat().st_size > 1000 for p in found)
        assert len(list((out / variant).glob("*.svg"))) == len(found)
        return found

    _check_variant_reports(out, table, s1, pngs, "ru")


def test_variants_table_problems_at_once(tmp_path, capsys):
    path = tmp_path / "v.csv"
    path.write_text("engine.bore_mm,engine.stroke_mm\n80,80\n")
    assert main(["engine", "--lang", "en", "--example", "--variants", str(path), "-o",
                 str(tmp_path / "o")]) == 2
    assert "no 'variant' (or 'name') column" in capsys.readouterr().err
    path.write_text("variant;engine.bore_mm\nA;80\nA;81\n;82\n")     # ';' separated
    with pytest.raises(SpecError) as e:
        read_variants(path)
    assert [str(p) for p in e.value.problems] == [
        "row 3: variant 'A' repeats row 2", "row 4: column 'variant' is empty"]
    assert not (tmp_path / "o").exists()


def test_parse_cell_and_apply_variant():
    assert parse_cell("79") == 79 and parse_cell("0.275") == 0.275
    assert parse_cell(80.0) == 80 and isinstance(parse_cell(80.0), int)
    assert parse_cell("[372, 375]") == [372, 375] and parse_cell("true") is True
    assert parse_cell("kolchin") == "kolchin" and parse_cell("  ") is None
    base = {"engine": {"name": "x", "bore_mm": 79}}
    d = apply_variant(base, VariantRow(2, "A1", {"engine.bore_mm": 82, "table.form": "s"}))
    assert d == {"engine": {"name": "A1", "bore_mm": 82}, "table": {"form": "s"}}
    assert base["engine"]["bore_mm"] == 79                      # the base is untouched
    with pytest.raises(SpecError, match=r"row 2: engine.bore_mm.x: engine.bore_mm is a value"):
        apply_variant(base, VariantRow(2, "A1", {"engine.bore_mm.x": 1}))


# ----------------------------------------------------------------------------- check
@pytest.fixture(scope="module")
def petrol_report(cli_report):
    rep = cli_report("engine", "--example", "petrol", "--lang", "en")  # shared, read-only
    assert rep.rc == 0
    return rep.folder


def _check(tmp_path, *argv):
    out = tmp_path / "chk"
    code = main(["check", *map(str, argv), "-o", str(out), "--lang", "en"])
    return code, out


def test_unaltered_workbook_passes(petrol_report, tmp_path):
    code, out = _check(tmp_path, PETROL, petrol_report / "petrol-vaz2106.xlsx")
    assert code == 0
    check = pd.read_csv(out / "check.csv")
    assert list(check.columns) == ["alpha_deg", "column", "student", "computed",
                                   "deviation", "ok"]
    assert check["ok"].all() and (check["deviation"] == 0).all()
    assert {"T_N", "T_mm", "beta_deg", "M_Nm", "psi_deg"} <= set(check["column"])


@pytest.mark.parametrize("form", ["seed", "kolchin"])
def test_altered_cells_are_flagged_exactly(tmp_path, capsys, cli_report, loaded_workbook,
                                           form):
    # the session's shared diesel report (read-only, parsed once per worker: the cells
    # are altered in a copy of its file, xlsx_edit.altered_copy); the example's own form
    # is seed, so that report is asked for without --form
    own = () if form == engine.load(example_path("diesel_d240.toml")).settings.form \
        else ("--form", form)
    rep = cli_report("engine", "--example", "diesel", "--lang", "ru", *own)
    assert rep.rc == 0
    src = rep.folder
    wb = loaded_workbook(src / "diesel-d240.xlsx")
    # Table 2 (keys in hidden row 5, data from row 6); Kolchin's form: its own sheet
    # (keys in row 3, data from row 4)
    sheets = {"t2": (wb.worksheets[1], 5)}
    if form == "kolchin":
        sheets["k"] = (wb[KOLCHIN_SHEET["ru"]], 3)
    keys = {s: [ws.cell(k, j).value for j in range(1, ws.max_column + 1)]
            for s, (ws, k) in sheets.items()}
    rows = {s: {ws.cell(r, 1).value: r for r in range(k + 1, ws.max_row + 1)}
            for s, (ws, k) in sheets.items()}
    # (sheet, α, column, factor): 30 % off is wrong (the values are ≥ 2 % of their
    # column's scale, so 30 % exceeds rtol + atol); 1 % off is within rtol = 2 %
    edits = [("t2", 30, "T_N", 1.30), ("t2", 420, "T_N", 0.70), ("t2", 120, "K_N", 1.30),
             ("t2", 60, "M_Nm", 1.01)]
    if form == "kolchin":
        edits += [("k", 210, "T_coef", 1.2), ("k", 240, "P_MPa", 0.5),
                  ("k", 150, "tg_beta", 1.30)]
    else:
        edits += [("t2", 210, "T_mm", 1.2), ("t2", 240, "P_N", 0.5)]
    wrong, changes = set(), {}
    for s, a, col, f in edits:
        ws = sheets[s][0]
        c = ws.cell(rows[s][a], keys[s].index(col) + 1)
        assert abs(c.value) > 1e-3                 # a real value, not a zero crossing
        changes.setdefault(wb.worksheets.index(ws) + 1, {})[c.coordinate] = c.value * f
        if abs(f - 1) > 0.02:
            wrong.add((a, col))
    student = altered_copy(src / "diesel-d240.xlsx", tmp_path / "student.xlsx", changes)
    code, out = _check(tmp_path, example_path("diesel_d240.toml"), student)
    assert code == 1
    check = pd.read_csv(out / "check.csv")
    flagged = {(a, c) for a, c in check.loc[~check["ok"], ["alpha_deg", "column"]]
               .itertuples(index=False)}
    assert flagged == wrong
    # the marked copy: exactly those cells red, each with the right value in a comment
    marked = load_workbook(out / "student_checked.xlsx")
    red = set()
    for s, (ws, k) in sheets.items():
        mws = marked[ws.title]
        red |= {(mws.cell(c.row, 1).value, keys[s][c.column - 1])
                for row in mws.iter_rows(min_row=k + 1) for c in row
                if c.fill.fgColor.rgb in ("00FF7C80", "FFFF7C80")}
    assert red == wrong
    study = engine.load(example_path("diesel_d240.toml"))
    t = engine.force_table(study.spec, settings=study.settings)
    s, a, col, _ = edits[0]
    mws = marked[sheets[s][0].title]
    comment = mws.cell(rows[s][a], keys[s].index(col) + 1).comment.text
    right = t.loc[t["alpha_deg"] == a, "T_N"].iat[0]
    assert f"right value: {right:.6g}" in comment
    text = capsys.readouterr().out
    assert "T_N            WRONG 2 of" in text and "M_Nm           right" in text


def test_check_reads_a_formula_by_its_value_and_marks_it_keeping_the_formula(
        petrol_report, tmp_path, loaded_workbook):
    """A student's cell computed by a formula is checked by the value the spreadsheet
    last computed (what a ``data_only`` reading gives), and the marked copy keeps the
    formula: one T_N cell ``=1.3*…`` (30 % off, flagged), one M_Nm cell ``=1*…`` (right).
    The formulas and their values are put into the sheet's XML as Excel and LibreOffice
    leave them (xlsx_edit.altered_copy; openpyxl writes no computed value)."""
    from crankbase.checking import check_table, write_check
    from engine.check import check_side

    wb = loaded_workbook(petrol_report / "petrol-vaz2106.xlsx")    # shared, read-only
    ws = wb.worksheets[1]                        # Table 2: keys in hidden row 5
    keys = [c.value for c in ws[5]]
    rows = {ws.cell(r, 1).value: r for r in range(6, ws.max_row + 1)}
    edits = {}                                   # coordinate → (formula, value)
    for a, col, f in ((30.0, "T_N", 1.3), (60.0, "M_Nm", 1.0)):
        c = ws.cell(rows[a], keys.index(col) + 1)
        edits[c.coordinate] = (f"{f!r}*{c.value!r}", f * c.value)
    student = altered_copy(petrol_report / "petrol-vaz2106.xlsx", tmp_path / "student.xlsx",
                           {2: edits})
    result = check_table(check_side(engine.load(PETROL)), student)
    bad = result.table.loc[~result.table["ok"], ["alpha_deg", "column"]].values.tolist()
    assert bad == [[30.0, "T_N"]]
    got = result.table.set_index(["alpha_deg", "column"])["student"]
    assert got[(30.0, "T_N")] == edits[ws.cell(rows[30.0], keys.index("T_N") + 1)
                                      .coordinate][1]
    files = write_check(result, tmp_path / "out", "en")
    assert files.n_marked == 1
    marked = load_workbook(files.marked).worksheets[1]
    for coord, (formula, _) in edits.items():
        assert marked[coord].value == f"={formula}", coord
    assert marked[next(iter(edits))].fill.fgColor.rgb in ("00FF7C80", "FFFF7C80")


def test_check_csv_with_a_column_mapping(petrol_report, tmp_path, capsys):
    df = pd.read_csv(petrol_report / "petrol-vaz2106_forces.csv")
    student = df[["alpha_deg", "T_N", "K_N"]].rename(columns={"alpha_deg": "α",
                                                              "T_N": "T, Н"})
    student.loc[2, "T, Н"] *= 1.5
    path = tmp_path / "s.csv"
    student.to_csv(path, index=False, sep=";", decimal=",")
    code, out = _check(tmp_path, PETROL, path, "--map", "α=alpha_deg", "--map", "T, Н=T_N")
    assert code == 1
    check = pd.read_csv(out / "check.csv")
    assert set(check["column"]) == {"T_N", "K_N"}
    bad = check[~check["ok"]]
    assert bad[["alpha_deg", "column"]].values.tolist() == [[df["alpha_deg"][2], "T_N"]]
    assert not list(out.glob("*.xlsx"))                  # no workbook for a CSV
    with pytest.raises(SpecError, match="^mapping: got 'no-equals-sign'"):
        parse_mapping(["no-equals-sign"])             # the library names its argument
    capsys.readouterr()
    code, _ = _check(tmp_path, PETROL, path, "--map", "no-equals-sign")
    assert code == 2                                   # the CLI names its option
    assert capsys.readouterr().err.splitlines() == [
        "crankdyn check: error: --map: got 'no-equals-sign'; write STUDENT_HEADER=our_column"]


def test_library_never_names_a_command_line_option():
    """No library package's messages name a CLI option (``--plans``, ``--map`` …): the
    CLI renames the argument a problem names (SpecError.renamed).  The developers'
    catalogue compiler, a script beside the catalogues that no module imports, has
    options of its own."""
    import re
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    compiler = root / "crankbase" / "locale" / "compile_catalogues.py"
    for pkg in ("crankbase", "linkage", "engine", "dynamics", "plans"):
        for f in (root / pkg).rglob("*.py"):
            if f == compiler:
                continue
            for n, line in enumerate(f.read_text().splitlines(), 1):
                code = line.split("#")[0]
                if re.search(r"[\"'(\s]--[a-z]", code) and '``' not in code:
                    raise AssertionError(f"{f.relative_to(root)}:{n}: {line.strip()}")


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_check_linkage_tables(tmp_path, cli_report, lang):
    """The check reads our linkage workbook by its CSV-name header row (row 3), the same
    in the Russian workbook (sheets «Скорости», «Реакции и Mур», symbols Mур, units Н·м)
    and the English one: altered cells are flagged exactly there, the unaltered
    workbook passes.  The workbook is the session's shared ``crankdyn linkage --example
    ratchet --no-plots --lang LANG`` report's (read-only: the altered copy is saved
    elsewhere)."""
    rep = cli_report("linkage", "--example", "ratchet", "--no-plots", "--lang", lang)
    assert rep.rc == 0, rep.err
    src = rep.folder
    wb = load_workbook(src / "ratchet-drive.xlsx")
    # sheets by their place (inputs, positions, velocities, accelerations, loads, forces):
    # the titles are in the report's language
    ws = wb.worksheets[2]
    assert ws.title == {"ru": "Скорости", "en": "velocities"}[lang]
    head = [c.value for c in ws[3]]
    j = head.index("omega3_rad_s") + 1
    ws.cell(4 + 5, j).value *= 1.3                        # position 6, ω3 30 % off
    wf = wb.worksheets[5]
    fh = [c.value for c in wf[3]]
    assert wf.cell(1, fh.index("M_drive_Nm") + 1).value == {"ru": "Mур", "en": "Mb"}[lang]
    wf.cell(4 + 2, fh.index("M_drive_Nm") + 1).value += 50.0    # position 3, Mур + 50 N·m
    student = tmp_path / "lk_student.xlsx"
    wb.save(student)
    code, out = _check(tmp_path, example_path("ratchet.toml"), student)
    assert code == 1
    check = pd.read_csv(out / "check.csv")
    assert list(check.columns)[0] == "position"
    bad = check[~check["ok"]][["position", "column"]].values.tolist()
    assert sorted(bad) == [[3, "M_drive_Nm"], [6, "omega3_rad_s"]]
    # every table column of the workbook was read (none ignored as unknown), and the
    # marked copy has the red cells on the student's own sheets
    res = pd.read_csv(src / "ratchet-drive_kinematics.csv")
    assert set(check["column"]) == (set(res.columns) - {"position"}) | set(
        pd.read_csv(src / "ratchet-drive_forces.csv").columns) - {"position"}
    marked = load_workbook(out / "lk_student_checked.xlsx")
    red = [(w.title, c.coordinate) for w in marked.worksheets for r in w.iter_rows()
           for c in r if c.comment is not None]
    assert sorted(red) == sorted([(ws.title, ws.cell(4 + 5, j).coordinate),
                                  (wf.title, wf.cell(4 + 2, fh.index("M_drive_Nm") + 1)
                                   .coordinate)])
    code, _ = _check(tmp_path / "2", example_path("ratchet.toml"), src / "ratchet-drive.xlsx")
    assert code == 0


def test_check_bad_input_exits_2(tmp_path, capsys):
    (tmp_path / "s.csv").write_text("a,b\n1,2\n")
    assert main(["check", "--lang", "en", str(PETROL), str(tmp_path / "s.csv"), "-o",
                 str(tmp_path / "o"), "--rtol", "-1"]) == 2
    assert "--rtol" in capsys.readouterr().err
    assert main(["check", "--lang", "en", str(PETROL), str(tmp_path / "s.csv"), "-o",
                 str(tmp_path / "o")]) == 2
    assert "no column 'alpha_deg'" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()
    shutil.rmtree(tmp_path, ignore_errors=True)


def test_check_an_unreadable_student_file_exits_2_with_one_line(tmp_path, capsys):
    """A file named .xlsx that is not a workbook, and a CSV that is not UTF-8 text: one
    line naming the file (exit 2), not a traceback; nothing written."""
    (tmp_path / "s.xlsx").write_bytes(b"not a workbook")
    (tmp_path / "s.csv").write_bytes("alpha_deg;T_N\n0;1\n".encode("utf-16"))
    for name in ("s.xlsx", "s.csv"):
        assert main(["check", "--lang", "en", str(PETROL), str(tmp_path / name), "-o",
                     str(tmp_path / "o")]) == 2
        err = capsys.readouterr().err.splitlines()
        assert err == [f"crankdyn check: error: {name}: cannot be read: " + err[0].split(
            "cannot be read: ", 1)[1]], err
    assert not (tmp_path / "o").exists()
