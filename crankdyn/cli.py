"""The ``crankdyn`` command line.

Each subcommand lives in its own module (``crankdyn.cmd_<name>``) exposing
``add_parser(subparsers)``, which registers an argparse parser whose ``func(args)`` runs
the job and returns an exit status.  Heavy libraries (numpy, pandas, matplotlib,
openpyxl) are imported inside ``func`` only, so ``crankdyn --help`` stays fast.

Bad input (a :class:`crankbase.errors.CrankdynError`) is reported one problem per line on
stderr, without a traceback, with exit status 2; no output file is written in that case.
Any other exception is a bug and shows with its traceback.

The help (``crankdyn --help``, ``crankdyn <command> --help``) and argparse's own complaints
(an unknown option, a missing argument, a bad choice) are in the language asked with
``--lang`` (pre-scanned before parsing, :func:`_language_asked`; default Russian, as every
report).  The help's words are the text layer's ``cli`` area (``cli.<command>.help``,
``cli.<command>.description``, ``cli.<command>.opt.<option>``, argparse's own headings
``cli.argparse.*``), read alone and without Babel (:func:`crankdyn.langs.cli_texts`), so
that ``crankdyn --help`` stays fast; the complaints' words are ``errors.argparse.*``, read
only when argparse has something to complain about.  Both are handed to argparse as its
message catalogue for this process (:func:`_speak_argparse`).
"""
from __future__ import annotations

import argparse
import importlib
import os
import re
import sys

from . import __version__
from .langs import DEFAULT_LANG, cli_texts, error_line

#: Subcommand modules, in the order ``--help`` lists them.
SUBCOMMANDS = ("engine", "linkage", "synth", "dynamics", "balance", "torsion", "check", "serve")


#: Characters a line may break before or after without a space (CJK ideographs, kana,
#: fullwidth forms), and the punctuation that never starts a line.
_CJK = re.compile(r"[\u2e80-\u9fff\uac00-\ud7af\uf900-\ufaff\ufe30-\ufe4f\uff00-\uffef]")
_NO_LINE_START = set("，。、；：）」』》〉！？…,.;:)]")
_NO_LINE_END = set("（「『《〈(")


def _width(text: str) -> int:
    """Terminal columns of ``text``: two for a wide (CJK) character, one otherwise."""
    return sum(2 if _CJK.match(ch) else 1 for ch in text)


class HelpFormatter(argparse.HelpFormatter):
    """argparse's formatter, with Chinese (or any CJK) text wrapped as it is written: a
    line may break between two CJK characters (there are no spaces to break at), never
    inside a Latin word or file name, before a closing mark or after an opening one, and
    a CJK character counts two columns.  Text without CJK is wrapped exactly as argparse does."""

    def _split_lines(self, text, width):
        if not _CJK.search(text):
            return super()._split_lines(text, width)
        return self._cjk_lines(self._whitespace_matcher.sub(" ", text).strip(), width)

    def _fill_text(self, text, width, indent):
        if not _CJK.search(text):
            return super()._fill_text(text, width, indent)
        text = self._whitespace_matcher.sub(" ", text).strip()
        return "\n".join(indent + line
                         for line in self._cjk_lines(text, width - len(indent)))

    @staticmethod
    def _cjk_lines(text, width):
        # a number keeps its unit on its line ("100–150 mm"): a no-break space between
        text = re.sub(r"(?<=\d) (?=[A-Za-zμ°%])", "\u00a0", text)
        units = []                     # words, single CJK characters and spaces
        for m in re.finditer(r" |[^ ]", text):
            ch = m.group(0)
            if (units and ch != " " and units[-1] != " "
                    and not _CJK.match(ch) and not _CJK.match(units[-1][-1])):
                units[-1] += ch        # a Latin word or a file name stays whole
            elif units and ch != " " and (
                    (ch in _NO_LINE_START and units[-1] != " ")
                    or units[-1][-1] in _NO_LINE_END):
                units[-1] += ch        # no line starts with a closing mark, or ends with
                                       # an opening one
            else:
                units.append(ch)
        lines, line = [], ""
        for unit in units:
            if unit == " " and not line:
                continue
            if line and _width(line + unit) > width and unit != " ":
                lines.append(line.rstrip())
                line = unit
            else:
                line += unit
        if line.strip():
            lines.append(line.rstrip())
        return [line.replace("\u00a0", " ") for line in lines]


class Parser(argparse.ArgumentParser):
    """The parser of ``crankdyn`` and of each subcommand: :class:`HelpFormatter` unless
    told otherwise."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", HelpFormatter)
        super().__init__(*args, **kwargs)


def build_parser(lang: str = DEFAULT_LANG) -> argparse.ArgumentParser:
    """The ``crankdyn`` parser with every subcommand, its help in ``lang`` (Russian when
    that language has no catalogue); argparse's own words too (:func:`_speak_argparse`)."""
    _speak_argparse(lang)
    t = cli_texts(lang)
    parser = Parser(prog="crankdyn", description=t("cli.description"))
    parser.add_argument("--version", action="version", version=f"crankdyn {__version__}",
                        help=t("cli.argparse.version"))
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    for name in SUBCOMMANDS:
        try:
            module = importlib.import_module(f"crankdyn.cmd_{name}")
        except ModuleNotFoundError as exc:  # a subcommand not built yet
            if exc.name != f"crankdyn.cmd_{name}":
                raise
            continue
        module.add_parser(sub, t)
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
}

#: argparse's error line (CPython 3.11–3.13): the command line's own ``cli.error``, the
#: template of every problem's line (:func:`crankdyn.langs.error_line`).
ARGPARSE_ERROR = "%(prog)s: error: %(message)s\n"


#: argparse's own words in a help (CPython 3.11–3.13) → the text key (area ``cli``).
ARGPARSE_HELP_TEXTS = {
    "usage: ": "cli.argparse.usage",
    "positional arguments": "cli.argparse.positional",
    "options": "cli.argparse.options",
    "optional arguments": "cli.argparse.options",          # its name before 3.10
    "show this help message and exit": "cli.argparse.help",
    "show program's version number and exit": "cli.argparse.version",
}


def _language_asked(argv) -> str:
    """The ``--lang`` of a command line not parsed yet (``--lang X`` or ``--lang=X``),
    or the reports' default, Russian."""
    lang = DEFAULT_LANG
    for i, arg in enumerate(argv):
        if arg == "--lang" and i + 1 < len(argv):
            lang = argv[i + 1]
        elif arg.startswith("--lang="):
            lang = arg.split("=", 1)[1]
    return lang


def _speak_argparse(lang: str) -> None:
    """Give argparse, for this process, the words of ``lang`` (Russian if that language
    is not offered) for its error messages and its help's own headings.

    argparse looks its messages up through the module-level ``_`` it imported from
    :mod:`gettext`; replacing that name is the catalogue hook argparse offers a program
    that has no ``.mo`` files installed.  The catalogues are read only when argparse has
    something to complain about; the headings of a help are the ``cli`` area alone
    (:func:`crankdyn.langs.cli_texts`), so ``crankdyn --help`` stays fast.  A message
    argparse adds in a later Python stays English."""
    words = []

    def t(key, **fields):
        if not words:
            from crankbase.texts import offered, texts

            words.append(texts(lang if offered(lang) else "ru"))
        return words[0](key, **fields)

    class Template(str):
        """A translated template that also names argparse's ``%(type)s`` (the Python
        type of an option: ``float``, ``int``) in the words of the language."""

        def __mod__(self, args):
            if isinstance(args, dict) and args.get("type") in ("float", "int"):
                args = {**args, "type": t(f"errors.argparse.type.{args['type']}")}
            return str.__mod__(self, args)

    def translate(message):
        if message in ARGPARSE_HELP_TEXTS:
            return cli_texts(lang)(ARGPARSE_HELP_TEXTS[message])
        if message == ARGPARSE_ERROR:
            return cli_texts(lang)("cli.error", prog="%(prog)s", message="%(message)s") + "\n"
        key, fields = ARGPARSE_TEXTS.get(message, (None, None))
        return message if key is None else Template(t(key, **fields))

    argparse._ = translate


def _streams_for_every_language():
    """Standard output and error able to print every language's text, so that a report
    already written never ends in a :class:`UnicodeEncodeError` while its summary is
    printed: redirected to a file or a pipe (Windows then writes in the ANSI code page,
    cp1252 or cp1251, which lacks Cyrillic, Greek or "→"), the streams write UTF-8; a
    terminal, or an encoding the user chose with ``PYTHONIOENCODING``, keeps its encoding
    and shows a character it lacks as "?".  A stream without ``reconfigure`` (a test's
    ``StringIO``) is left as it is."""
    for stream in (sys.stdout, sys.stderr):
        if not hasattr(stream, "reconfigure"):
            continue
        enc = (getattr(stream, "encoding", None) or "").lower().replace("_", "-")
        if enc in ("utf-8", "utf8"):
            continue
        try:
            tty = stream.isatty()
        except (OSError, ValueError):
            tty = False
        if tty or os.environ.get("PYTHONIOENCODING"):
            stream.reconfigure(errors="replace")
        else:
            stream.reconfigure(encoding="utf-8")


def main(argv=None) -> int:
    if argv is None:              # the crankdyn command itself, not a call from a script
        _streams_for_every_language()
    argv = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(_language_asked(argv))
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
        print(error_line(args.command, Text("errors.cli.empty_output").render(lang), lang),
              file=sys.stderr)
        return 2
    try:
        return int(args.func(args) or 0)
    except CrankdynError as exc:  # the project's own errors only: anything else is a bug
        for line in exc.lines(lang) or [repr(exc)]:
            print(error_line(args.command, line, lang), file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `crankdyn ... | head`
        sys.stdout = open(os.devnull, "w")
        return 0
    except (FileNotFoundError, IsADirectoryError, PermissionError) as exc:
        why = Text("errors.cli.os_file", {"file": exc.filename, "reason": os_reason(exc)}) \
            if exc.filename is not None else Text("errors.cli.os", {"reason": os_reason(exc)})
        print(error_line(args.command, why.render(lang), lang), file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
