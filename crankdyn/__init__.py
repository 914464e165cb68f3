"""crankdyn: dynamics of crank mechanisms.

The computational packages are :mod:`linkage` (planar crank-rocker and crank-slider
kinematics and kinetostatics by Assur groups) and :mod:`engine` (the engine crank-slider
force table).  This package holds the command line only (errors, validation, safe output and shipped
files live in :mod:`crankbase`);
it imports nothing heavy at import time.
"""
__version__ = "0.1.0"
