"""Benchmark of the workbook writing: each bundled example's workbook built and saved.

    python benchmarks/bench_workbooks.py [--repeat N] [--only WORD] [--out DIR]

The studies are computed first (not timed); then, per workbook and language (ru, en), the
time of building it from the computed report, finishing it (:func:`crankbase.workbook.finish`:
fonts, number formats, widths, rows, A4) and saving it (:func:`crankbase.workbook.save`):
what `crankdyn engine`, `linkage`, `dynamics`, `synth` and `torsion` spend on their
workbook, and what the web app and every test that writes a report pay.  (`crankdyn
balance` writes no workbook.)  The best of ``--repeat`` rounds (3) on the process's CPU
clock, and the wall clock's best; of the best CPU round, the part in
:func:`crankbase.workbook.finish` and the part in openpyxl's ``Workbook.save`` (with
crankdyn's writer of number cells, :func:`crankbase.output.full_precision_xlsx`), the rest
being the build (the writer's own code, :mod:`crankbase.workbook`'s cells and headers, the
engine's template).  The load average before and after.  ``--out DIR`` keeps the last
round's workbooks (the same files the commands write, to compare them part by part).  No
assertions: the figures go into the README.
"""
from __future__ import annotations

import argparse
import functools
import os
import sys
import tempfile
import time
from pathlib import Path

from timing import cpu_model, load_average, one_thread

one_thread()

ENGINES = ("petrol", "diesel", "v8", "six")
LINKAGES = ("ratchet", "press", "shaper", "shaper_cn")
DYNAMICS = ("press", "shaper", "petrol")
TORSION = ("three-rotor", "six")
LANGS = ("ru", "en")


def cases():
    """[(name, lang, write(path))]: each workbook's build-and-save as one call."""
    import dynamics.study as dyn
    import engine
    from engine.study import report_workbook
    import linkage.study as lst
    from crankbase.resources import example_path
    from crankbase.workbook import save
    from crankdyn.cmd_dynamics import EXAMPLES as DYN_EXAMPLES
    from crankdyn.cmd_engine import EXAMPLES as ENGINE_EXAMPLES
    from crankdyn.cmd_linkage import EXAMPLES as LINKAGE_EXAMPLES
    from dynamics.report import build_workbook as dynamics_workbook
    from linkage.synthesis_report import write_workbook as synthesis_workbook
    from linkage.synthesis_study import run_study as synthesis_study

    out = []
    for ex in ENGINES:
        report = engine.run_study(engine.load(example_path(ENGINE_EXAMPLES[ex])))
        for lang in LANGS:
            out.append((f"engine {ex}", lang, lambda p, r=report, lang=lang:
                        save(report_workbook(r, lang), p)))
    for ex in LINKAGES:
        report = lst.run_study(example_path(LINKAGE_EXAMPLES[ex]), plots=False)
        if getattr(report, "chain", False):
            from linkage.chain_report import write_chain_workbook as write
        else:
            from linkage.report import write_workbook as write
        for lang in LANGS:
            out.append((f"linkage {ex}", lang, lambda p, r=report, lang=lang, w=write:
                        w(r.result, p, lang=lang)))
    for ex in DYNAMICS:
        report = dyn.run_study(example_path(DYN_EXAMPLES[ex]))
        for lang in LANGS:
            out.append((f"dynamics {ex}", lang, lambda p, r=report, lang=lang:
                        save(dynamics_workbook(r, lang, name=r.name), p)))
    from crankdyn.cmd_torsion import EXAMPLES as TORSION_EXAMPLES
    from torsion.report import build_workbook as torsion_workbook
    from torsion.study import load as torsion_load, run_study as torsion_study

    for ex in TORSION:
        report = torsion_study(torsion_load(example_path(TORSION_EXAMPLES[ex])))
        for lang in LANGS:
            out.append((f"torsion {ex}", lang, lambda p, r=report, lang=lang:
                        save(torsion_workbook(r, lang), p)))
    # the README's synthesis: crankdyn synth --phi0 30 --l2 0.9 --mu-min 40 --l1-step 0.01
    # --ground 0.5
    report = synthesis_study(30.0, l2=0.9, mu_min=40.0, l1_step=0.01, ground=0.5,
                             plots=False)
    for lang in LANGS:
        out.append(("synth kkm-30", lang, lambda p, r=report, lang=lang:
                    synthesis_workbook(p, r.table1, r.phi0, r.mechanism, lang=lang)))
    return out


#: CPU seconds spent in each phase of the current round: {"finish": s, "save": s}.
PHASES = {}


def _counted(owner, name, phase):
    """Wrap ``owner.name`` to add its CPU time to ``PHASES[phase]`` (not when nested)."""
    fn = getattr(owner, name)

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        if PHASES.get("_in"):
            return fn(*args, **kwargs)
        PHASES["_in"] = True
        t0 = time.process_time()
        try:
            return fn(*args, **kwargs)
        finally:
            PHASES[phase] = PHASES.get(phase, 0.0) + time.process_time() - t0
            PHASES["_in"] = False
    setattr(owner, name, wrapper)


def count_phases():
    """Count the CPU of :func:`crankbase.workbook.finish` (every writer imports it when
    called) and of openpyxl's ``Workbook.save``."""
    import crankbase.workbook
    from openpyxl.workbook.workbook import Workbook

    _counted(crankbase.workbook, "finish", "finish")
    _counted(Workbook, "save", "save")


def timed_phases(fn, repeat):
    """The best of ``repeat`` rounds of ``fn()`` (after a warm-up) on the CPU clock, with
    the phases of that round, and the best wall-clock round: (cpu, wall, phases)."""
    fn()
    best, wall = None, float("inf")
    for _ in range(repeat):
        PHASES.clear()
        t0, c0 = time.perf_counter(), time.process_time()
        fn()
        cpu, w = time.process_time() - c0, time.perf_counter() - t0
        wall = min(wall, w)
        if best is None or cpu < best[0]:
            best = (cpu, dict(PHASES))
    return best[0], wall, best[1]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", default="", help="only the workbooks whose name has WORD")
    ap.add_argument("--out", help="keep the workbooks in this folder")
    args = ap.parse_args(argv)
    print(f"{cpu_model()}; load average before: {load_average()}")
    todo = [c for c in cases() if args.only in c[0]]
    count_phases()
    keep = Path(args.out) if args.out else None
    total = {"cpu": 0.0, "build": 0.0, "finish": 0.0, "save": 0.0}
    print(f"{'workbook':<24}{'CPU best':>9}{'build':>8}{'finish':>8}{'save':>8}"
          f"{'wall best':>11}{'size':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        for name, lang, write in todo:
            folder = keep or Path(tmp)
            folder.mkdir(parents=True, exist_ok=True)
            path = folder / f"{name.replace(' ', '_')}_{lang}.xlsx"
            cpu, wall, phases = timed_phases(lambda: write(path), args.repeat)
            finish, save = phases.get("finish", 0.0), phases.get("save", 0.0)
            build = cpu - finish - save
            for k, v in (("cpu", cpu), ("build", build), ("finish", finish), ("save", save)):
                total[k] += v
            size = os.path.getsize(path) / 1024
            print(f"{name + ' ' + lang:<24}{cpu:8.3f}s{build:7.3f}s{finish:7.3f}s{save:7.3f}s"
                  f"{wall:10.3f}s{size:7.0f} KiB")
    print(f"{'total (' + str(len(todo)) + ' workbooks)':<24}{total['cpu']:8.3f}s"
          f"{total['build']:7.3f}s{total['finish']:7.3f}s{total['save']:7.3f}s")
    print(f"load average after: {load_average()}")
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    sys.exit(main())
