"""The output's extremes of a chain (issue #20, speed of a small ``analyze``):
:func:`linkage.chain_analysis.output_extremes` refines each sign change of the output's
rate by a bisection that evaluates a tree of midpoints per solve of the chain
(:func:`linkage.chain_analysis.bisect_rate`).  Its result must be the sequential
bisection's bit for bit: the reference routine below is the code it replaced, and the
two are compared with ``==`` on every bundled chain (every link as the output, both
senses of rotation) and on random chains of every group kind."""
from __future__ import annotations

import glob
import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

import linkage
from crankbase.resources import example_path
from linkage import chain as ch
from linkage import chain_analysis as ca
from test_chain_judge import BUILDERS, PARAMS


def sequential_bisection(rate, lo, hi, r_lo, steps=60):
    """The bisection as output_extremes ran it before: one call of ``rate`` per step."""
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        same = np.sign(rate(mid)) == np.sign(r_lo)
        lo2, hi2 = np.where(same, mid, lo), np.where(same, hi, mid)
        if np.array_equal(lo2, lo) and np.array_equal(hi2, hi):
            break
        lo, hi = lo2, hi2
    return lo, hi


def reference_extremes(mech, output, rotation=1, n=720):
    """output_extremes as it was (the sequential bisection), the reference."""
    phi = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    c, r, _ = ca.output_motion(ch.solve(mech, phi, float(rotation), 0.0), output)
    r1 = np.roll(r, -1)
    idx = np.nonzero((r > 0) & (r1 <= 0) | (r < 0) & (r1 >= 0))[0]
    if len(idx) < 2:
        return None
    lo = phi[idx]

    def rate(x):
        return ca.output_motion(ch.solve(mech, x, float(rotation), 0.0, check=False),
                                output)[1]

    lo, hi = sequential_bisection(rate, lo, lo + 2.0 * math.pi / n, r[idx])
    z = np.mod(0.5 * (lo + hi), 2.0 * math.pi)
    cz, _, _ = ca.output_motion(ch.solve(mech, z, float(rotation), 0.0, check=False), output)
    if ca.output_kind_of(mech, output) == "rocker":
        ref = cz[0]
        cz = ref + np.angle(np.exp(1j * (cz - ref)))
    i_min, i_max = int(np.argmin(cz)), int(np.argmax(cz))
    return float(z[i_min]), float(cz[i_min]), float(z[i_max]), float(cz[i_max])


def _chain_examples():
    out = []
    for path in sorted(glob.glob(os.path.join(os.path.dirname(example_path("shaper.toml")),
                                              "*.toml"))):
        try:
            spec = linkage.load_spec(path)
        except Exception:          # engine specs and the like: not a linkage
            continue
        if isinstance(getattr(spec, "mechanism", None), ch.Mechanism):
            out.append(os.path.basename(path))
    return out


CHAINS = _chain_examples()


def test_every_chain_example_is_compared():
    assert {"shaper.toml", "shaper_cn.toml", "sixbar_rrr.toml", "compressor_v.toml",
            "press6.toml"} <= set(CHAINS)


@pytest.mark.parametrize("name", CHAINS)
def test_extremes_of_every_link_are_the_sequential_bisections(name):
    mech = linkage.load_spec(example_path(name)).mechanism
    found = 0
    for link in mech.link_names:
        for rotation in (1, -1):
            want = reference_extremes(mech, link, rotation)
            for levels in (1, 5, ca.BISECT_LEVELS):
                old, ca.BISECT_LEVELS = ca.BISECT_LEVELS, levels
                try:
                    got = ca.output_extremes(mech, link, rotation)
                finally:
                    ca.BISECT_LEVELS = old
                assert got == want, (link, rotation, levels)
            found += want is not None
    assert found >= 2 * (len(mech.link_names) - 2)      # all but the crank and one more


def test_summary_of_the_shaper_keeps_its_numbers():
    """The shaper example's K and stroke as the sequential bisection gives them."""
    spec = linkage.load_spec(example_path("shaper.toml"))
    p_min, c_min, p_max, c_max = reference_extremes(spec.mechanism, spec.output, 1)
    sm = linkage.analyze(spec).summary
    assert sm.travel == abs(c_max - c_min)
    assert {sm.phi_working_start_deg, sm.phi_working_end_deg} == \
        {math.degrees(p_min) % 360.0, math.degrees(p_max) % 360.0}


@pytest.mark.parametrize("levels", [1, 2, 3, 7, 8, 13])
def test_tree_walk_is_the_bisection_on_a_rate_with_many_sign_changes(levels):
    """A rate whose sign is a hash of the angle's bits (a sign change between almost any
    two floats, as round-off makes near a root): only the same midpoints in the same
    order find the same bracket."""
    def rate(x):
        b = np.asarray(x, float).view(np.uint64)
        return np.where((b * np.uint64(0x9E3779B97F4A7C15)) >> np.uint64(63), 1.0, -1.0)

    rng = np.random.default_rng(7)
    lo = rng.uniform(0.0, 2.0 * math.pi, 9)
    hi = lo + rng.uniform(1e-9, 0.1, 9)
    r_lo = rate(lo)
    for steps in (3, 17, 60):
        want = sequential_bisection(rate, lo, hi, r_lo, steps)
        got = ca.bisect_rate(rate, lo, hi, r_lo, steps, levels)
        assert np.array_equal(got[0], want[0]) and np.array_equal(got[1], want[1])
    assert not np.array_equal(want[1] - want[0], np.zeros(9))


def test_bisection_ends_on_adjacent_floats():
    """A smooth rate: the bracket ends at two adjacent floats around the root."""
    root = 1.2345678901234567
    lo, hi = ca.bisect_rate(lambda x: root - x, np.array([1.0]), np.array([1.5]),
                            np.array([root - 1.0]))
    assert lo[0] <= root <= hi[0] and hi[0] == np.nextafter(lo[0], 2.0)


SETTINGS = settings(max_examples=12, deadline=None, derandomize=True, database=None,
                    phases=(Phase.explicit, Phase.generate),
                    suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])


@pytest.mark.parametrize("kind", sorted(BUILDERS))
def test_random_chains_extremes_are_the_sequential_bisections(kind):
    compared = []

    @SETTINGS
    @given(PARAMS, st.sampled_from([1, -1]))
    def run(p, rotation):
        mech = BUILDERS[kind](p)
        try:
            ch.check_cycle(mech)
        except ch.AssemblyError:
            assume(False)
        for link in mech.link_names:
            want = reference_extremes(mech, link, rotation)
            assert ca.output_extremes(mech, link, rotation) == want, link
            compared.append(want is not None)

    run()
    assert any(compared), kind


def reference_transmission_angles(res):
    """transmission_angles as it was (numpy's modulus of the Vec, new arrays each step)."""
    from linkage import groups as g
    out = {}
    for grp, s in zip(res.mech.groups, res.solutions):
        with np.errstate(invalid="ignore", divide="ignore"):
            if grp.kind == "RRR":
                x = g.cross(s.link3.e, s.link4.e)
            elif grp.kind == "RRP":
                x = g.dot(s.link3.e, s.link4.e)
            elif grp.kind == "RPR":
                d = s.block.origin.z - s.lever.origin.z
                x = g.dot(s.lever.e, d) / np.abs(d)
            elif grp.kind == "PRP":
                x = g.cross(s.link2.e, s.link3.e)
            else:
                x = g.cross(s.block.e, s.yoke.e)
            mu = np.arcsin(np.minimum(np.abs(np.asarray(x, float)), 1.0))
            out["_".join(grp.links)] = mu if mu.shape == res.phi.shape else \
                mu * np.ones(res.phi.shape)
    return out


def _same_bits(a, b):
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


@pytest.mark.parametrize("name", CHAINS)
def test_transmission_angles_are_the_old_formulas_bit_for_bit(name):
    mech = linkage.load_spec(example_path(name)).mechanism
    res = ch.solve(mech, np.linspace(-1.0, 7.0, 3001), 2.0, 0.5)
    got, want = ca.transmission_angles(res), reference_transmission_angles(res)
    assert list(got) == list(want) and all(_same_bits(got[k], want[k]) for k in want)
    one = ch.solve(mech, np.array([0.4]), 2.0, 0.5)                 # a single position
    got, want = ca.transmission_angles(one), reference_transmission_angles(one)
    assert all(_same_bits(got[k], want[k]) for k in want)


@pytest.mark.parametrize("kind", sorted(BUILDERS))
def test_random_chains_transmission_angles_bit_for_bit(kind):
    @SETTINGS
    @given(PARAMS)
    def run(p):
        mech = BUILDERS[kind](p)
        res = ch.solve(mech, np.linspace(0.0, 2.0 * math.pi, 257), p["omega"], p["eps"],
                       check=False)                      # NaN where it cannot assemble
        got, want = ca.transmission_angles(res), reference_transmission_angles(res)
        assert list(got) == list(want)
        for k in want:
            assert _same_bits(got[k], want[k]), k

    run()
