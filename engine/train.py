"""The whole engine: the crank train layout (inline, vee, boxer), the cylinders' phases by
the firing order, the total torque, its uniformity, the flywheel, and the free forces and
moments of the engine with their balance by counterweights.

Every cylinder is the same single-cylinder model (:func:`engine.force_table`) placed by its
bank angle γ and phase φ (:mod:`engine.kinematics`); the engine sums them at the same
crankshaft angle θ, the crankshaft angle being cylinder 1's crank angle α₁.

Conventions (also in the README and on the Inputs sheet of the report)
----------------------------------------------------------------------
- Engine frame, seen from the flywheel end: x to the right, y up, z along the crankshaft
  from the front (cylinder 1) to the flywheel; (x, y, z) is right-handed.  The crankshaft
  turns counter-clockwise in this view (clockwise seen from the front, the usual sense).
- Cylinders: inline 1…i from the front.  Vee and boxer: the first bank holds 1…i/2 from the
  front, the second bank i/2+1…i; the first bank is on the right (+x, bank angle −V/2,
  boxer −90°), the second on the left (+V/2, +90°).  On a common pin the first bank's
  cylinder reaches TDC V° before the second bank's.
- Throws: inline and boxer, one per cylinder (throw j carries cylinder j); vee, one per
  pair (throw k carries cylinders k and k + i/2).  ``throw_angles_deg[k]`` is the angle of
  throw k from throw 1, measured in the direction of rotation (a throw leading by τ reaches
  TDC τ° earlier).  Default (firing order only): the crankshaft that makes the engine
  fire evenly in that order — its throws follow from τ ≡ γ_b − γ₁ − φ (mod 360°).
- Phases: cylinder j's working cycle lags cylinder 1's by φ_j (its α = θ − φ_j).  Its
  geometric lag g_j = (γ_j − γ₁ − τ_k) mod 360° fixes φ_j modulo 360°; the firing order
  fixes the revolution: walking it from its first cylinder, each cylinder fires at its
  first TDC after the previous one (the next revolution if at the same angle); the walk
  must fit in one cycle (720° four-stroke, 360° two-stroke), the last interval closing it.
- Axial positions z: inline cylinder j at (j − 1)·spacing; vee and boxer, first-bank
  cylinder k at (k − 1)·spacing and the second bank's at that + ``bank_offset`` (+ towards
  the flywheel); or given per cylinder.  Moments are taken about the engine's centre, the
  middle between the first and the last cylinder.
- Free force: the sum of the inertia forces of the moving masses (what the engine puts on
  its mounts).  Reciprocating: F = mj·j·u along each cylinder axis (+ away from the
  crankshaft at TDC); first order mj·Rω²(cos α + kλ sin α)·u, second order mj·Rω²λ·cos 2α·u,
  and the sum under the acceleration model in use (``Fj``).  Rotating: (mш.к + mк)·Rω²
  along each throw, outwards (mш.к at its rod's plane, mк at the throw's middle).
  Moment M = Σ z × F about the centre: M_x = −Σ z·F_y, M_y = Σ z·F_x.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей. 4-е изд.
   М.: Высшая школа, 2008, гл. "Динамика КШМ" (суммарный крутящий момент, порядок работы,
   равномерность хода μ = (Mкр.max − Mкр.min)/Mкр.ср, маховик: Lизб, J0 = Lизб/(δω²),
   mм·Dср² = 4Jм) and "Уравновешивание двигателей" (силы инерции первого и второго
   порядков, центробежные силы, их моменты; противовесы).
.. [2] 孙桓, 陈作模, 葛文杰. 机械原理 (Theory of Machines), 7th ed., ch. 11: two-plane
   (dynamic) balancing of a rotor, Example 11-1; the flywheel by the largest swing of
   the work of Med − Mer, Example 11-3.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from crankbase.errors import Problem
from crankbase.tolerances import BALANCED_RTOL, ROUNDOFF_RTOL, SAME_ANGLE_DEG, snap_roundoff

from .forces import PLOT_STEP_DEG, analyze, force_table, indicated_power
from .kinematics import (acceleration_orders, crank_slider, cylinder_axis_angle,
                         guide_direction, two_term_acceleration)
from .spec import (ARRANGEMENTS, COUNTERWEIGHT_DESIGNS, Counterweight, CrankTrain, EngineSpec,
                   EngineSpecError, TableSettings)

if TYPE_CHECKING:                       # annotations only: no pandas import at run time
    import pandas as pd

    from .result import EngineResult

__all__ = ["ARRANGEMENTS", "COUNTERWEIGHT_DESIGNS", "Counterweight", "CrankTrain", "Layout",
           "layout", "default_firing_order", "cylinder_torques", "free_forces",
           "counterweights_for", "two_plane_balance", "excess_work", "flywheel",
           "FlywheelResult", "analyze_engine", "EngineTrainResult", "EngineTrainSummary",
           "TORQUE_COLUMNS", "BALANCE_COLUMNS", "CYLINDER_COLUMNS"]


#: Textbook firing orders used when a four-stroke spec gives none (Kolchin & Demidov [1]_;
#: the V8 order is that of the ЗИЛ-130 and КамАЗ-740 engines).
DEFAULT_FIRING_ORDERS = {
    ("inline", 1): (1,), ("inline", 2): (1, 2), ("inline", 3): (1, 3, 2),
    ("inline", 4): (1, 3, 4, 2), ("inline", 5): (1, 2, 4, 5, 3),
    ("inline", 6): (1, 5, 3, 6, 2, 4), ("inline", 8): (1, 6, 2, 5, 8, 3, 7, 4),
    ("vee", 2): (1, 2), ("vee", 8): (1, 5, 4, 2, 6, 3, 7, 8), ("boxer", 2): (1, 2),
}


def _bad(key, message):
    return EngineSpecError(Problem(key, message))


@dataclass(frozen=True)
class Layout:
    """The placed cylinders of an engine (:func:`layout`).

    Attributes
    ----------
    cylinders : pandas.DataFrame
        One row per cylinder: ``cylinder``, ``bank``, ``throw``, ``axial_position_mm``,
        ``bank_angle_deg``, ``throw_angle_deg``, ``phase_deg`` (the columns of
        cylinders.csv).
    firing_order : tuple of int
    throw_angles_deg : tuple of float
        Angle of each throw from throw 1 in the direction of rotation. [deg]
    throw_z : ndarray
        Axial position of each throw's middle, from cylinder 1's axis. [m]
    z_centre : float
        The engine's centre (moments are taken about it). [m]
    cycle_deg : float
    even_firing : bool
        All firing intervals equal (720°/i four-stroke, 360°/i two-stroke).
    crankshaft : str
        How the throw angles were obtained ("given" or "default for even firing").
    """

    cylinders: pd.DataFrame
    firing_order: tuple
    throw_angles_deg: tuple
    throw_z: np.ndarray
    z_centre: float
    cycle_deg: float
    even_firing: bool
    crankshaft: str

    @property
    def n(self) -> int:
        return len(self.cylinders)

    @property
    def phase_deg(self) -> np.ndarray:
        return self.cylinders["phase_deg"].to_numpy()

    @property
    def bank_deg(self) -> np.ndarray:
        return self.cylinders["bank_angle_deg"].to_numpy()

    @property
    def z(self) -> np.ndarray:
        """Axial position of each cylinder (its rod on the pin), from cylinder 1. [m]"""
        return self.cylinders["axial_position_mm"].to_numpy() * 1e-3

    @property
    def throw_of(self) -> np.ndarray:
        """Throw index (0-based) of each cylinder."""
        return self.cylinders["throw"].to_numpy() - 1

    @property
    def firing_interval_deg(self) -> float:
        """The even firing interval cycle/i. [deg]"""
        return self.cycle_deg / self.n


def default_firing_order(arrangement, cylinders):
    """The textbook firing order of a four-stroke engine (None when there is none)."""
    return DEFAULT_FIRING_ORDERS.get((arrangement, cylinders))


def _mod(a, m=360.0):
    r = np.mod(a, m)
    return np.where(np.abs(r - m) < SAME_ANGLE_DEG, 0.0, r)


def layout(spec: EngineSpec, train: CrankTrain) -> Layout:
    """Place the cylinders: banks, throws, axial positions, throw angles and phases.

    Parameters
    ----------
    spec : EngineSpec
        Gives the number of cylinders and the stroke cycle.
    train : CrankTrain

    Returns
    -------
    Layout

    Raises
    ------
    EngineSpecError
        One clear problem, named by its spec key: a firing order that is not a permutation
        of the cylinders, throw angles inconsistent with the number of throws, a vee or
        boxer with an odd number of cylinders, a layout that cannot fire evenly in the
        given order when even firing is implied (no throw angles), a firing order that
        does not close the cycle with the given throws, or no firing order where there
        is no textbook default.
    """
    import pandas as pd

    if not isinstance(spec, EngineSpec):
        raise _bad("spec", f"must be an EngineSpec (engine.load_spec), got "
                           f"{type(spec).__name__}")
    if not isinstance(train, CrankTrain):
        raise _bad("train", f"must be a CrankTrain, got {type(train).__name__}")
    n, cyc = spec.cylinders, spec.cycle_deg
    arr = train.arrangement
    if arr != "inline" and n % 2:
        raise _bad("engine.cylinders", f"got {n}; a {arr} engine needs an even number of "
                                       "cylinders (two banks)")
    half = n // 2
    cyl = np.arange(1, n + 1)
    if arr == "inline":
        bank = np.ones(n, int)
    else:
        bank = np.where(cyl <= half, 1, 2)
    n_throws = half if arr == "vee" else n
    throw = (cyl - 1) % half + 1 if arr == "vee" else cyl
    gam = np.asarray(train.bank_angles_deg)[bank - 1]

    # axial positions
    if train.cylinder_positions is not None:
        if len(train.cylinder_positions) != n:
            raise _bad("engine.cylinder_positions_mm", f"has {len(train.cylinder_positions)}"
                                                       f" positions for {n} cylinders")
        z = np.asarray(train.cylinder_positions, float)
    else:
        s = train.cylinder_spacing or 0.0
        k = cyl - 1 if arr == "inline" else (cyl - 1) % half
        z = k * s + np.where(bank == 2, train.bank_offset, 0.0)
    throw_z = np.array([z[throw == t].mean() for t in range(1, n_throws + 1)])

    # firing order
    order = train.firing_order
    if order is not None:
        if sorted(order) != list(range(1, n + 1)):
            raise _bad("engine.firing_order", f"got {list(order)}; must be a permutation of "
                                              f"the cylinders 1…{n}, each once")
    elif spec.strokes == 4 or train.throw_angles_deg is None:
        order = default_firing_order(arr, n) if spec.strokes == 4 else tuple(range(1, n + 1))
        if order is None:
            raise _bad("engine.firing_order", f"missing; there is no textbook default for a "
                                              f"{n}-cylinder {arr} engine: give it")
    pos = {c: p for p, c in enumerate(order)} if order is not None else None

    # throws
    if train.throw_angles_deg is not None:
        tau = np.asarray(train.throw_angles_deg, float)
        if len(tau) != n_throws:
            raise _bad("engine.throw_angles_deg", f"has {len(tau)} angles but the {arr} "
                                                  f"crankshaft of {n} cylinders has "
                                                  f"{n_throws} throws")
        if abs(_mod(tau[0])) > SAME_ANGLE_DEG:
            raise _bad("engine.throw_angles_deg", f"the first angle is {tau[0]:g}; angles "
                                                  "are measured from throw 1 (give 0 first)")
        how = "given"
    else:
        interval = cyc / n
        phi_even = np.array([pos[c] * interval for c in cyl]) - pos[1] * interval
        tau = np.zeros(n_throws)
        for t in range(1, n_throws + 1):
            members = cyl[throw == t]
            j0 = members[0] - 1
            tau[t - 1] = float(_mod(gam[j0] - gam[0] - phi_even[j0]))
            for c in members[1:]:
                lag = float(_mod(gam[c - 1] - gam[0] - tau[t - 1]))
                need = float(_mod(phi_even[c - 1]))
                if abs(_mod(lag - need + 180.0) - 180.0) > SAME_ANGLE_DEG:
                    apart = float(_mod(gam[c - 1] - gam[j0]))
                    needed = float(_mod(phi_even[c - 1] - phi_even[j0]))
                    raise _bad("engine.firing_order",
                               f"cannot fire evenly in the order {list(order)}: cylinders "
                               f"{members[0]} and {c} share throw {t}, so their TDCs are "
                               f"{apart:g}° apart, but firing every {interval:g}° in this "
                               f"order needs {needed:g}° (mod 360°); give throw_angles_deg "
                               f"for an odd-firing engine")
        how = "default for even firing"
    g = _mod(gam - gam[0] - tau[throw - 1])          # geometric lag of each cylinder

    # phases by the firing order (or the geometry alone for a two-stroke without one)
    if order is None:
        phase = g.copy()
    else:
        t_abs = np.zeros(n)
        t = 0.0
        for a, b in zip(order[:-1], order[1:]):
            d = float(_mod(g[b - 1] - g[a - 1]))
            if d < SAME_ANGLE_DEG:
                if spec.strokes == 2:
                    raise _bad("engine.firing_order", f"cylinders {a} and {b} reach TDC "
                                                      "together; a two-stroke cannot fire "
                                                      "them one after the other")
                d = 360.0
            t += d
            t_abs[b - 1] = t
        d_close = float(_mod(g[order[0] - 1] - g[order[-1] - 1]))
        if n > 1 and d_close < SAME_ANGLE_DEG:
            d_close = 360.0
        if n > 1 and t + d_close > cyc + SAME_ANGLE_DEG:
            raise _bad("engine.firing_order",
                       f"the order {list(order)} does not close one cycle of {cyc:g}° with "
                       f"these throws (firing each cylinder at its next TDC takes "
                       f"{t + d_close:g}°); check the order or throw_angles_deg")
        phase = _mod(t_abs - t_abs[0], cyc)
    intervals = np.diff(np.sort(np.append(phase, cyc)))
    even = bool(np.all(np.abs(intervals - cyc / n) < SAME_ANGLE_DEG))
    if order is None:
        order = tuple(int(c) for c in cyl[np.argsort(phase, kind="stable")])
    table = pd.DataFrame(dict(cylinder=cyl, bank=bank, throw=throw,
                              axial_position_mm=z * 1e3, bank_angle_deg=gam,
                              throw_angle_deg=tau[throw - 1], phase_deg=phase))
    return Layout(cylinders=table, firing_order=tuple(int(c) for c in order),
                  throw_angles_deg=tuple(float(x) for x in tau), throw_z=throw_z,
                  z_centre=float((z.min() + z.max()) / 2), cycle_deg=cyc, even_firing=even,
                  crankshaft=how)


# ------------------------------------------------------------------------------ torque

def _uniform_grid(theta_deg, cycle):
    """(step, offset index) when θ is a uniform grid from 0 whose step divides the cycle."""
    if theta_deg.size < 2 or theta_deg[0] != 0.0:
        return None
    step = theta_deg[1] - theta_deg[0]
    n = cycle / step
    if abs(n - round(n)) > ROUNDOFF_RTOL * n or not np.allclose(
            theta_deg, step * np.arange(theta_deg.size), rtol=0, atol=SAME_ANGLE_DEG):
        return None
    return step, int(round(n))


def cylinder_torques(spec, lay, theta_deg, columns=("M_Nm",), base=None):
    """Each cylinder's table columns at the crankshaft angles θ, from the one-cylinder
    model at the cylinder's bank angle and phase.

    Parameters
    ----------
    spec : EngineSpec
    lay : Layout
    theta_deg : array_like
        Crankshaft angles (cylinder 1's α). [deg]
    columns : tuple of str
        Columns of :func:`engine.force_table` wanted.
    base : pandas.DataFrame, optional
        The one-cylinder table at step·(0, 1, …, n − 1) when already computed (the shifted
        path only).

    Returns
    -------
    dict of ndarray
        ``{column: array (cylinders × angles)}``.

    Notes
    -----
    Cylinder j's row at θ is the one-cylinder table at α = θ − φ_j (:func:`force_table`
    with ``phase_deg = φ_j``; the bank does not change the table).  On a uniform grid from
    0 whose step divides the cycle and the phases, the one-cylinder table is computed once
    over the cycle and each cylinder's row is that table shifted by its phase (the same
    numbers; a test holds the two paths together).
    """
    theta = np.asarray(theta_deg, float)
    cyc = lay.cycle_deg
    grid = _uniform_grid(theta, cyc)
    phases = lay.phase_deg
    out = {c: np.empty((lay.n, theta.size)) for c in columns}
    if grid is not None:
        step, n = grid
        shifts = phases / step
        if np.all(np.abs(shifts - np.round(shifts)) < ROUNDOFF_RTOL * max(n, 1)):
            if base is None or len(base) != n:
                base = force_table(spec, step * np.arange(n))
            idx = np.arange(theta.size)
            for c in columns:
                col = base[c].to_numpy()
                rows = np.mod(idx[None, :] - np.round(shifts).astype(int)[:, None], n)
                out[c] = col[rows]
            return out
    for j in range(lay.n):
        t = force_table(spec, theta, bank_deg=float(lay.bank_deg[j]),
                        phase_deg=float(phases[j]))
        for c in columns:
            out[c][j] = t[c].to_numpy()
    return out


# ------------------------------------------------------------------------------ balance

def _throw_direction(lay, theta_rad, tau_deg):
    """Unit vector (complex) of a direction fixed on the crankshaft at τ from throw 1."""
    g1 = math.radians(float(lay.bank_deg[0]))
    return np.exp(1j * (cylinder_axis_angle(g1) + theta_rad[None, :]
                        + np.radians(np.asarray(tau_deg, float))[:, None]))


def two_plane_balance(unbalance, z, z_a, z_b=None):
    """Correction masses in two planes that balance rotating unbalances (or one plane).

    Parameters
    ----------
    unbalance : array_like of complex
        Mass·radius vectors of the unbalances, rotating with the shaft (any common
        frame). [kg·m]
    z : array_like of float
        Their axial positions. [m]
    z_a, z_b : float
        The two correction planes (``z_b`` None or equal to ``z_a``: one plane, static
        balance only). [m]

    Returns
    -------
    c_a, c_b : complex
        Mass·radius of the corrections in planes a and b (c_b = 0 for one plane). [kg·m]

    Notes
    -----
    Σ u + c_a + c_b = 0 (no force) and Σ z·u + z_a·c_a + z_b·c_b = 0 (no moment): the lever
    rule of dynamic balancing [2]_ (Example 11-1), solved in complex numbers.
    """
    u = np.asarray(unbalance, complex)
    z = np.asarray(z, float)
    S = -np.sum(u)
    if z_b is None or abs(z_b - z_a) <= SAME_ANGLE_DEG * 1e-3:
        return complex(S), 0j
    Q = -np.sum(z * u)
    c_a = (Q - z_b * S) / (z_a - z_b)
    return complex(c_a), complex(S - c_a)


def counterweights_for(spec, lay, train):
    """The counterweights of the train's design, as :class:`Counterweight` (z from
    cylinder 1's axis, angle from throw 1 in the direction of rotation)."""
    if train.counterweight_list:
        return tuple(train.counterweight_list)
    if train.counterweights == "none":
        return ()
    R, tau = spec.R, np.asarray(lay.throw_angles_deg)
    m_crank = spec.m_crank_rot or 0.0
    out = []
    for t in range(len(tau)):
        rods = int(np.sum(lay.throw_of == t))
        mr = (rods * spec.m_rod_rot + m_crank) * R
        if mr > 0:
            out.append(Counterweight(float(lay.throw_z[t]), mr, float(tau[t] + 180.0) % 360))
    if train.counterweights == "throws+first_order":
        # forward-rotating first-order force and moment, as mass·radius in the crank frame
        A = spec.mj * R                          # per cylinder, ×ω² gives the force
        phi = np.radians(lay.phase_deg)
        u = guide_direction(np.radians(lay.bank_deg))
        g1 = math.radians(float(lay.bank_deg[0]))
        # F1_fwd = ω²·(A/2)·Σ e^{−iφ}u; a mass·radius c at angle ψ gives ω²·i·e^{iγ1}·c
        # cos α + kλ sin α = Re[(1 − ikλ)e^{iα}]: the pin offset turns the forward part
        c1 = 1 - 1j * spec.k_offset * spec.lam
        unb = (A / 2) * c1 * np.exp(-1j * phi) * u / (1j * np.exp(1j * g1))
        zs = lay.z
        c_a, c_b = two_plane_balance(unb, zs, float(zs.min()), float(zs.max()))
        for zz, c in ((float(zs.min()), c_a), (float(zs.max()), c_b)):
            if abs(c) > ROUNDOFF_RTOL * A * max(lay.n, 1):
                out.append(Counterweight(zz, abs(c), math.degrees(np.angle(c)) % 360))
    return tuple(out)


def free_forces(spec, lay, theta_deg, counterweights=(), Pj=None):
    """The free (shaking) forces and moments of the engine over crankshaft angles.

    Parameters
    ----------
    spec : EngineSpec
    lay : Layout
    theta_deg : array_like
        Crankshaft angles. [deg]
    counterweights : sequence of Counterweight
    Pj : ndarray, optional
        Each cylinder's Pj at ``theta_deg`` (cylinders × angles) when already known
        (from :func:`cylinder_torques`). [N]

    Returns
    -------
    dict of complex ndarray
        ``F1, F2, Fj, Fr, Fcw, F`` (force, x + iy) [N] and ``M1, M2, Mj, Mr, Mcw, M``
        (moment about the centre, M_x + iM_y) [N·m]; F = Fj + Fr + Fcw, M likewise.
    """
    theta = np.radians(np.asarray(theta_deg, float))
    w2 = spec.omega ** 2
    R, lam, k = spec.R, spec.lam, spec.k_offset
    alpha = theta[None, :] - np.radians(lay.phase_deg)[:, None]
    u = guide_direction(np.radians(lay.bank_deg))[:, None]
    zc = (lay.z - lay.z_centre)[:, None]
    A = spec.mj * R * w2
    first, second = acceleration_orders(alpha, lam, k, amplitude=A)
    f1 = first * u
    f2 = second * u
    if Pj is None:
        if spec.acceleration == "exact":
            j = crank_slider(alpha.ravel(), R, spec.L, spec.omega,
                             offset=spec.pin_offset).j.reshape(alpha.shape)
        else:
            j = two_term_acceleration(alpha, R, lam, spec.omega, k)
        Pj = -spec.mj * j
    fj = -np.asarray(Pj) * u
    # rotating masses: each rod's mш.к at its own plane, mк at the throw's middle
    rod_dir = _throw_direction(lay, theta, np.asarray(lay.throw_angles_deg)[lay.throw_of])
    fr_rod = spec.m_rod_rot * R * w2 * rod_dir
    m_crank = spec.m_crank_rot or 0.0
    thr_dir = _throw_direction(lay, theta, lay.throw_angles_deg)
    fr_thr = m_crank * R * w2 * thr_dir
    ztc = (lay.throw_z - lay.z_centre)[:, None]
    if counterweights:
        cw_dir = _throw_direction(lay, theta, [c.angle_deg for c in counterweights])
        mr = np.array([c.mr for c in counterweights])[:, None]
        fcw = mr * w2 * cw_dir
        zcw = (np.array([c.z for c in counterweights]) - lay.z_centre)[:, None]
        Fcw, Mcw = fcw.sum(0), 1j * (zcw * fcw).sum(0)
    else:
        Fcw = Mcw = np.zeros(theta.shape, complex)
    out = dict(F1=f1.sum(0), F2=f2.sum(0), Fj=fj.sum(0),
               Fr=fr_rod.sum(0) + fr_thr.sum(0), Fcw=Fcw,
               M1=1j * (zc * f1).sum(0), M2=1j * (zc * f2).sum(0), Mj=1j * (zc * fj).sum(0),
               Mr=1j * ((zc * fr_rod).sum(0) + (ztc * fr_thr).sum(0)), Mcw=Mcw)
    out["F"] = out["Fj"] + out["Fr"] + out["Fcw"]
    out["M"] = out["Mj"] + out["Mr"] + out["Mcw"]
    return out


# ---------------------------------------------------------------------------- flywheel

def excess_work(theta_deg, M):
    """Running work of the torque above its mean, ∫(M − Mср)dθ, and its largest swing.

    Parameters
    ----------
    theta_deg : array_like
        Crankshaft angles over one whole cycle, sorted, first to last. [deg]
    M : array_like
        Total torque at those angles. [N·m]

    Returns
    -------
    work : ndarray
        ∫₀^θ (M − Mср) dθ (trapezoid rule, θ in rad). [J]
    L : float
        Lизб = max − min of ``work``, the excess work [1]_. [J]
    M_mean : float
        Mср over the range (trapezoid rule). [N·m]
    """
    th = np.radians(np.asarray(theta_deg, float))
    M = np.asarray(M, float)
    d = np.diff(th)
    M_mean = float(np.sum(0.5 * (M[1:] + M[:-1]) * d) / (th[-1] - th[0]))
    inc = 0.5 * ((M[1:] - M_mean) + (M[:-1] - M_mean)) * d
    work = np.concatenate(([0.0], np.cumsum(inc)))
    return work, float(work.max() - work.min()), M_mean


@dataclass(frozen=True)
class FlywheelResult:
    """A flywheel for a coefficient of speed fluctuation δ (:func:`flywheel`): the one
    result type of the engine's estimate (:func:`analyze_engine`) and of a machine's
    (:func:`dynamics.motion.size_flywheel`, which adds the exact flywheel and its
    motion). SI units.

    Attributes ``dW_max`` (= ``L_excess_J``) and ``J_classic`` (= ``J_flywheel_kgm2``)
    are the names :mod:`dynamics` reports them under.
    """

    L_excess_J: float          #: Lизб = ΔW_max, the largest swing of ∫(M − Mср)dθ [J]
    delta: float               #: δ = (ωmax − ωmin)/ωср [-]
    J0_kgm2: float             #: J0 = Lизб/(δω²), all rotating parts [kg·m²]
    share: float | None        #: Jм/J0 when the flywheel is that share of J0 [-]
    J_flywheel_kgm2: float     #: Jм = share·J0, or J0 − J_c [kg·m²]
    mD2_kgm2: float            #: flywheel moment mм·Dср² = 4·Jм [kg·m²]
    diameter_m: float | None = None   #: mean rim diameter Dср, when given [m]
    mass_kg: float | None = None      #: mм = 4Jм/Dср² [kg]
    rim_speed_m_s: float | None = None  #: peripheral speed π·Dср·n/60 [m/s]
    J_c: float = 0.0           #: inertia already on the shaft, subtracted from J0 [kg·m²]
    J_exact: float | None = None  #: the flywheel giving exactly δ with a variable J_red
    motion: object = None      #: the motion with ``J_exact`` (dynamics.MotionResult)

    @property
    def dW_max(self) -> float:
        """ΔW_max = Lизб. [J]"""
        return self.L_excess_J

    @property
    def J_classic(self) -> float:
        """The classic estimate J0 − J_c (or share·J0); ≤ 0: no flywheel needed. [kg·m²]"""
        return self.J_flywheel_kgm2


def flywheel(L_excess, omega, delta, share=0.85, diameter=None, *, J_c=None):
    """Flywheel from the excess work: J0 = Lизб/(δ·ω²), then Jм = share·J0 (the engine,
    Kolchin) or Jм = J0 − J_c (a machine whose own inertia J_c is known); mм·Dср² = 4·Jм.

    Parameters
    ----------
    L_excess : float
        Lизб (ΔW_max). [J]
    omega : float
        Mean angular velocity. [rad/s]
    delta : float
        Coefficient of cyclic irregularity. [-]
    share : float
        Jм/J0 (Kolchin: the flywheel carries 0.8…0.9 of J0) [1]_; not used with ``J_c``.
        [-]
    diameter : float, optional
        Mean diameter of the rim Dср (the rim taken as a thin ring, J = m(D/2)²). [m]
    J_c : float, optional
        The constant inertia already on the shaft (the cycle mean of J_red): then
        Jм = J0 − J_c (Khurmi & Gupta eq. 16.8; may be ≤ 0). [kg·m²]

    Returns
    -------
    FlywheelResult

    Notes
    -----
    From ½J0(ωmax² − ωmin²) = Lизб with ωmax + ωmin = 2ω [1]_, [2]_ (Example 11-3).
    """
    for key, v, lo in (("L_excess", L_excess, 0.0), ("omega", omega, 0.0)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= lo):
            raise _bad(key, f"got {v!r}; must be a finite number >= {lo:g}")
    if not (isinstance(delta, (int, float)) and math.isfinite(delta) and 0 < delta <= 1):
        raise _bad("delta", f"got {delta!r}; must be > 0 and <= 1")
    J0 = L_excess / (delta * omega ** 2)
    if J_c is None:
        Jm, Jc = share * J0, 0.0
    else:
        Jm, Jc, share = J0 - J_c, float(J_c), None
    mass = speed = None
    if diameter is not None:
        mass = 4.0 * Jm / diameter ** 2
        speed = diameter * omega / 2.0
    return FlywheelResult(L_excess, delta, J0, share, Jm, 4.0 * Jm, diameter, mass, speed,
                          J_c=Jc)


# ------------------------------------------------------------------------ the pipeline

#: Columns of cylinders.csv.
CYLINDER_COLUMNS = ("cylinder", "bank", "throw", "axial_position_mm", "bank_angle_deg",
                    "throw_angle_deg", "phase_deg")
#: Columns of balance.csv, in order: forces [N] then moments [N·m].
BALANCE_PARTS = ("1", "2", "j", "r", "cw", "")
BALANCE_COLUMNS = ("alpha_deg",) + tuple(
    f"F{p}_{c}_N" for p in BALANCE_PARTS for c in "xy") + tuple(
    f"M{p}_{c}_Nm" for p in BALANCE_PARTS for c in "xy")


def TORQUE_COLUMNS(n):
    """Columns of torque.csv for n cylinders."""
    return ("alpha_deg",) + tuple(f"M_{j}_Nm" for j in range(1, n + 1)) + ("M_total_Nm",)


@dataclass(frozen=True)
class EngineTrainSummary:
    """Summary of the whole engine (:func:`analyze_engine`); SI units, angles in deg."""

    M_mean_Nm: float            #: Mкр.ср, mean total torque over the cycle
    M_max_Nm: float             #: Mкр.max
    alpha_M_max_deg: float      #: its crankshaft angle
    M_min_Nm: float             #: Mкр.min
    alpha_M_min_deg: float      #: its crankshaft angle
    mu: float                   #: non-uniformity μ = (Mкр.max − Mкр.min)/Mкр.ср [-]
    Mi_Nm: float                #: indicated torque Mi = pi·Vh·i/(π·τ)
    Me_Nm: float | None         #: effective torque Me = ηм·Mi
    Ni_kW: float                #: indicated power Ni = pi·Vh·i·n/(30·τ)
    Ne_kW: float | None         #: effective power Ne = ηм·Ni
    diff_pct: float             #: (Mкр.ср − Mi)/Mi·100, the course project's check
    L_excess_J: float           #: Lизб, largest swing of ∫(Mкр − Mкр.ср)dθ
    flywheel: FlywheelResult | None  #: J0, Jм, mм·Dср² (when δ is given)
    counterweights: tuple       #: the Counterweight list in use
    firing_interval_deg: float  #: cycle/i
    even_firing: bool


@dataclass(frozen=True)
class EngineTrainResult:
    """The whole engine computed at the spec's speed (constant ω).

    Attributes
    ----------
    cylinder : EngineResult
        The one-cylinder table, curves and summary (every cylinder is this model).
    train : CrankTrain
    layout : Layout
    torque : pandas.DataFrame
        torque.csv: ``alpha_deg``, ``M_1_Nm`` … ``M_i_Nm``, ``M_total_Nm`` over the cycle
        at the table step.
    curves : pandas.DataFrame
        The same on the fine grid, with ``work_J`` = ∫(M_total − Mср)dθ.
    torque_table : pandas.DataFrame
        The course project's total-torque table: the torque columns over one firing
        interval (the whole cycle for an odd-firing engine) at the table step.
    balance : pandas.DataFrame
        balance.csv (:data:`BALANCE_COLUMNS`) over one revolution at the table step.
    balance_curves : pandas.DataFrame
        The same on the fine grid (plots).
    balance_amplitudes : pandas.DataFrame
        Largest free force and moment of each part over a revolution and whether it is
        balanced: rows ``1, 2, j, r, cw, before, after``.
    summary : EngineTrainSummary
    """

    cylinder: EngineResult
    train: CrankTrain
    layout: Layout
    torque: pd.DataFrame
    curves: pd.DataFrame
    torque_table: pd.DataFrame
    balance: pd.DataFrame
    balance_curves: pd.DataFrame
    balance_amplitudes: pd.DataFrame
    summary: EngineTrainSummary


def _uniform(step, cycle):
    n = int(math.ceil(cycle / step * (1 - ROUNDOFF_RTOL)))
    return np.linspace(0.0, cycle, n + 1)


def _balance_frame(theta_deg, f, scale_F, scale_M):
    """balance.csv: the free forces and moments at ``theta_deg``, their round-off
    residues (a balanced part: ~1e-12 N) as 0 against the engine's force and moment
    scales ``scale_F`` [N] and ``scale_M`` [N·m]."""
    import pandas as pd

    cols, scale = [np.asarray(theta_deg, float)], [0.0]     # angles: only −0.0 → 0.0
    for kind, sc in (("F", scale_F), ("M", scale_M)):
        for p in BALANCE_PARTS:
            v = f[f"{kind}{p}"]
            cols += [v.real, v.imag]
            scale += [sc, sc]
    block = snap_roundoff(np.column_stack(cols), scale)
    return pd.DataFrame(block, columns=list(BALANCE_COLUMNS))


def analyze_engine(spec, train, settings=None, *, fine_step_deg=None) -> EngineTrainResult:
    """The whole engine: layout, torques, uniformity, flywheel, free forces and balance.

    Parameters
    ----------
    spec : EngineSpec
    train : CrankTrain
    settings : TableSettings, optional
        The table step (torque.csv, balance.csv) and the one-cylinder table rows.
    fine_step_deg : float, optional
        Step of the fine grid for the extremes, Lизб and the plots (default: the table
        step, at most 0.5°, adjusted to divide the cycle). [deg]

    Returns
    -------
    EngineTrainResult
    """
    import pandas as pd

    settings = TableSettings() if settings is None else settings
    if not isinstance(settings, TableSettings):
        raise _bad("settings", f"must be a TableSettings, got {type(settings).__name__}")
    if fine_step_deg is not None and not (
            isinstance(fine_step_deg, (int, float)) and math.isfinite(fine_step_deg)
            and 0 < fine_step_deg <= spec.cycle_deg if isinstance(spec, EngineSpec) else True):
        raise _bad("fine_step_deg", f"got {fine_step_deg!r}; must be a finite number > 0 "
                                    "and not above the cycle [deg]")
    lay = layout(spec, train)
    one = analyze(spec, settings)
    cyc, n = spec.cycle_deg, lay.n
    step = settings.step_deg
    fine = min(step, PLOT_STEP_DEG) if fine_step_deg is None else fine_step_deg
    cols = TORQUE_COLUMNS(n)

    def torque_frame(theta, M):
        """torque.csv: θ, each cylinder's Mкр and the total; round-off residues (the
        total of a balanced instant, ~1e-14 N·m) as 0 against the largest torque."""
        block = np.column_stack([theta, M.T, M.sum(0)])
        scale = np.full(block.shape[1], np.max(np.abs(block[:, 1:]), initial=0.0))
        scale[0] = 0.0
        return pd.DataFrame(snap_roundoff(block, scale), columns=list(cols))

    n_steps = cyc / step
    if abs(n_steps - round(n_steps)) < ROUNDOFF_RTOL * n_steps:
        table_theta = _uniform(step, cyc)
    else:
        table_theta = np.append(step * np.arange(int(cyc // step) + 1), cyc)
    theta_f = table_theta if (step <= fine and table_theta.size > 1 and np.allclose(
        np.diff(table_theta), step)) else _uniform(fine, cyc)
    # the one-cylinder table over the cycle, shared by every cylinder when it fits
    base = None
    a_one = one.table["alpha_deg"].to_numpy()
    if a_one.size == theta_f.size and np.allclose(a_one, theta_f, rtol=0,
                                                  atol=SAME_ANGLE_DEG):
        base = one.table.iloc[:-1]
    parts = cylinder_torques(spec, lay, theta_f, ("M_Nm", "Pj_N"), base=base)
    same = theta_f is table_theta
    torque = torque_frame(table_theta, parts["M_Nm"] if same else
                          cylinder_torques(spec, lay, table_theta, base=base)["M_Nm"])
    M_total = parts["M_Nm"].sum(0)
    work, L, M_mean = excess_work(theta_f, M_total)
    curves = pd.DataFrame(np.column_stack([theta_f, parts["M_Nm"].T, M_total, work]),
                          columns=list(cols) + ["work_J"])
    span = lay.firing_interval_deg if lay.even_firing else cyc
    torque_table = torque[torque["alpha_deg"] <= span + SAME_ANGLE_DEG].reset_index(drop=True)

    cws = counterweights_for(spec, lay, train)
    # the engine's force scale (every inertia force in phase) and its arm, the length
    scale_F = n * spec.mj * spec.R * spec.omega ** 2 + \
        (n * spec.m_rod_rot + (spec.m_crank_rot or 0) * len(lay.throw_angles_deg)) \
        * spec.R * spec.omega ** 2
    length = max(float(np.ptp(lay.z)), spec.bore)
    keep = theta_f <= 360.0 + SAME_ANGLE_DEG
    fb = free_forces(spec, lay, theta_f[keep], cws, Pj=parts["Pj_N"][:, keep])
    balance_curves = _balance_frame(theta_f[keep], fb, scale_F, scale_F * length)
    if same:
        balance = balance_curves
    else:
        rev = table_theta[table_theta <= 360.0 + SAME_ANGLE_DEG]
        balance = _balance_frame(rev, free_forces(spec, lay, rev, cws), scale_F,
                                 scale_F * length)
    rows = []
    for key, F, M in (("1", fb["F1"], fb["M1"]), ("2", fb["F2"], fb["M2"]),
                      ("j", fb["Fj"], fb["Mj"]), ("r", fb["Fr"], fb["Mr"]),
                      ("cw", fb["Fcw"], fb["Mcw"]),
                      ("before", fb["Fj"] + fb["Fr"], fb["Mj"] + fb["Mr"]),
                      ("after", fb["F"], fb["M"])):
        fmax, mmax = float(np.max(np.abs(F))), float(np.max(np.abs(M)))
        rows.append(dict(part=key, F_max_N=fmax, M_max_Nm=mmax,
                         F_balanced=fmax <= BALANCED_RTOL * scale_F,
                         M_balanced=mmax <= BALANCED_RTOL * scale_F * length))
    amplitudes = pd.DataFrame(rows)

    # summary
    i_max, i_min = int(np.argmax(M_total)), int(np.argmin(M_total))
    pi = one.summary.pi_MPa * 1e6
    Mi = pi * spec.Vh * n / (math.pi * spec.strokes)
    Ni = indicated_power(pi, spec.Vh, spec.speed_rpm, spec.strokes, n)
    eta = train.mechanical_efficiency
    fw = None
    if train.delta is not None:
        fw = flywheel(L, spec.omega, train.delta, train.flywheel_share,
                      train.flywheel_diameter)
    summary = EngineTrainSummary(
        M_mean_Nm=M_mean, M_max_Nm=float(M_total[i_max]),
        alpha_M_max_deg=float(theta_f[i_max]), M_min_Nm=float(M_total[i_min]),
        alpha_M_min_deg=float(theta_f[i_min]),
        mu=(float(M_total[i_max] - M_total[i_min]) / M_mean) if M_mean else float("nan"),
        Mi_Nm=Mi, Me_Nm=None if eta is None else eta * Mi, Ni_kW=Ni * 1e-3,
        Ne_kW=None if eta is None else eta * Ni * 1e-3,
        diff_pct=(M_mean - Mi) / Mi * 100.0 if Mi else float("nan"), L_excess_J=L,
        flywheel=fw, counterweights=cws, firing_interval_deg=lay.firing_interval_deg,
        even_firing=lay.even_firing)
    return EngineTrainResult(cylinder=one, train=train, layout=lay, torque=torque,
                             curves=curves, torque_table=torque_table, balance=balance,
                             balance_curves=balance_curves, balance_amplitudes=amplitudes,
                             summary=summary)
