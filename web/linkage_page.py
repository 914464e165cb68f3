"""The linkage page: the plan of positions, kinematics, kinetostatics (``crankdyn linkage``).

Its :class:`LinkagePage` computes through :func:`plans.study.run_study` (the spec dict
read by :func:`linkage.load_spec`; a four-bar's or any chain's of class II groups) and
writes through :func:`linkage.study.write_report`.  With positions for the plans (the
field ``plans``, like ``--plans 2,5``, and the sheet size ``sheet``, like ``--sheet``)
the run adds the graphical method's files as the command line writes them: the plans
sheet (PDF, DXF and its PNG preview), the plans at each position and their tables.
"""
from __future__ import annotations

from .pages import Kind, Run, finish_files, table_rows

__all__ = ["EXAMPLES", "LinkagePage"]

#: The bundled mechanisms (the same as ``crankdyn linkage --example NAME``).
EXAMPLES = {"ratchet": "ratchet.toml", "press": "press.toml", "shaper": "shaper.toml",
            "press6": "press6.toml"}


class LinkagePage(Kind):
    name = "linkage"
    nav_key = "web.nav.linkage"
    title_key, intro_key = "web.linkage.title", "web.linkage.intro"
    results_template = "linkage_results.html"
    options_template = "linkage_options.html"
    examples = EXAMPLES
    example_prefix = "web.linkage.example."
    extra_fields = ("step", "plans", "sheet")

    def schema(self):
        from linkage.schema import SCHEMA

        return SCHEMA

    def schema_for(self, data=None, values=None):
        """A chain's schema for a spec or form of ``kind = "chain"``, else the four-bar's."""
        from linkage.schema import CHAIN_SCHEMA, SCHEMA

        mech = (data or {}).get("mechanism")
        kind = mech.get("kind") if isinstance(mech, dict) else None
        if values is not None:
            kind = values.get("mechanism.kind", kind)
        return CHAIN_SCHEMA if kind == "chain" else SCHEMA

    def options(self, values):
        return {"step": values.pop("step", "").strip(),
                "plans": values.pop("plans", "").strip(),
                "sheet": values.pop("sheet", "").strip() or "A1"}

    def waits(self, run):
        return bool(run.options.get("plans"))     # the drawings: listed once written

    def compute(self, data, input_dir, pressure, options):
        """Validate and analyse (:func:`plans.study.run_study`, the full turn at the
        page's step for the diagrams; with ``plans`` the graphical method at those
        positions on a ``sheet``).  Raises the library's SpecError (a bad step, position
        list or sheet is named ``step``, ``plans`` or ``sheet``, the page's fields)."""
        from plans.study import run_study

        text = options.get("step") or "1"
        try:
            step = float(text.replace(",", "."))
        except ValueError:
            step = text
        return run_study(data, step=step, plots=True, plans=options.get("plans") or None,
                         sheet=options.get("sheet") or "A1")

    def write(self, run: Run) -> dict:
        from linkage.study import write_report

        report = run.report
        written = write_report(report, run.folder / "report", run.lang)
        files = {n: written.folder / n for n in written.files}
        return finish_files(run, report.name, files)

    def results(self, run, lang, files=None):
        from crankbase.texts import texts
        from linkage.chain_report import CHAIN_PLOTS
        from linkage.study import PLOTS, notice_lines, summary_lines

        t = texts(lang)
        r = run.report
        tables = r.tables()
        kin, frc = (f"{r.name}_kinematics.csv", f"{r.name}_forces.csv")
        head, rows = table_rows(tables[kin])
        head2, rows2 = table_rows(tables[frc])
        plots = CHAIN_PLOTS if getattr(r, "chain", False) else PLOTS
        figures = [f"{r.name}_{p}.png" for p in plots]
        if files:      # with plans: the sheet's previews first, then each position's plans
            figures = sorted(n for n in files if n.startswith(f"{r.name}_sheet")
                             and n.endswith(".png")) + figures + [
                n for n in files if n.startswith(f"{r.name}_plans_") and n.endswith(".png")]
        more = {}
        if getattr(r, "plans", None) is not None:
            more["drawings_label"] = t("web.linkage.results.drawings")
        return dict(more, head=head, rows=rows, head2=head2, rows2=rows2,
                    total=len(tables[kin]), total2=len(tables[frc]),
                    summary=summary_lines(r, lang) + notice_lines(r, lang=lang),
                    figures=figures,
                    tables=list(tables), xlsx=f"{r.name}.xlsx", name=r.name,
                    title1=t("web.linkage.results.kinematics"),
                    title2=t("web.linkage.results.forces"),
                    toml_label=t("web.linkage.results.toml"))
