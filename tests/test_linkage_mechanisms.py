"""linkage.mechanisms: change-point mechanisms (s + l = p + q; a crank-slider whose rod
equals crank + |offset|) are accepted, analysed at the requested angles, their singular
positions reported in ``.warnings`` and as :class:`linkage.SingularPositionWarning`, and
left out of ``full_turn``; a linkage that cannot be assembled or whose crank cannot turn
fully gives :class:`linkage.AssemblyError` (a ``ValueError``) with the crank angles and the
reason."""
import copy
import math
import warnings

import numpy as np
import pytest

import linkage
from newton_euler import loaded_rocker, loaded_slider, reference, rel_err, wrap_deg
from test_linkage_spec import rocker, slider


CHANGE_POINTS = {
    # s + l = p + q with |AC| = AB − CB at φ = γ: 1 + 3 = 2 + 2
    "rocker-near": (rocker(crank=1.0, coupler=3.0, rocker=2.0, ground=2.0,
                           ground_angle_deg=30.0), [30.0]),
    # s + l = p + q with |AC| = AB + CB at φ = γ + 180°: 1 + 3 = 2 + 2 (ground longest)
    "rocker-far": (rocker(crank=1.0, coupler=2.0, rocker=2.0, ground=3.0,
                          ground_angle_deg=-50.0), [130.0]),
    # rod = crank + offset: the rod stands perpendicular to the guide at γ − 90°
    "slider-plus": (slider(crank=0.1, coupler=0.15, offset=0.05, ground_angle_deg=20.0),
                    [290.0]),
    # rod = crank + |offset| with the offset on the other side: at γ + 90°
    "slider-minus": (slider(crank=0.1, coupler=0.15, offset=-0.05, ground_angle_deg=20.0),
                     [110.0]),
    # central, rod = crank: both
    "slider-central": (slider(crank=0.1, coupler=0.1, offset=0.0), [90.0, 270.0]),
}


@pytest.mark.parametrize("name", list(CHANGE_POINTS))
def test_change_point_is_accepted_analysed_and_warned(name):
    data, singular = CHANGE_POINTS[name]
    angles = [5.0, 47.0, 200.0, 333.0]
    with pytest.warns(linkage.SingularPositionWarning) as rec:
        res = linkage.analyze(data, crank_angles_deg=angles)
    # only the singular-position warning: no numpy RuntimeWarning leaks
    assert all(issubclass(w.category, linkage.SingularPositionWarning) for w in rec)
    assert len(res.warnings) >= 1
    assert "change-point" in res.warnings[0]
    got = sorted(float(x) % 360.0 for x in res.summary.singular_phi_deg)
    np.testing.assert_allclose(got, sorted(singular), atol=1e-9)
    for a in singular:  # the warning names each singular crank angle
        assert f"{a:.6g}°" in res.warnings[0]
    # analysed at the requested angles, one row each in the order given, all finite
    k = res.kinematics
    np.testing.assert_allclose(k["phi_deg"], angles)
    assert np.isfinite(k.drop(columns="position").to_numpy(float)).all()
    assert np.isfinite(res.forces.drop(columns="position").to_numpy(float)).all()
    # and right: against the independent global solve
    ref = reference(data, angles)
    for c in ("omega3_rad_s", "eps3_rad_s2", "M_drive_Nm", "R23_x_N", "R14_y_N"):
        got = k[c] if c in k else res.forces[c]
        assert rel_err(got, ref[c], max(np.max(np.abs(ref[c])), 1.0)) <= 1e-9, c
    if data["mechanism"]["kind"] == "crank-slider":
        assert res.summary.grashof == "change-point"
    else:
        assert "CHANGE" in str(res.summary.grashof).upper()


@pytest.mark.parametrize("name", list(CHANGE_POINTS))
def test_change_point_at_the_singular_angle(name):
    """Asked exactly at the singular position: a row that is not finite, and a second
    warning saying so; the other rows stay good."""
    data, singular = CHANGE_POINTS[name]
    angles = [singular[0], 40.0]
    with pytest.warns(linkage.SingularPositionWarning):
        res = linkage.analyze(data, crank_angles_deg=angles)
    assert any("requested crank angles include a singular position" in w
               for w in res.warnings)
    rate = "omega4_rad_s" if "omega4_rad_s" in res.kinematics else "v4_m_s"
    assert not np.isfinite(res.kinematics[rate].iloc[0])
    assert np.isfinite(res.kinematics[rate].iloc[1])


@pytest.mark.parametrize("name", list(CHANGE_POINTS))
def test_full_turn_leaves_singular_positions_out(name):
    data, singular = CHANGE_POINTS[name]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # full_turn handles its own warnings
        ft = linkage.full_turn(data, step_deg=1.0)
    k = ft.kinematics
    phi = k["phi_deg"].to_numpy(float)
    np.testing.assert_allclose(phi, np.arange(0.0, 361.0, 1.0))
    near = np.zeros(len(phi), bool)
    for a in singular:
        near |= np.abs(wrap_deg(phi - a)) <= 1.0 + 1e-9
    vals = k.drop(columns=["position", "phi_deg"]).to_numpy(float)
    assert np.isnan(vals[near]).all()
    assert np.isfinite(vals[~near]).all()
    assert (~near).sum() >= 361 - 3 * len(singular) - 1
    fv = ft.forces.drop(columns=["position", "phi_deg"]).to_numpy(float)
    assert np.isnan(fv[near]).all() and np.isfinite(fv[~near]).all()


def test_change_point_slider_has_a_plan_of_positions():
    """rod = crank + |offset|: the folded extreme is the dead position itself; the plan of
    positions starts there (working stroke "away") and the stroke is the full travel."""
    data, _ = CHANGE_POINTS["slider-plus"]
    data = copy.deepcopy(data)
    data["analysis"] = {"positions": 12, "working_stroke": "away"}
    with pytest.warns(linkage.SingularPositionWarning):
        res = linkage.analyze(data)
    assert len(res.kinematics) == 12
    assert res.summary.phi_working_start_deg % 360 == pytest.approx(290.0, abs=1e-9)
    l1, l2, e = 0.1, 0.15, 0.05
    stroke = math.sqrt((l1 + l2) ** 2 - e * e) - math.sqrt(max((l2 - l1) ** 2 - e * e, 0))
    assert res.summary.stroke_m == pytest.approx(stroke, rel=1e-9)
    assert res.kinematics["v4_m_s"].iloc[1] > 0


def test_regular_mechanism_has_no_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = linkage.analyze(loaded_rocker())
        res2 = linkage.analyze(loaded_slider())
    assert res.warnings == [] and res2.warnings == []
    assert res.summary.singular_phi_deg == [] == res2.summary.singular_phi_deg


def _assembly_error(data):
    with pytest.raises(linkage.AssemblyError) as ei:
        linkage.analyze(data)
    e = ei.value
    assert isinstance(e, ValueError)
    assert "cannot" in e.reason and e.reason in str(e)
    assert e.crank_angles_deg
    return e


def test_rocker_whose_crank_cannot_turn_fully():
    """Non-Grashof (s + l > p + q): |AC| exceeds AB + CB around φ = γ + 180°; the reported
    angles are where |AC| = AB + CB exactly (law of cosines)."""
    l1, l2, l3, l0, gam = 2.0, 3.0, 2.5, 4.0, 25.0
    e = _assembly_error(rocker(crank=l1, coupler=l2, rocker=l3, ground=l0,
                               ground_angle_deg=gam))
    assert "|AB| + |CB|" in e.reason
    zC = l0 * complex(math.cos(math.radians(gam)), math.sin(math.radians(gam)))
    for a in e.crank_angles_deg:
        zA = l1 * complex(math.cos(math.radians(a)), math.sin(math.radians(a)))
        assert abs(zC - zA) == pytest.approx(l2 + l3, rel=1e-12)
    h = math.degrees(math.acos((l0 ** 2 + l1 ** 2 - (l2 + l3) ** 2) / (2 * l0 * l1)))
    assert sorted(e.crank_angles_deg) == pytest.approx(sorted([(gam + h) % 360,
                                                               (gam - h) % 360]))
    # the message names the interval the crank cannot pass, in degrees
    assert f"{(gam + h) % 360:.4g}°" in e.reason and f"{(gam - h) % 360:.4g}°" in e.reason


def test_rocker_too_short_near_the_line_of_centres():
    """|AC| < |AB − CB| around φ = γ (the coupler and rocker cannot reach down)."""
    l1, l2, l3, l0 = 1.0, 4.0, 1.5, 2.0
    e = _assembly_error(rocker(crank=l1, coupler=l2, rocker=l3, ground=l0))
    assert "|AB − CB|" in e.reason
    for a in e.crank_angles_deg:
        zA = l1 * complex(math.cos(math.radians(a)), math.sin(math.radians(a)))
        assert abs(l0 - zA) == pytest.approx(abs(l2 - l3), rel=1e-12)


def test_rocker_that_cannot_be_assembled_at_all():
    e = _assembly_error(rocker(crank=1.0, coupler=1.0, rocker=1.0, ground=5.0))
    assert "every crank angle" in e.reason


@pytest.mark.parametrize("offset", [0.0, 0.04, -0.04])
def test_slider_whose_rod_is_too_short(offset):
    """rod < crank + |offset|: the reported angles are where the pin A is exactly one rod
    length from the guide line."""
    l1, L, gam = 0.1, 0.08, 40.0
    e = _assembly_error(slider(crank=l1, coupler=L, offset=offset, ground_angle_deg=gam))
    assert "rod" in e.reason
    for a in e.crank_angles_deg:
        yA = l1 * math.sin(math.radians(a - gam))
        assert abs(offset - yA) == pytest.approx(L, rel=1e-12)


def test_slider_that_cannot_be_assembled_at_all():
    e = _assembly_error(slider(crank=0.1, coupler=0.05, offset=0.3))
    assert "every crank angle" in e.reason
