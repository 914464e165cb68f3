"""``crankdyn serve`` in a real browser: Debian's headless Chromium driven by Selenium.

One server (uvicorn in a thread, on a free port of 127.0.0.1, serving the session's app)
and one browser for the module.  The browser loads the petrol example, changes the speed,
computes, and the first rows of Table 2 on the page must be the CLI's ``forces.csv`` for
the same spec; the workbook it downloads must equal the CLI's part for part (but its save
time); a bad bore is named next to its field.  Where the browser cannot start, the test
fails: CI installs ``chromium`` and ``chromium-driver`` (.ci/run).  With ``CRANKDYN_SCREENSHOTS=DIR`` the page's screenshots
are kept in DIR (the README's, in docs/).
"""
from __future__ import annotations

import csv
import os
import socket
import threading
import time
import tomllib
from pathlib import Path

import pytest

from crankbase.resources import example_path
from test_web import workbook_parts

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
SPEED = "4000.0"

#: Every web test module runs on one xdist worker (``--dist loadgroup``), with one app
#: (tests/conftest.py ``web_app_kept``): the studies and drawings one module asks for are
#: not computed and drawn again for another, and the app's drawing processes start once.
#: (A module-level mark: the group is known when xdist names the tests.)
pytestmark = pytest.mark.xdist_group("web")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def server(web_app_kept):
    """The session's app (tests/conftest.py ``web_app_kept``: its render processes already
    started when another web module ran first) served by uvicorn; without its lifespan,
    whose end would close the app's pools for the modules after this one."""
    import uvicorn

    port = _free_port()
    config = uvicorn.Config(web_app_kept, host="127.0.0.1", port=port, log_level="warning",
                            lifespan="off")
    srv = uvicorn.Server(config)
    th = threading.Thread(target=srv.run, daemon=True)
    th.start()
    for _ in range(200):
        if srv.started:
            break
        time.sleep(0.05)
    assert srv.started, "the web app did not start"
    yield f"http://127.0.0.1:{port}"
    srv.should_exit = True
    th.join(10)


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    assert Path(CHROMIUM).is_file() and Path(CHROMEDRIVER).is_file(), (
        "the browser test needs Debian's chromium and chromium-driver: "
        "apt-get install -y chromium chromium-driver")
    downloads = tmp_path_factory.mktemp("downloads")
    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync",
                 "--disable-dev-shm-usage", "--window-size=1400,1000",
                 f"--user-data-dir={tmp_path_factory.mktemp('chromium-profile')}"):
        opts.add_argument(flag)
    opts.add_experimental_option("prefs", {
        "download.default_directory": str(downloads), "download.prompt_for_download": False,
        "safebrowsing.enabled": False})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=opts)
    driver.downloads = downloads
    yield driver
    driver.quit()


def _wait(driver, cond, timeout=60):
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(driver, timeout).until(cond)


def _by_id(driver, id_, timeout=60):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support import expected_conditions as EC

    return _wait(driver, EC.presence_of_element_located((By.ID, id_)), timeout)


def _settled_text(driver, id_, text, timeout=60):
    """Wait until element ``id_`` of the page now shown holds ``text`` (found anew at each
    poll: the page that held it before the submit may still be on screen, and its element
    goes stale when the answer arrives); the caller then asserts the text, so a wrong one
    fails with what the page says."""
    from selenium.common.exceptions import TimeoutException
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support import expected_conditions as EC

    try:
        _wait(driver, EC.text_to_be_present_in_element((By.ID, id_), text), timeout)
    except TimeoutException:
        pass


def _images_loaded(driver):
    return driver.execute_script(
        "return [...document.images].every(i => i.complete && i.naturalWidth > 0)")


def _shot(driver, name, tmp_path):
    folder = Path(os.environ.get("CRANKDYN_SCREENSHOTS") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    assert driver.save_screenshot(str(path)) and path.stat().st_size > 10_000
    return path


def _shared(rep) -> Path:
    """The folder of a session-shared CLI report (conftest ``cli_report``: read-only)."""
    assert rep.rc == 0, rep.err
    return rep.folder


def _compute(driver, speed=None):
    from selenium.webdriver.common.by import By

    if speed is not None:
        box = driver.find_element(By.ID, "engine.speed_rpm")
        box.clear()
        box.send_keys(speed)
    old = driver.find_elements(By.ID, "results")
    driver.find_element(By.ID, "compute").click()
    if old:
        _wait(driver, lambda d: not _stale_check(old[0]))
    _by_id(driver, "table2")


def _stale_check(el):
    from selenium.common.exceptions import StaleElementReferenceException

    try:
        el.tag_name
        return True
    except StaleElementReferenceException:
        return False


# The text of a table's cells read in the page by one script, as WebDriver's element text
# reads it (the rendered text, trimmed; a cell not shown reads ""): one call instead of
# one per cell (a row of 47 cells asked cell by cell costs 47 round trips through
# chromedriver and the browser, with Selenium's visible-text script run for each).
_CELLS_JS = """
const [table, rows, cell] = arguments;
const text = (el) => (el.checkVisibility() ? el.innerText : "").trim();
if (rows === null) return [...table.querySelectorAll(cell)].map(text);
return [...table.querySelectorAll(rows)].map(
    (tr) => [...tr.querySelectorAll(cell)].map(text));
"""


def _head(table):
    """The text of a table's column heads."""
    return table.parent.execute_script(_CELLS_JS, table, None, "thead th")


def _first_rows(table, n=None):
    """The text of the cells of the first ``n`` rows (all with ``n=None``) of a table on
    the page: only those rows read (a results table holds up to 1000 rows of up to 47
    cells; reading every row costs the browser more than reading the few compared)."""
    rows = "tbody tr" if n is None else f"tbody tr:nth-child(-n+{n})"
    return table.parent.execute_script(_CELLS_JS, table, rows, "td")


def _example_in(driver, server, page, example, lang, first):
    """The page in ``lang`` with ``example``'s values on its form.  The ``first``
    language opens the page and loads the example; a next one switches the page's
    language with its own link (``lang-<lang>``: the session keeps the example's values
    and its last results), as a student changing the language does, without loading the
    example again (each load of a page showing a run's tables, up to 1000 rows of up to
    47 cells, costs the browser a second or two of CPU)."""
    from selenium.webdriver.common.by import By

    if first:
        driver.get(server + f"/{page}?lang={lang}")
        driver.find_element(By.ID, f"example-{example}").click()
        _by_id(driver, "notice")
        return
    driver.find_element(By.ID, f"lang-{lang}").click()
    _wait(driver, lambda d: d.find_element(By.TAG_NAME, "html").get_attribute("lang") == lang)
    assert driver.find_element(By.ID, f"lang-{lang}").get_attribute("class") == "active"


def test_the_petrol_example_in_the_browser_equals_the_cli(server, browser, tmp_path,
                                                          petrol_at_4000_tables):
    from selenium.webdriver.common.by import By

    d = browser
    d.get(server + "/engine?lang=en")
    d.find_element(By.ID, "example-petrol").click()
    _by_id(d, "notice")
    assert d.find_element(By.ID, "engine.speed_rpm").get_attribute("value") == "5400.0"
    _compute(d, SPEED)
    # Table 2's first rows on the page = the CLI's forces.csv for the same spec
    spec = tomllib.loads(example_path("petrol_vaz2106.toml").read_text(encoding="utf-8"))
    spec["engine"]["speed_rpm"] = float(SPEED)
    shared_spec, report = petrol_at_4000_tables         # the session's spec and CLI run
    assert shared_spec == spec
    cli = _shared(report)
    with open(cli / "petrol-vaz2106_forces.csv", newline="") as fh:
        want = list(csv.reader(fh))
    table = d.find_element(By.ID, "table2")
    head = _head(table)
    rows = _first_rows(table, 5)
    assert head == want[0]
    assert rows == want[1:6]
    assert float(rows[0][head.index("Pj_N")]) != 0.0
    assert "n = 4000 rpm" in d.find_element(By.ID, "summary").text
    # every figure is shown
    _wait(d, _images_loaded)
    assert len(d.find_elements(By.CSS_SELECTOR, "#figures img")) == 13
    d.execute_script("document.getElementById('results').scrollIntoView()")
    _shot(d, "web_engine_results_en.png", tmp_path)
    d.execute_script("document.getElementById('figures').scrollIntoView()")
    _shot(d, "web_engine_figures_en.png", tmp_path)
    # the workbook, downloaded by the browser, equals the CLI's part for part (every
    # sheet, cell and style; but the time of its save: test_web.workbook_parts)
    d.find_element(By.ID, "dl-xlsx").click()
    target = d.downloads / "petrol-vaz2106.xlsx"
    _wait(d, lambda _d: target.is_file() and not list(d.downloads.glob("*.crdownload")))
    assert workbook_parts(target) == workbook_parts(cli / "petrol-vaz2106.xlsx")


@pytest.mark.parametrize("lang,words", [("en", "must be > 0"), ("ru", "должно быть > 0")])
def test_a_bad_bore_is_named_next_to_its_field_in_the_browser(server, browser, tmp_path,
                                                              lang, words):
    from selenium.webdriver.common.by import By

    d = browser
    d.get(server + f"/engine?lang={lang}")
    d.find_element(By.ID, "example-petrol").click()
    _by_id(d, "notice")
    if lang == "ru":                    # the results page in Russian, for its screenshot
        _compute(d)
        _wait(d, _images_loaded)
        d.execute_script("document.getElementById('results').scrollIntoView()")
        assert "Таблица 2" in d.find_element(By.ID, "results").text
        _shot(d, "web_engine_results_ru.png", tmp_path)
    box = d.find_element(By.ID, "engine.bore_mm")
    box.clear()
    box.send_keys("-5")
    d.find_element(By.ID, "compute").click()
    err = _by_id(d, "err-engine.bore_mm")
    field = d.find_element(By.ID, "field-engine.bore_mm")
    assert err in field.find_elements(By.CLASS_NAME, "problem")
    assert "engine.bore_mm" in err.text and "-5" in err.text and words in err.text
    assert not d.find_elements(By.ID, "results")
    d.execute_script("document.getElementById('field-engine.bore_mm')"
                     ".scrollIntoView({block: 'center'})")
    _shot(d, f"web_engine_form_{lang}.png", tmp_path)


def test_the_linkage_page_in_the_browser(server, browser, tmp_path, cli_report):
    """The ratchet drive: its kinematics table on the page is the CLI's, in both
    languages; the screenshots of the page."""
    from selenium.webdriver.common.by import By

    # only its kinematics.csv is read: the session's run without figures
    out = _shared(cli_report("linkage", "--example", "ratchet", "--no-plots", "--lang", "en"))
    with open(out / "ratchet-drive_kinematics.csv", newline="") as fh:
        want = list(csv.reader(fh))
    d = browser
    for lang in ("en", "ru"):
        _example_in(d, server, "linkage", "ratchet", lang, first=lang == "en")
        _compute(d)
        table = d.find_element(By.ID, "table2")
        head = _head(table)
        rows = _first_rows(table, 3)
        assert head == want[0] and rows == want[1:4]
        _wait(d, _images_loaded)
        assert len(d.find_elements(By.CSS_SELECTOR, "#figures img")) == 5
        d.execute_script("document.getElementById('results').scrollIntoView()")
        _shot(d, f"web_linkage_results_{lang}.png", tmp_path)


def test_the_synthesis_page_in_the_browser(server, browser, tmp_path, cli_report):
    """The README's synthesis (λ2 = 0.8, μmin = 40°, ground 0.5 m): the chosen mechanism
    on the page is the CLI's ``kkm-30_mechanism.csv``, in both languages; a bad μmin at
    its field; the screenshots of the page."""
    from selenium.webdriver.common.by import By

    out = _shared(cli_report("synth", "--l2", "0.8", "--mu-min", "40", "--ground", "0.5",
                             "--lang", "en", "--no-plots"))     # only its CSV is read
    with open(out / "kkm-30_mechanism.csv", newline="") as fh:
        want = list(csv.reader(fh))
    d = browser
    for lang in ("en", "ru"):
        _example_in(d, server, "synth", "readme", lang, first=lang == "en")
        _compute(d)
        table = d.find_element(By.ID, "table2-form")
        head = _head(table)
        rows = _first_rows(table)
        assert [head, *rows] == want
        _wait(d, _images_loaded)
        assert len(d.find_elements(By.CSS_SELECTOR, "#figures img")) == 3
        d.execute_script("document.getElementById('results').scrollIntoView()")
        _shot(d, f"web_synth_results_{lang}.png", tmp_path)
    box = d.find_element(By.ID, "synth.mu_min_deg")     # ru: a bad μmin at its field
    box.clear()
    box.send_keys("95")
    d.find_element(By.ID, "compute").click()
    err = _by_id(d, "err-synth.mu_min_deg")
    assert "95" in err.text and "углом в градусах" in err.text
    assert not d.find_elements(By.ID, "results")
    d.execute_script("document.getElementById('form').scrollIntoView()")
    _shot(d, "web_synth_form_ru.png", tmp_path)


def test_the_dynamics_page_in_the_browser(server, browser, tmp_path, cli_report):
    """The shaper (a six-link chain driven by a motor, ``crankdyn dynamics --example
    shaper``): the motion table and the forces under the true motion on the page are the
    CLI's, in both languages; the screenshots of the page."""
    from selenium.webdriver.common.by import By

    out = _shared(cli_report("dynamics", "--example", "shaper", "--lang", "en"))
    want = {}
    for key, name in (("table2", "shaper-machine_motion.csv"),
                      ("table2-form", "shaper-machine_forces_true_motion.csv")):
        with open(out / name, newline="") as fh:
            want[key] = list(csv.reader(fh))
    d = browser
    for lang in ("en", "ru"):
        _example_in(d, server, "dynamics", "shaper", lang, first=lang == "en")
        _compute(d)
        for key, rows_want in want.items():
            table = d.find_element(By.ID, key)
            head = _head(table)
            rows = _first_rows(table, 3)
            assert head == rows_want[0] and rows == rows_want[1:4]
        _wait(d, _images_loaded)
        assert len(d.find_elements(By.CSS_SELECTOR, "#figures img")) >= 5
        d.execute_script("document.getElementById('results').scrollIntoView()")
        _shot(d, f"web_dynamics_results_{lang}.png", tmp_path)


def test_the_balance_page_in_the_browser(server, browser, tmp_path):
    """The textbook's two-plane rotor: plane I 285.60 g·mm at 53.54° on the page, in both
    languages (Example 11-1 of the seed textbook, examples/rotor_two_plane.toml)."""
    from selenium.webdriver.common.by import By

    d = browser
    for lang in ("en", "ru"):
        _example_in(d, server, "balance", "rotor", lang, first=lang == "en")
        _compute(d)
        table = d.find_element(By.ID, "table2")
        head = _head(table)
        first = _first_rows(table, 1)[0]
        # the one-script reading of the cells is WebDriver's element text, cell by cell
        # (checked on this small table: its heads and first row)
        assert head == [th.text for th in table.find_elements(By.CSS_SELECTOR, "thead th")]
        assert first == [td.text for td in table.find_element(
            By.CSS_SELECTOR, "tbody tr").find_elements(By.TAG_NAME, "td")]
        row = dict(zip(head, first))
        assert round(float(row["mr_gmm"]), 2) == 285.60
        assert round(float(row["angle_deg"]), 2) == 53.54
        _wait(d, _images_loaded)
        d.execute_script("document.getElementById('results').scrollIntoView()")
        _shot(d, f"web_balance_results_{lang}.png", tmp_path)


def test_the_teacher_page_in_the_browser(server, browser, tmp_path, monkeypatch,
                                        unrendered_figures):
    """A class of two variants uploaded through the page's file inputs: the progress bar
    reaches 2 of 2 and the summary table lists both; the page in both languages.  The
    page, its form, progress and summary are the subject here, not the reports: the
    batch runs in the server's process (``BATCH_JOBS`` 1, no drawing processes started)
    with its figures saved unrendered (conftest ``unrendered_figures``); the app's own
    batch, in its drawing processes with every figure rendered and zipped, is
    tests/test_web.py ``test_the_teacher_page_runs_a_class_and_zips_every_report``."""
    from selenium.webdriver.common.by import By

    from web import teacher_page

    monkeypatch.setattr(teacher_page, "BATCH_JOBS", 1)

    table = tmp_path / "class.csv"
    table.write_text("variant,engine.bore_mm,engine.speed_rpm\nivanov,80,5000\n"
                     "petrova,82,4800\n", encoding="utf-8")
    d = browser
    d.get(server + "/teacher?lang=en")
    d.find_element(By.ID, "teacher-base").send_keys(str(example_path("petrol_vaz2106.toml")))
    d.find_element(By.ID, "teacher-variants").send_keys(str(table))
    d.find_element(By.ID, "teacher-submit").click()
    _by_id(d, "batch-progress")
    line = _by_id(d, "batch-line", timeout=300)
    assert "2 variants: 2 written" in line.text
    assert d.find_element(By.ID, "batch-progress").get_attribute("value") == "2"
    rows = d.find_elements(By.CSS_SELECTOR, "#summary-table tbody tr")
    assert [r.find_elements(By.TAG_NAME, "td")[0].text for r in rows] == ["ivanov", "petrova"]
    _shot(d, "web_teacher_en.png", tmp_path)
    d.get(server + "/teacher?lang=ru")
    assert "вариантов: 2; записано 2" in _by_id(d, "batch-line").text
    _shot(d, "web_teacher_ru.png", tmp_path)
    assert unrendered_figures and set(unrendered_figures) == {"png", "svg"}   # both reports


@pytest.mark.parametrize("lang,status", [("en", "1 value is wrong"),
                                         ("ru", "1 значение неверно")])
def test_the_teacher_s_check_of_a_workbook_in_the_browser(server, browser, tmp_path,
                                                          cli_report, lang, status):
    """A student's workbook (the CLI's petrol workbook, one cell of T changed by 30 %)
    checked through the page's second form: the T_N column is flagged at that angle, the
    checked workbook is offered; the screenshots of the verdict."""
    import openpyxl
    from selenium.webdriver.common.by import By

    src = _shared(cli_report("engine", "--example", "petrol", "--lang", lang))
    wb = openpyxl.load_workbook(src / "petrol-vaz2106.xlsx")
    ws = wb.worksheets[1]                           # Table 2: keys in hidden row 5
    keys = [ws.cell(5, j).value for j in range(1, ws.max_column + 1)]
    row = next(r for r in range(6, ws.max_row + 1) if ws.cell(r, 1).value == 30)
    ws.cell(row, keys.index("T_N") + 1).value *= 1.3
    student = tmp_path / "ivanov.xlsx"
    wb.save(student)
    d = browser
    d.get(server + f"/teacher?lang={lang}")
    d.find_element(By.ID, "check-spec").send_keys(str(example_path("petrol_vaz2106.toml")))
    d.find_element(By.ID, "check-student").send_keys(str(student))
    d.find_element(By.ID, "check-submit").click()
    _settled_text(d, "check-status", status)
    assert d.find_element(By.ID, "check-status").text == status
    verdict = d.find_element(By.ID, "check-verdict").text.splitlines()
    assert verdict[0].startswith("ivanov.xlsx")
    (t_line,) = [ln.split() for ln in verdict if ln.split()[:1] == ["T_N"]]
    assert t_line[1] in ("WRONG", "НЕВЕРНО"), verdict
    cells = [[td.text for td in tr.find_elements(By.TAG_NAME, "td")]
             for tr in d.find_elements(By.CSS_SELECTOR, "#check-wrong tbody tr")]
    assert [c[:2] for c in cells] == [["30.0", "T_N"]]
    assert d.find_element(By.ID, "dl-check-marked").get_attribute("href").endswith(
        "/ivanov_checked.xlsx")
    d.execute_script("document.getElementById('check-result').scrollIntoView()")
    _shot(d, f"web_teacher_check_{lang}.png", tmp_path)


@pytest.fixture(scope="module")
def torsion_modes():
    """The library's torsion_modes.csv of the torsion example (its study with the
    torsion on), as rows of text: computed once for both languages' tests."""
    import engine

    report = engine.run_study(engine.load(example_path("torsion_inline6.toml")),
                              torsion=True)
    return list(csv.reader(report.torsion.tables["torsion_modes.csv"].to_csv(
        index=False, lineterminator="\n").splitlines()))


def test_the_torsion_example_in_the_browser(server, browser, tmp_path, torsion_modes):
    """The torsion example computed with the option on, in both languages: the natural
    frequencies table on the page is the library's torsion_modes.csv, Campbell's diagram
    is shown; the screenshots of the torsion results.  (One test for both languages, as
    the other pages': Russian is reached with the page's language link.)"""
    from selenium.webdriver.common.by import By

    want = torsion_modes
    d = browser
    for lang in ("en", "ru"):
        _example_in(d, server, "engine", "torsion", lang, first=lang == "en")
        assert d.find_element(By.ID, "opt-torsion").is_selected()
        _compute(d)
        table = d.find_element(By.ID, "torsion-modes")
        head = _head(table)
        rows = _first_rows(table)
        assert [head] + rows == want
        _wait(d, _images_loaded)
        assert d.find_elements(By.ID, "fig-bmw-m54b30_campbell.png")
        d.execute_script("document.getElementById('fig-bmw-m54b30_campbell.png')"
                         ".parentElement.scrollIntoView()")
        _shot(d, f"web_engine_torsion_{lang}.png", tmp_path)
