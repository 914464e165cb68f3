"""The ``crankdyn`` command line.

Each subcommand lives in its own module (``crankdyn.cmd_<name>``) exposing
``add_parser(subparsers)``, which registers an argparse parser whose ``func(args)`` runs
the job and returns an exit status.  Heavy libraries (numpy, pandas, matplotlib,
openpyxl) are imported inside ``func`` only, so ``crankdyn --help`` stays fast.

Bad input (a :class:`crankbase.errors.CrankdynError`) is reported one problem per line on
stderr, without a traceback, with exit status 2; no output file is written in that case.
Any other exception is a bug and shows with its traceback.

argparse's own complaints (an unknown option, a missing argument, a bad choice) are shown in
the language asked with ``--lang`` (default Russian, as every report): their words come from
the text layer (``errors.argparse.*``), handed to argparse as its message catalogue for
this process (:func:`_speak_argparse`).
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
    parser.subcommands = sub.choices        # {name: its parser}, to name it in errors
    return parser


#: argparse's message (its msgid, CPython 3.11–3.13) → the text key and the ``%``-fields
#: the translated template must carry back, in argparse's formatting.
ARGPARSE_TEXTS = {
    "invalid choice: %(value)r (choose from %(choices)s)":
        ("errors.argparse.invalid_choice", {"value": "%(value)r", "choices": "%(choices)s"}),
    "the following arguments are required: %s": ("errors.argparse.required", {"names": "%s"}),
    "unrecognized arguments: %s": ("errors.argparse.unrecognized", {"args": "%s"}),
    "expected one argument": ("errors.argparse.expected_one", {}),
    "expected at least one argument": ("errors.argparse.expected_at_least_one", {}),
    "expected at most one argument": ("errors.argparse.expected_at_most_one", {}),
    "invalid %(type)s value: %(value)r":
        ("errors.argparse.invalid_value", {"type": "%(type)s", "value": "%(value)r"}),
    "ambiguous option: %(option)s could match %(matches)s":
        ("errors.argparse.ambiguous", {"option": "%(option)s", "matches": "%(matches)s"}),
    "not allowed with argument %s": ("errors.argparse.not_allowed_with", {"other": "%s"}),
    "one of the arguments %s is required": ("errors.argparse.one_of_required", {"names": "%s"}),
    "argument %(argument_name)s: %(message)s":
        ("errors.argparse.argument", {"argument": "%(argument_name)s",
                                      "message": "%(message)s"}),
    "%(prog)s: error: %(message)s\n":
        ("errors.argparse.prog_error", {"prog": "%(prog)s", "message": "%(message)s"}),
}


def _language_asked(argv) -> str:
    """The ``--lang`` of a command line not parsed yet (``--lang X`` or ``--lang=X``),
    or the reports' default, Russian."""
    lang = "ru"
    for i, arg in enumerate(argv):
        if arg == "--lang" and i + 1 < len(argv):
            lang = argv[i + 1]
        elif arg.startswith("--lang="):
            lang = arg.split("=", 1)[1]
    return lang


def _speak_argparse(lang: str) -> None:
    """Give argparse, for this process, the words of ``lang`` (Russian if that language
    is not offered) for its error messages.

    argparse looks its messages up through the module-level ``_`` it imported from
    :mod:`gettext`; replacing that name is the catalogue hook argparse offers a program
    that has no ``.mo`` files installed.  The catalogues are read only when argparse has
    something to complain about, so ``crankdyn --help`` stays fast.  A message argparse
    adds in a later Python stays English."""
    words = []

    def t(key, **fields):
        if not words:
            from crankbase.texts import languages, texts

            words.append(texts(lang if lang in languages() else "ru"))
        return words[0](key, **fields)

    class Template(str):
        """A translated template that also names argparse's ``%(type)s`` (the Python
        type of an option: ``float``, ``int``) in the words of the language."""

        def __mod__(self, args):
            if isinstance(args, dict) and args.get("type") in ("float", "int"):
                args = {**args, "type": t(f"errors.argparse.type.{args['type']}")}
            return str.__mod__(self, args)

    def translate(message):
        key, fields = ARGPARSE_TEXTS.get(message, (None, None))
        return message if key is None else Template(t(key, **fields))

    argparse._ = translate


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    _speak_argparse(_language_asked(argv))
    parser = build_parser()
    args, unknown = parser.parse_known_args(argv)
    if unknown:  # said by the subcommand's parser, so the line names the subcommand
        parser.subcommands.get(args.command, parser).error(
            argparse._("unrecognized arguments: %s") % " ".join(unknown))
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
