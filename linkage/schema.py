"""Every key of a linkage spec file, declared once (:mod:`crankbase.schema`).

SI units in the file (lengths in m, angles in degrees); the words (labels, help,
symbols) are in the ``spec`` catalogue under ``spec.<table>.<key>``.
:func:`linkage.load_spec` reads every table through this schema and adds the checks
that join several keys.
"""
from __future__ import annotations

from crankbase.schema import ArrayOfTables, Key, Schema, Table
from crankbase.validation import MAX_ROWS

__all__ = ["SCHEMA", "SCHEMAS", "CHAIN_SCHEMA", "CHAIN_MECHANISM", "GROUP", "GROUP_KINDS",
           "MECHANISM", "LINKS", "LINK", "LOAD", "ANALYSIS", "KINDS",
           "LINK_NAMES", "WORKING_STROKES"]

KINDS = ("crank-rocker", "crank-slider")
#: Link names per kind, in the textbook numbering 2, 3, 4.
LINK_NAMES = {"crank-rocker": ("crank", "coupler", "rocker"),
              "crank-slider": ("crank", "coupler", "slider")}
#: The strokes of the output link, per kind ([analysis] working_stroke).
WORKING_STROKES = {"crank-rocker": ("ccw", "cw"), "crank-slider": ("away", "toward")}

M = dict(unit="m")

MECHANISM = Table("mechanism", (
    Key("kind", "choice", choices=KINDS + ("chain",), required=True),
    Key("name", "name", default="mechanism"),
    Key("crank", gt=0, divisor=True, required=True, symbol=True, **M),
    Key("coupler", gt=0, divisor=True, required=True, symbol=True, **M),
    Key("rocker", gt=0, divisor=True, required="cond", symbol=True, **M),
    Key("ground", gt=0, divisor=True, required="cond", symbol=True, **M),
    Key("ground_angle_deg", unit="°", default=0.0),
    Key("offset", default=0.0, symbol=True, **M),
    Key("assembly", "choice", choices=(1, -1), default=1),
    Key("omega_rad_s", unit="rad/s", required=True, symbol=True),
    Key("epsilon_rad_s2", unit="rad/s²", default=0.0, symbol=True),
    Key("gravity_m_s2", ge=0, unit="m/s²", default=9.81, symbol=True),
), required=True)

#: One link's table; read as ``[links.crank]``, ``[links.coupler]``, ``[links.rocker]``
#: or ``[links.slider]``.
LINK = Table("links.<link>", (
    Key("mass_kg", ge=0, unit="kg", default=0.0, symbol=True),
    Key("inertia_kg_m2", ge=0, unit="kg·m²", default=0.0, symbol=True),
    Key("cg", "numbers", length=2, shown_default="spec.default.link_middle", **M),
    Key("points", "points", **M),
))

LINKS = Table("links", (LINK,))

LOAD = ArrayOfTables("load", (
    Key("link", "choice", choices=("crank", "coupler", "rocker", "slider"),
        required=True),
    Key("at", "numbers", length=2, shown_default="[0, 0]", **M),
    Key("force_N", "numbers", length=2, unit="N", required="cond"),
    Key("moment_Nm", unit="N·m", required="cond"),
    Key("resistance_Nm", ge=0, unit="N·m", required="cond"),
    Key("resistance_N", ge=0, unit="N", required="cond"),
    Key("stroke", "choice", choices=("working", "idle", "both"), default="working"),
    Key("start_deg", ge=0, unit="°", default=0.0),
    Key("start_m", ge=0, default=0.0, **M),
    Key("span_deg", gt=0, unit="°"),
    Key("span_m", gt=0, **M),
    Key("from_fraction", ge=0, lt=1, default=0.0),
    Key("to_fraction", gt=0, le=1, default=1.0),
))

ANALYSIS = Table("analysis", (
    Key("positions", "integer", ge=1, le=MAX_ROWS, default=12),
    Key("crank_angles_deg", "numbers", min_length=1, unit="°"),
    Key("working_stroke", "choice", choices=("ccw", "cw", "away", "toward"),
        required="cond"),
))

#: The linkage spec file (``crankdyn linkage``; ``[drawing]`` is read by
#: :mod:`plans.drawing`, ``[dynamics]`` by :mod:`dynamics.spec`).
SCHEMA = Schema("linkage", (MECHANISM, LINKS, LOAD, ANALYSIS), extra=("drawing",))


# ------------------------------------------------------------ any chain of Assur groups

#: Kinds of class II group of a chain spec (:mod:`linkage.chain`).
GROUP_KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")

#: ``[mechanism]`` of a chain spec (``kind = "chain"``): the frame's joints, the crank
#: (the driver I(0,1)) and the output link; the groups follow in ``[[group]]``.
CHAIN_MECHANISM = Table("mechanism", (
    Key("kind", "choice", choices=KINDS + ("chain",), required=True),
    Key("name", "name", default="mechanism"),
    Key("frame", "points", required=True, **M),
    Key("crank", gt=0, divisor=True, required=True, symbol=True, **M),
    Key("crank_link", "string", default="crank"),
    Key("pivot", "string", default="O"),
    Key("pin", "string", default="A"),
    Key("output", "string", required=True),
    Key("omega_rad_s", unit="rad/s", required=True, symbol=True),
    Key("epsilon_rad_s2", unit="rad/s²", default=0.0, symbol=True),
    Key("gravity_m_s2", ge=0, unit="m/s²", default=9.81, symbol=True),
), required=True)

#: One class II group of a chain, in the order of the structure formula.
GROUP = ArrayOfTables("group", (
    Key("kind", "choice", choices=GROUP_KINDS, required=True),
    Key("links", "names", length=2, required=True),
    Key("joints", "names", required=True),
    Key("lengths", "numbers", gt=0, min_length=1, max_length=2, required="cond", **M),
    Key("assembly", "choice", choices=(1, -1), default=1),
    Key("offset", default=0.0, **M),
    Key("guide_link", "string", default="frame"),
    Key("guide_point", "numbers", length=2, shown_default="[0, 0]", **M),
    Key("guide_angle_deg", unit="°", default=0.0),
    Key("guide_offset", default=0.0, **M),
    Key("guide2_link", "string", default="frame"),
    Key("guide2_point", "numbers", length=2, shown_default="[0, 0]", **M),
    Key("guide2_angle_deg", unit="°", default=90.0),
    Key("guide2_offset", default=0.0, **M),
    Key("slot_angle_deg", unit="°", default=90.0),
), min_items=1)

#: A chain spec file (``[mechanism] kind = "chain"``): any linkage of class II groups.
CHAIN_SCHEMA = Schema("chain", (CHAIN_MECHANISM, GROUP, LINKS, LOAD, ANALYSIS),
                      extra=("drawing",))

#: Both spec files of ``crankdyn linkage`` (the README's reference lists each).
SCHEMAS = (SCHEMA, CHAIN_SCHEMA)
