"""Assur-group routines: the driver (crank) and the class II groups RRR, RRP, RPR, PRP, RPP.

Kinematics and kinetostatics of each basic group, closed form and vectorised over arrays
of crank positions.  Everything is SI (m, s, rad, kg, N, N·m).  These are the only
implementation of the groups: :func:`linkage.analyze` evaluates them over cache-sized
chunks of crank positions, and :mod:`engine` builds its crank-slider from them.

Planar vectors are :class:`Vec`: two float arrays ``x, y`` with the arithmetic of the
complex number ``z = x + iy`` (``v.perp()`` is ``i·v``, a product of two vectors is the
complex product, i.e. a rotation).  The formulas read as in the textbooks' complex form,
and run in real arithmetic, about twice as fast as numpy's complex arrays.  A link
direction is the unit vector ``e = (cos θ, sin θ)``.  A point ``r`` (local coordinates)
fixed on a link whose origin moves with ``z0, v0, a0`` and which turns with ``ω, ε`` has

    z = z0 + r·e,   v = v0 + iω·(r·e),   a = a0 + (iε − ω²)·(r·e).

Mechanisms are assembled from these routines in the order of their structure formula
``I(1,2) → II(3,4)``: kinematics driver first, then the dyad; forces dyad first (it is
statically determinate on its own), then the driver, which yields the balancing
(driving) moment.

References
----------
.. [1] Артоболевский И. И. Теория механизмов и машин. 4-е изд. М.: Наука, 1988: the
   kinematics of the class-II groups and the kinetostatics by Assur groups.
.. [2] 孙桓 等. 机械原理 (Theory of machines), ch. 11 "Dynamic analysis and design of
   machine systems": kinetostatics by basic link groups, one subroutine per group type.
"""
from __future__ import annotations

import math
import operator
from dataclasses import dataclass, field

import numpy as np

#: Crank positions per chunk of every table built from these routines
#: (:func:`linkage.analyze` of a four-bar and of a chain).  Each numpy call costs ~0.4 µs
#: however short its arrays, and the routines make a few hundred per chunk; past ~16k
#: positions the intermediate arrays of a chunk (128 KB each) no longer stay in cache, and
#: whole arrays of a million positions are memory-bound (benchmarks/bench_linkage.py).
CHUNK = 16384

#: Bytes of one page of memory (a small page; a huge page is a multiple of it).
_PAGE = 4096


def column_block(rows, n):
    """A float block of ``rows`` columns × ``n`` positions (uninitialised), the storage
    of a table filled chunk by chunk, with every page of it mapped now.

    A fresh block of a million positions is hundreds of MB that the operating system
    maps (and zeroes) on first touch.  Touched chunk by chunk, every chunk's writes
    land on pages not yet mapped, across all its rows, and the zeroing of each new
    (huge) page evicts the chunk's intermediate arrays from the cache; one write per
    page here maps the whole block in one sweep before the first chunk
    (benchmarks/bench_linkage.py: about 10 % of ``analyze`` at 1,000,000 positions).
    The values written are overwritten by the chunks."""
    block = np.empty((rows, n))
    block.reshape(-1)[::_PAGE // block.itemsize] = 0.0
    return block


__all__ = [
    "CHUNK", "column_block", "Vec", "PointMotion", "LinkMotion", "Wrench",
    "cross", "dot",
    "crank", "rrr", "rrp", "RRRSolution", "RRPSolution",
    "inertia_load", "link_wrench", "rrr_reactions", "rrp_reactions", "driver_reactions",
    "RRRReactions", "RRPReactions", "DriverReactions",
    "coincident", "rrp_guided", "rpr", "prp", "rpp", "RPRSolution", "PRPSolution",
    "RPPSolution", "rpr_reactions", "prp_reactions", "rpp_reactions", "RPRReactions",
    "PRPReactions", "RPPReactions", "FRAME",
]


#: float64, the dtype of every array these routines make (in-place writes only into it).
_F8 = np.dtype(float)


# A component that is the float constant 0.0 (``type(c) is float and c == 0.0``, not an
# array of zeros) costs no array operation.  These helpers run a few hundred times per
# chunk of crank positions, so they test it inline.

def _is_zero(v):
    """True for a vector that is the exact constant zero (``Vec(0.0, 0.0)`` of floats)."""
    x, y = v.x, v.y
    return type(x) is float and x == 0.0 and type(y) is float and y == 0.0


def _plus(a, b):
    """a + b, skipping a float-constant zero."""
    if type(b) is float and b == 0.0:
        return a
    if type(a) is float and a == 0.0:
        return b
    return a + b


def _minus(a, b):
    """a − b, skipping a float-constant zero ``b``."""
    return a if type(b) is float and b == 0.0 else a - b


#: The Python operator of each ufunc written in place: what a routine computes when it
#: cannot write in place (scalars: a float stays a Python float, as with ``t - u``).
_OPERATOR = {np.add: operator.add, np.subtract: operator.sub, np.multiply: operator.mul,
             np.divide: operator.truediv}


def _into(op, t, u):
    """``op(t, u)`` written into ``t`` when ``t`` is a fresh float64 array of this routine
    (the result of a numpy operation, referenced nowhere else) and ``u`` a float or a
    float64 array of its shape; else a new array.  The same floating-point operation in
    the same order: the same bits, one temporary fewer to allocate and to bring through
    the cache."""
    if type(t) is np.ndarray and t.dtype is _F8 and (
            type(u) is float or type(u) is np.ndarray and u.dtype is _F8 and u.shape == t.shape):
        return op(t, u, out=t)
    return _OPERATOR[op](t, u)       # the operator itself (floats stay Python floats)


def _rinto(op, u, t):
    """``op(u, t)`` written into the fresh array ``t`` (see :func:`_into`)."""
    if type(t) is np.ndarray and t.dtype is _F8 and (
            type(u) is float or type(u) is np.ndarray and u.dtype is _F8 and u.shape == t.shape):
        return op(u, t, out=t)
    return _OPERATOR[op](u, t)


def _add_to(a, t):
    """``_plus(a, t)`` with ``t`` fresh (see :func:`_into`): the sum written into ``t``."""
    if type(t) is float and t == 0.0:
        return a
    if type(a) is float and a == 0.0:
        return t
    return _rinto(np.add, a, t)


def _add_first(t, b):
    """``_plus(t, b)`` with ``t`` fresh: the sum written into ``t``.  Not ``_add_to(b, t)``:
    the sum of a NaN takes the first operand's NaN, so the operands keep their order."""
    if type(b) is float and b == 0.0:
        return t
    if type(t) is float and t == 0.0:
        return b
    return _into(np.add, t, b)


def _add_out(a, t, out):
    """``out[...] = _add_to(a, t)`` with the sum computed straight into ``out`` where
    :func:`_add_to` adds two arrays (``np.add(a, t)``, the same operands in the same
    order: the same bits, NaN payloads too); returns ``out``."""
    if type(t) is float and t == 0.0:
        out[...] = a
    elif type(a) is float and a == 0.0:
        out[...] = t
    elif type(t) is np.ndarray and t.dtype is _F8 and t.shape == out.shape and (
            type(a) is float or type(a) is np.ndarray and a.dtype is _F8 and a.shape == t.shape):
        np.add(a, t, out=out)
    else:
        out[...] = a + t
    return out


def _vadd(a, t):
    """``a + t`` of two vectors, ``t`` a fresh product of this routine (a :class:`Vec`
    product's components are new arrays, or float constants): the sum written into
    ``t``'s arrays.  The same operations as ``Vec.__add__`` (a float-constant zero
    skipped), so the same bits."""
    return Vec(_add_to(a.x, t.x), _add_to(a.y, t.y))


def _vadd_first(t, b):
    """``t + b``, ``t`` a fresh product: the sum written into ``t``'s arrays."""
    return Vec(_add_first(t.x, b.x), _add_first(t.y, b.y))


def _vsub(a, t):
    """``a − t``, ``t`` a fresh product: the difference written into ``t``'s arrays (as
    ``Vec.__sub__``: ``−t`` when ``a`` is the constant zero)."""
    if _is_zero(a):
        return Vec(_neg_to(t.x), _neg_to(t.y))
    return Vec(a.x if type(t.x) is float and t.x == 0.0 else _rinto(np.subtract, a.x, t.x),
               a.y if type(t.y) is float and t.y == 0.0 else _rinto(np.subtract, a.y, t.y))


def _vadd_sub(a, t, b):
    """``a + t − b``, ``t`` a fresh product: both written into ``t``'s arrays (as
    ``Vec.__add__`` then ``Vec.__sub__``)."""
    s = _vadd(a, t)
    if _is_zero(s):
        return -b
    return Vec(_sub_fresh(s.x, b.x, type(t.x) is np.ndarray),
               _sub_fresh(s.y, b.y, type(t.y) is np.ndarray))


def _sub_fresh(s, b, fresh):
    """``_minus(s, b)``, into ``s`` when it is ``fresh``."""
    if type(b) is float and b == 0.0:
        return s
    return _into(np.subtract, s, b) if fresh else s - b


def _sqrt_to(t):
    """``√t``, into ``t`` when it is a fresh float64 array."""
    return np.sqrt(t, out=t) if type(t) is np.ndarray and t.dtype is _F8 else np.sqrt(t)


def _neg_to(t):
    """``−t``, into ``t`` when it is a fresh float64 array."""
    return np.negative(t, out=t) if type(t) is np.ndarray and t.dtype is _F8 else -t


def _is_complex(k):
    """True for a complex number or a complex array."""
    return isinstance(k, (complex, np.complexfloating)) or \
        (isinstance(k, np.ndarray) and k.dtype.kind == "c")


class Vec:
    """Planar vectors: x and y components as float arrays (or floats).

    The arithmetic of complex numbers ``x + iy`` in real arithmetic: ``+``, ``−``, a
    product with a real number or array scales, a product with a complex number or
    another :class:`Vec` is the complex product (a rotation and a scaling), ``/`` by a
    real number or array divides both components.  :meth:`perp` is ``i·v`` (the vector
    turned 90° counter-clockwise).  ``.real`` and ``.imag`` are ``x`` and ``y``, so
    :func:`cross` and :func:`dot` take vectors and complex arrays alike; numpy sees a
    ``Vec`` as the complex array ``x + iy`` (``np.angle(v)``, ``np.abs(v)``).

    A vector whose components are the float constants 0.0 (the velocity of a fixed pivot)
    is skipped in sums, so the routines pay nothing for a fixed pivot.
    """

    __slots__ = ("x", "y")

    def __init__(self, x, y):
        self.x = x
        self.y = y

    @staticmethod
    def of(z) -> "Vec":
        """``z`` as a :class:`Vec`: a Vec itself, a complex (or real) number or array."""
        if type(z) is Vec:
            return z
        if isinstance(z, (int, float, complex)):
            z = complex(z)
            return Vec(z.real, z.imag)
        z = np.asarray(z)
        if z.dtype.kind == "c":
            return Vec(np.ascontiguousarray(z.real), np.ascontiguousarray(z.imag))
        return Vec(np.asarray(z, float), np.zeros(z.shape))

    # -- complex-number view
    @property
    def real(self):
        return self.x

    @property
    def imag(self):
        return self.y

    @property
    def shape(self):
        return np.broadcast_shapes(np.shape(self.x), np.shape(self.y))

    def __array__(self, dtype=None, copy=None):
        # numpy 2 wants an ndarray here, also for scalar components (a 0-d array)
        z = np.asarray(np.asarray(self.x) + 1j * np.asarray(self.y))
        return z if dtype is None else z.astype(dtype)

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        # numpy on the left of an operator: keep vector arithmetic; any other ufunc
        # sees the complex array x + iy.
        if method == "__call__" and not kwargs and len(inputs) == 2:
            a, b = inputs
            if ufunc is np.multiply:
                return a * b if type(a) is Vec else b * a
            if ufunc is np.add:
                return a + b if type(a) is Vec else b + a
            if ufunc is np.subtract:
                return a - b if type(a) is Vec else (-b) + a
        args = [np.asarray(v) if type(v) is Vec else v for v in inputs]
        return getattr(ufunc, method)(*args, **kwargs)

    def __complex__(self):
        return complex(self.x, self.y)

    def __eq__(self, o):
        # as complex numbers compare: componentwise (an array of bools for array components)
        o = o if type(o) is Vec else Vec.of(o)
        return (self.x == o.x) & (self.y == o.y)

    def __ne__(self, o):
        return ~(self == o) if np.ndim(self.x) or np.ndim(self.y) else not (self == o)

    __hash__ = None

    def __getitem__(self, index):
        # a constant component (a float, e.g. a guide direction) is the same at every index
        return Vec(self.x[index] if np.ndim(self.x) else self.x,
                   self.y[index] if np.ndim(self.y) else self.y)

    def __len__(self):
        return len(self.x) if np.ndim(self.x) else len(self.y)

    def __repr__(self):
        return f"Vec(x={self.x!r}, y={self.y!r})"

    # -- arithmetic (a component that is the float constant 0.0 costs no array operation)
    def __add__(self, o):
        if type(o) is not Vec:
            o = Vec.of(o)
        return Vec(_plus(self.x, o.x), _plus(self.y, o.y))

    __radd__ = __add__

    def __sub__(self, o):
        if type(o) is not Vec:
            o = Vec.of(o)
        if _is_zero(self):
            return -o
        return Vec(_minus(self.x, o.x), _minus(self.y, o.y))

    def __rsub__(self, o):
        return Vec.of(o) - self

    def __neg__(self):
        return Vec(-self.x, -self.y)

    def __mul__(self, k):
        if type(k) is not Vec:
            if type(k) is float or not _is_complex(k):     # a real factor: scale
                if type(k) is float and k == 0.0 or _is_zero(self):
                    return _ZERO
                return Vec(self.x * k, self.y * k)
            k = Vec.of(k)
        # complex product (x1 + iy1)(x2 + iy2), each sum into its first product
        return Vec(_into(np.subtract, self.x * k.x, self.y * k.y),
                   _into(np.add, self.x * k.y, self.y * k.x))

    __rmul__ = __mul__

    def __truediv__(self, k):
        if type(k) is Vec or isinstance(k, complex) or np.iscomplexobj(k):
            k = Vec.of(k)
            n = k.x * k.x + k.y * k.y
            return self * Vec(k.x / n, -k.y / n)
        return Vec(self.x / k, self.y / k)

    def __abs__(self):
        return np.sqrt(self.x * self.x + self.y * self.y)

    def perp(self) -> "Vec":
        """``i·v``: the vector turned 90° counter-clockwise, ``(−y, x)``."""
        return Vec(-self.y, self.x)

    def conj(self) -> "Vec":
        """The mirror image in the x axis, ``(x, −y)``."""
        return Vec(self.x, -self.y)

    @property
    def angle(self):
        """Direction, ccw from +x, in (−π, π]. [rad]"""
        return np.arctan2(self.y, self.x)


#: The constant zero vector (a fixed point's velocity and acceleration).
_ZERO = Vec(0.0, 0.0)


def cross(a, b):
    """z-component of the planar cross product a × b: ``a_x·b_y − a_y·b_x``
    (``Im(conj(a)·b)`` of complex vectors)."""
    return _into(np.subtract, a.real * b.imag, a.imag * b.real)


def dot(a, b):
    """Planar dot product: ``a_x·b_x + a_y·b_y`` (``Re(conj(a)·b)``)."""
    return _into(np.add, a.real * b.real, a.imag * b.imag)


@dataclass
class PointMotion:
    """Position, velocity and acceleration of a point. [m, m/s, m/s²]

    Each is a :class:`Vec` (complex numbers or arrays are converted)."""

    z: Vec
    v: Vec
    a: Vec

    def __post_init__(self):
        self.z, self.v, self.a = Vec.of(self.z), Vec.of(self.v), Vec.of(self.a)


@dataclass
class LinkMotion:
    """Motion of a rigid link.

    Attributes
    ----------
    origin : PointMotion
        The link's first joint (the origin of its local frame). [m, m/s, m/s²]
    e : Vec
        Unit vector of the local x axis, ``(cos θ, sin θ)``. [-]
    omega, eps : float or ndarray
        Angular velocity and acceleration, + counter-clockwise. [rad/s, rad/s²]
    """

    origin: PointMotion
    e: Vec
    omega: object
    eps: object
    _points: dict = field(default_factory=dict, init=False, repr=False, compare=False)
    _theta: object = field(default=None, init=False, repr=False, compare=False)
    #: A link with the same ``e`` (an RPR's block and lever): its angle is this one's.
    _same_e: object = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        self.e = Vec.of(self.e)

    @property
    def theta(self):
        """Angle of the local x axis, ccw from +x, in (−π, π]. [rad]

        Kept once computed: the tables and the resistance rule (the rocker's angle) ask
        for the same angle."""
        if self._theta is None:
            self._theta = self.e.angle if self._same_e is None else self._same_e.theta
        return self._theta

    def point(self, local, out=None) -> PointMotion:
        """Motion of the point with local coordinates ``local`` (complex or real, m).

        The result is kept: the tables and the link's wrench ask for the same centre of
        mass.  ``out``: six float arrays (x, y, vx, vy, ax, ay over the positions) that a
        point not yet computed (and not the origin) is written into, the last operation of
        each component straight into its array (a table's rows): the same operations in
        the same order as without, so the same bits."""
        local = complex(local)
        got = self._points.get(local)
        if got is None:
            got = self._points[local] = self._point(local, out)
        return got

    def _point(self, local: complex, out=None) -> PointMotion:
        o = self.origin
        if local == 0:
            return o
        r = self.e * local if local.imag else self.e * local.real     # r·e
        ir = r.perp()                                                  # i·r·e
        if out is not None:
            zx, zy, vx, vy, ax, ay = out
            t = ir * self.omega
            v = Vec(_add_out(o.v.x, t.x, vx), _add_out(o.v.y, t.y, vy))
            t = _vadd(o.a, ir * self.eps)
            w = r * (-(self.omega * self.omega))
            a = Vec(_add_out(t.x, w.x, ax), _add_out(t.y, w.y, ay))
            return PointMotion(Vec(_add_out(o.z.x, r.x, zx), _add_out(o.z.y, r.y, zy)), v, a)
        v = _vadd(o.v, ir * self.omega)
        a = _vadd(_vadd(o.a, ir * self.eps), r * (-(self.omega * self.omega)))  # (iε−ω²)·r·e
        return PointMotion(_vadd(o.z, r), v, a)     # (r last: its arrays hold z)


@dataclass
class Wrench:
    """Resultant of the loads on one link, reduced to a point.

    Attributes
    ----------
    force : Vec
        Resultant force (complex arrays are converted). [N]
    moment : float or ndarray
        Resultant moment about ``point``, + counter-clockwise. [N·m]
    point : Vec
        Reduction point. [m]
    """

    force: Vec
    moment: object
    point: Vec

    def __post_init__(self):
        self.force, self.point = Vec.of(self.force), Vec.of(self.point)

    def moment_about(self, q):
        """Resultant moment about the point ``q``: ``M + (P − q) × F``. [N·m]"""
        return _rinto(np.add, self.moment, cross(self.point - q, self.force))


# --------------------------------------------------------------------------- kinematics


def crank(phi, omega, eps, length=None, pivot=0j) -> LinkMotion:
    """Driver I(1,2): a crank turning about a fixed pivot.

    Parameters
    ----------
    phi : array_like
        Crank angle, ccw from +x. [rad]
    omega, eps : float or array_like
        Crank angular velocity and acceleration, + ccw. [rad/s, rad/s²]
    length : float, optional
        Crank length |OA|; not needed for the link's motion (the crank pin A is
        ``link.point(length)``), accepted for readability of the caller. [m]
    pivot : complex or Vec
        Position of the fixed pivot O. [m]

    Returns
    -------
    LinkMotion
        Origin O (at rest), x axis towards the crank pin A.
    """
    phi = np.asarray(phi, dtype=float)
    e = Vec(np.cos(phi), np.sin(phi))
    return LinkMotion(PointMotion(Vec.of(pivot), _ZERO, _ZERO), e, omega, eps)


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


def rrr(A: PointMotion, C: PointMotion, l3: float, l4: float, assembly: int) -> RRRSolution:
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

    Returns
    -------
    RRRSolution

    Notes
    -----
    With ``d = C − A``, ``D = |d|``, ``p = (l3² − l4² + D²)/(2D)``, ``h² = l3² − p²``:
    ``B = A + (p + i·assembly·h)·d/D``.  Velocity: ``iω3(B − A) − iω4(B − C) = vC − vA``
    gives ``ω3 = (B−C)·Δv / det``, ``ω4 = (B−A)·Δv / det`` with ``det = (B−A)×(B−C)``;
    acceleration likewise with ``Δa = aC − aA + ω3²(B−A) − ω4²(B−C)`` [1]_.
    """
    d = C.z - A.z
    D2 = dot(d, d)
    iD = _rinto(np.divide, 1.0, np.sqrt(D2))     # (products by reciprocals: one division)
    p = _into(np.multiply, _rinto(np.add, l3 * l3 - l4 * l4, D2), 0.5 * iD)
    h2 = _rinto(np.subtract, l3 * l3, p * p)
    h = _sqrt_to(np.maximum(h2, 0.0))
    ed = d * iD
    zB = _vadd(_vadd(A.z, ed * p), ed.perp() * (h if assembly > 0 else _neg_to(h)))
    r3 = zB - A.z
    r4 = zB - C.z
    det = cross(r3, r4)
    idet = 1.0 / det
    dv = C.v - A.v
    w3 = _into(np.multiply, dot(r4, dv), idet)
    w4 = _into(np.multiply, dot(r3, dv), idet)
    r3w3sq, r4w4sq = r3 * (w3 * w3), r4 * (w4 * w4)
    da = _vsub(C.a - A.a + r3w3sq, r4w4sq)
    e3 = _into(np.multiply, dot(r4, da), idet)
    e4 = _into(np.multiply, dot(r3, da), idet)
    ir3 = r3.perp()
    B = PointMotion(zB, _vadd(A.v, ir3 * w3), _vadd_sub(A.a, ir3 * e3, r3w3sq))
    link3 = LinkMotion(A, r3 * (1.0 / l3), w3, e3)
    link4 = LinkMotion(C, r4 * (1.0 / l4), w4, e4)
    link3._points[complex(l3)] = link4._points[complex(l4)] = B
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
    guide_point : complex or Vec
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
    with the right-hand side ``aA − ω3²(B − A)`` [1]_.
    """
    u = Vec(float(np.cos(guide_angle)), float(np.sin(guide_angle)))
    O = Vec.of(guide_point)
    rel = (A.z - O) * u.conj()                         # A in guide coordinates
    dy = offset - rel.y
    h2 = L * L - dy * dy
    h = np.sqrt(np.maximum(h2, 0.0))
    s = rel.x + h if assembly > 0 else rel.x - h
    zB = O + Vec(s, offset) * u
    r3 = zB - A.z
    mden = -1.0 / dot(u, r3)
    w3 = _into(np.multiply, cross(u, A.v), mden)
    ir3 = r3.perp()
    v = dot(u, _vadd(A.v, ir3 * w3))                 # (sums into the fresh products)
    rhs = _vsub(A.a, r3 * (w3 * w3))
    e3 = _into(np.multiply, cross(u, rhs), mden)
    a = dot(u, _vadd(rhs, ir3 * e3))
    B = PointMotion(zB, u * v, u * a)
    link3 = LinkMotion(A, r3 * (1.0 / L), w3, e3)
    link4 = LinkMotion(B, u, 0.0, 0.0)
    link3._points[complex(L)] = B
    return RRPSolution(link3, link4, B, s, v, a, h2)


# ----------------------------------------------------------------------- kinetostatics


def inertia_load(a_S, eps, mass=0.0, inertia=0.0):
    """d'Alembert inertia load of a link: force ``Fu = −m·a_S`` at its centre of mass and
    moment ``Mu = −J_S·ε`` (the course project's Fui = −mi·aSi, Mui = −JSi·εi of its
    table of force inputs) [1]_.

    Parameters
    ----------
    a_S : Vec, complex or real array_like
        Acceleration of the centre of mass (or one of its components). [m/s²]
    eps : float or array_like
        Angular acceleration of the link, + ccw. [rad/s²]
    mass : float
        m. [kg]
    inertia : float
        J_S about the centre of mass. [kg·m²]

    Returns
    -------
    Fu : same kind as ``a_S``
        Inertia force. [N]
    Mu : float or ndarray
        Inertia moment, + ccw. [N·m]
    """
    if type(a_S) is not Vec:
        a_S = np.asarray(a_S)
    return a_S * (-mass), np.asarray(eps) * (-inertia) if np.ndim(eps) else -inertia * eps


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
        External forces (Vec or complex, global components) [N] applied at points given
        as *global* positions (Vec or complex) [m] (arrays over positions or scalars).
    moments : iterable of array_like
        External moments (couples), + ccw. [N·m]

    Returns
    -------
    Wrench
        Force ``ΣF + m·g·(−j) − m·a_S`` and moment about S ``Σ(r × F) + ΣM − J_S·ε``.
    """
    S = link.point(cg)
    F, M = inertia_load(S.a, link.eps, mass, inertia)
    if mass * gravity != 0.0:
        F = _vadd_first(F, Vec(0.0, -mass * gravity))     # (F: the fresh inertia force)
    for f, at in forces:
        f = Vec.of(f)
        F = F + f
        M = _rinto(np.add, M, cross(Vec.of(at) - S.z, f))
    for m in moments:
        M = _into(np.add, M, m)       # (M: fresh, the inertia moment or a sum made here)
    return Wrench(F, M, S.z)


def _split(W, e1, e2, idet=None):
    """Solve n1·e1 + n2·e2 = W for the real magnitudes n1, n2 (vectorised).

    ``idet`` is ``1/(e1 × e2)`` when the caller has it already: a group solves the same
    pair of directions for its velocities and its accelerations."""
    if idet is None:
        idet = _rinto(np.divide, 1.0, cross(e1, e2))
    return _into(np.multiply, cross(W, e2), idet), _into(np.multiply, cross(e1, W), idet)


@dataclass
class RRRReactions:
    """Reactions in the pairs of an RRR dyad (links 3 = AB, 4 = CB). [N]

    ``RA``: force of the preceding link on link 3 at A (R23); ``RB``: force of link 4 on
    link 3 at B (R43); ``RC``: force at C on link 4 (R14).  ``RA_n``, ``RA_t``: components
    of RA along A→B and 90° ccw from it; ``RC_n``, ``RC_t``: of RC along C→B and 90° ccw
    from it (the textbook's R23n, R23t, R14n, R14t).
    """

    RA: Vec
    RB: Vec
    RC: Vec
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
    t3 = _into(np.multiply, W3.moment_about(zB), 1.0 / l3)
    t4 = _into(np.multiply, W4.moment_about(zB), 1.0 / l4)
    T3, T4 = e3.perp() * t3, e4.perp() * t4
    n3, n4 = _split(-(W3.force + W4.force + T3 + T4), e3, e4)
    RA = _vadd_first(e3 * n3, T3)
    RC = _vadd_first(e4 * n4, T4)
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

    RA: Vec
    RA_n: np.ndarray
    RA_t: np.ndarray
    RB: Vec
    RG: Vec
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
    gives ``R43 = −(R23 + F3)`` [1]_.
    """
    zB = sol.B.z
    e3 = sol.link3.e
    iu = sol.link4.e.perp()
    t3 = W3.moment_about(zB) * (1.0 / L)
    T3 = e3.perp() * t3
    n3, nG = _split(-(W3.force + W4.force + T3), e3, iu)
    RA = e3 * n3 + T3
    RB = -(RA + W3.force)
    MG = -W4.moment_about(zB)
    return RRPReactions(RA, n3, t3, RB, iu * nG, nG, MG)


@dataclass
class DriverReactions:
    """Reactions of the driver I(1,2). ``R12``: force of the ground on the crank at O [N];
    ``M_drive``: the driving (balancing) moment applied to the crank, + ccw [N·m]."""

    R12: Vec
    M_drive: np.ndarray


def driver_reactions(crank_link: LinkMotion, zA, R32, W2: Wrench) -> DriverReactions:
    """Kinetostatics of the driver: ground reaction and balancing moment Mур.

    Parameters
    ----------
    crank_link : LinkMotion
        The crank (origin at the fixed pivot O).
    zA : Vec or complex ndarray
        Position of the crank pin A. [m]
    R32 : Vec or complex ndarray
        Force of the dyad's first link on the crank at A (= −R23). [N]
    W2 : Wrench
        Resultant loads on the crank (inertia and weight included).

    Returns
    -------
    DriverReactions
        ``R12 = −(R32 + F2)``; ``M_drive = −(OA × R32) − M2(O)`` [1]_.
    """
    zO = crank_link.origin.z
    R32 = Vec.of(R32)
    R12 = -(R32 + W2.force)
    M = _into(np.subtract, _neg_to(cross(Vec.of(zA) - zO, R32)), W2.moment_about(zO))
    return DriverReactions(R12, M)


# ------------------------------------------------------- groups with prismatic pairs
#
# A prismatic pair's guide belongs to a link (the frame or a moving link): a point P on
# it slides along a line of that link.  With Pj the point of the guide's link that
# coincides with P at the instant, and x the sliding coordinate along the guide's unit
# vector u (which turns with the link, ω_j, ε_j):
#
#     v_P = v_Pj + ẋ·u,    a_P = a_Pj + ẍ·u + 2·ω_j·ẋ·(i·u)      (Coriolis: 2 ω_j × v_rel).

#: The frame as a link at rest (origin 0, x axis along +x); its points are constants.
FRAME = LinkMotion(PointMotion(_ZERO, _ZERO, _ZERO), Vec(1.0, 0.0), 0.0, 0.0)


def coincident(link: LinkMotion, z) -> PointMotion:
    """Motion of the point of ``link`` that is at the global position ``z`` at the
    instant: ``v = v0 + iω·(z − z0)``, ``a = a0 + (iε − ω²)·(z − z0)``. [m, m/s, m/s²]"""
    z = Vec.of(z)
    o = link.origin
    r = z - o.z
    ir = r.perp()
    w = link.omega
    return PointMotion(z, o.v + ir * w, o.a + ir * link.eps + r * (-(w * w)))


def _guide_line(link: LinkMotion, point=0j, angle=0.0, offset=0.0):
    """World point and unit direction of a guide fixed on ``link``: the line through the
    local ``point`` [m] at the local ``angle`` [rad], shifted by ``offset`` [m] to the
    left of its direction."""
    u = link.e * complex(math.cos(angle), math.sin(angle))
    G = link.origin.z + link.e * complex(point)
    if offset:
        G = G + u.perp() * offset
    return G, u


def rrp_guided(A: PointMotion, L: float, guide: LinkMotion, point=0j, angle=0.0,
               offset=0.0, assembly: int = 1) -> RRPSolution:
    """Kinematics of the RRP dyad whose guide is a line of a moving link (or the frame).

    Like :func:`rrp` (rod 3 = AB from a moving joint A, slider 4 at B), but the guide is
    fixed on the link ``guide``: the line through its local ``point`` at local ``angle``
    [rad], shifted by ``offset`` [m] to the left of its direction.  The slider turns with
    the guide's link; ``s``, ``v``, ``a`` are the slider's coordinate on the guide (from
    the guide point), and its velocity and acceleration *relative to the guide*.

    Notes
    -----
    ``B = G + s·u``, ``|B − A| = L``: circle–line intersection as in :func:`rrp`.  With
    ``B_j`` the guide's point under B: ``v·u − iω3(B − A) = v_A − v_Bj`` and
    ``a·u − iε3(B − A) = a_A − ω3²(B − A) − a_Bj − 2ω_j·v·iu`` (Coriolis) [1]_.
    """
    G, u = _guide_line(guide, point, angle, offset)
    rel = (A.z - G) * u.conj()
    h2 = L * L - rel.y * rel.y
    h = np.sqrt(np.maximum(h2, 0.0))
    s = rel.x + h if assembly > 0 else rel.x - h
    zB = G + u * s
    Bj = coincident(guide, zB)
    r3 = zB - A.z
    ir3 = r3.perp()
    mir3 = -ir3
    idet = _rinto(np.divide, 1.0, cross(u, mir3))     # (one 2×2 system: v and a)
    v, w3 = _split(A.v - Bj.v, u, mir3, idet)
    iu = u.perp()
    rhs = A.a - r3 * (w3 * w3) - Bj.a - iu * (2.0 * guide.omega * v)
    a, e3 = _split(rhs, u, mir3, idet)
    B = PointMotion(zB, Bj.v + u * v, Bj.a + u * a + iu * (2.0 * guide.omega * v))
    link3 = LinkMotion(A, r3 * (1.0 / L), w3, e3)
    link4 = LinkMotion(B, u, guide.omega, guide.eps)
    link3._points[complex(L)] = B
    return RRPSolution(link3, link4, B, s, v, a, h2)


@dataclass
class RPRSolution:
    """Result of :func:`rpr` (the crank-slotted-lever group).

    ``block`` (link 2, the slider) has its origin at A and its x axis along the slot;
    ``lever`` (link 3, the slotted lever) has its origin at its pivot C and the same x
    axis (they turn together).  ``s``, ``v_rel``, ``a_rel``: the block's coordinate along
    the slot from C's foot, and its velocity and acceleration relative to the lever;
    ``A_lever``: the lever's point under A; ``coriolis``: ``2ω3·v_rel·(i·e)``.  ``h2`` is
    ``|AC|² − offset²`` (negative: cannot be assembled), ``det`` is ``s`` (zero where A
    passes over C: a dead position).
    """

    block: LinkMotion
    lever: LinkMotion
    s: np.ndarray
    v_rel: np.ndarray
    a_rel: np.ndarray
    A_lever: PointMotion
    coriolis: Vec
    h2: np.ndarray
    det: np.ndarray


def rpr(A: PointMotion, C: PointMotion, offset=0.0, assembly: int = 1) -> RPRSolution:
    """Kinematics of the RPR group: a block pinned at A slides in the slot of a lever
    pivoted at C (the crank-slotted-lever, «кулисный механизм», 导杆机构).

    Parameters
    ----------
    A, C : PointMotion
        The block's pin (on a preceding link) and the lever's pivot (frame or a link).
    offset : float
        Distance of the slot's line from C, + to the left of the slot direction. [m]
    assembly : {+1, -1}
        Sign of the block's coordinate ``s`` along the slot (+1: the slot's x axis points
        from C towards A).

    Returns
    -------
    RPRSolution

    Notes
    -----
    ``A − C = (s + i·offset)·e`` gives ``s = ±√(|AC|² − offset²)`` and
    ``e = (A − C)/(s + i·offset)``.  Velocity: ``v_rel·e + ω·i(A − C) = v_A − v_C``;
    acceleration: ``a_rel·e + ε·i(A − C) = a_A − a_C + ω²(A − C) − 2ω·v_rel·ie``, the last
    term the Coriolis acceleration of the block relative to the lever [1]_.
    """
    d = A.z - C.z
    D2 = dot(d, d)
    h2 = D2 - offset * offset
    s = np.sqrt(np.maximum(h2, 0.0))
    if assembly < 0:
        s = -s
    # e = (A − C)/(s + i·offset); with no offset s = ±|AC| and e = (A − C)/s
    e = d * Vec(s, -offset) * (1.0 / D2) if offset else d * (1.0 / s)
    idd = d.perp()
    idet = _rinto(np.divide, 1.0, cross(e, idd))     # (one 2×2 system: v and a)
    vr, w = _split(A.v - C.v, e, idd, idet)
    ie = e.perp()
    cor = ie * (2.0 * w * vr)
    dww = d * (w * w)
    ar, eps = _split(A.a - C.a + dww - cor, e, idd, idet)
    lever = LinkMotion(C, e, w, eps)
    block = LinkMotion(A, e, w, eps)
    block._same_e = lever                     # one angle θ for both
    A3 = PointMotion(A.z, _vadd(C.v, idd * w), _vadd_sub(C.a, idd * eps, dww))
    return RPRSolution(block, lever, s, vr, ar, A3, cor, h2, s)


@dataclass
class PRPSolution:
    """Result of :func:`prp`: two sliders pinned together at B, each on a guide.

    ``link2`` slides on the first guide (origin B, x axis along it, turning with the
    first guide's link), ``link3`` on the second.  ``s1, v1, a1`` and ``s2, v2, a2``:
    coordinates of B on each guide (from its point) and its velocity and acceleration
    relative to it.  ``det`` is ``u1 × u2`` (zero: parallel guides, no solution).
    """

    link2: LinkMotion
    link3: LinkMotion
    B: PointMotion
    s1: np.ndarray
    v1: np.ndarray
    a1: np.ndarray
    s2: np.ndarray
    v2: np.ndarray
    a2: np.ndarray
    det: np.ndarray


def prp(guide1: LinkMotion, guide2: LinkMotion, point1=0j, angle1=0.0, point2=0j,
        angle2=0.0) -> PRPSolution:
    """Kinematics of the PRP group: B is the intersection of two guides, each a line of a
    link (``point``, ``angle`` local to it, as in :func:`rrp_guided`).

    Notes
    -----
    ``G1 + s1·u1 = G2 + s2·u2`` (line–line intersection, one solution); velocity
    ``v1·u1 − v2·u2 = v_B2 − v_B1``; acceleration
    ``a1·u1 − a2·u2 = a_B2 − a_B1 + 2ω_2·v2·iu2 − 2ω_1·v1·iu1`` (the two Coriolis
    terms), with ``B_k`` the point of guide k's link under B [1]_.
    """
    G1, u1 = _guide_line(guide1, point1, angle1)
    G2, u2 = _guide_line(guide2, point2, angle2)
    mu2 = -u2
    idet = _rinto(np.divide, 1.0, cross(u1, mu2))     # (one 2×2 system: s, v and a)
    s1, s2 = _split(G2 - G1, u1, mu2, idet)
    zB = G1 + u1 * s1
    B1, B2 = coincident(guide1, zB), coincident(guide2, zB)
    v1, v2 = _split(B2.v - B1.v, u1, mu2, idet)
    iu1, iu2 = u1.perp(), u2.perp()
    c1, c2 = iu1 * (2.0 * guide1.omega * v1), iu2 * (2.0 * guide2.omega * v2)
    a1, a2 = _split(B2.a - B1.a + c2 - c1, u1, mu2, idet)
    B = PointMotion(zB, B1.v + u1 * v1, B1.a + u1 * a1 + c1)
    return PRPSolution(LinkMotion(B, u1, guide1.omega, guide1.eps),
                       LinkMotion(B, u2, guide2.omega, guide2.eps),
                       B, s1, v1, a1, s2, v2, a2, cross(u1, u2))


@dataclass
class RPPSolution:
    """Result of :func:`rpp`: a block pinned at A slides in the slot of a yoke which
    slides on a guide (the Scotch yoke, «кулисный механизм с поступательной кулисой»).

    ``block`` (link 2): origin A, x axis along the slot; ``yoke`` (link 3): origin on the
    guide line (``G + s_guide·u``), x axis along the guide; both turn with the guide's
    link.  ``s_slot, v_slot, a_slot``: A's coordinate along the slot from the yoke's
    origin, relative velocity and acceleration; ``s_guide, v_guide, a_guide``: the
    yoke's on the guide.  ``det`` is ``u × w`` = sin(slot angle).
    """

    block: LinkMotion
    yoke: LinkMotion
    s_slot: np.ndarray
    v_slot: np.ndarray
    a_slot: np.ndarray
    s_guide: np.ndarray
    v_guide: np.ndarray
    a_guide: np.ndarray
    det: object


def rpp(A: PointMotion, guide: LinkMotion, point=0j, angle=0.0, slot_angle=0.5 * math.pi
        ) -> RPPSolution:
    """Kinematics of the RPP group: block 2 pinned at A slides in the slot of yoke 3, the
    yoke slides on a guide of ``guide`` (local ``point``, ``angle``); the slot makes
    ``slot_angle`` [rad] with the guide (90°: the Scotch yoke).

    Notes
    -----
    ``A = G + y·u + x·w`` with ``w = u·e^{i·slot_angle}``: one 2×2 solve for y, x; the
    velocities and accelerations of the same form relative to the guide's link, with
    the Coriolis term ``2ω_j·i(ẏu + ẋw)`` [1]_.
    """
    G, u = _guide_line(guide, point, angle)
    w = u * complex(math.cos(slot_angle), math.sin(slot_angle))
    idet = _rinto(np.divide, 1.0, cross(u, w))     # (one 2×2 system: y, x and rates)
    y, x = _split(A.z - G, u, w, idet)
    zO = G + u * y
    Aj, Oj = coincident(guide, A.z), coincident(guide, zO)
    vy, vx = _split(A.v - Aj.v, u, w, idet)
    wj = guide.omega
    cor = (u * vy + w * vx).perp() * (2.0 * wj)
    ay, ax = _split(A.a - Aj.a - cor, u, w, idet)
    iu = u.perp()
    O = PointMotion(zO, Oj.v + u * vy, Oj.a + u * ay + iu * (2.0 * wj * vy))
    return RPPSolution(LinkMotion(A, w, wj, guide.eps), LinkMotion(O, u, wj, guide.eps),
                       x, vx, ax, y, vy, ay, cross(u, w))


@dataclass
class RPRReactions:
    """Reactions of an RPR group (block 2 at A, lever 3 pivoted at C). [N, N·m]

    ``RA``: force of the preceding link on the block at A; ``RC``: force at C on the lever
    (of the frame or the link C is on); ``N``: the lever's normal force on the block,
    signed along ``i·e`` (90° ccw from the slot); ``M``: the lever's couple on the block
    about A (the normal force acts on the line ``A + (M/N)·e``); the block's force on
    the lever is ``−N·ie`` (and ``−M``).
    """

    RA: Vec
    RC: Vec
    N: np.ndarray
    M: np.ndarray


def rpr_reactions(sol: RPRSolution, W2: Wrench, W3: Wrench) -> RPRReactions:
    """Kinetostatics of the RPR group.

    Notes
    -----
    The block's moments about A give the couple ``M = −M2(A)``; the lever's moments about
    C, ``M3(C) − N·s − M = 0`` (``(A − C) × ie = s``), give ``N``; the block's and the
    lever's force sums give ``RA = −(N·ie + F2)`` and ``RC = N·ie − F3`` [1]_.
    """
    zA, zC = sol.block.origin.z, sol.lever.origin.z
    ie = sol.lever.e.perp()
    M = -W2.moment_about(zA)
    N = (W3.moment_about(zC) - M) * (1.0 / sol.s)
    NF = ie * N
    RA = -(NF + W2.force)
    RC = NF - W3.force
    return RPRReactions(RA, RC, N, M)


@dataclass
class PRPReactions:
    """Reactions of a PRP group (links 2 and 3 pinned at B). [N, N·m]

    ``N1``, ``M1``: the first guide's normal force on link 2 (along ``i·u1``) and its
    couple about B; ``N2``, ``M2`` likewise on link 3; ``RB``: the force of link 3 on
    link 2 at B.
    """

    N1: np.ndarray
    M1: np.ndarray
    N2: np.ndarray
    M2: np.ndarray
    RB: Vec


def prp_reactions(sol: PRPSolution, W2: Wrench, W3: Wrench) -> PRPReactions:
    """Kinetostatics of the PRP group: the force polygon of both links gives
    ``N1·iu1 + N2·iu2 = −(F2 + F3)``; each link's moments about B give its couple;
    link 2's force sum gives ``RB = −(F2 + N1·iu1)`` [1]_."""
    zB = sol.B.z
    iu1, iu2 = sol.link2.e.perp(), sol.link3.e.perp()
    N1, N2 = _split(-(W2.force + W3.force), iu1, iu2)
    RB = -(W2.force + iu1 * N1)
    return PRPReactions(N1, -W2.moment_about(zB), N2, -W3.moment_about(zB), RB)


@dataclass
class RPPReactions:
    """Reactions of an RPP group (block 2 at A, yoke 3 on the guide). [N, N·m]

    ``RA``: force of the preceding link on the block at A; ``N``, ``M``: the yoke's normal
    force on the block (along ``i·w``, w the slot direction) and its couple about A;
    ``NG``, ``MG``: the guide's normal force on the yoke (along ``i·u``) and its couple
    about the yoke's origin.
    """

    RA: Vec
    N: np.ndarray
    M: np.ndarray
    NG: np.ndarray
    MG: np.ndarray


def rpp_reactions(sol: RPPSolution, W2: Wrench, W3: Wrench) -> RPPReactions:
    """Kinetostatics of the RPP group.

    Notes
    -----
    The yoke's force sum ``NG·iu − N·iw = −F3`` gives both normal forces; the block's
    moments about A its couple ``M = −M2(A)``; the block's force sum
    ``RA = −(N·iw + F2)``; the yoke's moments about its origin O3 the guide's couple
    ``MG = −M3(O3) + (A − O3) × (N·iw) + M`` [1]_.
    """
    zA, zO = sol.block.origin.z, sol.yoke.origin.z
    iw, iu = sol.block.e.perp(), sol.yoke.e.perp()
    NG, N = _split(-W3.force, iu, -iw)
    M = -W2.moment_about(zA)
    NF = iw * N
    RA = -(NF + W2.force)
    MG = -W3.moment_about(zO) + cross(zA - zO, NF) + M
    return RPPReactions(RA, N, M, NG, MG)
