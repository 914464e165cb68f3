"""End-to-end: `crankdyn linkage` on the bundled examples; workbook read back = CSV;
bad input exits 2 with one line per problem and writes nothing."""
import math
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
from openpyxl import load_workbook

from crankdyn.cli import main
from crankbase.resources import example_path

SHEETS = ("inputs", "positions", "velocities", "accelerations", "loads", "forces",
          "extremes")
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


@pytest.fixture(scope="module")
def ratchet_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("ratchet")
    assert main(["linkage", "--example", "-o", str(out)]) == 0
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


def test_workbook_read_back_equals_csv(ratchet_run):
    wb = load_workbook(ratchet_run / "ratchet-drive.xlsx")
    assert set(SHEETS) <= set(wb.sheetnames)
    k = pd.read_csv(_one(ratchet_run, "kinematics.csv"))
    f = pd.read_csv(_one(ratchet_run, "forces.csv"))
    seen = set()
    for sheet in ("positions", "velocities", "accelerations"):
        df = _sheet_frame(wb[sheet])
        for c in df.columns:
            np.testing.assert_array_equal(df[c].to_numpy(float), k[c].to_numpy(float))
            seen.add(c)
    assert seen == set(k.columns)  # every kinematics column is on some sheet
    seen = set()
    for sheet in ("loads", "forces"):
        df = _sheet_frame(wb[sheet])
        assert list(df.columns[:2]) == ["position", "phi_deg"]
        for c in df.columns:
            np.testing.assert_array_equal(df[c].to_numpy(float), f[c].to_numpy(float))
            seen.add(c)
    assert seen == set(f.columns)  # every force column is on some sheet
    # the course tables' magnitudes come first on the velocities sheet
    vel = list(_sheet_frame(wb["velocities"]).columns)
    assert vel.index("v_BA_m_s") < vel.index("A_vx_m_s")
    assert {"G3_N", "Fu3_N", "Mu3_Nm", "M_res_Nm"} <= set(_sheet_frame(wb["loads"]).columns)
    assert "Fu3_N" not in _sheet_frame(wb["forces"]).columns


def test_workbook_inputs_and_extremes(ratchet_run):
    wb = load_workbook(ratchet_run / "ratchet-drive.xlsx")
    values = {r[0]: r[1] for r in wb["inputs"].iter_rows(values_only=True) if r and r[0]}
    assert values["mechanism.crank"] == 0.175
    assert values["links.coupler.inertia_kg_m2"] == 0.51
    assert values["Grashof type"] == "crank-rocker"
    # seed 000 / domain.md §2: with OC = 0.54 m, swing ≈ 68.4°, K ≈ 1.138
    assert values["rocker swing"] == pytest.approx(68.4, abs=0.05)
    assert values["time-ratio coefficient K = φwork/φidle"] == pytest.approx(1.138, abs=5e-4)
    # the extremes sheet lists one quantity per row (readable on A4): transpose it back
    rows = list(wb["extremes"].iter_rows(min_row=2, values_only=True))
    ext = pd.DataFrame({r[2]: list(r[3:]) for r in rows})
    assert list(ext["label"]) == ["working start", "working end"]
    # the rocker stands still at both extreme positions
    assert np.abs(ext["omega4_rad_s"].to_numpy(float)).max() < 1e-9
    # position 1 is the working-stroke start
    k = pd.read_csv(_one(ratchet_run, "kinematics.csv"))
    assert ext["phi_deg"].iat[0] == pytest.approx(k["phi_deg"].iat[0], abs=1e-9)


@pytest.mark.parametrize("name", ["ratchet.toml", "press.toml"])
def test_every_bundled_linkage_example_runs(name, tmp_path):
    out = tmp_path / "out"
    assert main(["linkage", "--example", name, "-o", str(out)]) == 0
    for p in PLOTS:
        assert _one(out, f"{p}.png").stat().st_size > 1000
    k = pd.read_csv(_one(out, "kinematics.csv"))
    assert len(k) == 12 and list(k["position"]) == list(range(1, 13))


def test_explicit_angles_crank_slider(tmp_path):
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
    df = _sheet_frame(wb["forces"])
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
    assert main(["linkage", str(spec), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    lines = [l for l in err.splitlines() if l.strip()]
    assert all(l.startswith("crankdyn linkage: error: ") for l in lines)
    assert "Traceback" not in err
    for key in expected:
        assert any(key in l for l in lines), (key, lines)
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


def test_missing_spec_file(tmp_path, capsys):
    assert main(["linkage", str(tmp_path / "nope.toml"), "-o", str(tmp_path / "o")]) == 2
    assert "does not exist" in capsys.readouterr().err
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
                        str(tmp_path / "o")], capture_output=True, text=True)
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
    assert "statics, ω = 0" in text and "<NA>" not in text
    for p in ("plan", "driving_moment", "transmission_angle"):
        assert _one(out, f"{p}.png").stat().st_size > 1000
    assert not list(out.glob("*_velocities.png")) and not list(out.glob("*_accelerations.png"))
    f = pd.read_csv(_one(out, "forces.csv"))
    assert f["M_drive_Nm"].iat[0] == pytest.approx(3 * W * a, rel=1e-12)
    k = pd.read_csv(_one(out, "kinematics.csv"))
    assert (k["omega3_rad_s"] == 0).all() and (k["B_a_m_s2"] == 0).all()
    wb = load_workbook(out / "rhombus.xlsx")
    assert "extremes" not in wb.sheetnames        # no strokes without rotation
