"""Plot helpers: each draws on the Axes it is given and returns it; English plots carry no
Cyrillic, Russian ones the textbook symbols; curves told apart by line style."""
import re

import pytest
from matplotlib.figure import Figure

from crankbase.resources import example_path
from dynamics import balance_rotor, mechanism_balance
from dynamics.plots import (plot_inertia, plot_moments, plot_omega, plot_startup,
                            plot_true_forces, plot_wittenbauer)
from dynamics.rotor import plot_mr_polygon
from dynamics.shaking import plot_shaking_force, plot_shaking_locus
from dynamics.spec import load_dynamics_spec, run_job

CYR = re.compile("[\u0400-\u04ff]")


@pytest.fixture(scope="module")
def results():
    press = run_job(load_dynamics_spec(example_path("press_dynamics.toml")))
    rotor = balance_rotor([90, 600], [270, 45], [100, 420], [0, 300])
    mech = mechanism_balance(example_path("ratchet_balance.toml"))
    return press, rotor, mech


def _texts(ax):
    out = [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
    out += [t.get_text() for t in ax.texts]
    leg = ax.get_legend()
    if leg is not None:
        out += [t.get_text() for t in leg.get_texts()]
    return out


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_helpers_draw_on_the_given_axes(results, lang):
    press, rotor, mech = results
    calls = [
        lambda ax: plot_inertia(press["motion"], ax, lang),
        lambda ax: plot_moments(press["motion"], ax, lang),
        lambda ax: plot_wittenbauer(press["motion"], ax, lang),
        lambda ax: plot_omega(press["motion"], ax, lang),
        lambda ax: plot_startup(press["startup"], press["motion"], ax, lang),
        lambda ax: plot_true_forces(press["forces"], "M_drive_Nm", ax, lang),
        lambda ax: plot_mr_polygon(rotor, 1, ax, lang),
        lambda ax: plot_shaking_force(mech, ax, lang),
        lambda ax: plot_shaking_locus(mech, ax, lang),
    ]
    for call in calls:
        ax = Figure().add_subplot()
        assert call(ax) is ax
        text = " ".join(_texts(ax))
        assert bool(CYR.search(text)) == (lang == "ru"), text
        # two or more curves: not all drawn alike (black-and-white print)
        curves = [line for line in ax.get_lines() if len(line.get_xdata()) > 2]
        if len(curves) >= 2:
            looks = {(line.get_linestyle(), line.get_color()) for line in curves}
            assert len(looks) >= 2


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_correction_label_covers_no_arrow_of_the_polygon(lang):
    """The (m r)b label of each plane sits beside the closing vector, away from the
    polygon: no point of a side of the polygon lies under its box, also for the thin
    polygon of plane II of the bundled two-plane rotor (seed 001, Example 11-1)."""
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from dynamics import rotor_balance

    res = rotor_balance(example_path("rotor_two_plane.toml"))
    fig = Figure(figsize=(10.4, 5.2), layout="constrained")
    FigureCanvasAgg(fig)
    axes = [plot_mr_polygon(res, k, fig.add_subplot(1, 2, k + 1), lang) for k in (0, 1)]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for k, ax in enumerate(axes):
        label = res.corrections["plane"].iloc[k]
        sh = res.shares[res.shares["plane"] == label]
        pts = np.concatenate([[0j], np.cumsum((sh["mr_x_gmm"] + 1j * sh["mr_y_gmm"])
                                              .to_numpy()), [0j]])
        box = next(t for t in ax.texts if t.get_text().startswith("(m r)")) \
            .get_bbox_patch().get_window_extent(renderer)
        s = np.linspace(0, 1, 200)
        for a, b in zip(pts[:-1], pts[1:]):
            z = a + (b - a) * s
            xy = ax.transData.transform(np.column_stack([z.real, z.imag]))
            inside = ((xy[:, 0] > box.x0) & (xy[:, 0] < box.x1) & (xy[:, 1] > box.y0)
                      & (xy[:, 1] < box.y1))
            assert not inside.any(), (k, a, b)


def test_every_figure_of_a_run_speaks_its_language(results):
    """dynamics_figures of the press (motor, start-up, linkage forces) and the petrol
    engine (its crank torque and Rшш / Rcp): English without Cyrillic, Russian with the
    textbook symbols; the names are PLOT_NAMES."""
    from dynamics.plots import PLOT_NAMES, dynamics_figures

    petrol = run_job(load_dynamics_spec(example_path("petrol_dynamics.toml")))
    for res, names in ((results[0], PLOT_NAMES), (petrol, PLOT_NAMES[:4] + PLOT_NAMES[5:])):
        for lang in ("en", "ru"):
            figs = dynamics_figures(res, lang)
            assert tuple(figs) == names
            text = " ".join(t for f in figs.values() for ax in f.axes for t in _texts(ax))
            assert bool(CYR.search(text)) == (lang == "ru"), text
            if lang == "ru":
                for sym in ("Jп", "Mд", "Mс", "ΔT", "ωmax", "ωmin", "ωср", "δ"):
                    assert sym in text, sym
            for f in figs.values():
                f.clear()
    ru = " ".join(t for ax in dynamics_figures(petrol, "ru")["forces_true_motion"].axes
                  for t in _texts(ax))
    assert "Mкр" in ru and "Rшш" in ru


def test_a_fully_balanced_locus_is_marked(results):
    """After a full force balance the locus is a point: drawn as a marker at the origin
    and said so in the legend (a zero-length dashed curve would show nothing)."""
    mech = results[2]
    for lang, text in (("en", "$F_{sh}$ = 0"), ("ru", "Fин = 0")):
        ax = plot_shaking_locus(mech, Figure().add_subplot(), lang)
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert any(text in lab for lab in labels), labels
