"""Time :func:`crankbase.output.save_figure` on the figures of the bundled examples.

Each example is run once through the CLI (in this process) with ``save_figure`` recorded:
every figure it saves, with its formats, dpi and crop.  Then each recorded figure is saved
again into a temporary folder ``--repeat`` times; the best CPU time (``time.process_time``)
per figure and per example is printed, with the load average.  Asserts nothing.

    python benchmarks/bench_figures.py [--repeat 3] [--only engine_v8 dyn_press ...]
    python benchmarks/bench_figures.py --profile dyn_press      # cProfile of the saves

The figures are the ones a report saves (engine petrol and V8, linkage ratchet and
shaper with their plans, dynamics press, the synthesis); the plans' A1 sheet, written by
``fig.savefig`` into a multi-page PDF, is timed by ``bench_plans.py``.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import os
import sys
import tempfile
import time
from pathlib import Path

from timing import cpu_model, load_average, one_thread

one_thread()

#: name → CLI arguments (without ``-o``)
EXAMPLES = {
    "engine_petrol": ["engine", "--example", "petrol", "--bearings"],
    "engine_v8": ["engine", "--example", "v8", "--lang", "en", "--bearings"],
    "linkage_ratchet": ["linkage", "--example", "ratchet", "--plans", "5,11"],
    "linkage_shaper": ["linkage", "--example", "shaper", "--plans", "2,5"],
    "dyn_press": ["dynamics", "--example", "press", "--lang", "en"],
    "synth": ["synth", "--l2", "0.8", "--mu-min", "40", "--ground", "0.5"],
}


def record(argv, out):
    """Run the CLI with ``argv`` into ``out``; return the saves it made: a list of
    (stem name, figure, keyword arguments of save_figure, rcParams) and the CPU time of the saves."""
    import crankbase.output as output
    import plans.report
    from crankdyn.cli import main

    real = output.save_figure
    saves, cpu = [], [0.0]

    def spy(fig, stem, formats=("png", "svg"), dpi=110, tight=False):
        import matplotlib

        rc = dict(matplotlib.rcParams)      # the run's settings (svg.fonttype …)
        c0 = time.process_time()
        paths = real(fig, stem, formats=formats, dpi=dpi, tight=tight)
        cpu[0] += time.process_time() - c0
        saves.append((Path(stem).name, fig, {"formats": tuple(formats), "dpi": dpi,
                                              "tight": tight}, rc))
        return paths

    with contextlib.ExitStack() as stack:
        stack.enter_context(contextlib.redirect_stdout(io.StringIO()))
        for mod in (output, plans.report):
            stack.callback(setattr, mod, "save_figure", mod.save_figure)
            mod.save_figure = spy
        rc = main([*argv, "-o", str(out)])
    if rc != 0:
        raise SystemExit(f"{' '.join(argv)}: exit code {rc}")
    return saves, cpu[0]


def time_saves(saves, folder, repeat):
    """Best CPU time [s] of saving each recorded figure again, in order."""
    import matplotlib

    from crankbase.output import save_figure

    best = []
    for name, fig, kw, rc in saves:
        times = []
        for _ in range(repeat):
            with matplotlib.rc_context(rc):
                c0 = time.process_time()
                save_figure(fig, folder / name, **kw)
                times.append(time.process_time() - c0)
        best.append(min(times))
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", nargs="*", default=None, help="names of EXAMPLES")
    ap.add_argument("--profile", default=None, help="one name: cProfile the saves")
    ap.add_argument("--verbose", action="store_true", help="a line per figure")
    a = ap.parse_args()
    os.environ.setdefault("MPLBACKEND", "Agg")
    names = [a.profile] if a.profile else (a.only or list(EXAMPLES))
    print(f"load average {load_average()}; {cpu_model()}; best of {a.repeat} "
          f"(CPU time, time.process_time)")
    total = 0.0
    for name in names:
        with tempfile.TemporaryDirectory() as tmp:
            tmp = Path(tmp)
            saves, first = record(EXAMPLES[name], tmp / "run")
            if a.profile:
                import cProfile
                import pstats

                prof = cProfile.Profile()
                prof.enable()
                time_saves(saves, tmp, a.repeat)
                prof.disable()
                pstats.Stats(prof).sort_stats(os.environ.get("BENCH_SORT", "cumulative")).print_stats(int(os.environ.get("BENCH_ROWS", "45")))
                continue
            best = time_saves(saves, tmp, a.repeat)
        files = sum(len(kw["formats"]) for _, _, kw, _ in saves)
        total += sum(best)
        print(f"{name:16s} {len(saves):3d} figures {files:3d} files: "
              f"save_figure {sum(best):6.2f} s (first save in the run {first:6.2f} s)")
        if a.verbose:
            for (stem, _, kw, _), t in zip(saves, best):
                print(f"    {stem:40s} {'+'.join(kw['formats']):12s} {t * 1000:7.0f} ms")
    if not a.profile:
        print(f"{'total':16s} save_figure {total:6.2f} s; load average {load_average()}")


if __name__ == "__main__":
    sys.exit(main())
