"""The engine study as a library call (engine.study, engine.report.summary): run_study gives the
tables the command line writes, bit for bit; write_report writes exactly the files it
lists, as one unit (a failing figure or workbook writes nothing); the terminal summary
speaks the report's language with the right plural forms."""
from __future__ import annotations

import errno
import os
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

import engine
from crankbase.errors import OutputError, SpecError
from crankbase.output import MANIFEST_NAME, write_csv
from crankbase.resources import example_path
from engine.study import ReportFiles
from engine.report.summary import summary_lines, written_line

CYRILLIC = re.compile("[\u0400-\u04ff]")


def _report(example, **options):
    path = example_path(example)
    return engine.run_study(engine.load(path), source=path, **options)


@pytest.fixture(scope="module")
def petrol():
    return _report("petrol_vaz2106.toml", bearings=True)


@pytest.fixture(scope="module")
def v8():
    return _report("diesel_kamaz740.toml", bearings=True)


# ------------------------------------------------------------------------ the tables
def test_report_holds_the_typed_results(petrol):
    """The tables are the results' own frames, in the order written; the whole engine
    sums the cylinder (4 cylinders: Mкр.ср of the engine = 4 × that of one cylinder)."""
    assert list(petrol.tables)[:5] == ["forces.csv", "table2.csv", "cylinders.csv",
                                       "torque.csv", "balance.csv"]
    assert petrol.tables["forces.csv"] is petrol.cylinder.table
    assert petrol.tables["torque.csv"] is petrol.whole.torque
    assert petrol.whole.cylinder is petrol.cylinder
    assert petrol.whole.summary.M_mean_Nm == pytest.approx(4 * petrol.cylinder.summary.M_mean_Nm,
                                                           rel=1e-9)
    assert petrol.bearings is not None and "wear.csv" in petrol.tables
    assert petrol.bearings.tables["crankpins.csv"] is petrol.tables["crankpins.csv"]
    # one throw's crank-pin load is the force table's Rшш, at the table rows
    np.testing.assert_array_equal(petrol.tables["crankpins.csv"]["R_1_N"].to_numpy(),
                                  petrol.cylinder.table["R_N"].to_numpy())
    assert len(petrol.plot_names) == 22 and petrol.name == "petrol-vaz2106"
    with pytest.raises(AttributeError):
        petrol.name = "other"                                  # frozen
    with pytest.raises(TypeError):
        petrol.tables["forces.csv"] = None                     # read-only mapping


def test_options_and_the_bearings_switch():
    path = example_path("diesel_d240.toml")
    study = engine.load(path)
    plain = engine.run_study(study)
    assert plain.bearings is None and "crankpins.csv" not in plain.tables
    coarse = engine.run_study(path, step=10, form="kolchin")     # a path is loaded
    t = coarse.tables["forces.csv"]
    assert len(t) == 73 + 1 and 375 in set(t["alpha_deg"])       # 0..720 every 10°, + 375°
    assert coarse.study.settings.form == "kolchin" and "tg_beta" in coarse.tables["table2.csv"]
    # the same physics at another step: the rows on both grids agree exactly
    both = plain.tables["forces.csv"].merge(t, on="alpha_deg", suffixes=("", "_10"))
    assert len(both) > 10
    np.testing.assert_array_equal(both["T_N"], both["T_N_10"])
    for bad, key in ((dict(step=0), "step"), (dict(form="textbook"), "form")):
        with pytest.raises(SpecError, match=f"^{key}: got"):
            engine.run_study(study, **bad)


def test_a_bearings_table_in_the_source_asks_for_the_bearings():
    """A spec dict with [bearings]: the bearing loads without asking (the study carries
    the table, read once by engine.load); the same engine without it has none."""
    d = tomllib.loads(example_path("diesel_d240.toml").read_text())
    d["pressure"]["file"] = str(example_path("diesel_d240_indicator.csv"))
    d["bearings"] = dict(wear_half_angle_deg=45.0)
    study = engine.load(d)
    asked = engine.run_study(study)
    assert asked.bearings is not None
    assert asked.bearings.analysis.options.wear_half_angle_deg == 45.0
    assert "+/-45 deg" in "\n".join(asked.summary_lines("en"))
    del d["bearings"]
    assert engine.run_study(engine.load(d)).bearings is None


# ------------------------------------------------------------------------ the writing
def _files(folder):
    return {p.name for p in folder.iterdir() if p.name != MANIFEST_NAME}


def test_write_writes_exactly_the_files_listed_and_removes_stale_ones(tmp_path,
                                                                     unrendered_figures):
    """(Which files are written and removed; the figures are built, not drawn: the
    petrol's plots are rendered by the session's shared CLI reports, the drawings in
    tests/test_reports_plots.py.)"""
    path = example_path("petrol_vaz2106.toml")
    report = engine.run_study(engine.load(path), source=path)
    out = tmp_path / "out"
    written = engine.write_report(report, out, "en", formats=("png",), drawing=True)
    assert isinstance(written, ReportFiles)
    assert _files(out) == {p.name for p in written}
    assert len(written.tables) == 5 and len(written.plots) == 13 == written.plot_count
    assert [p.name for p in written.drawings] == [
        "petrol-vaz2106_drawing_forces_P.pdf", "petrol-vaz2106_drawing_forces_NKT.pdf",
        "petrol-vaz2106_drawing_polar.pdf"]
    line = written_line(written, "en")
    assert line.startswith("wrote petrol-vaz2106_forces.csv, ")
    assert line.endswith(", petrol-vaz2106.xlsx, 13 plots (PNG), "
                         "petrol-vaz2106_drawing_forces_P.pdf, "
                         "petrol-vaz2106_drawing_forces_NKT.pdf, "
                         f"petrol-vaz2106_drawing_polar.pdf in {out}")
    # another engine's files in the folder stay; this engine's PNGs and PDFs of the
    # earlier run are stale when the new run writes SVG without the drawing
    (out / "other_forces_P.png").write_bytes(b"x")
    assert unrendered_figures == ["png"] * 13 + ["pdf"] * 3
    again = engine.write_report(report, out, "ru", formats="svg")
    assert _files(out) == {p.name for p in again} | {"other_forces_P.png"}
    assert not list(out.glob("petrol-vaz2106*.png")) and not list(out.glob("*.pdf"))
    assert written_line(again, "ru").endswith(
        f"petrol-vaz2106.xlsx, 13 графиков (SVG) в {out}")


def test_bad_write_arguments_write_nothing(petrol, tmp_path):
    # formats=() is valid: the tables and the workbook without figures
    # (tests/test_teacher_tools.py::test_a_report_without_figures)
    for kwargs, key in ((dict(lang="de"), "lang"), (dict(formats=("png", "gif")), "formats"),
                        (dict(formats=("bmp",)), "formats")):
        with pytest.raises(SpecError, match=f"^{key}: got"):
            engine.write_report(petrol, tmp_path / "o", **kwargs)
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("what", ["workbook", "figure"])
def test_a_failing_workbook_or_figure_writes_nothing(what, tmp_path, monkeypatch):
    import matplotlib.figure

    import engine.report.workbook

    path = example_path("diesel_d240.toml")
    report = engine.run_study(engine.load(path), source=path)
    if what == "workbook":
        def broken(wb, dst):
            Path(dst).write_bytes(b"partial")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(dst))
        monkeypatch.setattr(engine.report.workbook, "save_workbook", broken)
    else:
        calls = []

        def broken(self, fname, *a, **k):
            calls.append(fname)
            Path(fname).write_bytes(b"\x89PNG partial")
            if len(calls) == 7:                 # the seventh plot file, mid-way
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(fname))
        monkeypatch.setattr(matplotlib.figure.Figure, "savefig", broken)
    out = tmp_path / "new" / "out"
    with pytest.raises(OutputError, match="No space left on device"):
        engine.write_report(report, out, "en")
    assert list(tmp_path.iterdir()) == []        # not even the folders it made


def test_the_spec_file_is_an_input_no_output_may_overwrite(tmp_path):
    spec = tmp_path / "petrol-vaz2106.xlsx"         # the spec named as the workbook
    spec.write_text(example_path("petrol_vaz2106.toml").read_text())
    d = tomllib.loads(spec.read_text())
    report = engine.run_study(engine.load(d), source=spec)
    with pytest.raises(OutputError, match="input"):
        engine.write_report(report, tmp_path)
    assert spec.read_text() == example_path("petrol_vaz2106.toml").read_text()


# ------------------------------------------------------------------------ the summary
def test_summary_in_english_has_no_cyrillic_and_in_russian_no_english_word(petrol, v8):
    for report in (petrol, v8):
        en = "\n".join(report.summary_lines("en"))
        ru = engine.report.summary.summary_text(report, "ru")
        assert not CYRILLIC.search(en), en
        words = set(re.findall(r"[A-Za-z]{3,}", ru.replace(report.study.spec.name, "")))
        assert words <= {"max", "min"}, words
        assert len(en.splitlines()) == len(ru.splitlines())
    ru = "\n".join(summary_lines(v8, "ru"))
    assert "двигатель: 8 цил., V-образный, порядок работы 1-5-4-2-6-3-7-8" in ru
    assert "без них не уравновешены: 1-го порядка, вращающиеся" in ru
    en = "\n".join(summary_lines(v8, "en"))
    assert "unbalanced before them: 1st order, rotating" in en


def test_summary_numbers_are_the_results(petrol):
    """Each number of the summary is the typed result's, in the template's format."""
    s, ws = petrol.cylinder.summary, petrol.whole.summary
    en = summary_lines(petrol, "en")
    assert en[2] == f"  P max              {s.P_N.max:10.0f} N    at alpha = " \
                    f"{s.P_N.alpha_max_deg:g} deg"
    assert f"Mкр.ср = {ws.M_mean_Nm:.1f} Н·м" in summary_lines(petrol, "ru")[7]
    cw = ws.counterweights[0]
    assert f"m*r = {cw.mr * 1e3:9.2f} kg·mm at {cw.angle_deg:6.1f} deg" in "\n".join(en)


@pytest.mark.parametrize("n, ru, en", [(1, "1 график (PNG)", "1 plot (PNG)"),
                                       (3, "3 графика (PNG)", "3 plots (PNG)"),
                                       (13, "13 графиков (PNG)", "13 plots (PNG)"),
                                       (21, "21 график (PNG)", "21 plots (PNG)"),
                                       (22, "22 графика (PNG)", "22 plots (PNG)"),
                                       (25, "25 графиков (PNG)", "25 plots (PNG)")])
def test_the_wrote_line_agrees_with_the_number_of_plots(n, ru, en, tmp_path):
    files = ReportFiles(folder=tmp_path, tables=(tmp_path / "e_forces.csv",),
                        workbook=tmp_path / "e.xlsx", plots=(), plot_count=n,
                        formats=("png",))
    assert written_line(files, "ru") == f"записано: e_forces.csv, e.xlsx, {ru} в {tmp_path}"
    assert written_line(files, "en") == f"wrote e_forces.csv, e.xlsx, {en} in {tmp_path}"


def test_the_balance_line_agrees_with_the_number_of_counterweights(petrol):
    from dataclasses import replace

    whole = petrol.whole
    one = replace(whole, summary=replace(whole.summary,
                                         counterweights=whole.summary.counterweights[:1]))
    line = engine.report.summary.whole_engine_lines(one, "en")[4]
    assert "with 1 counterweight; unbalanced before it: 2nd order" in line
    assert "with 4 counterweights; unbalanced before them" in \
        engine.report.summary.whole_engine_lines(whole, "en")[4]


# The README's "Scripting a study" example runs as written, and prints and writes what it
# says, in tests/test_readme_blocks.py (PROMISES): every README block runs there once.


def test_the_command_line_names_its_options_where_the_library_names_arguments(tmp_path,
                                                                             capsys):
    from crankdyn.cli import main

    assert main(["engine", "--example", "-o", str(tmp_path / "o"), "--step", "0",
                 "--lang", "en"]) == 2
    assert capsys.readouterr().err.splitlines() == [
        "crankdyn engine: error: --step: got 0.0; must be a number > 0 and <= 720"]
    assert main(["engine", "--example", "-o", str(tmp_path / "o"), "--step", "0"]) == 2
    assert capsys.readouterr().err.splitlines() == [     # the report's language, ru
        "crankdyn engine: ошибка: --step: получено 0.0; должно быть числом > 0 и <= 720"]
    with pytest.raises(SpecError, match="^step: got 0.0"):
        engine.run_study(example_path("petrol_vaz2106.toml"), step=0.0)
    assert not (tmp_path / "o").exists()
