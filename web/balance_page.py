"""The balance page: two-plane balancing of a rigid rotor (``crankdyn balance``).

A rotor spec (``[rotor]`` with its ``[[rotor.mass]]`` lines): :class:`BalancePage`
computes through :func:`dynamics.balance_study.run_study` and writes through
:func:`dynamics.balance_study.write_report`: the corrections of each plane, the shares,
the m·r polygons.  (A linkage's shaking-force balance runs from the command line.)
"""
from __future__ import annotations

from .pages import Kind, Run, finish_files, table_rows

__all__ = ["EXAMPLES", "BalancePage"]

#: The bundled rotor (``crankdyn balance --example rotor``).
EXAMPLES = {"rotor": "rotor_two_plane.toml"}


class BalancePage(Kind):
    name = "balance"
    nav_key = "web.nav.balance"
    title_key, intro_key = "web.balance.title", "web.balance.intro"
    examples = EXAMPLES
    example_prefix = "web.balance.example."
    wait_for_files = True

    def schema(self):
        from dynamics.schema import ROTOR_SCHEMA

        return ROTOR_SCHEMA

    def compute(self, data, input_dir, pressure, options):
        from dynamics.balance_study import run_study

        return run_study(data)

    def write(self, run: Run) -> dict:
        from dynamics.balance_study import write_report

        out = run.folder / "report"
        write_report(run.report, out, run.lang, formats=("png",))
        files = {p.name: p for p in sorted(out.iterdir())
                 if p.is_file() and not p.name.startswith(".")}
        return finish_files(run, run.report.stem, files)

    def results(self, run, lang, files=None):
        from crankbase.texts import texts
        from dynamics.balance_study import summary_lines

        t = texts(lang)
        r = run.report
        tables = r.tables()
        names = list(tables)
        head, rows = table_rows(tables[names[0]])
        head2, rows2 = table_rows(tables[names[1]])
        return dict(head=head, rows=rows, head2=head2, rows2=rows2,
                    total=len(tables[names[0]]), total2=len(tables[names[1]]),
                    summary=summary_lines(r, lang), tables=names, xlsx="", name=r.stem,
                    title1=names[0], title2=names[1],
                    toml_label=t("web.balance.results.toml"),
                    figures=sorted(n for n in (files or {}) if n.endswith(".png")))
