"""``crankdyn engine``: the engine force table (Table 2), its workbook and plots.

    crankdyn engine SPEC.toml -o DIR [--lang ru|en] [--step DEG]
    crankdyn engine --example [NAME] -o DIR

Writes ``DIR/forces.csv``, ``DIR/<name>.xlsx`` and the plots (PNG and SVG) after
everything has been validated and computed, all at once through a staging folder; bad
input writes nothing.  Heavy libraries
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
    p.set_defaults(func=run)


def _example_path(name):
    from crankbase.errors import SpecError

    from crankbase.resources import example_path

    stems = {f[:-5]: f for f in EXAMPLES.values()}
    stem = name[:-5] if name.endswith(".toml") else name
    fname = EXAMPLES.get(stem) or stems.get(stem)
    if fname is None:
        raise SpecError(f"--example: no engine example {name!r}; available: "
                        + ", ".join(list(EXAMPLES) + list(stems)))
    return example_path(fname)


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

    from dataclasses import replace

    import engine
    from engine.plots import PLOT_NAMES, TRAIN_PLOT_NAMES, figures, train_figures
    from engine.report import add_engine_sheets, build_workbook, save_workbook

    from crankbase.output import (check_not_input, ensure_finite, safe_name, save_figure,
                                  staged_output, write_csv)

    # 1. validate and compute everything
    study = engine.load(spec_path)
    spec, settings = study.spec, study.settings
    if args.step is not None:
        from crankbase.validation import step_argument

        rows = spec.cycle_deg + len(settings.extra_angles_deg) * args.step
        step = step_argument(args.step, "--step", spec.cycle_deg, rows_span=rows)
        settings = replace(settings, step_deg=step)
    whole = engine.analyze_engine(spec, study.train, settings)
    result = whole.cylinder
    table = result.table
    ensure_finite(table, "force table")
    ensure_finite(result.curves, "force table (plot grid)")
    summary = result.summary
    for df, what in ((whole.torque, "torque"), (whole.balance, "balance")):
        ensure_finite(df, what)
    csv_path = out / "forces.csv"
    csvs = {"cylinders.csv": whole.layout.cylinders, "torque.csv": whole.torque,
            "balance.csv": whole.balance}
    xlsx_path = out / f"{safe_name(spec.name, 'engine')}.xlsx"
    stems = [out / name for name in PLOT_NAMES + TRAIN_PLOT_NAMES]
    from engine.bearing_spec import read_bearing_inputs
    inputs = read_bearing_inputs(spec_path, spec)
    bearing = _bearings(spec, table, result.curves, inputs, whole) \
        if args.bearings or inputs.asked else None
    if bearing is not None:
        csvs.update(bearing["csv"])
        stems += [out / name for name in bearing["figures"]]
    outputs = [csv_path, xlsx_path] + [out / n for n in csvs] + [
        s.with_suffix(f".{e}") for s in stems for e in ("png", "svg")]
    check_not_input(outputs, [spec_path, spec.pressure_file])
    wb = add_engine_sheets(build_workbook(result, args.lang), whole, args.lang)
    figs = figures(result, args.lang)
    figs.update(train_figures(whole, args.lang))
    if bearing is not None:
        from engine.bearing_plots import bearing_figures
        from engine.bearing_report import add_bearing_sheets
        figs.update(bearing_figures(bearing["analysis"], args.lang))
        add_bearing_sheets(wb, bearing["csv"], bearing["analysis"], args.lang)

    # 2. write: every file into a staging folder, moved into DIR only when all are done;
    #    SVG text stays text (searchable, and a third cheaper to write than glyph paths)
    import matplotlib

    with staged_output(out, inputs=[spec_path, spec.pressure_file]) as stage, \
            matplotlib.rc_context({"svg.fonttype": "none"}):
        write_csv(table, stage / csv_path.name)
        for name, df in csvs.items():
            write_csv(df, stage / name)
        save_workbook(wb, stage / xlsx_path.name)
        for stem in stems:
            save_figure(figs[stem.name], stage / stem.name)

    # 3. terminal summary
    ru = args.lang == "ru"
    P, T, R = summary.P_N, summary.T_N, summary.R_N
    lines = [
        f"{spec.name}: {spec.strokes}-stroke, D x S = {spec.bore * 1e3:g} x "
        f"{spec.stroke * 1e3:g} mm, lambda = {spec.lam:.4f}, n = {spec.speed_rpm:g} rpm, "
        f"acceleration {spec.acceleration}",
        f"  peak gas pressure  {summary.p_max_MPa:10.3f} MPa  at alpha = "
        f"{summary.alpha_p_max_deg:g} deg;  indicated mean pressure pi = "
        f"{summary.pi_MPa:.4f} MPa",
        f"  P max              {P.max:10.0f} N    at alpha = {P.alpha_max_deg:g} deg",
        f"  T max              {T.max:10.0f} N    at alpha = {T.alpha_max_deg:g} deg",
        f"  mean torque        {summary.M_mean_Nm:10.2f} N*m  (one cylinder)",
        f"  R_crank-pin max    {R.max:10.0f} N    at alpha = {R.alpha_max_deg:g} deg;"
        f"  mean {summary.R_mean_N:.0f} N;  chi = "
        + (f"{summary.chi:.3f}" if summary.chi == summary.chi else "undefined "
           "(the mean load is 0)"),
    ]
    ws = whole.summary
    lay = whole.layout
    lines += [
        f"whole engine: {lay.n} cylinders {whole.train.arrangement}, firing order "
        f"{'-'.join(map(str, lay.firing_order))}, throws "
        f"{', '.join(f'{x:g}' for x in lay.throw_angles_deg)} deg ({lay.crankshaft})"
        + ("" if lay.even_firing else ", uneven firing"),
        f"  total torque       mean {ws.M_mean_Nm:.1f} N*m, max {ws.M_max_Nm:.1f} at "
        f"{ws.alpha_M_max_deg:g} deg, min {ws.M_min_Nm:.1f} at {ws.alpha_M_min_deg:g} deg;"
        f"  mu = {ws.mu:.3f}",
        f"  indicated          Mi = {ws.Mi_Nm:.1f} N*m (mean differs by {ws.diff_pct:+.4f} %),"
        f" Ni = {ws.Ni_kW:.2f} kW"
        + ("" if ws.Me_Nm is None else f";  Me = {ws.Me_Nm:.1f} N*m, Ne = {ws.Ne_kW:.2f} kW"),
        f"  excess work        L = {ws.L_excess_J:.1f} J"
        + ("" if ws.flywheel is None else
           f";  J0 = {ws.flywheel.J0_kgm2:.4f} kg*m^2 (delta = {ws.flywheel.delta:g}), "
           f"flywheel m*D^2 = {ws.flywheel.mD2_kgm2:.4f} kg*m^2"),
    ]
    amp = whole.balance_amplitudes.set_index("part")
    unbalanced = [p for p in ("1", "2", "r") if not (amp.loc[p, "F_balanced"]
                                                    and amp.loc[p, "M_balanced"])]
    lines.append(f"  balance            free force max {amp.loc['after', 'F_max_N']:.1f} N, "
                 f"free moment max {amp.loc['after', 'M_max_Nm']:.1f} N*m with "
                 f"{len(ws.counterweights)} counterweights; unbalanced before them: "
                 + (", ".join({"1": "1st order", "2": "2nd order", "r": "rotating"}[p]
                              for p in unbalanced) or "none"))
    if ws.flywheel is not None and ws.flywheel.mass_kg is not None:
        lines.append(f"  flywheel           J = {ws.flywheel.J_flywheel_kgm2:.4f} kg*m^2 "
                     f"({ws.flywheel.share:g} of J0): rim D = "
                     f"{ws.flywheel.diameter_m * 1e3:g} mm, m = {ws.flywheel.mass_kg:.2f} kg,"
                     f" rim speed {ws.flywheel.rim_speed_m_s:.1f} m/s")
    for cw in ws.counterweights:
        lines.append(f"  counterweight      m*r = {cw.mr * 1e3:9.2f} kg*mm at "
                     f"{cw.angle_deg:6.1f} deg from throw 1, z = {cw.z * 1e3:7.1f} mm")
    if bearing is not None:
        lines += bearing["lines"]
    lines.append(f"wrote {csv_path} ({len(table)} rows), cylinders.csv, torque.csv, "
                 f"balance.csv, {xlsx_path}, {len(stems)} plots (PNG, SVG) in {out}"
                 + (" [ru]" if ru else " [en]"))
    print("\n".join(lines))
    return 0


def _bearings(spec, table, fine, inputs, whole):
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
    L = res.loads
    kp, jm, jt = L.most_loaded_pin, L.most_loaded_journal, L.most_twisted_journal
    ps, js, ts = L.pin_stats[kp - 1], L.journal_stats[jm - 1], L.torque_stats[jt - 1]
    lines = [
        f"  crank pins         most loaded: {kp} (max {ps.max_N:.0f} N at alpha = "
        f"{ps.alpha_max_deg:g} deg; mean {ps.mean_N:.0f} N; chi = {ps.chi:.3f}); oil holes "
        "at " + ", ".join(f"{w.oil_hole_deg:g}" for w in pin_wear) + " deg (crank frame)",
        f"  main journals      most loaded: {jm} (max {js.max_N:.0f} N, mean "
        f"{js.mean_N:.0f} N, chi = {js.chi:.3f}); oil holes at "
        + ", ".join(f"{w.oil_hole_deg:g}" for w in res.journal_wear) + " deg",
        f"  journal torques    largest swing: journal {jt} (max {ts['max_Nm']:.1f}, min "
        f"{ts['min_Nm']:.1f} N*m); the last carries the total; wear arcs +/-"
        f"{res.options.wear_half_angle_deg:g} deg"]
    if res.rod_comparison is not None:
        ext = res.rod_comparison.extremes
        lines.append(
            f"  rigid rod          dT {ext['dT_N'][2]:+.1f}...{ext['dT_N'][0]:+.1f} N, dM "
            f"{ext['dM_Nm'][2]:+.2f}...{ext['dM_Nm'][0]:+.2f} N*m, dR "
            f"{ext['dR_N'][2]:+.1f}...{ext['dR_N'][0]:+.1f} N against the two-mass rod")
    lines += [f"  note: {n}" for n in res.notes]
    lines.append("  bearing tables: " + ", ".join(csv))
    return dict(analysis=res, csv=csv, figures=list(_figure_names(res)), lines=lines)


def _figure_names(res):
    from engine.bearing_plots import BEARING_PLOT_NAMES
    for name in BEARING_PLOT_NAMES:
        if name == "piston_pin" and res.rod_bearings["Pp_N"].isna().all():
            continue
        if name == "rod_model" and res.rod_comparison is None:
            continue
        yield name
