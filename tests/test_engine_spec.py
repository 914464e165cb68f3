"""Engine spec validation (every problem at once, with its key path or CSV row), mass
models, pressure sources and the computed indicator diagram."""
import copy
import math
import sys
import subprocess

import numpy as np
import pytest

import engine
from engine.indicator import (cycle_pressure, interpolate_periodic, sharp_cycle_pressure,
                              theoretical_mean_pressure, volume_ratio)
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
    assert s.R == pytest.approx(0.0625)
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


def test_interpolate_periodic_wraps_last_to_first():
    a = np.array([10.0, 100.0, 700.0])
    p = np.array([1.0, 2.0, 3.0])
    # between 700 and 730 (= 10 of the next cycle): linear from 3 to 1
    np.testing.assert_allclose(interpolate_periodic([715.0, 0.0, 10.0, 55.0], a, p, 720),
                               [2.0, 5 / 3, 1.0, 1.5])


def test_repeated_end_row_is_accepted():
    d = spec_with(pressure=dict(angle_deg=[0, 360, 720], p_MPa=[0.1, 5.0, 0.1]))
    s = engine.load_spec(d)
    assert list(s.angle_deg) == [0, 360]


def test_csv_pressure_file_relative_to_spec(tmp_path):
    (tmp_path / "ind.csv").write_text("# comment\nangle_deg,V_l,p_kPa\n0,1,100\n360,0.1,5000\n"
                                      "720,1,100\n")
    d = spec_with(pressure={"file": "ind.csv"})
    s = engine.load_spec(d, base_dir=tmp_path)
    np.testing.assert_allclose(s.p, [1e5, 5e6])
    toml = tmp_path / "e.toml"
    toml.write_text('[engine]\nbore_mm = 110\nstroke_mm = 125\nrod_ratio = 0.27\n'
                    'speed_rpm = 2000\n[masses]\nreciprocating_kg = 1\nrod_rotating_kg = 1\n'
                    '[pressure]\nfile = "ind.csv"\n[table]\nforce_scale_N_per_mm = 100\n')
    s = engine.load_spec(toml)
    assert s.pressure_file == (tmp_path / "ind.csv").resolve()
    assert s.name == "engine"


def test_with_step():
    s = engine.load_spec(BASE).with_step(0.1)
    assert len(engine.force_table(s)) == 7201
    with pytest.raises(SpecError):
        s.with_step(0)
    with pytest.raises(SpecError):
        s.with_step(float("nan"))


def test_table_angles_include_end_and_extras():
    d = spec_with("table.step_deg", 50.0)
    d["table"]["extra_angles_deg"] = [372, 5.5, 372]
    s = engine.load_spec(d)
    a = engine.table_angles(s)
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
    ("0,0.1\n360,abc\n", 3, "not a number"),
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


# ----------------------------------------------------------------------- the diagram

def cycle_spec(cyc, **kw):
    return engine.load_spec(spec_with(pressure={"cycle": dict(cyc, **kw)}))


@pytest.mark.parametrize("cyc", [OTTO, DIESEL], ids=["otto", "diesel"])
def test_sharp_diagram_mean_pressure_equals_closed_form(cyc):
    """Kolchin & Demidov: p′i = pc/(ε−1)·[λ(ρ−1) + λρ/(n2−1)(1 − δ^(1−n2))
    − 1/(n1−1)(1 − ε^(1−n1))]; the numeric ∮p dV/Vh of the sharp diagram adds the pumping
    loop −(pr − pa)."""
    s = cycle_spec(cyc, rounding=False)
    numeric = engine.indicated_mean_pressure(s, step_deg=0.01)
    closed = theoretical_mean_pressure(s.cycle) - (s.cycle.pr - s.cycle.pa)
    assert numeric == pytest.approx(closed, rel=2e-6)


@pytest.mark.parametrize("cyc", [OTTO, DIESEL], ids=["otto", "diesel"])
def test_sharp_diagram_points(cyc):
    s = cycle_spec(cyc, rounding=False)
    c = s.cycle
    p = sharp_cycle_pressure([0, 90, 180, 359.999999, 360, 539.9999999, 540, 600], c, s.lam)
    eps = c.compression_ratio
    assert p[0] == c.pa and p[1] == c.pa and p[2] == pytest.approx(c.pa)
    assert p[3] == pytest.approx(c.pa * eps ** c.n1, rel=1e-9)           # pc
    assert p[4] == pytest.approx(c.pz)                                    # z (or z′)
    assert p[5] == pytest.approx(c.pz * (c.rho / eps) ** c.n2, rel=1e-9)  # pb
    assert p[6] == c.pr and p[7] == c.pr
    vr = volume_ratio([0, 180], s.lam, eps)
    np.testing.assert_allclose(vr, [1.0, eps])


def test_diesel_isobaric_part():
    s = cycle_spec(DIESEL, rounding=False)
    a = np.linspace(360, 420, 6001)
    vr = volume_ratio(a, s.lam, 16.0)
    p = sharp_cycle_pressure(a, s.cycle, s.lam)
    assert np.all(p[vr <= 1.35] == s.cycle.pz)
    assert np.all(p[vr > 1.35] < s.cycle.pz)


@pytest.mark.parametrize("cyc", [OTTO, DIESEL], ids=["otto", "diesel"])
def test_rounded_diagram_rules(cyc):
    s = cycle_spec(cyc)
    c = s.cycle
    a = np.arange(0, 720.0001, 0.01)
    p = cycle_pressure(a, c, s.lam)
    # continuous everywhere (no jumps left), peak where the rule puts it
    assert np.max(np.abs(np.diff(p))) < 2e-3 * c.pz
    i = int(np.argmax(p))
    assert a[i] == pytest.approx(360 + c.peak_after_tdc_deg, abs=0.02)
    assert p[i] == pytest.approx(c.peak_factor * c.pz, rel=1e-9)
    at = cycle_pressure([360.0, 540.0, 360 - c.advance_deg], c, s.lam)
    assert at[0] == pytest.approx(c.pc_factor * c.pc)
    pb = sharp_cycle_pressure([539.99999999], c, s.lam)[0]
    assert at[1] == pytest.approx((pb + c.pa) / 2, rel=1e-6)
    assert at[2] == pytest.approx(sharp_cycle_pressure([360 - c.advance_deg], c, s.lam)[0])
    # the sharp diagram is untouched outside the rounding zones
    out = (a > 30) & (a < 300)
    np.testing.assert_array_equal(p[out], sharp_cycle_pressure(a[out], c, s.lam))
    # rounding removes area: the diagram fullness φп = pi/pi_sharp in (0.88, 1)
    ratio = engine.indicated_mean_pressure(s) / engine.indicated_mean_pressure(
        cycle_spec(cyc, rounding=False))
    assert 0.88 < ratio < 1.0


def test_lambda_z_instead_of_pz():
    cyc = {k: v for k, v in OTTO.items() if k != "pz_MPa"}
    s = cycle_spec(cyc, lambda_z=3.6)
    assert s.cycle.pz == pytest.approx(3.6 * 0.085e6 * 8.5 ** 1.377)


def test_importing_engine_is_light():
    code = ("import sys, engine; print('matplotlib' in sys.modules, 'openpyxl' in sys.modules,"
            " 'pandas' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == ["False", "False", "False"]


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=30, deadline=None)
@given(kind=st.sampled_from(["otto", "diesel"]), eps=st.floats(6.0, 22.0),
       pa=st.floats(0.07, 0.12), pr=st.floats(0.1, 0.13), n1=st.floats(1.3, 1.4),
       n2=st.floats(1.18, 1.3), lam_z=st.floats(1.3, 4.5), rho=st.floats(1.1, 1.7),
       lam=st.floats(0.2, 0.35))
def test_random_cycles(kind, eps, pa, pr, n1, n2, lam_z, rho, lam):
    """Random thermal-calculation data: the sharp diagram's ∮p dV matches the closed
    form; the rounded one is continuous, positive, peaks where the rule says, and keeps
    nearly the same area."""
    cyc = dict(kind=kind, compression_ratio=eps, pa_MPa=pa, pr_MPa=pr, n1=n1, n2=n2,
               lambda_z=lam_z)
    if kind == "diesel":
        cyc["rho"] = rho
    d = spec_with("engine.rod_ratio", lam, pressure={"cycle": dict(cyc, rounding=False)})
    sharp = engine.load_spec(d)
    c = sharp.cycle
    closed = theoretical_mean_pressure(c) - (c.pr - c.pa)
    assert engine.indicated_mean_pressure(sharp, 0.01) == pytest.approx(closed, rel=1e-5)
    d["pressure"]["cycle"]["rounding"] = True
    try:
        rounded = engine.load_spec(d)
    except SpecError as exc:          # a peak below pc''·pc is refused, by key
        assert exc.lines()[0].startswith("pressure.cycle.peak_factor")
        return
    a = np.arange(0, 720.0001, 0.05)
    p = cycle_pressure(a, rounded.cycle, rounded.lam)
    assert np.all(p > 0) and np.all(np.isfinite(p))
    assert np.max(np.abs(np.diff(p))) < 0.01 * c.pz
    assert a[int(np.argmax(p))] == pytest.approx(360 + rounded.cycle.peak_after_tdc_deg,
                                                 abs=0.06)
    # rounding changes the area only a little (it usually removes some: φп < 1)
    ratio = engine.indicated_mean_pressure(rounded) / engine.indicated_mean_pressure(sharp)
    assert 0.8 < ratio < 1.02


def test_rounded_peak_must_lie_inside_the_sharp_diagram():
    cyc = {k: v for k, v in OTTO.items() if k != "pz_MPa"}
    line = one_problem(spec_with(pressure={"cycle": dict(cyc, compression_ratio=14.0,
                                                         lambda_z=2.0)}),
                       "pressure.cycle.peak_factor", "above the expansion line")
    assert "372°" in line
    # the same data unrounded are fine
    engine.load_spec(spec_with(pressure={"cycle": dict(cyc, compression_ratio=14.0,
                                                       lambda_z=2.0, rounding=False)}))


def test_rounding_needs_the_isobaric_part_inside_its_zone():
    one_problem(spec_with(pressure={"cycle": dict(DIESEL, compression_ratio=22.0, rho=3.5,
                                                  pz_MPa=9.0)}),
                "pressure.cycle.peak_factor", "isobaric")
