"""Output robustness (issue 15): a report replaces the old one as one unit, survives kills
and concurrent runs, and every file-system failure is one clear line with exit 2."""
from __future__ import annotations

import errno
import json
import os
import random
import shlex
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


#: A process that imports the CLI and runs one report once (every lazy import done, the
#: text catalogues read), then forks one child process per run asked of it: each child
#: runs ``crankdyn.cli.main(argv)`` (what ``python -m crankdyn`` runs) and exits with its
#: status.  A child is a real process that is killed, or runs beside others, while it
#: writes its report; what it no longer pays each time is the start of Python, the
#: imports and the catalogues (~0.8 s of CPU a run, the time the old fresh processes
#: were mostly killed in, before they wrote anything).  The protocol: one JSON line
#: each way; ``{"run": argv, "mark": path or null}`` → ``{"pid": n}`` (``mark``: the
#: child's replace phase is slowed by 30 ms a file and the file ``mark`` is written
#: when the commit marker is in place), ``{"wait": n}`` → ``{"rc": exit code}``
#: (negative: killed by that signal), ``{"warm": seconds}`` the warm-up run's time.
FORK_SERVER = r"""
import contextlib, io, json, os, sys, time
from crankdyn.cli import main

def slowed_commit(mark):
    real_replace, real_rename = os.replace, os.rename
    def slow_replace(a, b):
        real_replace(a, b)
        if '.crankdyn-commit' in str(a):
            time.sleep(0.03)
    def rename(a, b):
        real_rename(a, b)
        if str(b).endswith('.crankdyn-commit'):
            with open(mark, 'w') as f:
                f.write('COMMIT')
    os.replace, os.rename = slow_replace, rename

def child(argv, mark):
    rc = 70
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)                      # its terminal text goes nowhere
        if mark:
            slowed_commit(mark)
        rc = main(argv)
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(rc)

t0 = time.perf_counter()
with contextlib.redirect_stdout(io.StringIO()):
    assert main(sys.argv[1:]) == 0                 # the warm-up run
print(json.dumps({"warm": time.perf_counter() - t0}), flush=True)
for line in sys.stdin:
    req = json.loads(line)
    if "run" in req:
        pid = os.fork()
        if pid == 0:
            child(req["run"], req.get("mark"))
        reply = {"pid": pid}
    else:
        reply = {"rc": os.waitstatus_to_exitcode(os.waitpid(req["wait"], 0)[1])}
    print(json.dumps(reply), flush=True)
"""


class Forker:
    """The test's end of :data:`FORK_SERVER`."""

    def __init__(self, warm_out):
        self.proc = subprocess.Popen([sys.executable, "-c", FORK_SERVER, *RUN_C, "-o",
                                      str(warm_out)], cwd=ROOT, stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, text=True)
        self.warm_s = self._ask(None)["warm"]

    def _ask(self, req):
        if req is not None:
            self.proc.stdin.write(json.dumps(req) + "\n")
            self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        assert line, f"the fork server ended (exit {self.proc.wait()})"
        return json.loads(line)

    def run(self, args, out, mark=None):
        """Start ``crankdyn ARGS -o OUT`` in a forked child; its pid."""
        return self._ask({"run": [*args, "-o", str(out)],
                          "mark": None if mark is None else str(mark)})["pid"]

    def wait(self, pid):
        """The child's exit status (negative: the signal that killed it)."""
        return self._ask({"wait": pid})["rc"]

    def close(self):
        self.proc.stdin.close()
        assert self.proc.wait(60) == 0
        self.proc.stdout.close()


@pytest.fixture(scope="module")
def forker(tmp_path_factory):
    if not hasattr(os, "fork"):           # Windows: no fork, no SIGKILL
        pytest.skip("the killed and concurrent runs are forked children (POSIX os.fork)")
    f = Forker(tmp_path_factory.mktemp("warm") / "out")
    yield f
    f.close()


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


def test_sigkill_at_random_moments(references, forker, tmp_path):
    """SIGKILL anywhere in a run: after the next run's recovery the folder holds exactly the
    old or exactly the new report; the next run leaves no staging behind.  The moments
    are drawn over the run's own length (a whole run of B over A timed first), so that
    the kills land while it computes, writes, stages and replaces."""
    rng = random.Random(15)
    out = tmp_path / "out"
    shutil.copytree(references["A"][0], out)
    t0 = time.monotonic()
    assert forker.wait(forker.run(RUN_B, out)) == 0
    whole = time.monotonic() - t0
    assert _content(out) == references["B"][1]
    seen = set()
    for trial in range(6):
        if out.exists():
            shutil.rmtree(out)
        shutil.copytree(references["A"][0], out)
        pid = forker.run(RUN_B, out)
        time.sleep(rng.uniform(0.0, 1.2 * whole))
        os.kill(pid, signal.SIGKILL)
        assert forker.wait(pid) in (-signal.SIGKILL, 0)   # killed, or done before
        if not (out / COMMIT_NAME).exists():   # no replacement under way: a whole report
            assert _content(out) in (references["A"][1], references["B"][1])
        recover_output(out)
        got = _content(out)
        assert got in (references["A"][1], references["B"][1])
        seen.add("A" if got == references["A"][1] else "B")
        assert not [p for p in out.iterdir() if p.name.startswith(STAGE_PREFIX)
                    or p.name == COMMIT_NAME]
    # the next run: complete report, nothing hidden left but the manifest
    assert forker.wait(forker.run(RUN_C, out)) == 0
    assert _content(out) == references["C"][1]
    _no_leftovers(out)


def test_sigkill_inside_the_replace_phase(references, forker, tmp_path):
    """The replace phase is slowed (30 ms per file) and the run killed inside it: the
    folder is marked as mid-replacement (verify_report refuses it) and recovery completes
    the new report; no mix of old and new files survives."""
    rng = random.Random(7)
    out = tmp_path / "out"
    for trial in range(5):
        if out.exists():
            shutil.rmtree(out)
        shutil.copytree(references["A"][0], out)
        mark = tmp_path / f"commit{trial}"
        pid = forker.run(RUN_B, out, mark=mark)
        deadline = time.monotonic() + 120
        while not mark.exists():                    # the commit marker is in place
            assert time.monotonic() < deadline, "no commit after 120 s"
            time.sleep(0.002)
        time.sleep(rng.uniform(0.0, 0.12))
        os.kill(pid, signal.SIGKILL)
        assert forker.wait(pid) in (-signal.SIGKILL, 0)
        if (out / COMMIT_NAME).exists():
            with pytest.raises(OutputError, match="interrupted"):
                verify_report(out)
        recover_output(out)
        assert _content(out) == references["B"][1]
        _no_leftovers(out)


def test_concurrent_runs_give_one_complete_report(references, forker, tmp_path):
    out = tmp_path / "out"
    pids = [forker.run(args, out) for args in (RUN_A, RUN_B, RUN_C, RUN_B)]
    assert [forker.wait(p) for p in pids] == [0, 0, 0, 0]
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


#: The file-system cases, each a tmpfs set up under its own folder ``$M`` and one run of
#: the CLI: {case: (shell setup, the CLI's arguments)}.
NS_CASES = {
    "mount point": ("mount -t tmpfs -o size=4m none $M", [*RUN_B, "-o", "$M"]),
    "full disk": ("mount -t tmpfs -o size=12k none $M", [*RUN_B, "--lang", "en", "-o",
                                                          "$M/out"]),
    "read-only": ("mount -t tmpfs none $M; mkdir $M/out; echo keep > $M/out/forces.csv; "
                  "mount -o remount,ro,bind $M", [*RUN_B, "--lang", "en", "-o",
                                                  "$M/out/sub"]),
    "read-only parent": ("mount -t tmpfs none $M; mkdir $M/w; mount -t tmpfs none $M/w; "
                         "mount -o remount,ro,bind $M", [*RUN_B, "-o", "$M/w"]),
}

#: The runs of :data:`NS_CASES` in one process: each ``main(argv)`` with its own stderr.
NS_RUNS = r"""
import contextlib, io, json, sys
from crankdyn.cli import main
done = []
for argv in json.loads(sys.argv[1]):
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        try:
            rc = main(argv)
        except SystemExit as exc:
            rc = exc.code
    done.append({"rc": rc, "err": err.getvalue()})
print(json.dumps(done))
"""


@pytest.fixture(scope="module")
def namespace_runs(tmp_path_factory):
    """Every case of :data:`NS_CASES` inside one private user+mount namespace: the shell
    sets up each case's file systems under its own ``$M``, then one Python process runs
    the CLI's ``main`` once per case, one after the other, each with its own exit status
    and stderr (one start of Python and of the library for the four, as
    tests/test_portable.py runs its reports); then the listing of each ``$M``.
    {case: (rc, stderr lines, listing of $M with the folder written "$M", the folder)}."""
    tmp = tmp_path_factory.mktemp("ns")
    folders = {case: tmp / f"m{i}" for i, case in enumerate(NS_CASES)}
    setups = []
    argvs = []
    for case, (setup, args) in NS_CASES.items():
        m = folders[case]
        m.mkdir()
        setups.append(f"M={m}; {setup}")
        argvs.append([a.replace("$M", str(m)) for a in args])
    lists = "; ".join(f"echo '#{i}'; find {m} -mindepth 1 | sort"
                      for i, m in enumerate(folders.values()))
    script = (f"set -e; {'; '.join(setups)}; set +e; "
              f"{sys.executable} -c {shlex.quote(NS_RUNS)} {shlex.quote(json.dumps(argvs))}; "
              f"{lists}")
    r = subprocess.run(["unshare", "-Urm", "sh", "-c", script], cwd=ROOT,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout.startswith("["), r.stderr
    head, *rest = r.stdout.split("\n#")
    runs = json.loads(head)
    out = {}
    for i, (case, m) in enumerate(folders.items()):
        lines = rest[i].splitlines()
        assert lines[0] == str(i), lines
        out[case] = (runs[i]["rc"], runs[i]["err"].strip().splitlines(),
                     [l.replace(str(m), "$M") for l in lines[1:]], m)
    return out


@needs_ns
def test_mount_point_as_output_folder(namespace_runs):
    """-o on a mount point (staging beside it would cross devices)."""
    rc, err, files, _ = namespace_runs["mount point"]
    assert rc == 0, err
    assert "$M/old_mechanism.csv" in files and f"$M/{MANIFEST_NAME}" in files
    assert not [f for f in files if STAGE_PREFIX in f]


@needs_ns
def test_full_disk(namespace_runs):
    rc, err, files, m = namespace_runs["full disk"]
    assert rc == 2
    assert err == ["crankdyn synth: error: cannot write the report into $M/out: No space "
                   "left on device".replace("$M", str(m))]
    assert files == []                      # the folder it created is gone again


@needs_ns
def test_read_only_file_system(namespace_runs):
    rc, err, files, m = namespace_runs["read-only"]
    assert rc == 2
    assert len(err) == 1 and err[0].startswith("crankdyn synth: error: ") \
        and "Read-only file system" in err[0] and str(m / "out" / "sub") in err[0]
    assert files == ["$M/out", "$M/out/forces.csv"]


@needs_ns
def test_writable_folder_under_read_only_parent(namespace_runs):
    rc, err, files, _ = namespace_runs["read-only parent"]
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
