"""``crankdyn engine``: the engine force table (Table 2), its workbook and plots.

    crankdyn engine SPEC.toml -o DIR [--lang ru|en|zh] [--step DEG] [--form seed|kolchin]
                                     [--bearings] [--drawing] [--torsion]
    crankdyn engine --example [NAME] -o DIR
    crankdyn engine SPEC.toml --variants variants.csv|xlsx -o DIR [--jobs N]

Writes ``DIR/<name>_forces.csv``, ``DIR/<name>_table2.csv``, the whole-engine tables
``DIR/<name>_cylinders.csv``, ``_torque.csv``, ``_balance.csv`` (and the bearing tables
with --bearings), ``DIR/<name>.xlsx`` and the plots ``DIR/<name>_<plot>.png|svg``
(``<name>``: the engine's name as a file stem, so that two engines in one folder never
mix) after everything has been validated and computed, all at once through a staging
folder; bad input writes nothing.  The work is the library's (:func:`engine.run_study`,
:func:`engine.write_report`, :mod:`engine.report.summary`); this module parses the arguments and
prints.  Heavy libraries are imported inside :func:`run` only, so ``crankdyn --help``
stays fast.
"""
from __future__ import annotations
from crankbase.errors import Text
from .langs import report_command

#: Bundled examples by short name (``--example NAME``; a file stem works too).
EXAMPLES = {"petrol": "petrol_vaz2106.toml", "diesel": "diesel_d240.toml",
            "six": "petrol_bmw_m54.toml", "v8": "diesel_kamaz740.toml"}


def add_parser(subparsers, t=None):
    """Register ``crankdyn engine``; ``t`` the help's words (:func:`crankdyn.langs.cli_texts`,
    Russian when not given)."""
    p, t = report_command(subparsers, "engine", t, EXAMPLES, "petrol")
    p.add_argument("--step", type=float, metavar="DEG", help=t("cli.engine.opt.step"))
    p.add_argument("--bearings", action="store_true", help=t("cli.engine.opt.bearings"))
    p.add_argument("--torsion", action="store_true", help=t("cli.engine.opt.torsion"))
    p.add_argument("--form", choices=("seed", "kolchin"), help=t("cli.engine.opt.form"))
    p.add_argument("--drawing", action="store_true", help=t("cli.engine.opt.drawing"))
    p.add_argument("--variants", metavar="TABLE", help=t("cli.engine.opt.variants"))
    p.add_argument("--jobs", type=int, default=1, metavar="N", help=t("cli.engine.opt.jobs"))
    p.set_defaults(func=run)


def run(args) -> int:
    from crankbase.errors import SpecError

    from .examples import output_folder, spec_file

    spec_path, out = spec_file(args, EXAMPLES, "engine"), output_folder(args)
    if args.jobs < 1:
        raise SpecError(Text("errors.crankdyn.cli_engine.jobs_whole_number", {"jobs": args.jobs}))
    try:
        if getattr(args, "variants", None):
            from .variants_cli import run_variants
            return run_variants(args, spec_path, out)

        import engine

        report = engine.run_study(engine.load(spec_path), bearings=args.bearings,
                                  step=args.step, form=args.form, source=spec_path,
                                  torsion=getattr(args, "torsion", False))
        written = engine.write_report(report, out, args.lang, drawing=args.drawing)
    except SpecError as exc:            # the library's arguments → this command's options
        raise exc.renamed(OPTION_NAMES) from None
    print("\n".join(report.summary_lines(args.lang, written=written)))
    return 0


#: The library's argument names → this command's options (in problems of bad input).
OPTION_NAMES = {"step": "--step", "form": "--form", "lang": "--lang", "out": "-o",
                "jobs": "--jobs"}


def with_options(study, step=None, form=None):
    """The study with ``--step`` and ``--form`` applied (:func:`engine.study.with_options`;
    kept for scripts that used it from here)."""
    from engine.study import with_options as apply

    return apply(study, step, form)


def output_names(stem, names):
    """``{name: file name}`` of every output, named after its report (``<stem>_<name>``):
    :func:`engine.study.output_names`."""
    return {n: f"{stem}_{n}" for n in names}
