"""Plots of one cylinder's force table, matplotlib object-oriented API only (``Figure``,
never ``pyplot``), headless.

Every ``plot_*(result, ax=None, lang="ru")`` consumes an :class:`engine.EngineResult`
(:func:`engine.analyze`), draws on the given Axes (or on a new Figure's one) and returns
the Axes, so it works in a notebook; nothing here computes physics.  :func:`figures`
composes the report's figures by file stem (the CLI saves them).
"""
from __future__ import annotations

import numpy as np

from crankbase.errors import Problem

__all__ = ["plot_indicator", "plot_pressure", "plot_piston_forces", "plot_nkt",
           "plot_torque", "plot_polar", "plot_developed", "figures", "PLOT_NAMES", "LANGS"]

#: File stems of the report's figures, in order.
PLOT_NAMES = ("indicator", "forces_P", "forces_NKT", "torque", "polar_Rshsh",
              "developed_Rshsh")

LANGS = ("ru", "en")

#: Symbols of the quantities: the Russian textbook's, and the English textbooks' (no
#: Cyrillic in an English plot).
SYMBOLS = {
    "ru": dict(p="pг", dPg="ΔPг", Pj="Pj", P="P", S="Sш", N="N", K="K", T="T", M="Mкр",
               R="Rшш", Kr="Kr.ш", Osh="Oш", Fx="Fп·x"),
    "en": dict(p="$p_g$", dPg="$F_g$", Pj="$F_j$", P="$F$", S="$S$", N="$N$", K="$K$",
               T="$T$", M="$M$", R="$R_{cp}$", Kr="$K_r$", Osh="$O_r$", Fx="$A_p x$"),
}

_TXT = {
    "ru": dict(alpha="α, ° п.к.в.", p="pг, МПа", V="V, л", Vs="Fп·x, л (от ВМТ)",
               force="Сила, кН", torque="Mкр, Н·м", Rk="Rшш, кН",
               ind="Индикаторная диаграмма", pV="p–V", pa="p–α",
               fP="Силы по оси цилиндра", fNKT="Силы N, K, T",
               tq="Крутящий момент одного цилиндра", polar="Полярная диаграмма нагрузки "
               "на шатунную шейку", dev="Развёрнутая диаграмма нагрузки на шатунную шейку",
               T="T, кН", K="K, кН",
               frame="система координат кривошипа: кривошип вверх от оси вала O, "
                     "вращение по часовой стрелке; +T вправо, +K вниз (к оси вала)",
               tdc="ВМТ", bdc="НМТ", sub=".ср", kN="кН", N="Н", Nm="Н·м", MPa="МПа",
               poles="O – полюс силы Sш (T, K), Oш – полюс силы Rшш"),
    "en": dict(alpha="α, crank deg", p="$p_g$, MPa", V="V, l", Vs="$A_p x$, l (from TDC)",
               force="Force, kN", torque="$M$, N·m", Rk="$R_{cp}$, kN",
               ind="Indicator diagram", pV="p–V", pa="p–α",
               fP="Forces along the cylinder axis", fNKT="Forces N, K, T",
               tq="Torque of one cylinder", polar="Polar diagram of the crank-pin load",
               dev="Developed diagram of the crank-pin load", T="$T$, kN", K="$K$, kN",
               frame="crank-fixed frame: crank up from the shaft axis O, rotation "
                     "clockwise; +T to the right, +K downwards (towards the shaft axis)",
               tdc="TDC", bdc="BDC", sub=" mean", kN="kN", N="N", Nm="N·m", MPa="MPa",
               poles="O – pole of the rod force S (T, K), $O_r$ – pole of the crank-pin "
                     "load $R_{cp}$"),
}


def _texts(lang):
    if lang not in _TXT:
        from .spec import EngineSpecError
        raise EngineSpecError(Problem("lang", f"got {lang!r}; valid: {', '.join(LANGS)}"))
    return dict(_TXT[lang], sym=SYMBOLS[lang])


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
    t = _texts(lang)
    ax = _axes(ax, (6, 5))
    spec, c = result.spec, result.curves
    p = c["p_gas_MPa"].to_numpy()
    sw = spec.area * c["x_mm"].to_numpy()            # swept volume [l] = m² · mm
    if spec.Vc is not None:
        ax.plot(spec.Vc * 1e3 + sw, p, color="C0", lw=1.4)
        ax.set_xlabel(t["V"])
        vc, va = spec.Vc * 1e3, (spec.Vc + spec.Vh) * 1e3
        for v, lab in ((vc, t["tdc"]), (va, t["bdc"])):
            ax.axvline(v, color="0.5", lw=0.7, ls="--")
            ax.annotate(lab, (v, 1.0), xycoords=("data", "axes fraction"),
                        xytext=(2, -12), textcoords="offset points", fontsize=8)
        ax.set_xlim(0, va * 1.05)
    else:
        ax.plot(sw, p, color="C0", lw=1.4)
        ax.set_xlabel(t["Vs"])
    ax.set_ylabel(t["p"])
    ax.set_title(t["pV"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_ylim(bottom=0)
    return ax


def plot_pressure(result, ax=None, lang="ru"):
    """Gas pressure over α with its peak marked. Returns the Axes."""
    t = _texts(lang)
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
    return ax


#: Line styles of the curves drawn together, told apart in black-and-white print.
_STYLES = ("-", "--", "-.")


def _lines(ax, table, cols, labels, scale=1e-3):
    a = table["alpha_deg"].to_numpy()
    for k, (col, lab) in enumerate(zip(cols, labels)):
        ax.plot(a, table[col].to_numpy() * scale, lw=1.4, label=lab, color=f"C{k}",
                ls=_STYLES[k % len(_STYLES)])
    ax.legend(loc="best", fontsize=9)


def plot_piston_forces(result, ax=None, lang="ru"):
    """ΔPг, Pj and P over α. Returns the Axes."""
    t = _texts(lang)
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
    t = _texts(lang)
    ax = _axes(ax)
    y = t["sym"]
    _lines(ax, result.curves, ("N_N", "K_N", "T_N"), (y["N"], y["K"], y["T"]))
    _alpha_axis(ax, result.spec, t)
    ax.set_ylabel(t["force"])
    ax.set_title(f"{t['fNKT']}: {result.spec.name}")
    return ax


def plot_torque(result, ax=None, lang="ru"):
    """Mкр over α with its cycle mean. Returns the Axes."""
    t = _texts(lang)
    ax = _axes(ax)
    c = result.curves
    M = t["sym"]["M"]
    ax.plot(c["alpha_deg"].to_numpy(), c["M_Nm"].to_numpy(), lw=1.4, color="C0", label=M)
    m = result.summary.M_mean_Nm
    ax.axhline(m, color="C3", ls="--", lw=1.0, label=f"{M}{t['sub']} = {m:.1f} {t['Nm']}")
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
    t = _texts(lang)
    ax = _axes(ax, (9, 9.8), left=0.09, right=0.97, bottom=0.12, top=0.95)
    spec, c = result.spec, result.curves
    T = c["T_N"].to_numpy() * 1e-3
    K = c["K_N"].to_numpy() * 1e-3
    kr = spec.Kr * 1e-3
    ax.plot(T, K, color="C0", lw=1.3)
    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_yaxis()
    ax.axhline(0, color="k", lw=0.7)
    ax.axvline(0, color="k", lw=0.7)
    labels = np.arange(0, spec.cycle_deg, 30.0)           # α labels every 30°
    lt, lk = _at(c, "T_N", labels) * 1e-3, _at(c, "K_N", labels) * 1e-3
    ax.plot(lt, lk, "o", ms=3, color="C0")
    for ang, x, y in zip(labels, lt, lk):
        ax.annotate(f"{ang:g}", (x, y), xytext=(3, 3), textcoords="offset points",
                    fontsize=7, color="0.2")
    ax.plot([0], [0], "ks", ms=5)
    ax.annotate("O", (0, 0), xytext=(-12, -10), textcoords="offset points", fontsize=11,
                weight="bold")
    ax.plot([0], [-kr], "o", color="C3", ms=6)
    y = t["sym"]
    ax.annotate(y["Osh"], (0, -kr), xytext=(-22, 6), textcoords="offset points",
                fontsize=11, weight="bold", color="C3")
    R = c["R_N"].to_numpy() * 1e-3
    a = c["alpha_deg"].to_numpy()
    unit = t["kN"]
    for idx, name, col in ((int(np.argmax(R)), f"{y['R']} max", "C3"),
                           (int(np.argmin(R)), f"{y['R']} min", "C2")):
        ax.annotate("", xy=(T[idx], K[idx]), xytext=(0, -kr),
                    arrowprops=dict(arrowstyle="-|>", color=col, lw=1.3))
        at = (T[idx], K[idx]) if name.endswith("max") else (0, -kr)
        ax.annotate(f"{name} = {R[idx]:.2f} {unit}\n(α = {a[idx]:g}°)", at,
                    xytext=(8, -14) if name.endswith("max") else (10, 6),
                    textcoords="offset points", fontsize=9, color=col)
    ax.set_ylabel(t["K"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(f"{t['polar']}: {spec.name}", fontsize=11)
    import textwrap

    # the conventions go under the T axis, outside the diagram (never over the curve)
    note = (textwrap.wrap(f"{y['Kr']} = {spec.Kr:.0f} {t['N']};  {t['poles']}", 80)
            + textwrap.wrap(t["frame"], 80))
    ax.set_xlabel("\n".join([t["T"]] + note), fontsize=8.5, linespacing=1.4)
    return ax


def plot_developed(result, ax=None, lang="ru"):
    """Developed diagram Rшш(α) with its cycle mean, max and min marked. Returns the Axes."""
    t = _texts(lang)
    ax = _axes(ax)
    c = result.curves
    a = c["alpha_deg"].to_numpy()
    R = c["R_N"].to_numpy() * 1e-3
    Rs = t["sym"]["R"]
    ax.plot(a, R, lw=1.4, color="C0", label=Rs)
    unit = t["kN"]
    m = result.summary.R_mean_N * 1e-3
    ax.axhline(m, color="C3", ls="--", lw=1.0, label=f"{Rs}{t['sub']} = {m:.2f} {unit}")
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

    t = _texts(lang)
    fig = Figure(figsize=(11, 5))
    fig.subplots_adjust(left=0.065, right=0.98, bottom=0.11, top=0.86, wspace=0.2)
    ax1, ax2 = fig.subplots(1, 2)
    plot_indicator(result, ax1, lang)
    plot_pressure(result, ax2, lang)
    pi = "pi" if lang == "ru" else "$p_i$"
    fig.suptitle(f"{t['ind']}: {result.spec.name};  {pi} = {result.summary.pi_MPa:.3f} "
                 f"{t['MPa']}")
    out = {"indicator": fig}
    for name, f in zip(PLOT_NAMES[1:], (plot_piston_forces, plot_nkt, plot_torque,
                                        plot_polar, plot_developed)):
        out[name] = f(result, None, lang).figure
    return out
