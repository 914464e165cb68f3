"""Kinematics of one cylinder's crank-slider (engine.kinematics): the dyad path against the
closed-form textbook formulas (central and offset mechanism), derivatives, and the three
placement parameters (bank, pin offset, phase)."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.forces import two_term_acceleration
from engine.kinematics import crank_slider, guide_direction, piston_travel


def offset_closed_form(alpha, R, L, e, w):
    """Offset (désaxé) crank-slider in its guide frame, written independently of the
    dyad: A = R(cos α, sin α), B = (s, e), s = R cos α + √(L² − (R sin α − e)²)
    (Kolchin & Demidov, 2008, "дезаксиальный КШМ"; sign of e as in engine.kinematics)."""
    y = R * np.sin(alpha) - e
    root = np.sqrt(L ** 2 - y ** 2)
    s = R * np.cos(alpha) + root
    x = np.sqrt((L + R) ** 2 - e ** 2) - s
    # ṡ/ω and s̈/ω² by differentiating s(α) by hand
    ds = -R * np.sin(alpha) - y * R * np.cos(alpha) / root
    dy = R * np.cos(alpha)
    d2s = (-R * np.cos(alpha) - (dy * dy + y * (-R * np.sin(alpha))) / root
           - (y * dy) ** 2 / root ** 3)
    beta = np.arcsin(y / L)
    return x, -ds * w, -d2s * w * w, beta


def test_closed_form_kinematics_match_the_dyad():
    lam, R, w = 0.3, 0.05, 400.0
    alpha = np.radians(np.linspace(0, 720, 1441))
    m = crank_slider(alpha, R, R / lam, w)
    s2 = np.sin(alpha) ** 2
    root = np.sqrt(1 - lam ** 2 * s2)
    x = R * ((1 - np.cos(alpha)) + (1 - root) / lam)
    v = R * w * (np.sin(alpha) + lam * np.sin(2 * alpha) / (2 * root))
    j = R * w ** 2 * (np.cos(alpha) + lam * (np.cos(2 * alpha) + lam ** 2 * s2 ** 2) / root ** 3)
    np.testing.assert_allclose(m.x, x, rtol=1e-9, atol=1e-12 * R)
    np.testing.assert_allclose(m.v, v, rtol=1e-9, atol=1e-12 * R * w)
    np.testing.assert_allclose(m.j, j, rtol=1e-9, atol=1e-12 * R * w * w)
    np.testing.assert_allclose(m.beta, np.arcsin(lam * np.sin(alpha)), atol=1e-12)
    assert m.travel == 2 * R
    # the two-term acceleration is the textbook approximation of j: error ~ λ³
    j2 = two_term_acceleration(alpha, R, lam, w)
    assert np.max(np.abs(j2 - j)) < 0.05 * R * w * w


def test_piston_velocity_is_derivative_of_displacement():
    lam, R, w = 0.27, 0.0625, 230.0
    h = 1e-6
    a = np.radians(np.arange(0, 360, 5.0))
    m = crank_slider(a, R, R / lam, w)
    dx = (crank_slider(a + h, R, R / lam, w).x - crank_slider(a - h, R, R / lam, w).x) / (2 * h)
    np.testing.assert_allclose(m.v, dx * w, rtol=1e-6, atol=1e-8)


@pytest.mark.parametrize("e", [0.012, -0.009])
def test_offset_mechanism_matches_its_closed_form(e):
    R, L, w = 0.045, 0.15, 500.0
    alpha = np.radians(np.linspace(0, 720, 2881))
    m = crank_slider(alpha, R, L, w, offset=e)
    x, v, j, beta = offset_closed_form(alpha, R, L, e, w)
    np.testing.assert_allclose(m.x, x, rtol=1e-9, atol=1e-12 * R)
    np.testing.assert_allclose(m.v, v, rtol=1e-9, atol=1e-11 * R * w)
    np.testing.assert_allclose(m.j, j, rtol=1e-9, atol=1e-11 * R * w * w)
    np.testing.assert_allclose(m.beta, beta, atol=1e-12)
    # sign convention: e > 0 lowers β (and so N) after TDC: sin β = λ(sin α − k)
    k = e / R
    np.testing.assert_allclose(np.sin(m.beta), R / L * (np.sin(alpha) - k), atol=1e-12)
    # TDC and BDC: x = 0 at the real TDC (crank and rod in line), the travel at BDC
    a_tdc = np.arcsin(e / (L + R))
    a_bdc = np.pi + np.arcsin(e / (L - R))
    ends = crank_slider(np.array([a_tdc, a_bdc]), R, L, w, offset=e)
    assert abs(ends.x[0]) < 1e-15
    assert ends.x[1] == pytest.approx(m.travel, rel=1e-12)
    assert m.travel == pytest.approx(piston_travel(R, L, e)) and m.travel > 2 * R
    assert np.max(m.x) == pytest.approx(m.travel, rel=1e-6)
    np.testing.assert_allclose(ends.v, 0, atol=1e-10 * R * w)
    # the two-term acceleration with the offset term is the first-order approximation
    j2 = two_term_acceleration(alpha, R, R / L, w, k)
    assert np.max(np.abs(j2 - j)) < 0.05 * R * w * w
    assert np.max(np.abs(two_term_acceleration(alpha, R, R / L, w) - j)) > \
        2 * np.max(np.abs(j2 - j))


def test_offset_derivatives():
    R, L, w, e = 0.05, 0.17, 300.0, 0.01
    h = 1e-6
    a = np.radians(np.arange(0, 360, 7.0))

    def at(x):
        return crank_slider(x, R, L, w, offset=e)
    np.testing.assert_allclose(at(a).v, (at(a + h).x - at(a - h).x) / (2 * h) * w,
                               rtol=1e-6, atol=1e-8)
    np.testing.assert_allclose(at(a).j, (at(a + h).v - at(a - h).v) / (2 * h) * w,
                               rtol=1e-6, atol=1e-5)


@settings(max_examples=30, deadline=None)
@given(bank=st.floats(-180, 180), phase=st.floats(-720, 720), e=st.floats(-0.01, 0.01))
def test_bank_rotates_phase_shifts(bank, phase, e):
    """A banked cylinder is the same mechanism turned by the bank angle: its x, v, j, β
    equal the upright one's at the same α = θ − phase, and every point is rotated."""
    R, L, w = 0.04, 0.14, 600.0
    theta = np.radians(np.arange(0, 720, 15.0))
    b, ph = np.radians(bank), np.radians(phase)
    m = crank_slider(theta, R, L, w, bank=b, offset=e, phase=ph)
    ref = crank_slider(theta - ph, R, L, w, offset=e)
    np.testing.assert_allclose(m.alpha, theta - ph)
    for k in ("x", "v", "j"):
        np.testing.assert_allclose(getattr(m, k), getattr(ref, k), rtol=1e-9,
                                   atol=1e-9 * R * w * w)
    np.testing.assert_allclose(np.sin(m.beta - ref.beta), 0, atol=1e-12)
    rot = np.exp(1j * b)
    np.testing.assert_allclose(m.dyad.B.z, ref.dyad.B.z * rot, atol=1e-12)
    np.testing.assert_allclose(m.dyad.B.a, ref.dyad.B.a * rot, atol=1e-8 * R * w * w)
    assert np.asarray(m.dyad.link4.e).ravel()[0] == pytest.approx(guide_direction(b))
    # the piston moves along its own axis
    u = guide_direction(b)
    np.testing.assert_allclose((m.dyad.B.v * np.conj(u)).imag, 0, atol=1e-9 * R * w)
