"""Plans of the graphical method against the exact solution: every segment is its exact
value ÷ the scale, every polygon closes, the Zhukovsky lever gives the kinetostatic Mур
(virtual power), over the bundled examples and random mechanisms (hypothesis)."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

import linkage
import plans
from crankbase.resources import example_path
from plans import tables
from plans.model import ROUND_MANTISSAS

TOL = 1e-9


@pytest.fixture(scope="module")
def ratchet():
    res = linkage.analyze(example_path("ratchet.toml"))
    return res, plans.build_plans(res, "all")


@pytest.fixture(scope="module")
def press():
    res = linkage.analyze(example_path("press.toml"))
    return res, plans.build_plans(res, "all")


def _all_vectors(pps):
    for pp in pps:
        for plan in pp.plans.values():
            for v in plan.vectors:
                yield pp, plan, v


@pytest.mark.parametrize("which", ["ratchet", "press"])
def test_segment_length_is_value_over_scale(which, request):
    res, pps = request.getfixturevalue(which)
    n = 0
    for pp, plan, v in _all_vectors(pps):
        assert v.scale == plan.scale
        assert math.isclose(v.length_mm, v.value / v.scale, rel_tol=TOL, abs_tol=1e-12), v
        n += 1
    assert n > 12 * 15


@pytest.mark.parametrize("which", ["ratchet", "press"])
def test_segments_equal_the_core_columns(which, request):
    """Lengths against the analysis columns that the plan did not use to draw them
    (speeds, |aB − aA|, aⁿ, aᵗ, reaction magnitudes, inertia forces): value/μ."""
    res, pps = request.getfixturevalue(which)
    K, F = res.kinematics, res.forces
    rocker = res.spec.kind == "crank-rocker"
    for i, pp in enumerate(pps):
        V, A = pp.plans["velocity"], pp.plans["acceleration"]
        D, C = pp.plans["force_dyad"], pp.plans["force_crank"]
        checks = [(V, "pa", K["A_v_m_s"]), (V, "pb", K["B_v_m_s"]), (V, "ab", K["v_BA_m_s"]),
                  (V, "ps3", K["S3_v_m_s"]),
                  (A, "pi_a", K["A_a_m_s2"]), (A, "pi_b", K["B_a_m_s2"]),
                  (A, "ab", K["a_BA_m_s2"]), (A, "a_n3", K["a_BA_n_m_s2"]),
                  (A, "n3_b", K["a_BA_t_m_s2"]), (A, "pi_s3", K["S3_a_m_s2"]),
                  (D, "R43", F["R43_N"]), (D, "Fu3", F["Fu3_N"]), (D, "G3", F["G3_N"]),
                  (D, "R23t", F["R23_t_N"].abs()), (D, "R23n", F["R23_n_N"].abs()),
                  (D, "R14n" if rocker else "R14", (F["R14_n_N"].abs() if rocker
                                                     else F["R14_N"])),
                  (C, "R32", F["R23_N"]), (C, "Fu2", F["Fu2_N"]),
                  (C, "Fb", F["M_drive_Nm"].abs() / res.spec.crank)]
        if rocker:
            checks += [(A, "pi_n4", K["a_BC_n_m_s2"]), (A, "n4_b", K["a_BC_t_m_s2"]),
                       (V, "ps4", K["S4_v_m_s"]), (D, "R14t", F["R14_t_N"].abs())]
        for plan, seg, col in checks:
            v = plan.vector(seg)
            exact = float(col.iat[i])
            assert math.isclose(v.length_mm, exact / plan.scale, rel_tol=TOL,
                                abs_tol=1e-9), (pp.tag, seg, v.length_mm, exact / plan.scale)


@pytest.mark.parametrize("which", ["ratchet", "press"])
def test_every_polygon_closes(which, request):
    res, pps = request.getfixturevalue(which)
    count = 0
    for pp in pps:
        for kind, plan in pp.plans.items():
            errs = plan.closure()
            assert errs, kind
            assert max(errs) < TOL, (pp.tag, kind, errs)
            count += len(errs)
    # velocity 1, acceleration 2 (+1 for a rocker), dyad 2, crank 1 per position
    assert count == len(pps) * (6 + (res.spec.kind == "crank-rocker"))


@pytest.mark.parametrize("which", ["ratchet", "press"])
def test_lever_equals_kinetostatics(which, request):
    res, pps = request.getfixturevalue(which)
    for pp in pps:
        L = pp.lever
        scale = max(1.0, abs(L.M_kinetostatic_Nm))
        assert abs(L.M_lever_Nm - L.M_kinetostatic_Nm) <= TOL * scale, pp.tag
        # arms are measured on the plan: |moment| = |F|·|arm|
        for f in L.forces:
            assert math.isclose(abs(f.moment_Nmm), abs(f.force) * abs(f.arm_mm),
                                rel_tol=1e-12, abs_tol=1e-9)
        # the balancing force at a: arm pa, F·pa balances the sum of the moments
        total = sum(f.moment_Nmm for f in L.forces)
        assert math.isclose(abs(L.balancing_force_N) * L.pa_mm, abs(total), rel_tol=1e-12,
                            abs_tol=1e-9)


def _crank_vectors(res, pp, i):
    """The crank polygon's vectors (N) and, from the analysis columns, A, S2 (m), R12 with
    Mур as a couple, the loads G2, Fu2 and Mu2 of the crank."""
    K, F = res.kinematics, res.forces
    C = pp.plans["force_crank"]
    vec = {v.name: (v.end - v.start) * C.scale for v in C.vectors}
    zA = complex(K["A_x_m"].iat[i], K["A_y_m"].iat[i])
    zS2 = complex(K["S2_x_m"].iat[i], K["S2_y_m"].iat[i])
    R12_couple = complex(F["R12_x_N"].iat[i], F["R12_y_N"].iat[i])
    return vec, zA, zS2, R12_couple


def _cross(a, b):
    return a.real * b.imag - a.imag * b.real


@pytest.mark.parametrize("which", ["ratchet", "press"])
def test_crank_polygon_with_the_balancing_force(which, request):
    """The crank's polygon as the textbook builds it (seed 000 §4; Artobolevsky 1988 §13):
    R32 + G2 + Fu2 + Fур + R12 = 0, Fур at A ⟂ OA with |Fур|·lOA = |Mур| and
    OA × Fур = Mур (the sign that makes its moment about O the kinetostatic Mур).  With
    Fур at A the crank is in equilibrium without the couple: the moments about O of R32,
    G2, Fu2, Fур and the inertia couple Mu2 sum to 0; R12 is then the analysis' R12 (Mур
    a couple) minus Fур."""
    res, pps = request.getfixturevalue(which)
    F = res.forces
    l_OA = res.spec.crank
    for i, pp in enumerate(pps):
        C = pp.plans["force_crank"]
        assert [v.name for v in C.vectors] == (["R32", "G2", "Fu2", "Fb", "R12"])
        assert C.closure()[0] < TOL
        vec, zA, zS2, R12_couple = _crank_vectors(res, pp, i)
        M = float(F["M_drive_Nm"].iat[i])
        Fb = vec["Fb"]
        big = max(abs(v) for v in vec.values())
        assert math.isclose(abs(Fb) * l_OA, abs(M), rel_tol=TOL, abs_tol=1e-9)
        assert abs(Fb.real * zA.real + Fb.imag * zA.imag) <= TOL * abs(Fb) * l_OA  # ⟂ OA
        assert abs(_cross(zA, Fb) - M) <= TOL * max(abs(M), 1.0)                 # sign
        # the crank's moments about O without the couple Mур
        moments = (_cross(zA, vec["R32"]) + _cross(zS2, vec["G2"] + vec["Fu2"])
                   + float(F["Mu2_Nm"].iat[i]) + _cross(zA, Fb))
        assert abs(moments) <= TOL * big * l_OA, (pp.tag, moments)
        assert abs(vec["R12"] - (R12_couple - Fb)) <= TOL * big
        # the lever's Fур (from its moments about the pole) is the same vector
        L = pp.lever
        assert abs(L.balancing_force - Fb) <= TOL * max(abs(Fb), 1.0)
        assert math.isclose(L.balancing_force_N, L.F_kinetostatic_N, rel_tol=TOL,
                            abs_tol=1e-9)
        assert math.isclose(L.F_kinetostatic_N * l_OA, M, rel_tol=TOL, abs_tol=1e-9)
        # plans.csv and the student table carry Fур at μF
        row = tables.plans_table([pp]).query("plan == 'force_crank' and segment == 'Fb'")
        assert len(row) == 1
        assert math.isclose(row["length_mm"].iat[0], abs(M) / l_OA / C.scale, rel_tol=TOL)
        assert row["scale"].iat[0] == C.scale and row["unit"].iat[0] == "N"
    labels = {(v.label_ru, v.label_en) for v in pps[0].plans["force_crank"].vectors}
    assert {("Fур", "Fb"), ("R₁₂", "R₁₂"), ("R₃₂", "R₃₂"), ("G₂", "G₂")} <= labels


def test_balancing_force_catches_a_wrong_sign(ratchet):
    """The checks are not vacuous: Fур reversed (or along OA) breaks the crank's balance
    of moments by 2|Mур| at every position where Mур ≠ 0."""
    res, pps = ratchet
    F = res.forces
    n = 0
    for i, pp in enumerate(pps):
        vec, zA, zS2, _ = _crank_vectors(res, pp, i)
        M = float(F["M_drive_Nm"].iat[i])
        rest = (_cross(zA, vec["R32"]) + _cross(zS2, vec["G2"] + vec["Fu2"])
                + float(F["Mu2_Nm"].iat[i]))
        assert abs(rest + _cross(zA, vec["Fb"])) < 1e-9 * max(1.0, abs(M))
        assert math.isclose(abs(rest - _cross(zA, vec["Fb"])), 2 * abs(M), rel_tol=1e-9)
        assert abs(_cross(zA, vec["Fb"] * 1j)) < 1e-9 * max(1.0, abs(M))   # along OA: no moment
        n += abs(M) > 10.0
    assert n >= 10


def test_couples_of_one_link_are_one_pair_on_the_lever(ratchet):
    """The rocker of the ratchet drive carries its inertia moment Mи4 and the resistance
    Mпс: on the lever they are one couple (their sum) at b and c, not two pairs on one
    line; its moment is that of the two moments."""
    res, pps = ratchet
    combined = 0
    for pp in pps:
        row = res.forces[res.forces["position"] == pp.position].iloc[0]
        names = [f.name for f in pp.lever.forces]
        if row["M_res_Nm"] == 0:                        # idle stroke: Mи4 alone
            assert "Mu4_b" in names and not any("Mres" in n for n in names)
            continue
        combined += 1
        assert not {"Mres_b", "Mres_c", "Mu4_b", "Mu4_c"} & set(names)
        pair = [f for f in pp.lever.forces if f.name.startswith("Mu4+Mres_")]
        assert [f.name for f in pair] == ["Mu4+Mres_b", "Mu4+Mres_c"]
        assert pair[0].label_ru == "F(Mи₄+Mпс)"
        M = row["Mu4_Nm"] + row["M_res_Nm"]                 # the one couple [N·m]
        l4 = res.spec.rocker
        assert abs(pair[0].force) == pytest.approx(abs(M) / l4, rel=TOL)
        assert pair[0].force == pytest.approx(-pair[1].force, rel=TOL)
    assert combined >= 3                                # the working stroke's positions


def test_lever_arrows_to_scale(ratchet, press):
    """Every force on the lever is drawn from its point at the lever's one round force
    scale: the arrow is F/μF (length and direction, 1e-9), the largest within
    (75/1.5, 75] mm; the scale is stated under the title and in plans.csv."""
    from plans import layout
    from plans.model import LEVER_LONGEST_MM

    for res, pps in (ratchet, press):
        for pp in pps:
            L = pp.lever
            arrows = L.arrows()
            assert [a.name for a in arrows] == [f.name for f in L.forces] + ["Fb"]
            for a, f in zip(arrows, L.forces + [None]):
                force = f.force if f is not None else L.balancing_force
                assert a.scale == L.scale
                assert math.isclose(a.length_mm, abs(force) / L.scale, rel_tol=TOL,
                                    abs_tol=1e-12)
                assert abs((a.end - a.start) - force / L.scale) <= TOL * max(a.length_mm, 1)
                assert a.start == (f.at if f is not None else L.balancing_at)
            longest = max(a.length_mm for a in arrows)
            assert LEVER_LONGEST_MM / 1.5 < longest <= LEVER_LONGEST_MM + 1e-9
            m = L.scale / 10 ** math.floor(math.log10(L.scale))
            assert any(math.isclose(m, r, rel_tol=1e-9) for r in ROUND_MANTISSAS)
            # the drawing: one arrow per nonzero force, each of its length in mm
            for lang in ("ru", "en"):
                b = layout.lever_block(pp, lang)
                drawn = {it.name.split(":")[-1]: abs(it.p2 - it.p1) for it in b.items
                         if isinstance(it, layout.Arrow) and it.layer == "LEVER"}
                expect = {a.name: a.length_mm for a in arrows if a.length_mm >= 1e-6}
                assert drawn.keys() == expect.keys()
                for k, v in expect.items():
                    assert math.isclose(drawn[k], v, rel_tol=TOL), k
                mu = "μF" if lang == "ru" else "kF"
                scale_text = f"{mu} = {layout.fmt(L.scale, lang)} " + (
                    "Н/мм" if lang == "ru" else "N/mm")
                assert any(isinstance(it, layout.Text) and scale_text in it.text
                           for it in b.items), scale_text
            rows = tables.plans_table([pp]).query("plan == 'lever'")
            assert rows["segment"].tolist() == [a.name for a in arrows]
            assert (rows["scale"] == L.scale).all()
            assert np.allclose(rows["length_mm"], rows["value"] / L.scale, rtol=TOL)
    # a given lever scale is used as it is
    res, _ = ratchet
    pp = plans.build_plans(res, [5], scales={"lever": 25.0})[0]
    assert pp.lever.scale == 25.0
    assert math.isclose(pp.lever.arrows()[-1].length_mm,
                        abs(pp.lever.balancing_force_N) / 25.0, rel_tol=1e-12)


def test_lever_catches_a_wrong_sign(ratchet):
    """The check is not vacuous: dropping the inertia couples or flipping a weight moves
    the lever's Mур away from the kinetostatic one."""
    res, pps = ratchet
    L = pps[4].lever
    total = sum(f.moment_Nmm for f in L.forces if not f.name.startswith("Mu"))
    mu = pps[4].plans["velocity"].scale
    assert abs(-total * mu / res.spec.omega - L.M_kinetostatic_Nm) > 1.0


def _side(P):
    x0, y0, x1, y1 = P.bbox()
    return max(x1 - x0, y1 - y0)


def test_round_scales(ratchet, press):
    """Reference vector in (100, 150] mm, unless the whole plan would exceed 250 mm: then
    the plan is within (250/1.5, 250] mm."""
    binding = 0
    for res, pps in (ratchet, press):
        for pp in pps:
            for kind, ref in (("velocity", "pa"), ("acceleration", "pi_a"),
                              ("force_dyad", None), ("force_crank", None)):
                P = pp.plans[kind]
                big = (P.vector(ref).length_mm if ref else
                       max(v.length_mm for v in P.vectors if v.name != "R43"))
                side = _side(P)
                assert big <= 150.0 + 1e-9 and side <= 250.0 + 1e-9, (pp.tag, kind)
                assert big > 100.0 or side > 250.0 / 1.5, (pp.tag, kind, big, side)
                binding += big <= 100.0
            for P in pp.plans.values():
                m = P.scale / 10 ** math.floor(math.log10(P.scale))
                assert any(math.isclose(m, r, rel_tol=1e-9) for r in ROUND_MANTISSAS), P.scale
    # seed 000: VA = 2.975 m/s → μV = 0.02 (pa = 148.75 mm); aA = 50.575 → μa = 0.4
    assert plans.round_scale(2.975) == 0.02
    assert plans.round_scale(50.575) == 0.4
    assert plans.round_scale(150.0) == 1.0 and plans.round_scale(150.0001) == 1.5


def test_angular_values_read_off_the_plans(ratchet):
    res, pps = ratchet
    K = res.kinematics
    for i, pp in enumerate(pps):
        got = {a["quantity"]: a["value"] for a in pp.angular}
        for q, col in (("omega3", "omega3_rad_s"), ("omega4", "omega4_rad_s"),
                       ("eps3", "eps3_rad_s2"), ("eps4", "eps4_rad_s2")):
            assert math.isclose(got[q], abs(K[col].iat[i]), rel_tol=TOL, abs_tol=1e-12)


def test_tables(ratchet):
    res, pps = ratchet
    pt = tables.plans_table(pps)
    assert list(pt.columns) == ["position", "plan", "segment", "length_mm", "value", "unit",
                                "scale"]
    assert np.allclose(pt["length_mm"], pt["value"] / pt["scale"], rtol=TOL)
    lt = tables.lever_table(pps)
    assert list(lt.columns) == ["position", "M_lever_Nm", "M_kinetostatic_Nm",
                                "difference_percent", "F_lever_N", "F_kinetostatic_N",
                                "scale_N_per_mm"]
    assert (lt["difference_percent"].abs() < 1e-9).all()
    assert np.allclose(lt["F_lever_N"], lt["F_kinetostatic_N"], rtol=TOL, atol=1e-9)
    assert np.allclose(lt["F_kinetostatic_N"] * res.spec.crank, lt["M_kinetostatic_Nm"],
                       rtol=TOL)
    lf = tables.lever_forces_table(pps)
    assert np.allclose(lf["length_mm"], lf["F_N"] / lf["scale"], rtol=TOL)
    assert lt["position"].tolist() == list(range(1, 13))


def test_error_table_of_a_student(ratchet, tmp_path):
    """Seed 000, Table 3.3: δ = (exact − plan)/exact·100 %.  A student who measures every
    segment 2 % short gets +2 %; values given directly are compared as they are."""
    res, pps = ratchet
    st_ = tables.student_table(pps[4:5])
    rows = st_[st_["plan"] == "velocity"]
    csv = tmp_path / "measured.csv"
    lines = ["position,plan,segment,length_mm,value"]
    for _, r in rows.iterrows():
        if r["quantity"].startswith("omega"):
            lines.append(f"{r['position']},,{r['quantity']},,{r['value'] * 1.034}")
        else:
            lines.append(f"{r['position']},velocity,{r['segment']},{r['length_mm'] * 0.98},")
    csv.write_text("\n".join(lines) + "\n")
    m = tables.read_measurements(csv)
    et = tables.error_table(st_, m)
    assert len(et) == len(rows)
    # "ab" is in both kinematic plans: without the plan column it is ambiguous
    with pytest.raises(plans.PlanError, match="more than one segment 'ab'"):
        tables.error_table(st_, m.drop(columns="plan"))
    seg = et[~et["quantity"].str.startswith("omega")]
    assert np.allclose(seg["error_percent"], 2.0, atol=1e-9)
    om = et[et["quantity"].str.startswith("omega")]
    assert len(om) == 2 and np.allclose(om["error_percent"], -3.4, atol=1e-9)


def test_bad_measurements(tmp_path):
    csv = tmp_path / "m.csv"
    csv.write_text("position,segment,length_mm,value\n5,pa,,\n5,pb,-3,\n5,ab,1,2\n")
    with pytest.raises(plans.PlanError) as e:
        tables.read_measurements(csv)
    assert len(e.value.problems) == 3
    csv.write_text("pos,segment,length_mm\n")
    with pytest.raises(plans.PlanError, match="position"):
        tables.read_measurements(csv)


def test_bad_requests(ratchet):
    res, _ = ratchet
    with pytest.raises(plans.PlanError, match="position 13"):
        plans.build_plans(res, [5, 13])
    with pytest.raises(plans.PlanError, match="scales.velocity"):
        plans.build_plans(res, [5], scales={"velocity": -1.0})
    spec = dict(linkage.load_spec(example_path("ratchet.toml")).raw)
    spec = {k: dict(v) if isinstance(v, dict) else v for k, v in spec.items()}
    spec["mechanism"]["omega_rad_s"] = 0.0
    spec["load"] = []
    spec["analysis"] = {"crank_angles_deg": [30.0]}
    st_res = linkage.analyze(spec)
    with pytest.raises(plans.PlanError, match="statics"):
        plans.build_plans(st_res)
    with pytest.raises(plans.PlanError, match="course_tables"):
        plans.build_plans(linkage.analyze(example_path("ratchet.toml"), course_tables=False))


def test_given_scales_are_used(ratchet):
    """Seed 000 §3.2.1–3.3.1: pa = 150 mm gives μV = 2.975/150; πa = 100 mm gives
    μa = 0.50575; then ps2 = pa·OS2/OA = 68.6 mm and πs2 = 45.71 mm as printed."""
    res, _ = ratchet
    pp = plans.build_plans(res, [5], scales={"velocity": 2.975 / 150,
                                             "acceleration": 0.50575})[0]
    V, A = pp.plans["velocity"], pp.plans["acceleration"]
    assert math.isclose(V.vector("pa").length_mm, 150.0, rel_tol=1e-12)
    assert round(V.vector("ps2").length_mm, 1) == 68.6          # seed 000: "рs2 = 68,6 мм"
    assert math.isclose(A.vector("pi_a").length_mm, 100.0, rel_tol=1e-12)
    assert round(A.vector("pi_s2").length_mm, 2) == 45.71       # seed 000: "pS2 = 45,71 мм"
    assert math.isclose(V.vector("pa").value, 2.975, rel_tol=1e-12)     # VA = 2,975 м/с
    assert math.isclose(A.vector("pi_a").value, 50.575, rel_tol=1e-12)  # aA = 50,575 м/с²


# --------------------------------------------------------------------- hypothesis


@st.composite
def mechanisms(draw):
    kind = draw(st.sampled_from(["crank-rocker", "crank-slider"]))
    crank = draw(st.floats(0.05, 0.2))
    omega = draw(st.sampled_from([-1, 1])) * draw(st.floats(2.0, 40.0))
    eps = draw(st.sampled_from([0.0, draw(st.floats(-50.0, 50.0))]))
    mech = {"kind": kind, "name": "random", "crank": crank, "omega_rad_s": omega,
            "epsilon_rad_s2": eps, "gravity_m_s2": draw(st.sampled_from([0.0, 9.81])),
            "assembly": draw(st.sampled_from([1, -1]))}
    if kind == "crank-rocker":
        coupler, rocker = draw(st.floats(0.4, 1.2)), draw(st.floats(0.4, 1.2))
        ground = 1.0
        ls = sorted([crank, coupler, rocker, ground])
        assume(ls[0] == crank and ls[0] + ls[3] <= ls[1] + ls[2] - 0.05)
        mech.update(coupler=coupler, rocker=rocker, ground=ground,
                    ground_angle_deg=draw(st.floats(-30, 30)))
        out = "rocker"
    else:
        mech.update(coupler=draw(st.floats(0.4, 1.0)), offset=draw(st.floats(-0.1, 0.1)),
                    ground_angle_deg=draw(st.floats(-90, 90)))
        out = "slider"

    def link(name, bar):
        d = {"mass_kg": draw(st.floats(0.0, 30.0))}
        if bar:
            d["inertia_kg_m2"] = draw(st.floats(0.0, 1.0))
            d["cg"] = [draw(st.floats(0.0, 0.3)), draw(st.floats(-0.05, 0.05))]
        return d

    links = {"crank": link("crank", True), "coupler": link("coupler", True),
             out: link(out, out == "rocker")}
    loads = [{"link": "coupler", "at": [draw(st.floats(0, 0.4)), draw(st.floats(-0.1, 0.1))],
              "force_N": [draw(st.floats(-500, 500)), draw(st.floats(-500, 500))]},
             {"link": draw(st.sampled_from(["crank", "coupler", out])),
              "moment_Nm": draw(st.floats(-200, 200))}]
    if kind == "crank-rocker":
        loads.append({"link": "rocker", "resistance_Nm": draw(st.floats(0, 800)),
                      "stroke": "both"})
    else:
        loads.append({"link": "slider", "resistance_N": draw(st.floats(0, 3000)),
                      "stroke": "both"})
    angles = draw(st.lists(st.floats(0, 359), min_size=1, max_size=3))
    return {"mechanism": mech, "links": links, "load": loads,
            "analysis": {"crank_angles_deg": angles}}


@settings(max_examples=40, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(mechanisms())
def test_random_mechanisms(spec):
    res = linkage.analyze(spec)
    F = res.forces
    assume(np.isfinite(F["M_drive_Nm"]).all())
    # keep clear of dead positions, where the plans have no finite scale
    assume((res.kinematics["mu_deg"] > 5).all())
    pps = plans.build_plans(res)
    for pp in pps:
        L = pp.lever
        big = max([abs(f.moment_Nmm) for f in L.forces] + [1e-300])
        mu = pp.plans["velocity"].scale
        # tolerance relative to the largest term of the power balance
        scale = max(abs(L.M_kinetostatic_Nm), big * mu / abs(res.spec.omega))
        assert abs(L.M_lever_Nm - L.M_kinetostatic_Nm) <= TOL * scale
        # Fур: from the lever equal to the kinetostatic one; OA × Fур = Mур, ⟂ OA
        l_OA = res.spec.crank
        assert abs(L.balancing_force_N - L.F_kinetostatic_N) <= TOL * scale / l_OA
        C = pp.plans["force_crank"]
        Fb = (C.vector("Fb").end - C.vector("Fb").start) * C.scale
        assert abs(L.balancing_force - Fb) <= TOL * scale / l_OA
        i = pps.index(pp)
        zA = complex(res.kinematics["A_x_m"].iat[i], res.kinematics["A_y_m"].iat[i])
        M = float(F["M_drive_Nm"].iat[i])
        assert abs(_cross(zA, Fb) - M) <= TOL * max(abs(M), 1e-6)
        assert abs(Fb.real * zA.real + Fb.imag * zA.imag) <= TOL * max(abs(M), 1e-6)
        R12 = complex(F["R12_x_N"].iat[i], F["R12_y_N"].iat[i]) - Fb
        big = max(v.length_mm for v in C.vectors) * C.scale
        assert abs((C.vector("R12").end - C.vector("R12").start) * C.scale - R12) <= TOL * big
        # the lever's arrows: F/μF
        for a in L.arrows():
            assert math.isclose(a.length_mm, a.value / L.scale, rel_tol=TOL, abs_tol=1e-12)
        for kind, plan in pp.plans.items():
            assert max(plan.closure()) < TOL, kind
            for v in plan.vectors:
                assert math.isclose(v.length_mm, v.value / v.scale, rel_tol=TOL,
                                    abs_tol=1e-12)


def test_import_is_light():
    """Importing the plans (model and tables) pulls in neither matplotlib nor ezdxf."""
    import subprocess
    import sys

    code = ("import sys, plans, plans.tables; "
            "bad = [m for m in ('matplotlib', 'ezdxf', 'openpyxl') if m in sys.modules]; "
            "print(bad); sys.exit(1 if bad else 0)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


@settings(max_examples=6, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(mechanisms())
def test_random_sheets_have_no_overlapping_labels(spec):
    from plans import drawing

    res = linkage.analyze(spec)
    assume(np.isfinite(res.forces["M_drive_Nm"]).all())
    assume((res.kinematics["mu_deg"] > 5).all())
    pps = plans.build_plans(res, [1])
    for sh in drawing.layout_sheets(res, pps, "en", "A1"):
        assert drawing.check_no_overlap(sh.items) == []
