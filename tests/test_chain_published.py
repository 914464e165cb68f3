"""Published worked examples of six-link mechanisms (issue #20) against the chain's analysis.

Each case models the book's mechanism as a ``kind = "chain"`` spec, I(0,1) → II RPR(2,3)
→ II RRP(4,5) (crank, block in the slot of the lever, rod, ram), and compares the chain's
own numbers (:attr:`linkage.chain_analysis.ChainAnalysis.summary`: the ram's extremes found
by bisection of its velocity, the crank angles between them, the stroke) with the printed
answers.

Source: R. S. Khurmi, J. K. Gupta, *Theory of Machines*, 14th ed., S. Chand, New Delhi,
2005, chapter 5 "Simple Mechanisms" (crank and slotted lever and Whitworth quick return
motion mechanisms).  The books' answers there are exact trigonometric results (the slot is
tangent to the crank circle, or perpendicular to the line of centres, at the extremes),
printed as round numbers (30°, 2, 450 mm; 20 mm, 75 mm, 240°, 120°), so the chain, whose
extremes are refined to round-off, must reproduce them to round-off: the tolerance is
1e-9 relative, not the 2-3 figures of a graphical answer.  A second, independent worked
answer (a Whitworth time ratio printed to 4 figures from an angle rounded to 0.1°) is
compared at the precision of its rounding.

Velocities and accelerations: the shaping machine (牛头刨床) of the Chinese course design on
the theory of machines, data set 方案 I (n2 = 60 r/min, l_O2O4 = 380, l_O2A = 110,
l_O4B = 540, l_BC = 0.25·l_O4B mm), bundled as ``examples/shaper_cn.toml``, against a
published course-design report's velocity plan at position 9 and acceleration plan at
position 4 («机械原理课程设计 牛头刨床», https://m.qiqiwenku.com/ppt/164184.html).  The
report's plans were drawn in CAD (scale 0.001 (m/s)/mm, lengths printed to 1e-4 mm) and
printed to 5-8 figures; every one of its twelve numbers is reproduced to its last printed
digit, so the tolerance is 1e-5 relative or half a unit of the last printed digit,
whichever is coarser (a hand-drawn plan would warrant 2-5 %; these are far sharper).
The geometry the report does not print (where position 1 is, the height of the ram's
guide) is the course's rule, and the tests show that the other readings (numbering from
the other extreme, the guide through the top or the chord of B's arc) miss the printed
numbers by far more than the tolerance.

Not found: a second, independent worked example of a six-link mechanism with printed
velocities and accelerations whose geometry is all stated in the text (Khurmi's
Whitworth velocity example, OQ = 100, OP = 200, RQ = 150, RS = 500 mm, the crank at 60°
to the vertical, 120 rpm, and the acceleration examples of ch. 8 fix the ram's line of
stroke or some lengths only in their figures; Rattan's exercises likewise), and a
published kinetostatic answer (reactions, Mур) for 方案 I.  The
velocity and acceleration plans of the chain are also checked against their own closure
and an independent solve in tests/test_chain*.py.
"""
import math

import numpy as np
import pytest

import linkage
from crankbase.resources import example_path
from linkage import chain as ch


def quick_return(O, C, crank, arm, rod, guide_y, working_stroke, omega=1.0):
    """Crank O→A, block A in the slot of the lever pivoted at C (its point D at ``arm``
    metres along the slot from C, negative: on the far side of C from the crank pin),
    rod D→E and the ram E on the horizontal guide y = ``guide_y``."""
    return {"mechanism": {"kind": "chain", "name": "quick_return", "crank": crank,
                          "crank_link": "crank", "pivot": "O", "pin": "A", "output": "ram",
                          "omega_rad_s": omega, "gravity_m_s2": 0.0,
                          "frame": {"O": list(O), "C": list(C)}},
            "group": [{"kind": "RPR", "links": ["block", "lever"], "joints": ["A", "C"]},
                      {"kind": "RRP", "links": ["rod", "ram"], "joints": ["D", "E"],
                       "lengths": [rod], "guide_point": [0.0, guide_y],
                       "guide_angle_deg": 0.0, "assembly": 1}],
            "links": {"lever": {"points": {"D": [arm, 0.0]}}},
            "analysis": {"positions": 12, "working_stroke": working_stroke}}


def lever_at(result, phi_deg):
    """(lever angle from the +y axis [deg], crank pin A, crank pivot O) at a crank angle."""
    res = ch.solve(result.spec.mechanism, math.radians(phi_deg), 1.0, 0.0)
    theta = float(np.asarray(res.links["lever"].theta))
    zA = res.point("A").z
    A = complex(float(zA.x), float(zA.y))
    return math.degrees(theta) - 90.0, A


# Khurmi & Gupta, Theory of Machines, 14th ed. (2005), ch. 5, Example 5.2: crank and
# slotted lever quick return motion mechanism; distance between the fixed centres 240 mm,
# driving crank 120 mm, slotted bar 450 mm, the line of stroke through the extreme
# positions of the free end of the lever.  Printed answers: inclination of the slotted
# bar with the vertical in the extreme position 30°, time ratio (cutting : return) 2,
# length of stroke 450 mm.  The connecting rod's length is not given (the stroke does not
# depend on it when the line of stroke passes through the lever's extreme ends): two
# lengths are tried.
KHURMI_5_2 = {"centres_m": 0.240, "crank_m": 0.120, "lever_m": 0.450,
              "inclination_deg": 30.0, "time_ratio": 2.0, "stroke_m": 0.450}


@pytest.mark.parametrize("rod", [0.15, 0.30])
def test_khurmi_example_5_2_crank_and_slotted_lever(rod):
    k = KHURMI_5_2
    tilt = math.radians(k["inclination_deg"])
    # lever pivot C at the origin, crank centre O above it; the line of stroke at the
    # height of the lever's end in its extreme positions (l·cos 30°, the book's figure)
    spec = quick_return((0.0, k["centres_m"]), (0.0, 0.0), k["crank_m"], k["lever_m"], rod,
                        k["lever_m"] * math.cos(tilt), "toward")
    r = linkage.analyze(spec)
    s = r.summary
    # the cutting stroke is the slow one: with the crank turning ccw it is the ram's
    # travel toward −x ("toward" the start of the guide's axis)
    assert s.time_ratio == pytest.approx(k["time_ratio"], rel=1e-9)
    assert s.working_crank_angle_deg == pytest.approx(240.0, rel=1e-9)
    assert s.idle_crank_angle_deg == pytest.approx(120.0, rel=1e-9)
    assert s.travel == pytest.approx(k["stroke_m"], rel=1e-9)
    # the slotted bar's inclination with the vertical in both extreme positions, and the
    # book's construction: there the slot is tangent to the crank circle (OA ⟂ CA)
    tilts = []
    for phi in (s.phi_working_start_deg, s.phi_working_end_deg):
        t, A = lever_at(r, phi)
        tilts.append(t)
        OA = A - 1j * k["centres_m"]
        assert abs((OA * A.conjugate()).real) < 1e-9 * k["crank_m"] * abs(A)
    assert sorted(tilts) == pytest.approx([-k["inclination_deg"], k["inclination_deg"]],
                                          rel=1e-9)
    # the ram's extremes are D's extreme x ± the rod: the stroke is 2·l·sin 30°
    assert abs(s.end - s.start) == pytest.approx(2 * k["lever_m"] * math.sin(tilt), rel=1e-9)


# Khurmi & Gupta, Theory of Machines, 14th ed. (2005), ch. 5, Exercises, problem on the
# Whitworth quick return motion mechanism of Fig. 5.38: length of stroke 150 mm, driving
# crank 40 mm, time of cutting stroke / time of return stroke = 2; find CD (the distance
# between the crank centre C and the lever's pivot D) and PD (the lever's arm to the rod),
# and the angles α (cutting) and β (return).  Printed answers: CD = 20 mm, PD = 75 mm
# (hint: stroke = 2·PD), α = 240°, β = 120°.  Here the book's answers are the input and
# the chain must give back the stroke and the time ratio; the line of stroke passes
# through D (the lever horizontal in the extremes), the rod PR is not given (two tried).
KHURMI_WHITWORTH = {"crank_m": 0.040, "CD_m": 0.020, "PD_m": 0.075, "stroke_m": 0.150,
                    "time_ratio": 2.0, "alpha_deg": 240.0, "beta_deg": 120.0}


@pytest.mark.parametrize("rod", [0.20, 0.35])
def test_khurmi_whitworth_exercise(rod):
    k = KHURMI_WHITWORTH
    # crank centre at the origin, the lever's pivot D above it (|CD| = 20 mm < crank: the
    # lever turns fully); the arm PD on the far side of D from the crank pin
    spec = quick_return((0.0, 0.0), (0.0, k["CD_m"]), k["crank_m"], -k["PD_m"], rod,
                        k["CD_m"], "toward")
    r = linkage.analyze(spec)
    s = r.summary
    assert s.time_ratio == pytest.approx(k["time_ratio"], rel=1e-9)
    assert s.working_crank_angle_deg == pytest.approx(k["alpha_deg"], rel=1e-9)
    assert s.idle_crank_angle_deg == pytest.approx(k["beta_deg"], rel=1e-9)
    assert s.travel == pytest.approx(k["stroke_m"], rel=1e-9)
    # in the extremes the lever (the slot) is horizontal, perpendicular to CD
    for phi in (s.phi_working_start_deg, s.phi_working_end_deg):
        t, _ = lever_at(r, phi)
        assert abs(math.sin(math.radians(t + 90.0))) < 1e-9


def test_khurmi_whitworth_other_centre_distance_fails():
    """A wrong CD (the crank's 40 mm · cos 45°) gives another time ratio: the comparison
    is sharp."""
    k = KHURMI_WHITWORTH
    spec = quick_return((0.0, 0.0), (0.0, k["crank_m"] * math.cos(math.pi / 4)),
                        k["crank_m"], -k["PD_m"], 0.2, k["crank_m"] * math.cos(math.pi / 4),
                        "toward")
    s = linkage.analyze(spec).summary
    assert s.time_ratio == pytest.approx(3.0, rel=1e-9)          # β = 90°: 270/90
    assert s.time_ratio != pytest.approx(k["time_ratio"], rel=1e-3)


# A Whitworth quick return problem with a worked answer from a second, independent
# source: assignmentexpert.com, Engineering / Mechanical Engineering, question 133648
# ("The Whitworth quick return motion mechanism has the driving crank AC = 150 mm long.
# The distance between fixed centres CD = 100 mm. The line of stroke of the ram passes
# through the centre of rotation of the slotted lever whose free end is connected to the
# ram by a connecting link. Find the ratio of time of cutting to time of return."),
# worked answer cos(β/2) = CD/AC, β/2 = 48.2°, β = 96.4°, ratio 2.735.  The answer goes
# through an angle rounded to 0.1° (2.734 from 96.4° exactly), so the tolerance is 2e-3
# on the ratio and 0.1° on β; the lever's arm and the rod are not given (two tried: the
# ratio does not depend on them).
ASSIGNMENTEXPERT_133648 = {"crank_m": 0.150, "CD_m": 0.100, "time_ratio": 2.735,
                           "beta_deg": 96.4}


@pytest.mark.parametrize("arm, rod", [(0.10, 0.30), (0.25, 0.60)])
def test_whitworth_time_ratio_second_source(arm, rod):
    k = ASSIGNMENTEXPERT_133648
    spec = quick_return((0.0, 0.0), (0.0, k["CD_m"]), k["crank_m"], -arm, rod, k["CD_m"],
                        "toward")
    s = linkage.analyze(spec).summary
    assert s.time_ratio == pytest.approx(k["time_ratio"], abs=2e-3)
    assert s.idle_crank_angle_deg == pytest.approx(k["beta_deg"], abs=0.1)
    # and the exact value of the book's construction, to round-off
    beta = 2.0 * math.degrees(math.acos(k["CD_m"] / k["crank_m"]))
    assert s.idle_crank_angle_deg == pytest.approx(beta, rel=1e-9)
    assert s.travel == pytest.approx(2.0 * arm, rel=1e-9)


# ---------------------------------------------------------------------------------------
# The Chinese course design's shaper, data set 方案 I: velocities and accelerations.
#
# Source: «机械原理课程设计 牛头刨床» (a course-design report on the shaping machine of the
# course design to Sun Huan's 《机械原理》, data set 方案 I), published at
# https://m.qiqiwenku.com/ppt/164184.html: "3. 对位置 9 点进行速度分析和加速度分析 (a) 速度
# 分析", velocity scale μv = 0.001 (m/s)/mm, figure 1-6 (the velocity plan at position 9),
# and the acceleration plan of the section before it (figure 1-5).  Its printed numbers:
# position 9: v_A4 = 0.3289949 m/s, ω4 = v_A4 / l_O4A = 0.3289949 / 0.315119 = 1.044034
# rad/s, v_A4A3 = 0.60782497 m/s, v_B = ω4·l_O4B = 0.56377824 m/s, v_C = 0.5518355 m/s,
# v_CB = 0.1436768 m/s, ω5 = v_CB / l_BC = 1.06427 rad/s;
# figure 1-5: a_B = a_A4·l_O4B/l_O4A = 1.201248 m/s², a^n_CB = ω5²·l_BC = 0.01785 m/s²,
# a_C = 0.617683 m/s², a^t_CB = 0.9942344 m/s².  The excerpt read does not show that
# section's position number; of the twelve positions only position 4 fits its a_B (the
# neighbours: 2.035 at 3, 1.152 at 5), and there every one of the four numbers agrees.
# The report prints magnitudes (the directions are in its plans).
# As printed (strings: the last printed digit sets the rounding allowance).
SHAPER_CN_POSITION_9 = {"l_O4A_m": "0.315119", "v_A4_m_s": "0.3289949",
                        "omega4_rad_s": "1.044034", "v_A4A3_m_s": "0.60782497",
                        "v_B_m_s": "0.56377824", "v_C_m_s": "0.5518355",
                        "v_CB_m_s": "0.1436768", "omega5_rad_s": "1.06427"}
SHAPER_CN_POSITION_4 = {"a_B_m_s2": "1.201248", "an_CB_m_s2": "0.01785",
                        "a_C_m_s2": "0.617683", "at_CB_m_s2": "0.9942344"}
#: the precision of CAD-drawn plans (see the module's docstring) …
SHAPER_CN_RTOL = 1e-5


def printed(text):
    """``pytest.approx`` of a printed number: 1e-5 relative, or half a unit of its last
    printed digit where that is coarser (0.01785 is 0.0178502 rounded)."""
    half_unit = 0.5 * 10.0 ** -len(text.split(".")[1])
    return pytest.approx(float(text), rel=SHAPER_CN_RTOL, abs=half_unit)
L_O4B, L_BC = 0.540, 0.135           # 方案 I: l_O4B, l_BC = 0.25·l_O4B [m]


@pytest.fixture(scope="module")
def shaper_cn():
    r = linkage.analyze(example_path("shaper_cn.toml"))
    return r, r.kinematics.set_index("position")


def _shaper_cn_numbers(k, pos):
    """The report's quantities from the chain's kinematics table at position ``pos``."""
    row = k.loc[pos]
    w4, w5, e5 = row["omega_lever_rad_s"], row["omega_rod_rad_s"], row["eps_rod_rad_s2"]
    s = row["s_block_lever_m"]
    return {"l_O4A_m": s, "v_A4_m_s": abs(w4) * s, "omega4_rad_s": abs(w4),
            "v_A4A3_m_s": abs(row["vrel_block_lever_m_s"]), "v_B_m_s": row["v_B_m_s"],
            "v_C_m_s": abs(row["v_ram_m_s"]), "v_CB_m_s": abs(w5) * L_BC,
            "omega5_rad_s": abs(w5),
            "a_B_m_s2": row["a_B_m_s2"], "an_CB_m_s2": w5 * w5 * L_BC,
            "a_C_m_s2": abs(row["a_ram_m_s2"]), "at_CB_m_s2": abs(e5) * L_BC}


def test_shaper_cn_positions_are_the_course_positions(shaper_cn):
    """Position 1 is the ram's extreme at the start of the slow stroke (the slot tangent
    to the crank circle), the crank turns ccw by 30° a position; K and H as the course's
    formulas give them."""
    r, k = shaper_cn
    s = r.summary
    psi = math.asin(0.110 / 0.380)                     # the lever's half swing
    assert s.time_ratio == pytest.approx((math.pi + 2 * psi) / (math.pi - 2 * psi), rel=1e-9)
    assert s.travel == pytest.approx(2 * L_O4B * math.sin(psi), rel=1e-9)
    # the guide through the middle of the sagitta of B's arc (the spec's literal)
    guide = r.spec.mechanism.groups[1].guide
    assert complex(guide.point).imag == pytest.approx(L_O4B * (1 + math.cos(psi)) / 2,
                                                      abs=1e-10)
    assert k.loc[1, "phi_deg"] == pytest.approx(s.phi_working_start_deg, abs=1e-9)
    assert np.diff(np.unwrap(np.radians(k["phi_deg"].to_numpy()))) == pytest.approx(
        np.full(11, math.radians(30.0)))
    assert abs(k.loc[1, "v_ram_m_s"]) < 1e-9 and abs(k.loc[1, "omega_lever_rad_s"]) < 1e-9
    # positions 2 … 8 are in the working (slow) stroke, 9 … 12 in the return: 8' is at
    # 180° + 2ψ = 213.65° from position 1
    v = k["v_ram_m_s"].to_numpy()
    assert (np.sign(v[1:8]) == np.sign(v[1])).all() and (np.sign(v[8:]) == -np.sign(v[1])).all()


@pytest.mark.parametrize("key", list(SHAPER_CN_POSITION_9))
def test_shaper_cn_velocity_plan_position_9(shaper_cn, key):
    """The course-design report's velocity plan at position 9 (figure 1-6), m.qiqiwenku.com
    /ppt/164184.html: every printed number to 1e-5 relative."""
    _, k = shaper_cn
    ours = _shaper_cn_numbers(k, 9)[key]
    assert ours == printed(SHAPER_CN_POSITION_9[key])


@pytest.mark.parametrize("key", list(SHAPER_CN_POSITION_4))
def test_shaper_cn_acceleration_plan_position_4(shaper_cn, key):
    """The same report's acceleration plan (figure 1-5): a_B, a^n_CB, a_C, a^t_CB at
    position 4 to 1e-5 relative."""
    _, k = shaper_cn
    ours = _shaper_cn_numbers(k, 4)[key]
    assert ours == printed(SHAPER_CN_POSITION_4[key])


def test_shaper_cn_coriolis_position_9(shaper_cn):
    """The Coriolis acceleration of the block in the slot, a^k_A4A3 = 2·ω4·v_A4A3, from the
    report's printed ω4 and v_A4A3 at position 9 (the course's plan computes it so), and
    perpendicular to the slot."""
    r, k = shaper_cn
    p = SHAPER_CN_POSITION_9
    row = k.loc[9]
    assert row["acor_block_lever_m_s2"] == pytest.approx(
        2 * float(p["omega4_rad_s"]) * float(p["v_A4A3_m_s"]), rel=SHAPER_CN_RTOL)
    slot = math.radians(row["theta_lever_deg"])
    along = row["acorx_block_lever_m_s2"] * math.cos(slot) \
        + row["acory_block_lever_m_s2"] * math.sin(slot)
    assert abs(along) < 1e-12 * row["acor_block_lever_m_s2"]


def _shaper_cn_spec(guide_y=None, start_from_idle=False):
    import tomllib
    data = tomllib.loads(example_path("shaper_cn.toml").read_text(encoding="utf-8"))
    if guide_y is not None:
        data["group"][1]["guide_point"] = [0.0, guide_y]
    if start_from_idle:
        data["analysis"]["working_stroke"] = "away"
    return data


@pytest.mark.parametrize("change", ["guide through the top of B's arc",
                                    "guide through the chord of B's arc",
                                    "numbered from the other extreme"])
def test_shaper_cn_other_readings_miss_the_report(change):
    """The readings of the geometry the report does not print are fixed by its numbers:
    the ram's guide through the middle of the sagitta of B's arc and position 1 at the
    start of the slow stroke.  Each other reading misses at least one printed number by
    far more than the tolerance (the comparison is sharp)."""
    psi = math.asin(0.110 / 0.380)
    data = {"guide through the top of B's arc": lambda: _shaper_cn_spec(guide_y=L_O4B),
            "guide through the chord of B's arc":
                lambda: _shaper_cn_spec(guide_y=L_O4B * math.cos(psi)),
            "numbered from the other extreme":
                lambda: _shaper_cn_spec(start_from_idle=True)}[change]()
    k = linkage.analyze(data).kinematics.set_index("position")
    book = {**SHAPER_CN_POSITION_9, **SHAPER_CN_POSITION_4}
    ours = {**{q: _shaper_cn_numbers(k, 9)[q] for q in SHAPER_CN_POSITION_9},
            **{q: _shaper_cn_numbers(k, 4)[q] for q in SHAPER_CN_POSITION_4}}
    worst = max(abs(ours[q] / float(book[q]) - 1.0) for q in book)
    assert worst > 100 * SHAPER_CN_RTOL


def test_shaper_cn_graphical_plans_are_the_reports():
    """The graphical method's own plans (``crankdyn linkage --example shaper_cn --plans 4,9``,
    :func:`plans.chain_model.build_chain_plans`) give the report's segments: at position 9
    p→a4 (v_A4), a3→a4 (v_A4A3), p→b, p→c, b→c; at position 4 π→b, b→n (a^n_CB), π→c,
    n→c (a^t_CB), each as its segment's length × the plan's scale."""
    from plans.chain_model import build_chain_plans

    res = linkage.analyze(example_path("shaper_cn.toml"))
    pps = {pp.position: pp for pp in build_chain_plans(res, [4, 9])}
    v9, a4 = pps[9].plans["velocity"], pps[4].plans["acceleration"]
    p9, p4 = SHAPER_CN_POSITION_9, SHAPER_CN_POSITION_4
    for plan, segment, key, book in ((v9, "pa3", "v_A4_m_s", p9), (v9, "a_a3", "v_A4A3_m_s", p9),
                                     (v9, "pb", "v_B_m_s", p9), (v9, "pc", "v_C_m_s", p9),
                                     (v9, "b_c", "v_CB_m_s", p9),
                                     (a4, "pi_b", "a_B_m_s2", p4), (a4, "b_n4", "an_CB_m_s2", p4),
                                     (a4, "pi_c", "a_C_m_s2", p4),
                                     (a4, "n4_c", "at_CB_m_s2", p4)):
        vec = plan.vector(segment)
        assert vec.length_mm * plan.scale == printed(book[key]), (segment, key)
