"""The torsion figures (torsion.plots): every figure of a V8 run and of a free-vibration
chain, in both languages, checked by figure_check (nothing overlaps, nothing is cut), no
English word in a Russian figure and no Cyrillic in an English one, the curves told apart
in black and white."""
import re
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("matplotlib")
sys.path.insert(0, str(Path(__file__).resolve().parent))
from figure_check import figure_problems  # noqa: E402

import engine  # noqa: E402
from crankbase.errors import SpecError  # noqa: E402
from crankbase.resources import example_path  # noqa: E402
from engine.train import layout  # noqa: E402
from torsion.chain import damping_matrix, natural_modes, shaft_stiffness  # noqa: E402
from torsion.engine_chain import (cylinder_excitation, cylinder_throws,  # noqa: E402
                                  throw_inertia)
from torsion.plots import TORSION_PLOT_NAMES, plot_mode_shapes, torsion_figures  # noqa: E402
from torsion.response import critical_speeds, forced_response  # noqa: E402

LANGS = ("ru", "en")
CYRILLIC = re.compile("[\u0400-\u04FF]")
MATH = re.compile(r"\$[^$]*\$")
#: Latin words a Russian figure may show: units and symbols (k, n, f, N·m in mathtext …)
LATIN_WORD = re.compile(r"\b[A-Za-z]{3,}\b")


def v8_case():
    study = engine.load(example_path("diesel_kamaz740.toml"))
    spec = study.spec
    lay = layout(spec, study.train)
    throws, phases = cylinder_throws(lay)
    names = ["damper", "throw 1", "throw 2", "throw 3", "throw 4", "flywheel"]
    J = [0.08] + [throw_inertia(spec, 0.012, 2)] * 4 + [1.2]
    k = [2.1e6, 1.8e6, 1.8e6, 1.8e6, 1.5e6]
    m = natural_modes(J, k)
    h = cylinder_excitation(spec, orders_max=12)
    cs = critical_speeds(m, throws + 1, phases, h["total"].order, (600, 6000), lay.n, 720)
    r = forced_response(J, k, damping_matrix(J, m, 0.02), throws + 1, phases, h["gas"],
                        h["inertia"], spec.speed_rpm, np.arange(600.0, 6001.0, 10.0))
    return m, cs, h, r, names


def free_case():
    J = [0.15, 0.3, 0.09]
    k = [shaft_stiffness(84e9, 0.07, 1.5), shaft_stiffness(84e9, 0.07, 1.0)]
    return natural_modes(J, k), ["A", "B", "C"]


@pytest.fixture(scope="module")
def v8():
    return v8_case()


def _problems(fig, lang):
    from matplotlib.text import Text

    out = list(figure_problems(fig))
    for t in fig.findobj(Text):
        s = t.get_text()
        if not s or not t.get_visible():
            continue
        plain = MATH.sub("", s)
        if "_" in plain:
            out.append(f"literal underscore: {s!r}")
        if lang == "en" and CYRILLIC.search(s):
            out.append(f"Cyrillic in an English figure: {s!r}")
        if lang == "ru" and LATIN_WORD.search(plain.replace("throw", "").replace(
                "damper", "").replace("flywheel", "")):
            out.append(f"a Latin word in a Russian figure: {s!r}")
    return out


@pytest.mark.parametrize("lang", LANGS)
def test_v8_figures_are_clean(v8, lang):
    m, cs, h, r, names = v8
    figs = torsion_figures(m, cs, h, r, names, (600, 6000), lang)
    assert tuple(figs) == TORSION_PLOT_NAMES
    found = []
    for stem, fig in figs.items():
        found += [f"{stem} [{lang}]: {p}" for p in _problems(fig, lang)]
    assert not found, "\n".join(found[:40])


@pytest.mark.parametrize("lang", LANGS)
def test_free_chain_figures_are_clean(lang):
    m, names = free_case()
    figs = torsion_figures(m, None, None, None, names, (600, 6000), lang)
    assert list(figs) == ["torsion_modes"]
    found = [p for fig in figs.values() for p in _problems(fig, lang)]
    assert not found, "\n".join(found)


def test_curves_are_told_apart_in_black_and_white(v8):
    m, cs, h, r, names = v8
    figs = torsion_figures(m, cs, h, r, names, (600, 6000), "en")
    for stem in ("torsion_modes", "torsion_response", "torsion_angles"):
        ax = figs[stem].axes[0]
        looks = [(ln.get_linestyle(), ln.get_marker(), ln.get_color())
                 for ln in ax.get_lines() if not ln.get_label().startswith("_")]
        assert len(looks) == len(set(looks)), stem
    # the mode-shape curves are the modes' shapes, the Campbell's filled markers the
    # major critical speeds
    ax = figs["torsion_modes"].axes[0]
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), m.shapes[0])
    camp = figs["campbell"].axes[0]
    filled = [ln for ln in camp.get_lines() if ln.get_marker() == "o"
              and ln.get_markerfacecolor() == "black"]
    assert len(filled) == 1
    np.testing.assert_allclose(filled[0].get_xdata(), cs.loc[cs["major"], "speed_rpm"])


def test_a_given_axes_is_drawn_on_and_a_bad_language_is_an_error():
    from matplotlib.figure import Figure

    m, names = free_case()
    ax = Figure().subplots()
    assert plot_mode_shapes(m, names, ax, "en") is ax
    with pytest.raises(SpecError):
        plot_mode_shapes(m, names, None, "xx")


if __name__ == "__main__":          # write the PNGs to look at: python tests/test_torsion_plots.py DIR
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    case = v8_case()
    for lang in LANGS:
        for stem, fig in torsion_figures(*case[:4], case[4], (600, 6000), lang).items():
            fig.savefig(out / f"{stem}_{lang}.png", dpi=90)
        fm, fn = free_case()
        for stem, fig in torsion_figures(fm, None, None, None, fn, (600, 6000), lang).items():
            fig.savefig(out / f"free_{stem}_{lang}.png", dpi=90)
