"""Bearing loads, wear diagrams and the rod model of a one-cylinder engine spec.

Takes the optional spec tables ``[bearings]`` and ``[rod]`` as read by :func:`engine.load`
(``study.bearings``, :mod:`engine.spec.inputs`; :func:`read_bearing_inputs` reads just
them) and composes :mod:`engine.bearings.loads`, :mod:`engine.bearings.wear` and
:mod:`engine.rodmodel` on the force table of :func:`engine.force_table` into one typed result,
:class:`BearingAnalysis`.  (A multi-cylinder crank train feeds the same array functions
with its own layout.)

``[bearings]`` keys (all optional):

``wear_half_angle_deg``
    Half-angle of the arc each load wears (default 60°, the textbooks').
``journal_positions_mm``
    The two main journals' axial positions relative to the crank-pin centre, e.g.
    ``[-60, 60]`` (default symmetric: each carries half the throw's loads).
``counterweight_kg_mm``
    m·r of the throw's counterweights together (both webs, symmetric about the pin
    centre) [kg·mm]; default none.
``counterweight_angle_deg``
    Their direction from the crank, in the direction of rotation (default 180: opposite
    the crank pin).

The crank's own rotating mass mк is ``[masses] crank_rotating_kg`` (0 if not given).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from crankbase.schema import SpecReader
from crankbase.validation import read_toml

from .loads import (Crankshaft, CrankshaftLoads, big_end_load, crank_pin_load,
                       crankshaft_loads, piston_pin_load)
from ..forces import crank_pin_resultant
from ..rodmodel import RigidRod, compare_rod_models
from ..spec import EngineSpecError
from ..spec.inputs import (BEARING_KEYS, BearingInputs, BearingOptions, bearing_options,
                          mass_parts, read_tables)
from .wear import WearDiagram, wear_diagram

__all__ = ["BEARING_KEYS", "BearingOptions", "bearing_options", "check_tables",
           "BearingInputs", "read_bearing_inputs", "BearingAnalysis", "bearing_analysis",
           "wear_table", "rod_bearing_table", "piston_mass"]

def check_tables(c, data):
    """Check the keys of ``[bearings]`` and ``[rod]`` of a spec file's dict, adding the
    problems to the checker ``c`` (:func:`engine.load` reads them itself, into
    ``study.bearings``)."""
    read_tables(c, data)


def read_bearing_inputs(path_or_dict, spec):
    """The ``[bearings]`` and ``[rod]`` tables of a spec file, for its loaded engine.

    :func:`engine.load` reads them with the rest of the file (``study.bearings``); this
    reads just these two tables, for ``spec`` (which may differ from the file's, e.g. a
    variant made with :func:`dataclasses.replace`).

    Parameters
    ----------
    path_or_dict : str, Path or dict
        The spec file (as given to :func:`engine.load`) or its dict.
    spec : EngineSpec
        The engine loaded from it (for the rigid rod's defaults and checks).

    Returns
    -------
    BearingInputs

    Raises
    ------
    EngineSpecError
        Every problem of the two tables.
    """
    data, _ = read_toml(path_or_dict)
    c = SpecReader()
    inputs = read_tables(c, data, spec)
    c.raise_if_any(EngineSpecError)
    return inputs


#: The note of a bearing analysis whose piston mass is unknown (the piston-pin load needs it).
NOTE_NO_PISTON_MASS = ("piston-pin load not computed: give the masses as parts "
                       "(piston_group_kg, rod_kg) or [rod] mass_kg")


def piston_mass(spec, rod: RigidRod | None = None):
    """mп: ``piston_group_kg`` (or per area) when the masses are given as parts, else the
    rigid rod's, else None (the piston-pin load then needs it). [kg]"""
    parts = mass_parts(spec)
    if parts is not None:
        return parts[0]
    return rod.m_piston if rod is not None else None


@dataclass
class BearingAnalysis:
    """Bearing loads of a one-cylinder engine over its cycle.

    Attributes
    ----------
    loads : CrankshaftLoads
        Crank pin (one throw) and the two main journals, journal torques.
    pin_wear : WearDiagram
        Crank pin, crank frame (contact opposite to Rшш).
    journal_wear : list of WearDiagram
        Main journals, crank frame (contact along the journal load).
    rod_bearings : pandas.DataFrame
        ``alpha_deg``, big end ``Rbe_along_N``, ``Rbe_across_N``, ``Rbe_N``,
        ``Rbe_angle_deg`` (rod frame) and piston pin ``Pp_axial_N``, ``Pp_side_N``,
        ``Pp_N`` (NaN when the piston mass is unknown).
    rod_model : str
        "two-mass" or "rigid".
    rod_comparison : RodModelComparison or None
    options : BearingOptions
    m_piston : float or None
    """

    loads: CrankshaftLoads
    pin_wear: WearDiagram
    journal_wear: list
    rod_bearings: object
    rod_model: str
    rod_comparison: object
    options: BearingOptions
    m_piston: float | None
    notes: list = field(default_factory=list)


def rod_bearing_table(table, spec, m_piston, phase_deg=0.0):
    """Big-end (rod frame) and piston-pin loads from a force table (DataFrame) whose rows
    are at the crankshaft angles θ of a cylinder with phase ``phase_deg`` (α = θ − φ)."""
    import pandas as pd

    a = table["alpha_deg"].to_numpy()
    along, across = big_end_load(table["K_N"], table["T_N"], table["Kr_N"], a - phase_deg,
                                 table["beta_deg"])
    R_be, angle = crank_pin_resultant(across, along)     # the same rule in the rod frame
    out = dict(alpha_deg=a, Rbe_along_N=along, Rbe_across_N=across,
               Rbe_N=R_be, Rbe_angle_deg=angle)
    if m_piston is not None and spec.mj > 0:
        j_used = -table["Pj_N"].to_numpy() / spec.mj
        ax, side, mag = piston_pin_load(table["dPg_N"], j_used, m_piston, table["N_N"])
    else:
        ax = side = mag = np.full(len(a), np.nan)
    out.update(Pp_axial_N=ax, Pp_side_N=side, Pp_N=mag)
    return pd.DataFrame(out)


def _shaft(spec, opt):
    m_k = spec.m_crank_rot or 0.0
    cw = ((opt.counterweight_mr, opt.counterweight_angle_deg, 0.0, 0),) \
        if opt.counterweight_mr > 0 else ()
    return Crankshaft((0.0,), (0.0,), tuple(opt.journal_positions), (m_k,), cw)


def bearing_analysis(spec, table, inputs: BearingInputs | None = None, n_points=360):
    """Bearing loads, wear diagrams and the rod model of a one-cylinder spec.

    Parameters
    ----------
    spec : EngineSpec
    table : pandas.DataFrame
        :func:`engine.force_table` over the whole cycle, sorted, preferably on a fine grid
        (:func:`engine.fine_angles`): the statistics and wear integrate over its rows.
    inputs : BearingInputs, optional
        From :func:`read_bearing_inputs` (default: the defaults and the two-mass rod).
    n_points : int
        Points of the wear diagrams around the circumference.

    Returns
    -------
    BearingAnalysis
    """
    inputs = inputs if inputs is not None else BearingInputs()
    opt, model, rod = inputs.options, inputs.rod_model, inputs.rod
    a = table["alpha_deg"].to_numpy()
    Kp, Tp = crank_pin_load(table["K_N"].to_numpy(), table["T_N"].to_numpy(),
                            spec.m_rod_rot, spec.R, spec.omega)
    loads = crankshaft_loads(a, _shaft(spec, opt), Kp[None, :], Tp[None, :], spec.R,
                             spec.omega, spec.cycle_deg, pin_Kr=[spec.Kr])
    h = opt.wear_half_angle_deg
    pins = loads.crankpins
    pin_wear = wear_diagram("pin 1", a, pins["psi_1_deg"].to_numpy() + 180.0,
                            pins["R_1_N"].to_numpy(), h, n_points)
    jr = loads.journals
    jw = [wear_diagram(f"journal {j}", a, jr[f"psi_{j}_deg"].to_numpy(),
                       jr[f"R_{j}_N"].to_numpy(), h, n_points)
          for j in range(1, len(loads.shaft.z_journal) + 1)]
    mp = piston_mass(spec, rod)
    notes = [] if mp is not None else [NOTE_NO_PISTON_MASS]
    comp = compare_rod_models(spec, rod, table=table) \
        if model == "rigid" and rod is not None else None
    return BearingAnalysis(loads, pin_wear, jw, rod_bearing_table(table, spec, mp), model,
                           comp, opt, mp, notes)


def wear_table(diagrams):
    """One DataFrame of wear diagrams: ``phi_deg`` then ``wear_<name>_Ndeg`` (name with
    spaces as underscores, e.g. ``wear_pin_1_Ndeg``)."""
    import pandas as pd

    cols = {"phi_deg": diagrams[0].phi_deg}
    for d in diagrams:
        cols[f"wear_{d.name.replace(' ', '_')}_Ndeg"] = d.wear
    return pd.DataFrame(cols)
