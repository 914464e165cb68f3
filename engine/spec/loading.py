"""Read an engine spec file: every table once, through the schema, every problem at once.

:func:`load` reads the keys by their description in :mod:`engine.schema` (type, unit,
range, default: :class:`crankbase.schema.SpecReader`), adds the checks that join several
keys, and returns an :class:`~engine.spec.model.EngineStudy`: the physics, the report
settings, the crank train and the bearing inputs.
"""
from __future__ import annotations

from pathlib import Path

from crankbase.errors import Text
from crankbase.schema import SpecReader
from crankbase.validation import read_toml, rows_problem

from ..indicator import CycleSpec, PressureTable
from ..schema import (BALANCE, COUNTERWEIGHT, CYCLE, ENGINE, FLYWHEEL, MASS_WAYS, MASSES,
                      PRESSURE, PRESSURE_UNITS, SCHEMA, TABLE)
from .cycle import check_rounded_peak, read_cycle
from .inputs import read_tables
from .model import (Counterweight, CrankTrain, EngineSpec, EngineSpecError, EngineStudy,
                    TableSettings, loaded)
from .pressure import inline_pressure, read_pressure_csv
from .torsion_inputs import read_torsion

__all__ = ["load", "load_spec"]


def load(path_or_dict, base_dir=None) -> EngineStudy:
    """Read and validate an engine spec file; return everything it holds.

    Parameters
    ----------
    path_or_dict : str, Path or dict
        A TOML file, or the same content as a dict.
    base_dir : str or Path, optional
        Folder against which ``[pressure] file`` is resolved when a dict is given
        (default: the current folder).  For a file, its own folder is used.

    Returns
    -------
    EngineStudy
        ``spec`` (:class:`EngineSpec`), ``settings`` (:class:`TableSettings`), ``train``
        (:class:`CrankTrain`), ``bearings`` (the ``[bearings]`` and ``[rod]`` inputs,
        :class:`~engine.spec.inputs.BearingInputs`) and ``torsion`` (the ``[torsion]``
        inputs, :class:`~engine.spec.torsion_inputs.TorsionInputs`, None without it).

    Raises
    ------
    EngineSpecError
        Listing *every* problem, each with its key path (or CSV file and row).

    Notes
    -----
    Every key, its unit, range and default: the README's spec reference (rendered from
    :mod:`engine.schema`).  Checks that join keys: exactly one of ``rod_ratio`` and
    ``rod_length_mm`` (> stroke/2), |e| < Lш − R; ``[masses]`` given exactly one way
    (mj and mш.к; or the parts mп and mш, split by ``rod_small_end_fraction`` [1]_; or
    the parts per unit piston area); ``[pressure]`` exactly one source (inline
    ``angle_deg`` with one of ``p_MPa``, ``p_bar``, ``p_kPa``, ``p_Pa``; a CSV or
    Diesel-RK ``.ind`` ``file``; or ``[pressure.cycle]``); the table's rows at most
    :data:`~crankbase.validation.MAX_ROWS`; a firing order a permutation of the
    cylinders.

    References
    ----------
    .. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей.
       4-е изд. М.: Высшая школа, 2008.
    """
    data, file_dir = read_toml(path_or_dict)
    if not isinstance(path_or_dict, dict):
        base = file_dir
        source_path = Path(path_or_dict).resolve()
    else:
        base = Path(base_dir) if base_dir is not None else Path.cwd()
        source_path = None
    c = SpecReader()
    c.top(data, SCHEMA)

    # ---- [engine]
    e = c.sub(data, ENGINE)

    def eng(key, **kw):
        return c.get(e, ENGINE, key, **kw)

    name = eng("name")
    strokes = eng("strokes")
    cylinders = eng("cylinders")
    bore = eng("bore_mm")
    stroke = eng("stroke_mm")
    speed = eng("speed_rpm")
    p0 = eng("crankcase_MPa")
    accel = eng("acceleration")
    eps_engine = eng("compression_ratio")
    offset = eng("pin_offset_mm")
    has_ratio, has_len = "rod_ratio" in e, "rod_length_mm" in e
    lam = L_mm = None
    if has_ratio and has_len:
        c.add("engine.rod_ratio", Text("errors.engine.loading.give_either_rod"))
    elif not has_ratio and not has_len:
        c.add("engine.rod_ratio", Text("errors.engine.loading.missing_give_rod"))
    elif has_ratio:
        lam = eng("rod_ratio", required=True)
    else:
        L_mm = eng("rod_length_mm", required=True)
        if L_mm is not None and stroke is not None and not L_mm > stroke / 2:
            c.add("engine.rod_length_mm",
                  Text("errors.engine.loading.crank_radius_stroke",
                       {"L_mm": L_mm, "stroke": stroke / 2}))
            L_mm = None
    if offset and stroke is not None and (lam is not None or L_mm is not None):
        span = (L_mm if L_mm is not None else stroke / 2 / lam) - stroke / 2
        if not abs(offset) < span:
            c.add("engine.pin_offset_mm", Text("errors.engine.loading.e_l_r",
                                               {"offset": offset, "span": span}))

    # ---- [masses]
    m = c.sub(data, MASSES)
    masses = {}
    groups = [g for g in MASS_WAYS.values() if any(k in m for k in g)]
    if "masses" in data and isinstance(m, dict):
        if not groups:
            c.add("masses", Text("errors.engine.loading.no_masses_given"))
        elif len(groups) > 1:
            c.add("masses", Text("errors.engine.loading.give_masses_one",
                                 {"items": " / ".join(" + ".join(g) for g in groups)}))
    frac = c.get(m, MASSES, "rod_small_end_fraction")
    masses["crank_rotating_kg"] = c.get(m, MASSES, "crank_rotating_kg")
    if len(groups) == 1:
        g = groups[0]
        for k in g:
            masses[k] = c.get(m, MASSES, k, required=True)
        if g is MASS_WAYS["direct"] and "rod_small_end_fraction" in m:
            c.add("masses.rod_small_end_fraction",
                  Text("errors.engine.loading.only_used_with_3"))

    # ---- [pressure]
    pr = c.sub(data, PRESSURE)
    sources = []
    if "angle_deg" in pr or any(k in pr for k in PRESSURE_UNITS):
        sources.append("inline")
    if "file" in pr:
        sources.append("file")
    if "cycle" in pr:
        sources.append("cycle")
    cycle_deg = 720.0 if strokes == 4 else 360.0
    pressure = None
    if "pressure" in data and isinstance(pr, dict):
        if not sources:
            c.add("pressure", Text("errors.engine.loading.no_pressure_source"))
        elif len(sources) > 1:
            c.add("pressure", Text("errors.engine.loading.give_exactly_one",
                                   {"items": " and ".join(sources)}))
    fname = pr.get("file") if isinstance(pr, dict) else None
    if "firing_tdc_deg" in pr and not (isinstance(fname, str)
                                       and fname.lower().endswith(".ind")):
        c.add("pressure.firing_tdc_deg", Text("errors.engine.loading.only_used_with"))
    if sources == ["inline"]:
        angle, p = inline_pressure(c, pr, cycle_deg)
        if angle is not None:
            pressure = PressureTable(tuple(angle.tolist()), tuple(p.tolist()))
    elif sources == ["file"]:
        fname = c.get(pr, PRESSURE, "file", required=True)
        if fname is not None:
            pfile = (base / fname) if not Path(fname).is_absolute() else Path(fname)
            if not pfile.is_file():
                c.add("pressure.file", Text("errors.engine.loading.file_does_not",
                                            {"value": str(pfile)}))
            elif pfile.suffix.lower() == ".ind":          # Diesel-RK export
                from ..dieselrk import read_ind
                angle, p = read_ind(pfile, cycle_deg, c.get(pr, PRESSURE, "firing_tdc_deg"),
                                    c)
                if angle is not None:
                    pressure = PressureTable(tuple(angle.tolist()), tuple(p.tolist()),
                                             pfile.resolve())
            else:
                pressure = read_pressure_csv(pfile, cycle_deg, c)
    elif sources == ["cycle"]:
        pressure = read_cycle(c, c.sub(pr, CYCLE, required=True), strokes)

    if isinstance(pressure, CycleSpec) and eps_engine is not None \
            and eps_engine != pressure.compression_ratio:
        c.add("engine.compression_ratio",
              Text("errors.engine.loading.but_pressure_cycle",
                   {"eps_engine": eps_engine, "compression_ratio": pressure.compression_ratio}))

    # ---- [table]
    t = c.sub(data, TABLE)
    step = c.get(t, TABLE, "step_deg", le=cycle_deg)
    extra = c.get(t, TABLE, "extra_angles_deg")
    if step is not None:     # rows of the table: every step over the cycle, its end, extras
        too_many = rows_problem(cycle_deg / step + 1 + len(extra or []), "table.step_deg")
        if too_many:
            c.problems.append(too_many)
    for i, x in enumerate(extra or []):
        if x > cycle_deg:
            c.add(f"table.extra_angles_deg[{i}]", Text("errors.engine.loading.message",
                                                       {"x": x, "cycle_deg": cycle_deg}))
    mu = c.get(t, TABLE, "force_scale_N_per_mm")
    form = c.get(t, TABLE, "form")

    train = _crank_train(c, data, e, cylinders)
    torsion = read_torsion(c, data, strokes)  # [torsion]: None without the table

    if isinstance(pressure, CycleSpec) and pressure.rounding and not c.problems:
        check_rounded_peak(c, pressure, lam if lam is not None else stroke / 2.0 / L_mm,
                           offset / (stroke / 2.0))
    if c.problems:
        read_tables(c, data)                 # [bearings], [rod]: their own problems too
        c.raise_if_any(EngineSpecError)

    with loaded():                           # checked above: validate once
        spec = EngineSpec(
            name=name.strip(), strokes=int(strokes), cylinders=int(cylinders),
            bore=ENGINE.key("bore_mm").to_si(bore), stroke=ENGINE.key("stroke_mm").to_si(stroke),
            rod_ratio=lam, rod_length=ENGINE.key("rod_length_mm").to_si(L_mm),
            speed_rpm=speed, p0=ENGINE.key("crankcase_MPa").to_si(p0), acceleration=accel,
            compression_ratio=eps_engine, pin_offset=ENGINE.key("pin_offset_mm").to_si(offset),
            pressure=pressure, source_path=source_path, rod_small_end_fraction=frac,
            **masses)
        settings = TableSettings(step_deg=step,
                                 extra_angles_deg=tuple(sorted(set(extra or []))),
                                 force_scale=mu, form=form or "seed")
    bearings = read_tables(c, data, spec)
    c.raise_if_any(EngineSpecError)
    return EngineStudy(spec, settings, train, bearings, torsion)


def _crank_train(c, data, e, cylinders):
    """The crank train of ``[engine]``, ``[flywheel]`` and ``[balance]`` (None on a
    problem, which is recorded in ``c``)."""
    n0 = len(c.problems)

    def eng(key, **kw):
        return c.get(e, ENGINE, key, **kw)

    arr = eng("arrangement")
    vee = eng("vee_angle_deg")
    if arr == "vee" and "vee_angle_deg" not in e:
        c.add("engine.vee_angle_deg", Text("errors.engine.loading.missing_vee_needs"))
    elif arr != "vee" and "vee_angle_deg" in e:
        c.add("engine.vee_angle_deg", Text("errors.engine.loading.only_used_with_4"))
    order = eng("firing_order")
    if order is not None:
        if any(x != int(x) for x in order):
            c.add("engine.firing_order", Text("errors.engine.loading.cylinder_numbers_whole",
                                              {"order": order}))
            order = None
        else:
            order = tuple(int(x) for x in order)
            n = cylinders or 0               # at most MAX_CYLINDERS (the schema's bound)
            if sorted(order) != list(range(1, n + 1)):
                c.add("engine.firing_order",
                      Text("errors.engine.loading.permutation_cylinders_each",
                           {"value": list(order), "n": n}))
    spacing = eng("cylinder_spacing_mm")
    boff = eng("bank_offset_mm")
    if "bank_offset_mm" in e and arr == "inline":
        c.add("engine.bank_offset_mm", Text("errors.engine.loading.only_used_with_2"))
    positions = eng("cylinder_positions_mm")
    if positions is not None and spacing is not None:
        c.add("engine.cylinder_positions_mm", Text("errors.engine.loading.give_cylinder_spacing"))
    throws = eng("throw_angles_deg")
    eta = eng("mechanical_efficiency")
    fw = c.sub(data, FLYWHEEL)
    delta = c.get(fw, FLYWHEEL, "delta")
    share = c.get(fw, FLYWHEEL, "share")
    dia = c.get(fw, FLYWHEEL, "mean_diameter_mm", si=True)
    bal = c.sub(data, BALANCE)
    design = c.get(bal, BALANCE, "counterweights")
    cws = []
    for where, cw in c.rows(bal, COUNTERWEIGHT):
        z, mr, ang = (c.get(cw, COUNTERWEIGHT, k, path=where, si=True)
                      for k in ("z_mm", "mr_kg_mm", "angle_deg"))
        if None not in (z, mr, ang):
            cws.append(Counterweight(z, mr, ang))
    if cws and "counterweights" in bal and design != "none":
        c.add("balance.counterweights", Text("errors.engine.loading.give_design_or"))
    if len(c.problems) > n0:
        return None
    with loaded():
        return CrankTrain(
            arrangement=arr, vee_angle_deg=vee, firing_order=order,
            cylinder_spacing=ENGINE.key("cylinder_spacing_mm").to_si(spacing),
            bank_offset=ENGINE.key("bank_offset_mm").to_si(boff),
            cylinder_positions=None if positions is None
            else tuple(ENGINE.key("cylinder_positions_mm").to_si(positions)),
            throw_angles_deg=None if throws is None else tuple(throws),
            mechanical_efficiency=eta, delta=delta, flywheel_share=share,
            flywheel_diameter=dia, counterweights=design, counterweight_list=tuple(cws))


def load_spec(path_or_dict, base_dir=None) -> EngineSpec:
    """Read and validate an engine spec; return its :class:`EngineSpec` (the physics).

    The whole file is validated (see :func:`load`, which also returns the report
    settings, the crank train and the bearing inputs).
    """
    return load(path_or_dict, base_dir).spec
