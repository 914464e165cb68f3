"""Loaded by pytest before ``tests/conftest.py`` (the project's root is pytest's rootdir):
only what has to happen before the test suite's own configuration imports anything.

pytest rewrites the ``assert`` statements of every test module, of ``tests/conftest.py``
and of the pytest plugins' packages (hypothesis is one: ``tests/conftest.py`` imports it)
as it imports them, an AST pass and a compile: ~5 s of CPU in every process that
collects the suite (each xdist worker does), ~0.6 s more for hypothesis in every process
(the xdist controller too).  It keeps the result in ``__pycache__`` (``*-pytest-*.pyc``,
checked against the source's size and time) and reuses it on the next run, unless
bytecode writing is off (``PYTHONDONTWRITEBYTECODE`` set, ``python -B``): then every
run, in every process, rewrites all of it anew.  The test processes write bytecode again
from here on (into the ``__pycache__`` folders ``.gitignore`` leaves out; the modules
pytest imported before this file, its own and its plugins' entry modules, are not
concerned), so a second run collects in ~3 s instead of ~8.  What is rewritten and run is
the same either way.  ``CRANKDYN_TEST_BYTECODE=0`` leaves the interpreter's choice alone.
"""
import os
import sys

if sys.dont_write_bytecode and os.environ.get("CRANKDYN_TEST_BYTECODE", "1") != "0":
    sys.dont_write_bytecode = False
