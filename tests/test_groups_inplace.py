"""linkage.groups writes a sum into the fresh product it adds (``_vadd`` …, ``_into``): the
same floating-point operations in the same order as the operator-by-operator formulas,
hence the same bits, and never into an input (a joint's motion, a load, a constant).

The references below are the routines' formulas written with the plain :class:`Vec`
operators (as they read before the in-place writes); the arrays hold signed zeros,
values that cancel exactly and a NaN, where a reordered or skipped operation would show.
"""
import math

import numpy as np
import pytest

from linkage import groups as g
from linkage.groups import Vec


def _bits(x):
    return np.asarray(x, float).view(np.int64)


def _same(got, want):
    """Bit for bit, Vec or array or float (signed zeros and NaN included)."""
    if isinstance(want, Vec):
        _same(got.x, want.x)
        _same(got.y, want.y)
        return
    assert np.array_equal(_bits(np.broadcast_to(got, np.shape(want))), _bits(want))


def _arrays(seed, n=257):
    rng = np.random.default_rng(seed)
    x = rng.standard_normal(n)
    x[:4] = (0.0, -0.0, 1.0, -1.0)          # signed zeros, exact cancellations
    x[4] = np.nan
    return x


def _point(seed, moving=True, n=257):
    mk = (lambda k: Vec(_arrays(seed + k, n), _arrays(seed + k + 1, n))) if moving else \
        (lambda k: Vec(0.0, 0.0))
    return g.PointMotion(mk(0), mk(2), mk(4))


def _copy(v):
    return Vec(np.copy(v.x), np.copy(v.y)) if isinstance(v, Vec) else np.copy(v)


def _unchanged(before, after):
    for b, a in zip(before, after):
        _same(a, b)


def _ref_point(link, local):
    """LinkMotion._point with the plain operators."""
    o = link.origin
    r = link.e * local.real
    ir = r.perp()
    v = o.v + ir * link.omega
    a = o.a + ir * link.eps + r * (-(link.omega * link.omega))
    return o.z + r, v, a


@pytest.mark.parametrize("origin_moves", [True, False])
@pytest.mark.parametrize("eps", ["array", 0.0])
def test_point_same_bits_inputs_untouched(origin_moves, eps):
    o = _point(10, origin_moves)
    e = Vec(np.cos(_arrays(1)), np.sin(_arrays(1)))
    w = _arrays(3)
    ep = _arrays(5) if eps == "array" else 0.0
    link = g.LinkMotion(o, e, w, ep)
    kept = [_copy(o.z), _copy(o.v), _copy(o.a), _copy(e), _copy(w)]
    P = link.point(0.37)
    want = _ref_point(link, 0.37 + 0j)
    _same(P.z, want[0])
    _same(P.v, want[1])
    _same(P.a, want[2])
    _unchanged(kept, [o.z, o.v, o.a, e, w])


def _ref_rrr(A, C, l3, l4, assembly):
    d = C.z - A.z
    D2 = g.dot(d, d)
    iD = 1.0 / np.sqrt(D2)
    p = (l3 * l3 - l4 * l4 + D2) * (0.5 * iD)
    h2 = l3 * l3 - p * p
    h = np.sqrt(np.maximum(h2, 0.0))
    ed = d * iD
    zB = A.z + ed * p + ed.perp() * (h if assembly > 0 else -h)
    r3, r4 = zB - A.z, zB - C.z
    idet = 1.0 / g.cross(r3, r4)
    dv = C.v - A.v
    w3, w4 = g.dot(r4, dv) * idet, g.dot(r3, dv) * idet
    r3w3sq, r4w4sq = r3 * (w3 * w3), r4 * (w4 * w4)
    da = C.a - A.a + r3w3sq - r4w4sq
    e3, e4 = g.dot(r4, da) * idet, g.dot(r3, da) * idet
    ir3 = r3.perp()
    return zB, A.v + ir3 * w3, A.a + ir3 * e3 - r3w3sq, w3, w4, e3, e4, h2


@pytest.mark.parametrize("c_moves", [True, False])
@pytest.mark.parametrize("assembly", [1, -1])
def test_rrr_same_bits_inputs_untouched(c_moves, assembly):
    phi = np.linspace(0.0, 2.0 * math.pi, 361)
    A = g.crank(phi, 17.0, 3.0).point(0.175)
    C = _point(20, n=361) if c_moves else g.PointMotion(Vec(0.54, 0.0), Vec(0.0, 0.0),
                                                 Vec(0.0, 0.0))
    if c_moves:                 # near the crank's pivot, so the dyad closes somewhere
        C = g.PointMotion(Vec(0.54 + 0.01 * C.z.x, 0.01 * C.z.y), C.v, C.a)
    kept = [_copy(v) for v in (A.z, A.v, A.a, C.z, C.v, C.a)]
    with np.errstate(all="ignore"):
        s = g.rrr(A, C, 0.55, 0.325, assembly)
        want = _ref_rrr(A, C, 0.55, 0.325, assembly)
    got = (s.B.z, s.B.v, s.B.a, s.link3.omega, s.link4.omega, s.link3.eps, s.link4.eps,
           s.h2)
    for a, b in zip(got, want):
        _same(a, b)
    _unchanged(kept, [A.z, A.v, A.a, C.z, C.v, C.a])


def test_wrench_and_reactions_same_bits_loads_untouched():
    phi = np.linspace(0.0, 2.0 * math.pi, 361)
    cr = g.crank(phi, 17.0, 0.0)
    A = cr.point(0.175)
    C = g.PointMotion(Vec(0.54, 0.0), Vec(0.0, 0.0), Vec(0.0, 0.0))
    with np.errstate(all="ignore"):
        s = g.rrr(A, C, 0.55, 0.325, 1)
        f = Vec(_arrays(7, 361), _arrays(8, 361))
        at = s.link3.point(0.3).z
        m = _arrays(9, 361)
        kept = [_copy(f), _copy(at), _copy(m)]
        W3 = g.link_wrench(s.link3, 17.0, 0.51, 0.24, 9.81, [(f, at)], [m, 2.5])
        W4 = g.link_wrench(s.link4, 17.0, 0.18, 0.14, 9.81, [], [m])
        S3, S4 = s.link3.point(0.24), s.link4.point(0.14)
        # the plain operators: force, then the moment about S
        F3 = S3.a * (-17.0) + Vec(0.0, -17.0 * 9.81) + f
        M3 = s.link3.eps * (-0.51) + g.cross(at - S3.z, f) + m + 2.5
        _same(W3.force, F3)
        _same(W3.moment, M3)
        _same(W4.moment, s.link4.eps * (-0.18) + m)
        r = g.rrr_reactions(s, 0.55, 0.325, W3, W4)
        t3 = (W3.moment + g.cross(W3.point - s.B.z, W3.force)) * (1.0 / 0.55)
        t4 = (W4.moment + g.cross(W4.point - s.B.z, W4.force)) * (1.0 / 0.325)
        T3, T4 = s.link3.e.perp() * t3, s.link4.e.perp() * t4
        W = -(W3.force + W4.force + T3 + T4)
        idet = 1.0 / g.cross(s.link3.e, s.link4.e)
        n3, n4 = g.cross(W, s.link4.e) * idet, g.cross(s.link3.e, W) * idet
        RA = s.link3.e * n3 + T3
        _same(r.RA_t, t3)
        _same(r.RC_t, t4)
        _same(r.RA_n, n3)
        _same(r.RC_n, n4)
        _same(r.RA, RA)
        _same(r.RC, s.link4.e * n4 + T4)
        _same(r.RB, -(RA + W3.force))
        W2 = g.link_wrench(cr, 16.0, 0.0, 0.08, 9.81)
        dr = g.driver_reactions(cr, A.z, -r.RA, W2)
        _same(dr.M_drive, -g.cross(A.z - cr.origin.z, -r.RA)
              - (W2.moment + g.cross(W2.point - cr.origin.z, W2.force)))
    _unchanged(kept, [f, at, m])


def test_in_place_only_into_fresh_float64():
    t = np.arange(4.0)
    assert g._into(np.add, t, 1.0) is t                      # written into t
    t32 = np.arange(4, dtype=np.float32)
    got = g._into(np.add, t32, np.full(4, 0.1))              # float64 result: a new array
    assert got.dtype == np.float64 and got is not t32
    assert np.array_equal(t32, np.arange(4, dtype=np.float32))
    short = np.arange(1.0, 2.0)
    assert g._into(np.multiply, short, np.arange(3.0)).shape == (3,)   # broadcasts: new
    assert g._add_to(t, 0.0) is t and g._add_first(0.0, t) is t       # a constant 0 skipped
    assert g._neg_to(2.0) == -2.0 and g._sqrt_to(4.0) == 2.0


def test_scalars_stay_python_numbers():
    # the plans compute the lever with Python complex numbers: a numpy scalar there would
    # send later complex products and magnitudes through numpy's own loops (other bits)
    for value in (g.cross(1.5 + 2j, 3 - 4j), g.dot(1.5 + 2j, 3 - 4j),
                  g._into(np.subtract, 1.0, 2.0), g._rinto(np.divide, 1.0, 4.0)):
        assert type(value) is float
    assert g.cross(1.5 + 2j, 3 - 4j) == 1.5 * -4.0 - 2.0 * 3.0
    w = g.Wrench(Vec(1.0, 2.0), 0.5, Vec(0.25, 0.0))
    assert type(w.moment_about(Vec(0.0, 0.0))) is float


@pytest.mark.parametrize("origin_moves", [True, False])
@pytest.mark.parametrize("omega", ["array", 1.7, 0.0])
@pytest.mark.parametrize("local", [0.37, 0.2 - 0.45j])
def test_point_into_rows_same_bits_as_without(origin_moves, omega, local):
    """LinkMotion.point(local, out=rows) (the chain's tables: the point written straight
    into its rows) gives the bits of point(local) — NaN payloads, signed zeros, a fixed
    origin's float zeros and a constant ω (a fill) included — and returns the rows."""
    def link():
        o = _point(10, origin_moves)
        e = Vec(np.cos(_arrays(1)), np.sin(_arrays(1)))
        e.x[6] = np.float64(np.nan) * -1.0          # a NaN of the other sign: its operand
        w = _arrays(3) if omega == "array" else omega
        return g.LinkMotion(o, e, w, _arrays(5) if omega == "array" else 0.0)

    want = link().point(local)
    lk = link()
    kept = [_copy(lk.origin.z), _copy(lk.origin.v), _copy(lk.origin.a), _copy(lk.e)]
    rows = tuple(np.full(257, 12345.0) for _ in range(6))
    got = lk.point(local, rows)
    ref = (want.z.x, want.z.y, want.v.x, want.v.y, want.a.x, want.a.y)
    for r, c, w in zip(rows, (got.z.x, got.z.y, got.v.x, got.v.y, got.a.x, got.a.y), ref):
        assert c is r                               # computed into the rows themselves
        _same(r, np.broadcast_to(w, r.shape))       # (a float zero: filled)
    _unchanged(kept, [lk.origin.z, lk.origin.v, lk.origin.a, lk.e])
    assert lk.point(local) is got                   # kept, as without rows


def _ref_rrp_tail(A, u, r3, w3, mden):
    """rrp's velocity and acceleration with the plain operators (before the sums into
    the fresh products)."""
    ir3 = r3.perp()
    v = g.dot(u, A.v + ir3 * w3)
    rhs = A.a - r3 * (w3 * w3)
    e3 = g.cross(u, rhs) * mden
    return v, e3, g.dot(u, rhs + ir3 * e3)


@pytest.mark.parametrize("a_moves", [True, False])
def test_rrp_same_bits_inputs_untouched(a_moves):
    A = _point(30)
    if not a_moves:                          # standing still: float-zero v and a
        A = g.PointMotion(A.z, Vec(0.0, 0.0), Vec(0.0, 0.0))
    kept = [_copy(A.z), _copy(A.v), _copy(A.a)]
    sol = g.rrp(A, 2.5, 0.1 + 0.2j, 0.3, 0.05, 1)
    u = Vec(float(np.cos(0.3)), float(np.sin(0.3)))
    r3 = sol.B.z - A.z
    mden = -1.0 / g.dot(u, r3)
    v, e3, a = _ref_rrp_tail(A, u, r3, g.cross(u, A.v) * mden, mden)
    _same(sol.v, v)
    _same(sol.link3.eps, e3)
    _same(sol.a, a)
    _unchanged(kept, [A.z, A.v, A.a])


@pytest.mark.parametrize("c_moves", [True, False])
def test_rpr_pin_on_lever_same_bits_inputs_untouched(c_moves):
    """rpr's point of the lever under the block (A3): C.v + i(A−C)·ω and
    C.a + i(A−C)·ε − (A−C)·ω², as the plain operators give them."""
    A, C = _point(40), _point(50, c_moves)
    kept = [_copy(A.z), _copy(A.v), _copy(A.a), _copy(C.z), _copy(C.v), _copy(C.a)]
    with np.errstate(all="ignore"):              # (the zeros and the NaN of the data)
        sol = g.rpr(A, C, 0.0, 1)
    d = A.z - C.z
    w, eps = sol.lever.omega, sol.lever.eps
    _same(sol.A_lever.v, C.v + d.perp() * w)
    _same(sol.A_lever.a, C.a + d.perp() * eps - d * (w * w))
    _unchanged(kept, [A.z, A.v, A.a, C.z, C.v, C.a])
