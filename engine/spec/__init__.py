"""The engine spec, by job: the data classes (:mod:`.model`), reading a file through the
schema (:mod:`.loading`, keys in :mod:`engine.schema`), the tabulated indicator diagram
(:mod:`.pressure`), the computed one (:mod:`.cycle`) and the bearing inputs
(:mod:`.inputs`).

Every documented name stays importable from here: ``engine.spec.load``,
``engine.spec.load_spec``, :class:`EngineSpec`, :class:`EngineStudy`,
:class:`TableSettings`, :func:`read_pressure_csv` ...
"""
from pathlib import Path  # noqa: F401  (kept: engine.spec.Path was reachable)

from crankbase.errors import Problem, SpecError  # noqa: F401
from crankbase.validation import Checker, read_toml  # noqa: F401

from ..schema import MASS_WAYS, ROUNDING_DEFAULTS, TABLE_FORMS  # noqa: F401
from .inputs import BearingInputs, BearingOptions, RigidRod  # noqa: F401
from .loading import load, load_spec
from .model import (ARRANGEMENTS, COUNTERWEIGHT_DESIGNS, PRESSURE_UNITS,
                    ROD_SMALL_END_FRACTION, Counterweight, CrankTrain, CycleSpec,
                    EngineSpec, EngineSpecError, EngineStudy, PressureTable, TableSettings)
from .pressure import read_pressure_csv
from .torsion_inputs import TorsionInputs

__all__ = ["EngineSpec", "TableSettings", "EngineStudy", "CrankTrain", "Counterweight",
           "ARRANGEMENTS", "COUNTERWEIGHT_DESIGNS", "CycleSpec", "PressureTable",
           "EngineSpecError", "load", "load_spec", "PRESSURE_UNITS", "read_pressure_csv",
           "ROD_SMALL_END_FRACTION", "BearingInputs", "TorsionInputs"]
