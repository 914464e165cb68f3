"""Old path of :mod:`engine.report.summary` (moved into the engine's sub-packages, issue #19).

``import engine.summary`` still works: it warns (``DeprecationWarning``) and gives the
very module :mod:`engine.report.summary`, so every name and object is the same.  Import
the new path.
"""
import sys
import warnings

from .report import summary as _moved

warnings.warn("engine.summary is deprecated: import engine.report.summary instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
