"""Graphical method of the course project: velocity and acceleration plans, force
polygons of the Assur groups and the Zhukovsky lever, from the exact solution of
:func:`linkage.analyze`, at the textbook's scales and with its labels.

:mod:`plans.model` builds the plan objects (segments in millimetres of the drawing);
:mod:`plans.tables` turns them into tables (``plans.csv``, ``lever.csv``, the student's
table and the error table); :mod:`plans.drawing` draws them (matplotlib: SVG/PDF/PNG at
true scale, the A1/A3 sheet) and :mod:`plans.dxf` writes the sheet as DXF (ezdxf).
:mod:`plans.chain_model` builds the plans of a ``kind = "chain"`` spec (any linkage of
class II groups, from its :class:`linkage.chain.ChainResult` and reactions).
Importing this package imports neither matplotlib nor ezdxf.
"""
from .chain_model import build_chain_plans
from .errors import PlanError
from .model import (Lever, LeverForce, Plan, PositionPlans, Vector, balancing_force,
                    build_plans, round_scale)

__all__ = ["build_plans", "build_chain_plans", "round_scale", "balancing_force", "Plan", "Vector", "Lever",
           "LeverForce", "PositionPlans", "PlanError"]
