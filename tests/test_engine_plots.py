"""Plot helpers of the engine (engine.plots): python-control style, each draws on a given
Axes and returns it; the report's figures; no Cyrillic in an English figure; no pyplot."""
import re
import subprocess
import sys

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
