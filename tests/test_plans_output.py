"""End to end: `crankdyn linkage SPEC --plans …` writes the drawings, the tables and the
sheet; the DXF read back with ezdxf holds the vectors of plans.csv in real millimetres on
their layers; the PDF pages are A1/A3 exactly; labels do not overlap; bad input exits 2
with one line per problem and writes nothing."""
import math
import re

import ezdxf
import numpy as np
import pandas as pd
import pytest

import linkage
import plans
from crankdyn.cli import main
from crankbase.resources import example_path
from plans import drawing, layout
from plans.dxf import APPID, LAYERS

PT = 72.0 / 25.4
RATCHET = "ratchet-drive"      # examples/ratchet.toml: mechanism.name, the files' stem
PRESS = "crank-press"          # examples/press.toml


def _pages(pdf_path):
    """(width, height) in points of every page of a PDF (its /MediaBox entries)."""
    data = pdf_path.read_bytes()
    boxes = re.findall(rb"/MediaBox\s*\[\s*([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s*\]",
                       data)
    return [(float(c) - float(a), float(d) - float(b)) for a, b, c, d in boxes]


#: ``crankdyn linkage --example --plans 5,11 --no-plots`` (the ratchet, Russian): the
#: session's shared run (read-only), which tests/test_cli_linkage.py reads too (its
#: Russian terminal text with the plans' lines).
RATCHET_PLANS_ARGV = ("linkage", "--example", "--plans", "5,11", "--no-plots")


@pytest.fixture(scope="module")
def ratchet_run(cli_report):
    rep = cli_report(*RATCHET_PLANS_ARGV)
    assert rep.rc == 0, rep.err
    return rep.folder


@pytest.fixture(scope="module")
def press_run(tmp_path_factory, figures_rendered_only_within):
    """``crankdyn linkage press.toml --plans 2 --sheet A3 --lang en --measured …`` with a
    title block: its drawings (the position's plans, the sheets and their previews)
    rendered; its five linkage plots saved unrendered (their names are read here; the
    press's plots are rendered in the session's shared ``linkage --example press``)."""
    d = tmp_path_factory.mktemp("plans_press")
    spec = d / "press.toml"
    spec.write_text(example_path("press.toml").read_text() + """
[drawing]
designation = "ТММ.КП.01.000"
organization = "ВолгГТУ, гр. М-301"
developer = "Иванов"
scale = "1:2"
""", encoding="utf-8")
    measured = d / "measured.csv"
    measured.write_text("position,plan,segment,length_mm,value\n"
                        "2,velocity,pb,80.0,\n2,,omega3,,1.5\n", encoding="utf-8")
    out = d / "out"
    with figures_rendered_only_within("_plans_", "_sheet") as saved:
        assert main(["linkage", str(spec), "-o", str(out), "--plans", "2", "--sheet", "A3",
                     "--lang", "en", "--measured", str(measured)]) == 0
    assert sorted(name.lstrip(".").split(".")[0] for name, drawn in saved
                  if not drawn) == sorted(f"{PRESS}_{s}" for s in (
                      "accelerations", "driving_moment", "plan", "transmission_angle",
                      "velocities"))
    return out


def _files(folder):
    return {p.name for p in folder.iterdir() if not p.name.startswith(".")}


def test_files(ratchet_run, press_run):
    """Every output is named after the mechanism (``<name>_…``), the plans' files as the
    linkage tables, workbook and plots."""
    from plans.report import output_names

    for tag in ("5", "11"):
        for ext in ("svg", "pdf"):
            assert (ratchet_run / f"{RATCHET}_plans_{tag}.{ext}").stat().st_size > 5000
    for name in ("plans_2.png", "plans_2.svg", "plans_2.pdf", "sheet.png", "plan_errors.csv"):
        assert (press_run / f"{PRESS}_{name}").stat().st_size > 100, name
    for run, stem in ((ratchet_run, RATCHET), (press_run, PRESS)):
        for name in ("plans.csv", "lever.csv", "lever_forces.csv", "student_table.csv",
                     "sheet.pdf", "sheet.dxf", "kinematics.csv", "forces.csv"):
            assert (run / f"{stem}_{name}").stat().st_size > 100, name
        assert all(n.startswith(stem + "_") or n == f"{stem}.xlsx" for n in _files(run))
    # exactly the files of plans.report.output_names (and the linkage tables/workbook)
    base = {f"{RATCHET}_kinematics.csv", f"{RATCHET}_forces.csv", f"{RATCHET}.xlsx"}
    assert _files(ratchet_run) == base | set(output_names(RATCHET, ["5", "11"],
                                                          previews=False))
    n_sheets = len(_pages(press_run / f"{PRESS}_sheet.pdf"))
    plots = {f"{PRESS}_{s}.png" for s in ("plan", "velocities", "accelerations",
                                          "driving_moment", "transmission_angle")}
    assert _files(press_run) == ({f"{PRESS}_kinematics.csv", f"{PRESS}_forces.csv",
                                  f"{PRESS}.xlsx"} | plots
                                 | set(output_names(PRESS, ["2"], n_sheets, True)))
    lever = pd.read_csv(ratchet_run / f"{RATCHET}_lever.csv")
    assert list(lever.columns) == ["position", "M_lever_Nm", "M_kinetostatic_Nm",
                                   "difference_percent", "F_lever_N", "F_kinetostatic_N",
                                   "scale_N_per_mm"]
    assert lever["position"].tolist() == [5, 11]
    forces = pd.read_csv(ratchet_run / f"{RATCHET}_forces.csv").set_index("position")
    l_OA = linkage.load_spec(example_path("ratchet.toml")).crank
    for _, r in lever.iterrows():
        assert r["M_kinetostatic_Nm"] == forces.loc[r["position"], "M_drive_Nm"]
        assert abs(r["M_lever_Nm"] - r["M_kinetostatic_Nm"]) < 1e-9 * abs(
            r["M_kinetostatic_Nm"])
        # Fур = Mур/lOA, from the lever equal to the kinetostatic one
        assert math.isclose(r["F_kinetostatic_N"] * l_OA, r["M_kinetostatic_Nm"],
                            rel_tol=1e-12)
        assert abs(r["F_lever_N"] - r["F_kinetostatic_N"]) < 1e-9 * abs(
            r["F_kinetostatic_N"])
    # Fур in plans.csv (crank polygon at μF) and the lever's arrows at the lever's scale
    table = pd.read_csv(ratchet_run / f"{RATCHET}_plans.csv")
    for _, r in lever.iterrows():
        fb = table[(table["position"] == r["position"]) & (table["plan"] == "force_crank")
                   & (table["segment"] == "Fb")].iloc[0]
        assert math.isclose(fb["value"], abs(r["F_kinetostatic_N"]), rel_tol=1e-12)
        assert math.isclose(fb["length_mm"], fb["value"] / fb["scale"], rel_tol=1e-12)
        lv = table[(table["position"] == r["position"]) & (table["plan"] == "lever")]
        assert (lv["scale"] == r["scale_N_per_mm"]).all() and "Fb" in set(lv["segment"])


def test_given_lever_scale(tmp_path, figures_rendered_only):
    """--mu-lever fixes the lever's force scale: every lever arrow is F/μ of it.  (Its
    tables only: the drawings saved unrendered.)"""
    figures_rendered_only()
    out = tmp_path / "out"
    assert main(["linkage", "--example", "-o", str(out), "--plans", "5", "--no-plots",
                 "--mu-lever", "50"]) == 0
    t = pd.read_csv(out / f"{RATCHET}_plans.csv")
    lever = t[t["plan"] == "lever"]
    assert len(lever) > 0 and (lever["scale"] == 50.0).all()
    assert np.allclose(lever["length_mm"], lever["value"] / 50.0, rtol=1e-12)
    assert pd.read_csv(out / f"{RATCHET}_lever.csv")["scale_N_per_mm"].tolist() == [50.0]
    assert (t[t["plan"] != "lever"]["scale"] != 50.0).any()       # the others unchanged


def test_two_mechanisms_share_a_folder(tmp_path, figures_rendered_only):
    """The plans of two mechanisms written into one folder keep each other's files: each
    run replaces only the files named after its own mechanism.  (A check of names and
    bytes kept: the drawings are saved unrendered; ratchet_run and press_run render them.)"""
    figures_rendered_only()
    out = tmp_path / "both"
    assert main(["linkage", "--example", "-o", str(out), "--plans", "5,11",
                 "--no-plots"]) == 0
    first = {n: (out / n).read_bytes() for n in _files(out)}
    assert main(["linkage", "--example", "press", "-o", str(out), "--plans", "2",
                 "--no-plots"]) == 0
    files = _files(out)
    assert {n: (out / n).read_bytes() for n in first} == first      # untouched
    assert f"{PRESS}_plans.csv" in files and f"{PRESS}_sheet.dxf" in files
    # a second run of the ratchet with other positions drops its own old position files
    assert main(["linkage", "--example", "-o", str(out), "--plans", "5",
                 "--no-plots"]) == 0
    files = _files(out)
    assert f"{RATCHET}_plans_11.pdf" not in files and f"{RATCHET}_plans_5.pdf" in files
    assert f"{PRESS}_plans_2.pdf" in files
    press_plans = pd.read_csv(out / f"{PRESS}_plans.csv")
    assert press_plans["position"].unique().tolist() == [2]


def test_mechanism_names_with_a_common_prefix(tmp_path, figures_rendered_only):
    """``press`` and ``press_b`` in one folder: the run of ``press`` keeps ``press_b``'s
    plans (their names start with ``press_`` too; the manifest knows whose they are).
    (Drawings saved unrendered, as in the test above.)"""
    figures_rendered_only()
    text = example_path("press.toml").read_text(encoding="utf-8")
    assert text.count(f'name = "{PRESS}"') == 1
    specs = {}
    for n in ("press", "press_b"):
        specs[n] = tmp_path / f"{n}.toml"
        specs[n].write_text(text.replace(f'name = "{PRESS}"', f'name = "{n}"'),
                            encoding="utf-8")
    out = tmp_path / "out"
    assert main(["linkage", str(specs["press_b"]), "-o", str(out), "--plans", "2",
                 "--no-plots"]) == 0
    b_files = {n: (out / n).read_bytes() for n in _files(out)}
    assert "press_b_plans_2.pdf" in b_files and "press_b_sheet.dxf" in b_files
    for plans_arg in ("2", "3"):
        assert main(["linkage", str(specs["press"]), "-o", str(out), "--plans", plans_arg,
                     "--no-plots"]) == 0
        assert {n: (out / n).read_bytes() for n in b_files} == b_files
    assert "press_plans_3.pdf" in _files(out) and "press_plans_2.pdf" not in _files(out)


def test_error_table_written(press_run):
    et = pd.read_csv(press_run / f"{PRESS}_plan_errors.csv")
    st_ = pd.read_csv(press_run / f"{PRESS}_student_table.csv")
    pb = st_[(st_["plan"] == "velocity") & (st_["segment"] == "pb")].iloc[0]
    row = et[et["segment"] == "pb"].iloc[0]
    assert math.isclose(row["measured_value"], 80.0 * pb["scale"], rel_tol=1e-12)
    assert math.isclose(row["error_percent"],
                        100 * (pb["value"] - 80.0 * pb["scale"]) / pb["value"], rel_tol=1e-12)
    om = et[et["quantity"] == "omega3"].iloc[0]
    assert math.isclose(om["error_percent"], 100 * (om["exact_value"] - 1.5) / om["exact_value"])


@pytest.mark.parametrize("run, stem, size", [("ratchet_run", RATCHET, (841.0, 594.0)),
                                             ("press_run", PRESS, (420.0, 297.0))])
def test_pdf_page_size_is_the_sheet(run, stem, size, ratchet_run, press_run):
    """(Both module runs asked for by name, not through ``request.getfixturevalue``: so
    the test is in the module's xdist group and reads the runs its worker built.)"""
    out = {"ratchet_run": ratchet_run, "press_run": press_run}[run]
    pages = _pages(out / f"{stem}_sheet.pdf")
    assert pages
    for w, h in pages:
        assert abs(w - size[0] * PT) < 0.01 and abs(h - size[1] * PT) < 0.01


def test_position_drawing_is_true_scale(ratchet_run):
    """The per-position PDF is exactly the laid-out size in mm; its SVG says so in pt."""
    res = linkage.analyze(example_path("ratchet.toml"))
    pp = plans.build_plans(res, [5])[0]
    fig = drawing.position_figure(pp)
    w_mm, h_mm = fig.get_size_inches() * 25.4
    (w, h), = _pages(ratchet_run / f"{RATCHET}_plans_5.pdf")
    assert abs(w - w_mm * PT) < 0.01 and abs(h - h_mm * PT) < 0.01
    svg = (ratchet_run / f"{RATCHET}_plans_5.svg").read_text()
    m = re.search(r'width="([\d.]+)pt" height="([\d.]+)pt"', svg)
    assert abs(float(m.group(1)) - w_mm * PT) < 0.01
    # the axes map 1 data unit to 1 mm: the x range equals the width in mm
    ax = fig.axes[0]
    assert ax.get_xlim() == (0.0, pytest.approx(w_mm)) and ax.get_position().width == 1.0


@pytest.mark.parametrize("run, stem", [("ratchet_run", RATCHET), ("press_run", PRESS)])
def test_dxf_read_back_equals_plans_csv(run, stem, ratchet_run, press_run):
    """Every vector of plans.csv (the plans, the polygons with Fур, and the lever's force
    arrows at the lever's scale) is one LINE of its layer in the DXF, as long in mm as
    its ``length_mm`` = value/scale, with its arrowhead."""
    out = {"ratchet_run": ratchet_run, "press_run": press_run}[run]
    table = pd.read_csv(out / f"{stem}_plans.csv")
    files = sorted(out.glob(f"{stem}_sheet*.dxf"))
    found = {}
    for f in files:
        doc = ezdxf.readfile(f)
        assert doc.header["$INSUNITS"] == 4          # millimetres
        for name, lw in LAYERS.items():
            assert doc.layers.get(name).dxf.lineweight == lw
        msp = doc.modelspace()
        for layer in ("VECTORS", "LEVER"):
            n = 0
            for e in msp.query(f"LINE[layer=='{layer}']"):
                assert e.has_xdata(APPID)
                name = e.get_xdata(APPID)[0].value
                assert name not in found
                assert (name.split(":")[1] == "lever") == (layer == "LEVER"), name
                found[name] = (e.dxf.end - e.dxf.start).magnitude
                n += 1
            # every vector has its arrowhead on the same layer
            assert len(msp.query(f"SOLID[layer=='{layer}']")) == n
        # the sheet's limits and its outer trim line: the sheet's size
        xs = [p for e in msp.query("LINE[layer=='THIN']") for p in (e.dxf.start.x,
                                                                    e.dxf.end.x)]
        assert max(xs) == pytest.approx(doc.header["$LIMMAX"][0])
    expected = {f"{r.position}:{r.plan}:{r.segment}": r.length_mm
                for r in table.itertuples() if r.length_mm > 1e-6}
    assert set(found) == set(expected)
    for k, v in expected.items():
        assert math.isclose(found[k], v, rel_tol=1e-9, abs_tol=1e-9), k
    # the lever's arrows: F/μF of the lever, read back from the DXF
    lever = table[table["plan"] == "lever"]
    assert len(lever) > 0 and lever.groupby("position")["scale"].nunique().eq(1).all()
    for r in lever.itertuples():
        if r.length_mm > 1e-6:
            key = f"{r.position}:lever:{r.segment}"
            assert math.isclose(found[key], r.value / r.scale, rel_tol=1e-9), key
    assert {f"{p}:force_crank:Fb" for p in table["position"].unique()} <= set(found)
    # one DXF per page of the PDF (A3 needs several sheets for the press)
    assert len(files) == len(_pages(out / f"{stem}_sheet.pdf"))
    assert (len(files) == 1) == (run == "ratchet_run")


def test_title_block_fields(press_run):
    doc = ezdxf.readfile(press_run / f"{PRESS}_sheet.dxf")
    texts = {e.dxf.text for e in doc.modelspace().query("TEXT")}
    for s in ("ТММ.КП.01.000", "ВолгГТУ, гр. М-301", "Иванов", "1:2", "crank-press",
              "Sheet 1", f"Sheets {len(_pages(press_run / f'{PRESS}_sheet.pdf'))}"):
        assert s in texts, s
    # English drawing: no Cyrillic except the fields the user typed
    user = {"ТММ.КП.01.000", "ВолгГТУ, гр. М-301", "Иванов"}
    assert not [t for t in texts - user if re.search("[а-яА-ЯёЁ]", t)]


@pytest.mark.parametrize("which, chosen, lang", [("ratchet.toml", [5, 11], "ru"),
                                                 ("press.toml", [2, 8], "en")])
def test_nothing_overlaps_and_every_vector_is_labelled(which, chosen, lang):
    res = linkage.analyze(example_path(which))
    pps = plans.build_plans(res, chosen)
    for sh in drawing.layout_sheets(res, pps, lang, "A1"):
        assert drawing.check_no_overlap(sh.items) == []
        # diagrams are inside the frame and clear of the title block
        for it in sh.items:
            if isinstance(it, layout.Arrow):
                for z in (it.p1, it.p2):
                    assert 20 < z.real < sh.width - 5 and 5 < z.imag < sh.height - 5
                    assert not (z.real > sh.width - 5 - 185 and z.imag < 5 + 55)
    for pp in pps:
        for kind in ("velocity", "acceleration", "force_dyad", "force_crank"):
            b = layout.diagram_block(pp, kind, lang)
            arrows = [i for i in b.items if isinstance(i, layout.Arrow)]
            texts = [i for i in b.items if isinstance(i, layout.Text)]
            vecs = pp.plans[kind].vectors
            assert len(arrows) == len(vecs)
            n_points = len(pp.plans[kind].point_labels) if kind in ("velocity",
                                                                    "acceleration") else 0
            assert len(texts) == sum(v.length_mm > 1e-6 for v in vecs) + n_points + 2
            labels = {t.text for t in texts}
            for v in vecs:
                assert layout.vector_label(v, lang) in labels
            if lang == "en":
                assert not [t for t in labels if re.search("[а-яА-ЯёЁ]", t)]
        lb = layout.lever_block(pp, lang)
        assert len([i for i in lb.items if isinstance(i, layout.Arrow)]) == \
            sum(f.force != 0 for f in pp.lever.forces) + 1
        lever_texts = {i.text for i in lb.items if isinstance(i, layout.Text)}
        assert ("Fур" if lang == "ru" else "Fb") in lever_texts
        for f in pp.lever.forces:
            if f.force != 0:
                assert (f.label_ru if lang == "ru" else f.label_en) in lever_texts


def test_bad_input_exits_2_and_writes_nothing(tmp_path, capsys):
    out = tmp_path / "out"
    spec = str(example_path("ratchet.toml"))
    assert main(["linkage", "--lang", "en",
                 spec, "-o", str(out), "--plans", "0,x", "--sheet", "A4",
                 "--mu-a", "-2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 4 and all(line.startswith("crankdyn linkage: error: ") for line in err)
    assert not out.exists()
    assert main(["linkage", "--lang", "en", spec, "-o", str(out), "--plans", "5,13"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["crankdyn linkage: error: --plans: position 13 is not in the analysis; "
                   "valid: 1…12"]
    assert not out.exists()
    # position 11's acceleration plan (≈ 250 mm at μa = 0.4) does not fit an A3 sheet
    # beside the title block: at the default scale it is drawn at the next round one
    # (plans.drawing.fit_plans), at the scale the student fixed it is refused before
    # anything is written
    assert main(["linkage", "--lang", "en", spec, "-o", str(out), "--plans", "11",
                 "--sheet", "A3", "--mu-a", "0.4"]) == 2
    err = capsys.readouterr().err
    assert "does not fit" in err and "Traceback" not in err
    assert not out.exists()
    assert main(["linkage", "--lang", "en", spec, "-o", str(out), "--measured", "x.csv"]) == 2
    assert "only with --plans" in capsys.readouterr().err
    assert main(["linkage", "--lang", "en", spec, "-o", str(out), "--mu-lever", "50"]) == 2
    assert "only with --plans" in capsys.readouterr().err
    assert main(["linkage", "--lang", "en",
                 spec, "-o", str(out), "--plans", "5", "--mu-lever", "0"]) == 2
    assert capsys.readouterr().err.strip() == ("crankdyn linkage: error: --mu-lever: got 0; "
                                               "must be a positive number")
    assert not out.exists()
    bad = tmp_path / "bad.toml"
    bad.write_text(example_path("ratchet.toml").read_text() + '\n[drawing]\nauthor = "X"\n',
                   encoding="utf-8")
    assert main(["linkage", "--lang", "en", str(bad), "-o", str(out), "--plans", "5"]) == 2
    assert "drawing.author: unknown key" in capsys.readouterr().err
    assert not out.exists()


def test_massless_unloaded_mechanism_draws(tmp_path):
    """No masses and no loads: the force polygons are all zero; the drawing and the DXF
    are still written (nothing to label, nothing crashes)."""
    spec = {"mechanism": {"kind": "crank-rocker", "name": "bare", "crank": 0.1,
                          "coupler": 0.4, "rocker": 0.3, "ground": 0.45,
                          "omega_rad_s": 5.0},
            "analysis": {"positions": 6, "working_stroke": "ccw"}}
    res = linkage.analyze(spec)
    pps = plans.build_plans(res, [2])
    assert pps[0].lever.M_kinetostatic_Nm == 0 and pps[0].lever.M_lever_Nm == 0
    from plans.report import write_plans
    info = write_plans(res, pps, tmp_path, previews=False)
    assert info["sheets"] == 1 and (tmp_path / "bare_sheet.dxf").is_file()
    assert pps[0].lever.balancing_force_N == 0 and pps[0].lever.F_kinetostatic_N == 0


# ------------------------------------------- one position at a time on the sheets (#23)

def _sheet_positions(sh):
    """The positions whose diagrams a sheet holds, from its vectors' names."""
    from plans.layout import Arrow

    return {it.name.split(":")[0] for it in sh.items if isinstance(it, Arrow) and it.name}


@pytest.mark.parametrize("example, size", [("press.toml", "A1"), ("press.toml", "A3"),
                                           ("ratchet.toml", "A1")])
def test_each_sheet_holds_one_or_two_positions(example, size):
    """A teacher grades one position at a time: every sheet holds the diagrams of one
    position or of two, a position's diagrams lie on consecutive sheets, and on A1 all
    five diagrams of a position lie on one sheet."""
    spec = linkage.load_spec(example_path(example))
    result = linkage.analyze(spec)
    plan_list = plans.build_plans(result, "all")
    sheets = drawing.layout_sheets(result, plan_list, "ru", size)
    where = {}
    for k, sh in enumerate(sheets):
        tags = _sheet_positions(sh)
        assert tags == {b.split(":")[0] for b in sh.blocks if b != "positions"}
        assert 1 <= len(tags) <= 2 or sh.blocks == ["positions"], (k + 1, sorted(tags))
        for tag in tags:
            where.setdefault(tag, []).append(k)
    assert set(where) == {pp.tag for pp in plan_list}
    for tag, ks in where.items():
        assert ks == list(range(ks[0], ks[-1] + 1)), (tag, ks)
        if size == "A1":
            assert len(ks) == 1, (tag, ks)
    assert "positions" in sheets[0].blocks


def test_render_items_adds_what_add_line_and_add_patch_add():
    """plans.drawing.render_items adds its lines and patches with one update of the
    axes' data limits: the artists are those ``add_line``/``add_patch`` add (the same
    data, clip box, transform and ``_child<n>`` labels, in the same order) and, on
    axes that autoscale, the data limits and the autoscaled view are the same."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    items = [layout.Line(10 + 5j, 60 + 25j, "MAIN"), layout.Text(30 + 40j, "A"),
             layout.Arrow(-20 + 0j, -20 + 70j), layout.Line(0j, 5 + 5j, "DASHED"),
             layout.Circle(80 + 10j, 7.5, filled=True), layout.Circle(-5 - 30j, 2.0)]

    fig = Figure()
    ax, ref = fig.subplots(1, 2)
    ax.plot([0, 1])
    ref.plot([0, 1])
    drawing.render_items(ax, items)
    real_line, real_patch = ref.add_line, ref.add_patch
    ref.add_artist = lambda a: (real_line(a) if isinstance(a, Line2D) else real_patch(a))
    drawing.render_items(ref, items)
    assert np.allclose(ax.dataLim.get_points(), ref.dataLim.get_points(), atol=1e-9)
    head_x0 = min(z.real for z in layout.arrow_parts(-20 + 0j, -20 + 70j))
    assert head_x0 < -20                              # the head is wider than its shaft
    assert np.allclose(ax.dataLim.get_points(), [[head_x0, -32], [87.5, 70]], atol=1e-9)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg(fig).draw()
    assert ax.get_xlim() == pytest.approx(ref.get_xlim())
    assert ax.get_ylim() == pytest.approx(ref.get_ylim())
    assert [type(a) for a in ax.get_children()] == [type(a) for a in ref.get_children()]
    assert [ln.get_label() for ln in ax.lines] == [ln.get_label() for ln in ref.lines]
    assert [ln.get_label() for ln in ax.lines][:2] == ["_child0", "_child1"]
    for a, b in zip(ax.lines, ref.lines):
        assert np.array_equal(a.get_xydata(), b.get_xydata())
        assert a.get_clip_box().bounds == ax.bbox.bounds         # clipped by their axes
        assert b.get_clip_box().bounds == ref.bbox.bounds
        assert a.get_transform() is ax.transData and b.get_transform() is ref.transData
    for a, b in zip(ax.patches, ref.patches):
        assert np.array_equal(a.get_path().vertices, b.get_path().vertices)
        assert a.get_clip_box().bounds == ax.bbox.bounds
        assert b.get_clip_box().bounds == ref.bbox.bounds
