"""Benchmark of the bearing loads of a whole crankshaft (issue 11).

    python benchmarks/bench_bearings.py

A 90° V8 built from the petrol example's cylinder (cross-plane crank, throws at 0/90/270/180,
two rods per pin, full support with 5 main journals, a counterweight per throw) at a 0.1°
step over 720° (7,200 angles): the eight force tables, the four pin loads, the five
journal loads and torques, and the wear diagrams of the four pins and five journals.  No
assertions: the figures go into the README.
"""
from __future__ import annotations

import numpy as np

from timing import timed


def main():
    import engine
    from crankbase.resources import example_path
    from engine.bearings import (Crankshaft, crank_pin_load, crankshaft_loads,
                                 cylinder_alpha)
    from engine.bearings.wear import wear_diagram

    spec = engine.load_spec(example_path("petrol_vaz2106.toml"))
    theta = np.arange(0.0, 720.0, 0.1)
    tau = [0.0, 90.0, 270.0, 180.0]
    # bank A at −45°, bank B at +45° (turned in the direction of rotation): phase = γ − τ
    banks = (-45.0, 45.0)
    shaft = Crankshaft.full_support(tau, 0.1, 1.0, [(0.02, 180.0, k) for k in range(4)])

    def tables():
        return [[engine.force_table(spec, cylinder_alpha(theta, (g - t) % 720.0, 720.0))
                 for g in banks] for t in tau]

    def loads(tabs):
        K, T = zip(*(crank_pin_load([a.K_N, b.K_N], [a.T_N, b.T_N],
                                    [spec.m_rod_rot] * 2, spec.R, spec.omega)
                     for a, b in tabs))
        return crankshaft_loads(theta, shaft, np.array(K), np.array(T), spec.R,
                                spec.omega, 720.0)

    def wear(res):
        p, j = res.crankpins, res.journals
        return ([wear_diagram(f"pin {k}", theta, p[f"psi_{k}_deg"] + 180, p[f"R_{k}_N"])
                 for k in range(1, 5)]
                + [wear_diagram(f"journal {k}", theta, j[f"psi_{k}_deg"], j[f"R_{k}_N"])
                   for k in range(1, 6)])

    tabs = tables()
    res = loads(tabs)
    for name, fn in (("8 force tables (7,200 angles each)", tables),
                     ("pin and journal loads, journal torques", lambda: loads(tabs)),
                     ("9 wear diagrams (360 points)", lambda: wear(res))):
        t = timed(fn, repeat=5, number=5)
        best, med = t.best, t.median
        print(f"{name:45s} {best * 1e3:8.1f} ms (median {med * 1e3:.1f} ms)")
    t = timed(lambda: wear(loads(tables())), repeat=5, number=5)
    best, med = t.best, t.median
    print(f"{'all of it':45s} {best * 1e3:8.1f} ms (median {med * 1e3:.1f} ms)")


if __name__ == "__main__":
    main()
