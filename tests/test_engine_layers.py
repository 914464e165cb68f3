"""The engine's layers in its folders (issue #19): physics at the top of ``engine``, the
figures in ``engine.plots``, the workbook and terminal words in ``engine.report``, the
bearing loads in ``engine.bearings``.  The old module paths keep working: each import
warns (DeprecationWarning naming the new path) and gives the very same module."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: old path -> new path (the README documented these; the modules that only the project's
#: own code imported moved without a forwarding module)
MOVED = {
    "engine.bearing_plots": "engine.plots.bearing",
    "engine.bearing_spec": "engine.bearings.analysis",
    "engine.train_bearings": "engine.bearings.train",
    "engine.summary": "engine.report.summary",
}


@pytest.mark.parametrize("old", sorted(MOVED))
def test_an_old_path_warns_and_is_the_new_module(old):
    # a fresh interpreter: the warning comes once, at the first import
    new = MOVED[old]
    code = f"""
import importlib, json, sys, warnings
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    old = importlib.import_module({old!r})
new = importlib.import_module({new!r})
pkg, leaf = {old!r}.rsplit(".", 1)
names = [n for n in getattr(new, "__all__", []) if getattr(old, n) is not getattr(new, n)]
print(json.dumps(dict(
    same=old is new, attr=getattr(sys.modules[pkg], leaf) is new, names=names,
    n_names=len(getattr(new, "__all__", [])),
    warnings=[(w.category.__name__, str(w.message)) for w in caught
              if {old!r} in str(w.message)])))
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, check=True).stdout
    got = json.loads(out)
    assert got["same"] and got["attr"], got
    assert got["n_names"] > 0 and got["names"] == [], got
    assert len(got["warnings"]) == 1, got
    category, message = got["warnings"][0]
    assert category == "DeprecationWarning"
    assert new in message, message


def test_the_project_imports_no_old_path():
    """Importing the whole engine (its study, plots, reports, bearings) touches none of
    the old paths: the project's own code uses the new ones (tests run with
    filterwarnings=error, so a stray old import would fail them anyway)."""
    code = ("import sys, engine, engine.study, engine.plots, engine.report, "
            "engine.bearings, engine.report.summary, engine.variants, engine.check\n"
            f"print(sorted(m for m in {sorted(MOVED)!r} if m in sys.modules))")
    out = subprocess.run([sys.executable, "-W", "error", "-c", code], capture_output=True,
                         text=True, cwd=ROOT, check=True).stdout
    assert out.strip() == "[]", out


def test_the_packages_reexport_the_documented_names():
    """The README's imports from the package level are the sub-modules' own objects."""
    import engine.bearings as B
    import engine.plots as P
    import engine.report as R
    from engine.bearings import analysis, loads, train, wear
    from engine.plots import bearing, cylinder, drawing, whole
    from engine.report import workbook

    assert (B.crank_pin_load, B.crankshaft_loads, B.Crankshaft, B.cylinder_alpha) == (
        loads.crank_pin_load, loads.crankshaft_loads, loads.Crankshaft, loads.cylinder_alpha)
    assert (B.bearing_analysis, B.Cylinder, B.engine_bearings, B.wear_diagram) == (
        analysis.bearing_analysis, train.Cylinder, train.engine_bearings, wear.wear_diagram)
    assert (P.plot_torque, P.plot_polar, P.figures, P.PLOT_NAMES) == (
        cylinder.plot_torque, cylinder.plot_polar, cylinder.figures, cylinder.PLOT_NAMES)
    assert (P.plot_total_torque, P.plot_moment_locus, P.train_figures) == (
        whole.plot_total_torque, whole.plot_moment_locus, whole.train_figures)
    assert (P.plot_pin_polar, P.plot_wear, P.bearing_figures, P.drawing_figures) == (
        bearing.plot_pin_polar, bearing.plot_wear, bearing.bearing_figures,
        drawing.drawing_figures)
    assert (R.build_workbook, R.save_workbook, R.KOLCHIN_SHEET) == (
        workbook.build_workbook, workbook.save_workbook, workbook.KOLCHIN_SHEET)
    for mod in (B, P, R):
        assert all(hasattr(mod, n) for n in mod.__all__), mod
    # the cylinder's and the whole engine's figures are distinct sets
    assert not set(P.PLOT_NAMES) & set(P.TRAIN_PLOT_NAMES)
