"""linkage.chain: the mechanism as data (a driver and an ordered list of class II groups).

* Today's crank-rocker and crank-slider are two instances of the chain: the chain of
  :func:`linkage.chain.from_mechanism` gives ``linkage.analysis``'s numbers bit for bit
  (the same group routines in the same order, the same loads).
* The structure formula, Chebyshev's mobility and one clear error for each structural
  mistake (a link named twice, a group attached to a joint not yet solved, a joint that
  does not exist, a mechanism that cannot be assembled, a group that passes a dead
  position).

The independent judge of every group kind (a global Newton–Euler solve) is in
tests/test_chain_judge.py.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from crankbase.errors import AssemblyError, SpecError
from linkage import chain as ch
from linkage.analysis import build_mechanism, solve_columns
from linkage.loads import external_loads, stroke_cycle
from linkage.spec import load_spec
from newton_euler import loaded_rocker, loaded_slider, ratchet_data

_DEG = 180.0 / math.pi

SPECS = {
    "ratchet": ratchet_data,
    "rocker": loaded_rocker,
    "rocker-cw-branch": lambda: loaded_rocker(ground_angle_deg=-35.0, assembly=-1,
                                              omega=-12.0, eps=-5.0, working="cw"),
    "slider": loaded_slider,
    "slider-toward": lambda: loaded_slider(assembly=-1, working="toward", offset=-0.02,
                                           guide_deg=-120.0, omega=90.0, eps=-30.0),
}


def _today_and_chain(data, phi):
    spec = load_spec(data)
    mech = build_mechanism(spec)
    rot = 1 if spec.omega > 0 else -1
    ext = mech.extremes(rot, spec.working_stroke) if spec.working_stroke else None
    K, F = solve_columns(spec, phi, mech, ext, course_tables=False)
    chain = ch.from_mechanism(mech, spec.links)
    res = ch.solve(chain, phi, spec.omega, spec.epsilon)
    kin = {"crank": res.links["crank"], "A": res.joints["A"], "dyad": res.solutions[0],
           "links": res.links}
    forces, moments, _ = external_loads(spec, mech, kin, stroke_cycle(mech, spec, ext))
    frc = ch.kinetostatics(res, forces, moments, spec.gravity)
    return spec, K, F, chain, res, frc


@pytest.mark.parametrize("name", sorted(SPECS))
def test_today_mechanisms_are_chains_bit_for_bit(name):
    phi = np.radians(np.array([0.0, 17.0, 95.5, 181.0, 250.0, 333.3]))
    spec, K, F, _, res, frc = _today_and_chain(SPECS[name](), phi)
    out = spec.link_names[2]
    same = np.testing.assert_array_equal
    same(np.multiply(res.links["coupler"].theta, _DEG), K["theta3_deg"])
    same(res.omega("coupler"), K["omega3_rad_s"])
    same(res.eps("coupler"), K["eps3_rad_s2"])
    if out == "rocker":
        same(np.multiply(res.links["rocker"].theta, _DEG), K["theta4_deg"])
        same(res.omega("rocker"), K["omega4_rad_s"])
        same(res.eps("rocker"), K["eps4_rad_s2"])
    else:
        s = res.solutions[0]
        same(s.s, K["s4_m"])
        same(s.v, K["v4_m_s"])
        same(s.a, K["a4_m_s2"])
    points = {"A": res.point("A"), "B": res.point("B"),
              "S2": res.links["crank"].point(spec.links["crank"].cg),
              "S3": res.links["coupler"].point(spec.links["coupler"].cg),
              "S4": res.links[out].point(spec.links[out].cg)}
    for p, P in points.items():
        for col, v in zip(("x_m", "y_m", "vx_m_s", "vy_m_s", "ax_m_s2", "ay_m_s2"),
                          (P.z.x, P.z.y, P.v.x, P.v.y, P.a.x, P.a.y)):
            same(np.broadcast_to(v, phi.shape), K[f"{p}_{col}"], err_msg=f"{p}_{col}")
    for col, v in (("R12", frc.R("frame", "crank")), ("R23", frc.R("crank", "coupler")),
                   ("R43", frc.R(out, "coupler"))):
        same(v.x, F[f"{col}_x_N"], err_msg=col)
        same(v.y, F[f"{col}_y_N"], err_msg=col)
    r23 = frc.reactions[("crank", "coupler")]
    same(r23.n, F["R23_n_N"])
    same(r23.t, F["R23_t_N"])
    r14 = frc.reactions[("frame", out)]
    same(r14.force.x, F["R14_x_N"])
    same(r14.force.y, F["R14_y_N"])
    if out == "rocker":
        same(r14.n, F["R14_n_N"])
        same(r14.t, F["R14_t_N"])
    else:
        same(r14.normal, F["N14_N"])
        same(r14.couple, F["M14_Nm"])
    same(frc.M_drive, F["M_drive_Nm"])
    assert np.all(np.abs(F["M_drive_Nm"]) > 0)          # a loaded mechanism (not all zero)


def test_reactions_hold_both_orders_with_opposite_signs():
    phi = np.radians([10.0, 200.0])
    *_, frc = _today_and_chain(loaded_rocker(), phi)
    for (i, j), r in list(frc.reactions.items()):
        back = frc.reactions[(j, i)]
        np.testing.assert_array_equal(back.force.x, -r.force.x)
        assert (r.on, r.by) == (j, i)


def test_structure_formula_and_mobility():
    mech = ch.from_mechanism(build_mechanism(load_spec(loaded_rocker())))
    assert ch.structure_formula(mech) == "I(0,1) → II(2,3)"
    assert ch.structure_formula(mech, kinds=True) == "I(0,1) → II RRR(2,3)"
    assert ch.mobility(mech) == (1, 3, 4, 0)
    shaper = _shaper()
    assert ch.structure_formula(shaper) == "I(0,1) → II(2,3) → II(4,5)"
    assert ch.structure_formula(shaper, kinds=True) == "I(0,1) → II RPR(2,3) → II RRP(4,5)"
    assert ch.mobility(shaper) == (1, 5, 7, 0)
    assert shaper.link_names == ["crank", "block", "lever", "rod", "ram"]


def _shaper(**kw):
    """A crank-slotted-lever shaper: crank OA = 0.1 m, lever pivot C 0.3 m below O, lever
    CD = 0.6 m, rod DE = 0.25 m, ram on a horizontal guide 0.55 m above C."""
    groups = kw.pop("groups", None) or [
        ch.RPR(("block", "lever"), ("A", "C")),
        ch.RRP(("rod", "ram"), ("D", "E"), 0.25, ch.Guide("frame", 0.25j, 0.0), 1)]
    return ch.Mechanism({"O": 0j, "C": -0.3j}, ch.Driver(0.1), groups,
                        {"lever": ch.Link(20.0, 0.6, 0.3 + 0j, {"D": 0.6 + 0j}),
                         **kw.pop("links", {})}, "shaper")


def test_a_link_named_twice_is_a_mobility_error():
    with pytest.raises(SpecError) as e:
        _shaper(groups=[ch.RPR(("block", "lever"), ("A", "C")),
                        ch.RRP(("rod", "lever"), ("D", "E"), 0.25)])
    msg = str(e.value)
    assert "W = 3n − 2p5 − p4 = 3·4 − 2·7 − 0 = -2" in msg
    ru = "\n".join(e.value.lines("ru"))
    assert "Чебышева" in ru and "W = " in ru


def test_a_group_attached_to_a_joint_not_yet_solved():
    with pytest.raises(SpecError) as e:
        _shaper(groups=[ch.RRP(("rod", "ram"), ("D", "E"), 0.25, ch.Guide("frame", 0.25j)),
                        ch.RPR(("block", "lever"), ("A", "C"))])
    assert "groups[0]" in str(e.value)
    assert "II RRP(2,3) is attached to the joint D, which a later group or link defines" \
        in str(e.value)


def test_a_joint_that_does_not_exist_and_a_guide_not_yet_solved():
    with pytest.raises(SpecError) as e:
        _shaper(groups=[ch.RPR(("block", "lever"), ("A", "Q")),
                        ch.PRP(("s1", "s2"), ("F",), (ch.Guide("s2"), ch.Guide("frame")))])
    msg = str(e.value)
    assert "joint Q, which no frame joint" in msg
    assert "guide of the link s2, which is not solved before it" in msg


def test_a_joint_named_twice_and_the_frame_as_a_group_link():
    with pytest.raises(SpecError, match="names its new joint C, a name already given"):
        _shaper(groups=[ch.RPR(("block", "lever"), ("A", "C")),
                        ch.RRP(("rod", "ram"), ("D", "C"), 0.25, ch.Guide("frame", 0.25j))])
    with pytest.raises(SpecError, match="lists the frame among its two moving links"):
        _shaper(groups=[ch.RPR(("block", "lever"), ("A", "C")),
                        ch.RRP(("rod", "frame"), ("D", "E"), 0.25, ch.Guide("frame", 0.25j))])


def test_a_group_with_the_wrong_number_of_joints():
    with pytest.raises(SpecError) as e:
        _shaper(groups=[ch.RPR(("block", "lever"), ("A", "C")),
                        ch.RRR(("rod", "ram"), ("D", "E"), (0.2, 0.3))])
    assert "groups[1]: a group RRR has two links and 3 joint name(s) (A, B, C)" in str(e.value)
    assert "у группы RRR два звена" in "\n".join(e.value.lines("ru"))


def test_unknown_link_and_pivot():
    with pytest.raises(SpecError, match="not a link of the mechanism"):
        _shaper(links={"rocker": ch.Link(1.0)})
    with pytest.raises(SpecError, match="pivot X is not a joint of the frame"):
        ch.Mechanism({"O": 0j}, ch.Driver(0.1, pivot="X"), [])


def test_cannot_be_assembled_names_the_crank_angles():
    # the rod DE shorter than the distance of the lever's tip from the ram's guide
    mech = _shaper(groups=[ch.RPR(("block", "lever"), ("A", "C")),
                           ch.RRP(("rod", "ram"), ("D", "E"), 0.03,
                                  ch.Guide("frame", 0.25j, 0.0), 1)])
    with pytest.raises(AssemblyError) as e:
        ch.solve(mech, np.radians([0.0, 90.0, 180.0, 270.0]))
    assert "II RRP(4,5) cannot be assembled" in str(e.value)
    assert e.value.crank_angles_deg            # the positions where it fails
    # at φ = 90° the lever is upright: D at 0.3 m above O, 0.05 m above the guide
    assert 90.0 in e.value.crank_angles_deg


def test_a_group_through_its_dead_position_is_a_branch_error():
    # a crank-rocker whose dyad straightens (a change point): |AC| = l2 + l3 at φ = 180°
    mech = ch.Mechanism({"O": 0j, "C": 0.3 + 0j}, ch.Driver(0.1),
                        [ch.RRR(("coupler", "rocker"), ("A", "B", "C"), (0.25, 0.15))])
    with pytest.raises(AssemblyError) as e:
        ch.check_cycle(mech, n=360)
    assert "passes a dead position" in str(e.value)
    assert 180.0 in [round(a, 6) for a in e.value.crank_angles_deg]
    ch.check_cycle(_shaper())                       # the shaper turns fully: no error


def test_shaper_moves_as_the_crank_slotted_lever():
    """Closed-form checks of the RPR group by hand: at φ = 90° (A above O, on the line
    C–O) the lever is upright, the block slides at the crank pin's full speed ω·OA along
    the slot and the lever does not turn; at φ = 0° the lever turns at
    ω·OA·cos(γ)/|CA| with |CA| = √(0.1² + 0.3²)."""
    mech = _shaper()
    res = ch.solve(mech, np.radians([90.0, 0.0]), 10.0, 0.0)
    s = res.solutions[0]
    assert s.v_rel[0] == pytest.approx(0.0, abs=1e-12)        # A moves ⟂ to the slot
    assert res.omega("lever")[0] == pytest.approx(10.0 * 0.1 / 0.4, rel=1e-12)
    ca = math.hypot(0.1, 0.3)
    # at φ = 0 A = (0.1, 0), vA = (0, 1) m/s; the slot direction (0.1, 0.3)/|CA|
    assert res.omega("lever")[1] == pytest.approx(1.0 * 0.1 / ca / ca, rel=1e-12)
    assert s.v_rel[1] == pytest.approx(1.0 * 0.3 / ca, rel=1e-12)


def test_published_crank_slotted_lever_extreme_inclination():
    """A crank-slotted-lever quick-return mechanism with the fixed centres 0.240 m apart
    and a driving crank of 0.120 m: the slotted bar's inclination with the vertical in an
    extreme position is 30° (the answer printed to whole degrees in the question "Find
    the inclination of the slotted bar with the vertical in degrees in the extreme
    position ...", Machine Kinematics, "Single Slider Crank Chain and its Inversions",
    https://qna.carrieradda.com/26665/ , choice (a) 30).  Here the lever's angle over a
    full turn (0.01° steps, refined where its ω changes sign) swings ±30° about the
    vertical line of centres, and the time ratio of the strokes follows, (180° + 2·30°) /
    (180° − 2·30°) = 2 (derived, not printed there)."""
    mech = ch.Mechanism({"O": 0j, "C": -0.240j}, ch.Driver(0.120),
                        [ch.RPR(("block", "lever"), ("A", "C"))])
    phi = np.radians(np.arange(0.0, 360.0, 0.01))
    res = ch.solve(mech, phi, 1.0, 0.0)
    theta = np.degrees(res.links["lever"].theta)
    incl = theta - 90.0                       # from the vertical (the slot points up at C)
    assert round(float(incl.max())) == 30 and round(float(-incl.min())) == 30
    # the extremes exactly: where the crank is perpendicular to the slot (ω_lever = 0)
    w = res.omega("lever")
    turns = np.flatnonzero(np.sign(w[:-1]) != np.sign(w[1:]))
    assert len(turns) == 2
    ext = []
    for k in turns:                            # linear refinement of the sign change
        p = phi[k] + (phi[k + 1] - phi[k]) * w[k] / (w[k] - w[k + 1])
        ext.append((p, float(np.degrees(ch.solve(mech, [p]).links["lever"].theta[0])) - 90.0))
    assert sorted(round(a, 6) for _, a in ext) == [-30.0, 30.0]
    work = math.degrees((ext[1][0] - ext[0][0]) % (2 * math.pi))
    ratio = max(work, 360 - work) / min(work, 360 - work)
    assert ratio == pytest.approx(2.0, rel=1e-6)


def test_rrp_on_a_guide_of_the_frame_equals_todays_rrp():
    """linkage.groups.rrp_guided (a guide on any link, with the Coriolis term) on the
    frame is today's rrp to round-off, on both branches and an offset turned guide."""
    from linkage import groups as g
    phi = np.radians(np.arange(0.0, 360.0, 7.5))
    cr = g.crank(phi, -23.0, 40.0)
    A = cr.point(0.07)
    for asm in (1, -1):
        old = g.rrp(A, 0.31, 0.02 - 0.01j, 0.6, 0.015, asm)
        new = g.rrp_guided(A, 0.31, g.FRAME, 0.02 - 0.01j, 0.6, 0.015, asm)
        for a, b in ((old.s, new.s), (old.v, new.v), (old.a, new.a),
                     (old.link3.omega, new.link3.omega), (old.link3.eps, new.link3.eps),
                     (old.B.a.x, new.B.a.x), (old.B.a.y, new.B.a.y)):
            np.testing.assert_allclose(b, a, rtol=1e-12, atol=1e-12 * np.max(np.abs(a)))
