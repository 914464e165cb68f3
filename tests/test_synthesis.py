"""Tests of linkage.synthesis: the ККМ-φ0 families (seed 004, Sereda 2016).

Layers: the paper's printed numbers (cited beside each assertion) → exact reductions of the
general-φ0 formulas to the paper's φ0 = 30° equations → an independent method (angles from
the assembled joint positions) → hypothesis properties over random φ0 and random admissible
mechanisms, checked through the kinematic core (to_spec → load_spec → analyze).
"""
from __future__ import annotations

import math
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
def test_transmission_angle_from_joint_positions():
    phi = np.linspace(0, 359, 360)
    for l1, l2, l3 in [(0.3240740, 1.0185185, 0.6018519),   # seed 000 ratchet / OC = 0.54
                       (0.09142873454295534, 0.7, 0.6), (0.2, 0.9, 0.6)]:
        for asm in (1, -1):
            np.testing.assert_allclose(transmission_angle_deg(phi, l1, l2, l3),
                                       mu_from_joints(phi, l1, l2, l3, asm), atol=1e-9)


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
                min(syn._kolchin_residuals(l1, l2, l3)) > -1e-12
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
    # s + l = p + q within 1e-12 relative is a change point
    assert grashof(0.3 * (1 + 1e-13), 0.7, 0.6) is GrashofType.CHANGE_POINT
    assert grashof(0.3 * (1 + 1e-9), 0.7, 0.6) is GrashofType.NON_GRASHOF
    assert grashof(0.3 * (1 - 1e-9), 0.7, 0.6) is GrashofType.CRANK_ROCKER
    assert str(GrashofType.CRANK_ROCKER) == "crank-rocker"
    assert set(GrashofType.__members__) == {"CRANK_ROCKER", "DOUBLE_CRANK", "DOUBLE_ROCKER",
                                            "CHANGE_POINT", "NON_GRASHOF"}


def test_grashof_errors():
    with pytest.raises(GeometryError) as e:
        grashof(-1, 0.5, float("nan"))
    assert isinstance(e.value, ValueError)
    lines = e.value.lines()
    assert len(lines) == 2 and lines[0].startswith("l1:") and lines[1].startswith("l3:")


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


def test_transmission_angle_nan_where_not_assemblable():
    mu = transmission_angle_deg([0.0, 180.0], 0.5, 0.6, 0.7)
    assert np.isfinite(mu[0]) and np.isnan(mu[1])


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
