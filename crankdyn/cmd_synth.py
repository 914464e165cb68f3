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
and the values that are words; its header rows are the seed's Russian, Chinese in zh, over
the CSV column names) and the
terminal summary; English output holds no Cyrillic letter (the family is KKM-φ0).
numpy, pandas, matplotlib and openpyxl are imported inside :func:`run` only.
"""
from __future__ import annotations

from .langs import add_lang, add_output, command


def add_parser(sub, t=None):
    """Register ``crankdyn synth``; ``t`` the help's words (:func:`crankdyn.langs.cli_texts`,
    Russian when not given)."""
    p, t = command(sub, "synth", t)
    p.add_argument("--phi0", default="30", metavar="DEG", help=t("cli.synth.opt.phi0"))
    p.add_argument("--l1", metavar="L1", help=t("cli.synth.opt.l1"))
    p.add_argument("--l2", metavar="L2", help=t("cli.synth.opt.l2"))
    p.add_argument("--l3", metavar="L3", help=t("cli.synth.opt.l3"))
    p.add_argument("--mu-min", dest="mu_min", metavar="DEG", help=t("cli.synth.opt.mu_min"))
    p.add_argument("--l1-step", dest="l1_step", metavar="STEP",
                   help=t("cli.synth.opt.l1_step"))
    p.add_argument("--ground", metavar="M", help=t("cli.synth.opt.ground"))
    p.add_argument("--name", metavar="NAME", help=t("cli.synth.opt.name"))
    p.add_argument("--omega", metavar="RAD_S", help=t("cli.synth.opt.omega"))
    add_output(p, t, "cli.common.opt.output_plain")
    p.add_argument("--no-plots", action="store_true", help=t("cli.common.opt.no_plots"))
    add_lang(p, t, "synth")
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
