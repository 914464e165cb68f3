"""Result types of the torsion physics: :class:`Modes`, :class:`Harmonics`, :class:`Response`.

Plain frozen dataclasses of numpy arrays, each with a ``table()`` giving the rows a CSV or a
workbook sheet shows.  Conventions (``tools/TORSION_API.md``): masses 1…n from the free
front end to the load, section i joins mass i and i + 1 and is named
``"<mass i>-<mass i+1>"``; SI units inside, degrees where a column says ``_deg``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:                       # annotations only: no pandas import at run time
    import pandas as pd

__all__ = ["Modes", "Harmonics", "Response", "mass_names", "section_names"]


def mass_names(n, names=None) -> list[str]:
    """The names of the ``n`` masses: ``names`` as given, or ``"1"`` … ``"n"``."""
    if names is None:
        return [str(i + 1) for i in range(n)]
    names = [str(x) for x in names]
    if len(names) != n:
        from crankbase.errors import Problem, SpecError, Text

        raise SpecError(Problem("names", Text("errors.torsion.count",
                                              {"got": len(names), "expected": n})))
    return names


def section_names(names) -> list[str]:
    """``"<mass i>-<mass i+1>"`` for each shaft section between consecutive masses."""
    return [f"{a}-{b}" for a, b in zip(names[:-1], names[1:])]


@dataclass(frozen=True)
class Modes:
    """The elastic natural modes of a free–free chain (:func:`torsion.chain.natural_modes`).

    Attributes
    ----------
    omega_rad_s : ndarray (m,)
        Natural angular frequencies of the elastic modes, ascending. [rad/s]
    f_Hz : ndarray (m,)
        The same in Hz. [Hz]
    shapes : ndarray (m, n)
        Mode shapes, one row per mode, normalised to the first (free-end) mass = 1
        (a mode in which mass 1 is at rest to 1e-9 of the mode's largest amplitude, which
        only a very uneven chain has, to its largest entry = 1 instead).
    nodes : tuple of m ndarrays
        The nodes of each mode along the shaft in "mass units": 1.0 at mass 1, 2.37 in
        section 2, 37 % of the way from mass 2 to mass 3 (linear interpolation of the
        sign change of the shape, exact for a uniform shaft section whose twist is
        linear along it).  Mode m (1-based) has m nodes.
    rigid_omega_rad_s : float
        The rigid-rotation eigenvalue's frequency, ≈ 0 (round-off), kept apart. [rad/s]
    phi : ndarray (m, n)
        Mass-normalised shapes, one row per mode: ``phi @ diag(J) @ phi.T = I``.
    rigid_phi : ndarray (n,)
        The mass-normalised rigid mode (every entry 1/√ΣJ).
    """

    omega_rad_s: np.ndarray
    f_Hz: np.ndarray
    shapes: np.ndarray
    nodes: tuple
    rigid_omega_rad_s: float
    phi: np.ndarray
    rigid_phi: np.ndarray

    @property
    def count(self) -> int:
        """Number of elastic modes (n − 1)."""
        return len(self.omega_rad_s)

    def table(self, names=None) -> pd.DataFrame:
        """One row per mode: ``mode`` (1-based), ``f_Hz``, ``omega_rad_s``, ``nodes`` (the
        node positions in mass units, ``"; "``-joined to 3 decimals) and ``theta_<mass>``
        (the shape, first mass = 1)."""
        import pandas as pd

        names = mass_names(self.shapes.shape[1], names)
        data = {"mode": np.arange(1, self.count + 1), "f_Hz": self.f_Hz,
                "omega_rad_s": self.omega_rad_s,
                "nodes": ["; ".join(f"{x:.3f}" for x in nd) for nd in self.nodes]}
        for i, name in enumerate(names):
            data[f"theta_{name}"] = self.shapes[:, i]
        return pd.DataFrame(data)


@dataclass(frozen=True)
class Harmonics:
    """The Fourier series of a periodic torque (:func:`torsion.harmonics.torque_harmonics`).

    M(α) = M0 + Σ_k [a_k cos(kα) + b_k sin(kα)], α in crankshaft radians, k the order
    (multiples of 360°/cycle: 0.5 for a four-stroke cycle of 720°); the complex amplitude
    M_k = a_k − i·b_k, so M(α) = Re Σ M_k e^{ikα}.  Order 0 is the mean (b = 0).

    Attributes
    ----------
    order : ndarray (K,)
        0, base, 2·base … orders_max.
    a_Nm, b_Nm : ndarray (K,)
        Cosine and sine coefficients. [N·m]
    amplitude_Nm : ndarray (K,)
        hypot(a, b) (|M0| for order 0). [N·m]
    phase_deg : ndarray (K,)
        atan2(−b, a), the angle of M_k. [deg]
    complex_Nm : ndarray (K,)
        M_k = a − i·b. [N·m]
    reconstruction_rms_Nm : float
        rms over the grid of M minus the truncated series (the orders above orders_max).
    rms_Nm : float
        rms of M over the grid.
    cycle_deg : float
        The period of M in crankshaft degrees (720 four-stroke, 360 two-stroke).
    """

    order: np.ndarray
    a_Nm: np.ndarray
    b_Nm: np.ndarray
    amplitude_Nm: np.ndarray
    phase_deg: np.ndarray
    complex_Nm: np.ndarray
    reconstruction_rms_Nm: float
    rms_Nm: float
    cycle_deg: float

    @property
    def mean_Nm(self) -> float:
        """The order-0 term, the mean of M over the cycle. [N·m]"""
        return float(self.a_Nm[0])

    def series(self, alpha_deg) -> np.ndarray:
        """The truncated series evaluated at crankshaft angles ``alpha_deg``. [N·m]"""
        a = np.radians(np.asarray(alpha_deg, float))
        return np.real(np.exp(1j * np.multiply.outer(a, self.order)) @ self.complex_Nm)

    def scaled(self, factor) -> "Harmonics":
        """Every coefficient times ``factor`` (an inertia torque at another speed:
        factor = (n/n_ref)²)."""
        f = float(factor)
        return Harmonics(self.order, self.a_Nm * f, self.b_Nm * f,
                         self.amplitude_Nm * abs(f),
                         np.degrees(np.angle(self.complex_Nm * f)), self.complex_Nm * f,
                         self.reconstruction_rms_Nm * abs(f), self.rms_Nm * abs(f),
                         self.cycle_deg)

    def table(self) -> pd.DataFrame:
        """Columns ``order, a_Nm, b_Nm, amplitude_Nm, phase_deg``."""
        import pandas as pd

        return pd.DataFrame({"order": self.order, "a_Nm": self.a_Nm, "b_Nm": self.b_Nm,
                             "amplitude_Nm": self.amplitude_Nm,
                             "phase_deg": self.phase_deg})


@dataclass(frozen=True)
class Response:
    """The steady forced response of the chain over a speed range
    (:func:`torsion.response.forced_response`).

    Attributes
    ----------
    speeds_rpm : ndarray (S,)
    amplitude_deg : ndarray (S, n)
        Peak vibration angle of each mass over one cycle (the orders summed in time): the
        elastic (twisting) motion, relative to the rotation of the whole chain's mean
        inertia (Θ − Σ J Θ / Σ J per order, :func:`torsion.response.elastic_part`), which
        peaks at the critical speeds. [deg]
    torque_Nm : ndarray (S, n − 1)
        Peak vibration torque k_i(θ_i − θ_{i+1}) of each section over one cycle. [N·m]
    stress_MPa : ndarray (S, n − 1) or None
        Peak shear stress τ = 16 M/(π d³) of each section (with its diameter). [MPa]
    orders : ndarray (K,)
        The excitation orders (order 0, the mean torque, is no vibration and is left out).
    amplitude_by_order_deg : ndarray (S, K, n)
        |Θ_k − Σ J Θ_k / Σ J| of each order alone (elastic, as ``amplitude_deg``). [deg]
    worst : tuple
        (speed_rpm, section index (0-based), torque_Nm) of the largest vibration torque.
    swing_deg : ndarray (S, n) or None
        Peak absolute angle of each mass over one cycle: the elastic motion plus the
        swing of the whole free chain (the speed fluctuation, ∝ 1/n² at low speed). [deg]
    """

    speeds_rpm: np.ndarray
    amplitude_deg: np.ndarray
    torque_Nm: np.ndarray
    stress_MPa: np.ndarray | None
    orders: np.ndarray
    amplitude_by_order_deg: np.ndarray
    worst: tuple
    swing_deg: np.ndarray | None = None

    def table(self, names=None) -> pd.DataFrame:
        """Columns ``speed_rpm``, ``theta_<mass>_deg`` … (elastic vibration amplitude),
        ``M_<section>_Nm`` …, ``tau_<section>_MPa`` … (with diameters only), then
        ``swing_<mass>_deg`` … (absolute angle, the whole chain's swing included; when
        known)."""
        import pandas as pd

        names = mass_names(self.amplitude_deg.shape[1], names)
        secs = section_names(names)
        data = {"speed_rpm": self.speeds_rpm}
        for i, name in enumerate(names):
            data[f"theta_{name}_deg"] = self.amplitude_deg[:, i]
        for i, sec in enumerate(secs):
            data[f"M_{sec}_Nm"] = self.torque_Nm[:, i]
        if self.stress_MPa is not None:
            for i, sec in enumerate(secs):
                data[f"tau_{sec}_MPa"] = self.stress_MPa[:, i]
        if self.swing_deg is not None:
            for i, name in enumerate(names):
                data[f"swing_{name}_deg"] = self.swing_deg[:, i]
        return pd.DataFrame(data)
