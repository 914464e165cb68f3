"""linkage.plots: compute → result → plot_*(result, ax=None, lang=...) on a given Axes."""
import re
import warnings

import pytest

import linkage
from crankbase.resources import example_path
from linkage import plots

CYRILLIC = re.compile("[\u0400-\u04FF]")
CURVES = [plots.plot_velocities, plots.plot_accelerations, plots.plot_driving_moment,
          plots.plot_transmission_angle]


@pytest.fixture(scope="module", params=["ratchet.toml", "press.toml"])
def results(request):
    spec = linkage.load_spec(example_path(request.param))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", linkage.SingularPositionWarning)
        return linkage.analyze(spec), linkage.full_turn(spec, 5.0)


def _texts(ax):
    fig = ax.figure
    out = [t.get_text() for a in fig.axes for t in a.texts]
    for a in fig.axes:
        out += [a.get_title(), a.get_xlabel(), a.get_ylabel()]
        out += [t.get_text() for t in a.get_xticklabels() + a.get_yticklabels()]
        leg = a.get_legend()
        if leg is not None:
            out += [t.get_text() for t in leg.get_texts()]
        for child in a.get_children():        # secondary axes (plan positions on top)
            if hasattr(child, "get_xlabel"):
                out.append(child.get_xlabel())
    return out


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_plot_helpers_draw_on_the_given_axes_and_return_it(results, lang):
    from matplotlib.figure import Figure

    res, full = results
    fig = Figure()
    axes = fig.subplots(1, len(CURVES) + 1)
    assert plots.plot_plan(res, ax=axes[0], lang=lang, full=full) is axes[0]
    for fn, ax in zip(CURVES, axes[1:]):
        assert fn(full, ax=ax, lang=lang, plan=res) is ax
        assert ax.lines, fn.__name__            # something was drawn
    texts = " ".join(t for ax in axes for t in _texts(ax))
    if lang == "en":
        assert not CYRILLIC.search(texts), CYRILLIC.findall(texts)
    else:
        assert CYRILLIC.search(texts)


def test_plot_helpers_make_their_own_figure(results):
    res, full = results
    ax = plots.plot_transmission_angle(full)
    assert ax.figure is not None and ax.figure.axes[0] is ax
    # μmin of the summary is the dashed line
    assert any(line.get_ydata()[0] == pytest.approx(full.summary.mu_min_deg)
               for line in ax.lines if line.get_linestyle() == "--")


def test_unknown_language_is_refused(results):
    with pytest.raises(ValueError, match="lang"):
        plots.plot_velocities(results[1], lang="de")


def test_a_long_plan_is_thinned_to_at_most_max_positions():
    spec = linkage.load_spec(example_path("ratchet.toml"))
    res = linkage.analyze(spec, crank_angles_deg=range(0, 360, 3))       # 120 rows
    ax = plots.plot_plan(res)
    drawn = [ln for ln in ax.lines if ln.get_marker() == "o" and len(ln.get_xdata()) >= 3]
    assert 1 < len(drawn) <= plots.MAX_PLAN_POSITIONS + 1        # + the other extreme
    assert "of 120 rows drawn" in ax.get_title()


def test_synthesis_plots_return_their_axes_without_cyrillic():
    import numpy as np
    from matplotlib.figure import Figure

    from linkage import synthesis as syn
    from linkage import synthesis_plots as sp

    d = syn.design_for_mu_min(0.90, 40, 30, l1_step=0.01)
    phi = np.arange(0.0, 361.0)
    fig = Figure()
    axes = fig.subplots(1, 3)
    got = [sp.plot_region(syn.existence_region(30), d, family=syn.right_angle_family(d.l1, 30),
                          ax=axes[0]),
           sp.plot_mu_min_curves(syn.mu_min_curves(30), d, mu_required=40, ax=axes[1]),
           sp.plot_transmission_angle(phi, syn.transmission_angle_deg(phi, d.l1, d.l2, d.l3),
                                      d, ax=axes[2])]
    assert got == list(axes)
    texts = " ".join(t for ax in axes for t in _texts(ax))
    assert "KKM-30" in texts and not CYRILLIC.search(texts), CYRILLIC.findall(texts)
