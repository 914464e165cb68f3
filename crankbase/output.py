"""Safe report output: write to a temporary file in the target folder, then rename.

A crash or a bad value never leaves half a report, and an existing report is replaced
only by a complete new one.  Inputs are never overwritten: :func:`check_not_input`
refuses an output path that is one of the input files.
"""
from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

import numpy as np

from .errors import OutputError

__all__ = ["atomic_path", "staged_output", "write_csv", "check_not_input", "ensure_finite",
           "full_precision_xlsx", "safe_name", "save_figure", "OutputError"]


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
            raise OutputError(f"output {out} is an input file; choose another output folder")


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
            raise OutputError(f"{what}: column {col} is not finite at row {row + 1}")


def write_csv(df, path) -> None:
    """Write a DataFrame as CSV (comma, '.', header row, full float precision), atomically."""
    with atomic_path(path) as tmp:
        # float_format=None with pandas writes repr(), i.e. the shortest round-trip form.
        df.to_csv(tmp, index=False, float_format=None, lineterminator="\n")


@contextlib.contextmanager
def staged_output(directory, inputs=()):
    """Context manager for a multi-file report: yields a staging folder; on success every
    file in it is moved into ``directory`` (created if needed), replacing older files of
    the same name one by one with ``os.replace``; on an exception nothing is moved and the
    staging folder is deleted, so a failed run writes nothing.

    ``inputs`` are input paths that must not be overwritten (:class:`OutputError`).
    """
    import shutil

    directory = Path(directory)
    if directory.exists() and not directory.is_dir():
        raise OutputError(f"output {directory} exists and is not a folder")
    parent = directory.resolve().parent
    parent.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=f".{directory.name}.staging.", dir=parent))
    try:
        yield stage
        names = sorted(p.name for p in stage.iterdir())
        check_not_input([directory / n for n in names], inputs)
        directory.mkdir(parents=True, exist_ok=True)
        for name in names:
            os.replace(stage / name, directory / name)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


@contextlib.contextmanager
def full_precision_xlsx():
    """While active, openpyxl stores floats at full precision.

    openpyxl serialises numbers with ``"%.16g"``, which does not round-trip every double
    (one unit in the last place can be lost).  Inside this context, finite floats are
    written with Python's shortest round-trip representation instead, so a workbook read
    back equals the CSV bit for bit.  Wrap ``Workbook.save`` in it.
    """
    import math

    from openpyxl.cell import _writer

    original = _writer.safe_string

    def safe_string(value):
        if isinstance(value, float) and math.isfinite(value):
            return float.__repr__(value)
        return original(value)

    _writer.safe_string = safe_string
    try:
        yield
    finally:
        _writer.safe_string = original


def safe_name(name: str, default: str = "report") -> str:
    """A file-name stem from a spec's name: letters (any script), digits, ``_``, ``.`` and
    ``-`` kept, every other run of characters replaced by ``_``; ``default`` if nothing is
    left.  The full name stays inside the report."""
    import re

    return re.sub(r"[^\w.-]+", "_", name).strip("._") or default


def save_figure(fig, stem, formats=("png", "svg"), dpi=110, tight=False) -> list[Path]:
    """Save a matplotlib figure as ``stem.<fmt>`` for each format, each file atomically.

    ``stem`` is a path without suffix.  ``tight`` crops to the drawn content (keeps a
    legend placed outside the axes inside the image).  Returns the paths written.
    """
    paths = []
    extra = {"bbox_inches": "tight", "pad_inches": 0.15} if tight else {}
    for fmt in formats:
        path = Path(f"{stem}.{fmt}")
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format=fmt, dpi=dpi, **extra)
        paths.append(path)
    return paths
