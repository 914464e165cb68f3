"""``crankdyn linkage``: kinematics and kinetostatics of a crank-rocker, a crank-slider or
any chain of class II Assur groups (``kind = "chain"``: the shaper, six-bar press, V
compressor examples).

Writes ``<name>_kinematics.csv``, ``<name>_forces.csv``, the workbook ``<name>.xlsx`` and
the plots ``<name>_<plot>.png`` (``<name>``: the mechanism's name as a file stem)
(plan of positions; over a full turn at 1°: ω and ε of links 3 and 4, the driving moment
Mур, the transmission angle); with ``--plans`` the graphical method's files, named the
same way (``<name>_plans.csv``, ``<name>_sheet.pdf`` …, see :mod:`plans.report`).  All
outputs are produced in a staging folder and moved into place only when every one of them
is complete; the reports of other mechanisms in the folder stay.

``--lang ru|en|zh`` (default ru) chooses the language of the workbook (sheet titles, labels,
units, symbols: :mod:`linkage.report`), the plots, the plan drawings and the terminal
summary; the CSV files, the workbook's numbers and its CSV-name header row are the same
in both.
"""
from __future__ import annotations

import sys
from .langs import LANG_CHOICES, LANG_HELP

#: Bundled examples by short name (``--example NAME``; a file stem works too).
EXAMPLES = {"ratchet": "ratchet.toml", "press": "press.toml", "shaper": "shaper.toml",
            "press6": "press6.toml", "compressor_v": "compressor_v.toml",
            "sixbar_rrr": "sixbar_rrr.toml", "shaper_cn": "shaper_cn.toml"}



def add_parser(sub):
    p = sub.add_parser(
        "linkage", help="kinematics and kinetostatics of a crank-rocker, crank-slider or any "
                        "chain of class II groups",
        description="Kinematics and kinetostatics of a crank-rocker or crank-slider from a "
                    "TOML spec (see README): CSV tables, an Excel workbook and plots.")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("spec", nargs="?", help="the mechanism spec (TOML)")
    src.add_argument("--example", nargs="?", const="ratchet", metavar="NAME",
                     help="run a bundled example instead of a spec: "
                          + ", ".join(EXAMPLES) + " (default ratchet: the ratchet drive "
                          "of the course project; press: a crank-slider press; chains of "
                          "class II groups: shaper, the crank-slotted lever of a shaping "
                          "machine; press6, a six-bar press; compressor_v, a two-cylinder "
                          "V compressor; sixbar_rrr, an RRR-RRR six-bar; shaper_cn, the "
                          "shaper of the Chinese course design, data set I)")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--step", type=float, default=1.0, metavar="DEG",
                   help="crank-angle step of the full-turn plots (default 1°)")
    p.add_argument("--no-plots", action="store_true", help="write the tables only")
    p.add_argument("--lang", choices=LANG_CHOICES, metavar="LANG", default="ru",
                   help=LANG_HELP
                   + "language of every output: the workbook (sheet titles, labels, "
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


#: The library's argument names in its problems → this command's options.
OPTIONS = {"positions": "--plans", "size": "--sheet", "plans": "--plans", "sheet": "--sheet",
           "step": "--step", "measured": "--measured", "mu_v": "--mu-v", "mu_a": "--mu-a",
           "mu_f": "--mu-f", "mu_lever": "--mu-lever"}


def run(args) -> int:
    from crankbase.errors import SpecError

    try:
        return _run(args)
    except SpecError as exc:
        raise exc.renamed(OPTIONS) from None


def _run(args) -> int:
    from crankbase.errors import Problem, SpecError, Text
    from linkage.study import notice_lines, summary_lines, write_report
    from plans.study import run_study

    if args.example:
        from .examples import find_example
        spec_path = find_example(args.example, EXAMPLES, "linkage")
    else:
        spec_path = args.spec
    if args.plans is None and (args.measured or args.mu_v or args.mu_a or args.mu_f
                               or args.mu_lever is not None):
        raise SpecError([Problem("--measured, --mu-v, --mu-a, --mu-f, --mu-lever",
                                 Text("errors.cli.only_with_plans"))])
    report = run_study(spec_path, step=args.step, plots=not args.no_plots, plans=args.plans,
                       sheet=args.sheet, measured=args.measured, mu_v=args.mu_v,
                       mu_a=args.mu_a, mu_f=args.mu_f, mu_lever=args.mu_lever)
    written = write_report(report, args.output, lang=args.lang)
    for line in notice_lines(report, written, args.lang):
        print(f"crankdyn linkage: {line}", file=sys.stderr)
    print("\n".join(summary_lines(report, args.lang, written)))
    return 0
