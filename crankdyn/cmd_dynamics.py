"""``crankdyn dynamics``: the true motion of a machine over its steady cycle, the flywheel,
a motor drive with the start-up, the forces under the true motion.

    crankdyn dynamics SPEC.toml -o DIR [--lang ru|en]
    crankdyn dynamics --example [NAME] -o DIR

SPEC is a machine given by its reduced quantities (``[machine]``) or a linkage spec, with a
``[dynamics]`` section.  Every output is named after the spec's name (``<name>``, the
name as a file stem), so that the reports of two specs share a folder:
``DIR/<name>_motion.csv`` (``phi_deg, J_red_kgm2, dJ_red_dphi_kgm2, M_drive_Nm,
M_resist_Nm, omega_rad_s, eps_rad_s2, t_s`` and ``phi_rad, W_J, E_J``; a linkage adds
``M_resist_loads_Nm, M_resist_weights_Nm``), ``DIR/<name>_forces_true_motion.csv``
(linkage, engine), ``DIR/<name>_startup.csv`` (motor), ``DIR/<name>_dynamics.xlsx`` and
the plots ``DIR/<name>_<plot>.png|svg`` (``inertia``, ``moments``, ``wittenbauer``,
``omega``, ``startup``, ``forces_true_motion``), all at once through a staging folder
as one report unit (``dynamics:<name>``): a rerun replaces only its own files, removing
those it no longer writes; bad input writes nothing.  The terminal summary speaks the
report's language (``--lang``).
"""
from __future__ import annotations

import sys

#: Bundled examples by short name (``--example NAME``).
EXAMPLES = {"flywheel": "flywheel_seed.toml", "press": "press_dynamics.toml",
            "petrol": "petrol_dynamics.toml", "hoist": "hoist_machine.toml"}

MOTION_COLUMNS = ["phi_deg", "J_red_kgm2", "dJ_red_dphi_kgm2", "M_drive_Nm", "M_resist_Nm",
                  "omega_rad_s", "eps_rad_s2", "t_s", "phi_rad", "W_J", "E_J"]

#: Tables a run can write (``<name>_<table>``).
TABLES = ("motion.csv", "forces_true_motion.csv", "startup.csv")

#: The unnamed outputs of crankdyn versions before the files were named after the spec.
LEGACY_NAMES = ("motion.csv", "forces_true_motion.csv", "startup.csv") + tuple(
    f"{p}.{e}" for p in ("inertia", "moments", "wittenbauer", "omega", "startup", "forces")
    for e in ("png", "svg"))


def add_parser(subparsers):
    p = subparsers.add_parser(
        "dynamics", help="machine dynamics: true motion, flywheel, motor start-up",
        description="The reduced model (J_red, M_d, M_c) of a machine or a linkage, its "
                    "steady motion ω(φ), ε, t, δ, the flywheel for a required δ (classic "
                    "and exact), a motor characteristic with the start-up, and the forces "
                    "under the true motion beside the constant-speed ones.  Every output "
                    "is named after the spec's name: <name>_motion.csv, "
                    "<name>_dynamics.xlsx, <name>_omega.png …, so that the reports of "
                    "several specs share a folder; a rerun replaces only its own files.")
    p.add_argument("spec", nargs="?", metavar="SPEC.toml",
                   help="machine, linkage or engine spec with [dynamics]")
    p.add_argument("--example", nargs="?", const="flywheel", metavar="NAME",
                   help="run a bundled example instead of a spec: "
                        + ", ".join(EXAMPLES) + " (default flywheel)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if needed)")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="language of the workbook, the plots and the terminal summary "
                        "(default ru, the Russian textbook symbols)")
    p.set_defaults(func=run)


def run(args) -> int:
    from pathlib import Path

    from crankbase.errors import SpecError

    spec_path = _spec_path(args, EXAMPLES, "dynamics")
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise SpecError(f"-o: {out} exists and is not a folder")

    from dynamics.plots import PLOT_NAMES, dynamics_figures
    from dynamics.report import build_workbook, summary_lines
    from dynamics.spec import load_dynamics_spec, run_job

    from crankbase.output import (check_not_input, ensure_finite, full_precision_xlsx,
                                  safe_name, save_figure, staged_output, write_csv)

    from .cmd_engine import output_names

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
    name = safe_name(job.model.name, "machine")
    wb = build_workbook(res, args.lang, name=job.model.name)
    figs = dynamics_figures(res, args.lang)
    files = output_names(name, list(tables))
    xlsx = f"{name}_dynamics.xlsx"
    plots = output_names(name, list(figs))
    names = list(files.values()) + [xlsx] + [f"{p}.{e}" for p in plots.values()
                                             for e in ("png", "svg")]
    check_not_input([out / n for n in names], [spec_path])
    stale = stale_outputs(out, name, list(TABLES) + [
        f"{p}.{e}" for p in PLOT_NAMES for e in ("png", "svg")], names)
    with staged_output(out, inputs=[spec_path], unit=f"dynamics:{name}") as stage:
        for key, df in tables.items():
            write_csv(df, stage / files[key])
        with full_precision_xlsx():
            wb.save(stage / xlsx)
        for key, fig in figs.items():
            save_figure(fig, stage / plots[key])
    for fig in figs.values():
        fig.clear()

    lines = summary_lines(res, job.model.name, job.kind, job.settings.driving, args.lang)
    lines.append(written_line(list(files.values()) + [xlsx], len(figs), out, args.lang))
    print("\n".join(lines))
    report_stale("dynamics", stale, out, args.lang)
    return 0


def stale_outputs(out, name, whats, written):
    """Files ``<name>_<what>`` of an earlier run in ``out`` that this run does not write
    (``whats``: every output the command can write; ``written``: this run's names)."""
    from pathlib import Path

    out = Path(out)
    return [out / f"{name}_{w}" for w in whats
            if f"{name}_{w}" not in written and (out / f"{name}_{w}").is_file()]


def report_stale(command, stale, out, lang, legacy=LEGACY_NAMES):
    """After a run: remove the ``stale`` files of this spec an earlier run wrote and this
    one did not (the report swap removes those its manifest lists; any other copy goes
    too), and say so on stderr; name the unnamed outputs of an older crankdyn
    (``legacy``) still in ``out``, which are left alone.  In the report's language."""
    import contextlib
    from pathlib import Path

    ru = lang == "ru"
    for path in stale:
        with contextlib.suppress(FileNotFoundError):
            path.unlink()
        print(f"crankdyn {command}: " + (f"удалён {path} (файл прежнего расчёта по той же "
                                        f"спецификации, теперь не записывается)" if ru else
                                        f"removed {path} (an earlier run's output for this "
                                        f"spec, not written now)"), file=sys.stderr)
    old = [n for n in legacy if (Path(out) / n).is_file()]
    if old:
        print(f"crankdyn {command}: " + (
            "в папке остались файлы прежней версии программы, названные без имени "
            "спецификации (не тронуты): " if ru else "the folder still holds unnamed outputs of an older "
            "crankdyn (left alone): ") + ", ".join(old), file=sys.stderr)


def written_line(files, n_plots, out, lang):
    """The last line of a terminal summary: the files written, in ``lang``."""
    if lang == "ru":
        return (f"записано: {', '.join(files)}"
                + (f", графиков: {n_plots} (PNG, SVG)" if n_plots else "") + f" в {out}")
    return (f"wrote {', '.join(files)}"
            + (f", {n_plots} plot{'s' if n_plots > 1 else ''} (PNG, SVG)" if n_plots
               else "") + f" in {out}")


def _spec_path(args, examples, what):
    """The spec file of ``args.spec`` or ``--example NAME`` (one of them, not both)."""
    from pathlib import Path

    from crankbase.errors import SpecError

    from .examples import find_example

    if args.spec and args.example:
        raise SpecError("give either SPEC.toml or --example, not both")
    if args.spec:
        return Path(args.spec)
    if not args.example:
        raise SpecError(f"give a {what} spec SPEC.toml or --example [NAME]")
    return find_example(args.example, examples, what)
