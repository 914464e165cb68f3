"""The words of the figures (titles, axis labels, legends, annotations), read from the
``plot`` catalogue of the text layer (:mod:`crankbase.texts`, ``locale/<lang>/plot.po``).

``plot_words(lang, area)`` is ``{name: text}`` of the keys ``plot.<area>.<name>``; a
dotted name below it (``plot.bearing.axis.pin``) becomes a nested dict (``["axis"]
["pin"]``).  A text with ``{fields}`` stays a template for the plot to fill; a text
without is returned as drawn (its doubled mathtext braces ``$M_{{mean}}$`` undone).
"""
from __future__ import annotations

import functools

__all__ = ["plot_words"]


@functools.lru_cache(maxsize=None)
def _words(lang, area):
    from .texts import REFERENCE, fields, keys, texts

    t = texts(lang)
    prefix = f"plot.{area}."
    out = {}
    for key in sorted(keys(REFERENCE)):
        if not key.startswith(prefix):
            continue
        text = t(key)
        if not fields(text):
            text = text.format()
        *parents, name = key[len(prefix):].split(".")
        d = out
        for p in parents:
            d = d.setdefault(p, {})
        d[name] = text
    return out


def plot_words(lang: str, area: str) -> dict:
    """``{name: text}`` of the plot words ``plot.<area>.*`` in ``lang`` (a copy)."""
    import copy

    return copy.deepcopy(_words(lang, area))
