"""Benchmarks of the machine-dynamics package and its commands.

    python benchmarks/bench_dynamics.py

Prints: the linkage reduced model (720 steps) and its steady motion; the exact flywheel
(brentq on the energy solution); the motor periodic state (solve_ivp shooting); the CLI
runs of the bundled examples (a fresh process each, imports included).  No assertions:
the figures go into the README.
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time


def best_of(fn, repeat=5, number=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number)
    return min(times), statistics.median(times)


def wall(cmd, repeat=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return min(times), statistics.median(times)


def main():
    import linkage
    from crankbase.resources import example_path
    from dynamics import (Motor, balance_rotor, linkage_model, motor_steady_motion,
                          size_flywheel, steady_motion)

    spec = linkage.load_spec(example_path("press.toml"))
    model = linkage_model(spec)
    rows = [
        ("linkage_model(press, 720 steps)", lambda: linkage_model(spec)),
        ("steady_motion(press, J_F = 70)", lambda: steady_motion(model, J_flywheel=70.0)),
        ("size_flywheel(press, delta = 0.03)", lambda: size_flywheel(model, 0.03)),
        ("motor_steady_motion(press, J_F = 70)",
         lambda: motor_steady_motion(model, Motor(1500.0, 11.0), J_flywheel=70.0)),
        ("balance_rotor(2 masses, 2 planes)",
         lambda: balance_rotor([90, 600], [270, 45], [100, 420], [0, 300])),
    ]
    for name, fn in rows:
        b, m = best_of(fn)
        print(f"{name:<40} best {b * 1e3:8.2f} ms   median {m * 1e3:8.2f} ms")
    with tempfile.TemporaryDirectory() as d:
        for ex in ("flywheel_seed.toml", "press_dynamics.toml", "petrol_dynamics.toml"):
            b, m = wall([sys.executable, "-m", "crankdyn", "dynamics",
                         str(example_path(ex)), "-o", f"{d}/{ex}"])
            print(f"crankdyn dynamics {ex:<22} best {b:6.2f} s   median {m:6.2f} s")
        b, m = wall([sys.executable, "-m", "crankdyn", "balance",
                     str(example_path("rotor_two_plane.toml")), "-o", f"{d}/rotor"])
        print(f"crankdyn balance rotor_two_plane.toml     best {b:6.2f} s   median {m:6.2f} s")


if __name__ == "__main__":
    main()
