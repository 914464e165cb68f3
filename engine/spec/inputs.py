"""The inputs of the bearing calculation: the optional tables ``[bearings]`` and ``[rod]``.

Read by :func:`engine.load` with the rest of the file (``study.bearings``, a
:class:`BearingInputs`), through the schema (:data:`engine.schema.BEARINGS`,
:data:`engine.schema.ROD`).  Imports nothing of the calculation (:mod:`engine.forces`,
:mod:`engine.bearings`, :mod:`engine.rodmodel`), which import the spec.

``[bearings]`` keys (all optional): ``wear_half_angle_deg`` (half-angle of the arc each
load wears, default 60°), ``journal_positions_mm`` (the two main journals' axial positions
relative to the crank-pin centre, e.g. ``[-60, 60]``; default symmetric),
``counterweight_kg_mm`` (m·r of the throw's counterweights together [kg·mm]; default none),
``counterweight_angle_deg`` (their direction from the crank, in the direction of rotation;
default 180).

``[rod]``: ``model`` ("two-mass", default, or "rigid"); for the rigid rod
``inertia_kg_m2`` (J about its centre of mass, required), ``mass_kg`` (default: ``rod_kg``
of ``[masses]``) and ``cg_from_big_end_mm`` (default: the two-mass centre of mass).
"""
from __future__ import annotations

from dataclasses import dataclass

from crankbase.errors import Text
from crankbase.schema import SpecReader

from ..schema import BEARINGS, ROD, ROD_MODELS
from ..schema import DEFAULT_HALF_ANGLE_DEG

__all__ = ["BEARING_KEYS", "ROD_KEYS", "ROD_MODELS", "BearingOptions", "bearing_options",
           "BearingInputs", "RigidRod", "rod_options", "read_tables", "mass_parts"]

BEARING_KEYS = BEARINGS.names
ROD_KEYS = ROD.names

#: Default distance of each main journal from the crank-pin centre when none is given:
#: only the ratio matters for the lever rule (symmetric: one half each). [m]
_DEFAULT_HALF_SPAN = 0.05


def _reader(checker):
    """A :class:`SpecReader` that records into ``checker``'s problems (a new one when
    None)."""
    if isinstance(checker, SpecReader):
        return checker
    r = SpecReader()
    if checker is not None:
        r.problems = checker.problems           # the same list: one report
    return r


@dataclass(frozen=True)
class BearingOptions:
    """``[bearings]`` in SI: half-angle [deg], journal positions [m], counterweight
    m·r [kg·m] and angle [deg]; ``given``: the keys the spec gave."""

    wear_half_angle_deg: float = DEFAULT_HALF_ANGLE_DEG
    journal_positions: tuple = (-_DEFAULT_HALF_SPAN, _DEFAULT_HALF_SPAN)
    counterweight_mr: float = 0.0
    counterweight_angle_deg: float = 180.0
    given: tuple = ()


def bearing_options(table, checker=None):
    """Validated :class:`BearingOptions` from the ``[bearings]`` table (None: defaults)."""
    c = _reader(checker)
    t = table if table is not None else {}
    if not isinstance(t, dict):
        c.addk("bearings", "errors.table.type", value=repr(t)[:60])
        t = {}
    c.unknown(t, BEARINGS.names, "bearings")
    h = c.get(t, BEARINGS, "wear_half_angle_deg")
    zj = c.get(t, BEARINGS, "journal_positions_mm")
    if zj is not None and not zj[0] <= 0 <= zj[1]:
        c.add("bearings.journal_positions_mm",
              Text("errors.engine.inputs.two_journals_lie", {"zj": zj}))
        zj = None
    if zj is not None and zj[0] == zj[1]:
        c.add("bearings.journal_positions_mm", Text("errors.engine.inputs.journals_differ",
                                                    {"zj": zj}))
        zj = None
    mr = c.get(t, BEARINGS, "counterweight_kg_mm", si=True)
    ang = c.get(t, BEARINGS, "counterweight_angle_deg")
    if checker is None:
        c.raise_if_any()
    return BearingOptions(
        h if h is not None else DEFAULT_HALF_ANGLE_DEG,
        tuple(BEARINGS.key("journal_positions_mm").to_si(zj)) if zj
        else (-_DEFAULT_HALF_SPAN, _DEFAULT_HALF_SPAN),
        mr or 0.0, ang if ang is not None else 180.0,
        tuple(k for k in t if k in BEARINGS.names))


@dataclass(frozen=True)
class RigidRod:
    """A rigid rod and the piston group (SI).

    ``mass`` m [kg], ``cg`` b: centre of mass from the crank pin along the rod [m],
    ``inertia`` J about the centre of mass [kg·m²], ``m_piston`` mп [kg]."""

    mass: float
    cg: float
    inertia: float
    m_piston: float

    def two_mass_inertia(self, L):
        """J of the two-mass rod with this mass and centre of mass: m·a·b. [kg·m²]"""
        return self.mass * self.cg * (L - self.cg)


def mass_parts(spec):
    """(piston group mass, rod mass) when [masses] gives them as parts, else None. [kg]"""
    src = spec.mass_source
    if "piston_group_kg" in src:
        return float(src["piston_group_kg"]), float(src["rod_kg"])
    if "piston_group_kg_m2" in src:
        return (float(src["piston_group_kg_m2"]) * spec.area,
                float(src["rod_kg_m2"]) * spec.area)
    return None


def rod_options(table, spec=None, checker=None):
    """Read the ``[rod]`` table: ``("two-mass", None)`` or ``("rigid", RigidRod)``.

    Parameters
    ----------
    table : dict or None
        The ``[rod]`` table of the spec file (None or {} when absent).
    spec : EngineSpec, optional
        The engine, for the defaults and the checks that need it (mass, centre of mass,
        piston mass); without it only the keys and their ranges are checked and the
        rigid rod is not built (``("rigid", None)``).
    checker : Checker, optional
        Problems are added to it (else a :class:`SpecError` is raised).

    Raises
    ------
    SpecError
        Naming every bad key of ``[rod]`` (unknown key, bad model, missing or
        non-positive J, a centre of mass off the rod, a negative piston mass).
    """
    c = _reader(checker)
    n0 = len(c.problems)
    t = table if table is not None else {}
    out = ("two-mass", None)
    if not isinstance(t, dict):
        c.addk("rod", "errors.table.type", value=repr(t)[:60])
        t = {}
    c.unknown(t, ROD.names, "rod")
    model = c.get(t, ROD, "model")
    if model != "rigid":
        for k in t:
            if k != "model" and k in ROD.names:
                c.add(f"rod.{k}", Text("errors.engine.inputs.only_used_with"))
    else:
        out = ("rigid", _rigid(c, t, spec))
    if checker is None:
        c.raise_if_any()
    return out if len(c.problems) == n0 else ("two-mass", None)


def _rigid(c, t, spec):
    J = c.get(t, ROD, "inertia_kg_m2", required=True)
    m = c.get(t, ROD, "mass_kg")
    b_mm = c.get(t, ROD, "cg_from_big_end_mm")
    if spec is None:
        return None
    parts = mass_parts(spec)
    L = spec.L
    if m is None and "mass_kg" not in t:
        if parts is None:
            c.add("rod.mass_kg", Text("errors.engine.inputs.missing_needed_for"))
        else:
            m = parts[1]
    b = None
    if b_mm is not None:
        if not b_mm < L * 1e3:
            c.add("rod.cg_from_big_end_mm", Text("errors.engine.inputs.centre_mass_lie",
                                                 {"b_mm": b_mm, "L": L * 1e3}))
        else:
            b = b_mm / 1e3
    elif m is not None:
        small = m - spec.m_rod_rot
        if not 0 < small < m:
            c.add("rod.mass_kg", Text("errors.engine.inputs.kg_exceed_rotating",
                                      {"m": m, "m_rod_rot": spec.m_rod_rot}))
        else:
            b = L * small / m
    if m is None or b is None or J is None:
        return None
    mp = parts[0] if parts is not None else spec.mj - (m - spec.m_rod_rot)
    if mp < 0:
        c.add("rod.mass_kg", Text("errors.engine.inputs.kg_piston_mass", {"m": m, "mp": mp}))
        return None
    return RigidRod(float(m), float(b), float(J), float(mp))


@dataclass(frozen=True)
class BearingInputs:
    """The inputs of the bearing calculation beside the engine spec.

    ``options``: :class:`BearingOptions`; ``rod_model``: "two-mass" or "rigid"; ``rod``:
    the :class:`RigidRod` (None for the two-mass rod); ``asked``: the spec file has a
    ``[bearings]`` or ``[rod]`` table.
    """

    options: BearingOptions = BearingOptions()
    rod_model: str = "two-mass"
    rod: RigidRod | None = None
    asked: bool = False


def read_tables(c, data, spec=None) -> BearingInputs:
    """The ``[bearings]`` and ``[rod]`` tables of a spec file's dict, problems recorded in
    ``c``; ``spec`` (the engine, when it could be built) completes the rigid rod."""
    opt = bearing_options(data.get("bearings"), c)
    model, rod = rod_options(data.get("rod"), spec, c)
    return BearingInputs(opt, model, rod, "bearings" in data or "rod" in data)
