"""A chain spec (``[mechanism] kind = "chain"``) from the file to the report (issue #20).

Checks: today's ratchet (crank-rocker) and press (crank-slider) written as chains give
today's numbers; the shaper's time ratio and ram stroke equal their closed forms; the
power balance Mур·ω = −Σ(F·v + M·ω) on every bundled chain example; the transmission
angle against today's; the keyed bad-input errors, nothing written, exit 2; the summary
in both languages.  Cheap: the study layer for the numbers, one CLI run.
"""
from __future__ import annotations

import contextlib
import io
import math
import re
import tomllib

import numpy as np
import pytest

import linkage
from crankbase.errors import AssemblyError, SpecError
from crankbase.resources import example_path
from linkage import groups as g
from linkage.study import run_study, summary_lines

CHAINS = ("shaper.toml", "press6.toml", "compressor_v.toml", "sixbar_rrr.toml",
          "shaper_cn.toml")


def _toml(name):
    with open(example_path(name), "rb") as f:
        return tomllib.load(f)


def _links(old):
    return {k: v for k, v in old.get("links", {}).items()}


def _ratchet_chain():
    old = _toml("ratchet.toml")
    m = old["mechanism"]
    return {"mechanism": {"kind": "chain", "name": "ratchet-chain", "crank": m["crank"],
                          "output": "rocker", "omega_rad_s": m["omega_rad_s"],
                          "gravity_m_s2": m["gravity_m_s2"],
                          "frame": {"O": [0.0, 0.0], "C": [m["ground"], 0.0]}},
            "group": [{"kind": "RRR", "links": ["coupler", "rocker"],
                       "joints": ["A", "B", "C"], "lengths": [m["coupler"], m["rocker"]],
                       "assembly": m["assembly"]}],
            "links": _links(old), "load": old["load"], "analysis": old["analysis"]}


def _press_chain():
    old = _toml("press.toml")
    m = old["mechanism"]
    return {"mechanism": {"kind": "chain", "name": "press-chain", "crank": m["crank"],
                          "output": "slider", "omega_rad_s": m["omega_rad_s"],
                          "gravity_m_s2": m["gravity_m_s2"], "frame": {"O": [0.0, 0.0]}},
            "group": [{"kind": "RRP", "links": ["coupler", "slider"], "joints": ["A", "B"],
                       "lengths": [m["coupler"]], "assembly": m["assembly"],
                       "guide_angle_deg": m["ground_angle_deg"],
                       "guide_offset": m["offset"]}],
            "links": _links(old), "load": old["load"], "analysis": old["analysis"]}


def _close(a, b, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = scale or max(1.0, float(np.max(np.abs(b))))
    assert np.max(np.abs(a - b)) <= 1e-9 * scale, np.max(np.abs(a - b))


# the old columns -> the chain's, and the sign between them
RATCHET = {"omega3_rad_s": "omega_coupler_rad_s", "eps4_rad_s2": "eps_rocker_rad_s2",
           "omega4_rad_s": "omega_rocker_rad_s", "B_x_m": "x_B_m", "B_ay_m_s2": "ay_B_m_s2",
           "E_vx_m_s": "vx_E_m_s", "E_ay_m_s2": "ay_E_m_s2", "S3_ax_m_s2": "ax_S_coupler_m_s2"}
RATCHET_F = {"M_drive_Nm": ("M_drive_Nm", 1), "M_res_Nm": ("M_res_Nm", 1),
             "R12_x_N": ("Rx_frame_crank_N", 1), "R23_y_N": ("Ry_crank_coupler_N", 1),
             "R14_x_N": ("Rx_frame_rocker_N", 1), "R43_x_N": ("Rx_rocker_coupler_N", 1),
             "R23_n_N": ("Rn_crank_coupler_N", 1), "R14_t_N": ("Rt_frame_rocker_N", 1)}


def test_the_ratchet_as_a_chain_gives_todays_numbers():
    old = linkage.analyze(example_path("ratchet.toml"))
    new = linkage.analyze(_ratchet_chain())
    _close(new.kinematics["phi_deg"], old.kinematics["phi_deg"], 360.0)
    for a, b in RATCHET.items():
        _close(new.kinematics[b], old.kinematics[a])
    for a, (b, sign) in RATCHET_F.items():
        _close(sign * new.forces[b], old.forces[a])
    # today's transmission angle is the angle between coupler and rocker, folded to 90°
    mu = old.kinematics["mu_deg"]
    _close(new.kinematics["mu_coupler_rocker_deg"], np.minimum(mu, 180.0 - mu), 90.0)
    assert new.summary.time_ratio == pytest.approx(old.summary.time_ratio, rel=1e-12)
    assert new.summary.travel == pytest.approx(old.summary.swing_deg, rel=1e-12)


def test_the_press_as_a_chain_gives_todays_numbers():
    old = linkage.analyze(example_path("press.toml"))
    new = linkage.analyze(_press_chain())
    for a, b in {"s4_m": "s_slider_m", "v4_m_s": "v_slider_m_s", "a4_m_s2": "a_slider_m_s2",
                 "omega3_rad_s": "omega_coupler_rad_s", "B_vy_m_s": "vy_B_m_s",
                 "S4_ay_m_s2": "ay_S_slider_m_s2"}.items():
        _close(new.kinematics[b], old.kinematics[a])
    for a, b in {"M_drive_Nm": "M_drive_Nm", "F_res_N": "F_res_N",
                 "R12_y_N": "Ry_frame_crank_N", "R23_x_N": "Rx_crank_coupler_N",
                 "R14_x_N": "Rx_frame_slider_N", "M14_Nm": "Mp_frame_slider_Nm"}.items():
        _close(new.forces[b], old.forces[a])
    mu = old.kinematics["mu_deg"]        # today's: between the rod and the guide's normal
    _close(new.kinematics["mu_coupler_slider_deg"], np.minimum(mu, 180.0 - mu), 90.0)
    assert new.summary.travel == pytest.approx(old.summary.stroke_m, rel=1e-12)
    assert new.summary.time_ratio == pytest.approx(old.summary.time_ratio, rel=1e-12)


def test_shaper_time_ratio_and_stroke_are_the_closed_forms():
    # crank-slotted lever: the lever is at its extremes where it is tangent to the crank
    # circle, θ = 2·asin(r/c), K = (180 + θ)/(180 − θ) (Артоболевский, ТММ, §
    # "коэффициент изменения средней скорости"); the ram's ends are symmetric, H =
    # 2·|CD|·sin(asin(r/c)) = 2·|CD|·r/c
    spec = linkage.load_spec(example_path("shaper.toml"))
    frame = spec.mechanism.frame
    c, r = abs(frame["O"] - frame["C"]), spec.crank
    theta = math.degrees(2.0 * math.asin(r / c))
    sm = linkage.analyze(spec).summary
    assert sm.time_ratio == pytest.approx((180.0 + theta) / (180.0 - theta), rel=1e-12)
    assert sm.working_crank_angle_deg == pytest.approx(180.0 + theta, rel=1e-12)
    L = spec.mechanism.links["lever"].points["D"].real
    assert sm.travel == pytest.approx(2.0 * L * r / c, rel=1e-12)
    assert sm.structure == "I(0,1) → II RPR(2,3) → II RRP(4,5)"
    assert sm.mobility == (1, 5, 7, 0)


@pytest.mark.parametrize("name", CHAINS)
def test_power_balance_on_every_chain_example(name):
    spec = linkage.load_spec(example_path(name))
    res = linkage.analyze(spec, np.arange(3.0, 360.0, 11.0))
    mot, (forces, moments) = res.motion, res.loads
    P = 0.0
    for ln, lk in spec.mechanism.links.items():
        W = g.link_wrench(mot.links[ln], lk.mass, lk.inertia, lk.cg, spec.gravity,
                          forces.get(ln, ()), moments.get(ln, ()))
        P = P + g.dot(W.force, mot.links[ln].point(lk.cg).v) + W.moment * mot.omega(ln)
    M = res.forces["M_drive_Nm"].to_numpy()
    assert np.max(np.abs(M * spec.omega + P)) <= 1e-9 * np.max(np.abs(P))
    assert np.max(np.abs(M)) > 0.0


def test_every_output_column_is_named_after_the_spec_and_finite():
    res = linkage.analyze(example_path("shaper.toml"))
    k, f = res.kinematics, res.forces
    for col in ("x_A_m", "v_E_m_s", "omega_lever_rad_s", "vrel_block_lever_m_s",
                "acor_block_lever_m_s2", "s_ram_m", "mu_rod_ram_deg"):
        assert col in k.columns
    for col in ("R_crank_block_N", "Rx_frame_lever_N", "Mp_frame_ram_Nm", "F_res_N",
                "M_drive_Nm"):
        assert col in f.columns
    assert all(re.fullmatch(r"[A-Za-z0-9_]+", c) for c in [*k.columns, *f.columns])
    assert np.isfinite(k.drop(columns="position").to_numpy()).all()
    # Coriolis: 2·ω_lever·v_rel
    _close(k["acor_block_lever_m_s2"], 2.0 * np.abs(k["omega_lever_rad_s"]
                                                    * k["vrel_block_lever_m_s"]))


def _bad(edit):
    d = _toml("shaper.toml")
    edit(d)
    return d


@pytest.mark.parametrize("edit, key", [
    (lambda d: d["group"][1].update(joints=["X", "E"]), "errors.linkage.chain.unknown_joint"),
    (lambda d: d["group"].reverse(), "errors.linkage.chain.unsolved_joint"),
    (lambda d: (d["group"][1].update(links=["rod", "block"]), d["links"].pop("ram"),
                d.pop("load"), d["mechanism"].update(output="rod")),
     "errors.linkage.chain.mobility"),
])
def test_structure_errors_are_keyed(edit, key):
    with pytest.raises(SpecError) as e:
        linkage.load_spec(_bad(edit))
    assert key in [p.text.key for p in e.value.problems if p.text is not None]


@pytest.mark.parametrize("edit, path, key", [
    # the four-bar's checks of points, loads and the plan, read by the same functions
    # (linkage.spec.read_link, read_loads, read_plan)
    (lambda d: d["links"]["rod"].update(points={"P_1": [0.1, 0.0]}),
     "links.rod.points.P_1", "errors.linkage.spec.invalid_point_name_chain"),
    (lambda d: d["links"]["rod"].update(points={"D": [0.1, 0.0]}),
     "links.rod.points.D", "errors.linkage.spec.point_name_already"),
    (lambda d: d["load"].append({"link": "rod", "force_N": [0.0, -10.0], "span_m": 0.1}),
     "load[1].span_m", "errors.linkage.spec.applies_resistance_only"),
    (lambda d: d["load"].append({"link": "lever", "moment_Nm": 5.0, "at": [0.1, 0.0]}),
     "load[1].at", "errors.linkage.spec.does_not_apply_2"),
    (lambda d: d["load"][0].update(at=[0.0, 0.1]),
     "load[0].at", "errors.linkage.spec.resistance_acts_at"),
    (lambda d: d["load"][0].update(span_deg=30.0),
     "load[0].span_deg", "errors.linkage.spec.use_for"),
    (lambda d: d["load"][0].update(link="rod"),
     "load[0].link", "errors.linkage.spec.resistance_acts_on"),
    (lambda d: (d["mechanism"].update(omega_rad_s=0.0),
                d["analysis"].update(crank_angles_deg=[10.0, 20.0]),
                d["analysis"].pop("positions", None)),
     "load[0].resistance_N", "errors.linkage.spec.resistance_opposes_motion"),
])
def test_points_loads_and_plan_are_checked_like_the_four_bar(edit, path, key):
    with pytest.raises(SpecError) as e:
        linkage.load_spec(_bad(edit))
    found = [(p.key, p.text.key) for p in e.value.problems if p.text is not None]
    assert (path, key) in found, found


def test_a_chain_spec_without_working_stroke_takes_the_first():
    d = _bad(lambda d: d["analysis"].pop("working_stroke"))
    assert linkage.load_spec(d).working_stroke == "away"     # the ram's first stroke


def test_a_chain_that_cannot_be_assembled_is_an_error():
    d = _bad(lambda d: d["group"][1].update(lengths=[0.01]))
    with pytest.raises(AssemblyError):
        linkage.analyze(d)


def test_cli_error_writes_nothing_and_exits_2(tmp_path):
    from crankdyn.cli import main

    spec = tmp_path / "bad.toml"
    text = example_path("shaper.toml").read_text(encoding="utf-8")
    spec.write_text(text.replace('joints = ["D", "E"]', 'joints = ["Z", "E"]'),
                    encoding="utf-8")
    out = tmp_path / "out"
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        assert main(["linkage", str(spec), "-o", str(out), "--lang", "en"]) == 2
    assert "Z" in err.getvalue() and not out.exists()


def test_summary_in_both_languages():
    rep = run_study(example_path("shaper.toml"), plots=False)
    en = "\n".join(summary_lines(rep, "en"))
    ru = "\n".join(summary_lines(rep, "ru"))
    assert not re.search("[А-Яа-яЁё]", en)
    assert "I(0,1) → II RPR(2,3) → II RRP(4,5)" in en and "K = 1.5521" in en
    assert "формула строения" in ru and "K = 1.5521" in ru
    # no English word in the Russian summary but the spec's own names
    words = set(re.findall(r"\b[a-z]{3,}\b", ru)) - {"ram", "block", "lever", "rod", "shaper", "max"}
    assert not words, words


@pytest.mark.parametrize("name, lang", [(n, "en") for n in CHAINS] + [("shaper.toml", "ru")])
def test_chain_figures_and_workbook_read_cleanly(name, lang, tmp_path):
    import sys
    from pathlib import Path

    from openpyxl import load_workbook

    sys.path.insert(0, str(Path(__file__).parent))
    from figure_check import figure_problems
    from workbook_audit import problems

    from linkage.chain_report import chain_figures, write_chain_workbook

    spec = linkage.load_spec(example_path(name))
    res, full = linkage.analyze(spec), linkage.full_turn(spec, 5.0)
    found = []
    for stem, fig in chain_figures(res, full, lang).items():
        found += [f"{stem}: {p}" for p in figure_problems(fig)]
    p = write_chain_workbook(res, tmp_path / "w.xlsx", lang)
    wb = load_workbook(p)
    found += problems(wb, name)
    assert not found, found
    # the key row under the labels holds the CSV's column names
    ws = wb.worksheets[1]
    assert [c.value for c in ws[2]][:len(res.kinematics.columns)] == list(res.kinematics.columns)


def test_plans_of_a_chain_are_drawn():
    from plans.study import run_study as run_plans

    rep = run_plans(example_path("shaper.toml"), plots=False, plans=[1])
    assert getattr(rep, "chain", False)
    assert [pp.position for pp in rep.plans] == [1]
    assert set(rep.plans[0].plans) == {"velocity", "acceleration", "force_2_3", "force_4_5",
                                       "force_crank"}
    # without plans the chain's own report comes back
    assert getattr(run_plans(example_path("shaper.toml"), plots=False), "chain", False)


def test_transmission_angle_of_an_offset_slotted_lever():
    # RPR with the slot offset e from the lever's pivot C: the force on the lever is
    # normal to the slot, the lever's point at A moves normal to CA, so the transmission
    # angle is asin(|u·CA|/|CA|) = acos(e/|CA|) (u along the slot)
    d = _toml("shaper.toml")
    d["group"][0]["offset"] = 0.04
    spec = linkage.load_spec(d)
    res = linkage.analyze(spec, np.arange(0.0, 360.0, 15.0))
    k = res.kinematics
    zA = k["x_A_m"] + 1j * k["y_A_m"]
    CA = np.abs(zA - spec.mechanism.frame["C"])
    _close(k["mu_block_lever_deg"], np.degrees(np.arccos(0.04 / CA)), 90.0)


def test_a_branch_that_flips_in_the_cycle_is_an_error():
    # a change-point four-bar (0.10 + 0.30 = 0.20 + 0.20): the coupler and the rocker
    # fall in line once a turn, where the assembly branch may flip
    d = _ratchet_chain()
    d["mechanism"].update(crank=0.10, frame={"O": [0.0, 0.0], "C": [0.20, 0.0]})
    d["group"][0]["lengths"] = [0.30, 0.20]
    d.pop("load")
    d.pop("links")
    with pytest.raises(AssemblyError) as e:
        linkage.analyze(d)
    assert e.value.text.key == "errors.linkage.chain.branch_flips"


def test_write_report_of_a_chain(tmp_path):
    from linkage.study import write_report

    rep = run_study(example_path("compressor_v.toml"), step=10.0)
    w = write_report(rep, tmp_path, lang="en")
    n = "compressor-v"
    assert w.files == [f"{n}_kinematics.csv", f"{n}_forces.csv", f"{n}.xlsx",
                       f"{n}_plan.png", f"{n}_driving_moment.png", f"{n}_output_motion.png"]
    import pandas as pd

    back = pd.read_csv(tmp_path / f"{n}_forces.csv")
    assert list(back.columns) == list(rep.result.forces.columns)
    np.testing.assert_array_equal(back["M_drive_Nm"], rep.result.forces["M_drive_Nm"])
    # an axial crank-slider: the piston's dead centres with the crank along the cylinder
    sm = rep.result.summary
    assert sm.time_ratio == pytest.approx(1.0, abs=1e-12)
    assert sm.phi_working_end_deg == pytest.approx(45.0, abs=1e-9)
    assert sm.travel == pytest.approx(2 * 0.05, rel=1e-12)


def test_a_scotch_yoke_with_an_inclined_slot():
    # I(0,1) → II RPP(2,3): the block at A in a slot at β = 60° to the yoke's guide (x):
    # the yoke sits at s = x_A − y_A/tan β, so its stroke is 2r/sin β, K = 1, and the
    # transmission angle (the slot's normal against the guide) is β at every position
    r, beta = 0.05, 60.0
    d = {"mechanism": {"kind": "chain", "name": "yoke", "crank": r, "output": "yoke",
                       "omega_rad_s": 10.0, "frame": {"O": [0.0, 0.0]}},
         "group": [{"kind": "RPP", "links": ["block", "yoke"], "joints": ["A"],
                    "slot_angle_deg": beta}],
         "links": {"yoke": {"mass_kg": 2.0}, "block": {"mass_kg": 0.5}},
         "analysis": {"positions": 8, "working_stroke": "away"}}
    res = linkage.analyze(d)
    sm = res.summary
    assert sm.travel == pytest.approx(2 * r / math.sin(math.radians(beta)), rel=1e-12)
    assert sm.time_ratio == pytest.approx(1.0, abs=1e-12)
    _close(res.kinematics["mu_block_yoke_deg"], np.full(8, beta), 90.0)
    k = res.kinematics
    _close(k["s_yoke_m"], k["x_A_m"] - k["y_A_m"] / math.tan(math.radians(beta)))
