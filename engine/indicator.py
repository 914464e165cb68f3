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

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from crankbase.tolerances import POLYTROPE_SLOPE_STEP_DEG

from .kinematics import crank_slider

__all__ = ["CycleSpec", "PressureTable", "JOIN_AFTER_PEAK_DEG", "interpolate_periodic",
           "volume_ratio", "sharp_cycle_pressure", "cycle_pressure", "gas_pressure",
           "indicated_mean_pressure", "theoretical_mean_pressure"]

#: The rounded combustion curve meets the expansion polytrope this far after the peak [1]_.
#: [deg]
JOIN_AFTER_PEAK_DEG = 20.0


#: Default ignition (otto) and injection (diesel) advance before TDC for the rounding [1]_.
#: [deg]
ADVANCE_DEFAULT_DEG = {"otto": 30.0, "diesel": 20.0}


@dataclass(frozen=True)
class PressureTable:
    """A tabulated indicator diagram (inline in the spec or read from a CSV file).

    Attributes
    ----------
    angle_deg : tuple of float
        Crank angles from the TDC that starts intake, sorted, in [0, cycle). [deg]
    p : tuple of float
        Absolute gas pressure at those angles. [Pa]
    file : Path or None
        The CSV file the table was read from (None: inline in the spec).
    """

    angle_deg: tuple
    p: tuple
    file: Path | None = None


@dataclass(frozen=True)
class CycleSpec:
    """Thermal-calculation data for a computed indicator diagram (``[pressure.cycle]``).

    Inputs only, pressures in Pa and angles in degrees; the pressure at the end of
    compression pc, the peak pz (when λz = pz/pc is given) and λz are computed
    (:attr:`pc`, :attr:`pz`, :attr:`lambda_z`).  Exactly one of ``pz_input`` and
    ``lambda_z_input`` is set.  See the module docstring for the model.
    """

    kind: str                      # "otto" or "diesel"
    compression_ratio: float       # ε [-]
    pa: float                      # pressure at the end of intake [Pa]
    pr: float                      # residual-gas (exhaust) pressure [Pa]
    n1: float                      # compression polytropic index [-]
    n2: float                      # expansion polytropic index [-]
    pz_input: float | None         # maximum pressure of the thermal calculation [Pa]
    lambda_z_input: float | None   # or the pressure-rise ratio λz = pz/pc [-]
    rho: float                     # pre-expansion ratio ρ (1 for otto) [-]
    rounding: bool                 # round the diagram by the textbook rules
    advance_deg: float | None      # ignition (otto) / injection (diesel) advance [deg]
    pc_factor: float               # pc'' = pc_factor · pc at TDC [-]
    peak_factor: float             # real peak pzд = peak_factor · pz [-]
    peak_after_tdc_deg: float      # angle of the real peak after TDC [deg]
    exhaust_opening_deg: float     # exhaust valve opening before BDC [deg]
    intake_opening_deg: float      # intake valve opening before TDC [deg]
    exhaust_closing_deg: float     # exhaust valve closing after TDC [deg]

    @property
    def advance(self) -> float:
        """Ignition or injection advance before TDC: given, else the textbook default
        for the kind (:data:`ADVANCE_DEFAULT_DEG`). [deg]"""
        if self.advance_deg is not None:
            return self.advance_deg
        return ADVANCE_DEFAULT_DEG[self.kind]

    @property
    def pc(self) -> float:
        """Pressure at the end of compression pc = pa·ε^n1 [1]_. [Pa]"""
        return self.pa * self.compression_ratio ** self.n1

    @property
    def pz(self) -> float:
        """Maximum pressure of the thermal calculation: given, or λz·pc. [Pa]"""
        if self.pz_input is not None:
            return self.pz_input
        return self.lambda_z_input * self.pc

    @property
    def lambda_z(self) -> float:
        """Pressure-rise ratio λz = pz/pc. [-]"""
        return self.pz / self.pc


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


def volume_ratio(alpha_deg, lam, eps, k=0.0):
    """Cylinder volume over the clearance volume, V/Vc = 1 + (ε − 1)·x/Sп.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angle from the cylinder axis (TDC of the central mechanism). [deg]
    lam : float
        λ = R/Lш. [-]
    eps : float
        Compression ratio ε. [-]
    k : float
        Relative piston-pin offset e/R (désaxé; sign in :mod:`engine.kinematics`). [-]

    Returns
    -------
    ndarray
        V/Vc, with the exact piston displacement x(α) from the real TDC of the
        crank-slider dyad and the piston's travel Sп between the dead centres (2R for a
        central mechanism), so that V = Vc at TDC and V = ε·Vc at BDC. [-]
    """
    m = crank_slider(np.radians(alpha_deg), 1.0, 1.0 / lam, 1.0, offset=k)
    return 1.0 + (eps - 1.0) * m.x / m.travel


def _compression(vr, cyc):
    return cyc.pa * (cyc.compression_ratio / vr) ** cyc.n1


def _expansion(vr, cyc):
    return cyc.pz * np.minimum(1.0, (cyc.rho / vr)) ** cyc.n2


def sharp_cycle_pressure(alpha_deg, cyc, lam, vr=None, k=0.0):
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
    k : float
        Relative piston-pin offset e/R. [-]

    Returns
    -------
    ndarray
        Absolute gas pressure. [Pa]  (Processes in the module docstring, [1]_.)
    """
    a = np.mod(np.atleast_1d(np.asarray(alpha_deg, float)), 720.0)
    if vr is None:
        vr = volume_ratio(a, lam, cyc.compression_ratio, k)
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


def cycle_pressure(alpha_deg, cyc, lam, vr=None, k=0.0):
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
    k : float
        Relative piston-pin offset e/R. [-]

    Returns
    -------
    ndarray
        Absolute gas pressure. [Pa]  (Rounding rules in the module docstring, [1]_.)
    """
    a = np.mod(np.atleast_1d(np.asarray(alpha_deg, float)), 720.0)
    p = sharp_cycle_pressure(a, cyc, lam, vr, k)
    if not cyc.rounding:
        return p
    eps = cyc.compression_ratio
    a0 = 360.0 - cyc.advance                  # c': ignition / injection
    a2 = 360.0 + cyc.peak_after_tdc_deg           # z_d: the real peak
    a3 = a2 + JOIN_AFTER_PEAK_DEG                 # back on the expansion line
    b0 = 540.0 - cyc.exhaust_opening_deg          # b': exhaust valve opens
    b2 = 540.0 + cyc.exhaust_opening_deg / 2.0    # on the exhaust line pr
    h = POLYTROPE_SLOPE_STEP_DEG
    # V/Vc at every knot (and ±h for the slopes) in one kinematics pass
    knots = np.array([a0 - h, a0, a0 + h, a3 - h, a3, a3 + h, b0 - h, b0, b0 + h, 540.0])
    vk = volume_ratio(knots, lam, eps, k)
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
        Crank angle of the cylinder's working cycle (from the TDC that starts intake for
        a four-stroke). [deg]
    x : ndarray, optional
        Piston displacement from TDC at ``alpha_deg`` when already known (saves a
        kinematics pass for a computed diagram). [m]

    Returns
    -------
    ndarray
        pг. [Pa]
    """
    cyc = spec.cycle
    if cyc is not None:
        vr = None
        if x is not None:
            vr = 1.0 + (cyc.compression_ratio - 1.0) * np.asarray(x) / spec.piston_travel
        return cycle_pressure(alpha_deg, cyc, spec.lam, vr, spec.k_offset)
    table = spec.pressure
    return interpolate_periodic(alpha_deg, np.asarray(table.angle_deg, float),
                                np.asarray(table.p, float), spec.cycle_deg)


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
    dV = Fп·dx and Vh = Fп·Sп, so pi = ∮ p d(x/Sп) needs no clearance volume; x(α) is the
    exact piston displacement of the crank-slider dyad and Sп its travel between the dead
    centres.
    """
    n = int(round(spec.cycle_deg / step_deg))
    alpha = np.linspace(0.0, spec.cycle_deg, n + 1)
    m = crank_slider(np.radians(alpha), spec.R, spec.L, spec.omega, offset=spec.pin_offset)
    p = gas_pressure(spec, alpha, m.x)
    x = m.x / m.travel
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
