"""Balancing of a rigid rotor: static (one correction plane) and dynamic (two planes).

Every unbalance is a mass-radius product ``m·r`` [g·mm] at an angle [deg] (counter-clockwise
from the rotor's reference line, looking along +z) in a transverse plane at ``z`` [mm].  The
centrifugal force of each is ``m·r·ω²`` along its direction, so balancing works on the
vectors ``m·r·e^{iθ}`` (complex numbers here).

* Static balancing (one plane, narrow rotors, D/b ≥ 5): the correction is
  ``(m r)_b = −Σ m_i r_i`` (eq. 11-4 of the seed textbook).
* Dynamic balancing (two planes I and II at z_I, z_II): each ``m_i r_i`` at ``z_i`` is
  resolved into the two planes by the lever rule,
  ``(m r)_iI = m_i r_i (z_II − z_i)/(z_II − z_I)``,
  ``(m r)_iII = m_i r_i (z_i − z_I)/(z_II − z_I)`` (a mass outside the span, an overhung
  one, gives a negative share), then each plane is balanced statically (eqs. 11-6 … 11-9).
  Then both the resultant force and the resultant moment of the centrifugal forces vanish.

Angles of the corrections are reported in [0°, 360°) as the direction of the correction
vector itself.  Textbooks that write ``θ_b = arctan((m r)_by / (m r)_bx)`` without fixing
the quadrant print the direction of the opposite vector when both components are negative:
the seed's Example 11-1 prints 43.57° for the plane-II correction whose direction is
223.5° (see :attr:`RotorBalance.corrections`, column ``angle_deg``, and the tests).

References
----------
.. [1] Textbook chapter 11 "机械系统的动力分析与设计" (Dynamic analysis and design of
   machine systems), §11.2.1, eqs. (11-3)…(11-9), Example 11-1 (seed 001 of this project,
   shared/seeds/001_*.txt).
.. [2] Khurmi R. S., Gupta J. K. Theory of Machines. S. Chand, 14th ed., 2005, ch. 21
   "Balancing of rotating masses", §21.4–21.5.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import Text
from ._base import Problem, SpecError, read_toml

__all__ = ["RotorSpec", "RotorBalance", "balance_rotor", "load_rotor_spec", "rotor_balance",
           "plot_mr_polygon"]


def _angle_deg(z):
    """Direction of complex vectors in [0, 360). [deg]"""
    a = np.degrees(np.angle(z)) % 360.0
    return np.where(a >= 360.0 - 1e-12, 0.0, a)


@dataclass(frozen=True)
class RotorSpec:
    """A validated rotor spec (see :func:`load_rotor_spec`).  Lengths [mm], mass-radius
    products [g·mm], angles [deg]."""

    name: str
    planes_mm: tuple
    mr_gmm: tuple
    angle_deg: tuple
    z_mm: tuple
    correction_radius_mm: float | None = None
    source: str | None = None


@dataclass
class RotorBalance:
    """Result of :func:`balance_rotor`.

    Attributes
    ----------
    name : str
    kind : {"static", "dynamic"}
        One correction plane or two.
    masses : pandas.DataFrame
        The given unbalances: ``mass, z_mm, mr_gmm, angle_deg, mr_x_gmm, mr_y_gmm``.
    shares : pandas.DataFrame
        Each unbalance resolved into each correction plane (the lever rule; for static
        balancing all of it in the one plane): ``plane, mass, mr_x_gmm, mr_y_gmm,
        mr_gmm, angle_deg``.  ``mr_gmm`` is signed along the mass's own direction (negative
        for an overhung mass's share in the far plane).
    corrections : pandas.DataFrame
        One row per plane: ``plane`` ("I", "II"), ``z_mm``, ``mr_gmm`` (magnitude),
        ``angle_deg`` in [0, 360) (direction of the correction vector), ``mr_x_gmm``,
        ``mr_y_gmm``; and ``r_mm``, ``m_g`` when a correction radius was given.
    residual_force_gmm : float
        |Σ m r| over the unbalances and the corrections (zero up to rounding). [g·mm]
    residual_moment_gmm2 : float
        |Σ m r (z − z_I)| about the first correction plane: zero for dynamic balancing;
        for static balancing the couple left (a static correction does not remove it).
        [g·mm²]
    initial_force_gmm, initial_moment_gmm2 : float
        The same before correction.
    """

    name: str
    kind: str
    masses: object
    shares: object
    corrections: object
    residual_force_gmm: float
    residual_moment_gmm2: float
    initial_force_gmm: float
    initial_moment_gmm2: float
    planes_mm: np.ndarray = field(default_factory=lambda: np.zeros(1))


def balance_rotor(mr_gmm, angle_deg, z_mm=None, planes_mm=(0.0,), *,
                  correction_radius_mm=None, name="rotor") -> RotorBalance:
    """Static or two-plane balancing of a rigid rotor.

    Parameters
    ----------
    mr_gmm : array_like
        Mass-radius products of the unbalances, ``m_i r_i`` ≥ 0. [g·mm]
    angle_deg : array_like
        Their directions, counter-clockwise from the reference line. [deg]
    z_mm : array_like, optional
        Axial positions of their planes. [mm]  Needed for two correction planes; for one
        plane they only enter the residual couple (default: all in the correction plane).
    planes_mm : sequence of 1 or 2 floats
        Axial positions of the correction planes I (and II). [mm]
    correction_radius_mm : float, optional
        Radius at which the correction masses sit; adds ``m_g = (m r)_b / r``. [mm]
    name : str

    Returns
    -------
    RotorBalance

    Raises
    ------
    SpecError
        Empty or mismatched inputs, negative ``m r``, two coincident correction planes,
        every unbalance in one transverse plane with two correction planes asked (a
        single-plane rotor is balanced statically), a correction radius ≤ 0.

    Notes
    -----
    Eqs. (11-4) and (11-6)…(11-9) of [1]_ (module docstring); the lever rule resolves each
    unbalance so that both the force and the moment about either plane are reproduced.
    """
    import pandas as pd

    mr = np.atleast_1d(np.asarray(mr_gmm, dtype=float))
    ang = np.atleast_1d(np.asarray(angle_deg, dtype=float))
    planes = np.atleast_1d(np.asarray(planes_mm, dtype=float))
    problems = []
    if mr.size == 0:
        problems.append(Problem("rotor.mass", Text("errors.dynamics.rotor.no_unbalance_given")))
    if ang.shape != mr.shape:
        problems.append(Problem("angle_deg", Text("errors.dynamics.rotor.angles_for_masses",
                                                  {"size": ang.size, "size2": mr.size})))
    if z_mm is None:
        z = np.full(mr.shape, planes[0] if planes.size else 0.0)
    else:
        z = np.atleast_1d(np.asarray(z_mm, dtype=float))
        if z.shape != mr.shape:
            problems.append(Problem("z_mm", Text("errors.dynamics.rotor.positions_for_masses",
                                                 {"size": z.size, "size2": mr.size})))
    if np.any(mr < 0) or not np.all(np.isfinite(mr)):
        problems.append(Problem("mr_gmm", Text("errors.dynamics.rotor.every_m_r",
                                               {"value": mr.tolist()})))
    if planes.size not in (1, 2) or not np.all(np.isfinite(planes)):
        problems.append(Problem("rotor.planes_mm", Text("errors.dynamics.rotor.give_one_plane",
                                                        {"value": planes.tolist()})))
    elif planes.size == 2 and planes[0] == planes[1]:
        problems.append(Problem("rotor.planes_mm",
                                Text("errors.dynamics.rotor.two_correction_planes",
                                     {"value": planes.tolist()})))
    if correction_radius_mm is not None and not correction_radius_mm > 0:
        problems.append(Problem("rotor.correction_radius_mm",
                                Text("errors.dynamics.rotor.message",
                                     {"correction_radius_mm": correction_radius_mm})))
    if not problems and planes.size == 2 and z_mm is None:
        problems.append(Problem("rotor.mass.z_mm",
                                Text("errors.dynamics.rotor.missing_two_plane")))
    if not problems and planes.size == 2 and mr.size > 0 and np.ptp(z) == 0:
        problems.append(Problem(
            "rotor.mass.z_mm", Text("errors.dynamics.rotor.every_mass_lies", {"value": z[0]})))
    if problems:
        raise SpecError(problems)

    vec = mr * np.exp(1j * np.radians(ang))
    zI = planes[0]
    if planes.size == 1:
        share = vec[None, :]
        labels = ["I"]
    else:
        zII = planes[1]
        span = zII - zI
        share = np.vstack([vec * (zII - z) / span, vec * (z - zI) / span])
        labels = ["I", "II"]
    corr = -share.sum(axis=1)
    tot_f0 = vec.sum()
    tot_m0 = (vec * (z - zI)).sum()
    res_f = tot_f0 + corr.sum()
    res_m = tot_m0 + (corr * (planes - zI)).sum()

    masses = pd.DataFrame({"mass": np.arange(1, mr.size + 1), "z_mm": z, "mr_gmm": mr,
                           "angle_deg": ang % 360.0, "mr_x_gmm": vec.real,
                           "mr_y_gmm": vec.imag})
    k, j = np.meshgrid(np.arange(len(labels)), np.arange(mr.size), indexing="ij")
    unit = np.exp(1j * np.radians(ang))[None, :] + 0 * share
    shares = pd.DataFrame({
        "plane": np.array(labels)[k.ravel()], "mass": j.ravel() + 1,
        "mr_x_gmm": share.real.ravel(), "mr_y_gmm": share.imag.ravel(),
        "mr_gmm": (share * np.conj(unit)).real.ravel(),
        "angle_deg": np.broadcast_to(ang % 360.0, share.shape).ravel()})
    corrections = pd.DataFrame({"plane": labels, "z_mm": planes, "mr_gmm": np.abs(corr),
                                "angle_deg": _angle_deg(corr), "mr_x_gmm": corr.real,
                                "mr_y_gmm": corr.imag})
    if correction_radius_mm is not None:
        corrections["r_mm"] = float(correction_radius_mm)
        corrections["m_g"] = np.abs(corr) / correction_radius_mm
    return RotorBalance(name=name, kind="static" if planes.size == 1 else "dynamic",
                        masses=masses, shares=shares, corrections=corrections,
                        residual_force_gmm=float(abs(res_f)),
                        residual_moment_gmm2=float(abs(res_m)),
                        initial_force_gmm=float(abs(tot_f0)),
                        initial_moment_gmm2=float(abs(tot_m0)), planes_mm=planes)




def load_rotor_spec(path_or_dict) -> RotorSpec:
    """Read and validate a rotor spec (TOML file or dict)::

        [rotor]
        name = "two-plane-example"
        planes_mm = [0, 300]          # one plane: static balancing; two: dynamic
        correction_radius_mm = 50     # optional: report the correction masses m_g
        [[rotor.mass]]
        mr_gmm = 90                   # or m_g and r_mm
        angle_deg = 270
        z_mm = 100

    Every problem is reported at once (:class:`SpecError`), each with its key path.
    """
    if isinstance(path_or_dict, RotorSpec):
        return path_or_dict
    data, _ = read_toml(path_or_dict)
    from crankbase.schema import SpecReader

    from .schema import ROTOR, ROTOR_MASS, ROTOR_SCHEMA

    ck = SpecReader()
    ck.top(data, ROTOR_SCHEMA)
    rot = ck.sub(data, ROTOR)
    name = ck.get(rot, ROTOR, "name")
    planes = ck.get(rot, ROTOR, "planes_mm")
    if planes is not None and len(planes) > 2:
        ck.add("rotor.planes_mm", Text("errors.dynamics.rotor.planes_give_one",
                                       {"n": len(planes)}))
        planes = None
    radius = ck.get(rot, ROTOR, "correction_radius_mm")
    mr, ang, zz = [], [], []
    need_z = planes is not None and len(planes) == 2
    for path, m in ck.rows(rot, ROTOR_MASS):

        def get(key, **kw):
            return ck.get(m, ROTOR_MASS, key, path=path, **kw)

        if "mr_gmm" in m and ("m_g" in m or "r_mm" in m):
            ck.add(path, Text("errors.dynamics.rotor.give_either_mr"))
            value = None
        elif "mr_gmm" in m:
            value = get("mr_gmm", required=True)
        else:
            mg = get("m_g", required=True)
            rr = get("r_mm", required=True)
            value = None if mg is None or rr is None else mg * rr
        a = get("angle_deg")
        z = get("z_mm", required=need_z)
        mr.append(value)
        ang.append(a)
        zz.append(z)
    ck.raise_if_any()
    if not need_z and any(z is None for z in zz):
        zz = [planes[0] if z is None else z for z in zz]
    src = None if isinstance(path_or_dict, dict) else str(path_or_dict)
    spec = RotorSpec(name=name, planes_mm=tuple(planes), mr_gmm=tuple(mr),
                     angle_deg=tuple(ang), z_mm=tuple(zz), correction_radius_mm=radius,
                     source=src)
    return spec


def rotor_balance(spec) -> RotorBalance:
    """Balance the rotor of a spec (path, dict or :class:`RotorSpec`)."""
    spec = load_rotor_spec(spec)
    try:
        return balance_rotor(spec.mr_gmm, spec.angle_deg, spec.z_mm, spec.planes_mm,
                             correction_radius_mm=spec.correction_radius_mm, name=spec.name)
    except SpecError as exc:  # name the spec keys
        raise SpecError([Problem(p.key if p.key.startswith("rotor") else f"rotor.mass.{p.key}",
                                 p.text or p.message) for p in exc.problems]) from None


def plot_mr_polygon(result: RotorBalance, plane=0, ax=None, lang="en"):
    """The m·r vector polygon of one correction plane: the unbalances' shares head to tail,
    closed by the correction (dashed).  Equal aspect; returns the Axes.

    Parameters
    ----------
    result : RotorBalance
    plane : int
        0 for plane I, 1 for plane II.
    ax : matplotlib.axes.Axes, optional
    lang : {"en", "ru"}
    """
    if ax is None:
        from matplotlib.figure import Figure
        ax = Figure(figsize=(5, 5)).add_subplot()
    label = result.corrections["plane"].iloc[plane]
    sh = result.shares[result.shares["plane"] == label]
    vec = (sh["mr_x_gmm"] + 1j * sh["mr_y_gmm"]).to_numpy()
    corr = complex(result.corrections["mr_x_gmm"].iloc[plane],
                   result.corrections["mr_y_gmm"].iloc[plane])
    pts = np.concatenate([[0j], np.cumsum(vec)])
    span = max(np.max(np.abs(pts)), abs(corr), 1e-12)
    styles = ["-", (0, (6, 2)), (0, (1, 1.5)), (0, (4, 1.5, 1, 1.5))]
    for i, v in enumerate(vec):
        a, b = pts[i], pts[i + 1]
        ax.annotate("", xy=(b.real, b.imag), xytext=(a.real, a.imag),
                    arrowprops=dict(arrowstyle="-|>", color="black", lw=1.4,
                                    linestyle=styles[i % len(styles)]))
        nrm = 1j * (b - a) / max(abs(b - a), 1e-300)  # left normal of the arrow
        mid = 0.5 * (a + b) + 0.06 * span * nrm
        ax.text(mid.real, mid.imag, f"{i + 1}", fontsize=10, ha="center", va="center")
    end = pts[-1]
    ax.annotate("", xy=(0, 0), xytext=(end.real, end.imag),
                arrowprops=dict(arrowstyle="-|>", color="0.35", lw=2.0, linestyle="--"))
    # the label beside the middle of the closing vector, on the side away from the
    # polygon (its vertices' mean), so that it covers no arrow of a thin polygon
    nrm = -1j * end / max(abs(end), 1e-300)   # right normal of the closing vector
    centre = np.mean(pts) - 0.5 * end
    if (centre.real * nrm.real + centre.imag * nrm.imag) > 0:
        nrm = -nrm
    cm = 0.5 * end + 0.2 * span * nrm
    from crankbase.plot_texts import plot_words

    w = plot_words(lang, "rotor")
    b_lab = w["b"]
    ax.text(cm.real, cm.imag, f"{b_lab} = {abs(corr):.4g}\n{_angle_deg(corr):.2f}°",
            fontsize=9, color="0.2", ha="center", va="center",
            bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="0.7", lw=0.5))
    ax.plot([0], [0], "ko", ms=4)
    pad = 0.15 * span
    xs = np.concatenate([pts.real, [0]])
    ys = np.concatenate([pts.imag, [0]])
    ax.set_xlim(xs.min() - pad, xs.max() + pad)
    ax.set_ylim(ys.min() - pad, ys.max() + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.grid(True, lw=0.3)
    z = f"{result.corrections['z_mm'].iloc[plane]:g}"
    ax.set_title(w["title"].format(plane=label, z=z))
    ax.set_xlabel(w["x"])
    ax.set_ylabel(w["y"])
    return ax
