"""Benchmarks of the machine-dynamics package and its commands.

    python benchmarks/bench_dynamics.py

Prints: the linkage reduced model (720 steps) and its steady motion; the exact flywheel
(brentq on the energy solution); the motor periodic state (solve_ivp shooting); the CLI
runs of the bundled examples (a fresh process each, imports included).  No assertions:
the figures go into the README.
"""
from __future__ import annotations

import sys
import tempfile

from timing import timed, timed_process


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
        t = timed(fn, repeat=5, number=3)
        b, m = t.best, t.median
        print(f"{name:<40} best {b * 1e3:8.2f} ms   median {m * 1e3:8.2f} ms")
    with tempfile.TemporaryDirectory() as d:
        for ex in ("flywheel_seed.toml", "press_dynamics.toml", "petrol_dynamics.toml"):
            t = timed_process([sys.executable, "-m", "crankdyn", "dynamics",
                               str(example_path(ex)), "-o", f"{d}/{ex}"], repeat=3)
            b, m = t.best, t.median
            print(f"crankdyn dynamics {ex:<22} best {b:6.2f} s   median {m:6.2f} s")
        t = timed_process([sys.executable, "-m", "crankdyn", "balance",
                           str(example_path("rotor_two_plane.toml")), "-o", f"{d}/rotor"],
                          repeat=3)
        b, m = t.best, t.median
        print(f"crankdyn balance rotor_two_plane.toml     best {b:6.2f} s   median {m:6.2f} s")


if __name__ == "__main__":
    main()
