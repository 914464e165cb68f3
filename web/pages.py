"""What every page of the app shares: a session's state of a page, one run, and the
description of a page (:class:`Kind`): its schema, examples, computation and results.

:mod:`web.engine_page` and :mod:`web.linkage_page` each define one :class:`Kind`;
:mod:`web.app` serves every kind through the same handlers (example, upload, form, files).
"""
from __future__ import annotations

import csv
import io
import threading
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["PageState", "Run", "Kind", "table_rows", "spec_toml", "finish_files", "PAGE_ROWS",
           "render_job", "report_blob", "write_and_list"]


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
    options: dict = field(default_factory=dict)
    write_future: object = None
    #: Starts the drawing of a run not yet drawn (``web.app.build_app(draw="on_request")``):
    #: a callable returning the drawing job's future; None once started (or drawn ahead).
    draw: object = None


@dataclass
class PageState:
    """What a session holds of one page between requests."""

    values: dict = field(default_factory=dict)
    source: str = "cycle"
    options: dict = field(default_factory=dict)
    pressure: tuple | None = None          # (server name, bytes) of the uploaded file
    problems: list = field(default_factory=list)
    notice: object = None                  # a crankbase.errors.Text
    run: Run | None = None
    runs: int = 0
    lock: threading.Lock = field(default_factory=threading.Lock)


class Kind:
    """One page: override the attributes and methods."""

    name = ""                  # the URL: /<name>
    nav_key = ""               # its name in the menu
    title_key = intro_key = ""
    results_template = options_template = ""
    examples: dict = {}        # short name: bundled file
    example_prefix = ""        # text keys of the examples' labels: <prefix><short name>
    has_pressure = False
    extra_fields: tuple = ()   # problem keys shown at a field outside the schema's
    wait_for_files = False     # the results list files known only once written

    def schema(self):
        raise NotImplementedError

    def schema_for(self, data: dict | None = None, values: dict | None = None):
        """The schema of the form for a spec dict ``data`` or the posted field texts
        ``values`` (a page whose spec has several shapes chooses; default
        :meth:`schema`)."""
        return self.schema()

    def waits(self, run: Run) -> bool:
        """Whether the results list files known only once written."""
        return self.wait_for_files or bool(run.options.get("drawing"))

    def example_spec(self, name) -> tuple:
        """``(spec dict, pressure file as (server name, bytes) or None)``."""
        import tomllib

        from crankbase.resources import example_path

        return tomllib.loads(example_path(self.examples[name]).read_text(
            encoding="utf-8")), None

    def options(self, values: dict) -> dict:
        """The page's options, taken out of the posted ``values``."""
        return {}

    def spec_options(self, data: dict, options: dict) -> dict:
        """The page's options once a spec (an example, an upload) is loaded."""
        return options

    def form_spec(self, data: dict, options: dict) -> dict:
        """The spec dict the form's fields make, as the page's options take it."""
        return data

    def compute(self, data, input_dir, pressure, options):
        raise NotImplementedError

    def write(self, run: Run) -> dict:
        raise NotImplementedError

    def results(self, run: Run, lang: str, files=None) -> dict:
        """What the results show: ``name`` (the file stem), ``head``/``rows`` and
        ``head2``/``rows2`` (two tables), ``title1``/``title2``, ``summary`` (lines),
        ``figures`` and ``tables`` (file names), ``xlsx``, ``toml_label``; optionally
        ``toml`` and ``zip`` (other names of the spec and the zip), ``command`` (the
        command line that repeats the run), ``drawings`` (the drawings' files); ``files``:
        the written files, when :meth:`waits`."""
        raise NotImplementedError


#: Rows of a table the page shows at most (the CSV holds them all): a fine step can make
#: tens of thousands, too many for a page.
PAGE_ROWS = 1000


def table_rows(df, limit: int = PAGE_ROWS) -> tuple[list, list]:
    """``(header, rows)`` of a table as its CSV holds them: the same pandas call as
    :func:`crankbase.output.write_csv` (shortest round-trip floats), read back as text,
    so the page shows exactly the numbers of the downloaded CSV; the first ``limit``
    rows (``len(df)`` tells how many there are)."""
    text = df.iloc[:limit].to_csv(index=False, float_format=None, lineterminator="\n")
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], rows[1:]


def spec_toml(spec: dict) -> str:
    import tomli_w

    return tomli_w.dumps(spec)


def finish_files(run: Run, name: str, files: dict, spec_name: str | None = None) -> dict:
    """Add the run's spec TOML (``spec_name``, default ``<name>.toml``; and the pressure
    file) and a zip of every file to ``files`` (``{file name: path}`` of the written
    report)."""
    spec = run.folder / "spec"
    spec.mkdir(exist_ok=True)
    toml = spec / (spec_name or f"{name}.toml")
    toml.write_text(spec_toml(run.spec), encoding="utf-8")
    files[toml.name] = toml
    if run.pressure is not None:
        p = spec / run.pressure[0]
        p.write_bytes(run.pressure[1])
        files[p.name] = p
    zpath = run.folder / f"{name}_report.zip"
    with zipfile.ZipFile(zpath, "w", zipfile.ZIP_DEFLATED) as z:
        for fname, path in files.items():
            z.write(path, arcname=fname)
    files[zpath.name] = zpath
    return files


def _mappingproxy(items: dict):
    """A read-only mapping again (:func:`report_blob`: ``types.MappingProxyType`` has no
    pickle of its own)."""
    from types import MappingProxyType

    return MappingProxyType(items)


def report_blob(report) -> bytes | None:
    """``report`` pickled for a drawing process (its read-only mappings as
    :func:`_mappingproxy` calls), or None when it holds something that does not pickle
    (the drawing process then computes it again from its spec)."""
    import pickle
    from types import MappingProxyType

    class Pickler(pickle.Pickler):
        def reducer_override(self, obj):
            if type(obj) is MappingProxyType:
                return _mappingproxy, (dict(obj),)
            return NotImplemented

    buf = io.BytesIO()
    try:
        Pickler(buf, protocol=pickle.HIGHEST_PROTOCOL).dump(report)
    except Exception:                       # noqa: BLE001 - any failure: compute again
        return None
    return buf.getvalue()


def render_job(kind: Kind, number: int, folder: Path, spec: dict, lang: str, pressure,
               options: dict, blob: bytes | None = None) -> dict:
    """Write one run's report in a drawing process (:mod:`web.jobs`, "spawn"), then
    :meth:`Kind.write`; ``{file name: path}``.  The report is the page's own, pickled
    (``blob``, :func:`report_blob`: the study is computed once per run, a chain's
    dynamics costs as much as its drawing); without it, the study computed again from
    its spec (the same numbers: the study is a function of its spec and options)."""
    if blob is not None:
        import pickle

        report = pickle.loads(blob)
    else:
        report = kind.compute(spec, folder / "input", pressure, options)
    return kind.write(Run(number=number, folder=folder, report=report, spec=spec, lang=lang,
                          pressure=pressure, options=options))


def write_and_list(run: Run, write_report) -> dict:
    """Write ``run``'s report with a study layer's ``write_report(report, out, lang,
    formats=…)`` into the run's ``report`` folder (PNG figures only: the page shows them),
    and finish its files (:func:`finish_files`): every written file by its name."""
    out = run.folder / "report"
    write_report(run.report, out, run.lang, formats=("png",))
    files = {p.name: p for p in sorted(out.iterdir())
             if p.is_file() and not p.name.startswith(".")}
    return finish_files(run, run.report.stem, files)
