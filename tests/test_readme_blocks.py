"""Every ```python block of README.md runs as written (issue 23): each in a fresh
namespace, in a temporary folder that holds a copy of the bundled examples (the blocks
name them as ``examples/<file>``, the way they are used from the project folder), so a
block that uses a name it never defines or imports, or a call that no longer exists,
fails here."""
from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
BLOCKS = [(README.count("\n", 0, m.start()) + 2, m.group(1))
          for m in re.finditer(r"^```python\n(.*?)^```", README, re.S | re.M)]


def test_the_readme_has_its_python_blocks():
    assert len(BLOCKS) >= 7
    assert any("engine.load" in code for _, code in BLOCKS)
    assert any("synthesis as syn" in code for _, code in BLOCKS)


#: What a block prints and writes, beyond running: {a line of the block: (texts it
#: prints, files it writes)}.  The "Scripting a study" example writes the engine's report
#: into out/ and prints its summary (its words are the library's, its last line names
#: the files written).
PROMISES = {
    'files = engine.write_report(report, "out", lang="en")':
        (("whole engine: 4 cylinders inline",
          "petrol-vaz2106.xlsx, 22 plots (PNG, SVG) in out"),
         ("out/petrol-vaz2106_crankpins.csv",)),
    'report.write_plans(res, pps, "out/plans")':
        ((), tuple(f"out/plans/ratchet-drive_{f}" for f in (
            "plans.csv", "lever.csv", "student_table.csv", "plans_5.pdf", "plans_11.svg",
            "plans_11.png", "sheet.pdf", "sheet.png", "sheet.dxf"))),
    'write_report(report, "out/ratchet", lang="en")':
        (("wrote ratchet-drive_kinematics.csv", "ratchet-drive_sheet.dxf, 2 images (SVG) "
          "in out/ratchet"),
         tuple(f"out/ratchet/ratchet-drive_{f}" for f in (
             "lever.csv", "plans_5.pdf", "plans_11.svg", "sheet.pdf", "sheet.dxf"))),
}


#: A block holding one of these writes a whole report: its figures are not drawn.  The
#: engine's report (the petrol engine with its bearings, 22 plots); the ratchet's plans for
#: positions 5 and 11 with their drawing sheets (``plans.report.write_plans``, once called
#: directly and once through ``linkage.study.write_report``: PDF, SVG and PNG, ~2-3 s of
#: CPU each), rendered from the same inputs by tests/test_plans_output.py
#: (``crankdyn linkage --example --plans 5,11``).
UNRENDERED = ("engine.write_report(", 'report.write_plans(res, pps, "out/plans")',
              'write_report(report, "out/ratchet", lang="en")')


def test_every_promise_names_a_block():
    for marker in PROMISES:
        assert sum(marker in code for _, code in BLOCKS) == 1, marker
    for marker in UNRENDERED:
        assert sum(marker in code for _, code in BLOCKS) == 1, marker


@pytest.mark.parametrize("line, code", BLOCKS, ids=[f"line{n}" for n, _ in BLOCKS])
def test_readme_block_runs_as_written(line, code, tmp_path, monkeypatch, capsys, request):
    """A block that writes a whole report (:data:`UNRENDERED`: the petrol engine with
    its bearings, 22 plots; the ratchet's plans and drawing sheets) builds its figures
    but does not draw them (tests/conftest.py ``figures_rendered_only`` with no name:
    a drawing sheet saved into a ``PdfPages`` too): what the block promises is that its
    calls run, what it prints and which files it writes; the engine's figures are
    rendered by the CLI's tests (the session's shared reports, the bearings' in
    tests/test_engine_bearings_cli.py), the plans' by tests/test_plans_output.py.  Every
    other block draws what it saves."""
    if any(marker in code for marker in UNRENDERED):
        request.getfixturevalue("figures_rendered_only")()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    shutil.copytree(ROOT / "examples", tmp_path / "examples",
                    ignore=shutil.ignore_patterns("__pycache__", "*.py"))
    monkeypatch.chdir(tmp_path)
    before = set(plt.get_fignums())
    try:
        exec(compile(code, f"README.md:{line}", "exec"), {"__name__": "__readme__"})
    finally:
        for n in set(plt.get_fignums()) - before:
            plt.close(n)
    # a block that saves a file saves it where it says (the current folder)
    for saved in re.findall(r"savefig\(\"([^\"]+)\"\)", code):
        assert (tmp_path / saved).stat().st_size > 1000, saved
    printed = capsys.readouterr().out
    for marker, (texts, files) in PROMISES.items():
        if marker in code:
            for t in texts:
                assert t in printed, (t, printed)
            for f in files:
                assert (tmp_path / f).is_file(), f
