"""End to end: ``crankdyn dynamics`` on the bundled examples in both languages (CSV columns,
workbook read back, plots exist), bad input exits 2 with one line per problem and writes
nothing."""
import numpy as np
import pandas as pd
import pytest

from crankdyn.cli import main
from crankdyn.langs import error_line
from crankbase.resources import example_path

COLS = ["phi_deg", "J_red_kgm2", "dJ_red_dphi_kgm2", "M_drive_Nm", "M_resist_Nm",
        "omega_rad_s", "eps_rad_s2", "t_s"]


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_machine_example(cli_report, lang, loaded_workbook):
    rep = cli_report("dynamics", "--example", "flywheel", "--lang", lang)  # shared, read-only
    assert rep.rc == 0
    out = rep.folder
    df = pd.read_csv(out / "flywheel-example-11-3_motion.csv")
    assert list(df.columns[:8]) == COLS
    assert df["omega_rad_s"].max() == pytest.approx(168.45, abs=0.01)   # seed Ex. 11-3
    assert df["omega_rad_s"].min() == pytest.approx(145.72, abs=0.01)
    wb = loaded_workbook(out / "flywheel-example-11-3_dynamics.xlsx")     # shared
    ws = wb.worksheets[1]
    header = [c.value for c in ws[2]]           # row 1: the quantity, row 2: the CSV name
    col = header.index("omega_rad_s")
    assert ws.cell(1, col + 1).value == ("ω, рад/с" if lang == "ru" else "ω [rad/s]")
    vals = np.array([r[col] for r in ws.iter_rows(min_row=3, values_only=True)], float)
    assert np.array_equal(vals, df["omega_rad_s"].to_numpy())
    for name in ("inertia", "moments", "wittenbauer", "omega"):
        assert (out / f"flywheel-example-11-3_{name}.png").stat().st_size > 5000
    assert "168.44" in rep.out
    strings = [c.value for w in wb.worksheets for row in w.iter_rows() for c in row
               if isinstance(c.value, str)]
    has_cyr = any(any("\u0400" <= ch <= "\u04ff" for ch in v) for v in strings)
    assert has_cyr == (lang == "ru")


def test_linkage_motor_example(cli_report):
    rep = cli_report("dynamics", "--example", "press", "--lang", "en")    # shared, read-only
    assert rep.rc == 0
    out = rep.folder
    m = pd.read_csv(out / "crank-press_motion.csv")
    w = m["omega_rad_s"]
    assert (w.max() - w.min()) / (0.5 * (w.max() + w.min())) == pytest.approx(0.05, rel=1e-5)
    f = pd.read_csv(out / "crank-press_forces_true_motion.csv")
    assert {"M_drive_Nm", "M_drive_Nm_const", "R12_x_N", "R12_x_N_const"} <= set(f.columns)
    s = pd.read_csv(out / "crank-press_startup.csv")
    assert s["omega_rad_s"].iloc[0] == 0.0 and s["omega_rad_s"].iloc[-1] > 9.0
    assert (out / "crank-press_startup.png").exists()
    assert (out / "crank-press_forces_true_motion.png").exists()


@pytest.mark.parametrize("body,keys", [
    ('[machine]\nJ_red_kgm2 = -1\nomega_mean_rad_s = 10\n[[machine.moment]]\nrole = "resist"\n'
     'phi_deg = [0, 360]\nM_Nm = [1, 1]\n[dynamics]\ndelta = 1.5\n',
     ["machine.J_red_kgm2", "dynamics.delta"]),
    ('[machine]\nJ_red_kgm2 = 0.001\nomega_mean_rad_s = 1\n[[machine.moment]]\nrole = "resist"\n'
     'phi_deg = [0, 90, 90, 360]\nM_Nm = [600, 600, 200, 200]\n', ["dynamics"]),
    ('[machine]\nJ_red_kgm2 = 1\nomega_mean_rad_s = 10\n[[machine.moment]]\nrole = "resist"\n'
     'phi_deg = [0, 360]\nM_Nm = [500, 500]\n[dynamics]\ndriving = "motor"\n'
     'motor_start_torque_Nm = 400\nmotor_sync_speed_rad_s = 100\n',
     ["dynamics.motor_start_torque_Nm"]),
])
def test_bad_input(tmp_path, capsys, body, keys):
    spec = tmp_path / "bad.toml"
    spec.write_text(body, encoding="utf-8")
    out = tmp_path / "out"
    code = main(["dynamics", str(spec), "-o", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2
    assert not out.exists()
    prefix = error_line("dynamics", "")     # the default language's, Russian
    for k in keys:
        assert any(line.startswith(f"{prefix}{k}:") for line in err), (k, err)


def test_engine_example(cli_report):
    rep = cli_report("dynamics", "--example", "petrol", "--lang", "ru")   # shared, read-only
    assert rep.rc == 0
    out = rep.folder
    m = pd.read_csv(out / "petrol-vaz2106_motion.csv")
    w = m["omega_rad_s"]
    assert (w.max() - w.min()) / (0.5 * (w.max() + w.min())) == pytest.approx(0.01, rel=1e-6)
    assert m["phi_deg"].iloc[-1] == pytest.approx(720.0)


def test_examples_flag(tmp_path, capsys):
    assert main(["balance", "--lang", "en", "--example", "-o", str(tmp_path / "r")]) == 0
    assert (tmp_path / "r" / "two-plane-example_rotor_balance.csv").exists()
    assert main(["dynamics", "--lang", "en",
                 "--example", "flywheel", "-o", str(tmp_path / "f")]) == 0
    assert (tmp_path / "f" / "flywheel-example-11-3_motion.csv").exists()
    assert main(["dynamics", "--lang", "en", "--example", "nope", "-o", str(tmp_path / "n")]) == 2
    assert main(["dynamics", "--lang", "en", str(example_path("flywheel_seed.toml")), "--example",
                 "-o", str(tmp_path / "n")]) == 2
    err = capsys.readouterr().err
    assert "no dynamics example 'nope'" in err and "not both" in err
    assert not (tmp_path / "n").exists()


def test_linkage_and_dynamics_problems_reported_together(tmp_path, capsys):
    text = example_path("press.toml").read_text(encoding="utf-8")
    text = text.replace("crank = 0.08 ", "crank = -0.08 ")
    bad = tmp_path / "p.toml"
    bad.write_text(text + "\n[dynamics]\ndelta = 2\nbogus = 1\n", encoding="utf-8")
    assert main(["dynamics", str(bad), "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    for key in ("mechanism.crank", "dynamics.delta", "dynamics.bogus"):
        assert error_line("dynamics", key) in err, (key, err)
