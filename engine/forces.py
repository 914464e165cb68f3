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
   § "Силы, действующие в КШМ"; and the course manual page (seed 003 of this project),
   eqs. (1.10)–(1.15) and its Table 2.
"""
from __future__ import annotations

import numpy as np

from crankbase.validation import angles_argument, step_argument
from linkage.groups import Wrench, dot, driver_reactions, link_wrench, rrp_reactions

from .indicator import gas_pressure, indicated_mean_pressure
from .kinematics import GUIDE_ANGLE, PistonKinematics, crank_slider

__all__ = ["COLUMNS", "table_angles", "fine_angles", "gas_force", "two_term_acceleration",
           "inertia_force", "crank_pin_forces", "force_table", "summarize",
           "SUMMARY_QUANTITIES"]

#: Columns of the force table, in order (units in the names).
COLUMNS = ("alpha_deg", "p_gas_MPa", "dPg_N", "Pj_N", "P_N", "beta_deg", "N_N", "S_N",
           "K_N", "T_N", "M_Nm", "Kr_N", "R_N", "psi_deg", "x_mm", "v_m_s", "j_m_s2")


def table_angles(spec, step_deg=None) -> np.ndarray:
    """Crank angles of the table rows: every ``step_deg`` from 0 to the cycle end (which
    is always included), plus the spec's extra angles, sorted, without repeats. [deg]"""
    cyc = spec.cycle_deg
    step = spec.step_deg if step_deg is None else step_argument(step_deg, "step_deg", cyc)
    n = int(np.floor(cyc / step + 1e-9))
    a = step * np.arange(n + 1)
    if cyc - a[-1] > 1e-9 * cyc:
        a = np.append(a, cyc)
    else:
        a[-1] = min(a[-1], cyc)
    if spec.extra_angles_deg:
        a = np.union1d(a, np.asarray(spec.extra_angles_deg, float))
    return a


def fine_angles(spec, step_deg=0.5) -> np.ndarray:
    """Angles for plots and the summary: a fine grid (default 0.5°) united with the
    table's own rows, so every table row and every extra angle is on it. [deg]"""
    return np.union1d(table_angles(spec, step_deg), table_angles(spec))


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


def two_term_acceleration(alpha, R, lam, omega):
    """Textbook two-term piston acceleration j = Rω²(cos α + λ cos 2α), + towards the
    crank axis.

    Parameters
    ----------
    alpha : array_like
        Crank angle from TDC. [rad]
    R : float
        Crank radius. [m]
    lam : float
        λ = R/Lш. [-]
    omega : float
        Crank angular velocity. [rad/s]

    Returns
    -------
    ndarray
        j. [m/s²]  ([1]_: the first two terms of the Fourier series of the exact j.)
    """
    alpha = np.asarray(alpha, float)
    return R * omega ** 2 * (np.cos(alpha) + lam * np.cos(2.0 * alpha))


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


def crank_pin_forces(mech: PistonKinematics, P, L):
    """Rod force on the crank pin and side force from the RRP dyad's kinetostatics.

    Parameters
    ----------
    mech : PistonKinematics
        Kinematics (:func:`engine.kinematics.crank_slider`).
    P : array_like
        Total piston force ΔPг + Pj, + towards the crank axis, applied to a massless
        piston. [N]
    L : float
        Rod length. [m]

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
    Forces dyad first, then the driver (domain brief § 1): ``rrp_reactions`` with a
    massless rod (W3 = 0) and the piston loaded by −P·u (u: from the crank axis
    towards TDC) gives R23 at A and the guide's normal force R14 = R14n·iu.  Then
    S = R32 = −R23; in the crank frame (e₂ from O to A) K = S·(−e₂), T = S·(ie₂);
    Sш = S·(A − B)/|AB|; N = R41·(−iu) = R14n; and ``driver_reactions`` with a massless
    crank gives Mкр = −Mур = (OA × S).
    """
    sol = mech.dyad
    u = np.exp(1j * GUIDE_ANGLE)
    zB = sol.B.z
    zero = np.zeros(zB.shape)
    W3 = Wrench(zero + 0j, zero, zB)               # massless rod without loads
    W4 = link_wrench(sol.link4, forces=[(-np.asarray(P, float) * u, zB)])
    reac = rrp_reactions(sol, L, W3, W4)
    S32 = -reac.RA
    e2 = mech.crank.e
    A = sol.link3.origin.z
    W2 = Wrench(zero + 0j, zero, mech.crank.origin.z)   # massless crank
    drv = driver_reactions(mech.crank, A, S32, W2)
    return dict(S32=S32, S=dot(S32, -sol.link3.e), K=dot(S32, -e2), T=dot(S32, 1j * e2),
                N=reac.RG_n, M=-drv.M_drive, reactions=reac)


def force_table(spec, alpha_deg=None):
    """The engine force table ("Table 2") of one cylinder.

    Parameters
    ----------
    spec : EngineSpec
        From :func:`engine.load_spec`.
    alpha_deg : array_like, optional
        Crank angles of the rows [deg]; default :func:`table_angles` (every
        ``table.step_deg`` over the cycle, plus ``table.extra_angles_deg``).

    Returns
    -------
    pandas.DataFrame
        Columns :data:`COLUMNS`: ``alpha_deg`` [deg], ``p_gas_MPa`` absolute gas pressure,
        ``dPg_N`` ΔPг, ``Pj_N`` Pj, ``P_N`` P, ``beta_deg`` β, ``N_N`` N, ``S_N`` Sш,
        ``K_N`` K, ``T_N`` T, ``M_Nm`` Mкр, ``Kr_N`` Kr.ш, ``R_N`` Rшш, ``psi_deg`` Ψ,
        ``x_mm`` piston displacement from TDC, ``v_m_s`` piston velocity and ``j_m_s2``
        its exact acceleration (both + towards the crank axis).  Signs: module docstring.

    Notes
    -----
    ``acceleration = "two-term"``: Pj = −mj·Rω²(cos α + λ cos 2α) [1]_.  ``"exact"``:
    Pj = −mj·j with j the exact piston acceleration of the RRP dyad.  In both modes Pj
    enters the dyad as an external force on a massless piston (the same loads as a
    piston of mass mj in exact mode); the rod is massless, its mass being split into mj
    and mш.к.  Kr.ш = −mш.к·R·ω²; Rшш = √(T² + (K + Kr.ш)²); Ψ = atan2(T, K + Kr.ш).
    """
    import pandas as pd

    from .spec import EngineSpec, EngineSpecError

    if not isinstance(spec, EngineSpec):
        raise EngineSpecError(f"spec: expected an EngineSpec from engine.load_spec, got "
                              f"{type(spec).__name__}")
    a_deg = table_angles(spec) if alpha_deg is None else angles_argument(alpha_deg,
                                                                         "alpha_deg")
    alpha = np.radians(a_deg)
    mech = crank_slider(alpha, spec.R, spec.L, spec.omega)
    p = gas_pressure(spec, a_deg, mech.x)
    dPg = gas_force(p, spec.p0, spec.area)
    if spec.acceleration == "exact":
        Pj = inertia_force(spec.mj, mech.j)
    else:
        Pj = inertia_force(spec.mj, two_term_acceleration(alpha, spec.R, spec.lam,
                                                          spec.omega))
    P = dPg + Pj
    f = crank_pin_forces(mech, P, spec.L)
    Kr = np.full_like(P, spec.Kr)
    Kt = f["K"] + Kr
    cols = dict(alpha_deg=a_deg, p_gas_MPa=p / 1e6, dPg_N=dPg, Pj_N=Pj, P_N=P,
                beta_deg=np.degrees(mech.beta), N_N=f["N"], S_N=f["S"], K_N=f["K"],
                T_N=f["T"], M_Nm=f["M"], Kr_N=Kr, R_N=np.hypot(f["T"], Kt),
                psi_deg=_psi(f["T"], Kt), x_mm=mech.x * 1e3,
                v_m_s=mech.v, j_m_s2=mech.j)
    return pd.DataFrame(cols, columns=list(COLUMNS))


def _psi(T, Kt):
    """Ψ = atan2(T, K + Kr.ш) in degrees, in (−180°, 180°] (−180° from rounding → 180°)."""
    psi = np.degrees(np.arctan2(T, Kt))
    return np.where(psi <= -180.0 + 1e-9, psi + 360.0, psi)


#: Quantities whose max and min the summary reports: (column, symbol).
SUMMARY_QUANTITIES = (("P_N", "P"), ("S_N", "Sш"), ("N_N", "N"), ("K_N", "K"),
                      ("T_N", "T"), ("M_Nm", "Mкр"), ("R_N", "Rшш"))


def _cycle_mean(alpha, y, cycle_deg):
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(alpha)) / cycle_deg)


def summarize(table, spec):
    """Extremes and cycle means of a force table.

    Parameters
    ----------
    table : pandas.DataFrame
        From :func:`force_table` (rows sorted by angle, covering 0 … cycle end).
    spec : EngineSpec

    Returns
    -------
    dict
        ``extremes``: {column: (max, α at max, min, α at min)} for :data:`SUMMARY_QUANTITIES`
        [N, N·m, deg]; ``p_max_MPa`` and ``alpha_p_max_deg``; ``M_mean_Nm`` and
        ``R_mean_N`` (trapezoid rule over α / cycle); ``chi`` = Rшш,max/Rшш,mean;
        ``pi_MPa`` the indicated mean pressure of the diagram (∮p dV/Vh, pumping loop
        included); ``power_i_kW`` = pi·Vh·n/(30·τ) of one cylinder (τ = strokes);
        ``pi_theory_MPa`` p′i of the unrounded diagram (computed diagrams only).
    """
    a = table["alpha_deg"].to_numpy()
    cyc = spec.cycle_deg
    out = {"extremes": {}}
    for col, _ in SUMMARY_QUANTITIES:
        y = table[col].to_numpy()
        i, k = int(np.argmax(y)), int(np.argmin(y))
        out["extremes"][col] = (float(y[i]), float(a[i]), float(y[k]), float(a[k]))
    p = table["p_gas_MPa"].to_numpy()
    out["p_max_MPa"] = float(p.max())
    out["alpha_p_max_deg"] = float(a[int(np.argmax(p))])
    out["M_mean_Nm"] = _cycle_mean(a, table["M_Nm"].to_numpy(), cyc)
    out["R_mean_N"] = _cycle_mean(a, table["R_N"].to_numpy(), cyc)
    rmax = out["extremes"]["R_N"][0]
    out["chi"] = rmax / out["R_mean_N"] if out["R_mean_N"] > 0 else float("nan")
    pi = indicated_mean_pressure(spec)
    out["pi_MPa"] = pi / 1e6
    out["power_i_kW"] = pi * spec.Vh * spec.speed_rpm / (30.0 * spec.strokes) * 1e-3
    if spec.cycle is not None:
        from .indicator import theoretical_mean_pressure
        out["pi_theory_MPa"] = theoretical_mean_pressure(spec.cycle) / 1e6
    return out
