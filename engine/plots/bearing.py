"""Plots of the bearing loads, wear diagrams and the rod-model comparison (matplotlib
object-oriented API, no ``pyplot``).

Every ``plot_*(result, ax=None, lang=...)`` draws on the given Axes (a new figure when
``ax`` is None) and returns the Axes; nothing here computes physics.  The crank-frame
drawings use the textbook view of :func:`engine.plots.plot_polar`: the crank up from the
shaft axis O, +T to the right, +K downwards (towards the shaft axis); a direction φ of
the crank frame (0° towards the shaft axis, + in the direction of rotation) is drawn at
(sin φ, −cos φ).
"""
from __future__ import annotations

import numpy as np

from ..symbols import sym

__all__ = ["plot_pin_polar", "plot_journal_polar", "plot_developed_loads", "plot_wear",
           "plot_journal_torques",
           "plot_rod_model", "plot_big_end", "plot_piston_pin", "bearing_figures",
           "BEARING_PLOT_NAMES"]


def _words(lang):
    """The words of the bearing plots in ``lang`` (``plot.bearing.*``)."""
    from crankbase.plot_texts import plot_words

    from .cylinder import engine_words
    engine_words(lang)                                   # an unknown language: a spec error
    return plot_words(lang, "bearing")


#: Line styles told apart in black-and-white print.
_STYLES = [dict(ls="-", marker=None), dict(ls="--", marker=None), dict(ls="-.", marker=None),
           dict(ls=":", marker=None), dict(ls="-", marker="o", markevery=60, ms=3),
           dict(ls="--", marker="s", markevery=60, ms=3), dict(ls="-.", marker="^",
                                                               markevery=60, ms=3)]


def _axes(ax, size=(8, 8), right=0.96, bottom=0.09):
    if ax is not None:
        return ax
    from matplotlib.figure import Figure
    fig = Figure(figsize=size)
    fig.subplots_adjust(left=0.1, right=right, bottom=bottom, top=0.9)
    return fig.subplots()


def _xy(phi_deg, r):
    p = np.radians(phi_deg)
    return r * np.sin(p), -r * np.cos(p)


def _polar(ax, a, T, K, R, title, lang, stats, cycle, Kr=0.0):
    """The load locus (T, K) with its pole; with Kr ≠ 0 (a crank pin) the curve is the
    rods' force ΣS with the pole O and the pole Oш = (0, −ΣKr.ш), from which the same
    curve reads as the pin load R (as :func:`engine.plots.plot_polar`).  ``R`` is the
    load's magnitude from the result's table (the plot computes no load). [N]"""
    from .cylinder import draw_polar

    t = _words(lang)
    draw_polar(ax, a, np.asarray(T) * 1e-3, (np.asarray(K) - Kr) * 1e-3,
               np.asarray(R) * 1e-3, Kr * 1e-3, cycle,
               None if Kr == 0.0 else sym("pole_R", lang),
               "R", t["kN"])
    ax.set_xlabel(t["T"])
    ax.set_ylabel(t["K"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(f"{title}\nRmax = {stats.max_N * 1e-3:.2f}, R{t['mean']} = "
                 f"{stats.mean_N * 1e-3:.2f} {t['kN']}, χ = {stats.chi:.2f}", fontsize=10)
    return ax


def plot_pin_polar(result, ax=None, lang="ru", throw=1, short=False):
    """Polar diagram of a crank pin's load (rods incl. Kr.ш) in its crank frame, pole at
    the pin centre.  ``result``: :class:`engine.bearings.CrankshaftLoads` or a
    :class:`engine.bearings.analysis.BearingAnalysis`; ``short``: a short title (grids)."""
    loads = getattr(result, "loads", result)
    ax = _axes(ax)
    p = loads.crankpins
    cyc = _cycle(loads)
    kr = 0.0 if loads.Kr_throw is None else float(loads.Kr_throw[throw - 1])
    t = _words(lang)
    title = f"{t['dev_pin']} {throw}" if short else t["pin"].format(k=throw)
    return _polar(ax, p["alpha_deg"].to_numpy(), p[f"T_{throw}_N"], p[f"K_{throw}_N"],
                  p[f"R_{throw}_N"], title, lang, loads.pin_stats[throw - 1], cyc, kr)


def plot_journal_polar(result, ax=None, lang="ru", journal=1, short=False):
    """Polar diagram of a main journal's load Q in the crank frame of its reference
    throw; ``short``: a short title (grids)."""
    loads = getattr(result, "loads", result)
    ax = _axes(ax)
    j = loads.journals
    k = loads.shaft.frame_throw()[journal - 1] + 1
    t = _words(lang)
    title = (f"{t['dev_j']} {journal} " if short else t["journal"].format(k=journal) + " ") \
        + t["frame_j"].format(k=k)
    return _polar(ax, j["alpha_deg"].to_numpy(), j[f"T_{journal}_N"], j[f"K_{journal}_N"],
                  j[f"R_{journal}_N"], title, lang, loads.journal_stats[journal - 1], _cycle(loads))


def _cycle(loads):
    a = loads.alpha_deg
    return 720.0 if a[-1] - a[0] > 360.0 + 1e-9 else 360.0


def plot_developed_loads(result, ax=None, lang="ru", which="journals"):
    """Developed diagrams R(α) of every crank pin (``which="pins"``) or main journal, with
    their cycle means (thin lines of the same style)."""
    loads = getattr(result, "loads", result)
    t = _words(lang)
    ax = _axes(ax, (10, 6.4), bottom=0.27)
    df = loads.crankpins if which == "pins" else loads.journals
    stats = loads.pin_stats if which == "pins" else loads.journal_stats
    a = df["alpha_deg"].to_numpy()
    label = t["dev_pin"] if which == "pins" else t["dev_j"]
    for k, s in enumerate(stats, start=1):
        st = _STYLES[(k - 1) % len(_STYLES)]
        ax.plot(a, df[f"R_{k}_N"] * 1e-3, color="k", lw=1.1,
                label=f"{label} {k}: max {s.max_N * 1e-3:.2f}, {t['mean']} "
                      f"{s.mean_N * 1e-3:.2f} {t['kN']}, χ = {s.chi:.2f}", **st)
        ax.axhline(s.mean_N * 1e-3, color="0.4", lw=0.7, ls=st["ls"])
    ax.set_xlim(a[0], a[-1])
    ax.set_xticks(np.arange(a[0], a[-1] + 1, 90))
    ax.set_ylim(bottom=0)
    ax.set_xlabel(t["alpha"])
    ax.set_ylabel(t["R"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=2,
              frameon=False)
    ax.set_title(t["dev"])
    return ax


def plot_wear(diagram, ax=None, lang="ru", note=True):
    """Wear diagram on the journal's circle: the wear drawn inwards from the circle
    (depth ∝ wear, the largest at 40 % of the radius), the oil-hole direction marked;
    ``note``: the method and the frame written under it (a grid writes it once)."""
    t = _words(lang)
    ax = _axes(ax, (7, 7.4))
    phi = np.append(diagram.phi_deg, diagram.phi_deg[0] + 360.0)
    w = np.append(diagram.wear, diagram.wear[0])
    depth = 0.4 * w / w.max() if w.max() > 0 else 0 * w
    cx, cy = _xy(phi, 1.0)
    ix, iy = _xy(phi, 1.0 - depth)
    ax.fill(np.concatenate([cx, ix[::-1]]), np.concatenate([cy, iy[::-1]]),
            facecolor="0.6", edgecolor="none", hatch="///")
    ax.plot(ix, iy, color="k", lw=0.8)
    ax.plot(cx, cy, color="k", lw=1.4)
    for ang in range(0, 360, 30):
        x0, y0 = _xy(ang, 1.0)
        x1, y1 = _xy(ang, 1.08)
        ax.plot([x0, x1], [y0, y1], color="0.4", lw=0.6)
        tx, ty = _xy(ang, 1.17)
        ax.text(tx, ty, f"{ang}°", ha="center", va="center", fontsize=7, color="0.3")
    hole = diagram.oil_hole_deg
    hx, hy = _xy(hole, 1.0)
    ax.plot([0, 0.62 * hx], [0, 0.62 * hy], color="C3", lw=1.0, ls="--")
    ax.plot([0], [0], "ko", ms=3)
    ax.plot([hx], [hy], marker=(3, 0, 180 - hole), ms=7, color="C3", ls="none")
    ox, oy = _xy(0.0, 1.42)
    ax.annotate("", xy=(ox, oy - 0.08), xytext=(ox, oy + 0.12),
                arrowprops=dict(arrowstyle="-|>", color="0.3", lw=1.0))
    kind, _, num = diagram.name.partition(" ")
    ax.text(ox + 0.06, oy - 0.02, t["axis"].get(kind, ""), fontsize=7.5, color="0.3",
            va="center")
    ax.set_aspect("equal")
    ax.set_xlim(-1.65, 1.65)
    ax.set_ylim(-1.65, 1.65)
    ax.axis("off")
    # nor its axes' ticks (an axes switched off draws none, but the placing of its title
    # laid out the y axis's ticks, made for nothing)
    ax.xaxis.set_visible(False)
    ax.yaxis.set_visible(False)
    ax.set_title(t["wear"].format(name=f"{t['names'].get(kind, kind)} {num}"), fontsize=11)
    _hole_label(ax, f"{t['hole']} {hole:g}°", hole)
    if not note:
        return ax
    text = t["wear_note"].format(h=diagram.half_angle_deg, zero=t["axis"].get(kind, ""))
    ax.text(0.5, -0.02, text,
            transform=ax.transAxes, ha="center", va="top", fontsize=7.5, color="0.3")
    return ax


def _hole_label(ax, text, hole):
    """The oil hole's name outside the ring of angle labels, in the hole's direction (as
    near as it is free): never over the wear, the circle or a label."""
    from crankbase.plot_labels import Obstacles, place_label, renderer_of

    r = renderer_of(ax.figure)
    ax.apply_aspect()
    tr = ax.transData.transform
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    for txt in ax.texts:
        e = txt.get_window_extent(r)
        obs.boxes.append((e.x0, e.y0, e.x1, e.y1))
    for line in ax.lines:
        obs.add_line(tr(line.get_xydata()))
    for ann in ax.texts:
        if getattr(ann, "arrow_patch", None) is not None:
            obs.add_segment(tr(ann.xy), tr(ann.xyann))
    anchor = tr([_xy(hole, 1.1)])[0]
    normal = np.array(_xy(hole, 1.0)) * (1, 1)
    t = place_label(ax, obs, anchor, text, normal=normal, gaps_pt=(6, 10, 16, 24),
                    fontsize=8.5, color="C3", gid="oil-hole")
    if t is None:                  # no room beside the ring: under the title
        ax.set_title(ax.get_title() + f"\n{text}", fontsize=10)


def plot_journal_torques(result, ax=None, lang="ru"):
    """Torques carried by the main journals over the crank angle, one line style each."""
    loads = getattr(result, "loads", result)
    t = _words(lang)
    ax = _axes(ax, (10, 6.0), bottom=0.2)
    df = loads.journal_torques
    a = df["alpha_deg"].to_numpy()
    for j in range(1, len(df.columns)):
        ax.plot(a, df[f"M_{j}_Nm"], color="k", lw=1.1, label=t["Mj"].format(j=j),
                **_STYLES[(j - 1) % len(_STYLES)])
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlim(a[0], a[-1])
    ax.set_xticks(np.arange(a[0], a[-1] + 1, 90))
    ax.set_xlabel(t["alpha"])
    ax.set_ylabel(t["M"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=5,
              frameon=False)
    ax.set_title(t["tq"])
    return ax


def plot_rod_model(comparison, ax=None, lang="ru"):
    """ΔT, ΔK, ΔRшш (rigid − two-mass) over α; the right axis reads ΔT as ΔMкр = ΔT·R."""
    t = _words(lang)
    ax = _axes(ax, (10, 5.6), right=0.9)
    df = comparison.table
    a = df["alpha_deg"].to_numpy()
    for col, lab, st in (("dT_N", "ΔT", _STYLES[0]), ("dK_N", "ΔK", _STYLES[1]),
                         ("dR_N", f"Δ{sym('R', lang)}", _STYLES[2])):
        ax.plot(a, df[col], color="k", lw=1.1, label=lab, **st)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlim(a[0], a[-1])
    ax.set_xticks(np.arange(a[0], a[-1] + 1, 90))
    ax.set_xlabel(t["alpha"])
    ax.set_ylabel(t["dN"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(fontsize=9, loc="upper right")
    R = float(np.max(np.abs(df["dM_Nm"]))) / max(float(np.max(np.abs(df["dT_N"]))), 1e-300)
    sec = ax.secondary_yaxis("right", functions=(lambda x: x * R, lambda y: y / R))
    sec.set_ylabel(t["dM"])
    rod = comparison.rod
    ax.set_title(f"{t['rod']}: J = {rod.inertia:.4g} {t['kgm2']}, m·a·b = "
                 f"{comparison.J_two_mass:.4g} {t['kgm2']} ({t['exact']})",
                 fontsize=10)
    return ax


def plot_big_end(result, ax=None, lang="ru"):
    """Polar diagram of the big-end bearing load in the rod frame."""
    t = _words(lang)
    ax = _axes(ax)
    df = result.rod_bearings
    x, y = df["Rbe_across_N"].to_numpy() * 1e-3, df["Rbe_along_N"].to_numpy() * 1e-3
    a = df["alpha_deg"].to_numpy()
    ax.plot(x, y, color="C0", lw=1.2)
    labels = np.arange(0.0, _cycle(result.loads), 30.0)
    lx, ly = np.interp(labels, a, x), np.interp(labels, a, y)
    ax.plot(lx, ly, "o", ms=3, color="C0", gid="alpha-marker")
    ax.plot([0], [0], "ks", ms=4)
    ax.axhline(0, color="k", lw=0.7)
    ax.axvline(0, color="k", lw=0.7)
    ax.set_aspect("equal", adjustable="datalim")
    from .cylinder import label_alpha_points
    label_alpha_points(ax, x, y, a, labels, lx, ly, ms=3)
    ax.set_xlabel(t["across"])
    ax.set_ylabel(t["along"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(t["be"], fontsize=10)
    return ax


def plot_piston_pin(result, ax=None, lang="ru"):
    """Piston-pin load over α: axial Pп, side N and magnitude."""
    t = _words(lang)
    ax = _axes(ax, (10, 5.6))
    df = result.rod_bearings
    a = df["alpha_deg"].to_numpy()
    for col, lab, st in (("Pp_axial_N", t["Pp"], _STYLES[0]), ("Pp_side_N", t["N"],
                                                                _STYLES[1]),
                         ("Pp_N", t["Ppm"], _STYLES[3])):
        ax.plot(a, df[col] * 1e-3, color="k", lw=1.1, label=lab, **st)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlim(a[0], a[-1])
    ax.set_xticks(np.arange(a[0], a[-1] + 1, 90))
    ax.set_xlabel(t["alpha"])
    ax.set_ylabel(t["kN"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(fontsize=9, loc="upper right")
    ax.set_title(t["pp"])
    return ax


#: File stems of the one-cylinder bearing plots (rod_model only with the rigid rod,
#: piston_pin only when the piston mass is known).
BEARING_PLOT_NAMES = ("polar_pins", "polar_journals", "developed_pins",
                      "developed_journals", "wear_pins", "wear_journals", "journal_torques",
                      "big_end", "piston_pin", "rod_model")


def _wears(w):
    return list(w) if isinstance(w, (list, tuple)) else [w]


def _grid(n, cell, cols=3):
    """A figure with n axes in a grid of cell-sized cells (fixed margins)."""
    from matplotlib.figure import Figure
    ncol = min(n, cols)
    nrow = -(-n // ncol)
    fig = Figure(figsize=(cell[0] * ncol, cell[1] * nrow))
    fig.subplots_adjust(left=0.06 if ncol > 1 else 0.1, right=0.97, bottom=0.12 / nrow,
                        top=1 - 0.09 / nrow, wspace=0.28, hspace=0.32)
    axes = np.atleast_1d(fig.subplots(nrow, ncol)).ravel()
    for ax in axes[n:]:
        ax.set_visible(False)
    return fig, axes[:n]


def bearing_figures(analysis, lang="ru"):
    """``{stem: Figure}`` of a :class:`engine.bearings.analysis.BearingAnalysis` (one
    cylinder) or an :class:`engine.bearings.train.EngineBearings` (a whole engine): the
    polar and wear diagrams of every pin and journal in one grid each."""
    out = {}
    loads = analysis.loads
    npin, nj = len(loads.pin_stats), len(loads.journal_stats)

    def fig(stem, func, *args, size=(8, 8), right=0.96, bottom=0.09, **kw):
        ax = _axes(None, size, right, bottom)
        func(*args, ax=ax, lang=lang, **kw)
        out[stem] = ax.figure

    def grid(stem, n, cell, draw):
        f, axes = _grid(n, cell)
        for k, ax in enumerate(axes, start=1):
            draw(ax, k)
            ax.title.set_fontsize(9)
        out[stem] = f

    grid("polar_pins", npin, (5.6, 5.6),
         lambda ax, k: plot_pin_polar(analysis, ax=ax, lang=lang, throw=k, short=True))
    grid("polar_journals", nj, (5.6, 5.6),
         lambda ax, k: plot_journal_polar(analysis, ax=ax, lang=lang, journal=k,
                                          short=True))
    fig("developed_pins", plot_developed_loads, analysis, size=(10, 6.4), bottom=0.27,
        which="pins")
    fig("developed_journals", plot_developed_loads, analysis, size=(10, 6.4), bottom=0.27)
    pins, jw = _wears(analysis.pin_wear), _wears(analysis.journal_wear)
    t = _words(lang)
    for stem, diagrams, kind in (("wear_pins", pins, "pin"), ("wear_journals", jw, "journal")):
        grid(stem, len(diagrams), (4.8, 5.0),
             lambda ax, k, d=diagrams: plot_wear(d[k - 1], ax=ax, lang=lang, note=False))
        out[stem].text(0.5, 0.005, t["wear_note"].format(
            h=diagrams[0].half_angle_deg, zero=t["axis"][kind]).replace("\n", " "),
            ha="center", va="bottom", fontsize=8, color="0.3")
    fig("journal_torques", plot_journal_torques, analysis, size=(10, 6.0), bottom=0.2)
    fig("big_end", plot_big_end, analysis)
    if not analysis.rod_bearings["Pp_N"].isna().all():
        fig("piston_pin", plot_piston_pin, analysis, size=(10, 5.6))
    if getattr(analysis, "rod_comparison", None) is not None:
        fig("rod_model", plot_rod_model, analysis.rod_comparison, size=(10, 5.6),
            right=0.9)
    return out
