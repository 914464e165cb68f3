"""End to end: ``crankdyn engine`` on both bundled examples in both languages; the
workbook read back with openpyxl equals the CSV; mm columns = N ÷ μP; every plot exists
and is not empty; bad input exits 2 with one line per problem and writes nothing; an
existing report is replaced only by a complete new one."""
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from openpyxl import load_workbook
from rendering import unrendered

import engine
from crankbase.output import MANIFEST_NAME
from crankdyn.cli import main
from crankbase.resources import example_path
from engine.plots import PLOT_NAMES, TRAIN_PLOT_NAMES
from engine.plots.bearing import BEARING_PLOT_NAMES
from engine.report import TABLE2_FORCES, TABLE2_KEYS

EXAMPLES = {"petrol": ("petrol_vaz2106.toml", "petrol-vaz2106.xlsx"),
            "diesel": ("diesel_d240.toml", "diesel-d240.xlsx"),
            "six": ("petrol_bmw_m54.toml", "petrol-bmw-m54b30.xlsx"),
            "v8": ("diesel_kamaz740.toml", "diesel-kamaz740.xlsx")}


def named(name, file):
    """An output of example ``name``: every file is named after the engine."""
    return f"{EXAMPLES[name][1][:-5]}_{file}"


def run_cli(*argv):
    return main(["engine", *map(str, argv)])


#: The runs with the bearings: the Russian V8 is the session's shared ``engine --example v8
#: --bearings`` (Russian, the default; tests/test_portable.py and the summary test below
#: read it too), its engine files the same as without the bearings, plus theirs.
BEARINGS = {("v8", "ru")}
BEARING_CSVS = ("crankpins.csv", "journals.csv", "journal_torques.csv", "rod_bearings.csv",
                "wear.csv")
#: The bearing sheets, between the engine's nine printed sheets and the hidden last one.
BEARING_SHEETS = 6


RUNS = [("petrol", "ru"), ("petrol", "en"), ("diesel", "ru"), ("diesel", "en"),
        ("six", "en"), ("v8", "ru"), ("v8", "en")]


def _shared(cli_report, name, lang):
    if (name, lang) in BEARINGS:
        return cli_report("engine", "--example", name, "--bearings")  # shared, read-only
    return cli_report("engine", "--example", name, "--lang", lang)   # shared, read-only


@pytest.fixture(scope="module", params=RUNS, ids=lambda p: "-".join(p))
def run(request, cli_report):
    name, lang = request.param
    rep = _shared(cli_report, name, lang)
    assert rep.rc == 0
    return name, lang, rep.folder


def test_outputs_exist(run):
    name, lang, out = run
    files = {p.name for p in out.iterdir()}
    expected = {named(name, f) for f in ("forces.csv", "table2.csv", "cylinders.csv",
                                         "torque.csv", "balance.csv")}
    expected |= {EXAMPLES[name][1], MANIFEST_NAME}
    expected |= {named(name, f"{s}.{e}") for s in PLOT_NAMES + TRAIN_PLOT_NAMES
                 for e in ("png", "svg")}
    if (name, lang) in BEARINGS:      # the V8 has no rod model: every other bearing plot
        expected |= {named(name, f) for f in BEARING_CSVS}
        expected |= {named(name, f"{s}.{e}") for s in BEARING_PLOT_NAMES
                     if s != "rod_model" for e in ("png", "svg")}
    assert files == expected          # nothing else (no temporary files left)


def test_csv_equals_force_table(run):
    name, lang, out = run
    df = pd.read_csv(out / named(name, "forces.csv"))
    study = engine.load(example_path(EXAMPLES[name][0]))
    t = engine.force_table(study.spec, settings=study.settings)
    assert list(df.columns) == list(engine.COLUMNS)
    np.testing.assert_array_equal(df.to_numpy(), t.to_numpy())   # full precision
    text = (out / named(name, "forces.csv")).read_text()
    assert text.splitlines()[0].startswith("alpha_deg,p_gas_MPa,dPg_N,Pj_N,P_N,beta_deg")
    assert ";" not in text


def test_csv_has_no_round_off_residues(run):
    """At TDC the piston speed and β are exactly 0 (not −2e-32 m/s and −0.0°); no CSV of
    the engine carries a round-off residue below 1e-12 of its column's scale, nor −0.0."""
    name, lang, out = run
    t = pd.read_csv(out / named(name, "forces.csv"))
    tdc = t[t["alpha_deg"] == 0.0].iloc[0]
    for col in ("v_m_s", "beta_deg", "x_mm", "N_N", "T_N", "M_Nm"):
        assert tdc[col] == 0.0 and not np.signbit(tdc[col]), col
    for csv in ("forces.csv", "torque.csv", "balance.csv", "table2.csv"):
        text = (out / named(name, csv)).read_text()
        assert not re.search(r"(^|,)-0\.0(,|$)", text, re.M), csv
        a = np.abs(pd.read_csv(out / named(name, csv)).to_numpy(float))
        tiny = (a > 0) & (a <= 1e-12 * a.max(axis=0))
        assert not tiny.any(), (csv, np.argwhere(tiny)[:3])


def test_workbook_equals_csv(run, loaded_workbook):
    name, lang, out = run
    df = pd.read_csv(out / named(name, "forces.csv"))
    wb = loaded_workbook(out / EXAMPLES[name][1])      # shared, read-only
    # 9 printed sheets (and the bearings'); the native charts' data (the fine grid) on a
    # hidden last one
    printed = 9 + (BEARING_SHEETS if (name, lang) in BEARINGS else 0)
    assert [ws.sheet_state for ws in wb.worksheets] == ["visible"] * printed + ["hidden"]
    ws_in, ws_t2, ws_sum, ws_data, ws_ch = wb.worksheets[:5]
    mu = engine.load(example_path(EXAMPLES[name][0])).settings.force_scale
    # Table 2: α, (mm, N) × 8 forces, Mкр, Ψ — numbers, not formulas
    assert ws_t2["C2"].value == mu
    n = len(df)
    # row 5 (hidden): the column keys, for `crankdyn check`; data from row 6
    assert ws_t2.row_dimensions[5].hidden
    assert [c.value for c in ws_t2[5]][:19] == list(TABLE2_KEYS)
    rows = list(ws_t2.iter_rows(min_row=6, max_row=5 + n, values_only=True))
    assert _value(ws_t2, 6 + n, 1) is None
    arr = np.array(rows, dtype=float)
    np.testing.assert_array_equal(arr[:, 0], df["alpha_deg"])
    for k, col in enumerate(TABLE2_FORCES):
        np.testing.assert_array_equal(arr[:, 2 + 2 * k], df[col])            # N
        np.testing.assert_allclose(arr[:, 1 + 2 * k], df[col] / mu, rtol=1e-15)  # mm
    np.testing.assert_array_equal(arr[:, 17], df["M_Nm"])
    np.testing.assert_array_equal(arr[:, 18], df["psi_deg"])
    for row in ws_t2.iter_rows(min_row=6, max_row=5 + n):
        for c in row:
            assert c.data_type == "n"
    # Data sheet: the CSV, header and values, at full precision
    assert [c.value for c in ws_data[3]][:len(df.columns)] == list(df.columns)
    data = np.array(list(ws_data.iter_rows(min_row=4, max_row=3 + n, max_col=len(df.columns),
                                           values_only=True)), dtype=float)
    np.testing.assert_array_equal(data, df.to_numpy())
    # native charts
    assert len(ws_ch._charts) == 5      # 4 over α and the polar diagram


def test_table2_layout_like_the_textbook(run, loaded_workbook):
    name, lang, out = run
    wb = loaded_workbook(out / EXAMPLES[name][1])      # shared, read-only
    ws = wb.worksheets[1]
    mm, nn = ("мм", "Н") if lang == "ru" else ("mm", "N")
    head = [ws.cell(3, c).value for c in range(1, 20)]
    sub = [ws.cell(4, c).value for c in range(1, 20)]
    assert head[0] == "α, °"
    symbols = (["ΔPг", "Pj", "P", "Sш", "N", "K", "T", "Rшш"] if lang == "ru" else
               ["ΔPg", "Pj", "P", "S", "N", "K", "T", "Rcp"])   # English: no Cyrillic
    assert [head[c] for c in range(1, 17, 2)] == symbols
    assert sub[1:17] == [mm, nn] * 8
    assert head[17].startswith("Mкр" if lang == "ru" else "M,") and head[18] == "Ψ, °"
    merged = {str(r) for r in ws.merged_cells.ranges}
    assert {"A3:A4", "B3:C3", "P3:Q3", "R3:R4", "S3:S4"} <= merged
    title = ws["A1"].value
    assert ("Таблица 2" in title) if lang == "ru" else ("Table 2" in title)
    # borders copied to every data row; one number format per column, about six
    # significant digits of its largest value (issue 23: no 0.0 / 0.00 / 0 in one table)
    from crankbase.workbook import number_format

    last = ws.max_row
    assert ws.cell(last, 3).border.left.style == "thin"
    for j in range(1, 20):
        column = [ws.cell(r, j) for r in range(6, last + 1)]
        assert {c.number_format for c in column} == {number_format(c.value for c in column)}


def test_inputs_and_summary_sheets(run, loaded_workbook):
    name, lang, out = run
    study = engine.load(example_path(EXAMPLES[name][0]))
    spec = study.spec
    wb = loaded_workbook(out / EXAMPLES[name][1])      # shared, read-only
    ws_in, ws_sum = wb.worksheets[0], wb.worksheets[2]
    vals = {r[0]: r[3] for r in ws_in.iter_rows(min_row=4, max_col=4, values_only=True)
            if r[0]}
    assert vals["bore_mm"] == pytest.approx(spec.bore * 1e3)
    assert vals["R_mm"] == pytest.approx(spec.R * 1e3)
    assert vals["L_mm"] == pytest.approx(spec.L * 1e3)
    assert vals["area_cm2"] == pytest.approx(spec.area * 1e4)
    assert vals["Vh_l"] == pytest.approx(spec.Vh * 1e3)
    assert vals["omega"] == pytest.approx(spec.omega)
    assert vals["mj"] == pytest.approx(spec.mj)
    assert vals["m_rod_rot"] == pytest.approx(spec.m_rod_rot)
    assert vals["Kr"] == pytest.approx(spec.Kr)
    assert vals["mu_P"] == study.settings.force_scale
    assert vals["pi"] > 0.5
    summ = engine.analyze(spec, study.settings).summary
    rows = {r[0]: r[3:7] for r in ws_sum.iter_rows(min_row=4, max_col=7, values_only=True)
            if r[0]}
    for col in ("P_N", "S_N", "N_N", "K_N", "T_N", "M_Nm", "R_N"):
        e = summ.extreme(col)
        assert tuple(rows[col]) == pytest.approx((e.max, e.alpha_max_deg, e.min,
                                                  e.alpha_min_deg))
    for key in ("M_mean_Nm", "R_mean_N", "chi", "p_max_MPa", "pi_MPa"):
        assert rows[key][0] == pytest.approx(getattr(summ, key))
    assert summ.chi == pytest.approx(summ.R_N.max / summ.R_mean_N)


def test_plots_exist_and_are_not_empty(run, cli_report):
    """Every plot of a shared report drawn (PNG and SVG) where its figures are rendered:
    the Russian runs (the V8's with its bearings) and the six's English one; the English
    petrol, diesel and V8 reports save theirs unrendered (tests/conftest.py
    UNRENDERED_REPORTS), each file by its name, and their Russian runs are rendered."""
    import matplotlib.image as mpimg

    name, lang, out = run
    bearings = tuple(s for s in BEARING_PLOT_NAMES if s != "rod_model") \
        if (name, lang) in BEARINGS else ()
    if not _shared(cli_report, name, lang).rendered:
        for stem in PLOT_NAMES + TRAIN_PLOT_NAMES + bearings:
            for ext in ("png", "svg"):
                assert unrendered(out / f"{named(name, stem)}.{ext}"), (stem, ext)
        others = [r for r in RUNS if r[0] == name and r != (name, lang)]
        assert others and all(_shared(cli_report, *r).rendered for r in others)
        return
    for stem in PLOT_NAMES + TRAIN_PLOT_NAMES + bearings:
        stem = named(name, stem)
        png = out / f"{stem}.png"
        img = mpimg.imread(png)
        assert img.shape[0] > 300 and img.shape[1] > 300
        assert np.std(img[..., :3]) > 0.05                 # not a blank canvas
        svg = (out / f"{stem}.svg").read_text()
        assert "<svg" in svg and svg.count("<path") > 10


def _value(ws, row, col):
    """A cell's value, read without creating the cell (``ws.cell`` creates an empty one,
    which would grow a shared workbook past its used range)."""
    return getattr(ws._cells.get((row, col)), "value", None)


def _block(ws, first_row, first_col, n_cols):
    rows = []
    r = first_row
    while _value(ws, r, first_col) is not None:
        rows.append([_value(ws, r, first_col + j) for j in range(n_cols)])
        r += 1
    return rows


def test_engine_csvs_equal_the_workbook_and_the_library(run, loaded_workbook):
    """cylinders.csv, torque.csv and balance.csv read back equal the workbook's Layout,
    Total torque and Balance sheets and the library's result, bit for bit."""
    name, lang, out = run
    study = engine.load(example_path(EXAMPLES[name][0]))
    res = engine.analyze_engine(study.spec, study.train, study.settings)
    cyl = pd.read_csv(out / named(name, "cylinders.csv"))
    tq = pd.read_csv(out / named(name, "torque.csv"))
    bal = pd.read_csv(out / named(name, "balance.csv"))
    assert list(cyl.columns) == ["cylinder", "bank", "throw", "axial_position_mm",
                                 "bank_angle_deg", "throw_angle_deg", "phase_deg"]
    n = study.spec.cylinders
    assert list(tq.columns) == (["alpha_deg"] + [f"M_{j}_Nm" for j in range(1, n + 1)]
                                + ["M_total_Nm"])
    parts = ("1", "2", "j", "r", "cw", "")
    assert list(bal.columns) == (["alpha_deg"] + [f"F{p}_{c}_N" for p in parts for c in "xy"]
                                 + [f"M{p}_{c}_Nm" for p in parts for c in "xy"])
    np.testing.assert_array_equal(cyl.to_numpy(), res.layout.cylinders.to_numpy())
    np.testing.assert_array_equal(tq.to_numpy(), res.torque.to_numpy())
    np.testing.assert_array_equal(bal.to_numpy(), res.balance.to_numpy())
    assert tq["alpha_deg"].iloc[-1] == study.spec.cycle_deg and bal["alpha_deg"].iloc[-1] == 360
    wb = loaded_workbook(out / EXAMPLES[name][1])      # shared, read-only
    ws_lay, ws_tq, ws_bal, ws_fw = wb.worksheets[5:9]
    np.testing.assert_array_equal(np.array(_block(ws_lay, 4, 1, 7), float), cyl.to_numpy())
    np.testing.assert_array_equal(np.array(_block(ws_tq, 4, n + 4, n + 2), float),
                                  tq.to_numpy())
    head = [r for r in range(1, ws_bal.max_row + 1) if ws_bal.cell(r, 1).value == "alpha_deg"]
    assert len(head) == 1
    np.testing.assert_array_equal(np.array(_block(ws_bal, head[0] + 1, 1, len(bal.columns)),
                                           float), bal.to_numpy())
    # the counterweights, in kg·mm, under their header
    cws = res.summary.counterweights
    head = [r for r in range(1, ws_bal.max_row + 1)
            if str(ws_bal.cell(r, 1).value).startswith("z ")]
    if cws:
        got = np.array(_block(ws_bal, head[0] + 1, 1, 3), float)
        np.testing.assert_allclose(got, [(c.z * 1e3, c.mr * 1e3, c.angle_deg) for c in cws])
        assert np.all(got[:, 1] < 1e4)          # kg·mm of a real counterweight
    # the textbook total-torque table: one firing interval for an even-firing engine
    table = np.array(_block(ws_tq, 4, 1, n + 2), float)
    assert table[-1, 0] == pytest.approx(720.0 / n)
    np.testing.assert_array_equal(table, res.torque_table.to_numpy())
    assert len(ws_tq._charts) == 1
    # flywheel sheet holds the summary's numbers
    fw = res.summary.flywheel
    values = [_value(ws_fw, r, 2) for r in range(3, 13)]
    assert values[0] == pytest.approx(fw.L_excess_J) and values[3] == pytest.approx(fw.J0_kgm2)
    if lang == "en":
        import re
        cyr = re.compile("[\u0400-\u04ff]")
        for ws in wb.worksheets:                  # every sheet, the template's included
            for row in ws.iter_rows(values_only=True):
                for v in row:
                    assert not (isinstance(v, str) and cyr.search(v)), (ws.title, v)


def test_terminal_summary(cli_report):
    """The terminal text of the petrol example in Russian and in English (the session's
    shared runs; that a run without ``--lang`` speaks Russian is checked on the shared
    ``engine --example v8 --bearings`` in the next test but one)."""
    text = cli_report("engine", "--example", "petrol", "--lang", "ru").out   # shared
    for word in ("pг max", "Mкр.ср", "Rшш max", "χ =", "среднее индикаторное давление"):
        assert word in text                    # Russian textbook symbols for ru
    text = cli_report("engine", "--example", "petrol", "--lang", "en").out   # shared
    for word in ("peak gas pressure", "P max", "T max", "M mean", "Rcp max", "chi", "petrol",
                 "firing order 1-3-4-2", "mu =", "excess work", "J0 =", "balance"):
        assert word in text


def test_readme_states_the_symbol_table():
    """The README's table of Russian and English symbols is engine.symbols' own."""
    from engine.symbols import correspondence
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    for en, ru, what in correspondence("en"):
        assert f"| {en} | {ru} | {what} |" in readme


def test_terminal_summary_speaks_the_report_language(cli_report):
    """The whole engine and its bearings (V8: flywheel, counterweights, every line) print
    in the report's language: no English word in a Russian run, no Cyrillic letter in an
    English one.  Russian: the CLI's run (the session's shared one).  English: the study's
    summary (the lines the CLI prints above its last one) and the CLI's own English
    terminal text, last line included, of the shared petrol run."""
    import re
    rep = cli_report("engine", "--example", "v8", "--bearings")      # shared, read-only
    assert rep.rc == 0
    text = rep.out
    for word in ("двигатель: 8 цил., V-образный, порядок работы 1-5-4-2-6-3-7-8",
                 "противовес", "маховик", "шатунные шейки", "коренные шейки", "дуги износа"):
        assert word in text
    summary, written = text.rsplit("записано: ", 1)   # the last line lists file names
    assert "diesel-kamaz740_journals.csv" in written
    words = set(re.findall(r"[A-Za-z]{3,}", summary.replace("diesel-kamaz740", "")))
    assert words <= {"max", "min"}, words
    report = engine.run_study(engine.load(example_path("diesel_kamaz740.toml")),
                              bearings=True)
    ru = report.summary_lines("ru")               # the study prints what the CLI printed
    assert summary.rstrip("\n").splitlines() == ru
    text = "\n".join(report.summary_lines("en"))
    assert not re.search("[\u0400-\u04ff]", text), text
    for word in ("whole engine: 8 cylinders vee", "counterweight", "most loaded"):
        assert word in text
    rep = cli_report("engine", "--example", "petrol", "--lang", "en")   # shared
    assert rep.rc == 0 and rep.out.splitlines()[-1].startswith("wrote ")
    assert not re.search("[\u0400-\u04ff]", rep.out), rep.out


def test_step_option_and_spec_path(tmp_path, unrendered_figures):
    """--step and a spec's path (the CSV read; the plots are built, not drawn)."""
    spec = example_path("diesel_d240.toml")
    assert run_cli(spec, "-o", tmp_path, "--step", 10, "--lang", "en") == 0
    df = pd.read_csv(tmp_path / "diesel-d240_forces.csv")
    assert len(df) == 73 + 1          # 0..720 every 10°, plus 375° (370° is on the grid)
    assert 375 in set(df["alpha_deg"])


def test_help_is_fast_and_lazy():
    code = ("import sys, crankdyn.cmd_engine as m, argparse; "
            "p = argparse.ArgumentParser(); m.add_parser(p.add_subparsers()); "
            "print(sorted(x for x in ('numpy', 'pandas', 'matplotlib', 'openpyxl', 'engine')"
            " if x in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "[]"


def test_engine_help(capsys):
    """``crankdyn engine --help`` (in this process: ``python -m crankdyn --help`` runs
    as a real process in tests/test_cli_linkage.py) exits 0 naming the options."""
    with pytest.raises(SystemExit) as exit_:
        main(["engine", "--help"])
    out = capsys.readouterr().out
    assert exit_.value.code == 0 and "--example" in out and "--lang" in out


# ------------------------------------------------------------------------ bad input

GOOD = """[engine]
name = "t"
bore_mm = 110
stroke_mm = 125
rod_ratio = 0.27
speed_rpm = 2000
[masses]
reciprocating_kg = 3
rod_rotating_kg = 1
[pressure]
angle_deg = [0, 360, 370]
p_MPa = [0.1, 6, 7]
[table]
force_scale_N_per_mm = 100
"""

BAD = {
    "lambda_zero": (GOOD.replace("rod_ratio = 0.27", "rod_ratio = 0"), ["engine.rod_ratio"]),
    "lambda_one": (GOOD.replace("rod_ratio = 0.27", "rod_ratio = 1"), ["engine.rod_ratio"]),
    "bore": (GOOD.replace("bore_mm = 110", "bore_mm = 0"), ["engine.bore_mm"]),
    "stroke": (GOOD.replace("stroke_mm = 125", "stroke_mm = -1"), ["engine.stroke_mm"]),
    "speed": (GOOD.replace("speed_rpm = 2000", "speed_rpm = 0"), ["engine.speed_rpm"]),
    "ratio_and_length": (GOOD.replace("rod_ratio = 0.27", "rod_ratio = 0.27\nrod_length_mm = 230"),
                         ["engine.rod_ratio"]),
    "no_masses": (GOOD.replace("[masses]\nreciprocating_kg = 3\nrod_rotating_kg = 1\n", ""),
                  ["masses"]),
    "no_pressure": (GOOD.replace("angle_deg = [0, 360, 370]\np_MPa = [0.1, 6, 7]\n", ""),
                    ["pressure"]),
    "pressure_twice": (GOOD.replace("p_MPa = [0.1, 6, 7]\n",
                                    "p_MPa = [0.1, 6, 7]\nfile = 'p.csv'\n"), ["pressure"]),
    "csv_no_column": (GOOD.replace("angle_deg = [0, 360, 370]\np_MPa = [0.1, 6, 7]\n",
                                   "file = 'nocol.csv'\n"), ["pressure.file"]),
    "csv_missing": (GOOD.replace("angle_deg = [0, 360, 370]\np_MPa = [0.1, 6, 7]\n",
                                 "file = 'missing.csv'\n"), ["pressure.file"]),
    "unknown_keys": (GOOD.replace("speed_rpm = 2000", "speed_rpm = 2000\nspeed = 1")
                     + "[colour]\nx = 1\n", ["engine.speed", "colour"]),
    "many": (GOOD.replace("bore_mm = 110", "bore_mm = -1").replace("speed_rpm = 2000",
                                                                  "speed_rpm = -5"),
             ["engine.bore_mm", "engine.speed_rpm"]),
    "toml_syntax": ("[engine\n", ["spec.toml"]),
    "v6_60_cannot_fire_evenly": (GOOD.replace("speed_rpm = 2000", "speed_rpm = 2000\n"
                                              "cylinders = 6\narrangement = \"vee\"\n"
                                              "vee_angle_deg = 60\n"
                                              "firing_order = [1, 4, 2, 5, 3, 6]"),
                                 ["engine.firing_order"]),
    "firing_order_not_a_permutation": (GOOD.replace("speed_rpm = 2000", "speed_rpm = 2000\n"
                                                    "cylinders = 4\n"
                                                    "firing_order = [1, 2, 2, 4]"),
                                       ["engine.firing_order"]),
    "vee_angle_out_of_range": (GOOD.replace("speed_rpm = 2000", "speed_rpm = 2000\n"
                                            "cylinders = 2\narrangement = \"vee\"\n"
                                            "vee_angle_deg = 200"),
                               ["engine.vee_angle_deg"]),
    "throws_count": (GOOD.replace("speed_rpm = 2000", "speed_rpm = 2000\ncylinders = 4\n"
                                  "throw_angles_deg = [0, 180]\nfiring_order = [1, 3, 4, 2]"),
                     ["engine.throw_angles_deg"]),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_input_exit_2_nothing_written(case, tmp_path, capsys):
    text, keys = BAD[case]
    (tmp_path / "p.csv").write_text("angle_deg,p_MPa\n0,0.1\n360,5\n")
    (tmp_path / "nocol.csv").write_text("angle_deg,pressure\n0,0.1\n360,5\n")
    spec = tmp_path / "spec.toml"
    spec.write_text(text)
    out = tmp_path / "out"
    assert run_cli(spec, "-o", out) == 2
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert "Traceback" not in err
    assert len(lines) == len(keys)
    for line, key in zip(sorted(lines), sorted(keys)):
        assert line.startswith("crankdyn engine: ошибка: ")          # a Russian run
        assert key in line
    assert not out.exists()


def test_bad_input_via_subprocess_has_no_traceback(tmp_path):
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD.replace("rod_ratio = 0.27", "rod_ratio = 1.5"))
    r = subprocess.run([sys.executable, "-m", "crankdyn", "engine", str(spec), "-o",
                        str(tmp_path / "out"), "--lang", "en"], capture_output=True,
                       text=True)
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == [
        "crankdyn engine: error: engine.rod_ratio: got 1.5; must be > 0 and < 1"]
    assert not (tmp_path / "out").exists()


def test_bad_input_in_russian_by_default(tmp_path, capsys):
    """A Russian run (the default) tells the same problem as the process above, in
    Russian (in this process: the exit status and the clean stderr of a real process are
    the test above's)."""
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD.replace("rod_ratio = 0.27", "rod_ratio = 1.5"))
    assert run_cli(spec, "-o", tmp_path / "out") == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "crankdyn engine: ошибка: engine.rod_ratio: получено 1.5; должно быть > 0 и < 1"]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("argv", [
    ["--example", "nope"],
    [],
    ["--example", "petrol", "--step", "0"],
    ["--example", "petrol", "--step", "nan"],
    ["SPEC", "--example", "petrol"],
])
def test_bad_arguments(argv, tmp_path, capsys):
    argv = [str(tmp_path / "x.toml") if a == "SPEC" else a for a in argv]
    assert run_cli(*argv, "-o", tmp_path / "out") == 2
    err = capsys.readouterr().err
    assert err.startswith("crankdyn engine: ошибка: ") and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


def _snapshot(folder):
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_existing_report_survives_bad_input(tmp_path, cli_report):
    out = tmp_path / "out"          # a copy of the session's diesel report (--lang ru)
    shutil.copytree(cli_report("engine", "--example", "diesel", "--lang", "ru").folder, out)
    before = _snapshot(out)
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD.replace("name = \"t\"", "name = \"diesel-d240\"")
                    .replace("bore_mm = 110", "bore_mm = 0"))
    assert run_cli(spec, "-o", out) == 2
    assert _snapshot(out) == before


def test_existing_report_survives_a_crash_while_saving(tmp_path, monkeypatch, capsys,
                                                      cli_report, unrendered_figures):
    """A failure in the middle of saving the workbook leaves the old workbook whole and
    no temporary file behind.  (The failing run's plots are not drawn: a placeholder
    written over one of the old report's real plots would differ from it byte for
    byte.)"""
    out = tmp_path / "out"          # a copy of the session's petrol report (--lang ru)
    shutil.copytree(cli_report("engine", "--example", "petrol", "--lang", "ru").folder, out)
    before = _snapshot(out)
    import openpyxl.workbook.workbook as wbmod

    def broken_save(self, filename):
        Path(filename).write_bytes(b"partial")
        raise OSError("disk full")

    monkeypatch.setattr(wbmod.Workbook, "save", broken_save)
    assert run_cli("--example", "petrol", "-o", out, "--lang", "en") == 2
    assert f"cannot write the report into {out}: disk full" in capsys.readouterr().err
    after = _snapshot(out)
    assert after["petrol-vaz2106.xlsx"] == before["petrol-vaz2106.xlsx"]
    assert set(after) == set(before)
    load_workbook(out / "petrol-vaz2106.xlsx")     # still a valid workbook


def test_output_may_not_overwrite_an_input(tmp_path, capsys):
    (tmp_path / "t_forces.csv").write_text("angle_deg,p_MPa\n0,0.1\n360,5\n")
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD.replace("angle_deg = [0, 360, 370]\np_MPa = [0.1, 6, 7]\n",
                                 "file = 't_forces.csv'\n"))
    before = (tmp_path / "t_forces.csv").read_text()
    assert run_cli(spec, "--lang", "en", "-o", tmp_path) == 2
    assert "input" in capsys.readouterr().err
    assert (tmp_path / "t_forces.csv").read_text() == before


def test_name_is_text_not_formula(tmp_path, unrendered_figures):
    """A name starting with ``=`` is a text cell, and a file name (the workbook read; the
    plots are built, not drawn: test_two_stroke_engine_end_to_end renders this spec's)."""
    spec = tmp_path / "spec.toml"
    spec.write_text(GOOD.replace('name = "t"', 'name = "=1+1"'))
    assert run_cli(spec, "-o", tmp_path / "o") == 0
    files = [p.name for p in (tmp_path / "o").iterdir() if p.suffix == ".xlsx"]
    assert files == ["1_1.xlsx"]
    wb = load_workbook(tmp_path / "o" / files[0])
    vals = {r[0]: r[3] for r in wb.worksheets[0].iter_rows(min_row=4, max_col=4,
                                                           values_only=True) if r[0]}
    assert vals["name"] == "=1+1"
    assert wb.worksheets[0].cell(4, 4).data_type == "s"


def test_two_stroke_engine_end_to_end(tmp_path, figures_rendered_only):
    """A two-stroke engine (a 360° cycle) end to end, its 13 plots rendered as PNG (each
    a real image; the SVGs saved unrendered: the same plots of the four-stroke examples
    are rendered as SVG in the session's shared reports,
    test_plots_exist_and_are_not_empty)."""
    saved = figures_rendered_only(".png")
    spec = tmp_path / "two.toml"
    spec.write_text(GOOD.replace("name = \"t\"", "name = \"two-stroke\"\nstrokes = 2")
                    .replace("angle_deg = [0, 360, 370]\np_MPa = [0.1, 6, 7]",
                             "angle_deg = [0, 10, 120, 180, 240, 350]\n"
                             "p_MPa = [5.5, 6.0, 0.5, 0.1, 0.3, 2.5]"))
    assert run_cli(spec, "-o", tmp_path / "o", "--step", 15) == 0
    df = pd.read_csv(tmp_path / "o" / "two-stroke_forces.csv")
    assert df["alpha_deg"].iloc[-1] == 360 and len(df) == 25
    assert (tmp_path / "o" / "two-stroke_polar_Rshsh.png").stat().st_size > 10000
    drawn = [name for name, rendered in saved if rendered]
    assert len(drawn) == len(saved) // 2 == len(PLOT_NAMES + TRAIN_PLOT_NAMES)
    for stem in PLOT_NAMES + TRAIN_PLOT_NAMES:
        png = (tmp_path / "o" / f"two-stroke_{stem}.png").read_bytes()
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10000, stem


def test_chinese_summary_and_cli_run(tmp_path, capsys, unrendered_figures):
    """Issue #19: a Chinese run (``--lang zh``) prints Chinese: no Cyrillic letter, no
    English word beyond the Latin symbols and units, the same numbers as the English
    summary; its workbook is the Chinese template (Chinese sheet names and labels).
    (The CLI run's figures are built, not drawn: the petrol's Chinese figures are drawn
    and checked in tests/test_figures_clean.py.)"""
    import re

    from openpyxl import load_workbook

    report = engine.run_study(engine.load(example_path("diesel_kamaz740.toml")),
                              bearings=True)
    zh, en = report.summary_lines("zh"), report.summary_lines("en")
    text = "\n".join(zh)
    assert not re.search("[\u0400-\u04ff]", text), text
    words = set(re.findall(r"[A-Za-z]{3,}", text.replace("diesel-kamaz740", "")))
    assert words <= {"max", "min", "MPa"}, words                # symbols, units
    for word in ("整机：8 缸", "平衡重", "飞轮", "曲柄销", "主轴颈"):
        assert word in text, word
    num = re.compile(r"-?\d+\.\d+")
    assert num.findall(text) == num.findall("\n".join(en)) and num.findall(text)
    # the CLI in Chinese
    assert run_cli("--example", "-o", tmp_path, "--lang", "zh") == 0
    out = capsys.readouterr().out
    assert not re.search("[\u0400-\u04ff]", out), out
    assert out.splitlines()[-1].startswith("已写入：")
    assert len(unrendered_figures) == 26                   # 13 plots, PNG and SVG
    wb = load_workbook(tmp_path / "petrol-vaz2106.xlsx")
    assert [ws.title for ws in wb.worksheets][:3] == ["输入数据", "表 2", "汇总"]
    cells = [v for ws in wb.worksheets for row in ws.iter_rows(values_only=True)
             for v in row if isinstance(v, str)]
    assert "活塞行程" in cells and "曲柄销载荷" in cells
    assert not any(re.search("[\u0400-\u04ff]", v) for v in cells)
