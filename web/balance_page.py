"""The balance page: two-plane balancing of a rigid rotor or a linkage's shaking force
(``crankdyn balance``).

A rotor spec (``[rotor]`` with its ``[[rotor.mass]]`` lines: the corrections of each
plane, the shares, the m·r polygons) or a linkage spec (``[mechanism]``, a four-bar's or
any chain's, with an optional ``[balance]``: the counterweights, the shaking force and
moment before and after, its plots); the form follows the spec's kind
(:meth:`BalancePage.schema_for`).  :class:`BalancePage` computes through
:func:`dynamics.balance_study.run_study` and writes through
:func:`dynamics.balance_study.write_report`.
"""
from __future__ import annotations

from .pages import Kind, Run, table_rows, write_and_list

__all__ = ["EXAMPLES", "BalancePage"]

#: The bundled specs (the same as ``crankdyn balance --example NAME``).
EXAMPLES = {"rotor": "rotor_two_plane.toml", "ratchet": "ratchet_balance.toml",
            "shaper": "shaper.toml"}


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

    def schema_for(self, data=None, values=None):
        """The rotor's schema; for a spec or form of a linkage (``[mechanism]`` and no
        ``[rotor]``, as :func:`dynamics.balance_study.run_study` tells them) the
        linkage's or the chain's with the linkage's ``[balance]``."""
        from crankbase.schema import Schema
        from dynamics.schema import LINKAGE_BALANCE
        from linkage.schema import CHAIN_SCHEMA, SCHEMA

        data = data or {}
        if values:
            tops = {k.split(".", 1)[0] for k in values}
            linkage = "mechanism" in tops and "rotor" not in tops
            kind = values.get("mechanism.kind")
        else:
            linkage = "mechanism" in data and "rotor" not in data
            mech = data.get("mechanism")
            kind = mech.get("kind") if isinstance(mech, dict) else None
        if not linkage:
            return self.schema()
        base = CHAIN_SCHEMA if kind == "chain" else SCHEMA
        return Schema(base.name, tuple(base.tables) + (LINKAGE_BALANCE,), base.extra)

    def compute(self, data, input_dir, pressure, options):
        from dynamics.balance_study import run_study

        return run_study(data)

    def write(self, run: Run) -> dict:
        from dynamics.balance_study import write_report

        return write_and_list(run, write_report)

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
                    title1=self._title(r, names[0], t), title2=self._title(r, names[1], t),
                    toml_label=t("web.balance.results.toml"),
                    figures=sorted(n for n in (files or {}) if n.endswith(".png")))

    @staticmethod
    def _title(report, fname, t):
        """A table's heading: its words and its file name."""
        what = fname[len(report.stem) + 1:]
        key = {"counterweights.csv": "web.dyn.results.counterweights",
               "shaking.csv": "web.dyn.results.shaking"}.get(what)
        return t(key, file=fname) if key else fname
