"""The teacher's page: a whole class's reports from a base spec and a variants table.

The teacher uploads the base engine spec (with its pressure file when it names one) and
the variants table (CSV or .xlsx: a ``variant`` column and one column per spec key); the
batch is :func:`engine.variants.run_variants` (each variant's complete report, its spec,
the summary table, the bad rows' problems), run in processes (its figures are drawn there,
not in the server's drawing thread) while the page shows a progress bar; the result is one
zip of every report and the summary.
"""
from __future__ import annotations

import shutil
import threading
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Batch", "TeacherState", "MAX_VARIANTS", "prepare", "run_batch"]

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
class TeacherState:
    batch: Batch | None = None
    problems: list = field(default_factory=list)        # rendered lines
    runs: int = 0
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
