"""Test-suite configuration.

Under CI (the environment variable ``CI`` set, as ``.ci/run`` runs) hypothesis draws the
same examples on every run (``derandomize``), so a submission's result does not depend on
chance; a developer's local run keeps drawing new random examples, which is how new
counter-examples are found (and then written into the tests).

Reports rendered once per session (:func:`cli_report`): the end-to-end runs of the CLI
that several test files only read (an engine report with its 13 plots costs about 3 s of
CPU, most of it rendering PNG and SVG) are written once and shared, across the
pytest-xdist workers too (the first worker that asks writes it, the others wait for it).

Tests that share an expensive module-scoped fixture run on one xdist worker
(:func:`pytest_collection_modifyitems` puts them in one ``xdist_group``; ``--dist
loadgroup`` in ``pyproject.toml``), so the fixture is built once, not once per worker."""
import contextlib
import hashlib
import io
import json
import os
import time
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import settings

from rendering import save_through_savefig

settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")


@pytest.hookimpl(tryfirst=True)     # before xdist's, which reads the groups (below)
def pytest_collection_modifyitems(config, items):
    """Every test that uses a module-scoped fixture goes to the ``xdist_group`` of its
    module (and of the fixture's parameter, when the fixture is parametrized): under
    ``--dist loadgroup`` one worker builds that fixture once.  Other tests are spread
    over the workers one by one.

    The modules that hold a test marked ``slow`` run first (each module's tests stay
    together and in their order), so the longest tests do not start last, with one
    worker busy and the other idle at the end."""
    def module(item):
        return getattr(getattr(item, "module", None), "__name__", "")

    slow = {module(item) for item in items if item.get_closest_marker("slow")}
    items.sort(key=lambda item: module(item) not in slow)               # stable
    for item in items:
        info = getattr(item, "_fixtureinfo", None)
        if info is None or item.get_closest_marker("xdist_group"):
            continue
        shared = sorted(name for name, defs in info.name2fixturedefs.items()
                        if defs and defs[-1].scope == "module")
        if not shared:
            continue
        params = getattr(getattr(item, "callspec", None), "params", {})
        key = [module(item)]
        key += [f"{n}={params[n]!r}" for n in shared if n in params]
        item.add_marker(pytest.mark.xdist_group("|".join(key)))


@dataclass(frozen=True)
class Report:
    """One run of ``crankdyn ARGV -o folder``: the folder, exit status and terminal text;
    ``rendered``: whether its figures were drawn (False for :data:`UNRENDERED_REPORTS`)."""
    folder: Path
    rc: int
    out: str
    err: str
    rendered: bool = True


#: The shared reports (:func:`cli_report`) whose figures are saved unrendered (each file
#: written under its name by the report's own ``savefig`` call and listed in the
#: manifest, its bytes a short text naming the format, as :func:`unrendered_figures`
#: writes): no test reads these runs' figure bytes beyond their names and sizes above 0
#: (the web pages' PNGs are drawn by the app itself).  Each repeats figures a rendered
#: run draws and checks as PNG and SVG: ``dynamics`` press, petrol and hoist in Russian
#: (tests/test_dynamics_reports.py); ``engine`` petrol and diesel in Russian and the V8
#: with its bearings (Russian; tests/test_engine_cli.py::test_plots_exist_and_are_not_empty);
#: the Russian ratchet's plans (``--plans 5,11``, tests/test_plans_output.py) and the
#: Chinese one's (a glyph missing from a font would show on its stderr,
#: tests/test_cli_linkage.py) for the English ratchet's plans and the A3 sheets the web
#: pages compare (their CSVs only).  The shaper's dynamics and the Kolchin form are read for their tables,
#: workbooks and terminal text only.  Each figure's layout in each language is checked
#: without rendering in tests/test_figures_clean.py.
UNRENDERED_REPORTS = frozenset({
    ("dynamics", "--example", "press", "--lang", "en"),
    ("dynamics", "--example", "petrol", "--lang", "en"),
    ("dynamics", "--example", "hoist", "--lang", "en"),
    ("dynamics", "--example", "shaper", "--lang", "en"),
    ("engine", "--example", "petrol", "--lang", "en"),
    ("engine", "--example", "diesel", "--lang", "en"),
    ("engine", "--example", "v8", "--lang", "en"),
    ("engine", "--example", "diesel", "--lang", "ru", "--form", "kolchin"),
    ("linkage", "--example", "--no-plots", "--plans", "5", "--lang", "en"),
    ("linkage", "--example", "shaper", "--plans", "2,5", "--sheet", "A3", "--lang", "en",
     "--no-plots"),
    ("linkage", "--example", "ratchet", "--plans", "5", "--sheet", "A3", "--lang", "en",
     "--no-plots"),
})


#: How long a worker waits for another one to write a shared report.
WAIT_S = 900.0


def _shared_root(tmp_path_factory):
    """The folder every worker of this session sees: the session's base temporary folder
    (under xdist, the parent of the workers' own ones)."""
    base = tmp_path_factory.getbasetemp()
    root = (base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / "cli_reports"
    root.mkdir(exist_ok=True)
    return root


#: matplotlib's own ``Figure.savefig``, kept by :func:`unrendered_figures` before it
#: patches it, so that a shared report is always rendered for real.
_REAL_SAVEFIG = {}


def _run_cli(key, folder):
    from crankdyn.cli import main

    o, e = io.StringIO(), io.StringIO()
    rendered = key not in UNRENDERED_REPORTS
    with contextlib.ExitStack() as stack:
        real = _REAL_SAVEFIG.get("savefig")
        if real is not None or not rendered:   # a test with unrendered_figures may be
            from matplotlib.figure import Figure    # asking for it

            stack.callback(setattr, Figure, "savefig", Figure.savefig)
            Figure.savefig = real if rendered else _savefig_rendering_only((), [])
            if not rendered:
                import crankbase.plot_layout as layout

                stack.callback(setattr, layout, "save_laid_out", layout.save_laid_out)
                layout.save_laid_out = save_through_savefig
        with contextlib.redirect_stdout(o), contextlib.redirect_stderr(e):
            rc = main([*key, "-o", str(folder)])
    return Report(folder, rc, o.getvalue(), e.getvalue(), rendered)


def _shared_run(root, key, wait=True):
    """The report of ``key``, written by whichever process asks first: the writer holds
    the lock folder ``<name>.lock`` (``mkdir`` is atomic) and leaves ``<name>.json``
    (exit status and terminal text) when the report is complete; the others wait for
    that file (or, ``wait=False``, get None while it is being written)."""
    name = "_".join(k.lstrip("-") for k in key[:3]) + "_" + \
        hashlib.sha1("\0".join(key).encode()).hexdigest()[:10]
    done = root / f"{name}.json"
    folder = root / name
    try:
        (root / f"{name}.lock").mkdir()
    except FileExistsError:                         # another worker writes it
        if not wait and not done.exists():
            return None
        deadline = time.monotonic() + WAIT_S
        while not done.exists():
            if time.monotonic() > deadline:
                raise TimeoutError(f"no shared report {key} after {WAIT_S} s")
            time.sleep(0.05)
        rec = json.loads(done.read_text(encoding="utf-8"))
        if "error" in rec:
            raise RuntimeError(f"the shared report {key} failed in another worker: "
                               f"{rec['error']}")
        return Report(folder, rec["rc"], rec["out"], rec["err"],
                      key not in UNRENDERED_REPORTS)
    try:
        rep = _run_cli(key, folder)
        rec = {"rc": rep.rc, "out": rep.out, "err": rep.err}
    except BaseException as exc:
        rec = {"error": repr(exc)}
        raise
    finally:
        tmp = root / f"{name}.json.part"
        tmp.write_text(json.dumps(rec), encoding="utf-8")
        os.replace(tmp, done)
    return rep


@pytest.fixture(scope="session")
def cli_report(tmp_path_factory):
    """``cli_report(*argv)``: the :class:`Report` of ``crankdyn *argv -o <folder>``, run
    once per session for each distinct ``argv`` (once for all xdist workers) and shared
    by every test that asks for it.  Shared means read-only: a test that changes a
    report's files must run its own (at the end of the session every shared report is
    checked against its manifest, so a test that altered one fails there).
    ``cli_report.many([argv, ...])``: the reports of several runs, in that order."""
    root = _shared_root(tmp_path_factory)
    cache = {}

    def run(*argv):
        key = tuple(str(a) for a in argv)
        if key not in cache:
            cache[key] = _shared_run(root, key)
        return cache[key]

    def many(argvs):
        """``[run(*argv) for argv in argvs]``, but this worker first writes those no
        other worker is writing, then waits for the rest (two workers asking for the
        same reports in the same order do not wait for each other in turn)."""
        keys = [tuple(str(a) for a in argv) for argv in argvs]
        for key in keys:
            if key not in cache:
                rep = _shared_run(root, key, wait=False)
                if rep is not None:
                    cache[key] = rep
        return [run(*key) for key in keys]

    run.many = many
    yield run
    from crankbase.output import verify_report

    for key, rep in cache.items():
        if rep.rc == 0:
            verify_report(rep.folder)       # no test altered a shared report


@pytest.fixture
def unrendered_figures(monkeypatch):
    """Figures saved without being drawn: ``Figure.savefig`` writes a short text naming
    the format instead of rendering PNG, SVG or PDF (a third of a report's CPU).  For the
    tests that check which files a run writes, keeps and removes (names, manifest, stale
    files), not what a plot shows; each such test relies on a rendered end-to-end report
    (the session's :func:`cli_report`) to prove the real files are written.  Returns the
    list of the formats saved so, one per file."""
    from pathlib import PurePath

    from matplotlib.figure import Figure

    saved = []

    def savefig(self, fname, *args, format=None, **kwargs):
        fmt = format or PurePath(str(fname)).suffix.lstrip(".") or "png"
        data = f"figure not rendered ({fmt}), tests/conftest.py\n".encode()
        if hasattr(fname, "write"):
            fname.write(data)
        else:
            Path(fname).write_bytes(data)
        saved.append(fmt)

    _REAL_SAVEFIG.setdefault("savefig", Figure.savefig)
    monkeypatch.setattr(Figure, "savefig", savefig)
    monkeypatch.setattr("crankbase.plot_layout.save_laid_out", save_through_savefig)
    return saved


# --------------------------------------------------------------------------- the web app
#: The upload limit of the tests' app (big enough for the teacher's workbooks; the limit's
#: message is checked in tests/test_web.py with a bigger upload).
WEB_UPLOAD_LIMIT = 1_500_000


@pytest.fixture(scope="session")
def web_app(tmp_path_factory):
    """One app (``web.create_app``, two render processes) for every web test module a
    worker runs: each module built its own before, and each app's render processes import
    the whole library.  ``app.root`` is its sessions' folder.  Each module's autouse
    fixture drains the renders its tests asked for (``app.app.state.render.drain``).
    It draws ahead, as ``crankdyn serve`` does by default: a test's app drawing on
    request (``draw="on_request"``) saved ~2 s (nearly every drawing is read by some
    test) and would leave the default mode to one test; the other mode is
    tests/test_web.py ``test_a_run_is_drawn_ahead_or_when_first_asked_for``'s."""
    import web

    root = tmp_path_factory.mktemp("webroot")
    a = web.create_app(root=root, upload_limit=WEB_UPLOAD_LIMIT, workers=2)
    a.root = root
    return a


# ------------------------------------------------------------------------- tests-figures
def _savefig_rendering_only(parts, saved):
    """A ``Figure.savefig`` that renders for real only the files whose name holds one of
    ``parts`` and saves every other figure as :func:`unrendered_figures` does (a short
    text naming the format; a drawing sheet saved into a ``PdfPages`` too: the text is
    its PDF file); appends ``(file name, rendered)`` to ``saved``."""
    from pathlib import PurePath

    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    real = _REAL_SAVEFIG.setdefault("savefig", Figure.savefig)

    def savefig(self, fname, *args, format=None, **kwargs):
        if isinstance(fname, PdfPages):
            name = str(fname._filename)
        else:
            name = str(getattr(fname, "name", fname))
        if any(p in PurePath(name).name for p in parts):
            saved.append((PurePath(name).name, True))
            return real(self, fname, *args, format=format, **kwargs)
        fmt = format or PurePath(name).suffix.lstrip(".") or "png"
        data = f"figure not rendered ({fmt}), tests/conftest.py\n".encode()
        if isinstance(fname, PdfPages):
            Path(name).write_bytes(data)                # PdfPages writes no page then
        elif hasattr(fname, "write"):
            fname.write(data)
        else:
            Path(fname).write_bytes(data)
        saved.append((PurePath(name).name, False))

    return savefig


@pytest.fixture
def figures_rendered_only(monkeypatch):
    """``figures_rendered_only(*parts)``: from then on, ``Figure.savefig`` renders for
    real only the files whose name holds one of ``parts`` (none: no file); every other
    figure is saved as :func:`unrendered_figures` saves it (a short text naming the
    format), a drawing sheet saved into a ``PdfPages`` too.  For a run whose other
    figures are rendered by another test (named where it is used).  Returns the list of
    ``(file name, rendered)`` saved so, one per file."""
    from matplotlib.figure import Figure

    saved = []

    def start(*parts):
        monkeypatch.setattr(Figure, "savefig", _savefig_rendering_only(parts, saved))
        monkeypatch.setattr("crankbase.plot_layout.save_laid_out", save_through_savefig)
        return saved

    return start


@pytest.fixture(scope="session")
def figures_rendered_only_within():
    """:func:`figures_rendered_only` for a module- or session-scoped fixture: ``with
    figures_rendered_only_within(*parts) as saved:`` (``Figure.savefig`` restored on
    leaving)."""
    from matplotlib.figure import Figure

    @contextlib.contextmanager
    def within(*parts):
        saved = []
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(Figure, "savefig", _savefig_rendering_only(parts, saved))
            mp.setattr("crankbase.plot_layout.save_laid_out", save_through_savefig)
            yield saved

    return within


# ----------------------------------------------------------------------------- tests-web
@pytest.fixture(scope="session")
def petrol_at_4000_tables(tmp_path_factory, figures_rendered_only_within):
    """The petrol example at 4000 rpm for the tests that compare only its tables, workbook
    and terminal text (the web pages' runs at 4000 rpm): the spec (the petrol example
    with ``engine.speed_rpm = 4000.0``) and ``crankdyn engine <that spec> -o DIR --lang
    en`` run in this process once per worker, its figures saved unrendered
    (:func:`figures_rendered_only_within`: no figure of that run was ever looked at; the
    page's own are drawn in the app's render processes and checked as PNG there).
    ``(spec dict, Report)``."""
    import tomllib

    import tomli_w

    from crankbase.resources import example_path
    from crankdyn.cli import main

    spec = tomllib.loads(example_path("petrol_vaz2106.toml").read_text(encoding="utf-8"))
    spec["engine"]["speed_rpm"] = 4000.0
    root = tmp_path_factory.mktemp("petrol_at_4000")
    path = root / "petrol_at_4000.toml"
    path.write_text(tomli_w.dumps(spec), encoding="utf-8")
    folder = root / "report"
    o, e = io.StringIO(), io.StringIO()
    with figures_rendered_only_within() as saved, contextlib.redirect_stdout(o), \
            contextlib.redirect_stderr(e):
        rc = main(["engine", str(path), "-o", str(folder), "--lang", "en"])
    assert rc == 0, e.getvalue()
    assert saved and not any(rendered for _name, rendered in saved)
    return spec, Report(folder, rc, o.getvalue(), e.getvalue())


# ------------------------------------------------------------------------ collector
@pytest.fixture(scope="session", autouse=True)
def _fewer_collections():
    """The cyclic garbage collector run less often in the test processes: the first
    generation collected after 10,000 allocations instead of 700, the older ones after
    50 and 100 collections of the younger instead of 10 and 10.  A figure is thousands of
    artists and transforms (matplotlib's transform tree makes a weak reference and a
    callback for every parent) and a workbook hundreds of thousands of cells, each a
    container the collector walks: measured on the figure tests, a fifth less CPU for the
    same figures.  What the collector frees it still frees, later; nothing a test checks
    depends on when.  The thresholds are restored at the end."""
    import gc

    before = gc.get_threshold()
    gc.set_threshold(10000, 50, 100)
    try:
        yield
    finally:
        gc.set_threshold(*before)


# ------------------------------------------------------------------------- tests-wbcache
#: How many workbooks :func:`loaded_workbook` keeps parsed in one worker (the least
#: recently read is dropped first): the tests reading one workbook run close together
#: (a module's parametrized fixture groups them), and an engine report takes ~16 MB.
WORKBOOK_CACHE_SIZE = 24


def _refuse_save(*args, **kwargs):
    raise RuntimeError("a workbook from the loaded_workbook fixture is shared read-only: "
                       "load your own copy with openpyxl.load_workbook to change or save it")


def _workbook_shape(wb):
    """Each sheet's (title, state, max_row, max_column): what a test reading a shared
    workbook may not change."""
    return tuple((ws.title, ws.sheet_state, ws.max_row, ws.max_column)
                 for ws in wb.worksheets)


@pytest.fixture(scope="session")
def loaded_workbook():
    """``loaded_workbook(path, **options)``: ``openpyxl.load_workbook(path, **options)``,
    parsed once per worker (process) and shared by every test of the session that reads
    the same file (parsing is most of the CPU of a test that reads a report: an engine
    report holds ~40,000 cells).  Keyed by the resolved path, the file's size and
    modification time (ns) and the load options, so a file written anew at the same path
    is parsed anew.  Shared means read-only: a test that changes a workbook (a cell, a
    style, a sheet) loads its own copy with ``openpyxl.load_workbook``; a shared one
    refuses ``save``, and a later call fails when a sheet was added, removed, renamed or
    grew (``ws.cell(r, c)`` creates the cell it reads: read a cell that may be past the
    used range with ``ws._cells.get((r, c))``).  ``read_only=True`` workbooks (they keep
    the file open) are not cached: the call is passed on."""
    from collections import OrderedDict

    from openpyxl import load_workbook

    cache = OrderedDict()

    def get(path, **options):
        if options.get("read_only"):
            return load_workbook(path, **options)
        path = Path(path).resolve()
        st = path.stat()
        key = (str(path), st.st_size, st.st_mtime_ns, tuple(sorted(options.items())))
        if key in cache:
            cache.move_to_end(key)
            wb, shape = cache[key]
            if _workbook_shape(wb) != shape:
                raise AssertionError(f"a test changed the shared workbook {path}: "
                                     f"{shape} -> {_workbook_shape(wb)}")
            return wb
        wb = load_workbook(path, **options)
        wb.save = _refuse_save
        cache[key] = wb, _workbook_shape(wb)
        while len(cache) > WORKBOOK_CACHE_SIZE:
            cache.popitem(last=False)
        return wb

    get.cache = cache
    return get


# ---------------------------------------------------------------------------- tests-webcpu
#: Studies the tests' app keeps, with the files drawn for each in every language
#: (``web.app.StudyCache`` and ``DrawnCache``; the app's default is 8): more than the web
#: test modules ask for (about 35), so that a study one module asks again (the browser's
#: runs repeat the TestClient modules' examples) is neither computed nor drawn again.
WEB_KEPT_STUDIES = 64


@pytest.fixture(scope="session")
def web_app_kept(web_app):
    """The session's app (:func:`web_app`) keeping :data:`WEB_KEPT_STUDIES` studies and
    their drawn files, for the web test modules, which all run on one xdist worker (their
    ``pytestmark``: the group ``web``), so one app serves them all: a study computed and
    drawn for one module is linked for another asking for it in the same language (byte
    for byte the files its drawing would write, ``DrawnCache``'s own guarantee, checked in
    tests/test_web.py).  The tests of the caches themselves clear them first."""
    state = web_app.app.state
    state.studies.size = max(state.studies.size, WEB_KEPT_STUDIES)
    state.drawn.size = max(state.drawn.size, WEB_KEPT_STUDIES)
    return web_app

