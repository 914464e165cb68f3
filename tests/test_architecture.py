"""The one-way flow of the packages: crankbase -> linkage -> engine (and the other
calculation packages) -> reports and plots -> the crankdyn command line.

Importing a calculation package must not import the command line, and must not import
matplotlib or openpyxl until a plot or a workbook is asked for (scikit-rf's rule).
"""
from __future__ import annotations

import ast
import json
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
#: Library packages: none of their modules may import the CLI package ``crankdyn``.
LIBRARIES = [p.name for p in ROOT.iterdir()
             if p.is_dir() and (p / "__init__.py").exists()
             and p.name not in {"crankdyn", "tests", "templates", "examples", "benchmarks"}]
#: What each layer may import of the project (the flow is one way).
ALLOWED = {"crankbase": {"crankbase"}, "linkage": {"crankbase", "linkage"}}


def _project_imports(path: pathlib.Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(a.name.split(".")[0] for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    return names


def test_libraries_found():
    assert {"crankbase", "linkage", "engine"} <= set(LIBRARIES)


@pytest.mark.parametrize("package", LIBRARIES)
def test_no_library_module_imports_the_cli(package):
    for path in sorted((ROOT / package).rglob("*.py")):
        imported = _project_imports(path)
        assert "crankdyn" not in imported, f"{path.relative_to(ROOT)} imports the CLI package"
        if package in ALLOWED:
            project = imported & (set(LIBRARIES) | {"crankdyn"})
            assert project <= ALLOWED[package], (
                f"{path.relative_to(ROOT)} imports {sorted(project - ALLOWED[package])}, "
                f"above its layer")


def _modules_after(code: str) -> list[str]:
    out = subprocess.run([sys.executable, "-c", code + "\nimport sys, json\n"
                          "print(json.dumps(sorted(sys.modules)))"],
                         capture_output=True, text=True, check=True, cwd=ROOT)
    return json.loads(out.stdout.splitlines()[-1])


#: Imported only where a function needs them (plots, workbooks, the flywheel's and the
#: torsion's solvers, DXF drawings): importing a library or running a force table or a
#: linkage analysis loads none of them.
HEAVY = {"matplotlib", "openpyxl", "scipy", "ezdxf"}


@pytest.mark.parametrize("package", LIBRARIES)
def test_import_loads_no_cli_and_nothing_heavy(package):
    mods = _modules_after(f"import {package}")
    assert not [m for m in mods if m == "crankdyn" or m.startswith("crankdyn.")]
    assert not [m for m in mods if m.split(".")[0] in HEAVY]


def test_a_computation_loads_nothing_heavy():
    mods = _modules_after(
        "import engine, linkage\n"
        "from crankbase.resources import example_path\n"
        "s = engine.load_spec(example_path('petrol_vaz2106.toml'))\n"
        "engine.force_table(s)\n"
        "linkage.analyze(linkage.load_spec(example_path('ratchet.toml')))\n")
    assert not [m for m in mods if m.split(".")[0] in HEAVY]
    assert not [m for m in mods if m == "crankdyn" or m.startswith("crankdyn.")]


def test_the_engine_loads_only_the_group_routines_of_linkage():
    """The engine uses linkage's group routines (:mod:`linkage.groups`) only; the package
    imports its analysis, chain and spec reader when one of their names is first asked
    (PEP 562), so an engine run does not pay for them.  Those names still work: as
    attributes, by ``from linkage import …``, by ``import *`` and as submodules."""
    mods = _modules_after("import engine")
    assert sorted(m for m in mods if m.split(".")[0] == "linkage") == [
        "linkage", "linkage.groups"]
    mods = _modules_after(
        "import linkage\n"
        "from linkage import *\n"
        "from linkage import analyze, load_spec\n"
        "assert linkage.analyze is analyze and linkage.chain.solve\n"
        "assert set(linkage.__all__) <= set(dir(linkage))\n"
        "assert all(getattr(linkage, n) is globals()[n] for n in linkage.__all__)\n"
        "try:\n    linkage.no_such_name\nexcept AttributeError:\n    pass\n"
        "else:\n    raise SystemExit('no AttributeError')\n")
    assert {"linkage.analysis", "linkage.spec", "linkage.chain"} <= set(mods)


@pytest.mark.parametrize("package", LIBRARIES + ["crankdyn"])
def test_no_module_imports_babel(package):
    """Babel is a test dependency only (pyproject's ``test`` extra, and the developers'
    catalogue compiler, the script ``crankbase/locale/compile_catalogues.py``, which no
    module imports): the text layer reads its compiled catalogues with the standard
    library (crankbase.texts.read_mo, gettext)."""
    compiler = ROOT / "crankbase" / "locale" / "compile_catalogues.py"
    for path in sorted((ROOT / package).rglob("*.py")):
        if path == compiler:
            continue
        assert "babel" not in _project_imports(path), f"{path.relative_to(ROOT)} imports babel"


def test_cli_catches_only_the_project_errors(monkeypatch, capsys):
    """A bug (any exception that is not a CrankdynError) shows as a bug, with its traceback;
    the project's own errors are one line each and exit 2."""
    from crankbase.errors import CrankdynError, SpecError
    from crankdyn import cli
    import crankdyn.cmd_engine as cmd

    def boom(args):
        raise ValueError("a bug inside numpy")
    monkeypatch.setattr(cmd, "run", boom)
    with pytest.raises(ValueError, match="a bug inside numpy"):
        cli.main(["engine", "--example", "-o", "unused"])

    def bad(args):
        raise SpecError(["a: first", "b: second"])
    monkeypatch.setattr(cmd, "run", bad)
    assert cli.main(["engine", "--example", "-o", "unused"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err == ["crankdyn engine: ошибка: a: first",         # a Russian run, the default
                   "crankdyn engine: ошибка: b: second"]
    assert issubclass(CrankdynError, ValueError)


def test_every_error_class_is_in_the_hierarchy():
    import crankbase.errors as errors
    import engine

    classes = [getattr(errors, n) for n in errors.__all__ if isinstance(getattr(errors, n), type)]
    classes.append(engine.EngineSpecError)
    for cls in classes:
        if issubclass(cls, Exception):
            assert issubclass(cls, errors.CrankdynError), cls


def _private_uses(path: pathlib.Path) -> list[str]:
    """Every private name (``_x``, not a dunder) of another project module that ``path``
    uses: ``from X import _x`` (absolute or relative) and ``M._x`` / ``pkg.M._x`` where
    ``M`` was bound by an import of a project module."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    project = set(LIBRARIES) | {"crankdyn"}

    def private(name):
        return name.startswith("_") and not name.startswith("__")

    out, modules = [], set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            ours = node.level > 0 or (node.module or "").split(".")[0] in project
            if not ours:
                continue
            for a in node.names:
                if private(a.name):
                    out.append(f"line {node.lineno}: from {'.' * node.level}"
                               f"{node.module or ''} import {a.name}")
                else:                  # may be a module (from linkage import fourbar)
                    modules.add(a.asname or a.name)
        elif isinstance(node, ast.Import):
            for a in node.names:
                if a.name.split(".")[0] in project:
                    modules.add(a.asname or a.name.split(".")[0])
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and private(node.attr):
            base = node.value
            while isinstance(base, ast.Attribute):
                base = base.value
            if isinstance(base, ast.Name) and base.id in modules:
                out.append(f"line {node.lineno}: {ast.unparse(node)}")
    return out


@pytest.mark.parametrize("package", LIBRARIES)
def test_no_private_name_crosses_modules(package):
    """A module's private helpers (``_x``) stay in it: another module that needs one
    calls a public function (engine.forces.crank_pin_resultant, not forces._psi)."""
    bad = {str(p.relative_to(ROOT)): u for p in sorted((ROOT / package).rglob("*.py"))
           if (u := _private_uses(p))}
    assert not bad, bad


def test_the_private_name_scan_finds_both_forms(tmp_path):
    """The scan catches the two forms (a test of the test, so it cannot pass vacuously)."""
    src = tmp_path / "m.py"
    src.write_text("from .forces import _psi, force_table\n"
                   "from linkage import fourbar\nimport engine.rodmodel as rm\n"
                   "import numpy as np\n"
                   "x = fourbar._mu(1) + rm._parts(2) + np._private + force_table.__doc__\n"
                   "def _own():\n    return _own\n", encoding="utf-8")
    found = _private_uses(src)
    assert len(found) == 3, found
    assert any("_psi" in f for f in found) and any("fourbar._mu" in f for f in found)
    assert any("rm._parts" in f for f in found)


# ------------------------------------------------------------------ no import circle
#: Import edges allowed to close a circle (none: the last one, engine.spec ->
#: engine.bearing_spec, went with the split of engine/spec.py); an entry that no longer
#: closes a circle fails the test.
KNOWN_CIRCLE_EDGES: set = set()


def _module_files(root: pathlib.Path, packages) -> dict:
    """{dotted module name: (path, is a package __init__)} of every module of ``packages``."""
    mods = {}
    for pkg in packages:
        for path in sorted((root / pkg).rglob("*.py")):
            parts = list(path.relative_to(root).with_suffix("").parts)
            is_pkg = parts[-1] == "__init__"
            mods[".".join(parts[:-1] if is_pkg else parts)] = (path, is_pkg)
    return mods


def import_graph(root: pathlib.Path, packages) -> dict:
    """{module: set of project modules it imports}, from the AST of every file: top-level
    and function-level imports, absolute and relative; ``from pkg import name`` points at
    the module ``pkg.name`` when there is one, else at ``pkg``."""
    mods = _module_files(root, packages)
    graph = {}
    for name, (path, is_pkg) in mods.items():
        base = name.split(".") if is_pkg else name.split(".")[:-1]
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                found.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                mod = (".".join(base[:len(base) - node.level + 1]
                                + ([node.module] if node.module else []))
                       if node.level else node.module)
                for a in node.names:
                    found.add(f"{mod}.{a.name}" if f"{mod}.{a.name}" in mods else mod)
        edges = set()
        for target in found:
            while target and target not in mods:       # a name inside a module
                target = target.rpartition(".")[0]
            if target and target != name:
                edges.add(target)
        graph[name] = edges
    return graph


def import_circles(graph: dict) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan), sorted."""
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(out)


ALL_PACKAGES = [p.name for p in ROOT.iterdir() if p.is_dir() and (p / "__init__.py").exists()
                and p.name not in {"tests", "benchmarks"}]


def test_no_import_circle_among_the_project_modules():
    graph = import_graph(ROOT, ALL_PACKAGES)
    assert {"engine.study", "crankdyn.cmd_engine", "crankdyn.variants_cli"} <= set(graph)
    for a, b in KNOWN_CIRCLE_EDGES:
        assert b in graph[a], f"{a} no longer imports {b}: drop it from KNOWN_CIRCLE_EDGES"
        graph[a] = graph[a] - {b}
    assert import_circles(graph) == []


def test_the_circle_finder_finds_circles(tmp_path):
    """The graph sees top-level, function-level and relative imports, and a circle of
    any length (the CLI's old variants_cli <-> cmd_engine circle, rebuilt)."""
    pkg = tmp_path / "cli"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "cmd_engine.py").write_text("def run():\n    from .variants_cli import go\n")
    (pkg / "variants_cli.py").write_text("def go():\n    from .cmd_engine import run\n")
    (pkg / "a.py").write_text("import cli.b\n")
    (pkg / "b.py").write_text("from cli import c\n")
    (pkg / "c.py").write_text("from . import a\nimport json\n")
    (pkg / "d.py").write_text("from .a import x\n")             # into the circle only
    graph = import_graph(tmp_path, ["cli"])
    assert graph["cli.d"] == {"cli.a"} and graph["cli.c"] == {"cli.a"}
    assert import_circles(graph) == [["cli.a", "cli.b", "cli.c"],
                                     ["cli.cmd_engine", "cli.variants_cli"]]


def test_the_readme_architecture_table_names_what_exists():
    """Every dotted name in the README's "Architecture" section (``engine.forces.
    crank_pin_forces``, ``crankbase.texts`` …) is a module, or an attribute of one, that
    exists: the one place of each formula, word and spec key stays true as code moves."""
    import importlib
    import re

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    start = text.index("## Architecture: where each thing lives")
    section = text[start:text.index("\n## ", start + 10)]
    packages = tuple(LIBRARIES) + ("crankdyn",)
    names = {n for n in re.findall(r"`([a-z_]+(?:\.[A-Za-z_]+)+)", section)
             if n.split(".")[0] in packages}
    assert len(names) > 20, names
    missing = []
    for name in sorted(names):
        parts = name.split(".")
        for i in range(len(parts), 0, -1):
            try:
                obj = importlib.import_module(".".join(parts[:i]))
            except ModuleNotFoundError:
                continue
            try:
                for attr in parts[i:]:
                    obj = getattr(obj, attr)
            except AttributeError:
                missing.append(name)
            break
        else:
            missing.append(name)
    assert not missing, missing


def test_every_package_folder_ships_in_the_wheel():
    """Every folder with an ``__init__.py`` is listed in pyproject's explicit
    ``packages`` (a sub-package left out installs from a wheel without it: ``import
    engine`` failed after ``pip install .`` when engine/spec/ was new), and so is every
    catalogue of the text layer."""
    import tomllib

    conf = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    listed = set(conf["tool"]["setuptools"]["packages"])
    dirs = conf["tool"]["setuptools"].get("package-dir", {})
    folders = {v: k for k, v in dirs.items()}
    found = set()
    for init in ROOT.rglob("__init__.py"):
        rel = init.parent.relative_to(ROOT)
        top = rel.parts[0]
        if (top in ("tests", "benchmarks", "build", "dist") or top.startswith(".")
                or top.endswith(".egg-info")):        # not sources: pip's build folder …
            continue
        found.add(folders.get(rel.as_posix(), ".".join(rel.parts)))
    assert found <= listed, sorted(found - listed)
    data = conf["tool"]["setuptools"]["package-data"]["crankbase"]
    import fnmatch

    for po in [*(ROOT / "crankbase" / "locale").rglob("*.po"),
               *(ROOT / "crankbase" / "locale").rglob("*.mo")]:
        rel = po.relative_to(ROOT / "crankbase").as_posix()
        assert any(fnmatch.fnmatch(rel, pat) for pat in data), rel
