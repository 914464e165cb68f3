"""From a spec to the kinematics and force tables: :func:`analyze`.

The pipeline, vectorised over crank positions and run in cache-sized chunks:

1. build the mechanism (:mod:`linkage.mechanisms`), check that the crank turns fully;
2. kinematics: driver, then the dyad;
3. the loads on every link at every position: external forces and moments, useful
   resistance (by stroke and span), weight ``−m·g·j`` and d'Alembert inertia
   ``−m·a_S``, ``−J_S·ε``;
4. kinetostatics: the dyad, then the driver (balancing moment Mур).

Columns are SI with the unit in the name (``omega3_rad_s``, ``R23_x_N``); angles in
degrees.  ``Rij`` is the force of link i on link j (1 ground, 2 crank, 3 coupler or rod,
4 rocker or slider).
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from . import groups as g
from .errors import SpecError
from .mechanisms import CrankRocker, CrankSlider
from .columns import derived_kinematics_columns, force_columns, kinematics_columns, point_names
from .derived import fill_derived
from .kernel import Kernel, fill_blocks
from .spec import MechanismSpec, load_spec

__all__ = ["build_mechanism", "analyze", "AnalysisResult", "solve_columns",
           "kinematics_columns", "force_columns", "plan_angles", "SingularPositionWarning"]

#: Crank positions per chunk.  Each numpy call costs ~0.4 µs however short its arrays,
#: and the kernel makes ~300 per chunk; past ~16k positions the ~110 arrays of a chunk
#: (128 KB each) no longer stay in cache.  Measured (benchmarks/bench_linkage.py):
#: 4096 → 7.9, 16384 → 9.3, 32768 → 9.2 M positions/s; whole arrays are memory-bound.
CHUNK = 16384


class SingularPositionWarning(UserWarning):
    """A change-point mechanism was analysed at (or its full turn passes) a singular
    position, where the output link's motion is indeterminate."""


def build_mechanism(spec: MechanismSpec):
    """The mechanism object of a spec (geometry only)."""
    if spec.kind == "crank-rocker":
        return CrankRocker(spec.crank, spec.coupler, spec.rocker, spec.ground,
                           spec.ground_angle, spec.assembly)
    return CrankSlider(spec.crank, spec.coupler, spec.ground_angle, spec.offset,
                       spec.assembly)


def _stroke_state(mech, spec, kin, ext):
    """Per position: +1 in the working stroke, −1 in the idle stroke, 0 at rest; and the
    swing (rad) or travel (m) from the start of the current stroke."""
    rate = mech._output_rate(kin)
    coord = mech.output_coordinate(kin)
    if spec.working_stroke is None or ext is None:
        return None, None, rate
    wsign = mech._working_sign(spec.working_stroke)
    scale = abs(spec.omega) * (1.0 if spec.kind == "crank-rocker" else spec.crank)
    moving = np.abs(rate) > 1e-9 * scale
    state = np.where(moving, np.sign(rate * wsign), 0.0)
    # output coordinate at the two extreme positions (start of the working and idle strokes)
    # positions only (ω may be an array over positions: dynamics under the true motion)
    ek = mech.kinematics(np.array([ext.phi_start, ext.phi_end]), 1.0, 0.0)
    c_start = mech.output_coordinate(ek)
    start = np.where(state >= 0, c_start[0], c_start[1])
    if spec.kind == "crank-rocker":
        travel = np.abs(np.angle(np.exp(1j * (coord - start))))
    else:
        travel = np.abs(coord - start)
    return state, travel, rate


def _external_loads(mech, spec, kin, ext):
    """External forces and moments per link (global forces at global points)."""
    forces = {n: [] for n in spec.link_names}
    moments = {n: [] for n in spec.link_names}
    res_value = np.zeros(kin["A"].z.shape)
    state = travel = rate = None
    for ld in spec.loads:
        link = kin["links"][ld.link]
        if ld.kind == "force":
            forces[ld.link].append((ld.force, link.point(ld.at).z))
        elif ld.kind == "moment":
            moments[ld.link].append(ld.moment)
        else:
            if state is None:
                state, travel, rate = _stroke_state(mech, spec, kin, ext)
            if state is None:  # stroke "both", no working stroke given
                scale = abs(spec.omega) * (1.0 if spec.kind == "crank-rocker" else spec.crank)
                state_b = np.where(np.abs(rate) > 1e-9 * scale, 1.0, 0.0)
                active = state_b != 0
            else:
                want = {"working": state > 0, "idle": state < 0, "both": state != 0}
                active = want[ld.stroke].copy()
                if ld.span is not None:
                    active &= travel <= ld.span * (1 + 1e-12)
            value = np.where(active, -np.sign(rate) * ld.resistance, 0.0)
            res_value = res_value + value
            if spec.kind == "crank-rocker":
                moments[ld.link].append(value)
            else:
                forces[ld.link].append((value * mech.u, kin["dyad"].B.z))
    return forces, moments, res_value


def solve_columns(spec: MechanismSpec, phi, mech=None, ext=None, out_kin=None,
                  out_force=None, rows=slice(None)):
    """Kinematics and forces at crank angles ``phi`` [rad], written into column dicts.

    ``out_kin``/``out_force`` map column name → preallocated array; values go to
    ``[rows]``.  Returns the two dicts (allocated here when not given).

    This is the readable reference: the mechanism assembled from the group routines of
    :mod:`linkage.groups` (driver → dyad, then dyad → driver for the forces).
    :func:`analyze` evaluates the same equations with the fused kernel :class:`linkage.kernel.Kernel`
    (about 3× faster); the two agree to a few ulps.
    """
    mech = mech or build_mechanism(spec)
    n = len(phi)
    if out_kin is None:
        out_kin = {c: np.empty(n) for c in kinematics_columns(spec) if c != "position"}
    if out_force is None:
        out_force = {c: np.empty(n) for c in force_columns(spec) if c != "position"}
    kin = mech.kinematics(phi, spec.omega, spec.epsilon)
    d = kin["dyad"]
    K = out_kin
    deg = 180.0 / math.pi
    K["phi_deg"][rows] = phi * deg
    K["theta3_deg"][rows] = np.angle(d.link3.e) * deg
    K["omega3_rad_s"][rows] = d.link3.omega
    K["eps3_rad_s2"][rows] = d.link3.eps
    if spec.kind == "crank-rocker":
        K["theta4_deg"][rows] = np.angle(d.link4.e) * deg
        K["omega4_rad_s"][rows] = d.link4.omega
        K["eps4_rad_s2"][rows] = d.link4.eps
    else:
        K["s4_m"][rows] = d.s
        K["v4_m_s"][rows] = d.v
        K["a4_m_s2"][rows] = d.a
    for pname, (lname, local) in point_names(spec).items():
        P = d.B if pname == "B" else kin["links"][lname].point(local)
        K[f"{pname}_x_m"][rows] = P.z.real
        K[f"{pname}_y_m"][rows] = P.z.imag
        K[f"{pname}_vx_m_s"][rows] = P.v.real
        K[f"{pname}_vy_m_s"][rows] = P.v.imag
        K[f"{pname}_ax_m_s2"][rows] = P.a.real
        K[f"{pname}_ay_m_s2"][rows] = P.a.imag
    K["mu_deg"][rows] = mech.transmission_angle(kin) * deg

    forces, moments, res = _external_loads(mech, spec, kin, ext)
    W = {}
    for lname in spec.link_names:
        ls = spec.links[lname]
        W[lname] = g.link_wrench(kin["links"][lname], ls.mass, ls.inertia, ls.cg,
                                 spec.gravity, forces[lname], moments[lname])
    r, drv = mech.reactions(kin, W)
    F = out_force
    F["phi_deg"][rows] = phi * deg
    F["R12_x_N"][rows] = drv.R12.real
    F["R12_y_N"][rows] = drv.R12.imag
    F["R23_x_N"][rows] = r.RA.real
    F["R23_y_N"][rows] = r.RA.imag
    F["R43_x_N"][rows] = r.RB.real
    F["R43_y_N"][rows] = r.RB.imag
    F["M_drive_Nm"][rows] = drv.M_drive
    F["R23_n_N"][rows] = r.RA_n
    F["R23_t_N"][rows] = r.RA_t
    if spec.kind == "crank-rocker":
        F["R14_x_N"][rows] = r.RC.real
        F["R14_y_N"][rows] = r.RC.imag
        F["R14_n_N"][rows] = r.RC_n
        F["R14_t_N"][rows] = r.RC_t
        F["M_res_Nm"][rows] = res
    else:
        F["R14_x_N"][rows] = r.RG.real
        F["R14_y_N"][rows] = r.RG.imag
        F["N14_N"][rows] = r.RG_n
        F["M14_Nm"][rows] = r.MG
        F["F_res_N"][rows] = res
    if "R12_N" in F:  # the course tables' columns were asked for
        fill_derived(spec, {c: a[rows] for c, a in K.items()},
                     {c: a[rows] for c, a in F.items()})
    return out_kin, out_force


def plan_angles(ext, rotation_sign, n):
    """Crank angles [rad] of the plan of ``n`` equal positions: position 1 at the start of
    the working stroke, position k (k−1)·360°/n further in the direction of rotation."""
    k = np.arange(n)
    return np.mod(ext.phi_start + rotation_sign * k * (2 * math.pi / n), 2 * math.pi)


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
        "working end"), kinematics and force columns.  None for a double crank.
    summary : dict
        Geometry of the cycle: Grashof type, swing or stroke, time-ratio coefficient,
        extreme crank angles, the minimum transmission angle over a full turn and where.
    warnings : list of str
        For example the singular positions of a change-point mechanism.
    """

    spec: MechanismSpec
    kinematics: object
    forces: object
    extremes: object
    summary: dict
    warnings: list = field(default_factory=list)


def _table(spec, phi, mech, ext, positions, course_tables=True):
    """The kinematics and force DataFrames at crank angles ``phi`` [rad]: :class:`Kernel`
    run chunk by chunk into two preallocated column blocks, which become the frames'
    storage without a copy."""
    import pandas as pd

    n = len(phi)
    kcols = [c for c in kinematics_columns(spec, course_tables) if c != "position"]
    fcols = [c for c in force_columns(spec, course_tables) if c != "position"]
    kblock = np.empty((len(kcols), n))
    fblock = np.empty((len(fcols), n))
    fill_blocks(Kernel(spec, mech, ext, max(1, min(n, CHUNK)), course_tables), phi, kblock,
                fblock)
    if positions is None:  # all missing (pd.array([None] * n) is slow for large n)
        pos = pd.arrays.IntegerArray(np.zeros(n, np.int64), np.ones(n, bool))
    else:
        pos = pd.array(positions, dtype="Int64")
    kin = pd.DataFrame(kblock.T, columns=kcols, copy=False)
    frc = pd.DataFrame(fblock.T, columns=fcols, copy=False)
    kin.insert(0, "position", pos)
    frc.insert(0, "position", pos.copy())
    return kin, frc


def _summary(spec, mech, ext):
    """Cycle geometry: Grashof type, extremes, swing/stroke, K, μmin over a full turn."""
    s = {"kind": spec.kind, "name": spec.name,
         "grashof": str(mech.grashof())}
    if ext is not None:
        ek = mech.kinematics(np.array([ext.phi_start, ext.phi_end]), spec.omega, 0.0)
        c = mech.output_coordinate(ek)
        s["phi_working_start_deg"] = math.degrees(ext.phi_start)
        s["phi_working_end_deg"] = math.degrees(ext.phi_end)
        s["working_crank_angle_deg"] = math.degrees(ext.working_crank_angle)
        s["idle_crank_angle_deg"] = math.degrees(ext.idle_crank_angle)
        s["time_ratio"] = ext.time_ratio
        if spec.kind == "crank-rocker":
            s["theta4_working_start_deg"] = math.degrees(c[0])
            s["theta4_working_end_deg"] = math.degrees(c[1])
            s["swing_deg"] = abs(math.degrees(np.angle(np.exp(1j * (c[1] - c[0])))))
        else:
            s["s4_working_start_m"] = float(c[0])
            s["s4_working_end_m"] = float(c[1])
            s["stroke_m"] = abs(float(c[1] - c[0]))
    # minimum transmission angle over a full turn: grid, then refined by golden section
    # on the closed-form μ(φ) (vectorised bracket refinement, no per-angle loop).
    grid = np.linspace(0.0, 2 * math.pi, 3601)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = mech.transmission_angle(mech.kinematics(grid, 1.0, 0.0))
    i = int(np.nanargmin(mu))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    for _ in range(60):
        pts = np.linspace(lo, hi, 5)
        with np.errstate(divide="ignore", invalid="ignore"):
            m5 = mech.transmission_angle(mech.kinematics(pts, 1.0, 0.0))
        j = int(np.nanargmin(m5))
        lo, hi = pts[max(j - 1, 0)], pts[min(j + 1, 4)]
    phi_min = 0.5 * (lo + hi)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu_min = float(mech.transmission_angle(mech.kinematics(np.array([phi_min]), 1.0, 0.0))[0])
    s["mu_min_deg"] = math.degrees(mu_min)
    phi_min_deg = math.degrees(phi_min) % 360.0
    s["mu_min_phi_deg"] = 0.0 if phi_min_deg > 360.0 - 1e-6 else phi_min_deg
    s["rotation"] = "ccw" if spec.omega > 0 else "cw" if spec.omega < 0 else "none (statics)"
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
    mech = build_mechanism(spec)
    mech.check_rotatable()
    rot = 1 if spec.omega > 0 else -1
    ext = None                 # statics (ω = 0): no rotation, hence no strokes
    if spec.omega != 0:
        default = "ccw" if spec.kind == "crank-rocker" else "away"
        with np.errstate(divide="ignore", invalid="ignore"):  # a change point at an extreme
            ext = mech.extremes(rot, spec.working_stroke or default)
    if ext is None and (spec.positions is not None and crank_angles_deg is None
                        and spec.crank_angles_deg is None):
        raise SpecError(["analysis.positions: the output link turns fully (a double crank) "
                         "and has no extreme positions to number from; give "
                         "analysis.crank_angles_deg instead"])
    positions = None
    if crank_angles_deg is not None:
        phi = np.radians(np.atleast_1d(np.asarray(crank_angles_deg, dtype=float)))
        if not np.all(np.isfinite(phi)):
            raise SpecError(["crank_angles_deg: every angle must be finite"])
    elif spec.crank_angles_deg is not None:
        phi = np.radians(np.asarray(spec.crank_angles_deg, dtype=float))
    else:
        phi = plan_angles(ext, rot, spec.positions)
        positions = np.arange(1, spec.positions + 1)
    ext_loads = ext if spec.working_stroke is not None else None
    kin, frc = _table(spec, phi, mech, ext_loads, positions, course_tables)
    ext_df = None
    if ext is not None:
        ek, ef = _table(spec, np.array([ext.phi_start, ext.phi_end]), mech, ext_loads, None,
                        course_tables)
        ek.insert(0, "label", ["working start", "working end"])
        ext_df = _join_extremes(ek, ef)
    with np.errstate(divide="ignore", invalid="ignore"):
        summary = _summary(spec, mech, ext)
    msgs = []
    sing = mech.singular_angles()
    if sing:
        where = ", ".join(f"{math.degrees(a):.6g}°" for a in sing)
        msgs.append(f"change-point mechanism: singular position(s) at crank angle {where} "
                    "(links collinear; the output's motion is indeterminate there)")
        hit = [a for a in sing if np.any(np.abs(np.angle(np.exp(1j * (phi - a)))) < 1e-9)]
        if hit:
            msgs.append("requested crank angles include a singular position; its "
                        "velocities, accelerations and forces are not finite")
            # rounding can leave finite garbage there (e.g. a slider's rod exactly
            # perpendicular to the guide): report them as NaN, keep the positions
            near = np.zeros(len(phi), bool)
            for a in hit:
                near |= np.abs(np.angle(np.exp(1j * (phi - a)))) < 1e-9
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
    summary["singular_phi_deg"] = [math.degrees(a) for a in sing]
    return AnalysisResult(spec, kin, frc, ext_df, summary, msgs)


def _join_extremes(ek, ef):
    """One table for the two extreme positions: label, kinematics, then forces."""
    import pandas as pd

    ef = ef.drop(columns=["position", "phi_deg"])
    return pd.concat([ek.drop(columns="position"), ef], axis=1)


def full_turn(spec, step_deg=1.0):
    """Analysis over a full turn at ``step_deg`` from 0° (for plots), singular positions
    of a change-point mechanism left out (set to NaN)."""
    spec = load_spec(spec)
    phi = np.arange(0.0, 360.0 + 0.5 * step_deg, step_deg)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularPositionWarning)
        res = analyze(spec, crank_angles_deg=phi)
    sing = res.summary.get("singular_phi_deg", [])
    if sing:
        near = np.zeros(len(phi), bool)
        for a in sing:
            near |= np.abs((phi - a + 180.0) % 360.0 - 180.0) <= step_deg * 1.01
        for df in (res.kinematics, res.forces):
            cols = [c for c in df.columns if c not in ("position", "phi_deg")]
            df.loc[near, cols] = np.nan
    return res
