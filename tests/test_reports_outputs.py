"""Outputs are named after the engine or mechanism (issue 14): two runs into one folder
never mix, and a plot an earlier run drew but this one did not is not left behind."""
import shutil

import pytest

from crankbase.output import MANIFEST_NAME, verify_report
from crankdyn.cli import main


def test_two_engines_into_one_folder_do_not_mix(tmp_path, cli_report, unrendered_figures):
    """The diesel's plots are saved unrendered (names only); the petrol report copied in
    is the session's rendered one."""
    out = tmp_path / "o"            # a copy of the session's petrol report (--lang ru)
    shutil.copytree(cli_report("engine", "--example", "petrol", "--lang", "ru").folder, out)
    first = {p.name: p.read_bytes() for p in out.iterdir() if p.name != MANIFEST_NAME}
    assert main(["engine", "--example", "diesel", "-o", str(out)]) == 0
    names = {p.name for p in out.iterdir()} - {MANIFEST_NAME}
    petrol = {n for n in names if n.startswith("petrol-vaz2106")}
    diesel = {n for n in names if n.startswith("diesel-d240")}
    assert petrol == set(first) and len(diesel) == len(petrol)
    assert petrol | diesel == names
    for n in petrol:                                   # the petrol report is untouched
        assert (out / n).read_bytes() == first[n]
    verify_report(out)                   # the manifest lists both reports, intact
    assert unrendered_figures


def test_two_mechanisms_and_stale_plots(tmp_path, capsys, cli_report, unrendered_figures):
    """The press's plots are saved unrendered (names only); the ratchet report copied in
    is the session's rendered one."""
    out = tmp_path / "o"            # a copy of the session's ratchet report
    shutil.copytree(cli_report("linkage", "--example").folder, out)
    assert main(["linkage", "--example", "press", "-o", str(out)]) == 0
    names = {p.name for p in out.iterdir()} - {MANIFEST_NAME}
    assert {"ratchet-drive_kinematics.csv", "crank-press_kinematics.csv",
            "ratchet-drive.xlsx", "crank-press.xlsx", "ratchet-drive_plan.png",
            "crank-press_plan.png"} <= names
    assert not [n for n in names if not n.startswith(("ratchet-drive", "crank-press"))]
    # the same mechanism again without plots: its old plots are removed, and said so
    capsys.readouterr()
    assert main(["linkage", "--example", "ratchet", "-o", str(out), "--no-plots"]) == 0
    assert "удалён" in capsys.readouterr().err             # --lang ru, the default
    names = {p.name for p in out.iterdir()}
    assert not [n for n in names if n.startswith("ratchet-drive_") and n.endswith(".png")]
    assert "crank-press_plan.png" in names            # another mechanism's plots stay
    assert unrendered_figures


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_linkage_inputs_carry_units(cli_report, lang):
    from openpyxl import load_workbook

    # the session's shared run (read-only; test_reports_workbooks reads it too)
    rep = cli_report("linkage", "--example", "ratchet", "--no-plots", "--lang", lang)
    assert rep.rc == 0, rep.err
    ws = load_workbook(rep.folder / "ratchet-drive.xlsx").worksheets[0]     # the inputs
    units = {r[0]: r[2] for r in ws.iter_rows(min_row=4, max_col=3, values_only=True)
             if r[0] and "." in str(r[0])}
    m, rad_s, kg_m2, kg = (("m", "rad/s", "kg·m²", "kg") if lang == "en" else
                           ("м", "рад/с", "кг·м²", "кг"))
    assert units["mechanism.crank"] == m and units["mechanism.omega_rad_s"] == rad_s
    assert units["links.coupler.inertia_kg_m2"] == kg_m2
    assert units["links.crank.mass_kg"] == kg and units["mechanism.kind"] in ("", None)


def test_drawing_option_writes_the_one_to_one_pdfs(tmp_path):
    import re

    assert main(["engine", "--example", "petrol", "-o", str(tmp_path), "--drawing"]) == 0
    pdfs = sorted(p.name for p in tmp_path.glob("*.pdf"))
    assert pdfs == ["petrol-vaz2106_drawing_forces_NKT.pdf", "petrol-vaz2106_drawing_forces_P.pdf",
                    "petrol-vaz2106_drawing_polar.pdf"]
    head = (tmp_path / pdfs[1]).read_bytes()
    box = re.search(rb"/MediaBox\s*\[\s*0\s+0\s+([\d.]+)\s+([\d.]+)", head)
    # a ГОСТ 2.301 sheet (A4 … A1, either orientation), printable at 100 % (#23): the
    # 280 mm wide drawing of the forces (240 mm of α axis + 10 mm + margins 30 mm) and
    # the title block need A2 portrait, 420 × 594 mm, at 72 pt per inch
    w, h = (float(box.group(k)) / 72 * 25.4 for k in (1, 2))
    assert (w, h) == (pytest.approx(420.0, abs=0.01), pytest.approx(594.0, abs=0.01))
