"""End to end: ``crankdyn engine --bearings`` and a spec with ``[rod]``/``[bearings]``:
the bearing CSVs read back equal the library's tables, the plots exist, bad keys exit 2
with one line per problem."""
import copy
import tomllib

import numpy as np
import pandas as pd
import pytest

import engine
from crankdyn.cli import main
from crankbase.resources import example_path
from engine.plots.bearing import BEARING_PLOT_NAMES
from engine.bearings.analysis import bearing_analysis, read_bearing_inputs

CSVS = ("crankpins.csv", "journals.csv", "journal_torques.csv", "rod_bearings.csv",
        "wear.csv")


def _toml(d):
    """A minimal TOML writer for the spec dicts used here (tables of scalars and lists)."""
    def val(v):
        if isinstance(v, str):
            return '"' + v + '"'
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, list):
            return "[" + ", ".join(val(x) for x in v) + "]"
        return repr(v)
    out = []

    def table(name, t):
        out.append(f"[{name}]")
        subs = []
        for k, v in t.items():
            if isinstance(v, dict):
                subs.append((f"{name}.{k}", v))
            else:
                out.append(f"{k} = {val(v)}")
        for n, s in subs:
            table(n, s)
    for k, v in d.items():
        table(k, v)
    return "\n".join(out) + "\n"


def test_bearings_flag_writes_tables_equal_to_the_library(tmp_path, capsys,
                                                         figures_rendered_only):
    """The diesel example, an inline 4 (firing 1-3-4-2, counterweights per throw).  Its
    bearing plots are rendered as PNG (as SVG too in the session's shared V8 report with
    its bearings, tests/test_engine_cli.py); its engine plots and bearing SVGs are built,
    not drawn (the same engine plots of ``crankdyn engine --example diesel --lang ru``
    are rendered in the session's shared report, tests/test_engine_cli.py)."""
    saved = figures_rendered_only(*(f"_{stem}.png" for stem in BEARING_PLOT_NAMES))
    out = tmp_path / "o"
    assert main(["engine", "--example", "diesel", "-o", str(out), "--bearings",
                 "--lang", "en"]) == 0
    text = capsys.readouterr().out
    assert "crank pins         most loaded:" in text and "main journals      most" in text
    names = {p.name for p in out.iterdir()}
    assert {f"diesel-d240_{c}" for c in CSVS} <= names
    assert "diesel-d240_rod_model.csv" not in names
    for stem in BEARING_PLOT_NAMES[:-1]:
        png = (out / f"diesel-d240_{stem}.png").read_bytes()
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000, stem
        assert (out / f"diesel-d240_{stem}.svg").is_file(), stem
    assert sum(r for _, r in saved) == len(BEARING_PLOT_NAMES) - 1
    study = engine.load(example_path("diesel_d240.toml"))
    spec = study.spec
    t = engine.force_table(spec, settings=study.settings)
    theta = t["alpha_deg"].to_numpy()
    cyl = pd.read_csv(out / "diesel-d240_cylinders.csv")
    pins = pd.read_csv(out / "diesel-d240_crankpins.csv")
    # inline: one rod per pin, so pin k's load is cylinder k's Rшш at its own phase
    for k, phase in zip(cyl["throw"], cyl["phase_deg"]):
        tk = engine.force_table(spec, theta, phase_deg=phase)
        np.testing.assert_allclose(pins[f"R_{k}_N"], tk["R_N"], rtol=1e-12)
        np.testing.assert_allclose(pins[f"psi_{k}_deg"], tk["psi_deg"], atol=1e-9)
    # the last main journal carries the engine's total torque (torque.csv)
    tq = pd.read_csv(out / "diesel-d240_journal_torques.csv")
    total = pd.read_csv(out / "diesel-d240_torque.csv")
    assert list(tq.columns) == ["alpha_deg"] + [f"M_{j}_Nm" for j in range(1, 6)]
    both = tq.merge(total, on="alpha_deg")          # torque.csv has no extra angles
    assert len(both) == len(total)
    np.testing.assert_allclose(both["M_5_Nm"], both["M_total_Nm"], rtol=1e-10, atol=1e-6)
    assert (tq["M_1_Nm"] == 0).all()
    wear = pd.read_csv(out / "diesel-d240_wear.csv")
    assert list(wear.columns) == (["phi_deg"] + [f"wear_pin_{k}_Ndeg" for k in range(1, 5)]
                                  + [f"wear_journal_{j}_Ndeg" for j in range(1, 6)])
    assert len(wear) == 360
    rb = pd.read_csv(out / "diesel-d240_rod_bearings.csv")
    assert list(rb.columns)[-3:] == ["Pp_axial_N", "Pp_side_N", "Pp_N"]
    # the workbook's bearing sheets hold the CSVs bit for bit, and the summary
    from openpyxl import load_workbook
    from engine.report.bearing_sheets import SHEET_NAMES
    # read-only: the values of the six sheets read, the others not parsed
    wb = load_workbook(out / "diesel-d240.xlsx", read_only=True)
    for fname in CSVS:
        rows = list(wb[SHEET_NAMES["en"][fname]].values)
        df = pd.read_csv(out / f"diesel-d240_{fname}")
        assert list(rows[0]) == list(df.columns)
        np.testing.assert_array_equal(np.array(rows[1:], float), df.to_numpy())
    summ = {r[0]: r[1:] for r in wb[SHEET_NAMES["en"]["summary"]].values if r and r[0]}
    wb.close()
    assert set(summ) >= {f"Crank pin {k}, R, N" for k in range(1, 5)}
    assert summ["Most loaded main journal"][0] in range(1, 6)
    assert summ["Crank pin 1, R, N"][0] == pytest.approx(float(pins["R_1_N"].max()),
                                                         rel=0.05)


def test_one_cylinder_spec_with_bearing_tables(tmp_path, capsys, unrendered_figures):
    """A one-cylinder spec: the [bearings] journal positions and the statistics as the
    library gives them on the fine grid (the plots built, not drawn: the diesel's and the
    V8's bearing plots are rendered in test_bearings_flag_writes_tables_equal_to_the_library
    and the session's shared V8 report)."""
    d = tomllib.loads(example_path("diesel_d240.toml").read_text())
    d["pressure"]["file"] = str(example_path("diesel_d240_indicator.csv"))
    for k in ("cylinders", "firing_order", "cylinder_spacing_mm", "mechanical_efficiency"):
        d["engine"].pop(k, None)
    d.pop("flywheel", None)
    d.pop("balance", None)
    d["bearings"] = dict(journal_positions_mm=[-50.0, 70.0])
    spec_path = tmp_path / "one.toml"
    spec_path.write_text(_toml(d))
    out = tmp_path / "o"
    assert main(["engine", str(spec_path), "-o", str(out), "--lang", "en"]) == 0
    text = capsys.readouterr().out
    study = engine.load(spec_path)
    spec = study.spec
    fine = bearing_analysis(spec, engine.analyze(spec, study.settings).curves,
                            read_bearing_inputs(spec_path, spec))
    ps = fine.loads.pin_stats[0]
    assert f"most loaded: 1 (max {ps.max_N:.0f} N at alpha = {ps.alpha_max_deg:g} deg" in text
    assert (out / "diesel-d240_wear_journals.png").exists()
    pins = pd.read_csv(out / "diesel-d240_crankpins.csv")
    t = engine.force_table(spec, settings=study.settings)
    np.testing.assert_array_equal(pins["R_1_N"].to_numpy(), t["R_N"].to_numpy())
    from openpyxl import load_workbook
    from engine.report.bearing_sheets import SHEET_NAMES
    wb = load_workbook(out / "diesel-d240.xlsx", read_only=True)   # one sheet's values
    summ = {r[0]: r[1:] for r in wb[SHEET_NAMES["en"]["summary"]].values if r and r[0]}
    wb.close()
    assert summ["Crank pin 1, R, N"][:6] == (ps.max_N, ps.alpha_max_deg, ps.min_N,
                                             ps.alpha_min_deg, ps.mean_N, ps.chi)
    assert summ["crank pin 1"][0] == fine.pin_wear.oil_hole_deg


def test_rigid_rod_spec_writes_rod_model(tmp_path, capsys, figures_rendered_only):
    """A rigid rod: the rod model's table and plot.  The plots it names are rendered
    (the rod model's only here), the others built, not drawn (the diesel's engine and
    bearing plots are rendered in the test above and the session's shared report)."""
    saved = figures_rendered_only("_rod_model.", "_wear_pins.", "_wear_journals.")
    d = tomllib.loads(example_path("diesel_d240.toml").read_text())
    d = copy.deepcopy(d)
    d["pressure"]["file"] = str(example_path("diesel_d240_indicator.csv"))
    d["rod"] = dict(model="rigid", inertia_kg_m2=0.030)
    d["bearings"] = dict(wear_half_angle_deg=45.0)
    spec_path = tmp_path / "r.toml"
    spec_path.write_text(_toml(d))
    out = tmp_path / "o"
    assert main(["engine", str(spec_path), "-o", str(out), "--lang", "ru"]) == 0
    text = capsys.readouterr().out
    assert "жёсткий шатун" in text and "дуги износа ±45°" in text   # the report's language
    rm = pd.read_csv(out / "diesel-d240_rod_model.csv")
    assert list(rm.columns[:4]) == ["alpha_deg", "K_2m_N", "K_rigid_N", "dK_N"]
    np.testing.assert_allclose(rm["dT_N"], rm["T_rigid_N"] - rm["T_2m_N"], rtol=1e-12)
    assert (out / "diesel-d240_rod_model.png").exists()
    assert (out / "diesel-d240_wear_pins.svg").exists()
    assert (out / "diesel-d240_wear_journals.png").exists()
    for name in ("rod_model.png", "rod_model.svg", "wear_pins.svg", "wear_journals.png"):
        assert (out / f"diesel-d240_{name}").stat().st_size > 1000, name
    assert sorted(n.split(".")[-1] for n, r in saved if r) == ["png"] * 3 + ["svg"] * 3


def test_bad_bearing_keys_exit_2_and_write_nothing(tmp_path, capsys):
    d = tomllib.loads(example_path("diesel_d240.toml").read_text())
    d["pressure"]["file"] = str(example_path("diesel_d240_indicator.csv"))
    d["rod"] = dict(model="rigid")
    d["bearings"] = dict(wear_half_angle_deg=200)
    spec_path = tmp_path / "bad.toml"
    spec_path.write_text(_toml(d))
    out = tmp_path / "o"
    assert main(["engine", str(spec_path), "-o", str(out), "--lang", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert any("bearings.wear_half_angle_deg: got 200" in e for e in err)
    assert any("rod.inertia_kg_m2: missing" in e for e in err)
    assert not out.exists() or not any(out.iterdir())
