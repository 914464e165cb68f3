"""Bearing loads of the crank mechanism (conventions: :mod:`engine.bearings.loads`):

- :mod:`engine.bearings.loads`: crank pins, main journals (lever rule), journal torques,
  big end and piston pin, load statistics (:func:`crank_pin_load`, :func:`crankshaft_loads`,
  :class:`Crankshaft`, :func:`cylinder_alpha`);
- :mod:`engine.bearings.wear`: wear diagrams by the sector rule;
- :mod:`engine.bearings.analysis`: one cylinder's bearings from the spec's ``[bearings]``
  (:func:`read_bearing_inputs`, :func:`bearing_analysis`);
- :mod:`engine.bearings.train`: the whole engine's bearings (:class:`Cylinder`,
  :func:`engine_bearings`).

Reading a spec imports none of these (their inputs live in :mod:`engine.spec.inputs`).
"""
from .analysis import (BEARING_KEYS, BearingAnalysis, BearingInputs, BearingOptions,
                       bearing_analysis, bearing_options, check_tables, piston_mass,
                       read_bearing_inputs, rod_bearing_table, wear_table)
from .loads import (BearingInputError, Crankshaft, CrankshaftLoads, LoadStats, big_end_load,
                    crank_pin_load, crank_unit, crankshaft_loads, cylinder_alpha,
                    journal_torques, lever_rule, load_stats, piston_pin_load,
                    to_crank_frame, to_engine_frame)
from .train import (Cylinder, EngineBearings, engine_bearings, full_support_journals,
                    layout_cylinders)
from .wear import (DEFAULT_HALF_ANGLE_DEG, WearDiagram, least_wear_direction, wear_diagram,
                   wear_profile)

__all__ = ["crank_unit", "to_engine_frame", "to_crank_frame", "cylinder_alpha",
           "crank_pin_load", "lever_rule", "journal_torques", "big_end_load",
           "piston_pin_load", "load_stats", "LoadStats", "Crankshaft", "CrankshaftLoads",
           "crankshaft_loads", "BearingInputError", "BEARING_KEYS", "BearingOptions",
           "bearing_options", "check_tables", "BearingInputs", "read_bearing_inputs",
           "BearingAnalysis", "bearing_analysis", "wear_table", "rod_bearing_table",
           "piston_mass", "Cylinder", "EngineBearings", "engine_bearings",
           "full_support_journals", "layout_cylinders", "wear_profile",
           "least_wear_direction", "WearDiagram", "wear_diagram", "DEFAULT_HALF_ANGLE_DEG"]
