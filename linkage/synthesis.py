"""Synthesis of crank-rockers by the transmission angle: the ККМ-φ0 families.

A designer wants the transmission angle μ of a crank-rocker to be exactly 90° at the crank
angle φ0 where the load is largest, and never to fall below an acceptable minimum.  Sereda
[1]_ works this out for φ0 = 30° (the family "ККМ-30°"); every formula here is the paper's
with cos 30° replaced by cos φ0, so the same functions cover any 0° < φ0 < 180°.

Conventions
-----------
* Lengths are relative to the ground (line of centres) O–C: λ0 = 1, λ1 = crank OA,
  λ2 = coupler AB, λ3 = rocker CB (dimensionless; ``l1, l2, l3`` in code).
* φ is the crank angle measured counter-clockwise from the line of centres O→C, in
  degrees.  With the ground along +x (``ground_angle_deg = 0`` in a spec), φ is the
  absolute crank angle of :func:`linkage.analyze`.
* μ is the acute transmission angle: the angle between coupler and rocker at B, folded
  into 0…90°.
* c = cos φ0.  The family is the circle (eq. 6 generalised)

      λ2² + λ3² = λ1² + 1 − 2 λ1 cos φ0,

  and on it (eq. 12, 13 generalised)

      cos μ(φ) = λ1 (cos φ − cos φ0) / (λ2 λ3),
      μmin = arccos[λ1 (1 + |cos φ0|) / (λ2 λ3)],

  reached at φ = 180° when φ0 < 90° (the paper's case), at φ = 0° when φ0 > 90° and at
  both when φ0 = 90°.  μmin = 0 (a dead position, a change-point mechanism) on Kolchin's
  line 1 + λ1 = λ2 + λ3 when φ0 ≤ 90° (the paper's curve cda), on Kolchin's lines
  1 − λ1 = ±(λ2 − λ3) when φ0 ≥ 90°.  Inside the region, the crank is the shortest link
  and the Grashof condition holds: the mechanism is a crank-rocker.

Points within :data:`TOL` (1e-9) of the region's boundary count as inside (the paper's
own Table 1 sits on the boundary); such mechanisms are reported as change-point ones.

References
----------
.. [1] Середа Н. А. Семейство кривошипно-коромысловых механизмов с максимумом угла
   передачи при угле поворота кривошипа, равном 30°. Известия Самарского научного центра
   РАН, 2016 (the journal paper the ККМ-30° family comes from): eq. (1)–(3) Kolchin's lines, (6) the family,
   (9)–(11) the boundary and λ1max, (12)–(16) the transmission angle, Table 1, Fig. 2, 3.
.. [2] Колчин Н. И. Механика машин, т. 1. М.–Л.: Машгиз, 1963, p. 86 (the region of
   geometric rotatability, eq. (1)–(3) of [1]).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import Problem, Text
from crankbase.tolerances import DEGENERATE_QUADRATIC_ATOL, ROTATABILITY_RTOL, ROUNDOFF_RTOL

from .fourbar import (GeometryError, GrashofType, as_float, fmt_value, grashof,
                      min_transmission_angle_deg, positive_lengths, rotatability_margin,
                      transmission_angle_deg)

__all__ = [
    "TOL", "SynthesisError", "GrashofType", "grashof",
    "transmission_angle_deg", "min_transmission_angle_deg",
    "family_radius", "family_l3", "family_mu_min_deg",
    "crank_length_for_right_angle", "kolchin_line_points", "right_angle_family",
    "existence_region", "l1_max", "mu_min_curves",
    "Design", "design", "design_from_l2_l3", "design_equal_l2_l3", "design_for_mu_min",
    "to_spec", "FamilyArc", "ExistenceRegion", "MuMinCurves",
]

#: Points within this distance of the boundary of the region of existence (measured on
#: the residuals of Kolchin's inequalities, lengths relative to the ground) are inside:
#: the project's rotatability margin (:data:`crankbase.tolerances.ROTATABILITY_RTOL`).
TOL = ROTATABILITY_RTOL


class SynthesisError(GeometryError):
    """A synthesis argument is invalid or asks for a mechanism that does not exist.

    A :class:`ValueError` (through :class:`~crankbase.errors.SpecError`): each problem names
    the argument, the bad value and what would be valid; the CLI prints one per line.
    """


# --------------------------------------------------------------------------- validation
def _phi0(problems, phi0_deg, name="phi0_deg"):
    a = as_float(name, phi0_deg, problems)
    if a is None:
        return None
    if a.ndim != 0 or not math.isfinite(float(a)) or not 0.0 < float(a) < 180.0:
        problems.append(Problem(name, Text("errors.linkage.synthesis.crank_angle_strictly",
                                           {"value": fmt_value(phi0_deg)})))
        return None
    return float(a)


def _raise(problems):
    if problems:
        raise SynthesisError(problems)


def _scalar(name, value, problems):
    a = as_float(name, value, problems)
    if a is None:
        return None
    if a.ndim != 0:
        problems.append(Problem(name, Text("errors.linkage.synthesis.single_number",
                                           {"value": fmt_value(value)})))
        return None
    return float(a)


def _kolchin_margin(l1, l2, l3):
    """Signed distance in the (λ2, λ3) plane to the nearest of Kolchin's lines for this
    λ1: ≥ 0 for a crank-rocker or change point (:func:`linkage.fourbar.rotatability_margin`
    of the crank-rocker region, ground 1)."""
    return rotatability_margin(l1, l2, l3, 1.0, crank_rocker=True)


def _type_with_tol(l1, l2, l3) -> GrashofType:
    """:func:`grashof` (its change-point band is the region's boundary band, :data:`TOL`)."""
    return grashof(l1, l2, l3)


# --------------------------------------------------------------------------- the family
def family_radius(l1, phi0_deg=30.0):
    """Radius of the family's circle in the (λ2, λ3) plane, eq. (6) generalised.

    Parameters
    ----------
    l1 : array_like
        Crank length relative to the ground. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]

    Returns
    -------
    ndarray
        R = √(λ1² + 1 − 2 λ1 cos φ0). [-]

    References
    ----------
    .. [1] Sereda (2016), eq. (4)–(6): λ2² + λ3² = λ1 (λ1 − √3) + 1 for φ0 = 30°.
    """
    c = _c(phi0_deg)
    l1 = np.asarray(l1, dtype=float)
    return np.sqrt(l1 * (l1 - 2.0 * c) + 1.0)


def family_l3(l1, l2, phi0_deg=30.0):
    """Rocker length of the family member with crank ``l1`` and coupler ``l2``.

    Parameters
    ----------
    l1, l2 : array_like
        Crank and coupler lengths relative to the ground. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]

    Returns
    -------
    ndarray
        λ3 = √(λ1 (λ1 − 2 cos φ0) + 1 − λ2²); NaN where the circle does not reach λ2. [-]

    References
    ----------
    .. [1] Sereda (2016), eq. (6) solved for λ3 (the root under eq. (16)).
    """
    c = _c(phi0_deg)
    l1 = np.asarray(l1, dtype=float)
    l2 = np.asarray(l2, dtype=float)
    q = l1 * (l1 - 2.0 * c) + 1.0 - l2 ** 2
    with np.errstate(invalid="ignore"):
        return np.where(q >= 0.0, np.sqrt(np.maximum(q, 0.0)), np.nan)


def family_mu_min_deg(l1, l2, phi0_deg=30.0):
    """Minimum transmission angle of the family member with crank ``l1``, coupler ``l2``.

    Parameters
    ----------
    l1, l2 : array_like
        Crank and coupler lengths relative to the ground (by the symmetry of eq. (15),
        (16) the coupler and rocker may be swapped). [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]

    Returns
    -------
    ndarray
        μmin = arccos[λ1 (1 + |cos φ0|) / (λ2 √(λ1 (λ1 − 2 cos φ0) − λ2² + 1))]; NaN
        where the member is not a crank-rocker (λ1 < 0, λ1 > 1, λ3 not real, or the
        argument of arccos > 1 + :data:`TOL`); λ1 = 0 gives the limit 90°. [deg]

    References
    ----------
    .. [1] Sereda (2016), eq. (16) (and (15) with λ2 ↔ λ3); (14) for λ2 = λ3.
    """
    c = _c(phi0_deg)
    l1 = np.asarray(l1, dtype=float)
    l2 = np.asarray(l2, dtype=float)
    l3 = family_l3(l1, l2, phi0_deg)
    with np.errstate(invalid="ignore", divide="ignore"):
        x = l1 * (1.0 + abs(c)) / (l2 * l3)
        ok = (l1 >= 0) & (l1 <= 1.0 + TOL) & (l2 > 0) & np.isfinite(x) & (x <= 1.0 + TOL)
        return np.where(ok, np.degrees(np.arccos(np.clip(x, 0.0, 1.0))), np.nan)


def _c(phi0_deg):
    """cos φ0, exactly 0 at φ0 = 90° (math.cos(π/2) is 6e-17, which would shift λ1max
    by 1e-8 through its square root)."""
    return 0.0 if phi0_deg == 90.0 else math.cos(math.radians(phi0_deg))


def l1_max(phi0_deg=30.0) -> float:
    """Largest crank length of the family, eq. (11) generalised.

    Parameters
    ----------
    phi0_deg : float
        Crank angle where μ = 90°, 0 < φ0 < 180. [deg]

    Returns
    -------
    float
        For φ0 ≤ 90°, the smaller root of λ1² − 2 λ1 (1 + 2 cos φ0) + 1 = 0, i.e.
        1 / (√cos φ0 + √(1 + cos φ0))²  (0.1896 for φ0 = 30°); for φ0 ≥ 90°, 1 (there the
        boundary is Kolchin's lines (1)–(2) and any crank shorter than the ground fits). [-]

    References
    ----------
    .. [1] Sereda (2016), eq. (11): λ1² − 2 λ1 (1 + √3) + 1 = 0 → λ1 = 0.1896.
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    _raise(problems)
    c = _c(phi0)
    if c <= 0.0:
        return 1.0
    # Product of the roots is 1: the smaller one, without cancellation.
    return 1.0 / (math.sqrt(c) + math.sqrt(1.0 + c)) ** 2


def _boundary_sd(l1, c):
    """Sum and difference of the boundary point's coordinates for crank ``l1``.

    On the boundary λ2 λ3 = P = λ1 (1 + |c|) and λ2² + λ3² = R², so
    (λ2 + λ3)² = R² + 2P and (λ2 − λ3)² = R² − 2P: for c ≥ 0 these are (1 + λ1)² and
    λ1² − 2 λ1 (1 + 2c) + 1 (eq. (9)–(10)); for c ≤ 0, (1 + λ1)² − 4 c λ1 and (1 − λ1)².
    """
    R2 = l1 * (l1 - 2.0 * c) + 1.0
    P = l1 * (1.0 + abs(c))
    if c >= 0.0:
        S = 1.0 + l1
        # λ1² − 2 λ1 (1 + 2c) + 1 factored by its roots λ1max and 1/λ1max (eq. (11)), so
        # that it is exactly 0 at λ1max and accurate near it.
        top = 1.0 / (math.sqrt(c) + math.sqrt(1.0 + c)) ** 2
        D2 = (top - l1) * (1.0 / top - l1)
    else:
        S = np.sqrt(R2 + 2.0 * P)
        D2 = (1.0 - l1) ** 2
    return S, np.sqrt(np.maximum(D2, 0.0))


def kolchin_line_points(l1, phi0_deg=30.0):
    """Where the family's circle for crank ``l1`` meets Kolchin's boundary line(s).

    Parameters
    ----------
    l1 : array_like
        Crank length relative to the ground, 0 ≤ λ1 ≤ λ1max (λ1 = 0 gives the ends of the
        unit arc, (1, 0) and (0, 1)). [-]
    phi0_deg : float
        Crank angle where μ = 90°, 0 < φ0 < 180. [deg]

    Returns
    -------
    ndarray, shape ``(*np.shape(l1), 2, 2)``
        ``pts[..., k, :] = (λ2, λ3)`` of intersection k, the larger λ2 first (the two rows
        of the paper's Table 1 for each λ1; they coincide at λ1max). [-]

    Raises
    ------
    SynthesisError
        φ0 outside (0°, 180°), or λ1 outside [0, λ1max] (beyond :data:`TOL`).

    Notes
    -----
    For φ0 ≤ 90° the line is 1 + λ1 = λ2 + λ3 (eq. (3); the paper's case):

        λ2,3 = [λ1 + 1 ± √(λ1² − 2 λ1 (1 + 2 cos φ0) + 1)] / 2.

    For φ0 > 90° the dead position moves to φ = 0 and the boundary lines are
    1 − λ1 = ±(λ2 − λ3) (eq. (1)–(2)); the points are
    λ2,3 = [√((1 + λ1)² − 4 λ1 cos φ0) ± (1 − λ1)] / 2.  In both cases μmin = 0 there.

    References
    ----------
    .. [1] Sereda (2016), eq. (7)–(10) and Table 1.
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    l1a = as_float("l1", l1, problems)
    _raise(problems)
    top = l1_max(phi0)
    bad = ~np.isfinite(l1a) | (l1a < 0.0) | (l1a > top + TOL)
    if np.any(bad):
        raise SynthesisError(Problem(
            "l1", Text("errors.linkage.synthesis.lie_max_for",
                       {"top": top, "phi0": phi0,
                        "value": fmt_value(l1a[bad] if l1a.ndim else l1a)})))
    l1a = np.minimum(l1a, top)
    S, D = _boundary_sd(l1a, _c(phi0))
    big, small = (S + D) / 2.0, (S - D) / 2.0
    return np.stack([np.stack([big, small], axis=-1), np.stack([small, big], axis=-1)],
                    axis=-2)


@dataclass(frozen=True)
class FamilyArc:
    """The admissible arc of the family for one crank length.

    Attributes
    ----------
    l1 : float
        Crank length. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    radius : float
        R = √(λ1² + 1 − 2 λ1 cos φ0), eq. (6). [-]
    l2, l3 : ndarray
        Points of the arc between the two Kolchin points (crank-rockers and their
        change-point ends), from the larger λ2 to the smaller. [-]
    mu_min_deg : ndarray
        μmin of each point, 0 at both ends. [deg]
    """

    l1: float
    phi0_deg: float
    radius: float
    l2: np.ndarray = field(repr=False)
    l3: np.ndarray = field(repr=False)
    mu_min_deg: np.ndarray = field(repr=False)

    def l3_of(self, l2):
        """λ3 on the family circle for a given λ2 (eq. (6)); NaN off the circle. [-]"""
        return family_l3(self.l1, l2, self.phi0_deg)


def right_angle_family(l1, phi0_deg=30.0, n=181) -> FamilyArc:
    """The (λ2, λ3) relation of the family for crank ``l1``: the arc of the circle
    λ2² + λ3² = λ1² + 1 − 2 λ1 cos φ0 inside the region of existence.

    Parameters
    ----------
    l1 : float
        Crank length relative to the ground, 0 < λ1 ≤ λ1max. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    n : int
        Number of points on the arc.

    Returns
    -------
    FamilyArc

    References
    ----------
    .. [1] Sereda (2016), eq. (6) and Fig. 2 (the arcs of radius R = √(λ1 (λ1 − √3) + 1)).
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    l1f = _scalar("l1", l1, problems)
    if l1f is not None and not (math.isfinite(l1f) and l1f > 0):
        problems.append(Problem("l1", Text("errors.linkage.synthesis.positive_finite_length",
                                           {"l1": l1})))
    if not isinstance(n, (int, np.integer)) or n < 2:
        problems.append(Problem("n", Text("errors.linkage.synthesis.integer", {"n": n})))
    _raise(problems)
    pts = kolchin_line_points(l1f, phi0)
    R = float(family_radius(l1f, phi0))
    t0 = math.atan2(pts[0, 1], pts[0, 0])
    t1 = math.atan2(pts[1, 1], pts[1, 0])
    t = np.linspace(t0, t1, n)
    l2, l3 = R * np.cos(t), R * np.sin(t)
    l2[0], l3[0] = pts[0]
    l2[-1], l3[-1] = pts[1]
    c = _c(phi0)
    x = np.clip(min(l1f, 1.0) * (1.0 + abs(c)) / (l2 * l3), 0.0, 1.0)
    return FamilyArc(l1f, phi0, R, l2, l3, np.degrees(np.arccos(x)))


@dataclass(frozen=True)
class ExistenceRegion:
    """Region of existence of the ККМ-φ0 family in the (λ2, λ3) plane (Fig. 2).

    Attributes
    ----------
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    l1_max : float
        Largest admissible crank length (eq. (11); 0.1896 for φ0 = 30°). [-]
    l2, l3 : ndarray
        The closed boundary: the unit arc abc (λ1 = 0) from (1, 0) to (0, 1), then the
        curve cda back to (1, 0). [-]
    arc_l2, arc_l3 : ndarray
        The unit arc abc alone. [-]
    curve_l1, curve_l2, curve_l3 : ndarray
        The boundary curve cda (μmin = 0) and the crank length of each of its points;
        it runs from (1, 0) along the larger-λ2 branch to the point d at λ1max and back
        to (0, 1). [-]
    d : tuple of float
        The point d, where both intersections coincide (λ1 = λ1max). [-]
    kolchin_line : str
        Which of Kolchin's lines carries the curve (eq. (3), or (1)–(2) for φ0 > 90°).
    kolchin_numbers : tuple of int
        The numbers of those lines in the paper: ``(3,)``, or ``(1, 2)`` for φ0 > 90°.
    kkm5_l2, kkm5_l3, kkm7_l2, kkm7_l3 : ndarray or None
        For φ0 < 90°, the segments where the family coincides with ККМ-5 (λ3 = sin φ0,
        λ1 + λ2 = cos φ0: crank and coupler in one line at φ0) and with ККМ-7 (λ2 = sin φ0,
        λ1 + λ3 = cos φ0: crank and rocker parallel, on opposite sides of the line of
        centres at φ = −φ0), inside the region; ``None`` for φ0 ≥ 90° (no such member).
    """

    phi0_deg: float
    l1_max: float
    l2: np.ndarray = field(repr=False)
    l3: np.ndarray = field(repr=False)
    arc_l2: np.ndarray = field(repr=False)
    arc_l3: np.ndarray = field(repr=False)
    curve_l1: np.ndarray = field(repr=False)
    curve_l2: np.ndarray = field(repr=False)
    curve_l3: np.ndarray = field(repr=False)
    d: tuple
    kolchin_line: str
    kkm5_l2: np.ndarray | None = field(default=None, repr=False)
    kkm5_l3: np.ndarray | None = field(default=None, repr=False)
    kkm7_l2: np.ndarray | None = field(default=None, repr=False)
    kkm7_l3: np.ndarray | None = field(default=None, repr=False)
    kolchin_numbers: tuple = (3,)

    def contains(self, l2, l3):
        """True where (λ2, λ3) is inside the region or within :data:`TOL` of it."""
        l2 = np.asarray(l2, dtype=float)
        l3 = np.asarray(l3, dtype=float)
        return _region_contains(l2, l3, self.phi0_deg)


def _smallest_admissible_root(l2, l3, c, floor=0.0):
    """Crank lengths solving eq. (6) for (λ2, λ3), vectorised: the smallest root > ``floor``
    that satisfies Kolchin's inequalities within TOL, else NaN.  Also returns both roots."""
    rho2 = l2 ** 2 + l3 ** 2
    disc = c * c - 1.0 + rho2
    # within TOL of the circle of radius sin φ0 (where the two roots meet; the unit arc
    # itself when φ0 = 90°), the discriminant is 0
    disc = np.where((disc < 0) & (disc >= -2.0 * TOL * np.sqrt(rho2)), 0.0, disc)
    with np.errstate(invalid="ignore"):
        sq = np.where(disc >= 0.0, np.sqrt(np.maximum(disc, 0.0)), np.nan)
    # r_minus = c − sq without cancellation: (1 − ρ²)/(c + sq) when c + sq > 0.
    with np.errstate(invalid="ignore", divide="ignore"):
        r_minus = np.where(c + sq > 0.5 * abs(c) + np.finfo(float).tiny, (1.0 - rho2) / (c + sq), c - sq)
    r_plus = c + sq
    best = np.full(np.broadcast(l2, l3).shape, np.nan)
    for r in (r_plus, r_minus):  # later assignment (the smaller root) wins
        with np.errstate(invalid="ignore"):
            ok = (r > floor) & (_kolchin_margin(r, l2, l3) >= -TOL)
        best = np.where(ok, r, best)
    return best, r_minus, r_plus


def _region_contains(l2, l3, phi0_deg):
    # The unit arc (λ1 = 0) is part of the boundary: roots down to −TOL count.
    best, _, _ = _smallest_admissible_root(l2, l3, _c(phi0_deg), floor=-TOL)
    return np.isfinite(best) & (l2 >= 0) & (l3 >= 0)


def existence_region(phi0_deg=30.0, n=400) -> ExistenceRegion:
    """Boundary of the region of existence of the ККМ-φ0 family and λ1max.

    Parameters
    ----------
    phi0_deg : float
        Crank angle where μ = 90°, 0 < φ0 < 180. [deg]
    n : int
        Points on each branch of the boundary curve and on the unit arc.

    Returns
    -------
    ExistenceRegion

    Notes
    -----
    The region is bounded by the arc abc of the unit circle (λ1 = 0) and the curve cda
    swept by the intersections of the circles R = √(λ1² + 1 − 2 λ1 cos φ0),
    0 ≤ λ1 ≤ λ1max, with Kolchin's boundary line(s), on which μmin = 0.

    References
    ----------
    .. [1] Sereda (2016), eq. (9)–(11), Table 1 and Fig. 2.
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    if not isinstance(n, (int, np.integer)) or n < 3:
        problems.append(Problem("n", Text("errors.linkage.synthesis.integer_2", {"n": n})))
    _raise(problems)
    c, s = _c(phi0), math.sin(math.radians(phi0))
    top = l1_max(phi0)
    # λ1 = top (1 − u²): the boundary coordinates are smooth in u near the point d.
    u = np.linspace(1.0, 0.0, n)
    l1 = top * (1.0 - u ** 2)
    l1[-1] = top
    pts = kolchin_line_points(l1, phi0)
    big_l2, big_l3 = pts[:, 0, 0], pts[:, 0, 1]
    sm_l2, sm_l3 = pts[::-1, 1, 0], pts[::-1, 1, 1]
    curve_l1 = np.concatenate([l1, l1[::-1][1:]])
    curve_l2 = np.concatenate([big_l2, sm_l2[1:]])
    curve_l3 = np.concatenate([big_l3, sm_l3[1:]])
    curve_l2[[0, -1]], curve_l3[[0, -1]] = (1.0, 0.0), (0.0, 1.0)   # the ends a and c
    t = np.linspace(0.0, math.pi / 2.0, n)
    arc_l2, arc_l3 = np.cos(t), np.sin(t)
    arc_l2[-1], arc_l3[0] = 0.0, 0.0
    l2 = np.concatenate([arc_l2, curve_l2[::-1][1:]])
    l3 = np.concatenate([arc_l3, curve_l3[::-1][1:]])
    d = (float(pts[-1, 0, 0]), float(pts[-1, 0, 1]))
    line = ("1 + λ1 = λ2 + λ3 (eq. 3)" if c >= 0 else "1 − λ1 = ±(λ2 − λ3) (eq. 1–2)")
    kw = {"kolchin_numbers": (3,) if c >= 0 else (1, 2)}
    if c > 0:
        # ККМ-5: λ3 = sin φ0, λ2 = cos φ0 − λ1, from the unit arc (λ1 = 0) to the boundary
        # line 1 + λ1 = λ2 + λ3, i.e. λ2 = (1 + cos φ0 − sin φ0)/2.  ККМ-7 is its mirror.
        # Both segments are non-degenerate because sin φ0 + cos φ0 > 1 on (0°, 90°).
        seg = np.linspace(c, (1.0 + c - s) / 2.0, 50)
        kw.update(kkm5_l2=seg, kkm5_l3=np.full_like(seg, s),
                  kkm7_l2=np.full_like(seg, s), kkm7_l3=seg.copy())
    return ExistenceRegion(phi0, top, l2, l3, arc_l2, arc_l3, curve_l1, curve_l2, curve_l3,
                           d, line, **kw)


@dataclass(frozen=True)
class MuMinCurves:
    """μmin over λ1 for fixed coupler lengths (the paper's Fig. 3).

    Attributes
    ----------
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    l1 : ndarray, shape (n,)
        Crank lengths, 0 … λ1max. [-]
    l2 : ndarray, shape (m,)
        Coupler lengths, one curve each. [-]
    mu_min_deg : ndarray, shape (m, n)
        μmin (eq. (16)); NaN where the member is not a crank-rocker. [deg]
    l1_end : ndarray, shape (m,)
        Crank length where each curve reaches μmin = 0 (its end on the boundary). [-]
    """

    phi0_deg: float
    l1: np.ndarray = field(repr=False)
    l2: np.ndarray = field(repr=False)
    mu_min_deg: np.ndarray = field(repr=False)
    l1_end: np.ndarray = field(repr=False)


def mu_min_curves(phi0_deg=30.0, l2=tuple(np.round(np.arange(1, 10) / 10.0, 2)),
                  n=600) -> MuMinCurves:
    """μmin as a function of λ1 at constant λ2 (Fig. 3 of the paper).

    Parameters
    ----------
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    l2 : sequence of float
        Coupler lengths of the curves (the paper: 0.1 … 0.9). [-]
    n : int
        Number of λ1 values in 0 … λ1max; the exact end of each curve is added. [-]

    Returns
    -------
    MuMinCurves

    Notes
    -----
    The end of a curve solves μmin = 0, i.e. λ1² (1 + |c|)² = λ2² λ3² with λ3 from eq. (6):
    λ1² [(1 + |c|)² − λ2²] + 2 c λ2² λ1 − λ2² (1 − λ2²) = 0, its positive root.

    References
    ----------
    .. [1] Sereda (2016), eq. (16) and Fig. 3.
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    l2a = positive_lengths(problems, l2=l2).get("l2")
    _raise(problems)
    l2a = np.atleast_1d(l2a)
    c = _c(phi0)
    ends = np.array([_largest_l1_for_k(float(v), c, 1.0) for v in l2a])
    l1 = np.linspace(0.0, l1_max(phi0), n)
    l1 = np.unique(np.concatenate([l1, ends[np.isfinite(ends)]]))
    mu = family_mu_min_deg(l1[None, :], l2a[:, None], phi0)
    return MuMinCurves(phi0, l1, l2a, mu, ends)


def _largest_l1_for_k(l2, c, k):
    """Largest λ1 in (0, 1] with λ1 (1 + |c|) ≤ k λ2 λ3(λ1) on the family (μmin ≥ arccos k),
    or NaN.  Squared: a λ1² + b λ1 + e ≤ 0."""
    kk = (k * l2) ** 2
    a = (1.0 + abs(c)) ** 2 - kk
    b = 2.0 * c * kk
    e = -kk * (1.0 - l2 ** 2)
    if abs(a) < DEGENERATE_QUADRATIC_ATOL:
        roots = [-e / b] if b != 0 else []
    else:
        disc = b * b - 4.0 * a * e
        if disc < 0:
            return math.nan if a > 0 else 1.0
        sq = math.sqrt(disc)
        q = -0.5 * (b + math.copysign(sq, b) if b != 0 else sq)
        roots = sorted([q / a, e / q] if q != 0 else [0.0, 0.0])
    if a < 0:  # g ≤ 0 outside the roots: unbounded above; the crank must stay ≤ 1
        return 1.0
    pos = [r for r in roots if r > 0]
    return min(max(pos), 1.0) if pos else math.nan


# --------------------------------------------------------------------------- designs
@dataclass(frozen=True)
class Design:
    """A member of the ККМ-φ0 family (lengths relative to the ground).

    Attributes
    ----------
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    l1, l2, l3 : float
        Crank, coupler and rocker lengths. [-]
    mu_min_deg : float
        Smallest transmission angle over a turn. [deg]
    mu_min_at_deg : float
        Crank angle of μmin (180° for φ0 ≤ 90°, 0° for φ0 > 90°). [deg]
    grashof : GrashofType
        ``CRANK_ROCKER``, or ``CHANGE_POINT`` on the boundary (μmin = 0).
    method : str
        How the lengths were found (which design task).
    """

    phi0_deg: float
    l1: float
    l2: float
    l3: float
    mu_min_deg: float
    mu_min_at_deg: float
    grashof: GrashofType
    method: str = ""

    @property
    def mu_at_phi0_deg(self) -> float:
        """Transmission angle at φ0 (90° by construction, to rounding). [deg]"""
        return float(transmission_angle_deg(self.phi0_deg, self.l1, self.l2, self.l3))

    def lengths_m(self, ground_m):
        """Absolute lengths (crank, coupler, rocker, ground) for the given ground. [m]"""
        g = float(ground_m)
        return self.l1 * g, self.l2 * g, self.l3 * g, g

    def to_spec(self, ground_m, **mechanism):
        """The crank-rocker spec dict of this design; see :func:`to_spec`."""
        mechanism.setdefault("name", f"kkm-{self.phi0_deg:g}")
        return to_spec(self.l1, self.l2, self.l3, ground_m, **mechanism)

    def as_dict(self) -> dict:
        """Flat dict of the design (for a one-row table)."""
        return {"phi0_deg": self.phi0_deg, "l1": self.l1, "l2": self.l2, "l3": self.l3,
                "mu_min_deg": self.mu_min_deg, "mu_min_at_deg": self.mu_min_at_deg,
                "mu_at_phi0_deg": self.mu_at_phi0_deg, "grashof": str(self.grashof),
                "method": self.method}


def design(l1, l2, l3, phi0_deg=30.0, method="given") -> Design:
    """Check that (λ1, λ2, λ3) is a member of the ККМ-φ0 family and describe it.

    Parameters
    ----------
    l1, l2, l3 : float
        Crank, coupler, rocker relative to the ground. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    method : str
        Recorded in :attr:`Design.method`.

    Raises
    ------
    SynthesisError
        Non-positive lengths, φ0 out of range, the lengths off the family's circle
        (eq. (6), beyond :data:`TOL`) or outside the region of existence.

    References
    ----------
    .. [1] Sereda (2016), eq. (6), (13).
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    vals = [_scalar(k, v, problems) for k, v in (("l1", l1), ("l2", l2), ("l3", l3))]
    positive_lengths(problems, **{k: v for k, v in zip(("l1", "l2", "l3"), vals) if v is not None})
    _raise(problems)
    l1, l2, l3 = vals
    c = _c(phi0)
    resid = l2 * l2 + l3 * l3 - (l1 * (l1 - 2.0 * c) + 1.0)
    if abs(resid) > TOL:
        raise SynthesisError(Problem(
            "l1, l2, l3", Text("errors.linkage.synthesis.not_member_family",
                               {"l1": l1, "l2": l2, "l3": l3, "phi0": phi0, "resid": resid})))
    if not _kolchin_margin(l1, l2, l3) >= -TOL:
        t = grashof(l1, l2, l3)
        raise SynthesisError(Problem(
            "l1, l2, l3", Text("errors.linkage.synthesis.outside_region_existence_2",
                               {"l1": l1, "l2": l2, "l3": l3, "phi0": phi0,
                                "t": Text("linkage.grashof." + str(t).lower().replace("-", "_")),
                                "value": l1_max(phi0)})))
    mu, at = min_transmission_angle_deg(l1, l2, l3)
    return Design(phi0, l1, l2, l3, mu, at, _type_with_tol(l1, l2, l3), method)


def crank_length_for_right_angle(l2, l3, phi0_deg=30.0) -> float:
    """Crank length that makes μ = 90° at φ0 for coupler ``l2`` and rocker ``l3``.

    Parameters
    ----------
    l2, l3 : float
        Coupler and rocker lengths relative to the ground. [-]
    phi0_deg : float
        Crank angle where μ = 90°, 0 < φ0 < 180. [deg]

    Returns
    -------
    float
        The smallest positive root of λ1² − 2 λ1 cos φ0 + 1 − λ2² − λ3² = 0 that gives a
        crank-rocker (or a change point within :data:`TOL` of the boundary):
        λ1 = cos φ0 ∓ √(cos² φ0 − 1 + λ2² + λ3²). [-]

    Raises
    ------
    SynthesisError
        Non-positive lengths, φ0 out of range, no real or positive root, or no root that
        gives a crank-rocker ((λ2, λ3) outside the region of existence).

    References
    ----------
    .. [1] Sereda (2016), eq. (6): λ2² + λ3² = λ1 (λ1 − √3) + 1; first example: λ2 = 0.70,
       λ3 = 0.60 → λ1 = 0.09.
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    l2f, l3f = _scalar("l2", l2, problems), _scalar("l3", l3, problems)
    positive_lengths(problems, **{k: v for k, v in (("l2", l2f), ("l3", l3f)) if v is not None})
    _raise(problems)
    c = _c(phi0)
    best, r_minus, r_plus = (float(v) for v in _smallest_admissible_root(l2f, l3f, c))
    if math.isfinite(best):
        return best
    where = f"(λ2, λ3) = ({l2f:.6g}, {l3f:.6g})"
    rho2 = l2f * l2f + l3f * l3f
    if not math.isfinite(r_plus):
        why = Text("errors.linkage.synthesis.no_crank_length",
                   {"rho2": rho2, "sin2": 1 - c * c, "phi0": phi0})
    elif r_plus <= 0:
        why = Text("errors.linkage.synthesis.no_positive_root", {"a": r_minus, "b": r_plus})
    else:
        roots = [Text("errors.linkage.synthesis.root_gives",
                      {"r": r, "t": Text("linkage.grashof." + str(grashof(r, l2f, l3f))
                                         .lower().replace("-", "_"))})
                 for r in sorted({r_minus, r_plus}) if r > 0]
        roots = roots[0] if len(roots) == 1 else Text("errors.list2",
                                                       {"a": roots[0], "b": roots[1]})
        why = Text("errors.linkage.synthesis.no_root_crank_rocker", {"roots": roots})
    raise SynthesisError(Problem(
        "l2, l3", Text("errors.linkage.synthesis.outside_region_existence",
                       {"where": where, "phi0": phi0, "why": why,
                        "value": Text("errors.linkage.synthesis.line_sum" if c >= 0
                                      else "errors.linkage.synthesis.lines_diff")})))


def design_from_l2_l3(l2, l3, phi0_deg=30.0) -> Design:
    """First design task of the paper: pick (λ2, λ3) in the region, get λ1 from eq. (6).

    Parameters
    ----------
    l2, l3 : float
        Coupler and rocker lengths relative to the ground. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]

    Returns
    -------
    Design

    References
    ----------
    .. [1] Sereda (2016), practical example 1 to Fig. 2: λ2 = 0.70, λ3 = 0.60 → λ1 = 0.09.
    """
    l1 = crank_length_for_right_angle(l2, l3, phi0_deg)
    return design(l1, float(l2), float(l3), phi0_deg, method="given l2, l3")


def design_equal_l2_l3(l1, phi0_deg=30.0) -> Design:
    """Second design task: given λ1, take λ2 = λ3 on the family's circle.

    Parameters
    ----------
    l1 : float
        Crank length relative to the ground, 0 < λ1 ≤ λ1max. [-]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]

    Returns
    -------
    Design
        λ2 = λ3 = √((λ1² + 1 − 2 λ1 cos φ0) / 2); μmin by eq. (14).

    References
    ----------
    .. [1] Sereda (2016), practical example 2 to Fig. 2: λ1 = 0.146, λ2 = λ3 → 0.620; eq. (14).
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    l1f = _scalar("l1", l1, problems)
    if l1f is not None:
        positive_lengths(problems, l1=l1f)
    _raise(problems)
    top = l1_max(phi0)
    if l1f > top + TOL:
        raise SynthesisError(Problem(
            "l1", Text("errors.linkage.synthesis.not_exceed_max",
                       {"top": top, "phi0": phi0, "l1f": l1f})))
    l2 = float(family_radius(l1f, phi0)) / math.sqrt(2.0)
    return design(l1f, l2, l2, phi0, method="given l1, l2 = l3")


def design_for_mu_min(l2, mu_min_deg, phi0_deg=30.0, l1_step=None) -> Design:
    """Third design task: given λ2 and the required μmin, the largest λ1 and its λ3.

    Parameters
    ----------
    l2 : float
        Coupler length relative to the ground. [-]
    mu_min_deg : float
        Required minimum transmission angle, 0 ≤ μmin < 90. [deg]
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    l1_step : float, optional
        Round λ1 down to a multiple of this step, as a designer reading Fig. 3 does (the
        paper takes λ1 = 0.08 for an exact 0.0840); μmin then exceeds the requirement. [-]

    Returns
    -------
    Design
        λ1 the largest crank length with μmin ≥ the requirement, λ3 from eq. (6).

    Raises
    ------
    SynthesisError
        Bad arguments, or no member of the family with this λ2 reaches the μmin.

    Notes
    -----
    μmin ≥ μ* ⇔ λ1 (1 + |cos φ0|) ≤ cos μ* · λ2 λ3 with λ3² = λ1² − 2 λ1 cos φ0 + 1 − λ2²:
    a quadratic inequality in λ1 whose larger root is the answer (capped at λ1max).

    References
    ----------
    .. [1] Sereda (2016), eq. (16), Fig. 3 and practical example 2 to it: λ2 = 0.90,
       μmin ≥ 40° → λ1 = 0.08, λ3 = 0.24, μmin = 46°16′.
    """
    problems = []
    phi0 = _phi0(problems, phi0_deg)
    l2f = _scalar("l2", l2, problems)
    if l2f is not None:
        positive_lengths(problems, l2=l2f)
    mu = _scalar("mu_min_deg", mu_min_deg, problems)
    if mu is not None and not (math.isfinite(mu) and 0.0 <= mu < 90.0):
        problems.append(Problem("mu_min_deg", Text("errors.linkage.synthesis.angle_min",
                                                   {"mu_min_deg": mu_min_deg})))
    step = None
    if l1_step is not None:
        step = _scalar("l1_step", l1_step, problems)
        if step is not None and not (math.isfinite(step) and step > 0):
            problems.append(Problem("l1_step", Text("errors.linkage.synthesis.positive_step",
                                                    {"l1_step": l1_step})))
    _raise(problems)
    c = _c(phi0)
    top = l1_max(phi0)
    k = math.cos(math.radians(mu))
    l1 = _largest_l1_for_k(l2f, c, k)
    if math.isfinite(l1):
        l1 = min(l1, top)
    ok = math.isfinite(l1) and l1 > 0
    if ok:
        l3 = float(family_l3(l1, l2f, phi0))
        ok = (math.isfinite(l3) and l3 > 0 and _kolchin_margin(l1, l2f, l3) >= -TOL
              and l1 * (1 + abs(c)) <= k * l2f * l3 * (1 + ROUNDOFF_RTOL) + TOL)
    if not ok:
        grid = np.linspace(0.0, top, 4001)[1:]
        best = family_mu_min_deg(grid, l2f, phi0)
        if np.all(np.isnan(best)):
            hint = Text("errors.linkage.synthesis.no_member", {"l2": l2f, "phi0": phi0})
        else:
            i = int(np.nanargmax(best))
            hint = Text("errors.linkage.synthesis.best", {"l2": l2f, "mu": best[i],
                                                          "l1": grid[i]})
        raise SynthesisError(Problem(
            "mu_min_deg", Text("errors.linkage.synthesis.min_not_reachable",
                               {"mu": mu, "phi0": phi0, "l2f": l2f, "hint": hint})))
    method = f"given l2 and mu_min >= {mu:g} deg"
    if step is not None:
        n = math.floor(l1 / step * (1 + ROUNDOFF_RTOL))
        if n < 1:
            raise SynthesisError(Problem(
                "l1_step", Text("errors.linkage.synthesis.rounding_down_multiple",
                                {"l1": l1, "step": step})))
        l1 = n * step
        l3 = float(family_l3(l1, l2f, phi0))
        method += f", l1 rounded down to a multiple of {step:g}"
    return design(l1, l2f, l3, phi0, method=method)


# --------------------------------------------------------------------------- spec
def to_spec(l1, l2, l3, ground_m, **mechanism) -> dict:
    """A crank-rocker spec dict (the contract of ``linkage.load_spec``) for the lengths.

    Parameters
    ----------
    l1, l2, l3 : float
        Crank, coupler, rocker lengths relative to the ground. [-]
    ground_m : float
        Ground length |OC|; the other lengths are scaled by it. [m]
    **mechanism
        Further or overriding keys of the ``[mechanism]`` table (``name``,
        ``omega_rad_s``, ``assembly``, ``gravity_m_s2``, …).

    Returns
    -------
    dict
        ``{"mechanism": {...}, "links": {...}, "analysis": {...}}`` with the ground along +x
        (``ground_angle_deg = 0``), so that the crank angle φ of this module is the
        absolute crank angle ``phi_deg`` of :func:`linkage.analyze`; massless links and
        no loads (kinematics and transmission angle only); 12 positions, working stroke
        counter-clockwise.  Add masses and loads to the returned dict as needed.

    Raises
    ------
    SynthesisError
        A length is not positive and finite.
    """
    problems = []
    vals = {k: _scalar(k, v, problems) for k, v in
            (("l1", l1), ("l2", l2), ("l3", l3), ("ground_m", ground_m))}
    positive_lengths(problems, **{k: v for k, v in vals.items() if v is not None})
    _raise(problems)
    g = vals["ground_m"]
    mech = {
        "kind": "crank-rocker",
        "name": "kkm",
        "crank": vals["l1"] * g,
        "coupler": vals["l2"] * g,
        "rocker": vals["l3"] * g,
        "ground": g,
        "ground_angle_deg": 0.0,
        "assembly": 1,
        "omega_rad_s": 1.0,
        "epsilon_rad_s2": 0.0,
        "gravity_m_s2": 0.0,
    }
    mech.update(mechanism)
    return {
        "mechanism": mech,
        "analysis": {"positions": 12, "working_stroke": "ccw"},
    }
