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
"""
from __future__ import annotations

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
