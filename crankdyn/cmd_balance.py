"""``crankdyn balance``: balancing of a rigid rotor or of a linkage's mechanism.

    crankdyn balance ROTOR.toml -o DIR [--lang ru|en]
    crankdyn balance LINKAGE.toml -o DIR [--lang ru|en]     # optional [balance] section
    crankdyn balance --example [NAME] -o DIR                 # rotor, ratchet

Rotor (a ``[rotor]`` table): ``DIR/rotor_balance.csv`` (``plane, z_mm, mr_gmm,
angle_deg`` and ``m_g, r_mm`` when the spec gives ``correction_radius_mm``),
``DIR/rotor_shares.csv`` (every unbalance resolved into the planes) and
``DIR/rotor_polygons.png``/``.svg`` (the m·r polygon of every plane).

Linkage (a ``[mechanism]`` table): full shaking-force balance of a crank-rocker or partial
balance of a crank-slider: ``DIR/counterweights.csv`` (``link, mr_kgm, angle_deg,
radius_m, mass_kg``), ``DIR/shaking.csv`` (``phi_deg`` and the shaking force and moment
before and after: ``F_x_N, F_y_N, F_N, M_O_Nm`` and ``*_after``) and the plots
``shaking_force`` and ``shaking_locus``.

Everything is written at once through a staging folder; bad input writes nothing.
"""
from __future__ import annotations


#: Bundled examples by short name (``--example NAME``).
EXAMPLES = {"rotor": "rotor_two_plane.toml", "ratchet": "ratchet_balance.toml"}


def add_parser(subparsers):
    p = subparsers.add_parser(
        "balance", help="rotor balancing (static or two-plane): corrections and m·r polygons",
        description="Static (one plane) or dynamic (two planes) balancing of a rigid rotor "
                    "given by its unbalances (m·r or m and r, angle, z): the correction m·r "
                    "and angle per plane, the mass at a chosen radius, the residual force "
                    "and moment, and the m·r polygons.")
    p.add_argument("spec", nargs="?", metavar="SPEC.toml",
                   help="rotor spec ([rotor]) or linkage spec (optional [balance])")
    p.add_argument("--example", nargs="?", const="rotor", metavar="NAME",
                   help="run a bundled example instead of a spec: "
                        + ", ".join(EXAMPLES) + " (default rotor)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if needed)")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="plot language (default ru)")
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

    from crankbase.output import check_not_input, ensure_finite, staged_output, write_csv

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
    names = ["rotor_balance.csv", "rotor_shares.csv", "rotor_polygons.png",
             "rotor_polygons.svg"]
    check_not_input([out / nm for nm in names], [spec_path])
    with staged_output(out, inputs=[spec_path]) as stage:
        write_csv(table, stage / names[0])
        write_csv(res.shares, stage / names[1])
        fig.savefig(stage / names[2], dpi=110)
        fig.savefig(stage / names[3])

    print(f"{res.name}: {res.kind} balancing, {len(res.masses)} unbalance(s), "
          f"{n} correction plane(s)")
    for _, row in table.iterrows():
        extra = f",  m = {row['m_g']:.4g} g at r = {row['r_mm']:g} mm" if "m_g" in row else ""
        print(f"  plane {row['plane']:>2} (z = {row['z_mm']:g} mm): m*r = "
              f"{row['mr_gmm']:.2f} g*mm at {row['angle_deg']:.2f} deg{extra}")
    print(f"  residual force {res.residual_force_gmm:.3g} g*mm, residual moment "
          f"{res.residual_moment_gmm2:.3g} g*mm^2 (before: {res.initial_force_gmm:.4g}, "
          f"{res.initial_moment_gmm2:.4g})")
    print(f"wrote {out / names[0]}, {out / names[1]}, {out / 'rotor_polygons'}.png/.svg")
    return 0


def _run_linkage(args, spec_path, out):
    import pandas as pd
    from matplotlib.figure import Figure

    from dynamics.shaking import mechanism_balance, plot_shaking_force, plot_shaking_locus

    from crankbase.output import check_not_input, ensure_finite, staged_output, write_csv

    res = mechanism_balance(spec_path)
    b, a = res.before.table, res.after.table
    table = pd.concat([b, a.drop(columns="phi_deg").add_suffix("_after")], axis=1)
    ensure_finite(table, "shaking force")
    ensure_finite(res.counterweights.drop(columns="link"), "counterweights")
    figs = {}
    for name, fn, size in (("shaking_force", plot_shaking_force, (7.5, 4.2)),
                           ("shaking_locus", plot_shaking_locus, (6, 6))):
        fig = Figure(figsize=size, layout="constrained")
        fn(res, fig.add_subplot(), lang=args.lang)
        figs[name] = fig
    names = ["counterweights.csv", "shaking.csv"] + [f"{n}.{e}" for n in figs
                                                      for e in ("png", "svg")]
    check_not_input([out / n for n in names], [spec_path])
    with staged_output(out, inputs=[spec_path]) as stage:
        write_csv(res.counterweights, stage / names[0])
        write_csv(table, stage / names[1])
        for n, fig in figs.items():
            fig.savefig(stage / f"{n}.png", dpi=110)
            fig.savefig(stage / f"{n}.svg")
    spec = res.balanced_spec
    print(f"{spec.name}: {spec.kind}, shaking-force balance by counterweights")
    for _, r in res.counterweights.iterrows():
        print(f"  {r['link']:<7} m*r = {r['mr_kgm']:.6g} kg*m at {r['angle_deg']:.2f} deg "
              f"(link frame), m = {r['mass_kg']:.6g} kg at r = {r['radius_m']:.6g} m")
    print(f"  max shaking force {res.before.F_max:.6g} N before, {res.after.F_max:.6g} N after")
    print(f"wrote {out / names[0]}, {out / names[1]}, {len(figs)} plots (PNG, SVG) in {out}")
    return 0
