"""The synthesis study: one call designs a crank-rocker of the ККМ-φ0 family, another
writes it.

:func:`run_study` computes the region of existence and Table 1 for φ0 and, when one
design task is given, the chosen mechanism, μ(φ) over a turn and (with ``ground``) the
spec of the mechanism for ``crankdyn linkage``; it returns a :class:`SynthesisReport`,
writing nothing.  :func:`write_report` writes its tables, workbook, spec and plots as one
report unit; :func:`summary_lines` is the terminal summary in the report's language
(words from ``crankbase/locale/<lang>/synth.po``).  ``crankdyn synth`` is these three
calls.

Design tasks (one of): ``l2`` and ``l3`` (λ1 from eq. 6); ``l1`` (λ2 = λ3); ``l2`` and
``mu_min`` (the largest λ1 with μmin ≥ it, optionally rounded down to ``l1_step``); none:
the region and Table 1 only.

Examples
--------
>>> from linkage.synthesis_study import run_study
>>> report = run_study(30, l2=0.8, mu_min=40, ground=0.5, plots=False)
>>> list(report.tables())
['kkm-30_table1.csv', 'kkm-30_mechanism.csv', 'kkm-30_transmission_angle.csv']
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from crankbase.errors import Problem, SpecError, Text
from crankbase.schema import Key, Schema, Table

__all__ = ["SynthesisReport", "WrittenReport", "run_study", "write_report", "summary_lines",
           "MODES", "INPUTS", "SCHEMA", "check_inputs", "inputs_from_spec", "study_arguments",
           "command_line", "FLAGS", "option"]

#: The design task by the lengths and angle given.
MODES = {
    frozenset(): "region",
    frozenset({"l2", "l3"}): "l2_l3",
    frozenset({"l1"}): "l1",
    frozenset({"l2", "mu_min"}): "mu_min",
}

# ----------------------------------------------------------------------------- the inputs
#: The inputs of a synthesis, declared once (:mod:`crankbase.schema`; words in the
#: ``spec`` catalogue under ``spec.synth.<key>``): the synthesis page's form and the
#: options of ``crankdyn synth`` (:data:`FLAGS`), both checked by :func:`check_inputs`.
INPUTS = Table("synth", (
    Key("phi0_deg", gt=0, lt=180, unit="°", default=30.0, symbol=True),
    Key("l1", gt=0, symbol=True),
    Key("l2", gt=0, symbol=True),
    Key("l3", gt=0, symbol=True),
    Key("mu_min_deg", ge=0, lt=90, unit="°", symbol=True),
    Key("l1_step", gt=0),
    Key("ground_m", gt=0, unit="m", symbol=True),
    Key("omega_rad_s", unit="rad/s", symbol=True),
    Key("name", "name", shown_default="kkm-<φ0>"),
), required=True)

#: The inputs as a spec (``[synth]``: the synthesis page's upload and its spec download).
SCHEMA = Schema("synth", (INPUTS,))

#: Each input's flag on ``crankdyn synth``'s command line, without its dashes (the CLI
#: names a problem's input by it, :func:`command_line` writes it): declared here, beside
#: the inputs, so the command line and the synthesis page's "repeat it" line agree.
FLAGS = {"phi0_deg": "phi0", "l1": "l1", "l2": "l2", "l3": "l3", "mu_min_deg": "mu-min",
         "l1_step": "l1-step", "ground_m": "ground", "omega_rad_s": "omega", "name": "name"}


def option(key: str) -> str:
    """The command-line option of input ``key`` (``"mu_min_deg"`` → ``--mu-min``), or of
    a flag every subcommand shares (``"lang"`` → ``--lang``)."""
    return "--" + FLAGS.get(key, key)

#: ``(test, what is valid)`` of each number (the words in ``errors.po``).
_VALID = {"phi0_deg": (lambda x: 0 < x < 180, "errors.cli.synth.phi0"),
          "l1": (lambda x: x > 0, "errors.cli.synth.positive"),
          "l2": (lambda x: x > 0, "errors.cli.synth.positive"),
          "l3": (lambda x: x > 0, "errors.cli.synth.positive"),
          "mu_min_deg": (lambda x: 0 <= x < 90, "errors.cli.synth.mu_min"),
          "l1_step": (lambda x: x > 0, "errors.cli.synth.l1_step"),
          "ground_m": (lambda x: x > 0, "errors.cli.synth.ground"),
          "omega_rad_s": (lambda x: x != 0, "errors.cli.synth.omega")}

#: The design-task inputs, by their names in :data:`MODES`.
_TASK = (("l1", "l1"), ("l2", "l2"), ("l3", "l3"), ("mu_min_deg", "mu_min"))


def _number(problems, key, value, names):
    """One input as a float (None when not given or bad); a problem naming the input,
    the value and what is valid when it is not a number or out of its range."""
    import math

    if value is None:
        return None
    test, valid = _VALID[key]
    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        value = str(value)
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        problems.append(Problem(names[key], Text("errors.cli.synth.not_number",
                                                 {"value": value, "valid": Text(valid)})))
        return None
    if not (math.isfinite(x) and test(x)):
        problems.append(Problem(names[key], Text("errors.cli.synth.bad",
                                                 {"value": value, "valid": Text(valid)})))
        return None
    from crankbase.validation import magnitude_text

    why = magnitude_text(x)              # the same bound as every spec number
    if why:
        problems.append(Problem(names[key], why))
        return None
    return x


def check_inputs(values: dict, names: dict | None = None) -> tuple[dict, str]:
    """Check the inputs of a synthesis: every problem at once, one per input.

    The one check of ``crankdyn synth`` and the synthesis page.

    Parameters
    ----------
    values : dict
        The inputs by their :data:`INPUTS` key (``phi0_deg``, ``l1``, ``l2``, ``l3``,
        ``mu_min_deg``, ``l1_step``, ``ground_m``, ``omega_rad_s``, ``name``): a number,
        its text as typed, or None (not given; ``phi0_deg`` then 30°).
    names : dict, optional
        How the problems name each input (default: its key; ``crankdyn synth`` gives
        :func:`option`, a form its fields); ``"mode"`` names a wrong choice of the
        design task (default ``"mode"``).

    Returns
    -------
    (dict, str)
        The inputs as numbers (``name`` a text; None where not given) and the design
        task, one of :data:`MODES`' values.

    Raises
    ------
    SpecError
        Every problem: a value that is no number or out of its range (what is valid
        named), a wrong set of lengths and angle, ``l1_step`` without ``mu_min_deg``,
        ``ground_m`` without a mechanism, ``omega_rad_s`` without ``ground_m``, a bad
        ``name``.

    Examples
    --------
    >>> check_inputs({"l2": "0.8", "mu_min_deg": 40})[1]
    'mu_min'
    """
    names = {**{k: k for k in FLAGS}, "mode": "mode", **(names or {})}
    unknown = set(values) - set(FLAGS)
    if unknown:
        raise ValueError(f"check_inputs: unknown inputs {sorted(unknown)}")
    given = {k: v for k, v in values.items() if v is not None}
    problems = []
    out = {k: _number(problems, k, given.get(k), names) for k in _VALID}
    if out["phi0_deg"] is None and "phi0_deg" not in given:
        out["phi0_deg"] = 30.0
    task = frozenset(m for k, m in _TASK if k in given)
    mode = MODES.get(task)
    if mode is None:
        got = " ".join(names[k] for k, _ in _TASK if k in given)
        problems.append(Problem(names["mode"], Text(
            "errors.linkage.synthesis_study.modes",
            {"got": got, "l1": names["l1"], "l2": names["l2"], "l3": names["l3"],
             "mu_min": names["mu_min_deg"]})))
    if "l1_step" in given and mode != "mu_min":
        problems.append(Problem(names["l1_step"], Text(
            "errors.linkage.synthesis_study.l1_step_only",
            {"l2": names["l2"], "mu_min": names["mu_min_deg"]})))
    if "ground_m" in given and mode == "region":
        problems.append(Problem(names["ground_m"], Text(
            "errors.linkage.synthesis_study.ground_needs",
            {"l1": names["l1"], "l2": names["l2"], "l3": names["l3"],
             "mu_min": names["mu_min_deg"]})))
    if "omega_rad_s" in given and "ground_m" not in given:
        problems.append(Problem(names["omega_rad_s"], Text(
            "errors.linkage.synthesis_study.omega_only", {"ground": names["ground_m"]})))
    out["name"] = None
    if "name" in given:
        from crankbase.validation import name_text

        why = name_text(given["name"])
        if why:
            problems.append(Problem(names["name"], why))
        else:
            out["name"] = given["name"]
    if problems:
        raise SpecError(problems)
    return out, mode


def inputs_from_spec(data: dict) -> tuple[dict, str]:
    """The checked inputs of a ``[synth]`` spec (the synthesis page's form or upload):
    :func:`check_inputs`, each problem named by its key path (``synth.mu_min_deg``),
    unknown tables and keys reported ("did you mean")."""
    from crankbase.schema import SpecReader

    r = SpecReader()
    if not isinstance(data, dict):
        data = {}
    r.top(data, SCHEMA)
    raw = r.sub(data, INPUTS)
    r.raise_if_any()
    values = {k: raw.get(k) for k in FLAGS}
    return check_inputs(values, {**{k: f"synth.{k}" for k in FLAGS}, "mode": "synth"})


def study_arguments(inputs: dict) -> dict:
    """The keyword arguments of :func:`run_study` for checked ``inputs``
    (:func:`check_inputs`' first value)."""
    return dict(phi0=inputs["phi0_deg"], l1=inputs["l1"], l2=inputs["l2"],
                l3=inputs["l3"], mu_min=inputs["mu_min_deg"], l1_step=inputs["l1_step"],
                ground=inputs["ground_m"], name=inputs["name"], omega=inputs["omega_rad_s"])


def command_line(inputs: dict, lang="ru", output="OUT") -> str:
    """The ``crankdyn synth`` command that repeats a synthesis of checked ``inputs``."""
    import shlex

    parts = ["crankdyn", "synth"]
    for key in FLAGS:
        v = inputs.get(key)
        if v is None:
            continue
        parts += [option(key), v if isinstance(v, str) else f"{v!r}".removesuffix(".0")
                  if float(v).is_integer() else repr(v)]
    parts += [option("lang"), lang, "-o", output]
    return " ".join(shlex.quote(p) for p in parts)


@dataclass
class SynthesisReport:
    """One synthesis (nothing written).

    Attributes
    ----------
    phi0 : float
        Crank angle where μ = 90°. [deg]
    mode : {"region", "l2_l3", "l1", "mu_min"}
    region : linkage.synthesis.ExistenceRegion
    table1 : pandas.DataFrame
        The paper's Table 1 for φ0.
    design : linkage.synthesis.Design or None
    mechanism : pandas.DataFrame or None
        The chosen mechanism (one row; absolute lengths with ``ground``).
    transmission : pandas.DataFrame or None
        ``phi_deg, mu_deg`` over a turn at 1°.
    spec : dict or None
        The ``crankdyn linkage`` spec of the mechanism (with ``ground``).
    ground : float or None
        Ground length. [m]
    mu_min : float or None
        The required μmin of the task (drawn on the μmin plot). [deg]
    name : str
        The design's name (default ``kkm-<φ0>``); ``stem`` is its file stem.
    plots : bool
        Whether :func:`write_report` draws the plots.
    """

    phi0: float
    mode: str
    region: object
    table1: object
    design: object = None
    mechanism: object = None
    transmission: object = None
    spec: dict | None = None
    ground: float | None = None
    mu_min: float | None = None
    name: str = "kkm"
    plots: bool = True

    @property
    def stem(self) -> str:
        from crankbase.output import safe_name

        return safe_name(self.name, "kkm")

    def tables(self) -> dict:
        """The CSV tables by file name (``<stem>_table1.csv``; with a design
        ``<stem>_mechanism.csv`` and ``<stem>_transmission_angle.csv``): what
        :func:`write_report` writes, bit for bit."""
        out = {f"{self.stem}_table1.csv": self.table1}
        if self.design is not None:
            out[f"{self.stem}_mechanism.csv"] = self.mechanism
            out[f"{self.stem}_transmission_angle.csv"] = self.transmission
        return out


@dataclass
class WrittenReport:
    """What :func:`write_report` wrote: ``files`` (names in ``folder``, in order)."""

    folder: Path
    files: list


def run_study(phi0=30.0, *, l1=None, l2=None, l3=None, mu_min=None, l1_step=None,
              ground=None, name=None, omega=None, plots=True) -> SynthesisReport:
    """Run a synthesis of the ККМ-φ0 family; write nothing.

    Parameters
    ----------
    phi0 : float
        Crank angle where μ = 90°, 0 < φ0 < 180. [deg]
    l1, l2, l3 : float, optional
        Lengths relative to the ground (λ0 = 1); see the design tasks above.
    mu_min : float, optional
        Required minimum transmission angle, with ``l2``. [deg]
    l1_step : float, optional
        With ``mu_min``: λ1 rounded down to a multiple of it (the paper: 0.01).
    ground : float, optional
        Ground length: absolute lengths and the spec for ``crankdyn linkage``. [m]
    name : str, optional
        The design's name (default ``kkm-<φ0>``).
    omega : float, optional
        Crank speed written into the spec (default 1; with ``ground``). [rad/s]
    plots : bool
        Draw the plots when written.

    Raises
    ------
    SpecError
        Problems naming the arguments (``l1``, ``l2``, ``mu_min_deg`` …).
    """
    import numpy as np
    import pandas as pd

    from crankbase.output import ensure_finite

    from . import synthesis as syn
    from . import synthesis_report as rep

    given = frozenset(k for k, v in (("l1", l1), ("l2", l2), ("l3", l3), ("mu_min", mu_min))
                      if v is not None)
    mode = MODES.get(given)
    problems = []
    if mode is None:
        problems.append(Problem(", ".join(sorted(given)),
                                Text("errors.linkage.synthesis_study.choose_one_l")))
    if l1_step is not None and mode != "mu_min":
        problems.append(Problem("l1_step", Text("errors.linkage.synthesis_study.only_with_l")))
    if ground is not None and mode == "region":
        problems.append(Problem("ground_m",
                                Text("errors.linkage.synthesis_study.needs_chosen_mechanism")))
    if omega is not None and ground is None:
        problems.append(Problem("omega", Text("errors.linkage.synthesis_study.only_with_ground")))
    if problems:
        raise SpecError(problems)
    try:
        design = None
        if mode == "l2_l3":
            design = syn.design_from_l2_l3(l2, l3, phi0)
        elif mode == "l1":
            design = syn.design_equal_l2_l3(l1, phi0)
        elif mode == "mu_min":
            design = syn.design_for_mu_min(l2, mu_min, phi0, l1_step=l1_step)
        region = syn.existence_region(phi0)
    except syn.SynthesisError as exc:
        raise SpecError(exc.problems) from None
    table = rep.table1(phi0)
    ensure_finite(table, "Table 1")
    mech = mu_turn = spec = None
    name = name if name is not None else f"kkm-{phi0:g}"
    if design is not None:
        mech = rep.mechanism_table(design, ground)
        ensure_finite(mech, "mechanism")
        phi = np.arange(0.0, 361.0, 1.0)
        mu_turn = pd.DataFrame({"phi_deg": phi, "mu_deg": syn.transmission_angle_deg(
            phi, design.l1, design.l2, design.l3)})
        ensure_finite(mu_turn, "transmission angle")
        if ground is not None:
            extra = {"name": name}
            if omega is not None:
                extra["omega_rad_s"] = omega
            spec = design.to_spec(ground, **extra)
            import linkage
            linkage.load_spec(spec)   # the core must accept what we write
    return SynthesisReport(phi0=phi0, mode=mode, region=region, table1=table,
                           design=design, mechanism=mech, transmission=mu_turn, spec=spec,
                           ground=ground, mu_min=mu_min, name=name, plots=plots)


def _figures(report, lang):
    from . import synthesis as syn
    from . import synthesis_plots as plots

    d, phi0 = report.design, report.phi0
    family = syn.right_angle_family(d.l1, phi0) if d is not None else None
    figures = {"region": plots.plot_region(report.region, d, family=family,
                                           lang=lang).figure,
               "mu_min": plots.plot_mu_min_curves(syn.mu_min_curves(phi0), d,
                                                  mu_required=report.mu_min,
                                                  lang=lang).figure}
    if d is not None:
        tr = report.transmission
        figures["transmission_angle"] = plots.plot_transmission_angle(
            tr["phi_deg"].to_numpy(), tr["mu_deg"].to_numpy(), d, lang=lang).figure
    return figures


def write_report(report: SynthesisReport, out, lang="ru",
                 formats=("png", "svg")) -> WrittenReport:
    """Write a synthesis into the folder ``out`` as one report unit (named after the
    design): ``<stem>_table1.csv``, the workbook ``<stem>_synthesis.xlsx``, with a design
    ``<stem>_mechanism.csv`` and ``<stem>_transmission_angle.csv``, with ``ground`` the
    spec ``<stem>.toml``, and the plots ``<stem>_region``, ``_mu_min``,
    ``_transmission_angle`` in ``formats``; all files appear together, or none."""
    from crankbase.output import save_figure, staged_output, write_csv
    from crankbase.validation import check_lang

    from . import synthesis_report as rep

    check_lang(lang)
    figures = _figures(report, lang) if report.plots else {}
    stem = report.stem
    written = []

    def put(name):
        written.append(name)
        return stage / name
    tables = report.tables()
    with staged_output(out, unit=stem) as stage:
        write_csv(tables[f"{stem}_table1.csv"], put(f"{stem}_table1.csv"))
        rep.write_workbook(put(f"{stem}_synthesis.xlsx"), report.table1, report.phi0,
                           report.mechanism, lang=lang)
        if report.design is not None:
            for suffix in ("mechanism", "transmission_angle"):
                write_csv(tables[f"{stem}_{suffix}.csv"], put(f"{stem}_{suffix}.csv"))
        if report.spec is not None:
            rep.write_toml(report.spec, put(f"{stem}.toml"),
                           rep.toml_header(report.design, lang))
        for name, fig in figures.items():
            save_figure(fig, stage / f"{stem}_{name}", formats=formats, dpi=150,
                        tight=True)
            written.extend(f"{stem}_{name}.{ext}" for ext in formats)
    return WrittenReport(out, written)


def summary_lines(report: SynthesisReport, lang="ru", written=None) -> list:
    """The terminal summary of a synthesis in ``lang``
    (:func:`linkage.synthesis_report.summary_lines`), with ``written`` the files."""
    from . import synthesis_report as rep

    lines = rep.summary_lines(report.region, report.table1, report.design, report.ground,
                              lang)
    if written is not None:
        lines.append(rep.written_line(written.folder, written.files, lang))
    return lines
