"""Fuzz (issue 15): mutated specs through the Python API and mutated TOML/CSV through the
CLI.  Only the project's typed errors may escape the API (numpy warnings are errors under
the suite's filterwarnings); every accepted spec gives finite tables; the CLI exits 0 or 2,
never lets an exception out (which would print a traceback), and on exit 2 writes nothing.
Bounded for CI: a few hundred API examples and a few dozen CLI runs (~30 s)."""
from __future__ import annotations

import re
import shutil
import tomllib
import warnings

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import engine
import linkage
from crankbase.errors import CrankdynError
from crankbase.resources import example_path
from crankdyn.cli import main
from linkage.analysis import SingularPositionWarning
from rendering import save_through_savefig


def _load(name):
    with open(example_path(name), "rb") as f:
        return tomllib.load(f)


OTTO = dict(kind="otto", compression_ratio=8.5, pa_MPa=0.085, pr_MPa=0.118, n1=1.377,
            n2=1.251, pz_MPa=6.1)
ENGINE_BASES = [
    {"engine": dict(name="t", bore_mm=110.0, stroke_mm=125.0, rod_ratio=0.272,
                    speed_rpm=2600.0, crankcase_MPa=0.1, acceleration="exact"),
     "masses": dict(piston_group_kg=2.35, rod_kg=3.2),
     "pressure": dict(angle_deg=[0, 360, 370, 500], p_bar=[1.0, 50.0, 60.0, 3.0]),
     "table": dict(step_deg=30, extra_angles_deg=[372], force_scale_N_per_mm=500.0)},
    _load("petrol_vaz2106.toml"),
    {"engine": dict(name="d", bore_mm=110.0, stroke_mm=125.0, rod_length_mm=230.0,
                    speed_rpm=2200.0),
     "masses": dict(piston_group_kg_m2=250.0, rod_kg_m2=330.0),
     "pressure": {"cycle": dict(kind="diesel", compression_ratio=16.0, pa_MPa=0.088,
                                pr_MPa=0.115, n1=1.37, n2=1.25, lambda_z=1.6, rho=1.35)},
     "table": dict(force_scale_N_per_mm=250.0)},
]
_STATICS = _load("press.toml")
_STATICS["mechanism"]["omega_rad_s"] = 0.0
del _STATICS["load"]
_STATICS["analysis"] = {"crank_angles_deg": [0.0, 45.0, 90.0, 200.0]}
LINKAGE_BASES = [_load("ratchet.toml"), _load("press.toml"), _STATICS]

#: Replacement values: wrong types, non-finite, absurd magnitudes, huge integers.
ODD = st.one_of(
    st.none(), st.booleans(), st.text(max_size=4),
    st.integers(-10**6, 10**6), st.integers(10**15, 10**400),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-320, 1e-300, 1e-15, 1e-12, 1e12, 1e13, 1e154, 1e300,
                     -1e300, 5e-324]),
    st.lists(st.floats(-1e3, 1e3), max_size=3),
    st.dictionaries(st.sampled_from(["a", "x", "kind"]), st.integers(0, 3), max_size=2),
    st.just(1j))


def _leaves(node, path=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield path + (k,), v
            yield from _leaves(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield path + (i,), v
            yield from _leaves(v, path + (i,))


def _set(d, path, value, delete=False):
    node = d
    for k in path[:-1]:
        node = node[k]
    if delete:
        del node[path[-1]]
    else:
        node[path[-1]] = value


def _copy(node):
    """A copy of a TOML tree (dicts and lists copied, their scalars immutable): what
    ``copy.deepcopy`` gives, at a fraction of its cost per example."""
    if isinstance(node, dict):
        return {k: _copy(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_copy(v) for v in node]
    return node


@st.composite
def mutated(draw, bases):
    d = _copy(draw(st.sampled_from(bases)))
    for _ in range(draw(st.integers(1, 3))):
        paths = [p for p, _ in _leaves(d)]
        path = draw(st.sampled_from(paths))
        node = d
        for k in path:
            node = node[k]
        op = draw(st.sampled_from(["odd", "scale", "scale", "delete", "unknown"]))
        if op == "scale" and isinstance(node, (int, float)) and not isinstance(node, bool):
            k = draw(st.integers(-330, 330))
            try:
                _set(d, path, node * 10.0 ** k)
            except OverflowError:           # beyond the float range: a huge integer
                _set(d, path, (int(node) or 1) * 10 ** abs(k))
        elif op == "delete" and isinstance(path[-1], str):
            _set(d, path, None, delete=True)
        elif op == "unknown" and isinstance(node, dict):
            node["zz_unknown"] = 1
        else:
            _set(d, path, draw(ODD))
    return d


def _finite(df):
    return bool(np.isfinite(df.select_dtypes("float").to_numpy()).all())


API = settings(max_examples=250, deadline=None, derandomize=True,
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@API
@given(mutated(ENGINE_BASES))
def test_engine_api_fuzz(d):
    try:
        spec = engine.load_spec(d, base_dir=example_path("petrol_vaz2106.toml").parent)
        table = engine.force_table(spec)
        fine = engine.force_table(spec, engine.fine_angles(spec))
        engine.summarize(fine, spec)
    except CrankdynError:
        return
    assert _finite(table) and _finite(fine)


@API
@given(mutated(LINKAGE_BASES))
def test_linkage_api_fuzz(d):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SingularPositionWarning)
        try:
            res = linkage.analyze(d)
        except CrankdynError:
            return
    if not res.warnings:            # NaN rows only at flagged singular positions
        assert _finite(res.kinematics) and _finite(res.forces)


# ------------------------------------------------------------------------------ CLI
NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?")
ODD_TEXT = ["1e308", "-1e308", "1e-320", "nan", "inf", "-0", "9" * 400, "0x10", "1_000",
            "\"x\"", "[1, 2]", "{a = 1}", "true", "1e13", "1e-13", "", "[[[[[[1]]]]]]",
            "\"\\t\"", "0,5", "Ж"]


@st.composite
def mutated_text(draw, text, odd=ODD_TEXT, csv=False):
    lines = text.splitlines()
    for _ in range(draw(st.integers(1, 3))):
        i = draw(st.integers(0, max(0, len(lines) - 1)))
        op = draw(st.sampled_from(["number", "number", "delete", "dup", "insert", "chars"]
                                  + (["comma", "semicolon", "field"] if csv else [])))
        line = lines[i] if lines else ""
        if op == "number" and NUMBER.search(line):
            m = list(NUMBER.finditer(line))[draw(st.integers(0, len(NUMBER.findall(line)) - 1))]
            lines[i] = line[:m.start()] + draw(st.sampled_from(odd)) + line[m.end():]
        elif op == "delete" and lines:
            del lines[i]
        elif op == "dup" and lines:
            lines.insert(i, line)
        elif op == "insert":
            lines.insert(i, draw(st.text(max_size=12)))
        elif op == "comma":
            lines[i] = line.replace(".", ",")
        elif op == "semicolon":
            lines[i] = line.replace(",", ";")
        elif op == "field":
            lines[i] = line + "," + draw(st.sampled_from(["1", "", "x", "0,5"]))
        else:
            pos = draw(st.integers(0, len(line)))
            lines[i] = line[:pos] + draw(st.text(max_size=3)) + line[pos:]
    return "\n".join(lines) + "\n"


def _run_cli(tmp_path, capsys, args, out):
    if out.exists():
        shutil.rmtree(out)
    rc = main([*args, "-o", str(out)])
    captured = capsys.readouterr()
    assert rc in (0, 2), (rc, captured.err)
    if rc == 2:
        assert not out.exists(), "exit 2 but an output folder was written"
        lines = [l for l in captured.err.splitlines() if l.strip()]
        assert lines and all(l.startswith(f"crankdyn {args[0]}: ошибка: ") for l in lines), \
            captured.err
    return rc


CLI = settings(deadline=None, derandomize=True,
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                      HealthCheck.function_scoped_fixture])


@CLI.__class__(CLI, max_examples=40)
@given(data=st.data())
def test_linkage_cli_fuzz(tmp_path, capsys, data):
    name = data.draw(st.sampled_from(["ratchet.toml", "press.toml"]))
    text = example_path(name).read_text(encoding="utf-8")
    spec = tmp_path / "spec.toml"
    spec.write_text(data.draw(mutated_text(text)), encoding="utf-8")
    _run_cli(tmp_path, capsys, ["linkage", str(spec), "--no-plots"], tmp_path / "out")


def _laid_out_not_encoded(monkeypatch):
    """``Figure.savefig`` draws the figure once without output
    (``Figure.draw_without_rendering``: every artist's draw, text and mathtext layout,
    ticks, the layout engine, so an error a fuzzed number causes at drawing time still
    escapes) and writes a short text instead of encoding PNG and SVG (each a draw of its
    own: two thirds of a run's CPU).  The engine's figures are encoded for real by the
    CLI tests' reports.  Returns the list of the formats saved so."""
    from pathlib import Path, PurePath

    from matplotlib.figure import Figure

    saved = []

    def savefig(self, fname, *args, format=None, **kwargs):
        fmt = format or PurePath(str(fname)).suffix.lstrip(".")
        if fmt == "png":                       # the first format of each figure
            self.draw_without_rendering()
        Path(fname).write_bytes(f"figure laid out, not encoded ({fmt})\n".encode())
        saved.append(fmt)

    monkeypatch.setattr(Figure, "savefig", savefig)
    monkeypatch.setattr("crankbase.plot_layout.save_laid_out", save_through_savefig)
    return saved


@CLI.__class__(CLI, max_examples=10)
@given(data=st.data())
def test_engine_cli_fuzz_toml_and_csv(tmp_path, capsys, monkeypatch, data):
    saved = _laid_out_not_encoded(monkeypatch)
    spec_text = example_path("diesel_d240.toml").read_text(encoding="utf-8")
    csv_text = example_path("diesel_d240_indicator.csv").read_text(encoding="utf-8")
    which = data.draw(st.sampled_from(["toml", "csv", "csv"]))
    if which == "toml":
        spec_text = data.draw(mutated_text(spec_text))
    else:
        csv_text = data.draw(mutated_text(csv_text, csv=True))
    (tmp_path / "spec.toml").write_text(spec_text, encoding="utf-8")
    (tmp_path / "diesel_d240_indicator.csv").write_text(csv_text, encoding="utf-8")
    del saved[:]
    rc = _run_cli(tmp_path, capsys, ["engine", str(tmp_path / "spec.toml"), "--step", "90"],
                  tmp_path / "out")
    # an accepted spec's report has its plots (PNG and SVG each), a refused one none
    assert (saved and saved == ["png", "svg"] * (len(saved) // 2)) if rc == 0 else \
        saved == [], saved
