"""Locate files shipped with crankdyn (Excel templates, bundled examples).

The top-level folders ``templates/`` and ``examples/`` are installed as the packages
``crankdyn.templates`` and ``crankdyn.examples`` (see ``pyproject.toml``), so the same
lookup works from a plain wheel install and from an editable install.
"""
from __future__ import annotations

from importlib import resources
from pathlib import Path

__all__ = ["template_path", "example_path", "list_examples"]


def _resource(package: str, name: str) -> Path:
    ref = resources.files(package) / name
    if not ref.is_file():
        available = sorted(p.name for p in resources.files(package).iterdir()
                           if p.is_file() and not p.name.startswith("__"))
        raise FileNotFoundError(f"{package}: no file {name!r}; shipped: {', '.join(available)}")
    # Both install modes put real files on disk; as_file keeps zip installs working too.
    with resources.as_file(ref) as path:
        return Path(path)


def template_path(name: str) -> Path:
    """Path of an Excel template shipped in ``templates/``."""
    return _resource("crankdyn.templates", name)


def example_path(name: str) -> Path:
    """Path of a bundled example spec or data file in ``examples/``."""
    return _resource("crankdyn.examples", name)


def list_examples(suffix: str = ".toml") -> list[str]:
    """Names of the bundled example files with the given suffix."""
    return sorted(p.name for p in resources.files("crankdyn.examples").iterdir()
                  if p.name.endswith(suffix))
