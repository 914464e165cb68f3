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
three: «1 график», «3 графика», «22 графика», «5 графиков»).  The catalogues are read with
the standard library (:func:`read_po`: a few milliseconds a language, where Babel's
``read_po`` and ``write_mo`` took ~0.1 s) and looked up through its
:class:`gettext.GNUTranslations`, the plural rule compiled by :func:`gettext.c2py`; only
the language asked and the reference are read (:func:`offered`), every catalogue only when
the list of offered languages is asked (:func:`languages`).  A test checks the reading
against Babel's of every catalogue.

Adding a language is filling a catalogue, not changing code: copy ``locale/en`` to
``locale/<lang>``, set the header's ``Language`` and ``Plural-Forms``, translate every
``msgstr``; the language is offered (:func:`languages`) once its catalogue is complete.
The catalogue also says the language's notation, which the code asks through
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
from collections.abc import Sequence
from pathlib import Path

__all__ = ["Texts", "texts", "area_texts", "read_area", "read_po", "languages", "offered",
           "catalogue_languages", "keys", "CatalogueError", "LOCALE_DIR", "REFERENCE",
           "OfferedLanguages", "OFFERED", "SYMBOL_SETS", "UNITS", "unit_key", "UNIT_FIELD"]

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
    "s": "s", "°": "deg", "deg": "deg_word", "rad": "rad", "rpm": "rpm",
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
    """Every language with a catalogue folder, complete or not."""
    return tuple(sorted(p.name for p in LOCALE_DIR.iterdir()
                        if p.is_dir() and any(p.glob("*.po"))))


class CatalogueError(ValueError):
    """A catalogue that cannot be read: a line that is no ``.po`` syntax, a key twice in
    one language, a plural entry with the wrong number of forms, files of one language
    with different ``Plural-Forms``."""


_PO_KEYWORD = re.compile(r'(msgctxt|msgid_plural|msgid|msgstr(?:\[(\d+)\])?)[ \t]+"(.*)"$')
_PO_ESCAPE = re.compile(r'\\([\\trn"])')
_PO_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", '"': '"', "\\": "\\"}
_DEFAULT_PLURAL = ("nplurals=2; plural=(n != 1);", 2, "(n != 1)")


def _po_string(body: str) -> str:
    """A quoted ``.po`` string's body unescaped as Babel's ``read_po`` does (``\\n \\t
    \\r \\" \\\\``; any other backslash is kept as written)."""
    if "\\" not in body:
        return body
    return _PO_ESCAPE.sub(lambda m: _PO_ESCAPES[m.group(1)], body)


def _plural_forms(header: str):
    """``(Plural-Forms value, nplurals, plural expression)`` of a catalogue header (the
    ``msgstr`` of its empty ``msgid``); English's rule when the header names none."""
    for line in header.split("\n"):
        name, _, value = line.partition(":")
        if name.strip().lower() == "plural-forms":
            value = value.strip()
            params = dict(p.strip().partition("=")[::2] for p in value.split(";") if p.strip())
            try:
                return value, int(params["nplurals"]), params["plural"].strip()
            except (KeyError, ValueError):
                raise CatalogueError(f"bad Plural-Forms {value!r}") from None
    return _DEFAULT_PLURAL


def read_po(path: Path):
    """One ``.po`` file read with the standard library: ``(plural_forms, entries)``,
    ``plural_forms`` as :func:`_plural_forms` gives it, ``entries`` a ``{key: text}`` in
    the file's order whose plural entries (``msgid_plural``) are tuples of their
    ``msgstr[i]``.  Fuzzy entries are skipped (as Babel's ``write_mo`` skips them), so is
    the header.  Every line must be ``.po`` syntax (comment, keyword with a quoted string,
    continued string, blank), a key must not repeat, a plural entry must have exactly the
    header's ``nplurals`` forms: else a :class:`CatalogueError` naming the file and line.
    ``msgctxt`` is refused: no key of the text layer has a context."""
    where = f"{path.parent.name}/{path.name}"
    out: dict = {}
    plural = _DEFAULT_PLURAL
    entry: dict = {}
    field = None
    fuzzy = False
    lineno = start = 0                 # the line read, the line of the entry's msgid

    def fail(message, line=None):
        raise CatalogueError(f"{where}:{line or lineno}: {message}")

    def close():
        nonlocal entry, fuzzy, field, plural
        msgid = entry.get("msgid")
        if msgid is None:
            fail("msgstr without msgid")
        forms = entry.get("forms")
        if "msgid_plural" in entry:
            if "msgstr" in entry or not forms or sorted(forms) != list(range(len(forms))):
                fail(f"{msgid!r}: a plural entry needs msgstr[0], msgstr[1] … only", start)
            value = tuple(forms[i] for i in range(len(forms)))
        elif forms or "msgstr" not in entry:
            fail(f"{msgid!r}: a singular entry needs one msgstr", start)
        else:
            value = entry["msgstr"]
        if msgid == "":
            plural = _plural_forms(value)
        elif not fuzzy:
            if msgid in out:
                fail(f"key {msgid!r} twice in one file", start)
            if isinstance(value, tuple) and len(value) != plural[1]:
                fail(f"{msgid!r}: {len(value)} plural forms, the header says "
                     f"nplurals={plural[1]}", start)
            out[msgid] = value
        entry, fuzzy, field = {}, False, None

    for lineno, raw in enumerate(path.read_text(encoding="utf-8-sig").splitlines(), 1):
        line = raw.strip()
        if not line:
            continue
        first = line[0]
        if first == '"':
            if field is None or len(line) < 2 or line[-1] != '"':
                fail(f"cannot read the line {raw!r}")
            text = _po_string(line[1:-1])
            if type(field) is int:
                entry["forms"][field] += text
            else:
                entry[field] += text
            continue
        if first == "#":
            if "msgstr" in entry or "forms" in entry:
                close()                        # a comment starts the next entry
            if line.startswith("#,") and "fuzzy" in (f.strip() for f in line[2:].split(",")):
                fuzzy = True
            continue
        m = _PO_KEYWORD.match(line)
        if m is None:
            fail(f"cannot read the line {raw!r}")
        keyword, index, body = m.groups()
        if keyword == "msgctxt":
            fail("msgctxt: the text layer's keys have no context")
        if keyword == "msgid":
            if "msgstr" in entry or "forms" in entry:
                close()
            start = lineno
        text = _po_string(body)
        if index is not None:
            forms = entry.setdefault("forms", {})
            field = int(index)
            if field in forms:
                fail(f"msgstr[{field}] twice")
            forms[field] = text
        else:
            if keyword in entry:
                fail(f"{keyword} twice in one entry")
            field = keyword
            entry[field] = text
    if entry:
        close()
    return plural, out


class _Translations(gettext.GNUTranslations):
    """The standard library's :class:`gettext.GNUTranslations`, filled from entries read
    by :func:`read_po` instead of from a compiled ``.mo``: the same ``_catalog`` a ``.mo``
    gives it (``key → text``, ``(key, i) → form i``), the same plural function
    (:func:`gettext.c2py` of the header's expression), so its ``gettext``/``ngettext``
    answer as before."""

    def __init__(self, catalog: dict, plural_expr: str):
        gettext.NullTranslations.__init__(self)
        self._catalog = catalog
        self.plural = gettext.c2py(plural_expr)
        self._charset = "UTF-8"


@functools.lru_cache(maxsize=None)
def _catalogue(lang: str):
    """``(GNUTranslations, keys)`` of one language: every ``.po`` of its folder read by
    :func:`read_po` (standard library only) and merged; a key in two files of one
    language, or two files with different ``Plural-Forms``, is a :class:`CatalogueError`.

    What a ``.mo`` compiled from the catalogue would hold (Babel's ``write_mo``, the
    former path): an empty singular text is left out (``gettext`` answers the key), an
    empty plural form is the key.  A test compares it with Babel's reading of every
    catalogue."""
    files = sorted((LOCALE_DIR / lang).glob("*.po"))
    if not files:
        raise KeyError(lang)
    catalog: dict = {}
    keys: set = set()
    rule = None
    for path in files:
        plural, entries = read_po(path)
        if rule is None:
            rule = plural
        elif plural[0] != rule[0]:
            raise CatalogueError(f"{lang}/{path.name}: Plural-Forms {plural[0]!r}; "
                                 f"{lang}/{files[0].name} says {rule[0]!r}")
        for key, value in entries.items():
            if key in keys:
                raise CatalogueError(f"{lang}/{path.stem}.po: key {key!r} is also in "
                                     f"another file of {lang}")
            keys.add(key)
            if isinstance(value, tuple):
                for i, form in enumerate(value):
                    catalog[(key, i)] = form or key
            elif value:
                catalog[key] = value
    return _Translations(catalog, rule[2]), frozenset(keys)


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
    """``{key: text}`` of one area's catalogue (``locale/<lang>/<area>.po``) alone, read by
    :func:`read_po` (standard library only, no other area).  For an area read on a fast
    path (the command line's ``--help``, area ``cli``); it holds singular entries only (a
    plural entry is a :class:`CatalogueError`), fuzzy entries are skipped as
    :func:`texts` skips them.  A test compares it with Babel's reading of every
    ``cli.po``."""
    _, entries = read_po(LOCALE_DIR / lang / f"{area}.po")
    for key, value in entries.items():
        if isinstance(value, tuple):
            raise CatalogueError(f"{lang}/{area}.po: {key!r} is a plural entry; "
                                 "read_area reads singular entries only")
    return entries


class _AreaTranslations:
    """The two look-ups :class:`Texts` makes, over one area's ``{key: text}``."""

    def __init__(self, words):
        self._words = words

    def gettext(self, key):
        return self._words[key]

    def ngettext(self, key, plural, n):  # read_area refuses plural entries
        return self._words[key]


def _unit_words(lang: str) -> dict[str, str]:
    """The ``common.unit.*`` entries of ``lang``'s ``common.po`` alone (:func:`read_po`):
    what an area read alone (:func:`area_texts`) needs for its templates' unit fields."""
    path = LOCALE_DIR / lang / "common.po"
    if not path.is_file():
        return {}
    _, entries = read_po(path)
    return {k: v for k, v in entries.items() if k.startswith("common.unit.")}


@functools.lru_cache(maxsize=None)
def area_texts(lang: str, area: str) -> Texts:
    """The :class:`Texts` of one area only (:func:`read_area`), cached: read once a process,
    a key missing in ``lang`` falls back to English's same area.  For the command line's
    help (area ``cli``), which needs no other area (:func:`texts` reads every area of the
    language and of English); the keys are the same as :func:`texts` gives."""
    if lang not in catalogue_languages():
        raise KeyError(f"no text catalogue for language {lang!r}; there are: "
                       + ", ".join(catalogue_languages()))
    words = read_area(lang, area) if (LOCALE_DIR / lang / f"{area}.po").is_file() else {}
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
    return (isinstance(lang, str) and lang in catalogue_languages()
            and keys(REFERENCE) <= keys(lang))


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
