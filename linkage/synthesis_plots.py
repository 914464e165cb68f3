"""Plots of the ККМ-φ0 synthesis (the paper's Fig. 2 and Fig. 3, and μ over a turn).

Compute first, then plot: every function here only draws arrays computed by
:mod:`linkage.synthesis` (an :class:`~linkage.synthesis.ExistenceRegion`, a
:class:`~linkage.synthesis.MuMinCurves`, a :class:`~linkage.synthesis.Design`, μ(φ)).
matplotlib's object-oriented API only (``Figure``, never ``pyplot``), imported inside
the functions; works headless.  Each ``plot_*`` draws on ``ax`` when given (else on a new
:class:`~matplotlib.figure.Figure`'s) and returns the Axes (``ax.figure`` for the figure),
like the helpers of :mod:`linkage.plots`.

``lang="ru"`` labels with the paper's own Russian terms (область существования ККМ-30°,
дуга abc, кривая cda, прямые Колчина, шатун λ2 …); ``lang="en"`` with English ones and
no Cyrillic letter (the family is named KKM-φ0, the paper's ККМ-φ0 transliterated).  Every
number is formatted once and put into the words of either language.  Curves differ by
line style (dash pattern, width, marker), not by colour only, so they can be told apart
in black-and-white print; the curves of Fig. 3 carry their numbers 1…9, as in the paper.
"""
from __future__ import annotations

import numpy as np

from crankbase.plot_layout import run_layout
from crankbase.tolerances import SAME_ANGLE_DEG

__all__ = ["plot_region", "plot_mu_min_curves", "plot_transmission_angle"]

#: The words of the figures; numbers come in already formatted ({l1}, {phi0} …).

#: Kolchin's three lines (Sereda 2016, eq. (1)–(3)) as λ3 = k λ2 + b(λ1): number,
#: formula, slope k, intercept b(λ1), dash pattern (thin grey lines, told apart by dash).
_KOLCHIN = ((1, "1 − λ1 = λ2 − λ3", 1.0, lambda lam: -(1.0 - lam), (0, (8, 3))),
            (2, "1 − λ1 = λ3 − λ2", 1.0, lambda lam: 1.0 - lam, (0, (2.5, 2))),
            (3, "1 + λ1 = λ2 + λ3", -1.0, lambda lam: 1.0 + lam, (0, (8, 3, 2, 3))))

#: Dash patterns of the nine curves of Fig. 3 (with their numbers on the curves, as in
#: the paper, they are told apart without colour).
_CURVE_DASHES = ("-", (0, (7, 2)), (0, (1, 1.5)), (0, (7, 2, 1.5, 2)), (0, (12, 2.5)),
                 (0, (3, 2)), (0, (7, 2, 1.5, 2, 1.5, 2)), (0, (12, 2, 3, 2)),
                 (0, (1.5, 1.5, 4.5, 1.5)))


def _text(lang):
    """The words of these plots in ``lang`` (``plot.synth.*``)."""
    from crankbase.texts import OFFERED

    if lang not in OFFERED:
        raise ValueError(f"lang: got {lang!r}; one of {', '.join(OFFERED)}")
    from crankbase.plot_texts import plot_words

    return plot_words(lang, "synth")


def _axes(ax, size):
    if ax is not None:
        return ax.figure, ax
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.add_subplot()


def plot_region(region, design=None, kolchin_l1=None, family=None, ax=None, lang="en"):
    """The region of existence of the ККМ-φ0 family in the (λ2, λ3) plane (Fig. 2).

    Parameters
    ----------
    region : linkage.synthesis.ExistenceRegion
        The boundary (unit arc abc and curve cda), λ1max, the point d and, for φ0 < 90°,
        the ККМ-5 and ККМ-7 segments.
    design : linkage.synthesis.Design, optional
        The chosen mechanism, marked with its coordinates.
    kolchin_l1 : float, optional
        λ1 of Kolchin's three lines (eq. (1)–(3)); default the chosen mechanism's λ1,
        else λ1max (where line (3) touches the curve at d).
    family : linkage.synthesis.FamilyArc, optional
        The family's admissible arc for the chosen λ1 (drawn dotted).
    ax : matplotlib.axes.Axes, optional
    lang : {"en", "ru"}
        Language of the labels.

    Returns
    -------
    matplotlib.axes.Axes

    References
    ----------
    .. [1] Sereda (2016), Fig. 2, eq. (1)–(3), (6).
    """
    T = _text(lang)
    fig, ax = _axes(ax, (6.4, 8.4))
    lam = kolchin_l1 if kolchin_l1 is not None else (design.l1 if design is not None
                                                     else region.l1_max)
    n = {"phi0": f"{region.phi0_deg:g}", "l1max": f"{region.l1_max:.4f}",
         "lam": f"{lam:.4g}"}
    n["kkm"] = T["kkm"].format(**n)
    ax.fill(region.l2, region.l3, color="tab:blue", alpha=0.12, lw=0,
            label=T["fill"].format(**n))
    ax.plot(region.arc_l2, region.arc_l3, color="k", lw=1.2, label=T["arc"])
    nums = region.kolchin_numbers
    ax.plot(region.curve_l2, region.curve_l3, color="tab:blue", lw=2.8,
            label=T["curve"].format(line=T["line" if len(nums) == 1 else "lines"],
                                    nums="–".join(f"({k})" for k in nums)))
    hi = max(1.05, float(np.max(region.l2)) * 1.08)
    t = np.array([0.0, hi])
    for num, formula, k, b, dash in _KOLCHIN:
        label = T["kolchin"].format(n=num, l1=n["lam"], formula=formula)
        ax.plot(t, k * t + b(lam), color="0.3", lw=1.0, ls=dash, label=label)
    if family is not None:
        ax.plot(family.l2, family.l3, color="tab:green", lw=1.8, ls=(0, (1, 1.6)),
                label=T["family"].format(l1=f"{family.l1:.4g}", R=f"{family.radius:.4f}"))
    if region.kkm5_l2 is not None:
        ax.plot(region.kkm5_l2, region.kkm5_l3, color="tab:orange", lw=3.0, ls="-",
                solid_capstyle="butt", label=T["kkm5"].format(**n))
        ax.plot(region.kkm7_l2, region.kkm7_l3, color="tab:purple", lw=3.0,
                ls=(0, (4, 1, 1, 1)), label=T["kkm7"].format(**n))
    # the letters of the paper's figure (Latin in both languages, as in the paper)
    mid = len(region.arc_l2) // 2
    marks = {"a": (1.0, 0.0, (6, 4)), "b": (region.arc_l2[mid], region.arc_l3[mid], (5, 5)),
             "c": (0.0, 1.0, (5, 5)), "d": (*region.d, (-14, -12))}
    for name, (x, y, off) in marks.items():
        ax.plot([x], [y], "k.", ms=5)
        ax.annotate(name, (x, y), textcoords="offset points", xytext=off,
                    fontsize=11, fontstyle="italic")
    if design is not None:
        ax.plot([design.l2], [design.l3], "o", color="tab:red", mec="k", mew=0.8, ms=7,
                zorder=5, label=T["chosen"].format(l1=f"{design.l1:.4f}",
                                                   l2=f"{design.l2:.4f}",
                                                   l3=f"{design.l3:.4f}"))
    ax.set_xlim(0, hi)
    ax.set_ylim(0, hi)
    ax.set_aspect("equal")
    ax.set_xlabel(T["coupler"])
    ax.set_ylabel(T["rocker"])
    ax.set_title(T["region_title"].format(**n), fontsize=10)
    ax.grid(True, lw=0.4, alpha=0.5)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.09), fontsize=8, ncols=1,
              frameon=False, handlelength=3.2)
    return ax


def _even(p, step):
    """The finite points of the polyline ``p`` (n, 2), resampled every ``step`` along its
    length (so that steep parts are as densely covered as flat ones).  Layout only."""
    p = p[np.all(np.isfinite(p), axis=1)]
    if len(p) < 2:
        return p
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))])
    t = np.linspace(0.0, s[-1], max(2, int(s[-1] / step) + 1))
    return np.column_stack([np.interp(t, s, p[:, 0]), np.interp(t, s, p[:, 1])])


def _label_curves(ax, xs, ys, names, avoid, fontsize=8, step=0.02, label_in=0.12,
                  lines=None):
    """Write ``names[i]`` on curve i where it is farthest from every other curve, from
    the polylines ``avoid`` (a list of (x, y) arrays) and from the labels already placed
    (like contour labels): a white box over its own curve only.  Distances in inches of
    the axes, the curves resampled every ``step`` inches, a label counted ``label_in``
    wide.  Layout only, no physics."""
    fig = ax.figure
    if lines is not None:
        run_layout(fig)         # the final axes box (constrained layout), nothing drawn
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    pos = ax.get_position()
    w = pos.width * fig.get_figwidth()        # axes size in inches (before the layout:
    h = pos.height * fig.get_figheight()      # the aspect is what matters)

    def inches(x, y):
        return (np.asarray(x) - x0) / (x1 - x0) * w, (np.asarray(y) - y0) / (y1 - y0) * h

    pts = [_even(np.column_stack(inches(x, y)), step) for x, y in zip(xs, ys)]
    extra = np.concatenate([np.empty((0, 2))] + [_even(np.column_stack(inches(x, y)), step)
                                                 for x, y in avoid])
    placed = []
    texts = []
    for i, (p, name) in enumerate(zip(pts, names)):
        # candidates away from the frame (the box must fit inside the axes)
        ok = ((p[:, 0] > 0.04 * w) & (p[:, 0] < 0.96 * w) & (p[:, 1] > 0.08 * h)
              & (p[:, 1] < 0.92 * h))
        cand = p[ok] if ok.any() else p
        others = np.concatenate([q for j, q in enumerate(pts) if j != i] + [extra])
        d = np.sqrt(((cand[:, None, :] - others[None, :, :]) ** 2).sum(-1)).min(axis=1)
        if placed:          # another label counts as an obstacle of its own size
            q = np.array(placed)
            d = np.minimum(d, np.sqrt(((cand[:, None, :] - q[None, :, :]) ** 2).sum(-1))
                           .min(axis=1) - label_in)
        k = int(np.argmax(d))
        placed.append(cand[k])
        x = x0 + cand[k, 0] / w * (x1 - x0)
        y = y0 + cand[k, 1] / h * (y1 - y0)
        texts.append(ax.text(x, y, name, fontsize=fontsize, ha="center", va="center",
                             zorder=6, bbox=dict(boxstyle="round,pad=0.15", fc="white",
                                                 ec="none", alpha=0.9)))
    if lines is not None:
        _break_lines(ax, lines, texts)
    return texts


def _break_lines(ax, lines, texts, pad_px=2.5):
    """Break each curve where its label sits (as inline contour labels do): the line's
    points inside the label's box are left out, so no line runs under a label."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = ax.figure
    r = (fig.canvas if hasattr(fig.canvas, "get_renderer") else FigureCanvasAgg(fig)
         ).get_renderer()
    for line, text in zip(lines, texts):
        bb = text.get_window_extent(r).padded(pad_px)
        x, y = (np.asarray(v, float) for v in line.get_data())
        # resample so that the gap is cut where the box is, not at the nearest vertices
        keep = np.isfinite(x) & np.isfinite(y)
        xy = ax.transData.transform(np.column_stack([x[keep], y[keep]]))
        xy = _even(xy, 1.0)
        inside = (xy[:, 0] > bb.x0) & (xy[:, 0] < bb.x1) & (xy[:, 1] > bb.y0) & \
            (xy[:, 1] < bb.y1)
        data = ax.transData.inverted().transform(xy)
        data[inside] = np.nan
        line.set_data(data[:, 0], data[:, 1])


def plot_mu_min_curves(curves, design=None, mu_required=None, ax=None, lang="en"):
    """μmin over λ1 at constant λ2 (the paper's Fig. 3).

    Parameters
    ----------
    curves : linkage.synthesis.MuMinCurves
    design : linkage.synthesis.Design, optional
        Marked at (λ1, μmin).
    mu_required : float, optional
        A required minimum, drawn as a horizontal line. [deg]
    ax : matplotlib.axes.Axes, optional
    lang : {"en", "ru"}
        Language of the labels.

    Returns
    -------
    matplotlib.axes.Axes

    References
    ----------
    .. [1] Sereda (2016), eq. (16) and Fig. 3 (curves 1–9: λ2 = 0.1 … 0.9).
    """
    T = _text(lang)
    fig, ax = _axes(ax, (9.0, 5.2))
    kkm = T["kkm"].format(phi0=f"{curves.phi0_deg:g}")
    import matplotlib as mpl

    colors = mpl.colormaps["tab10"].colors
    xmax = float(curves.l1[-1]) * 1.04
    ax.set_xlim(0, xmax)
    ax.set_ylim(0, 92)
    avoid = []
    if mu_required is not None:
        ax.axhline(mu_required, color="tab:red", lw=1.0, ls=(0, (5, 2)),
                   label=T["required"].format(mu=f"{mu_required:g}"))
        avoid.append((np.array([0.0, xmax]), np.full(2, float(mu_required))))
    lines = []
    for i, (l2, mu) in enumerate(zip(curves.l2, curves.mu_min_deg)):
        lines += ax.plot(curves.l1, mu, color=colors[i % 10], lw=1.5,
                ls=_CURVE_DASHES[i % len(_CURVE_DASHES)],
                label=T["curve_n"].format(i=i + 1, l2=f"{l2:.2f}"))
    if design is not None:
        ax.plot([design.l1], [design.mu_min_deg], "o", color="tab:red", mec="k", mew=0.8,
                ms=7, zorder=5, label=T["chosen_mu"].format(
                    l1=f"{design.l1:.4f}", l2=f"{design.l2:.3f}",
                    mu=f"{design.mu_min_deg:.2f}"))
        avoid.append((np.array([design.l1]), np.array([design.mu_min_deg])))
    ax.set_yticks(np.arange(0, 91, 10))
    ax.set_xlabel(T["crank"])
    ax.set_ylabel(T["mu_min_axis"])
    ax.set_title(T["mu_title"].format(kkm=kkm), fontsize=10)
    ax.grid(True, lw=0.4, alpha=0.5)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False,
              handlelength=3.6)
    _label_curves(ax, [curves.l1] * len(curves.l2), list(curves.mu_min_deg),
                  [str(i + 1) for i in range(len(curves.l2))], avoid, lines=lines)
    return ax


def plot_transmission_angle(phi_deg, mu_deg, design, ax=None, lang="en"):
    """μ over a full crank turn of the chosen mechanism (eq. (12)).

    Parameters
    ----------
    phi_deg : array_like
        Crank angles from the line of centres, 0…360. [deg]
    mu_deg : array_like
        Acute transmission angle at those angles. [deg]
    design : linkage.synthesis.Design
        For φ0, μmin and where (marked), and the title.
    ax : matplotlib.axes.Axes, optional
    lang : {"en", "ru"}
        Language of the labels.

    Returns
    -------
    matplotlib.axes.Axes

    References
    ----------
    .. [1] Sereda (2016), eq. (12)–(13).
    """
    T = _text(lang)
    fig, ax = _axes(ax, (7.2, 4.4))
    d = design
    n = {"phi0": f"{d.phi0_deg:g}", "phi0b": f"{360 - d.phi0_deg:g}",
         "mu": f"{d.mu_min_deg:.2f}", "at": f"{d.mu_min_at_deg:g}",
         "l1": f"{d.l1:.4f}", "l2": f"{d.l2:.4f}", "l3": f"{d.l3:.4f}"}
    n["kkm"] = T["kkm"].format(**n)
    ax.plot(phi_deg, mu_deg, color="tab:blue", lw=1.8, label=T["mu_phi"])
    ax.axhline(90.0, color="0.5", lw=0.8, ls=":")
    for p in (d.phi0_deg, 360.0 - d.phi0_deg):
        ax.plot([p], [90.0], "o", color="tab:green", mec="k", mew=0.6, ms=6, zorder=5)
    ax.plot([], [], "o", color="tab:green", mec="k", mew=0.6,
            label=T["right"].format(a=n["phi0"], b=n["phi0b"]))
    off90 = abs(d.phi0_deg - 90.0) > SAME_ANGLE_DEG
    ats = [d.mu_min_at_deg] if off90 else [0.0, 180.0, 360.0]
    if d.mu_min_at_deg == 0.0 and 360.0 not in ats:
        ats.append(360.0)
    where = f"{n['at']}°" if off90 else T["two"].format(a="0", b="180")
    ax.plot(ats, [d.mu_min_deg] * len(ats), "v", color="tab:red", mec="k", mew=0.6, ms=7,
            zorder=5, label=T["min_at"].format(mu=n["mu"], where=where))
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.set_ylim(0, 95)
    ax.set_yticks(np.arange(0, 91, 15))
    ax.set_xlabel(T["phi_axis"])
    ax.set_ylabel(T["mu_axis"])
    ax.set_title(T["ta_title"].format(**n), fontsize=10)
    ax.grid(True, lw=0.4, alpha=0.5)
    ax.legend(loc="lower left", fontsize=8, framealpha=0.92)
    return ax
