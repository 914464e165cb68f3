"""The linkage study with the graphical method: one call runs it, another writes it.

:func:`run_study` is :func:`linkage.study.run_study` plus, at chosen positions, the
velocity and acceleration plans, the force polygons and Zhukovsky's lever
(:func:`plans.build_plans`), and a student's measured segments; it returns a
:class:`PlansReport` (a :class:`linkage.study.LinkageReport`), writing nothing.
:func:`linkage.study.write_report` writes it (the linkage's files and the plans', one
report unit) and :func:`linkage.study.summary_lines` is its terminal summary (the plans'
lines from ``crankbase/locale/<lang>/plans.po``).  This module lives in :mod:`plans`
because the graphical method sits above :mod:`linkage` (which never imports it).

Examples
--------
>>> from crankbase.resources import example_path
>>> from plans.study import run_study
>>> report = run_study(example_path("ratchet.toml"), plans=[5, 11], plots=False)
>>> sorted(report.tables())[:3]
['ratchet-drive_forces.csv', 'ratchet-drive_kinematics.csv', 'ratchet-drive_lever.csv']
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from crankbase.errors import Problem, SpecError, Text
from linkage.study import LinkageReport, check_step
from linkage.study import run_study as run_linkage

__all__ = ["PlansReport", "run_study", "SHEETS"]

#: Drawing sheet sizes (landscape).
SHEETS = ("A1", "A3")

#: Scale arguments of :func:`run_study` → the plans they fix (:func:`plans.build_plans`).
_SCALES = (("mu_v", ("velocity",)), ("mu_a", ("acceleration",)),
           ("mu_f", ("force_dyad", "force_crank")), ("mu_lever", ("lever",)))


@dataclass
class PlansReport(LinkageReport):
    """A :class:`linkage.study.LinkageReport` with the graphical method.

    Attributes
    ----------
    plans : list of plans.PositionPlans or None
        The plans at the chosen positions (None: not asked); once written (or summed
        up), as drawn on the sheet: a diagram that does not fit the sheet at its
        default scale at a coarser round one (:func:`plans.drawing.fit_plans`).
    sheet : str
        Drawing sheet size, ``"A1"`` or ``"A3"``.
    measured : pandas.DataFrame or None
        A student's measured segments (:func:`plans.tables.read_measurements`).
    measured_source : Path or None
        Their file.
    """

    plans: list | None = None
    sheet: str = "A1"
    measured: object = None
    measured_source: Path | None = None

    def tables(self) -> dict:
        """Every CSV table by its file name: the linkage's, and with plans
        ``<name>_plans.csv``, ``_lever.csv``, ``_lever_forces.csv``,
        ``_student_table.csv`` and with measurements ``_plan_errors.csv``: the numbers
        the write writes, bit for bit."""
        out = super().tables()
        if self.plans is None:
            return out
        from .tables import (error_table, lever_forces_table, lever_table, plans_table,
                             student_table)

        n = self.name
        st = student_table(self.plans)
        out[f"{n}_plans.csv"] = plans_table(self.plans)
        if all(pp.lever is not None for pp in self.plans):
            out.update({f"{n}_lever.csv": lever_table(self.plans),
                        f"{n}_lever_forces.csv": lever_forces_table(self.plans)})
        out[f"{n}_student_table.csv"] = st
        if self.measured is not None:
            out[f"{n}_plan_errors.csv"] = error_table(st, self.measured)
        return out

    def inputs(self) -> list:
        return super().inputs() + ([self.measured_source] if self.measured_source else [])

    def write_more(self, stage, lang, previews) -> tuple:
        """Write the plans' files (:func:`plans.report.write_plans`) into ``stage``;
        returns their names in the documented order and the number of sheets."""
        if self.plans is None:
            return [], 0
        from .report import output_names, write_plans

        before = set(stage.iterdir())
        info = write_plans(self.result, self.plans, stage, name=self.name, lang=lang,
                           sheet=self.sheet, measurements=self.measured, previews=previews)
        self.plans = info["plans"]          # as drawn: a diagram fitted to the sheet
        made = {p.name for p in set(stage.iterdir()) - before}
        listed = output_names(self.name, [pp.tag for pp in self.plans], info["sheets"],
                              self.measured is not None, previews)
        files = [f for f in listed if f in made] + sorted(made - set(listed))
        return files, info["sheets"]

    def more_lines(self, lang, written=None) -> list:
        """The plans' lines of the summary (:func:`plans.report.summary_lines`)."""
        if self.plans is None:
            return []
        from .report import summary_lines

        if written is not None:
            sheets = written.sheets
        else:
            from .drawing import layout_fitted, title_fields

            drawn, self.plans = layout_fitted(self.result, self.plans, lang, self.sheet,
                                              title_fields(self.spec))
            sheets = len(drawn)
        errors = (self.tables()[f"{self.name}_plan_errors.csv"]
                  if self.measured is not None else None)
        return summary_lines(self.plans, self.sheet, sheets, lang, errors=errors)


@dataclass
class ChainPlansReport(PlansReport):
    """A :class:`PlansReport` of a chain spec: the chain's files (as
    :class:`linkage.study.ChainReport`) and its velocity and acceleration plans."""

    chain = True


def _positions(plans, problems):
    """Position numbers from ``"all"``, ``"5,11"`` or an iterable of ints."""
    if isinstance(plans, str):
        text = plans.strip()
        if text.lower() == "all":
            return "all"
        parts = [p.strip() for p in text.split(",")]
    else:
        parts = list(plans)
    out = []
    for part in parts:
        ok = (part.isdigit() and int(part) >= 1) if isinstance(part, str) else (
            isinstance(part, int) and not isinstance(part, bool) and part >= 1)
        if not ok:
            problems.append(Problem("plans", Text("errors.plans.study.give_position_numbers",
                                                  {"part": part})))
        elif int(part) not in out:
            out.append(int(part))
    return out


def run_study(spec, *, step=1.0, plots=True, plans=None, sheet="A1", measured=None,
              mu_v=None, mu_a=None, mu_f=None, mu_lever=None) -> PlansReport:
    """Run the whole linkage study with the graphical method; write nothing.

    Parameters
    ----------
    spec : str, Path, dict or linkage.MechanismSpec
        The mechanism spec.
    step : float
        Crank-angle step of the full turn for the plots, 0 < step <= 30. [deg]
    plots : bool
        Analyse the full turn (the plots) and write the PNG previews; False: the tables
        and drawings only.
    plans : "all", str or iterable of int, optional
        Positions of the graphical method (``[5, 11]``, ``"5,11"``, ``"all"``); None:
        the linkage study alone.
    sheet : {"A1", "A3"}
        Drawing sheet size.
    measured : str, Path or DataFrame, optional
        A student's measured segments (:func:`plans.tables.read_measurements`); with
        ``plans`` only.
    mu_v, mu_a, mu_f, mu_lever : float, optional
        Fixed scales of the velocity plan [(m/s)/mm], the acceleration plan [(m/s²)/mm],
        the force polygons [N/mm] and the lever's forces [N/mm] (default: round scales).

    Returns
    -------
    PlansReport

    Raises
    ------
    SpecError
        Every problem of the arguments at once, each naming its argument (``step``,
        ``plans``, ``sheet``, ``mu_v`` …; ``positions`` and ``size`` from the plans), then
        those of the spec.
    """
    check_step(step)
    scale_args = {"mu_v": mu_v, "mu_a": mu_a, "mu_f": mu_f, "mu_lever": mu_lever}
    problems = []
    positions = scales = None
    if plans is not None:
        positions = _positions(plans, problems)
        if sheet not in SHEETS:
            problems.append(Problem("sheet", Text("errors.plans.study.valid",
                                                  {"sheet": sheet, "items": ', '.join(SHEETS)})))
        scales = {}
        for arg, kinds in _SCALES:
            value = scale_args[arg]
            if value is None:
                continue
            if not (isinstance(value, (int, float)) and 0 < value < math.inf):
                problems.append(Problem(arg, Text("errors.plans.study.scale", {"value": value})
                                        if isinstance(value, (int, float)) else
                                        Text("errors.plans.study.scale_other",
                                             {"value": repr(value)})))
            for k in kinds:
                scales[k] = value
    else:
        given = ["measured"] * (measured is not None) + [
            a for a, v in scale_args.items() if v is not None]
        problems += [Problem(a, Text("errors.plans.study.only_with_plans")) for a in given]
    if problems:
        raise SpecError(problems)

    base = run_linkage(spec, step=step, plots=plots)
    plan_list = table = measured_source = None
    if getattr(base, "chain", False):           # a chain: velocity and acceleration plans
        if plans is None:
            return base
        from .chain_model import build_chain_plans
        from .drawing import title_fields

        title_fields(base.spec)
        plan_list = build_chain_plans(base.result, positions, scales=scales)
        return ChainPlansReport(**vars(base), plans=plan_list, sheet=sheet)
    if plans is not None:
        from . import build_plans
        from .drawing import title_fields
        from .tables import read_measurements

        title_fields(base.spec)                              # [drawing] keys checked
        plan_list = build_plans(base.result, positions, scales=scales)
        if measured is not None:
            if hasattr(measured, "columns"):
                table = measured
            else:
                measured_source = Path(measured)
                table = read_measurements(measured)
    return PlansReport(**vars(base), plans=plan_list, sheet=sheet, measured=table,
                       measured_source=measured_source)
