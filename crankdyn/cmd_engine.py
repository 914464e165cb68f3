"""``crankdyn engine``: the engine force table (Table 2), its workbook and plots.

    crankdyn engine SPEC.toml -o DIR [--lang ru|en] [--step DEG] [--form seed|kolchin]
    crankdyn engine --example [NAME] -o DIR
    crankdyn engine SPEC.toml --variants variants.csv|xlsx -o DIR

Writes ``DIR/<name>_forces.csv``, ``DIR/<name>.xlsx``, the plots
``DIR/<name>_<plot>.png|svg`` and, with ``--drawing``, the diagrams at the drawing scale
``DIR/<name>_drawing_*.pdf`` (``<name>``: the engine's name as a file stem), so runs of
two engines into one folder never mix, after everything has been validated and computed,
all at once through a staging folder; bad input writes nothing.  Heavy libraries
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
    p.add_argument("--form", choices=("seed", "kolchin"),
                   help="Table 2 in the seed's form (forces in mm and N) or Kolchin's "
                        "(specific forces in MPa with the coefficients tg β, 1/cos β, "
                        "cos(α+β)/cos β, sin(α+β)/cos β); overrides [table] form")
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

    if args.jobs < 1:
        raise SpecError(f"--jobs: got {args.jobs}; must be a whole number >= 1")
    if getattr(args, "variants", None):
        from .variants_cli import run_variants
        return run_variants(args, spec_path, out)

    import engine

    spec = engine.load_spec(spec_path)
    if args.step is not None:
        spec = spec.with_step(args.step)
    if getattr(args, "form", None):
        from dataclasses import replace
        spec = replace(spec, table_form=args.form)
    table, summary, paths = report(spec, out, args.lang, inputs=[spec_path],
                                   drawing=args.drawing)
    # terminal summary, in the report's language
    print("\n".join(summary_lines(spec, table, summary, args.lang, *paths, out)))
    return 0


def report(spec, out, lang, inputs=(), drawing=False):
    """Compute the force table of ``spec`` and write its complete report into ``out``
    (CSV, workbook, plots and, with ``drawing``, the 1:1 drawing-scale PDFs; all named
    after the engine, through a staging folder).

    Returns ``(table, summary, (csv_path, xlsx_path, n_plots))``.
    """
    import engine
    from engine.drawing import DRAWING_NAMES, drawing_figures
    from engine.plots import PLOT_NAMES, all_figures
    from engine.report import build_workbook, save_workbook

    from crankbase.output import (check_not_input, ensure_finite, safe_name, save_figure,
                                  staged_output, write_csv)

    # 1. validate and compute everything
    table = engine.force_table(spec)
    fine = engine.force_table(spec, engine.fine_angles(spec))
    ensure_finite(table, "force table")
    ensure_finite(fine, "force table (plot grid)")
    summary = engine.summarize(fine, spec)
    stem = safe_name(spec.name, "engine")
    csv_path = out / f"{stem}_forces.csv"
    xlsx_path = out / f"{stem}.xlsx"
    stems = [out / f"{stem}_{name}" for name in PLOT_NAMES]
    drawings = [out / f"{stem}_{name}.pdf" for name in DRAWING_NAMES] if drawing else []
    outputs = [csv_path, xlsx_path, *drawings] + [s.with_suffix(f".{e}") for s in stems
                                                  for e in ("png", "svg")]
    inputs = [*inputs, spec.pressure_file]
    check_not_input(outputs, inputs)
    wb = build_workbook(table, summary, spec, lang)
    figs = all_figures(fine, spec, summary, lang)
    if drawing:
        figs.update(drawing_figures(fine, spec, summary, lang))

    # 2. write: every file into a staging folder, moved into DIR only when all are done
    with staged_output(out, inputs=inputs) as stage:
        write_csv(table, stage / csv_path.name)
        save_workbook(wb, stage / xlsx_path.name)
        for name, path in zip(PLOT_NAMES, stems):
            save_figure(figs[name], stage / path.name)
        for name, path in zip(DRAWING_NAMES, drawings):       # 1:1, vector only
            save_figure(figs[name], stage / path.stem, formats=("pdf",))
    for fig in figs.values():
        fig.clear()
    return table, summary, (csv_path, xlsx_path, len(stems))


def summary_lines(spec, table, summary, lang, csv_path, xlsx_path, n_plots, out):
    """The terminal summary of one run, in ``lang`` (Russian or English symbols)."""
    from engine.symbols import sym

    ext = summary["extremes"]
    pmax, apmax = summary["p_max_MPa"], summary["alpha_p_max_deg"]
    R = sym("R", lang)
    if lang == "ru":
        return [
            f"{spec.name}: {spec.strokes}-тактный, D × S = {spec.bore * 1e3:g} × "
            f"{spec.stroke * 1e3:g} мм, λ = {spec.lam:.4f}, n = {spec.speed_rpm:g} мин⁻¹, "
            f"ускорение {'двучленное' if spec.acceleration == 'two-term' else 'точное'}",
            f"  pг max             {pmax:10.3f} МПа  при α = {apmax:g}°;  "
            f"среднее индикаторное давление pi = {summary['pi_MPa']:.4f} МПа",
            f"  P max              {ext['P_N'][0]:10.0f} Н    при α = {ext['P_N'][1]:g}°",
            f"  T max              {ext['T_N'][0]:10.0f} Н    при α = {ext['T_N'][1]:g}°",
            f"  Mкр.ср             {summary['M_mean_Nm']:10.2f} Н·м  (один цилиндр)",
            f"  {R} max           {ext['R_N'][0]:10.0f} Н    при α = {ext['R_N'][1]:g}°;"
            f"  {sym('R_mean', lang)} = {summary['R_mean_N']:.0f} Н;  "
            f"χ = {summary['chi']:.3f}",
            f"записано: {csv_path} ({len(table)} строк), {xlsx_path}, {n_plots} графиков "
            f"(PNG, SVG) в {out}",
        ]
    return [
        f"{spec.name}: {spec.strokes}-stroke, D x S = {spec.bore * 1e3:g} x "
        f"{spec.stroke * 1e3:g} mm, lambda = {spec.lam:.4f}, n = {spec.speed_rpm:g} rpm, "
        f"acceleration {spec.acceleration}",
        f"  peak gas pressure  {pmax:10.3f} MPa  at alpha = {apmax:g} deg;  "
        f"indicated mean pressure pi = {summary['pi_MPa']:.4f} MPa",
        f"  P max              {ext['P_N'][0]:10.0f} N    at alpha = {ext['P_N'][1]:g} deg",
        f"  T max              {ext['T_N'][0]:10.0f} N    at alpha = {ext['T_N'][1]:g} deg",
        f"  mean torque Mt     {summary['M_mean_Nm']:10.2f} N*m  (one cylinder)",
        f"  {R} max           {ext['R_N'][0]:10.0f} N    at alpha = {ext['R_N'][1]:g} deg;"
        f"  mean {summary['R_mean_N']:.0f} N;  chi = {summary['chi']:.3f}",
        f"wrote {csv_path} ({len(table)} rows), {xlsx_path}, {n_plots} plots (PNG, SVG) "
        f"in {out}",
    ]
