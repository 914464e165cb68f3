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

__all__ = ["LANG_CHOICES", "LANG_HELP", "DEFAULT_LANG", "cli_texts", "lang_help"]

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


def lang_help(t, key: str) -> str:
    """The help of a ``--lang`` option: the choices (listed when the help is printed; the
    option's metavar is LANG, so that building the parser reads no other catalogue), then
    what the language changes (``key``)."""
    return t("cli.lang.choices") + t(key)
