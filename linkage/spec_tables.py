"""The tables a four-bar spec (:mod:`linkage.spec`) and a chain spec
(:mod:`linkage.chain_spec`) share, read by one function each: a link's ``[links.<name>]``
(:func:`read_link`), the ``[[load]]`` rows (:func:`read_loads`) and the ``[analysis]``
plan (:func:`read_plan`), with every check of their keys written once.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from types import MappingProxyType

from crankbase.errors import Text
from crankbase.validation import rows_problem

from .loads import LoadSpec
from .schema import ANALYSIS, LINK, LOAD

__all__ = ["LinkSpec", "kind_text", "read_link", "read_loads", "read_plan"]

#: The keys of a resistance's window inside its stroke (a force or a moment takes none).
WINDOW_KEYS = ("start_deg", "start_m", "span_deg", "span_m", "from_fraction", "to_fraction")

#: A point's name: a letter, then letters or digits (it becomes part of column names).
POINT_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]*$")


@dataclass(frozen=True)
class LinkSpec:
    """Inertia and reported points of one link (in the link's local frame: :mod:`linkage.spec`
    for a four-bar, :mod:`linkage.chain` for a chain).

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


def kind_text(word, prefix="errors.kind."):
    """A mechanism kind (or an output link) named in an error, keyed when it is one of
    ours (``crank-rocker`` → ``errors.kind.crank_rocker``), else as given."""
    key = prefix + str(word).replace("-", "_")
    return Text(key) if word in ("crank-rocker", "crank-slider", "this", "rocker",
                                 "slider") else word


def read_link(ck, lt, lname, default_cg, point_names, reserved=()) -> LinkSpec:
    """One link's ``[links.<lname>]`` table (mass, J, centre of mass, named points) of a
    four-bar or a chain spec: ``default_cg`` [m, local] where ``cg`` is not given; a
    point's name must be a letter then letters or digits, not in ``reserved`` (the
    names the core reports itself) and not already a point of another link
    (``point_names``, updated)."""
    path = f"links.{lname}"
    t = ck.sub(lt, LINK, path=path, required=False)
    mass = ck.get(t, LINK, "mass_kg", path=path)
    inertia = ck.get(t, LINK, "inertia_kg_m2", path=path)
    cg = None
    if "cg" in t:
        xy = ck.get(t, LINK, "cg", path=path, required=True)
        cg = complex(*xy) if xy else None
    if cg is None:
        cg = default_cg
    pts = {}
    ptable = t.get("points", {})
    if not isinstance(ptable, dict):
        ck.add(f"{path}.points", Text("errors.linkage.spec.table_name_x", {"ptable": ptable}))
        ptable = {}
    for pname in ptable:
        ppath = f"{path}.points"
        if not POINT_NAME.match(pname) or pname in reserved:
            ck.add(f"{ppath}.{pname}",
                   Text("errors.linkage.spec.invalid_point_name",
                        {"items": ', '.join(reserved)}) if reserved
                   else Text("errors.linkage.spec.invalid_point_name_chain"))
            continue
        if pname in point_names:
            ck.add(f"{ppath}.{pname}", Text("errors.linkage.spec.point_name_already"))
            continue
        xy = ck.numbers(ptable, pname, ppath, length=2)
        if xy:
            pts[pname] = complex(*xy)
            point_names.add(pname)
    return LinkSpec(mass if mass is not None else 0.0,
                    inertia if inertia is not None else 0.0, cg, MappingProxyType(pts))


def read_loads(ck, data, link_names, output, rotary, wrong_resistance):
    """The ``[[load]]`` rows of a four-bar or a chain spec: a force at a point, a moment,
    or the useful resistance on the ``output`` link (``resistance_Nm``, ``start_deg`` and
    ``span_deg`` when it turns, ``rotary``; else ``resistance_N``, ``start_m`` and
    ``span_m``; or, for either, its window as ``from_fraction``/``to_fraction`` of the
    stroke, not both forms); the other key named by ``wrong_resistance(want)`` (a
    :class:`~crankbase.errors.Text`).  Whether a window fits in the stroke is known only
    with the stroke: :func:`linkage.loads.resistance_window`.

    Returns
    -------
    loads : list of LoadSpec
    resistance_paths : list of str
        The key path of each resistance (for the checks of the analysis plan).
    """
    loads, resistance_paths = [], []
    for path, t in ck.rows(data, LOAD):

        def get(key, **kw):
            return ck.get(t, LOAD, key, path=path, **kw)

        link = get("link", choices=tuple(link_names)) if link_names else None
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
            for k in ("stroke", *WINDOW_KEYS):
                if k in t:
                    ck.add(f"{path}.{k}", Text("errors.linkage.spec.applies_resistance_only"))
            if f and link:
                loads.append(LoadSpec(link, "force", at=at, force=complex(*f)))
            continue
        if key == "moment_Nm":
            mval = get("moment_Nm", required=True)
            for k in ("at", "stroke", *WINDOW_KEYS):
                if k in t:
                    ck.add(f"{path}.{k}", Text("errors.linkage.spec.does_not_apply_2"))
            if mval is not None and link:
                loads.append(LoadSpec(link, "moment", moment=mval))
            continue
        # resistance
        want = "resistance_Nm" if rotary else "resistance_N"
        if key != want:
            ck.add(f"{path}.{key}", wrong_resistance(want))
            continue
        if link is not None and link != output:
            ck.add(f"{path}.link", Text("errors.linkage.spec.resistance_acts_on",
                                        {"output": output, "link": link}))
        r = get(key, required=True)
        stroke = get("stroke")
        unit = "_deg" if rotary else "_m"
        for other in ("span_m", "start_m") if rotary else ("span_deg", "start_deg"):
            if other in t:
                ck.add(f"{path}.{other}", Text("errors.linkage.spec.use_for", {
                    "span_key": other.rsplit("_", 1)[0] + unit,
                    "output": kind_text(output, "errors.link.")}))
        if "at" in t:
            ck.add(f"{path}.at", Text("errors.linkage.spec.resistance_acts_at"))
        span = get("span" + unit)
        start = get("start" + unit) if "start" + unit in t else None
        if rotary:
            span = math.radians(span) if span is not None else None
            start = math.radians(start) if start is not None else None
        fractions = window_key = None
        given = [k for k in ("start" + unit, "span" + unit) if k in t]
        fracs = [k for k in ("from_fraction", "to_fraction") if k in t]
        if fracs:
            f0, f1 = get("from_fraction"), get("to_fraction")
            window_key = f"{path}.{fracs[0]}"
            if given:
                ck.add(window_key, Text("errors.linkage.spec.window_both",
                                        {"keys": ", ".join(given)}))
            elif f0 is not None and f1 is not None:
                if f0 >= f1:
                    ck.add(window_key, Text("errors.linkage.spec.window_order",
                                            {"start": f0, "end": f1}))
                else:
                    fractions = (f0, f1)
        elif given:
            window_key = f"{path}.{given[0]}"
        if r is not None:
            loads.append(LoadSpec(output, "resistance", resistance=r,
                                  stroke=stroke or "working", span=span, start=start,
                                  fractions=fractions, key=window_key or f"{path}.{key}"))
            resistance_paths.append(f"{path}.{key}")
    return loads, resistance_paths


def read_plan(ck, data, strokes, loads, omega, resistance_paths, working_default=None):
    """The ``[analysis]`` plan of a four-bar or a chain spec: ``positions`` equal steps
    (12 when neither they nor ``crank_angles_deg`` are given) or the crank angles, and
    the ``working_stroke`` (one of ``strokes``).  Without ``working_default`` the
    working stroke must be given where the positions' numbering, a resistance limited to
    one stroke or a span needs it; with it, that stroke is taken.  At rest (``omega`` =
    0: statics) the crank angles must be given, and a resistance (it opposes a motion)
    or a working stroke is an error.

    Returns
    -------
    positions : int or None
        None when crank angles are given.
    angles : tuple of float or None
        The crank angles [deg].
    working : str or None
    """
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
    working = ck.get(a, ANALYSIS, "working_stroke", choices=strokes)
    needs = []               # what needs the working stroke, each a keyed text
    if positions is not None and "crank_angles_deg" not in a:
        needs.append(Text("errors.linkage.spec.needs.positions" if "positions" in a
                          else "errors.linkage.spec.needs.positions_default"))
    if any(ld.kind == "resistance" and ld.stroke != "both" for ld in loads):
        needs.append(Text("errors.linkage.spec.needs.resistance_stroke"))
    if any(ld.kind == "resistance" and (ld.span is not None or ld.start is not None
                                        or ld.fractions is not None) for ld in loads):
        needs.append(Text("errors.linkage.spec.needs.resistance_window"))
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
    if working is None and working_default is not None:
        working = working_default
    elif needs and working is None and "working_stroke" not in a:
        ck.add("analysis.working_stroke",
               Text("errors.linkage.spec.missing_required_with",
                    {"items": needs, "items2": ', '.join(map(repr, strokes))}))
    return None if angles else positions, angles, working
