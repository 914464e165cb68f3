"""The command line's help in every language (issue #19 item 4): ``crankdyn --help`` and
``crankdyn <command> --help`` are built in the language asked with ``--lang`` (Russian by
default, as every report) from the text layer's ``cli`` area, read alone and without Babel.

The rule of a help "in Russian", "in English", "in Chinese" is tests/language_rules.py's;
what is typed rather than read is what the parser knows: option names, metavars, the
choices and example names it accepts, the program's and the commands' names.  Chinese: every
line that still holds a word (not a unit) after the taking-out holds a CJK character."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
from babel.messages.pofile import read_po

from crankbase import texts as T
from crankdyn.cli import HelpFormatter, build_parser, main

COMMANDS = (None, "engine", "linkage", "synth", "dynamics", "balance", "torsion", "check",
            "serve")
LANGS = ("ru", "en", "zh")
from language_rules import CJK, CYRILLIC, UNITS, latin_words, reading_text

def _help(capsys, command, lang, columns=80, monkeypatch=None):
    argv = ([command] if command else []) + ["--help"]
    if lang:
        argv += ["--lang", lang]
    with pytest.raises(SystemExit) as done:
        main(argv)
    assert done.value.code == 0
    return capsys.readouterr().out


def _typed_words(command):
    """What a user types, as the parser of ``command`` knows it: option strings, metavars,
    choices (the subcommands too), the program's name, the example names."""
    from importlib import import_module

    top = build_parser("en")
    parsers = [top] + ([top.subcommands[command]] if command else [])
    words = {"crankdyn", *top.subcommands}
    for p in parsers:
        for action in p._actions:
            words.update(action.option_strings)
            if action.metavar:
                words.add(str(action.metavar))
            if not action.option_strings:
                words.add(action.dest)            # a positional shown by its name
            if action.choices is not None:
                words.update(str(c) for c in action.choices)
    if command:
        words.update(getattr(import_module(f"crankdyn.cmd_{command}"), "EXAMPLES", {}))
    return words


def _reading_text(text, command):
    return reading_text(text, _typed_words(command))


def _latin_words(text, command):
    return latin_words(text, _typed_words(command))


def test_the_rule_catches_english_and_passes_typed_words():
    """The rule itself: an English phrase is caught, what a user types is not."""
    assert _latin_words("папка результатов (created if needed)", "engine") == [
        "created", "if", "needed"]
    assert _latin_words("  -o DIR, --output DIR  папка; по умолчанию petrol, "
                        "<name>_forces.csv, `[table] step_deg`, TOML, tg β, 0.2 %%",
                        "engine") == []
    assert _latin_words("по умолчанию petrol", "linkage") == ["petrol"]   # not its example


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c or "crankdyn")
def test_russian_help_has_no_english_word(command, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    text = _help(capsys, command, "ru")
    assert CYRILLIC.search(text)
    assert not _latin_words(text, command), (_latin_words(text, command), text)
    # Russian is the default: the same help without --lang
    assert _help(capsys, command, None) == text


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c or "crankdyn")
def test_english_help_has_no_cyrillic(command, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    text = _help(capsys, command, "en")
    assert not CYRILLIC.search(text), [ln for ln in text.splitlines() if CYRILLIC.search(ln)]
    assert "usage:" in text and ("show this help message and exit" in text)


@pytest.mark.parametrize("columns", ["80", "52"])
@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c or "crankdyn")
def test_chinese_help_has_cjk_in_every_line_of_text(command, columns, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", columns)
    text = _help(capsys, command, "zh")
    assert not CYRILLIC.search(text)
    reading = _reading_text(text, command)
    bare = [line for line, rest in zip(text.splitlines(), reading.splitlines())
            if [w for w in re.findall(r"[A-Za-z]{2,}", rest) if w not in UNITS]
            and not CJK.search(line)]
    assert not bare, bare
    assert "用法：" in text and "显示此帮助信息并退出" in text


def test_chinese_help_wraps_between_characters_never_inside_a_file_name(capsys,
                                                                       monkeypatch):
    """argparse's own wrapping finds no space in a Chinese sentence and cuts a file name
    («journal_to» / «rques.csv»); crankdyn's HelpFormatter breaks between CJK characters,
    keeps every Latin word whole and counts a CJK character two columns."""
    monkeypatch.setenv("COLUMNS", "80")
    text = _help(capsys, "engine", "zh")
    source = T.area_texts("zh", "cli")("cli.engine.opt.bearings")
    for name in re.findall(r"[\w.]+\.csv", source):
        assert name in text, name
    for line in text.splitlines():
        width = sum(2 if CJK.match(ch) or "\uff00" <= ch <= "\uffef" or "\u3000" <= ch
                    <= "\u303f" else 1 for ch in line)
        assert width <= 80 or " " not in line.strip(), line
    assert not any(line.lstrip().startswith(("，", "、", "；", "）", "。"))
                   for line in text.splitlines())
    # text without CJK is wrapped exactly as argparse wraps it
    plain = "word " * 40
    assert (HelpFormatter("x")._split_lines(plain, 30)
            == __import__("argparse").HelpFormatter("x")._split_lines(plain, 30))
    assert HelpFormatter._cjk_lines("甲乙丙丁，戊己 file_name.csv 庚", 8) == [
        "甲乙丙", "丁，戊己", "file_name.csv", "庚"]
    # a number keeps its unit: no line of "mm" alone
    assert HelpFormatter._cjk_lines("最大力为 50–75 mm）", 14) == ["最大力为", "50–75 mm）"]


@pytest.mark.parametrize("lang", LANGS)
def test_every_cli_key_in_every_language_and_read_alone_as_babel_reads_it(lang):
    """The ``cli`` area is read alone from its compiled catalogue, without Babel
    (crankbase.texts.read_area): the same entries as Babel reads from the .po, every
    English key translated (zh included: the help is not a fallback to English)."""
    with (T.LOCALE_DIR / lang / "cli.po").open("rb") as fh:
        babel = {m.id: m.string for m in read_po(fh) if m.id}
    assert T.read_area(lang, "cli") == babel
    assert set(babel) == set(T.read_area("en", "cli"))
    assert all(k.startswith("cli.") for k in babel)


def _compile(folder):
    """One language folder compiled by the developers' tool
    (crankbase/locale/compile_catalogues.py)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(
        "compile_catalogues", Path(__file__).resolve().parent.parent / "crankbase"
        / "locale" / "compile_catalogues.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    for path, data in tool.compile_language(folder).items():
        path.parent.mkdir(exist_ok=True)
        path.write_bytes(data)


def test_read_area_reads_what_babel_reads(tmp_path, monkeypatch):
    """Continued lines, escapes, a fuzzy entry skipped (as texts() skips it) and the one
    after it kept, compiled and read back; a plural entry refused (the help's area has
    none)."""
    (tmp_path / "xx").mkdir()
    po = tmp_path / "xx" / "cli.po"
    po.write_text('# header\nmsgid ""\nmsgstr ""\n"Language: xx\\n"\n\n'
                  'msgid "cli.a"\nmsgstr ""\n"one \\"two\\" "\n"three\\n"\n\n'
                  '#, fuzzy\nmsgid "cli.b"\nmsgstr "draft"\n'
                  'msgid "cli.c"\nmsgstr "c\\\\d"\n', encoding="utf-8")
    _compile(tmp_path / "xx")
    monkeypatch.setattr(T, "LOCALE_DIR", tmp_path)
    assert T.read_area("xx", "cli") == {"cli.a": 'one "two" three\n', "cli.c": "c\\d"}
    with po.open("rb") as fh:
        babel = {m.id: m.string for m in read_po(fh) if m.id and not m.fuzzy}
    assert T.read_area("xx", "cli") == babel
    po.write_text('msgid "cli.n"\nmsgid_plural "cli.n"\nmsgstr[0] "a"\nmsgstr[1] "b"\n',
                  encoding="utf-8")
    _compile(tmp_path / "xx")
    with pytest.raises(ValueError, match="plural"):
        T.read_area("xx", "cli")


def test_top_level_help_reads_only_the_cli_catalogue():
    """``crankdyn --help`` builds the parser in the language asked and formats its help
    without Babel and without any other catalogue (what keeps it fast: Babel alone costs
    more than the whole help did)."""
    code = ("import sys\nfrom crankdyn.cli import build_parser\n"
            "for lang in ('ru', 'en', 'zh'):\n    build_parser(lang).format_help()\n"
            "from crankbase import texts\n"
            "print(sorted(m for m in ('babel', 'numpy', 'pandas', 'matplotlib', 'openpyxl')"
            " if m in sys.modules), texts._catalogue.cache_info().currsize)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["[]", "0"]


def test_parser_built_once_in_the_language_asked(monkeypatch, capsys):
    import crankdyn.cli as cli

    built = []
    real = cli.build_parser
    monkeypatch.setattr(cli, "build_parser", lambda lang="ru": built.append(lang) or real(lang))
    with pytest.raises(SystemExit):
        cli.main(["torsion", "--help", "--lang=zh"])
    assert built == ["zh"]
    assert "扭转振动" in capsys.readouterr().out


@pytest.mark.parametrize("lang, words", [("ru", "нужны дополнительные пакеты"),
                                         ("en", "needs the web extra"),
                                         ("zh", "需要网页附加包")])
def test_serve_speaks_its_lang_when_the_web_extra_is_missing(lang, words, monkeypatch,
                                                              capsys):
    monkeypatch.setitem(sys.modules, "uvicorn", None)        # import uvicorn → ImportError
    assert main(["serve", "--lang", lang]) == 2
    err = capsys.readouterr().err.strip()
    error = {"ru": ": ошибка: ", "en": ": error: ", "zh": "：错误："}[lang]
    assert err.startswith("crankdyn serve" + error) and words in err, err
    assert "uvicorn" in err and 'pip install "crankdyn[web]"' in err
    if lang == "ru":
        assert not _latin_words(err.split(error, 1)[1], "serve"), err
    else:
        assert not CYRILLIC.search(err)


@pytest.mark.parametrize("asked, mode", [([], "ahead"), (["--draw", "on_request"],
                                                          "on_request")])
def test_serve_draw_option_reaches_the_app(monkeypatch, asked, mode):
    """``crankdyn serve --draw`` is the app's ``draw`` (web.create_app): ahead by default."""
    pytest.importorskip("starlette")
    import types

    seen = {}
    fake = types.SimpleNamespace(run=lambda app, **kw: seen.update(app=app, **kw))
    monkeypatch.setitem(sys.modules, "uvicorn", fake)
    import web

    monkeypatch.setattr(web, "create_app", lambda **kw: seen.setdefault("options", kw))
    assert main(["serve", "--port", "8765", *asked]) == 0
    assert seen["options"]["draw"] == mode and seen["port"] == 8765
