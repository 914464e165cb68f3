"""``crankdyn linkage``: kinematics and kinetostatics of a crank-rocker or crank-slider.

Writes ``<name>_kinematics.csv``, ``<name>_forces.csv``, the workbook ``<name>.xlsx`` and
the plots ``<name>_<plot>.png`` (``<name>``: the mechanism's name as a file stem)
(plan of positions; over a full turn at 1°: ω and ε of links 3 and 4, the driving moment
Mур, the transmission angle); with ``--plans`` the graphical method's files, named the
same way (``<name>_plans.csv``, ``<name>_sheet.pdf`` …, see :mod:`plans.report`).  All
outputs are produced in a staging folder and moved into place only when every one of them
is complete; the reports of other mechanisms in the folder stay.

``--lang ru|en`` (default ru) chooses the language of the workbook (sheet titles, labels,
units, symbols: :mod:`linkage.report`), the plots, the plan drawings and the terminal
summary; the CSV files, the workbook's numbers and its CSV-name header row are the same
in both.
"""
from __future__ import annotations

import sys

#: Bundled examples by short name (``--example NAME``; a file stem works too).
EXAMPLES = {"ratchet": "ratchet.toml", "press": "press.toml"}

#: File stems of every plot ``crankdyn linkage`` may draw (linkage.plots.all_figures).
PLOTS = ("plan", "velocities", "accelerations", "driving_moment", "transmission_angle")


def add_parser(sub):
    p = sub.add_parser(
        "linkage", help="kinematics and kinetostatics of a crank-rocker or crank-slider",
        description="Kinematics and kinetostatics of a crank-rocker or crank-slider from a "
                    "TOML spec (see README): CSV tables, an Excel workbook and plots.")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("spec", nargs="?", help="the mechanism spec (TOML)")
    src.add_argument("--example", nargs="?", const="ratchet", metavar="NAME",
                     help="run a bundled example instead of a spec: "
                          + ", ".join(EXAMPLES) + " (default ratchet: the ratchet drive "
                          "of the course project; press: a crank-slider press)")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--step", type=float, default=1.0, metavar="DEG",
                   help="crank-angle step of the full-turn plots (default 1°)")
    p.add_argument("--no-plots", action="store_true", help="write the tables only")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="language of every output: the workbook (sheet titles, labels, "
                        "units, symbols), the plots, the plan drawings and this terminal "
                        "summary; ru (the Russian textbook's symbols Mур, Mпс, Fпс and "
                        "units Н·м, м/с, default) or en (English symbols Mb, Mr, Fr, no "
                        "Cyrillic). The CSV files are the same in both")
    g = p.add_argument_group(
        "graphical method (velocity and acceleration plans, force polygons, Zhukovsky lever)")
    g.add_argument("--plans", metavar="LIST",
                   help="position numbers, e.g. 5,11, or 'all': <name>_plans_<pos>.svg/.pdf/"
                        ".png, <name>_plans.csv, _lever.csv, _lever_forces.csv, "
                        "_student_table.csv, _sheet.pdf, _sheet.dxf")
    g.add_argument("--sheet", default="A1", metavar="A1|A3",
                   help="drawing sheet size, landscape (default A1)")
    g.add_argument("--measured", metavar="CSV",
                   help="a student's measured segments (position, segment, length_mm or "
                        "value): writes <name>_plan_errors.csv, the error of the plan method "
                        "in %%")
    g.add_argument("--mu-v", type=float, metavar="MU",
                   help="velocity plan scale, (m/s)/mm (default: round, pa 100-150 mm)")
    g.add_argument("--mu-a", type=float, metavar="MU",
                   help="acceleration plan scale, (m/s²)/mm (default: round, πa 100-150 mm)")
    g.add_argument("--mu-f", type=float, metavar="MU",
                   help="force polygon scale, N/mm (default: round, largest force 100-150 mm)")
    g.add_argument("--mu-lever", type=float, metavar="MU",
                   help="force scale of the Zhukovsky lever, N/mm (default: round, largest "
                        "force 50-75 mm)")
    p.set_defaults(func=run)
    return p


def _plan_options(args):
    """Check the plan options; return (positions, scales).  One problem per line."""
    from crankbase.errors import SpecError

    problems = []
    text = args.plans.strip()
    positions = "all" if text.lower() == "all" else []
    if positions != "all":
        for part in text.split(","):
            part = part.strip()
            if not part.isdigit() or int(part) < 1:
                problems.append(f"--plans: got {part!r}; give position numbers >= 1 "
                                "separated by commas (e.g. 5,11) or 'all'")
            elif int(part) not in positions:
                positions.append(int(part))
    if args.sheet not in ("A1", "A3"):
        problems.append(f"--sheet: got {args.sheet!r}; valid: A1, A3")
    if args.lang not in ("ru", "en"):
        problems.append(f"--lang: got {args.lang!r}; valid: ru, en")
    scales = {}
    for opt, kinds, value in (("--mu-v", ("velocity",), args.mu_v),
                              ("--mu-a", ("acceleration",), args.mu_a),
                              ("--mu-f", ("force_dyad", "force_crank"), args.mu_f),
                              ("--mu-lever", ("lever",), args.mu_lever)):
        if value is None:
            continue
        if not (value > 0 and value < float("inf")):
            problems.append(f"{opt}: got {value:g}; must be a positive number")
        for k in kinds:
            scales[k] = value
    if problems:
        raise SpecError(problems)
    return positions, scales


#: The library's argument names in its problems → this command's options.
OPTIONS = {"positions": "--plans", "size": "--sheet"}


def run(args) -> int:
    from crankbase.errors import SpecError

    try:
        return _run(args)
    except SpecError as exc:
        raise exc.renamed(OPTIONS) from None


def _run(args) -> int:
    import warnings

    import linkage
    from crankbase.output import safe_name, save_figure, staged_output
    from linkage.analysis import SingularPositionWarning
    from crankbase.errors import SpecError
    from linkage.report import (kind_text, summary_lines, text, warning_text, write_csvs,
                                write_workbook)
    from pandas import isna as pd_isna

    if args.example:
        from .examples import find_example
        spec_path = find_example(args.example, EXAMPLES, "linkage")
    else:
        spec_path = args.spec
    if not (0 < args.step <= 30):
        raise SpecError([f"--step: got {args.step:g}; must be > 0 and <= 30 degrees"])
    from crankbase.validation import rows_problem
    if rows_problem(360.0 / args.step + 1, "--step"):
        raise SpecError([rows_problem(360.0 / args.step + 1, "--step")])
    plan_opts = None
    if args.plans is not None:
        plan_opts = _plan_options(args)
    elif (args.measured or args.mu_v or args.mu_a or args.mu_f
          or args.mu_lever is not None):
        raise SpecError(["--measured, --mu-v, --mu-a, --mu-f, --mu-lever: only with --plans"])
    spec = linkage.load_spec(spec_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SingularPositionWarning)
        result = linkage.analyze(spec)
    plan_list = measured = None
    if plan_opts is not None:
        import plans as plans_pkg
        from plans.drawing import title_fields
        from plans.tables import read_measurements

        title_fields(spec)                                   # [drawing] keys checked
        plan_list = plans_pkg.build_plans(result, plan_opts[0], scales=plan_opts[1])
        if args.measured:
            measured = read_measurements(args.measured)
    full = linkage.full_turn(spec, args.step) if not args.no_plots else None
    figures = {}
    if full is not None:
        from linkage.plots import all_figures
        figures = all_figures(result, full, lang=args.lang)
    from pathlib import Path

    name = safe_name(spec.name, "linkage")
    inputs = [spec_path] + ([args.measured] if args.measured else [])
    stale = [p for p in (Path(args.output) / f"{name}_{s}.png" for s in PLOTS
                         if s not in figures) if p.exists()]
    # every file is named after the mechanism (the plans' too): other mechanisms' reports
    # in the folder stay
    with staged_output(args.output, inputs=inputs, unit=name) as stage:
        if plan_list is not None:
            from plans.report import write_plans

            info = write_plans(result, plan_list, stage, name=name, lang=args.lang,
                               sheet=args.sheet, measurements=measured,
                               previews=not args.no_plots)
        before = set(stage.iterdir())
        write_csvs(result, stage)
        for csv in sorted(set(stage.iterdir()) - before):   # named after the mechanism
            csv.rename(stage / f"{name}_{csv.name}")
        write_workbook(result, stage / f"{name}.xlsx", lang=args.lang)
        for stem, fig in figures.items():
            save_figure(fig, stage / f"{name}_{stem}", formats=("png",), dpi=120)
    # plots of this mechanism from an earlier run that this run did not draw are stale
    # (the report swap removes those it wrote itself; any other copy goes too)
    t = text(args.lang)
    for path in stale:
        if path.exists():
            path.unlink()
        if not path.exists():
            print(t["removed"].format(path=path), file=sys.stderr)
    for w in caught:
        print(t["warning_line"].format(w=warning_text(w.message, args.lang)),
              file=sys.stderr)
    statics = t["statics"] if spec.omega == 0 else ""
    print(t["run"].format(name=spec.name, kind=kind_text(spec.kind, args.lang),
                          statics=statics, n=len(result.kinematics), out=args.output))
    for label, value, unit in summary_lines(result, args.lang):
        v = f"{value:.4f}" if isinstance(value, float) else str(value)
        print(f"  {label}: {v} {unit}".rstrip())
    m = result.forces["M_drive_Nm"].abs()
    if m.notna().any():
        i = int(m.idxmax())
        pos = result.forces["position"].iat[i]
        where = "" if pd_isna(pos) else t["at_pos"].format(pos=pos)
        print("  " + t["max_M"].format(M=result.forces["M_drive_Nm"].iat[i], where=where,
                                       phi=result.forces["phi_deg"].iat[i]))
    if plan_list is not None:
        print("  " + t["plans"].format(n=len(plan_list), sheets=info["sheets"],
                                       size=args.sheet))
        for pp in plan_list:
            L = pp.lever
            print("    " + t["lever"].format(tag=pp.tag, lever=L.M_lever_Nm,
                                             kin=L.M_kinetostatic_Nm,
                                             diff=L.difference_percent,
                                             Fb=L.balancing_force_N))
    return 0
