"""Velocity and acceleration plans of chains of class II groups (plans.chain_model, issue #20).

Every vector of the plans is checked against the chain analysis' own table columns
(``v_<joint>_m_s``, ``omega_<link>_rad_s``, ``vrel_…``, ``acorx_…``), so a wrong sign,
factor or swapped angle in the plans shows; every vector polygon the course draws
(V_B = V_A + V_BA …, a_A3 = a_A2 + aᵏ_A3A2 + aʳ_A3A2 …) closes; the sheet holds the plans
without overlapping labels.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

import linkage
from crankbase.resources import example_path
from plans import drawing, layout
from plans.chain_model import build_chain_plans
from plans.model import ROUND_MANTISSAS, Plan

EXAMPLES = [("shaper.toml", [2, 5]), ("press6.toml", [1, 4]),
            ("compressor_v.toml", [3, 7]), ("sixbar_rrr.toml", [2, 9]),
            ("shaper_cn.toml", [4, 9])]


@pytest.fixture(scope="module", params=EXAMPLES, ids=[e[0] for e in EXAMPLES])
def case(request):
    name, chosen = request.param
    res = linkage.analyze(example_path(name))
    return res, chosen, build_chain_plans(res, chosen)


@pytest.fixture(scope="module")
def case_sheets(case):
    """``case_sheets(lang, size)``: the case's sheets (:func:`plans.drawing.layout_sheets`),
    laid out once per module for the tests that read them (the ru A1 sheets are read by
    two)."""
    res, chosen, pps = case
    memo = {}

    def get(lang, size):
        if (lang, size) not in memo:
            memo[lang, size] = drawing.layout_sheets(res, pps, lang, size)
        return memo[lang, size]
    return get


@pytest.fixture(scope="module")
def shaper():
    res = linkage.analyze(example_path("shaper.toml"))
    return res, build_chain_plans(res, [2, 5])


def _row(res, pp):
    K = res.kinematics
    return int(np.flatnonzero(K["position"].to_numpy() == pp.position)[0])


def test_every_polygon_closes(case):
    res, _, pps = case
    for pp in pps:
        for kind, plan in pp.plans.items():
            assert plan.polygons, kind
            assert max(plan.closure()) < 1e-12, (kind, plan.closure())


def test_absolute_vectors_are_the_chain_columns(case):
    """|p→x|·μv = v_X and |π→x|·μa = a_X for every joint and named point in the tables."""
    res, _, pps = case
    K = res.kinematics
    for pp in pps:
        i = _row(res, pp)
        checked = 0
        for kind, col in (("velocity", "vx_{}_m_s"), ("acceleration", "ax_{}_m_s2")):
            plan = pp.plans[kind]
            for v in plan.vectors:
                if v.kind != "absolute":
                    continue
                point = v.quantity.split("_", 1)[1]
                cx = col.format(point)
                if cx not in K.columns:
                    continue
                exact = complex(K[cx].iat[i], K[cx.replace("x_", "y_", 1)].iat[i])
                assert v.start == 0
                # the vector itself (direction too), at the plan's scale
                assert abs(v.end * plan.scale - exact) <= 1e-9 * max(1.0, abs(exact))
                assert v.length_mm == pytest.approx(v.value / v.scale, rel=1e-12)
                checked += 1
        assert checked >= 6


def test_scales_are_round_and_the_reference_fits(case):
    res, _, pps = case
    for pp in pps:
        for kind, ref in (("velocity", "pa"), ("acceleration", "pi_a")):
            plan = pp.plans[kind]
            m = plan.scale / 10 ** math.floor(math.log10(plan.scale) + 1e-12)
            assert any(abs(m - r) < 1e-9 for r in ROUND_MANTISSAS), plan.scale
            assert plan.vector(ref).length_mm <= 150 + 1e-9
            x0, y0, x1, y1 = plan.bbox()
            assert max(x1 - x0, y1 - y0) <= 250 + 1e-9


def test_slotted_lever_velocity_plan(shaper):
    """The shaper's RPR: V_A3 = V_A2 + V_A3A2, V_A3A2 along the slot with |v_rel|, V_A3 ⟂ CA
    with |ω_lever|·CA; D on the lever: pd/pa3 = CD/CA (similarity)."""
    res, pps = shaper
    K = res.kinematics
    mech = res.spec.mechanism
    for pp in pps:
        i = _row(res, pp)
        vp = pp.plans["velocity"]
        mu = vp.scale
        zA, zC, zD = pp.geometry["A"], pp.geometry["C"], complex(K["x_D_m"].iat[i],
                                                                  K["y_D_m"].iat[i])
        slot = (zA - zC) / abs(zA - zC)
        rel = vp.vector("a_a3")
        d = (rel.end - rel.start) * mu
        assert abs(d) == pytest.approx(abs(K["vrel_block_lever_m_s"].iat[i]), rel=1e-9)
        assert abs((d / slot).imag) < 1e-9 * abs(d)                # along the slot
        a3 = vp.vector("pa3").end * mu
        w = K["omega_lever_rad_s"].iat[i]
        assert a3 == pytest.approx(1j * w * (zA - zC), rel=1e-9)  # sign of ω too
        assert abs(vp.vector("pd").end / vp.vector("pa3").end) == pytest.approx(
            abs(zD - zC) / abs(zA - zC), rel=1e-9)
        assert mech.groups[0].kind == "RPR"


def test_slotted_lever_acceleration_plan(shaper):
    """a_A3 = a_A2 + aᵏ_A3A2 + aʳ_A3A2 = aⁿ_A3C + aᵗ_A3C: the Coriolis vector is
    2ω3·i·V_A3A2 (the chain's column acor of the block relative to the lever, reversed),
    aⁿ = ω²·CA towards C, aᵗ = |ε|·CA."""
    res, pps = shaper
    K = res.kinematics
    for pp in pps:
        i = _row(res, pp)
        ap, vp = pp.plans["acceleration"], pp.plans["velocity"]
        zA, zC = pp.geometry["A"], pp.geometry["C"]
        w, e = K["omega_lever_rad_s"].iat[i], K["eps_lever_rad_s2"].iat[i]
        k = ap.vector("a_k_a3")
        cor = (k.end - k.start) * ap.scale
        col = complex(K["acorx_block_lever_m_s2"].iat[i], K["acory_block_lever_m_s2"].iat[i])
        assert cor == pytest.approx(-col, rel=1e-9)
        vrel = (vp.vector("a_a3").end - vp.vector("a_a3").start) * vp.scale
        assert cor == pytest.approx(2 * w * 1j * vrel, rel=1e-9)
        n = ap.vector("pole_n3")
        assert (n.end - n.start) * ap.scale == pytest.approx(-w * w * (zA - zC), rel=1e-9)
        t = ap.vector("n3_a3")
        assert (t.end - t.start) * ap.scale == pytest.approx(1j * e * (zA - zC), rel=1e-9)
        r = ap.vector("k_a3_a3")
        assert abs(r.end - r.start) * ap.scale == pytest.approx(
            abs(K["arel_block_lever_m_s2"].iat[i]), rel=1e-9)


def test_a_wrong_coriolis_sign_does_not_close(shaper):
    """The closure check is a real check: the Coriolis vector reversed opens the polygon."""
    _, pps = shaper
    ap = pps[0].plans["acceleration"]
    k = ap.vector("a_k_a3")
    bad = [v if v.name != "a_k_a3" else type(v)(**{**vars(v), "end": 2 * k.start - k.end})
           for v in ap.vectors]
    wrong = Plan(ap.kind, ap.scale, ap.unit, ap.points, ap.point_labels, bad, ap.polygons)
    assert max(wrong.closure()) > 0.1


def test_rotation_of_the_rods(case):
    """|V_BA| = |ω|·l and |aᵗ_BA| = |ε|·l of every rod with a relative rotation vector."""
    res, _, pps = case
    K = res.kinematics
    mech = res.spec.mechanism
    seen = 0
    for pp in pps:
        i = _row(res, pp)
        for grp in mech.groups:
            if grp.kind not in ("RRR", "RRP"):
                continue
            jA, jB = grp.joints[0], grp.joints[1]
            if jA in mech.frame:
                continue
            ka, kb = (j.lower() + ("_pt" if j.lower() in ("p", "pi") else "")
                      for j in (jA, jB))              # a point P apart from the pole p
            link = grp.links[0]
            zA = complex(K[f"x_{jA}_m"].iat[i], K[f"y_{jA}_m"].iat[i])
            zB = complex(K[f"x_{jB}_m"].iat[i], K[f"y_{jB}_m"].iat[i])
            w, e = K[f"omega_{link}_rad_s"].iat[i], K[f"eps_{link}_rad_s2"].iat[i]
            vp, ap = pp.plans["velocity"], pp.plans["acceleration"]
            v = vp.vector(f"{ka}_{kb}")
            assert (v.end - v.start) * vp.scale == pytest.approx(1j * w * (zB - zA),
                                                                 rel=1e-9)
            num = mech.link_names.index(link) + 1      # the link's number, n₂ of link 2
            n = ap.vector(f"{ka}_n{num}")
            t = [x for x in ap.vectors if x.start == n.end and x.kind == "tangential"][0]
            assert (n.end - n.start) * ap.scale == pytest.approx(-w * w * (zB - zA), rel=1e-9)
            assert (t.end - t.start) * ap.scale == pytest.approx(1j * e * (zB - zA), rel=1e-9)
            seen += 1
    assert seen >= 2


def test_sheet_fits_and_nothing_overlaps(case, case_sheets):
    res, chosen, pps = case
    for lang in ("ru", "en"):
        sheets = case_sheets(lang, "A1")
        keys = [k for sh in sheets for k in sh.blocks]
        assert "positions" in keys
        for tag in map(str, chosen):
            assert f"{tag}:velocity" in keys and f"{tag}:acceleration" in keys
        for sh in sheets:
            assert drawing.check_no_overlap(sh.items) == []
            for it in sh.items:
                if isinstance(it, layout.Arrow):
                    for z in (it.p1, it.p2):
                        assert 20 < z.real < sh.width - 5 and 5 < z.imag < sh.height - 5
                        assert not (z.real > sh.width - 5 - 185 and z.imag < 5 + 55)
            texts = {t.text for t in sh.items if isinstance(t, layout.Text)}
            if lang == "en":
                assert not [t for t in texts if re.search("[а-яА-ЯёЁ]", t)]
        # every vector is drawn and labelled
        for pp in pps:
            for kind in pp.plans:
                b = layout.diagram_block(pp, kind, lang)
                assert len([i for i in b.items if isinstance(i, layout.Arrow)]) == \
                    len(pp.plans[kind].vectors)


def test_cli_writes_the_chain_plans(tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    from plans.study import run_study

    rep = run_study(example_path("press6.toml"), plots=False, plans="2,5", sheet="A3")
    tables = rep.tables()
    assert f"{rep.name}_plans.csv" in tables and f"{rep.name}_lever.csv" in tables
    lev = tables[f"{rep.name}_lever.csv"]
    assert list(lev["position"]) == [2, 5]
    assert np.allclose(lev["M_lever_Nm"], lev["M_kinetostatic_Nm"], rtol=1e-9, atol=0)
    df = tables[f"{rep.name}_plans.csv"]
    assert set(df["plan"]) == {"velocity", "acceleration", "force_2_3", "force_4_5",
                               "force_crank"}
    assert np.allclose(df["length_mm"], df["value"] / df["scale"])
    from plans.report import write_plans

    info = write_plans(rep.result, rep.plans, tmp_path, name="p", lang="en", sheet="A3",
                       previews=False)
    assert info["sheets"] >= 1
    assert (tmp_path / "p_sheet.pdf").stat().st_size > 0
    assert (tmp_path / "p_sheet.dxf").exists()
    assert (tmp_path / "p_lever.csv").exists() and (tmp_path / "p_lever_forces.csv").exists()


def test_bad_position_is_a_keyed_error():
    from plans.errors import PlanError

    res = linkage.analyze(example_path("shaper.toml"))
    with pytest.raises(PlanError) as e:
        build_chain_plans(res, [99])
    assert e.value.problems[0].text.key == "errors.plans.model.position_not_analysis"


def test_force_polygons_are_the_chain_reactions(case):
    """Each group's polygon: its links' G, Fu, loads and the reactions of the chain's
    kinetostatics, closing; R32 closes link 2's own polygon; every reaction vector is
    the chain's (direction too)."""
    res, _, pps = case
    cf, mech = res.reactions, res.spec.mechanism
    num = {ln: k + 1 for k, ln in enumerate(mech.link_names)}
    name = {0: "frame", **{v: k for k, v in num.items()}}
    for pp in pps:
        i = _row(res, pp)
        for k, grp in enumerate(mech.groups):
            kind = f"force_{num[grp.links[0]]}_{num[grp.links[1]]}"
            plan = pp.plans[kind]
            assert len(plan.polygons) == 2 and max(plan.closure()) < 1e-12
            rs = [v for v in plan.vectors if v.kind == "reaction"]
            assert len(rs) >= 3
            for v in rs:
                by, on = name[int(v.name[1])], name[int(v.name[2])]
                R = cf.R(by, on)
                exact = complex(np.broadcast_to(R.x, res.motion.phi.shape)[i],
                                np.broadcast_to(R.y, res.motion.phi.shape)[i])
                assert (v.end - v.start) * plan.scale == pytest.approx(exact, rel=1e-9,
                                                                       abs=1e-9)
        crank = pp.plans["force_crank"]
        assert max(crank.closure()) < 1e-12


def test_zhukovsky_lever_agrees_with_the_crank_polygon(case):
    """Fур of the crank's polygon (from the kinetostatic Mур) equals Zhukovsky's lever's
    (linkage.chain_lever, an independent power balance on the turned velocity plan)."""
    from linkage.chain_lever import zhukovsky

    res, _, pps = case
    forces, moments = res.loads
    lev = zhukovsky(res.motion, forces, moments, res.spec.gravity)
    n = res.motion.phi.shape
    for pp in pps:
        i = _row(res, pp)
        fb = pp.plans["force_crank"].vector("Fb")
        F = (fb.end - fb.start) * fb.scale
        d = complex(np.broadcast_to(lev.balancing_dir.x, n)[i],
                    np.broadcast_to(lev.balancing_dir.y, n)[i])
        assert F == pytest.approx(lev.balancing_force[i] * d, rel=1e-7, abs=1e-7)
        drv = res.spec.mechanism.driver                 # the spec's names of O and A
        zA, zO = pp.geometry[drv.joint], pp.geometry[drv.pivot]
        # Mур = Fур·l_OA with its sign (+ ccw), and the kinetostatic Mур
        assert (F / d).real * abs(zA - zO) == pytest.approx(lev.M_balance[i], rel=1e-7)
        assert lev.M_balance[i] == pytest.approx(
            float(np.broadcast_to(res.reactions.M_drive, n)[i]), rel=1e-7)


def test_summary_lines_in_each_language(shaper):
    from plans.report import summary_lines

    _, pps = shaper
    ru = summary_lines(pps, "A1", 1, "ru")
    en = summary_lines(pps, "A1", 1, "en")
    assert len(ru) == len(en) == 1 + 2 * len(pps)
    assert "0.005" in ru[1] and "0.03" in ru[1]          # μV and μa of position 2
    # the lever's line under each position: Mур of the lever and of the kinetostatics
    L = pps[0].lever
    assert f"{L.M_lever_Nm:.4f}" in en[2] and en[2].count(f"{L.M_kinetostatic_Nm:.4f}") == 2
    assert "Жуковского" in ru[2] and f"μF = {L.scale:g}" in ru[2]
    assert not [s for s in en if re.search("[а-яА-ЯёЁ]", s)]
    assert not [s for s in ru if re.search(r"\b(plan|position|velocity|lever)\b", s)]
    # Fур acts at the crank pin, perpendicular to the crank, as the spec names them
    assert "A ⟂ OA" in en[2] and "A ⟂ OA" in ru[2]


def test_the_lever_line_names_the_spec_s_crank(case):
    """The balancing force's line names the spec's own crank pivot and pin (the Chinese
    shaper's crank is O2A), in every language."""
    from plans.report import summary_lines

    res, _, pps = case
    d = res.spec.mechanism.driver
    for lang in ("ru", "en", "zh"):
        lines = summary_lines(pps, "A1", 1, lang)
        assert [s for s in lines if f"⟂ {d.pivot}{d.joint}" in s], (lang, lines)


def test_angular_values_read_off_the_plans(case):
    """ω = V_rel/l and ε = aᵗ/l of every turning group link, read off the segments, are the
    chain's |omega_<link>| and |eps_<link>| columns."""
    res, _, pps = case
    K = res.kinematics
    names = res.spec.mechanism.link_names
    for pp in pps:
        i = _row(res, pp)
        assert pp.angular
        for a in pp.angular:
            n = int(a["quantity"].lstrip("omegaps"))
            col = ("omega_{}_rad_s" if a["quantity"].startswith("omega")
                   else "eps_{}_rad_s2").format(names[n - 1])
            assert a["signed_value"] == pytest.approx(K[col].iat[i], rel=1e-12)
            assert a["value"] == pytest.approx(abs(K[col].iat[i]), rel=1e-9)


def test_the_lever_on_the_sheet_balances_as_the_lever_and_the_kinetostatics(case):
    """The chain's lever as drawn (plans.chain_model: the loads on the turned velocity
    plan at μV, a link's couples moved to two of its points, Fур solved again from the
    drawing's moments) gives the Mур of :func:`linkage.chain_lever.zhukovsky` and of the
    kinetostatics, sign included, to 1e-9; each force's moment about the pole is its
    power over μV (v·F/μV, v the chain's own velocity of its point), so a force put at a
    wrong point or the plan turned the wrong way shows."""
    from linkage.chain_lever import zhukovsky

    res, _, pps = case
    forces, moments = res.loads
    zl = zhukovsky(res.motion, forces, moments, res.spec.gravity)
    n = res.motion.phi.shape
    M_kin = np.broadcast_to(res.reactions.M_drive, n)
    mech = res.spec.mechanism
    for pp in pps:
        i = _row(res, pp)
        L = pp.lever
        assert L.M_lever_Nm == pytest.approx(float(zl.M_balance[i]), rel=1e-9)
        assert L.M_lever_Nm == pytest.approx(float(M_kin[i]), rel=1e-9)
        assert L.M_kinetostatic_Nm == pytest.approx(float(M_kin[i]), rel=1e-12)
        assert abs(L.difference_percent) < 1e-7
        mu = pp.plans["velocity"].scale
        total = 0.0
        for f in L.forces:
            total += f.moment_Nmm
            m = re.fullmatch(r"(G|Fu)(\d+)", f.name)
            if not m:
                continue
            ln = mech.link_names[int(m.group(2)) - 1]
            lk, lm = mech.links[ln], res.motion.links[ln]
            vS = g_vec(lm.point(lk.cg).v, i, n)
            assert f.moment_Nmm == pytest.approx((vS.conjugate() * f.force).real / mu,
                                                 rel=1e-9, abs=1e-9 * abs(f.force))
        # the drawing's balance: Σ moments + Fур·(a × its direction) = 0, |pa| = V_A/μV
        drv = mech.driver                               # the spec's names of O and A
        zA, zO = pp.geometry[drv.joint], pp.geometry[drv.pivot]
        assert abs(L.balancing_dir) == pytest.approx(1.0)
        assert (L.balancing_dir * (zA - zO).conjugate()).real == pytest.approx(
            0.0, abs=1e-12)
        arm = (L.balancing_at.conjugate() * L.balancing_dir).imag
        assert total + L.balancing_force_N * arm == pytest.approx(0.0, abs=1e-9 * max(
            abs(total), 1.0))
        assert L.M_lever_Nm == pytest.approx(L.balancing_force_N * abs(zA - zO), rel=1e-12)


def g_vec(v, i, n):
    return complex(np.broadcast_to(v.x, n)[i], np.broadcast_to(v.y, n)[i])


def test_the_lever_is_drawn_on_the_pdf_and_dxf_sheet(case, case_sheets, tmp_path):
    """Each chosen position's lever is a block of the sheet, every force arrow (and Fур)
    one LINE of the LEVER layer in the DXF, |F|/μF mm long; its texts give Mур from the
    lever beside the kinetostatic one; no two texts overlap."""
    import ezdxf

    from plans.dxf import APPID, write_dxf

    res, chosen, pps = case
    for lang, size in (("ru", "A1"), ("en", "A3")):
        sheets = case_sheets(lang, size)
        keys = [k for sh in sheets for k in sh.blocks]
        found = {}
        texts = []
        for k, sh in enumerate(sheets):
            assert drawing.check_no_overlap(sh.items) == []
            texts += [t.text for t in sh.items if isinstance(t, layout.Text)]
            path = tmp_path / f"{lang}_{k}.dxf"
            write_dxf(sh, path)
            msp = ezdxf.readfile(path).modelspace()
            for e in msp.query("LINE[layer=='LEVER']"):
                found[e.get_xdata(APPID)[0].value] = (e.dxf.end - e.dxf.start).magnitude
        for pp in pps:
            assert f"{pp.tag}:lever" in keys
            L = pp.lever
            for v in L.arrows():
                if v.length_mm < 1e-6:
                    continue
                assert found[f"{pp.tag}:lever:{v.name}"] == pytest.approx(
                    v.value / L.scale, rel=1e-9)
            M = layout.fmt(L.M_lever_Nm, lang, 6)
            assert sum(M in t for t in texts) >= 2         # the lever's and kinetostatics'
        if lang == "en":
            assert not [t for t in texts if re.search("[а-яА-ЯёЁ]", t)]


def test_a_fixed_lever_scale_is_kept():
    res = linkage.analyze(example_path("shaper.toml"))
    pp, = build_chain_plans(res, [2], scales={"lever": 50.0})
    assert pp.lever.scale == 50.0
    Fb = [v for v in pp.lever.arrows() if v.name == "Fb"][0]
    assert Fb.length_mm == pytest.approx(abs(pp.lever.balancing_force_N) / 50.0, rel=1e-12)
