"""End-to-end: `crankdyn linkage` on the bundled examples; workbook read back = CSV in
both languages; the Russian report in Russian (sheet titles, labels, units, symbols Mур,
Mпс, terminal summary), the English one without a Cyrillic letter; bad input exits 2
with one line per problem and writes nothing."""
import math
import re
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
from openpyxl import load_workbook

from crankdyn.cli import main
from crankbase.resources import example_path

#: The sheets in their order; their titles are in the report's language.
SHEETS = ("inputs", "positions", "velocities", "accelerations", "loads", "forces",
          "extremes")
TITLES = {"en": SHEETS,
          "ru": ("Исходные данные", "Положения", "Скорости", "Ускорения", "Нагрузки",
                 "Реакции и Mур", "Крайние положения")}
CYRILLIC = re.compile("[\u0400-\u04FF]")
PLOTS = ("plan", "velocities", "accelerations", "driving_moment", "transmission_angle")


def _one(folder, tail):
    """The one output in ``folder`` named ``<mechanism>_<tail>`` (issue 14: every output
    is named after the mechanism, so two runs into one folder never mix)."""
    found = [p for p in folder.iterdir() if p.name.endswith("_" + tail)]
    assert len(found) == 1, (tail, sorted(p.name for p in folder.iterdir()))
    return found[0]


def _sheet_frame(ws):
    """A sheet's table as a DataFrame keyed by the CSV column names (header row 3)."""
    rows = list(ws.iter_rows(values_only=True))
    cols = rows[2]
    data = [r for r in rows[3:] if any(v is not None for v in r)]
    return pd.DataFrame(data, columns=cols)


def _sheet(wb, key):
    """A workbook's sheet by its place (``key`` in SHEETS), whatever the language."""
    return wb.worksheets[SHEETS.index(key)]


@pytest.fixture(scope="module")
def ratchet_run(cli_report):
    rep = cli_report("linkage", "--example")          # shared, read-only
    assert rep.rc == 0
    return rep.folder


@pytest.fixture(scope="module")
def lang_runs(cli_report):
    """Both bundled examples in both languages (tables only; the session's shared
    ``crankdyn linkage --example EX --no-plots --lang LANG`` runs, read-only, which
    tests/test_reports_workbooks.py reads too): (example, lang) → (folder, terminal
    stdout, stderr)."""
    out = {}
    for ex in ("ratchet", "press"):
        for lang in ("ru", "en"):
            rep = cli_report("linkage", "--example", ex, "--no-plots", "--lang", lang)
            assert rep.rc == 0, rep.err
            out[(ex, lang)] = (rep.folder, rep.out, rep.err)
    return out


def test_outputs_exist_and_are_not_empty(ratchet_run):
    for name in ["ratchet-drive_kinematics.csv", "ratchet-drive_forces.csv",
                 "ratchet-drive.xlsx"] + [f"ratchet-drive_{p}.png" for p in PLOTS]:
        f = ratchet_run / name
        assert f.is_file() and f.stat().st_size > 1000, name
    # no staging leftovers beside the output folder
    assert not [p for p in ratchet_run.parent.iterdir() if ".staging." in p.name]


def test_csv_has_the_contract_columns_and_rows(ratchet_run):
    k = pd.read_csv(_one(ratchet_run, "kinematics.csv"))
    f = pd.read_csv(_one(ratchet_run, "forces.csv"))
    assert len(k) == len(f) == 12  # positions = 12 gives exactly 12 rows
    assert list(k["position"]) == list(range(1, 13))
    for c in ("phi_deg", "theta3_deg", "omega3_rad_s", "eps3_rad_s2", "theta4_deg",
              "omega4_rad_s", "eps4_rad_s2", "mu_deg", "E_x_m", "S3_ay_m_s2", "B_vx_m_s"):
        assert c in k.columns, c
    for c in ("R12_x_N", "R23_y_N", "R43_x_N", "R14_y_N", "M_drive_Nm", "R23_n_N",
              "R23_t_N", "R14_n_N", "R14_t_N"):
        assert c in f.columns, c


def test_csv_is_full_precision(ratchet_run):
    """The CSV round-trips the analysis to the last bit (other programs compare at 1e-6)."""
    import linkage

    res = linkage.analyze(example_path("ratchet.toml"))
    k = pd.read_csv(_one(ratchet_run, "kinematics.csv"))
    f = pd.read_csv(_one(ratchet_run, "forces.csv"))
    num = [c for c in res.kinematics.columns if c != "position"]
    np.testing.assert_array_equal(k[num].to_numpy(), res.kinematics[num].to_numpy())
    num = [c for c in res.forces.columns if c != "position"]
    np.testing.assert_array_equal(f[num].to_numpy(), res.forces[num].to_numpy())


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_workbook_read_back_equals_csv(lang_runs, lang, loaded_workbook):
    """Every number of the workbook equals the CSV to the last bit, in either language."""
    run = lang_runs[("ratchet", lang)][0]
    wb = loaded_workbook(run / "ratchet-drive.xlsx")            # shared, read-only
    assert tuple(wb.sheetnames) == TITLES[lang]
    k = pd.read_csv(_one(run, "kinematics.csv"))
    f = pd.read_csv(_one(run, "forces.csv"))
    seen = set()
    for sheet in ("positions", "velocities", "accelerations"):
        df = _sheet_frame(_sheet(wb, sheet))
        for c in df.columns:
            np.testing.assert_array_equal(df[c].to_numpy(float), k[c].to_numpy(float))
            seen.add(c)
    assert seen == set(k.columns)  # every kinematics column is on some sheet
    seen = set()
    for sheet in ("loads", "forces"):
        df = _sheet_frame(_sheet(wb, sheet))
        assert list(df.columns[:2]) == ["position", "phi_deg"]
        for c in df.columns:
            np.testing.assert_array_equal(df[c].to_numpy(float), f[c].to_numpy(float))
            seen.add(c)
    assert seen == set(f.columns)  # every force column is on some sheet
    # the course tables' magnitudes come first on the velocities sheet
    vel = list(_sheet_frame(_sheet(wb, "velocities")).columns)
    assert vel.index("v_BA_m_s") < vel.index("A_vx_m_s")
    assert {"G3_N", "Fu3_N", "Mu3_Nm", "M_res_Nm"} <= set(
        _sheet_frame(_sheet(wb, "loads")).columns)
    assert "Fu3_N" not in _sheet_frame(_sheet(wb, "forces")).columns


#: Labels of the inputs sheet by language: Grashof type, swing, K, extremes' stroke names.
INPUT_LABELS = {
    "en": ("Grashof type", "crank-rocker", "rocker swing",
           "time-ratio coefficient K = φwork/φidle", ["working start", "working end"]),
    "ru": ("Тип механизма по Грасгофу", "кривошипно-коромысловый", "угол размаха коромысла",
           "коэффициент изменения средней скорости выходного звена K = φр.х/φх.х",
           ["начало рабочего хода", "конец рабочего хода"]),
}


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_workbook_inputs_and_extremes(lang_runs, lang, loaded_workbook):
    run = lang_runs[("ratchet", lang)][0]
    grashof, crank_rocker, swing, K, strokes = INPUT_LABELS[lang]
    wb = loaded_workbook(run / "ratchet-drive.xlsx")            # shared, read-only
    rows = [r for r in _sheet(wb, "inputs").iter_rows(values_only=True) if r and r[0]]
    values = {r[0]: r[1] for r in rows}
    units = {r[0]: r[2] for r in rows}
    assert values["mechanism.crank"] == 0.175
    assert values["links.coupler.inertia_kg_m2"] == 0.51
    assert units["mechanism.crank"] == {"ru": "м", "en": "m"}[lang]
    assert units["links.coupler.inertia_kg_m2"] == {"ru": "кг·м²", "en": "kg·m²"}[lang]
    assert units["links.coupler.mass_kg"] == {"ru": "кг", "en": "kg"}[lang]
    assert units["load[0].resistance_Nm"] == {"ru": "Н·м", "en": "N·m"}[lang]
    assert values[grashof] == crank_rocker
    # seed 000 / domain.md §2: with OC = 0.54 m, swing ≈ 68.4°, K ≈ 1.138
    assert values[swing] == pytest.approx(68.4, abs=0.05)
    assert values[K] == pytest.approx(1.138, abs=5e-4)
    # the extremes sheet lists one quantity per row (readable on A4): transpose it back
    rows = list(_sheet(wb, "extremes").iter_rows(min_row=2, values_only=True))
    ext = pd.DataFrame({r[2]: list(r[3:]) for r in rows})
    assert list(ext["label"]) == strokes
    # the rocker stands still at both extreme positions
    assert np.abs(ext["omega4_rad_s"].to_numpy(float)).max() < 1e-9
    # position 1 is the working-stroke start
    k = pd.read_csv(_one(run, "kinematics.csv"))
    assert ext["phi_deg"].iat[0] == pytest.approx(k["phi_deg"].iat[0], abs=1e-9)


def test_example_names_are_the_commands_own(tmp_path, capsys):
    """--example lists and accepts only linkage examples, by name: an engine example is
    refused naming the linkage ones, and nothing is written."""
    assert main(["linkage", "--lang", "en",
                 "--example", "petrol_vaz2106", "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["crankdyn linkage: error: --example: no linkage example "
                   "'petrol_vaz2106'; available: ratchet, press, shaper, press6, "
                   "compressor_v, sixbar_rrr, shaper_cn"]
    assert not (tmp_path / "o").exists()
    with pytest.raises(SystemExit):
        main(["linkage", "--lang", "en", "--help"])
    assert "ratchet, press" in " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize("name", ["ratchet", "press", "ratchet.toml"])
def test_every_bundled_linkage_example_runs(name, cli_report, tmp_path):
    """Each example by its name and by its file name.  The ratchet's plots are those of
    the session's shared run of the default example (the ratchet, rendered once); a run
    that names it (``ratchet``, ``ratchet.toml``) writes the tables only, and they are
    that run's byte for byte."""
    shared = ("linkage", "--example", "press") if name == "press" else \
        ("linkage", "--example")
    rep = cli_report(*shared)                           # shared, read-only
    assert rep.rc == 0
    out = rep.folder
    for p in PLOTS:
        assert _one(out, f"{p}.png").stat().st_size > 1000
    k = pd.read_csv(_one(out, "kinematics.csv"))
    assert len(k) == 12 and list(k["position"]) == list(range(1, 13))
    if name != "press":
        named = tmp_path / "named"
        assert main(["linkage", "--example", name, "-o", str(named), "--no-plots"]) == 0
        for tail in ("kinematics.csv", "forces.csv"):
            assert _one(named, tail).read_bytes() == _one(out, tail).read_bytes(), tail


def test_explicit_angles_crank_slider(tmp_path, unrendered_figures):
    """(The tables and the workbook are checked; the plots are built, not drawn: the
    press example's, a crank-slider's, are rendered in the shared run above.)"""
    spec = tmp_path / "slider.toml"
    spec.write_text("""
[mechanism]
kind = "crank-slider"
name = "press"
crank = 0.1
coupler = 0.4
offset = 0.02
omega_rad_s = -30.0
[links.slider]
mass_kg = 5.0
[[load]]
link = "slider"
resistance_N = 800.0
stroke = "both"
[analysis]
crank_angles_deg = [10.0, 200.0, 90.0]
""")
    out = tmp_path / "out"
    assert main(["linkage", str(spec), "-o", str(out)]) == 0
    k = pd.read_csv(_one(out, "kinematics.csv"))
    f = pd.read_csv(_one(out, "forces.csv"))
    assert list(k["phi_deg"]) == [10.0, 200.0, 90.0]   # one row each, in the order given
    assert k["position"].isna().all()                 # empty for explicit angles
    for c in ("s4_m", "v4_m_s", "a4_m_s2"):
        assert c in k.columns
    for c in ("M14_Nm", "N14_N", "F_res_N"):
        assert c in f.columns
    # the resistance opposes the slider's velocity
    assert np.all(np.sign(f["F_res_N"]) == -np.sign(k["v4_m_s"]))
    wb = load_workbook(out / "press.xlsx")
    df = _sheet_frame(_sheet(wb, "forces"))
    assert df["position"].isna().all()


BAD_SPECS = {
    "negative length and unknown key": ("""
[mechanism]
kind = "crank-rocker"
crank = -0.1
coupler = 0.5
rocker = 0.3
ground = 0.5
omega_rad_s = 10
colour = "red"
[analysis]
crank_angles_deg = [0.0]
""", ["mechanism.crank", "mechanism.colour"]),
    "cannot turn fully": ("""
[mechanism]
kind = "crank-rocker"
crank = 0.4
coupler = 0.5
rocker = 0.3
ground = 0.5
omega_rad_s = 10
[analysis]
crank_angles_deg = [0.0]
""", ["cannot turn fully"]),
    "positions and angles": ("""
[mechanism]
kind = "crank-slider"
crank = 0.1
coupler = 0.3
omega_rad_s = 10
[links.rocker]
mass_kg = 1.0
[links.slider]
mass_kg = -1.0
[analysis]
positions = 8
crank_angles_deg = [0.0]
working_stroke = "away"
""", ["links.rocker", "links.slider.mass_kg", "analysis"]),
}


@pytest.mark.parametrize("case", list(BAD_SPECS))
def test_bad_input_exit_2_one_line_per_problem_nothing_written(case, tmp_path, capsys):
    text, expected = BAD_SPECS[case]
    spec = tmp_path / "bad.toml"
    spec.write_text(text)
    out = tmp_path / "out"
    assert main(["linkage", "--lang", "en", str(spec), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    lines = [l for l in err.splitlines() if l.strip()]
    assert all(l.startswith("crankdyn linkage: error: ") for l in lines)
    assert "Traceback" not in err
    for key in expected:
        assert any(key in l for l in lines), (key, lines)
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


def test_missing_spec_file(tmp_path, capsys):
    assert main(["linkage", str(tmp_path / "nope.toml"), "-o", str(tmp_path / "o"),
                 "--lang", "en"]) == 2
    assert "does not exist" in capsys.readouterr().err
    assert main(["linkage", str(tmp_path / "nope.toml"), "-o", str(tmp_path / "o")]) == 2
    assert "файл задания не существует" in capsys.readouterr().err   # the default: ru
    assert not (tmp_path / "o").exists()


def test_existing_report_replaced_only_when_complete(tmp_path, monkeypatch):
    out = tmp_path / "out"
    assert main(["linkage", "--example", "-o", str(out), "--no-plots"]) == 0
    before = (_one(out, "forces.csv")).read_bytes()
    import linkage.report as report

    def boom(*a, **k):
        raise RuntimeError("disk full")
    monkeypatch.setattr(report, "write_workbook", boom)
    with pytest.raises(RuntimeError):
        main(["linkage", "--example", "-o", str(out), "--no-plots"])
    assert (_one(out, "forces.csv")).read_bytes() == before
    assert not [p for p in tmp_path.iterdir() if ".staging." in p.name]


def test_cli_subprocess_help_and_error_no_traceback(tmp_path):
    r = subprocess.run([sys.executable, "-m", "crankdyn", "--help"], capture_output=True,
                       text=True)
    assert r.returncode == 0 and "linkage" in r.stdout
    bad = tmp_path / "bad.toml"
    bad.write_text("[mechanism\n")
    r = subprocess.run([sys.executable, "-m", "crankdyn", "linkage", str(bad), "-o",
                        str(tmp_path / "o"), "--lang", "en"], capture_output=True, text=True)
    assert r.returncode == 2
    assert "not valid TOML" in r.stderr and "Traceback" not in r.stderr


def test_core_import_is_light():
    """Importing the computational core must not import matplotlib or openpyxl."""
    code = ("import sys, linkage, linkage.groups, linkage.analysis; "
            "bad = [m for m in ('matplotlib', 'openpyxl') if m in sys.modules]; "
            "print(','.join(bad))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == ""


def test_help_imports_nothing_heavy():
    code = ("import sys\nfrom crankdyn.cli import build_parser\nbuild_parser()\n"
            "print(','.join(m for m in ('numpy', 'pandas', 'matplotlib', 'openpyxl') "
            "if m in sys.modules))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == ""


def test_statics_run_at_explicit_angles(tmp_path, capsys):
    """ω = 0: a static force analysis at the given crank angles.  The velocity plot (and,
    with ε = 0, the acceleration plot) would be flat zeros and is not written; the
    terminal says statics; the driving moment is the static one (here the rhombus of
    tests/test_linkage_published.py without its string: 3·W·a at −60°)."""
    a, W, g = 0.5, 100.0, 9.81
    rod = f"mass_kg = {W / g!r}\ncg = [{a / 2}, 0.0]\n"
    spec = tmp_path / "rhombus.toml"
    spec.write_text(f"""
[mechanism]
kind = "crank-rocker"
name = "rhombus"
crank = {a}
coupler = {a}
rocker = {a}
ground = {a}
assembly = -1
omega_rad_s = 0.0
gravity_m_s2 = {g}
[links.crank]
{rod}[links.coupler]
{rod}[links.rocker]
{rod}[[load]]
link = "crank"
at = [{a}, 0.0]
force_N = [0.0, {-4 * W}]
[analysis]
crank_angles_deg = [300.0, 290.0]
""")
    out = tmp_path / "out"
    assert main(["linkage", str(spec), "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "статика, ω = 0" in text and "<NA>" not in text          # --lang ru
    for p in ("plan", "driving_moment", "transmission_angle"):
        assert _one(out, f"{p}.png").stat().st_size > 1000
    assert not list(out.glob("*_velocities.png")) and not list(out.glob("*_accelerations.png"))
    f = pd.read_csv(_one(out, "forces.csv"))
    assert f["M_drive_Nm"].iat[0] == pytest.approx(3 * W * a, rel=1e-12)
    k = pd.read_csv(_one(out, "kinematics.csv"))
    assert (k["omega3_rad_s"] == 0).all() and (k["B_a_m_s2"] == 0).all()
    wb = load_workbook(out / "rhombus.xlsx")
    assert len(wb.worksheets) == len(SHEETS) - 1   # no extremes without rotation


# ------------------------------------------------------------ the report's language
def _workbook_strings(path, load=load_workbook):
    """Every text of a workbook: sheet names and string cells, (where, text); ``load``:
    how the workbook is loaded (the session's ``loaded_workbook`` for a shared one)."""
    wb = load(path)
    for ws in wb.worksheets:
        yield ws.title, ws.title
        for row in ws.iter_rows():
            for c in row:
                if isinstance(c.value, str):
                    yield f"{ws.title}!{c.coordinate}", c.value


def test_english_report_has_no_cyrillic(lang_runs, loaded_workbook):
    """An English user sees no Cyrillic letter: not in the workbook (cells, sheet names,
    the raw XML parts as well), not on the terminal."""
    import zipfile

    for ex in ("ratchet", "press"):
        run, out, err = lang_runs[(ex, "en")]
        path = next(run.glob("*.xlsx"))
        bad = [(w, v) for w, v in _workbook_strings(path, loaded_workbook)
               if CYRILLIC.search(v)]
        assert not bad, (ex, bad[:5])
        with zipfile.ZipFile(path) as z:
            for name in z.namelist():
                assert not CYRILLIC.search(z.read(name).decode("utf-8", "replace")), name
        assert not CYRILLIC.search(out + err), (ex, out, err)
        assert "max |Mb| at the positions" in out


def _symbol_rows(wb):
    """Symbol row, unit row and CSV-name row of every table sheet, by sheet place."""
    out = {}
    for key, ws in zip(SHEETS[1:6], wb.worksheets[1:6]):
        rows = list(ws.iter_rows(min_row=1, max_row=3, values_only=True))
        out[key] = rows
    return out


#: Column → (Russian, English) symbol: the textbook's and the English set of the
#: project (linkage.report's docstring; seed 000 tables 3.1, 3.2, 4.1 for the Russian).
EXPECTED_SYMBOLS = {
    "M_drive_Nm": ("Mур", "Mb"), "M_res_Nm": ("Mпс", "Mr"), "Fu3_N": ("Fи3", "Fi3"),
    "Fu3_x_N": ("Fи3x", "Fi3x"), "Mu3_Nm": ("Mи3", "Mi3"), "v_BA_m_s": ("VBA", "VBA"),
    "B_v_m_s": ("VB", "VB"), "a_BA_n_m_s2": ("aBAⁿ", "aBAⁿ"), "a_BA_t_m_s2": ("aBAᵗ", "aBAᵗ"),
    "omega3_rad_s": ("ω3", "ω3"), "R23_n_N": ("R23n", "R23n"), "G3_N": ("G3", "G3"),
    "position": ("№", "No."),
}
EXPECTED_UNITS = {
    "M_drive_Nm": ("Н·м", "N·m"), "Fu3_N": ("Н", "N"), "B_v_m_s": ("м/с", "m/s"),
    "a_BA_n_m_s2": ("м/с²", "m/s²"), "omega3_rad_s": ("рад/с", "rad/s"),
    "eps3_rad_s2": ("рад/с²", "rad/s²"), "E_x_m": ("м", "m"), "phi_deg": ("°", "°"),
}


def test_workbook_symbols_units_and_numbers_in_both_languages(lang_runs, loaded_workbook):
    """The Russian workbook carries the Russian textbook symbols and units, the English
    one the English set; the CSV-name row and every number are identical in both (and
    equal the CSV to the last bit: test_workbook_read_back_equals_csv)."""
    for ex in ("ratchet", "press"):
        # the shared runs' workbooks (read-only)
        wr = loaded_workbook(next(lang_runs[(ex, "ru")][0].glob("*.xlsx")))
        we = loaded_workbook(next(lang_runs[(ex, "en")][0].glob("*.xlsx")))
        ru, en = _symbol_rows(wr), _symbol_rows(we)
        found = {}
        for key in ru:
            assert ru[key][2] == en[key][2], (ex, key)          # CSV names: the same
            for j, col in enumerate(ru[key][2]):
                found[col] = ((ru[key][0][j], en[key][0][j]), (ru[key][1][j], en[key][1][j]))
            for unit in ru[key][1]:                              # no English unit left
                assert unit in (None, "°") or CYRILLIC.search(unit), (ex, key, unit)
        for col, (r, e) in EXPECTED_SYMBOLS.items():
            if col in found:
                assert found[col][0] == (r, e), (ex, col, found[col][0])
        for col, (r, e) in EXPECTED_UNITS.items():
            if col in found:
                assert found[col][1] == (r, e), (ex, col, found[col][1])
        if ex == "ratchet":
            assert set(EXPECTED_SYMBOLS) <= set(found)
        else:                                                   # the slider's resistance
            assert found["F_res_N"] == (("Fпс", "Fr"), ("Н", "N"))
        # every number of every sheet, cell by cell, is the same in both languages
        assert len(wr.worksheets) == len(we.worksheets)
        for a, b in zip(wr.worksheets[1:], we.worksheets[1:]):
            na = [(c.coordinate, c.value) for r in a.iter_rows() for c in r
                  if isinstance(c.value, (int, float))]
            nb = [(c.coordinate, c.value) for r in b.iter_rows() for c in r
                  if isinstance(c.value, (int, float))]
            assert na == nb and len(na) > 20, (ex, a.title)
        va = [r[1] for r in wr.worksheets[0].iter_rows(values_only=True)
              if isinstance(r[1] if len(r) > 1 else None, float)]
        vb = [r[1] for r in we.worksheets[0].iter_rows(values_only=True)
              if isinstance(r[1] if len(r) > 1 else None, float)]
        assert va == vb                                          # the inputs sheet too


def test_column_label_is_the_one_table():
    """column_label(col, lang) gives every symbol; the English set is the one the
    English plots and plan drawings use (Mb, Mr, Fr, Fi, Mi), without Cyrillic."""
    from linkage.plots import _text
    PLOT_TEXT = {lang: _text(lang) for lang in ("en", "ru")}     # the plot.linkage.* texts
    from linkage.report import column_label, unit_text

    assert column_label("M_drive_Nm", "ru") == ("Mур", "Н·м")
    assert column_label("M_drive_Nm", "en") == ("Mb", "N·m")
    assert column_label("F_res_N", "ru") == ("Fпс", "Н")
    assert column_label("Mu4_Nm", "ru") == ("Mи4", "Н·м")
    assert column_label("B_vx_m_s", "ru") == ("VBx", "м/с")
    assert column_label("a_BC_t_m_s2", "en") == ("aBCᵗ", "m/s²")
    assert unit_text("kg·m²", "ru") == "кг·м²"
    with pytest.raises(ValueError, match="lang"):
        column_label("M_drive_Nm", "de")
    # the plots of the same report: "Mb, balancing …", "Mr, resistance …"
    assert PLOT_TEXT["en"]["Md"].split(",")[0] == column_label("M_drive_Nm", "en")[0]
    assert PLOT_TEXT["en"]["Mr"].split(",")[0] == column_label("M_res_Nm", "en")[0]
    assert PLOT_TEXT["ru"]["Md"].split(",")[0] == column_label("M_drive_Nm", "ru")[0]
    assert PLOT_TEXT["ru"]["Mr"].split(",")[0] == column_label("M_res_Nm", "ru")[0]
    # the plan drawings (force polygons): Fres → Fr / Fпс, Fu3 → Fi₃ / Fи₃
    import linkage
    import plans

    res = linkage.analyze(example_path("press.toml"))
    poly = plans.build_plans(res, [2])[0].plans["force_dyad"]
    sub = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
    labels = {v.name: (v.label_ru.translate(sub), v.label_en.translate(sub))
              for v in poly.vectors}
    assert labels["Fres"] == (column_label("F_res_N", "ru")[0], column_label("F_res_N", "en")[0])
    assert labels["Fu3"] == (column_label("Fu3_N", "ru")[0], column_label("Fu3_N", "en")[0])


_LATIN_WORD = re.compile(r"[A-Za-z]{3,}")


def _russian_terminal_problems(text, allowed):
    """English words of 3+ letters in a Russian terminal text, apart from ``allowed``
    (the mechanism's name, file names), the command's own name on stderr lines
    ("crankdyn linkage: предупреждение: …") and max/min."""
    for a in sorted(allowed, key=len, reverse=True) + ["crankdyn linkage:"]:
        # the name and the files named after it ("ratchet-drive_kinematics.csv")
        text = re.sub(re.escape(a) + r"[\w.\-]*", "", text)
    return [w for w in _LATIN_WORD.findall(text) if w not in ("max", "min", "PNG", "SVG")]


def _plans_run(cli_report, lang):
    """``crankdyn linkage --example --no-plots --plans 5 --lang LANG`` (the ratchet with
    its plans for position 5, tables only): the session's shared run (read-only), so the
    English one serves the two tests that read it.  Russian (the default language): the
    shared run of the ratchet's plans for positions 5 and 11 that
    tests/test_plans_output.py reads (``ratchet_run``), one run for both."""
    if lang == "ru":
        rep = cli_report("linkage", "--example", "--plans", "5,11", "--no-plots")
        assert rep.rc == 0, rep.err
        return rep
    rep = cli_report("linkage", "--example", "--no-plots", "--plans", "5", "--lang", lang)
    assert rep.rc == 0, rep.err
    return rep


def test_terminal_summary_speaks_the_report_language(lang_runs, cli_report):
    for ex, name in (("ratchet", "ratchet-drive"), ("press", "crank-press")):
        run, out, err = lang_runs[(ex, "ru")]
        assert not _russian_terminal_problems(out + err, [str(run), name]), (ex, out)
        assert "max |Mур| в положениях: " in out and " Н·м (положение " in out
        assert "Тип механизма по Грасгофу" in out or "Проворачиваемость кривошипа" in out
        # the same numbers in both languages
        num = re.compile(r"-?\d+\.\d+")
        en_out = lang_runs[(ex, "en")][1]
        assert num.findall(out) == num.findall(en_out) and num.findall(out)
    # the plans' lines (Zhukovsky lever) too
    for lang in ("ru", "en"):
        cap = _plans_run(cli_report, lang)
        if lang == "ru":
            assert not _russian_terminal_problems(cap.out + cap.err,
                                                  [str(cap.folder), "ratchet-drive"]), \
                cap.out
            assert "рычаг Жуковского" in cap.out and "Fур = " in cap.out
        else:
            assert not CYRILLIC.search(cap.out + cap.err), cap.out
            assert "Zhukovsky lever" in cap.out and "Fb = " in cap.out


def test_lang_help_says_what_it_changes(capsys):
    with pytest.raises(SystemExit):
        main(["linkage", "--help", "--lang", "en"])
    text = " ".join(capsys.readouterr().out.split())
    assert "--lang" in text and "workbook" in text and "terminal" in text
    with pytest.raises(SystemExit):
        main(["linkage", "--help"])                 # Russian by default
    text = " ".join(capsys.readouterr().out.split())
    assert "--lang" in text and "книги .xlsx" in text and "сводки в терминале" in text


def test_inputs_sheet_wrapped_rows_are_tall_enough(lang_runs, loaded_workbook):
    """A wrapped label or meaning on the inputs sheet never runs into the next row: a row
    whose text needs more than one line at its column's width (words put on lines by the
    character widths of crankbase.workbook, measured on LibreOffice's rendering, where a
    Cyrillic text is wider) is at least 12 pt a line tall; merged cells (title,
    conventions) count their merged width."""
    from crankbase.workbook import wrapped_lines

    for key, (run, _, _) in lang_runs.items():
        from openpyxl.utils import get_column_letter

        ws = loaded_workbook(next(run.glob("*.xlsx"))).worksheets[0]     # shared
        spans = {(r.min_row, r.min_col): r for r in ws.merged_cells.ranges}
        wrapped = 0
        for row in ws.iter_rows():
            for c in row:
                if not (isinstance(c.value, str) and c.alignment.wrap_text):
                    continue
                wrapped += 1
                m = spans.get((c.row, c.column))
                cols = range(m.min_col, m.max_col + 1) if m else [c.column]
                width = sum(ws.column_dimensions[get_column_letter(j)].width for j in cols)
                lines = wrapped_lines(c.value, width, bool(c.font.b), c.font.sz or 11)
                if lines > 1:
                    height = ws.row_dimensions[c.row].height
                    assert height and height >= 12 * lines, (key, c.coordinate, c.value)
        assert wrapped > 20, key


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_change_point_warnings_in_the_report_language(lang, tmp_path, capsys):
    """A change-point mechanism asked at its singular position (1 + 3 = 2 + 2, the
    singular crank angle 30°: tests/test_linkage_mechanisms.py): both warnings of the
    analysis reach the terminal and the inputs sheet in the report's language; the
    singular row is left empty, the other row is the same number in both languages."""
    spec = tmp_path / "cp.toml"
    spec.write_text("""
[mechanism]
kind = "crank-rocker"
name = "cp"
crank = 1.0
coupler = 3.0
rocker = 2.0
ground = 2.0
ground_angle_deg = 30.0
omega_rad_s = 1.0
[analysis]
crank_angles_deg = [30.0, 40.0]
""")
    out = tmp_path / "o"
    assert main(["linkage", str(spec), "-o", str(out), "--no-plots", "--lang", lang]) == 0
    cap = capsys.readouterr()
    warned = [l for l in cap.err.splitlines() if "30°" in l or "особое" in l
              or "singular position;" in l]
    assert len(warned) == 2, cap.err
    ws = load_workbook(out / "cp.xlsx").worksheets[0]
    texts = [r[1] for r in ws.iter_rows(values_only=True)
             if r[0] in ("warning", "предупреждение")]
    assert len(texts) == 2
    if lang == "ru":
        assert texts[0].startswith("механизм с переходным положением: особые положения "
                                   "при угле кривошипа 30°")
        assert texts[1].startswith("заданные углы кривошипа включают особое положение")
        assert not _russian_terminal_problems(cap.out + cap.err, [str(out), "cp"])
    else:
        assert texts[0].startswith("change-point mechanism: singular position(s) at crank "
                                   "angle 30°")
        assert not CYRILLIC.search(cap.out + cap.err)
        assert not any(CYRILLIC.search(v) for _, v in _workbook_strings(out / "cp.xlsx"))
    df = _sheet_frame(_sheet(load_workbook(out / "cp.xlsx"), "velocities"))
    assert math.isnan(df["omega4_rad_s"].iat[0]) and np.isfinite(df["omega4_rad_s"].iat[1])


def test_a_chinese_run_prints_and_writes_chinese(cli_report):
    """Issue #19: ``crankdyn linkage --lang zh`` (ratchet, with its plans for position 5):
    the summary and the workbook in Chinese, no Cyrillic letter, no English word beyond
    the mechanism's own names and the Latin symbols; the same numbers as in English."""
    num = re.compile(r"-?\d+\.\d+")
    outs = {lang: _plans_run(cli_report, lang) for lang in ("en", "zh")}
    out = outs["zh"].out + outs["zh"].err
    assert not CYRILLIC.search(out), out
    text = re.sub(r"\S*/\S*|ratchet-drive\S*|\S+\.(csv|xlsx|pdf|dxf|png|svg)", " ", out)
    words = set(re.findall(r"(?<![\w-])[A-Za-z]{3,}(?![\w-])", text))
    assert words <= {"max", "PNG", "SVG"}, words
    assert "茹科夫斯基杠杆" in out and "曲柄摇杆机构" in out
    assert num.findall(outs["zh"].out) == num.findall(outs["en"].out)
    strings = [v for _, v in _workbook_strings(outs["zh"].folder / "ratchet-drive.xlsx")]
    assert not any(CYRILLIC.search(v) for v in strings)
    assert "曲柄长度 lOA" in strings
