"""``crankdyn serve`` through Starlette's TestClient: every page, the form's problems next
to their fields, downloads equal to the CLI's files, sessions isolated, limits, a crash.

The reference of every number is the CLI (``crankdyn engine``) on the same spec: the
page computes through the same library calls, so its CSVs must be byte-identical and its
workbook the same file but for the time of its save (:func:`workbook_parts`).
"""
from __future__ import annotations

import csv
import html as htmllib
import io
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

pytest.importorskip("starlette")  # the test extra installs it; a bare core install skips
from starlette.testclient import TestClient  # noqa: E402

from crankbase.resources import example_path  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent

#: Every web test module runs on one xdist worker (``--dist loadgroup``), with one app
#: (tests/conftest.py ``web_app_kept``): the studies and drawings one module asks for are
#: not computed and drawn again for another, and the app's drawing processes start once.
#: (A module-level mark: the group is known when xdist names the tests.)
pytestmark = pytest.mark.xdist_group("web")


@pytest.fixture(scope="module")
def app(web_app_kept):
    """The session's app (tests/conftest.py ``web_app_kept``)."""
    return web_app_kept


@pytest.fixture(autouse=True)
def reports_written(app):
    """After each test, every report it asked for is written (its files gone from the
    machine before the next test asks for more)."""
    yield
    app.app.state.render.drain(300)


def client(app, lang="en"):
    c = TestClient(app)
    c.get(f"/engine?lang={lang}")
    return c


def field_value(html, path):
    m = re.search(rf'id="{re.escape(path)}" value="([^"]*)"', html)
    return m.group(1) if m else None


def form_values(html):
    """Every field of a page's form as the page shows it (what a browser posts)."""
    vals = dict(re.findall(r'<input type="text" name="([^"]+)" id="[^"]+" value="([^"]*)"', html))
    for name, body in re.findall(r'<textarea name="([^"]+)"[^>]*>([^<]*)</textarea>', html):
        vals[name] = body
    for name, body in re.findall(r'<select name="([^"]+)"[^>]*>(.*?)</select>', html, re.S):
        sel = re.search(r'<option value="([^"]*)" selected>', body)
        vals[name] = sel.group(1) if sel else ""
    src = re.search(r'name="pressure_source" value="(\w+)" id="source-\w+" checked', html)
    if src:
        vals["pressure_source"] = src.group(1)
    return {k: htmllib.unescape(v) for k, v in vals.items()}


def run_cli(spec, out, lang="en"):
    from crankdyn.cli import main

    assert main(["engine", str(spec), "-o", str(out), "--lang", lang]) == 0
    return out


def shared(rep):
    """The folder of a session-shared CLI report (conftest ``cli_report``: read-only)."""
    assert rep.rc == 0, rep.err
    return rep.folder


def page_table(html, table_id="table2"):
    body = re.search(rf'<table id="{table_id}".*?</table>', html, re.S).group(0)
    head = re.findall(r"<th>([^<]*)</th>", body)
    rows = [re.findall(r"<td>([^<]*)</td>", r) for r in re.findall(r"<tr>(.*?)</tr>", body, re.S)]
    return head, [r for r in rows if r]


#: The save time in a workbook's docProps/core.xml: the one thing two saves of the same
#: workbook differ in.
SAVE_TIME = re.compile(rb"(<dcterms:(?:created|modified)[^>]*>)[^<]*(</dcterms:)")


def workbook_parts(data):
    """Every part of a workbook (an .xlsx is a zip; ``data``: its bytes or path) by name,
    byte for byte, but the time of the save in docProps/core.xml.  Two workbooks equal so
    are the same file but for when it was saved: every sheet, cell, value, style and chart
    (a comparison stronger than value for value, and without parsing the sheets: the
    library writes a report's workbook the same way from the same numbers,
    tests/test_workbook_writing.py)."""
    z = zipfile.ZipFile(io.BytesIO(data) if isinstance(data, bytes) else data)
    parts = {i.filename: z.read(i.filename) for i in z.infolist()}
    parts["docProps/core.xml"] = SAVE_TIME.sub(rb"\1\2", parts["docProps/core.xml"])
    return parts


def run_petrol(c, speed="4000.0"):
    c.post("/engine/example", data={"example": "petrol"})
    vals = form_values(c.get("/engine").text)
    assert vals["engine.speed_rpm"] == "5400.0"
    vals["engine.speed_rpm"] = speed
    r = c.post("/engine/run", data=vals)
    assert r.status_code == 200 and 'id="results"' in r.text, r.text[:2000]
    return r.text


def links(html):
    return re.findall(r'href="(/engine/run/\d+/[^"]+)"', html)


@pytest.fixture(scope="module")
def petrol_page(app):
    """One session's run of the petrol example at 4000 rpm through the page, shared by
    the tests that only read it (its downloads, its links): ``(client, html)``."""
    c = client(app)
    return c, run_petrol(c, "4000.0")


@pytest.fixture(scope="module")
def diesel_upload(app):
    """One session's upload of the diesel example as a student would send it (the TOML
    naming its CSV, under names of the user's), shared by the tests that only read it:
    ``(client, response)``."""
    c = client(app)
    r = c.post("/engine/upload", files={
        "spec": ("my spec.toml", example_path("diesel_d240.toml").read_bytes(),
                 "application/toml"),
        "pressure": ("../../etc/diesel_d240_indicator.csv",
                     example_path("diesel_d240_indicator.csv").read_bytes(), "text/csv")})
    return c, r


# ----------------------------------------------------------------------------- pages
@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_engine_page_shows_every_schema_key_with_its_words(app, lang):
    from engine.schema import SCHEMA
    from web.engine_form import FILE_KEY, sections

    c = client(app, lang)
    html = c.get("/engine").text
    secs = sections(lang)
    paths = {f.path for s in secs for f in s.fields}
    # every key of the engine schema is a field (the file key is the upload)
    from crankbase.schema import ArrayOfTables, Table

    def walk(tables):
        for tab in tables:
            if isinstance(tab, ArrayOfTables):
                yield tab.path                      # one field: a line per table
                continue
            yield from (f"{tab.path}.{k.name}" for k in tab.keys())
            yield from walk([e for e in tab.entries if isinstance(e, Table)])
    schema_paths = set(walk(SCHEMA.tables))
    assert "pressure.cycle.n1" in schema_paths and len(schema_paths) > 60
    assert schema_paths - {FILE_KEY} == paths
    bore = SCHEMA.describe("engine.bore_mm", lang)
    assert 'id="engine.bore_mm"' in html and bore["label"] in html and bore["help"] in html
    assert "(0" not in bore["range"] or bore["range"] in html
    assert bore["unit"] and bore["unit"] in html
    for p in ("engine.speed_rpm", "pressure.cycle.n1", "table.force_scale_N_per_mm",
              "flywheel.delta", "balance.counterweight", "bearings.wear_half_angle_deg",
              "rod.model", "masses.rod_kg_m2"):
        assert p in paths and f'id="{p}"' in html, p
    assert FILE_KEY not in paths
    n1 = SCHEMA.describe("pressure.cycle.n1", lang)
    assert n1["range"] == "(1, 2)" and "(1, 2)" in html
    if lang == "ru":
        assert "Рассчитать" in html and "Compute" not in html and "Diagrams" not in html
    else:
        assert not re.search("[А-Яа-яЁё]", html), re.findall("[А-Яа-яЁё]+", html)[:5]


def test_home_redirects_to_the_engine_page(app):
    r = client(app).get("/", follow_redirects=False)
    assert r.status_code == 307 and r.headers["location"] == "/engine"


@pytest.mark.parametrize("name,want", [("petrol", "petrol-vaz2106"), ("diesel", "diesel-d240"),
                                        ("six", "bmw"), ("v8", "kamaz")])
def test_each_example_fills_the_form(app, name, want):
    import tomllib

    from web.engine_page import EXAMPLES

    c = client(app)
    html = c.post("/engine/example", data={"example": name}).text
    assert want in field_value(html, "engine.name").lower()
    spec = tomllib.loads(example_path(EXAMPLES[name]).read_text(encoding="utf-8"))
    assert field_value(html, "engine.bore_mm") == repr(spec["engine"]["bore_mm"])
    assert field_value(html, "engine.speed_rpm") == repr(spec["engine"]["speed_rpm"])
    source = "file" if "file" in spec["pressure"] else "cycle"
    assert f'value="{source}" id="source-{source}" checked' in html


# ----------------------------------------------------------------------------- problems
@pytest.mark.parametrize("lang,words", [("en", "must be > 0"), ("ru", "должно быть > 0")])
def test_a_bad_bore_is_named_next_to_its_field_and_nothing_is_computed(app, lang, words):
    c = client(app, lang)
    c.post("/engine/example", data={"example": "petrol"})
    vals = form_values(c.get("/engine").text)
    vals["engine.bore_mm"] = "-5"
    vals["pressure.cycle.n1"] = "2.5"          # a second problem, shown at once
    html = c.post("/engine/run", data=vals).text
    err = re.search(r'<p class="problem" id="err-engine.bore_mm">([^<]*)</p>', html)
    assert err, html[:3000]
    msg = htmllib.unescape(err.group(1))
    assert "engine.bore_mm" in msg and "-5" in msg and words in msg
    # it stands inside the bore's own field block
    block = re.search(r'<div class="field bad" id="field-engine.bore_mm">(.*?)</div>', html, re.S)
    assert block and "err-engine.bore_mm" in block.group(1)
    n1 = htmllib.unescape(re.search(r'id="err-pressure.cycle.n1">([^<]*)<', html).group(1))
    assert "pressure.cycle.n1" in n1 and "2.5" in n1 and "> 1" in n1 and "< 2" in n1
    assert 'id="results"' not in html
    assert field_value(html, "engine.bore_mm") == "-5"        # the form keeps what was typed


def test_text_in_a_number_field_and_a_missing_key_are_the_library_s_problems(app):
    c = client(app)
    c.post("/engine/example", data={"example": "petrol"})
    vals = form_values(c.get("/engine").text)
    vals["engine.speed_rpm"] = "fast"
    vals["engine.stroke_mm"] = ""
    html = c.post("/engine/run", data=vals).text
    assert "must be a number, got &#39;fast&#39;" in html
    assert re.search(r'id="err-engine.stroke_mm">engine.stroke_mm: missing', html)
    assert 'id="results"' not in html


def test_a_bad_counterweight_row_is_shown_at_the_rows_field(app):
    c = client(app)
    c.post("/engine/example", data={"example": "petrol"})
    vals = form_values(c.get("/engine").text)
    vals["balance.counterweights"] = ""
    vals["balance.counterweight"] = "0, 21.3, 180\n95, -1, 0"
    html = c.post("/engine/run", data=vals).text
    err = re.search(r'id="err-balance.counterweight">([^<]*)<', html)
    assert err and "balance.counterweight[1].mr_kg_mm" in err.group(1), html[-4000:]


# ------------------------------------------------------------ the app's kept studies
# The two tests clearing the app's kept studies (web.app.StudyCache, DrawnCache) run
# before any other run of the web modules (one app for them all, tests/conftest.py
# ``web_app_kept``), so that what the others compute and draw is kept for those asking
# for it again.
def test_the_same_study_asked_again_is_drawn_again_but_not_computed_again(app,
                                                                          monkeypatch):
    """A session's flywheel run posted again in Russian (web.app._same_study): the
    library's study runs once, the second run's CSVs are the first's byte for byte, its
    summary and figures are Russian (drawn again, from the first run's report); a changed
    value is computed again, with other numbers.  Another session's run of the same
    spec is not computed again either (web.app.StudyCache: one study for a class), and
    its CSVs are the first's byte for byte."""
    import dynamics.study as study

    real, calls = study.run_study, []
    monkeypatch.setattr(study, "run_study", lambda *a, **k: calls.append(1) or real(*a, **k))
    app.app.state.studies.clear()           # the app's earlier tests' studies forgotten
    app.app.state.drawn.clear()

    def files(html, ext):
        urls = re.findall(rf'(?:href|src)="(/dynamics/run/\d+/[^"]+\.{ext})"', html)
        return {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}

    c = client(app)
    c.post("/dynamics/example", data={"example": "flywheel"})
    vals = form_values(c.get("/dynamics").text)
    first = c.post("/dynamics/run", data=vals).text
    assert 'id="results"' in first and calls == [1]
    csv1, png1 = files(first, "csv"), files(first, "png")
    again = c.post("/dynamics/run?lang=ru", data=vals).text
    assert 'id="results"' in again and calls == [1]            # not computed again
    summary = re.search(r'<pre id="summary">(.*?)</pre>', again, re.S).group(1)
    assert re.search("[А-Яа-яЁё]", summary) and not re.search(
        "[А-Яа-яЁё]", re.search(r'<pre id="summary">(.*?)</pre>', first, re.S).group(1))
    csv2, png2 = files(again, "csv"), files(again, "png")
    assert csv1 and csv2 == csv1
    assert sorted(png2) == sorted(png1) and all(png2[n][:4] == b"\x89PNG" for n in png2)
    assert any(png2[n] != png1[n] for n in png1)                # drawn again, in Russian
    # the study test_the_dynamics_page_equals_crankdyn_dynamics[flywheel] runs later, in
    # English: its files drawn here, once (web.app.DrawnCache)
    vals["machine.J_red_kgm2"] = "0.3"
    other = c.post("/dynamics/run?lang=en", data=vals).text
    assert 'id="results"' in other and calls == [1, 1]         # a new study: computed
    csv3 = files(other, "csv")
    assert sorted(csv3) == sorted(csv1) and csv3 != csv1
    # a second session (a classmate) posting the example's values in English: the app's
    # study, and the files drawn for the first run (web.app.DrawnCache), its own links
    render, drawn = app.app.state.render, []
    real_submit = render.submit
    monkeypatch.setattr(render, "submit", lambda *a, **k: drawn.append(1) or
                        real_submit(*a, **k))
    c2 = client(app)
    c2.post("/dynamics/example", data={"example": "flywheel"})
    vals2 = form_values(c2.get("/dynamics").text)
    assert vals2["machine.J_red_kgm2"] != "0.3"
    html = c2.post("/dynamics/run", data=vals2).text
    assert 'id="results"' in html and calls == [1, 1]          # not computed again
    assert drawn == []                                          # nor drawn again
    got = {}
    for ext in ("csv", "png", "xlsx", "toml"):
        urls = re.findall(rf'(?:href|src)="(/dynamics/run/\d+/[^"]+\.{ext})"', html)
        got[ext] = {u.rsplit("/", 1)[1]: c2.get(u).content for u in urls}
    assert got["csv"] == csv1 and got["png"] == png1
    assert got["xlsx"] and got["toml"]
    s1 = app.app.state.store.get(c.cookies["crankdyn_session"]).folder
    s2 = app.app.state.store.get(c2.cookies["crankdyn_session"]).folder
    # the first run's folder is gone (its session ran again), its files were kept
    assert not (s1 / "dynamics-1").exists()
    assert sorted(p.name for p in (s2 / "dynamics-1").rglob("*.png")) == sorted(png1)
    # in Russian, the classmate gets the first session's Russian files; a changed
    # value is drawn (and computed) anew
    again2 = c2.post("/dynamics/run?lang=ru", data=vals2).text
    assert drawn == [] and calls == [1, 1]
    urls = re.findall(r'(?:href|src)="(/dynamics/run/\d+/[^"]+\.png)"', again2)
    assert {u.rsplit("/", 1)[1]: c2.get(u).content for u in urls} == png2
    vals2["machine.J_red_kgm2"] = "0.31"
    assert 'id="results"' in c2.post("/dynamics/run", data=vals2).text
    assert drawn == [1] and calls == [1, 1, 1]


def test_a_crashing_job_shows_an_error_in_its_session_and_the_server_goes_on(app, monkeypatch):
    import engine

    real = engine.run_study

    def boom(*a, **k):
        raise ZeroDivisionError("a bug")
    monkeypatch.setattr(engine, "run_study", boom)
    app.app.state.studies.clear()      # the petrol example computed again, by the bug
    c = client(app)
    c.post("/engine/example", data={"example": "petrol"})
    r = c.post("/engine/run", data=form_values(c.get("/engine").text))
    assert r.status_code == 500 and "ZeroDivisionError" in r.text and "internal error" in r.text
    monkeypatch.setattr(engine, "run_study", real)
    other = client(app)
    assert "petrol-vaz2106" in run_petrol(other)
    assert 'id="results"' not in c.get("/engine").text        # the crashed one: no results


# ----------------------------------------------------------------------------- results
def test_table2_on_the_page_and_the_downloads_equal_the_cli_files(petrol_page, tmp_path,
                                                                  cli_report,
                                                                  petrol_at_4000_tables):
    import tomllib

    c, html = petrol_page
    urls = links(html)
    got = tmp_path / "web"
    got.mkdir()
    for u in urls:
        r = c.get(u)
        assert r.status_code == 200, u
        (got / u.rsplit("/", 1)[1]).write_bytes(r.content)
    toml = got / "petrol-vaz2106.toml"
    assert 'speed_rpm = 4000.0' in toml.read_text(encoding="utf-8")
    # the downloaded spec is the example at 4000 rpm (the CLI reads a spec as this dict),
    # so the session's CLI run of that spec is the same run from the CLI (its figures
    # unrendered, conftest petrol_at_4000_tables: the page's are checked as PNG below)
    spec, report = petrol_at_4000_tables
    assert tomllib.loads(toml.read_text(encoding="utf-8")) == spec
    cli = shared(report)
    csvs = sorted(p.name for p in cli.glob("*.csv"))
    assert len(csvs) == 5
    for name in csvs:
        assert (got / name).read_bytes() == (cli / name).read_bytes(), name
    assert workbook_parts(got / "petrol-vaz2106.xlsx") == \
        workbook_parts(cli / "petrol-vaz2106.xlsx")
    # Table 2 on the page: the CSV's own text, every row (the page scrolls)
    head, rows = page_table(html)
    with open(cli / "petrol-vaz2106_forces.csv", newline="") as fh:
        want = list(csv.reader(fh))
    assert head == want[0] and rows == want[1:]
    # the speed was used: the inertia force differs from the example's at 5400 rpm
    base = shared(cli_report("engine", "--example", "petrol", "--lang", "en"))
    assert (base / "petrol-vaz2106_forces.csv").read_bytes() != \
        (cli / "petrol-vaz2106_forces.csv").read_bytes()
    # the summary and every figure
    assert "n = 4000 rpm" in html
    figs = re.findall(r'<img src="(/engine/run/\d+/[^"]+\.png)"', html)
    assert len(figs) == 13
    for u in figs:
        r = c.get(u)
        assert r.status_code == 200 and r.content[:8] == b"\x89PNG\r\n\x1a\n"
    # the zip holds the whole report and the spec
    z = zipfile.ZipFile(io.BytesIO(c.get(next(u for u in urls if u.endswith(".zip"))).content))
    names = set(z.namelist())
    assert {"petrol-vaz2106.toml", "petrol-vaz2106.xlsx", *csvs} <= names
    assert len([n for n in names if n.endswith(".png")]) == 13
    assert z.read("petrol-vaz2106_torque.csv") == (cli / "petrol-vaz2106_torque.csv").read_bytes()


def test_an_uploaded_spec_with_its_pressure_file_equals_the_cli(app, tmp_path, cli_report,
                                                               diesel_upload,
                                                               unrendered_figures):
    """The diesel example as a student would upload it (the TOML naming its CSV): same
    CSVs as the CLI on the bundled file; the spec and pressure file downloaded from the
    page repeat the run from the command line (whose figures are saved unrendered: the
    CSVs are compared; the page's figures are rendered, the shared English CLI report's
    are not: tests/conftest.py ``UNRENDERED_REPORTS``)."""
    c, r = diesel_upload
    pcsv = example_path("diesel_d240_indicator.csv")
    assert r.status_code == 200 and 'id="results"' in r.text, r.text[:3000]
    urls = links(r.text)
    got = {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}   # waits for the writing
    # (matplotlib draws in one thread at a time: the CLI runs after the page's report)
    cli = shared(cli_report("engine", "--example", "diesel", "--lang", "en"))
    for name in sorted(p.name for p in cli.glob("*.csv")):
        assert got[name] == (cli / name).read_bytes(), name
    # the downloaded spec + pressure file (server names) repeat the run
    again = tmp_path / "again"
    again.mkdir()
    for u in urls:
        if u.endswith((".toml", "pressure.csv")):
            (again / u.rsplit("/", 1)[1]).write_bytes(c.get(u).content)
    assert (again / "pressure.csv").read_bytes() == pcsv.read_bytes()
    out = run_cli(again / "diesel-d240.toml", tmp_path / "cli2")   # on the downloaded files
    for name in sorted(p.name for p in cli.glob("*.csv")):
        assert (out / name).read_bytes() == (cli / name).read_bytes()
    # no name from the user reached the disk
    assert not list(Path(app.root).rglob("my spec*")) and \
        not list(Path(app.root).rglob("diesel_d240_indicator*"))


def test_an_upload_naming_a_pressure_file_it_did_not_send_is_a_problem(app):
    c = client(app)
    r = c.post("/engine/upload", files={
        "spec": ("s.toml", example_path("diesel_d240.toml").read_bytes(), "text/plain")})
    err = re.search(r'id="err-pressure.file">([^<]*)<', r.text)
    assert err and "diesel_d240_indicator.csv" in err.group(1)
    assert 'id="results"' not in r.text


def test_an_upload_that_is_not_toml_or_has_unknown_keys(app):
    c = client(app, "ru")
    r = c.post("/engine/upload", files={"spec": ("s.toml", b"[engine\nbore = ", "text/plain")})
    assert "не корректный TOML" in r.text and 'id="results"' not in r.text
    text = example_path("petrol_vaz2106.toml").read_text(encoding="utf-8")
    bad = text.replace("bore_mm = 79.0", "bore = 79.0")
    r = c.post("/engine/upload", files={"spec": ("s.toml", bad.encode(), "text/plain")})
    assert "engine.bore" in r.text and "bore_mm" in r.text and 'id="results"' not in r.text


# ----------------------------------------------------------------------------- safety
def test_two_sessions_do_not_see_each_other_s_files(app, petrol_page, diesel_upload):
    a, ha = petrol_page                     # a's run: the petrol example at 4000 rpm
    b, rb = diesel_upload                   # b's run: the diesel example, uploaded
    hb = rb.text
    assert 'id="results"' in hb
    assert "petrol-vaz2106" in ha and "diesel-d240" in hb
    assert "diesel-d240" not in a.get("/engine").text
    for u in links(hb):
        assert a.get(u).status_code == 404                  # b's file, a's cookie
    for u in links(ha):
        assert b.get(u).status_code == 404
        assert a.get(u).status_code == 200
    sa = app.app.state.store.get(a.cookies["crankdyn_session"])
    sb = app.app.state.store.get(b.cookies["crankdyn_session"])
    assert sa.folder != sb.folder and sa.folder.parent == sb.folder.parent == Path(app.root)
    assert not list(sa.folder.rglob("diesel*")) and not list(sb.folder.rglob("petrol*"))


def test_a_forged_session_id_gets_a_new_session_and_no_path_is_used(app):
    c = TestClient(app, cookies={"crankdyn_session": "../../etc"})
    r = c.get("/engine")
    assert r.status_code == 200
    sid = re.search(r"crankdyn_session=([^;]+)", r.headers["set-cookie"]).group(1)
    assert sid != "../../etc" and app.app.state.store.get(sid) is not None
    assert c.get("/engine/run/1/..%2F..%2Fetc%2Fpasswd").status_code == 404


def test_an_upload_over_the_limit_gets_a_clear_message(app):
    for lang, words in (("en", "larger than the limit of 1.5 MB"), ("ru", "больше предела 1.5 МБ")):
        c = client(app, lang)
        r = c.post("/engine/upload", files={"spec": ("s.toml", b"#" * 1_600_000, "text/plain")})
        assert r.status_code == 413 and words in r.text
        assert c.get("/engine").status_code == 200             # the server goes on


def test_idle_sessions_and_shutdown_remove_their_folders(tmp_path):
    import time

    import web

    a = web.create_app(root=tmp_path / "root", idle_seconds=60)
    with TestClient(a) as c:
        c.get("/engine")
        c.post("/engine/example", data={"example": "diesel"})
        store = a.app.state.store
        s = store.get(c.cookies["crankdyn_session"])
        assert s.folder.is_dir()
        assert store.sweep(time.monotonic() + 30) == 0 and s.folder.is_dir()
        assert store.sweep(time.monotonic() + 120) == 1 and not s.folder.exists()
        c.get("/engine")                                         # a new session
        assert len(store) == 1
    assert not (tmp_path / "root").exists()                      # shutdown


def test_the_job_pool_refuses_beyond_its_bound():
    import threading

    from web.jobs import Busy, JobPool

    pool = JobPool(workers=1, queue=1)
    gate = threading.Event()
    f1, f2 = pool.submit(gate.wait), pool.submit(gate.wait)
    with pytest.raises(Busy):
        pool.submit(gate.wait)
    gate.set()
    f1.result(5), f2.result(5)
    pool.submit(lambda: 1).result(5)
    pool.close()


def test_the_page_loads_without_the_heavy_libraries():
    """One fresh interpreter: ``import engine, web`` imports nothing of the framework
    (only ``web`` itself), then the app's page and an example loaded import neither
    matplotlib, openpyxl nor scipy (the two checks were two interpreters before; the
    first runs first, before the framework is imported)."""
    code = ("import sys, engine, web\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] in "
            "('starlette', 'jinja2', 'uvicorn', 'web')))\n"
            "from starlette.testclient import TestClient\n"
            "c = TestClient(web.create_app())\nassert c.get('/engine').status_code == 200\n"
            "c.post('/engine/example', data={'example': 'petrol'})\n"
            "print(sorted({m.split('.')[0] for m in sys.modules} & {'matplotlib', 'openpyxl', 'scipy'}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, check=True).stdout.strip().splitlines()
    assert out[0] == "['web']"
    assert out[-1] == "[]"


def test_serve_without_the_web_extra_says_how_to_install_it(monkeypatch, capsys):
    from crankdyn.cli import main

    monkeypatch.setitem(sys.modules, "uvicorn", None)
    assert main(["serve", "--port", "9"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and 'pip install "crankdyn[web]"' in err[0]


def test_form_texts_round_trip_to_the_spec_dict():
    """A spec read into the form and posted back is the same dict (floats by repr)."""
    import tomllib

    from web.engine_form import spec_from_values, values_from_spec

    for name in ("petrol_vaz2106.toml", "petrol_bmw_m54.toml", "diesel_kamaz740.toml"):
        spec = tomllib.loads(example_path(name).read_text(encoding="utf-8"))
        values, source = values_from_spec(spec)
        assert spec_from_values(values, source) == spec, name
    d = tomllib.loads(example_path("diesel_d240.toml").read_text(encoding="utf-8"))
    values, source = values_from_spec(d)
    assert source == "file"
    back = spec_from_values(values, source, "pressure.csv")
    d["pressure"]["file"] = "pressure.csv"
    assert back == d


def test_crankdyn_serve_starts_the_app_and_prints_its_address():
    import socket
    import time
    import urllib.request

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen([sys.executable, "-m", "crankdyn", "serve", "--port", str(port)],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    try:
        line = proc.stdout.readline()
        assert line.startswith(f"crankdyn serve: http://127.0.0.1:{port}/")
        for _ in range(100):
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/engine?lang=ru",
                                            timeout=5) as r:
                    assert r.status == 200 and "Двигатель" in r.read().decode("utf-8")
                    break
            except OSError:
                time.sleep(0.1)
        else:
            pytest.fail("crankdyn serve did not answer")
    finally:
        proc.terminate()
        proc.wait(30)
        proc.stdout.close()
        proc.stderr.close()


def test_the_bearing_and_drawing_options_add_their_tables_figures_and_pdfs(app):
    c = client(app)
    c.post("/engine/example", data={"example": "petrol"})
    vals = form_values(c.get("/engine").text)
    html = c.post("/engine/run", data={**vals, "bearings": "on", "drawing": "on"}).text
    assert 'id="results"' in html
    urls = links(html)
    for name in ("crankpins.csv", "journals.csv", "journal_torques.csv", "wear.csv"):
        assert any(u.endswith("_" + name) for u in urls), name
    figs = re.findall(r'<img src="(/engine/run/\d+/[^"]+\.png)"', html)
    assert len(figs) > 13 and any("wear" in u for u in figs)
    pdfs = [u for u in urls if u.endswith(".pdf")]
    assert len(pdfs) >= 3 and all("_drawing_" in u for u in pdfs)
    r = c.get(pdfs[0])
    assert r.status_code == 200 and r.content[:5] == b"%PDF-"
    assert 'id="opt-bearings" checked' in html


# ----------------------------------------------------------------------------- linkage page
def test_the_linkage_page_runs_the_ratchet_like_the_cli(app, tmp_path, cli_report,
                                                        unrendered_figures):
    """The ratchet drive with a new crank speed: every CSV byte for byte and the workbook
    part for part (:func:`workbook_parts`) equal to ``crankdyn linkage`` on the downloaded
    spec (the CLI's figures saved unrendered: the page's own, drawn in the app's render
    processes, are checked as PNG)."""
    from crankdyn.cli import main

    c = client(app)
    html = c.get("/linkage").text
    assert 'id="mechanism.crank"' in html and 'id="links.coupler.points"' in html
    c.post("/linkage/example", data={"example": "ratchet"})
    vals = form_values(c.get("/linkage").text)
    assert vals["mechanism.omega_rad_s"] == "17.0" and vals["links.coupler.points"] == "E = 0.365, 0.0"
    assert vals["load"].startswith('link = "rocker", resistance_Nm = 1500.0')
    vals["mechanism.omega_rad_s"] = "12.5"
    vals["step"] = "2"
    r = c.post("/linkage/run", data=vals)
    assert 'id="results"' in r.text, r.text[:3000]
    urls = re.findall(r'href="(/linkage/run/\d+/[^"]+)"', r.text)
    got = {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}
    spec = tmp_path / "ratchet-drive.toml"
    spec.write_bytes(got["ratchet-drive.toml"])
    assert "omega_rad_s = 12.5" in spec.read_text(encoding="utf-8")
    out = tmp_path / "cli"
    assert main(["linkage", str(spec), "-o", str(out), "--lang", "en", "--step", "2"]) == 0
    for name in ("ratchet-drive_kinematics.csv", "ratchet-drive_forces.csv"):
        assert got[name] == (out / name).read_bytes(), name
    assert workbook_parts(got["ratchet-drive.xlsx"]) == \
        workbook_parts(out / "ratchet-drive.xlsx")
    head, rows = page_table(r.text)
    with open(out / "ratchet-drive_kinematics.csv", newline="") as fh:
        assert [head, *rows] == list(csv.reader(fh))
    figs = re.findall(r'<img src="(/linkage/run/\d+/[^"]+\.png)"', r.text)
    assert len(figs) == 5 and all(c.get(u).content[:4] == b"\x89PNG" for u in figs)
    # the example's own run: only its forces.csv is read (the session's run without figures)
    base = shared(cli_report("linkage", "--example", "ratchet", "--no-plots", "--lang", "en"))
    assert (base / "ratchet-drive_forces.csv").read_bytes() != got["ratchet-drive_forces.csv"]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_linkage_problems_stand_at_their_fields(app, lang):
    c = client(app, lang)
    c.post("/linkage/example", data={"example": "press"})
    vals = form_values(c.get("/linkage").text)
    vals["mechanism.crank"] = "0"
    vals["links.slider.mass_kg"] = "-35"
    vals["step"] = "45"
    html = c.post("/linkage/run", data=vals).text
    assert 'id="results"' not in html
    if "err-step" in html:                 # a bad step is refused before the spec is read
        assert "45" in htmllib.unescape(re.search(r'id="err-step">([^<]*)<', html).group(1))
        vals["step"] = "1"
        html = c.post("/linkage/run", data=vals).text
    crank = htmllib.unescape(re.search(r'id="err-mechanism.crank">([^<]*)<', html).group(1))
    assert "mechanism.crank" in crank and ("> 0" in crank)
    mass = htmllib.unescape(re.search(r'id="err-links.slider.mass_kg">([^<]*)<', html).group(1))
    assert "links.slider.mass_kg" in mass and "-35" in mass
    assert 'id="results"' not in html


# ----------------------------------------------------------------------------- dynamics page
@pytest.mark.parametrize("example,key,value", [("flywheel", "machine.J_red_kgm2", "0.3"),
                                               ("hoist", "dynamics.motor_start_torque_Nm",
                                                "4500.0")])
def test_the_dynamics_page_equals_crankdyn_dynamics(app, tmp_path, example, key, value,
                                                    unrendered_figures):
    """The page's files equal ``crankdyn dynamics`` on its downloaded spec: CSVs byte for
    byte, the workbook part for part, the CLI's figures by name (saved unrendered) among
    the page's, which are PNG (drawn in the app's render processes)."""
    from crankdyn.cli import main

    c = client(app)
    c.post("/dynamics/example", data={"example": example})
    vals = form_values(c.get("/dynamics").text)
    assert vals[key] != value
    vals[key] = value
    r = c.post("/dynamics/run", data=vals)
    assert 'id="results"' in r.text, r.text[:3000]
    urls = re.findall(r'(?:href|src)="(/dynamics/run/\d+/[^"]+)"', r.text)
    got = {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}
    toml = next(n for n in got if n.endswith(".toml"))
    spec = tmp_path / toml
    spec.write_bytes(got[toml])
    out = tmp_path / "cli"
    assert main(["dynamics", str(spec), "-o", str(out), "--lang", "en"]) == 0
    csvs = sorted(p.name for p in out.glob("*.csv"))
    assert csvs and all(got[n] == (out / n).read_bytes() for n in csvs), csvs
    xlsx = next(p.name for p in out.glob("*.xlsx"))
    assert workbook_parts(got[xlsx]) == workbook_parts(out / xlsx)
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert pngs and all(got[n][:4] == b"\x89PNG" for n in pngs)
    head, rows = page_table(r.text)
    with open(next(out.glob("*_motion.csv")), newline="") as fh:
        want = list(csv.reader(fh))
    from web.pages import PAGE_ROWS

    assert head == want[0] and rows == want[1:PAGE_ROWS + 1]       # the first rows
    if len(want) - 1 > PAGE_ROWS:
        assert f"The first {PAGE_ROWS} of {len(want) - 1} rows" in r.text


def test_the_kept_drawn_files_are_links_the_oldest_dropped_beyond_the_size(tmp_path):
    """web.app.DrawnCache of size 1: a run's files kept as links (a removed run folder
    leaves them whole); a new run gets links of them, byte for byte; a second key drops
    the first (its folder removed); a run whose files are gone keeps nothing;
    StudyCache keeps no run that reads a pressure file."""
    import shutil

    from web.app import DrawnCache, StudyCache
    from web.engine_page import EnginePage

    run = tmp_path / "run1"
    (run / "report").mkdir(parents=True)
    files = {"a.csv": run / "report" / "a.csv", "a.png": run / "a.png"}
    files["a.csv"].write_text("x,y\n1,2\n")
    files["a.png"].write_bytes(b"\x89PNG-1")
    cache = DrawnCache(tmp_path / "drawn", 1)
    cache.keep(("k1", "en"), files)
    shutil.rmtree(run)
    got = cache.files(("k1", "en"), tmp_path / "run2" / "report")
    assert sorted(got) == ["a.csv", "a.png"] and got["a.png"].read_bytes() == b"\x89PNG-1"
    assert got["a.csv"].parent == tmp_path / "run2" / "report"
    assert cache.files(("k1", "ru"), tmp_path / "run3") is None
    assert not (tmp_path / "run3").exists()
    kept1 = next((tmp_path / "drawn").iterdir())
    cache.keep(("k2", "en"), {"b.csv": got["a.csv"]})
    assert len(cache) == 1 and not kept1.exists()
    assert cache.files(("k1", "en"), tmp_path / "run4") is None
    assert cache.files(("k2", "en"), tmp_path / "run4")["b.csv"].read_text() == "x,y\n1,2\n"
    cache.keep(("k3", "en"), {"c.csv": tmp_path / "gone.csv"})
    assert cache.files(("k3", "en"), tmp_path / "run5") is None and len(cache) == 1
    kind = EnginePage()
    assert StudyCache.key(kind, {"engine": {"bore_mm": 79.0}}, None, {"torsion": False}) == \
        ("engine", "[engine]\nbore_mm = 79.0\n", "[('torsion', False)]")
    assert StudyCache.key(kind, {"engine": {}}, ("pressure.csv", b"1"), {}) is None


def test_a_run_is_drawn_ahead_or_when_first_asked_for(app, monkeypatch):
    """``create_app(draw=...)``, read at each run (``app.state.draw``).  "on_request": a
    run of a page that lists its files by name (the synthesis) is not drawn when it is
    computed nor when its page is shown; a run replaced by the next one before any file
    of it was asked for is never drawn (nothing of it written); the first file asked
    for draws the run, once for all its files.  "ahead" (the default): the drawing is
    submitted with the run, before any page or file is asked for, and the page of a kind
    listing its files once written (the balance) shows them ready, a file asked right
    after served (the default: the tests' app, conftest ``web_app``, draws ahead, as
    ``crankdyn serve`` does)."""
    import web
    from web.sessions import COOKIE

    state = app.app.state
    assert state.draw == "ahead"                            # the default
    monkeypatch.setattr(state, "draw", "on_request")
    with pytest.raises(ValueError, match="draw"):
        web.create_app(draw="later")
    render, jobs = state.render, []
    real_submit = render.submit
    monkeypatch.setattr(render, "submit",
                        lambda *a, **k: jobs.append(a[1].name) or real_submit(*a, **k))
    # on request: studies of their own (no other test runs these values: none kept drawn)
    c = client(app)
    c.post("/synth/example", data={"example": "readme"})
    vals = form_values(c.get("/synth").text)
    folder = state.store.get(c.cookies[COOKIE]).folder
    pages = []
    for mu in ("37.5", "38.5"):
        r = c.post("/synth/run", data={**vals, "synth.mu_min_deg": mu})
        assert r.status_code == 200 and 'id="results"' in r.text, r.text[:2000]
        pages.append(r.text)
    assert jobs == []                                       # neither run drawn
    figs = re.findall(r'<img src="(/synth/run/2/[^"]+\.png)"', pages[1])
    assert len(figs) == 3
    assert c.get(re.sub(r"/run/2/", "/run/1/", figs[0])).status_code == 404
    got = [c.get(u) for u in figs]
    assert all(g.status_code == 200 and g.content[:4] == b"\x89PNG" for g in got)
    assert jobs == ["synth"]                                # drawn once, for all three
    assert not (folder / "synth-1").exists()                # the replaced run: never
    assert sorted(p.name for p in (folder / "synth-2").rglob("*.png")) == sorted(
        u.rsplit("/", 1)[1] for u in figs)
    # ahead
    monkeypatch.setattr(state, "draw", "ahead")
    c = client(app)
    c.post("/balance/example", data={"example": "rotor"})
    vals = form_values(c.get("/balance").text)
    vals["rotor.mass"] = vals["rotor.mass"].replace("z_mm = 420", "z_mm = 404")
    r = c.post("/balance/run", data=vals, follow_redirects=False)
    assert r.status_code == 303 and jobs == ["synth", "balance"]    # before any page
    html = c.get("/balance").text
    urls = re.findall(r'(?:href|src)="(/balance/run/1/[^"]+)"', html)
    png = next(u for u in urls if u.endswith("_rotor_polygons.png"))
    assert c.get(png).content[:4] == b"\x89PNG"
    assert sum(u.endswith(".csv") for u in urls) == 2 and jobs == ["synth", "balance"]


def test_a_report_crosses_to_the_drawing_process_pickled():
    """web.pages.report_blob: read-only mappings (a report's tables) pickled as such;
    something that does not pickle gives None (the drawing process then computes)."""
    import pickle
    from types import MappingProxyType

    from web.pages import report_blob

    back = pickle.loads(report_blob({"tables": MappingProxyType({"a": 1.5}), "x": [1, 2]}))
    assert type(back["tables"]) is MappingProxyType and back == {"tables": {"a": 1.5},
                                                                 "x": [1, 2]}
    assert report_blob({"f": lambda: 0}) is None


@pytest.mark.parametrize("lang,words", [("en", "must be > 0 and < 1"),
                                        ("ru", "должно быть > 0 и < 1")])
def test_a_bad_delta_is_named_at_its_field(app, lang, words):
    c = client(app, lang)
    c.post("/dynamics/example", data={"example": "flywheel"})
    vals = form_values(c.get("/dynamics").text)
    vals["dynamics.delta"] = "2"
    html = c.post("/dynamics/run", data=vals).text
    err = htmllib.unescape(re.search(r'id="err-dynamics.delta">([^<]*)<', html).group(1))
    assert "dynamics.delta" in err and words in err
    assert 'id="results"' not in html


# ----------------------------------------------------------------------------- balance page
def test_the_balance_page_equals_crankdyn_balance(app, tmp_path, unrendered_figures):
    """The textbook's two-plane rotor (example 11-1: plane I 285.60 g·mm at 53.54°) with
    its second mass moved: the page's CSVs equal ``crankdyn balance`` on its spec (whose
    figures are saved unrendered)."""
    from crankdyn.cli import main

    c = client(app)
    c.post("/balance/example", data={"example": "rotor"})
    vals = form_values(c.get("/balance").text)
    assert vals["rotor.mass"].splitlines() == ["mr_gmm = 90, angle_deg = 270, z_mm = 100",
                                               "mr_gmm = 600, angle_deg = 45, z_mm = 420"]
    r = c.post("/balance/run", data=vals)
    assert 'id="results"' in r.text, r.text[:3000]
    head, rows = page_table(r.text)
    row = dict(zip(head, rows[0]))
    assert round(float(row["mr_gmm"]), 2) == 285.60 and round(float(row["angle_deg"]), 2) == 53.54
    vals["rotor.mass"] = vals["rotor.mass"].replace("z_mm = 420", "z_mm = 380")
    r = c.post("/balance/run", data=vals)
    urls = re.findall(r'(?:href|src)="(/balance/run/\d+/[^"]+)"', r.text)
    got = {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}
    toml = next(n for n in got if n.endswith(".toml"))
    (tmp_path / toml).write_bytes(got[toml])
    out = tmp_path / "cli"
    assert main(["balance", str(tmp_path / toml), "-o", str(out), "--lang", "en"]) == 0
    csvs = sorted(p.name for p in out.glob("*.csv"))
    assert len(csvs) == 2 and all(got[n] == (out / n).read_bytes() for n in csvs)
    assert any(n.endswith("_rotor_polygons.png") for n in got)
    head, rows = page_table(r.text)
    assert round(float(dict(zip(head, rows[0]))["mr_gmm"]), 2) != 285.60


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_bad_rotor_mass_line_is_named_at_its_field(app, lang):
    c = client(app, lang)
    c.post("/balance/example", data={"example": "rotor"})
    vals = form_values(c.get("/balance").text)
    vals["rotor.mass"] = "mr_gmm = -90, angle_deg = 270, z_mm = 100\nangle_deg = 45"
    html = c.post("/balance/run", data=vals).text
    errs = [htmllib.unescape(m) for m in re.findall(r'id="err-rotor.mass[^"]*">([^<]*)<', html)]
    assert any("rotor.mass[0].mr_gmm" in e and "-90" in e for e in errs), errs
    assert 'id="results"' not in html


def test_the_pages_of_one_session_keep_their_files_apart(app, petrol_page):
    """One session on every page in turn: each page's run has its own folder, so one
    page's new run neither removes nor lists another page's files.  The engine page's
    run is the shared petrol run's session (its run came first)."""
    c, html = petrol_page
    pages = {"engine": "petrol", "linkage": "ratchet", "dynamics": "flywheel",
             "balance": "rotor"}
    assert 'id="results"' in html
    shown = {"engine": re.findall(r'(?:href|src)="(/engine/run/\d+/[^"]+)"', html)}
    for page, example in list(pages.items())[1:]:
        c.post(f"/{page}/example", data={"example": example})
        html = c.post(f"/{page}/run", data=form_values(c.get(f"/{page}").text)).text
        assert 'id="results"' in html, page
        shown[page] = re.findall(rf'(?:href|src)="(/{page}/run/\d+/[^"]+)"', html)
    for page, urls in shown.items():
        for u in urls:
            assert c.get(u).status_code == 200, u
    figs = [u for u in shown["balance"] if u.endswith(".png")]
    assert len(figs) == 1 and figs[0].endswith("_rotor_polygons.png")
    s = app.app.state.store.get(c.cookies["crankdyn_session"])
    assert sorted(p.name.split("-")[0] for p in s.folder.iterdir()) == sorted(pages)


# ----------------------------------------------------------------------------- teacher page
def test_the_teacher_page_runs_a_class_and_zips_every_report(app, tmp_path, request):
    """Three variants of the petrol engine, one of them bad: the page's progress ends
    with two reports and the bad row named; each report in the zip is what
    ``crankdyn engine`` writes for the variant's own spec (its CSVs; that run's figures
    are saved unrendered, once the batch, with its real figures, is done)."""
    from crankdyn.cli import main

    c = client(app)
    assert "variants-form" in c.get("/teacher").text
    table = ("variant,engine.bore_mm,engine.speed_rpm\n"
             "v1,80,5000\nv2,-3,5000\nv3,82,4800\n").encode()
    r = c.post("/teacher/variants", files={
        "base": ("base.toml", example_path("petrol_vaz2106.toml").read_bytes(), "text/plain"),
        "variants": ("class.csv", table, "text/csv")})
    assert r.status_code == 200 and "batch-progress" in r.text
    app.app.state.batches.drain(600)        # the batch done: its page asked once, not polled
    html = c.get("/teacher").text
    line = htmllib.unescape(re.search(r'id="batch-line">([^<]*)<', html).group(1))
    assert "3 variants: 2 written" in line and "1 failed (row 3)" in line
    fails = htmllib.unescape(" ".join(re.findall(r'<li class="problem">([^<]*)</li>', html)))
    assert "engine.bore_mm" in fails and "-3" in fails
    assert 'value="3" max="3"' in html
    zurl = re.search(r'href="(/teacher/batch/\d+/class_reports.zip)"', html).group(1)
    z = zipfile.ZipFile(io.BytesIO(c.get(zurl).content))
    names = z.namelist()
    assert "variants_summary.csv" in names and "variants_errors.csv" in names
    assert not any(n.startswith("v2/") for n in names)
    # every figure of both reports drawn for real, in PNG and SVG (the browser's class,
    # tests/test_web_browser.py, saves its figures unrendered)
    for v in ("v1", "v3"):
        pngs = [n for n in names if n.startswith(f"{v}/") and n.endswith(".png")]
        svgs = [n for n in names if n.startswith(f"{v}/") and n.endswith(".svg")]
        assert len(pngs) == 13 and sorted(n[:-4] for n in svgs) == sorted(n[:-4] for n in pngs)
        assert all(z.read(n)[:8] == b"\x89PNG\r\n\x1a\n" for n in pngs)
        assert all(b"<svg" in z.read(n)[:1000] for n in svgs)
    spec = next(n for n in names if n.startswith("v3/") and n.endswith(".toml"))
    (tmp_path / "v3").mkdir()
    for n in names:
        if n.startswith("v3/") and not n.endswith((".png", ".svg", ".xlsx")):
            (tmp_path / n).write_bytes(z.read(n))
    assert "bore_mm = 82" in (tmp_path / spec).read_text(encoding="utf-8")
    out = tmp_path / "cli"
    assert request.getfixturevalue("unrendered_figures") == []
    assert main(["engine", str(tmp_path / spec), "-o", str(out), "--lang", "ru"]) == 0
    for p in out.glob("*.csv"):
        assert z.read(f"v3/{p.name}") == p.read_bytes(), p.name


def test_the_teacher_page_names_a_bad_table_and_too_many_variants(app):
    c = client(app, "ru")
    base = example_path("petrol_vaz2106.toml").read_bytes()
    r = c.post("/teacher/variants", files={"base": ("b.toml", base, "text/plain"),
                                           "variants": ("t.csv", b"bore\n1\n", "text/csv")})
    assert "variant" in r.text and "batch-progress" not in r.text
    assert "/input/" not in r.text                              # no server path shown
    rows = "variant,engine.bore_mm\n" + "".join(f"v{i},80\n" for i in range(101))
    r = c.post("/teacher/variants", files={"base": ("b.toml", base, "text/plain"),
                                           "variants": ("t.csv", rows.encode(), "text/csv")})
    assert "не более 100" in htmllib.unescape(r.text) and "batch-progress" not in r.text


def test_the_language_switch_offers_chinese_and_the_page_speaks_it(app):
    """Issue #19: the switch lists every offered language (crankbase.texts.languages);
    the Chinese engine page has the Chinese words and no Cyrillic."""
    from crankbase.texts import languages, texts

    c = client(app, "zh")
    html = c.get("/engine").text
    for lang in languages():
        assert f'id="lang-{lang}"' in html
    assert 'id="lang-zh" class="active"' in html
    assert '<html lang="zh">' in html
    t = texts("zh")
    assert t("web.engine.title") in html and t("web.form.compute") in html
    assert "发动机动力学" in html
    assert not re.search(r"[А-Яа-яЁё]", re.sub(r'id="lang-\w+"[^<]*', "", html))
