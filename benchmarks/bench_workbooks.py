"""Benchmark of the workbook writing: each bundled example's workbook built and saved.

    python benchmarks/bench_workbooks.py [--repeat N] [--only WORD] [--out DIR]

The studies are computed first (not timed); then, per workbook and language (ru, en), the
time of building it from the computed report, finishing it (:func:`crankbase.workbook.finish`:
fonts, number formats, widths, rows, A4) and saving it (:func:`crankbase.workbook.save`):
what `crankdyn engine`, `linkage`, `dynamics` and `synth` spend on their workbook, and what
the web app and every test that writes a report pay.  The best of ``--repeat`` rounds (3)
on the process's CPU clock, and the wall clock's best; the load average before and after.
``--out DIR`` keeps the last round's workbooks (the same files the commands write, to
compare them part by part).  No assertions: the figures go into the README.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

from timing import cpu_model, load_average, one_thread, timed

one_thread()

ENGINES = ("petrol", "diesel", "v8", "six")
LINKAGES = ("ratchet", "press", "shaper_cn")
DYNAMICS = ("press", "shaper", "petrol")
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
    # the README's synthesis: crankdyn synth --phi0 30 --l2 0.9 --mu-min 40 --l1-step 0.01
    # --ground 0.5
    report = synthesis_study(30.0, l2=0.9, mu_min=40.0, l1_step=0.01, ground=0.5,
                             plots=False)
    for lang in LANGS:
        out.append(("synth kkm-30", lang, lambda p, r=report, lang=lang:
                    synthesis_workbook(p, r.table1, r.phi0, r.mechanism, lang=lang)))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", default="", help="only the workbooks whose name has WORD")
    ap.add_argument("--out", help="keep the workbooks in this folder")
    args = ap.parse_args(argv)
    print(f"{cpu_model()}; load average before: {load_average()}")
    todo = [c for c in cases() if args.only in c[0]]
    keep = Path(args.out) if args.out else None
    total = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for name, lang, write in todo:
            folder = keep or Path(tmp)
            folder.mkdir(parents=True, exist_ok=True)
            path = folder / f"{name.replace(' ', '_')}_{lang}.xlsx"
            t = timed(lambda: write(path), repeat=args.repeat, warmup=True)
            total += t.cpu
            size = os.path.getsize(path) / 1024
            print(f"{name:<20} {lang}  CPU best {t.cpu:6.3f} s   wall best {t.best:6.3f} s"
                  f"   {size:7.0f} KiB")
    print(f"{'total':<23} CPU {total:6.2f} s ({len(todo)} workbooks); "
          f"load average after: {load_average()}")
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    sys.exit(main())
