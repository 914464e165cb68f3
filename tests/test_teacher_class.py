"""Issue 23, the teacher's workflow for variants: each variant's full spec beside its report
(loadable, giving its tables bit for bit, its pressure file copied beside it), a whole class
graded in one call against its variants, and default tolerances that catch a 3 % error of
any value above a third of its column's largest magnitude."""
from __future__ import annotations

import shutil
import tomllib

import numpy as np
import pandas as pd
import pytest
from openpyxl import load_workbook

import engine
from crankbase.checking import StudentTable, compare, match_variant
from crankbase.output import write_csv
from crankbase.resources import example_path
from crankbase.tolerances import CHECK_ATOL_OF_SCALE, CHECK_RTOL
from crankdyn.cli import main
from engine.check import computed_rows, known_columns
from engine.variants import check_class, run_variants
from xlsx_edit import altered_copy

PETROL = example_path("petrol_vaz2106.toml")
DIESEL = example_path("diesel_d240.toml")
RED = ("00FF7C80", "FFFF7C80")


@pytest.fixture(scope="module")
def petrol_variants(tmp_path_factory):
    """Two petrol variants written by the variants batch (reports and specs; without
    figures, ``formats=()``: the tests read the tables, workbooks and specs only)."""
    d = tmp_path_factory.mktemp("variants")
    table = d / "variants.csv"
    table.write_text("variant,engine.bore_mm,engine.speed_rpm,masses.rod_kg_m2\n"
                     "v01,80,5000,140\nv02,82.5,5600,165\n", encoding="utf-8")
    run = run_variants(PETROL, table, d / "out", "en", formats=())
    assert [o.ok for o in run.outcomes] == [True, True]
    return table, d / "out"


# ------------------------------------------------------------------ variant spec files
def test_variant_spec_reproduces_its_report(petrol_variants):
    table, out = petrol_variants
    for name, bore, speed in (("v01", 80, 5000), ("v02", 82.5, 5600)):
        path = out / name / f"{name}.toml"
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
        assert raw["engine"]["name"] == name and raw["engine"]["bore_mm"] == bore
        study = engine.load(path)
        assert study.spec.bore == pytest.approx(bore * 1e-3, rel=1e-15)
        assert study.spec.speed_rpm == speed
        # every table of the spec, written as the report writes it, is the variant's
        # CSV byte for byte (forces.csv, table2.csv, torque, balance ...)
        report = engine.run_study(study)
        again = out.parent / f"{name}_again"
        again.mkdir()
        assert "forces.csv" in report.tables
        for n, df in report.tables.items():
            write_csv(df, again / report.file_names[n])
            assert (again / report.file_names[n]).read_bytes() == \
                (out / name / report.file_names[n]).read_bytes(), n
    # the two variants differ (a spec that ignored its row would not)
    assert (out / "v01" / "v01_forces.csv").read_bytes() != \
        (out / "v02" / "v02_forces.csv").read_bytes()


def test_variant_spec_carries_its_pressure_file_step_and_form(tmp_path,
                                                             unrendered_figures):
    """(The variant's report is written without figures and the CLI's figures are
    saved unrendered: this test compares tables and specs.)"""
    table = tmp_path / "v.csv"
    table.write_text("variant,engine.speed_rpm\nd1,2000\n", encoding="utf-8")
    run = run_variants(DIESEL, table, tmp_path / "out", "en", step=15, form="kolchin",
                       formats=())
    folder = tmp_path / "out" / "d1"
    assert run.outcomes[0].spec == folder / "d1.toml"
    raw = tomllib.loads((folder / "d1.toml").read_text(encoding="utf-8"))
    assert raw["pressure"]["file"] == "diesel_d240_indicator.csv"       # relative
    assert raw["table"]["step_deg"] == 15 and raw["table"]["form"] == "kolchin"
    assert (folder / "diesel_d240_indicator.csv").read_bytes() == \
        (DIESEL.parent / "diesel_d240_indicator.csv").read_bytes()
    # moved elsewhere, the folder's spec still runs (`crankdyn engine d1.toml`) to the
    # variant's tables bit for bit
    moved = tmp_path / "elsewhere"
    shutil.copytree(folder, moved)
    assert main(["engine", str(moved / "d1.toml"), "-o", str(tmp_path / "again"),
                 "--lang", "en"]) == 0
    for kind in ("forces", "table2"):
        assert (tmp_path / "again" / f"d1_{kind}.csv").read_bytes() == \
            (folder / f"d1_{kind}.csv").read_bytes()
    forces = pd.read_csv(folder / "d1_forces.csv")
    assert np.diff(forces["alpha_deg"]).min() <= 15 and 15.0 in set(forces["alpha_deg"])


# ------------------------------------------------------------------ a class at once
def _alter(src, dst, alpha, column, factor):
    """A copy of a report workbook with one Table 2 cell multiplied by ``factor``,
    altered in the file (xlsx_edit.altered_copy): Table 2 (the second sheet) holds the
    report's forces.csv from row 6 in its order, its columns engine.report.TABLE2_KEYS
    (so the cell is found without parsing the workbook; were it another, the test's
    check would flag another cell)."""
    from openpyxl.utils import get_column_letter

    from engine.report import TABLE2_KEYS

    forces = pd.read_csv(src.with_name(f"{src.stem}_forces.csv"))
    i = forces.index[forces["alpha_deg"] == alpha]
    assert len(i) == 1
    coord = f"{get_column_letter(TABLE2_KEYS.index(column) + 1)}{6 + i[0]}"
    altered_copy(src, dst, {2: {coord: forces[column].iat[i[0]] * factor}})
    return coord


def test_a_class_of_four_in_one_call(petrol_variants, tmp_path, capsys):
    table, out = petrol_variants
    students = tmp_path / "students"
    students.mkdir()
    shutil.copy(out / "v01" / "v01.xlsx", students / "ivanov_v01.xlsx")     # right
    wb = load_workbook(out / "v02" / "v02.xlsx")                            # right, by
    ws = wb.create_sheet("title")                                          # its cell
    ws["A1"], ws["B1"] = "Вариант:", "v02"
    wb.save(students / "petrov.xlsx")
    coord = _alter(out / "v02" / "v02.xlsx", students / "sidorov_v02.xlsx",   # Sш +3 %
                   390.0, "S_N", 1.03)
    shutil.copy(out / "v01" / "v01.xlsx", students / "kuznetsov.xlsx")      # no variant
    (students / "notes.txt").write_text("not a table")                      # ignored

    done = check_class(PETROL, table, students, tmp_path / "graded", "en")
    expected = pd.DataFrame({
        "student": ["ivanov_v01.xlsx", "kuznetsov.xlsx", "petrov.xlsx", "sidorov_v02.xlsx"],
        "variant": ["v01", None, "v02", "v02"],
        "columns_wrong": [0, None, 0, 1], "cells_wrong": [0, None, 0, 1],
        "verdict": ["right", "no variant", "right", "WRONG"]})
    got = pd.read_csv(done.csv)
    assert list(got.columns) == ["student", "variant", "columns_wrong", "cells_wrong",
                                 "verdict", "detail"]
    pd.testing.assert_frame_equal(got.drop(columns="detail"), expected, check_dtype=False)
    assert got["detail"].tolist()[3] == "S_N (1)"
    assert "no variant name in the file name" in got["detail"].tolist()[1]
    assert not done.ok
    # the one wrong cell is the altered one, in the student's checked workbook
    check = pd.read_csv(tmp_path / "graded" / "sidorov_v02" / "check.csv")
    assert check.loc[~check["ok"], ["alpha_deg", "column"]].values.tolist() == \
        [[390.0, "S_N"]]
    marked = load_workbook(tmp_path / "graded" / "sidorov_v02" /
                           "sidorov_v02_checked.xlsx").worksheets[1]
    red = [c.coordinate for row in marked.iter_rows() for c in row
           if c.fill.fgColor.rgb in RED]
    assert red == [coord]
    assert (tmp_path / "graded" / "ivanov_v01" / "ivanov_v01_checked.xlsx").is_file()
    assert not (tmp_path / "graded" / "kuznetsov").exists()
    # the workbook holds the same verdict table, and states the tolerance
    ws = load_workbook(done.xlsx).worksheets[0]
    assert [ws.cell(r, 1).value for r in range(5, 9)] == expected["student"].tolist()
    assert [ws.cell(r, 5).value for r in range(5, 9)] == expected["verdict"].tolist()
    assert "2.2 % of itself" in ws["A2"].value

    # the same through the command line, in Russian; exit 1 (a student is wrong)
    assert main(["check", str(PETROL), "--variants", str(table), str(students),
                 "-o", str(tmp_path / "cli")]) == 1
    text = capsys.readouterr().out
    assert "sidorov_v02.xlsx" in text and "НЕВЕРНО" in text and "нет варианта" in text
    ru = pd.read_csv(tmp_path / "cli" / "class_check.csv")
    assert ru["verdict"].tolist() == ["верно", "нет варианта", "верно", "НЕВЕРНО"]


def test_class_lines_for_files_matched_to_none_or_two(petrol_variants, tmp_path):
    table, out = petrol_variants
    students = tmp_path / "s"
    students.mkdir()
    forces = pd.read_csv(out / "v01" / "v01_forces.csv")[["alpha_deg", "T_N", "S_N"]]
    forces.to_csv(students / "a_v01.csv", index=False)
    forces.to_csv(students / "b_v01_v02.csv", index=False)        # two variants
    forces.to_csv(students / "c_v02.csv", index=False)            # v01's values as v02
    (students / "d_v01.csv").write_text("x,y\n1,2\n")             # no alpha_deg column
    (students / "e_v02.xlsx").write_bytes(b"not a zip file")       # a damaged workbook
    done = check_class(PETROL, table, students, tmp_path / "o", "en")
    got = pd.read_csv(done.csv)
    assert got["verdict"].tolist() == ["right", "several variants", "WRONG", "not read",
                                       "not read"]
    assert got["cells_wrong"][2] > 0 and got["variant"].tolist()[4] == "v02"
    assert got["detail"][1] == "matches v01, v02: rename the file"
    assert "no column 'alpha_deg'" in got["detail"][3]


def test_variant_cell_of_a_workbook(tmp_path):
    from openpyxl import Workbook

    from crankbase.checking import variant_in_workbook

    def book(*cells):
        wb = Workbook()
        for coord, value in cells:
            wb.active[coord] = value
        wb.save(tmp_path / "s.xlsx")
        return tmp_path / "s.xlsx"

    assert variant_in_workbook(book(("B2", "Вариант"), ("D2", "v02"))) == "v02"
    assert variant_in_workbook(book(("A1", "variant: V7"))) == "V7"
    assert variant_in_workbook(book(("A1", "Вариант №"), ("B1", 12.0))) == "12"
    assert variant_in_workbook(book(("A1", "Variants"), ("B1", "v02"))) is None
    assert variant_in_workbook(book(("A1", "Фамилия"), ("B1", "v02"))) is None
    # the cell decides when the file name names no variant; both count when both do
    assert match_variant(book(("A1", "Вариант"), ("B1", "V02")), ["v01", "v02"]) == \
        (["v02"], "V02")
    wb = tmp_path / "ivanov_v01.xlsx"
    (tmp_path / "s.xlsx").rename(wb)
    assert match_variant(wb, ["v01", "v02"])[0] == ["v01", "v02"]


def test_matching_rule_whole_words():
    names = ["v1", "v10", "v02", "B"]
    assert match_variant("ivanov_v10.xlsx", names)[0] == ["v10"]
    assert match_variant("V02-petrov.csv", names)[0] == ["v02"]
    assert match_variant("a_v1 v02.csv", names)[0] == ["v1", "v02"]
    assert match_variant("ivanov_v021.csv", names)[0] == []
    assert match_variant("bob.csv", names)[0] == []              # 'b' inside a word
    assert match_variant("group b.csv", names)[0] == ["B"]


# ------------------------------------------------------------------ the 3 % rule
@pytest.mark.parametrize("example", ["petrol_vaz2106.toml", "diesel_d240.toml",
                                     "diesel_kamaz740.toml"])
def test_defaults_catch_three_percent_above_a_third_of_the_peak(example):
    """Every column a student's engine table may hold: a value 3 % off is wrong whenever
    the value is above a third of its column's largest magnitude (issue 23: Sш + 3 % at
    390° passed at the old atol of 0.5 %); 1.5 % off always passes."""
    study = engine.load(example_path(example))
    alpha = engine.force_table(study.spec, settings=study.settings)["alpha_deg"].to_numpy()
    computed = computed_rows(study.spec, study.settings, alpha)
    columns = known_columns()
    for factor, wrong_expected in ((1.03, True), (0.97, True), (1.015, False)):
        student = computed.copy()
        student[columns[1:]] = student[columns[1:]] * factor
        table = compare(StudentTable(student), computed, "alpha_deg")
        checked = 0
        for col in columns[1:]:
            x = computed[col].to_numpy(float)
            peak = np.nanmax(np.abs(x))
            ok = table.loc[table["column"] == col, "ok"].to_numpy()
            if wrong_expected:
                big = np.abs(x) > peak / 3
                assert not ok[big].any(), (col, alpha[big & ok])
                checked += int(big.sum())
            else:
                assert ok[np.isfinite(x)].all(), col
        assert not wrong_expected or checked > 10 * len(columns)
    # the rule stated: 2.2 % at the peak, 2.6 % at a third of it
    assert CHECK_RTOL + CHECK_ATOL_OF_SCALE == pytest.approx(0.022)
    assert CHECK_RTOL + 3 * CHECK_ATOL_OF_SCALE == pytest.approx(0.026)
