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
"""
from .analysis import AnalysisResult, AnalysisSummary, SingularPositionWarning, analyze, full_turn
from crankbase.errors import AssemblyError, CrankdynError, Problem, SpecError
from .mechanisms import CrankRocker, CrankSlider
from .spec import MechanismSpec, load_spec

__all__ = ["load_spec", "analyze", "full_turn", "AnalysisResult", "AnalysisSummary",
           "MechanismSpec",
           "CrankRocker", "CrankSlider", "SpecError", "AssemblyError", "CrankdynError",
           "Problem", "SingularPositionWarning"]
