"""The coupling of the torsional chain with crankdyn's engine: a throw's inertia, one
cylinder's torque harmonics from the force table, the throws and phases of the crank train.

- A throw's mass moment of inertia (domain brief § 7; Колчин & Демидов [1]_, Ker Wilson
  [2]_): the crank's own J (webs, pin, journal) plus, for each cylinder on the throw, the
  rod's rotating part mш.к·R² and the mean over a turn of the reciprocating mass's
  mj·(dx/dα)², which for x = R[(1 − cos α) + (λ/4)(1 − cos 2α)] is
  mj·R²·(1/2 + λ²/8):  J_throw = J_crank + z·(mш.к + mj·(1/2 + λ²/8))·R², z cylinders.
- One cylinder's torque Mкр = T·R over its cycle from :func:`engine.force_table` (the one
  force model of crankdyn) on a uniform grid, split exactly into its gas part (from ΔPг)
  and its inertia part (from Pj): at a given α, T is linear in the piston force P
  (T = P·sin(α+β)/cos β), so M_gas = (M/P)·ΔPг and M_inertia = (M/P)·Pj with the
  table's own ratio M/P = R·sin(α+β)/cos β.
- The throws and the phases of the cylinders from :func:`engine.train.layout` (its
  ``cylinders`` table: the one source of phases, throws and banks).

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей, 4-е
   изд., 2008, гл. "Динамика КШМ" (Table 2, силы и моменты).
.. [2] W. Ker Wilson, *Practical Solution of Torsional Vibration Problems*, vol. 1
   (equivalent inertia of a crank throw with its reciprocating parts).
"""
from __future__ import annotations

import numpy as np

from .chain import check_positive
from .harmonics import torque_harmonics

__all__ = ["throw_inertia", "cylinder_excitation", "cylinder_torque_parts",
           "cylinder_throws"]


def throw_inertia(spec, throw_J_kgm2, cylinders_per_throw=1) -> float:
    """The mass moment of inertia of one throw with its cylinders' moving masses [kg·m²]:

    J = J_crank + z·(mш.к + mj·(1/2 + λ²/8))·R²

    ``throw_J_kgm2`` the crank's own J, z = ``cylinders_per_throw`` (2 on a vee's common
    pin), mш.к the rod's rotating part, mj the reciprocating mass, R the crank radius,
    λ = R/L (the mean of mj·(dx/dα)² over a turn, x to the λ-term of the piston path).
    """
    J0 = float(check_positive(throw_J_kgm2, "torsion.throw_J_kgm2", allow_zero=True)[0])
    z = float(check_positive(cylinders_per_throw, "cylinders_per_throw")[0])
    R, lam = spec.R, spec.lam
    return J0 + z * (spec.m_rod_rot + spec.mj * (0.5 + lam ** 2 / 8.0)) * R ** 2


def cylinder_torque_parts(spec, settings=None, step_deg=0.5):
    """One cylinder's torque over its cycle on the grid ``arange(0, cycle, step_deg)``:
    ``(alpha_deg, M_gas, M_inertia, M_total)`` [deg, N·m], from
    :func:`engine.force_table` at the spec's speed (gas + inertia = total exactly)."""
    from engine.forces import force_table     # not the package: no import circle

    step = float(check_positive(step_deg, "step_deg")[0])
    alpha = np.arange(0.0, spec.cycle_deg, step)
    table = force_table(spec, alpha, settings=settings)
    M, P = table["M_Nm"].to_numpy(), table["P_N"].to_numpy()
    dPg, Pj = table["dPg_N"].to_numpy(), table["Pj_N"].to_numpy()
    # the lever M/P = R·sin(α+β)/cos β: from the table where P ≠ 0, else the formula
    a, b = np.radians(table["alpha_deg"].to_numpy()), np.radians(table["beta_deg"].to_numpy())
    lever = spec.R * np.sin(a + b) / np.cos(b)
    big = np.abs(P) > 1e-9 * np.max(np.abs(P))
    lever = np.where(big, M / np.where(big, P, 1.0), lever)
    gas = lever * dPg
    return alpha, gas, M - gas, M


def cylinder_excitation(spec, settings=None, orders_max=12, step_deg=0.5) -> dict:
    """The harmonics of one cylinder's torque Mкр = T·R at the spec's speed.

    Parameters
    ----------
    spec : engine.EngineSpec
    settings : engine.TableSettings, optional
        Passed to :func:`engine.force_table` (the rows are this function's own grid).
    orders_max : float
        Highest order (a multiple of 0.5 four-stroke, of 1 two-stroke).
    step_deg : float
        The grid step over the cycle. [deg]

    Returns
    -------
    dict
        ``{"gas": Harmonics, "inertia": Harmonics, "total": Harmonics}``; the inertia
        harmonics hold at ``spec.speed_rpm`` and scale with (n / n_ref)², the gas ones are
        those of the indicator diagram at every speed.
    """
    alpha, gas, inertia, total = cylinder_torque_parts(spec, settings, step_deg)
    cyc = spec.cycle_deg
    return {name: torque_harmonics(alpha, m, cyc, orders_max)
            for name, m in (("gas", gas), ("inertia", inertia), ("total", total))}


def cylinder_throws(layout):
    """``(throw_index, phases_deg)``: the 0-based throw of each cylinder and its phase φ_j
    [deg], from an :func:`engine.train.layout` (its ``cylinders`` table)."""
    cyl = layout.cylinders
    return (cyl["throw"].to_numpy().astype(int) - 1,
            cyl["phase_deg"].to_numpy().astype(float))
