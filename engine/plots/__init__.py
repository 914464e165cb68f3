"""The engine's figures: matplotlib object-oriented API only (``Figure``, never ``pyplot``),
headless; matplotlib is imported only when a figure is drawn.  Nothing here computes
physics: every ``plot_*(result, ax=None, lang="ru")`` draws a computed result on the given
Axes (or on a new Figure's one) and returns the Axes.

- :mod:`engine.plots.cylinder`: one cylinder's force table (indicator diagram, forces,
  torque, polar and developed diagram of the crank-pin load); :func:`figures`;
- :mod:`engine.plots.whole`: the whole engine (total torque, excess work, free forces and
  moments, crankshaft scheme); :func:`train_figures`;
- :mod:`engine.plots.bearing`: the bearing loads and wear diagrams; :func:`bearing_figures`;
- :mod:`engine.plots.drawing`: the diagrams at the drawing scale (1:1 PDF);
- :mod:`engine.plots.diagram_points`: the indicator diagram's characteristic points.
"""
from .bearing import (BEARING_PLOT_NAMES, bearing_figures, plot_big_end, plot_developed_loads,
                      plot_journal_polar, plot_journal_torques, plot_piston_pin,
                      plot_pin_polar, plot_rod_model, plot_wear)
from .cylinder import (LANGS, LINE_STYLES, PLOT_NAMES, SYMBOLS, draw_polar, engine_words,
                       figures, label_alpha_points, plot_developed, plot_indicator, plot_nkt,
                       plot_piston_forces, plot_polar, plot_pressure, plot_torque)
from .drawing import DRAWING_NAMES, drawing_figures
from .whole import (TRAIN_PLOT_NAMES, plot_crankshaft, plot_excess_work, plot_force_locus,
                    plot_free_forces, plot_free_moments, plot_moment_locus, plot_total_torque,
                    train_figures)

__all__ = ["plot_indicator", "plot_pressure", "plot_piston_forces", "plot_nkt",
           "plot_torque", "plot_polar", "plot_developed", "figures", "PLOT_NAMES", "LANGS",
           "plot_total_torque", "plot_excess_work", "plot_force_locus", "plot_moment_locus",
           "plot_free_forces", "plot_free_moments", "plot_crankshaft", "train_figures",
           "TRAIN_PLOT_NAMES", "plot_pin_polar", "plot_journal_polar", "plot_developed_loads",
           "plot_wear", "plot_journal_torques", "plot_rod_model", "plot_big_end",
           "plot_piston_pin", "bearing_figures", "BEARING_PLOT_NAMES", "DRAWING_NAMES",
           "drawing_figures", "SYMBOLS", "LINE_STYLES", "engine_words", "draw_polar",
           "label_alpha_points"]
