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
    from crankbase.errors import SpecError

    try:
        return _run(args)
    except SpecError as exc:            # the library's argument → this command's option
        raise exc.renamed({"mapping": "--map"}) from None


def _run(args) -> int:
    from pathlib import Path

    from crankbase.checking import (compare, mark_workbook, parse_mapping,
                                    read_student_table, verdicts)
    from crankbase.errors import SpecError
    from crankbase.output import check_not_input, safe_name, staged_output, write_csv
    from crankbase.validation import read_toml

    problems = []
    if args.rtol is not None and not (0 <= args.rtol < 1):
        problems.append(f"--rtol: got {args.rtol:g}; must be >= 0 and < 1")
    if args.atol is not None and not args.atol >= 0:
        problems.append(f"--atol: got {args.atol:g}; must be >= 0")
    mapping = parse_mapping(args.map)
    if problems:
        raise SpecError(problems)
    spec_path, student_path, out = Path(args.spec), Path(args.student), Path(args.output)
    raw, _ = read_toml(spec_path)
    if "engine" in raw:
        import engine
        from engine.check import KEY, computed_rows, known_columns

        study = engine.load(spec_path)
        spec = study.spec
        student = read_student_table(student_path, KEY, known_columns(), mapping)
        keys = student.data[KEY]
        bad = [k for k in keys if not isinstance(k, float) or k != k]
        if bad:
            raise SpecError(f"{student_path}: {KEY} must be numbers; got {bad[:5]}")
        computed = computed_rows(spec, study.settings, keys.to_numpy(float))
    elif "mechanism" in raw:
        import linkage
        from linkage.check import KEY, computed_rows, computed_table

        table = computed_table(linkage.load_spec(spec_path))
        student = read_student_table(student_path, KEY, set(table.columns), mapping)
        computed = computed_rows(table, student.data[KEY].tolist())
    else:
        raise SpecError(f"{spec_path}: neither an engine spec ([engine]) nor a linkage "
                        "spec ([mechanism])")
    check = compare(student, computed, KEY, args.rtol, args.atol)
    checked = out / f"{safe_name(student_path.stem, 'student')}_checked.xlsx"
    outputs = [out / "check.csv"] + ([checked] if student.cells else [])
    check_not_input(outputs, [spec_path, student_path])
    with staged_output(out, inputs=[spec_path, student_path]) as stage:
        write_csv(check.drop(columns=["row_index"]), stage / "check.csv")
        n_marked = (mark_workbook(student, check, stage / checked.name, args.lang)
                    if student.cells else 0)
    ru = args.lang == "ru"
    n_bad = int((~check["ok"]).sum())
    cols = check["column"].nunique()
    head = (f"{student_path.name}: {len(student.data)} строк, {cols} столбцов проверено "
            f"(rtol = {args.rtol if args.rtol is not None else 0.02:g})" if ru else
            f"{student_path.name}: {len(student.data)} rows, {cols} columns checked "
            f"(rtol = {args.rtol if args.rtol is not None else 0.02:g})")
    print(head)
    print("\n".join(verdicts(check, KEY, args.lang)))
    if student.ignored:
        print(("  не проверены (неизвестные столбцы): " if ru else
               "  not checked (unknown columns): ") + ", ".join(student.ignored))
    tail = (f"итог: {'всё верно' if not n_bad else f'неверных значений: {n_bad}'}; "
            f"{out / 'check.csv'}" if ru else
            f"verdict: {'all right' if not n_bad else f'{n_bad} wrong values'}; "
            f"{out / 'check.csv'}")
    if student.cells:
        tail += (f", {checked} (отмечено ячеек: {n_marked})" if ru
                 else f", {checked} ({n_marked} cells marked)")
    print(tail)
    return 1 if n_bad else 0
