"""Assur-group routines: the driver (crank), the RRR and the RRP dyad.

Kinematics and kinetostatics of each basic group, closed form and vectorised over arrays
of crank positions.  Planar vectors are complex numbers ``z = x + iy``; a link direction
is the unit complex ``e = exp(iθ)``.  Everything is SI (m, s, rad, kg, N, N·m).

A point ``r`` (local coordinates, complex) fixed on a link whose reference point moves
with ``z0, v0, a0`` and which turns with ``θ, ω, ε`` has

    z = z0 + r·e,   v = v0 + iω·r·e,   a = a0 + (iε − ω²)·r·e.

Mechanisms are assembled from these routines in the order of their structure formula
``I(1,2) → II(3,4)``: kinematics driver first, then the dyad; forces dyad first (it is
statically determinate on its own), then the driver, which yields the balancing
(driving) moment.

References
----------
.. [1] Artobolevsky, I. I. Теория механизмов и машин. Moscow: Nauka, 1988, ch. 4 (the
   kinematics of class-II groups) and ch. 13 (kinetostatics by Assur groups).
.. [2] 孙桓 等. 机械原理 (Theory of machines), ch. 11: kinetostatics by basic link groups,
   one subroutine per group type (seed 001 of this project).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "PointMotion", "LinkMotion", "Wrench",
    "cross", "dot",
    "crank", "rrr", "rrp", "RRRSolution", "RRPSolution",
    "inertia_load", "link_wrench", "rrr_reactions", "rrp_reactions", "driver_reactions",
    "RRRReactions", "RRPReactions", "DriverReactions",
]


def cross(a, b):
    """z-component of the planar cross product a × b of complex vectors: Im(conj(a)·b)."""
    return a.real * b.imag - a.imag * b.real


def dot(a, b):
    """Planar dot product of complex vectors: Re(conj(a)·b)."""
    return a.real * b.real + a.imag * b.imag


@dataclass
class PointMotion:
    """Position, velocity and acceleration of a point, complex arrays. [m, m/s, m/s²]"""

    z: np.ndarray
    v: np.ndarray
    a: np.ndarray


@dataclass
class LinkMotion:
    """Motion of a rigid link.

    Attributes
    ----------
    origin : PointMotion
        The link's first joint (the origin of its local frame). [m, m/s, m/s²]
    e : complex ndarray
        Unit vector of the local x axis, ``exp(iθ)``. [-]
    omega, eps : ndarray
        Angular velocity and acceleration, + counter-clockwise. [rad/s, rad/s²]
    """

    origin: PointMotion
    e: np.ndarray
    omega: np.ndarray
    eps: np.ndarray

    @property
    def theta(self):
        """Angle of the local x axis, ccw from +x. [rad]"""
        return np.angle(self.e)

    def point(self, local) -> PointMotion:
        """Motion of the point with local coordinates ``local`` (complex, m)."""
        r = local * self.e
        o = self.origin
        if np.all(local == 0):
            return PointMotion(o.z + 0 * r, o.v + 0 * r, o.a + 0 * r)
        iwr = 1j * r
        return PointMotion(o.z + r, o.v + self.omega * iwr,
                           o.a + self.eps * iwr - self.omega * self.omega * r)


@dataclass
class Wrench:
    """Resultant of the loads on one link, reduced to a point.

    Attributes
    ----------
    force : complex ndarray
        Resultant force. [N]
    moment : ndarray
        Resultant moment about ``point``, + counter-clockwise. [N·m]
    point : complex ndarray
        Reduction point. [m]
    """

    force: np.ndarray
    moment: np.ndarray
    point: np.ndarray

    def moment_about(self, q):
        """Resultant moment about the point ``q``. [N·m]"""
        return self.moment + cross(self.point - q, self.force)


# --------------------------------------------------------------------------- kinematics


def crank(phi, omega, eps, length, pivot=0j) -> LinkMotion:
    """Driver I(1,2): a crank turning about a fixed pivot.

    Parameters
    ----------
    phi : array_like
        Crank angle, ccw from +x. [rad]
    omega, eps : float or array_like
        Crank angular velocity and acceleration, + ccw. [rad/s, rad/s²]
    length : float
        Crank length |OA| (kept for the caller; the frame needs only the angle). [m]
    pivot : complex
        Position of the fixed pivot O. [m]

    Returns
    -------
    LinkMotion
        Origin O (at rest), x axis towards the crank pin A. Point A is
        ``link.point(length)``.
    """
    phi = np.asarray(phi, dtype=float)
    e = np.exp(1j * phi)
    zero = np.zeros_like(e)
    o = PointMotion(pivot + zero, zero, zero)
    return LinkMotion(o, e, np.broadcast_to(np.asarray(omega, float), phi.shape),
                      np.broadcast_to(np.asarray(eps, float), phi.shape))


@dataclass
class RRRSolution:
    """Result of :func:`rrr`.

    ``link3`` has its origin at A and x axis towards B; ``link4`` has its origin at C and
    x axis towards B.  ``B`` is the inner joint.  ``h2`` is the squared height of B over
    the line A–C: negative where the dyad cannot be assembled.  ``det`` is
    ``cross(B − A, B − C)``: zero where links 3 and 4 are collinear (a dead position, where
    velocities are indeterminate).
    """

    link3: LinkMotion
    link4: LinkMotion
    B: PointMotion
    h2: np.ndarray
    det: np.ndarray


def rrr(A: PointMotion, C: PointMotion, l3: float, l4: float, assembly: int,
        omega_C=0.0, eps_C=0.0) -> RRRSolution:
    """Kinematics of the RRR dyad (class II, first kind): links 3 = AB and 4 = CB.

    Position by circle–circle intersection, velocity and acceleration by 2×2 linear
    solves (no numerical differentiation, no iteration).

    Parameters
    ----------
    A, C : PointMotion
        Outer joints (A on the preceding link, C on the ground or another link).
    l3, l4 : float
        |AB| and |CB|. [m]
    assembly : {+1, -1}
        +1 puts B to the left of the directed line A→C, −1 to the right.  It is fixed
        for all positions, so the branch never switches.
    omega_C, eps_C : float or array
        Unused for the joint itself (C's motion is in ``C``); kept for symmetry. [rad/s]

    Returns
    -------
    RRRSolution

    Notes
    -----
    With ``d = C − A``, ``D = |d|``, ``p = (l3² − l4² + D²)/(2D)``, ``h² = l3² − p²``:
    ``B = A + (p + i·assembly·h)·d/D``.  Velocity: ``iω3(B − A) − iω4(B − C) = vC − vA``
    gives ``ω3 = (B−C)·Δv / det``, ``ω4 = (B−A)·Δv / det`` with ``det = (B−A)×(B−C)``;
    acceleration likewise with ``Δa = aC − aA + ω3²(B−A) − ω4²(B−C)``.
    """
    d = C.z - A.z
    D2 = d.real * d.real + d.imag * d.imag
    D = np.sqrt(D2)
    p = (l3 * l3 - l4 * l4 + D2) / (2.0 * D)
    h2 = l3 * l3 - p * p
    h = np.sqrt(np.maximum(h2, 0.0))
    ed = d / D
    zB = A.z + (p + (1j * assembly) * h) * ed
    r3 = zB - A.z
    r4 = zB - C.z
    det = cross(r3, r4)
    dv = C.v - A.v
    w3 = dot(r4, dv) / det
    w4 = dot(r3, dv) / det
    da = C.a - A.a + w3 * w3 * r3 - w4 * w4 * r4
    e3 = dot(r4, da) / det
    e4 = dot(r3, da) / det
    vB = A.v + 1j * w3 * r3
    aB = A.a + (1j * e3 - w3 * w3) * r3
    B = PointMotion(zB, vB, aB)
    link3 = LinkMotion(A, r3 / l3, w3, e3)
    link4 = LinkMotion(C, r4 / l4, w4, e4)
    return RRRSolution(link3, link4, B, h2, det)


@dataclass
class RRPSolution:
    """Result of :func:`rrp`.

    ``link3`` (the rod) has its origin at A and x axis towards B; ``link4`` (the slider)
    has its origin at B and x axis along the guide direction, with ω = ε = 0.  ``s``,
    ``v``, ``a`` are the slider's displacement, velocity and acceleration along the guide
    direction, ``s`` measured from the foot of the perpendicular from the guide point.
    ``h2`` is ``L² − (offset − y_A)²``: negative where the dyad cannot be assembled.
    """

    link3: LinkMotion
    link4: LinkMotion
    B: PointMotion
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    h2: np.ndarray


def rrp(A: PointMotion, L: float, guide_point=0j, guide_angle=0.0, offset=0.0,
        assembly: int = 1) -> RRPSolution:
    """Kinematics of the RRP dyad: a rod AB from a moving joint A to a slider B on a fixed
    straight guide.

    Parameters
    ----------
    A : PointMotion
        The rod's outer joint (the crank pin).
    L : float
        Rod length |AB|. [m]
    guide_point : complex
        The point the guide is referred to (for a crank-slider, the crank pivot O). [m]
    guide_angle : float
        Direction of the guide, ccw from +x. [rad]
    offset : float
        Distance of the guide line from ``guide_point``, + to the left of the guide
        direction. [m]
    assembly : {+1, -1}
        +1 puts B ahead of A along the guide direction, −1 behind.

    Returns
    -------
    RRPSolution

    Notes
    -----
    In guide coordinates (origin at ``guide_point``, x along the guide), A = (xA, yA) and
    B = (s, offset) with ``s = xA + assembly·√(L² − (offset − yA)²)``.  Velocity:
    ``v·u − iω3(B − A) = vA`` with ``u`` the guide direction gives
    ``ω3 = −(u × vA)/(u·(B − A))`` and ``v = u·(vA + iω3(B − A))``; acceleration likewise
    with the right-hand side ``aA − ω3²(B − A)``.
    """
    u = complex(np.cos(guide_angle), np.sin(guide_angle))
    rel = (A.z - guide_point) * u.conjugate()
    dy = offset - rel.imag
    h2 = L * L - dy * dy
    s = rel.real + assembly * np.sqrt(np.maximum(h2, 0.0))
    zB = guide_point + (s + 1j * offset) * u
    r3 = zB - A.z
    den = dot(u, r3)
    w3 = -cross(u, A.v) / den
    vB_vec = A.v + 1j * w3 * r3
    v = dot(u, vB_vec)
    rhs = A.a - w3 * w3 * r3
    e3 = -cross(u, rhs) / den
    aB_vec = rhs + 1j * e3 * r3
    a = dot(u, aB_vec)
    B = PointMotion(zB, v * u, a * u)
    zero = np.zeros_like(s)
    link3 = LinkMotion(A, r3 / L, w3, e3)
    link4 = LinkMotion(B, u + 0 * r3, zero, zero)
    return RRPSolution(link3, link4, B, s, v, a, h2)


# ----------------------------------------------------------------------- kinetostatics


def inertia_load(a_S, eps, mass=0.0, inertia=0.0):
    """d'Alembert inertia load of a link: force ``Fu = −m·a_S`` at its centre of mass and
    moment ``Mu = −J_S·ε`` (the course project's
    Fui = −mi·aSi, Mui = −JSi·εi of its table of force inputs).

    Parameters
    ----------
    a_S : complex array_like
        Acceleration of the centre of mass. [m/s²]
    eps : array_like
        Angular acceleration of the link, + ccw. [rad/s²]
    mass : float
        m. [kg]
    inertia : float
        J_S about the centre of mass. [kg·m²]

    Returns
    -------
    Fu : complex ndarray
        Inertia force. [N]
    Mu : ndarray
        Inertia moment, + ccw. [N·m]
    """
    return -mass * np.asarray(a_S), -inertia * np.asarray(eps)


def link_wrench(link: LinkMotion, mass=0.0, inertia=0.0, cg=0j, gravity=0.0,
                forces=(), moments=()) -> Wrench:
    """Resultant of all loads on one link, with d'Alembert inertia, reduced to its centre
    of mass S.

    Parameters
    ----------
    link : LinkMotion
    mass : float
        Link mass m. [kg]
    inertia : float
        Moment of inertia about the centre of mass J_S. [kg·m²]
    cg : complex
        Centre of mass in the link's local frame. [m]
    gravity : float
        Acceleration of gravity g, acting along −y. [m/s²]
    forces : iterable of (force, point)
        External forces (complex, global components) [N] applied at points given as
        complex *global* positions [m] (arrays over positions or scalars).
    moments : iterable of array_like
        External moments (couples), + ccw. [N·m]

    Returns
    -------
    Wrench
        Force ``ΣF + m·g·(−j) − m·a_S`` and moment about S ``Σ(r × F) + ΣM − J_S·ε``.
    """
    S = link.point(cg)
    Fu, Mu = inertia_load(S.a, link.eps, mass, inertia)
    F = Fu - 1j * (mass * gravity) + 0 * S.z
    M = Mu + 0.0 * S.z.real
    for f, at in forces:
        F = F + f
        M = M + cross(at - S.z, f)
    for m in moments:
        M = M + m
    return Wrench(F, M, S.z)


def _split(W, e1, e2):
    """Solve n1·e1 + n2·e2 = W for the real magnitudes n1, n2 (vectorised)."""
    det = cross(e1, e2)
    return cross(W, e2) / det, cross(e1, W) / det


@dataclass
class RRRReactions:
    """Reactions in the pairs of an RRR dyad (links 3 = AB, 4 = CB). [N]

    ``RA``: force of the preceding link on link 3 at A (R23); ``RB``: force of link 4 on
    link 3 at B (R43); ``RC``: force at C on link 4 (R14).  ``RA_n``, ``RA_t``: components
    of RA along A→B and 90° ccw from it; ``RC_n``, ``RC_t``: of RC along C→B and 90° ccw
    from it (the textbook's R23n, R23t, R14n, R14t).
    """

    RA: np.ndarray
    RB: np.ndarray
    RC: np.ndarray
    RA_n: np.ndarray
    RA_t: np.ndarray
    RC_n: np.ndarray
    RC_t: np.ndarray


def rrr_reactions(sol: RRRSolution, l3: float, l4: float, W3: Wrench, W4: Wrench
                  ) -> RRRReactions:
    """Kinetostatics of the RRR dyad: the reactions in A, B and C.

    Parameters
    ----------
    sol : RRRSolution
        The dyad's kinematics (for the joint positions and link directions).
    l3, l4 : float
        |AB|, |CB|. [m]
    W3, W4 : Wrench
        Resultant loads on links 3 and 4, inertia and weight included (see
        :func:`link_wrench`).

    Returns
    -------
    RRRReactions

    Notes
    -----
    The textbook sequence [1]_: moments about B of link 3 alone give the tangential
    component ``R23t = M3(B)/l3``; of link 4 alone ``R14t = M4(B)/l4``; the force polygon
    of the whole dyad, ``R23n·e3 + R14n·e4 = −(F3 + F4 + R23t·ie3 + R14t·ie4)``, gives the
    normal components; link 3's equilibrium gives ``R43 = −(R23 + F3)``.
    """
    zB = sol.B.z
    e3, e4 = sol.link3.e, sol.link4.e
    t3 = W3.moment_about(zB) / l3
    t4 = W4.moment_about(zB) / l4
    ie3, ie4 = 1j * e3, 1j * e4
    W = -(W3.force + W4.force + t3 * ie3 + t4 * ie4)
    n3, n4 = _split(W, e3, e4)
    RA = n3 * e3 + t3 * ie3
    RC = n4 * e4 + t4 * ie4
    RB = -(RA + W3.force)
    return RRRReactions(RA, RB, RC, n3, t3, n4, t4)


@dataclass
class RRPReactions:
    """Reactions in the pairs of an RRP dyad (rod 3 = AB, slider 4). [N, N·m]

    ``RA``: force of the preceding link (the crank) on the rod at A (R23); ``RA_n``,
    ``RA_t``: its components along A→B and 90° ccw from it; ``RB``: force of the slider on
    the rod at B (R43); ``RG``: force of the guide on the slider (R14), perpendicular to
    the guide; ``RG_n``: its signed magnitude along ``i·u`` (90° ccw from the guide
    direction); ``MG``: the guide's moment on the slider about B (M14).
    """

    RA: np.ndarray
    RA_n: np.ndarray
    RA_t: np.ndarray
    RB: np.ndarray
    RG: np.ndarray
    RG_n: np.ndarray
    MG: np.ndarray


def rrp_reactions(sol: RRPSolution, L: float, W3: Wrench, W4: Wrench) -> RRPReactions:
    """Kinetostatics of the RRP dyad: the reactions at A, B and in the guide.

    Parameters
    ----------
    sol : RRPSolution
    L : float
        Rod length. [m]
    W3, W4 : Wrench
        Resultant loads on the rod and on the slider (inertia and weight included).

    Returns
    -------
    RRPReactions

    Notes
    -----
    The guide (frictionless) acts on the slider with a force normal to it and a couple.
    Moments about B of the rod give ``R23t = M3(B)/L``; the force polygon of the dyad,
    ``R23n·e3 + R14·iu = −(F3 + F4 + R23t·ie3)``, gives ``R23n`` and the normal force
    ``R14``; the slider's moments about B give ``M14 = −M4(B)``; the rod's equilibrium
    gives ``R43 = −(R23 + F3)``.
    """
    zB = sol.B.z
    e3 = sol.link3.e
    iu = 1j * sol.link4.e
    t3 = W3.moment_about(zB) / L
    ie3 = 1j * e3
    W = -(W3.force + W4.force + t3 * ie3)
    n3, nG = _split(W, e3, iu)
    RA = n3 * e3 + t3 * ie3
    RG = nG * iu
    RB = -(RA + W3.force)
    MG = -W4.moment_about(zB)
    return RRPReactions(RA, n3, t3, RB, RG, nG, MG)


@dataclass
class DriverReactions:
    """Reactions of the driver I(1,2). ``R12``: force of the ground on the crank at O [N];
    ``M_drive``: the driving (balancing) moment applied to the crank, + ccw [N·m]."""

    R12: np.ndarray
    M_drive: np.ndarray


def driver_reactions(crank_link: LinkMotion, zA, R32, W2: Wrench) -> DriverReactions:
    """Kinetostatics of the driver: ground reaction and balancing moment Mур.

    Parameters
    ----------
    crank_link : LinkMotion
        The crank (origin at the fixed pivot O).
    zA : complex ndarray
        Position of the crank pin A. [m]
    R32 : complex ndarray
        Force of the dyad's first link on the crank at A (= −R23). [N]
    W2 : Wrench
        Resultant loads on the crank (inertia and weight included).

    Returns
    -------
    DriverReactions
        ``R12 = −(R32 + F2)``; ``M_drive = −(OA × R32) − M2(O)``.
    """
    zO = crank_link.origin.z
    R12 = -(R32 + W2.force)
    M = -cross(zA - zO, R32) - W2.moment_about(zO)
    return DriverReactions(R12, M)
