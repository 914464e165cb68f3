"""The one text layer (crankbase.texts): every key in every language, the same fields,
plural forms by each language's own rule, and every key the code uses in the catalogue."""
from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

import pytest
from babel.messages.pofile import read_po

from crankbase import texts as T
from crankbase.errors import SpecError

ROOT = Path(__file__).resolve().parent.parent
LIBRARIES = ("crankbase", "linkage", "engine", "dynamics", "plans", "crankdyn", "web")


def _tool():
    """The developers' catalogue compiler (``crankbase/locale/compile_catalogues.py``, a
    script of the repository, not an imported module), loaded once."""
    import importlib.util

    if "compile_catalogues" not in sys.modules:
        spec = importlib.util.spec_from_file_location(
            "compile_catalogues", ROOT / "crankbase" / "locale" / "compile_catalogues.py")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        sys.modules["compile_catalogues"] = mod
    return sys.modules["compile_catalogues"]


def _compile(folder):
    """Compile one language's folder (a test's own) as the tool does; returns the paths
    written."""
    written = _tool().compile_language(folder)
    for path, data in written.items():
        path.parent.mkdir(exist_ok=True)
        path.write_bytes(data)
    return written


def _copy_languages(target, *langs):
    """The committed catalogues of ``langs`` (.po and .mo) copied under ``target``."""
    for lang in langs:
        (target / lang / T.MO_FOLDER).mkdir(parents=True)
        for p in [*(T.LOCALE_DIR / lang).glob("*.po"),
                  *(T.LOCALE_DIR / lang / T.MO_FOLDER).glob("*.mo")]:
            (target / p.relative_to(T.LOCALE_DIR)).write_bytes(p.read_bytes())


def _entries(lang):
    """{key: (is_plural, [templates])} of every .po file of ``lang``."""
    out = {}
    for path in sorted((T.LOCALE_DIR / lang).glob("*.po")):
        with path.open("rb") as fh:
            cat = read_po(fh)
        for m in cat:
            if not m.id:
                continue
            key = m.id[0] if isinstance(m.id, (tuple, list)) else m.id
            strings = list(m.string) if isinstance(m.string, (tuple, list)) else [m.string]
            assert key not in out, f"{lang}: key {key!r} twice"
            out[key] = (m.pluralizable, strings, path.stem)
    return out


def test_russian_and_english_hold_the_same_keys():
    en, ru = _entries("en"), _entries("ru")
    assert set(en) == set(ru), (sorted(set(en) - set(ru)), sorted(set(ru) - set(en)))


@pytest.mark.parametrize("lang", T.catalogue_languages())
def test_every_translation_is_complete_and_uses_the_english_fields(lang):
    en, other = _entries("en"), _entries(lang)
    assert set(other) <= set(en), f"{lang}: keys not in en: {sorted(set(other) - set(en))}"
    for key, (plural, strings, area) in other.items():
        assert key.split(".")[0] == area, f"{lang}: {key} belongs in {key.split('.')[0]}.po"
        e_plural, e_strings, _ = en[key]
        assert plural == e_plural, f"{lang}: {key}: plural in one language only"
        want = set().union(*(T.fields(s) for s in e_strings))
        for s in strings:
            assert s, f"{lang}: {key}: empty text"
            assert T.fields(s) == want, f"{lang}: {key}: fields {T.fields(s)} != {want}"


@pytest.mark.parametrize("lang", T.catalogue_languages())
def test_each_language_has_one_plural_rule_and_the_right_number_of_forms(lang):
    rules = set()
    for path in (T.LOCALE_DIR / lang).glob("*.po"):
        with path.open("rb") as fh:
            cat = read_po(fh)
        rules.add(cat.plural_forms)
        for m in cat:
            if m.id and m.pluralizable:
                assert len(m.string) == cat.num_plurals, (path.name, m.id)
    assert len(rules) == 1, f"{lang}: different Plural-Forms headers {rules}"


@pytest.mark.parametrize("n, want", [(1, "1 график"), (2, "2 графика"), (4, "4 графика"),
                                     (5, "5 графиков"), (11, "11 графиков"),
                                     (12, "12 графиков"), (21, "21 график"),
                                     (22, "22 графика"), (25, "25 графиков"),
                                     (101, "101 график"), (111, "111 графиков")])
def test_russian_plural_agreement(n, want):
    # The Russian rule (1 / 2–4 / 5–20, by the last one or two digits), the gettext
    # manual's "Plural forms" example for Russian.
    assert T.texts("ru").n("common.plots", n) == want


def test_english_plural_and_rows():
    assert T.texts("en").n("common.plots", 1) == "1 plot"
    assert T.texts("en").n("common.plots", 0) == "0 plots"
    assert T.texts("ru").n("common.rows", 3) == "3 строки"


def test_offered_languages_are_complete_russian_first():
    offered = T.languages()
    assert offered[:2] == ("ru", "en")
    ref = T.keys("en")
    for lang in offered:
        assert ref <= T.keys(lang)


def test_unknown_language_is_a_spec_error_naming_the_choices():
    from crankbase.validation import check_lang

    with pytest.raises(SpecError, match=r"lang: got 'de'; must be one of ru, en"):
        check_lang("de")
    with pytest.raises(KeyError, match="no text catalogue for language 'de'"):
        T.texts("de")


def test_a_missing_key_is_a_key_error_and_an_incomplete_language_falls_back(tmp_path,
                                                                           monkeypatch):
    with pytest.raises(KeyError):
        T.texts("en")("common.no_such_key")
    # a new language with one key translated: the rest falls back to English
    _copy_languages(tmp_path, "en", "ru")
    (tmp_path / "xx").mkdir()
    (tmp_path / "xx" / "common.po").write_text(
        'msgid ""\nmsgstr ""\n"Language: xx\\n"\n"Plural-Forms: nplurals=1; plural=0;\\n"\n'
        '\nmsgid "common.none"\nmsgstr "nada"\n', encoding="utf-8")
    assert [p.relative_to(tmp_path).as_posix() for p in _compile(tmp_path / "xx")] == [
        "xx/LC_MESSAGES/common.mo"]
    monkeypatch.setattr(T, "LOCALE_DIR", tmp_path)
    for f in (T._catalogue, T.texts, T.languages):
        f.cache_clear()
    try:
        xx = T.texts("xx")
        assert xx("common.none") == "nada"
        assert xx.n("common.plots", 2) == "2 plots"          # English fallback
        assert "xx" not in T.languages()                     # not offered until complete
    finally:
        monkeypatch.undo()
        for f in (T._catalogue, T.texts, T.languages):
            f.cache_clear()


_CALL = re.compile(r"""(?:\bt|\btx|\.n|texts\([^()]*\))\(\s*["']([a-z]+\.[A-Za-z0-9_.]+)["']""")


def test_every_key_the_code_uses_is_in_the_catalogue():
    """Every literal key passed to a Texts object (``t("…")``, ``t.n("…", n)``) in the
    library code exists in the reference catalogue."""
    known = T.keys("en")
    missing = []
    for pkg in LIBRARIES + ("templates",):
        for path in [*(ROOT / pkg).rglob("*.py"), *(ROOT / pkg).rglob("*.html")]:
            for key in _CALL.findall(path.read_text(encoding="utf-8")):
                if key not in known:
                    missing.append(f"{path.relative_to(ROOT)}: {key}")
    assert not missing, missing


def test_the_catalogues_ship_with_the_package():
    """The compiled catalogues are package data (read at run time), the .po files too
    (their source, for a translator); .mo files are binary to git (no line endings)."""
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert '"crankbase" = ["locale/*/*.po", "locale/*/LC_MESSAGES/*.mo"]' in text
    assert (T.LOCALE_DIR / "ru" / "common.po").is_file()
    assert T.mo_path("ru", "common").is_file()
    assert T.mo_path("ru", "common") == T.LOCALE_DIR / "ru" / "LC_MESSAGES" / "common.mo"
    assert "*.mo binary" in (ROOT / ".gitattributes").read_text(encoding="utf-8").splitlines()


# ---- Chinese (issue #19): complete, offered, in en's order, one plural form -------------

def _order(lang, area):
    with (T.LOCALE_DIR / lang / f"{area}.po").open("rb") as fh:
        return [m.id[0] if isinstance(m.id, (tuple, list)) else m.id
                for m in read_po(fh) if m.id]


def test_chinese_holds_every_english_key():
    """zh is offered (crankbase.texts.languages) only while complete: when a merge adds
    English keys, this names each missing one by its file, to be translated there."""
    en, zh = _entries("en"), _entries("zh")
    missing = {}
    for key, (_, _, area) in en.items():
        if key not in zh:
            missing.setdefault(area, []).append(key)
    report = "; ".join(f"crankbase/locale/zh/{area}.po lacks {len(keys)}: {', '.join(keys)}"
                       for area, keys in sorted(missing.items()))
    assert not missing, f"zh is not offered until complete: {report}"
    assert "zh" in T.languages()


def test_chinese_keys_are_in_the_english_order():
    for path in sorted((T.LOCALE_DIR / "en").glob("*.po")):
        en = _order("en", path.stem)
        zh = [k for k in _order("zh", path.stem) if k in set(en)]
        assert zh == [k for k in en if k in set(zh)], f"zh/{path.name}: keys out of en's order"


def test_chinese_has_one_plural_form_and_no_cyrillic():
    zh = T.texts("zh")
    assert zh.n("common.plots", 1) == zh.n("common.plots", 22).replace("22", "1")
    assert "22" in zh.n("common.plots", 22)
    cyr = re.compile(r"[А-Яа-яЁё]")
    han = re.compile(r"[\u4e00-\u9fff]")
    en = _entries("en")
    words = 0
    for key, (_, strings, _) in _entries("zh").items():
        for s in strings:
            # one source text names the Russian workbook's own cell label «Вариант»
            if key != "check.class.detail.no_variant":
                assert not cyr.search(s), f"zh: {key}: Cyrillic in {s!r}"
            if han.search(s):
                words += 1
            # a sentence left in English: a translation identical to en's with words in it
            e = en[key][1][-1]
            if s == e and len(re.findall(r"\b[a-z]{3,}\b", re.sub(r"\{[^}]*\}", "", e))) >= 3:
                raise AssertionError(f"zh: {key}: left in English: {s!r}")
    assert words > 1500


# ---- the notation is the catalogue's (issue #19 item 4): no code compares a language ----

_LANG_NAME = re.compile(r"(^|_)lang(uage)?s?$", re.I)


def _is_language(node):
    """``lang``, ``report_lang``, ``args.lang``, ``self.language``, ``langs[0]``."""
    if isinstance(node, ast.Subscript):
        return _is_language(node.value)
    name = node.id if isinstance(node, ast.Name) else getattr(node, "attr", None)
    return bool(name and _LANG_NAME.search(name))


def _literals(node):
    """The strings of a str literal or of a tuple/list/set of them, else None."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return {node.value}
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)) and node.elts and all(
            isinstance(e, ast.Constant) and isinstance(e.value, str) for e in node.elts):
        return {e.value for e in node.elts}
    return None


def language_comparisons(source: str, codes=frozenset(T.catalogue_languages())):
    """``(line, text)`` of every comparison in ``source`` of a language with a literal:
    a language-named value (``lang``, ``args.lang``) against any string literal, or any
    value against a literal that is a catalogue's language code (``"ru"``, ``("ru",
    "en")``)."""
    out = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Compare):
            continue
        operands = [node.left, *node.comparators]
        lits = [_literals(o) for o in operands]
        if any(s and s & codes for s in lits) or (
                any(_is_language(o) for o in operands) and any(s is not None for s in lits)):
            out.append((node.lineno, ast.unparse(node)))
    return out


def test_no_module_but_the_text_layer_compares_a_language_code():
    """Which symbols a language writes, how it spells a unit and its decimal sign are its
    catalogue's (``common.format.*``, ``common.unit.*``, asked through Texts): a third
    language is a catalogue to fill, not code to change."""
    found = []
    for pkg in (*LIBRARIES, "torsion", "templates"):
        for path in sorted((ROOT / pkg).rglob("*.py")):
            if path == ROOT / "crankbase" / "texts.py":
                continue
            found += [f"{path.relative_to(ROOT)}:{line}: {text}"
                      for line, text in language_comparisons(path.read_text(encoding="utf-8"))]
    assert not found, found


@pytest.mark.parametrize("source, hits", [
    ('x = a if lang == "ru" else b', 1), ('if lang != "ru":\n    pass', 1),
    ('ok = args.lang in ("ru", "en")', 1), ('ok = code == "zh"', 1),
    ('ok = report_language == "de"', 1), ('ok = "en" != self.lang', 1),
    ('ok = lang in OFFERED', 0), ('ok = t.symbols == "latin"', 0), ('ok = kind == "ru2"', 0),
])
def test_the_language_comparison_scan_finds_each_form(source, hits):
    assert len(language_comparisons(source)) == hits


def test_each_catalogue_names_its_notation():
    """The symbol set, decimal sign and unit spellings come from the catalogue: Russian
    writes the textbook's symbols, a decimal comma (GOST 2.304 lettering on the plans
    sheet; Babel's CLDR number symbols for ru say the same) and Cyrillic units."""
    from babel import Locale

    for lang in T.catalogue_languages():
        t = T.texts(lang)
        assert t.symbols in T.SYMBOL_SETS
        assert t.decimal_sign == Locale.parse(lang).number_symbols["latn"]["decimal"], lang
        for si in T.UNITS:
            assert t.unit(si), (lang, si)
    ru, en, zh = T.texts("ru"), T.texts("en"), T.texts("zh")
    assert (ru.symbols, en.symbols, zh.symbols) == ("ru", "en", "en")
    assert ru.symbol("Mкр", "M") == "Mкр" and zh.symbol("Mкр", "M") == "M"
    assert (ru.unit("N·m"), en.unit("N·m"), zh.unit("N·m")) == ("Н·м", "N·m", "N·m")
    assert ru.unit("m/s²") == "м/с²" and ru.unit("kg/m²") == "кг/м²"
    assert ru.unit("°") == en.unit("°") == "°"          # a sign no catalogue spells
    assert (ru.number("0.25"), en.number("0.25"), zh.number("-1.5e-03")) == (
        "0,25", "0.25", "-1.5e-03")


def test_a_third_language_writes_the_notation_its_catalogue_names(tmp_path, monkeypatch):
    """A new language whose catalogue names the Russian textbook's symbols, a decimal comma
    and Cyrillic units gets them in the engine's symbols, the plans' numbers and the
    dynamics' headers (whose symbols are its ``dynamics.symbol.*`` keys: those it fills),
    with no code changed (its words fall back to English)."""
    from dynamics.report import column_label
    from engine.symbols import mass_inputs, sym
    from plans.layout import fmt

    _copy_languages(tmp_path, "en", "ru")
    (tmp_path / "xx").mkdir()
    entries = {"common.format.symbols": "ru", "common.format.decimal_sign": ",",
               "common.format.quantity_unit": "{symbol} / {unit}", "common.unit.N_m": "Нм",
               "common.unit.kg": "кг"}
    (tmp_path / "xx" / "common.po").write_text(
        'msgid ""\nmsgstr ""\n"Language: xx\\n"\n"Plural-Forms: nplurals=1; plural=0;\\n"\n'
        + "".join(f'\nmsgid "{k}"\nmsgstr "{v}"\n' for k, v in entries.items()),
        encoding="utf-8")
    (tmp_path / "xx" / "dynamics.po").write_text(
        'msgid ""\nmsgstr ""\n"Language: xx\\n"\n"Plural-Forms: nplurals=1; plural=0;\\n"\n'
        '\nmsgid "dynamics.symbol.M"\nmsgstr "Mкр"\n', encoding="utf-8")
    _compile(tmp_path / "xx")
    monkeypatch.setattr(T, "LOCALE_DIR", tmp_path)
    for f in (T._catalogue, T.texts, T.languages):
        f.cache_clear()
    try:
        assert sym("M", "xx") == sym("M", "ru") == "Mкр"
        assert fmt(0.125, "xx") == "0,125" and fmt(0.125, "en") == "0.125"
        assert column_label("M_Nm", "xx") == "Mкр / Нм"
        assert column_label("t_s", "xx") == "t / s"                   # English fallback
        assert column_label("R_N", "xx") == "Rcp / N"       # a symbol it does not fill
        assert mass_inputs({"rod_kg": 0.7}, "xx") == "mш = 0.7 кг"
    finally:
        monkeypatch.undo()
        for f in (T._catalogue, T.texts, T.languages):
            f.cache_clear()


# ---- the compiled catalogues (.mo) read by the standard library (issue #19 item 4) -------

def test_the_committed_mo_files_are_what_the_po_files_compile_to():
    """Every .po compiled in memory (crankbase/locale/compile_catalogues.py: Babel's read_po and
    write_mo) gives the committed .mo byte for byte, and no .mo is left without its .po:
    else edit nothing by hand, run the tool and commit the .mo files with the .po."""
    want, write, remove = _tool().stale(T.LOCALE_DIR)
    assert len(want) == 3 * len(list((T.LOCALE_DIR / "en").glob("*.po"))) >= 45
    assert not write and not remove, (
        f"stale compiled catalogues: {[p.relative_to(T.LOCALE_DIR).as_posix() for p in write]}"
        f", without a .po: {[p.relative_to(T.LOCALE_DIR).as_posix() for p in remove]}; "
        f"run: {T.COMPILE_COMMAND} (and commit the .mo files)")


def test_the_compiler_is_deterministic_and_writes_no_date_nor_version(tmp_path):
    """The same .po gives the same bytes (twice, from a copy elsewhere, from a copy with
    Windows line endings, as a checkout with core.autocrlf has it); the header
    holds the .po's Language and Plural-Forms and the MIME lines only: not the compile
    time Babel writes for a .po without POT-Creation-Date, nor Babel's version."""
    import gettext
    import io

    tool = _tool()
    po = T.LOCALE_DIR / "ru" / "common.po"
    (tmp_path / "ru").mkdir()
    (tmp_path / "ru" / "common.po").write_bytes(po.read_bytes())
    first = tool.mo_bytes(tool.read_catalogue(po))
    assert first == tool.mo_bytes(tool.read_catalogue(tmp_path / "ru" / "common.po"))
    (tmp_path / "ru" / "common.po").write_bytes(po.read_bytes().replace(b"\n", b"\r\n"))
    assert first == tool.mo_bytes(tool.read_catalogue(tmp_path / "ru" / "common.po"))
    assert first == T.mo_path("ru", "common").read_bytes()
    info = gettext.GNUTranslations(io.BytesIO(first)).info()
    assert set(info) == {"language", "plural-forms", "mime-version", "content-type",
                         "content-transfer-encoding"}
    assert info["language"] == "ru" and info["plural-forms"].startswith("nplurals=3;")
    assert b"POT-Creation-Date" not in first and b"Generated-By" not in first


def _babel_translations(lang, folder=None):
    """The reference, independent of the compiler: every ``.po`` of ``lang`` read by
    Babel's ``read_po`` into one Babel catalogue (its own header), compiled by
    ``write_mo`` and loaded by GNUTranslations."""
    import gettext
    import io

    from babel.messages.catalog import Catalog
    from babel.messages.mofile import write_mo

    merged = None
    for path in sorted(((folder or T.LOCALE_DIR) / lang).glob("*.po")):
        with path.open("rb") as fh:
            cat = read_po(fh, locale=None, domain=path.stem)
        if merged is None:
            merged = Catalog(locale=None, domain="crankdyn")
            merged.mime_headers = cat.mime_headers
        for msg in cat:
            if msg.id and not msg.fuzzy:
                assert msg.id not in merged
                merged[msg.id] = msg
    buf = io.BytesIO()
    write_mo(buf, merged)
    buf.seek(0)
    keys = frozenset(m.id if isinstance(m.id, str) else m.id[0] for m in merged if m.id)
    return gettext.GNUTranslations(buf), keys


def _babel_entries(path):
    """``{key: text or tuple of forms}`` of one file as Babel reads it, fuzzy skipped."""
    with path.open("rb") as fh:
        cat = read_po(fh)
    return cat, {(m.id[0] if isinstance(m.id, (tuple, list)) else m.id):
                 (tuple(m.string) if isinstance(m.string, (tuple, list)) else m.string)
                 for m in cat if m.id and not m.fuzzy}


@pytest.mark.parametrize("lang", T.catalogue_languages())
def test_the_compiled_catalogues_read_as_babel_reads_the_po(lang):
    """Every area: the .mo read by the standard library (read_po's entries, its plural
    rule) holds what Babel reads from the .po; the merged language: the same keys, the
    same table as Babel's own write_mo of the merged .po files, the same text of every
    key and the same plural form of every plural key for n = 0..200."""
    for path in sorted((T.LOCALE_DIR / lang).glob("*.po")):
        cat, babel = _babel_entries(path)
        plural, entries = T.read_po(path)
        assert entries == babel, path.name
        assert plural[1] == cat.num_plurals and plural[0] == cat.plural_forms, path.name
    old, old_keys = _babel_translations(lang)
    T._catalogue.cache_clear()
    new, new_keys = T._catalogue(lang)
    assert new_keys == old_keys and len(new_keys) > 1000
    assert new._catalog == {k: v for k, v in old._catalog.items() if k != ""}
    plurals = [k for k in new_keys if (k, 0) in old._catalog]
    assert len(plurals) >= 5
    for n in range(201):
        assert new.plural(n) == old.plural(n), n
        for key in plurals:
            assert new.ngettext(key, key, n) == old.ngettext(key, key, n), (key, n)
    for key in new_keys:
        assert new.gettext(key) == old.gettext(key), key


def test_the_mo_files_are_where_gettext_looks():
    """The standard machinery finds them as they are laid out: gettext.translation with
    the area as domain gives the same Russian plural forms as Texts."""
    import gettext

    tr = gettext.translation("common", T.LOCALE_DIR, languages=["ru"])
    assert [tr.ngettext("common.plots", "common.plots", n).format(n=n) for n in (1, 3, 5)] \
        == [T.texts("ru").n("common.plots", n) for n in (1, 3, 5)] \
        == ["1 график", "3 графика", "5 графиков"]


_TRICKY = r"""# a header comment
msgid ""
msgstr ""
"Language: xx\n"
"Plural-Forms: nplurals=3; plural=(n%10==1 && n%100!=11 ? 0 : n%10>=2 && n%10<=4 && (n%100<10 || n%100>=20) ? 1 : 2);\n"

#. an extracted comment
#: a/reference.py:12
msgid "common.a"
msgstr ""
"one \"two\" "
"three\n"
"tab\there \\ back\\slash"

#, fuzzy
msgid "common.b"
msgstr "draft"
msgid "common.c"
msgstr "c"

#, python-format, fuzzy
#| msgid "common.old"
msgid "common.d"
msgid_plural "common.d"
msgstr[0] "d0"
msgstr[1] "d1"
msgstr[2] "d2"

#~ msgid "common.gone"
#~ msgstr "obsolete"

msgid "common.e"
msgid_plural "common.e"
msgstr[0] "{n} e0"
msgstr[1] ""
"{n} e1"
msgstr[2] "{n} e2"
#, no-fuzzy-here
msgid "common.f"
msgstr "f"
"""


def test_the_compiled_po_syntax_reads_as_babel_reads_it(tmp_path, monkeypatch):
    """Continued strings, escapes, fuzzy entries (a flag among others, an entry with no
    blank line before it), obsolete entries and comments of every kind: compiled, the
    same entries as Babel reads; the Russian rule of the header chooses the forms."""
    (tmp_path / "xx").mkdir()
    po = tmp_path / "xx" / "common.po"
    po.write_text(_TRICKY, encoding="utf-8")
    _compile(tmp_path / "xx")
    cat, babel = _babel_entries(po)
    monkeypatch.setattr(T, "LOCALE_DIR", tmp_path)
    T._catalogue.cache_clear()
    try:
        plural, entries = T.read_po(po)
        assert entries == babel
        assert entries == {"common.a": 'one "two" three\ntab\there \\ back\\slash',
                           "common.c": "c", "common.e": ("{n} e0", "{n} e1", "{n} e2"),
                           "common.f": "f"}
        assert plural[1] == 3 == cat.num_plurals
        tr, keys = T._catalogue("xx")
        old, old_keys = _babel_translations("xx", tmp_path)
        assert keys == old_keys == {"common.a", "common.c", "common.e", "common.f"}
        assert [tr.ngettext("common.e", "common.e", n) for n in (1, 3, 5, 21, 111)] == [
            "{n} e0", "{n} e1", "{n} e2", "{n} e0", "{n} e2"]
        assert tr._catalog == {k: v for k, v in old._catalog.items() if k != ""}
    finally:
        monkeypatch.undo()
        T._catalogue.cache_clear()


@pytest.mark.parametrize("files, match", [
    ({"common": 'msgid "common.a"\nmsgstr "1"\n\nmsgid "common.a"\nmsgstr "2"\n'},
     r"xx/common.po:4: key 'common.a' twice in one file"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\n', "engine": 'msgid "common.a"\nmsgstr "2"\n'},
     r"xx/engine.po:1: key 'common.a' is also in xx/common.po"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\nmsgstr but no quotes\n'},
     r"xx/common.po:3: cannot read the line 'msgstr but no quotes'"),
    ({"common": 'msgid "common.a"\nmsgstr "1\n'}, r"xx/common.po:2: cannot read the line"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\n"2\n'}, r"xx/common.po:3: cannot read"),
    ({"common": 'msgid "common.a"\nmsgstr "a "b" c"\n'}, r"xx/common.po:2: cannot read"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\nmsgfoo "2"\n'}, r"xx/common.po:3: cannot read"),
    ({"common": 'msgid "common.a"\nmsgid_plural "common.a"\nmsgstr[0] "1"\n'},
     r"xx/common.po:1: 'common.a': msgstr\[1\] missing or empty; the header says nplurals=2"),
    ({"common": 'msgid "common.a"\nmsgid_plural "common.a"\nmsgstr[0] "1"\nmsgstr[2] "3"\n'},
     r"xx/common.po:1: msg has more translations than num_plurals"),
    ({"common": 'msgid "common.a"\nmsgstr[0] "1"\n'},
     r"xx/common.po:2: a singular entry has one msgstr"),
    ({"common": 'msgid "common.a"\nmsgid_plural "common.a"\nmsgstr "1"\n'},
     r"xx/common.po:3: a plural entry has msgstr\[0\], msgstr\[1\]"),
    ({"common": 'msgstr "1"\n'}, r"xx/common.po:1: msgstr without msgid"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\nmsgstr "2"\n'},
     r"xx/common.po:3: msgstr without msgid, or twice"),
    ({"common": 'msgid "common.a"\n\nmsgid "common.b"\nmsgstr "1"\n'},
     r"xx/common.po:1: missing msgstr for msgid 'common.a'"),
    ({"common": 'msgctxt "menu"\nmsgid "common.a"\nmsgstr "1"\n'}, r"xx/common.po:2: msgctxt"),
    ({"common": 'msgid ""\nmsgstr "Plural-Forms: nplurals=1; plural=0;\\n"\n',
      "engine": 'msgid ""\nmsgstr "Plural-Forms: nplurals=2; plural=(n != 1);\\n"\n'},
     r"xx/engine.po: Plural-Forms 'nplurals=2; plural=\(n != 1\);'; xx/common.po says "
     r"'nplurals=1; plural=0;'"),
])
def test_a_broken_po_is_an_error_of_the_compiler(files, match, tmp_path):
    (tmp_path / "xx").mkdir()
    for area, text in files.items():
        (tmp_path / "xx" / f"{area}.po").write_text(text, encoding="utf-8")
    with pytest.raises(T.CatalogueError, match=match):
        _tool().compile_language(tmp_path / "xx")
    assert not (tmp_path / "xx" / T.MO_FOLDER).exists()
    # the command line says it in one line, exit 2, and writes nothing
    tool = ROOT / "crankbase" / "locale" / "compile_catalogues.py"
    r = subprocess.run([sys.executable, str(tool), "--locale-dir", str(tmp_path)],
                       capture_output=True, text=True)
    assert r.returncode == 2 and re.search(match, r.stderr), r.stderr
    assert not (tmp_path / "xx" / T.MO_FOLDER).exists()


def _each_compiled_alone(folder):
    """Each .po of ``folder`` compiled on its own (no check across areas), as a stale or
    hand-made set of .mo files could be."""
    tool = _tool()
    (folder / T.MO_FOLDER).mkdir()
    for po in folder.glob("*.po"):
        (folder / T.MO_FOLDER / f"{po.stem}.mo").write_bytes(
            tool.mo_bytes(tool.read_catalogue(po)))


@pytest.mark.parametrize("files, change, match", [
    ({"common": 'msgid "common.a"\nmsgstr "1"\n', "engine": 'msgid "common.a"\nmsgstr "2"\n'},
     None, r"key 'common.a' is in xx/common.po and in xx/engine.po"),
    ({"common": 'msgid ""\nmsgstr "Plural-Forms: nplurals=1; plural=0;\\n"\n',
      "engine": 'msgid ""\nmsgstr "Plural-Forms: nplurals=2; plural=(n != 1);\\n"\n'},
     None, r"xx/engine.po: Plural-Forms 'nplurals=2; plural=\(n != 1\);'; xx/common.po"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\n', "engine": 'msgid "engine.a"\nmsgstr "2"\n'},
     "drop engine.mo", r"out of step: xx/engine.po \(no LC_MESSAGES/engine.mo\); "
                       r"run python crankbase/locale/compile_catalogues.py"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\n', "engine": 'msgid "engine.a"\nmsgstr "2"\n'},
     "drop engine.po", r"out of step: xx/LC_MESSAGES/engine.mo \(no engine.po\)"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\n'}, "garble common.mo",
     r"xx/LC_MESSAGES/common.mo: not a compiled catalogue \(.*\); run python crankbase/locale/"),
    ({"common": 'msgid "common.a"\nmsgstr "1"\n'}, "cut common.mo",
     r"xx/LC_MESSAGES/common.mo: not a compiled catalogue"),
])
def test_a_broken_or_stale_mo_is_a_catalogue_error_at_run_time(files, change, match,
                                                                tmp_path, monkeypatch):
    """What the run time checks of the compiled catalogues: a key in two areas (both
    named), two plural rules, a .po without its .mo or the reverse, a .mo that is not one
    (bad magic number, cut short)."""
    folder = tmp_path / "xx"
    folder.mkdir()
    for area, text in files.items():
        (folder / f"{area}.po").write_text(text, encoding="utf-8")
    _each_compiled_alone(folder)
    mo = folder / T.MO_FOLDER / "common.mo"
    if change == "drop engine.mo":
        (folder / T.MO_FOLDER / "engine.mo").unlink()
    elif change == "drop engine.po":
        (folder / "engine.po").unlink()
    elif change == "garble common.mo":
        mo.write_bytes(b"\x00" * 4 + mo.read_bytes()[4:])
    elif change == "cut common.mo":
        mo.write_bytes(mo.read_bytes()[:40])
    monkeypatch.setattr(T, "LOCALE_DIR", tmp_path)
    T._catalogue.cache_clear()
    try:
        with pytest.raises(T.CatalogueError, match=match):
            T._catalogue("xx")
    finally:
        monkeypatch.undo()
        T._catalogue.cache_clear()


def test_a_run_reads_its_language_and_english_only_and_no_babel():
    """What ``crankdyn engine --lang ru`` asks of the text layer (check the language,
    argparse's ``choices``, the texts) reads the compiled catalogues of two languages (ru
    and its fallback en) with the standard library: Babel is not imported, no .po is
    opened; ``--lang zh`` reads zh and en."""
    code = ("import sys, builtins\nfrom crankbase import texts as T\n"
            "from crankbase.validation import check_lang\n"
            "read, real, po = set(), T.read_mo, []\n"
            "T.read_mo = lambda path: read.add(path.parent.parent.name) or real(path)\n"
            "opened = builtins.open\n"
            "builtins.open = lambda f, *a, **k: (str(f).endswith('.po') and po.append(f))"
            " or opened(f, *a, **k)\n"
            "for lang in sys.argv[1:]:\n"
            "    assert lang in T.OFFERED and check_lang(lang) == lang\n"
            "    T.texts(lang).n('common.plots', 22)\n"
            "print('babel' in sys.modules, ','.join(sorted(read)), len(po))")
    for langs, want in ((["ru"], "en,ru"), (["zh"], "en,zh"), (["en"], "en"),
                        (["ru", "zh"], "en,ru,zh")):
        r = subprocess.run([sys.executable, "-c", code, *langs], capture_output=True,
                           text=True, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        assert r.stdout.split() == ["False", want, "0"], langs
