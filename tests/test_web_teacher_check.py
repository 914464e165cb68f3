"""The teacher's check of a student's work on ``/teacher`` and the torsional vibration on
the engine page, through Starlette's TestClient (no browser).

The reference of every word and number is the command line on the same inputs:
``crankdyn check SPEC STUDENT`` (its verdict lines, ``check.csv``, the checked workbook
as :func:`crankbase.checking.write_check` writes it) and ``crankdyn engine SPEC
--torsion`` (the torsion CSVs byte for byte, its summary lines).
"""
from __future__ import annotations

import html as htmllib
import re
import shutil
from pathlib import Path

import pytest

pytest.importorskip("starlette")  # the test extra installs it; a bare core install skips
from starlette.testclient import TestClient  # noqa: E402

from crankbase.resources import example_path  # noqa: E402

from test_web import form_values, links, page_table, workbook_parts  # noqa: E402

PETROL = example_path("petrol_vaz2106.toml")
DIESEL = example_path("diesel_d240.toml")
DIESEL_P = example_path("diesel_d240_indicator.csv")
TORSION = example_path("torsion_inline6.toml")

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
    yield
    app.app.state.render.drain(300)


def client(app, lang="en", page="teacher"):
    c = TestClient(app)
    c.get(f"/{page}?lang={lang}")
    return c


@pytest.fixture(scope="module")
def petrol(cli_report):
    rep = cli_report("engine", "--example", "petrol", "--lang", "en")   # shared, read-only
    assert rep.rc == 0, rep.err
    return rep.folder


def cli_check(spec, student, out, lang="en"):
    """``crankdyn check SPEC STUDENT -o OUT --lang LANG``: (exit status, printed lines)."""
    import contextlib
    import io

    from crankdyn.cli import main

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        code = main(["check", str(spec), str(student), "-o", str(out), "--lang", lang])
    return code, buf.getvalue().splitlines()


def post_check(c, spec, student, pressure=None, **fields):
    """Post the check form: ``spec``, ``student``, ``pressure`` are ``(name, bytes)``."""
    files = {"spec": (spec[0], spec[1], "application/toml"),
             "student": (student[0], student[1], "application/octet-stream")}
    if pressure is not None:
        files["pressure"] = (pressure[0], pressure[1], "text/csv")
    r = c.post("/teacher/check", files=files, data=fields)
    assert r.status_code == 200, r.text[:2000]
    return r.text


def verdict(html):
    m = re.search(r'<pre id="check-verdict">(.*?)</pre>', html, re.S)
    return [htmllib.unescape(ln) for ln in m.group(1).splitlines()] if m else None


def field_problems(html, name):
    return [htmllib.unescape(m) for m in
            re.findall(rf'<p class="problem" id="err-check-{name}(?:-\d+)?">([^<]*)</p>', html)]


# ----------------------------------------------------------------------------- check: CSV
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_good_csv_is_all_right_with_the_cli_s_words(app, petrol, tmp_path, lang):
    """Table 2 as the CLI wrote it for the same spec: every column right, the verdict the
    same lines as ``crankdyn check`` prints (its last line names its files: the page names
    them without the server's folder)."""
    student = tmp_path / "ivanov.csv"
    shutil.copyfile(petrol / "petrol-vaz2106_table2.csv", student)
    code, cli = cli_check(PETROL, student, tmp_path / "chk", lang)
    assert code == 0
    c = client(app, lang)
    html = post_check(c, ("my spec.toml", PETROL.read_bytes()),
                      ("ivanov.csv", student.read_bytes()))
    lines = verdict(html)
    assert lines[:-1] == cli[:-1] and lines[0].startswith("ivanov.csv")
    assert len(lines) > 6                       # head, tolerance, a line per column
    assert "check.csv" in lines[-1] and str(app.root) not in html
    assert 'id="check-status" class="ok"' in html and 'id="check-wrong"' not in html
    assert 'id="dl-check-marked"' not in html          # a CSV has no checked workbook
    if lang == "ru":
        assert "все значения верны" in html and "WRONG" not in html


def test_one_changed_cell_flags_that_column_and_that_cell(app, petrol, tmp_path):
    import pandas as pd

    df = pd.read_csv(petrol / "petrol-vaz2106_forces.csv")
    row = int(df.index[df["alpha_deg"] == 30][0])
    right = df.loc[row, "T_N"]
    assert abs(right) > 0.05 * df["T_N"].abs().max()         # not a zero crossing
    df.loc[row, "T_N"] = right * 1.3
    student = tmp_path / "petrov.csv"
    df.to_csv(student, index=False)
    code, cli = cli_check(PETROL, student, tmp_path / "chk")
    assert code == 1
    c = client(app)
    html = post_check(c, ("spec.toml", PETROL.read_bytes()),
                      ("petrov.csv", student.read_bytes()))
    lines = verdict(html)
    assert lines[:-1] == cli[:-1]
    t_line = next(ln for ln in lines if ln.split()[:1] == ["T_N"])
    assert "WRONG 1 of" in t_line and "30" in t_line
    others = [ln for ln in lines[2:-1] if ln.split()[:1] not in (["T_N"], ["Not"])
              and not ln.startswith("columns")]
    assert others and all("WRONG" not in ln for ln in others), others
    assert 'id="check-status" class="problem"' in html and "1 value is wrong" in html
    head, rows = page_table(html, "check-wrong")
    assert head == ["alpha_deg", "column", "student", "computed", "deviation", "ok"]
    assert [r[:2] for r in rows] == [["30.0", "T_N"]]
    assert float(rows[0][3]) == pytest.approx(right) and float(rows[0][2]) == \
        pytest.approx(right * 1.3)
    # check.csv downloaded is the CLI's, byte for byte
    url = re.search(r'href="(/teacher/check/\d+/check.csv)"', html).group(1)
    assert c.get(url).content == (tmp_path / "chk" / "check.csv").read_bytes()


# ----------------------------------------------------------------------------- check: xlsx
def _cells(path):
    """Every cell of every sheet: value, fill colour, comment text."""
    from openpyxl import load_workbook

    wb = load_workbook(path)
    out = {}
    for ws in wb.worksheets:
        for row in ws.iter_rows():
            for c in row:
                if c.value is not None or c.comment is not None:
                    out[(ws.title, c.coordinate)] = (
                        c.value, c.fill.fgColor.rgb if c.fill.fill_type else None,
                        c.comment.text if c.comment else None)
    return out


def test_the_checked_workbook_equals_the_library_s(app, cli_report, tmp_path):
    """The diesel's workbook (the spec naming its pressure file, uploaded under the
    user's names) with two cells changed: the page's checked workbook equals what the
    library writes for the same inputs, cell for cell (values, red fills, comments)."""
    from openpyxl import load_workbook

    import engine
    from crankbase.checking import check_table, write_check
    from engine.check import check_side

    rep = cli_report("engine", "--example", "diesel", "--lang", "ru")   # shared, read-only
    assert rep.rc == 0, rep.err
    wb = load_workbook(rep.folder / "diesel-d240.xlsx")
    ws = wb.worksheets[1]                        # Table 2: keys in hidden row 5
    keys = [ws.cell(5, j).value for j in range(1, ws.max_column + 1)]
    rows = {ws.cell(r, 1).value: r for r in range(6, ws.max_row + 1)}
    for a, col, f in ((60, "T_N", 1.3), (390, "K_N", 0.6)):
        cell = ws.cell(rows[a], keys.index(col) + 1)
        assert abs(cell.value) > 1e-3
        cell.value *= f
    student = tmp_path / "sidorov.xlsx"
    wb.save(student)
    c = client(app, "ru")
    html = post_check(c, ("../my diesel.toml", DIESEL.read_bytes()),
                      ("sidorov.xlsx", student.read_bytes()),
                      pressure=("indicator.csv", DIESEL_P.read_bytes()))
    assert "2 значения неверны" in html, verdict(html)
    url = re.search(r'href="(/teacher/check/\d+/sidorov_checked.xlsx)"', html).group(1)
    got = tmp_path / "page_checked.xlsx"
    got.write_bytes(c.get(url).content)
    result = check_table(check_side(engine.load(DIESEL)), student)
    written = write_check(result, tmp_path / "lib", "ru")
    assert written.marked.name == "sidorov_checked.xlsx" and written.n_marked == 2
    want = _cells(written.marked)
    assert _cells(got) == want
    red = sorted(k for k, v in want.items() if v[1] in ("00FF7C80", "FFFF7C80"))
    assert len(red) == 2 and all(want[k][2] for k in red)
    # nothing of the user's names reached the disk
    assert not list(Path(app.root).rglob("sidorov*")) and not list(
        Path(app.root).rglob("*my diesel*"))


# ----------------------------------------------------------------------------- check: bad
def test_bad_files_are_named_next_to_their_fields(app, petrol):
    c = client(app)
    good_csv = ("s.csv", (petrol / "petrol-vaz2106_table2.csv").read_bytes())
    html = post_check(c, ("a.toml", b"[engine\nname = 1"), good_csv)
    assert field_problems(html, "spec") and "check-verdict" not in html
    html = post_check(c, ("a.toml", PETROL.read_bytes()), ("s.txt", b"alpha_deg\n1\n"))
    assert field_problems(html, "student") == ["s.txt: not a workbook (.xlsx, .xlsm) or a CSV"]
    html = post_check(c, ("a.toml", PETROL.read_bytes()), ("s.xlsx", b"not a workbook"))
    (msg,) = field_problems(html, "student")
    assert msg.startswith("s.xlsx: cannot be read")
    html = post_check(c, ("a.toml", PETROL.read_bytes()), ("s.csv", b"T_N\n1\n"))
    (msg,) = field_problems(html, "student")
    assert msg.startswith("s.csv: ") and "alpha_deg" in msg and str(app.root) not in msg
    html = post_check(c, ("d.toml", DIESEL.read_bytes()), good_csv)
    (msg,) = field_problems(html, "pressure")
    assert "diesel_d240_indicator.csv" in msg
    html = post_check(c, ("a.toml", PETROL.read_bytes()), good_csv, rtol="2", atol="-1")
    assert field_problems(html, "rtol") and field_problems(html, "atol")
    html = post_check(c, ("a.toml", b'[other]\nx = 1\n'), good_csv)
    assert field_problems(html, "spec")
    r = c.post("/teacher/check", files={"spec": ("a.toml", PETROL.read_bytes(), "text/plain")})
    assert field_problems(r.text, "student") == ["Choose this file."]
    # a failed check leaves no folder of it behind
    folder = app.app.state.store.get(c.cookies["crankdyn_session"]).folder
    assert folder.is_dir() and not list(folder.iterdir())


# ----------------------------------------------------------------------------- a class
@pytest.fixture(scope="module")
def class_inputs(tmp_path_factory):
    """Two petrol variants (``run_variants(..., formats=())``) and a class of two: Ivanov's
    workbook of v01 as written (right), Petrov's forces CSV of v02 with T at 30° × 1.3."""
    import pandas as pd

    from engine.variants import run_variants

    d = tmp_path_factory.mktemp("class")
    table = d / "variants.csv"
    table.write_text("variant,engine.bore_mm,engine.speed_rpm\nv01,80,5000\nv02,82.5,5600\n",
                     encoding="utf-8")
    run = run_variants(PETROL, table, d / "out", "en", formats=())
    assert [o.ok for o in run.outcomes] == [True, True]
    students = d / "students"
    students.mkdir()
    shutil.copyfile(d / "out" / "v01" / "v01.xlsx", students / "ivanov_v01.xlsx")
    df = pd.read_csv(d / "out" / "v02" / "v02_forces.csv")
    row = int(df.index[df["alpha_deg"] == 30][0])
    assert abs(df.loc[row, "T_N"]) > 0.05 * df["T_N"].abs().max()
    df.loc[row, "T_N"] *= 1.3
    df.to_csv(students / "petrov_v02.csv", index=False)
    return table, students


def post_class(c, base, variants, students, pressure=None, **fields):
    """Post the class form: ``base``, ``variants``, ``pressure`` are ``(name, bytes)``,
    ``students`` a list of them."""
    files = [("base", (base[0], base[1], "application/toml")),
             ("variants", (variants[0], variants[1], "text/csv"))]
    files += [("students", (n, b, "application/octet-stream")) for n, b in students]
    if pressure is not None:
        files.append(("pressure", (pressure[0], pressure[1], "text/csv")))
    r = c.post("/teacher/class", files=files, data=fields)
    assert r.status_code == 200, r.text[:2000]
    return r.text


def class_problems(html, name):
    return [htmllib.unescape(m) for m in
            re.findall(rf'<p class="problem" id="err-class-{name}(?:-\d+)?">([^<]*)</p>', html)]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_class_check_equals_the_library_s(app, class_inputs, tmp_path, lang):
    """The page's class_check.csv is what engine.variants.check_class writes for the same
    inputs, byte for byte; Petrov's changed cell flags him (1 cell, 1 column), Ivanov is
    right; the zip holds each student's check.csv."""
    import io
    import zipfile

    from engine.variants import check_class

    table, students = class_inputs
    done = check_class(PETROL, table, students, tmp_path / "lib", lang)
    recs = {r["student"]: r for r in done.records(lang)}
    assert recs["petrov_v02.csv"]["cells_wrong"] == 1 and \
        recs["petrov_v02.csv"]["columns_wrong"] == 1
    assert recs["ivanov_v01.xlsx"]["cells_wrong"] == 0 and not done.ok
    c = client(app, lang)
    html = post_class(c, ("my base.toml", PETROL.read_bytes()),
                      ("variants.csv", table.read_bytes()),
                      [(p.name, p.read_bytes()) for p in sorted(students.iterdir())])
    assert 'id="class-status" class="problem"' in html, html[-3000:]
    url = re.search(r'href="(/teacher/class/\d+/class_check.csv)"', html).group(1)
    assert c.get(url).content == (tmp_path / "lib" / "class_check.csv").read_bytes()
    head, rows = page_table(html, "class-table")
    text = (tmp_path / "lib" / "class_check.csv").read_text(encoding="utf-8").splitlines()
    from crankbase.texts import texts

    tx = texts(lang)
    assert head == [tx(f"check.class.column.{k}") for k in text[0].split(",")]
    assert head[0] == {"en": "student", "ru": "студент"}[lang] and len(rows) == 2
    by = {r[0]: r for r in rows}
    assert by["petrov_v02.csv"][1:4] == ["v02", "1", "1"]
    assert by["ivanov_v01.xlsx"][1:4] == ["v01", "0", "0"]
    assert by["petrov_v02.csv"][4] == recs["petrov_v02.csv"]["verdict"] != \
        by["ivanov_v01.xlsx"][4]
    lines = htmllib.unescape(re.search(r'<pre id="class-verdict">(.*?)</pre>', html,
                                       re.S).group(1))
    assert str(app.root) not in html and "class_check.csv" in lines
    if lang == "ru":
        assert "ошибки" in html and not re.search(r"\b(wrong|right)\b", lines)
    else:
        assert "1 student is not right" in html
    z = zipfile.ZipFile(io.BytesIO(c.get(url.replace("class_check.csv",
                                                     "class_check.zip")).content))
    names = set(z.namelist())
    assert {"class_check.csv", "class_check.xlsx", "petrov_v02/check.csv",
            "ivanov_v01/check.csv", "ivanov_v01/ivanov_v01_checked.xlsx"} <= names, names
    assert z.read("petrov_v02/check.csv") == \
        (tmp_path / "lib" / "petrov_v02" / "check.csv").read_bytes()
    assert c.get(url.replace("class_check.csv", "class_check.xlsx")).content[:2] == b"PK"


@pytest.mark.parametrize("lang,words", [
    ("en", "not a plain file name of a workbook (.xlsx, .xlsm) or a CSV"),
    ("ru", "не простое имя файла книги (.xlsx, .xlsm) или CSV")])
def test_a_bad_student_file_is_named_at_its_field(app, class_inputs, lang, words):
    table, students = class_inputs
    good = [(p.name, p.read_bytes()) for p in sorted(students.iterdir())]
    c = client(app, lang)
    html = post_class(c, ("b.toml", PETROL.read_bytes()), ("v.csv", table.read_bytes()),
                      good + [("notes.txt", b"x"), ("../../etc/x.csv", b"alpha_deg\n1\n")])
    assert class_problems(html, "students") == [f"notes.txt: {words}",
                                                f"../../etc/x.csv: {words}"]
    assert 'id="class-result"' not in html
    html = post_class(c, ("b.toml", PETROL.read_bytes()), ("v.csv", b"variant\n"), good)
    assert class_problems(html, "variants") and 'id="class-result"' not in html
    html = post_class(c, ("b.toml", PETROL.read_bytes()), ("v.csv", table.read_bytes()),
                      good, rtol="-1")
    assert class_problems(html, "rtol")
    r = c.post("/teacher/class", files={"base": ("b.toml", PETROL.read_bytes(), "text/plain")})
    assert class_problems(r.text, "students") and class_problems(r.text, "variants")
    # a failed check leaves no folder of it behind
    folder = app.app.state.store.get(c.cookies["crankdyn_session"]).folder
    assert folder.is_dir() and not list(folder.iterdir())


# ----------------------------------------------------------------------------- torsion
@pytest.fixture(scope="module")
def torsion_page(app):
    """The torsion example loaded and computed with the option on: ``(client, html)``."""
    c = client(app, "en", "engine")
    html = c.post("/engine/example", data={"example": "torsion"}).text
    assert 'id="opt-torsion" checked' in html
    vals = form_values(html)
    assert vals["torsion.stiffnesses_Nm_rad"].startswith("900000.0, 750000.0")
    r = c.post("/engine/run", data={**vals, "torsion": "on"})
    assert r.status_code == 200 and 'id="results"' in r.text, r.text[:3000]
    return c, r.text


@pytest.fixture
def torsion_cli(tmp_path_factory, unrendered_figures):
    """``crankdyn engine examples/torsion_inline6.toml --torsion -o DIR --lang en``:
    ``(folder, printed text)``; its figures saved unrendered (conftest
    ``unrendered_figures``: its tables, workbook and text are compared; the page's
    figures are drawn in the app's render processes and read as PNG)."""
    import contextlib
    import io
    from types import SimpleNamespace

    from crankdyn.cli import main

    out = tmp_path_factory.mktemp("torsion_cli")
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main(["engine", str(TORSION), "--torsion", "-o", str(out),
                     "--lang", "en"]) == 0
    return SimpleNamespace(folder=out, out=buf.getvalue())


def test_the_torsion_files_equal_the_cli_s(torsion_page, torsion_cli):
    c, html = torsion_page
    cli = torsion_cli
    urls = links(html)
    names = {u.rsplit("/", 1)[1]: u for u in urls}
    want = sorted(p.name for p in cli.folder.glob("*_torsion*.csv")) + sorted(
        p.name for p in cli.folder.glob("*.csv") if p.stem.endswith(
            ("_holzer", "_torque_harmonics", "_critical_speeds")))
    assert "bmw-m54b30_torsion_modes.csv" in want and len(want) == 5
    for name in want:
        assert c.get(names[name]).content == (cli.folder / name).read_bytes(), name
    # the natural frequencies on the page are the CSV's text
    head, rows = page_table(html, "torsion-modes")
    text = (cli.folder / "bmw-m54b30_torsion_modes.csv").read_text().splitlines()
    assert ",".join(head) == text[0] and [",".join(r) for r in rows] == text[1:]
    # the torsion workbook: part for part (every sheet, cell and style; but its save time)
    assert workbook_parts(c.get(names["bmw-m54b30_torsion.xlsx"]).content) == \
        workbook_parts(cli.folder / "bmw-m54b30_torsion.xlsx")
    # the summary holds the CLI's torsion lines; the figures are shown and served
    summary = htmllib.unescape(re.search(r'<pre id="summary">(.*?)</pre>', html,
                                         re.S).group(1)).splitlines()
    tors = [ln for ln in cli.out.splitlines() if "natural frequenc" in ln
            or "critical speed" in ln]
    assert len(tors) >= 3 and all(ln in summary for ln in tors)
    figs = re.findall(r'<img src="(/engine/run/\d+/[^"]+\.png)"', html)
    for p in ("torsion_modes", "campbell", "torque_spectrum", "torsion_response",
              "torsion_angles"):
        (u,) = [f for f in figs if f.endswith(f"_{p}.png")]
        if p == "campbell":
            assert c.get(u).content[:8] == b"\x89PNG\r\n\x1a\n"
    # the zip of the report holds them too
    import io
    import zipfile

    z = zipfile.ZipFile(io.BytesIO(c.get(names["bmw-m54b30_report.zip"]).content))
    assert set(want) <= set(z.namelist())


def test_the_torsion_option_off_leaves_the_chain_out_and_on_needs_its_table(app):
    c = client(app, "en", "engine")
    vals = form_values(c.post("/engine/example", data={"example": "torsion"}).text)
    html = c.post("/engine/run", data=vals).text          # the option unticked
    assert 'id="results"' in html and "torsion_modes" not in html
    assert 'id="opt-torsion" checked' not in html
    assert vals["torsion.throw_J_kgm2"] in html           # the fields are kept
    vals = form_values(c.post("/engine/example", data={"example": "petrol"}).text)
    assert not any(v for k, v in vals.items() if k.startswith("torsion."))
    html = c.post("/engine/run", data={**vals, "torsion": "on"}).text
    assert 'id="results"' not in html and "[torsion]" in htmllib.unescape(
        re.search(r'<div class="problems" id="problems">(.*?)</div>', html, re.S).group(1))


@pytest.mark.parametrize("lang,words", [("en", "must be > 0"), ("ru", "должно быть > 0")])
def test_a_bad_stiffness_is_named_next_to_its_field(app, lang, words):
    c = client(app, lang, "engine")
    vals = form_values(c.post("/engine/example", data={"example": "torsion"}).text)
    k = vals["torsion.stiffnesses_Nm_rad"].split(", ")
    k[2] = "0"
    vals["torsion.stiffnesses_Nm_rad"] = ", ".join(k)
    html = c.post("/engine/run", data={**vals, "torsion": "on"}).text
    assert 'id="results"' not in html
    (msg,) = re.findall(r'<p class="problem" id="err-torsion.stiffnesses_Nm_rad">([^<]*)</p>',
                        html)
    msg = htmllib.unescape(msg)
    assert msg.startswith("torsion.stiffnesses_Nm_rad[2]") and words in msg, msg
    assert 'class="field bad" id="field-torsion.stiffnesses_Nm_rad"' in html
