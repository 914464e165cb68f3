"""Published numbers for the main-bearing loads (the lever rule of a split crankshaft).

R. S. Khurmi, J. K. Gupta, *A Textbook of Machine Design*, 14th ed., Eurasia (S. Chand),
2005, ch. 32 "Internal Combustion Engine Parts", the worked design of a centre crankshaft
(pp. 1177–1181): bore D = 400 mm, stroke 600 mm (r = 300 mm), l/r = 5, the main bearings
b = 2D = 800 mm apart with the crank pin midway (b1 = b2 = 400 mm); inertia neglected.

* Crank at the dead centre, p = 2.5 N/mm²: FP = π/4·400²·2.5 = 314.2 kN, and the two
  bearings carry H1 = H2 = 157.1 kN (p. 1177).
* Crank at 35° from TDC (maximum torque), p′ = 1 N/mm²: FP = 125.68 kN, φ = 6.58°,
  FQ = 126.5 kN, FT = 84 kN, FR = 94.6 kN; the bearings carry HT1 = HT2 = 42 kN and
  HR1 = HR2 = 47.3 kN, the resultant R1 = √(42² + 47.3²) = 63.3 kN (pp. 1179–1181).

The book rounds π to 3.142 and prints 3–4 significant digits, hence rel = 2e-3.  Also
searched (and not found with complete inputs): Russian course projects with Rшш.ср, χ,
Rк.ш tables or wear diagrams (Kolchin & Demidov-style dynamic calculations) in the pages
and code corpora.
"""
import numpy as np
import pytest

import engine
from engine.bearings.analysis import bearing_analysis, read_bearing_inputs


def khurmi(p_MPa):
    d = {
        "engine": dict(name="khurmi-centre-crankshaft", bore_mm=400.0, stroke_mm=600.0,
                       rod_ratio=0.2, speed_rpm=200.0, crankcase_MPa=0.0),
        "masses": dict(reciprocating_kg=0.0, rod_rotating_kg=0.0),
        "pressure": dict(angle_deg=[0.0, 360.0], p_MPa=[p_MPa, p_MPa]),
        "table": dict(step_deg=5.0, force_scale_N_per_mm=1000.0),
        "bearings": dict(journal_positions_mm=[-400.0, 400.0]),
    }
    spec = engine.load_spec(d)
    return spec, read_bearing_inputs(d, spec)


def test_khurmi_centre_crankshaft_at_dead_centre():
    spec, inputs = khurmi(2.5)
    t = engine.force_table(spec, [0.0, 5.0])
    res = bearing_analysis(spec, t, inputs)
    assert t["P_N"].iloc[0] == pytest.approx(314.2e3, rel=2e-3)
    for j in (1, 2):
        assert res.loads.journals[f"R_{j}_N"].iloc[0] == pytest.approx(157.1e3, rel=2e-3)
        assert res.loads.journals[f"K_{j}_N"].iloc[0] == pytest.approx(157.1e3, rel=2e-3)


def test_khurmi_centre_crankshaft_at_maximum_torque():
    spec, inputs = khurmi(1.0)
    t = engine.force_table(spec, [35.0, 40.0])
    res = bearing_analysis(spec, t, inputs)
    row = t.iloc[0]
    assert row["P_N"] == pytest.approx(125.68e3, rel=2e-3)
    assert row["beta_deg"] == pytest.approx(6.58, abs=0.01)
    assert row["S_N"] == pytest.approx(126.5e3, rel=2e-3)
    assert row["T_N"] == pytest.approx(84.0e3, rel=2e-3)
    assert row["K_N"] == pytest.approx(94.6e3, rel=2e-3)
    jr = res.loads.journals.iloc[0]
    for j in (1, 2):
        assert jr[f"T_{j}_N"] == pytest.approx(42.0e3, rel=2e-3)       # HT1, HT2
        assert jr[f"K_{j}_N"] == pytest.approx(47.3e3, rel=2e-3)       # HR1, HR2
        assert jr[f"R_{j}_N"] == pytest.approx(63.3e3, rel=2e-3)       # R1
    # the torque: the flywheel-side journal carries FT·r = 84 kN × 0.3 m = 25.2 kN·m
    assert res.loads.journal_torques["M_2_Nm"].iloc[0] == pytest.approx(25.2e3, rel=2e-3)
    assert res.loads.journal_torques["M_1_Nm"].iloc[0] == 0.0
