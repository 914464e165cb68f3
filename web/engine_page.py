"""The engine page: Table 2, the summary, every diagram, the workbook (``crankdyn engine``).

Its :class:`EnginePage` validates and computes through the library (:func:`engine.load`,
:func:`engine.run_study`) and writes through it (:func:`engine.write_report`); the
pressure may come from an uploaded file, kept by the server under its own name.
"""
from __future__ import annotations

from .pages import Kind, Run, finish_files, table_rows

__all__ = ["EXAMPLES", "EnginePage", "PRESSURE_NAMES", "FIGURE_FORMAT", "pressure_name"]

#: The bundled examples by short name (the same as ``crankdyn engine --example NAME``).
EXAMPLES = {"petrol": "petrol_vaz2106.toml", "diesel": "diesel_d240.toml",
            "six": "petrol_bmw_m54.toml", "v8": "diesel_kamaz740.toml",
            "torsion": "torsion_inline6.toml"}
#: The server's own names of an uploaded pressure file (a CSV, or a Diesel-RK export).
PRESSURE_NAMES = ("pressure.csv", "pressure.ind")
#: The figures are written (and shown) as PNG.
FIGURE_FORMAT = "png"


def pressure_name(upload_name: str, spec_file: str | None = None) -> str:
    """The server's name for an uploaded pressure file: a Diesel-RK export when the
    upload or the spec names an ``.ind`` file, else a CSV (only this choice is taken from
    the names; the names themselves never reach the file system)."""
    names = [n for n in (upload_name, spec_file) if isinstance(n, str)]
    return PRESSURE_NAMES[1] if any(n.lower().endswith(".ind") for n in names) \
        else PRESSURE_NAMES[0]


class EnginePage(Kind):
    name = "engine"
    nav_key = "web.nav.engine"
    title_key, intro_key = "web.engine.title", "web.engine.intro"
    results_template = "engine_results.html"
    options_template = "engine_options.html"
    examples = EXAMPLES
    example_prefix = "web.example."
    has_pressure = True
    extra_fields = ("pressure.file",)

    def schema(self):
        from engine.schema import SCHEMA

        return SCHEMA

    def example_spec(self, name):
        from crankbase.resources import example_path

        data, _ = super().example_spec(name)
        pr = data.get("pressure", {})
        pressure = None
        if "file" in pr:
            pressure = (pressure_name(pr["file"]), example_path(pr["file"]).read_bytes())
        return data, pressure

    def options(self, values):
        return {"bearings": values.pop("bearings", "") == "on",
                "drawing": values.pop("drawing", "") == "on",
                "torsion": values.pop("torsion", "") == "on"}

    def spec_options(self, data, options):
        """A loaded spec with a ``[torsion]`` table has its torsional vibration (as
        ``crankdyn engine`` computes it): the option is shown on."""
        return dict(options, torsion=isinstance(data.get("torsion"), dict))

    def form_spec(self, data, options):
        """The option "torsional vibration" off leaves the form's ``[torsion]`` fields
        out of the spec (kept on the form, not computed); on, the spec is computed as
        ``crankdyn engine SPEC --torsion`` does (without the table: its problem)."""
        if not options.get("torsion"):
            data.pop("torsion", None)
        return data

    def compute(self, data, input_dir, pressure, options):
        """Validate ``data`` (:func:`engine.load`; the pressure file, if any, written into
        ``input_dir`` first under its server name) and compute the whole report
        (:func:`engine.run_study`).  Raises the library's
        :class:`~crankbase.errors.SpecError` with every problem."""
        import engine

        input_dir.mkdir(parents=True, exist_ok=True)
        if pressure is not None:
            (input_dir / pressure[0]).write_bytes(pressure[1])
        study = engine.load(data, base_dir=input_dir)
        return engine.run_study(study, bearings=options.get("bearings", False),
                                torsion=options.get("torsion", False))

    def write(self, run: Run) -> dict:
        """The report (:func:`engine.write_report`, PNG figures), its spec and zip."""
        import engine

        report = run.report
        written = engine.write_report(report, run.folder / "report", run.lang,
                                      formats=(FIGURE_FORMAT,),
                                      drawing=run.options.get("drawing", False))
        return finish_files(run, report.name, {p.name: p for p in written})

    def results(self, run, lang, files=None):
        from crankbase.texts import texts

        t = texts(lang)
        r = run.report
        head, rows = table_rows(r.tables["forces.csv"])
        head2, rows2 = table_rows(r.tables["table2.csv"])
        out = dict(head=head, rows=rows, head2=head2, rows2=rows2,
                   total=len(r.tables["forces.csv"]), total2=len(r.tables["table2.csv"]),
                   form=r.study.settings.form, summary=r.summary_lines(lang),
                   figures=[f"{r.name}_{p}.{FIGURE_FORMAT}" for p in r.plot_names],
                   tables=[r.file_names[n] for n in r.tables], xlsx=f"{r.name}.xlsx",
                   name=r.name, title1=t("web.results.table2"),
                   title2=t("web.results.table2_form", form=r.study.settings.form),
                   toml_label=t("web.results.toml"))
        v = r.torsion
        if v is not None:               # [torsion]: the files `crankdyn engine` writes
            head3, rows3 = table_rows(v.tables["torsion_modes.csv"])
            names = v.file_names
            out.update(head3=head3, rows3=rows3, total3=len(v.tables["torsion_modes.csv"]),
                       title3=t("web.results.torsion_modes"),
                       xlsx2=f"{v.name}_torsion.xlsx",
                       xlsx2_label=t("web.results.torsion_workbook"))
            out["tables"] += [names[n] for n in v.tables]
            out["figures"] += [f"{names[p]}.{FIGURE_FORMAT}" for p in v.plot_names]
        return out
