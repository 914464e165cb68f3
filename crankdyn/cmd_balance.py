"""``crankdyn balance``: balancing of a rigid rotor or of a linkage's mechanism.

    crankdyn balance ROTOR.toml -o DIR [--lang ru|en]
    crankdyn balance LINKAGE.toml -o DIR [--lang ru|en]     # optional [balance] section
    crankdyn balance --example [NAME] -o DIR                 # rotor, ratchet

Every output is named after the spec's name (``<name>``: the rotor's or the
mechanism's name as a file stem), so that the reports of several specs share a folder.

Rotor (a ``[rotor]`` table): ``DIR/<name>_rotor_balance.csv`` (``plane, z_mm, mr_gmm,
angle_deg`` and ``m_g, r_mm`` when the spec gives ``correction_radius_mm``),
``DIR/<name>_rotor_shares.csv`` (every unbalance resolved into the planes) and
``DIR/<name>_rotor_polygons.png``/``.svg`` (the m·r polygon of every plane).

Linkage (a ``[mechanism]`` table): full shaking-force balance of a crank-rocker or partial
balance of a crank-slider: ``DIR/<name>_counterweights.csv`` (``link, mr_kgm, angle_deg,
radius_m, mass_kg``; a crank-slider adds ``fraction, m_rec_kg``), ``DIR/<name>_shaking.csv``
(``phi_deg`` and the shaking force and moment before and after: ``F_x_N, F_y_N, F_N,
M_O_Nm`` and ``*_after``) and the plots ``<name>_shaking_force`` and
``<name>_shaking_locus``.

Everything is written at once through a staging folder as one report unit
(``balance:<name>``, apart from the ``crankdyn linkage`` report of the same mechanism):
a rerun replaces only its own files; bad input writes nothing.  The terminal summary
speaks the report's language (``--lang``).
"""
from __future__ import annotations


#: Bundled examples by short name (``--example NAME``).
EXAMPLES = {"rotor": "rotor_two_plane.toml", "ratchet": "ratchet_balance.toml"}


def add_parser(subparsers):
    p = subparsers.add_parser(
        "balance", help="rotor balancing (static or two-plane) or a linkage's shaking-force "
                        "balance by counterweights",
        description="Static (one plane) or dynamic (two planes) balancing of a rigid rotor "
                    "given by its unbalances (m·r or m and r, angle, z): the correction m·r "
                    "and angle per plane, the mass at a chosen radius, the residual force "
                    "and moment, and the m·r polygons.  A linkage spec: full shaking-force "
                    "balance of a crank-rocker or partial balance of a crank-slider by "
                    "counterweights.  Every output is named after the spec's name "
                    "(<name>_rotor_balance.csv, <name>_counterweights.csv …), so that the "
                    "reports of several specs share a folder; a rerun replaces only its "
                    "own files.")
    p.add_argument("spec", nargs="?", metavar="SPEC.toml",
                   help="rotor spec ([rotor]) or linkage spec (optional [balance])")
    p.add_argument("--example", nargs="?", const="rotor", metavar="NAME",
                   help="run a bundled example instead of a spec: "
                        + ", ".join(EXAMPLES) + " (default rotor)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if needed)")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="language of the plots and the terminal summary (default ru, the "
                        "Russian textbook symbols)")
    p.set_defaults(func=run)


def run(args) -> int:
    from pathlib import Path

    from crankbase.errors import SpecError

    from .cmd_dynamics import _spec_path

    spec_path = _spec_path(args, EXAMPLES, "balance")
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise SpecError(f"-o: {out} exists and is not a folder")

    from crankbase.validation import read_toml

    data, _ = read_toml(spec_path)
    if "mechanism" in data and "rotor" not in data:
        return _run_linkage(args, spec_path, out)

    from matplotlib.figure import Figure

    from dynamics.rotor import plot_mr_polygon, rotor_balance

    from crankbase.output import (check_not_input, ensure_finite, safe_name, save_figure,
                                  staged_output, write_csv)

    from .cmd_dynamics import report_stale, written_line

    res = rotor_balance(spec_path)
    cols = ["plane", "z_mm", "mr_gmm", "angle_deg"]
    if "m_g" in res.corrections:
        cols += ["m_g", "r_mm"]
    table = res.corrections[cols]
    ensure_finite(table, "rotor corrections")
    ensure_finite(res.shares, "rotor shares")
    n = len(table)
    fig = Figure(figsize=(5.2 * n, 5.2), layout="constrained")
    for k in range(n):
        plot_mr_polygon(res, k, fig.add_subplot(1, n, k + 1), lang=args.lang)
    name = safe_name(res.name, "rotor")
    csvs = [f"{name}_rotor_balance.csv", f"{name}_rotor_shares.csv"]
    names = csvs + [f"{name}_rotor_polygons.png", f"{name}_rotor_polygons.svg"]
    check_not_input([out / nm for nm in names], [spec_path])
    with staged_output(out, inputs=[spec_path], unit=f"balance:{name}") as stage:
        write_csv(table, stage / names[0])
        write_csv(res.shares, stage / names[1])
        save_figure(fig, stage / f"{name}_rotor_polygons")
    fig.clear()
    print("\n".join(rotor_lines(res, table, args.lang)
                    + [written_line(csvs, 1, out, args.lang)]))
    report_stale("balance", [], out, args.lang, legacy=LEGACY_ROTOR)
    return 0


#: The unnamed outputs of crankdyn versions before the files were named after the spec.
LEGACY_ROTOR = ("rotor_balance.csv", "rotor_shares.csv", "rotor_polygons.png",
                "rotor_polygons.svg")
LEGACY_LINKAGE = ("counterweights.csv", "shaking.csv", "shaking_force.png",
                  "shaking_force.svg", "shaking_locus.png", "shaking_locus.svg")

#: Words of the rotor summary: (ru, en).
_ROTOR = {"static": ("статическое уравновешивание", "static balancing"),
          "dynamic": ("динамическое уравновешивание", "dynamic balancing"),
          "masses": ("неуравновешенностей", "unbalances"),
          "planes": ("плоскостей коррекции", "correction planes"),
          "plane": ("плоскость", "plane"), "mr": ("(m r)б", "m·r"),
          "at": ("под углом", "at"), "at_r": ("при", "at"), "g": ("г", "g"),
          "mm": ("мм", "mm"), "gmm": ("г·мм", "g·mm"), "gmm2": ("г·мм²", "g·mm²"),
          "deg": ("°", " deg"), "F": ("остаточная сила", "residual force"),
          "M": ("остаточный момент", "residual moment"),
          "before": ("до уравновешивания", "before")}


def _snap(value, scale):
    """A residual below round-off of ``scale`` is shown as 0 (crankbase.tolerances)."""
    import numpy as np

    from crankbase.tolerances import snap_roundoff

    return float(snap_roundoff(np.array([float(value)]), scale)[0])


def rotor_lines(res, table, lang="en"):
    """The terminal summary of a rotor balancing in ``lang`` (ru: Russian words and the
    textbook's (m r)б; en: no Cyrillic letter); every number formatted once."""
    i = 0 if lang == "ru" else 1
    W = {k: v[i] for k, v in _ROTOR.items()}
    lines = [f"{res.name}: {W[res.kind]}, {W['masses']}: {len(res.masses)}, "
             f"{W['planes']}: {len(table)}"]
    for _, row in table.iterrows():
        extra = (f",  m = {row['m_g']:.4g} {W['g']} {W['at_r']} r = {row['r_mm']:g} "
                 f"{W['mm']}" if "m_g" in row else "")
        lines.append(f"  {W['plane']} {row['plane']:>2} (z = {row['z_mm']:g} {W['mm']}): "
                     f"{W['mr']} = {row['mr_gmm']:.2f} {W['gmm']} {W['at']} "
                     f"{row['angle_deg']:.2f}{W['deg']}{extra}")
    F = _snap(res.residual_force_gmm, max(res.initial_force_gmm, res.masses["mr_gmm"].abs()
                                          .max()))
    M = _snap(res.residual_moment_gmm2, max(res.initial_moment_gmm2,
                                            res.masses["mr_gmm"].abs().max()
                                            * max(1.0, float(abs(res.masses["z_mm"]).max()))))
    lines.append(f"  {W['F']} {F:.3g} {W['gmm']}, {W['M']} {M:.3g} {W['gmm2']} "
                 f"({W['before']}: {res.initial_force_gmm:.4g}, "
                 f"{res.initial_moment_gmm2:.4g})")
    return lines


def _run_linkage(args, spec_path, out):
    import pandas as pd
    from matplotlib.figure import Figure

    from dynamics.shaking import mechanism_balance, plot_shaking_force, plot_shaking_locus

    from crankbase.output import (check_not_input, ensure_finite, safe_name, save_figure,
                                  staged_output, write_csv)

    from .cmd_dynamics import report_stale, written_line

    res = mechanism_balance(spec_path)
    b, a = res.before.table, res.after.table
    table = pd.concat([b, a.drop(columns="phi_deg").add_suffix("_after")], axis=1)
    ensure_finite(table, "shaking force")
    ensure_finite(res.counterweights.drop(columns="link"), "counterweights")
    figs = {}
    for key, fn, size in (("shaking_force", plot_shaking_force, (7.5, 4.2)),
                          ("shaking_locus", plot_shaking_locus, (6, 6))):
        fig = Figure(figsize=size, layout="constrained")
        fn(res, fig.add_subplot(), lang=args.lang)
        figs[key] = fig
    spec = res.balanced_spec
    name = safe_name(spec.name, "linkage")
    csvs = [f"{name}_counterweights.csv", f"{name}_shaking.csv"]
    names = csvs + [f"{name}_{k}.{e}" for k in figs for e in ("png", "svg")]
    check_not_input([out / n for n in names], [spec_path])
    with staged_output(out, inputs=[spec_path], unit=f"balance:{name}") as stage:
        write_csv(res.counterweights, stage / csvs[0])
        write_csv(table, stage / csvs[1])
        for key, fig in figs.items():
            save_figure(fig, stage / f"{name}_{key}")
    for fig in figs.values():
        fig.clear()
    print("\n".join(linkage_lines(res, args.lang)
                    + [written_line(csvs, len(figs), out, args.lang)]))
    report_stale("balance", [], out, args.lang, legacy=LEGACY_LINKAGE)
    return 0


#: Words of the linkage balance summary: (ru, en).
_LINKAGE = {"crank-rocker": ("кривошипно-коромысловый механизм", "crank-rocker"),
            "crank-slider": ("кривошипно-ползунный механизм", "crank-slider"),
            "what": ("уравновешивание главного вектора сил инерции противовесами",
                     "shaking-force balance by counterweights"),
            "partial": ("частичное уравновешивание главного вектора сил инерции "
                        "противовесом", "partial shaking-force balance by a counterweight"),
            "crank": ("кривошип", "crank"), "rocker": ("коромысло", "rocker"),
            "mr": ("(m r)б", "m·r"), "kgm": ("кг·м", "kg·m"), "kg": ("кг", "kg"),
            "m": ("м", "m"), "N": ("Н", "N"), "at": ("под углом", "at"),
            "at_r": ("при", "at"), "deg": ("°", " deg"),
            "frame": ("(в системе звена)", "(link frame)"),
            "F": ("главный вектор сил инерции max", "max shaking force"),
            "before": ("до", "before"), "after": ("после", "after"),
            "fraction": ("доля уравновешенной массы поступательно движущихся частей",
                         "balanced share of the reciprocating mass")}


def linkage_lines(res, lang="en"):
    """The terminal summary of a linkage's balance in ``lang`` (ru: Russian words and
    symbols; en: no Cyrillic letter); every number formatted once."""
    i = 0 if lang == "ru" else 1
    W = {k: v[i] for k, v in _LINKAGE.items()}
    spec = res.balanced_spec
    what = W["partial"] if spec.kind == "crank-slider" else W["what"]
    lines = [f"{spec.name}: {W.get(spec.kind, spec.kind)}, {what}"]
    cw = res.counterweights
    width = max(len(W.get(r, r)) for r in cw["link"])
    for _, r in cw.iterrows():
        lines.append(f"  {W.get(r['link'], r['link']):<{width}}  {W['mr']} = "
                     f"{r['mr_kgm']:.6g} {W['kgm']} {W['at']} {r['angle_deg']:.2f}{W['deg']} "
                     f"{W['frame']}, m = {r['mass_kg']:.6g} {W['kg']} {W['at_r']} r = "
                     f"{r['radius_m']:.6g} {W['m']}")
    if "fraction" in cw:
        lines.append(f"  {W['fraction']}: {cw['fraction'].iloc[0]:g}")
    before = res.before.F_max
    after = _snap(res.after.F_max, before)
    lines.append(f"  {W['F']}: {before:.6g} {W['N']} {W['before']}, {after:.6g} {W['N']} "
                 f"{W['after']}")
    return lines
