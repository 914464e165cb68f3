"""Engine spec validation (every problem at once, with its key path or CSV row), mass
models, pressure sources and the computed indicator diagram."""
import copy
import dataclasses
import math
import subprocess
import sys

import numpy as np
import pytest

import engine
from crankbase.errors import SpecError

BASE = {
    "engine": dict(name="t", bore_mm=110.0, stroke_mm=125.0, rod_ratio=0.272,
                   speed_rpm=2600.0, crankcase_MPa=0.1),
    "masses": dict(reciprocating_kg=3.08, rod_rotating_kg=0.9),
    "pressure": dict(angle_deg=[0, 360, 370], p_MPa=[0.1, 5.0, 6.0]),
    "table": dict(step_deg=30, force_scale_N_per_mm=500.0),
}

OTTO = dict(kind="otto", compression_ratio=8.5, pa_MPa=0.085, pr_MPa=0.118, n1=1.377,
            n2=1.251, pz_MPa=6.1)
DIESEL = dict(kind="diesel", compression_ratio=16.0, pa_MPa=0.088, pr_MPa=0.115, n1=1.37,
              n2=1.25, pz_MPa=7.8, rho=1.35)


def spec_with(path=None, value=None, delete=None, pressure=None):
    d = copy.deepcopy(BASE)
    if pressure is not None:
        d["pressure"] = pressure
    if path:
        *head, last = path.split(".")
        node = d
        for k in head:
            node = node.setdefault(k, {})
        node[last] = value
    if delete:
        *head, last = delete.split(".")
        node = d
        for k in head:
            node = node[k]
        del node[last]
    return d


def problems(d, **kw):
    with pytest.raises(SpecError) as info:
        engine.load_spec(d, **kw)
    assert isinstance(info.value, ValueError)
    return info.value.lines()


def one_problem(d, key, *words, **kw):
    lines = problems(d, **kw)
    assert len(lines) == 1, lines
    assert lines[0].startswith(key), lines
    for w in words:
        assert w in lines[0], lines
    return lines[0]


# ----------------------------------------------------------------------- good specs

def test_base_spec_derived_quantities():
    s = engine.load_spec(BASE)
    assert s.R == 0.0625 and s.rod_ratio == 0.272 and s.rod_length is None
    assert s.L == pytest.approx(0.0625 / 0.272)
    assert s.area == pytest.approx(math.pi * 0.11 ** 2 / 4)
    assert s.Vh == pytest.approx(s.area * 0.125)
    assert s.omega == pytest.approx(2600 * math.pi / 30)
    assert s.Kr == pytest.approx(-0.9 * 0.0625 * s.omega ** 2)
    assert s.strokes == 4 and s.cycle_deg == 720 and s.acceleration == "two-term"
    assert s.p0 == pytest.approx(1e5)


def test_rod_length_instead_of_ratio():
    d = spec_with("engine.rod_length_mm", 230.0, delete="engine.rod_ratio")
    s = engine.load_spec(d)
    assert s.L == pytest.approx(0.23) and s.lam == pytest.approx(62.5 / 230)


def test_masses_from_parts_and_per_area():
    d = copy.deepcopy(BASE)
    d["masses"] = dict(piston_group_kg=2.35, rod_kg=3.2, crank_rotating_kg=4.0)
    s = engine.load_spec(d)
    assert s.mj == pytest.approx(2.35 + 0.275 * 3.2)
    assert s.m_rod_rot == pytest.approx(0.725 * 3.2)
    assert s.m_crank_rot == 4.0
    d["masses"] = dict(piston_group_kg_m2=250.0, rod_kg_m2=300.0, rod_small_end_fraction=0.3)
    s = engine.load_spec(d)
    A = math.pi * 0.11 ** 2 / 4
    assert s.mj == pytest.approx((250 + 0.3 * 300) * A)
    assert s.m_rod_rot == pytest.approx(0.7 * 300 * A)


def test_pressure_units_inline_and_periodic_interpolation():
    d = spec_with(pressure=dict(angle_deg=[0, 360], p_bar=[1.0, 50.0]))
    s = engine.load_spec(d)
    np.testing.assert_allclose(engine.gas_pressure(s, [0, 180, 360, 540, 720, 900]),
                               [1e5, 25.5e5, 50e5, 25.5e5, 1e5, 25.5e5])


def test_repeated_end_row_is_accepted():
    d = spec_with(pressure=dict(angle_deg=[0, 360, 720], p_MPa=[0.1, 5.0, 0.1]))
    s = engine.load_spec(d)
    assert list(s.pressure.angle_deg) == [0, 360]


def test_csv_pressure_file_relative_to_spec(tmp_path):
    (tmp_path / "ind.csv").write_text("# comment\nangle_deg,V_l,p_kPa\n0,1,100\n360,0.1,5000\n"
                                      "720,1,100\n")
    d = spec_with(pressure={"file": "ind.csv"})
    s = engine.load_spec(d, base_dir=tmp_path)
    np.testing.assert_allclose(s.pressure.p, [1e5, 5e6])
    toml = tmp_path / "e.toml"
    toml.write_text('[engine]\nbore_mm = 110\nstroke_mm = 125\nrod_ratio = 0.27\n'
                    'speed_rpm = 2000\n[masses]\nreciprocating_kg = 1\nrod_rotating_kg = 1\n'
                    '[pressure]\nfile = "ind.csv"\n[table]\nforce_scale_N_per_mm = 100\n')
    s = engine.load_spec(toml)
    assert s.pressure_file == (tmp_path / "ind.csv").resolve()
    assert s.name == "engine"


def test_table_settings_are_separate_from_the_physics():
    study = engine.load(BASE)
    assert study.settings == engine.TableSettings(step_deg=30.0, force_scale=500.0)
    assert not hasattr(study.spec, "step_deg") and not hasattr(study.spec, "force_scale")
    fine = engine.TableSettings(step_deg=0.1)
    assert len(engine.force_table(study.spec, settings=fine)) == 7201
    for bad in (0, -1, float("nan"), "1"):
        with pytest.raises(SpecError) as info:
            engine.TableSettings(step_deg=bad)
        assert info.value.lines()[0].startswith("step_deg")
    with pytest.raises(SpecError):
        engine.TableSettings(extra_angles_deg=(float("inf"),))


def test_table_angles_include_end_and_extras():
    d = spec_with("table.step_deg", 50.0)
    d["table"]["extra_angles_deg"] = [372, 5.5, 372]
    study = engine.load(d)
    a = engine.table_angles(study.spec, study.settings)
    assert a[0] == 0 and a[-1] == 720 and 700 in a and 372 in a and 5.5 in a
    assert np.all(np.diff(a) > 0)


# ----------------------------------------------------------------------- bad input

@pytest.mark.parametrize("path,value,key", [
    ("engine.rod_ratio", 0.0, "engine.rod_ratio"),
    ("engine.rod_ratio", -0.2, "engine.rod_ratio"),
    ("engine.rod_ratio", 1.0, "engine.rod_ratio"),
    ("engine.rod_ratio", 1.5, "engine.rod_ratio"),
    ("engine.bore_mm", 0.0, "engine.bore_mm"),
    ("engine.bore_mm", -110.0, "engine.bore_mm"),
    ("engine.stroke_mm", 0.0, "engine.stroke_mm"),
    ("engine.speed_rpm", 0.0, "engine.speed_rpm"),
    ("engine.speed_rpm", -100.0, "engine.speed_rpm"),
    ("engine.strokes", 3, "engine.strokes"),
    ("engine.acceleration", "three-term", "engine.acceleration"),
    ("engine.bore_mm", "110", "engine.bore_mm"),
    ("engine.bore_mm", float("nan"), "engine.bore_mm"),
    ("table.force_scale_N_per_mm", 0.0, "table.force_scale_N_per_mm"),
    ("table.step_deg", 0.0, "table.step_deg"),
    ("table.step_deg", 800.0, "table.step_deg"),
    ("masses.reciprocating_kg", -1.0, "masses.reciprocating_kg"),
])
def test_bad_number_names_its_key(path, value, key):
    one_problem(spec_with(path, value), key)


def test_rod_ratio_and_rod_length_together():
    one_problem(spec_with("engine.rod_length_mm", 230.0), "engine.rod_ratio", "not both")


def test_neither_rod_ratio_nor_length():
    one_problem(spec_with(delete="engine.rod_ratio"), "engine.rod_ratio", "missing")


def test_rod_shorter_than_crank():
    d = spec_with("engine.rod_length_mm", 60.0, delete="engine.rod_ratio")
    one_problem(d, "engine.rod_length_mm", "crank radius")


def test_no_masses():
    one_problem(spec_with(delete="masses"), "masses", "missing")
    one_problem(spec_with("masses", {}), "masses", "no masses")


def test_masses_given_two_ways():
    d = spec_with("masses.rod_kg", 3.0)
    d["masses"]["piston_group_kg"] = 2.0
    one_problem(d, "masses", "one way")


def test_masses_half_given():
    one_problem(spec_with(delete="masses.rod_rotating_kg"), "masses.rod_rotating_kg")


def test_pressure_source_missing_or_twice(tmp_path):
    one_problem(spec_with(pressure={}), "pressure", "no pressure source")
    one_problem(spec_with(delete="pressure"), "pressure", "missing")
    (tmp_path / "p.csv").write_text("angle_deg,p_MPa\n0,0.1\n360,5\n")
    d = spec_with("pressure.file", "p.csv")
    one_problem(d, "pressure", "exactly one", base_dir=tmp_path)
    d = spec_with(pressure={"file": "p.csv", "cycle": dict(OTTO)})
    one_problem(d, "pressure", "exactly one", base_dir=tmp_path)


def test_csv_without_a_known_pressure_column(tmp_path):
    (tmp_path / "p.csv").write_text("angle_deg,pressure\n0,0.1\n360,5\n")
    line = one_problem(spec_with(pressure={"file": "p.csv"}), "pressure.file",
                       "p.csv line 1", "no pressure column", base_dir=tmp_path)
    assert "p_MPa" in line


def test_csv_with_two_pressure_columns(tmp_path):
    (tmp_path / "p.csv").write_text("angle_deg,p_MPa,p_bar\n0,0.1,1\n360,5,50\n")
    one_problem(spec_with(pressure={"file": "p.csv"}), "pressure.file",
                "more than one pressure column", base_dir=tmp_path)


def test_csv_file_does_not_exist(tmp_path):
    one_problem(spec_with(pressure={"file": "nothere.csv"}), "pressure.file",
                "does not exist", base_dir=tmp_path)


@pytest.mark.parametrize("body,line,word", [
    ("0,0.1\n400,5\n300,2\n", 4, "not sorted"),
    ("0,0.1\n300,5\n300,2\n", 4, "repeated"),
    ("0,0.1\n730,5\n", 3, "outside the cycle"),
    ("0,0.1\n-10,5\n", 3, "outside the cycle"),
    ("0,0.1\n360,-5\n", 3, "negative"),
    ("0,0.1\n360,nan\n", 3, "finite"),
    ("0,0.1\n360,abc\n", 3, "not two numbers"),
    ("0,0.1\n720,0.2\n", 3, "must repeat"),
])
def test_csv_bad_rows_name_the_row(tmp_path, body, line, word):
    (tmp_path / "p.csv").write_text("angle_deg,p_MPa\n" + body)
    one_problem(spec_with(pressure={"file": "p.csv"}), "pressure.file",
                f"line {line}", word, base_dir=tmp_path)


def test_csv_fewer_than_two_points(tmp_path):
    (tmp_path / "p.csv").write_text("angle_deg,p_MPa\n0,0.1\n")
    one_problem(spec_with(pressure={"file": "p.csv"}), "pressure.file", "at least two",
                base_dir=tmp_path)


@pytest.mark.parametrize("pressure,key,word", [
    (dict(angle_deg=[0], p_MPa=[0.1]), "pressure.p_MPa", "at least two"),
    (dict(angle_deg=[0, 360, 100], p_MPa=[0.1, 5, 1]), "pressure.p_MPa[2]", "not sorted"),
    (dict(angle_deg=[0, 360], p_MPa=[0.1, -5]), "pressure.p_MPa[1]", "negative"),
    (dict(angle_deg=[0, 900], p_MPa=[0.1, 5]), "pressure.p_MPa[1]", "outside"),
    (dict(angle_deg=[0, 360], p_MPa=[0.1]), "pressure.p_MPa", "differ in length"),
    (dict(angle_deg=[0, 360]), "pressure", "p_MPa"),
    (dict(angle_deg=[0, 360], p_MPa=[0.1, 5], p_bar=[1, 50]), "pressure", "one pressure"),
])
def test_inline_pressure_problems(pressure, key, word):
    one_problem(spec_with(pressure=pressure), key, word)


def test_unknown_keys_everywhere():
    d = copy.deepcopy(BASE)
    d["engine"]["bore"] = 1
    d["masses"]["mass"] = 1
    d["table"]["steps"] = 1
    d["extra"] = {}
    lines = problems(d)
    keys = sorted(l.split(":")[0] for l in lines)
    assert keys == ["engine.bore", "extra", "masses.mass", "table.steps"]
    assert all("unknown key" in l for l in lines)
    d = spec_with(pressure={"cycle": dict(OTTO, sparks=1)})
    one_problem(d, "pressure.cycle.sparks", "unknown key")


def test_every_problem_at_once():
    d = copy.deepcopy(BASE)
    d["engine"]["rod_ratio"] = 1.2
    d["engine"]["bore_mm"] = -1
    d["engine"]["speed_rpm"] = 0
    d["engine"]["colour"] = "red"
    del d["masses"]
    d["pressure"] = {}
    lines = problems(d)
    keys = {l.split(":")[0] for l in lines}
    assert {"engine.rod_ratio", "engine.bore_mm", "engine.speed_rpm", "engine.colour",
            "masses", "pressure"} <= keys


def test_missing_spec_file_and_bad_toml(tmp_path):
    one_problem(str(tmp_path / "none.toml"), str(tmp_path / "none.toml"), "does not exist")
    bad = tmp_path / "bad.toml"
    bad.write_text("[engine\n")
    one_problem(bad, str(bad), "not valid TOML")


@pytest.mark.parametrize("change,key", [
    (dict(kind="wankel"), "pressure.cycle.kind"),
    (dict(compression_ratio=1.0), "pressure.cycle.compression_ratio"),
    (dict(n1=0.9), "pressure.cycle.n1"),
    (dict(pz_MPa=1.0), "pressure.cycle.pz_MPa"),          # below pc
    (dict(lambda_z=3.5), "pressure.cycle.pz_MPa"),        # both pz and λz
    (dict(rho=1.3), "pressure.cycle.rho"),                # otto has no ρ
    (dict(peak_factor=1.5), "pressure.cycle.peak_factor"),
    (dict(advance_deg=0.0), "pressure.cycle.advance_deg"),
    (dict(rounding="yes"), "pressure.cycle.rounding"),
])
def test_cycle_problems(change, key):
    one_problem(spec_with(pressure={"cycle": dict(OTTO, **change)}), key)


def test_cycle_diesel_needs_rho_and_four_strokes():
    one_problem(spec_with(pressure={"cycle": {k: v for k, v in DIESEL.items()
                                              if k != "rho"}}), "pressure.cycle.rho")
    d = spec_with("engine.strokes", 2, pressure={"cycle": dict(DIESEL)})
    one_problem(d, "pressure.cycle", "four-stroke")


def test_compression_ratio_given_twice_differently():
    d = spec_with("engine.compression_ratio", 9.0, pressure={"cycle": dict(OTTO)})
    one_problem(d, "engine.compression_ratio", "give it once")


def test_importing_engine_is_light():
    code = ("import sys, engine; print('matplotlib' in sys.modules, 'openpyxl' in sys.modules,"
            " 'pandas' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == ["False", "False", "False"]


# ------------------------------------------------ a spec holds inputs only (issue 9)

PARTS = spec_with("masses", dict(piston_group_kg=2.35, rod_kg=3.2, crank_rotating_kg=4.0),
                  delete="engine.rod_ratio")
PARTS["engine"]["rod_length_mm"] = 230.0
AREA = spec_with("masses", dict(piston_group_kg_m2=250.0, rod_kg_m2=300.0,
                                rod_small_end_fraction=0.3),
                 pressure={"cycle": dict(OTTO)})
DIESEL_BASE = spec_with(pressure={"cycle": dict(DIESEL)})
TWO_STROKE = spec_with(pressure=dict(angle_deg=[0, 10, 180, 300], p_MPa=[5, 6, 0.1, 1]))
BASES = {"direct": BASE, "parts": PARTS, "area": AREA, "diesel": DIESEL_BASE,
         "two": TWO_STROKE}

#: EngineSpec field -> (base, dict key path, value in the spec file, value in the spec).
FIELD_EDITS = {
    "name": ("direct", "engine.name", "other", "other"),
    "strokes": ("two", "engine.strokes", 2, 2),
    "cylinders": ("direct", "engine.cylinders", 6, 6),
    "bore": ("area", "engine.bore_mm", 100.0, 0.1),
    "stroke": ("parts", "engine.stroke_mm", 110.0, 0.11),
    "speed_rpm": ("direct", "engine.speed_rpm", 3000.0, 3000.0),
    "rod_ratio": ("direct", "engine.rod_ratio", 0.3, 0.3),
    "rod_length": ("parts", "engine.rod_length_mm", 240.0, 0.24),
    "p0": ("direct", "engine.crankcase_MPa", 0.12, 0.12e6),
    "acceleration": ("area", "engine.acceleration", "exact", "exact"),
    "compression_ratio": ("direct", "engine.compression_ratio", 15.0, 15.0),
    "pin_offset": ("area", "engine.pin_offset_mm", 6.0, 0.006),
    "reciprocating_kg": ("direct", "masses.reciprocating_kg", 2.0, 2.0),
    "rod_rotating_kg": ("direct", "masses.rod_rotating_kg", 1.5, 1.5),
    "piston_group_kg": ("parts", "masses.piston_group_kg", 2.0, 2.0),
    "rod_kg": ("parts", "masses.rod_kg", 3.5, 3.5),
    "piston_group_kg_m2": ("area", "masses.piston_group_kg_m2", 200.0, 200.0),
    "rod_kg_m2": ("area", "masses.rod_kg_m2", 350.0, 350.0),
    "rod_small_end_fraction": ("parts", "masses.rod_small_end_fraction", 0.3, 0.3),
    "crank_rotating_kg": ("parts", "masses.crank_rotating_kg", 5.0, 5.0),
    "pressure": ("direct", "pressure", dict(angle_deg=[0, 360, 380], p_MPa=[0.1, 4.0, 5.0]),
                 engine.PressureTable((0.0, 360.0, 380.0), (1e5, 4e6, 5e6))),
}
#: Fields that are not physics of the table (it must not change with them).
NOT_IN_TABLE = {"name", "cylinders", "compression_ratio", "crank_rotating_kg"}

#: CycleSpec field -> (base, key in [pressure.cycle], value in the file, value in the spec).
CYCLE_EDITS = {
    "kind": ("area", "kind", "diesel", "diesel"),   # (a diesel needs ρ: see below)
    "compression_ratio": ("area", "compression_ratio", 9.5, 9.5),
    "pa": ("area", "pa_MPa", 0.09, 0.09e6),
    "pr": ("area", "pr_MPa", 0.12, 0.12e6),
    "n1": ("area", "n1", 1.36, 1.36),
    "n2": ("area", "n2", 1.26, 1.26),
    "pz_input": ("area", "pz_MPa", 6.5, 6.5e6),
    "lambda_z_input": ("area", "lambda_z", 3.4, 3.4),
    "rho": ("diesel", "rho", 1.4, 1.4),
    "rounding": ("area", "rounding", False, False),
    "advance_deg": ("area", "advance_deg", 25.0, 25.0),
    "pc_factor": ("area", "pc_factor", 1.25, 1.25),
    "peak_factor": ("area", "peak_factor", 0.8, 0.8),
    "peak_after_tdc_deg": ("area", "peak_after_tdc_deg", 10.0, 10.0),
    "exhaust_opening_deg": ("area", "exhaust_opening_deg", 45.0, 45.0),
    "intake_opening_deg": ("area", "intake_opening_deg", 15.0, 15.0),
    "exhaust_closing_deg": ("area", "exhaust_closing_deg", 25.0, 25.0),
}

ANGLES = np.arange(0.0, 720.0, 2.5)


def _tables_equal(a, b):
    import pandas as pd
    pd.testing.assert_frame_equal(engine.force_table(a, ANGLES),
                                  engine.force_table(b, ANGLES), check_exact=True)


def test_every_input_field_is_covered():
    names = {f.name for f in dataclasses.fields(engine.EngineSpec)}
    assert names - {"source_path"} == set(FIELD_EDITS)
    assert {f.name for f in dataclasses.fields(engine.CycleSpec)} == set(CYCLE_EDITS)


@pytest.mark.parametrize("field", list(FIELD_EDITS))
def test_replace_any_input_gives_the_table_of_the_edited_file(field):
    """dataclasses.replace(spec, field=v) == load_spec(file with the key edited): the
    same spec and the same table; nothing derived is stored, so nothing goes stale."""
    base, path, file_value, spec_value = FIELD_EDITS[field]
    d = copy.deepcopy(BASES[base])
    old = engine.load_spec(d)
    *head, last = path.split(".")
    node = d
    for k in head:
        node = node[k]
    node[last] = file_value
    edited = engine.load_spec(d)
    replaced = dataclasses.replace(old, **{field: spec_value})
    assert replaced == edited and replaced != old
    _tables_equal(replaced, edited)
    assert engine.indicated_mean_pressure(replaced) == engine.indicated_mean_pressure(edited)
    changed = not engine.force_table(old, ANGLES).equals(engine.force_table(replaced, ANGLES))
    assert changed == (field not in NOT_IN_TABLE)


@pytest.mark.parametrize("field", list(CYCLE_EDITS))
def test_replace_any_cycle_input_gives_the_table_of_the_edited_file(field):
    base, key, file_value, spec_value = CYCLE_EDITS[field]
    d = copy.deepcopy(BASES[base])
    old = engine.load_spec(d)
    cyc = d["pressure"]["cycle"]
    cyc[key] = file_value
    change = {field: spec_value}
    if field == "lambda_z_input":                 # λz replaces pz: one of the two
        del cyc["pz_MPa"]
        change["pz_input"] = None
    if field == "kind":                           # a diesel (mixed) cycle needs ρ
        cyc["rho"] = change["rho"] = 1.15
    edited = engine.load_spec(d)
    replaced = dataclasses.replace(old, pressure=dataclasses.replace(old.pressure, **change))
    assert replaced == edited and replaced != old
    _tables_equal(replaced, edited)
    assert not engine.force_table(old, ANGLES).equals(engine.force_table(replaced, ANGLES))


def test_replace_the_pressure_file(tmp_path):
    (tmp_path / "a.csv").write_text("angle_deg,p_MPa\n0,0.1\n360,5\n")
    (tmp_path / "b.csv").write_text("angle_deg,p_bar\n0,1\n370,60\n")
    d = spec_with(pressure={"file": "a.csv"})
    old = engine.load_spec(d, base_dir=tmp_path)
    d["pressure"]["file"] = "b.csv"
    edited = engine.load_spec(d, base_dir=tmp_path)
    new = engine.read_pressure_csv(tmp_path / "b.csv", old.cycle_deg)
    replaced = dataclasses.replace(old, pressure=new)
    assert replaced == edited and replaced.pressure_file == (tmp_path / "b.csv").resolve()
    _tables_equal(replaced, edited)


def test_issue_9_new_user_check():
    """The report of issue 9: Pj stayed −11460.7 N at both speeds.  Now it follows n²."""
    from crankbase.resources import example_path
    spec = engine.load_spec(example_path("petrol_vaz2106.toml"))
    pj = engine.force_table(spec, [0.0])["Pj_N"].iloc[0]
    assert pj == pytest.approx(-11460.7, abs=0.05)
    slow = dataclasses.replace(spec, speed_rpm=2700.0)
    assert engine.force_table(slow, [0.0])["Pj_N"].iloc[0] == pytest.approx(pj / 4, rel=1e-12)
    assert slow.omega == pytest.approx(2700 * math.pi / 30)


@pytest.mark.parametrize("change,key", [
    (dict(speed_rpm=-1.0), "speed_rpm"),
    (dict(bore=float("nan")), "bore"),
    (dict(rod_ratio=1.2), "rod_ratio"),
    (dict(rod_length=0.2), "rod_ratio"),            # both given
    (dict(acceleration="three-term"), "acceleration"),
    (dict(strokes=3), "strokes"),
    (dict(pin_offset=0.5), "pin_offset"),
    (dict(reciprocating_kg=None), "reciprocating_kg"),
    (dict(reciprocating_kg=None, rod_rotating_kg=None), "masses"),
    (dict(piston_group_kg=2.0), "masses"),           # two ways
    (dict(rod_rotating_kg=-1.0), "rod_rotating_kg"),
    (dict(pressure=None), "pressure"),
])
def test_replace_with_a_bad_value_is_refused_by_name(change, key):
    spec = engine.load_spec(BASE)
    with pytest.raises(SpecError) as info:
        dataclasses.replace(spec, **change)
    assert isinstance(info.value, engine.EngineSpecError)
    assert info.value.lines()[0].startswith(key)


def test_pin_offset_in_the_spec_file():
    s = engine.load_spec(spec_with("engine.pin_offset_mm", -4.0))
    assert s.pin_offset == -0.004 and s.k_offset == pytest.approx(-0.004 / 0.0625)
    one_problem(spec_with("engine.pin_offset_mm", 200.0), "engine.pin_offset_mm",
                "Lш − R")
