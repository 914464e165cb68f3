"""The synthesis page: a crank-rocker of the ККМ-φ0 family by its transmission angle
(``crankdyn synth``).

Its form is the schema of the synthesis inputs (:data:`linkage.synthesis_study.SCHEMA`,
one ``[synth]`` table); :class:`SynthPage` checks them with the command's own check
(:func:`linkage.synthesis_study.inputs_from_spec`, each problem at its field), computes
through :func:`linkage.synthesis_study.run_study` and writes through
:func:`linkage.synthesis_study.write_report`: the region of existence, Table 1, the chosen
mechanism, μ(φ) over a turn, the plots, the workbook and (with the ground length) the spec
for ``crankdyn linkage``; the page shows the ``crankdyn synth`` command that repeats the run.
"""
from __future__ import annotations

from .pages import Kind, Run, finish_files, table_rows

__all__ = ["EXAMPLES", "SynthPage", "FIGURES"]

#: The bundled tasks by short name: the README's (``crankdyn synth --l2 0.8 --mu-min 40
#: --ground 0.5``), the paper's Fig. 3 reading (Sereda 2016: λ2 = 0.9, μmin = 40°, λ1 read
#: to 0.01), equal coupler and rocker, and the region and Table 1 alone.
EXAMPLES = {
    "readme": {"synth": {"phi0_deg": 30, "l2": 0.8, "mu_min_deg": 40, "ground_m": 0.5}},
    "paper": {"synth": {"phi0_deg": 30, "l2": 0.9, "mu_min_deg": 40, "l1_step": 0.01,
                        "ground_m": 0.5}},
    "equal": {"synth": {"phi0_deg": 30, "l1": 0.15}},
    "region": {"synth": {"phi0_deg": 45}},
}

#: The plots (``<stem>_<plot>.png``); the last only with a chosen mechanism.
FIGURES = ("region", "mu_min", "transmission_angle")

#: The library's argument names in its problems → the form's fields.
FIELDS = {"phi0_deg": "synth.phi0_deg", "l1": "synth.l1", "l2": "synth.l2",
          "l3": "synth.l3", "mu_min_deg": "synth.mu_min_deg", "mu_min": "synth.mu_min_deg",
          "l1_step": "synth.l1_step", "ground_m": "synth.ground_m",
          "omega": "synth.omega_rad_s"}


class SynthPage(Kind):
    name = "synth"
    nav_key = "web.nav.synth"
    title_key, intro_key = "web.synth.title", "web.synth.intro"
    examples = EXAMPLES
    example_prefix = "web.synth.example."

    def schema(self):
        from linkage.synthesis_study import SCHEMA

        return SCHEMA

    def example_spec(self, name):
        import copy

        return copy.deepcopy(self.examples[name]), None

    def compute(self, data, input_dir, pressure, options):
        """Check the ``[synth]`` inputs (``crankdyn synth``'s check, each problem named
        by its field) and run the synthesis; nothing is computed from a bad form."""
        from crankbase.errors import SpecError
        from linkage.synthesis_study import inputs_from_spec, run_study, study_arguments

        inputs, _mode = inputs_from_spec(data)
        try:
            return run_study(**study_arguments(inputs))
        except SpecError as exc:
            raise exc.renamed(FIELDS) from None

    def write(self, run: Run) -> dict:
        from linkage.synthesis_study import write_report

        report = run.report
        written = write_report(report, run.folder / "report", run.lang, formats=("png",))
        files = {n: written.folder / n for n in written.files}
        # the inputs' spec beside the design's (``<stem>.toml``, a crankdyn linkage spec)
        return finish_files(run, report.stem, files, spec_name=f"{report.stem}_synth.toml")

    def results(self, run, lang, files=None):
        from crankbase.texts import texts
        from linkage.synthesis_study import command_line, inputs_from_spec, summary_lines

        t = texts(lang)
        r = run.report
        tables = r.tables()
        names = list(tables)
        head, rows = table_rows(tables[names[0]])
        out = dict(head=head, rows=rows, head2=[], rows2=[], total=len(tables[names[0]]),
                   total2=0, summary=summary_lines(r, lang), tables=names,
                   xlsx=f"{r.stem}_synthesis.xlsx", name=r.stem,
                   title1=t("web.synth.results.table1", phi0=r.phi0), title2="",
                   toml=f"{r.stem}_synth.toml", toml_label=t("web.synth.results.toml"),
                   command=command_line(inputs_from_spec(run.spec)[0], lang),
                   figures=[f"{r.stem}_{f}.png" for f in FIGURES
                            if r.design is not None or f != "transmission_angle"])
        if r.design is not None:
            mech = f"{r.stem}_mechanism.csv"
            out["head2"], out["rows2"] = table_rows(tables[mech])
            out["total2"] = len(tables[mech])
            out["title2"] = t("web.synth.results.mechanism")
        if r.spec is not None:
            out["linkage_spec"] = f"{r.stem}.toml"
        return out
