"""linkage.spec: bad input.  Bad specs give one :class:`linkage.SpecError` (a
``ValueError``) naming every problem (key path and what is valid); statics (ω = 0) is
accepted at explicit crank angles only.  Change points and assembly errors:
test_linkage_mechanisms.py."""
import math

import numpy as np
import pytest

import linkage


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


# ------------------------------------------------------------------ assembly


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


@pytest.mark.parametrize("bad, index, more", [
    ([10.0, 20.0, float("nan")], 2, False), ([float("-inf"), 1.0], 0, False),
    ([1.0, -1.0000001e6, 2e6], 1, True), ([1e6, -1e6, 1e300], 2, False)])
def test_crank_angle_argument_range(bad, index, more):
    """analyze's crank angles are checked by their minimum and maximum (no temporary
    array); a refused array still names its first bad item (and how many more)."""
    arr = np.array(bad)
    with pytest.raises(linkage.SpecError) as err:
        linkage.analyze(rocker(), crank_angles_deg=arr)
    (p,) = err.value.problems
    assert p.key == f"crank_angles_deg[{index}]"
    assert ("more" in str(p)) is more


def test_crank_angle_argument_read_not_copied_nor_changed():
    """±1e6° (the limit) are accepted; the caller's float array is read in place and left
    as it was; the rows' φ is np.radians of it, bit for bit."""
    from crankbase.validation import angles_argument

    deg = np.array([1e6, -1e6, 37.5, -0.0, 359.99])
    keep = deg.copy()
    assert angles_argument(deg, "a", copy=False) is deg
    assert angles_argument(deg, "a") is not deg
    res = linkage.analyze(rocker(), crank_angles_deg=deg, course_tables=False)
    assert np.array_equal(deg.view(np.uint64), keep.view(np.uint64))
    phi = deg * (math.pi / 180.0)                      # np.radians, bit for bit
    assert np.array_equal(phi.view(np.uint64), np.radians(deg).view(np.uint64))
    want = phi * (180.0 / math.pi)
    got = res.kinematics["phi_deg"].to_numpy()
    assert np.array_equal(got.view(np.uint64), want.view(np.uint64))
