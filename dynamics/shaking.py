"""Shaking force and moment of a linkage on its frame, and their balancing by counterweights.

The shaking force is the resultant of the links' d'Alembert inertia forces,
``F_sh = Σ (−m_i a_Si)``, and the shaking moment their resultant moment about the crank
pivot O, ``M_sh = Σ [−J_Si ε_i + (r_Si − r_O) × (−m_i a_Si)]``: with no other loads the
frame receives exactly these through its bearings and the motor's stator (d'Alembert:
the reactions of the frame balance the inertia loads).  Inertia loads come from the core
(``linkage.groups.inertia_load`` on the core's kinematics).

Full shaking-force balance of the four-bar (the method of linearly independent vectors,
Berkof & Lowen 1969): with the loop closure ``l1 e2 + l2 e3 = r_C + l3 e4`` the total mass
centre is

    M r_G = e2 [m2 r2 + m3 l1 (1 − r3/l2)] + e4 [m4 r4 + m3 r3 l3/l2] + const,

(r_i the centre of mass of link i in its own frame, as a complex number), so r_G stands
still when both brackets vanish: a counterweight ``(m r)_cw2 = −m2 r2 − m3 l1 (1 − r3/l2)``
on the crank and ``(m r)_cw4 = −m4 r4 − m3 r3 l3/l2`` on the rocker, each a complex number
in the link's frame (x along the link).

Partial balance of the crank-slider: the coupler's mass is split exactly (for the force)
between A and B, ``m3 (1 − r3/l2)`` and ``m3 r3/l2``; the counterweight on the crank takes
all the rotating mass and a fraction ``f`` of the reciprocating one,
``(m r)_cw = −m2 r2 − m3 (1 − r3/l2) l1 − f·m_rec·l1`` with
``m_rec = m4 + m3 Re(r3)/l2`` (Khurmi & Gupta, ch. 22, §22.3: B·b = (m1 + c·m) r).

References
----------
.. [1] Berkof R. S., Lowen G. G. A new method for completely force balancing simple
   linkages. ASME J. Eng. Ind., 91(1), 1969, 21–26.
.. [2] Seed 001: textbook chapter 11 "机械系统的动力分析与设计", §11.2.3 (balancing of
   mechanisms by added masses).
.. [3] Khurmi R. S., Gupta J. K. Theory of Machines, 14th ed., S. Chand, 2005, ch. 22,
   Example 22.1.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from crankbase.errors import Text
from ._base import Problem, SpecError

__all__ = ["ShakingResult", "shaking", "BalanceResult", "balance_fourbar",
           "balance_crank_slider", "balance_chain", "mechanism_balance", "plot_shaking_force",
           "plot_shaking_locus"]


@dataclass
class ShakingResult:
    """``table``: ``phi_deg, F_x_N, F_y_N, F_N, M_O_Nm`` (shaking force components and
    magnitude, shaking moment about the crank pivot, + ccw), at the spec's ω and ε."""

    name: str
    table: object

    @property
    def F_max(self):
        return float(self.table["F_N"].max())


def shaking(spec, crank_angles_deg=None) -> ShakingResult:
    """Shaking force and moment of a linkage spec over the crank angle.

    Parameters
    ----------
    spec : linkage spec (path, dict or MechanismSpec)
    crank_angles_deg : array_like, optional
        Absolute crank angles [deg]; default 0…360° by 1°.
    """
    import pandas as pd
    from linkage import load_spec
    from linkage import chain as ch
    from linkage.analysis import spec_chain

    from .chain_model import chain_shaking

    spec = load_spec(spec)
    phi_deg = np.arange(0.0, 361.0, 1.0) if crank_angles_deg is None else \
        np.atleast_1d(np.asarray(crank_angles_deg, float))
    chain = spec_chain(spec)            # every kind: a chain of class II groups
    sh = chain_shaking(ch.solve(chain, np.radians(phi_deg), spec.omega, spec.epsilon,
                                check=False), chain.frame[chain.driver.pivot])
    F = np.asarray(sh.F)
    M = sh.M
    table = pd.DataFrame({"phi_deg": phi_deg, "F_x_N": F.real, "F_y_N": F.imag,
                          "F_N": np.abs(F), "M_O_Nm": M})
    return ShakingResult(spec.name, table)


@dataclass
class BalanceResult:
    """Counterweights and the shaking before and after.

    Attributes
    ----------
    counterweights : pandas.DataFrame
        ``link, mr_kgm`` (|m r|), ``angle_deg`` (direction in the link's frame, from the
        link's line towards its left), ``radius_m``, ``mass_kg``.
    balanced_spec : MechanismSpec
        The spec with each counterweight merged into its link (mass, centre of mass and
        J_S by the parallel-axis theorem, the counterweight taken as a point mass).
    before, after : ShakingResult
    """

    counterweights: object
    balanced_spec: object
    before: ShakingResult
    after: ShakingResult


def _with_counterweights(spec, cws):
    """The spec with point-mass counterweights ``{link: (mass, local position)}`` merged."""
    links = dict(spec.links)
    for lname, (m, p) in cws.items():
        ls = links[lname]
        M = ls.mass + m
        if M <= 0:
            continue
        cg = (ls.mass * ls.cg + m * p) / M
        J = ls.inertia + ls.mass * abs(ls.cg - cg) ** 2 + m * abs(p - cg) ** 2
        links[lname] = dataclasses.replace(ls, mass=M, cg=complex(cg), inertia=float(J))
    return dataclasses.replace(spec, links=MappingProxyType(links))


def _table(rows):
    import pandas as pd

    return pd.DataFrame(rows, columns=["link", "mr_kgm", "angle_deg", "radius_m", "mass_kg"])


def _cw(lname, mr, radius, key):
    if radius is not None and not radius > 0:
        raise SpecError(Problem(key, Text("errors.dynamics.shaking.counterweight_radius",
                                          {"radius": radius})))
    a = abs(mr)
    mass = a / radius if a > 0 else 0.0
    pos = radius * mr / a if a > 0 else 0j
    return (lname, a, math.degrees(math.atan2(mr.imag, mr.real)) % 360.0, radius, mass), \
        (mass, pos)


def balance_fourbar(spec, radius_crank_m=None, radius_rocker_m=None,
                    crank_angles_deg=None) -> BalanceResult:
    """Full shaking-force balance of a crank-rocker by one counterweight on the crank and
    one on the rocker (linearly independent vectors, module docstring).

    Parameters
    ----------
    radius_crank_m, radius_rocker_m : float, optional
        Distance of each counterweight from its pivot (O, C); default the link's length.
    """
    from linkage import load_spec

    spec = load_spec(spec)
    if spec.kind != "crank-rocker":     # the closed form below is the four-bar's loop
        raise SpecError(Problem("mechanism.kind",
                                Text("errors.dynamics.shaking.full_force_balance",
                                     {"kind": spec.kind})))
    l1, l2, l3 = spec.crank, spec.coupler, spec.rocker
    m2, m3, m4 = (spec.links[n].mass for n in ("crank", "coupler", "rocker"))
    r2, r3, r4 = (spec.links[n].cg for n in ("crank", "coupler", "rocker"))
    mr2 = -m2 * r2 - m3 * l1 * (1 - r3 / l2)
    mr4 = -m4 * r4 - m3 * r3 * l3 / l2
    row2, cw2 = _cw("crank", complex(mr2), radius_crank_m or l1, "balance.radius_crank_m")
    row4, cw4 = _cw("rocker", complex(mr4), radius_rocker_m or l3, "balance.radius_rocker_m")
    bal = _with_counterweights(spec, {"crank": cw2, "rocker": cw4})
    return BalanceResult(_table([row2, row4]), bal, shaking(spec, crank_angles_deg),
                         shaking(bal, crank_angles_deg))


def balance_crank_slider(spec, fraction=0.0, radius_m=None,
                         crank_angles_deg=None) -> BalanceResult:
    """Partial balance of a crank-slider: a counterweight on the crank for all the rotating
    mass and ``fraction`` of the reciprocating one (module docstring).

    Parameters
    ----------
    fraction : float in [0, 1]
        Share of the reciprocating mass balanced (textbooks: ½ … ⅔).
    radius_m : float, optional
        Counterweight radius; default the crank length.
    """
    from linkage import load_spec

    spec = load_spec(spec)
    if spec.kind != "crank-slider":     # the slider's reciprocating mass: no other kind
        raise SpecError(Problem("mechanism.kind",
                                Text("errors.dynamics.shaking.partial_balance_for",
                                     {"kind": spec.kind})))
    if not 0.0 <= fraction <= 1.0:
        raise SpecError(Problem("balance.fraction",
                                Text("errors.dynamics.shaking.balanced_share_reciprocating",
                                     {"fraction": fraction})))
    l1, l2 = spec.crank, spec.coupler
    m2, m3, m4 = (spec.links[n].mass for n in ("crank", "coupler", "slider"))
    r2, r3 = spec.links["crank"].cg, spec.links["coupler"].cg
    m_rec = m4 + m3 * r3.real / l2
    mr = -m2 * r2 - m3 * (1 - r3 / l2) * l1 - fraction * m_rec * l1
    row, cw = _cw("crank", complex(mr), radius_m or l1, "balance.radius_m")
    bal = _with_counterweights(spec, {"crank": cw})
    res = BalanceResult(_table([row]), bal, shaking(spec, crank_angles_deg),
                        shaking(bal, crank_angles_deg))
    res.counterweights["fraction"] = fraction
    res.counterweights["m_rec_kg"] = m_rec
    return res


def _chain_with_counterweight(spec, mass, pos):
    """A chain spec with a point mass ``mass`` at the crank's local point ``pos`` merged
    into the crank (mass, centre of mass, J_S by the parallel-axis theorem)."""
    from linkage import chain as ch

    mech = spec.mechanism
    crank = mech.driver.link
    lk = mech.links[crank]
    M = lk.mass + mass
    if M <= 0 or mass == 0:
        return spec
    cg = (lk.mass * lk.cg + mass * pos) / M
    J = lk.inertia + lk.mass * abs(lk.cg - cg) ** 2 + mass * abs(pos - cg) ** 2
    links = dict(mech.links)
    links[crank] = ch.Link(float(M), float(J), complex(cg), dict(lk.points))
    new = ch.Mechanism(dict(mech.frame), mech.driver, list(mech.groups), links, mech.name)
    return dataclasses.replace(spec, mechanism=new, links=MappingProxyType(links))


def balance_chain(spec, radius_m=None, crank_angles_deg=None) -> BalanceResult:
    """Partial shaking-force balance of any chain of class II groups (a chain spec) by one
    counterweight on the crank: the one that cancels the forward-rotating first harmonic
    of the shaking force, which minimises its mean square over a turn.

    With the shaking force written as a complex Fourier series over the crank angle,
    ``F_sh(φ) = Σ_k c_k e^{ikφ}``, a point mass ``m`` at the crank's local point ``p`` adds
    ``m ω² p e^{iφ}`` (its centrifugal force at constant ω), orthogonal to every other
    term, so ``m p = −c_1/ω²`` (computed at the spec's ω, the coefficient by the mean over
    a turn by 1°).  For a crank-slider this is the classic counterweight for all the
    rotating mass and half the reciprocating one (the primary force m_rec ω² r cos φ is
    half forward- and half backward-rotating).

    Parameters
    ----------
    radius_m : float, optional
        Counterweight radius from the crank's pivot; default the crank length.
    """
    from linkage import load_spec

    spec = load_spec(spec)
    if spec.kind != "chain":
        raise SpecError(Problem("mechanism.kind",
                                Text("errors.dynamics.shaking.chain_only",
                                     {"kind": spec.kind})))
    if spec.omega == 0:
        raise SpecError(Problem("mechanism.omega_rad_s",
                                Text("errors.dynamics.shaking.chain_needs_omega")))
    grid = shaking(spec, np.arange(0.0, 360.0, 1.0)).table
    phi = np.radians(grid["phi_deg"].to_numpy())
    F = grid["F_x_N"].to_numpy() + 1j * grid["F_y_N"].to_numpy()
    c1 = np.mean(F * np.exp(-1j * phi))
    mr = -c1 / spec.omega ** 2
    row, cw = _cw(spec.mechanism.driver.link, complex(mr), radius_m or spec.crank,
                  "balance.radius_m")
    bal = _chain_with_counterweight(spec, *cw)
    return BalanceResult(_table([row]), bal, shaking(spec, crank_angles_deg),
                         shaking(bal, crank_angles_deg))


def _words(lang):
    """The words of the shaking-force plots in ``lang`` (``plot.shaking.*``)."""
    from crankbase.plot_texts import plot_words

    return plot_words(lang, "shaking")


def plot_shaking_force(result: BalanceResult, ax=None, lang="en"):
    """|F_sh|(φ) before (solid) and after (dashed) balancing."""
    L = _words(lang)
    if ax is None:
        from matplotlib.figure import Figure
        ax = Figure(figsize=(7, 4), layout="constrained").add_subplot()
    for r, ls, lab in ((result.before, "-", L["b"]), (result.after, (0, (5, 2)), L["a"])):
        ax.plot(r.table["phi_deg"], r.table["F_N"], color="black", ls=ls, lw=1.4, label=lab)
    ax.set_xlabel(L["phi"])
    ax.set_ylabel(L["F"])
    ax.set_title(L["t"])
    ax.legend(fontsize=8, loc="best")
    ax.grid(True, lw=0.3)
    return ax


def plot_shaking_locus(result: BalanceResult, ax=None, lang="en"):
    """Polar loci of the shaking force vector (its tip over a turn), before and after;
    equal aspect, the pole marked."""
    L = _words(lang)
    if ax is None:
        from matplotlib.figure import Figure
        ax = Figure(figsize=(5.5, 5.5), layout="constrained").add_subplot()
    from crankbase.tolerances import ROUNDOFF_RTOL

    ax.plot(result.before.table["F_x_N"], result.before.table["F_y_N"], color="black",
            ls="-", lw=1.3, label=L["b"])
    if result.after.F_max <= ROUNDOFF_RTOL * result.before.F_max:   # fully balanced
        ax.plot([0], [0], "o", mfc="white", mec="black", ms=9, ls="none", label=L["zero"])
    else:
        ax.plot(result.after.table["F_x_N"], result.after.table["F_y_N"], color="black",
                ls=(0, (5, 2)), lw=1.3, label=L["a"])
    ax.plot([0], [0], "ko", ms=4)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(L["x"])
    ax.set_ylabel(L["y"])
    ax.set_title(L["loc"])
    ax.legend(fontsize=8, loc="best")
    ax.grid(True, lw=0.3)
    return ax


_BAL_KEYS = ("fraction", "radius_m", "radius_crank_m", "radius_rocker_m")


def mechanism_balance(path_or_dict) -> BalanceResult:
    """Balance the mechanism of a linkage spec with an optional ``[balance]`` section::

        [balance]
        fraction = 0.5            # crank-slider: balanced share of the reciprocating mass
        radius_m = 0.08           # crank-slider: counterweight radius (default the crank)
        radius_crank_m = 0.05     # crank-rocker: counterweight radii (default the link
        radius_rocker_m = 0.3     #   lengths)

    Crank-rocker: full force balance; crank-slider: partial balance.  Over a full turn
    by 1°, at the spec's ω and ε.
    """
    from linkage import load_spec

    from ._base import Checker, read_toml

    data, _ = read_toml(path_or_dict)
    ck = Checker()
    bal = ck.table(data, "balance", required=False)
    ck.unknown(bal, _BAL_KEYS, "balance")
    frac = ck.number(bal, "fraction", "balance", required=False, default=0.0, ge=0, le=1)
    radius = {k: ck.number(bal, k, "balance", required=False, gt=0)
              for k in ("radius_m", "radius_crank_m", "radius_rocker_m")}
    rest = {k: v for k, v in data.items() if k != "balance"}
    try:
        spec = load_spec(rest)
    except SpecError as exc:
        raise SpecError(ck.problems + exc.problems) from None
    method, kind_keys = _BALANCE[spec.kind]
    for k in bal:
        if k in _BAL_KEYS and k not in kind_keys:
            ck.add(f"balance.{k}", Text("errors.dynamics.shaking.does_not_apply",
                                        {"kind": Text("errors.kind."
                                                      + spec.kind.replace("-", "_")),
                                         "items": ", ".join(kind_keys)}))
    ck.raise_if_any()
    return method(spec, **{k: frac if k == "fraction" else radius[k] for k in kind_keys})


#: The balance of each kind and the ``[balance]`` keys it takes.  Genuinely different
#: methods, hence one entry each: the four-bar's full force balance by linearly
#: independent vectors (Berkof & Lowen) exists in closed form for the crank-rocker only;
#: the crank-slider's is the textbook partial balance of the reciprocating mass; a chain
#: cancels the first harmonic.
_BALANCE = {"crank-rocker": (balance_fourbar, ("radius_crank_m", "radius_rocker_m")),
            "crank-slider": (balance_crank_slider, ("fraction", "radius_m")),
            "chain": (balance_chain, ("radius_m",))}
