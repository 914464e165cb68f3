"""The connecting rod as a rigid body: exact K, T, Mкр and crank-pin load, beside the
textbook two-mass rod.

The textbook rod [1]_ is two point masses, mш.п at the piston pin and mш.к at the crank
pin; it has the rod's mass and centre of mass but the moment of inertia
mш.п·a² + mш.к·b² = m·a·b (a, b: distances of the centre of mass from the piston pin and
from the crank pin), not the rod's own J.  Here the rod is a rigid link of mass m, centre
of mass at b from the crank pin on the line of centres and moment of inertia J about it;
the piston group mп is a slider.  Its inertia loads come from the exact kinematics of the
RRP dyad and the reactions from the dyad's kinetostatics (:mod:`linkage.groups`), so K, T,
Mкр and the pin load are exact for that body.  With J = m·a·b (and exact acceleration) it
reproduces the two-mass table exactly.

Spec table ``[rod]`` (read by :func:`rod_options`; :func:`engine.load` checks its keys,
:func:`engine.bearing_spec.read_bearing_inputs` builds the rod for a loaded spec):

``model``
    ``"two-mass"`` (default, the textbook) or ``"rigid"`` (computed beside it).
``inertia_kg_m2``
    J about the centre of mass (> 0); required for ``"rigid"``.
``mass_kg``
    m; default the rod mass of ``[masses]`` when given as parts (``rod_kg`` or
    ``rod_kg_m2``·Fп); required with ``reciprocating_kg``/``rod_rotating_kg``.
``cg_from_big_end_mm``
    b; default the two-mass position b = L·(m − mш.к)/m (the same centre of mass as the
    two-mass rod, so that only J differs).

The piston group mass mп is ``piston_group_kg`` (or ``piston_group_kg_m2``·Fп) when the
masses are given as parts, else mj − (m − mш.к).

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей, 2008,
   § "Приведение масс частей КШМ" (the two-mass rod and the moment-of-inertia error it
   makes).
.. [2] Artobolevsky, I. I. Теория механизмов и машин, 1988, ch. 13 (kinetostatics of the
   RRP group with the inertia of its links).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .forces import crank_pin_forces, crank_pin_resultant, force_table
from .kinematics import crank_slider
from .spec.inputs import ROD_KEYS, ROD_MODELS, RigidRod, mass_parts, rod_options

__all__ = ["RigidRod", "rod_options", "rigid_rod_forces", "RodModelComparison",
           "compare_rod_models", "mass_parts", "ROD_MODELS", "ROD_KEYS"]



def rigid_rod_forces(alpha_deg, R, L, omega, dPg, rod: RigidRod, offset=0.0):
    """Forces of the crank-slider with a rigid rod, by the RRP dyad's kinetostatics.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angle from TDC. [deg]
    R, L, omega : float
        Crank radius [m], rod length [m], angular velocity [rad/s].
    dPg : array_like
        Gas force ΔPг, + towards the crank axis. [N]
    rod : RigidRod
    offset : float
        Piston-pin offset e (désaxé), as in :func:`engine.kinematics.crank_slider`. [m]

    Returns
    -------
    dict of ndarray
        ``K`` (+ towards the crank axis) and ``T`` (+ in the direction of rotation): the
        crank-frame components of the whole rod's force on the crank pin, inertia of the
        rod included (compare with K + Kr.ш of the two-mass table) [N]; ``R`` = |(K, T)|
        and ``psi`` = atan2(T, K) [N, deg]; ``M`` = T·R, the torque on the crank [N·m];
        ``N`` the side force on the wall [N]; ``S`` the force along the rod at the
        crank pin, + compressing [N].

    Notes
    -----
    Kinematics I(1,2) → RRP(3,4) by :func:`engine.kinematics.crank_slider` (exact); the
    forces by the engine's one crank-pin routine :func:`engine.forces.crank_pin_forces`
    with the rod: the rod with mass m, J and centre of mass at b on A→B, the piston with
    mass mп and the gas force −ΔPг·u at B, the dyad's and the driver's reactions [2]_;
    R and ψ by :func:`engine.forces.crank_pin_resultant`.
    """
    a = np.radians(np.asarray(alpha_deg, float))
    mech = crank_slider(a, R, L, omega, offset=offset)
    f = crank_pin_forces(mech, dPg, L, rod=rod)
    K, T = f["K"], f["T"]
    R_pin, psi = crank_pin_resultant(T, K)
    return dict(K=K, T=T, R=R_pin, psi=psi, M=f["M"], N=f["N"], S=f["S"])


@dataclass
class RodModelComparison:
    """The two rod models side by side.

    ``table``: DataFrame with ``alpha_deg`` and, for the two-mass table (suffix ``2m``,
    its K being K + Kr.ш) and the rigid rod (``rigid``), ``K_*_N``, ``T_*_N``, ``M_*_Nm``,
    ``R_*_N``, and the differences rigid − two-mass ``dK_N``, ``dT_N``, ``dM_Nm``,
    ``dR_N``.  ``extremes``: {column: (max, α at max, min, α at min)} of the differences.
    ``rod``: the :class:`RigidRod`; ``J_two_mass``: m·a·b [kg·m²]; ``acceleration``:
    "exact": both models use the exact piston kinematics, so the differences are those of
    the rod's moment of inertia alone (with a two-term spec the two-mass table is
    recomputed with the exact acceleration for the comparison).
    """

    table: object
    extremes: dict
    rod: RigidRod
    J_two_mass: float
    acceleration: str


def compare_rod_models(spec, rod: RigidRod, alpha_deg=None, table=None):
    """The rigid rod beside the spec's two-mass force table.

    Parameters
    ----------
    spec : EngineSpec
    rod : RigidRod
    alpha_deg : array_like, optional
        Angles [deg]; default those of ``table`` or the table rows.
    table : pandas.DataFrame, optional
        The two-mass force table at those angles, used as is when the spec's acceleration
        is exact (else recomputed with the exact acceleration at its angles).

    Returns
    -------
    RodModelComparison
    """
    import pandas as pd
    from dataclasses import replace

    if table is not None and alpha_deg is None:
        alpha_deg = table["alpha_deg"].to_numpy()
    if table is None or spec.acceleration != "exact":
        exact = spec if spec.acceleration == "exact" else replace(spec, acceleration="exact")
        table = force_table(exact, alpha_deg)
    a = table["alpha_deg"].to_numpy()
    rg = rigid_rod_forces(a, spec.R, spec.L, spec.omega, table["dPg_N"].to_numpy(), rod,
                          spec.pin_offset)
    K2 = (table["K_N"] + table["Kr_N"]).to_numpy()
    T2 = table["T_N"].to_numpy()
    M2 = table["M_Nm"].to_numpy()
    R2 = table["R_N"].to_numpy()
    cols = dict(alpha_deg=a, K_2m_N=K2, K_rigid_N=rg["K"], dK_N=rg["K"] - K2,
                T_2m_N=T2, T_rigid_N=rg["T"], dT_N=rg["T"] - T2,
                M_2m_Nm=M2, M_rigid_Nm=rg["M"], dM_Nm=rg["M"] - M2,
                R_2m_N=R2, R_rigid_N=rg["R"], dR_N=rg["R"] - R2)
    df = pd.DataFrame(cols)
    ext = {}
    for col in ("dK_N", "dT_N", "dM_Nm", "dR_N"):
        y = df[col].to_numpy()
        i, k = int(np.argmax(y)), int(np.argmin(y))
        ext[col] = (float(y[i]), float(a[i]), float(y[k]), float(a[k]))
    return RodModelComparison(df, ext, rod, rod.two_mass_inertia(spec.L), "exact")
