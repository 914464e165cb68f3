"""Four-bar geometry: Grashof type, transmission angle μ(φ) and its closed-form minimum.

One home for the geometry that the mechanisms (:mod:`linkage.mechanisms`), the analysis
summary (:mod:`linkage.analysis`) and the synthesis (:mod:`linkage.synthesis`) share:

* :func:`rotatability_margin` (:func:`rotatability_residuals`, :func:`crank_turns_fully`):
  the one rotatability rule with its one tolerance
  (:data:`crankbase.tolerances.ROTATABILITY_RTOL`), used by :func:`grashof`, the
  mechanisms' ``check_rotatable`` and the synthesis region;
* :func:`grashof`: Grashof type of a four-bar (:class:`GrashofType`);
  :func:`slider_crank_type`: the same question for a crank-slider (rod vs crank + |e|);
* :func:`transmission_angle`: μ from the directions of the two links that meet at the
  output joint (the tables, at every position);
* :func:`transmission_angle_deg`: μ(φ) of a four-bar by the cosine theorem;
* :func:`min_transmission_angle_deg`, :func:`min_transmission_angle_slider_deg`: μmin over
  a full turn in closed form (where it occurs is known: on the line of centres for a
  four-bar, with the crank perpendicular to the guide for a crank-slider).

μ is always the acute angle (folded into 0…90°).

References
----------
.. [1] Артоболевский И. И. Теория механизмов и машин. 4-е изд. М.: Наука, 1988: Grashof's
   criterion s + l ≤ p + q for a link that turns fully, and the angle of transmission.
.. [2] Середа Н. А. Семейство кривошипно-коромысловых механизмов с максимумом угла
   передачи при угле поворота кривошипа, равном 30°. Известия Самарского научного центра
   РАН, 2016: eq. (4)–(5), (12) μ(φ) and (13) μmin on the line of centres.
"""
from __future__ import annotations

import enum
import math

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.tolerances import ROTATABILITY_RTOL, ROUNDOFF_RTOL

__all__ = ["GeometryError", "GrashofType", "SliderCrankType", "grashof",
           "rotatability_residuals", "rotatability_margin", "crank_turns_fully",
           "slider_rotatability_margin", "slider_crank_type", "transmission_angle",
           "transmission_angle_deg", "min_transmission_angle_deg", "min_transmission_angle_slider_deg"]


class GeometryError(SpecError):
    """Lengths that do not describe a four-bar (not positive, not finite), or a four-bar
    whose crank cannot turn where a full turn is needed.  A :class:`ValueError`."""


class GrashofType(str, enum.Enum):
    """Grashof type of a four-bar (s shortest, l longest, p, q the others).  Compares
    equal to its text (``GrashofType.CRANK_ROCKER == "crank-rocker"``)."""

    #: s + l < p + q and the crank (λ1) is the shortest link.
    CRANK_ROCKER = "crank-rocker"
    #: s + l < p + q and the ground is the shortest link (drag link).
    DOUBLE_CRANK = "double-crank"
    #: s + l < p + q and the coupler or the rocker is the shortest link.
    DOUBLE_ROCKER = "double-rocker"
    #: s + l = p + q (within the rotatability tolerance): the links can become collinear.
    CHANGE_POINT = "change-point"
    #: s + l > p + q: no link turns fully (triple rocker).
    NON_GRASHOF = "non-Grashof"

    def __str__(self) -> str:
        return self.value


class SliderCrankType(str, enum.Enum):
    """Whether the crank of a crank-slider turns fully: rod L against crank + |offset|."""

    #: L > r + |e|.
    ROTATABLE = "rotatable"
    #: L = r + |e| (within the rotatability tolerance): the rod stands perpendicular to
    #: the guide once.
    CHANGE_POINT = "change-point"
    #: L < r + |e|: the crank cannot turn fully.
    NON_ROTATABLE = "non-rotatable"

    def __str__(self) -> str:
        return self.value


# --------------------------------------------------------------------------- validation
def fmt_value(value) -> str:
    """A value for an error message: the number, or the first bad ones of an array."""
    a = np.asarray(value)
    if a.ndim == 0:
        return repr(float(a)) if a.dtype.kind in "fiub" else repr(value)
    bad = a.ravel()
    return f"an array ({a.size} values)" if bad.size > 4 else repr(bad.tolist())


def as_float(name, value, problems):
    """``value`` as a float array, or None with a problem recorded under ``name``."""
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        problems.append(Problem(name, Text("errors.linkage.fourbar.number", {"value": value})))
        return None
    return a


def positive_lengths(problems, **named):
    """Convert lengths to float arrays; record every non-finite or non-positive one."""
    out = {}
    for name, value in named.items():
        a = as_float(name, value, problems)
        if a is None:
            continue
        bad = ~np.isfinite(a) | (a <= 0)
        if np.any(bad):
            shown = value if a.ndim == 0 else a[bad].ravel()[:4].tolist()
            problems.append(Problem(name, Text("errors.linkage.fourbar.positive_finite_length",
                                               {"shown": shown})))
        out[name] = a
    return out


def _raise(problems):
    if problems:
        raise GeometryError(problems)


# --------------------------------------------------------------------------- Grashof
def rotatability_residuals(l1, l2, l3, l0=1.0, crank_rocker=False):
    """Residuals of the conditions for the crank to turn fully, ≥ 0 when they hold.

    The dyad closes at every crank angle when |λ2 − λ3| ≤ |AC| ≤ λ2 + λ3 over the whole
    range of |AC|, |λ0 − λ1| … λ0 + λ1: Grashof's s + l ≤ p + q with the crank or the
    ground shortest.  With ``crank_rocker`` the crank must also be the shorter of crank
    and ground (λ0 − λ1 in place of |λ0 − λ1|): Kolchin's three inequalities,
    eq. (1)–(3) of Sereda [2]_, the region of the crank-rockers.

    Parameters
    ----------
    l1, l2, l3, l0 : float or array_like
        Crank, coupler, rocker and ground lengths (one unit). [-] or [m]
    crank_rocker : bool
        The crank-rocker region (crank shorter than the ground).

    Returns
    -------
    tuple of three
        (λ2 + λ3 − λ0 − λ1, d − (λ2 − λ3), d − (λ3 − λ2)) with d = |λ0 − λ1| (or λ0 − λ1),
        in the unit of the lengths.
    """
    d = (l0 - l1) if crank_rocker else np.abs(l0 - l1)
    return (l2 + l3 - l0 - l1, d - (l2 - l3), d - (l3 - l2))


def rotatability_margin(l1, l2, l3, l0=1.0, crank_rocker=False):
    """The one rotatability rule: the signed distance, in the plane of (λ2, λ3) over the
    ground, to the nearest boundary of the crank's full turn.

    Returns
    -------
    float or ndarray
        min(:func:`rotatability_residuals`)/(√2·λ0): ≥ 0 when the crank turns fully;
        within ±``ROTATABILITY_RTOL`` of 0 a change-point mechanism (the links can become
        collinear), which counts as turning fully.  [-]
    """
    r = rotatability_residuals(l1, l2, l3, l0, crank_rocker)
    return np.minimum(np.minimum(r[0], r[1]), r[2]) / (math.sqrt(2.0) * l0)


def crank_turns_fully(l1, l2, l3, l0=1.0, crank_rocker=False):
    """True where :func:`rotatability_margin` ≥ −``ROTATABILITY_RTOL``."""
    return rotatability_margin(l1, l2, l3, l0, crank_rocker) >= -ROTATABILITY_RTOL


def grashof(l1, l2, l3, l0=1.0) -> GrashofType:
    """Grashof type of the four-bar with crank ``l1``, coupler ``l2``, rocker ``l3``,
    ground ``l0``.

    Parameters
    ----------
    l1, l2, l3, l0 : float
        Crank, coupler, rocker and ground lengths, all in the same unit (relative to the
        ground, or absolute). [-] or [m]

    Returns
    -------
    GrashofType
        With s the shortest, l the longest and p, q the other two links:
        ``CHANGE_POINT`` if s + l = p + q within the rotatability tolerance
        (|p + q − s − l| ≤ √2·``ROTATABILITY_RTOL``·λ0, the rule of
        :func:`rotatability_margin`); ``NON_GRASHOF`` if s + l > p + q beyond it;
        otherwise ``CRANK_ROCKER`` (crank shortest), ``DOUBLE_CRANK`` (ground shortest)
        or ``DOUBLE_ROCKER`` (coupler or rocker shortest).

    Raises
    ------
    GeometryError
        A length is not a positive finite number.

    References
    ----------
    .. [1] Grashof's criterion s + l ≤ p + q [1]_ (module references); with λ0 = 1 and the
       crank shortest it is equivalent to Kolchin's three inequalities, eq. (1)–(3) of [2]_
       (then p + q − s − l is the smallest of :func:`rotatability_residuals`).
    """
    problems = []
    named = positive_lengths(problems, l1=l1, l2=l2, l3=l3, l0=l0)
    for name, a in named.items():
        if a.ndim != 0:
            problems.append(Problem(name, Text("errors.linkage.fourbar.single_number",
                                               {"value": fmt_value(a)})))
    _raise(problems)
    links = [float(named[k]) for k in ("l0", "l1", "l2", "l3")]
    s, p, q, l = sorted(links)
    margin = (p + q - s - l) / (math.sqrt(2.0) * links[0])
    if abs(margin) <= ROTATABILITY_RTOL:
        return GrashofType.CHANGE_POINT
    if margin < 0:
        return GrashofType.NON_GRASHOF
    shortest = links.index(s)  # unique: equal shortest links cannot be strictly Grashof
    return (GrashofType.DOUBLE_CRANK, GrashofType.CRANK_ROCKER,
            GrashofType.DOUBLE_ROCKER, GrashofType.DOUBLE_ROCKER)[shortest]


def slider_rotatability_margin(crank, rod, offset=0.0):
    """The rotatability rule of a crank-slider: (L − r − |e|)/r, ≥ 0 when the crank turns
    fully (the rod reaches the guide line from every crank position); within
    ±``ROTATABILITY_RTOL`` a change point, which counts as turning fully.  [-]

    The same tolerance as :func:`rotatability_margin`; ``CrankSlider.check_rotatable``
    tests each side, L − r − e and L − r + e, against it."""
    return (rod - (crank + abs(offset))) / crank


def slider_crank_type(crank, rod, offset=0.0) -> SliderCrankType:
    """Whether the crank of a crank-slider turns fully.

    Parameters
    ----------
    crank, rod : float
        |OA| and |AB|. [m]
    offset : float
        Distance of the guide line from the crank pivot (either sign). [m]

    Returns
    -------
    SliderCrankType
        ``ROTATABLE`` if L > r + |e|, ``CHANGE_POINT`` if equal within the rotatability
        tolerance (:func:`slider_rotatability_margin` within ±``ROTATABILITY_RTOL``),
        else ``NON_ROTATABLE`` [1]_.
    """
    margin = slider_rotatability_margin(crank, rod, offset)
    if abs(margin) <= ROTATABILITY_RTOL:
        return SliderCrankType.CHANGE_POINT
    return SliderCrankType.ROTATABLE if margin > 0 else SliderCrankType.NON_ROTATABLE


# --------------------------------------------------------------------- transmission angle
def transmission_angle(e_out, e_in):
    """Acute angle between two link directions: the transmission angle μ at the joint
    where the coupler (direction ``e_in``) drives the output link (direction ``e_out``).

    Parameters
    ----------
    e_out, e_in : Vec or complex array_like
        Directions (any length) of the output link (the rocker; for a slider, the normal
        to the guide) and of the coupler.

    Returns
    -------
    ndarray
        μ = atan2(|e_out × e_in|, |e_out · e_in|) in [0, π/2]. [rad]

    Notes
    -----
    For a crank-slider μ is 90° minus the acute angle between rod and guide, i.e. the
    acute angle between the rod and the guide's normal [1]_.  atan2 keeps full precision
    near 90°, where arccos of the cosine theorem loses half the digits.
    """
    c = e_out.real * e_in.imag - e_out.imag * e_in.real
    d = e_out.real * e_in.real + e_out.imag * e_in.imag
    return np.arctan2(np.abs(c), np.abs(d))


def _cos_mu(phi_deg, l1, l2, l3, l0=1.0):
    """cos μ by the cosine theorem in the triangles OAC and ABC."""
    phi = np.radians(phi_deg)
    return (l2 ** 2 + l3 ** 2 - l1 ** 2 - l0 ** 2 + 2.0 * l1 * l0 * np.cos(phi)) / (2.0 * l2 * l3)


def _acute_deg(cos_mu, ok=True):
    """Acute angle of arccos(cos μ) in degrees, cos μ clipped to [−1, 1]; NaN where not
    ``ok``."""
    x = np.minimum(np.abs(cos_mu), 1.0)
    return np.where(ok, np.degrees(np.arccos(x)), np.nan)


def _assembles(phi_deg, l1, l2, l3, l0=1.0):
    """True where the dyad closes: |λ2 − λ3| ≤ |AC| ≤ λ2 + λ3 within √2·ROTATABILITY_RTOL·λ0,
    |AC| the diagonal from the crank pin to the rocker pivot: the rule of
    :func:`rotatability_margin` at one crank angle."""
    phi = np.radians(phi_deg)
    ac = np.sqrt(np.maximum(l0 ** 2 + l1 ** 2 - 2.0 * l0 * l1 * np.cos(phi), 0.0))
    tol = math.sqrt(2.0) * ROTATABILITY_RTOL * l0
    return (ac >= np.abs(l2 - l3) - tol) & (ac <= l2 + l3 + tol)


def transmission_angle_deg(phi_deg, l1, l2, l3, l0=1.0):
    """Acute transmission angle of a four-bar at crank angle φ, vectorised.

    Parameters
    ----------
    phi_deg : array_like
        Crank angle, counter-clockwise from the line of centres O→C. [deg]
    l1, l2, l3 : array_like
        Crank, coupler and rocker lengths (relative to the ground when ``l0 = 1``). [-]
    l0 : array_like, optional
        Ground length, in the unit of the others. [-]

    Returns
    -------
    ndarray
        μ folded into 0…90° (broadcast shape of the arguments); NaN where the linkage
        cannot be assembled at that crank angle (|AC| outside |λ2 − λ3| … λ2 + λ3 by more
        than √2·ROTATABILITY_RTOL·λ0). [deg]

    Notes
    -----
    cos μ = (λ2² + λ3² − λ1² − λ0² + 2 λ1 λ0 cos φ) / (2 λ2 λ3); the cosine theorem in the
    triangles OAC and ABC.  Assembly branch does not matter: both give the same μ.

    References
    ----------
    .. [1] [2]_ (module references), eq. (4)–(5) and (12).
    """
    problems = []
    n = positive_lengths(problems, l1=l1, l2=l2, l3=l3, l0=l0)
    phi = as_float("phi_deg", phi_deg, problems)
    if phi is not None and not np.all(np.isfinite(phi)):
        problems.append(Problem("phi_deg", Text("errors.linkage.fourbar.finite_crank_angles")))
    _raise(problems)
    args = (phi, n["l1"], n["l2"], n["l3"], n["l0"])
    return _acute_deg(_cos_mu(*args), _assembles(*args))


def mu_min_on_line_of_centres(l1, l2, l3, l0):
    """(μmin [deg], φ [deg]: 0 or 180, 180 on a tie) from the two positions on the line of
    centres, where cos μ, monotonic in cos φ, takes its extremes."""
    m0 = _acute_deg(_cos_mu(0.0, l1, l2, l3, l0))
    m180 = _acute_deg(_cos_mu(180.0, l1, l2, l3, l0))
    at180 = m180 <= m0 + ROUNDOFF_RTOL * 90.0
    return np.where(at180, m180, m0), np.where(at180, 180.0, 0.0)


def min_transmission_angle_deg(l1, l2, l3, l0=1.0):
    """Smallest acute transmission angle of a four-bar over a full crank turn, and where.

    Parameters
    ----------
    l1, l2, l3 : array_like
        Crank, coupler and rocker lengths (relative to the ground when ``l0 = 1``). [-]
    l0 : array_like, optional
        Ground length. [-]

    Returns
    -------
    mu_min_deg : ndarray or float
        min over φ of μ(φ). [deg]
    phi_deg : ndarray or float
        Crank angle of the minimum from the line of centres, 0° or 180° (cos μ is
        monotonic in cos φ, so the extremes sit on the line of centres); 180° on a
        tie. [deg]

    Raises
    ------
    GeometryError
        A length is not positive, or the crank cannot turn fully
        (:func:`crank_turns_fully`).

    References
    ----------
    .. [1] [2]_ (module references), eq. (13): μmin = arccos[λ1 (1 + √3/2) / (λ2 λ3)] at
       φ = 180° for the ККМ-30° family.
    """
    problems = []
    n = positive_lengths(problems, l1=l1, l2=l2, l3=l3, l0=l0)
    _raise(problems)
    args = (n["l1"], n["l2"], n["l3"], n["l0"])
    bad = ~crank_turns_fully(*args)
    if np.any(bad):
        raise GeometryError(Problem(
            "l1, l2, l3", Text("errors.linkage.fourbar.crank_cannot_turn",
                               {"value": fmt_value(n['l1']), "value2": fmt_value(n['l2']),
                                "value3": fmt_value(n['l3']), "value4": fmt_value(n['l0'])})))
    mu, where = mu_min_on_line_of_centres(*args)
    if mu.ndim == 0:
        return float(mu), float(where)
    return mu, where


def min_transmission_angle_slider_deg(crank, rod, offset=0.0):
    """Smallest transmission angle of a crank-slider over a full crank turn, and where.

    Parameters
    ----------
    crank, rod : float
        |OA| = r and |AB| = L, with L ≥ r + |e|. [m]
    offset : float
        Distance e of the guide line from the crank pivot, + to the left of the guide
        direction. [m]

    Returns
    -------
    mu_min_deg : float
        μmin = arccos[(r + |e|)/L]. [deg]
    phi_deg : float
        Crank angle of the minimum, from the guide direction: −90° (= 270°) for e ≥ 0,
        +90° for e < 0. [deg]

    Notes
    -----
    In guide coordinates the crank pin is at y_A = r·sin φ and the rod makes the angle
    β with the guide, sin β = (e − y_A)/L; μ = 90° − |β| is smallest where |e − y_A| is
    largest, r + |e|, with the crank perpendicular to the guide on the side away from
    the guide line [1]_.
    """
    x = min((crank + abs(offset)) / rod, 1.0)
    return math.degrees(math.acos(x)), (90.0 if offset < 0 else 270.0)
