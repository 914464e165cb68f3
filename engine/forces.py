"""Forces in the engine crank-slider: the textbook "Table 2".

The dynamic model of the textbook [1]_: the piston group and the small-end share of the
rod make the reciprocating mass mj; the big-end share mш.к rotates with the crank pin; the
rod itself is then massless.  The piston force P = ΔPг + Pj acts on the piston along the
cylinder axis; the RRP dyad of :mod:`linkage.groups` (rod 3, piston 4) carries it to the
crank pin, where the rod force S = R32 = −R23 is resolved in the crank frame into K and T.

Sign conventions (the textbook's):

- forces along the cylinder axis (ΔPг, Pj, P) are + towards the crank axis;
- Sш is + when the rod is compressed (S = P/cos β);
- N, the side force of the piston on the cylinder wall, is + when its moment about the
  crank axis opposes the rotation (N = P·tg β with β + for 0 < α < 180°);
- K is + towards the crank axis, T + in the direction of rotation, Mкр = T·R + in the
  direction of rotation;
- Kr.ш = −mш.к·R·ω² (− : outwards, away from the crank axis);
- Rшш = √(T² + (K + Kr.ш)²) is the load on the crank pin; Ψ = atan2(T, K + Kr.ш) is its
  direction in the crank frame: 0° along the crank towards the crank axis, + towards the
  direction of rotation, in (−180°, 180°].

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей, 2008,
   4-е изд., гл. "Динамика кривошипно-шатунного механизма" (силы, действующие в КШМ:
   N = P tg β, Sш = P/cos β, K = P cos(α + β)/cos β, T = P sin(α + β)/cos β,
   Mкр = T·R, Kr.ш = −mш.к·R·ω², Rшш, Ψ); the same formulas, numbered (1.10)–(1.15),
   and the layout of "Таблица 2" in the Russian course-project manuals built on it.
"""
from __future__ import annotations

import math

import numpy as np

from crankbase.errors import Problem, Text
from crankbase.tolerances import ROUNDOFF_RTOL, SAME_ANGLE_DEG, snap_roundoff
from crankbase.validation import angles_argument, step_argument
from linkage.groups import Wrench, dot, driver_reactions, link_wrench, rrp_reactions

from .indicator import gas_pressure, indicated_mean_pressure, theoretical_mean_pressure
from .kinematics import (PistonKinematics, acceleration_orders, crank_slider,
                         two_term_acceleration)
from .result import EngineResult, EngineSummary, Extreme
from .spec import EngineSpec, EngineSpecError, TableSettings

__all__ = ["COLUMNS", "table_angles", "fine_angles", "gas_force", "acceleration_orders",
           "two_term_acceleration", "inertia_force", "crank_pin_forces",
           "crank_pin_resultant", "load_angle_deg", "indicated_power", "force_table",
           "summarize", "analyze", "SUMMARY_QUANTITIES", "PLOT_STEP_DEG"]

#: Columns of the force table, in order (units in the names).
COLUMNS = ("alpha_deg", "p_gas_MPa", "dPg_N", "Pj_N", "P_N", "beta_deg", "N_N", "S_N",
           "K_N", "T_N", "M_Nm", "Kr_N", "R_N", "psi_deg", "x_mm", "v_m_s", "j_m_s2")

#: Step of the fine grid on which plots and the summary's extremes are taken. [deg]
PLOT_STEP_DEG = 0.5


def _check_spec(spec):
    if not isinstance(spec, EngineSpec):
        raise EngineSpecError(Problem("spec", Text("errors.engine.forces.enginespec_engine_load",
                                                   {"name__": type(spec).__name__})))


def _check_angle(value, key):
    if not (isinstance(value, (int, float)) and not isinstance(value, bool)
            and math.isfinite(value)):
        raise EngineSpecError(Problem(key, Text("errors.engine.forces.finite_number_deg",
                                                {"value": value})))
    return float(value)


def table_angles(spec, settings=None) -> np.ndarray:
    """Crank angles of the table rows: every ``settings.step_deg`` from 0 to the cycle end
    (which is always included), plus the extra angles, sorted, without repeats. [deg]

    Parameters
    ----------
    spec : EngineSpec
        Gives the cycle length (720° four-stroke, 360° two-stroke).
    settings : TableSettings, optional
        Default :class:`TableSettings` () (every 30°).
    """
    _check_spec(spec)
    settings = TableSettings() if settings is None else settings
    cyc = spec.cycle_deg
    step = step_argument(settings.step_deg, "step_deg", cyc, error=EngineSpecError)
    n = int(np.floor(cyc / step * (1 + ROUNDOFF_RTOL)))
    a = step * np.arange(n + 1)
    if cyc - a[-1] > SAME_ANGLE_DEG:
        a = np.append(a, cyc)
    else:
        a[-1] = min(a[-1], cyc)
    if settings.extra_angles_deg:
        a = np.union1d(a, np.asarray(settings.extra_angles_deg, float))
    return a


def fine_angles(spec, settings=None, step_deg=PLOT_STEP_DEG) -> np.ndarray:
    """Angles for plots and the summary: a fine grid (default 0.5°) united with the
    table's own rows, so every table row and every extra angle is on it. [deg]"""
    settings = TableSettings() if settings is None else settings
    fine = TableSettings(step_deg=_check_angle(step_deg, "step_deg"))
    return np.union1d(table_angles(spec, fine), table_angles(spec, settings))


def gas_force(p, p0, area):
    """Gas force on the piston ΔPг = (pг − p0)·Fп, + towards the crank axis.

    Parameters
    ----------
    p : array_like
        Absolute gas pressure pг. [Pa]
    p0 : float
        Crankcase pressure. [Pa]
    area : float
        Piston area Fп. [m²]

    Returns
    -------
    ndarray
        ΔPг. [N]  ([1]_, domain brief § 5.)
    """
    return (np.asarray(p, float) - p0) * area


def inertia_force(mj, j):
    """Inertia force of the reciprocating masses Pj = −mj·j, + towards the crank axis.

    Parameters
    ----------
    mj : float
        Reciprocating mass. [kg]
    j : array_like
        Piston acceleration, + towards the crank axis. [m/s²]

    Returns
    -------
    ndarray
        Pj. [N]
    """
    return -mj * np.asarray(j, float)


def crank_pin_forces(mech: PistonKinematics, P, L, rod=None):
    """Rod force on the crank pin and side force from the RRP dyad's kinetostatics.

    The one routine for both rod models: the textbook two-mass rod (``rod`` None: a
    massless rod and a massless piston carrying P) and the rigid rod
    (:class:`engine.rodmodel.RigidRod`: the rod with its mass, J and centre of mass, the
    piston group with its mass mп, P the gas force alone).

    Parameters
    ----------
    mech : PistonKinematics
        Kinematics (:func:`engine.kinematics.crank_slider`).
    P : array_like
        Force on the piston along the cylinder axis, + towards the crank axis [N]: the
        total ΔPг + Pj of the two-mass model (``rod`` None), the gas force ΔPг with a
        rigid rod (the inertia of the rod and of the piston then come from their masses).
    L : float
        Rod length. [m]
    rod : RigidRod, optional
        Anything with ``mass`` [kg], ``inertia`` J about the centre of mass [kg·m²], ``cg``
        (centre of mass from the crank pin along the rod) [m] and ``m_piston`` [kg].

    Returns
    -------
    dict of ndarray
        ``S32`` the rod's force on the crank pin (complex, global frame) [N]; ``S`` its
        signed magnitude, + compressing the rod [N]; ``K`` + towards the crank axis,
        ``T`` + in the direction of rotation [N]; ``N`` the piston's side force on the
        wall, + when its moment about the crank axis opposes rotation [N]; ``M`` the
        torque of the rod on the crank, + in the direction of rotation (−Mур of the
        driver group) [N·m]; ``reactions`` the :class:`~linkage.groups.RRPReactions`.

    Notes
    -----
    Forces dyad first, then the driver (domain brief § 1): ``rrp_reactions`` with the
    rod's wrench (W3 = 0 for the massless rod; else its d'Alembert inertia by
    ``link_wrench``) and the piston loaded by −P·u (u, the dyad's guide direction: the
    cylinder axis from the crank axis towards TDC; plus the piston's inertia with a
    rigid rod) gives R23 at A and the guide's normal force R14 = R14n·iu.  Then
    S = R32 = −R23; in the crank frame (e₂ from O to A) K = S·(−e₂), T = S·(ie₂);
    Sш = S·(A − B)/|AB|; N = R41·(−iu) = R14n; and ``driver_reactions`` with a massless
    crank gives Mкр = −Mур = (OA × S).
    """
    sol = mech.dyad
    u = sol.link4.e                                # the dyad's own guide: the cylinder axis
    zB = sol.B.z
    zero = np.zeros(zB.shape)
    load = [(-np.asarray(P, float) * u, zB)]
    if rod is None:
        W3 = Wrench(zero + 0j, zero, zB)           # massless rod without loads
        W4 = link_wrench(sol.link4, forces=load)
    else:
        W3 = link_wrench(sol.link3, mass=rod.mass, inertia=rod.inertia, cg=rod.cg)
        W4 = link_wrench(sol.link4, mass=rod.m_piston, forces=load)
    reac = rrp_reactions(sol, L, W3, W4)
    S32 = -reac.RA
    e2 = mech.crank.e
    A = sol.link3.origin.z
    W2 = Wrench(zero + 0j, zero, mech.crank.origin.z)   # massless crank
    drv = driver_reactions(mech.crank, A, S32, W2)
    return dict(S32=S32, S=dot(S32, -sol.link3.e), K=dot(S32, -e2), T=dot(S32, 1j * e2),
                N=reac.RG_n, M=-drv.M_drive, reactions=reac)


def load_angle_deg(across, along):
    """Direction of a load in a frame: atan2(across, along) in degrees, in (−180°, 180°]
    (−180° from rounding → 180°).

    Parameters
    ----------
    across, along : array_like
        The load's components across and along the frame's reference direction (for the
        crank pin: T and K + Kr.ш). [N]

    Returns
    -------
    ndarray
        Ψ. [deg]
    """
    psi = np.degrees(np.arctan2(across, along))
    return np.where(psi <= -180.0 + SAME_ANGLE_DEG, psi + 360.0, psi)


def crank_pin_resultant(T, K, Kr=None):
    """The load on the crank pin and its direction in the crank frame.

    Parameters
    ----------
    T : array_like
        Tangential force, + in the direction of rotation. [N]
    K : array_like
        Radial force, + towards the crank axis. [N]
    Kr : array_like or float, optional
        Kr.ш = −mш.к·R·ω², the rod's rotating mass (none for a rigid rod, whose K and T
        already hold its inertia). [N]

    Returns
    -------
    R, psi : ndarray
        Rшш = √(T² + (K + Kr.ш)²) [N] and Ψ = atan2(T, K + Kr.ш) [deg]: 0° along the
        crank towards the crank axis, + towards the direction of rotation, in
        (−180°, 180°] [1]_.
    """
    Kt = K if Kr is None else K + Kr
    return np.hypot(T, Kt), load_angle_deg(T, Kt)


def indicated_power(p_i, Vh, speed_rpm, strokes, cylinders=1):
    """Indicated power Ni = pi·Vh·i·n/(30·τ) [W] ([1]_).

    Parameters
    ----------
    p_i : float
        Indicated mean pressure. [Pa]
    Vh : float
        Displacement of one cylinder. [m³]
    speed_rpm : float
        n. [rpm]
    strokes : int
        τ, 4 or 2.
    cylinders : int
        i.
    """
    return p_i * Vh * cylinders * speed_rpm / (30.0 * strokes)


def force_table(spec, alpha_deg=None, *, settings=None, bank_deg=0.0, phase_deg=0.0):
    """The engine force table ("Table 2") of one cylinder.

    Parameters
    ----------
    spec : EngineSpec
        From :func:`engine.load_spec`.
    alpha_deg : array_like, optional
        Crankshaft angles θ of the rows [deg]; default :func:`table_angles` of
        ``settings``.  The cylinder's own crank angle is α = θ − ``phase_deg``.
    settings : TableSettings, optional
        Table rows when ``alpha_deg`` is not given (default every 30°).
    bank_deg : float
        Cylinder axis angle from the engine's vertical, + in the direction of
        rotation (:mod:`engine.kinematics`); the table's forces are in the cylinder's
        and the crank's own frames, so they do not depend on it. [deg]
    phase_deg : float
        Lag of the cylinder's working cycle behind θ. [deg]

    Returns
    -------
    pandas.DataFrame
        Columns :data:`COLUMNS`: ``alpha_deg`` the row's angle θ [deg], ``p_gas_MPa``
        absolute gas pressure, ``dPg_N`` ΔPг, ``Pj_N`` Pj, ``P_N`` P, ``beta_deg`` β,
        ``N_N`` N, ``S_N`` Sш, ``K_N`` K, ``T_N`` T, ``M_Nm`` Mкр, ``Kr_N`` Kr.ш, ``R_N``
        Rшш, ``psi_deg`` Ψ, ``x_mm`` piston displacement from TDC, ``v_m_s`` piston
        velocity and ``j_m_s2`` its exact acceleration (both + towards the crank axis).
        Signs: module docstring.

    Raises
    ------
    EngineSpecError
        A non-finite angle or a wrong argument type, naming the argument.

    Notes
    -----
    ``acceleration = "two-term"``: Pj = −mj·Rω²(cos α + λ cos 2α) [1]_ (+ kλ sin α with a
    pin offset).  ``"exact"``: Pj = −mj·j with j the exact piston acceleration of the RRP
    dyad.  In both modes Pj enters the dyad as an external force on a massless piston
    (the same loads as a piston of mass mj in exact mode); the rod is massless, its mass
    being split into mj and mш.к.  Kr.ш = −mш.к·R·ω²; Rшш = √(T² + (K + Kr.ш)²) and
    Ψ = atan2(T, K + Kr.ш) by :func:`crank_pin_resultant`.
    """
    import pandas as pd

    f = _cylinder_forces(spec, alpha_deg, settings, bank_deg, phase_deg)
    mech, P = f["mech"], f["P"]
    Kr = np.full_like(P, spec.Kr)
    zero = np.zeros_like(P)                         # Rшш and Ψ: from the snapped T, K
    cols = (f["theta_deg"], f["p"] / 1e6, f["dPg"], f["Pj"], P, np.degrees(mech.beta),
            f["N"], f["S"], f["K"], f["T"], f["M"], Kr, zero, zero, mech.x * 1e3, mech.v,
            mech.j)
    # one float block (the columns of COLUMNS, in order): cheaper than a dict of arrays;
    # round-off residues of exact zeros (v and β at TDC) become 0 before Rшш and Ψ
    block = np.column_stack(cols)
    snap_roundoff(block, _column_scales(block))
    block[:, _COL["R_N"]], block[:, _COL["psi_deg"]] = crank_pin_resultant(
        block[:, _COL["T_N"]], block[:, _COL["K_N"]], block[:, _COL["Kr_N"]])
    return pd.DataFrame(block, columns=list(COLUMNS))


_COL = {c: i for i, c in enumerate(COLUMNS)}


def _column_scales(block):
    """The scale of each column of a force-table block [its unit]: the largest magnitude
    of all force columns (``*_N``) for a force, of the column itself otherwise."""
    scale = np.max(np.abs(block), axis=0, initial=0.0)
    force = np.array([c.endswith("_N") for c in COLUMNS])
    scale[force] = np.max(scale[force])
    return scale


def _cylinder_forces(spec, alpha_deg, settings, bank_deg, phase_deg):
    """Kinematics, piston forces and crank-pin forces of one cylinder (validated args)."""
    _check_spec(spec)
    bank = math.radians(_check_angle(bank_deg, "bank_deg"))
    phase = _check_angle(phase_deg, "phase_deg")
    theta = table_angles(spec, settings) if alpha_deg is None else angles_argument(alpha_deg, "alpha_deg", error=EngineSpecError)
    a_deg = theta - phase
    mech = crank_slider(np.radians(theta), spec.R, spec.L, spec.omega, bank=bank,
                        offset=spec.pin_offset, phase=math.radians(phase))
    p = gas_pressure(spec, a_deg, mech.x)
    dPg = gas_force(p, spec.p0, spec.area)
    if spec.acceleration == "exact":
        Pj = inertia_force(spec.mj, mech.j)
    else:
        Pj = inertia_force(spec.mj, two_term_acceleration(mech.alpha, spec.R, spec.lam,
                                                          spec.omega, spec.k_offset))
    P = dPg + Pj
    f = crank_pin_forces(mech, P, spec.L)
    f.update(theta_deg=theta, mech=mech, p=p, dPg=dPg, Pj=Pj, P=P)
    return f


#: Columns whose max and min the summary reports (P, Sш, N, K, T, Mкр, Rшш).
SUMMARY_QUANTITIES = ("P_N", "S_N", "N_N", "K_N", "T_N", "M_Nm", "R_N")


def _cycle_mean(alpha, y, cycle_deg):
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(alpha)) / cycle_deg)


def summarize(table, spec) -> EngineSummary:
    """Extremes and cycle means of a force table.

    Parameters
    ----------
    table : pandas.DataFrame
        From :func:`force_table` (rows sorted by angle, covering 0 … cycle end).
    spec : EngineSpec

    Returns
    -------
    EngineSummary
        Max and min with their angles of P, Sш, N, K, T, Mкр, Rшш [N, N·m, deg]; the peak
        gas pressure and its angle; Mкр.ср and Rшш.ср (trapezoid rule over α / cycle);
        χ = Rшш,max/Rшш,ср; the indicated mean pressure pi of the diagram (∮p dV/Vh,
        pumping loop included) and the indicated power of one cylinder
        Ni = pi·Vh·n/(30·τ) [1]_; p′i of the unrounded diagram (computed diagrams only).
    """
    _check_spec(spec)
    missing = [c for c in COLUMNS if c not in getattr(table, "columns", ())]
    if missing:
        raise EngineSpecError(Problem("table", Text("errors.engine.forces.force_table_engine",
                                                    {"items": ', '.join(missing)})))
    a = table["alpha_deg"].to_numpy()
    cyc = spec.cycle_deg
    ext = {}
    for col in SUMMARY_QUANTITIES:
        y = table[col].to_numpy()
        i, k = int(np.argmax(y)), int(np.argmin(y))
        ext[col] = Extreme(float(y[i]), float(a[i]), float(y[k]), float(a[k]))
    p = table["p_gas_MPa"].to_numpy()
    R_mean = _cycle_mean(a, table["R_N"].to_numpy(), cyc)
    pi = indicated_mean_pressure(spec)
    return EngineSummary(
        P_N=ext["P_N"], S_N=ext["S_N"], N_N=ext["N_N"], K_N=ext["K_N"], T_N=ext["T_N"],
        M_Nm=ext["M_Nm"], R_N=ext["R_N"],
        p_max_MPa=float(p.max()), alpha_p_max_deg=float(a[int(np.argmax(p))]),
        M_mean_Nm=_cycle_mean(a, table["M_Nm"].to_numpy(), cyc), R_mean_N=R_mean,
        chi=ext["R_N"].max / R_mean if R_mean > 0 else float("nan"),
        pi_MPa=pi / 1e6,
        power_i_kW=indicated_power(pi, spec.Vh, spec.speed_rpm, spec.strokes) * 1e-3,
        pi_theory_MPa=(theoretical_mean_pressure(spec.cycle) / 1e6
                       if spec.cycle is not None else None))


def analyze(spec, settings=None, *, fine_step_deg=PLOT_STEP_DEG) -> EngineResult:
    """The force table of one cylinder with its fine curves and summary.

    Parameters
    ----------
    spec : EngineSpec
    settings : TableSettings, optional
        The table rows (default every 30°) and the force scale of the report.
    fine_step_deg : float
        Step of the fine grid for the plots and the extremes (the table rows are added
        to it). [deg]

    Returns
    -------
    EngineResult
        ``table`` at the settings' rows, ``curves`` on the fine grid, ``summary`` taken on
        the fine grid (so peaks between rows are caught).
    """
    settings = TableSettings() if settings is None else settings
    if not isinstance(settings, TableSettings):
        raise EngineSpecError(Problem("settings", Text("errors.engine.forces.tablesettings",
                                                       {"name__": type(settings).__name__})))
    table = force_table(spec, settings=settings)
    fine = fine_angles(spec, settings, fine_step_deg)
    # a table at least as fine as the plot grid is its own fine curve
    curves = table if fine.size == len(table) else force_table(spec, fine)
    return EngineResult(spec=spec, settings=settings, table=table, curves=curves,
                        summary=summarize(curves, spec))
