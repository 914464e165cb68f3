"""``crankdyn serve``: the course project in the browser (the ``web`` extra).

    crankdyn serve [--host 127.0.0.1] [--port 8000] [--open]

Starts the web app (:mod:`web`) with uvicorn and prints its address.  The web packages
(Starlette, Jinja2, uvicorn, python-multipart) are imported only here, when the command
runs; without them the command says in one line how to install them.
"""
from __future__ import annotations


def add_parser(subparsers):
    p = subparsers.add_parser(
        "serve", help="the course project in the browser: a local web app",
        description="Start the crankdyn web app: the engine page (Table 2, diagrams, "
                    "workbook) from a bundled example, an uploaded spec or a form. Every "
                    "browser session works in its own temporary folder, removed after an "
                    "hour idle and at shutdown. Needs the web extra: pip install "
                    "\"crankdyn[web]\".")
    p.add_argument("--host", default="127.0.0.1",
                   help="address to listen on (default 127.0.0.1, this computer only; "
                        "0.0.0.0 to serve a class on the local network)")
    p.add_argument("--port", type=int, default=8000, help="port (default 8000)")
    p.add_argument("--open", action="store_true", help="open the page in the browser")
    p.add_argument("--workers", type=int, default=2, metavar="N",
                   help="computations at once (threads) and processes drawing the "
                        "reports (default 2)")
    p.set_defaults(func=run)


def run(args) -> int:
    import sys

    try:
        import uvicorn

        import web.app  # noqa: F401  (the framework: Starlette, Jinja2, multipart)
    except ImportError as exc:
        print(f"crankdyn serve: error: the web app needs the web extra ({exc.name} is "
              "missing): pip install \"crankdyn[web]\"", file=sys.stderr)
        return 2
    from web import create_app

    url = f"http://{'127.0.0.1' if args.host in ('0.0.0.0', '::') else args.host}:{args.port}/"
    print(f"crankdyn serve: {url}  (Ctrl+C stops)", flush=True)
    if args.open:
        import threading
        import webbrowser

        threading.Timer(1.0, webbrowser.open, (url,)).start()
    n = max(1, args.workers)
    uvicorn.run(create_app(workers=n, render_workers=n), host=args.host, port=args.port,
                log_level="warning")
    return 0
