"""The indicator diagram (engine.indicator): the computed diagram's processes, its
rounding rules, p′i by the closed formula, and random thermal-calculation data."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine
from engine.indicator import (cycle_pressure, interpolate_periodic, sharp_cycle_pressure,
                              theoretical_mean_pressure, volume_ratio)
from crankbase.errors import SpecError

from test_engine_spec import DIESEL, OTTO, one_problem, spec_with

# ----------------------------------------------------------------------- the diagram

def cycle_spec(cyc, **kw):
    return engine.load_spec(spec_with(pressure={"cycle": dict(cyc, **kw)}))


@pytest.mark.parametrize("cyc", [OTTO, DIESEL], ids=["otto", "diesel"])
def test_sharp_diagram_mean_pressure_equals_closed_form(cyc):
    """Kolchin & Demidov: p′i = pc/(ε−1)·[λ(ρ−1) + λρ/(n2−1)(1 − δ^(1−n2))
    − 1/(n1−1)(1 − ε^(1−n1))]; the numeric ∮p dV/Vh of the sharp diagram adds the pumping
    loop −(pr − pa)."""
    s = cycle_spec(cyc, rounding=False)
    numeric = engine.indicated_mean_pressure(s, step_deg=0.01)
    closed = theoretical_mean_pressure(s.cycle) - (s.cycle.pr - s.cycle.pa)
    assert numeric == pytest.approx(closed, rel=2e-6)


@pytest.mark.parametrize("cyc", [OTTO, DIESEL], ids=["otto", "diesel"])
def test_sharp_diagram_points(cyc):
    s = cycle_spec(cyc, rounding=False)
    c = s.cycle
    p = sharp_cycle_pressure([0, 90, 180, 359.999999, 360, 539.9999999, 540, 600], c, s.lam)
    eps = c.compression_ratio
    assert p[0] == c.pa and p[1] == c.pa and p[2] == pytest.approx(c.pa)
    assert p[3] == pytest.approx(c.pa * eps ** c.n1, rel=1e-9)           # pc
    assert p[4] == pytest.approx(c.pz)                                    # z (or z′)
    assert p[5] == pytest.approx(c.pz * (c.rho / eps) ** c.n2, rel=1e-9)  # pb
    assert p[6] == c.pr and p[7] == c.pr
    vr = volume_ratio([0, 180], s.lam, eps)
    np.testing.assert_allclose(vr, [1.0, eps])


def test_diesel_isobaric_part():
    s = cycle_spec(DIESEL, rounding=False)
    a = np.linspace(360, 420, 6001)
    vr = volume_ratio(a, s.lam, 16.0)
    p = sharp_cycle_pressure(a, s.cycle, s.lam)
    assert np.all(p[vr <= 1.35] == s.cycle.pz)
    assert np.all(p[vr > 1.35] < s.cycle.pz)


@pytest.mark.parametrize("cyc", [OTTO, DIESEL], ids=["otto", "diesel"])
def test_rounded_diagram_rules(cyc):
    s = cycle_spec(cyc)
    c = s.cycle
    a = np.arange(0, 720.0001, 0.01)
    p = cycle_pressure(a, c, s.lam)
    # continuous everywhere (no jumps left), peak where the rule puts it
    assert np.max(np.abs(np.diff(p))) < 2e-3 * c.pz
    i = int(np.argmax(p))
    assert a[i] == pytest.approx(360 + c.peak_after_tdc_deg, abs=0.02)
    assert p[i] == pytest.approx(c.peak_factor * c.pz, rel=1e-9)
    at = cycle_pressure([360.0, 540.0, 360 - c.advance], c, s.lam)
    assert at[0] == pytest.approx(c.pc_factor * c.pc)
    pb = sharp_cycle_pressure([539.99999999], c, s.lam)[0]
    assert at[1] == pytest.approx((pb + c.pa) / 2, rel=1e-6)
    assert at[2] == pytest.approx(sharp_cycle_pressure([360 - c.advance], c, s.lam)[0])
    # the sharp diagram is untouched outside the rounding zones
    out = (a > 30) & (a < 300)
    np.testing.assert_array_equal(p[out], sharp_cycle_pressure(a[out], c, s.lam))
    # rounding removes area: the diagram fullness φп = pi/pi_sharp in (0.88, 1)
    ratio = engine.indicated_mean_pressure(s) / engine.indicated_mean_pressure(
        cycle_spec(cyc, rounding=False))
    assert 0.88 < ratio < 1.0


def test_lambda_z_instead_of_pz():
    cyc = {k: v for k, v in OTTO.items() if k != "pz_MPa"}
    s = cycle_spec(cyc, lambda_z=3.6)
    assert s.cycle.pz == pytest.approx(3.6 * 0.085e6 * 8.5 ** 1.377)




@settings(max_examples=30, deadline=None)
@given(kind=st.sampled_from(["otto", "diesel"]), eps=st.floats(6.0, 22.0),
       pa=st.floats(0.07, 0.12), pr=st.floats(0.1, 0.13), n1=st.floats(1.3, 1.4),
       n2=st.floats(1.18, 1.3), lam_z=st.floats(1.3, 4.5), rho=st.floats(1.1, 1.7),
       lam=st.floats(0.2, 0.35))
def test_random_cycles(kind, eps, pa, pr, n1, n2, lam_z, rho, lam):
    """Random thermal-calculation data: the sharp diagram's ∮p dV matches the closed
    form; the rounded one is continuous, positive, peaks where the rule says, and keeps
    nearly the same area."""
    cyc = dict(kind=kind, compression_ratio=eps, pa_MPa=pa, pr_MPa=pr, n1=n1, n2=n2,
               lambda_z=lam_z)
    if kind == "diesel":
        cyc["rho"] = rho
    d = spec_with("engine.rod_ratio", lam, pressure={"cycle": dict(cyc, rounding=False)})
    sharp = engine.load_spec(d)
    c = sharp.cycle
    closed = theoretical_mean_pressure(c) - (c.pr - c.pa)
    assert engine.indicated_mean_pressure(sharp, 0.01) == pytest.approx(closed, rel=1e-5)
    d["pressure"]["cycle"]["rounding"] = True
    try:
        rounded = engine.load_spec(d)
    except SpecError as exc:          # a peak below pc''·pc is refused, by key
        assert exc.lines()[0].startswith("pressure.cycle.peak_factor")
        return
    a = np.arange(0, 720.0001, 0.05)
    p = cycle_pressure(a, rounded.cycle, rounded.lam)
    assert np.all(p > 0) and np.all(np.isfinite(p))
    assert np.max(np.abs(np.diff(p))) < 0.01 * c.pz
    assert a[int(np.argmax(p))] == pytest.approx(360 + rounded.cycle.peak_after_tdc_deg,
                                                 abs=0.06)
    # rounding changes the area only a little (it usually removes some: φп < 1)
    ratio = engine.indicated_mean_pressure(rounded) / engine.indicated_mean_pressure(sharp)
    assert 0.8 < ratio < 1.02


def test_rounded_peak_must_lie_inside_the_sharp_diagram():
    cyc = {k: v for k, v in OTTO.items() if k != "pz_MPa"}
    line = one_problem(spec_with(pressure={"cycle": dict(cyc, compression_ratio=14.0,
                                                         lambda_z=2.0)}),
                       "pressure.cycle.peak_factor", "above the expansion line")
    assert "372°" in line
    # the same data unrounded are fine
    engine.load_spec(spec_with(pressure={"cycle": dict(cyc, compression_ratio=14.0,
                                                       lambda_z=2.0, rounding=False)}))


def test_rounding_needs_the_isobaric_part_inside_its_zone():
    one_problem(spec_with(pressure={"cycle": dict(DIESEL, compression_ratio=22.0, rho=3.5,
                                                  pz_MPa=9.0)}),
                "pressure.cycle.peak_factor", "isobaric")


def test_interpolate_periodic_wraps_last_to_first():
    a = np.array([10.0, 100.0, 700.0])
    p = np.array([1.0, 2.0, 3.0])
    # between 700 and 730 (= 10 of the next cycle): linear from 3 to 1
    np.testing.assert_allclose(interpolate_periodic([715.0, 0.0, 10.0, 55.0], a, p, 720),
                               [2.0, 5 / 3, 1.0, 1.5])
