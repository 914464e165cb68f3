"""Issue 23, "English error messages in a Russian run": every error the command line
prints is in the run's language.

Two guards: a table of bad inputs run through every subcommand with ``--lang ru`` (no
English word left outside key paths, option names, file names, units and symbols) and
``--lang en`` (no Cyrillic); and a static scan of the library and CLI code for an error
built from a literal message (``Problem("key", "got …")``, ``SpecError(f"…")``,
``OutputError("…")``, ``checker.add(key, "…")``) instead of a key of the ``errors``
catalogue.
"""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from crankbase.texts import texts
from crankdyn.cli import main

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

ENGINE = """\
[engine]
name = "t"
bore_mm = 110.0
stroke_mm = 125.0
{rod}
speed_rpm = 2600.0
crankcase_MPa = 0.1
{engine_extra}

[masses]
reciprocating_kg = 3.08
rod_rotating_kg = 0.9

{pressure}

[table]
step_deg = 30
force_scale_N_per_mm = 500.0
{extra}
"""
INLINE = "[pressure]\nangle_deg = [0, 360, 370]\np_MPa = [0.1, 5.0, 6.0]"
OTTO = ("[pressure.cycle]\nkind = \"otto\"\ncompression_ratio = 8.5\npa_MPa = 0.085\n"
        "pr_MPa = 0.118\nn1 = 1.377\nn2 = 1.251\npz_MPa = 6.1\n")


def engine_spec(tmp, rod="rod_ratio = 0.272", engine_extra="", pressure=INLINE, extra=""):
    path = tmp / "spec.toml"
    path.write_text(ENGINE.format(rod=rod, engine_extra=engine_extra, pressure=pressure,
                                  extra=extra), encoding="utf-8")
    return str(path)


def write(tmp, name, text):
    path = tmp / name
    path.write_text(text, encoding="utf-8")
    return str(path)


LINKAGE = """\
[mechanism]
kind = "crank-rocker"
name = "m"
crank = {crank}
coupler = 0.55
rocker = 0.325
ground = 0.54
omega_rad_s = 17.0

[links.coupler]
mass_kg = 10.0
inertia_kg_m2 = 0.3
{extra}
[analysis]
positions = 12
working_stroke = "ccw"
"""


def linkage_spec(tmp, crank=0.175, extra=""):
    return write(tmp, "mech.toml", LINKAGE.format(crank=crank, extra=extra))


def rotor_spec(tmp, planes="[0, 300]", mass="mr_gmm = 90"):
    return write(tmp, "rotor.toml", f"[rotor]\nname = \"r\"\nplanes_mm = {planes}\n"
                                    f"correction_radius_mm = 50\n\n[[rotor.mass]]\n{mass}\n"
                                    f"angle_deg = 270\nz_mm = 100\n")


def a_file(tmp):
    return write(tmp, "afile", "not a folder\n")


#: (case id, argv builder taking the tmp folder); each must exit with status 2.
CASES = [
    # engine: spec keys (one key's bounds, an unknown key, keys given together)
    ("engine-keys", lambda t: ["engine", engine_spec(
        t, rod="rod_ratio = 0.272\nrod_length_mm = 230.0\nbore = 3",
        engine_extra="offset_mm = -1e9")]),
    ("engine-no-rod", lambda t: ["engine", engine_spec(t, rod="")]),
    ("engine-pressure-inline", lambda t: ["engine", engine_spec(
        t, pressure="[pressure]\nangle_deg = [0, 360, 350]\np_MPa = [0.1, 5.0, -6.0]")]),
    ("engine-pressure-lists", lambda t: ["engine", engine_spec(
        t, pressure="[pressure]\nangle_deg = [0, 360]\np_MPa = [0.1]\np_bar = [1, 2]")]),
    ("engine-no-pressure", lambda t: ["engine", engine_spec(t, pressure="")]),
    ("engine-csv-values", lambda t: [
        "engine", engine_spec(t, pressure="[pressure]\nfile = \"p.csv\""),
        write(t, "p.csv", "angle_deg;p_MPa\n0;0.1\n200;-1\n100;2\n800;3\n") and "--step",
        "10"]),
    ("engine-csv-header", lambda t: [
        "engine", engine_spec(t, pressure="[pressure]\nfile = \"p.csv\""),
        write(t, "p.csv", "angle;pressure\n0;0.1\n360;2\n") and "--step", "10"]),
    ("engine-csv-missing", lambda t: [
        "engine", engine_spec(t, pressure="[pressure]\nfile = \"nothing.csv\"")]),
    ("engine-cycle", lambda t: ["engine", engine_spec(
        t, pressure=OTTO + "lambda_z = 1.5\nrho = 9.0\n")]),
    ("engine-rod", lambda t: ["engine", engine_spec(
        t, extra="[rod]\nmodel = \"rigid\"\ncg_from_big_end_mm = 900.0\n")]),
    ("engine-bearings", lambda t: ["engine", engine_spec(
        t, extra="[bearings]\njournal_positions_mm = [10.0, 50.0]\n"), "--bearings"]),
    ("engine-out-input", lambda t: [
        "engine", engine_spec(t, pressure="[pressure]\nfile = \"t_forces.csv\""),
        write(t, "t_forces.csv", "angle_deg,p_MPa\n0,0.1\n360,5\n") and "-o", str(t)]),
    ("engine-step", lambda t: ["engine", "--example", "--step", "0"]),
    ("engine-jobs", lambda t: ["engine", "--example", "--jobs", "0", "-o", str(t / "o")]),
    ("engine-both", lambda t: ["engine", engine_spec(t), "--example"]),
    ("engine-example", lambda t: ["engine", "--example", "nope"]),
    ("engine-out-file", lambda t: ["engine", "--example", "-o", a_file(t)]),
    ("engine-out-empty", lambda t: ["engine", "--example", "-o", ""]),
    ("engine-no-spec", lambda t: ["engine", str(t / "missing.toml")]),
    ("engine-variants", lambda t: [
        "engine", engine_spec(t), "--variants", write(t, "v.csv", "engine.bore_mm\n100\n"),
        "-o", str(t / "o")]),
    # linkage
    ("linkage-unassemblable", lambda t: ["linkage", linkage_spec(t, crank=0.5)]),
    ("linkage-loads", lambda t: ["linkage", linkage_spec(
        t, extra="[[load]]\nlink = \"rocker\"\nresistance_N = 100.0\n\n"
                 "[[load]]\nlink = \"wheel\"\nmoment_Nm = 5.0\n")]),
    # a resistance's window (issue #20): both forms, from ≥ to (read with the spec), and a
    # window outside the rocker's swing of 68.4° (known once the mechanism is solved)
    ("linkage-window", lambda t: ["linkage", linkage_spec(
        t, extra="[[load]]\nlink = \"rocker\"\nresistance_Nm = 100.0\nspan_deg = 10.0\n"
                 "from_fraction = 0.05\n\n[[load]]\nlink = \"rocker\"\n"
                 "resistance_Nm = 100.0\nfrom_fraction = 0.9\nto_fraction = 0.1\n")]),
    ("linkage-window-outside", lambda t: ["linkage", linkage_spec(
        t, extra="[[load]]\nlink = \"rocker\"\nresistance_Nm = 100.0\nstart_deg = 60.0\n"
                 "span_deg = 10.0\n")]),
    # what needs the working stroke, named in the run's language (it was English words)
    ("linkage-needs-stroke", lambda t: ["linkage", write(t, "mech.toml", LINKAGE.format(
        crank=0.175, extra="[[load]]\nlink = \"rocker\"\nresistance_Nm = 100.0\n"
                          "span_deg = 10.0\n").replace('working_stroke = "ccw"\n', ""))]),
    ("linkage-step", lambda t: ["linkage", linkage_spec(t), "--step", "45"]),
    ("linkage-plans", lambda t: ["linkage", "--example", "press", "--plans", "13",
                                 "-o", str(t / "o")]),
    ("linkage-out-file", lambda t: ["linkage", linkage_spec(t), "-o", a_file(t)]),
    # synth
    ("synth-l1", lambda t: ["synth", "--l1", "-1"]),
    ("synth-region", lambda t: ["synth", "--l2", "5", "--l3", "0.1"]),
    ("synth-mu", lambda t: ["synth", "--l2", "0.7", "--mu-min", "95",
                                "--omega", "3"]),
    ("synth-out-file", lambda t: ["synth", "--l2", "0.7", "--l3", "0.6", "-o", a_file(t)]),
    # dynamics
    ("dynamics-neither", lambda t: ["dynamics", write(t, "d.toml", "[dynamics]\n"
                                                      "driving = \"constant\"\n")]),
    ("dynamics-both", lambda t: ["dynamics", write(
        t, "d.toml", (EXAMPLES / "flywheel_seed.toml").read_text(encoding="utf-8")
        + "delta = 0.05\nflywheel_kgm2 = 1.0\n")]),
    ("dynamics-example", lambda t: ["dynamics", "--example", "nope"]),
    ("dynamics-nothing", lambda t: ["dynamics"]),
    ("dynamics-out-file", lambda t: ["dynamics", "--example", "-o", a_file(t)]),
    ("dynamics-linkage-statics", lambda t: ["dynamics", write(
        t, "d.toml", LINKAGE.format(crank=0.175, extra="").replace(
            "omega_rad_s = 17.0", "omega_rad_s = 0.0").replace(
            'positions = 12\nworking_stroke = "ccw"', "crank_angles_deg = [0, 90]")
        + "\n[dynamics]\ndelta = 0.05\n")]),
    # balance
    ("balance-no-z", lambda t: ["balance", write(
        t, "rotor.toml", "[rotor]\nname = \"r\"\nplanes_mm = [0, 300]\n\n"
                         "[[rotor.mass]]\nmr_gmm = 90\nangle_deg = 270\n")]),
    ("balance-planes", lambda t: ["balance", rotor_spec(t, planes="[0, 0, 300]")]),
    ("balance-mass", lambda t: ["balance", rotor_spec(t, mass="mr_gmm = 90\nm_g = 3\n"
                                                             "r_mm = 30")]),
    ("balance-plane-z", lambda t: ["balance", rotor_spec(t, planes="[100, 100]")]),
    ("balance-example", lambda t: ["balance", "--example", "nope"]),
    # check
    ("check-neither", lambda t: ["check", write(t, "x.toml", "[other]\na = 1\n"),
                                 write(t, "s.csv", "a,b\n1,2\n"), "-o", str(t / "o")]),
    ("check-tolerance", lambda t: ["check", str(EXAMPLES / "petrol_vaz2106.toml"),
                                   write(t, "s.csv", "a,b\n1,2\n"), "--rtol", "2",
                                   "-o", str(t / "o")]),
    ("check-student", lambda t: ["check", str(EXAMPLES / "petrol_vaz2106.toml"),
                                 write(t, "s.csv", "a,b\n1,2\n"), "-o", str(t / "o")]),
]
# the spec and -o of every report command, checked in one place (crankdyn.examples):
# neither SPEC.toml nor --example, both, and -o naming a file
CASES += [(f"{cmd}-{what}", build) for cmd in ("engine", "dynamics", "balance", "torsion")
          for what, build in (
              ("no-spec", lambda t, cmd=cmd: [cmd]),
              ("spec-and-example", lambda t, cmd=cmd: [cmd, a_file(t), "--example"]),
              ("o-file", lambda t, cmd=cmd: [cmd, "--example", "-o", a_file(t)]))]

#: The start of a problem's line on stderr in each language (``cli.error``, argparse's
#: "error:" too): the word in the run's language (issue #19 item 4).
PREFIXES = {"en": r"crankdyn \w+: error: ", "ru": r"crankdyn \w+: ошибка: ",
            "zh": r"crankdyn \w+：错误："}
_PREFIX = re.compile("^(?:" + "|".join(PREFIXES.values()) + ")")

#: Latin words a Russian message may keep, each a name rather than an English word:
#: the program's name, the placeholders of its usage line (SPEC.toml, --example [NAME],
#: HEADER=column), the names of the encoding (UTF-8) and of the spec format (TOML), the
#: program Diesel-RK whose files are read, and the function symbols of formulas (cos φ0,
#: mod 360°).
LATIN_NAMES = {"crankdyn", "SPEC", "NAME", "HEADER", "UTF", "TOML", "Diesel", "cos", "sin",
               "mod"}

def _spec_key_names():
    """Every key name and table of the specs (from the labels of the spec catalogue,
    ``spec.engine.bore_mm.label`` → ``engine``, ``bore_mm``): a message names keys as they
    are written (``delta``, ``kind``, ``model``), in any language."""
    from crankbase.texts import keys

    names = set()
    for key in keys("en"):
        parts = key.split(".")
        if parts[0] == "spec" and parts[-1] == "label":
            names.update(parts[1:-1])
    return names


#: Cyrillic notation an English message keeps on purpose (the course books' symbols:
#: the rod length Lш, the rod's rotating mass mш.к, the ККМ family of crank-rockers).
CYRILLIC_SYMBOLS = ("Lш", "mш.к", "ККМ")


def english_words(line: str) -> list[str]:
    """The English words of a message line outside its names: quoted values as given,
    [tables], paths and file names, --options, key paths (``engine.bore_mm``),
    identifiers (``rod_ratio``), symbols with an index (``λ1max``, ``M0``), lists of
    identifiers after a colon (valid values, columns, examples)."""
    s = _PREFIX.sub("", line)
    s = re.sub(r"^[\w.\[\]\-]+(?:, ?[\w.\[\]\-]+)*: ", " ", s)     # the key path(s)
    s = re.sub(r"'[^']*'|\"[^\"]*\"", " ", s)
    s = re.sub(r"\b\w+ = ", " ", s)                                  # key = value
    s = re.sub(r"\[\[?[\w.\-]+\]\]?", " ", s)
    s = re.sub(r"\S*[/\\]\S*", " ", s)
    s = re.sub(r"(?<![\w])--?[A-Za-z][\w-]*", " ", s)
    s = re.sub(r"[\w\-]+\.(toml|csv|xlsx|ind|png|txt|json)\b", " ", s)
    s = re.sub(r"[\w\[\]]+(?:\.[\w\[\]]+)+", " ", s)
    s = re.sub(r"\w*_\w*", " ", s)
    s = re.sub(r"\w*\d\w*", " ", s)
    s = re.sub(r"[A-Za-z][\w\-]*(?:, [A-Za-z][\w\-]*)+", " ", s)  # lists of names
    names = LATIN_NAMES | _spec_key_names()
    return [w for w in re.findall(r"(?<![\w-])[A-Za-z]{3,}(?![\w-])", s)
            if w not in names]


def cyrillic(line: str) -> list[str]:
    s = re.sub(r"'[^']*'|\"[^\"]*\"", " ", line)
    for sym in CYRILLIC_SYMBOLS:
        s = s.replace(sym, " ")
    return re.findall(r"[А-Яа-яЁё]+", s)


def test_the_filters_catch_english_and_cyrillic():
    """The filters themselves: an English message is caught, names are not."""
    assert english_words("crankdyn engine: error: engine.rod_ratio: give either rod_ratio "
                         "or rod_length_mm, not both") == ["give", "either", "not", "both"]
    assert english_words("crankdyn engine: error: engine.bore_mm: получено -1; должно быть "
                         "> 0; -o: /tmp/a b/out.csv, --step, [pressure.cycle], λ1max, "
                         "'p MPa'; допустимо: crank, coupler, rocker") == []
    assert english_words("crankdyn linkage: error: the crank cannot turn") == [
        "the", "cannot", "turn"]
    assert cyrillic("crankdyn engine: error: got 3; must be < Lш − R = 2 mm") == []
    assert cyrillic("crankdyn engine: error: получено 3") == ["получено"]


def _run(argv, capsys):
    capsys.readouterr()
    rc = main(argv)
    return rc, capsys.readouterr().err.splitlines()


@pytest.mark.parametrize("case, build", CASES, ids=[c for c, _ in CASES])
def test_errors_in_the_run_language(case, build, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    lines = {}
    for lang in ("ru", "en", "zh"):
        folder = tmp_path / lang
        folder.mkdir()
        argv = build(folder)
        cmd, rest = argv[0], argv[1:]
        if "-o" not in rest:
            rest = [*rest, "-o", str(folder / "o")]
        rc, err = _run([cmd, "--lang", lang, *rest], capsys)
        assert rc == 2, (lang, err)
        assert err and all(re.match(PREFIXES[lang], ln) for ln in err), (lang, err)
        lines[lang] = err
        # bad input writes nothing: no output folder, not even an empty one
        assert not (folder / "o").exists(), (lang, sorted((folder / "o").rglob("*")))
    russian = {ln: cyrillic(ln) for ln in lines["en"] if cyrillic(ln)}
    assert not russian, russian
    # Russian, and Chinese (issue #19): no English word, the same problems as in English,
    # and translated (a line not given in the language, or a text equal to the English
    # one, is caught here); Chinese has no Cyrillic either
    for lang, script in (("ru", r"[А-Яа-яЁё]"), ("zh", r"[\u4e00-\u9fff]")):
        english = {ln: english_words(ln) for ln in lines[lang] if english_words(ln)}
        assert not english, (lang, english)
        assert len(lines[lang]) == len(lines["en"]), lines
        assert any(re.search(script, ln) for ln in lines[lang]), lines[lang]
    russian = {ln: cyrillic(ln) for ln in lines["zh"] if cyrillic(ln)}
    assert not russian, russian


# --------------------------------------------------------------------------- static
CODE = ("crankbase", "engine", "linkage", "dynamics", "plans", "crankdyn")

#: calls whose message argument must be a keyed Text, not words: the error classes of the
#: one hierarchy (found from crankbase.errors.CrankdynError) and Problem; and a checker's
#: ``add(key, message)``.
def _error_names():
    import importlib
    import pkgutil
    import warnings

    from crankbase.errors import CrankdynError

    for pkg in CODE[:-1]:
        mod = importlib.import_module(pkg)
        for info in pkgutil.walk_packages(mod.__path__, pkg + "."):
            with warnings.catch_warnings():     # the old engine paths forward with a warning
                warnings.simplefilter("ignore", DeprecationWarning)
                importlib.import_module(info.name)
    names, todo = set(), [CrankdynError]
    while todo:
        cls = todo.pop()
        names.add(cls.__name__)
        todo += cls.__subclasses__()
    return names | {"Problem"}


def _is_words(node) -> bool:
    """A message written as words: a string literal (f-string, sum or choice of them)."""
    if isinstance(node, ast.Constant):
        return isinstance(node.value, str) and bool(re.search(r"[A-Za-z]{3,}", node.value))
    if isinstance(node, ast.JoinedStr):
        return any(_is_words(v) for v in node.values if isinstance(v, ast.Constant))
    if isinstance(node, ast.BinOp):
        return _is_words(node.left) or _is_words(node.right)
    if isinstance(node, ast.IfExp):
        return _is_words(node.body) or _is_words(node.orelse)
    if isinstance(node, (ast.List, ast.Tuple)):
        return any(_is_words(e) for e in node.elts)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr in ("format", "join"):
        return _is_words(node.func.value)
    return False


def _message_args(node, errors):
    name = node.func.id if isinstance(node.func, ast.Name) else \
        node.func.attr if isinstance(node.func, ast.Attribute) else None
    kw = [k.value for k in node.keywords if k.arg in ("message", "reason", "problems")]
    if name == "Problem":
        return node.args[1:2] + kw
    if name in errors:
        return node.args[:1] + kw
    if name == "add" and isinstance(node.func, ast.Attribute) and len(node.args) == 2 \
            and isinstance(node.func.value, ast.Name) \
            and node.func.value.id in ("c", "ck", "checker", "reader", "self"):
        return node.args[1:2]
    return []


def literal_messages():
    errors = _error_names()
    found = []
    for pkg in CODE:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"))
            for node in ast.walk(tree):
                if isinstance(node, ast.Call) and any(
                        _is_words(a) for a in _message_args(node, errors)):
                    found.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    return found


def test_no_error_is_built_from_literal_words():
    """Every error message is a key of the errors catalogue (``Text("errors.…")``,
    ``Problem.keyed``, ``checker.addk``), so that it can be given in the run's language."""
    assert literal_messages() == []


def test_the_scan_sees_a_literal_message(tmp_path):
    """The scan itself: each way of writing an error in words is found."""
    errors = _error_names()
    src = ('raise SpecError(Problem("k", f"got {x}; must be > 0"))\n'
           'raise OutputError("cannot write")\n'
           'c.add("k", "give either a or b")\n'
           'raise AssemblyError("crank " + s, [])\n'
           'raise SpecError(Problem("k", Text("errors.x", {"v": "ok"})))\n')
    hits = [node.lineno for node in ast.walk(ast.parse(src)) if isinstance(node, ast.Call)
            and any(_is_words(a) for a in _message_args(node, errors))]
    assert sorted(hits) == [1, 2, 3, 4]


def test_every_error_class_renders_in_the_run_language():
    """OutputError, AssemblyError (any CrankdynError) keyed: English str, Russian lines."""
    from crankbase.errors import AssemblyError, OutputError, Problem, SpecError, Text

    out = OutputError(Text("errors.output.output_folder_exists", {"directory": "x"}))
    assert str(out) == "output folder x: exists and is not a folder"
    assert out.lines("ru") == ["папка вывода x: существует и не является папкой"]
    asm = AssemblyError.keyed("errors.linkage.mechanisms.crank_cannot_turn_2",
                              [10.0, 20.0], items="10°…20°")
    assert asm.reason == str(asm) and asm.reason.startswith("the crank cannot turn fully")
    assert asm.crank_angles_deg == [10.0, 20.0]
    assert asm.lines("ru")[0].startswith("кривошип не проворачивается полностью")
    # a problem's key may hold words too (a variants row): rendered in the language
    spec = SpecError([Problem(Text("errors.engine.variants.row", {"row": 3}),
                              Text("errors.engine.variants.column_empty", {"value": "v"}))])
    assert str(spec) == "row 3: column 'v' is empty"
    assert spec.lines("ru") == ["строка 3: столбец 'v' пуст"]


# --------------------------------------------------------------------------- argparse
ARGPARSE_CASES = [
    ("bad choice", ["engine", "--example", "petrol", "--form", "nosuch", "-o", "{o}"],
     "--form"),
    ("unknown option", ["linkage", "--example", "ratchet", "--bogus", "-o", "{o}"], "--bogus"),
    ("no output", ["dynamics", "--example", "flywheel"], "-o/--output"),
    ("not a number", ["engine", "--example", "petrol", "--step", "abc", "-o", "{o}"],
     "'abc'"),
    ("no value", ["engine", "--example", "petrol", "-o"], "-o/--output"),
]


@pytest.mark.parametrize("argv, names", [(a, n) for _, a, n in ARGPARSE_CASES],
                         ids=[c for c, _, _ in ARGPARSE_CASES])
def test_argparse_complaints_in_the_run_language(argv, names, tmp_path, capsys):
    """argparse's own messages (crankdyn/cli.py ARGPARSE_TEXTS) speak the language asked
    with --lang, Russian by default: one line, exit 2, nothing written, the option named."""
    argv = [a.format(o=tmp_path / "o") for a in argv]
    lines = {}
    for lang in ("ru", "en", "zh", None):
        capsys.readouterr()
        with pytest.raises(SystemExit) as exit_:
            main(argv if lang is None else [argv[0], "--lang", lang, *argv[1:]])
        assert exit_.value.code == 2
        usage = tuple(texts(code)("cli.argparse.usage").strip() for code in ("en", "ru", "zh"))
        err = [ln for ln in capsys.readouterr().err.splitlines()
               if not ln.startswith((*usage, " "))]
        assert len(err) == 1 and re.match(PREFIXES[lang or "ru"], err[0]) \
            and names in err[0], err
        lines[lang] = err[0]
    assert not (tmp_path / "o").exists()
    assert lines[None] == lines["ru"]
    assert re.search(r"[А-Яа-яЁё]", lines["ru"]) and not english_words(lines["ru"]), lines
    assert not cyrillic(lines["en"]), lines
    assert re.search(r"[\u4e00-\u9fff]", lines["zh"]) and not cyrillic(lines["zh"]), lines
