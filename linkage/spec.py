"""The linkage spec: a crank-rocker or crank-slider with masses, loads and an analysis plan.

:func:`load_spec` reads TOML (or a dict of the same shape), checks every key and returns
a frozen :class:`MechanismSpec`.  SI units, angles in degrees at the edge.  All problems
are reported at once in one :class:`~crankbase.errors.SpecError`.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from types import MappingProxyType

from crankbase.errors import SpecError, Text
from crankbase.schema import SpecReader
from crankbase.validation import read_toml, rows_problem

from .course import COURSES
from .loads import LoadSpec  # one load's spec: shared with linkage.chain_spec
from .schema import (ANALYSIS, KINDS, LINK, LINK_NAMES, LOAD, MECHANISM, SCHEMA,
                     WORKING_STROKES)

__all__ = ["LinkSpec", "LoadSpec", "MechanismSpec", "load_spec", "LINK_NAMES", "KINDS"]

#: Link number of each name.
LINK_NUMBER = {"crank": 2, "coupler": 3, "rocker": 4, "slider": 4}
#: Point names the core reports itself; extra points must not reuse them.
RESERVED_POINTS = ("O", "A", "B", "C", "S2", "S3", "S4")

_POINT_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]*$")


@dataclass(frozen=True)
class LinkSpec:
    """Inertia and reported points of one link (local frame, see the module docs).

    Attributes
    ----------
    mass : float  [kg]
    inertia : float  Moment of inertia about the centre of mass. [kg·m²]
    cg : complex  Centre of mass in local coordinates. [m]
    points : mapping of str to complex  Extra named points in local coordinates. [m]
    """

    mass: float = 0.0
    inertia: float = 0.0
    cg: complex = 0j
    points: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))


@dataclass(frozen=True)
class MechanismSpec:
    """A validated linkage spec (SI, angles in radians inside; degrees as given kept in
    ``raw``).  See the README for every key."""

    kind: str
    name: str
    crank: float
    coupler: float
    rocker: float | None
    ground: float | None
    ground_angle: float
    offset: float
    assembly: int
    omega: float
    epsilon: float
    gravity: float
    links: MappingProxyType
    loads: tuple
    positions: int | None
    crank_angles_deg: tuple | None
    working_stroke: str | None
    raw: MappingProxyType
    source: str | None = None

    @property
    def link_names(self):
        return LINK_NAMES[self.kind]

    def link(self, name: str) -> LinkSpec:
        return self.links[name]



def _kind_text(word, prefix="errors.kind."):
    """A mechanism kind (or an output link) named in an error, keyed when it is one of
    ours (``crank-rocker`` → ``errors.kind.crank_rocker``), else as given."""
    key = prefix + str(word).replace("-", "_")
    return Text(key) if word in ("crank-rocker", "crank-slider", "this", "rocker",
                                 "slider") else word

def _default_cg(kind, name, lengths):
    """Default centre of mass: mid-length of a bar, the pin B of a slider."""
    if name == "slider":
        return 0j
    return complex(lengths[name] / 2.0, 0.0)


def load_spec(path_or_dict) -> MechanismSpec:
    """Read and validate a linkage spec.

    Parameters
    ----------
    path_or_dict : str, Path, dict or MechanismSpec
        A TOML file, the same content as a dict, or an already loaded spec (returned as
        is).

    Returns
    -------
    MechanismSpec or linkage.chain_spec.ChainSpec
        A ``[mechanism] kind = "chain"`` file gives a
        :class:`~linkage.chain_spec.ChainSpec` (:func:`linkage.chain_spec.load_chain_spec`).

    Raises
    ------
    SpecError
        With every problem found, each naming its key path, the value and what is valid.
    """
    if isinstance(path_or_dict, MechanismSpec) or getattr(path_or_dict, "kind", "") == "chain":
        return path_or_dict
    data, _ = read_toml(path_or_dict)
    source = None if isinstance(path_or_dict, dict) else str(path_or_dict)
    from .chain_spec import is_chain, load_chain_spec

    if is_chain(data):                 # any linkage of class II groups (linkage.chain_spec)
        return load_chain_spec(data, source)
    ck = SpecReader()
    # "drawing": the title block fields of the plans sheet, checked by plans.drawing
    ck.top(data, SCHEMA)

    m = ck.sub(data, MECHANISM)

    def mech(key, **kw):
        return ck.get(m, MECHANISM, key, **kw)

    kind = mech("kind")
    name = mech("name")
    crank = mech("crank")
    coupler = mech("coupler")
    rocker = ground = None
    # the two kinds' geometry keys differ (the input schema itself): one check each
    if kind == "crank-rocker":
        rocker = mech("rocker", required=True)
        ground = mech("ground", required=True)
        if "offset" in m:
            ck.add("mechanism.offset", Text("errors.linkage.spec.applies_crank_slider"))
    elif kind == "crank-slider":
        for key in ("rocker", "ground"):
            if key in m:
                ck.add(f"mechanism.{key}", Text("errors.linkage.spec.applies_crank_rocker"))
    ground_angle = mech("ground_angle_deg")
    offset = mech("offset")
    assembly = mech("assembly")
    omega = mech("omega_rad_s")
    epsilon = mech("epsilon_rad_s2")
    gravity = mech("gravity_m_s2")

    lengths = {"crank": crank, "coupler": coupler, "rocker": rocker}
    link_names = LINK_NAMES.get(kind, ())
    lt = ck.table(data, "links", required=False)     # its keys: the link names (below)
    links = {}
    for lname in lt:
        if lname not in link_names:
            ck.add(f"links.{lname}",
                   Text("errors.linkage.spec.unknown_link_valid",
                        {"value": _kind_text(kind or "this"), "items": ', '.join(link_names)}))
    point_names = set()
    for lname in link_names:
        path = f"links.{lname}"
        t = ck.sub(lt, LINK, path=path, required=False)
        mass = ck.get(t, LINK, "mass_kg", path=path)
        inertia = ck.get(t, LINK, "inertia_kg_m2", path=path)
        cg = None
        if "cg" in t:
            xy = ck.get(t, LINK, "cg", path=path, required=True)
            cg = complex(*xy) if xy else None
        if cg is None:
            cg = _default_cg(kind, lname, lengths) if lengths.get(lname) or lname == "slider" \
                else 0j
        pts = {}
        ptable = t.get("points", {})
        if not isinstance(ptable, dict):
            ck.add(f"{path}.points", Text("errors.linkage.spec.table_name_x", {"ptable": ptable}))
            ptable = {}
        for pname in ptable:
            ppath = f"{path}.points"
            if not _POINT_NAME.match(pname) or pname in RESERVED_POINTS:
                ck.add(f"{ppath}.{pname}",
                       Text("errors.linkage.spec.invalid_point_name",
                            {"items": ', '.join(RESERVED_POINTS)}))
                continue
            if pname in point_names:
                ck.add(f"{ppath}.{pname}", Text("errors.linkage.spec.point_name_already"))
                continue
            xy = ck.numbers(ptable, pname, ppath, length=2)
            if xy:
                pts[pname] = complex(*xy)
                point_names.add(pname)
        links[lname] = LinkSpec(mass if mass is not None else 0.0,
                                inertia if inertia is not None else 0.0, cg,
                                MappingProxyType(pts))

    loads, resistance_paths = [], []
    output = COURSES[kind].output if kind in COURSES else "slider"
    for path, t in ck.rows(data, LOAD):

        def get(key, **kw):
            return ck.get(t, LOAD, key, path=path, **kw)

        link = get("link", choices=link_names) if link_names else None
        which = [k for k in ("force_N", "moment_Nm", "resistance_Nm", "resistance_N") if k in t]
        if len(which) != 1:
            ck.add(path, Text("errors.linkage.spec.needs_exactly_one",
                              {"value": ', '.join(which) or Text("errors.none")}))
            continue
        key = which[0]
        at = 0j
        if "at" in t:
            xy = get("at")
            at = complex(*xy) if xy else 0j
        if key == "force_N":
            f = get("force_N", required=True)
            for k in ("stroke", "span_deg", "span_m"):
                if k in t:
                    ck.add(f"{path}.{k}", Text("errors.linkage.spec.applies_resistance_only"))
            if f and link:
                loads.append(LoadSpec(link, "force", at=at, force=complex(*f)))
            continue
        if key == "moment_Nm":
            mval = get("moment_Nm", required=True)
            for k in ("at", "stroke", "span_deg", "span_m"):
                if k in t:
                    ck.add(f"{path}.{k}", Text("errors.linkage.spec.does_not_apply_2"))
            if mval is not None and link:
                loads.append(LoadSpec(link, "moment", moment=mval))
            continue
        # resistance
        want = "resistance_Nm" if output == "rocker" else "resistance_N"
        if key != want:
            ck.add(f"{path}.{key}", Text("errors.linkage.spec.takes_on",
                                         {"kind": _kind_text(kind), "want": want,
                                          "output": _kind_text(output, "errors.link.")}))
            continue
        if link is not None and link != output:
            ck.add(f"{path}.link", Text("errors.linkage.spec.resistance_acts_on",
                                        {"output": output, "link": link}))
        r = get(key, required=True)
        stroke = get("stroke")
        span_key = "span_deg" if output == "rocker" else "span_m"
        other = "span_m" if output == "rocker" else "span_deg"
        if other in t:
            ck.add(f"{path}.{other}", Text("errors.linkage.spec.use_for",
                                           {"span_key": span_key,
                                            "output": _kind_text(output, "errors.link.")}))
        if "at" in t:
            ck.add(f"{path}.at", Text("errors.linkage.spec.resistance_acts_at"))
        span = get(span_key)
        if span is not None and span_key == "span_deg":
            span = math.radians(span)
        if r is not None:
            loads.append(LoadSpec(output, "resistance", resistance=r,
                                  stroke=stroke or "working", span=span))
            resistance_paths.append(f"{path}.{key}")

    a = ck.sub(data, ANALYSIS)
    positions = ck.get(a, ANALYSIS, "positions", le=None, default=None)
    if positions is not None and rows_problem(positions, "analysis.positions"):
        ck.problems.append(rows_problem(positions, "analysis.positions"))
        positions = None
    angles = None
    if "crank_angles_deg" in a:
        angles = ck.get(a, ANALYSIS, "crank_angles_deg", required=True)
        angles = tuple(angles) if angles else None
        if "positions" in a:
            ck.add("analysis", Text("errors.linkage.spec.give_either_positions"))
    elif "positions" not in a:
        positions = 12
    strokes = WORKING_STROKES.get(kind, WORKING_STROKES["crank-slider"])
    working = ck.get(a, ANALYSIS, "working_stroke", choices=strokes)
    needs = []
    if positions is not None and "crank_angles_deg" not in a:
        needs.append("positions" + ("" if "positions" in a else " (12 by default)"))
    if any(ld.kind == "resistance" and ld.stroke != "both" for ld in loads):
        needs.append("a resistance limited to one stroke")
    if any(ld.kind == "resistance" and ld.span is not None for ld in loads):
        needs.append("a resistance with a span")
    if omega == 0.0:
        # statics (or start from rest): no direction of rotation, no strokes
        if positions is not None and "crank_angles_deg" not in a:
            ck.add("analysis.crank_angles_deg",
                   Text("errors.linkage.spec.missing_with_mechanism"))
        for rp in resistance_paths:
            ck.add(rp, Text("errors.linkage.spec.resistance_opposes_motion"))
        if "working_stroke" in a:
            ck.add("analysis.working_stroke",
                   Text("errors.linkage.spec.does_not_apply"))
        needs = []
    if needs and working is None and "working_stroke" not in a:
        ck.add("analysis.working_stroke",
               Text("errors.linkage.spec.missing_required_with",
                    {"items": ' and '.join(needs), "items2": ', '.join(map(repr, strokes))}))
    ck.raise_if_any()
    return MechanismSpec(
        kind=kind, name=name, crank=crank, coupler=coupler, rocker=rocker, ground=ground,
        ground_angle=math.radians(ground_angle), offset=offset, assembly=int(assembly),
        omega=omega, epsilon=epsilon, gravity=gravity, links=MappingProxyType(links),
        loads=tuple(loads), positions=None if angles else positions,
        crank_angles_deg=angles, working_stroke=working,
        raw=MappingProxyType(dict(data)), source=source)


def spec_error(key: str, message: str) -> SpecError:
    """One-problem :class:`SpecError` (for checks made after loading)."""
    from crankbase.errors import Problem
    return SpecError(Problem(key, message))
