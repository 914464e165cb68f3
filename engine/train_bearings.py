"""Old path of :mod:`engine.bearings.train` (moved into the engine's sub-packages, issue #19).

``import engine.train_bearings`` still works: it warns (``DeprecationWarning``) and gives
the very module :mod:`engine.bearings.train`, so every name and object is the same.
Import the new path.
"""
import sys
import warnings

from .bearings import train as _moved

warnings.warn("engine.train_bearings is deprecated: import engine.bearings.train instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
