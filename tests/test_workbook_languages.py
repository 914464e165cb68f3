"""A Chinese workbook holds no English word (issue #19 item 4): every cell of a ``--lang zh``
synthesis and torsion workbook is Chinese, a number, a symbol or unit, a CSV column name
(the second header row), or a name the spec gave (the engine's, a damper's, a flywheel's),
by the rule of tests/language_rules.py.  The words come from the catalogues
(``synth.book.*``, ``torsion.mass.throw``, ``torsion.part.*``); the CSV files keep their
names.  The Russian workbooks keep the seed's words, now read from the same catalogues."""
from __future__ import annotations

import pandas as pd
import pytest
from openpyxl import load_workbook

from crankbase.resources import example_path
from crankdyn.cli import main
from language_rules import CJK, CYRILLIC, SYMBOLS, UNITS, latin_words


def _strings(wb):
    return [(ws.title, c.coordinate, c.value) for ws in wb.worksheets
            for row in ws.iter_rows() for c in row if isinstance(c.value, str)]


def _english_cells(wb, typed):
    """Cells of ``wb`` with an English word: neither a CSV column name nor a given name
    (``typed``), and a Latin word left by the rule."""
    bad = []
    for sheet, at, v in _strings(wb):
        if v in typed:
            continue
        if CYRILLIC.search(v) or latin_words(v, typed, SYMBOLS | UNITS):
            bad.append((sheet, at, v))
    return bad


@pytest.fixture(scope="module")
def synth_zh(tmp_path_factory):
    out = tmp_path_factory.mktemp("synth_zh")
    assert main(["synth", "--phi0", "30", "--l2", "0.7", "--l3", "0.6", "--ground", "0.1",
                 "--no-plots", "--lang", "zh", "-o", str(out)]) == 0
    return out


@pytest.fixture(scope="module")
def torsion_six():
    from torsion.study import load, run_study

    return run_study(load(example_path("torsion_inline6.toml")))


def test_rule_catches_an_english_cell():
    assert latin_words("crank λ1", (), SYMBOLS | UNITS) == ["crank"]
    assert latin_words("θ 曲拐1（含轴系整体摆动），°", ("damper",), SYMBOLS | UNITS) == []
    assert latin_words("ω = 2467.2 rad/s（f = 392.7 Hz）", (), SYMBOLS | UNITS) == []
    assert latin_words("ω throw", ("damper",), SYMBOLS | UNITS) == ["throw"]
    assert latin_words("gas", ("damper",), SYMBOLS | UNITS) == ["gas"]


def test_chinese_synthesis_workbook_has_no_english_word(synth_zh):
    wb = load_workbook(synth_zh / "kkm-30_synthesis.xlsx")
    csv_names = set()
    for f in synth_zh.glob("*.csv"):
        csv_names.update(pd.read_csv(f, nrows=0).columns)
    assert not _english_cells(wb, csv_names), _english_cells(wb, csv_names)
    t1, mech = wb.worksheets
    rows = [[c.value for c in r] for r in t1.iter_rows(min_row=2, max_row=3)]
    assert rows == [["长度 λ1", "长度 λ2", "长度 λ3", "μmin, °"],
                    ["l1", "l2", "l3", "mu_min_deg"]]        # Chinese over the CSV names
    labels = {r[1].value: r[0].value for r in mech.iter_rows(min_row=3)}
    assert labels["l1"] == "曲柄 λ1" and labels["l3"] == "摇杆 λ3"
    assert labels["mu_min_deg"] == "最小传动角 μmin, °"
    assert [c.value for c in mech[2]] == ["参数", "CSV 列名", "数值"]
    # the chosen mechanism's values in the cells, against the CSV (λ2 = 0.7 in l2's row)
    values = {r[1].value: r[2].value for r in mech.iter_rows(min_row=3)}
    csv = pd.read_csv(synth_zh / "kkm-30_mechanism.csv").iloc[0]
    assert values["l2"] == 0.7 and values["l3"] == 0.6 and values["l1"] == csv["l1"]


def test_chinese_torsion_workbook_has_no_english_word(torsion_six):
    from torsion.report import build_workbook

    from torsion.report import FIXED_COLUMNS

    wb = build_workbook(torsion_six, "zh")
    given = {torsion_six.study.name, "damper", "flywheel"}      # the spec's own names
    # the CSV column names of the second header row: FIXED_COLUMNS, or with an underscore
    bad = _english_cells(wb, given | set(FIXED_COLUMNS))
    assert not bad, bad
    cells = {v for _, _, v in _strings(wb)}
    # the chain's own throws and the torque's parts are Chinese words, the spec's names stay
    for word in ("曲拐1", "曲拐6", "气体压力", "惯性力", "合成", "damper", "flywheel"):
        assert word in cells, word
    assert "M 曲拐1-曲拐2, N·m" in cells and "θ damper" in cells
    assert not any(v in ("gas", "inertia", "total", "throw1") for v in cells)


def test_russian_torsion_workbook_names_the_throws_in_russian(torsion_six):
    from torsion.report import build_workbook

    cells = {v for _, _, v in _strings(build_workbook(torsion_six, "ru"))}
    assert {"колено 1", "колено 6", "газовые силы", "силы инерции", "суммарный"} <= cells
    assert "M колено 1-колено 2, Н·м" in cells
    # English keeps the CSV's names: throw1 … and gas, inertia, total
    cells_en = {v for _, _, v in _strings(build_workbook(torsion_six, "en"))}
    assert {"throw1", "gas", "inertia", "total", "M throw1-throw2, N·m"} <= cells_en
    assert not any(CJK.search(v) or CYRILLIC.search(v) for v in cells_en)
