"""The linkage study: one call runs the whole study of a mechanism spec, another writes it.

The layer between the library's pieces and a command line (pvlib's ``ModelChain`` is the
model): :func:`run_study` loads the spec, analyses the plan of positions and the full
turn for the plots and returns a :class:`LinkageReport` holding every result and table,
without writing anything; :func:`write_report` writes it (CSV files, the workbook, the
plots) into a folder as one report unit, and :func:`summary_lines` is the terminal
summary in the report's language (words from ``crankbase/locale/<lang>/linkage.po``).

The graphical method sits one layer up (:mod:`plans` imports :mod:`linkage`, never the
other way): :func:`plans.study.run_study` is the same call with the plans of chosen
positions, a student's measured segments and the plans' scales; its report is a
:class:`LinkageReport` that also writes and summarises the plans (through the hooks
:meth:`LinkageReport.write_more` and :meth:`LinkageReport.more_lines`).
``crankdyn linkage`` is these three calls.

Examples
--------
>>> from crankbase.resources import example_path
>>> from linkage.study import run_study
>>> report = run_study(example_path("ratchet.toml"), plots=False)
>>> sorted(report.tables())
['ratchet-drive_forces.csv', 'ratchet-drive_kinematics.csv']
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from crankbase.errors import Problem, SpecError, Text

__all__ = ["LinkageReport", "ChainReport", "WrittenReport", "run_study", "write_report", "summary_lines",
           "notice_lines", "written_line", "check_step", "PLOTS"]

#: File stems of every plot a report may hold (``<name>_<stem>.png``;
#: :func:`linkage.plots.all_figures`).
PLOTS = ("plan", "velocities", "accelerations", "driving_moment", "transmission_angle")

@dataclass
class LinkageReport:
    """Everything one linkage study computed (:func:`run_study`), nothing written yet.

    Attributes
    ----------
    spec : linkage.MechanismSpec
    result : linkage.AnalysisResult
        The plan of positions: kinematics, kinetostatics, cycle summary.
    full : linkage.AnalysisResult or None
        The full turn at ``step`` for the plots (None: no plots).
    step : float
        Crank-angle step of the full turn. [deg]
    warnings : list of str
        The analysis' warnings (singular positions), in English.
    source : Path or None
        The spec file (an input a report may never overwrite).
    name : str
        File stem of every output (the mechanism's name, :func:`crankbase.output.safe_name`).
    """

    spec: object
    result: object
    full: object = None
    step: float = 1.0
    warnings: list = field(default_factory=list)
    source: Path | None = None
    name: str = "linkage"

    def tables(self) -> dict:
        """Every CSV table of the report by its file name (``<name>_kinematics.csv``,
        ``<name>_forces.csv``): the numbers :func:`write_report` writes, bit for bit."""
        n = self.name
        return {f"{n}_kinematics.csv": self.result.kinematics,
                f"{n}_forces.csv": self.result.forces}

    def inputs(self) -> list:
        """The input files of the study (no output may overwrite one)."""
        return [self.source] if self.source is not None else []

    def write_more(self, stage, lang, previews) -> tuple:
        """Hook of a study one layer up (the plans): write its files into the staging
        folder ``stage``; returns ``(file names in order, drawing sheets)``."""
        return [], 0

    def more_lines(self, lang, written=None) -> list:
        """Hook of a study one layer up: its lines of the terminal summary."""
        return []

    def max_driving_moment(self):
        """``(M, position, phi_deg)`` of the largest |Mb| over the positions (M signed
        [N·m], position None at an explicit angle), or None when no moment is finite."""
        F = self.result.forces
        m = F["M_drive_Nm"].abs()
        if not m.notna().any():
            return None
        i = int(m.idxmax())
        pos = F["position"].iat[i]
        import pandas as pd

        return (float(F["M_drive_Nm"].iat[i]), None if pd.isna(pos) else int(pos),
                float(F["phi_deg"].iat[i]))


@dataclass
class ChainReport(LinkageReport):
    """A :class:`LinkageReport` of a chain spec (any linkage of class II groups,
    :mod:`linkage.chain_analysis`): the same tables' files, its own workbook, figures
    (:data:`linkage.chain_report.CHAIN_PLOTS`) and summary lines."""

    chain = True


@dataclass
class WrittenReport:
    """What :func:`write_report` did: ``files`` (names in ``folder``, in the order
    written), ``removed`` (an earlier run's plots of this mechanism not drawn now, deleted)
    and ``sheets`` (drawing sheets of the plans, 0 without plans)."""

    folder: Path
    files: list
    removed: list = field(default_factory=list)
    sheets: int = 0


def check_step(step) -> float:
    """The full turn's step [deg], 0 < step <= 30 and not too many rows; else a
    :class:`SpecError` naming ``step``."""
    from crankbase.validation import rows_problem

    if isinstance(step, bool) or not isinstance(step, (int, float)) \
            or not (0 < step <= 30):
        raise SpecError(Problem("step", Text("errors.linkage.study.step", {"value": step})
                                if isinstance(step, (int, float)) else
                                Text("errors.linkage.study.step_other",
                                     {"value": repr(step)})))
    too_many = rows_problem(360.0 / step + 1, "step")
    if too_many:
        raise SpecError([too_many])
    return float(step)


def run_study(spec, *, step=1.0, plots=True) -> LinkageReport:
    """Run the whole study of a linkage spec; write nothing.

    Parameters
    ----------
    spec : str, Path, dict or linkage.MechanismSpec
        The mechanism spec (a file is read by :func:`linkage.load_spec`).
    step : float
        Crank-angle step of the full turn for the plots, 0 < step <= 30. [deg]
    plots : bool
        Analyse the full turn (the plots); False: the tables only.

    Returns
    -------
    LinkageReport

    Raises
    ------
    SpecError
        A bad ``step`` (naming it), then every problem of the spec.

    See Also
    --------
    plans.study.run_study : the same with the graphical method.
    """
    import warnings

    import linkage
    from crankbase.output import safe_name

    from .analysis import SingularPositionWarning

    step = check_step(step)
    source = None if isinstance(spec, dict) or hasattr(spec, "kind") else Path(spec)
    spec = linkage.load_spec(spec)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SingularPositionWarning)
        result = linkage.analyze(spec)
    full = linkage.full_turn(spec, step) if plots else None
    cls = ChainReport if spec.kind == "chain" else LinkageReport
    return cls(spec=spec, result=result, full=full, step=step,
                         warnings=[str(w.message) for w in caught], source=source,
                         name=safe_name(spec.name, "linkage"))


def write_report(report: LinkageReport, out, lang="ru", formats=("png",),
                 dpi=120) -> WrittenReport:
    """Write a linkage report into the folder ``out`` as one report unit.

    Files (every one named after the mechanism, so the reports of other mechanisms in
    the folder stay): ``<name>_kinematics.csv``, ``<name>_forces.csv``, the workbook
    ``<name>.xlsx``, the plots ``<name>_<plot>.png`` (:data:`PLOTS`, when the report has
    its full turn) and with plans the graphical method's files (:mod:`plans.report`).
    Every file is produced in a staging folder and moved into place only when all are
    complete (:func:`crankbase.output.staged_output`); a plot of this mechanism an
    earlier run drew and this one does not is removed.

    Parameters
    ----------
    report : LinkageReport
    out : path-like
        The output folder (created if needed).
    lang : {"ru", "en"}
        Language of the workbook, the plots and the drawings (the CSV files are the same
        in both).
    formats : tuple of str
        Image formats of the plots.
    dpi : int
        Resolution of the raster plots.

    Returns
    -------
    WrittenReport
    """
    from crankbase.output import save_figure, staged_output
    from crankbase.validation import check_lang

    from .report import write_csvs, write_workbook

    check_lang(lang)
    folder, out = out, Path(out)
    name = report.name
    figures = {}
    chain = getattr(report, "chain", False)
    if report.full is not None and chain:
        from .chain_report import chain_figures

        figures = chain_figures(report.result, report.full, lang=lang)
    elif report.full is not None:
        from .plots import all_figures

        figures = all_figures(report.result, report.full, lang=lang)
    inputs = report.inputs()
    if chain:
        from .chain_report import CHAIN_PLOTS, write_chain_csvs, write_chain_workbook

        write_csvs, write_workbook, stems = write_chain_csvs, write_chain_workbook, CHAIN_PLOTS
    else:
        stems = PLOTS
    stale = [p for p in (out / f"{name}_{s}.{e}" for s in stems for e in formats
                         if s not in figures) if p.exists()]
    files = []
    sheets = 0
    # every file is named after the mechanism (the plans' too): other mechanisms' reports
    # in the folder stay
    with staged_output(out, inputs=inputs, unit=name) as stage:
        before = set(stage.iterdir())
        write_csvs(report.result, stage)
        for csv in sorted(set(stage.iterdir()) - before):   # named after the mechanism
            csv.rename(stage / f"{name}_{csv.name}")
        files += [f"{name}_kinematics.csv", f"{name}_forces.csv"]
        write_workbook(report.result, stage / f"{name}.xlsx", lang=lang)
        files.append(f"{name}.xlsx")
        more, sheets = report.write_more(stage, lang, report.full is not None)
        files += more
        for stem, fig in figures.items():
            save_figure(fig, stage / f"{name}_{stem}", formats=formats, dpi=dpi)
            files += [f"{name}_{stem}.{e}" for e in formats]
    # plots of this mechanism from an earlier run that this run did not draw are stale
    # (the report swap removes those it wrote itself; any other copy goes too)
    removed = []
    for path in stale:
        if path.exists():
            path.unlink()
        if not path.exists():
            removed.append(path)
    return WrittenReport(folder, files, removed, sheets)


def _number(value, fmt, scale=0.0):
    from crankbase.tolerances import format_snapped

    return format_snapped(value, fmt, scale)


def summary_lines(report: LinkageReport, lang="ru", written=None) -> list:
    """The terminal summary of a linkage study in ``lang``: the mechanism and its number
    of positions (``-> folder`` when ``written``, a :class:`WrittenReport`, is given), the
    cycle geometry (:func:`linkage.report.summary_lines`), the largest driving moment over
    the positions, with plans the Zhukovsky lever against the kinetostatics per position
    (:meth:`LinkageReport.more_lines`), and with ``written`` the files written.  Every number is formatted once, the same in both languages; the words
    are the catalogue's (``linkage.po``, ``plans.po``)."""
    from crankbase.texts import texts

    from .report import kind_text
    from .report import summary_lines as cycle_rows

    t = texts(lang)
    spec = report.spec
    statics = t("linkage.summary.statics") if spec.omega == 0 else ""
    head = dict(name=spec.name, kind=kind_text(spec.kind, lang), statics=statics,
                n=len(report.result.kinematics))
    lines = [t("linkage.summary.run", out=written.folder, **head) if written is not None
             else t("linkage.summary.title", **head)]
    dash = t("linkage.summary.dimensionless")
    if getattr(report, "chain", False):
        from .chain_report import chain_summary_rows

        lines += ["  " + row for row in chain_summary_rows(report.result, lang)]
    for label, value, unit in ([] if getattr(report, "chain", False)
                               else cycle_rows(report.result, lang)):
        if isinstance(value, float):
            v, unit = _number(value, ".4f"), unit or dash
        else:
            v = str(value)
        lines.append(f"  {label}: {v} {unit}".rstrip())
    top = report.max_driving_moment()
    if top is not None:
        M, pos, phi = top
        where = "" if pos is None else t("linkage.summary.at_position", pos=pos)
        lines.append("  " + t("linkage.summary.max_moment", M=_number(M, ".2f"),
                              where=where, phi=_number(phi, ".2f")))
    lines += report.more_lines(lang, written)
    if written is not None:
        lines.append(written_line(written, lang))
    return lines


def notice_lines(report: LinkageReport, written: WrittenReport | None = None,
                 lang="ru") -> list:
    """The lines for the error stream, in ``lang``: the plots removed (``written``) and
    the analysis' warnings."""
    from crankbase.texts import texts

    from .report import warning_text

    t = texts(lang)
    lines = [t("linkage.notice.removed", path=p) for p in (written.removed if written
                                                            else [])]
    lines += [t("linkage.notice.warning", w=warning_text(w, lang)) for w in report.warnings]
    return lines


#: Suffixes of the files named one by one in the "wrote" line (images are counted).
_LISTED = (".csv", ".xlsx", ".pdf", ".dxf")


def written_line(written: WrittenReport, lang="ru") -> str:
    """The last line of the summary: the tables, workbook and drawings written (the
    measured segments' errors among them), the number of images, and the folder."""
    from crankbase.texts import texts

    t = texts(lang)
    listed = [f for f in written.files if f.endswith(_LISTED)]
    images = sorted({f.rsplit(".", 1)[1].upper() for f in written.files
                     if not f.endswith(_LISTED)})
    n_img = sum(1 for f in written.files if not f.endswith(_LISTED))
    files = ", ".join(listed)
    if n_img:
        files += ", " + t.n("linkage.summary.images", n_img, formats=", ".join(images))
    return t("common.wrote", files=files, folder=written.folder)
