"""Bearing loads of a whole engine (engine.bearings.train.engine_bearings): a 90° V8
cross-plane and an inline 4 from the one-cylinder model, checked against vector sums and
equilibria built in the tests."""
import copy

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine
from engine.bearings.analysis import bearing_analysis, read_bearing_inputs
from engine.bearings import BearingInputError
from engine.bearings.train import Cylinder, engine_bearings, full_support_journals

BASE = {
    "engine": dict(name="v8", bore_mm=92.0, stroke_mm=86.0, rod_ratio=0.28,
                   speed_rpm=4800.0, crankcase_MPa=0.1),
    "masses": dict(piston_group_kg=0.6, rod_kg=0.9, crank_rotating_kg=0.8),
    "pressure": {"cycle": dict(kind="otto", compression_ratio=9.5, pa_MPa=0.085,
                               pr_MPa=0.115, n1=1.37, n2=1.25, pz_MPa=6.5)},
    "table": dict(step_deg=10.0, force_scale_N_per_mm=100.0),
}
SPEC = engine.load_spec(copy.deepcopy(BASE))
THETA = np.arange(0.0, 720.0, 2.0)


def v8(spacing=0.1, offset=0.02):
    """90° V8, cross-plane throws 0/90/270/180 from throw 1; bank A (cylinders 1–4) at
    −45°, bank B (5–8) at +45°; θ is cylinder 1's α, so throw k points at −45° + τk."""
    tau = [0.0, 90.0, 270.0, 180.0]
    g1 = -45.0
    cyls = []
    for bank, gamma in ((0, -45.0), (1, 45.0)):
        for k in range(4):
            lag = (gamma - g1 - tau[k]) % 360.0
            late = 360.0 if (k + bank) % 2 else 0.0       # any revolution is physical
            cyls.append(Cylinder(gamma, lag + late, k, spacing * k + offset * bank))
    z_throw = [spacing * k + offset / 2 for k in range(4)]
    return cyls, [g1 + t for t in tau], z_throw


def _rod_engine_frame(t, cyl):
    """One rod's force on its pin incl. Kr.ш, engine frame, from Sш and β in the
    cylinder frame turned by the bank angle (no K, T)."""
    a = np.radians(t["alpha_deg"].to_numpy() - cyl.phase_deg)
    b = np.radians(t["beta_deg"].to_numpy())
    F = -t["S_N"].to_numpy() * np.exp(1j * (np.pi / 2 - b)) \
        + SPEC.m_rod_rot * SPEC.R * SPEC.omega ** 2 * np.exp(1j * (np.pi / 2 + a))
    return F * np.exp(1j * np.radians(cyl.bank_deg))


def test_v8_pins_are_vector_sums_and_the_shaft_is_in_equilibrium():
    cyls, tau, zt = v8()
    cw = [(0.0, 0.05, 200.0), (0.3, 0.05, 20.0)]
    res = engine_bearings(SPEC, THETA, cyls, tau, zt, counterweights=cw)
    L = res.loads
    tabs = [engine.force_table(SPEC, THETA, bank_deg=c.bank_deg, phase_deg=c.phase_deg)
            for c in cyls]
    F_loads, z_loads = [], []
    for k in range(4):
        e = np.exp(1j * np.radians(90.0 + THETA + tau[k]))
        F = sum(_rod_engine_frame(t, c) for t, c in zip(tabs, cyls) if c.throw == k)
        K = F.real * -e.real + F.imag * -e.imag
        T = F.real * -e.imag + F.imag * e.real
        scale = np.abs(F).max()
        assert np.abs(L.crankpins[f"K_{k + 1}_N"] - K).max() < 1e-10 * scale
        assert np.abs(L.crankpins[f"T_{k + 1}_N"] - T).max() < 1e-10 * scale
        for t, c in zip(tabs, cyls):
            if c.throw == k:
                F_loads.append(_rod_engine_frame(t, c))
                z_loads.append(c.z)
        F_loads.append(0.8 * SPEC.R * SPEC.omega ** 2 * e)
        z_loads.append(zt[k])
    e1 = np.exp(1j * np.radians(90.0 + THETA + tau[0]))
    for z, mr, ang in cw:
        F_loads.append(mr * SPEC.omega ** 2 * e1 * np.exp(1j * np.radians(ang)))
        z_loads.append(z)
    F_loads, z_loads = np.array(F_loads), np.array(z_loads)
    zj = np.asarray(L.shaft.z_journal)
    scale = np.abs(F_loads).max() * len(z_loads)
    assert np.abs(F_loads.sum(0) - L.Q.sum(0)).max() < 1e-9 * scale
    mom = (z_loads[:, None] * F_loads).sum(0) - (zj[:, None] * L.Q).sum(0)
    assert np.abs(mom).max() < 1e-9 * scale
    # journal torques: the last carries every cylinder's Mкр at its phase
    total = sum(t["M_Nm"].to_numpy() for t in tabs)
    assert np.allclose(L.journal_torques["M_5_Nm"], total, atol=1e-9 * np.abs(total).max())
    assert len(res.pin_wear) == 4 and len(res.journal_wear) == 5
    assert zj.tolist() == pytest.approx(full_support_journals(zt).tolist())
    assert zj.tolist() == pytest.approx([-0.04, 0.06, 0.16, 0.26, 0.36])


def test_one_cylinder_engine_equals_the_one_cylinder_analysis():
    res = engine_bearings(SPEC, THETA, [Cylinder(0.0, 0.0, 0, 0.0)], [0.0], [0.0])
    t = engine.force_table(SPEC, THETA)
    one = bearing_analysis(SPEC, t)
    np.testing.assert_allclose(res.loads.crankpins.to_numpy(),
                               one.loads.crankpins.to_numpy(), rtol=1e-13, atol=1e-9)
    np.testing.assert_allclose(res.loads.journals.to_numpy(),
                               one.loads.journals.to_numpy(), rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(res.pin_wear[0].wear, one.pin_wear.wear, rtol=1e-12)


def test_a_phase_that_contradicts_the_layout_is_refused():
    cyls, tau, zt = v8()
    bad = list(cyls)
    bad[5] = Cylinder(bad[5].bank_deg, bad[5].phase_deg + 90.0, bad[5].throw, bad[5].z)
    with pytest.raises(BearingInputError, match="cylinder 6: phase .* does not match"):
        engine_bearings(SPEC, THETA, bad, tau, zt)
    with pytest.raises(BearingInputError, match="throw 5 does not exist"):
        engine_bearings(SPEC, THETA, [Cylinder(0.0, 0.0, 4, 0.0)], tau, zt)
    d = copy.deepcopy(BASE)
    d["bearings"] = dict(journal_positions_mm=[-40.0, 40.0], wear_half_angle_deg=50.0)
    inputs = read_bearing_inputs(d, SPEC)
    with pytest.raises(BearingInputError, match="bearings.journal_positions_mm: only for a "
                                                "one-cylinder spec"):
        engine_bearings(SPEC, THETA, cyls, tau, zt, inputs=inputs)


@st.composite
def layouts(draw):
    nt = draw(st.integers(1, 3))
    tau = [draw(st.floats(-180.0, 180.0)) for _ in range(nt)]
    cyls = []
    for k in range(nt):
        for r in range(draw(st.integers(1, 2))):
            g = draw(st.floats(-80.0, 80.0))
            phase = (g - tau[k]) % 360.0 + 360.0 * draw(st.integers(0, 1))
            cyls.append(Cylinder(g, phase, k, 0.1 * k + 0.02 * r))
    return cyls, tau, [0.1 * k + 0.01 for k in range(nt)]


@settings(max_examples=8, deadline=None)
@given(layouts())
def test_random_layouts_pins_and_equilibrium(case):
    cyls, tau, zt = case
    th = np.arange(0.0, 720.0, 15.0)
    res = engine_bearings(SPEC, th, cyls, tau, zt)
    L = res.loads
    F_all = []
    for k in range(len(tau)):
        e = np.exp(1j * np.radians(90.0 + th + tau[k]))
        F = 0
        for c in cyls:
            if c.throw == k:
                t = engine.force_table(SPEC, th, bank_deg=c.bank_deg, phase_deg=c.phase_deg)
                F = F + _rod_engine_frame(t, c)
        K = F.real * -e.real + F.imag * -e.imag
        T = F.real * -e.imag + F.imag * e.real
        scale = np.abs(F).max()
        assert np.abs(L.crankpins[f"K_{k + 1}_N"] - K).max() < 1e-10 * scale
        assert np.abs(L.crankpins[f"T_{k + 1}_N"] - T).max() < 1e-10 * scale
        F_all.append(F + 0.8 * SPEC.R * SPEC.omega ** 2 * e)
    total = np.sum(F_all, axis=0)
    assert np.abs(total - L.Q.sum(axis=0)).max() < 1e-9 * np.abs(total).max() * len(cyls)
