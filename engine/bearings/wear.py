"""Wear diagrams of journals by the classic sector method.

Each load vector of the cycle is assumed to wear the journal uniformly over an arc of
±``half_angle_deg`` (60° in the textbooks) about the point where it presses the journal
against its bearing, in proportion to its magnitude [1]_.  Summed over the cycle this gives
the wear profile around the circumference; where it is least the oil hole goes.

Here every load enters weighted by the crank angle it acts over (trapezoid rule), so the
profile is ∫|F|·[φ within ±h of the contact point] dα over the cycle [N·deg] and does not
depend on how finely the cycle is sampled; divided by the cycle it is a mean load.

Contact point (which side of the journal wears)
-----------------------------------------------
A journal is pressed against its shell on the side towards which the rest of the
crankshaft pushes it: for a main journal, along its load Q (:mod:`engine.bearings`).  A
crank pin is pushed by the rod's big end: the rod's force on the pin Rшш is applied by the
shell from the opposite side, so the pin wears about the direction opposite to Rшш
(Ψ + 180°).  The functions here take the contact direction itself, so the caller states
which one it is.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей, 2008,
   § "Диаграммы износа шеек": each force acts on ±60° of the circumference about its
   point of application, proportional to its magnitude; the oil hole is placed in the
   zone of least wear.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.tolerances import WEAR_ARC_EDGE_DEG, WEAR_TIE_RTOL

from ..schema import DEFAULT_HALF_ANGLE_DEG

__all__ = ["wear_profile", "least_wear_direction", "WearDiagram", "wear_diagram",
           "DEFAULT_HALF_ANGLE_DEG"]


def _weights(alpha_deg):
    """Trapezoid weights of samples over α (the angle each sample stands for). [deg]"""
    a = np.asarray(alpha_deg, float)
    if a.size < 2:
        return np.ones_like(a)
    d = np.diff(a)
    w = np.zeros_like(a)
    w[:-1] += 0.5 * d
    w[1:] += 0.5 * d
    return w


def wear_profile(contact_deg, magnitude, half_angle_deg=DEFAULT_HALF_ANGLE_DEG,
                 weights=None, n_points=360):
    """Wear around a journal's circumference.

    Parameters
    ----------
    contact_deg : array_like, shape (n,)
        Direction of each load's contact point on the journal, in the journal's frame.
        [deg]
    magnitude : array_like, shape (n,)
        Load magnitudes (≥ 0). [N]
    half_angle_deg : float
        Half-angle h of the worn arc, 0 < h ≤ 180. [deg]
    weights : array_like, shape (n,), optional
        Weight of each load (the crank angle it acts over); default 1.
    n_points : int
        Points around the circumference (every 360/n_points degrees from 0).

    Returns
    -------
    phi_deg : ndarray, shape (n_points,)
        Directions around the journal, same frame as ``contact_deg``. [deg]
    wear : ndarray, shape (n_points,)
        Σ wᵢ·|Fᵢ| over the loads whose contact point is within ±h of φ (ends included).
        [N·weight unit]
    """
    if not (np.isfinite(half_angle_deg) and 0 < half_angle_deg <= 180):
        raise SpecError(Problem("wear_half_angle_deg",
                                Text("errors.engine.wear.message",
                                     {"half_angle_deg": half_angle_deg})))
    c = np.mod(np.asarray(contact_deg, float).ravel(), 360.0)
    m = np.asarray(magnitude, float).ravel()
    w = np.ones_like(m) if weights is None else np.asarray(weights, float).ravel()
    v = w * m
    phi = np.arange(n_points) * (360.0 / n_points)
    # every load wears the whole circle (a window of 360° or more would count the point
    # opposite a load twice, from the load's copies one turn either side)
    if half_angle_deg + WEAR_ARC_EDGE_DEG >= 180.0:
        return phi, np.full(n_points, v.sum())
    # window sums by prefix sums over the contact angles, sorted and repeated one turn
    # either side so that a window [φ − h, φ + h] never wraps (O((n + N) log n))
    order = np.argsort(c, kind="stable")
    ce = np.concatenate([c[order] - 360.0, c[order], c[order] + 360.0])
    cum = np.concatenate([[0.0], np.cumsum(np.tile(v[order], 3))])
    lo = np.searchsorted(ce, phi - half_angle_deg - WEAR_ARC_EDGE_DEG, side="left")
    hi = np.searchsorted(ce, phi + half_angle_deg + WEAR_ARC_EDGE_DEG, side="right")
    return phi, cum[hi] - cum[lo]


def least_wear_direction(phi_deg, wear):
    """Direction of least wear (where the oil hole goes): the middle of the longest run
    of points at the minimum (ties within ``WEAR_TIE_RTOL`` of the range), wrapping
    around. [deg]"""
    phi = np.asarray(phi_deg, float)
    y = np.asarray(wear, float)
    tol = WEAR_TIE_RTOL * max(float(np.ptp(y)), float(np.max(np.abs(y))), 1e-300)
    at_min = y <= y.min() + tol
    n = len(y)
    if at_min.all():
        return float(phi[0])
    start = int(np.argmin(at_min))            # a point not at the minimum
    ring = np.concatenate(([False], np.roll(at_min, -start), [False])).astype(int)
    edges = np.diff(ring)
    first, past = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0]
    k = int(np.argmax(past - first))          # the longest run (the first of equals)
    best_mid = start + first[k] + (past[k] - first[k] - 1) / 2.0
    dphi = 360.0 / n
    return float(np.mod(phi[0] + best_mid * dphi, 360.0))


@dataclass
class WearDiagram:
    """A wear diagram of one journal.

    Attributes
    ----------
    name : str
        Which journal ("pin 1", "journal 2", …).
    phi_deg : ndarray
        Directions around the journal in its crank frame (0° along the crank towards the
        crank axis, + in the direction of rotation). [deg]
    wear : ndarray
        Wear profile ∫|F|dα over the cycle within ±h. [N·deg]
    half_angle_deg : float
    oil_hole_deg : float
        Direction of least wear. [deg]
    """

    name: str
    phi_deg: np.ndarray
    wear: np.ndarray
    half_angle_deg: float
    oil_hole_deg: float


def wear_diagram(name, alpha_deg, contact_deg, magnitude,
                 half_angle_deg=DEFAULT_HALF_ANGLE_DEG, n_points=360):
    """Wear diagram of a journal from its loads over one cycle.

    Parameters
    ----------
    name : str
    alpha_deg : array_like
        Crank angles of the loads, sorted over one cycle (weights by the trapezoid rule).
        [deg]
    contact_deg, magnitude : array_like
        Contact direction and magnitude of each load (see the module notes). [deg, N]
    half_angle_deg : float
    n_points : int

    Returns
    -------
    WearDiagram
    """
    phi, w = wear_profile(contact_deg, magnitude, half_angle_deg, _weights(alpha_deg),
                          n_points)
    return WearDiagram(name, phi, w, float(half_angle_deg), least_wear_direction(phi, w))
