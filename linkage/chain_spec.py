"""The chain spec: any planar linkage of class II Assur groups, named joints and links.

A spec file with ``[mechanism] kind = "chain"`` (:data:`linkage.schema.CHAIN_SCHEMA`)
lists the frame's joints, the crank (the driver I(0,1)), the groups in the order of the
structure formula (``[[group]]``), the links' masses, moments of inertia, centres of mass
and named points (``[links.<name>]``), the loads (``[[load]]``) and the analysis plan.
:func:`load_chain_spec` reads it into a frozen :class:`ChainSpec` holding the
:class:`linkage.chain.Mechanism` it describes; :func:`linkage.load_spec` calls it for
such a file.  Every problem is reported at once, keyed (``errors.linkage.chain.*``).

Local frames of the links (where ``cg``, ``points`` and a load's ``at`` are measured)
are those of :mod:`linkage.chain`: the crank from the pivot towards the pin; an RRR's
bars from their outer joint towards the inner one; an RRP's rod from A to B, its slider
at B along the guide; an RPR's block at A and its lever at C, both along the slot.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from crankbase.errors import Text
from crankbase.schema import SpecReader

from . import chain as ch
from .loads import LoadSpec
from .schema import CHAIN_MECHANISM, CHAIN_SCHEMA, GROUP
from .spec_tables import read_link, read_loads, read_plan

__all__ = ["ChainLoad", "ChainSpec", "load_chain_spec", "output_kind", "is_chain"]

#: How many lengths each group kind takes.
_LENGTHS = {"RRR": 2, "RRP": 1, "RPR": 0, "PRP": 0, "RPP": 0}


#: One external load on a link of a chain: the four-bar's :class:`linkage.loads.LoadSpec`
#: (``kind`` "force", "moment" or "resistance" on the link named ``link``).
ChainLoad = LoadSpec


@dataclass(frozen=True)
class ChainSpec:
    """A validated chain spec (SI, radians inside).

    Attributes
    ----------
    kind : str
        ``"chain"``.
    name : str
    mechanism : linkage.chain.Mechanism
        Frame joints, driver, groups, links (mass, J, centre of mass, points).
    output : str
        The output link (its extremes, stroke or swing, time ratio; the resistance).
    omega, epsilon, gravity : float
        The crank's ω [rad/s] and ε [rad/s²]; g [m/s²].
    links : mapping of str to linkage.chain.Link
    loads : tuple of ChainLoad
    positions, crank_angles_deg, working_stroke
        The analysis plan, as in :class:`linkage.spec.MechanismSpec`.
    raw : mapping
        The file's content as read.
    """

    kind: str
    name: str
    mechanism: object
    output: str
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
    def crank(self) -> float:
        return self.mechanism.driver.length

    @property
    def link_names(self):
        return tuple(self.mechanism.link_names)

    @property
    def output_kind(self) -> str:
        """``"slider"`` (the slider of an RRP on a frame guide: a stroke) or ``"rocker"``."""
        return output_kind(self.mechanism, self.output)

    def link(self, name: str) -> ch.Link:
        return self.links[name]


def output_kind(mech, output) -> str:
    """``"slider"`` when ``output`` is the slider of an RRP group on a frame guide or the
    yoke of an RPP group on a frame guide (it translates), else ``"rocker"``."""
    for grp in mech.groups:
        if grp.kind in ("RRP", "RPP") and grp.links[1] == output and grp.guide.link == ch.FRAME:
            return "slider"
    return "rocker"


def _xy(value):
    return complex(*value) if value else 0j


def load_chain_spec(data: dict, source=None) -> ChainSpec:
    """Read a chain spec from its TOML content ``data`` (``source``: its file).

    Raises
    ------
    SpecError
        Every problem at once: a key of the schema, an unknown joint or link, a group
        attached to a joint not yet solved, a mobility other than 1.
    """
    ck = SpecReader()
    ck.top(data, CHAIN_SCHEMA)
    m = ck.sub(data, CHAIN_MECHANISM)

    def mech(key, **kw):
        return ck.get(m, CHAIN_MECHANISM, key, **kw)

    name = mech("name")
    crank = mech("crank")
    crank_link, pivot, pin = mech("crank_link"), mech("pivot"), mech("pin")
    output = mech("output")
    omega, epsilon, gravity = mech("omega_rad_s"), mech("epsilon_rad_s2"), mech("gravity_m_s2")
    frame = {}
    ftable = m.get("frame", {})
    if not isinstance(ftable, dict) or not ftable:
        ck.add("mechanism.frame", Text("errors.linkage.chain.frame_table"))
        ftable = {}
    for jn in ftable:
        xy = ck.numbers(ftable, jn, "mechanism.frame", length=2)
        if xy:
            frame[jn] = complex(*xy)

    groups = []
    for path, t in ck.rows(data, GROUP, required=True):

        def get(key, **kw):
            return ck.get(t, GROUP, key, path=path, **kw)

        kind = get("kind")
        links = get("links")
        joints = get("joints")
        need = _LENGTHS.get(kind, 0)
        lengths = get("lengths", required=need > 0)
        if kind is None or links is None or joints is None or (need and lengths is None):
            continue
        if lengths is not None and len(lengths) != need:
            ck.add(f"{path}.lengths", Text("errors.linkage.chain.lengths",
                                           {"kind": kind, "n": need}))
            continue
        if need == 0 and "lengths" in t:
            ck.add(f"{path}.lengths", Text("errors.linkage.chain.no_lengths", {"kind": kind}))

        def guide(prefix):
            return ch.Guide(get(prefix + "_link"), _xy(get(prefix + "_point")),
                            math.radians(get(prefix + "_angle_deg")), get(prefix + "_offset"))

        asm = int(get("assembly"))
        if kind == "RRR":
            groups.append(ch.RRR(links, joints, tuple(lengths), asm))
        elif kind == "RRP":
            groups.append(ch.RRP(links, joints, lengths[0], guide("guide"), asm))
        elif kind == "RPR":
            groups.append(ch.RPR(links, joints, get("offset"), asm))
        elif kind == "PRP":
            groups.append(ch.PRP(links, joints, (guide("guide"), guide("guide2"))))
        else:
            groups.append(ch.RPP(links, joints, guide("guide"),
                                 math.radians(get("slot_angle_deg"))))
    ck.raise_if_any()

    names = [crank_link]
    for grp in groups:
        names += [n for n in grp.links if n not in names]
    lengths_of = {crank_link: crank}
    for grp in groups:
        if grp.kind == "RRR":
            lengths_of.update(zip(grp.links, grp.lengths))
        elif grp.kind == "RRP":
            lengths_of[grp.links[0]] = grp.length

    lt = ck.table(data, "links", required=False)
    for lname in lt:
        if lname not in names:
            ck.add(f"links.{lname}", Text("errors.linkage.chain.unknown_link",
                                          {"valid": ", ".join(names)}))
    point_names = set()
    read = {lname: read_link(ck, lt, lname, complex(lengths_of.get(lname, 0.0) / 2.0, 0.0),
                             point_names)
            for lname in names}
    links = chain_links = {lname: ch.Link(lk.mass, lk.inertia, lk.cg, dict(lk.points))
                           for lname, lk in read.items()}
    if output is not None and output not in names:
        ck.add("mechanism.output", Text("errors.linkage.chain.unknown_link",
                                        {"valid": ", ".join(names)}))
    ck.raise_if_any()
    mechanism = ch.Mechanism(frame, ch.Driver(crank, crank_link, pivot, pin), groups,
                             chain_links, name)          # structure checked: SpecError
    out_kind = output_kind(mechanism, output)

    loads, resistance_paths = read_loads(
        ck, data, names, output, rotary=out_kind != "slider",
        wrong_resistance=lambda want: Text("errors.linkage.chain.resistance_key",
                                           {"want": want, "output": output}))
    strokes = ("away", "toward") if out_kind == "slider" else ("ccw", "cw")
    positions, angles, working = read_plan(ck, data, strokes, loads, omega, resistance_paths,
                                           working_default=strokes[0])
    ck.raise_if_any()
    return ChainSpec(kind="chain", name=name, mechanism=mechanism, output=output,
                     omega=omega, epsilon=epsilon, gravity=gravity,
                     links=MappingProxyType(links), loads=tuple(loads),
                     positions=positions, crank_angles_deg=angles,
                     working_stroke=working, raw=MappingProxyType(dict(data)),
                     source=source)


def is_chain(data) -> bool:
    """True when the TOML content ``data`` is a chain spec (``[mechanism] kind = "chain"``)."""
    m = data.get("mechanism") if isinstance(data, dict) else None
    return isinstance(m, dict) and m.get("kind") == "chain"
