"""The reduced model of a linkage against the core (linkage.analyze): J_red = 2·KE/ω² from
the core's own velocities, dJ_red/dφ by numerical differentiation, the virtual-power
balance with variable ω (the core's balancing moment under the true motion equals the
applied driving moment minus the flywheel's J_F·ε), the constant-speed limit; hypothesis
over random crank-rockers and crank-sliders (the strategies of test_linkage_properties)."""
import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given

import crankbase.validation
import linkage
from crankbase.resources import example_path
from dynamics.motion import size_flywheel, steady_motion, true_motion_forces
from dynamics.reduced import linkage_model
from test_linkage_properties import SETTINGS, mechanisms


def kinetic_energy_from_core(spec, phi_deg):
    """2·KE/ω² from the core's kinematics table at the spec's own ω (independent of the
    reduction code: it reads the analyze() columns)."""
    res = linkage.analyze(spec, crank_angles_deg=phi_deg, course_tables=False)
    np.testing.assert_allclose(res.kinematics["phi_deg"].to_numpy(), phi_deg, rtol=0,
                               atol=1e-9)                 # one row per angle, in order
    k = res.kinematics
    w = spec.omega
    ke = 0.0
    omegas = {"crank": np.full(len(k), w), "coupler": k["omega3_rad_s"].to_numpy(),
              "rocker": k["omega4_rad_s"].to_numpy() if "omega4_rad_s" in k else None,
              "slider": np.zeros(len(k))}
    for lname in spec.link_names:
        ls = spec.links[lname]
        i = linkage.spec.LINK_NUMBER[lname]
        vx, vy = k[f"S{i}_vx_m_s"].to_numpy(), k[f"S{i}_vy_m_s"].to_numpy()
        ke = ke + 0.5 * ls.mass * (vx ** 2 + vy ** 2) + 0.5 * ls.inertia * omegas[lname] ** 2
    return 2 * ke / w ** 2


def _check_model(spec, steps=720):
    model = linkage_model(spec, steps=steps)
    # the core's 2·KE/ω² at the model's angles and at ±h (h = 1e-4°), in one analysis
    # (each angle's row is computed on its own: the same numbers as three analyses)
    h = 1e-4
    n = len(model.phi_deg)
    J_core, J_plus, J_minus = np.split(kinetic_energy_from_core(spec, np.concatenate(
        [model.phi_deg, model.phi_deg + h, model.phi_deg - h])), [n, 2 * n])
    scale = max(np.max(np.abs(J_core)), 1e-12)
    assert np.max(np.abs(model.J_kgm2 - J_core)) <= 1e-9 * scale
    # dJ/dφ against a central difference of the core's 2·KE/ω², in the direction of
    # rotation
    dJ_num = (J_plus - J_minus) / (2 * math.radians(h))
    dJ_num *= model.rotation
    dscale = max(np.max(np.abs(model.dJ_dphi_kgm2)), 1e-6 * scale)
    assert np.max(np.abs(dJ_num - model.dJ_dphi_kgm2)) <= 1e-5 * dscale + 1e-8 * scale
    return model


def _true_motion_power_balance(model):
    W = model.with_constant_drive()[0].W_net_J
    wm = model.omega_nominal
    JF = 10 * np.ptp(W) / wm ** 2 + 1e-3 * max(model.J_kgm2.max(), 1e-9)
    r = steady_motion(model, J_flywheel=JF)
    f = true_motion_forces(model, r)
    Md = r.table["M_drive_Nm"].to_numpy()
    eps = r.table["eps_rad_s2"].to_numpy()
    expect = model.rotation * (Md - JF * eps)   # the core's moments are + ccw
    scale = max(np.max(np.abs(Md)), np.max(np.abs(f["M_drive_Nm_const"])), 1.0)
    assert np.max(np.abs(f["M_drive_Nm"].to_numpy() - expect)) <= 1e-8 * scale
    return r, f


@pytest.mark.parametrize("name", ["press.toml", "ratchet.toml"])
def test_examples_identities(name):
    spec = linkage.load_spec(example_path(name))
    model = _check_model(spec)
    _true_motion_power_balance(model)


def test_resisting_moment_parts():
    """M_c = (applied loads and useful resistance) + (weights); the weights' part is the
    derivative of the potential energy Σ m g y_S (zero work over a turn)."""
    spec = linkage.load_spec(example_path("press.toml"))
    m = linkage_model(spec, steps=1440)
    lo, we = m.extra["M_resist_loads_Nm"], m.extra["M_resist_weights_Nm"]
    assert np.allclose(lo + we, m.M_resist_Nm, rtol=0, atol=1e-12 * np.abs(m.M_resist_Nm).max())
    res = linkage.analyze(spec, crank_angles_deg=m.phi_deg, course_tables=False).kinematics
    V = sum(spec.links[n].mass * spec.gravity * res[f"S{i}_y_m"].to_numpy()
            for n, i in (("crank", 2), ("coupler", 3), ("slider", 4)))
    dV = np.gradient(V, m.phi, edge_order=2)
    assert np.max(np.abs(dV - we)) < 1e-4 * np.max(np.abs(we))
    assert np.sum(0.5 * (we[1:] + we[:-1]) * np.diff(m.phi)) == pytest.approx(0, abs=1e-9 * np.ptp(V) + 1e-9)
    assert np.all(lo >= -1e-9)   # the press's only load is the resistance


def test_reduced_resistance_is_the_core_constant_speed_moment():
    """At constant speed without masses the core's balancing moment is the reduced
    resisting moment (virtual work), position by position."""
    data = crankbase.validation.read_toml(example_path("press.toml"))[0]
    for t in data["links"].values():
        t["mass_kg"] = 0.0
        t.pop("inertia_kg_m2", None)
    spec = linkage.load_spec(data)
    model = linkage_model(spec, steps=360)
    res = linkage.analyze(spec, crank_angles_deg=model.phi_deg, course_tables=False)
    assert np.max(np.abs(res.forces["M_drive_Nm"].to_numpy() - model.M_resist_Nm)) < 1e-9 * 1e3


def test_huge_flywheel_gives_the_constant_speed_forces():
    spec = linkage.load_spec(example_path("press.toml"))
    model = linkage_model(spec)
    r = steady_motion(model, J_flywheel=1e9)
    assert r.delta < 1e-7
    f = true_motion_forces(model, r)
    for c in ("R12_x_N", "R23_y_N", "R14_x_N", "M_drive_Nm"):
        scale = np.max(np.abs(f[f"{c}_const"]))
        assert np.max(np.abs(f[c] - f[f"{c}_const"])) < 1e-4 * scale


def test_exact_flywheel_reaches_delta_for_a_linkage():
    spec = linkage.load_spec(example_path("press.toml"))
    model = linkage_model(spec)
    fw = size_flywheel(model, 0.03)
    assert fw.motion.delta == pytest.approx(0.03, rel=1e-6)
    assert fw.J_exact > 0 and fw.J_classic > 0
    # the classic estimate treats J_red as constant; here it differs by under 10 %
    assert fw.J_exact == pytest.approx(fw.J_classic, rel=0.1)


@SETTINGS
@given(mechanisms)
def test_random_mechanisms(data):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            spec = linkage.load_spec(data)
            model = _check_model(spec, steps=360)
    except linkage.AssemblyError:
        assume(False)
    assume(np.all(np.isfinite(model.J_kgm2)) and model.J_kgm2.min() > 1e-9)
    _true_motion_power_balance(model)


@pytest.mark.parametrize("name", ["press.toml", "ratchet.toml"])
def test_linkage_forces_equal_the_core_table_at_constant_speed(name):
    """dynamics.motion.linkage_forces (the core's routines with ω, ε per position) at a
    constant ω and ε gives the core's own force table (linkage.analysis.solve_columns)."""
    from linkage.analysis import solve_columns

    from dynamics.motion import linkage_forces

    spec = linkage.load_spec(example_path(name))
    phi = np.radians(np.arange(0.0, 360.0, 2.5))
    mech = linkage.analysis.build_mechanism(spec)
    from dynamics.reduced import stroke_extremes

    ext = stroke_extremes(spec, mech)
    ours = linkage_forces(spec, phi, spec.omega, spec.epsilon, mech, ext)
    _, core = solve_columns(spec, phi, mech, ext, course_tables=False)
    for c, v in ours.items():
        scale = max(np.max(np.abs(core[c])), 1.0)
        assert np.max(np.abs(v - core[c])) <= 1e-12 * scale, c
    # and with arrays equal to that constant, the same numbers
    arr = linkage_forces(spec, phi, np.full_like(phi, spec.omega),
                         np.full_like(phi, spec.epsilon), mech, ext)
    for c in ours:
        assert np.array_equal(arr[c], ours[c]), c
