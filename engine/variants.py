"""Course variants: one base engine spec plus a table with one row per student variant.

The table (CSV or .xlsx, header in the first row) has a ``variant`` (or ``name``) column
and one column per spec key as a dotted path (``engine.bore_mm``, ``masses.rod_kg``,
``table.form`` …).  Each row overrides those keys of the base spec; an empty cell keeps
the base value.  A cell is read as a TOML value when it is one (``79``, ``0.275``,
``true``, ``[372, 375]``, ``"text"``) and as text otherwise.  Every problem of a row is
reported with its row number (as a spreadsheet shows it: the header is row 1) and key; a
bad row never stops the good ones.  :func:`run_variants` runs the whole batch (one
complete report per variant through :func:`engine.run_study` and
:func:`engine.write_report`, a summary table side by side, the problems of the bad rows);
``crankdyn engine --variants`` is this call with a progress bar.  Each variant's folder
also gets the variant's full spec, ``<variant>.toml`` (:func:`write_variant_spec`: the
base with the row applied, the run's step and form written in, its pressure file copied
beside it), which ``crankdyn engine`` / :func:`engine.load` read to the same tables bit
for bit and ``crankdyn check`` takes for that variant; :func:`check_class` grades a whole
class against the variants in one call.
"""
from __future__ import annotations

import copy
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from crankbase.errors import Problem, SpecError, Text

__all__ = ["VariantRow", "read_variants", "parse_cell", "apply_variant", "load_variant",
           "SUMMARY_FIELDS", "summary_record", "NAME_COLUMNS", "run_variants",
           "VariantOutcome", "VariantsRun", "write_summary", "SUMMARY_FILES",
           "variant_spec", "write_variant_spec", "check_class"]

#: Column names that name a variant (case-insensitive), in order of preference.
NAME_COLUMNS = ("variant", "name")


@dataclass
class VariantRow:
    """One variant: its row in the file (header = row 1), its name and the overrides."""

    row: int
    variant: str
    values: dict = field(default_factory=dict)


def parse_cell(value):
    """A table cell as a spec value: numbers stay numbers (integral floats from a
    spreadsheet become ints), text is parsed as a TOML value when it is one, else kept
    as text; an empty cell is ``None`` (keep the base value)."""
    if value is None:
        return None
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, float)):
        if isinstance(value, float) and math.isfinite(value) and value.is_integer():
            return int(value)
        return value
    text = str(value).strip()
    if not text:
        return None
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def _read_rows(path: Path):
    """Header and rows of the first sheet (.xlsx) or of a CSV (``,`` or ``;``)."""
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        from openpyxl import load_workbook

        wb = load_workbook(path, read_only=True, data_only=True)
        rows = [list(r) for r in wb.worksheets[0].iter_rows(values_only=True)]
        wb.close()
    else:
        import csv

        text = path.read_text(encoding="utf-8-sig")
        head = text.splitlines()[0] if text.strip() else ""
        delim = ";" if head.count(";") > head.count(",") else ","
        rows = list(csv.reader(text.splitlines(), delimiter=delim))
    rows = [r for r in rows if any(v not in (None, "") for v in r)]
    if not rows:
        raise SpecError(Problem(str(path), Text("errors.engine.variants.variants_table_empty")))
    return [("" if h is None else str(h).strip()) for h in rows[0]], rows[1:]


def read_variants(path) -> list[VariantRow]:
    """Read a variants table.

    Parameters
    ----------
    path : str or Path
        CSV (UTF-8, ``,`` or ``;`` separated) or .xlsx (first sheet).

    Returns
    -------
    list of VariantRow

    Raises
    ------
    SpecError
        The file is missing or empty, has no ``variant``/``name`` column, a column header
        is empty or repeated, or a variant name is empty or repeated (all at once).
    """
    path = Path(path)
    if not path.is_file():
        raise SpecError(Problem(str(path), Text("errors.engine.variants.variants_file_does")))
    header, rows = _read_rows(path)
    problems = []
    lower = [h.lower() for h in header]
    name_col = next((lower.index(n) for n in NAME_COLUMNS if n in lower), None)
    if name_col is None:
        problems.append(Problem(str(path), Text("errors.engine.variants.no_variant_or",
                                                {"items": ", ".join(header)})))
    for j, h in enumerate(header):
        if not h:
            problems.append(Problem(str(path), Text("errors.engine.variants.column_has_no",
                                                    {"j": j + 1})))
        elif lower.count(h.lower()) > 1 and lower.index(h.lower()) == j:
            problems.append(Problem(str(path), Text("errors.engine.variants.column_appears_more",
                                                    {"h": h})))
    if problems:
        raise SpecError(problems)
    out, seen = [], {}
    for i, r in enumerate(rows, start=2):
        r = list(r) + [None] * (len(header) - len(r))
        name = "" if r[name_col] is None else str(r[name_col]).strip()
        if isinstance(r[name_col], float) and r[name_col].is_integer():
            name = str(int(r[name_col]))
        if not name:
            problems.append(Problem(Text("errors.engine.variants.row", {"row": i}),
                                    Text("errors.engine.variants.column_empty",
                                         {"value": header[name_col]})))
            continue
        if name in seen:
            problems.append(Problem(Text("errors.engine.variants.row", {"row": i}),
                                    Text("errors.engine.variants.variant_repeats_row",
                                         {"name": name, "value": seen[name]})))
            continue
        seen[name] = i
        values = {}
        for j, h in enumerate(header):
            if j == name_col:
                continue
            v = parse_cell(r[j])
            if v is not None:
                values[h] = v
        out.append(VariantRow(i, name, values))
    if problems:
        raise SpecError(problems)
    return out


def apply_variant(base: dict, variant: VariantRow) -> dict:
    """The base spec dict with the variant's dotted keys set (a deep copy).  Without an
    ``engine.name`` column the engine is named after the variant.

    Raises
    ------
    SpecError
        A dotted path runs through a value that is not a table (``row N: key: …``).
    """
    spec = copy.deepcopy(base)
    problems = []
    values = dict(variant.values)
    values.setdefault("engine.name", variant.variant)
    for key, value in values.items():
        parts = key.split(".")
        node = spec
        for k, part in enumerate(parts[:-1]):
            nxt = node.setdefault(part, {})
            if not isinstance(nxt, dict):
                problems.append(Problem(
                    Text("errors.engine.variants.row_key", {"row": variant.row, "key": key}),
                    Text("errors.engine.variants.value_not_table",
                         {"items": '.'.join(parts[:k + 1])})))
                break
            node = nxt
        else:
            node[parts[-1]] = value
    if problems:
        raise SpecError(problems)
    return spec


def load_variant(base: dict, variant: VariantRow, base_dir=None):
    """Apply a variant and validate it: an :class:`~engine.EngineStudy`, or a
    :class:`SpecError` whose every problem starts with ``row N (variant): key``."""
    from .spec import load

    try:
        return load(apply_variant(base, variant), base_dir=base_dir)
    except SpecError as exc:
        raise SpecError([Problem(
            Text("errors.engine.variants.row_variant_key",
                 {"row": variant.row, "variant": variant.variant, "key": p.key})
            if p.key and not str(p.key).startswith("row ") else
            Text("errors.engine.variants.row_variant",
                 {"row": variant.row, "variant": variant.variant}), p.text or p.message)
            for p in exc.problems]) from None


def variant_spec(base: dict, variant: VariantRow, base_dir=None, step=None, form=None):
    """The variant's full spec, as it is written beside its report.

    The base with the row applied (:func:`apply_variant`), the run's ``step`` and ``form``
    (when given) written into ``[table]``, and a pressure file (``[pressure] file``) given
    by its bare name, for a copy beside the spec.

    Returns
    -------
    spec : dict
    pressure_file : Path or None
        The pressure file the variant reads (resolved against ``base_dir``), to be copied
        beside the spec; None for an inline diagram or a ``[pressure.cycle]``.
    """
    spec = apply_variant(base, variant)
    table = spec.setdefault("table", {})
    if step is not None:
        table["step_deg"] = step
    if form is not None:
        table["form"] = form
    if not table:
        del spec["table"]
    pr = spec.get("pressure")
    source = None
    if isinstance(pr, dict) and isinstance(pr.get("file"), str):
        source = Path(pr["file"])
        if not source.is_absolute():
            source = Path(base_dir or ".") / source
        pr["file"] = source.name
    return spec, source


def write_variant_spec(base: dict, variant: VariantRow, folder, base_dir=None, step=None,
                       form=None, lang: str = "ru", inputs=()) -> Path:
    """Write the variant's full spec into its folder: ``folder/<folder name>.toml`` (and
    its pressure file copied beside it, the path in the TOML relative), as one unit of the
    folder (:func:`crankbase.output.staged_output`; the report's own files stay).

    The spec loads with :func:`engine.load` (``crankdyn engine``) to the very tables of
    the variant's report, bit for bit (:func:`variant_spec`).  Returns the spec's path.
    """
    import shutil

    import tomli_w

    from crankbase.output import staged_output
    from crankbase.texts import texts

    t = texts(lang)
    folder = Path(folder)
    spec, pressure = variant_spec(base, variant, base_dir, step, form)
    path = folder / f"{folder.name}.toml"
    head = t("variants.spec.comment", variant=variant.variant, row=variant.row,
             file=path.name)
    text = "".join(f"# {ln}\n" for ln in head.splitlines()) + "\n" + tomli_w.dumps(spec)
    with staged_output(folder, inputs=list(inputs), unit=f"{folder.name}.toml") as stage:
        (stage / path.name).write_text(text, encoding="utf-8")
        if pressure is not None:
            shutil.copyfile(pressure, stage / pressure.name)
    return path


#: Columns of the variants summary: (column, how it is obtained from spec and summary).
SUMMARY_FIELDS = ("variant", "name", "bore_mm", "stroke_mm", "lambda", "speed_rpm",
                  "mj_kg", "m_rod_rot_kg", "Kr_N", "p_max_MPa", "alpha_p_max_deg",
                  "P_max_N", "alpha_P_max_deg", "T_max_N", "alpha_T_max_deg", "T_min_N",
                  "M_mean_Nm", "R_max_N", "alpha_R_max_deg", "R_mean_N", "chi", "pi_MPa",
                  "power_i_kW")


def summary_record(variant: str, spec, summary) -> dict:
    """The key inputs and results of one variant, side by side with the others (values
    taken from the spec and from its :class:`~engine.EngineSummary`, nothing
    recomputed)."""
    s = summary
    return dict(
        variant=variant, name=spec.name, bore_mm=spec.bore * 1e3, stroke_mm=spec.stroke * 1e3,
        **{"lambda": spec.lam}, speed_rpm=spec.speed_rpm, mj_kg=spec.mj,
        m_rod_rot_kg=spec.m_rod_rot, Kr_N=spec.Kr, p_max_MPa=s.p_max_MPa,
        alpha_p_max_deg=s.alpha_p_max_deg, P_max_N=s.P_N.max,
        alpha_P_max_deg=s.P_N.alpha_max_deg, T_max_N=s.T_N.max,
        alpha_T_max_deg=s.T_N.alpha_max_deg, T_min_N=s.T_N.min, M_mean_Nm=s.M_mean_Nm,
        R_max_N=s.R_N.max, alpha_R_max_deg=s.R_N.alpha_max_deg, R_mean_N=s.R_mean_N,
        chi=s.chi, pi_MPa=s.pi_MPa, power_i_kW=s.power_i_kW)


#: The files of a variants run beside the variants' folders.
SUMMARY_FILES = ("variants_summary.csv", "variants_summary.xlsx", "variants_errors.csv")


@dataclass(frozen=True)
class VariantOutcome:
    """What became of one variant of a :func:`run_variants` batch.

    Attributes
    ----------
    variant : VariantRow
    folder : Path
        Its report folder (``<out>/<variant as a file stem>``).
    record : dict or None
        Its :func:`summary_record` when its report was written.
    problems : tuple of str
        Every problem of a bad row (``row N (variant): key: problem``); empty when written.
    kept_earlier : bool
        The row is bad and its folder holds an earlier report, which was not replaced.
    spec : Path or None
        The variant's full spec written into its folder (:func:`write_variant_spec`).
    """

    variant: VariantRow
    folder: Path
    record: dict | None = None
    problems: tuple = ()
    kept_earlier: bool = False
    spec: Path | None = None

    @property
    def ok(self) -> bool:
        return not self.problems


@dataclass(frozen=True)
class VariantsRun:
    """A whole variants batch (:func:`run_variants`).

    Attributes
    ----------
    folder : Path
    outcomes : tuple of VariantOutcome
        One per row, in the table's order.
    summary_csv, summary_xlsx : Path
    errors_csv : Path or None
        ``variants_errors.csv`` when a row failed.
    """

    folder: Path
    outcomes: tuple
    summary_csv: Path
    summary_xlsx: Path
    errors_csv: Path | None = None

    @property
    def records(self) -> list:
        """The summary records of the variants written, in the table's order."""
        return [o.record for o in self.outcomes if o.ok]

    @property
    def failures(self) -> list:
        """The outcomes of the bad rows, in the table's order."""
        return [o for o in self.outcomes if not o.ok]

    def summary_lines(self, lang: str = "ru") -> list[str]:
        """How many variants were written and failed (the failed rows), the summary table
        and, when any was written, where each variant's spec is, in ``lang``."""
        from crankbase.texts import texts

        t = texts(lang)
        bad = self.failures
        rows = "" if not bad else t.n("variants.summary.failed_rows", len(bad),
                                      rows=", ".join(str(o.variant.row) for o in bad))
        return [t.n("variants.summary.result", len(self.outcomes),
                    written=len(self.outcomes) - len(bad), folder=str(self.folder),
                    failed=len(bad), rows=rows),
                t("variants.summary.table", path=str(self.summary_xlsx))] + (
            [t("variants.summary.specs")] if len(bad) < len(self.outcomes) else [])


def _one_variant(task) -> VariantOutcome:
    """Validate one variant and write its complete report.  A module-level function, so
    that a process pool can run it."""
    from crankbase.errors import CrankdynError

    from .study import run_study, write_report

    base, v, base_dir, inputs, folder, lang, step, form, bearings, drawing, formats = task
    try:
        study = load_variant(base, v, base_dir)
        report = run_study(study, bearings=bearings, step=step, form=form,
                           source=apply_variant(base, v))
        write_report(report, folder, lang, formats=formats, drawing=drawing,
                     inputs=inputs)
        spec = write_variant_spec(base, v, folder, base_dir, step, form, lang, inputs)
    except CrankdynError as exc:
        from crankbase.texts import texts

        t = texts(lang)
        lines = exc.lines(lang) or [str(exc)]
        head = t("errors.engine.variants.row", row="").strip()
        return VariantOutcome(v, folder, problems=tuple(
            ln if ln.startswith(head) else
            t("errors.engine.variants.row_line", row=v.row, variant=v.variant, line=ln)
            for ln in lines), kept_earlier=folder.exists())
    return VariantOutcome(v, folder, summary_record(v.variant, report.study.spec,
                                                    report.cylinder.summary), spec=spec)


def run_variants(base, variants, out, lang: str = "ru", step=None, form=None,
                 bearings: bool = False, drawing: bool = False, jobs: int = 1,
                 progress=None, formats=("png", "svg")) -> VariantsRun:
    """One complete engine report per variant, and the summary table.

    Parameters
    ----------
    base : str or Path
        The base engine spec file.
    variants : str or Path
        The variants table (:func:`read_variants`).
    out : str or Path
        The output folder: each good variant's report goes into ``out/<variant>/``
        (:func:`engine.write_report`) with its full spec ``<variant>.toml``
        (:func:`write_variant_spec`), the summary into ``out/variants_summary.csv`` and
        ``.xlsx``, the problems of bad rows into ``out/variants_errors.csv``.
    lang : {"ru", "en"}, default "ru"
    step, form, bearings, drawing
        As :func:`engine.run_study` and :func:`engine.write_report`, for every variant.
    jobs : int, default 1
        Reports written at a time (separate processes when more than one).
    progress : callable, optional
        Called as ``progress(outcome, total)`` with each :class:`VariantOutcome` as it is
        done (in the order done) and the number of variants.
    formats : sequence of {"png", "svg", "pdf"}, default ("png", "svg")
        Formats of each variant's figures (:func:`engine.write_report`); empty
        (``()``): no figure is built or written, each report has its tables and
        workbook only (a check of the numbers or the names of many reports need not
        draw 13 figures for each).

    Returns
    -------
    VariantsRun
        A bad row does not stop the others: its problems are in its outcome.

    Raises
    ------
    SpecError
        The table cannot be read, two variants would share a folder, or ``jobs`` is not a
        whole number >= 1 (nothing written).
    OutputError
        A summary file would overwrite an input.
    """
    from crankbase.output import check_not_input, figure_formats, safe_name
    from crankbase.validation import check_lang
    from crankbase.validation import read_toml

    check_lang(lang)
    if not isinstance(formats, str):
        formats = tuple(formats)
    formats = figure_formats(formats) if formats != () else ()
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise SpecError(Problem("jobs", Text("errors.engine.variants.whole_number",
                                             {"jobs": jobs})))
    base_path, variants_path, out = Path(base), Path(variants), Path(out)
    base_dict, base_dir = read_toml(base_path)
    rows = read_variants(variants_path)
    folders, clash = {}, []
    for v in rows:
        f = safe_name(v.variant, "variant")
        if f in folders:
            clash.append(Text("errors.engine.variants.folder_clash",
                              {"row": v.row, "variant": v.variant, "folder": f,
                               "row2": folders[f].row, "variant2": folders[f].variant}))
        folders[f] = v
    if clash:
        raise SpecError(clash)
    check_not_input([out / name for name in SUMMARY_FILES], [base_path, variants_path])

    inputs = (base_path, variants_path)
    tasks = [(base_dict, v, base_dir, inputs, out / folder, lang, step, form, bearings,
              drawing, formats) for folder, v in folders.items()]
    done = []
    if jobs == 1:
        for task in tasks:
            done.append(_one_variant(task))
            if progress is not None:
                progress(done[-1], len(tasks))
    else:
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor, as_completed

        with ProcessPoolExecutor(max_workers=jobs,
                                 mp_context=multiprocessing.get_context("spawn")) as pool:
            for fut in as_completed([pool.submit(_one_variant, t) for t in tasks]):
                done.append(fut.result())
                if progress is not None:
                    progress(done[-1], len(tasks))
    outcomes = tuple(sorted(done, key=lambda o: o.variant.row))     # the table's order
    paths = write_summary(out, [o.record for o in outcomes if o.ok],
                          [(o.variant, o.problems) for o in outcomes if not o.ok], lang)
    return VariantsRun(out, outcomes, *paths)


def write_summary(out, records, failures, lang: str = "ru"):
    """``variants_summary.csv`` and ``.xlsx`` (and ``variants_errors.csv`` when rows
    failed: ``failures`` as ``(VariantRow, problem lines)``), each written atomically; an
    errors file of an earlier run is removed when none failed.  Returns the three paths
    (the errors file None when none failed)."""
    import pandas as pd

    from crankbase.output import write_csv
    from crankbase.texts import texts

    t = texts(lang)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    df = pd.DataFrame(records, columns=list(SUMMARY_FIELDS))
    summary_csv, summary_xlsx, errors = (out / name for name in SUMMARY_FILES)
    write_csv(df, summary_csv)
    if failures:
        err = pd.DataFrame([(v.row, v.variant, ln) for v, lines in failures for ln in lines],
                           columns=["row", "variant", "problem"])
        write_csv(err, errors)
    elif errors.exists():
        errors.unlink()

    from crankbase.workbook import summary_workbook

    summary_workbook(df, summary_xlsx, t("variants.workbook.title"), sheet="variants")
    return summary_csv, summary_xlsx, errors if failures else None


def _variant_side(base: dict, variant: VariantRow, base_dir):
    """The check side of one variant (:func:`engine.check.check_side` of its spec)."""
    from .check import check_side

    return check_side(load_variant(base, variant, base_dir))


def check_class(base, variants, students, out, lang: str = "ru", rtol=None, atol=None,
                mapping=None):
    """Grade a whole class in one call: every student's file of a folder against its own
    variant of the base spec.

    Parameters
    ----------
    base : str or Path
        The base engine spec file.
    variants : str or Path
        The variants table (:func:`read_variants`).
    students : str or Path
        The folder of the students' files (``.xlsx``, ``.xlsm``, ``.csv``).  Each file is
        matched to a variant by :func:`crankbase.checking.match_variant`: the variant's
        name as a whole word of the file name (``ivanov_v02.xlsx`` → ``v02``), or the
        variant the workbook names in a cell labelled «Вариант»/«Variant».
    out : str or Path
        Output folder: ``class_check.csv`` / ``.xlsx`` (``student, variant,
        columns_wrong, cells_wrong, verdict, detail``, one line per file) and, per student
        checked, ``out/<file stem>/`` with its ``check.csv`` and checked workbook.
    lang, rtol, atol, mapping
        As :func:`crankbase.checking.check_table`.

    Returns
    -------
    crankbase.checking.ClassCheck
        A file matched to no variant or to several, unreadable, or of a variant whose
        row has errors is a line of the verdict table, not an exception.

    Raises
    ------
    SpecError
        The base spec or the variants table cannot be read, the students' folder is
        missing, or bad tolerances or mapping.
    """
    from functools import partial

    from crankbase.checking import check_class as check_all
    from crankbase.validation import read_toml

    base_path, variants_path = Path(base), Path(variants)
    base_dict, base_dir = read_toml(base_path)
    rows = read_variants(variants_path)
    sides = {v.variant: partial(_variant_side, base_dict, v, base_dir) for v in rows}
    return check_all(sides, students, out, lang, rtol, atol, mapping,
                     inputs=(base_path, variants_path))
