"""External loads of a mechanism spec at every position: applied forces and moments, and
the useful resistance (the one implementation of its rule).

A useful resistance (``[[load]] resistance_Nm`` on the rocker, ``resistance_N`` on the
slider) always opposes the motion of its link, acts only while the link moves in the
load's stroke (``"working"``, ``"idle"`` or ``"both"``), and, with a window, only while
the swing (travel) from the start of that stroke is inside the window: from ``start``
(``start_deg``/``start_m``, 0 by default) over ``span`` (``span_deg``/``span_m``, to the
stroke's end by default), or from ``from_fraction``·H to ``to_fraction``·H of the stroke
(swing) H.  This is the useful resistance (момент полезного сопротивления Mпс) of the
course projects on the theory of machines, e.g. a constant moment on the rocker of a
ratchet drive during the first τ radians of the working stroke, or the cutting force of a
shaping machine between its idle runs of 0.05·H at both ends of the cut (0.05 … 0.95 of
the stroke).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.tolerances import AT_REST_RTOL, ROUNDOFF_RTOL

from .course import course_of
from .groups import Vec

__all__ = ["StrokeCycle", "stroke_cycle", "resistance", "resistance_window", "external_loads"]


@dataclass(frozen=True)
class StrokeCycle:
    """What the resistance rule needs to know of the cycle.

    Attributes
    ----------
    working_sign : {+1, -1}
        Sign of the output rate (ω4, or the slider velocity along the guide direction) in
        the working stroke.
    start_working, start_idle : float
        Output coordinate (rocker angle θ4 [rad], or slider position s4 [m]) at the start
        of the working and of the idle stroke (the two extreme positions).
    rocker : bool
        True for a rocker (the coordinate is an angle, wrapped), False for a slider.
    at_rest : float
        |rate| at or below which the output counts as at rest (AT_REST_RTOL of |ω2|, or
        of |ω2|·|OA| for a slider). [rad/s] or [m/s]
    """

    working_sign: int
    start_working: float | None
    start_idle: float | None
    rocker: bool
    at_rest: float

    def travel(self, coord, working):
        """Swing [rad] (wrapped, in [0, π]) or travel [m] of the output from the start
        of the current stroke (``working``: True in the working stroke)."""
        d = np.abs(coord - np.where(working, self.start_working, self.start_idle))
        if self.rocker:   # |angle of e^{iΔθ}| = min(|Δθ|, 2π − |Δθ|) for |Δθ| ≤ 2π
            d = np.minimum(d, 2.0 * math.pi - d)
        return d

    @property
    def length(self):
        """The stroke [m] or swing [rad] between the two extreme positions (None when the
        strokes are not known)."""
        if self.start_working is None or self.start_idle is None:
            return None
        return float(self.travel(np.float64(self.start_idle), True))


def stroke_cycle(mech, spec, ext) -> StrokeCycle:
    """The cycle data of the resistance rule for a mechanism and its spec.

    ``ext`` is the mechanism's :class:`~linkage.mechanisms.Extremes` (None in statics or
    for an output that turns fully); without it, or without ``working_stroke`` in the
    spec, the strokes are not known and a resistance acts whenever its link moves (only
    ``stroke = "both"`` is valid then)."""
    rocker = course_of(spec).angular
    at_rest = AT_REST_RTOL * abs(spec.omega) * (1.0 if rocker else spec.crank)
    if spec.working_stroke is None or ext is None:
        return StrokeCycle(1, None, None, rocker, at_rest)
    with np.errstate(divide="ignore", invalid="ignore"):
        ek = mech.kinematics(np.array([ext.phi_start, ext.phi_end]), spec.omega, 0.0)
    c = mech.output_coordinate(ek)
    return StrokeCycle(mech.working_sign(spec.working_stroke), float(c[0]), float(c[1]),
                       rocker, at_rest)


def resistance_window(ld, cycle: StrokeCycle):
    """Where a resistance acts inside its stroke: ``(start, end)``, the swing [rad] or
    travel [m] from the start of the stroke (``start`` None: from the stroke's start;
    ``end`` None: to its end).

    ``ld`` is a :class:`LoadSpec`: ``span`` alone gives ``(None, span)`` (the rule before
    windows, unchanged; a span longer than the stroke acts over the whole stroke);
    ``start`` gives ``(start, start + span)`` (``span`` None: to the stroke's end); the
    fractions ``(f0, f1)`` of the stroke (swing) H give ``(f0·H, f1·H)``.

    Raises
    ------
    SpecError
        A window (``start`` or fractions) of an output whose strokes are not known (it
        turns fully), or a window that does not fit in the stroke (``start`` ≥ H or
        ``start + span`` > H), named by the load's key path ``ld.key``.
    """
    if ld.start is None and ld.fractions is None:
        return None, ld.span
    length = cycle.length
    if length is None:
        raise SpecError(Problem(ld.key, Text("errors.linkage.spec.window_needs_extremes",
                                             {"key": ld.key.rsplit(".", 1)[-1]})))
    if ld.fractions is not None:
        f0, f1 = ld.fractions
        return f0 * length, f1 * length
    start = ld.start
    end = start + ld.span if ld.span is not None else None
    if start >= length or (end is not None and end > length * (1.0 + ROUNDOFF_RTOL)):
        conv = math.degrees if cycle.rocker else float
        raise SpecError(Problem(ld.key, Text(
            "errors.linkage.spec.window_outside_" + ("deg" if cycle.rocker else "m"),
            {"start": conv(start), "end": conv(end if end is not None else length),
             "length": conv(length)})))
    return start, end


def resistance(value, stroke, span, rate, coord, cycle: StrokeCycle, start=None):
    """The useful resistance at every position: ``−sign(rate)·value`` where it acts, else 0.

    Parameters
    ----------
    value : float
        Magnitude of the resistance (moment [N·m] on a rocker, force [N] on a slider).
    stroke : {"working", "idle", "both"}
        The stroke in which it acts.
    span : float or None
        It acts only while the output's swing [rad] or travel [m] from the start of that
        stroke is at most ``span`` (None: to the end of the stroke).
    rate, coord : ndarray
        Output rate (ω4 [rad/s] or slider velocity [m/s] along the guide direction) and
        coordinate (θ4 [rad] or s4 [m]) at every position.
    cycle : StrokeCycle
    start : float or None
        ... and only once that swing [rad] or travel [m] is at least ``start`` (None or 0:
        from the start of the stroke).  ``(start, span)`` is what
        :func:`resistance_window` gives for a load.

    Returns
    -------
    ndarray
        The resistance, + ccw (rocker) or + along the guide direction (slider).
    """
    moving = np.abs(rate) > cycle.at_rest
    if cycle.start_working is None:        # strokes unknown: "both"
        active = moving
        working = None
    else:
        working = rate * cycle.working_sign > 0
        active = moving & {"working": working, "idle": ~working, "both": True}[stroke]
        if span is not None or start:
            travel = cycle.travel(coord, working)
            if span is not None:
                active = active & (travel <= span * (1.0 + ROUNDOFF_RTOL))
            if start:
                active = active & (travel >= start * (1.0 - ROUNDOFF_RTOL))
    return np.where(active, -np.sign(rate) * value, 0.0)


def external_loads(spec, mech, kin, cycle: StrokeCycle):
    """Applied forces and moments of a spec on every link at the positions of ``kin``.

    Parameters
    ----------
    spec : MechanismSpec
    mech : CrankRocker or CrankSlider
    kin : dict
        :meth:`~linkage.mechanisms.CrankRocker.kinematics` at the positions.
    cycle : StrokeCycle

    Returns
    -------
    forces : dict
        link name → list of (force [N], global point [m]) as :class:`~linkage.groups.Vec`.
    moments : dict
        link name → list of moments [N·m], + ccw.
    res : ndarray or float
        The sum of the useful resistances (rocker: moment [N·m]; slider: force along the
        guide direction [N]); 0.0 without one.
    """
    forces = {n: [] for n in spec.link_names}
    moments = {n: [] for n in spec.link_names}
    res = 0.0
    rate = coord = None
    for ld in spec.loads:
        link = kin["links"][ld.link]
        if ld.kind == "force":
            forces[ld.link].append((Vec.of(ld.force), link.point(ld.at).z))
        elif ld.kind == "moment":
            moments[ld.link].append(ld.moment)
        else:
            if rate is None:
                rate, coord = mech.output_rate(kin), mech.output_coordinate(kin)
            start, end = resistance_window(ld, cycle)
            value = resistance(ld.resistance, ld.stroke, end, rate, coord, cycle, start)
            res = res + value
            if cycle.rocker:
                moments[ld.link].append(value)
            else:
                forces[ld.link].append((Vec.of(mech.u) * value, kin["dyad"].B.z))
    return forces, moments, res


@dataclass(frozen=True)
class LoadSpec:
    """One external load.

    ``kind`` is ``"force"`` (global components ``force`` [N] at local point ``at`` [m]),
    ``"moment"`` (``moment`` [N·m], + ccw) or ``"resistance"`` (magnitude ``resistance``
    [N·m] on a rocker or [N] on a slider, always opposing the link's motion, only in
    ``stroke`` and only inside its window: from ``start`` (None: the stroke's start) over
    ``span`` (None: to the stroke's end) of swing [rad] or travel [m] from the start of the
    stroke, or from ``fractions[0]``·H to ``fractions[1]``·H of the stroke (swing) H;
    :func:`resistance_window`).  ``key`` is the key path of the window (or of the
    resistance) that an error about the window names.
    """

    link: str
    kind: str
    at: complex = 0j
    force: complex = 0j
    moment: float = 0.0
    resistance: float = 0.0
    stroke: str = "working"
    span: float | None = None
    start: float | None = None
    fractions: tuple[float, float] | None = None
    key: str = field(default="", compare=False)
