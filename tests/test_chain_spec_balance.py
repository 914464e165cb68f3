"""Shaking force and its balance for a chain spec (``crankdyn balance`` on any six-link
mechanism, issue #20).

* The shaper's shaking force and moment (the balance study's table) equal the load of the
  links on the frame from the group-by-group kinetostatics with no external load and no
  weight (the frame's reactions summed, with the motor stator's −Mур), at every position:
  d'Alembert; a wrong sign or a missing link's inertia breaks it.
* The first-harmonic crank counterweight of an axial crank-slider written as a chain equals
  the textbook one for all the rotating mass and half the reciprocating mass
  (Khurmi & Gupta, Theory of Machines, ch. 22, §22.3: B·b = (m1 + c·m) r with c = ½;
  today's :func:`dynamics.shaking.balance_crank_slider` with ``fraction = 0.5``).
* After the balance the forward first harmonic is gone and the mean square drops.
"""
from __future__ import annotations

import copy
import tomllib

import numpy as np
import pytest

from crankbase.errors import SpecError
from crankbase.resources import example_path
from dynamics.balance_study import run_study, summary_lines
from dynamics.chain_model import frame_load
from dynamics.shaking import balance_chain, balance_crank_slider, mechanism_balance, shaking
from linkage import chain as ch
from linkage import load_spec


def _toml(name):
    with open(example_path(name), "rb") as f:
        return tomllib.load(f)


def test_shaper_shaking_equals_the_frame_reactions():
    spec = load_spec(example_path("shaper.toml"))
    tab = shaking(spec).table
    phi = np.radians(tab["phi_deg"].to_numpy())
    mech = spec.mechanism
    res = ch.solve(mech, phi, spec.omega, spec.epsilon)
    O = mech.frame[mech.driver.pivot]
    F, M = frame_load(ch.kinetostatics(res, {}, {}, 0.0), O)
    scale = tab["F_N"].max()
    assert scale > 100.0
    assert np.max(np.abs(tab["F_x_N"] - F.x)) <= 1e-9 * scale
    assert np.max(np.abs(tab["F_y_N"] - F.y)) <= 1e-9 * scale
    assert np.max(np.abs(tab["M_O_Nm"] - M)) <= 1e-9 * max(1.0, np.max(np.abs(M)))


def _axial_slider():
    old = _toml("press.toml")
    m = old["mechanism"]
    m["offset"] = 0.0
    chain = {"mechanism": {"kind": "chain", "name": "axial", "crank": m["crank"],
                           "output": "slider", "omega_rad_s": m["omega_rad_s"],
                           "gravity_m_s2": m["gravity_m_s2"], "frame": {"O": [0.0, 0.0]}},
             "group": [{"kind": "RRP", "links": ["coupler", "slider"], "joints": ["A", "B"],
                        "lengths": [m["coupler"]], "assembly": m["assembly"],
                        "guide_angle_deg": m["ground_angle_deg"], "guide_offset": 0.0}],
             "links": copy.deepcopy(old["links"]), "load": old["load"],
             "analysis": old["analysis"]}
    return old, chain


def test_first_harmonic_counterweight_of_an_axial_slider_is_the_textbook_one():
    old, chain = _axial_slider()
    ref = balance_crank_slider(load_spec(old), fraction=0.5)
    new = balance_chain(load_spec(chain))
    a, b = ref.counterweights.iloc[0], new.counterweights.iloc[0]
    assert b["mr_kgm"] == pytest.approx(a["mr_kgm"], rel=1e-9)
    assert b["angle_deg"] == pytest.approx(a["angle_deg"], abs=1e-7)
    assert b["mass_kg"] == pytest.approx(a["mass_kg"], rel=1e-9)
    # the balanced chain shakes as today's balanced crank-slider
    assert np.max(np.abs(new.after.table["F_N"] - ref.after.table["F_N"])) <= \
        1e-9 * ref.before.F_max


def test_shaper_balance_removes_the_forward_harmonic():
    res = mechanism_balance(example_path("shaper.toml"))
    assert res.counterweights["link"].tolist() == ["crank"]
    out = []
    for r in (res.before, res.after):
        t = r.table.iloc[:-1]                    # 0…359°
        phi = np.radians(t["phi_deg"].to_numpy())
        F = t["F_x_N"].to_numpy() + 1j * t["F_y_N"].to_numpy()
        out.append((abs(np.mean(F * np.exp(-1j * phi))), np.mean(np.abs(F) ** 2)))
    (c1_b, ms_b), (c1_a, ms_a) = out
    assert c1_b > 50.0 and c1_a <= 1e-9 * c1_b
    assert ms_a == pytest.approx(ms_b - c1_b ** 2, rel=1e-9)     # Parseval
    # the counterweight's mass is merged into the crank of the balanced spec
    m0 = load_spec(example_path("shaper.toml")).mechanism.links["crank"].mass
    assert res.balanced_spec.mechanism.links["crank"].mass == pytest.approx(
        m0 + res.counterweights["mass_kg"].iloc[0])


def test_chain_balance_report_and_keyed_errors():
    rep = run_study(example_path("shaper.toml"))
    en, ru = summary_lines(rep, "en"), summary_lines(rep, "ru")
    assert "I(0,1) → II(2,3) → II(4,5)" in en[0]
    assert not any(any("а" <= c <= "я" for c in line.lower()) for line in en)
    assert "кривошип" in ru[1]
    data = _toml("shaper.toml")
    data["balance"] = {"fraction": 0.5}
    with pytest.raises(SpecError) as exc:
        mechanism_balance(data)
    assert [p.key for p in exc.value.problems] == ["balance.fraction"]
