"""linkage.groups: the one implementation of the Assur groups.  Vec arithmetic is the
complex arithmetic it stands for; the routines take complex inputs as the engine passes
them; the README's direct use of the groups runs and closes the loop."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from linkage import groups as g
from linkage.groups import Vec

finite = st.floats(-1e3, 1e3).map(lambda v: v + 0.0)       # no signed zeros
arrays = st.lists(st.tuples(finite, finite), min_size=1, max_size=6)


def _z(pairs):
    return np.array([complex(x, y) for x, y in pairs])


@settings(max_examples=60, deadline=None)
@given(a=arrays, b=arrays, k=finite, c=st.tuples(finite, finite))
def test_vec_arithmetic_is_complex_arithmetic(a, b, k, c):
    n = min(len(a), len(b))
    za, zb, zc = _z(a[:n]), _z(b[:n]), complex(*c)
    va, vb = Vec.of(za), Vec.of(zb)
    cases = [(va + vb, za + zb), (va - vb, za - zb), (-va, -za), (va * vb, za * zb),
             (va * k, za * k), (k * va, k * za), (va * zc, za * zc), (zc * va, zc * za),
             (va.perp(), 1j * za), (1j * va, 1j * za), (va.conj(), np.conj(za)),
             (va + zc, za + zc), (zc - va, zc - za), (zb * va, zb * za)]
    for got, want in cases:
        assert type(got) is Vec
        np.testing.assert_allclose(np.asarray(got), want, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(abs(va), np.abs(za), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(g.cross(va, vb), g.cross(za, zb), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(g.dot(va, vb), (np.conj(za) * zb).real, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(np.angle(va), np.angle(za))      # numpy sees x + iy


def test_constant_zero_components_cost_nothing_and_stay_exact():
    v = Vec(np.array([1.0, 2.0]), np.array([3.0, 4.0]))
    z = v + Vec(0.0, 0.0)
    assert z.x is v.x and z.y is v.y
    w = v + Vec(0.0, 5.0)
    assert w.x is v.x and np.array_equal(w.y, [8.0, 9.0])
    assert np.array_equal(np.asarray(Vec(0.0, 0.0) - v), -np.asarray(v))


def test_groups_take_complex_inputs_as_the_engine_passes_them():
    """Central crank-slider along +y (the engine frame): complex forces and points in a
    Wrench and link_wrench; the crank-pin force against the textbook S = P/cos β."""
    R, L, w = 0.05, 0.2, 300.0
    alpha = np.radians(np.array([20.0, 75.0, 130.0]))
    cr = g.crank(math.pi / 2 + alpha, w, 0.0, R)
    sol = g.rrp(cr.point(R), L, 0j, math.pi / 2, 0.0, +1)
    P = np.array([1000.0, -2000.0, 500.0])             # + towards the crank axis
    u = 1j
    zero = np.zeros(3)
    W3 = g.Wrench(zero + 0j, zero, sol.B.z)            # complex force, Vec point
    W4 = g.link_wrench(sol.link4, forces=[(-P * u, sol.B.z)])
    reac = g.rrp_reactions(sol, L, W3, W4)
    beta = np.arcsin(R / L * np.sin(alpha))
    S = g.dot(-reac.RA, -sol.link3.e)                  # rod force on the pin, + compressing
    np.testing.assert_allclose(S, P / np.cos(beta), rtol=1e-12)
    np.testing.assert_allclose(reac.RG_n, P * np.tan(beta), rtol=1e-12)     # N = P·tg β
    beta_dyad = -np.angle(sol.link3.e * np.conj(np.exp(1j * math.pi / 2)))
    np.testing.assert_allclose(beta_dyad, beta, rtol=1e-12)
    drv = g.driver_reactions(cr, sol.link3.origin.z, -reac.RA,
                             g.Wrench(zero + 0j, zero, cr.origin.z))
    T = g.dot(-reac.RA, 1j * cr.e)
    np.testing.assert_allclose(-drv.M_drive, T * R, rtol=1e-12)
    # per-position indexing of a constant direction (the guide) gives that direction
    assert np.asarray(sol.link4.e[1]) == pytest.approx(1j, abs=1e-15)
    assert np.asarray(sol.B.z[2]) == pytest.approx(np.asarray(sol.B.z)[2])


def test_readme_example_closes_the_loop():
    phi = np.radians(np.arange(0, 360, 0.1))
    crank = g.crank(phi, omega=17.0, eps=0.0, length=0.175)
    A = crank.point(0.175)
    C = g.PointMotion(0.54 + 0j, 0j, 0j)
    dyad = g.rrr(A, C, 0.55, 0.325, assembly=1)
    W3 = g.link_wrench(dyad.link3, mass=17, inertia=0.51, cg=0.24, gravity=9.81)
    W4 = g.link_wrench(dyad.link4, mass=17, inertia=0.18, cg=0.14, gravity=9.81)
    r = g.rrr_reactions(dyad, 0.55, 0.325, W3, W4)
    d = g.driver_reactions(crank, A.z, -r.RA, g.link_wrench(crank, 16, 0, 0.08, 9.81))
    np.testing.assert_allclose(abs(dyad.B.z - A.z), 0.55, rtol=1e-12)
    np.testing.assert_allclose(abs(dyad.B.z - C.z), 0.325, rtol=1e-12)
    assert np.all(np.isfinite(d.M_drive)) and d.M_drive.shape == phi.shape
    # the coupler's equilibrium with the reactions the dyad returns
    np.testing.assert_allclose(np.asarray(r.RA + r.RB + W3.force), 0.0, atol=1e-9)


def test_points_are_kept_once_per_link():
    cr = g.crank(np.array([0.1, 0.2]), 2.0, 0.0)
    assert cr.point(0.3) is cr.point(0.3 + 0j)
    assert cr.point(0.3) is not cr.point(0.3 + 0.1j)
