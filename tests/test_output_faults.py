"""Output robustness (issue 15): a report replaces the old one as one unit, survives kills
and concurrent runs, and every file-system failure is one clear line with exit 2."""
from __future__ import annotations

import errno
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from crankbase.errors import OutputError
from crankbase.output import (COMMIT_NAME, MANIFEST_NAME, STAGE_PREFIX, recover_output,
                              staged_output, verify_report)
from crankdyn.cli import main

ROOT = Path(__file__).resolve().parents[1]
#: Three synthesis reports of one unit (the design "old"): A writes old.toml as well, B
#: does not (so B's report must also remove old.toml, which belonged to A's report).
RUN_A = ["synth", "--l2", "0.7", "--l3", "0.6", "--ground", "0.5", "--name", "old",
         "--no-plots"]
RUN_B = ["synth", "--l2", "0.6", "--l3", "0.7", "--name", "old", "--no-plots"]
RUN_C = ["synth", "--l1", "0.1", "--name", "old", "--no-plots"]


def _cli(args, out, **kw):
    return subprocess.Popen([sys.executable, "-m", "crankdyn", *args, "-o", str(out)],
                            cwd=ROOT, stdout=subprocess.DEVNULL, **kw)


def _content(folder):
    """The report as {file: bytes} for the deterministic files (CSV, TOML), with the
    manifest's file list; the workbook carries a time stamp, so it is checked through the
    manifest (verify_report) only."""
    names = verify_report(folder)
    visible = sorted(p.name for p in folder.iterdir() if not p.name.startswith("."))
    assert visible == names, (visible, names)          # nothing but the report
    return {n: (folder / n).read_bytes() for n in names if not n.endswith(".xlsx")}


@pytest.fixture(scope="module")
def references(tmp_path_factory):
    """The three reports, each written whole by the CLI's main in this process (the
    same code the killed child processes run, without a start of Python each)."""
    import contextlib
    import io

    refs = {}
    for key, args in (("A", RUN_A), ("B", RUN_B), ("C", RUN_C)):
        out = tmp_path_factory.mktemp(key) / "out"
        with contextlib.redirect_stdout(io.StringIO()):
            assert main([*args, "-o", str(out)]) == 0
        refs[key] = (out, _content(out))
    assert refs["A"][1] != refs["B"][1] and "old.toml" in refs["A"][1]
    return refs


def _no_leftovers(folder):
    hidden = sorted(p.name for p in folder.iterdir() if p.name.startswith("."))
    assert hidden in ([MANIFEST_NAME], []), hidden


def test_sigkill_at_random_moments(references, tmp_path):
    """SIGKILL anywhere in a run: after the next run's recovery the folder holds exactly the
    old or exactly the new report; the next run leaves no staging behind."""
    rng = random.Random(15)
    out = tmp_path / "out"
    seen = set()
    for trial in range(6):
        if out.exists():
            shutil.rmtree(out)
        shutil.copytree(references["A"][0], out)
        proc = _cli(RUN_B, out)
        time.sleep(rng.uniform(0.3, 1.6))
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        if not (out / COMMIT_NAME).exists():   # no replacement under way: a whole report
            assert _content(out) in (references["A"][1], references["B"][1])
        recover_output(out)
        got = _content(out)
        assert got in (references["A"][1], references["B"][1])
        seen.add("A" if got == references["A"][1] else "B")
        assert not [p for p in out.iterdir() if p.name.startswith(STAGE_PREFIX)
                    or p.name == COMMIT_NAME]
    # the next run: complete report, nothing hidden left but the manifest
    assert _cli(RUN_C, out).wait() == 0
    assert _content(out) == references["C"][1]
    _no_leftovers(out)


SLOW_COMMIT = """
import os, sys, time
real_replace, real_rename = os.replace, os.rename
def slow_replace(a, b):
    real_replace(a, b)
    if '.crankdyn-commit' in str(a):
        time.sleep(0.03)
def rename(a, b):
    real_rename(a, b)
    if str(b).endswith('.crankdyn-commit'):
        sys.stderr.write('COMMIT\\n'); sys.stderr.flush()
os.replace, os.rename = slow_replace, rename
from crankdyn.cli import main
sys.exit(main(sys.argv[1:]))
"""


def test_sigkill_inside_the_replace_phase(references, tmp_path):
    """The replace phase is slowed (30 ms per file) and the run killed inside it: the
    folder is marked as mid-replacement (verify_report refuses it) and recovery completes
    the new report; no mix of old and new files survives."""
    rng = random.Random(7)
    out = tmp_path / "out"
    for trial in range(5):
        if out.exists():
            shutil.rmtree(out)
        shutil.copytree(references["A"][0], out)
        proc = subprocess.Popen([sys.executable, "-c", SLOW_COMMIT, *RUN_B, "-o", str(out)],
                                cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                text=True)
        assert proc.stderr.readline().strip() == "COMMIT"
        time.sleep(rng.uniform(0.0, 0.12))
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        proc.stderr.close()
        if (out / COMMIT_NAME).exists():
            with pytest.raises(OutputError, match="interrupted"):
                verify_report(out)
        recover_output(out)
        assert _content(out) == references["B"][1]
        _no_leftovers(out)


def test_concurrent_runs_give_one_complete_report(references, tmp_path):
    out = tmp_path / "out"
    procs = [_cli(args, out) for args in (RUN_A, RUN_B, RUN_C, RUN_B)]
    assert [p.wait() for p in procs] == [0, 0, 0, 0]
    got = _content(out)
    assert got in [r[1] for r in references.values()]
    _no_leftovers(out)


def test_stale_staging_of_dead_runs_removed_live_ones_kept(tmp_path):
    out = tmp_path / "out"
    with staged_output(out) as stage:
        (stage / "a.csv").write_text("x\n1\n")
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    live = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(30)"])
    try:
        from crankbase.output import _process_start
        start = _process_start(live.pid)
        stale = out / f"{STAGE_PREFIX}{dead.pid}.1.abc"
        reused = out / f"{STAGE_PREFIX}{live.pid}.{int(start) - 1}.abc"   # pid reused
        running = out / f"{STAGE_PREFIX}{live.pid}.{start}.abc"
        for d in (stale, reused, running):
            d.mkdir()
            (d / "forces.csv").write_text("half")
        with staged_output(out) as stage:
            (stage / "a.csv").write_text("x\n2\n")
        assert not stale.exists() and not reused.exists()
        assert running.exists()          # its owner is alive: not ours to delete
    finally:
        live.kill()
        live.wait()
    assert (out / "a.csv").read_text() == "x\n2\n"


def test_obsolete_files_of_the_old_report_removed_unless_changed(tmp_path):
    out = tmp_path / "out"
    with staged_output(out) as stage:
        for n in ("a.csv", "b.csv", "c.csv"):
            (stage / n).write_text(n)
    (out / "c.csv").write_text("edited by the user")
    (out / "notes.txt").write_text("mine")
    with staged_output(out) as stage:
        (stage / "a.csv").write_text("new")
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [MANIFEST_NAME, "a.csv", "c.csv", "notes.txt"])
    assert (out / "c.csv").read_text() == "edited by the user"
    assert verify_report(out) == ["a.csv"]
    assert json.loads((out / MANIFEST_NAME).read_text())["files"]["a.csv"]["size"] == 3


def test_units_whose_names_share_a_prefix_keep_their_files(tmp_path):
    """Reports named ``press`` and ``press_b`` in one folder: the manifest records which
    report wrote each file, so a run of ``press`` replaces its own old files only, never
    ``press_b_…`` (whose names also start with ``press_``)."""
    out = tmp_path / "out"
    with staged_output(out, unit="press_b") as stage:
        for n in ("press_b.xlsx", "press_b_plans.csv", "press_b_plans_2.pdf"):
            (stage / n).write_text(n)
    with staged_output(out, unit="press") as stage:
        for n in ("press.xlsx", "press_plans.csv", "press_plans_2.pdf"):
            (stage / n).write_text(n)
    with staged_output(out, unit="press") as stage:          # position 3 instead of 2
        for n in ("press.xlsx", "press_plans.csv", "press_plans_3.pdf"):
            (stage / n).write_text(n + " again")
    names = sorted(p.name for p in out.iterdir() if p.name != MANIFEST_NAME)
    assert names == ["press.xlsx", "press_b.xlsx", "press_b_plans.csv", "press_b_plans_2.pdf",
                     "press_plans.csv", "press_plans_3.pdf"]
    files = json.loads((out / MANIFEST_NAME).read_text())["files"]
    assert {n: f["unit"] for n, f in files.items()} == {
        n: ("press_b" if n.startswith("press_b") else "press") for n in names}
    assert verify_report(out) == names
    # a manifest of an older version (no unit per file): judged by the name, as before
    old = {n: {k: v for k, v in f.items() if k != "unit"} for n, f in files.items()}
    (out / MANIFEST_NAME).write_text(json.dumps({"format": 1, "files": old}))
    with staged_output(out, unit="press_b") as stage:
        (stage / "press_b.xlsx").write_text("b again")
    left = sorted(p.name for p in out.iterdir() if p.name != MANIFEST_NAME)
    assert left == ["press.xlsx", "press_b.xlsx", "press_plans.csv", "press_plans_3.pdf"]


def test_failure_inside_leaves_nothing_and_removes_created_folders(tmp_path):
    out = tmp_path / "new" / "deeper" / "out"
    with pytest.raises(OutputError, match=f"cannot write the report into {out}: No space"):
        with staged_output(out) as stage:
            (stage / "a.csv").write_text("x")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    assert list(tmp_path.iterdir()) == []


def test_enospc_while_writing_a_plot_cli(tmp_path, capsys, monkeypatch, unrendered_figures):
    """The first report's plots are saved unrendered (names only: what the failed second
    run must leave untouched is the files, not what they show)."""
    import matplotlib.figure

    out = tmp_path / "out"
    assert main(["synth", "--lang", "en", "--l2", "0.7", "--l3", "0.6", "-o", str(out)]) == 0
    assert unrendered_figures                               # the plots were saved
    before = {p.name: p.stat().st_mtime_ns for p in out.iterdir()}

    def full(self, fname, *a, **k):
        Path(fname).write_bytes(b"\x89PNG partial")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(fname))
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", full)
    capsys.readouterr()
    assert main(["synth", "--lang", "en", "--l2", "0.6", "--l3", "0.7", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"crankdyn synth: error: cannot write the report into {out}: "
                   "No space left on device"]
    assert {p.name: p.stat().st_mtime_ns for p in out.iterdir()} == before


def test_output_through_a_file_and_empty_output(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("x")
    assert main(["synth", "--lang", "en",
                 "--l1", "0.1", "--no-plots", "-o", str(afile / "sub")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(afile) in err[0] and "not a folder" in err[0], err
    assert main(["synth", "--lang", "en", "--l1", "0.1", "--no-plots", "-o", str(afile)]) == 2
    assert "not a folder" in capsys.readouterr().err
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        for cmd in (["synth", "--l1", "0.1"], ["engine", "--example"],
                    ["linkage", "--example"]):
            assert main([*cmd, "--lang", "en", "-o", ""]) == 2
            err = capsys.readouterr().err.strip().splitlines()
            assert len(err) == 1 and "-o: empty output folder" in err[0], err
    finally:
        os.chdir(cwd)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


# ---------------------------------------------------------------- real file systems
def _namespace_ok():
    if not shutil.which("unshare") or not sys.platform.startswith("linux"):
        return "needs Linux unshare"
    r = subprocess.run(["unshare", "-Urm", "sh", "-c", "mount -t tmpfs -o size=16k none /mnt"],
                       capture_output=True)
    return None if r.returncode == 0 else "user+mount namespaces not permitted here: " \
        + r.stderr.decode(errors="replace").strip()


NS_REASON = _namespace_ok()
needs_ns = pytest.mark.skipif(NS_REASON is not None, reason=str(NS_REASON))


def _in_namespace(setup, args, tmp_path):
    """Run the CLI inside a private user+mount namespace after the shell ``setup`` (which
    mounts tmpfs file systems under ``$M``); return (rc, stderr, listing of $M)."""
    m = tmp_path / "m"
    m.mkdir()
    script = (f"set -e; M={m}; {setup}; set +e; "
              f"{sys.executable} -m crankdyn {' '.join(args)} >/dev/null; rc=$?; "
              f"echo RC=$rc; find $M -mindepth 1 | sort")
    r = subprocess.run(["unshare", "-Urm", "sh", "-c", script], cwd=ROOT,
                       capture_output=True, text=True, timeout=60)
    lines = r.stdout.splitlines()
    rc = int(lines[0].removeprefix("RC="))
    return rc, r.stderr.strip().splitlines(), [l.replace(str(m), "$M") for l in lines[1:]]


@needs_ns
def test_mount_point_as_output_folder(tmp_path):
    """-o on a mount point (staging beside it would cross devices)."""
    rc, err, files = _in_namespace("mount -t tmpfs -o size=4m none $M",
                                   [*RUN_B, "-o", "$M"], tmp_path)
    assert rc == 0, err
    assert "$M/old_mechanism.csv" in files and f"$M/{MANIFEST_NAME}" in files
    assert not [f for f in files if STAGE_PREFIX in f]


@needs_ns
def test_full_disk(tmp_path):
    rc, err, files = _in_namespace("mount -t tmpfs -o size=12k none $M",
                                   [*RUN_B, "--lang", "en", "-o", "$M/out"], tmp_path)
    assert rc == 2
    assert err == ["crankdyn synth: error: cannot write the report into $M/out: No space "
                   "left on device".replace("$M", str(tmp_path / "m"))]
    assert files == []                      # the folder it created is gone again


@needs_ns
def test_read_only_file_system(tmp_path):
    rc, err, files = _in_namespace(
        "mount -t tmpfs none $M; mkdir $M/out; echo keep > $M/out/forces.csv; "
        "mount -o remount,ro,bind $M", [*RUN_B, "--lang", "en", "-o", "$M/out/sub"], tmp_path)
    assert rc == 2
    assert len(err) == 1 and err[0].startswith("crankdyn synth: error: ") \
        and "Read-only file system" in err[0] and str(tmp_path / "m" / "out" / "sub") in err[0]
    assert files == ["$M/out", "$M/out/forces.csv"]


@needs_ns
def test_writable_folder_under_read_only_parent(tmp_path):
    rc, err, files = _in_namespace(
        "mount -t tmpfs none $M; mkdir $M/w; mount -t tmpfs none $M/w; "
        "mount -o remount,ro,bind $M", [*RUN_B, "-o", "$M/w"], tmp_path)
    assert rc == 0, err
    assert "$M/w/old_mechanism.csv" in files


def test_verify_report_detects_a_changed_or_missing_file(tmp_path):
    out = tmp_path / "out"
    with staged_output(out) as stage:
        (stage / "a.csv").write_text("1\n")
        (stage / "b.csv").write_text("2\n")
    assert verify_report(out) == ["a.csv", "b.csv"]
    (out / "a.csv").write_text("9\n")
    with pytest.raises(OutputError, match="a.csv: not the file the report's manifest lists"):
        verify_report(out)
    (out / "a.csv").unlink()
    with pytest.raises(OutputError, match="a.csv"):
        verify_report(out)
    with pytest.raises(OutputError, match="no crankdyn report"):
        verify_report(tmp_path)
