"""A planar linkage as data: a driver and an ordered list of class II Assur groups.

The mechanism is a crank on the frame (the driver I(0,1), given ω and ε) followed by
groups of two links and three pairs, each attached to joints, points or guides of links
already solved (or of the frame), with its assembly branch:

=====  ==========================================================================
kind   links (local frames) and pairs
=====  ==========================================================================
RRR    two bars: the first from the outer joint A to the inner joint B (origin A,
       x → B), the second from the outer joint C to B (origin C, x → B)
RRP    a rod from A to the slider's pin B (origin A, x → B), the slider on a guide of
       the frame or of a moving link (origin B, x along the guide)
RPR    a block pinned at A sliding in the slot of a lever pivoted at C (both: x
       along the slot; block origin A, lever origin C): the crank-slotted-lever
PRP    two sliders pinned together at B, each on a guide (origin B, x along its guide)
RPP    a block pinned at A in the slot of a yoke that slides on a guide (block: origin
       A, x along the slot; yoke: origin on the guide line, x along the guide)
=====  ==========================================================================

:func:`solve` runs the group routines of :mod:`linkage.groups` (closed form, vectorised
over crank positions) in the order of the structure formula and keeps every joint's and
link's motion (:class:`ChainResult`); :func:`kinetostatics` goes from the last group back
to the driver: every pair's reaction and the driving moment Mур.  :func:`structure_formula`
writes the course's ``I(0,1) → II(2,3) → II(4,5)``; :func:`mobility` is Chebyshev's
``W = 3n − 2p₅ − p₄``.  :func:`from_mechanism` builds the chain of today's crank-rocker
or crank-slider (:mod:`linkage.mechanisms`): the same group functions in the same order,
so the same numbers bit for bit.

Reactions are keyed by the pair's two links as the course writes ``Rij``: ``(i, j)`` is
the force of link i on link j (``"frame"`` is the frame).

References
----------
.. [1] Артоболевский И. И. Теория механизмов и машин. 4-е изд. М.: Наука, 1988: the
   structure of mechanisms by Assur groups, Chebyshev's formula, the kinematics and
   kinetostatics group by group.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import AssemblyError, Problem, SpecError, Text
from crankbase.tolerances import ROTATABILITY_RTOL

from . import groups as g

__all__ = ["Link", "Guide", "Driver", "RRR", "RRP", "RPR", "PRP", "RPP", "Mechanism",
           "ChainResult", "Reaction", "ChainForces", "solve", "kinetostatics",
           "structure_formula", "mobility", "check_cycle", "from_mechanism", "FRAME"]

#: The name of the frame (стойка, link 0).
FRAME = "frame"


@dataclass(frozen=True)
class Link:
    """A moving link's inertia and named points.

    ``mass`` [kg], ``inertia`` J_S about the centre of mass [kg·m²], ``cg`` the centre of
    mass and ``points`` name → position, both in the link's local frame (set by its group,
    see the module's table) as complex numbers [m]."""

    mass: float = 0.0
    inertia: float = 0.0
    cg: complex = 0j
    points: dict = field(default_factory=dict)


@dataclass(frozen=True)
class Guide:
    """A straight guide on a link: the line through the local ``point`` [m] (on the frame:
    global) at the local ``angle`` [rad], shifted by ``offset`` [m] to the left of it."""

    link: str = FRAME
    point: complex = 0j
    angle: float = 0.0
    offset: float = 0.0


@dataclass(frozen=True)
class Driver:
    """I(0,1): the crank ``link`` turning about the frame joint ``pivot``; its pin
    ``joint`` at ``length`` [m] on its x axis (x axis at the crank angle φ)."""

    length: float
    link: str = "crank"
    pivot: str = "O"
    joint: str = "A"


@dataclass(frozen=True)
class RRR:
    """Two bars ``links`` = (AB, CB) of ``lengths`` [m]; ``joints`` = (A, B, C), A and C
    already solved, B the new inner joint; ``assembly`` +1 puts B left of A→C."""

    links: tuple
    joints: tuple
    lengths: tuple
    assembly: int = 1
    kind = "RRR"


@dataclass(frozen=True)
class RRP:
    """A rod ``links[0]`` = AB of ``length`` [m] and a slider ``links[1]`` pinned at B on
    ``guide``; ``joints`` = (A, B); ``assembly`` +1 puts B ahead of A along the guide."""

    links: tuple
    joints: tuple
    length: float
    guide: Guide = Guide()
    assembly: int = 1
    kind = "RRP"


@dataclass(frozen=True)
class RPR:
    """A block ``links[0]`` pinned at A sliding in the slot of the lever ``links[1]``
    pivoted at C; ``joints`` = (A, C); the slot's line at ``offset`` [m] left of C;
    ``assembly`` +1: the slot's x axis points from C towards A."""

    links: tuple
    joints: tuple
    offset: float = 0.0
    assembly: int = 1
    kind = "RPR"


@dataclass(frozen=True)
class PRP:
    """Two sliders ``links`` pinned together at the new joint ``joints[0]`` (B), each on
    its guide of ``guides``."""

    links: tuple
    joints: tuple
    guides: tuple
    kind = "PRP"
    assembly = 1


@dataclass(frozen=True)
class RPP:
    """A block ``links[0]`` pinned at ``joints[0]`` (A) in the slot of the yoke
    ``links[1]``, the yoke on ``guide``; the slot at ``slot_angle`` [rad] to the guide."""

    links: tuple
    joints: tuple
    guide: Guide = Guide()
    slot_angle: float = 0.5 * math.pi
    kind = "RPP"
    assembly = 1


@dataclass
class Mechanism:
    """A planar linkage: frame joints (name → global position [m], complex), the driver,
    the ordered class II groups and the moving links (name → :class:`Link`; a link not
    listed has no mass).  Construction checks the structure (:func:`mobility`, every
    group attached to what is already solved) and raises a keyed :class:`SpecError`."""

    frame: dict
    driver: Driver
    groups: list
    links: dict = field(default_factory=dict)
    name: str = ""

    def __post_init__(self):
        self.frame = {k: complex(v) for k, v in self.frame.items()}
        self.groups = list(self.groups)
        bad = [n for n in self.links if n not in self.link_names]
        if bad:
            raise SpecError([Problem(f"links.{n}", Text("errors.linkage.chain.unknown_link",
                                                        {"valid": ", ".join(self.link_names)}))
                             for n in bad])
        bad = [k for k, grp in enumerate(self.groups) if getattr(grp, "kind", None) not in _KINDS]
        if bad:
            raise SpecError([Problem(f"groups[{k}]", Text("errors.linkage.chain.kind",
                                                          {"valid": ", ".join(_KINDS)}))
                             for k in bad])
        bad = [(k, grp) for k, grp in enumerate(self.groups)
               if len(tuple(grp.links)) != 2 or len(tuple(grp.joints)) != _ARITY[grp.kind]
               or (grp.kind == "PRP" and len(tuple(grp.guides)) != 2)]
        if bad:
            raise SpecError([Problem(f"groups[{k}]", Text(
                "errors.linkage.chain.arity",
                {"kind": grp.kind, "joints": _ARITY[grp.kind],
                 "names": _JOINT_NAMES[grp.kind]})) for k, grp in bad])
        self.links = {n: self.links.get(n, Link()) for n in self.link_names}
        _check_structure(self)

    @property
    def link_names(self):
        """Moving links in the order of the structure formula (the crank first)."""
        names = [self.driver.link]
        for grp in self.groups:
            names += [n for n in grp.links if n not in names]
        return names


# --------------------------------------------------------------------------- structure


def mobility(mech: Mechanism):
    """Chebyshev's formula W = 3n − 2p₅ − p₄ of the chain: (W, n, p5, p4).

    n counts the distinct moving links, p₅ the lower pairs (the crank's revolute on the
    frame, three per group), p₄ the higher pairs (none in a linkage of Assur groups)."""
    n = len(mech.link_names)
    p5 = 1 + 3 * len(mech.groups)
    p4 = 0
    return 3 * n - 2 * p5 - p4, n, p5, p4


def structure_formula(mech: Mechanism, kinds: bool = False) -> str:
    """The course's structure formula ``I(0,1) → II(2,3) → II(4,5)``: the frame 0, the
    crank 1, the groups' links numbered in order (``kinds``: ``II RPR(2,3)``)."""
    num = {n: i + 1 for i, n in enumerate(mech.link_names)}
    parts = [f"I(0,{num[mech.driver.link]})"]
    for grp in mech.groups:
        a, b = (num[n] for n in grp.links)
        parts.append(f"II{' ' + grp.kind if kinds else ''}({a},{b})")
    return " → ".join(parts)


def _structure_problems(mech):
    """Every structural problem of the chain, as keyed problems."""
    probs = []
    W, n, p5, p4 = mobility(mech)
    if W != 1:
        probs.append(Problem("mechanism", Text("errors.linkage.chain.mobility",
                                               {"W": W, "n": n, "p5": p5, "p4": p4})))
    if mech.driver.pivot not in mech.frame:
        probs.append(Problem("driver.pivot", Text("errors.linkage.chain.pivot_not_frame",
                                                  {"joint": mech.driver.pivot})))
    # every name a group may attach to, and the group (or link) that defines it
    anywhere = set(mech.frame) | {mech.driver.joint}
    for grp in mech.groups:
        anywhere.update(_new_joints(grp))
    for lk in mech.links.values():
        anywhere.update(lk.points)
    solved = set(mech.frame) | {mech.driver.joint} | set(mech.links[mech.driver.link].points)
    links_done = {mech.driver.link}
    for k, grp in enumerate(mech.groups):
        where = f"groups[{k}]"
        label = structure_label(mech, k)
        for j in _outer_joints(grp):
            if j in solved:
                continue
            key = "unsolved_joint" if j in anywhere else "unknown_joint"
            probs.append(Problem(where, Text("errors.linkage.chain." + key,
                                             {"group": label, "joint": j})))
        for gd in _guides(grp):
            if gd.link != FRAME and gd.link not in links_done:
                probs.append(Problem(where, Text("errors.linkage.chain.unsolved_guide",
                                                 {"group": label, "link": gd.link})))
        for j in _new_joints(grp):
            if j in solved:
                probs.append(Problem(where, Text("errors.linkage.chain.joint_twice",
                                                 {"group": label, "joint": j})))
        solved.update(_new_joints(grp))
        for ln in grp.links:
            if ln == FRAME:
                probs.append(Problem(where, Text("errors.linkage.chain.frame_in_group",
                                                 {"group": label})))
            links_done.add(ln)
            solved.update(mech.links[ln].points)
    return probs


def structure_label(mech, k):
    """``II RPR(2,3)``: the k-th group as the structure formula names it."""
    num = {n: i + 1 for i, n in enumerate(mech.link_names)}
    grp = mech.groups[k]
    return f"II {grp.kind}({','.join(str(num.get(n, '?')) for n in grp.links)})"


def _check_structure(mech):
    probs = _structure_problems(mech)
    if probs:
        raise SpecError(probs)


_KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")
#: How many joint names each group kind takes, and which.
_ARITY = {"RRR": 3, "RRP": 2, "RPR": 2, "PRP": 1, "RPP": 1}
_JOINT_NAMES = {"RRR": "(A, B, C)", "RRP": "(A, B)", "RPR": "(A, C)", "PRP": "(B,)",
                "RPP": "(A,)"}


def _outer_joints(grp):
    return {"RRR": lambda: (grp.joints[0], grp.joints[2]),
            "RRP": lambda: (grp.joints[0],),
            "RPR": lambda: tuple(grp.joints[:2]),
            "PRP": lambda: (),
            "RPP": lambda: (grp.joints[0],)}.get(grp.kind, lambda: ())()


def _new_joints(grp):
    return {"RRR": lambda: (grp.joints[1],), "RRP": lambda: (grp.joints[1],),
            "PRP": lambda: (grp.joints[0],)}.get(grp.kind, lambda: ())()


def _guides(grp):
    if grp.kind in ("RRP", "RPP"):
        return (grp.guide,)
    if grp.kind == "PRP":
        return tuple(grp.guides)
    return ()


# --------------------------------------------------------------------------- kinematics


@dataclass
class ChainResult:
    """The motion of every joint and link of a chain at the crank angles ``phi``.

    Attributes
    ----------
    mech : Mechanism
    phi : ndarray
        Crank angles, ccw from +x. [rad]
    links : dict
        Link name → :class:`~linkage.groups.LinkMotion` (``theta``, ``omega``, ``eps``,
        ``point(local)``), the crank and every group's links.
    joints : dict
        Joint name → :class:`~linkage.groups.PointMotion` (``z``, ``v``, ``a`` as
        :class:`~linkage.groups.Vec`), the frame's joints, the crank pin, every group's
        inner joint.
    solutions : list
        Each group's solution (:class:`~linkage.groups.RRRSolution` …), in order: the
        sliding coordinates, relative velocities and accelerations, Coriolis terms.
    """

    mech: Mechanism
    phi: np.ndarray
    links: dict
    joints: dict
    solutions: list

    def point(self, name) -> g.PointMotion:
        """Motion of a joint or of a link's named point."""
        return _lookup(self, name)

    def omega(self, link):
        """ω of a link [rad/s] as an array over the positions."""
        return np.broadcast_to(self.links[link].omega, self.phi.shape)

    def eps(self, link):
        """ε of a link [rad/s²] as an array over the positions."""
        return np.broadcast_to(self.links[link].eps, self.phi.shape)


def _lookup(res, name):
    if name in res.joints:
        return res.joints[name]
    for ln, motion in res.links.items():
        local = res.mech.links[ln].points.get(name)
        if local is not None:
            return motion.point(local)
    raise KeyError(name)


def _frame_point(z):
    return g.PointMotion(z, 0j, 0j)


def _solve_group(res, grp):
    """One group's routine; returns (solution, {link: motion}, {joint: point})."""
    P = res.point
    if grp.kind == "RRR":
        A, B, C = grp.joints
        s = g.rrr(P(A), P(C), grp.lengths[0], grp.lengths[1], grp.assembly)
        return s, dict(zip(grp.links, (s.link3, s.link4))), {B: s.B}
    if grp.kind == "RRP":
        A, B = grp.joints
        gd = grp.guide
        if gd.link == FRAME:                         # today's routine (bit for bit)
            s = g.rrp(P(A), grp.length, gd.point, gd.angle, gd.offset, grp.assembly)
        else:
            s = g.rrp_guided(P(A), grp.length, _guide_link(res, gd), gd.point, gd.angle,
                             gd.offset, grp.assembly)
        return s, dict(zip(grp.links, (s.link3, s.link4))), {B: s.B}
    if grp.kind == "RPR":
        A, C = grp.joints
        s = g.rpr(P(A), P(C), grp.offset, grp.assembly)
        return s, dict(zip(grp.links, (s.block, s.lever))), {}
    if grp.kind == "PRP":
        (B,) = grp.joints
        g1, g2 = grp.guides
        s = g.prp(_guide_link(res, g1), _guide_link(res, g2), _shifted(g1), g1.angle,
                  _shifted(g2), g2.angle)
        return s, dict(zip(grp.links, (s.link2, s.link3))), {B: s.B}
    (A,) = grp.joints
    gd = grp.guide
    s = g.rpp(P(A), _guide_link(res, gd), _shifted(gd), gd.angle, grp.slot_angle)
    return s, dict(zip(grp.links, (s.block, s.yoke))), {}


def _guide_link(res, gd):
    return g.FRAME if gd.link == FRAME else res.links[gd.link]


def _shifted(gd):
    """The guide's local point moved by its offset to the left of its direction."""
    if not gd.offset:
        return complex(gd.point)
    return complex(gd.point) + gd.offset * 1j * complex(math.cos(gd.angle), math.sin(gd.angle))


def _assembly_measure(grp, s):
    """(h², scale²) of a group: h² < 0 where it cannot be assembled; |h²| ≈ 0 at a dead
    position, where its branch may flip; None for a group that always assembles."""
    if grp.kind == "RRR":
        return s.h2, grp.lengths[0] * grp.lengths[1]
    if grp.kind == "RRP":
        return s.h2, grp.length * grp.length
    if grp.kind == "RPR":
        return s.h2, None
    return None


def solve(mech: Mechanism, phi, omega=1.0, eps=0.0, *, check=True, out=None) -> ChainResult:
    """Kinematics of the chain at crank angles ``phi`` [rad]: driver, then the groups in
    order.

    Parameters
    ----------
    mech : Mechanism
    phi : array_like
        Crank angles, ccw from +x. [rad]
    omega, eps : float
        The crank's ω [rad/s] and ε [rad/s²].
    check : bool
        Raise :class:`AssemblyError` naming the crank angles where a group cannot be
        assembled.
    out : dict, optional
        Joint or named point → six float arrays (x, y, vx, vy, ax, ay over the positions,
        a table's rows): the crank pin and the links' named points are computed straight
        into them (:meth:`linkage.groups.LinkMotion.point`), as each link is solved; the
        same values as without.  A joint a group solves is not written.

    Returns
    -------
    ChainResult
    """
    phi = np.asarray(phi, dtype=float)
    d = mech.driver
    cr = g.crank(phi, omega, eps, d.length, mech.frame[d.pivot])
    todo = None
    if out is not None:
        todo = {p: rows for p, rows in out.items() if p not in mech.frame and p != d.joint}
    res = ChainResult(mech, phi, {d.link: cr},
                      {**{k: _frame_point(z) for k, z in mech.frame.items()},
                       d.joint: cr.point(d.length, None if out is None else out.get(d.joint))},
                      [])
    if todo:
        _points_into(res, {d.link: cr}, todo)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for k, grp in enumerate(mech.groups):
            s, links, joints = _solve_group(res, grp)
            if check:
                _check_assembled(mech, k, grp, s, phi)
            res.solutions.append(s)
            res.links.update(links)
            res.joints.update(joints)
            if todo:
                _points_into(res, links, todo)
    return res


def _points_into(res, links, todo):
    """The named points of the new ``links`` (name → motion, in the order of
    ``res.links``) that :func:`_lookup` finds on them computed into their rows ``todo``
    (name → six arrays; done ones dropped): on the first link that names the point, as
    :func:`_lookup` searches."""
    for p in list(todo):
        if p in res.joints:
            del todo[p]
            continue
        for ln, motion in links.items():
            local = res.mech.links[ln].points.get(p)
            if local is not None:
                motion.point(local, todo.pop(p))
                break


def _fmt_angles(phi):
    deg = np.degrees(np.asarray(phi, float)) % 360.0
    shown = ", ".join(f"{a:.6g}°" for a in deg[:8])
    return shown + (" …" if len(deg) > 8 else "")


def _check_assembled(mech, k, grp, s, phi):
    m = _assembly_measure(grp, s)
    if m is None:                  # two guides (PRP) or a slot and a guide (RPP) parallel
        det = np.abs(np.asarray(s.det, float) * np.ones(phi.shape))
        if not np.min(det, initial=np.inf) > ROTATABILITY_RTOL:
            _cannot_assemble(mech, k, phi, ~(det > ROTATABILITY_RTOL))
        return
    h2, sc = m
    if grp.kind == "RPR":          # h² = |AC|² − offset²; |AC| = 0 gives NaN
        sc = grp.offset * grp.offset
    if not np.min(h2, initial=np.inf) >= -ROTATABILITY_RTOL * sc:      # NaN fails too
        _cannot_assemble(mech, k, phi, ~(np.asarray(h2) >= -ROTATABILITY_RTOL * sc))


def _cannot_assemble(mech, k, phi, bad):
    where = np.atleast_1d(phi)[np.atleast_1d(bad)]
    raise AssemblyError(Text("errors.linkage.chain.cannot_assemble",
                             {"group": structure_label(mech, k),
                              "angles": _fmt_angles(where)}),
                        [float(a) for a in np.degrees(where) % 360.0])


def check_cycle(mech: Mechanism, n=3600, tol=1e-6):
    """Check a full turn of the crank on ``n`` positions: raise :class:`AssemblyError`
    where a group cannot be assembled, and where a group passes a dead position (its
    two links or its guide collinear, ``|h²|`` within ``tol`` of its scale, or its
    solution's determinant within ``tol``), where the assembly branch may flip."""
    phi = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    res = solve(mech, phi, 1.0, 0.0)
    for k, (grp, s) in enumerate(zip(mech.groups, res.solutions)):
        m = _assembly_measure(grp, s)
        if m is not None and m[1] is not None:
            flip = np.abs(m[0]) <= tol * m[1]
        else:
            det = np.asarray(s.det, float) * np.ones(phi.shape)
            scale = float(np.max(np.abs(det))) or 1.0
            flip = np.abs(det) <= tol * scale
        if np.any(flip):
            where = phi[flip]
            raise AssemblyError(Text("errors.linkage.chain.branch_flips",
                                     {"group": structure_label(mech, k),
                                      "angles": _fmt_angles(where)}),
                                [float(a) for a in np.degrees(where)])


# ----------------------------------------------------------------------- kinetostatics


@dataclass
class Reaction:
    """The reaction in one pair: the force of link ``by`` on link ``on``. [N, N·m]

    ``kind`` "R" (revolute at the joint ``joint``) or "P" (prismatic).  ``force`` is a
    :class:`~linkage.groups.Vec`; ``at`` its point of application (the pin, or for a
    prismatic pair the point the couple is taken about).  Revolute pairs of the RRR and
    RRP groups' outer joints carry ``n``, ``t``: the
    components along the ``on`` link's x axis and 90° ccw from it (the course's R23n,
    R23t).  Prismatic pairs carry ``normal`` (signed along i·u, u the guide's
    direction), ``couple`` about ``at``; :attr:`line` is where along the guide from
    ``at`` the normal force acts with no couple.
    """

    on: str
    by: str
    kind: str
    force: g.Vec
    at: g.Vec
    joint: str | None = None
    n: object = None
    t: object = None
    normal: object = None
    couple: object = None

    @property
    def line(self):
        """Prismatic pair: ``couple / normal``, the normal force's line along the guide
        from ``at``. [m]"""
        return None if self.normal is None else self.couple / self.normal


class _Reactions(dict):
    """(i, j) → :class:`Reaction` of link i on link j; the reverse order (j, i) is made
    on first use (the same pair, opposite force and couple)."""

    def __missing__(self, key):
        r = dict.get(self, (key[1], key[0]))
        if r is None:
            raise KeyError(key)
        self[key] = nr = _neg(r)
        return nr


@dataclass
class ChainForces:
    """Result of :func:`kinetostatics`: ``reactions`` (the pair (i, j) → :class:`Reaction`
    of link i on link j; either order may be asked), ``M_drive`` the driving
    (balancing) moment Mур on the crank, + ccw [N·m], and ``wrenches`` (link → the
    resultant of its own loads, weight and inertia and of the reactions of the groups
    attached to it later, :class:`~linkage.groups.Wrench`)."""

    reactions: dict
    M_drive: np.ndarray
    wrenches: dict

    def R(self, i, j):
        """Force of link i on link j (a :class:`~linkage.groups.Vec`). [N]"""
        return self.reactions[(i, j)].force


def _neg(r: Reaction) -> Reaction:
    return Reaction(r.by, r.on, r.kind, -r.force, r.at, r.joint, None, None,
                    None if r.normal is None else -r.normal,
                    None if r.couple is None else -r.couple)


def kinetostatics(res: ChainResult, forces=None, moments=None, gravity=9.81) -> ChainForces:
    """Reactions in every pair and the driving moment, group by group from the last to
    the driver.

    Parameters
    ----------
    res : ChainResult
    forces : dict, optional
        Link name → list of (force, global point) applied to it (Vec or complex; arrays
        over the positions or constants). [N, m]
    moments : dict, optional
        Link name → list of applied moments, + ccw. [N·m]
    gravity : float
        g along −y. [m/s²]

    Returns
    -------
    ChainForces

    Notes
    -----
    Each group's links carry their own loads, weight, d'Alembert inertia and the
    reactions of the groups attached to them later (already solved, applied with the
    opposite sign); the group's routine in :mod:`linkage.groups` gives its pairs'
    reactions.  The driver last: the frame's reaction at the pivot and Mур.
    """
    mech = res.mech
    forces = forces or {}
    moments = moments or {}
    ef = {n: list(forces.get(n, ())) for n in mech.link_names}
    em = {n: list(moments.get(n, ())) for n in mech.link_names}
    W = {}
    out = _Reactions()

    def wrench(n):
        lk = mech.links[n]
        W[n] = g.link_wrench(res.links[n], lk.mass, lk.inertia, lk.cg, gravity, ef[n], em[n])
        return W[n]

    def add(r: Reaction):
        out[(r.by, r.on)] = r
        if r.by != FRAME and r.by in ef and r.by not in W:      # on an earlier link
            out[(r.on, r.by)] = nr = _neg(r)
            ef[nr.on].append((nr.force, nr.at))
            if nr.couple is not None:
                em[nr.on].append(nr.couple)

    owner = _joint_owner(mech)
    for k in range(len(mech.groups) - 1, -1, -1):
        grp, s = mech.groups[k], res.solutions[k]
        l2, l3 = grp.links
        W2, W3 = wrench(l2), wrench(l3)
        if grp.kind == "RRR":
            A, B, C = grp.joints
            r = g.rrr_reactions(s, grp.lengths[0], grp.lengths[1], W2, W3)
            add(Reaction(l2, owner[A], "R", r.RA, s.link3.origin.z, A, r.RA_n, r.RA_t))
            add(Reaction(l2, l3, "R", r.RB, s.B.z, B))
            add(Reaction(l3, owner[C], "R", r.RC, s.link4.origin.z, C, r.RC_n, r.RC_t))
        elif grp.kind == "RRP":
            A, B = grp.joints
            r = g.rrp_reactions(s, grp.length, W2, W3)
            add(Reaction(l2, owner[A], "R", r.RA, s.link3.origin.z, A, r.RA_n, r.RA_t))
            add(Reaction(l2, l3, "R", r.RB, s.B.z, B))
            add(Reaction(l3, grp.guide.link, "P", r.RG, s.B.z, None, normal=r.RG_n,
                         couple=r.MG))
        elif grp.kind == "RPR":
            A, C = grp.joints
            r = g.rpr_reactions(s, W2, W3)
            add(Reaction(l2, owner[A], "R", r.RA, s.block.origin.z, A))
            add(Reaction(l2, l3, "P", s.lever.e.perp() * r.N, s.block.origin.z, None,
                         normal=r.N, couple=r.M))
            add(Reaction(l3, owner[C], "R", r.RC, s.lever.origin.z, C))
        elif grp.kind == "PRP":
            (B,) = grp.joints
            r = g.prp_reactions(s, W2, W3)
            g1, g2 = grp.guides
            add(Reaction(l2, g1.link, "P", s.link2.e.perp() * r.N1, s.B.z, None,
                         normal=r.N1, couple=r.M1))
            add(Reaction(l2, l3, "R", r.RB, s.B.z, B))
            add(Reaction(l3, g2.link, "P", s.link3.e.perp() * r.N2, s.B.z, None,
                         normal=r.N2, couple=r.M2))
        else:
            (A,) = grp.joints
            r = g.rpp_reactions(s, W2, W3)
            add(Reaction(l2, owner[A], "R", r.RA, s.block.origin.z, A))
            add(Reaction(l2, l3, "P", s.block.e.perp() * r.N, s.block.origin.z, None,
                         normal=r.N, couple=r.M))
            add(Reaction(l3, grp.guide.link, "P", s.yoke.e.perp() * r.NG, s.yoke.origin.z,
                         None, normal=r.NG, couple=r.MG))
    d = mech.driver
    cr = res.links[d.link]
    own = forces.get(d.link, ())
    W2 = g.link_wrench(cr, mech.links[d.link].mass, mech.links[d.link].inertia,
                       mech.links[d.link].cg, gravity, list(own), list(moments.get(d.link, ())))
    W[d.link] = W2
    extra_f = ef[d.link][len(own):]
    extra_m = em[d.link][len(moments.get(d.link, ())):]
    if len(extra_f) == 1 and not extra_m:       # one group on the crank: today's routine
        R32, zA = extra_f[0]
        dr = g.driver_reactions(cr, zA, R32, W2)
        R12, M = dr.R12, dr.M_drive
    else:
        zO = cr.origin.z
        F = W2.force
        M = -W2.moment_about(zO)
        for f, at in extra_f:
            F = F + f
            M = M - g.cross(g.Vec.of(at) - zO, f)
        for m in extra_m:
            M = M - m
        R12 = -F
    add(Reaction(d.link, FRAME, "R", R12, cr.origin.z, d.pivot))
    return ChainForces(out, M, W)


def _joint_owner(mech):
    """Joint or point name → the solved link (or the frame) the group's outer pair is on:
    the frame's joints, the crank pin on the crank, a named point on its link, a group's
    inner joint on the group's second link (the first link of a later group attached
    there pins to the second: the course's usual chain, e.g. the rocker's B)."""
    own = {j: FRAME for j in mech.frame}
    own[mech.driver.joint] = mech.driver.link
    for ln in mech.link_names:
        for p in mech.links[ln].points:
            own.setdefault(p, ln)
    for grp in mech.groups:
        for j in _new_joints(grp):
            own.setdefault(j, grp.links[1])
    return own


# --------------------------------------------------------------- today's mechanisms


def from_mechanism(mech, links=None) -> Mechanism:
    """The chain of today's :class:`~linkage.mechanisms.CrankRocker` (``I(0,1) →
    II RRR(2,3)``, frame joints O and C) or :class:`~linkage.mechanisms.CrankSlider`
    (``I(0,1) → II RRP(2,3)``, the guide on the frame), with the links ``crank``,
    ``coupler`` and ``rocker`` or ``slider`` and the joints O, A, B (C).

    ``links``: name → :class:`Link` (or a spec's :class:`~linkage.spec.LinkSpec`, whose
    ``mass``, ``inertia``, ``cg`` are read)."""
    links = {n: Link(float(lk.mass), float(lk.inertia), complex(lk.cg),
                     dict(getattr(lk, "points", {}) or {}))
             for n, lk in (links or {}).items()}
    drv = Driver(mech.l1, "crank", "O", "A")
    if mech.kind == "crank-rocker":
        grp = RRR(("coupler", "rocker"), ("A", "B", "C"), (mech.l2, mech.l3), mech.assembly)
        frame = {"O": mech.pivot, "C": mech.zC}
    else:
        grp = RRP(("coupler", "slider"), ("A", "B"), mech.l2,
                  Guide(FRAME, mech.pivot, mech.guide_angle, mech.offset), mech.assembly)
        frame = {"O": mech.pivot}
    return Mechanism(frame, drv, [grp], links, mech.kind)
