"""The engine page's work: start from an example, an upload or the form; compute; write.

Everything a session holds for the page is an :class:`EngineState` (the field texts, the
pressure source, the uploaded pressure file as bytes, the problems of the last try, the
last :class:`Run`).  :func:`compute` validates and computes through the library
(:func:`engine.load`, :func:`engine.run_study`), :func:`write` writes the report
(:func:`engine.write_report`) and its zip into the run's own folder.  Both run in the
job pool (:mod:`web.jobs`); the page shows Table 2 and the summary as soon as
:func:`compute` is done, the figures and downloads when :func:`write` is.
"""
from __future__ import annotations

import csv
import io
import threading
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["EXAMPLES", "EngineState", "Run", "example_spec", "compute", "write",
           "table_rows", "PRESSURE_NAMES", "FIGURE_FORMAT"]

#: The bundled examples by short name (the same as ``crankdyn engine --example NAME``).
EXAMPLES = {"petrol": "petrol_vaz2106.toml", "diesel": "diesel_d240.toml",
            "six": "petrol_bmw_m54.toml", "v8": "diesel_kamaz740.toml"}
#: The server's own names of an uploaded pressure file (a CSV, or a Diesel-RK export).
PRESSURE_NAMES = ("pressure.csv", "pressure.ind")
#: The figures are written (and shown) as PNG.
FIGURE_FORMAT = "png"


@dataclass
class Run:
    """One computation of a session: the report, its spec and, once written, its files
    (``{file name: path}``, the only names a download may ask for)."""

    number: int
    folder: Path
    report: object
    spec: dict
    lang: str
    pressure: tuple | None = None          # (server name, bytes)
    drawing: bool = False
    write_future: object = None
    files: dict = field(default_factory=dict)
    zip_name: str = ""
    toml_name: str = ""


@dataclass
class EngineState:
    values: dict = field(default_factory=dict)
    source: str = "cycle"
    bearings: bool = False
    drawing: bool = False
    pressure: tuple | None = None          # (server name, bytes) of the uploaded file
    problems: list = field(default_factory=list)
    notice: object = None                  # a crankbase.errors.Text
    run: Run | None = None
    runs: int = 0
    lock: threading.Lock = field(default_factory=threading.Lock)


def example_spec(name: str) -> tuple[dict, tuple | None]:
    """The spec dict of the bundled example ``name`` (a key of :data:`EXAMPLES`) and its
    pressure file as ``(server name, bytes)`` when it has one."""
    import tomllib

    from crankbase.resources import example_path

    data = tomllib.loads(example_path(EXAMPLES[name]).read_text(encoding="utf-8"))
    pr = data.get("pressure", {})
    pressure = None
    if "file" in pr:
        fname = pr["file"]
        server = PRESSURE_NAMES[1] if fname.lower().endswith(".ind") else PRESSURE_NAMES[0]
        pressure = (server, example_path(fname).read_bytes())
    return data, pressure


def pressure_name(upload_name: str, spec_file: str | None = None) -> str:
    """The server's name for an uploaded pressure file: a Diesel-RK export when the
    upload or the spec names an ``.ind`` file, else a CSV (only this choice is taken from
    the names; the names themselves never reach the file system)."""
    names = [n for n in (upload_name, spec_file) if isinstance(n, str)]
    return PRESSURE_NAMES[1] if any(n.lower().endswith(".ind") for n in names) \
        else PRESSURE_NAMES[0]


def compute(data: dict, input_dir: Path, pressure, bearings: bool):
    """Validate ``data`` (:func:`engine.load`, the pressure file, if any, written into
    ``input_dir`` first under its server name) and compute the whole report
    (:func:`engine.run_study`).  Raises the library's :class:`~crankbase.errors.SpecError`
    with every problem."""
    import engine

    input_dir.mkdir(parents=True, exist_ok=True)
    for n in PRESSURE_NAMES:
        (input_dir / n).unlink(missing_ok=True)
    if pressure is not None:
        (input_dir / pressure[0]).write_bytes(pressure[1])
    study = engine.load(data, base_dir=input_dir)
    return engine.run_study(study, bearings=bearings)


def spec_toml(spec: dict) -> str:
    import tomli_w

    return tomli_w.dumps(spec)


def write(run: Run, drawing: bool) -> dict:
    """Write the run's report into its folder (:func:`engine.write_report`), then its
    spec TOML (and pressure file) and a zip of all; ``{file name: path}``."""
    import engine

    report = run.report
    written = engine.write_report(report, run.folder / "report", run.lang,
                                  formats=(FIGURE_FORMAT,), drawing=drawing)
    files = {p.name: p for p in written}
    spec = run.folder / "spec"
    spec.mkdir(exist_ok=True)
    toml = spec / f"{report.name}.toml"
    toml.write_text(spec_toml(run.spec), encoding="utf-8")
    files[toml.name] = toml
    if run.pressure is not None:
        p = spec / run.pressure[0]
        p.write_bytes(run.pressure[1])
        files[p.name] = p
    zpath = run.folder / f"{report.name}_report.zip"
    with zipfile.ZipFile(zpath, "w", zipfile.ZIP_DEFLATED) as z:
        for name, path in files.items():
            z.write(path, arcname=name)
    run.zip_name, run.toml_name = zpath.name, toml.name
    files[zpath.name] = zpath
    return files


def table_rows(df) -> tuple[list, list]:
    """``(header, rows)`` of a table as its CSV holds them: the same pandas call as
    :func:`crankbase.output.write_csv` (shortest round-trip floats), read back as text,
    so the page shows exactly the numbers of the downloaded CSV."""
    text = df.to_csv(index=False, float_format=None, lineterminator="\n")
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], rows[1:]
