"""Plots of a linkage analysis (matplotlib object-oriented API, headless).

Every function takes computed results (an :class:`~linkage.analysis.AnalysisResult` of the
plan of positions and one over a full turn) and returns a :class:`matplotlib.figure.Figure`;
nothing here computes physics.  Curves over the cycle are drawn against the crank rotation
from position 1 (the start of the working stroke) when the mechanism has extreme
positions, with the numbered positions marked on a top axis; otherwise against the
absolute crank angle.
"""
from __future__ import annotations


import numpy as np

from .analysis import build_mechanism

__all__ = ["plan_figure", "velocity_figure", "acceleration_figure", "moment_figure",
           "transmission_figure", "all_figures"]

_GREY = "#9a9a9a"


def _figure(w=8.0, h=5.0):
    from matplotlib.figure import Figure

    return Figure(figsize=(w, h), dpi=120, layout="constrained")


def _cycle_axis(result, full):
    """x values for the full-turn curves and a function that decorates an axis."""
    phi = full.kinematics["phi_deg"].to_numpy()
    s = result.summary
    rot = 1 if result.spec.omega > 0 else -1
    if not s.has_extremes:
        order = np.argsort(phi)
        return phi, order, "crank angle φ [°]", None
    x = np.mod((phi - s.phi_working_start_deg) * rot, 360.0)
    x[-1] = 360.0 if abs(x[-1]) < 1e-9 and len(x) > 1 else x[-1]
    order = np.argsort(x, kind="stable")
    work = s.working_crank_angle_deg
    pos = result.kinematics["position"]
    n = int(pos.max()) if pos.notna().all() and len(pos) else 0

    def decorate(ax):
        ax.axvspan(0, work, color="#fff2cc", alpha=0.6, lw=0, label="working stroke")
        ax.axvline(work, color="k", lw=0.8, ls=":")
        ax.set_xlim(0, 360)
        ax.set_xticks(np.arange(0, 361, 30))
        if n:
            top = ax.secondary_xaxis("top")
            ticks = np.arange(n) * 360.0 / n
            top.set_xticks(ticks, [str(k + 1) for k in range(n)])
            top.set_xlabel("position")
    return x, order, "crank rotation from position 1, φ − φ1 [°]", decorate


def _curves(result, full, series, ylabel, title):
    fig = _figure()
    ax = fig.add_subplot()
    x, order, xlabel, decorate = _cycle_axis(result, full)
    if decorate:
        decorate(ax)
    for col, label, df in series:
        y = df[col].to_numpy()
        ax.plot(x[order], y[order], lw=1.6, label=label)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, lw=0.4, alpha=0.6)
    ax.legend(loc="best", fontsize=8)
    return fig


def velocity_figure(result, full):
    """ω3 and ω4 (or the slider velocity v4 on a second axis) over a full turn."""
    k = full.kinematics
    if result.spec.kind == "crank-rocker":
        return _curves(result, full, [("omega3_rad_s", "ω3 (coupler)", k),
                                      ("omega4_rad_s", "ω4 (rocker)", k)],
                       "angular velocity [rad/s]", f"{result.spec.name}: angular velocities")
    fig = _curves(result, full, [("omega3_rad_s", "ω3 (rod)", k)], "ω3 [rad/s]",
                  f"{result.spec.name}: rod angular velocity and slider velocity")
    _twin(fig, result, full, "v4_m_s", "v4 (slider)", "v4 [m/s]")
    return fig


def acceleration_figure(result, full):
    """ε3 and ε4 (or the slider acceleration a4 on a second axis) over a full turn."""
    k = full.kinematics
    if result.spec.kind == "crank-rocker":
        return _curves(result, full, [("eps3_rad_s2", "ε3 (coupler)", k),
                                      ("eps4_rad_s2", "ε4 (rocker)", k)],
                       "angular acceleration [rad/s²]",
                       f"{result.spec.name}: angular accelerations")
    fig = _curves(result, full, [("eps3_rad_s2", "ε3 (rod)", k)], "ε3 [rad/s²]",
                  f"{result.spec.name}: rod angular acceleration and slider acceleration")
    _twin(fig, result, full, "a4_m_s2", "a4 (slider)", "a4 [m/s²]")
    return fig


def _twin(fig, result, full, col, label, ylabel):
    ax = fig.axes[0]
    x, order, _, _ = _cycle_axis(result, full)
    ax2 = ax.twinx()
    ax2.plot(x[order], full.kinematics[col].to_numpy()[order], color="C1", lw=1.6, label=label)
    ax2.set_ylabel(ylabel)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, loc="best", fontsize=8)


def moment_figure(result, full):
    """The driving (balancing) moment Mур on the crank and the useful resistance."""
    f = full.forces
    series = [("M_drive_Nm", "Mур, driving moment on the crank", f)]
    res = f["M_res_Nm"].to_numpy(float) if result.spec.kind == "crank-rocker" else None
    if res is not None and np.any(np.nan_to_num(res) != 0):   # NaN: left-out singular rows
        series.append(("M_res_Nm", "Mпс, resistance on the rocker", f))
    fig = _curves(result, full, series, "moment [N·m]",
                  f"{result.spec.name}: driving moment Mур (+ ccw)")
    ax = fig.axes[0]
    pts = result.forces
    x = _plan_x(result)
    if x is not None:
        ax.plot(x, pts["M_drive_Nm"].to_numpy(), "o", color="C0", ms=4,
                label="plan positions")
    return fig


def _plan_x(result):
    s = result.summary
    if not s.has_extremes or result.kinematics["position"].isna().any():
        return None
    rot = 1 if result.spec.omega > 0 else -1
    return np.mod((result.kinematics["phi_deg"].to_numpy() - s.phi_working_start_deg) * rot,
                  360.0)


def transmission_figure(result, full):
    """Transmission angle μ over a full turn, with its minimum marked."""
    fig = _curves(result, full, [("mu_deg", "μ", full.kinematics)], "transmission angle μ [°]",
                  f"{result.spec.name}: transmission angle")
    ax = fig.axes[0]
    s = result.summary
    ax.axhline(s.mu_min_deg, color="C3", lw=0.8, ls="--",
               label=f"μmin = {s.mu_min_deg:.2f}°")
    ax.set_ylim(0, 95)
    ax.legend(loc="best", fontsize=8)
    return fig


def plan_figure(result, full):
    """The mechanism drawn at the numbered positions (the textbook plan of positions).

    Position 1 (start of the working stroke) and the other extreme position are drawn
    bold; the paths of B and of the extra coupler points over a full turn are dashed.
    """
    spec = result.spec
    fig = _figure(8.0, 6.5)
    ax = fig.add_subplot()
    k = result.kinematics
    fk = full.kinematics
    mech = build_mechanism(spec)   # pivot positions and guide direction of the model
    zO = mech.pivot
    ax.add_patch(_circle(zO, spec.crank))
    extras = [n for ls in spec.links.values() for n in ls.points]
    for name in ["B"] + extras:
        ax.plot(fk[f"{name}_x_m"], fk[f"{name}_y_m"], "--", lw=0.8,
                color="C2" if name == "B" else "C4",
                label=f"path of {name}")
    if spec.kind == "crank-rocker":
        zC = mech.zC
    else:
        zC = None
        u = mech.u
        s4 = fk["s4_m"].to_numpy()
        lo, hi = np.nanmin(s4) - 0.15 * spec.coupler, np.nanmax(s4) + 0.15 * spec.coupler
        g0 = (lo + 1j * spec.offset) * u
        g1 = (hi + 1j * spec.offset) * u
        ax.plot([g0.real, g1.real], [g0.imag, g1.imag], color="k", lw=1.2, label="guide")
    for i in range(len(k)):
        lw, col = (2.2, "C0") if i == 0 else (0.9, _GREY)
        _draw_links(ax, k, i, zO, zC, lw, col)
        label = k["position"].iat[i]
        label = str(label) if label is not None and not _isna(label) else \
            f"{k['phi_deg'].iat[i]:.0f}°"
        # B's labels: positions where the output moves one way on one side, the
        # return on the other, so the two strokes' labels do not overprint.
        rate = k["omega4_rad_s" if spec.kind == "crank-rocker" else "v4_m_s"].iat[i]
        b_off = (5, 2) if rate >= 0 else (-12, 2)
        for P, off in (("A", (3, 3)), ("B", b_off)):
            x, y = k[f"{P}_x_m"].iat[i], k[f"{P}_y_m"].iat[i]
            ax.annotate(label, (x, y), fontsize=7, color="C0" if i == 0 else "0.3",
                        textcoords="offset points", xytext=off)
    if result.extremes is not None:
        e = result.extremes
        _draw_links(ax, e, 1, zO, zC, 2.0, "C3", ls="--")
        ax.plot([], [], color="C3", ls="--", lw=2.0, label="other extreme position")
    numbered = k["position"].notna().all() and len(k) and result.summary.has_extremes
    ax.plot([], [], color="C0", lw=2.2,
            label="position 1 (working-stroke start)" if numbered
            else f"first crank angle given, φ = {k['phi_deg'].iat[0]:.4g}°")
    for z, name in ((zO, "O"), (zC, "C")):
        if z is None:
            continue
        ax.plot(z.real, z.imag, marker="^", ms=11, color="k", mfc="w", zorder=5)
        ax.annotate(name, (z.real, z.imag), textcoords="offset points", xytext=(-12, -14))
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    turn = "statics" if spec.omega == 0 else "ccw" if spec.omega > 0 else "cw"
    ax.set_title(f"{spec.name}: plan of positions ({spec.kind}, "
                 f"ω = {spec.omega:g} rad/s, {turn})")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.legend(loc="upper left", fontsize=7, framealpha=0.85)
    return fig


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


def all_figures(result, full):
    """Every linkage figure as a dict ``file stem → Figure``.  In statics (ω = 0) the
    velocity curves are identically zero and left out, and so are the accelerations when
    ε = 0 too."""
    spec = result.spec
    figs = {"plan": plan_figure(result, full)}
    if spec.omega != 0:
        figs["velocities"] = velocity_figure(result, full)
    if spec.omega != 0 or spec.epsilon != 0:
        figs["accelerations"] = acceleration_figure(result, full)
    figs["driving_moment"] = moment_figure(result, full)
    figs["transmission_angle"] = transmission_figure(result, full)
    return figs
