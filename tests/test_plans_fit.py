"""Every position's plans sheet fits the paper, the Zhukovsky lever included (issue #20).

On A3 (ГОСТ 2.301, 420 × 297 mm) some diagrams of the bundled chains are too large for the
sheet's field at their default round scale: the shaper's lever at position 10 (its turned
velocity plan alone 249 mm tall), its acceleration plan at 11, press6's lever at 11.
:func:`plans.drawing.fit_plans` draws each such diagram at the largest round scale at
which it fits (a coarser μa; the lever on a coarser copy of the velocity plan, its own μV
printed); every other diagram keeps its scale.  Here, for every bundled chain and every
position 1…12 on A3 and A1, built through the library (no PDF rendered):

* the sheets build, every item of every diagram lies inside the frame's field and off the
  title block, no two texts overlap;
* the lever drawn gives the Mур of :func:`linkage.chain_lever.zhukovsky` (1e-9), and so
  does its Fур arrow measured on the sheet times the *printed* μF times lOA;
* every absolute vector of the velocity and acceleration plans measured on the sheet
  times its plan's printed scale is the chain's own |v| and |a| (the analysis' columns),
  and the crank polygon's Fур arrow times its printed μF times lOA is the kinetostatic
  |Mур|: a scale printed but not applied, or applied twice, shows;
* a position that fits keeps its plans (the same objects); a fitted diagram's scale is
  round and the next finer round scale would not fit.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

import linkage
from crankbase.plot_labels import segment_hits_box
from crankbase.resources import example_path
from linkage.chain_lever import zhukovsky
from plans import drawing, layout
from plans.chain_model import build_chain_plans
from plans.errors import PlanError
from plans.model import ROUND_MANTISSAS, round_scale

CHAINS = ["shaper.toml", "press6.toml", "compressor_v.toml", "sixbar_rrr.toml"]
#: (size, language) of the sheets checked: A3 in Russian, A1 in English.
SIZES = [("A3", "ru"), ("A1", "en")]


@pytest.fixture(scope="module", params=CHAINS)
def chain(request):
    res = linkage.analyze(example_path(request.param))
    return res, build_chain_plans(res, "all")


def _row(res, pp):
    return int(np.flatnonzero(res.kinematics["position"].to_numpy() == pp.position)[0])


def _number(s):
    return float(s.replace(",", "."))


def _printed(sheet, title, where):
    """The scales printed under the diagram titled ``title`` of position ``where`` on
    ``sheet``: ``{symbol: value}`` read from the line under the title."""
    texts = [t for t in sheet.items if isinstance(t, layout.Text)]
    for t in texts:
        if t.text != title:
            continue
        below = [u for u in texts if abs(u.at.real - t.at.real) < 1e-6
                 and 0 < t.at.imag - u.at.imag < 10 and u.text.startswith(where + ", ")]
        if below:
            line = min(below, key=lambda u: t.at.imag - u.at.imag).text
            return {m.group(1): _number(m.group(2))
                    for m in re.finditer(r"(\w+) = ([0-9.,e+-]+) ", line + " ")}
    return None


def _arrows(sheets):
    return {it.name: (it, sh) for sh in sheets for it in sh.items
            if isinstance(it, layout.Arrow)}


def _inside(sheet, frame_count):
    """Items of the diagrams outside the field or on the title block."""
    W, H = sheet.width, sheet.height
    tb = (W - 5 - 185, 5, W - 5, 5 + 55)
    bad = []
    for it in sheet.items[frame_count:]:
        if isinstance(it, (layout.Line, layout.Arrow)):
            pts = [it.p1, it.p2]
            if segment_hits_box((it.p1.real, it.p1.imag), (it.p2.real, it.p2.imag), tb):
                bad.append(it)
        elif isinstance(it, layout.Text):
            b = layout.text_box(it)
            pts = [complex(b[0], b[1]), complex(b[2], b[3])]
            if layout.boxes_overlap(b, tb, 0.0):
                bad.append(it)
        else:
            pts = [it.center - it.r * (1 + 1j), it.center + it.r * (1 + 1j)]
        if not all(20 < z.real < W - 5 and 5 < z.imag < H - 5 for z in pts):
            bad.append(it)
    return bad


@pytest.mark.parametrize("size,lang", SIZES)
def test_every_position_fits_and_the_drawn_scales_are_the_printed_ones(chain, size, lang):
    res, pps = chain
    spec, K = res.spec, res.kinematics
    mech = spec.mechanism
    forces, moments = res.loads
    zl = zhukovsky(res.motion, forces, moments, spec.gravity)
    M_kin = np.broadcast_to(res.reactions.M_drive, res.motion.phi.shape)
    w = layout.plan_words(lang)
    fields = drawing.title_fields(spec)
    sheets, drawn = drawing.layout_fitted(res, pps, lang, size, fields)
    assert [pp.tag for pp in drawn] == [str(k) for k in range(1, 13)]
    keys = [k for sh in sheets for k in sh.blocks]
    for sh in sheets:
        frame = drawing.frame_items(sh.width, sh.height, fields, sh.number, sh.count, lang)
        assert sh.items[:len(frame)] == frame
        assert _inside(sh, len(frame)) == []
        assert drawing.check_no_overlap(sh.items) == []
    arrows = _arrows(sheets)
    d = mech.driver
    for pp in drawn:
        i = _row(res, pp)
        l_OA = abs(pp.geometry[d.joint] - pp.geometry[d.pivot])
        where = w["where"].format(n=pp.tag)
        for kind in list(pp.plans) + ["lever"]:
            assert f"{pp.tag}:{kind}" in keys
        # |vector on the sheet| · printed scale = the chain's own value
        for kind, col in (("velocity", "vx_{}_m_s"), ("acceleration", "ax_{}_m_s2")):
            sh = next(s for s in sheets if f"{pp.tag}:{kind}" in s.blocks)
            mu = _printed(sh, w["title"][kind], where)[w["mu"][kind]]
            assert mu == pp.plans[kind].scale
            checked = 0
            for v in pp.plans[kind].vectors:
                cx = col.format(v.quantity.split("_", 1)[1])
                if v.kind != "absolute" or cx not in K.columns:
                    continue
                exact = abs(complex(K[cx].iat[i], K[cx.replace("x_", "y_", 1)].iat[i]))
                a, _ = arrows[f"{pp.tag}:{kind}:{v.name}"]
                assert abs(a.p2 - a.p1) * mu == pytest.approx(exact, rel=1e-9)
                checked += 1
            assert checked >= 3
        # the crank's polygon: Fур measured at its printed μF gives the kinetostatic Mур
        sh = next(s for s in sheets if f"{pp.tag}:force_crank" in s.blocks)
        mu = _printed(sh, w["title"]["force_crank"], where)[w["mu"]["force_crank"]]
        a, _ = arrows[f"{pp.tag}:force_crank:Fb"]
        assert abs(a.p2 - a.p1) * mu * l_OA == pytest.approx(abs(M_kin[i]), rel=1e-9)
        # the lever: Mур of the lever drawn, and of its Fур arrow on the sheet
        L = pp.lever
        assert L.M_lever_Nm == pytest.approx(float(zl.M_balance[i]), rel=1e-9)
        sh = next(s for s in sheets if f"{pp.tag}:lever" in s.blocks)
        printed = _printed(sh, w["title"]["lever"], where)
        assert printed[w["mu"]["lever"]] == L.scale
        # the lever's own μV is printed exactly when it is not the velocity plan's
        mu_v = printed.get(w["mu"]["velocity"], pp.plans["velocity"].scale)
        assert mu_v == L.plan_scale
        a, _ = arrows[f"{pp.tag}:lever:Fb"]
        sign = math.copysign(1.0, ((a.p2 - a.p1) / L.balancing_dir).real)
        M_sheet = sign * abs(a.p2 - a.p1) * printed[w["mu"]["lever"]] * l_OA
        assert M_sheet == pytest.approx(float(zl.M_balance[i]), rel=1e-9)
        assert any(layout.fmt(L.M_lever_Nm, lang, 6) in t.text for t in sh.items
                   if isinstance(t, layout.Text))
        # the lever's turned pa on the sheet (from its pole, a filled circle, to the
        # start of Fур) at the printed μV is V_A
        poles = [c.center for c in sh.items if isinstance(c, layout.Circle) and c.filled]
        pa = [ln for ln in sh.items if isinstance(ln, layout.Line)
              and abs(ln.p2 - a.p1) < 1e-9 and min(abs(z - ln.p1) for z in poles) < 1e-9]
        assert pa
        vA = abs(complex(K[f"vx_{d.joint}_m_s"].iat[i], K[f"vy_{d.joint}_m_s"].iat[i]))
        assert abs(pa[0].p2 - pa[0].p1) * mu_v == pytest.approx(vA, rel=1e-9)


def _mantissa(mu):
    return mu / 10 ** math.floor(math.log10(mu) + 1e-12)


def _finer(mu):
    """The next finer round scale than ``mu``."""
    k = math.floor(math.log10(mu) + 1e-12)
    below = [m * 10.0 ** kk for kk in (k - 1, k) for m in ROUND_MANTISSAS
             if m * 10.0 ** kk < mu * (1 - 1e-9)]
    return round_scale(max(below), 1.0)


def test_only_what_does_not_fit_changes_and_at_the_largest_round_scale_that_fits():
    """Shaper on A3: positions that fit keep their plans (the same objects); at 10 the
    lever is drawn on μV = 0.008 instead of 0.006 (A3's field is 271 mm high: 249 mm of
    turned plan and its texts are not), at 11 the acceleration plan at μa = 0.05; the
    scale chosen is round, and the next finer round one does not fit."""
    res = linkage.analyze(example_path("shaper.toml"))
    pps = build_chain_plans(res, "all")
    fitted = drawing.fit_plans(res, pps, "A3", "ru")
    changed = {pp.tag for pp, f in zip(pps, fitted) if pp is not f}
    assert changed == {"10", "11"}
    assert drawing.fit_plans(res, pps, "A1", "ru") == pps
    assert all(a is b for a, b in zip(drawing.fit_plans(res, pps, "A1", "ru"), pps))
    before, after = pps[9], fitted[9]
    assert after.lever.plan_scale == 0.008 and before.lever.plan_scale == 0.006
    assert after.plans["velocity"].scale == before.plans["velocity"].scale == 0.006
    for a, b in zip(after.lever.forces, before.lever.forces):
        assert a.force == b.force
        assert a.at == pytest.approx(b.at * 0.006 / 0.008, rel=1e-12, abs=1e-12)
    assert after.lever.M_lever_Nm == pytest.approx(before.lever.M_lever_Nm, rel=1e-12)
    assert not drawing.block_fits(layout.lever_block(before, "ru"), "A3")
    assert drawing.block_fits(layout.lever_block(after, "ru"), "A3")
    before, after = pps[10], fitted[10]
    assert (before.plans["acceleration"].scale, after.plans["acceleration"].scale) == (
        0.04, 0.05)
    assert after.plans["velocity"].scale == before.plans["velocity"].scale
    for pp in fitted:
        for mu in [p.scale for p in pp.plans.values()] + [pp.lever.scale,
                                                           pp.lever.plan_scale]:
            assert any(abs(_mantissa(mu) - m) < 1e-9 for m in ROUND_MANTISSAS), mu
    # the next finer round scale would not fit
    finer, = build_chain_plans(res, [11], scales={"acceleration": _finer(0.05)})
    assert _finer(0.05) == 0.04
    assert not drawing.block_fits(layout.diagram_block(finer, "acceleration", "ru"), "A3")
    finer, = build_chain_plans(res, [10], scales={"lever_velocity": _finer(0.008)})
    assert not drawing.block_fits(layout.lever_block(finer, "ru"), "A3")


def test_a_scale_the_student_fixed_is_kept_and_then_the_error_stays():
    """A fixed scale is the student's: never changed; a diagram that does not fit at it
    is refused with its words (choose A1 or a coarser scale)."""
    res = linkage.analyze(example_path("shaper.toml"))
    pps = build_chain_plans(res, [10, 11], scales={"acceleration": 0.04})
    assert pps[1].fixed == ("acceleration",)
    fitted = drawing.fit_plans(res, pps, "A3", "en")
    assert fitted[1].plans["acceleration"].scale == 0.04
    assert fitted[0].lever.plan_scale == 0.008          # the lever is still fitted
    with pytest.raises(PlanError) as e:
        drawing.layout_sheets(res, pps, "en", "A3")
    msg = str(e.value)
    assert "does not fit the sheet's field" in msg and "Acceleration" in msg
    assert "position 11" in msg and "position 10" not in msg
    # the student's lever scales are kept too: its turned plan alone is 249 mm tall
    pp, = build_chain_plans(res, [10], scales={"lever_velocity": 0.006, "lever": 50.0})
    with pytest.raises(PlanError, match="Zhukovsky"):
        drawing.layout_sheets(res, [pp], "en", "A3")


def test_the_four_bar_fits_a3_too():
    """The ratchet's position 11 (acceleration plan) and 12 (lever) did not fit A3; now
    they are drawn at μa = 0.5 and on a lever of μV = 0.025 (m/s)/mm."""
    from plans import build_plans

    res = linkage.analyze(example_path("ratchet.toml"))
    pps = build_plans(res, [5, 11, 12])
    sheets, drawn = drawing.layout_fitted(res, pps, "en", "A3")
    assert drawn[0] is pps[0]
    assert drawn[1].plans["acceleration"].scale == 0.5
    assert drawn[2].lever.plan_scale == 0.025
    assert drawn[2].lever.M_lever_Nm == pytest.approx(pps[2].lever.M_lever_Nm, rel=1e-12)
    assert drawn[2].fixed == pps[2].fixed == ()
    for sh in sheets:
        assert drawing.check_no_overlap(sh.items) == []


def test_the_written_files_hold_the_scales_drawn(tmp_path, figures_rendered_only):
    """``crankdyn linkage --example shaper --plans 10,11 --sheet A3`` (through the
    library): the plans' CSV gives position 11's acceleration plan at μa = 0.05 as drawn,
    the lever's forces at 10 sit on the μV = 0.008 plan, the report's tables are the
    files written, and the summary says the lever is drawn on its own μV (ru and en).
    (Tables and texts only: the drawings are saved unrendered; a chain's plans and sheet
    are rendered by tests/test_plans_chain.py::test_cli_writes_the_chain_plans, the
    positions' drawings by tests/test_plans_output.py's runs.)"""
    import pandas as pd

    figures_rendered_only()

    from linkage.study import summary_lines, write_report
    from plans.study import run_study

    report = run_study(example_path("shaper.toml"), plans=[10, 11], sheet="A3",
                       plots=False)
    assert report.plans[1].plans["acceleration"].scale == 0.04        # not yet drawn
    written = write_report(report, tmp_path, lang="en")
    table = pd.read_csv(tmp_path / "shaper_plans.csv")
    acc = table[(table["position"] == 11) & (table["plan"] == "acceleration")]
    assert set(acc["scale"]) == {0.05}
    assert (acc["length_mm"] * acc["scale"]).to_numpy() == pytest.approx(
        acc["value"].to_numpy(), rel=1e-12)
    forces = pd.read_csv(tmp_path / "shaper_lever_forces.csv")
    L = report.plans[0].lever
    assert L.plan_scale == 0.008
    fu5 = forces[(forces["position"] == 10) & (forces["force"] == "Fu5")].iloc[0]
    v_s5 = next(v for v in report.plans[0].plans["velocity"].vectors if v.name == "ps5")
    # the ram's inertia force is horizontal: its arm on the lever (the plan turned 90°)
    # is the ram's velocity over the lever's μV, 0.008, not the velocity plan's 0.006
    assert v_s5.scale == 0.006 and abs(v_s5.end.imag) < 1e-9
    assert abs(fu5["arm_mm"]) == pytest.approx(v_s5.value / 0.008, rel=1e-9)
    assert abs(fu5["arm_mm"]) > 100
    for name, df in report.tables().items():
        if name.startswith("shaper_plans") or name.startswith("shaper_lever"):
            assert df.to_csv(index=False, lineterminator="\n") == (
                tmp_path / name).read_text(encoding="utf-8"), name
    en = summary_lines(report, "en", written)
    assert [ln.strip() for ln in en if "to fit the A3 sheet" in ln] == [
        "the lever drawn on the velocity plan at kv = 0.008 (m/s)/mm, to fit the A3 sheet"]
    assert not [ln for ln in en if re.search("[а-яА-ЯёЁ]", ln)]
    ru = summary_lines(report, "ru", written)
    assert sum("μV = 0.008 (м/с)/мм, чтобы поместиться на листе A3" in ln for ln in ru) == 1
    assert any("μa = 0.05 (м/с²)/мм" in ln for ln in ru)
