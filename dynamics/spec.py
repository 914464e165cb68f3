"""Specs of ``crankdyn dynamics``: a machine given by its reduced quantities, or a linkage
spec, each with a ``[dynamics]`` section (see the README for every key).

    [dynamics]
    driving = "constant"          # "constant" (steady), "table" (phi_deg + M_Nm) or "motor"
    # phi_deg = [...]; M_Nm = [...]            # driving = "table": piecewise linear, periodic
    # motor_start_torque_Nm = 900; motor_sync_speed_rad_s = 157   # "motor": M0 (1 − ω/ω0)
    delta = 0.05                  # required δ → the flywheel; or
    # flywheel_kgm2 = 1.2         # a given flywheel → the motion it gives
    # omega_mean_rad_s = 10.5     # default: the spec's crank speed
    # steps = 720                 # grid intervals over the period

    [machine]                     # instead of a mechanism
    name = "flywheel-example"
    J_red_kgm2 = 0.22             # and/or elements with constant speed ratios:
    # [[machine.element]]         # J_kgm2 + speed_ratio (ω_k/ω), m_kg + velocity_ratio_m
    # J_kgm2 = 2.5                # (v/ω [m]); J_red = J_red_kgm2 + Σ J ratio² + Σ m ratio²
    # speed_ratio = 0.25
    omega_mean_rad_s = 157.08
    period_deg = 360
    [[machine.moment]]            # role "drive" or "resist"; piecewise linear over phi_deg,
    role = "resist"               # a repeated angle is a step; periodic over period_deg
    phi_deg = [0, 120, 120, 360]
    M_Nm = [600, 600, 200, 200]
"""
from __future__ import annotations

from dataclasses import dataclass, replace

from crankbase.errors import Text
from crankbase.schema import SpecReader

from ._base import MotionError, Problem, SpecError, read_toml
from .schema import DYNAMICS, ELEMENT, MACHINE, MOMENT

__all__ = ["DynamicsSettings", "DynamicsJob", "load_dynamics_spec"]

_ELEMENT_KEYS = ELEMENT.names


@dataclass(frozen=True)
class DynamicsSettings:
    """The ``[dynamics]`` section, validated."""

    driving: str = "constant"
    table_phi_deg: tuple | None = None
    table_M_Nm: tuple | None = None
    motor_M0: float | None = None
    motor_omega0: float | None = None
    delta: float | None = None
    flywheel: float | None = None
    omega_mean: float | None = None
    steps: int | None = None


@dataclass
class DynamicsJob:
    """What ``crankdyn dynamics`` runs: the reduced model and the settings."""

    kind: str            # "machine" or "linkage"
    model: object        # ReducedModel (without the table drive)
    settings: DynamicsSettings
    source: str | None
    #: What the run assumed (``"delta_from_flywheel"``, ``"no_flywheel"``: an engine spec
    #: without a [dynamics] delta or flywheel), said in the summary.
    notes: tuple = ()


def _settings(ck, dyn, period_deg, engine=False):
    """The ``[dynamics]`` table ``dyn`` (its unknown keys already reported by
    :meth:`SpecReader.sub`)."""
    if not engine and "J_engine_extra_kgm2" in dyn:
        ck.add("dynamics.J_engine_extra_kgm2", Text("errors.dynamics.spec.only_for_engine"))

    def get(key, **kw):
        return ck.get(dyn, DYNAMICS, key, **kw)

    driving = get("driving")
    phi = M = M0 = w0 = None
    if driving == "table":
        phi = get("phi_deg", required=True)
        M = get("M_Nm", required=True)
    else:
        for k in ("phi_deg", "M_Nm"):
            if k in dyn:
                ck.add(f"dynamics.{k}", Text("errors.dynamics.spec.only_with_driving"))
    if driving == "motor":
        M0 = get("motor_start_torque_Nm", required=True)
        w0 = get("motor_sync_speed_rad_s", required=True)
        if "omega_mean_rad_s" in dyn:
            ck.add("dynamics.omega_mean_rad_s",
                   Text("errors.dynamics.spec.motor_s_characteristic"))
    else:
        for k in ("motor_start_torque_Nm", "motor_sync_speed_rad_s"):
            if k in dyn:
                ck.add(f"dynamics.{k}", Text("errors.dynamics.spec.only_with_driving_2"))
    delta = get("delta")
    fly = get("flywheel_kgm2")
    if "delta" in dyn and "flywheel_kgm2" in dyn:
        ck.add("dynamics", Text("errors.dynamics.spec.give_either_delta"))
    wm = get("omega_mean_rad_s")
    steps = get("steps")
    return DynamicsSettings(driving, tuple(phi) if phi else None, tuple(M) if M else None,
                            M0, w0, delta, fly, wm, steps)


def load_dynamics_spec(path_or_dict) -> DynamicsJob:
    """Read a dynamics spec: ``[machine]`` + ``[dynamics]``, or a linkage spec + ``[dynamics]``.

    Raises
    ------
    SpecError
        Every problem at once, each with its key path.
    """
    from .reduced import PiecewiseLinear, linkage_model, machine_model

    data, base_dir = read_toml(path_or_dict)
    src = None if isinstance(path_or_dict, dict) else str(path_or_dict)
    ck = SpecReader()
    notes = ()
    dyn = ck.sub(data, DYNAMICS)
    if "engine" in data:
        import engine

        from .reduced import engine_model

        rest = {k: v for k, v in data.items() if k != "dynamics"}
        settings = _settings(ck, dyn, 720.0, engine=True)
        J_extra = ck.get(dyn, DYNAMICS, "J_engine_extra_kgm2")
        problems = list(ck.problems)
        try:
            estudy = engine.load(rest, base_dir=base_dir)
        except SpecError as exc:
            raise SpecError(problems + exc.problems) from None
        if problems:
            raise SpecError(problems)
        espec = estudy.spec
        fw_delta = getattr(estudy.train, "delta", None)
        if settings.delta is None and settings.flywheel is None:   # #23: [flywheel] delta
            notes = ("delta_from_flywheel",) if fw_delta is not None else ("no_flywheel",)
            if fw_delta is not None and fw_delta < 1:
                settings = replace(settings, delta=float(fw_delta))
        if settings.driving != "constant":
            raise SpecError(Problem("dynamics.driving",
                                    Text("errors.dynamics.spec.engine_drives_itself",
                                         {"driving": settings.driving})))
        model = engine_model(espec, steps=settings.steps or 1440, J_extra_kgm2=J_extra,
                             train=estudy.train)
        if settings.omega_mean is not None:
            model.omega_nominal = settings.omega_mean
        kind = "engine"
        period = 720.0 if espec.strokes == 4 else 360.0
    elif "machine" in data:
        from .schema import SCHEMA

        ck.top(data, SCHEMA)
        mach = ck.sub(data, MACHINE)
        name = ck.get(mach, MACHINE, "name")
        elements = ck.rows(mach, ELEMENT)
        J = ck.get(mach, MACHINE, "J_red_kgm2", required=not elements)
        rot, trans = ([], []), ([], [])
        for path, el in elements:
            if "J_kgm2" in el or "speed_ratio" in el:
                Jk = ck.get(el, ELEMENT, "J_kgm2", path=path, required=True)
                rk = ck.get(el, ELEMENT, "speed_ratio", path=path, required=True)
                if Jk is not None and rk is not None:
                    rot[0].append(Jk)
                    rot[1].append(rk)
            if "m_kg" in el or "velocity_ratio_m" in el:
                mk = ck.get(el, ELEMENT, "m_kg", path=path, required=True)
                vk = ck.get(el, ELEMENT, "velocity_ratio_m", path=path, required=True)
                if mk is not None and vk is not None:
                    trans[0].append(mk)
                    trans[1].append(vk)
            if not any(k in el for k in _ELEMENT_KEYS):
                ck.add(path, Text("errors.dynamics.spec.give_j_kgm"))
        if elements and J is not None:
            from .reduced import chain_reduce

            try:
                J = J + chain_reduce(rot[0], rot[1], trans[0], trans[1]).J_red_kgm2
            except SpecError as exc:
                ck.problems.extend(Problem("machine.element", p.text or p.message)
                                   for p in exc.problems)
        wm = ck.get(mach, MACHINE, "omega_mean_rad_s")
        period = ck.get(mach, MACHINE, "period_deg")
        parsed = []
        for path, mt in ck.rows(mach, MOMENT):
            role = ck.get(mt, MOMENT, "role", path=path)
            phi = ck.get(mt, MOMENT, "phi_deg", path=path)
            M = ck.get(mt, MOMENT, "M_Nm", path=path)
            if role and phi is not None and M is not None and period:
                try:
                    parsed.append((role, PiecewiseLinear(phi, M, period, key=path)))
                except SpecError as exc:
                    ck.problems.extend(exc.problems)
        settings = _settings(ck, dyn, period)
        ck.raise_if_any()
        if settings.omega_mean is not None:
            wm = settings.omega_mean
        model = machine_model(J, parsed, period, name=name, steps=settings.steps or 1440,
                              omega_nominal=wm)
        kind = "machine"
    elif "mechanism" in data:
        from linkage import load_spec

        rest = {k: v for k, v in data.items() if k != "dynamics"}
        settings = _settings(ck, dyn, 360.0)
        problems = list(ck.problems)
        try:
            lspec = load_spec(rest)
        except SpecError as exc:
            raise SpecError(problems + exc.problems) from None
        if problems:
            raise SpecError(problems)
        if lspec.omega == 0:
            raise SpecError(Problem("mechanism.omega_rad_s",
                                    Text("errors.dynamics.spec.machine_dynamics_needs")))
        model = linkage_model(lspec, steps=settings.steps or 720)
        if settings.omega_mean is not None:
            model.omega_nominal = settings.omega_mean
        kind = "linkage"
        period = 360.0
    else:
        raise SpecError(Problem("", Text("errors.dynamics.spec.neither_machine_nor")))
    if settings.driving == "table":
        try:
            pl = PiecewiseLinear(settings.table_phi_deg, settings.table_M_Nm, period,
                                 key="dynamics")
        except SpecError:
            raise
        # the table's angles are the angle turned from the start of the cycle
        model = model.with_drive(model.M_drive_Nm + pl(model.phi),
                                 model.W_drive_J + pl.integral(0.0, model.phi))
    return DynamicsJob(kind, model, settings, src, notes)


def run_job(job: DynamicsJob):
    """Compute everything a dynamics job asks: the motion (and the flywheel), for a motor
    the start-up, for a linkage the forces under the true motion.

    Returns
    -------
    dynamics.study.DynamicsReport
        ``motion`` (MotionResult), ``flywheel`` (FlywheelResult or None), ``startup``
        (StartupResult or None), ``forces`` (DataFrame or None), ``model``, the name,
        kind and driving; read as a mapping too (``report["motion"]``), as before.
        Written by :func:`dynamics.study.write_report`.
    """
    from .motion import (Motor, engine_true_motion_forces, motor_startup,
                         motor_steady_motion, size_flywheel, steady_motion,
                         true_motion_forces)

    s, model = job.settings, job.model
    fly = startup = None
    if s.driving == "motor":
        motor = Motor(s.motor_M0, s.motor_omega0)
        JF = s.flywheel or 0.0
        if s.delta is not None:
            fly = _motor_flywheel(model, motor, s.delta)
            JF = fly.J_exact
            motion = fly.motion
        else:
            motion = motor_steady_motion(model, motor, J_flywheel=JF)
        startup = motor_startup(model, motor, J_flywheel=JF, steady=motion)
    else:
        driving = "constant" if s.driving == "constant" else "given"
        if model.omega_nominal is None:
            raise SpecError(Problem("dynamics.omega_mean_rad_s",
                                    Text("errors.dynamics.spec.missing_give_mean")))
        if s.delta is not None:
            fly = size_flywheel(model, s.delta, driving=driving)
            motion = fly.motion
        else:
            motion = steady_motion(model, J_flywheel=s.flywheel or 0.0, driving=driving)
    forces = None
    if job.kind == "linkage":
        forces = true_motion_forces(model, motion)
    elif job.kind == "engine":
        forces = engine_true_motion_forces(model, motion)
    from .results import DynamicsReport

    return DynamicsReport(name=model.name, kind=job.kind, driving=s.driving, model=model,
                          motion=motion, flywheel=fly, startup=startup, forces=forces,
                          settings=s, source=job.source, notes=tuple(job.notes))


def _motor_flywheel(model, motor, delta):
    """Flywheel for δ under a motor characteristic: the classic estimate (constant driving
    moment, at the motor's steady mean speed; :func:`dynamics.motion.classic_flywheel`),
    exact by brentq on the periodic solution with the motor."""
    from scipy.optimize import brentq

    from dataclasses import replace

    from .motion import classic_flywheel_result, motor_steady_motion

    m0 = motor_steady_motion(model, motor)
    const, _ = model.with_constant_drive()
    fw = classic_flywheel_result(const, delta, m0.omega_mean)
    Jc, J_classic = fw.J_c, fw.J_classic
    if m0.delta <= delta:
        return replace(fw, J_exact=0.0, motion=m0)

    cache = {}

    def motion(JF):
        if JF not in cache:
            cache[JF] = motor_steady_motion(model, motor, J_flywheel=JF)
        return cache[JF]

    def f(JF):
        return motion(JF).delta - delta

    JF = None
    x0 = max(J_classic, 1e-6 * max(Jc, 1e-9))
    try:   # 1/δ is nearly linear in J_F: a secant from the classic estimate, ~4 solves
        from scipy.optimize import newton
        JF = float(newton(lambda J: 1.0 / motion(max(J, 0.0)).delta - 1.0 / delta, x0,
                          x1=1.2 * x0, tol=1e-7 * x0, maxiter=20))
        if not (JF >= 0 and abs(f(JF)) <= 1e-5 * delta):
            JF = None
    except (RuntimeError, ArithmeticError, MotionError):
        JF = None
    if JF is None:         # bracket and bisect
        hi = x0
        while f(hi) > 0:
            hi *= 2.0
        JF = brentq(f, 0.0, hi, xtol=1e-9 * hi, rtol=1e-9)
    return replace(fw, J_exact=float(JF), motion=motion(JF))
