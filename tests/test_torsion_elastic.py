"""The vibration amplitude is the elastic (twisting) motion (issue #21, third pass).

The chain is free–free: each harmonic torque also swings the whole chain as a rigid body
(Σ J Θ = −Σ F / Ω² when the damping holds the rigid mode free), about 1.9° at 800 rpm on
the inline six, falling as 1/n², which hid the resonances.  The course and the engine
texts (Den Hartog, *Mechanical Vibrations*, 4th ed., § 5.7; Ker Wilson, *Practical
Solution of Torsional Vibration Problems*, vol. 2) give the vibration amplitude as the
twisting motion, relative to the rotation of the chain's mean inertia, whose curve peaks
at the critical speeds n = 60 f / k.  The absolute angle stays as ``swing_<mass>_deg``.
"""
from __future__ import annotations

import numpy as np
import pytest

from crankbase.resources import example_path
from torsion.chain import damping_matrix, stiffness_matrix
from torsion.response import elastic_part, excitation_vectors, harmonic_solve
from torsion.study import build_outputs, load, run_study


@pytest.fixture(scope="module")
def six():
    return run_study(load(example_path("torsion_inline6.toml")))


def _complex_response(rep):
    """Θ_k of every mass, speed and order, solved here from the report's chain and
    harmonics (the same equations as torsion.response.forced_response)."""
    ch, r = rep.chain, rep.response
    assert not ch.dampers                     # modal damping only: the rigid mode is free
    C = damping_matrix(ch.J, rep.modes, rep.study.inputs.damping_ratio)
    hg, hi = rep.harmonics["gas"], rep.harmonics["inertia"]
    keep = hg.order > 0
    orders = hg.order[keep]
    Fg = excitation_vectors(len(ch.J), ch.cylinder_mass, ch.phases_deg, hg.complex_Nm[keep],
                            orders)
    Fi = excitation_vectors(len(ch.J), ch.cylinder_mass, ch.phases_deg, hi.complex_Nm[keep],
                            orders)
    s = r.speeds_rpm
    F = Fg[None] + ((s / rep.speed_ref_rpm) ** 2)[:, None, None] * Fi[None]
    Omega = np.outer(s * 2 * np.pi / 60, orders)
    return F, Omega, harmonic_solve(stiffness_matrix(ch.k), ch.J, C, F, Omega)


def test_the_rigid_part_is_gone_per_order(six):
    """Σ J Θ_elastic = 0 at every speed and order (a complex identity), what was taken out
    is the rigid body's answer −Σ F / (Ω² Σ J) (the same angle at every mass; on the six
    only the major orders move it, the others' torques cancel), and the report's
    per-order amplitude is |Θ_elastic|."""
    J = six.chain.J
    F, Omega, theta = _complex_response(six)
    e = elastic_part(theta, J)
    scale = np.abs(theta).max()
    assert np.abs(e @ J).max() <= 1e-12 * scale * J.sum()
    rigid = theta - e
    np.testing.assert_allclose(rigid, rigid[..., :1] * np.ones(len(J)), rtol=0,
                               atol=1e-12 * scale)
    want = -F.sum(axis=-1) / (Omega ** 2 * J.sum())
    np.testing.assert_allclose(rigid[..., 0], want, rtol=1e-7, atol=1e-9 * np.abs(want).max())
    np.testing.assert_allclose(six.response.amplitude_by_order_deg, np.degrees(np.abs(e)),
                               rtol=1e-9, atol=1e-14)
    # the rigid swing was the larger part at the bottom of the range: about 1.9° at 800 rpm
    r = six.response
    assert r.speeds_rpm[0] == 800.0
    assert r.swing_deg[0, 0] == pytest.approx(1.9, abs=0.05)
    assert r.amplitude_deg[0, 0] < 0.25 * r.swing_deg[0, 0]


def test_free_end_amplitude_peaks_at_the_major_critical_speeds(six):
    """Inline six (majors: multiples of 3): the free-end mass's amplitude has a local
    maximum within one speed step of every critical speed of a major order in range, in
    the order's own amplitude; in the orders summed in time at mode 1's three (orders
    12, 9, 6: 1963, 2618, 3927 rpm).  Mode 2 by order 12 at 5783 rpm is a peak of its
    order (0.014°) but lies under the other orders (0.28° summed): no peak of the sum."""
    r, cs = six.response, six.critical
    s = r.speeds_rpm
    step = float(np.diff(s).max())
    assert step == 10.0

    def local_maxima(a):
        i = np.flatnonzero((a[1:-1] > a[:-2]) & (a[1:-1] > a[2:])) + 1
        return s[i]

    major = cs[cs["major"]]
    assert [(int(m), float(k)) for m, k in zip(major["mode"], major["order"])] == [
        (1, 6.0), (1, 9.0), (1, 12.0), (2, 12.0)]
    orders = list(r.orders)
    for mode, k, n in zip(major["mode"], major["order"], major["speed_rpm"]):
        peaks = local_maxima(r.amplitude_by_order_deg[:, orders.index(k), 0])
        assert np.abs(peaks - n).min() <= step, (mode, k, n, peaks)
    summed = local_maxima(r.amplitude_deg[:, 0])
    for n in major.loc[major["mode"] == 1, "speed_rpm"]:
        assert np.abs(summed - n).min() <= step, (n, summed)
    # the absolute angle, swing included, falls steadily through the low critical speed:
    # the resonance at 1963 rpm was hidden there
    assert np.abs(local_maxima(r.swing_deg[:, 0]) - 1963.3).min() > step
    # mode 2, order 12: its share at its critical speed is small beside the sum
    n2 = float(major.loc[major["mode"] == 2, "speed_rpm"].iloc[0])
    j = int(np.argmin(np.abs(s - n2)))
    assert r.amplitude_by_order_deg[j, orders.index(12.0), 0] < 0.1 * r.amplitude_deg[j, 0]


def test_the_columns_and_the_figure_are_the_elastic_amplitude(six):
    """theta_<mass>_deg is the elastic amplitude, swing_<mass>_deg the absolute one, the
    section torques unchanged (from the twists); the angles figure draws the elastic
    curves and its title has no caveat about the whole chain's swing."""
    tab = six.tables["torsion_response.csv"]
    r = six.response
    names = six.chain.names
    for i, name in enumerate(names):
        np.testing.assert_array_equal(tab[f"theta_{name}_deg"], r.amplitude_deg[:, i])
        np.testing.assert_array_equal(tab[f"swing_{name}_deg"], r.swing_deg[:, i])
    cols = list(tab.columns)
    assert cols.index(f"tau_{names[-2]}-{names[-1]}_MPa") < cols.index(f"swing_{names[0]}_deg")
    for lang, banned in (("en", ("swing", "whole chain")), ("ru", ("целого", "цепочк"))):
        _, figs = build_outputs(six, lang)
        ax = figs["torsion_angles"].axes[0]
        title = ax.get_title()
        assert title and not any(b in title for b in banned), title
        curves = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == len(r.speeds_rpm)]
        assert len(curves) == len(names)
        for i, ln in enumerate(curves):
            np.testing.assert_array_equal(ln.get_ydata(), r.amplitude_deg[:, i])
        assert ax.get_ylim()[1] < 1.0             # not 1.9°: the swing is not drawn
        for fig in figs.values():
            fig.clear()
