"""The coupling of the torsion physics with crankdyn's engine (torsion.engine_chain):
one cylinder's torque split into gas and inertia, its harmonics against the engine's own
numbers and against the closed form in λ, the throws' inertia, the throws and phases of
the bundled inline-4, inline-6 and V8, their major orders."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import engine
from crankbase.resources import example_path
from engine.train import layout
from torsion.chain import damping_matrix, natural_modes
from torsion.engine_chain import (cylinder_excitation, cylinder_throws,
                                  cylinder_torque_parts, throw_inertia)
from torsion.harmonics import inertia_torque_closed_form
from torsion.response import critical_speeds, forced_response


@pytest.fixture(scope="module")
def vaz():
    return engine.load(example_path("petrol_vaz2106.toml"))


@pytest.fixture(scope="module")
def v8():
    return engine.load(example_path("diesel_kamaz740.toml"))


def test_gas_and_inertia_parts_make_the_total(vaz):
    spec = vaz.spec
    alpha, gas, inertia, total = cylinder_torque_parts(spec, step_deg=1.0)
    assert alpha[0] == 0 and alpha[-1] == 719 and len(alpha) == 720
    np.testing.assert_allclose(gas + inertia, total, atol=1e-9 * np.abs(total).max())
    t = engine.force_table(spec, alpha)
    np.testing.assert_allclose(total, t["M_Nm"])
    # T is linear in P at each α: the gas part is ΔPг·R·sin(α+β)/cos β (Колчин & Демидов,
    # Table 2: T = P·sin(φ+β)/cos β), the inertia part Pj times the same lever
    a, b = np.radians(t["alpha_deg"]), np.radians(t["beta_deg"])
    lever = spec.R * np.sin(a + b) / np.cos(b)
    np.testing.assert_allclose(gas, lever * t["dPg_N"], atol=1e-9 * np.abs(total).max())
    np.testing.assert_allclose(inertia, lever * t["Pj_N"], atol=1e-9 * np.abs(total).max())


def test_mean_torque_is_order_zero_and_the_engines_mean(vaz, v8):
    for study in (vaz, v8):
        spec = study.spec
        h = cylinder_excitation(spec, orders_max=12, step_deg=0.5)
        summary = engine.analyze(spec).summary
        assert h["total"].mean_Nm == pytest.approx(summary.M_mean_Nm, rel=1e-6)
        assert h["total"].a_Nm[0] == h["total"].mean_Nm
        # Pj alone does no work over a cycle (domain brief § 5)
        assert abs(h["inertia"].mean_Nm) < 1e-9 * h["inertia"].amplitude_Nm.max()
        assert h["gas"].mean_Nm == pytest.approx(summary.M_mean_Nm, rel=1e-6)
        # four-stroke: half orders 0, 0.5 … 12
        np.testing.assert_allclose(h["total"].order, np.arange(25) * 0.5)
        # the series up to order 12 reconstructs Mкр to a small part of its rms
        assert h["total"].reconstruction_rms_Nm < 0.05 * h["total"].rms_Nm


def test_inertia_harmonics_match_the_closed_form_in_lambda(vaz):
    """Mj/(mj R² ω²) ≈ (λ/4) sin α − (1/2) sin 2α − (3λ/4) sin 3α − (λ²/4) sin 4α (domain
    brief § 7; Den Hartog § 5.6): to the λ³ terms the closed form drops."""
    spec = vaz.spec
    h = cylinder_excitation(spec, orders_max=8, step_deg=0.5)["inertia"]
    scale = spec.mj * spec.R ** 2 * spec.omega ** 2
    lam = spec.lam
    i = {float(o): j for j, o in enumerate(h.order)}
    expected_b = {1.0: lam / 4, 2.0: -0.5, 3.0: -0.75 * lam, 4.0: -lam ** 2 / 4}
    for order, b in expected_b.items():
        assert h.b_Nm[i[order]] / scale == pytest.approx(b, abs=0.15 * lam ** 3)
    # orders above 4 are of order λ³ and smaller
    for order in (5.0, 6.0, 7.0, 8.0):
        assert h.amplitude_Nm[i[order]] / scale < 0.1 * lam ** 3
    # the inertia torque is odd in α: no cosine terms; it repeats every turn: no half orders
    assert np.max(np.abs(h.a_Nm)) < 1e-9 * scale
    half = np.array([o % 1 == 0.5 for o in h.order])
    assert np.max(h.amplitude_Nm[half]) < 1e-9 * scale
    # and the closed form as a function, against the force table's inertia torque
    alpha, _, inertia, _ = cylinder_torque_parts(spec, step_deg=1.0)
    closed = inertia_torque_closed_form(alpha, spec.mj, spec.R, spec.omega, lam)
    assert np.max(np.abs(closed - inertia)) < lam ** 3 * scale


def test_inertia_scales_with_speed_squared_gas_does_not():
    study = engine.load(example_path("diesel_d240.toml"))          # indicator diagram from a file
    spec = study.spec
    fast = dataclasses.replace(spec, speed_rpm=2 * spec.speed_rpm)
    h1, h2 = cylinder_excitation(spec), cylinder_excitation(fast)
    np.testing.assert_allclose(h2["inertia"].complex_Nm, 4 * h1["inertia"].complex_Nm,
                               rtol=1e-9, atol=1e-9 * h1["inertia"].amplitude_Nm.max())
    np.testing.assert_allclose(h2["gas"].complex_Nm, h1["gas"].complex_Nm,
                               atol=1e-9 * h1["gas"].amplitude_Nm.max())


def test_throw_inertia_formula(vaz):
    spec = vaz.spec
    R, lam = spec.R, spec.lam
    one = throw_inertia(spec, 0.012)
    assert one == pytest.approx(0.012 + (spec.m_rod_rot + spec.mj * (0.5 + lam ** 2 / 8))
                                * R ** 2, rel=1e-14)
    # the reciprocating mean equals the mean of mj·(dx/dα)² with x to the λ term
    a = np.radians(np.arange(0, 360, 0.25))
    dx = R * (np.sin(a) + lam / 2 * np.sin(2 * a))
    assert spec.mj * np.mean(dx ** 2) == pytest.approx(
        spec.mj * R ** 2 * (0.5 + lam ** 2 / 8), rel=1e-12)
    two = throw_inertia(spec, 0.012, cylinders_per_throw=2)
    assert two - 0.012 == pytest.approx(2 * (one - 0.012), rel=1e-14)


@pytest.mark.parametrize("example, majors", [
    ("petrol_vaz2106.toml", [2.0, 4.0, 6.0, 8.0, 10.0, 12.0]),      # inline-4
    ("petrol_bmw_m54.toml", [3.0, 6.0, 9.0, 12.0]),                 # inline-6
    ("diesel_kamaz740.toml", [4.0, 8.0, 12.0]),                     # V8, i/2 = 4
])
def test_major_orders_of_the_bundled_engines(example, majors):
    study = engine.load(example_path(example))
    lay = layout(study.spec, study.train)
    throws, phases = cylinder_throws(lay)
    np.testing.assert_array_equal(throws, lay.throw_of)
    np.testing.assert_allclose(phases, lay.phase_deg)
    n_throws = int(throws.max()) + 1
    J = [0.1] + [0.02] * n_throws + [1.0]
    k = [5e5] * (n_throws + 1)
    m = natural_modes(J, k)
    orders = np.arange(1, 25) * 0.5
    cs = critical_speeds(m, throws + 1, phases, orders, (1.0, 1e7), lay.n, lay.cycle_deg)
    got = sorted(set(cs.loc[cs["major"], "order"]))
    assert got == majors
    # a major order's vector sum is the plain sum of the throws' amplitudes
    row = cs[cs["major"]].iloc[0]
    assert row["sum_relative_amplitude"] == pytest.approx(
        abs(m.shapes[int(row["mode"]) - 1, throws + 1].sum()))


def test_v8_response_runs_and_peaks_near_a_major_critical(v8):
    spec, train = v8.spec, v8.train
    lay = layout(spec, train)
    throws, phases = cylinder_throws(lay)
    Jt = throw_inertia(spec, 0.012, cylinders_per_throw=2)
    J = [0.08] + [Jt] * 4 + [1.2]
    k = [2.1e6, 1.8e6, 1.8e6, 1.8e6, 1.5e6]
    m = natural_modes(J, k)
    C = damping_matrix(J, m, 0.02)
    h = cylinder_excitation(spec, orders_max=12)
    speeds = np.arange(600.0, 6001.0, 10.0)
    r = forced_response(J, k, C, throws + 1, phases, h["gas"], h["inertia"],
                        spec.speed_rpm, speeds)
    assert r.amplitude_deg.shape == (len(speeds), 6) and r.torque_Nm.shape == (len(speeds), 5)
    cs = critical_speeds(m, throws + 1, phases, h["total"].order, (600, 6000), 8, 720)
    # the largest vibration torque lies at a critical speed (within the 10 rpm step and
    # the damped peak's shift)
    assert np.min(np.abs(cs["speed_rpm"] - r.worst[0])) < 0.02 * r.worst[0]


def test_excitation_phases_follow_the_engines_cylinder_torques(v8):
    """The torque each throw's mass gets, synthesised from one cylinder's harmonics with
    each cylinder's phase (M_k e^{−ikφ_j}), is the sum of the force tables of its
    cylinders at α = θ − φ_j (engine.force_table(phase_deg=φ_j)): a wrong sign of the
    phase or a swapped cylinder shows here."""
    from torsion.response import excitation_vectors

    spec = v8.spec
    lay = layout(spec, v8.train)
    throws, phases = cylinder_throws(lay)
    h = cylinder_excitation(spec, orders_max=200, step_deg=0.25)["total"]
    F = excitation_vectors(4, throws, phases, h.complex_Nm, h.order)       # (K, 4)
    theta = np.arange(0.0, 720.0, 5.0)
    series = np.real(np.exp(1j * np.radians(np.multiply.outer(theta, h.order))) @ F)
    direct = np.zeros((len(theta), 4))
    for t, p in zip(throws, phases):
        direct[:, t] += engine.force_table(spec, theta, phase_deg=p)["M_Nm"].to_numpy()
    scale = np.abs(direct).max()
    assert np.max(np.abs(series - direct)) < 2e-3 * scale
    # and with the phase's sign turned the wrong way round it would not be
    Fw = excitation_vectors(4, throws, -phases, h.complex_Nm, h.order)
    wrong = np.real(np.exp(1j * np.radians(np.multiply.outer(theta, h.order))) @ Fw)
    assert np.max(np.abs(wrong - direct)) > 0.1 * scale
