"""Old path of :mod:`engine.plots.diagram_points` (moved into the engine's sub-packages, issue #19).

``import engine.diagram_points`` still works: it warns (``DeprecationWarning``) and gives
the very module :mod:`engine.plots.diagram_points`, so every name and object is the same.
Import the new path.
"""
import sys
import warnings

from .plots import diagram_points as _moved

warnings.warn("engine.diagram_points is deprecated: import engine.plots.diagram_points instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
