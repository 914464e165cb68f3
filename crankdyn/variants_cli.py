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

    from crankbase.errors import CrankdynError, SpecError
    from crankbase.output import check_not_input, safe_name
    from crankbase.validation import read_toml
    from engine.variants import load_variant, read_variants, summary_record

    from .cmd_engine import report

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
    bar = tqdm(list(folders.items()), desc="варианты" if ru else "variants",
               unit="var", file=sys.stderr, disable=None, leave=False)
    for folder, v in bar:
        try:
            spec = load_variant(base, v, base_dir)
            if args.step is not None:
                spec = spec.with_step(args.step)
            if getattr(args, "form", None):
                from dataclasses import replace
                spec = replace(spec, table_form=args.form)
            _, summary, _ = report(spec, out / folder, args.lang,
                                   inputs=[spec_path, variants_path], drawing=args.drawing)
        except CrankdynError as exc:
            lines = exc.lines() or [str(exc)]
            lines = [ln if ln.startswith("row ") else f"row {v.row} ({v.variant}): {ln}"
                     for ln in lines]
            failures.append((v, lines))
            for ln in lines:
                tqdm.write(f"crankdyn engine: error: {ln}", file=sys.stderr)
            stale = out / folder
            if stale.exists():
                tqdm.write(f"crankdyn engine: warning: {stale} holds an earlier report of "
                           f"variant {v.variant!r}; it was not replaced", file=sys.stderr)
            continue
        records.append(summary_record(v.variant, spec, summary))
    bar.close()

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
        ws.column_dimensions[c.column_letter].width = 11 if j > 2 else 16
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
    ws.page_setup.fitToWidth = 2
    ws.page_setup.fitToHeight = 0
    with atomic_path(out / "variants_summary.xlsx") as tmp, full_precision_xlsx():
        wb.save(tmp)
