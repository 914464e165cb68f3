"""The Starlette application of ``crankdyn serve``: pages rendered on the server.

:func:`build_app` makes the app with its limits; :mod:`web.engine_page` does the engine
page's work through the library, :mod:`web.sessions` isolates each browser session in its
own folder, :mod:`web.jobs` runs the computations in a bounded pool of threads and the
drawing of the reports in processes: as soon as a run is computed (``draw="ahead"``, the
default) or when its files are first asked for (``draw="on_request"``: a class server on
a small machine draws only what a student looks at).
Starlette, Jinja2 and python-multipart are the ``web`` extra; nothing here is imported by
``import engine`` (or any other library package), and matplotlib and openpyxl are
imported only by the first computation, not by a page.
"""
from __future__ import annotations

import asyncio
import contextlib
import logging
import os
import shutil
from concurrent.futures import Future
from functools import partial
from pathlib import Path

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import FileResponse, HTMLResponse, RedirectResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles
from starlette.templating import Jinja2Templates

from crankbase.errors import CrankdynError, SpecError, Text
from crankbase.texts import languages, texts

from . import engine_form as form
from .engine_page import EnginePage
from .jobs import Busy, JobPool
from .balance_page import BalancePage
from .dynamics_page import DynamicsPage
from .linkage_page import LinkagePage
from .synth_page import SynthPage
from .pages import PageState, Run, render_job, report_blob, spec_toml
from .sessions import COOKIE, SessionStore

__all__ = ["build_app", "StudyCache", "DrawnCache", "UPLOAD_LIMIT", "LANG_COOKIE",
           "DRAW_MODES"]

HERE = Path(__file__).resolve().parent
#: Largest request body (an uploaded spec and its pressure file) [bytes].
UPLOAD_LIMIT = 2_000_000
#: The cookie of the page language.
LANG_COOKIE = "crankdyn_lang"
log = logging.getLogger("crankdyn.web")
#: When a run's report is drawn and written (:func:`build_app`'s ``draw``): "ahead", as
#: soon as its numbers are computed; "on_request", when its files are first asked for.
DRAW_MODES = ("ahead", "on_request")
#: The pages, in the menu's order.
KINDS = (EnginePage(), LinkagePage(), SynthPage(), DynamicsPage(), BalancePage())


# ----------------------------------------------------------------------------- body limit
class BodyLimit:
    """ASGI middleware: a request whose body is over ``limit`` bytes is answered with a
    page saying so (413) before the body is read (by its Content-Length) or as soon as
    it passes the limit (a body sent in chunks)."""

    def __init__(self, app, limit: int):
        self.app, self.limit = app, int(limit)

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        headers = dict(scope.get("headers") or [])
        length = headers.get(b"content-length")
        lang = _cookie_lang(headers.get(b"cookie", b"").decode("latin-1"))
        if length is not None and length.isdigit() and int(length) > self.limit:
            return await self._refuse(scope, receive, send, lang)
        if scope.get("method") not in ("POST", "PUT", "PATCH"):
            return await self.app(scope, receive, send)
        # read the body first (at most the limit), then hand it on
        messages, seen = [], 0
        while True:
            msg = await receive()
            messages.append(msg)
            if msg["type"] != "http.request":
                break
            seen += len(msg.get("body", b""))
            if seen > self.limit:
                return await self._refuse(scope, receive, send, lang)
            if not msg.get("more_body", False):
                break

        async def replay():
            return messages.pop(0) if messages else await receive()
        await self.app(scope, replay, send)

    async def _refuse(self, scope, receive, send, lang):
        t = texts(lang)
        body = _page_html(t("web.error.title"), t("web.upload.too_large",
                                                  mb=self.limit / 1e6), lang)
        await HTMLResponse(body, status_code=413)(scope, receive, send)


def _cookie_lang(cookie: str) -> str:
    for part in cookie.split(";"):
        k, _, v = part.strip().partition("=")
        if k == LANG_COOKIE and v in languages():
            return v
    return languages()[0]


def _page_html(title, message, lang) -> str:
    import html

    return (f'<!doctype html><html lang="{lang}"><meta charset="utf-8"><title>'
            f'{html.escape(title)}</title><link rel="stylesheet" href="/static/style.css">'
            f'<main><h1>{html.escape(title)}</h1><p class="problem" id="page-error">'
            f'{html.escape(message)}</p><p><a href="/engine">crankdyn</a></p></main></html>')


# ----------------------------------------------------------------------------- the app
def build_app(*, root=None, upload_limit: int = UPLOAD_LIMIT, idle_seconds: float = 3600.0,
              workers: int = 2, queue: int = 32, timeout: float = 120.0,
              max_sessions: int = 500, render_workers: int = 2, studies: int = 8,
              draw: str = "ahead"):
    """The ``crankdyn serve`` app.

    Parameters
    ----------
    root : path, optional
        Folder under which every session gets its own folder (default: a new temporary
        folder, removed at shutdown).
    upload_limit : int
        Largest request body [bytes].
    idle_seconds : float
        A session idle this long is removed with its files.
    workers, queue : int
        Computations at once (threads), and waiting beyond them (more are refused with a
        message).
    render_workers : int
        Processes drawing and writing the reports.
    timeout : float
        Longest wait of a page for its computation [s].
    max_sessions : int
        Live sessions at most (a new one beyond removes the one idle longest).
    studies : int
        Studies kept for every session (:class:`StudyCache`), and the files drawn for
        them in each language (:class:`DrawnCache`): a study asked again, by any session
        (a class computing the same example), is not computed again, nor drawn again in a
        language it was drawn in; 0: none.  A kept study holds its report twice (as
        computed and pickled for the drawing processes): up to a few MB each (the
        torsion example with bearings 3.4 MB pickled).
    draw : {"ahead", "on_request"}
        When a run's report (its figures, workbook, CSVs and zip) is drawn and written
        in the drawing processes.  "ahead" (default): as soon as its numbers are
        computed, while the student reads the page, so its files are ready when asked
        for.  "on_request": when the page first needs them, i.e. when a file of the run
        is asked for (a figure shown on the page, a download), or when its page lists
        files known only once written (the dynamics and balance pages, the engine
        page's drawings); a run whose page is left before that (a form corrected and run
        again, a student who only reads the tables) is never drawn.  A class server on a
        small machine may prefer it: drawing is most of an engine run's CPU (its 13
        figures, workbook and zip about 2 s, its numbers a few hundredths), and the first
        figure shown then waits for the drawing instead of the drawing starting behind
        the page.  The mode is
        ``app.state.draw`` (the Starlette app's), read at each run.
    """
    if draw not in DRAW_MODES:
        raise ValueError(f"draw must be one of {DRAW_MODES}, not {draw!r}")
    store = SessionStore(root, idle_seconds, max_sessions)
    pool = JobPool(workers, queue, timeout)
    # the reports are drawn and written in processes: matplotlib's text layout is not
    # thread-safe (two reports drawn by two threads broke each other's mathtext), and
    # processes use every core; a page waits for its files longer than for its numbers
    render = JobPool(render_workers, 2 * queue, 4 * timeout, processes=True)
    # a class's batch of reports draws in processes of its own (engine.variants); one
    # batch at a time, a few waiting
    batches = JobPool(1, 4, 3600.0)
    cache = StudyCache(studies)
    drawn = DrawnCache(store.root / "drawn", studies)
    templates = Jinja2Templates(directory=str(HERE / "templates"))
    templates.env.globals["languages"] = languages

    @contextlib.asynccontextmanager
    async def lifespan(app):
        async def sweeper():
            while True:
                await asyncio.sleep(60)
                store.sweep()
        task = asyncio.create_task(sweeper())
        try:
            yield
        finally:
            task.cancel()
            pool.close()
            render.close()
            batches.close()
            store.close()

    # ---- helpers
    def lang_of(request: Request) -> str:
        q = request.query_params.get("lang")
        if q in languages():
            return q
        c = request.cookies.get(LANG_COOKIE)
        return c if c in languages() else languages()[0]

    def session_of(request: Request):
        s = store.get(request.cookies.get(COOKIE))
        return s if s is not None else store.new()

    def finish(response: Response, session, lang) -> Response:
        response.set_cookie(COOKIE, session.id, httponly=True, samesite="lax")
        response.set_cookie(LANG_COOKIE, lang, samesite="lax")
        return response

    def error_page(request, session, lang, message, status):
        t = texts(lang)
        return finish(HTMLResponse(_page_html(t("web.error.title"), message, lang),
                                   status_code=status), session, lang)

    def read_form(request, max_files=4):
        """The posted form (``async with``: its uploaded files are closed after); at most
        ``max_files`` files (the class check: a file per student)."""
        return request.form(max_files=max_files, max_fields=400,
                            max_part_size=upload_limit)

    async def home(request):
        return RedirectResponse("/engine", status_code=307)

    routes = [Route("/", home)]
    for kind in KINDS:
        routes += _page_routes(kind, templates=templates, store=store, pool=pool,
                               render=render, cache=cache, drawn=drawn,
                               upload_limit=upload_limit,
                               lang_of=lang_of, session_of=session_of, finish=finish,
                               error_page=error_page, read_form=read_form)
    routes += _teacher_routes(templates=templates, store=store, pool=pool, batches=batches,
                              upload_limit=upload_limit, lang_of=lang_of,
                              session_of=session_of, finish=finish, error_page=error_page,
                              read_form=read_form)
    routes.append(Mount("/static", StaticFiles(directory=str(HERE / "static")),
                        name="static"))
    app = Starlette(routes=routes, lifespan=lifespan)
    app.state.store, app.state.pool, app.state.render = store, pool, render
    app.state.batches, app.state.studies, app.state.drawn = batches, cache, drawn
    app.state.draw = draw
    return BodyLimit(app, upload_limit) if upload_limit else app


def _page_routes(kind, *, templates, store, pool, render, cache, drawn, upload_limit, lang_of,
                 session_of, finish, error_page, read_form):
    """The routes of one page (:class:`web.pages.Kind`): ``/<name>`` (GET), its
    ``/example``, ``/upload`` and ``/run`` (POST) and ``/run/<n>/<file>``."""
    base = f"/{kind.name}"

    def state_of(session) -> PageState:
        return session.pages.setdefault(kind.name, PageState())

    def back(session, lang, anchor=""):
        return finish(RedirectResponse(f"{base}{anchor}", status_code=303), session, lang)

    def drop(st):
        """Forget the session's last run (the page shows results of its form only); its
        files go once its writing is over."""
        old, st.run = st.run, None
        if old is not None:
            if old.draw is not None:        # never drawn (draw="on_request"): never will be
                old.draw = None
                old.write_future.cancel()
            old.write_future.add_done_callback(
                lambda _f, d=old.folder: shutil.rmtree(d, ignore_errors=True))

    async def get(request):
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        t = texts(lang)
        schema = kind.schema_for(values=st.values)
        secs = form.sections(lang, schema, st.values)
        fields = {f.path for s in secs for f in s.fields} | set(kind.extra_fields)
        by_field, general = {}, []
        for p in st.problems:
            f = form.problem_field(p.key, fields)
            (by_field.setdefault(f, []) if f else general).append(p.render(lang))
        run = st.run
        ctx = dict(t=t, lang=lang, page=kind, sections=secs, values=st.values,
                   source=st.source, options=st.options, errors=by_field, general=general,
                   notice=st.notice.render(lang) if st.notice else "",
                   examples=[(n, t(kind.example_prefix + n)) for n in kind.examples],
                   pressure=st.pressure, run=None, file_key=form.FILE_KEY,
                   upload_mb=upload_limit / 1e6, kinds=KINDS,
                   sources=[(s, t(f"web.form.source.{s}")) for s in form.PRESSURE_SOURCES])
        if run is not None:
            files = None
            if kind.waits(run):                 # listed once written
                with contextlib.suppress(Exception):
                    _start_drawing(run)
                    files = await render.wait(run.write_future)
            res = kind.results(run, lang, files)
            ctx["run"] = dict(dict(zip=f"{res['name']}_report.zip", toml=f"{res['name']}.toml",
                                   drawings=[n for n in files or ()
                                             if n.endswith((".pdf", ".dxf"))]),
                              **res, number=run.number,
                              pressure=run.pressure[0] if run.pressure else None)
        return finish(templates.TemplateResponse(request, "page.html", ctx), session, lang)

    async def example(request):
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        async with read_form(request) as f:
            name = f.get("example")
        if name not in kind.examples:
            return error_page(request, session, lang, texts(lang)("web.example.unknown"), 400)
        data, pressure = kind.example_spec(name)
        values, source = form.values_from_spec(data, kind.schema_for(data=data))
        with st.lock:
            st.values, st.source, st.pressure, st.problems = values, source, pressure, []
            st.notice = Text("web.example.loaded", {"name": name})
            st.options = kind.spec_options(data, st.options)
        return back(session, lang, "#form")

    async def upload(request):
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        raw = pname = praw = None
        async with read_form(request) as f:
            spec, pfile = f.get("spec"), f.get("pressure")
            if hasattr(spec, "read"):
                raw = await spec.read()
            if hasattr(pfile, "read") and pfile.filename:
                pname, praw = pfile.filename, await pfile.read()
        if raw is None:
            return error_page(request, session, lang, texts(lang)("web.upload.no_spec"), 400)
        import tomllib

        try:
            data = tomllib.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
            with st.lock:
                st.problems = [_problem("", Text("web.upload.bad_toml", {"reason": str(exc)}))]
                st.notice = None
            return back(session, lang, "#form")
        pressure = None
        spec_file = None
        if kind.has_pressure and isinstance(data.get("pressure"), dict):
            spec_file = data["pressure"].get("file")
        if pname is not None and kind.has_pressure:
            from .engine_page import pressure_name

            pressure = (pressure_name(pname, spec_file), praw)
        values, source = form.values_from_spec(data, kind.schema_for(data=data))
        with st.lock:
            st.values, st.source, st.pressure = values, source, pressure
            st.notice, st.problems = Text("web.upload.loaded"), []
            st.options = kind.spec_options(data, st.options)
        if spec_file is not None and pressure is None:
            with st.lock:
                st.problems = [_problem(form.FILE_KEY, Text("web.upload.pressure_missing",
                                                            {"file": str(spec_file)}))]
            return back(session, lang, "#form")
        # the file as uploaded through the library: every problem of it (unknown keys too)
        if spec_file is None:
            pressure = None
        else:
            data["pressure"]["file"] = pressure[0]
        return await run_spec(request, session, lang, st, data, pressure)

    async def run_form(request):
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        upload = None
        async with read_form(request) as f:
            values = {k: v for k, v in f.items() if isinstance(v, str)}
            pfile = f.get("pressure_upload")
            if kind.has_pressure and hasattr(pfile, "read") and pfile.filename:
                from .engine_page import pressure_name

                upload = (pressure_name(pfile.filename), await pfile.read())
        source = values.pop("pressure_source", "cycle")
        source = source if source in form.PRESSURE_SOURCES else "cycle"
        options = kind.options(values)
        with st.lock:
            st.values, st.source, st.options = values, source, options
            if upload is not None:
                st.pressure = upload
        data = kind.form_spec(form.spec_from_values(
            values, source, st.pressure[0] if st.pressure else None,
            kind.schema_for(values=values)), options)
        return await run_spec(request, session, lang, st, data,
                              st.pressure if kind.has_pressure and source == "file" else None)

    async def run_spec(request, session, lang, st, data, pressure):
        # computed from the spec TOML the page offers for download, read back: the CLI
        # on that file repeats the run exactly (the order of the keys too)
        import tomllib

        with contextlib.suppress(TypeError, ValueError):
            data = tomllib.loads(spec_toml(data))
        with st.lock:
            st.runs += 1
            number = st.runs
            options = dict(st.options)
            last = st.run
        folder = session.folder / f"{kind.name}-{number}"     # each page its own folders
        try:
            key = StudyCache.key(kind, data, pressure, options)
            if _same_study(last, data, pressure, options):
                # the session's last study asked again (in another language, say): its
                # report is drawn anew, the numbers are not computed again
                report, blob = last.report, report_blob(last.report)
            elif (hit := cache.get(key)) is not None:
                report, blob = hit          # another session's study of the same spec
            else:
                report, blob = await pool.run(_computed, kind, data, folder / "input",
                                              pressure, options)
                cache.put(key, (report, blob))
        except SpecError as exc:
            shutil.rmtree(folder, ignore_errors=True)
            with st.lock:
                st.problems, st.notice = list(exc.problems), None
                drop(st)
            return back(session, lang, "#form")
        except CrankdynError as exc:
            shutil.rmtree(folder, ignore_errors=True)
            with st.lock:
                st.problems = [_problem("", Text("web.run.failed",
                                                 {"reason": "; ".join(exc.lines(lang))}))]
                st.notice = None
                drop(st)
            return back(session, lang, "#form")
        except Busy:
            shutil.rmtree(folder, ignore_errors=True)
            return error_page(request, session, lang, texts(lang)("web.run.busy"), 503)
        except asyncio.TimeoutError:
            return error_page(request, session, lang, texts(lang)("web.run.timeout",
                                                                  s=pool.timeout), 504)
        except Exception as exc:          # a bug in a job: this session's error only
            log.exception("%s job failed", kind.name)
            shutil.rmtree(folder, ignore_errors=True)
            return error_page(request, session, lang, texts(lang)(
                "web.run.crashed", what=type(exc).__name__), 500)
        run = Run(number=number, folder=folder, report=report, spec=data, lang=lang,
                  pressure=pressure, options=options)
        dkey = None if key is None else (*key, lang)
        files = drawn.files(dkey, folder / "report")
        if files is not None:             # drawn for another run in this language
            run.write_future = Future()
            run.write_future.set_result(files)
        else:
            draw = partial(_drawn_job, render, drawn, dkey, render_job, kind, number, folder,
                           data, lang, pressure, options, blob)
            if request.app.state.draw == "on_request":
                run.write_future, run.draw = Future(), draw
            else:
                try:
                    run.write_future = draw()
                except Busy:
                    return error_page(request, session, lang, texts(lang)("web.run.busy"),
                                      503)
        with st.lock:
            drop(st)
            st.run, st.problems, st.notice = run, [], None
        return back(session, lang, "#results")

    async def run_file(request):
        """A file of the session's current run, by the name the server gave it."""
        lang = lang_of(request)
        s = store.get(request.cookies.get(COOKIE))
        st = s.pages.get(kind.name) if s is not None else None
        run = st.run if st is not None else None
        if run is None or str(run.number) != request.path_params["number"]:
            return Response(texts(lang)("web.file.gone"), status_code=404)
        try:
            _start_drawing(run)
            files = await render.wait(run.write_future)
        except Busy:
            return Response(texts(lang)("web.run.busy"), status_code=503)
        except asyncio.TimeoutError:
            return Response(texts(lang)("web.run.timeout", s=render.timeout), status_code=504)
        except Exception as exc:
            log.exception("%s report failed", kind.name)
            return Response(texts(lang)("web.run.crashed", what=type(exc).__name__),
                            status_code=500)
        name = request.path_params["name"]
        path = files.get(name)
        if path is None:
            return Response(texts(lang)("web.file.gone"), status_code=404)
        inline = name.endswith(".png")
        return FileResponse(path, filename=None if inline else name,
                            content_disposition_type="inline" if inline else "attachment")

    return [Route(base, get), Route(f"{base}/example", example, methods=["POST"]),
            Route(f"{base}/upload", upload, methods=["POST"]),
            Route(f"{base}/run", run_form, methods=["POST"]),
            Route(base + "/run/{number:str}/{name:str}", run_file)]


class _Teacher:
    """The teacher's page in the menu."""

    name = "teacher"
    nav_key = "web.nav.teacher"


#: The files of a batch a download may ask for.
BATCH_FILES = ("class_reports.zip", "variants_summary.csv", "variants_summary.xlsx",
               "variants_errors.csv")


def _teacher_routes(*, templates, store, pool, batches, upload_limit, lang_of, session_of,
                    finish, error_page, read_form):
    from . import teacher_page as tp

    def state_of(session):
        return session.pages.setdefault("teacher", tp.TeacherState())

    async def get(request):
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        t = texts(lang)
        b = st.batch
        ctx = dict(t=t, lang=lang, page=_Teacher, kinds=KINDS, problems=st.problems,
                   upload_mb=upload_limit / 1e6, batch=None, max_variants=tp.MAX_VARIANTS,
                   check=st.check, check_errors=st.check_problems,
                   check_values=st.check_values, klass=st.class_run,
                   class_errors=st.class_problems, class_values=st.class_values,
                   class_files=tp.CLASS_FILES)
        if b is not None:
            info = dict(number=b.number, done=b.done, total=b.total, running=True)
            if b.future.done():
                info["running"] = False
                try:
                    run = b.future.result()
                except Exception as exc:
                    info["error"] = ("; ".join(exc.lines(lang)) if isinstance(exc, CrankdynError)
                                     else t("web.run.crashed", what=type(exc).__name__))
                else:
                    bad = run.failures
                    rows = "" if not bad else t.n(
                        "variants.summary.failed_rows", len(bad),
                        rows=", ".join(str(o.variant.row) for o in bad))
                    info["line"] = t.n("variants.summary.result", len(run.outcomes),
                                       written=len(run.outcomes) - len(bad),
                                       folder=b.zip_name, failed=len(bad), rows=rows)
                    info["failures"] = [ln for o in bad for ln in o.problems]
                    info["head"], info["rows"] = [], []
                    if run.records:           # the summary CSV's own text
                        import csv

                        with open(run.summary_csv, newline="", encoding="utf-8") as fh:
                            rows = list(csv.reader(fh))
                        info["head"], info["rows"] = rows[0], rows[1:]
                    info["files"] = [n for n in BATCH_FILES
                                     if (b.folder / n).is_file()
                                     or (b.folder / "reports" / n).is_file()]
            ctx["batch"] = info
        return finish(templates.TemplateResponse(request, "teacher.html", ctx), session, lang)

    async def start(request):
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        up = {}
        async with read_form(request) as f:
            for key in ("base", "pressure", "variants"):
                item = f.get(key)
                if hasattr(item, "read") and item.filename:
                    up[key] = (item.filename, await item.read())
        t = texts(lang)
        if "base" not in up or "variants" not in up:
            with st.lock:
                st.problems = [t("web.teacher.need_both")]
            return finish(RedirectResponse("/teacher", status_code=303), session, lang)
        with st.lock:
            st.runs += 1
            number = st.runs
        folder = session.folder / f"teacher-{number}"
        xlsx = up["variants"][0].lower().endswith(".xlsx")
        try:
            base_path, vpath, n = await pool.run(tp.prepare, folder, up["base"][1],
                                                 up.get("pressure"), up["variants"][1], xlsx)
        except (CrankdynError, ValueError, UnicodeDecodeError) as exc:
            shutil.rmtree(folder, ignore_errors=True)
            lines = (exc.lines(lang) if isinstance(exc, CrankdynError)
                     else [t("web.upload.bad_toml", reason=str(exc))])
            inside = str(folder / "input") + "/"
            with st.lock:
                st.problems = [ln.replace(inside, "") for ln in lines]
            return finish(RedirectResponse("/teacher", status_code=303), session, lang)
        except Busy:
            shutil.rmtree(folder, ignore_errors=True)
            return error_page(request, session, lang, t("web.run.busy"), 503)
        batch = tp.Batch(number=number, folder=folder, total=n, lang=lang)
        try:
            batch.future = batches.submit(tp.run_batch, batch, base_path, vpath)
        except Busy:
            shutil.rmtree(folder, ignore_errors=True)
            return error_page(request, session, lang, t("web.run.busy"), 503)
        with st.lock:
            tp.remove(st.batch)
            st.batch, st.problems = batch, []
        return finish(RedirectResponse("/teacher", status_code=303), session, lang)

    async def batch_file(request):
        lang = lang_of(request)
        s = store.get(request.cookies.get(COOKIE))
        st = s.pages.get("teacher") if s is not None else None
        b = st.batch if st is not None else None
        name = request.path_params["name"]
        if (b is None or str(b.number) != request.path_params["number"]
                or name not in BATCH_FILES or not b.future.done()):
            return Response(texts(lang)("web.file.gone"), status_code=404)
        path = b.folder / name if name == b.zip_name else b.folder / "reports" / name
        if not path.is_file():
            return Response(texts(lang)("web.file.gone"), status_code=404)
        return FileResponse(path, filename=name)

    async def form_check(request, *, singles, multiple, typed, required, folder_name,
                         attrs, job, anchor, field_of_failure, max_files=4):
        """A check form posted (one student's, a class's): the uploads read (``singles``
        one file each, ``multiple`` a list), ``typed`` values kept for the form, the
        ``required`` fields named when empty, ``job(folder, number, *uploads, *values,
        lang)`` run in the pool; its :class:`~web.teacher_page.CheckProblem` shown at its
        fields, its result kept in the state's ``attrs`` = (result, problems, values)."""
        lang = lang_of(request)
        session = session_of(request)
        st = state_of(session)
        up, values = {}, {}
        async with read_form(request, max_files) as f:
            for key in singles:
                item = f.get(key)
                if hasattr(item, "read") and item.filename:
                    up[key] = (item.filename, await item.read())
            for key in multiple:
                items = [(i.filename, await i.read()) for i in f.getlist(key)
                         if hasattr(i, "read") and i.filename]
                if items:
                    up[key] = items
            for key in typed:
                v = f.get(key)
                values[key] = v if isinstance(v, str) else ""
        t = texts(lang)
        result_attr, problems_attr, values_attr = attrs
        back = finish(RedirectResponse(f"/teacher#{anchor}", status_code=303), session, lang)
        missing = {k: [t("web.check.choose")] for k in required if k not in up}
        with st.lock:
            setattr(st, values_attr, values)
        if missing:
            with st.lock:
                setattr(st, problems_attr, missing)
            return back
        with st.lock:
            st.runs += 1
            number = st.runs
        folder = session.folder / f"{folder_name}-{number}"
        args = [up.get(k) for k in (*singles, *multiple)] + [values[k] for k in typed]
        try:
            run = await pool.run(job, folder, number, *args, lang)
        except tp.CheckProblem as exc:
            shutil.rmtree(folder, ignore_errors=True)
            with st.lock:
                setattr(st, problems_attr, exc.lines(lang))
            return back
        except CrankdynError as exc:
            shutil.rmtree(folder, ignore_errors=True)
            with st.lock:
                setattr(st, problems_attr, {field_of_failure: [t(
                    "web.run.failed", reason="; ".join(exc.lines(lang)))]})
            return back
        except Busy:
            shutil.rmtree(folder, ignore_errors=True)
            return error_page(request, session, lang, t("web.run.busy"), 503)
        except asyncio.TimeoutError:
            return error_page(request, session, lang, t("web.run.timeout", s=pool.timeout),
                              504)
        except Exception as exc:          # a bug in a job: this session's error only
            log.exception("teacher %s failed", folder_name)
            shutil.rmtree(folder, ignore_errors=True)
            return error_page(request, session, lang, t("web.run.crashed",
                                                        what=type(exc).__name__), 500)
        with st.lock:
            old = getattr(st, result_attr)
            setattr(st, result_attr, run)
            setattr(st, problems_attr, {})
        if old is not None:
            shutil.rmtree(old.folder, ignore_errors=True)
        return back

    async def check(request):
        """One student's work checked (``crankdyn check SPEC STUDENT``)."""
        return await form_check(
            request, singles=("spec", "pressure", "student"), multiple=(),
            typed=("rtol", "atol", "map"), required=("spec", "student"),
            folder_name="check", attrs=("check", "check_problems", "check_values"),
            job=tp.check_work, anchor="check", field_of_failure="student")

    async def check_class(request):
        """A whole class checked (``crankdyn check BASE --variants VARIANTS DIR``)."""
        return await form_check(
            request, singles=("base", "pressure", "variants"), multiple=("students",),
            typed=("rtol", "atol"), required=("base", "variants", "students"),
            folder_name="class", attrs=("class_run", "class_problems", "class_values"),
            job=tp.check_class_work, anchor="class", field_of_failure="students",
            max_files=3 + tp.MAX_VARIANTS)

    def last_run_file(attr):
        """The handler of a file of the session's last run of a teacher's form
        (``st.<attr>``: the one-student check or the class check), by the name the page
        offered."""
        async def handler(request):
            lang = lang_of(request)
            s = store.get(request.cookies.get(COOKIE))
            st = s.pages.get("teacher") if s is not None else None
            run = getattr(st, attr) if st is not None else None
            path = None if run is None or str(run.number) != request.path_params["number"] \
                else run.files.get(request.path_params["name"])
            if path is None or not path.is_file():
                return Response(texts(lang)("web.file.gone"), status_code=404)
            return FileResponse(path, filename=request.path_params["name"])
        return handler

    check_file, class_file = last_run_file("check"), last_run_file("class_run")

    return [Route("/teacher", get), Route("/teacher/variants", start, methods=["POST"]),
            Route("/teacher/batch/{number:str}/{name:str}", batch_file),
            Route("/teacher/check", check, methods=["POST"]),
            Route("/teacher/check/{number:str}/{name:str}", check_file),
            Route("/teacher/class", check_class, methods=["POST"]),
            Route("/teacher/class/{number:str}/{name:str}", class_file)]


def _drawn_job(render, drawn, dkey, job, *args):
    """``job(*args)`` (:func:`web.pages.render_job`) submitted to the drawing pool
    ``render``: its future, whose files ``drawn`` keeps for ``dkey`` once written
    (:class:`DrawnCache`); :class:`~web.jobs.Busy` when the pool is full."""
    fut = render.submit(job, *args)
    if dkey is not None:
        fut.add_done_callback(partial(drawn.keep_done, dkey))
    return fut


def _start_drawing(run) -> None:
    """Start the drawing of ``run`` if it waits to be asked for (``build_app(draw=
    "on_request")``: ``run.draw`` submits it): its outcome becomes ``run.write_future``'s.
    Called from the event loop's thread only, so a run is drawn once; :class:`Busy`
    (the run stays undrawn, a later request tries again) when the drawing pool is full."""
    draw = run.draw
    if draw is None:
        return
    job = draw()                        # Busy: run.draw kept
    run.draw = None
    job.add_done_callback(partial(_pass_on, run.write_future))


def _pass_on(target, fut) -> None:
    """``fut``'s outcome (result, exception or cancellation) set on ``target``."""
    from concurrent.futures import InvalidStateError

    with contextlib.suppress(InvalidStateError):    # the run dropped (cancelled) meanwhile
        if fut.cancelled():
            target.cancel()
        elif fut.exception() is not None:
            target.set_exception(fut.exception())
        else:
            target.set_result(fut.result())


def _computed(kind, data, input_dir, pressure, options):
    """A page's computation (:meth:`web.pages.Kind.compute`) and its report pickled for
    the drawing process (:func:`web.pages.report_blob`): ``(report, blob)``."""
    report = kind.compute(data, input_dir, pressure, options)
    return report, report_blob(report)


class StudyCache:
    """The last ``size`` studies computed by the app's pages, for every session: the
    ``(report, blob)`` of :func:`_computed` by :meth:`key`.  A report is never changed
    once computed (a session's same study asked again is drawn from it too,
    :func:`_same_study`), so sessions can share it; each run still draws its own files
    into its own folder.  A class computing the same example, each student in a session
    of their own, computes it once.  Only the event loop's thread uses it."""

    def __init__(self, size: int = 8):
        from collections import OrderedDict

        self.size = max(0, int(size))
        self._items = OrderedDict()

    @staticmethod
    def key(kind, data, pressure, options):
        """The key of a page's study: its kind, spec and options; None (not kept) for a
        run reading a pressure file (its report names the file of its own folder) or a
        spec that does not write as TOML."""
        if pressure is not None:
            return None
        try:
            spec = spec_toml(data)
        except (TypeError, ValueError):
            return None
        return kind.name, spec, repr(sorted(options.items()))

    def get(self, key):
        if key is None or key not in self._items:
            return None
        self._items.move_to_end(key)
        return self._items[key]

    def put(self, key, value) -> None:
        if key is None or not self.size:
            return
        self._items[key] = value
        self._items.move_to_end(key)
        while len(self._items) > self.size:
            self._items.popitem(last=False)

    def clear(self) -> None:
        self._items.clear()

    def __len__(self) -> int:
        return len(self._items)


class DrawnCache:
    """The files drawn and written for the last ``size`` runs of a kept study
    (:class:`StudyCache`) in a language, by ``(study key, lang)``: hard links (copies
    where the file system has none) in ``folder``, made once a run's files are all
    written, so that no session's removal takes them.  Another run of that study in that
    language gets links of them in its own folder at once, byte for byte the files its
    drawing would write (a run's files are a function of its study, options and
    language), instead of drawing them again.  Used from the event loop and from the
    drawing pool's thread: a lock."""

    def __init__(self, folder, size: int = 8):
        import threading
        from collections import OrderedDict

        self.folder = Path(folder)
        self.size = max(0, int(size))
        self._items = OrderedDict()
        self._lock = threading.Lock()
        self._made = 0

    def keep(self, key, files: dict) -> None:
        """Keep ``files`` (``{file name: path}``, a run's written files) for ``key``."""
        if key is None or not self.size:
            return
        with self._lock:
            if key in self._items:
                self._items.move_to_end(key)
                return
            self._made += 1
            folder = self.folder / str(self._made)
            try:
                folder.mkdir(parents=True)
                kept = {name: _linked(path, folder / name) for name, path in files.items()}
            except OSError:                 # the run's folder went meanwhile: not kept
                shutil.rmtree(folder, ignore_errors=True)
                return
            self._items[key] = (folder, kept)
            while len(self._items) > self.size:
                _key, (old, _files) = self._items.popitem(last=False)
                shutil.rmtree(old, ignore_errors=True)

    def keep_done(self, key, future) -> None:
        """:meth:`keep` the files of a finished drawing job's ``future`` (its done
        callback); a failed or cancelled job keeps nothing."""
        if not future.cancelled() and future.exception() is None:
            self.keep(key, future.result())

    def files(self, key, folder) -> dict | None:
        """The files kept for ``key``, linked into ``folder`` (a new run's own):
        ``{file name: path}``; None when none are kept."""
        if key is None:
            return None
        with self._lock:
            item = self._items.get(key)
            if item is None:
                return None
            self._items.move_to_end(key)
            folder = Path(folder)
            try:
                folder.mkdir(parents=True, exist_ok=True)
                return {name: _linked(path, folder / name) for name, path in item[1].items()}
            except OSError:
                shutil.rmtree(folder, ignore_errors=True)
                return None

    def clear(self) -> None:
        with self._lock:
            for folder, _files in self._items.values():
                shutil.rmtree(folder, ignore_errors=True)
            self._items.clear()

    def __len__(self) -> int:
        return len(self._items)


def _linked(src, dst) -> Path:
    """``dst`` made a hard link of ``src`` (a copy where links cannot be made)."""
    try:
        os.link(src, dst)
    except OSError:
        shutil.copyfile(src, dst)
    return Path(dst)


def _same_study(last, data, pressure, options) -> bool:
    """Whether the session's ``last`` run (a :class:`web.pages.Run` or None) is the study
    of the spec dict ``data`` with these options: its report is then the one this run
    would compute (a study is a function of its spec and options).  A run reading a
    pressure file is computed again (its report names the file of its own folder)."""
    return (last is not None and pressure is None and last.pressure is None
            and last.options == options and last.spec == data)


def _problem(key, text):
    from crankbase.errors import Problem

    return Problem(key, text)
