"""Old path of :mod:`engine.bearings.analysis` (moved into the engine's sub-packages, issue #19).

``import engine.bearing_spec`` still works: it warns (``DeprecationWarning``) and gives
the very module :mod:`engine.bearings.analysis`, so every name and object is the same.
Import the new path.
"""
import sys
import warnings

from .bearings import analysis as _moved

warnings.warn("engine.bearing_spec is deprecated: import engine.bearings.analysis instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
