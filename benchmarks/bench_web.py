"""Load benchmark of ``crankdyn serve`` on this machine (loopback only).

    python benchmarks/bench_web.py [--sessions 20] [--workers 2]

Starts the web app with uvicorn in a child process on a free port of 127.0.0.1, then:

1. one session, the petrol example, three times: the time from submitting the form to
   the results page (Table 2 and the summary on screen) and to the last of its 13 figures
   and the workbook;
2. ``--sessions`` sessions at once (threads, each its own cookie jar), each running the
   petrol example at its own speed (3000 + 50·i rpm, so that mixed-up sessions would show):
   each session's ``forces.csv`` must be byte for byte the library's (the CLI's) for its
   speed; the time per job (page, and all files) and the wall time of the whole load.

No assertion on time: the figures go into the README.  Every request goes to 127.0.0.1;
the loops are bounded (one job per session) and the server is stopped at the end.
"""
from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

try:                                   # the test extra's client; httpx has the same API
    import httpx2 as httpx
except ImportError:                    # pragma: no cover
    import httpx

ROOT = Path(__file__).resolve().parent.parent


def free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(port: int, workers: int):
    code = ("import uvicorn, web; uvicorn.run(web.create_app(workers=%d, render_workers=%d), "
            "host='127.0.0.1', port=%d, log_level='warning')" % (workers, workers, port))
    proc = subprocess.Popen([sys.executable, "-c", code], cwd=ROOT)
    url = f"http://127.0.0.1:{port}"
    for _ in range(300):
        try:
            if httpx.get(url + "/engine", timeout=1).status_code == 200:
                return proc, url
        except httpx.HTTPError:
            time.sleep(0.1)
    proc.kill()
    raise SystemExit("the server did not start")


def form(speed: float) -> dict:
    import tomllib

    from crankbase.resources import example_path
    from web.engine_form import values_from_spec

    spec = tomllib.loads(example_path("petrol_vaz2106.toml").read_text(encoding="utf-8"))
    spec["engine"]["speed_rpm"] = speed
    values, source = values_from_spec(spec)
    return {**values, "pressure_source": source}, spec


def expected_forces(spec: dict) -> bytes:
    """``forces.csv`` as the CLI writes it for ``spec`` (the library's writer)."""
    import engine
    from crankbase.output import write_csv

    report = engine.run_study(engine.load(spec))
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "f.csv"
        write_csv(report.tables["forces.csv"], p)
        return p.read_bytes()


def one_job(url: str, speed: float) -> dict:
    import re

    data, spec = form(speed)
    with httpx.Client(base_url=url, timeout=600, follow_redirects=True) as c:
        c.get("/engine?lang=en")
        t0 = time.perf_counter()
        r = c.post("/engine/run", data=data)
        t_page = time.perf_counter() - t0
        assert r.status_code == 200 and 'id="table2"' in r.text, r.text[:500]
        urls = re.findall(r'(?:href|src)="(/engine/run/\d+/[^"]+)"', r.text)
        files = {}
        for u in urls:
            if u.endswith((".png", ".xlsx", "_forces.csv")):
                g = c.get(u)
                assert g.status_code == 200, u
                files[u.rsplit("/", 1)[1]] = g.content
        t_all = time.perf_counter() - t0
    forces = next(v for k, v in files.items() if k.endswith("_forces.csv"))
    return dict(speed=speed, page=t_page, all=t_all, forces=forces, spec=spec,
                figures=sum(k.endswith(".png") for k in files))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sessions", type=int, default=20)
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args(argv)
    proc, url = start_server(free_port(), args.workers)
    try:
        one_job(url, 5400.0)                       # warm the server (first imports)
        single = [one_job(url, 5400.0) for _ in range(3)]
        print(f"one session, petrol example: results page "
              f"{statistics.median(j['page'] for j in single):.2f} s after submit "
              f"(median of 3), all {single[0]['figures']} figures and the workbook "
              f"{statistics.median(j['all'] for j in single):.2f} s")
        jobs, errors = [None] * args.sessions, []

        def worker(i):
            try:
                jobs[i] = one_job(url, 3000.0 + 50 * i)
            except Exception as exc:               # reported below
                errors.append(f"session {i}: {exc!r}")
        threads = [threading.Thread(target=worker, args=(i,)) for i in range(args.sessions)]
        t0 = time.perf_counter()
        for th in threads:
            th.start()
        for th in threads:
            th.join()
        wall = time.perf_counter() - t0
        if errors:
            raise SystemExit("\n".join(errors))
        same = sum(j["forces"] == expected_forces(j["spec"]) for j in jobs)
        pages = sorted(j["page"] for j in jobs)
        alls = sorted(j["all"] for j in jobs)
        print(f"{args.sessions} sessions at once ({args.workers} compute threads, "
              f"{args.workers} drawing processes): wall {wall:.1f} s; results page "
              f"min/median/max "
              f"{pages[0]:.2f}/{statistics.median(pages):.2f}/{pages[-1]:.2f} s; all files "
              f"{alls[0]:.1f}/{statistics.median(alls):.1f}/{alls[-1]:.1f} s; "
              f"{wall / args.sessions:.2f} s per job; forces.csv equal to the CLI's: "
              f"{same}/{args.sessions}")
        if same != args.sessions:
            raise SystemExit("some session's numbers differ from the CLI's")
    finally:
        proc.terminate()
        proc.wait(30)


if __name__ == "__main__":
    main()
