"""Benchmark of the torsion physics on the bundled V8 (``diesel_kamaz740``, issue #21).

    python benchmarks/bench_torsion.py

The chain: damper, four throws (two cylinders each, :func:`torsion.engine_chain.throw_inertia`),
flywheel.  Times, each the best of several runs (wall and CPU, the load printed beside):
``natural_modes``; ``torque_harmonics`` of the gas, inertia and total torque of one
cylinder from its force table at 0.5° (24 orders: 0.5 … 12; and the whole
``cylinder_excitation`` with the force table); ``critical_speeds``; ``forced_response``
over 600–6000 rpm at 10 rpm steps (541 speeds × 24 orders, batched solves and the
peak in time); and all four together (target < 100 ms).  No assertions: the figures go
into the README.
"""
from __future__ import annotations

import os

import numpy as np

from timing import load_average, timed


def main():
    import engine
    from crankbase.resources import example_path
    from engine.train import layout
    from torsion.chain import damping_matrix, natural_modes
    from torsion.engine_chain import (cylinder_excitation, cylinder_throws,
                                      cylinder_torque_parts, throw_inertia)
    from torsion.harmonics import torque_harmonics
    from torsion.response import critical_speeds, forced_response

    study = engine.load(example_path("diesel_kamaz740.toml"))
    spec = study.spec
    lay = layout(spec, study.train)
    throws, phases = cylinder_throws(lay)
    throws = throws + 1                       # mass 0 is the damper
    J = [0.08] + [throw_inertia(spec, 0.012, 2)] * 4 + [1.2]
    k = [2.1e6, 1.8e6, 1.8e6, 1.8e6, 1.5e6]
    alpha, gas, inertia, total = cylinder_torque_parts(spec, step_deg=0.5)
    speeds = np.arange(600.0, 6001.0, 10.0)

    def modes():
        return natural_modes(J, k)

    def harmonics():
        return {name: torque_harmonics(alpha, m, 720.0, 12.0)
                for name, m in (("gas", gas), ("inertia", inertia), ("total", total))}

    m = modes()
    h = harmonics()
    C = damping_matrix(J, m, 0.02)

    def critical():
        return critical_speeds(m, throws, phases, h["total"].order, (600, 6000), 8, 720)

    def response():
        return forced_response(J, k, C, throws, phases, h["gas"], h["inertia"],
                               spec.speed_rpm, speeds)

    def everything():
        mm = natural_modes(J, k)
        hh = harmonics()
        cc = damping_matrix(J, mm, 0.02)
        critical_speeds(mm, throws, phases, hh["total"].order, (600, 6000), 8, 720)
        forced_response(J, k, cc, throws, phases, hh["gas"], hh["inertia"], spec.speed_rpm,
                        speeds)

    print(f"V8 chain of {len(J)} masses; {len(speeds)} speeds x {len(h['total'].order) - 1} "
          f"orders; load average {load_average()} on {os.cpu_count()} cores")
    for label, fn in (("natural_modes", modes),
                      ("torque_harmonics x3 (gas, inertia, total)", harmonics),
                      ("cylinder_excitation (force table + harmonics)",
                       lambda: cylinder_excitation(spec, orders_max=12)),
                      ("critical_speeds", critical),
                      ("forced_response 600-6000 rpm / 10 rpm", response),
                      ("modes + harmonics + critical + response (target < 100 ms)",
                       everything)):
        t = timed(fn, repeat=7, number=5)
        best, med, cpu = t.best, t.median, t.cpu
        print(f"{label:<60s} best {best * 1e3:7.2f} ms  median {med * 1e3:7.2f} ms  "
              f"cpu {cpu * 1e3:7.2f} ms")


if __name__ == "__main__":
    main()
