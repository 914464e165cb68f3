"""The torsion physics on plain arrays (torsion.chain, torsion.harmonics, torsion.response):
published worked examples, identities, random chains against each other and against
openTorsion, and one clear error for each bad input."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from crankbase.errors import SpecError
from torsion.chain import (damping_matrix, holzer_residual, holzer_table, natural_modes,
                           shaft_stiffness, stiffness_matrix)
from torsion.harmonics import torque_harmonics
from torsion.response import (critical_speeds, forced_response, harmonic_solve,
                              is_major)
from torsion.results import Harmonics

# --------------------------------------------------------------------------------------
# Published worked examples
# --------------------------------------------------------------------------------------
# Three-rotor system of R. S. Khurmi & J. K. Gupta, "Theory of Machines", ch. "Torsional
# Vibrations" (single-cylinder oil engine driving a generator; C = 84 kN/mm²): rotors
# 0.15, 0.3, 0.09 kg·m², shaft 70 mm in diameter, 2.5 m long, the middle rotor 1.5 m
# from the first.  Printed: single-node f = 171 Hz, node 1.146 m from rotor A; two-node
# f = 277 Hz, nodes 0.4356 m from A and 0.726 m from C.  (Numbers as reproduced in the
# worked answers at qna.carrieradda.com/26013 and /26108; the book's page was not seen.)
KHURMI_J = [0.15, 0.3, 0.09]
KHURMI_L = [1.5, 1.0]


def khurmi_chain():
    return KHURMI_J, [shaft_stiffness(84e9, 0.070, length) for length in KHURMI_L]


def test_khurmi_three_rotor_frequencies_and_nodes():
    J, k = khurmi_chain()
    m = natural_modes(J, k)
    assert m.count == 2
    assert round(m.f_Hz[0]) == 171                       # printed 171 Hz
    assert round(m.f_Hz[1]) == 277                       # printed 277 Hz
    # nodes in mass units → metres along the shaft from rotor A
    (n1,), (n2a, n2b) = m.nodes
    assert (n1 - 1) * KHURMI_L[0] == pytest.approx(1.146, abs=2e-3)   # printed 1.146 m
    assert (n2a - 1) * KHURMI_L[0] == pytest.approx(0.4356, abs=1e-4)  # printed 0.4356 m
    assert (3 - n2b) * KHURMI_L[1] == pytest.approx(0.726, abs=5e-4)   # from C: 0.726 m
    # the one-node mode has its node in section 1, the two-node mode one in each section
    assert 1 < n1 < 2 and 1 < n2a < 2 < n2b < 3


def test_khurmi_holzer_residual_brackets_the_printed_frequencies():
    """The printed frequencies (to 1 Hz) each lie in a sign change of Holzer's residual
    torque, as a course's trial tables close on them."""
    J, k = khurmi_chain()
    for f in (171.0, 277.0):
        lo, hi = holzer_residual(J, k, 2 * np.pi * np.array([f - 0.5, f + 0.5]))
        assert lo * hi < 0


def test_two_rotor_closed_form():
    """Two rotors on a shaft: ω² = k(J1 + J2)/(J1 J2), the node at J2/(J1 + J2) of the
    shaft from rotor 1, amplitude ratio θ2/θ1 = −J1/J2 (Thomson § 5.1; Den Hartog § 5.2)."""
    J1, J2, k = 75.0, 50.0, 3.1e6
    m = natural_modes([J1, J2], [k])
    assert m.omega_rad_s[0] ** 2 == pytest.approx(k * (J1 + J2) / (J1 * J2), rel=1e-12)
    assert m.shapes[0, 1] == pytest.approx(-J1 / J2, rel=1e-12)
    assert m.nodes[0][0] == pytest.approx(1 + J2 / (J1 + J2), rel=1e-12)


def test_equal_three_rotor_closed_form():
    """Three equal discs J and equal shafts k: ω² = 0, k/J, 3k/J, shapes (1, 0, −1) and
    (1, −2, 1) (Thomson ch. 6, the semi-definite system)."""
    m = natural_modes([2.0, 2.0, 2.0], [50.0, 50.0])
    np.testing.assert_allclose(m.omega_rad_s ** 2, [25.0, 75.0], rtol=1e-12)
    np.testing.assert_allclose(m.shapes, [[1, 0, -1], [1, -2, 1]], atol=1e-12)
    # the one-node mode's node sits exactly at the middle mass
    np.testing.assert_allclose(m.nodes[0], [2.0])
    np.testing.assert_allclose(m.nodes[1], [4 / 3, 8 / 3])     # 1 → −2: a third of the way


def test_holzer_table_by_hand():
    """Two discs 1 and 2 kg·m² on k = 300 at ω = 10: θ = 1, 1 − 100/300; J ω² θ = 100,
    200·(2/3); residual 100 + 133.33 (ω² = 150 is natural: k(J1+J2)/(J1J2) = 450/2…)."""
    t = holzer_table([1.0, 2.0], [300.0], 10.0, names=["A", "B"])
    assert list(t.columns) == ["omega_rad_s", "mass", "J_kgm2", "theta_rad",
                               "inertia_torque_Nm", "sum_torque_Nm", "k_Nm_rad",
                               "twist_rad"]
    assert t["mass"].tolist() == ["A", "B"]
    np.testing.assert_allclose(t["theta_rad"], [1.0, 2.0 / 3.0])
    np.testing.assert_allclose(t["inertia_torque_Nm"], [100.0, 400.0 / 3.0])
    np.testing.assert_allclose(t["sum_torque_Nm"], [100.0, 700.0 / 3.0])
    assert t["k_Nm_rad"].iloc[0] == 300.0 and math.isnan(t["k_Nm_rad"].iloc[1])
    assert t["twist_rad"].iloc[0] == pytest.approx(1.0 / 3.0)
    # at the natural ω² = k(J1 + J2)/(J1 J2) = 450 the residual vanishes
    assert holzer_residual([1.0, 2.0], [300.0], math.sqrt(450.0)) == pytest.approx(
        0.0, abs=1e-10)
    # stacked tables: one block of n rows per ω
    t2 = holzer_table([1.0, 2.0], [300.0], [10.0, 20.0])
    assert t2["omega_rad_s"].tolist() == [10.0, 10.0, 20.0, 20.0]


def test_shaft_stiffness():
    # k = G·π d⁴/(32 l): 84 GPa, 70 mm, 1.5 m → 1.3200e5 N·m/rad (Ip = 2.357e-6 m⁴)
    assert shaft_stiffness(84e9, 0.07, 1.5) == pytest.approx(
        84e9 * math.pi * 0.07 ** 4 / 32 / 1.5, rel=1e-15)
    assert shaft_stiffness(84e9, 0.07, 1.5) == pytest.approx(1.3200e5, rel=1e-4)


# --------------------------------------------------------------------------------------
# Random chains: identities, eigen vs Holzer, forced response vs modal sum
# --------------------------------------------------------------------------------------
def chains(min_n=2, max_n=12):
    """Random chains with J over 3 decades and k over 4."""
    return st.integers(min_n, max_n).flatmap(lambda n: st.tuples(
        st.lists(st.floats(-2.0, 1.0), min_size=n, max_size=n),
        st.lists(st.floats(3.0, 7.0), min_size=n - 1, max_size=n - 1)).map(
        lambda t: (10.0 ** np.array(t[0]), 10.0 ** np.array(t[1]))))


SETTINGS = settings(max_examples=60, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(chains())
def test_modes_identities(chain):
    J, k = chain
    m = natural_modes(J, k)
    n = len(J)
    assert m.count == n - 1 and np.all(np.diff(m.omega_rad_s) > 0)
    # one zero frequency: the rigid one, zero to round-off (√(ε·λmax) ≈ 1.5e-8 ω_max)
    assert m.rigid_omega_rad_s < 1e-6 * m.omega_rad_s[-1]
    np.testing.assert_allclose(m.rigid_phi, 1 / math.sqrt(J.sum()), rtol=1e-6)
    # J-orthogonal, mass-normalised; orthogonal to the rigid mode (ΣJθ = 0)
    np.testing.assert_allclose(m.phi @ np.diag(J) @ m.phi.T, np.eye(n - 1), atol=1e-8)
    np.testing.assert_allclose(m.phi @ J / np.abs(m.phi * J).sum(axis=1), 0, atol=1e-8)
    # K φ = ω² J φ
    K = stiffness_matrix(k)
    np.testing.assert_allclose(m.phi @ K, (m.omega_rad_s[:, None] ** 2) * m.phi * J,
                               rtol=1e-7, atol=1e-7 * k.max() * np.abs(m.phi).max())
    # shapes: mass 1 = 1 (or the largest entry, where mass 1 is at rest to round-off)
    first = np.abs(m.phi[:, 0]) > 1e-9 * np.abs(m.phi).max(axis=1)
    np.testing.assert_allclose(m.shapes[first, 0], 1.0)
    np.testing.assert_allclose(np.abs(m.shapes[~first]).max(axis=1), 1.0)
    # mode j has j nodes (a Sturm sequence) where every mass's motion is resolved
    resolved = np.abs(m.phi).min(axis=1) > 1e-6 * np.abs(m.phi).max(axis=1)
    counts = np.array([len(nd) for nd in m.nodes])
    modes_no = np.arange(1, n)
    np.testing.assert_array_equal(counts[resolved], modes_no[resolved])
    assert np.all(counts <= modes_no)
    for nd in m.nodes:
        assert np.all((nd >= 1) & (nd <= n))


@SETTINGS
@given(chains())
def test_eigen_against_holzer(chain):
    """The eigen-frequencies zero Holzer's residual, whose sign alternates between them;
    Holzer's θ at a natural frequency is the eigen mode shape."""
    J, k = chain
    m = natural_modes(J, k)
    w = m.omega_rad_s
    # each eigen-frequency is a root of the residual: it changes sign within ±1e-7·ω
    # (Holzer's march amplifies round-off on very uneven chains, so the residual's
    # value at ω itself is no measure)
    lo = holzer_residual(J, k, w * (1 - 1e-7))
    hi = holzer_residual(J, k, w * (1 + 1e-7))
    assert np.all(lo * hi < 0)
    # one sign change between consecutive natural frequencies, none below the first
    mid = np.concatenate([[0.5 * w[0]], 0.5 * (w[1:] + w[:-1]), [1.5 * w[-1]]])
    s = np.sign(holzer_residual(J, k, mid))
    assert np.all(s[1:] == -s[:-1])
    # Holzer's table at a natural frequency is the mode shape (on chains of a modest
    # spread: the march from mass 1 amplifies round-off where the mode dies away)
    theta = holzer_table(J, k, w)["theta_rad"].to_numpy().reshape(len(w), -1)
    if J.max() / J.min() < 10 and k.max() / k.min() < 10:
        np.testing.assert_allclose(theta, m.shapes, rtol=1e-5,
                                   atol=1e-6 * np.abs(m.shapes).max())
    # and its rows obey the march: θ_{i+1} = θ_i − ΣJω²θ / k_i
    np.testing.assert_allclose(theta[:, 1:], theta[:, :-1] - np.cumsum(
        J * w[:, None] ** 2 * theta, axis=1)[:, :-1] / k, rtol=1e-9,
        atol=1e-9 * np.abs(theta).max())


@SETTINGS
@given(chains(2, 8), st.floats(0.05, 3.0), st.integers(0, 6))
def test_undamped_response_is_the_modal_sum(chain, ratio, at):
    """At zero damping (K − Ω²J)Θ = F equals Σ_m φ_m φ_mᵀ F/(ω_m² − Ω²) − φ₀φ₀ᵀF/Ω²
    (the rigid mode's term)."""
    J, k = chain
    n = len(J)
    m = natural_modes(J, k)
    Omega = ratio * m.omega_rad_s[0] * 1.0137
    if np.min(np.abs(m.omega_rad_s - Omega)) < 1e-3 * Omega:
        return
    F = np.zeros(n, complex)
    F[at % n] = 1.0 + 0.5j
    theta = harmonic_solve(stiffness_matrix(k), J, np.zeros((n, n)), F, Omega)
    modal = (m.phi.T * (1.0 / (m.omega_rad_s ** 2 - Omega ** 2))) @ (m.phi @ F)
    modal -= m.rigid_phi * (m.rigid_phi @ F) / Omega ** 2
    np.testing.assert_allclose(theta, modal, rtol=1e-6,
                               atol=1e-9 * np.abs(modal).max())


@SETTINGS
@given(chains(2, 8), st.floats(0.0, 0.2))
def test_damping_matrix_gives_each_mode_its_ratio(chain, zeta):
    J, k = chain
    m = natural_modes(J, k)
    C = damping_matrix(J, m, zeta)
    np.testing.assert_allclose(m.phi @ C @ m.phi.T, np.diag(2 * zeta * m.omega_rad_s),
                               atol=1e-8 * max(1.0, 2 * zeta * m.omega_rad_s.max()))
    np.testing.assert_allclose(C @ np.ones(len(J)), 0, atol=1e-8 * max(1, np.abs(C).max()))
    np.testing.assert_allclose(C, C.T)


@SETTINGS
@given(chains(2, 8), st.floats(0.01, 0.2), st.floats(0.2, 3.0))
def test_power_balance_of_the_damped_response(chain, zeta, ratio):
    """Steady state: the mean power the torque puts in, ½ Re(F̄·iΩΘ), equals the mean
    power the damping dissipates, ½ Ω² Θ̄ᵀ C Θ."""
    J, k = chain
    n = len(J)
    m = natural_modes(J, k)
    C = damping_matrix(J, m, zeta, dampers={n - 1: 0.1 * zeta * math.sqrt(k[0] * J[0])})
    Omega = ratio * m.omega_rad_s[0]
    F = np.linspace(1.0, 2.0, n) * np.exp(1j * np.arange(n))
    th = harmonic_solve(stiffness_matrix(k), J, C, F, Omega)
    p_in = 0.5 * np.real(np.conj(F) @ (1j * Omega * th))
    p_out = 0.5 * Omega ** 2 * np.real(np.conj(th) @ C @ th)
    assert p_in == pytest.approx(p_out, rel=1e-7, abs=1e-12 * np.abs(F).max() ** 2)
    assert p_out >= 0


def test_static_limit_of_a_grounded_chain():
    """Ω → 0 on a chain grounded at its last mass: Θ → K⁻¹F (the static twist), and the
    torque of each section is the sum of the torques in front of it."""
    J = np.array([0.5, 1.0, 2.0, 4.0])
    k = np.array([1e5, 2e5, 3e5])
    K = stiffness_matrix(k)
    K[-1, -1] += 1e6                              # a ground spring behind the last mass
    F = np.array([10.0, -4.0, 3.0, 0.0])
    th = harmonic_solve(K, J, 1e-3 * np.eye(4), F, 1e-6)
    np.testing.assert_allclose(th.real, np.linalg.solve(K, F), rtol=1e-9)
    np.testing.assert_allclose(k * (th.real[:-1] - th.real[1:]), np.cumsum(F)[:-1],
                               rtol=1e-9)


# --------------------------------------------------------------------------------------
# Harmonics: known signals, Parseval, reconstruction, offset grids
# --------------------------------------------------------------------------------------
def test_harmonics_of_a_known_signal():
    a = np.arange(0.0, 720.0, 2.0)
    r = np.radians(a)
    M = 50 + 30 * np.cos(0.5 * r) - 20 * np.sin(1.5 * r) + 7 * np.cos(4 * r + 0.3)
    h = torque_harmonics(a, M, 720, 4)
    np.testing.assert_allclose(h.order, np.arange(9) * 0.5)
    i = {o: j for j, o in enumerate(h.order)}
    assert h.a_Nm[0] == pytest.approx(50) and h.mean_Nm == pytest.approx(50)
    assert h.a_Nm[i[0.5]] == pytest.approx(30) and h.b_Nm[i[0.5]] == pytest.approx(0, abs=1e-12)
    assert h.b_Nm[i[1.5]] == pytest.approx(-20) and h.a_Nm[i[1.5]] == pytest.approx(0, abs=1e-12)
    # 7 cos(4α + 0.3) = 7cos0.3 cos 4α − 7 sin0.3 sin 4α: a = 7cos0.3, b = −7 sin0.3,
    # phase = atan2(−b, a) = +0.3 rad (the angle of M_k)
    assert h.amplitude_Nm[i[4.0]] == pytest.approx(7)
    assert h.phase_deg[i[4.0]] == pytest.approx(math.degrees(0.3))
    assert h.complex_Nm[i[4.0]] == pytest.approx(7 * np.exp(0.3j))
    assert h.reconstruction_rms_Nm < 1e-9
    np.testing.assert_allclose(h.series(a), M, atol=1e-9)
    # the same torque on a grid starting at 7°: the same coefficients
    a7 = a + 7.0
    r7 = np.radians(a7)
    M7 = 50 + 30 * np.cos(0.5 * r7) - 20 * np.sin(1.5 * r7) + 7 * np.cos(4 * r7 + 0.3)
    h7 = torque_harmonics(a7, M7, 720, 4)
    np.testing.assert_allclose(h7.complex_Nm, h.complex_Nm, atol=1e-9)
    # a two-stroke cycle: whole orders
    h2 = torque_harmonics(np.arange(0.0, 360.0, 1.0),
                          np.sin(np.radians(3 * np.arange(0.0, 360.0, 1.0))), 360, 5)
    np.testing.assert_allclose(h2.order, np.arange(6.0))
    assert h2.b_Nm[3] == pytest.approx(1.0)
    tab = h.table()
    assert list(tab.columns) == ["order", "a_Nm", "b_Nm", "amplitude_Nm", "phase_deg"]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-1e4, 1e4), min_size=40, max_size=40), st.integers(1, 19))
def test_parseval_and_reconstruction(values, jmax):
    """rms² = M0² + Σ|M_k|²/2 + (reconstruction rms)²; the truncated series misses M by
    exactly the reconstruction rms."""
    M = np.array(values)
    a = np.arange(40) * 18.0                                  # 720° / 40
    h = torque_harmonics(a, M, 720, jmax * 0.5)
    lhs = h.rms_Nm ** 2
    rhs = h.a_Nm[0] ** 2 + 0.5 * np.sum(h.amplitude_Nm[1:] ** 2) + h.reconstruction_rms_Nm ** 2
    assert lhs == pytest.approx(rhs, rel=1e-9, abs=1e-9)
    miss = np.sqrt(np.mean((M - h.series(a)) ** 2))
    assert miss == pytest.approx(h.reconstruction_rms_Nm, rel=1e-6, abs=1e-6)


# --------------------------------------------------------------------------------------
# Critical speeds and major orders
# --------------------------------------------------------------------------------------
def test_major_orders_from_the_phases():
    # inline-4, four-stroke, firing 1-3-4-2: phases 0, 540, 180, 360 → multiples of 2
    orders = np.arange(1, 25) * 0.5
    four = np.array([0.0, 540.0, 180.0, 360.0])
    assert orders[is_major(orders, four)].tolist() == [2.0, 4.0, 6.0, 8.0, 10.0, 12.0]
    # inline-6, 1-5-3-6-2-4: multiples of 3
    six = np.array([0.0, 480.0, 240.0, 600.0, 120.0, 360.0])
    assert orders[is_major(orders, six)].tolist() == [3.0, 6.0, 9.0, 12.0]
    # an odd-firing V-twin (phases 0, 270): only the multiples of 4 add in phase
    assert orders[is_major(orders, [0.0, 270.0])].tolist() == [4.0, 8.0, 12.0]


def test_critical_speeds_table():
    J, k = [0.5, 0.1, 0.1, 0.1, 0.1, 2.0], [3e5, 4e5, 4e5, 4e5, 3e5]
    m = natural_modes(J, k)
    throws = [1, 2, 3, 4]
    phases = [0.0, 540.0, 180.0, 360.0]
    orders = np.arange(0, 25) * 0.5
    cs = critical_speeds(m, throws, phases, orders, (600, 6000), 4, 720)
    assert list(cs.columns) == ["mode", "order", "f_Hz", "speed_rpm", "major",
                                "sum_relative_amplitude"]
    assert len(cs) and cs["speed_rpm"].between(600, 6000).all()
    np.testing.assert_allclose(cs["speed_rpm"], 60 * cs["f_Hz"] / cs["order"])
    # the vector sum by hand for one row
    row = cs.iloc[0]
    beta = m.shapes[int(row["mode"]) - 1, throws]
    z = np.exp(-1j * row["order"] * np.radians(phases))
    assert row["sum_relative_amplitude"] == pytest.approx(abs(np.sum(beta * z)))
    # a major order's sum is the plain sum of the throws' amplitudes
    maj = cs[cs["major"]]
    for _, r in maj.iterrows():
        assert r["order"] % 2 == 0
        assert r["sum_relative_amplitude"] == pytest.approx(
            abs(m.shapes[int(r["mode"]) - 1, throws].sum()))
    # every (mode, order) whose speed is in range is listed, and no other
    all_speeds = 60 * m.f_Hz[:, None] / orders[None, 1:]
    assert len(cs) == int(((all_speeds >= 600) & (all_speeds <= 6000)).sum())


# --------------------------------------------------------------------------------------
# Forced response
# --------------------------------------------------------------------------------------
def _harm(order, complex_Nm, cycle=720.0):
    c = np.asarray(complex_Nm, complex)
    return Harmonics(np.asarray(order, float), c.real, -c.imag, np.abs(c),
                     np.degrees(np.angle(c)), c, 0.0, 0.0, cycle)


def test_forced_response_against_a_direct_solution():
    """One speed, two orders, two cylinders: the peak angle and section torque over the
    cycle, computed here by a direct sum in time on a fine grid."""
    J = np.array([0.3, 0.2, 0.25, 1.5])
    k = np.array([2e5, 1.5e5, 1e5])
    m = natural_modes(J, k)
    C = damping_matrix(J, m, 0.05)
    orders = [0.0, 1.0, 2.5]
    gas = _harm(orders, [10.0, 80 - 30j, 25 + 5j])
    inertia = _harm(orders, [0.0, 20j, -12.0])
    throws, phases = [1, 2], [0.0, 360.0]
    speed, ref = 3000.0, 2000.0
    r = forced_response(J, k, C, throws, phases, gas, inertia, ref, [speed],
                        diameters_m=[0.05, 0.04, 0.06])
    w = speed * 2 * np.pi / 60
    th = np.zeros((2, 4), complex)
    for q, order in enumerate(orders[1:], start=1):
        Mk = gas.complex_Nm[q] + (speed / ref) ** 2 * inertia.complex_Nm[q]
        F = np.zeros(4, complex)
        for t, p in zip(throws, phases):
            F[t] += Mk * np.exp(-1j * order * math.radians(p))
        A = stiffness_matrix(k) - (order * w) ** 2 * np.diag(J) + 1j * order * w * C
        th[q - 1] = np.linalg.solve(A, F)
    ang = np.radians(np.arange(0, 720, 0.01))
    x = np.real(np.exp(1j * np.multiply.outer(ang, [1.0, 2.5])) @ th)      # (T, n)
    # the absolute angle (swing of the whole chain included) and the elastic one, the
    # inertia-weighted mean rotation of the chain taken out at every instant
    np.testing.assert_allclose(r.swing_deg[0], np.degrees(np.abs(x).max(axis=0)),
                               rtol=2e-3)
    xe = x - (x @ J / J.sum())[:, None]
    np.testing.assert_allclose(r.amplitude_deg[0], np.degrees(np.abs(xe).max(axis=0)),
                               rtol=2e-3)
    assert not np.allclose(r.amplitude_deg[0], r.swing_deg[0], rtol=0.05)
    th = th - (th @ J / J.sum())[:, None]
    tw = k * (x[:, :-1] - x[:, 1:])
    np.testing.assert_allclose(r.torque_Nm[0], np.abs(tw).max(axis=0), rtol=2e-3)
    np.testing.assert_allclose(r.stress_MPa[0],
                               16 * r.torque_Nm[0] / (np.pi * np.array([0.05, 0.04, 0.06]) ** 3)
                               / 1e6)
    np.testing.assert_allclose(r.amplitude_by_order_deg[0], np.degrees(np.abs(th)))
    assert r.orders.tolist() == [1.0, 2.5]
    # the peak in time is at most the sum of the orders' amplitudes, at least the largest
    assert np.all(r.amplitude_deg[0] <= r.amplitude_by_order_deg[0].sum(axis=0) * (1 + 1e-9))
    assert np.all(r.amplitude_deg[0] >= r.amplitude_by_order_deg[0].max(axis=0) * (1 - 2e-3))
    tab = r.table(["a", "b", "c", "d"])
    assert list(tab.columns) == ["speed_rpm", "theta_a_deg", "theta_b_deg", "theta_c_deg",
                                 "theta_d_deg", "M_a-b_Nm", "M_b-c_Nm", "M_c-d_Nm",
                                 "tau_a-b_MPa", "tau_b-c_MPa", "tau_c-d_MPa",
                                 "swing_a_deg", "swing_b_deg", "swing_c_deg", "swing_d_deg"]
    np.testing.assert_array_equal(tab["theta_b_deg"], r.amplitude_deg[:, 1])
    np.testing.assert_array_equal(tab["swing_b_deg"], r.swing_deg[:, 1])


def test_response_peaks_at_the_critical_speed_and_inertia_scales_with_speed():
    J = np.array([0.05, 0.1, 0.1, 1.0])
    k = np.array([1e5, 1e5, 1e5])
    m = natural_modes(J, k)
    C = damping_matrix(J, m, 0.02)
    order = 3.0
    zero = _harm([0.0, order], [0.0, 0.0])
    one = _harm([0.0, order], [0.0, 100.0])
    speeds = np.arange(200.0, 6000.0, 1.0)
    r = forced_response(J, k, C, [1, 2], [0.0, 0.0], one, zero, 3000.0, speeds)
    crit = 60 * m.f_Hz[0] / order
    assert r.worst[0] == pytest.approx(crit, rel=0.01)
    # inertia-only excitation at 2·n_ref is the gas excitation ×4 at that speed
    r_in = forced_response(J, k, C, [1, 2], [0.0, 0.0], zero, one, 1000.0, [2000.0])
    r_gas = forced_response(J, k, C, [1, 2], [0.0, 0.0], one, zero, 1000.0, [2000.0])
    np.testing.assert_allclose(r_in.torque_Nm, 4 * r_gas.torque_Nm, rtol=1e-12)


# --------------------------------------------------------------------------------------
# Side by side with openTorsion (PyPI opentorsion, Aalto ARotor lab)
# --------------------------------------------------------------------------------------
def _ot_assembly(J, k):
    import opentorsion as ot        # in the test extra: a missing peer fails, never skips
    shafts = [ot.Shaft(i, i + 1, k=float(ki)) for i, ki in enumerate(k)]
    disks = [ot.Disk(i, I=float(Ji)) for i, Ji in enumerate(J)]
    return ot.Assembly(shafts, disk_elements=disks)


@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(chains(2, 10))
def test_natural_frequencies_as_opentorsion(chain):
    J, k = chain
    asm = _ot_assembly(J, k)
    lam, _ = asm.undamped_modal_analysis()
    w_ot = np.sort(np.sqrt(np.abs(lam.real)))[1:]
    np.testing.assert_allclose(natural_modes(J, k).omega_rad_s, w_ot, rtol=1e-6)


@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(chains(2, 8), st.floats(0.01, 0.1), st.floats(0.3, 2.5))
def test_forced_response_as_opentorsion(chain, zeta, ratio):
    """The same modal damping (openTorsion's Assembly.C_modal) and the same excitation:
    the same steady response (openTorsion's ss_response)."""
    J, k = chain
    asm = _ot_assembly(J, k)
    m = natural_modes(J, k)
    C = damping_matrix(J, m, zeta)
    C_ot = asm.C_modal(asm.M, asm.K, xi=zeta)
    np.testing.assert_allclose(C, C_ot, atol=1e-6 * np.abs(C).max())
    n = len(J)
    Omega = ratio * m.omega_rad_s[0]
    F = (np.arange(n) + 1.0) * np.exp(0.7j * np.arange(n))
    q_ot, _ = asm.ss_response(F[:, None], np.array([Omega]), C=C)
    th = harmonic_solve(stiffness_matrix(k), J, C, F, Omega)
    np.testing.assert_allclose(th, q_ot[:, 0], rtol=1e-7, atol=1e-10 * np.abs(th).max())


# --------------------------------------------------------------------------------------
# Bad input: one clear error each, naming the spec key
# --------------------------------------------------------------------------------------
def _key(exc):
    return exc.value.problems[0].key


def test_bad_chain_inputs():
    with pytest.raises(SpecError) as e:
        natural_modes([1.0, 2.0, 3.0], [1e5])
    assert _key(e) == "torsion.stiffnesses_Nm_rad" and "3 masses" in str(e.value)
    with pytest.raises(SpecError) as e:
        natural_modes([1.0, 0.0], [1e5])
    assert _key(e) == "torsion.inertias_kgm2"
    with pytest.raises(SpecError) as e:
        natural_modes([1.0, 2.0], [-5.0])
    assert _key(e) == "torsion.stiffnesses_Nm_rad" and "-5" in str(e.value)
    with pytest.raises(SpecError) as e:
        natural_modes([1.0], [])
    assert _key(e) == "torsion.inertias_kgm2"
    with pytest.raises(SpecError) as e:
        natural_modes([1.0, float("nan")], [1.0])
    assert _key(e) == "torsion.inertias_kgm2"
    with pytest.raises(SpecError) as e:
        natural_modes([1.0, "x"], [1.0])
    assert _key(e) == "torsion.inertias_kgm2"
    m = natural_modes([1.0, 2.0], [1e5])
    with pytest.raises(SpecError) as e:
        damping_matrix([1.0, 2.0], m, -0.1)
    assert _key(e) == "torsion.damping_ratio"
    with pytest.raises(SpecError) as e:
        damping_matrix([1.0, 2.0], m, 0.02, dampers={5: 1.0})
    assert _key(e) == "torsion.dampers"
    with pytest.raises(SpecError) as e:
        shaft_stiffness(80e9, 0.0, 1.0)
    assert _key(e) == "d_m"
    # the Russian words of the same error
    with pytest.raises(SpecError) as e:
        natural_modes([1.0, 2.0, 3.0], [1e5])
    assert "жёсткостей" in e.value.lines("ru")[0]


def test_bad_harmonics_and_response_inputs():
    a = np.arange(0.0, 720.0, 10.0)
    M = np.sin(np.radians(a))
    with pytest.raises(SpecError) as e:
        torque_harmonics(a, M, 720, 1.25)              # not a multiple of 0.5
    assert _key(e) == "torsion.orders_max"
    with pytest.raises(SpecError) as e:
        torque_harmonics(a, M, 720, 0)
    assert _key(e) == "torsion.orders_max"
    with pytest.raises(SpecError) as e:
        torque_harmonics(a, M, 720, 36)                # beyond the grid's Nyquist order
    assert _key(e) == "torsion.orders_max"
    with pytest.raises(SpecError) as e:
        torque_harmonics(np.append(a, 720.0), np.append(M, 0.0), 720, 2)   # endpoint
    assert _key(e) == "alpha_deg"
    with pytest.raises(SpecError) as e:
        torque_harmonics(a, M[:-1], 720, 2)
    assert _key(e) == "M_Nm"
    m = natural_modes([1.0, 2.0, 3.0], [1e5, 1e5])
    for bad in ([0, 6000], [6000, 600], [600, float("inf")], [600]):
        with pytest.raises(SpecError) as e:
            critical_speeds(m, [0], [0.0], [1.0], bad, 1, 720)
        assert _key(e) == "torsion.speed_range_rpm"
    for bad_throw in ([3], [-1], [0.5], ["x"]):
        with pytest.raises(SpecError) as e:
            critical_speeds(m, bad_throw, [0.0], [1.0], [600, 6000], 1, 720)
        assert _key(e) == "throw_index"
    # a whole number given as a float is a mass index
    assert len(critical_speeds(m, [1.0], [0.0], [0.5, 1.0], [1, 1e9], 1, 720)) == 4
    with pytest.raises(SpecError) as e:                 # 0.75 is no order of a 720° cycle
        critical_speeds(m, [1], [0.0], [0.75], [600, 6000], 1, 720)
    assert _key(e) == "torsion.orders_max"
    h = _harm([0.0, 1.0], [0.0, 1.0])
    h2 = _harm([0.0, 2.0], [0.0, 1.0])
    C = np.zeros((3, 3))
    with pytest.raises(SpecError) as e:
        forced_response([1.0, 2.0, 3.0], [1e5, 1e5], C, [0], [0.0], h, h2, 1000, [1000])
    assert _key(e) == "harmonics_inertia"
    with pytest.raises(SpecError) as e:
        forced_response([1.0, 2.0, 3.0], [1e5, 1e5], C, [0], [0.0], h, h, 1000, [0.0])
    assert _key(e) == "speeds_rpm"
    with pytest.raises(SpecError) as e:
        forced_response([1.0, 2.0, 3.0], [1e5, 1e5], C, [0], [0.0, 1.0], h, h, 1000, [10])
    assert _key(e) == "phases_deg"


def test_result_tables():
    J, k = khurmi_chain()
    m = natural_modes(J, k)
    tab = m.table(["A", "B", "C"])
    assert list(tab.columns) == ["mode", "f_Hz", "omega_rad_s", "nodes", "theta_A",
                                 "theta_B", "theta_C"]
    assert tab["mode"].tolist() == [1, 2]
    np.testing.assert_allclose(tab["theta_A"], 1.0)
    assert tab["nodes"].iloc[1] == "; ".join(f"{x:.3f}" for x in m.nodes[1])
    with pytest.raises(SpecError):
        m.table(["A", "B"])
    a = np.arange(0.0, 720.0, 10.0)
    h = torque_harmonics(a, 5 + 2 * np.cos(np.radians(2 * a) + 0.4), 720, 3)
    h4 = h.scaled(4.0)
    np.testing.assert_allclose(h4.complex_Nm, 4 * h.complex_Nm)
    np.testing.assert_allclose(h4.series(a), 4 * h.series(a))
    np.testing.assert_allclose(h4.phase_deg[4], h.phase_deg[4])
    hm = h.scaled(-1.0)                                   # a sign turns the phase by 180°
    assert abs(((hm.phase_deg[4] - h.phase_deg[4]) % 360.0) - 180.0) < 1e-9


def test_docstring_examples():
    import doctest

    import torsion.chain
    import torsion.harmonics

    for mod in (torsion.chain, torsion.harmonics):
        assert doctest.testmod(mod).failed == 0, mod.__name__
