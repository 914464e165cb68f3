"""Torsional vibration of the crankshaft (issue #21).

The physics on plain arrays (J, k, c), so that one code serves a crankshaft, a gear train
or a test rig: :mod:`torsion.chain` (natural modes, Holzer tables, damping),
:mod:`torsion.harmonics` (the harmonic series of one cylinder's torque),
:mod:`torsion.response` (critical speeds, forced response), :mod:`torsion.engine_chain`
(the coupling with crankdyn's engine: a throw's inertia, one cylinder's excitation from
the force table, the throws and phases of the layout) and :mod:`torsion.plots`.

The study in two calls (:mod:`torsion.study`, as :mod:`engine.study`):
``run_study(load("spec.toml"))`` builds the chain from the ``[torsion]`` table (and the
engine's crank train) and computes everything into a frozen
:class:`~torsion.study.TorsionReport`; ``write_report(report, out, lang)`` writes its CSVs,
workbook and figures as one unit; ``report.summary_lines(lang)`` is the terminal summary.
Nothing heavy is imported until it is used.
"""
from __future__ import annotations

__all__ = ["load", "run_study", "write_report", "build_chain", "TorsionReport",
           "TorsionStudy", "Chain"]


def __getattr__(name):
    # the study layer on first use: ``import torsion`` loads neither pandas nor the engine
    if name in __all__:
        from . import study

        return getattr(study, name)
    raise AttributeError(f"module 'torsion' has no attribute {name!r}")
