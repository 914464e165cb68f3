"""The computed side of ``crankdyn check`` for an engine: every column a student's Table 2
may hold (either textbook form, and the force-table columns), at the student's own crank
angles.  Computed by :func:`engine.force_table` and :func:`engine.table2.table2`; the
comparison itself is :mod:`crankbase.checking`.  :func:`spec_check_side` is the side of
any spec file ``crankdyn check`` takes (an engine's or a linkage's, by its tables).
"""
from __future__ import annotations

import numpy as np

__all__ = ["KEY", "known_columns", "computed_rows", "check_side", "spec_check_side"]

#: The row key of an engine table.
KEY = "alpha_deg"


def known_columns():
    """Every column name a student's engine table may use (force table ∪ both forms)."""
    from .forces import COLUMNS
    from .table2 import FORMS, table2_columns

    names = list(COLUMNS)
    for form in FORMS:
        names += [c for c in table2_columns(form) if c not in names]
    return names


def computed_rows(spec, settings, alpha_deg):
    """The computed table at the given crank angles [deg], every :func:`known_columns`
    column, one row per angle in the given order."""
    import pandas as pd

    from .forces import force_table
    from .table2 import FORMS, table2

    a = np.asarray(alpha_deg, float)
    t = force_table(spec, a, settings=settings)
    parts = [t] + [table2(t, spec, settings, form) for form in FORMS]
    out = {}
    for p in parts:
        for c in p.columns:
            out.setdefault(c, p[c].to_numpy())
    return pd.DataFrame(out)[known_columns()]


def check_side(study):
    """The engine's side of :func:`crankbase.checking.check_table` for an
    :class:`~engine.EngineStudy`: Table 2 (either form) and the force table at the
    student's crank angles."""
    from functools import partial

    from crankbase.checking import CheckSide

    return CheckSide(KEY, tuple(known_columns()),
                     partial(computed_rows, study.spec, study.settings), numeric_key=True)


def spec_check_side(spec_path):
    """The computed side of ``crankdyn check SPEC.toml STUDENT``: an engine spec
    (``[engine]``) checks Table 2 (:func:`check_side`), a linkage spec (``[mechanism]``)
    the course tables (:func:`linkage.check.check_side`).

    Parameters
    ----------
    spec_path : str or Path
        The spec file (a pressure file it names is read beside it).

    Returns
    -------
    crankbase.checking.CheckSide

    Raises
    ------
    SpecError
        An unreadable spec, every problem of it, or a spec with neither table.
    """
    from pathlib import Path

    from crankbase.errors import SpecError, Text
    from crankbase.validation import read_toml

    spec_path = Path(spec_path)
    raw, _ = read_toml(spec_path)
    if "engine" in raw:
        from .spec import load

        return check_side(load(spec_path))
    if "mechanism" in raw:
        import linkage
        from linkage.check import check_side as linkage_side

        return linkage_side(linkage.load_spec(spec_path))
    raise SpecError(Text("errors.crankdyn.cli_check.neither_engine_spec",
                         {"spec_path": spec_path}))
