"""The study layer (issue #19 item 1): one library call runs the whole study of a bundled
example and gives the same tables as the command line, bit for bit, without writing; a
separate write writes exactly the files it lists; the terminal summary is the library's,
in the report's language.  #23: an engine spec without [dynamics] uses its [flywheel] δ."""
from __future__ import annotations

import contextlib
import io
import os
import re

import pytest

from crankbase.resources import example_path
from crankdyn.cli import main

CYRILLIC = re.compile("[\u0400-\u04FF]")
MANIFEST = ".crankdyn-report.json"


def _csv_text(df):
    return df.to_csv(index=False, float_format=None, lineterminator="\n")


def _cli(argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(argv)
    assert rc == 0, err.getvalue()
    return out.getvalue(), err.getvalue()


def _same_tables(tables, folder):
    """Every table of a study equals the CSV the command wrote, byte for byte, and the
    command wrote no CSV the study does not hold."""
    assert tables
    for name, df in tables.items():
        assert (folder / name).read_text(encoding="utf-8") == _csv_text(df), name
    assert {p.name for p in folder.glob("*.csv")} == set(tables)


def _nothing_written(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return lambda: sorted(os.listdir(tmp_path)) == []


def _english_words(text, allowed):
    for a in sorted(map(str, allowed), key=len, reverse=True):
        text = re.sub(re.escape(a) + r"[\w.\-]*", "", text)
    # a word: 3+ Latin letters, not part of a word of other letters (ΔTmax, Jм)
    return [w for w in re.findall(r"(?<![^\W\d_])[A-Za-z]{3,}(?![^\W\d_])", text)
            if w not in ("max", "min", "const", "PNG", "SVG")]


# ------------------------------------------------------------------------------ linkage
@pytest.fixture(scope="module")
def ratchet_plans(tmp_path_factory, figures_rendered_only_within):
    """``plans.study.run_study`` of the ratchet with the plans of positions 5 and 11 (no
    plots), run once in an empty working folder that it must leave empty (the run writes
    nothing), and its report written once in English (``linkage.study.write_report``):
    ``(report, written, folder)`` for the tests that read them (read-only).  Its tests
    read tables, file names and summaries: the drawings are saved unrendered (the
    ratchet's plans 5 and 11 are rendered in tests/test_plans_output.py's ratchet_run)."""
    from linkage.study import write_report
    from plans.study import run_study

    here, cwd = os.getcwd(), tmp_path_factory.mktemp("ratchet_plans")
    os.chdir(cwd)
    try:
        report = run_study(example_path("ratchet.toml"), plots=False, plans=[5, 11])
        assert sorted(os.listdir(cwd)) == []                 # the run writes nothing
    finally:
        os.chdir(here)
    out = cwd / "out"
    with figures_rendered_only_within():
        written = write_report(report, out, lang="en")
    return report, written, out


@pytest.mark.parametrize("example, argv, kw", [
    ("ratchet.toml", ["--plans", "5,11"], dict(plans=[5, 11])),
    ("press.toml", ["--plans", "3", "--sheet", "A1", "--mu-lever", "50"],
     dict(plans="3", mu_lever=50.0)),
])
def test_linkage_study_gives_the_cli_tables_and_writes_what_it_lists(example, argv, kw,
                                                                     tmp_path, monkeypatch,
                                                                     request,
                                                                     figures_rendered_only):
    """The ratchet's study and its English report are the module's (:func:`ratchet_plans`,
    which checks that the run writes nothing), the press's are run here.  Tables, file
    names and the summary are compared: the drawings are saved unrendered (the plans of
    both mechanisms are rendered in tests/test_plans_output.py)."""
    from linkage.study import summary_lines, write_report
    from plans.study import run_study

    figures_rendered_only()

    cli = tmp_path / "cli"
    stdout, _ = _cli(["linkage", str(example_path(example)), "-o", str(cli), "--no-plots",
                      "--lang", "en", *argv])
    if example == "ratchet.toml":
        assert kw == dict(plans=[5, 11])
        report, written, out = request.getfixturevalue("ratchet_plans")
    else:
        (tmp_path / "lib").mkdir()
        empty = _nothing_written(tmp_path / "lib", monkeypatch)
        report = run_study(example_path(example), plots=False, **kw)
        assert empty()                                       # the run writes nothing
        out = tmp_path / "lib" / "out"
        written = write_report(report, out, lang="en")
    _same_tables(report.tables(), cli)
    assert sorted(written.files) == sorted(p.name for p in out.iterdir()
                                           if p.name != MANIFEST)
    assert summary_lines(report, "en", written) == stdout.replace(
        str(cli), str(out)).splitlines()


def test_linkage_study_without_plans_writes_its_plots(tmp_path, unrendered_figures):
    """linkage.study alone (no plans): the tables, the workbook and the five plots (built,
    not drawn: the session's rendered linkage reports prove the images)."""
    from linkage.study import PLOTS, run_study, summary_lines, write_report

    report = run_study(example_path("press.toml"), step=5.0)
    assert len(report.full.kinematics) == 73                  # 0…360° every 5°
    written = write_report(report, tmp_path / "o", lang="en")
    files = sorted(p.name for p in (tmp_path / "o").iterdir() if p.name != MANIFEST)
    assert sorted(written.files) == files
    assert {f"crank-press_{p}.png" for p in PLOTS} <= set(files)
    assert summary_lines(report, "en", written)[-1].endswith(
        f"crank-press.xlsx, 5 images (PNG) in {tmp_path / 'o'}")
    # a rerun without plots removes this mechanism's plots, and says so
    again = write_report(run_study(example_path("press.toml"), plots=False), tmp_path / "o")
    assert sorted(p.name for p in again.removed) == sorted(f"crank-press_{p}.png"
                                                           for p in PLOTS)
    assert not list((tmp_path / "o").glob("*.png"))
    assert unrendered_figures.count("png") == len(PLOTS)        # each plot saved once


def test_linkage_summary_in_both_languages_with_plural_forms(ratchet_plans):
    """The summaries of the ratchet's plans (the module's study and written report)."""
    from linkage.study import summary_lines

    report, written, out = ratchet_plans
    ru = "\n".join(summary_lines(report, "ru", written))
    en = "\n".join(summary_lines(report, "en", written))
    assert not CYRILLIC.search(en), en
    assert not _english_words(ru, [out, "ratchet-drive"]), ru
    assert "для 2 положений на 1 листе A1" in ru and "plans of 2 positions on 1 A1 sheet" in en
    # K is dimensionless: its unit is "-"
    assert re.search(r"K = φр\.х/φх\.х: 1\.1377 -$", ru, re.M)
    # the "wrote" line names the tables, the workbook and the drawings
    last = ru.splitlines()[-1]
    assert last.startswith("записано: ratchet-drive_kinematics.csv, ratchet-drive_forces.csv,"
                           " ratchet-drive.xlsx") and "ratchet-drive_sheet.dxf" in last


def test_linkage_measured_segments_are_written_and_listed(tmp_path, figures_rendered_only):
    """The measured segments' error table written and listed (the drawing saved
    unrendered: tests/test_plans_output.py's press_run renders a run with measurements)."""
    from linkage.study import summary_lines, write_report
    from plans.study import run_study

    figures_rendered_only()

    measured = tmp_path / "m.csv"
    measured.write_text("position,segment,length_mm\n5,pb,50\n", encoding="utf-8")
    report = run_study(example_path("ratchet.toml"), plots=False, plans=[5],
                       measured=measured)
    errors = report.tables()["ratchet-drive_plan_errors.csv"]
    written = write_report(report, tmp_path / "o", lang="en")
    lines = summary_lines(report, "en", written)
    assert "ratchet-drive_plan_errors.csv" in lines[-1] and lines[-1].startswith("wrote ")
    err = float(errors["error_percent"].iat[0])
    assert f"largest |error| {err:.2f} % (position 5)" in "\n".join(lines)
    assert (tmp_path / "o" / "ratchet-drive_plan_errors.csv").read_text() == _csv_text(errors)


def test_massless_mechanism_prints_no_negative_zero():
    """A massless, unloaded mechanism: Mb is ±0.0 at every position; the summary says
    0.00, never -0.00."""
    from linkage.study import summary_lines
    from plans.study import run_study

    spec = {"mechanism": {"kind": "crank-rocker", "name": "bare", "crank": 0.1,
                          "coupler": 0.4, "rocker": 0.3, "ground": 0.45, "omega_rad_s": 5.0},
            "analysis": {"positions": 6, "working_stroke": "ccw"}}
    report = run_study(spec, plots=False, plans=[2])
    assert any(str(m) == "-0.0" for m in report.result.forces["M_drive_Nm"])
    for lang in ("ru", "en"):
        text = "\n".join(summary_lines(report, lang))
        assert "-0.0" not in text, text
        assert re.search(r"\|M(b|ур)\| .*: 0\.00 ", text)


def test_format_snapped():
    from crankbase.tolerances import format_snapped

    assert format_snapped(-0.0, ".2f") == "0.00"
    assert format_snapped(-0.004, ".2f") == "0.00"          # rounds to zero: no sign
    assert format_snapped(-0.5, ".2f") == "-0.50"
    assert format_snapped(-3.6e-14, ".1e") == "-3.6e-14"    # not zero: keeps its sign
    assert format_snapped(-1e-13, ".3g", 1000.0) == "0"     # round-off of 1000
    assert format_snapped(-1e-13, ".3g") == "-1e-13"


def test_linkage_study_arguments_are_named_and_renamed_by_the_cli(tmp_path, capsys):
    from crankbase.errors import SpecError
    from plans.study import run_study

    with pytest.raises(SpecError) as exc:
        run_study(example_path("ratchet.toml"), plans="0,x", sheet="A4", mu_a=-2.0)
    assert [p.key for p in exc.value.problems] == ["plans", "plans", "sheet", "mu_a"]
    with pytest.raises(SpecError, match="step: got 45"):
        run_study(example_path("ratchet.toml"), step=45)
    with pytest.raises(SpecError, match="measured: only with plans"):
        run_study(example_path("ratchet.toml"), measured="x.csv")
    assert main(["linkage", "--lang", "en",
                 "--example", "-o", str(tmp_path / "o"), "--step", "45"]) == 2
    assert capsys.readouterr().err.strip() == (
        "crankdyn linkage: error: --step: got 45; must be > 0 and <= 30 degrees")


# ----------------------------------------------------------------------------- dynamics
@pytest.mark.parametrize("example, lang", [("flywheel_seed.toml", "ru"),
                                           ("press_dynamics.toml", "en")])
def test_dynamics_study_gives_the_cli_tables_and_writes_what_it_lists(example, lang,
                                                                      tmp_path, cli_report,
                                                                      unrendered_figures):
    """The study layer's tables equal the CLI's, and its report lists what it writes (its
    plots built, not drawn: the CLI's report is the session's shared one, rendered in
    Russian, its English figures placeholders: tests/conftest.py ``UNRENDERED_REPORTS``)."""
    from dynamics.study import run_study, summary_lines, write_report

    # the CLI's report of the example (the session's shared run, read-only)
    short = {"flywheel_seed.toml": "flywheel", "press_dynamics.toml": "press"}[example]
    rep = cli_report("dynamics", "--example", short, "--lang", lang)
    assert rep.rc == 0, rep.err
    cli, stdout = rep.folder, rep.out
    report = run_study(example_path(example))
    assert report["motion"] is report.motion                # read as the old mapping too
    _same_tables(report.tables(), cli)
    out = tmp_path / "lib"
    written = write_report(report, out, lang=lang)
    files = {p.name for p in out.iterdir() if p.name != MANIFEST}
    assert set(written.files) <= files
    assert len(files - set(written.files)) == written.plots * 2      # PNG and SVG
    assert sorted(unrendered_figures) == ["png"] * written.plots + ["svg"] * written.plots
    assert summary_lines(report, lang, written) == stdout.replace(
        str(cli), str(out)).splitlines()


def test_dynamics_plural_of_plots_in_the_wrote_line(tmp_path):
    from dynamics.study import WrittenReport, written_line

    w = WrittenReport("o", ["a.csv"], 4)
    assert written_line(w, "ru") == "записано: a.csv, 4 графика (PNG, SVG) в o"
    assert written_line(WrittenReport("o", ["a.csv"], 5), "ru") == (
        "записано: a.csv, 5 графиков (PNG, SVG) в o")
    assert written_line(WrittenReport("o", ["a.csv"], 1), "en") == (
        "wrote a.csv, 1 plot (PNG, SVG) in o")


def test_engine_spec_without_dynamics_uses_its_flywheel_delta():
    """#23: petrol_vaz2106.toml has no [dynamics] but [flywheel] delta = 0.01: the run
    sizes the flywheel for that δ (it ran with no flywheel, δ ≈ 0.29, before) and says
    so; without [flywheel] delta it runs without a flywheel and says that."""
    import tomllib

    from dynamics.report import summary_lines
    from dynamics.study import run_study

    path = example_path("petrol_vaz2106.toml")
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    assert "dynamics" not in data and data["flywheel"]["delta"] == 0.01
    report = run_study(path)
    assert report.notes == ("delta_from_flywheel",)
    assert report.flywheel is not None and report.flywheel.delta == 0.01
    assert report.motion.delta == pytest.approx(0.01, rel=1e-3)
    assert report.motion.J_flywheel > 0
    en = "\n".join(summary_lines(report, lang="en"))
    ru = "\n".join(summary_lines(report, lang="ru"))
    assert "flywheel sized for δ = 0.01" in en and "по δ = 0.01" in ru
    assert not CYRILLIC.search(en) and not _english_words(ru, [report.name])
    # no δ anywhere: no flywheel, and the summary says so
    bare = {k: v for k, v in data.items() if k != "flywheel"}
    report0 = run_study(bare)
    assert report0.notes == ("no_flywheel",) and report0.flywheel is None
    assert report0.motion.J_flywheel == 0 and report0.motion.delta > 0.1
    assert "no flywheel (JF = 0)" in "\n".join(summary_lines(report0, lang="en"))


# ------------------------------------------------------------------------------ balance
@pytest.mark.parametrize("example, lang", [("rotor_two_plane.toml", "ru"),
                                           ("ratchet_balance.toml", "en")])
def test_balance_study_gives_the_cli_tables_and_writes_what_it_lists(example, lang,
                                                                     tmp_path, cli_report,
                                                                     unrendered_figures):
    """As the dynamics study's: the CLI's report (``--example``, that spec) is the
    session's shared one, rendered; the study layer's plots are built, not drawn."""
    from dynamics.balance_study import run_study, summary_lines, write_report

    short = {"rotor_two_plane.toml": "rotor", "ratchet_balance.toml": "ratchet"}[example]
    rep = cli_report("balance", "--example", short, "--lang", lang)
    assert rep.rc == 0, rep.err
    cli, stdout = rep.folder, rep.out
    report = run_study(example_path(example))
    _same_tables(report.tables(), cli)
    out = tmp_path / "lib"
    written = write_report(report, out, lang=lang)
    files = {p.name for p in out.iterdir() if p.name != MANIFEST}
    assert set(written.files) <= files and len(files) == len(written.files) + 2 * written.plots
    assert sorted(unrendered_figures) == ["png"] * written.plots + ["svg"] * written.plots
    assert summary_lines(report, lang, written) == stdout.replace(
        str(cli), str(out)).splitlines()


# -------------------------------------------------------------------------------- synth
def test_synthesis_study_gives_the_cli_tables_and_writes_what_it_lists(tmp_path,
                                                                       monkeypatch):
    from linkage.synthesis_study import run_study, summary_lines, write_report

    cli = tmp_path / "cli"
    stdout, _ = _cli(["synth", "--l2", "0.8", "--mu-min", "40", "--ground", "0.5", "-o",
                      str(cli), "--no-plots"])
    (tmp_path / "lib").mkdir()
    empty = _nothing_written(tmp_path / "lib", monkeypatch)
    report = run_study(30, l2=0.8, mu_min=40, ground=0.5, plots=False)
    assert empty()
    _same_tables(report.tables(), cli)
    out = tmp_path / "lib" / "out"
    written = write_report(report, out, lang="ru")
    assert sorted(written.files) == sorted(p.name for p in out.iterdir()
                                           if p.name != MANIFEST)
    assert (out / "kkm-30.toml").read_text() == (cli / "kkm-30.toml").read_text()
    assert summary_lines(report, "ru", written) == stdout.replace(
        str(cli), str(out)).splitlines()
    assert "таблица 1: 7 строк" in stdout


def test_synthesis_rows_plural():
    from linkage.synthesis_report import _rows

    assert [_rows(n, "ru") for n in (3, 7, 21)] == ["3 строки", "7 строк", "21 строка"]
