"""The computed side of ``crankdyn check`` for a linkage: the course tables (positions,
velocities, accelerations, loads, reactions, Mур) by position number, from
:func:`linkage.analyze`; the comparison itself is :mod:`crankbase.checking`.
"""
from __future__ import annotations

import numpy as np

__all__ = ["KEY", "computed_table", "computed_rows", "check_side"]

#: The row key of a linkage table.
KEY = "position"


def computed_table(spec):
    """Kinematics and forces of the spec's positions joined on ``position``."""
    from .analysis import analyze

    res = analyze(spec)
    k, f = res.kinematics, res.forces
    f = f[[c for c in f.columns if c == KEY or c not in k.columns]]
    return k.merge(f, on=KEY, how="left")


def computed_rows(table, positions):
    """Rows of :func:`computed_table` for the student's position numbers, in their order
    (a position the analysis does not have gives a row of NaN)."""
    import pandas as pd

    idx = {int(p): i for i, p in enumerate(table[KEY].tolist())}
    rows = [idx.get(int(p)) if isinstance(p, (int, float)) and np.isfinite(p) else None
            for p in positions]
    num = table.drop(columns=[KEY]).apply(pd.to_numeric, errors="coerce")
    data = np.full((len(rows), num.shape[1]), np.nan)
    for i, r in enumerate(rows):
        if r is not None:
            data[i] = num.iloc[r].to_numpy(float)
    out = pd.DataFrame(data, columns=num.columns)
    out.insert(0, KEY, list(positions))
    return out


def check_side(spec):
    """The linkage's side of :func:`crankbase.checking.check_table` for a linkage spec:
    the course tables by position number."""
    from functools import partial

    from crankbase.checking import CheckSide

    table = computed_table(spec)
    return CheckSide(KEY, tuple(table.columns), partial(computed_rows, table))
