"""``crankdyn serve``: the course project in the browser (the ``web`` extra).

    crankdyn serve [--host 127.0.0.1] [--port 8000] [--open] [--workers N]
                   [--draw ahead|on_request] [--lang ru|en|zh]

Starts the web app (:mod:`web`) with uvicorn and prints its address.  ``--lang`` is the
language of this command's own lines (the page has its own language switch).  The web packages
(Starlette, Jinja2, uvicorn, python-multipart) are imported only here, when the command
runs; without them the command says in one line how to install them.
"""
from __future__ import annotations

from .langs import add_lang, cli_texts, command, error_line


def add_parser(subparsers, t=None):
    """Register ``crankdyn serve``; ``t`` the help's words (:func:`crankdyn.langs.cli_texts`,
    Russian when not given)."""
    p, t = command(subparsers, "serve", t)
    p.add_argument("--host", default="127.0.0.1", help=t("cli.serve.opt.host"))
    p.add_argument("--port", type=int, default=8000, help=t("cli.serve.opt.port"))
    p.add_argument("--open", action="store_true", help=t("cli.serve.opt.open"))
    p.add_argument("--workers", type=int, default=2, metavar="N",
                   help=t("cli.serve.opt.workers"))
    p.add_argument("--draw", choices=("ahead", "on_request"), default="ahead",
                   help=t("cli.serve.opt.draw"))
    add_lang(p, t, "serve")
    p.set_defaults(func=run)


def run(args) -> int:
    import sys

    t = cli_texts(getattr(args, "lang", None))
    try:
        import uvicorn

        import web.app  # noqa: F401  (the framework: Starlette, Jinja2, multipart)
    except ImportError as exc:
        print(error_line("serve", t("cli.serve.needs_extra", module=exc.name),
                         getattr(args, "lang", None)), file=sys.stderr)
        return 2
    from web import create_app

    url = f"http://{'127.0.0.1' if args.host in ('0.0.0.0', '::') else args.host}:{args.port}/"
    print("crankdyn serve: " + t("cli.serve.started", url=url), flush=True)
    if args.open:
        import threading
        import webbrowser

        threading.Timer(1.0, webbrowser.open, (url,)).start()
    n = max(1, args.workers)
    uvicorn.run(create_app(workers=n, render_workers=n, draw=args.draw), host=args.host,
                port=args.port, log_level="warning")
    return 0
