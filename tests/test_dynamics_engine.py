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
