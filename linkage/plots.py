"""Plots of a linkage analysis (matplotlib object-oriented API, headless).

Compute, then plot (python-control style): every ``plot_*`` helper takes an
:class:`~linkage.analysis.AnalysisResult`, draws on the given Axes (a new figure's when
``ax`` is None) and returns the Axes; nothing here computes physics.

* :func:`plot_plan`: the mechanism at the rows of ``result`` (the plan of positions);
  ``full=`` a full-turn result adds the paths of B and the extra points;
* :func:`plot_velocities`, :func:`plot_accelerations`, :func:`plot_driving_moment`,
  :func:`plot_transmission_angle`: curves over the rows of ``result`` (a full turn,
  :func:`linkage.full_turn`); ``plan=`` the plan-of-positions result marks and numbers
  its positions.

Curves are drawn against the crank rotation from position 1 (the start of the working
stroke) when the mechanism has extreme positions, otherwise against the absolute crank
angle.  ``lang="en"`` labels with the English textbook symbols (no Cyrillic), ``"ru"``
with the Russian ones (Mур, Mпс).  Curves differ by dash pattern and marker, so they can
be told apart in black-and-white print.

Example::

    import linkage
    from linkage.plots import plot_driving_moment
    spec = linkage.load_spec("ratchet.toml")
    res, full = linkage.analyze(spec), linkage.full_turn(spec)
    ax = plot_driving_moment(full, plan=res, lang="en")
    ax.figure.savefig("moment.png")
"""
from __future__ import annotations

import numpy as np

from crankbase.tolerances import SAME_ANGLE_DEG

from . import chain as ch
from .analysis import build_mechanism
from .course import course_of

__all__ = ["plot_plan", "plot_velocities", "plot_accelerations", "plot_driving_moment",
           "plot_transmission_angle", "all_figures", "MAX_PLAN_POSITIONS"]

_GREY = "#9a9a9a"
#: Dash patterns and markers of successive curves (told apart in black-and-white print).
_STYLES = [dict(ls="-", marker=None), dict(ls="--", marker=None), dict(ls="-.", marker=None)]



def _text(lang):
    """The words of these plots in ``lang`` (``plot.linkage.*``)."""
    from crankbase.texts import OFFERED

    if lang not in OFFERED:
        raise ValueError(f"lang: got {lang!r}; one of {', '.join(OFFERED)}")
    from crankbase.plot_texts import plot_words

    return plot_words(lang, "linkage")


def _axes(ax, w=8.0, h=5.0):
    """The given Axes, or the single Axes of a new headless figure."""
    if ax is not None:
        return ax
    from matplotlib.figure import Figure

    return Figure(figsize=(w, h), dpi=120, layout="constrained").add_subplot()


def _cycle_axis(result, plan, t):
    """x values of the rows of ``result``, their order, the x label and a function that
    decorates an axis (working stroke shaded, plan positions numbered on top)."""
    phi = result.kinematics["phi_deg"].to_numpy()
    s = result.summary
    if not s.has_extremes:
        return phi, np.argsort(phi), t["phi"], None
    rot = 1 if result.spec.omega > 0 else -1
    x = np.mod((phi - s.phi_working_start_deg) * rot, 360.0)
    x[-1] = 360.0 if abs(x[-1]) < SAME_ANGLE_DEG and len(x) > 1 else x[-1]
    order = np.argsort(x, kind="stable")
    work = s.working_crank_angle_deg
    n = 0
    if plan is not None:
        pos = plan.kinematics["position"]
        n = int(pos.max()) if len(pos) and pos.notna().all() else 0

    def decorate(ax):
        ax.axvspan(0, work, color="#fff2cc", alpha=0.6, lw=0, label=t["working"])
        ax.axvline(work, color="k", lw=0.8, ls=":")
        ax.set_xlim(0, 360)
        ax.set_xticks(np.arange(0, 361, 30))
        if n:
            top = ax.secondary_xaxis("top")
            top.set_xticks(np.arange(n) * 360.0 / n, [str(k + 1) for k in range(n)])
            top.set_xlabel(t["position"])
    return x, order, t["phi1"], decorate


def _plan_x(plan):
    """x of the plan positions on the cycle axis, or None when they are not numbered."""
    s = plan.summary
    if not s.has_extremes or plan.kinematics["position"].isna().any():
        return None
    rot = 1 if plan.spec.omega > 0 else -1
    return np.mod((plan.kinematics["phi_deg"].to_numpy() - s.phi_working_start_deg) * rot,
                  360.0)


def _curves(ax, result, plan, t, series, ylabel, title):
    x, order, xlabel, decorate = _cycle_axis(result, plan, t)
    if decorate:
        decorate(ax)
    for (col, label, df), style in zip(series, _STYLES):
        ax.plot(x[order], df[col].to_numpy()[order], lw=1.6, color="k" if style["ls"] == "-"
                else "C0", ls=style["ls"], label=label)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(loc="best", fontsize=8)
    return ax


def _twin(ax, result, plan, t, col, label, ylabel):
    """A second y axis with the slider curve (dotted, square markers every 30 rows)."""
    x, order, _, _ = _cycle_axis(result, plan, t)
    ax2 = ax.twinx()
    ax2.plot(x[order], result.kinematics[col].to_numpy()[order], color="C3", lw=1.6, ls=":",
             marker="s", ms=3, markevery=max(1, len(x) // 12), label=label)
    ax2.set_ylabel(ylabel)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, loc="best", fontsize=8)
    return ax


def _rates(result, ax, lang, plan, order):
    """Link 3 and 4 rates of the given ``order`` (1: velocities, 2: accelerations)."""
    t, k, name = _text(lang), result.kinematics, result.spec.name
    ax = _axes(ax)
    w3, s4 = ("omega3_rad_s", "v4") if order == 1 else ("eps3_rad_s2", "a4")
    sym, kind = ("omega", "vel") if order == 1 else ("eps", "acc")
    course = course_of(result.spec)
    col = course.output_columns[order]           # the output's rate or acceleration
    if course.angular:       # a rocker's ω4, ε4 share the coupler's axis and unit
        return _curves(ax, result, plan, t, [(w3, t[f"{sym}3_c"], k), (col, t[f"{sym}4"], k)],
                       t[f"ang_{kind}"], t[f"{kind}_title"].format(name=name))
    # a slider's v4, a4 are linear: a second axis of their own
    _curves(ax, result, plan, t, [(w3, t[f"{sym}3_r"], k)], t["w3" if order == 1 else "e3"],
            t[f"{kind}_title_s"].format(name=name))
    return _twin(ax, result, plan, t, col, t[s4], t[f"{s4}_unit"])


def plot_velocities(result, ax=None, lang="en", *, plan=None):
    """ω3 and ω4 (a crank-slider: ω3 and, on a second axis, the slider velocity v4) over
    the rows of ``result`` (a full turn).  Returns the Axes."""
    return _rates(result, ax, lang, plan, 1)


def plot_accelerations(result, ax=None, lang="en", *, plan=None):
    """ε3 and ε4 (a crank-slider: ε3 and, on a second axis, the slider acceleration a4)
    over the rows of ``result`` (a full turn).  Returns the Axes."""
    return _rates(result, ax, lang, plan, 2)


def plot_driving_moment(result, ax=None, lang="en", *, plan=None):
    """The balancing (driving) moment Mур on the crank over the rows of ``result`` (a full
    turn), with the resistance moment of a crank-rocker and the values at the positions of
    ``plan``.  Returns the Axes."""
    t, f = _text(lang), result.forces
    ax = _axes(ax)
    series = [("M_drive_Nm", t["Md"], f)]
    course = course_of(result.spec)    # a resistance moment shares Mур's axis, a force not
    res = f[course.resistance_column].to_numpy(float) if course.angular else None
    if res is not None and np.any(np.nan_to_num(res) != 0):   # NaN: left-out singular rows
        series.append((course.resistance_column, t["Mr"], f))
    _curves(ax, result, plan, t, series, t["moment"],
            t["Md_title"].format(name=result.spec.name))
    x = _plan_x(plan) if plan is not None else None
    if x is not None:
        ax.plot(x, plan.forces["M_drive_Nm"].to_numpy(), "o", color="k", mfc="w", ms=5,
                label=t["plan_pts"])
        ax.legend(loc="best", fontsize=8)
    return ax


def plot_transmission_angle(result, ax=None, lang="en", *, plan=None):
    """Transmission angle μ over the rows of ``result`` (a full turn), with μmin of the
    summary (closed form over the full turn) marked.  Returns the Axes."""
    t = _text(lang)
    ax = _axes(ax)
    _curves(ax, result, plan, t, [("mu_deg", t["mu"], result.kinematics)], t["mu_axis"],
            t["mu_title"].format(name=result.spec.name))
    v = result.summary.mu_min_deg
    ax.axhline(v, color="k", lw=0.9, ls="--", label=t["mu_min"].format(v=v))
    ax.set_ylim(0, 95)
    ax.legend(loc="best", fontsize=8)
    return ax


#: Most positions the plan of positions draws (rows beyond it are thinned out evenly: a
#: plan of more is unreadable, and each position costs ~7 ms to draw).
MAX_PLAN_POSITIONS = 24


def plot_plan(result, ax=None, lang="en", *, full=None):
    """The mechanism drawn at the rows of ``result`` (the textbook plan of positions).

    Position 1 (start of the working stroke) and the other extreme position are drawn
    bold; with ``full`` (a full-turn result) the paths of B and of the extra points are
    dashed.  At most :data:`MAX_PLAN_POSITIONS` rows are drawn (every n-th, the first
    always; the title says so).  Returns the Axes."""
    t = _text(lang)
    spec = result.spec
    ax = _axes(ax, 8.0, 6.5)
    k = result.kinematics
    mech = build_mechanism(spec)   # pivot positions and guide direction of the model
    zO = mech.pivot
    ax.add_patch(_circle(zO, spec.crank))
    path_df = full.kinematics if full is not None else k
    extras = [n for ls in spec.links.values() for n in ls.points]
    if full is not None:
        for name, ls_ in zip(["B"] + extras, ["--", ":", "-.", (0, (5, 1, 1, 1))] * 4):
            ax.plot(path_df[f"{name}_x_m"], path_df[f"{name}_y_m"], ls=ls_, lw=0.9,
                    color="0.25", label=t["path"].format(p=name))
    zC = ch.from_mechanism(mech).frame.get("C")    # a rocker's pivot on the frame
    if zC is None:                                  # a slider's guide instead
        u = mech.u
        s4 = path_df["s4_m"].to_numpy()
        lo, hi = np.nanmin(s4) - 0.15 * spec.coupler, np.nanmax(s4) + 0.15 * spec.coupler
        g0, g1 = (lo + 1j * spec.offset) * u, (hi + 1j * spec.offset) * u
        ax.plot([g0.real, g1.real], [g0.imag, g1.imag], color="k", lw=1.2, label=t["guide"])
    every = max(1, -(-len(k) // MAX_PLAN_POSITIONS))
    numbers = []                        # (row, its number), labelled once all is drawn
    for i in range(0, len(k), every):
        lw, col = (2.2, "C0") if i == 0 else (0.9, _GREY)
        _draw_links(ax, k, i, zO, zC, lw, col)
        label = k["position"].iat[i]
        label = str(label) if label is not None and not _isna(label) else \
            f"{k['phi_deg'].iat[i]:.0f}°"
        numbers.append((i, label))
    if result.extremes is not None:
        _draw_links(ax, result.extremes, 1, zO, zC, 2.0, "C3", ls="--")
        ax.plot([], [], color="C3", ls="--", lw=2.0, label=t["other"])
    numbered = k["position"].notna().all() and len(k) and result.summary.has_extremes
    ax.plot([], [], color="C0", lw=2.2,
            label=t["pos1"] if numbered else t["first"].format(v=k["phi_deg"].iat[0]))
    pivots = [(z, name) for z, name in ((zO, "O"), (zC, "C")) if z is not None]
    for z, name in pivots:
        ax.plot(z.real, z.imag, marker="^", ms=11, color="k", mfc="w", zorder=5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(t["x"])
    ax.set_ylabel(t["y"])
    turn = t["statics"] if spec.omega == 0 else t["ccw"] if spec.omega > 0 else t["cw"]
    import textwrap

    title = "\n".join(textwrap.wrap(t["plan_title"].format(
        name=spec.name, kind=t["kind"].get(spec.kind, spec.kind), w=spec.omega, turn=turn),
        72))
    if every > 1:
        title += "\n" + t["thinned"].format(k=-(-len(k) // every), n=len(k), every=every)
    ax.set_title(title)
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.legend(loc="upper left", fontsize=7, framealpha=0.85)
    _plan_labels(ax, k, numbers, pivots)
    return ax


def _plan_labels(ax, k, numbers, pivots):
    """The position numbers at A and at B and the pivots' names, each where no link,
    path or other label crosses it; positions whose points (nearly) coincide share one
    label ("12/1"), a label with no free place is left out."""
    from crankbase.plot_labels import fixed_axes_obstacles, label_points, place_label

    fig = ax.figure
    tr, obs = fixed_axes_obstacles(ax)
    for patch in ax.patches:
        obs.add_line(patch.get_transform().transform_path(patch.get_path()).vertices)
    leg = ax.get_legend()
    if leg is not None:
        e = leg.get_window_extent()
        obs.boxes.append((e.x0, e.y0, e.x1, e.y1))
    o = tr([(pivots[0][0].real, pivots[0][0].imag)])[0]
    for z, name in pivots:
        p = tr([(z.real, z.imag)])[0]
        place_label(ax, obs, p, name, normal=(-1, -1), fontsize=9)
    texts = [lab for _, lab in numbers]
    order = list(range(len(numbers)))           # position 1 first
    for P in ("A", "B"):
        pts = tr(np.column_stack([[k[f"{P}_x_m"].iat[i] for i, _ in numbers],
                                  [k[f"{P}_y_m"].iat[i] for i, _ in numbers]]))
        normals = pts - (o if P == "A" else pts.mean(axis=0))
        placed, _ = label_points(ax, obs, pts, texts, normals, order,
                                 merge_px=7 * fig.dpi / 72, fontsize=7, color="0.3")
        for lab in placed:
            if lab.get_text().split("/")[0] == texts[0]:
                lab.set_color("C0")


def _isna(v):
    try:
        import pandas as pd
        return bool(pd.isna(v))
    except (TypeError, ValueError):
        return False


def _circle(z, r):
    from matplotlib.patches import Circle

    return Circle((z.real, z.imag), r, fill=False, ls=":", lw=0.8, color="0.4")


def _draw_links(ax, df, i, zO, zC, lw, color, ls="-"):
    ax_, ay = df["A_x_m"].iat[i], df["A_y_m"].iat[i]
    bx, by = df["B_x_m"].iat[i], df["B_y_m"].iat[i]
    xs = [zO.real, ax_, bx] + ([zC.real] if zC is not None else [])
    ys = [zO.imag, ay, by] + ([zC.imag] if zC is not None else [])
    ax.plot(xs, ys, ls, color=color, lw=lw, marker="o", ms=3 if lw < 2 else 4)


def all_figures(result, full, lang="en"):
    """Every linkage figure as a dict ``file stem → Figure`` (what ``crankdyn linkage``
    writes): ``result`` the plan of positions, ``full`` the same mechanism over a full
    turn.  In statics (ω = 0) the velocity curves are identically zero and left out, and
    so are the accelerations when ε = 0 too."""
    spec = result.spec
    axes = {"plan": plot_plan(result, lang=lang, full=full)}
    if spec.omega != 0:
        axes["velocities"] = plot_velocities(full, lang=lang, plan=result)
    if spec.omega != 0 or spec.epsilon != 0:
        axes["accelerations"] = plot_accelerations(full, lang=lang, plan=result)
    axes["driving_moment"] = plot_driving_moment(full, lang=lang, plan=result)
    axes["transmission_angle"] = plot_transmission_angle(full, lang=lang, plan=result)
    return {stem: ax.figure for stem, ax in axes.items()}
