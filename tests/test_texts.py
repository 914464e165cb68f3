"""The one text layer (crankbase.texts): every key in every language, the same fields,
plural forms by each language's own rule, and every key the code uses in the catalogue."""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest
from babel.messages.pofile import read_po

from crankbase import texts as T
from crankbase.errors import SpecError

ROOT = Path(__file__).resolve().parent.parent
LIBRARIES = ("crankbase", "linkage", "engine", "dynamics", "plans", "crankdyn", "web")


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
    for lang in ("en", "ru"):
        (tmp_path / lang).mkdir()
        for p in (T.LOCALE_DIR / lang).glob("*.po"):
            (tmp_path / lang / p.name).write_bytes(p.read_bytes())
    (tmp_path / "xx").mkdir()
    (tmp_path / "xx" / "common.po").write_text(
        'msgid ""\nmsgstr ""\n"Language: xx\\n"\n"Plural-Forms: nplurals=1; plural=0;\\n"\n'
        '\nmsgid "common.none"\nmsgstr "nada"\n', encoding="utf-8")
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
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert '"crankbase" = ["locale/*/*.po"]' in text
    tree = ast.parse((ROOT / "crankbase" / "texts.py").read_text(encoding="utf-8"))
    assert tree  # the module parses; the catalogue folder is beside it
    assert (T.LOCALE_DIR / "ru" / "common.po").is_file()


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
    dynamics' headers, with no code changed (its words fall back to English)."""
    from dynamics.report import column_label
    from engine.symbols import mass_inputs, sym
    from plans.layout import fmt

    for lang in ("en", "ru"):
        (tmp_path / lang).mkdir()
        for p in (T.LOCALE_DIR / lang).glob("*.po"):
            (tmp_path / lang / p.name).write_bytes(p.read_bytes())
    (tmp_path / "xx").mkdir()
    entries = {"common.format.symbols": "ru", "common.format.decimal_sign": ",",
               "common.format.quantity_unit": "{symbol} / {unit}", "common.unit.N_m": "Нм",
               "common.unit.kg": "кг"}
    (tmp_path / "xx" / "common.po").write_text(
        'msgid ""\nmsgstr ""\n"Language: xx\\n"\n"Plural-Forms: nplurals=1; plural=0;\\n"\n'
        + "".join(f'\nmsgid "{k}"\nmsgstr "{v}"\n' for k, v in entries.items()),
        encoding="utf-8")
    monkeypatch.setattr(T, "LOCALE_DIR", tmp_path)
    for f in (T._catalogue, T.texts, T.languages):
        f.cache_clear()
    try:
        assert sym("M", "xx") == sym("M", "ru") == "Mкр"
        assert fmt(0.125, "xx") == "0,125" and fmt(0.125, "en") == "0.125"
        assert column_label("M_Nm", "xx") == "Mкр / Нм"
        assert column_label("t_s", "xx") == "t / s"                   # English fallback
        assert mass_inputs({"rod_kg": 0.7}, "xx") == "mш = 0.7 кг"
    finally:
        monkeypatch.undo()
        for f in (T._catalogue, T.texts, T.languages):
            f.cache_clear()
