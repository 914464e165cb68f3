"""The ``crankdyn`` command line.

Each subcommand lives in its own module (``crankdyn.cmd_<name>``) exposing
``add_parser(subparsers)``, which registers an argparse parser whose ``func(args)`` runs
the job and returns an exit status.  Heavy libraries (numpy, pandas, matplotlib,
openpyxl) are imported inside ``func`` only, so ``crankdyn --help`` stays fast.

Bad input (a :class:`crankbase.errors.CrankdynError`) is reported one problem per line on
stderr, without a traceback, with exit status 2; no output file is written in that case.
Any other exception is a bug and shows with its traceback.
"""
from __future__ import annotations

import argparse
import importlib
import os
import sys

from . import __version__

#: Subcommand modules, in the order ``--help`` lists them.
SUBCOMMANDS = ("engine", "linkage", "synth", "dynamics", "balance", "torsion", "check", "serve")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="crankdyn",
        description="Dynamics of crank mechanisms: engine force table (Table 2), "
                    "planar linkage kinematics and kinetostatics, synthesis.")
    parser.add_argument("--version", action="version", version=f"crankdyn {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in SUBCOMMANDS:
        try:
            module = importlib.import_module(f"crankdyn.cmd_{name}")
        except ModuleNotFoundError as exc:  # a subcommand not built yet
            if exc.name != f"crankdyn.cmd_{name}":
                raise
            continue
        module.add_parser(sub)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    from crankbase.errors import CrankdynError, Text, os_reason

    lang = getattr(args, "lang", None) or "en"
    if getattr(args, "output", None) is not None and not args.output.strip():
        # Path("") is ".": an empty -o would write into the current folder unasked
        print(f"crankdyn {args.command}: error: "
              + Text("errors.cli.empty_output").render(lang), file=sys.stderr)
        return 2
    try:
        return int(args.func(args) or 0)
    except CrankdynError as exc:  # the project's own errors only: anything else is a bug
        for line in exc.lines(lang) or [repr(exc)]:
            print(f"crankdyn {args.command}: error: {line}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `crankdyn ... | head`
        sys.stdout = open(os.devnull, "w")
        return 0
    except (FileNotFoundError, IsADirectoryError, PermissionError) as exc:
        why = Text("errors.cli.os_file", {"file": exc.filename, "reason": os_reason(exc)}) \
            if exc.filename is not None else Text("errors.cli.os", {"reason": os_reason(exc)})
        print(f"crankdyn {args.command}: error: {why.render(lang)}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
