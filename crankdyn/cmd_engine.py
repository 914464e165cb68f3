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

    import math
    from dataclasses import replace

    import engine
    from engine.plots import PLOT_NAMES, TRAIN_PLOT_NAMES, figures, train_figures
    from engine.report import add_engine_sheets, build_workbook, save_workbook

    from crankbase.errors import Problem
    from crankbase.output import (check_not_input, ensure_finite, safe_name, save_figure,
                                  staged_output, write_csv)

    # 1. validate and compute everything
    study = engine.load(spec_path)
    spec, settings = study.spec, study.settings
    if args.step is not None:
        if not (math.isfinite(args.step) and 0 < args.step <= spec.cycle_deg):
            raise SpecError(Problem("--step", f"got {args.step!r}; must be > 0 and "
                                              f"<= {spec.cycle_deg:g}"))
        settings = replace(settings, step_deg=float(args.step))
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
    outputs = [csv_path, xlsx_path] + [out / n for n in csvs] + [
        s.with_suffix(f".{e}") for s in stems for e in ("png", "svg")]
    check_not_input(outputs, [spec_path, spec.pressure_file])
    wb = add_engine_sheets(build_workbook(result, args.lang), whole, args.lang)
    figs = figures(result, args.lang)
    figs.update(train_figures(whole, args.lang))

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
        f"  mean {summary.R_mean_N:.0f} N;  chi = {summary.chi:.3f}",
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
    lines.append(f"wrote {csv_path} ({len(table)} rows), cylinders.csv, torque.csv, "
                 f"balance.csv, {xlsx_path}, {len(stems)} plots (PNG, SVG) in {out}"
                 + (" [ru]" if ru else " [en]"))
    print("\n".join(lines))
    return 0
