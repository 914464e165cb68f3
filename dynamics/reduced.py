"""The reduced (equivalent) dynamic model of a machine at its main shaft (the crank).

A single-degree-of-freedom machine moves like one shaft with the reduced moment of inertia
``J_red(φ)`` driven by the reduced moments ``M_d(φ)`` and resisted by ``M_c(φ)``:

    J_red(φ) = Σ [ m_i (v_Si/ω)² + J_Si (ω_i/ω)² ]                       (eq. 11-10)
    M_red(φ) = Σ [ F_i v_i cos α_i ± M_i ω_i ] / ω                       (eq. 11-13)

Both depend on the position only (velocity ratios), so they come straight from the
kinematics.  φ here is the angle turned by the crank *in its direction of rotation* from
the start of the cycle, so ω > 0; moments are positive in the direction of rotation
(``M_drive``) or against it (``M_resist``).

Sources of a model:

* :func:`machine_model` – given directly by its reduced quantities (a constant J and
  piecewise-linear moments, the textbooks' turning-moment diagrams);
* :func:`linkage_model` – a crank-rocker or crank-slider of :mod:`linkage`, reduced as its
  chain by :func:`dynamics.chain_model.chain_model` (the reduction of any chain of class II
  groups): J_red and dJ_red/dφ from the velocity ratios (kinematics at unit crank speed),
  the reduced resisting moment from the power of the core's own external loads and weights;
* :func:`chain_reduce` – a chain of elements with constant speed ratios (shafts, gear pairs,
  a hoist drum with a load): the seed's Example 11-2.

References
----------
.. [1] Seed 001: textbook chapter 11 "机械系统的动力分析与设计", §11.3.1 (equivalent model,
   eqs. 11-10…11-14), Example 11-2.
.. [2] Артоболевский И. И. Теория механизмов и машин. М.: Наука, 1988, гл. 15
   (приведённые массы и силы).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from crankbase.errors import Text
from ._base import Problem, SpecError
from .chain_model import stroke_extremes  # noqa: F401  (its home was here)
from .results import ReducedModel

__all__ = ["ReducedModel", "PiecewiseLinear", "machine_model", "linkage_model",
           "engine_model", "chain_reduce", "ChainReduction", "braking_moment"]


class PiecewiseLinear:
    """A periodic piecewise-linear function of the angle (a turning-moment diagram).

    Parameters
    ----------
    phi_deg : sequence of float
        Nondecreasing angles [deg] within one period; a repeated angle is a step (the
        value jumps there).  Outside [phi_deg[0], phi_deg[-1]] the diagram is closed by a
        straight line from the last point to the first one a period later.
    values : sequence of float
        The values at those angles.
    period_deg : float
        Period [deg].

    Notes
    -----
    :meth:`integral` is exact (trapezoids between the breakpoints), so steps and kinks
    cost no accuracy whatever the evaluation grid.
    """

    def __init__(self, phi_deg, values, period_deg, key="moment"):
        x = np.asarray(phi_deg, dtype=float)
        y = np.asarray(values, dtype=float)
        probs = []
        if x.ndim != 1 or x.size < 1 or x.shape != y.shape:
            probs.append(Problem(key, Text("errors.dynamics.reduced.phi_deg_and",
                                           {"size": x.size, "size2": y.size})))
        elif np.any(np.diff(x) < 0):
            probs.append(Problem(f"{key}.phi_deg",
                                 Text("errors.dynamics.reduced.angles_not_decrease",
                                      {"value": x.tolist()})))
        elif x[-1] - x[0] > period_deg + 1e-9:
            probs.append(Problem(f"{key}.phi_deg", Text("errors.dynamics.reduced.spans_more_than",
                                                        {"value": x[-1] - x[0],
                                                         "period_deg": period_deg})))
        if probs:
            raise SpecError(probs)
        # one closed period starting at x[0]: append the first point a period later
        self.x = np.radians(np.concatenate([x, [x[0] + period_deg]]))
        self.y = np.concatenate([y, [y[0]]])
        self.period = math.radians(period_deg)
        seg = 0.5 * (self.y[1:] + self.y[:-1]) * np.diff(self.x)
        self._cum = np.concatenate([[0.0], np.cumsum(seg)])   # ∫ from x[0] to x[k]

    @property
    def cycle_integral(self):
        """∫ over one period. [value·rad]"""
        return float(self._cum[-1])

    def _reduce(self, phi):
        """Number of whole periods before ``phi`` (from x[0]) and the angle in the period."""
        n = np.floor((np.asarray(phi, float) - self.x[0]) / self.period)
        return n, np.asarray(phi, float) - n * self.period

    def __call__(self, phi):
        """Value at ``phi`` [rad]; at a step the value after it (right-continuous)."""
        _, p = self._reduce(phi)
        k = np.clip(np.searchsorted(self.x, p, side="right") - 1, 0, len(self.x) - 2)
        dx = self.x[k + 1] - self.x[k]
        with np.errstate(invalid="ignore", divide="ignore"):
            t = np.where(dx > 0, (p - self.x[k]) / np.where(dx > 0, dx, 1.0), 0.0)
        return self.y[k] + t * (self.y[k + 1] - self.y[k])

    def primitive(self, phi):
        """∫ from x[0] to ``phi`` [rad] of the function (continuous over steps)."""
        n, p = self._reduce(phi)
        k = np.clip(np.searchsorted(self.x, p, side="right") - 1, 0, len(self.x) - 2)
        v = self(p)
        part = 0.5 * (self.y[k] + v) * (p - self.x[k])
        return n * self._cum[-1] + self._cum[k] + part

    def integral(self, a, b):
        """∫ from ``a`` to ``b`` [rad]."""
        return self.primitive(b) - self.primitive(a)


def _grid(period, steps):
    return np.linspace(0.0, period, int(steps) + 1)


def machine_model(J_kgm2, moments, period_deg=360.0, *, name="machine", steps=1440,
                  omega_nominal=None) -> ReducedModel:
    """A machine given by its reduced quantities.

    Parameters
    ----------
    J_kgm2 : float
        Constant reduced moment of inertia (> 0). [kg·m²]
    moments : sequence of (role, PiecewiseLinear)
        ``role`` "drive" or "resist"; the diagrams add up per role.
    period_deg : float
        Period of the cycle. [deg]
    steps : int
        Grid intervals over the period (the diagrams' breakpoints are added to the grid).
    omega_nominal : float, optional
        Nominal mean speed. [rad/s]
    """
    if not J_kgm2 > 0:
        raise SpecError(Problem("machine.J_red_kgm2", Text("errors.dynamics.reduced.message",
                                                           {"J_kgm2": J_kgm2})))
    period = math.radians(period_deg)
    # the uniform grid plus every breakpoint of the diagrams: the extremes of the work
    # (kinks of the diagrams, ends of steps) are then grid points, not missed between them
    knots = [np.mod(pl.x - 0.0, period) for _, pl in moments]
    phi = np.union1d(_grid(period, steps), np.concatenate([[0.0, period], *knots]))
    phi = phi[(phi >= 0.0) & (phi <= period)]
    Md, Mc, Wd, Wc = (np.zeros_like(phi) for _ in range(4))
    for role, pl in moments:
        val, work = pl(phi), pl.integral(0.0, phi)
        if role == "drive":
            Md, Wd = Md + val, Wd + work
        else:
            Mc, Wc = Mc + val, Wc + work
    J = np.full_like(phi, float(J_kgm2))
    return ReducedModel(name, phi, J, np.zeros_like(phi), Md, Mc, Wd, Wc, period,
                        omega_nominal=omega_nominal)


# --------------------------------------------------------------------------- linkage


def linkage_model(spec, *, steps=720, phi0_deg=None, drive_power=False) -> ReducedModel:
    """The reduced model of a crank-rocker or crank-slider of :mod:`linkage`, or of any
    chain of class II groups (a ``kind = "chain"`` spec:
    :func:`dynamics.chain_model.chain_spec_model`).

    Parameters
    ----------
    spec : linkage spec (path, dict, MechanismSpec or ChainSpec)
    steps : int
        Grid intervals over one turn.
    phi0_deg : float, optional
        Absolute crank angle of φ = 0 [deg]; default the start of the working stroke (or
        0° for a double crank / no working stroke).

    Returns
    -------
    ReducedModel
        ``M_resist_Nm`` is minus the reduced moment of every external load and weight
        (positive where the loads resist), ``extra["M_resist_loads_Nm"]`` and
        ``extra["M_resist_weights_Nm"]`` its two parts; ``M_drive_Nm`` is zero (a drive is
        added by :mod:`dynamics.motion`).  The crank's own mass and J_S2 are in J_red.

    Notes
    -----
    The mechanism is solved as its chain (:func:`linkage.chain.from_mechanism`) by
    :func:`dynamics.chain_model.chain_model`, the one reduction of any chain: velocity
    ratios from the kinematics at ω = ±1 rad/s, ε = 0; eq. (11-10)/(11-13) of [1]_.  The
    loads are the core's (:func:`linkage.loads.external_loads`): one load model for the
    force analysis and for the reduction.  The spec's ε is not used (the true motion sets it).
    """
    from .chain_model import spec_chain_model

    return spec_chain_model(spec, steps=steps, phi0_deg=phi0_deg)


# --------------------------------------------------------------------------- engine


def engine_model(spec, *, steps=1440, J_extra_kgm2=0.0, train=None) -> ReducedModel:
    """The reduced model of a (multi-cylinder) engine of :mod:`engine`.

    Parameters
    ----------
    spec : EngineSpec
        From :func:`engine.load_spec`.
    steps : int
        Grid intervals over the cycle (720° four-stroke, 360° two-stroke).
    J_extra_kgm2 : float
        Crankshaft and other rotating parts not in the spec's masses. [kg·m²]
    train : CrankTrain, optional
        The crank train of the spec file (:func:`engine.load` gives it: arrangement,
        vee angle, firing order, throw angles).  Every cylinder's phase φ_j and bank
        angle γ_j are those of its layout, :func:`engine.train.layout` (the one place
        they are computed).  Default: the inline engine of the spec's cylinders firing
        evenly (the textbook firing order, else 1…i), cylinder phases k·cycle/i.

    Returns
    -------
    ReducedModel
        ``J_kgm2`` = Σ_j [m_j (v_j/ω)² + m_ш.к R²] + Σ_throws m_к R² + J_extra (the
        two-mass model of the engine's rod, as in the force table; m_к once per throw);
        ``dJ_dphi_kgm2`` = Σ 2 m_j (v/ω)(j/ω²) (exact kinematics at constant ω);
        ``M_drive_Nm`` the gas torque Σ Mкр(ΔPг) from the engine's own crank-pin force
        routine with the gas force alone (the piston's inertia torque is the
        −½ω² dJ/dφ term of the equation of motion); no resisting moment (a constant one
        is added by :func:`dynamics.motion.steady_motion`).
        ``extra["layout"]`` is the :class:`engine.train.Layout` used.

    Notes
    -----
    Cylinder j is the one-cylinder model at α_j = θ − φ_j on its own axis (bank γ_j,
    :func:`engine.kinematics.crank_slider`); its throw only fixes φ_j (through the
    layout), since the rotating masses give the same m·R² on any throw.  The cylinders
    are summed in the order of their phases (the order of firing from cylinder 1).
    """
    import engine
    from engine.train import CrankTrain, default_firing_order, layout

    cyc = spec.cycle_deg
    i = int(spec.cylinders)
    if train is None:
        order = default_firing_order("inline", i) if spec.strokes == 4 else None
        train = CrankTrain(firing_order=order or tuple(range(1, i + 1)))
    lay = layout(spec, train)
    phi = _grid(math.radians(cyc), steps)
    theta = np.degrees(phi)
    Mgas, vr, ar = [], [], []
    for j in np.argsort(lay.phase_deg, kind="stable"):     # in the order of the phases
        phase, bank = float(lay.phase_deg[j]), float(lay.bank_deg[j])
        tab = engine.force_table(spec, theta, bank_deg=bank, phase_deg=phase)
        mech = engine.crank_slider(phi, spec.R, spec.L, spec.omega, bank=math.radians(bank),
                                   offset=spec.pin_offset, phase=math.radians(phase))
        Mgas.append(engine.crank_pin_forces(mech, tab["dPg_N"].to_numpy(), spec.L)["M"])
        vr.append(tab["v_m_s"].to_numpy() / spec.omega)            # dx/dφ [m]
        ar.append(tab["j_m_s2"].to_numpy() / spec.omega ** 2)       # d²x/dφ² [m]
    Mgas, vr, ar = np.array(Mgas), np.array(vr), np.array(ar)
    J = np.sum(spec.mj * vr * vr + spec.m_rod_rot * spec.R ** 2, axis=0)
    if spec.m_crank_rot:                  # mк once per throw of the layout (vee: a pair)
        J = J + len(lay.throw_angles_deg) * spec.m_crank_rot * spec.R ** 2
    J = J + J_extra_kgm2
    dJ = np.sum(2.0 * spec.mj * vr * ar, axis=0)
    Md = np.sum(Mgas, axis=0)
    Wd = np.concatenate([[0.0], np.cumsum(0.5 * (Md[1:] + Md[:-1]) * np.diff(phi))])
    zero = np.zeros_like(phi)
    return ReducedModel(spec.name, phi, J, dJ, Md, zero.copy(), Wd, zero.copy(),
                        math.radians(cyc), omega_nominal=spec.omega, source=spec,
                        extra={"cylinders": i, "cycle_deg": cyc, "layout": lay})


# --------------------------------------------------------------------------- chains


@dataclass
class ChainReduction:
    """A chain of elements with constant speed ratios reduced to one shaft.

    Attributes
    ----------
    J_red_kgm2 : float
        Σ J_k (ω_k/ω)² + Σ m_j (v_j/ω)². [kg·m²]
    M_red_Nm : float
        Σ M_k (ω_k/ω) + Σ F_j (v_j/ω) (+ in the direction of rotation). [N·m]
    """

    J_red_kgm2: float
    M_red_Nm: float


def chain_reduce(inertias_kgm2=(), ratios=(), masses_kg=(), velocity_ratios_m=(),
                 moments_Nm=(), moment_ratios=(), forces_N=(), force_ratios_m=()):
    """Reduce elements with constant speed ratios to the main shaft (eqs. 11-10, 11-13).

    Parameters
    ----------
    inertias_kgm2, ratios : sequences
        Rotating elements: J_k [kg·m²] and ω_k/ω [-].
    masses_kg, velocity_ratios_m : sequences
        Translating elements: m_j [kg] and v_j/ω [m].
    moments_Nm, moment_ratios : sequences
        Moments M_k [N·m] (+ in the element's positive sense) on elements turning at ω_k/ω.
    forces_N, force_ratios_m : sequences
        Forces F_j [N] (component along the element's positive velocity) with v_j/ω [m].

    Returns
    -------
    ChainReduction

    Examples
    --------
    The seed's hoist (Example 11-2): motor shaft I with J1 and gear z1, shaft II with J2,
    gear z2 and a drum of diameter D lifting a weight G: ω2/ω1 = z1/z2 and v/ω1 =
    (D/2)·z1/z2, so J_e = J1 + J2 (z1/z2)² + (G/g)(D z1/(2 z2))².
    """
    J = sum(j * r * r for j, r in zip(inertias_kgm2, ratios))
    J += sum(m * r * r for m, r in zip(masses_kg, velocity_ratios_m))
    M = sum(m * r for m, r in zip(moments_Nm, moment_ratios))
    M += sum(f * r for f, r in zip(forces_N, force_ratios_m))
    if not J > 0:
        raise SpecError(Problem("chain", Text("errors.dynamics.reduced.reduced_moment_inertia",
                                              {"J": J})))
    return ChainReduction(float(J), float(M))


def braking_moment(J_red_kgm2, omega0_rad_s, t_stop_s, M_other_Nm=0.0):
    """Constant brake moment that stops a machine of constant reduced quantities from ω0 in
    ``t_stop_s`` (differential form with J constant: J dω/dt = M_other − M_brake).

    Parameters
    ----------
    J_red_kgm2 : float
        Reduced moment of inertia at the braked shaft. [kg·m²]
    omega0_rad_s : float
        Initial speed of that shaft (> 0). [rad/s]
    t_stop_s : float
        Stopping time (> 0). [s]
    M_other_Nm : float
        Reduced moment of the other loads, + in the direction of motion (a lowered weight
        helps the motion, a lifted one opposes it). [N·m]

    Returns
    -------
    float
        M_brake = J ω0 / t + M_other [N·m] (seed 001, Example 11-2, eq. 11-17).
    """
    probs = []
    if not J_red_kgm2 > 0:
        probs.append(Problem("J_red_kgm2", Text("errors.dynamics.reduced.message_2",
                                                {"J_red_kgm2": J_red_kgm2})))
    if not omega0_rad_s > 0:
        probs.append(Problem("omega0_rad_s", Text("errors.dynamics.reduced.message_3",
                                                  {"omega0_rad_s": omega0_rad_s})))
    if not t_stop_s > 0:
        probs.append(Problem("t_stop_s", Text("errors.dynamics.reduced.message_4",
                                              {"t_stop_s": t_stop_s})))
    if probs:
        raise SpecError(probs)
    return J_red_kgm2 * omega0_rad_s / t_stop_s + M_other_Nm
