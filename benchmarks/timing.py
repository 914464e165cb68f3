"""Timing helpers shared by the benchmark scripts of this folder (``python
benchmarks/bench_*.py``: the script's folder is on ``sys.path``, so ``import timing``).

One definition of: pinning BLAS/OpenMP to one thread (:func:`one_thread`, called before
numpy is imported), the best and median time of repeated calls on the wall clock and on the
process's CPU clock (:func:`timed`), the same for a fresh process such as the CLI
(:func:`timed_process`), the load average (:func:`load_average`) and the processor's name
(:func:`cpu_model`).  The CPU clock (``time.process_time``: user plus system time of this
process) is what the code costs even when other jobs share the cores; the wall clock counts
their time too.  Windows has no load average and no ``resource`` module: there the load
reads "n/a" and a child process's CPU time is not measured (``nan``).
"""
from __future__ import annotations

import math
import os
import platform
import statistics
import subprocess
import time
from dataclasses import dataclass

__all__ = ["Timing", "one_thread", "timed", "timed_process", "load_average", "cpu_model"]

#: The environment variables of the thread pools numpy's BLAS and OpenMP may start.
THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                    "NUMEXPR_NUM_THREADS", "VECLIB_MAXIMUM_THREADS")


@dataclass(frozen=True)
class Timing:
    """Times of one call [s]: the best and the median wall-clock time, and the best CPU
    time (``nan`` where it is not measured)."""

    best: float
    median: float
    cpu: float


def one_thread() -> None:
    """Pin BLAS/OpenMP to one thread (before numpy is imported: the pools read these
    variables when they start)."""
    for name in THREAD_VARIABLES:
        os.environ[name] = "1"


def timed(fn, repeat=5, number=1, warmup=False) -> Timing:
    """Time ``fn()``: ``repeat`` rounds of ``number`` calls each (after one warm-up call
    if ``warmup``); per call, the best and median round on the wall clock and the best
    round on the CPU clock."""
    if warmup:
        fn()
    walls, cpus = [], []
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        for _ in range(number):
            fn()
        walls.append((time.perf_counter() - t0) / number)
        cpus.append((time.process_time() - c0) / number)
    return Timing(min(walls), statistics.median(walls), min(cpus))


def _children_cpu() -> float:
    """User plus system time of the finished child processes [s] (nan without
    ``resource``: Windows)."""
    try:
        import resource
    except ImportError:
        return math.nan
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed_process(cmd, repeat=5) -> Timing:
    """Time a fresh process ``cmd`` (a list, run ``repeat`` times, its output discarded;
    a failing run raises): wall clock and its own CPU time."""
    walls, cpus = [], []
    for _ in range(repeat):
        c0 = _children_cpu()
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        walls.append(time.perf_counter() - t0)
        cpus.append(_children_cpu() - c0)
    return Timing(min(walls), statistics.median(walls), min(cpus))


def load_average() -> str:
    """The 1, 5 and 15 minute load averages, e.g. ``"0.7, 0.6, 1.2"`` (``"n/a"`` where
    the system has none: Windows)."""
    try:
        return ", ".join(f"{x:.1f}" for x in os.getloadavg())
    except (AttributeError, OSError):
        return "n/a"


def cpu_model() -> str:
    """The processor's model name (Linux: /proc/cpuinfo), else ``platform.processor()``."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"
