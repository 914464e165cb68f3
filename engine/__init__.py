"""Engine crank-slider dynamics: the force table (Table 2).

``load`` reads and validates an engine spec file into the physics (:class:`EngineSpec`,
inputs only; everything derived is computed) and the report settings
(:class:`TableSettings`); ``analyze`` computes the textbook "Table 2" (ΔPг, Pj, P, β, N, Sш,
K, T, Mкр, Kr.ш, Rшш, Ψ over the crank angle) through the Assur-group routines of
:mod:`linkage` and returns a typed :class:`EngineResult`; ``force_table`` and ``summarize``
are its two steps.  Reports (:mod:`engine.report`, openpyxl) and plots
(:mod:`engine.plots`, matplotlib) are imported only when used.
"""
from .forces import (COLUMNS, analyze, crank_pin_forces, fine_angles, force_table,
                     summarize, table_angles)
from .indicator import CycleSpec, PressureTable, gas_pressure, indicated_mean_pressure
from .kinematics import crank_slider
from .result import EngineResult, EngineSummary, Extreme
from .spec import (EngineSpec, EngineSpecError, EngineStudy, TableSettings, load, load_spec,
                   read_pressure_csv)

__all__ = ["load", "load_spec", "analyze", "force_table", "summarize", "table_angles",
           "fine_angles", "COLUMNS", "EngineSpec", "TableSettings", "EngineStudy",
           "CycleSpec", "PressureTable", "EngineSpecError", "EngineResult", "EngineSummary",
           "Extreme", "gas_pressure", "indicated_mean_pressure", "crank_slider",
           "crank_pin_forces", "read_pressure_csv"]
