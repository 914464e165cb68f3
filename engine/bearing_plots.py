"""Old path of :mod:`engine.plots.bearing` (moved into the engine's sub-packages, issue #19).

``import engine.bearing_plots`` still works: it warns (``DeprecationWarning``) and gives
the very module :mod:`engine.plots.bearing`, so every name and object is the same.  Import
the new path.
"""
import sys
import warnings

from .plots import bearing as _moved

warnings.warn("engine.bearing_plots is deprecated: import engine.plots.bearing instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
