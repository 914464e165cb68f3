"""The one text layer: every word that crankdyn shows, keyed, in every language.

Words live in gettext catalogues, one folder per language and one ``.po`` file per area
(``crankbase/locale/<lang>/<area>.po``: ``common``, ``engine``, ``linkage``, ``dynamics``,
``errors`` …; a key's first dotted part names its area: ``engine.summary.title`` lives in
``engine.po``).  The ``msgid`` is the key, the ``msgstr`` the text in that language; the
English catalogue is the reference, and every other language must hold every one of its
keys (a test checks this, and that each translation uses the same ``{fields}``).  A text
is a :meth:`str.format` template: numbers are passed in and formatted by the template, so
a translator controls word order.

Plural forms are gettext's: an entry with ``msgid_plural`` has one ``msgstr[i]`` per form
of its language, chosen by the ``Plural-Forms`` rule in the catalogue's header (Russian has
three: «1 график», «3 графика», «22 графика», «5 графиков»).

At run time the catalogues are read compiled, by the standard library alone: each
``<lang>/<area>.po`` has its ``<lang>/LC_MESSAGES/<area>.mo`` (the layout
:func:`gettext.translation` looks in, domain = area), read by
:class:`gettext.GNUTranslations` (:func:`read_mo`), which also compiles the plural rule
of the ``.mo`` header; the areas of a language are merged into one table (a key in two
areas is a :class:`CatalogueError` naming both).  Only the language asked and the
reference are read (:func:`offered`), every catalogue only when the list of offered
languages is asked (:func:`languages`).  The ``.mo`` files are made from the ``.po``
files by the developers' tool ``python crankbase/locale/compile_catalogues.py`` (Babel's
``read_po`` and ``write_mo``; deterministic: the same ``.po``, the same bytes) and
committed with them; a test compiles every ``.po`` and fails on a ``.mo`` that differs.

Adding a language is filling a catalogue, not changing code: copy ``locale/en`` to
``locale/<lang>``, set the header's ``Language`` and ``Plural-Forms``, translate every
``msgstr``, compile (``python crankbase/locale/compile_catalogues.py``); the language is
offered (:func:`languages`) once its catalogue is complete.  The catalogue also says the
language's notation, which the code asks through
:class:`Texts` and never by comparing language codes: ``common.format.symbols`` (the
symbol set, :attr:`Texts.symbols`: ``ru`` the Russian textbook's, ``en`` Latin),
``common.format.decimal_sign`` (:meth:`Texts.number`) and one ``common.unit.<name>`` per
unit the tool writes (:meth:`Texts.unit`; the one table of units is :data:`UNITS`).

A template names a unit by that table, never by spelling it: the field ``{unit[N·m]}``
(the unit's international spelling, a key of :data:`UNITS`) is the unit as the template's
own catalogue spells it («Mкр.ср = {M:.1f} {unit[N·m]}» gives «Mкр.ср = 12.3 Н·м»).
:class:`Texts` fills the unit fields before anything else, so a text asked without fields
(a word table formatted later by a plot, a sheet, the web pages) comes with its units
written and its other fields left for the caller; a test checks that no template spells
a unit after a number or a field.  The symbols the textbooks write differently are the
catalogue's too (``linkage.symbol.*``, ``dynamics.symbol.*``: the table columns), so a
language chooses its own by filling those keys.

Examples
--------
>>> from crankbase.texts import texts
>>> t = texts("ru")
>>> t.n("common.plots", 22)
'22 графика'
>>> texts("en").n("common.plots", 1)
'1 plot'
"""
from __future__ import annotations

import functools
import gettext
import re
import string
import struct
from collections.abc import Sequence
from pathlib import Path

__all__ = ["Texts", "texts", "area_texts", "read_area", "read_mo", "read_po", "mo_path",
           "languages", "offered", "catalogue_languages", "keys", "CatalogueError",
           "LOCALE_DIR", "MO_FOLDER", "COMPILE_COMMAND", "REFERENCE", "OfferedLanguages",
           "OFFERED", "SYMBOL_SETS", "UNITS", "unit_key", "UNIT_FIELD"]

#: Folder of the catalogues (shipped as package data of ``crankbase``).
LOCALE_DIR = Path(__file__).resolve().parent / "locale"

#: The reference language: every other catalogue must hold every one of its keys.
REFERENCE = "en"

#: The symbol sets a catalogue may name in ``common.format.symbols`` (:attr:`Texts.symbols`).
SYMBOL_SETS = ("ru", "en")

#: Every unit the tool writes, in its international spelling → the name of its key
#: ``common.unit.<name>`` (:meth:`Texts.unit`; :func:`unit_key`): the one table of units
#: (the spec schemas' :attr:`~crankbase.schema.Key.unit`, the column-suffix tables of the
#: reports, the sheets' rows and the templates name their units here; a test checks
#: it).  ``"°"`` is the degree sign (the spec reference, the inputs sheets); ``"deg"`` is
#: the degree of a column header and a sheet's unit column, written as the catalogue says
#: ("φ [deg]" in English, «φ, °» in Russian, "φ [°]" in Chinese).  ``"-"`` is a
#: dimensionless number.
UNITS = {
    # length, area, volume, mass
    "m": "m", "mm": "mm", "cm²": "cm2", "l": "l", "g": "g", "kg": "kg",
    "kg/m²": "kg_per_m2", "kg·mm": "kg_mm", "g·mm": "g_mm", "kg·m²": "kg_m2",
    # time, angle, motion
    "s": "s", "Hz": "Hz", "°": "deg", "deg": "deg_word", "rad": "rad", "rpm": "rpm",
    "m/s": "m_s", "m/s²": "m_s2", "rad/s": "rad_s", "rad/s²": "rad_s2",
    # force, moment, stiffness, damping, pressure, energy, power
    "N": "N", "N/mm": "N_per_mm", "N·m": "N_m", "N·m/rad": "N_m_per_rad",
    "N·m·s/rad": "N_m_s_per_rad", "Pa": "Pa", "kPa": "kPa", "bar": "bar", "MPa": "MPa",
    "J": "J", "kW": "kW",
    # ratios
    "%": "percent", "-": "one",
}


#: A unit field of a template: ``{unit[N·m]}`` (:meth:`Texts.__call__`).
UNIT_FIELD = re.compile(r"(?<!\{)\{unit\[([^\[\]{}]+)\]\}")


def unit_key(si: str) -> str:
    """The catalogue key of a unit of :data:`UNITS` (``"N·m"`` → ``"common.unit.N_m"``),
    for a :class:`~crankbase.errors.Text` rendered later; a unit the table does not name is
    a programming error (:class:`KeyError`): add it to :data:`UNITS` and every catalogue."""
    try:
        return f"common.unit.{UNITS[si]}"
    except KeyError:
        raise KeyError(f"unit {si!r} is not in crankbase.texts.UNITS") from None


class Texts:
    """The texts of one language.

    Call it with a key and the template's fields: ``t("common.wrote", files="a.csv",
    folder="out")``; :meth:`n` chooses a plural form by a count.  A key missing from this
    language's catalogue falls back to the reference language (English); a key missing
    there too is a programming error (:class:`KeyError`).
    """

    def __init__(self, lang: str, translations, keys: frozenset, fallback=None):
        self.lang = lang
        self._tr = translations
        self._keys = keys
        self._fallback = fallback
        self._filled: dict = {}         # template → its unit fields written (_units)

    def _source(self, key):
        if key in self._keys:
            return self
        if self._fallback is not None and key in self._fallback._keys:
            return self._fallback
        raise KeyError(f"text key {key!r} is in no catalogue ({self.lang}, {REFERENCE})")

    def __call__(self, key: str, /, **fields) -> str:
        src = self._source(key)
        template = src._units(src._tr.gettext(key))
        return template.format(**fields) if fields else template

    def n(self, key: str, count, /, **fields) -> str:
        """The plural form of ``key`` for ``count`` (passed to the template as ``n``)."""
        src = self._source(key)
        template = src._units(src._tr.ngettext(key, key, int(count)))
        return template.format(n=count, **fields)

    def _units(self, template: str) -> str:
        """``template`` with its unit fields (``{unit[N·m]}``, :data:`UNIT_FIELD`) written
        as this catalogue spells the units (:meth:`unit`), its other fields left as they
        are; cached by template.  The units are the catalogue's whose template it is (an
        English text a language lacks keeps its English units)."""
        if "{unit[" not in template:
            return template
        done = self._filled.get(template)
        if done is None:
            done = self._filled[template] = UNIT_FIELD.sub(
                lambda m: self.unit(m.group(1)), template)
        return done

    # -- the notation of this language: which symbols, how units and numbers are spelled.
    # A catalogue says it (common.format.*, common.unit.*); code asks here and never
    # compares a language code (a test checks that no other module does).

    @property
    def symbols(self) -> str:
        """The symbol set this language's reports use (``common.format.symbols``):
        ``"ru"``, the Russian textbook's (Рг, Мкр, Fпс), or ``"en"``, Latin and Greek
        (Pg, M, Fr; the English and the Chinese textbooks')."""
        value = self("common.format.symbols")
        if value not in SYMBOL_SETS:
            raise ValueError(f"{self.lang}: common.format.symbols is {value!r}; one of "
                             + ", ".join(SYMBOL_SETS))
        return value

    def symbol(self, ru, en):
        """``ru`` or ``en`` by this language's :attr:`symbols`: the one of two spellings
        (of a symbol, a label, a symbol table) that its symbol set writes."""
        return ru if self.symbols == "ru" else en

    def unit(self, si: str) -> str:
        """A unit of :data:`UNITS`, given in its international spelling (``"N·m"``,
        ``"m/s²"``), as this language spells it (``common.unit.<name>``: «Н·м» in
        Russian); "" for no unit.  A unit the table does not name is a
        :class:`KeyError` (one table, so that no unit is spelled twice)."""
        return self(unit_key(si)) if si else ""

    @property
    def decimal_sign(self) -> str:
        """The decimal separator of this language's drawings
        (``common.format.decimal_sign``: "," in Russian, "." in English)."""
        return self("common.format.decimal_sign")

    def number(self, text: str) -> str:
        """A number already formatted with a decimal point (``f"{x:.2f}"``), with this
        language's :attr:`decimal_sign`."""
        sign = self.decimal_sign
        return text if sign == "." else text.replace(".", sign)

    def has(self, key: str) -> bool:
        """Whether this language's own catalogue (not the fallback) holds ``key``."""
        return key in self._keys

    def __repr__(self):
        return f"Texts({self.lang!r}, {len(self._keys)} keys)"


def catalogue_languages() -> tuple[str, ...]:
    """Every language with a compiled catalogue (``<lang>/LC_MESSAGES/*.mo``), complete
    or not.  The folder :data:`LOCALE_DIR` is listed once a process (as each catalogue is
    read once, :func:`_catalogue`): a report asks it for every column it labels."""
    return _catalogue_languages(LOCALE_DIR)


@functools.lru_cache(maxsize=None)
def _catalogue_languages(folder: Path) -> tuple[str, ...]:
    """:func:`catalogue_languages` of one locale folder."""
    return tuple(sorted(p.name for p in folder.iterdir()
                        if p.is_dir() and any((p / MO_FOLDER).glob("*.mo"))))


class CatalogueError(ValueError):
    """A catalogue that cannot be used: a compiled ``.mo`` missing, broken or out of step
    with the ``.po`` files beside it (run ``python crankbase/locale/compile_catalogues.py``), a key
    in two areas of one language, areas of one language with different
    ``Plural-Forms``; and, from the developers' compiler, a ``.po`` that is no ``.po``
    syntax, a key twice in one file, a plural entry without all its forms."""


#: The folder of a language's compiled catalogues (``locale/<lang>/LC_MESSAGES/<area>.mo``:
#: where :func:`gettext.translation` and :func:`gettext.find` look for domain ``<area>``).
MO_FOLDER = "LC_MESSAGES"

#: The command that compiles the ``.po`` files into the ``.mo`` files (a developer's
#: tool of the repository, needing Babel; users never run it).
COMPILE_COMMAND = "python crankbase/locale/compile_catalogues.py"

_DEFAULT_PLURAL = ("nplurals=2; plural=(n != 1);", 2, "(n != 1)")


def mo_path(lang: str, area: str) -> Path:
    """The compiled catalogue of one area of one language:
    ``LOCALE_DIR/<lang>/LC_MESSAGES/<area>.mo``."""
    return LOCALE_DIR / lang / MO_FOLDER / f"{area}.mo"


def read_mo(path: Path) -> gettext.GNUTranslations:
    """One compiled catalogue read by the standard library (:class:`gettext.GNUTranslations`:
    its texts, its plural rule compiled from the ``Plural-Forms`` of its header).  A
    missing or unreadable file is a :class:`CatalogueError` naming it and the command that
    compiles it."""
    where = f"{path.parent.parent.name}/{path.parent.name}/{path.name}"
    try:
        with open(path, "rb") as fh:
            return gettext.GNUTranslations(fh)
    except FileNotFoundError:
        raise CatalogueError(f"{where}: no compiled catalogue; run {COMPILE_COMMAND}") from None
    except (OSError, ValueError, struct.error, IndexError) as exc:
        raise CatalogueError(f"{where}: not a compiled catalogue ({exc}); "
                             f"run {COMPILE_COMMAND}") from None


def _areas(lang: str) -> list[str]:
    """The areas of ``lang``: its compiled catalogues, which must be those of its ``.po``
    files where these are present (a source tree, a wheel); else a
    :class:`CatalogueError` naming the files out of step."""
    folder = LOCALE_DIR / lang
    compiled = {p.stem for p in (folder / MO_FOLDER).glob("*.mo")}
    sources = {p.stem for p in folder.glob("*.po")}
    if sources and sources != compiled:
        lost = [f"{lang}/{a}.po (no {MO_FOLDER}/{a}.mo)" for a in sorted(sources - compiled)]
        lost += [f"{lang}/{MO_FOLDER}/{a}.mo (no {a}.po)" for a in sorted(compiled - sources)]
        raise CatalogueError(f"catalogues out of step: {', '.join(lost)}; "
                             f"run {COMPILE_COMMAND}")
    return sorted(compiled)


@functools.lru_cache(maxsize=None)
def _catalogue(lang: str):
    """``(GNUTranslations, keys)`` of one language: every compiled area of its folder
    (:func:`read_mo`) merged into one table; a key in two areas, or two areas with
    different ``Plural-Forms``, is a :class:`CatalogueError` naming both."""
    areas = _areas(lang)
    if not areas:
        raise KeyError(lang)
    merged = None
    owner: dict = {}
    for area in areas:
        tr = read_mo(mo_path(lang, area))
        rule = tr.info().get("plural-forms")
        if merged is None:
            merged, first = tr, (area, rule)
        elif rule != first[1]:
            raise CatalogueError(f"{lang}/{area}.po: Plural-Forms {rule!r}; "
                                 f"{lang}/{first[0]}.po says {first[1]!r}")
        for entry in tr._catalog:      # key → text, (key, i) → plural form i; "" the header
            key = entry if type(entry) is str else entry[0]
            if owner.setdefault(key, area) != area and key:
                raise CatalogueError(f"key {key!r} is in {lang}/{owner[key]}.po and in "
                                     f"{lang}/{area}.po")
        if tr is not merged:
            merged._catalog.update(tr._catalog)
    merged._catalog.pop("", None)
    owner.pop("", None)
    return merged, frozenset(owner)


@functools.lru_cache(maxsize=None)
def texts(lang: str = "ru") -> Texts:
    """The :class:`Texts` of ``lang`` (a :func:`catalogue_languages` code), cached.  A
    language given by a user is checked first with
    :func:`crankbase.validation.check_lang` (a :class:`~crankbase.errors.SpecError`)."""
    if lang not in catalogue_languages():
        raise KeyError(f"no text catalogue for language {lang!r}; there are: "
                       + ", ".join(catalogue_languages()))
    tr, keys = _catalogue(lang)
    fallback = None if lang == REFERENCE else texts(REFERENCE)
    return Texts(lang, tr, keys, fallback)


def read_area(lang: str, area: str) -> dict[str, str]:
    """``{key: text}`` of one area's compiled catalogue
    (``locale/<lang>/LC_MESSAGES/<area>.mo``) alone, read by :func:`read_mo`.  For an
    area read on a fast path (the command line's ``--help``, area ``cli``); it holds
    singular entries only (a plural entry is a :class:`CatalogueError`)."""
    out = {}
    for key, text in read_mo(mo_path(lang, area))._catalog.items():
        if type(key) is not str:
            raise CatalogueError(f"{lang}/{area}.po: {key[0]!r} is a plural entry; "
                                 "read_area reads singular entries only")
        if key:
            out[key] = text
    return out


def read_po(path: Path):
    """``(plural_forms, entries)`` of one area as before session 11, now read from its
    compiled catalogue (``<lang>/<area>.po`` → ``<lang>/LC_MESSAGES/<area>.mo``, by
    :func:`read_mo`): ``plural_forms`` is ``(Plural-Forms value, nplurals, plural
    expression)``, ``entries`` a ``{key: text}`` in key order whose plural entries are
    tuples of their forms.  Kept for earlier callers; the ``.po`` text itself is read
    only by the developers' compiler (``crankbase/locale/compile_catalogues.py``, Babel)."""
    path = Path(path)
    tr = read_mo(path.parent / MO_FOLDER / f"{path.stem}.mo")
    value = tr.info().get("plural-forms")
    if value is None:
        plural = _DEFAULT_PLURAL
    else:
        params = dict(p.strip().partition("=")[::2] for p in value.split(";") if p.strip())
        plural = (value, int(params["nplurals"]), params["plural"].strip())
    entries: dict = {}
    order = sorted((k, -1) if type(k) is str else k for k in tr._catalog if k != "")
    for entry in (k if i == -1 else (k, i) for k, i in order):
        if type(entry) is str:
            entries[entry] = tr._catalog[entry]
        else:
            entries[entry[0]] = entries.get(entry[0], ()) + (tr._catalog[entry],)
    return plural, entries


class _AreaTranslations:
    """The two look-ups :class:`Texts` makes, over one area's ``{key: text}``."""

    def __init__(self, words):
        self._words = words

    def gettext(self, key):
        return self._words[key]

    def ngettext(self, key, plural, n):  # read_area refuses plural entries
        return self._words[key]


def _unit_words(lang: str) -> dict[str, str]:
    """The ``common.unit.*`` entries of ``lang``'s compiled ``common`` catalogue alone
    (:func:`read_mo`): what an area read alone (:func:`area_texts`) needs for its
    templates' unit fields."""
    path = mo_path(lang, "common")
    if not path.is_file():
        return {}
    return {k: v for k, v in read_mo(path)._catalog.items()
            if type(k) is str and k.startswith("common.unit.")}


@functools.lru_cache(maxsize=None)
def area_texts(lang: str, area: str) -> Texts:
    """The :class:`Texts` of one area only (:func:`read_area`), cached: read once a process,
    a key missing in ``lang`` falls back to English's same area.  For the command line's
    help (area ``cli``), which needs no other area (:func:`texts` reads every area of the
    language and of English); the keys are the same as :func:`texts` gives."""
    if lang not in catalogue_languages():
        raise KeyError(f"no text catalogue for language {lang!r}; there are: "
                       + ", ".join(catalogue_languages()))
    words = read_area(lang, area) if mo_path(lang, area).is_file() else {}
    if any("{unit[" in text for text in words.values()):
        words = {**words, **_unit_words(lang)}      # its templates' unit fields
    fallback = None if lang == REFERENCE else area_texts(REFERENCE, area)
    return Texts(lang, _AreaTranslations(words), frozenset(words), fallback)


def keys(lang: str = REFERENCE) -> frozenset:
    """Every key of ``lang``'s own catalogue."""
    return _catalogue(lang)[1]


def offered(lang) -> bool:
    """Whether ``lang`` is offered (:func:`languages`): it has a catalogue holding every
    key of the reference catalogue.  Reads that language and the reference only, not
    every catalogue: what a ``--lang`` check needs."""
    return isinstance(lang, str) and _offered(LOCALE_DIR, lang)


@functools.lru_cache(maxsize=None)
def _offered(folder: Path, lang: str) -> bool:
    """:func:`offered` of ``lang`` in one locale folder, answered once a process (as the
    catalogues are read once): a report asks it for every column it labels."""
    return lang in _catalogue_languages(folder) and keys(REFERENCE) <= keys(lang)


@functools.lru_cache(maxsize=None)
def languages() -> tuple[str, ...]:
    """The languages offered for reports: those whose catalogue holds every key of the
    reference catalogue (Russian first, the default of the course projects).  Reads every
    catalogue; whether one language is offered is :func:`offered`."""
    done = [lang for lang in catalogue_languages() if offered(lang)]
    return tuple(sorted(done, key=lambda code: (code != "ru", code != "en", code)))


class OfferedLanguages(Sequence):
    """:func:`languages` as a lazy, read-only sequence: the catalogues are read when it
    is first asked (``"zh" in OFFERED``, iterated, indexed), not when it is imported, so
    a module constant or argparse ``choices`` can be it at no cost."""

    def __getitem__(self, i):
        return languages()[i]

    def __len__(self):
        return len(languages())

    def __contains__(self, value):
        return offered(value)          # reads that one catalogue, not all

    def __repr__(self):
        return f"OfferedLanguages({languages()!r})"


#: The offered languages (:func:`languages`), lazily: ``lang in OFFERED``.
OFFERED = OfferedLanguages()


def fields(template: str) -> set[str]:
    """The names of a template's ``{fields}`` that its caller fills (for the catalogue
    checks); its unit fields (``{unit[N·m]}``, :data:`UNIT_FIELD`) are the text layer's,
    not the caller's, and a language may name a unit where another writes none."""
    return {re.split(r"[.\[]", f)[0] for _, f, _, _ in string.Formatter().parse(template)
            if f is not None and not (f.startswith("unit[") and f.endswith("]"))}
