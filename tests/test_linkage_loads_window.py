"""A useful resistance over a window of its stroke (issue #20): ``start_m``/``start_deg``
with ``span_*``, or ``from_fraction``/``to_fraction`` of the stroke (swing) H.

* The shaping machine of the Chinese course (examples/shaper_cn.toml): the cutting force
  acts between idle runs of 0.05·H at both ends of the cut («在切削行程H中，前、后各有一段
  0.05H的空刀距离», https://360docs.net/doc/5714254414.html).  Which crank angles of a fine
  grid fall inside 0.05·H … 0.95·H is worked out here from the ram's coordinate and the
  geometry of 方案 I alone (the extreme positions of the lever tangent to the crank circle,
  H = 2·l_O4B·sin ψ), not from the tool's rule; the force opposes the ram's motion; the
  power balance Mур·ω = −Σ P of the whole chain holds with the windowed load.
* The fraction form gives the same numbers as the metre (degree) form; a window on the
  four-bar's rocker and slider by the swing (travel) from the stroke's start.
* The machine dynamics (the reduced resisting moment) and the plans (force polygons,
  Zhukovsky's lever) take the windowed resistance.
* Errors: both forms, from ≥ to, a window outside the stroke, in ru, en and zh.
"""
from __future__ import annotations

import copy
import math
import re
import tomllib

import numpy as np
import pytest

import linkage
from crankbase.errors import SpecError
from crankbase.resources import example_path
from newton_euler import loaded_slider, ratchet_data, wrap_deg

# 方案 I (examples/shaper_cn.toml), in metres
L_O2O4, L_O2A, L_O4B, L_BC = 0.380, 0.110, 0.540, 0.135
Y_GUIDE = 0.5284402126
F_CUT = 7000.0
GRID = np.arange(0.0, 360.0, 0.25)


def _shaper_cn():
    with open(example_path("shaper_cn.toml"), "rb") as f:
        return tomllib.load(f)


def _hand_stroke():
    """The ram's extreme positions by hand: at each extreme the slot O4B is tangent to
    the crank circle, at ψ = asin(l_O2A / l_O2O4) on either side of the line O4O2 (the
    y axis); C on the guide y = Y_GUIDE at |BC| to the right of B (assembly +1)."""
    psi = math.asin(L_O2A / L_O2O4)
    bx, by = L_O4B * math.sin(psi), L_O4B * math.cos(psi)
    dx = math.sqrt(L_BC ** 2 - (Y_GUIDE - by) ** 2)
    return bx + dx, -bx + dx, 2.0 * L_O4B * math.sin(psi)   # right, left extreme, H


@pytest.fixture(scope="module")
def shaper_cn():
    return linkage.analyze(example_path("shaper_cn.toml"), crank_angles_deg=GRID)


def test_the_cut_acts_between_the_idle_runs_by_the_ram_coordinate(shaper_cn):
    """The working stroke is "toward" (the ram moves to −x, from the right extreme): the
    cut acts where the ram has travelled 0.05·H … 0.95·H from the right extreme, and
    nowhere in the idle stroke."""
    s_right, s_left, H = _hand_stroke()
    assert H == pytest.approx(0.31263157894736837, rel=1e-15)
    k, f = shaper_cn.kinematics, shaper_cn.forces
    s = k["x_C_m"].to_numpy()                  # the ram's coordinate along the guide (+x)
    v = k["vx_C_m_s"].to_numpy()
    assert np.all(s <= s_right + 1e-12) and np.all(s >= s_left - 1e-12)
    travel = s_right - s                        # from the start of the working stroke
    working = v < 0.0
    inside = working & (travel >= 0.05 * H) & (travel <= 0.95 * H)
    clear = (np.abs(travel - 0.05 * H) > 1e-9) & (np.abs(travel - 0.95 * H) > 1e-9)
    F = f["F_res_N"].to_numpy()
    np.testing.assert_array_equal((F != 0.0)[clear], inside[clear])
    # both idle runs of the working stroke are found on the grid, and the cut between them
    assert np.sum(working & (travel < 0.05 * H)) >= 10
    assert np.sum(working & (travel > 0.95 * H)) >= 10
    assert np.sum(inside) > 300
    # the force opposes the ram's motion, at full magnitude: +x while the ram moves to −x
    np.testing.assert_array_equal(F[inside], F_CUT)
    assert np.all(F[inside] * v[inside] < 0.0)
    # the whole-stroke force of the example before the window acts in the idle runs too
    d = _shaper_cn()
    for key in ("from_fraction", "to_fraction"):
        del d["load"][0][key]
    F0 = linkage.analyze(d, crank_angles_deg=GRID).forces["F_res_N"].to_numpy()
    assert np.all(F0[working & clear] == F_CUT)


def test_the_twelve_positions_of_the_course(shaper_cn):
    """Positions 2 … 7 cut; 8 (0.3 mm before the end of the working stroke, 0.999·H) is
    in the idle run after the cut; 1 is the extreme (at rest); 9 … 12 the idle stroke."""
    res = linkage.analyze(example_path("shaper_cn.toml"))
    s_right, _, H = _hand_stroke()
    travel = (s_right - res.kinematics["x_C_m"].to_numpy()) / H
    assert 0.05 < travel[1] < 0.06 and 0.998 < travel[7] < 0.9995
    np.testing.assert_array_equal(res.forces["F_res_N"].to_numpy(),
                                  [0.0] + [F_CUT] * 6 + [0.0] * 5)
    # the kinematics of the example do not depend on the load
    d = _shaper_cn()
    for key in ("from_fraction", "to_fraction"):
        del d["load"][0][key]
    whole = linkage.analyze(d)
    assert res.kinematics.equals(whole.kinematics)
    changed = res.forces["M_drive_Nm"].to_numpy() != whole.forces["M_drive_Nm"].to_numpy()
    np.testing.assert_array_equal(np.flatnonzero(changed), [7])


def test_power_balance_of_the_chain_with_the_windowed_cut(shaper_cn):
    """Mур·ω₁ = −Σ P: the power of every weight, d'Alembert force and moment of inertia
    and of the windowed cutting force, from the kinematics table alone."""
    spec = shaper_cn.spec
    k, f = shaper_cn.kinematics, shaper_cn.forces
    g = spec.gravity
    P = f["F_res_N"].to_numpy() * k["vx_C_m_s"].to_numpy()
    for name, lk in spec.links.items():
        if lk.mass:
            vx, vy = k[f"vx_S_{name}_m_s"].to_numpy(), k[f"vy_S_{name}_m_s"].to_numpy()
            ax, ay = k[f"ax_S_{name}_m_s2"].to_numpy(), k[f"ay_S_{name}_m_s2"].to_numpy()
            P = P + lk.mass * (-ax * vx + (-g - ay) * vy)
        if lk.inertia:
            P = P - lk.inertia * (k[f"eps_{name}_rad_s2"].to_numpy()
                                  * k[f"omega_{name}_rad_s"].to_numpy())
    M = f["M_drive_Nm"].to_numpy()
    w1 = spec.omega
    scale = np.max(np.abs(M)) * abs(w1)
    np.testing.assert_allclose(M * w1, -P, rtol=0, atol=1e-9 * scale)


def test_the_fraction_form_equals_the_metre_form(shaper_cn):
    H = shaper_cn.summary.travel
    d = _shaper_cn()
    ld = d["load"][0]
    del ld["from_fraction"], ld["to_fraction"]
    ld.update(start_m=0.05 * H, span_m=0.90 * H)
    m = linkage.analyze(d, crank_angles_deg=GRID)
    assert m.forces.equals(shaper_cn.forces)
    assert m.kinematics.equals(shaper_cn.kinematics)


def _window_case(kind):
    """A four-bar with a window: the ratchet's rocker (degrees) or an offset slider on a
    turned guide (metres): data, its columns, the window's keys in both forms."""
    if kind == "rocker":
        d = ratchet_data()
        ld = d["load"][0]
        del ld["span_deg"]
        return d, ld, "M_res_Nm", "omega4_rad_s", "theta4_deg", "deg"
    d = loaded_slider()
    ld = d["load"][-1]
    ld.pop("span_m", None)
    return d, ld, "F_res_N", "v4_m_s", "s4_m", "m"


@pytest.mark.parametrize("kind", ["rocker", "slider"])
@pytest.mark.parametrize("stroke", ["working", "idle"])
def test_a_four_bar_window_by_the_swing_or_travel(kind, stroke):
    """start ≤ x ≤ start + span of the swing (travel) x from the start of the stroke, x
    from the extreme positions (the extremes table); the fraction form gives the same
    numbers; the stroke H is the distance between the extremes."""
    d, ld, rcol, vcol, ccol, unit = _window_case(kind)
    ld["stroke"] = stroke
    res0 = linkage.analyze(d, crank_angles_deg=[0.0])
    ex = res0.extremes[ccol].to_numpy()          # start of the working, of the idle stroke
    if kind == "rocker":
        H = abs(float(wrap_deg(ex[1] - ex[0])))
    else:
        H = abs(ex[1] - ex[0])
    start, span = 0.2 * H, 0.5 * H
    ld.update({f"start_{unit}": start, f"span_{unit}": span})
    res = linkage.analyze(d, crank_angles_deg=np.arange(0.0, 360.0, 0.5))
    k, f = res.kinematics, res.forces
    m = d["mechanism"]
    wsign = {"ccw": 1, "cw": -1, "away": m.get("assembly", 1),
             "toward": -m.get("assembly", 1)}[d["analysis"]["working_stroke"]]
    rate = k[vcol].to_numpy()
    state = np.sign(rate) * wsign
    c = k[ccol].to_numpy()
    origin = np.where(state > 0, ex[0], ex[1])
    x = np.abs(wrap_deg(c - origin)) if kind == "rocker" else np.abs(c - origin)
    in_stroke = state > 0 if stroke == "working" else state < 0
    active = in_stroke & (x >= start) & (x <= start + span)
    clear = (np.abs(x - start) > 1e-6 * H) & (np.abs(x - start - span) > 1e-6 * H)
    val = f[rcol].to_numpy()
    np.testing.assert_array_equal((val != 0)[clear], active[clear])
    assert np.sum(in_stroke & (x < start)) > 5 and np.sum(in_stroke & (x > start + span)) > 5
    assert np.all(val[active] * rate[active] < 0)
    # the same window as fractions of the stroke
    del ld[f"start_{unit}"], ld[f"span_{unit}"]
    ld.update(from_fraction=0.2, to_fraction=0.7)
    fr = linkage.analyze(d, crank_angles_deg=np.arange(0.0, 360.0, 0.5)).forces
    np.testing.assert_array_equal(fr[rcol].to_numpy()[clear], val[clear])
    np.testing.assert_allclose(fr["M_drive_Nm"].to_numpy()[clear],
                               f["M_drive_Nm"].to_numpy()[clear], rtol=0, atol=0)


def test_a_start_alone_acts_to_the_end_of_the_stroke():
    """A press over the last part of its stroke: ``start_m`` without ``span_m``."""
    d = copy.deepcopy(loaded_slider())
    ld = d["load"][-1]
    ld.pop("span_m", None)
    ld["stroke"] = "working"
    ex = linkage.analyze(d, crank_angles_deg=[0.0]).extremes["s4_m"].to_numpy()
    H = abs(ex[1] - ex[0])
    ld["start_m"] = 0.75 * H
    res = linkage.analyze(d, crank_angles_deg=np.arange(0.0, 360.0, 0.5))
    ld.pop("start_m")
    ld.update(from_fraction=0.75)
    same = linkage.analyze(d, crank_angles_deg=np.arange(0.0, 360.0, 0.5))
    F = res.forces["F_res_N"].to_numpy()
    np.testing.assert_array_equal(F, same.forces["F_res_N"].to_numpy())
    x = np.abs(res.kinematics["s4_m"].to_numpy() - ex[0])
    on = F != 0
    assert on.sum() > 5 and np.all(x[on] >= 0.75 * H * (1 - 1e-12))


def test_the_dynamics_take_the_windowed_cut():
    """The reduced model of the chain (what ``crankdyn dynamics`` runs): the cutting
    work per cycle is F·0.9·H with the window and F·H without it."""
    from dynamics.chain_model import chain_spec_model

    _, _, H = _hand_stroke()
    work = {}
    for windowed in (True, False):
        d = _shaper_cn()
        if not windowed:
            del d["load"][0]["from_fraction"], d["load"][0]["to_fraction"]
        model = chain_spec_model(linkage.load_spec(d), steps=1440)
        work[windowed] = np.trapezoid(model.extra["M_resist_loads_Nm"], model.phi)
    assert work[False] == pytest.approx(F_CUT * H, rel=2e-3)
    assert work[True] == pytest.approx(F_CUT * 0.9 * H, rel=2e-3)


def test_the_plans_take_the_windowed_cut():
    """Force polygons and Zhukovsky's lever at position 7 (cutting) and 8 (idle run
    after the cut): the ram's load vector is the cut or absent, and the lever's Mур is
    the kinetostatic Mур of the windowed load."""
    from linkage.chain_lever import zhukovsky
    from plans.chain_model import build_chain_plans

    res = linkage.analyze(example_path("shaper_cn.toml"))
    pps = build_chain_plans(res, [7, 8])
    forces, moments = res.loads
    lev = zhukovsky(res.motion, forces, moments, res.spec.gravity)
    M = res.forces["M_drive_Nm"].to_numpy()
    for pp, cut in zip(pps, (True, False)):
        i = pp.position - 1
        assert lev.M_balance[i] == pytest.approx(M[i], rel=1e-9)
        loads = {v.name: v for plan in pp.plans.values() for v in plan.vectors
                 if v.kind == "load"}
        cuts = [v for name, v in loads.items() if name.startswith("F")
                and abs((v.end - v.start) * v.scale - F_CUT) < 1e-6]
        assert bool(cuts) == cut, sorted(loads)


# ------------------------------------------------------------------------- errors
def _errors(d, analyze=False):
    with pytest.raises(SpecError) as e:
        linkage.analyze(d) if analyze else linkage.load_spec(d)
    return {(p.key, p.text.key) for p in e.value.problems if p.text is not None}, e.value


@pytest.mark.parametrize("edit, analyze, path, key", [
    (lambda ld: ld.update(start_m=0.01), False, "load[0].from_fraction",
     "errors.linkage.spec.window_both"),
    (lambda ld: ld.update(from_fraction=0.6, to_fraction=0.4), False,
     "load[0].from_fraction", "errors.linkage.spec.window_order"),
    (lambda ld: ld.update(from_fraction=0.5, to_fraction=0.5), False,
     "load[0].from_fraction", "errors.linkage.spec.window_order"),
    (lambda ld: (ld.pop("from_fraction"), ld.pop("to_fraction"),
                 ld.update(start_m=0.2, span_m=0.2)), True, "load[0].start_m",
     "errors.linkage.spec.window_outside_m"),
    (lambda ld: (ld.pop("from_fraction"), ld.pop("to_fraction"),
                 ld.update(start_m=0.32)), True, "load[0].start_m",
     "errors.linkage.spec.window_outside_m"),
    (lambda ld: ld.update(start_deg=1.0), False, "load[0].start_deg",
     "errors.linkage.spec.use_for"),
])
def test_window_errors_are_keyed(edit, analyze, path, key):
    d = _shaper_cn()
    edit(d["load"][0])
    found, _ = _errors(d, analyze)
    assert (path, key) in found, found


def test_a_window_on_a_force_or_a_fraction_out_of_range_is_refused():
    d = _shaper_cn()
    d["load"].append({"link": "rod", "force_N": [0.0, -10.0], "start_m": 0.1})
    d["load"][0]["to_fraction"] = 1.5
    found, _ = _errors(d)
    assert ("load[1].start_m", "errors.linkage.spec.applies_resistance_only") in found
    assert any(p == "load[0].to_fraction" for p, _ in found), found


def test_a_rocker_window_outside_the_swing_in_each_language():
    """The ratchet's swing (OA 0.175, AB 0.55, CB 0.325, OC 0.54 m) by the law of cosines
    at the two extremes (OB = AB ± OA) is 68.43°: a window from 40° over 30° does not fit."""
    d = ratchet_data()
    d["load"][0].update(start_deg=40.0, span_deg=30.0)
    found, err = _errors(d, analyze=True)
    assert ("load[0].start_deg", "errors.linkage.spec.window_outside_deg") in found
    lines = {lang: "\n".join(err.lines(lang)) for lang in ("en", "ru", "zh")}
    assert "40 … 70° from the start of the swing" in lines["en"], lines["en"]
    assert "участок 40 … 70° от начала качания" in lines["ru"], lines["ru"]
    assert "40 … 70° 的作用区段超出了摆角" in lines["zh"], lines["zh"]
    swing = re.search(r"swing of ([\d.]+)°", lines["en"]).group(1)

    def gamma(ob):
        return math.degrees(math.acos((0.54 ** 2 + 0.325 ** 2 - ob ** 2) / (2 * 0.54 * 0.325)))
    assert float(swing) == pytest.approx(gamma(0.55 + 0.175) - gamma(0.55 - 0.175), abs=1e-4)


def test_a_window_of_an_output_that_turns_fully_is_refused():
    """A chain whose output rocker turns fully (a double crank: the lever of a Whitworth
    quick-return) has no strokes: a window cannot be placed (a span alone acts whenever
    the link moves, as before)."""
    d = {"mechanism": {"kind": "chain", "name": "whitworth", "crank": 0.1,
                       "output": "lever", "omega_rad_s": 10.0,
                       "frame": {"O": [0.0, 0.0], "C": [0.0, 0.04]}},
         "group": [{"kind": "RPR", "links": ["block", "lever"], "joints": ["A", "C"]}],
         "load": [{"link": "lever", "resistance_Nm": 5.0, "stroke": "both",
                   "from_fraction": 0.1}],
         "analysis": {"crank_angles_deg": [0.0, 90.0, 180.0, 270.0]}}
    found, _ = _errors(d, analyze=True)
    assert ("load[0].from_fraction", "errors.linkage.spec.window_needs_extremes") in found
    d["load"][0].pop("from_fraction")
    d["load"][0]["span_deg"] = 30.0
    M = linkage.analyze(d).forces["M_res_Nm"].to_numpy()
    assert np.all(np.abs(M) == 5.0)
