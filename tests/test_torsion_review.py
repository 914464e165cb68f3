"""Review of the torsion report (issue #21, second pass): named masses of a chain given by
hand (``names``), the Campbell diagram agreeing with the critical-speed CSV and with the
engine's major orders, readable mode shapes, and every bad input the issue names refused
through the CLI (one line, exit status 2, nothing written)."""
from __future__ import annotations

import tomllib

import numpy as np
import pandas as pd
import pytest

from crankbase.errors import SpecError
from crankbase.resources import example_path
from crankdyn.cli import main
from torsion.study import build_outputs, load, run_study

pytest.importorskip("matplotlib")

HAND = {"name": "rig", "torsion": {"inertias_kgm2": [0.15, 0.3, 0.09],
                                   "stiffnesses_Nm_rad": [132001.87, 198002.80],
                                   "names": ["engine", "flywheel", "pump"]}}


def _toml(d: dict) -> str:
    """A flat two-level dict as TOML (enough for the specs of these tests)."""
    def value(v):
        if isinstance(v, str):
            return f'"{v}"'
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v)
    lines = [f"name = {value(d['name'])}", "", "[torsion]"]
    lines += [f"{k} = {value(v)}" for k, v in d["torsion"].items()]
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------ names
def test_named_masses_name_every_column_the_workbook_and_the_figure(tmp_path):
    report = run_study(load(HAND))
    assert report.chain.names == ("engine", "flywheel", "pump")
    assert report.chain.section_names == ("engine-flywheel", "flywheel-pump")
    modes = report.tables["torsion_modes.csv"]
    assert [c for c in modes.columns if c.startswith("theta_")] == [
        "theta_engine", "theta_flywheel", "theta_pump"]
    assert report.tables["holzer.csv"]["mass"].tolist()[:3] == ["engine", "flywheel",
                                                                 "pump"]
    wb, figs = build_outputs(report, "en")
    cells = {str(c.value) for ws in wb.worksheets for row in ws.iter_rows() for c in row
             if c.value is not None}
    assert {"engine", "flywheel", "pump"} <= cells
    ax = figs["torsion_modes"].axes[0]
    assert [t.get_text() for t in ax.get_xticklabels()] == ["engine", "flywheel", "pump"]


def test_named_masses_through_the_cli_file_and_dampers_by_name_or_number(tmp_path,
                                                                          capsys):
    d = {"name": "rig", "torsion": {**HAND["torsion"]}}
    spec = tmp_path / "rig.toml"
    spec.write_text(_toml(d) + '\ndampers = [{ at = "pump", c_Nms_rad = 3.0 }, '
                    '{ at = 1, c_Nms_rad = 2.0 }]\n', encoding="utf-8")
    chain = run_study(load(spec)).chain
    assert dict(chain.dampers) == {2: 3.0, 0: 2.0}     # "pump" = mass 3, 1 = "engine"
    out = tmp_path / "out"
    assert main(["torsion", str(spec), "-o", str(out), "--lang", "en"]) == 0
    assert "nodes at 1.77 (engine-flywheel)" in capsys.readouterr().out
    assert "theta_pump" in pd.read_csv(out / "rig_torsion_modes.csv").columns


def test_the_bundled_three_rotor_example_names_its_rotors():
    report = run_study(load(example_path("torsion_three_rotor.toml")))
    assert report.chain.names == ("A", "B", "C")
    # Khurmi & Gupta, "Theory of Machines", three-rotor example: 171 and 277 Hz
    assert [round(float(f)) for f in report.modes.f_Hz] == [171, 277]


@pytest.mark.parametrize("names, key, words", [
    (["a", "b"], "torsion.names", "2 names for 3 masses"),
    (["a b", "c", "d"], "torsion.names[0]", "letters, digits, _ and . only"),
    (["a-b", "c", "d"], "torsion.names[0]", "letters, digits, _ and . only"),
    (["a", "b", "a"], "torsion.names[2]", "given twice"),
    (["throw1", "b", "c"], "torsion.names[0]", "the throws' own"),
    (["a", 3, "c"], "torsion.names[1]", "must be a string"),
    ("abc", "torsion.names", "must be a list of names"),
])
def test_bad_names_one_keyed_error(names, key, words):
    d = {"name": "rig", "torsion": {**HAND["torsion"], "names": names}}
    with pytest.raises(SpecError) as e:
        load(d)
    lines = e.value.lines()
    assert len(lines) == 1 and lines[0].startswith(key + ":") and words in lines[0], lines


def test_names_beside_the_throws_is_an_error():
    data = tomllib.loads(example_path("torsion_inline6.toml").read_text(encoding="utf-8"))
    data["torsion"]["names"] = ["a", "b"]
    with pytest.raises(SpecError) as e:
        load(data)
    assert any(line.startswith("torsion.names: names belongs to a chain by hand")
               for line in e.value.lines())


def test_names_with_the_engine_name_the_response_columns():
    """A by-hand chain with throws on an engine: the response's columns carry the names."""
    data = tomllib.loads(example_path("torsion_inline6.toml").read_text(encoding="utf-8"))
    six = run_study(load(example_path("torsion_inline6.toml")))
    t = data["torsion"]
    for key in ("throw_J_kgm2", "masses"):
        del t[key]
    t["inertias_kgm2"] = six.chain.J.tolist()
    t["throws"] = [0, 1, 2, 3, 4, 5, 6, 0]
    t["names"] = ["pulley", "c1", "c2", "c3", "c4", "c5", "c6", "flywheel"]
    t["speed_step_rpm"] = 100
    r = run_study(load(data))
    cols = r.tables["torsion_response.csv"].columns.tolist()
    assert "theta_pulley_deg" in cols and "M_c5-c6_Nm" in cols and "tau_c6-flywheel_MPa" \
        in cols
    # the same chain as the layout-built one: the same natural frequencies
    assert r.modes.f_Hz == pytest.approx(six.modes.f_Hz, rel=1e-12)


# ------------------------------------------------------------------ the figures
@pytest.fixture(scope="module")
def six():
    return run_study(load(example_path("torsion_inline6.toml")))


def _order_lines(ax):
    """{order: Line2D} of the Campbell diagram's order lines (through the origin)."""
    out = {}
    for line in ax.get_lines():
        x, y = (np.asarray(v, float) for v in line.get_data())
        if len(x) == 2 and x[0] == 0.0 and y[0] == 0.0 and x[1] > 0:
            out[round(60.0 * y[1] / x[1], 6)] = line
    return out


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_campbell_major_lines_are_the_engines_major_orders(six, lang):
    """Inline six, four-stroke: the major orders are the multiples of 3 (i/2), each drawn
    as a major (solid black) line whether or not it meets a natural frequency inside the
    range; order 3 crosses mode 1 at 60·392.7/3 = 7853 rpm, outside 800–6500."""
    _, figs = build_outputs(six, lang)
    lines = _order_lines(figs["campbell"].axes[0])
    assert set(lines) == {0.5 * i for i in range(1, 25)}
    major = {k for k, ln in lines.items() if ln.get_linestyle() == "-"
             and ln.get_color() == "black"}
    assert major == {3.0, 6.0, 9.0, 12.0}
    assert 3.0 not in set(six.critical["order"])          # no critical speed of order 3


def test_campbell_marks_are_the_csv_critical_speeds(six):
    _, figs = build_outputs(six, "en")
    ax = figs["campbell"].axes[0]
    marks = {}
    for line in ax.get_lines():
        if line.get_linestyle() == "None" and line.get_marker() == "o":
            for x, y in zip(*line.get_data()):
                marks[(round(float(x), 6), round(float(y), 6))] = \
                    line.get_markerfacecolor() == "black"
    cs = six.critical
    want = {(round(float(s), 6), round(float(f), 6)): bool(m)
            for s, f, m in zip(cs["speed_rpm"], cs["f_Hz"], cs["major"])}
    assert marks == want
    # every mark lies on its order line: f = k·n/60
    assert np.allclose(cs["f_Hz"], cs["order"] * cs["speed_rpm"] / 60.0, rtol=1e-9)


@pytest.mark.parametrize("example", ["torsion_inline6.toml", "torsion_three_rotor.toml"])
def test_mode_shapes_each_drawn_to_its_largest_amplitude(example):
    """Each mode drawn scaled to max |θ| = 1 with mass 1 positive: the first mode of the
    six stays readable beside the seventh, whose amplitudes relative to mass 1 run to 19;
    the shape itself (the ratios) is the CSV's."""
    report = run_study(load(example_path(example)))
    _, figs = build_outputs(report, "en")
    ax = figs["torsion_modes"].axes[0]
    curves = [ln for ln in ax.get_lines() if ln.get_label().startswith("mode ")]
    assert len(curves) == report.modes.count
    for m, ln in enumerate(curves):
        y = np.asarray(ln.get_ydata(), float)
        shape = np.asarray(report.modes.shapes[m], float)
        assert np.max(np.abs(y)) == pytest.approx(1.0)
        assert y[0] > 0
        assert y == pytest.approx(shape / np.max(np.abs(shape)) * np.sign(shape[0]))


# ------------------------------------------------------------------ bad input, CLI
def _six_with(**changes):
    data = tomllib.loads(example_path("torsion_inline6.toml").read_text(encoding="utf-8"))
    data["torsion"].update(changes)
    return data


BAD = [
    ("stiffness count", HAND | {"torsion": {**HAND["torsion"],
                                            "stiffnesses_Nm_rad": [1e5, 1e5, 1e5]}},
     "torsion.stiffnesses_Nm_rad", "3 stiffnesses for 3 masses"),
    ("J <= 0", HAND | {"torsion": {**HAND["torsion"], "inertias_kgm2": [0.15, 0.0, 0.09]}},
     "torsion.inertias_kgm2[1]", "> 0"),
    ("k <= 0", HAND | {"torsion": {**HAND["torsion"],
                                   "stiffnesses_Nm_rad": [132001.87, -1.0]}},
     "torsion.stiffnesses_Nm_rad[1]", "> 0"),
    ("speed range reversed", _six_with(speed_range_rpm=[6500, 800]),
     "torsion.speed_range_rpm", "0 <"),
    ("speed range zero", _six_with(speed_range_rpm=[0, 6500]),
     "torsion.speed_range_rpm[0]", "> 0"),
    ("orders_max", _six_with(orders_max=7.3), "torsion.orders_max", "0.5"),
]


@pytest.mark.parametrize("case", BAD, ids=[b[0] for b in BAD])
def test_each_bad_input_one_error_exit_2_nothing_written(tmp_path, capsys, case):
    _, data, key, words = case
    import tomli_w

    spec = tmp_path / "bad.toml"
    spec.write_text(tomli_w.dumps(data), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["torsion", str(spec), "-o", str(out), "--lang", "en"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1, err
    assert err[0].startswith(f"crankdyn torsion: error: {key}: "), err
    assert words in err[0], err
    assert not out.exists()


# ------------------------------------------------------------------ the workbook
def test_workbook_text_cells_stand_apart_from_the_number_before_them(six):
    """The modes sheet: ω (a number, right-aligned) then the nodes ("1.203; 3.428 …", a
    text): rendered, "2467.2 6.604" read as one cell; every text cell of a table is
    left-aligned with an indent."""
    wb, _ = build_outputs(six, "en")
    ws = wb.worksheets[1]
    header = {c.value: c.column for c in ws[4] if c.value}      # the machine-name row
    col = header["nodes"]
    cells = [ws.cell(r, col) for r in range(5, 5 + six.modes.count)]
    assert all(isinstance(c.value, str) for c in cells)
    assert all(c.alignment.horizontal == "left" and c.alignment.indent >= 1 for c in cells)


def test_names_are_bounded_before_they_are_read():
    d = {"name": "rig", "torsion": {**HAND["torsion"], "names": ["m"] * 65}}
    with pytest.raises(SpecError) as e:
        load(d)
    assert e.value.lines() == ["torsion.names: has 65 names; at most 64 are allowed"]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_bad_name_in_either_language_through_the_cli(tmp_path, capsys, lang):
    from test_error_language import cyrillic, english_words

    spec = tmp_path / "rig.toml"
    spec.write_text(_toml({"name": "rig", "torsion": {**HAND["torsion"],
                                                      "names": ["a", "b"]}}),
                    encoding="utf-8")
    out = tmp_path / "out"
    assert main(["torsion", str(spec), "-o", str(out), "--lang", lang]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "torsion.names: " in err[0] and not out.exists()
    body = err[0].split("torsion.names: ", 1)[1]
    assert not (cyrillic(body) if lang == "en" else english_words(body)), body
