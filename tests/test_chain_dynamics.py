"""Machine dynamics, shaking force and Zhukovsky's lever of any chain (issue #20).

* Today's crank-rocker and crank-slider (the bundled dynamics examples): the chain's
  reduced model (:mod:`dynamics.chain_model`, now the implementation of
  ``dynamics.reduced.linkage_model``) equals the reduction written out on the old
  mechanism's own kinematics (``linkage.mechanisms``'s ``kinematics``), and the true motion
  and the flywheel run on it; the shaking force of the chain equals the old formula.
* Random six-bars of every group kind (the generators of tests/test_chain_judge.py) with
  random masses, loads, ω₁ and ε₁:
  - dJ_red/dφ equals a central difference of J_red over the crank angle, and J_red
    equals Σ(m v_S² + J_S ω²)/ω₁² with the velocities of the independent judge
    (tests/chain_judge.py: a global loop-closure solve and finite differences);
  - the energy identity against the kinetostatics (group by group): the driving moment
    Mур = −M_red + J_red ε₁ + ½ ω₁² dJ_red/dφ at every position (the equation of motion
    in the energy form; a wrong factor ½, a sign of the weights or of the loads' power
    breaks it);
  - the shaking force −Σ m a_S and moment = the frame's reactions summed (with the
    stator's −Mур) at every position, about the pivot and about another point;
  - Zhukovsky's lever's Mур = the kinetostatics' Mур at every position.
"""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest
from hypothesis import given

from chain_judge import Judge, guess_from
from crankbase.resources import example_path
from dynamics.chain_model import (chain_model, chain_shaking, frame_load, reduced_inertia,
                                  reduced_moment)
from dynamics.motion import size_flywheel, steady_motion
from dynamics.reduced import linkage_model, stroke_extremes
from linkage import chain as ch
from linkage.chain_lever import zhukovsky
from linkage.groups import cross, dot, inertia_load
from test_chain_judge import BUILDERS, PARAMS, SETTINGS, _case


def _linkage_data(name):
    with open(example_path(name), "rb") as f:
        data = tomllib.load(f)
    return {k: v for k, v in data.items() if k in ("mechanism", "links", "load", "analysis")}


TODAY = ["press_dynamics.toml", "ratchet.toml", "ratchet.toml-cw"]


def _old_reduction(spec):
    """The reduction written out on the old mechanism's kinematics (today's crank-rocker
    or crank-slider class, not the chain): J_red, dJ_red/dφ, M_resist."""
    from linkage.analysis import build_mechanism
    from linkage.loads import external_loads, stroke_cycle

    mech = build_mechanism(spec)
    s = 1 if spec.omega >= 0 else -1
    ext = stroke_extremes(spec, mech)
    phi0 = ext.phi_start if ext is not None else 0.0
    phi = np.linspace(0.0, 2 * math.pi, 721)
    kin = mech.kinematics(phi0 + s * phi, float(s), 0.0)
    J = dJ = P = 0.0
    for n in spec.link_names:
        ls, L = spec.links[n], kin["links"][n]
        S = L.point(ls.cg)
        J = J + ls.mass * dot(S.v, S.v) + ls.inertia * L.omega ** 2
        dJ = dJ + 2 * ls.mass * dot(S.v, S.a) + 2 * ls.inertia * L.omega * L.eps
        P = P - ls.mass * spec.gravity * S.v.imag
    forces, moments, _ = external_loads(spec, mech, kin, stroke_cycle(mech, spec, ext))
    for n in spec.link_names:
        L = kin["links"][n]
        for f, at in forces[n]:
            P = P + dot(f, L.origin.v + (at - L.origin.z).perp() * L.omega)
        for m in moments[n]:
            P = P + m * L.omega
    return phi, J, dJ, -P


@pytest.mark.parametrize("name", TODAY)
def test_today_reduced_model_is_the_chain_one(name):
    from linkage import load_spec

    data = _linkage_data(name.removesuffix("-cw"))
    if name.endswith("-cw"):                  # the crank turning clockwise
        data["mechanism"]["omega_rad_s"] = -data["mechanism"]["omega_rad_s"]
    spec = load_spec(data)
    model = linkage_model(spec)
    assert isinstance(model.extra["chain"].mech, ch.Mechanism)       # solved as a chain
    phi, J, dJ, Mc = _old_reduction(spec)
    np.testing.assert_allclose(model.phi, phi, rtol=0, atol=1e-15)
    scale = np.max(np.abs(J))
    np.testing.assert_allclose(model.J_kgm2, J, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(model.dJ_dphi_kgm2, dJ, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(model.M_resist_Nm, Mc, rtol=0,
                               atol=1e-12 * np.max(np.abs(Mc)))
    # the true motion and the flywheel run on the chain's model
    fw = size_flywheel(model, 0.05, abs(spec.omega))
    assert fw.motion.delta == pytest.approx(0.05, rel=1e-6)
    assert fw.J_exact == pytest.approx(fw.J_classic, rel=0.15)
    motion = steady_motion(model, abs(spec.omega), J_flywheel=fw.J_exact)
    assert motion.delta == pytest.approx(0.05, rel=1e-6)
    assert motion.omega_mean == pytest.approx(abs(spec.omega), rel=1e-9)


@pytest.mark.parametrize("name", ["press.toml", "ratchet.toml"])
def test_today_shaking_is_the_chain_one(name):
    """The old formula on the old mechanism's kinematics."""
    from linkage import load_spec
    from linkage.analysis import build_mechanism

    spec = load_spec(_linkage_data(name))
    mech = build_mechanism(spec)
    phi = np.radians(np.arange(0.0, 360.0, 7.0))
    kin = mech.kinematics(phi, spec.omega, spec.epsilon)
    F = 0j * phi
    M = 0.0 * phi
    for n in spec.link_names:
        ls, L = spec.links[n], kin["links"][n]
        S = L.point(ls.cg)
        Fu, Mu = inertia_load(S.a, L.eps, ls.mass, ls.inertia)
        F = F + Fu
        M = M + Mu + cross(S.z - mech.pivot, Fu)
    res = ch.solve(ch.from_mechanism(mech, spec.links), phi, spec.omega, spec.epsilon)
    sh = chain_shaking(res)
    assert sh.about == mech.pivot
    np.testing.assert_allclose(np.asarray(sh.F), F, rtol=0, atol=1e-12 * np.max(np.abs(F)))
    np.testing.assert_allclose(sh.M, M, rtol=0, atol=1e-12 * np.max(np.abs(M)))


# ------------------------------------------------------------------- random six-bars


def _loads(mech, res, applied, couples):
    forces = {n: [(F, res.links[n].point(loc).z)] for n, F, loc in applied}
    moments = {n: [M] for n, M in couples}
    return forces, moments


def _check(kind, p):
    mech, res, frc, applied, couples = _case(kind, p)
    forces, moments = _loads(mech, res, applied, couples)
    w1, e1 = p["omega"], p["eps"]
    J, dJ = reduced_inertia(ch.solve(mech, res.phi, 1.0, 0.0))
    # J_red does not depend on ω₁; dJ only at ε₁ = 0 (so at unit speed)
    J_w, _ = reduced_inertia(ch.solve(mech, res.phi, w1, 0.0))
    np.testing.assert_allclose(J_w, J, rtol=1e-12)
    # dJ_red/dφ against a central difference of J_red
    h = 1e-5
    Jp, _ = reduced_inertia(ch.solve(mech, res.phi + h, 1.0, 0.0))
    Jm, _ = reduced_inertia(ch.solve(mech, res.phi - h, 1.0, 0.0))
    np.testing.assert_allclose(dJ, (Jp - Jm) / (2 * h), rtol=0,
                               atol=1e-6 * (np.max(np.abs(J)) + np.max(np.abs(dJ))))
    # the energy identity against the group-by-group kinetostatics at ω₁, ε₁
    M_loads, M_w = reduced_moment(res, forces, moments, 9.81)
    M_loads1, M_w1 = reduced_moment(ch.solve(mech, res.phi, 1.0, 0.0), forces, moments, 9.81)
    sgn = math.copysign(1.0, w1)          # M_red is + in the direction of rotation
    np.testing.assert_allclose(sgn * M_loads, M_loads1, rtol=1e-10, atol=1e-9)
    expect = -sgn * (M_loads + M_w) + J * e1 + 0.5 * w1 * w1 * dJ
    scale = np.max(np.abs(frc.M_drive)) + np.max(np.abs(M_loads)) + 1.0
    np.testing.assert_allclose(frc.M_drive, expect, rtol=0, atol=1e-9 * scale)
    # Zhukovsky's lever
    lev = zhukovsky(res, forces, moments, 9.81)
    np.testing.assert_allclose(lev.M_balance, frc.M_drive, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(lev.balancing_force * mech.driver.length, frc.M_drive,
                               rtol=0, atol=1e-9 * scale)
    # the shaking force and moment = the frame's reactions (no loads, no weight)
    frc0 = ch.kinetostatics(res, gravity=0.0)
    for about in (None, 0.3 - 0.2j):
        sh = chain_shaking(res, about)
        F, M = frame_load(frc0, sh.about)
        fs = np.max(sh.F_N) + 1.0
        np.testing.assert_allclose(np.asarray(sh.F), np.asarray(F), rtol=0, atol=1e-9 * fs)
        np.testing.assert_allclose(sh.M, M, rtol=0, atol=1e-9 * fs)
    # J_red with the independent judge's velocities at the first position
    judge = Judge(mech, 9.81)
    q, qd, qdd = judge.motion(res.phi[0], guess_from(mech, res, 0), 1.0, 0.0)
    Jj = 0.0
    for n in mech.link_names:
        lk = mech.links[n]
        _, v, _ = judge.point_motion(q, qd, qdd, n, lk.cg)
        Jj += lk.mass * abs(v) ** 2 + lk.inertia * qd[3 * judge.idx[n] + 2] ** 2
    assert J[0] == pytest.approx(Jj, rel=1e-7)
    return J


@pytest.mark.parametrize("kind", sorted(BUILDERS))
def test_chain_dynamics_of_random_six_bars(kind):
    checked = []

    @SETTINGS
    @given(PARAMS)
    def run(p):
        _check(kind, p)
        checked.append(p)
    run()
    assert len(checked) >= 6, f"only {len(checked)} random {kind} mechanisms assembled"


# ------------------------------------------------------------------- by hand


def test_lever_by_hand_crank_with_a_slider():
    """A crank-slider with one force on the slider and a moment on the crank, worked by
    hand: the lever's image of A is O→A itself (ω₁ > 0 and < 0), and
    Mур = −F·(dx_B/dφ) − M on the crank (the power balance written out)."""
    r, L = 0.1, 0.4
    mech = ch.Mechanism({"O": 0j}, ch.Driver(r),
                        [ch.RRP(("rod", "ram"), ("A", "B"), L, ch.Guide(), 1)])
    phi = np.radians([30.0, 100.0, 250.0])
    for w1 in (7.0, -7.0):
        res = ch.solve(mech, phi, w1, 0.0)
        F = -500.0 + 0j                                      # pushes the ram towards −x
        lev = zhukovsky(res, {"ram": [(F, res.joints["B"].z)]}, {"crank": [40.0]}, 0.0)
        a = np.asarray(lev.points["A"])
        np.testing.assert_allclose(a, r * np.exp(1j * phi), atol=1e-15)
        # x_B = r cos φ + sqrt(L² − r² sin² φ): dx_B/dφ by hand
        dxB = -r * np.sin(phi) - r * r * np.sin(phi) * np.cos(phi) / np.sqrt(
            L * L - (r * np.sin(phi)) ** 2)
        np.testing.assert_allclose(lev.M_balance, -(F.real * dxB) - 40.0, rtol=1e-12)
        frc = ch.kinetostatics(res, {"ram": [(F, res.joints["B"].z)]}, {"crank": [40.0]},
                               0.0)
        np.testing.assert_allclose(lev.M_balance, frc.M_drive, rtol=1e-12)


def test_chain_model_of_a_six_bar_runs_the_true_motion():
    """A shaper-like six-bar (crank + RPR + RRP) with a cutting force on the ram over
    the forward stroke: the model's work balance and the flywheel for δ."""
    C = -0.3j
    mech = ch.Mechanism({"O": 0j, "C": C}, ch.Driver(0.1),
                        [ch.RPR(("block", "lever"), ("A", "C"), 0.0, 1),
                         ch.RRP(("rod", "ram"), ("D", "E"), 0.15,
                                ch.Guide("frame", 0.25j, 0.0), 1)],
                        {"crank": ch.Link(2.0, 0.002, 0.02),
                         "block": ch.Link(0.5, 0.0001),
                         "lever": ch.Link(8.0, 0.2, 0.25, {"D": 0.55 + 0j}),
                         "rod": ch.Link(2.0, 0.005, 0.075),
                         "ram": ch.Link(25.0)})

    def cutting(res):
        vE = res.joints["E"].v.x                 # dx_E/dφ at unit speed
        F = np.where(vE > 0, -2000.0, 0.0)       # resists the forward stroke only
        return {"ram": [(F + 0j, res.joints["E"].z)]}, {}

    model = chain_model(mech, cutting, steps=1440, omega_nominal=6.0)
    res = model.extra["chain"]
    vE = res.joints["E"].v.x
    W_cut = np.sum(np.where(vE > 0, 2000.0 * vE, 0.0)[:-1]) * (2 * math.pi / 1440)
    assert model.W_resist_J[-1] == pytest.approx(W_cut, rel=2e-3)   # the weights' work: 0
    assert model.W_resist_J[-1] == pytest.approx(2000.0 * np.ptp(res.joints["E"].z.x),
                                                 rel=2e-3)           # F × stroke
    fw = size_flywheel(model, 0.04)
    assert fw.motion.delta == pytest.approx(0.04, rel=1e-6)
    assert np.min(model.J_kgm2) > 0


def test_v_compressor_reduced_inertia_by_the_two_mass_rod():
    """A two-cylinder V compressor (two RRP groups on one crank pin, central guides at
    γ₁, γ₂ through O) in closed form.  A rod of mass m, centre of mass at a from the crank
    pin and b = L − a from the piston pin with J_S = m·a·b is dynamically equivalent to
    m·b/L at A and m·a/L at B (the two-mass rod, l₁·l₂ = k_G²: Khurmi & Gupta, Theory of
    Machines, 14th ed., 2005, the chapter on inertia forces in reciprocating parts:
    "equivalent dynamical system"), so

        J_red = J_crank,O + Σ_j [ m_j b_j/L_j · r² + (m_pj + m_j a_j/L_j) x_j'(φ)² ],
        x_j' = −r sin θ − r² sin θ cos θ / √(L_j² − r² sin² θ),  θ = φ − γ_j,

    the exact piston velocity ratio along its guide."""
    r = 0.06
    rods = [(0.25, 0.09, 3.0, 7.0, math.radians(45.0)), (0.27, 0.1, 3.5, 6.0,
                                                         math.radians(135.0))]
    groups, links = [], {"crank": ch.Link(5.0, 0.01, 0.015 + 0j)}
    for k, (L, a, m, mp, gam) in enumerate(rods, 1):
        groups.append(ch.RRP((f"rod{k}", f"piston{k}"), ("A", f"B{k}"), L,
                             ch.Guide("frame", 0j, gam, 0.0), 1))
        links[f"rod{k}"] = ch.Link(m, m * a * (L - a), a + 0j)
        links[f"piston{k}"] = ch.Link(mp)
    mech = ch.Mechanism({"O": 0j}, ch.Driver(r), groups, links)
    model = chain_model(mech, steps=360, gravity=0.0)
    phi = model.phi
    J = 0.01 + 5.0 * 0.015 ** 2 + 0.0 * phi
    dJ = 0.0 * phi
    for L, a, m, mp, gam in rods:
        th = phi - gam
        root = np.sqrt(L * L - (r * np.sin(th)) ** 2)
        x1 = -r * np.sin(th) - r * r * np.sin(th) * np.cos(th) / root
        x2 = (-r * np.cos(th) - r * r * np.cos(2 * th) / root
              - r ** 4 * np.sin(th) ** 2 * np.cos(th) ** 2 / root ** 3)
        J = J + m * (L - a) / L * r * r + (mp + m * a / L) * x1 * x1
        dJ = dJ + 2 * (mp + m * a / L) * x1 * x2
    np.testing.assert_allclose(model.J_kgm2, J, rtol=1e-12)
    np.testing.assert_allclose(model.dJ_dphi_kgm2, dJ, rtol=0, atol=1e-12 * np.max(J))
    np.testing.assert_allclose(model.M_resist_Nm, 0.0, atol=0)      # no load, no weight
    # reversed rotation: the same J over the angle turned, dJ/dφ turned with it
    back = chain_model(mech, steps=360, gravity=0.0, rotation=-1)
    np.testing.assert_allclose(back.J_kgm2, J[::-1], rtol=1e-12)
    np.testing.assert_allclose(back.dJ_dphi_kgm2, -dJ[::-1], rtol=0, atol=1e-12 * np.max(J))
