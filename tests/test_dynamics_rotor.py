"""Rotor balancing: the seed's Example 11-1, a published static problem, exact identities
(zero residual force and moment), hypothesis over random rotors, the CLI."""
import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st

from crankdyn.cli import main
from crankbase.resources import example_path
from dynamics import balance_rotor, rotor_balance
from crankbase.errors import SpecError


def test_seed_example_11_1():
    """Seed 001 (textbook ch. 11 "机械系统的动力分析与设计"), Example 11-1, eqs. (11-6)–(11-9):
    m1r1 = 90 g·mm at 270° at z = 100 mm, m2r2 = 600 g·mm at 45° at z = 420 mm, planes
    I (z = 0) and II (z = 300 mm)."""
    r = balance_rotor([90, 600], [270, 45], [100, 420], [0, 300])
    c = r.corrections.set_index("plane")
    # eq. (11-6): shares in plane I: 60 and −240 g·mm; eq. (11-7): in plane II 30 and 840
    sh = r.shares.set_index(["plane", "mass"])["mr_gmm"]
    assert sh[("I", 1)] == pytest.approx(60.0) and sh[("I", 2)] == pytest.approx(-240.0)
    assert sh[("II", 1)] == pytest.approx(30.0) and sh[("II", 2)] == pytest.approx(840.0)
    # eq. (11-8): plane I components 169.71, 229.71; 285.60 g·mm at 53.54°
    assert c.loc["I", "mr_x_gmm"] == pytest.approx(169.71, abs=0.005)
    assert c.loc["I", "mr_y_gmm"] == pytest.approx(229.71, abs=0.005)
    assert c.loc["I", "mr_gmm"] == pytest.approx(285.60, abs=0.005)
    assert c.loc["I", "angle_deg"] == pytest.approx(53.54, abs=0.005)
    # eq. (11-9): components −593.96, −563.96 (printed as magnitudes), 819.05 g·mm: the
    # book rounds the components first (hypot(593.96, 563.96) = 819.05; unrounded 819.06)
    assert c.loc["II", "mr_x_gmm"] == pytest.approx(-593.97, abs=0.01)
    assert c.loc["II", "mr_y_gmm"] == pytest.approx(-563.97, abs=0.01)
    assert c.loc["II", "mr_gmm"] == pytest.approx(819.05, abs=0.015)
    # Direction of the plane-II correction: 223.52° (both components negative).  The book
    # prints "43.57°" = arctan(y/x) without the quadrant, i.e. the direction of the
    # OPPOSITE vector (223.52° − 180° = 43.52°; the printed 43.57 also carries a slip of
    # 0.05° in the last digits).
    assert c.loc["II", "angle_deg"] == pytest.approx(223.52, abs=0.005)
    printed_convention = math.degrees(math.atan(c.loc["II", "mr_y_gmm"] / c.loc["II", "mr_x_gmm"]))
    assert printed_convention == pytest.approx(c.loc["II", "angle_deg"] - 180.0)
    assert printed_convention == pytest.approx(43.57, abs=0.06)
    assert r.residual_force_gmm < 1e-9 and r.residual_moment_gmm2 < 1e-6


def test_gate_2019_static():
    """GATE 2019 ME (set 2), Q.38: ma = 10 kg at 200 mm, mb = 20 kg at 400 mm, 90° apart, in
    one plane; the balance mass at 200 mm: official answer key 41.0 … 41.5 kg (41.23)."""
    r = balance_rotor([10 * 200, 20 * 400], [0, 90], planes_mm=[0], correction_radius_mm=200)
    m = r.corrections["m_g"].iloc[0]  # units follow the input: kg·mm / mm = kg here
    assert 41.0 <= m <= 41.5
    assert m == pytest.approx(41.23, abs=0.005)
    # opposite the resultant: 180° + atan(8000/2000)
    assert r.corrections["angle_deg"].iloc[0] == pytest.approx(180 + math.degrees(math.atan(4)))


def test_static_leaves_a_couple():
    """Two equal opposite masses in different planes: statically balanced already (zero
    correction) but a couple remains; two-plane balancing removes it."""
    r1 = balance_rotor([100, 100], [0, 180], [0, 100], [50])
    assert r1.corrections["mr_gmm"].iloc[0] == pytest.approx(0, abs=1e-12)
    assert r1.residual_moment_gmm2 == pytest.approx(100 * 100)
    r2 = balance_rotor([100, 100], [0, 180], [0, 100], [0, 100])
    assert r2.corrections["mr_gmm"].to_numpy() == pytest.approx([100, 100])
    assert r2.corrections["angle_deg"].to_numpy() == pytest.approx([180, 0])
    assert r2.residual_moment_gmm2 < 1e-9


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 1e4), st.floats(-720, 720), st.floats(-500, 500)),
                min_size=2, max_size=8),
       st.floats(-300, 0), st.floats(10, 600))
def test_dynamic_balance_identities(masses, z1, gap):
    """After two-plane balancing the centrifugal forces have zero resultant force and zero
    moment about ANY axial point (checked about z = 0 and z = 1000, independently of the
    implementation's own residuals)."""
    mr, ang, z = map(np.array, zip(*masses))
    if np.ptp(z) == 0:
        z = z + np.arange(len(z))
    planes = [z1, z1 + gap]
    r = balance_rotor(mr, ang, z, planes)
    v = np.concatenate([mr * np.exp(1j * np.radians(ang)),
                        r.corrections["mr_gmm"] * np.exp(1j * np.radians(r.corrections["angle_deg"]))])
    zz = np.concatenate([z, planes])
    scale = max(mr.sum(), 1.0)
    assert abs(v.sum()) <= 1e-9 * scale
    for z0 in (0.0, 1000.0):
        assert abs((v * (zz - z0)).sum()) <= 1e-9 * scale * 2000


def test_errors():
    with pytest.raises(SpecError, match="different z"):
        balance_rotor([1], [0], [5], [10, 10])
    with pytest.raises(SpecError, match="balanced statically"):
        balance_rotor([1, 2], [0, 90], [5, 5], [0, 10])
    with pytest.raises(SpecError, match="mr_gmm"):
        balance_rotor([-1], [0], [5], [0])
    spec = {"rotor": {"planes_mm": [0, 300, 600], "bogus": 1,
                      "mass": [{"mr_gmm": 1, "m_g": 2, "angle_deg": 0}]}}
    with pytest.raises(SpecError) as e:
        rotor_balance(spec)
    text = str(e.value)
    assert "rotor.planes_mm" in text and "rotor.bogus" in text and "not both" in text


def test_spec_m_and_r():
    spec = {"rotor": {"planes_mm": [0], "correction_radius_mm": 10,
                      "mass": [{"m_g": 2, "r_mm": 30, "angle_deg": 0}]}}
    r = rotor_balance(spec)
    assert r.corrections["m_g"].iloc[0] == pytest.approx(6.0)
    assert r.corrections["angle_deg"].iloc[0] == pytest.approx(180.0)


def test_cli(tmp_path, capsys):
    assert main(["balance", str(example_path("rotor_two_plane.toml")), "-o",
                 str(tmp_path), "--lang", "en"]) == 0
    df = pd.read_csv(tmp_path / "two-plane-example_rotor_balance.csv")
    assert list(df.columns) == ["plane", "z_mm", "mr_gmm", "angle_deg", "m_g", "r_mm"]
    assert df["mr_gmm"].to_numpy() == pytest.approx([285.595, 819.0615], abs=1e-3)
    assert df["m_g"].to_numpy() == pytest.approx(df["mr_gmm"].to_numpy() / 50)
    assert (tmp_path / "two-plane-example_rotor_polygons.png").stat().st_size > 10_000


def test_cli_bad_input(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text('[rotor]\nplanes_mm = [0, 0]\n[[rotor.mass]]\nmr_gmm = 5\nangle_deg = 0\n'
                   'z_mm = 3\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["balance", str(bad), "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "rotor.planes_mm" in err[0]
    assert not out.exists()
