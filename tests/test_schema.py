"""The one spec schema (crankbase.schema, engine/linkage/dynamics schema modules): every
key declared once, every problem keyed and told in the run's language, "did you mean",
unit conversion, bounds on every count and size, the README reference generated from it;
and the bad input of issue #23 that escaped as a traceback."""
from __future__ import annotations

import copy
import re
from pathlib import Path

import numpy as np
import pytest

import engine
import linkage
from crankbase import schema as S
from crankbase.errors import SpecError
from crankbase.texts import keys
from dynamics.rotor import load_rotor_spec
from dynamics.spec import load_dynamics_spec

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"

ENGINE = {
    "engine": dict(name="t", bore_mm=110.0, stroke_mm=125.0, rod_ratio=0.272,
                   speed_rpm=2600.0, crankcase_MPa=0.1),
    "masses": dict(reciprocating_kg=3.08, rod_rotating_kg=0.9),
    "pressure": dict(angle_deg=[0, 360, 370], p_MPa=[0.1, 5.0, 6.0]),
    "table": dict(step_deg=30, force_scale_N_per_mm=500.0),
}
LINKAGE = {
    "mechanism": dict(kind="crank-rocker", name="m", crank=0.175, coupler=0.55,
                      rocker=0.325, ground=0.54, omega_rad_s=17.0),
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


def problems(fn):
    with pytest.raises(SpecError) as info:
        fn()
    return info.value


# ------------------------------------------------------------------ issue #23
def test_a_huge_cylinder_count_is_refused_before_anything_is_sized():
    # main: list(range(1, n + 1)) for the firing-order check → MemoryError
    d = edit(ENGINE, "engine.cylinders", 4_000_000_000)
    d["engine"]["firing_order"] = [1, 3, 4, 2]
    err = problems(lambda: engine.load(d))
    line = next(l for l in err.lines() if l.startswith("engine.cylinders"))
    assert "4e+09" in line and f"<= {S.MAX_CYLINDERS}" in line, line
    # the physical bound: 24 cylinders load, 25 do not
    ok = edit(ENGINE, "engine.cylinders", S.MAX_CYLINDERS)
    assert engine.load(ok).spec.cylinders == S.MAX_CYLINDERS
    problems(lambda: engine.load(edit(ENGINE, "engine.cylinders", S.MAX_CYLINDERS + 1)))
    # and built directly
    from dataclasses import replace
    with pytest.raises(SpecError, match="cylinders"):
        replace(engine.load(ENGINE).spec, cylinders=4_000_000_000)


@pytest.mark.parametrize("kind", ["engine", "linkage"])
def test_an_integer_of_5000_digits_is_a_spec_error_naming_the_file(tmp_path, kind):
    # main: Python's "Exceeds the limit (4300 digits)" ValueError escaped as a traceback
    big = "9" * 5000
    if kind == "engine":
        text = (EXAMPLES / "petrol_vaz2106.toml").read_text(encoding="utf-8")
        text = re.sub(r"(?m)^speed_rpm = .*$", f"speed_rpm = {big}", text)
        load = engine.load
    else:
        text = (EXAMPLES / "press.toml").read_text(encoding="utf-8")
        text = re.sub(r"(?m)^omega_rad_s = .*$", f"omega_rad_s = {big}", text)
        load = linkage.load_spec
    assert big in text
    path = tmp_path / f"{kind}.toml"
    path.write_text(text, encoding="utf-8")
    err = problems(lambda: load(path))
    assert err.lines() == [f"{path}: holds an integer of more than 4300 digits; every "
                           f"number of a spec must be at most 1e+12 in magnitude"]


@pytest.mark.parametrize("load, base, key, value", [
    (engine.load, ENGINE, "engine.acceleration", np.array(["exact", "two-term"])),
    (engine.load, ENGINE, "engine.strokes", np.array([4, 2])),
    (linkage.load_spec, LINKAGE, "analysis.working_stroke", np.array(["ccw", "cw"])),
    (linkage.load_spec, LINKAGE, "mechanism.kind", np.array(["crank-rocker"])),
])
def test_a_numpy_array_for_a_choice_is_refused_naming_the_key(load, base, key, value):
    # main: "The truth value of an array with more than one element is ambiguous"
    err = problems(lambda: load(edit(base, key, value)))
    assert any(l.startswith(f"{key}: got array(") and "valid:" in l for l in err.lines()), \
        err.lines()


def test_numpy_scalars_and_1d_arrays_are_read_as_their_values():
    d = edit(ENGINE, "engine.bore_mm", np.float64(110.0))
    d["engine"]["acceleration"] = np.str_("exact")
    d["table"]["extra_angles_deg"] = np.array([5.0, 15.0])
    study = engine.load(d)
    assert study.spec.bore == 0.11 and study.spec.acceleration == "exact"
    assert study.settings.extra_angles_deg == (5.0, 15.0)


# ------------------------------------------------------------------ the run's language
def test_a_bad_spec_in_a_russian_run_gives_russian_lines():
    d = edit(ENGINE, "engine.bore_mm", -5)
    d["engine"]["bore"] = 92
    d["table"]["form"] = "long"
    del d["engine"]["speed_rpm"]
    err = problems(lambda: engine.load(d))
    ru = err.lines("ru")
    en = err.lines()
    assert en == [str(p) for p in err.problems]          # English stays the default
    by_key = dict(line.split(": ", 1) for line in ru)
    assert by_key["engine.bore"] == ("неизвестный ключ; возможно, имелось в виду 'bore_mm'? "
                                     "допустимые ключи здесь: " +
                                     ", ".join(engine.schema.ENGINE.names))
    assert by_key["engine.bore_mm"] == "получено -5; должно быть > 0"
    assert by_key["engine.speed_rpm"] == ("отсутствует; требуется частота вращения "
                                          "коленчатого вала [мин⁻¹]")
    assert by_key["table.form"] == "получено 'long'; допустимо: 'seed', 'kolchin'"
    assert dict(line.split(": ", 1) for line in en)["engine.speed_rpm"] == \
        "missing; crankshaft speed [rpm] is required"


def test_cli_prints_the_problems_in_the_runs_language(tmp_path, capsys):
    from crankdyn.cli import main

    text = (EXAMPLES / "press.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^crank = ", "crank_m = ", text, count=1)
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["linkage", str(path), "-o", str(tmp_path / "o"), "--lang", "ru"]) == 2
    err = capsys.readouterr().err
    assert "mechanism.crank_m: неизвестный ключ; возможно, имелось в виду 'crank'?" in err
    assert "mechanism.crank: отсутствует; требуется длина кривошипа [м]" in err
    assert main(["linkage", str(path), "-o", str(tmp_path / "o"), "--lang", "en"]) == 2
    err = capsys.readouterr().err
    assert "mechanism.crank_m: unknown key; did you mean 'crank'?" in err
    assert not re.search("[а-яА-Я]", err)


@pytest.mark.parametrize("typo, guess", [("bore", "bore_mm"), ("stroke_m", "stroke_mm"),
                                         ("speed", "speed_rpm"), ("cylindres", "cylinders"),
                                         ("rod_lenght_mm", "rod_length_mm")])
def test_unknown_key_did_you_mean(typo, guess):
    err = problems(lambda: engine.load(edit(ENGINE, f"engine.{typo}", 1)))
    assert any(l.startswith(f"engine.{typo}: unknown key; did you mean {guess!r}?")
               for l in err.lines()), err.lines()


def test_unknown_table_did_you_mean():
    err = problems(lambda: engine.load(edit(ENGINE, "flywhel.delta", 0.01)))
    assert any(l.startswith("flywhel: unknown key; did you mean 'flywheel'?")
               for l in err.lines()), err.lines()


# ------------------------------------------------------------------ one schema
SCHEMAS = S._schemas()


def _all_keys():
    for s in SCHEMAS:
        for t in S._walk(s.tables):
            for k in t.keys():
                yield s, t, k


def test_every_key_has_its_words_in_every_language():
    for lang in ("en", "ru"):
        missing = [k for k in S.key_texts() if k not in keys(lang)]
        assert not missing, (lang, missing)


def test_every_count_and_list_is_bounded():
    for s, t, k in _all_keys():
        if k.kind == "integer":
            assert k.le is not None, f"{t.path}.{k.name}: a count without an upper bound"
        if k.kind == "numbers":
            assert (k.length or k.max_length or S.MAX_ROWS) <= S.MAX_ROWS
    for s in SCHEMAS:
        for t in S._walk(s.tables):
            if isinstance(t, S.ArrayOfTables):
                assert t.max_items <= S.MAX_TABLE_ROWS


def test_the_loaders_know_exactly_the_schema_keys():
    # an unknown-key problem lists the valid keys: they are the schema's, per table
    cases = [(engine.load, ENGINE, "masses", engine.schema.MASSES),
             (engine.load, ENGINE, "pressure", engine.schema.PRESSURE),
             (engine.load, ENGINE, "bearings", engine.schema.BEARINGS),
             (linkage.load_spec, LINKAGE, "analysis", linkage.schema.ANALYSIS)]
    for load, base, table, decl in cases:
        err = problems(lambda: load(edit(base, f"{table}.zzz", 1)))
        line = next(l for l in err.lines() if l.startswith(f"{table}.zzz"))
        assert line.endswith("valid keys here: " + ", ".join(decl.names)), line


def test_units_are_converted_exactly_as_the_division_by_1000():
    key = engine.schema.ENGINE.key("bore_mm")
    for mm in (92.0, 79.0, 110.0, 0.1, 123.456):
        assert key.to_si(mm) == mm / 1000.0
    assert engine.schema.ENGINE.key("crankcase_MPa").to_si(0.1) == 0.1 * 1e6
    assert engine.schema.COUNTERWEIGHT.key("mr_kg_mm").to_si([42.6]) == [42.6 / 1e3]
    study = engine.load(edit(ENGINE, "bearings.counterweight_kg_mm", 250.0))
    assert study.bearings.options.counterweight_mr == 0.25
    assert study.spec.p0 == 1e5 and study.spec.stroke == 0.125


def test_the_study_carries_the_bearing_inputs_read_once():
    from engine.bearings.analysis import read_bearing_inputs

    d = edit(ENGINE, "bearings.wear_half_angle_deg", 45.0)
    d["rod"] = dict(model="rigid", inertia_kg_m2=0.003, mass_kg=1.2)
    study = engine.load(d)
    assert study.bearings.asked and study.bearings.options.wear_half_angle_deg == 45.0
    assert study.bearings.rod_model == "rigid"
    assert read_bearing_inputs(d, study.spec) == study.bearings
    assert engine.load(ENGINE).bearings.asked is False


def test_spec_modules_import_no_calculation():
    # the spec <-> bearing_spec circle is broken: reading a spec needs none of forces,
    # bearings, rodmodel
    import subprocess
    import sys

    code = ("import sys, engine.spec.loading; "
            "print(sorted(m for m in sys.modules if m == 'engine.rodmodel' "
            "or m.startswith(('engine.bearing', 'engine.wear'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, check=True).stdout
    # engine/__init__ imports forces (and so on) but never the bearing modules
    assert out.strip() == "[]", out


def test_every_bundled_example_still_loads():
    from torsion.study import load as load_torsion

    unread = []
    for path in sorted(EXAMPLES.glob("*.toml")):
        text = path.read_text(encoding="utf-8")
        if "[torsion]" in text and "[engine]" not in text:     # a chain given by hand
            load_torsion(path)
        elif "[engine]" in text and "[dynamics]" not in text:
            engine.load(path)
        elif "[mechanism]" in text and "[dynamics]" not in text \
                and "[balance]" not in text:
            linkage.load_spec(path)
        elif "[rotor]" in text:
            load_rotor_spec(path)
        elif "[dynamics]" in text:
            load_dynamics_spec(path)
        else:
            unread.append(path.name)
    # only the linkage balance study is read elsewhere (dynamics.balance_study)
    assert all("[balance]" in (EXAMPLES / n).read_text(encoding="utf-8")
               for n in unread), unread


def test_array_of_tables_is_bounded_and_typed():
    d = edit(ENGINE, "balance.counterweight", [dict(z_mm=0, mr_kg_mm=1, angle_deg=0)] * 51)
    err = problems(lambda: engine.load(d))
    assert "balance.counterweight: has 51 tables; at most 50 are allowed" in err.lines()
    d = edit(ENGINE, "balance.counterweight", [dict(z_mm=0, mr_kg=1, angle_deg=0), 3])
    lines = problems(lambda: engine.load(d)).lines()
    assert any(l.startswith("balance.counterweight[0].mr_kg: unknown key; did you mean "
                            "'mr_kg_mm'?") for l in lines), lines
    assert "balance.counterweight[1]: must be a table, got 3" in lines


# ------------------------------------------------------------------ the README
def test_readme_spec_reference_is_generated_from_the_schema():
    # regenerate with: python -m crankbase.schema update-readme
    assert S.readme_reference(ROOT / "README.md") == S.readme_block()


def test_reference_rows_carry_type_unit_range_default():
    md = S.markdown_reference("en")
    assert ("| `bore_mm` | number | mm | > 0 |  | yes | cylinder bore D: inner diameter of "
            "the cylinder; sets the piston area Ap = πD²/4 |") in md
    assert "| `cylinders` | integer |  | [1, 24] | 1 | no |" in md
    assert "| `n1` | number |  | (1, 2) |  | yes |" in md
    ru = S.markdown_reference("ru")
    assert "| `bore_mm` | число | мм | > 0 |  | да | диаметр цилиндра D:" in ru


def test_describe_gives_a_keys_words_for_the_sheets():
    d = engine.schema.SCHEMA.describe("engine.bore_mm", "ru")
    assert d == {"key": "bore_mm", "label": "диаметр цилиндра",
                 "help": "внутренний диаметр цилиндра; задаёт площадь поршня Fп = πD²/4",
                 "symbol": "D", "unit": "мм", "range": "> 0", "default": "",
                 "required": True}
    en = engine.schema.SCHEMA.describe("pressure.cycle.n1", "en")
    assert (en["label"], en["range"]) == ("compression polytropic exponent", "(1, 2)")
    assert engine.schema.SCHEMA.describe("masses.rod_kg", "ru")["symbol"] == "mш"
