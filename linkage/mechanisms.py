"""Crank-rocker and crank-slider, assembled from the Assur-group routines.

Structure formula of both: ``I(1,2) → II(3,4)``.  The crank-rocker O-A-B-C uses the RRR
dyad, the crank-slider O-A-B the RRP dyad.  Kinematics runs driver → dyad; kinetostatics
dyad → driver (:mod:`linkage.groups`).

Also here: the geometry of the cycle: rotatability (an :class:`AssemblyError` naming the
crank angles where the dyad cannot be assembled), singular (change-point) positions, the
two extreme positions of the output link, swing or stroke, time-ratio coefficient, and
the transmission angle (by :mod:`linkage.fourbar`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from crankbase.errors import AssemblyError, Text
from crankbase.tolerances import ASSEMBLY_CHECK_RTOL, ROTATABILITY_RTOL, ROUNDOFF_RTOL

from . import fourbar
from . import groups as g

__all__ = ["CrankRocker", "CrankSlider", "Extremes"]

TWO_PI = 2.0 * math.pi


def _wrap(x):
    """Wrap angles to [0, 2π)."""
    return np.mod(x, TWO_PI)


def _deg360(a):
    """An angle in degrees wrapped to [0, 360) (a wrap that rounds to 360 gives 0)."""
    a = a % 360.0
    return 0.0 if a >= 360.0 - ROUNDOFF_RTOL * 360.0 else a


def _intervals_deg(lo, hi):
    """Format a crank-angle interval (radians, lo < hi) in degrees wrapped to [0, 360)."""
    if hi - lo >= TWO_PI * (1.0 - ROUNDOFF_RTOL):
        return "0°…360° (every crank angle)"
    a, b = math.degrees(lo) % 360.0, math.degrees(hi) % 360.0
    return f"{a:.4g}°…{b:.4g}°"


@dataclass(frozen=True)
class Extremes:
    """The two extreme positions of the output link.

    Attributes
    ----------
    phi_start, phi_end : float
        Crank angles (rad, ccw from +x) where the working stroke starts and ends.
    working_crank_angle : float
        Crank rotation during the working stroke, in the direction of rotation. [rad]
    """

    phi_start: float
    phi_end: float
    working_crank_angle: float

    @property
    def idle_crank_angle(self):
        return TWO_PI - self.working_crank_angle

    @property
    def time_ratio(self):
        """Time-ratio coefficient K = φ_working / φ_idle (duration of the working stroke
        over that of the idle stroke at constant crank speed). [-]"""
        return self.working_crank_angle / self.idle_crank_angle


class _CrankMechanism:
    """Common parts of the two mechanisms (driver, points, extremes)."""

    kind = ""
    output = ""

    def __init__(self, crank, coupler, assembly=1, pivot=0j):
        self.l1 = float(crank)
        self.l2 = float(coupler)
        self.assembly = int(assembly)
        self.pivot = complex(pivot)

    # -- driver
    def driver(self, phi, omega, eps):
        """Crank motion at crank angles ``phi`` [rad]."""
        return g.crank(phi, omega, eps, self.l1, self.pivot)

    def kinematics(self, phi, omega, eps):
        """Kinematics at crank angles ``phi`` [rad] (array), ω [rad/s], ε [rad/s²].

        Returns
        -------
        dict
            ``crank`` (LinkMotion), ``A`` (PointMotion), ``dyad`` (the dyad solution) and
            ``links`` mapping link name → LinkMotion.
        """
        cr = self.driver(phi, omega, eps)
        A = cr.point(self.l1)
        dyad = self._dyad(A)
        return {"crank": cr, "A": A, "dyad": dyad,
                "links": {"crank": cr, "coupler": dyad.link3, self.output: dyad.link4}}

    # -- extreme positions
    def _extreme_candidates(self):  # pragma: no cover - abstract
        raise NotImplementedError

    def extremes(self, rotation_sign: int, working: str) -> Extremes | None:
        """The two extreme positions of the output link, in the plan-of-positions order.

        Parameters
        ----------
        rotation_sign : {+1, -1}
            Direction of crank rotation (+1 ccw).
        working : str
            Direction of the output link in the working stroke (``"ccw"``/``"cw"`` for a
            rocker, ``"away"``/``"toward"`` for a slider).

        Returns
        -------
        Extremes or None
            None when the output link turns fully (a double crank has no extremes).

        Notes
        -----
        At an extreme position the output velocity is zero, which happens exactly when
        crank and coupler are collinear (extended or folded).  The candidate crank
        angles are closed form; each is confirmed against the dyad's own assembly branch.
        After an extreme the output moves in the direction of its acceleration there
        (its velocity being zero), which tells the start of the working stroke from its
        end.
        """
        phis = self._extreme_candidates()
        if len(phis) != 2:
            return None
        phis = np.array(phis)
        kin = self.kinematics(phis, float(rotation_sign), 0.0)
        acc = self.output_rate(kin, second=True)
        sign_work = self.working_sign(working)
        starts = np.flatnonzero(acc * sign_work > 0)
        if len(starts) != 1:  # degenerate (change point at an extreme)
            starts = [int(np.argmax(acc * sign_work))]
        i = int(starts[0])
        p0, p1 = float(_wrap(phis[i])), float(_wrap(phis[1 - i]))
        work = float(_wrap((p1 - p0) * rotation_sign))
        return Extremes(p0, p1, work)

    def working_sign(self, working):
        """+1 or −1: the sign of the output's rate during the working stroke
        (``working``: "ccw", "cw" for a rocker, "away", "toward" for a slider)."""
        return {"ccw": 1, "cw": -1, "away": self.assembly, "toward": -self.assembly}[working]

    def _collinear_extreme(self, candidates, folded):
        """The crank angle (a list of at most one) at which the crank pin lies on the line
        O→B for one of the candidate pin positions B (extended) or opposite it (folded),
        confirmed against the dyad's assembly branch."""
        phis = [np.angle(b - self.pivot) + (math.pi if folded else 0.0) for b in candidates]
        return self._confirm(phis, candidates)[:1]

    def _confirm(self, phis, targets):
        """Keep the candidate crank angles whose assembled B equals the target B."""
        phis = np.asarray(phis, float)
        kin = self.kinematics(phis, 1.0, 0.0)
        ok = abs(kin["dyad"].B.z - np.asarray(targets)) <= \
            ASSEMBLY_CHECK_RTOL * (self.l1 + self.l2)
        return [float(p) for p in phis[ok]]


class CrankRocker(_CrankMechanism):
    """Crank-rocker (four-bar) O-A-B-C: crank OA, coupler AB, rocker CB, ground OC.

    Parameters
    ----------
    crank, coupler, rocker, ground : float
        |OA|, |AB|, |CB|, |OC|. [m]
    ground_angle : float
        Direction of O→C, ccw from +x. [rad]
    assembly : {+1, -1}
        +1 puts B to the left of the directed line A→C.
    pivot : complex
        Position of O. [m]
    """

    kind = "crank-rocker"
    output = "rocker"

    def __init__(self, crank, coupler, rocker, ground, ground_angle=0.0, assembly=1,
                 pivot=0j):
        super().__init__(crank, coupler, assembly, pivot)
        self.l3 = float(rocker)
        self.l0 = float(ground)
        self.ground_angle = float(ground_angle)
        self.zC = self.pivot + self.l0 * complex(math.cos(ground_angle), math.sin(ground_angle))

    def _dyad(self, A):
        C = g.PointMotion(self.zC, 0j, 0j)        # the rocker pivot, at rest
        return g.rrr(A, C, self.l2, self.l3, self.assembly)

    def reactions(self, kin, wrenches):
        """Reactions from link wrenches (``crank``, ``coupler``, ``rocker``)."""
        r = g.rrr_reactions(kin["dyad"], self.l2, self.l3, wrenches["coupler"],
                            wrenches["rocker"])
        d = g.driver_reactions(kin["crank"], kin["A"].z, -r.RA, wrenches["crank"])
        return r, d

    def grashof(self) -> fourbar.GrashofType:
        """Grashof type (:func:`linkage.fourbar.grashof`)."""
        return fourbar.grashof(self.l1, self.l2, self.l3, self.l0)

    def min_transmission_angle(self):
        """(μmin [deg], absolute crank angle of μmin [deg] in [0, 360)) over a full turn,
        closed form on the line of centres (:mod:`linkage.fourbar`)."""
        mu, at = fourbar.mu_min_on_line_of_centres(self.l1, self.l2, self.l3, self.l0)
        return float(mu), _deg360(float(at) + math.degrees(self.ground_angle))

    def _cos_limits(self):
        """cos(φ − γ) thresholds: D² = l0² + l1² − 2·l0·l1·cos(φ−γ) with D = |AC|."""
        l0, l1, l2, l3 = self.l0, self.l1, self.l2, self.l3
        c_near = (l0 * l0 + l1 * l1 - (l2 - l3) ** 2) / (2 * l0 * l1)  # D = |l2 − l3|
        c_far = (l0 * l0 + l1 * l1 - (l2 + l3) ** 2) / (2 * l0 * l1)   # D = l2 + l3
        return c_near, c_far

    def check_rotatable(self, tol=ROTATABILITY_RTOL):
        """Raise :class:`AssemblyError` unless the crank can turn fully.

        The rule is :func:`linkage.fourbar.rotatability_margin` (the dyad assembles where
        ``|l2 − l3| ≤ |AC| ≤ l2 + l3``): a mechanism within ``tol`` of the limit counts as
        a change-point mechanism and is accepted, the same rule and margin as
        :func:`linkage.fourbar.grashof` and the synthesis region's boundary.  The crank
        angles where the dyad does not assemble are reported (closed form).
        """
        far, near, near2 = fourbar.rotatability_residuals(self.l1, self.l2, self.l3, self.l0)
        scale = math.sqrt(2.0) * self.l0
        c_near, c_far = self._cos_limits()
        gam = self.ground_angle
        bad, ends = [], []
        if min(near, near2) / scale < -tol:  # |AC| too short around φ = γ
            h = math.acos(max(-1.0, c_near))
            bad.append(Text("errors.linkage.mechanisms.short",
                            {"angles": _intervals_deg(gam - h, gam + h)}))
            ends += [math.degrees(gam - h) % 360, math.degrees(gam + h) % 360]
        if far / scale < -tol:  # |AC| too long around φ = γ + π
            h = math.acos(min(1.0, c_far))
            bad.append(Text("errors.linkage.mechanisms.long",
                            {"angles": _intervals_deg(gam + h, gam + TWO_PI - h)}))
            ends += [math.degrees(gam + h) % 360, math.degrees(gam - h) % 360]
        if bad:
            raise AssemblyError(
                Text("errors.linkage.mechanisms.crank_cannot_turn",
                     {"items": bad, "value": Text("linkage.grashof." + str(self.grashof())
                                                  .lower().replace("-", "_"))}), ends)

    def singular_angles(self, tol=ROTATABILITY_RTOL):
        """Crank angles [rad] where all four joints are collinear (change point)."""
        far, near, near2 = fourbar.rotatability_residuals(self.l1, self.l2, self.l3, self.l0)
        scale = math.sqrt(2.0) * self.l0
        out = []
        if abs(min(near, near2)) / scale <= tol:
            out.append(float(_wrap(self.ground_angle)))
        if abs(far) / scale <= tol:
            out.append(float(_wrap(self.ground_angle + math.pi)))
        return out

    def _extreme_candidates(self):
        """Crank angles where crank and coupler are collinear (rocker at rest)."""
        out = []
        for d, folded in ((self.l1 + self.l2, False), (self.l2 - self.l1, True)):
            if d <= 0:
                continue
            # B on the circle (O, d) and on the circle (C, l3): both intersections.
            D = self.l0
            p = (d * d - self.l3 * self.l3 + D * D) / (2 * D)
            h2 = d * d - p * p
            if h2 < 0:
                return []  # the rocker turns fully: no extreme positions
            ed = (self.zC - self.pivot) / D
            cands = [self.pivot + (p + 1j * s * math.sqrt(h2)) * ed for s in (1, -1)]
            out.extend(self._collinear_extreme(cands, folded))
        return out

    def output_rate(self, kin, second=False):
        """The rocker's ω4 [rad/s] (its ε4 [rad/s²] with ``second``)."""
        d = kin["dyad"]
        return d.link4.eps if second else d.link4.omega

    def output_coordinate(self, kin):
        """Rocker angle θ4 [rad]."""
        return kin["dyad"].link4.theta

    def transmission_angle(self, kin):
        """Acute angle between coupler and rocker at B. [rad]"""
        d = kin["dyad"]
        return fourbar.transmission_angle(d.link4.e, d.link3.e)


class CrankSlider(_CrankMechanism):
    """Crank-slider O-A-B: crank OA, rod AB, slider B on a straight guide.

    Parameters
    ----------
    crank, coupler : float
        |OA|, |AB|. [m]
    guide_angle : float
        Direction of the guide, ccw from +x. [rad]
    offset : float
        Distance of the guide line from O, + to the left of the guide direction. [m]
    assembly : {+1, -1}
        +1 puts B ahead of A along the guide direction.
    pivot : complex
        Position of O. [m]
    """

    kind = "crank-slider"
    output = "slider"

    def __init__(self, crank, coupler, guide_angle=0.0, offset=0.0, assembly=1, pivot=0j):
        super().__init__(crank, coupler, assembly, pivot)
        self.guide_angle = float(guide_angle)
        self.offset = float(offset)
        self.u = complex(math.cos(guide_angle), math.sin(guide_angle))

    def _dyad(self, A):
        return g.rrp(A, self.l2, self.pivot, self.guide_angle, self.offset, self.assembly)

    def reactions(self, kin, wrenches):
        """Reactions from link wrenches (``crank``, ``coupler``, ``slider``)."""
        r = g.rrp_reactions(kin["dyad"], self.l2, wrenches["coupler"], wrenches["slider"])
        d = g.driver_reactions(kin["crank"], kin["A"].z, -r.RA, wrenches["crank"])
        return r, d

    def grashof(self) -> fourbar.SliderCrankType:
        """Rotatability type (:func:`linkage.fourbar.slider_crank_type`)."""
        return fourbar.slider_crank_type(self.l1, self.l2, self.offset)

    def min_transmission_angle(self):
        """(μmin [deg], absolute crank angle of μmin [deg] in [0, 360)) over a full turn,
        closed form (:func:`linkage.fourbar.min_transmission_angle_slider_deg`)."""
        mu, at = fourbar.min_transmission_angle_slider_deg(self.l1, self.l2, self.offset)
        return mu, _deg360(at + math.degrees(self.guide_angle))

    def check_rotatable(self, tol=ROTATABILITY_RTOL):
        """Raise :class:`AssemblyError` unless the crank can turn fully
        (|offset − y_A| ≤ L in guide coordinates for every crank angle): the rule of
        :func:`linkage.fourbar.slider_rotatability_margin` on each side of the guide,
        (L − r ∓ e)/r ≥ −``tol``."""
        l1, L, e = self.l1, self.l2, self.offset
        gam = self.guide_angle
        bad, ends = [], []
        for bound, label in (((e - L) / l1, "below"), ((e + L) / l1, "above")):
            # fails where sin(φ − γ) < (e − L)/l1 (first) or > (e + L)/l1 (second)
            if label == "below" and bound > -1 + tol:
                lo = math.asin(min(1.0, bound))
                # sin x < bound for x in (π − lo, 2π + lo)
                bad.append(f"rod too short for crank angles {_intervals_deg(gam + math.pi - lo, gam + TWO_PI + lo)}")
                ends += [math.degrees(gam + math.pi - lo) % 360, math.degrees(gam + lo) % 360]
            if label == "above" and bound < 1 - tol:
                hi = math.asin(max(-1.0, bound))
                bad.append(f"rod too short for crank angles {_intervals_deg(gam + hi, gam + math.pi - hi)}")
                ends += [math.degrees(gam + hi) % 360, math.degrees(gam + math.pi - hi) % 360]
        if bad:
            raise AssemblyError(
                Text("errors.linkage.mechanisms.crank_cannot_turn_2",
                     {"items": "; ".join(bad)}), ends)

    def singular_angles(self, tol=ROTATABILITY_RTOL):
        """Crank angles [rad] where the rod stands perpendicular to the guide."""
        l1, L, e = self.l1, self.l2, self.offset
        out = []
        if abs((e - L) / l1 + 1) <= tol:
            out.append(float(_wrap(self.guide_angle - math.pi / 2)))
        if abs((e + L) / l1 - 1) <= tol:
            out.append(float(_wrap(self.guide_angle + math.pi / 2)))
        return out

    def _extreme_candidates(self):
        """Crank angles where crank and rod are collinear (slider at rest)."""
        out = []
        for d, folded in ((self.l1 + self.l2, False), (self.l2 - self.l1, True)):
            if d < abs(self.offset) * (1.0 - ROUNDOFF_RTOL):
                continue  # (d = |offset|: a change point, the extreme is the dead position)
            x = math.sqrt(max(d * d - self.offset ** 2, 0.0))
            cands = [self.pivot + (s * x + 1j * self.offset) * self.u for s in (1, -1)]
            out.extend(self._collinear_extreme(cands, folded))
        return out

    def output_rate(self, kin, second=False):
        """The slider's speed along the guide [m/s] (its acceleration [m/s²] with
        ``second``)."""
        d = kin["dyad"]
        return d.a if second else d.v

    def output_coordinate(self, kin):
        """Slider displacement s along the guide from the foot of O. [m]"""
        return kin["dyad"].s

    def transmission_angle(self, kin):
        """90° minus the acute angle between rod and guide: the acute angle between the
        rod and the guide's normal. [rad]"""
        return fourbar.transmission_angle(kin["dyad"].link4.e.perp(), kin["dyad"].link3.e)
