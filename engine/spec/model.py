"""The engine spec's data classes: the inputs, validated once, in SI.

A spec is a TOML file (or an equivalent dict) with the tables ``[engine]``, ``[masses]``,
``[pressure]`` (exactly one source of the indicator diagram) and ``[table]``, read by
:func:`engine.load` (:mod:`engine.spec.loading`, through the schema
:mod:`engine.schema`); unknown keys are errors.

:class:`EngineSpec` holds the physical inputs only (SI inside: m, kg, Pa; the speed in rpm as
given); everything derived — R, L or λ, ω, Fп, Vh, mj, mш.к, Kr.ш — is a property computed
from them, so ``dataclasses.replace(spec, speed_rpm=3000)`` gives the right table.  The
presentation settings of the report (table step, extra rows, force scale μP) are a
separate :class:`TableSettings`; the report language is an argument of the report itself.

Validated once: the loader checks a file's keys (naming them as the file does, with their
units); an object built directly (``EngineSpec(...)``, ``dataclasses.replace``) is checked
by its own ``__post_init__``, which the loader skips (:func:`loaded`) because it has
checked the same things already.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей. 4-е изд.
   М.: Высшая школа, 2008, гл. "Динамика кривошипно-шатунного механизма": the dynamic model
   with mj = mп + mш.п and mш.к, mш.п ≈ 0.275·mш, masses per unit piston area; Kr.ш.
"""
from __future__ import annotations

import contextlib
import contextvars
import math
from dataclasses import dataclass, field
from numbers import Integral
from pathlib import Path

from crankbase.errors import Problem, SpecError, Text
from crankbase.schema import MAX_CYLINDERS

from ..indicator import CycleSpec, PressureTable
from ..kinematics import piston_travel
from ..schema import (ARRANGEMENTS, COUNTERWEIGHT_DESIGNS, MASS_WAYS, PRESSURE_UNITS,
                      ROD_SMALL_END_FRACTION, TABLE_FORMS)
from .inputs import BearingInputs
from .torsion_inputs import TorsionInputs

__all__ = ["EngineSpec", "TableSettings", "EngineStudy", "CrankTrain", "Counterweight",
           "ARRANGEMENTS", "COUNTERWEIGHT_DESIGNS", "TABLE_FORMS", "CycleSpec",
           "PressureTable", "EngineSpecError", "PRESSURE_UNITS", "ROD_SMALL_END_FRACTION",
           "MASS_WAYS", "loaded"]

_LOADED = contextvars.ContextVar("engine_spec_loaded", default=False)


@contextlib.contextmanager
def loaded():
    """Inside this block the data classes skip their own checks: the loader has checked
    every key of the file already (validate once)."""
    token = _LOADED.set(True)
    try:
        yield
    finally:
        _LOADED.reset(token)


class EngineSpecError(SpecError):
    """An engine spec or an argument of an engine function is invalid (a
    :class:`crankbase.errors.SpecError`, so a ValueError); each problem names its key."""


def _finite(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) \
        and math.isfinite(value)


@dataclass(frozen=True)
class EngineSpec:
    """The physical inputs of one cylinder's crank mechanism (SI; inputs only).

    Attributes
    ----------
    name : str
    strokes : int
        4 (cycle 0…720°, α = 0 at the TDC that starts intake) or 2 (0…360°).
    cylinders : int
        Number of cylinders.
    bore, stroke : float
        Cylinder bore D and stroke S = 2R (twice the crank radius). [m]
    rod_ratio, rod_length : float or None
        Exactly one is given: λ = R/Lш [-] or Lш [m].
    speed_rpm : float
        Crankshaft speed n. [rpm]
    p0 : float
        Crankcase pressure. [Pa]
    acceleration : str
        "two-term" (j = Rω²(cos α + λ cos 2α)) or "exact" (from the RRP dyad).
    pressure : PressureTable or CycleSpec
        The indicator diagram: tabulated (inline or from a CSV file) or computed from the
        thermal calculation.
    compression_ratio : float or None
        ε as given in ``[engine]`` (a computed diagram has its own; see :attr:`epsilon`).
    pin_offset : float
        Piston-pin offset e (désaxé), + towards the direction of rotation at TDC
        (:mod:`engine.kinematics`). [m]
    reciprocating_kg, rod_rotating_kg : float or None
        mj and mш.к given directly. [kg]
    piston_group_kg, rod_kg : float or None
        mп and mш (the rod is split by ``rod_small_end_fraction``). [kg]
    piston_group_kg_m2, rod_kg_m2 : float or None
        The same per unit piston area. [kg/m²]
    rod_small_end_fraction : float
        mш.п/mш (default 0.275 [1]_). [-]
    crank_rotating_kg : float or None
        Unbalanced rotating mass of one crank throw mк, reduced to the crank radius. [kg]
    source_path : Path or None
        The spec file (provenance only; not compared).
    """

    bore: float
    stroke: float
    speed_rpm: float
    pressure: PressureTable | CycleSpec
    rod_ratio: float | None = None
    rod_length: float | None = None
    name: str = "engine"
    strokes: int = 4
    cylinders: int = 1
    p0: float = 1e5
    acceleration: str = "two-term"
    compression_ratio: float | None = None
    pin_offset: float = 0.0
    reciprocating_kg: float | None = None
    rod_rotating_kg: float | None = None
    piston_group_kg: float | None = None
    rod_kg: float | None = None
    piston_group_kg_m2: float | None = None
    rod_kg_m2: float | None = None
    rod_small_end_fraction: float = ROD_SMALL_END_FRACTION
    crank_rotating_kg: float | None = None
    source_path: Path | None = field(default=None, compare=False)

    def __post_init__(self):
        if _LOADED.get():
            return
        problems = []

        def bad(key, msg):
            problems.append(Problem(key, msg))

        if isinstance(self.cylinders, bool) or not isinstance(self.cylinders, Integral) \
                or not 1 <= self.cylinders <= MAX_CYLINDERS:
            bad("cylinders", f"got {self.cylinders!r:.40}; must be a whole number from 1 "
                             f"to {MAX_CYLINDERS}")

        for key in ("bore", "stroke", "speed_rpm"):
            v = getattr(self, key)
            if not (_finite(v) and v > 0):
                bad(key, f"got {v!r}; must be a finite number > 0")
        if self.strokes not in (2, 4):
            bad("strokes", f"got {self.strokes!r}; valid: 4, 2")
        if self.acceleration not in ("two-term", "exact"):
            bad("acceleration", f"got {self.acceleration!r}; valid: 'two-term', 'exact'")
        if not (_finite(self.p0) and self.p0 >= 0):
            bad("p0", f"got {self.p0!r}; must be a finite number >= 0")
        if (self.rod_ratio is None) == (self.rod_length is None):
            bad("rod_ratio", "give exactly one of rod_ratio and rod_length")
        elif self.rod_ratio is not None and not (_finite(self.rod_ratio)
                                                 and 0 < self.rod_ratio < 1):
            bad("rod_ratio", f"got {self.rod_ratio!r}; must be > 0 and < 1")
        elif self.rod_length is not None and not (
                _finite(self.rod_length) and _finite(self.stroke)
                and self.rod_length > self.stroke / 2):
            bad("rod_length", f"got {self.rod_length!r}; must be > the crank radius")
        if not _finite(self.pin_offset):
            bad("pin_offset", f"got {self.pin_offset!r}; must be a finite number")
        elif not problems and not abs(self.pin_offset) < self.L - self.R:
            bad("pin_offset", f"got {self.pin_offset!r} m; |e| must be < Lш − R = "
                              f"{self.L - self.R:.6g} m for the crank to turn fully")
        given = [w for w, keys in MASS_WAYS.items()
                 if any(getattr(self, k) is not None for k in keys)]
        if len(given) != 1:
            bad("masses", "give the masses exactly one way: "
                + " / ".join(" + ".join(k) for k in MASS_WAYS.values()))
        else:
            for k in MASS_WAYS[given[0]]:
                v = getattr(self, k)
                if not (_finite(v) and v >= 0):
                    bad(k, f"got {v!r}; must be a finite number >= 0")
        if not (_finite(self.rod_small_end_fraction)
                and 0 <= self.rod_small_end_fraction <= 1):
            bad("rod_small_end_fraction", f"got {self.rod_small_end_fraction!r}; must be "
                                          ">= 0 and <= 1")
        if not isinstance(self.pressure, (PressureTable, CycleSpec)):
            bad("pressure", f"must be a PressureTable or a CycleSpec, got "
                            f"{type(self.pressure).__name__}")
        if problems:
            raise EngineSpecError(problems)

    # ---- geometry and speed
    @property
    def R(self) -> float:
        """Crank radius R = S/2. [m]"""
        return self.stroke / 2.0

    @property
    def L(self) -> float:
        """Connecting-rod length Lш (given, or R/λ). [m]"""
        return self.rod_length if self.rod_length is not None else self.R / self.rod_ratio

    @property
    def lam(self) -> float:
        """λ = R/Lш (given, or from Lш). [-]"""
        return self.rod_ratio if self.rod_ratio is not None else self.R / self.rod_length

    @property
    def k_offset(self) -> float:
        """Relative piston-pin offset k = e/R. [-]"""
        return self.pin_offset / self.R

    @property
    def piston_travel(self) -> float:
        """The piston's travel between the dead centres (2R for a central mechanism). [m]"""
        return piston_travel(self.R, self.L, self.pin_offset)

    @property
    def omega(self) -> float:
        """Crankshaft angular velocity ω = πn/30. [rad/s]"""
        return math.pi * self.speed_rpm / 30.0

    @property
    def cycle_deg(self) -> float:
        """Length of the cycle in crank degrees: 720 (four-stroke) or 360. [deg]"""
        return 720.0 if self.strokes == 4 else 360.0

    @property
    def area(self) -> float:
        """Piston area Fп = πD²/4. [m²]"""
        return math.pi * self.bore ** 2 / 4.0

    @property
    def Vh(self) -> float:
        """Displacement of one cylinder Vh = Fп·Sп (Sп = S for a central mechanism). [m³]"""
        return self.area * self.piston_travel

    @property
    def epsilon(self) -> float | None:
        """Compression ratio ε: the computed diagram's, else ``[engine]``'s, else None. [-]"""
        return self.cycle.compression_ratio if self.cycle is not None \
            else self.compression_ratio

    @property
    def Vc(self) -> float | None:
        """Clearance volume Vc = Vh/(ε − 1), when ε is known. [m³]"""
        eps = self.epsilon
        return None if eps is None else self.Vh / (eps - 1.0)

    @property
    def piston_speed_mean(self) -> float:
        """Mean piston speed vп.ср = S·n/30. [m/s]"""
        return self.stroke * self.speed_rpm / 30.0

    # ---- the dynamic model's masses [1]_
    @property
    def mass_way(self) -> str:
        """How the masses are given: "direct", "parts" or "per_area"."""
        return next(w for w, keys in MASS_WAYS.items()
                    if any(getattr(self, k) is not None for k in keys))

    @property
    def mass_source(self) -> dict:
        """The mass inputs as given (key → value), for the report."""
        keys = MASS_WAYS[self.mass_way]
        if self.mass_way != "direct":
            keys += ("rod_small_end_fraction",)
        if self.crank_rotating_kg is not None:
            keys += ("crank_rotating_kg",)
        return {k: getattr(self, k) for k in keys}

    def _rod_split(self):
        """(mj, mш.к): mj = mп + f·mш, mш.к = (1 − f)·mш [1]_, per area × Fп. [kg]"""
        way = self.mass_way
        if way == "direct":
            return self.reciprocating_kg, self.rod_rotating_kg
        f = self.rod_small_end_fraction
        if way == "parts":
            mp, mr, scale = self.piston_group_kg, self.rod_kg, 1.0
        else:
            mp, mr, scale = self.piston_group_kg_m2, self.rod_kg_m2, self.area
        return (mp + f * mr) * scale, (1.0 - f) * mr * scale

    @property
    def mj(self) -> float:
        """Reciprocating mass mj = mп + mш.п. [kg]"""
        return self._rod_split()[0]

    @property
    def m_rod_rot(self) -> float:
        """Rotating part of the rod mass mш.к = mш − mш.п. [kg]"""
        return self._rod_split()[1]

    @property
    def m_crank_rot(self) -> float | None:
        """Unbalanced rotating mass of the crank throw mк (None if not given). [kg]"""
        return self.crank_rotating_kg

    @property
    def Kr(self) -> float:
        """Centrifugal force of the rod's rotating part Kr.ш = −mш.к·R·ω² [1]_. [N]"""
        return -self.m_rod_rot * self.R * self.omega ** 2

    # ---- the indicator diagram
    @property
    def cycle(self) -> CycleSpec | None:
        """The thermal-calculation data of a computed diagram (None for a table)."""
        return self.pressure if isinstance(self.pressure, CycleSpec) else None

    @property
    def pressure_source(self) -> str:
        """"cycle", "file" or "inline"."""
        if self.cycle is not None:
            return "cycle"
        return "file" if self.pressure.file is not None else "inline"

    @property
    def pressure_file(self) -> Path | None:
        """The CSV file of a tabulated diagram (None otherwise)."""
        return None if self.cycle is not None else self.pressure.file


@dataclass(frozen=True)
class TableSettings:
    """Presentation settings of the force table and its report (not physics).

    Attributes
    ----------
    step_deg : float
        Table rows every ``step_deg`` over the cycle. [deg]
    extra_angles_deg : tuple of float
        Extra rows (sorted, without repeats). [deg]
    force_scale : float or None
        μP, the force scale of the drawing: the mm columns are force ÷ μP. [N/mm]
    form : {"seed", "kolchin"}
        Form of Table 2 in the report: the seed's (forces in mm and N) or Kolchin's
        (specific forces in MPa with tg β, 1/cos β, cos(α+β)/cos β, sin(α+β)/cos β).
    """

    step_deg: float = 30.0
    extra_angles_deg: tuple = ()
    force_scale: float | None = None
    form: str = "seed"

    def __post_init__(self):
        if _LOADED.get():
            return
        problems = []
        if self.form not in TABLE_FORMS:
            problems.append(Problem("form", Text(
                "errors.engine.model.valid",
                {"form": self.form, "items": ", ".join(repr(f) for f in TABLE_FORMS)})))
        if not (_finite(self.step_deg) and self.step_deg > 0):
            problems.append(Problem("step_deg", Text("errors.engine.model.finite_number",
                                                     {"step_deg": self.step_deg})))
        for i, a in enumerate(self.extra_angles_deg):
            if not (_finite(a) and a >= 0):
                problems.append(Problem(f"extra_angles_deg[{i}]",
                                        Text("errors.engine.model.finite_number_3", {"a": a})))
        if self.force_scale is not None and not (_finite(self.force_scale)
                                                 and self.force_scale > 0):
            problems.append(Problem("force_scale", Text("errors.engine.model.finite_number_2",
                                                        {"force_scale": self.force_scale})))
        if problems:
            raise EngineSpecError(problems)


@dataclass(frozen=True)
class Counterweight:
    """One counterweight: an unbalanced mass·radius on a crank web.

    Attributes
    ----------
    z : float
        Axial position, from cylinder 1's axis towards the flywheel. [m]
    mr : float
        Mass times the radius of its centre of mass. [kg·m]
    angle_deg : float
        Its direction from throw 1, in the direction of rotation. [deg]
    """

    z: float
    mr: float
    angle_deg: float


@dataclass(frozen=True)
class CrankTrain:
    """The inputs of the crank train, the flywheel estimate and the balance (inputs only).

    Attributes
    ----------
    arrangement : {"inline", "vee", "boxer"}
    vee_angle_deg : float or None
        Angle between the banks of a vee, in (0°, 180°). [deg]
    firing_order : tuple of int or None
        A permutation of 1…i (default: :data:`DEFAULT_FIRING_ORDERS`).
    cylinder_spacing : float or None
        Distance between neighbouring cylinder axes of one bank along the crankshaft
        (None: 0, a planar engine without moments). [m]
    bank_offset : float
        Axial offset of the second bank's rods, + towards the flywheel. [m]
    cylinder_positions : tuple of float or None
        Axial position of each cylinder, instead of the spacing. [m]
    throw_angles_deg : tuple of float or None
        Angle of each throw from throw 1 in the direction of rotation (default: the
        even-firing crankshaft of the firing order). [deg]
    mechanical_efficiency : float or None
        ηм, effective from indicated figures. [-]
    delta : float or None
        Coefficient of cyclic irregularity δ = (ωmax − ωmin)/ωср for the flywheel. [-]
    flywheel_share : float
        Share of J0 taken by the flywheel, Jм/J0 (Kolchin: 0.8…0.9). [-]
    flywheel_diameter : float or None
        Mean diameter of the flywheel rim Dср, to give its mass. [m]
    counterweights : {"none", "throws", "throws+first_order"}
        Automatic design: none; one per throw sized for its rotating masses (mш.к of its
        rods + mк), opposite the throw; and also two end counterweights that cancel the
        forward-rotating first-order force and moment (all of it when it is a constant
        rotating vector, as in a 90° V8 cross-plane or a 90° V-twin).
    counterweight_list : tuple of Counterweight
        Counterweights given one by one (instead of a design).
    """

    arrangement: str = "inline"
    vee_angle_deg: float | None = None
    firing_order: tuple | None = None
    cylinder_spacing: float | None = None
    bank_offset: float = 0.0
    cylinder_positions: tuple | None = None
    throw_angles_deg: tuple | None = None
    mechanical_efficiency: float | None = None
    delta: float | None = None
    flywheel_share: float = 0.85
    flywheel_diameter: float | None = None
    counterweights: str = "none"
    counterweight_list: tuple = field(default=())

    def __post_init__(self):
        if _LOADED.get():
            return
        problems = []
        if self.arrangement not in ARRANGEMENTS:
            problems.append(Problem("arrangement", Text("errors.engine.model.valid_2",
                                                        {"arrangement": self.arrangement,
                                                         "items": ", ".join(ARRANGEMENTS)})))
        if self.arrangement == "vee":
            v = self.vee_angle_deg
            if not (isinstance(v, (int, float)) and math.isfinite(v) and 0 < v < 180):
                problems.append(Problem("vee_angle_deg",
                                        Text("errors.engine.model.vee_needs_angle", {"v": v})))
        elif self.vee_angle_deg is not None:
            problems.append(Problem("vee_angle_deg", Text("errors.engine.model.only_used_with")))
        if self.counterweights not in COUNTERWEIGHT_DESIGNS:
            problems.append(Problem("counterweights", Text(
                "errors.engine.model.valid_3",
                {"counterweights": self.counterweights,
                 "items": ", ".join(COUNTERWEIGHT_DESIGNS)})))
        if self.counterweight_list and self.counterweights != "none":
            problems.append(Problem("counterweights", Text("errors.engine.model.give_design_or")))
        for key in ("mechanical_efficiency", "delta"):
            v = getattr(self, key)
            if v is not None and not (math.isfinite(v) and 0 < v <= 1):
                problems.append(Problem(key, Text("errors.engine.model.and_2", {"v": v})))
        if not (math.isfinite(self.flywheel_share) and 0 < self.flywheel_share <= 1):
            problems.append(Problem("flywheel_share", Text(
                "errors.engine.model.and", {"flywheel_share": self.flywheel_share})))
        if problems:
            raise EngineSpecError(problems)

    @property
    def bank_angles_deg(self) -> tuple:
        """Bank angles γ of the first and (vee, boxer) second bank. [deg]"""
        if self.arrangement == "inline":
            return (0.0,)
        half = 90.0 if self.arrangement == "boxer" else self.vee_angle_deg / 2.0
        return (-half, half)



@dataclass(frozen=True)
class EngineStudy:
    """What an engine spec file holds, every table read once: the one-cylinder physics
    (``spec``), the report settings (``settings``), the crank train of the whole engine
    (``train``: ``[engine]`` layout keys, ``[flywheel]``, ``[balance]``) and the inputs of
    the bearing calculation (``bearings``: ``[bearings]`` and ``[rod]``, a
    :class:`~engine.spec.inputs.BearingInputs`) and of the torsional vibration
    (``torsion``: ``[torsion]``, a :class:`~engine.spec.torsion_inputs.TorsionInputs`;
    None without the table)."""

    spec: EngineSpec
    settings: TableSettings
    train: CrankTrain = field(default_factory=lambda: CrankTrain())
    bearings: BearingInputs = field(default_factory=BearingInputs)
    torsion: TorsionInputs | None = None
