"""The four-bar's course as data: what tells a crank-rocker from a crank-slider.

Both are instances of the chain (:func:`linkage.chain.from_mechanism`: ``I(0,1) → II
RRR(2,3)`` or ``I(0,1) → II RRP(2,3)``), solved and loaded by the same routines.  What
the course adds is names: the documented columns (``theta4_deg`` or ``s4_m`` …), the
reactions ``Rij`` by the textbook numbers of the links (1 ground, 2 crank, 3 coupler,
4 rocker or slider), the summary's fields, the relative motions of the course tables.
They are declared here once, one :class:`Course` per kind (:data:`COURSES`), and every
table, report, plot and plan reads them instead of branching on the kind.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["Course", "COURSES", "REACTIONS", "course_of"]


@dataclass(frozen=True)
class Course:
    """The names the course gives one kind of four-bar.

    Attributes
    ----------
    kind : str
        ``"crank-rocker"`` or ``"crank-slider"``.
    output : str
        The output link's name (link 4): ``"rocker"`` or ``"slider"``.
    angular : bool
        The output turns (a rocker: its coordinate is an angle, its swing is wrapped) or
        slides (a slider: a length along the guide).
    output_columns : tuple of str
        The kinematics columns of the output's coordinate, rate and acceleration, as the
        chain gives them (:func:`linkage.chain_analysis.output_motion`).
    coordinate_scale : float
        The chain's coordinate [rad or m] times this is the column's [deg or m].
    frame_pair : tuple of (str, str)
        The force columns of the frame–output pair R14 beyond its components: (column,
        attribute of the chain's :class:`~linkage.chain.Reaction`): the revolute C's
        components along and across the rocker, or the prismatic pair's normal force and
        couple.
    resistance_column : str
        The useful resistance: a moment on a rocker, a force on a slider.
    relative : tuple
        The relative motions of B in the course tables: (name, the joint B moves about —
        None for the frame joint C —, ω column, ε column, link whose length it is).
    default_working_stroke : str
        The working stroke when the spec gives none (for the extremes only).
    summary_fields : tuple of str
        The :class:`~linkage.analysis.AnalysisSummary` fields of the output at the start
        and the end of the working stroke and of its swing or stroke.
    summary_keys : tuple of str
        Their rows' catalogue keys (``linkage.cycle.<key>``, :mod:`linkage.report`).
    type_key : str
        The row of the mechanism's type: the Grashof type of a four-bar
        (``linkage.cycle.grashof``) or the rotatability of a crank-slider
        (``linkage.cycle.rotatable``).
    """

    kind: str
    output: str
    angular: bool
    output_columns: tuple
    coordinate_scale: float
    frame_pair: tuple
    resistance_column: str
    relative: tuple
    default_working_stroke: str
    summary_fields: tuple
    summary_keys: tuple
    type_key: str


#: The reactions the course tabulates: column stem → (link i, link j), the force of link
#: i on link j in the chain's names ("frame" the ground; "output" stands for link 4).
REACTIONS = (("R12", ("frame", "crank")), ("R23", ("crank", "coupler")),
             ("R43", ("output", "coupler")), ("R14", ("frame", "output")))

_BA = ("BA", "A", "omega3_rad_s", "eps3_rad_s2", "coupler")

#: One :class:`Course` per four-bar kind.
COURSES = {
    "crank-rocker": Course(
        kind="crank-rocker", output="rocker", angular=True,
        output_columns=("theta4_deg", "omega4_rad_s", "eps4_rad_s2"),
        coordinate_scale=180.0 / math.pi,
        frame_pair=(("R14_n_N", "n"), ("R14_t_N", "t")),
        resistance_column="M_res_Nm",
        relative=(_BA, ("BC", None, "omega4_rad_s", "eps4_rad_s2", "rocker")),
        default_working_stroke="ccw",
        summary_fields=("theta4_working_start_deg", "theta4_working_end_deg", "swing_deg"),
        summary_keys=("th_ws", "th_we", "swing"), type_key="grashof"),
    "crank-slider": Course(
        kind="crank-slider", output="slider", angular=False,
        output_columns=("s4_m", "v4_m_s", "a4_m_s2"),
        coordinate_scale=1.0,
        frame_pair=(("N14_N", "normal"), ("M14_Nm", "couple")),
        resistance_column="F_res_N",
        relative=(_BA,),
        default_working_stroke="away",
        summary_fields=("s4_working_start_m", "s4_working_end_m", "stroke_m"),
        summary_keys=("s_ws", "s_we", "stroke"), type_key="rotatable"),
}


def course_of(spec) -> Course:
    """The :class:`Course` of a four-bar spec (anything with a ``kind``)."""
    return COURSES[spec.kind]
