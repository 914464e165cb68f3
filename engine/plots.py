"""Plots of the engine force table, matplotlib object-oriented API only (``Figure``, never
``pyplot``), headless.

Every function consumes a computed table (:func:`engine.force_table`, preferably on a fine
grid) and its summary (:func:`engine.summarize`) and returns a ``Figure``; nothing here
computes physics.  :func:`all_figures` gives every plot by file stem; :func:`save_figure`
writes PNG and SVG atomically.
"""
from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from .symbols import sym

__all__ = ["plot_indicator", "plot_piston_forces", "plot_nkt", "plot_torque",
           "plot_polar", "plot_developed", "all_figures", "PLOT_NAMES"]

#: File stems of the plots, in order.
PLOT_NAMES = ("indicator", "forces_P", "forces_NKT", "torque", "polar_Rshsh",
              "developed_Rshsh")

_TXT = {
    "ru": dict(alpha="α, ° п.к.в.", p="pг, МПа", V="V, л", Vs="Fп·x, л (от ВМТ)",
               force="Сила, кН", torque="Mкр, Н·м", Rk="Rшш, кН",
               ind="Индикаторная диаграмма", pV="p–V", pa="p–α",
               fP="Силы по оси цилиндра", fNKT="Силы N, K, T",
               tq="Крутящий момент одного цилиндра", polar="Полярная диаграмма нагрузки "
               "на шатунную шейку", dev="Развёрнутая диаграмма нагрузки на шатунную шейку",
               mean="среднее", T="T, кН", K="K, кН", crank="кривошип",
               frame="система координат кривошипа: кривошип вверх от оси вала O, "
                     "вращение по часовой стрелке; +T вправо, +K вниз (к оси вала)",
               tdc="ВМТ", bdc="НМТ", sub="ср", Kr="Kr.ш", pole_sh="Oш", Rsh="Rшш",
               poles="O – полюс силы Sш (T, K), Oш – полюс силы Rшш"),
    "en": dict(alpha="α, crank deg", p="pg, MPa", V="V, l", Vs="Ap·x, l (from TDC)",
               force="Force, kN", torque="Mt, N·m", Rk="Rpin, kN",
               ind="Indicator diagram", pV="p–V", pa="p–α",
               fP="Forces along the cylinder axis", fNKT="Forces N, K, T",
               tq="Torque of one cylinder", polar="Polar diagram of the crank-pin load",
               dev="Developed diagram of the crank-pin load", mean="mean", T="T, kN",
               K="K, kN", crank="crank",
               frame="crank-fixed frame: crank up from the shaft axis O, rotation "
                     "clockwise; +T to the right, +K downwards (towards the shaft axis)",
               tdc="TDC", bdc="BDC", sub="mean", Kr="Kr,rod", pole_sh="Opin", Rsh="Rpin",
               poles="O – pole of the rod force Srod (T, K), Opin – pole of Rpin"),
}


def _alpha_axis(ax, spec, t):
    cyc = spec.cycle_deg
    ax.set_xlim(0, cyc)
    ax.set_xticks(np.arange(0, cyc + 1, 90 if cyc > 360 else 30))
    ax.set_xlabel(t["alpha"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.axhline(0, color="k", lw=0.7)


def _new(figsize=(10, 5.6), **margins):
    """A figure with fixed margins (a layout engine would double the rendering time)."""
    fig = Figure(figsize=figsize)
    adjust = dict(left=0.08, right=0.975, bottom=0.1, top=0.92)
    adjust.update(margins)
    fig.subplots_adjust(**adjust)
    return fig


def plot_indicator(table, spec, summary=None, lang="ru"):
    """Indicator diagram: p–V (left) and p–α (right) of the table's gas pressure."""
    t = _TXT[lang]
    fig = _new((11, 5), left=0.065, right=0.98, bottom=0.11, top=0.86, wspace=0.2)
    ax1, ax2 = fig.subplots(1, 2)
    p = table["p_gas_MPa"].to_numpy()
    a = table["alpha_deg"].to_numpy()
    sw = spec.area * table["x_mm"].to_numpy() * 1e-3 * 1e3   # swept volume [l]
    if spec.Vc is not None:
        ax1.plot(spec.Vc * 1e3 + sw, p, color="C0", lw=1.4)
        ax1.set_xlabel(t["V"])
        vc, va = spec.Vc * 1e3, (spec.Vc + spec.Vh) * 1e3
        for v, lab in ((vc, t["tdc"]), (va, t["bdc"])):
            ax1.axvline(v, color="0.5", lw=0.7, ls="--")
            ax1.annotate(lab, (v, 1.0), xycoords=("data", "axes fraction"),
                         xytext=(2, -12), textcoords="offset points", fontsize=8)
        ax1.set_xlim(0, va * 1.05)
    else:
        ax1.plot(sw, p, color="C0", lw=1.4)
        ax1.set_xlabel(t["Vs"])
    ax1.set_ylabel(t["p"])
    ax1.set_title(t["pV"])
    ax1.grid(True, lw=0.4, alpha=0.6)
    ax1.set_ylim(bottom=0)
    ax2.plot(a, p, color="C3", lw=1.4)
    _alpha_axis(ax2, spec, t)
    ax2.set_ylabel(t["p"])
    ax2.set_title(t["pa"])
    ax2.set_ylim(bottom=0)
    _diagram_points(ax1, ax2, table, spec, sw, lang)
    title = f"{t['ind']}: {spec.name}"
    if summary is not None:
        title += f";  pi = {summary['pi_MPa']:.3f} " + ("МПа" if lang == "ru" else "MPa")
        from .diagram_points import fullness
        phi = fullness(summary)
        if phi is not None:
            title += f";  {sym('fullness', lang)} = pi/p′i = {phi:.3f}"
    fig.suptitle(title)
    return fig


def _diagram_points(ax1, ax2, table, spec, sw, lang):
    """Mark and name the characteristic points (r, a, c′, c, c″, zд, b′, b″) on the p–V and
    p–α diagrams; names placed clear of each other and of the markers."""
    from .diagram_points import characteristic_points
    from .plot_labels import Obstacles, place_label, renderer_of

    a = table["alpha_deg"].to_numpy()
    p = table["p_gas_MPa"].to_numpy()
    pts = characteristic_points(spec, table)
    if not pts:
        return
    x_of = (lambda al: (spec.Vc * 1e3 if spec.Vc is not None else 0.0)
            + np.interp(al, a, sw))
    r = renderer_of(ax1.figure)
    for ax, xfun in ((ax1, x_of), (ax2, lambda al: np.asarray(al, float))):
        ax.set_xlim(ax.get_xlim())
        ax.set_ylim(ax.get_ylim())
        ax.set_autoscale_on(False)
        bb = ax.get_window_extent()
        obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
        line = ax.get_lines()[0]
        obs.curve = ax.transData.transform(line.get_xydata())
        for text in ax.texts:                       # the TDC/BDC names already there
            e = text.get_window_extent(r)
            obs.boxes.append((e.x0, e.y0, e.x1, e.y1))
        xy = []
        for pt in pts:
            al = pt.alpha_deg % spec.cycle_deg if pt.alpha_deg < spec.cycle_deg else 0.0
            pp = pt.p / 1e6 if pt.p is not None else float(np.interp(al, a, p))
            xy.append((float(xfun(al)), pp, pt.p is not None))
        for x, y, off in xy:
            ax.plot([x], [y], "o", ms=4.5, mfc="white" if off else "k", mec="k",
                    gid="diagram-point", zorder=5)
            obs.add_marker(ax.transData.transform((x, y)), 4.5 * ax.figure.dpi / 72 + 1)
        for pt, (x, y, _) in zip(pts, xy):
            place_label(ax, obs, ax.transData.transform((x, y)),
                        pt.name_ru if lang == "ru" else pt.name_en, normal=(0.6, 1.0),
                        fontsize=9, gid="diagram-label", color="0.1")


#: Line styles of the curves of one plot: colour and dash pattern both differ, so the
#: curves stay apart in black-and-white print (Okabe–Ito colours, distinct greys).
LINE_STYLES = (dict(color="#0072B2", ls="-", lw=1.6), dict(color="#D55E00", ls="--", lw=1.6),
               dict(color="#000000", ls="-.", lw=1.4), dict(color="#009E73", ls=":", lw=1.8))


def _lines(ax, table, cols, labels, scale=1e-3):
    a = table["alpha_deg"].to_numpy()
    for k, (col, lab) in enumerate(zip(cols, labels)):
        ax.plot(a, table[col].to_numpy() * scale, label=lab, **LINE_STYLES[k])
    ax.legend(loc="best", fontsize=9)


def plot_piston_forces(table, spec, summary=None, lang="ru"):
    """ΔPг, Pj and P over α."""
    t = _TXT[lang]
    fig = _new()
    ax = fig.subplots()
    dpg = sym("dPg", lang)
    _lines(ax, table, ("dPg_N", "Pj_N", "P_N"), (dpg, "Pj", f"P = {dpg} + Pj"))
    _alpha_axis(ax, spec, t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['fP']}: {spec.name}")
    return fig


def plot_nkt(table, spec, summary=None, lang="ru"):
    """N, K and T over α."""
    t = _TXT[lang]
    fig = _new()
    ax = fig.subplots()
    _lines(ax, table, ("N_N", "K_N", "T_N"), ("N", "K", "T"))
    _alpha_axis(ax, spec, t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['fNKT']}: {spec.name}")
    return fig


def plot_torque(table, spec, summary=None, lang="ru"):
    """Mкр over α with its cycle mean."""
    t = _TXT[lang]
    fig = _new()
    ax = fig.subplots()
    a = table["alpha_deg"].to_numpy()
    ax.plot(a, table["M_Nm"].to_numpy(), lw=1.4, color="C0", label=sym("M", lang))
    if summary is not None:
        m = summary["M_mean_Nm"]
        ax.axhline(m, color="C3", ls="--", lw=1.0,
                   label=f"{sym('M_mean', lang)} = {_num(m, 1)} "
                   + ("Н·м" if lang == "ru" else "N·m"))
    ax.legend(loc="best", fontsize=9)
    _alpha_axis(ax, spec, t)
    ax.set_ylabel(t["torque"])
    ax.set_title(f"{t['tq']}: {spec.name}")
    return fig


def _at(table, col, angles):
    a = table["alpha_deg"].to_numpy()
    return np.interp(angles, a, table[col].to_numpy())


def plot_polar(table, spec, summary=None, lang="ru"):
    """Polar diagram of the crank-pin load in the crank-fixed frame.

    The curve is the locus of the rod force S = (T, K) with the pole O; the pole shifted
    by Kr.ш, Oш = (0, −Kr.ш), makes the same curve read as Rшш (the vector from Oш to a
    point).  +T to the right, +K downwards (towards the shaft axis), equal aspect, α
    labels every 30°, Rшш max and min marked.
    """
    t = _TXT[lang]
    fig = _new((9, 9.5), left=0.09, right=0.97, bottom=0.08, top=0.93)
    ax = fig.subplots()
    T = table["T_N"].to_numpy() * 1e-3
    K = table["K_N"].to_numpy() * 1e-3
    a = table["alpha_deg"].to_numpy()
    kr = spec.Kr * 1e-3
    ax.plot(T, K, color="C0", lw=1.3)
    ax.axhline(0, color="k", lw=0.7)
    ax.axvline(0, color="k", lw=0.7)
    ax.set_xlabel(t["T"])
    ax.set_ylabel(t["K"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(f"{t['polar']}: {spec.name}\n{t['Kr']} = {_num(spec.Kr, 0)} "
                 + ("Н" if lang == "ru" else "N") + f";  {t['poles']}", fontsize=11)
    fig.text(0.5, 0.012, t["frame"], fontsize=8, color="0.3", ha="center")
    # α markers every 30°, poles, Rшш max/min arrows
    labels = np.arange(0, spec.cycle_deg, 30.0)
    lt, lk = _at(table, "T_N", labels) * 1e-3, _at(table, "K_N", labels) * 1e-3
    ms = 3.5
    ax.plot(lt, lk, "o", ms=ms, color="C0", gid="alpha-marker")
    ax.plot([0], [0], "ks", ms=5, gid="pole-marker")
    ax.plot([0], [-kr], "o", color="C3", ms=6, gid="pole-marker")
    R = table["R_N"].to_numpy() * 1e-3
    unit = "кН" if lang == "ru" else "kN"
    ext = [(int(np.argmax(R)), "max", "C3"), (int(np.argmin(R)), "min", "C2")]
    for idx, _, col in ext:
        ax.annotate("", xy=(T[idx], K[idx]), xytext=(0, -kr),
                    arrowprops=dict(arrowstyle="-|>", color=col, lw=1.3))
    # freeze the limits (equal aspect, room for labels) before measuring anything
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.07)
    ax.autoscale_view()
    ax.invert_yaxis()
    ax.apply_aspect()
    ax.set_xlim(ax.get_xlim())
    ax.set_ylim(ax.get_ylim())
    ax.set_autoscale_on(False)
    _polar_labels(ax, T, K, kr, lt, lk, labels, ext, R, a, t, unit, ms)
    return fig


def _num(x, digits):
    """A number with a true minus sign (U+2212), never "-0"."""
    s = f"{x:.{digits}f}"
    if float(s) == 0:
        s = s.lstrip("-")
    return s.replace("-", "\u2212")


def _polar_labels(ax, T, K, kr, lt, lk, angles, ext, R, a, t, unit, ms):
    """Place the pole names, the Rшш max/min texts and the α labels of the polar diagram
    so that no label covers another label, a marker or an arrow (measured with the
    renderer; see :mod:`engine.plot_labels`)."""
    from .plot_labels import Obstacles, label_points, place_label, renderer_of

    fig = ax.figure
    renderer_of(fig)
    tr = ax.transData.transform
    px = fig.dpi / 72.0
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    curve = tr(np.column_stack([T, K]))
    obs.curve = curve
    pts = tr(np.column_stack([lt, lk]))
    for p in pts:
        obs.add_marker(p, ms * px + 1)
    o, osh = tr([(0.0, 0.0)])[0], tr([(0.0, -kr)])[0]
    obs.add_marker(o, 5 * px + 1)
    obs.add_marker(osh, 6 * px + 1)
    for idx, _, _ in ext:
        obs.add_segment(osh, curve[idx])
    # pole names first, then Rшш max/min, then α labels (multiples of 90° first)
    place_label(ax, obs, o, "O", normal=(-1, -1), fontsize=11, weight="bold",
                gid="polar-label")
    place_label(ax, obs, osh, t["pole_sh"], normal=(-1, 0), fontsize=11, weight="bold",
                color="C3", gid="polar-label")
    for idx, name, col in ext:
        pos = curve[idx] if name == "max" else osh
        away = curve[idx] - osh
        place_label(ax, obs, pos, f"{t['Rsh']} {name} = {R[idx]:.2f} {unit}\n"
                    f"(α = {a[idx]:g}°)", normal=away if name == "max" else (1, 0),
                    fontsize=9, color=col, gid="polar-label", gaps_pt=(4, 8, 14, 22, 32))
    # α labels: normal of the curve at each point, pointing away from the curve's centre
    d = np.gradient(curve, axis=0)
    ang_all = a
    tx = np.interp(angles, ang_all, d[:, 0])
    ty = np.interp(angles, ang_all, d[:, 1])
    normals = np.column_stack([-ty, tx])
    centre = curve.mean(axis=0)
    flip = np.sum(normals * (pts - centre), axis=1) < 0
    normals[flip] *= -1
    order = sorted(range(len(angles)), key=lambda i: (angles[i] % 90 != 0, angles[i]))
    texts = [f"{x:g}" for x in angles]
    label_points(ax, obs, pts, texts, normals, order, merge_px=1.4 * 7 * px,
                 fontsize=7, color="0.15", gid="alpha-label")


def plot_developed(table, spec, summary=None, lang="ru"):
    """Developed diagram Rшш(α) with its cycle mean, max and min marked."""
    t = _TXT[lang]
    fig = _new()
    ax = fig.subplots()
    a = table["alpha_deg"].to_numpy()
    R = table["R_N"].to_numpy() * 1e-3
    ax.plot(a, R, lw=1.4, color="C0", label=sym("R", lang))
    unit = "кН" if lang == "ru" else "kN"
    if summary is not None:
        m = summary["R_mean_N"] * 1e-3
        ax.axhline(m, color="C3", ls="--", lw=1.0, label=f"{sym('R_mean', lang)} = {m:.2f} {unit}")
    for idx, name, col in ((int(np.argmax(R)), "max", "C3"), (int(np.argmin(R)), "min",
                                                               "C2")):
        ax.plot(a[idx], R[idx], "o", color=col)
        ax.annotate(f"{R[idx]:.2f} {unit} ({a[idx]:g}°)", (a[idx], R[idx]),
                    xytext=(6, 4), textcoords="offset points", fontsize=8, color=col)
    ax.legend(loc="best", fontsize=9)
    _alpha_axis(ax, spec, t)
    ax.set_ylim(bottom=0)
    ax.set_ylabel(t["Rk"])
    ax.set_title(f"{t['dev']}: {spec.name}")
    return fig


def all_figures(table, spec, summary=None, lang="ru"):
    """Every plot, as ``{stem: Figure}`` in :data:`PLOT_NAMES` order."""
    funcs = (plot_indicator, plot_piston_forces, plot_nkt, plot_torque, plot_polar,
             plot_developed)
    return {name: f(table, spec, summary, lang) for name, f in zip(PLOT_NAMES, funcs)}
