"""The force diagrams at the scale of the student's drawing (millimetre paper).

A student transfers Table 2 onto millimetre paper: forces at μP [N/mm] (``table.
force_scale_N_per_mm``), crank angles at μα [°/mm].  These figures are drawn 1:1 in
millimetres of that drawing — each on a sheet of a ГОСТ 2.301 format (A4 … A1, the
smallest that holds it) with the frame and title block of the plans sheet, the axes
labelled in mm, with a millimetre grid in neutral greys under the curves (1 mm, 5 mm and
10 mm lines) — so a PDF printed at 100 % is the student's sheet, and the scales are stated
in the title.  They only
consume a computed force table; nothing is computed here but the division by the scales.
matplotlib object-oriented API.
"""
from __future__ import annotations

import numpy as np

from ..symbols import sym

__all__ = ["DRAWING_NAMES", "default_mu_alpha", "plot_drawing_forces",
           "plot_drawing_polar", "drawing_figures"]

#: File stems of the drawing-scale diagrams.
DRAWING_NAMES = ("drawing_forces_P", "drawing_forces_NKT", "drawing_polar")

#: Length of the α axis of the drawing [mm] that sets the default μα.
ALPHA_AXIS_MM = 240.0
_MARGIN_MM = (22.0, 8.0, 14.0, 16.0)       # left, right, bottom, top


def default_mu_alpha(spec):
    """μα [°/mm] that puts the whole cycle on :data:`ALPHA_AXIS_MM` (3 °/mm for 720°)."""
    return spec.cycle_deg / ALPHA_AXIS_MM


def _paper(width_mm, height_mm, spec, lang):
    """A sheet of a ГОСТ 2.301 format (A4 … A1, either orientation, the smallest that
    holds it) with its frame and title block (:func:`plans.drawing.frame_items`, the
    plans sheet's), and an axes of ``width_mm`` × ``height_mm`` above the title block
    whose data units are millimetres of the drawing (1 data unit = 1 mm of paper).
    The figure is exactly the sheet's size, so the PDF prints at 100 %."""
    from matplotlib.figure import Figure

    from plans.drawing import TITLE_KEYS, fit_format, frame_items, render_items

    left, right, bottom, top = _MARGIN_MM
    name, W, H = fit_format(width_mm + left + right, height_mm + bottom + top)
    fig = Figure(figsize=(W / 25.4, H / 25.4))
    # the drawing in the middle of the field above the title block (the first axes)
    x_free = W - 20.0 - 5.0
    y_free = H - 10.0 - 55.0
    x0 = 20.0 + (x_free - (width_mm + left + right)) / 2 + left
    y0 = 5.0 + 55.0 + (y_free - (height_mm + bottom + top)) / 2 + bottom
    ax = fig.add_axes([x0 / W, y0 / H, width_mm / W, height_mm / H])
    sheet = fig.add_axes((0, 0, 1, 1), zorder=-1)       # frame and title block, beneath
    sheet.set_xlim(0, W)
    sheet.set_ylim(0, H)
    sheet.set_axis_off()
    fields = {k: "" for k in TITLE_KEYS}
    fields.update(title=spec.name, scale="1:1")
    render_items(sheet, frame_items(W, H, fields, 1, 1, lang))
    fig.format_name = name
    return fig, ax


def _words(lang):
    """The words of the drawings in ``lang`` (``plot.drawing.*``)."""
    from crankbase.plot_texts import plot_words

    return plot_words(lang, "drawing")


def _grid(ax, x0, x1, y0, y1):
    """Millimetre paper: lines every 1 mm (thin), 5 mm and 10 mm (darker)."""
    # neutral greys under the curves (an orange grid hid the orange dashed Pj)
    for step, lw, c in ((1, 0.15, "#e4e4e4"), (5, 0.3, "#c8c8c8"), (10, 0.5, "#a8a8a8")):
        xs = np.arange(np.ceil(x0 / step) * step, x1 + 1e-9, step)
        ys = np.arange(np.ceil(y0 / step) * step, y1 + 1e-9, step)
        ax.vlines(xs, y0, y1, lw=lw, color=c, zorder=0, gid="paper-grid")
        ax.hlines(ys, x0, x1, lw=lw, color=c, zorder=0, gid="paper-grid")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.tick_params(labelsize=6, length=2)


def _extent(values, pad=5.0):
    lo, hi = float(np.min(values)), float(np.max(values))
    return np.floor(min(lo, 0.0) / 10) * 10 - pad, np.ceil(max(hi, 0.0) / 10) * 10 + pad


def plot_drawing_forces(result, lang="ru", cols=("dPg_N", "Pj_N", "P_N"), mu_alpha=None):
    """Forces over α of an :class:`~engine.EngineResult` at the drawing scale:
    x = α/μα [mm], y = F/μP [mm] (μP from its settings).  Returns the Figure."""
    from .cylinder import LINE_STYLES

    table, spec = result.curves, result.spec
    mu_p = result.settings.force_scale
    mu_a = default_mu_alpha(spec) if mu_alpha is None else mu_alpha
    x = table["alpha_deg"].to_numpy() / mu_a
    ys = [table[c].to_numpy() / mu_p for c in cols]
    y0, y1 = _extent(np.concatenate(ys))
    width = spec.cycle_deg / mu_a
    fig, ax = _paper(width + 10, y1 - y0, spec, lang)
    _grid(ax, -5, width + 5, y0, y1)
    names = {"dPg_N": sym("dPg", lang), "Pj_N": "Pj", "P_N": "P", "N_N": "N", "K_N": "K",
             "T_N": "T"}
    for k, (c, y) in enumerate(zip(cols, ys)):
        ax.plot(x, y, label=names.get(c, c), **LINE_STYLES[k])
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xticks(np.arange(0, width + 1e-9, 30.0 / mu_a if mu_a < 2 else 90.0 / mu_a))
    t = _words(lang)
    ax.set_xlabel(f"α / μα, {t['mm']}", fontsize=7)
    ax.set_ylabel(f"F / μP, {t['mm']}", fontsize=7)
    ax.legend(fontsize=7, loc="upper right")
    ax.set_title(f"{spec.name}: μP = {mu_p:g} {t['N_mm']}, μα = {mu_a:g} {t['deg_mm']} "
                 + t["print"], fontsize=8, loc="left")
    return fig


def plot_drawing_polar(result, lang="ru"):
    """The polar diagram of the crank-pin load at the drawing scale: T/μP right, K/μP down
    [mm], poles O and Oш = (0, −Kr.ш/μP).  Returns the Figure."""
    table, spec = result.curves, result.spec
    mu_p = result.settings.force_scale
    T = table["T_N"].to_numpy() / mu_p
    K = table["K_N"].to_numpy() / mu_p
    kr = spec.Kr / mu_p
    x0, x1 = _extent(np.r_[T, 0.0])
    y0, y1 = _extent(np.r_[K, 0.0, -kr])
    fig, ax = _paper(x1 - x0, y1 - y0, spec, lang)
    _grid(ax, x0, x1, y0, y1)
    ax.invert_yaxis()
    ax.plot(T, K, color="#0072B2", lw=1.0)
    ax.axhline(0, color="k", lw=0.6)
    ax.axvline(0, color="k", lw=0.6)
    ax.plot([0], [0], "ks", ms=3)
    ax.plot([0], [-kr], "o", color="#D55E00", ms=3.5)
    ax.annotate("O", (0, 0), xytext=(-8, 3), textcoords="offset points", fontsize=7)
    ax.annotate(sym("pole_R", lang), (0, -kr), xytext=(4, 3), textcoords="offset points",
                fontsize=7, color="#D55E00")
    angles = np.arange(0, spec.cycle_deg, 30.0)
    a = table["alpha_deg"].to_numpy()
    ax.plot(np.interp(angles, a, T), np.interp(angles, a, K), "o", ms=1.8, color="#0072B2")
    t = _words(lang)
    ax.set_xlabel(f"T / μP, {t['mm']}", fontsize=7)
    ax.set_ylabel(f"K / μP, {t['mm']}", fontsize=7)
    ax.set_title(f"{spec.name}: μP = {mu_p:g} {t['N_mm']} " + t["print"], fontsize=8,
                 loc="left")
    return fig


def drawing_figures(result, lang="ru"):
    """Every drawing-scale diagram of an :class:`~engine.EngineResult` as
    ``{stem: Figure}`` (:data:`DRAWING_NAMES`)."""
    return {"drawing_forces_P": plot_drawing_forces(result, lang),
            "drawing_forces_NKT": plot_drawing_forces(result, lang,
                                                      cols=("N_N", "K_N", "T_N")),
            "drawing_polar": plot_drawing_polar(result, lang)}
