"""Every key of a linkage spec file, declared once (:mod:`crankbase.schema`).

SI units in the file (lengths in m, angles in degrees); the words (labels, help,
symbols) are in the ``spec`` catalogue under ``spec.<table>.<key>``.
:func:`linkage.load_spec` reads every table through this schema and adds the checks
that join several keys.
"""
from __future__ import annotations

from crankbase.schema import ArrayOfTables, Key, Schema, Table
from crankbase.validation import MAX_ROWS

__all__ = ["SCHEMA", "MECHANISM", "LINKS", "LINK", "LOAD", "ANALYSIS", "KINDS",
           "LINK_NAMES", "WORKING_STROKES"]

KINDS = ("crank-rocker", "crank-slider")
#: Link names per kind, in the textbook numbering 2, 3, 4.
LINK_NAMES = {"crank-rocker": ("crank", "coupler", "rocker"),
              "crank-slider": ("crank", "coupler", "slider")}
#: The strokes of the output link, per kind ([analysis] working_stroke).
WORKING_STROKES = {"crank-rocker": ("ccw", "cw"), "crank-slider": ("away", "toward")}

M = dict(unit="m")

MECHANISM = Table("mechanism", (
    Key("kind", "choice", choices=KINDS, required=True),
    Key("name", "name", default="mechanism"),
    Key("crank", gt=0, divisor=True, required=True, symbol=True, **M),
    Key("coupler", gt=0, divisor=True, required=True, symbol=True, **M),
    Key("rocker", gt=0, divisor=True, required="cond", symbol=True, **M),
    Key("ground", gt=0, divisor=True, required="cond", symbol=True, **M),
    Key("ground_angle_deg", unit="deg", default=0.0),
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
    Key("span_deg", gt=0, unit="deg"),
    Key("span_m", gt=0, **M),
))

ANALYSIS = Table("analysis", (
    Key("positions", "integer", ge=1, le=MAX_ROWS, default=12),
    Key("crank_angles_deg", "numbers", min_length=1, unit="deg"),
    Key("working_stroke", "choice", choices=("ccw", "cw", "away", "toward"),
        required="cond"),
))

#: The linkage spec file (``crankdyn linkage``; ``[drawing]`` is read by
#: :mod:`plans.drawing`, ``[dynamics]`` by :mod:`dynamics.spec`).
SCHEMA = Schema("linkage", (MECHANISM, LINKS, LOAD, ANALYSIS), extra=("drawing",))
