"""Locate files shipped with crankdyn (Excel templates, bundled examples).

The top-level folders ``templates/`` and ``examples/`` are installed as the packages
``crankbase.templates`` and ``crankbase.examples`` (see ``pyproject.toml``), so the same
lookup works from a plain wheel install and from an editable install.
"""
from __future__ import annotations

from importlib import resources
from pathlib import Path

__all__ = ["template_path", "example_path", "list_examples"]


#: Source-tree folder of each resource package (used when Python runs from a checkout
#: whose own ``crankdyn`` folder shadows the installed one).
_SOURCE_DIRS = {"crankbase.templates": "templates", "crankbase.examples": "examples"}


def _folder(package: str):
    try:
        return resources.files(package)
    except ModuleNotFoundError:
        return Path(__file__).resolve().parent.parent / _SOURCE_DIRS[package]


def _resource(package: str, name: str) -> Path:
    folder = _folder(package)
    ref = folder / name
    if not ref.is_file():
        available = sorted(p.name for p in folder.iterdir()
                           if p.is_file() and not p.name.startswith(("_", ".")))
        raise FileNotFoundError(f"{package}: no file {name!r}; shipped: {', '.join(available)}")
    if isinstance(ref, Path):
        return ref
    # Both install modes put real files on disk; as_file keeps zip installs working too.
    with resources.as_file(ref) as path:
        return Path(path)


def template_path(name: str) -> Path:
    """Path of an Excel template shipped in ``templates/``."""
    return _resource("crankbase.templates", name)


def example_path(name: str) -> Path:
    """Path of a bundled example spec or data file in ``examples/``."""
    return _resource("crankbase.examples", name)


def list_examples(suffix: str = ".toml") -> list[str]:
    """Names of the bundled example files with the given suffix."""
    return sorted(p.name for p in _folder("crankbase.examples").iterdir()
                  if p.name.endswith(suffix))
