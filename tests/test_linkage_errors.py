"""Bad input and limiting cases (issue 2, section 5).

Change-point mechanisms (s + l = p + q; a crank-slider whose rod equals crank + |offset|)
are accepted, analysed at the requested angles, their singular positions reported in
``.warnings`` and as :class:`linkage.SingularPositionWarning`, and left out of
``full_turn``.  Bad specs give one :class:`linkage.SpecError` naming every problem (key
path and what is valid); a linkage that cannot be assembled or whose crank cannot turn
fully gives :class:`linkage.AssemblyError` with the crank angles and the reason.  Both are
``ValueError`` subclasses."""
import copy
import math
import warnings

import numpy as np
import pytest

import linkage
from newton_euler import loaded_rocker, loaded_slider, reference, rel_err, wrap_deg


def rocker(**mech):
    m = {"kind": "crank-rocker", "crank": 1.0, "coupler": 3.0, "rocker": 2.0,
         "ground": 2.5, "omega_rad_s": 2.0}
    m.update(mech)
    return {"mechanism": m, "links": {"coupler": {"mass_kg": 1.0, "inertia_kg_m2": 0.2,
                                                  "cg": [1.5, 0.1]},
                                      "rocker": {"mass_kg": 2.0, "cg": [1.0, 0.0]}},
            "load": [{"link": "rocker", "moment_Nm": 10.0}],
            "analysis": {"crank_angles_deg": [10.0, 100.0]}}


def slider(**mech):
    m = {"kind": "crank-slider", "crank": 0.1, "coupler": 0.3, "omega_rad_s": 50.0}
    m.update(mech)
    return {"mechanism": m, "links": {"slider": {"mass_kg": 1.0}},
            "analysis": {"crank_angles_deg": [10.0, 100.0]}}


# ------------------------------------------------------------------ change points

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


# ------------------------------------------------------------------ assembly


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


# ------------------------------------------------------------------ spec errors


def _spec_error(data, *expected):
    """The SpecError's lines; each expected (key path, fragment) is in one line."""
    with pytest.raises(linkage.SpecError) as ei:
        linkage.analyze(data)
    err = ei.value
    assert isinstance(err, ValueError)
    lines = err.lines()
    for key, frag in expected:
        hits = [ln for ln in lines if ln.startswith(key + ":") and frag in ln]
        assert hits, f"no line for {key!r} with {frag!r} in {lines}"
    return lines


@pytest.mark.parametrize("key", ["crank", "coupler", "rocker", "ground"])
@pytest.mark.parametrize("value", [0.0, -0.2])
def test_lengths_must_be_positive(key, value):
    _spec_error(rocker(**{key: value}), (f"mechanism.{key}", "must be > 0"))


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -float("inf")])
def test_non_finite_numbers(value):
    d = rocker(crank=value, omega_rad_s=value, epsilon_rad_s2=value)
    d["links"]["coupler"]["cg"] = [value, 0.0]
    d["load"].append({"link": "coupler", "at": [0.1, 0.0], "force_N": [1.0, value]})
    _spec_error(d, ("mechanism.crank", "finite"), ("mechanism.omega_rad_s", "finite"),
                ("mechanism.epsilon_rad_s2", "finite"), ("links.coupler.cg[0]", "finite"),
                ("load[1].force_N[1]", "finite"))
    with pytest.raises(linkage.SpecError, match="finite"):
        linkage.analyze(rocker(), crank_angles_deg=[10.0, value])


def test_non_finite_crank_angle_in_the_spec():
    d = rocker()
    d["analysis"]["crank_angles_deg"] = [0.0, float("nan")]
    _spec_error(d, ("analysis.crank_angles_deg[1]", "finite"))


def test_unknown_keys_and_links():
    d = rocker(colour="red")
    d["links"]["crank"] = {"mass_kg": 1.0, "massa": 2.0}
    d["links"]["slider"] = {"mass_kg": 1.0}
    d["load"].append({"link": "piston", "moment_Nm": 1.0})
    d["load"].append({"link": "rocker", "moment_Nm": 1.0, "torque": 3.0})
    d["analysis"]["step"] = 1
    d["extra"] = {}
    lines = _spec_error(
        d, ("mechanism.colour", "valid keys here"), ("links.crank.massa", "mass_kg"),
        ("links.slider", "crank, coupler, rocker"), ("load[1].link", "'rocker'"),
        ("load[2].torque", "valid keys"), ("analysis.step", "positions"),
        ("extra", "mechanism"))
    assert len(lines) == 7


def test_slider_keys_on_a_rocker_and_back():
    d = rocker(offset=0.1)
    _spec_error(d, ("mechanism.offset", "crank-slider only"))
    s = slider(rocker=0.2, ground=0.5)
    _spec_error(s, ("mechanism.rocker", "crank-rocker only"),
                ("mechanism.ground", "crank-rocker only"))


@pytest.mark.parametrize("key", ["kind", "crank", "coupler", "rocker", "ground",
                                 "omega_rad_s"])
def test_missing_required_keys(key):
    d = rocker()
    del d["mechanism"][key]
    if key == "kind":
        _spec_error(d, ("mechanism.kind", "'crank-rocker', 'crank-slider'"))
    else:
        _spec_error(d, (f"mechanism.{key}", "missing"))


def test_missing_mechanism_table_and_working_stroke():
    _spec_error({"analysis": {"positions": 4}}, ("mechanism", "missing"))
    d = rocker()
    d["analysis"] = {"positions": 12}
    _spec_error(d, ("analysis.working_stroke", "'ccw', 'cw'"))
    s = slider()
    s["load"] = [{"link": "slider", "resistance_N": 10.0, "span_m": 0.01}]
    _spec_error(s, ("analysis.working_stroke", "'away', 'toward'"))


def test_positions_together_with_crank_angles():
    d = rocker()
    d["analysis"] = {"positions": 12, "crank_angles_deg": [0.0], "working_stroke": "ccw"}
    _spec_error(d, ("analysis", "either positions or crank_angles_deg"))


@pytest.mark.parametrize("link", ["crank", "coupler", "rocker"])
def test_negative_mass_and_inertia(link):
    d = rocker()
    d["links"][link] = {"mass_kg": -1.0, "inertia_kg_m2": -0.5}
    _spec_error(d, (f"links.{link}.mass_kg", ">= 0"),
                (f"links.{link}.inertia_kg_m2", ">= 0"))


def test_bad_choices():
    _spec_error(rocker(assembly=2), ("mechanism.assembly", "1, -1"))
    _spec_error(rocker(kind="four-bar"), ("mechanism.kind", "'crank-rocker'"))


def test_statics_needs_explicit_angles_and_no_resistance_or_stroke():
    """ω = 0 is a static force analysis: no direction of rotation, so no plan of positions,
    no working stroke, and a resistance (which opposes motion) would silently be zero."""
    d = rocker(omega_rad_s=0.0)
    del d["analysis"]
    _spec_error(d, ("analysis.crank_angles_deg", "statics"))
    d = rocker(omega_rad_s=0.0)
    d["analysis"] = {"positions": 6}
    _spec_error(d, ("analysis.crank_angles_deg", "direction of rotation"))
    d = rocker(omega_rad_s=0.0)
    d["load"] = [{"link": "rocker", "moment_Nm": 10.0},
                 {"link": "rocker", "resistance_Nm": 100.0, "stroke": "both"}]
    d["analysis"]["working_stroke"] = "ccw"
    _spec_error(d, ("load[1].resistance_Nm", "moment_Nm or force_N"),
                ("analysis.working_stroke", "statics"))
    for make in (rocker, slider):
        with pytest.raises(linkage.SpecError):
            linkage.analyze(make(omega_rad_s=0.0, foo=1))   # the usual checks still run


@pytest.mark.parametrize("make", [rocker, slider])
def test_statics_is_accepted_at_explicit_angles(make):
    """ω = ε = 0: every velocity and acceleration is zero, the inertia loads vanish, and
    the reactions and the driving moment balance weights and applied loads alone (the
    same numbers as the quasi-static limit of a slowly turning crank)."""
    d = make(omega_rad_s=0.0, gravity_m_s2=9.81)
    if make is slider:              # a load along the guide, so the crank has work to do
        d["load"] = [{"link": "slider", "at": [0.0, 0.0], "force_N": [-200.0, 0.0]}]
    res = linkage.analyze(d)
    k, f = res.kinematics, res.forces
    rates = [c for c in k.columns if c.startswith(("omega", "eps", "v4", "a4"))
             or c.endswith(("_vx_m_s", "_vy_m_s", "_ax_m_s2", "_ay_m_s2"))]
    assert rates and np.all(k[rates].to_numpy(float) == 0.0)
    fu = [c for c in f.columns if c.startswith(("Fu", "Mu"))]
    assert np.all(f[fu].to_numpy(float) == 0.0)
    assert res.summary.rotation == "none (statics)" and res.extremes is None
    slow = dict(d, mechanism=dict(d["mechanism"], omega_rad_s=1e-4))
    ref = linkage.analyze(slow).forces
    scale = np.max(np.abs(f["M_drive_Nm"].to_numpy(float)))
    np.testing.assert_allclose(f["M_drive_Nm"].to_numpy(float),
                               ref["M_drive_Nm"].to_numpy(float), atol=1e-6 * scale)
    assert scale > 0


def test_resistance_on_the_wrong_link_or_unit():
    d = rocker()
    d["analysis"]["working_stroke"] = "ccw"
    d["load"] = [{"link": "coupler", "resistance_Nm": 10.0},
                 {"link": "rocker", "resistance_N": 10.0},
                 {"link": "rocker", "resistance_Nm": -5.0}]
    _spec_error(d, ("load[0].link", "output link 'rocker'"),
                ("load[1].resistance_N", "resistance_Nm"),
                ("load[2].resistance_Nm", ">= 0"))


def test_several_problems_are_all_reported_at_once():
    d = {"mechanism": {"kind": "crank-rocker", "crank": -1.0, "coupler": float("nan"),
                       "rocker": 2.0, "omega_rad_s": 1.0, "foo": 1},
         "links": {"crank": {"mass_kg": -1.0}, "slider": {}},
         "analysis": {"positions": 3, "crank_angles_deg": [1.0]}}
    lines = _spec_error(d, ("mechanism.foo", "unknown key"), ("mechanism.crank", "> 0"),
                        ("mechanism.coupler", "finite"), ("mechanism.ground", "missing"),
                        ("links.slider", "unknown link"), ("links.crank.mass_kg", ">= 0"),
                        ("analysis", "not both"))
    assert len(lines) == 7
    with pytest.raises(linkage.SpecError) as ei:
        linkage.load_spec(d)
    assert str(ei.value).count("\n") == 6  # one line per problem


def test_spec_file_errors(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text('[mechanism]\nkind = "crank-rocker"\ncrank = 0.0\n', encoding="utf-8")
    with pytest.raises(linkage.SpecError) as ei:
        linkage.load_spec(p)
    assert any(ln.startswith("mechanism.crank:") for ln in ei.value.lines())
    p.write_text("[mechanism\n", encoding="utf-8")
    with pytest.raises(linkage.SpecError, match="not valid TOML"):
        linkage.load_spec(p)
    with pytest.raises(linkage.SpecError, match="does not exist"):
        linkage.load_spec(tmp_path / "missing.toml")
