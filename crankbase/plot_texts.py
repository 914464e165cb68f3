"""The words of the figures (titles, axis labels, legends, annotations), read from the
``plot`` catalogue of the text layer (:mod:`crankbase.texts`, ``locale/<lang>/plot.po``).

``plot_words(lang, area)`` is ``{name: text}`` of the keys ``plot.<area>.<name>``; a
dotted name below it (``plot.bearing.axis.pin``) becomes a nested dict (``["axis"]
["pin"]``).  A text with ``{fields}`` stays a template for the plot to fill; a text
without is returned as drawn (its doubled mathtext braces ``$M_{{mean}}$`` undone).

The one place the figures get their font is here too (:func:`plot_fonts`, applied by
:func:`plot_words`): DejaVu Sans (matplotlib's own, Latin, Greek and Cyrillic) first, then
the common system fonts with Chinese glyphs (:data:`CJK_FONTS`), which matplotlib ≥ 3.6
falls back to glyph by glyph; PDFs embed their fonts as TrueType (Type 42).
"""
from __future__ import annotations

import functools
import re

__all__ = ["plot_words", "plot_fonts", "cjk_fonts", "plain_math", "cjk_texts",
           "figure_texts", "CJK_FONTS", "FONT_FAMILY"]

#: Fonts with Chinese glyphs, tried in this order after DejaVu Sans: Linux (Noto Sans CJK /
#: Source Han Sans: fonts-noto-cjk; WenQuanYi Zen Hei: fonts-wqy-zenhei; Droid Sans
#: Fallback: fonts-droid-fallback), Windows (Microsoft YaHei, SimHei), macOS (PingFang SC).
CJK_FONTS = ("Noto Sans CJK SC", "Source Han Sans SC", "WenQuanYi Zen Hei",
             "Microsoft YaHei", "SimHei", "PingFang SC", "Hiragino Sans GB",
             "Droid Sans Fallback")

#: The sans-serif list of every figure: matplotlib's DejaVu Sans first (every Latin,
#: Greek and Cyrillic glyph as before), then the CJK fonts as per-glyph fallback.
FONT_FAMILY = ("DejaVu Sans",) + CJK_FONTS

#: Languages whose words need a CJK font.
CJK_LANGS = ("zh",)


#: Parts of the file names of the :data:`CJK_FONTS` (lower case), to find them when
#: matplotlib's font cache was built before they were installed.
CJK_FILES = ("notosanscjk", "notoserifcjk", "sourcehansans", "wqy-zenhei", "wqy-microhei",
             "msyh", "simhei", "pingfang", "hiragino", "droidsansfallback")


@functools.lru_cache(maxsize=None)
def cjk_fonts() -> tuple:
    """The fonts of :data:`CJK_FONTS` installed on this machine.  Those matplotlib's font
    cache lacks (installed after the cache was built) are looked for among the system's
    font files by name (:data:`CJK_FILES`) and added to matplotlib's font manager."""
    from matplotlib import font_manager

    fm = font_manager.fontManager
    names = {f.name for f in fm.ttflist}
    if not names & set(CJK_FONTS):
        for path in font_manager.findSystemFonts():
            base = path.replace("\\", "/").rsplit("/", 1)[-1].lower().replace(" ", "")
            if any(part in base for part in CJK_FILES):
                try:
                    fm.addfont(path)
                except (OSError, RuntimeError, ValueError):   # unreadable font file
                    continue
        names = {f.name for f in fm.ttflist}
    return tuple(n for n in CJK_FONTS if n in names)


_warned = set()


def plot_fonts(lang: str = "ru") -> tuple:
    """Set matplotlib's fonts for the figures of ``lang``; return the CJK fonts used.

    Every language: the sans-serif list starts with :data:`FONT_FAMILY` and PDFs and
    PostScript embed TrueType (Type 42) fonts.  A language written in Chinese characters
    (``zh``): the font family becomes DejaVu Sans followed by every installed font of
    :data:`CJK_FONTS` (matplotlib falls back glyph by glyph; only installed ones, so
    matplotlib logs no missing family); with none installed it warns once (a
    :class:`UserWarning` naming the fonts to install) instead of drawing empty boxes
    silently."""
    import matplotlib

    rc = matplotlib.rcParams
    if tuple(rc["font.sans-serif"][:len(FONT_FAMILY)]) != FONT_FAMILY:
        rc["font.sans-serif"] = list(FONT_FAMILY) + [
            f for f in rc["font.sans-serif"] if f not in FONT_FAMILY]
    rc["pdf.fonttype"] = 42
    rc["ps.fonttype"] = 42
    found = cjk_fonts() if lang in CJK_LANGS else ()
    if found:
        rc["font.family"] = [FONT_FAMILY[0], *found]
        # a CJK font with one weight only (Droid Sans Fallback) draws bold titles in its
        # regular weight; matplotlib would log that once per font in English
        import logging

        logging.getLogger("matplotlib.font_manager").setLevel(logging.ERROR)
    if lang in CJK_LANGS and not found and lang not in _warned:
        import warnings

        _warned.add(lang)
        warnings.warn(
            "no font with Chinese glyphs found, so the figures' Chinese words will show as "
            "empty boxes; install one of: " + ", ".join(CJK_FONTS)
            + " (Debian/Ubuntu: apt install fonts-noto-cjk or fonts-wqy-zenhei; Windows "
            "and macOS ship Microsoft YaHei / PingFang SC)", UserWarning, stacklevel=2)
    return found


#: Characters that need a CJK font: CJK punctuation, ideographs, full-width forms.
_CJK = re.compile("[\u3000-\u303f\u3400-\u4dbf\u4e00-\u9fff\uff00-\uffef]")
_MATH = re.compile(r"(?<!\\)\$(.+?)(?<!\\)\$")
_SUB = dict(zip("0123456789aehijklmnoprstuvx+-=()",
                "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ₊₋₌₍₎"))
_COMMANDS = {"\\Delta": "Δ", "\\delta": "δ", "\\omega": "ω", "\\varphi": "φ",
             "\\phi": "φ", "\\alpha": "α", "\\mu": "μ", "\\,": " ", "\\ ": " "}


def plain_math(text: str) -> str:
    """``text`` with its mathtext (``$…$``) set as plain Unicode: a subscript in Unicode
    subscript letters where a subscript of two or more letters has them all
    (``$M_{mean}$`` → "Mₘₑₐₙ"), else on the line ("$R_{cp}$" → "Rcp", "$F_x$" → "Fx"); ``\\Delta`` → Δ.  Matplotlib's mathtext draws its plain parts
    in one font without fallback, so a label mixing mathtext and Chinese would show boxes;
    as plain text every glyph falls back to a CJK font (:func:`plot_fonts`)."""
    def one(m):
        body = m.group(1)
        for cmd, ch in _COMMANDS.items():
            body = body.replace(cmd + " ", ch).replace(cmd, ch)

        def sub(g):
            part = g.group(1) or g.group(2)
            return ("".join(_SUB[c] for c in part)
                    if len(part) > 1 and all(c in _SUB for c in part) else part)
        body = re.sub(r"_\{([^{}]*)\}|_(\w)", sub, body)
        return body.replace("{", "").replace("}", "")
    return _MATH.sub(one, text)


def figure_texts(fig):
    """Every :class:`matplotlib.text.Text` of ``fig``, as ``fig.findobj(Text)`` finds
    them, but without making an axis's ticks: ``Axis.get_children`` asks for as many
    ticks as the locator gives (each a tick of two lines, a grid line and two labels,
    a third of the CPU of a figure that is built and not drawn).  The ticks an axis
    already has are walked (a label set with ``set_ticklabels`` is on them); a tick
    made later, when the figure is drawn, gets its label's text from the formatter
    then, so none holds a text yet."""
    from matplotlib.axis import Axis
    from matplotlib.text import Text

    stack = [fig]
    while stack:
        art = stack.pop()
        if isinstance(art, Text):
            yield art
        if isinstance(art, Axis):
            made = vars(art)                 # the lazy tick lists, once made
            children = [art.label, art.offsetText, *made.get("majorTicks", ()),
                        *made.get("minorTicks", ())]
        else:
            children = art.get_children()
        stack.extend(reversed(children))


def cjk_texts(fig) -> int:
    """Every text of ``fig`` that holds Chinese characters: drawn in DejaVu Sans with the
    installed CJK fonts as fallback (:func:`plot_fonts`), and its mathtext set as plain
    Unicode (:func:`plain_math`); returns the number of texts whose mathtext changed.  Texts without Chinese characters
    (every Russian and English figure) are left exactly as they are.  No tick is made
    for the search (:func:`figure_texts`)."""
    n = 0
    family = None
    for art in list(figure_texts(fig)):
        s = art.get_text()
        if not _CJK.search(s):
            continue
        if family is None:
            family = [FONT_FAMILY[0], *plot_fonts("zh")]
        if len(family) > 1:
            art.set_fontfamily(family)     # drawn before plot_fonts was called: its fonts
        if "$" in s:
            new = plain_math(s)
            if new != s:
                art.set_text(new)
                n += 1
    return n


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
    """``{name: text}`` of the plot words ``plot.<area>.*`` in ``lang`` (a copy); sets
    the figures' fonts for ``lang`` (:func:`plot_fonts`)."""
    import copy

    plot_fonts(lang)

    return copy.deepcopy(_words(lang, area))
