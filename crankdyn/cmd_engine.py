"""``crankdyn engine``: the engine force table (Table 2), its workbook and plots.

    crankdyn engine SPEC.toml -o DIR [--lang ru|en] [--step DEG] [--form seed|kolchin]
                                     [--bearings] [--drawing]
    crankdyn engine --example [NAME] -o DIR
    crankdyn engine SPEC.toml --variants variants.csv|xlsx -o DIR [--jobs N]

Writes ``DIR/<name>_forces.csv``, ``DIR/<name>_table2.csv``, the whole-engine tables
``DIR/<name>_cylinders.csv``, ``_torque.csv``, ``_balance.csv`` (and the bearing tables
with --bearings), ``DIR/<name>.xlsx`` and the plots ``DIR/<name>_<plot>.png|svg``
(``<name>``: the engine's name as a file stem, so that two engines in one folder never
mix) after everything has been validated and computed, all at once through a staging
folder; bad input writes nothing.  Heavy libraries
are imported inside :func:`run` only, so ``crankdyn --help`` stays fast.
"""
from __future__ import annotations

#: Bundled examples by short name (``--example NAME``; a file stem works too).
EXAMPLES = {"petrol": "petrol_vaz2106.toml", "diesel": "diesel_d240.toml",
            "six": "petrol_bmw_m54.toml", "v8": "diesel_kamaz740.toml"}


def add_parser(subparsers):
    p = subparsers.add_parser(
        "engine", help="engine force table (Table 2), Excel report and plots",
        description="Engine crank-slider forces over the crank angle (ΔPг, Pj, P, β, N, "
                    "Sш, K, T, Mкр, Kr.ш, Rшш, Ψ): forces.csv, an Excel report from a "
                    "template and the plots (indicator diagram, forces, torque, polar and "
                    "developed crank-pin load diagrams).")
    p.add_argument("spec", nargs="?", metavar="SPEC.toml", help="engine spec (TOML)")
    p.add_argument("--example", nargs="?", const="petrol", metavar="NAME",
                   help="run a bundled example instead of a spec: "
                        + ", ".join(EXAMPLES) + " (default petrol)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if needed)")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="report and plot language (default ru, the textbook symbols)")
    p.add_argument("--step", type=float, metavar="DEG",
                   help="table step in crank degrees (overrides [table] step_deg)")
    p.add_argument("--bearings", action="store_true",
                   help="also the bearing loads: crank pin, main journals, journal torques, "
                        "big end and piston pin, wear diagrams (crankpins.csv, journals.csv, "
                        "journal_torques.csv, rod_bearings.csv, wear.csv, rod_model.csv with "
                        "[rod] model = \"rigid\", and their plots); implied by a [bearings] "
                        "or [rod] table in the spec")
    p.add_argument("--form", choices=("seed", "kolchin"),
                   help="Table 2 (<name>_table2.csv) in the seed's form (forces in mm and N) "
                        "or Kolchin's (specific forces in MPa with the coefficients tg β, "
                        "1/cos β, cos(α+β)/cos β, sin(α+β)/cos β); overrides [table] form")
    p.add_argument("--drawing", action="store_true",
                   help="also write the diagrams at the drawing scale (forces over α, N/K/T, "
                        "polar), 1:1 PDF on millimetre paper: axes in mm of the drawing, "
                        "μP from the spec, μα = cycle/240 mm")
    p.add_argument("--variants", metavar="TABLE",
                   help="course variants: a CSV or .xlsx table with a 'variant' (or "
                        "'name') column and one column per spec key as a dotted path "
                        "(engine.bore_mm, masses.rod_kg, …) overriding the base spec "
                        "(SPEC.toml or --example); writes one complete report per variant "
                        "in DIR/<variant>/ and DIR/variants_summary.csv|xlsx; bad rows are "
                        "reported by row and key and skipped; exit status 1 if any failed")
    p.add_argument("--jobs", type=int, default=1, metavar="N",
                   help="with --variants: write N reports at a time (processes; default 1)")
    p.set_defaults(func=run)


def _example_path(name):
    from .examples import find_example
    return find_example(name, EXAMPLES, "engine")


def run(args) -> int:
    from pathlib import Path

    from crankbase.errors import SpecError

    if args.spec and args.example:
        raise SpecError("give either SPEC.toml or --example, not both")
    if not args.spec and not args.example:
        raise SpecError("give an engine spec SPEC.toml or --example [NAME]")
    spec_path = Path(args.spec) if args.spec else _example_path(args.example)
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise SpecError(f"-o: {out} exists and is not a folder")
    if args.jobs < 1:
        raise SpecError(f"--jobs: got {args.jobs}; must be a whole number >= 1")
    if getattr(args, "variants", None):
        from .variants_cli import run_variants
        return run_variants(args, spec_path, out)

    import engine

    study = with_options(engine.load(spec_path), args.step, args.form)
    lines = report(study, spec_path, out, args.lang, inputs=[spec_path],
                   bearings=args.bearings, drawing=args.drawing)["lines"]
    print("\n".join(lines))
    return 0


def with_options(study, step=None, form=None):
    """The study with the command line's ``--step`` and ``--form`` applied to its
    :class:`~engine.TableSettings` (presentation only; the physics is untouched)."""
    from dataclasses import replace

    settings = study.settings
    if step is not None:
        from crankbase.validation import step_argument

        spec = study.spec
        rows = spec.cycle_deg + len(settings.extra_angles_deg) * step
        settings = replace(settings, step_deg=step_argument(step, "--step", spec.cycle_deg,
                                                             rows_span=rows))
    if form:
        settings = replace(settings, form=form)
    return replace(study, settings=settings)


def output_names(stem, names):
    """``{name: file name}`` of every output, named after the engine (``<stem>_<name>``),
    so that reports of two engines in one folder never mix."""
    return {n: f"{stem}_{n}" for n in names}


def report(study, spec_path, out, lang, inputs=(), bearings=False, drawing=False):
    """Compute the whole engine of ``study`` and write its complete report into ``out``:
    ``<name>_forces.csv``, ``<name>_table2.csv`` (Table 2 in the settings' form),
    ``<name>_cylinders.csv``, ``<name>_torque.csv``, ``<name>_balance.csv``, the bearing
    tables (``<name>_crankpins.csv`` …) when asked, ``<name>.xlsx``, the plots
    ``<name>_<plot>.png|svg`` and, with ``drawing``, the 1:1 drawing-scale PDFs
    ``<name>_drawing_*.pdf`` (``<name>``: the engine's name as a file stem), all through a
    staging folder.  Plots of this engine that this run does not draw are removed.

    Returns a dict: ``result`` (one cylinder), ``whole``, ``lines`` (terminal summary).
    """
    import engine
    from engine.drawing import DRAWING_NAMES, drawing_figures
    from engine.plots import PLOT_NAMES, TRAIN_PLOT_NAMES, figures, train_figures
    from engine.report import a4_setup, add_engine_sheets, build_workbook, save_workbook
    from engine.table2 import table2

    from crankbase.output import (check_not_input, ensure_finite, safe_name, save_figure,
                                  staged_output, write_csv)

    # 1. validate and compute everything
    spec, settings = study.spec, study.settings
    whole = engine.analyze_engine(spec, study.train, settings)
    result = whole.cylinder
    table = result.table
    ensure_finite(table, "force table")
    ensure_finite(result.curves, "force table (plot grid)")
    for df, what in ((whole.torque, "torque"), (whole.balance, "balance")):
        ensure_finite(df, what)
    name = safe_name(spec.name, "engine")
    csvs = {"forces.csv": table, "table2.csv": table2(table, spec, settings),
            "cylinders.csv": whole.layout.cylinders, "torque.csv": whole.torque,
            "balance.csv": whole.balance}
    xlsx_path = out / f"{name}.xlsx"
    plot_names = list(PLOT_NAMES + TRAIN_PLOT_NAMES)
    from engine.bearing_spec import read_bearing_inputs
    b_inputs = read_bearing_inputs(spec_path, spec)
    bearing = _bearings(spec, table, result.curves, b_inputs, whole, lang) \
        if bearings or b_inputs.asked else None
    if bearing is not None:
        csvs.update(bearing["csv"])
        plot_names += list(bearing["figures"])
    files = output_names(name, list(csvs) + plot_names)
    pdfs = output_names(name, DRAWING_NAMES) if drawing else {}
    outputs = [xlsx_path] + [out / files[n] for n in csvs] + [
        out / f"{files[n]}.{e}" for n in plot_names for e in ("png", "svg")] + [
        out / f"{f}.pdf" for f in pdfs.values()]
    inputs = [*inputs, spec.pressure_file]
    check_not_input(outputs, inputs)
    wb = add_engine_sheets(build_workbook(result, lang), whole, lang)
    figs = figures(result, lang)
    figs.update(train_figures(whole, lang))
    if bearing is not None:
        from engine.bearing_plots import bearing_figures
        from engine.bearing_report import add_bearing_sheets
        figs.update(bearing_figures(bearing["analysis"], lang))
        add_bearing_sheets(wb, bearing["csv"], bearing["analysis"], lang)
    a4_setup(wb)
    if drawing:
        figs.update(drawing_figures(result, lang))

    # 2. write: every file into a staging folder, moved into DIR only when all are done;
    #    SVG text stays text (searchable, and a third cheaper to write than glyph paths)
    import matplotlib

    with staged_output(out, inputs=inputs, unit=name) as stage, \
            matplotlib.rc_context({"svg.fonttype": "none"}):
        for n, df in csvs.items():
            write_csv(df, stage / files[n])
        save_workbook(wb, stage / xlsx_path.name)
        for n in plot_names:
            save_figure(figs[n], stage / files[n])
        for n, f in pdfs.items():                      # 1:1, vector only
            save_figure(figs[n], stage / f, formats=("pdf",))
    for fig in figs.values():
        fig.clear()
    # plots of this engine from an earlier run that this run did not draw are stale
    from engine.bearing_plots import BEARING_PLOT_NAMES
    for n in set(BEARING_PLOT_NAMES + DRAWING_NAMES) - set(plot_names) - set(pdfs):
        for ext in ("png", "svg", "pdf"):
            path = out / f"{name}_{n}.{ext}"
            if path.exists():
                path.unlink()
    lines = summary_lines(result, whole, lang)
    if bearing is not None:
        lines += bearing["lines"]
    lines.append(("записано: " if lang == "ru" else "wrote ")
                 + ", ".join(files[n] for n in csvs) + f", {xlsx_path.name}, "
                 + f"{len(plot_names)} " + ("графиков (PNG, SVG) в " if lang == "ru"
                                              else "plots (PNG, SVG) in ") + str(out))
    return dict(result=result, whole=whole, lines=lines)


def summary_lines(result, whole, lang="en"):
    """The terminal summary of one run: the cylinder in ``lang`` (Russian textbook
    symbols for ru), then the whole engine."""
    spec, summary = result.spec, result.summary
    P, T, R = summary.P_N, summary.T_N, summary.R_N
    chi = (f"{summary.chi:.3f}" if summary.chi == summary.chi else
           ("не определено (средняя нагрузка 0)" if lang == "ru"
            else "undefined (the mean load is 0)"))
    if lang == "ru":
        lines = [
            f"{spec.name}: {spec.strokes}-тактный, D × S = {spec.bore * 1e3:g} × "
            f"{spec.stroke * 1e3:g} мм, λ = {spec.lam:.4f}, n = {spec.speed_rpm:g} мин⁻¹, "
            f"ускорение {'двучленное' if spec.acceleration == 'two-term' else 'точное'}",
            f"  pг max             {summary.p_max_MPa:10.3f} МПа  при α = "
            f"{summary.alpha_p_max_deg:g}°;  среднее индикаторное давление pi = "
            f"{summary.pi_MPa:.4f} МПа",
            f"  P max              {P.max:10.0f} Н    при α = {P.alpha_max_deg:g}°",
            f"  T max              {T.max:10.0f} Н    при α = {T.alpha_max_deg:g}°",
            f"  Mкр.ср             {summary.M_mean_Nm:10.2f} Н·м  (один цилиндр)",
            f"  Rшш max            {R.max:10.0f} Н    при α = {R.alpha_max_deg:g}°;"
            f"  Rшш.ср = {summary.R_mean_N:.0f} Н;  χ = {chi}",
        ]
    else:
        lines = [
            f"{spec.name}: {spec.strokes}-stroke, D x S = {spec.bore * 1e3:g} x "
            f"{spec.stroke * 1e3:g} mm, lambda = {spec.lam:.4f}, n = {spec.speed_rpm:g} rpm, "
            f"acceleration {spec.acceleration}",
            f"  peak gas pressure  {summary.p_max_MPa:10.3f} MPa  at alpha = "
            f"{summary.alpha_p_max_deg:g} deg;  indicated mean pressure pi = "
            f"{summary.pi_MPa:.4f} MPa",
            f"  P max              {P.max:10.0f} N    at alpha = {P.alpha_max_deg:g} deg",
            f"  T max              {T.max:10.0f} N    at alpha = {T.alpha_max_deg:g} deg",
            f"  M mean             {summary.M_mean_Nm:10.2f} N*m  (one cylinder)",
            f"  Rcp max            {R.max:10.0f} N    at alpha = {R.alpha_max_deg:g} deg;"
            f"  Rcp mean = {summary.R_mean_N:.0f} N;  chi = {chi}",
        ]
    return lines + whole_engine_lines(whole, lang)


#: Words of the terminal summary that depend on the language (the numbers do not).
_ARRANGEMENT_RU = {"inline": "рядный", "vee": "V-образный", "boxer": "оппозитный"}
_CRANKSHAFT_RU = {"given": "заданы",
                  "default for even firing": "по умолчанию для равномерного чередования"}
_ORDER = {"ru": {"1": "1-го порядка", "2": "2-го порядка", "r": "вращающиеся"},
          "en": {"1": "1st order", "2": "2nd order", "r": "rotating"}}


def whole_engine_lines(whole, lang="en"):
    """The terminal summary of the whole engine (total torque, its uniformity, the
    flywheel, the balance and counterweights) in ``lang``."""
    ws, lay = whole.summary, whole.layout
    ru = lang == "ru"
    order = "-".join(map(str, lay.firing_order))
    throws = ", ".join(f"{x:g}" for x in lay.throw_angles_deg)
    if ru:
        lines = [f"двигатель: {lay.n} цил., {_ARRANGEMENT_RU[whole.train.arrangement]}, "
                 f"порядок работы {order}, колена {throws}° "
                 f"({_CRANKSHAFT_RU[lay.crankshaft]})"
                 + ("" if lay.even_firing else ", неравномерное чередование"),
                 f"  суммарный Mкр      Mкр.ср = {ws.M_mean_Nm:.1f} Н·м, max "
                 f"{ws.M_max_Nm:.1f} при α = {ws.alpha_M_max_deg:g}°, min "
                 f"{ws.M_min_Nm:.1f} при α = {ws.alpha_M_min_deg:g}°;  μ = {ws.mu:.3f}",
                 f"  индикаторные       Mi = {ws.Mi_Nm:.1f} Н·м (Mкр.ср отличается на "
                 f"{ws.diff_pct:+.4f} %), Ni = {ws.Ni_kW:.2f} кВт"
                 + ("" if ws.Me_Nm is None else
                    f";  Me = {ws.Me_Nm:.1f} Н·м, Ne = {ws.Ne_kW:.2f} кВт"),
                 f"  избыточная работа  Lизб = {ws.L_excess_J:.1f} Дж"
                 + ("" if ws.flywheel is None else
                    f";  J0 = {ws.flywheel.J0_kgm2:.4f} кг·м² (δ = {ws.flywheel.delta:g}), "
                    f"маховой момент m·D² = {ws.flywheel.mD2_kgm2:.4f} кг·м²")]
    else:
        lines = [f"whole engine: {lay.n} cylinders {whole.train.arrangement}, firing order "
                 f"{order}, throws {throws} deg ({lay.crankshaft})"
                 + ("" if lay.even_firing else ", uneven firing"),
                 f"  total torque       mean {ws.M_mean_Nm:.1f} N*m, max {ws.M_max_Nm:.1f} "
                 f"at {ws.alpha_M_max_deg:g} deg, min {ws.M_min_Nm:.1f} at "
                 f"{ws.alpha_M_min_deg:g} deg;  mu = {ws.mu:.3f}",
                 f"  indicated          Mi = {ws.Mi_Nm:.1f} N*m (mean differs by "
                 f"{ws.diff_pct:+.4f} %), Ni = {ws.Ni_kW:.2f} kW"
                 + ("" if ws.Me_Nm is None else
                    f";  Me = {ws.Me_Nm:.1f} N*m, Ne = {ws.Ne_kW:.2f} kW"),
                 f"  excess work        L = {ws.L_excess_J:.1f} J"
                 + ("" if ws.flywheel is None else
                    f";  J0 = {ws.flywheel.J0_kgm2:.4f} kg*m^2 (delta = "
                    f"{ws.flywheel.delta:g}), flywheel m*D^2 = "
                    f"{ws.flywheel.mD2_kgm2:.4f} kg*m^2")]
    amp = whole.balance_amplitudes.set_index("part")
    unbalanced = ", ".join(_ORDER[lang][p] for p in ("1", "2", "r")
                           if not (amp.loc[p, "F_balanced"] and amp.loc[p, "M_balanced"]))
    F, M, n_cw = amp.loc["after", "F_max_N"], amp.loc["after", "M_max_Nm"], \
        len(ws.counterweights)
    fw = ws.flywheel if ws.flywheel is not None and ws.flywheel.mass_kg is not None \
        else None
    if ru:
        lines.append(f"  уравновешенность   свободная сила max {F:.1f} Н, свободный момент "
                     f"max {M:.1f} Н·м, противовесов {n_cw}; без них не уравновешены: "
                     + (unbalanced or "нет"))
        if fw is not None:
            lines.append(f"  маховик            Jм = {fw.J_flywheel_kgm2:.4f} кг·м² "
                         f"({fw.share:g} от J0): D обода = {fw.diameter_m * 1e3:g} мм, "
                         f"m = {fw.mass_kg:.2f} кг, окружная скорость обода "
                         f"{fw.rim_speed_m_s:.1f} м/с")
        lines += [f"  противовес         m·r = {cw.mr * 1e3:9.2f} кг·мм под углом "
                  f"{cw.angle_deg:6.1f}° от колена 1, z = {cw.z * 1e3:7.1f} мм"
                  for cw in ws.counterweights]
    else:
        lines.append(f"  balance            free force max {F:.1f} N, free moment max "
                     f"{M:.1f} N*m with {n_cw} counterweights; unbalanced before them: "
                     + (unbalanced or "none"))
        if fw is not None:
            lines.append(f"  flywheel           J = {fw.J_flywheel_kgm2:.4f} kg*m^2 "
                         f"({fw.share:g} of J0): rim D = {fw.diameter_m * 1e3:g} mm, "
                         f"m = {fw.mass_kg:.2f} kg, rim speed {fw.rim_speed_m_s:.1f} m/s")
        lines += [f"  counterweight      m*r = {cw.mr * 1e3:9.2f} kg*mm at "
                  f"{cw.angle_deg:6.1f} deg from throw 1, z = {cw.z * 1e3:7.1f} mm"
                  for cw in ws.counterweights]
    return lines


def _bearings(spec, table, fine, inputs, whole, lang):
    """Bearing loads: one cylinder by its spec ([bearings] journal positions and
    counterweight), a whole engine by its layout and counterweights.  CSVs at the table
    rows; plots, wear diagrams and the summary lines from the fine grid."""
    from crankbase.output import ensure_finite
    from engine.bearing_spec import bearing_analysis, wear_table

    lay = whole.layout
    if lay.n == 1:
        rows = bearing_analysis(spec, table, inputs)
        res = bearing_analysis(spec, fine, inputs)
    else:
        from engine.train_bearings import engine_bearings, layout_cylinders

        cyl, tau, zt = layout_cylinders(lay)
        cw = [(c.z, c.mr, c.angle_deg) for c in whole.summary.counterweights]

        def run(theta):
            return engine_bearings(spec, theta, cyl, tau, zt, counterweights=cw,
                                   inputs=inputs)
        rows, res = run(table["alpha_deg"].to_numpy()), run(fine["alpha_deg"].to_numpy())
    rb = rows.rod_bearings
    if rows.m_piston is None:                       # piston mass unknown: big end only
        rb = rb.drop(columns=["Pp_axial_N", "Pp_side_N", "Pp_N"])
    pin_wear = res.pin_wear if isinstance(res.pin_wear, list) else [res.pin_wear]
    csv = {"crankpins.csv": rows.loads.crankpins, "journals.csv": rows.loads.journals,
           "journal_torques.csv": rows.loads.journal_torques, "rod_bearings.csv": rb,
           "wear.csv": wear_table(pin_wear + res.journal_wear)}
    if rows.rod_comparison is not None:
        csv["rod_model.csv"] = rows.rod_comparison.table
    for name, df in csv.items():
        ensure_finite(df, name)
    lines = bearing_lines(res, pin_wear, lang)
    return dict(analysis=res, csv=csv, figures=list(_figure_names(res)), lines=lines)


def bearing_lines(res, pin_wear, lang="en"):
    """The terminal summary of a bearing analysis ``res`` (its crank-pin wear diagrams
    ``pin_wear``) in ``lang``."""
    from engine.bearing_spec import NOTE_NO_PISTON_MASS

    L = res.loads
    kp, jm, jt = L.most_loaded_pin, L.most_loaded_journal, L.most_twisted_journal
    ps, js, ts = L.pin_stats[kp - 1], L.journal_stats[jm - 1], L.torque_stats[jt - 1]
    pin_holes = ", ".join(f"{w.oil_hole_deg:g}" for w in pin_wear)
    journal_holes = ", ".join(f"{w.oil_hole_deg:g}" for w in res.journal_wear)
    half = res.options.wear_half_angle_deg
    ext = None if res.rod_comparison is None else res.rod_comparison.extremes
    if lang == "ru":
        lines = [
            f"  шатунные шейки     наиболее нагружена {kp}-я: Rшш max {ps.max_N:.0f} Н при "
            f"α = {ps.alpha_max_deg:g}°, Rшш.ср {ps.mean_N:.0f} Н, χ = {ps.chi:.3f}; "
            f"масляные отверстия под углом {pin_holes}° (от оси кривошипа)",
            f"  коренные шейки     наиболее нагружена {jm}-я: Rк.ш max {js.max_N:.0f} Н, "
            f"Rк.ш.ср {js.mean_N:.0f} Н, χ = {js.chi:.3f}; масляные отверстия под углом "
            f"{journal_holes}°",
            f"  моменты на шейках  наибольший размах у {jt}-й коренной шейки: max "
            f"{ts['max_Nm']:.1f}, min {ts['min_Nm']:.1f} Н·м (последняя передаёт "
            f"суммарный Mкр); дуги износа ±{half:g}°"]
        if ext is not None:
            lines.append(
                f"  жёсткий шатун      ΔT {ext['dT_N'][2]:+.1f}…{ext['dT_N'][0]:+.1f} Н, ΔMкр "
                f"{ext['dM_Nm'][2]:+.2f}…{ext['dM_Nm'][0]:+.2f} Н·м, ΔRшш "
                f"{ext['dR_N'][2]:+.1f}…{ext['dR_N'][0]:+.1f} Н против двухмассовой модели")
        notes = {NOTE_NO_PISTON_MASS: "нагрузка на поршневой палец не вычислена: задайте "
                 "массы по частям (piston_group_kg, rod_kg) или [rod] mass_kg"}
        lines += [f"  примечание: {notes.get(n, n)}" for n in res.notes]
        return lines
    lines = [
        f"  crank pins         most loaded: {kp} (max {ps.max_N:.0f} N at alpha = "
        f"{ps.alpha_max_deg:g} deg; mean {ps.mean_N:.0f} N; chi = {ps.chi:.3f}); oil holes "
        f"at {pin_holes} deg (crank frame)",
        f"  main journals      most loaded: {jm} (max {js.max_N:.0f} N, mean "
        f"{js.mean_N:.0f} N, chi = {js.chi:.3f}); oil holes at {journal_holes} deg",
        f"  journal torques    largest swing: journal {jt} (max {ts['max_Nm']:.1f}, min "
        f"{ts['min_Nm']:.1f} N*m); the last carries the total; wear arcs +/-{half:g} deg"]
    if ext is not None:
        lines.append(
            f"  rigid rod          dT {ext['dT_N'][2]:+.1f}...{ext['dT_N'][0]:+.1f} N, dM "
            f"{ext['dM_Nm'][2]:+.2f}...{ext['dM_Nm'][0]:+.2f} N*m, dR "
            f"{ext['dR_N'][2]:+.1f}...{ext['dR_N'][0]:+.1f} N against the two-mass rod")
    return lines + [f"  note: {n}" for n in res.notes]


def _figure_names(res):
    from engine.bearing_plots import BEARING_PLOT_NAMES
    for name in BEARING_PLOT_NAMES:
        if name == "piston_pin" and res.rod_bearings["Pp_N"].isna().all():
            continue
        if name == "rod_model" and res.rod_comparison is None:
            continue
        yield name
