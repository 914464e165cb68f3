"""The synthesis page (``/synth``) and the plans sheet on the linkage page, through
Starlette's TestClient (issue #22).

The reference of every number is the command line on the same inputs: ``crankdyn synth``
for the synthesis page (the page and the command call the same check and the same study,
so their CSVs must be byte-identical and their problems the same words), ``crankdyn
linkage --plans`` for the plans sheet.
"""
from __future__ import annotations

import csv
import html as htmllib
import re
import shlex

import pytest

pytest.importorskip("starlette")
from starlette.testclient import TestClient  # noqa: E402

from test_web import form_values, shared  # noqa: E402
from test_web import page_table as raw_table  # noqa: E402

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


def client(app, lang="en"):
    c = TestClient(app)
    c.get(f"/synth?lang={lang}")
    return c


def downloads(c, html, page):
    urls = re.findall(rf'href="(/{page}/run/\d+/[^"]+)"', html)
    return {u.rsplit("/", 1)[1]: c.get(u).content for u in urls}


def page_table(html, table_id="table2"):
    """A table of the page as text (the HTML's escapes read back)."""
    head, rows = raw_table(html, table_id)
    return ([htmllib.unescape(h) for h in head],
            [[htmllib.unescape(c) for c in row] for row in rows])


def csv_rows(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.reader(fh))


# ----------------------------------------------------------------------------- synthesis
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_synthesis_form_shows_every_input_with_its_words(app, lang):
    from linkage.synthesis_study import INPUTS

    html = client(app, lang).get("/synth").text
    assert 'id="nav-synth"' in html
    for k in INPUTS.keys():
        field = re.search(rf'<div class="field" id="field-synth\.{k.name}">(.*?)</div>',
                          html, re.S).group(1)
        text = htmllib.unescape(field)
        assert k.label(lang) in text and k.help(lang) in text, k.name
        if k.symbol:
            assert k.symbol_text(lang) in text
        if k.unit:
            assert k.unit_text(lang) in text
    mu = htmllib.unescape(re.search(r'id="field-synth\.mu_min_deg">(.*?)</div>', html,
                                    re.S).group(1))
    assert "[0, 90)" in mu                    # the range from the schema
    if lang == "ru":
        assert "угол передачи" in mu


def test_the_synthesis_page_gives_the_numbers_of_crankdyn_synth(app, tmp_path):
    """The README's task with a changed λ2 and μmin: every CSV and the spec for
    ``crankdyn linkage`` byte for byte equal to ``crankdyn synth`` on the same inputs,
    the page's tables the CSV's text, and the command line the page shows repeats it."""
    from crankdyn.cli import main

    c = client(app)
    c.post("/synth/example", data={"example": "readme"})
    vals = form_values(c.get("/synth").text)
    assert (vals["synth.l2"], vals["synth.mu_min_deg"], vals["synth.ground_m"]) == (
        "0.8", "40", "0.5")
    vals["synth.l2"], vals["synth.mu_min_deg"] = "0.85", "35"
    r = c.post("/synth/run", data=vals)
    assert 'id="results"' in r.text, r.text[:3000]
    got = downloads(c, r.text, "synth")
    out = tmp_path / "cli"
    assert main(["synth", "--l2", "0.85", "--mu-min", "35", "--ground", "0.5", "--lang", "en",
                 "-o", str(out), "--no-plots"]) == 0
    names = ["kkm-30_table1.csv", "kkm-30_mechanism.csv", "kkm-30_transmission_angle.csv",
             "kkm-30.toml"]
    for name in names:
        assert got[name] == (out / name).read_bytes(), name
    head, rows = page_table(r.text)
    assert [head, *rows] == csv_rows(out / "kkm-30_table1.csv")
    head2, rows2 = page_table(r.text, "table2-form")
    assert [head2, *rows2] == csv_rows(out / "kkm-30_mechanism.csv")
    # the summary is the command's own (its numbers, less the "wrote" line)
    summary = htmllib.unescape(re.search(r'<pre id="summary">(.*?)</pre>', r.text,
                                         re.S).group(1))
    assert "λ2 = 0.8500" in summary and "μmin" in summary
    # the command line shown repeats the run
    command = htmllib.unescape(re.search(r'<pre id="command">(.*?)</pre>', r.text).group(1))
    argv = shlex.split(command)
    assert argv[:2] == ["crankdyn", "synth"] and argv[argv.index("--mu-min") + 1] == "35"
    again = tmp_path / "again"
    argv[argv.index("-o") + 1] = str(again)
    assert main(argv[1:] + ["--no-plots"]) == 0
    for name in names:
        assert (again / name).read_bytes() == got[name], name
    # the figures, the workbook, the inputs' spec (upload it again: the same run)
    figs = re.findall(r'<img src="(/synth/run/\d+/[^"]+\.png)"', r.text)
    assert len(figs) == 3 and all(c.get(u).content[:4] == b"\x89PNG" for u in figs)
    assert got["kkm-30_synthesis.xlsx"][:2] == b"PK" and got["kkm-30_report.zip"][:2] == b"PK"
    assert "mu_min_deg = 35" in got["kkm-30_synth.toml"].decode()
    r2 = c.post("/synth/upload", files={"spec": ("x.toml", got["kkm-30_synth.toml"])})
    assert downloads(c, r2.text, "synth")["kkm-30_mechanism.csv"] == got["kkm-30_mechanism.csv"]


@pytest.mark.parametrize("lang, valid", [("en", "must be an angle in degrees, 0 <= mu_min < 90"),
                                         ("ru", "должно быть углом в градусах, 0 <= mu_min < 90")])
def test_a_bad_mu_min_stands_at_its_field_and_nothing_is_computed(app, lang, valid,
                                                                   monkeypatch, capsys,
                                                                   tmp_path):
    """μmin = 95°: the command's own words at the field, in the page's language; the
    study is never called."""
    import linkage.synthesis_study as study
    from crankdyn.cli import main

    calls = []
    real = study.run_study
    monkeypatch.setattr(study, "run_study", lambda *a, **k: calls.append(1) or real(*a, **k))
    c = client(app, lang)
    c.post("/synth/example", data={"example": "readme"})
    vals = form_values(c.get("/synth").text)
    vals["synth.mu_min_deg"] = "95"
    html = c.post("/synth/run", data=vals).text
    assert 'id="results"' not in html and calls == []
    msg = htmllib.unescape(re.search(r'id="err-synth.mu_min_deg">([^<]*)<', html).group(1))
    assert msg == f"synth.mu_min_deg: получено 95; {valid}" if lang == "ru" else \
        msg == f"synth.mu_min_deg: got 95; {valid}"
    assert 'class="field bad" id="field-synth.mu_min_deg"' in html
    # the command line says the same words of its option
    assert main(["synth", "--l2", "0.8", "--mu-min", "95", "--lang", lang,
                 "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert f"--mu-min: {msg.split(': ', 1)[1]}" in err
    # a wrong set of lengths: above the form, naming the fields; still nothing computed
    vals["synth.mu_min_deg"], vals["synth.l3"] = "40", "0.5"
    vals["synth.l2"] = ""
    html = c.post("/synth/run", data=vals).text
    general = htmllib.unescape(re.search(r'<li class="problem">([^<]*)</li>', html).group(1))
    assert "synth.l3 synth.mu_min_deg" in general and calls == []


# ----------------------------------------------------------------------------- plans
@pytest.mark.parametrize("example, stem, positions", [("shaper", "shaper", "2,5"),
                                                      ("ratchet", "ratchet-drive", "5")])
def test_the_linkage_page_writes_the_plans_sheet_like_the_cli(app, cli_report, example,
                                                              stem, positions):
    """Positions for the plans on a chain (the shaper) and a four-bar: the sheet's PDF
    and DXF offered, its PNG preview shown, the plans CSV and the kinematics (the chain's
    form read back) byte for byte the command's (run with ``--no-plots``: only its CSVs
    are compared; the page's sheet, plans and figures are its own, drawn)."""
    c = client(app)
    c.post("/linkage/example", data={"example": example})
    vals = form_values(c.get("/linkage").text)
    vals["plans"], vals["sheet"] = positions, "A3"
    r = c.post("/linkage/run", data=vals)
    assert 'id="results"' in r.text, r.text[:3000]
    got = downloads(c, r.text, "linkage")
    assert got[f"{stem}_sheet.pdf"][:5] == b"%PDF-"
    assert b"SECTION" in got[f"{stem}_sheet.dxf"][:200]
    base = shared(cli_report("linkage", "--example", example, "--plans", positions,
                             "--sheet", "A3", "--lang", "en", "--no-plots"))
    for name in (f"{stem}_plans.csv", f"{stem}_student_table.csv", f"{stem}_kinematics.csv",
                 f"{stem}_forces.csv"):
        assert got[name] == (base / name).read_bytes(), name
    figs = re.findall(r'<img src="(/linkage/run/\d+/[^"]+\.png)"', r.text)
    assert any(f.endswith(f"{stem}_sheet.png") for f in figs), figs
    assert c.get(next(f for f in figs if f.endswith("_sheet.png"))).content[:4] == b"\x89PNG"
    for tag in positions.split(","):
        assert f"{stem}_plans_{tag}.pdf" in got
    assert 'id="drawings"' in r.text


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_bad_position_list_stands_at_its_field(app, lang):
    c = client(app, lang)
    c.post("/linkage/example", data={"example": "press6"})
    vals = form_values(c.get("/linkage").text)
    vals["plans"] = "2,x"
    html = c.post("/linkage/run", data=vals).text
    assert 'id="results"' not in html
    msg = htmllib.unescape(re.search(r'id="err-plans">([^<]*)<', html).group(1))
    assert "'x'" in msg and ("5,11" in msg)
    assert ("получено" in msg) if lang == "ru" else ("got" in msg)
    assert 'class="field bad" id="field-plans"' in html


# ----------------------------------------------------------------------------- the one check
def test_check_inputs_reads_texts_and_numbers_alike_and_names_each_problem():
    """The library's check of ``crankdyn synth`` and the page: a text and a number give
    the same value; each problem is named as the caller names the input."""
    from crankbase.errors import SpecError
    from linkage.synthesis_study import FLAGS, check_inputs, command_line, option

    a, mode = check_inputs({"l2": "0.8", "mu_min_deg": "40", "ground_m": "0.5"})
    b, _ = check_inputs({"l2": 0.8, "mu_min_deg": 40, "ground_m": 0.5})
    assert a == b and mode == "mu_min" and a["phi0_deg"] == 30.0 and a["l1"] is None
    assert check_inputs({"l1": 0.15})[1] == "l1"
    assert check_inputs({"l2": 0.9, "l3": 0.5})[1] == "l2_l3"
    assert check_inputs({})[1] == "region"
    assert command_line(a, "en") == ("crankdyn synth --phi0 30 --l2 0.8 --mu-min 40 "
                                     "--ground 0.5 --lang en -o OUT")
    with pytest.raises(SpecError) as e:
        check_inputs({"phi0_deg": "180", "l1": 0.1, "l3": "-1", "omega_rad_s": 0,
                      "l1_step": "0.01"}, {**{k: option(k) for k in FLAGS}, "mode": "options"})
    lines = e.value.lines("en")
    keys = [ln.split(": ")[0] for ln in lines]
    assert keys == ["--phi0", "--l3", "--omega", "options", "--l1-step", "--omega"], lines
    assert "got --l1 --l3; choose one of: --l2 and --l3, --l1 alone" in lines[3]
    with pytest.raises(SpecError) as e:
        check_inputs({"mu_min_deg": "40,5"})
    assert e.value.lines("en")[0].startswith("mu_min_deg: got '40,5'; must be a number")
