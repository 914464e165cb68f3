"""Machine dynamics and balancing (theory of machines, the machine-dynamics chapter).

* :mod:`dynamics.rotor` – static and two-plane (dynamic) balancing of a rigid rotor;
* :mod:`dynamics.reduced` – the reduced (equivalent) model at the crank: J_red(φ),
  dJ_red/dφ, the reduced driving and resisting moments; from given reduced quantities, from
  a linkage (the core's velocity ratios and loads), from an engine (gas torque of all
  cylinders) and from a chain of constant ratios;
* :mod:`dynamics.chain_model` – the reduced model of any chain of class II groups
  (:mod:`linkage.chain`: J_red, dJ_red/dφ, M_red from the power of every load, as a
  ``ReducedModel``), its shaking force and moment, the frame's load from the kinetostatics;
* :mod:`dynamics.motion` – the true motion ω(φ) of the steady cycle (energy form), the
  flywheel (classic and exact), a motor characteristic M(ω) integrated in time to the
  periodic state and the start-up; kinetostatics under the true motion;
* :mod:`dynamics.shaking` – shaking force and moment of a mechanism on its frame and
  their balancing by counterweights.

Numpy arrays in, arrays out; SI inside (the rotor works in g·mm and mm, as the textbooks).
This package uses :mod:`linkage` and :mod:`engine`; they never import it.  No matplotlib or
openpyxl at import time (:mod:`dynamics.plots` imports them when called).
"""
from ._base import MotionError
from .chain_model import ChainShaking, chain_shaking
from .motion import (FlywheelResult, Motor, MotionResult, classic_flywheel,
                     engine_true_motion_forces, linkage_forces, motor_startup,
                     motor_steady_motion, size_flywheel, steady_motion, true_motion_forces)
from .reduced import (PiecewiseLinear, ReducedModel, braking_moment, chain_reduce,
                      engine_model, linkage_model, machine_model)
from .rotor import RotorBalance, balance_rotor, load_rotor_spec, rotor_balance
from .shaking import (BalanceResult, balance_crank_slider, balance_fourbar, mechanism_balance,
                      shaking)
from .spec import load_dynamics_spec, run_job

__all__ = ["MotionError", "RotorBalance", "balance_rotor", "load_rotor_spec",
           "rotor_balance", "ReducedModel", "PiecewiseLinear", "machine_model",
           "linkage_model", "engine_model", "chain_reduce", "braking_moment",
           "MotionResult", "FlywheelResult", "Motor", "steady_motion", "size_flywheel",
           "classic_flywheel", "motor_steady_motion", "motor_startup", "linkage_forces",
           "true_motion_forces", "engine_true_motion_forces", "BalanceResult", "shaking", "balance_fourbar",
           "balance_crank_slider", "mechanism_balance", "load_dynamics_spec", "run_job",
           "chain_shaking", "ChainShaking"]
