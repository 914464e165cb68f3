"""Engine crank-slider dynamics: the force table (Table 2).

``load_spec`` reads and validates an engine spec (TOML or dict); ``force_table`` computes
the textbook "Table 2" (ΔPг, Pj, P, β, N, Sш, K, T, Mкр, Kr.ш, Rшш, Ψ over the crank
angle) through the Assur-group routines of :mod:`linkage`; ``summarize`` gives its
extremes and means.  Reports (:mod:`engine.report`, openpyxl) and plots
(:mod:`engine.plots`, matplotlib) are imported only when used.
"""
from .forces import COLUMNS, fine_angles, force_table, summarize, table_angles
from .indicator import gas_pressure, indicated_mean_pressure
from .kinematics import crank_slider
from .spec import EngineSpec, EngineSpecError, load_spec

__all__ = ["load_spec", "force_table", "summarize", "table_angles", "fine_angles", "COLUMNS",
           "EngineSpec", "EngineSpecError", "gas_pressure", "indicated_mean_pressure",
           "crank_slider"]
