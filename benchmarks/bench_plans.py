"""Time the graphical method: plans of all 12 positions, the layout of a sheet, the PDF
and DXF writers, one position's true-scale figure, and a whole `crankdyn linkage --plans`
run.  Prints the best of ``--repeat`` runs; asserts nothing.

    python benchmarks/bench_plans.py [--repeat 5]
"""
from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import linkage
import plans
from crankbase.resources import example_path
from plans import drawing, dxf
from timing import timed, timed_process


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    spec = example_path("ratchet.toml")
    res = linkage.analyze(spec)
    pps = plans.build_plans(res, "all")
    two = plans.build_plans(res, [5, 11])
    tmp = Path(tempfile.mkdtemp())
    sheets = drawing.layout_sheets(res, two)
    rows = [
        ("build_plans, 12 positions", lambda: plans.build_plans(res, "all")),
        ("layout of an A1 sheet, positions 5 and 11",
         lambda: drawing.layout_sheets(res, two)),
        ("sheet PDF (matplotlib)", lambda: drawing.sheet_figure(sheets[0]).savefig(
            tmp / "s.pdf")),
        ("sheet DXF (ezdxf)", lambda: dxf.write_dxf(sheets[0], tmp / "s.dxf")),
        ("one position: SVG + PDF + PNG", lambda: [
            f.savefig(tmp / n) for f in [drawing.position_figure(pps[4])]
            for n in ("p.svg", "p.pdf", "p.png")]),
    ]
    for name, fn in rows:
        print(f"{name}: {timed(fn, a.repeat).best * 1000:.0f} ms")
    cli = [sys.executable, "-m", "crankdyn.cli", "linkage", str(spec), "-o", str(tmp / "o"),
           "--plans", "5,11"]
    t = timed_process(cli, max(1, a.repeat // 2)).best
    print(f"crankdyn linkage ratchet --plans 5,11 (fresh process, all outputs): {t:.1f} s")


if __name__ == "__main__":
    main()
