"""Critical speeds and the steady forced response of the chain to the cylinders' torques.

Excitation (``tools/TORSION_API.md``): cylinder j, whose cycle lags cylinder 1's by φ_j
(α_j = θ − φ_j), puts on its throw's mass the torque Re Σ_k M_k e^{−ikφ_j} e^{ikθ}, M_k the
complex amplitude of order k of one cylinder's torque (:mod:`torsion.harmonics`).

Critical speeds (domain brief § 7; Den Hartog [1]_ § 5.7, Ker Wilson [2]_): mode m
(natural frequency f_m) is in resonance with order k at n = 60 f_m / k rpm.  How strongly
the order excites the mode is the work its torques do over the mode's shape, measured by
the vector sum |Σ_j β_j e^{−ikφ_j}| of the mode's relative amplitudes β_j at the throws
(shape normalised to mass 1 = 1).  An order is *major* when every cylinder's phasor
e^{−ikφ_j} is the same (they add in phase whatever the mode): for an even-firing
four-stroke i-cylinder engine the multiples of i/2; computed from the phases, so that an
odd-firing engine is right too.

Forced response (the same sources): at crankshaft speed ω each order k is a harmonic
torque of frequency Ω = kω; the steady complex response of the damped chain is
(K − Ω² J + iΩ C) Θ_k = F_k (:func:`harmonic_solve`), solved at once for every speed and
order (batched :func:`numpy.linalg.solve`).  The angle of every mass over one cycle is
the sum of the orders in time, θ(θ_c) = Re Σ_k Θ_k e^{ikθ_c}, and its peak over the cycle
is reported (not the sum of the amplitudes, which overstates it) without the rigid-body
swing of the whole free chain (:func:`elastic_part`: the vibration amplitude is the
twisting motion, relative to the rotation of the chain's mean inertia); likewise the vibration
torque of section i, k_i(θ_i − θ_{i+1}), and its shear stress τ = 16 M/(π d³).  The gas
torque's harmonics are kept from the indicator diagram at every speed; the inertia
torque's scale with (n / n_ref)² (its force is mj·j ∝ ω²).

References
----------
.. [1] J. P. Den Hartog, *Mechanical Vibrations*, 4th ed., ch. 5.
.. [2] W. Ker Wilson, *Practical Solution of Torsional Vibration Problems*, vol. 2
   (phase vector sums; major and minor orders).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from crankbase.errors import Problem, SpecError, Text

from .chain import check_chain, check_positive, stiffness_matrix
from .harmonics import base_order
from .results import Modes, Response

if TYPE_CHECKING:                       # annotations only: no pandas import at run time
    import pandas as pd

__all__ = ["critical_speeds", "forced_response", "harmonic_solve", "excitation_vectors",
           "elastic_part", "is_major", "check_speed_range", "SPEED_RANGE_KEY"]

SPEED_RANGE_KEY = "torsion.speed_range_rpm"
#: |Σ_j e^{−ikφ_j}| within this fraction of the cylinder count: all phasors equal (major).
MAJOR_RTOL = 1e-9


def check_speed_range(speed_range_rpm):
    """``(low, high)`` with 0 < low < high finite, or a SpecError naming
    ``torsion.speed_range_rpm``."""
    try:
        lo, hi = (float(x) for x in speed_range_rpm)
    except (TypeError, ValueError):
        lo = hi = float("nan")
    if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo < hi):
        raise SpecError(Problem(SPEED_RANGE_KEY, Text("errors.torsion.speed_range",
                                                      {"value": repr(speed_range_rpm)})))
    return lo, hi


def _throws(throw_index, phases_deg, n):
    """The throws' mass indices (whole numbers in 0 … n − 1) and the phases, checked."""
    raw = np.asarray(throw_index).reshape(-1)
    try:
        val = raw.astype(float)
    except (TypeError, ValueError):
        val = np.full(raw.shape, np.nan)
    ok = np.isfinite(val) & (val == np.round(val)) & (val >= 0) & (val <= n - 1)
    if not ok.all():
        raise SpecError(Problem("throw_index", Text("errors.torsion.mass_index",
                                                    {"value": raw[~ok][0], "last": n - 1})))
    ph = np.asarray(phases_deg, float).reshape(-1)
    if len(ph) != len(raw) or not np.all(np.isfinite(ph)):
        raise SpecError(Problem("phases_deg", Text("errors.torsion.phases",
                                                   {"got": len(ph), "expected": len(raw)})))
    return val.astype(int), ph


def is_major(orders, phases_deg) -> np.ndarray:
    """Whether each order is major: every cylinder's phasor e^{−ikφ_j} the same."""
    k = np.asarray(orders, float).reshape(-1)
    ph = np.radians(np.asarray(phases_deg, float))
    z = np.exp(-1j * np.multiply.outer(k, ph))             # (K, cylinders)
    return np.abs(z.sum(axis=1)) >= len(ph) * (1 - MAJOR_RTOL)


def critical_speeds(modes: Modes, throw_index, phases_deg, orders, speed_range_rpm,
                    cylinders, cycle_deg) -> pd.DataFrame:
    """The critical speeds of every mode by every order inside the speed range.

    Parameters
    ----------
    modes : Modes
        :func:`torsion.chain.natural_modes`.
    throw_index : array_like of int (cylinders,)
        0-based index of the mass that carries each cylinder's throw.
    phases_deg : array_like (cylinders,)
        Each cylinder's phase φ_j (lag behind cylinder 1). [deg]
    orders : array_like
        The orders to consider (multiples of the base order 360/cycle; 0 is skipped).
    speed_range_rpm : (float, float)
    cylinders : int
        The number of cylinders (= len(throw_index)).
    cycle_deg : float
        720 four-stroke, 360 two-stroke.

    Returns
    -------
    pandas.DataFrame
        Columns ``mode`` (1-based), ``order``, ``f_Hz``, ``speed_rpm`` (60 f / k),
        ``major``, ``sum_relative_amplitude`` |Σ_j β_j e^{−ikφ_j}|; sorted by mode, then
        order.
    """
    import pandas as pd

    lo, hi = check_speed_range(speed_range_rpm)
    n = modes.shapes.shape[1]
    idx, ph = _throws(throw_index, phases_deg, n)
    if len(idx) != int(cylinders):
        raise SpecError(Problem("phases_deg", Text("errors.torsion.phases",
                                                   {"got": len(idx),
                                                    "expected": int(cylinders)})))
    k = np.asarray(orders, float).reshape(-1)
    k = k[k > 0]
    base = base_order(cycle_deg)
    if not np.allclose(k / base, np.round(k / base), rtol=0, atol=1e-9):
        raise SpecError(Problem("torsion.orders_max", Text(
            "errors.torsion.orders_max", {"base": base, "cycle": float(cycle_deg),
                                          "value": float(k[np.argmax(np.abs(
                                              k / base - np.round(k / base)))])})))
    z = np.exp(-1j * np.multiply.outer(k, np.radians(ph)))          # (K, c)
    beta = modes.shapes[:, idx]                                      # (m, c)
    vsum = np.abs(beta @ z.T)                                        # (m, K)
    speed = 60.0 * modes.f_Hz[:, None] / k[None, :]                  # (m, K)
    major = np.broadcast_to(is_major(k, ph)[None, :], speed.shape)
    mode = np.broadcast_to(np.arange(1, modes.count + 1)[:, None], speed.shape)
    order = np.broadcast_to(k[None, :], speed.shape)
    f = np.broadcast_to(modes.f_Hz[:, None], speed.shape)
    inside = (speed >= lo) & (speed <= hi)
    return pd.DataFrame({"mode": mode[inside], "order": order[inside], "f_Hz": f[inside],
                         "speed_rpm": speed[inside], "major": major[inside],
                         "sum_relative_amplitude": vsum[inside]})


def harmonic_solve(K, J_kgm2, C, F, Omega) -> np.ndarray:
    """The steady complex response Θ of (K − Ω² J + iΩ C) Θ = F, batched.

    Parameters
    ----------
    K, C : ndarray (n, n)
        Stiffness and damping matrices (K may be grounded or free–free).
    J_kgm2 : array_like (n,)
    F : ndarray (..., n)
        Complex torque amplitudes. [N·m]
    Omega : ndarray (...)
        Angular frequency of each F (broadcast with F's leading axes). [rad/s]

    Returns
    -------
    ndarray (..., n)
        Complex angle amplitudes. [rad]
    """
    W = np.asarray(Omega, float)
    F = np.asarray(F, complex)
    n = F.shape[-1]
    lead = np.broadcast_shapes(W.shape, F.shape[:-1])
    W = np.broadcast_to(W, lead)[..., None, None]
    A = np.empty(lead + (n, n), complex)
    A.real = K
    A.real[..., np.arange(n), np.arange(n)] -= W[..., 0] ** 2 * np.asarray(J_kgm2, float)
    np.multiply(W, C, out=A.imag)
    return np.linalg.solve(A, np.broadcast_to(F, lead + (n,))[..., None])[..., 0]


def excitation_vectors(n, throw_index, phases_deg, complex_Nm, orders) -> np.ndarray:
    """(K, n) complex torque on each mass per order: Σ over the cylinders on a mass of
    M_k e^{−ikφ_j}."""
    idx, ph = _throws(throw_index, phases_deg, n)
    z = np.asarray(complex_Nm)[:, None] * np.exp(
        -1j * np.multiply.outer(np.asarray(orders, float), np.radians(ph)))   # (K, c)
    F = np.zeros((z.shape[0], n), complex)
    np.add.at(F.T, idx, z.T)
    return F


def elastic_part(theta, J_kgm2) -> np.ndarray:
    """The elastic (twisting) part of complex angle amplitudes: Θ − Σ J Θ / Σ J.

    The rigid-body part Σ J Θ / Σ J is the rotation of the chain's mean inertia (the
    angle of a free rigid body of inertia Σ J under the same torques); what is left twists
    the shaft, and Σ J Θ_elastic = 0 exactly.

    Parameters
    ----------
    theta : ndarray (..., n)
        Complex angle amplitudes of the n masses (any leading axes: speeds, orders). [rad]
    J_kgm2 : array_like (n,)

    Returns
    -------
    ndarray (..., n)
        The same minus the inertia-weighted mean over the last axis. [rad]
    """
    J = np.asarray(J_kgm2, float)
    theta = np.asarray(theta)
    return theta - (theta @ J / J.sum())[..., None]


def _in_time(amp, jj, nt):
    """x(θ) = Re Σ_k amp_k e^{i j_k 2πθ/cycle} on a grid of nt points over one cycle
    (amp (S, K, m), jj the integer harmonic index of each order): (S, m, nt)."""
    S, _, m = amp.shape
    X = np.zeros((S, m, nt // 2 + 1), complex)
    X[:, :, jj] = np.swapaxes(amp, 1, 2) * (nt / 2.0)
    return np.fft.irfft(X, n=nt, axis=-1)


def _peak_abs(x):
    """max |x| along the last axis, from the max and the min (no |x| array)."""
    return np.maximum(x.max(axis=-1), -x.min(axis=-1))


def forced_response(J_kgm2, k_Nm_rad, C, throw_index, phases_deg, harmonics_gas,
                    harmonics_inertia, speed_ref_rpm, speeds_rpm,
                    diameters_m=None) -> Response:
    """The steady forced torsional vibration of the chain over a range of speeds.

    Parameters
    ----------
    J_kgm2, k_Nm_rad : array_like
        The chain (:func:`torsion.chain.natural_modes`).
    C : ndarray (n, n)
        Damping matrix (:func:`torsion.chain.damping_matrix`).
    throw_index : array_like of int (cylinders,)
        0-based mass index of each cylinder's throw.
    phases_deg : array_like (cylinders,)
        Each cylinder's phase φ_j. [deg]
    harmonics_gas, harmonics_inertia : Harmonics
        One cylinder's gas and inertia torque (same orders); the gas part is applied as
        it is at every speed, the inertia part scaled by (n / speed_ref_rpm)².
    speed_ref_rpm : float
        The speed at which ``harmonics_inertia`` was computed. [rpm]
    speeds_rpm : array_like (S,)
        Crankshaft speeds. [rpm]
    diameters_m : array_like (n − 1,), optional
        Shaft diameter of each section, for the shear stress. [m]

    Returns
    -------
    Response
        Peak elastic vibration angles of the masses [deg] (and the absolute ones, swing
        of the whole chain included), peak vibration torques [N·m] (and stresses
        [MPa]) of the sections at each speed, each order's amplitude, the worst section.

    Notes
    -----
    Order 0 (the mean torque) accelerates the free chain as a whole and twists it
    steadily; it is no vibration and is left out.  The chain is free–free, so each
    order's response Θ_k holds, beside the twisting, a rigid-body part: the swing of the
    whole chain with its mean rotation Σ J Θ_k / Σ J (the speed fluctuation the flywheel
    limits: large at low speed, falling as 1/Ω²), which hides the resonances.  The
    vibration amplitude (``amplitude_deg``, ``amplitude_by_order_deg``) is the elastic
    motion without it, Θ_k − Σ J Θ_k / Σ J (:func:`elastic_part`), as the course and the
    engine texts give it (Den Hartog [1]_ § 5.7: the amplitude curve peaks at the critical
    speeds); the absolute angle, swing included, is ``swing_deg``.  The section torques,
    from the twists, are the same either way.  The peaks are taken on a grid of at
    least 16 points per period of the highest order (error below 2 % of that order's
    share in the worst case).
    """
    J, k = check_chain(J_kgm2, k_Nm_rad)
    n = len(J)
    C = np.asarray(C, float)
    if C.shape != (n, n) or not np.all(np.isfinite(C)):
        raise SpecError(Problem("C", Text("errors.torsion.count",
                                          {"got": "x".join(map(str, C.shape)),
                                           "expected": f"{n}x{n}"})))
    idx, ph = _throws(throw_index, phases_deg, n)
    hg, hi = harmonics_gas, harmonics_inertia
    if hg.order.shape != hi.order.shape or not np.allclose(hg.order, hi.order):
        raise SpecError(Problem("harmonics_inertia", Text("errors.torsion.same_orders")))
    n_ref = float(check_positive(speed_ref_rpm, "speed_ref_rpm")[0])
    speeds = check_positive(speeds_rpm, "speeds_rpm")
    d = None if diameters_m is None else check_positive(diameters_m, "diameters_m")
    if d is not None and len(d) != n - 1:
        raise SpecError(Problem("diameters_m", Text("errors.torsion.count",
                                                    {"got": len(d), "expected": n - 1})))
    keep = hg.order > 0
    orders = hg.order[keep]
    Fg = excitation_vectors(n, idx, ph, hg.complex_Nm[keep], orders)       # (K, n)
    Fi = excitation_vectors(n, idx, ph, hi.complex_Nm[keep], orders)
    scale = (speeds / n_ref) ** 2                                          # (S,)
    F = Fg[None] + scale[:, None, None] * Fi[None]                         # (S, K, n)
    omega = speeds * (2 * np.pi / 60.0)
    Omega = omega[:, None] * orders[None, :]                               # (S, K)
    theta = harmonic_solve(stiffness_matrix(k), J, C, F, Omega)            # (S, K, n)
    elastic = elastic_part(theta, J)                                       # (S, K, n)
    base = base_order(hg.cycle_deg)
    jj = np.rint(orders / base).astype(int)
    nt = max(256, 16 * int(jj.max(initial=1)))
    x = _in_time(theta, jj, nt)                                            # (S, n, nt)
    swing = np.degrees(_peak_abs(x))
    amp = np.degrees(_peak_abs(_in_time(elastic, jj, nt)))
    x = np.subtract(x[:, :-1], x[:, 1:], out=x[:, 1:])                     # the twists
    torque = k * _peak_abs(x)                                              # (S, n-1)
    stress = None if d is None else 16.0 * torque / (np.pi * d ** 3) / 1e6
    s, i = np.unravel_index(int(np.argmax(torque)), torque.shape)
    return Response(speeds_rpm=speeds, amplitude_deg=amp, torque_Nm=torque,
                    stress_MPa=stress, orders=orders,
                    amplitude_by_order_deg=np.degrees(np.abs(elastic)),
                    worst=(float(speeds[s]), int(i), float(torque[s, i])),
                    swing_deg=swing)
