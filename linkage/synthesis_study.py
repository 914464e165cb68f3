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

__all__ = ["SynthesisReport", "WrittenReport", "run_study", "write_report", "summary_lines",
           "MODES"]

#: The design task by the lengths and angle given.
MODES = {
    frozenset(): "region",
    frozenset({"l2", "l3"}): "l2_l3",
    frozenset({"l1"}): "l1",
    frozenset({"l2", "mu_min"}): "mu_min",
}


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
    try:
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
    finally:
        for fig in figures.values():
            fig.clear()
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
