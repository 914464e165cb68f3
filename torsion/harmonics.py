"""Harmonic analysis of a cylinder's torque over its cycle.

The torque of one cylinder Mкр(α) = T·R repeats every cycle (720° of the crankshaft for a
four-stroke engine, 360° for a two-stroke), so its Fourier series runs in orders
k = 0, 0.5, 1, 1.5 … of the crankshaft speed (four-stroke) or 0, 1, 2 … (two-stroke):

    M(α) = M0 + Σ_k [a_k cos(kα) + b_k sin(kα)],   M_k = a_k − i·b_k,
    M(α) = Re Σ_k M_k e^{ikα},

α in crankshaft radians (``tools/TORSION_API.md``).  The coefficients are the discrete
Fourier transform (:func:`numpy.fft.rfft`) of M on a uniform grid over one cycle — exact
for a torque sampled on that grid (Parseval: rms² = M0² + Σ|M_k|²/2 + the rms² of the
orders left out, which :class:`~torsion.results.Harmonics` states as the reconstruction
error).

The inertia torque of the two-term piston acceleration has the closed-form harmonics
(domain brief § 7; Колчин & Демидов [1]_, Den Hartog [2]_)

    Mj / (mj R² ω²) ≈ (λ/4) sin α − (1/2) sin 2α − (3λ/4) sin 3α − (λ²/4) sin 4α,

from T = Pj·sin(α+β)/cos β with sin(α+β)/cos β ≈ sin α + (λ/2) sin 2α (terms of λ³ and
higher dropped): :func:`inertia_torque_closed_form`.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей,
   4-е изд., 2008, гл. "Динамика КШМ".
.. [2] J. P. Den Hartog, *Mechanical Vibrations*, 4th ed., § 5.6 (the harmonic
   components of the torque of a reciprocating engine; the inertia torque).
"""
from __future__ import annotations

import numpy as np

from crankbase.errors import Problem, SpecError, Text

from .results import Harmonics

__all__ = ["torque_harmonics", "inertia_torque_closed_form", "base_order", "check_orders_max"]

ORDERS_KEY = "torsion.orders_max"


def base_order(cycle_deg) -> float:
    """The lowest order of a torque that repeats every ``cycle_deg``: 360/cycle (0.5 for a
    four-stroke cycle of 720°, 1 for a two-stroke)."""
    return 360.0 / float(cycle_deg)


def check_orders_max(orders_max, cycle_deg) -> int:
    """The number of base orders up to ``orders_max`` (orders_max / base), or a SpecError
    naming ``torsion.orders_max`` if it is not a positive multiple of the base order."""
    base = base_order(cycle_deg)
    try:
        value = float(orders_max)
    except (TypeError, ValueError):
        value = float("nan")
    j = value / base if np.isfinite(value) else float("nan")
    if not (np.isfinite(j) and j >= 1 and abs(j - round(j)) < 1e-9):
        raise SpecError(Problem(ORDERS_KEY, Text("errors.torsion.orders_max",
                                                 {"base": base, "cycle": float(cycle_deg),
                                                  "value": orders_max})))
    return int(round(j))


def torque_harmonics(alpha_deg, M_Nm, cycle_deg, orders_max) -> Harmonics:
    """The Fourier coefficients of a periodic torque up to ``orders_max``.

    Parameters
    ----------
    alpha_deg : array_like (N,)
        Crankshaft angles of a uniform grid over one cycle with the endpoint excluded
        (``numpy.arange(a0, a0 + cycle, step)``, as :func:`engine.force_table` gives the
        table for it). [deg]
    M_Nm : array_like (N,)
        The torque at those angles. [N·m]
    cycle_deg : float
        The period (720 four-stroke, 360 two-stroke). [deg]
    orders_max : float
        The highest order kept; a multiple of the base order 360/cycle, below N/2 base
        orders (the grid's Nyquist limit).

    Returns
    -------
    Harmonics
        Orders 0, base … orders_max with a, b, amplitude, phase, M_k, the rms of M and the
        rms of what the truncated series leaves out.

    Raises
    ------
    crankbase.errors.SpecError
        A grid that is not uniform over one cycle, a torque of another length, an
        ``orders_max`` that is not a multiple of the base order or beyond the grid.

    Examples
    --------
    >>> a = np.arange(0.0, 720.0, 5.0)
    >>> h = torque_harmonics(a, 10 + 3 * np.sin(np.radians(1.5 * a)), 720, 2)
    >>> float(h.order[3]), round(float(h.b_Nm[3]), 9), round(float(h.a_Nm[0]), 9)
    (1.5, 3.0, 10.0)
    """
    cycle = float(check_positive_scalar(cycle_deg, "cycle_deg"))
    alpha = np.asarray(alpha_deg, float).reshape(-1)
    M = np.asarray(M_Nm, float).reshape(-1)
    N = len(alpha)
    if len(M) != N:
        raise SpecError(Problem("M_Nm", Text("errors.torsion.values_grid",
                                             {"got": len(M), "expected": N})))
    step = cycle / max(N, 1)
    if (N < 4 or not np.all(np.isfinite(alpha))
            or not np.allclose(alpha, alpha[0] + step * np.arange(N), rtol=0,
                               atol=1e-9 * cycle)):
        raise SpecError(Problem("alpha_deg", Text("errors.torsion.grid", {"cycle": cycle})))
    if not np.all(np.isfinite(M)):
        raise SpecError(Problem("M_Nm", Text("errors.torsion.vector",
                                             {"value": "non-finite"})))
    jmax = check_orders_max(orders_max, cycle)
    if jmax >= N / 2:
        raise SpecError(Problem(ORDERS_KEY, Text("errors.torsion.orders_grid",
                                                 {"value": float(orders_max),
                                                  "need": 2 * jmax, "got": N})))
    Xall = np.fft.rfft(M)
    X = Xall[: jmax + 1]
    order = np.arange(jmax + 1) * base_order(cycle)
    c = 2.0 * X / N
    c[0] = X[0] / N
    c = c * np.exp(-1j * np.radians(order * alpha[0]))   # a grid that starts at α0 ≠ 0
    a, b = c.real.copy(), -c.imag
    b[0] = 0.0
    c = a - 1j * b
    rms = float(np.sqrt(np.mean(M ** 2)))
    # the truncated series on the grid: the transform with the orders above jmax removed
    Xall[jmax + 1:] = 0.0
    resid = float(np.sqrt(np.mean((M - np.fft.irfft(Xall, n=N)) ** 2)))
    return Harmonics(order=order, a_Nm=a, b_Nm=b, amplitude_Nm=np.hypot(a, b),
                     phase_deg=np.degrees(np.arctan2(-b, a)) + 0.0, complex_Nm=c,
                     reconstruction_rms_Nm=resid, rms_Nm=rms, cycle_deg=cycle)


def check_positive_scalar(value, key) -> float:
    """``value`` as a positive finite float, or a SpecError naming ``key``."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = float("nan")
    if not (np.isfinite(v) and v > 0):
        raise SpecError(Problem(key, Text("errors.torsion.positive", {"value": value})))
    return v


def inertia_torque_closed_form(alpha_deg, m_j_kg, R_m, omega_rad_s, lam) -> np.ndarray:
    """The inertia torque of the reciprocating mass by its four-term series [N·m]:

    Mj = mj R² ω² [(λ/4) sin α − (1/2) sin 2α − (3λ/4) sin 3α − (λ²/4) sin 4α]

    (two-term acceleration j = Rω²(cos α + λ cos 2α), Pj = −mj·j, T = Pj·sin(α+β)/cos β
    expanded to λ²; + in the direction of rotation, α from TDC).  The exact product
    differs by terms of order λ³ mj R² ω².
    """
    a = np.radians(np.asarray(alpha_deg, float))
    s = m_j_kg * R_m ** 2 * omega_rad_s ** 2
    return s * (lam / 4 * np.sin(a) - 0.5 * np.sin(2 * a) - 0.75 * lam * np.sin(3 * a)
                - lam ** 2 / 4 * np.sin(4 * a))
