"""The linkage page: the plan of positions, kinematics, kinetostatics (``crankdyn linkage``).

Its :class:`LinkagePage` computes through :func:`linkage.study.run_study` (the spec dict
read by :func:`linkage.load_spec`) and writes through :func:`linkage.study.write_report`.
"""
from __future__ import annotations

from .pages import Kind, Run, finish_files, table_rows

__all__ = ["EXAMPLES", "LinkagePage"]

#: The bundled mechanisms (the same as ``crankdyn linkage --example NAME``).
EXAMPLES = {"ratchet": "ratchet.toml", "press": "press.toml"}


class LinkagePage(Kind):
    name = "linkage"
    nav_key = "web.nav.linkage"
    title_key, intro_key = "web.linkage.title", "web.linkage.intro"
    results_template = "linkage_results.html"
    options_template = "linkage_options.html"
    examples = EXAMPLES
    example_prefix = "web.linkage.example."
    extra_fields = ("step",)

    def schema(self):
        from linkage.schema import SCHEMA

        return SCHEMA

    def options(self, values):
        return {"step": values.pop("step", "").strip()}

    def compute(self, data, input_dir, pressure, options):
        """Validate and analyse (:func:`linkage.study.run_study`, the full turn at the
        page's step for the diagrams).  Raises the library's SpecError (a bad step is
        named ``step``, the page's field)."""
        from linkage.study import run_study

        text = options.get("step") or "1"
        try:
            step = float(text.replace(",", "."))
        except ValueError:
            step = text
        return run_study(data, step=step, plots=True)

    def write(self, run: Run) -> dict:
        from linkage.study import write_report

        report = run.report
        written = write_report(report, run.folder / "report", run.lang)
        files = {n: written.folder / n for n in written.files}
        return finish_files(run, report.name, files)

    def results(self, run, lang, files=None):
        from crankbase.texts import texts
        from linkage.study import PLOTS, notice_lines, summary_lines

        t = texts(lang)
        r = run.report
        tables = r.tables()
        kin, frc = (f"{r.name}_kinematics.csv", f"{r.name}_forces.csv")
        head, rows = table_rows(tables[kin])
        head2, rows2 = table_rows(tables[frc])
        return dict(head=head, rows=rows, head2=head2, rows2=rows2,
                    total=len(tables[kin]), total2=len(tables[frc]),
                    summary=summary_lines(r, lang) + notice_lines(r, lang=lang),
                    figures=[f"{r.name}_{p}.png" for p in PLOTS],
                    tables=[kin, frc], xlsx=f"{r.name}.xlsx", name=r.name,
                    title1=t("web.linkage.results.kinematics"),
                    title2=t("web.linkage.results.forces"),
                    toml_label=t("web.linkage.results.toml"))
