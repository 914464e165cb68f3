"""Quantities of the course tables that follow from the solved columns.

The course project tabulates, per position, the speeds and accelerations of the points
(lengths of the vectors of the velocity and acceleration plans), the relative motion of B
about A and about C (VBA = ω3·lAB, aBA^n = ω3²·lAB, aBA^t = ε3·lAB, ...), the force inputs
of the kinetostatics (weights Gi = mi·g, inertia forces Fui = −mi·aSi, inertia moments
Mui = −JSi·εi) and the magnitudes of the reactions.  :func:`fill_derived` computes them
from the columns the group routines have filled (chunk by chunk, in
:func:`linkage.analyze`).  The inertia loads are those of
:func:`linkage.groups.inertia_load`, the model that enters the kinetostatics; the tests
hold them, with the reactions, to the equilibrium of every link.
"""
from __future__ import annotations

import numpy as np

from . import groups as g
from .columns import point_names
from .course import course_of
from .spec import LINK_NUMBER, MechanismSpec

__all__ = ["fill_derived"]


def _norm(x, y, out, t):
    """|(x, y)| into ``out`` (``t`` scratch): sqrt(x² + y²), out= throughout (the
    chunks stay in cache; ``np.hypot``'s overflow care is not needed here)."""
    np.multiply(x, x, out=out)
    np.multiply(y, y, out=t)
    np.add(out, t, out=out)
    np.sqrt(out, out=out)


def fill_derived(spec: MechanismSpec, K, F, scratch=None):
    """Fill the derived columns of one block of rows, in place.

    Parameters
    ----------
    spec : MechanismSpec
    K, F : dict of str → ndarray
        Kinematics and force columns (equal-length arrays of the same rows); the base
        columns must be filled, the derived ones (``columns.derived_*_columns``) are
        overwritten.
    scratch : ndarray, optional
        A float array of the rows' length to work in (allocated when not given).

    Notes
    -----
    Fui = −mi·aSi and Mui = −JSi·εi come from :func:`linkage.groups.inertia_load`, the
    model the kinetostatics applies, evaluated per component to stay in real arithmetic.
    """
    n = len(K["phi_deg"])
    t = np.empty(n) if scratch is None else scratch
    for p in point_names(spec):
        _norm(K[f"{p}_vx_m_s"], K[f"{p}_vy_m_s"], K[f"{p}_v_m_s"], t)
        _norm(K[f"{p}_ax_m_s2"], K[f"{p}_ay_m_s2"], K[f"{p}_a_m_s2"], t)
    for name, pivot, w, e, link in course_of(spec).relative:
        length = getattr(spec, link)           # |AB| or |CB|
        # VBA = |ω3|·lAB, aBAⁿ = ω3²·lAB, aBAᵗ = |ε3|·lAB; |aB − aA| from the columns
        np.abs(K[w], out=t)
        np.multiply(t, length, out=K[f"v_{name}_m_s"])
        np.multiply(K[w], K[w], out=t)
        np.multiply(t, length, out=K[f"a_{name}_n_m_s2"])
        np.abs(K[e], out=t)
        np.multiply(t, length, out=K[f"a_{name}_t_m_s2"])
        if pivot is None:                      # C is fixed: B's own acceleration
            np.copyto(K[f"a_{name}_m_s2"], K["B_a_m_s2"])
        else:
            out = K[f"a_{name}_m_s2"]
            np.subtract(K["B_ax_m_s2"], K[f"{pivot}_ax_m_s2"], out=out)
            np.multiply(out, out, out=out)
            np.subtract(K["B_ay_m_s2"], K[f"{pivot}_ay_m_s2"], out=t)
            np.multiply(t, t, out=t)
            np.add(out, t, out=out)
            np.sqrt(out, out=out)

    eps = {"crank": spec.epsilon, "coupler": K["eps3_rad_s2"],
           "rocker": K.get("eps4_rad_s2"), "slider": 0.0}
    for lname in spec.link_names:
        ls, i = spec.links[lname], LINK_NUMBER[lname]
        F[f"G{i}_N"].fill(ls.mass * spec.gravity)
        # the model's d'Alembert loads, per component (inertia_load is linear in a_S)
        fx, mu = g.inertia_load(K[f"S{i}_ax_m_s2"], eps[lname], ls.mass, ls.inertia)
        fy, _ = g.inertia_load(K[f"S{i}_ay_m_s2"], 0.0, ls.mass, 0.0)
        np.add(fx, 0.0, out=F[f"Fu{i}_x_N"])     # + 0.0: no −0.0 when m = 0
        np.add(fy, 0.0, out=F[f"Fu{i}_y_N"])
        np.multiply(K[f"S{i}_a_m_s2"], ls.mass, out=F[f"Fu{i}_N"])
        if lname != "slider":                      # a slider does not turn
            np.add(mu, 0.0, out=F[f"Mu{i}_Nm"])
    for r in ("R12", "R23", "R43", "R14"):
        _norm(F[f"{r}_x_N"], F[f"{r}_y_N"], F[f"{r}_N"], t)
