"""``crankdyn engine --variants``: one complete report per course variant, and a summary.

The batch is the library's :func:`engine.variants.run_variants` (each good variant's report
in ``DIR/<variant>/``, ``DIR/variants_summary.csv`` / ``.xlsx`` with the key results side by
side, a bad row's problems in ``DIR/variants_errors.csv`` without stopping the others);
this module adds the progress bar (tqdm, on a terminal), reports each bad row on stderr by
row and key as it is done, and prints the summary.  Exit status 0 when every variant was
written, 1 when any failed; a table that cannot be read at all is an error (2) and writes
nothing.
"""
from __future__ import annotations

import sys

from .langs import error_line, warning_line


def run_variants(args, spec_path, out) -> int:
    from tqdm import tqdm

    from crankbase.texts import texts
    from engine.variants import run_variants as run

    t = texts(args.lang)
    bar = tqdm(desc=t("variants.progress"), unit="var", file=sys.stderr, disable=None,
               leave=False)

    def progress(outcome, total):
        bar.total = total
        bar.update(1)
        for ln in outcome.problems:
            tqdm.write(error_line("engine", ln, args.lang), file=sys.stderr)
        if outcome.kept_earlier:
            tqdm.write(warning_line("engine", t(
                "variants.kept_earlier", folder=str(outcome.folder),
                variant=outcome.variant.variant), args.lang), file=sys.stderr)

    try:
        done = run(spec_path, args.variants, out, args.lang, step=args.step,
                   form=getattr(args, "form", None),
                   bearings=getattr(args, "bearings", False), drawing=args.drawing,
                   jobs=max(1, int(getattr(args, "jobs", 1) or 1)), progress=progress)
    finally:
        bar.close()
    print("\n".join(done.summary_lines(args.lang)))
    return 1 if done.failures else 0
