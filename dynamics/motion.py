"""The true motion of a machine over its steady cycle, the flywheel, a motor drive.

Energy form (eq. 11-16 of the seed textbook)::

    ½ J(φ) ω² − ½ J(0) ω0² = ∫0^φ (M_d − M_c) dφ = W(φ)

gives ω(φ) = sqrt((J(0) ω0² + 2 W(φ)) / J(φ)) on the whole grid at once; the cycle is steady
when W(period) = 0.  ω0 is found (``scipy.optimize.brentq``) so that the mean speed
ω_m = (ω_max + ω_min)/2 (the textbooks' definition, Example 11-3) is the one asked.
Then ε = dω/dt = (M_d − M_c − ½ ω² dJ/dφ)/J (the differential form, eq. 11-17, evaluated
pointwise, exact for the solution above), δ = (ω_max − ω_min)/ω_m, and t(φ) = ∫dφ/ω
(trapezoids).

A motor characteristic M_d(ω) = M0 (1 − ω/ω0) (linear asynchronous motor) makes the
equation depend on ω; its periodic steady state is found by shooting on the differential
form in the angle, dω/dφ = (M_d(ω) − M_c − ½ ω² J')/(J ω), with ``scipy.integrate.solve_ivp``
(LSODA: it switches to a stiff method by itself when the motor's slope makes the equation
stiff) and ``brentq`` on ω(0) = ω(period); the start-up from rest integrates the same
equation in time (φ and ω as states, since ω = 0 at the start).

The flywheel for a required δ: the classic estimate J_F = ΔW_max/(δ ω_m²) − J_c with
ΔW_max the swing of W(φ) and J_c the cycle mean of J_red (it treats the machine as a
constant inertia), and the exact J_F that gives δ with the variable J_red (``brentq``
on δ(J_F) of the energy-form solution).

References
----------
.. [1] Seed 001: textbook chapter 11 "机械系统的动力分析与设计", §11.3.2 (eqs. 11-16,
   11-17), Example 11-3, §11.4 (flywheel).
.. [2] Khurmi R. S., Gupta J. K. Theory of Machines. S. Chand, 14th ed., 2005, ch. 16
   "Turning moment diagrams and flywheel", eqs. 16.4–16.8.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from engine.train import FlywheelResult, flywheel

from crankbase.errors import Text
from ._base import MotionError, Problem, SpecError

__all__ = ["MotionResult", "steady_motion", "FlywheelResult", "size_flywheel",
           "motor_steady_motion", "motor_startup", "StartupResult", "check_delta",
           "linkage_forces", "true_motion_forces", "engine_true_motion_forces",
           "classic_flywheel", "classic_flywheel_result"]


def _cumtrapz(y, x):
    return np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x))])


@dataclass
class MotionResult:
    """The steady periodic motion of a reduced model.

    Attributes
    ----------
    table : pandas.DataFrame
        One row per grid point: ``phi_deg`` (absolute crank angle for a linkage),
        ``phi_rad`` (angle turned from the start of the cycle), ``J_red_kgm2`` (with the
        flywheel), ``dJ_red_dphi_kgm2``, ``M_drive_Nm``, ``M_resist_Nm``, ``W_J`` (work
        of M_d − M_c from the start), ``E_J`` (kinetic energy ½Jω²), ``omega_rad_s``,
        ``eps_rad_s2``, ``t_s``.
    omega_max, omega_min, omega_mean : float
        [rad/s]; ``omega_mean`` = (max + min)/2.
    omega_time_mean : float
        period / cycle time. [rad/s]
    delta : float
        (ω_max − ω_min)/ω_m. [-]
    dW_max : float
        Swing of W(φ) over the cycle. [J]
    J_flywheel : float
        The flywheel added to the model's J. [kg·m²]
    M_drive_const : float or None
        The constant driving moment that makes the cycle steady (``driving="constant"``);
        negative for a machine given by its driving moments only, which gets the constant
        resisting moment −M_drive_const instead (see ``ReducedModel.with_constant_drive``);
        ``constant_role`` says which ("drive" or "resist").
    cycle_time : float
        [s]
    phi_omega_max_deg, phi_omega_min_deg : float
        Where ω is largest and smallest (same angle scale as ``phi_deg``).
    """

    name: str
    table: object
    omega_max: float
    omega_min: float
    omega_mean: float
    omega_time_mean: float
    delta: float
    dW_max: float
    J_flywheel: float
    M_drive_const: float | None
    cycle_time: float
    phi_omega_max_deg: float
    phi_omega_min_deg: float
    driving: str = "constant"
    constant_role: str | None = None
    extra: dict = field(default_factory=dict)


def _add_extra_columns(table, model):
    """Per-position arrays the model carries besides the standard ones (e.g. the parts of
    a linkage's resisting moment) as more columns."""
    for k, v in model.extra.items():
        if isinstance(v, np.ndarray) and v.shape == model.phi.shape:
            table[k] = v


def check_delta(delta, key="dynamics.delta"):
    if delta is None or not (0.0 < delta < 1.0):
        raise SpecError(Problem(key, Text("errors.dynamics.motion.coefficient_speed_fluctuation",
                                          {"delta": delta})))


def _net_work_check(model, what):
    W = model.W_net_J
    scale = max(np.max(np.abs(model.W_drive_J)), np.max(np.abs(model.W_resist_J)), 1e-12)
    if abs(W[-1]) > 1e-6 * scale:
        kind = Text("errors.dynamics.motion.short" if W[-1] < 0
                    else "errors.dynamics.motion.exceeds")
        raise MotionError(Problem(
            what, Text("errors.dynamics.motion.driving_work_per",
                       {"value": model.W_drive_J[-1], "kind": kind, "value2": model.W_resist_J[-1],
                        "value3": W[-1]})))


def _omega_of(model, J, W, w0):
    num = J[0] * w0 * w0 + 2.0 * W
    return np.sqrt(np.maximum(num, 0.0) / J), num


def steady_motion(model, omega_mean=None, *, J_flywheel=0.0, driving="constant"):
    """Steady periodic motion of a reduced model by the energy equation.

    Parameters
    ----------
    model : ReducedModel
    omega_mean : float, optional
        Mean speed ω_m = (ω_max + ω_min)/2 [rad/s] (> 0); default the model's nominal one.
    J_flywheel : float
        Flywheel added on the main shaft (≥ 0). [kg·m²]
    driving : {"constant", "given"}
        "constant": add the constant driving moment that makes the cycle steady;
        "given": the model's driving moment as is (its cycle work must balance).

    Returns
    -------
    MotionResult

    Raises
    ------
    SpecError
        ω_m ≤ 0, J ≤ 0 somewhere, J_flywheel < 0.
    MotionError
        The cycle's net work is not zero (``driving="given"``); or the kinetic-energy swing
        is so large against ½Jω_m² that no motion with this ω_m keeps ω > 0 (the machine
        would stop: a flywheel or a higher speed is needed).
    """
    import pandas as pd
    from scipy.optimize import brentq

    wm = model.omega_nominal if omega_mean is None else omega_mean
    probs = []
    if wm is None or not wm > 0:
        probs.append(Problem("dynamics.omega_mean_rad_s",
                             Text("errors.dynamics.motion.mean_speed", {"wm": wm})))
    if not J_flywheel >= 0:
        probs.append(Problem("dynamics.flywheel_kgm2", Text("errors.dynamics.motion.message",
                                                            {"J_flywheel": J_flywheel})))
    if np.any(model.J_kgm2 + J_flywheel <= 0):
        probs.append(Problem("J_red_kgm2", Text("errors.dynamics.motion.min_reduced_moment",
                                                {"value": np.min(model.J_kgm2)})))
    if probs:
        raise SpecError(probs)
    Mconst = None
    role = None
    if driving == "constant":
        resist_free = not np.any(model.M_resist_Nm) and not np.any(model.W_resist_J)
        model, Mconst = model.with_constant_drive()
        role = "resist" if resist_free and Mconst < 0 else "drive"
    else:
        _net_work_check(model, "dynamics.driving")
    J = model.J_kgm2 + J_flywheel
    W = model.W_net_J
    # smallest ω0 that keeps J0 ω0² + 2W ≥ 0 everywhere
    w_lo = math.sqrt(max(0.0, -2.0 * np.min(W)) / J[0])

    def mean_minus(w0):
        w, _ = _omega_of(model, J, W, w0)
        return 0.5 * (w.max() + w.min()) - wm

    if mean_minus(w_lo) >= 0:
        w, _ = _omega_of(model, J, W, w_lo)
        i = int(np.argmin(w))
        need = np.ptp(W) / (0.5 * wm * wm) if wm > 0 else math.inf
        raise MotionError(Problem(
            "dynamics", Text("errors.dynamics.motion.machine_cannot_keep",
                             {"wm": wm, "value": np.ptp(W), "value2": model.phi_deg[i],
                              "need": need})))
    hi = max(2.0 * wm, w_lo * 2 + 1.0)
    while mean_minus(hi) < 0:
        hi *= 2.0
    w0 = brentq(mean_minus, w_lo, hi, xtol=1e-14 * hi, rtol=4 * np.finfo(float).eps,
                maxiter=200)
    w, _ = _omega_of(model, J, W, w0)
    Mnet = model.M_drive_Nm - model.M_resist_Nm
    eps = (Mnet - 0.5 * w * w * model.dJ_dphi_kgm2) / J
    with np.errstate(divide="ignore"):
        t = _cumtrapz(1.0 / w, model.phi)
    wmax, wmin = float(w.max()), float(w.min())
    wmean = 0.5 * (wmax + wmin)
    table = pd.DataFrame({
        "phi_deg": model.phi_deg, "phi_rad": model.phi, "J_red_kgm2": J,
        "dJ_red_dphi_kgm2": model.dJ_dphi_kgm2, "M_drive_Nm": model.M_drive_Nm,
        "M_resist_Nm": model.M_resist_Nm, "W_J": W, "E_J": 0.5 * J * w * w,
        "omega_rad_s": w, "eps_rad_s2": eps, "t_s": t})
    _add_extra_columns(table, model)
    return MotionResult(
        name=model.name, table=table, omega_max=wmax, omega_min=wmin, omega_mean=wmean,
        omega_time_mean=float(model.period / t[-1]), delta=(wmax - wmin) / wmean,
        dW_max=float(np.ptp(W)), J_flywheel=float(J_flywheel), M_drive_const=Mconst,
        cycle_time=float(t[-1]), phi_omega_max_deg=float(model.phi_deg[np.argmax(w)]),
        phi_omega_min_deg=float(model.phi_deg[np.argmin(w)]), driving=driving,
        constant_role=role)


def size_flywheel(model, delta, omega_mean=None, *, driving="constant") -> FlywheelResult:
    """Flywheel on the main shaft for the coefficient of speed fluctuation ``delta``.

    Classic: :func:`classic_flywheel_result`.  Exact: brentq on δ(J_F) − δ with the
    energy-form solution (δ decreases monotonically with J_F).

    Returns
    -------
    FlywheelResult
        The one flywheel type (:class:`engine.train.FlywheelResult`): ``delta`` the asked
        δ; ``dW_max`` ΔW_max of the classic estimate, the swing of
        ∫(M_d − M_c − ½ω_m² dJ/dφ)dφ; ``J_c`` the cycle mean of J_red; ``J_classic``
        ΔW_max/(δ ω_m²) − J_c (may be ≤ 0); ``J_exact`` the flywheel that gives exactly δ
        with the variable J_red (0 when the machine is already within δ); ``motion`` the
        motion with ``J_exact``.
    """
    from dataclasses import replace

    from scipy.optimize import brentq

    check_delta(delta)
    wm = model.omega_nominal if omega_mean is None else omega_mean
    m0 = steady_motion(model, wm, J_flywheel=0.0, driving=driving) \
        if _feasible(model, wm, 0.0, driving) else None
    base = model.with_constant_drive()[0] if driving == "constant" else model
    fw = classic_flywheel_result(base, delta, wm)
    dW, J_classic = fw.dW_max, fw.J_classic
    if m0 is not None and m0.delta <= delta:
        return replace(fw, J_exact=0.0, motion=m0)

    def f(JF):
        return steady_motion(model, wm, J_flywheel=JF, driving=driving).delta - delta

    hi = max(J_classic, dW / (delta * wm * wm), 1e-9)
    while f(hi) > 0:
        hi *= 2.0
    lo = 0.0
    if m0 is None:  # without a flywheel the machine cannot even run: bracket from above
        a, b = 0.0, hi
        for _ in range(200):
            mid = 0.5 * (a + b)
            if not _feasible(model, wm, mid, driving):
                a = mid
            elif f(mid) <= 0:
                b = mid
            else:
                break
        lo = mid
    JF = brentq(f, lo, hi, xtol=1e-12 * hi, rtol=1e-12)
    return replace(fw, J_exact=float(JF),
                   motion=steady_motion(model, wm, J_flywheel=JF, driving=driving))


def classic_flywheel_result(model, delta, omega_mean) -> FlywheelResult:
    """The classic flywheel estimate as a :class:`FlywheelResult` (without the exact
    flywheel): :func:`engine.train.flywheel` of the swing ΔW_max of the turning-moment
    diagram at the constant speed ω_m, M_d − M_c − ½ω_m² dJ/dφ (the inertia torque of the
    variable part of J_red included, as in the engine's total torque Mкр of gas and
    inertia forces), with J_c the cycle mean of J_red, the constant part the estimate
    treats as already there: J_F = ΔW_max/(δ ω_m²) − J_c (Khurmi & Gupta eq. 16.8; seed
    001 §11.4).  For a constant J_red it is exact; ≤ 0 means no flywheel is needed by
    this estimate.
    """
    # ∫½ω_m² dJ/dφ dφ = ½ω_m² (J − J(0)) exactly; W_net is exact for the diagrams
    W = model.W_net_J - 0.5 * omega_mean ** 2 * (model.J_kgm2 - model.J_kgm2[0])
    dW = float(np.ptp(W))
    Jc = float(np.mean(model.J_kgm2[:-1]))
    return flywheel(dW, float(omega_mean), delta, J_c=Jc)


def classic_flywheel(model, delta, omega_mean):
    """The classic flywheel estimate ``(ΔW_max, J_c, J_F)`` of
    :func:`classic_flywheel_result` as a tuple."""
    fw = classic_flywheel_result(model, delta, omega_mean)
    return fw.dW_max, fw.J_c, fw.J_classic


def _feasible(model, wm, JF, driving):
    try:
        steady_motion(model, wm, J_flywheel=JF, driving=driving)
        return True
    except MotionError:
        return False


# --------------------------------------------------------------------------- motor


@dataclass
class Motor:
    """Linear motor characteristic M = M0 (1 − ω/ω0) [N·m] (asynchronous motor on the
    stable branch, or a DC shunt motor)."""

    M0: float
    omega0: float

    def __call__(self, w):
        return self.M0 * (1.0 - w / self.omega0)


def _interp_periodic(model):
    """``f(φ) → (J, dJ/dφ, M_d − M_c)`` by linear interpolation on the model's grid,
    periodic; scalar Python arithmetic (the ODE right-hand sides call it ~10⁵ times)."""
    import bisect

    P = float(model.period)
    x = model.phi.tolist()
    n = len(x) - 1
    J = model.J_kgm2.tolist()
    dJ = model.dJ_dphi_kgm2.tolist()
    M = (model.M_drive_Nm - model.M_resist_Nm).tolist()

    def f(p):
        u = p % P
        k = min(max(bisect.bisect_right(x, u) - 1, 0), n - 1)
        t = (u - x[k]) / (x[k + 1] - x[k])
        return (J[k] + t * (J[k + 1] - J[k]), dJ[k] + t * (dJ[k + 1] - dJ[k]),
                M[k] + t * (M[k + 1] - M[k]))

    return f


def _check_motor(model, motor, JF):
    probs = []
    if not motor.M0 > 0:
        probs.append(Problem("dynamics.motor_start_torque_Nm",
                             Text("errors.dynamics.motion.message_2", {"M0": motor.M0})))
    if not motor.omega0 > 0:
        probs.append(Problem("dynamics.motor_sync_speed_rad_s",
                             Text("errors.dynamics.motion.message_3", {"omega0": motor.omega0})))
    if not JF >= 0:
        probs.append(Problem("dynamics.flywheel_kgm2", Text("errors.dynamics.motion.message_4",
                                                            {"JF": JF})))
    if probs:
        raise SpecError(probs)
    Mc_mean = (model.W_resist_J[-1] - model.W_drive_J[-1]) / model.period
    if Mc_mean >= motor.M0:
        raise MotionError(Problem(
            "dynamics.motor_start_torque_Nm",
            Text("errors.dynamics.motion.motor_stalls_mean",
                 {"Mc_mean": Mc_mean, "M0": motor.M0})))
    return Mc_mean


def motor_steady_motion(model, motor: Motor, *, J_flywheel=0.0, rtol=1e-9):
    """Periodic steady state of a machine driven by a linear motor characteristic.

    Shooting: ω(0) such that the differential form integrated over one period in the angle
    returns to ω(0) (brentq), integrated by ``solve_ivp`` (LSODA, rtol 1e-9); then the
    table on the model's grid as in :func:`steady_motion` (``driving="motor"``).

    Raises
    ------
    MotionError
        The motor stalls (mean resistance ≥ M0, or ω reaches zero within the cycle).
    """
    import pandas as pd
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    Mc_mean = _check_motor(model, motor, J_flywheel)
    state = _interp_periodic(model)
    P = model.period
    M0, w0m = motor.M0, motor.omega0

    def rhs(p, y):
        w = y[0]
        J, dJ, M = state(p)
        M += M0 * (1.0 - w / w0m)
        return [(M - 0.5 * w * w * dJ) / ((J + J_flywheel) * w)]

    w_floor = 1e-4 * motor.omega0   # below this the machine is taken as stopped

    def stop(p, y):
        return y[0] - w_floor
    stop.terminal = True

    def shoot(w0, dense=False):
        if not w0 > 2 * w_floor:
            return None
        try:
            sol = solve_ivp(rhs, (0.0, P), [w0], method="LSODA", rtol=rtol,
                            atol=1e-12 * motor.omega0, events=stop, dense_output=dense)
        except ValueError:  # the event's root lost in the 1/ω singularity: a stall
            return None
        if sol.status != 0 or not np.isfinite(sol.y[0, -1]):
            return None
        return sol

    def g(w0):
        sol = shoot(w0)
        # a stall (or a start at ω ≤ 0) counts as losing all the speed
        return -(abs(w0) + 1e-9 * motor.omega0) if sol is None else sol.y[0, -1] - w0

    w_ss = motor.omega0 * (1.0 - Mc_mean / motor.M0)   # the constant-J estimate
    w0 = None
    try:  # secant from the constant-J estimate: g is smooth, ~5 shots
        from scipy.optimize import newton
        w0 = float(newton(g, w_ss, x1=w_ss * (1.0 + 1e-3), tol=1e-8 * motor.omega0,
                          maxiter=30))
        if not (w0 > 0 and shoot(w0) is not None):
            w0 = None
    except (RuntimeError, OverflowError, ValueError):
        w0 = None
    if w0 is None:  # bracket and bisect
        hi = motor.omega0 * 1.5
        lo = w_ss
        for _ in range(60):
            if g(lo) > 0:
                break
            lo *= 0.8
        else:
            lo = None
        if lo is None or g(hi) >= 0:
            raise MotionError(Problem(
                "dynamics.motor_start_torque_Nm",
                Text("errors.dynamics.motion.motor_stalls_with",
                     {"M0": motor.M0, "omega0": motor.omega0})))
        w0 = brentq(g, lo, hi, xtol=1e-9 * motor.omega0)
    sol = shoot(w0, dense=True)
    if sol is None:
        raise MotionError(Problem("dynamics.motor_start_torque_Nm",
                                  Text("errors.dynamics.motion.motor_stalls_within")))
    w = sol.sol(model.phi)[0]
    J = model.J_kgm2 + J_flywheel
    Md = motor(w) + model.M_drive_Nm
    eps = (Md - model.M_resist_Nm - 0.5 * w * w * model.dJ_dphi_kgm2) / J
    t = _cumtrapz(1.0 / w, model.phi)
    Wd = _cumtrapz(Md, model.phi)
    Wnet = Wd - model.W_resist_J
    wmax, wmin = float(w.max()), float(w.min())
    table = pd.DataFrame({
        "phi_deg": model.phi_deg, "phi_rad": model.phi, "J_red_kgm2": J,
        "dJ_red_dphi_kgm2": model.dJ_dphi_kgm2, "M_drive_Nm": Md,
        "M_resist_Nm": model.M_resist_Nm, "W_J": Wnet, "E_J": 0.5 * J * w * w,
        "omega_rad_s": w, "eps_rad_s2": eps, "t_s": t})
    _add_extra_columns(table, model)
    wmean = 0.5 * (wmax + wmin)
    return MotionResult(
        name=model.name, table=table, omega_max=wmax, omega_min=wmin, omega_mean=wmean,
        omega_time_mean=float(P / t[-1]), delta=(wmax - wmin) / wmean,
        dW_max=float(np.ptp(Wnet)), J_flywheel=float(J_flywheel), M_drive_const=None,
        cycle_time=float(t[-1]), phi_omega_max_deg=float(model.phi_deg[np.argmax(w)]),
        phi_omega_min_deg=float(model.phi_deg[np.argmin(w)]), driving="motor",
        extra={"motor_M0_Nm": motor.M0, "motor_omega0_rad_s": motor.omega0})


@dataclass
class StartupResult:
    """Start-up from rest: ``table`` with ``t_s, phi_rad, omega_rad_s``; ``t_steady`` the
    time after which the cycle-end speed stays within 1 % of the steady δ band."""

    table: object
    t_steady: float


def motor_startup(model, motor: Motor, *, J_flywheel=0.0, steady: MotionResult | None = None,
                  cycles=None, points=2000):
    """Start-up from rest (φ = 0, ω = 0) under the motor characteristic, integrated in
    time by ``solve_ivp`` (LSODA) on J(φ)ω' = M(ω) + M_d(φ) − M_c(φ) − ½ω² J'(φ),
    φ' = ω, until the speed settles (a few motor time constants J/(M0/ω0) and at least
    ten cycles of the steady motion).

    Raises
    ------
    MotionError
        The motor cannot start (M0 below the resistance at rest) or stalls.
    """
    import pandas as pd
    from scipy.integrate import solve_ivp

    Mc_mean = _check_motor(model, motor, J_flywheel)
    state = _interp_periodic(model)
    if motor.M0 + state(0.0)[2] <= 0.0:
        raise MotionError(Problem(
            "dynamics.motor_start_torque_Nm",
            Text("errors.dynamics.motion.motor_cannot_start",
                 {"M0": motor.M0, "value": -state(0.0)[2]})))
    w_ss = steady.omega_time_mean if steady is not None else \
        motor.omega0 * (1.0 - Mc_mean / motor.M0)
    Jm = float(np.mean(model.J_kgm2)) + J_flywheel
    tau = Jm * motor.omega0 / motor.M0
    T = model.period / w_ss
    t_end = max(6.0 * tau, (cycles or 10) * T)

    def rhs(t, y):
        p, w = y
        J, dJ, M = state(p)
        M += motor(w)
        return [w, (M - 0.5 * w * w * dJ) / (J + J_flywheel)]

    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0], method="LSODA", rtol=1e-8,
                    atol=[1e-10, 1e-10 * motor.omega0], max_step=T / 40, dense_output=True)
    t = np.linspace(0.0, t_end, points)
    p, w = sol.sol(t)
    if np.any(w[t > T] <= 0):
        raise MotionError(Problem("dynamics.motor_start_torque_Nm",
                                  Text("errors.dynamics.motion.motor_stalls_during")))
    band = (steady.omega_min, steady.omega_max) if steady is not None else (w_ss, w_ss)
    tol = 0.01 * max(band[1] - band[0], 0.01 * w_ss)
    out = (w < band[0] - tol) | (w > band[1] + tol)
    t_steady = float(t[np.flatnonzero(out)[-1]]) if out.any() else 0.0
    table = pd.DataFrame({"t_s": t, "phi_rad": p, "omega_rad_s": w})
    return StartupResult(table, t_steady)


# --------------------------------------------------------------------------- kinetostatics


def linkage_forces(spec, phi, omega, eps, mech=None, ext=None):
    """The core's kinetostatics at crank angles ``phi`` [rad] with the crank's ω and ε given
    per position (arrays or scalars, signed, + ccw).

    The same steps as the core's table (``linkage.analysis``): the mechanism's chain
    solved (:func:`linkage.chain.solve`), the external loads by the core's rule
    (:func:`linkage.loads.external_loads`, its stroke cycle from the spec's constant ω),
    then its kinetostatics group by group (:func:`linkage.chain.kinetostatics`), the
    reactions named as the course names them (:data:`linkage.course.REACTIONS`).

    Returns
    -------
    dict of ndarray
        ``R12_x_N, R12_y_N, R23_x_N, R23_y_N, R43_x_N, R43_y_N, R14_x_N, R14_y_N,
        M_drive_Nm`` (+ ``M14_Nm`` for a slider), as the core's columns of the same names.
    """
    from linkage import chain as ch
    from linkage.analysis import build_mechanism
    from linkage.course import REACTIONS, course_of
    from linkage.loads import external_loads, stroke_cycle

    mech = mech or build_mechanism(spec)
    course = course_of(spec)
    res = ch.solve(ch.from_mechanism(mech, spec.links), phi, omega, eps, check=False)
    kin = {"crank": res.links["crank"], "A": res.joints["A"], "dyad": res.solutions[0],
           "links": res.links}
    forces, moments, _ = external_loads(spec, mech, kin, stroke_cycle(mech, spec, ext))
    cf = ch.kinetostatics(res, forces, moments, spec.gravity)
    link = {"output": course.output}
    out = {}
    for name, (i, j) in REACTIONS:
        v = cf.R(link.get(i, i), link.get(j, j))
        out[f"{name}_x_N"] = np.broadcast_to(v.real, np.shape(phi)).astype(float)
        out[f"{name}_y_N"] = np.broadcast_to(v.imag, np.shape(phi)).astype(float)
    out["M_drive_Nm"] = np.broadcast_to(cf.M_drive, np.shape(phi)).astype(float)
    couple = cf.reactions[("frame", course.output)].couple    # a prismatic pair's only
    if couple is not None:
        out["M14_Nm"] = np.broadcast_to(couple, np.shape(phi)).astype(float)
    return out


def true_motion_forces(model, motion: MotionResult):
    """The core's force analysis re-run under the true motion ω(φ), ε(φ) of the crank,
    beside the constant-speed one (at ω_m, ε = 0).

    Parameters
    ----------
    model : ReducedModel
        From :func:`dynamics.reduced.linkage_model` (``model.source`` is the linkage spec).
    motion : MotionResult
        Its steady motion.

    Returns
    -------
    pandas.DataFrame
        ``phi_deg``, ``omega_rad_s``, ``eps_rad_s2`` and, for every reaction of the core
        (``R12_x_N`` … ``R14_y_N``, ``M_drive_Nm``), the value under the true motion and
        the constant-speed value with the suffix ``_const``; also ``R12_N`` (and
        ``R12_N_const``), the magnitude of the crank bearing's reaction.  ``M_drive_Nm``
        is the core's balancing moment on the crank (+ counter-clockwise, as in
        :mod:`linkage`) without the flywheel: under the true motion it equals
        ``rotation·(M_d − J_F·ε)``.

    Notes
    -----
    :func:`linkage_forces` (the core's routines) with the crank's ω and ε as the arrays
    ω(φ), ε(φ): the group routines take the driver's ω and ε per position.
    """
    import dataclasses

    import pandas as pd
    from linkage.analysis import build_mechanism

    from .reduced import stroke_extremes

    spec = model.source
    if getattr(spec, "kind", "") == "chain":        # any chain of class II groups
        from .chain_model import chain_spec_forces

        return chain_spec_forces(model, motion)
    s = model.rotation
    # the resistance rule's cycle (at-rest threshold) at the mean speed
    spec_m = dataclasses.replace(spec, omega=float(s * motion.omega_mean), epsilon=0.0)
    mech = build_mechanism(spec_m)
    ext = stroke_extremes(spec_m, mech)
    phi = np.radians(motion.table["phi_deg"].to_numpy())
    w = motion.table["omega_rad_s"].to_numpy()
    e = motion.table["eps_rad_s2"].to_numpy()
    true = linkage_forces(spec_m, phi, s * w, s * e, mech, ext)
    const = linkage_forces(spec_m, phi, spec_m.omega, 0.0, mech, ext)
    df = pd.DataFrame({"phi_deg": motion.table["phi_deg"].to_numpy(),
                       "omega_rad_s": w, "eps_rad_s2": e})
    for c in true:
        df[c] = true[c]
        df[f"{c}_const"] = const[c]
    for name, f in (("", true), ("_const", const)):   # the crank bearing's load
        df[f"R12_N{name}"] = np.hypot(f["R12_x_N"], f["R12_y_N"])
    return df


def engine_true_motion_forces(model, motion: MotionResult):
    """The engine's crank-pin forces of cylinder 1 under the true motion ω(α), ε(α),
    beside those at the constant speed ω_m.

    The engine's own routines: piston kinematics ``engine.kinematics.crank_slider`` at the
    array ω(α) (exact j at that ω), plus the angular-acceleration term of the piston
    acceleration, j = x''(α)·ω² + x'(α)·ε with x' = v/ω; ``inertia_force``,
    ``crank_pin_forces`` (T, K, Mкр) and Kr.ш of the spec scaled to ω(α)²; the gas force of the
    force table.  The constant-speed columns (suffix ``_const``) go through the same code
    with ω = ω_m, ε = 0, so the difference is the speed fluctuation alone (exact piston
    acceleration in both, whatever the spec's ``acceleration``).

    Returns
    -------
    pandas.DataFrame
        ``alpha_deg, omega_rad_s, eps_rad_s2, j_m_s2, Pj_N, P_N, T_N, K_N, M_Nm, R_N``
        and the same with ``_const``.
    """
    import engine
    import pandas as pd
    from engine.forces import crank_pin_resultant, inertia_force

    spec = model.source
    a_deg = motion.table["phi_deg"].to_numpy()
    alpha = np.radians(a_deg)
    dPg = engine.force_table(spec, a_deg)["dPg_N"].to_numpy()
    w = motion.table["omega_rad_s"].to_numpy()
    e = motion.table["eps_rad_s2"].to_numpy()

    def run(omega, eps):
        mech = engine.crank_slider(alpha, spec.R, spec.L, omega, offset=spec.pin_offset)
        j = mech.j + mech.v / omega * eps
        Pj = inertia_force(spec.mj, j)
        P = dPg + Pj
        f = engine.crank_pin_forces(mech, P, spec.L)
        Kr = spec.Kr * (omega / spec.omega) ** 2        # Kr.ш ∝ ω²
        return {"j_m_s2": j, "Pj_N": Pj, "P_N": P, "T_N": f["T"], "K_N": f["K"],
                "M_Nm": f["M"], "R_N": crank_pin_resultant(f["T"], f["K"], Kr)[0]}

    true = run(w, e)
    const = run(np.full_like(w, motion.omega_mean), np.zeros_like(w))
    df = pd.DataFrame({"alpha_deg": a_deg, "omega_rad_s": w, "eps_rad_s2": e})
    for c in true:
        df[c] = true[c]
        df[f"{c}_const"] = const[c]
    return df
