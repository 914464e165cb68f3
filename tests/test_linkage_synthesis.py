"""Tests of linkage.synthesis: the ККМ-φ0 families (seed 004, Sereda 2016).

Layers: the paper's printed numbers (cited beside each assertion) → exact reductions of the
general-φ0 formulas to the paper's φ0 = 30° equations → an independent method (angles from
the assembled joint positions) → hypothesis properties over random φ0 and random admissible
mechanisms, checked through the kinematic core (to_spec → load_spec → analyze).
"""
from __future__ import annotations

import math
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import linkage
from linkage import fourbar
from linkage import synthesis as syn
from linkage.fourbar import GeometryError
from linkage.synthesis import (GrashofType, SynthesisError, crank_length_for_right_angle,
                               design_equal_l2_l3, design_for_mu_min, design_from_l2_l3,
                               existence_region, grashof, kolchin_line_points, l1_max,
                               min_transmission_angle_deg, right_angle_family, to_spec,
                               transmission_angle_deg)

SQ3 = math.sqrt(3.0)


def deg_min(deg):
    """Degrees → (degrees, minutes rounded), as the paper prints angles (46°16′)."""
    d = int(deg)
    return d, round((deg - d) * 60.0)


# --------------------------------------------------------------------------- helpers
def joints(phi_deg, l1, l2, l3, assembly=1):
    """Independent geometry: O = 0, C = 1 (ground along +x), A on the crank, B the
    intersection of circle(A, λ2) and circle(C, λ3) on the chosen side of A→C."""
    A = l1 * np.exp(1j * np.radians(phi_deg))
    C = 1.0 + 0j
    d = np.abs(C - A)
    a = (l2 ** 2 - l3 ** 2 + d ** 2) / (2 * d)
    h = np.sqrt(np.maximum(l2 ** 2 - a ** 2, 0.0))
    u = (C - A) / d
    B = A + a * u + assembly * 1j * h * u
    return A, B, C


def mu_from_joints(phi_deg, l1, l2, l3, assembly=1):
    """Acute angle between BA and BC from the joint positions (atan2, no cosine formula)."""
    A, B, C = joints(phi_deg, l1, l2, l3, assembly)
    ang = np.abs(np.degrees(np.angle((A - B) / (C - B))))
    return np.minimum(ang, 180.0 - ang)


def random_member(phi0, frac, t):
    """An admissible member of the ККМ-φ0 family: λ1 = frac·λ1max, the point a fraction t
    of the way along the admissible arc between the two Kolchin points."""
    l1 = frac * l1_max(phi0)
    arc = right_angle_family(l1, phi0, n=3)
    (a2, a3), (b2, b3) = kolchin_line_points(l1, phi0)
    th = (1 - t) * math.atan2(a3, a2) + t * math.atan2(b3, b2)
    return l1, arc.radius * math.cos(th), arc.radius * math.sin(th)


# --------------------------------------------------------------------------- the paper
@pytest.mark.parametrize("l1, l2, l3", [
    (0.05, 0.9520, 0.0980),   # seed 004, Table 1, row 1
    (0.10, 0.8904, 0.2096),   # seed 004, Table 1, row 3
    (0.15, 0.8002, 0.3498),   # seed 004, Table 1, row 5
])
def test_table1_rows(l1, l2, l3):
    pts = kolchin_line_points(l1, 30.0)
    assert pts.shape == (2, 2)
    np.testing.assert_array_equal(np.round(pts[0], 4), [l2, l3])   # larger λ2 first
    np.testing.assert_array_equal(np.round(pts[1], 4), [l3, l2])   # the mirrored row
    # both lie on Kolchin's line (3) and on the family circle (6)
    assert pts[0].sum() == pytest.approx(1 + l1, abs=1e-15)
    assert pts[0] @ pts[0] == pytest.approx(l1 * (l1 - SQ3) + 1, abs=1e-15)


def test_l1_max_and_point_d():
    # seed 004, eq. (11) and Table 1 last row: λ1 = 0.1896, λ2 = λ3 = 0.5948
    top = l1_max(30.0)
    assert round(top, 4) == 0.1896
    assert top ** 2 - 2 * top * (1 + SQ3) + 1 == pytest.approx(0.0, abs=1e-15)
    pts = kolchin_line_points(top, 30.0)
    np.testing.assert_array_equal(np.round(pts, 4), [[0.5948, 0.5948], [0.5948, 0.5948]])
    assert pts[0, 0] == pts[0, 1]                       # the two roots coincide exactly
    reg = existence_region(30.0)
    assert reg.l1_max == top
    assert np.round(reg.d, 4).tolist() == [0.5948, 0.5948]
    # the Table 1 vectorised over λ1 in one call
    t1 = kolchin_line_points([0.05, 0.10, 0.15, top], 30.0)
    assert t1.shape == (4, 2, 2)
    np.testing.assert_array_equal(np.round(t1[:, 0, 0], 4), [0.9520, 0.8904, 0.8002, 0.5948])


def test_design_example_1_l2_l3_given():
    # seed 004, example 1 to Fig. 2: λ2 = 0.70, λ3 = 0.60 → by (6) λ1 = 0.09
    d = design_from_l2_l3(0.70, 0.60, 30.0)
    assert round(d.l1, 2) == 0.09
    assert d.l1 == pytest.approx(SQ3 / 2 - math.sqrt(0.75 - 1 + 0.85), rel=1e-14)
    assert d.grashof is GrashofType.CRANK_ROCKER
    assert d.mu_at_phi0_deg == pytest.approx(90.0, abs=1e-9)
    # seed 004, example 1 to Fig. 3: λ2 = 0.70 (and that λ1) → μmin = 66°2′
    assert deg_min(d.mu_min_deg) == (66, 2)
    assert d.mu_min_at_deg == 180.0          # seed 004: the minimum is at φ = 180°


def test_design_example_2_equal_l2_l3():
    # seed 004, example 2 to Fig. 2: λ1 = 0.146, λ2 = λ3 → by (6) λ2 = λ3 = 0.620
    d = design_equal_l2_l3(0.146, 30.0)
    assert round(d.l2, 3) == 0.620 and d.l3 == d.l2
    # eq. (14): μmin for λ2 = λ3
    eq14 = math.degrees(math.acos(2 * 0.146 * (1 + SQ3 / 2) / (0.146 * (0.146 - SQ3) + 1)))
    assert d.mu_min_deg == pytest.approx(eq14, abs=1e-12)


def test_design_example_fig3_mu_min():
    # seed 004, example 2 to Fig. 3: λ2 = 0.90, μmin ≥ 40° → from curve 9, λ1 = 0.08;
    # by (6) λ3 = 0.24; by (13) μmin = 46°16′.
    exact = design_for_mu_min(0.90, 40.0, 30.0)
    assert exact.mu_min_deg == pytest.approx(40.0, abs=1e-9)   # the largest λ1 is exact
    assert round(exact.l1, 4) == 0.0840 and math.floor(exact.l1 * 100) / 100 == 0.08
    paper = design_for_mu_min(0.90, 40.0, 30.0, l1_step=0.01)  # as read off Fig. 3
    assert paper.l1 == pytest.approx(0.08, abs=1e-15)
    assert round(paper.l3, 2) == 0.24
    assert paper.mu_min_deg >= 40.0
    assert 46.2 <= paper.mu_min_deg <= 46.4     # domain.md §3: 46.2–46.4° with rounding
    # with the paper's rounded λ3 = 0.24, eq. (13) gives 46°16.9′, printed as 46°16′
    eq13 = math.degrees(math.acos(0.08 * (1 + SQ3 / 2) / (0.90 * 0.24)))
    assert eq13 == pytest.approx(46 + 16 / 60, abs=1 / 60)
    # (the rounded lengths are off the family circle by 4e-4, so the general cosine
    # formula gives 46°14′ for them: still within the paper's 46°16′ ± 3′)
    mu, at = min_transmission_angle_deg(0.08, 0.90, 0.24)
    assert mu == pytest.approx(46 + 16 / 60, abs=3 / 60) and at == 180.0


def test_fig3_trends():
    # seed 004, conclusion 4 and Fig. 3: at constant λ2, μmin falls as λ1 grows and
    # reaches 0 on the boundary; the curve for λ2 = 0.70 passes 66°2′ near λ1 = 0.09.
    cur = syn.mu_min_curves(30.0)
    assert cur.l2.tolist() == [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]
    for row, end in zip(cur.mu_min_deg, cur.l1_end):
        ok = np.isfinite(row)
        assert ok[0] and row[0] == pytest.approx(90.0)
        assert np.all(np.diff(row[ok]) < 0)
        assert cur.l1[ok][-1] == pytest.approx(end, abs=1e-12)
        assert row[ok][-1] == pytest.approx(0.0, abs=1e-5)
    # at constant λ1, μmin rises with λ2 and then falls (conclusion 4)
    i = np.searchsorted(cur.l1, 0.05)
    col = cur.mu_min_deg[:, i]
    k = int(np.nanargmax(col))
    assert 0 < k < len(col) - 1


# --------------------------------------------------------------------------- reductions
L1 = np.linspace(0.001, l1_max(30.0), 50)


def test_family_reduces_to_eq6_at_30():
    # seed 004, eq. (6): λ2² + λ3² = λ1 (λ1 − √3) + 1
    np.testing.assert_allclose(syn.family_radius(L1, 30.0) ** 2, L1 * (L1 - SQ3) + 1,
                               rtol=1e-15)
    l2 = 0.7
    np.testing.assert_allclose(syn.family_l3(L1, l2, 30.0),
                               np.sqrt(L1 * (L1 - SQ3) + 1 - l2 ** 2), rtol=1e-15)


def test_transmission_angle_reduces_to_eq12_at_30():
    # seed 004, eq. (12): μ = arccos[λ1 (cos φ − √3/2) / (λ2 λ3)] on the ККМ-30° family
    phi = np.linspace(0, 360, 721)
    for l1 in (0.05, 0.1, 0.15):
        arc = right_angle_family(l1, 30.0, n=7)
        for l2, l3 in zip(arc.l2[1:-1], arc.l3[1:-1]):
            eq12 = np.degrees(np.arccos(l1 * (np.cos(np.radians(phi)) - SQ3 / 2) / (l2 * l3)))
            acute = np.minimum(eq12, 180 - eq12)
            np.testing.assert_allclose(transmission_angle_deg(phi, l1, l2, l3), acute,
                                       atol=1e-10)


def test_mu_min_reduces_to_eq13_eq16_at_30():
    # seed 004, eq. (13): μmin = arccos[λ1 (1 + √3/2) / (λ2 λ3)];
    # eq. (16): the same with λ3 = √(λ1 (λ1 − √3) − λ2² + 1)
    for l2 in (0.3, 0.5, 0.7, 0.9):
        l1 = np.linspace(0.005, 0.04, 8)
        l3 = np.sqrt(l1 * (l1 - SQ3) - l2 ** 2 + 1)
        eq16 = np.degrees(np.arccos(l1 * (1 + SQ3 / 2) / (l2 * l3)))
        np.testing.assert_allclose(syn.family_mu_min_deg(l1, l2, 30.0), eq16, rtol=1e-14)
        mu, at = min_transmission_angle_deg(l1, l2, l3)
        np.testing.assert_allclose(mu, eq16, atol=1e-10)
        assert np.all(at == 180.0)


def test_kolchin_points_reduce_to_eq9_eq10_at_30():
    # seed 004, eq. (9)–(10): λ2,3 = [λ1 + 1 ± √(λ1² − 2 λ1 (1 + √3) + 1)] / 2
    pts = kolchin_line_points(L1, 30.0)
    root = np.sqrt(np.maximum(L1 ** 2 - 2 * L1 * (1 + SQ3) + 1, 0))
    np.testing.assert_allclose(pts[:-1, 0, 0], (L1 + 1 + root)[:-1] / 2, rtol=0, atol=1e-15)
    np.testing.assert_allclose(pts[:-1, 0, 1], (L1 + 1 - root)[:-1] / 2, rtol=0, atol=1e-15)
    # at λ1max the paper's form takes √ of a rounding error (≈1e-8); the code factors the
    # radicand by its roots (λ1max, 1/λ1max) and gets the double point exactly
    np.testing.assert_allclose(pts[-1, 0], (L1[-1] + 1 + np.array([1, -1]) * root[-1]) / 2,
                               atol=2e-8)
    assert pts[-1, 0, 0] == pts[-1, 0, 1]


# --------------------------------------------------------------------------- independent


def test_kkm5_and_kkm7_segments_are_what_the_paper_says():
    # seed 004, after Fig. 2: λ3 = 0.5 with λ1 + λ2 = √3/2 is ККМ-5 (crank and coupler in
    # one line at φ = 30°); λ2 = 0.5 with λ1 + λ3 = √3/2 is ККМ-7 (crank and rocker
    # parallel, on opposite sides of the line of centres, at φ = 330°).
    reg = existence_region(30.0)
    np.testing.assert_allclose(reg.kkm5_l3, 0.5, rtol=1e-15)
    np.testing.assert_allclose(reg.kkm7_l2, 0.5, rtol=1e-15)
    np.testing.assert_allclose(reg.kkm5_l2[[0, -1]], [SQ3 / 2, (1 + SQ3 / 2 - 0.5) / 2])
    assert np.all(reg.contains(reg.kkm5_l2, reg.kkm5_l3))
    assert np.all(reg.contains(reg.kkm7_l2, reg.kkm7_l3))
    for l2 in reg.kkm5_l2[1:]:          # [0] is on the unit arc: λ1 = 0
        l1 = SQ3 / 2 - l2
        assert crank_length_for_right_angle(l2, 0.5, 30.0) == pytest.approx(l1, abs=1e-12)
        A, B, C = joints(30.0, l1, l2, 0.5, assembly=1)
        assert np.angle(B - A) == pytest.approx(np.angle(A), abs=1e-9)       # collinear
        A, B, C = joints(-30.0, l1, 0.5, l2, assembly=1)    # ККМ-7: λ2 ↔ λ3, φ = 330°
        assert np.angle(B - C) == pytest.approx(np.angle(-A), abs=1e-9)      # antiparallel
    assert existence_region(120.0).kkm5_l2 is None


def test_region_boundary_has_dead_positions():
    # seed 004: on the curve cda μmin = 0 (a dead position); on the arc abc λ1 = 0
    for phi0 in (30.0, 75.0, 90.0, 120.0, 160.0):
        reg = existence_region(phi0)
        for l1, l2, l3 in zip(reg.curve_l1[1:-1], reg.curve_l2[1:-1], reg.curve_l3[1:-1]):
            # |cos μ| = 1 at the dead position (arccos near 1 would amplify rounding)
            at = 180.0 if phi0 <= 90 else 0.0
            assert abs(fourbar._cos_mu(at, l1, l2, l3)) == pytest.approx(1.0, abs=1e-12)
            assert grashof(l1, l2, l3) is GrashofType.CHANGE_POINT or \
                min(fourbar.rotatability_residuals(l1, l2, l3, crank_rocker=True)) > -1e-12
        np.testing.assert_allclose(np.hypot(reg.arc_l2, reg.arc_l3), 1.0, atol=1e-15)
        assert np.all(reg.contains(reg.l2[1:-1], reg.l3[1:-1]))
        assert reg.l2[0] == reg.l2[-1] and reg.l3[0] == reg.l3[-1]   # closed


def test_region_other_phi0():
    # φ0 ≤ 90°: boundary on line (3); φ0 > 90°: on lines (1)–(2), and λ1 can reach 1
    assert l1_max(90.0) == 1.0 and l1_max(150.0) == 1.0
    assert l1_max(60.0) == pytest.approx(2 - SQ3, abs=1e-15)   # 1/(√½ + √(3/2))² = 2 − √3
    for l1 in (0.1, 0.5, 0.9):
        (a2, a3), (b2, b3) = kolchin_line_points(l1, 120.0)
        assert a2 - a3 == pytest.approx(1 - l1, abs=1e-14)
        assert a2 ** 2 + a3 ** 2 == pytest.approx(l1 ** 2 + 1 + l1, abs=1e-14)
        d = syn.design(l1, a2, a3, 120.0)
        assert d.mu_min_deg == pytest.approx(0.0, abs=1e-5) and d.mu_min_at_deg == 0.0


def test_inside_within_1e9_of_boundary():
    # points within 1e-9 of the boundary count as inside
    top = l1_max(30.0)
    assert design_equal_l2_l3(top + 5e-10).grashof is GrashofType.CHANGE_POINT
    with pytest.raises(SynthesisError, match="λ1max"):
        design_equal_l2_l3(top + 1e-6)
    (a2, a3), _ = kolchin_line_points(0.1, 30.0)
    assert crank_length_for_right_angle(a2, a3, 30.0) == pytest.approx(0.1, abs=1e-12)
    reg = existence_region(30.0)
    assert reg.contains(a2 - 4e-10, a3 - 4e-10)
    assert not reg.contains(a2 - 1e-6, a3 - 1e-6)
    assert reg.contains(1.0, 0.0) and reg.contains(math.sqrt(0.5), math.sqrt(0.5))
    assert not reg.contains(0.8, 0.8)


# --------------------------------------------------------------------------- Grashof


# --------------------------------------------------------------------------- bad input
def test_errors_name_the_argument_value_and_what_is_valid():
    with pytest.raises(SynthesisError, match=r"phi0_deg: .*between 0° and 180°, got 180"):
        l1_max(180.0)
    with pytest.raises(SynthesisError, match=r"phi0_deg"):
        kolchin_line_points(0.1, 0.0)
    with pytest.raises(SynthesisError) as e:
        crank_length_for_right_angle(0.0, -0.2, 30.0)
    assert [ln.split(":")[0] for ln in e.value.lines()] == ["l2", "l3"]
    with pytest.raises(SynthesisError, match=r"outside the region of existence.*crank-rocker"):
        crank_length_for_right_angle(0.9, 0.9, 30.0)        # outside the unit arc
    with pytest.raises(SynthesisError, match=r"sin² φ0"):
        crank_length_for_right_angle(0.2, 0.2, 30.0)        # the circle cannot get so small
    with pytest.raises(SynthesisError, match=r"outside the region"):
        crank_length_for_right_angle(0.7, 0.2, 30.0)        # beyond the curve cda
    with pytest.raises(SynthesisError, match=r"l1: must lie in 0 … λ1max"):
        kolchin_line_points(0.2, 30.0)
    with pytest.raises(SynthesisError, match=r"mu_min_deg: must be an angle"):
        design_for_mu_min(0.9, 90.0)
    with pytest.raises(SynthesisError, match=r"not reachable.*best with λ2 = 1.2"):
        design_for_mu_min(1.2, 40.0, 120.0)
    with pytest.raises(SynthesisError, match=r"not reachable"):
        design_for_mu_min(1.5, 10.0, 30.0)
    with pytest.raises(SynthesisError, match=r"l1_step"):
        design_for_mu_min(0.9, 40.0, l1_step=0.1)
    with pytest.raises(SynthesisError, match=r"not a member"):
        syn.design(0.1, 0.7, 0.6)
    with pytest.raises(GeometryError, match=r"crank cannot turn fully"):
        min_transmission_angle_deg(0.5, 0.6, 0.7)
    with pytest.raises(SynthesisError, match=r"ground_m"):
        to_spec(0.1, 0.7, 0.6, 0.0)


def test_importing_synthesis_is_light():
    code = ("import sys, linkage.synthesis; "
            "print(any(m in sys.modules for m in ('matplotlib', 'openpyxl')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "False"


# --------------------------------------------------------------------------- the core
def test_to_spec_shape():
    spec = to_spec(0.1, 0.7, 0.6, 0.5, name="x", omega_rad_s=-3.0)
    m = spec["mechanism"]
    assert m["kind"] == "crank-rocker" and m["name"] == "x" and m["omega_rad_s"] == -3.0
    assert (m["crank"], m["coupler"], m["rocker"], m["ground"]) == pytest.approx(
        (0.05, 0.35, 0.3, 0.5))
    assert m["ground_angle_deg"] == 0.0
    s = linkage.load_spec(spec)
    assert s.kind == "crank-rocker"


def test_paper_example_through_the_core():
    d = design_from_l2_l3(0.70, 0.60, 30.0)
    res = linkage.analyze(d.to_spec(0.4), crank_angles_deg=[30.0, 180.0, 330.0])
    mu = res.kinematics["mu_deg"].to_numpy()
    assert mu[0] == pytest.approx(90.0, abs=1e-9) and mu[2] == pytest.approx(90.0, abs=1e-9)
    assert mu[1] == pytest.approx(d.mu_min_deg, abs=1e-9)            # 66°2′, seed 004
    assert res.summary.mu_min_deg == pytest.approx(d.mu_min_deg, abs=1e-9)
    assert res.summary.grashof == "crank-rocker"


def test_boundary_member_is_a_change_point_in_the_core():
    # Table 1 points have μmin = 0: the core accepts them as change-point mechanisms
    (l2, l3), _ = kolchin_line_points(0.1, 30.0)
    with warnings.catch_warnings(record=True):
        warnings.simplefilter("always")
        res = linkage.analyze(to_spec(0.1, l2, l3, 1.0), crank_angles_deg=[30.0, 90.0])
    assert res.kinematics["mu_deg"].iloc[0] == pytest.approx(90.0, abs=1e-9)
    assert res.summary.grashof == "change-point"
    assert res.summary.singular_phi_deg == [pytest.approx(180.0)]


phi0s = st.floats(1.0, 179.0)
fracs = st.floats(0.01, 0.99)


@settings(max_examples=300, deadline=None)
@given(phi0=phi0s, frac=fracs, t=fracs)
def test_property_family_member(phi0, frac, t):
    l1, l2, l3 = random_member(phi0, frac, t)
    # μ = 90° at φ0 (and at −φ0)
    assert transmission_angle_deg(phi0, l1, l2, l3) == pytest.approx(90.0, abs=1e-9)
    assert transmission_angle_deg(-phi0, l1, l2, l3) == pytest.approx(90.0, abs=1e-9)
    # independent: from the assembled joints
    assert mu_from_joints(phi0, l1, l2, l3) == pytest.approx(90.0, abs=1e-7)
    # the predicted μmin is the minimum over a fine grid (which contains 0° and 180°)
    phi = np.linspace(0.0, 360.0, 7201)
    mu_grid = transmission_angle_deg(phi, l1, l2, l3)
    mu_min, at = min_transmission_angle_deg(l1, l2, l3)
    assert mu_grid.min() == pytest.approx(mu_min, abs=1e-9)
    assert mu_min == pytest.approx(float(syn.family_mu_min_deg(l1, l2, phi0)), abs=1e-9)
    assert at == (180.0 if phi0 < 90 else 0.0) or abs(phi0 - 90) < 1e-6
    assert np.min(mu_from_joints(phi, l1, l2, l3)) == pytest.approx(mu_min, abs=1e-7)
    # the design helpers give the member (or one with a shorter crank) back
    back = crank_length_for_right_angle(l2, l3, phi0)
    assert back <= l1 + 1e-12
    assert l2 ** 2 + l3 ** 2 == pytest.approx(back ** 2 + 1 - 2 * back * math.cos(math.radians(phi0)),
                                              abs=1e-12)
    assert grashof(l1, l2, l3) is GrashofType.CRANK_ROCKER
    assert existence_region(phi0, n=5).contains(l2, l3)


@settings(max_examples=150, deadline=None)
@given(phi0=phi0s, frac=fracs, t=fracs, ground=st.floats(0.01, 10.0))
def test_property_round_trip_through_core(phi0, frac, t, ground):
    l1, l2, l3 = random_member(phi0, frac, t)
    mu_min, at = min_transmission_angle_deg(l1, l2, l3)
    spec = linkage.load_spec(to_spec(l1, l2, l3, ground))
    res = linkage.analyze(spec, crank_angles_deg=[phi0, at, 360.0 - phi0])
    mu = res.kinematics["mu_deg"].to_numpy()
    assert res.kinematics["phi_deg"].iloc[0] == pytest.approx(phi0)
    assert mu[0] == pytest.approx(90.0, abs=1e-9)
    assert mu[2] == pytest.approx(90.0, abs=1e-9)
    assert mu[1] == pytest.approx(mu_min, abs=1e-9)
    assert res.summary.mu_min_deg == pytest.approx(mu_min, abs=1e-9)
    assert res.summary.grashof == "crank-rocker"


@settings(max_examples=100, deadline=None)
@given(phi0=st.floats(1.0, 89.0), l2=st.floats(0.05, 0.95), mu=st.floats(1.0, 89.0))
def test_property_design_for_mu_min(phi0, l2, mu):
    try:
        d = design_for_mu_min(l2, mu, phi0)
    except SynthesisError:
        # only when even the shortest cranks miss the μmin, i.e. the arc is out of reach
        assume(False)
    assert d.mu_min_deg >= mu - 1e-9
    if d.l1 < l1_max(phi0) - 1e-12:
        assert d.mu_min_deg == pytest.approx(mu, abs=1e-7)    # the largest λ1 is tight
        worse = syn.family_mu_min_deg(d.l1 * (1 + 1e-6), l2, phi0)
        assert not worse >= mu                                  # NaN or below


def test_right_angle_family_arc():
    # seed 004, Fig. 2: for 0 < λ1 < λ1max the family is the arc of radius
    # R = √(λ1 (λ1 − √3) + 1) between its two Table 1 points
    arc = right_angle_family(0.10, 30.0, n=101)
    assert arc.radius == pytest.approx(math.sqrt(0.1 * (0.1 - SQ3) + 1), rel=1e-15)
    np.testing.assert_allclose(np.hypot(arc.l2, arc.l3), arc.radius, rtol=1e-14)
    np.testing.assert_array_equal(np.round([arc.l2[0], arc.l3[0]], 4), [0.8904, 0.2096])
    np.testing.assert_array_equal(np.round([arc.l2[-1], arc.l3[-1]], 4), [0.2096, 0.8904])
    assert arc.mu_min_deg[0] == pytest.approx(0, abs=1e-5)
    assert arc.mu_min_deg[50] == pytest.approx(arc.mu_min_deg.max())   # best at λ2 = λ3
    assert np.all(syn._kolchin_margin(0.1, arc.l2, arc.l3) >= -syn.TOL)
    np.testing.assert_allclose(arc.l3_of(arc.l2[1:-1]), arc.l3[1:-1], rtol=1e-12)
    with pytest.raises(SynthesisError, match="l1"):
        right_angle_family(0.0, 30.0)


# --------------------------------------------------------------------------- languages
CYRILLIC = re.compile("[\u0400-\u04FF]")
NUMBER = re.compile(r"\d+(?:\.\d+)?")


def _numbers(text):
    """Every number of a text, sorted (the word order differs between the languages)."""
    return sorted(NUMBER.findall(text))


def _paper_example():
    # seed 004, example 2 to Fig. 3: λ2 = 0.90, μmin ≥ 40°, λ1 read off Fig. 3 to 0.01
    return design_for_mu_min(0.90, 40.0, 30.0, l1_step=0.01)


def test_summary_lines_in_both_languages():
    from linkage import synthesis_report as rep

    d = _paper_example()
    reg, table = existence_region(30.0), rep.table1(30.0)
    ru = "\n".join(rep.summary_lines(reg, table, d, 0.5, lang="ru"))
    en = "\n".join(rep.summary_lines(reg, table, d, 0.5, lang="en"))
    for text in (ru, en):
        # seed 004: λ1 = 0.08, λ3 = 0.24 (0.2405 unrounded); λ1max = 0.1896, d = 0.5948
        assert "λ1 = 0.0800" in text and "λ3 = 0.2405" in text and "0.1896" in text
        assert "(0.5948, 0.5948)" in text and "46°24′" in text
    assert not CYRILLIC.search(en), CYRILLIC.findall(en)
    for term in ("KKM-30°: region of existence", "KKM-30° (μ = 90° at φ0 = 30°)",
                 "given λ2 and μmin ≥ 40°; λ1 rounded down to a multiple of 0.01",
                 "Grashof type: crank-rocker", "Table 1: 7 rows",
                 "lengths: crank 0.04 m, coupler 0.45 m, rocker 0.120246 m, ground 0.5 m"):
        assert term in en, term
    for term in ("ККМ-30°: область существования", "ККМ-30° (μ = 90° при φ0 = 30°)",
                 "заданы λ2 и μmin ≥ 40°; λ1 округлено в меньшую сторону до кратного 0.01",
                 "Тип по Грасгофу: кривошипно-коромысловый", "таблица 1: 7 строк",
                 "длины: кривошип 0.04 м, шатун 0.45 м, коромысло 0.120246 м, стойка 0.5 м"):
        assert term in ru, term
    # the Russian summary has no English word (μmin, λ1max: the paper's symbols)
    assert set(re.findall(r"[A-Za-z]{2,}", ru)) <= {"min", "max"}, ru
    assert _numbers(ru) == _numbers(en)
    # the region alone: one line
    assert rep.summary_lines(reg, table, lang="ru") == [ru.splitlines()[0]]


def test_words_of_the_design_tasks_and_grashof_types():
    from linkage import synthesis_report as rep

    tasks = [design_from_l2_l3(0.70, 0.60, 30.0).method, design_equal_l2_l3(0.146, 30.0).method,
             design_for_mu_min(0.90, 40.0, 30.0).method, _paper_example().method,
             syn.design(*[0.1, *kolchin_line_points(0.1, 30.0)[0]], 30.0).method]
    for method in tasks:
        ru, en = rep.method_text(method, "ru"), rep.method_text(method, "en")
        assert ru != method and en != method, method          # every task is translated
        assert CYRILLIC.search(ru) and not CYRILLIC.search(en), (ru, en)
        assert _numbers(ru) == _numbers(en), (ru, en, method)
    ru, en = (rep.method_text(_paper_example().method, lang) for lang in ("ru", "en"))
    assert ru == "заданы λ2 и μmin ≥ 40°; λ1 округлено в меньшую сторону до кратного 0.01"
    assert en == "given λ2 and μmin ≥ 40°; λ1 rounded down to a multiple of 0.01"
    assert rep.method_text("by hand", "ru") == "by hand"       # unknown: unchanged
    for t in GrashofType:
        ru, en = rep.grashof_text(t, "ru"), rep.grashof_text(t, "en")
        assert CYRILLIC.search(ru) and not CYRILLIC.search(en) and en.startswith(t.value)
    assert rep.grashof_text(GrashofType.CRANK_ROCKER, "ru") == "кривошипно-коромысловый"
    with pytest.raises(ValueError, match="lang"):
        rep.grashof_text("crank-rocker", "de")


def test_russian_plural_of_rows():
    from linkage.synthesis_report import _rows

    assert [_rows(n, "ru") for n in (1, 2, 5, 11, 21, 22, 112)] == [
        "1 строка", "2 строки", "5 строк", "11 строк", "21 строка", "22 строки", "112 строк"]
    assert [_rows(n, "en") for n in (1, 7)] == ["1 row", "7 rows"]


def test_toml_header_in_both_languages():
    import tomllib

    from linkage import synthesis_report as rep

    d = _paper_example()
    ru, en = rep.toml_header(d, "ru"), rep.toml_header(d, "en")
    assert "ККМ-30°: кривошипно-коромысловый механизм" in ru and "KKM-30°: crank-rocker" in en
    assert not CYRILLIC.search(en)
    assert _numbers(ru) == _numbers(en)
    assert f"λ3 = {d.l3!r}" in ru and f"λ3 = {d.l3!r}" in en    # the spec's own digits
    text = rep.dumps_toml(d.to_spec(0.5), ru)
    assert tomllib.loads(text)["mechanism"]["rocker"] == 0.5 * d.l3
    # Chinese: the comment in Chinese (synth.toml.header), no English word, the same digits
    zh = rep.toml_header(d, "zh")
    assert "KKM-30°：" in zh and "曲柄摇杆机构" in zh and _numbers(zh) == _numbers(en)
    assert not CYRILLIC.search(zh) and "crank-rocker" not in zh and "massless" not in zh
    assert tomllib.loads(rep.dumps_toml(d.to_spec(0.5), zh))["mechanism"]["rocker"] == (
        0.5 * d.l3)


def _plot_texts(ax):
    out = [t.get_text() for t in ax.texts]
    out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
    leg = ax.get_legend()
    if leg is not None:
        out += [t.get_text() for t in leg.get_texts()]
    return out


def _figures(lang, phi0=30.0, design=None, mu_required=40.0):
    from linkage import synthesis_plots as sp

    d = design if design is not None else _paper_example()
    phi = np.arange(0.0, 361.0)
    return {"region": sp.plot_region(existence_region(phi0), d,
                                     family=right_angle_family(d.l1, phi0), lang=lang),
            "mu_min": sp.plot_mu_min_curves(syn.mu_min_curves(phi0), d,
                                            mu_required=mu_required, lang=lang),
            "transmission_angle": sp.plot_transmission_angle(
                phi, transmission_angle_deg(phi, d.l1, d.l2, d.l3), d, lang=lang)}


#: The paper's own Russian terms (seed 004, Sereda 2016) each Russian figure carries.
RU_TERMS = {
    "region": ("Область существования ККМ-30°", "область существования ККМ-30°",
               "дуга abc", "кривая cda (μmin = 0)", "прямой Колчина (3)",
               "прямая Колчина (1)", "прямая Колчина (2)", "прямая Колчина (3)",
               "дуга семейства", "ККМ-30° → ККМ-5", "ККМ-30° → ККМ-7", "выбранный механизм",
               "шатун λ2", "коромысло λ3"),
    "mu_min": ("ККМ-30°: минимальный угол передачи μmin в функции λ1 при λ2 = const",
               "требуемый μmin ≥ 40°", "выбранный механизм", "кривошип λ1",
               "минимальный угол передачи μmin", "9: λ2 = 0.90"),
    "transmission_angle": ("угол передачи μ(φ)", "μ = 90° при φ = 30° и 330°",
                           "μmin = 46.39° при φ = 180°", "угол поворота кривошипа φ",
                           "угол передачи μ"),
}
EN_TERMS = {
    "region": ("Region of existence of KKM-30°", "arc abc", "curve cda (μmin = 0)",
               "Kolchin's line (1)", "Kolchin's line (2)", "Kolchin's line (3)",
               "family arc", "KKM-30° → KKM-5", "KKM-30° → KKM-7", "chosen mechanism",
               "coupler λ2", "rocker λ3"),
    "mu_min": ("KKM-30°: μmin over λ1 at constant λ2", "required μmin ≥ 40°",
               "chosen mechanism", "crank λ1", "9: λ2 = 0.90"),
    "transmission_angle": ("transmission angle μ(φ)", "μ = 90° at φ = 30° and 330°",
                           "μmin = 46.39° at φ = 180°", "crank angle φ"),
}


@pytest.fixture(scope="module")
def figures():
    """The three figures of the paper's example in each language, drawn once a module
    (the tests below read their texts, styles and layout; none changes them)."""
    drawn = {}

    def get(lang):
        if lang not in drawn:
            drawn[lang] = _figures(lang)
        return drawn[lang]
    return get


def test_plots_speak_the_report_language_with_the_same_numbers(figures):
    ru, en = figures("ru"), figures("en")
    for key in ru:
        t_ru = "\n".join(_plot_texts(ru[key]))
        t_en = "\n".join(_plot_texts(en[key]))
        assert not CYRILLIC.search(t_en), (key, CYRILLIC.findall(t_en))
        for term in RU_TERMS[key]:
            assert term in t_ru, (key, term)
        for term in EN_TERMS[key]:
            assert term in t_en, (key, term)
        assert _numbers(t_ru) == _numbers(t_en), key
    with pytest.raises(ValueError, match="lang"):
        _figures("de")


def test_region_plot_for_phi0_above_90_names_kolchin_lines_1_2():
    d = design_equal_l2_l3(0.3, 120.0)
    reg = existence_region(120.0)
    assert reg.kolchin_numbers == (1, 2) and existence_region(30.0).kolchin_numbers == (3,)
    from linkage import synthesis_plots as sp

    for lang, want in (("ru", "на прямых Колчина (1)–(2)"),
                       ("en", "on Kolchin's lines (1)–(2)")):
        texts = "\n".join(_plot_texts(sp.plot_region(reg, d, lang=lang)))
        assert want in texts, texts


def _style(line):
    """What tells a curve apart in black-and-white print: dash pattern, width, marker."""
    dashes = getattr(line, "_unscaled_dash_pattern", None)
    return (line.get_linestyle(), str(dashes), line.get_linewidth(), line.get_marker())


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_curves_differ_by_line_style_not_by_colour_only(lang, figures):
    from matplotlib.lines import Line2D

    for key, ax in figures(lang).items():
        handles = [h for h in ax.get_legend().legend_handles if isinstance(h, Line2D)]
        styles = [_style(h) for h in handles]
        assert len(set(styles)) == len(styles), (key, styles)
        labelled = [ln for ln in ax.lines if not ln.get_label().startswith("_")]
        assert len({_style(ln) for ln in labelled}) == len(labelled), key


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_fig3_curves_carry_their_numbers_without_overlap(lang, figures):
    """Each curve of Fig. 3 is numbered on the figure (as in the paper): the numbers 1…9,
    each inside the axes, no two label boxes overlapping, no box on the chosen point."""
    ax = figures(lang)["mu_min"]
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(ax.figure)
    canvas.draw()                                             # the final layout
    r = canvas.get_renderer()
    labels = [t for t in ax.texts if t.get_text().isdigit()]
    assert [t.get_text() for t in labels] == [str(i) for i in range(1, 10)]
    boxes = [t.get_window_extent(r) for t in labels]
    frame = ax.get_window_extent(r)
    for i, b in enumerate(boxes):
        assert frame.x0 <= b.x0 and b.x1 <= frame.x1 and frame.y0 <= b.y0 and b.y1 <= frame.y1
        for c in boxes[i + 1:]:
            assert not b.overlaps(c), (labels[i].get_text(), b, c)
    chosen = ax.transData.transform([[_paper_example().l1, _paper_example().mu_min_deg]])[0]
    assert not any(b.contains(*chosen) for b in boxes)
    # every number sits on its own curve: the curve passes through the label's box
    curves = syn.mu_min_curves(30.0)
    for t, mu in zip(labels, curves.mu_min_deg):
        x, y = t.get_position()
        ok = np.isfinite(mu)
        assert np.interp(x, curves.l1[ok], mu[ok]) == pytest.approx(y, abs=2.0), t.get_text()
