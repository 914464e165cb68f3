"""The rule by which a test says a text is in one language (tests/test_cli_help.py,
tests/test_workbook_languages.py): what is typed rather than read is taken out first, then

- Russian: no Latin word of two or more letters is left (but the textbooks' Latin
  :data:`SYMBOLS`);
- English: no Cyrillic letter at all;
- Chinese: no Cyrillic letter, and no Latin word left but SI :data:`UNITS` and
  :data:`SYMBOLS` (a help line: every line that holds one has a CJK character).

Taken out: `code spans`, ``%`` specifiers, the words given (option names, metavars,
choices, example names, the names a spec gives), file names and paths, TOML table names,
identifiers with an underscore or an ``=``, all-capital acronyms (CSV, TOML, PDF, KKM)."""
from __future__ import annotations

import re

CYRILLIC = re.compile(r"[А-Яа-яЁё]")
CJK = re.compile(r"[\u4e00-\u9fff]")
#: The textbooks' Latin symbols a Russian text writes as printed: Pj (inertia force of the
#: reciprocating masses), Kr (Kr.ш, the rod's centrifugal force), pa (the velocity plan's
#: segment from the pole), tg/cos/sin (the Russian names of the functions).
SYMBOLS = frozenset({"Pj", "Kr", "pa", "tg", "cos", "sin"})
#: SI unit symbols, which a Chinese text writes in Latin letters (GB 3102).
UNITS = frozenset({"mm", "Hz", "rad", "MPa", "kg", "rpm", "min"})
_FILE = re.compile(r"\S*(?:[_/<>=\[\]|]|\.(?:csv|xlsx|xlsm|toml|png|svg|pdf|dxf)\b)\S*")
_LATIN = re.compile(r"(?<![\w])[A-Za-z]{2,}(?![\w])")


def _blank(m):
    return re.sub(r"[^\n]", " ", m.group(0))


def reading_text(text: str, typed=()) -> str:
    """``text`` without what is typed rather than read; its lines kept (what is taken out
    becomes spaces)."""
    text = re.sub(r"`[^`]*`", _blank, text)
    text = re.sub(r"%\(\w+\)s|%%", " ", text)
    for word in sorted(typed, key=len, reverse=True):
        text = re.sub(rf"(?<!\w){re.escape(word)}(?!\w)", _blank, text)
    text = _FILE.sub(_blank, text)
    return re.sub(r"\b[A-Z][A-Z0-9]+\b", _blank, text)


def latin_words(text: str, typed=(), allowed=SYMBOLS) -> list[str]:
    """The Latin words left in ``text`` once the typed words are out, but ``allowed``."""
    return [w for w in _LATIN.findall(reading_text(text, typed)) if w not in allowed]
