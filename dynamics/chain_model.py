"""Machine dynamics and the shaking force of any chain of class II groups (:mod:`linkage.chain`).

The reduced (equivalent) model of a chain at its crank, from the chain's own kinematics at
unit crank speed (velocities are then velocity ratios d(·)/dφ, accelerations d²(·)/dφ²):

    J_red(φ)  = Σ [ m_k |v_Sk|² + J_Sk ω_k² ] / ω₁²                          (eq. 11-10)
    dJ_red/dφ = Σ 2 [ m_k v_Sk·a_Sk + J_Sk ω_k ε_k ] / ω₁³      (at ε₁ = 0)
    M_red(φ)  = Σ [ F·v + M ω_k ] / ω₁                                       (eq. 11-13)

summed over every moving link of the chain and every load (a force at a point of a link, a
moment on a link, the weights); ``M_red`` is + in the direction of rotation.  The result is
a :class:`dynamics.reduced.ReducedModel`, so the true motion ω(φ), the flywheel and the
motor's start-up of :mod:`dynamics.motion` run on it unchanged.  For today's crank-rocker and
crank-slider (:func:`linkage.chain.from_mechanism`) :func:`spec_chain_model` gives
:func:`dynamics.reduced.linkage_model`'s numbers (the same load model,
:func:`linkage.loads.external_loads`).

The shaking force on the frame, ``F_sh = Σ (−m_k a_Sk)``, and the shaking moment about a
point P, ``M_sh = Σ [−J_Sk ε_k + (r_Sk − P) × (−m_k a_Sk)]``, are what the frame receives
through its pairs and the motor's stator when no other load acts (d'Alembert);
:func:`frame_load` sums the frame's reactions of :func:`linkage.chain.kinetostatics` (the
force of every link on the frame, the couples of its prismatic pairs and the stator's
−Mур), the check of :func:`chain_shaking` at every position.

Everything is vectorised over the crank positions (one :func:`linkage.chain.solve`).

References
----------
.. [1] Seed 001: textbook chapter 11 "机械系统的动力分析与设计", §11.3.1 (equivalent model,
   eqs. 11-10…11-14).
.. [2] Артоболевский И. И. Теория механизмов и машин. М.: Наука, 1988, гл. 15
   (приведённые массы и силы), §13 (уравновешивание, силы, передаваемые на стойку).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["reduced_inertia", "reduced_moment", "chain_model", "spec_chain_model",
           "chain_spec_model", "chain_spec_forces", "spec_loads", "stroke_extremes", "ChainShaking", "chain_shaking", "frame_load"]


def _zero(res):
    """Zeros over the positions: 0·x of the crank pin (the signed zeros of the earlier
    ``linkage_model``, so its outputs stay the same byte for byte)."""
    return 0.0 * np.asarray(res.joints[res.mech.driver.joint].z.x, float)


def _vel(res, link, at):
    """Velocity of the link's material point at the global position ``at``."""
    from linkage.groups import Vec

    L = res.links[link]
    o = L.origin
    return o.v + (Vec.of(at) - o.z).perp() * L.omega          # v = v_O + iω (r − r_O)


def reduced_inertia(res):
    """J_red and dJ_red/dφ of a solved chain (:class:`linkage.chain.ChainResult`).

    J_red = Σ (m |v_S|² + J_S ω²)/ω₁²; dJ_red/dφ = Σ 2 (m v_S·a_S + J_S ω ε)/|ω₁|³, the
    derivative over the angle φ turned in the direction of ω₁ (the model's φ), valid
    where the chain was solved at ε₁ = 0 (:func:`chain_model` solves it at ω₁ = ±1,
    ε₁ = 0).  [kg·m², kg·m²/rad]
    """
    from linkage.groups import dot

    w1 = np.abs(res.omega(res.mech.driver.link))
    J = _zero(res)
    dJ = _zero(res)
    for name in res.mech.link_names:
        lk = res.mech.links[name]
        L = res.links[name]
        S = L.point(lk.cg)
        J = J + lk.mass * dot(S.v, S.v) + lk.inertia * L.omega ** 2
        dJ = dJ + 2 * lk.mass * dot(S.v, S.a) + 2 * lk.inertia * L.omega * L.eps
    return J / w1 ** 2, dJ / w1 ** 3


def reduced_moment(res, forces=None, moments=None, gravity=9.81):
    """Reduced moment of the loads on a solved chain: (M_loads, M_weights) = power / |ω₁|,
    + in the direction of rotation (helping the motion). [N·m]

    ``forces``: link → list of (force, global point); ``moments``: link → list of moments
    (+ ccw), as :func:`linkage.chain.kinetostatics` takes them (constants or arrays over
    the positions); ``gravity`` along −y.  Velocity ratios, so any ω₁ ≠ 0 gives the same.
    """
    from linkage.groups import dot

    mech = res.mech
    w1 = np.abs(res.omega(mech.driver.link))
    P = _zero(res)
    Pw = P
    for name in mech.link_names:
        L = res.links[name]
        for f, at in (forces or {}).get(name, ()):
            P = P + dot(f, _vel(res, name, at))
        for m in (moments or {}).get(name, ()):
            P = P + m * L.omega
        lk = mech.links[name]
        if lk.mass and gravity:                               # weight −m g j at S
            Pw = Pw - lk.mass * gravity * L.point(lk.cg).v.imag
    return P / w1, Pw / w1


def _grid(steps):
    return np.linspace(0.0, 2 * math.pi, int(steps) + 1)


def chain_model(mech, loads=None, *, steps=720, phi0_deg=0.0, rotation=1, gravity=9.81,
                name=None, omega_nominal=None, check=True):
    """The reduced model of a chain (:class:`linkage.chain.Mechanism`) over one turn.

    Parameters
    ----------
    mech : linkage.chain.Mechanism
    loads : callable or tuple, optional
        ``(forces, moments)`` as :func:`linkage.chain.kinetostatics` takes them, given on
        the grid's positions, or a function ``loads(res) → (forces, moments)`` of the
        chain's solution at unit crank speed (a useful resistance that depends on the
        position or on the direction of the output's motion).
    steps : int
        Grid intervals over one turn.
    phi0_deg : float
        Absolute crank angle at φ = 0. [deg]
    rotation : +1 or −1
        The crank turns ccw (+1) or cw: absolute angle = phi0_deg + rotation·φ.
    gravity : float
        g along −y. [m/s²]
    check : bool
        Check the whole turn first (:func:`linkage.chain.check_cycle`: assembly and no
        branch flip).

    Returns
    -------
    dynamics.reduced.ReducedModel
        ``M_resist_Nm`` = −(M_loads + M_weights) (positive where the loads resist),
        ``extra["M_resist_loads_Nm"]``, ``extra["M_resist_weights_Nm"]`` its parts,
        ``extra["chain"]`` the solution at unit speed; ``M_drive_Nm`` zero (the drive is
        added by :mod:`dynamics.motion`); the work of the resistance by trapezoids.
    """
    from linkage import chain as ch

    from .results import ReducedModel

    s = 1 if rotation >= 0 else -1
    if check:
        ch.check_cycle(mech)
    phi = _grid(steps)
    res = ch.solve(mech, math.radians(phi0_deg) + s * phi, float(s), 0.0)
    J, dJ = reduced_inertia(res)
    if callable(loads):
        forces, moments = loads(res)
    else:
        forces, moments = loads or ({}, {})
    P_loads, P_weights = reduced_moment(res, forces, moments, gravity)
    Mc = -(P_loads + P_weights)
    Wc = np.concatenate([[0.0], np.cumsum(0.5 * (Mc[1:] + Mc[:-1]) * np.diff(phi))])
    zero = np.zeros_like(phi)
    return ReducedModel(name if name is not None else (mech.name or "chain"), phi, J, dJ,
                        zero.copy(), Mc, zero.copy(), Wc, 2 * math.pi,
                        omega_nominal=omega_nominal, phi0_deg=float(phi0_deg), rotation=s,
                        source=mech, extra={"M_resist_loads_Nm": -P_loads,
                                            "M_resist_weights_Nm": -P_weights,
                                            "chain": res})


def spec_loads(spec, mech, ext):
    """The loads of a crank-rocker or crank-slider spec (:mod:`linkage.loads`, today's
    load model: forces, moments, useful resistance by stroke and window) as a ``loads(res)``
    function for :func:`chain_model` on the chain :func:`linkage.chain.from_mechanism`."""
    from linkage.loads import external_loads, stroke_cycle

    cycle = stroke_cycle(mech, spec, ext)

    def loads(res):
        kin = {"crank": res.links["crank"], "A": res.joints["A"], "dyad": res.solutions[0],
               "links": res.links}
        forces, moments, _ = external_loads(spec, mech, kin, cycle)
        return forces, moments
    return loads


def spec_chain_model(spec, *, steps=720, phi0_deg=None):
    """The reduced model of a crank-rocker or crank-slider spec on its chain
    (:func:`linkage.chain.from_mechanism`), with the spec's loads (:func:`spec_loads`):
    the implementation of :func:`dynamics.reduced.linkage_model` (see it for the
    parameters; φ = 0 at the start of the working stroke by default)."""
    from linkage import chain as ch
    from linkage import load_spec
    from linkage.analysis import build_mechanism

    spec = load_spec(spec)
    if spec.kind == "chain":
        return chain_spec_model(spec, steps=steps, phi0_deg=phi0_deg)
    mech = build_mechanism(spec)
    mech.check_rotatable()
    s = 1 if spec.omega >= 0 else -1
    ext = stroke_extremes(spec, mech)
    if phi0_deg is None:
        phi0_deg = math.degrees(ext.phi_start) if ext is not None else 0.0
    chain = ch.from_mechanism(mech, spec.links)
    model = chain_model(chain, spec_loads(spec, mech, ext), steps=steps, phi0_deg=phi0_deg,
                        rotation=s, gravity=spec.gravity, name=spec.name,
                        omega_nominal=abs(spec.omega) or None, check=False)
    model.source = spec
    return model


def _chain_summary(spec):
    """The chain's summary (extremes, working stroke) by :func:`linkage.chain_analysis.
    analyze_chain` at one position."""
    from linkage.chain_analysis import analyze_chain

    return analyze_chain(spec, [0.0]).summary


def _chain_spec_loads(spec, summary, omega):
    """``loads(res)`` of a chain spec (:func:`linkage.chain_analysis.chain_loads`, the
    analysis's own load model) for a solution at the crank speed ``omega`` (the resistance
    rule's at-rest threshold scales with it)."""
    import dataclasses

    from linkage.chain_analysis import chain_loads

    spec_w = dataclasses.replace(spec, omega=float(omega), epsilon=0.0)

    def loads(res):
        forces, moments, _ = chain_loads(spec_w, res, summary)
        return forces, moments
    return loads


def chain_spec_model(spec, *, steps=720, phi0_deg=None):
    """The reduced model of a chain spec (:class:`linkage.chain_spec.ChainSpec`, any
    linkage of class II groups) with its loads, as :func:`spec_chain_model` for a four-bar.

    φ = 0 at the start of the output's working stroke (0° of the crank without extremes);
    the loads are those of the chain's analysis (:func:`linkage.chain_analysis.chain_loads`:
    forces, moments, the useful resistance over its window of its stroke), evaluated
    at unit crank speed; ``model.source`` is the spec and ``extra["summary"]`` the chain's
    summary.
    """
    s = 1 if spec.omega >= 0 else -1
    summary = _chain_summary(spec)
    if phi0_deg is None:
        phi0_deg = summary.phi_working_start_deg if summary.has_extremes else 0.0
    model = chain_model(spec.mechanism, _chain_spec_loads(spec, summary, s), steps=steps,
                        phi0_deg=phi0_deg, rotation=s, gravity=spec.gravity, name=spec.name,
                        omega_nominal=abs(spec.omega) or None, check=True)
    model.source = spec
    model.extra["summary"] = summary
    return model


def _force_columns(cf):
    """The reactions of a chain's kinetostatics as columns named as in the chain's force
    table (:mod:`linkage.chain_analysis`): ``Rx_i_j_N``, ``Ry_i_j_N``, ``R_i_j_N`` (force
    of link i on link j), ``M_drive_Nm``."""
    from linkage.chain_analysis import reaction_tags

    F = {}
    for tag, r in reaction_tags(cf.reactions):
        F[f"Rx_{tag}_N"], F[f"Ry_{tag}_N"] = r.force.x, r.force.y
        F[f"R_{tag}_N"] = np.hypot(r.force.x, r.force.y)
    F["M_drive_Nm"] = cf.M_drive
    return F


def chain_spec_forces(model, motion):
    """The chain's kinetostatics under the true motion ω(φ), ε(φ) of the crank, beside the
    one at the constant mean speed (ε = 0): the chain's counterpart of
    :func:`dynamics.motion.true_motion_forces`.

    Returns
    -------
    pandas.DataFrame
        ``phi_deg``, ``omega_rad_s``, ``eps_rad_s2``; for every pair ``Rx_i_j_N``,
        ``Ry_i_j_N``, ``R_i_j_N`` (force of link i on link j, the chain's force-table
        names) and ``M_drive_Nm`` (Mур on the crank, + ccw, without the flywheel), each
        also with the suffix ``_const``.  ``attrs["crank_bearing"]`` names the magnitude
        column of the frame's reaction on the crank.
    """
    import pandas as pd
    from linkage import chain as ch

    spec = model.source
    s = model.rotation
    mech = spec.mechanism
    summary = model.extra.get("summary") or _chain_summary(spec)
    w_m = float(s * motion.omega_mean)
    phi_deg = motion.table["phi_deg"].to_numpy()
    phi = np.radians(phi_deg)                  # absolute crank angles (model.phi_deg)
    w = motion.table["omega_rad_s"].to_numpy()
    e = motion.table["eps_rad_s2"].to_numpy()
    loads = _chain_spec_loads(spec, summary, w_m)
    out = {}
    for suffix, om, ep in (("", s * w, s * e), ("_const", w_m + 0.0 * w, 0.0 * w)):
        res = ch.solve(mech, phi, om, ep, check=False)
        forces, moments = loads(res)
        cf = ch.kinetostatics(res, forces, moments, spec.gravity)
        out[suffix] = _force_columns(cf)
    df = pd.DataFrame({"phi_deg": phi_deg, "omega_rad_s": w, "eps_rad_s2": e})
    for c in out[""]:
        df[c] = out[""][c]
        df[f"{c}_const"] = out["_const"][c]
    df.attrs["crank_bearing"] = f"R_{ch.FRAME}_{mech.driver.link}_N"
    return df


def stroke_extremes(spec, mech):
    """The extremes the core's load model needs (None without a working stroke)."""
    if spec.working_stroke is None:
        return None
    from linkage.course import course_of

    default = course_of(spec).default_working_stroke
    with np.errstate(divide="ignore", invalid="ignore"):
        return mech.extremes(1 if spec.omega >= 0 else -1, spec.working_stroke or default)


# --------------------------------------------------------------------------- shaking


@dataclass
class ChainShaking:
    """Shaking force ``F`` (:class:`linkage.groups.Vec`, [N]) and moment ``M`` about the
    point ``about`` (+ ccw, [N·m]) on the frame, arrays over the positions ``phi``."""

    phi: np.ndarray
    F: object
    M: np.ndarray
    about: complex

    @property
    def F_N(self):
        """|F_sh|. [N]"""
        return np.hypot(self.F.x, self.F.y)


def chain_shaking(res, about=None):
    """Shaking force and moment of a solved chain on its frame (module docstring).

    ``about``: the moment's point (complex, [m]); default the crank's pivot.  The crank
    angles, ω₁ and ε₁ are those ``res`` was solved at (:func:`linkage.chain.solve`)."""
    from linkage.groups import Vec, cross, inertia_load

    mech = res.mech
    O = complex(mech.frame[mech.driver.pivot] if about is None else about)
    zero = 0.0 * res.phi                       # as the earlier shaking(): 0·φ
    F = Vec(zero, zero)
    M = zero
    for name in mech.link_names:
        lk = mech.links[name]
        L = res.links[name]
        S = L.point(lk.cg)
        Fu, Mu = inertia_load(S.a, L.eps, lk.mass, lk.inertia)
        F = F + Fu
        M = M + Mu + cross(S.z - O, Fu)
    return ChainShaking(res.phi, F, np.broadcast_to(M, np.shape(res.phi)), O)


def frame_load(frc, about, stator=True):
    """The load of the links on the frame from a kinetostatics (:class:`linkage.chain.
    ChainForces`): (force, moment about ``about``), the sum over the frame's pairs of the
    opposite of each reaction of the frame (forces and the couples of prismatic pairs),
    and with ``stator`` the motor stator's reaction −Mур. [N, N·m]"""
    from linkage.chain import FRAME
    from linkage.groups import Vec, cross

    F = Vec(0.0, 0.0)
    M = 0.0
    for (by, _on), r in list(frc.reactions.items()):
        if by != FRAME:
            continue
        F = F - r.force
        M = M - cross(Vec.of(r.at) - complex(about), r.force)
        if r.couple is not None:
            M = M - r.couple
    if stator:
        M = M - frc.M_drive
    return F, M
