"""The rigid connecting rod (engine.rodmodel): against the two-mass table when its J is
the two-mass one, and against the independent Newton–Euler solve of tests/newton_euler.py
(one global linear system per position, no linkage code)."""
import copy

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine
from engine.bearings.analysis import read_bearing_inputs
from engine.rodmodel import RigidRod, compare_rod_models, rigid_rod_forces
from newton_euler import reference

BASE = {
    "engine": dict(name="rod", bore_mm=92.0, stroke_mm=86.0, rod_length_mm=150.0,
                   speed_rpm=5600.0, crankcase_MPa=0.1, acceleration="exact"),
    "masses": dict(piston_group_kg=0.62, rod_kg=0.88, rod_small_end_fraction=0.28),
    "pressure": {"cycle": dict(kind="otto", compression_ratio=9.5, pa_MPa=0.085,
                               pr_MPa=0.115, n1=1.37, n2=1.25, pz_MPa=6.5)},
    "table": dict(step_deg=2.0, force_scale_N_per_mm=100.0),
}


def make(rod=None, **engine_keys):
    d = copy.deepcopy(BASE)
    d["engine"].update(engine_keys)
    if rod is not None:
        d["rod"] = rod
    return engine.load_spec(d)


def rod_options(rod):
    """(model, RigidRod) of a [rod] table on BASE, as the CLI reads them."""
    d = copy.deepcopy(BASE)
    d["rod"] = rod
    spec = engine.load_spec(d)
    inp = read_bearing_inputs(d, spec)
    return inp.rod_model, inp.rod


def test_two_mass_inertia_reproduces_the_table():
    """J = mш.п·a² + mш.к·b² = m·a·b (centre of mass at b = 0.28·L from the crank pin):
    the rigid rod and the two-mass table agree to round-off, exact acceleration."""
    L, m, f = 0.150, 0.88, 0.28
    b = f * L
    J2 = 0.28 * m * (L - b) ** 2 + (1 - f) * m * b ** 2
    assert J2 == pytest.approx(m * b * (L - b))
    spec = make(rod=dict(model="rigid", inertia_kg_m2=J2))
    model, rod = rod_options(dict(model="rigid", inertia_kg_m2=J2))
    assert model == "rigid"
    assert (rod.mass, rod.cg, rod.m_piston) == pytest.approx((m, b, 0.62))
    cmp_ = compare_rod_models(spec, rod)
    t = cmp_.table
    scale = t["R_2m_N"].abs().max()
    for col in ("dK_N", "dT_N", "dR_N"):
        assert t[col].abs().max() < 1e-9 * scale, col
    assert t["dM_Nm"].abs().max() < 1e-9 * scale * spec.R
    assert cmp_.J_two_mass == pytest.approx(J2)


def test_real_inertia_differs_and_only_through_J():
    """A rod whose J differs from m·a·b (a real rod's is usually smaller, the two-mass
    model overstating it; here 25 % larger, the formula holds for either sign): the
    torque and the pin load change; at TDC and BDC the rod's ε is extreme and its centre of mass moves the
    same in both models, so the difference is J's extra inertia couple −ΔJ·ε₃ alone."""
    L, m, b = 0.150, 0.88, 0.28 * 0.150
    J2 = m * b * (L - b)
    spec = make(rod=dict(model="rigid", inertia_kg_m2=1.25 * J2))
    _, rod = rod_options(dict(model="rigid", inertia_kg_m2=1.25 * J2))
    c = compare_rod_models(spec, rod)
    assert c.table["dT_N"].abs().max() > 1.0
    # on the cylinder axis (α = 0, 180°) the couple −ΔJ·ε₃ is balanced by a pair of forces
    # across the rod at A and B, so at the crank pin it adds ±ΔJ·ε₃/L along T only
    from engine.kinematics import crank_slider
    mech = crank_slider(np.radians([0.0, 180.0]), spec.R, spec.L, spec.omega)
    eps3 = mech.dyad.link3.eps
    dJ = 0.25 * J2
    row = c.table.set_index("alpha_deg")
    # moments about B: L·R23x = ΔJ·ε₃; T is + along −x at α = 0 and along +x at 180°
    expected = np.array([dJ * eps3[0] / spec.L, -dJ * eps3[1] / spec.L])
    assert row.loc[[0.0, 180.0], "dT_N"].to_numpy() == pytest.approx(expected, rel=1e-9)


def _ne_case(spec, rod, alpha_deg, dPg):
    data = {
        "mechanism": dict(kind="crank-slider", crank=spec.R, coupler=spec.L,
                          ground_angle_deg=90.0, offset=0.0, assembly=1,
                          omega_rad_s=spec.omega, gravity_m_s2=0.0),
        "links": {"coupler": dict(mass_kg=rod.mass, inertia_kg_m2=rod.inertia,
                                  cg=[rod.cg, 0.0]),
                  "slider": dict(mass_kg=rod.m_piston)},
        "load": [dict(link="slider", force_N=[0.0, -dPg], at=[0.0, 0.0])],
    }
    return reference(data, [90.0 + alpha_deg])


@settings(max_examples=15, deadline=None)
@given(st.floats(0.8, 1.6), st.floats(0.15, 0.45))
def test_rigid_rod_against_newton_euler(j_factor, f_cg):
    """Random J and centre of mass: K, T, Mкр and the side force from the dyad path equal
    the global Newton–Euler solve (one position at a time, as the reference is written
    for constant loads)."""
    spec = make()
    L = spec.L
    m = 0.88
    b = f_cg * L
    rod = RigidRod(m, b, j_factor * m * b * (L - b), 0.62)
    alpha = np.array([0.0, 17.0, 95.0, 180.0, 222.0, 365.0, 371.5, 540.0, 700.0])
    t = engine.force_table(spec, alpha)
    got = rigid_rod_forces(alpha, spec.R, L, spec.omega, t["dPg_N"].to_numpy(), rod)
    for i, a in enumerate(alpha):
        ref = _ne_case(spec, rod, a, float(t["dPg_N"].iloc[i]))
        R32 = -(ref["R23_x_N"][0] + 1j * ref["R23_y_N"][0])
        e2 = np.exp(1j * np.radians(90.0 + a))
        K = -(R32.real * e2.real + R32.imag * e2.imag)
        T = R32.real * (1j * e2).real + R32.imag * (1j * e2).imag
        scale = max(abs(R32), 1.0)
        assert got["K"][i] == pytest.approx(K, abs=1e-9 * scale)
        assert got["T"][i] == pytest.approx(T, abs=1e-9 * scale)
        assert got["M"][i] == pytest.approx(-ref["M_drive_Nm"][0], abs=1e-9 * scale * spec.R)
        assert got["N"][i] == pytest.approx(ref["N14_N"][0], abs=1e-9 * scale)


@pytest.mark.parametrize("rod, message", [
    (dict(model="rigid"), "rod.inertia_kg_m2: missing"),
    (dict(model="rigid", inertia_kg_m2=-1), "rod.inertia_kg_m2: got -1"),
    (dict(model="stiff"), "rod.model: got 'stiff'"),
    (dict(model="two-mass", inertia_kg_m2=0.002), 'only used with model = "rigid"'),
    (dict(model="rigid", inertia_kg_m2=0.002, cg_from_big_end_mm=150.0),
     "rod.cg_from_big_end_mm: got 150"),
    (dict(model="rigid", inertia_kg_m2=0.002, colour=1), "rod.colour: unknown key"),
])
def test_bad_rod_keys_are_named(rod, message):
    with pytest.raises(engine.EngineSpecError, match=message.replace(".", r"\.")):
        rod_options(rod)


def test_direct_masses_need_the_rod_mass():
    d = copy.deepcopy(BASE)
    d["masses"] = dict(reciprocating_kg=0.87, rod_rotating_kg=0.63)
    d["rod"] = dict(model="rigid", inertia_kg_m2=0.003)
    # the keys are fine; the rod needs its mass: a problem of the file, reported by the
    # one load (the study carries the rod), and by read_bearing_inputs for a given spec
    with pytest.raises(engine.EngineSpecError, match="rod.mass_kg: missing"):
        engine.load(d)
    spec = engine.load_spec({k: v for k, v in d.items() if k != "rod"})
    with pytest.raises(engine.EngineSpecError, match="rod.mass_kg: missing"):
        read_bearing_inputs(d, spec)
    d["rod"]["mass_kg"] = 0.88          # mш.п = 0.25, mп = 0.87 − 0.25
    rod = read_bearing_inputs(d, engine.load_spec(d)).rod
    assert rod.m_piston == pytest.approx(0.62)
    assert rod.cg == pytest.approx(0.150 * 0.25 / 0.88)
    assert engine.load(d).bearings.rod == rod
    d["rod"]["mass_kg"] = 2.0           # mш.п = 1.37 > mj
    with pytest.raises(engine.EngineSpecError, match="would be negative"):
        engine.load(d)
    with pytest.raises(engine.EngineSpecError, match="would be negative"):
        read_bearing_inputs(d, spec)


def test_rod_key_problems_come_with_the_engine_problems():
    """engine.load reports a bad [rod] key together with the other problems of the file."""
    d = copy.deepcopy(BASE)
    d["rod"] = dict(model="rigid", inertia_kg_m2=-1.0)
    d["engine"]["bore_mm"] = -5.0
    with pytest.raises(engine.EngineSpecError) as exc:
        engine.load_spec(d)
    text = str(exc.value)
    assert "engine.bore_mm" in text and "rod.inertia_kg_m2: got -1" in text


@pytest.mark.parametrize("offset_mm", [4.0, 9.0])
def test_two_mass_inertia_reproduces_the_table_with_a_pin_offset(offset_mm):
    """The same with a désaxé piston pin: the rigid rod runs on the dyad's own guide."""
    L, m, f = 0.150, 0.88, 0.28
    b = f * L
    d = copy.deepcopy(BASE)
    d["engine"]["pin_offset_mm"] = offset_mm
    d["rod"] = dict(model="rigid", inertia_kg_m2=m * b * (L - b))
    spec = engine.load_spec(d)
    c = compare_rod_models(spec, read_bearing_inputs(d, spec).rod,
                           np.arange(0.0, 720.0, 3.0))
    scale = c.table["R_2m_N"].abs().max()
    for col in ("dK_N", "dT_N", "dR_N"):
        assert c.table[col].abs().max() < 1e-9 * scale, col
    # and the offset matters: the central engine's T differs
    central = compare_rod_models(make(rod=d["rod"]), read_bearing_inputs(d, spec).rod,
                                 np.arange(0.0, 720.0, 3.0))
    assert np.abs(central.table["T_2m_N"] - c.table["T_2m_N"]).max() > 1.0
