"""Issue #19: the figures' fonts in one place (crankbase.plot_texts.plot_fonts): DejaVu
Sans then the system's CJK fonts, TrueType in PDFs, a warning naming what to install when
a Chinese run finds no CJK font; Chinese labels' mathtext set as plain text."""
from __future__ import annotations

import warnings

import pytest

pytest.importorskip("matplotlib")

from crankbase import plot_texts as P  # noqa: E402


def test_the_font_list_starts_with_dejavu_then_the_cjk_fonts():
    import matplotlib

    P.plot_fonts("en")
    rc = matplotlib.rcParams
    assert rc["font.sans-serif"][:len(P.FONT_FAMILY)] == list(P.FONT_FAMILY)
    assert P.FONT_FAMILY[0] == "DejaVu Sans"
    for name in ("Noto Sans CJK SC", "WenQuanYi Zen Hei", "Microsoft YaHei", "SimHei",
                 "PingFang SC", "Droid Sans Fallback"):
        assert name in P.CJK_FONTS
    assert rc["pdf.fonttype"] == 42 and rc["ps.fonttype"] == 42


def test_a_chinese_run_without_a_cjk_font_warns_once_naming_what_to_install(monkeypatch):
    monkeypatch.setattr(P, "cjk_fonts", lambda: ())
    monkeypatch.setattr(P, "_warned", set())
    with pytest.warns(UserWarning, match="fonts-noto-cjk or fonts-wqy-zenhei") as rec:
        assert P.plot_fonts("zh") == ()
    assert "Noto Sans CJK SC" in str(rec[0].message)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        P.plot_fonts("zh")                     # once only
        P.plot_fonts("ru")                     # never for a language without CJK


def test_plain_math_keeps_the_symbols_readable():
    assert P.plain_math("$M_{mean}$ = 3 N·m（平均）") == "Mₘₑₐₙ = 3 N·m（平均）"
    assert P.plain_math("$R_{cp}$，kN") == "Rcp，kN"
    assert P.plain_math("$F_x$，无平衡重") == "Fx，无平衡重"
    assert P.plain_math("$\\Delta P_{g}$、Pj") == "ΔPg、Pj"
    assert P.plain_math("no math, a $ sign alone") == "no math, a $ sign alone"


def test_only_chinese_texts_change():
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.add_subplot()
    ax.set_title("$M_{mean}$ = 3 N·m")
    ax.set_xlabel("$R_{cp}$，kN")
    ru = ax.set_ylabel("$F_x$, кН")
    family = list(ru.get_fontfamily())
    P.cjk_texts(fig)
    assert ax.get_title() == "$M_{mean}$ = 3 N·m"          # English and Russian: as drawn
    assert ru.get_text() == "$F_x$, кН" and list(ru.get_fontfamily()) == family
    assert ax.get_xlabel() == "Rcp，kN"
    if P.cjk_fonts():
        assert ax.xaxis.label.get_fontfamily()[0] == "DejaVu Sans"
        assert set(P.cjk_fonts()) <= set(ax.xaxis.label.get_fontfamily())


def test_chinese_texts_are_found_without_making_ticks():
    """crankbase.plot_texts.cjk_texts (every figure's save: the Chinese report above)
    finds every text findobj finds that holds a word, Chinese tick labels set with
    ``set_xticks(…, labels)`` included, and gives the Chinese ones the CJK fonts, without
    making an axis's ticks (Axis.get_children makes as many as its locator gives: a
    third of the CPU of a figure saved unrendered); its drawing makes them as before."""
    from matplotlib.figure import Figure
    from matplotlib.text import Text

    from crankbase.plot_texts import FONT_FAMILY, cjk_fonts, cjk_texts, figure_texts

    fig = Figure()
    ax = fig.subplots()
    ax.plot([0.0, 1.0], [0.0, 2.0])
    ax.set_xticks([0.0, 1.0], ["曲柄", "连杆 $M_{kr}$"])
    ax.set_ylabel("扭矩 $M_{kr}$, N·m")
    fig.suptitle("petrol-vaz2106")
    ticks = len(ax.yaxis.majorTicks)
    title = fig._suptitle.get_fontfamily()          # rcParams' (a Chinese run's changed)
    found = {id(t) for t in figure_texts(fig)}
    assert cjk_texts(fig) == 3          # mathtext set as plain text: the y label and the
    assert ax.yaxis.label.get_text() == "扭矩 Mₖᵣ, N·m"    # tick's two labels (label2 too)
    assert len(ax.yaxis.majorTicks) == ticks            # no tick made
    worded = [t for t in fig.findobj(Text) if t.get_text()]
    assert len(ax.yaxis.majorTicks) > ticks             # findobj makes the locator's
    assert worded and all(id(t) in found for t in worded)
    assert ax.xaxis.majorTicks[1].label1.get_text() == "连杆 Mₖᵣ"
    family = [FONT_FAMILY[0], *cjk_fonts()]
    if len(family) > 1:                                  # a CJK font installed
        for t in (ax.yaxis.label, ax.xaxis.majorTicks[0].label1,
                  ax.xaxis.majorTicks[1].label2):
            assert t.get_fontfamily() == family, t
    assert fig._suptitle.get_fontfamily() == title      # no Chinese: left as it is
