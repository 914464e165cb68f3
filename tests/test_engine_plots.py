"""Plot helpers of the engine (engine.plots): python-control style, each draws on a given
Axes and returns it; the report's figures; no Cyrillic in an English figure; no pyplot."""
import re
import subprocess
import sys

import numpy as np
import pytest
from matplotlib.figure import Figure
from matplotlib.text import Text

import engine
from crankbase.resources import example_path
from engine import plots

HELPERS = [plots.plot_indicator, plots.plot_pressure, plots.plot_piston_forces,
           plots.plot_nkt, plots.plot_torque, plots.plot_polar, plots.plot_developed]
CYRILLIC = re.compile("[\u0400-\u04ff]")


@pytest.fixture(scope="module")
def result():
    study = engine.load(example_path("diesel_d240.toml"))
    return engine.analyze(study.spec, study.settings, fine_step_deg=2.0)


@pytest.mark.parametrize("helper", HELPERS, ids=lambda f: f.__name__)
def test_helper_draws_on_the_given_axes(helper, result):
    fig = Figure()
    ax = fig.subplots()
    out = helper(result, ax=ax, lang="en")
    assert out is ax and len(ax.lines) >= 1
    # the curve drawn is the result's data, not a recomputation
    xs = ax.lines[0].get_xdata()
    assert len(xs) == len(result.curves)


@pytest.mark.parametrize("helper", HELPERS, ids=lambda f: f.__name__)
def test_helper_makes_its_own_axes(helper, result):
    ax = helper(result)
    assert isinstance(ax.figure, Figure) and ax in ax.figure.axes


def _texts(fig):
    return [t.get_text() for t in fig.findobj(Text) if t.get_text()]


def test_report_figures_both_languages(result):
    en = plots.figures(result, "en")
    ru = plots.figures(result, "ru")
    assert list(en) == list(plots.PLOT_NAMES) == list(ru)
    for name, fig in en.items():
        bad = [t for t in _texts(fig) if CYRILLIC.search(t)]
        assert not bad, (name, bad)
    assert any(CYRILLIC.search(t) for t in _texts(ru["torque"]))
    assert len(en["indicator"].axes) == 2


def test_bad_language_is_a_typed_error(result):
    with pytest.raises(engine.EngineSpecError, match="^lang"):
        plots.plot_torque(result, lang="de")


def test_plots_never_use_pyplot():
    code = ("import engine, engine.plots as p\n"
            "from crankbase.resources import example_path\n"
            "s = engine.load(example_path('petrol_vaz2106.toml'))\n"
            "p.figures(engine.analyze(s.spec, s.settings, fine_step_deg=5.0), 'en')\n"
            "import sys; print('matplotlib.pyplot' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == ["False"]


TRAIN_HELPERS = [plots.plot_total_torque, plots.plot_excess_work, plots.plot_force_locus,
                 plots.plot_moment_locus, plots.plot_free_forces, plots.plot_free_moments,
                 plots.plot_crankshaft]


@pytest.fixture(scope="module")
def whole():
    study = engine.load(example_path("diesel_kamaz740.toml"))
    return engine.analyze_engine(study.spec, study.train,
                                 engine.TableSettings(step_deg=10.0), fine_step_deg=2.0)


@pytest.mark.parametrize("helper", TRAIN_HELPERS, ids=lambda f: f.__name__)
def test_train_helper_draws_on_the_given_axes(helper, whole):
    fig = Figure()
    ax = fig.subplots()
    assert helper(whole, ax=ax, lang="en") is ax
    assert ax.lines or ax.patches


def test_train_figures_both_languages(whole):
    en = plots.train_figures(whole, "en")
    ru = plots.train_figures(whole, "ru")
    assert list(en) == list(plots.TRAIN_PLOT_NAMES) == list(ru)
    for name, fig in en.items():
        bad = [t for t in _texts(fig) if CYRILLIC.search(t)]
        assert not bad, (name, bad)
    # the total torque shows every cylinder faintly, the sum and the mean
    ax = en["torque_total"].axes[0]
    assert len(ax.lines) >= whole.layout.n + 2
    # the loci: before and after the counterweights
    labels = [line.get_label() for line in en["free_moment_locus"].axes[0].lines]
    assert "with counterweights" in labels and "without counterweights" in labels


# ------------------------------------------------- drawings on standard paper (issue #23)

GOST_FORMATS = {(210.0, 297.0), (297.0, 420.0), (420.0, 594.0), (594.0, 841.0)}


@pytest.mark.parametrize("name", ["petrol_vaz2106.toml", "diesel_kamaz740.toml"])
def test_drawings_are_on_a_gost_format_at_the_stated_scale(name):
    """Every --drawing figure is exactly an A4 … A1 sheet (ГОСТ 2.301, either
    orientation), and its drawing is 1:1: one data unit of the axes is one millimetre of
    paper, and a force F is drawn F/μP mm from the axis (μP as the title states)."""
    import engine
    from crankbase.resources import example_path
    from engine.plots.drawing import drawing_figures

    study = engine.load(example_path(name))
    result = engine.analyze(study.spec, study.settings)
    mu_p = result.settings.force_scale
    for stem, fig in drawing_figures(result, "ru").items():
        w, h = (float(v) * 25.4 for v in fig.get_size_inches())
        assert tuple(sorted((round(w, 6), round(h, 6)))) in GOST_FORMATS, (stem, w, h)
        ax = fig.axes[0]                                  # the drawing, then the sheet
        pos = ax.get_position()
        x0, x1 = ax.get_xlim()
        y0, y1 = sorted(ax.get_ylim())
        assert pos.width * w / (x1 - x0) == pytest.approx(1.0, rel=1e-9), stem
        assert pos.height * h / (y1 - y0) == pytest.approx(1.0, rel=1e-9), stem
        assert f"μP = {mu_p:g}" in ax.get_title(loc="left")
        curve = ax.lines[0].get_ydata()
        col = "K_N" if stem == "drawing_polar" else ("dPg_N" if stem.endswith("_P")
                                                     else "N_N")
        np.testing.assert_allclose(curve, result.curves[col].to_numpy() / mu_p)
        # the frame and the title block of the plans sheet: its edge is the sheet's
        sheet = fig.axes[1]
        assert sheet.get_xlim()[1] == pytest.approx(w)
        assert any(t.get_text() == result.spec.name for t in sheet.texts)
        fig.clear()
