"""The languages ``--lang`` accepts: :data:`crankbase.texts.OFFERED` (every language
whose catalogue is complete, :func:`crankbase.texts.languages`: ru, en, zh …), read only
when argparse checks a value or prints the choices, so ``crankdyn --help`` stays fast."""
from __future__ import annotations

from crankbase.texts import OFFERED

__all__ = ["LANG_CHOICES", "LANG_HELP"]

#: ``choices`` of every subcommand's ``--lang``.
LANG_CHOICES = OFFERED

#: The start of every ``--lang`` help: the choices, listed when the help is printed (the
#: option's metavar is LANG, so that building the parser reads no catalogue).
LANG_HELP = "one of %(choices)s; "
