"""Engine crank-slider dynamics: the force table (Table 2).

``load`` reads and validates an engine spec file into the physics (:class:`EngineSpec`,
inputs only; everything derived is computed) and the report settings
(:class:`TableSettings`); ``analyze`` computes the textbook "Table 2" (ΔPг, Pj, P, β, N, Sш,
K, T, Mкр, Kr.ш, Rшш, Ψ over the crank angle) through the Assur-group routines of
:mod:`linkage` and returns a typed :class:`EngineResult`; ``force_table`` and ``summarize``
are its two steps.  Reports (:mod:`engine.report`, openpyxl) and plots
(:mod:`engine.plots`, matplotlib) are imported only when used.

The whole engine (:mod:`engine.train`): ``analyze_engine(spec, train, settings)`` places
every cylinder of the :class:`CrankTrain` (inline, vee, boxer; firing order, throws) and
gives the total torque, its uniformity, the flywheel and the free forces and moments with
their balance, as an :class:`EngineTrainResult`.

The whole study in two calls (:mod:`engine.study`, pvlib's ModelChain pattern):
``run_study(study, bearings=False, step=None, form=None)`` computes one cylinder, the whole
engine, Table 2 and the bearing loads into a frozen :class:`EngineReport` (its ``tables``,
``summary_lines(lang)``); ``write_report(report, out, lang)`` writes the CSVs, the workbook
and the figures as one unit and returns the :class:`ReportFiles` written.
"""
from .forces import (COLUMNS, analyze, crank_pin_forces, crank_pin_resultant, fine_angles,
                     force_table, summarize, table_angles)
from .indicator import CycleSpec, PressureTable, gas_pressure, indicated_mean_pressure
from .kinematics import crank_slider
from .result import EngineResult, EngineSummary, Extreme
from .spec import (Counterweight, CrankTrain, EngineSpec, EngineSpecError, EngineStudy,
                   TableSettings, load, load_spec, read_pressure_csv)
from .study import EngineReport, ReportFiles, run_study, write_report
from .train import (EngineTrainResult, EngineTrainSummary, FlywheelResult, Layout,
                    analyze_engine, layout)

__all__ = ["load", "load_spec", "analyze", "force_table", "summarize", "table_angles",
           "fine_angles", "COLUMNS", "EngineSpec", "TableSettings", "EngineStudy",
           "CycleSpec", "PressureTable", "EngineSpecError", "EngineResult", "EngineSummary",
           "Extreme", "gas_pressure", "indicated_mean_pressure", "crank_slider",
           "crank_pin_forces", "crank_pin_resultant", "read_pressure_csv", "CrankTrain",
           "Counterweight", "Layout", "layout", "analyze_engine", "EngineTrainResult",
           "EngineTrainSummary", "FlywheelResult", "run_study", "write_report",
           "EngineReport", "ReportFiles"]
