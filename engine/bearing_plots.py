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

__all__ = ["plot_pin_polar", "plot_journal_polar", "plot_wear", "plot_journal_torques",
           "plot_rod_model", "plot_big_end", "plot_piston_pin", "bearing_figures",
           "BEARING_PLOT_NAMES"]

_TXT = {
    "ru": dict(pin="Полярная диаграмма нагрузки на шатунную шейку {k}",
               journal="Полярная диаграмма нагрузки на коренную шейку {k}",
               frame_j="(система координат кривошипа {k})",
               T="T, кН", K="K, кН", R="R, кН", kN="кН", Nm="Н·м",
               wear="Диаграмма износа: {name}", hole="масляное отверстие",
               wear_note="износ ∝ ∫R dα по дуге ±{h:g}°;\nсистема координат кривошипа: "
                         "0° — {zero}, углы по направлению вращения (по часовой)",
               axis={"pin": "к оси вала O", "journal": "от кривошипа (кривошип — 180°)"},
               tq="Крутящие моменты, передаваемые коренными шейками",
               Mj="Mк.ш {j}", M="Mк.ш, Н·м", alpha="α, ° п.к.в.",
               rod="Жёсткий шатун минус двухмассовая модель",
               dN="ΔT, ΔK, ΔRшш, Н", exact="обе модели с точной кинематикой",
               kgm2="кг·м²", dM="ΔMкр = ΔT·R, Н·м",
               be="Нагрузка на подшипник нижней головки шатуна (система шатуна)",
               along="вдоль шатуна (+ к поршневому пальцу), кН", across="поперёк, кН",
               pp="Нагрузка на поршневой палец", Pp="Pп = ΔPг + Pj.п", N="N",
               Ppm="|Rп.п|", mean="ср", names={"pin": "шатунная шейка",
                                                "journal": "коренная шейка"}),
    "en": dict(pin="Polar diagram of the load on crank pin {k}",
               journal="Polar diagram of the load on main journal {k}",
               frame_j="(crank frame of throw {k})",
               T="T, kN", K="K, kN", R="R, kN", kN="kN", Nm="N·m",
               wear="Wear diagram: {name}", hole="oil hole",
               wear_note="wear ∝ ∫R dα over an arc of ±{h:g}°;\ncrank frame: 0° {zero}, "
                         "angles in the direction of rotation (clockwise)",
               axis={"pin": "towards the shaft axis O",
                     "journal": "away from the crank (the crank at 180°)"},
               tq="Torques carried by the main journals",
               Mj="M journal {j}", M="M, N·m", alpha="α, crank deg",
               rod="Rigid rod minus the two-mass model",
               dN="ΔT, ΔK, ΔR, N", exact="both with exact kinematics",
               kgm2="kg·m²", dM="ΔM = ΔT·R, N·m",
               be="Load on the big-end bearing (rod frame)",
               along="along the rod (+ towards the piston pin), kN", across="across, kN",
               pp="Load on the piston pin", Pp="Pp = ΔPg + Pj,piston", N="N",
               Ppm="|Rpp|", mean="mean", names={"pin": "crank pin",
                                                "journal": "main journal"}),
}

#: Line styles told apart in black-and-white print.
_STYLES = [dict(ls="-", marker=None), dict(ls="--", marker=None), dict(ls="-.", marker=None),
           dict(ls=":", marker=None), dict(ls="-", marker="o", markevery=60, ms=3),
           dict(ls="--", marker="s", markevery=60, ms=3), dict(ls="-.", marker="^",
                                                               markevery=60, ms=3)]


def _axes(ax, size=(8, 8), right=0.96):
    if ax is not None:
        return ax
    from matplotlib.figure import Figure
    fig = Figure(figsize=size)
    fig.subplots_adjust(left=0.1, right=right, bottom=0.09, top=0.9)
    return fig.subplots()


def _xy(phi_deg, r):
    p = np.radians(phi_deg)
    return r * np.sin(p), -r * np.cos(p)


def _polar(ax, a, T, K, title, lang, stats, cycle):
    t = _TXT[lang]
    T, K = np.asarray(T) * 1e-3, np.asarray(K) * 1e-3
    ax.plot(T, K, color="C0", lw=1.3)
    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_yaxis()
    ax.axhline(0, color="k", lw=0.7)
    ax.axvline(0, color="k", lw=0.7)
    labels = np.arange(0.0, cycle, 30.0)
    lt, lk = np.interp(labels, a, T), np.interp(labels, a, K)
    ax.plot(lt, lk, "o", ms=3, color="C0")
    for ang, x, y in zip(labels, lt, lk):
        ax.annotate(f"{ang:g}", (x, y), xytext=(3, 3), textcoords="offset points",
                    fontsize=7, color="0.25")
    R = np.hypot(T, K)
    for idx, name, col in ((int(np.argmax(R)), "max", "C3"), (int(np.argmin(R)), "min",
                                                               "C2")):
        ax.annotate("", xy=(T[idx], K[idx]), xytext=(0, 0),
                    arrowprops=dict(arrowstyle="-|>", color=col, lw=1.2))
        ax.annotate(f"R{name} = {R[idx]:.2f} {t['kN']} (α = {a[idx]:g}°)",
                    (T[idx], K[idx]), xytext=(8, -12 if name == "max" else 8),
                    textcoords="offset points", fontsize=8, color=col)
    ax.plot([0], [0], "ks", ms=4)
    ax.set_xlabel(t["T"])
    ax.set_ylabel(t["K"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(f"{title}\nRmax = {stats.max_N * 1e-3:.2f}, R{t['mean']} = "
                 f"{stats.mean_N * 1e-3:.2f} {t['kN']}, χ = {stats.chi:.2f}", fontsize=10)
    return ax


def plot_pin_polar(result, ax=None, lang="ru", throw=1):
    """Polar diagram of a crank pin's load (rods incl. Kr.ш) in its crank frame, pole at
    the pin centre.  ``result``: :class:`engine.bearings.CrankshaftLoads` or a
    :class:`engine.bearing_spec.BearingAnalysis`."""
    loads = getattr(result, "loads", result)
    ax = _axes(ax)
    p = loads.crankpins
    cyc = _cycle(loads)
    return _polar(ax, p["alpha_deg"].to_numpy(), p[f"T_{throw}_N"], p[f"K_{throw}_N"],
                  _TXT[lang]["pin"].format(k=throw), lang, loads.pin_stats[throw - 1], cyc)


def plot_journal_polar(result, ax=None, lang="ru", journal=1):
    """Polar diagram of a main journal's load Q in the crank frame of its reference
    throw."""
    loads = getattr(result, "loads", result)
    ax = _axes(ax)
    j = loads.journals
    k = loads.shaft.frame_throw()[journal - 1] + 1
    t = _TXT[lang]
    title = t["journal"].format(k=journal) + " " + t["frame_j"].format(k=k)
    return _polar(ax, j["alpha_deg"].to_numpy(), j[f"T_{journal}_N"], j[f"K_{journal}_N"],
                  title, lang, loads.journal_stats[journal - 1], _cycle(loads))


def _cycle(loads):
    a = loads.alpha_deg
    return 720.0 if a[-1] - a[0] > 360.0 + 1e-9 else 360.0


def plot_wear(diagram, ax=None, lang="ru"):
    """Wear diagram on the journal's circle: the wear drawn inwards from the circle
    (depth ∝ wear, the largest at 40 % of the radius), the oil-hole direction marked."""
    t = _TXT[lang]
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
    tx, ty = _xy(hole + 14.0, 1.36)
    ax.annotate(f"{t['hole']}\n{hole:g}°", xy=(hx, hy), xytext=(tx, ty),
                ha="center", va="center", fontsize=9, color="C3",
                arrowprops=dict(arrowstyle="-|>", color="C3", lw=1.4))
    ax.plot([0, 0.62 * hx], [0, 0.62 * hy], color="C3", lw=1.0, ls="--")
    ax.plot([0], [0], "ko", ms=3)
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
    ax.set_title(t["wear"].format(name=f"{t['names'].get(kind, kind)} {num}"), fontsize=11)
    note = t["wear_note"].format(h=diagram.half_angle_deg, zero=t["axis"].get(kind, ""))
    ax.text(0.5, -0.02, note,
            transform=ax.transAxes, ha="center", va="top", fontsize=7.5, color="0.3")
    return ax


def plot_journal_torques(result, ax=None, lang="ru"):
    """Torques carried by the main journals over the crank angle, one line style each."""
    loads = getattr(result, "loads", result)
    t = _TXT[lang]
    ax = _axes(ax, (10, 5.6))
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
    ax.legend(fontsize=8, loc="upper left", ncol=3)
    ax.set_title(t["tq"])
    return ax


def plot_rod_model(comparison, ax=None, lang="ru"):
    """ΔT, ΔK, ΔRшш (rigid − two-mass) over α; the right axis reads ΔT as ΔMкр = ΔT·R."""
    t = _TXT[lang]
    ax = _axes(ax, (10, 5.6), right=0.9)
    df = comparison.table
    a = df["alpha_deg"].to_numpy()
    for col, lab, st in (("dT_N", "ΔT", _STYLES[0]), ("dK_N", "ΔK", _STYLES[1]),
                         ("dR_N", "ΔRшш" if lang == "ru" else "ΔR", _STYLES[2])):
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
    t = _TXT[lang]
    ax = _axes(ax)
    df = result.rod_bearings
    x, y = df["Rbe_across_N"].to_numpy() * 1e-3, df["Rbe_along_N"].to_numpy() * 1e-3
    a = df["alpha_deg"].to_numpy()
    ax.plot(x, y, color="C0", lw=1.2)
    labels = np.arange(0.0, _cycle(result.loads), 30.0)
    lx, ly = np.interp(labels, a, x), np.interp(labels, a, y)
    ax.plot(lx, ly, "o", ms=3, color="C0")
    for ang, u, v in zip(labels, lx, ly):
        ax.annotate(f"{ang:g}", (u, v), xytext=(3, 3), textcoords="offset points",
                    fontsize=7, color="0.25")
    ax.plot([0], [0], "ks", ms=4)
    ax.axhline(0, color="k", lw=0.7)
    ax.axvline(0, color="k", lw=0.7)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(t["across"])
    ax.set_ylabel(t["along"])
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.set_title(t["be"], fontsize=10)
    return ax


def plot_piston_pin(result, ax=None, lang="ru"):
    """Piston-pin load over α: axial Pп, side N and magnitude."""
    t = _TXT[lang]
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
BEARING_PLOT_NAMES = ("polar_pin", "polar_journal_1", "wear_pin", "wear_journal_1",
                      "journal_torques", "big_end", "piston_pin", "rod_model")


def bearing_figures(analysis, lang="ru"):
    """``{stem: Figure}`` of a :class:`engine.bearing_spec.BearingAnalysis`."""
    out = {}

    def fig(stem, func, *args, size=(8, 8), right=0.96):
        ax = _axes(None, size, right)
        func(*args, ax=ax, lang=lang)
        out[stem] = ax.figure

    fig("polar_pin", plot_pin_polar, analysis)
    fig("polar_journal_1", plot_journal_polar, analysis)
    fig("wear_pin", plot_wear, analysis.pin_wear, size=(7, 7.4))
    fig("wear_journal_1", plot_wear, analysis.journal_wear[0], size=(7, 7.4))
    fig("journal_torques", plot_journal_torques, analysis, size=(10, 5.6))
    fig("big_end", plot_big_end, analysis)
    if not analysis.rod_bearings["Pp_N"].isna().all():
        fig("piston_pin", plot_piston_pin, analysis, size=(10, 5.6))
    if analysis.rod_comparison is not None:
        fig("rod_model", plot_rod_model, analysis.rod_comparison, size=(10, 5.6),
            right=0.9)
    return out
