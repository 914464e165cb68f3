"""The torsional-vibration study as one library call: build the chain, compute, write.

pvlib's ``ModelChain`` pattern, as :mod:`engine.study`: :func:`load` reads a spec file
(an engine spec with ``[torsion]``, or a file with only ``name`` and a by-hand
``[torsion]`` chain), :func:`build_chain` turns the ``[torsion]`` inputs and the engine's
crank train into the lumped-mass chain (names, J, k, which mass carries which throw),
:func:`run_study` computes everything into a frozen :class:`TorsionReport` (nothing drawn,
nothing written) and :func:`write_report` writes its CSVs, workbook and figures as one unit
(:func:`crankbase.output.staged_output`).  The physics is :mod:`torsion.chain`,
:mod:`torsion.harmonics`, :mod:`torsion.response` and :mod:`torsion.engine_chain`; this
module only composes them.

Conventions: masses numbered 1 … n from the free (front) end to the load, section i
joins masses i and i + 1; a throw's mass is named ``throw<N>``; SI inside, degrees in
the columns that say ``_deg``.

Examples
--------
>>> from crankbase.resources import example_path
>>> from torsion.study import load, run_study
>>> report = run_study(load(example_path("torsion_three_rotor.toml")))
>>> [round(float(f), 2) for f in report.modes.f_Hz]   # Khurmi & Gupta: 171 and 277 Hz
[170.69, 277.03]
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.output import FIGURE_FORMATS    # the formats write_report takes

__all__ = ["TorsionStudy", "Chain", "TorsionReport", "TorsionFiles", "load", "build_chain",
           "run_study", "write_report", "TABLE_NAMES", "FIGURE_FORMATS"]

#: The report's CSVs by short name (the file is ``<name>_<short name>``), in the order
#: written; a free-vibration report has the first two only.
TABLE_NAMES = ("torsion_modes.csv", "holzer.csv", "torque_harmonics.csv",
               "critical_speeds.csv", "torsion_response.csv")


@dataclass(frozen=True)
class TorsionStudy:
    """What :func:`load` returns: the report's ``name``, the ``[torsion]`` ``inputs``
    (:class:`~engine.spec.torsion_inputs.TorsionInputs`), the ``engine`` study around
    them (an :class:`~engine.EngineStudy`, None for a chain on its own) and the
    ``source`` file."""

    name: str
    inputs: object
    engine: object = None
    source: Path | None = None


@dataclass(frozen=True)
class Chain:
    """The lumped-mass chain, from the free end to the load.

    Attributes
    ----------
    names : tuple of str
        Mass names (``damper``, ``throw1`` … ``flywheel``; by hand ``names``, else ``1``
        … ``n``).
    J : ndarray (n,)
        Moments of inertia [kg·m²].
    k : ndarray (n − 1,)
        Section stiffnesses [N·m/rad].
    throw_J : ndarray (n,)
        Of each throw's mass, the parts of its J: own crank, rod's rotating part,
        reciprocating mean (zeros for other masses), [kg·m²]; None by hand.
    cylinder_mass : ndarray of int or None
        The 0-based mass index of each cylinder's throw (None: no excitation).
    phases_deg : ndarray or None
        Each cylinder's phase φ_j (:func:`engine.train.layout`).
    diameters : ndarray (n − 1,) or None
        Section diameters [m].
    dampers : dict
        {0-based mass index: c [N·m·s/rad]}.
    throw_number : tuple of int
        The throw (1-based) each mass carries, 0 for none (all 0 without excitation).
    """

    names: tuple
    J: np.ndarray
    k: np.ndarray
    throw_J: object = None
    cylinder_mass: object = None
    phases_deg: object = None
    diameters: object = None
    dampers: Mapping = field(default_factory=lambda: MappingProxyType({}))
    throw_number: tuple = ()

    @property
    def n(self) -> int:
        return len(self.names)

    @property
    def section_names(self) -> tuple:
        """``<mass i>-<mass i+1>`` of every section."""
        return tuple(f"{a}-{b}" for a, b in zip(self.names[:-1], self.names[1:]))

    @property
    def excited(self) -> bool:
        """The chain carries throws and an engine drives them."""
        return self.cylinder_mass is not None

    def table(self):
        """The chain as a DataFrame: ``mass``, ``J_kgm2``, ``k_Nm_rad`` (of the section
        after it, NaN on the last), ``throw`` (1-based, 0: none)."""
        import pandas as pd

        throw = np.asarray(self.throw_number or (0,) * self.n, int)
        return pd.DataFrame({"mass": list(self.names), "J_kgm2": self.J,
                             "k_Nm_rad": np.append(self.k, np.nan), "throw": throw})


def load(path_or_dict, base_dir=None) -> TorsionStudy:
    """Read a spec with a ``[torsion]`` table.

    An engine spec (it has ``[engine]``) is read whole by :func:`engine.load` (its
    ``study.torsion``); a file with only ``name`` and ``[torsion]`` (a chain given by
    hand: ``inertias_kgm2``, ``stiffnesses_Nm_rad``) is read through the same schema
    entries (:data:`engine.schema.TORSION`, :func:`engine.spec.torsion_inputs.read_torsion`).

    Raises
    ------
    SpecError
        Every problem of the file, each with its key; a file without ``[torsion]``.
    """
    from crankbase.schema import SpecReader
    from crankbase.validation import read_toml

    data, _ = read_toml(path_or_dict)
    source = None if isinstance(path_or_dict, dict) else Path(path_or_dict).resolve()
    if isinstance(data, dict) and "engine" in data:
        from engine.spec.loading import load as load_engine

        study = load_engine(path_or_dict, base_dir)
        if study.torsion is None:
            raise SpecError([Problem("torsion", Text("torsion.error.no_table"))])
        return TorsionStudy(study.spec.name, study.torsion, study, source)
    from engine.schema import TORSION_SCHEMA
    from engine.spec.torsion_inputs import read_torsion

    c = SpecReader()
    c.top(data, TORSION_SCHEMA)
    name = c.name(data, "name", "", default="torsion")
    if "torsion" not in data:
        c.add("torsion", Text("torsion.error.no_table"))
    inputs = read_torsion(c, data)
    if inputs is not None and not inputs.by_hand:
        c.add("torsion.throw_J_kgm2", Text("torsion.error.needs_engine"))
    c.raise_if_any(SpecError)
    return TorsionStudy(name, inputs, None, source)


def _throw_place(value, throws):
    return 1 if value == "first" else throws if value == "last" else int(value)


def build_chain(inputs, spec=None, lay=None) -> Chain:
    """The chain of the ``[torsion]`` inputs, with the engine's ``spec`` and layout
    ``lay`` (:func:`engine.train.layout`) when there is an engine around it.

    Beside the throws: every throw of the layout is a mass ``throw<N>`` of J =
    :func:`torsion.engine_chain.throw_inertia` (its own crank ``throw_J_kgm2`` + the rods'
    rotating parts + the reciprocating means of its cylinders); the extra masses go
    before/after the throws they name, in the file's order.  By hand: the masses as given;
    ``throws`` maps them onto the engine's throws (the engine must have exactly that many).

    Raises
    ------
    SpecError
        A stiffness count that does not match the masses, a throw number the engine does
        not have, a damper at a mass that does not exist, a diameter count that does not
        match the sections, a by-hand ``throws`` list that does not cover the engine's
        throws.
    """
    c_problems = []

    def bad(key, text_key, **fields):
        c_problems.append(Problem(key, Text(text_key, fields)))

    cyl_throw = phases = None
    throw_J = None
    if lay is not None:
        from .engine_chain import cylinder_throws

        cyl_throw, phases = cylinder_throws(lay)
        cyl_throw = np.asarray(cyl_throw, int)
        phases = np.asarray(phases, float)
    if not inputs.by_hand:
        if lay is None:
            raise SpecError([Problem("torsion.throw_J_kgm2",
                                     Text("torsion.error.needs_engine"))])
        from .engine_chain import throw_inertia

        T = int(cyl_throw.max()) + 1
        per_throw = np.bincount(cyl_throw, minlength=T)
        before = {t: [] for t in range(1, T + 1)}
        after = {t: [] for t in range(1, T + 1)}
        for i, m in enumerate(inputs.masses):
            t = _throw_place(m.throw, T)
            if not 1 <= t <= T:
                bad(f"torsion.masses[{i}].{m.side}", "torsion.error.no_such_throw",
                    value=m.throw, throws=T)
                continue
            (before if m.side == "before" else after)[t].append(m)
        if c_problems:                 # a mass left out would miscount the stiffnesses
            raise SpecError(c_problems)
        names, J, tJ, mass_of_throw = [], [], [], {}
        for t in range(1, T + 1):
            for m in before[t]:
                names.append(m.name)
                J.append(m.J)
                tJ.append(0.0)
            mass_of_throw[t - 1] = len(names)
            names.append(f"throw{t}")
            Jt = throw_inertia(spec, inputs.throw_J, int(per_throw[t - 1]))
            J.append(Jt)
            tJ.append(Jt)
            for m in after[t]:
                names.append(m.name)
                J.append(m.J)
                tJ.append(0.0)
        cylinder_mass = np.array([mass_of_throw[int(t)] for t in cyl_throw], int)
        throw_J = np.asarray(tJ, float)
        throw_number = [0] * len(names)
        for t, m in mass_of_throw.items():
            throw_number[m] = t + 1
    else:
        names = list(inputs.names or (str(i) for i in range(1, len(inputs.inertias) + 1)))
        J = list(inputs.inertias)
        cylinder_mass = None
        throw_number = [0] * len(names)
        throws = inputs.throws or ()
        used = [x for x in throws if x]
        if used and lay is not None:
            T = int(cyl_throw.max()) + 1
            if len(used) != T:
                bad("torsion.throws", "torsion.error.throws_engine", n=len(used), throws=T)
            else:
                mass_of_throw = {t - 1: i for i, t in enumerate(throws) if t}
                cylinder_mass = np.array([mass_of_throw[int(t)] for t in cyl_throw], int)
                throw_number = list(throws)
    n = len(names)
    k = np.asarray(inputs.stiffnesses, float)
    if len(k) != n - 1:
        bad("torsion.stiffnesses_Nm_rad", "torsion.error.stiffness_count",
            k=len(k), n=n, need=n - 1)
    d = None
    if inputs.shaft_diameters is not None:
        d = np.asarray(inputs.shaft_diameters, float)
        if len(d) != n - 1:
            bad("torsion.shaft_diameters_mm", "torsion.error.diameter_count",
                d=len(d), need=n - 1)
    dampers = {}
    for i, (at, cv) in enumerate(inputs.dampers):
        if at not in names and inputs.by_hand and at.isdigit() and 1 <= int(at) <= n:
            at = names[int(at) - 1]            # a by-hand mass by its number 1 … n
        if at not in names:
            bad(f"torsion.dampers[{i}].at", "torsion.error.no_such_mass", name=at,
                names=", ".join(repr(n) for n in names))
        else:
            dampers[names.index(at)] = dampers.get(names.index(at), 0.0) + cv
    if c_problems:
        raise SpecError(c_problems)
    return Chain(tuple(names), np.asarray(J, float), k, throw_J,
                 cylinder_mass, phases if cylinder_mass is not None else None, d,
                 MappingProxyType(dampers), tuple(int(x) for x in throw_number))


@dataclass(frozen=True)
class TorsionReport:
    """Everything a torsional-vibration report holds, computed, nothing written.

    Attributes
    ----------
    name : str
        The file stem (:func:`crankbase.output.safe_name` of the spec's name).
    study : TorsionStudy
    chain : Chain
    modes : torsion.results.Modes
        Natural frequencies (elastic modes, ascending), shapes, nodes; the rigid mode
        apart.
    holzer : pandas.DataFrame
        The Holzer tables at every natural frequency, then at the trial frequencies.
    harmonics : dict or None
        {"gas", "inertia", "total"}: :class:`torsion.harmonics.Harmonics` of one cylinder's
        torque at ``speed_ref_rpm`` (None for free vibration).
    critical : pandas.DataFrame or None
    response : torsion.response.Response or None
    speed_ref_rpm : float or None
        The engine speed of the harmonics (the spec's ``speed_rpm``).
    tables : Mapping of str to pandas.DataFrame
        Every CSV by short name (:data:`TABLE_NAMES`), in the order written.
    plot_names : tuple of str
    notes : tuple of Text
        What the report says of its own scope (free vibration only …).
    """

    name: str
    study: TorsionStudy
    chain: Chain
    modes: object
    holzer: object
    harmonics: object
    critical: object
    response: object
    speed_ref_rpm: float | None
    tables: Mapping
    plot_names: tuple
    notes: tuple = ()

    @property
    def free_only(self) -> bool:
        return self.response is None

    @property
    def source(self):
        return self.study.source

    @property
    def file_names(self) -> dict:
        return {n: f"{self.name}_{n}" for n in list(self.tables) + list(self.plot_names)}

    def summary_lines(self, lang: str = "ru", written=None) -> list[str]:
        """The terminal summary in ``lang`` (:func:`torsion.summary.summary_lines`)."""
        from .summary import summary_lines

        return summary_lines(self, lang, written)


def harmonics_table(harmonics):
    """``<name>_torque_harmonics.csv``: ``part`` (gas, inertia, total), then the
    :meth:`Harmonics.table` columns ``order, a_Nm, b_Nm, amplitude_Nm, phase_deg``."""
    import pandas as pd

    frames = []
    for part in ("gas", "inertia", "total"):
        df = harmonics[part].table().copy()
        df.insert(0, "part", part)
        frames.append(df)
    return pd.concat(frames, ignore_index=True)


def _speeds(inputs):
    lo, hi = inputs.speed_range_rpm
    n = int(np.floor((hi - lo) / inputs.speed_step_rpm + 1e-9))
    s = lo + inputs.speed_step_rpm * np.arange(n + 1)
    return s if s[-1] >= hi - 1e-9 else np.append(s, hi)


def run_study(study, *, source=None) -> TorsionReport:
    """Compute a torsional-vibration report: the chain's natural modes and Holzer tables
    and, with an engine driving the throws, the harmonics of one cylinder's torque, the
    critical speeds and the forced response over the speed range.

    Parameters
    ----------
    study : TorsionStudy, engine.EngineStudy, or str, Path or dict
        From :func:`load` (or an engine study with ``[torsion]``; a spec file or dict is
        loaded first).

    Returns
    -------
    TorsionReport

    Raises
    ------
    SpecError
        The chain does not fit the engine (:func:`build_chain`), or no ``[torsion]``; a
        chain with throws but no ``speed_range_rpm``.
    """
    from crankbase.output import ensure_finite, safe_name

    from .chain import damping_matrix, holzer_table, natural_modes

    if not isinstance(study, TorsionStudy):
        if hasattr(study, "spec") and hasattr(study, "torsion"):      # an EngineStudy
            if study.torsion is None:
                raise SpecError([Problem("torsion", Text("torsion.error.no_table"))])
            study = TorsionStudy(study.spec.name, study.torsion, study,
                                 Path(source) if isinstance(source, (str, Path)) else None)
        else:
            study = load(study)
    inputs, es = study.inputs, study.engine
    spec = lay = None
    if es is not None:
        from engine.train import layout

        spec = es.spec
        lay = layout(spec, es.train)
    chain = build_chain(inputs, spec, lay)
    notes = []
    if chain.excited and inputs.speed_range_rpm is None:
        raise SpecError([Problem("torsion.speed_range_rpm",
                                 Text("torsion.error.speed_range_missing"))])
    modes = natural_modes(chain.J, chain.k)
    omegas = list(np.asarray(modes.omega_rad_s, float)) + list(inputs.holzer_trial_rad_s)
    holzer = holzer_table(chain.J, chain.k, np.asarray(omegas), names=list(chain.names))
    tables = {"torsion_modes.csv": modes.table(list(chain.names)), "holzer.csv": holzer}
    harmonics = critical = response = None
    speed_ref = None
    if chain.excited:
        from .engine_chain import cylinder_excitation
        from .response import critical_speeds, forced_response

        speed_ref = float(spec.speed_rpm)
        harmonics = cylinder_excitation(spec, es.settings, orders_max=inputs.orders_max)
        orders = np.asarray(harmonics["total"].order, float)
        orders = orders[orders > 0]
        critical = critical_speeds(modes, chain.cylinder_mass, chain.phases_deg, orders,
                                   inputs.speed_range_rpm, spec.cylinders, spec.cycle_deg)
        C = damping_matrix(chain.J, modes, inputs.damping_ratio, dict(chain.dampers))
        response = forced_response(chain.J, chain.k, C, chain.cylinder_mass,
                                   chain.phases_deg, harmonics["gas"], harmonics["inertia"],
                                   speed_ref, _speeds(inputs), chain.diameters)
        tables["torque_harmonics.csv"] = harmonics_table(harmonics)
        tables["critical_speeds.csv"] = critical
        tables["torsion_response.csv"] = response.table(list(chain.names))
    elif es is None:
        notes.append(Text("torsion.note.no_engine"))
    else:
        notes.append(Text("torsion.note.no_throws"))
    for n, df in tables.items():
        ensure_finite(df.select_dtypes("number").replace(np.nan, 0.0) if n == "holzer.csv"
                      else df.select_dtypes("number"), n)
    from .plots import TORSION_PLOT_NAMES

    plots = TORSION_PLOT_NAMES if response is not None else ("torsion_modes",)
    return TorsionReport(name=safe_name(study.name, "torsion"), study=study, chain=chain,
                         modes=modes, holzer=holzer, harmonics=harmonics, critical=critical,
                         response=response, speed_ref_rpm=speed_ref,
                         tables=MappingProxyType(tables),
                         plot_names=tuple(plots),
                         notes=tuple(notes))


@dataclass(frozen=True)
class TorsionFiles:
    """The files :func:`write_report` wrote (iterating gives every path, in order)."""

    folder: Path
    tables: tuple
    workbook: Path
    plots: tuple
    plot_count: int
    formats: tuple

    @property
    def paths(self) -> tuple:
        return (*self.tables, self.workbook, *self.plots)

    def __iter__(self):
        return iter(self.paths)

    def __len__(self):
        return len(self.paths)


def output_paths(report: TorsionReport, out, formats=("png", "svg")) -> dict:
    """``{"tables": …, "workbook": …, "plots": …}``: the paths :func:`write_report` (or
    an engine report with ``[torsion]``) writes into ``out``."""
    out = Path(out)
    files = report.file_names
    return {"tables": tuple(out / files[n] for n in report.tables),
            "workbook": out / f"{report.name}_torsion.xlsx",
            "plots": tuple(out / f"{files[n]}.{e}" for n in report.plot_names
                           for e in formats)}


def build_outputs(report: TorsionReport, lang="ru"):
    """The workbook and the figures of ``report`` built in memory: ``(workbook, {plot
    name: Figure})`` (an engine report with ``[torsion]`` writes them with its own)."""
    from .plots import torsion_figures
    from .report import build_workbook

    figs = torsion_figures(report.modes, report.critical, report.harmonics,
                           report.response, list(report.chain.names),
                           report.study.inputs.speed_range_rpm, lang,
                           report.chain.phases_deg)
    return build_workbook(report, lang), {n: figs[n] for n in report.plot_names}


def write_into(stage, report: TorsionReport, wb, figs, formats) -> None:
    """Write the built outputs of ``report`` into an open staging folder ``stage``."""
    from crankbase.output import save_figure, write_csv
    from crankbase.workbook import save

    files = report.file_names
    for n, df in report.tables.items():
        write_csv(df, stage / files[n])
    save(wb, stage / f"{report.name}_torsion.xlsx")
    for n in report.plot_names:
        save_figure(figs[n], stage / files[n], formats=formats)


def write_report(report: TorsionReport, out, lang: str = "ru", formats=("png", "svg"),
                 inputs=()) -> TorsionFiles:
    """Write a torsional-vibration report into the folder ``out`` as one unit:
    ``<name>_<table>`` for every CSV of :data:`TABLE_NAMES` the report has,
    ``<name>_torsion.xlsx`` and the figures ``<name>_<plot>.<format>``, through a staging
    folder (:func:`crankbase.output.staged_output`): all or nothing, never over an input.

    Raises
    ------
    SpecError
        A bad ``lang`` or ``formats``.
    OutputError
        An output would overwrite an input, or the folder cannot be written.
    """
    import matplotlib

    from crankbase.output import check_not_input, figure_formats, output_folder, staged_output
    from crankbase.validation import check_lang

    check_lang(lang)
    formats = figure_formats(formats)
    out = output_folder(out)
    paths = output_paths(report, out, formats)
    inputs = [*inputs, *([report.source] if report.source is not None else [])]
    check_not_input([paths["workbook"], *paths["tables"], *paths["plots"]], inputs)
    wb, figs = build_outputs(report, lang)
    with staged_output(out, inputs=inputs, unit=report.name) as stage, \
            matplotlib.rc_context({"svg.fonttype": "none"}):
        write_into(stage, report, wb, figs, formats)
    return TorsionFiles(folder=out, tables=paths["tables"], workbook=paths["workbook"],
                        plots=paths["plots"], plot_count=len(report.plot_names),
                        formats=formats)
