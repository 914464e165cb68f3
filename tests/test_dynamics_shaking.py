"""Shaking force and moment of a linkage, full force balance of the four-bar (zero shaking
force at every angle, hypothesis over random crank-rockers), partial balance of the
crank-slider (Khurmi & Gupta Example 22.1), the d'Alembert identity against the core's
frame reactions."""
import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given

import linkage
from crankbase.resources import example_path
from dynamics.shaking import balance_crank_slider, balance_fourbar, shaking
from crankbase.errors import SpecError
from test_linkage_properties import SETTINGS, crank_rockers, crank_sliders


def _no_loads(data):
    data = {k: v for k, v in data.items() if k != "load"}
    data["mechanism"] = dict(data["mechanism"], gravity_m_s2=0.0)
    return data


@SETTINGS
@given(crank_rockers())
def test_fourbar_full_force_balance(data):
    """After the two counterweights the total mass centre stands still: zero shaking force
    at every crank angle (computed from the core's kinematics of the balanced spec)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            spec = linkage.load_spec(data)
            res = balance_fourbar(spec, crank_angles_deg=np.arange(0, 360, 7.5))
        except linkage.AssemblyError:
            assume(False)
    before = res.before.table["F_N"].max()
    scale = max(before, sum(l.mass for l in spec.links.values()) * abs(spec.omega) ** 2 *
                spec.crank, 1e-12)
    assert res.after.table["F_N"].max() <= 1e-9 * scale + 1e-9
    # the counterweights are what the formula says, merged as point masses
    assert np.all(res.counterweights["mass_kg"] >= 0)


@SETTINGS
@given(crank_rockers())
def test_shaking_equals_frame_reactions(data):
    """d'Alembert: with no external loads and no gravity the frame's reactions from the
    core's force analysis carry exactly the shaking force and moment:
    F_sh = −(R12 + R14), M_sh(O) = −(M_drive + (r_C − r_O) × R14)."""
    data = _no_loads(data)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            spec = linkage.load_spec(data)
            ang = np.arange(3.0, 360.0, 11.0)
            sh = shaking(spec, ang).table
            f = linkage.analyze(spec, crank_angles_deg=ang, course_tables=False).forces
        except linkage.AssemblyError:
            assume(False)
    from linkage.analysis import build_mechanism

    zC = build_mechanism(spec).zC
    R12 = f["R12_x_N"] + 1j * f["R12_y_N"]
    R14 = f["R14_x_N"] + 1j * f["R14_y_N"]
    F = -(R12 + R14)
    scale = max(sh["F_N"].max(), 1.0)
    assert np.max(np.abs(F.to_numpy() - (sh["F_x_N"] + 1j * sh["F_y_N"]).to_numpy())) < 1e-8 * scale
    M = -(f["M_drive_Nm"] + zC.real * R14.to_numpy().imag - zC.imag * R14.to_numpy().real)
    mscale = max(np.abs(sh["M_O_Nm"]).max(), scale * spec.ground, 1.0)
    assert np.max(np.abs(M - sh["M_O_Nm"])) < 1e-8 * mscale


@SETTINGS
@given(crank_sliders())
def test_crank_slider_rotating_balance(data):
    """Balancing all the rotating mass (fraction 0) leaves a shaking force along the guide
    only: −m_rec a_B (the coupler split between A and B is exact for the force when its
    centre of mass lies on AB)."""
    data = _no_loads(data)
    data["links"]["coupler"]["cg"][1] = 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            spec = linkage.load_spec(data)
            res = balance_crank_slider(spec, 0.0, crank_angles_deg=np.arange(0, 360, 10.0))
        except linkage.AssemblyError:
            assume(False)
    g = math.radians(data["mechanism"]["ground_angle_deg"])
    t = res.after.table
    F = (t["F_x_N"] + 1j * t["F_y_N"]).to_numpy()
    perp = (F * np.exp(-1j * g)).imag
    scale = max(res.before.table["F_N"].max(), 1e-9)
    assert np.max(np.abs(perp)) <= 1e-9 * scale


def test_khurmi_22_1_partial_balance():
    """Khurmi & Gupta, Theory of Machines, 14th ed., Example 22.1: 240 rpm, stroke 300 mm,
    reciprocating parts 50 kg, revolving parts 37 kg at 150 mm; all the revolving and two
    thirds of the reciprocating parts balanced at 400 mm.  Printed: B = 26.38 kg.  The
    residual at 60° from dead centre by the book's formula (obliquity neglected)
    m ω² r √((1−c)² cos²θ + c² sin²θ) = 2.847 kN; the mechanism with a very long rod
    (obliquity → 0) gives it."""
    w = 240 * math.pi / 30
    data = {"mechanism": {"kind": "crank-slider", "crank": 0.15, "coupler": 0.15 * 1e4,
                          "omega_rad_s": w},
            "links": {"crank": {"mass_kg": 37.0, "cg": [0.15, 0.0]},
                      "coupler": {"mass_kg": 0.0}, "slider": {"mass_kg": 50.0}},
            "analysis": {"crank_angles_deg": [60.0]}}
    res = balance_crank_slider(data, 2 / 3, radius_m=0.4, crank_angles_deg=[60.0])
    assert res.counterweights["mass_kg"].iloc[0] == pytest.approx(26.375)  # printed 26.38
    assert round(res.counterweights["mass_kg"].iloc[0] + 1e-12, 2) == 26.38
    assert res.counterweights["angle_deg"].iloc[0] == pytest.approx(180.0)
    c, th = 2 / 3, math.radians(60)
    book = 50 * w * w * 0.15 * math.sqrt((1 - c) ** 2 * math.cos(th) ** 2 + c ** 2 * math.sin(th) ** 2)
    assert book == pytest.approx(2847, abs=1)
    assert res.after.table["F_N"].iloc[0] == pytest.approx(book, rel=2e-4)


def test_kind_errors():
    with pytest.raises(SpecError, match="crank-rocker"):
        balance_fourbar(example_path("press.toml"))
    with pytest.raises(SpecError, match="crank-slider"):
        balance_crank_slider(example_path("ratchet.toml"))
    with pytest.raises(SpecError, match="fraction"):
        balance_crank_slider(example_path("press.toml"), 1.5)


def test_cli_linkage_balance(tmp_path):
    import pandas as pd

    from crankdyn.cli import main

    out = tmp_path / "o"
    assert main(["balance", str(example_path("ratchet_balance.toml")), "-o", str(out),
                 "--lang", "en"]) == 0
    t = pd.read_csv(out / "ratchet-drive_shaking.csv")
    assert t["F_N"].max() > 100 and t["F_N_after"].max() < 1e-9 * t["F_N"].max()
    cw = pd.read_csv(out / "ratchet-drive_counterweights.csv")
    assert list(cw["link"]) == ["crank", "rocker"]
    assert cw["radius_m"].iloc[0] == pytest.approx(0.05)
    assert (out / "ratchet-drive_shaking_locus.png").exists()


def test_cli_balance_bad_section(tmp_path, capsys):
    from crankdyn.cli import main

    text = example_path("press.toml").read_text(encoding="utf-8")
    bad = tmp_path / "p.toml"
    bad.write_text(text + "\n[balance]\nfraction = 2\nradius_rocker_m = 0.1\n", encoding="utf-8")
    assert main(["balance", str(bad), "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert any("balance.fraction" in e for e in err)
    assert any("balance.radius_rocker_m" in e for e in err)
    assert not (tmp_path / "o").exists()
