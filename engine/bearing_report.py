"""Old path of :mod:`engine.report.bearing_sheets` (moved into the engine's sub-packages,
issue #19).

``import engine.bearing_report`` still works: it warns (``DeprecationWarning``) and gives
the very module :mod:`engine.report.bearing_sheets`, so every name and object is the same.
Import the new path.
"""
import sys
import warnings

from .report import bearing_sheets as _moved

warnings.warn("engine.bearing_report is deprecated: import engine.report.bearing_sheets instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
