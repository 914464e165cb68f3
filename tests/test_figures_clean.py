"""Nothing overlaps, nothing is cut (issue #23): every figure the tool draws for every
bundled example, in both languages, built through the library's plot functions (no file
written) and checked by :func:`figure_check.figure_problems`: texts against texts, against
the figure's edge and against the drawn lines."""
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from crankbase.output import paused_gc
from crankbase.resources import example_path

pytest.importorskip("matplotlib")
sys.path.insert(0, str(Path(__file__).resolve().parent))
from figure_check import figure_problems, marker_problems  # noqa: E402

LANGS = ("ru", "en")


def _engine(name, bearings=False, drawing=True):
    import engine
    from engine.plots import figures, train_figures

    study = engine.load(example_path(name))
    whole = engine.analyze_engine(study.spec, study.train, study.settings)

    def build(lang):
        figs = {**figures(whole.cylinder, lang), **train_figures(whole, lang)}
        if drawing:
            from engine.plots.drawing import drawing_figures
            figs.update(drawing_figures(whole.cylinder, lang))
        if bearings:
            from engine.plots.bearing import bearing_figures
            figs.update(bearing_figures(_bearing_analysis(name, study, whole), lang))
        return figs
    return build


def _bearing_analysis(name, study, whole):
    """The bearing analysis the CLI draws (``engine --bearings``), on the fine grid."""
    from engine.bearings.analysis import bearing_analysis, read_bearing_inputs
    from engine.bearings.train import engine_bearings, layout_cylinders

    spec = study.spec
    inputs = read_bearing_inputs(example_path(name), spec)
    fine = whole.cylinder.curves
    lay = whole.layout
    if lay.n == 1:
        return bearing_analysis(spec, fine, inputs)
    cyl, tau, zt = layout_cylinders(lay)
    cw = [(c.z, c.mr, c.angle_deg) for c in whole.summary.counterweights]
    return engine_bearings(spec, fine["alpha_deg"].to_numpy(), cyl, tau, zt,
                           counterweights=cw, inputs=inputs)


def _linkage(name, sizes=("A1",)):
    import linkage
    import plans
    from linkage.plots import all_figures
    from plans.drawing import layout_sheets, position_figure, sheet_figure

    spec = linkage.load_spec(example_path(name))
    result = linkage.analyze(spec)
    full = linkage.full_turn(spec, 5.0)
    plan_list = plans.build_plans(result, "all")

    def build(lang):
        figs = dict(all_figures(result, full, lang=lang))
        for pp in plan_list:
            figs[f"plans_{pp.tag}"] = position_figure(pp, lang)
        for size in sizes:
            for k, sh in enumerate(layout_sheets(result, plan_list, lang, size)):
                figs[f"sheet_{size}_{k + 1}"] = sheet_figure(sh)
        return figs
    return build


def _synth():
    from linkage import synthesis as syn
    from linkage import synthesis_plots as plots

    phi0 = 30.0
    design = syn.design_for_mu_min(0.9, 40.0, phi0, l1_step=0.01)
    region = syn.existence_region(phi0)
    family = syn.right_angle_family(design.l1, phi0)
    phi = np.arange(0.0, 361.0, 1.0)
    mu = syn.transmission_angle_deg(phi, design.l1, design.l2, design.l3)

    def build(lang):
        return {"region": plots.plot_region(region, design, family=family,
                                            lang=lang).figure,
                "mu_min": plots.plot_mu_min_curves(syn.mu_min_curves(phi0), design,
                                                   mu_required=40.0, lang=lang).figure,
                "transmission_angle": plots.plot_transmission_angle(
                    phi, mu, design, lang=lang).figure}
    return build


def _dynamics(name):
    from dynamics.plots import dynamics_figures
    from dynamics.spec import load_dynamics_spec, run_job

    res = run_job(load_dynamics_spec(example_path(name)))
    return lambda lang: dynamics_figures(res, lang)


def _balance(example):
    """The balance study's own figures (dynamics.balance_study.balance_figures)."""
    from dynamics.balance_study import balance_figures, run_study

    report = run_study(example_path(example))
    return lambda lang: balance_figures(report, lang)


def _torsion(name):
    """The torsion report's figures (torsion.study.build_outputs): the inline six beside
    its throws (all five figures) or the three-rotor chain by hand (the mode shapes)."""
    from torsion.study import build_outputs, load, run_study

    report = run_study(load(example_path(name)))
    return lambda lang: build_outputs(report, lang)[1]


def _rotor():
    return _balance("rotor_two_plane.toml")


def _shaking():
    return _balance("ratchet_balance.toml")


#: Every bundled example: how its figures are built, and whether they are saved with a
#: tight bounding box (``crankdyn synth``: the edge is the content's).
EXAMPLES = {
    "engine-petrol": (lambda: _engine("petrol_vaz2106.toml", bearings=True), True),
    "engine-diesel": (lambda: _engine("diesel_d240.toml", bearings=True), True),
    "engine-six": (lambda: _engine("petrol_bmw_m54.toml", bearings=True), True),
    "engine-v8": (lambda: _engine("diesel_kamaz740.toml", bearings=True), True),
    "linkage-ratchet": (lambda: _linkage("ratchet.toml"), True),
    "linkage-press": (lambda: _linkage("press.toml", ("A1", "A3")), True),
    "synth": (_synth, False),
    "dynamics-flywheel": (lambda: _dynamics("flywheel_seed.toml"), True),
    "dynamics-press": (lambda: _dynamics("press_dynamics.toml"), True),
    "dynamics-petrol": (lambda: _dynamics("petrol_dynamics.toml"), True),
    "dynamics-hoist": (lambda: _dynamics("hoist_machine.toml"), True),
    "balance-rotor": (_rotor, True),
    "balance-ratchet": (_shaking, True),
    "torsion-six": (lambda: _torsion("torsion_inline6.toml"), True),
    "torsion-three-rotor": (lambda: _torsion("torsion_three_rotor.toml"), True),
}


CYRILLIC = re.compile("[\u0400-\u04FF]")
MATH = re.compile(r"\$[^$]*\$")


def _texts(fig):
    """Every ``Text`` of ``fig`` without making ticks (a sheet's or a drawing's axes,
    switched off, would make their thousand-odd ticks only for the search):
    :func:`crankbase.plot_texts.figure_texts`."""
    from crankbase.plot_texts import figure_texts

    return list(figure_texts(fig))


def _word_problems(fig, lang):
    """Words no figure may show: a literal underscore outside mathtext ("M_d": #23), and
    in English a Cyrillic letter."""
    out = []
    for t in _texts(fig):
        s = t.get_text()
        if not s or not t.get_visible():
            continue
        if "_" in MATH.sub("", s):
            out.append(f"literal underscore: {s!r}")
        if lang == "en" and CYRILLIC.search(s):
            out.append(f"Cyrillic in an English figure: {s!r}")
    return out


@pytest.fixture(autouse=True)
def _collector_paused():
    """Python's cyclic garbage collector paused while a test builds and checks its
    figures, resumed after it (a figure's artists refer to each other: what a test
    drops is collected then).  Building a report's figures makes half a million
    objects, none of them garbage until the figure is dropped, and each full collection
    walked every one of them again: about half of the CPU of building a linkage's
    plans and sheets.  Nothing checked changes: every figure is built and checked as
    before."""
    with paused_gc():
        yield


@pytest.fixture(scope="module", params=list(EXAMPLES))
def example(request):
    make, edge = EXAMPLES[request.param]
    return request.param, make(), edge


#: ``{(example, lang): {stem: marker problems}}`` of the torsion figures, found by
#: test_nothing_overlaps_nothing_is_cut on the figures it has just laid out, read by
#: test_torsion_marks_are_drawn_whole (which builds and checks them itself when it runs
#: alone or first).
_MARKS = {}


@pytest.mark.parametrize("lang", LANGS)
def test_nothing_overlaps_nothing_is_cut(example, lang):
    name, build, edge = example
    figs = build(lang)
    assert figs
    found = []
    marks = {}
    # the figures are dropped with the test, not cleared (Figure.clear re-creates every
    # axes' ticks and spines: about a fifth of the CPU of checking the figure)
    for stem, fig in figs.items():
        found += [f"{name} [{lang}] {stem}: {p}" for p in figure_problems(fig, edge=edge)]
        found += [f"{name} [{lang}] {stem}: {p}" for p in _word_problems(fig, lang)]
        if name.startswith("torsion"):                  # laid out just now
            marks[stem] = marker_problems(fig, edge=edge, draw=False)
    if marks:
        _MARKS[name, lang] = marks
    assert not found, "\n".join(found[:60]) + f"\n({len(found)} problems)"


@pytest.mark.parametrize("example", [k for k in EXAMPLES if k.startswith("torsion")],
                         indirect=True)
@pytest.mark.parametrize("lang", LANGS)
def test_torsion_marks_are_drawn_whole(example, lang):
    """Issue #21: the lone marks of the torsion figures (the response's "largest" circle,
    the Campbell diagram's critical speeds) are drawn whole.  On the inline six the
    largest vibration torque lies at the top of the speed range (6500 rpm, its right
    edge): a mark clipped by the axes showed half a circle there.  (The torsion study
    is the module's, computed once for both tests; the marks are those the test above
    found on the same figures, laid out once for both checks, when it ran first:
    :data:`_MARKS`.)"""
    name, build, edge = example
    marks = _MARKS.pop((name, lang), None)
    if marks is None:
        marks = {}
        for stem, fig in build(lang).items():
            marks[stem] = marker_problems(fig, edge=edge)
    assert marks
    found = [f"{name} [{lang}] {stem}: {p}" for stem, ps in marks.items() for p in ps]
    assert not found, "\n".join(found)


def test_the_check_finds_each_kind_of_fault():
    """The checker itself: two texts on top of each other, a text over a curve, an axis
    line through a text, a text cut at the edge; a clean figure has none."""
    from matplotlib.figure import Figure

    def fig_with(draw):
        fig = Figure(figsize=(4, 3))
        ax = fig.add_axes((0.15, 0.15, 0.8, 0.75))
        ax.set_xlim(0, 10)
        ax.set_ylim(0, 10)
        draw(ax)
        return fig

    clean = fig_with(lambda ax: (ax.plot([0, 10], [1, 1]), ax.text(5, 5, "free")))
    assert figure_problems(clean) == []
    both = fig_with(lambda ax: (ax.text(5, 5, "one"), ax.text(5.1, 5.05, "two")))
    assert any(p.startswith("overlap") for p in figure_problems(both))
    curve = fig_with(lambda ax: (ax.plot([0, 10], [5.1, 5.1]),
                                 ax.text(5, 5, "label", va="center")))
    assert any(p.startswith("crossed") for p in figure_problems(curve))
    axis = fig_with(lambda ax: (ax.axvline(5.2), ax.text(5, 5, "label", va="center")))
    assert any("crossed" in p for p in figure_problems(axis))
    edge = fig_with(lambda ax: ax.annotate("far too long a text for this small figure",
                                           (9, 9)))
    assert any(p.startswith("cut") for p in figure_problems(edge))
    mark = fig_with(lambda ax: ax.plot([10], [5], ls="none", marker="o", ms=11))
    assert any(p.startswith("mark cut by its axes") for p in marker_problems(mark))
    whole = fig_with(lambda ax: ax.plot([10], [5], ls="none", marker="o", ms=11,
                                        clip_on=False))
    assert marker_problems(whole) == []
    assert marker_problems(fig_with(lambda ax: ax.plot([5], [5], "o"))) == []
    gap = fig_with(lambda ax: (ax.plot([0, 4, float("nan"), 6, 10], [5.1] * 5),
                               ax.text(5, 5, "x", va="center")))
    assert figure_problems(gap) == []                  # a broken line under a label
    # the lines skipped unsampled (their vertices' extent meets no text box) and those
    # sampled: a circle's edge (a curve) and a line collection through a label are
    # found, the same circle and collection away from it are not; a line of a polar
    # axes (a non-affine transform: sampled along its display path) through a label
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Circle

    ring = fig_with(lambda ax: (ax.add_patch(Circle((5, 3), 2.0, fill=False)),
                                ax.text(5, 5, "label", ha="center", va="center")))
    assert any("Circle edge" in p for p in figure_problems(ring))
    apart = fig_with(lambda ax: (ax.add_patch(Circle((2, 2), 1.0, fill=False)),
                                 ax.add_collection(LineCollection([[(6, 1), (9, 2)]])),
                                 ax.text(5, 7, "label", ha="center", va="center")))
    assert figure_problems(apart) == []
    bunch = fig_with(lambda ax: (ax.add_collection(LineCollection(
        [[(0, 1), (1, 1)], [(4, 5.05), (6, 5.05)]])), ax.text(5, 5, "label", va="center")))
    assert any("by line collection" in p for p in figure_problems(bunch))
    polar = Figure(figsize=(4, 4))
    pax = polar.add_axes((0.1, 0.1, 0.8, 0.8), projection="polar")
    pax.set_ylim(0, 1)
    pax.plot([0.0, np.pi / 2], [0.8, 0.8])           # its chord passes r = 0.8 cos 45°
    pax.text(np.pi / 4, 0.8 * np.cos(np.pi / 4), "chord", ha="center", va="center")
    assert any(p.startswith("crossed: text: 'chord' by line")
               for p in figure_problems(polar))
    pax.texts[0].set_position((np.pi / 4, 0.3))      # inside it: free
    assert not any("chord" in p for p in figure_problems(polar))


@pytest.mark.parametrize("name", ["engine-petrol", "linkage-ratchet"])
def test_chinese_figures_nothing_overlaps_nothing_is_cut(name):
    """Issue #19: the same checks on the Chinese figures of one engine and one linkage
    (as saved: crankbase.output.save_figure sets their Chinese labels' mathtext as plain
    text in a CJK font), and every Chinese label drawn in a font that has its glyphs."""
    from crankbase.plot_texts import cjk_fonts, cjk_texts
    from matplotlib.font_manager import findfont, get_font

    han = re.compile("[\u3000-\u303f\u4e00-\u9fff\uff00-\uffef]")

    if not cjk_fonts():
        pytest.skip("no CJK font installed (fonts-noto-cjk, fonts-wqy-zenhei …)")
    cheap = {"engine-petrol": lambda: _engine("petrol_vaz2106.toml", drawing=False)}
    make, edge = EXAMPLES[name]
    figs = cheap.get(name, make)()("zh")
    found, chinese = [], 0
    for stem, fig in figs.items():
        cjk_texts(fig)
        found += [f"{name} [zh] {stem}: {p}" for p in figure_problems(fig, edge=edge)]
        found += [f"{name} [zh] {stem}: {p}" for p in _word_problems(fig, "zh")]
        from matplotlib.text import Text

        for t in fig.findobj(Text):
            s = t.get_text()
            if not han.search(s):
                continue
            chinese += 1
            assert "$" not in s, (stem, s)
            fonts = [get_font(findfont(f)) for f in t.get_fontfamily()]
            missing = [c for c in set(s) if han.match(c)
                       and not any(f.get_char_index(ord(c)) for f in fonts)]
            assert not missing, (stem, s, missing)
    assert chinese > 10
    assert not found, "\n".join(found[:60]) + f"\n({len(found)} problems)"
