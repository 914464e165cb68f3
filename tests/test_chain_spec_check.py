"""``crankdyn check`` of a student's tables for a chain spec (six-link mechanisms, issue
#20): the chain's own column names (``x_E_m``, ``omega_lever_rad_s``, ``R_frame_crank_N``
…, :mod:`linkage.chain_analysis`) by position number.

* The tool's own tables pass: its workbook (the key row of every sheet) and a CSV cut
  from its CSVs.
* A cell altered by 10 % (a wrong lever speed, a wrong bearing reaction) is flagged at
  its position and column, the workbook's cell marked; a correct value within 1 % passes.
* The CLI: exit 0 when right, 1 when a value is wrong.
"""
from __future__ import annotations

import contextlib
import io

import numpy as np
import pandas as pd
import pytest

import linkage
from crankbase.checking import check_table, write_check
from crankbase.resources import example_path
from linkage.check import check_side
from linkage.study import run_study, write_report

SPEC = example_path("shaper.toml")
COLS = ["position", "x_E_m", "omega_lever_rad_s", "eps_lever_rad_s2", "s_ram_m",
        "R_frame_crank_N", "Rx_lever_rod_N", "M_drive_Nm"]


@pytest.fixture(scope="module")
def tables():
    res = linkage.analyze(SPEC)
    k, f = res.kinematics, res.forces
    both = k.merge(f[[c for c in f.columns if c == "position" or c not in k.columns]],
                   on="position")
    return both[COLS]


def test_student_csv_of_the_chains_columns(tables, tmp_path):
    assert {"omega_lever_rad_s", "R_frame_crank_N", "M_drive_Nm"} <= set(tables.columns)
    side = check_side(linkage.load_spec(SPEC))
    good = tmp_path / "good.csv"
    tables.to_csv(good, index=False)
    res = check_table(side, good)
    assert res.ok and res.table["column"].nunique() == len(tables.columns) - 1
    bad = tables.copy()
    bad.loc[4, "omega_lever_rad_s"] *= 1.10           # position 5: 10 % off
    bad.loc[7, "R_frame_crank_N"] *= 0.90             # position 8
    bad.loc[2, "M_drive_Nm"] *= 1.01                  # within the tolerance
    path = tmp_path / "bad.csv"
    bad.to_csv(path, index=False)
    res = check_table(side, path)
    wrong = res.table[~res.table["ok"]]
    assert sorted(zip(wrong["column"], wrong["position"])) == [
        ("R_frame_crank_N", 8), ("omega_lever_rad_s", 5)]
    # a student's rows in another order are matched by position
    path2 = tmp_path / "shuffled.csv"
    tables.iloc[::-1].to_csv(path2, index=False)
    assert check_table(side, path2).ok


def test_the_tools_workbook_passes_and_an_altered_cell_is_marked(tmp_path):
    from openpyxl import load_workbook

    rep = run_study(SPEC)
    write_report(rep, tmp_path / "rep", "en", formats=())
    book = tmp_path / "rep" / "shaper.xlsx"
    side = check_side(linkage.load_spec(SPEC))
    res = check_table(side, book)
    assert res.ok and res.table["column"].nunique() > 40
    wb = load_workbook(book)
    hit = None
    for ws in wb.worksheets:                  # the key row holds our column names
        for row in ws.iter_rows(max_row=12):
            for c in row:
                if c.value == "omega_lever_rad_s":
                    hit = (ws, c.column)
                    break
            if hit:
                break
        if hit:
            break
    assert hit is not None
    ws, col = hit
    cells = [c for c in next(ws.iter_cols(min_col=col, max_col=col))
             if isinstance(c.value, float)]
    assert len(cells) == 12
    target = max(cells, key=lambda c: abs(c.value))
    target.value = -target.value                       # a wrong sign
    student = tmp_path / "student.xlsx"
    wb.save(student)
    res = check_table(side, student)
    wrong = res.table[~res.table["ok"]]
    assert wrong["column"].tolist() == ["omega_lever_rad_s"]
    files = write_check(res, tmp_path / "out", "en")
    assert files.n_marked == 1 and files.marked.exists()


def test_cli_check_of_a_chain(tables, tmp_path):
    from crankdyn.cli import main

    good = tmp_path / "good.csv"
    tables.to_csv(good, index=False)
    bad = tables.copy()
    bad.loc[0, "x_E_m"] += 0.05
    badp = tmp_path / "bad.csv"
    bad.to_csv(badp, index=False)
    for path, rc in ((good, 0), (badp, 1)):
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            code = main(["check", str(SPEC), str(path), "-o", str(tmp_path / path.stem),
                         "--lang", "en"])
        assert code == rc, buf.getvalue()
        assert "x_E_m" in buf.getvalue()
    out = pd.read_csv(tmp_path / "bad" / "check.csv")
    row = out[(out["column"] == "x_E_m") & (out["position"] == 1)].iloc[0]
    assert not bool(row["ok"]) and row["deviation"] == pytest.approx(0.05, rel=1e-9)
    assert np.isclose(row["student"] - row["computed"], 0.05)
