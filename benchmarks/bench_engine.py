"""Benchmarks of the engine force table and the ``crankdyn engine`` command.

    python benchmarks/bench_engine.py

Prints: ``force_table`` at a 0.1° step over 720° (7,201 rows; target well under 10 ms);
the whole CLI run with the workbook and all plots, per bundled example (target < 3 s, a
fresh process each time, imports included); ``crankdyn --help`` (target < 0.3 s).  No
assertions: the figures go into the README.
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time


def best_of(fn, repeat=7, number=20):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number)
    return min(times), statistics.median(times)


def wall(cmd, repeat=5):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return min(times), statistics.median(times)


def main():
    import engine
    from crankbase.resources import example_path

    fine = engine.TableSettings(step_deg=0.1)
    for name in ("petrol_vaz2106.toml", "diesel_d240.toml"):
        spec = engine.load_spec(example_path(name))
        rows = len(engine.force_table(spec, settings=fine))
        best, med = best_of(lambda: engine.force_table(spec, settings=fine))
        print(f"force_table {name:22s} 0.1° step, {rows} rows: best {best * 1e3:6.2f} ms, "
              f"median {med * 1e3:6.2f} ms  (target < 10 ms)")

    py = sys.executable
    with tempfile.TemporaryDirectory() as tmp:
        for ex, lang in (("petrol", "ru"), ("diesel", "en")):
            best, med = wall([py, "-m", "crankdyn", "engine", "--example", ex, "-o", tmp,
                              "--lang", lang], repeat=3)
            print(f"crankdyn engine --example {ex} --lang {lang} (CSV, xlsx, 6 plots × PNG+SVG): "
                  f"best {best:5.2f} s, median {med:5.2f} s  (target < 3 s)")
    best, med = wall([py, "-m", "crankdyn", "--help"], repeat=7)
    print(f"crankdyn --help: best {best * 1e3:5.0f} ms, median {med * 1e3:5.0f} ms  "
          f"(target < 300 ms)")


if __name__ == "__main__":
    main()
