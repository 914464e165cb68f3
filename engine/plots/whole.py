"""Plots of the whole engine (:class:`engine.EngineTrainResult`, :func:`engine.analyze_engine`):
total torque, excess work, the free forces' and moments' loci and curves, the crankshaft
scheme.  Same conventions as :mod:`engine.plots.cylinder`: matplotlib object-oriented API
only, each ``plot_*(result, ax=None, lang="ru")`` draws on the given Axes (or a new
Figure's one) and returns it; :func:`train_figures` composes the report's figures.
"""
from __future__ import annotations

import numpy as np

from ..kinematics import guide_direction
from .cylinder import engine_words, figure_axes

__all__ = ["plot_total_torque", "plot_excess_work", "plot_force_locus", "plot_moment_locus",
           "plot_free_forces", "plot_free_moments", "plot_crankshaft", "train_figures",
           "TRAIN_PLOT_NAMES"]

#: File stems of the whole engine's figures, in order.
TRAIN_PLOT_NAMES = ("torque_total", "excess_work", "free_force_locus", "free_moment_locus",
                    "free_forces", "free_moments", "crankshaft")


def _ttexts(lang):
    """The words of the whole engine's plots (``plot.train.*``)."""
    engine_words(lang)
    from crankbase.plot_texts import plot_words

    return plot_words(lang, "train")


def _theta_axis(ax, cycle, t):
    ax.set_xlim(0, cycle)
    ax.set_xticks(np.arange(0, cycle + 1, 90 if cycle > 360 else 45))
    ax.set_xlabel(t["theta"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.axhline(0, color="k", lw=0.7)


def plot_total_torque(result, ax=None, lang="ru"):
    """Total torque over the cycle: each cylinder's curve faint, the sum, its mean, max
    and min. ``result``: :class:`engine.EngineTrainResult`. Returns the Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax, (10, 6), bottom=0.2, left=0.09)
    c, s = result.curves, result.summary
    th = c["alpha_deg"].to_numpy()
    n = result.layout.n
    for j in range(n):
        ax.plot(th, c[f"M_{j + 1}_Nm"].to_numpy(), color="0.55", lw=0.6, ls=":",
                label=t["cyl"].format(n=n) if j == 0 else None, gid="context")
    ax.plot(th, c["M_total_Nm"].to_numpy(), color="C0", lw=1.6, label=t["Mtot"])
    ax.axhline(s.M_mean_Nm, color="C3", ls="--", lw=1.1, label=t["mean"].format(v=s.M_mean_Nm))
    # max and min marked on the curve and named in the legend (below the axes): a text
    # beside the point would be cut at the edge or crossed by the cylinders' curves
    for v, a, key, mk in ((s.M_max_Nm, s.alpha_M_max_deg, "Mmax", "^"),
                          (s.M_min_Nm, s.alpha_M_min_deg, "Mmin", "v")):
        ax.plot([a], [v], mk, color="C3", ms=6, ls="none", label=t[key].format(v=v, a=a))
    _theta_axis(ax, result.layout.cycle_deg, t)
    ax.set_ylabel(t["M"])
    # below the axes: the curves fill the whole plot, a legend inside would cover them
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=3, fontsize=8,
              frameon=False)
    ax.set_title(f"{t['tq']}: {result.cylinder.spec.name}, μ = {s.mu:.3f}")
    return ax


def plot_excess_work(result, ax=None, lang="ru"):
    """The running excess work ∫(M − Mср)dθ over the cycle with Lизб marked. Returns the
    Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax)
    c = result.curves
    th, w = c["alpha_deg"].to_numpy(), c["work_J"].to_numpy()
    ax.plot(th, w, color="C0", lw=1.5)
    i, k = int(np.argmax(w)), int(np.argmin(w))
    for idx in (i, k):
        ax.axhline(w[idx], color="0.4", lw=0.7, ls="--")
    x = th[i] if abs(th[i] - th[k]) > 20 else th[i] + 20
    ax.annotate("", xy=(x, w[i]), xytext=(x, w[k]),
                arrowprops=dict(arrowstyle="<->", color="C3", lw=1.2))
    _theta_axis(ax, result.layout.cycle_deg, t)
    ax.set_ylabel(t["work"])
    ax.set_title(f"{t['wt']}: {result.cylinder.spec.name}")
    _free_label(ax, t["L"].format(v=result.summary.L_excess_J), (x, (w[i] + w[k]) / 2),
                normal=(1, 0), color="C3", fontsize=9)
    return ax


def _free_label(ax, text, xy, normal=(1, 0), **kw):
    """Put ``text`` near the data point ``xy`` where no drawn line, arrow or text of
    ``ax`` crosses it (the limits are frozen first); when there is no such place, the text
    goes into the title."""
    from crankbase.plot_labels import frozen_frame, place_label, renderer_of

    r = renderer_of(ax.figure)
    tr, obs = frozen_frame(ax)
    for line in ax.lines:
        obs.add_line(line.get_transform().transform(line.get_xydata()))
    for txt in ax.texts:
        if txt.get_text():
            e = txt.get_window_extent(r)
            obs.boxes.append((e.x0, e.y0, e.x1, e.y1))
        if getattr(txt, "arrow_patch", None) is not None:
            obs.add_segment(tr(txt.xy), tr(txt.xyann))
    if place_label(ax, obs, tr(xy), text, normal=normal, **kw) is None:
        ax.set_title(f"{ax.get_title()}\n{text}")


def _min_extent(result, kind):
    """Smallest half-range of a force (kN) or moment (N·m) axis: 2 % of the engine's
    first-order inertia force (times its length), so that round-off of a balanced
    engine (~1e-13) is drawn as the zero it is."""
    spec, lay = result.cylinder.spec, result.layout
    F = lay.n * spec.mj * spec.R * spec.omega ** 2
    if kind == "F":
        return 0.02 * F * 1e-3
    return 0.02 * F * max(float(np.ptp(lay.z)), spec.bore)


def _locus(ax, result, kind, t):
    b = result.balance_curves
    unit = "N" if kind == "F" else "Nm"
    scale = 1e-3 if kind == "F" else 1.0
    for key, label, style in (("after", t["after"], dict(color="C0", ls="-", lw=2.6,
                                                         alpha=0.45)),
                              ("before", t["before"], dict(color="C1", ls="--", lw=1.2))):
        if key == "before":
            x = b[f"{kind}j_x_{unit}"] + b[f"{kind}r_x_{unit}"]
            y = b[f"{kind}j_y_{unit}"] + b[f"{kind}r_y_{unit}"]
        else:
            x, y = b[f"{kind}_x_{unit}"], b[f"{kind}_y_{unit}"]
        x, y = x.to_numpy() * scale, y.to_numpy() * scale
        ax.plot(x, y, label=label, **style)
        ax.plot(x[:1], y[:1], "o" if key == "after" else "s", color=style["color"], ms=5)
    ax.plot([0], [0], "k+", ms=10)
    lim = _min_extent(result, kind)
    ax.plot([-lim, lim], [-lim, lim], alpha=0)          # keeps at least this extent
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(loc="upper right", fontsize=8)


def plot_force_locus(result, ax=None, lang="ru"):
    """Locus of the free force vector over one revolution, before and after the
    counterweights (the marker is θ = 0). Returns the Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax, (7, 7), left=0.14, bottom=0.09)
    _locus(ax, result, "F", t)
    ax.set_xlabel(t["Fx"])
    ax.set_ylabel(t["Fy"])
    ax.set_title(f"{t['Floc']}: {result.cylinder.spec.name}", fontsize=10)
    return ax


def plot_moment_locus(result, ax=None, lang="ru"):
    """Locus of the free moment vector over one revolution, before and after the
    counterweights. Returns the Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax, (7, 7), left=0.14, bottom=0.09)
    _locus(ax, result, "M", t)
    ax.set_xlabel(t["Mx"])
    ax.set_ylabel(t["My"])
    ax.set_title(f"{t['Mloc']}: {result.cylinder.spec.name}", fontsize=10)
    return ax


def _over_alpha(ax, result, kind, t):
    b = result.balance_curves
    th = b["alpha_deg"].to_numpy()
    unit = "N" if kind == "F" else "Nm"
    scale = 1e-3 if kind == "F" else 1.0
    sym = {"F": ("F_x", "F_y"), "M": ("M_x", "M_y")}[kind]
    for key, lab, styles in (("after", t["after"], ("-", ":")),
                             ("before", t["before"], ("--", "-."))):
        for comp, name, ls, col in (("x", sym[0], styles[0], "C0"),
                                    ("y", sym[1], styles[1], "C3")):
            if key == "before":
                v = b[f"{kind}j_{comp}_{unit}"] + b[f"{kind}r_{comp}_{unit}"]
            else:
                v = b[f"{kind}_{comp}_{unit}"]
            after = key == "after"
            ax.plot(th, v.to_numpy() * scale, ls=ls, color=col if after else
                    ("C1" if comp == "x" else "C2"), lw=2.6 if after else 1.2,
                    alpha=0.4 if after else 1.0, label=f"${name}$, {lab}")
    lim = _min_extent(result, kind)
    lo, hi = ax.get_ylim()
    ax.set_ylim(min(lo, -lim), max(hi, lim))
    _theta_axis(ax, 360.0, t)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=4, fontsize=8,
              frameon=False)


def plot_free_forces(result, ax=None, lang="ru"):
    """Free force components over one revolution, before and after the counterweights.
    Returns the Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax, (10, 6), bottom=0.2, left=0.1)
    _over_alpha(ax, result, "F", t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['Fa']}: {result.cylinder.spec.name}")
    return ax


def plot_free_moments(result, ax=None, lang="ru"):
    """Free moment components over one revolution, before and after the counterweights.
    Returns the Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax, (10, 6), bottom=0.2, left=0.1)
    _over_alpha(ax, result, "M", t)
    ax.set_ylabel(t["moment"])
    ax.set_title(f"{t['Ma']}: {result.cylinder.spec.name}")
    return ax


def plot_crankshaft(result, ax=None, lang="ru"):
    """The crankshaft seen from the flywheel end at θ = 0: the bank axes, each throw with
    its cylinders, the rotation and the firing order. Returns the Axes."""
    t = _ttexts(lang)
    ax = figure_axes(ax, (7.5, 8))
    lay = result.layout
    cyl = lay.cylinders
    g1 = float(lay.bank_deg[0])
    banks = sorted(set(zip(cyl["bank"], cyl["bank_angle_deg"])))
    ax.set_xlim(-1.9, 1.9)
    ax.set_ylim(-1.9, 1.9)
    ax.set_aspect("equal")
    from matplotlib.patches import Circle

    ax.add_patch(Circle((0, 0), 1.0, fill=False, color="0.8", lw=0.8))
    ends = []                                    # (tip, text, colour, fontsize)
    for b, gam in banks:
        d = guide_direction(gam, deg=True)
        ax.plot([0, 1.55 * d.real], [0, 1.55 * d.imag], color="0.45", lw=1.0, ls="--")
        ends.append((1.55 * d, t["bank"].format(b=b), "0.3", 9))
    groups = {}                                  # throws at the same angle: one label
    for k, tau in enumerate(lay.throw_angles_deg):
        groups.setdefault(round(tau % 360.0, 6), []).append(k)
    arrows = []
    for g, (tau, ks) in enumerate(sorted(groups.items())):
        d = guide_direction(g1 + tau, deg=True)
        members = ", ".join(str(c) for k in ks
                            for c in cyl["cylinder"][cyl["throw"] == k + 1])
        ax.annotate("", xy=(d.real, d.imag), xytext=(0, 0),
                    arrowprops=dict(arrowstyle="-|>", color=f"C{g % 10}", lw=2.2))
        arrows.append(d)
        label = t["throw"].format(k=", ".join(str(k + 1) for k in ks), c=members)
        ends.append((d, label, f"C{g % 10}", 8))
    # the sense of rotation: an arc arrow round the shaft axis, counter-clockwise over
    # the top (a quadratic Bézier from (0.35, 0.18) to (−0.35, 0.18))
    s_ = np.linspace(0.0, 1.0, 40)[:, None]
    p0, c1, p2 = np.array([0.35, 0.18]), np.array([0.0, 0.53]), np.array([-0.35, 0.18])
    arc = (1 - s_) ** 2 * p0 + 2 * s_ * (1 - s_) * c1 + s_ ** 2 * p2
    ax.annotate("", xy=tuple(p2), xytext=tuple(p0),
                arrowprops=dict(arrowstyle="-|>", connectionstyle="arc3,rad=0.5",
                                color="k", lw=1.0))
    ax.plot([0], [0], "ko", ms=4)
    ax.set_xticks([])
    ax.set_yticks([])
    order = "-".join(str(c) for c in lay.firing_order)
    throws = ", ".join(f"{x:g}°" for x in lay.throw_angles_deg)
    ax.set_xlabel(t["order"].format(o=order) + "\n" + t["throws"].format(t=throws),
                  fontsize=9)
    ax.set_title(f"{t['crank']}: {result.cylinder.spec.name}", fontsize=10)
    # every label where no arrow, line or other label crosses it
    from crankbase.plot_labels import Obstacles, place_label, renderer_of

    renderer_of(ax.figure)
    ax.apply_aspect()
    tr = ax.transData.transform
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    for line in ax.lines:
        obs.add_line(tr(line.get_xydata()))
    phi = np.linspace(0, 2 * np.pi, 200)
    obs.add_line(tr(np.column_stack([np.cos(phi), np.sin(phi)])))
    obs.add_line(tr(arc))
    o = tr([(0.0, 0.0)])[0]
    for d in arrows:
        obs.add_segment(o, tr([(d.real, d.imag)])[0])
    obs.add_marker(o, 8)
    for d, label, col, fs in ends:
        at = tr([(d.real, d.imag)])[0]
        if place_label(ax, obs, at, label, normal=at - o, gaps_pt=(3, 6, 10, 15),
                       color=col, fontsize=fs) is None:
            ax.set_title(ax.get_title() + f"\n{label}", fontsize=9)
    top = tr([(0.0, 0.53)])[0]
    place_label(ax, obs, top, t["rot"], normal=(0, 1), fontsize=8)
    return ax


def train_figures(result, lang="ru"):
    """The whole engine's figures, ``{stem: Figure}`` in :data:`TRAIN_PLOT_NAMES` order."""
    funcs = (plot_total_torque, plot_excess_work, plot_force_locus, plot_moment_locus,
             plot_free_forces, plot_free_moments, plot_crankshaft)
    return {name: f(result, None, lang).figure for name, f in zip(TRAIN_PLOT_NAMES, funcs)}
