"""End to end: ``crankdyn engine --bearings`` and a spec with ``[rod]``/``[bearings]``:
the bearing CSVs read back equal the library's tables, the plots exist, bad keys exit 2
with one line per problem."""
import copy
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import engine
from crankdyn.cli import main
from crankbase.resources import example_path
from engine.bearing_plots import BEARING_PLOT_NAMES
from engine.bearing_spec import bearing_analysis

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


def test_bearings_flag_writes_tables_equal_to_the_library(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(["engine", "--example", "diesel", "-o", str(out), "--bearings",
                 "--lang", "en"]) == 0
    text = capsys.readouterr().out
    assert "crank pin          max    41618 N at alpha = 372 deg" in text
    names = {p.name for p in out.iterdir()}
    assert set(CSVS) <= names and "rod_model.csv" not in names
    for stem in BEARING_PLOT_NAMES[:-1]:
        for ext in ("png", "svg"):
            assert (out / f"{stem}.{ext}").stat().st_size > 1000, stem
    study = engine.load(example_path("diesel_d240.toml"))
    spec = study.spec
    t = engine.force_table(spec, settings=study.settings)
    res = bearing_analysis(spec, t)
    pins = pd.read_csv(out / "crankpins.csv")
    np.testing.assert_array_equal(pins.to_numpy(), res.loads.crankpins.to_numpy())
    np.testing.assert_array_equal(pins["R_1_N"].to_numpy(), t["R_N"].to_numpy())
    tq = pd.read_csv(out / "journal_torques.csv")
    np.testing.assert_allclose(tq["M_2_Nm"], t["M_Nm"], rtol=1e-15)
    wear = pd.read_csv(out / "wear.csv")
    assert list(wear.columns) == ["phi_deg", "wear_pin_1_Ndeg", "wear_journal_1_Ndeg",
                                  "wear_journal_2_Ndeg"]
    assert len(wear) == 360
    rb = pd.read_csv(out / "rod_bearings.csv")
    assert list(rb.columns)[-3:] == ["Pp_axial_N", "Pp_side_N", "Pp_N"]


def test_rigid_rod_spec_writes_rod_model(tmp_path, capsys):
    d = tomllib.loads(example_path("diesel_d240.toml").read_text())
    d = copy.deepcopy(d)
    d["pressure"]["file"] = str(example_path("diesel_d240_indicator.csv"))
    d["rod"] = dict(model="rigid", inertia_kg_m2=0.030)
    d["bearings"] = dict(wear_half_angle_deg=45.0, journal_positions_mm=[-50.0, 70.0])
    spec_path = tmp_path / "r.toml"
    spec_path.write_text(_toml(d))
    out = tmp_path / "o"
    assert main(["engine", str(spec_path), "-o", str(out), "--lang", "ru"]) == 0
    text = capsys.readouterr().out
    assert "rigid rod" in text and "wear arcs +/-45 deg" in text
    rm = pd.read_csv(out / "rod_model.csv")
    assert list(rm.columns[:4]) == ["alpha_deg", "K_2m_N", "K_rigid_N", "dK_N"]
    np.testing.assert_allclose(rm["dT_N"], rm["T_rigid_N"] - rm["T_2m_N"], rtol=1e-12)
    assert (out / "rod_model.png").exists() and (out / "wear_pin.svg").exists()
    jr = pd.read_csv(out / "journals.csv")
    np.testing.assert_allclose(jr["R_1_N"] / (jr["R_1_N"] + jr["R_2_N"]), 70 / 120,
                               rtol=1e-9)


def test_bad_bearing_keys_exit_2_and_write_nothing(tmp_path, capsys):
    d = tomllib.loads(example_path("diesel_d240.toml").read_text())
    d["pressure"]["file"] = str(example_path("diesel_d240_indicator.csv"))
    d["rod"] = dict(model="rigid")
    d["bearings"] = dict(wear_half_angle_deg=200)
    spec_path = tmp_path / "bad.toml"
    spec_path.write_text(_toml(d))
    out = tmp_path / "o"
    assert main(["engine", str(spec_path), "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert any("bearings.wear_half_angle_deg: got 200" in e for e in err)
    assert any("rod.inertia_kg_m2: missing" in e for e in err)
    assert not out.exists() or not any(out.iterdir())
