"""Safe report output: write to a temporary file in the target folder, then rename.

A crash or a bad value never leaves half a report, and an existing report is replaced
only by a complete new one.  Inputs are never overwritten: :func:`check_not_input`
refuses an output path that is one of the input files.
"""
from __future__ import annotations

import contextlib
import os
import re
import tempfile
from pathlib import Path

import numpy as np

from .errors import OutputError, Problem, SpecError, Text, os_reason

__all__ = ["atomic_path", "staged_output", "recover_output", "verify_report", "read_manifest",
           "write_csv", "check_not_input", "ensure_finite", "full_precision_xlsx", "paused_gc",
           "safe_name", "save_figure", "OutputError", "MANIFEST_NAME", "WINDOWS_RESERVED"]


@contextlib.contextmanager
def atomic_path(path):
    """Context manager yielding a temporary path beside ``path``; renamed on success.

    On an exception the temporary file is removed and ``path`` is left untouched.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp" + path.suffix,
                               dir=path.parent)
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp creates 0600; a report is an ordinary file
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise


def check_not_input(outputs, inputs) -> None:
    """Raise :class:`OutputError` if any output path is one of the input paths."""
    ins = {Path(p).resolve() for p in inputs if p is not None}
    for out in outputs:
        if Path(out).resolve() in ins:
            raise OutputError(Text("errors.output.output_input_file", {"out": out}))


def ensure_finite(df, what: str) -> None:
    """Raise :class:`OutputError` naming the column and row of the first non-finite number.

    ``df`` is a pandas DataFrame; non-numeric columns are skipped.
    """
    for col in df.columns:
        values = df[col].to_numpy()
        if values.dtype.kind not in "fc":
            continue
        bad = ~np.isfinite(values)
        if bad.any():
            row = int(np.flatnonzero(bad)[0])
            raise OutputError(Text("errors.output.column_not_finite",
                                   {"what": what, "col": col, "row": row + 1}))


def write_csv(df, path) -> None:
    """Write a DataFrame as CSV (comma, '.', header row, full float precision), atomically."""
    with atomic_path(path) as tmp:
        # float_format=None with pandas writes repr(), i.e. the shortest round-trip form.
        df.to_csv(tmp, index=False, float_format=None, lineterminator="\n")


# ----------------------------------------------------------------------------- reports
#: Hidden names inside an output folder.  A run stages its files in
#: ``.crankdyn-stage.<pid>.<start>.<random>``, renames that folder to ``.crankdyn-commit``
#: when every file is complete (the point of no return), then moves the files into place
#: and writes the manifest ``.crankdyn-report.json`` last.
STAGE_PREFIX = ".crankdyn-stage."
COMMIT_NAME = ".crankdyn-commit"
MANIFEST_NAME = ".crankdyn-report.json"
#: The lock file of a run in progress (see :func:`_lock`); deleted by the run at its end.
LOCK_NAME = ".crankdyn-lock"
_OBSOLETE_NAME = ".obsolete.json"


def _reason(exc: OSError):
    return os_reason(exc)


def _output_error(exc: OSError, what: str, path=None) -> OutputError:
    """One line naming the path and the reason of a file-system error; ``what`` is the
    key of the action's text (``errors.output.create``)."""
    where = exc.filename if exc.filename is not None else path
    if where is not None:
        return OutputError(Text("errors.output.os_where", {"what": Text(what), "where": where,
                                                            "reason": _reason(exc)}))
    return OutputError(Text("errors.output.os", {"what": Text(what), "reason": _reason(exc)}))


def _process_start(pid: int):
    """Start time of a process, or None when the process does not exist; ``""`` when it
    exists but its start time cannot be read.

    Linux: clock ticks since boot from ``/proc/<pid>/stat``; Windows: the creation time
    from ``GetProcessTimes``; elsewhere (macOS, BSD: no /proc) ``os.kill(pid, 0)`` tells
    only whether the process exists."""
    if os.name == "nt":
        return _process_start_windows(pid)
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            stat = f.read()
        return stat.rsplit(b")", 1)[1].split()[19].decode()
    except FileNotFoundError:
        if os.path.isdir("/proc/self"):
            return None
        return _process_start_without_proc(pid)
    except (OSError, IndexError):
        return _process_start_without_proc(pid)


def _process_start_without_proc(pid: int):
    """``None`` if no process ``pid`` exists, else ``""`` (start time unknown).  POSIX
    only: on Windows ``os.kill(pid, 0)`` would terminate the process."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return None
    except PermissionError:
        pass
    except OSError:
        return ""
    return ""


def _process_start_windows(pid: int):
    """Windows: the creation time of process ``pid`` (100 ns units since 1601, as text),
    None when no such process is running, ``""`` when it exists but cannot be queried."""
    import ctypes
    from ctypes import wintypes

    kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
    kernel32.OpenProcess.restype = wintypes.HANDLE
    kernel32.OpenProcess.argtypes = (wintypes.DWORD, wintypes.BOOL, wintypes.DWORD)
    query_limited_information, error_invalid_parameter, still_active = 0x1000, 87, 259
    handle = kernel32.OpenProcess(query_limited_information, False, pid)
    if not handle:
        # no such process (ERROR_INVALID_PARAMETER); any other error (access denied):
        # it exists but belongs to someone else
        return None if ctypes.get_last_error() == error_invalid_parameter else ""
    try:
        code = wintypes.DWORD()
        if kernel32.GetExitCodeProcess(handle, ctypes.byref(code)) and \
                code.value != still_active:
            return None                 # exited; the handle only keeps its record alive
        times = [wintypes.FILETIME() for _ in range(4)]
        if not kernel32.GetProcessTimes(handle, *(ctypes.byref(t) for t in times)):
            return ""
        created = times[0]
        return str((created.dwHighDateTime << 32) | created.dwLowDateTime)
    finally:
        kernel32.CloseHandle(handle)


def _stage_is_dead(name: str) -> bool:
    """True when the run that owns staging folder ``name`` no longer exists (its pid is
    gone, or the pid now belongs to a process started at another time)."""
    parts = name[len(STAGE_PREFIX):].split(".")
    try:
        pid, start = int(parts[0]), parts[1]
    except (IndexError, ValueError):
        return True     # not a name this module makes: a leftover of an older version
    if pid == os.getpid():
        return False
    now = _process_start(pid)
    return now is None or (now != "" and start != "" and now != start)


def _sha256(path: Path) -> str:
    import hashlib

    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _fsync_dir(path: Path) -> None:
    """Flush a folder's entries (the renames in it) to disk where the system allows it:
    POSIX opens a folder read-only and fsyncs it; Windows cannot open a folder as a file
    (PermissionError) and needs no such step, NTFS journals its metadata: a no-op."""
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def read_manifest(directory):
    """The manifest of the report in ``directory`` (dict: ``files`` name → ``size`` and
    ``sha256``, ``created`` UTC time), or None when the folder holds no crankdyn report."""
    import json

    path = Path(directory) / MANIFEST_NAME
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as exc:
        raise OutputError(Text("errors.output.unreadable_report_manifest",
                               {"path": path, "exc": exc})) from None


def verify_report(directory) -> list[str]:
    """Check that ``directory`` holds one complete crankdyn report; return its file names.

    Raises :class:`OutputError` when a replacement was interrupted (a ``.crankdyn-commit``
    folder is present: the next run, or :func:`recover_output`, completes it), or when a
    file listed in the manifest is missing or differs from what was written.
    """
    directory = Path(directory)
    if (directory / COMMIT_NAME).exists():
        raise OutputError(Text("errors.output.report_replacement_was", {"directory": directory}))
    man = read_manifest(directory)
    if man is None:
        raise OutputError(Text("errors.output.no_crankdyn_report",
                               {"directory": directory, "MANIFEST_NAME": MANIFEST_NAME}))
    for name, info in man["files"].items():
        p = directory / name
        if not p.is_file() or p.stat().st_size != info["size"] or _sha256(p) != info["sha256"]:
            raise OutputError(Text("errors.output.not_file_report", {"p": p}))
    return sorted(man["files"])


def _roll_forward(directory: Path) -> None:
    """Finish an interrupted replacement: the ``.crankdyn-commit`` folder holds the new
    report complete with its manifest; move what is left of it into place (idempotent)."""
    import json

    commit = directory / COMMIT_NAME
    obsolete_file = commit / _OBSOLETE_NAME
    if obsolete_file.exists():
        for name in json.loads(obsolete_file.read_text(encoding="utf-8")):
            with contextlib.suppress(FileNotFoundError):
                os.unlink(directory / name)
        os.unlink(obsolete_file)
    for p in sorted(commit.iterdir()):
        if p.name != MANIFEST_NAME:
            os.replace(p, directory / p.name)
    if (commit / MANIFEST_NAME).exists():
        os.replace(commit / MANIFEST_NAME, directory / MANIFEST_NAME)
    os.rmdir(commit)
    _fsync_dir(directory)


def recover_output(directory) -> None:
    """Bring an output folder back to one complete report: finish a replacement that a
    killed run had begun (``.crankdyn-commit``) and delete the staging folders of runs that
    no longer exist.  Every run does this first, holding the folder's lock; call it
    yourself only while no crankdyn run writes into ``directory``.  The lock file a killed
    run left (``.crankdyn-lock``) is deleted too, unless a run holds it."""
    directory = Path(directory)
    _recover(directory)
    _remove_stale_lock(directory)


def _remove_stale_lock(directory: Path) -> None:
    """Delete the lock file of a killed run if no run holds it (taken without waiting)."""
    from filelock import Timeout

    if not (directory / LOCK_NAME).is_file():
        return
    lock = _filelock()(directory / LOCK_NAME, thread_local=False)
    try:
        lock.acquire(blocking=False)
    except (Timeout, OSError):
        return
    _unlock(lock, directory)


def _recover(directory: Path) -> None:
    import shutil

    commit = directory / COMMIT_NAME
    if commit.is_dir():
        if (commit / MANIFEST_NAME).exists():
            _roll_forward(directory)
        else:           # cannot happen with this module (the manifest goes in first)
            shutil.rmtree(commit)
    with os.scandir(directory) as it:
        stale = [e.name for e in it if e.name.startswith(STAGE_PREFIX) and e.is_dir()
                 and _stage_is_dead(e.name)]
    for name in stale:
        shutil.rmtree(directory / name, ignore_errors=True)


def _make_folder(directory: Path) -> list[Path]:
    """Create ``directory`` and its missing parents; return those created (outermost
    first) so a failed run can remove them again."""
    created = []
    for p in reversed([directory, *directory.parents]):
        if p.is_dir():
            continue
        try:
            p.mkdir()
        except FileExistsError:
            if not p.is_dir():
                raise OutputError(Text("errors.output.output_folder_exists_2",
                                       {"directory": directory, "p": p})) from None
            continue
        created.append(p)
    return created


def _filelock():
    """:class:`filelock.FileLock`: ``LockFileEx`` on Windows, ``flock`` on POSIX; where
    Python has no :mod:`fcntl` (an unusual POSIX build) filelock falls back to a lock by
    exclusive creation of the file, and its warning about that is not ours to print."""
    import warnings

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "only soft file lock is available")
        from filelock import FileLock
    return FileLock


def _lock(directory: Path):
    """An exclusive lock on the output folder: a :class:`filelock.FileLock` on the hidden
    file ``.crankdyn-lock`` inside it (``flock`` on POSIX, ``LockFileEx`` on Windows),
    held until :func:`_unlock`; None where the file system has no locks.

    :func:`_unlock` deletes the lock file while still holding it, so no run leaves it
    behind; a waiter that then obtains the lock on the deleted file sees that (filelock
    checks the link count, this function checks the file is there) and locks anew.  A
    run that fails removes a folder it created; a run that waited for that folder's lock
    then finds the path gone or a new folder there, and retries on the new one."""
    FileLock = _filelock()
    path = directory / LOCK_NAME
    for _ in range(100):
        _make_folder(directory.absolute())
        lock = FileLock(path, thread_local=False)
        try:
            lock.acquire()
        except FileNotFoundError:   # the folder was removed by a failed run meanwhile
            continue
        except NotImplementedError:  # a file system without locks of any kind
            return None
        if path.is_file():
            return lock
        lock.release()
    raise OutputError(Text("errors.output.output_folder_keeps", {"directory": directory}))


def _unlock(lock, directory: Path) -> None:
    """Delete the lock file of :func:`_lock` while the lock is still held, then release
    it (Windows refuses to delete an open file: there the file goes after the release,
    by filelock or here)."""
    path = directory / LOCK_NAME
    try:
        os.unlink(path)
        gone = True
    except FileNotFoundError:
        gone = True
    except OSError:         # Windows: a file open in any process cannot be deleted
        gone = False
    lock.release()
    # Never delete the path after the release on POSIX: another run may have created and
    # locked a new lock file there by now.  Windows refuses to delete one that another
    # run holds open, so the second try can only remove our own, now unlocked, file.
    if not gone and os.name == "nt":
        with contextlib.suppress(OSError):
            os.unlink(path)


def _in_unit(name: str, unit, info=None) -> bool:
    """Whether output file ``name`` of the previous manifest (its entry ``info``) belongs
    to the report named ``unit``; every file does when ``unit`` is None.  The manifest
    records the unit that wrote each file, so a file belongs to exactly that unit (the
    report ``press_b``'s ``press_b_plans.csv`` is not the report ``press``'s, though its
    name starts with ``press_``); an entry without a unit (a manifest of an older version,
    a report that was not named) is judged by its name: ``<unit>.xlsx``,
    ``<unit>_forces.csv`` …"""
    if unit is None:
        return True
    if info is not None and info.get("unit") is not None:
        return info["unit"] == unit
    return name.startswith((unit + "_", unit + "."))


def _commit(directory: Path, stage: Path, inputs, unit=None) -> None:
    import datetime
    import json

    names = sorted(p.name for p in stage.iterdir())
    check_not_input([directory / n for n in names], inputs)
    files = {}
    for n in names:
        p = stage / n
        with open(p, "rb") as f:
            os.fsync(f.fileno())
        files[n] = {"size": p.stat().st_size, "sha256": _sha256(p), "unit": unit}
    # files of the previous report that this one does not write are part of the old unit:
    # removed, unless the user has changed them since (then they are not ours any more)
    old = None
    with contextlib.suppress(OutputError):
        old = read_manifest(directory)
    obsolete = []
    if old is not None:
        ins = {Path(p).resolve() for p in inputs if p is not None}
        for n, info in old.get("files", {}).items():
            p = directory / n
            if n in files or p.resolve() in ins or not p.is_file():
                continue
            if not _in_unit(n, unit, info):    # another report's file in this folder
                files[n] = info
                continue
            if p.stat().st_size == info.get("size") and _sha256(p) == info.get("sha256"):
                obsolete.append(n)
    manifest = {"format": 1, "created": datetime.datetime.now(datetime.timezone.utc)
                .isoformat(timespec="seconds"), "files": files}
    (stage / MANIFEST_NAME).write_text(json.dumps(manifest, indent=1), encoding="utf-8")
    (stage / _OBSOLETE_NAME).write_text(json.dumps(obsolete), encoding="utf-8")
    _fsync_dir(stage)
    os.rename(stage, directory / COMMIT_NAME)      # the point of no return
    _roll_forward(directory)


@contextlib.contextmanager
def staged_output(directory, inputs=(), unit=None):
    """Context manager for a multi-file report, replaced as one unit.

    Yields a staging folder *inside* ``directory`` (so on the same file system, whatever
    is mounted where); write every file of the report there.  On success the report
    replaces the previous one as one unit; on an exception nothing in ``directory``
    changes, the staging folder is deleted, and a folder this call had to create is
    removed again.

    Protocol (documented in the README, section "Output folders"):

    1. ``directory`` (and missing parents) is created and locked (a ``filelock`` lock on
       the hidden file ``.crankdyn-lock`` in it, deleted again at the end of the run)
       for the rest of the call, so concurrent runs into one folder take turns and the
       folder ends with the complete report of the last one;
    2. :func:`recover_output` finishes a replacement a killed run had begun and deletes
       staging folders whose run no longer exists;
    3. the files are written into ``.crankdyn-stage.<pid>.<start>.<random>/``;
    4. commit: the files are fsynced and listed with size and SHA-256 in the manifest
       ``.crankdyn-report.json``; the staging folder is renamed to ``.crankdyn-commit``
       (one atomic rename: from here the new report is complete on disk); then the files
       of the old report that the new one does not write are deleted, the new files moved
       into place with ``os.replace`` and the manifest last; ``.crankdyn-commit`` is
       removed.  A kill during step 4 leaves ``.crankdyn-commit``, which the next run (or
       :func:`recover_output`) rolls forward; :func:`verify_report` refuses such a folder.

    Any :class:`OSError` (read-only file system, disk full, a path through a file, ...)
    becomes one :class:`OutputError` naming the path and the reason.  ``inputs`` are input
    paths that must not be overwritten (:class:`OutputError`).  ``unit``: the name of
    the report when its files are named after it (``<unit>.xlsx``, ``<unit>_*.csv``):
    then only the old files of that same report are replaced, and reports of other
    engines or mechanisms in the folder stay (and stay in the manifest, which records
    the unit of every file, so ``press`` never takes ``press_b``'s files for its own).
    """
    import shutil

    if directory is None or str(directory).strip() == "":
        raise OutputError(Text("errors.output.output_folder_empty"))
    directory = Path(directory)
    if directory.exists() and not directory.is_dir():
        raise OutputError(Text("errors.output.output_folder_exists", {"directory": directory}))
    try:
        created = _make_folder(directory.absolute())
    except OSError as exc:
        raise _output_error(exc, "errors.output.create", directory) from None
    stage = lock = None
    failed = False
    try:
        try:
            lock = _lock(directory)
            _recover(directory)
            start = _process_start(os.getpid()) or "0"
            stage = Path(tempfile.mkdtemp(prefix=f"{STAGE_PREFIX}{os.getpid()}.{start}.",
                                          dir=directory))
        except OSError as exc:
            raise _output_error(exc, "errors.output.write_into", directory) \
                from None
        try:
            yield stage
        except OSError as exc:   # name the output folder, not the hidden temporary file
            raise OutputError(Text("errors.output.cannot_write_report",
                                   {"directory": directory, "value": _reason(exc)})) \
                from None
        try:
            _commit(directory, stage, inputs, unit)
        except OSError as exc:
            raise _output_error(exc, "errors.output.replace_in", directory) from None
    except BaseException:
        failed = True
        if stage is not None:
            shutil.rmtree(stage, ignore_errors=True)
        if lock is not None:     # the folder must be empty to go (POSIX: still locked)
            with contextlib.suppress(OSError):
                os.unlink(directory / LOCK_NAME)
        _remove_folders(created)             # a failed run leaves no folder behind
        raise
    finally:
        if lock is not None:
            _unlock(lock, directory)
            if failed:                       # Windows: empty only after the release
                _remove_folders(created)


def _remove_folders(created) -> None:
    for p in reversed(created):
        with contextlib.suppress(OSError):
            p.rmdir()


@contextlib.contextmanager
def paused_gc():
    """While active, Python's cyclic garbage collector does not run (it runs again after,
    as it was: a nested use, or a caller that had it off, leaves it so); usable as a
    decorator, ``@paused_gc()``.

    Building and saving a workbook makes hundreds of thousands of openpyxl objects that
    live until the save (cells, their styles) and no garbage cycle: each collection the
    allocations set off scans them all again, a third of the time a report's workbook
    took.  Reference counting still frees everything at once; a cycle made meanwhile is
    collected at the next collection after."""
    import gc

    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()


@contextlib.contextmanager
def full_precision_xlsx():
    """While active, openpyxl stores floats at full precision, and writes number cells
    faster.

    openpyxl serialises numbers with ``"%.16g"``, which does not round-trip every double
    (one unit in the last place can be lost).  Inside this context, finite floats are
    written with Python's shortest round-trip representation instead, so a workbook read
    back equals the CSV bit for bit.  Wrap ``Workbook.save`` in it.

    A number cell (a finite float or an int, or an empty styled cell) is written as the
    text openpyxl's own writer makes of it, without building an element for it
    (:func:`_number_cell_writer`), a row's run of them as one text (its ``row_writer``),
    the rows found by sorting the sheet's cell keys alone: a report's workbook holds tens
    of thousands of them, and the element per cell was half the time of a save.  The file
    is the same byte for byte (tests/test_engine_workbook_charts.py compares them).
    """
    import math

    from openpyxl.cell import _writer
    from openpyxl.worksheet import _writer as sheet_writer

    original = _writer.safe_string
    original_cell = sheet_writer.write_cell
    writer = sheet_writer.WorksheetWriter
    original_row, original_rows = writer.write_row, writer.rows

    def safe_string(value):
        if isinstance(value, float) and math.isfinite(value):
            return float.__repr__(value)
        return original(value)

    safe_string.finite_float_text = float.__repr__
    _writer.safe_string = safe_string
    cell_writer = _number_cell_writer(original_cell, safe_string)
    sheet_writer.write_cell = cell_writer
    row_writer = getattr(cell_writer, "row_writer", None)
    if row_writer is not None:
        writer.write_row, writer.rows = row_writer, _sheet_rows
    try:
        with paused_gc():            # a save makes an object or more per cell
            yield
    finally:
        _writer.safe_string = original
        sheet_writer.write_cell = original_cell
        writer.write_row, writer.rows = original_row, original_rows


def _sheet_rows(self):
    """openpyxl's ``WorksheetWriter.rows``: [(row, its cells left to right)], a row of
    only a height or a style (a row dimension) with no cells; the cells' keys sorted
    alone (pairs of ints), several times cheaper than sorting the (key, cell) pairs."""
    import itertools
    import operator

    cells = self.ws._cells
    cell = cells.__getitem__
    rows = {r: list(map(cell, keys))
            for r, keys in itertools.groupby(sorted(cells), operator.itemgetter(0))}
    for r in self.ws.row_dimensions.keys() - rows.keys():
        rows[r] = []
    return sorted(rows.items())


def _number_cell_writer(write_cell, number_text):
    """openpyxl's ``write_cell(xf, worksheet, cell, styled)`` with a short way for the
    cells of a number and the empty styled ones: their XML text written straight to the
    file of the standard library's incremental writer (``et_xmlfile``, which openpyxl uses
    without lxml): ``<c r="B6" s="3" t="n"><v>1.5</v></c>``, ``<c r="B7" s="3" t="n" />``,
    the serialisation ``write_cell`` gives them (attributes r, s, t in that order; no
    character of a cell reference or a number needs escaping).  Every other cell (text,
    formula, date, bool, NaN, a hyperlink) and any other writer (lxml's) goes to
    ``write_cell``.  ``number_text``: the number's text (openpyxl's ``safe_string``).

    Its attribute ``row_writer`` is openpyxl's ``WorksheetWriter.write_row`` that writes
    a row's run of such cells as one text (a cell's style id looked up in the workbook's
    styles without openpyxl's per-cell properties) and hands every other cell to
    ``write_cell``, in the same order."""
    import math

    from openpyxl.comments.comment_sheet import CommentRecord
    from openpyxl.utils.cell import get_column_letter

    isfinite = math.isfinite
    # number_text of a finite float, when it says which (full_precision_xlsx's: repr)
    float_repr = getattr(number_text, "finite_float_text", number_text)

    def write(xf, worksheet, cell, styled=None):
        raw = getattr(xf, "_file", None)
        value = cell._value
        if raw is None or cell.data_type != "n" or cell.hyperlink:
            return write_cell(xf, worksheet, cell, styled)
        kind = type(value)
        if value is not None and not (kind is int or (kind is float and
                                                      isfinite(value))):
            return write_cell(xf, worksheet, cell, styled)
        style = f' s="{cell.style_id}"' if styled else ""
        if value is None:
            raw(f'<c r="{cell.coordinate}"{style} t="n" />')
        else:
            raw(f'<c r="{cell.coordinate}"{style} t="n"><v>{number_text(value)}</v></c>')

    letters = {}
    sid_cache = {}                  # {id(styles): (styles, {style ids' bytes: style id})}

    def write_row(self, xf, row, row_idx):
        # openpyxl's WorksheetWriter.write_row, the number cells as write() writes them
        ws = self.ws
        attrs = {"r": f"{row_idx}"}
        attrs.update(ws.row_dimensions.get(row_idx, {}))
        raw = getattr(xf, "_file", None)
        styles = ws.parent._cell_styles
        ids = styles._dict
        cache = sid_cache.get(id(styles))
        if cache is None or cache[0] is not styles:
            cache = sid_cache[id(styles)] = (styles, {})
        sids = cache[1]
        tail = f"{row_idx}"
        parts = []                  # the cells' texts, or (cell, styled) for write_cell
        plain = raw is not None
        for cell in row:
            comment = cell._comment
            if comment is not None:
                ws._comments.append(CommentRecord.from_cell(cell))
            st = cell._style
            if st is None:
                sid = -1
            else:
                # the style's id (-1: no style), found (or added to the workbook's styles)
                # in the order of the cells as openpyxl does; known by the bytes of the
                # style's ids (hashed in C) after its first cell
                key = st.tobytes()
                sid = sids.get(key)
                if sid is None:
                    if any(st):
                        sid = ids.get(st)
                        if sid is None:
                            sid = styles.add(st)
                    else:
                        sid = -1
                    sids[key] = sid
            styled = sid >= 0
            value = cell._value
            if value is None and not styled and not comment:
                continue
            kind = type(value)
            if raw is None or cell.data_type != "n" or getattr(cell, "_hyperlink", None) \
                    or not (value is None or kind is int or kind is float and isfinite(value)):
                parts.append((cell, styled))
                plain = False
                continue
            col = cell.column
            letter = letters.get(col)
            if letter is None:
                letter = letters[col] = get_column_letter(col)
            if value is None:
                parts.append(f'<c r="{letter}{tail}" s="{sid}" t="n" />' if styled
                             else f'<c r="{letter}{tail}" t="n" />')
                continue
            text = float_repr(value) if kind is float else number_text(value)
            parts.append(f'<c r="{letter}{tail}" s="{sid}" t="n"><v>{text}</v></c>' if styled
                         else f'<c r="{letter}{tail}" t="n"><v>{text}</v></c>')
        if plain and all(k[:1] != "{" and _PLAIN_ATTRIBUTE.match(v) for k, v in attrs.items()):
            # the row element as et_xmlfile writes it (attributes in order, none to
            # escape; an opening and a closing tag), around its cells' texts
            raw("<row" + "".join(f' {k}="{v}"' for k, v in attrs.items()) + ">"
                + "".join(parts) + "</row>")
            return
        with xf.element("row", attrs):
            run = []
            for part in parts:
                if type(part) is str:
                    run.append(part)
                    continue
                if run:
                    raw("".join(run))
                    run = []
                write_cell(xf, ws, *part)
            if run:
                raw("".join(run))

    write.row_writer = write_row
    return write


#: An attribute value of a row that needs no escaping in XML (a number, a flag).
_PLAIN_ATTRIBUTE = re.compile(r"[\w.+-]*\Z")


#: Device names Windows reserves, with any extension and in any case (``con.xlsx``,
#: ``Aux_forces.csv`` is fine, ``nul.v2.csv`` is not): the stem before the first dot.
WINDOWS_RESERVED = frozenset(
    ["CON", "PRN", "AUX", "NUL", "CONIN$", "CONOUT$"]
    + [f"{dev}{i}" for dev in ("COM", "LPT") for i in (*"123456789", "\u00b9", "\u00b2",
                                                       "\u00b3")])


def safe_name(name: str, default: str = "report", max_bytes: int = 160) -> str:
    """A file-name stem from a spec's name, valid on Windows, macOS and Linux alike:
    letters (any script), digits, ``_``, ``.`` and ``-`` kept, every other run of
    characters (spaces, control characters, ``<>:"/\\|?*``) replaced by ``_``; no leading
    or trailing dot or ``_``; ``default`` if nothing is left; cut to at most ``max_bytes``
    bytes of UTF-8 (at a character boundary), so the file name fits any common file
    system.  A name Windows reserves for a device (:data:`WINDOWS_RESERVED`: ``CON``,
    ``nul``, ``COM1``, ``lpt9.v2`` ...) gets ``_`` after its first part (``CON_``,
    ``nul_``, ``lpt9_.v2``).  The full name stays inside the report."""
    import re

    stem = re.sub(r"[^\w.-]+", "_", name).strip("._") or default
    cut = stem.encode("utf-8")[:max_bytes].decode("utf-8", "ignore").rstrip("._") \
        or default
    first, dot, rest = cut.partition(".")
    if first.upper() in WINDOWS_RESERVED:
        cut = f"{first}_{dot}{rest}"
    return cut


def save_figure(fig, stem, formats=("png", "svg"), dpi=110, tight=False) -> list[Path]:
    """Save a matplotlib figure as ``stem.<fmt>`` for each format, each file atomically.

    ``stem`` is a path without suffix.  ``tight`` crops to the drawn content (keeps a
    legend placed outside the axes inside the image).  Returns the paths written.
    A figure with a layout engine is laid out once per file and drawn once
    (:func:`crankbase.plot_layout.save_laid_out`), not twice as by ``fig.savefig``; the
    files are the same.
    """
    from .plot_layout import save_laid_out
    from .plot_texts import cjk_texts

    cjk_texts(fig)           # Chinese labels: their mathtext as plain text (CJK fallback)
    paths = []
    extra = {"bbox_inches": "tight", "pad_inches": 0.15} if tight else {}
    for fmt in formats:
        path = Path(f"{stem}.{fmt}")
        with atomic_path(path) as tmp:      # a figure with a layout engine: drawn once
            save_laid_out(fig, tmp, fmt, dpi, **extra)
        paths.append(path)
    return paths


#: File formats a report's figures can be saved in (:func:`figure_formats`).
FIGURE_FORMATS = ("png", "svg", "pdf")


def figure_formats(formats) -> tuple:
    """``formats`` (one of :data:`FIGURE_FORMATS` or a sequence of them, each once) as a
    tuple.

    Raises
    ------
    SpecError
        Named ``formats``: empty, unknown or repeated.
    """
    if isinstance(formats, str):
        formats = (formats,)
    formats = tuple(formats)
    bad = [f for f in formats if f not in FIGURE_FORMATS]
    if not formats or bad or len(set(formats)) != len(formats):
        raise SpecError(Problem("formats", Text("errors.output.formats",
                                                {"formats": formats,
                                                 "items": ", ".join(FIGURE_FORMATS)})))
    return formats


def output_folder(out) -> Path:
    """``out`` as a :class:`~pathlib.Path` of a report folder (it may not exist yet).

    Raises
    ------
    SpecError
        Named ``out``: it exists and is not a folder.
    """
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise SpecError(Problem("out", Text("errors.output.not_a_folder", {"out": out})))
    return out
