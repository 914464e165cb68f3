"""Old path of :mod:`engine.bearings.wear` (moved into the engine's sub-packages, issue #19).

``import engine.wear`` still works: it warns (``DeprecationWarning``) and gives the very
module :mod:`engine.bearings.wear`, so every name and object is the same.  Import the new
path.
"""
import sys
import warnings

from .bearings import wear as _moved

warnings.warn("engine.wear is deprecated: import engine.bearings.wear instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
