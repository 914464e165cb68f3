"""Velocity and acceleration plans, force polygons and the Zhukovsky lever, built from the
exact solution of :func:`linkage.analyze`.

Nothing here solves the mechanism again: every vector is a column of the analysis
(velocities and accelerations of the points, ω and ε of the links, weights, inertia
loads, reactions and their n/t components, Mур) divided by the plan's scale.  The plans
are what a student draws by hand in the course project (seed 000, §3.2–3.3 and §4.2 of
the ratchet-drive project; Artobolevsky 1988, ch. 4 and 13): the plan is built from the
pole in the order of the structure formula, so each vector of the graphical solution is
a segment with its start and end point in millimetres of the drawing.

Shared with :mod:`plans.chain_model` (any chain of class II groups), one construction
each: the data classes, :func:`round_scale` and the default scale of a plan
(:func:`scaled_plan`), the force polygons (:func:`force_polygon`), a load on Zhukovsky's
lever (:func:`lever_force`) and its closure (:func:`close_lever`), the balancing force
(:func:`balancing_force`), ω and ε read off the plans (:func:`angular_reading`) and the
positions (:func:`position_rows`).  The four-bar's own part reads the course columns of
:func:`linkage.analyze` into the textbook's velocity and acceleration plans, dyad and
crank polygons and lever loads; the chain's construction of the same mechanism
(:func:`linkage.analysis.as_chain`) gives the same segments under
:func:`plans.chain_model.fourbar_name` (``tests/test_plans_fourbar_chain.py``).

Conventions
-----------
* Plan coordinates are millimetres on paper, x to the right, y up, the pole at (0, 0);
  complex numbers ``x + iy`` as in :mod:`linkage.groups`.
* A scale μ is the value of one millimetre: μV in (m/s)/mm, μa in (m/s²)/mm, μF in N/mm
  (seed 000: μV = VA/pa).  The default is the *round* scale of the textbook: the
  smallest μ = m·10^k, m ∈ {1, 1.5, 2, 2.5, 3, 4, 5, 6, 8}, that keeps the reference
  vector (pa, πa, the largest force of the polygon) at most 150 mm long; since
  consecutive round values differ by at most 1.5×, that vector is then longer than
  100 mm (:func:`round_scale`).  When the whole plan would then be larger than
  :data:`MAX_PLAN_MM` (250 mm) in width or height (near a dead position, ω3 and the
  plan grow without bound while pa stays), the round scale that keeps it within
  250 mm is taken instead, as a student would shorten pa.
* The Zhukovsky lever draws every force from its point at one force scale of its own,
  the round scale that keeps its largest force at most :data:`LEVER_LONGEST_MM` long.
* The crank's polygon takes the balancing moment Mур as the textbook does: as the
  balancing force Fур at A ⟂ OA (:func:`balancing_force`, segment ``Fb``), so its R12
  is the analysis' R12 (Mур a couple) minus Fур.
* Segment names are ASCII (``pa``, ``ab``, ``a_n3``, ``n3_b``, ``R23t``, ``Fb``); the
  labels on the drawing are the textbook's: Russian p, a, b, s₃, π, n₃, Fур …; English o,
  a, b, s₃ for the velocity diagram and o′, a′, b′ … for the acceleration diagram
  (Khurmi & Gupta), Fb for Fур.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from linkage import groups as g
from linkage.columns import point_names
from linkage.course import course_of
from linkage.spec import LINK_NUMBER

from .errors import PlanError, Problem, Text

__all__ = ["Vector", "Plan", "LeverForce", "Lever", "PositionPlans", "round_scale",
           "build_plans", "balancing_force", "force_polygon", "scaled_plan", "lever_force",
           "angular_reading",
           "close_lever", "position_rows", "ROUND_MANTISSAS", "PLAN_KINDS", "SCALE_KINDS",
           "LEVER_LONGEST_MM", "MAX_PLAN_MM"]

#: Mantissas of the round scales (ГОСТ-like series used for drawing scales of plans).
ROUND_MANTISSAS = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)
#: Plan kinds, in the order of the course project.
PLAN_KINDS = ("velocity", "acceleration", "force_dyad", "force_crank")
#: Scales that :func:`build_plans` accepts: the plans', the Zhukovsky lever's forces and
#: the lever's own turned velocity plan (``lever_velocity``, default the velocity plan's).
SCALE_KINDS = PLAN_KINDS + ("lever", "lever_velocity")
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


#: Largest extent (width or height) of a plan at the default scale. [mm]
MAX_PLAN_MM = 250.0
#: Longest force arrow on the Zhukovsky lever at its default round force scale: half the
#: 150 mm of pa, so the arrows stay within the turned velocity plan's size. [mm]
LEVER_LONGEST_MM = 75.0


def _extent(plan):
    """Largest side of a plan's bounding box (0 → 1 for an all-zero plan). [mm]"""
    x0, y0, x1, y1 = plan.bbox()
    return max(x1 - x0, y1 - y0) or 1.0


def round_scale(value, longest_mm=150.0):
    """The textbook's round scale for a reference vector of magnitude ``value``.

    Parameters
    ----------
    value : float
        Magnitude of the reference vector (VA, aA, the largest force). [SI]
    longest_mm : float
        Longest drawn length allowed for it. [mm]

    Returns
    -------
    float
        The smallest m·10^k (m in :data:`ROUND_MANTISSAS`) with ``value/μ ≤ longest_mm``;
        then ``value/μ > longest_mm/1.5`` (100 mm for the default 150 mm). [SI/mm]
    """
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise PlanError([Problem("scale", Text("errors.plans.model.reference",
                                               {"value": value}))])
    target = value / longest_mm
    k = math.floor(math.log10(target))
    for kk in (k - 1, k, k + 1):
        for m in ROUND_MANTISSAS:
            mu = float(f"{m}e{kk}")          # exact decimal, no 3*0.1 artefacts
            if mu >= target * (1 - 1e-12):
                return mu
    return float(f"1e{k + 2}")  # pragma: no cover - unreachable


@dataclass(frozen=True)
class Vector:
    """One drawn vector of a plan.

    Attributes
    ----------
    plan : str
        ``velocity``, ``acceleration``, ``force_dyad``, ``force_crank``.
    name : str
        ASCII segment name (``pa``, ``ab``, ``a_n3``, ``R23t`` …), unique in its plan.
    quantity : str
        ASCII name of the quantity it represents (``V_A``, ``a_BA_n``, ``R23_t``).
    label_ru, label_en : str
        The vector's name on the drawing (textbook symbols).
    start, end : complex
        End points on the plan. [mm]
    value : float
        Magnitude of the quantity. [m/s, m/s², N]
    unit : str
    scale : float
        The plan's scale (value of 1 mm). [unit/mm]
    kind : str
        ``absolute``, ``relative``, ``normal``, ``tangential``, ``load``, ``reaction``.
    """

    plan: str
    name: str
    quantity: str
    label_ru: str
    label_en: str
    start: complex
    end: complex
    value: float
    unit: str
    scale: float
    kind: str

    @property
    def length_mm(self) -> float:
        return abs(self.end - self.start)

    def label(self, lang="ru") -> str:
        """Its label in the symbol set of ``lang`` (:attr:`crankbase.texts.Texts.symbols`)."""
        from crankbase.texts import texts

        return texts(lang).symbol(self.label_ru, self.label_en)


@dataclass
class Plan:
    """A velocity or acceleration plan, or a force polygon.

    Attributes
    ----------
    kind : str
    scale : float
        μ: value of one millimetre. [m/s per mm, m/s² per mm, N per mm]
    unit : str
        Unit of the values (``m/s``, ``m/s2``, ``N``).
    points : dict of str to complex
        Named points of the plan (the pole ``p``/``pi`` at 0 for the kinematic plans). [mm]
    point_labels : dict of str to (str, str)
        Russian and English label of each point.
    vectors : list of Vector
    polygons : list of list of (str, int)
        Vector equations of the plan: the signed sum of each list is zero
        (e.g. ``pa + ab − pb = 0``).
    """

    kind: str
    scale: float
    unit: str
    points: dict
    point_labels: dict
    vectors: list
    polygons: list = field(default_factory=list)

    def vector(self, name) -> Vector:
        for v in self.vectors:
            if v.name == name:
                return v
        raise KeyError(name)

    def closure(self):
        """Closure error of every polygon: |Σ ± vectors| over the largest of its vectors."""
        out = []
        for poly in self.polygons:
            vs = [(self.vector(n), s) for n, s in poly]
            total = sum(s * (v.end - v.start) for v, s in vs)
            big = max(v.length_mm for v, _ in vs)
            out.append(abs(total) / big if big > 0 else 0.0)
        return out

    def bbox(self):
        """(xmin, ymin, xmax, ymax) of the points and vector ends. [mm]"""
        zs = [v.start for v in self.vectors] + [v.end for v in self.vectors]
        zs += list(self.points.values())
        xs = [z.real for z in zs]
        ys = [z.imag for z in zs]
        return min(xs), min(ys), max(xs), max(ys)


@dataclass(frozen=True)
class LeverForce:
    """One force on the Zhukovsky lever.

    Attributes
    ----------
    name, label_ru, label_en : str
        ASCII name (``G3``, ``Fu3``, ``Mu3_B`` …) and drawing labels.
    point : str
        The point of the velocity plan it is applied at (``s3``, ``b`` …).
    at : complex
        Application point on the lever (velocity plan turned 90° clockwise). [mm]
    force : complex
        The force. [N]
    arm_mm : float
        Signed arm about the pole: moment / |force|, + counter-clockwise. [mm]
    moment_Nmm : float
        Moment about the pole on the lever, ``at × force``. [N·mm]
    """

    name: str
    label_ru: str
    label_en: str
    point: str
    at: complex
    force: complex
    arm_mm: float
    moment_Nmm: float


@dataclass
class Lever:
    """The Zhukovsky lever of one position.

    Attributes
    ----------
    forces : list of LeverForce
        Every external load, inertia loads and weights included; moments replaced by
        force couples at the ends of their link.
    balancing_force_N : float
        Fур at the crank pin (point a of the lever), perpendicular to pa, from the lever's
        balance of moments about the pole, + in the sense of a counter-clockwise Mур. [N]
    balancing_at : complex
        Point a on the lever. [mm]
    balancing_dir : complex
        Unit direction of a positive Fур (i·e2, perpendicular to OA).
    pa_mm : float
        Its arm, the length of pa. [mm]
    M_lever_Nm, M_kinetostatic_Nm : float
        Balancing moment Mур = Fур·lOA from the lever, and the kinetostatic one
        (``M_drive_Nm``), + ccw. [N·m]
    difference_percent : float
        100·(M_lever − M_kinetostatic)/|M_kinetostatic| (0 when both are 0).
    points : dict of str to complex
        The turned velocity plan's points. [mm]
    segments : list of tuple
        The turned velocity plan's segments: (name, start, end, label ru, label en). [mm]
    scale : float
        μF of the lever: every force is drawn from its point as an arrow |F|/μF mm long
        (:meth:`arrows`). [N/mm]
    F_kinetostatic_N : float
        Fур = Mур/lOA from the kinetostatic Mур (:func:`balancing_force`), same sign
        convention as ``balancing_force_N``. [N]
    plan_scale : float or None
        μV of the turned velocity plan the lever is drawn on: the velocity plan's own
        scale, or a coarser round one where the lever would not fit the sheet
        (:func:`plans.drawing.fit_plans`; Fур and Mур do not depend on it). [(m/s)/mm]
    """

    forces: list
    balancing_force_N: float
    balancing_at: complex
    balancing_dir: complex
    pa_mm: float
    M_lever_Nm: float
    M_kinetostatic_Nm: float
    difference_percent: float
    points: dict
    segments: list
    scale: float
    F_kinetostatic_N: float
    plan_scale: float | None = None

    @property
    def balancing_force(self) -> complex:
        """Fур from the lever as a vector. [N]"""
        return self.balancing_force_N * self.balancing_dir

    def arrows(self):
        """The force arrows of the lever at its scale :attr:`scale`, as
        :class:`Vector` (plan ``lever``): each load from its point, then ``Fb`` (Fур) at
        a; ``length_mm = |F|/μF``."""
        out = [Vector("lever", f.name, f.name, f.label_ru, f.label_en, f.at,
                      f.at + f.force / self.scale, abs(f.force), "N", self.scale, "load")
               for f in self.forces]
        Fb = self.balancing_force
        out.append(Vector("lever", "Fb", "Fb", "Fур", "Fb", self.balancing_at,
                          self.balancing_at + Fb / self.scale, abs(Fb), "N", self.scale,
                          "balancing"))
        return out


@dataclass
class PositionPlans:
    """All plans of one position.

    Attributes
    ----------
    position : int or None
        Number in the plan of positions (None for an explicit crank angle).
    phi_deg : float
        Crank angle. [°]
    plans : dict of str to Plan
        ``velocity``, ``acceleration``, ``force_dyad``, ``force_crank``.
    lever : Lever
    angular : list of dict
        Angular velocities and accelerations read off the plans: ``quantity``,
        ``segment``, ``plan``, ``link_length_m``, ``value`` (+ ccw), ``unit``.
    kind : str
        ``crank-rocker`` or ``crank-slider``.
    geometry : dict of str to complex
        Joint positions of the mechanism at this position (O, A, B, C …). [m]
    fixed : tuple of str
        The scales the caller fixed (keys of ``scales``: ``velocity``, ``force_dyad``,
        ``lever`` …); :func:`plans.drawing.fit_plans` never changes them.
    driver : tuple of str
        The crank's pivot and pin as the spec names them (``("O", "A")`` for a four-bar;
        a chain's ``pivot`` and ``pin``): where Fур acts and what it is perpendicular to.
    """

    position: int | None
    phi_deg: float
    kind: str
    plans: dict
    lever: Lever
    angular: list
    geometry: dict
    fixed: tuple = ()
    driver: tuple = ("O", "A")

    @property
    def tag(self) -> str:
        """``5`` for position 5, ``phi37.5`` for an explicit angle."""
        return str(self.position) if self.position is not None else f"phi{self.phi_deg:g}"


# ----------------------------------------------------------------------------- helpers


def _row(df, i, name):
    return float(df[name].iat[i])


def _c(df, i, p, what):
    """Complex column pair of point ``p``: what in {"", "v", "a"}."""
    sx = {"": ("_x_m", "_y_m"), "v": ("_vx_m_s", "_vy_m_s"), "a": ("_ax_m_s2", "_ay_m_s2")}
    x, y = sx[what]
    return complex(_row(df, i, p + x), _row(df, i, p + y))


def _sub(name: str) -> str:
    """``s3`` → ``s₃`` (digits as subscripts)."""
    return name.translate(_SUB)


def force_polygon(kind, items, mu, *, inner=(), split=0, rest=()) -> Plan:
    """A force polygon: the forces of ``items`` head to tail from the pole at the scale
    ``mu``, their sum closing (the first polygon); each ``inner`` force (a group's inner
    reaction, R43 or R32) from the end of the first ``split`` items, which it closes with
    the items named in ``rest`` (the other component of a split reaction: R23n) as one
    link's own polygon.  The vertices of the chain are the plan's points ``k0``, ``k1`` …

    One construction of the polygons of the four-bar's dyad and crank
    (:func:`build_plans`) and of any chain's groups and crank
    (:func:`plans.chain_model.build_chain_plans`).

    Parameters
    ----------
    kind : str
        The plan's kind (``force_dyad``, ``force_crank``, ``force_2_3`` …).
    items, inner : sequence of tuple
        ``(name, quantity, label ru, label en, force, kind)``; force [N] as ``x + iy``.
    mu : float
        μF, the value of one millimetre. [N/mm]
    split : int
        How many ``items`` the ``inner`` forces start after.
    rest : sequence of str
        Names of items that close an inner force's polygon after it.

    Returns
    -------
    Plan
    """
    P = Plan(kind, mu, "N", {}, {}, [])
    z = 0j
    ends = [z]
    for name, quantity, lru, len_, F, vkind in items:
        w = F / mu
        P.vectors.append(Vector(kind, name, quantity, lru, len_, z, z + w, abs(F), "N", mu,
                                vkind))
        z = z + w
        ends.append(z)
    P.polygons.append([(it[0], 1) for it in items])
    for name, quantity, lru, len_, F, vkind in inner:
        z = ends[split]
        P.vectors.append(Vector(kind, name, quantity, lru, len_, z, z + F / mu, abs(F), "N",
                                mu, vkind))
        P.polygons.append([(it[0], 1) for it in items[:split]] + [(name, 1)]
                          + [(n, 1) for n in rest])
    for k, z in enumerate(ends):
        P.points[f"k{k}"] = z
    return P


def scaled_plan(build, reference_mm, fixed=None) -> Plan:
    """A plan at a fixed scale or at the textbook's default one.

    ``build(μ)`` is the plan at the scale μ; without ``fixed`` the scale is the round
    scale (:func:`round_scale`) that keeps the reference vector (``reference_mm`` of the
    plan at μ = 1: pa, πa, a polygon's largest force) at most 150 mm long, coarser when
    the whole plan would then be wider or higher than :data:`MAX_PLAN_MM`.  One rule for
    every plan of the four-bar and of a chain.
    """
    if fixed:
        return build(fixed)
    unit = build(1.0)
    mu = max(round_scale(reference_mm(unit)), round_scale(_extent(unit), MAX_PLAN_MM))
    return build(mu)


def lever_force(name, label_ru, label_en, point, v, F, mu) -> LeverForce:
    """A force ``F`` [N] applied at a point of velocity ``v`` [m/s] on Zhukovsky's lever:
    at ``−i·v/μV`` mm (the velocity plan of scale ``mu`` turned 90° clockwise), its
    moment about the pole ``at × F`` [N·mm] and its signed arm.  One rule for the
    four-bar's and a chain's loads."""
    at = complex(-1j * v / mu)
    F = complex(F)
    m = float(g.cross(at, F))
    size = abs(F)
    return LeverForce(name, label_ru, label_en, point, at, F, m / size if size != 0 else 0.0,
                      m)


# ------------------------------------------------------------------------------ builder


def _link_motions(spec, K, i):
    """The links at row ``i`` as :class:`linkage.groups.LinkMotion` (for points of loads)."""
    zero = 0j
    O = g.PointMotion(0j, zero, zero)
    A = g.PointMotion(_c(K, i, "A", ""), _c(K, i, "A", "v"), _c(K, i, "A", "a"))
    B = g.PointMotion(_c(K, i, "B", ""), _c(K, i, "B", "v"), _c(K, i, "B", "a"))
    phi = math.radians(_row(K, i, "phi_deg"))
    th3 = math.radians(_row(K, i, "theta3_deg"))
    links = {"crank": g.LinkMotion(O, complex(math.cos(phi), math.sin(phi)), spec.omega,
                                   spec.epsilon),
             "coupler": g.LinkMotion(A, complex(math.cos(th3), math.sin(th3)),
                                     _row(K, i, "omega3_rad_s"), _row(K, i, "eps3_rad_s2"))}
    if course_of(spec).angular:     # a rocker turns about the fixed C, a slider slides
        th4 = math.radians(_row(K, i, "theta4_deg"))
        e4 = complex(math.cos(th4), math.sin(th4))
        C = g.PointMotion(B.z - spec.rocker * e4, zero, zero)
        links["rocker"] = g.LinkMotion(C, e4, _row(K, i, "omega4_rad_s"),
                                       _row(K, i, "eps4_rad_s2"))
    else:
        u = complex(math.cos(spec.ground_angle), math.sin(spec.ground_angle))
        links["slider"] = g.LinkMotion(B, u, 0.0, 0.0)
    return links


def _velocity_plan(spec, K, i, mu, pts):
    P = Plan("velocity", mu, "m/s", {"p": 0j}, {"p": ("p", "o")}, [])
    rocker = course_of(spec).angular        # the fixed C of a rocker sits at the pole
    if rocker:
        P.point_labels["p"] = ("p, o, c", "o, c")
    else:
        P.point_labels["p"] = ("p, o", "o")
    vA, vB = _c(K, i, "A", "v"), _c(K, i, "B", "v")
    a, b = vA / mu, vB / mu
    P.points.update(a=a, b=b)
    P.point_labels.update(a=("a", "a"), b=("b", "b"))
    # relative velocity of B about A from the coupler's rotation: V_BA = iω3·(B − A)
    rBA = _c(K, i, "B", "") - _c(K, i, "A", "")
    vBA = 1j * _row(K, i, "omega3_rad_s") * rBA
    V = P.vectors
    V.append(Vector("velocity", "pa", "V_A", "pa", "oa", 0j, a, abs(vA), "m/s", mu, "absolute"))
    V.append(Vector("velocity", "ab", "V_BA", "ab", "ab", a, a + vBA / mu, abs(vBA), "m/s", mu,
                    "relative"))
    V.append(Vector("velocity", "pb", "V_B", "pb", "ob", 0j, b, abs(vB), "m/s", mu,
                    "absolute"))
    P.polygons.append([("pa", 1), ("ab", 1), ("pb", -1)])
    for pname in pts:
        if pname in ("A", "B") or (pname == "S4" and not rocker):
            continue  # the slider translates: V_S4 = V_B
        v = _c(K, i, pname, "v")
        key = pname.lower()
        P.points[key] = v / mu
        P.point_labels[key] = (_sub(key), _sub(key))
        V.append(Vector("velocity", f"p{key}", f"V_{pname}", "p" + _sub(key), "o" + _sub(key),
                        0j, v / mu, abs(v), "m/s", mu, "absolute"))
    return P


def _acceleration_plan(spec, K, i, mu, pts):
    # two constructions of the course: the RRR's B about A and about the fixed C, the
    # RRP's B about A and along the guide
    rocker = course_of(spec).angular
    P = Plan("acceleration", mu, "m/s2", {"pi": 0j},
             {"pi": ("π, o, c" if rocker else "π, o", "o′, c′" if rocker else "o′")}, [])
    V = P.vectors
    U = "m/s2"
    zA, zB = _c(K, i, "A", ""), _c(K, i, "B", "")
    aA, aB = _c(K, i, "A", "a"), _c(K, i, "B", "a")
    a, b = aA / mu, aB / mu
    P.points.update(a=a, b=b)
    P.point_labels.update(a=("a", "a′"), b=("b", "b′"))
    V.append(Vector("acceleration", "pi_a", "a_A", "πa", "o′a′", 0j, a, abs(aA), U, mu,
                    "absolute"))
    if spec.epsilon != 0:   # a_A = a_AO^n + a_AO^t
        an = -spec.omega ** 2 * zA
        n2 = an / mu
        P.points["n2"] = n2
        P.point_labels["n2"] = ("n₂", "n₂′")
        V.append(Vector("acceleration", "pi_n2", "a_AO_n", "πn₂", "o′n₂′", 0j, n2, abs(an), U,
                        mu, "normal"))
        at = 1j * spec.epsilon * zA
        V.append(Vector("acceleration", "n2_a", "a_AO_t", "n₂a", "n₂′a′", n2, n2 + at / mu,
                        abs(at), U, mu, "tangential"))
        P.polygons.append([("pi_n2", 1), ("n2_a", 1), ("pi_a", -1)])
    # B about A: a_BA^n = −ω3²·(B − A) (towards A), a_BA^t = iε3·(B − A)
    rBA = zB - zA
    w3, e3 = _row(K, i, "omega3_rad_s"), _row(K, i, "eps3_rad_s2")
    an3 = -w3 * w3 * rBA
    at3 = 1j * e3 * rBA
    n3 = a + an3 / mu
    P.points["n3"] = n3
    P.point_labels["n3"] = ("n₃", "n₃′")
    V.append(Vector("acceleration", "a_n3", "a_BA_n", "an₃", "a′n₃′", a, n3, abs(an3), U, mu,
                    "normal"))
    V.append(Vector("acceleration", "n3_b", "a_BA_t", "n₃b", "n₃′b′", n3, n3 + at3 / mu,
                    abs(at3), U, mu, "tangential"))
    V.append(Vector("acceleration", "pi_b", "a_B", "πb", "o′b′", 0j, b, abs(aB), U, mu,
                    "absolute"))
    V.append(Vector("acceleration", "ab", "a_BA", "ab", "a′b′", a, b, abs(aB - aA), U, mu,
                    "relative"))
    P.polygons.append([("pi_a", 1), ("a_n3", 1), ("n3_b", 1), ("pi_b", -1)])
    P.polygons.append([("pi_a", 1), ("ab", 1), ("pi_b", -1)])
    if rocker:   # B about C: a_BC^n = −ω4²·(B − C), a_BC^t = iε4·(B − C)
        th4 = math.radians(_row(K, i, "theta4_deg"))
        rBC = spec.rocker * complex(math.cos(th4), math.sin(th4))
        w4, e4 = _row(K, i, "omega4_rad_s"), _row(K, i, "eps4_rad_s2")
        an4 = -w4 * w4 * rBC
        at4 = 1j * e4 * rBC
        n4 = an4 / mu
        P.points["n4"] = n4
        P.point_labels["n4"] = ("n₄", "n₄′")
        V.append(Vector("acceleration", "pi_n4", "a_BC_n", "πn₄", "o′n₄′", 0j, n4, abs(an4), U,
                        mu, "normal"))
        V.append(Vector("acceleration", "n4_b", "a_BC_t", "n₄b", "n₄′b′", n4, n4 + at4 / mu,
                        abs(at4), U, mu, "tangential"))
        P.polygons.append([("pi_n4", 1), ("n4_b", 1), ("pi_b", -1)])
    for pname in pts:
        if pname in ("A", "B") or (pname == "S4" and not rocker):
            continue
        acc = _c(K, i, pname, "a")
        key = pname.lower()
        P.points[key] = acc / mu
        P.point_labels[key] = (_sub(key), _sub(key) + "′")
        V.append(Vector("acceleration", f"pi_{key}", f"a_{pname}", "π" + _sub(key),
                        "o′" + _sub(key) + "′", 0j, acc / mu, abs(acc), U, mu, "absolute"))
    return P


def _ext_forces(spec, lname, F, i):
    """External forces on a link (spec loads and a slider's resistance): list of
    (ascii name, label, force [N], local point)."""
    out = []
    k = 0
    for ld in spec.loads:
        if ld.link != lname or ld.kind != "force":
            continue
        k += 1
        n = LINK_NUMBER[lname]
        out.append((f"F{n}_{k}", f"F{_sub(str(n))}.{k}", ld.force, ld.at))
    if lname == "slider":
        fr = _row(F, i, "F_res_N")
        if fr != 0.0:
            u = complex(math.cos(spec.ground_angle), math.sin(spec.ground_angle))
            out.append(("Fres", "Fпс", fr * u, 0j))
    return out


def _ext_moments(spec, lname, F, i):
    """External couples on a link: list of (ascii name, label ru, label en, moment [N·m])."""
    out = []
    k = 0
    for ld in spec.loads:
        if ld.link == lname and ld.kind == "moment":
            k += 1
            n = LINK_NUMBER[lname]
            out.append((f"M{n}_{k}", f"M{_sub(str(n))}.{k}", f"M{_sub(str(n))}.{k}", ld.moment))
    if lname == "rocker":
        mr = _row(F, i, "M_res_Nm")
        if mr != 0.0:
            out.append(("Mres", "Mпс", "Mr", mr))
    return out


def _weight(spec, lname):
    return -1j * spec.links[lname].mass * spec.gravity


def _loads_of(spec, lname, F, i):
    """Force loads of one link in the textbook's order: G, Fu, external forces.
    Items: (name, quantity, label ru, label en, force, kind, local point or None=S)."""
    n = LINK_NUMBER[lname]
    ns = _sub(str(n))
    items = []
    ls = spec.links[lname]
    if ls.mass != 0 and spec.gravity != 0:
        items.append((f"G{n}", f"G{n}", f"G{ns}", f"G{ns}", _weight(spec, lname), "load", None))
    if ls.mass != 0:
        Fu = complex(_row(F, i, f"Fu{n}_x_N"), _row(F, i, f"Fu{n}_y_N"))
        items.append((f"Fu{n}", f"Fu{n}", f"Fи{ns}", f"Fi{ns}", Fu, "load", None))
    for name, lab, force, at in _ext_forces(spec, lname, F, i):
        lab_en = "Fr" if name == "Fres" else lab
        items.append((name, name, lab, lab_en, force, "load", at))
    return items


def _force_dyad(spec, K, F, i, mu):
    # the force polygon of the dyad: a rocker's R14 in its two components along and
    # across the rocker, a slider's R14 whole (its line is the guide's normal)
    course = course_of(spec)
    rocker, out = course.angular, course.output
    th3 = math.radians(_row(K, i, "theta3_deg"))
    e3 = complex(math.cos(th3), math.sin(th3))
    R23t = _row(F, i, "R23_t_N") * 1j * e3
    R23n = _row(F, i, "R23_n_N") * e3
    loads3 = _loads_of(spec, "coupler", F, i)
    loads4 = _loads_of(spec, out, F, i)
    items = [("R23t", "R23_t", "R₂₃ᵗ", "R₂₃ᵗ", R23t, "reaction")]
    items += [(n, q, lr, le, f, k) for n, q, lr, le, f, k, _ in loads3]
    n3 = len(items)
    items += [(n, q, lr, le, f, k) for n, q, lr, le, f, k, _ in loads4]
    if rocker:
        th4 = math.radians(_row(K, i, "theta4_deg"))
        e4 = complex(math.cos(th4), math.sin(th4))
        items.append(("R14t", "R14_t", "R₁₄ᵗ", "R₁₄ᵗ", _row(F, i, "R14_t_N") * 1j * e4,
                      "reaction"))
        items.append(("R14n", "R14_n", "R₁₄ⁿ", "R₁₄ⁿ", _row(F, i, "R14_n_N") * e4, "reaction"))
    else:
        items.append(("R14", "R14", "R₁₄", "R₁₄",
                      complex(_row(F, i, "R14_x_N"), _row(F, i, "R14_y_N")), "reaction"))
    items.append(("R23n", "R23_n", "R₂₃ⁿ", "R₂₃ⁿ", R23n, "reaction"))
    # R43 closes link 3's own polygon: from the end of its last load to the start of R23n
    R43 = complex(_row(F, i, "R43_x_N"), _row(F, i, "R43_y_N"))
    return force_polygon("force_dyad", items, mu,
                         inner=[("R43", "R43", "R₄₃", "R₄₃", R43, "reaction")], split=n3,
                         rest=("R23n",))


def balancing_force(M_Nm, zA):
    """The balancing force Fур that replaces the balancing moment Mур on the crank.

    Fур is applied at the crank pin A perpendicular to the crank OA, so that its moment
    about O is Mур: ``OA × Fур = Mур``, hence |Fур| = |Mур|/lOA and
    ``Fур = Mур·i·OA/lOA²`` (seed 000 §4, the force analysis of the initial link;
    Artobolevsky, Теория механизмов и машин, 1988, §13).

    Parameters
    ----------
    M_Nm : float
        The balancing moment Mур on the crank, + counter-clockwise. [N·m]
    zA : complex
        The crank pin relative to the pivot O (x + iy). [m]

    Returns
    -------
    complex
        Fур. [N]
    """
    return M_Nm * 1j * zA / (abs(zA) ** 2)


def _force_crank(spec, K, F, i, mu):
    """The crank's polygon as the textbook builds it: the balancing moment Mур applied as
    the force Fур at A ⟂ OA (:func:`balancing_force`), so R32 + G2 + Fu2 (+ applied
    forces) + Fур + R12 = 0 closes at R12.  R12 here is the frame's reaction with Fур at
    A: the analysis' R12 (Mур a couple) minus Fур."""
    R32 = -complex(_row(F, i, "R23_x_N"), _row(F, i, "R23_y_N"))
    Fb = balancing_force(_row(F, i, "M_drive_Nm"), _c(K, i, "A", ""))
    R12 = complex(_row(F, i, "R12_x_N"), _row(F, i, "R12_y_N")) - Fb
    items = [("R32", "R32", "R₃₂", "R₃₂", R32, "reaction")]
    items += [(n, q, lr, le, f, k) for n, q, lr, le, f, k, _ in _loads_of(spec, "crank", F, i)]
    items.append(("Fb", "Fb", "Fур", "Fb", Fb, "balancing"))
    items.append(("R12", "R12_Fb", "R₁₂", "R₁₂", R12, "reaction"))
    return force_polygon("force_crank", items, mu)


def _lever(spec, K, F, i, vplan: Plan, scale=None):
    """Zhukovsky's lever: the velocity plan turned 90° clockwise; a force F applied at a
    point of velocity v sits at −i·v/μV and its moment about the pole is v·F/μV, its
    power over μV.  Σ moments + Fур·pa = 0 gives Fур, and Mур = Fур·lOA.  The forces
    are drawn at the lever's own round force scale (``scale``, default from the largest
    force with :data:`LEVER_LONGEST_MM`).

    References: Artobolevsky, Теория механизмов и машин, 1988, §13 (рычаг Жуковского);
    seed 000 §4 (the same loads: Gi, Fui, Mui, Mпс)."""
    mu = vplan.scale
    links = _link_motions(spec, K, i)
    forces = []

    def add(name, lru, len_, pname, v, Fv):
        forces.append(lever_force(name, lru, len_, pname, v, Fv, mu))

    ends = {"crank": ("o", "a"), "coupler": ("a", "b"),
            "rocker": ("c", "b"), "slider": ("b", "b")}
    lengths = {"crank": spec.crank, "coupler": spec.coupler, "rocker": spec.rocker}
    for lname in spec.link_names:
        link = links[lname]
        n = LINK_NUMBER[lname]
        ls = spec.links[lname]
        S = link.point(ls.cg)
        for name, _q, lru, len_, Fv, _k, at in _loads_of(spec, lname, F, i):
            if at is None:
                add(name, lru, len_, f"s{n}", S.v, Fv)
            else:
                P = link.point(at)
                add(name, lru, len_, name.lower(), P.v, Fv)
        # couples: the inertia moment and external moments, each replaced by a pair of
        # forces ±M/l perpendicular to the link at its two joints (a slider does not turn)
        couples = []
        if lname != "slider" and ls.inertia != 0:
            couples.append((f"Mu{n}", f"Mи{_sub(str(n))}", f"Mi{_sub(str(n))}",
                            _row(F, i, f"Mu{n}_Nm")))
        couples += _ext_moments(spec, lname, F, i)
        if lname == "slider":
            continue
        if len(couples) > 1:
            # the couples of one link are one couple (their sum), as the textbook draws
            # them: separate pairs would lie on one line at the same joints
            names, lrus, lens, Ms = zip(*couples)
            couples = [("+".join(names), "+".join(lrus), "+".join(lens), sum(Ms))]
        l_ = lengths[lname]
        first = link.origin
        second = link.point(l_)
        perp = 1j * link.e
        for name, lru, len_, M in couples:
            f = M / l_ * perp
            p1, p2 = ends[lname]
            add(f"{name}_{p2}", f"F({lru})", f"F({len_})", p2, second.v, f)
            add(f"{name}_{p1}", f"F({lru})", f"F({len_})", p1, first.v, -f)
    vA, zA = _c(K, i, "A", "v"), _c(K, i, "A", "")
    return close_lever(forces, vplan, zA, vA, spec.crank, _row(F, i, "M_drive_Nm"), scale)


def close_lever(forces, vplan: Plan, zA, vA, crank_length, M_kin, scale=None,
                round_scale_of=None) -> Lever:
    """Close Zhukovsky's lever of one position: the balancing force Fур at the crank
    pin's point a of the velocity plan turned 90° clockwise (``−i·vA/μV`` mm), ⟂ OA, whose
    moment about the pole, Fур·(a × i·e2), balances the loads' moments (``forces``:
    :class:`LeverForce`, each ``moment_Nmm`` about the pole); Mур = Fур·lOA [N·m, + ccw],
    compared with the kinetostatic ``M_kin`` (its difference in % of |M_kin|); the plan's
    points and vectors turned onto the lever.  ``zA`` is the crank pin relative to the
    crank's pivot O [m].  The force scale: ``scale`` [N/mm] if given, else
    ``round_scale_of(forces, a, Fур, points)`` if given, else the textbook's round scale of the largest
    force (:func:`round_scale`, :data:`LEVER_LONGEST_MM`).  One construction for the
    four-bar (:func:`build_plans`) and any chain (:mod:`plans.chain_model`)."""
    mu = vplan.scale
    rot = -1j
    e2 = zA / abs(zA)                               # along OA
    at_a = rot * vA / mu
    total = sum(fc.moment_Nmm for fc in forces)
    arm_a = g.cross(at_a, 1j * e2)                  # signed, |arm| = pa [mm]
    Fb = -total / arm_a + 0.0                       # + 0.0: no −0.0 without loads
    M_lever = Fb * crank_length                     # Mур = Fур·lOA, + ccw
    pa = abs(vA) / mu
    F_kin_N = (balancing_force(M_kin, zA) / (1j * e2)).real + 0.0
    if M_kin != 0:
        diff = 100.0 * (M_lever - M_kin) / abs(M_kin)
    else:
        diff = 0.0 if M_lever == 0 else math.copysign(math.inf, M_lever)
    points = {k: rot * z for k, z in vplan.points.items()}
    segments = [(v.name, rot * v.start, rot * v.end, v.label_ru, v.label_en)
                for v in vplan.vectors]
    if scale is None and round_scale_of is not None:
        scale = round_scale_of(forces, at_a, Fb * 1j * e2, points)
    if scale is None:
        # the lever's force scale: the textbook's round scale of its largest force
        big = max([abs(fc.force) for fc in forces] + [abs(Fb)])
        scale = round_scale(big or 1.0, LEVER_LONGEST_MM)
    return Lever(forces, Fb, at_a, 1j * e2, pa, M_lever, M_kin, diff, points, segments,
                 scale, F_kin_N, mu)


def _angular(spec, K, i, vplan, aplan):
    """ω and ε of the links read off the plans (seed 000: ω3 = V_BA/l_AB, ε3 = a_BA^t/l_AB)."""
    rows = [("omega3", "velocity", "ab", spec.coupler, _row(K, i, "omega3_rad_s"), "rad/s"),
            ("eps3", "acceleration", "n3_b", spec.coupler, _row(K, i, "eps3_rad_s2"),
             "rad/s2")]
    if course_of(spec).angular:       # ω4, ε4 of a rocker from the plans' segments
        rows += [("omega4", "velocity", "pb", spec.rocker, _row(K, i, "omega4_rad_s"), "rad/s"),
                 ("eps4", "acceleration", "n4_b", spec.rocker, _row(K, i, "eps4_rad_s2"),
                  "rad/s2")]
    return [angular_reading(q, vplan if plan == "velocity" else aplan, seg, length, exact,
                            unit)
            for q, plan, seg, length, exact, unit in rows]


def angular_reading(quantity, plan: Plan, segment, length_m, exact, unit) -> dict:
    """A link's ω or ε read off a plan, as the student does (seed 000: ω3 = V_BA/l_AB,
    ε3 = aᵗ_BA/l_AB): the length of ``segment`` times the plan's scale over the link's
    length ``length_m`` [m]; ``exact`` is the analysis' signed value (+ ccw).  One
    reading for the four-bar's and a chain's links.

    Returns
    -------
    dict
        ``quantity``, ``plan``, ``segment``, ``link_length_m``, ``length_mm``, ``value``
        (≥ 0), ``signed_value``, ``unit``, ``scale``.
    """
    vec = plan.vector(segment)
    return {"quantity": quantity, "plan": plan.kind, "segment": segment,
            "link_length_m": length_m, "length_mm": vec.length_mm,
            "value": vec.length_mm * plan.scale / length_m, "signed_value": exact,
            "unit": unit, "scale": plan.scale}


def build_plans(result, positions=None, *, scales=None, crank_angles_deg=None):
    """Plans of the chosen positions of an analysed mechanism.

    Parameters
    ----------
    result : linkage.AnalysisResult
        From :func:`linkage.analyze` with the course tables (the default).
    positions : iterable of int or "all", optional
        Position numbers of the plan of positions (default: all rows of ``result``).
    scales : dict, optional
        Fixed scales: ``velocity`` [(m/s)/mm], ``acceleration`` [(m/s²)/mm],
        ``force_dyad``, ``force_crank``, ``lever`` [N/mm], ``lever_velocity`` (the
        velocity plan the lever is drawn on) [(m/s)/mm]; missing ones are the
        textbook's round scales (:func:`round_scale`; pa, πa and the largest force of a
        polygon ≤ 150 mm, the largest force on the lever ≤ :data:`LEVER_LONGEST_MM`).
    crank_angles_deg : ignored unless ``result`` was analysed at explicit angles; then
        ``positions`` selects rows by their 1-based order.

    Returns
    -------
    list of PositionPlans

    Raises
    ------
    PlanError
        Statics (ω = 0: no velocity plan), a position that is not in the result, a scale
        that is not a positive finite number, or missing course-table columns.
    """
    spec = result.spec
    K, F = result.kinematics, result.forces
    problems = []
    if spec.omega == 0:
        problems.append("mechanism.omega_rad_s: 0 (statics); velocity and acceleration plans "
                        "and the lever need a turning crank")
    if "Fu3_x_N" not in F.columns:
        problems.append("analysis: run linkage.analyze with course_tables=True (the plans "
                        "need the inertia loads)")
    scales = dict(scales or {})
    for k, v in scales.items():
        if k not in SCALE_KINDS:
            problems.append(f"scales.{k}: unknown plan; valid: {', '.join(SCALE_KINDS)}")
        elif v is not None and not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            problems.append(f"scales.{k}: got {v!r}; must be a positive number")
    if problems:
        raise PlanError(problems)
    rows = position_rows(K, positions)
    pos_col = K["position"]
    numbered = pos_col.notna().all()
    pts = list(point_names(spec))
    out = []
    for i in rows:
        vals = [K[c].iat[i] for c in ("A_vx_m_s", "omega3_rad_s")] + [F["M_drive_Nm"].iat[i]]
        if not np.all(np.isfinite(np.asarray(vals, float))):
            problems.append(f"position {pos_col.iat[i]}: a singular (dead) position; its "
                            "velocities and forces are not finite, no plan can be drawn")
            continue
        # the textbook's round scale from the reference vector, coarser when the whole
        # plan would be larger than MAX_PLAN_MM
        def scale_of(kind, build, ref):
            return scaled_plan(build, ref, scales.get(kind))

        vplan = scale_of("velocity", lambda m: _velocity_plan(spec, K, i, m, pts),
                         lambda p: p.vector("pa").length_mm)
        aplan = scale_of("acceleration", lambda m: _acceleration_plan(spec, K, i, m, pts),
                         lambda p: p.vector("pi_a").length_mm)
        dyad = scale_of("force_dyad", lambda m: _force_dyad(spec, K, F, i, m),
                        lambda p: max(v.length_mm for v in p.vectors if v.name != "R43")
                        or 1.0)
        crank = scale_of("force_crank", lambda m: _force_crank(spec, K, F, i, m),
                         lambda p: max(v.length_mm for v in p.vectors) or 1.0)
        lplan = vplan
        if scales.get("lever_velocity"):            # the lever on a plan of its own scale
            lplan = _velocity_plan(spec, K, i, scales["lever_velocity"], pts)
        lever = _lever(spec, K, F, i, lplan, scales.get("lever"))
        geo = {"O": 0j, "A": _c(K, i, "A", ""), "B": _c(K, i, "B", "")}
        if course_of(spec).angular:           # the rocker's pivot C on the frame
            geo["C"] = complex(spec.ground * math.cos(spec.ground_angle),
                               spec.ground * math.sin(spec.ground_angle))
        for pname in pts:
            geo[pname] = _c(K, i, pname, "")
        pos = None if not numbered else int(pos_col.iat[i])
        out.append(PositionPlans(pos, _row(K, i, "phi_deg"), spec.kind,
                                 {"velocity": vplan, "acceleration": aplan,
                                  "force_dyad": dyad, "force_crank": crank},
                                 lever, _angular(spec, K, i, vplan, aplan), geo,
                                 tuple(k for k in SCALE_KINDS if scales.get(k))))
    if problems:
        raise PlanError(problems)
    return out


def position_rows(K, positions) -> list:
    """The row indices of the analysis table ``K`` at the given ``positions`` (the
    course's numbers of the ``position`` column, or 1-based rows when the table has no
    numbers; ``None`` or ``"all"``: every row).

    Raises
    ------
    PlanError
        A position the analysis does not have (each named, with the valid range).
    """
    pos_col = K["position"]
    numbered = pos_col.notna().all()
    if positions is None or positions == "all":
        return list(range(len(K)))
    rows, problems = [], []
    for p in positions:
        if numbered:
            hit = np.flatnonzero((pos_col == int(p)).to_numpy(dtype=bool, na_value=False))
        else:
            hit = [int(p) - 1] if 1 <= int(p) <= len(K) else []
        if len(hit) == 0:
            valid = f"1…{int(pos_col.max())}" if numbered and len(K) else f"1…{len(K)}"
            problems.append(Problem("positions",
                                    Text("errors.plans.model.position_not_analysis",
                                         {"p": p, "valid": valid})))
        else:
            rows.append(int(hit[0]))
    if problems:
        raise PlanError(problems)
    return rows
