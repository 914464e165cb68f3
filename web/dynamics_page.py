"""The dynamics page: the true motion of a machine and its flywheel (``crankdyn dynamics``).

Three shapes of spec, as the command line reads them: a machine given by its reduced
quantities (``[machine]`` with its elements and moments, ``[dynamics]``: the seed's
flywheel example, the hoist), a linkage (a four-bar's or any chain's spec with
``[dynamics]``: the press, the shaper) or an engine spec with ``[dynamics]`` (the petrol
engine; an uploaded one with its pressure file).  The form follows the spec's kind
(:meth:`DynamicsPage.schema_for`: the linkage's, the chain's or the engine's schema plus
``[dynamics]``).  :class:`DynamicsPage` computes through :func:`dynamics.study.run_study`
and writes through :func:`dynamics.study.write_report`.
"""
from __future__ import annotations

from .pages import Kind, Run, table_rows, write_and_list

__all__ = ["EXAMPLES", "DynamicsPage", "spec_shape"]

#: The bundled machines (the same as ``crankdyn dynamics --example NAME``).
EXAMPLES = {"flywheel": "flywheel_seed.toml", "hoist": "hoist_machine.toml",
            "press": "press_dynamics.toml", "shaper": "shaper_dynamics.toml",
            "petrol": "petrol_dynamics.toml"}


def spec_shape(data: dict | None = None, values: dict | None = None) -> str:
    """``"machine"``, ``"linkage"``, ``"chain"`` or ``"engine"``: the shape of a spec
    dict ``data`` (as :func:`dynamics.spec.load_dynamics_spec` tells them: ``[engine]``
    first, then ``[machine]``, then ``[mechanism]``) or of the posted field texts
    ``values`` (the tables their fields' names start with)."""
    if values is not None and values:
        tops = {k.split(".", 1)[0] for k in values}
        if "engine" in tops:
            return "engine"
        if "machine" in tops:
            return "machine"
        if "mechanism" in tops:
            return "chain" if values.get("mechanism.kind") == "chain" else "linkage"
        return "machine"
    data = data or {}
    if "engine" in data:
        return "engine"
    if "machine" in data or "mechanism" not in data:
        return "machine"
    mech = data.get("mechanism")
    return "chain" if isinstance(mech, dict) and mech.get("kind") == "chain" else "linkage"


def _with_dynamics(schema):
    """``schema`` with the ``[dynamics]`` table after its own."""
    from crankbase.schema import Schema
    from dynamics.schema import DYNAMICS

    return Schema(schema.name, tuple(schema.tables) + (DYNAMICS,), schema.extra)


class DynamicsPage(Kind):
    name = "dynamics"
    nav_key = "web.nav.dynamics"
    title_key, intro_key = "web.dynamics.title", "web.dynamics.intro"
    examples = EXAMPLES
    example_prefix = "web.dynamics.example."
    has_pressure = True            # an engine spec's pressure file (a machine has none)
    extra_fields = ("pressure.file",)
    wait_for_files = True          # its figures depend on the machine: listed once drawn

    def schema(self):
        from dynamics.schema import SCHEMA

        return SCHEMA

    def schema_for(self, data=None, values=None):
        """The machine's schema; a linkage's, a chain's or an engine's with
        ``[dynamics]`` for a spec or form of that shape (:func:`spec_shape`)."""
        shape = spec_shape(data, values)
        if shape == "machine":
            return self.schema()
        if shape == "engine":
            from engine.schema import SCHEMA
        elif shape == "chain":
            from linkage.schema import CHAIN_SCHEMA as SCHEMA
        else:
            from linkage.schema import SCHEMA
        return _with_dynamics(SCHEMA)

    def example_spec(self, name):
        from crankbase.resources import example_path

        data, _ = super().example_spec(name)
        pr = data.get("pressure", {})
        pressure = None
        if isinstance(pr, dict) and "file" in pr:
            from .engine_page import pressure_name

            pressure = (pressure_name(pr["file"]), example_path(pr["file"]).read_bytes())
        return data, pressure

    def compute(self, data, input_dir, pressure, options):
        """Validate and compute (:func:`dynamics.study.run_study`).  An engine spec that
        reads a pressure file is run as the spec file written beside that file (under
        the server's names in ``input_dir``), as ``crankdyn dynamics SPEC.toml`` reads
        it; any other from the dict.  Raises the library's SpecError."""
        from dynamics.study import run_study

        pr = data.get("pressure") if isinstance(data, dict) else None
        if pressure is None or not (isinstance(pr, dict) and "file" in pr):
            return run_study(data)
        from .pages import spec_toml

        input_dir.mkdir(parents=True, exist_ok=True)
        (input_dir / pressure[0]).write_bytes(pressure[1])
        path = input_dir / "spec.toml"
        path.write_text(spec_toml(data), encoding="utf-8")
        return run_study(path)

    def write(self, run: Run) -> dict:
        from dynamics.study import write_report

        return write_and_list(run, write_report)

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
            key = {"forces_true_motion.csv": "web.dyn.results.forces",
                   "startup.csv": "web.dyn.results.startup"}.get(names[1][len(r.stem) + 1:])
            out["title2"] = t(key, file=names[1]) if key else names[1]
        return out
