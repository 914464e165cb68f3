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
from .langs import add_lang, add_output, command


def add_parser(sub, t=None):
    """Register ``crankdyn check``; ``t`` the help's words (:func:`crankdyn.langs.cli_texts`,
    Russian when not given)."""
    p, t = command(sub, "check", t)
    p.add_argument("spec", metavar="SPEC.toml", help=t("cli.check.opt.spec"))
    p.add_argument("student", metavar="STUDENT.xlsx|csv", help=t("cli.check.opt.student"))
    p.add_argument("--variants", metavar="VARIANTS.csv|xlsx", help=t("cli.check.opt.variants"))
    add_output(p, t, "cli.common.opt.output_plain")
    p.add_argument("--rtol", type=float, metavar="R", help=t("cli.check.opt.rtol"))
    p.add_argument("--atol", type=float, metavar="A", help=t("cli.check.opt.atol"))
    p.add_argument("--map", action="append", metavar="HEADER=column", default=[],
                   help=t("cli.check.opt.map"))
    add_lang(p, t, "check")
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
