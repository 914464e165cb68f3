"""linkage.fourbar: Grashof type, transmission angle μ(φ) and its closed-form minimum, for
the four-bar and the crank-slider (the geometry shared by mechanisms, analysis and
synthesis)."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import linkage
from linkage import fourbar
from linkage.fourbar import (GeometryError, GrashofType, grashof, min_transmission_angle_deg,
                             min_transmission_angle_slider_deg, transmission_angle_deg)
from test_linkage_synthesis import mu_from_joints


def test_transmission_angle_from_joint_positions():
    phi = np.linspace(0, 359, 360)
    for l1, l2, l3 in [(0.3240740, 1.0185185, 0.6018519),   # seed 000 ratchet / OC = 0.54
                       (0.09142873454295534, 0.7, 0.6), (0.2, 0.9, 0.6)]:
        for asm in (1, -1):
            np.testing.assert_allclose(transmission_angle_deg(phi, l1, l2, l3),
                                       mu_from_joints(phi, l1, l2, l3, asm), atol=1e-9)


@pytest.mark.parametrize("lengths, kind", [
    ((0.175, 0.55, 0.325, 0.54), GrashofType.CRANK_ROCKER),   # seed 000 ratchet, OC = 0.54 m
    ((0.10, 0.70, 0.60, 1.0), GrashofType.CRANK_ROCKER),
    ((1.0, 0.70, 0.60, 0.10), GrashofType.DOUBLE_CRANK),      # ground shortest
    ((0.70, 0.10, 0.60, 1.0), GrashofType.DOUBLE_ROCKER),     # coupler shortest
    ((0.70, 0.60, 0.10, 1.0), GrashofType.DOUBLE_ROCKER),     # rocker shortest
    ((0.5, 1.0, 0.5, 1.0), GrashofType.CHANGE_POINT),         # parallelogram
    ((0.3, 0.7, 0.6, 1.0), GrashofType.CHANGE_POINT),         # 0.3 + 1.0 = 0.7 + 0.6
    ((0.5, 0.6, 0.7, 1.0), GrashofType.NON_GRASHOF),
])
def test_grashof_types(lengths, kind):
    assert grashof(*lengths) is kind
    assert grashof(*(1000 * np.asarray(lengths))) is kind      # absolute lengths, any unit


def test_grashof_change_point_tolerance():
    # s + l = p + q within √2·ROTATABILITY_RTOL·λ0 (the one rotatability rule) is a
    # change point: 0.3·1e-9 off is inside the band, 0.3·1e-8 outside
    assert grashof(0.3 * (1 + 1e-13), 0.7, 0.6) is GrashofType.CHANGE_POINT
    assert grashof(0.3 * (1 + 1e-9), 0.7, 0.6) is GrashofType.CHANGE_POINT
    assert grashof(0.3 * (1 - 1e-9), 0.7, 0.6) is GrashofType.CHANGE_POINT
    assert grashof(0.3 * (1 + 1e-8), 0.7, 0.6) is GrashofType.NON_GRASHOF
    assert grashof(0.3 * (1 - 1e-8), 0.7, 0.6) is GrashofType.CRANK_ROCKER
    assert str(GrashofType.CRANK_ROCKER) == "crank-rocker"
    assert set(GrashofType.__members__) == {"CRANK_ROCKER", "DOUBLE_CRANK", "DOUBLE_ROCKER",
                                            "CHANGE_POINT", "NON_GRASHOF"}


def test_grashof_errors():
    with pytest.raises(GeometryError) as e:
        grashof(-1, 0.5, float("nan"))
    assert isinstance(e.value, ValueError)
    lines = e.value.lines()
    assert len(lines) == 2 and lines[0].startswith("l1:") and lines[1].startswith("l3:")


def test_transmission_angle_nan_where_not_assemblable():
    mu = transmission_angle_deg([0.0, 180.0], 0.5, 0.6, 0.7)
    assert np.isfinite(mu[0]) and np.isnan(mu[1])


# --------------------------------------------------------------- closed-form minimum
lengths = st.floats(0.05, 3.0)


@settings(max_examples=60, deadline=None)
@given(l1=lengths, l2=lengths, l3=lengths, l0=lengths)
def test_closed_form_mu_min_is_the_minimum_over_a_full_turn(l1, l2, l3, l0):
    """μmin on the line of centres (0° or 180°) equals the minimum of μ(φ) over a dense
    grid of a full turn, for any four-bar whose crank turns fully."""
    phi = np.linspace(0.0, 360.0, 72001)
    mu = transmission_angle_deg(phi, l1, l2, l3, l0)
    if not np.all(np.isfinite(mu)):               # the crank does not turn fully
        with pytest.raises(GeometryError):
            min_transmission_angle_deg(l1, l2, l3, l0)
        return
    got, at = min_transmission_angle_deg(l1, l2, l3, l0)
    assert got <= mu.min() + 1e-9
    assert got == pytest.approx(mu.min(), abs=1e-6)
    assert transmission_angle_deg(at, l1, l2, l3, l0) == pytest.approx(got, abs=1e-9)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(0.01, 1.0), extra=st.floats(0.0, 2.0), e=st.floats(-1.0, 1.0))
def test_closed_form_slider_mu_min(r, extra, e):
    """Crank-slider: μ = 90° − |β| with sin β = (e − r·sin φ)/L; the closed form
    arccos[(r + |e|)/L] is its minimum over a dense grid, at the angle it names."""
    L = r + abs(e) + extra + 1e-3
    phi = np.radians(np.linspace(0.0, 360.0, 72001))
    mu = 90.0 - np.degrees(np.abs(np.arcsin((e - r * np.sin(phi)) / L)))
    got, at = min_transmission_angle_slider_deg(r, L, e)
    assert got == pytest.approx(mu.min(), abs=1e-6)
    beta = math.asin((e - r * math.sin(math.radians(at))) / L)
    assert 90.0 - math.degrees(abs(beta)) == pytest.approx(got, abs=1e-9)


def test_transmission_angle_from_link_directions():
    """μ from the two link directions is the acute angle between them, for any lengths of
    the direction vectors, complex numbers and Vec alike."""
    from linkage.groups import Vec
    a = np.radians(np.linspace(-180, 180, 721))
    for b in (0.0, 0.3, 2.0):
        e_out, e_in = 2.0 * np.exp(1j * a), 0.5 * np.exp(1j * b) + 0 * a
        want = np.degrees(np.abs(np.angle(e_out / e_in)))
        want = np.minimum(want, 180.0 - want)
        got = np.degrees(fourbar.transmission_angle(e_out, e_in))
        np.testing.assert_allclose(got, want, atol=1e-12)
        np.testing.assert_allclose(np.degrees(fourbar.transmission_angle(Vec.of(e_out),
                                                                         Vec.of(e_in))),
                                   want, atol=1e-12)


@pytest.mark.parametrize("mech", [
    {"kind": "crank-rocker", "crank": 0.175, "coupler": 0.55, "rocker": 0.325,
     "ground": 0.54, "ground_angle_deg": 35.0},
    {"kind": "crank-slider", "crank": 0.1, "coupler": 0.35, "offset": 0.03,
     "ground_angle_deg": -20.0},
    {"kind": "crank-slider", "crank": 0.1, "coupler": 0.35, "offset": -0.03}])
def test_analysis_summary_uses_the_closed_form(mech):
    """The summary's μmin and its crank angle (absolute, in [0°, 360°)) are the closed
    form's, and no row of a fine full turn falls below it."""
    data = {"mechanism": {**mech, "omega_rad_s": 3.0},
            "analysis": {"working_stroke": "ccw" if "rocker" in mech else "away"}}
    full = linkage.full_turn(data, 0.05)
    s = full.summary
    mu = full.kinematics["mu_deg"].to_numpy()
    assert s.mu_min_deg <= mu.min() + 1e-9
    assert s.mu_min_deg == pytest.approx(mu.min(), abs=1e-4)
    at = linkage.analyze(data, crank_angles_deg=[s.mu_min_phi_deg]).kinematics["mu_deg"][0]
    assert at == pytest.approx(s.mu_min_deg, abs=1e-9)
    assert 0.0 <= s.mu_min_phi_deg < 360.0


@pytest.mark.parametrize("eps, turns", [(-3e-9, True), (-1e-9, True), (1e-9, True),
                                        (3e-9, False)])
def test_one_rotatability_rule_for_grashof_mechanisms_and_synthesis(eps, turns):
    """One rule, one tolerance: a crank-rocker pushed past Kolchin's line
    λ2 + λ3 = 1 + λ1 by eps (λ1 = 0.3 + eps) is accepted or refused alike by
    fourbar.crank_turns_fully, grashof (change point), CrankRocker.check_rotatable,
    min_transmission_angle_deg and the synthesis margin; the band is
    √2·ROTATABILITY_RTOL on the residual (|eps| = 1e-9 is inside it, 3e-9 outside)."""
    from crankbase.tolerances import ROTATABILITY_RTOL
    from linkage import synthesis
    from linkage.mechanisms import AssemblyError, CrankRocker

    l1, l2, l3 = 0.3 + eps, 0.7, 0.6            # s + l − p − q = eps (s = λ1, l = λ0 = 1)
    margin = fourbar.rotatability_margin(l1, l2, l3)
    assert margin == pytest.approx(-eps / math.sqrt(2.0), abs=1e-15)
    assert bool(fourbar.crank_turns_fully(l1, l2, l3)) is turns
    assert (grashof(l1, l2, l3) in (GrashofType.CHANGE_POINT, GrashofType.CRANK_ROCKER)) \
        is turns
    if abs(margin) <= ROTATABILITY_RTOL:
        assert grashof(l1, l2, l3) is GrashofType.CHANGE_POINT
    assert bool(synthesis._kolchin_margin(l1, l2, l3) >= -synthesis.TOL) is turns
    for scale, gamma in ((1.0, 0.0), (250.0, 0.7)):        # any unit, any ground angle
        mech = CrankRocker(l1 * scale, l2 * scale, l3 * scale, scale, gamma)
        if turns:
            mech.check_rotatable()
            min_transmission_angle_deg(l1 * scale, l2 * scale, l3 * scale, scale)
        else:
            with pytest.raises(AssemblyError):
                mech.check_rotatable()
            with pytest.raises(GeometryError):
                min_transmission_angle_deg(l1 * scale, l2 * scale, l3 * scale, scale)


@pytest.mark.parametrize("eps, turns", [(-5e-10, True), (5e-10, True), (-3e-9, False),
                                        (3e-9, True)])
@pytest.mark.parametrize("e", [0.012, -0.012])
def test_one_rotatability_rule_for_the_crank_slider(eps, turns, e):
    """slider_crank_type and CrankSlider.check_rotatable agree: L = r + |e| + eps·r."""
    from linkage.fourbar import SliderCrankType, slider_crank_type
    from linkage.mechanisms import AssemblyError, CrankSlider

    r = 0.05
    L = r + abs(e) + eps * r
    kind = slider_crank_type(r, L, e)
    assert (kind is not SliderCrankType.NON_ROTATABLE) is turns
    assert (kind is SliderCrankType.CHANGE_POINT) is (abs(eps) < 1e-9)
    mech = CrankSlider(r, L, 0.4, e)
    if turns:
        mech.check_rotatable()
    else:
        with pytest.raises(AssemblyError):
            mech.check_rotatable()
