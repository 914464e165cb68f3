"""The four-bar's plans against the chain's construction of the same mechanism (issue #20).

A crank-rocker or crank-slider spec written as the chain spec it is
(:func:`linkage.analysis.as_chain`: the crank and one RRR or RRP group) is tabulated by
:mod:`linkage.chain_analysis` and drawn by :func:`plans.build_chain_plans`; the four-bar
itself by :func:`linkage.analyze`'s course columns and :func:`plans.build_plans`.  Two
constructions of the plans from two tables: under the one naming rule
:func:`plans.chain_model.fourbar_name` every segment of the velocity and acceleration
plans has the same ends on paper, every force of the polygons the same value, and the
lever the same Fур and Mур, so a wrong sign, factor or swapped angle in either shows.
(The four-bar's dyad polygon draws R23 and a rocker's R14 in their n and t components,
the textbook's construction; the chain's draws them whole.)

Then each construction on its own against the analysis columns (not against the other),
so that a mistake both made would still show: every vector of the velocity and
acceleration plans, as a complex vector, is the analysis' V or a of its point, V_B − V_A,
−ω²·AB, iε·AB (and about C for a rocker, about O for a crank with ε ≠ 0) over the scale.
"""
from __future__ import annotations

import math

import pytest

import linkage
from crankbase.resources import example_path
from linkage.analysis import as_chain
from plans import build_chain_plans, build_plans
from plans.chain_model import fourbar_name

EXAMPLES = ["ratchet.toml", "press.toml"]


@pytest.fixture(scope="module", params=EXAMPLES)
def pair(request):
    spec = linkage.load_spec(example_path(request.param))
    four = build_plans(linkage.analyze(spec))
    chain = build_chain_plans(linkage.analyze(as_chain(spec)))
    assert len(four) == len(chain) == spec.positions
    return spec, four, chain


def _close(z1, z2, size=1.0, rel=1e-9):
    return abs(z1 - z2) <= rel * max(1.0, size)


def test_naming_rule():
    names = ["a_b", "pole_n3", "n3_b", "a_n2", "ps1", "pi_s3", "R21", "R01", "R03", "R32",
             "force_2_3", "force_crank", "omega2", "eps3", "pa", "pi_e", "Fb", "πn₃", "R₂₁"]
    assert [fourbar_name(n) for n in names] == [
        "ab", "pi_n4", "n4_b", "a_n3", "ps2", "pi_s4", "R32", "R12", "R14", "R43",
        "force_dyad", "force_crank", "omega3", "eps4", "pa", "pi_e", "Fb", "πn₄", "R₃₂"]


def test_the_chain_is_the_four_bar_s_mechanism(pair):
    spec, four, chain = pair
    assert tuple(as_chain(spec).mechanism.link_names) == tuple(spec.link_names)
    for a, b in zip(four, chain):
        assert a.position == b.position
        assert b.phi_deg == pytest.approx(a.phi_deg, abs=1e-9)
        for j in ("O", "A", "B") + (("C",) if spec.kind == "crank-rocker" else ()):
            assert _close(a.geometry[j], b.geometry[j], rel=1e-12), j


@pytest.mark.parametrize("kind", ["velocity", "acceleration"])
def test_kinematic_plans_have_the_same_segments(pair, kind):
    spec, four, chain = pair
    for a, b in zip(four, chain):
        pa, pb = a.plans[kind], b.plans[kind]
        assert pa.scale == pb.scale
        x0, y0, x1, y1 = pa.bbox()
        size = max(x1 - x0, y1 - y0)
        seen = set()
        for v in pb.vectors:
            name = fourbar_name(v.name)
            if name not in {u.name for u in pa.vectors}:
                # the slider's centre of mass translates with B: the four-bar draws pb only
                assert spec.kind == "crank-slider" and name.endswith("s4"), name
                pole_b = pb.vector("pb" if kind == "velocity" else "pi_b")
                assert _close(v.end, pole_b.end, size)
                continue
            u = pa.vector(name)
            seen.add(name)
            assert _close(u.start, v.start, size) and _close(u.end, v.end, size), name
            assert u.quantity == fourbar_name(v.quantity)
            assert (u.label_ru, u.label_en) == (fourbar_name(v.label_ru),
                                                fourbar_name(v.label_en)), name
            assert u.value == pytest.approx(v.value, rel=1e-9)
        extra = {u.name for u in pa.vectors} - seen
        if kind == "acceleration":
            # the four-bar also draws a_BA whole, from a to b
            assert extra == {"ab"}
            ab = pa.vector("ab")
            assert _close(ab.start, pb.vector("pi_a").end, size)
            assert _close(ab.end, pb.vector("pi_b").end, size)
        else:
            assert extra == set()
        for key, z in pb.points.items():
            if fourbar_name(key) not in pa.points:         # the slider's S4, drawn at b
                assert spec.kind == "crank-slider" and key == "s3"
                assert _close(z, pa.points["b"], size)
                continue
            assert _close(pa.points[fourbar_name(key)], z, size), key


def _forces(plan):
    return {v.name: (v.end - v.start) * plan.scale for v in plan.vectors}


def test_force_polygons_have_the_same_forces(pair):
    spec, four, chain = pair
    for a, b in zip(four, chain):
        fc = {fourbar_name(k): F for k, F in _forces(b.plans["force_crank"]).items()}
        fa = _forces(a.plans["force_crank"])
        big = max(abs(F) for F in fa.values())
        assert set(fa) == set(fc)
        for k in fa:
            assert _close(fa[k], fc[k], big), k
        fd = {fourbar_name(k): F for k, F in _forces(b.plans["force_2_3"]).items()}
        fa = _forces(a.plans["force_dyad"])
        big = max(abs(F) for F in fa.values())
        assert set(b.plans) == {"velocity", "acceleration", "force_2_3", "force_crank"}
        # the four-bar's R23 in its components ⟂ and along AB
        e3 = a.geometry["B"] - a.geometry["A"]
        assert abs((fa["R23t"] * e3.conjugate()).real) <= 1e-9 * big * abs(e3)
        assert abs((fa["R23n"] * e3.conjugate()).imag) <= 1e-9 * big * abs(e3)
        assert _close(fa["R23t"] + fa["R23n"], fd["R23"], big)
        R14 = fa["R14t"] + fa["R14n"] if spec.kind == "crank-rocker" else fa["R14"]
        assert _close(R14, fd["R14"], big)
        for k in ("R43", "G3", "Fu3", "G4", "Fu4"):
            assert _close(fa[k], fd[k], big), k
        # the output's other loads: the chain's resultant F4 (zero: none drawn)
        rest = sum(F for k, F in fa.items() if k in ("Fres",) or k.startswith("F4_"))
        assert _close(rest, fd.get("F4", 0j), big)


def test_lever_and_angular_velocities_agree(pair):
    spec, four, chain = pair
    for a, b in zip(four, chain):
        la, lb = a.lever, b.lever
        assert la.M_kinetostatic_Nm == pytest.approx(lb.M_kinetostatic_Nm, rel=1e-9,
                                                     abs=1e-9)
        assert la.M_lever_Nm == pytest.approx(lb.M_lever_Nm, rel=1e-9, abs=1e-9)
        assert la.balancing_force_N == pytest.approx(lb.balancing_force_N, rel=1e-9,
                                                      abs=1e-9)
        assert _close(la.balancing_dir, lb.balancing_dir)
        ang = {r["quantity"]: r for r in a.angular}
        assert set(ang) == {fourbar_name(r["quantity"]) for r in b.angular}
        for r in b.angular:
            q = ang[fourbar_name(r["quantity"])]
            assert q["segment"] == fourbar_name(r["segment"])
            assert q["signed_value"] == pytest.approx(r["signed_value"], rel=1e-9, abs=1e-9)
            assert q["value"] == pytest.approx(r["value"], rel=1e-9, abs=1e-9)


# --------------------------------------------------------------------------------------
# Each construction on its own against the analysis (not against the other one): every
# drawn vector of a four-bar's velocity and acceleration plans, as a vector (direction and
# sense, not only its length), is the analysis' quantity over the plan's scale.  A plan
# turned, mirrored, drawn from the wrong image or with ω for ε fails here, in either
# construction, even if both made the same mistake.

KHURMI_EPS = {"mechanism": {"kind": "crank-rocker", "name": "khurmi-8-2-eps", "crank": 0.0625,
                            "coupler": 0.175, "rocker": 0.1125, "ground": 0.2, "assembly": 1,
                            "omega_rad_s": -10.0, "epsilon_rad_s2": 40.0,
                            "gravity_m_s2": 0.0},
              "analysis": {"crank_angles_deg": [60.0, 200.0]}}
"""R. S. Khurmi & J. K. Gupta, A Textbook of Theory of Machines, 2005, Example 8.2's
four-bar (the published answers are checked in tests/test_plans_published.py), here with a
crank accelerating clockwise (ε ≠ 0: aⁿ_AO and aᵗ_AO drawn) at two angles."""


def _four_bar_spec(which):
    if which == "khurmi-eps":
        return linkage.load_spec(KHURMI_EPS)
    return linkage.load_spec(example_path(which))


def _plans_of(spec, construction):
    """Four-bar names for both: the chain's through :func:`fourbar_name`."""
    if construction == "four-bar":
        return build_plans(linkage.analyze(spec))
    out = []
    for pp in build_chain_plans(linkage.analyze(as_chain(spec))):
        renamed = {}
        for kind, plan in pp.plans.items():
            vecs = {fourbar_name(v.name): v for v in plan.vectors}
            pts = {fourbar_name(k): z for k, z in plan.points.items()}
            renamed[fourbar_name(kind)] = (plan.scale, vecs, pts)
        out.append(renamed)
    return out


def _as_dicts(pp):
    if isinstance(pp, dict):
        return pp
    return {k: (p.scale, {v.name: v for v in p.vectors}, p.points) for k, p in pp.plans.items()}


@pytest.mark.parametrize("construction", ["four-bar", "chain"])
@pytest.mark.parametrize("which", ["ratchet.toml", "press.toml", "khurmi-eps"])
def test_plan_vectors_are_the_analysis_quantities_over_the_scale(which, construction):
    spec = _four_bar_spec(which)
    res = linkage.analyze(spec)
    K = res.kinematics
    rocker = spec.kind == "crank-rocker"
    pps = _plans_of(spec, construction)
    assert len(pps) == len(K)
    zC = complex(spec.ground * math.cos(spec.ground_angle),
                 spec.ground * math.sin(spec.ground_angle)) if rocker else None
    checked = 0
    for i, pp in enumerate(pps):
        plans_ = _as_dicts(pp)

        def col(p, what):
            sx = {"": ("_x_m", "_y_m"), "v": ("_vx_m_s", "_vy_m_s"),
                  "a": ("_ax_m_s2", "_ay_m_s2")}[what]
            return complex(K[p + sx[0]].iat[i], K[p + sx[1]].iat[i])

        zA, zB = col("A", ""), col("B", "")
        w3, e3 = K["omega3_rad_s"].iat[i], K["eps3_rad_s2"].iat[i]
        for kind, what, pole in (("velocity", "v", "p"), ("acceleration", "a", "pi_")):
            mu, vecs, pts = plans_[kind]
            size = max(abs(z) for z in pts.values())

            def seg(name):
                v = vecs[name]
                return v.start * mu, v.end * mu

            # every absolute vector from the pole to a point's image: that point's V or a
            for name in vecs:
                key = name[len(pole):]
                if not name.startswith(pole) or key[:1] == "n":     # aⁿ from the pole
                    continue
                s, e = seg(name)
                exact = col(key.upper(), what)
                assert abs(s) == 0.0, (which, construction, name)
                assert _close(e, exact, abs(exact), rel=1e-9), (which, construction, i, name,
                                                                e, exact)
                assert _close(pts[key] * mu, exact, abs(exact), rel=1e-9), (name, key)
                checked += 1
            if kind == "velocity":
                # the relative vector from a to b: V_B − V_A of the analysis, = iω3·AB
                s, e = seg("ab")
                assert _close(s, col("A", "v"), size * mu)
                assert _close(e - s, col("B", "v") - col("A", "v"), size * mu), (which, i)
                assert _close(e - s, 1j * w3 * (zB - zA), size * mu)
                continue
            # B about A: aⁿ = −ω3²·AB from a (towards A), aᵗ = iε3·AB from its end
            s, e = seg("a_n3")
            assert _close(s, col("A", "a"), size * mu)
            assert _close(e - s, -w3 * w3 * (zB - zA), size * mu), (which, construction, i)
            s2, e2 = seg("n3_b")
            assert _close(s2, e, size * mu)
            assert _close(e2 - s2, 1j * e3 * (zB - zA), size * mu), (which, construction, i)
            assert _close(e2, col("B", "a"), size * mu)
            if rocker:        # B about the fixed C: −ω4²·CB from the pole, then iε4·CB
                w4, e4 = K["omega4_rad_s"].iat[i], K["eps4_rad_s2"].iat[i]
                s, e = seg("pi_n4")
                assert abs(s) == 0.0
                assert _close(e, -w4 * w4 * (zB - zC), size * mu), (which, construction, i)
                s2, e2 = seg("n4_b")
                assert _close(s2, e, size * mu)
                assert _close(e2 - s2, 1j * e4 * (zB - zC), size * mu)
            if spec.epsilon != 0:   # the crank pin: aⁿ_AO = −ω²·OA, aᵗ_AO = iε·OA
                s, e = seg("pi_n2")
                assert _close(e, -spec.omega ** 2 * zA, size * mu)
                s2, e2 = seg("n2_a")
                assert _close(s2, e, size * mu)
                assert _close(e2 - s2, 1j * spec.epsilon * zA, size * mu)
                assert _close(e2, col("A", "a"), size * mu)
            else:
                assert "pi_n2" not in vecs
    # a, b and each centre of mass or named point, in both plans, at every position
    assert checked >= len(pps) * 2 * (2 + (which != "khurmi-eps"))
