"""Benchmarks of the engine force table and the ``crankdyn engine`` command.

    python benchmarks/bench_engine.py

Prints: ``force_table`` at a 0.1° step over 720° (7,201 rows; target well under 10 ms);
the whole engine of the bundled V8 at a 0.1° step (``analyze_engine``: every cylinder's
table, the total torque, the balance and the flywheel; target < 50 ms); the whole CLI run
with the workbooks and all plots, per bundled example (target < 4 s, a fresh process each
time, imports included); ``crankdyn --help`` (target < 0.3 s).  No assertions: the
figures go into the README.
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time


def best_of(fn, repeat=7, number=20):
    """(best, median) wall time per call [s]; on a loaded machine see also cpu_of."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number)
    return min(times), statistics.median(times)


def cpu_of(fn, repeat=7, number=5):
    """Best CPU time per call (time.process_time) [s]: what the code costs even when
    other jobs share the cores."""
    times = []
    for _ in range(repeat):
        t0 = time.process_time()
        for _ in range(number):
            fn()
        times.append((time.process_time() - t0) / number)
    return min(times)


def wall(cmd, repeat=5):
    """(best, median) wall time and best CPU time (user + system) of a fresh process [s]."""
    import resource

    times, cpus = [], []
    for _ in range(repeat):
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
    return min(times), statistics.median(times), min(cpus)


def main():
    import engine
    from crankbase.resources import example_path

    fine = engine.TableSettings(step_deg=0.1)
    for name in ("petrol_vaz2106.toml", "diesel_d240.toml"):
        spec = engine.load_spec(example_path(name))
        rows = len(engine.force_table(spec, settings=fine))
        best, med = best_of(lambda: engine.force_table(spec, settings=fine))
        cpu = cpu_of(lambda: engine.force_table(spec, settings=fine))
        print(f"force_table {name:22s} 0.1° step, {rows} rows: best {best * 1e3:6.2f} ms, "
              f"median {med * 1e3:6.2f} ms, CPU {cpu * 1e3:6.2f} ms  (target < 10 ms)")

    study = engine.load(example_path("diesel_kamaz740.toml"))
    def whole():
        return engine.analyze_engine(study.spec, study.train, fine)
    best, med = best_of(whole, repeat=7, number=5)
    cpu = cpu_of(whole)
    print(f"analyze_engine V8 (diesel_kamaz740) 0.1° step, 8 cylinders, torque + balance + "
          f"flywheel: best {best * 1e3:6.1f} ms, median {med * 1e3:6.1f} ms, "
          f"CPU {cpu * 1e3:6.1f} ms  (target < 50 ms)")

    py = sys.executable
    with tempfile.TemporaryDirectory() as tmp:
        for ex, lang in (("petrol", "ru"), ("diesel", "en"), ("six", "en"), ("v8", "ru")):
            best, med, cpu = wall([py, "-m", "crankdyn", "engine", "--example", ex, "-o",
                                   tmp, "--lang", lang], repeat=3)
            print(f"crankdyn engine --example {ex} --lang {lang} (4 CSV, xlsx, 13 plots × "
                  f"PNG+SVG): best {best:5.2f} s, median {med:5.2f} s, CPU {cpu:5.2f} s  "
                  f"(target < 4 s)")
    best, med, _ = wall([py, "-m", "crankdyn", "--help"], repeat=7)
    print(f"crankdyn --help: best {best * 1e3:5.0f} ms, median {med * 1e3:5.0f} ms  "
          f"(target < 300 ms)")


if __name__ == "__main__":
    main()
