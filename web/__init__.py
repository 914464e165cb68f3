"""``crankdyn serve``: the course project in the browser.

A small server-rendered web app (Starlette, Jinja2 templates, uvicorn; the ``web``
extra): the engine page starts from a bundled example, an uploaded spec or a form
generated from the spec schema, computes through the library (:func:`engine.load`,
:func:`engine.run_study`, :func:`engine.write_report`) and shows Table 2, the summary and
every diagram, with the workbook, the CSVs, the zip of the report and the spec TOML to
download.  Every browser session works in its own temporary folder; uploads are read as
data and size-limited; the computations run in a bounded pool of threads.

``import web`` imports nothing of the framework: :func:`create_app` does.
"""
from __future__ import annotations

__all__ = ["create_app"]


def create_app(**options):
    """The ASGI app of ``crankdyn serve`` (:func:`web.app.build_app`'s options)."""
    from .app import build_app

    return build_app(**options)
