"""Check a student's table against computed values (``crankdyn check``): read, compare,
mark.  Nothing here computes physics: the computed table comes from the calculation
package (``engine.check``, ``linkage.check``); this module reads the student's table
(a workbook in our layout, a CSV with our column names, or either with a column mapping),
compares it cell by cell with a documented tolerance and writes a marked copy.

Tolerance: a value passes when |student − computed| ≤ atol + rtol·|computed|.  ``rtol``
defaults to :data:`crankbase.tolerances.CHECK_RTOL` (2 %: a graphical plan or a
hand-drawn diagram is good to a few per cent); ``atol``, unless given, is
:data:`crankbase.tolerances.CHECK_ATOL_OF_SCALE` times the largest magnitude of the
computed column, so a value near a zero crossing (T at α = 0) is judged against the
scale of its column instead of against zero.

The whole check is two calls: :func:`check_table` (a :class:`CheckSide` from the calculation
package — ``engine.check.check_side(study)``, ``linkage.check.check_side(spec)`` — and the
student's file → a :class:`CheckResult`) and :func:`write_check` (``check.csv`` and the
marked copy, as one unit); :meth:`CheckResult.summary_lines` is the verdict in the report's
language (``check.po``).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from .errors import Problem, SpecError, Text
from .texts import texts
from .tolerances import CHECK_ATOL_OF_SCALE, CHECK_RTOL

__all__ = ["StudentTable", "read_student_table", "parse_mapping", "compare", "verdicts",
           "mark_workbook", "CHECK_COLUMNS", "CheckSide", "CheckResult", "CheckFiles",
           "check_table", "write_check", "tolerance_text", "STUDENT_SUFFIXES", "VARIANT_LABELS",
           "student_files", "variant_in_workbook", "match_variant", "StudentVerdict",
           "ClassCheck", "CLASS_COLUMNS", "CLASS_FILES", "check_class"]

#: Columns of check.csv (``alpha_deg`` is replaced by the table's key column).
CHECK_COLUMNS = ("column", "student", "computed", "deviation", "ok")

_HEADER_SCAN_ROWS = 12


@dataclass
class StudentTable:
    """A student's table: values by our column keys, rows in the student's order.

    Attributes
    ----------
    data : pandas.DataFrame
        Column ``key`` first (α or position), then every recognised column; a cell that
        is empty is NaN, a cell that is not a number is kept as text.
    cells : dict
        (row index, column) → (sheet title, cell coordinate) for a workbook; empty for CSV.
    source : Path
    ignored : list of str
        Headers that are not columns of the computed table.
    """

    data: object
    cells: dict = field(default_factory=dict)
    source: Path | None = None
    ignored: list = field(default_factory=list)

    #: The student's workbook as :func:`read_student_table` loaded it (formulas kept), for
    #: :func:`mark_workbook` to mark instead of loading the file again (it takes it: a
    #: second marking loads the file afresh); None for a CSV.  Not compared, not pickled.
    _book = None

    def __getstate__(self):
        state = dict(self.__dict__)
        state.pop("_book", None)
        return state


def _has_formulas(wb) -> bool:
    """Whether a cell of ``wb`` (loaded with its formulas) holds a formula: without one,
    the values of a ``data_only`` load are the very same."""
    return any(c.data_type == "f" for ws in wb.worksheets for c in ws._cells.values())


def parse_mapping(items) -> dict:
    """``["T, Н=T_N", "α=alpha_deg"]`` → {"T, Н": "T_N", "α": "alpha_deg"}: a column
    mapping, student's header = our column; the last ``=`` splits, so a header may
    contain "=" itself.  Problems name the argument ``mapping``."""
    out, problems = {}, []
    for item in items or ():
        head, sep, key = str(item).rpartition("=")
        if not sep or not head.strip() or not key.strip():
            problems.append(Problem("mapping", Text("errors.checking.write_student_header",
                                                    {"item": item})))
            continue
        out[head.strip()] = key.strip()
    if problems:
        raise SpecError(problems)
    return out


def _number(v):
    if v is None:
        return np.nan
    if isinstance(v, bool):
        return v
    if isinstance(v, (int, float)):
        return float(v)
    text = str(v).strip().replace("\u2212", "-").replace(",", ".")
    if not text:
        return np.nan
    try:
        return float(text)
    except ValueError:
        return str(v)


def _frame(header, rows, key, known, mapping):
    """Pick the recognised columns of a header + rows block."""
    import pandas as pd

    names = [mapping.get(str(h).strip(), str(h).strip()) if h is not None else ""
             for h in header]
    keep = [(j, n) for j, n in enumerate(names) if n == key or n in known]
    seen, cols = set(), []
    for j, n in keep:
        if n not in seen:
            seen.add(n)
            cols.append((j, n))
    ignored = [n for n in names if n and n not in seen and n != key]
    data = {n: [_number(r[j]) if j < len(r) else np.nan for r in rows] for j, n in cols}
    return pd.DataFrame(data, columns=[n for _, n in cols]), cols, ignored


def read_student_table(path, key, known, mapping=None) -> StudentTable:
    """Read a student's table.

    Parameters
    ----------
    path : str or Path
        ``.xlsx`` (every sheet is searched for a header row holding ``key``, within its
        first rows: our workbooks have such a row, hidden on Table 2) or ``.csv``
        (``,`` or ``;``; header in the first row).
    key : str
        The row key column: ``alpha_deg`` (engine) or ``position`` (linkage).
    known : collection of str
        Column names the computed table has; other columns are ignored (and listed).
    mapping : dict, optional
        Student header → our column name (:func:`parse_mapping`).

    Raises
    ------
    SpecError
        The file is missing or cannot be read (a damaged workbook, a file that is not
        one, a CSV that is not UTF-8 text), or no sheet/CSV has the key column.
    """
    path = Path(path)
    mapping = dict(mapping or {})
    if not path.is_file():
        raise SpecError(Problem(str(path), Text("errors.checking.student_s_table")))
    known = set(known)
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        from openpyxl import load_workbook

        try:
            # loaded once as mark_workbook marks it (formulas kept); the values are read
            # from it unless a cell holds a formula (then from the values last computed,
            # data_only)
            book = wb = load_workbook(path)
            if _has_formulas(book):
                wb = load_workbook(path, data_only=True)
        except _unreadable() as exc:        # a damaged workbook, a file that is not one
            raise SpecError(Problem(path.name, Text("errors.checking.cannot_read",
                                                    {"reason": str(exc)}))) from None
        frames, cells, ignored = [], {}, []
        for ws in wb.worksheets:
            rows = list(ws.iter_rows(max_row=_HEADER_SCAN_ROWS, values_only=True))
            hdr = next((i for i, r in enumerate(rows, start=1)
                        if key in [mapping.get(str(v).strip(), str(v).strip())
                                   for v in r if v is not None]), None)
            if hdr is None:
                continue
            header = [c.value for c in ws[hdr]]
            kj = [mapping.get(str(v).strip(), str(v).strip()) if v is not None else ""
                  for v in header].index(key)
            body, coords = [], []
            for row in ws.iter_rows(min_row=hdr + 1):
                if row[kj].value is None:
                    if body:
                        break
                    continue
                body.append([c.value for c in row])
                coords.append([c.coordinate for c in row])
            df, cols, ign = _frame(header, body, key, known, mapping)
            taken = set().union(*(set(f.columns) for f in frames)) if frames else set()
            new = [n for _, n in cols if n not in taken or n == key]
            if len(new) <= 1:
                continue
            frames.append(df[new])
            ignored += ign
            for i in range(len(body)):
                for j, n in cols:
                    if n in new and n != key:
                        cells[(i, n)] = (ws.title, coords[i][j])
            cells.setdefault("_sheets", []).append(ws.title)
        if not frames:
            raise SpecError(Problem(str(path), Text("errors.checking.no_sheet_has",
                                                    {"key": key,
                                                     "HEADER_SCAN_ROWS": _HEADER_SCAN_ROWS})))
        data = join_words(frames, key, path)
        sheets = cells.pop("_sheets")
        # rows of later sheets are matched by key: re-point their cells
        table = StudentTable(data, _repoint(cells, frames, data, key, sheets), path, ignored)
        table._book = book
        return table
    import csv

    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as exc:       # not a text file (or not UTF-8)
        raise SpecError(Problem(path.name, Text("errors.checking.cannot_read",
                                                {"reason": str(exc)}))) from None
    lines = text.splitlines()
    head = lines[0] if lines else ""
    delim = ";" if head.count(";") > head.count(",") else ","
    rows = [r for r in csv.reader(lines, delimiter=delim) if any(x.strip() for x in r)]
    header = [mapping.get(h.strip(), h.strip()) for h in rows[0]] if rows else []
    if key not in header:
        raise SpecError(Problem(str(path), Text("errors.checking.no_column_columns",
                                                {"key": key,
                                                 "items": ", ".join(rows[0] if rows else [])})))
    df, _, ignored = _frame(header, rows[1:], key, known, {})
    return StudentTable(df, {}, path, ignored)


def join_words(frames, key, path):
    out = frames[0]
    for f in frames[1:]:
        out = out.merge(f, on=key, how="left", sort=False)
    if out[key].duplicated().any():
        dup = out[key][out[key].duplicated()].tolist()
        raise SpecError(Problem(str(path), Text("errors.checking.repeats",
                                                {"key": key, "value": dup[:5]})))
    return out


def _repoint(cells, frames, data, key, sheets):
    """Cell locations by row of the joined table (frames after the first matched by key)."""
    out = {}
    order = {v: i for i, v in enumerate(data[key].tolist())}
    for (i, col), loc in cells.items():
        f = next(f for f in frames if col in f.columns)
        k = f[key].iat[i]
        if k in order:
            out[(order[k], col)] = loc
    return out


def compare(student: StudentTable, computed, key, rtol=None, atol=None):
    """Compare every recognised column of the student's table with the computed one.

    Parameters
    ----------
    student : StudentTable
    computed : pandas.DataFrame
        The same rows (one per student row, same order) and every column.
    key : str
    rtol : float, optional
        Default :data:`~crankbase.tolerances.CHECK_RTOL`.
    atol : float, optional
        Default: :data:`~crankbase.tolerances.CHECK_ATOL_OF_SCALE` × max |computed column|.

    Returns
    -------
    pandas.DataFrame
        ``key, column, student, computed, deviation, ok`` in the student's row order, then
        column order; a text cell or an empty one where a number is due is not ok.
    """
    import pandas as pd

    rtol = CHECK_RTOL if rtol is None else float(rtol)
    recs = []
    s = student.data
    for col in s.columns:
        if col == key:
            continue
        comp = computed[col].to_numpy(float)
        finite = np.isfinite(comp)
        scale = float(np.abs(comp[finite]).max()) if finite.any() else 0.0
        tol_abs = CHECK_ATOL_OF_SCALE * scale if atol is None else float(atol)
        for i, (kv, sv, cv) in enumerate(zip(s[key], s[col], comp)):
            if isinstance(sv, str) or (isinstance(sv, float) and np.isnan(sv)):
                ok = isinstance(sv, float) and not np.isfinite(cv)   # both empty
                recs.append((kv, col, sv if isinstance(sv, str) else None, cv, None, ok, i))
                continue
            dev = float(sv) - cv
            if col.endswith("_deg") and np.isfinite(dev):
                dev = (dev + 180.0) % 360.0 - 180.0      # an angle: −180° is +180°
            ok = bool(np.isfinite(cv) and abs(dev) <= tol_abs + rtol * abs(cv))
            recs.append((kv, col, float(sv), cv, dev, ok, i))
    out = pd.DataFrame(recs, columns=[key, *CHECK_COLUMNS, "row_index"])
    return out


def tolerance_text(rtol=None, atol=None, lang="en") -> str:
    """What the tolerance accepts, in ``lang``: with the default ``atol`` (a fraction of the
    column's largest magnitude) the error allowed, in % of a value's own size, at its
    column's peak and at a third of the peak; with a given ``atol`` the rule itself."""
    t = texts(lang)
    rtol = CHECK_RTOL if rtol is None else float(rtol)
    if atol is not None:
        return t("check.tolerance.absolute", atol=float(atol), rtol_pct=100 * rtol)
    a = CHECK_ATOL_OF_SCALE
    return t("check.tolerance.scale", atol_pct=100 * a, rtol_pct=100 * rtol,
             peak_pct=100 * (rtol + a), third_pct=100 * (rtol + 3 * a))


def verdicts(check, key, lang="en"):
    """One line per column: all rows right, or how many are wrong and where."""
    t = texts(lang)
    keyname = {"alpha_deg": t("check.key_alpha"), "position": t("check.key_position")
               }.get(key, key)
    lines = []
    for col, g in check.groupby("column", sort=False):
        bad = g[~g["ok"]]
        dev = g["deviation"].abs().max()
        where = ", ".join(f"{v:g}" if isinstance(v, float) else str(v)
                          for v in bad[key].tolist()[:8]) + (" …" if len(bad) > 8 else "")
        line = (t("check.verdict.right", column=col) if bad.empty else
                t("check.verdict.wrong", column=col, wrong=len(bad), total=len(g),
                  key=keyname, where=where))
        if np.isfinite(dev):
            line += t("check.verdict.deviation", deviation=dev)
        lines.append(line)
    return lines


def mark_workbook(student: StudentTable, check, dst, lang="en") -> int:
    """A copy of the student's workbook with every wrong cell filled red and a comment
    carrying the computed value.  Returns the number of cells marked."""
    from openpyxl import load_workbook
    from openpyxl.comments import Comment
    from openpyxl.styles import PatternFill

    from .texts import texts
    from .workbook import save

    t = texts(lang)
    wb, student._book = student._book, None           # the workbook read, taken once
    if wb is None:
        wb = load_workbook(student.source)
    red = PatternFill("solid", fgColor="FF7C80")
    n = 0
    for rec in check[~check["ok"]].itertuples(index=False):
        loc = student.cells.get((rec.row_index, rec.column))
        if loc is None:
            continue
        cell = wb[loc[0]][loc[1]]
        cell.fill = red
        right = f"{rec.computed:.6g}" if np.isfinite(rec.computed) else "—"
        text = t("check.comment.right", value=right)
        if rec.deviation is not None and np.isfinite(rec.deviation):
            text += t("check.comment.deviation", deviation=rec.deviation)
        cell.comment = Comment(text, "crankdyn check", width=220, height=60)
        n += 1
    save(wb, dst)          # atomically; the student's numbers kept bit for bit
    return n


@dataclass(frozen=True)
class CheckSide:
    """The computed side of a check, as a calculation package gives it.

    Attributes
    ----------
    key : str
        The row key column (``alpha_deg``, ``position``).
    columns : tuple of str
        Every column a student's table may hold (others are ignored and listed).
    rows : callable
        ``rows(keys)`` → the computed table at the student's keys (a list, in their
        order): one row per key, every column.
    numeric_key : bool
        The keys must be numbers (crank angles); a text or empty key is refused.
    """

    key: str
    columns: tuple
    rows: Callable
    numeric_key: bool = False


@dataclass(frozen=True)
class CheckResult:
    """A student's table checked (:func:`check_table`).

    Attributes
    ----------
    student : StudentTable
    table : pandas.DataFrame
        :func:`compare`'s table (with ``row_index``, the row of the student's table).
    key : str
    rtol : float
        The relative tolerance used.
    """

    student: StudentTable
    table: object
    key: str
    rtol: float
    atol: float | None = None

    @property
    def n_wrong(self) -> int:
        return int((~self.table["ok"]).sum())

    @property
    def ok(self) -> bool:
        return self.n_wrong == 0

    def summary_lines(self, lang: str = "ru", written=None) -> list[str]:
        """The verdict in ``lang``: rows and columns checked, a line per column, the
        columns not checked and, given :func:`write_check`'s :class:`CheckFiles`, the
        result with the files written."""
        t = texts(lang)
        cols = int(self.table["column"].nunique())
        lines = [t("check.head", student=self.student.source.name,
                   rows=t.n("common.rows", len(self.student.data)),
                   columns=t.n("check.columns_checked", cols), rtol=self.rtol)]
        lines.append(tolerance_text(self.rtol, self.atol, lang))
        lines += verdicts(self.table, self.key, lang)
        if self.student.ignored:
            lines.append(t("check.ignored", columns=", ".join(self.student.ignored)))
        if written is not None:
            n = self.n_wrong
            tail = (t("check.tail.right", path=str(written.check_csv)) if not n else
                    t.n("check.tail.wrong", n, path=str(written.check_csv)))
            if written.marked is not None:
                tail += t.n("check.tail.marked", written.n_marked, path=str(written.marked))
            lines.append(tail)
        return lines


@dataclass(frozen=True)
class CheckFiles:
    """What :func:`write_check` wrote: ``check.csv``, the marked copy of a workbook (None
    for a CSV) and the number of cells marked in it."""

    check_csv: Path
    marked: Path | None
    n_marked: int = 0

    @property
    def paths(self) -> tuple:
        return (self.check_csv,) + ((self.marked,) if self.marked is not None else ())


def check_table(side: CheckSide, student_path, rtol=None, atol=None,
                mapping=None) -> CheckResult:
    """Check a student's table against the computed one.

    Parameters
    ----------
    side : CheckSide
        The computed side (``engine.check.check_side``, ``linkage.check.check_side``).
    student_path : str or Path
        The student's table (:func:`read_student_table`).
    rtol, atol : float, optional
        Tolerances (:func:`compare`): 0 <= rtol < 1, atol >= 0.
    mapping : dict or list of str, optional
        Student header → our column (a list of ``"HEADER=column"`` is parsed).

    Returns
    -------
    CheckResult

    Raises
    ------
    SpecError
        Bad tolerances or mapping (named ``rtol``, ``atol``, ``mapping``; all at once), an
        unreadable table, or keys that are not numbers where numbers are due.
    """
    mapping = _check_options(rtol, atol, mapping)
    student_path = Path(student_path)
    student = read_student_table(student_path, side.key, side.columns, mapping)
    keys = student.data[side.key]
    if side.numeric_key:
        bad = [k for k in keys if not isinstance(k, float) or k != k]
        if bad:
            raise SpecError(Text("errors.checking.numbers",
                                 {"student_path": student_path, "key": side.key,
                                  "value": bad[:5]}))
    computed = side.rows(keys.tolist())
    table = compare(student, computed, side.key, rtol, atol)
    return CheckResult(student, table, side.key, CHECK_RTOL if rtol is None else float(rtol),
                       None if atol is None else float(atol))


def _check_options(rtol, atol, mapping):
    """Check the tolerances and the mapping (all problems at once); the mapping as a dict."""
    problems = []
    if rtol is not None and not (isinstance(rtol, (int, float)) and 0 <= rtol < 1):
        problems.append(Problem("rtol", Text("errors.checking.rtol", {"value": rtol})
                                if isinstance(rtol, (int, float)) else
                                Text("errors.got", {"value": repr(rtol)})))
    if atol is not None and not (isinstance(atol, (int, float)) and atol >= 0):
        problems.append(Problem("atol", Text("errors.checking.atol", {"value": atol})
                                if isinstance(atol, (int, float)) else
                                Text("errors.got", {"value": repr(atol)})))
    if mapping is not None and not isinstance(mapping, dict):
        try:
            mapping = parse_mapping(mapping)
        except SpecError as exc:
            problems += exc.problems
    if problems:
        raise SpecError(problems)
    return mapping


def write_check(result: CheckResult, out, lang: str = "ru", inputs=()) -> CheckFiles:
    """Write ``out/check.csv`` (``key, column, student, computed, deviation, ok``) and, for
    a workbook, ``out/<student>_checked.xlsx`` (every wrong cell red, with a comment
    carrying the right value, in ``lang``), as one unit.  ``inputs``: files no output may
    overwrite (the student's table is always one)."""
    from .output import check_not_input, safe_name, staged_output, write_csv
    from .validation import check_lang

    check_lang(lang)
    out = Path(out)
    student = result.student
    inputs = [*inputs, student.source]
    marked = (out / f"{safe_name(student.source.stem, 'student')}_checked.xlsx"
              if student.cells else None)
    check_csv = out / "check.csv"
    check_not_input([check_csv] + ([marked] if marked else []), inputs)
    with staged_output(out, inputs=inputs) as stage:
        write_csv(result.table.drop(columns=["row_index"]), stage / check_csv.name)
        n_marked = (mark_workbook(student, result.table, stage / marked.name, lang)
                    if marked else 0)
    return CheckFiles(check_csv, marked, n_marked)


# ------------------------------------------------------------------ a whole class at once
#: Student files a class check reads from the students' folder (not its subfolders).
STUDENT_SUFFIXES = (".xlsx", ".xlsm", ".csv")

#: Labels of the workbook cell that names the student's variant (case-insensitive, a
#: trailing ":" allowed); the variant is the next non-empty cell to the right, or the rest
#: of the same cell (``Вариант: v02``).
VARIANT_LABELS = ("вариант", "variant")

#: Columns of the class verdict table.
CLASS_COLUMNS = ("student", "variant", "columns_wrong", "cells_wrong", "verdict", "detail")

#: The class verdict files, in the output folder.
CLASS_FILES = ("class_check.csv", "class_check.xlsx")

_LABEL_SCAN_ROWS, _LABEL_SCAN_COLS = 30, 30


def student_files(folder) -> list[Path]:
    """The students' files of a folder: ``.xlsx``, ``.xlsm``, ``.csv``, by name; hidden
    files and Excel's lock files (``~$…``) are skipped, subfolders are not searched."""
    folder = Path(folder)
    return sorted((p for p in folder.iterdir()
                   if p.is_file() and p.suffix.lower() in STUDENT_SUFFIXES
                   and not p.name.startswith((".", "~$"))), key=lambda p: p.name)


def _text(v) -> str:
    if isinstance(v, float) and v.is_integer():
        v = int(v)
    return "" if v is None else str(v).strip()


def variant_in_workbook(path):
    """The variant a workbook names: the cell right of a cell labelled «Вариант» or
    «Variant» (:data:`VARIANT_LABELS`), or the rest of such a cell (``Вариант: v02``), in
    the first rows and columns of any sheet; None for a CSV or a workbook without one."""
    import re

    path = Path(path)
    if path.suffix.lower() not in (".xlsx", ".xlsm"):
        return None
    from openpyxl import load_workbook

    labels = "|".join(VARIANT_LABELS)
    pattern = re.compile(rf"^(?:{labels})(?:\s*[:№#]\s*|\s+|$)(.*)$", re.IGNORECASE)
    try:
        wb = load_workbook(path, read_only=True, data_only=True)
    except _unreadable():          # the check itself says why it cannot read the file
        return None
    try:
        for ws in wb.worksheets:
            for row in ws.iter_rows(max_row=_LABEL_SCAN_ROWS, max_col=_LABEL_SCAN_COLS,
                                    values_only=True):
                for j, v in enumerate(row):
                    m = pattern.match(_text(v)) if isinstance(v, str) else None
                    if m is None:
                        continue
                    if m.group(1).strip():
                        return m.group(1).strip()
                    rest = [_text(x) for x in row[j + 1:] if _text(x)]
                    if rest:
                        return rest[0]
    finally:
        wb.close()
    return None


def _unreadable() -> tuple:
    """The exceptions of a file that is not a workbook (or not a readable one)."""
    import zipfile

    from openpyxl.utils.exceptions import InvalidFileException

    return (OSError, zipfile.BadZipFile, InvalidFileException)


def match_variant(path, names) -> tuple[list, str | None]:
    """The variants a student's file belongs to, by the rule of ``crankdyn check
    --variants``: every variant whose name is a whole word of the file name (letters and
    digits on neither side, case-insensitive: ``ivanov_v02.xlsx`` → ``v02``, not ``v0``
    nor ``v021``), together with the variant the workbook names in its «Вариант» cell
    (:func:`variant_in_workbook`).

    Returns
    -------
    matched : list of str
        The variants matched, in the order of ``names``: exactly one for a file that is
        checked.
    stated : str or None
        The variant the workbook states (even one not in ``names``).
    """
    import re

    path = Path(path)
    stem = path.stem
    stated = variant_in_workbook(path)
    out = []
    for name in names:
        word = re.compile(rf"(?<![^\W_]){re.escape(str(name))}(?![^\W_])", re.IGNORECASE)
        if word.search(stem) or (stated is not None
                                 and stated.casefold() == str(name).casefold()):
            out.append(name)
    return out, stated


@dataclass(frozen=True)
class StudentVerdict:
    """One student of a class check (:func:`check_class`).

    Attributes
    ----------
    student : Path
        The student's file.
    variant : str or None
        The variant it was matched to (None when matched to none or to several).
    status : {"right", "wrong", "no_variant", "two_variants", "unreadable", "bad_variant"}
    detail : str, Text or SpecError
        The wrong columns (``S_N (1), T_N (2)``: column and cells wrong), why the file was
        not matched (a :class:`~crankbase.errors.Text`) or the problem that stopped its
        check; :meth:`detail_text` gives it in a language.
    result : CheckResult or None
        The check, when the file was checked.
    files : CheckFiles or None
        ``check.csv`` and the checked workbook, in the student's own folder.
    """

    student: Path
    variant: str | None
    status: str
    detail: object = ""
    result: CheckResult | None = None
    files: CheckFiles | None = None

    @property
    def checked(self) -> bool:
        return self.result is not None

    def detail_text(self, lang: str = "ru") -> str:
        """:attr:`detail` in ``lang``."""
        d = self.detail
        if isinstance(d, Text):
            return d.render(lang)
        if isinstance(d, SpecError):
            return "; ".join(d.lines(lang) or [str(d)])
        return str(d)


@dataclass(frozen=True)
class ClassCheck:
    """A whole class checked (:func:`check_class`): one :class:`StudentVerdict` per
    student file, in name order, and the verdict table ``class_check.csv`` / ``.xlsx``."""

    folder: Path
    students: tuple
    csv: Path
    xlsx: Path
    rtol: float
    atol: float | None = None

    @property
    def ok(self) -> bool:
        """Every student's file was matched, read and right."""
        return all(s.status == "right" for s in self.students)

    def records(self, lang: str = "ru") -> list[dict]:
        """The rows of the verdict table (:data:`CLASS_COLUMNS`), in ``lang``."""
        t = texts(lang)
        recs = []
        for s in self.students:
            cols = cells = None
            if s.result is not None:
                cells = s.result.n_wrong
                cols = int(s.result.table.loc[~s.result.table["ok"], "column"].nunique())
            recs.append(dict(student=s.student.name, variant=s.variant, columns_wrong=cols,
                             cells_wrong=cells,
                             verdict=t(f"check.class.status.{s.status}"),
                             detail=s.detail_text(lang)))
        return recs

    def summary_lines(self, lang: str = "ru") -> list[str]:
        """The class verdict in ``lang``: a line per student, then the counts and files."""
        t = texts(lang)
        lines = [t("check.class.head", students=t.n("check.class.students",
                                                    len(self.students)),
                   folder=str(self.folder))]
        lines.append(tolerance_text(self.rtol, self.atol, lang))
        for r in self.records(lang):
            lines.append(t("check.class.line", student=r["student"],
                           variant=r["variant"] or "—", verdict=r["verdict"],
                           detail=r["detail"]).rstrip())
        right = sum(s.status == "right" for s in self.students)
        wrong = sum(s.status == "wrong" for s in self.students)
        lines.append(t("check.class.tail", right=right, wrong=wrong,
                       unchecked=len(self.students) - right - wrong, csv=str(self.csv),
                       xlsx=str(self.xlsx)))
        return lines


def check_class(sides, students, out, lang: str = "ru", rtol=None, atol=None,
                mapping=None, inputs=()) -> ClassCheck:
    """Check a whole class: every student's file of a folder against its own variant.

    Parameters
    ----------
    sides : mapping
        Variant name → its :class:`CheckSide`, or a callable returning it (called once,
        when a student of that variant is found; a :class:`~crankbase.errors.SpecError`
        it raises is that variant's problem, a line of the verdict table).
    students : str or Path
        The folder of the students' files (:func:`student_files`); each is matched to a
        variant by :func:`match_variant`.
    out : str or Path
        Output folder: ``class_check.csv`` and ``class_check.xlsx`` (one line per
        student: :data:`CLASS_COLUMNS`) and, per student checked, a folder named after the
        file with its ``check.csv`` and checked workbook (:func:`write_check`).
    lang : {"ru", "en"}, default "ru"
    rtol, atol, mapping
        As :func:`check_table`, for every student.
    inputs : sequence of path
        Files no output may overwrite (the students' files always are).

    Returns
    -------
    ClassCheck
        A file matched to no variant or to several, or that cannot be read, is a line of
        the verdict table (not checked), never an exception.

    Raises
    ------
    SpecError
        Bad tolerances or mapping, no variants, or the students' folder is missing.
    """
    from .output import check_not_input, safe_name
    from .validation import check_lang

    check_lang(lang)
    mapping = _check_options(rtol, atol, mapping)
    students = Path(students)
    if not students.is_dir():
        raise SpecError(Problem(str(students), Text("errors.checking.no_students_folder")))
    if not sides:
        raise SpecError(Problem("variants", Text("errors.checking.no_variants")))
    out = Path(out)
    files = student_files(students)
    inputs = [*inputs, *files]
    check_not_input([out / n for n in CLASS_FILES], inputs)
    names = list(sides)
    cache, verdicts_, folders = {}, [], set()
    for path in files:
        matched, stated = match_variant(path, names)
        if not matched:
            detail = (Text("check.class.detail.unknown_variant", {"variant": stated})
                      if stated is not None else Text("check.class.detail.no_variant"))
            verdicts_.append(StudentVerdict(path, None, "no_variant", detail))
            continue
        if len(matched) > 1:
            verdicts_.append(StudentVerdict(path, None, "two_variants", Text(
                "check.class.detail.variants", {"variants": ", ".join(map(str, matched))})))
            continue
        name = matched[0]
        if name not in cache:
            side = sides[name]
            try:
                cache[name] = side() if callable(side) else side
            except SpecError as exc:
                cache[name] = exc
        side = cache[name]
        if isinstance(side, SpecError):
            verdicts_.append(StudentVerdict(path, name, "bad_variant", side))
            continue
        try:
            result = check_table(side, path, rtol, atol, mapping)
        except SpecError as exc:
            verdicts_.append(StudentVerdict(path, name, "unreadable", exc))
            continue
        except _unreadable() as exc:        # a damaged workbook, a file that is not one
            verdicts_.append(StudentVerdict(path, name, "unreadable", SpecError(
                Problem(path.name, Text("errors.checking.cannot_read",
                                        {"reason": str(exc)})))))
            continue
        folder = safe_name(path.stem, "student")
        if folder in folders:
            folder = safe_name(path.name, "student")
        folders.add(folder)
        written = write_check(result, out / folder, lang, inputs=inputs)
        bad = result.table[~result.table["ok"]]
        detail = ", ".join(f"{c} ({n})" for c, n in
                           bad.groupby("column", sort=False).size().items())
        verdicts_.append(StudentVerdict(path, name, "right" if result.ok else "wrong",
                                        detail, result, written))
    run = ClassCheck(out, tuple(verdicts_), out / CLASS_FILES[0], out / CLASS_FILES[1],
                     CHECK_RTOL if rtol is None else float(rtol),
                     None if atol is None else float(atol))
    _write_class(run, lang)
    return run


def _write_class(run: ClassCheck, lang: str) -> None:
    """``class_check.csv`` and ``class_check.xlsx``, each written atomically."""
    import pandas as pd
    from openpyxl import Workbook
    from openpyxl.styles import Alignment, Font, PatternFill

    from .output import atomic_path, write_csv

    t = texts(lang)
    run.folder.mkdir(parents=True, exist_ok=True)
    df = pd.DataFrame(run.records(lang), columns=list(CLASS_COLUMNS))
    df["columns_wrong"] = df["columns_wrong"].astype("Int64")
    df["cells_wrong"] = df["cells_wrong"].astype("Int64")
    write_csv(df, run.csv)
    wb = Workbook()
    ws = wb.active
    ws.title = t("check.class.sheet")
    ws["A1"] = t("check.class.title")
    ws["A1"].font = Font(bold=True, size=12)
    ws["A2"] = tolerance_text(run.rtol, run.atol, lang).strip()
    headers = [t(f"check.class.column.{c}") for c in CLASS_COLUMNS]
    widths = (28, 12, 12, 12, 18, 60)
    for j, (name, w) in enumerate(zip(headers, widths), start=1):
        c = ws.cell(4, j, name)
        c.font = Font(bold=True)
        c.fill = PatternFill("solid", fgColor="DDE4EE")
        c.alignment = Alignment(horizontal="center", wrap_text=True)
        ws.column_dimensions[c.column_letter].width = w
    fills = {"right": "C6EFCE", "wrong": "FF7C80"}
    for i, (s, rec) in enumerate(zip(run.students, df.itertuples(index=False)), start=5):
        for j, val in enumerate(rec, start=1):
            c = ws.cell(i, j, None if pd.isna(val) else (int(val) if j in (3, 4) else val))
            if isinstance(val, str):
                c.data_type = "s"
        ws.cell(i, 5).fill = PatternFill("solid", fgColor=fills.get(s.status, "FFEB9C"))
    ws.freeze_panes = "B5"
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = "landscape"
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    ws.page_setup.fitToHeight = 0
    with atomic_path(run.xlsx) as tmp:
        wb.save(tmp)
