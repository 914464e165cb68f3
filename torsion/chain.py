"""The lumped-mass torsional chain: natural frequencies and modes, Holzer's table, damping.

The chain: masses J₁ … J_n [kg·m²] along the shaft, numbered from the free (front) end to
the load, joined by shaft sections of stiffness k₁ … k_{n−1} [N·m/rad] (section i joins
mass i and i + 1).  Free vibration solves K θ = ω² J θ, K the tridiagonal stiffness matrix
and J = diag(J_i), a symmetric generalised eigenproblem (:func:`scipy.linalg.eigh`); the
free–free chain has one zero frequency, the rigid rotation, kept apart from the n − 1
elastic modes [1]_ [2]_.

Holzer's table [1]_ [3]_ at a trial ω: θ₁ = 1; for each mass in turn the inertia torque
J_i ω² θ_i, the running sum ΣJω²θ (the torque the shaft after mass i carries), the twist
of that shaft ΣJω²θ / k_i and θ_{i+1} = θ_i − ΣJω²θ / k_i.  ω is natural when the sum
after the last mass (the residual, :func:`holzer_residual`) is zero.

References
----------
.. [1] W. T. Thomson, M. D. Dahleh, *Theory of Vibration with Applications*, 5th ed.,
   § 12.4 "Holzer method" (and ch. 6, multi-degree-of-freedom systems).
.. [2] J. P. Den Hartog, *Mechanical Vibrations*, 4th ed., ch. 5 (torsional vibrations of
   multi-cylinder engines).
.. [3] S. S. Rao, *Mechanical Vibrations*, 5th ed., § 7.6 (Holzer's method).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from crankbase.errors import Problem, SpecError, Text

from .results import Modes, mass_names

if TYPE_CHECKING:                       # annotations only: no pandas import at run time
    import pandas as pd

__all__ = ["natural_modes", "holzer_table", "holzer_residual", "damping_matrix",
           "shaft_stiffness", "stiffness_matrix", "check_chain", "check_positive",
           "INERTIAS_KEY", "STIFFNESSES_KEY"]

#: The spec keys the input errors name (the ``[torsion]`` table's keys).
INERTIAS_KEY = "torsion.inertias_kgm2"
STIFFNESSES_KEY = "torsion.stiffnesses_Nm_rad"
DAMPING_KEY = "torsion.damping_ratio"
DAMPERS_KEY = "torsion.dampers"


def _vector(value, key):
    """``value`` as a 1-D float array, or a SpecError naming ``key``."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise SpecError(Problem(key, Text("errors.torsion.vector", {"value": repr(value)})))
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim != 1:
        raise SpecError(Problem(key, Text("errors.torsion.vector", {"value": repr(value)})))
    return arr


def check_positive(value, key, *, allow_zero=False):
    """``value`` (a number or a list) as a float array whose entries are finite and > 0
    (≥ 0 with ``allow_zero``), or a :class:`~crankbase.errors.SpecError` naming ``key``."""
    arr = _vector(value, key)
    bad = ~np.isfinite(arr) | ((arr < 0) if allow_zero else (arr <= 0))
    if bad.any():
        text = "errors.torsion.nonnegative" if allow_zero else "errors.torsion.positive"
        raise SpecError(Problem(key, Text(text, {"value": f"{arr[bad][0]:g}"})))
    return arr


def check_chain(J_kgm2, k_Nm_rad):
    """The chain's inertias and stiffnesses as float arrays, checked: at least two masses,
    every J and k finite and positive, one stiffness between each two consecutive masses.

    Raises
    ------
    crankbase.errors.SpecError
        Naming ``torsion.inertias_kgm2`` or ``torsion.stiffnesses_Nm_rad``.
    """
    J = check_positive(J_kgm2, INERTIAS_KEY)
    if len(J) < 2:
        raise SpecError(Problem(INERTIAS_KEY, Text("errors.torsion.too_few_masses",
                                                   {"got": len(J)})))
    k = check_positive(k_Nm_rad, STIFFNESSES_KEY)
    if len(k) != len(J) - 1:
        raise SpecError(Problem(STIFFNESSES_KEY, Text("errors.torsion.stiffness_count",
                                                      {"got": len(k), "masses": len(J),
                                                       "expected": len(J) - 1})))
    return J, k


def stiffness_matrix(k_Nm_rad) -> np.ndarray:
    """The (n × n) tridiagonal stiffness matrix of a free–free chain of n − 1 sections."""
    k = np.asarray(k_Nm_rad, float)
    n = len(k) + 1
    K = np.zeros((n, n))
    i = np.arange(n - 1)
    K[i, i] += k
    K[i + 1, i + 1] += k
    K[i, i + 1] = -k
    K[i + 1, i] = -k
    return K


#: A shape entry below this fraction of the mode's largest is round-off of the eigen-solution:
#: taken as zero (a node at that mass between entries of opposite sign).
SHAPE_RESOLUTION = 1e-9


def _nodes(shapes):
    """The node positions of each mode in mass units (1-based): a sign change of the
    shape between consecutive masses, by linear interpolation; an entry zero to the
    eigen-solution's resolution between entries of opposite sign is a node at that mass
    (or, for a run of such entries, in their middle)."""
    out = []
    for row in shapes:                        # m modes of n entries: the ragged output
        s = np.where(np.abs(row) <= SHAPE_RESOLUTION * np.max(np.abs(row)), 0.0, row)
        nz = np.flatnonzero(s)
        a, b = nz[:-1], nz[1:]
        change = s[a] * s[b] < 0
        a, b = a[change], b[change]
        adjacent = b == a + 1
        pos = np.where(adjacent, a + 1 + s[a] / np.where(adjacent, s[a] - s[b], 1.0),
                       (a + b) / 2.0 + 1.0)
        out.append(np.sort(pos))
    return tuple(out)


def natural_modes(J_kgm2, k_Nm_rad) -> Modes:
    """Natural frequencies and mode shapes of the free–free torsional chain.

    Parameters
    ----------
    J_kgm2 : array_like (n,)
        Mass moments of inertia, from the free (front) end to the load. [kg·m²]
    k_Nm_rad : array_like (n − 1,)
        Torsional stiffness of each section (section i joins mass i and i + 1). [N·m/rad]

    Returns
    -------
    Modes
        The n − 1 elastic modes, ascending, with shapes normalised to mass 1 = 1 and to
        ``phi @ diag(J) @ phi.T = I``, the nodes, and the rigid mode apart.

    Raises
    ------
    crankbase.errors.SpecError
        Bad chain (:func:`check_chain`).

    Notes
    -----
    K θ = ω² J θ by :func:`scipy.linalg.eigh` (K symmetric, J positive definite): real
    eigenvalues, J-orthogonal eigenvectors.  The smallest eigenvalue is the rigid rotation
    (0 up to round-off, θ_i all equal); it is reported in ``rigid_omega_rad_s``.

    Examples
    --------
    Two equal discs: ω² = 2k/J.

    >>> m = natural_modes([1.0, 1.0], [100.0])
    >>> round(float(m.omega_rad_s[0]) ** 2, 6), m.shapes[0].round(6).tolist()
    (200.0, [1.0, -1.0])
    """
    from scipy.linalg import eigh

    J, k = check_chain(J_kgm2, k_Nm_rad)
    K = stiffness_matrix(k)
    # scale the problem to order 1 (the J and k of a chain span decades)
    Js, ks = J.max(), k.max()
    lam, vec = eigh(K / ks, np.diag(J / Js))
    lam = lam * (ks / Js)
    vec = vec / math.sqrt(Js)                  # vecᵀ diag(J) vec = I in SI
    # the rigid mode: the eigenvector with the most uniform sign (the smallest eigenvalue)
    rigid = vec[:, 0]
    rigid = rigid * np.sign(rigid.sum())
    phi = vec[:, 1:].T.copy()
    omega = np.sqrt(np.clip(lam[1:], 0.0, None))
    # normalised to mass 1 = 1; a mode in which mass 1 is at rest to the solution's
    # resolution (a mode held in a stiff far part of a very uneven chain) to its largest
    # entry = 1 instead
    big = np.take_along_axis(phi, np.argmax(np.abs(phi), axis=1)[:, None], axis=1)
    ref = np.where(np.abs(phi[:, :1]) > SHAPE_RESOLUTION * np.abs(big), phi[:, :1], big)
    phi *= np.sign(ref)                        # mass 1 (or the largest entry) positive
    shapes = phi / np.abs(ref)
    return Modes(omega_rad_s=omega, f_Hz=omega / (2 * np.pi), shapes=shapes,
                 nodes=_nodes(shapes),
                 rigid_omega_rad_s=float(math.sqrt(abs(lam[0]))), phi=phi,
                 rigid_phi=rigid)


def _holzer(J, k, omega):
    """θ (T, n), inertia torque (T, n), running sum (T, n) and twist (T, n − 1) of
    Holzer's table at each ω of ``omega`` (T,)."""
    w2 = np.asarray(omega, float).reshape(-1)[:, None] ** 2
    n = len(J)
    theta = np.empty((w2.shape[0], n))
    inertia = np.empty_like(theta)
    total = np.empty_like(theta)
    twist = np.empty((w2.shape[0], n - 1))
    theta[:, 0] = 1.0
    running = np.zeros(w2.shape[0])
    for i in range(n):                         # along the chain; vectorised over ω
        inertia[:, i] = J[i] * w2[:, 0] * theta[:, i]
        running = running + inertia[:, i]
        total[:, i] = running
        if i < n - 1:
            twist[:, i] = running / k[i]
            theta[:, i + 1] = theta[:, i] - twist[:, i]
    return theta, inertia, total, twist


def holzer_table(J_kgm2, k_Nm_rad, omega_rad_s, names=None) -> pd.DataFrame:
    """Holzer's table at one or more trial frequencies, in the course's form.

    Parameters
    ----------
    J_kgm2, k_Nm_rad : array_like
        The chain (:func:`natural_modes`).
    omega_rad_s : float or array_like (T,)
        Trial angular frequencies; one table per ω, stacked in the given order. [rad/s]
    names : list of str, optional
        The masses' names (default "1" … "n").

    Returns
    -------
    pandas.DataFrame
        n rows per ω: ``omega_rad_s``, ``mass``, ``J_kgm2``, ``theta_rad`` (θ₁ = 1),
        ``inertia_torque_Nm`` J ω² θ, ``sum_torque_Nm`` ΣJω²θ, ``k_Nm_rad`` of the shaft
        after the mass and ``twist_rad`` ΣJω²θ / k (both NaN on the last row).  The last
        row's ``sum_torque_Nm`` is the residual (:func:`holzer_residual`).

    Examples
    --------
    >>> t = holzer_table([1.0, 1.0], [100.0], [10.0])
    >>> t["sum_torque_Nm"].tolist()
    [100.0, 100.0]
    """
    import pandas as pd

    J, k = check_chain(J_kgm2, k_Nm_rad)
    w = check_positive(omega_rad_s, "omega_rad_s", allow_zero=True)
    names = mass_names(len(J), names)
    theta, inertia, total, twist = _holzer(J, k, w)
    T, n = theta.shape
    nan = np.full((T, 1), np.nan)
    return pd.DataFrame({
        "omega_rad_s": np.repeat(w, n),
        "mass": np.tile(np.array(names, dtype=object), T),
        "J_kgm2": np.tile(J, T),
        "theta_rad": theta.ravel(),
        "inertia_torque_Nm": inertia.ravel(),
        "sum_torque_Nm": total.ravel(),
        "k_Nm_rad": np.hstack([np.tile(k, (T, 1)), nan]).ravel(),
        "twist_rad": np.hstack([twist, nan]).ravel(),
    })


def holzer_residual(J_kgm2, k_Nm_rad, omega_rad_s) -> np.ndarray:
    """The residual torque ΣJω²θ after the last mass of Holzer's table (θ₁ = 1) at each
    ω of ``omega_rad_s`` (same shape); zero at a natural frequency. [N·m per rad of θ₁]"""
    J, k = check_chain(J_kgm2, k_Nm_rad)
    w = np.asarray(omega_rad_s, float)
    return _holzer(J, k, w)[2][:, -1].reshape(w.shape)


def damping_matrix(J_kgm2, modes: Modes, damping_ratio=0.0, dampers=None) -> np.ndarray:
    """The (n × n) viscous damping matrix of the chain.

    Parameters
    ----------
    J_kgm2 : array_like (n,)
    modes : Modes
        From :func:`natural_modes` of the same chain.
    damping_ratio : float or array_like (n − 1,)
        Modal (relative) damping ratio ζ of every elastic mode, or one per mode.
    dampers : dict, optional
        Absolute viscous dampers to ground ``{mass index (0-based): c [N·m·s/rad]}``.

    Returns
    -------
    ndarray (n, n)
        C = J Φᵀ diag(2ζω) Φ J (Φ the mass-normalised shapes, one row per mode; the rigid
        mode undamped) plus c on the diagonal at each damper's mass.  Then Φ C Φᵀ =
        diag(2ζω): each mode has exactly its ratio ζ.
    """
    J = check_positive(J_kgm2, INERTIAS_KEY)
    n = len(J)
    if modes.phi.shape[1] != n:
        raise SpecError(Problem(INERTIAS_KEY, Text("errors.torsion.count",
                                                   {"got": n,
                                                    "expected": modes.phi.shape[1]})))
    zeta = check_positive(damping_ratio, DAMPING_KEY, allow_zero=True)
    if len(zeta) not in (1, modes.count):
        raise SpecError(Problem(DAMPING_KEY, Text("errors.torsion.count",
                                                  {"got": len(zeta),
                                                   "expected": modes.count})))
    zeta = np.broadcast_to(zeta, (modes.count,))
    JP = J[:, None] * modes.phi.T              # J Φᵀ (n, m)
    C = (JP * (2.0 * zeta * modes.omega_rad_s)) @ JP.T
    C = 0.5 * (C + C.T)
    for idx, c in (dampers or {}).items():
        if not isinstance(idx, (int, np.integer)) or not 0 <= idx < n:
            raise SpecError(Problem(DAMPERS_KEY, Text("errors.torsion.mass_index",
                                                      {"value": idx, "last": n - 1})))
        C[idx, idx] += float(check_positive(c, DAMPERS_KEY, allow_zero=True)[0])
    return C


def shaft_stiffness(G_Pa, d_m, l_m) -> float:
    """Torsional stiffness of a plain solid round shaft k = G·Ip/l, Ip = π d⁴/32. [N·m/rad]

    >>> round(shaft_stiffness(80e9, 0.05, 1.0))
    49087
    """
    G = float(check_positive(G_Pa, "G_Pa")[0])
    d = float(check_positive(d_m, "d_m")[0])
    length = float(check_positive(l_m, "l_m")[0])
    return G * math.pi * d ** 4 / 32.0 / length
