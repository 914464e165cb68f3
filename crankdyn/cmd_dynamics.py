"""``crankdyn dynamics``: the true motion of a machine over its steady cycle, the flywheel,
a motor drive with the start-up, the forces under the true motion.

    crankdyn dynamics SPEC.toml -o DIR [--lang ru|en|zh]
    crankdyn dynamics --example [NAME] -o DIR

SPEC is a machine given by its reduced quantities (``[machine]``) or a linkage spec, with a
``[dynamics]`` section.  Every output is named after the spec's name (``<name>``, the
name as a file stem), so that the reports of two specs share a folder:
``DIR/<name>_motion.csv`` (``phi_deg, J_red_kgm2, dJ_red_dphi_kgm2, M_drive_Nm,
M_resist_Nm, omega_rad_s, eps_rad_s2, t_s`` and ``phi_rad, W_J, E_J``; a linkage adds
``M_resist_loads_Nm, M_resist_weights_Nm``), ``DIR/<name>_forces_true_motion.csv``
(linkage, engine; a chain spec's reactions are named after its links, ``Rx_frame_crank_N``
…), ``DIR/<name>_startup.csv`` (motor), ``DIR/<name>_dynamics.xlsx`` and
the plots ``DIR/<name>_<plot>.png|svg`` (``inertia``, ``moments``, ``wittenbauer``,
``omega``, ``startup``, ``forces_true_motion``), all at once through a staging folder
as one report unit (``dynamics:<name>``): a rerun replaces only its own files, removing
those it no longer writes; bad input writes nothing.  The terminal summary speaks the
report's language (``--lang``).
"""
from __future__ import annotations

import sys
from .langs import report_command

#: Bundled examples by short name (``--example NAME``).
EXAMPLES = {"flywheel": "flywheel_seed.toml", "press": "press_dynamics.toml",
            "petrol": "petrol_dynamics.toml", "hoist": "hoist_machine.toml",
            "shaper": "shaper_dynamics.toml"}


def add_parser(subparsers, t=None):
    """Register ``crankdyn dynamics``; ``t`` the help's words
    (:func:`crankdyn.langs.cli_texts`, Russian when not given)."""
    p, t = report_command(subparsers, "dynamics", t, EXAMPLES, "flywheel")
    p.set_defaults(func=run)


def run(args) -> int:
    from dynamics.study import notice_lines, run_study, summary_lines, write_report

    from .examples import output_folder, spec_file

    spec_path, out = spec_file(args, EXAMPLES, "dynamics"), output_folder(args)
    report = run_study(spec_path)
    written = write_report(report, out, lang=args.lang)
    print("\n".join(summary_lines(report, args.lang, written)))
    print_notices("dynamics", notice_lines(written, args.lang))
    return 0


def print_notices(command, lines):
    """The library's notices (stale files removed, old outputs left) on stderr, each
    after the command's name."""
    for line in lines:
        print(f"crankdyn {command}: {line}", file=sys.stderr)
