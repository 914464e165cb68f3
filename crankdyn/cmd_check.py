"""``crankdyn check``: check a student's table against the computed one.

    crankdyn check SPEC.toml STUDENT.xlsx|csv -o DIR [--rtol 0.02] [--atol A]
                   [--map "HEADER=column" ...] [--lang ru|en]

An engine spec (``[engine]``) checks Table 2 (either textbook form, by ``alpha_deg``); a
linkage spec (``[mechanism]``) checks the course tables (positions, velocities,
accelerations, loads, reactions, Mур, by ``position``).  Writes ``DIR/check.csv``
(``alpha_deg`` or ``position``, ``column, student, computed, deviation, ok``) and, for a
workbook, ``DIR/<student>_checked.xlsx``: a copy with every wrong cell red and a comment
with the right value.  Prints a verdict per column.  Exit status 0 when every value is
right, 1 when any is wrong, 2 on bad input.
"""
from __future__ import annotations
from crankbase.errors import Text


def add_parser(sub):
    p = sub.add_parser(
        "check", help="check a student's Table 2 or linkage tables against the computed ones",
        description="Read a student's table (our workbook layout, a CSV with our column "
                    "names, or either with --map), compute the same rows from the spec and "
                    "mark every value outside the tolerance |student - computed| <= atol + "
                    "rtol*|computed| (default rtol 0.02: a hand-drawn plan is good to a few "
                    "per cent; default atol 0.5 % of the column's largest magnitude).")
    p.add_argument("spec", metavar="SPEC.toml", help="engine or linkage spec (TOML)")
    p.add_argument("student", metavar="STUDENT.xlsx|csv", help="the student's table")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--rtol", type=float, metavar="R",
                   help="relative tolerance (default 0.02)")
    p.add_argument("--atol", type=float, metavar="A",
                   help="absolute tolerance in the column's unit (default: 0.5 %% of the "
                        "column's largest magnitude)")
    p.add_argument("--map", action="append", metavar="HEADER=column", default=[],
                   help="the student's header HEADER holds our column (repeatable), e.g. "
                        "--map 'T, Н=T_N' --map 'α=alpha_deg'")
    p.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="language of the verdicts and comments (default ru)")
    p.set_defaults(func=run)
    return p


def run(args) -> int:
    from pathlib import Path

    from crankbase.checking import check_table, write_check
    from crankbase.errors import SpecError
    from crankbase.validation import read_toml

    spec_path, student_path = Path(args.spec), Path(args.student)
    try:
        raw, _ = read_toml(spec_path)
        if "engine" in raw:
            import engine
            from engine.check import check_side

            side = check_side(engine.load(spec_path))
        elif "mechanism" in raw:
            import linkage
            from linkage.check import check_side

            side = check_side(linkage.load_spec(spec_path))
        else:
            raise SpecError(Text("errors.crankdyn.cli_check.neither_engine_spec",
                                 {"spec_path": spec_path}))
        result = check_table(side, student_path, args.rtol, args.atol, args.map)
        written = write_check(result, Path(args.output), args.lang, inputs=[spec_path])
    except SpecError as exc:            # the library's arguments → this command's options
        raise exc.renamed({"mapping": "--map", "rtol": "--rtol", "atol": "--atol"}) from None
    print("\n".join(result.summary_lines(args.lang, written)))
    return 0 if result.ok else 1
