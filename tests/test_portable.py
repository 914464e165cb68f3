"""Portable (issue 19, item 5): the reports run where Python has no POSIX-only modules
(Windows: no fcntl, resource, pwd, grp, os.fork, os.O_DIRECTORY, and a folder cannot be
opened as a file), and every file a report writes has a name Windows accepts."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from crankbase.output import LOCK_NAME, MANIFEST_NAME, safe_name, verify_report

ROOT = Path(__file__).resolve().parents[1]

# ---------------------------------------------------------------- Windows' naming rules
# (Microsoft, "Naming Files, Paths, and Namespaces", learn.microsoft.com/windows/win32/
# fileio/naming-a-file): no < > : " / \ | ? * nor characters 0-31 in a name; no name
# ending in a dot or a space; no device name CON, PRN, AUX, NUL, COM0-9, LPT0-9 (and the
# superscript digits ¹ ² ³), also not followed by an extension (NUL.txt), in any case;
# at most 255 characters a component.  Judged here independently of safe_name.
_FORBIDDEN = re.compile(r'[<>:"/\\|?*\x00-\x1f]')
_DEVICES = {"CON", "PRN", "AUX", "NUL"} | {f"{d}{i}" for d in ("COM", "LPT")
                                           for i in "0123456789\u00b9\u00b2\u00b3"}


def windows_problem(name: str) -> str | None:
    """Why Windows refuses the file name ``name`` (one path component), or None."""
    if _FORBIDDEN.search(name):
        return f"reserved character {_FORBIDDEN.search(name).group()!r}"
    if name.endswith((".", " ")):
        return "ends in a dot or a space"
    if name.split(".")[0].rstrip(" ").upper() in _DEVICES:
        return "a device name"
    if len(name) > 255:
        return "longer than 255 characters"
    return None


def test_the_judge_knows_the_rules():
    for bad in ("CON", "con.xlsx", "Nul.tar.gz", "com1", "LPT9.csv", "COM\u00b9", "a:b",
                "a?b", "x.", "x ", "tab\there", 'q"uote', "a|b", "aux .txt"):
        assert windows_problem(bad), bad
    for good in ("CONSOLE", "con_.xlsx", "COM10.csv", "nul_.v2.csv", "Дизель_Д-240.xlsx",
                 ".crankdyn-report.json", "petrol-vaz2106_polar.png"):
        assert windows_problem(good) is None, good


# ------------------------------------------------------------------------- safe_name
@pytest.mark.parametrize("device", sorted(_DEVICES - {"COM0", "LPT0"}))
@pytest.mark.parametrize("case", [str.upper, str.lower, str.title])
@pytest.mark.parametrize("suffix", ["", ".v2", ".tar.gz"])
def test_safe_name_never_gives_a_device_name(device, case, suffix):
    name = case(device) + suffix
    stem = safe_name(name)
    assert windows_problem(stem) is None, stem
    for ext in (".xlsx", "_forces.csv", ".png"):           # as the reports name files
        assert windows_problem(stem + ext) is None, stem + ext
    assert stem.upper().startswith(device.upper())      # still recognisably the name


@pytest.mark.parametrize("name, stem", [
    ("CON", "CON_"), ("nul", "nul_"), ("Com1.v2", "Com1_.v2"), ("LPT9", "LPT9_"),
    ("aux.tar.gz", "aux_.tar.gz"), ("CONSOLE", "CONSOLE"), ("COM10", "COM10"),
    ("con_", "con_"), ('a<b>c:d"e/f\\g|h?i*j', "a_b_c_d_e_f_g_h_i_j"),
    ("tab\there\x01", "tab_here"), ("trailing dots... ", "trailing_dots"),
    ("Дизель Д-240", "Дизель_Д-240"), ("...", "report"), ("", "report")])
def test_safe_name_replaces_what_windows_refuses(name, stem):
    assert safe_name(name) == stem
    assert windows_problem(safe_name(name)) is None


def test_safe_name_device_after_cutting():
    """A long name cut down to a device name is still made safe."""
    assert safe_name("AUX" + "." * 200, max_bytes=10) == "AUX_"
    assert safe_name("x" * 300, max_bytes=160) == "x" * 160


# ------------------------------------------------------------- every example's files
#: The report of every bundled example (the session's shared runs: the engine, linkage,
#: dynamics and balance tests read the same folders).
REPORTS = [("engine", "--example", "petrol", "--lang", "ru"),
           ("engine", "--example", "diesel", "--lang", "en"),
           ("engine", "--example", "six", "--lang", "en"),
           ("engine", "--example", "v8", "--bearings"),
           ("linkage", "--example"), ("linkage", "--example", "press"),
           *[("dynamics", "--example", ex, "--lang", lang)
             for ex in ("flywheel", "press", "petrol", "hoist") for lang in ("ru", "en")],
           *[("balance", "--example", ex, "--lang", lang)
             for ex in ("rotor", "ratchet") for lang in ("ru", "en")]]


def test_every_file_of_every_example_has_a_windows_name(cli_report):
    seen = 0
    for argv, rep in zip(REPORTS, cli_report.many(REPORTS)):
        assert rep.rc == 0, (argv, rep.err)
        listed = set(verify_report(rep.folder))
        on_disk = {p.name for p in rep.folder.iterdir()}
        assert on_disk == listed | {MANIFEST_NAME}, argv     # no lock file, nothing stray
        names = [p.relative_to(rep.folder) for p in rep.folder.rglob("*")]
        for rel in names:
            for part in rel.parts:
                assert windows_problem(part) is None, (argv, str(rel),
                                                       windows_problem(part))
        # Windows folders ignore case: two names differing only in case would collide
        lower = [str(r).lower() for r in names]
        assert len(set(lower)) == len(lower), argv
        seen += len(names)
    assert seen > 100


# ------------------------------------------------------------- without POSIX modules
WITHOUT_POSIX = r"""
import io, json, os, sys
from contextlib import redirect_stderr
for mod in ("fcntl", "resource", "pwd", "grp"):
    sys.modules[mod] = None                # importing it raises ImportError, as on Windows
for name in ("O_DIRECTORY", "fork", "forkpty"):
    if hasattr(os, name):
        delattr(os, name)
_open = os.open
def _windows_open(path, flags, *args, **kw):
    if os.path.isdir(path):                # Windows cannot open a folder as a file
        raise PermissionError(13, "Permission denied", str(path))
    return _open(path, flags, *args, **kw)
os.open = _windows_open
from pathlib import Path, PurePath
from matplotlib.figure import Figure
def _laid_out(self, fname, *args, format=None, **kwargs):
    # every artist drawn without output (matplotlib's and Pillow's encoders, which do
    # run on Windows, are not what this process judges), a short text for the file
    fmt = format or PurePath(str(fname)).suffix.lstrip(".")
    if not getattr(self, "_laid_out", False):      # once a figure, whatever its formats
        self.draw_without_rendering()
        self._laid_out = True
    Path(fname).write_bytes(f"figure laid out, not encoded ({fmt})\n".encode())
Figure.savefig = _laid_out
import crankbase.plot_layout as _layout   # savefig lays out: no second layout before it
_layout.save_laid_out = lambda fig, path, fmt, dpi, **kw: fig.savefig(path, format=fmt,
                                                                     dpi=dpi, **kw)
from crankdyn.cli import main
from crankbase.output import verify_report
results = []
for argv in json.loads(sys.argv[1]):       # one run after the other, as separate calls
    err = io.StringIO()
    with redirect_stderr(err):
        code = main(argv)
    out = argv[argv.index("-o") + 1]       # the folder as this run left it
    try:
        listed = verify_report(out)
    except Exception as exc:
        listed = repr(exc)
    results.append({"code": code, "stderr": err.getvalue(), "listed": listed,
                    "on_disk": sorted(os.listdir(out))})
try:
    import fcntl
except ImportError:
    fcntl = None
print(json.dumps({"runs": results, "fcntl_imported": fcntl is not None}))
"""


@pytest.mark.slow
def test_reports_run_without_posix_only_modules(tmp_path):
    """A whole engine report and a linkage report (twice into one folder: the second
    replaces the first and removes its plots) through the CLI's main in a process where
    fcntl, resource, pwd and grp cannot be imported, os has no O_DIRECTORY nor fork,
    and a folder cannot be opened: each succeeds, is complete, and leaves no lock.  The
    three runs are three calls of main in one such process (one start of Python and of
    the library instead of three), each with its own exit status and stderr.  Every
    figure is built and laid out (each artist drawn, without output) and its files
    written through the report's own staging, but not encoded: the PNG and SVG
    encoders are matplotlib's and Pillow's, which run on Windows (the simulation here
    judges this project's code; the same reports' figures are encoded by the session's
    shared runs, ``engine --example petrol --lang ru`` and ``linkage --example`` (the
    ratchet in Russian; the shared English petrol report saves its figures unrendered,
    tests/conftest.py UNRENDERED_REPORTS))."""
    import json
    import os

    runs = [(["engine", "--example", "petrol", "--lang", "en"], tmp_path / "engine"),
            (["linkage", "--example", "ratchet", "--lang", "en"], tmp_path / "linkage"),
            (["linkage", "--example", "ratchet", "--no-plots"], tmp_path / "linkage")]
    argvs = [[*argv, "-o", str(out)] for argv, out in runs]
    proc = subprocess.run([sys.executable, "-c", WITHOUT_POSIX, json.dumps(argvs)],
                          cwd=ROOT, capture_output=True, text=True,
                          env={**os.environ, "MPLBACKEND": "Agg"})
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr and "Warning" not in proc.stderr, proc.stderr
    done = json.loads(proc.stdout.splitlines()[-1])
    assert not done["fcntl_imported"]
    assert len(done["runs"]) == len(runs)
    for (argv, out), run in zip(runs, done["runs"]):        # each run as it left it
        assert run["code"] == 0, (argv, run["stderr"])
        assert "Traceback" not in run["stderr"] and "Warning" not in run["stderr"], \
            (argv, run["stderr"])
        assert isinstance(run["listed"], list), (argv, run["listed"])  # verify_report
        assert LOCK_NAME not in run["on_disk"], argv
        assert set(run["on_disk"]) == set(run["listed"]) | {MANIFEST_NAME}, argv
    assert [len([n for n in run["listed"] if n.endswith(".png")])
            for run in done["runs"]] == [13, 5, 0]  # the plain run's plots, then none
    for _, out in runs:                              # and as the parent reads them
        names = verify_report(out)
        assert not (out / LOCK_NAME).exists()
        assert {p.name for p in out.iterdir()} == set(names) | {MANIFEST_NAME}
    assert len([n for n in verify_report(tmp_path / "engine") if n.endswith(".png")]) == 13
    linkage = verify_report(tmp_path / "linkage")
    assert "ratchet-drive.xlsx" in linkage and not [n for n in linkage if n.endswith(".png")]


# ------------------------------------------------------------------- the output lock
def test_lock_excludes_and_leaves_no_file(tmp_path):
    """The folder's lock (filelock on .crankdyn-lock): a second taker waits until the
    first lets go, then holds a lock on a file that is there; each deletes the file when
    it lets go, and recover_output leaves a held lock alone but removes a stale one."""
    import threading

    from crankbase.output import _lock, _unlock, recover_output

    d = tmp_path / "out"
    first = _lock(d)
    assert (d / LOCK_NAME).is_file()
    recover_output(d)                                   # held: not touched
    assert (d / LOCK_NAME).is_file()
    got, second = threading.Event(), []

    def take():
        second.append(_lock(d))
        got.set()

    t = threading.Thread(target=take)
    t.start()
    assert not got.wait(0.5)                            # waits while the first holds it
    _unlock(first, d)
    assert got.wait(60)
    t.join()
    assert (d / LOCK_NAME).is_file()                    # the second's own lock file
    _unlock(second[0], d)
    assert not (d / LOCK_NAME).exists()
    (d / LOCK_NAME).write_bytes(b"")                    # what a killed run leaves
    recover_output(d)
    assert list(d.iterdir()) == []


def test_process_start_without_proc(monkeypatch):
    """Where there is no /proc (macOS, BSD) a process's existence is asked of os.kill
    with signal 0: this process exists (start time unknown, ""), a finished one does not
    (None)."""
    import builtins

    import crankbase.output as out

    real_open, real_isdir = builtins.open, out.os.path.isdir

    def no_proc_open(path, *a, **kw):
        if str(path).startswith("/proc/"):
            raise FileNotFoundError(2, "No such file or directory", str(path))
        return real_open(path, *a, **kw)

    done = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)
    monkeypatch.setattr(builtins, "open", no_proc_open)
    monkeypatch.setattr(out.os.path, "isdir",
                        lambda p: False if str(p).startswith("/proc") else real_isdir(p))
    assert out._process_start(__import__("os").getpid()) == ""
    assert out._process_start(int(done.stdout)) is None
