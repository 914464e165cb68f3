"""Bearing loads (engine.bearings, engine.bearings.analysis): crank pins, main journals, the
torques the journals carry, big end and piston pin.

Independent checks written here: the single-cylinder table's own Rшш and Ψ; a vee pin
built in the tests from the rod force Sш along the rod (not K, T) rotated by the bank
angle into the engine frame; the crankshaft's equilibrium from the loads the test itself
builds (its own unit vectors); the journal torques' steps; the big end by the rod force
along the rod; hypothesis over random crankshafts.
"""
import copy
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine
from engine.bearings.analysis import bearing_analysis, read_bearing_inputs, rod_bearing_table
from engine.bearings import (BearingInputError, Crankshaft, crank_pin_load,
                             crankshaft_loads, cylinder_alpha, journal_torques, lever_rule)

BASE = {
    "engine": dict(name="test", bore_mm=92.0, stroke_mm=86.0, rod_ratio=0.28,
                   speed_rpm=4800.0, crankcase_MPa=0.1),
    "masses": dict(piston_group_kg=0.6, rod_kg=0.9, crank_rotating_kg=0.8),
    "pressure": {"cycle": dict(kind="otto", compression_ratio=9.5, pa_MPa=0.085,
                               pr_MPa=0.115, n1=1.37, n2=1.25, pz_MPa=6.5)},
    "table": dict(step_deg=10.0, force_scale_N_per_mm=100.0),
}


def spec_dict(**sections):
    d = copy.deepcopy(BASE)
    for k, v in sections.items():
        d.setdefault(k, {}).update(v)
    return d


def make(**sections):
    return engine.load_spec(spec_dict(**sections))


def rel(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300))


# ------------------------------------------------------------------ crank pin


def test_single_cylinder_pin_is_the_tables_rshsh():
    spec = make()
    t = engine.force_table(spec, engine.fine_angles(spec, step_deg=1.0))
    K, T = crank_pin_load(t["K_N"], t["T_N"], spec.m_rod_rot, spec.R, spec.omega)
    assert np.allclose(np.hypot(K, T), t["R_N"], rtol=1e-13, atol=0)
    res = bearing_analysis(spec, t)
    assert np.array_equal(res.loads.crankpins["R_1_N"], t["R_N"])
    assert np.array_equal(res.loads.crankpins["psi_1_deg"], t["psi_deg"])
    # χ and the mean as the force table's summary gives them
    s = engine.summarize(t, spec)
    assert res.loads.pin_stats[0].mean_N == pytest.approx(s.R_mean_N, rel=1e-12)
    assert res.loads.pin_stats[0].chi == pytest.approx(s.chi, rel=1e-12)


def _rod_force_engine_frame(t, bank_deg, spec):
    """The rod's force on the pin and the rod's Kr.ш, engine frame, from Sш along the rod
    and β (cylinder frame: axis +y), turned by the bank angle: built here without K, T."""
    a = np.radians(t["alpha_deg"].to_numpy())
    b = np.radians(t["beta_deg"].to_numpy())
    rod_dir = np.exp(1j * (np.pi / 2 - b))            # crank pin -> piston pin
    crank_dir = np.exp(1j * (np.pi / 2 + a))
    F_cyl = -t["S_N"].to_numpy() * rod_dir + spec.m_rod_rot * spec.R * spec.omega ** 2 \
        * crank_dir
    return F_cyl * np.exp(1j * math.radians(bank_deg))


@pytest.mark.parametrize("vee, phase2", [(90.0, 450.0), (60.0, 60.0), (72.0, 432.0)])
def test_vee_pin_is_the_vector_sum_of_two_cylinders(vee, phase2):
    """Two rods on one pin: cylinder 1 on bank 0, cylinder 2 on bank γ (turned in the
    direction of rotation); the throw at τ = 0, so phase2 ≡ γ (mod 360)."""
    spec = make()
    theta = np.arange(0.0, 720.0, 2.5)
    cyl = [(0.0, 0.0), (vee, phase2)]
    tabs = [engine.force_table(spec, cylinder_alpha(theta, ph, 720.0)) for _, ph in cyl]
    K, T = crank_pin_load(np.stack([t["K_N"] for t in tabs]),
                          np.stack([t["T_N"] for t in tabs]),
                          [spec.m_rod_rot] * 2, spec.R, spec.omega)
    F = sum(_rod_force_engine_frame(t, g, spec) for t, (g, _) in zip(tabs, cyl))
    e = np.exp(1j * np.radians(90.0 + theta))          # throw 1 at θ from the vertical
    K_ref = F.real * -e.real + F.imag * -e.imag
    T_ref = F.real * (1j * e).real + F.imag * (1j * e).imag
    scale = np.max(np.abs(F))
    assert np.max(np.abs(K - K_ref)) < 1e-10 * scale
    assert np.max(np.abs(T - T_ref)) < 1e-10 * scale


@settings(max_examples=25, deadline=None)
@given(st.floats(-170.0, 170.0), st.floats(0.0, 359.0), st.booleans(),
       st.floats(-60.0, 60.0))
def test_vee_pin_hypothesis(bank2, tau, late, bank1):
    """Random banks γ1, γ2 and throw angle τ: the phases γ − τ (+ 360° for the second
    cylinder when it fires in the other revolution); the pin load in the throw's crank
    frame equals the engine-frame vector sum turned into it."""
    spec = make()
    theta = np.linspace(0.0, 720.0, 37)
    cyl = [(bank1, (bank1 - tau) % 360.0), (bank2, (bank2 - tau) % 360.0 + 360.0 * late)]
    tabs = [engine.force_table(spec, cylinder_alpha(theta, ph, 720.0)) for _, ph in cyl]
    K, T = crank_pin_load(np.stack([t["K_N"] for t in tabs]),
                          np.stack([t["T_N"] for t in tabs]),
                          [spec.m_rod_rot] * 2, spec.R, spec.omega)
    F = sum(_rod_force_engine_frame(t, g, spec) for t, (g, _) in zip(tabs, cyl))
    e = np.exp(1j * np.radians(90.0 + theta + tau))
    scale = np.max(np.abs(F))
    assert np.max(np.abs(K - (F.real * -e.real + F.imag * -e.imag))) < 1e-10 * scale
    assert np.max(np.abs(T - (F.real * -e.imag + F.imag * e.real))) < 1e-10 * scale


# ------------------------------------------------------------------ crankshaft


def _own_unit(theta, tau):
    return np.exp(1j * np.radians(90.0 + theta + tau))


@st.composite
def shafts(draw):
    n = draw(st.integers(1, 6))
    tau = draw(st.lists(st.floats(0, 359), min_size=n, max_size=n))
    spacing = draw(st.floats(0.05, 0.2))
    full = draw(st.booleans())
    z_throw = [spacing * (k + 0.5) for k in range(n)]
    if full:
        zj = [spacing * j for j in range(n + 1)]
    else:                                   # fewer journals: two throws per span
        zj = sorted({0.0, spacing * n} | {spacing * j for j in range(2, n, 2)})
    m_k = draw(st.lists(st.floats(0, 3), min_size=n, max_size=n))
    ncw = draw(st.integers(0, 2 * n))
    cw = [(draw(st.floats(0, 0.02)), draw(st.floats(-180, 180)),
           draw(st.floats(zj[0], zj[-1])), draw(st.integers(0, n - 1))) for _ in range(ncw)]
    seed = draw(st.integers(0, 2 ** 31 - 1))
    return Crankshaft(tuple(tau), tuple(z_throw), tuple(zj), tuple(m_k), tuple(cw)), seed


@settings(max_examples=40, deadline=None)
@given(shafts())
def test_crankshaft_equilibrium_force_and_moment(case):
    """Journal reactions −Q balance the pin loads, the crank masses and the counterweights,
    force and moment about an arbitrary axial point, at every angle."""
    shaft, seed = case
    rng = np.random.default_rng(seed)
    n = len(shaft.throw_angle_deg)
    theta = np.linspace(0.0, 720.0, 97)
    K = rng.normal(0, 2e4, (n, theta.size))
    T = rng.normal(0, 1e4, (n, theta.size))
    R, omega = 0.05, 400.0
    res = crankshaft_loads(theta, shaft, K, T, R, omega, 720.0)
    F, z = [], []
    for k in range(n):
        e = _own_unit(theta, shaft.throw_angle_deg[k])
        F += [e * (-K[k] + 1j * T[k]), shaft.m_crank_rot[k] * R * omega ** 2 * e]
        z += [shaft.z_throw[k]] * 2
    for mr, ang, zc, k in shaft.counterweights:
        F.append(mr * omega ** 2 * _own_unit(theta, shaft.throw_angle_deg[k] + ang))
        z.append(zc)
    F, z = np.array(F), np.array(z)
    scale = np.max(np.abs(F))
    zj = np.asarray(shaft.z_journal)
    force = F.sum(axis=0) - res.Q.sum(axis=0)
    z0 = rng.uniform(-1, 1)
    moment = ((z - z0)[:, None] * F).sum(axis=0) - ((zj - z0)[:, None] * res.Q).sum(axis=0)
    assert np.max(np.abs(force)) <= 1e-9 * scale * len(z)
    assert np.max(np.abs(moment)) <= 1e-9 * scale * len(z) * (zj[-1] - zj[0] + 2)
    # the journal table holds the same Q
    for j in range(len(zj)):
        assert np.array_equal(res.journals[f"X_{j + 1}_N"], res.Q[j].real)
        R_j = res.journals[f"R_{j + 1}_N"].to_numpy()
        assert np.allclose(np.hypot(res.journals[f"K_{j + 1}_N"], res.journals[f"T_{j + 1}_N"]),
                           R_j, rtol=1e-12, atol=1e-9 * scale)


@settings(max_examples=40, deadline=None)
@given(shafts())
def test_journal_torques_step_by_each_throw_and_end_at_the_total(case):
    shaft, seed = case
    rng = np.random.default_rng(seed)
    n = len(shaft.throw_angle_deg)
    theta = np.linspace(0.0, 720.0, 49)
    T = rng.normal(0, 1e4, (n, theta.size))
    R = 0.043
    res = crankshaft_loads(theta, shaft, np.zeros_like(T), T, R, 300.0, 720.0)
    M = np.stack([res.journal_torques[f"M_{j + 1}_Nm"] for j in range(len(shaft.z_journal))])
    assert np.all(M[0] == 0)                                   # the free end
    assert np.allclose(M[-1], R * T.sum(axis=0), rtol=1e-12, atol=1e-9)   # total
    zt, zj = np.asarray(shaft.z_throw), np.asarray(shaft.z_journal)
    for j in range(1, len(zj)):
        between = (zt > zj[j - 1]) & (zt < zj[j])
        assert np.allclose(M[j] - M[j - 1], R * T[between].sum(axis=0), atol=1e-9)


def test_inline_four_journal_torques_by_firing_phase():
    """Inline 4, flat crank, firing 1-3-4-2: throws at 0/180/180/0, phases 0, 540, 180,
    360 (cylinder k fires at its position in the firing order × 180°).  The last journal
    carries the sum of the four cylinders' T·R at their phases."""
    spec = make()
    theta = np.arange(0.0, 720.0, 1.0)
    phase = [0.0, 540.0, 180.0, 360.0]
    tabs = [engine.force_table(spec, cylinder_alpha(theta, ph, 720.0)) for ph in phase]
    shaft = Crankshaft.full_support([0.0, 180.0, 180.0, 0.0], 0.1)
    K = np.stack([t["K_N"] + t["Kr_N"] for t in tabs])
    T = np.stack([t["T_N"] for t in tabs])
    res = crankshaft_loads(theta, shaft, K, T, spec.R, spec.omega, 720.0)
    total = sum(t["M_Nm"].to_numpy() for t in tabs)
    assert np.allclose(res.journal_torques["M_5_Nm"], total, rtol=1e-12, atol=1e-9)
    # even firing: the total has period 180°
    assert np.allclose(total[:180], total[180:360], atol=1e-6 * np.max(np.abs(total)))
    swing = [np.ptp(res.journal_torques[f"M_{j}_Nm"]) for j in range(1, 6)]
    assert res.most_twisted_journal == 1 + int(np.argmax(swing))
    assert res.torque_stats[4]["max_Nm"] == pytest.approx(total.max())
    # the two halves of an inline-4's shaft: journal 3 carries cylinders 1 and 2
    assert np.allclose(res.journal_torques["M_3_Nm"],
                       tabs[0]["M_Nm"].to_numpy() + tabs[1]["M_Nm"].to_numpy())


def test_lever_rule_shares():
    F = np.array([[1000.0 + 0j], [10j]])
    Q = lever_rule(F, [0.25, 1.0], [0.0, 1.0, 2.0])
    assert Q[:, 0] == pytest.approx([750.0, 250.0 + 10j, 0.0])
    with pytest.raises(BearingInputError, match="outside the main journals"):
        lever_rule(F, [2.5, 1.0], [0.0, 1.0, 2.0])
    with pytest.raises(BearingInputError, match="strictly increasing"):
        lever_rule(F, [0.5, 1.0], [0.0, 0.0, 2.0])


def test_journal_torques_helper():
    M = journal_torques([[1.0, 2.0], [10.0, 20.0]], [0.5, 1.5], [0.0, 1.0, 2.0])
    assert M.tolist() == [[0.0, 0.0], [1.0, 2.0], [11.0, 22.0]]


def test_single_cylinder_counterweight_and_crank_mass():
    """One throw between two journals at −40 and +60 mm: the journals carry 60 % and 40 %
    of the pin load plus mк·R·ω² outwards plus the counterweight's m·r·ω² opposite."""
    d = spec_dict(bearings=dict(journal_positions_mm=[-40.0, 60.0], counterweight_kg_mm=30.0))
    spec = engine.load_spec(d)
    t = engine.force_table(spec, np.arange(0.0, 720.0, 5.0))
    res = bearing_analysis(spec, t, read_bearing_inputs(d, spec))
    a = np.radians(t["alpha_deg"].to_numpy())
    e = np.exp(1j * (np.pi / 2 + a))
    pin = e * (-(t["K_N"] + t["Kr_N"]).to_numpy() + 1j * t["T_N"].to_numpy())
    w2 = spec.omega ** 2
    total = pin + 0.8 * spec.R * w2 * e - 0.030 * w2 * e
    assert np.allclose(res.loads.Q[0], 0.6 * total, rtol=1e-12, atol=1e-6)
    assert np.allclose(res.loads.Q[1], 0.4 * total, rtol=1e-12, atol=1e-6)


# ------------------------------------------------------------------ big end, piston pin


def test_big_end_is_the_rod_force_reversed_in_the_rod_frame():
    """Along the rod the big end carries Sш + the component of Kr.ш along it; its
    magnitude is Rшш."""
    spec = make()
    t = engine.force_table(spec, np.arange(0.0, 720.0, 3.0))
    rb = rod_bearing_table(t, spec, 0.6)
    assert np.allclose(rb["Rbe_N"], t["R_N"], rtol=1e-12)
    a, b = np.radians(t["alpha_deg"]), np.radians(t["beta_deg"])
    # the big end carries Sш·e₃ (the rod compressed) + Kr.ш·e (Kr.ш < 0: the pin pulls the
    # rotating mass inwards); e·e₃ = cos(α + β)
    kr_along = t["Kr_N"] * np.cos(a + b)
    assert np.allclose(rb["Rbe_along_N"], t["S_N"] + kr_along, rtol=1e-12,
                       atol=1e-9 * t["R_N"].max())


def test_piston_pin_load_is_gas_plus_piston_inertia():
    """mп = 0.6 kg of mj = 0.6 + 0.275·0.9: the pin's axial load is ΔPг + (mп/mj)·Pj;
    with the rod's small end mass included it would be P."""
    spec = make()
    t = engine.force_table(spec, np.arange(0.0, 720.0, 3.0))
    rb = rod_bearing_table(t, spec, 0.6)
    mj = 0.6 + 0.275 * 0.9
    assert spec.mj == pytest.approx(mj)
    assert np.allclose(rb["Pp_axial_N"], t["dPg_N"] + 0.6 / mj * t["Pj_N"], rtol=1e-12,
                       atol=1e-9)
    assert np.allclose(rb["Pp_side_N"], t["N_N"])
    res = bearing_analysis(spec, t)
    assert res.m_piston == pytest.approx(0.6)


def test_direct_masses_leave_the_piston_pin_out_with_a_note():
    d = copy.deepcopy(BASE)
    d["masses"] = dict(reciprocating_kg=0.85, rod_rotating_kg=0.65)
    spec = engine.load_spec(d)
    res = bearing_analysis(spec, engine.force_table(spec))
    assert res.rod_bearings["Pp_N"].isna().all()
    assert "piston-pin" in res.notes[0]


# ------------------------------------------------------------------ spec keys


@pytest.mark.parametrize("bearings, message", [
    (dict(wear_half_angle_deg=0), "bearings.wear_half_angle_deg: got 0"),
    (dict(journal_positions_mm=[10, 50]), "either side of the crank pin"),
    (dict(journal_positions_mm=[10]), "exactly 2 numbers"),
    (dict(counterweight_kg_mm=-1), "bearings.counterweight_kg_mm: got -1"),
    (dict(oil_hole=1), "bearings.oil_hole: unknown key"),
])
def test_bad_bearing_keys_are_named(bearings, message):
    with pytest.raises(engine.EngineSpecError, match=message.replace(".", r"\.")
                       .replace("[", r"\[")):
        make(bearings=bearings)


def test_vee_rods_at_their_own_axial_positions():
    """A vee pin with the two rods offset along the pin (±b/2 about its centre): each rod
    enters the lever rule at its own z; the equilibrium holds and the journal loads differ
    from those of the pin load at the centre by the couple of the offset rods only."""
    theta = np.linspace(0.0, 720.0, 73)
    rng = np.random.default_rng(7)
    K1, T1, K2, T2 = rng.normal(0, 1e4, (4, theta.size))
    shaft = Crankshaft((0.0,), (0.06,), (0.0, 0.12), (1.0,))
    R, w = 0.045, 500.0
    off = 0.012
    res = crankshaft_loads(theta, shaft, [K1 + K2], [T1 + T2], R, w, 720.0,
                           rod_z=[[(K1, T1, 0.06 - off), (K2, T2, 0.06 + off)]])
    cen = crankshaft_loads(theta, shaft, [K1 + K2], [T1 + T2], R, w, 720.0)
    e = _own_unit(theta, 0.0)
    F1, F2 = e * (-K1 + 1j * T1), e * (-K2 + 1j * T2)
    couple = off * (F2 - F1) / 0.12          # the offset rods' extra moment, shared out
    assert np.allclose(res.Q[1] - cen.Q[1], couple, atol=1e-9 * np.abs(F1).max())
    assert np.allclose(res.Q[0] - cen.Q[0], -couple, atol=1e-9 * np.abs(F1).max())
    assert np.allclose(res.Q.sum(axis=0), cen.Q.sum(axis=0))
