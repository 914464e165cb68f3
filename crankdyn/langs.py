"""The languages ``--lang`` accepts, and the words of the command line's own help.

:data:`LANG_CHOICES` is :data:`crankbase.texts.OFFERED` (every language whose catalogue is
complete, :func:`crankbase.texts.languages`: ru, en, zh …), read only when argparse checks
a value or prints the choices.  :func:`cli_texts` is the ``cli`` area of the text layer
(``crankbase/locale/<lang>/cli.po``: every subcommand's ``help``/``description`` and option
help), read alone and without Babel (:func:`crankbase.texts.area_texts`), so that
``crankdyn --help`` stays fast."""
from __future__ import annotations

import functools

from crankbase.texts import OFFERED

__all__ = ["LANG_CHOICES", "LANG_HELP", "DEFAULT_LANG", "cli_texts", "lang_help", "command",
           "report_command", "add_spec_or_example", "add_output", "add_lang", "error_line",
           "warning_line"]

#: ``choices`` of every subcommand's ``--lang``.
LANG_CHOICES = OFFERED

#: The language of the help (and of every report) when ``--lang`` is not given.
DEFAULT_LANG = "ru"

#: The English start of every ``--lang`` help (kept for scripts that used it; the help
#: itself says it in its language: :func:`lang_help`).
LANG_HELP = "one of %(choices)s; "


@functools.lru_cache(maxsize=None)
def cli_texts(lang: str | None = None):
    """The command line's words (the ``cli`` area) in ``lang``; Russian, the reports'
    default, when ``lang`` is None or has no catalogue.  Cached: read once a process."""
    from crankbase.texts import area_texts, catalogue_languages

    if lang not in catalogue_languages():
        lang = DEFAULT_LANG
    return area_texts(lang, "cli")


def error_line(command: str, message: str, lang: str | None = None) -> str:
    """The stderr line of one problem of ``crankdyn <command>`` in ``lang`` (``cli.error``:
    "crankdyn engine: error: …", «crankdyn engine: ошибка: …»); argparse's own complaints
    take the same template (crankdyn/cli.py)."""
    return cli_texts(lang)("cli.error", prog=f"crankdyn {command}", message=message)


def warning_line(command: str, message: str, lang: str | None = None) -> str:
    """The stderr line of one warning of ``crankdyn <command>`` in ``lang``
    (``cli.warning``)."""
    return cli_texts(lang)("cli.warning", prog=f"crankdyn {command}", message=message)


def lang_help(t, key: str) -> str:
    """The help of a ``--lang`` option: the choices (listed when the help is printed; the
    option's metavar is LANG, so that building the parser reads no other catalogue), then
    what the language changes (``key``)."""
    return t("cli.lang.choices") + t(key)


def command(subparsers, name, t=None):
    """Register subcommand ``name`` with its help and description (``cli.<name>.help``,
    ``cli.<name>.description``); returns ``(parser, t)``, ``t`` the help's words
    (:func:`cli_texts`, Russian when not given)."""
    t = t or cli_texts()
    return subparsers.add_parser(name, help=t(f"cli.{name}.help"),
                                 description=t(f"cli.{name}.description")), t


def add_spec_or_example(p, t, name, examples, default):
    """The spec file (``cli.<name>.opt.spec``) or ``--example [NAME]`` (one of
    ``examples``, ``default`` when no name is given)."""
    p.add_argument("spec", nargs="?", metavar="SPEC.toml", help=t(f"cli.{name}.opt.spec"))
    p.add_argument("--example", nargs="?", const=default, metavar="NAME",
                   help=t("cli.common.opt.example", examples=", ".join(examples),
                          default=default))


def add_output(p, t, key="cli.common.opt.output"):
    """``-o DIR``, the output folder (required)."""
    p.add_argument("-o", "--output", required=True, metavar="DIR", help=t(key))


def add_lang(p, t, name):
    """``--lang LANG`` (default Russian), its help ``cli.<name>.opt.lang``."""
    p.add_argument("--lang", choices=LANG_CHOICES, metavar="LANG", default=DEFAULT_LANG,
                   help=lang_help(t, f"cli.{name}.opt.lang"))


def report_command(subparsers, name, t, examples, default):
    """A subcommand that writes a report from a spec or a bundled example: :func:`command`,
    then :func:`add_spec_or_example`, :func:`add_output` and :func:`add_lang`; returns
    ``(parser, t)`` for the command's own options."""
    p, t = command(subparsers, name, t)
    add_spec_or_example(p, t, name, examples, default)
    add_output(p, t)
    add_lang(p, t, name)
    return p, t
