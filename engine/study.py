"""The engine study as one library call: compute everything, then write the report.

pvlib's ``ModelChain`` is the model: :func:`run_study` takes an :class:`~engine.EngineStudy`
(what :func:`engine.load` returns) and runs the whole chain — one cylinder
(:func:`engine.analyze`), the whole engine (:func:`engine.analyze_engine`), Table 2 in the
settings' form, and the bearing loads when asked (or when the spec has a ``[bearings]`` or
``[rod]`` table) — into a frozen :class:`EngineReport`: every table the report writes, the
typed results, nothing drawn and nothing written.  :func:`write_report` then writes it
(CSVs, workbook, figures, the drawing-scale PDFs) into a folder as one unit
(:func:`crankbase.output.staged_output`), and :func:`engine.summary.summary_lines` gives
the terminal summary in the report's language.  ``crankdyn engine``, the course variants
(:mod:`engine.variants`) and any script use these two calls.

Examples
--------
>>> import engine
>>> from crankbase.resources import example_path
>>> report = engine.run_study(engine.load(example_path("petrol_vaz2106.toml")))
>>> list(report.tables)
['forces.csv', 'table2.csv', 'cylinders.csv', 'torque.csv', 'balance.csv']
>>> round(report.whole.summary.M_mean_Nm, 1)
122.6
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from types import MappingProxyType

from crankbase.errors import Problem, SpecError, Text
from crankbase.output import FIGURE_FORMATS    # the formats write_report takes

__all__ = ["EngineReport", "BearingReport", "ReportFiles", "run_study", "write_report", "report_workbook",
           "with_options", "output_names", "FIGURE_FORMATS"]


@dataclass(frozen=True)
class BearingReport:
    """The bearing part of an engine report.

    Attributes
    ----------
    analysis : engine.bearing_spec.BearingAnalysis or engine.train_bearings.EngineBearings
        The analysis on the fine grid (plots, wear diagrams, the summary).
    pin_wear : tuple of WearDiagram
        The crank-pin wear diagrams (one per throw).
    tables : Mapping of str to pandas.DataFrame
        ``crankpins.csv``, ``journals.csv``, ``journal_torques.csv``, ``rod_bearings.csv``,
        ``wear.csv`` (and ``rod_model.csv`` with the rigid rod) at the table rows.
    plot_names : tuple of str
        The bearing figures this analysis has (:data:`engine.bearing_plots.BEARING_PLOT_NAMES`
        without the piston pin when its load is unknown, without the rod-model comparison
        for the two-mass rod).
    """

    analysis: object
    pin_wear: tuple
    tables: Mapping
    plot_names: tuple


@dataclass(frozen=True)
class EngineReport:
    """Everything an engine report holds, computed and checked, nothing written.

    Attributes
    ----------
    study : EngineStudy
        The study with the table options applied.
    cylinder : EngineResult
        One cylinder: the force table, the fine curves, the summary.
    whole : EngineTrainResult
        The whole engine: layout, total torque, flywheel, balance.
    bearings : BearingReport or None
        The bearing loads, when asked or when the spec has ``[bearings]``/``[rod]``.
    tables : Mapping of str to pandas.DataFrame
        Every CSV of the report by its short name, in the order written: ``forces.csv``,
        ``table2.csv``, ``cylinders.csv``, ``torque.csv``, ``balance.csv``, then the bearing
        tables.  The file is ``<name>_<short name>``.
    name : str
        The engine's name as a file stem (every output is named after it).
    plot_names : tuple of str
        The figures of the report (without the drawing-scale ones).
    source : Path or None
        The spec file the study was read from (an input no output may overwrite).
    torsion : torsion.study.TorsionReport or None
        The torsional vibration of the crankshaft, when the spec has ``[torsion]`` (its
        own tables, workbook ``<name>_torsion.xlsx`` and figures, written beside the
        engine's: :func:`torsion.study.run_study`).
    """

    study: object
    cylinder: object
    whole: object
    bearings: BearingReport | None
    tables: Mapping
    name: str
    plot_names: tuple
    source: Path | None = None
    torsion: object = None

    @property
    def file_names(self) -> dict:
        """``{short name: file name}`` of every table and figure stem."""
        return output_names(self.name, list(self.tables) + list(self.plot_names))

    def summary_lines(self, lang: str = "ru", written=None) -> list[str]:
        """The terminal summary in ``lang`` (:func:`engine.summary.summary_lines`)."""
        from .report.summary import summary_lines

        return summary_lines(self, lang, written)


@dataclass(frozen=True)
class ReportFiles:
    """The files :func:`write_report` wrote (iterating gives every path, in order).

    Attributes
    ----------
    folder : Path
    tables : tuple of Path
        The CSVs, in the order of :attr:`EngineReport.tables`.
    workbook : Path
    plots : tuple of Path
        Every figure file (each plot in each format).
    plot_count : int
        How many figures (each saved in every one of ``formats``).
    formats : tuple of str
    drawings : tuple of Path
        The 1:1 drawing-scale PDFs (``drawing=True``).
    torsion : tuple of Path
        The torsional-vibration files (CSVs, workbook, figures) of a report with
        ``[torsion]``.
    """

    folder: Path
    tables: tuple
    workbook: Path
    plots: tuple
    plot_count: int
    formats: tuple
    drawings: tuple = ()
    torsion: tuple = ()

    @property
    def paths(self) -> tuple:
        return (*self.tables, self.workbook, *self.plots, *self.drawings, *self.torsion)

    def __iter__(self):
        return iter(self.paths)

    def __len__(self):
        return len(self.paths)


def output_names(stem, names) -> dict:
    """``{name: file name}`` of every output, named after the engine (``<stem>_<name>``),
    so that reports of two engines in one folder never mix."""
    return {n: f"{stem}_{n}" for n in names}


def with_options(study, step=None, form=None):
    """The study with a table step [deg] and a Table 2 form (``"seed"`` or ``"kolchin"``)
    applied to its :class:`~engine.TableSettings` (presentation only; the physics is
    untouched).  ``None`` keeps the spec's value.

    Raises
    ------
    SpecError
        A bad step (named ``step``) or form (named ``form``).
    """
    settings = study.settings
    if step is not None:
        from crankbase.validation import step_argument

        spec = study.spec
        rows = spec.cycle_deg + len(settings.extra_angles_deg) * step
        settings = replace(settings, step_deg=step_argument(step, "step", spec.cycle_deg,
                                                             rows_span=rows))
    if form is not None:
        from .table2 import FORMS

        if form not in FORMS:
            raise SpecError(Problem("form", Text("errors.engine.study.one",
                                                 {"form": form, "items": ", ".join(FORMS)})))
        settings = replace(settings, form=form)
    return replace(study, settings=settings)


def run_study(study, *, bearings: bool = False, step=None, form=None,
              source=None, torsion: bool = False) -> EngineReport:
    """Compute a whole engine report: one cylinder, the whole engine, Table 2 and, when
    asked, the bearing loads.  Nothing is drawn or written (:func:`write_report`).

    Parameters
    ----------
    study : EngineStudy, or str, Path or dict
        What :func:`engine.load` returns; a spec file (or dict) is loaded first and is
        then also the ``source``.
    bearings : bool, default False
        Also the bearing loads (crank pins, main journals, journal torques, big end and
        piston pin, wear diagrams).  A spec with a ``[bearings]`` or ``[rod]`` table has
        them anyway.
    step : float, optional
        Table step [deg], overriding ``[table] step_deg``.
    form : {"seed", "kolchin"}, optional
        Table 2's form, overriding ``[table] form``.
    source : str, Path or dict, optional
        The spec file the study was loaded from: an input that no output may overwrite.
        (The ``[bearings]`` and ``[rod]`` tables come with the study, ``study.bearings``,
        read once by :func:`engine.load`.)
    torsion : bool, default False
        Also the torsional vibration of the crankshaft (:mod:`torsion.study`).  A spec
        with a ``[torsion]`` table has it anyway; asked without the table it is an error
        (the shaft's stiffnesses cannot be guessed).

    Returns
    -------
    EngineReport

    Raises
    ------
    SpecError
        Bad options or a bad ``[bearings]``/``[rod]`` table.
    NumericalError
        A non-finite value in a table.
    """
    from crankbase.output import ensure_finite, safe_name

    from .plots.cylinder import PLOT_NAMES
    from .plots.whole import TRAIN_PLOT_NAMES
    from .spec import EngineStudy, load
    from .table2 import table2
    from .train import analyze_engine

    if not isinstance(study, EngineStudy):
        if source is None:
            source = study
        study = load(study)
    study = with_options(study, step, form)
    spec, settings = study.spec, study.settings
    b_inputs = study.bearings          # [bearings] and [rod], read once by engine.load
    whole = analyze_engine(spec, study.train, settings)
    result = whole.cylinder
    table = result.table
    ensure_finite(table, "force table")
    ensure_finite(result.curves, "force table (plot grid)")
    for df, what in ((whole.torque, "torque"), (whole.balance, "balance")):
        ensure_finite(df, what)
    tables = {"forces.csv": table, "table2.csv": table2(table, spec, settings),
              "cylinders.csv": whole.layout.cylinders, "torque.csv": whole.torque,
              "balance.csv": whole.balance}
    plot_names = PLOT_NAMES + TRAIN_PLOT_NAMES
    bearing = None
    if bearings or b_inputs.asked:
        bearing = _bearings(spec, table, result.curves, b_inputs, whole)
        tables.update(bearing.tables)
        plot_names += bearing.plot_names
    source = Path(source) if isinstance(source, (str, Path)) else None
    vibration = None
    if torsion and study.torsion is None:
        raise SpecError([Problem("torsion", Text("torsion.error.no_table"))])
    if study.torsion is not None:
        from torsion.study import run_study as run_torsion

        vibration = run_torsion(study, source=source)
    return EngineReport(study=study, cylinder=result, whole=whole, bearings=bearing,
                        tables=MappingProxyType(tables), name=safe_name(spec.name, "engine"),
                        plot_names=tuple(plot_names), source=source, torsion=vibration)


def _bearings(spec, table, fine, inputs, whole) -> BearingReport:
    """Bearing loads: one cylinder by its spec ([bearings] journal positions and
    counterweight), a whole engine by its layout and counterweights.  Tables at the table
    rows; plots, wear diagrams and the summary from the fine grid."""
    from crankbase.output import ensure_finite

    from .bearings.analysis import bearing_analysis, wear_table
    from .plots.bearing import BEARING_PLOT_NAMES

    lay = whole.layout
    if lay.n == 1:
        rows = bearing_analysis(spec, table, inputs)
        res = bearing_analysis(spec, fine, inputs)
    else:
        from .bearings.train import engine_bearings, layout_cylinders

        cyl, tau, zt = layout_cylinders(lay)
        cw = [(c.z, c.mr, c.angle_deg) for c in whole.summary.counterweights]

        def run(theta):
            return engine_bearings(spec, theta, cyl, tau, zt, counterweights=cw,
                                   inputs=inputs)
        rows, res = run(table["alpha_deg"].to_numpy()), run(fine["alpha_deg"].to_numpy())
    rb = rows.rod_bearings
    if rows.m_piston is None:                       # piston mass unknown: big end only
        rb = rb.drop(columns=["Pp_axial_N", "Pp_side_N", "Pp_N"])
    pin_wear = tuple(res.pin_wear if isinstance(res.pin_wear, list) else [res.pin_wear])
    tables = {"crankpins.csv": rows.loads.crankpins, "journals.csv": rows.loads.journals,
              "journal_torques.csv": rows.loads.journal_torques, "rod_bearings.csv": rb,
              "wear.csv": wear_table(list(pin_wear) + res.journal_wear)}
    if rows.rod_comparison is not None:
        tables["rod_model.csv"] = rows.rod_comparison.table
    for name, df in tables.items():
        ensure_finite(df, name)
    names = tuple(n for n in BEARING_PLOT_NAMES
                  if not (n == "piston_pin" and res.rod_bearings["Pp_N"].isna().all())
                  and not (n == "rod_model" and res.rod_comparison is None))
    return BearingReport(analysis=res, pin_wear=pin_wear, tables=MappingProxyType(tables),
                         plot_names=names)


def report_workbook(report: EngineReport, lang: str = "ru"):
    """The report's workbook, built in memory (not saved): the template's sheets of the
    cylinder, the whole engine's sheets, the bearing sheets when the report has them, A4
    print setup (:func:`engine.report.a4_setup`).  :func:`write_report` saves it."""
    from .report.workbook import a4_setup, add_engine_sheets, build_workbook

    wb = add_engine_sheets(build_workbook(report.cylinder, lang), report.whole, lang)
    if report.bearings is not None:
        from .report.bearing_sheets import add_bearing_sheets

        add_bearing_sheets(wb, dict(report.bearings.tables), report.bearings.analysis, lang)
    return a4_setup(wb)


def write_report(report: EngineReport, out, lang: str = "ru", formats=("png", "svg"),
                 drawing: bool = False, inputs=()) -> ReportFiles:
    """Write an engine report into the folder ``out`` as one unit.

    Writes ``<name>_<table>.csv`` for every table of the report, ``<name>.xlsx`` (from the
    template in ``lang``), every figure as ``<name>_<plot>.<format>`` and, with
    ``drawing``, the 1:1 drawing-scale PDFs ``<name>_drawing_*.pdf``, all through a staging
    folder (:func:`crankbase.output.staged_output`): a failure while building or saving
    anything writes nothing and leaves an earlier report whole.  Figures of this engine
    that this run does not draw (the bearing plots of an earlier ``bearings`` run, an
    earlier drawing, a format not asked for) are removed.

    Parameters
    ----------
    report : EngineReport
        From :func:`run_study`.
    out : str or Path
        The output folder (created if needed).
    lang : {"ru", "en"}, default "ru"
        Language of the workbook and the figures.
    formats : sequence of {"png", "svg", "pdf"}, default ("png", "svg")
        Formats of the figures; empty (``()``): no figure is built or written (the
        tables and the workbook only, as a check of names or numbers needs; the figures
        of an earlier run of this engine are removed as stale).
    drawing : bool, default False
        Also the diagrams at the drawing scale, 1:1 PDF on millimetre paper.
    inputs : sequence of path
        Input files no output may overwrite (the spec file and the pressure file are
        always among them).

    Returns
    -------
    ReportFiles
        The paths written (iterate over it, or its ``tables``, ``workbook``, ``plots``,
        ``drawings``).

    Raises
    ------
    SpecError
        A bad ``lang`` or ``formats``.
    OutputError
        An output would overwrite an input, or the folder cannot be written.
    """
    import matplotlib

    from crankbase.output import (check_not_input, figure_formats, output_folder, save_figure,
                                  staged_output, write_csv)
    from crankbase.validation import check_lang

    from .plots.bearing import BEARING_PLOT_NAMES
    from .plots.cylinder import PLOT_NAMES, figures
    from .plots.drawing import DRAWING_NAMES, drawing_figures
    from .plots.whole import TRAIN_PLOT_NAMES, train_figures
    from .report.workbook import save_workbook

    check_lang(lang)
    if not isinstance(formats, str):
        formats = tuple(formats)
    formats = figure_formats(formats) if formats != () else ()
    out = output_folder(out)
    name, result, whole = report.name, report.cylinder, report.whole
    files = report.file_names
    pdfs = output_names(name, DRAWING_NAMES) if drawing else {}
    xlsx = out / f"{name}.xlsx"
    tables = tuple(out / files[n] for n in report.tables)
    plots = tuple(out / f"{files[n]}.{e}" for n in report.plot_names for e in formats)
    drawings = tuple(out / f"{f}.pdf" for f in pdfs.values())
    inputs = [*inputs, *([report.source] if report.source is not None else []),
              report.study.spec.pressure_file]
    vib = vib_paths = None
    if report.torsion is not None:
        from torsion import study as vib

        vib_paths = vib.output_paths(report.torsion, out, formats)
    torsion_files = () if vib_paths is None else (
        *vib_paths["tables"], vib_paths["workbook"], *vib_paths["plots"])
    check_not_input([xlsx, *tables, *plots, *drawings, *torsion_files], inputs)

    # 1. build everything in memory
    wb = report_workbook(report, lang)
    figs = {}
    if formats:
        figs.update(figures(result, lang))
        figs.update(train_figures(whole, lang))
    if formats and report.bearings is not None:
        from .plots.bearing import bearing_figures

        figs.update(bearing_figures(report.bearings.analysis, lang))
    if drawing:
        figs.update(drawing_figures(result, lang))
    vib_wb = vib_figs = None
    if vib is not None:
        vib_wb, vib_figs = vib.build_outputs(report.torsion, lang)

    # 2. write: every file into a staging folder, moved into the folder only when all are
    #    done; SVG text stays text (searchable, and a third cheaper to write than glyph paths)
    with staged_output(out, inputs=inputs, unit=name) as stage, \
            matplotlib.rc_context({"svg.fonttype": "none"}):
        for n, df in report.tables.items():
            write_csv(df, stage / files[n])
        save_workbook(wb, stage / xlsx.name)
        for n in (report.plot_names if formats else ()):
            save_figure(figs[n], stage / files[n], formats=formats)
        for n, f in pdfs.items():                      # 1:1, vector only
            save_figure(figs[n], stage / f, formats=("pdf",))
        if vib is not None:                            # [torsion]: its own files
            vib.write_into(stage, report.torsion, vib_wb, vib_figs, formats)
    # figures of this engine from an earlier run that this run did not write are stale
    written = {p.name for p in (*plots, *drawings)}
    for n in set(PLOT_NAMES + TRAIN_PLOT_NAMES + BEARING_PLOT_NAMES + DRAWING_NAMES):
        for ext in FIGURE_FORMATS:
            path = out / f"{name}_{n}.{ext}"
            if path.name not in written and path.exists():
                path.unlink()
    return ReportFiles(folder=out, tables=tables, workbook=xlsx, plots=plots,
                       plot_count=len(report.plot_names) if formats else 0,
                       formats=formats,
                       drawings=drawings, torsion=torsion_files)
