"""Old path of :mod:`engine.plots.drawing` (moved into the engine's sub-packages, issue #19).

``import engine.drawing`` still works: it warns (``DeprecationWarning``) and gives the
very module :mod:`engine.plots.drawing`, so every name and object is the same.  Import the
new path.
"""
import sys
import warnings

from .plots import drawing as _moved

warnings.warn("engine.drawing is deprecated: import engine.plots.drawing instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
