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
from .kinematics import guide_direction
from .symbols import math_symbol, sym

__all__ = ["plot_indicator", "plot_pressure", "plot_piston_forces", "plot_nkt",
           "plot_torque", "plot_polar", "plot_developed", "figures", "PLOT_NAMES", "LANGS",
           "plot_total_torque", "plot_excess_work", "plot_force_locus", "plot_moment_locus",
           "plot_free_forces", "plot_free_moments", "plot_crankshaft", "train_figures",
           "TRAIN_PLOT_NAMES"]

#: File stems of the report's figures, in order.
PLOT_NAMES = ("indicator", "forces_P", "forces_NKT", "torque", "polar_Rshsh",
              "developed_Rshsh")

LANGS = ("ru", "en")

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
        from .spec import EngineSpecError
        raise EngineSpecError(Problem("lang", Text("errors.engine.plots.valid",
                                                   {"lang": lang, "items": ', '.join(LANGS)})))
    from crankbase.plot_texts import plot_words

    return dict(plot_words(lang, "engine"), sym=SYMBOLS[lang])


def _axes(ax, figsize=(10, 5.6), **margins):
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
    ax = _axes(ax, (6, 5))
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
    ax = _axes(ax, (6, 5))
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
    ax = _axes(ax)
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
    ax = _axes(ax)
    y = t["sym"]
    _lines(ax, result.curves, ("N_N", "K_N", "T_N"), (y["N"], y["K"], y["T"]))
    _alpha_axis(ax, result.spec, t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['fNKT']}: {result.spec.name}")
    return ax


def plot_torque(result, ax=None, lang="ru"):
    """Mкр over α with its cycle mean. Returns the Axes."""
    t = engine_words(lang)
    ax = _axes(ax)
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
    ax = _axes(ax, (9, 9.8), left=0.09, right=0.97, bottom=0.12, top=0.95)
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
    the bearing diagrams of :mod:`engine.bearing_plots`): the locus (T, K), +K
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
    renderer; see :mod:`engine.plot_labels`)."""
    from .plot_labels import Obstacles, place_label, renderer_of

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
    from .plot_labels import label_points

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
    from .plot_labels import Obstacles, place_label, renderer_of

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
                    pt.name_ru if lang == "ru" else pt.name_en, normal=(0.6, 1.0),
                    fontsize=9, gid="diagram-label", color="0.1")


def plot_developed(result, ax=None, lang="ru"):
    """Developed diagram Rшш(α) with its cycle mean, max and min marked. Returns the Axes."""
    t = engine_words(lang)
    ax = _axes(ax)
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


# ------------------------------------------------------------------ the whole engine

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
    ax = _axes(ax, (10, 6), bottom=0.2, left=0.09)
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
    ax = _axes(ax)
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
    ax = _axes(ax, (7, 7), left=0.14, bottom=0.09)
    _locus(ax, result, "F", t)
    ax.set_xlabel(t["Fx"])
    ax.set_ylabel(t["Fy"])
    ax.set_title(f"{t['Floc']}: {result.cylinder.spec.name}", fontsize=10)
    return ax


def plot_moment_locus(result, ax=None, lang="ru"):
    """Locus of the free moment vector over one revolution, before and after the
    counterweights. Returns the Axes."""
    t = _ttexts(lang)
    ax = _axes(ax, (7, 7), left=0.14, bottom=0.09)
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
    ax = _axes(ax, (10, 6), bottom=0.2, left=0.1)
    _over_alpha(ax, result, "F", t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['Fa']}: {result.cylinder.spec.name}")
    return ax


def plot_free_moments(result, ax=None, lang="ru"):
    """Free moment components over one revolution, before and after the counterweights.
    Returns the Axes."""
    t = _ttexts(lang)
    ax = _axes(ax, (10, 6), bottom=0.2, left=0.1)
    _over_alpha(ax, result, "M", t)
    ax.set_ylabel(t["moment"])
    ax.set_title(f"{t['Ma']}: {result.cylinder.spec.name}")
    return ax


def plot_crankshaft(result, ax=None, lang="ru"):
    """The crankshaft seen from the flywheel end at θ = 0: the bank axes, each throw with
    its cylinders, the rotation and the firing order. Returns the Axes."""
    t = _ttexts(lang)
    ax = _axes(ax, (7.5, 8))
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
    from .plot_labels import Obstacles, place_label, renderer_of

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
