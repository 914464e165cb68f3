"""linkage.course: the four-bar's documented names declared once as data (issue #20).

Every name the course gives a crank-rocker or crank-slider (the output's columns, the
reactions Rij, the frame pair's extra columns, the resistance) is checked against an
independent route: the same mechanism written as a chain spec (``kind = "chain"``,
tests/test_linkage_chain_spec.py's ratchet and press) and analysed by
:func:`linkage.chain_analysis.analyze_chain`, whose columns carry the chain's own names
(``theta_rocker_deg``, ``Rx_rocker_coupler_N`` …).  A swapped pair (R34 for R43), a wrong
scale (radians for degrees) or a component taken along the wrong axis fails here.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import linkage
from crankbase.resources import example_path
from linkage.columns import force_columns, kinematics_columns
from linkage.course import COURSES, REACTIONS, course_of
from test_linkage_chain_spec import _press_chain, _ratchet_chain

CASES = {"ratchet.toml": _ratchet_chain, "press.toml": _press_chain}


def _close(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(1.0, float(np.max(np.abs(b))))
    assert np.max(np.abs(a - b)) <= 1e-9 * scale, np.max(np.abs(a - b))


def _chain_name(i, j, columns):
    """The chain's column of the force of link i on link j and its sign (the chain names
    each pair once, in one order)."""
    if f"Rx_{i}_{j}_N" in columns:
        return f"{i}_{j}", 1.0
    assert f"Rx_{j}_{i}_N" in columns, (i, j)
    return f"{j}_{i}", -1.0


@pytest.mark.parametrize("example", sorted(CASES))
def test_course_names_are_the_chains_quantities(example):
    old = linkage.analyze(example_path(example))
    new = linkage.analyze(CASES[example]())
    course = course_of(old.spec)
    out = course.output
    K, F, NK, NF = old.kinematics, old.forces, new.kinematics, new.forces
    # the output's coordinate, rate and acceleration
    if course.angular:
        chain_cols = (f"theta_{out}_deg", f"omega_{out}_rad_s", f"eps_{out}_rad_s2")
    else:
        chain_cols = (f"s_{out}_m", f"v_{out}_m_s", f"a_{out}_m_s2")
    for doc, ours in zip(course.output_columns, chain_cols):
        _close(K[doc], NK[ours])
    # the reactions Rij: the force of link i on link j, by the textbook's numbers
    number = {"1": "frame", "2": "crank", "3": "coupler", "4": out}
    assert [stem for stem, _ in REACTIONS] == ["R12", "R23", "R43", "R14"]
    for stem, _ in REACTIONS:
        tag, sign = _chain_name(number[stem[1]], number[stem[2]], NF.columns)
        _close(F[f"{stem}_x_N"], sign * NF[f"Rx_{tag}_N"])
        _close(F[f"{stem}_y_N"], sign * NF[f"Ry_{tag}_N"])
    # the frame pair's extra columns
    for col, attr in course.frame_pair:
        if attr in ("n", "t"):       # along and across the rocker (the chain's Rn, Rt)
            _close(F[col], NF[f"R{attr}_frame_{out}_N"])
        elif attr == "couple":
            _close(F[col], NF[f"Mp_frame_{out}_Nm"])
        else:                        # the guide's normal force: R14 · (i·u)
            g = old.spec.ground_angle
            n = complex(-math.sin(g), math.cos(g))
            _close(F[col], F["R14_x_N"] * n.real + F["R14_y_N"] * n.imag)
    _close(F[course.resistance_column], NF[course.resistance_column])
    assert np.any(np.abs(F[course.resistance_column]) > 0)      # a loaded example


@pytest.mark.parametrize("kind", sorted(COURSES))
def test_every_course_name_is_a_documented_column(kind):
    """The course's names are the tables' columns (one declaration, no stray name)."""
    spec = linkage.load_spec(example_path({"crank-rocker": "ratchet.toml",
                                           "crank-slider": "press.toml"}[kind]))
    course = course_of(spec)
    assert course.kind == kind == spec.kind
    assert course.output == spec.link_names[2]
    kcols, fcols = kinematics_columns(spec), force_columns(spec)
    assert set(course.output_columns) <= set(kcols)
    assert {c for c, _ in course.frame_pair} | {course.resistance_column} <= set(fcols)
    for name, *_ in course.relative:
        assert f"v_{name}_m_s" in kcols and f"a_{name}_t_m_s2" in kcols
    summary = linkage.analyze(spec).summary
    for name in course.summary_fields:
        assert getattr(summary, name) is not None
