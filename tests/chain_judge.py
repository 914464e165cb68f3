"""An independent judge of linkage.chain (a helper module, not a test file).

Nothing here runs linkage's group routines: it reads a :class:`linkage.chain.Mechanism` as
data (its links, joints, guides and the local frames the chain's docs define) and
computes, at one crank angle:

* the positions of every link by a numeric loop-closure solve of the WHOLE mechanism at
  once (:func:`scipy.optimize.root`, then Newton polish): generalized coordinates
  ``(x, y, θ)`` of every moving link's local frame, two constraint equations per pair
  (a revolute: the two points coincide; a prismatic: the slider's point on the guide's
  line and the two angles fixed to each other) and ``θ_crank = φ``;
* velocities and accelerations by finite differences of those positions over φ (five
  point stencils; ``q̇ = q'·ω``, ``q̈ = q''·ω² + q'·ε``);
* every pair's reaction and the driving moment from ONE linear system per position:
  three Newton–Euler equations per moving link (ΣFx, ΣFy, ΣM about the global origin),
  with d'Alembert inertia and weight; unknowns: two per pair (a revolute: both force
  components; a prismatic: the normal force and its couple) and the driving moment.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import root

FRAME = "frame"


def _e(t):
    return complex(math.cos(t), math.sin(t))


def _cross(a, b):
    return a.real * b.imag - a.imag * b.real


class Judge:
    """The constraint model of a chain ``mech`` (read as data)."""

    def __init__(self, mech, gravity=9.81):
        self.mech = mech
        self.g = gravity
        self.names = list(mech.link_names)
        self.idx = {n: k for k, n in enumerate(self.names)}
        d = mech.driver
        owner = {j: (FRAME, z) for j, z in mech.frame.items()}
        owner[d.joint] = (d.link, complex(d.length))
        for ln in self.names:
            for p, loc in mech.links[ln].points.items():
                owner.setdefault(p, (ln, complex(loc)))
        # pairs: ("R", a, pa, b, pb) or ("P", a, ga, alpha, b, pb)  (a: guide/first link)
        pairs = [("R", FRAME, mech.frame[d.pivot], d.link, 0j)]
        for grp in mech.groups:
            l2, l3 = grp.links
            k = grp.kind
            if k == "RRR":
                A, B, C = grp.joints
                pairs += [("R", *owner[A], l2, 0j),
                          ("R", l2, complex(grp.lengths[0]), l3, complex(grp.lengths[1])),
                          ("R", *owner[C], l3, 0j)]
                owner.setdefault(B, (l3, complex(grp.lengths[1])))
            elif k == "RRP":
                A, B = grp.joints
                gd = grp.guide
                pairs += [("R", *owner[A], l2, 0j), ("R", l2, complex(grp.length), l3, 0j),
                          ("P", gd.link, _shift(gd), gd.angle, l3, 0j)]
                owner.setdefault(B, (l3, 0j))
            elif k == "RPR":
                A, C = grp.joints
                pairs += [("R", *owner[A], l2, 0j),
                          ("P", l3, 1j * grp.offset, 0.0, l2, 0j),
                          ("R", *owner[C], l3, 0j)]
            elif k == "PRP":
                (B,) = grp.joints
                g1, g2 = grp.guides
                pairs += [("P", g1.link, _shift(g1), g1.angle, l2, 0j),
                          ("R", l2, 0j, l3, 0j),
                          ("P", g2.link, _shift(g2), g2.angle, l3, 0j)]
                owner.setdefault(B, (l3, 0j))
            else:  # RPP
                (A,) = grp.joints
                gd = grp.guide
                pairs += [("R", *owner[A], l2, 0j),
                          ("P", l3, 0j, grp.slot_angle, l2, 0j),
                          ("P", gd.link, _shift(gd), gd.angle, l3, 0j)]
        self.pairs = pairs
        assert 2 * len(pairs) + 1 == 3 * len(self.names)

    # -- poses
    def pose(self, q, name):
        """(origin, angle) of a link (the frame: 0, 0)."""
        if name == FRAME:
            return 0j, 0.0
        k = 3 * self.idx[name]
        return complex(q[k], q[k + 1]), q[k + 2]

    def world(self, q, name, local):
        o, t = self.pose(q, name)
        return o + complex(local) * _e(t) if name != FRAME else complex(local)

    def residual(self, q, phi):
        out = [q[3 * self.idx[self.mech.driver.link] + 2] - phi]
        for p in self.pairs:
            if p[0] == "R":
                _, a, pa, b, pb = p
                r = self.world(q, a, pa) - self.world(q, b, pb)
                out += [r.real, r.imag]
            else:
                _, a, ga, alpha, b, pb = p
                _, ta = self.pose(q, a)
                _, tb = self.pose(q, b)
                u = _e(ta + alpha)
                out += [_cross(u, self.world(q, b, pb) - self.world(q, a, ga)),
                        math.sin(tb - ta - alpha)]
        return np.array(out)

    def positions(self, phi, guess):
        """Generalized coordinates at crank angle ``phi`` from a guess (numeric solve)."""
        sol = root(self.residual, guess, args=(phi,), method="hybr", tol=1e-14)
        q = sol.x
        # Newton polish with a central-difference Jacobian, taken once at hybr's solution
        # (a chord iteration: from a start already within ~1e-14 of the root it converges
        # to rounding in one or two steps, as a Jacobian taken anew at each step did)
        f = self.residual(q, phi)
        J = np.empty((len(f), len(q)))
        for i in range(len(q)):
            dq = np.zeros(len(q))
            dq[i] = 1e-7
            J[:, i] = (self.residual(q + dq, phi) - self.residual(q - dq, phi)) / 2e-7
        for _ in range(4):
            q = q - np.linalg.solve(J, f)
            f = self.residual(q, phi)
        assert np.max(np.abs(f)) < 1e-12
        return q

    def motion(self, phi, guess, omega, eps, h=1e-3):
        """(q, q̇, q̈) at ``phi``: positions by the loop-closure solve, their time
        derivatives by five-point finite differences over φ."""
        qs = {}
        q0 = self.positions(phi, guess)
        for k in (-2, -1, 1, 2):
            qs[k] = self.positions(phi + k * h, q0)
        d1 = (qs[-2] - 8 * qs[-1] + 8 * qs[1] - qs[2]) / (12 * h)
        d2 = (-qs[-2] + 16 * qs[-1] - 30 * q0 + 16 * qs[1] - qs[2]) / (12 * h * h)
        return q0, d1 * omega, d2 * omega * omega + d1 * eps

    def point_motion(self, q, qd, qdd, name, local):
        """(z, v, a) of a link's local point from the generalized coordinates."""
        if name == FRAME:
            return complex(local), 0j, 0j
        k = 3 * self.idx[name]
        o, t = complex(q[k], q[k + 1]), q[k + 2]
        r = complex(local) * _e(t)
        w, e = qd[k + 2], qdd[k + 2]
        return (o + r, complex(qd[k], qd[k + 1]) + 1j * w * r,
                complex(qdd[k], qdd[k + 1]) + (1j * e - w * w) * r)

    def forces(self, q, qd, qdd, applied=(), couples=()):
        """Reactions of every pair and the driving moment by one global Newton–Euler
        solve.  ``applied``: (link, force, global point); ``couples``: (link, moment).

        Returns (pairs' results, M_drive): for each pair (kind, a, b, force of a on b,
        moment of a's action on b about the global origin)."""
        n = len(self.names)
        A = np.zeros((3 * n, 3 * n))
        rhs = np.zeros(3 * n)
        mech = self.mech

        def load(link, F, z, M=0.0):            # a known load, moved to the right side
            if link == FRAME:
                return
            k = 3 * self.idx[link]
            rhs[k] -= F.real
            rhs[k + 1] -= F.imag
            rhs[k + 2] -= _cross(z, F) + M

        for ln in self.names:
            lk = mech.links[ln]
            zS, _, aS = self.point_motion(q, qd, qdd, ln, lk.cg)
            eps = qdd[3 * self.idx[ln] + 2]
            load(ln, -lk.mass * aS - 1j * lk.mass * self.g, zS, -lk.inertia * eps)
        for ln, F, z in applied:
            load(ln, complex(F), complex(z))
        for ln, M in couples:
            load(ln, 0j, 0j, M)
        col = 0
        at = []
        for p in self.pairs:
            if p[0] == "R":
                _, a, _, b, pb = p
                z = self.world(q, b, pb)
                basis = [(1.0 + 0j, 0.0), (1j, 0.0)]       # unit force components
            else:
                _, a, _, alpha, b, pb = p
                z = self.world(q, b, pb)
                _, ta = self.pose(q, a)
                basis = [(1j * _e(ta + alpha), 0.0), (0j, 1.0)]   # normal force, couple
            at.append(z)
            for F, M in basis:
                for link, sign in ((b, 1.0), (a, -1.0)):
                    if link == FRAME:
                        continue
                    k = 3 * self.idx[link]
                    A[k, col] += sign * F.real
                    A[k + 1, col] += sign * F.imag
                    A[k + 2, col] += sign * (_cross(z, F) + M)
                col += 1
        A[3 * self.idx[mech.driver.link] + 2, col] = 1.0     # the driving moment
        x = np.linalg.solve(A, rhs)
        out = []
        for i, p in enumerate(self.pairs):
            u, v = x[2 * i], x[2 * i + 1]
            z = at[i]
            if p[0] == "R":
                F = complex(u, v)
                out.append(("R", p[1], p[3], F, _cross(z, F)))
            else:
                _, ta = self.pose(q, p[1])
                F = u * 1j * _e(ta + p[3])
                out.append(("P", p[1], p[4], F, _cross(z, F) + v))
        return out, x[-1]


def _shift(gd):
    """A guide's local point moved by its offset to the left of its direction."""
    return complex(gd.point) + gd.offset * 1j * _e(gd.angle)


def guess_from(mech, res, i):
    """Generalized coordinates of the chain's result at position ``i`` (the starting
    guess of the loop-closure solve, which must land on the same assembly branch)."""
    q = []
    for ln in mech.link_names:
        L = res.links[ln]
        z = complex(np.broadcast_to(L.origin.z.x, res.phi.shape)[i],
                    np.broadcast_to(L.origin.z.y, res.phi.shape)[i])
        t = math.atan2(np.broadcast_to(L.e.y, res.phi.shape)[i],
                       np.broadcast_to(L.e.x, res.phi.shape)[i])
        if ln == mech.driver.link:              # the crank's angle as the driver's (unwrapped)
            t = float(res.phi[i])
        q += [z.real, z.imag, t]
    return np.array(q)
