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

import sys
import tempfile

from timing import timed, timed_process


def main():
    import engine
    from crankbase.resources import example_path

    fine = engine.TableSettings(step_deg=0.1)
    for name in ("petrol_vaz2106.toml", "diesel_d240.toml"):
        spec = engine.load_spec(example_path(name))
        rows = len(engine.force_table(spec, settings=fine))
        t = timed(lambda: engine.force_table(spec, settings=fine), repeat=7, number=20)
        best, med, cpu = t.best, t.median, t.cpu
        print(f"force_table {name:22s} 0.1° step, {rows} rows: best {best * 1e3:6.2f} ms, "
              f"median {med * 1e3:6.2f} ms, CPU {cpu * 1e3:6.2f} ms  (target < 10 ms)")

    study = engine.load(example_path("diesel_kamaz740.toml"))
    def whole():
        return engine.analyze_engine(study.spec, study.train, fine)
    t = timed(whole, repeat=7, number=5)
    best, med, cpu = t.best, t.median, t.cpu
    print(f"analyze_engine V8 (diesel_kamaz740) 0.1° step, 8 cylinders, torque + balance + "
          f"flywheel: best {best * 1e3:6.1f} ms, median {med * 1e3:6.1f} ms, "
          f"CPU {cpu * 1e3:6.1f} ms  (target < 50 ms)")

    py = sys.executable
    with tempfile.TemporaryDirectory() as tmp:
        for ex, lang in (("petrol", "ru"), ("diesel", "en"), ("six", "en"), ("v8", "ru")):
            t = timed_process([py, "-m", "crankdyn", "engine", "--example", ex, "-o",
                               tmp, "--lang", lang], repeat=3)
            best, med, cpu = t.best, t.median, t.cpu
            print(f"crankdyn engine --example {ex} --lang {lang} (4 CSV, xlsx, 13 plots × "
                  f"PNG+SVG): best {best:5.2f} s, median {med:5.2f} s, CPU {cpu:5.2f} s  "
                  f"(target < 4 s)")
    t = timed_process([py, "-m", "crankdyn", "--help"], repeat=7)
    best, med = t.best, t.median
    print(f"crankdyn --help: best {best * 1e3:5.0f} ms, median {med * 1e3:5.0f} ms  "
          f"(target < 300 ms)")


if __name__ == "__main__":
    main()
