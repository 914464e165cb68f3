"""Proof layer "identities that need no reference" (issue 2, section 4; domain.md §2,
"Checks that need no published data"): loop closure, velocities and accelerations against
numerical derivatives of the positions, virtual power, equilibrium of every link with the
reported reactions, extreme positions and the plan of positions, swing and time ratio of
the ratchet drive, the transmission-angle formula, the useful resistance, and the
reversal of the crank's direction.

Every quantity is read from the DataFrames of ``linkage.analyze`` and the spec dict; the
shared table checks are in tests/newton_euler.py."""
import copy
import math

import numpy as np
import pytest

import linkage
from newton_euler import (equilibrium_residuals, loaded_rocker, loaded_slider,
                          ratchet_data, virtual_power_terms, wrap_deg)

ROCKERS = {
    "ratchet": ratchet_data,
    "rocker-loaded": lambda: loaded_rocker(),
    "rocker-asm-cw": lambda: loaded_rocker(ground_angle_deg=-70.0, assembly=-1,
                                           omega=-9.0, eps=-25.0, working="cw"),
}
SLIDERS = {
    "slider-loaded": lambda: loaded_slider(),
    "slider-asm-toward": lambda: loaded_slider(assembly=-1, working="toward", offset=-0.02,
                                               guide_deg=200.0, omega=80.0, eps=-900.0),
}
ALL = {**ROCKERS, **SLIDERS}
ANGLES = np.arange(-7.5, 360.0, 15.0) + 0.3


def _z(df, p):
    return df[f"{p}_x_m"].to_numpy(float) + 1j * df[f"{p}_y_m"].to_numpy(float)


def _v(df, p):
    return df[f"{p}_vx_m_s"].to_numpy(float) + 1j * df[f"{p}_vy_m_s"].to_numpy(float)


def _a(df, p):
    return df[f"{p}_ax_m_s2"].to_numpy(float) + 1j * df[f"{p}_ay_m_s2"].to_numpy(float)


def _F(df, r):
    return df[f"{r}_x_N"].to_numpy(float) + 1j * df[f"{r}_y_N"].to_numpy(float)


def _col(df, c):
    return df[c].to_numpy(float)


def _cross(a, b):
    return a.real * b.imag - a.imag * b.real


def _dot(a, b):
    return a.real * b.real + a.imag * b.imag


def _run(name, angles=ANGLES):
    data = ALL[name]()
    return data, linkage.analyze(data, crank_angles_deg=angles)


# ------------------------------------------------------------------ loop closure


@pytest.mark.parametrize("name", list(ALL))
def test_loop_closure_and_local_frames(name):
    data, res = _run(name, np.arange(0.0, 360.0, 1.0))
    k = res.kinematics
    m = data["mechanism"]
    l1, l2 = m["crank"], m["coupler"]
    zA, zB = _z(k, "A"), _z(k, "B")
    phi = np.radians(_col(k, "phi_deg"))
    size = l1 + l2
    tol = 1e-12 * size
    np.testing.assert_allclose(zA, l1 * np.exp(1j * phi), rtol=0, atol=tol)
    np.testing.assert_allclose(np.abs(zB - zA), l2, rtol=0, atol=tol)
    e3 = np.exp(1j * np.radians(_col(k, "theta3_deg")))
    np.testing.assert_allclose(zB, zA + l2 * e3, rtol=0, atol=tol)
    gam = math.radians(m.get("ground_angle_deg", 0.0))
    u = complex(math.cos(gam), math.sin(gam))
    asm = m.get("assembly", 1)
    if m["kind"] == "crank-rocker":
        zC = m["ground"] * u
        e4 = np.exp(1j * np.radians(_col(k, "theta4_deg")))
        np.testing.assert_allclose(np.abs(zB - zC), m["rocker"], rtol=0, atol=tol)
        np.testing.assert_allclose(zB, zC + m["rocker"] * e4, rtol=0, atol=tol)
        # the assembly branch is kept all the way round: B left (+1) / right (−1) of A→C
        side = _cross(zC - zA, zB - zA) * asm
        assert np.all(side > 0)
        frames = {"crank": (0j, np.exp(1j * phi)), "coupler": (zA, e3), "rocker": (zC, e4)}
    else:
        # B on the guide line at the offset, s4 measured along it from the foot of O
        np.testing.assert_allclose(_cross(u, zB), m.get("offset", 0.0), rtol=0, atol=tol)
        np.testing.assert_allclose(_dot(u, zB), _col(k, "s4_m"), rtol=0, atol=tol)
        assert np.all(_dot(zB - zA, u) * asm > 0)  # B ahead of (+1) / behind (−1) A
        frames = {"crank": (0j, np.exp(1j * phi)), "coupler": (zA, e3), "slider": (zB, u)}
    # centres of mass and named points sit at their local coordinates
    for lname, (origin, e) in frames.items():
        t = data["links"].get(lname, {})
        num = {"crank": 2, "coupler": 3, "rocker": 4, "slider": 4}[lname]
        pts = {f"S{num}": t["cg"], **t.get("points", {})}
        for p, (x, y) in pts.items():
            np.testing.assert_allclose(_z(k, p), origin + complex(x, y) * e, rtol=0,
                                       atol=tol, err_msg=p)


# ------------------------------------------------------ numerical derivatives of positions


def _stencil(data, phi_deg, h_deg):
    """Tables at φ + j·h, j = −2…2 (five analyses at explicit angles)."""
    return [linkage.analyze(data, crank_angles_deg=phi_deg + j * h_deg).kinematics
            for j in (-2, -1, 0, 1, 2)]


def _derivs(vals, h):
    """First and second derivative by the five-point central stencils (error O(h⁴))."""
    m2, m1, c, p1, p2 = vals
    d1 = (m2 - 8 * m1 + 8 * p1 - p2) / (12 * h)
    d2 = (-m2 + 16 * m1 - 30 * c + 16 * p1 - p2) / (12 * h * h)
    return d1, d2


@pytest.mark.parametrize("name", list(ALL))
def test_velocities_and_accelerations_are_derivatives_of_positions(name):
    """With the crank turning at ω, ε: d/dt = ω·d/dφ, so v = ω·z′ and a = ε·z′ + ω²·z″."""
    data = ALL[name]()
    m = data["mechanism"]
    w, eps = m["omega_rad_s"], m.get("epsilon_rad_s2", 0.0)
    phi = np.arange(0.0, 360.0, 10.0) + 3.7
    h_deg = 0.05
    h = math.radians(h_deg)
    tabs = _stencil(data, phi, h_deg)
    mid = tabs[2]
    pts = [c[:-4] for c in mid.columns if c.endswith("_x_m")]
    assert {"A", "B", "S2", "S3", "S4"} <= set(pts)
    vscale = max(np.max(np.abs(_v(mid, p))) for p in pts)
    ascale = max(np.max(np.abs(_a(mid, p))) for p in pts)
    for p in pts:
        d1, d2 = _derivs([_z(t, p) for t in tabs], h)
        assert np.max(np.abs(_v(mid, p) - w * d1)) <= 1e-6 * vscale, p
        assert np.max(np.abs(_a(mid, p) - (eps * d1 + w * w * d2))) <= 1e-6 * ascale, p
    outs = [("theta3_deg", "omega3_rad_s", "eps3_rad_s2", True)]
    if m["kind"] == "crank-rocker":
        outs.append(("theta4_deg", "omega4_rad_s", "eps4_rad_s2", True))
    else:
        outs.append(("s4_m", "v4_m_s", "a4_m_s2", False))
    for pos, vel, acc, angle in outs:
        if angle:  # unwrap each angle around its value at the centre
            c = _col(mid, pos)
            vals = [np.radians(c + wrap_deg(_col(t, pos) - c)) for t in tabs]
        else:
            vals = [_col(t, pos) for t in tabs]
        d1, d2 = _derivs(vals, h)
        vs = max(np.max(np.abs(_col(mid, vel))), 1e-300)
        as_ = max(np.max(np.abs(_col(mid, acc))), 1e-300)
        assert np.max(np.abs(_col(mid, vel) - w * d1)) <= 1e-6 * vs, vel
        assert np.max(np.abs(_col(mid, acc) - (eps * d1 + w * w * d2))) <= 1e-6 * as_, acc


# ------------------------------------------------------------------ virtual power


@pytest.mark.parametrize("name", list(ALL))
def test_virtual_power(name):
    """M_drive·ω2 + Σ F_ext·v + Σ M_ext·ω + P_res − Σ(m·aS·vS + JS·ε·ω) − Σ m·g·vS,y = 0
    (domain.md §2), every term from the tables and the spec."""
    data = ALL[name]()
    plan = linkage.analyze(data)
    explicit = linkage.analyze(data, crank_angles_deg=ANGLES)
    for kin, frc in ((plan.kinematics, plan.forces), (explicit.kinematics, explicit.forces)):
        t = virtual_power_terms(data, kin, frc)
        total = sum(t.values())
        scale = np.max(sum(np.abs(v) for v in t.values()))
        assert np.max(np.abs(total)) <= 1e-9 * scale, {k: v[:3] for k, v in t.items()}
        # the balance is not trivially met: the driving term is of the size of the rest
        assert np.max(np.abs(t["drive"])) > 1e-3 * scale


def test_virtual_power_would_see_a_missing_term():
    """Guard on the check itself: drop the weight of one link and the balance fails."""
    data = loaded_rocker()
    res = linkage.analyze(data, crank_angles_deg=ANGLES)
    t = virtual_power_terms(data, res.kinematics, res.forces)
    scale = np.max(sum(np.abs(v) for v in t.values()))
    t.pop("weight coupler")
    assert np.max(np.abs(sum(t.values()))) > 1e-4 * scale


# ------------------------------------------------------------------ equilibrium


@pytest.mark.parametrize("name", list(ALL))
def test_every_link_in_equilibrium_with_the_reported_reactions(name):
    """ΣF = 0 and ΣM = 0 on crank, coupler and output link, with R32 = −R23, R34 = −R43
    (the tables report one of each pair) and all loads, inertia and weight."""
    data, res = _run(name)
    r, scale = equilibrium_residuals(data, res.kinematics, res.forces)
    size = data["mechanism"]["crank"] + data["mechanism"]["coupler"]
    for key, v in r.items():
        lim = 1e-9 * scale * (size if key.endswith(" M") else 1.0)
        assert np.max(np.abs(v)) <= lim, key


@pytest.mark.parametrize("name", list(ALL))
def test_course_table_magnitudes(name):
    """The course tables' columns (seed 000 Tables 3.1, 3.2): speeds and accelerations of
    the points are the lengths of their vectors; VBA = |ω3|·lAB is the length of vB − vA,
    and the relative acceleration splits into aBAⁿ = ω3²·lAB along B→A and aBAᵗ = |ε3|·lAB
    across; for a crank-rocker likewise about the fixed C (VBC = VB, aBC = aB)."""
    data, res = _run(name)
    k, m = res.kinematics, data["mechanism"]
    pts = [c[:-len("_vx_m_s")] for c in k.columns if c.endswith("_vx_m_s")]
    assert {"A", "B", "S2", "S3"} <= set(pts)
    for p in pts:
        np.testing.assert_allclose(_col(k, f"{p}_v_m_s"), np.abs(_v(k, p)), rtol=1e-12)
        np.testing.assert_allclose(_col(k, f"{p}_a_m_s2"), np.abs(_a(k, p)), rtol=1e-12)
    rel = [("BA", _z(k, "A"), _v(k, "A"), _a(k, "A"), m["coupler"])]
    if m["kind"] == "crank-rocker":
        gam = math.radians(m.get("ground_angle_deg", 0.0))
        zC = m["ground"] * complex(math.cos(gam), math.sin(gam))
        rel.append(("BC", zC, 0.0, 0.0, m["rocker"]))
    for name_, z0, v0, a0, length in rel:
        dv, da = _v(k, "B") - v0, _a(k, "B") - a0
        e = (_z(k, "B") - z0) / length                 # unit vector from the pivot to B
        scale_v, scale_a = np.max(np.abs(dv)), np.max(np.abs(da))
        assert np.max(np.abs(_col(k, f"v_{name_}_m_s") - np.abs(dv))) <= 1e-12 * scale_v
        # normal part points from B to the pivot, tangential across the link
        assert np.max(np.abs(_col(k, f"a_{name_}_n_m_s2") + _dot(da, e))) <= 1e-12 * scale_a
        assert np.max(np.abs(_col(k, f"a_{name_}_t_m_s2") - np.abs(_cross(e, da)))) \
            <= 1e-12 * scale_a
        assert np.max(np.abs(_col(k, f"a_{name_}_m_s2") - np.abs(da))) <= 1e-12 * scale_a


@pytest.mark.parametrize("name", list(ALL))
def test_force_inputs_and_reaction_magnitudes(name):
    """The loads sheet (seed 000 Table 4.1): Gi = mi·g, Fui = −mi·aSi, Mui = −JSi·εi; and
    the reported reactions, weights and inertia loads alone close the coupler's force
    polygon when the coupler carries no external force: R23 + R43 + Fu3 − j·G3 = 0
    (what a teacher checks on the force plan)."""
    data, res = _run(name)
    k, f, m = res.kinematics, res.forces, data["mechanism"]
    g = m.get("gravity_m_s2", 9.81)
    eps = {"crank": m.get("epsilon_rad_s2", 0.0) + 0 * _col(k, "phi_deg"),
           "coupler": _col(k, "eps3_rad_s2"),
           "rocker": _col(k, "eps4_rad_s2") if "eps4_rad_s2" in k else None}
    for lname, i in (("crank", 2), ("coupler", 3), ("rocker", 4), ("slider", 4)):
        if lname not in data["links"]:
            continue
        t = data["links"][lname]
        mass, J = t.get("mass_kg", 0.0), t.get("inertia_kg_m2", 0.0)
        aS = _a(k, f"S{i}")
        np.testing.assert_allclose(_col(f, f"G{i}_N"), mass * g, rtol=1e-15)
        assert np.max(np.abs(_F(f, f"Fu{i}") + mass * aS)) <= 1e-12 * mass * np.max(np.abs(aS))
        np.testing.assert_allclose(_col(f, f"Fu{i}_N"), mass * np.abs(aS), rtol=1e-12)
        if lname == "slider":
            assert f"Mu{i}_Nm" not in f
        else:
            np.testing.assert_allclose(_col(f, f"Mu{i}_Nm"), -J * eps[lname], rtol=1e-12,
                                       atol=1e-12)
    for r in ("R12", "R23", "R43", "R14"):
        np.testing.assert_allclose(_col(f, f"{r}_N"), np.abs(_F(f, r)), rtol=1e-12)
    if not any(ld.get("link") == "coupler" and "force_N" in ld for ld in data.get("load", [])):
        close = _F(f, "R23") + _F(f, "R43") + _F(f, "Fu3") - 1j * _col(f, "G3_N")
        assert np.max(np.abs(close)) <= 1e-9 * np.max(np.abs(_F(f, "R23")))


@pytest.mark.parametrize("name", list(ROCKERS))
def test_rocker_normal_and_tangential_components(name):
    """R23 = R23n·e3 + R23t·(i·e3) with e3 along A→B; R14 = R14n·e4 + R14t·(i·e4) with e4
    along C→B (the textbook's split, domain.md §2)."""
    data, res = _run(name)
    k, f = res.kinematics, res.forces
    m = data["mechanism"]
    gam = math.radians(m.get("ground_angle_deg", 0.0))
    zC = m["ground"] * complex(math.cos(gam), math.sin(gam))
    zA, zB = _z(k, "A"), _z(k, "B")
    e3 = (zB - zA) / m["coupler"]
    e4 = (zB - zC) / m["rocker"]
    scale = max(np.max(np.abs(_F(f, "R23"))), np.max(np.abs(_F(f, "R14"))))
    for R, n, t, e in (("R23", "R23_n_N", "R23_t_N", e3), ("R14", "R14_n_N", "R14_t_N", e4)):
        rebuilt = _col(f, n) * e + _col(f, t) * 1j * e
        assert np.max(np.abs(rebuilt - _F(f, R))) <= 1e-9 * scale, R
    # the tangential components come from moments about B of each link alone:
    # R23t·l2 balances the coupler's load moment about B (checked in the equilibrium test);
    # here: the split is not the trivial x/y one
    assert not np.allclose(_col(f, "R23_n_N"), _col(f, "R23_x_N"))


@pytest.mark.parametrize("name", list(SLIDERS))
def test_slider_guide_reaction(name):
    """The guide's force on the slider is perpendicular to the guide (N14 along i·u) and
    its couple M14 balances the slider's moment about B (its loads and R34 = −R43 at B)."""
    data, res = _run(name)
    k, f = res.kinematics, res.forces
    m = data["mechanism"]
    gam = math.radians(m.get("ground_angle_deg", 0.0))
    u = complex(math.cos(gam), math.sin(gam))
    R14 = _F(f, "R14")
    scale = np.max(np.abs(R14))
    assert np.max(np.abs(_dot(R14, u))) <= 1e-12 * scale
    np.testing.assert_allclose(_col(f, "N14_N") * 1j * u, R14, rtol=0, atol=1e-12 * scale)
    # moment about B of the slider's loads, from the spec and the tables
    sl = data["links"]["slider"]
    zB, zS, aS = _z(k, "B"), _z(k, "S4"), _a(k, "S4")
    msl = sl.get("mass_kg", 0.0)
    g = m.get("gravity_m_s2", 9.81)
    M = _cross(zS - zB, -msl * aS - 1j * msl * g)
    for ld in data["load"]:
        if ld["link"] != "slider":
            continue
        if "force_N" in ld:
            M = M + _cross(complex(*ld["at"]) * u, complex(*ld["force_N"]) + 0 * zB)
        elif "moment_Nm" in ld:
            M = M + ld["moment_Nm"]
    assert np.max(np.abs(_col(f, "M14_Nm") + M)) <= 1e-9 * max(np.max(np.abs(M)), 1.0)
    assert np.max(np.abs(M)) > 1.0  # the couple is really exercised


# ------------------------------------------------------------------ extremes and plan


@pytest.mark.parametrize("name", list(ALL))
def test_extremes_and_plan_of_positions(name):
    data = ALL[name]()
    m = data["mechanism"]
    rocker = m["kind"] == "crank-rocker"
    w = m["omega_rad_s"]
    rot = 1 if w > 0 else -1
    wsign = {"ccw": 1, "cw": -1, "away": m.get("assembly", 1),
             "toward": -m.get("assembly", 1)}[data["analysis"]["working_stroke"]]
    res = linkage.analyze(data)
    ex = res.extremes
    assert list(ex["label"]) == ["working start", "working end"]
    rate, coord, acc = (("omega4_rad_s", "theta4_deg", "eps4_rad_s2") if rocker
                        else ("v4_m_s", "s4_m", "a4_m_s2"))
    rscale = abs(w) * (1.0 if rocker else m["crank"])
    # the output link stands still at both extreme positions ...
    assert np.all(np.abs(_col(ex, rate)) <= 1e-9 * rscale)
    # ... and from the working start it accelerates into the working direction,
    # from the working end into the idle direction (ε = 0 would do; ε ≠ 0 still holds
    # because the output's velocity is zero there)
    a = _col(ex, acc)
    assert a[0] * wsign > 0 and a[1] * wsign < 0
    # they are the ends of the output's range over a full turn
    ft = linkage.full_turn(data, step_deg=0.25)
    c = _col(ft.kinematics, coord)
    ce = _col(ex, coord)
    if rocker:
        ref = ce[0]
        rel = wrap_deg(c - ref)
        lo, hi = sorted([0.0, float(wrap_deg(ce[1] - ref))])
        assert rel.min() >= lo - 1e-9 and rel.max() <= hi + 1e-9
        assert rel.min() <= lo + 0.01 and rel.max() >= hi - 0.01
        # working stroke from start to end in the working direction
        assert wrap_deg(ce[1] - ce[0]) * wsign > 0
    else:
        assert c.min() >= ce.min() - 1e-12 and c.max() <= ce.max() + 1e-12
        assert c.min() <= ce.min() + 1e-6 and c.max() >= ce.max() - 1e-6
        # "away": |s| grows during the working stroke
        grows = abs(ce[1]) > abs(ce[0])
        assert grows == (data["analysis"]["working_stroke"] == "away")
    # the plan of positions: N rows, position 1 at the working start, then steps of
    # 360°/N in the direction of rotation
    k = res.kinematics
    n = data["analysis"]["positions"]
    assert list(k["position"]) == list(range(1, n + 1))
    phi = _col(k, "phi_deg")
    assert abs(wrap_deg(phi[0] - _col(ex, "phi_deg")[0])) <= 1e-9
    steps = wrap_deg(np.diff(phi))
    np.testing.assert_allclose(steps, rot * 360.0 / n, atol=1e-9)
    # right after position 1 the output moves in the working direction
    assert _col(k, rate)[1] * wsign > 0
    assert _col(k, rate)[-1] * wsign < 0  # and before it, in the idle stroke
    # summary: the extreme crank angles and K = working / idle crank rotation
    s = res.summary
    assert s.phi_working_start_deg == pytest.approx(_col(ex, "phi_deg")[0], abs=1e-9)
    work = (rot * (s.phi_working_end_deg - s.phi_working_start_deg)) % 360.0
    assert s.working_crank_angle_deg == pytest.approx(work, abs=1e-9)
    assert s.time_ratio == pytest.approx(work / (360.0 - work), rel=1e-12)


def test_ratchet_swing_and_time_ratio():
    """domain.md §2 (seed 000, the ratchet drive with OC = 0.54 m): "rocker swing 68.4°,
    time-ratio coefficient 1.138"; and the same from the textbook's closed forms: the
    rocker's extremes lie where crank and coupler are extended (|OB| = OA + AB) and folded
    (|OB| = AB − OA), the swing is the difference of the angles at C, and
    K = (180° + θ)/(180° − θ) with θ the angle between the two lines OB."""
    res = linkage.analyze(ratchet_data())
    s = res.summary
    assert round(s.swing_deg, 1) == 68.4           # domain.md §2: swing 68.4°
    assert round(s.time_ratio, 3) == 1.138         # domain.md §2: K = 1.138
    l1, l2, l3, l0 = 0.175, 0.55, 0.325, 0.54
    c_at = {d: math.acos((l0 ** 2 + l3 ** 2 - d * d) / (2 * l0 * l3)) for d in (l1 + l2, l2 - l1)}
    o_at = {d: math.acos((l0 ** 2 + d * d - l3 ** 2) / (2 * l0 * d)) for d in (l1 + l2, l2 - l1)}
    swing = math.degrees(c_at[l1 + l2] - c_at[l2 - l1])
    theta = math.degrees(o_at[l2 - l1] - o_at[l1 + l2])
    assert s.swing_deg == pytest.approx(swing, rel=1e-9)
    assert s.time_ratio == pytest.approx((180 + theta) / (180 - theta), rel=1e-9)
    # B above the line of centres (assembly +1): the working start (rocker turning ccw
    # next) is the extended position, at crank angle = the angle of OB there
    assert s.phi_working_start_deg == pytest.approx(math.degrees(o_at[l1 + l2]), abs=1e-7)
    assert s.phi_working_end_deg == pytest.approx(180 + math.degrees(o_at[l2 - l1]),
                                                     abs=1e-7)


# ------------------------------------------------------------------ transmission angle


@pytest.mark.parametrize("name", list(ROCKERS))
def test_transmission_angle_formula_crank_rocker(name):
    """domain.md §2: cos μ = (λ2² + λ3² − λ1² − 1 + 2λ1 cos φ)/(2λ2λ3), lengths relative
    to the ground and φ from the line of centres O→C; the acute value is reported."""
    data = ALL[name]()
    m = data["mechanism"]
    res = linkage.analyze(data, crank_angles_deg=np.arange(0.0, 360.0, 2.5))
    l0 = m["ground"]
    L1, L2, L3 = m["crank"] / l0, m["coupler"] / l0, m["rocker"] / l0
    phi = np.radians(_col(res.kinematics, "phi_deg") - m.get("ground_angle_deg", 0.0))
    cmu = (L2 ** 2 + L3 ** 2 - L1 ** 2 - 1 + 2 * L1 * np.cos(phi)) / (2 * L2 * L3)
    want = np.degrees(np.arccos(np.abs(cmu)))
    np.testing.assert_allclose(_col(res.kinematics, "mu_deg"), want, rtol=0, atol=1e-9)
    assert res.summary.mu_min_deg == pytest.approx(want.min(), abs=0.5)
    assert res.summary.mu_min_deg <= want.min() + 1e-9


@pytest.mark.parametrize("name", list(SLIDERS))
def test_transmission_angle_crank_slider(name):
    """90° minus the acute angle β between rod and guide: cos μ = sin β = |e − y_A|/L,
    y_A the crank pin's distance from the guide direction through O."""
    data = ALL[name]()
    m = data["mechanism"]
    res = linkage.analyze(data, crank_angles_deg=np.arange(0.0, 360.0, 2.5))
    gam = math.radians(m.get("ground_angle_deg", 0.0))
    yA = m["crank"] * np.sin(np.radians(_col(res.kinematics, "phi_deg")) - gam)
    want = np.degrees(np.arccos(np.abs(m.get("offset", 0.0) - yA) / m["coupler"]))
    np.testing.assert_allclose(_col(res.kinematics, "mu_deg"), want, rtol=0, atol=1e-9)


# ------------------------------------------------------------------ useful resistance


def _resistance_case(kind, stroke):
    if kind == "rocker":
        d = ratchet_data()
        d["load"][0]["stroke"] = stroke
        return d, "M_res_Nm", "omega4_rad_s", "theta4_deg", math.radians(59.587), 1500.0
    d = loaded_slider()
    d["load"][-1]["stroke"] = stroke
    return d, "F_res_N", "v4_m_s", "s4_m", 0.06, 900.0


@pytest.mark.parametrize("kind", ["rocker", "slider"])
@pytest.mark.parametrize("stroke", ["working", "idle", "both"])
def test_resistance_only_in_its_stroke_and_span_opposing_motion(kind, stroke):
    data, rcol, vcol, ccol, span, R = _resistance_case(kind, stroke)
    res = linkage.analyze(data, crank_angles_deg=np.arange(0.0, 360.0, 0.5))
    k, f = res.kinematics, res.forces
    m = data["mechanism"]
    rocker = kind == "rocker"
    wsign = {"ccw": 1, "cw": -1, "away": m.get("assembly", 1),
             "toward": -m.get("assembly", 1)}[data["analysis"]["working_stroke"]]
    rate = _col(k, vcol)
    val = _col(f, rcol)
    ex = res.extremes
    c_start = {+1: _col(ex, ccol)[0], -1: _col(ex, ccol)[1]}  # start of working/idle
    state = np.sign(rate) * wsign
    if rocker:
        travel = np.abs(np.radians(wrap_deg(_col(k, ccol) - np.where(state > 0, c_start[1],
                                                                       c_start[-1]))))
    else:
        travel = np.abs(_col(k, ccol) - np.where(state > 0, c_start[1], c_start[-1]))
    in_stroke = {"working": state > 0, "idle": state < 0, "both": state != 0}[stroke]
    active = in_stroke & (travel <= span)
    # away from the on/off boundaries (the span's end) the rule is exact
    clear = np.abs(travel - span) > 1e-6
    np.testing.assert_array_equal(val[clear] != 0, active[clear])
    # it opposes the motion, at full magnitude
    assert np.all(val[active] * rate[active] < 0)
    np.testing.assert_allclose(np.abs(val[active]), R)
    assert active.sum() > 10 and (~active).sum() > 10
    # and it shows in the driving moment exactly by its power: ΔM_drive·ω2 = −P_res
    base = copy.deepcopy(data)
    base["load"] = [ld for ld in base["load"] if "resistance_Nm" not in ld
                    and "resistance_N" not in ld]
    f0 = linkage.analyze(base, crank_angles_deg=np.arange(0.0, 360.0, 0.5)).forces
    dM = _col(f, "M_drive_Nm") - _col(f0, "M_drive_Nm")
    scale = R * max(np.max(np.abs(rate)), 1e-300) / abs(m["omega_rad_s"])
    np.testing.assert_allclose(dM * m["omega_rad_s"], -val * rate, rtol=0, atol=1e-9 * scale
                               * abs(m["omega_rad_s"]))


def test_ratchet_resistance_in_the_plan():
    """Seed 000 (domain.md §2): M = 1500 N·m against the rocker's motion only in the
    working stroke and only over the first τ = 1.04 rad of swing: in the 12-position plan
    that is positions 2…5 (position 1 is the extreme, where the rocker stands still;
    position 6 is 62.6° into the stroke, past the span)."""
    f = linkage.analyze(ratchet_data()).forces
    want = [0.0, -1500.0, -1500.0, -1500.0, -1500.0] + [0.0] * 7
    np.testing.assert_array_equal(_col(f, "M_res_Nm"), want)


# ------------------------------------------------------------------ direction of rotation


@pytest.mark.parametrize("name", list(ALL))
def test_reversing_the_crank_reverses_velocities_and_keeps_accelerations(name):
    """ω2 → −ω2 with ε = 0: positions and accelerations (hence every d'Alembert load and
    every reaction) unchanged; ω3, ω4 (v4) and every point velocity reversed.  The
    resistance is removed (it depends on the direction of motion)."""
    data = ALL[name]()
    data["mechanism"]["epsilon_rad_s2"] = 0.0
    data["load"] = [ld for ld in data["load"] if "resistance_Nm" not in ld
                    and "resistance_N" not in ld]
    rev = copy.deepcopy(data)
    rev["mechanism"]["omega_rad_s"] = -data["mechanism"]["omega_rad_s"]
    a = linkage.analyze(data, crank_angles_deg=ANGLES)
    b = linkage.analyze(rev, crank_angles_deg=ANGLES)
    ka, kb = a.kinematics, b.kinematics
    for c in ka.columns:
        if c == "position":
            continue
        x, y = _col(ka, c), _col(kb, c)
        scale = max(np.max(np.abs(x)), 1e-9)
        flips = c.startswith(("omega", "v4")) or "_vx_" in c or "_vy_" in c
        want = -x if flips else x
        assert np.max(np.abs(y - want)) <= 1e-12 * scale, c
        if flips:
            assert np.max(np.abs(x)) > 0, c
    for c in a.forces.columns:
        if c in ("position",):
            continue
        x, y = _col(a.forces, c), _col(b.forces, c)
        assert np.max(np.abs(y - x)) <= 1e-12 * max(np.max(np.abs(x)), 1.0), c


@pytest.mark.parametrize("name", list(ALL))
def test_course_tables_off_leaves_exactly_the_contract_columns(name):
    """``course_tables=False`` drops the derived columns and changes nothing else."""
    data = ALL[name]()
    full = linkage.analyze(data, crank_angles_deg=ANGLES)
    lean = linkage.analyze(data, crank_angles_deg=ANGLES, course_tables=False)
    for a, b in ((full.kinematics, lean.kinematics), (full.forces, lean.forces)):
        assert list(b.columns) == [c for c in a.columns if c in b.columns]
        extra = set(a.columns) - set(b.columns)
        assert extra and all(c.endswith(("_v_m_s", "_a_m_s2")) or c.startswith(
            ("v_B", "a_B", "G", "Fu", "Mu")) or c in ("R12_N", "R23_N", "R43_N", "R14_N")
            for c in extra)
        np.testing.assert_array_equal(a[b.columns].to_numpy(float), b.to_numpy(float))
