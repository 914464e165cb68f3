"""The terminal summary in every language whatever the streams' encoding (issue #19 item 5,
Windows): redirected to a file, Windows' Python writes in the ANSI code page (cp1252 on an
English Windows), which has no Cyrillic, Greek or "→"; the report is then written but its
summary used to end in a UnicodeEncodeError.  ``crankdyn`` (``main()`` without ``argv``)
writes UTF-8 to a redirected stream and keeps a terminal's or ``PYTHONIOENCODING``'s
encoding with "?" for a character it lacks."""
from __future__ import annotations

import io
import subprocess
import sys

import pytest

from crankdyn import cli


class _Redirected(io.TextIOWrapper):
    """A stream as Windows hands a redirected one to Python: cp1252, not a terminal."""

    def __init__(self, tty=False):
        super().__init__(io.BytesIO(), encoding="cp1252", newline="\n")
        self._tty = tty

    def isatty(self):
        return self._tty

    def text(self):
        self.flush()
        return self.buffer.getvalue()


def _summary(monkeypatch, tmp_path, tty=False, env=None):
    out, err = _Redirected(tty), _Redirected(tty)
    monkeypatch.setattr(sys, "stdout", out)
    monkeypatch.setattr(sys, "stderr", err)
    for k, v in (env or {}).items():
        monkeypatch.setenv(k, v)
    if not env:
        monkeypatch.delenv("PYTHONIOENCODING", raising=False)
    monkeypatch.setattr(sys, "argv", ["crankdyn", "linkage", "--example", "ratchet",
                                      "--no-plots", "--lang", "ru", "-o",
                                      str(tmp_path / "o")])
    rc = cli.main()
    return rc, out, err


def test_a_redirected_russian_summary_is_written_in_utf8(monkeypatch, tmp_path):
    rc, out, _ = _summary(monkeypatch, tmp_path)
    assert rc == 0 and out.encoding == "utf-8"
    text = out.text().decode("utf-8")
    assert text.startswith("ratchet-drive (кривошипно-коромысловый механизм)")
    assert "φр.х" in text
    with pytest.raises(UnicodeEncodeError):        # what cp1252 alone would have failed on
        text.encode("cp1252")


def test_a_terminal_keeps_its_encoding_and_replaces_what_it_lacks(monkeypatch, tmp_path):
    rc, out, _ = _summary(monkeypatch, tmp_path, tty=True)
    assert rc == 0 and out.encoding == "cp1252" and out.errors == "replace"
    assert b"?" in out.text()
    _, out2, _ = _summary(monkeypatch, tmp_path, env={"PYTHONIOENCODING": "cp1252"})
    assert out2.encoding == "cp1252" and out2.errors == "replace"


def test_a_call_from_a_script_leaves_the_streams_alone(monkeypatch, tmp_path):
    out = _Redirected()
    monkeypatch.setattr(sys, "stdout", out)
    with pytest.raises(UnicodeEncodeError):        # the script's own stream, its own choice
        cli.main(["linkage", "--example", "ratchet", "--no-plots", "--lang", "ru", "-o",
                  str(tmp_path / "o")])
    assert out.encoding == "cp1252"


def test_the_command_redirected_under_an_ansi_code_page(tmp_path):
    """The command in a process of its own whose standard output is cp1252 and not a
    terminal (a pipe), as on an English Windows: exit 0 and the whole Russian summary."""
    import os

    code = ("import io, sys; from crankdyn.cli import main; "
            "sys.stdout = io.TextIOWrapper(sys.stdout.buffer, encoding='cp1252'); "
            "sys.argv = ['crankdyn', 'linkage', '--example', 'ratchet', '--no-plots', "
            f"'--lang', 'ru', '-o', {str(tmp_path / 'o')!r}]; sys.exit(main())")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONIOENCODING"}
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, timeout=300,
                       env=env)
    assert r.returncode == 0, r.stderr.decode("utf-8", "replace")
    text = r.stdout.decode("utf-8")
    assert text.startswith("ratchet-drive (кривошипно-коромысловый механизм)")
    assert "ratchet-drive.xlsx" in text.splitlines()[-1]
