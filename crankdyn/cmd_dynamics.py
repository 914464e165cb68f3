"""``crankdyn dynamics``: the true motion of a machine over its steady cycle, the flywheel,
a motor drive with the start-up, the forces under the true motion.

    crankdyn dynamics SPEC.toml -o DIR [--lang ru|en]
    crankdyn dynamics --example [NAME] -o DIR

SPEC is a machine given by its reduced quantities (``[machine]``) or a linkage spec, with a
``[dynamics]`` section.  Writes ``DIR/motion.csv`` (``phi_deg, J_red_kgm2,
dJ_red_dphi_kgm2, M_drive_Nm, M_resist_Nm, omega_rad_s, eps_rad_s2, t_s`` and ``phi_rad,
W_J, E_J``; a linkage adds ``M_resist_loads_Nm, M_resist_weights_Nm``),
``DIR/forces_true_motion.csv`` (linkage, engine), ``DIR/startup.csv`` (motor),
``DIR/<name>_dynamics.xlsx`` and the plots (PNG, SVG), all at once through a staging
folder; bad input writes nothing.
"""
from __future__ import annotations

#: Bundled examples by short name (``--example NAME``).
EXAMPLES = {"flywheel": "flywheel_seed.toml", "press": "press_dynamics.toml",
            "petrol": "petrol_dynamics.toml", "hoist": "hoist_machine.toml"}

MOTION_COLUMNS = ["phi_deg", "J_red_kgm2", "dJ_red_dphi_kgm2", "M_drive_Nm", "M_resist_Nm",
                  "omega_rad_s", "eps_rad_s2", "t_s", "phi_rad", "W_J", "E_J"]


def add_parser(subparsers):
    p = subparsers.add_parser(
        "dynamics", help="machine dynamics: true motion, flywheel, motor start-up",
        description="The reduced model (J_red, M_d, M_c) of a machine or a linkage, its "
                    "steady motion ω(φ), ε, t, δ, the flywheel for a required δ (classic "
                    "and exact), a motor characteristic with the start-up, and the forces "
                    "under the true motion beside the constant-speed ones.")
    p.add_argument("spec", nargs="?", metavar="SPEC.toml",
                   help="machine, linkage or engine spec with [dynamics]")
    p.add_argument("--example", nargs="?", const="flywheel", metavar="NAME",
                   help="run a bundled example instead of a spec: "
                        + ", ".join(EXAMPLES) + " (default flywheel)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if needed)")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="report and plot language (default ru)")
    p.set_defaults(func=run)


def run(args) -> int:
    import re
    from pathlib import Path

    from crankbase.errors import SpecError

    spec_path = _spec_path(args, EXAMPLES, "dynamics")
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise SpecError(f"-o: {out} exists and is not a folder")

    from dynamics.plots import dynamics_figures
    from dynamics.report import build_workbook, summary_rows
    from dynamics.spec import load_dynamics_spec, run_job

    from crankbase.output import (check_not_input, ensure_finite, full_precision_xlsx,
                                  staged_output, write_csv)

    job = load_dynamics_spec(spec_path)
    res = run_job(job)
    extra = [c for c in res["motion"].table.columns if c not in MOTION_COLUMNS]
    motion = res["motion"].table[MOTION_COLUMNS + extra]
    ensure_finite(motion, "motion table")
    tables = {"motion.csv": motion}
    if res["forces"] is not None:
        ensure_finite(res["forces"], "forces under the true motion")
        tables["forces_true_motion.csv"] = res["forces"]   # linkage or engine cylinder 1
    if res["startup"] is not None:
        ensure_finite(res["startup"].table, "start-up")
        tables["startup.csv"] = res["startup"].table
    wb = build_workbook(res, args.lang)
    figs = dynamics_figures(res, args.lang)
    safe = re.sub(r"[^\w.-]+", "_", job.model.name).strip("._") or "machine"
    xlsx = f"{safe}_dynamics.xlsx"
    names = list(tables) + [xlsx] + [f"{n}.{e}" for n in figs for e in ("png", "svg")]
    check_not_input([out / n for n in names], [spec_path])
    with staged_output(out, inputs=[spec_path]) as stage:
        for name, df in tables.items():
            write_csv(df, stage / name)
        with full_precision_xlsx():
            wb.save(stage / xlsx)
        for name, fig in figs.items():
            fig.savefig(stage / f"{name}.png", dpi=110)
            fig.savefig(stage / f"{name}.svg")

    m = res["motion"]
    print(f"{job.model.name}: {job.kind}, driving {job.settings.driving}, "
          f"{len(motion)} grid points over {m.table['phi_rad'].iloc[-1] * 57.29577951308232:g} deg")
    for label, value, unit in summary_rows(res, "en"):
        print(f"  {label:<36} {value:14.6g} {unit}")
    print(f"wrote {', '.join(tables)}, {xlsx}, {len(figs)} plots (PNG, SVG) in {out}"
          + (" [ru]" if args.lang == "ru" else " [en]"))
    return 0


def _spec_path(args, examples, what):
    """The spec file of ``args.spec`` or ``--example NAME`` (one of them, not both)."""
    from pathlib import Path

    from crankbase.errors import SpecError
    from crankbase.resources import example_path

    if args.spec and args.example:
        raise SpecError("give either SPEC.toml or --example, not both")
    if args.spec:
        return Path(args.spec)
    if not args.example:
        raise SpecError(f"give a {what} spec SPEC.toml or --example [NAME]")
    stem = args.example[:-5] if args.example.endswith(".toml") else args.example
    stems = {f[:-5]: f for f in examples.values()}
    fname = examples.get(stem) or stems.get(stem)
    if fname is None:
        raise SpecError(f"--example: no {what} example {args.example!r}; available: "
                        + ", ".join(list(examples) + list(stems)))
    return example_path(fname)
