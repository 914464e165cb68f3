"""Test-suite configuration.

Under CI (the environment variable ``CI`` set, as ``.ci/run`` runs) hypothesis draws the
same examples on every run (``derandomize``), so a submission's result does not depend on
chance; a developer's local run keeps drawing new random examples, which is how new
counter-examples are found (and then written into the tests).

Reports rendered once per session (:func:`cli_report`): the end-to-end runs of the CLI
that several test files only read (an engine report with its 13 plots costs about 3 s of
CPU, most of it rendering PNG and SVG) are written once and shared."""
import contextlib
import io
import os
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")


@dataclass(frozen=True)
class Report:
    """One run of ``crankdyn ARGV -o folder``: the folder, exit status and terminal text."""
    folder: Path
    rc: int
    out: str
    err: str


@pytest.fixture(scope="session")
def cli_report(tmp_path_factory):
    """``cli_report(*argv)``: the :class:`Report` of ``crankdyn *argv -o <folder>``, run
    once per session for each distinct ``argv`` and shared by every test that asks for it.
    Shared means read-only: a test that changes a report's files must run its own (at the
    end of the session every shared report is checked against its manifest, so a test
    that altered one fails there)."""
    from crankdyn.cli import main

    cache = {}

    def run(*argv):
        key = tuple(str(a) for a in argv)
        if key not in cache:
            folder = tmp_path_factory.mktemp("_".join(k.lstrip("-") for k in key[:3]))
            o, e = io.StringIO(), io.StringIO()
            with contextlib.redirect_stdout(o), contextlib.redirect_stderr(e):
                rc = main([*key, "-o", str(folder)])
            cache[key] = Report(folder, rc, o.getvalue(), e.getvalue())
        return cache[key]

    yield run
    from crankbase.output import verify_report

    for key, rep in cache.items():
        if rep.rc == 0:
            verify_report(rep.folder)       # no test altered a shared report
