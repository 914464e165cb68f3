"""Planar crank mechanisms: kinematics and kinetostatics by Assur groups.

Public API::

    spec = linkage.load_spec("ratchet.toml")      # or a dict of the same shape
    res = linkage.analyze(spec)                   # res.kinematics, res.forces (DataFrames)

The group routines (driver, RRR and RRP dyads, their kinetostatics) are in
:mod:`linkage.groups`; the mechanisms in :mod:`linkage.mechanisms`.  This package never
imports matplotlib or openpyxl (reports and plots import them when called).
"""
from .analysis import AnalysisResult, SingularPositionWarning, analyze, full_turn
from crankbase.errors import AssemblyError, CrankdynError, Problem, SpecError
from .mechanisms import CrankRocker, CrankSlider
from .spec import MechanismSpec, load_spec

__all__ = ["load_spec", "analyze", "full_turn", "AnalysisResult", "MechanismSpec",
           "CrankRocker", "CrankSlider", "SpecError", "AssemblyError", "CrankdynError",
           "Problem", "SingularPositionWarning"]
