"""The indicator diagram: gas pressure over the crank angle.

Three sources, one per spec: a tabulated diagram (inline or CSV) interpolated linearly and
periodically; or a diagram computed from the thermal-calculation results
(``[pressure.cycle]``), sharp or rounded by the textbook rules.  Pressures are absolute, in
Pa; angles in crank degrees from the TDC that starts intake.

The computed (four-stroke) diagram, with V/Vc = 1 + (ε − 1)·x(α)/S from the exact piston
displacement of the crank-slider (:func:`engine.kinematics.crank_slider`) [1]_:

=============  ==============  =====================================================
α [deg]        process         pressure
=============  ==============  =====================================================
[0, 180)       intake          pa
[180, 360)     compression     pa·(Va/V)^n1,  Va = ε·Vc
[360, 540)     expansion       otto: pz·(Vc/V)^n2;  diesel (mixed cycle): pz while
                               V ≤ ρ·Vc, then pz·(ρ·Vc/V)^n2
[540, 720)     exhaust         pr
=============  ==============  =====================================================

At 360° the sharp diagram jumps from pc = pa·ε^n1 to pz (combustion at TDC; for the
diesel the isochoric part c–z′ and the isobaric part z′–z); at 540° from pb to pr; at 0°
from pr to pa.  All jumps lie at dead centres, where dV = 0.

Rounding (``rounding = true``, the default), after Kolchin & Demidov [1]_
("Скругление индикаторной диаграммы"); every zone is a piecewise cubic Hermite curve in
the (α, p) plane, with slopes limited by Fritsch–Carlson so that it does not overshoot:

- combustion: from c′ on the compression line at 360° − ``advance_deg`` (ignition or
  injection advance; the slope of the compression line kept), through c″ at TDC with
  pc″ = ``pc_factor``·pc (textbook 1.15–1.25), to the real peak zд at 360° +
  ``peak_after_tdc_deg`` (10–15°) with pzд = ``peak_factor``·pz (≈ 0.85) and zero slope,
  then down to the expansion line, met 20° after the peak with its slope;
- exhaust blow-down: from b′ on the expansion line at 540° − ``exhaust_opening_deg``
  (exhaust valve opening before BDC), through b″ at BDC with pb″ = (pb + pa)/2 (the middle
  of the line b–a), to the exhaust line pr at 540° + ``exhaust_opening_deg``/2;
- valve overlap at TDC: from pr at 720° − ``intake_opening_deg`` to pa at
  ``exhaust_closing_deg`` after TDC, smoothly (zero slope at both ends).

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей.
   М.: Высшая школа, 2008: § "Построение индикаторных диаграмм" (the polytropes through
   V(α)), § "Скругление индикаторной диаграммы", and the indicated mean pressure of the
   unrounded diagram, p′i = pc/(ε − 1)·[λ(ρ − 1) + λρ/(n2 − 1)·(1 − 1/δ^(n2−1))
   − 1/(n1 − 1)·(1 − 1/ε^(n1−1))], δ = ε/ρ.
"""
from __future__ import annotations

import numpy as np

from crankbase.validation import angles_argument, step_argument

from .kinematics import crank_slider
from .spec import JOIN_AFTER_PEAK_DEG

__all__ = ["interpolate_periodic", "volume_ratio", "sharp_cycle_pressure",
           "cycle_pressure", "gas_pressure", "indicated_mean_pressure",
           "theoretical_mean_pressure"]


def interpolate_periodic(alpha_deg, angle_deg, p, cycle_deg):
    """Linear, periodic interpolation of a tabulated indicator diagram.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angles where the pressure is wanted (any real values). [deg]
    angle_deg : ndarray
        Tabulated angles, sorted, in [0, cycle). [deg]
    p : ndarray
        Tabulated absolute pressures. [Pa]
    cycle_deg : float
        720 (four-stroke) or 360. [deg]

    Returns
    -------
    ndarray
        Pressure at ``alpha_deg``; the last point connects linearly to the first one of
        the next cycle. [Pa]
    """
    a = np.mod(np.asarray(alpha_deg, float), cycle_deg)
    return np.interp(a, angle_deg, p, period=cycle_deg)


def volume_ratio(alpha_deg, lam, eps):
    """Cylinder volume over the clearance volume, V/Vc = 1 + (ε − 1)·x/S.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angle from TDC. [deg]
    lam : float
        λ = R/Lш. [-]
    eps : float
        Compression ratio ε. [-]

    Returns
    -------
    ndarray
        V/Vc, with the exact piston displacement x(α) of the crank-slider dyad. [-]
    """
    x = crank_slider(np.radians(alpha_deg), 1.0, 1.0 / lam, 1.0).x
    return 1.0 + (eps - 1.0) * x / 2.0


def _compression(vr, cyc):
    return cyc.pa * (cyc.compression_ratio / vr) ** cyc.n1


def _expansion(vr, cyc):
    return cyc.pz * np.minimum(1.0, (cyc.rho / vr)) ** cyc.n2


def sharp_cycle_pressure(alpha_deg, cyc, lam, vr=None):
    """Unrounded (theoretical) indicator diagram of a four-stroke engine.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angle from the TDC that starts intake (taken modulo 720°). [deg]
    cyc : CycleSpec
        Thermal-calculation data (pressures in Pa).
    lam : float
        λ = R/Lш. [-]
    vr : ndarray, optional
        V/Vc at ``alpha_deg`` when already known (from :func:`volume_ratio`). [-]

    Returns
    -------
    ndarray
        Absolute gas pressure. [Pa]  (Processes in the module docstring, [1]_.)
    """
    a = np.mod(np.atleast_1d(np.asarray(alpha_deg, float)), 720.0)
    if vr is None:
        vr = volume_ratio(a, lam, cyc.compression_ratio)
    p = np.where(a < 180.0, cyc.pa, cyc.pr)
    comp = (a >= 180.0) & (a < 360.0)
    p[comp] = _compression(vr[comp], cyc)
    exp_ = (a >= 360.0) & (a < 540.0)
    p[exp_] = _expansion(vr[exp_], cyc)
    return p


def _hermite(x, xk, yk, mk):
    """Piecewise cubic Hermite through (xk, yk) with slopes mk, evaluated at x (inside)."""
    xk, yk, mk = (np.asarray(v, float) for v in (xk, yk, mk))
    i = np.clip(np.searchsorted(xk, x, side="right") - 1, 0, len(xk) - 2)
    h = xk[i + 1] - xk[i]
    t = (x - xk[i]) / h
    t2, t3 = t * t, t * t * t
    return ((2 * t3 - 3 * t2 + 1) * yk[i] + (t3 - 2 * t2 + t) * h * mk[i]
            + (-2 * t3 + 3 * t2) * yk[i + 1] + (t3 - t2) * h * mk[i + 1])


def _limited_slopes(xk, yk, m_ends):
    """Slopes at the knots: given at the ends, Fritsch–Carlson inside, then limited so
    each segment stays monotone (α² + β² ≤ 9)."""
    xk, yk = np.asarray(xk, float), np.asarray(yk, float)
    d = np.diff(yk) / np.diff(xk)
    m = np.zeros(len(xk))
    m[0], m[-1] = m_ends
    for k in range(1, len(xk) - 1):
        if d[k - 1] * d[k] > 0:
            w1 = 2 * (xk[k + 1] - xk[k]) + (xk[k] - xk[k - 1])
            w2 = (xk[k + 1] - xk[k]) + 2 * (xk[k] - xk[k - 1])
            m[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k])
    for k in range(len(d)):
        if d[k] == 0:
            m[k] = m[k + 1] = 0.0
            continue
        a, b = m[k] / d[k], m[k + 1] / d[k]
        if a < 0:
            m[k], a = 0.0, 0.0
        if b < 0:
            m[k + 1], b = 0.0, 0.0
        r = a * a + b * b
        if r > 9:
            tau = 3 / np.sqrt(r)
            m[k], m[k + 1] = tau * a * d[k], tau * b * d[k]
    return m


def cycle_pressure(alpha_deg, cyc, lam, vr=None):
    """Indicator diagram from the thermal calculation, rounded when ``cyc.rounding``.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angle from the TDC that starts intake. [deg]
    cyc : CycleSpec
    lam : float
        λ = R/Lш. [-]
    vr : ndarray, optional
        V/Vc at ``alpha_deg`` when already known (from :func:`volume_ratio`). [-]

    Returns
    -------
    ndarray
        Absolute gas pressure. [Pa]  (Rounding rules in the module docstring, [1]_.)
    """
    a = np.mod(np.atleast_1d(np.asarray(alpha_deg, float)), 720.0)
    p = sharp_cycle_pressure(a, cyc, lam, vr)
    if not cyc.rounding:
        return p
    eps = cyc.compression_ratio
    a0 = 360.0 - cyc.advance_deg                  # c': ignition / injection
    a2 = 360.0 + cyc.peak_after_tdc_deg           # z_d: the real peak
    a3 = a2 + JOIN_AFTER_PEAK_DEG                 # back on the expansion line
    b0 = 540.0 - cyc.exhaust_opening_deg          # b': exhaust valve opens
    b2 = 540.0 + cyc.exhaust_opening_deg / 2.0    # on the exhaust line pr
    h = 1e-4
    # V/Vc at every knot (and ±h for the slopes) in one kinematics pass
    knots = np.array([a0 - h, a0, a0 + h, a3 - h, a3, a3 + h, b0 - h, b0, b0 + h, 540.0])
    vk = volume_ratio(knots, lam, eps)
    pc_k = _compression(vk[:3], cyc)
    pe_k = _expansion(vk[3:], cyc)
    slope_c0 = (pc_k[2] - pc_k[0]) / (2 * h)
    slope_e3 = (pe_k[2] - pe_k[0]) / (2 * h)
    slope_b0 = (pe_k[5] - pe_k[3]) / (2 * h)
    # combustion: c' -> c'' -> z_d -> expansion line
    xk = [a0, 360.0, a2, a3]
    yk = [pc_k[1], cyc.pc_factor * cyc.pc, cyc.peak_factor * cyc.pz, pe_k[1]]
    mk = _limited_slopes(xk, yk, (slope_c0, slope_e3))
    mk[2] = 0.0
    zone = (a >= a0) & (a <= a3)
    p[zone] = _hermite(a[zone], xk, yk, mk)
    # exhaust blow-down: b' -> b'' -> pr
    pb = pe_k[6]
    xk = [b0, 540.0, b2]
    yk = [pe_k[4], 0.5 * (pb + cyc.pa), cyc.pr]
    mk = _limited_slopes(xk, yk, (slope_b0, 0.0))
    zone = (a >= b0) & (a <= b2)
    p[zone] = _hermite(a[zone], xk, yk, mk)
    # valve overlap at TDC: pr -> pa (smoothstep across 720/0)
    r0 = 720.0 - cyc.intake_opening_deg
    width = cyc.intake_opening_deg + cyc.exhaust_closing_deg
    zone = (a >= r0) | (a <= cyc.exhaust_closing_deg)
    t = np.mod(a[zone] - r0, 720.0) / width
    p[zone] = cyc.pr + (cyc.pa - cyc.pr) * t * t * (3.0 - 2.0 * t)
    return p


def gas_pressure(spec, alpha_deg, x=None):
    """Absolute gas pressure of the spec's indicator diagram at the given angles.

    Parameters
    ----------
    spec : EngineSpec
    alpha_deg : array_like
        Crank angle from TDC (the TDC that starts intake for a four-stroke). [deg]
    x : ndarray, optional
        Piston displacement from TDC at ``alpha_deg`` when already known (saves a
        kinematics pass for a computed diagram). [m]

    Returns
    -------
    ndarray
        pг. [Pa]
    """
    alpha_deg = angles_argument(alpha_deg, "alpha_deg")
    if spec.cycle is not None:
        vr = None
        if x is not None:
            vr = 1.0 + (spec.cycle.compression_ratio - 1.0) * np.asarray(x) / spec.stroke
        return cycle_pressure(alpha_deg, spec.cycle, spec.lam, vr)
    return interpolate_periodic(alpha_deg, spec.angle_deg, spec.p, spec.cycle_deg)


def indicated_mean_pressure(spec, step_deg=0.05):
    """Indicated mean pressure of the spec's diagram, pi = ∮p dV / Vh.

    Parameters
    ----------
    spec : EngineSpec
    step_deg : float
        Integration step (trapezoid rule in V over the closed cycle). [deg]

    Returns
    -------
    float
        pi, the net indicated work per cycle over the displacement (pumping loop
        included for a four-stroke cycle). [Pa]

    Notes
    -----
    dV = Fп·dx, so pi = ∮ p d(x/S) needs no clearance volume; x(α) is the exact piston
    displacement of the crank-slider dyad.
    """
    step_deg = step_argument(step_deg, "step_deg", spec.cycle_deg)
    n = int(round(spec.cycle_deg / step_deg))
    alpha = np.linspace(0.0, spec.cycle_deg, n + 1)
    p = gas_pressure(spec, alpha)
    x = crank_slider(np.radians(alpha), spec.R, spec.L, spec.omega).x / spec.stroke
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(x)))


def theoretical_mean_pressure(cyc):
    """Indicated mean pressure of the unrounded diagram without the pumping loop, p′i.

    Parameters
    ----------
    cyc : CycleSpec

    Returns
    -------
    float
        p′i = pc/(ε − 1)·[λ(ρ − 1) + λρ/(n2 − 1)·(1 − 1/δ^(n2−1))
        − 1/(n1 − 1)·(1 − 1/ε^(n1−1))], δ = ε/ρ (ρ = 1 for otto) [1]_. [Pa]
    """
    eps, n1, n2, rho = cyc.compression_ratio, cyc.n1, cyc.n2, cyc.rho
    lam = cyc.lambda_z
    delta = eps / rho
    return cyc.pc / (eps - 1.0) * (lam * (rho - 1.0)
                                   + lam * rho / (n2 - 1.0) * (1.0 - delta ** (1.0 - n2))
                                   - 1.0 / (n1 - 1.0) * (1.0 - eps ** (1.0 - n1)))
