"""The independent judge of linkage.chain over random six-bars of every group kind.

For random mechanisms (hypothesis) of every class II group kind — crank + RRR + RRP (a
press), crank + RPR + RRP (the shaper), crank + RRR + RRR, two RRP on one crank (a V
compressor), crank + RPR + PRP (a slider in the swinging lever's slot pinned to the ram:
a guide on a moving link; and with the second guide on the crank), crank + RRR + RPP
(a yoke on the frame), crank + RRR + RPP with the yoke on the rocker and crank + RRR +
RRP with the guide on the coupler (moving guides), a rod pinned at an earlier group's
inner joint — with random masses, inertias, centres of mass and loads, at random crank
angles, against tests/chain_judge.py (a global loop-closure solve, finite differences,
one global Newton–Euler linear system per position):

* every link's position, velocity, acceleration, ω and ε;
* every pair's reaction (a revolute's force; a prismatic pair's normal force and moment)
  and the driving moment Mур;
* the power balance Mур·ω = −Σ(F·v + M·ω) over all links (applied loads, weight,
  d'Alembert inertia), with the judge's velocities.

A wrong sign, factor or swapped angle in any group routine (e.g. the Coriolis term of the
RPR or PRP group, or the couple of a prismatic pair) moves these by far more than the
finite differences' error (~1e-8 relative).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

from chain_judge import Judge, guess_from
from linkage import chain as ch

SETTINGS = settings(max_examples=12, deadline=None, derandomize=True,
                    phases=(Phase.explicit, Phase.generate),
                    suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])


def _u(t):
    return complex(math.cos(t), math.sin(t))


def unit(lo, hi):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


# ------------------------------------------------------------------ six-bar builders


def press(p):
    """Crank + RRR (crank-rocker) + RRP (rod from the rocker's point D to a ram)."""
    C = p["d0"] * _u(p["a0"])
    D = complex(p["l3"] * p["f1"], p["f2"] * 0.1)
    return ch.Mechanism({"O": 0j, "C": C}, ch.Driver(p["r"]),
                        [ch.RRR(("coupler", "rocker"), ("A", "B", "C"), (p["l2"], p["l3"]),
                                p["sgn"]),
                         ch.RRP(("rod", "ram"), ("D", "E"), p["L"],
                                ch.Guide("frame", C + 0.3 * _u(p["a1"]), p["a2"],
                                         0.05 * p["f2"]), p["sgn2"])],
                        {"rocker": ch.Link(points={"D": D})})


def press_at_b(p):
    """Crank + RRR + RRP with the rod pinned at the dyad's inner joint B (a pin shared by
    three links: the rod's pair is with the rocker, the chain's convention)."""
    mech = press(p)
    g0, g1 = mech.groups
    return ch.Mechanism(mech.frame, mech.driver,
                        [g0, ch.RRP(g1.links, ("B", "E"), g1.length, g1.guide, g1.assembly)])


def shaper(p):
    """Crank + RPR (block in the slotted lever) + RRP (rod from the lever's tip D to the
    ram on a guide)."""
    C = (p["r"] * (1.3 + p["f1"])) * _u(p["a0"])
    D = complex(0.4 + 0.3 * p["f2"], 0.05 * p["f1"])
    return ch.Mechanism({"O": 0j, "C": C}, ch.Driver(p["r"]),
                        [ch.RPR(("block", "lever"), ("A", "C"), 0.02 * p["f2"], p["sgn"]),
                         ch.RRP(("rod", "ram"), ("D", "E"), p["L"],
                                ch.Guide("frame", C + 0.4 * _u(p["a0"] + math.pi * 0.5 * p["sgn"]),
                                         p["a2"]), p["sgn2"])],
                        {"lever": ch.Link(points={"D": D})})


def double_rrr(p):
    """Crank + RRR + RRR (the second dyad from the coupler's point E to a frame pivot F)."""
    C = p["d0"] * _u(p["a0"])
    E = complex(p["l2"] * p["f1"], 0.1 * p["f2"])
    F = E + p["l3"] * _u(p["a1"]) + 0.3 * _u(p["a2"])        # near the coupler's reach
    return ch.Mechanism({"O": 0j, "C": C, "F": F}, ch.Driver(p["r"]),
                        [ch.RRR(("coupler", "rocker"), ("A", "B", "C"), (p["l2"], p["l3"]),
                                p["sgn"]),
                         ch.RRR(("link4", "link5"), ("E", "G", "F"), (p["L"], p["l3"]),
                                p["sgn2"])],
                        {"coupler": ch.Link(points={"E": E})})


def v_compressor(p):
    """Two RRP groups on one crank pin (a V compressor, guides through O)."""
    return ch.Mechanism({"O": 0j}, ch.Driver(p["r"]),
                        [ch.RRP(("rod1", "piston1"), ("A", "B1"), p["L"],
                                ch.Guide("frame", 0j, p["a1"], 0.02 * p["f1"]), 1),
                         ch.RRP(("rod2", "piston2"), ("A", "B2"), p["l2"] + p["r"],
                                ch.Guide("frame", 0j, p["a1"] + 1.0 + p["f2"], 0.0), 1)])


def shaper_prp(p):
    """Crank + RPR + PRP: a slider in the swinging lever's slot (a guide on a moving
    link) pinned at B to the ram on a frame guide."""
    C = (p["r"] * (1.3 + p["f1"])) * _u(p["a0"])
    up = _u(p["a0"] + math.pi)                   # from C towards O
    G = C + 0.5 * up
    return ch.Mechanism({"O": 0j, "C": C}, ch.Driver(p["r"]),
                        [ch.RPR(("block", "lever"), ("A", "C"), 0.0, 1),
                         ch.PRP(("slider", "ram"), ("B",),
                                (ch.Guide("lever", 0.05j * p["f2"], 0.0),
                                 ch.Guide("frame", G, math.atan2(up.imag, up.real)
                                          + 0.5 * math.pi + 0.3 * p["f2"])))])


def prp_two_moving(p):
    """Crank + RPR + PRP with both guides on moving links: a slider in the lever's slot
    pinned at B to a slider on the crank's line (two Coriolis terms)."""
    C = (p["r"] * (1.3 + p["f1"])) * _u(p["a0"])
    return ch.Mechanism({"O": 0j, "C": C}, ch.Driver(p["r"]),
                        [ch.RPR(("block", "lever"), ("A", "C"), 0.01 * p["f2"], p["sgn"]),
                         ch.PRP(("slider", "runner"), ("B",),
                                (ch.Guide("lever", 0.03j * p["f2"], 0.0),
                                 ch.Guide("crank", 0.05j, 0.4 * p["f2"])))])


def yoke(p):
    """Crank + RRR + RPP: a block at the coupler's point E in the slot of a yoke sliding on
    a frame guide."""
    C = p["d0"] * _u(p["a0"])
    E = complex(p["l2"] * p["f1"], 0.1 * p["f2"])
    return ch.Mechanism({"O": 0j, "C": C}, ch.Driver(p["r"]),
                        [ch.RRR(("coupler", "rocker"), ("A", "B", "C"), (p["l2"], p["l3"]),
                                p["sgn"]),
                         ch.RPP(("block", "yoke"), ("E",),
                                ch.Guide("frame", 0.2 * _u(p["a1"]), p["a2"], 0.01),
                                0.5 * math.pi + 0.6 * p["f2"])],
                        {"coupler": ch.Link(points={"E": E})})


def yoke_on_rocker(p):
    """Crank + RRR + RPP: a block pinned at the frame's F in the slot of a yoke that
    slides along the rocker (a moving guide)."""
    C = p["d0"] * _u(p["a0"])
    F = C + 0.5 * _u(p["a1"])
    return ch.Mechanism({"O": 0j, "C": C, "F": F}, ch.Driver(p["r"]),
                        [ch.RRR(("coupler", "rocker"), ("A", "B", "C"), (p["l2"], p["l3"]),
                                p["sgn"]),
                         ch.RPP(("block", "yoke"), ("F",),
                                ch.Guide("rocker", 0.1 + 0.02j, 0.2 * p["f2"]),
                                0.5 * math.pi + 0.6 * p["f1"])])


def rrp_on_coupler(p):
    """Crank + RRR + RRP: a rod from the frame's F to a slider on the coupler's line (a
    moving guide)."""
    C = p["d0"] * _u(p["a0"])
    F = 0.5 * C + 0.3 * _u(p["a1"])
    return ch.Mechanism({"O": 0j, "C": C, "F": F}, ch.Driver(p["r"]),
                        [ch.RRR(("coupler", "rocker"), ("A", "B", "C"), (p["l2"], p["l3"]),
                                p["sgn"]),
                         ch.RRP(("rod", "slider"), ("F", "G"), p["L"],
                                ch.Guide("coupler", 0.01j, 0.1 * p["f2"], 0.02), p["sgn2"])])


BUILDERS = {"press": press, "press-at-B": press_at_b, "shaper": shaper, "rrr-rrr": double_rrr,
            "v-compressor": v_compressor, "shaper-prp": shaper_prp,
            "prp-two-moving": prp_two_moving, "yoke": yoke,
            "yoke-on-rocker": yoke_on_rocker, "rrp-on-coupler": rrp_on_coupler}

PARAMS = st.fixed_dictionaries({
    "r": unit(0.05, 0.15), "d0": unit(0.3, 0.6), "l2": unit(0.25, 0.7),
    "l3": unit(0.2, 0.6), "L": unit(0.3, 0.8), "a0": unit(-math.pi, math.pi),
    "a1": unit(-math.pi, math.pi), "a2": unit(-math.pi, math.pi), "f1": unit(0.2, 1.0),
    "f2": unit(-1.0, 1.0), "sgn": st.sampled_from([1, -1]), "sgn2": st.sampled_from([1, -1]),
    "omega": unit(-30.0, 30.0).filter(lambda w: abs(w) > 1.0), "eps": unit(-50.0, 50.0),
    "phi": st.lists(unit(0.0, 2 * math.pi), min_size=2, max_size=2),
    "seed": st.integers(0, 2 ** 31)})


def _with_inertia(mech, seed):
    """The same mechanism with random masses, inertias and centres of mass."""
    rng = np.random.default_rng(seed)
    links = {n: ch.Link(float(rng.uniform(0.5, 20.0)), float(rng.uniform(0.01, 1.0)),
                        complex(*rng.uniform(-0.1, 0.2, 2)), dict(mech.links[n].points))
             for n in mech.link_names}
    return ch.Mechanism(mech.frame, mech.driver, mech.groups, links), rng


def _margin_ok(mech, res):
    """Every group well away from a dead position at these crank angles."""
    for grp, s in zip(mech.groups, res.solutions):
        if grp.kind == "RRR":
            if np.min(np.abs(s.det)) < 0.15 * grp.lengths[0] * grp.lengths[1]:
                return False
        elif grp.kind == "RRP":
            if np.min(s.h2) < 0.1 * grp.length ** 2:
                return False
        elif grp.kind == "RPR":
            if np.min(np.abs(s.s)) < 0.05:
                return False
        elif np.min(np.abs(np.asarray(s.det) * np.ones(res.phi.shape))) < 0.3:
            return False
    return True


def _case(kind, p):
    mech = BUILDERS[kind](p)
    mech, rng = _with_inertia(mech, p["seed"])
    phi = np.array(p["phi"])
    stencil = (phi[:, None] + np.array([-2, -1, 0, 1, 2]) * 1e-3).ravel()
    try:
        wide = ch.solve(mech, stencil, p["omega"], p["eps"])
    except ch.AssemblyError:
        assume(False)
    assume(_margin_ok(mech, wide))
    res = ch.solve(mech, phi, p["omega"], p["eps"])
    # random loads: a force at a point of every link, a couple on every link
    applied, couples = [], []
    forces, moments = {}, {}
    for n in mech.link_names:
        loc = complex(*rng.uniform(-0.1, 0.3, 2))
        F = complex(*rng.uniform(-500.0, 500.0, 2))
        M = float(rng.uniform(-50.0, 50.0))
        z = res.links[n].point(loc).z
        forces[n] = [(F, z)]
        moments[n] = [M]
        applied.append((n, F, loc))
        couples.append((n, M))
    frc = ch.kinetostatics(res, forces, moments, 9.81)
    return mech, res, frc, applied, couples


def _at(v, i, shape):
    return complex(np.broadcast_to(v.x, shape)[i], np.broadcast_to(v.y, shape)[i])


def _check(kind, p):
    mech, res, frc, applied, couples = _case(kind, p)
    judge = Judge(mech, 9.81)
    shape = res.phi.shape
    for i, phi in enumerate(res.phi):
        q, qd, qdd = judge.motion(phi, guess_from(mech, res, i), p["omega"], p["eps"])
        vscale = abs(p["omega"]) * 1.0 + 1e-3
        ascale = p["omega"] ** 2 + abs(p["eps"]) + 1e-3
        for ln in mech.link_names:
            L = res.links[ln]
            for local in (0j, 0.3 + 0.1j, mech.links[ln].cg):
                P = L.point(local)
                z, v, a = judge.point_motion(q, qd, qdd, ln, local)
                assert abs(_at(P.z, i, shape) - z) < 1e-10, (ln, "z")
                assert abs(_at(P.v, i, shape) - v) < 1e-7 * vscale, (ln, "v")
                assert abs(_at(P.a, i, shape) - a) < 1e-6 * ascale, (ln, "a")
            k = 3 * judge.idx[ln]
            assert res.omega(ln)[i] == pytest.approx(qd[k + 2], abs=1e-7 * vscale), ln
            assert res.eps(ln)[i] == pytest.approx(qdd[k + 2], abs=1e-6 * ascale), ln
        app = [(ln, F, judge.world(q, ln, loc)) for ln, F, loc in applied]
        pairs, M_drive = judge.forces(q, qd, qdd, app, couples)
        fscale = max(abs(x[3]) for x in pairs) + abs(M_drive)
        for kind_, a, b, F, M0 in pairs:
            r = frc.reactions[(a, b)]
            Fc = _at(r.force, i, shape)
            assert abs(Fc - F) < 1e-6 * fscale, (kind_, a, b, Fc, F)
            mc = _cross(_at(r.at, i, shape), Fc) + (
                0.0 if r.couple is None else float(np.broadcast_to(r.couple, shape)[i]))
            assert abs(mc - M0) < 1e-6 * fscale, (kind_, a, b, "moment", mc, M0)
        assert float(frc.M_drive[i]) == pytest.approx(M_drive, abs=1e-6 * fscale)
        # power balance with the judge's velocities and accelerations
        power = float(frc.M_drive[i]) * p["omega"]
        for ln in mech.link_names:
            lk = mech.links[ln]
            k = 3 * judge.idx[ln]
            _, vS, aS = judge.point_motion(q, qd, qdd, ln, lk.cg)
            w, e = qd[k + 2], qdd[k + 2]
            power += _dot(-lk.mass * aS - 1j * lk.mass * 9.81, vS) - lk.inertia * e * w
        for (ln, F, loc), (_, M) in zip(applied, couples):
            _, v, _ = judge.point_motion(q, qd, qdd, ln, loc)
            power += _dot(F, v) + M * qd[3 * judge.idx[ln] + 2]
        assert abs(power) < 1e-6 * fscale * vscale, power


def _cross(a, b):
    return a.real * b.imag - a.imag * b.real


def _dot(a, b):
    return a.real * b.real + a.imag * b.imag


@pytest.mark.parametrize("kind", sorted(BUILDERS))
def test_chain_against_the_global_newton_euler_judge(kind):
    checked = []

    @SETTINGS
    @given(PARAMS)
    def run(p):
        _check(kind, p)
        checked.append(p)
    run()
    assert len(checked) >= 6, f"only {len(checked)} random {kind} mechanisms assembled"
