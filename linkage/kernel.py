"""The fused table kernel behind :func:`linkage.analyze`.

:func:`linkage.analysis.solve_columns` assembles the tables from the group routines of
:mod:`linkage.groups` (complex arrays, a dataclass per group): the readable reference, and
the routines :mod:`engine` builds on.  For speed, :func:`linkage.analyze` evaluates the
very same equations with :class:`Kernel`: in real x/y arithmetic, every intermediate in a
preallocated cache-sized scratch array, every result written straight into its row of the
output block, chunk by chunk (whole-array numpy is memory-bound here).  Each step names
the group routine it mirrors and keeps its order of operations; the tests hold the kernel
against the group routines at 1e-12 relative and both against an independent global
Newton–Euler solve.
"""
from __future__ import annotations

import math

import numpy as np

from .columns import force_columns, kinematics_columns, point_names
from .derived import fill_derived
from .spec import LINK_NUMBER

__all__ = ["Kernel", "fill_blocks"]

_mul, _add, _sub, _div, _neg = np.multiply, np.add, np.subtract, np.divide, np.negative
_sqrt = np.sqrt


def _c(x):
    """A constant as a 0-d array (a numpy ufunc takes it faster than a Python float)."""
    return np.array(float(x))


class _LinkXY:
    """A link's motion inside the kernel (cf. :class:`linkage.groups.LinkMotion`).

    ``o`` is the origin's (x, y, vx, vy, ax, ay) as arrays, or None for an origin at rest
    at the constants ``(fx, fy)``; ``ex, ey`` the unit vector of the local x axis; ``w``,
    ``eps`` ω and ε (arrays, or 0-d constants for the crank; ``eps`` None when it is 0);
    ``nw`` = −ω, ``w2`` = ω², ``nw2`` = −ω², ``neps`` = −ε where needed.
    """

    __slots__ = ("o", "fx", "fy", "ex", "ey", "w", "nw", "w2", "nw2", "eps", "neps")

    def __init__(self, o, fx, fy, ex, ey, w, nw, w2, nw2, eps, neps):
        self.o, self.fx, self.fy, self.ex, self.ey = o, fx, fy, ex, ey
        self.w, self.nw, self.w2, self.nw2, self.eps, self.neps = w, nw, w2, nw2, eps, neps


class Kernel:
    """Kinematics and forces of one mechanism at a chunk of crank angles, in place.

    Built once per table (the spec, the mechanism, the extreme positions and every column
    index are resolved here); :meth:`run` then fills the output rows of one chunk.  The
    equations are those of :mod:`linkage.groups` (see each method); planar vectors are
    pairs of float arrays, ``cross(a, b) = a_x·b_y − a_y·b_x``, ``i·(x, y) = (−y, x)``.
    """

    def __init__(self, spec, mech, ext, size, course_tables=True):
        self.spec, self.mech, self.rocker = spec, mech, spec.kind == "crank-rocker"
        self.course_tables = course_tables
        kcols = [c for c in kinematics_columns(spec, course_tables) if c != "position"]
        fcols = [c for c in force_columns(spec, course_tables) if c != "position"]
        self.nk, self.nf = len(kcols), len(fcols)
        ki = {c: i for i, c in enumerate(kcols)}
        fi = {c: i for i, c in enumerate(fcols)}
        self.ki, self.fi = ki, fi
        self.kcols, self.fcols = kcols, fcols

        def six(p):
            return tuple(ki[f"{p}_{s}"] for s in ("x_m", "y_m", "vx_m_s", "vy_m_s",
                                                  "ax_m_s2", "ay_m_s2"))
        pts = point_names(spec)
        #: points other than A and B: (link name, rx, ry, their six kinematics rows)
        self.points = [(lname, local.real, local.imag, six(p))
                       for p, (lname, local) in pts.items() if p not in ("A", "B")]
        self.rowsA, self.rowsB = six("A"), six("B")
        self.rowsS = {lname: six(f"S{LINK_NUMBER[lname]}") for lname in spec.link_names}
        self.deg = _c(180.0 / math.pi)
        self.omega, self.epsilon = float(spec.omega), float(spec.epsilon)
        self.px, self.py = mech.pivot.real, mech.pivot.imag
        # loads: per link the forces (in order) and moments (in order), as in _external_loads
        self.forces = {n: [] for n in spec.link_names}
        self.moments = {n: [] for n in spec.link_names}
        self.resistances = []
        for ld in spec.loads:
            if ld.kind == "force":
                self.forces[ld.link].append(("force", ld))
            elif ld.kind == "moment":
                self.moments[ld.link].append(("moment", ld))
            else:
                self.resistances.append(ld)
                if self.rocker:
                    self.moments[ld.link].append(("resistance", ld))
                else:
                    self.forces[ld.link].append(("resistance", ld))
        # stroke state of a resistance (cf. _stroke_state): constants
        self.stroke = None
        if self.resistances:
            scale = abs(spec.omega) * (1.0 if self.rocker else spec.crank)
            self.thr = 1e-9 * scale
            if spec.working_stroke is not None and ext is not None:
                with np.errstate(divide="ignore", invalid="ignore"):
                    ek = mech.kinematics(np.array([ext.phi_start, ext.phi_end]),
                                         spec.omega, 0.0)
                c_start = mech.output_coordinate(ek)
                self.stroke = (mech._working_sign(spec.working_stroke),
                               float(c_start[0]), float(c_start[1]))
        if self.rocker:
            self.Cx, self.Cy = mech.zC.real, mech.zC.imag
        else:
            self.ux, self.uy = mech.u.real, mech.u.imag
            self.gx, self.gy = mech.pivot.real, mech.pivot.imag
        self.size = size
        self._names = ("c", "s", "t1", "t2", "dx", "dy", "D", "p", "h",
                       "r3x", "r3y", "r4x", "r4y", "det", "w3sq", "w4sq", "dax", "day",
                       "e3x", "e3y", "e4x", "e4y", "ce", "th4", "F2x", "F2y", "M2",
                       "F3x", "F3y", "M3", "F4x", "F4y", "M4", "te3x", "te3y", "te4x",
                       "te4y", "Gx", "Gy", "px", "py", "B1", "B2", "B3")
        self._names += tuple(f"val{j}" for j in range(len(self.resistances)))
        self._block = np.empty((len(self._names), size))
        self._full = dict(zip(self._names, self._block))

    def scratch(self, m):
        """Named scratch arrays of length ``m`` (views into one preallocated block)."""
        if m == self.size:
            return self._full
        return dict(zip(self._names, self._block[:, :m]))

    # -- kinematics --------------------------------------------------------------------
    def point(self, L, rx, ry, out, t):
        """Motion of the point with local coordinates (rx, ry) on link ``L`` into the six
        rows ``out`` (:meth:`linkage.groups.LinkMotion.point`)::

            r = (rx·e_x − ry·e_y, rx·e_y + ry·e_x)
            z = z_o + r,   v = v_o + ω·(−r_y, r_x),   a = a_o + ε·(−r_y, r_x) − ω²·r
        """
        x, y, vx, vy, ax, ay = out
        o = L.o
        if rx == 0.0 and ry == 0.0:  # the origin itself
            if o is None:
                x.fill(L.fx + 0.0); y.fill(L.fy + 0.0)
                vx.fill(0.0); vy.fill(0.0); ax.fill(0.0); ay.fill(0.0)
            else:
                for dst, src in zip(out, o):
                    np.copyto(dst, src)
            return
        _mul(L.ex, rx, out=x)
        _mul(L.ey, rx, out=y)
        if ry != 0.0:
            _sub(x, _mul(L.ey, ry, out=t), out=x)
            _add(y, _mul(L.ex, ry, out=t), out=y)
        _mul(y, L.nw, out=vx)
        _mul(x, L.w, out=vy)
        if L.eps is None:                  # ε = 0: a = a_o − ω²·r
            _mul(x, L.nw2, out=ax)
            _mul(y, L.nw2, out=ay)
        elif o is None:                    # origin at rest: a = ε·(−r_y, r_x) − ω²·r
            _sub(_mul(y, L.neps, out=ax), _mul(x, L.w2, out=t), out=ax)
            _sub(_mul(x, L.eps, out=ay), _mul(y, L.w2, out=t), out=ay)
        else:
            _sub(o[4], _mul(y, L.eps, out=ax), out=ax)
            _sub(ax, _mul(x, L.w2, out=t), out=ax)
            _add(o[5], _mul(x, L.eps, out=ay), out=ay)
            _sub(ay, _mul(y, L.w2, out=t), out=ay)
        if o is None:
            if L.fx != 0.0:
                _add(x, L.fx, out=x)
            if L.fy != 0.0:
                _add(y, L.fy, out=y)
        else:
            if L.eps is None:
                _add(o[4], ax, out=ax)
                _add(o[5], ay, out=ay)
            _add(o[0], x, out=x); _add(o[1], y, out=y)
            _add(o[2], vx, out=vx); _add(o[3], vy, out=vy)

    def point_z(self, L, rx, ry, x, y, t):
        """Position only of the point (rx, ry) on link ``L``: ``z = z_o + r``."""
        _mul(L.ex, rx, out=x)
        _mul(L.ey, rx, out=y)
        if ry != 0.0:
            _sub(x, _mul(L.ey, ry, out=t), out=x)
            _add(y, _mul(L.ex, ry, out=t), out=y)
        if L.o is None:
            if L.fx != 0.0:
                _add(x, L.fx, out=x)
            if L.fy != 0.0:
                _add(y, L.fy, out=y)
        else:
            _add(L.o[0], x, out=x); _add(L.o[1], y, out=y)

    def driver(self, phi, K, T):
        """Driver I(1,2) (:func:`linkage.groups.crank`): ``e = (cos φ, sin φ)`` and the
        crank pin A = ``point(l1, 0)`` of the crank, whose origin O is at rest."""
        c, s = T["c"], T["s"]
        np.cos(phi, out=c)
        np.sin(phi, out=s)
        w, eps = self.omega, self.epsilon
        crank = _LinkXY(None, self.px, self.py, c, s, _c(w), _c(-w), _c(w * w), _c(-(w * w)),
                        None if eps == 0.0 else _c(eps), _c(-eps))
        self.point(crank, self.mech.l1, 0.0, [K[i] for i in self.rowsA], T["t1"])
        return crank

    def rrr(self, A, K, T):
        """RRR dyad (:func:`linkage.groups.rrr`), C at rest.  With d = C − A, D = |d|::

            p = (l3² − l4² + D²)/(2D),  h = √max(l3² − p², 0),  B = A + (p + i·asm·h)·d/D
            r3 = B − A,  r4 = B − C,  det = r3 × r4
            ω3 = r4·(−v_A)/det,  ω4 = r3·(−v_A)/det
            Δa = −a_A + ω3²·r3 − ω4²·r4,  ε3 = r4·Δa/det,  ε4 = r3·Δa/det
            v_B = v_A + ω3·i·r3,  a_B = a_A + (i·ε3 − ω3²)·r3
        """
        m = self.mech
        ki = self.ki
        Ax, Ay, Avx, Avy, Aax, Aay = A
        Bx, By, Bvx, Bvy, Bax, Bay = (K[i] for i in self.rowsB)
        w3, e3, w4, e4 = (K[ki[c]] for c in ("omega3_rad_s", "eps3_rad_s2",
                                             "omega4_rad_s", "eps4_rad_s2"))
        t1, t2, dx, dy, D, p, h = (T[n] for n in ("t1", "t2", "dx", "dy", "D", "p", "h"))
        l3, l4 = m.l2, m.l3
        _sub(self.Cx, Ax, out=dx)
        _sub(self.Cy, Ay, out=dy)
        D2 = _add(_mul(dx, dx, out=D), _mul(dy, dy, out=t1), out=D)
        _div(_add(D2, l3 * l3 - l4 * l4, out=p), _mul(_sqrt(D2, out=D), 2.0, out=t1), out=p)
        _sub(l3 * l3, _mul(p, p, out=h), out=h)                     # h² (squared height)
        _sqrt(np.maximum(h, 0.0, out=h), out=h)
        _div(1.0, D, out=D)                                          # 1/D: d/D = d·(1/D)
        _mul(dx, D, out=dx)
        _mul(dy, D, out=dy)                                          # (dx, dy) = d/D now
        # B = A + (p·dx − ah·dy, p·dy + ah·dx),  ah = asm·h
        _mul(p, dx, out=Bx); _mul(h, dy, out=t1)
        _mul(p, dy, out=By); _mul(h, dx, out=t2)
        if m.assembly > 0:
            _sub(Bx, t1, out=Bx); _add(By, t2, out=By)
        else:
            _add(Bx, t1, out=Bx); _sub(By, t2, out=By)
        _add(Ax, Bx, out=Bx); _add(Ay, By, out=By)
        r3x, r3y, r4x, r4y, det = (T[n] for n in ("r3x", "r3y", "r4x", "r4y", "det"))
        _sub(Bx, Ax, out=r3x); _sub(By, Ay, out=r3y)
        _sub(Bx, self.Cx, out=r4x); _sub(By, self.Cy, out=r4y)
        _sub(_mul(r3x, r4y, out=det), _mul(r3y, r4x, out=t1), out=det)
        _neg(det, out=det)                                           # −det from here on
        # ω3 = r4·(−vA)/det = (r4·vA)/(−det); likewise ω4
        _div(_add(_mul(r4x, Avx, out=w3), _mul(r4y, Avy, out=t1), out=w3), det, out=w3)
        _div(_add(_mul(r3x, Avx, out=w4), _mul(r3y, Avy, out=t1), out=w4), det, out=w4)
        w3sq, w4sq, dax, day = (T[n] for n in ("w3sq", "w4sq", "dax", "day"))
        _mul(w3, w3, out=w3sq); _mul(w4, w4, out=w4sq)
        _sub(_sub(_mul(w3sq, r3x, out=dax), Aax, out=dax), _mul(w4sq, r4x, out=t1), out=dax)
        _sub(_sub(_mul(w3sq, r3y, out=day), Aay, out=day), _mul(w4sq, r4y, out=t1), out=day)
        _neg(det, out=det)                                           # det again
        _div(_add(_mul(r4x, dax, out=e3), _mul(r4y, day, out=t1), out=e3), det, out=e3)
        _div(_add(_mul(r3x, dax, out=e4), _mul(r3y, day, out=t1), out=e4), det, out=e4)
        _sub(Avx, _mul(w3, r3y, out=Bvx), out=Bvx)
        _add(Avy, _mul(w3, r3x, out=Bvy), out=Bvy)
        _sub(Aax, _add(_mul(w3sq, r3x, out=Bax), _mul(e3, r3y, out=t1), out=Bax), out=Bax)
        _add(Aay, _sub(_mul(e3, r3x, out=Bay), _mul(w3sq, r3y, out=t1), out=Bay), out=Bay)
        # unit vectors of the links: e3 = r3/l3, e4 = r4/l4 (as r·(1/l))
        e3x, e3y, e4x, e4y = (T[n] for n in ("e3x", "e3y", "e4x", "e4y"))
        i3, i4 = 1.0 / l3, 1.0 / l4
        _mul(r3x, i3, out=e3x); _mul(r3y, i3, out=e3y)
        _mul(r4x, i4, out=e4x); _mul(r4y, i4, out=e4y)
        coupler = _LinkXY(A, 0.0, 0.0, e3x, e3y, w3, None, w3sq, None, e3, None)
        rocker = _LinkXY(None, self.Cx, self.Cy, e4x, e4y, w4, None, w4sq, None, e4, None)
        _neg(w3, out=T["B1"]); coupler.nw = T["B1"]
        _neg(w4, out=T["B2"]); rocker.nw = T["B2"]
        _neg(e4, out=T["B3"]); rocker.neps = T["B3"]
        # angles, output coordinate θ4 [rad] and the transmission angle
        deg = self.deg
        _mul(np.arctan2(e3y, e3x, out=t1), deg, out=K[ki["theta3_deg"]])
        th4 = np.arctan2(e4y, e4x, out=T["th4"])
        _mul(th4, deg, out=K[ki["theta4_deg"]])
        ce = T["ce"]                                                 # cross(e3, e4)
        _sub(_mul(e3x, e4y, out=ce), _mul(e3y, e4x, out=t1), out=ce)
        _add(_mul(e3x, e4x, out=t1), _mul(e3y, e4y, out=t2), out=t1)
        mu = np.arctan2(np.absolute(ce, out=t2), np.absolute(t1, out=t1), out=t1)
        _mul(mu, deg, out=K[ki["mu_deg"]])
        return coupler, rocker, w4, th4

    def rrp(self, A, K, T):
        """RRP dyad (:func:`linkage.groups.rrp`).  In guide coordinates (origin at the pivot
        O, x along u) A = (x_A, y_A) and::

            s = x_A + asm·√max(L² − (offset − y_A)², 0),   B = O + (s + i·offset)·u
            r3 = B − A,  den = u·r3,  ω3 = −(u × v_A)/den,  v = u·(v_A + ω3·i·r3)
            q = a_A − ω3²·r3,  ε3 = −(u × q)/den,  a = u·(q + ε3·i·r3)
        """
        m = self.mech
        ki = self.ki
        ux, uy, gx, gy = self.ux, self.uy, self.gx, self.gy
        Ax, Ay, Avx, Avy, Aax, Aay = A
        Bx, By, Bvx, Bvy, Bax, Bay = (K[i] for i in self.rowsB)
        s, v, a = K[ki["s4_m"]], K[ki["v4_m_s"]], K[ki["a4_m_s2"]]
        w3, e3 = K[ki["omega3_rad_s"]], K[ki["eps3_rad_s2"]]
        t1, t2, dx, dy, h = (T[n] for n in ("t1", "t2", "dx", "dy", "h"))
        L, off = m.l2, m.offset
        # (dx, dy) = (A − O)·conj(u)
        ax_, ay_ = (Ax, Ay) if gx == 0.0 and gy == 0.0 else (
            _sub(Ax, gx, out=T["B1"]), _sub(Ay, gy, out=T["B2"]))
        if uy == 0.0 and ux == 1.0:
            dx, dy = ax_, ay_
        else:
            _add(_mul(ax_, ux, out=dx), _mul(ay_, uy, out=t1), out=dx)
            _sub(_mul(ay_, ux, out=dy), _mul(ax_, uy, out=t1), out=dy)
        _sub(off, dy, out=h)
        _sub(L * L, _mul(h, h, out=h), out=h)
        _sqrt(np.maximum(h, 0.0, out=h), out=h)
        (_add if m.assembly > 0 else _sub)(dx, h, out=s)
        # B = O + (s·ux − off·uy, s·uy + off·ux)
        _add(_mul(s, ux, out=Bx), gx - off * uy, out=Bx)
        _add(_mul(s, uy, out=By), gy + off * ux, out=By)
        r3x, r3y, den = T["r3x"], T["r3y"], T["det"]
        _sub(Bx, Ax, out=r3x); _sub(By, Ay, out=r3y)
        _add(_mul(r3x, ux, out=den), _mul(r3y, uy, out=t1), out=den)  # u·r3
        _neg(den, out=den)                                           # −den
        _div(_sub(_mul(Avy, ux, out=w3), _mul(Avx, uy, out=t1), out=w3), den, out=w3)
        _sub(Avx, _mul(w3, r3y, out=Bvx), out=Bvx)                   # v_A + ω3·i·r3
        _add(Avy, _mul(w3, r3x, out=Bvy), out=Bvy)
        _add(_mul(Bvx, ux, out=v), _mul(Bvy, uy, out=t1), out=v)
        w3sq, qx, qy = T["w3sq"], T["dax"], T["day"]
        _mul(w3, w3, out=w3sq)
        _sub(Aax, _mul(w3sq, r3x, out=qx), out=qx)
        _sub(Aay, _mul(w3sq, r3y, out=qy), out=qy)
        _div(_sub(_mul(qy, ux, out=e3), _mul(qx, uy, out=t1), out=e3), den, out=e3)
        _sub(qx, _mul(e3, r3y, out=t1), out=qx)                      # q + ε3·i·r3
        _add(qy, _mul(e3, r3x, out=t1), out=qy)
        _add(_mul(qx, ux, out=a), _mul(qy, uy, out=t1), out=a)
        _mul(v, ux, out=Bvx); _mul(v, uy, out=Bvy)
        _mul(a, ux, out=Bax); _mul(a, uy, out=Bay)
        e3x, e3y = T["e3x"], T["e3y"]
        iL = 1.0 / L
        _mul(r3x, iL, out=e3x); _mul(r3y, iL, out=e3y)
        coupler = _LinkXY(A, 0.0, 0.0, e3x, e3y, w3, None, w3sq, None, e3, None)
        _neg(w3, out=T["B3"]); coupler.nw = T["B3"]
        deg = self.deg
        _mul(np.arctan2(e3y, e3x, out=t1), deg, out=K[ki["theta3_deg"]])
        ce = T["ce"]                                                 # e3·u (= cross(e3, i·u))
        _add(_mul(e3x, ux, out=ce), _mul(e3y, uy, out=t1), out=ce)
        _sub(_mul(e3x, uy, out=t1), _mul(e3y, ux, out=t2), out=t1)   # e3 × u
        mu = np.arctan2(np.absolute(ce, out=t2), np.absolute(t1, out=t1), out=t1)
        _mul(mu, deg, out=K[ki["mu_deg"]])
        return coupler, v, s

    def slider_point(self, rx, ry, out, B):
        """A point of the slider (ω = ε = 0, x axis u): ``z = z_B + r``, ``v = v_B``,
        ``a = a_B``."""
        ux, uy = self.ux, self.uy
        if rx == 0.0 and ry == 0.0:
            for dst, src in zip(out, B):
                np.copyto(dst, src)
            return
        _add(B[0], rx * ux - ry * uy, out=out[0])
        _add(B[1], rx * uy + ry * ux, out=out[1])
        for dst, src in zip(out[2:], B[2:]):
            np.copyto(dst, src)

    # -- loads -------------------------------------------------------------------------
    def resistance_values(self, rate, coord, T):
        """The useful resistances (cf. :func:`_stroke_state`, :func:`_external_loads`): each
        acts against the output's motion, ``−sign(rate)·R``, where the output moves (|rate|
        above 1e-9 of its scale) in the load's stroke and, with a span, only while the swing
        (wrapped to [0, π]) or travel from the start of the current stroke is within it."""
        t1, t2 = T["t1"], T["t2"]
        moving = np.greater(np.absolute(rate, out=t1), self.thr)
        vals = []
        if self.stroke is None:  # no working stroke known: every resistance acts as "both"
            sgn = np.sign(rate, out=t2)
            for j, ld in enumerate(self.resistances):
                vals.append(np.where(moving, _mul(sgn, -ld.resistance, out=T[f"val{j}"]),
                                     0.0))
            return vals
        wsign, c0, c1 = self.stroke
        fwd = np.greater(rate, 0.0) if wsign > 0 else np.less(rate, 0.0)
        work = moving & fwd                    # state > 0: working stroke
        idle = moving & ~fwd                   # state < 0: idle stroke
        travel = None
        for j, ld in enumerate(self.resistances):
            if ld.stroke == "both":
                out = _mul(np.sign(rate, out=t2), -ld.resistance, out=T[f"val{j}"])
                active = moving
                k = None
            else:
                active = work if ld.stroke == "working" else idle
                # there sign(rate) = ±wsign, so −sign(rate)·R is a constant
                k = -wsign * ld.resistance if ld.stroke == "working" else wsign * ld.resistance
            if ld.span is not None:
                if travel is None:
                    start = np.where(idle, c1, c0)
                    travel = np.absolute(_sub(coord, start, out=t1), out=t1)
                    if self.rocker:  # |angle(exp(i·Δθ))| = min(|Δθ|, 2π − |Δθ|) for |Δθ| ≤ 2π
                        np.minimum(travel, _sub(2 * math.pi, travel, out=t2), out=travel)
                active = active & np.less_equal(travel, ld.span * (1 + 1e-12))
            vals.append(np.where(active, k if k is not None else out, 0.0))
        return vals

    def wrench(self, lname, L, K, T, Fx, Fy, M, vals, B):
        """Resultant load on one link at its centre of mass S (:func:`linkage.groups.
        link_wrench`): ``F = −m·a_S − m·g·j + ΣF_k``, ``M = −J_S·ε + Σ(r_k − S) × F_k +
        ΣM_k``.  Writes Fx, Fy, M (arrays); returns S's six rows."""
        ls = self.spec.links[lname]
        S = [K[i] for i in self.rowsS[lname]]
        _mul(S[4], -ls.mass, out=Fx)
        _mul(S[5], -ls.mass, out=Fy)
        mg = ls.mass * self.spec.gravity
        if mg != 0.0:
            _sub(Fy, mg, out=Fy)
        if lname == "crank":
            M.fill(-ls.inertia * self.epsilon)
        elif lname == "slider":
            M.fill(-ls.inertia * 0.0)
        else:
            _mul(L.eps, -ls.inertia, out=M)
        t1, t2, px, py = T["t1"], T["t2"], T["px"], T["py"]
        for kind, ld in self.forces[lname]:
            if kind == "force":
                fx, fy = ld.force.real, ld.force.imag
                _add(Fx, fx, out=Fx)
                _add(Fy, fy, out=Fy)
                if lname == "slider":
                    self.slider_point_z(ld.at.real, ld.at.imag, px, py, B)
                else:
                    self.point_z(L, ld.at.real, ld.at.imag, px, py, t1)
                # M += cross(at − S, f)
                _sub(_mul(_sub(px, S[0], out=px), fy, out=px),
                     _mul(_sub(py, S[1], out=py), fx, out=py), out=px)
                _add(M, px, out=M)
            else:  # a slider's resistance: value·u at the pin B
                v = vals[self.resistances.index(ld)]
                fx = _mul(v, self.ux, out=t1)
                fy = _mul(v, self.uy, out=t2)
                _add(Fx, fx, out=Fx)
                _add(Fy, fy, out=Fy)
                _sub(_mul(_sub(B[0], S[0], out=px), fy, out=px),
                     _mul(_sub(B[1], S[1], out=py), fx, out=py), out=px)
                _add(M, px, out=M)
        for kind, ld in self.moments[lname]:
            _add(M, ld.moment if kind == "moment" else vals[self.resistances.index(ld)],
                 out=M)
        return S

    def slider_point_z(self, rx, ry, x, y, B):
        """Position only of a point of the slider: ``z = z_B + r``."""
        ux, uy = self.ux, self.uy
        _add(B[0], rx * ux - ry * uy, out=x)
        _add(B[1], rx * uy + ry * ux, out=y)

    # -- kinetostatics -----------------------------------------------------------------
    @staticmethod
    def moment_about(M, S, F, q, out, t):
        """Moment of a wrench (M at S, force F) about the point q: ``M + (S − q) × F``."""
        _sub(_mul(_sub(S[0], q[0], out=out), F[1], out=out),
             _mul(_sub(S[1], q[1], out=t), F[0], out=t), out=out)
        return _add(M, out, out=out)

    def rrr_reactions(self, K, Fo, T, B, W3, W4):
        """RRR dyad (:func:`linkage.groups.rrr_reactions`)::

            R23t = M3(B)/l3,  R14t = M4(B)/l4,  G = F3 + F4 + R23t·i·e3 + R14t·i·e4
            (R23n, R14n) from R23n·e3 + R14n·e4 = −G:
                R23n = (G × e4)/(−e3 × e4),  R14n = (e3 × G)/(−e3 × e4)
            R23 = R23n·e3 + R23t·i·e3,  R14 = R14n·e4 + R14t·i·e4,  R43 = −(R23 + F3)
        """
        fi, m = self.fi, self.mech
        t1, t2 = T["t1"], T["t2"]
        e3x, e3y, e4x, e4y, ce = (T[n] for n in ("e3x", "e3y", "e4x", "e4y", "ce"))
        (S3, F3x, F3y, M3), (S4, F4x, F4y, M4) = W3, W4
        t3, t4 = Fo[fi["R23_t_N"]], Fo[fi["R14_t_N"]]
        n3, n4 = Fo[fi["R23_n_N"]], Fo[fi["R14_n_N"]]
        _div(self.moment_about(M3, S3, (F3x, F3y), B, t3, t1), m.l2, out=t3)
        _div(self.moment_about(M4, S4, (F4x, F4y), B, t4, t1), m.l3, out=t4)
        te3x, te3y, te4x, te4y, Gx, Gy = (T[n] for n in ("te3x", "te3y", "te4x", "te4y",
                                                         "Gx", "Gy"))
        _mul(t3, e3x, out=te3x); _mul(t3, e3y, out=te3y)
        _mul(t4, e4x, out=te4x); _mul(t4, e4y, out=te4y)
        _sub(_sub(_add(F3x, F4x, out=Gx), te3y, out=Gx), te4y, out=Gx)
        _add(_add(_add(F3y, F4y, out=Gy), te3x, out=Gy), te4x, out=Gy)
        _neg(ce, out=t2)                                             # −(e3 × e4)
        _div(_sub(_mul(Gx, e4y, out=n3), _mul(Gy, e4x, out=t1), out=n3), t2, out=n3)
        _div(_sub(_mul(e3x, Gy, out=n4), _mul(e3y, Gx, out=t1), out=n4), t2, out=n4)
        RAx, RAy = Fo[fi["R23_x_N"]], Fo[fi["R23_y_N"]]
        RCx, RCy = Fo[fi["R14_x_N"]], Fo[fi["R14_y_N"]]
        _sub(_mul(n3, e3x, out=RAx), te3y, out=RAx)
        _add(_mul(n3, e3y, out=RAy), te3x, out=RAy)
        _sub(_mul(n4, e4x, out=RCx), te4y, out=RCx)
        _add(_mul(n4, e4y, out=RCy), te4x, out=RCy)
        _neg(_add(RAx, F3x, out=Fo[fi["R43_x_N"]]), out=Fo[fi["R43_x_N"]])
        _neg(_add(RAy, F3y, out=Fo[fi["R43_y_N"]]), out=Fo[fi["R43_y_N"]])
        return RAx, RAy

    def rrp_reactions(self, K, Fo, T, B, W3, W4):
        """RRP dyad (:func:`linkage.groups.rrp_reactions`), guide direction u::

            R23t = M3(B)/L,  G = F3 + F4 + R23t·i·e3
            (R23n, N14) from R23n·e3 + N14·i·u = −G:
                R23n = (G·u)/(−e3·u),  N14 = (e3 × G)/(−e3·u)
            R23 = R23n·e3 + R23t·i·e3,  R14 = N14·i·u,  R43 = −(R23 + F3),
            M14 = −M4(B)
        """
        fi, ux, uy = self.fi, self.ux, self.uy
        t1, t2 = T["t1"], T["t2"]
        e3x, e3y, ce = T["e3x"], T["e3y"], T["ce"]
        (S3, F3x, F3y, M3), (S4, F4x, F4y, M4) = W3, W4
        t3, n3, nG = Fo[fi["R23_t_N"]], Fo[fi["R23_n_N"]], Fo[fi["N14_N"]]
        _div(self.moment_about(M3, S3, (F3x, F3y), B, t3, t1), self.mech.l2, out=t3)
        te3x, te3y, Gx, Gy = T["te3x"], T["te3y"], T["Gx"], T["Gy"]
        _mul(t3, e3x, out=te3x); _mul(t3, e3y, out=te3y)
        _sub(_add(F3x, F4x, out=Gx), te3y, out=Gx)
        _add(_add(F3y, F4y, out=Gy), te3x, out=Gy)
        _neg(ce, out=t2)                                             # −(e3·u)
        _div(_add(_mul(Gx, ux, out=n3), _mul(Gy, uy, out=t1), out=n3), t2, out=n3)
        _div(_sub(_mul(e3x, Gy, out=nG), _mul(e3y, Gx, out=t1), out=nG), t2, out=nG)
        RAx, RAy = Fo[fi["R23_x_N"]], Fo[fi["R23_y_N"]]
        _sub(_mul(n3, e3x, out=RAx), te3y, out=RAx)
        _add(_mul(n3, e3y, out=RAy), te3x, out=RAy)
        _mul(nG, -uy, out=Fo[fi["R14_x_N"]])
        _mul(nG, ux, out=Fo[fi["R14_y_N"]])
        _neg(_add(RAx, F3x, out=Fo[fi["R43_x_N"]]), out=Fo[fi["R43_x_N"]])
        _neg(_add(RAy, F3y, out=Fo[fi["R43_y_N"]]), out=Fo[fi["R43_y_N"]])
        MG = Fo[fi["M14_Nm"]]
        _neg(self.moment_about(M4, S4, (F4x, F4y), B, MG, t1), out=MG)
        return RAx, RAy

    def driver_reactions(self, K, Fo, T, RA, W2):
        """Driver (:func:`linkage.groups.driver_reactions`) with R32 = −R23::

            R12 = −(R32 + F2) = R23 − F2,   M_drive = (A − O) × R23 − M2(O)
        """
        fi = self.fi
        (S2, F2x, F2y, M2) = W2
        RAx, RAy = RA
        t1, t2 = T["t1"], T["t2"]
        _sub(RAx, F2x, out=Fo[fi["R12_x_N"]])
        _sub(RAy, F2y, out=Fo[fi["R12_y_N"]])
        Ax, Ay = K[self.rowsA[0]], K[self.rowsA[1]]
        if self.px != 0.0 or self.py != 0.0:
            Ax, Ay = _sub(Ax, self.px, out=T["B1"]), _sub(Ay, self.py, out=T["B2"])
        Md = Fo[fi["M_drive_Nm"]]
        _sub(_mul(Ax, RAy, out=Md), _mul(Ay, RAx, out=t1), out=Md)
        O = (self.px, self.py)
        _sub(Md, self.moment_about(M2, S2, (F2x, F2y), O, t1, t2), out=Md)

    # -- one chunk ---------------------------------------------------------------------
    def run(self, phi, K, Fo):
        """Fill the kinematics rows ``K`` and force rows ``Fo`` (lists of arrays of
        ``len(phi)``, in column order) at crank angles ``phi`` [rad]."""
        T = self.scratch(len(phi))
        ki, fi = self.ki, self.fi
        _mul(phi, self.deg, out=K[ki["phi_deg"]])
        np.copyto(Fo[fi["phi_deg"]], K[ki["phi_deg"]])
        crank = self.driver(phi, K, T)
        A = [K[i] for i in self.rowsA]
        B = [K[i] for i in self.rowsB]
        if self.rocker:
            coupler, out_link, rate, coord = self.rrr(A, K, T)
            links = {"crank": crank, "coupler": coupler, "rocker": out_link}
        else:
            coupler, rate, coord = self.rrp(A, K, T)
            links = {"crank": crank, "coupler": coupler}
        for lname, rx, ry, rows in self.points:
            out = [K[i] for i in rows]
            if lname == "slider":
                self.slider_point(rx, ry, out, B)
            else:
                self.point(links[lname], rx, ry, out, T["t1"])
        vals = self.resistance_values(rate, coord, T) if self.resistances else []
        res = Fo[fi["M_res_Nm" if self.rocker else "F_res_N"]]
        res.fill(0.0)
        for v in vals:
            _add(res, v, out=res)
        W = {}
        for lname, (fx, fy, mm) in zip(self.spec.link_names,
                                       (("F2x", "F2y", "M2"), ("F3x", "F3y", "M3"),
                                        ("F4x", "F4y", "M4"))):
            Fx, Fy, M = T[fx], T[fy], T[mm]
            S = self.wrench(lname, links.get(lname), K, T, Fx, Fy, M, vals, B)
            W[lname] = (S, Fx, Fy, M)
        out_name = "rocker" if self.rocker else "slider"
        if self.rocker:
            RA = self.rrr_reactions(K, Fo, T, B, W["coupler"], W[out_name])
        else:
            RA = self.rrp_reactions(K, Fo, T, B, W["coupler"], W[out_name])
        self.driver_reactions(K, Fo, T, RA, W["crank"])
        if self.course_tables:
            fill_derived(self.spec, dict(zip(self.kcols, K)), dict(zip(self.fcols, Fo)),
                         T["t1"])


def fill_blocks(kernel, phi, kblock, fblock):
    """Run ``kernel`` over ``phi`` [rad] in chunks of its size, into the rows of ``kblock``
    (kinematics columns × positions) and ``fblock`` (force columns × positions)."""
    n, chunk = len(phi), kernel.size
    krows, frows = list(kblock), list(fblock)
    with np.errstate(divide="ignore", invalid="ignore"):
        for start in range(0, n, chunk):
            stop = min(n, start + chunk)
            kernel.run(phi[start:stop], [r[start:stop] for r in krows],
                       [r[start:stop] for r in frows])
