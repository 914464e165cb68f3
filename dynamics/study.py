"""The dynamics study: one call runs a dynamics spec, another writes the report.

:func:`run_study` (or :func:`dynamics.spec.run_job` on a loaded job) computes the true
motion, the flywheel, a motor's start-up and the forces under the true motion and
returns a :class:`DynamicsReport`, writing nothing; :func:`write_report` writes its
tables, workbook and plots into a folder as one report unit; :func:`summary_lines` is the
terminal summary in the report's language (words from
``crankbase/locale/<lang>/dynamics.po``).  ``crankdyn dynamics`` is these three calls.
The report unit and the stale-file rules are shared with the balance study
(:mod:`dynamics.balance_study`).

Examples
--------
>>> from crankbase.resources import example_path
>>> from dynamics.study import run_study
>>> report = run_study(example_path("flywheel_seed.toml"))
>>> list(report.tables())
['flywheel-example-11-3_motion.csv']
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from pathlib import Path

from .results import MOTION_COLUMNS, DynamicsReport

__all__ = ["DynamicsReport", "WrittenReport", "run_study", "write_report", "summary_lines",
           "notice_lines", "written_line", "MOTION_COLUMNS", "TABLES", "LEGACY_NAMES"]

#: Tables a run can write (``<name>_<table>``).
TABLES = ("motion.csv", "forces_true_motion.csv", "startup.csv")

#: The unnamed outputs of crankdyn versions before the files were named after the spec.
LEGACY_NAMES = ("motion.csv", "forces_true_motion.csv", "startup.csv") + tuple(
    f"{p}.{e}" for p in ("inertia", "moments", "wittenbauer", "omega", "startup", "forces")
    for e in ("png", "svg"))


@dataclass
class WrittenReport:
    """What a write did: ``files`` (tables and workbook, in ``folder``, in the order
    written), ``plots`` (how many figures, each in every format of ``formats``),
    ``removed`` (an earlier run's files of this spec not written now, deleted) and
    ``legacy`` (unnamed outputs of an older crankdyn in the folder, left alone)."""

    folder: Path
    files: list
    plots: int = 0
    formats: tuple = ("png", "svg")
    removed: list = field(default_factory=list)
    legacy: list = field(default_factory=list)


def run_study(spec):
    """Run a dynamics spec (a path, a dict or a loaded
    :class:`~dynamics.spec.DynamicsJob`); write nothing.  Returns a
    :class:`DynamicsReport`."""
    from .spec import DynamicsJob, load_dynamics_spec, run_job

    job = spec if isinstance(spec, DynamicsJob) else load_dynamics_spec(spec)
    return run_job(job)


def stale_outputs(out, name, whats, written):
    """Files ``<name>_<what>`` of an earlier run in ``out`` that this run does not write
    (``whats``: every output the command can write; ``written``: this run's names)."""
    out = Path(out)
    return [out / f"{name}_{w}" for w in whats
            if f"{name}_{w}" not in written and (out / f"{name}_{w}").is_file()]


def remove_stale(stale, out, legacy=LEGACY_NAMES):
    """After a write: remove the ``stale`` files (the report swap removes those its
    manifest lists; any other copy goes too); return ``(removed, legacy)``, ``legacy``
    being the unnamed outputs of an older crankdyn still in ``out`` (left alone)."""
    for path in stale:
        with contextlib.suppress(FileNotFoundError):
            path.unlink()
    return list(stale), [n for n in legacy if (Path(out) / n).is_file()]


def write_report(report: DynamicsReport, out, lang="ru",
                 formats=("png", "svg")) -> WrittenReport:
    """Write a dynamics report into the folder ``out`` as one report unit
    (``dynamics:<name>``; :func:`crankbase.output.staged_output`): the tables
    (:meth:`DynamicsReport.tables`), the workbook ``<name>_dynamics.xlsx`` and the plots
    ``<name>_<plot>.<format>`` in ``lang``; an earlier run's files of this spec that this
    one does not write are removed; bad numbers write nothing.

    Raises
    ------
    OutputError
        A table holds a non-finite number, or an output is an input file.
    """
    from crankbase.output import (check_not_input, ensure_finite, full_precision_xlsx,
                                  save_figure, staged_output, write_csv)
    from crankbase.output import output_folder
    from crankbase.validation import check_lang

    from .plots import PLOT_NAMES, dynamics_figures
    from .report import build_workbook

    check_lang(lang)
    out = output_folder(out)
    tables = report.tables()
    what = {"motion.csv": "motion table", "forces_true_motion.csv":
            "forces under the true motion", "startup.csv": "start-up"}
    for fname, df in tables.items():
        ensure_finite(df, what[fname[len(report.stem) + 1:]])
    name = report.stem
    wb = build_workbook(report, lang, name=report.name)
    figs = dynamics_figures(report, lang)
    xlsx = f"{name}_dynamics.xlsx"
    names = list(tables) + [xlsx] + [f"{name}_{p}.{e}" for p in figs for e in formats]
    inputs = [report.source] if report.source else []
    check_not_input([out / n for n in names], inputs)
    stale = stale_outputs(out, name, list(TABLES) + [
        f"{p}.{e}" for p in PLOT_NAMES for e in ("png", "svg")], names)
    with staged_output(out, inputs=inputs, unit=f"dynamics:{name}") as stage:
        for fname, df in tables.items():
            write_csv(df, stage / fname)
        with full_precision_xlsx():
            wb.save(stage / xlsx)
        for key, fig in figs.items():
            save_figure(fig, stage / f"{name}_{key}", formats=formats)
    removed, legacy = remove_stale(stale, out)
    return WrittenReport(out, list(tables) + [xlsx], len(figs), tuple(formats), removed,
                         legacy)


def written_line(written: WrittenReport, lang="ru") -> str:
    """The last line of a terminal summary: the files written and the number of plots,
    in ``lang`` (plural forms of the language: «4 графика», «5 графиков»)."""
    from crankbase.texts import texts

    t = texts(lang)
    files = ", ".join(written.files)
    if written.plots:
        files += ", " + t("dynamics.summary.plots", plots=t.n("common.plots", written.plots),
                          formats=", ".join(f.upper() for f in written.formats))
    return t("common.wrote", files=files, folder=written.folder)


def notice_lines(written: WrittenReport, lang="ru") -> list:
    """Lines for the error stream in ``lang``: the stale files removed and the unnamed
    outputs of an older crankdyn left in the folder."""
    from crankbase.texts import texts

    t = texts(lang)
    lines = [t("dynamics.notice.removed", path=p) for p in written.removed]
    if written.legacy:
        lines.append(t("dynamics.notice.legacy", files=", ".join(written.legacy)))
    return lines


def summary_lines(report: DynamicsReport, lang="ru", written=None) -> list:
    """The terminal summary of a dynamics run in ``lang``
    (:func:`dynamics.report.summary_lines`), what the run assumed, and with ``written``
    (a :class:`WrittenReport`) the files written."""
    from .report import summary_lines as lines_of

    lines = lines_of(report, lang=lang)
    if written is not None:
        lines.append(written_line(written, lang))
    return lines
