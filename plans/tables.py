"""Tables of the plans: ``plans.csv``, ``lever.csv``, the student's table and the error
table of a hand-drawn solution ("relative error of the plan method", seed 000, Table 3.3:
δ = (x_exact − x_plan)/x_exact·100 %)."""
from __future__ import annotations

import numpy as np

from .errors import PlanError, Problem, Text
from crankbase.errors import os_reason

__all__ = ["plans_table", "lever_table", "lever_forces_table", "student_table",
           "read_measurements", "error_table"]

PLANS_COLUMNS = ["position", "plan", "segment", "length_mm", "value", "unit", "scale"]


def _pos(pp):
    return pp.position if pp.position is not None else pp.tag


def plans_table(plans):
    """One row per drawn vector: ``position, plan, segment, length_mm, value, unit, scale``
    (``value`` in the unit, ``scale`` in unit per mm; ``length_mm = value/scale``): the
    plans and polygons (the crank's with Fур, segment ``Fb``), then the force arrows of
    the Zhukovsky lever (plan ``lever``, at the lever's force scale; a chain's lever is
    in :func:`lever_forces_table` alone, its plans table as before the lever was
    drawn)."""
    import pandas as pd

    rows = []
    for pp in plans:
        for kind, plan in pp.plans.items():
            for v in plan.vectors:
                rows.append((_pos(pp), kind, v.name, v.length_mm, v.value, v.unit, v.scale))
        if pp.kind == "chain":      # its lever's arrows: <name>_lever_forces.csv only
            continue
        for v in (pp.lever.arrows() if pp.lever is not None else []):
            rows.append((_pos(pp), "lever", v.name, v.length_mm, v.value, v.unit, v.scale))
    return pd.DataFrame(rows, columns=PLANS_COLUMNS)


LEVER_COLUMNS = ["position", "M_lever_Nm", "M_kinetostatic_Nm", "difference_percent",
                 "F_lever_N", "F_kinetostatic_N", "scale_N_per_mm"]


def lever_table(plans):
    """``position, M_lever_Nm, M_kinetostatic_Nm, difference_percent, F_lever_N,
    F_kinetostatic_N, scale_N_per_mm``: the balancing moment Mур and the balancing force
    Fур = Mур/lOA (at a, ⟂ OA; + in the sense of a counter-clockwise Mур) from the lever
    and from the kinetostatics, and the lever's force scale μF."""
    import pandas as pd

    return pd.DataFrame([(_pos(pp), pp.lever.M_lever_Nm, pp.lever.M_kinetostatic_Nm,
                          pp.lever.difference_percent, pp.lever.balancing_force_N,
                          pp.lever.F_kinetostatic_N, pp.lever.scale) for pp in plans],
                        columns=LEVER_COLUMNS)


def lever_forces_table(plans):
    """Every force on the lever: ``position, force, point, F_N, arm_mm, moment_Nmm,
    length_mm, scale``, then the balancing force ``Fb`` at a (arm pa); ``length_mm`` is
    the arrow's length on the drawing, |F|/μF, at the lever's force scale ``scale``
    [N/mm]."""
    import pandas as pd

    rows = []
    for pp in plans:
        L = pp.lever
        arrows = {v.name: v for v in L.arrows()}
        for f in L.forces:
            a = arrows[f.name]
            rows.append((_pos(pp), f.name, f.point, abs(f.force), f.arm_mm, f.moment_Nmm,
                         a.length_mm, a.scale))
        mb = -sum(f.moment_Nmm for f in L.forces)      # the balancing force's moment
        fb = abs(L.balancing_force_N)
        a = arrows["Fb"]
        rows.append((_pos(pp), "Fb", "a", fb, mb / fb if fb else 0.0, mb, a.length_mm,
                     a.scale))
    return pd.DataFrame(rows, columns=["position", "force", "point", "F_N", "arm_mm",
                                       "moment_Nmm", "length_mm", "scale"])


def student_table(plans):
    """The table a student fills from the plans: every segment (length in mm, the value it
    stands for) and the angular velocities and accelerations read off them
    (ω = V_rel/l, ε = a^t/l).

    Columns: ``position, plan, segment, label_ru, label_en, quantity, length_mm, scale,
    value, unit``.
    """
    import pandas as pd

    rows = []
    for pp in plans:
        for kind, plan in pp.plans.items():
            for v in plan.vectors:
                rows.append((_pos(pp), kind, v.name, v.label_ru, v.label_en, v.quantity,
                             v.length_mm, v.scale, v.value, v.unit))
        for a in pp.angular:
            q = a["quantity"]                # omega3, eps4 … (a chain's: any link number)
            n = q.lstrip("omegaps").translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
            lab = ("ω" + n, "ω" + n) if q.startswith("omega") else ("ε" + n, "α" + n)
            rows.append((_pos(pp), a["plan"], a["segment"], lab[0], lab[1], a["quantity"],
                         a["length_mm"], a["scale"] / a["link_length_m"], a["value"],
                         a["unit"]))
    return pd.DataFrame(rows, columns=["position", "plan", "segment", "label_ru", "label_en",
                                       "quantity", "length_mm", "scale", "value", "unit"])


def read_measurements(path):
    """A student's measurements: CSV with ``position``, ``segment`` (a segment name such
    as ``pb`` or a quantity such as ``omega4``; with ``plan`` when a name is ambiguous)
    and ``length_mm`` or ``value`` (one of the two per row).

    Raises
    ------
    PlanError
        Missing columns, non-numeric or non-positive numbers; each problem names the file
        and line.
    """
    import pandas as pd

    try:
        df = pd.read_csv(path, comment="#", skipinitialspace=True)
    except (OSError, ValueError) as exc:
        raise PlanError([Problem(str(path), Text(
            "errors.plans.tables.unreadable",
            {"why": os_reason(exc) if isinstance(exc, OSError) else exc}))]) from None
    problems = []
    cols = set(df.columns)
    for c in ("position", "segment"):
        if c not in cols:
            problems.append(f"{path}: column '{c}' is missing; needed: position, segment and "
                            "length_mm or value")
    if not ({"length_mm", "value"} & cols):
        problems.append(f"{path}: needs a 'length_mm' or a 'value' column")
    if problems:
        raise PlanError(problems)
    for k in range(len(df)):
        line = k + 2
        lv = df["length_mm"].iat[k] if "length_mm" in cols else np.nan
        vv = df["value"].iat[k] if "value" in cols else np.nan
        try:
            lv, vv = float(lv), float(vv)
        except (TypeError, ValueError):
            problems.append(f"{path}, line {line}: length_mm/value must be numbers")
            continue
        if np.isnan(lv) == np.isnan(vv):
            problems.append(f"{path}, line {line}: give exactly one of length_mm and value")
        elif (not np.isnan(lv) and not lv >= 0) or (not np.isnan(vv) and not np.isfinite(vv)):
            problems.append(f"{path}, line {line}: got {lv if not np.isnan(lv) else vv!r}; "
                            "lengths must be ≥ 0 and values finite")
    if problems:
        raise PlanError(problems)
    return df


def error_table(student, measured):
    """Error of the plan method per measured segment.

    Parameters
    ----------
    student : DataFrame
        :func:`student_table`.
    measured : DataFrame
        :func:`read_measurements`.

    Returns
    -------
    DataFrame
        ``position, plan, segment, quantity, exact_value, measured_length_mm,
        measured_value, unit, error_percent`` with error_percent =
        (exact − measured)/exact·100 (seed 000, Table 3.3).  A measured length is turned
        into a value with the plan's scale.
    """
    import pandas as pd

    problems = []
    rows = []
    st = student.copy()
    st["_pos"] = st["position"].astype(str)
    for k in range(len(measured)):
        pos = str(measured["position"].iat[k])
        key = str(measured["segment"].iat[k]).strip()
        sel = st[(st["_pos"] == pos) & ((st["segment"] == key) | (st["quantity"] == key))]
        if "plan" in measured.columns and isinstance(measured["plan"].iat[k], str):
            sel = sel[sel["plan"] == measured["plan"].iat[k]]
        if key.startswith(("omega", "eps")):
            sel = sel[sel["quantity"] == key]
        elif len(sel) > 1:
            sel = sel[~sel["quantity"].str.startswith(("omega", "eps"))]
        if len(sel) != 1:
            what = "no" if len(sel) == 0 else "more than one"
            problems.append(f"measurements line {k + 2}: {what} segment '{key}' at position "
                            f"{pos}" + ("; add a 'plan' column" if len(sel) > 1 else ""))
            continue
        r = sel.iloc[0]
        length = (float(measured["length_mm"].iat[k]) if "length_mm" in measured.columns
                  else np.nan)
        if not np.isnan(length):
            value = length * r["scale"]
        else:
            value = float(measured["value"].iat[k])
        exact = r["value"]
        err = 100.0 * (exact - value) / exact if exact != 0 else np.nan
        rows.append((r["position"], r["plan"], r["segment"], r["quantity"], exact, length,
                     value, r["unit"], err))
    if problems:
        raise PlanError(problems)
    return pd.DataFrame(rows, columns=["position", "plan", "segment", "quantity",
                                       "exact_value", "measured_length_mm", "measured_value",
                                       "unit", "error_percent"])
