"""Velocity and acceleration plans of a chain of class II groups (:mod:`linkage.chain`).

The plans are built as the course draws them, group by group in the order of the
structure formula, from the pole: each group's vector equations as segments between the
images of its points.  Nothing is solved again: every vector is a quantity of the chain's
:class:`~linkage.chain.ChainResult` (a joint's or point's velocity and acceleration, a
link's ω and ε, a group's sliding velocity and acceleration, its Coriolis term) divided by
the plan's scale; the relative vectors are formed from ω, ε and the link's geometry
(``iω·(B − A)``, ``−ω²·(B − A)``, ``iε·(B − A)``), so that each polygon's closure checks
the chain's numbers against each other.

Equations drawn (Artobolevsky 1988, ch. 4 [1]_; the index of a point is its link's
number in the structure formula, ``a₃`` the point of link 3 under A):

* driver: ``V_A = ω·(A − O)``; ``a_A = aⁿ_AO + aᵗ_AO`` (the tangential part when ε ≠ 0);
* RRR (A, B, C): ``V_B = V_A + V_BA = V_C + V_BC``;
  ``a_B = a_A + aⁿ_BA + aᵗ_BA = a_C + aⁿ_BC + aᵗ_BC``;
* RRP (A, B, slider on a guide of link j): ``V_B = V_A + V_BA = V_Bj + V_BBj`` (along the
  guide); ``a_B = a_A + aⁿ_BA + aᵗ_BA = a_Bj + aᵏ_BBj + aʳ_BBj``;
* RPR (block 2 at A, lever 3 pivoted at C, the slotted lever): ``V_A3 = V_A2 + V_A3A2 =
  V_C + V_A3C``; ``a_A3 = a_A2 + aᵏ_A3A2 + aʳ_A3A2 = a_C + aⁿ_A3C + aᵗ_A3C``;
* PRP (sliders 2 and 3 at B on guides of links j, k): ``V_B = V_Bj + V_BBj = V_Bk +
  V_BBk``, the accelerations with their Coriolis terms;
* RPP (block 2 at A in the slot of yoke 3 on a guide of link j): ``V_A3 = V_Aj +
  V_A3Aj``, ``V_A = V_A3 + V_AA3``, the accelerations likewise.

The Coriolis acceleration is ``aᵏ = 2·ω_j × V_rel`` (``2ω_j·i·V_rel``), ω_j of the link that
carries the guide or slot.

Force polygons (plan kinds ``force_<i>_<j>``, links i, j by their numbers, and
``force_crank``), head to tail at a round μF: each group's links' weights G, inertia
forces Fu = −m·a_S, their other loads F (applied forces and the useful resistance), the
reactions of the groups attached later (R43 …) and the outer pairs' reactions of
:func:`linkage.chain.kinetostatics`; the group's sum closes, and the inner reaction R32
closes link 2's own.  The crank's polygon takes Mур as the force Fур at A ⟂ OA
(:func:`plans.model.balancing_force`), so its frame reaction is R01 − Fур, as for the
four-bar.

References
----------
.. [1] Артоболевский И. И. Теория механизмов и машин. 4-е изд. М.: Наука, 1988, гл. 4.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from linkage import chain as ch
from linkage import groups as g
from linkage.chain_lever import zhukovsky

from .errors import PlanError, Problem, Text
from .model import (LEVER_LONGEST_MM, Lever, Plan, PositionPlans, Vector, angular_reading,
                    balancing_force, close_lever, force_polygon, lever_force, position_rows,
                    round_scale, scaled_plan)

__all__ = ["build_chain_plans", "CHAIN_PLAN_KINDS", "fourbar_name"]

#: The kinematic plans of a chain position (then ``force_<i>_<j>`` …, ``force_crank``).
CHAIN_PLAN_KINDS = ("velocity", "acceleration")
_POLE = "_pole"
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


_SUPER = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")


def fourbar_name(name: str) -> str:
    """The four-bar's name of a segment, point, quantity, plan or label of the chain's
    construction of a four-bar (:func:`linkage.analysis.as_chain`: the crank and one
    group), the one naming rule between the two.

    The chain numbers the frame 0 and the crank 1, the textbook's four-bar the frame 1 and
    the crank 2 (:data:`linkage.spec.LINK_NUMBER`): every link number, a digit or a
    subscript digit, is one more (``ps1`` → ``ps2``, ``a_n2`` → ``a_n3``, ``R01`` →
    ``R12``, ``R₂₁`` → ``R₃₂``, ``omega2`` → ``omega3``); the group's polygon
    ``force_2_3`` is the four-bar's ``force_dyad``, a relative velocity between two
    images is written without the underscore (``a_b`` → ``ab``) and the pole of the
    acceleration plan is ``pi`` (``pole_n3`` → ``pi_n4``).  Names without a number are
    the same (``pa``, ``pi_e``, ``Fb``).  For the plans' segments, their labels and the
    ``angular`` quantities; not for the lever's load names (``F3_1`` counts loads).

    Examples
    --------
    >>> [fourbar_name(n) for n in ("a_b", "pole_n3", "n3_b", "R03", "force_2_3", "πn₃")]
    ['ab', 'pi_n4', 'n4_b', 'R14', 'force_dyad', 'πn₄']
    """
    if name == "force_2_3":
        return "force_dyad"
    out = []
    for ch_ in name:
        if ch_.isdigit():
            sub = ch_ not in "0123456789"
            d = int(ch_.translate(_SUPER)) + 1
            out.append(str(d).translate(_SUB) if sub else str(d))
        else:
            out.append(ch_)
    out = "".join(out)
    if out.startswith("pole_"):
        out = "pi_" + out[len("pole_"):]
    return {"a_b": "ab"}.get(out, out)


def _at(x, i, n):
    """Element ``i`` of a float or array broadcast over ``n`` positions."""
    return float(np.broadcast_to(np.asarray(x, float), (n,))[i])


class _Position:
    """The chain at one row ``i`` as complex numbers and floats."""

    def __init__(self, res: ch.ChainResult, i: int):
        self.res, self.i, self.n = res, i, len(res.phi)
        self.number = {ln: k + 1 for k, ln in enumerate(res.mech.link_names)}
        self.number[ch.FRAME] = 0

    def f(self, x):
        return _at(x, self.i, self.n)

    def c(self, v):
        v = g.Vec.of(v)
        return complex(self.f(v.x), self.f(v.y))

    def pm(self, p: g.PointMotion):
        return self.c(p.z), self.c(p.v), self.c(p.a)

    def point(self, name):
        return self.pm(self.res.point(name))

    def link(self, name):
        if name == ch.FRAME:
            return 0.0, 0.0
        lm = self.res.links[name]
        return self.f(lm.omega), self.f(lm.eps)

    def link_motion(self, name):
        return g.FRAME if name == ch.FRAME else self.res.links[name]


class _Builder:
    """Both plans of one position, in physical units (scale applied at the end)."""

    def __init__(self, P: _Position):
        self.P = P
        # point key -> (velocity, acceleration, label)
        self.pts = {}
        self.vel, self.acc = [], []          # (name, quantity, lru, len, start, end, kind)
        self.vpoly, self.apoly = [], []
        self.angular = []        # (link number, V segment, aᵗ segment, l, ω, ε)

    def _key(self, joint, link=None):
        k = joint.lower() + ("" if link is None else str(self.P.number[link]))
        return k + "_pt" if k in ("p", "pi") else k

    def add_point(self, key, v, a, lab):
        self.pts[key] = (v, a, lab)

    def absolute(self, key, quantity):
        v, a, lab = self.pts[key]
        self.vel.append((f"p{key}", "V_" + quantity, "p" + lab, "o" + lab, 0j, v, "absolute"))
        self.acc.append((f"pi_{key}", "a_" + quantity, "π" + lab, "o′" + lab + "′", 0j, a,
                         "absolute"))
        return f"p{key}", f"pi_{key}"

    def rel_v(self, k1, k2, dv, quantity, kind="relative"):
        """A velocity vector from the image of ``k1`` by ``dv`` (ends at ``k2``'s image)."""
        s = self.pts[k1][0]
        lab1, lab2 = self.pts[k1][2], self.pts[k2][2]
        if k1 == _POLE:                  # V_B = V_BC from a frame pivot: drawn as pb
            return None
        name = f"{k1.lstrip('_')}_{k2}"
        self.vel.append((name, "V_" + quantity, lab1 + lab2, lab1 + lab2, s, s + dv, kind))
        return name

    def chain_a(self, k1, parts):
        """Acceleration vectors head to tail from the image of ``k1``: ``parts`` =
        [(name, quantity, label ru, label en, value, kind)]."""
        z = self.pts[k1][1]
        names = []
        for name, quantity, lru, len_, w, kind in parts:
            self.acc.append((name, "a_" + quantity, lru, len_, z, z + w, kind))
            z = z + w
            names.append(name)
        return names


def _q(*joints_links):
    return "".join(joints_links)


def _build(P: _Position):
    res, mech = P.res, P.res.mech
    B = _Builder(P)
    d = mech.driver
    zO, _, _ = P.point(d.pivot)
    zA, vA, aA = P.point(d.joint)
    w1, e1 = P.link(d.link)
    n1 = P.number[d.link]
    ka = B._key(d.joint)
    B.add_point(ka, vA, aA, d.joint.lower())
    pv, pa = B.absolute(ka, d.joint)
    if e1 != 0:                     # a_A = aⁿ_AO + aᵗ_AO
        an, at = -w1 * w1 * (zA - zO), 1j * e1 * (zA - zO)
        nl = f"n{n1}".translate(_SUB)
        q = f"{d.joint}{d.pivot}"
        B.acc.append((f"pi_n{n1}", f"a_{q}_n", "π" + nl, "o′" + nl + "′", 0j, an, "normal"))
        B.acc.append((f"n{n1}_{ka}", f"a_{q}_t", nl + ka, nl + "′" + ka + "′", an, an + at,
                      "tangential"))
        B.apoly.append([(f"pi_n{n1}", 1), (f"n{n1}_{ka}", 1), (pa, -1)])

    def key_of(joint):
        """The key of a joint's image, adding the frame's joints as the pole."""
        if joint in mech.frame:
            return None
        k = B._key(joint)
        if k not in B.pts:                 # a named point of a link solved before
            _, v, a = P.point(joint)
            B.add_point(k, v, a, joint.lower())
            B.absolute(k, joint)
        return k

    def rot_rel(k_from, k_to, z_from, z_to, link, jf, jt):
        """Velocity and acceleration of ``k_to`` about ``k_from`` on a turning ``link``:
        V = iω·r, aⁿ = −ω²·r, aᵗ = iε·r; returns (velocity vector name, [a names])."""
        w, e = P.link(link)
        r = z_to - z_from
        q = f"{jt}{jf}"
        if k_from is None:                       # from the pole (a frame pivot)
            B.pts.setdefault(_POLE, (0j, 0j, ""))
            k_from = _POLE
        vn = B.rel_v(k_from, k_to, 1j * w * r, q) if k_to in B.pts else None
        nk = f"n{P.number[link]}"
        # ω = V_rel/l from the relative vector (pb itself from a frame pivot), ε = aᵗ/l
        B.angular.append((P.number[link], vn or f"p{k_to}", f"{nk}_{k_to}", abs(r), w, e))
        nl = nk.translate(_SUB)
        lab1, len1 = (("π", "o′") if k_from == _POLE else
                      (B.pts[k_from][2], B.pts[k_from][2] + "′"))
        names = B.chain_a(k_from, [(f"{k_from.lstrip('_')}_{nk}", q + "_n", lab1 + nl,
                                    len1 + nl + "′",
                                    -w * w * r, "normal"),
                                   (f"{nk}_{k_to}", q + "_t", nl + B.pts[k_to][2],
                                    nl + "′" + B.pts[k_to][2] + "′", 1j * e * r,
                                    "tangential")])
        return vn, names

    def abs_names(k):
        if k is None or k == _POLE:
            return None, None
        return f"p{k}", f"pi_{k}"

    def poly(kf, vrel, arel, kt):
        """``V_to = V_from + V_rel`` (and the accelerations) as polygons."""
        pvf, paf = abs_names(kf)
        pvt, pat = abs_names(kt)
        vrel = [n for n in vrel if n is not None]
        if vrel:
            B.vpoly.append(([(pvf, 1)] if pvf else []) + [(n, 1) for n in vrel] + [(pvt, -1)])
        if arel:
            B.apoly.append(([(paf, 1)] if paf else []) + [(n, 1) for n in arel] + [(pat, -1)])

    def slide(k_base, k_to, link_j, jq, u_v, u_a, cor, kq):
        """``V_to = V_base + v_rel`` along a guide of ``link_j``, ``a_to = a_base + aᵏ +
        aʳ``; k_base is the image of the guide link's point under the joint."""
        vn = B.rel_v(k_base, k_to, u_v, jq)
        parts = []
        if k_base == _POLE and P.link(link_j)[0] == 0:   # a slider on the frame: a_B itself
            poly(k_base, [], [], k_to)
            return
        kb_ = k_base.lstrip("_")
        if P.link(link_j)[0] != 0:
            kk = f"k_{k_to}"
            parts.append((f"{kb_}_{kk}", jq + "_k", B.pts[k_base][2] + "k",
                          B.pts[k_base][2] + "′k′", cor, "coriolis"))
            assert k_base != _POLE
        parts.append((f"{kb_}_{k_to}" if not parts else f"k_{k_to}_{k_to}", jq + "_r",
                      ("k" if len(parts) else B.pts[k_base][2]) + B.pts[k_to][2],
                      ("k′" if len(parts) else B.pts[k_base][2] + "′") + B.pts[k_to][2] + "′",
                      u_a, "relative"))
        an = B.chain_a(k_base, parts)
        poly(k_base, [vn], an, k_to)

    for gi, grp in enumerate(mech.groups):
        l2, l3 = grp.links
        if grp.kind == "RRR":
            jA, jB, jC = grp.joints
            zA_, zB_, zC_ = (P.point(j)[0] for j in (jA, jB, jC))
            _, vB, aB = P.point(jB)
            kb = B._key(jB)
            B.add_point(kb, vB, aB, jB.lower())
            B.absolute(kb, jB)
            kA, kC = key_of(jA), key_of(jC)
            vn, an = rot_rel(kA, kb, zA_, zB_, l2, jA, jB)
            poly(kA, [vn], an, kb)
            vn, an = rot_rel(kC, kb, zC_, zB_, l3, jC, jB)
            poly(kC, [vn], an, kb)
        elif grp.kind == "RRP":
            jA, jB = grp.joints
            zA_ = P.point(jA)[0]
            zB_, vB, aB = P.point(jB)
            kb = B._key(jB)
            B.add_point(kb, vB, aB, jB.lower())
            B.absolute(kb, jB)
            kA = key_of(jA)
            vn, an = rot_rel(kA, kb, zA_, zB_, l2, jA, jB)
            poly(kA, [vn], an, kb)
            gl = grp.guide.link
            s = res.solutions[gi]
            u = P.c(res.links[l3].e)
            cj = g.coincident(P.link_motion(gl), g.Vec.of(zB_)) if gl != ch.FRAME else None
            if cj is None:
                kj = _POLE
                B.pts.setdefault(_POLE, (0j, 0j, ""))
                wj = 0.0
            else:
                kj = B._key(jB, gl)
                B.add_point(kj, P.c(cj.v), P.c(cj.a), jB.lower() + str(P.number[gl]))
                B.absolute(kj, jB + str(P.number[gl]))
                wj = P.link(gl)[0]
            vr, ar = P.f(s.v), P.f(s.a)
            slide(kj, kb, gl, _q(jB, jB + str(P.number[gl])), vr * u, ar * u,
                  2 * wj * vr * 1j * u, "")
        elif grp.kind == "RPR":
            jA, jC = grp.joints
            s = res.solutions[gi]
            zA_, vA_, aA_ = P.point(jA)
            zC_ = P.point(jC)[0]
            n3 = P.number[l3]
            k3 = B._key(jA, l3)
            A3 = s.A_lever
            B.add_point(k3, P.c(A3.v), P.c(A3.a), jA.lower() + str(n3))
            B.absolute(k3, jA + str(n3))
            kA = key_of(jA)
            e = P.c(res.links[l3].e)
            w3 = P.link(l3)[0]
            vrel = -P.f(s.v_rel) * e                        # V_A3A2 = −v_rel·e
            # a_A3 = a_A2 + aᵏ_A3A2 + aʳ_A3A2, aᵏ = 2ω3·i·V_A3A2
            q = f"{jA}{n3}{jA}{P.number[l2]}"
            vn = B.rel_v(kA, k3, vrel, q)
            parts = [(f"{kA}_k_{k3}", q + "_k", jA.lower() + "k", jA.lower() + "′k′",
                      2 * w3 * 1j * vrel, "coriolis"),
                     (f"k_{k3}_{k3}", q + "_r", "k" + jA.lower() + str(n3).translate(_SUB),
                      "k′" + jA.lower() + str(n3).translate(_SUB) + "′",
                      -P.f(s.a_rel) * e, "relative")]
            an = B.chain_a(kA, parts)
            poly(kA, [vn], an, k3)
            kC = key_of(jC)
            vn, an = rot_rel(kC, k3, zC_, zA_, l3, jC, jA + str(n3))
            poly(kC, [vn], an, k3)
        elif grp.kind == "PRP":
            (jB,) = grp.joints
            s = res.solutions[gi]
            zB_, vB, aB = P.point(jB)
            kb = B._key(jB)
            B.add_point(kb, vB, aB, jB.lower())
            B.absolute(kb, jB)
            for gd, lk, sv, sa in ((grp.guides[0], l2, s.v1, s.a1),
                                   (grp.guides[1], l3, s.v2, s.a2)):
                u = P.c(res.links[lk].e)
                gl = gd.link
                if gl == ch.FRAME:
                    kj = _POLE
                    B.pts.setdefault(_POLE, (0j, 0j, ""))
                    wj = 0.0
                else:
                    cj = g.coincident(P.link_motion(gl), g.Vec.of(zB_))
                    kj = B._key(jB, gl)
                    B.add_point(kj, P.c(cj.v), P.c(cj.a), jB.lower() + str(P.number[gl]))
                    B.absolute(kj, jB + str(P.number[gl]))
                    wj = P.link(gl)[0]
                vr, ar = P.f(sv), P.f(sa)
                slide(kj, kb, gl, _q(jB, jB + str(P.number[gl])), vr * u, ar * u,
                      2 * wj * vr * 1j * u, "")
        else:  # RPP
            (jA,) = grp.joints
            s = res.solutions[gi]
            zA_ = P.point(jA)[0]
            kA = B._key(jA)
            gl = grp.guide.link
            u = P.c(res.links[l3].e)
            w = P.c(res.links[l2].e)
            if gl == ch.FRAME:
                kj, wj = _POLE, 0.0
                B.pts.setdefault(_POLE, (0j, 0j, ""))
            else:
                cj = g.coincident(P.link_motion(gl), g.Vec.of(zA_))
                kj = B._key(jA, gl)
                B.add_point(kj, P.c(cj.v), P.c(cj.a), jA.lower() + str(P.number[gl]))
                B.absolute(kj, jA + str(P.number[gl]))
                wj = P.link(gl)[0]
            n3 = P.number[l3]
            k3 = B._key(jA, l3)
            vy, ay = P.f(s.v_guide), P.f(s.a_guide)
            vx, ax = P.f(s.v_slot), P.f(s.a_slot)
            v3 = B.pts[kj][0] + vy * u
            a3 = B.pts[kj][1] + ay * u + 2 * wj * vy * 1j * u
            B.add_point(k3, v3, a3, jA.lower() + str(n3))
            B.absolute(k3, jA + str(n3))
            slide(kj, k3, gl, f"{jA}{n3}{jA}{P.number.get(gl, 0)}", vy * u, ay * u,
                  2 * wj * vy * 1j * u, "")
            slide(k3, kA, l3, f"{jA}{jA}{n3}", vx * w, ax * w, 2 * wj * vx * 1j * w, "")
    # the named points and centres of mass of the links: absolute vectors
    for ln in mech.link_names:
        link = mech.links[ln]
        for pname in link.points:
            if B._key(pname) in B.pts:
                continue
            _, v, a = P.point(pname)
            B.add_point(B._key(pname), v, a, pname.lower())
            B.absolute(B._key(pname), pname)
        if link.mass > 0:
            cg = g.coincident(res.links[ln], res.links[ln].origin.z
                              + res.links[ln].e * complex(link.cg))
            key = f"s{P.number[ln]}"
            if key not in B.pts and abs(P.c(cg.v)) + abs(P.c(cg.a)) > 0:
                B.add_point(key, P.c(cg.v), P.c(cg.a), key)
                B.absolute(key, key.upper())
    return B


def _plan(kind, rows, polys, pts, mu, which):
    unit = "m/s" if kind == "velocity" else "m/s2"
    pole = ("p", "o") if kind == "velocity" else ("π", "o′")
    P = Plan(kind, mu, unit, {("p" if kind == "velocity" else "pi"): 0j},
             {("p" if kind == "velocity" else "pi"): pole}, [])
    for key, (v, a, lab) in pts.items():
        if key == _POLE:
            continue
        z = (v if which == 0 else a) / mu
        P.points[key] = z
        lab = lab.translate(_SUB)
        P.point_labels[key] = (lab, lab if kind == "velocity" else lab + "′")
    seen = set()
    for name, quantity, lru, len_, s, e, vkind in rows:
        if name in seen:
            continue
        seen.add(name)
        P.vectors.append(Vector(kind, name, quantity, lru.translate(_SUB),
                                len_.translate(_SUB), s / mu, e / mu, abs(e - s), unit, mu,
                                vkind))
    P.polygons = [p for p in polys if len(p) > 1]
    return P


def _force_items(result, P: _Position):
    """The force polygons of one position, in N: ``{kind: (items, inner, split)}`` with
    ``force_<i>_<j>`` for each group (links i, j by their numbers) and ``force_crank``;
    items ``(name, quantity, label ru, label en, force, kind)`` head to tail, the inner
    reaction R32 from the end of link 2's ``split`` items
    (:func:`plans.model.force_polygon`)."""
    res, cf, mech = result.motion, result.reactions, result.spec.mechanism
    gvec = -1j * result.spec.gravity
    num = P.number
    sub = lambda k: str(k).translate(_SUB)             # noqa: E731

    def own(ln, later=()):
        """G, Fu and the rest of the link's own loads: the resultant of its wrench less
        the ``later`` groups' reactions on it (the crank's wrench holds none)."""
        link, lm = mech.links[ln], res.links[ln]
        G = link.mass * gvec
        aS = P.c(g.coincident(lm, lm.origin.z + lm.e * complex(link.cg)).a)
        Fu = -link.mass * aS
        W = P.c(cf.wrenches[ln].force)
        n = num[ln]
        out = []
        if G != 0:
            out.append((f"G{n}", f"G{n}", f"G{sub(n)}", f"G{sub(n)}", G, "load"))
        if Fu != 0:
            out.append((f"Fu{n}", f"Fu{n}", f"Fи{sub(n)}", f"Fi{sub(n)}", Fu, "load"))
        rest = W - G - Fu - sum(it[4] for it in later)
        if abs(rest) > 1e-9 * max(1.0, abs(W)):
            out.append((f"F{n}", f"F{n}", f"F{sub(n)}", f"F{sub(n)}", rest, "load"))
        return out + list(later)

    def reaction(by, on, r):
        a, b = num.get(by, 0), num.get(on, 0)
        return (f"R{a}{b}", f"R{a}{b}", f"R{sub(a)}{sub(b)}", f"R{sub(a)}{sub(b)}",
                P.c(r.force), "reaction")

    table = [r for _, r in cf.reactions.items()]
    out = {}
    for k, grp in enumerate(mech.groups):
        l2, l3 = grp.links
        mine = (l2, l3)
        after = {ln for gr in mech.groups[k + 1:] for ln in gr.links}
        later = {ln: [reaction(r.by, r.on, r) for r in table if r.on == ln and r.by in after]
                 for ln in mine}
        outer = {ln: [reaction(r.by, r.on, r) for r in table
                      if r.on == ln and r.by not in mine and r.by not in after]
                 for ln in mine}
        inner = [reaction(r.by, r.on, r) for r in table if r.on == l2 and r.by == l3]
        items2 = own(l2, later[l2]) + outer[l2]
        items3 = own(l3, later[l3]) + outer[l3]
        out[f"force_{num[l2]}_{num[l3]}"] = (items2 + items3, inner, len(items2))
    d = mech.driver
    items = own(d.link) + [reaction(r.by, r.on, r) for r in table
                           if r.on == d.link and r.by not in (ch.FRAME, d.link)]
    zO, zA = P.point(d.pivot)[0], P.point(d.joint)[0]
    M = P.f(cf.M_drive)
    Fb = balancing_force(M, zA - zO)
    items.append(("Fb", "F_b", "Fур", "Fb", Fb, "balancing"))
    R0 = [r for r in table if r.on == d.link and r.by == ch.FRAME][0]
    # with Mур as the force Fур at A, the frame's reaction is R01 − Fур
    items.append((f"R0{num[d.link]}", f"R0{num[d.link]}", f"R₀{sub(num[d.link])}",
                  f"R₀{sub(num[d.link])}", P.c(R0.force) - Fb, "reaction"))
    out["force_crank"] = (items, [], len(items))
    return out


def _link_points(P: _Position, ln):
    """The two points of link ``ln`` a couple on it is put at on the lever, as
    ``(key, z, v)`` (key: the point's key on the velocity plan): the joints and named
    points that move with the link at this position (v = v_O + iω·(z − z_O)), the one
    nearest its origin and the one farthest from that; a link with a single such point
    (a block) takes the point at the crank's length along its x axis as the second."""
    res = P.res
    L = res.links[ln]
    zo, vo = P.c(L.origin.z), P.c(L.origin.v)
    w = P.f(L.omega)
    names = list(res.mech.frame) + list(res.joints)
    names += [q for lk in res.mech.links.values() for q in lk.points]
    out = []
    for name in dict.fromkeys(names):
        z, v, _a = P.point(name)
        rigid = vo + 1j * w * (z - zo)
        if abs(v - rigid) <= 1e-9 * (abs(vo) + abs(w) * abs(z - zo) + 1e-12):
            key = name.lower()
            out.append((key + "_pt" if key in ("p", "pi") else key, z, v))
    if not out:
        out = [("", zo, vo)]
    first = min(out, key=lambda p: abs(p[1] - zo))
    second = max(out, key=lambda p: abs(p[1] - first[1]))
    if abs(second[1] - first[1]) < 1e-9:
        p2 = L.point(res.mech.driver.length)
        second = ("", P.c(p2.z), P.c(p2.v))
    return first, second


#: The largest width and height of a chain's lever drawing, turned plan and force arrows,
#: at its default force scale, unless the turned plan alone is larger (an A3 sheet's field
#: beside the title block is 186 mm wide). [mm]
LEVER_MAX_MM = 140.0


def _lever_scale(forces, at_a, Fb, points):
    """The lever's default round force scale: the four-bar's (the largest force
    :data:`plans.model.LEVER_LONGEST_MM` long at most), coarser while the arrows make the
    drawing wider or higher than :data:`LEVER_MAX_MM` or than the turned plan and 10 mm
    (a chain's velocity plan may be long)."""
    big = max([abs(fc.force) for fc in forces] + [abs(Fb)]) or 1.0
    mu = round_scale(big, LEVER_LONGEST_MM)
    base = [0j, at_a] + list(points.values()) + [fc.at for fc in forces]

    def extent(zs):
        xs, ys = [z.real for z in zs], [z.imag for z in zs]
        return max(xs) - min(xs), max(ys) - min(ys)

    # each side no longer than LEVER_MAX_MM, or than the turned plan and the loads' points
    # with arrows 10 mm beyond them
    limit = [max(LEVER_MAX_MM, p + 10.0) for p in extent(base)]
    for _ in range(30):
        ends = [fc.at + fc.force / mu for fc in forces] + [at_a + Fb / mu]
        size = extent(base + ends)
        if all(s <= m + 1e-9 for s, m in zip(size, limit)):
            break
        mu = round_scale(big, 0.99 * big / mu)           # the next round scale
    return mu


def _lever(result, zl, P: _Position, vplan: Plan, scale=None) -> Lever:
    """Zhukovsky's lever of one position for the drawing: the loads of
    :func:`linkage.chain_lever.zhukovsky` (``zl``, every position) on the velocity plan
    turned 90° clockwise at its scale (a point of velocity v at ``−i·v/μV`` mm), each
    force at its point, the couples of a link (its inertia moment and applied moments,
    summed) as a pair of forces ⟂ the link at two of its points, as the four-bar's lever
    draws them.  Σ moments + Fур·pa = 0 is solved again on the drawing, so that Mур of the
    sheet is checked against the lever's and the kinetostatic one."""
    res, mech = P.res, P.res.mech
    mu = vplan.scale
    w1 = P.f(res.omega(mech.driver.link))
    sub = lambda k: str(k).translate(_SUB)             # noqa: E731
    forces = []

    def add(name, lru, len_, key, v, F):
        forces.append(lever_force(name, lru, len_, key, v, F, mu))

    couples = {}
    count = {}
    for ld in zl.loads:
        n = P.number[ld.link]
        F = P.c(ld.force)
        kind = ld.name.split("_", 1)[0]
        if kind in ("Mu", "M"):                        # a couple: ±M (l = 1 m) pairs
            if ld.name.endswith("+"):
                e = P.c(res.links[ld.link].e)
                M = (F * (1j * e).conjugate()).real
                couples.setdefault(ld.link, []).append((f"{kind}{n}", M))
            continue
        v = P.c(ld.at) * w1 * 1j                       # the point's velocity: at = −i·v/ω₁
        if kind == "G":
            add(f"G{n}", f"G{sub(n)}", f"G{sub(n)}", f"s{n}", v, F)
        elif kind == "Fu":
            add(f"Fu{n}", f"Fи{sub(n)}", f"Fi{sub(n)}", f"s{n}", v, F)
        else:                                          # F_<link>_<k>: applied, resistance
            count[n] = count.get(n, 0) + 1
            k = count[n]
            add(f"F{n}_{k}", f"F{sub(n)}" + ("" if k == 1 else f".{k}"),
                f"F{sub(n)}" + ("" if k == 1 else f".{k}"), "", v, F)
    for ln, items in couples.items():
        M = sum(m for _, m in items)
        if M == 0 or np.all(np.asarray(res.links[ln].omega) == 0):
            continue                                   # a link that only slides: no turn
        n = P.number[ln]
        names = "+".join(k for k, _ in items)
        lab_ru = "+".join(("Mи" if k.startswith("Mu") else "M") + sub(n) for k, _ in items)
        lab_en = "+".join(("Mi" if k.startswith("Mu") else "M") + sub(n) for k, _ in items)
        (k1, z1, v1), (k2, z2, v2) = _link_points(P, ln)
        d = z2 - z1
        f = M * 1j * d / abs(d) ** 2                   # ±f at the two points: moment M
        add(f"{names}_{k2 or 'x'}", f"F({lab_ru})", f"F({lab_en})", k2, v2, f)
        add(f"{names}_{k1 or 'o'}", f"F({lab_ru})", f"F({lab_en})", k1, v1, -f)
    d = mech.driver
    zO, zA = P.point(d.pivot)[0], P.point(d.joint)[0]
    vA = P.point(d.joint)[1]
    lever = close_lever(forces, vplan, zA - zO, vA, d.length, P.f(result.reactions.M_drive),
                        scale, round_scale_of=_lever_scale)
    return replace(lever, balancing_force_N=float(lever.balancing_force_N),
                   M_lever_Nm=float(lever.M_lever_Nm),
                   difference_percent=float(lever.difference_percent))


def build_chain_plans(result, positions=None, *, scales=None):
    """Velocity and acceleration plans of the chosen positions of an analysed chain.

    Parameters
    ----------
    result : linkage.chain_analysis.ChainAnalysis
        From :func:`linkage.analyze` of a ``kind = "chain"`` spec.
    positions : iterable of int or "all", optional
        Position numbers of the plan of positions (default: all).
    scales : dict, optional
        Fixed ``velocity`` [(m/s)/mm], ``acceleration`` [(m/s²)/mm], ``force_dyad`` (every
        group's polygon; ``force_<i>_<j>`` one group's), ``force_crank`` and ``lever``
        [N/mm] scales, ``lever_velocity`` (the turned velocity plan of the lever, default
        the velocity plan's) [(m/s)/mm]; missing ones are the
        textbook's round scales (:func:`plans.model.round_scale`: pa and πa at
        most 150 mm, the whole plan at most :data:`plans.model.MAX_PLAN_MM`).

    Returns
    -------
    list of plans.PositionPlans
        ``plans`` holds ``velocity``, ``acceleration``, ``force_<i>_<j>`` of each group
        and ``force_crank``; ``lever`` is None (the chain's lever is
        :func:`linkage.chain_lever.zhukovsky`) and ``angular`` the ω and ε of every
        turning link of the groups read off the plans (ω = V_rel/l, ε = aᵗ/l).
    """
    spec = result.spec
    K = result.kinematics
    res = result.motion
    problems = []
    if spec.omega == 0:
        problems.append(Problem("mechanism.omega_rad_s",
                                Text("errors.plans.chain_model.statics", {})))
    scales = dict(scales or {})
    if problems:
        raise PlanError(problems)
    rows = position_rows(K, positions)
    pos_col = K["position"]
    numbered = pos_col.notna().all()
    forces, moments = result.loads
    zl = zhukovsky(res, forces, moments, spec.gravity)
    out = []
    for i in rows:
        P = _Position(res, i)
        B = _build(P)
        plans = {}
        for which, kind in enumerate(CHAIN_PLAN_KINDS):
            rows_ = B.vel if which == 0 else B.acc
            polys = B.vpoly if which == 0 else B.apoly
            ref = abs(B.pts[B._key(res.mech.driver.joint)][which])
            plans[kind] = scaled_plan(
                lambda mu: _plan(kind, rows_, polys, B.pts, mu, which),
                lambda unit: ref, scales.get(kind))
        for kind, (items, inner, n2) in _force_items(result, P).items():
            fixed = scales.get(kind) or (kind != "force_crank" and scales.get("force_dyad"))
            plans[kind] = scaled_plan(
                lambda mu: force_polygon(kind, items, mu, inner=inner, split=n2),
                lambda unit: max(v.length_mm for v in unit.vectors) or 1.0, fixed)
        angular = []
        for n, vseg, aseg, length, w, e in B.angular:
            for q, kind, seg, exact, unit in ((f"omega{n}", "velocity", vseg, w, "rad/s"),
                                              (f"eps{n}", "acceleration", aseg, e, "rad/s2")):
                angular.append(angular_reading(q, plans[kind], seg, length, exact, unit))
        geo = {}
        for j in list(res.mech.frame) + list(res.joints):
            geo[j] = P.point(j)[0]
        pos = int(pos_col.iat[i]) if numbered else None
        lplan = plans["velocity"]
        if scales.get("lever_velocity"):            # the lever on a plan of its own scale
            lplan = _plan("velocity", B.vel, B.vpoly, B.pts, scales["lever_velocity"], 0)
        lever = _lever(result, zl, P, lplan, scales.get("lever"))
        fixed = [k for k in scales if scales[k]]
        d = res.mech.driver
        out.append(PositionPlans(pos, math.degrees(float(res.phi[i])) % 360.0, "chain",
                                 plans, lever, angular, geo, tuple(fixed),
                                 (d.pivot, d.joint)))
    return out
