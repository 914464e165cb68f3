"""The dynamics page: the true motion of a machine and its flywheel (``crankdyn dynamics``).

A machine given by its reduced quantities (``[machine]`` with its elements and moments,
``[dynamics]``: the seed's flywheel example, the hoist): :class:`DynamicsPage` computes
through :func:`dynamics.study.run_study` and writes through
:func:`dynamics.study.write_report`.  (A linkage or an engine with ``[dynamics]`` runs from
the command line; its form is the linkage's or the engine's plus ``[dynamics]``.)
"""
from __future__ import annotations

from .pages import Kind, Run, finish_files, table_rows

__all__ = ["EXAMPLES", "DynamicsPage"]

#: The bundled machines (``crankdyn dynamics --example NAME``).
EXAMPLES = {"flywheel": "flywheel_seed.toml", "hoist": "hoist_machine.toml"}


class DynamicsPage(Kind):
    name = "dynamics"
    nav_key = "web.nav.dynamics"
    title_key, intro_key = "web.dynamics.title", "web.dynamics.intro"
    examples = EXAMPLES
    example_prefix = "web.dynamics.example."
    wait_for_files = True          # its figures depend on the machine: listed once drawn

    def schema(self):
        from dynamics.schema import SCHEMA

        return SCHEMA

    def compute(self, data, input_dir, pressure, options):
        from dynamics.study import run_study

        return run_study(data)

    def write(self, run: Run) -> dict:
        from dynamics.study import write_report

        out = run.folder / "report"
        write_report(run.report, out, run.lang, formats=("png",))
        files = {p.name: p for p in sorted(out.iterdir())
                 if p.is_file() and not p.name.startswith(".")}
        return finish_files(run, run.report.stem, files)

    def results(self, run, lang, files=None):
        from crankbase.texts import texts
        from dynamics.study import summary_lines

        t = texts(lang)
        r = run.report
        tables = r.tables()
        names = list(tables)
        head, rows = table_rows(tables[names[0]])
        out = dict(head=head, rows=rows, head2=[], rows2=[], summary=summary_lines(r, lang),
                   total=len(tables[names[0]]), total2=0,
                   tables=names, xlsx=f"{r.stem}_dynamics.xlsx", name=r.stem,
                   title1=t("web.dynamics.results.motion"), title2="",
                   toml_label=t("web.dynamics.results.toml"),
                   figures=sorted(n for n in (files or {}) if n.endswith(".png")))
        if len(names) > 1:
            out["head2"], out["rows2"] = table_rows(tables[names[1]])
            out["total2"] = len(tables[names[1]])
            out["title2"] = names[1]
        return out
