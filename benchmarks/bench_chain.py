"""Speed of the chain on a six-bar: the bundled crank-slotted-lever shaper
(examples/shaper.toml: crank + RPR + RRP) with masses, inertias, weight and a cutting
force, kinematics plus kinetostatics at 1,000,000 crank positions, on one core, beside the
four-bar through the same public API and beside pylinkage on the same six-bar.

    python benchmarks/bench_chain.py [--positions N] [--pylinkage-positions M] [--wall]

Times: best of several repeats of the CPU time of this process (``time.process_time``),
one thread (BLAS/OpenMP pinned to one); ``--wall`` times wall-clock instead.

* analyze (the issue's figure): the public ``linkage.analyze(spec,
  crank_angles_deg=..., course_tables=False)`` of the shaper example: check of the cycle,
  summary (extremes, K, μmin), the loads of the spec (the cutting force over its span of
  the working stroke), kinetostatics, and the two pandas DataFrames (fresh memory every
  call), chunk by chunk (``linkage.groups.CHUNK`` positions); also with the default
  ``course_tables=True`` (plus |v|, |a|, |a_cor|, |R|);
* the four-bar (the ratchet example) through ``linkage.analyze(..., course_tables=False)``
  in the same run: the ratio shaper/four-bar does not depend on the machine's load;
* chain, kinematics: :func:`linkage.chain.solve` (driver, RPR, RRP) chunk by chunk, every
  joint's and link's motion kept as arrays, no tables;
* chain, kinematics + forces: the same plus :func:`linkage.chain.kinetostatics` with the
  links' weight and inertia, a cutting force on the ram opposing its motion and a
  moment on the lever: every pair's reaction and the driving moment Mур;
* pylinkage (optional, ``pip install pylinkage``): the same shaper's kinematics
  (positions, velocities, accelerations of its joints) by ``Crank`` → ``FixedDyad`` (the
  lever's tip D on the line C→A) → ``RRPDyad`` (the ram's pin E on its guide):
  ``step_fast_with_kinematics`` and ``step_with_derivatives``, the faster one is the
  reference.  pylinkage computes no forces.  It runs on fewer positions and its time
  per position is extrapolated; its E is checked against ours.

Prints positions per second and the ratios, the load average at the start and the end,
and the target of issue #19 (a six-bar with forces through ``analyze(course_tables=False)``
≥ 2.5 M positions/s), marked met or not.  No assertions on time.
"""
from __future__ import annotations

import os

from timing import load_average, one_thread, timed

one_thread()

import argparse  # noqa: E402
import math  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402

#: Time on the wall clock (``--wall``) instead of the process's CPU clock.
WALL = False

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHAPER = os.path.join(ROOT, "examples", "shaper.toml")
FOURBAR = os.path.join(ROOT, "examples", "ratchet.toml")
OMEGA = 6.28                     # the shaper example's ω [rad/s] (checked in main)


def shaper():
    """The shaper example's mechanism (:class:`linkage.chain.Mechanism`)."""
    import linkage
    return linkage.load_spec(SHAPER).mechanism


def best_of(fn, repeat):
    """Best time of ``repeat`` calls (after one warm-up call), CPU or wall (:data:`WALL`). [s]"""
    t = timed(fn, repeat, warmup=True)
    return t.best if WALL else t.cpu


def run_chain(mech, phi, forces=True):
    """The chain chunk by chunk; returns the ram's pin E (x, y), (vx, vy), (ax, ay) and Mур."""
    from linkage import chain as ch
    from linkage.groups import CHUNK, Vec

    n = len(phi)
    E = np.empty((6, n))
    M = np.empty(n)
    for a in range(0, n, CHUNK):
        b = min(n, a + CHUNK)
        res = ch.solve(mech, phi[a:b], OMEGA, 0.0)   # (the example's ω)
        P = res.joints["E"]
        E[0, a:b], E[1, a:b] = P.z.x, P.z.y
        E[2, a:b], E[3, a:b] = P.v.x, P.v.y
        E[4, a:b], E[5, a:b] = P.a.x, P.a.y
        if forces:
            v = res.solutions[1].v                        # the ram's velocity on its guide
            cut = np.where(v > 0.0, -5000.0, 5000.0)      # the cutting force opposes it
            ram = res.links["ram"]
            frc = ch.kinetostatics(res, {"ram": [(Vec(cut * ram.e.x, cut * ram.e.y), P.z)]},
                                   {"lever": [25.0]}, 9.81)
            M[a:b] = frc.M_drive
    return E, M


def pylinkage_run(n_pl, phi, ours):
    try:
        import pylinkage
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import FixedDyad, RRPDyad
        from pylinkage.simulation import Linkage
    except ImportError:
        return None
    step = phi[1] - phi[0]
    mech = shaper()
    O0, C0 = mech.frame["O"], mech.frame["C"]
    OA = mech.driver.length
    CD = abs(mech.links["lever"].points["D"])
    rrp = mech.groups[1]
    DE, gp, ga = rrp.length, rrp.guide.point, rrp.guide.angle
    u = complex(math.cos(ga), math.sin(ga))

    def build():
        O = Ground(O0.real, O0.imag, name="O")
        C = Ground(C0.real, C0.imag, name="C")
        L1 = Ground((gp - u).real, (gp - u).imag, name="L1")
        L2 = Ground((gp + u).real, (gp + u).imag, name="L2")
        cr = Crank(anchor=O, radius=OA, angular_velocity=step, initial_angle=phi[0] - step,
                   name="A")
        D = FixedDyad(C, cr.output, distance=CD, angle=0.0, name="D")
        E = RRPDyad(D, L1, L2, distance=DE, x=float(ours[0, 0]), y=float(ours[1, 0]),
                    name="E")
        link = Linkage([O, C, L1, L2, cr, D, E], name="shaper")
        link.set_input_velocity(cr, omega=OMEGA, alpha=0.0)
        return link

    def fast():
        pos, vel, acc = build().step_fast_with_kinematics(iterations=n_pl)
        return pos[:, -1], vel[:, -1], acc[:, -1]

    def derivatives():
        out = list(build().step_with_derivatives(iterations=n_pl))
        return (np.array([p[-1] for p, _, _ in out], float),
                np.array([v[-1] for _, v, _ in out], float),
                np.array([a[-1] for _, _, a in out], float))

    results = []
    for label, fn in (("step_fast_with_kinematics", fast),
                      ("step_with_derivatives", derivatives)):
        try:
            t = best_of(fn, 2)
            got = fn()
        except (AttributeError, TypeError, ImportError, ValueError) as exc:
            print(f"  pylinkage {label}: not available ({type(exc).__name__}: {exc})")
            continue
        dev = [float(np.max(np.abs(np.asarray(g, float) - o[:n_pl])))
               for g, o in zip(got, (ours[0:2].T, ours[2:4].T, ours[4:6].T))]
        print(f"  pylinkage {label:26s} {n_pl:>9,d} positions  {n_pl / t / 1e6:8.3f} M/s   "
              f"max |ΔE| {dev[0]:.1e} m, |Δv_E| {dev[1]:.1e} m/s, |Δa_E| {dev[2]:.1e} m/s²")
        results.append((t / n_pl, label))
    if not results:
        return None
    t, label = min(results)
    return label, t, getattr(pylinkage, "__version__", "?")


def analyze_timings(n, repeat):
    """``linkage.analyze`` of the shaper (course_tables False and True) and of the four-bar
    (course_tables False) at ``n`` crank angles: best CPU times [s] and the shaper's result."""
    import linkage

    deg = 0.3 + (360.0 / n) * np.arange(n)
    six, four = linkage.load_spec(SHAPER), linkage.load_spec(FOURBAR)
    t_six = best_of(lambda: linkage.analyze(six, crank_angles_deg=deg, course_tables=False),
                    repeat)
    t_six_ct = best_of(lambda: linkage.analyze(six, crank_angles_deg=deg), repeat)
    t_four = best_of(lambda: linkage.analyze(four, crank_angles_deg=deg, course_tables=False),
                     repeat)
    return t_six, t_six_ct, t_four, linkage.analyze(six, crank_angles_deg=deg[:8],
                                                    course_tables=False)


def main():
    global WALL
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--positions", type=int, default=1_000_000)
    ap.add_argument("--pylinkage-positions", type=int, default=20_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--wall", action="store_true")
    args = ap.parse_args()
    WALL = args.wall
    from linkage import chain as ch
    from linkage.groups import CHUNK

    global OMEGA
    import linkage
    OMEGA = linkage.load_spec(SHAPER).omega
    mech = shaper()
    n = args.positions
    phi = 0.3 + (2 * math.pi / n) * np.arange(n)
    print(f"six-bar shaper {ch.structure_formula(mech, kinds=True)}, W = {ch.mobility(mech)[0]}, "
          f"{n:,d} positions, clock: {'wall' if args.wall else 'process CPU'}, best of "
          f"{args.repeat}; CHUNK = {CHUNK}; {os.cpu_count()} CPU(s), load average "
          f"{load_average()}")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        t_kin = best_of(lambda: run_chain(mech, phi, forces=False), args.repeat)
        t_all = best_of(lambda: run_chain(mech, phi, forces=True), args.repeat)
        t_an, t_an_ct, t_four, small = analyze_timings(n, args.repeat)
    E, M = run_chain(mech, phi)
    print(f"  analyze, course_tables=False {n:>9,d} positions  {n / t_an / 1e6:8.3f} M/s"
          f"   (target ≥ 2.5 M/s; {small.kinematics.shape[1]} + {small.forces.shape[1]} "
          "columns)")
    print(f"  analyze, course_tables=True  {n:>9,d} positions  {n / t_an_ct / 1e6:8.3f} M/s")
    print(f"  four-bar (ratchet) analyze, course_tables=False, same run  "
          f"{n / t_four / 1e6:8.3f} M/s; shaper/four-bar = {t_four / t_an:.3f}")
    print(f"  chain kinematics             {n:>9,d} positions  {n / t_kin / 1e6:8.3f} M/s")
    print(f"  chain kinematics + forces    {n:>9,d} positions  {n / t_all / 1e6:8.3f} M/s"
          f"   (no tables; Mур from {M.min():.1f} to {M.max():.1f} N·m)")
    print("\npylinkage, the same shaper's kinematics (joints only, no forces):")
    pl = pylinkage_run(min(args.pylinkage_positions, n), phi, E)
    if pl is None:
        print("  pylinkage is not installed (pip install pylinkage) or has no usable API")
    else:
        label, t_pl, version = pl
        print(f"  pylinkage {version} ({label}) {1 / t_pl / 1e6:.4f} M/s: chain kinematics "
              f"{t_pl * n / t_kin:,.0f} ×, kinematics + forces {t_pl * n / t_all:,.0f} ×, "
              f"analyze with forces and tables {t_pl * n / t_an:,.0f} × faster")
    print(f"\nload average at the end: {load_average()} (on {os.cpu_count()} CPU(s): a load above "
          "that shares the cores and the caches)")
    ok = n / t_an >= 2.5e6
    print(f"target (issue #19; kinematics + forces through the public API, one core, "
          f"{n:,d} positions):\n  six-bar analyze(course_tables=False) ≥ 2.5 M positions/s "
          f"{n / t_an / 1e6:13.2f} M/s  {'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
