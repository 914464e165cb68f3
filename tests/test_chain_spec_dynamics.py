"""Machine dynamics of a chain spec (``[mechanism] kind = "chain"`` + ``[dynamics]``,
issue #20): ``crankdyn dynamics`` on any six-link mechanism.

* Today's press (press_dynamics.toml, a crank-slider with a motor and δ = 0.05) written as a
  chain gives today's dynamics numbers (motion table, flywheel, forces under the true
  motion) to round-off: a swapped angle origin, a lost load or weight would break it.
* The bundled shaper (shaper_dynamics.toml): the energy identity of the true motion
  ½(J_red + J_F)ω² − ½(J_red + J_F)ω₀² = ∫(M_d − M_c)dφ; the cutting force's work per
  cycle equals F·span = 2000 N × 0.30 m (the spec's resistance over the first 0.30 m of
  the working stroke); the group-by-group Mур under the true motion equals the motor's
  moment minus the flywheel's inertia moment, M_d − J_F ε (the equation of motion at the
  crank shaft, the flywheel on it).
"""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from crankbase.resources import example_path
from dynamics.spec import load_dynamics_spec, run_job


def _toml(name):
    with open(example_path(name), "rb") as f:
        return tomllib.load(f)


def _press_chain(old):
    m = old["mechanism"]
    return {"mechanism": {"kind": "chain", "name": "press-chain", "crank": m["crank"],
                          "output": "slider", "omega_rad_s": m["omega_rad_s"],
                          "gravity_m_s2": m["gravity_m_s2"], "frame": {"O": [0.0, 0.0]}},
            "group": [{"kind": "RRP", "links": ["coupler", "slider"], "joints": ["A", "B"],
                       "lengths": [m["coupler"]], "assembly": m["assembly"],
                       "guide_angle_deg": m["ground_angle_deg"],
                       "guide_offset": m["offset"]}],
            "links": old["links"], "load": old["load"], "analysis": old["analysis"],
            "dynamics": old["dynamics"]}


def _close(a, b, rtol):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(1e-12, float(np.max(np.abs(b))))
    assert np.max(np.abs(a - b)) <= rtol * scale, (np.max(np.abs(a - b)), scale)


@pytest.fixture(scope="module")
def press():
    old = _toml("press_dynamics.toml")
    return run_job(load_dynamics_spec(old)), run_job(load_dynamics_spec(_press_chain(old)))


def test_the_press_as_a_chain_spec_gives_todays_dynamics(press):
    old, new = press
    assert new.model.source.kind == "chain" and old.model.source.kind == "crank-slider"
    mo, mn = old.motion.table, new.motion.table
    for c in ("phi_deg", "J_red_kgm2", "M_resist_Nm", "M_resist_loads_Nm",
              "M_resist_weights_Nm", "W_J"):
        _close(mn[c], mo[c], 1e-9)
    _close(mn["dJ_red_dphi_kgm2"], mo["dJ_red_dphi_kgm2"], 1e-8)
    # the motor's periodic solution and the flywheel found by iteration: round-off of it
    for c in ("omega_rad_s", "eps_rad_s2", "t_s", "M_drive_Nm", "E_J"):
        _close(mn[c], mo[c], 1e-7)
    assert new.flywheel.J_exact == pytest.approx(old.flywheel.J_exact, rel=1e-7)
    assert new.flywheel.J_classic == pytest.approx(old.flywheel.J_classic, rel=1e-9)
    fo, fn = old.forces, new.forces
    for a, b in (("M_drive_Nm", "M_drive_Nm"), ("R12_x_N", "Rx_frame_crank_N"),
                 ("R12_y_N", "Ry_frame_crank_N"), ("R12_N", "R_frame_crank_N")):
        for sfx, tol in (("", 1e-6), ("_const", 1e-7)):
            _close(fn[b + sfx], fo[a + sfx], tol)
    assert fn.attrs["crank_bearing"] == "R_frame_crank_N"


@pytest.fixture(scope="module")
def shaper():
    return run_job(load_dynamics_spec(example_path("shaper_dynamics.toml")))


def test_shaper_energy_identity_and_cutting_work(shaper):
    tab = shaper.motion.table
    JF = shaper.flywheel.J_exact
    phi = tab["phi_rad"].to_numpy()
    w = tab["omega_rad_s"].to_numpy()
    J = tab["J_red_kgm2"].to_numpy()          # the motion table's J includes J_F
    assert np.min(J) > JF > 100.0
    net = tab["M_drive_Nm"].to_numpy() - tab["M_resist_Nm"].to_numpy()
    W = np.concatenate([[0.0], np.cumsum(0.5 * (net[1:] + net[:-1]) * np.diff(phi))])
    dE = 0.5 * J * w ** 2 - 0.5 * J[0] * w[0] ** 2
    assert np.ptp(dE) > 300.0
    assert np.max(np.abs(dE - W)) <= 1e-3 * np.ptp(dE)
    # steady: periodic ω, and the cycle's net work zero
    assert w[-1] == pytest.approx(w[0], rel=1e-6)
    # the cutting force 2000 N over 0.30 m of the working stroke (shaper.toml)
    Wc = np.trapezoid(tab["M_resist_loads_Nm"].to_numpy(), phi)
    assert Wc == pytest.approx(2000.0 * 0.30, rel=2e-3)
    # the weights do no net work over a turn
    assert abs(np.trapezoid(tab["M_resist_weights_Nm"].to_numpy(), phi)) < 1e-6 * 600.0
    # the mean speed near the spec's 6.28 rad/s, δ as asked
    assert shaper.flywheel.motion.delta == pytest.approx(0.05, rel=1e-4)


def test_shaper_kinetostatic_drive_equals_motor_minus_flywheel(shaper):
    """Mур of the group-by-group kinetostatics under ω(φ), ε(φ) (the crank shaft without
    the flywheel) = M_d − J_F ε: the flywheel and the motor sit on the crank shaft."""
    tab, f = shaper.motion.table, shaper.forces
    JF = shaper.flywheel.J_exact
    s = shaper.model.rotation
    expect = s * (tab["M_drive_Nm"].to_numpy() - JF * tab["eps_rad_s2"].to_numpy())
    _close(f["M_drive_Nm"], expect, 2e-3)
    # at constant speed Mур = M_c − ½ω²dJ/dφ … averaged over a turn: the mean resistance
    const = f["M_drive_Nm_const"].to_numpy()
    phi = tab["phi_rad"].to_numpy()
    Mc = tab["M_resist_Nm"].to_numpy()
    assert np.trapezoid(const, phi) == pytest.approx(s * np.trapezoid(Mc, phi), rel=2e-3)
    # the frame's reaction on the crank is a column of the chain's force table
    assert f.attrs["crank_bearing"] == "R_frame_crank_N"
    assert {"Rx_frame_ram_N", "R_lever_rod_N", "M_drive_Nm_const"} <= set(f.columns)


def test_cli_dynamics_example_shaper(shaper, cli_report):
    """``crankdyn dynamics --example shaper``: the files, the chain's force columns, an
    English summary without Cyrillic; the Russian summary (the same study layer the CLI
    calls: :func:`dynamics.study.run_study` is ``run_job`` of the loaded spec, this
    module's ``shaper``) with its words.  The CLI's report is the session's shared run
    (read-only; the browser's shaper test reads it too)."""
    import re

    import pandas as pd

    from dynamics.study import summary_lines

    rep = cli_report("dynamics", "--example", "shaper", "--lang", "en")
    assert rep.rc == 0, rep.err
    en = rep.out
    ru = "\n".join(summary_lines(shaper, "ru"))
    assert not re.search("[\u0400-\u04FF]", en)
    assert "маховик" in ru and "flywheel" in en
    # the CLI's English summary is the study layer's, the same numbers as the Russian
    assert en.splitlines()[:-1] == summary_lines(shaper, "en")
    out = rep.folder
    for f in ("motion.csv", "forces_true_motion.csv", "startup.csv", "dynamics.xlsx",
              "omega.png", "forces_true_motion.png"):
        assert (out / f"shaper-machine_{f}").stat().st_size > 0, f
    forces = pd.read_csv(out / "shaper-machine_forces_true_motion.csv")
    assert {"R_frame_crank_N", "R_frame_crank_N_const", "Rx_frame_ram_N",
            "M_drive_Nm"} <= set(forces.columns)
    motion = pd.read_csv(out / "shaper-machine_motion.csv")
    assert motion["omega_rad_s"].mean() == pytest.approx(6.28, rel=0.01)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_shaper_dynamics_workbook_is_clean(shaper, lang, tmp_path, cli_report,
                                          loaded_workbook):
    """The shaper's dynamics workbook passes the reader's audit (tests/workbook_audit.py:
    nothing cut off, no ###, one number format per column), its long chain column names
    included; the forces sheet holds the chain's reactions.  In English the workbook the
    CLI wrote (the session's shared report), in Russian the study layer's."""
    from openpyxl import load_workbook
    from workbook_audit import problems

    from dynamics.report import build_workbook
    from engine.report import save_workbook

    if lang == "en":
        rep = cli_report("dynamics", "--example", "shaper", "--lang", "en")
        assert rep.rc == 0, rep.err
        path = rep.folder / f"{shaper.stem}_dynamics.xlsx"
        wb = loaded_workbook(path)                      # shared, read-only
    else:
        path = tmp_path / f"shaper_{lang}.xlsx"
        save_workbook(build_workbook(shaper, lang, name=shaper.model.name), path)
        wb = load_workbook(path)
    assert problems(wb, path.name) == []
    keys = {c.value for ws in wb.worksheets for row in ws.iter_rows(max_row=6) for c in row}
    assert "R_frame_crank_N" in keys and "Rx_lever_rod_N_const" in keys
