"""The languages ``--lang`` accepts: :data:`crankbase.texts.OFFERED` (every language
whose catalogue is complete, :func:`crankbase.texts.languages`: ru, en, zh …), read only
when argparse checks a value or prints the choices, so ``crankdyn --help`` stays fast."""
from __future__ import annotations

from crankbase.texts import OFFERED

__all__ = ["LANG_CHOICES"]

#: ``choices`` of every subcommand's ``--lang``.
LANG_CHOICES = OFFERED
