"""The linkage spec: a crank-rocker or crank-slider with masses, loads and an analysis plan.

:func:`load_spec` reads TOML (or a dict of the same shape), checks every key and returns
a frozen :class:`MechanismSpec`.  SI units, angles in degrees at the edge.  All problems
are reported at once in one :class:`~crankbase.errors.SpecError`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from crankbase.errors import SpecError, Text
from crankbase.schema import SpecReader
from crankbase.validation import read_toml

from .course import COURSES
from .loads import LoadSpec  # one load's spec: shared with linkage.chain_spec
from .schema import KINDS, LINK_NAMES, MECHANISM, SCHEMA, WORKING_STROKES
from .spec_tables import LinkSpec, kind_text, read_link, read_loads, read_plan

__all__ = ["LinkSpec", "LoadSpec", "MechanismSpec", "load_spec", "LINK_NAMES", "KINDS"]

#: Link number of each name.
LINK_NUMBER = {"crank": 2, "coupler": 3, "rocker": 4, "slider": 4}
#: Point names the core reports itself; extra points must not reuse them.
RESERVED_POINTS = ("O", "A", "B", "C", "S2", "S3", "S4")

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
    for lname in lt:
        if lname not in link_names:
            ck.add(f"links.{lname}",
                   Text("errors.linkage.spec.unknown_link_valid",
                        {"value": kind_text(kind or "this"), "items": ', '.join(link_names)}))
    point_names = set()
    links = {lname: read_link(ck, lt, lname,
                              _default_cg(kind, lname, lengths)
                              if lengths.get(lname) or lname == "slider" else 0j,
                              point_names, RESERVED_POINTS)
             for lname in link_names}

    output = COURSES[kind].output if kind in COURSES else "slider"
    loads, resistance_paths = read_loads(
        ck, data, link_names, output, rotary=output == "rocker",
        wrong_resistance=lambda want: Text(
            "errors.linkage.spec.takes_on",
            {"kind": kind_text(kind), "want": want,
             "output": kind_text(output, "errors.link.")}))
    strokes = WORKING_STROKES.get(kind, WORKING_STROKES["crank-slider"])
    positions, angles, working = read_plan(ck, data, strokes, loads, omega, resistance_paths)
    ck.raise_if_any()
    return MechanismSpec(
        kind=kind, name=name, crank=crank, coupler=coupler, rocker=rocker, ground=ground,
        ground_angle=math.radians(ground_angle), offset=offset, assembly=int(assembly),
        omega=omega, epsilon=epsilon, gravity=gravity, links=MappingProxyType(links),
        loads=tuple(loads), positions=positions, crank_angles_deg=angles,
        working_stroke=working,
        raw=MappingProxyType(dict(data)), source=source)


def spec_error(key: str, message: str) -> SpecError:
    """One-problem :class:`SpecError` (for checks made after loading)."""
    from crankbase.errors import Problem
    return SpecError(Problem(key, message))
