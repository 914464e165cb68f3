"""The balance study: one call balances a rotor or a linkage spec, another writes it.

:func:`run_study` reads a rotor spec (``[rotor]``: static or two-plane balancing,
:func:`dynamics.rotor.rotor_balance`) or a linkage spec (``[mechanism]``: shaking-force
balance by counterweights, :func:`dynamics.shaking.mechanism_balance`) and returns a
:class:`BalanceReport`, writing nothing; :func:`write_report` writes its tables and plots
as one report unit (``balance:<name>``); :func:`summary_lines` is the terminal summary in
the report's language (words from ``crankbase/locale/<lang>/balance.po``).
``crankdyn balance`` is these three calls.

Examples
--------
>>> from crankbase.resources import example_path
>>> from dynamics.balance_study import run_study
>>> report = run_study(example_path("rotor_two_plane.toml"))
>>> list(report.tables())
['two-plane-example_rotor_balance.csv', 'two-plane-example_rotor_shares.csv']
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .study import WrittenReport, remove_stale, written_line

__all__ = ["BalanceReport", "run_study", "write_report", "balance_figures", "summary_lines", "rotor_lines",
           "linkage_lines", "LEGACY_ROTOR", "LEGACY_LINKAGE"]

#: The unnamed outputs of crankdyn versions before the files were named after the spec.
LEGACY_ROTOR = ("rotor_balance.csv", "rotor_shares.csv", "rotor_polygons.png",
                "rotor_polygons.svg")
LEGACY_LINKAGE = ("counterweights.csv", "shaking.csv", "shaking_force.png",
                  "shaking_force.svg", "shaking_locus.png", "shaking_locus.svg")


@dataclass
class BalanceReport:
    """One balancing (nothing written).

    Attributes
    ----------
    kind : {"rotor", "linkage"}
    result : dynamics.rotor.RotorBalance or dynamics.shaking.MechanismBalance
    name : str
        The rotor's or the mechanism's name.
    source : Path or None
        The spec file.
    """

    kind: str
    result: object
    name: str
    source: Path | None = None

    @property
    def stem(self) -> str:
        """File stem of every output (:func:`crankbase.output.safe_name`)."""
        from crankbase.output import safe_name

        return safe_name(self.name, "rotor" if self.kind == "rotor" else "linkage")

    def tables(self) -> dict:
        """The CSV tables by file name: ``<stem>_rotor_balance.csv`` and
        ``<stem>_rotor_shares.csv`` (rotor), ``<stem>_counterweights.csv`` and
        ``<stem>_shaking.csv`` (linkage): what :func:`write_report` writes, bit for bit."""
        import pandas as pd

        res, n = self.result, self.stem
        if self.kind == "rotor":
            cols = ["plane", "z_mm", "mr_gmm", "angle_deg"]
            if "m_g" in res.corrections:
                cols += ["m_g", "r_mm"]
            return {f"{n}_rotor_balance.csv": res.corrections[cols],
                    f"{n}_rotor_shares.csv": res.shares}
        b, a = res.before.table, res.after.table
        shaking = pd.concat([b, a.drop(columns="phi_deg").add_suffix("_after")], axis=1)
        return {f"{n}_counterweights.csv": res.counterweights, f"{n}_shaking.csv": shaking}


def run_study(spec) -> BalanceReport:
    """Balance the rotor (``[rotor]``) or the linkage (``[mechanism]``, optional
    ``[balance]``) of a spec (a path or a dict); write nothing."""
    from crankbase.validation import read_toml

    data, _ = read_toml(spec)
    source = None if isinstance(spec, dict) else Path(spec)
    if "mechanism" in data and "rotor" not in data:
        from .shaking import mechanism_balance

        res = mechanism_balance(spec)
        return BalanceReport("linkage", res, res.balanced_spec.name, source)
    from .rotor import rotor_balance

    res = rotor_balance(spec)
    return BalanceReport("rotor", res, res.name, source)


def balance_figures(report, lang="ru"):
    """The report's figures, ``{stem suffix: Figure}``: the m·r polygons of each
    correction plane (rotor) or the shaking force and its locus (linkage); what
    :func:`write_report` saves."""
    from matplotlib.figure import Figure

    res = report.result
    if report.kind == "rotor":
        from .rotor import plot_mr_polygon

        n = len(report.tables()[f"{report.stem}_rotor_balance.csv"])
        fig = Figure(figsize=(5.2 * n, 5.2), layout="constrained")
        for k in range(n):
            plot_mr_polygon(res, k, fig.add_subplot(1, n, k + 1), lang=lang)
        return {"rotor_polygons": fig}
    from .shaking import plot_shaking_force, plot_shaking_locus

    figs = {}
    for key, fn, size in (("shaking_force", plot_shaking_force, (7.5, 4.2)),
                          ("shaking_locus", plot_shaking_locus, (6, 6))):
        fig = Figure(figsize=size, layout="constrained")
        fn(res, fig.add_subplot(), lang=lang)
        figs[key] = fig
    return figs


def write_report(report: BalanceReport, out, lang="ru",
                 formats=("png", "svg")) -> WrittenReport:
    """Write a balance report into the folder ``out`` as one report unit
    (``balance:<name>``, apart from the ``crankdyn linkage`` report of the same
    mechanism): the tables (:meth:`BalanceReport.tables`) and the plots
    (``<name>_rotor_polygons``; ``<name>_shaking_force``, ``<name>_shaking_locus``) in
    ``lang``; bad numbers write nothing."""
    from crankbase.output import (check_not_input, ensure_finite, save_figure,
                                  staged_output, write_csv)
    from crankbase.validation import check_lang

    check_lang(lang)
    out = Path(out)
    tables = report.tables()
    what = (("rotor corrections", "rotor shares") if report.kind == "rotor"
            else ("counterweights", "shaking force"))
    for (fname, df), w in zip(tables.items(), what):
        ensure_finite(df.drop(columns="link") if "link" in df else df, w)
    figs = balance_figures(report, lang)
    name = report.stem
    names = list(tables) + [f"{name}_{k}.{e}" for k in figs for e in formats]
    inputs = [report.source] if report.source else []
    check_not_input([out / n for n in names], inputs)
    with staged_output(out, inputs=inputs, unit=f"balance:{name}") as stage:
        for fname, df in tables.items():
            write_csv(df, stage / fname)
        for key, fig in figs.items():
            save_figure(fig, stage / f"{name}_{key}", formats=formats)
    removed, legacy = remove_stale([], out, LEGACY_ROTOR if report.kind == "rotor"
                                   else LEGACY_LINKAGE)
    return WrittenReport(out, list(tables), len(figs), tuple(formats), removed, legacy)


def _snap(value, scale, fmt):
    """A residual below round-off of ``scale`` is shown as 0 (crankbase.tolerances)."""
    from crankbase.tolerances import format_snapped

    return format_snapped(value, fmt, scale)


def rotor_lines(res, table=None, lang="en"):
    """The terminal summary of a rotor balancing in ``lang`` (ru: Russian words and the
    textbook's (m r)б; en: no Cyrillic letter); every number formatted once."""
    from crankbase.texts import texts

    t = texts(lang)
    if table is None:
        table = res.corrections
    lines = [t("balance.rotor.head", name=res.name, kind=t(f"balance.rotor.{res.kind}"),
               masses=len(res.masses), planes=len(table))]
    for _, row in table.iterrows():
        extra = (t("balance.rotor.mass", m=f"{row['m_g']:.4g}", r=f"{row['r_mm']:g}")
                 if "m_g" in row else "")
        lines.append("  " + t("balance.rotor.plane", plane=row["plane"],
                              z=f"{row['z_mm']:g}", mr=_snap(row["mr_gmm"], 0, ".2f"),
                              angle=f"{row['angle_deg']:.2f}", extra=extra))
    mr = res.masses["mr_gmm"].abs().max()
    F = _snap(res.residual_force_gmm, max(res.initial_force_gmm, mr), ".3g")
    M = _snap(res.residual_moment_gmm2, max(res.initial_moment_gmm2,
                                            mr * max(1.0, float(abs(res.masses["z_mm"])
                                                                .max()))), ".3g")
    lines.append("  " + t("balance.rotor.residual", F=F, M=M,
                          F0=f"{res.initial_force_gmm:.4g}",
                          M0=f"{res.initial_moment_gmm2:.4g}"))
    return lines


def linkage_lines(res, lang="en"):
    """The terminal summary of a linkage's balance in ``lang`` (ru: Russian words and
    symbols; en: no Cyrillic letter); every number formatted once."""
    from crankbase.texts import texts

    t = texts(lang)
    spec = res.balanced_spec
    kind = spec.kind.replace("-", "_")
    what = t("balance.linkage.partial") if spec.kind == "crank-slider" else t(
        "balance.linkage.full")
    if spec.kind == "chain":                 # any chain: the first-harmonic counterweight
        from linkage.chain import structure_formula

        label = t("balance.linkage.chain", formula=structure_formula(spec.mechanism))
        what = t("balance.linkage.harmonic")
    else:
        label = t(f"balance.linkage.{kind}") if kind in ("crank_rocker", "crank_slider") \
            else spec.kind
    lines = [t("balance.linkage.head", name=spec.name, kind=label, what=what)]
    cw = res.counterweights
    links = {"crank": t("balance.linkage.crank"), "rocker": t("balance.linkage.rocker")}
    width = max(len(links.get(r, r)) for r in cw["link"])
    for _, r in cw.iterrows():
        lines.append("  " + t("balance.linkage.counterweight",
                              link=f"{links.get(r['link'], r['link']):<{width}}",
                              mr=f"{r['mr_kgm']:.6g}", angle=f"{r['angle_deg']:.2f}",
                              m=f"{r['mass_kg']:.6g}", r=f"{r['radius_m']:.6g}"))
    if "fraction" in cw:
        lines.append("  " + t("balance.linkage.fraction", fraction=f"{cw['fraction'].iloc[0]:g}",
                              unit=t.unit("-")))
    before = res.before.F_max
    lines.append("  " + t("balance.linkage.force", before=f"{before:.6g}",
                          after=_snap(res.after.F_max, before, ".6g")))
    return lines


def summary_lines(report: BalanceReport, lang="ru", written=None) -> list:
    """The terminal summary of a balancing in ``lang`` (:func:`rotor_lines` or
    :func:`linkage_lines`), with ``written`` the files written."""
    if report.kind == "rotor":
        lines = rotor_lines(report.result,
                            report.tables()[f"{report.stem}_rotor_balance.csv"], lang)
    else:
        lines = linkage_lines(report.result, lang)
    if written is not None:
        lines.append(written_line(written, lang))
    return lines
