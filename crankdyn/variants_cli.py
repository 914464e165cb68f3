"""``crankdyn engine --variants``: one complete report per course variant, and a summary.

Reads the base spec and the variants table (:mod:`engine.variants`), writes each good
variant's report (the same as ``crankdyn engine`` writes) into ``DIR/<variant>/``, and
``DIR/variants_summary.csv`` / ``.xlsx`` with the key results side by side; a bad row is
reported on stderr by row and key (and in ``DIR/variants_errors.csv``) and does not stop
the others.  Exit status 0 when every variant was written, 1 when any failed; a table that
cannot be read at all is an error (2) and writes nothing.  A progress bar (tqdm) shows on
a terminal.
"""
from __future__ import annotations

import sys


def run_variants(args, spec_path, out) -> int:
    from pathlib import Path

    from tqdm import tqdm

    from crankbase.errors import SpecError
    from crankbase.output import check_not_input, safe_name
    from crankbase.validation import read_toml
    from engine.variants import read_variants

    variants_path = Path(args.variants)
    base, base_dir = read_toml(spec_path)
    rows = read_variants(variants_path)
    folders = {}
    clash = []
    for v in rows:
        f = safe_name(v.variant, "variant")
        if f in folders:
            clash.append(f"row {v.row} ({v.variant}): folder {f!r} is also the folder of "
                         f"row {folders[f].row} ({folders[f].variant}); rename one")
        folders[f] = v
    if clash:
        raise SpecError(clash)
    for name in ("variants_summary.csv", "variants_summary.xlsx", "variants_errors.csv"):
        check_not_input([out / name], [spec_path, variants_path])

    ru = args.lang == "ru"
    records, failures = [], []
    tasks = [(base, v, base_dir, spec_path, variants_path, out / folder, args.lang, args.step,
              getattr(args, "form", None), args.drawing) for folder, v in folders.items()]
    jobs = max(1, int(getattr(args, "jobs", 1) or 1))
    bar = tqdm(total=len(tasks), desc="варианты" if ru else "variants", unit="var",
               file=sys.stderr, disable=None, leave=False)
    if jobs == 1:
        results = (_one_variant(t) for t in tasks)
    else:
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor, as_completed

        pool = ProcessPoolExecutor(max_workers=jobs,
                                   mp_context=multiprocessing.get_context("spawn"))
        futures = [pool.submit(_one_variant, t) for t in tasks]
        results = (f.result() for f in as_completed(futures))
    done = []
    for v, record, lines in results:
        bar.update(1)
        done.append((v, record, lines))
        for ln in lines or ():
            tqdm.write(f"crankdyn engine: error: {ln}", file=sys.stderr)
        if lines and (out / safe_name(v.variant, "variant")).exists():
            tqdm.write(f"crankdyn engine: warning: {out / safe_name(v.variant, 'variant')} "
                       f"holds an earlier report of variant {v.variant!r}; it was not "
                       "replaced", file=sys.stderr)
    if jobs > 1:
        pool.shutdown()
    bar.close()
    for v, record, lines in sorted(done, key=lambda d: d[0].row):    # the table's order
        if lines:
            failures.append((v, lines))
        else:
            records.append(record)

    _write_summary(out, records, failures, args.lang)
    n_ok, n_bad = len(records), len(failures)
    if ru:
        print(f"вариантов: {len(rows)}; записано {n_ok} (по папке на вариант в {out}), "
              f"с ошибками {n_bad}" + (" (строки " + ", ".join(str(v.row) for v, _ in
                                                               failures) + ")"
                                       if n_bad else ""))
        print(f"сводная таблица: {out / 'variants_summary.xlsx'}")
    else:
        print(f"{len(rows)} variants: {n_ok} written (one folder each in {out}), {n_bad} "
              "failed" + (" (rows " + ", ".join(str(v.row) for v, _ in failures) + ")"
                          if n_bad else ""))
        print(f"summary table: {out / 'variants_summary.xlsx'}")
    return 1 if failures else 0


def _one_variant(task):
    """Validate one variant and write its complete report: ``(variant, summary record,
    None)``, or ``(variant, None, problem lines)`` when the row is bad.  A module-level
    function, so that a process pool (``--jobs``) can run it."""
    from crankbase.errors import CrankdynError
    from engine.variants import load_variant, summary_record

    from .cmd_engine import report, with_options

    base, v, base_dir, spec_path, variants_path, folder, lang, step, form, drawing = task
    try:
        study = with_options(load_variant(base, v, base_dir), step, form)
        done = report(study, spec_path, folder, lang, inputs=[spec_path, variants_path],
                      drawing=drawing)
        spec, summary = study.spec, done["result"].summary
    except CrankdynError as exc:
        lines = exc.lines() or [str(exc)]
        return v, None, [ln if ln.startswith("row ") else f"row {v.row} ({v.variant}): {ln}"
                         for ln in lines]
    return v, summary_record(v.variant, spec, summary), None


def _write_summary(out, records, failures, lang):
    """variants_summary.csv and .xlsx (and variants_errors.csv when rows failed), each
    written atomically; an errors file of an earlier run is removed when none failed."""
    import pandas as pd

    from crankbase.output import atomic_path, full_precision_xlsx, write_csv
    from engine.variants import SUMMARY_FIELDS

    out.mkdir(parents=True, exist_ok=True)
    df = pd.DataFrame(records, columns=list(SUMMARY_FIELDS))
    write_csv(df, out / "variants_summary.csv")
    errors = out / "variants_errors.csv"
    if failures:
        err = pd.DataFrame([(v.row, v.variant, ln) for v, lines in failures for ln in lines],
                           columns=["row", "variant", "problem"])
        write_csv(err, errors)
    elif errors.exists():
        errors.unlink()

    from openpyxl import Workbook
    from openpyxl.styles import Alignment, Font, PatternFill

    wb = Workbook()
    ws = wb.active
    ws.title = "variants"
    ws["A1"] = ("Сводка по вариантам: основные исходные данные и результаты"
                if lang == "ru" else "Variants: key inputs and results side by side")
    ws["A1"].font = Font(bold=True, size=12)
    for j, name in enumerate(df.columns, start=1):
        c = ws.cell(3, j, name)
        c.font = Font(bold=True)
        c.fill = PatternFill("solid", fgColor="DDE4EE")
        c.alignment = Alignment(horizontal="center", wrap_text=True)
        ws.column_dimensions[c.column_letter].width = max(10, len(name) + 2)
    for i, row in enumerate(df.itertuples(index=False), start=4):
        for j, val in enumerate(row, start=1):
            c = ws.cell(i, j, val.item() if hasattr(val, "item") else val)
            if isinstance(val, str):
                c.data_type = "s"
            elif j > 2:
                c.number_format = "0.000" if abs(val) < 100 else "0"
    ws.row_dimensions[3].height = 30
    ws.freeze_panes = "B4"
    ws.print_title_rows = "3:3"
    ws.print_title_cols = "A:A"
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = "landscape"
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    width = sum(max(10, len(n) + 2) for n in df.columns)
    ws.page_setup.fitToWidth = max(1, -(-width // 190))   # ≤ 190 width units a page
    ws.page_setup.fitToHeight = 0
    with atomic_path(out / "variants_summary.xlsx") as tmp, full_precision_xlsx():
        wb.save(tmp)
