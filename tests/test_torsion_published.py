"""Published worked examples of torsional vibration, through the public functions of
torsion.chain (issue #21, proof).  Each number asserted here is printed in the cited
source, and is asserted to its printed precision; none is back-computed from our code.

Sources looked for and NOT usable (so not tested here), see the module's end."""
from __future__ import annotations

import numpy as np
import pytest

from torsion.chain import (holzer_residual, holzer_table, natural_modes,
                           shaft_stiffness)

# --------------------------------------------------------------------------------------
# W. T. Thomson, "Theory of Vibration with Applications" (Taylor & Francis printing,
# 2010), § 12.4 "Holzer Method", Example 12.4-1, book pp. 388-389, Table 12.4-1.
# Read at digilib.universitaspertamina.ac.id/ebook/Theory%20of%20Vibration%20with
# %20Applications/files/basic-html/page401.html and page402.html.
# Printed parameters: J1 = 5, J2 = 11, J3 = 22 kg·m²; K1 = 0.10e6, K2 = 0.20e6 N·m/rad
# (free-free; K3 = 0).  The table starts θ1 = 1.0 at disk 1 and prints, per trial ω,
# θ1, θ2, θ3 and the running torque T1 = ω²J1θ1, T2 = T1 + ω²J2θ2, T3 = T2 + ω²J3θ3
# ("the torque to the right of disk 3, which must be zero at the natural frequencies").
# --------------------------------------------------------------------------------------
THOMSON_J = [5.0, 11.0, 22.0]
THOMSON_K = [0.10e6, 0.20e6]

# ω [rad/s]: (θ1, θ2, θ3 as printed, their printed precision),
#            (T1, T2, T3 as printed [N·m], their printed precision)
THOMSON_ROWS = {
    20.0: ((1.0, 0.980, 0.9484), (5e-2, 5e-4, 5e-5),
           (2.0e3, 6.312e3, 14.66e3), (0.05e3, 0.0005e3, 0.005e3)),
    40.0: ((1.0, 0.920, 0.799), (5e-2, 5e-4, 5e-4),
           (8.0e3, 24.19e3, 52.32e3), (0.05e3, 0.005e3, 0.005e3)),
}


def assert_printed(ours, printed, half_digit):
    """Each of ``ours`` within half a unit of the last printed digit of ``printed``."""
    ours, printed = np.asarray(ours, float), np.asarray(printed, float)
    assert np.all(np.abs(ours - printed) <= np.asarray(half_digit)), (ours, printed)


def test_thomson_12_4_1_holzer_table_rows():
    """Every printed cell of Thomson's Table 12.4-1 (ω = 20 and 40 rad/s), to the digits
    printed.  A wrong sign of the twist (θ2 = 1 + T1/K1 → 1.020), an ω instead of ω²
    (T1 = 100, not 2.0e3), or the inertias taken in reverse order (T1 = 22ω²) all fail."""
    t = holzer_table(THOMSON_J, THOMSON_K, list(THOMSON_ROWS))
    for omega, (theta, d_theta, torque, d_torque) in THOMSON_ROWS.items():
        rows = t[t["omega_rad_s"] == omega]
        assert rows["J_kgm2"].tolist() == THOMSON_J                 # printed J1, J2, J3
        assert_printed(rows["theta_rad"], theta, d_theta)
        assert_printed(rows["sum_torque_Nm"], torque, d_torque)
        # the inertia torques J ω² θ are the printed running torque's increments
        assert_printed(rows["inertia_torque_Nm"], np.diff([0.0, *torque]),
                       np.add(d_torque, [0.0, *d_torque[:-1]]))


def test_thomson_12_4_1_residual_is_the_printed_T3():
    """holzer_residual is the table's T3 (printed 14.66e3 and 52.32e3 N·m for θ1 = 1)."""
    r = holzer_residual(THOMSON_J, THOMSON_K, np.array([20.0, 40.0]))
    np.testing.assert_allclose(r, [14.66e3, 52.32e3], rtol=0, atol=5.0)


def test_thomson_12_4_1_both_trials_below_the_first_mode():
    """Both printed trials have T3 > 0 and θ3 > 0 (no node yet), so, as Thomson's
    Fig. 12.4-3 shows, the first natural frequency lies above 40 rad/s: our first mode
    must be above 40 rad/s and its single node between the disks."""
    m = natural_modes(THOMSON_J, THOMSON_K)
    assert m.count == 2
    assert m.omega_rad_s[0] > 40.0
    assert np.all(holzer_residual(THOMSON_J, THOMSON_K, np.linspace(1.0, 40.0, 40)) > 0)
    # Holzer's residual changes sign at each of our eigenfrequencies
    for w in m.omega_rad_s:
        lo, hi = holzer_residual(THOMSON_J, THOMSON_K, np.array([0.999 * w, 1.001 * w]))
        assert lo * hi < 0


# --------------------------------------------------------------------------------------
# Khurmi & Gupta's three-rotor shaft (70 mm, C = 84 kN/mm²; its frequencies and nodes are
# tested in test_torsion_physics.py).  The worked answers at qna.carrieradda.com/26013
# and /26108 print the shaft's polar moment of area as "2.36×10^6 m^4": the exponent's
# sign is lost in that reproduction (π·0.070⁴/32 m⁴ is of order 1e-6), so the mantissa
# 2.36 is asserted in units of 1e-6 m⁴, through shaft_stiffness = C·Ip/l at l = 1 m.
# --------------------------------------------------------------------------------------


def test_khurmi_polar_moment_of_the_70mm_shaft():
    G = 84e9
    Ip = shaft_stiffness(G, 0.070, 1.0) / G                  # [m⁴]
    assert Ip / 1e-6 == pytest.approx(2.36, abs=5e-3)         # printed 2.36 (×1e-6 m⁴)
    # stiffness ∝ 1/l: the 1.5 m and 1.0 m sections of the same shaft
    assert shaft_stiffness(G, 0.070, 1.5) == pytest.approx(G * Ip / 1.5, rel=1e-12)


# --------------------------------------------------------------------------------------
# Looked for, not usable here (no test can cite what was not seen printed):
# * NPTEL 112103024 (R. Tiwari, "Rotor Dynamics", IIT Guwahati), module 6, lec1-lec4
#   (archive.nptel.ac.in/content/storage2/courses/112103024/module6/lec2/8.html, 9.html,
#   lec4/7.html, lec4/16.html): the stored text keeps the prose of Examples 6.4, 6.5,
#   6.11-6.13 (three-disc, geared, branched) but every number sits in an equation
#   image that the stored page does not carry; the reciprocating-engine pages were not
#   found at all.
# * transtutors.com/questions/...-0-3-0-6-and-0-18-kg-1418436.htm (three rotors 0.3,
#   0.6, 0.18 kg·m², 70 mm, 84e9 N/m²): the statement only, no answer printed.
# * schoolsolver.com/question/65944 (shaft AB 100 mm + hollow shafts 138/106 mm, 130 kg
#   and 250 kg at k = 175 and 375 mm): the statement only, no answer printed.
# * Thomson Example 12.4-1's natural frequencies and mode shapes are given only as
#   plots (Figs. 12.4-3, 12.4-4), not as numbers.
# --------------------------------------------------------------------------------------
