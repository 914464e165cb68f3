"""The dynamics and balance pages on a linkage or an engine (issue #22) through Starlette's
TestClient: the bundled examples of ``crankdyn dynamics`` (press, shaper, petrol) and
``crankdyn balance`` (ratchet, shaper) run through the page's form, an engine spec with
``[dynamics]`` uploaded with its pressure file, a bad ``[dynamics]`` value next to its
field.

The reference of every number is the CLI on the same example (``crankdyn dynamics
--example NAME``, ``crankdyn balance --example NAME``): the page computes through the same
library calls, so its CSVs must be byte-identical, its workbook the same file (but for the
time of its save, ``test_web.workbook_parts``) and
its tables the CSV's text.  One page run per example (a module fixture), its figures PNG.
"""
from __future__ import annotations

import csv
import html as htmllib
import re

import pytest

pytest.importorskip("starlette")  # the test extra installs it; a bare core install skips
from starlette.testclient import TestClient  # noqa: E402

from crankbase.resources import example_path  # noqa: E402
from test_web import form_values, workbook_parts  # noqa: E402

CYRILLIC = re.compile("[А-Яа-яЁё]")

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


def client(app, page, lang="en"):
    c = TestClient(app)
    c.get(f"/{page}?lang={lang}")
    return c




def page_table(html, table_id):
    body = re.search(rf'<table id="{table_id}".*?</table>', html, re.S).group(0)
    head = [htmllib.unescape(h) for h in re.findall(r"<th>([^<]*)</th>", body)]
    rows = [[htmllib.unescape(c) for c in re.findall(r"<td>([^<]*)</td>", r)]
            for r in re.findall(r"<tr>(.*?)</tr>", body, re.S)]
    return head, [r for r in rows if r]


def downloads(c, page, html):
    """``{file name: bytes}`` of every file the results offer (links and figures)."""
    urls = set(re.findall(rf'(?:href|src)="(/{page}/run/\d+/[^"]+)"', html))
    return {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}


def shared(rep):
    assert rep.rc == 0, rep.err
    return rep.folder


def run_example(app, page, name, lang="en"):
    """The example loaded, its form posted as the page shows it: ``(html, files, vals)``."""
    c = client(app, page, lang)
    r = c.post(f"/{page}/example", data={"example": name})
    assert r.status_code == 200 and 'id="notice"' in r.text
    vals = form_values(r.text)
    r = c.post(f"/{page}/run", data=vals)
    assert 'id="results"' in r.text, r.text[:3000]
    return r.text, downloads(c, page, r.text), vals


def csv_rows(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.reader(fh))


@pytest.fixture(scope="module")
def dyn_press(app):
    return run_example(app, "dynamics", "press")


@pytest.fixture(scope="module")
def dyn_shaper(app):
    return run_example(app, "dynamics", "shaper")


@pytest.fixture(scope="module")
def dyn_petrol(app):
    return run_example(app, "dynamics", "petrol")


@pytest.fixture(scope="module")
def bal_ratchet(app):
    return run_example(app, "balance", "ratchet")


@pytest.fixture(scope="module")
def bal_shaper(app):
    return run_example(app, "balance", "shaper")


# ----------------------------------------------------------------------------- dynamics
@pytest.mark.parametrize("example,fixture,form_key", [
    ("press", "dyn_press", "mechanism.offset"),           # a four-bar's form
    ("shaper", "dyn_shaper", "links.lever.points"),       # a chain's form
    ("petrol", "dyn_petrol", "pressure.cycle.pz_MPa"),    # an engine's form
])
def test_the_dynamics_page_runs_the_cli_s_example(request, cli_report, example, fixture,
                                                  form_key):
    """Every CSV byte for byte and the workbook part for part equal to ``crankdyn
    dynamics --example NAME``; the tables on the page are the CSVs' text; the form is the
    spec's kind's with ``[dynamics]``; the summary is the CLI's."""
    html, got, vals = request.getfixturevalue(fixture)
    rep = cli_report("dynamics", "--example", example, "--lang", "en")
    cli = shared(rep)
    assert form_key in vals and "dynamics.delta" in vals and "machine.name" not in vals
    csvs = sorted(p.name for p in cli.glob("*.csv"))
    assert len(csvs) >= 2 and sorted(n for n in got if n.endswith(".csv")) == csvs
    for n in csvs:
        assert got[n] == (cli / n).read_bytes(), n
    xlsx = next(p.name for p in cli.glob("*.xlsx"))
    assert workbook_parts(got[xlsx]) == workbook_parts(cli / xlsx)
    motion = next(n for n in csvs if n.endswith("_motion.csv")
                  and not n.endswith("_true_motion.csv"))
    head, rows = page_table(html, "table2")
    assert [head, *rows] == csv_rows(cli / motion)[:len(rows) + 1] and len(rows) >= 100
    forces = next(n for n in csvs if n.endswith("_forces_true_motion.csv"))
    head2, rows2 = page_table(html, "table2-form")
    assert [head2, *rows2] == csv_rows(cli / forces)[:len(rows2) + 1]
    assert forces in html                    # its heading names the file
    summary = htmllib.unescape(re.search(r'<pre id="summary">(.*?)</pre>', html, re.S)
                               .group(1)).strip().splitlines()
    assert summary == rep.out.strip().splitlines()[:len(summary)] and len(summary) >= 3
    pngs = sorted(p.name for p in cli.glob("*.png"))
    assert pngs and all(got.get(n, b"")[:4] == b"\x89PNG" for n in pngs)


def test_the_dynamics_page_s_spec_repeats_the_run(dyn_shaper, cli_report):
    """The downloaded spec of the shaper's run repeats the run: it is the example's own
    spec (the chain's [[group]] and [dynamics] round-trip through the form), read as the
    same dict, and ``crankdyn dynamics`` computes a spec from that dict (the shaper names
    no other file), so ``crankdyn dynamics`` on it is the session's shared run of
    ``--example shaper``, whose CSVs are the page's byte for byte.  (Before: the command
    run again on the downloaded file, a second computation of the chain's dynamics.)"""
    import tomllib

    html, got, _ = dyn_shaper
    data = tomllib.loads(got["shaper-machine.toml"].decode("utf-8"))
    assert data["mechanism"]["kind"] == "chain" and len(data["group"]) == 2
    assert data["dynamics"] == {"driving": "motor", "motor_start_torque_Nm": 2000.0,
                                "motor_sync_speed_rad_s": 6.6, "delta": 0.05}
    assert data == tomllib.loads(example_path("shaper_dynamics.toml").read_text(
        encoding="utf-8"))
    assert not any(k in str(data) for k in ("file", ".csv", ".ind"))   # no other file
    cli = shared(cli_report("dynamics", "--example", "shaper", "--lang", "en"))
    csvs = list(cli.glob("*.csv"))
    assert len(csvs) >= 2
    for p in csvs:
        assert got[p.name] == p.read_bytes(), p.name


def test_an_engine_spec_with_dynamics_uploaded_with_its_pressure_file(app, tmp_path,
                                                                     unrendered_figures):
    """The diesel D-240 (its indicator table a CSV) with a [dynamics] table, uploaded under
    the user's names: the CSVs equal ``crankdyn dynamics`` on the same two files (whose
    figures are saved unrendered: the CSVs are compared); the run's downloads hold the
    pressure file under the server's name."""
    import shutil

    from crankdyn.cli import main

    text = example_path("diesel_d240.toml").read_text(encoding="utf-8") + (
        "\n[dynamics]\ndriving = \"constant\"\ndelta = 0.02\nJ_engine_extra_kgm2 = 0.1\n")
    raw = example_path("diesel_d240_indicator.csv").read_bytes()
    c = client(app, "dynamics")
    r = c.post("/dynamics/upload", files={
        "spec": ("my diesel.toml", text.encode("utf-8"), "application/toml"),
        "pressure": ("indicator (1).csv", raw, "text/csv")})
    assert 'id="results"' in r.text, r.text[:3000]
    vals = form_values(r.text)
    assert vals["pressure_source"] == "file" and vals["dynamics.delta"] == "0.02"
    got = downloads(c, "dynamics", r.text)
    assert got["pressure.csv"] == raw
    (tmp_path / "diesel.toml").write_text(text, encoding="utf-8")
    shutil.copy(example_path("diesel_d240_indicator.csv"), tmp_path)
    out = tmp_path / "cli"
    assert main(["dynamics", str(tmp_path / "diesel.toml"), "-o", str(out),
                 "--lang", "en"]) == 0
    csvs = sorted(p.name for p in out.glob("*.csv"))
    assert "diesel-d240_forces_true_motion.csv" in csvs
    for n in csvs:
        assert got[n] == (out / n).read_bytes(), n
    # the form's run with the same file (kept by the session) gives the same numbers
    r = c.post("/dynamics/run", data=vals)
    again = downloads(c, "dynamics", r.text)
    assert all(again[n] == got[n] for n in csvs)
    # without the file the upload says which file is missing, at the file's field
    c2 = client(app, "dynamics")
    r = c2.post("/dynamics/upload", files={
        "spec": ("my diesel.toml", text.encode("utf-8"), "application/toml")})
    assert 'id="results"' not in r.text
    assert "diesel_d240_indicator.csv" in htmllib.unescape(
        re.search(r'id="err-pressure.file">([^<]*)<', r.text).group(1))


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_bad_dynamics_value_of_an_uploaded_linkage_stands_at_its_field(app, lang):
    """The press with δ = 2 (δ < 1) and an unknown driving: both problems next to their
    fields of the linkage form's [dynamics], in the page's language; no results."""
    text = example_path("press_dynamics.toml").read_text(encoding="utf-8")
    text = text.replace("delta = 0.05", "delta = 2").replace('driving = "motor"',
                                                             'driving = "turbine"')
    c = client(app, "dynamics", lang)
    r = c.post("/dynamics/upload", files={
        "spec": ("press.toml", text.encode("utf-8"), "application/toml")})
    html = r.text
    assert 'id="results"' not in html
    assert 'id="mechanism.crank"' in html and 'id="links.slider.mass_kg"' in html
    delta = htmllib.unescape(re.search(r'id="err-dynamics.delta">([^<]*)<', html).group(1))
    driving = htmllib.unescape(re.search(r'id="err-dynamics.driving">([^<]*)<', html)
                               .group(1))
    assert "dynamics.delta" in delta and "2" in delta and "< 1" in delta
    assert "turbine" in driving and "motor" in driving
    for msg in (delta, driving):
        assert bool(CYRILLIC.search(msg)) == (lang == "ru"), msg
    vals = form_values(html)
    assert vals["dynamics.delta"] == "2" and vals["mechanism.crank"] == "0.08"


# ----------------------------------------------------------------------------- balance
@pytest.mark.parametrize("example,fixture", [("ratchet", "bal_ratchet"),
                                             ("shaper", "bal_shaper")])
def test_the_balance_page_runs_the_cli_s_linkage_example(request, cli_report, example,
                                                         fixture):
    """The counterweights and the shaking force byte for byte ``crankdyn balance --example
    NAME``'s; the page's tables their text; the summary the CLI's."""
    html, got, vals = request.getfixturevalue(fixture)
    rep = cli_report("balance", "--example", example, "--lang", "en")
    cli = shared(rep)
    csvs = sorted(p.name for p in cli.glob("*.csv"))
    assert len(csvs) == 2 and sorted(n for n in got if n.endswith(".csv")) == csvs
    for n in csvs:
        assert got[n] == (cli / n).read_bytes(), n
    cw = next(n for n in csvs if n.endswith("_counterweights.csv"))
    head, rows = page_table(html, "table2")
    assert [head, *rows] == csv_rows(cli / cw)
    shaking = next(n for n in csvs if n.endswith("_shaking.csv"))
    head2, rows2 = page_table(html, "table2-form")
    assert [head2, *rows2] == csv_rows(cli / shaking) and len(rows2) == 361   # 0..360°
    summary = htmllib.unescape(re.search(r'<pre id="summary">(.*?)</pre>', html, re.S)
                               .group(1)).strip().splitlines()
    assert summary == rep.out.strip().splitlines()[:len(summary)] and len(summary) >= 2
    pngs = sorted(p.name for p in cli.glob("*.png"))
    assert len(pngs) == 2 and all(got.get(n, b"")[:4] == b"\x89PNG" for n in pngs)
    assert "mechanism.crank" in vals and "rotor.planes_mm" not in vals


def test_the_ratchet_s_counterweight_radius_round_trips_through_the_form(bal_ratchet):
    """The ratchet's [balance] radius_crank_m = 0.05 m is a field of the form and reaches
    the run: the crank's counterweight stands at 0.05 m, its mass m·r / 0.05."""
    html, got, vals = bal_ratchet
    assert vals["balance.radius_crank_m"] == "0.05" and vals["balance.radius_m"] == ""
    rows = {r["link"]: r for r in csv.DictReader(
        got["ratchet-drive_counterweights.csv"].decode("utf-8").splitlines())}
    assert float(rows["crank"]["radius_m"]) == 0.05
    assert float(rows["crank"]["mass_kg"]) == pytest.approx(
        float(rows["crank"]["mr_kgm"]) / 0.05, rel=1e-12)
    assert float(rows["rocker"]["radius_m"]) == 0.325        # default: the rocker length


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_balance_key_of_another_kind_stands_at_its_field(app, lang):
    """The ratchet (a crank-rocker) posted with a crank-slider's fraction: the library's
    problem next to the field balance.fraction, in the page's language."""
    c = client(app, "balance", lang)
    r = c.post("/balance/example", data={"example": "ratchet"})
    vals = form_values(r.text)
    vals["balance.fraction"] = "0.5"
    html = c.post("/balance/run", data=vals).text
    assert 'id="results"' not in html
    msg = htmllib.unescape(re.search(r'id="err-balance.fraction">([^<]*)<', html).group(1))
    assert "radius_crank_m" in msg and bool(CYRILLIC.search(msg)) == (lang == "ru"), msg
