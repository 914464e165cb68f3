"""The RPR group routine (linkage.groups.rpr, the slotted lever) against a published
problem with its printed answer, and its Coriolis term by hand.

The published problem ("В кулисно-ползунном механизме (рис. 2.3.11) стержень 2 движется
влево замедленно. В момент времени, когда угол α = 30°, скорость и ускорение его равны
v2 = 1 м/с, a2 = 1 м/с². Определить угловую скорость и угловое ускорение кулисы 1 в
заданном положении механизма, если h = 20 см. Ответ: ω1 = 1,25 рад/с, ε1 = 4,16 рад/с²",
https://einsteins.ru/subjects/gidravlika/zadachi-gidravlika/resheno-410): a rod moving
along a straight line at the distance h from the lever's pivot carries a pin that slides
in the lever's slot; α is the angle between the slot and the rod's line.  With the pin
A = (h·cot α, h) above the pivot C = 0, moving left (v = −1 m/s) and slowing down
(a = +1 m/s²), the lever turns counter-clockwise, θ = α: ω = −v·sin²α/h = 1.25 rad/s and
ε = −a·sin²α/h + 2v²·sin³α·cos α/h² = 4.1627 rad/s², the printed 1,25 and 4,16.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from linkage import groups as g


def _published(assembly):
    h, alpha = 0.20, math.radians(30.0)
    A = g.PointMotion(complex(h / math.tan(alpha), h), complex(-1.0, 0.0), complex(1.0, 0.0))
    C = g.PointMotion(0j, 0j, 0j)
    return g.rpr(A, C, 0.0, assembly)


@pytest.mark.parametrize("assembly", [1, -1])
def test_published_slotted_lever_answer(assembly):
    s = _published(assembly)
    # printed to two decimals: ω1 = 1,25 rad/s, ε1 = 4,16 rad/s² (ccw with this layout)
    assert round(float(s.lever.omega), 2) == 1.25
    assert round(float(s.lever.eps), 2) == 4.16
    assert float(s.lever.eps) == pytest.approx(2 * 0.125 * math.cos(math.radians(30)) / 0.04
                                               - 0.25 / 0.2, rel=1e-12)
    # the block turns with the lever
    assert float(s.block.omega) == float(s.lever.omega)
    assert float(s.block.eps) == float(s.lever.eps)


def test_coriolis_and_relative_motion_by_hand():
    """The same instant: the pin's velocity splits into the lever point's (⟂ slot,
    ω·|CA|) and the sliding velocity along the slot; its acceleration into the lever
    point's, the sliding acceleration and the Coriolis term 2ω·v_rel turned 90° ccw."""
    s = _published(1)
    h, alpha = 0.20, math.radians(30.0)
    e = complex(math.cos(alpha), math.sin(alpha))
    CA = h / math.sin(alpha)
    v_rel = (-1.0 + 0j) * e.conjugate()               # v_A in the slot's frame
    assert float(s.v_rel) == pytest.approx(v_rel.real, rel=1e-12)     # −cos α
    assert float(s.s) == pytest.approx(CA, rel=1e-12)
    w = float(s.lever.omega)
    assert w * CA == pytest.approx(v_rel.imag, rel=1e-12)             # sin α
    cor = complex(s.coriolis.x, s.coriolis.y)
    assert cor == pytest.approx(2 * w * v_rel.real * 1j * e, rel=1e-12)
    # a_A = a_lever point + a_rel·e + Coriolis
    A3 = s.A_lever
    total = complex(A3.a.x, A3.a.y) + float(s.a_rel) * e + cor
    assert total == pytest.approx(1.0 + 0j, abs=1e-12)


def test_offset_slot_and_arrays():
    """A slot offset from the pivot: positions satisfy A − C = (s + i·offset)·e on both
    branches, vectorised over positions."""
    phi = np.linspace(0.0, 2 * math.pi, 13)
    cr = g.crank(phi, 3.0, -2.0)
    A = cr.point(0.1)
    C = g.PointMotion(-0.3j, 0j, 0j)
    for asm in (1, -1):
        s = g.rpr(A, C, 0.04, asm)
        e = s.lever.e
        back = C.z + e * g.Vec(s.s, 0.04 + 0.0 * s.s)
        np.testing.assert_allclose(back.x, A.z.x, atol=1e-14)
        np.testing.assert_allclose(back.y, A.z.y, atol=1e-14)
        assert np.all(np.sign(s.s) == asm)


def test_block_and_lever_share_one_angle():
    """The block slides in the lever's slot: one angle θ for both, that of the slot's
    direction e (the block's is the lever's, computed once), on both branches and with
    an offset slot; at the published instant the slot points at 30° (assembly +1) or at
    30° − 180° (−1: the slot's x axis points from A towards C)."""
    for asm, want in ((1, 30.0), (-1, -150.0)):
        s = _published(asm)
        assert math.degrees(float(s.block.theta)) == pytest.approx(want, abs=1e-12)
        assert float(s.block.theta) == float(s.lever.theta)
    phi = np.linspace(0.0, 2 * math.pi, 13)
    A = g.crank(phi, 3.0, -2.0).point(0.1)
    for asm in (1, -1):
        s = g.rpr(A, g.PointMotion(-0.3j, 0j, 0j), 0.04, asm)
        e = s.lever.e
        np.testing.assert_array_equal(s.block.theta, np.arctan2(e.y, e.x))
        np.testing.assert_array_equal(s.lever.theta, s.block.theta)
