"""The torsional-vibration study layer: spec → chain → report → CSVs/workbook (issue #21).

The physics itself (modes, Holzer, harmonics, response) is tested in
tests/test_torsion_physics.py; here: the ``[torsion]`` keys through the one schema, the
chain built from the engine's layout, the published example through the whole chain, the
CSVs equal to the study's tables, the engine report with ``[torsion]`` = without + the
torsion files, every bad input one keyed error in both languages, the summaries.
"""
from __future__ import annotations

import copy
import math
import re
import tomllib

import numpy as np
import pandas as pd
import pytest

import engine
from crankbase.errors import SpecError
from crankbase.output import safe_name
from crankbase.resources import example_path
from torsion.study import build_chain, load, run_study, write_report

THREE = example_path("torsion_three_rotor.toml")
SIX = example_path("torsion_inline6.toml")


def _six_dict():
    return tomllib.loads(SIX.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def three():
    return run_study(load(THREE))


@pytest.fixture(scope="module")
def six():
    return run_study(load(SIX))


# ------------------------------------------------------------------ the published example
def test_three_rotor_published_frequencies_and_nodes(three, tmp_path):
    """Khurmi & Gupta, "Theory of Machines", ch. "Torsional Vibrations": the oil engine and
    pump on a 70 mm shaft, rotors 0.15, 0.3, 0.09 kg·m², 1.5 m and 1.0 m apart, C = 84
    kN/mm²: single-node 171 Hz with the node 1.146 m from the first rotor, two-node 277 Hz
    with nodes 0.4356 m from the first rotor and 0.726 m from the last (printed values).
    Through the whole chain: the spec file → the study → the CSV written."""
    written = write_report(three, tmp_path, "en", formats=("png",))
    modes = pd.read_csv(tmp_path / "three-rotor-khurmi_torsion_modes.csv")
    assert [round(f) for f in modes["f_Hz"]] == [171, 277]
    node1 = float(modes["nodes"][0])                  # mass units: 1 + x / 1.5 m in section 1
    assert (node1 - 1.0) * 1.5 == pytest.approx(1.146, abs=0.003)
    n2a, n2b = (float(x) for x in modes["nodes"][1].split(";"))
    assert (n2a - 1.0) * 1.5 == pytest.approx(0.4356, abs=0.002)
    assert (3.0 - n2b) * 1.0 == pytest.approx(0.726, abs=0.002)
    assert not three.notes[0].render("en").startswith("no mass")   # the no-engine note
    assert three.free_only and set(three.tables) == {"torsion_modes.csv", "holzer.csv"}
    names = [p.name for p in written]
    assert names == [f"three-rotor-khurmi_{n}" for n in three.tables] + [
        "three-rotor-khurmi_torsion.xlsx"] + [p.name for p in written.plots]


def test_holzer_csv_closes_at_the_natural_frequencies(three, tmp_path):
    """The Holzer table's residual torque after the last mass vanishes at each natural
    frequency and not at the trial ones, which bracket the first mode (sign change)."""
    write_report(three, tmp_path, "ru", formats=("svg",))
    h = pd.read_csv(tmp_path / "three-rotor-khurmi_holzer.csv")
    last = h.groupby("omega_rad_s", sort=False)["sum_torque_Nm"].last()
    scale = h.groupby("omega_rad_s", sort=False)["sum_torque_Nm"].apply(
        lambda s: s.abs().max())
    w = list(last.index)
    assert w[:2] == pytest.approx(list(three.modes.omega_rad_s))
    assert w[2:] == [1000.0, 1100.0]
    assert np.all(np.abs(last.iloc[:2]) < 1e-9 * scale.iloc[:2])
    assert last.iloc[2] > 0 > last.iloc[3]             # 1000 < ω1 = 1072.5 < 1100 rad/s
    assert abs(last.iloc[2]) > 1e-3 * scale.iloc[2]


def test_the_csvs_equal_the_study_tables(six, tmp_path, unrendered_figures):
    """(The tables, the names and the workbook; the figures are built, not drawn: the
    torsion plots are rendered in tests/test_torsion_plots.py.)"""
    written = write_report(six, tmp_path, "en", formats=("png",))
    assert unrendered_figures == ["png"] * len(written.plots) and written.plots
    assert [p.name for p in written.tables] == [f"bmw-m54b30_{n}" for n in six.tables]
    for name, df in six.tables.items():
        back = pd.read_csv(tmp_path / f"bmw-m54b30_{name}")
        assert list(back.columns) == list(df.columns), name
        for col in df.columns:
            if df[col].dtype.kind in "fi":
                assert np.allclose(back[col].to_numpy(float), df[col].to_numpy(float),
                                   rtol=1e-12, atol=0, equal_nan=True), (name, col)
            else:
                assert list(back[col].astype(str)) == list(df[col].astype(str)), (name, col)
        assert all(c.isascii() for c in "".join(df.columns)), name
    for p in written:                                    # valid on Windows
        assert safe_name(p.stem) == p.stem and p.suffix in (".csv", ".xlsx", ".png")
    # the workbook: one sheet per table, every number finite (tests/workbook_audit.py)
    from openpyxl import load_workbook

    wb = load_workbook(written.workbook)
    assert len(wb.sheetnames) == 6
    for ws in wb.worksheets:
        assert int(ws.page_setup.paperSize) == int(ws.PAPERSIZE_A4)
        for row in ws.iter_rows(values_only=True):
            for v in row:
                assert not (isinstance(v, float) and not math.isfinite(v))


# ------------------------------------------------------------------ the chain of an engine
def test_the_engine_chain_from_the_layout(six):
    """Damper before throw 1, six throws, flywheel after the last; each throw's J is the
    crank's own 0.0025 + mш.к·R² + mj·R²(1/2 + λ²/8) (domain.md §7); every cylinder of
    the inline six sits on its own throw's mass; k and the diameters per section."""
    ch = six.chain
    assert ch.names == ("damper", "throw1", "throw2", "throw3", "throw4", "throw5",
                        "throw6", "flywheel")
    s = six.study.engine.spec
    J_throw = 0.0025 + (s.m_rod_rot + s.mj * (0.5 + s.lam ** 2 / 8)) * s.R ** 2
    assert ch.J[1:7] == pytest.approx([J_throw] * 6, rel=1e-12)
    assert ch.J[0] == 0.015 and ch.J[-1] == 0.12
    assert list(ch.cylinder_mass) == [1, 2, 3, 4, 5, 6]
    assert list(ch.table()["throw"]) == [0, 1, 2, 3, 4, 5, 6, 0]
    lay = engine.layout(s, six.study.engine.train)
    assert np.allclose(ch.phases_deg, lay.phase_deg)
    assert ch.k[0] == 0.9e6 and ch.k[-1] == 1.2e6 and ch.diameters[-1] == 0.07
    assert ch.section_names[5] == "throw5-throw6"
    assert list(six.tables["torsion_response.csv"].columns)[:2] == ["speed_rpm",
                                                                    "theta_damper_deg"]


def test_mass_placement_and_a_vee_throw():
    """``before``/``after`` a throw number go next to that throw, in the file's order; on
    a vee two cylinders share a throw, whose J then counts both rods and pistons."""
    from crankbase.schema import SpecReader
    from engine.spec.torsion_inputs import read_torsion

    study = load(SIX)
    es = study.engine
    lay = engine.layout(es.spec, es.train)
    d = _six_dict()["torsion"]
    d["masses"] = [{"name": "gear", "J_kgm2": 0.01, "after": 3},
                   {"name": "pulley", "J_kgm2": 0.02, "before": 1},
                   {"name": "hub", "J_kgm2": 0.03, "before": "first"},
                   {"name": "fw", "J_kgm2": 0.1, "after": "last"}]
    d["stiffnesses_Nm_rad"] = [1e6] * 9
    d.pop("shaft_diameters_mm")
    c = SpecReader()
    inputs = read_torsion(c, {"torsion": d})
    assert not c.problems
    ch = build_chain(inputs, es.spec, lay)
    assert ch.names == ("pulley", "hub", "throw1", "throw2", "throw3", "gear", "throw4",
                        "throw5", "throw6", "fw")
    assert list(ch.cylinder_mass) == [2, 3, 4, 6, 7, 8]
    v8 = engine.load(example_path("diesel_kamaz740.toml"))
    lay8 = engine.layout(v8.spec, v8.train)
    d8 = {"throw_J_kgm2": 0.01, "stiffnesses_Nm_rad": [1e6] * 3}
    ch8 = build_chain(read_torsion(SpecReader(), {"torsion": d8}), v8.spec, lay8)
    s = v8.spec
    one = (s.m_rod_rot + s.mj * (0.5 + s.lam ** 2 / 8)) * s.R ** 2
    assert ch8.n == 4 and ch8.J == pytest.approx([0.01 + 2 * one] * 4, rel=1e-12)
    assert sorted(np.bincount(ch8.cylinder_mass)) == [2, 2, 2, 2]


def test_inline_six_major_orders_are_multiples_of_three(six):
    cs = six.critical
    assert len(cs) > 0
    major = cs["major"].to_numpy(bool)
    assert np.all(np.isclose(cs["order"][major] % 3, 0))
    assert not np.any(np.isclose(cs["order"][~major] % 3, 0))
    # n = 60 f / k inside the range
    assert np.allclose(cs["speed_rpm"], 60 * cs["f_Hz"] / cs["order"])
    assert cs["speed_rpm"].between(800, 6500).all()


def test_engine_report_with_torsion_is_the_report_without_plus_the_torsion_files(
        tmp_path, unrendered_figures):
    """The engine report of the spec with [torsion] writes every file of the same spec
    without the table, byte for byte (the CSVs), plus the torsion files.  (Names and
    tables: the figures are built, not drawn; the six's engine plots are rendered by the
    session's shared CLI report, the torsion plots in tests/test_torsion_plots.py.)"""
    data = _six_dict()
    bare = copy.deepcopy(data)
    del bare["torsion"]
    without = engine.run_study(engine.load(bare))
    assert without.torsion is None
    a = engine.write_report(without, tmp_path / "a", "en", formats=("png",))
    rep = engine.run_study(engine.load(data))
    b = engine.write_report(rep, tmp_path / "b", "en", formats=("png",))
    names_a = {p.name for p in a}
    names_b = {p.name for p in b}
    torsion = {p.name for p in b.torsion}
    assert names_b == names_a | torsion and not names_a & torsion
    assert torsion == {f"bmw-m54b30_{n}" for n in rep.torsion.tables} | {
        "bmw-m54b30_torsion.xlsx"} | {p.name for p in b.torsion if p.suffix == ".png"}
    for p in a.tables:
        assert (tmp_path / "b" / p.name).read_bytes() == p.read_bytes(), p.name
    assert {p.name for p in (tmp_path / "b").iterdir()
            if not p.name.startswith(".")} == names_b


# ------------------------------------------------------------------ bad input
def _problem(data, lang="en"):
    with pytest.raises(SpecError) as err:
        run_study(load(data))
    return err.value.lines(lang)


BAD = [
    ("stiffness count (engine)", lambda d: d["torsion"].update(stiffnesses_Nm_rad=[1e6] * 6),
     "torsion.stiffnesses_Nm_rad"),
    ("non-positive J", lambda d: d["torsion"]["masses"][0].update(J_kgm2=0.0),
     "torsion.masses[0].J_kgm2"),
    ("non-positive k", lambda d: d["torsion"]["stiffnesses_Nm_rad"].__setitem__(2, -1.0),
     "torsion.stiffnesses_Nm_rad"),
    ("speed range order", lambda d: d["torsion"].update(speed_range_rpm=[6000, 600]),
     "torsion.speed_range_rpm"),
    ("speed range sign", lambda d: d["torsion"].update(speed_range_rpm=[0, 600]),
     "torsion.speed_range_rpm"),
    ("orders_max", lambda d: d["torsion"].update(orders_max=7.25), "torsion.orders_max"),
    ("no such throw", lambda d: d["torsion"]["masses"][1].update(after=7),
     "torsion.masses[1].after"),
    ("before and after", lambda d: d["torsion"]["masses"][0].update(after=2),
     "torsion.masses[0].before"),
    ("both forms", lambda d: d["torsion"].update(inertias_kgm2=[1.0, 2.0]),
     "torsion.inertias_kgm2"),
    ("damper at nothing", lambda d: d["torsion"].update(dampers=[{"at": "pump",
                                                                  "c_Nms_rad": 5.0}]),
     "torsion.dampers[0].at"),
    ("diameter count", lambda d: d["torsion"].update(shaft_diameters_mm=[60.0]),
     "torsion.shaft_diameters_mm"),
    ("no speed range", lambda d: d["torsion"].pop("speed_range_rpm"),
     "torsion.speed_range_rpm"),
    ("unknown key", lambda d: d["torsion"].update(stiffness_Nm_rad=[1.0]),
     "torsion.stiffness_Nm_rad"),
]


@pytest.mark.parametrize("what, change, key", BAD, ids=[b[0] for b in BAD])
def test_bad_input_one_keyed_error_in_both_languages(what, change, key):
    from test_error_language import cyrillic, english_words

    data = _six_dict()
    change(data)
    en, ru = _problem(data, "en"), _problem(data, "ru")
    assert len(en) == 1 and re.match(re.escape(key) + r"(\[\d+\])?: ", en[0]), en
    assert len(ru) == 1 and re.match(re.escape(key) + r"(\[\d+\])?: ", ru[0]), ru
    assert not cyrillic(en[0]), en
    assert not english_words(ru[0]), ru
    assert en[0] != ru[0]


def test_bad_by_hand_chains():
    base = {"name": "rig", "torsion": {"inertias_kgm2": [0.15, 0.3, 0.09],
                                       "stiffnesses_Nm_rad": [1.3e5, 2e5]}}
    for change, key in (
            (dict(stiffnesses_Nm_rad=[1.3e5]), "torsion.stiffnesses_Nm_rad"),
            (dict(inertias_kgm2=[0.15, 0.0, 0.09]), "torsion.inertias_kgm2"),
            (dict(throws=[0, 1]), "torsion.throws"),
            (dict(throws=[0, 2, 0]), "torsion.throws"),
            (dict(throw_J_kgm2=0.01, inertias_kgm2=None), "torsion.throw_J_kgm2")):
        d = copy.deepcopy(base)
        d["torsion"].update(change)
        d["torsion"] = {k: v for k, v in d["torsion"].items() if v is not None}
        lines = _problem(d)
        assert len(lines) == 1 and re.match(re.escape(key) + r"(\[\d+\])?: ", lines[0]), \
            (change, lines)
    with pytest.raises(SpecError, match="torsion"):
        load({"name": "rig"})


def test_by_hand_chain_in_an_engine_takes_the_engine_excitation():
    """A by-hand chain whose ``throws`` map masses onto the engine's throws is driven by
    the engine; with the wrong count of throws it is an error."""
    data = _six_dict()
    data["torsion"] = {"inertias_kgm2": [0.015] + [0.0047] * 6 + [0.12],
                       "throws": [0, 1, 2, 3, 4, 5, 6, 0],
                       "stiffnesses_Nm_rad": data["torsion"]["stiffnesses_Nm_rad"],
                       "speed_range_rpm": [800, 6500]}
    rep = run_study(load(data))
    assert list(rep.chain.cylinder_mass) == [1, 2, 3, 4, 5, 6]
    data["torsion"]["throws"] = [0, 6, 5, 4, 3, 2, 1, 0]           # the other way round
    back = run_study(load(data)).chain
    assert list(back.cylinder_mass) == [6, 5, 4, 3, 2, 1]
    assert list(back.table()["throw"]) == [0, 6, 5, 4, 3, 2, 1, 0]
    assert rep.response is not None and len(rep.critical) > 0
    data["torsion"]["throws"] = [0, 1, 2, 3, 4, 0, 0, 0]
    assert _problem(data)[0].startswith("torsion.throws:")


# ------------------------------------------------------------------ summaries
def test_summaries_in_both_languages(six, three):
    from test_error_language import cyrillic, english_words

    for rep in (six, three):
        en, ru = rep.summary_lines("en"), rep.summary_lines("ru")
        assert len(en) == len(ru)
        assert not [ln for ln in en if cyrillic(ln)], en
        names = set(rep.chain.names) | {rep.study.name}
        bad = [w for ln in ru for w in english_words(ln) if w not in names
               and not any(w in n for n in names)]
        assert not bad, (bad, ru)
    en = six.summary_lines("en")
    f1 = six.modes.f_Hz[0]
    assert f"f1 = {f1:.2f} Hz" in en[1]
    speed, sec, M = six.response.worst
    assert f"largest vibration torque {M:.0f} N·m in section " \
           f"{six.chain.section_names[sec]} at {speed:.0f} rpm" in "\n".join(en)
    assert re.search(r"worst critical speed \d+ rpm: mode \d, order [\d.]+", "\n".join(en))
    assert "8 masses" in en[0] and "из 8 масс" in six.summary_lines("ru")[0]
    assert "3 masses" in three.summary_lines("en")[0]


def test_the_workbooks_pass_the_audit(six, three):
    """No text cut off, no ####, one number format per column, one font family
    (tests/workbook_audit.py), in both languages; the Holzer sheet holds a block per
    frequency with its residual torque."""
    from workbook_audit import problems

    from torsion.report import build_workbook

    for rep, lang in ((six, "ru"), (three, "en")):
        wb = build_workbook(rep, lang)
        assert problems(wb, rep.name) == []
    ws = build_workbook(three, "en")["Holzer"]
    text = [c for row in ws.iter_rows(values_only=True) for c in row if isinstance(c, str)]
    assert sum(s.startswith("ω = ") for s in text) == 4                 # 2 modes + 2 trials
    assert sum(s.startswith("residual torque") for s in text) == 4


def test_damping_lowers_the_resonant_torque():
    """More modal damping, or a viscous damper at the front mass, lowers the largest
    vibration torque (a resonance in range); none of it moves the natural frequencies."""
    def worst(**change):
        data = _six_dict()
        data["torsion"].update(change)
        rep = run_study(load(data))
        return rep.modes.f_Hz[0], float(np.max(rep.response.torque_Nm[:, :6]))

    f0, m0 = worst(speed_range_rpm=[3800, 4050])          # mode 1 by order 6 at ≈ 3927 rpm
    f1, m1 = worst(speed_range_rpm=[3800, 4050], damping_ratio=0.05)
    f2, m2 = worst(speed_range_rpm=[3800, 4050],
                   dampers=[{"at": "damper", "c_Nms_rad": 30.0}])
    assert f0 == f1 == f2
    assert m1 < 0.7 * m0 and m2 < m0       # the other orders, off resonance, stay
