"""The teacher tools as library calls: engine.variants.run_variants (the batch behind
``crankdyn engine --variants``) and crankbase.checking.check_table / write_check (behind
``crankdyn check``), with their summaries in the report's language."""
from __future__ import annotations

import re

import pandas as pd
import pytest

import engine
from crankbase.checking import CheckFiles, check_table, write_check
from crankbase.errors import SpecError
from crankbase.resources import example_path
from engine.check import check_side
from engine.variants import run_variants

PETROL = example_path("petrol_vaz2106.toml")
CYRILLIC = re.compile("[\u0400-\u04ff]")


def test_run_variants_reports_each_row_and_the_summary(tmp_path, unrendered_figures):
    """(The default formats: the good variant's 13 figures built and saved as PNG and
    SVG, unrendered; tests/test_teacher_tools.py's three-variant run renders them.)"""
    from engine.plots import PLOT_NAMES, TRAIN_PLOT_NAMES

    table = tmp_path / "v.csv"
    table.write_text("variant,engine.bore_mm,engine.speed_rpm\nA,80,5000\nB,-5,5000\n")
    seen = []
    run = run_variants(PETROL, table, tmp_path / "out", "en",
                       progress=lambda o, total: seen.append((o.variant.variant, total)))
    assert unrendered_figures == ["png", "svg"] * len(PLOT_NAMES + TRAIN_PLOT_NAMES)
    assert sorted(seen) == [("A", 2), ("B", 2)]
    assert [o.ok for o in run.outcomes] == [True, False]
    bad = run.failures[0]
    assert bad.variant.row == 3
    assert bad.problems[0].startswith("row 3 (B): engine.bore_mm: got -5")
    assert not bad.kept_earlier and not (tmp_path / "out" / "B").exists()
    # the record is the variant's own result, computed directly
    study = engine.load(PETROL)
    from dataclasses import replace
    rec = run.records[0]
    direct = engine.analyze(replace(study.spec, bore=0.080, speed_rpm=5000.0, name="A"),
                            study.settings).summary
    assert rec["bore_mm"] == pytest.approx(80.0) and rec["M_mean_Nm"] == pytest.approx(
        direct.M_mean_Nm, rel=1e-12)
    assert pd.read_csv(run.summary_csv)["variant"].tolist() == ["A"]
    assert pd.read_csv(run.errors_csv)["row"].tolist() == [3]
    assert (tmp_path / "out" / "A" / "A_forces.csv").is_file()
    en, ru = run.summary_lines("en"), run.summary_lines("ru")
    assert en[0] == f"2 variants: 1 written (one folder each in {tmp_path / 'out'}), " \
                    "1 failed (row 3)"
    assert ru[0] == f"вариантов: 2; записано 1 (по папке на вариант в {tmp_path / 'out'}), " \
                    "с ошибками 1 (строка 3)"
    assert en[2] == ("each variant's folder holds its full spec <variant>.toml (for "
                     "crankdyn engine and crankdyn check)")
    assert run.outcomes[0].spec == tmp_path / "out" / "A" / "A.toml"
    assert run.outcomes[1].spec is None
    assert not CYRILLIC.search("\n".join(en))
    with pytest.raises(SpecError, match="^jobs: got 0"):
        run_variants(PETROL, table, tmp_path / "o2", jobs=0)


def _student_csv(path, wrong_T_at=None):
    study = engine.load(PETROL)
    t = engine.force_table(study.spec, [0.0, 30.0, 60.0, 90.0], settings=study.settings)
    t = t[["alpha_deg", "T_N", "K_N"]].copy()
    if wrong_T_at is not None:
        t.loc[t["alpha_deg"] == wrong_T_at, "T_N"] *= 1.3
    t["comment"] = "x"
    t.to_csv(path, index=False)
    return study


def test_check_table_flags_exactly_the_wrong_value_in_both_languages(tmp_path):
    path = tmp_path / "student.csv"
    study = _student_csv(path, wrong_T_at=60.0)
    result = check_table(check_side(study), path)
    assert result.n_wrong == 1 and not result.ok
    bad = result.table[~result.table["ok"]]
    assert bad[["alpha_deg", "column"]].values.tolist() == [[60.0, "T_N"]]
    row = bad.iloc[0]
    assert row["deviation"] == pytest.approx(0.3 * row["computed"], rel=1e-12)
    files = write_check(result, tmp_path / "o", "ru")
    assert isinstance(files, CheckFiles) and files.marked is None
    assert sorted(p.name for p in (tmp_path / "o").iterdir()
                  if not p.name.startswith(".")) == ["check.csv"]
    ru = result.summary_lines("ru", files)
    assert ru[0] == "student.csv: 4 строки, 2 столбца проверено (rtol = 0.02)"
    assert ru[1] == ("  допуск: |студент − расчёт| ≤ 0.2 % наибольшего по модулю значения "
                     "столбца + 2 % значения: значение у пика столбца может отличаться на "
                     "2.2 % от себя, на трети пика — на 2.6 %")
    assert ru[2].startswith("  T_N            НЕВЕРНО 1 из 4 (α = 60)")
    assert ru[3].startswith("  K_N            верно;  max |отклонение| = ")
    assert ru[4] == "  не проверены (неизвестные столбцы): comment"
    assert ru[5] == f"итог: неверных значений: 1; {tmp_path / 'o' / 'check.csv'}"
    en = result.summary_lines("en", files)
    assert en[0] == "student.csv: 4 rows, 2 columns checked (rtol = 0.02)"
    assert en[1] == ("  tolerance: |student − computed| ≤ 0.2 % of the column's largest "
                     "magnitude + 2 % of the value: a value at its column's peak may be off "
                     "by 2.2 % of itself, at a third of the peak by 2.6 %")
    assert en[-1] == f"verdict: 1 wrong value; {tmp_path / 'o' / 'check.csv'}"
    assert not CYRILLIC.search("\n".join(en))
    words = set(re.findall(r"[A-Za-z]{3,}", "\n".join(ru).replace(str(tmp_path), "")))
    assert words <= {"max", "student", "csv", "comment", "check", "rtol"}, words


def test_check_table_arguments_named_all_at_once(tmp_path):
    path = tmp_path / "s.csv"
    study = _student_csv(path)
    with pytest.raises(SpecError) as e:
        check_table(check_side(study), path, rtol=1.5, atol=float("nan"), mapping=["x"])
    assert [p.key for p in e.value.problems] == ["rtol", "atol", "mapping"]
    right = check_table(check_side(study), path, rtol=0.0, atol=1e-9)
    assert right.ok and right.n_wrong == 0
    assert right.summary_lines("en")[0].endswith("(rtol = 0)")
    assert right.summary_lines("en")[1] == ("  tolerance: |student − computed| ≤ 1e-09 + 0 % "
                                            "of the value")
