"""The inputs of the torsional-vibration study: the optional spec table ``[torsion]``.

Read by :func:`engine.load` with the rest of an engine spec (``study.torsion``, a
:class:`TorsionInputs`, None without the table) and by :func:`torsion.study.load` for a
file that holds only ``name`` and ``[torsion]`` (a chain given by hand), both through the
one declaration :data:`engine.schema.TORSION`.  Here every key is checked on its own and
against the other keys of the table; what needs the engine's crank train (how many throws,
so how many stiffnesses) is checked when the chain is built
(:func:`torsion.study.build_chain`).

Two forms (exactly one):

* beside the throws: ``throw_J_kgm2`` (each throw's own crank) and ``masses`` (extra
  masses placed ``before``/``after`` a throw number or ``"first"``/``"last"``); the throws
  come from the engine's layout;
* by hand: ``inertias_kgm2`` (every mass, from the free end) and optionally ``throws``
  (which throw each mass carries, 0: none).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from crankbase.errors import Text
from crankbase.validation import MAX_ROWS

from ..schema import TORSION, TORSION_DAMPERS, TORSION_MASSES

__all__ = ["TorsionInputs", "ExtraMass", "read_torsion", "base_order_problem", "PLACES",
           "mass_name_problem"]

#: The words ``before``/``after`` accept beside a throw number.
PLACES = ("first", "last")


@dataclass(frozen=True)
class ExtraMass:
    """A mass beside the throws: ``name``, ``J`` [kg·m²], placed ``side`` ("before" or
    "after") the throw ``throw`` (1-based number, or "first"/"last")."""

    name: str
    J: float
    side: str
    throw: object


@dataclass(frozen=True)
class TorsionInputs:
    """``[torsion]`` in SI, checked key by key (the chain itself: :mod:`torsion.study`).

    Attributes
    ----------
    throw_J : float or None
        Each throw's own crank about the shaft axis [kg·m²] (the form beside the throws).
    masses : tuple of ExtraMass
        The extra masses beside the throws, in the file's order.
    inertias : tuple of float or None
        Every mass of a by-hand chain, from the free end [kg·m²].
    names : tuple of str or None
        By hand: the masses' names (``names``; None: numbered 1 … n).
    throws : tuple of int or None
        By hand: the throw (1-based) each mass carries, 0 for none.
    stiffnesses : tuple of float
        Between consecutive masses [N·m/rad].
    damping_ratio : float
        Modal damping ratio ζ of every mode.
    dampers : tuple of (str, float)
        Absolute viscous dampers: (mass name, c [N·m·s/rad]).
    speed_range_rpm : tuple of float or None
    speed_step_rpm : float
    orders_max : float
    shaft_diameters : tuple of float or None
        Per section [m], for the shear stress τ = 16 M / (π d³).
    holzer_trial_rad_s : tuple of float
        Further Holzer tables at these trial frequencies.
    """

    stiffnesses: tuple
    throw_J: float | None = None
    masses: tuple = ()
    inertias: tuple | None = None
    names: tuple | None = None
    throws: tuple | None = None
    damping_ratio: float = 0.02
    dampers: tuple = ()
    speed_range_rpm: tuple | None = None
    speed_step_rpm: float = 10.0
    orders_max: float = 12.0
    shaft_diameters: tuple | None = None
    holzer_trial_rad_s: tuple = ()

    @property
    def by_hand(self) -> bool:
        """The chain is given mass by mass (``inertias_kgm2``)."""
        return self.inertias is not None


#: What a mass name may hold: it becomes a column name (``theta_<name>``) and, joined by
#: ``-``, a section's name, so letters (any script), digits, ``_`` and ``.`` only.
_MASS_NAME = re.compile(r"[\w.]+")


def mass_name_problem(c, where, name, seen) -> bool:
    """Record the problem of one mass ``name`` at ``where`` (characters, a throw's name,
    given twice among ``seen``); True if there is one."""
    if not _MASS_NAME.fullmatch(name):
        c.addk(where, "torsion.error.mass_name_chars", name=name)
    elif name.lower().startswith("throw"):
        c.addk(where, "torsion.error.mass_throw_name", name=name)
    elif name in seen:
        c.addk(where, "torsion.error.mass_twice", name=name)
    else:
        return False
    return True


def _place(c, item, where):
    """``(side, throw)`` of an extra mass: exactly one of ``before``/``after``, a throw
    number ≥ 1 or "first"/"last" (None on a problem, recorded)."""
    sides = [s for s in ("before", "after") if s in item]
    if len(sides) != 1:
        c.addk(f"{where}.before", "torsion.error.place_one")
        return None
    side = sides[0]
    value = item[side]
    if isinstance(value, bool) or not (
            (isinstance(value, int) and value >= 1) or value in PLACES):
        c.addk(f"{where}.{side}", "torsion.error.place_value", value=repr(value))
        return None
    return side, value


def read_torsion(c, data, strokes=4):
    """The ``[torsion]`` table of a spec file's dict as :class:`TorsionInputs` (None when
    the file has no such table, or on a problem, which is recorded in the checker ``c``).
    ``strokes`` (of the engine; 4 for a chain on its own) gives the base order that
    ``orders_max`` must be a multiple of."""
    if not isinstance(data, dict) or "torsion" not in data:
        return None
    n0 = len(c.problems)
    t = c.sub(data, TORSION)
    if not isinstance(data.get("torsion"), dict):
        return None

    def get(key, **kw):
        return c.get(t, TORSION, key, **kw)

    has_throw_J, has_hand = "throw_J_kgm2" in t, "inertias_kgm2" in t
    throw_J = inertias = throws = names = None
    masses = []
    if has_throw_J and has_hand:
        c.addk("torsion.inertias_kgm2", "torsion.error.one_form")
    elif has_hand:
        inertias = get("inertias_kgm2", required=True, si=True)
        if "masses" in t:
            c.addk("torsion.masses", "torsion.error.masses_by_hand")
        names = get("names")
        if names is not None:
            seen = set()
            for i, name in enumerate(names):
                if mass_name_problem(c, f"torsion.names[{i}]", name, seen):
                    names = None
                    break
                seen.add(name)
            else:
                if inertias is not None and len(names) != len(inertias):
                    c.addk("torsion.names", "torsion.error.names_count",
                           n=len(names), masses=len(inertias))
                    names = None
        throws = get("throws")
        if throws is not None:
            if any(x != int(x) for x in throws):
                c.addk("torsion.throws", "torsion.error.throws_whole")
                throws = None
            else:
                throws = tuple(int(x) for x in throws)
                if inertias is not None and len(throws) != len(inertias):
                    c.addk("torsion.throws", "torsion.error.throws_count",
                           n=len(throws), masses=len(inertias))
                    throws = None
                elif throws and max(throws) > 0:
                    used = sorted(x for x in throws if x)
                    if used != list(range(1, len(used) + 1)):
                        c.addk("torsion.throws", "torsion.error.throws_each",
                               value=list(throws))
                        throws = None
        if inertias is not None and (n := len(inertias)) and "stiffnesses_Nm_rad" in t:
            k = t.get("stiffnesses_Nm_rad")
            if isinstance(k, list) and len(k) != n - 1:
                c.addk("torsion.stiffnesses_Nm_rad", "torsion.error.stiffness_count",
                       k=len(k), n=n, need=n - 1)
    elif has_throw_J:
        throw_J = get("throw_J_kgm2", required=True, si=True)
        if "throws" in t:
            c.addk("torsion.throws", "torsion.error.throws_beside")
        if "names" in t:
            c.addk("torsion.names", "torsion.error.names_beside")
        seen = set()
        for where, item in c.rows(t, TORSION_MASSES):
            name = c.get(item, TORSION_MASSES, "name", path=where)
            J = c.get(item, TORSION_MASSES, "J_kgm2", path=where, si=True)
            if "name" not in item:
                c.addk(f"{where}.name", "torsion.error.mass_name")
            elif name is not None and mass_name_problem(c, f"{where}.name", name, seen):
                name = None
            place = _place(c, item, where)
            if name is not None:
                seen.add(name)
            if None not in (name, J, place):
                masses.append(ExtraMass(name, J, *place))
    else:
        c.addk("torsion", "torsion.error.no_form")
    k = get("stiffnesses_Nm_rad", si=True)
    zeta = get("damping_ratio")
    dampers = []
    for where, item in c.rows(t, TORSION_DAMPERS):
        if isinstance(item.get("at"), int) and not isinstance(item["at"], bool):
            item = {**item, "at": str(item["at"])}       # a by-hand chain's mass number
        at = c.get(item, TORSION_DAMPERS, "at", path=where)
        cv = c.get(item, TORSION_DAMPERS, "c_Nms_rad", path=where, si=True)
        if at is not None and cv is not None:
            dampers.append((at.strip(), cv))
    rng = get("speed_range_rpm")
    if rng is not None and not rng[0] < rng[1]:
        c.addk("torsion.speed_range_rpm", "torsion.error.speed_range", lo=rng[0], hi=rng[1])
        rng = None
    step = get("speed_step_rpm")
    if rng is not None and step is not None and (rng[1] - rng[0]) / step + 1 > MAX_ROWS:
        c.addk("torsion.speed_step_rpm", "torsion.error.too_many_speeds",
               n=int((rng[1] - rng[0]) / step) + 1, max=MAX_ROWS)
    orders_max = get("orders_max")
    if orders_max is not None and strokes in (2, 4) and \
            (why := base_order_problem(orders_max, strokes)):
        c.add("torsion.orders_max", why)
    d = get("shaft_diameters_mm", si=True)
    trial = get("holzer_trial_rad_s")
    if len(c.problems) > n0:
        return None
    return TorsionInputs(
        stiffnesses=tuple(k), throw_J=throw_J, masses=tuple(masses),
        inertias=None if inertias is None else tuple(inertias),
        names=None if names is None else tuple(names), throws=throws,
        damping_ratio=zeta, dampers=tuple(dampers),
        speed_range_rpm=None if rng is None else tuple(rng), speed_step_rpm=step,
        orders_max=orders_max, shaft_diameters=None if d is None else tuple(d),
        holzer_trial_rad_s=tuple(trial or ()))


def base_order_problem(orders_max, strokes):
    """The problem text when ``orders_max`` is not a multiple of the base order (0.5 for a
    four-stroke cycle, 1 for a two-stroke), else None."""
    base = 0.5 if strokes == 4 else 1.0
    if abs(orders_max / base - round(orders_max / base)) > 1e-9:
        return Text("torsion.error.orders_max", {"value": orders_max, "base": base,
                                                 "strokes": strokes})
    return None
