"""Planar crank mechanisms: kinematics and kinetostatics by Assur groups.

Public API::

    spec = linkage.load_spec("ratchet.toml")      # or a dict of the same shape
    res = linkage.analyze(spec)                   # AnalysisResult: .kinematics, .forces
                                                  # (DataFrames), .summary (typed), ...
    linkage.plots.plot_driving_moment(linkage.full_turn(spec), ax=ax)   # draw on an Axes

The group routines (driver, the class II groups RRR, RRP, RPR, PRP, RPP, their
kinetostatics; the one implementation) are in :mod:`linkage.groups`; any planar linkage of
those groups as data (a driver and an ordered list of groups: ``solve``,
``kinetostatics``, the structure formula and Chebyshev's mobility) in :mod:`linkage.chain`; four-bar geometry in :mod:`linkage.fourbar`;
the useful resistance in :mod:`linkage.loads`; the mechanisms in
:mod:`linkage.mechanisms`.  A spec with ``[mechanism] kind = "chain"`` describes any chain
of those groups by named joints and links (:mod:`linkage.chain_spec`); ``analyze`` then
returns a :class:`~linkage.chain_analysis.ChainAnalysis` (:mod:`linkage.chain_analysis`,
tables named after the spec's joints and links; report in :mod:`linkage.chain_report`).  This package never imports matplotlib or openpyxl (reports and
plots import them when called).

The names above are imported when first used (:pep:`562`), not with the package: a module
that needs only the group routines (:mod:`engine` imports :mod:`linkage.groups`) does not
load the analysis, the chain and the spec reader with it.  ``linkage.analyze``,
``from linkage import analyze``, ``from linkage import *`` and ``linkage.chain`` (a
submodule) work as before.
"""
import importlib

from crankbase.errors import AssemblyError, CrankdynError, Problem, SpecError

#: Each public name that lives in a submodule → that submodule (imported on first use).
_LAZY = {"AnalysisResult": "analysis", "AnalysisSummary": "analysis",
         "SingularPositionWarning": "analysis", "analyze": "analysis",
         "full_turn": "analysis", "CrankRocker": "mechanisms", "CrankSlider": "mechanisms",
         "MechanismSpec": "spec", "load_spec": "spec"}

__all__ = ["load_spec", "analyze", "full_turn", "AnalysisResult", "AnalysisSummary",
           "MechanismSpec",
           "CrankRocker", "CrankSlider", "SpecError", "AssemblyError", "CrankdynError",
           "Problem", "SingularPositionWarning"]


def __getattr__(name):
    """A public name of :data:`_LAZY` from its submodule, or a submodule not yet imported
    (``linkage.chain``); bound in the package once found."""
    module = _LAZY.get(name)
    if module is not None:
        value = getattr(importlib.import_module(f".{module}", __name__), name)
    elif name.startswith("__"):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    else:
        try:
            value = importlib.import_module(f".{name}", __name__)
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{name}":
                raise
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))
