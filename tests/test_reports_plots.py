"""Readability of the engine plots (issue 14): polar-diagram labels never overlap a label,
a marker or an arrow; curves of one plot differ in colour and dash; English plots carry
no Cyrillic letter."""
import re

import numpy as np
import pytest

import engine
from crankbase.resources import example_path

pytest.importorskip("matplotlib")

EXAMPLES = ("petrol_vaz2106.toml", "diesel_d240.toml")
CYRILLIC = re.compile("[\u0400-\u04FF]")


def _result(name):
    study = engine.load(example_path(name))
    return engine.analyze(study.spec, study.settings)


def _fine(name):
    r = _result(name)
    return r.curves, r.spec, r.summary


def _all_figures(name, lang):
    """Every plot of a run: the cylinder's and the whole engine's."""
    from engine.plots import figures, train_figures

    study = engine.load(example_path(name))
    whole = engine.analyze_engine(study.spec, study.train, study.settings)
    return {**figures(whole.cylinder, lang), **train_figures(whole, lang)}


def _boxes(fig, gids):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    fig.draw(canvas.get_renderer())      # what savefig does: layout as printed
    r = canvas.get_renderer()
    ax = fig.axes[0]
    return [(t.get_text(), t.get_window_extent(r)) for t in ax.texts
            if t.get_gid() in gids], r


def _apart(a, b):
    return a.x1 <= b.x0 or b.x1 <= a.x0 or a.y1 <= b.y0 or b.y1 <= a.y0


@pytest.mark.parametrize("name", EXAMPLES)
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_polar_labels_do_not_overlap(name, lang):
    from engine.plots import plot_polar

    result = _result(name)
    spec = result.spec
    fig = plot_polar(result, lang=lang).figure
    labels, r = _boxes(fig, {"alpha-label", "polar-label"})
    ax = fig.axes[0]
    # labels against labels
    for i in range(len(labels)):
        for j in range(i):
            assert _apart(labels[i][1], labels[j][1]), (labels[i][0], labels[j][0])
    # labels against markers (α points and both poles), measured from the drawn lines
    px = fig.dpi / 72
    for line in ax.lines:
        if line.get_gid() not in ("alpha-marker", "pole-marker"):
            continue
        half = line.get_markersize() * px / 2
        for x, y in ax.transData.transform(line.get_xydata()):
            from matplotlib.transforms import Bbox
            mb = Bbox([[x - half, y - half], [x + half, y + half]])
            for text, bb in labels:
                assert _apart(bb, mb), (text, (x, y))
    # labels against arrows: the arrow's straight segment from Oш to its tip
    from matplotlib.text import Annotation
    arrows = [t for t in ax.texts if isinstance(t, Annotation) and t.arrow_patch]
    assert len(arrows) == 2
    for arr in arrows:
        p = ax.transData.transform(arr.xyann)
        q = ax.transData.transform(arr.xy)
        for s in np.linspace(0, 1, 200):
            x, y = p + s * (q - p)
            for text, bb in labels:
                assert not (bb.x0 < x < bb.x1 and bb.y0 < y < bb.y1), text
    # every 30° point is named (merged names count), so the student can trace α
    named = set()
    for text, _ in labels:
        named.update(re.findall(r"^\d+(?:/\d+)*$", text))
    angles = {int(a) for n in named for a in n.split("/")}
    expected = set(range(0, int(spec.cycle_deg), 30))
    assert len(angles & expected) >= 0.9 * len(expected)
    # Rшш max/min and both pole names are present
    texts = " ".join(t for t, _ in labels)
    assert texts.count(" max = ") == 1 and texts.count(" min = ") == 1
    # labels stay inside the axes
    ab = ax.get_window_extent(r)
    for text, bb in labels:
        assert ab.x0 <= bb.x0 and bb.x1 <= ab.x1 and ab.y0 <= bb.y0 and bb.y1 <= ab.y1


def test_place_label_thins_when_no_room():
    """A label that cannot be placed without covering a marker is left out."""
    from matplotlib.figure import Figure

    from crankbase.plot_labels import Obstacles, place_label, renderer_of

    fig = Figure(figsize=(2, 2))
    ax = fig.subplots()
    renderer_of(fig)
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    obs.boxes.append((bb.x0, bb.y0, bb.x1, bb.y1))        # everything is taken
    assert place_label(ax, obs, ((bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2), "30") is None
    obs.boxes.clear()
    t = place_label(ax, obs, ((bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2), "30")
    assert t is not None and len(obs.boxes) == 1


def test_text_size_is_the_drawn_size_and_follows_the_font():
    """crankbase.plot_labels.text_size keeps what it measured: a size read back is the
    box the renderer draws for the text (a fresh measure), and a larger font (a
    property or the rcParams), a bolder one, another dpi or another text is measured
    anew, not read back."""
    from matplotlib import rc_context
    from matplotlib.figure import Figure

    from crankbase.plot_labels import renderer_of, text_size

    def fresh(fig, text, **kw):
        t = fig.text(0.3, 0.6, text, **kw)
        bb = t.get_window_extent(renderer_of(fig))
        t.remove()
        return bb.width, bb.height

    fig = Figure(figsize=(3, 2))
    first = text_size(fig, "240/600", fontsize=7)
    assert text_size(fig, "240/600", fontsize=7) == first
    assert first == pytest.approx(fresh(fig, "240/600", fontsize=7), abs=1e-9)
    bigger = text_size(fig, "240/600", fontsize=14)
    assert bigger[0] > 1.8 * first[0] and bigger[1] > 1.8 * first[1]
    assert text_size(fig, "240/600", fontsize=7, weight="bold")[0] > first[0]
    assert text_size(fig, "240", fontsize=7)[0] < 0.6 * first[0]
    with rc_context({"font.size": 20.0}):
        plain = text_size(fig, "240/600")
        assert plain == pytest.approx(fresh(fig, "240/600"), abs=1e-9)
    assert text_size(fig, "240/600") != plain                  # back at 10 pt
    sharp = Figure(figsize=(3, 2), dpi=200)
    assert text_size(sharp, "240/600", fontsize=7)[0] == pytest.approx(2 * first[0],
                                                                        rel=0.05)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_plot_curves_differ_in_colour_and_dash(lang):
    for stem, fig in _all_figures(EXAMPLES[0], lang).items():
        for ax in fig.axes:
            # faint context curves (one per cylinder under the total) share one style
            lines = [ln for ln in ax.get_lines() if len(ln.get_xdata()) > 2
                     and ln.get_linestyle() != "None" and ln.get_gid() != "context"]
            styles = [(ln.get_color(), ln.get_linestyle()) for ln in lines]
            colours = [c for c, _ in styles]
            dashes = [d for _, d in styles]
            assert len(set(colours)) == len(colours), (stem, styles)
            assert len(set(dashes)) == len(dashes), (stem, styles)


def _all_text(fig):
    out = []
    for t in fig.findobj(lambda a: hasattr(a, "get_text")):
        out.append(t.get_text())
    return "\n".join(out)


@pytest.mark.parametrize("name", EXAMPLES)
def test_english_plots_have_no_cyrillic(name):
    for stem, fig in _all_figures(name, "en").items():
        text = _all_text(fig)
        assert not CYRILLIC.search(text), (stem, CYRILLIC.findall(text))


def test_russian_plots_use_textbook_symbols():
    text = "\n".join(_all_text(f) for f in _all_figures(EXAMPLES[0], "ru").values())
    for symbol in ("ΔPг", "Pj", "Mкр", "Rшш", "Kr.ш", "Oш", "pг", "α"):
        assert symbol in text, symbol


def test_indicator_characteristic_points_and_fullness():
    """The points r, a, c′, c, c″, zд, b′, b″ sit at the spec's angles; those on the curve
    at its pressure, c at pc of the thermal calculation; φп = pi/p′i is in the textbook's
    range for a petrol engine (Kolchin & Demidov 2008: φп = 0.94–0.97)."""
    from engine.plots.diagram_points import characteristic_points, fullness
    from engine.plots import plot_indicator, plot_pressure

    result = _result(EXAMPLES[0])
    fine, spec, summary = result.curves, result.spec, result.summary
    cyc = spec.cycle
    pts = {p.name_ru: p for p in characteristic_points(spec, fine)}
    assert set(pts) == {"r", "a", "c′", "c", "c″", "zд", "b′", "b″"}
    assert pts["c′"].alpha_deg == 360 - cyc.advance
    assert pts["zд"].alpha_deg == 360 + cyc.peak_after_tdc_deg
    assert pts["b′"].alpha_deg == 540 - cyc.exhaust_opening_deg
    assert pts["c"].p == pytest.approx(cyc.pa * cyc.compression_ratio ** cyc.n1)
    phi = fullness(summary)
    assert phi == pytest.approx(summary.pi_MPa / summary.pi_theory_MPa)
    assert 0.94 <= phi <= 0.97
    ax1 = plot_indicator(result, lang="ru")
    ax2 = plot_pressure(result, lang="ru")
    marks = [ln for ln in ax2.get_lines() if ln.get_gid() == "diagram-point"]
    assert len(marks) == 8
    a, p = fine["alpha_deg"].to_numpy(), fine["p_gas_MPa"].to_numpy()
    zd = next(m for m in marks if m.get_xdata()[0] == pts["zд"].alpha_deg)
    assert zd.get_ydata()[0] == pytest.approx(np.interp(pts["zд"].alpha_deg, a, p))
    names = {t.get_text() for t in ax2.texts if t.get_gid() == "diagram-label"}
    assert names == set(pts)
    assert "φп = pi/p′i = " in ax1.get_title()
    assert len([ln for ln in ax1.get_lines() if ln.get_gid() == "diagram-point"]) == 8


@pytest.mark.parametrize("name", EXAMPLES)
def test_drawing_scale_diagrams_are_one_to_one(name):
    """The drawing-scale diagrams: one data unit is one millimetre of paper (x and y), the
    curves are the forces divided by μP (and α by μα), and the scales are stated."""
    from engine.plots.drawing import default_mu_alpha, drawing_figures

    result = _result(name)
    fine, spec, mu = result.curves, result.spec, result.settings.force_scale
    figs = drawing_figures(result, "en")
    for stem, fig in figs.items():
        ax = fig.axes[0]
        w_in, h_in = fig.get_size_inches()
        pos = ax.get_position()
        x0, x1 = sorted(ax.get_xlim())
        y0, y1 = sorted(ax.get_ylim())
        assert pos.width * w_in * 25.4 == pytest.approx(x1 - x0, rel=1e-9), stem
        assert pos.height * h_in * 25.4 == pytest.approx(y1 - y0, rel=1e-9), stem
        assert f"μP = {mu:g} N/mm" in ax.get_title(loc="left")
        assert not CYRILLIC.search(_all_text(fig))
    ax = figs["drawing_forces_P"].axes[0]
    p_line = [ln for ln in ax.get_lines() if ln.get_label() == "P"][0]
    np.testing.assert_allclose(p_line.get_ydata(), fine["P_N"] / mu)
    np.testing.assert_allclose(p_line.get_xdata(), fine["alpha_deg"] / default_mu_alpha(spec))
    polar = figs["drawing_polar"].axes[0]
    np.testing.assert_allclose(polar.get_lines()[0].get_xdata(),
                               fine["T_N"] / mu)
