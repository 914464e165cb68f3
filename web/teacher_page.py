"""The teacher's page: a whole class's reports from a base spec and a variants table.

The teacher uploads the base engine spec (with its pressure file when it names one) and
the variants table (CSV or .xlsx: a ``variant`` column and one column per spec key); the
batch is :func:`engine.variants.run_variants` (each variant's complete report, its spec,
the summary table, the bad rows' problems), run in processes (its figures are drawn there,
not in the server's drawing thread) while the page shows a progress bar; the result is one
zip of every report and the summary.

The second form checks one student's work (:func:`check_work`, ``crankdyn check SPEC
STUDENT``): the spec (with its pressure file) and the student's workbook or CSV, written
under the server's own names into the session's folder, go through the library
(:func:`engine.check.spec_check_side`, :func:`crankbase.checking.check_table` and
:func:`~crankbase.checking.write_check`); the page shows the verdict per column, the wrong
cells, and offers ``check.csv`` and the checked workbook (wrong cells red, with comments).

The third checks a whole class (:func:`check_class_work`, ``crankdyn check BASE.toml
--variants variants.csv STUDENTS_DIR``): the base spec and the variants table are written
as the first form writes them (:func:`prepare`), the students' files under their own
sanitized base names into ``students/``, and :func:`engine.variants.check_class` grades
each against its variant; the page shows ``class_check.csv`` and offers it, its workbook
and a zip of the whole output folder.
"""
from __future__ import annotations

import shutil
import threading
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Batch", "TeacherState", "MAX_VARIANTS", "prepare", "run_batch", "CheckRun",
           "CheckProblem", "check_work", "CHECK_FIELDS", "STUDENT_NAMES", "ClassRun",
           "check_class_work", "CLASS_FIELDS", "CLASS_FILES", "student_file_name"]

#: Variants of one batch at most (a class is 20 to 40; each report takes seconds).
MAX_VARIANTS = 100
#: Processes drawing the reports of one batch.
BATCH_JOBS = 2


@dataclass
class Batch:
    number: int
    folder: Path
    total: int
    lang: str
    done: int = 0
    future: object = None
    zip_name: str = "class_reports.zip"


@dataclass
class CheckRun:
    """One student's work checked: the verdict, the wrong cells and the files."""

    number: int
    folder: Path
    lines: tuple            # the verdict, as ``crankdyn check`` prints it
    ok: bool
    head: list              # the wrong cells (check.csv's columns and text)
    rows: list
    wrong: int
    files: dict             # {download name: path}
    marked: str | None      # the checked workbook's download name


@dataclass
class ClassRun:
    """A whole class checked: the verdict lines, the verdict table and the files."""

    number: int
    folder: Path
    lines: tuple            # the class verdict, as ``crankdyn check --variants`` prints it
    ok: bool
    not_right: int          # students not right (wrong, unmatched or unreadable)
    head: list              # class_check.csv's header (in the page's language)
    rows: list              # and rows, as written
    files: dict             # {download name: path}


@dataclass
class TeacherState:
    batch: Batch | None = None
    problems: list = field(default_factory=list)        # rendered lines
    runs: int = 0
    check: CheckRun | None = None
    check_problems: dict = field(default_factory=dict)  # field: [rendered lines]
    check_values: dict = field(default_factory=dict)    # rtol, atol, map as typed
    class_run: ClassRun | None = None
    class_problems: dict = field(default_factory=dict)  # field: [rendered lines]
    class_values: dict = field(default_factory=dict)    # rtol, atol as typed
    lock: threading.Lock = field(default_factory=threading.Lock)


def prepare(folder: Path, base: bytes, pressure, variants: bytes, variants_xlsx: bool):
    """Write the uploads under the server's names into ``folder/input`` and read the
    variants table (:func:`engine.variants.read_variants`): ``(base path, variants path,
    number of variants)``.  Raises the library's SpecError (or a TOML error) on bad
    input; more than :data:`MAX_VARIANTS` variants is a SpecError too."""
    import tomllib

    import tomli_w

    from crankbase.errors import Problem, SpecError, Text
    from engine.variants import read_variants

    from .engine_page import pressure_name

    inp = folder / "input"
    inp.mkdir(parents=True, exist_ok=True)
    data = tomllib.loads(base.decode("utf-8"))
    pr = data.get("pressure") if isinstance(data.get("pressure"), dict) else None
    if pr is not None and "file" in pr:
        if pressure is None:
            raise SpecError(Problem("pressure.file", Text("web.upload.pressure_missing",
                                                          {"file": str(pr["file"])})))
        pr["file"] = pressure_name(pressure[0], str(pr["file"]))
        (inp / pr["file"]).write_bytes(pressure[1])
    base_path = inp / "base.toml"
    base_path.write_text(tomli_w.dumps(data), encoding="utf-8")
    vpath = inp / ("variants.xlsx" if variants_xlsx else "variants.csv")
    vpath.write_bytes(variants)
    n = len(read_variants(vpath))
    if n > MAX_VARIANTS:
        raise SpecError(Problem("variants", Text("web.teacher.too_many",
                                                 {"n": n, "max": MAX_VARIANTS})))
    return base_path, vpath, n


def run_batch(batch: Batch, base_path: Path, vpath: Path):
    """Every variant's report into ``batch.folder/reports`` (:func:`engine.variants.
    run_variants`, :data:`BATCH_JOBS` processes), then the zip of them all; returns the
    :class:`~engine.variants.VariantsRun`."""
    from engine.variants import run_variants

    out = batch.folder / "reports"

    def progress(outcome, total):
        batch.done += 1
    run = run_variants(base_path, vpath, out, batch.lang, jobs=BATCH_JOBS, progress=progress)
    zpath = batch.folder / batch.zip_name
    with zipfile.ZipFile(zpath, "w", zipfile.ZIP_DEFLATED) as z:
        for p in sorted(out.rglob("*")):
            if p.is_file() and not any(part.startswith(".") for part in
                                       p.relative_to(out).parts):
                z.write(p, arcname=p.relative_to(out).as_posix())
    return run


def remove(batch: Batch | None) -> None:
    if batch is not None:
        batch.future.add_done_callback(
            lambda _f, d=batch.folder: shutil.rmtree(d, ignore_errors=True))


# ----------------------------------------------------------------------------- one student
#: The fields of the check form (a problem is shown next to one of them).
CHECK_FIELDS = ("spec", "pressure", "student", "rtol", "atol", "map")
#: The server's names of a student's file, by its kind (only the kind is taken from the
#: uploaded name).
STUDENT_NAMES = {".xlsx": "student.xlsx", ".xlsm": "student.xlsm", ".csv": "student.csv"}


class CheckProblem(Exception):
    """Bad input of the check form: ``{field: [Problem or Text]}``; ``names`` maps the
    server's paths to the names the teacher gave (a problem names the upload, never a
    path of the server)."""

    def __init__(self, problems: dict, names: dict | None = None):
        super().__init__(problems)
        self.problems = problems
        self.names = dict(names or {})

    def lines(self, lang: str) -> dict:
        """``{field: [line]}`` in ``lang``."""
        out = {}
        for f, items in self.problems.items():
            for item in items:
                line = item.render(lang)
                for path, name in sorted(self.names.items(), key=lambda kv: -len(kv[0])):
                    line = line.replace(path, name)
                out.setdefault(f, []).append(line)
        return out


def _tolerance(text):
    """A tolerance as typed: empty is the library's default (None), a number is read (a
    decimal comma too), anything else is passed on as text for the library to name."""
    s = (text or "").strip()
    if not s:
        return None
    try:
        return float(s.replace(",", "."))
    except ValueError:
        return s


def check_work(folder: Path, number: int, spec: tuple, pressure, student: tuple,
               rtol: str = "", atol: str = "", mapping: str = "",
               lang: str = "ru") -> CheckRun:
    """Check a student's table as ``crankdyn check SPEC STUDENT -o DIR`` does.

    Parameters
    ----------
    folder : Path
        The session's folder of this check: the uploads go into ``folder/input`` under
        the server's names, the outputs into ``folder/check``.
    number : int
        The check's number in its session (the downloads' URLs name it).
    spec, student : (upload name, bytes)
        The spec TOML (an engine's or a linkage's) and the student's ``.xlsx``/``.xlsm``/
        ``.csv`` (the upload name gives the kind and the names shown; it is never a path).
    pressure : (upload name, bytes) or None
        The pressure file the spec names, if it names one.
    rtol, atol, mapping : str
        As typed: tolerances (empty: the library's defaults) and ``HEADER=column`` lines.

    Raises
    ------
    CheckProblem
        The problems of the first input that fails (the student's file kind, the spec's
        TOML, the pressure file, the spec, then the table and the options all at once),
        each by the form field it belongs to.
    """
    import tomllib
    from dataclasses import replace

    import tomli_w

    from crankbase.checking import CheckFiles, check_table, write_check
    from crankbase.errors import SpecError, Text
    from crankbase.output import safe_name
    from engine.check import spec_check_side

    from .engine_page import pressure_name
    from .pages import table_rows

    spec_name = Path(spec[0]).name or "spec.toml"
    shown = Path(Path(student[0]).name or "student")
    kind = shown.suffix.lower()
    if kind not in STUDENT_NAMES:
        raise CheckProblem({"student": [Text("web.check.student_kind", {"name": shown.name})]})
    try:
        data = tomllib.loads(spec[1].decode("utf-8"))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise CheckProblem({"spec": [Text("web.upload.bad_toml", {"reason": str(exc)})]})
    inp = folder / "input"
    inp.mkdir(parents=True, exist_ok=True)
    pr = data.get("pressure") if isinstance(data.get("pressure"), dict) else None
    if pr is not None and isinstance(pr.get("file"), str):
        if pressure is None:
            raise CheckProblem({"pressure": [Text("web.upload.pressure_missing",
                                                  {"file": pr["file"]})]})
        pr["file"] = pressure_name(pressure[0], pr["file"])
        (inp / pr["file"]).write_bytes(pressure[1])
    spec_path = inp / "spec.toml"
    spec_path.write_text(tomli_w.dumps(data), encoding="utf-8")
    student_path = inp / STUDENT_NAMES[kind]
    student_path.write_bytes(student[1])
    names = {str(spec_path): spec_name, str(student_path): shown.name,
             str(inp) + "/": "", student_path.name: shown.name}
    try:
        side = spec_check_side(spec_path)
    except SpecError as exc:
        raise CheckProblem({"spec": list(exc.problems)}, names)
    maps = [ln.strip() for ln in (mapping or "").splitlines() if ln.strip()]
    try:
        result = check_table(side, student_path, _tolerance(rtol), _tolerance(atol), maps)
    except SpecError as exc:
        by = {}
        for p in exc.problems:
            by.setdefault({"rtol": "rtol", "atol": "atol", "mapping": "map"}.get(
                p.key, "student"), []).append(p)
        raise CheckProblem(by, names)
    written = write_check(result, folder / "check", lang, inputs=[spec_path])
    # the verdict names the files as the teacher knows them, never the server's paths
    marked = (f"{safe_name(shown.stem, 'student')}_checked.xlsx"
              if written.marked is not None else None)
    view = replace(result, student=replace(result.student, source=shown))
    lines = view.summary_lines(lang, CheckFiles(Path(written.check_csv.name),
                                                Path(marked) if marked else None,
                                                written.n_marked))
    files = {written.check_csv.name: written.check_csv}
    if marked:
        files[marked] = written.marked
    bad = result.table[~result.table["ok"]].drop(columns=["row_index"])
    head, rows = table_rows(bad)
    return CheckRun(number=number, folder=folder, lines=tuple(lines), ok=result.ok,
                    head=head, rows=rows, wrong=len(bad), files=files, marked=marked)


# ----------------------------------------------------------------------------- a class
#: The fields of the class form (a problem is shown next to one of them).
CLASS_FIELDS = ("base", "pressure", "variants", "students", "rtol", "atol")
#: The downloads of a class check.
CLASS_FILES = ("class_check.csv", "class_check.xlsx", "class_check.zip")


def student_file_name(upload: str) -> str | None:
    """The name a student's upload is saved under: its stem made safe
    (:func:`crankbase.output.safe_name`) and its kind (``.xlsx``, ``.xlsm``, ``.csv``,
    lower case); ``None`` for a name that is not a plain file name (a folder in it, ``..``,
    a leading dot) or of another kind."""
    from crankbase.output import safe_name

    name = upload or ""
    if ("/" in name or "\\" in name or name.startswith(".") or not name.strip()
            or "\x00" in name):
        return None
    path = Path(name)
    kind = path.suffix.lower()
    if kind not in STUDENT_NAMES or not path.stem.strip():
        return None
    return safe_name(path.stem, "student") + kind


def _by_field(problems, default: str) -> dict:
    """The library's problems by the class form's field (its key names it)."""
    by = {}
    for p in problems:
        key = str(getattr(p, "key", ""))
        f = ("pressure" if key.startswith("pressure") else
             key if key in ("rtol", "atol", "variants") else default)
        by.setdefault(f, []).append(p)
    return by


def check_class_work(folder: Path, number: int, base: tuple, pressure, variants: tuple,
                     students: list, rtol: str = "", atol: str = "",
                     lang: str = "ru") -> ClassRun:
    """Check a whole class as ``crankdyn check BASE.toml --variants VARIANTS STUDENTS_DIR
    -o DIR`` does, through :func:`engine.variants.check_class`.

    Parameters
    ----------
    folder : Path
        The session's folder of this check (``class-N``): the base spec and the variants
        table go into ``folder/input`` (:func:`prepare`), the students' files into
        ``folder/students`` under :func:`student_file_name`, the outputs into
        ``folder/class_check`` and its zip ``folder/class_check.zip``.
    number : int
        The check's number in its session (the downloads' URLs name it).
    base, variants : (upload name, bytes)
        The base engine spec and the variants table (``.csv`` or ``.xlsx`` by its name).
    pressure : (upload name, bytes) or None
        The pressure file the base spec names, if it names one.
    students : list of (upload name, bytes)
        The students' workbooks and CSVs (only the base name of each is used).
    rtol, atol : str
        As typed (empty: the library's defaults).

    Raises
    ------
    CheckProblem
        Every student's file of a bad name or kind (one line each, at ``students``), a
        name given twice, else the problems of the base spec, its pressure file, the
        variants table or the tolerances, each by its field.
    """
    from dataclasses import replace

    from crankbase.errors import SpecError, Text
    from crankbase.texts import texts
    from engine.variants import check_class

    saved, bad = {}, []
    for name, _data in students:
        own = student_file_name(name)
        if own is None:
            bad.append(Text("web.class.student_name", {"name": name}))
        elif own in saved:
            bad.append(Text("web.class.student_twice", {"name": name, "saved": own}))
        else:
            saved[own] = _data
    if bad:
        raise CheckProblem({"students": bad})
    inp = folder / "input"
    names = {str(inp) + "/": "", str(folder / "students") + "/": ""}
    try:
        base_path, vpath, _n = prepare(folder, base[1], pressure, variants[1],
                                       variants[0].lower().endswith(".xlsx"))
    except SpecError as exc:
        raise CheckProblem(_by_field(exc.problems, "base"), names)
    except (ValueError, UnicodeDecodeError) as exc:     # the base spec's TOML
        raise CheckProblem({"base": [Text("web.upload.bad_toml", {"reason": str(exc)})]})
    sdir = folder / "students"
    sdir.mkdir(parents=True, exist_ok=True)
    for own, data in saved.items():
        (sdir / own).write_bytes(data)
    out = folder / "class_check"
    try:
        done = check_class(base_path, vpath, sdir, out, lang, _tolerance(rtol),
                           _tolerance(atol), None)
    except SpecError as exc:
        raise CheckProblem(_by_field(exc.problems, "variants"), names)
    zpath = folder / "class_check.zip"
    with zipfile.ZipFile(zpath, "w", zipfile.ZIP_DEFLATED) as z:
        for p in sorted(out.rglob("*")):
            if p.is_file():
                z.write(p, arcname=p.relative_to(out).as_posix())
    # the verdict names the files by their download names, never the server's paths
    view = replace(done, folder=Path(zpath.name), csv=Path(done.csv.name),
                   xlsx=Path(done.xlsx.name))
    import csv

    with open(done.csv, newline="", encoding="utf-8") as fh:
        table = list(csv.reader(fh))
    files = {done.csv.name: done.csv, done.xlsx.name: done.xlsx, zpath.name: zpath}
    t = texts(lang)          # the header in the page's language, as the workbook's
    head = [t(f"check.class.column.{c}") for c in table[0]]
    return ClassRun(number=number, folder=folder, lines=tuple(view.summary_lines(lang)),
                    ok=done.ok, not_right=sum(s.status != "right" for s in done.students),
                    head=head, rows=table[1:], files=files)
