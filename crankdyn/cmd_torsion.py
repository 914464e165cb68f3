"""``crankdyn torsion``: torsional vibration of the crankshaft.

    crankdyn torsion SPEC.toml -o DIR [--lang ru|en|zh]
    crankdyn torsion --example [NAME] -o DIR            # three-rotor, six

SPEC is an engine spec with a ``[torsion]`` table, or a file with only ``name`` and a
``[torsion]`` chain given by hand (free vibration unless an engine drives its throws).
Writes ``DIR/<name>_torsion_modes.csv``, ``_holzer.csv`` and, with an engine,
``_torque_harmonics.csv``, ``_critical_speeds.csv``, ``_torsion_response.csv``, the
workbook ``DIR/<name>_torsion.xlsx`` and the figures, all at once through a staging folder;
bad input writes nothing (one line per problem, exit status 2).  The work is the
library's (:func:`torsion.study.run_study`, :func:`torsion.study.write_report`,
:mod:`torsion.summary`); this module parses the arguments and prints.
"""
from __future__ import annotations

from .langs import report_command

#: Bundled examples by short name (``--example NAME``; a file stem works too).
EXAMPLES = {"three-rotor": "torsion_three_rotor.toml", "six": "torsion_inline6.toml"}


def add_parser(subparsers, t=None):
    """Register ``crankdyn torsion``; ``t`` the help's words
    (:func:`crankdyn.langs.cli_texts`, Russian when not given)."""
    p, t = report_command(subparsers, "torsion", t, EXAMPLES, "three-rotor")
    p.set_defaults(func=run)


def run(args) -> int:
    from crankbase.errors import SpecError

    from .examples import output_folder, spec_file

    spec_path, out = spec_file(args, EXAMPLES, "torsion"), output_folder(args)
    from torsion.study import load, run_study, write_report

    try:
        report = run_study(load(spec_path))
        written = write_report(report, out, args.lang)
    except SpecError as exc:            # the library's arguments → this command's options
        raise exc.renamed({"lang": "--lang", "out": "-o"}) from None
    print("\n".join(report.summary_lines(args.lang, written=written)))
    return 0
