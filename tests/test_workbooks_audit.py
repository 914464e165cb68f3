"""Every workbook the tool writes, checked as a reader sees it (issue 23): one automatic
check (tests/workbook_audit.py: no text cut off, no number shown as ###, wrapped rows tall
enough, one number format per column of each table, one font family) run over every
bundled example's workbook in both languages, each saved and read back as a reader opens
it: built through the library's report functions (no plots, no rendering), or, where the
session's shared CLI reports already hold that very workbook (the dynamics examples, the
diesel and V8 engines in both languages, the six in English), the file the CLI wrote."""
from __future__ import annotations

import pytest
from openpyxl import load_workbook
from workbook_audit import problems
from xlsx_edit import altered_copy

import engine
from crankbase.resources import example_path

ENGINES = ("petrol_vaz2106.toml", "diesel_d240.toml", "petrol_bmw_m54.toml",
           "diesel_kamaz740.toml")
#: Engine workbooks that are a session's shared CLI report's, by (example, language): the
#: argv of that run (the same study and workbook: run_study, report_workbook, the same
#: save).  The Russian V8 is the shared ``--bearings`` run (Russian, the default; its
#: engine sheets the same as without, plus the bearing sheets, audited too: no run of
#: its own for the audit).  The petrol one is built here with its bearing sheets, the
#: six's Russian one has no shared run.
SHARED_ENGINES = {
    ("diesel_d240.toml", "ru"): ("engine", "--example", "diesel", "--lang", "ru"),
    ("diesel_d240.toml", "en"): ("engine", "--example", "diesel", "--lang", "en"),
    ("diesel_kamaz740.toml", "ru"): ("engine", "--example", "v8", "--bearings"),
    ("diesel_kamaz740.toml", "en"): ("engine", "--example", "v8", "--lang", "en"),
    ("petrol_bmw_m54.toml", "en"): ("engine", "--example", "six", "--lang", "en"),
}
#: The dynamics examples, all the shared ``crankdyn dynamics --example NAME --lang LANG``
#: reports' (dynamics.study.write_report: build_workbook of run_job, saved at full
#: precision as save_workbook saves).
SHARED_DYNAMICS = {"flywheel_seed.toml": "flywheel", "press_dynamics.toml": "press",
                   "petrol_dynamics.toml": "petrol", "hoist_machine.toml": "hoist"}
LINKAGES = ("ratchet.toml", "press.toml")
DYNAMICS = ("flywheel_seed.toml", "press_dynamics.toml", "petrol_dynamics.toml",
            "hoist_machine.toml")
LANGS = ("ru", "en")


def _saved(wb, path):
    from engine.report import save_workbook

    save_workbook(wb, path)
    return path


def _shared_xlsx(cli_report, *argv):
    rep = cli_report(*argv)
    assert rep.rc == 0, (argv, rep.err)
    (xlsx,) = rep.folder.glob("*.xlsx")
    return xlsx


def _all(tmp, cli_report, loaded_workbook):
    """{key: path} of every workbook."""
    import linkage
    from linkage import synthesis as syn
    from linkage import synthesis_report as rep
    from linkage.report import write_workbook

    from engine.study import report_workbook

    # each example computed once, its workbook built in each language
    studies = {name: engine.run_study(example_path(name),
                                      bearings=name == "petrol_vaz2106.toml")
               for name in ENGINES
               if any((name, lang) not in SHARED_ENGINES for lang in LANGS)}
    mechanisms = {name: linkage.analyze(linkage.load_spec(example_path(name)))
                  for name in LINKAGES}
    records = variant_records()
    out = {}
    for lang in LANGS:
        for name in ENGINES:
            if (name, lang) in SHARED_ENGINES:
                out[("engine", name, lang)] = _shared_xlsx(cli_report,
                                                           *SHARED_ENGINES[(name, lang)])
                continue
            out[("engine", name, lang)] = _saved(report_workbook(studies[name], lang),
                                                 tmp / f"{name}_{lang}.xlsx")
        for name in LINKAGES:
            p = tmp / f"{name}_{lang}.xlsx"
            write_workbook(mechanisms[name], p, lang)
            out[("linkage", name, lang)] = p
        design = syn.design_equal_l2_l3(0.15, 30.0)
        p = tmp / f"synth_{lang}.xlsx"
        rep.write_workbook(p, rep.table1(30.0), 30.0, rep.mechanism_table(design, 0.4),
                           lang=lang)
        out[("synth", lang)] = p
        for name in DYNAMICS:
            out[("dynamics", name, lang)] = _shared_xlsx(
                cli_report, "dynamics", "--example", SHARED_DYNAMICS[name], "--lang", lang)
        out[("variants", lang)] = variants_summary(tmp / f"variants_{lang}", lang, records)
        out[("check", lang)] = checked_copy(out[("engine", "diesel_d240.toml", lang)],
                                            tmp / f"check_{lang}", lang, loaded_workbook)
    return out


def variant_records():
    """The summary records of three variants of the petrol example (bores 76, 79 and
    82.5 mm), as the variants batch makes them (engine.variants.summary_record)."""
    from engine.spec import read_toml
    from engine.variants import VariantRow, load_variant, summary_record

    base, _ = read_toml(example_path("petrol_vaz2106.toml"))
    records = []
    for i, bore in enumerate((76, 79, 82.5), start=2):
        v = VariantRow(i, f"V{i - 1:02d}", {"engine.bore_mm": bore})
        study = load_variant(base, v, example_path("petrol_vaz2106.toml").parent)
        res = engine.analyze(study.spec, study.settings)
        records.append(summary_record(v.variant, study.spec, res.summary))
    return records


def variants_summary(folder, lang, records=None):
    """The variants summary workbook of three variants of the petrol example
    (:func:`variant_records`, computed once for both languages when given), written by
    the variants batch's own writer (engine.variants.write_summary)."""
    from engine.variants import write_summary

    records = variant_records() if records is None else records
    folder.mkdir()
    return write_summary(folder, records, [], lang)[1]


def checked_copy(report, folder, lang, loaded_workbook):
    """``crankdyn check``'s marked copy of a report with one cell altered (Table 2's
    B8, altered in the file: :func:`xlsx_edit.altered_copy`)."""
    from crankbase.checking import compare, mark_workbook, read_student_table
    from engine.check import KEY, computed_rows, known_columns

    folder.mkdir()
    b8 = loaded_workbook(report).worksheets[1]["B8"].value
    student = altered_copy(report, folder / "student.xlsx", {2: {"B8": b8 + 7.0}})
    study = engine.load(example_path("diesel_d240.toml"))
    table = read_student_table(student, KEY, known_columns(), {})
    computed = computed_rows(study.spec, study.settings, table.data[KEY].to_numpy(float))
    check = compare(table, computed, KEY)
    dst = folder / "checked.xlsx"
    assert mark_workbook(table, check, dst, lang) >= 1
    return dst


@pytest.fixture(scope="module")
def workbooks(tmp_path_factory, cli_report, loaded_workbook):
    return _all(tmp_path_factory.mktemp("audit"), cli_report, loaded_workbook)


def _shared(key):
    """Whether the workbook of ``key`` is a shared CLI report's (read by other modules
    too: loaded through the session's ``loaded_workbook``, parsed once per worker)."""
    return (key[0] == "engine" and key[1:] in SHARED_ENGINES) or key[0] == "dynamics"


def test_every_workbook_reads_cleanly(workbooks, loaded_workbook):
    """No cut text, no ###, tall enough wrapped rows, one format per table column, one
    font family, in every workbook of every bundled example in both languages."""
    found = []
    for key, path in workbooks.items():
        wb = loaded_workbook(path) if _shared(key) else load_workbook(path)
        found += problems(wb, " ".join(map(str, key)))
    assert not found, "\n".join(found[:40]) + f"\n({len(found)} problems)"


def test_the_audit_catches_each_defect(tmp_path):
    """The check finds each defect of issue 23 when it is put back: a label cut off by
    its neighbour, mixed decimals in one column, a serif header over sans data, a wrapped
    label in a one-line row, a number too wide for its column."""
    from openpyxl.styles import Alignment, Font

    from crankbase.workbook import finish, new_workbook

    def fresh():
        wb = new_workbook()
        ws = wb.active
        ws.append(["Неравномерность μ = (Mкр.max − Mкр.min)/Mкр.ср", 0.25, ""])
        ws.append(["α, °", "Mкр, Н·м", "ΣMкр, Н·м"])
        for a in range(0, 40, 10):
            ws.append([float(a), 1176.1 + a / 3, 1097.6 - a / 7])
        finish(wb)
        return wb, ws
    wb, ws = fresh()
    assert problems(wb) == []
    wb, ws = fresh()
    ws.column_dimensions["A"].width = 20
    assert any("cut off" in p for p in problems(wb))
    wb, ws = fresh()
    ws["B4"].number_format = "0.00" if ws["B3"].number_format != "0.00" else "0.0"
    assert any("formats" in p for p in problems(wb))
    wb, ws = fresh()
    ws["A2"].font = Font(name="Times New Roman", bold=True)
    assert any("font families" in p for p in problems(wb))
    wb, ws = fresh()
    ws["A1"].alignment = Alignment(wrap_text=True)
    ws.column_dimensions["A"].width = 15
    ws.row_dimensions[1].height = 15
    assert any("lines in a row" in p for p in problems(wb))
    wb, ws = fresh()
    ws["B3"].value = 123456789.123
    ws["B3"].number_format = "0.000"
    assert any("###" in p for p in problems(wb))


@pytest.mark.slow
def test_a_thinned_workbook_reads_cleanly(tmp_path):
    """A fine table step (0.25°: 2881 rows, thinned on the sheets with a note) passes
    the same check, the bearing sheets included."""
    from engine.study import report_workbook

    report = engine.run_study(example_path("petrol_vaz2106.toml"), bearings=True, step=0.25)
    for lang in LANGS:
        saved = _saved(report_workbook(report, lang), tmp_path / f"fine_{lang}.xlsx")
        found = problems(load_workbook(saved), f"fine {lang}")
        assert not found, "\n".join(found[:20])
