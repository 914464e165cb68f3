"""Bad input (issue 15): names, sizes, absurd magnitudes, argument checks of the public
functions and the pressure CSV reader.  Every case is one typed error naming the key (or
a finite result), never a crash, an inf/NaN table or a silently misread number."""
from __future__ import annotations

import copy
import warnings

import numpy as np
import pytest

import engine
import linkage
from crankbase.errors import CrankdynError, SpecError
from crankbase.output import safe_name
from crankbase.validation import MAX_NAME_BYTES, MAX_NAME_CHARS, MAX_ROWS, name_problem
from crankdyn.cli import main

ENGINE = {
    "engine": dict(name="t", bore_mm=110.0, stroke_mm=125.0, rod_ratio=0.272,
                   speed_rpm=2600.0, crankcase_MPa=0.1),
    "masses": dict(reciprocating_kg=3.08, rod_rotating_kg=0.9),
    "pressure": dict(angle_deg=[0, 360, 370], p_MPa=[0.1, 5.0, 6.0]),
    "table": dict(step_deg=30, force_scale_N_per_mm=500.0),
}
OTTO = dict(kind="otto", compression_ratio=8.5, pa_MPa=0.085, pr_MPa=0.118, n1=1.377,
            n2=1.251, pz_MPa=6.1)
LINKAGE = {
    "mechanism": dict(kind="crank-rocker", name="m", crank=0.175, coupler=0.55,
                      rocker=0.325, ground=0.54, omega_rad_s=17.0),
    "links": {"coupler": {"mass_kg": 10.0, "inertia_kg_m2": 0.3}},
    "analysis": {"positions": 12, "working_stroke": "ccw"},
}


def edit(base, path, value):
    d = copy.deepcopy(base)
    *head, last = path.split(".")
    node = d
    for k in head:
        node = node.setdefault(k, {})
    node[last] = value
    return d


def refused(fn, key, *words):
    with pytest.raises(SpecError) as info:
        fn()
    lines = info.value.lines()
    assert any(line.startswith(key) and all(w in line for w in words) for line in lines), lines
    return lines


def float_columns_finite(df):
    values = df.select_dtypes("float").to_numpy()
    return bool(np.isfinite(values).all())


# --------------------------------------------------------------------------- names
@pytest.mark.parametrize("name, words", [
    ("x" * 300, ["300 characters", f"at most {MAX_NAME_CHARS}"]),
    ("Ж" * 65, ["65 characters"]),
    ("a\tb", ["U+0009", "position 2"]),
    ("line\nbreak", ["U+000A"]),
    ("bell\x07", ["U+0007"]),
    ("   ", ["must not be empty"]),
    (17, ["must be a string"]),
])
def test_bad_names_refused_up_front(name, words):
    refused(lambda: engine.load_spec(edit(ENGINE, "engine.name", name)), "engine.name", *words)
    refused(lambda: linkage.load_spec(edit(LINKAGE, "mechanism.name", name)),
            "mechanism.name", *words)


def test_name_bytes_limit_and_safe_file_name():
    emoji = "\U0001F527" * 41                       # 41 characters, 164 bytes
    assert f"at most {MAX_NAME_BYTES}" in name_problem(emoji)
    ok = "Ж" * MAX_NAME_CHARS                        # 128 bytes: accepted
    assert name_problem(ok) is None
    assert engine.load_spec(edit(ENGINE, "engine.name", ok)).name == ok
    # the file name is cut at a character boundary below the byte budget
    stem = safe_name("Ж" * 200, max_bytes=31)
    assert stem == "Ж" * 15 and len(stem.encode()) <= 31


def test_long_cyrillic_name_runs_through_the_cli(tmp_path, unrendered_figures):
    """(The file names and the workbook; the figures are built, not drawn: the Russian
    reports of the session's shared CLI runs render Cyrillic titles.)"""
    name = "Двигатель ВАЗ-2106, расчёт по Колчину и Демидову (вариант 1)"
    spec = tmp_path / "s.toml"
    spec.write_text(_toml(edit(ENGINE, "engine.name", name)), encoding="utf-8")
    assert main(["engine", str(spec), "-o", str(tmp_path / "o")]) == 0
    from openpyxl import load_workbook
    xlsx = [p for p in (tmp_path / "o").iterdir() if p.suffix == ".xlsx"]
    assert len(xlsx) == 1 and len(unrendered_figures) == 26     # 13 plots, PNG and SVG
    wb = load_workbook(xlsx[0], read_only=True)
    assert any(name in str(c) for row in wb.worksheets[0].iter_rows(values_only=True)
               for c in row)


def _toml(d):
    import json
    out = []
    for table, body in d.items():
        out.append(f"[{table}]")
        for k, v in body.items():
            out.append(f"{k} = {json.dumps(v, ensure_ascii=False)}")
    return "\n".join(out) + "\n"


# --------------------------------------------------------------------------- sizes
@pytest.mark.parametrize("fn, key, rows", [
    (lambda: engine.load_spec(edit(ENGINE, "table.step_deg", 1e-9)), "table.step_deg",
     "720,000,000,001"),
    (lambda: engine.force_table(engine.load_spec(ENGINE),
                                settings=engine.TableSettings(step_deg=1e-6)),
     "step_deg", "720,000,001"),
    (lambda: linkage.load_spec(edit(LINKAGE, "analysis.positions", 100_000_000)),
     "analysis.positions", "100,000,000"),
    (lambda: linkage.load_spec(edit(LINKAGE, "analysis.positions", 1.2e10)),
     "analysis.positions", "12,000,000,000"),
    (lambda: linkage.full_turn(LINKAGE, 1e-6), "step_deg", "360,000,001"),
])
def test_row_limit_names_key_rows_and_limit(fn, key, rows):
    refused(fn, key, f"would make {rows} rows", f"at most {MAX_ROWS:,}")


def test_explicit_angle_list_limit_checked_before_the_items():
    d = edit(LINKAGE, "analysis", {"crank_angles_deg": [float("nan")] * (MAX_ROWS + 1)})
    d["mechanism"]["omega_rad_s"] = 0.0
    lines = refused(lambda: linkage.load_spec(d), "analysis.crank_angles_deg",
                    f"has {MAX_ROWS + 1:,} numbers", f"at most {MAX_ROWS:,}")
    assert len(lines) == 1


def test_bad_items_listed_with_a_cap():
    d = edit(ENGINE, "table.extra_angles_deg", ["x"] * 25)
    lines = refused(lambda: engine.load_spec(d), "table.extra_angles_deg[0]", "must be a number")
    assert len(lines) == 11 and "... and 15 more" in lines[-1]


def test_cli_steps_refused_before_work(tmp_path, capsys):
    assert main(["engine", "--example", "--step", "1e-6", "-o", str(tmp_path / "o")]) == 2
    assert capsys.readouterr().err.strip() == (     # the default: a Russian run
        "crankdyn engine: ошибка: --step: дало бы строк: 720,000,002; допускается не более "
        "100,000")
    assert main(["engine", "--example", "--step", "1e-6", "-o", str(tmp_path / "o"),
                 "--lang", "en"]) == 2
    assert main(["linkage", "--example", "--step", "1e-6", "-o", str(tmp_path / "o"),
                 "--lang", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["crankdyn engine: error: --step: would make 720,000,002 rows; at most "
                   "100,000 are allowed",
                   "crankdyn linkage: error: --step: would make 360,000,001 rows; at most "
                   "100,000 are allowed"]
    assert not (tmp_path / "o").exists()


def test_explicit_statics_angles_as_fast_as_a_sweep():
    """100,000 explicit angles go through the same vectorised kernel as a sweep: the
    explicit rows equal the rows of a sweep at the same angles (no per-angle path)."""
    d = copy.deepcopy(LINKAGE)
    angles = np.linspace(0.0, 359.0, MAX_ROWS)
    d["mechanism"]["omega_rad_s"] = 0.0
    d["analysis"] = {"crank_angles_deg": angles.tolist()}
    res = linkage.analyze(d, course_tables=False)
    ref = linkage.analyze(edit(d, "analysis", {"crank_angles_deg": [0.0]}),
                          crank_angles_deg=angles, course_tables=False)
    assert len(res.forces) == MAX_ROWS
    np.testing.assert_array_equal(res.forces["M_drive_Nm"].to_numpy(),
                                  ref.forces["M_drive_Nm"].to_numpy())


# --------------------------------------------------------------------------- magnitudes
@pytest.mark.parametrize("path, value, words", [
    ("engine.bore_mm", 1e308, ["at most 1e+12"]),
    ("engine.speed_rpm", 1e160, ["at most 1e+12"]),
    ("engine.rod_ratio", 1e-300, ["at least 1e-12"]),
    ("engine.stroke_mm", 10 ** 400, ["401 digits"]),
    ("masses.reciprocating_kg", 1e300, ["at most 1e+12"]),
    ("table.force_scale_N_per_mm", 1e13, ["at most 1e+12"]),
])
def test_absurd_engine_numbers_refused(path, value, words):
    refused(lambda: engine.load_spec(edit(ENGINE, path, value)), path, *words)


@pytest.mark.parametrize("key, value, words", [
    ("compression_ratio", 1e300, ["at most 1e+12"]),
    ("exhaust_opening_deg", 1e-15, [">= 1"]),
    ("pa_MPa", 1e-300, ["at least 1e-12"]),
])
def test_absurd_cycle_numbers_refused(key, value, words):
    d = edit(ENGINE, "pressure", {"cycle": dict(OTTO, **{key: value})})
    refused(lambda: engine.load_spec(d), f"pressure.cycle.{key}", *words)


@pytest.mark.parametrize("path, value", [
    ("mechanism.crank", 1e154), ("mechanism.ground", 1e-300), ("mechanism.omega_rad_s", 1e300),
    ("links.coupler.mass_kg", 1e200), ("mechanism.coupler", 10 ** 300),
])
def test_absurd_linkage_numbers_refused(path, value):
    refused(lambda: linkage.load_spec(edit(LINKAGE, path, value)), path)


def test_extremes_of_the_accepted_range_give_finite_tables():
    """At the edges of what is accepted the tables stay finite (no inf/NaN, no numpy
    warning): large engine, tiny-ratio rod, huge linkage at huge speed."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        d = edit(ENGINE, "engine", dict(ENGINE["engine"], bore_mm=1e12, stroke_mm=1e12,
                                        speed_rpm=1e12, rod_ratio=1e-12))
        d["masses"] = dict(reciprocating_kg=1e12, rod_rotating_kg=1e12)
        assert float_columns_finite(engine.force_table(engine.load_spec(d)))
        cyc = {k: v for k, v in OTTO.items() if k != "pz_MPa"}
        d = edit(ENGINE, "pressure", {"cycle": dict(cyc, compression_ratio=1e3, n1=1.99,
                                                    lambda_z=1e3, rounding=False)})
        assert float_columns_finite(engine.force_table(engine.load_spec(d)))
        m = dict(LINKAGE["mechanism"], crank=1.75e11, coupler=5.5e11, rocker=3.25e11,
                 ground=5.4e11, omega_rad_s=1e12, epsilon_rad_s2=1e12)
        d = dict(LINKAGE, mechanism=m, links={"coupler": {"mass_kg": 1e12,
                                                          "inertia_kg_m2": 1e12}})
        r = linkage.analyze(d)
        assert float_columns_finite(r.kinematics) and float_columns_finite(r.forces)


# --------------------------------------------------------------------------- arguments
@pytest.mark.parametrize("arg", [None, 42, 3.5, [], b"x", ""])
def test_load_spec_of_a_non_spec(arg):
    for load in (engine.load_spec, linkage.load_spec):
        refused(lambda: load(arg), "spec", "expected a TOML file path or a dict")


def test_deeply_nested_toml(tmp_path):
    p = tmp_path / "deep.toml"
    p.write_text("a = " + "[" * 3000 + "]" * 3000 + "\n")
    for load in (engine.load_spec, linkage.load_spec):
        refused(lambda: load(p), str(p), "nested too deeply")


@pytest.fixture(scope="module")
def otto_spec():
    return engine.load_spec(edit(ENGINE, "pressure", {"cycle": dict(OTTO)}))


@pytest.mark.parametrize("angles, words", [
    ([np.nan], ["alpha_deg[0]", "nan", "finite"]),
    ([0, np.inf], ["alpha_deg[1]", "inf"]),
    ([None], ["alpha_deg", "None"]),
    ([1 + 2j], ["alpha_deg", "complex"]),
    (np.zeros((2, 3)), ["alpha_deg", "shape (2, 3)"]),
    ([[1, 2], [3]], ["alpha_deg"]),
    ("30", ["alpha_deg", "'30'"]),
    ([], ["alpha_deg", "at least one"]),
    ([True], ["alpha_deg", "real numbers"]),
])
def test_force_table_refuses_bad_angles(otto_spec, angles, words):
    with pytest.raises(SpecError) as info:
        engine.force_table(otto_spec, alpha_deg=angles)
    assert all(w in str(info.value) for w in words), str(info.value)


def test_scalar_angle_on_a_computed_cycle_is_one_row(otto_spec):
    one = engine.force_table(otto_spec, alpha_deg=370.0)
    ref = engine.force_table(otto_spec, alpha_deg=[370.0])
    assert len(one) == 1 and one.equals(ref)
    assert engine.gas_pressure(otto_spec, 370.0).shape == (1,)


def test_force_table_of_a_non_spec():
    with pytest.raises(SpecError, match="must be an EngineSpec"):
        engine.force_table(ENGINE)


@pytest.mark.parametrize("angles", [[1j], [[0.0, 1.0]], [np.nan], ["a"]])
def test_analyze_refuses_bad_angles(angles):
    with pytest.raises(SpecError, match="crank_angles_deg"):
        linkage.analyze(LINKAGE, crank_angles_deg=angles)


# --------------------------------------------------------------------------- pressure CSV
def csv_spec(tmp_path, text, name="p.csv"):
    (tmp_path / name).write_text(text, encoding="utf-8")
    return lambda: engine.load_spec(edit(ENGINE, "pressure", {"file": name}),
                                    base_dir=tmp_path)


def test_decimal_commas_with_comma_separator_refused_not_misread(tmp_path):
    """Issue 15: '0,0,1015' (0° and 1.015 bar) was read as two columns and the third field
    dropped.  Now every such line is refused, saying what is ambiguous."""
    load = csv_spec(tmp_path, "angle_deg,p_bar\n0,0,1015\n360,66,3\n372,66,3\n")
    lines = refused(load, "pressure.file", "line 2", "3 fields but the header has 2",
                    "decimal commas", "'0,0,1015'")
    assert len(lines) == 3 and "line 4" in lines[2]


def test_rows_with_more_or_fewer_fields_refused(tmp_path):
    lines = refused(csv_spec(tmp_path, "angle_deg,p_MPa\n0,0.1,7\n360\n"), "pressure.file",
                    "line 2", "3 fields")
    assert any("line 3" in l and "1 fields but the header has 2" in l for l in lines)


@pytest.mark.parametrize("text", [
    "angle_deg;p_bar\n0;1,015\n360;66,3\n",
    "angle_deg;p_bar\n0;1.015\n360;66.3\n",
    "angle_deg\tp_bar\n0\t1,015\n360\t66,3\n",
    "# semicolons\nangle_deg;V_l;p_bar\n0;0,5;1,015\n360;0,05;66,3\n",
])
def test_semicolon_and_tab_files_read_right(tmp_path, text):
    s = csv_spec(tmp_path, text)()
    np.testing.assert_allclose(s.pressure.angle_deg, [0.0, 360.0])
    np.testing.assert_allclose(s.pressure.p, [1.015e5, 66.3e5], rtol=1e-15)


@pytest.mark.parametrize("text, words", [
    ("angle_deg;p_bar\n0;1.015\n360;66,3\n", ["decimal marks are mixed", "line 2", "line 3"]),
    ("angle_deg;p_kPa\n0;1.015,5\n360;6630\n", ["line 2", "both '.' and ','"]),
    ("angle_deg;p_bar,x\n0;1\n360;2\n", ["line 1", "more than one separator"]),
    ("angle_deg p_bar\n0 1\n", ["line 1", "one column"]),
])
def test_ambiguous_marks_and_separators_refused(tmp_path, text, words):
    refused(csv_spec(tmp_path, text), "pressure.file", *words)


def test_all_problems_of_a_csv_at_once_in_the_users_unit(tmp_path):
    text = "angle_deg,p_bar\n0,1\n90,x\n180,-2\n270,1e400\n360,40\n720,3\n"
    lines = refused(csv_spec(tmp_path, text), "pressure.file", "line 3", "'x'")
    joined = "\n".join(lines)
    assert "line 4: p_bar -2 is negative" in joined
    assert "line 5" in joined and "finite" in joined
    assert len(lines) == 3
    lines = refused(csv_spec(tmp_path, "angle_deg,p_bar\n0,1\n360,40\n720,3\n"),
                    "pressure.file", "line 4", "p_bar 3 and 1")
    refused(lambda: engine.load_spec(edit(ENGINE, "pressure", dict(angle_deg=[0, 360],
                                                                    p_bar=[1.0, -4.0]))),
            "pressure.p_bar[1]", "p_bar -4 is negative")


def test_crankdyn_errors_are_value_errors():
    assert issubclass(SpecError, CrankdynError) and issubclass(CrankdynError, ValueError)


def test_plan_of_many_positions_draws_at_most_24():
    """A plan of 5,000 explicit angles draws 24 of them (drawing each costs ~7 ms and the
    plan would be unreadable), saying so in its title."""
    from linkage.plots import MAX_PLAN_POSITIONS, plot_plan

    d = copy.deepcopy(LINKAGE)
    d["mechanism"]["omega_rad_s"] = 0.0
    d["analysis"] = {"crank_angles_deg": np.linspace(0.0, 359.0, 5000).tolist()}
    res = linkage.analyze(d, course_tables=False)
    ax = plot_plan(res, full=linkage.full_turn(d, 5.0))
    assert "24 of 5000 rows drawn (1 in 209)" in ax.get_title()
    links = [ln for ln in ax.lines if ln.get_marker() == "o" and ln.get_linestyle() == "-"]
    assert len(links) == MAX_PLAN_POSITIONS
    # numbered at A and at B; positions that crowd share a label ("75°/90°") or go
    # without one (labels never overlap, #23)
    parts = [p for t in ax.texts if t.get_text().endswith("°")
             for p in t.get_text().split("/")]
    assert 0 < len(parts) <= 2 * MAX_PLAN_POSITIONS


ISSUE_CASES = {          # the issue's reproductions through the CLI: (spec edit, key)
    "bore": (("engine.bore_mm", 1e308), "engine.bore_mm"),
    "eps": (("engine.compression_ratio", 1e300), "engine.compression_ratio"),
    "speed": (("engine.speed_rpm", 1e160), "engine.speed_rpm"),
    "rod": (("engine.rod_ratio", 1e-300), "engine.rod_ratio"),
    "digits": (("engine.stroke_mm", 10 ** 300), "engine.stroke_mm"),
    "step": (("table.step_deg", 1e-9), "table.step_deg"),
    "name": (("engine.name", "x" * 300), "engine.name"),
    "tab": (("engine.name", "a\tb"), "engine.name"),
}


@pytest.mark.parametrize("case", list(ISSUE_CASES))
def test_issue_reproductions_through_the_cli(case, tmp_path, capsys):
    (path, value), key = ISSUE_CASES[case]
    spec = tmp_path / "s.toml"
    text = _toml(edit(ENGINE, path, value))
    spec.write_text(text, encoding="utf-8")
    assert main(["engine", str(spec), "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"crankdyn engine: ошибка: {key}: "), err
    assert not (tmp_path / "o").exists()


def test_synth_options_bounded_like_spec_numbers(tmp_path, capsys):
    assert main(["synth", "--lang", "en",
                 "--l2", "1e308", "--l3", "1e308", "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"crankdyn synth: error: --{k}: got 1e+308; every number must be at most "
                   "1e+12 in magnitude" for k in ("l2", "l3")]
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("step", [0, -1, float("nan"), float("inf"), 1e-9, "1", True, 1e4])
def test_step_arguments_checked(otto_spec, step):
    for fn in (lambda: engine.table_angles(otto_spec, engine.TableSettings(step_deg=step)),
               lambda: engine.fine_angles(otto_spec, step_deg=step),
               lambda: engine.indicated_mean_pressure(otto_spec, step),
               lambda: linkage.full_turn(LINKAGE, step)):
        with pytest.raises(SpecError, match="step_deg"):
            fn()


def test_no_warning_reaches_the_terminal_at_the_edges(tmp_path):
    """A real process (default warning filters, not the suite's) at the edges of the
    accepted ranges: exit 0 and an empty stderr (no numpy RuntimeWarning)."""
    import subprocess
    import sys

    d = edit(ENGINE, "engine", dict(ENGINE["engine"], bore_mm=1e12, stroke_mm=1e-12,
                                    speed_rpm=1e12, rod_ratio=0.999999))
    d["masses"] = dict(reciprocating_kg=1e12, rod_rotating_kg=0.0)
    (tmp_path / "e.toml").write_text(_toml(d), encoding="utf-8")
    r = subprocess.run([sys.executable, "-m", "crankdyn", "engine", str(tmp_path / "e.toml"),
                        "--step", "90", "-o", str(tmp_path / "o")],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stderr == "", r.stderr
