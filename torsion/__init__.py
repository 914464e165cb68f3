"""Torsional vibration of the crankshaft (issue #21): the lumped-mass chain of a crankshaft
(natural frequencies and modes, Holzer's table), the harmonic analysis of a cylinder's
torque, the critical speeds, the forced response of the damped chain and their plots.

The physics works on plain arrays (J [kg·m²], k [N·m/rad], c [N·m·s/rad]) so that the same
code serves a crankshaft, a gear train or a test rig: :mod:`torsion.chain`,
:mod:`torsion.harmonics`, :mod:`torsion.response`; :mod:`torsion.engine_chain` couples it
with crankdyn's engine (the force table, the crank train's throws and phases);
:mod:`torsion.plots` draws the results.  Conventions: ``tools/TORSION_API.md`` and the
module docstrings (masses numbered from the free front end to the load; section i joins
mass i and i + 1).
"""
