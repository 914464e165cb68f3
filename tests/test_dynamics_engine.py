"""The engine as a machine: the reduced model against the engine's own force table."""
import numpy as np
import pytest

import engine
from crankbase.resources import example_path
from dynamics.motion import steady_motion
from dynamics.reduced import engine_model
from crankbase.validation import read_toml


def _spec(acceleration="exact", cylinders=4):
    data, base = read_toml(example_path("petrol_dynamics.toml"))
    data = {k: v for k, v in data.items() if k != "dynamics"}
    data["engine"] = dict(data["engine"], acceleration=acceleration, cylinders=cylinders)
    return engine.load_spec(data, base_dir=base)


@pytest.mark.parametrize("cylinders", [1, 4])
def test_inertia_torque_is_the_force_tables(cylinders):
    """At constant speed the equation of motion's M_gas − ½ω² dJ/dφ is the engine's total
    torque Σ Mкр (gas + inertia of the reciprocating masses, exact acceleration) of the
    force table: the variable J carries exactly the torque of Pj."""
    spec = _spec("exact", cylinders)
    m = engine_model(spec, steps=720)
    cyc = 720.0
    a = np.degrees(m.phi)
    total = sum(engine.force_table(spec, np.mod(a - k * cyc / cylinders, cyc))["M_Nm"].to_numpy()
                for k in range(cylinders))
    lhs = m.M_drive_Nm - 0.5 * spec.omega ** 2 * m.dJ_dphi_kgm2
    assert np.max(np.abs(lhs - total)) < 1e-9 * np.max(np.abs(total))
    # and dJ/dφ is the derivative of J
    dJ = np.gradient(m.J_kgm2, m.phi, edge_order=2)
    assert np.max(np.abs(dJ - m.dJ_dphi_kgm2)) < 2e-3 * np.max(np.abs(m.dJ_dphi_kgm2))


def test_mean_torque_and_constant_resistance():
    """The constant resisting torque that makes the cycle steady is the mean gas torque;
    the piston inertia torque has zero mean (domain brief §5)."""
    spec = _spec("two-term", 4)
    m = engine_model(spec)
    r = steady_motion(m, J_flywheel=0.2)
    assert r.constant_role == "resist"
    assert -r.M_drive_const == pytest.approx(m.W_drive_J[-1] / m.period)
    assert m.J_kgm2[-1] - m.J_kgm2[0] == pytest.approx(0.0, abs=1e-12)
    assert np.sum(0.5 * (m.dJ_dphi_kgm2[1:] + m.dJ_dphi_kgm2[:-1]) * np.diff(m.phi)) == \
        pytest.approx(0.0, abs=1e-9)


def test_true_motion_torque_virtual_power():
    """One cylinder under the true motion: the engine's crank torque (gas + piston inertia
    with the ε term) equals M_gas − (J_rec ε + ½ ω² dJ/dφ), J_rec = m_j (dx/dφ)² the part of
    J_red the piston carries: the virtual-power balance with variable ω.  A huge flywheel
    gives the constant-speed forces."""
    from dynamics.motion import engine_true_motion_forces

    spec = _spec("exact", 1)
    m = engine_model(spec, steps=1440)
    r = steady_motion(m, J_flywheel=0.05)
    f = engine_true_motion_forces(m, r)
    w, eps = r.table["omega_rad_s"].to_numpy(), r.table["eps_rad_s2"].to_numpy()
    J_rec = m.J_kgm2 - (spec.m_rod_rot + (spec.m_crank_rot or 0.0)) * spec.R ** 2
    expect = m.M_drive_Nm - (J_rec * eps + 0.5 * w * w * m.dJ_dphi_kgm2)
    assert np.max(np.abs(f["M_Nm"] - expect)) < 1e-9 * np.max(np.abs(expect))
    assert r.delta > 0.01   # a real fluctuation, so the test is not the trivial one
    big = engine_true_motion_forces(m, steady_motion(m, J_flywheel=1e8))
    for c in ("T_N", "K_N", "R_N"):
        assert np.max(np.abs(big[c] - big[f"{c}_const"])) < 1e-5 * np.max(np.abs(big[c]))


def test_classic_flywheel_of_an_engine_includes_the_inertia_torque():
    """The classic estimate uses the turning-moment diagram at constant speed (gas and
    inertia torque): for the petrol engine at 5400 rpm it is within 1 % of the exact J_F,
    while the gas torque alone would give a third of it."""
    from dynamics.motion import size_flywheel

    spec = _spec("two-term", 4)
    m = engine_model(spec, J_extra_kgm2=0.02)
    fw = size_flywheel(m, 0.01)
    assert fw.motion.delta == pytest.approx(0.01, rel=1e-6)
    assert fw.J_classic == pytest.approx(fw.J_exact, rel=0.01)
    const, _ = m.with_constant_drive()
    gas_only = np.ptp(const.W_net_J) / (0.01 * m.omega_nominal ** 2) - fw.J_c
    assert gas_only < 0.5 * fw.J_exact


def _vtwin(**masses):
    """The petrol cylinder as a 90° V-twin on one common crank pin (odd firing: the
    second bank's cylinder reaches TDC 90° after the first, and fires there)."""
    data, base = read_toml(example_path("petrol_dynamics.toml"))
    data = {k: v for k, v in data.items() if k != "dynamics"}
    data["engine"] = dict(data["engine"], acceleration="exact", cylinders=2,
                          arrangement="vee", vee_angle_deg=90.0, throw_angles_deg=[0.0],
                          firing_order=[1, 2])
    data["masses"] = dict(data["masses"], **masses)
    return data, base


def _shifted(y, shift):
    """A periodic grid array (last point = first) delayed by ``shift`` grid steps."""
    body = np.roll(y[:-1], shift)
    return np.append(body, body[0])


@pytest.mark.parametrize("crank_kg", [None, 1.5])
def test_odd_firing_vee_twin_is_the_sum_of_its_cylinders(crank_kg):
    """A 90° V-twin as a machine: its reduced model and its true motion are those of its
    two cylinders computed one by one as one-cylinder engines at their own phases (0° and
    90°, from the layout) and banks (∓45°), summed.  The old model put the second cylinder
    at k·720°/i = 360° whatever the layout."""
    from dynamics.reduced import ReducedModel
    from dynamics.spec import load_dynamics_spec

    masses = {} if crank_kg is None else {"crank_rotating_kg": crank_kg}
    data, base = _vtwin(**masses)
    job = load_dynamics_spec(dict(data, dynamics={"driving": "constant", "steps": 1440},
                                  **({"pressure": data["pressure"]} if "pressure" in data
                                     else {})))
    twin = job.model
    study = engine.load(data, base_dir=base)
    lay = engine.layout(study.spec, study.train)
    assert list(lay.phase_deg) == [0.0, 90.0] and list(lay.bank_deg) == [-45.0, 45.0]

    one = dict(data, engine=dict(data["engine"], cylinders=1, arrangement="inline"))
    for k in ("vee_angle_deg", "throw_angles_deg", "firing_order"):
        one["engine"].pop(k)
    single = engine.load_spec(one, base_dir=base)
    m1 = engine_model(single, steps=1440)                # phase 0, bank 0
    step = 720.0 / 1440
    # each cylinder's table does not depend on its bank (forces in its own frames)
    t0 = engine.force_table(single, np.degrees(m1.phi))
    tb = engine.force_table(single, np.degrees(m1.phi), bank_deg=45.0, phase_deg=0.0)
    for c in ("M_Nm", "dPg_N", "v_m_s", "j_m_s2"):      # up to the rotated frame's round-off
        assert np.max(np.abs(t0[c] - tb[c])) < 1e-12 * np.max(np.abs(t0[c]))
    parts = [int(round(p / step)) for p in lay.phase_deg]
    J = sum(_shifted(m1.J_kgm2, s) for s in parts)
    if crank_kg:                     # one throw carries both rods: mк counted once
        J = J - crank_kg * single.R ** 2
    dJ = sum(_shifted(m1.dJ_dphi_kgm2, s) for s in parts)
    Md = sum(_shifted(m1.M_drive_Nm, s) for s in parts)
    scale = np.max(np.abs(Md))
    assert np.max(np.abs(twin.J_kgm2 - J)) < 1e-12 * np.max(J)
    assert np.max(np.abs(twin.dJ_dphi_kgm2 - dJ)) < 1e-9 * np.max(np.abs(dJ))
    assert np.max(np.abs(twin.M_drive_Nm - Md)) < 1e-9 * scale
    # the even-firing placement (second cylinder at 360°) is a different machine
    wrong = m1.M_drive_Nm + _shifted(m1.M_drive_Nm, int(round(360.0 / step)))
    assert np.max(np.abs(twin.M_drive_Nm - wrong)) > 0.3 * scale

    Wd = np.concatenate([[0.0], np.cumsum(0.5 * (Md[1:] + Md[:-1]) * np.diff(m1.phi))])
    zero = np.zeros_like(m1.phi)
    ref = ReducedModel("sum", m1.phi, J, dJ, Md, zero, Wd, zero.copy(), m1.period,
                       omega_nominal=single.omega)
    a = steady_motion(twin, J_flywheel=0.1)
    b = steady_motion(ref, J_flywheel=0.1)
    assert a.delta > 0.005          # a real fluctuation
    assert a.delta == pytest.approx(b.delta, rel=1e-9)
    w_a, w_b = a.table["omega_rad_s"].to_numpy(), b.table["omega_rad_s"].to_numpy()
    assert np.max(np.abs(w_a - w_b)) < 1e-9 * single.omega
