"""``crankdyn linkage``: kinematics and kinetostatics of a crank-rocker or crank-slider.

Writes ``<name>_kinematics.csv``, ``<name>_forces.csv``, the workbook ``<name>.xlsx`` and
the plots ``<name>_<plot>.png`` (``<name>``: the mechanism's name as a file stem)
(plan of positions; over a full turn at 1°: ω and ε of links 3 and 4, the driving moment
Mур, the transmission angle).  All outputs are produced in a staging folder and moved
into place only when every one of them is complete.
"""
from __future__ import annotations

import sys

EXAMPLE = "ratchet.toml"

#: File stems of every plot ``crankdyn linkage`` may draw (linkage.plots.all_figures).
PLOTS = ("plan", "velocities", "accelerations", "driving_moment", "transmission_angle")


def add_parser(sub):
    p = sub.add_parser(
        "linkage", help="kinematics and kinetostatics of a crank-rocker or crank-slider",
        description="Kinematics and kinetostatics of a crank-rocker or crank-slider from a "
                    "TOML spec (see README): CSV tables, an Excel workbook and plots.")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("spec", nargs="?", help="the mechanism spec (TOML)")
    src.add_argument("--example", nargs="?", const=EXAMPLE, metavar="NAME",
                     help=f"use a bundled example spec (default {EXAMPLE})")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--step", type=float, default=1.0, metavar="DEG",
                   help="crank-angle step of the full-turn plots (default 1°)")
    p.add_argument("--no-plots", action="store_true", help="write the tables only")
    p.set_defaults(func=run)
    return p


def run(args) -> int:
    import warnings

    import linkage
    from crankbase.output import safe_name, save_figure, staged_output
    from linkage.analysis import SingularPositionWarning
    from crankbase.errors import SpecError
    from linkage.report import summary_lines, write_csvs, write_workbook
    from pandas import isna as pd_isna

    if args.example:
        from crankbase.resources import example_path
        spec_path = example_path(args.example if args.example.endswith(".toml")
                                 else args.example + ".toml")
    else:
        spec_path = args.spec
    if not (0 < args.step <= 30):
        raise SpecError([f"--step: got {args.step:g}; must be > 0 and <= 30 degrees"])
    spec = linkage.load_spec(spec_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SingularPositionWarning)
        result = linkage.analyze(spec)
    full = linkage.full_turn(spec, args.step) if not args.no_plots else None
    figures = {}
    if full is not None:
        from linkage.plots import all_figures
        figures = all_figures(result, full)
    from pathlib import Path

    name = safe_name(spec.name, "linkage")
    with staged_output(args.output, inputs=[spec_path]) as stage:
        write_csvs(result, stage)
        for csv in list(stage.iterdir()):        # every output named after the mechanism
            csv.rename(stage / f"{name}_{csv.name}")
        write_workbook(result, stage / f"{name}.xlsx")
        for stem, fig in figures.items():
            save_figure(fig, stage / f"{name}_{stem}", formats=("png",), dpi=120)
    # plots of this mechanism from an earlier run that this run did not draw are stale
    stale = [Path(args.output) / f"{name}_{p}.png" for p in PLOTS if p not in figures]
    for path in stale:
        if path.exists():
            path.unlink()
            print(f"crankdyn linkage: removed {path} (an earlier run's plot, not drawn now)",
                  file=sys.stderr)
    for w in caught:
        print(f"crankdyn linkage: warning: {w.message}", file=sys.stderr)
    statics = "; statics, ω = 0" if spec.omega == 0 else ""
    print(f"{spec.name} ({spec.kind}{statics}): {len(result.kinematics)} positions -> "
          f"{args.output}")
    for label, value, unit in summary_lines(result):
        v = f"{value:.4f}" if isinstance(value, float) else str(value)
        print(f"  {label}: {v} {unit}".rstrip())
    m = result.forces["M_drive_Nm"].abs()
    if m.notna().any():
        i = int(m.idxmax())
        pos = result.forces["position"].iat[i]
        where = "" if pd_isna(pos) else f"position {pos}, "
        print(f"  max |Mур| at the positions: {result.forces['M_drive_Nm'].iat[i]:.2f} N·m "
              f"({where}φ = {result.forces['phi_deg'].iat[i]:.2f}°)")
    return 0
