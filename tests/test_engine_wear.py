"""Wear diagrams (engine.bearings.wear): the sector rule's exact cases and properties."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine
from crankbase.errors import SpecError
from engine.bearings.analysis import bearing_analysis
from engine.bearings.wear import least_wear_direction, wear_diagram, wear_profile


@pytest.mark.parametrize("direction, half", [(0.0, 60.0), (37.0, 60.0), (300.0, 45.0),
                                             (180.0, 90.0)])
def test_single_constant_load_wears_exactly_its_sector(direction, half):
    a = np.linspace(0.0, 720.0, 145)
    d = wear_diagram("pin", a, np.full(a.size, direction), np.full(a.size, 5000.0), half)
    off = np.abs((d.phi_deg - direction + 180.0) % 360.0 - 180.0)
    inside = off <= half
    assert np.allclose(d.wear[inside], 5000.0 * 720.0, rtol=1e-12)   # ∫|F| dα
    assert np.all(d.wear[~inside] == 0.0)
    assert inside.sum() == 2 * half + 1                               # 1° grid, ends in
    # the oil hole: in the middle of the unworn arc, opposite the load
    assert abs((d.oil_hole_deg - direction) % 360.0 - 180.0) <= 0.5 + 1e-9


def test_uniformly_turning_load_wears_uniformly():
    a = np.arange(0.0, 720.0, 1.0)          # the load turns twice round, 1° a step
    phi, w = wear_profile(np.mod(a, 360.0), np.full(a.size, 800.0), 60.0)
    assert np.allclose(w, 800.0 * 2 * 121, rtol=1e-13, atol=0)   # two turns, 121 within ±60°


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 359.99), st.floats(0, 1e5)), min_size=1,
                max_size=30), st.floats(5, 180))
def test_wear_is_the_sum_of_single_load_sectors(loads, half):
    c = np.array([x for x, _ in loads])
    m = np.array([y for _, y in loads])
    phi, w = wear_profile(c, m, half)
    ref = np.zeros_like(phi)
    for ci, mi in loads:
        _, wi = wear_profile([ci], [mi], half)
        ref += wi
    assert np.allclose(w, ref, rtol=1e-12, atol=1e-6)
    # brute force: the distance of every direction from every contact point
    d = np.abs(np.mod(phi[:, None] - c[None, :] + 180.0, 360.0) - 180.0)
    assert np.allclose(w, (d <= half + 1e-9).astype(float) @ m, rtol=1e-12, atol=1e-6)
    # total wear = Σ|F| × (points within the sector), each load's own count
    counts = [np.sum(np.abs((phi - ci + 180) % 360 - 180) <= half + 1e-9) for ci in c]
    assert w.sum() == pytest.approx(float(np.dot(m, counts)), rel=1e-12)


def test_wear_rotates_with_the_loads():
    rng = np.random.default_rng(3)
    c, m = rng.uniform(0, 360, 50), rng.uniform(0, 1e4, 50)
    _, w = wear_profile(np.round(c), m, 60.0)
    _, w30 = wear_profile(np.round(c) + 30.0, m, 60.0)
    assert np.allclose(np.roll(w, 30), w30, rtol=1e-12)


def test_least_wear_direction_wraps_round_zero():
    phi = np.arange(360.0)
    w = np.ones(360)
    w[350:] = 0.0
    w[:11] = 0.0                 # least wear from 350° through 0° to 10°
    assert least_wear_direction(phi, w) == pytest.approx(0.0)
    w2 = np.ones(360)
    w2[100:121] = 0.0
    assert least_wear_direction(phi, w2) == pytest.approx(110.0)


def test_bad_half_angle_is_refused():
    with pytest.raises(SpecError, match="wear_half_angle_deg"):
        wear_profile([0.0], [1.0], 0.0)


@pytest.mark.parametrize("example", ["diesel_d240.toml", "petrol_vaz2106.toml"])
def test_textbook_like_pin_diagram(example):
    """The bundled engines: the crank pin wears most on its side facing the crankshaft
    axis (the rod's rotating mass pulls the big end outwards for most of the cycle, so
    the shell presses the pin's inner side: the textbook observation), and the oil hole,
    at the least wear, lies outside the ±60° arc that the combustion peak presses."""
    spec = engine.load_spec(engine.spec.Path(__file__).parents[1] / "examples" / example)
    t = engine.force_table(spec, engine.fine_angles(spec))
    d = bearing_analysis(spec, t).pin_wear
    worst = d.phi_deg[int(np.argmax(d.wear))]
    assert abs((worst + 180) % 360 - 180) <= 60.0
    k = int(np.argmax(t["R_N"].to_numpy()))
    peak_contact = (t["psi_deg"].to_numpy()[k] + 180.0) % 360.0
    assert abs((d.oil_hole_deg - peak_contact + 180) % 360 - 180) > 60.0
    assert d.wear[int(round(d.oil_hole_deg)) % 360] == pytest.approx(d.wear.min())
    # brute force, one direction at a time: ∫|F| dα over the loads pressing within ±60°
    a, R, c = t["alpha_deg"].to_numpy(), t["R_N"].to_numpy(), (t["psi_deg"].to_numpy() + 180)
    for phi in (0.0, 90.0, 200.0, float(round(d.oil_hole_deg))):
        near = np.abs((c - phi + 180) % 360 - 180) <= 60.0
        y = np.where(near, R, 0.0)
        ref = np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(a))       # trapezoid over α
        assert d.wear[int(round(phi)) % 360] == pytest.approx(ref, rel=1e-12)
