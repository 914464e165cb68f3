"""Bearing loads of a whole engine: every crank pin with its rods, the main journals, the
torques they carry and their wear diagrams, from the placed cylinders of a crank train.

Array interface (independent of how the layout is obtained): each cylinder is given by
its bank angle γ, its phase φ, its throw and its axial position; each throw by its
direction at θ = 0 and its axial position.  Every cylinder's forces come from the same
one-cylinder model, :func:`engine.force_table` at its own bank angle and phase; the rods
of a throw are summed in its crank frame (:func:`engine.bearings.crank_pin_load`) and the
crankshaft is shared out over the main journals by :func:`engine.bearings.crankshaft_loads`
(each rod at its own axial position).  Conventions: :mod:`engine.bearings`.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import Problem, Text
from crankbase.tolerances import PHASE_MATCH_DEG

from .analysis import (NOTE_NO_PISTON_MASS, BearingInputs, piston_mass,
                           rod_bearing_table)
from .loads import BearingInputError, Crankshaft, CrankshaftLoads, crankshaft_loads
from ..forces import force_table
from .wear import wear_diagram

__all__ = ["Cylinder", "EngineBearings", "engine_bearings", "full_support_journals",
           "layout_cylinders"]



@dataclass(frozen=True)
class Cylinder:
    """A placed cylinder: bank angle γ [deg], phase φ [deg] (its α = θ − φ), its throw
    (0-based) and the axial position of its rod on the pin [m]."""

    bank_deg: float
    phase_deg: float
    throw: int
    z: float


def layout_cylinders(lay):
    """The cylinders, throw directions and throw positions of a crank-train layout
    (:func:`engine.train.layout`: θ is cylinder 1's α, throw angles from throw 1, bank
    angles, phases, throws and axial positions per cylinder).

    Returns
    -------
    cylinders : tuple of Cylinder
    throw_dir_deg : ndarray
        γ₁ + each throw's angle from throw 1. [deg]
    z_throw : ndarray
        [m]
    """
    df = lay.cylinders
    cyl = tuple(Cylinder(float(g), float(p), int(k) - 1, float(z) * 1e-3)
                for g, p, k, z in zip(df["bank_angle_deg"], df["phase_deg"], df["throw"],
                                      df["axial_position_mm"]))
    tau = float(df["bank_angle_deg"].iloc[0]) + np.asarray(lay.throw_angles_deg, float)
    return cyl, tau, np.asarray(lay.throw_z, float)


def full_support_journals(z_throw, spacing=None):
    """Main-journal positions of a full-support crankshaft: one between every two
    neighbouring throws (midway) and one beyond each end throw, half a spacing out
    (spacing: the smallest distance between throws, or ``spacing``; 0.1 m for one
    throw — only ratios matter to the lever rule). [m]"""
    z = np.unique(np.asarray(z_throw, float))
    if spacing is None:
        spacing = float(np.min(np.diff(z))) if len(z) > 1 else 0.1
    mids = 0.5 * (z[1:] + z[:-1])
    return np.concatenate([[z[0] - spacing / 2], mids, [z[-1] + spacing / 2]])


@dataclass
class EngineBearings:
    """Bearing loads of a whole engine over the crankshaft angle θ.

    Attributes
    ----------
    loads : CrankshaftLoads
        Crank pins (per throw), main journals, journal torques, their statistics.
    pin_wear, journal_wear : list of WearDiagram
    rod_bearings : pandas.DataFrame
        Big end and piston pin of cylinder 1 over θ (every rod's are the same, shifted by
        its phase).
    cylinders : tuple of Cylinder
    options : BearingOptions
    m_piston : float or None
    rod_model : str
    rod_comparison : RodModelComparison or None
        The rigid rod beside the two-mass one (the same for every cylinder).
    notes : list of str
    """

    loads: CrankshaftLoads
    pin_wear: list
    journal_wear: list
    rod_bearings: object
    cylinders: tuple
    options: object
    m_piston: float | None
    rod_model: str = "two-mass"
    rod_comparison: object = None
    notes: list = field(default_factory=list)


def engine_bearings(spec, theta_deg, cylinders, throw_dir_deg, z_throw, *,
                    z_journal=None, m_crank_rot=None, counterweights=(), inputs=None,
                    n_points=360):
    """Crank-pin and main-journal loads, journal torques and wear of a whole engine.

    Parameters
    ----------
    spec : EngineSpec
        The one-cylinder model every cylinder uses.
    theta_deg : array_like
        Crankshaft angles over one cycle, sorted (cylinder 1's α when its phase is 0). [deg]
    cylinders : sequence of Cylinder
    throw_dir_deg : sequence of float
        Direction of each throw from the vertical at θ = 0, in the direction of rotation
        (γ₁ + its angle from throw 1 when θ is cylinder 1's α). [deg]
    z_throw : sequence of float
        Axial position of each throw's middle. [m]
    z_journal : sequence of float, optional
        Main-journal positions; default :func:`full_support_journals`. [m]
    m_crank_rot : float, optional
        mк of each throw (default the spec's ``crank_rotating_kg`` or 0). [kg]
    counterweights : sequence of (z [m], m·r [kg·m], angle [deg])
        Direction from throw 1, in the direction of rotation.
    inputs : BearingInputs, optional
        Wear half-angle (its journal positions and counterweight are for one cylinder and
        are not used here).
    n_points : int
        Points of the wear diagrams.

    Returns
    -------
    EngineBearings

    Raises
    ------
    BearingInputError
        A cylinder whose phase does not match its bank angle and throw
        (φ ≢ γ − τ mod 360°), a throw index out of range, or one-cylinder ``[bearings]``
        keys (journal positions, counterweight).
    """
    inputs = inputs if inputs is not None else BearingInputs()
    one_cylinder_keys = [k for k in inputs.options.given
                         if k in ("journal_positions_mm", "counterweight_kg_mm",
                                  "counterweight_angle_deg")]
    if one_cylinder_keys:
        raise BearingInputError([Problem(
            f"bearings.{k}", Text("errors.engine.train_bearings.only_for_one"))
            for k in one_cylinder_keys])
    th = np.asarray(theta_deg, float)
    tau = np.asarray(throw_dir_deg, float)
    nt = len(tau)
    cyl = tuple(cylinders)
    for i, c in enumerate(cyl, start=1):
        if not 0 <= c.throw < nt:
            raise BearingInputError(Problem(f"cylinder {i}",
                                            Text("errors.engine.train_bearings.throw_does_not",
                                                 {"value": c.throw + 1, "nt": nt})))
        lag = (c.bank_deg - tau[c.throw] - c.phase_deg) % 360.0
        if min(lag, 360.0 - lag) > PHASE_MATCH_DEG:
            raise BearingInputError(Problem(
                f"cylinder {i}", Text("errors.engine.train_bearings.phase_does_not",
                                      {"phase_deg": c.phase_deg, "bank_deg": c.bank_deg,
                                       "value": c.throw + 1, "value2": tau[c.throw]})))
    tables = [force_table(spec, th, bank_deg=c.bank_deg, phase_deg=c.phase_deg)
              for c in cyl]
    K = np.zeros((nt, th.size))
    T = np.zeros((nt, th.size))
    Kr = np.zeros(nt)
    rods = [[] for _ in range(nt)]
    for c, t in zip(cyl, tables):
        k_rod = (t["K_N"] + t["Kr_N"]).to_numpy()
        K[c.throw] += k_rod
        T[c.throw] += t["T_N"].to_numpy()
        Kr[c.throw] += spec.Kr
        rods[c.throw].append((k_rod, t["T_N"].to_numpy(), c.z))
    zt = np.asarray(z_throw, float)
    zj = full_support_journals(zt) if z_journal is None else np.asarray(z_journal, float)
    mk = (spec.m_crank_rot or 0.0) if m_crank_rot is None else m_crank_rot
    shaft = Crankshaft(tuple(tau.tolist()), tuple(zt.tolist()), tuple(zj.tolist()),
                       (float(mk),) * nt,
                       tuple((mr, ang, z, 0) for z, mr, ang in counterweights))
    loads = crankshaft_loads(th, shaft, K, T, spec.R, spec.omega, spec.cycle_deg,
                             rod_z=rods, pin_Kr=Kr)
    h = inputs.options.wear_half_angle_deg
    p, j = loads.crankpins, loads.journals
    pin_wear = [wear_diagram(f"pin {k}", th, p[f"psi_{k}_deg"].to_numpy() + 180.0,
                             p[f"R_{k}_N"].to_numpy(), h, n_points) for k in range(1, nt + 1)]
    jw = [wear_diagram(f"journal {k}", th, j[f"psi_{k}_deg"].to_numpy(),
                       j[f"R_{k}_N"].to_numpy(), h, n_points) for k in range(1, len(zj) + 1)]
    mp = piston_mass(spec, inputs.rod)
    rb = rod_bearing_table(tables[0], spec, mp, phase_deg=cyl[0].phase_deg)
    notes = [] if mp is not None else [NOTE_NO_PISTON_MASS]
    comp = None
    if inputs.rod_model == "rigid" and inputs.rod is not None:
        from ..rodmodel import compare_rod_models
        comp = compare_rod_models(spec, inputs.rod, th)
    return EngineBearings(loads, pin_wear, jw, rb, cyl, inputs.options, mp,
                          inputs.rod_model, comp, notes)
