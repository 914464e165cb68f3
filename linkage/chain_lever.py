"""Zhukovsky's lever for any chain of class II groups (:mod:`linkage.chain`), vectorised.

The velocity plan turned 90° clockwise is a lever pivoted at the pole: a point of velocity
v has the image ``−i·v/ω₁`` (in metres: the plan at the scale of the crank's length, so the
crank pin's image is the crank itself, a = O→A), and a force F applied at the point, moved
parallel to itself to the image, has the moment ``(−i·v/ω₁) × F = F·v/ω₁`` about the pole,
its power over ω₁.  A couple M on a link turning at ω is a pair of forces ±M/l
perpendicular to the link at two of its points l apart; on the lever the pair has the
moment ``M·ω/ω₁`` whatever l (here l = 1 m along the link's x axis from its origin).
The balancing force Fур at the crank pin, perpendicular to OA, balances the lever:
``Σ moments + Fур·l_OA = 0``, and Mур = Fур·l_OA (+ ccw), which is the driving moment of
:func:`linkage.chain.kinetostatics` at every position (the same loads: applied forces and
moments, the weights and the d'Alembert inertia loads at the chain's ω₁, ε₁).

References
----------
.. [1] Артоболевский И. И. Теория механизмов и машин. 4-е изд. М.: Наука, 1988, §13
   (рычаг Жуковского).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import groups as g

__all__ = ["LeverLoad", "ChainLever", "zhukovsky"]


@dataclass
class LeverLoad:
    """One force on the lever: ``name`` (``G_rod``, ``Fu_rod``, ``F_rod_1``, ``Mu_rod+``
    …), its ``link``, the point ``at`` of the lever it is applied at (the image of its
    point, [m]), the ``force`` ([N], a :class:`~linkage.groups.Vec`) and its ``moment``
    about the pole ([N·m], + ccw)."""

    name: str
    link: str
    at: g.Vec
    force: g.Vec
    moment: np.ndarray


@dataclass
class ChainLever:
    """Zhukovsky's lever of a solved chain at every position.

    Attributes
    ----------
    loads : list of LeverLoad
    points : dict
        Joint name → its image on the lever (the turned velocity plan, pole at 0). [m]
    balancing_force : ndarray
        Fур at the crank pin along ``balancing_dir`` (perpendicular to OA, + for a ccw
        Mур). [N]
    balancing_dir : Vec
        i·e_OA.
    M_balance : ndarray
        Mур = Fур·l_OA, + ccw. [N·m]
    """

    loads: list
    points: dict
    balancing_force: np.ndarray
    balancing_dir: g.Vec
    M_balance: np.ndarray
    extra: dict = field(default_factory=dict)


def zhukovsky(res, forces=None, moments=None, gravity=9.81, inertia=True) -> ChainLever:
    """Zhukovsky's lever of a solved chain (:func:`linkage.chain.solve`).

    Parameters
    ----------
    res : linkage.chain.ChainResult
        At the crank's ω₁ ≠ 0 and ε₁ of the inertia loads wanted.
    forces : dict, optional
        Link → list of (force, global point), as :func:`linkage.chain.kinetostatics`
        takes them. [N, m]
    moments : dict, optional
        Link → list of moments, + ccw. [N·m]
    gravity : float
        g along −y (the weights at the centres of mass). [m/s²]
    inertia : bool
        Put the d'Alembert inertia loads (−m a_S at S, −J_S ε) on the lever.

    Returns
    -------
    ChainLever
    """
    mech = res.mech
    shape = np.shape(res.phi)
    w1 = np.broadcast_to(res.omega(mech.driver.link), shape)
    rot = -1j                                               # 90° clockwise

    def image(v):
        return (g.Vec.of(v) * rot) / w1

    loads = []

    def put(name, link, v, F):
        at = image(v)
        F = g.Vec.of(F)
        loads.append(LeverLoad(name, link, at, F,
                               np.broadcast_to(g.cross(at, F), shape).astype(float)))

    def couple(name, link, M):
        L = res.links[link]
        o, tip = L.origin, L.point(1.0)
        f = L.e.perp() * M                                  # ±M/l, l = 1 m
        put(name + "+", link, tip.v, f)
        put(name + "-", link, o.v, -f)

    for name in mech.link_names:
        lk = mech.links[name]
        L = res.links[name]
        S = L.point(lk.cg)
        if lk.mass and gravity:
            put(f"G_{name}", name, S.v, g.Vec(0.0 * np.ones(shape), -lk.mass * gravity))
        if inertia:
            Fu, Mu = g.inertia_load(S.a, L.eps, lk.mass, lk.inertia)
            if lk.mass:
                put(f"Fu_{name}", name, S.v, Fu)
            if lk.inertia:
                couple(f"Mu_{name}", name, Mu)
        for k, (f, at) in enumerate((forces or {}).get(name, ())):
            o = L.origin
            put(f"F_{name}_{k + 1}", name, o.v + (g.Vec.of(at) - o.z).perp() * L.omega, f)
        for k, m in enumerate((moments or {}).get(name, ())):
            couple(f"M_{name}_{k + 1}", name, m)
    total = np.zeros(shape)
    for ld in loads:
        total = total + ld.moment
    d = mech.driver
    crank = res.links[d.link]
    at_a = image(crank.point(d.length).v)                  # = l_OA·e_OA
    e_dir = crank.e.perp()
    arm = g.cross(at_a, e_dir)                              # = l_OA (signed)
    Fb = -total / arm
    points = {j: image(p.v) for j, p in res.joints.items()}
    return ChainLever(loads, points, np.broadcast_to(Fb, shape) + 0.0, e_dir,
                      np.broadcast_to(Fb * d.length, shape) + 0.0)
