"""Bearing loads of the crank train: crank pins, main journals, the torques the main
journals carry, the big-end bearing and the piston pin.

Array interfaces (no engine layout object needed): every function takes the crank angles
as an array and the per-cylinder quantities of the force table (:func:`engine.force_table`)
as arrays, so a single cylinder, a vee pin with two rods and a whole crankshaft use the
same code.  Vectorised over the angles; loops only over the (few) rods, throws and
journals.

Frames and signs
----------------
*Engine frame* (x, y), as in :mod:`engine.kinematics`: the crank axis O at the origin, y
up along the cylinder axis of a bank with bank angle 0, x to the right, seen from the
flywheel end (z runs from the front to the flywheel); the shaft turns counter-clockwise
in this view (ω > 0).  Forces are complex numbers ``x + iy``.

*Crankshaft angle* θ [deg] and throws: throw k points at δk = θ + τk from the vertical
(+y), counted in the direction of rotation; τk is the throw's direction at θ = 0 (for an
engine whose θ is cylinder 1's α, τk = γ1 + the throw's angle from throw 1, γ1 the bank
angle of cylinder 1).  A cylinder whose axis is turned by its bank angle γ from +y (in
the direction of rotation) sees the crank of its throw at its own crank angle
α = δk − γ (mod 360°); its working cycle lags by its phase, α = θ − phase (mod cycle), so
``phase ≡ γ − τk`` (mod 360°).

*Crank frame* of a throw (the textbook's, as for Rшш in :mod:`engine.forces`): K along
the crank towards the crank axis, T perpendicular to it in the direction of rotation; the
direction angle Ψ = atan2(T, K) is 0° along the crank towards the crank axis and grows
in the direction of rotation.  A crank-frame load (K, T) of a throw pointing at δ is the
engine-frame force ``F = e·(−K + iT)`` with ``e = exp(i(90° + δ))`` (the unit vector
from O to the crank pin).

*Main journals* are numbered from the front (free) end; the last one is next to the
flywheel (power take-off).  The load on a journal Q is the force the crankshaft presses
the bearing with (the sum of the lever-rule shares of the loads on the crankshaft); the
bearing's reaction on the shaft is −Q.  Its crank-frame components (K, T, Ψ) are given in
the crank frame of a reference throw (default: the throw just in front of the journal;
for the first journal, throw 1), as the textbook draws the polar diagram of a main
journal [1]_.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей.
   М.: Высшая школа, 2008, § "Силы, действующие на шейки коленчатого вала" (the crank-pin
   load Rшш = √(T² + (K + Kr.ш)²), the main-journal loads from the adjacent throws by the
   split-crankshaft (lever) rule, the torques carried by the main journals, the polar and
   wear diagrams).
.. [2] Вихерт М. М. и др. Конструирование и расчёт автотракторных двигателей. М.:
   Машиностроение, 1964 (big-end and piston-pin loads).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.tolerances import ROUNDOFF_RTOL
from linkage.groups import dot

from ..forces import crank_pin_resultant, load_angle_deg
from ..kinematics import guide_direction

__all__ = ["crank_unit", "to_engine_frame", "to_crank_frame", "cylinder_alpha",
           "crank_pin_load", "lever_rule", "journal_torques",
           "big_end_load", "piston_pin_load", "load_stats", "LoadStats", "Crankshaft",
           "CrankshaftLoads", "crankshaft_loads", "BearingInputError"]


class BearingInputError(SpecError):
    """Inconsistent crank-train data for the bearing loads (a :class:`SpecError`)."""


# ------------------------------------------------------------------------ frames


def crank_unit(delta_deg):
    """Unit vector from the crank axis O to the crank pin, engine frame.

    Parameters
    ----------
    delta_deg : array_like
        Angle of the throw from the vertical (+y), in the direction of rotation. [deg]

    Returns
    -------
    complex ndarray
        ``exp(i(90° + δ))``.
    """
    return guide_direction(np.asarray(delta_deg, float), deg=True)


def to_engine_frame(K, T, delta_deg):
    """Engine-frame force of a crank-frame load (K + towards the crank axis, T + in the
    direction of rotation) on a throw pointing at ``delta_deg``: ``F = e·(−K + iT)``. [N]"""
    return crank_unit(delta_deg) * (-np.asarray(K, float) + 1j * np.asarray(T, float))


def to_crank_frame(F, delta_deg):
    """Crank-frame components (K, T) of the engine-frame force ``F`` on a throw pointing at
    ``delta_deg``: K = F·(−e), T = F·(ie). [N]"""
    e = crank_unit(delta_deg)
    return dot(F, -e), dot(F, 1j * e)


def cylinder_alpha(theta_deg, phase_deg, cycle_deg):
    """A cylinder's own crank angle α = θ − phase, wrapped into [0, cycle). [deg]"""
    return np.mod(np.asarray(theta_deg, float) - phase_deg, cycle_deg)


# ------------------------------------------------------------------------ crank pin


def crank_pin_load(K, T, m_rod_rot, R, omega):
    """Load on a crank pin from any number of rods, in the crank frame.

    Parameters
    ----------
    K, T : array_like, shape (n_rods, n) or (n,)
        Each rod's force on the pin at the same crankshaft angles (the force table's
        ``K_N`` and ``T_N`` of that cylinder at its own α): K + towards the crank axis, T +
        in the direction of rotation.  Both are crank-frame components, so the rods of a
        vee pin add without any rotation: the bank angle only sets each cylinder's α. [N]
    m_rod_rot : float or array_like, shape (n_rods,)
        Rotating part of each rod mш.к. [kg]
    R, omega : float
        Crank radius [m] and angular velocity [rad/s].

    Returns
    -------
    K_pin, T_pin : ndarray, shape (n,)
        ΣK + ΣKr.ш (Kr.ш = −mш.к·R·ω², outwards) and ΣT. [N]

    Notes
    -----
    For one rod this is the textbook Rшш = √(T² + (K + Kr.ш)²) of the force table [1]_.
    """
    K = np.atleast_2d(np.asarray(K, float))
    T = np.atleast_2d(np.asarray(T, float))
    m = np.broadcast_to(np.asarray(m_rod_rot, float), (K.shape[0],))
    Kr = -m.sum() * R * omega ** 2
    return K.sum(axis=0) + Kr, T.sum(axis=0)


# ------------------------------------------------------------------------ main journals


def lever_rule(F, z, z_journals):
    """Shares of point loads on the journals of a split (statically determinate)
    crankshaft.

    Parameters
    ----------
    F : complex array_like, shape (n_loads, n)
        Loads on the crankshaft (engine frame). [N]
    z : array_like, shape (n_loads,)
        Their axial positions. [m]
    z_journals : array_like, shape (n_journals,)
        Axial positions of the main journals, increasing. [m]

    Returns
    -------
    complex ndarray, shape (n_journals, n)
        Q, the load each journal carries (the force it presses its bearing with). [N]

    Notes
    -----
    Each load lies in one span between neighbouring journals j and j + 1 and is shared
    as on a simply supported beam: ``Qj += F·(ζj+1 − z)/(ζj+1 − ζj)``,
    ``Qj+1 += F·(z − ζj)/(ζj+1 − ζj)`` [1]_.  A load on a journal goes to it entirely.
    Loads outside the outermost journals are refused (an overhung crank is not a
    split-crankshaft case).
    """
    F = np.atleast_2d(np.asarray(F, complex))
    z = np.asarray(z, float)
    zj = np.asarray(z_journals, float)
    if zj.ndim != 1 or len(zj) < 2 or np.any(np.diff(zj) <= 0):
        raise BearingInputError(Problem("journal_positions_mm",
                                        Text("errors.engine.bearings.need_at_least",
                                             {"value": list(zj * 1e3)})))
    tol = ROUNDOFF_RTOL * (zj[-1] - zj[0])
    bad = (z < zj[0] - tol) | (z > zj[-1] + tol)
    if np.any(bad):
        raise BearingInputError(Problem(
            "journal_positions_mm",
            Text("errors.engine.bearings.loads_at_mm",
                 {"value": list(np.round(z[bad] * 1e3, 6)), "value2": zj[0] * 1e3,
                  "value3": zj[-1] * 1e3})))
    span = np.clip(np.searchsorted(zj, z, side="right") - 1, 0, len(zj) - 2)
    a, b = zj[span], zj[span + 1]
    w_right = np.clip((z - a) / (b - a), 0.0, 1.0)
    Q = np.zeros((len(zj), F.shape[1]), complex)
    np.add.at(Q, span, (1.0 - w_right)[:, None] * F)
    np.add.at(Q, span + 1, w_right[:, None] * F)
    return Q


def journal_torques(M_throw, z_throw, z_journals):
    """Torques carried by the main journals ("набегающие моменты").

    Parameters
    ----------
    M_throw : array_like, shape (n_throws, n)
        Torque each throw receives from its rods, + in the direction of rotation. [N·m]
    z_throw : array_like, shape (n_throws,)
        Axial positions of the throws. [m]
    z_journals : array_like, shape (n_journals,)
        Axial positions of the journals, increasing from the free end. [m]

    Returns
    -------
    ndarray, shape (n_journals, n)
        The torque through each journal: the sum of the torques of the throws in front
        of it (z < ζj); the last journal, at the flywheel end, carries the total [1]_.
    """
    M = np.atleast_2d(np.asarray(M_throw, float))
    z = np.asarray(z_throw, float)
    zj = np.asarray(z_journals, float)
    before = (z[None, :] < zj[:, None]).astype(float)
    return before @ M


# ------------------------------------------------------------------------ rods, pistons


def big_end_load(K, T, Kr, alpha_deg, beta_deg):
    """Load on the big-end bearing of one rod, in the rod frame.

    Parameters
    ----------
    K, T : array_like
        The rod's force on the crank pin (force table ``K_N``, ``T_N``). [N]
    Kr : float or array_like
        Kr.ш = −mш.к·R·ω² of this rod. [N]
    alpha_deg, beta_deg : array_like
        The cylinder's crank angle α and rod angle β (force table). [deg]

    Returns
    -------
    along, across : ndarray
        Force of the crank pin on the big end: along the rod, + from the big end towards
        the piston pin (compressing the rod), and across it, + 90° counter-clockwise
        from that direction (engine frame seen from the front). [N]

    Notes
    -----
    The big end carries the pin load of its own rod, reversed: −Rшш (the rod's rotating
    mass mш.к sits in the big end, so Kr.ш is included).  In the cylinder's own frame the
    crank is e = exp(i(90° + α)) and the rod points from the crank pin to the piston pin
    along e₃ = exp(i(90° − β)).
    """
    e = crank_unit(alpha_deg)                        # the crank, cylinder frame
    e3 = np.exp(1j * (np.pi / 2 - np.radians(np.asarray(beta_deg, float))))
    F = -(e * (-(np.asarray(K, float) + np.asarray(Kr, float)) + 1j * np.asarray(T, float)))
    return dot(F, e3), dot(F, 1j * e3)


def piston_pin_load(dPg, j, m_piston, N):
    """Load on the piston pin from the piston: gas force and the piston's own inertia
    (without the rod's small end), with the side force.

    Parameters
    ----------
    dPg : array_like
        Gas force ΔPг, + towards the crank axis. [N]
    j : array_like
        Piston acceleration used by the table (+ towards the crank axis). [m/s²]
    m_piston : float
        Piston group mass mп (without the rod's small end mш.п). [kg]
    N : array_like
        Side force N of the force table (the wall's force on the piston). [N]

    Returns
    -------
    axial, side, magnitude : ndarray
        Pп = ΔPг − mп·j along the cylinder axis (+ towards the crank axis), the side
        component N that the pin passes from the rod to the piston, and √(Pп² + N²). [N]

    Notes
    -----
    The piston's equilibrium: gas, its inertia −mп·j and the wall's force N are balanced
    by the pin, so the piston presses the pin with ΔPг + Pj.п along the axis and N across
    it [2]_ (the small end's inertia −mш.п·j acts on the rod, not on the pin).
    """
    axial = np.asarray(dPg, float) - m_piston * np.asarray(j, float)
    side = np.asarray(N, float)
    return axial, side, np.hypot(axial, side)


# ------------------------------------------------------------------------ statistics


@dataclass
class LoadStats:
    """Extremes and cycle mean of a load magnitude (one bearing).

    ``max_N``, ``alpha_max_deg``, ``min_N``, ``alpha_min_deg``, ``mean_N`` (trapezoid
    rule over the angle / cycle) and ``chi`` = max/mean (the load-shock coefficient
    χ of the textbook [1]_).
    """

    max_N: float
    alpha_max_deg: float
    min_N: float
    alpha_min_deg: float
    mean_N: float
    chi: float


def load_stats(alpha_deg, magnitude, cycle_deg):
    """:class:`LoadStats` of a load magnitude over one cycle (rows sorted, covering the
    cycle from its start to its end)."""
    a = np.asarray(alpha_deg, float)
    y = np.asarray(magnitude, float)
    i, k = int(np.argmax(y)), int(np.argmin(y))
    mean = float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(a)) / cycle_deg)
    return LoadStats(float(y[i]), float(a[i]), float(y[k]), float(a[k]), mean,
                     float(y[i] / mean) if mean > 0 else float("nan"))


# ------------------------------------------------------------------------ crankshaft


@dataclass(frozen=True)
class Crankshaft:
    """Geometry and rotating masses of a crankshaft for the bearing loads (SI).

    Attributes
    ----------
    throw_angle_deg : tuple of float
        τk, the direction of each throw from the vertical at θ = 0, in the direction of
        rotation (module docstring). [deg]
    z_throw : tuple of float
        Axial position of each throw (its crank-pin centre), from the front. [m]
    z_journal : tuple of float
        Axial positions of the main journals, increasing. [m]
    m_crank_rot : tuple of float
        Rotating mass of each throw's crank (pin and webs) reduced to the crank radius,
        mк. [kg]
    counterweights : tuple of (float, float, float)
        (m·r [kg·m], angle from its throw in the direction of rotation [deg], axial
        position [m]) per counterweight, and the index of its throw as a fourth item.
    journal_frame_throw : tuple of int or None
        For each journal, the throw (0-based) whose crank frame its (K, T) use; default
        the throw in front of it (throw 0 for the first journal).
    """

    throw_angle_deg: tuple
    z_throw: tuple
    z_journal: tuple
    m_crank_rot: tuple
    counterweights: tuple = ()
    journal_frame_throw: tuple | None = None

    @classmethod
    def full_support(cls, throw_angle_deg, spacing, m_crank_rot=0.0, counterweights=()):
        """Inline layout with a main journal between every two throws and at both ends
        (i + 1 journals): throws at spacing·(k + ½), journals at spacing·j.  Counterweights
        given as (m·r, angle, throw index) sit at their throw's axial position."""
        n = len(throw_angle_deg)
        z = tuple(spacing * (k + 0.5) for k in range(n))
        zj = tuple(spacing * j for j in range(n + 1))
        m = tuple(np.broadcast_to(np.asarray(m_crank_rot, float), (n,)).tolist())
        cw = tuple((mr, ang, z[k], k) for mr, ang, k in counterweights)
        return cls(tuple(float(t) for t in throw_angle_deg), z, zj, m, cw)

    def frame_throw(self):
        """The reference throw (0-based) of each journal's crank frame."""
        if self.journal_frame_throw is not None:
            return tuple(self.journal_frame_throw)
        zt = np.asarray(self.z_throw)
        out = []
        for zj in self.z_journal:
            front = np.nonzero(zt < zj)[0]
            out.append(int(front[np.argmax(zt[front])]) if len(front) else
                       int(np.argmin(zt)))
        return tuple(out)


@dataclass
class CrankshaftLoads:
    """Loads on the crank pins and main journals over the crankshaft angle.

    Attributes
    ----------
    alpha_deg : ndarray
        Crankshaft angle θ (= cylinder 1's α). [deg]
    crankpins : pandas.DataFrame
        ``alpha_deg``, then per throw k (1-based): ``K_k_N``, ``T_k_N`` (crank frame, incl.
        Kr.ш), ``R_k_N``, ``psi_k_deg``.
    journals : pandas.DataFrame
        ``alpha_deg``, then per journal j (1-based): ``X_j_N``, ``Y_j_N`` (engine frame),
        ``K_j_N``, ``T_j_N``, ``R_j_N``, ``psi_j_deg`` (crank frame of its reference throw).
    journal_torques : pandas.DataFrame
        ``alpha_deg``, then ``M_j_Nm`` per journal (torque carried, + in the direction of
        rotation).
    pin_stats, journal_stats : list of LoadStats
    torque_stats : list of dict
        Per journal: ``max_Nm``, ``min_Nm``, ``swing_Nm`` = max − min.
    most_loaded_pin, most_loaded_journal, most_twisted_journal : int
        1-based numbers (by the largest load, by the largest |torque| swing).
    F_throw : complex ndarray (n_throws, n)
        Pin loads in the engine frame (rods incl. Kr.ш). [N]
    F_rot : complex ndarray (n_throws, n)
        Centrifugal force of each throw's crank mass mк. [N]
    F_cw : complex ndarray (n_cw, n)
        Centrifugal forces of the counterweights. [N]
    Q : complex ndarray (n_journals, n)
        Journal loads, engine frame. [N]
    shaft : Crankshaft
    Kr_throw : ndarray (n_throws,)
        ΣKr.ш of each throw's rods, when given (the pole Oш of the polar diagram). [N]
    """

    alpha_deg: np.ndarray
    crankpins: object
    journals: object
    journal_torques: object
    pin_stats: list
    journal_stats: list
    torque_stats: list
    most_loaded_pin: int
    most_loaded_journal: int
    most_twisted_journal: int
    F_throw: np.ndarray = field(repr=False)
    F_rot: np.ndarray = field(repr=False)
    F_cw: np.ndarray = field(repr=False)
    Q: np.ndarray = field(repr=False)
    shaft: Crankshaft = field(repr=False, default=None)
    Kr_throw: np.ndarray = field(repr=False, default=None)


def crankshaft_loads(theta_deg, shaft: Crankshaft, pin_K, pin_T, R, omega, cycle_deg,
                     rod_z=None, pin_Kr=None):
    """Crank-pin and main-journal loads and the journal torques of a crankshaft.

    Parameters
    ----------
    theta_deg : array_like, shape (n,)
        Crankshaft angles (sorted, covering one cycle for the statistics). [deg]
    shaft : Crankshaft
    pin_K, pin_T : array_like, shape (n_throws, n)
        Crank-frame pin load of each throw from its rods, rotating parts included (from
        :func:`crank_pin_load`). [N]
    R, omega : float
        Crank radius [m], angular velocity [rad/s].
    cycle_deg : float
        Cycle length for the means. [deg]
    rod_z : sequence, optional
        Per throw, a list of (K, T, z) of its rods when they sit at different axial
        positions on the pin (a vee with a bank offset): each rod's force then enters the
        lever rule at its own z.  By default the pin load acts at the throw's centre.
    pin_Kr : array_like, shape (n_throws,), optional
        ΣKr.ш of each throw's rods (included in ``pin_K``), kept for the polar diagram's
        pole Oш. [N]

    Returns
    -------
    CrankshaftLoads

    Notes
    -----
    Loads on the shaft: the pin loads, the crank masses' centrifugal forces
    mк·R·ω²·e and the counterweights' m·r·ω² at their angles; all shared out by
    :func:`lever_rule` [1]_.  Torques: Mk = Tk·R per throw, accumulated by
    :func:`journal_torques`.
    """
    import pandas as pd

    th = np.asarray(theta_deg, float)
    pin_K = np.atleast_2d(np.asarray(pin_K, float))
    pin_T = np.atleast_2d(np.asarray(pin_T, float))
    nt = len(shaft.throw_angle_deg)
    if pin_K.shape[0] != nt or pin_T.shape[0] != nt:
        raise BearingInputError(Text("errors.engine.bearings.pin_loads_given",
                                     {"value": pin_K.shape[0], "nt": nt}))
    tau = np.asarray(shaft.throw_angle_deg, float)
    delta = th[None, :] + tau[:, None]                       # (nt, n)
    e = crank_unit(delta)
    F_throw = to_engine_frame(pin_K, pin_T, delta)
    F_rot = np.asarray(shaft.m_crank_rot, float)[:, None] * R * omega ** 2 * e
    cw = shaft.counterweights
    if cw:
        F_cw = np.stack([mr * omega ** 2 * e[k] * np.exp(1j * np.radians(ang))
                         for mr, ang, _, k in cw])
        z_cw = np.array([c[2] for c in cw], float)
    else:
        F_cw = np.zeros((0, len(th)), complex)
        z_cw = np.zeros(0)
    zt = np.asarray(shaft.z_throw, float)
    if rod_z is None:
        loads, zs = [F_throw], [zt]
    else:
        Fr, zr = [], []
        for k, rods in enumerate(rod_z):
            for K_r, T_r, z_r in rods:
                Fr.append(to_engine_frame(K_r, T_r, delta[k]))
                zr.append(z_r)
        loads, zs = [np.array(Fr)], [np.array(zr, float)]
    loads += [F_rot, F_cw]
    zs += [zt, z_cw]
    zj = np.asarray(shaft.z_journal, float)
    Q = lever_rule(np.concatenate(loads), np.concatenate(zs), zj)
    Mt = pin_T * R
    Mj = journal_torques(Mt, zt, zj)

    pins = {"alpha_deg": th}
    pin_stats = []
    for k in range(nt):
        Rk, psi = crank_pin_resultant(pin_T[k], pin_K[k])
        pins.update({f"K_{k + 1}_N": pin_K[k], f"T_{k + 1}_N": pin_T[k],
                     f"R_{k + 1}_N": Rk, f"psi_{k + 1}_deg": psi})
        pin_stats.append(load_stats(th, Rk, cycle_deg))
    jr = {"alpha_deg": th}
    j_stats = []
    ref = shaft.frame_throw()
    for j in range(len(zj)):
        Kj, Tj = to_crank_frame(Q[j], delta[ref[j]])
        Rj = np.abs(Q[j])
        jr.update({f"X_{j + 1}_N": Q[j].real, f"Y_{j + 1}_N": Q[j].imag,
                   f"K_{j + 1}_N": Kj, f"T_{j + 1}_N": Tj, f"R_{j + 1}_N": Rj,
                   f"psi_{j + 1}_deg": load_angle_deg(Tj, Kj)})
        j_stats.append(load_stats(th, Rj, cycle_deg))
    tq = {"alpha_deg": th}
    t_stats = []
    for j in range(len(zj)):
        tq[f"M_{j + 1}_Nm"] = Mj[j]
        t_stats.append(dict(max_Nm=float(Mj[j].max()), min_Nm=float(Mj[j].min()),
                            swing_Nm=float(Mj[j].max() - Mj[j].min())))
    return CrankshaftLoads(
        alpha_deg=th, crankpins=pd.DataFrame(pins), journals=pd.DataFrame(jr),
        journal_torques=pd.DataFrame(tq), pin_stats=pin_stats, journal_stats=j_stats,
        torque_stats=t_stats,
        most_loaded_pin=1 + int(np.argmax([s.max_N for s in pin_stats])),
        most_loaded_journal=1 + int(np.argmax([s.max_N for s in j_stats])),
        most_twisted_journal=1 + int(np.argmax([s["swing_Nm"] for s in t_stats])),
        F_throw=F_throw, F_rot=F_rot, F_cw=F_cw, Q=Q, shaft=shaft,
        Kr_throw=np.zeros(nt) if pin_Kr is None else np.asarray(pin_Kr, float))
