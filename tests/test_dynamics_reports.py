"""The reports of ``crankdyn dynamics`` and ``crankdyn balance`` (issue 14): every output
named after the spec, so two specs share a folder and a rerun replaces only its own
files; the terminal summary, the workbook and the plots speak the report's language."""
import re

import pytest
from rendering import RENDER_ROWS, needs_office, page_sizes_many, unrendered
from xlsx_edit import thinned_copy

from crankbase.output import MANIFEST_NAME, read_manifest, verify_report
from crankbase.resources import example_path
from crankdyn.cli import main
from dynamics.plots import PLOT_NAMES

CYRILLIC = re.compile("[\u0400-\u04FF]")

#: --example → (spec name, the plots it draws, the tables it writes) of crankdyn dynamics.
DYNAMICS = {
    "flywheel": ("flywheel-example-11-3", PLOT_NAMES[:4], ("motion",)),
    "press": ("crank-press", PLOT_NAMES, ("motion", "forces_true_motion", "startup")),
    "petrol": ("petrol-vaz2106", PLOT_NAMES[:4] + ("forces_true_motion",),
               ("motion", "forces_true_motion")),
    "hoist": ("hoist", PLOT_NAMES[:5], ("motion", "startup")),
}
#: --example → the files of crankdyn balance.
BALANCE = {
    "rotor": {f"two-plane-example_rotor_{w}" for w in
              ("balance.csv", "shares.csv", "polygons.png", "polygons.svg")},
    "ratchet": {f"ratchet-drive_{w}" for w in
                ("counterweights.csv", "shaking.csv", "shaking_force.png",
                 "shaking_force.svg", "shaking_locus.png", "shaking_locus.svg")},
}


def dynamics_files(example):
    name, plots, tables = DYNAMICS[example]
    return ({f"{name}_{t}.csv" for t in tables} | {f"{name}_dynamics.xlsx"}
            | {f"{name}_{p}.{e}" for p in plots for e in ("png", "svg")})


def _names(folder):
    return {p.name for p in folder.iterdir()} - {MANIFEST_NAME}


@pytest.fixture(scope="module")
def runs(cli_report):
    """Every bundled example of both commands in both languages, each in its own folder
    (the session's shared reports, read-only): (command, example, lang) → (folder,
    stdout, stderr)."""
    keys = [(command, ex, lang) for command, examples in (("dynamics", DYNAMICS),
                                                          ("balance", BALANCE))
            for ex in examples for lang in ("ru", "en")]
    out = {}
    for key, rep in zip(keys, cli_report.many([(c, "--example", ex, "--lang", lang)
                                               for c, ex, lang in keys])):
        assert rep.rc == 0, rep.err
        out[key] = (rep.folder, rep.out, rep.err)
        RENDERED[key] = rep.rendered
    return out


#: (command, example, lang) → whether that shared report's figures are rendered (the
#: English dynamics reports of press, petrol and hoist are not: tests/conftest.py
#: UNRENDERED_REPORTS; their Russian ones are, and checked as PNG and SVG below).
RENDERED = {}


# ------------------------------------------------------------------ names and units
def test_every_output_is_named_after_the_spec(runs):
    for (command, ex, lang), (d, _, _) in runs.items():
        want = dynamics_files(ex) if command == "dynamics" else BALANCE[ex]
        assert _names(d) == want, (command, ex, lang)
        assert set(verify_report(d)) == want
        rendered = RENDERED[(command, ex, lang)]
        for n in want:          # the plots are rendered (the other tests here do not draw)
            head = (d / n).read_bytes()[:300]
            if not rendered and n.endswith((".png", ".svg")):     # saved by its savefig
                assert unrendered(d / n), (command, ex, lang, n)
            elif n.endswith(".png"):
                assert head.startswith(b"\x89PNG\r\n\x1a\n"), (command, ex, lang, n)
            elif n.endswith(".svg"):
                assert b"<svg" in head, (command, ex, lang, n)
    # every example's plots rendered for real in at least one language
    for command, examples in (("dynamics", DYNAMICS), ("balance", BALANCE)):
        for ex in examples:
            assert RENDERED[(command, ex, "ru")] or RENDERED[(command, ex, "en")], ex
    assert RENDERED[("dynamics", "press", "ru")]     # the example drawing every plot


def test_two_specs_share_a_folder_and_a_rerun_replaces_only_its_own(tmp_path, capsys,
                                                                    cli_report,
                                                                    unrendered_figures):
    import shutil

    out = tmp_path / "o"            # the hoist first: a copy of the session's report
    shutil.copytree(cli_report("dynamics", "--example", "hoist", "--lang", "ru").folder, out)
    for cmd, ex in (("dynamics", "flywheel"), ("balance", "rotor"), ("balance", "ratchet")):
        assert main([cmd, "--example", ex, "-o", str(out)]) == 0
    both = dynamics_files("hoist") | dynamics_files("flywheel") | BALANCE["rotor"] \
        | BALANCE["ratchet"]
    assert _names(out) == both
    assert set(verify_report(out)) == both
    before = {n: (out / n).read_bytes() for n in both}
    # the hoist again, now driven at constant speed: no start-up any more
    spec = tmp_path / "hoist.toml"
    text = example_path("hoist_machine.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?s)\[dynamics\].*", '[dynamics]\ndriving = "constant"\n', text)
    spec.write_text(text, encoding="utf-8")
    capsys.readouterr()
    assert main(["dynamics", str(spec), "-o", str(out), "--lang", "en"]) == 0
    gone = {"hoist_startup.csv", "hoist_startup.png", "hoist_startup.svg"}
    assert _names(out) == both - gone
    for n in both - gone:
        if not n.startswith("hoist_"):           # every other report is untouched
            assert (out / n).read_bytes() == before[n], n
    assert (out / "hoist_motion.csv").read_bytes() != before["hoist_motion.csv"]
    assert set(verify_report(out)) == both - gone
    units = {n: f["unit"] for n, f in read_manifest(out)["files"].items()}
    assert units["hoist_motion.csv"] == "dynamics:hoist"
    assert units["two-plane-example_rotor_shares.csv"] == "balance:two-plane-example"
    assert unrendered_figures          # the plots were saved (names only, not drawn)


def test_stale_copies_are_removed_and_said_so(tmp_path, capsys, cli_report,
                                              unrendered_figures):
    """A file of this spec the manifest does not list (copied back by hand) that this run
    does not write goes too, with a line on stderr in the report's language."""
    import shutil

    out = tmp_path / "o"            # a copy of the session's hoist report (--lang ru)
    shutil.copytree(cli_report("dynamics", "--example", "hoist", "--lang", "ru").folder, out)
    (out / "hoist_forces_true_motion.png").write_bytes(b"old")
    (out / "motion.csv").write_text("an older crankdyn's unnamed output\n")
    capsys.readouterr()
    assert main(["dynamics", "--example", "hoist", "-o", str(out), "--lang", "ru"]) == 0
    err = capsys.readouterr().err
    assert not (out / "hoist_forces_true_motion.png").exists()
    assert "удалён" in err and "hoist_forces_true_motion.png" in err
    assert (out / "motion.csv").exists() and "motion.csv" in err     # named, left alone
    assert not _latin_words(_strip(err, out))
    assert unrendered_figures


def test_linkage_engine_and_dynamics_reports_of_one_mechanism_stay_together(
        tmp_path, unrendered_figures):
    """``crankdyn linkage`` and ``crankdyn dynamics`` of the same press (and engine and
    dynamics of the same petrol engine) name their files after the same spec: each is
    its own report unit, so neither takes the other's files for stale ones."""
    out = tmp_path / "o"
    assert main(["linkage", "--example", "press", "-o", str(out), "--no-plots"]) == 0
    linkage_files = _names(out)
    assert main(["engine", "--example", "petrol", "-o", str(out)]) == 0
    engine_files = _names(out) - linkage_files
    for ex in ("press", "petrol"):
        assert main(["dynamics", "--example", ex, "-o", str(out)]) == 0
    assert main(["balance", str(example_path("ratchet_balance.toml")), "-o", str(out)]) == 0
    assert main(["linkage", "--example", "press", "-o", str(out), "--no-plots"]) == 0
    assert main(["engine", "--example", "petrol", "-o", str(out)]) == 0
    assert _names(out) == (linkage_files | engine_files | dynamics_files("press")
                           | dynamics_files("petrol") | BALANCE["ratchet"])
    verify_report(out)
    assert unrendered_figures


# ------------------------------------------------------------------ language
#: Latin words allowed in a Russian terminal summary: textbook notation (max, min,
#: const, as in "ωmax", "Mс = const"), the file formats (PNG, SVG).  Spec names, file
#: names, the output folder and the "crankdyn <command>:" prefix of a stderr line are
#: removed before the check; a word is a run of letters of 3 or more, all Latin (ΔTmax,
#: ωmax and Mс are symbols, not English words); units are Russian (кг, Н·м, рад/с).
ALLOWED_LATIN = {"max", "min", "const", "PNG", "SVG"}


def _latin_words(text):
    return {w for w in re.findall(r"[^\W\d_]+", text)
            if re.fullmatch(r"[A-Za-z]{3,}", w)} - ALLOWED_LATIN


def _strip(text, folder, spec_name=None):
    """``text`` without the output folder, the file names and the spec's name."""
    text = re.sub(r"(?m)^crankdyn \w+: ", "", text.replace(str(folder), ""))
    text = re.sub(r"\S+\.(csv|xlsx|png|svg)\b", "", text)
    if spec_name:
        text = text.replace(spec_name, "")
    return text


def _spec_name(command, ex):
    if command == "dynamics":
        return DYNAMICS[ex][0]
    return {"rotor": "two-plane-example", "ratchet": "ratchet-drive"}[ex]


def test_russian_summaries_speak_russian(runs):
    for (command, ex, lang), (d, out, err) in runs.items():
        if lang != "ru":
            continue
        text = _strip(out + err, d, _spec_name(command, ex))
        words = _latin_words(text)
        assert not words, (command, ex, words, out)
        assert "записано:" in out and CYRILLIC.search(out)
    press = runs[("dynamics", "press", "ru")][1]
    for symbol in ("ωmax", "ωmin", "ωср", "δ", "ΔTmax", "Jм", "Jc", "время цикла",
                   "время разгона", "рад/с", "кг·м²"):
        assert symbol in press, symbol
    assert "Mс = const" in runs[("dynamics", "petrol", "ru")][1]
    assert "Mд = const" in runs[("dynamics", "flywheel", "ru")][1]
    assert "(m r)б" in runs[("balance", "rotor", "ru")][1]
    assert "кривошип" in runs[("balance", "ratchet", "ru")][1]


def test_english_summaries_have_no_cyrillic(runs):
    for (command, ex, lang), (d, out, err) in runs.items():
        if lang == "en":
            assert not CYRILLIC.search(out + err), (command, ex, out)
            assert "wrote " in out


def test_summaries_carry_the_same_numbers_in_both_languages(runs):
    """One summary function per report with a language argument: the numbers of the ru
    and en summaries are the same, in the same order and format."""
    number = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:e[-+]\d+)?")
    for (command, ex, lang), (d, out, _) in runs.items():
        if lang != "ru":
            continue
        en = runs[(command, ex, "en")][1]
        nums = [number.findall(_strip(t, f, _spec_name(command, ex))) for t, f in
                ((out, d), (en, runs[(command, ex, "en")][0]))]
        assert nums[0] == nums[1], (command, ex)
    # the flywheel of seed 001, Example 11-3: ω_max 168.45, ω_min 145.72 rad/s
    assert "168.444 рад/с" in runs[("dynamics", "flywheel", "ru")][1]
    assert "168.444 rad/s" in runs[("dynamics", "flywheel", "en")][1]


# ------------------------------------------------------------------ workbook
@pytest.fixture(scope="module")
def workbooks(runs, loaded_workbook):
    """The workbook of each dynamics run, loaded once per worker for the tests that read
    it (the session's :func:`loaded_workbook`, shared with tests/test_workbooks_audit.py;
    read-only): (example, lang) → openpyxl workbook."""
    def get(ex, lang):
        d = runs[("dynamics", ex, lang)][0]
        return loaded_workbook(d / f"{DYNAMICS[ex][0]}_dynamics.xlsx")
    return get


def _workbook(workbooks, ex, lang):
    return workbooks(ex, lang)


def test_dynamics_workbook_speaks_the_report_language(workbooks):
    for ex in DYNAMICS:
        en = _workbook(workbooks, ex, "en")
        for ws in en.worksheets:
            assert not CYRILLIC.search(ws.title)
            for row in ws.iter_rows(values_only=True):
                for v in row:
                    assert not (isinstance(v, str) and CYRILLIC.search(v)), (ex, ws.title, v)
        ru = _workbook(workbooks, ex, "ru")
        text = "\n".join([ws.title for ws in ru.worksheets] + [     # the first 40 rows
            str(v) for ws in ru.worksheets            # (not past the last: iter_rows
            for row in ws.iter_rows(max_row=min(40, ws.max_row), values_only=True)
            for v in row])                            # would add empty cells there)
        for symbol in ("Итоги", "ωmax", "ωср", "ΔTmax", "Jм", "Jп, кг·м²", "Mд, Н·м",
                       "Mс, Н·м", "ω, рад/с", "ε, рад/с²", "φ, °"):
            assert symbol in text, (ex, symbol)


def test_dynamics_workbook_headers_and_print_setup(workbooks):
    from dynamics.report import column_label

    for ex in DYNAMICS:
        for lang in ("ru", "en"):
            wb = _workbook(workbooks, ex, lang)
            assert wb.worksheets[0]["A1"].value.startswith(DYNAMICS[ex][0])
            for ws in wb.worksheets:
                ps = ws.page_setup
                assert int(ps.paperSize) == 9, (ex, ws.title)                  # A4
                assert ws.sheet_properties.pageSetUpPr.fitToPage
                assert int(ps.fitToHeight) == 0 and int(ps.fitToWidth) >= 1
            for ws in wb.worksheets[1:]:
                names = [c.value for c in ws[2]]
                assert [c.value for c in ws[1]] == [column_label(n, lang, ws.title in
                                                                 ("Силы", "Forces") and
                                                                 {"M_drive": ("Mур", "M_b")}
                                                                 or None) for n in names]
                assert ws.print_title_rows == "$1:$2" or ws.print_title_rows == "1:2"
    # the linkage's forces sheet: its M_drive is the core's balancing moment Mур
    forces = _workbook(workbooks, "press", "ru")["Силы"]
    header = dict(zip((c.value for c in forces[2]), (c.value for c in forces[1])))
    assert header["M_drive_Nm"] == "Mур, Н·м"
    assert header["M_drive_Nm_const"] == "Mур, Н·м (ω = const)"
    assert header["R12_N"] == "R12, Н"


def test_column_labels():
    from dynamics.report import column_label

    assert column_label("omega_rad_s", "ru") == "ω, рад/с"
    assert column_label("omega_rad_s", "en") == "ω [rad/s]"
    assert column_label("eps_rad_s2", "ru") == "ε, рад/с²"
    assert column_label("dJ_red_dphi_kgm2", "ru") == "dJп/dφ, кг·м²"
    assert column_label("j_m_s2_const", "en") == "j [m/s²] (ω = const)"
    assert column_label("R_N", "ru") == "Rшш, Н" and column_label("R_N", "en") == "Rcp [N]"
    assert column_label("M_Nm", "ru") == "Mкр, Н·м"
    assert column_label("t_s", "en") == "t [s]"
    assert column_label("R12_x_N", "ru") == "R12_x, Н"
    # the notation from the catalogue (common.unit.*, common.format.*): the degree a sign
    # in Russian, a word in English; Chinese writes the Latin symbols and SI spellings
    assert column_label("phi_deg", "ru") == "φ, °" and column_label("phi_deg", "en") == "φ [deg]"
    assert column_label("W_J", "ru") == "ΔT = ∫(Mд − Mс)dφ, Дж"
    assert column_label("J_red_kgm2", "zh") == "J_red [kg·m²]"
    # the parts of the resisting moment: a symbol in words of the language
    assert column_label("M_resist_loads_Nm", "ru") == "Mс от нагрузок, Н·м"
    assert column_label("M_resist_weights_Nm", "en") == "M_c of the weights [N·m]"
    assert column_label("M_resist_loads_Nm", "zh") == "M_c（载荷） [N·m]"


@pytest.mark.slow
@needs_office
def test_dynamics_workbooks_render_on_a4_pages(runs, tmp_path, workbooks):
    """LibreOffice prints the press example's dynamics workbook (every sheet a dynamics
    report has) in both languages to PDF: every page is A4 (either orientation) and every
    sheet yields at least one page, a long sheet more.  Each sheet is cut to its first
    :data:`RENDER_ROWS` rows first (``xlsx_edit.thinned_copy``: its page setup and every
    other part the same bytes): the 2,000 rows of the start-up sheet and the 720 of the
    motion and force sheets, 121 pages a language, cost LibreOffice seconds and print on
    the same paper as their first pages."""
    src = {lang: runs[("dynamics", "press", lang)][0] / "crank-press_dynamics.xlsx"
           for lang in ("ru", "en")}
    (tmp_path / "thin").mkdir()
    thin = {lang: thinned_copy(path, tmp_path / "thin" / f"{lang}.xlsx", RENDER_ROWS)
            for lang, path in src.items()}
    sizes = page_sizes_many(thin, tmp_path / "pdf")
    for lang in src:
        pages = sizes[lang]
        sheets = workbooks("press", lang).worksheets
        assert set(pages) == {(595, 842)}, (lang, set(pages))
        long = sum(ws.max_row > RENDER_ROWS for ws in sheets)
        assert long >= 3 and len(pages) >= len(sheets) + long, (lang, len(pages))


def test_crank_slider_balance_summary_in_both_languages(tmp_path, capsys,
                                                        unrendered_figures):
    """The partial balance of a crank-slider (press.toml with [balance] fraction = 0.5):
    named after the mechanism, its summary in the report's language with the fraction."""
    spec = tmp_path / "slider.toml"
    spec.write_text(example_path("press.toml").read_text(encoding="utf-8")
                    + "\n[balance]\nfraction = 0.5\n", encoding="utf-8")
    out = tmp_path / "o"
    text = {}
    for lang in ("ru", "en"):
        capsys.readouterr()
        assert main(["balance", str(spec), "-o", str(out), "--lang", lang]) == 0
        text[lang] = capsys.readouterr()
    assert _names(out) == {f"crank-press_{w}" for w in (
        "counterweights.csv", "shaking.csv", "shaking_force.png", "shaking_force.svg",
        "shaking_locus.png", "shaking_locus.svg")}
    ru = text["ru"].out + text["ru"].err
    assert not _latin_words(_strip(ru, out, "crank-press")), ru
    assert "частичное" in ru and "кривошипно-ползунный" in ru and ": 0.5" in ru
    en = text["en"].out + text["en"].err
    assert not CYRILLIC.search(en) and "partial" in en and ": 0.5" in en
    assert unrendered_figures


def test_the_readme_names_the_headers_the_workbook_prints():
    """The README's row of ``<name>_dynamics.xlsx`` promises the headers of ω, M_d and R
    in both languages: they are the ones ``dynamics.report.column_label`` prints (#23: it
    promised ``M_b [N·m]`` where the workbook printed ``M_d [N·m]``)."""
    import re
    from pathlib import Path

    from dynamics.report import column_label

    readme = (Path(__file__).resolve().parent.parent / "README.md").read_text("utf-8")
    row = next(ln for ln in readme.splitlines() if ln.startswith("| `<name>_dynamics.xlsx`"))
    promised = re.search(r"\(`([^`]+)`, `([^`]+)`, `([^`]+)` / `([^`]+)`, `([^`]+)`, "
                         r"`([^`]+)`", row).groups()
    cols = ("omega_rad_s", "M_drive_Nm", "R_N")
    printed = tuple(column_label(c, "ru") for c in cols) + tuple(column_label(c, "en")
                                                               for c in cols)
    assert promised == printed
