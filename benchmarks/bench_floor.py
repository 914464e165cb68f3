"""Where the time of ``linkage.analyze(..., course_tables=False)`` goes at 1,000,000
positions, one core: the four-bar (ratchet example) and the six-bar (shaper example).

    python benchmarks/bench_floor.py [--positions N]

Best of 5 CPU times (``time.process_time``, after a warm-up call), one thread.  Parts:

* ``analyze``: the public call (fresh result memory each call, as a caller gets it);
* fresh column blocks: :func:`linkage.groups.column_block` for both tables (the kernel maps
  and zeroes every page of a new block: a cost of fresh memory, proportional to
  columns × positions, that no arithmetic change removes);
* stores alone: a constant written into every row of reused, mapped blocks chunk by
  chunk (``linkage.groups.CHUNK``) -- the memory traffic of writing the tables once,
  whatever computes the values;
* the four-bar's group routines into reused blocks (``linkage.analysis._Tables.fill``,
  what ``analyze`` runs between the two above), the six-bar's chain (solve, loads,
  kinetostatics) chunk by chunk without tables;
* the fixed costs (do not grow with N): ``analyze`` at 2 positions (check of the cycle,
  extremes, summary), the angle argument's check and conversion, the DataFrames.

The floor of a call with fresh result memory is about fresh blocks + routines into reused
blocks; the stores are part of the routines' time.  No assertions on time.
"""
from __future__ import annotations

from timing import load_average, one_thread, timed

one_thread()

import argparse  # noqa: E402
import math  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402


def best(fn):
    """Best CPU time of 5 calls after a warm-up call. [s]"""
    return timed(fn, 5, warmup=True).cpu


def stores(blocks, n, chunk):
    """A function that writes 1.0 into every row of ``blocks``, chunk by chunk."""
    def run():
        for a in range(0, n, chunk):
            b = min(n, a + chunk)
            for block in blocks:
                for row in block:
                    row[a:b] = 1.0
    return run


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--positions", type=int, default=1_000_000)
    n = p.parse_args(argv).positions

    import pandas as pd

    import linkage
    from crankbase.resources import example_path
    from crankbase.validation import angles_argument
    from linkage import analysis as an
    from linkage import chain_analysis as ca
    from linkage import groups as g

    warnings.simplefilter("ignore")
    phi = 0.3 + (2 * math.pi / n) * np.arange(n)
    deg = np.degrees(phi)
    print(f"load average at the start: {load_average()}; {n:,} positions, "
          f"CHUNK = {g.CHUNK}, best of 5 CPU")

    spec = linkage.load_spec(example_path("ratchet.toml"))
    mech = an.build_mechanism(spec)
    ext = mech.extremes(1 if spec.omega > 0 else -1, spec.working_stroke)
    tables = an._Tables(spec, mech, ext, False, min(n, g.CHUNK))
    nk, nf = len(tables.kcols), len(tables.fcols)
    kb, fb = np.zeros((nk, n)), np.zeros((nf, n))

    def frames():
        kin = pd.DataFrame(kb.T, columns=tables.kcols, copy=False)
        frc = pd.DataFrame(fb.T, columns=tables.fcols, copy=False)
        pos = pd.Series(pd.arrays.IntegerArray(np.zeros(n, np.int64), np.ones(n, bool)),
                        index=kin.index, copy=False)
        kin.insert(0, "position", pos)
        frc.insert(0, "position", pos)

    rows = [
        ("analyze(course_tables=False)",
         best(lambda: linkage.analyze(spec, crank_angles_deg=deg, course_tables=False))),
        (f"fresh column blocks ({(nk + nf) * 8 * n / 1e6:.0f} MB)",
         best(lambda: (g.column_block(nk, n), g.column_block(nf, n)))),
        ("group routines into reused blocks", best(lambda: tables.fill(phi, kb, fb))),
        ("  of which at least: stores alone", best(stores((kb, fb), n, g.CHUNK))),
        ("fixed: analyze at 2 positions",
         best(lambda: linkage.analyze(spec, crank_angles_deg=deg[:2], course_tables=False))),
        ("angles checked and converted",
         best(lambda: angles_argument(deg, "a", copy=False) * an._RAD)),
        ("DataFrames and position column", best(frames)),
    ]
    report(f"four-bar (ratchet), {nk} + {nf} columns", rows, n)

    spec = linkage.load_spec(example_path("shaper.toml"))
    res = linkage.analyze(spec, crank_angles_deg=deg[:10], course_tables=False)
    nk, nf = res.kinematics.shape[1] - 1, res.forces.shape[1] - 1
    kb, fb = np.zeros((nk, n)), np.zeros((nf, n))

    def chain_only():
        for a in range(0, n, g.CHUNK):
            ca._solve_positions(spec, res.summary, phi[a:min(n, a + g.CHUNK)])

    rows = [
        ("analyze(course_tables=False)",
         best(lambda: linkage.analyze(spec, crank_angles_deg=deg, course_tables=False))),
        (f"fresh column blocks ({(nk + nf) * 8 * n / 1e6:.0f} MB)",
         best(lambda: (g.column_block(nk, n), g.column_block(nf, n)))),
        ("stores alone (reused blocks)", best(stores((kb, fb), n, g.CHUNK))),
        ("chain solve + loads + kinetostatics, no tables", best(chain_only)),
        ("fixed: analyze at 2 positions",
         best(lambda: linkage.analyze(spec, crank_angles_deg=deg[:2], course_tables=False))),
    ]
    report(f"six-bar (shaper), {nk} + {nf} columns", rows, n)
    print(f"load average at the end: {load_average()}")


def report(title, rows, n):
    print(title)
    for label, t in rows:
        print(f"  {label:50s} {t * 1e3:8.1f} ms  {n / t / 1e6:8.2f} M pos/s")


if __name__ == "__main__":
    main()
