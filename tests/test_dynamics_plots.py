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
