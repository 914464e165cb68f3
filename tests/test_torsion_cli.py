"""``crankdyn torsion`` and ``crankdyn engine --torsion``: one end-to-end run each, and
bad input: one line per problem, exit status 2, nothing written, in both languages."""
from __future__ import annotations

import tomllib

import pandas as pd
import pytest

from crankbase.resources import example_path
from crankdyn.cli import main


def test_crankdyn_torsion_example_end_to_end(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["torsion", "--example", "six", "-o", str(out), "--lang", "en"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith("bmw-m54b30: torsional chain of 8 masses")
    assert lines[-1].startswith("wrote ") and lines[-1].endswith(str(out))
    names = {p.name for p in out.iterdir() if not p.name.startswith(".")}
    for n in ("torsion_modes.csv", "holzer.csv", "torque_harmonics.csv",
              "critical_speeds.csv", "torsion_response.csv", "torsion.xlsx"):
        assert f"bmw-m54b30_{n}" in names
    cs = pd.read_csv(out / "bmw-m54b30_critical_speeds.csv")
    assert list(cs.columns) == ["mode", "order", "f_Hz", "speed_rpm", "major",
                                "sum_relative_amplitude"]
    h = pd.read_csv(out / "bmw-m54b30_torque_harmonics.csv")
    assert list(h.columns) == ["part", "order", "a_Nm", "b_Nm", "amplitude_Nm", "phase_deg"]
    assert set(h["part"]) == {"gas", "inertia", "total"}
    tot = h[h.part == "total"].set_index("order")
    parts = h[h.part != "total"].groupby("order")[["a_Nm", "b_Nm"]].sum()
    assert tot[["a_Nm", "b_Nm"]].to_numpy() == pytest.approx(parts.to_numpy(), abs=1e-6)


def _bad_spec(tmp_path):
    data = tomllib.loads(example_path("torsion_inline6.toml").read_text(encoding="utf-8"))
    spec = tmp_path / "bad.toml"
    text = example_path("torsion_inline6.toml").read_text(encoding="utf-8")
    text = text.replace("orders_max = 12", "orders_max = 7.3").replace(
        "speed_range_rpm = [800, 6500]", "speed_range_rpm = [800, -6500]")
    spec.write_text(text, encoding="utf-8")
    assert data["torsion"]["orders_max"] == 12
    return spec


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_bad_spec_one_line_per_problem_exit_2_nothing_written(tmp_path, capsys, lang):
    from test_error_language import cyrillic, english_words

    out = tmp_path / "out"
    assert main(["torsion", str(_bad_spec(tmp_path)), "-o", str(out), "--lang", lang]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 2, err
    error = {"en": "error", "ru": "ошибка"}[lang]
    assert err[0].startswith(f"crankdyn torsion: {error}: torsion.speed_range_rpm")
    assert err[1].startswith(f"crankdyn torsion: {error}: torsion.orders_max")
    assert not out.exists()
    for line in err:
        assert not (cyrillic(line) if lang == "en" else english_words(line)), line


def test_engine_torsion_option_needs_the_table(tmp_path, capsys):
    """--torsion on a spec without [torsion]: the stiffnesses cannot be guessed, so it is
    one error (exit 2, nothing written), not a run with made-up numbers."""
    out = tmp_path / "out"
    assert main(["engine", "--example", "petrol", "--torsion", "-o", str(out),
                 "--lang", "ru"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("crankdyn engine: ошибка: torsion: ")
    assert "[torsion]" in err[0] and not out.exists()


def test_torsion_example_names(tmp_path, capsys):
    assert main(["torsion", "--example", "petrol", "-o", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "three-rotor" in err and "six" in err
    assert main(["torsion", "-o", str(tmp_path / "o")]) == 2
