"""End-to-end tests of ``crankdyn synth`` (seed 004, Sereda 2016): run the CLI into a
temporary folder, read the CSV, the workbook and the spec TOML back."""
from __future__ import annotations

import math
import re
import subprocess
import sys
import tomllib

import numpy as np
import pandas as pd
import pytest
from openpyxl import load_workbook

import linkage
from crankbase.output import MANIFEST_NAME
from crankdyn.cli import main
from linkage import synthesis as syn

PLOTS = ["region", "mu_min", "transmission_angle"]


def run(args, out):
    return main(["synth", *args, "-o", str(out)])


def test_paper_example_fig3_with_ground(tmp_path, capsys, figures_rendered_only):
    """(Its three plots rendered as PNG; as SVG, in both languages, by the module's
    ``both`` run of the same design: test_plot_files_in_both_languages.)"""
    saved = figures_rendered_only(".png")
    out = tmp_path / "out"
    # seed 004, example 2 to Fig. 3: λ2 = 0.90, μmin ≥ 40° → λ1 = 0.08, λ3 = 0.24, μmin 46°16′
    rc = run(["--phi0", "30", "--l2", "0.9", "--mu-min", "40", "--l1-step", "0.01",
              "--ground", "0.5", "--name", "press drive"], out)
    assert rc == 0
    printed = capsys.readouterr().out
    assert "λ1 = 0.0800" in printed and "λ3 = 0.2405" in printed and "46°24′" in printed
    names = sorted(p.name for p in out.iterdir() if p.name != MANIFEST_NAME)
    assert names == sorted(["press_drive_table1.csv", "press_drive_synthesis.xlsx",
                            "press_drive_mechanism.csv", "press_drive_transmission_angle.csv",
                            "press_drive.toml", *[f"press_drive_{p}.{e}" for p in PLOTS
                                                  for e in ("png", "svg")]])
    assert sum(drawn for _, drawn in saved) == len(PLOTS) == len(saved) // 2
    for p in PLOTS:
        png = (out / f"press_drive_{p}.png").read_bytes()
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000, p

    mech = pd.read_csv(out / "press_drive_mechanism.csv")
    assert len(mech) == 1
    m = mech.iloc[0]
    assert m["l1"] == pytest.approx(0.08, abs=1e-15)
    assert round(m["l3"], 2) == 0.24                         # seed 004: λ3 = 0.24
    assert 46.2 <= m["mu_min_deg"] <= 46.4                   # seed 004: 46°16′ (rounded λ3)
    assert m["mu_min_at_deg"] == 180.0 and m["mu_at_phi0_deg"] == pytest.approx(90, abs=1e-9)
    assert m["grashof"] == "crank-rocker"
    assert (m["crank_m"], m["coupler_m"], m["ground_m"]) == pytest.approx((0.04, 0.45, 0.5))

    # the spec TOML: valid TOML, accepted by the core, and gives the same μ
    with open(out / "press_drive.toml", "rb") as f:
        spec = tomllib.load(f)
    assert spec["mechanism"]["name"] == "press drive"
    assert spec["mechanism"]["rocker"] == pytest.approx(0.5 * m["l3"], rel=1e-15)
    loaded = linkage.load_spec(out / "press_drive.toml")
    res = linkage.analyze(loaded, crank_angles_deg=[30.0, 180.0])
    np.testing.assert_allclose(res.kinematics["mu_deg"], [90.0, m["mu_min_deg"]], atol=1e-9)

    # μ(φ) table: 0…360° at 1°, 90° at φ0 and the minimum at 180°
    mu = pd.read_csv(out / "press_drive_transmission_angle.csv")
    assert mu["phi_deg"].tolist() == list(np.arange(0.0, 361.0))
    assert mu["mu_deg"].iloc[30] == pytest.approx(90.0, abs=1e-9)
    assert mu["mu_deg"].min() == pytest.approx(m["mu_min_deg"], abs=1e-12)

    # the spec runs through `crankdyn linkage` (its tables: a crank-rocker's plots are
    # rendered by the linkage tests' ratchet)
    assert main(["linkage", str(out / "press_drive.toml"), "-o", str(tmp_path / "lk"),
                 "--no-plots"]) == 0
    kin = pd.read_csv(next((tmp_path / "lk").glob("*_kinematics.csv")))
    assert kin["mu_deg"].min() >= m["mu_min_deg"] - 1e-9


def test_table1_csv_and_workbook(tmp_path, unrendered_figures):
    """Table 1 and the workbook (the numbers and labels only: the run's three figures
    are built and saved unrendered; the same three are rendered as PNG and SVG by
    test_paper_example_fig3_with_ground)."""
    out = tmp_path / "o"
    assert run(["--l2", "0.7", "--l3", "0.6"], out) == 0
    assert unrendered_figures == ["png", "svg"] * len(PLOTS)
    t1 = pd.read_csv(out / "kkm-30_table1.csv")
    assert list(t1.columns) == ["l1", "l2", "l3", "mu_min_deg"]
    # seed 004, Table 1 (four decimals)
    expected = [(0.05, 0.9520, 0.0980), (0.05, 0.0980, 0.9520),
                (0.10, 0.8904, 0.2096), (0.10, 0.2096, 0.8904),
                (0.15, 0.8002, 0.3498), (0.15, 0.3498, 0.8002),
                (0.1896, 0.5948, 0.5948)]
    np.testing.assert_array_equal(t1[["l1", "l2", "l3"]].round(4).to_numpy(), expected)
    assert (t1["mu_min_deg"] == 0).all()

    wb = load_workbook(out / "kkm-30_synthesis.xlsx", read_only=True)
    assert wb.sheetnames == ["Таблица 1", "Механизм"]          # --lang ru, the default
    rows = list(wb["Таблица 1"].iter_rows(values_only=True))
    assert rows[0][0].startswith("Таблица 1. ККМ-30°")
    assert rows[1][:3] == ("Длина λ1", "Длина λ2", "Длина λ3")
    assert rows[2][:4] == ("l1", "l2", "l3", "mu_min_deg")          # the CSV's names
    data = np.array([r[:4] for r in rows[3:]], dtype=float)
    np.testing.assert_array_equal(data, t1.to_numpy())          # full precision
    mech = {r[1]: r[2] for r in wb["Механизм"].iter_rows(min_row=3, values_only=True)}
    # seed 004, example 1 to Fig. 2: λ2 = 0.70, λ3 = 0.60 → λ1 = 0.09; μmin = 66°2′
    assert round(mech["l1"], 2) == 0.09
    assert mech["mu_min_deg"] == pytest.approx(66 + 2 / 60, abs=0.5 / 60)
    assert mech["grashof"] == "кривошипно-коромысловый"
    assert mech["method"] == "заданы λ2, λ3; λ1 по ур. (6)"
    csv = pd.read_csv(out / "kkm-30_mechanism.csv").iloc[0]
    assert mech["l1"] == csv["l1"] and mech["mu_min_deg"] == csv["mu_min_deg"]
    labels = {r[1]: r[0] for r in wb["Механизм"].iter_rows(min_row=3, values_only=True)}
    assert labels["l1"] == "Кривошип λ1" and labels["mu_min_deg"] == "Минимальный угол передачи μmin, °"


def test_equal_l2_l3_example(tmp_path, capsys):
    # seed 004, example 2 to Fig. 2: λ1 = 0.146, λ2 = λ3 → 0.620
    assert run(["--l1", "0.146", "--no-plots"], tmp_path / "o") == 0
    m = pd.read_csv(tmp_path / "o" / "kkm-30_mechanism.csv").iloc[0]
    assert round(m["l2"], 3) == 0.620 and m["l3"] == m["l2"]
    assert not list((tmp_path / "o").glob("*.png"))
    assert "λ2 = 0.6199" in capsys.readouterr().out


def test_region_only_and_other_phi0(tmp_path, figures_rendered_only):
    """φ0 = 120°: the region and μmin figures only.  The region's PNG is rendered (its
    boundary on Kolchin's lines (1)–(2), drawn nowhere else); the others are saved
    unrendered (their kinds are rendered by test_paper_example_fig3_with_ground)."""
    saved = figures_rendered_only("_region.png")
    out = tmp_path / "o"
    assert run(["--phi0", "120"], out) == 0
    rendered = [name for name, drawn in saved if drawn]     # (each saved to a temporary
    assert len(saved) == 4 and len(rendered) == 1           # name, then renamed)
    assert rendered[0].lstrip(".").startswith("kkm-120_region.png")
    assert (out / "kkm-120_region.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    names = {p.name for p in out.iterdir()} - {MANIFEST_NAME}
    assert names == {"kkm-120_table1.csv", "kkm-120_synthesis.xlsx", "kkm-120_region.png",
                     "kkm-120_region.svg", "kkm-120_mu_min.png", "kkm-120_mu_min.svg"}
    t1 = pd.read_csv(out / "kkm-120_table1.csv")
    # φ0 > 90°: the boundary is on Kolchin's lines (1)–(2): |λ2 − λ3| = 1 − λ1
    np.testing.assert_allclose((t1["l2"] - t1["l3"]).abs(), 1 - t1["l1"], atol=1e-12)
    assert t1["l1"].iloc[-1] == 1.0
    wb = load_workbook(out / "kkm-120_synthesis.xlsx", read_only=True)
    assert wb.sheetnames == ["Таблица 1"]


def test_rerun_replaces_outputs(tmp_path):
    out = tmp_path / "o"
    assert run(["--l2", "0.7", "--l3", "0.6", "--no-plots"], out) == 0
    assert run(["--l2", "0.6", "--l3", "0.7", "--no-plots"], out) == 0
    assert pd.read_csv(out / "kkm-30_mechanism.csv")["l2"].iloc[0] == 0.6
    assert [p.name for p in out.iterdir() if p.name.startswith(".")] == [MANIFEST_NAME]


def test_two_designs_share_a_folder(tmp_path):
    """Named designs never mix: a second design in the folder leaves the first's files."""
    out = tmp_path / "o"
    assert run(["--l2", "0.7", "--l3", "0.6", "--no-plots", "--name", "a"], out) == 0
    assert run(["--l2", "0.6", "--l3", "0.7", "--no-plots", "--name", "b"], out) == 0
    assert pd.read_csv(out / "a_mechanism.csv")["l2"].iloc[0] == 0.7
    assert pd.read_csv(out / "b_mechanism.csv")["l2"].iloc[0] == 0.6


BAD = [
    (["--phi0", "180", "--l1", "0.1"], ["--phi0: got 180"]),
    (["--phi0", "0"], ["--phi0: got 0"]),
    (["--phi0", "abc"], ["--phi0: got 'abc'"]),
    (["--l2", "-0.7", "--l3", "0"], ["--l2: got -0.7", "--l3: got 0"]),
    (["--l2", "nan", "--l3", "0.6"], ["--l2: got nan"]),
    (["--l2", "0.9", "--l3", "0.9"], ["--l2, --l3: (λ2, λ3) = (0.9, 0.9) is outside the region"]),
    (["--l2", "0.7", "--l3", "0.2"], ["--l2, --l3:"]),                 # beyond the curve cda
    (["--l1", "0.19"], ["--l1: must not exceed λ1max = 0.189591"]),
    (["--l2", "0.9", "--mu-min", "90"], ["--mu-min: got 90"]),
    (["--phi0", "120", "--l2", "1.2", "--mu-min", "40"], ["--mu-min: μmin ≥ 40° is not reachable"]),
    (["--l1", "0.1", "--l3", "0.5"], ["options: got --l1 --l3"]),
    (["--l3", "0.5"], ["options: got --l3"]),
    (["--mu-min", "40"], ["options: got --mu-min"]),
    (["--l1", "0.1", "--l2", "0.5", "--mu-min", "40"], ["options: got --l1 --l2 --mu-min"]),
    (["--l1", "0.1", "--l1-step", "0.01"], ["--l1-step: only with --l2 and --mu-min"]),
    (["--ground", "0.5"], ["--ground: needs a chosen mechanism"]),
    (["--l1", "0.1", "--ground", "-1", "--omega", "0"],
     ["--ground: got -1", "--omega: got 0"]),
]


@pytest.mark.parametrize("args, expected", BAD)
def test_bad_input_exit_2_one_line_per_problem_nothing_written(tmp_path, capsys, args,
                                                               expected):
    out = tmp_path / "out"
    out.mkdir()
    rc = run([*args, "--lang", "en"], out)
    assert rc == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == len(expected), err
    for line, want in zip(err, expected):
        assert line.startswith("crankdyn synth: error: ")
        assert want in line, (line, want)
    assert "Traceback" not in "\n".join(err)
    assert list(out.iterdir()) == []
    assert [p.name for p in tmp_path.iterdir()] == ["out"]     # no staging folder left


def test_bad_input_does_not_create_the_folder(tmp_path):
    assert run(["--l2", "0.9", "--l3", "0.9"], tmp_path / "new") == 2
    assert not (tmp_path / "new").exists()


def test_all_problems_at_once(tmp_path, capsys):
    rc = run(["--phi0", "-5", "--l2", "x", "--l3", "-1", "--ground", "0"], tmp_path / "o")
    assert rc == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert [ln.split(": ")[2] for ln in err] == ["--phi0", "--l2", "--l3", "--ground"]


def test_help_is_fast_and_lists_synth():
    code = ("import sys, time; t = time.perf_counter(); "
            "from crankdyn.cli import build_parser; p = build_parser(); "
            "h = p.format_help(); dt = time.perf_counter() - t; "
            "print('synth' in h, dt, any(m in sys.modules for m in "
            "('numpy', 'pandas', 'matplotlib', 'openpyxl')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out[0] == "True"
    assert out[2] == "False"            # cmd_synth imports no heavy library at module top
    # ``python -m crankdyn --help`` as a whole loads none of them either (what kept it
    # within its 0.3 s budget; a clock here failed on a busy machine, issue #19)
    code = ("import runpy, sys; sys.argv = ['crankdyn', '--help']\n"
            "try:\n    runpy.run_module('crankdyn', run_name='__main__')\n"
            "except SystemExit as e:\n    rc = e.code\n"
            "print(rc, sorted(m for m in ('numpy', 'pandas', 'matplotlib', 'openpyxl',"
            " 'scipy') if m in sys.modules), file=sys.stderr)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       check=True)
    assert "synth" in r.stdout
    assert r.stderr.strip().splitlines()[-1] in ("0 []", "None []"), r.stderr


def test_synth_help_mentions_the_modes(capsys):
    with pytest.raises(SystemExit):
        main(["synth", "--help", "--lang", "en"])
    text = capsys.readouterr().out
    for opt in ("--phi0", "--l1", "--l2", "--l3", "--mu-min", "--ground", "--output",
                "--lang"):
        assert opt in text
    assert "--lang LANG" in text and "one of ru, en, zh" in " ".join(text.split())
    assert "default" in text.split("--lang")[-1]
    # the default help is Russian, the reports' default language
    with pytest.raises(SystemExit):
        main(["synth", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "одно из ru, en, zh" in text and "по умолчанию" in text.split("--lang")[-1]


def test_toml_writer_round_trip():
    from linkage.synthesis_report import dumps_toml

    spec = syn.to_spec(0.1, 0.7, 0.6, 1.0, name='a "quoted" name\\', omega_rad_s=2.5)
    spec["links"] = {"coupler": {"mass_kg": 1.5, "cg": [0.1, 0.0],
                                 "points": {"E": [0.3, 0.05]}}}
    spec["load"] = [{"link": "rocker", "moment_Nm": 12.0},
                    {"link": "rocker", "resistance_Nm": 100.0, "stroke": "working"}]
    text = dumps_toml(spec, "comment line")
    assert text.startswith("# comment line\n")
    assert tomllib.loads(text) == spec
    with pytest.raises(ValueError, match="not finite"):
        dumps_toml({"a": math.inf})


# ----------------------------------------------------------------------- --lang ru|en
CYRILLIC = re.compile("[\u0400-\u04FF]")
NUMBER = re.compile(r"\d+(?:\.\d+)?")
PAPER = ["--phi0", "30", "--l2", "0.9", "--mu-min", "40", "--l1-step", "0.01", "--ground",
         "0.5"]


@pytest.fixture(scope="module")
def both(tmp_path_factory, figures_rendered_only_within):
    """The paper's example (seed 004, example 2 to Fig. 3) run in both languages into one
    folder name each: {lang: (folder, printed lines)}.  Its tests read the terminal text,
    the file names, tables, spec, workbook and the SVGs' texts: the SVGs are rendered,
    the PNGs saved unrendered (test_paper_example_fig3_with_ground renders this example's
    PNGs; their layout is checked in tests/test_figures_clean.py)."""
    import contextlib
    import io

    out = {}
    for lang in ("ru", "en"):
        d = tmp_path_factory.mktemp("synth") / "out"
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf), figures_rendered_only_within(".svg"):
            assert main(["synth", *PAPER, "-o", str(d), "--lang", lang]) == 0
        out[lang] = (d, buf.getvalue().splitlines())
    return out


def test_default_language_is_russian(tmp_path, capsys):
    assert run(["--l1", "0.146", "--no-plots"], tmp_path / "o") == 0
    printed = capsys.readouterr().out
    assert printed.startswith("ККМ-30°: область существования")
    assert "Тип по Грасгофу: кривошипно-коромысловый" in printed


def test_terminal_summary_speaks_the_report_language(both):
    ru, en = both["ru"][1], both["en"][1]
    assert not CYRILLIC.search("\n".join(en)), [ln for ln in en if CYRILLIC.search(ln)]
    assert en[0].startswith("KKM-30°: region of existence 0 < λ1 ≤ 0.1896")
    assert "  Grashof type: crank-rocker" in en
    assert "  lengths: crank 0.04 m, coupler 0.45 m, rocker 0.120246 m, ground 0.5 m" in en
    assert en[-1].startswith(f"written to {both['en'][0]}: kkm-30_table1.csv, ")
    assert ru[0].startswith("ККМ-30°: область существования 0 < λ1 ≤ 0.1896")
    assert "  Тип по Грасгофу: кривошипно-коромысловый" in ru
    assert "  длины: кривошип 0.04 м, шатун 0.45 м, коромысло 0.120246 м, стойка 0.5 м" in ru
    assert ru[-1].startswith(f"записано в {both['ru'][0]}: kkm-30_table1.csv, ")
    # no English word in the Russian summary (file names and the paper's μmin, λ1max aside)
    words = set(re.findall(r"[A-Za-z]{2,}", "\n".join(ru[:-1])))
    assert words <= {"min", "max"}, words
    # the numbers are formatted once: the same in both (the folders' names aside);
    # seed 004: λ1 = 0.08, λ3 = 0.24 (0.2405), μmin 46°16′ with λ3 rounded (46°24′ exact)
    assert sorted(NUMBER.findall("\n".join(ru[:-1]))) == sorted(
        NUMBER.findall("\n".join(en[:-1])))
    assert "  λ1 = 0.0800   λ2 = 0.9000   λ3 = 0.2405   (λ0 = 1)" in ru
    assert any("46°24′" in ln for ln in ru) and any("46°24′" in ln for ln in en)


def test_files_and_numbers_identical_in_both_languages(both):
    (d_ru, _), (d_en, _) = both["ru"], both["en"]
    names = sorted(p.name for p in d_ru.iterdir())
    assert names == sorted(p.name for p in d_en.iterdir())
    for name in names:
        if name.endswith(".csv"):                   # tables: language-neutral, identical
            assert (d_ru / name).read_bytes() == (d_en / name).read_bytes(), name
    m = pd.read_csv(d_en / "kkm-30_mechanism.csv").iloc[0]
    assert m["l1"] == 0.08 and round(m["l3"], 2) == 0.24           # seed 004, Fig. 3
    # the spec TOML: same numbers, comments in the report language
    t_ru = (d_ru / "kkm-30.toml").read_text(encoding="utf-8")
    t_en = (d_en / "kkm-30.toml").read_text(encoding="utf-8")
    assert tomllib.loads(t_ru) == tomllib.loads(t_en)
    assert not CYRILLIC.search(t_en)
    assert t_ru.startswith("# ККМ-30°: кривошипно-коромысловый механизм")


def _cells(path):
    wb = load_workbook(path)
    return wb, [(ws.title, c.coordinate, c.value) for ws in wb.worksheets
                for row in ws.iter_rows() for c in row if c.value is not None]


def test_workbook_in_the_report_language_keeps_both_header_rows(both):
    from crankbase.texts import keys, texts

    wb_ru, ru = _cells(both["ru"][0] / "kkm-30_synthesis.xlsx")
    wb_en, en = _cells(both["en"][0] / "kkm-30_synthesis.xlsx")
    assert wb_ru.sheetnames == ["Таблица 1", "Механизм"]
    assert wb_en.sheetnames == ["table1", "mechanism"]
    for wb in (wb_ru, wb_en):            # the two header rows: the seed's Russian, CSV names
        rows = [[c.value for c in r] for r in wb.worksheets[0].iter_rows(min_row=2,
                                                                         max_row=3)]
        assert rows == [["Длина λ1", "Длина λ2", "Длина λ3", "μmin, °"],
                        ["l1", "l2", "l3", "mu_min_deg"]]
        assert [c.value for c in wb.worksheets[1][2]][:2] == ["Параметр", "столбец CSV"]
    # English: Cyrillic only in the Russian header row and the Russian label column
    russian = {texts("ru")(k) for k in keys("ru") if k.startswith("synth.book.")}
    bad = [(s, at, v) for s, at, v in en
           if isinstance(v, str) and CYRILLIC.search(v) and v not in russian]
    assert not bad, bad
    assert not any(CYRILLIC.search(name) for name in wb_en.sheetnames)
    mech_en = {r[1].value: r[2].value for r in wb_en["mechanism"].iter_rows(min_row=3)}
    mech_ru = {r[1].value: r[2].value for r in wb_ru["Механизм"].iter_rows(min_row=3)}
    assert mech_en["grashof"] == "crank-rocker"
    assert mech_ru["grashof"] == "кривошипно-коромысловый"
    assert mech_en["method"] == ("given λ2 and μmin ≥ 40°; λ1 rounded down to a multiple "
                                 "of 0.01")
    assert mech_ru["method"].startswith("заданы λ2 и μmin ≥ 40°")
    assert wb_ru.worksheets[0]["A1"].value.startswith("Таблица 1. ККМ-30°")
    assert wb_en.worksheets[0]["A1"].value.startswith("Table 1. KKM-30°")
    # every number in the same cell in both languages, at full precision
    num_ru = [(at, v) for _, at, v in ru if isinstance(v, (int, float))]
    num_en = [(at, v) for _, at, v in en if isinstance(v, (int, float))]
    assert num_ru == num_en and len(num_ru) > 28
    assert mech_en["l3"] == pd.read_csv(both["en"][0] / "kkm-30_mechanism.csv")[
        "l3"].iloc[0]


def test_plot_files_in_both_languages(both):
    """The SVGs (rendered) carry their texts: Russian terms in ru, no Cyrillic letter in
    en."""
    for name in PLOTS:
        ru = (both["ru"][0] / f"kkm-30_{name}.svg").read_text(encoding="utf-8")
        en = (both["en"][0] / f"kkm-30_{name}.svg").read_text(encoding="utf-8")
        for svg in (ru, en):
            assert "<svg" in svg[:500] and len(svg.encode()) > 1000, name
        assert not CYRILLIC.search(en), name
        assert "ККМ-30°" in ru and "KKM-30°" in en, name
