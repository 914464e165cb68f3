"""Old path of :mod:`crankbase.plot_labels` (the collision-free text labels, shared by the
engine and the linkage plots).

``import engine.plot_labels`` still works: it warns (``DeprecationWarning``) and gives the
very module :mod:`crankbase.plot_labels`.  Import the new path.
"""
import sys
import warnings

from crankbase import plot_labels as _moved

warnings.warn("engine.plot_labels is deprecated: import crankbase.plot_labels instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = _moved
