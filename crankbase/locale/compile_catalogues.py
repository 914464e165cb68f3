"""Compile the text catalogues: every ``crankbase/locale/<lang>/<area>.po`` into the
``crankbase/locale/<lang>/LC_MESSAGES/<area>.mo`` that :mod:`crankbase.texts` reads at run
time (with the standard library's :class:`gettext.GNUTranslations`).

A developer's tool, not part of the installed package: it needs Babel (the ``test`` extra,
``pip install -e ".[test]"``); users never run it.  After editing a ``.po``::

    python crankbase/locale/compile_catalogues.py           # writes the .mo files that changed
    python crankbase/locale/compile_catalogues.py --check   # exit 1, naming each stale .mo

and commit the ``.po`` and ``.mo`` together (``tests/test_texts.py`` compiles every
``.po`` in memory and fails on a committed ``.mo`` that differs, naming this command).

Each file is read by Babel (:class:`babel.messages.pofile.PoFileParser`, what
``pofile.read_po`` runs, into a stricter catalogue) and written by Babel's
``mofile.write_mo``.  The output is deterministic: the same ``.po`` gives the same bytes
on any machine and any day.  ``write_mo`` sorts the entries; the ``.mo`` header holds only
what the ``.po`` header says and gettext reads (``Language``, ``Plural-Forms``, the
MIME lines), not the compile time Babel writes where the ``.po`` names no
``POT-Creation-Date`` nor Babel's version (``Generated-By``).

The catalogue is checked while compiled, each problem a
:class:`crankbase.texts.CatalogueError` naming the file and line: a string line that is
not one quoted ``.po`` string (Babel would read it silently, less its last character), a
keyword Babel does not know, a key twice in one file, a key in two areas of one language
(both named), a ``msgctxt`` (no key of the text layer has a context), a plural entry
without all the header's ``nplurals`` forms, areas of one language with different
``Plural-Forms``.  Fuzzy entries are left out, as gettext's ``msgfmt`` leaves them out.
"""
from __future__ import annotations

import argparse
import io
import re
import sys
from pathlib import Path

from babel.messages.catalog import Catalog
from babel.messages.mofile import write_mo
from babel.messages.pofile import PoFileError, PoFileParser

ROOT = Path(__file__).resolve().parents[2]
if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))        # run as a script: crankbase of this checkout

from crankbase.texts import MO_FOLDER, CatalogueError  # noqa: E402

#: The catalogues of this checkout (not of an installed copy).
LOCALE_DIR = ROOT / "crankbase" / "locale"

#: The header lines a compiled catalogue keeps (what gettext reads; no date, no version).
HEADER = ("Language", "Plural-Forms", "MIME-Version", "Content-Type",
          "Content-Transfer-Encoding")

#: The command named when a compiled catalogue is stale.
COMMAND = "python crankbase/locale/compile_catalogues.py"

# one .po line that is not a comment: a keyword with one quoted string, or a quoted string
_LINE = re.compile(r'(?:(msgctxt|msgid|msgid_plural|msgstr(?:\[\d+\])?)[ \t]+)?'
                   r'"(?:[^"\\]|\\.)*"')


def _check_lines(text: str, where: str) -> None:
    """What Babel's parser reads silently and the old reader refused: every line not a
    comment is one quoted string, alone or after a keyword; ``msgstr`` follows a
    ``msgid`` (once, in a singular entry), ``msgstr[i]`` a ``msgid_plural``."""
    state = None                 # None, "msgid" (awaiting msgstr), "plural", "done"
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        m = _LINE.fullmatch(line)
        if m is None:
            raise CatalogueError(f"{where}:{lineno}: cannot read the line {raw!r}")
        keyword = m.group(1) or ""
        if keyword == "msgid":
            state = "msgid"
        elif keyword == "msgid_plural":
            if state != "msgid":
                raise CatalogueError(f"{where}:{lineno}: msgid_plural without its msgid")
            state = "plural"
        elif keyword == "msgstr":
            if state != "msgid":
                raise CatalogueError(
                    f"{where}:{lineno}: " + ("a plural entry has msgstr[0], msgstr[1] …"
                                             if state == "plural" else
                                             "msgstr without msgid, or twice"))
            state = "done"
        elif keyword.startswith("msgstr[") and state != "plural":
            raise CatalogueError(f"{where}:{lineno}: a singular entry has one msgstr "
                                 "(msgstr[i] follows a msgid_plural)")


class _Catalogue(Catalog):
    """Babel's :class:`~babel.messages.catalog.Catalog`, refusing a key twice and a
    context while a ``.po`` is read, and writing a header of :data:`HEADER` only."""

    where = "?"

    def __setitem__(self, id, message):
        if id:
            key = id[0] if isinstance(id, (tuple, list)) else id
            if message.context is not None:
                raise CatalogueError(f"{self.where}:{message.lineno}: msgctxt: the text "
                                     "layer's keys have no context")
            if id in self:
                raise CatalogueError(f"{self.where}:{message.lineno}: key {key!r} twice "
                                     "in one file")
        super().__setitem__(id, message)

    @property
    def mime_headers(self):
        return [(name, value) for name, value in Catalog.mime_headers.fget(self)
                if name in HEADER]

    @mime_headers.setter
    def mime_headers(self, headers):
        Catalog.mime_headers.fset(self, headers)


def _where(path: Path) -> str:
    return f"{path.parent.name}/{path.name}"


def read_catalogue(path: Path) -> Catalog:
    """One ``.po`` file read by Babel and checked (see the module's docstring)."""
    where = _where(path)
    data = path.read_bytes()
    _check_lines(data.decode("utf-8-sig"), where)
    catalogue = _Catalogue(domain=path.stem, charset="utf-8")
    catalogue.where = where
    try:
        PoFileParser(catalogue, ignore_obsolete=True, abort_invalid=True).parse(
            io.BytesIO(data.removeprefix(b"\xef\xbb\xbf")))
    except PoFileError as exc:
        raise CatalogueError(f"{where}:{exc.lineno + 1}: {exc}") from None
    for message in catalogue:
        if message.id and message.pluralizable and not message.fuzzy:
            for i, form in enumerate(message.string):
                if not form:
                    raise CatalogueError(
                        f"{where}:{message.lineno}: {message.id[0]!r}: msgstr[{i}] missing "
                        f"or empty; the header says nplurals={catalogue.num_plurals}")
    return catalogue


def mo_bytes(catalogue: Catalog) -> bytes:
    """The ``.mo`` of a catalogue, by Babel's ``write_mo`` (fuzzy entries left out)."""
    buf = io.BytesIO()
    write_mo(buf, catalogue)
    return buf.getvalue()


def compile_language(folder: Path) -> dict[Path, bytes]:
    """``{.mo path: bytes}`` of every ``.po`` of one language's folder, the language
    checked as a whole: no key in two areas, one ``Plural-Forms``."""
    out = {}
    owner: dict[str, str] = {}
    rule = None
    for path in sorted(folder.glob("*.po")):
        catalogue = read_catalogue(path)
        if rule is None:
            rule = (catalogue.plural_forms, _where(path))
        elif catalogue.plural_forms != rule[0]:
            raise CatalogueError(f"{_where(path)}: Plural-Forms {catalogue.plural_forms!r}; "
                                 f"{rule[1]} says {rule[0]!r}")
        for message in catalogue:
            if not message.id or message.fuzzy:
                continue
            key = message.id[0] if message.pluralizable else message.id
            if key in owner:
                raise CatalogueError(f"{_where(path)}:{message.lineno}: key {key!r} is also "
                                     f"in {owner[key]}")
            owner[key] = _where(path)
        out[folder / MO_FOLDER / f"{path.stem}.mo"] = mo_bytes(catalogue)
    return out


def compile_all(locale_dir: Path = LOCALE_DIR) -> dict[Path, bytes]:
    """``{.mo path: bytes}`` of every catalogue of every language under ``locale_dir``."""
    out = {}
    for folder in sorted(p for p in locale_dir.iterdir() if p.is_dir()):
        out.update(compile_language(folder))
    return out


def stale(locale_dir: Path = LOCALE_DIR):
    """``(compiled, to write, to remove)``: :func:`compile_all`, the ``.mo`` files missing
    or not what their ``.po`` compiles to, and the ``.mo`` files whose ``.po`` is gone."""
    want = compile_all(locale_dir)
    write = [p for p, data in want.items() if not p.is_file() or p.read_bytes() != data]
    remove = [p for p in sorted(locale_dir.glob(f"*/{MO_FOLDER}/*.mo")) if p not in want]
    return want, write, remove


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 naming every stale .mo")
    parser.add_argument("--locale-dir", type=Path, default=LOCALE_DIR, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    try:
        want, write, remove = stale(args.locale_dir)
    except CatalogueError as exc:
        print(f"compile_catalogues: {exc}", file=sys.stderr)
        return 2
    rel = lambda p: p.relative_to(args.locale_dir).as_posix()  # noqa: E731
    if args.check:
        for p in write:
            print(f"stale: {rel(p)}")
        for p in remove:
            print(f"no .po: {rel(p)}")
        if write or remove:
            print(f"run: {COMMAND}")
        return 1 if write or remove else 0
    for p in write:
        p.parent.mkdir(exist_ok=True)
        p.write_bytes(want[p])
        print(f"wrote {rel(p)}")
    for p in remove:
        p.unlink()
        print(f"removed {rel(p)}")
    print(f"{len(want)} catalogues, {len(write)} written, {len(remove)} removed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
