"""linkage.loads: the useful resistance acts only in its stroke and span, against the
motion of its link (read back from the tables of linkage.analyze)."""
import copy
import math

import numpy as np
import pytest

import linkage
from newton_euler import loaded_slider, ratchet_data, wrap_deg
from test_linkage_analysis import _col


def _resistance_case(kind, stroke):
    if kind == "rocker":
        d = ratchet_data()
        d["load"][0]["stroke"] = stroke
        return d, "M_res_Nm", "omega4_rad_s", "theta4_deg", math.radians(59.587), 1500.0
    d = loaded_slider()
    d["load"][-1]["stroke"] = stroke
    return d, "F_res_N", "v4_m_s", "s4_m", 0.06, 900.0


@pytest.mark.parametrize("kind", ["rocker", "slider"])
@pytest.mark.parametrize("stroke", ["working", "idle", "both"])
def test_resistance_only_in_its_stroke_and_span_opposing_motion(kind, stroke):
    data, rcol, vcol, ccol, span, R = _resistance_case(kind, stroke)
    res = linkage.analyze(data, crank_angles_deg=np.arange(0.0, 360.0, 0.5))
    k, f = res.kinematics, res.forces
    m = data["mechanism"]
    rocker = kind == "rocker"
    wsign = {"ccw": 1, "cw": -1, "away": m.get("assembly", 1),
             "toward": -m.get("assembly", 1)}[data["analysis"]["working_stroke"]]
    rate = _col(k, vcol)
    val = _col(f, rcol)
    ex = res.extremes
    c_start = {+1: _col(ex, ccol)[0], -1: _col(ex, ccol)[1]}  # start of working/idle
    state = np.sign(rate) * wsign
    if rocker:
        travel = np.abs(np.radians(wrap_deg(_col(k, ccol) - np.where(state > 0, c_start[1],
                                                                       c_start[-1]))))
    else:
        travel = np.abs(_col(k, ccol) - np.where(state > 0, c_start[1], c_start[-1]))
    in_stroke = {"working": state > 0, "idle": state < 0, "both": state != 0}[stroke]
    active = in_stroke & (travel <= span)
    # away from the on/off boundaries (the span's end) the rule is exact
    clear = np.abs(travel - span) > 1e-6
    np.testing.assert_array_equal(val[clear] != 0, active[clear])
    # it opposes the motion, at full magnitude
    assert np.all(val[active] * rate[active] < 0)
    np.testing.assert_allclose(np.abs(val[active]), R)
    assert active.sum() > 10 and (~active).sum() > 10
    # and it shows in the driving moment exactly by its power: ΔM_drive·ω2 = −P_res
    base = copy.deepcopy(data)
    base["load"] = [ld for ld in base["load"] if "resistance_Nm" not in ld
                    and "resistance_N" not in ld]
    f0 = linkage.analyze(base, crank_angles_deg=np.arange(0.0, 360.0, 0.5)).forces
    dM = _col(f, "M_drive_Nm") - _col(f0, "M_drive_Nm")
    scale = R * max(np.max(np.abs(rate)), 1e-300) / abs(m["omega_rad_s"])
    np.testing.assert_allclose(dM * m["omega_rad_s"], -val * rate, rtol=0, atol=1e-9 * scale
                               * abs(m["omega_rad_s"]))


def test_ratchet_resistance_in_the_plan():
    """Seed 000 (domain.md §2): M = 1500 N·m against the rocker's motion only in the
    working stroke and only over the first τ = 1.04 rad of swing: in the 12-position plan
    that is positions 2…5 (position 1 is the extreme, where the rocker stands still;
    position 6 is 62.6° into the stroke, past the span)."""
    f = linkage.analyze(ratchet_data()).forces
    want = [0.0, -1500.0, -1500.0, -1500.0, -1500.0] + [0.0] * 7
    np.testing.assert_array_equal(_col(f, "M_res_Nm"), want)
