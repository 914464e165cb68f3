"""Plots of the machine dynamics (matplotlib OO API; each draws on a given Axes and returns
it).  They only consume computed results.  ``lang="ru"`` uses the Russian textbook
symbols (Jп, Mд, Mс, ΔT, ω, δ), ``lang="en"`` the English ones set as mathtext (Jred, Md,
Mc, ΔE); the words are the ``plot.dynamics.*`` texts (:mod:`crankbase.plot_texts`)."""
from __future__ import annotations

import numpy as np

__all__ = ["plot_inertia", "plot_moments", "plot_wittenbauer", "plot_omega", "plot_startup",
           "plot_true_forces", "dynamics_figures", "PLOT_NAMES"]

#: Every figure a dynamics run can draw (``startup`` with a motor, ``forces_true_motion``
#: for a linkage or an engine), in order.
PLOT_NAMES = ("inertia", "moments", "wittenbauer", "omega", "startup", "forces_true_motion")



def _words(lang):
    """The words of the dynamics plots in ``lang`` (``plot.dynamics.*``)."""
    from crankbase.plot_texts import plot_words

    from crankbase.texts import OFFERED

    if lang not in OFFERED:
        raise KeyError(lang)
    return plot_words(lang, "dynamics")


def _ax(ax, size=(7, 4)):
    if ax is None:
        from matplotlib.figure import Figure
        ax = Figure(figsize=size, layout="constrained").add_subplot()
    return ax


def _phi(motion):
    t = motion.table
    return t["phi_deg"].to_numpy()


def plot_inertia(motion, ax=None, lang="en"):
    """J_red(φ) (with the flywheel) and dJ_red/dφ on a twin axis."""
    L = _words(lang)
    ax = _ax(ax)
    x = _phi(motion)
    ax.plot(x, motion.table["J_red_kgm2"], "k-", lw=1.5, label=L["J"].split(",")[0].split(" [")[0])
    ax.set_xlabel(L["phi"])
    ax.set_ylabel(L["J"])
    ax2 = ax.twinx()
    ax2.plot(x, motion.table["dJ_red_dphi_kgm2"], color="0.4", ls="--", lw=1.2,
             label=L["dJ"].split(",")[0].split(" [")[0])
    ax2.set_ylabel(L["dJ"])
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, loc="upper right", fontsize=8)
    ax.set_title(L["t_J"])
    ax.grid(True, lw=0.3)
    return ax


def plot_moments(motion, ax=None, lang="en"):
    """The reduced driving and resisting moments over the cycle."""
    L = _words(lang)
    ax = _ax(ax)
    x = _phi(motion)
    ax.plot(x, motion.table["M_drive_Nm"], "k-", lw=1.5, label=L["Md"])
    ax.plot(x, motion.table["M_resist_Nm"], color="0.35", ls=(0, (5, 2)), lw=1.5,
            label=L["Mc"])
    ax.set_xlabel(L["phi"])
    ax.set_ylabel(L["M"])
    ax.legend(loc="best", fontsize=8)
    ax.set_title(L["t_M"])
    ax.grid(True, lw=0.3)
    return ax


def plot_wittenbauer(motion, ax=None, lang="en"):
    """ΔE = ∫(M_d − M_c)dφ against J_red: the energy–inertia curve; the steady motion's
    ω_max and ω_min are the slopes tan ψ = ω²/2 of its two tangents (drawn dashed)."""
    L = _words(lang)
    ax = _ax(ax, (6, 5))
    J = motion.table["J_red_kgm2"].to_numpy()
    W = motion.table["W_J"].to_numpy()
    ax.plot(J, W, "k-", lw=1.4)
    # E0 + W = ½Jω²: the points of equal ω lie on the ray W = ½ω²J − E0 from the pole
    # (0, −E0); the rays of ω_max and ω_min touch the curve (drawn through those points)
    if np.ptp(J) < 1e-9 * max(J.max(), 1e-12):   # constant J: a vertical segment
        lo, hi = J[0] * 0.98, J[0] * 1.02
    else:
        lo, hi = J.min() - 0.05 * np.ptp(J), J.max() + 0.05 * np.ptp(J)
    jj = np.array([lo, hi])
    for w, ls, lab in ((motion.omega_max, (0, (5, 2)), L["wmax"]),
                       (motion.omega_min, (0, (1, 1.5)), L["wmin"])):
        i = int(np.argmin(np.abs(motion.table["omega_rad_s"].to_numpy() - w)))
        ax.plot(jj, W[i] + 0.5 * w * w * (jj - J[i]), color="0.4", ls=ls, lw=1.0, label=lab)
    ax.set_xlim(lo, hi)
    ax.set_xlabel(L["J"])
    ax.set_ylabel(L["dE"])
    pad = 0.1 * max(np.ptp(W), 1e-9)
    ax.set_ylim(W.min() - pad, W.max() + pad)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(L["t_W"])
    ax.grid(True, lw=0.3)
    return ax


def plot_omega(motion, ax=None, lang="en"):
    """ω(φ) with the ω_max, ω_min and ω_m lines and δ in the title."""
    L = _words(lang)
    ax = _ax(ax)
    x = _phi(motion)
    ax.plot(x, motion.table["omega_rad_s"], "k-", lw=1.5, label="ω")
    for v, ls, lab in ((motion.omega_max, (0, (5, 2)), L["wmax"]),
                       (motion.omega_mean, "-.", L["wm"]),
                       (motion.omega_min, (0, (1, 1.5)), L["wmin"])):
        ax.axhline(v, color="0.4", ls=ls, lw=1.0, label=f"{lab} = {v:.4g}")
    ax.set_xlabel(L["phi"])
    ax.set_ylabel(L["w"])
    ax.set_title(f"{L['t_w']}: δ = {motion.delta:.4g}")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=4, fontsize=8,
              frameon=False)
    ax.grid(True, lw=0.3)
    return ax


def plot_startup(startup, motion=None, ax=None, lang="en"):
    """ω(t) from rest, with the steady band ω_min…ω_max."""
    L = _words(lang)
    ax = _ax(ax)
    t = startup.table
    ax.plot(t["t_s"], t["omega_rad_s"], "k-", lw=1.2, label="ω(t)")
    if motion is not None:
        ax.axhspan(motion.omega_min, motion.omega_max, color="0.85", label=L["steady"])
    ax.set_xlabel(L["t"])
    ax.set_ylabel(L["w"])
    ax.set_title(L["t_s"])
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(True, lw=0.3)
    return ax


def plot_true_forces(forces, column="M_drive_Nm", ax=None, lang="en"):
    """A force column of the core under the true motion against constant speed."""
    L = _words(lang)
    ax = _ax(ax)
    x = forces["phi_deg" if "phi_deg" in forces else "alpha_deg"].to_numpy()
    order = np.argsort(np.mod(x, 360.0)) if "phi_deg" in forces else np.arange(len(x))
    xx = (np.mod(x, 360.0) if "phi_deg" in forces else x)[order]
    ax.plot(xx, forces[column].to_numpy()[order], "k-", lw=1.5, label=L["true"])
    ax.plot(xx, forces[f"{column}_const"].to_numpy()[order], color="0.4", ls=(0, (5, 2)),
            lw=1.3, label=L["const"])
    ax.set_xlabel(L["phi"])
    labels = {"M_drive_Nm": (L["Mur"], L["t_F"]), "R12_N": (L["R12"], L["t_R"]),
              "M_Nm": (L["Mkr"], L["t_Mkr"]), "R_N": (L["Rpin"], L["t_Rpin"])}
    if column == forces.attrs.get("crank_bearing"):      # a chain's crank bearing
        column = "R12_N"
    ylab, title = labels.get(column, (column, column))
    ax.set_ylabel(ylab)
    ax.set_title(title)
    ax.legend(loc="best", fontsize=8)
    ax.grid(True, lw=0.3)
    return ax


def dynamics_figures(result: dict, lang="en"):
    """Every figure of a dynamics run: name (one of :data:`PLOT_NAMES`) → Figure
    (``startup`` and ``forces_true_motion`` only when computed)."""
    from matplotlib.figure import Figure

    m = result["motion"]
    figs = {}
    for name, fn in (("inertia", plot_inertia), ("moments", plot_moments),
                     ("wittenbauer", plot_wittenbauer), ("omega", plot_omega)):
        fig = Figure(figsize=(6.5, 5) if name == "wittenbauer" else (7.5, 4.2),
                     layout="constrained")
        fn(m, fig.add_subplot(), lang=lang)
        figs[name] = fig
    if result.get("startup") is not None:
        fig = Figure(figsize=(7.5, 4.2), layout="constrained")
        plot_startup(result["startup"], m, fig.add_subplot(), lang=lang)
        figs["startup"] = fig
    if result.get("forces") is not None:
        fig = Figure(figsize=(7.5, 7.4), layout="constrained")
        ax1, ax2 = fig.subplots(2, 1, sharex=True)
        eng = "alpha_deg" in result["forces"]
        plot_true_forces(result["forces"], "M_Nm" if eng else "M_drive_Nm", ax1, lang=lang)
        bearing = result["forces"].attrs.get("crank_bearing", "R12_N")   # a chain's name
        plot_true_forces(result["forces"], "R_N" if eng else bearing, ax2, lang=lang)
        ax1.set_xlabel("")
        figs["forces_true_motion"] = fig
    return figs
