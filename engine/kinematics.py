"""Piston, rod and crank kinematics of the central crank-slider, built from the Assur
groups of :mod:`linkage.groups` (the driver ``crank`` and the ``rrp`` dyad).

The engine frame: the crank axis O at the origin, the cylinder axis along +y (the guide
direction u points from O towards TDC), the crank turning counter-clockwise (ω > 0).  The
crank angle α is counted from TDC in the direction of rotation, so the crank's angle in the
linkage frame is φ = 90° + α.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей, 2008,
   § "Кинематика кривошипно-шатунного механизма": x, v, j, β of the central mechanism.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from linkage.groups import LinkMotion, RRPSolution, crank, rrp

__all__ = ["PistonKinematics", "crank_slider", "GUIDE_ANGLE"]

#: Direction of the cylinder axis (guide) in the linkage frame: +y, towards TDC. [rad]
GUIDE_ANGLE = np.pi / 2


@dataclass
class PistonKinematics:
    """Kinematics of the engine crank-slider (piston, rod, crank) over an array of crank angles.

    Attributes
    ----------
    alpha : ndarray
        Crank angle from TDC, in the direction of rotation. [rad]
    crank : LinkMotion
        The crank (driver I(1,2)), origin at the crank axis O.
    dyad : RRPSolution
        The RRP dyad (rod 3 = AB, piston 4) of :func:`linkage.groups.rrp`.
    x : ndarray
        Piston displacement from TDC, + towards the crank axis. [m]
    v : ndarray
        Piston velocity, + towards the crank axis (away from TDC). [m/s]
    j : ndarray
        Piston acceleration, + towards the crank axis; the exact value from the dyad. [m/s²]
    beta : ndarray
        Rod angle from the cylinder axis, + for 0 < α < 180° (textbook β = arcsin(λ sin α)).
        [rad]
    """

    alpha: np.ndarray
    crank: LinkMotion
    dyad: RRPSolution
    x: np.ndarray
    v: np.ndarray
    j: np.ndarray
    beta: np.ndarray


def crank_slider(alpha, R, L, omega) -> PistonKinematics:
    """Kinematics of the central crank-slider by the Assur groups I(1,2) → II(3,4).

    Parameters
    ----------
    alpha : array_like
        Crank angle from TDC in the direction of rotation. [rad]
    R : float
        Crank radius. [m]
    L : float
        Connecting-rod length Lш (> R). [m]
    omega : float
        Crank angular velocity (constant), > 0. [rad/s]

    Returns
    -------
    PistonKinematics

    Notes
    -----
    The crank pin A = ``crank(φ = π/2 + α).point(R)``; the dyad ``rrp(A, L, O, π/2)``
    gives the piston pin B at s = OB along the cylinder axis, with the slider's exact
    velocity and acceleration (2×2 solves, no finite differences).  The textbook
    quantities follow by sign changes only: x = R + L − s, v = −ṡ, j = −s̈, and
    β = −arg(e₃·ū) with e₃ the rod direction A→B [1]_.  Closed forms for the same
    quantities (x = R[(1 − cos α) + (1/λ)(1 − √(1 − λ² sin² α))], β = arcsin(λ sin α))
    are used only in the tests, as the independent check.
    """
    alpha = np.asarray(alpha, dtype=float)
    link2 = crank(GUIDE_ANGLE + alpha, omega, 0.0, R)
    A = link2.point(R)
    sol = rrp(A, L, 0j, GUIDE_ANGLE, 0.0, +1)
    u = np.exp(1j * GUIDE_ANGLE)
    beta = -np.angle(sol.link3.e * np.conj(u))
    return PistonKinematics(alpha, link2, sol, R + L - sol.s, -sol.v, -sol.a, beta)
