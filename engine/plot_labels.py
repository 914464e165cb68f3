"""Collision-free text labels for plots: moved to :mod:`crankbase.plot_labels` (shared by
the engine and the linkage plots); this name stays for the old imports."""
from crankbase.plot_labels import *  # noqa: F401,F403
from crankbase.plot_labels import Obstacles, label_points, place_label, renderer_of, text_size

__all__ = ["Obstacles", "renderer_of", "text_size", "place_label", "label_points"]
