"""Speed of the linkage core: kinematics plus forces of a crank-rocker at 1,000,000 crank
positions, on one core, beside pylinkage.

    python benchmarks/bench_linkage.py [--positions N] [--pylinkage-positions M]

Times: best of several repeats of the CPU time of this process (``time.process_time``: on
a shared machine the wall time also counts the time other processes hold the core), one
thread (BLAS/OpenMP pinned to one); ``--wall`` times wall-clock instead:

* analyze: the public ``linkage.analyze(spec, crank_angles_deg=...)`` on the ratchet
  example (crank-rocker with masses, inertias, an extra point and a stroke- and
  span-limited resistance), including the extremes, the summary and the two pandas
  DataFrames (fresh memory every call): with ``course_tables=False`` (every kinematics
  and force column: the issue's "kinematics plus forces") and with the default (plus
  the course tables' magnitudes and inertia loads of :mod:`linkage.derived`);
* blocks: the same group routines of :mod:`linkage.groups` evaluated in chunks of
  ``linkage.analysis.CHUNK`` positions into preallocated column blocks (what ``analyze``
  runs, without the DataFrames and the extremes);
* the same for the bundled crank-slider (the press example);
* pylinkage (optional: ``pip install pylinkage``, the ``bench`` extra; skipped when it is
  not installed): the same four-bar and the same crank positions.  pylinkage computes
  kinematics only -- positions, velocities and accelerations of the joints A and B, by its
  own closed-form velocity/acceleration solvers while its solver steps the crank
  (``Linkage.step_with_derivatives``; ``step_fast_with_kinematics`` is timed too and the
  faster of the two is the reference) -- no link angles, no centres of mass, no forces.
  It runs on fewer positions (``--pylinkage-positions``) and its time per position is
  extrapolated to the full count.  Its B is checked against ours.

Prints a table of positions per second and the ratios, the load average at the start and
the end (on a shared machine a load above the number of cores shares the cores and their
caches: compare runs at similar loads), and the targets of issues #20 and #9 (four-bar
``analyze(course_tables=False)`` ≥ 5 M positions/s, ≥ 100 × pylinkage; the default
``analyze`` ≥ 2 M/s), each marked met or not.  No assertions on time.
"""
from __future__ import annotations

import os

from timing import cpu_model, load_average, one_thread, timed

one_thread()

import argparse  # noqa: E402
import math  # noqa: E402
import platform  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402


#: Time on the wall clock (``--wall``) instead of the process's CPU clock.
WALL = False


def best_of(fn, repeat):
    """Best time of ``repeat`` calls (after one warm-up call), CPU or wall (:data:`WALL`). [s]"""
    t = timed(fn, repeat, warmup=True)
    return t.best if WALL else t.cpu


def crank_angles(n, phi0=0.3):
    """``n`` equal crank steps over one turn from ``phi0`` [rad]."""
    return phi0 + (2 * math.pi / n) * np.arange(n)


def core_timings(example, n, repeat):
    """The group routines into column blocks, and ``analyze``, on one bundled example;
    returns (spec, phi, analyze result, {label: (positions, seconds)})."""
    import linkage
    from linkage import analysis as an
    from crankbase.resources import example_path

    spec = linkage.load_spec(example_path(example))
    mech = an.build_mechanism(spec)
    rot = 1 if spec.omega > 0 else -1
    ext = mech.extremes(rot, spec.working_stroke)
    phi = crank_angles(n)
    deg = np.degrees(phi)

    def blocks_runner(course_tables):
        tables = an._Tables(spec, mech, ext, course_tables, min(n, an.CHUNK))
        kb, fb = np.empty((len(tables.kcols), n)), np.empty((len(tables.fcols), n))
        return lambda: tables.fill(phi, kb, fb)

    def run_analyze(course_tables=True):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return linkage.analyze(spec, crank_angles_deg=deg, course_tables=course_tables)

    out = {"blocks-lean": (n, best_of(blocks_runner(False), repeat)),
           "blocks": (n, best_of(blocks_runner(True), repeat)),
           "analyze-lean": (n, best_of(lambda: run_analyze(False), repeat)),
           "analyze": (n, best_of(run_analyze, repeat))}
    res = run_analyze()
    return spec, phi, res, out


def pylinkage_timing(spec, n_pl, res_phi, res):
    """pylinkage on the crank-rocker of ``spec`` at the first ``n_pl`` of the crank angles
    ``res_phi`` (equal steps); returns (label, seconds per position, max |ΔB| [m],
    max |Δv_B| [m/s], max |Δa_B| [m/s²]) for the faster method, or None if not
    installed."""
    try:
        import pylinkage  # noqa: F401
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import RRRDyad
        from pylinkage.simulation import Linkage
    except ImportError:
        return None
    try:
        from pylinkage._numba_compat import HAS_NUMBA
    except ImportError:  # pragma: no cover - other pylinkage layouts
        HAS_NUMBA = None
    import linkage

    phi = res_phi[:n_pl]
    step = phi[1] - phi[0]
    gam = spec.ground_angle
    C = (spec.ground * math.cos(gam), spec.ground * math.sin(gam))
    # branch hint: our B one step before the first angle (pylinkage keeps the nearest one)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        k0 = linkage.analyze(spec, crank_angles_deg=[math.degrees(phi[0] - step)]).kinematics
    hint = (float(k0["B_x_m"][0]), float(k0["B_y_m"][0]))

    def build():
        O = Ground(0.0, 0.0, name="O")
        G = Ground(C[0], C[1], name="C")
        cr = Crank(anchor=O, radius=spec.crank, angular_velocity=step,
                   initial_angle=phi[0] - step, name="A")
        B = RRRDyad(cr.output, G, distance1=spec.coupler, distance2=spec.rocker,
                    x=hint[0], y=hint[1], name="B")
        mech = Linkage([O, G, cr, B], name="four-bar")
        mech.set_input_velocity(cr, omega=spec.omega, alpha=spec.epsilon)
        return mech

    def with_derivatives():
        mech = build()
        out = list(mech.step_with_derivatives(iterations=n_pl))
        pos = np.array([p[3] for p, _, _ in out], float)
        vel = np.array([v[3] for _, v, _ in out], float)
        acc = np.array([a[3] for _, _, a in out], float)
        return pos, vel, acc

    def fast_with_kinematics():
        mech = build()
        pos, vel, acc = mech.step_fast_with_kinematics(iterations=n_pl)
        return pos[:, 3], vel[:, 3], acc[:, 3]

    k = res.kinematics
    ours = [np.column_stack([k[f"B_{a}"].to_numpy()[:n_pl], k[f"B_{b}"].to_numpy()[:n_pl]])
            for a, b in (("x_m", "y_m"), ("vx_m_s", "vy_m_s"), ("ax_m_s2", "ay_m_s2"))]
    results = []
    for label, fn in (("step_with_derivatives", with_derivatives),
                      ("step_fast_with_kinematics", fast_with_kinematics)):
        try:
            t = best_of(fn, 2)
        except (AttributeError, TypeError, ImportError) as exc:  # another pylinkage API
            print(f"  pylinkage {label}: not available ({type(exc).__name__}: {exc})")
            continue
        got = fn()
        dev = [float(np.max(np.abs(g - o))) for g, o in zip(got, ours)]
        results.append((t / n_pl, label, dev))
    for t, label, dev in results:
        print(f"  pylinkage {label:26s} {n_pl:>9,d} positions  {1 / t / 1e6:8.3f} M/s   "
              f"max |ΔB| {dev[0]:.1e} m, |Δv_B| {dev[1]:.1e} m/s, |Δa_B| {dev[2]:.1e} m/s²")
    if not results:
        return None
    t, label, dev = min(results)
    return label, t, HAS_NUMBA, getattr(pylinkage, "__version__", "?")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--positions", type=int, default=1_000_000)
    ap.add_argument("--pylinkage-positions", type=int, default=20_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--wall", action="store_true", help="wall-clock time instead of CPU time")
    args = ap.parse_args(argv)
    global WALL
    WALL = args.wall
    n = args.positions

    from linkage import analysis as an
    import pandas as pd
    print(f"{cpu_model()}; Python {platform.python_version()}, numpy {np.__version__}, "
          f"pandas {pd.__version__}, "
          f"{os.cpu_count()} CPU(s) available, one thread used; CHUNK = {an.CHUNK}; "
          f"{'wall-clock' if args.wall else 'CPU'} time; load average "
          f"{load_average()}")
    rows = []
    spec, phi, res, rocker = core_timings("ratchet.toml", n, args.repeat)
    _, _, _, slider = core_timings("press.toml", n, args.repeat)
    for mech, timings in (("crank-rocker (ratchet)", rocker), ("crank-slider (press)", slider)):
        for key, what in (("analyze-lean", "analyze(course_tables=False), DataFrames"),
                          ("analyze", "analyze (default), DataFrames"),
                          ("blocks-lean", "group routines into blocks, kin. + forces"),
                          ("blocks", "group routines into blocks, + course tables")):
            npos, t = timings[key]
            rows.append((mech, what, npos, t))

    print("\npylinkage, same four-bar, same crank angles (kinematics of A and B only):")
    pl = pylinkage_timing(spec, min(args.pylinkage_positions, n), phi, res)
    if pl is None:
        print("  pylinkage is not installed (pip install pylinkage) or has no usable "
              "kinematics API: skipped")
    else:
        label, t_pl, has_numba, version = pl
        numba = {True: "with numba", False: "without numba (pure Python)",
                 None: "numba: unknown"}[has_numba]
        print(f"  pylinkage {version}, {numba}; reference: {label}, extrapolated to "
              f"{n:,d} positions: {t_pl * n:.1f} s")
        rows.append(("crank-rocker (ratchet)", f"pylinkage {label}", n, t_pl * n))

    print()
    head = f"{'mechanism':24s} {'what':46s} {'positions':>10s} {'best s':>8s} " \
           f"{'M pos/s':>8s}"
    if pl is not None:
        head += f" {'× pylinkage':>12s}"
    print(head)
    print("-" * len(head))
    for mech, what, npos, t in rows:
        line = f"{mech:24s} {what:46s} {npos:>10,d} {t:8.3f} {npos / t / 1e6:8.2f}"
        if pl is not None and mech.startswith("crank-rocker"):
            line += f" {(npos / t) * t_pl:12.0f}"
        print(line)
    print(f"\nload average at the end: {load_average()} "
          f"(on {os.cpu_count()} CPU(s): a load above that shares the cores and the caches)")
    lean = n / rocker["analyze-lean"][1] / 1e6
    print("targets (issues #20 and #9; kinematics + forces through the public API, one core, "
          f"{n:,d} positions):")
    for text, got, ok in (
            ("four-bar analyze(course_tables=False) ≥ 5 M positions/s", f"{lean:.2f} M/s",
             lean >= 5.0),
            ("four-bar analyze (default) ≥ 2 M positions/s",
             f"{n / rocker['analyze'][1] / 1e6:.2f} M/s", n / rocker["analyze"][1] >= 2e6),
            ("four-bar ≥ 100 × pylinkage (its kinematics only)",
             "pylinkage not installed" if pl is None
             else f"{lean * 1e6 * t_pl:.0f} ×", pl is not None and lean * 1e6 * t_pl >= 100)):
        print(f"  {text:58s} {got:>24s}  {'met' if ok else 'NOT met'}")


if __name__ == "__main__":
    main()
