"""``crankdyn synth``: synthesis of a crank-rocker by the transmission angle (ККМ-φ0).

    crankdyn synth --phi0 30 [--l2 L2 --l3 L3 | --l1 L1 | --l2 L2 --mu-min DEG]
                   [--ground M] [--lang ru|en|zh] -o DIR

Writes, named after the design (``<name>``: ``--name``, default ``kkm-<φ0>``, so that two
designs in one folder never mix), the chosen mechanism (``<name>_mechanism.csv``, printed
too), the paper's Table 1 for that φ0 (``<name>_table1.csv``, and the workbook
``<name>_synthesis.xlsx``), μ(φ) over a turn (``<name>_transmission_angle.csv``), with
``--ground`` a spec TOML for ``crankdyn linkage`` (``<name>.toml``), and the plots
``<name>_region``, ``_mu_min`` and ``_transmission_angle`` (PNG and SVG).  Every input
is checked before anything is written, by the library's one check
(:func:`linkage.synthesis_study.check_inputs`, the synthesis page's too); bad input
prints one line per problem, each naming its option, and exits 2.
``--lang`` (default ru) is the language of the plots, the workbook (its title, sheet names
and the values that are words; both header rows, Russian and English, stay) and the
terminal summary; English output holds no Cyrillic letter (the family is KKM-φ0).
numpy, pandas, matplotlib and openpyxl are imported inside :func:`run` only.
"""
from __future__ import annotations

from .langs import LANG_CHOICES, LANG_HELP


def add_parser(sub):
    p = sub.add_parser(
        "synth", help="crank-rocker synthesis by the transmission angle (ККМ-φ0 family)",
        description="Synthesis of a crank-rocker whose transmission angle is 90° at the "
                    "crank angle φ0 (from the line of centres) and never below a minimum "
                    "(Sereda 2016, the ККМ-30° family, generalised to any φ0). Lengths are "
                    "relative to the ground (λ0 = 1). Choose the mechanism by one of: "
                    "--l2 and --l3 (λ1 from eq. 6); --l1 (λ2 = λ3); --l2 and --mu-min (the "
                    "largest λ1 with μmin ≥ the given angle). Without any, only the region "
                    "of existence, Table 1 and Fig. 3 are written.")
    p.add_argument("--phi0", default="30", metavar="DEG",
                   help="crank angle where μ = 90°, 0 < φ0 < 180 (default 30)")
    p.add_argument("--l1", metavar="L1", help="crank length λ1 = l1/l0 (then λ2 = λ3)")
    p.add_argument("--l2", metavar="L2", help="coupler length λ2 = l2/l0")
    p.add_argument("--l3", metavar="L3", help="rocker length λ3 = l3/l0 (with --l2)")
    p.add_argument("--mu-min", dest="mu_min", metavar="DEG",
                   help="required minimum transmission angle, 0 ≤ μmin < 90 (with --l2)")
    p.add_argument("--l1-step", dest="l1_step", metavar="STEP",
                   help="with --mu-min: round λ1 down to a multiple of STEP, as read off "
                        "Fig. 3 (the paper: 0.01)")
    p.add_argument("--ground", metavar="M",
                   help="ground length l0 in metres: also write a spec TOML for "
                        "`crankdyn linkage` with the absolute lengths")
    p.add_argument("--name", metavar="NAME",
                   help="name of the design: its files are <NAME>_table1.csv, "
                        "<NAME>_synthesis.xlsx …, the spec <NAME>.toml with --ground, and "
                        "the mechanism's name in it (default kkm-<φ0>)")
    p.add_argument("--omega", metavar="RAD_S",
                   help="crank angular velocity in the spec, rad/s, + ccw (default 1; "
                        "with --ground)")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--no-plots", action="store_true", help="write the tables only")
    p.add_argument("--lang", choices=LANG_CHOICES, metavar="LANG", default="ru",
                   help=LANG_HELP
                   + "language of the plots, the workbook's titles, sheet names and "
                        "words, and the terminal summary: ru (the paper's Russian terms, "
                        "ККМ-φ0; default), en (English, no Cyrillic: KKM-φ0) or zh "
                        "(Chinese, KKM-φ0). The workbook keeps its Russian (Chinese in zh) "
                        "and English header rows")
    p.set_defaults(func=run)
    return p


def _values(args) -> dict:
    """The options as the inputs of :func:`linkage.synthesis_study.check_inputs`."""
    return {"phi0_deg": args.phi0, "l1": args.l1, "l2": args.l2, "l3": args.l3,
            "mu_min_deg": args.mu_min, "l1_step": args.l1_step, "ground_m": args.ground,
            "omega_rad_s": args.omega, "name": args.name}


#: Python argument names of linkage.synthesis → the options that set them.
ARG_OPTION = {"l1": "--l1", "l2": "--l2", "l3": "--l3", "mu_min_deg": "--mu-min",
              "mu_min": "--mu-min", "l1_step": "--l1-step", "phi0_deg": "--phi0",
              "ground_m": "--ground", "omega": "--omega", "omega_rad_s": "--omega"}


def _as_options(exc):
    """The same error with each problem's key path written as the CLI options."""
    from crankbase.errors import Problem, SpecError

    problems = []
    for p in getattr(exc, "problems", []):
        key = ", ".join(ARG_OPTION.get(k.strip(), k.strip()) for k in p.key.split(","))
        problems.append(Problem(key if p.key else "", p.text or p.message))
    return SpecError(problems) if problems else exc


def run(args) -> int:
    from crankbase.errors import SpecError
    from linkage.synthesis_study import (FLAGS, check_inputs, option, run_study, study_arguments,
                                         summary_lines, write_report)

    # the library's one check of the inputs (the synthesis page's too), named as options
    inputs, _mode = check_inputs(_values(args), {**{k: option(k) for k in FLAGS}, "mode": "options"})
    # compute everything first (a problem leaves the output untouched)
    try:
        report = run_study(**study_arguments(inputs), plots=not args.no_plots)
    except SpecError as exc:
        raise _as_options(exc) from None
    written = write_report(report, args.output, lang=args.lang)
    print("\n".join(summary_lines(report, args.lang, written)))
    return 0
