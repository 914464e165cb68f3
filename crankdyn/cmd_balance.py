"""``crankdyn balance``: balancing of a rigid rotor or of a linkage's mechanism.

    crankdyn balance ROTOR.toml -o DIR [--lang ru|en|zh]
    crankdyn balance LINKAGE.toml -o DIR [--lang ru|en|zh]     # optional [balance] section
    crankdyn balance --example [NAME] -o DIR                 # rotor, ratchet, shaper

Every output is named after the spec's name (``<name>``: the rotor's or the
mechanism's name as a file stem), so that the reports of several specs share a folder.

Rotor (a ``[rotor]`` table): ``DIR/<name>_rotor_balance.csv`` (``plane, z_mm, mr_gmm,
angle_deg`` and ``m_g, r_mm`` when the spec gives ``correction_radius_mm``),
``DIR/<name>_rotor_shares.csv`` (every unbalance resolved into the planes) and
``DIR/<name>_rotor_polygons.png``/``.svg`` (the m·r polygon of every plane).

Linkage (a ``[mechanism]`` table): full shaking-force balance of a crank-rocker or partial
balance of a crank-slider: ``DIR/<name>_counterweights.csv`` (``link, mr_kgm, angle_deg,
radius_m, mass_kg``; a crank-slider adds ``fraction, m_rec_kg``), ``DIR/<name>_shaking.csv``
(``phi_deg`` and the shaking force and moment before and after: ``F_x_N, F_y_N, F_N,
M_O_Nm`` and ``*_after``) and the plots ``<name>_shaking_force`` and
``<name>_shaking_locus``.  A chain spec (``kind = "chain"``, any six-link mechanism): one
crank counterweight cancelling the forward first harmonic of the shaking force (the least
mean square; ``[balance] radius_m``), the same files.

Everything is written at once through a staging folder as one report unit
(``balance:<name>``, apart from the ``crankdyn linkage`` report of the same mechanism):
a rerun replaces only its own files; bad input writes nothing.  The terminal summary
speaks the report's language (``--lang``).
"""
from __future__ import annotations
from .langs import report_command


#: Bundled examples by short name (``--example NAME``).
EXAMPLES = {"rotor": "rotor_two_plane.toml", "ratchet": "ratchet_balance.toml",
            "shaper": "shaper.toml"}


def add_parser(subparsers, t=None):
    """Register ``crankdyn balance``; ``t`` the help's words (:func:`crankdyn.langs.cli_texts`,
    Russian when not given)."""
    p, t = report_command(subparsers, "balance", t, EXAMPLES, "rotor")
    p.set_defaults(func=run)


def run(args) -> int:
    from dynamics.balance_study import run_study, summary_lines, write_report
    from dynamics.study import notice_lines

    from .cmd_dynamics import print_notices
    from .examples import output_folder, spec_file

    spec_path, out = spec_file(args, EXAMPLES, "balance"), output_folder(args)
    report = run_study(spec_path)
    written = write_report(report, out, lang=args.lang)
    print("\n".join(summary_lines(report, args.lang, written)))
    print_notices("balance", notice_lines(written, args.lang))
    return 0
