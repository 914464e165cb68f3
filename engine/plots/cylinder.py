"""Plots of one cylinder's force table, matplotlib object-oriented API only (``Figure``,
never ``pyplot``), headless.

Every ``plot_*(result, ax=None, lang="ru")`` consumes an :class:`engine.EngineResult`
(:func:`engine.analyze`), draws on the given Axes (or on a new Figure's one) and returns
the Axes, so it works in a notebook; nothing here computes physics.  :func:`figures`
composes the report's figures by file stem (the CLI saves them).
"""
from __future__ import annotations

import numpy as np

from crankbase.errors import Problem, Text
from crankbase.texts import OFFERED
from ..kinematics import guide_direction
from ..symbols import math_symbol, sym, symbol_set

__all__ = ["plot_indicator", "plot_pressure", "plot_piston_forces", "plot_nkt",
           "plot_torque", "plot_polar", "plot_developed", "figures", "PLOT_NAMES", "LANGS"]

#: File stems of the report's figures, in order.
PLOT_NAMES = ("indicator", "forces_P", "forces_NKT", "torque", "polar_Rshsh",
              "developed_Rshsh")

LANGS = OFFERED              # every offered language (crankbase.texts.languages)

#: Symbols of the quantities, from the one table :mod:`engine.symbols`: the Russian
#: textbook's, and the English report's set as mathtext (no Cyrillic in an English plot).
_PLOT_KEYS = dict(p="p_gas", dPg="dPg", Pj="Pj", P="P", S="S", N="N", K="K", T="T",
                  M="M", R="R", Kr="Kr", Osh="pole_R")
SYMBOLS = {
    "ru": dict({k: sym(v, "ru") for k, v in _PLOT_KEYS.items()}, Fx="Fп·x"),
    "en": dict({k: math_symbol(v) for k, v in _PLOT_KEYS.items()}, Fx="$A_{p} x$"),
}



def engine_words(lang):
    """The words of the cylinder's plots in ``lang`` (the ``plot.engine.*`` texts) and its
    symbols."""
    if lang not in LANGS:
        from ..spec import EngineSpecError
        raise EngineSpecError(Problem("lang", Text("errors.engine.plots.valid",
                                                   {"lang": lang, "items": ', '.join(LANGS)})))
    from crankbase.plot_texts import plot_words

    return dict(plot_words(lang, "engine"), sym=SYMBOLS[symbol_set(lang)])


def figure_axes(ax, figsize=(10, 5.6), **margins):
    """The given Axes, or the only Axes of a new Figure with fixed margins (a layout
    engine would double the rendering time)."""
    if ax is not None:
        return ax
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize)
    adjust = dict(left=0.08, right=0.975, bottom=0.1, top=0.92)
    adjust.update(margins)
    fig.subplots_adjust(**adjust)
    return fig.subplots()


def _alpha_axis(ax, spec, t):
    cyc = spec.cycle_deg
    ax.set_xlim(0, cyc)
    ax.set_xticks(np.arange(0, cyc + 1, 90 if cyc > 360 else 30))
    ax.set_xlabel(t["alpha"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.axhline(0, color="k", lw=0.7)


def plot_indicator(result, ax=None, lang="ru"):
    """Indicator diagram p–V of the result's gas pressure (V = Vc + Fп·x when ε is known,
    else the swept volume Fп·x). Returns the Axes."""
    t = engine_words(lang)
    ax = figure_axes(ax, (6, 5))
    spec, c = result.spec, result.curves
    p = c["p_gas_MPa"].to_numpy()
    sw = spec.area * c["x_mm"].to_numpy()            # swept volume [l] = m² · mm
    if spec.Vc is not None:
        ax.plot(spec.Vc * 1e3 + sw, p, color="C0", lw=1.4)
        ax.set_xlabel(t["V"])
        vc, va = spec.Vc * 1e3, (spec.Vc + spec.Vh) * 1e3
        for v, lab, side in ((vc, t["tdc"], 1), (va, t["bdc"], -1)):
            ax.axvline(v, color="0.5", lw=0.7, ls="--")
            # TDC right of its line, BDC left of its (the frame is close on the right)
            ax.annotate(lab, (v, 1.0), xycoords=("data", "axes fraction"),
                        xytext=(2 * side, -12), textcoords="offset points", fontsize=8,
                        ha="left" if side > 0 else "right")
        ax.set_xlim(0, va * 1.05)
    else:
        ax.plot(sw, p, color="C0", lw=1.4)
        ax.set_xlabel(t["Vs"])
    ax.set_ylabel(t["p"])
    from .diagram_points import fullness

    s = result.summary
    title = f"{t['pV']}: pi = {s.pi_MPa:.3f} {t['MPa']}"
    phi = fullness(s)
    if phi is not None:
        title += f";  {sym('fullness', lang)} = pi/p′i = {phi:.3f}"
    ax.set_title(title)
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_ylim(bottom=0)
    a = c["alpha_deg"].to_numpy()
    v0 = spec.Vc * 1e3 if spec.Vc is not None else 0.0
    _diagram_points(ax, result, lambda al: v0 + np.interp(al, a, sw), lang)
    return ax


def plot_pressure(result, ax=None, lang="ru"):
    """Gas pressure over α with its peak marked. Returns the Axes."""
    t = engine_words(lang)
    ax = figure_axes(ax, (6, 5))
    c = result.curves
    p = c["p_gas_MPa"].to_numpy()
    a = c["alpha_deg"].to_numpy()
    ax.plot(a, p, color="C3", lw=1.4)
    _alpha_axis(ax, result.spec, t)
    ax.set_ylabel(t["p"])
    ax.set_title(t["pa"])
    ax.set_ylim(bottom=0)
    i = int(np.argmax(p))
    ax.annotate(f"{p[i]:.2f} ({a[i]:g}°)", (a[i], p[i]), xytext=(8, -4),
                textcoords="offset points", fontsize=8)
    _diagram_points(ax, result, lambda al: np.asarray(al, float), lang)
    return ax


#: Line styles of the curves of one plot: colour and dash pattern both differ, so the
#: curves stay apart in black-and-white print (Okabe–Ito colours, distinct greys).
LINE_STYLES = (dict(color="#0072B2", ls="-", lw=1.6), dict(color="#D55E00", ls="--", lw=1.6),
               dict(color="#000000", ls="-.", lw=1.4), dict(color="#009E73", ls=":", lw=1.8))


def _lines(ax, table, cols, labels, scale=1e-3):
    a = table["alpha_deg"].to_numpy()
    for k, (col, lab) in enumerate(zip(cols, labels)):
        ax.plot(a, table[col].to_numpy() * scale, label=lab,
                **LINE_STYLES[k % len(LINE_STYLES)])
    ax.legend(loc="best", fontsize=9)


def plot_piston_forces(result, ax=None, lang="ru"):
    """ΔPг, Pj and P over α. Returns the Axes."""
    t = engine_words(lang)
    ax = figure_axes(ax)
    y = t["sym"]
    _lines(ax, result.curves, ("dPg_N", "Pj_N", "P_N"),
           (y["dPg"], y["Pj"], f"{y['P']} = {y['dPg']} + {y['Pj']}"))
    _alpha_axis(ax, result.spec, t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['fP']}: {result.spec.name}")
    return ax


def plot_nkt(result, ax=None, lang="ru"):
    """N, K and T over α. Returns the Axes."""
    t = engine_words(lang)
    ax = figure_axes(ax)
    y = t["sym"]
    _lines(ax, result.curves, ("N_N", "K_N", "T_N"), (y["N"], y["K"], y["T"]))
    _alpha_axis(ax, result.spec, t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['fNKT']}: {result.spec.name}")
    return ax


def plot_torque(result, ax=None, lang="ru"):
    """Mкр over α with its cycle mean. Returns the Axes."""
    t = engine_words(lang)
    ax = figure_axes(ax)
    c = result.curves
    M = t["sym"]["M"]
    ax.plot(c["alpha_deg"].to_numpy(), c["M_Nm"].to_numpy(), label=M, **LINE_STYLES[0])
    m = result.summary.M_mean_Nm
    ax.axhline(m, **{**LINE_STYLES[1], "lw": 1.0}, label=f"{M}{t['sub']} = {m:.1f} {t['Nm']}")
    ax.legend(loc="best", fontsize=9)
    _alpha_axis(ax, result.spec, t)
    ax.set_ylabel(t["torque"])
    ax.set_title(f"{t['tq']}: {result.spec.name}")
    return ax


def _at(table, col, angles):
    a = table["alpha_deg"].to_numpy()
    return np.interp(angles, a, table[col].to_numpy())


def plot_polar(result, ax=None, lang="ru"):
    """Polar diagram of the crank-pin load in the crank-fixed frame. Returns the Axes.

    The curve is the locus of the rod force S = (T, K) with the pole O; the pole shifted
    by Kr.ш, Oш = (0, −Kr.ш), makes the same curve read as Rшш (the vector from Oш to a
    point).  +T to the right, +K downwards (towards the shaft axis), equal aspect, α
    labels every 30°, Rшш max and min marked.
    """
    t = engine_words(lang)
    ax = figure_axes(ax, (9, 9.8), left=0.09, right=0.97, bottom=0.12, top=0.95)
    spec, c = result.spec, result.curves
    y = t["sym"]
    draw_polar(ax, c["alpha_deg"].to_numpy(), c["T_N"].to_numpy() * 1e-3,
               c["K_N"].to_numpy() * 1e-3, c["R_N"].to_numpy() * 1e-3, spec.Kr * 1e-3,
               spec.cycle_deg, y["Osh"], y["R"], t["kN"])
    ax.set_ylabel(t["K"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(f"{t['polar']}: {spec.name}", fontsize=11)
    import textwrap

    # the conventions go under the T axis, outside the diagram (never over the curve)
    kr = f"{spec.Kr:.0f}".replace("-", "−")               # a minus sign, not a hyphen
    note = (textwrap.wrap(f"{y['Kr']} = {kr} {t['N']};  {t['poles']}", 80)
            + textwrap.wrap(t["frame"], 80))
    ax.set_xlabel("\n".join([t["T"]] + note), fontsize=8.5, linespacing=1.4)
    return ax


def draw_polar(ax, a, T, K, R, kr, cycle_deg, pole_name, r_name, unit, ms=3.5):
    """Draw a polar load diagram on ``ax`` (the shared drawing of :func:`plot_polar` and
    the bearing diagrams of :mod:`engine.plots.bearing`): the locus (T, K), +K
    downwards, equal aspect; the pole O and the shifted pole (0, −kr) named
    ``pole_name`` (None: no shifted pole); α markers and labels every 30°; the arrows to the largest and the
    smallest load ``R`` with their values; every label placed clear of the others, the
    markers and the arrows (:func:`_polar_labels`).  All quantities in the plot's unit
    (``unit``, e.g. kN); ``R`` comes from the result's table (nothing is computed here).
    """
    a, T, K, R = (np.asarray(v, float) for v in (a, T, K, R))
    ax.plot(T, K, color="C0", lw=1.3)
    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_yaxis()
    ax.axhline(0, color="k", lw=0.7)
    ax.axvline(0, color="k", lw=0.7)
    labels = np.arange(0, cycle_deg, 30.0)                # α labels every 30°
    lt, lk = np.interp(labels, a, T), np.interp(labels, a, K)
    ax.plot(lt, lk, "o", ms=ms, color="C0", gid="alpha-marker")
    ax.plot([0], [0], "ks", ms=5, gid="pole-marker")
    if pole_name:                   # no shifted pole (a main journal): arrows from O
        ax.plot([0], [-kr], "o", color="C3", ms=6, gid="pole-marker")
    ext = [(int(np.argmax(R)), "max", "C3"), (int(np.argmin(R)), "min", "C2")]
    for idx, _, col in ext:
        ax.annotate("", xy=(T[idx], K[idx]), xytext=(0, -kr),
                    arrowprops=dict(arrowstyle="-|>", color=col, lw=1.3))
    # freeze the limits (equal aspect, room for labels) before measuring anything
    ax.margins(0.07)
    ax.autoscale_view()
    ax.apply_aspect()
    ax.set_xlim(ax.get_xlim())
    ax.set_ylim(ax.get_ylim())
    ax.set_autoscale_on(False)
    _polar_labels(ax, T, K, kr, lt, lk, labels, ext, R, a, pole_name, r_name, unit, ms)
    return ax


def _polar_labels(ax, T, K, kr, lt, lk, angles, ext, R, a, pole_name, r_name, unit, ms):
    """Place the pole names, the Rшш max/min texts and the α labels of the polar diagram
    so that no label covers another label, a marker or an arrow (measured with the
    renderer; see :mod:`crankbase.plot_labels`)."""
    from crankbase.plot_labels import Obstacles, place_label, renderer_of

    fig = ax.figure
    renderer_of(fig)
    tr = ax.transData.transform
    px = fig.dpi / 72.0
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    curve = tr(np.column_stack([T, K]))
    obs.set_curve(curve)
    pts = tr(np.column_stack([lt, lk]))
    for p in pts:
        obs.add_marker(p, ms * px + 1)
    o, osh = tr([(0.0, 0.0)])[0], tr([(0.0, -kr)])[0]
    obs.add_marker(o, 5 * px + 1)
    obs.add_marker(osh, 6 * px + 1)
    for idx, _, _ in ext:
        obs.add_segment(osh, curve[idx])
    # the axes T = 0 and K = 0 cross the whole frame: no label on them
    obs.add_line([(bb.x0, o[1]), (bb.x1, o[1])])
    obs.add_line([(o[0], bb.y0), (o[0], bb.y1)])
    # pole names first, then Rшш max/min, then α labels (multiples of 90° first)
    place_label(ax, obs, o, "O", normal=(-1, -1), fontsize=11, weight="bold",
                gid="polar-label")
    if pole_name:
        place_label(ax, obs, osh, pole_name, normal=(-1, 0), fontsize=11, weight="bold",
                    color="C3", gid="polar-label")
    for idx, name, col in ext:
        pos = curve[idx] if name == "max" else osh
        away = curve[idx] - osh
        place_label(ax, obs, pos, f"{r_name} {name} = {R[idx]:.2f} {unit}\n"
                    f"(α = {a[idx]:g}°)", normal=away if name == "max" else (1, 0),
                    fontsize=9, color=col, gid="polar-label", curve_weight=25.0,
                    gaps_pt=(4, 8, 14, 22, 32, 46, 64))      # off the curve, even if farther
    _alpha_labels(ax, obs, curve, pts, a, angles)


def _alpha_labels(ax, obs, curve, pts, a, angles):
    """The α labels of a polar diagram: each off the curve along its normal (away from
    the curve's centre), multiples of 90° first; points closer than a label's height share
    one label ("240/600"); a label with no free place is left out."""
    from crankbase.plot_labels import label_points

    px = ax.figure.dpi / 72.0
    d = np.gradient(curve, axis=0)
    tx = np.interp(angles, a, d[:, 0])
    ty = np.interp(angles, a, d[:, 1])
    normals = np.column_stack([-ty, tx])
    centre = curve.mean(axis=0)
    flip = np.sum(normals * (pts - centre), axis=1) < 0
    normals[flip] *= -1
    order = sorted(range(len(angles)), key=lambda i: (angles[i] % 90 != 0, angles[i]))
    texts = [f"{x:g}" for x in angles]
    label_points(ax, obs, pts, texts, normals, order, merge_px=1.4 * 7 * px,
                 fontsize=7, color="0.15", gid="alpha-label")


def label_alpha_points(ax, x, y, a, angles, lx, ly, ms=3.0):
    """Label the α markers (``lx``, ``ly`` at ``angles``) of a curve (``x``, ``y`` over
    ``a``) drawn on ``ax`` with its axes lines x = 0 and y = 0: the limits are frozen and
    every label is placed clear of the curve, the axes lines, the markers and the other
    labels (:func:`_alpha_labels`)."""
    from crankbase.plot_labels import frozen_frame

    fig = ax.figure
    ax.margins(0.07)
    tr, obs = frozen_frame(ax)
    curve = tr(np.column_stack([x, y]))
    obs.set_curve(curve)
    pts = tr(np.column_stack([lx, ly]))
    px = fig.dpi / 72.0
    for p in pts:
        obs.add_marker(p, ms * px + 1)
    o = tr([(0.0, 0.0)])[0]
    obs.add_marker(o, 5 * px + 1)
    x0, y0, x1, y1 = obs.frame
    obs.add_line([(x0, o[1]), (x1, o[1])])            # the axes lines T = 0 and K = 0
    obs.add_line([(o[0], y0), (o[0], y1)])
    _alpha_labels(ax, obs, curve, pts, np.asarray(a, float), np.asarray(angles, float))


def _diagram_points(ax, result, x_of, lang):
    """Mark and name the characteristic points (r, a, c′, c, c″, zд, b′, b″) of the
    indicator diagram on ``ax`` (x of a crank angle by ``x_of``); names placed clear of
    each other and of the markers."""
    from .diagram_points import characteristic_points
    from crankbase.plot_labels import Obstacles, place_label, renderer_of
    from crankbase.texts import texts

    t = texts(lang)
    spec, c = result.spec, result.curves
    a = c["alpha_deg"].to_numpy()
    p = c["p_gas_MPa"].to_numpy()
    pts = characteristic_points(spec, c)
    if not pts:
        return
    r = renderer_of(ax.figure)
    ax.set_xlim(ax.get_xlim())
    ax.set_ylim(ax.get_ylim())
    ax.set_autoscale_on(False)
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    obs.set_curve(ax.transData.transform(ax.get_lines()[0].get_xydata()))
    for text in ax.texts:                       # the TDC/BDC names already there
        e = text.get_window_extent(r)
        obs.boxes.append((e.x0, e.y0, e.x1, e.y1))
    xy = []
    for pt in pts:
        al = pt.alpha_deg % spec.cycle_deg if pt.alpha_deg < spec.cycle_deg else 0.0
        pp = pt.p / 1e6 if pt.p is not None else float(np.interp(al, a, p))
        xy.append((float(x_of(al)), pp, pt.p is not None))
    for x, y, off in xy:
        ax.plot([x], [y], "o", ms=4.5, mfc="white" if off else "k", mec="k",
                gid="diagram-point", zorder=5)
        obs.add_marker(ax.transData.transform((x, y)), 4.5 * ax.figure.dpi / 72 + 1)
    for pt, (x, y, _) in zip(pts, xy):
        place_label(ax, obs, ax.transData.transform((x, y)),
                    t.symbol(pt.name_ru, pt.name_en), normal=(0.6, 1.0),
                    fontsize=9, gid="diagram-label", color="0.1")


def plot_developed(result, ax=None, lang="ru"):
    """Developed diagram Rшш(α) with its cycle mean, max and min marked. Returns the Axes."""
    t = engine_words(lang)
    ax = figure_axes(ax)
    c = result.curves
    a = c["alpha_deg"].to_numpy()
    R = c["R_N"].to_numpy() * 1e-3
    Rs = t["sym"]["R"]
    ax.plot(a, R, label=Rs, **LINE_STYLES[0])
    unit = t["kN"]
    m = result.summary.R_mean_N * 1e-3
    ax.axhline(m, **{**LINE_STYLES[1], "lw": 1.0}, label=f"{Rs}{t['sub']} = {m:.2f} {unit}")
    for idx, col in ((int(np.argmax(R)), "C3"), (int(np.argmin(R)), "C2")):
        ax.plot(a[idx], R[idx], "o", color=col)
        ax.annotate(f"{R[idx]:.2f} {unit} ({a[idx]:g}°)", (a[idx], R[idx]),
                    xytext=(6, 4), textcoords="offset points", fontsize=8, color=col)
    ax.legend(loc="best", fontsize=9)
    _alpha_axis(ax, result.spec, t)
    ax.set_ylim(bottom=0)
    ax.set_ylabel(t["Rk"])
    ax.set_title(f"{t['dev']}: {result.spec.name}")
    return ax


def figures(result, lang="ru"):
    """The report's figures, ``{stem: Figure}`` in :data:`PLOT_NAMES` order: the
    indicator diagram (p–V beside p–α) and one figure per other plot."""
    from matplotlib.figure import Figure

    t = engine_words(lang)
    fig = Figure(figsize=(11, 5))
    fig.subplots_adjust(left=0.065, right=0.98, bottom=0.11, top=0.86, wspace=0.2)
    ax1, ax2 = fig.subplots(1, 2)
    plot_indicator(result, ax1, lang)
    plot_pressure(result, ax2, lang)
    pi = t["pi"]
    fig.suptitle(f"{t['ind']}: {result.spec.name};  {pi} = {result.summary.pi_MPa:.3f} "
                 f"{t['MPa']}")
    out = {"indicator": fig}
    for name, f in zip(PLOT_NAMES[1:], (plot_piston_forces, plot_nkt, plot_torque,
                                        plot_polar, plot_developed)):
        out[name] = f(result, None, lang).figure
    return out

