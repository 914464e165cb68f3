"""From a spec to the kinematics and force tables: :func:`analyze`.

The pipeline, vectorised over crank positions and run in cache-sized chunks:

1. build the mechanism (:mod:`linkage.mechanisms`: the closed forms of the cycle —
   Grashof type, extremes, μmin, singular positions), check that the crank turns fully,
   and its chain (:func:`linkage.chain.from_mechanism`: ``I(0,1) → II RRR(2,3)`` or
   ``I(0,1) → II RRP(2,3)``);
2. kinematics: the chain solved, driver then the dyad (:func:`linkage.chain.solve`);
3. the loads on every link at every position: external forces and moments, useful
   resistance (by stroke and window inside it), weight ``−m·g·j`` and d'Alembert inertia
   ``−m·a_S``, ``−J_S·ε``;
4. kinetostatics: the dyad, then the driver (balancing moment Mур)
   (:func:`linkage.chain.kinetostatics`).

The chain's quantities go into the columns under the names the course gives them,
declared once for both kinds in :mod:`linkage.course` (no branch on the kind).

Columns are SI with the unit in the name (``omega3_rad_s``, ``R23_x_N``); angles in
degrees.  ``Rij`` is the force of link i on link j (1 ground, 2 crank, 3 coupler or rod,
4 rocker or slider).
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.tolerances import SAME_ANGLE_RAD
from crankbase.validation import angles_argument, step_argument

from . import chain as ch
from . import groups as g
from .groups import CHUNK  # positions per chunk (one constant for every table)
from .columns import derived_kinematics_columns, force_columns, kinematics_columns, point_names
from .chain_analysis import output_motion
from .chain_spec import ChainSpec
from .course import REACTIONS, course_of
from .derived import fill_derived
from .fourbar import GrashofType, SliderCrankType
from .loads import external_loads, stroke_cycle
from .mechanisms import CrankRocker, CrankSlider
from .spec import MechanismSpec, load_spec

if TYPE_CHECKING:  # pandas is imported when a table is built
    import pandas as pd

__all__ = ["build_mechanism", "spec_chain", "as_chain", "analyze", "full_turn", "AnalysisResult", "AnalysisSummary",
           "solve_columns", "kinematics_columns", "force_columns", "plan_angles",
           "SingularPositionWarning", "CHUNK"]

_DEG = 180.0 / math.pi
_RAD = math.pi / 180.0      # x * _RAD is np.radians(x) bit for bit, without its slower loop



class SingularPositionWarning(UserWarning):
    """A change-point mechanism was analysed at (or its full turn passes) a singular
    position, where the output link's motion is indeterminate."""


def build_mechanism(spec: MechanismSpec):
    """The mechanism object of a spec (geometry only)."""
    # the two closed-form models take different geometry (the spec's keys differ)
    if spec.kind == "crank-rocker":
        return CrankRocker(spec.crank, spec.coupler, spec.rocker, spec.ground,
                           spec.ground_angle, spec.assembly)
    return CrankSlider(spec.crank, spec.coupler, spec.ground_angle, spec.offset,
                       spec.assembly)


def spec_chain(spec):
    """The chain of any linkage spec (:mod:`linkage.chain`), its crank checked to turn
    fully: a chain spec's own, or the chain of a crank-rocker's or crank-slider's
    mechanism (:func:`linkage.chain.from_mechanism`, the spec's masses and points).

    Raises
    ------
    AssemblyError
        The crank cannot turn fully (the four-bar's Grashof check, or the chain's cycle)."""
    if spec.kind == "chain":
        ch.check_cycle(spec.mechanism)
        return spec.mechanism
    mech = build_mechanism(spec)
    mech.check_rotatable()
    return ch.from_mechanism(mech, spec.links)


def as_chain(spec):
    """A crank-rocker's or crank-slider's spec as the chain spec it is: its chain
    (:func:`linkage.chain.from_mechanism`: ``I(0,1) → II RRR(2,3)`` with the frame's O and C,
    or ``I(0,1) → II RRP(2,3)`` with the guide on the frame; the links' names, masses,
    centres of mass and points), the output link (``rocker`` or ``slider``), its loads,
    analysis plan and content as read, so that :func:`analyze` solves and tabulates it as
    any chain (the chain's numbering: the frame 0, the crank 1).  A chain spec is
    returned as it is.

    Parameters
    ----------
    spec : MechanismSpec or linkage.chain_spec.ChainSpec

    Returns
    -------
    linkage.chain_spec.ChainSpec
    """
    if spec.kind == "chain":
        return spec
    chain = ch.from_mechanism(build_mechanism(spec), spec.links)
    return ChainSpec(kind="chain", name=spec.name, mechanism=chain,
                     output=course_of(spec).output, omega=spec.omega, epsilon=spec.epsilon,
                     gravity=spec.gravity, links=MappingProxyType(dict(chain.links)),
                     loads=spec.loads, positions=spec.positions,
                     crank_angles_deg=spec.crank_angles_deg,
                     working_stroke=spec.working_stroke, raw=spec.raw, source=spec.source)


class _Tables:
    """Everything a table needs that does not depend on the crank angle: the spec, the
    mechanism and its chain, the course's names, the cycle of the resistance rule, the
    column names, a scratch row."""

    def __init__(self, spec, mech, ext, course_tables, size):
        self.spec, self.mech, self.course_tables = spec, mech, course_tables
        self.course = course = course_of(spec)
        self.chain = ch.from_mechanism(mech, spec.links)
        self.cycle = stroke_cycle(mech, spec, ext)
        self.kcols = [c for c in kinematics_columns(spec, course_tables) if c != "position"]
        self.fcols = [c for c in force_columns(spec, course_tables) if c != "position"]
        self.points = [(p, lname, local, tuple(f"{p}_{q}" for q in _POINT_COLUMNS))
                       for p, (lname, local) in point_names(spec).items()]
        link = {"output": course.output}
        self.reactions = [(stem, (link.get(i, i), link.get(j, j))) for stem, (i, j) in REACTIONS]
        self.scratch = np.empty(size)

    def solve(self, phi, K, F):
        """Kinematics and forces at the crank angles ``phi`` [rad] into the column rows
        ``K`` and ``F`` (dicts column → array of ``len(phi)``): the chain solved and its
        kinetostatics run (:mod:`linkage.chain`), the chain's quantities written under the
        course's names (:mod:`linkage.course`)."""
        spec, mech, course = self.spec, self.mech, self.course
        res = ch.solve(self.chain, phi, spec.omega, spec.epsilon, check=False)
        links = res.links
        d = res.solutions[0]          # the dyad, as the four-bar's own kinematics names it
        kin = {"crank": links["crank"], "A": res.joints["A"], "dyad": d, "links": links}
        np.multiply(phi, _DEG, out=K["phi_deg"])
        np.multiply(links["coupler"].theta, _DEG, out=K["theta3_deg"])
        K["omega3_rad_s"][:] = links["coupler"].omega
        K["eps3_rad_s2"][:] = links["coupler"].eps
        c, rate, acc = course.output_columns
        coord, r, a = output_motion(res, course.output)
        np.multiply(coord, course.coordinate_scale, out=K[c])
        K[rate][:] = r
        K[acc][:] = a
        for pname, lname, local, cols in self.points:
            P = res.joints["B"] if pname == "B" else links[lname].point(local)
            for col, value in zip(cols, (P.z.x, P.z.y, P.v.x, P.v.y, P.a.x, P.a.y)):
                K[col][:] = value
        np.multiply(mech.transmission_angle(kin), _DEG, out=K["mu_deg"])

        forces, moments, res_load = external_loads(spec, mech, kin, self.cycle)
        cf = ch.kinetostatics(res, forces, moments, spec.gravity)
        F["phi_deg"][:] = K["phi_deg"]
        for stem, pair in self.reactions:
            v = cf.R(*pair)
            F[f"{stem}_x_N"][:] = v.x
            F[f"{stem}_y_N"][:] = v.y
        F["M_drive_Nm"][:] = cf.M_drive
        r23 = cf.reactions[("crank", "coupler")]
        F["R23_n_N"][:] = r23.n
        F["R23_t_N"][:] = r23.t
        r14 = cf.reactions[("frame", course.output)]
        for col, attr in course.frame_pair:
            F[col][:] = getattr(r14, attr)
        F[course.resistance_column][:] = res_load
        if self.course_tables:
            fill_derived(spec, K, F, self.scratch[:len(phi)])

    def fill(self, phi, kblock, fblock):
        """Solve at ``phi`` [rad] chunk by chunk (:data:`CHUNK`) into the rows of
        ``kblock`` (kinematics columns × positions) and ``fblock`` (force columns ×
        positions)."""
        n = len(phi)
        with np.errstate(divide="ignore", invalid="ignore"):
            for a in range(0, n, CHUNK):
                b = min(n, a + CHUNK)
                self.solve(phi[a:b], dict(zip(self.kcols, kblock[:, a:b])),
                           dict(zip(self.fcols, fblock[:, a:b])))


def solve_columns(spec, phi, mech=None, ext=None, *, course_tables=True):
    """Kinematics and forces at crank angles ``phi`` [rad] as column arrays.

    Parameters
    ----------
    spec : MechanismSpec
    phi : array_like
        Absolute crank angles, ccw from +x. [rad]
    mech : CrankRocker or CrankSlider, optional
        Built from the spec when not given.
    ext : Extremes, optional
        The extreme positions, needed by a resistance limited to a stroke.
    course_tables : bool, default True
        Also the course tables' columns (:mod:`linkage.derived`).

    Returns
    -------
    kinematics, forces : dict of str → ndarray
        The columns of :func:`kinematics_columns` and :func:`force_columns` (without
        ``position``).
    """
    spec = load_spec(spec)
    mech = mech or build_mechanism(spec)
    kcols, fcols, kblock, fblock = _blocks(spec, np.asarray(phi, dtype=float), mech, ext,
                                           course_tables)
    return dict(zip(kcols, kblock)), dict(zip(fcols, fblock))


def _blocks(spec, phi, mech, ext, course_tables):
    """The group routines at crank angles ``phi`` [rad], chunk by chunk, into two
    preallocated column blocks; returns the kinematics and force column names (without
    ``position``) and the blocks (columns × positions)."""
    n = len(phi)
    t = _Tables(spec, mech, ext, course_tables, max(1, min(n, CHUNK)))
    kblock = g.column_block(len(t.kcols), n)
    fblock = g.column_block(len(t.fcols), n)
    t.fill(phi, kblock, fblock)
    return t.kcols, t.fcols, kblock, fblock


def plan_angles(ext, rotation_sign, n):
    """Crank angles [rad] of the plan of ``n`` equal positions: position 1 at the start of
    the working stroke, position k (k−1)·360°/n further in the direction of rotation."""
    k = np.arange(n)
    return np.mod(ext.phi_start + rotation_sign * k * (2 * math.pi / n), 2 * math.pi)


_POINT_COLUMNS = ("x_m", "y_m", "vx_m_s", "vy_m_s", "ax_m_s2", "ay_m_s2")


@dataclass
class AnalysisSummary:
    """Geometry of the cycle of an analysed mechanism.

    Attributes
    ----------
    kind, name : str
        ``"crank-rocker"`` or ``"crank-slider"``; the spec's name.
    grashof : GrashofType or SliderCrankType
        Grashof type (compares equal to its text, e.g. ``"crank-rocker"``,
        ``"change-point"``; a crank-slider: ``"rotatable"``).
    rotation : str
        ``"ccw"``, ``"cw"`` or ``"none (statics)"``.
    mu_min_deg, mu_min_phi_deg : float
        Minimum transmission angle over a full turn (closed form, :mod:`linkage.fourbar`)
        and the absolute crank angle where it occurs, in [0°, 360°). [deg]
    singular_phi_deg : list of float
        Singular crank angles of a change-point mechanism (empty otherwise). [deg]
    phi_working_start_deg, phi_working_end_deg : float or None
        Crank angles of the extreme positions where the working stroke starts and ends;
        None (like every field below) in statics or for an output that turns fully. [deg]
    working_crank_angle_deg, idle_crank_angle_deg : float or None
        Crank rotation in the working and in the idle stroke. [deg]
    time_ratio : float or None
        Time-ratio coefficient K = φwork/φidle. [-]
    theta4_working_start_deg, theta4_working_end_deg, swing_deg : float or None
        Crank-rocker: rocker angle at the two extremes, and the swing. [deg]
    s4_working_start_m, s4_working_end_m, stroke_m : float or None
        Crank-slider: slider position at the two extremes, and the stroke. [m]
    """

    kind: str
    name: str
    grashof: GrashofType | SliderCrankType
    rotation: str
    mu_min_deg: float
    mu_min_phi_deg: float
    singular_phi_deg: list = field(default_factory=list)
    phi_working_start_deg: float | None = None
    phi_working_end_deg: float | None = None
    working_crank_angle_deg: float | None = None
    idle_crank_angle_deg: float | None = None
    time_ratio: float | None = None
    theta4_working_start_deg: float | None = None
    theta4_working_end_deg: float | None = None
    swing_deg: float | None = None
    s4_working_start_m: float | None = None
    s4_working_end_m: float | None = None
    stroke_m: float | None = None

    @property
    def has_extremes(self) -> bool:
        """True when the output link has extreme positions (a rocking output, ω ≠ 0)."""
        return self.phi_working_start_deg is not None


@dataclass
class AnalysisResult:
    """Result of :func:`analyze`.

    Attributes
    ----------
    spec : MechanismSpec
    kinematics, forces : pandas.DataFrame
        One row per position (see the README for every column).
    extremes : pandas.DataFrame or None
        The two extreme positions of the output link (``label`` "working start" and
        "working end"), kinematics and force columns.  None in statics or for a double
        crank.
    summary : AnalysisSummary
        Geometry of the cycle.
    warnings : list of str
        For example the singular positions of a change-point mechanism.
    """

    spec: MechanismSpec
    kinematics: pd.DataFrame
    forces: pd.DataFrame
    extremes: pd.DataFrame | None
    summary: AnalysisSummary
    warnings: list[str] = field(default_factory=list)


def _table(spec, phi, mech, ext, positions, course_tables=True):
    """The kinematics and force DataFrames at crank angles ``phi`` [rad]: the group
    routines run chunk by chunk into two preallocated column blocks, which become the
    frames' storage without a copy (one float block per frame, plus the ``position``
    column, one Int64 array that both frames share copy-on-write)."""
    import pandas as pd

    n = len(phi)
    kcols, fcols, kblock, fblock = _blocks(spec, phi, mech, ext, course_tables)
    if positions is None:  # all missing (pd.array([None] * n) is slow for large n)
        pos = pd.arrays.IntegerArray(np.zeros(n, np.int64), np.ones(n, bool))
    else:
        pos = pd.array(positions, dtype="Int64")
    kin = pd.DataFrame(kblock.T, columns=kcols, copy=False)
    frc = pd.DataFrame(fblock.T, columns=fcols, copy=False)
    # a Series on the frames' own index is inserted by reference (copy-on-write), an
    # array would be copied
    pos = pd.Series(pos, index=kin.index, copy=False)
    kin.insert(0, "position", pos)
    frc.insert(0, "position", pos)
    return kin, frc


def _summary(spec, mech, ext):
    """Cycle geometry: Grashof type, extremes, swing/stroke, K, μmin over a full turn."""
    mu_min, mu_at = mech.min_transmission_angle()
    rotation = "ccw" if spec.omega > 0 else "cw" if spec.omega < 0 else "none (statics)"
    s = AnalysisSummary(spec.kind, spec.name, mech.grashof(), rotation, mu_min, mu_at,
                        [math.degrees(a) for a in mech.singular_angles()])
    if ext is not None:
        ek = mech.kinematics(np.array([ext.phi_start, ext.phi_end]), spec.omega, 0.0)
        c = mech.output_coordinate(ek)
        s.phi_working_start_deg = math.degrees(ext.phi_start)
        s.phi_working_end_deg = math.degrees(ext.phi_end)
        s.working_crank_angle_deg = math.degrees(ext.working_crank_angle)
        s.idle_crank_angle_deg = math.degrees(ext.idle_crank_angle)
        s.time_ratio = ext.time_ratio
        course = course_of(spec)
        if course.angular:           # a rocker's angles and its swing, wrapped
            values = (math.degrees(c[0]), math.degrees(c[1]),
                      abs(math.degrees(np.angle(np.exp(1j * (c[1] - c[0]))))))
        else:                        # a slider's positions and its stroke
            values = (float(c[0]), float(c[1]), abs(float(c[1] - c[0])))
        for name, value in zip(course.summary_fields, values):
            setattr(s, name, value)
    return s


def analyze(spec, crank_angles_deg=None, *, course_tables=True) -> AnalysisResult:
    """Kinematics and kinetostatics of a crank-rocker or crank-slider.

    Parameters
    ----------
    spec : MechanismSpec, dict, str or Path
        A loaded spec, or anything :func:`linkage.load_spec` accepts.
    crank_angles_deg : array_like, optional
        Absolute crank angles (ccw from +x) [deg]; overrides the spec's ``[analysis]``.
        One row each, in the order given.
    course_tables : bool, default True
        Also report the course tables' quantities (:mod:`linkage.derived`): speeds and
        accelerations of the points (``P_v_m_s``, ``P_a_m_s2``), the relative motion of B
        (``v_BA_m_s``, ``a_BA_n_m_s2``, ...), weights and inertia loads (``Gi_N``,
        ``Fui_x_N``, ``Fui_N``, ``Mui_Nm``) and reaction magnitudes (``R12_N``, ...).
        False leaves them out (large sweeps: about 40 % fewer columns to fill).
        A chain: False leaves out the magnitudes ``v_P_m_s``, ``a_P_m_s2``,
        ``acor_…_m_s2`` and ``R_i_j_N`` (:func:`linkage.chain_analysis.analyze_chain`).

    Returns
    -------
    AnalysisResult

    Raises
    ------
    SpecError
        Bad spec.
    AssemblyError
        The mechanism cannot be assembled or its crank cannot turn fully.

    Notes
    -----
    With ``positions = N`` the rows are the plan of positions: position 1 at the extreme
    position where the working stroke starts, position k (k−1)·360°/N further in the
    direction of crank rotation.  A change-point mechanism is analysed too; its singular
    crank angles are listed in ``warnings`` (and raised as
    :class:`SingularPositionWarning`); values exactly there are not finite.
    """
    spec = load_spec(spec)
    if spec.kind == "chain":        # any linkage of class II groups (linkage.chain_analysis)
        from .chain_analysis import analyze_chain

        return analyze_chain(spec, crank_angles_deg, course_tables=course_tables)
    mech = build_mechanism(spec)
    mech.check_rotatable()
    rot = 1 if spec.omega > 0 else -1
    ext = None                 # statics (ω = 0): no rotation, hence no strokes
    if spec.omega != 0:
        default = course_of(spec).default_working_stroke
        with np.errstate(divide="ignore", invalid="ignore"):  # a change point at an extreme
            ext = mech.extremes(rot, spec.working_stroke or default)
    if ext is None and (spec.positions is not None and crank_angles_deg is None
                        and spec.crank_angles_deg is None):
        raise SpecError([Problem("analysis.positions",
                                 Text("errors.linkage.analysis.no_extremes"))])
    positions = None
    if crank_angles_deg is not None:
        phi = angles_argument(crank_angles_deg, "crank_angles_deg", copy=False) * _RAD
    elif spec.crank_angles_deg is not None:
        phi = np.radians(np.asarray(spec.crank_angles_deg, dtype=float))
    else:
        phi = plan_angles(ext, rot, spec.positions)
        positions = np.arange(1, spec.positions + 1)
    ext_loads = ext if spec.working_stroke is not None else None
    kin, frc = _table(spec, phi, mech, ext_loads, positions, course_tables)
    ext_df = None
    if ext is not None:
        ext_df = _extremes_table(spec, mech, ext, ext_loads, course_tables)
    with np.errstate(divide="ignore", invalid="ignore"):
        summary = _summary(spec, mech, ext)
    msgs = []
    sing = mech.singular_angles()
    if sing:
        where = ", ".join(f"{math.degrees(a):.6g}°" for a in sing)
        msgs.append(f"change-point mechanism: singular position(s) at crank angle {where} "
                    "(links collinear; the output's motion is indeterminate there)")
        hit = [a for a in sing if np.any(_angle_apart(phi, a) < SAME_ANGLE_RAD)]
        if hit:
            msgs.append("requested crank angles include a singular position; its "
                        "velocities, accelerations and forces are not finite")
            # rounding can leave finite garbage there (e.g. a slider's rod exactly
            # perpendicular to the guide): report them as NaN, keep the positions
            near = np.zeros(len(phi), bool)
            for a in hit:
                near |= _angle_apart(phi, a) < SAME_ANGLE_RAD
            rates = [c for c in ("omega3_rad_s", "eps3_rad_s2", "omega4_rad_s",
                                 "eps4_rad_s2", "v4_m_s", "a4_m_s2") if c in kin.columns]
            rates += [f"{p}_{q}" for p, (ln, _) in point_names(spec).items() if ln != "crank"
                      for q in ("vx_m_s", "vy_m_s", "ax_m_s2", "ay_m_s2", "v_m_s", "a_m_s2")]
            rates += [c for c in derived_kinematics_columns(spec) if c.startswith(("v_B", "a_B"))]
            rates = [c for c in rates if c in kin.columns]
            kin.loc[near, rates] = np.nan
            fcols = [c for c in frc.columns if c not in ("position", "phi_deg")]
            frc.loc[near, fcols] = np.nan
        for m in msgs:
            warnings.warn(m, SingularPositionWarning, stacklevel=2)
    return AnalysisResult(spec, kin, frc, ext_df, summary, msgs)


def _angle_apart(phi, a):
    """|φ − a| wrapped to [0, π]. [rad]"""
    return np.abs((phi - a + math.pi) % (2.0 * math.pi) - math.pi)


def _extremes_table(spec, mech, ext, ext_loads, course_tables):
    """One table for the two extreme positions: label, kinematics, then forces (without
    ``phi_deg`` a second time)."""
    import pandas as pd

    kcols, fcols, kblock, fblock = _blocks(spec, np.array([ext.phi_start, ext.phi_end]), mech,
                                           ext_loads, course_tables)
    # the force columns start with phi_deg, which the kinematics columns have already
    df = pd.DataFrame(np.vstack([kblock, fblock[1:]]).T, columns=kcols + fcols[1:], copy=False)
    df.insert(0, "label", ["working start", "working end"])
    return df


def full_turn(spec, step_deg=1.0):
    """Analysis over a full turn at ``step_deg`` from 0° (for plots), singular positions
    of a change-point mechanism left out (set to NaN)."""
    spec = load_spec(spec)
    step_deg = step_argument(step_deg, "step_deg", 30.0, rows_span=360.0)
    phi = np.arange(0.0, 360.0 + 0.5 * step_deg, step_deg)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularPositionWarning)
        res = analyze(spec, crank_angles_deg=phi)
    if spec.kind == "chain":
        return res
    sing = res.summary.singular_phi_deg
    if sing:
        near = np.zeros(len(phi), bool)
        for a in sing:   # the grid rows within one step (1 % slack for the grid's rounding)
            near |= np.abs((phi - a + 180.0) % 360.0 - 180.0) <= step_deg * 1.01
        for df in (res.kinematics, res.forces):
            cols = [c for c in df.columns if c not in ("position", "phi_deg")]
            df.loc[near, cols] = np.nan
    return res
