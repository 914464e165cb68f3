"""Figures of the torsional vibration: mode shapes, the Campbell diagram, the harmonic
spectrum of one cylinder's torque, the response curves.

Matplotlib's object API (:class:`matplotlib.figure.Figure`, no pyplot state), imported
only when a figure is drawn.  Each ``plot_*`` draws on the ``ax`` it is given or on the
only Axes of a new Figure, and returns the Axes; :func:`torsion_figures` builds the whole
set, ``{stem: Figure}`` in :data:`TORSION_PLOT_NAMES` order.  Curves are told apart in
black and white (line styles, markers, hatches), the words come from the ``torsionplot``
catalogue in the run's language (:mod:`crankbase.texts`); legends stand beside the axes,
never over a curve.
"""
from __future__ import annotations

import numpy as np

from crankbase.errors import Problem, SpecError, Text

from .results import mass_names, section_names

__all__ = ["plot_mode_shapes", "plot_campbell", "plot_spectrum", "plot_response",
           "plot_response_angles", "torsion_figures", "TORSION_PLOT_NAMES", "LINE_STYLES"]

#: File stems of the figures, in order.
TORSION_PLOT_NAMES = ("torsion_modes", "campbell", "torque_spectrum", "torsion_response",
                      "torsion_angles")

#: Black-and-white line styles, one per curve, cycled.
LINE_STYLES = (
    dict(color="black", ls="-", marker="o"),
    dict(color="black", ls="--", marker="s"),
    dict(color="black", ls="-.", marker="^"),
    dict(color="black", ls=":", marker="D"),
    dict(color="0.45", ls="-", marker="v"),
    dict(color="0.45", ls="--", marker="x"),
    dict(color="0.45", ls="-.", marker="P"),
    dict(color="0.45", ls=":", marker="*"),
)

#: Figure size [in] and the margins that leave the legend room on the right.
FIGSIZE = (10.5, 5.6)
MARGINS = dict(left=0.085, right=0.72, bottom=0.12, top=0.9)


def _words(lang):
    from crankbase.texts import catalogue_languages, texts

    if lang not in catalogue_languages():
        raise SpecError(Problem("lang", Text("errors.torsion.lang",
                                             {"lang": lang,
                                              "items": ", ".join(catalogue_languages())})))
    from crankbase.plot_texts import plot_fonts

    plot_fonts(lang)
    return texts(lang)


def _axes(ax, figsize=FIGSIZE, **margins):
    """The given Axes, or the only Axes of a new Figure with fixed margins."""
    if ax is not None:
        return ax
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize)
    fig.subplots_adjust(**{**MARGINS, **margins})
    return fig.subplots()


def _style(i, markevery=None):
    s = dict(LINE_STYLES[i % len(LINE_STYLES)], lw=1.3, ms=5)
    if markevery is not None:
        s["markevery"] = markevery
    return s


def _legend(ax, x=1.02, **kw):
    ax.legend(loc="upper left", bbox_to_anchor=(x, 1.0), borderaxespad=0.0,
              fontsize=9, frameon=False, **kw)


def plot_mode_shapes(modes, names=None, ax=None, lang="ru"):
    """The shape of every elastic mode along the shaft, its nodes marked.  Each shape is
    drawn scaled to its largest |θ| = 1 (mass 1 positive), so that a low mode stays
    readable beside a high one whose amplitudes relative to mass 1 run into tens (the
    CSV keeps θ_1 = 1).  Returns the Axes."""
    t = _words(lang)
    n = modes.shapes.shape[1]
    names = mass_names(n, names)
    long_names = max(len(s) for s in names) > 4
    ax = _axes(ax, bottom=0.2 if long_names else MARGINS["bottom"])
    x = np.arange(1, n + 1)
    for m in range(modes.count):
        shape = np.asarray(modes.shapes[m], float)
        ax.plot(x, shape / np.max(np.abs(shape)) * (1.0 if shape[0] >= 0 else -1.0),
                **_style(m),
                label=t("torsionplot.mode", m=m + 1, f=float(modes.f_Hz[m])))
    nodes = np.concatenate(modes.nodes) if modes.count else np.array([])
    if nodes.size:
        ax.plot(nodes, np.zeros_like(nodes), ls="none", marker="|", ms=12, mew=1.5,
                color="black", label=t("torsionplot.node"))
    ax.axhline(0.0, color="black", lw=0.7)
    ax.set_xticks(x)
    ax.set_xticklabels(names, rotation=30 if long_names else 0,
                       ha="right" if long_names else "center")
    ax.set_xlim(0.7, n + 0.3)
    ax.set_xlabel(t("torsionplot.mass_axis"))
    ax.set_ylabel(t("torsionplot.shape_axis"))
    ax.set_title(t("torsionplot.modes_title"))
    ax.grid(True, lw=0.4, alpha=0.6)
    _legend(ax)
    return ax


def plot_campbell(modes, critical, speed_range, orders, ax=None, lang="ru",
                  phases_deg=None):
    """The Campbell diagram: natural frequencies (horizontal), order lines f = k·n/60
    (major orders solid black, minor thin grey), the critical speeds inside the range
    (filled: major, open: minor).  Returns the Axes.

    Parameters
    ----------
    modes : Modes
    critical : pandas.DataFrame or None
        :func:`torsion.response.critical_speeds` (its ``major`` column marks the orders).
    speed_range : (float, float) [rpm]
    orders : array_like
        The order lines to draw (order 0 is skipped).
    phases_deg : array_like, optional
        Each cylinder's phase (:func:`engine.train.layout`): the major orders are then
        those of the engine (:func:`torsion.response.is_major`), with or without a
        critical speed in the range; without it, those of ``critical``.
    """
    t = _words(lang)
    ax = _axes(ax, right=0.66)
    lo, hi = (float(v) for v in speed_range)
    k = np.asarray(orders, float)
    k = k[k > 0]
    fmax_exc = k.max(initial=1.0) * hi / 60.0
    shown = modes.f_Hz[modes.f_Hz <= fmax_exc]
    if shown.size == 0:
        shown = modes.f_Hz[:1]
    ymax = 1.15 * float(shown.max())
    xmax = hi * 1.02
    major = set()
    if phases_deg is not None:
        from .response import is_major

        major = {float(o) for o in k[is_major(k, phases_deg)]}
    elif critical is not None and len(critical):
        major = {float(o) for o in critical.loc[critical["major"], "order"]}
    n = np.array([0.0, xmax])
    first = {True: True, False: True}
    for kk in k:
        is_major = float(kk) in major
        style = (dict(color="black", lw=1.2, ls="-") if is_major
                 else dict(color="0.6", lw=0.6, ls=":"))
        label = None
        if first[is_major]:
            label = t("torsionplot.major_order" if is_major else "torsionplot.minor_order")
            first[is_major] = False
        ax.plot(n, kk * n / 60.0, **style, label=label)
    for i, f in enumerate(shown):
        ax.axhline(f, color="black", lw=1.0, ls="--",
                   label=t("torsionplot.natural") if i == 0 else None)
    ax.axvspan(lo, hi, color="0.93", zorder=0, label=t("torsionplot.range"))
    if critical is not None and len(critical):
        for flag, key, face in ((True, "torsionplot.critical_major", "black"),
                                (False, "torsionplot.critical_minor", "white")):
            c = critical[critical["major"] == flag]
            if len(c):
                ax.plot(c["speed_rpm"], c["f_Hz"], ls="none", marker="o", ms=6,
                        mfc=face, mec="black", zorder=5, label=t(key))
    # the major orders named at the edge the line leaves through (right or top margin)
    for kk in sorted(major):
        if kk not in set(k.tolist()):
            continue
        x_top = 60.0 * ymax / kk
        if x_top <= xmax:
            ax.annotate(t("torsionplot.order_label", k=kk), (x_top, ymax), xytext=(0, 3),
                        textcoords="offset points", ha="center", va="bottom", fontsize=8,
                        annotation_clip=False)
        else:
            ax.annotate(t("torsionplot.order_label", k=kk), (xmax, kk * xmax / 60.0),
                        xytext=(3, 0), textcoords="offset points", ha="left",
                        va="center", fontsize=8, annotation_clip=False)
    ax.set_xlim(0.0, xmax)
    ax.set_ylim(0.0, ymax)
    ax.set_xlabel(t("torsionplot.speed_axis"))
    ax.set_ylabel(t("torsionplot.freq_axis"))
    ax.set_title(t("torsionplot.campbell_title"), pad=16)
    _legend(ax, x=1.1)           # the order names at the right edge stand before it
    return ax


def plot_spectrum(harmonics, ax=None, lang="ru"):
    """Bars of the amplitude of each order (above 0) of one cylinder's torque: gas,
    inertia and total side by side (white hatched, grey, black).  ``harmonics`` is the
    dict of :func:`torsion.engine_chain.cylinder_excitation` (any of its keys).
    Returns the Axes."""
    t = _words(lang)
    ax = _axes(ax)
    parts = [p for p in ("gas", "inertia", "total") if p in harmonics]
    looks = {"gas": dict(color="white", edgecolor="black", hatch="///"),
             "inertia": dict(color="0.6", edgecolor="black"),
             "total": dict(color="black", edgecolor="black")}
    width = 0.5 * 0.8 / max(len(parts), 1)
    ref = harmonics[parts[0]]
    keep = ref.order > 0
    for i, p in enumerate(parts):
        h = harmonics[p]
        x = h.order[keep] + (i - (len(parts) - 1) / 2) * width
        ax.bar(x, h.amplitude_Nm[keep], width=width, lw=0.6, label=t(f"torsionplot.{p}"),
               **looks[p])
    top = float(ref.order.max())
    step = 1.0 if top <= 16 else 2.0
    ax.set_xticks(np.arange(0.0, top + 0.5 * step, step))
    ax.set_xlim(0.0, top + 0.5)
    ax.set_xlabel(t("torsionplot.order_axis"))
    ax.set_ylabel(t("torsionplot.amplitude_axis"))
    mean = harmonics["total" if "total" in harmonics else parts[0]].mean_Nm
    ax.set_title(t("torsionplot.spectrum_title", mean=mean))
    ax.grid(True, axis="y", lw=0.4, alpha=0.6)
    _legend(ax)
    return ax


def _mark_every(S):
    """About 12 marks along a curve of S points, the first half a step in: none on the
    axes' ends, where the frame would cut it in half."""
    step = max(1, S // 12)
    return (step // 2, step)


def plot_response(response, names=None, ax=None, lang="ru"):
    """The peak vibration torque of every shaft section over the speed range, the
    largest marked.  Returns the Axes."""
    t = _words(lang)
    ax = _axes(ax)
    names = mass_names(response.amplitude_deg.shape[1], names)
    secs = section_names(names)
    S = len(response.speeds_rpm)
    for i, sec in enumerate(secs):
        ax.plot(response.speeds_rpm, response.torque_Nm[:, i],
                **_style(i, _mark_every(S)), label=t("torsionplot.section", name=sec))
    n, i, M = response.worst
    # unclipped: at an end of the speed range the circle stands whole over the frame
    ax.plot([n], [M], ls="none", marker="o", ms=11, mfc="none", mec="black", mew=1.5,
            clip_on=False, zorder=6, label=t("torsionplot.worst", M=M, n=n))
    ax.set_xlim(float(response.speeds_rpm.min()), float(response.speeds_rpm.max()))
    ax.set_ylim(0.0, 1.08 * M if M > 0 else 1.0)
    ax.set_xlabel(t("torsionplot.speed_axis"))
    ax.set_ylabel(t("torsionplot.torque_axis"))
    ax.set_title(t("torsionplot.response_title"))
    ax.grid(True, lw=0.4, alpha=0.6)
    _legend(ax)
    return ax


def plot_response_angles(response, names=None, ax=None, lang="ru"):
    """The peak vibration angle of every mass over the speed range: the elastic
    (twisting) amplitude, without the swing of the whole free chain
    (:attr:`torsion.results.Response.amplitude_deg`), so that it peaks at the critical
    speeds.  Returns the Axes."""
    t = _words(lang)
    ax = _axes(ax)
    names = mass_names(response.amplitude_deg.shape[1], names)
    S = len(response.speeds_rpm)
    for i, name in enumerate(names):
        ax.plot(response.speeds_rpm, response.amplitude_deg[:, i],
                **_style(i, _mark_every(S)), label=t("torsionplot.mass", name=name))
    top = float(response.amplitude_deg.max())
    ax.set_xlim(float(response.speeds_rpm.min()), float(response.speeds_rpm.max()))
    ax.set_ylim(0.0, 1.08 * top if top > 0 else 1.0)
    ax.set_xlabel(t("torsionplot.speed_axis"))
    ax.set_ylabel(t("torsionplot.angle_axis"))
    ax.set_title(t("torsionplot.angles_title"))
    ax.grid(True, lw=0.4, alpha=0.6)
    _legend(ax)
    return ax


def torsion_figures(modes, critical, harmonics, response, names, speed_range_rpm,
                    lang="ru", phases_deg=None) -> dict:
    """Every torsion figure, ``{stem: Figure}`` in :data:`TORSION_PLOT_NAMES` order; a
    figure whose input is None (no engine: no harmonics, critical speeds or response) is
    left out, and the Campbell diagram then has no order lines unless ``critical`` is
    given.  ``phases_deg`` (the cylinders' phases) tells the Campbell diagram the major
    orders (:func:`plot_campbell`)."""
    out = {"torsion_modes": plot_mode_shapes(modes, names, None, lang).figure}
    if critical is not None or harmonics is not None:
        if harmonics is not None:
            orders = next(iter(harmonics.values())).order
        else:
            orders = np.unique(critical["order"].to_numpy())
        out["campbell"] = plot_campbell(modes, critical, speed_range_rpm, orders, None,
                                        lang, phases_deg).figure
    if harmonics is not None:
        out["torque_spectrum"] = plot_spectrum(harmonics, None, lang).figure
    if response is not None:
        out["torsion_response"] = plot_response(response, names, None, lang).figure
        out["torsion_angles"] = plot_response_angles(response, names, None, lang).figure
    return out
