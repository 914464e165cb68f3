"""Piston, rod and crank kinematics of one cylinder's crank-slider, built from the Assur
groups of :mod:`linkage.groups` (the driver ``crank`` and the ``rrp`` dyad).

The engine frame: the crankshaft axis O at the origin, +y the engine's vertical (the axis
of a cylinder with bank angle 0, pointing from O towards its TDC), the crank turning
counter-clockwise (ω > 0) as seen in this frame.  One cylinder is placed by three
parameters:

- ``bank`` γ: the angle of its axis from +y, + in the direction of rotation; its guide
  direction is u = exp(i(90° + γ)) (from O towards TDC);
- ``offset`` e (désaxé): the distance of the piston-pin axis (the line the piston pin B
  moves on) from O, + towards the side to which the crank pin moves just after TDC (the
  direction of rotation at TDC, i.e. i·u).  With this sign the rod angle is
  sin β = λ(sin α − k), k = e/R, and a positive offset lowers the side force during the
  expansion stroke (the usual design);
- ``phase`` φ: the angle by which the cylinder's working cycle lags the crankshaft angle
  θ: its crank angle is α = θ − φ.

α is counted from the cylinder axis direction u in the direction of rotation (so the
crank throw points along u at α = 0; with an offset the real TDC lies at α = asin(k·λ/(1 + λ)),
slightly after).  In the linkage frame the crank's angle is 90° + γ + α.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей. 4-е изд.
   М.: Высшая школа, 2008, гл. "Кинематика кривошипно-шатунного механизма": x, v, j, β of
   the central and the offset (дезаксиальный) mechanism.
.. [2] Artobolevsky, I. I. Теория механизмов и машин. Moscow: Nauka, 1988, ch. 4: the
   kinematics of the RRP (class II, second kind) group.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from linkage.groups import LinkMotion, RRPSolution, crank, rrp

__all__ = ["PistonKinematics", "crank_slider", "cylinder_axis_angle", "guide_direction",
           "piston_travel", "acceleration_orders", "two_term_acceleration"]


def cylinder_axis_angle(bank, deg=False):
    """Direction angle of a cylinder axis (from the crankshaft axis towards TDC) in the
    engine's linkage frame, counter-clockwise from +x: 90° + γ.

    The one place of the rule "bank γ from the vertical, + in the direction of rotation";
    a crank throw at angle δ from the vertical points the same way (δ in place of γ).

    Parameters
    ----------
    bank : float or array_like
        γ (or δ), + in the direction of rotation. [rad], or [deg] with ``deg=True``
    deg : bool
        Angles in degrees (in and out).

    Returns
    -------
    float or ndarray
        π/2 + γ [rad] (90° + γ [deg]).
    """
    return (90.0 if deg else np.pi / 2) + bank


def guide_direction(bank=0.0, deg=False):
    """Unit vector u of a cylinder axis (from the crankshaft axis towards TDC) in the
    linkage frame, as a complex number.

    Parameters
    ----------
    bank : float or array_like
        Cylinder axis angle from the engine's vertical +y, + in the direction of
        rotation. [rad], or [deg] with ``deg=True``
    deg : bool
        ``bank`` in degrees.

    Returns
    -------
    complex or complex ndarray
        u = exp(i(π/2 + γ)) (:func:`cylinder_axis_angle`). [-]
    """
    if deg:
        u = np.exp(1j * np.radians(cylinder_axis_angle(bank, deg=True)))
    else:
        u = np.exp(1j * cylinder_axis_angle(bank))
    return complex(u) if np.ndim(u) == 0 else u


def piston_travel(R, L, offset=0.0):
    """Distance between the piston pin's dead-centre positions (the piston's travel).

    Parameters
    ----------
    R, L : float
        Crank radius and rod length. [m]
    offset : float
        Piston-pin offset e. [m]

    Returns
    -------
    float
        Sп = √((L + R)² − e²) − √((L − R)² − e²); exactly 2R when e = 0 [1]_. [m]
    """
    if offset == 0:
        return 2.0 * R
    return float(np.sqrt((L + R) ** 2 - offset ** 2) - np.sqrt((L - R) ** 2 - offset ** 2))


def acceleration_orders(alpha, lam, k=0.0, amplitude=1.0):
    """The first- and second-order terms of the textbook piston acceleration.

    Parameters
    ----------
    alpha : array_like
        Crank angle from TDC. [rad]
    lam : float
        λ = R/Lш. [-]
    k : float
        Relative piston-pin offset e/R (sign in :mod:`engine.kinematics`); 0 for the
        central mechanism. [-]
    amplitude : float
        Factor of both terms (Rω² for the acceleration, mj·Rω² for the inertia forces).

    Returns
    -------
    first, second : ndarray
        amplitude·(cos α + kλ sin α) and amplitude·λ·cos 2α: j = Rω²(first + second)
        with amplitude 1 (Kolchin & Demidov [1]_; the offset term from √(L² − (R sin α − e)²) ≈
        L − (R sin α − e)²/(2L)).
    """
    alpha = np.asarray(alpha, float)
    first = np.cos(alpha)
    if k:
        first = first + k * lam * np.sin(alpha)
    return amplitude * first, amplitude * lam * np.cos(2.0 * alpha)


def two_term_acceleration(alpha, R, lam, omega, k=0.0):
    """Textbook two-term piston acceleration j = Rω²(cos α + λ cos 2α + kλ sin α), + towards
    the crank axis.

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
    k : float
        Relative piston-pin offset e/R (sign in :mod:`engine.kinematics`); 0 for the
        central mechanism. [-]

    Returns
    -------
    ndarray
        j. [m/s²]  ([1]_: the terms of the exact j up to the first order in λ, the sum of
        :func:`acceleration_orders`.)
    """
    first, second = acceleration_orders(alpha, lam, k)
    return R * omega ** 2 * (first + second)


@dataclass
class PistonKinematics:
    """Kinematics of one cylinder's crank-slider over an array of crank angles.

    Attributes
    ----------
    alpha : ndarray
        The cylinder's crank angle α = θ − phase, from its axis in the direction of
        rotation. [rad]
    crank : LinkMotion
        The crank (driver I(1,2)), origin at the crankshaft axis O.
    dyad : RRPSolution
        The RRP dyad (rod 3 = AB, piston 4) of :func:`linkage.groups.rrp`; its guide
        direction ``dyad.link4.e`` is the cylinder axis u.
    x : ndarray
        Piston displacement from TDC, + towards the crank axis. [m]
    v : ndarray
        Piston velocity, + towards the crank axis (away from TDC). [m/s]
    j : ndarray
        Piston acceleration, + towards the crank axis; the exact value from the dyad. [m/s²]
    beta : ndarray
        Rod angle from the cylinder axis, + for 0 < α < 180° of a central mechanism
        (textbook β = arcsin(λ sin α); with an offset arcsin(λ(sin α − k))). [rad]
    travel : float
        The piston's travel between the dead centres Sп (2R for a central mechanism). [m]
    """

    alpha: np.ndarray
    crank: LinkMotion
    dyad: RRPSolution
    x: np.ndarray
    v: np.ndarray
    j: np.ndarray
    beta: np.ndarray
    travel: float


def crank_slider(alpha, R, L, omega, *, bank=0.0, offset=0.0, phase=0.0) -> PistonKinematics:
    """Kinematics of one cylinder's crank-slider by the Assur groups I(1,2) → II(3,4).

    Parameters
    ----------
    alpha : array_like
        Crankshaft angle θ (the cylinder's α when ``phase`` = 0). [rad]
    R : float
        Crank radius. [m]
    L : float
        Connecting-rod length Lш (> R + |offset|). [m]
    omega : float
        Crank angular velocity (constant), > 0. [rad/s]
    bank : float
        Cylinder axis angle from the engine's vertical, + in the direction of
        rotation. [rad]
    offset : float
        Piston-pin offset e (désaxé), + towards the direction of rotation at TDC. [m]
    phase : float
        Lag of the cylinder's working cycle behind θ: α = θ − phase. [rad]

    Returns
    -------
    PistonKinematics

    Notes
    -----
    The crank pin A = ``crank(φ = π/2 + γ + α).point(R)``; the dyad
    ``rrp(A, L, O, π/2 + γ, e)`` gives the piston pin B at s = OB along the cylinder
    axis, with the slider's exact velocity and acceleration (2×2 solves, no finite
    differences).  The textbook quantities follow by sign changes only:
    x = s_TDC − s with s_TDC = √((L + R)² − e²), v = −ṡ, j = −s̈, and
    β = −arg(e₃·ū) with e₃ the rod direction A→B [1]_.  Closed forms for the same
    quantities are used only in the tests, as the independent check.
    """
    alpha = np.asarray(alpha, dtype=float) - phase
    guide = cylinder_axis_angle(bank)
    link2 = crank(guide + alpha, omega, 0.0, R)
    A = link2.point(R)
    sol = rrp(A, L, 0j, guide, offset, +1)
    u = sol.link4.e
    beta = -np.angle(sol.link3.e * np.conj(u))
    s_tdc = R + L if offset == 0 else np.sqrt((L + R) ** 2 - offset ** 2)
    return PistonKinematics(alpha, link2, sol, s_tdc - sol.s, -sol.v, -sol.a, beta,
                            piston_travel(R, L, offset))
