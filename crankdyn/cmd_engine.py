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
EXAMPLES = {"petrol": "petrol_vaz2106.toml", "diesel": "diesel_d240.toml"}


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

    import math
    from dataclasses import replace

    import engine
    from engine.plots import PLOT_NAMES, figures
    from engine.report import build_workbook, save_workbook

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
    result = engine.analyze(spec, settings)
    table = result.table
    ensure_finite(table, "force table")
    ensure_finite(result.curves, "force table (plot grid)")
    summary = result.summary
    csv_path = out / "forces.csv"
    xlsx_path = out / f"{safe_name(spec.name, 'engine')}.xlsx"
    stems = [out / name for name in PLOT_NAMES]
    from engine.bearing_spec import read_bearing_inputs
    inputs = read_bearing_inputs(spec_path, spec)
    bearing = _bearings(spec, table, result.curves, inputs) \
        if args.bearings or inputs.asked else None
    extra_csv = {} if bearing is None else bearing["csv"]
    stems += [] if bearing is None else [out / name for name in bearing["figures"]]
    outputs = [csv_path, xlsx_path] + [out / n for n in extra_csv] + [
        s.with_suffix(f".{e}") for s in stems for e in ("png", "svg")]
    check_not_input(outputs, [spec_path, spec.pressure_file])
    wb = build_workbook(result, args.lang)
    figs = figures(result, args.lang)
    if bearing is not None:
        from engine.bearing_plots import bearing_figures
        figs.update(bearing_figures(bearing["analysis"], args.lang))

    # 2. write: every file into a staging folder, moved into DIR only when all are done
    with staged_output(out, inputs=[spec_path, spec.pressure_file]) as stage:
        write_csv(table, stage / csv_path.name)
        for name, df in extra_csv.items():
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
        f"wrote {csv_path} ({len(table)} rows), {xlsx_path}, "
        f"{len(stems)} plots (PNG, SVG) in {out}" + (" [ru]" if ru else " [en]"),
    ]
    if bearing is not None:
        lines[-1:-1] = bearing["lines"]
    print("\n".join(lines))
    return 0


def _bearings(spec, table, fine, inputs):
    """Bearing loads of the one-cylinder spec: CSVs at the table rows, plots, the wear
    diagrams and the summary lines from the fine grid."""
    from crankbase.output import ensure_finite
    from engine.bearing_spec import bearing_analysis, wear_table

    rows = bearing_analysis(spec, table, inputs)
    res = bearing_analysis(spec, fine, inputs)
    rb = rows.rod_bearings
    if rows.m_piston is None:                       # piston mass unknown: big end only
        rb = rb.drop(columns=["Pp_axial_N", "Pp_side_N", "Pp_N"])
    csv = {"crankpins.csv": rows.loads.crankpins, "journals.csv": rows.loads.journals,
           "journal_torques.csv": rows.loads.journal_torques, "rod_bearings.csv": rb,
           "wear.csv": wear_table([res.pin_wear] + res.journal_wear)}
    if rows.rod_comparison is not None:
        csv["rod_model.csv"] = rows.rod_comparison.table
    for name, df in csv.items():
        ensure_finite(df, name)
    ls, js = res.loads.pin_stats[0], res.loads.journal_stats
    jm = res.loads.most_loaded_journal
    lines = [
        f"  crank pin          max {ls.max_N:8.0f} N at alpha = {ls.alpha_max_deg:g} deg; "
        f"mean {ls.mean_N:.0f} N; chi = {ls.chi:.3f}; oil hole at "
        f"{res.pin_wear.oil_hole_deg:g} deg (crank frame)",
        f"  main journals      most loaded: {jm} (max {js[jm - 1].max_N:.0f} N, mean "
        f"{js[jm - 1].mean_N:.0f} N); oil holes at "
        + ", ".join(f"{w.oil_hole_deg:g}" for w in res.journal_wear) + " deg",
        f"  journal torque     last journal max {res.loads.torque_stats[-1]['max_Nm']:.1f}, "
        f"min {res.loads.torque_stats[-1]['min_Nm']:.1f} N*m; wear arcs +/-"
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
