"""``crankdyn check``: check a student's table against the computed one.

    crankdyn check SPEC.toml STUDENT.xlsx|csv -o DIR [--rtol 0.02] [--atol A]
                   [--map "HEADER=column" ...] [--lang ru|en|zh]
    crankdyn check BASE.toml --variants variants.csv STUDENTS_DIR -o DIR [...]

An engine spec (``[engine]``) checks Table 2 (either textbook form, by ``alpha_deg``); a
linkage spec (``[mechanism]``) checks the course tables (positions, velocities,
accelerations, loads, reactions, Mур, by ``position``).  Writes ``DIR/check.csv``
(``alpha_deg`` or ``position``, ``column, student, computed, deviation, ok``) and, for a
workbook, ``DIR/<student>_checked.xlsx``: a copy with every wrong cell red and a comment
with the right value.  Prints a verdict per column.  Exit status 0 when every value is
right, 1 when any is wrong, 2 on bad input.

With ``--variants`` the whole class is graded in one call
(:func:`engine.variants.check_class`): every ``.xlsx``/``.xlsm``/``.csv`` of STUDENTS_DIR
is matched to its variant (the variant's name as a whole word of the file name, or a
workbook cell labelled «Вариант»/«Variant») and checked against it; ``DIR/class_check.csv``
and ``.xlsx`` hold one line per student (``student, variant, columns_wrong, cells_wrong,
verdict, detail``), ``DIR/<student>/`` the student's ``check.csv`` and checked workbook.
Exit status 0 when every student is matched and right, 1 otherwise.
"""
from __future__ import annotations
from .langs import LANG_CHOICES, LANG_HELP


def add_parser(sub):
    p = sub.add_parser(
        "check", help="check a student's Table 2 or linkage tables against the computed ones",
        description="Read a student's table (our workbook layout, a CSV with our column "
                    "names, or either with --map), compute the same rows from the spec and "
                    "mark every value outside the tolerance |student - computed| <= atol + "
                    "rtol*|computed| (default rtol 0.02: a hand-drawn plan is good to a few "
                    "per cent; default atol 0.2 % of the column's largest magnitude: a value "
                    "at its column's peak may be off by 2.2 % of itself, at a third of the "
                    "peak by 2.6 %, so a 3 % error above a third of the peak is caught). "
                    "With --variants, STUDENT is a folder: a whole class, each file checked "
                    "against its own variant.")
    p.add_argument("spec", metavar="SPEC.toml",
                   help="engine or linkage spec (TOML); with --variants the base engine spec")
    p.add_argument("student", metavar="STUDENT.xlsx|csv",
                   help="the student's table; with --variants the folder of the students' "
                        "tables (STUDENTS_DIR)")
    p.add_argument("--variants", metavar="VARIANTS.csv|xlsx",
                   help="the variants table of `crankdyn engine --variants`: grade the "
                        "whole class in STUDENTS_DIR, each file against its variant (the "
                        "variant's name as a whole word of the file name, e.g. "
                        "ivanov_v02.xlsx, or a cell labelled Вариант/Variant)")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--rtol", type=float, metavar="R",
                   help="relative tolerance (default 0.02)")
    p.add_argument("--atol", type=float, metavar="A",
                   help="absolute tolerance in the column's unit (default: 0.2 %% of the "
                        "column's largest magnitude)")
    p.add_argument("--map", action="append", metavar="HEADER=column", default=[],
                   help="the student's header HEADER holds our column (repeatable), e.g. "
                        "--map 'T, Н=T_N' --map 'α=alpha_deg'")
    p.add_argument("--lang", choices=LANG_CHOICES, metavar="LANG", default="ru",
                   help=LANG_HELP
                   + "language of the verdicts and comments (default ru)")
    p.set_defaults(func=run)
    return p


def run(args) -> int:
    from pathlib import Path

    from crankbase.checking import check_table, write_check
    from crankbase.errors import SpecError
    from engine.check import spec_check_side

    spec_path, student_path = Path(args.spec), Path(args.student)
    if getattr(args, "variants", None):
        return _run_class(args, spec_path, student_path)
    try:
        side = spec_check_side(spec_path)
        result = check_table(side, student_path, args.rtol, args.atol, args.map)
        written = write_check(result, Path(args.output), args.lang, inputs=[spec_path])
    except SpecError as exc:            # the library's arguments → this command's options
        raise exc.renamed({"mapping": "--map", "rtol": "--rtol", "atol": "--atol"}) from None
    print("\n".join(result.summary_lines(args.lang, written)))
    return 0 if result.ok else 1


def _run_class(args, spec_path, students) -> int:
    """``crankdyn check BASE.toml --variants variants.csv STUDENTS_DIR -o DIR``."""
    from pathlib import Path

    from crankbase.errors import SpecError
    from engine.variants import check_class

    try:
        done = check_class(spec_path, args.variants, students, Path(args.output), args.lang,
                           args.rtol, args.atol, args.map)
    except SpecError as exc:            # the library's arguments → this command's options
        raise exc.renamed({"mapping": "--map", "rtol": "--rtol", "atol": "--atol",
                           "variants": "--variants"}) from None
    print("\n".join(done.summary_lines(args.lang)))
    return 0 if done.ok else 1
