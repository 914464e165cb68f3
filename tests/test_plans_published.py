"""Published problems solved by velocity and acceleration diagrams, read off our plans.

The books measure their diagrams by hand; our plans are exact, so the printed answers
must agree within the accuracy of a drawing.  The course project of seed 000 reports
0.4–3.4 % for its plans (Table 3.3); we allow 3 % where the book's printed value is a
measured length and say so where a book's measurement is worse.
"""
import math

import pytest

import linkage
import plans


def _plan_value(pp, kind, segment):
    return pp.plans[kind].vector(segment).value


def _angular(pp, q):
    return next(a["value"] for a in pp.angular if a["quantity"] == q)


@pytest.fixture(scope="module")
def khurmi_8_2():
    """R. S. Khurmi & J. K. Gupta, *A Textbook of Theory of Machines*, S. Chand, 2005,
    ch. 8 "Acceleration in Mechanisms", Example 8.2 (problem and measured answers as
    quoted at askfilo.com, "PQRS is a four-bar chain ... qr = 0.333 m/s, sr = 0.426 m/s,
    xr' = 4.7 m/s², yr' = 5.3 m/s²"): four-bar chain PQRS, PS = 200 mm
    fixed, PQ = 62.5 mm, QR = 175 mm, RS = 112.5 mm, crank PQ at 10 rad/s clockwise,
    ∠QPS = 60°, Q and R on the same side of PS.  Here P = O, Q = A, R = B, S = C."""
    spec = {"mechanism": {"kind": "crank-rocker", "name": "khurmi-8-2", "crank": 0.0625,
                          "coupler": 0.175, "rocker": 0.1125, "ground": 0.2, "assembly": 1,
                          "omega_rad_s": -10.0, "gravity_m_s2": 0.0},
            "analysis": {"crank_angles_deg": [60.0]}}
    res = linkage.analyze(spec)
    assert res.kinematics["B_y_m"].iat[0] > 0          # R on Q's side of PS
    return plans.build_plans(res)[0]


def test_khurmi_8_2_velocities(khurmi_8_2):
    pp = khurmi_8_2
    # vQ = ω·PQ = 10 × 0.0625 = 0.625 m/s (computed in the book)
    assert math.isclose(_plan_value(pp, "velocity", "pa"), 0.625, rel_tol=1e-12)
    # "By measurement, vRS = vector sr = 0.426 m/s" (Ex. 8.2)
    assert _plan_value(pp, "velocity", "pb") == pytest.approx(0.426, rel=0.03)
    # ωRS = vRS/RS = 0.426/0.1125 = 3.78 rad/s
    assert _angular(pp, "omega4") == pytest.approx(3.78, rel=0.03)
    # "vRQ = vector qr = 0.333 m/s": ours is 0.3465 m/s (3.9 % more; another drawing of
    # the same problem reads 0.325 m/s): within 5 %
    assert _plan_value(pp, "velocity", "ab") == pytest.approx(0.333, rel=0.05)
    assert _angular(pp, "omega3") == pytest.approx(0.333 / 0.175, rel=0.05)


def test_khurmi_8_2_accelerations(khurmi_8_2):
    pp = khurmi_8_2
    # radial components the book computes from its measured velocities:
    # a^r_QP = ω²·PQ = 6.25 m/s²; a^r_RS = vRS²/RS = 0.426²/0.1125 = 1.613 m/s²
    assert math.isclose(_plan_value(pp, "acceleration", "pi_a"), 6.25, rel_tol=1e-12)
    assert _plan_value(pp, "acceleration", "pi_n4") == pytest.approx(1.613, rel=0.01)
    # "by measurement, a^t_RS = vector yr' = 5.3 m/s²" → αRS = 5.3/0.1125 = 47.1 rad/s²
    assert _plan_value(pp, "acceleration", "n4_b") == pytest.approx(5.3, rel=0.03)
    assert _angular(pp, "eps4") == pytest.approx(5.3 / 0.1125, rel=0.03)
    # "a^t_RQ = vector xr' = 4.7 m/s²" → αQR = 26.9 rad/s².  Exact: 4.09 m/s² and
    # 23.4 rad/s²; the book's short vector is 15 % long (its a^r_RQ = 0.634 m/s² also
    # comes from the measured vRQ = 0.333).  Asserted at the book's own 15 %.
    assert _plan_value(pp, "acceleration", "n3_b") == pytest.approx(4.7, rel=0.15)
    assert _plan_value(pp, "acceleration", "a_n3") == pytest.approx(0.634, rel=0.10)


@pytest.fixture(scope="module")
def khurmi_8_1():
    """Khurmi & Gupta (2005), ch. 8, Example 8.1 (answers as quoted at mechdiploma.com
    and qna.carrieradda.com: vD = 4.1 m/s, aD = 117 m/s²): crank-slider, crank OB = 150 mm,
    rod BA = 600 mm, 300 rpm clockwise, crank at 45° from the inner dead centre (the
    crank turned 45° from pointing at the piston).  D is the rod's mid-point."""
    w = -2 * math.pi * 300 / 60
    spec = {"mechanism": {"kind": "crank-slider", "name": "khurmi-8-1", "crank": 0.15,
                          "coupler": 0.6, "assembly": 1, "omega_rad_s": w,
                          "gravity_m_s2": 0.0},
            "links": {"coupler": {"points": {"D": [0.3, 0.0]}}},
            "analysis": {"crank_angles_deg": [-45.0]}}
    return plans.build_plans(linkage.analyze(spec))[0]


def test_khurmi_8_1(khurmi_8_1):
    pp = khurmi_8_1
    # vB = ω·OB = 31.42 × 0.15 = 4.713 m/s (computed in the book)
    assert _plan_value(pp, "velocity", "pa") == pytest.approx(4.713, rel=1e-3)
    # "By measurement, vD = vector od = 4.1 m/s" (ours 3.995 m/s: 2.6 %)
    assert _plan_value(pp, "velocity", "pd") == pytest.approx(4.1, rel=0.03)
    # "By measurement, aD = vector o'd' = 117 m/s²" (ours 117.31 m/s²)
    assert _plan_value(pp, "acceleration", "pi_d") == pytest.approx(117.0, rel=0.03)
    # the radial component of the crank pin: ω²·OB = 148 m/s²
    assert _plan_value(pp, "acceleration", "pi_a") == pytest.approx(148.0, rel=3e-3)
    # mid-point of the rod: d lies half-way along ab on both plans (similarity theorem)
    V, A = pp.plans["velocity"], pp.plans["acceleration"]
    for P in (V, A):
        assert abs(P.points["d"] - (P.points["a"] + P.points["b"]) / 2) < 1e-9
