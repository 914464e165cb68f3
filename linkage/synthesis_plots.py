"""Plots of the ККМ-φ0 synthesis (the paper's Fig. 2 and Fig. 3, and μ over a turn).

Compute first, then plot: every function here only draws arrays computed by
:mod:`linkage.synthesis` (an :class:`~linkage.synthesis.ExistenceRegion`, a
:class:`~linkage.synthesis.MuMinCurves`, a :class:`~linkage.synthesis.Design`, μ(φ)).
matplotlib's object-oriented API only (``Figure``, never ``pyplot``), imported inside
the functions; works headless.  Each ``plot_*`` draws into ``ax`` when given and returns
its figure, else makes a new :class:`~matplotlib.figure.Figure`.
"""
from __future__ import annotations

import numpy as np

__all__ = ["plot_region", "plot_mu_min_curves", "plot_transmission_angle"]


def _axes(ax, size):
    if ax is not None:
        return ax.figure, ax
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.add_subplot()


def plot_region(region, design=None, kolchin_l1=None, family=None, ax=None):
    """The region of existence of the ККМ-φ0 family in the (λ2, λ3) plane (Fig. 2).

    Parameters
    ----------
    region : linkage.synthesis.ExistenceRegion
        The boundary (unit arc abc and curve cda), λ1max, the point d and, for φ0 < 90°,
        the ККМ-5 and ККМ-7 segments.
    design : linkage.synthesis.Design, optional
        The chosen mechanism, marked with its coordinates.
    kolchin_l1 : float, optional
        λ1 of Kolchin's three lines (eq. (1)–(3)); default the chosen mechanism's λ1,
        else λ1max (where line (3) touches the curve at d).
    family : linkage.synthesis.FamilyArc, optional
        The family's admissible arc for the chosen λ1 (drawn dotted).
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = _axes(ax, (6.4, 8.2))
    phi0 = region.phi0_deg
    ax.fill(region.l2, region.l3, color="tab:blue", alpha=0.12, lw=0,
            label=f"region of existence of ККМ-{phi0:g}°")
    ax.plot(region.arc_l2, region.arc_l3, color="k", lw=1.6,
            label="arc abc: unit circle (λ1 = 0)")
    ax.plot(region.curve_l2, region.curve_l3, color="tab:blue", lw=2.0,
            label=f"curve cda: μmin = 0 on {region.kolchin_line}")
    lam = kolchin_l1 if kolchin_l1 is not None else (design.l1 if design is not None
                                                     else region.l1_max)
    hi = max(1.05, float(np.max(region.l2)) * 1.08)
    t = np.array([0.0, hi])
    # Kolchin's lines as λ3 = k·λ2 + b, each with its own dash pattern and legend entry
    lines = (("(1) 1 − λ1 = λ2 − λ3", 1.0, -(1 - lam), (0, (6, 3))),
             ("(2) 1 − λ1 = λ3 − λ2", 1.0, 1 - lam, (0, (2, 2))),
             ("(3) 1 + λ1 = λ2 + λ3", -1.0, 1 + lam, (0, (8, 3, 2, 3))))
    for i, (txt, k, b, dash) in enumerate(lines):
        ax.plot(t, k * t + b, color="0.3", lw=1.0, ls=dash,
                label=f"Kolchin's line {txt}" + (f", λ1 = {lam:.4g}" if i == 0 else ""))
    if family is not None:
        ax.plot(family.l2, family.l3, color="tab:green", lw=1.4, ls=":",
                label=f"family arc for λ1 = {family.l1:.4g} (R = {family.radius:.4f})")
    if region.kkm5_l2 is not None:
        ax.plot(region.kkm5_l2, region.kkm5_l3, color="tab:orange", lw=2.2,
                label=f"ККМ-{phi0:g}° → ККМ-5 (λ3 = sin φ0)")
        ax.plot(region.kkm7_l2, region.kkm7_l3, color="tab:purple", lw=2.2,
                label=f"ККМ-{phi0:g}° → ККМ-7 (λ2 = sin φ0)")
    # the letters of the paper's figure
    mid = len(region.arc_l2) // 2
    marks = {"a": (1.0, 0.0, (6, 4)), "b": (region.arc_l2[mid], region.arc_l3[mid], (5, 5)),
             "c": (0.0, 1.0, (5, 5)), "d": (*region.d, (-14, -12))}
    for name, (x, y, off) in marks.items():
        ax.plot([x], [y], "k.", ms=5)
        ax.annotate(name, (x, y), textcoords="offset points", xytext=off,
                    fontsize=11, fontstyle="italic")
    if design is not None:
        ax.plot([design.l2], [design.l3], "o", color="tab:red", ms=7, zorder=5,
                label=f"chosen: λ1 = {design.l1:.4f}, λ2 = {design.l2:.4f}, "
                      f"λ3 = {design.l3:.4f}")
    ax.set_xlim(0, hi)
    ax.set_ylim(0, hi)
    ax.set_aspect("equal")
    ax.set_xlabel("coupler λ2 = l2/l0  [–]")
    ax.set_ylabel("rocker λ3 = l3/l0  [–]")
    ax.set_title(f"Region of existence of ККМ-{phi0:g}° (μ = 90° at φ0 = {phi0:g}°), "
                 f"λ1max = {region.l1_max:.4f}", fontsize=10)
    ax.grid(True, lw=0.4, alpha=0.5)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.09), fontsize=8, ncols=1,
              frameon=False)
    return fig


def plot_mu_min_curves(curves, design=None, mu_required=None, ax=None):
    """μmin over λ1 at constant λ2 (the paper's Fig. 3).

    Parameters
    ----------
    curves : linkage.synthesis.MuMinCurves
    design : linkage.synthesis.Design, optional
        Marked at (λ1, μmin).
    mu_required : float, optional
        A required minimum, drawn as a horizontal line. [deg]
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = _axes(ax, (9.0, 5.0))
    if mu_required is not None:
        ax.axhline(mu_required, color="tab:red", lw=0.9, ls="--",
                   label=f"required μmin ≥ {mu_required:g}°")
    import matplotlib as mpl

    colors = mpl.colormaps["tab10"].colors
    for i, (l2, mu) in enumerate(zip(curves.l2, curves.mu_min_deg)):
        ax.plot(curves.l1, mu, color=colors[i % 10], lw=1.5, label=f"{i + 1}: λ2 = {l2:.2f}")
    if design is not None:
        ax.plot([design.l1], [design.mu_min_deg], "o", color="tab:red", ms=7, zorder=5,
                label=f"chosen: λ1 = {design.l1:.4f},\nλ2 = {design.l2:.3f}, "
                      f"μmin = {design.mu_min_deg:.2f}°")
    ax.set_xlim(0, float(curves.l1[-1]) * 1.04)
    ax.set_ylim(0, 92)
    ax.set_yticks(np.arange(0, 91, 10))
    ax.set_xlabel("crank λ1 = l1/l0  [–]")
    ax.set_ylabel("minimum transmission angle μmin  [°]")
    ax.set_title(f"ККМ-{curves.phi0_deg:g}°: μmin over λ1 at constant λ2 (eq. 16)",
                 fontsize=10)
    ax.grid(True, lw=0.4, alpha=0.5)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    return fig


def plot_transmission_angle(phi_deg, mu_deg, design, ax=None):
    """μ over a full crank turn of the chosen mechanism (eq. (12)).

    Parameters
    ----------
    phi_deg : array_like
        Crank angles from the line of centres, 0…360. [deg]
    mu_deg : array_like
        Acute transmission angle at those angles. [deg]
    design : linkage.synthesis.Design
        For φ0, μmin and where (marked), and the title.
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, ax = _axes(ax, (7.2, 4.4))
    d = design
    ax.plot(phi_deg, mu_deg, color="tab:blue", lw=1.8, label="μ(φ)")
    ax.axhline(90.0, color="0.5", lw=0.8, ls=":")
    for p in (d.phi0_deg, 360.0 - d.phi0_deg):
        ax.plot([p], [90.0], "o", color="tab:green", ms=6, zorder=5)
    ax.plot([], [], "o", color="tab:green", label=f"μ = 90° at φ = {d.phi0_deg:g}° and "
                                                   f"{360 - d.phi0_deg:g}°")
    ats = [d.mu_min_at_deg] if abs(d.phi0_deg - 90.0) > 1e-9 else [0.0, 180.0, 360.0]
    if d.mu_min_at_deg == 0.0 and 360.0 not in ats:
        ats.append(360.0)
    where = (f"{d.mu_min_at_deg:g}°" if abs(d.phi0_deg - 90.0) > 1e-9
             else "0° and 180°")
    ax.plot(ats, [d.mu_min_deg] * len(ats), "v", color="tab:red", ms=7, zorder=5,
            label=f"μmin = {d.mu_min_deg:.2f}° at φ = {where}")
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.set_ylim(0, 95)
    ax.set_yticks(np.arange(0, 91, 15))
    ax.set_xlabel("crank angle φ from the line of centres  [°]")
    ax.set_ylabel("transmission angle μ  [°]")
    ax.set_title(f"ККМ-{d.phi0_deg:g}°: λ1 = {d.l1:.4f}, λ2 = {d.l2:.4f}, "
                 f"λ3 = {d.l3:.4f}", fontsize=10)
    ax.grid(True, lw=0.4, alpha=0.5)
    ax.legend(loc="lower left", fontsize=8, framealpha=0.92)
    return fig
