"""The engine spec: read and validate (every problem at once), inputs only.

A spec is a TOML file (or an equivalent dict) with the tables ``[engine]``, ``[masses]``,
``[pressure]`` (exactly one source of the indicator diagram) and ``[table]``.  Every key is
documented in :func:`load`; unknown keys are errors.

:class:`EngineSpec` holds the physical inputs only (SI inside: m, kg, Pa; the speed in rpm as
given); everything derived — R, L or λ, ω, Fп, Vh, mj, mш.к, Kr.ш — is a property computed
from them, so ``dataclasses.replace(spec, speed_rpm=3000)`` gives the right table.  The
presentation settings of the report (table step, extra rows, force scale μP) are a
separate :class:`TableSettings`; the report language is an argument of the report itself.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей. 4-е изд.
   М.: Высшая школа, 2008, гл. "Динамика кривошипно-шатунного механизма": the dynamic model
   with mj = mп + mш.п and mш.к, mш.п ≈ 0.275·mш, masses per unit piston area; Kr.ш.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from crankbase.errors import Problem, SpecError
from crankbase.validation import MAX_ROWS, Checker, read_toml, rows_problem

from .indicator import JOIN_AFTER_PEAK_DEG, CycleSpec, PressureTable, sharp_cycle_pressure
from .kinematics import piston_travel

__all__ = ["EngineSpec", "TableSettings", "EngineStudy", "CrankTrain", "Counterweight",
           "ARRANGEMENTS", "COUNTERWEIGHT_DESIGNS", "CycleSpec", "PressureTable",
           "EngineSpecError", "load", "load_spec", "PRESSURE_UNITS", "read_pressure_csv",
           "ROD_SMALL_END_FRACTION"]

#: Pressure column names accepted in a CSV (and inline) and their factor to Pa.
PRESSURE_UNITS = {"p_MPa": 1e6, "p_bar": 1e5, "p_kPa": 1e3, "p_Pa": 1.0}

#: Default share of the rod mass taken as reciprocating (small end), mш.п / mш [1]_.
ROD_SMALL_END_FRACTION = 0.275

#: The mass inputs, by the way they are given (exactly one way per spec).
MASS_WAYS = {
    "direct": ("reciprocating_kg", "rod_rotating_kg"),
    "parts": ("piston_group_kg", "rod_kg"),
    "per_area": ("piston_group_kg_m2", "rod_kg_m2"),
}


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
        problems = []

        def bad(key, msg):
            problems.append(Problem(key, msg))

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


#: Forms of Table 2 in the report ([table] form, --form).
TABLE_FORMS = ("seed", "kolchin")


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
        problems = []
        if self.form not in TABLE_FORMS:
            problems.append(Problem("form", f"got {self.form!r}; valid: "
                                            + ", ".join(repr(f) for f in TABLE_FORMS)))
        if not (_finite(self.step_deg) and self.step_deg > 0):
            problems.append(Problem("step_deg", f"got {self.step_deg!r}; must be a finite "
                                                "number > 0"))
        for i, a in enumerate(self.extra_angles_deg):
            if not (_finite(a) and a >= 0):
                problems.append(Problem(f"extra_angles_deg[{i}]",
                                        f"got {a!r}; must be a finite number >= 0"))
        if self.force_scale is not None and not (_finite(self.force_scale)
                                                 and self.force_scale > 0):
            problems.append(Problem("force_scale", f"got {self.force_scale!r}; must be a "
                                                   "finite number > 0"))
        if problems:
            raise EngineSpecError(problems)


#: Crank-train arrangements.
ARRANGEMENTS = ("inline", "vee", "boxer")
#: Automatic counterweight designs ([balance] counterweights).
COUNTERWEIGHT_DESIGNS = ("none", "throws", "throws+first_order")


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
        problems = []
        if self.arrangement not in ARRANGEMENTS:
            problems.append(Problem("arrangement", f"got {self.arrangement!r}; valid: "
                                    + ", ".join(ARRANGEMENTS)))
        if self.arrangement == "vee":
            v = self.vee_angle_deg
            if not (isinstance(v, (int, float)) and math.isfinite(v) and 0 < v < 180):
                problems.append(Problem("vee_angle_deg", f"got {v!r}; a vee needs an angle "
                                                         "between the banks in (0°, 180°)"))
        elif self.vee_angle_deg is not None:
            problems.append(Problem("vee_angle_deg", "only used with arrangement = 'vee'"))
        if self.counterweights not in COUNTERWEIGHT_DESIGNS:
            problems.append(Problem("counterweights", f"got {self.counterweights!r}; valid: "
                                    + ", ".join(COUNTERWEIGHT_DESIGNS)))
        if self.counterweight_list and self.counterweights != "none":
            problems.append(Problem("counterweights", "give a design or a list of "
                                                      "counterweights, not both"))
        for key in ("mechanical_efficiency", "delta"):
            v = getattr(self, key)
            if v is not None and not (math.isfinite(v) and 0 < v <= 1):
                problems.append(Problem(key, f"got {v!r}; must be > 0 and <= 1"))
        if not (math.isfinite(self.flywheel_share) and 0 < self.flywheel_share <= 1):
            problems.append(Problem("flywheel_share", f"got {self.flywheel_share!r}; must be "
                                                      "> 0 and <= 1"))
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
    """What an engine spec file holds: the one-cylinder physics, the report settings and
    the crank train of the whole engine."""

    spec: EngineSpec
    settings: TableSettings
    train: CrankTrain = field(default_factory=lambda: CrankTrain())


# ----------------------------------------------------------------------------- loader

_ENGINE_KEYS = ("name", "strokes", "cylinders", "bore_mm", "stroke_mm", "rod_ratio",
                "rod_length_mm", "speed_rpm", "crankcase_MPa", "acceleration",
                "compression_ratio", "pin_offset_mm", "arrangement", "vee_angle_deg",
                "firing_order", "cylinder_spacing_mm", "bank_offset_mm",
                "cylinder_positions_mm", "throw_angles_deg", "mechanical_efficiency")
_FLYWHEEL_KEYS = ("delta", "share", "mean_diameter_mm")
_BALANCE_KEYS = ("counterweights", "counterweight")
_COUNTERWEIGHT_KEYS = ("z_mm", "mr_kg_mm", "angle_deg")
_MASS_DIRECT = ("reciprocating_kg", "rod_rotating_kg")
_MASS_PARTS = ("piston_group_kg", "rod_kg")
_MASS_AREA = ("piston_group_kg_m2", "rod_kg_m2")
_MASS_KEYS = _MASS_DIRECT + _MASS_PARTS + _MASS_AREA + ("rod_small_end_fraction",
                                                        "crank_rotating_kg")
_PRESSURE_KEYS = ("angle_deg", *PRESSURE_UNITS, "file", "cycle", "firing_tdc_deg")
_CYCLE_KEYS = ("kind", "compression_ratio", "pa_MPa", "pr_MPa", "n1", "n2", "pz_MPa",
               "lambda_z", "rho", "rounding", "advance_deg", "pc_factor", "peak_factor",
               "peak_after_tdc_deg", "exhaust_opening_deg", "intake_opening_deg",
               "exhaust_closing_deg")
_TABLE_KEYS = ("step_deg", "extra_angles_deg", "force_scale_N_per_mm", "form")

#: Rounding defaults (Kolchin & Demidov, "Скругление индикаторной диаграммы"); the
#: advance depends on the kind and is resolved by :attr:`CycleSpec.advance`.
ROUNDING_DEFAULTS = dict(pc_factor=1.2, peak_factor=0.85, peak_after_tdc_deg=12.0,
                         exhaust_opening_deg=50.0, intake_opening_deg=20.0,
                         exhaust_closing_deg=20.0)


def load(path_or_dict, base_dir=None) -> EngineStudy:
    """Read and validate an engine spec file; return its physics and its report settings.

    Parameters
    ----------
    path_or_dict : str, Path or dict
        A TOML file, or the same content as a dict.
    base_dir : str or Path, optional
        Folder against which ``[pressure] file`` is resolved when a dict is given
        (default: the current folder).  For a file, its own folder is used.

    Returns
    -------
    EngineStudy
        ``spec`` (:class:`EngineSpec`) and ``settings`` (:class:`TableSettings`).

    Raises
    ------
    EngineSpecError
        Listing *every* problem, each with its key path (or CSV file and row).

    Notes
    -----
    ``[engine]``: ``name`` (str), ``strokes`` (4 or 2, default 4), ``cylinders`` (default 1),
    ``bore_mm`` > 0, ``stroke_mm`` > 0 (S = 2R), exactly one of ``rod_ratio``
    (0 < λ < 1) and ``rod_length_mm`` (> stroke/2), ``speed_rpm`` > 0, ``crankcase_MPa``
    (p0 ≥ 0, default 0.1), ``acceleration`` ("two-term", default, or "exact"),
    ``compression_ratio`` (ε > 1, optional: sets Vc for the p–V plot), ``pin_offset_mm``
    (désaxé e, default 0, + towards the direction of rotation at TDC, |e| < Lш − R).

    ``[masses]``, exactly one way: ``reciprocating_kg`` and ``rod_rotating_kg`` (mj,
    mш.к); or ``piston_group_kg`` and ``rod_kg``; or per unit piston area
    ``piston_group_kg_m2`` and ``rod_kg_m2``; with the parts, ``rod_small_end_fraction``
    (default 0.275) gives mш.п = f·mш, mш.к = (1 − f)·mш, mj = mп + mш.п [1]_.
    ``crank_rotating_kg`` (mк) is optional.

    ``[pressure]``, exactly one source: inline ``angle_deg`` with one of ``p_MPa``,
    ``p_bar``, ``p_kPa``, ``p_Pa`` (absolute); ``file`` (a CSV with a header row holding
    ``angle_deg`` and one of those pressure columns, or a Diesel-RK ``.ind`` export read
    by :func:`engine.dieselrk.read_ind`, with ``firing_tdc_deg`` its firing TDC, default
    360); or ``[pressure.cycle]``.

    ``[table]``: ``step_deg`` (default 30), ``extra_angles_deg`` (default none),
    ``force_scale_N_per_mm`` (μP > 0, required), ``form`` ("seed": forces in mm and N,
    the default; "kolchin": specific forces in MPa with the coefficient columns).

    ``[bearings]`` and ``[rod]`` (optional): checked here, read by
    :func:`engine.bearing_spec.read_bearing_inputs`.
    """
    data, file_dir = read_toml(path_or_dict)
    if not isinstance(path_or_dict, dict):
        base = file_dir
        source_path = Path(path_or_dict).resolve()
    else:
        base = Path(base_dir) if base_dir is not None else Path.cwd()
        source_path = None
    c = Checker()
    c.unknown(data, ("engine", "masses", "pressure", "table", "flywheel", "balance", "rod",
                     "bearings"))

    # ---- [engine]
    e = c.table(data, "engine")
    c.unknown(e, _ENGINE_KEYS, "engine")
    name = c.name(e, "name", "engine", default="engine")
    strokes = c.choice(e, "strokes", (4, 2), "engine", required=False, default=4)
    cylinders = c.number(e, "cylinders", "engine", required=False, default=1, ge=1,
                         integer=True)
    bore = c.number(e, "bore_mm", "engine", gt=0, divisor=True,
                    what="the cylinder bore D [mm]")
    stroke = c.number(e, "stroke_mm", "engine", gt=0, divisor=True,
                      what="the piston stroke S [mm]")
    speed = c.number(e, "speed_rpm", "engine", gt=0, what="the crankshaft speed [rpm]")
    p0 = c.number(e, "crankcase_MPa", "engine", required=False, default=0.1, ge=0)
    accel = c.choice(e, "acceleration", ("two-term", "exact"), "engine", required=False,
                     default="two-term")
    eps_engine = c.number(e, "compression_ratio", "engine", required=False, gt=1)
    offset = c.number(e, "pin_offset_mm", "engine", required=False, default=0.0)
    has_ratio, has_len = "rod_ratio" in e, "rod_length_mm" in e
    lam = L_mm = None
    if has_ratio and has_len:
        c.add("engine.rod_ratio", "give either rod_ratio or rod_length_mm, not both")
    elif not has_ratio and not has_len:
        c.add("engine.rod_ratio", "missing; give rod_ratio (λ = R/Lш, 0 < λ < 1) "
                                  "or rod_length_mm")
    elif has_ratio:
        lam = c.number(e, "rod_ratio", "engine", gt=0, lt=1, divisor=True)
    else:
        L_mm = c.number(e, "rod_length_mm", "engine", gt=0, divisor=True)
        if L_mm is not None and stroke is not None and not L_mm > stroke / 2:
            c.add("engine.rod_length_mm",
                  f"got {L_mm:g}; must be > the crank radius stroke_mm/2 = {stroke / 2:g}")
            L_mm = None
    if offset and stroke is not None and (lam is not None or L_mm is not None):
        span = (L_mm if L_mm is not None else stroke / 2 / lam) - stroke / 2
        if not abs(offset) < span:
            c.add("engine.pin_offset_mm", f"got {offset:g}; |e| must be < Lш − R = "
                                          f"{span:.6g} mm for the crank to turn fully")

    # ---- [masses]
    m = c.table(data, "masses")
    c.unknown(m, _MASS_KEYS, "masses")
    masses = {}
    groups = [g for g in (_MASS_DIRECT, _MASS_PARTS, _MASS_AREA) if any(k in m for k in g)]
    if "masses" in data and isinstance(m, dict):
        if not groups:
            c.add("masses", "no masses given; give reciprocating_kg and rod_rotating_kg, "
                            "or piston_group_kg and rod_kg, or piston_group_kg_m2 and "
                            "rod_kg_m2")
        elif len(groups) > 1:
            c.add("masses", "give the masses one way only: "
                  + " / ".join(" + ".join(g) for g in groups) + " were all given")
    frac = c.number(m, "rod_small_end_fraction", "masses", required=False,
                    default=ROD_SMALL_END_FRACTION, ge=0, le=1)
    masses["crank_rotating_kg"] = c.number(m, "crank_rotating_kg", "masses",
                                           required=False, ge=0)
    if len(groups) == 1:
        g = groups[0]
        for k in g:
            masses[k] = c.number(m, k, "masses", ge=0)
        if g is _MASS_DIRECT and "rod_small_end_fraction" in m:
            c.add("masses.rod_small_end_fraction",
                  "only used with piston_group_kg/rod_kg or the per-area masses")

    # ---- [pressure]
    pr = c.table(data, "pressure")
    c.unknown(pr, _PRESSURE_KEYS, "pressure")
    sources = []
    if "angle_deg" in pr or any(k in pr for k in PRESSURE_UNITS):
        sources.append("inline")
    if "file" in pr:
        sources.append("file")
    if "cycle" in pr:
        sources.append("cycle")
    cycle_deg = 720.0 if strokes == 4 else 360.0
    pressure = None
    if "pressure" in data and isinstance(pr, dict):
        if not sources:
            c.add("pressure", "no pressure source; give angle_deg with p_MPa (inline), "
                              "file = \"...csv\", or a [pressure.cycle] table")
        elif len(sources) > 1:
            c.add("pressure", "give exactly one pressure source; got "
                  + " and ".join(sources))
    if sources == ["inline"]:
        angle, p = _inline_pressure(c, pr, cycle_deg)
        if angle is not None:
            pressure = PressureTable(tuple(angle.tolist()), tuple(p.tolist()))
    elif sources == ["file"]:
        fname = c.string(pr, "file", "pressure")
        if fname is not None:
            pfile = (base / fname) if not Path(fname).is_absolute() else Path(fname)
            if not pfile.is_file():
                c.add("pressure.file", f"file {str(pfile)!r} does not exist")
            elif pfile.suffix.lower() == ".ind":          # Diesel-RK export
                from .dieselrk import DIESEL_RK_TDC_DEG, read_ind
                angle, p = read_ind(pfile, cycle_deg, c.number(
                    pr, "firing_tdc_deg", "pressure", required=False,
                    default=DIESEL_RK_TDC_DEG), c)
                if angle is not None:
                    pressure = PressureTable(tuple(angle.tolist()), tuple(p.tolist()),
                                             pfile.resolve())
            else:
                pressure = read_pressure_csv(pfile, cycle_deg, c)
    elif sources == ["cycle"]:
        pressure = _cycle(c, c.table(pr, "cycle", "pressure"), strokes)

    if isinstance(pressure, CycleSpec) and eps_engine is not None \
            and eps_engine != pressure.compression_ratio:
        c.add("engine.compression_ratio",
              f"got {eps_engine:g} but pressure.cycle.compression_ratio is "
              f"{pressure.compression_ratio:g}; give it once")

    # ---- [table]
    t = c.table(data, "table")
    c.unknown(t, _TABLE_KEYS, "table")
    step = c.number(t, "step_deg", "table", required=False, default=30.0, gt=0,
                    le=cycle_deg, divisor=True)
    extra = c.numbers(t, "extra_angles_deg", "table", required=False, default=[], ge=0,
                      max_length=MAX_ROWS)
    if step is not None:     # rows of the table: every step over the cycle, its end, extras
        too_many = rows_problem(cycle_deg / step + 1 + len(extra or []), "table.step_deg")
        if too_many:
            c.problems.append(too_many)
    for i, x in enumerate(extra or []):
        if x > cycle_deg:
            c.add(f"table.extra_angles_deg[{i}]", f"got {x:g}; must be <= {cycle_deg:g}")
    mu = c.number(t, "force_scale_N_per_mm", "table", gt=0,
                  what="the force scale μP [N/mm]")
    form = c.choice(t, "form", ("seed", "kolchin"), "table", required=False,
                    default="seed")

    train = _crank_train(c, data, e, cylinders)

    if isinstance(pressure, CycleSpec) and pressure.rounding and not c.problems:
        _check_rounded_peak(c, pressure, lam if lam is not None else stroke / 2.0 / L_mm,
                            offset / (stroke / 2.0))
    from .bearing_spec import check_tables      # [rod], [bearings], pressure.firing_tdc_deg
    check_tables(c, data)
    if c.problems:
        raise EngineSpecError(c.problems)

    spec = EngineSpec(
        name=name.strip(), strokes=int(strokes), cylinders=int(cylinders),
        bore=bore / 1000.0, stroke=stroke / 1000.0, rod_ratio=lam,
        rod_length=None if L_mm is None else L_mm / 1000.0, speed_rpm=speed, p0=p0 * 1e6,
        acceleration=accel, compression_ratio=eps_engine, pin_offset=offset / 1000.0,
        pressure=pressure, source_path=source_path,
        rod_small_end_fraction=frac, **masses)
    settings = TableSettings(step_deg=step, extra_angles_deg=tuple(sorted(set(extra or []))),
                             force_scale=mu, form=form or "seed")
    return EngineStudy(spec, settings, train)


def _crank_train(c, data, e, cylinders):
    """The crank train of ``[engine]``, ``[flywheel]`` and ``[balance]`` (None on a
    problem, which is recorded in ``c``)."""
    n0 = len(c.problems)
    arr = c.choice(e, "arrangement", ARRANGEMENTS, "engine", required=False,
                   default="inline")
    vee = c.number(e, "vee_angle_deg", "engine", required=False, gt=0, lt=180,
                   what="the angle between the banks")
    if arr == "vee" and "vee_angle_deg" not in e:
        c.add("engine.vee_angle_deg", "missing; a vee needs the angle between its banks, "
                                      "in (0°, 180°)")
    elif arr != "vee" and "vee_angle_deg" in e:
        c.add("engine.vee_angle_deg", "only used with arrangement = \"vee\"")
    order = c.numbers(e, "firing_order", "engine", required=False)
    if order is not None:
        if any(x != int(x) for x in order):
            c.add("engine.firing_order", f"got {order}; cylinder numbers are whole numbers")
            order = None
        else:
            order = tuple(int(x) for x in order)
            n = cylinders or 0
            if sorted(order) != list(range(1, n + 1)):
                c.add("engine.firing_order", f"got {list(order)}; must be a permutation of "
                                             f"the cylinders 1…{n}, each once")
    spacing = c.number(e, "cylinder_spacing_mm", "engine", required=False, gt=0)
    boff = c.number(e, "bank_offset_mm", "engine", required=False, default=0.0)
    if "bank_offset_mm" in e and arr == "inline":
        c.add("engine.bank_offset_mm", "only used with a vee or boxer (two banks)")
    positions = c.numbers(e, "cylinder_positions_mm", "engine", required=False)
    if positions is not None and spacing is not None:
        c.add("engine.cylinder_positions_mm", "give cylinder_spacing_mm or "
                                              "cylinder_positions_mm, not both")
    throws = c.numbers(e, "throw_angles_deg", "engine", required=False)
    eta = c.number(e, "mechanical_efficiency", "engine", required=False, gt=0, le=1)
    fw = c.table(data, "flywheel", required=False)
    c.unknown(fw, _FLYWHEEL_KEYS, "flywheel")
    delta = c.number(fw, "delta", "flywheel", required=False, gt=0, le=1)
    share = c.number(fw, "share", "flywheel", required=False, default=0.85, gt=0, le=1)
    dia = c.number(fw, "mean_diameter_mm", "flywheel", required=False, gt=0)
    bal = c.table(data, "balance", required=False)
    c.unknown(bal, _BALANCE_KEYS, "balance")
    design = c.choice(bal, "counterweights", COUNTERWEIGHT_DESIGNS, "balance",
                      required=False, default="none")
    cws = []
    raw = bal.get("counterweight", []) if isinstance(bal, dict) else []
    if not isinstance(raw, list):
        c.add("balance.counterweight", "must be an array of tables [[balance.counterweight]]"
                                       " with z_mm, mr_kg_mm, angle_deg")
        raw = []
    for i, cw in enumerate(raw):
        where = f"balance.counterweight[{i}]"
        if not isinstance(cw, dict):
            c.add(where, f"must be a table with z_mm, mr_kg_mm, angle_deg; got {cw!r}")
            continue
        c.unknown(cw, _COUNTERWEIGHT_KEYS, where)
        z = c.number(cw, "z_mm", where)
        mr = c.number(cw, "mr_kg_mm", where, ge=0)
        ang = c.number(cw, "angle_deg", where)
        if None not in (z, mr, ang):
            cws.append(Counterweight(z / 1000.0, mr / 1e3, ang))
    if cws and "counterweights" in bal and design != "none":
        c.add("balance.counterweights", "give a design or [[balance.counterweight]] "
                                        "tables, not both")
    if len(c.problems) > n0:
        return None
    return CrankTrain(
        arrangement=arr, vee_angle_deg=vee, firing_order=order,
        cylinder_spacing=None if spacing is None else spacing / 1000.0,
        bank_offset=boff / 1000.0,
        cylinder_positions=None if positions is None else tuple(x / 1000.0
                                                                for x in positions),
        throw_angles_deg=None if throws is None else tuple(throws),
        mechanical_efficiency=eta, delta=delta, flywheel_share=share,
        flywheel_diameter=None if dia is None else dia / 1000.0, counterweights=design,
        counterweight_list=tuple(cws))


def load_spec(path_or_dict, base_dir=None) -> EngineSpec:
    """Read and validate an engine spec; return its :class:`EngineSpec` (the physics).

    The whole file is validated (see :func:`load`, which also returns the report
    settings).
    """
    return load(path_or_dict, base_dir).spec


def _check_pressure_points(c, angle, p, cycle_deg, where, unit="p_Pa"):
    """Validate a tabulated diagram; ``where(i)`` names row i.  Returns arrays or None.

    ``p`` is in Pa; messages give pressures in the user's ``unit`` (a key of
    :data:`PRESSURE_UNITS`).  Points must lie in [0, cycle), sorted, without repeats; a
    last row at the cycle end equal to the first row (720° = 0°) is accepted and dropped.
    """
    f = PRESSURE_UNITS[unit]
    n0 = len(c.problems)
    if len(angle) != len(p):
        c.add(where(None), f"angle and pressure lists differ in length "
                           f"({len(angle)} and {len(p)})")
        return None, None
    for i, (a, q) in enumerate(zip(angle, p)):
        if not (math.isfinite(a) and math.isfinite(q)):
            c.add(where(i), f"angle {a!r} and pressure {q / f!r} must be finite numbers")
        elif q < 0:
            c.add(where(i), f"{unit} {q / f:g} is negative (pressures are absolute)")
    if len(c.problems) > n0:
        return None, None
    if len(angle) >= 2 and angle[-1] == cycle_deg and angle[0] == 0.0:
        if p[-1] != p[0]:
            c.add(where(len(angle) - 1), f"the end row at {cycle_deg:g}° must repeat the "
                                         f"row at 0° (got {unit} {p[-1] / f:g} and "
                                         f"{p[0] / f:g})")
            return None, None
        angle, p = angle[:-1], p[:-1]
    if len(angle) < 2:
        c.add(where(None), f"needs at least two distinct points, got {len(angle)}")
        return None, None
    for i, a in enumerate(angle):
        if not 0 <= a < cycle_deg:
            c.add(where(i), f"angle {a:g}° is outside the cycle [0, {cycle_deg:g})")
        elif i and a <= angle[i - 1]:
            word = "repeated" if a == angle[i - 1] else "not sorted"
            c.add(where(i), f"angle {a:g}° is {word} (angles must increase)")
    if len(c.problems) > n0:
        return None, None
    return np.asarray(angle, float), np.asarray(p, float)


def _inline_pressure(c, pr, cycle_deg):
    units = [k for k in PRESSURE_UNITS if k in pr]
    angle = c.numbers(pr, "angle_deg", "pressure", max_length=MAX_ROWS)
    if not units:
        c.add("pressure", "inline data need one of " + ", ".join(PRESSURE_UNITS)
              + " beside angle_deg")
        return None, None
    if len(units) > 1:
        c.add("pressure", "give one pressure list, got " + ", ".join(units))
        return None, None
    key = units[0]
    vals = c.numbers(pr, key, "pressure", max_length=MAX_ROWS)
    if angle is None or vals is None:
        return None, None
    p = [v * PRESSURE_UNITS[key] for v in vals]

    def where(i):
        return f"pressure.{key}" if i is None else f"pressure.{key}[{i}]"
    return _check_pressure_points(c, list(angle), p, cycle_deg, where, unit=key)


def read_pressure_csv(path, cycle_deg, checker=None):
    """Read an indicator diagram from CSV: header row with ``angle_deg`` and one of
    ``p_MPa``, ``p_bar``, ``p_kPa``, ``p_Pa``; lines starting with ``#`` are comments;
    other columns are ignored.

    The field separator is taken from the header: ``,`` (then the decimal mark must be
    ``.``), ``;`` or a tab (then the decimal mark may be ``.`` or ``,``, one of them for the
    whole file).  Nothing is guessed: a row with more or fewer fields than the header
    (e.g. decimal commas in a comma-separated file: ``0,0,1015``), a header with two
    kinds of separator, a file mixing decimal marks, or a number with both marks
    (``1.015,5``) is refused naming the line and what is ambiguous; no field is ever
    dropped.  Every problem of the file is reported at once (the first
    :data:`~crankbase.validation.MAX_ITEM_PROBLEMS` lines one by one, then a count), with
    values in the file's own unit.

    Parameters
    ----------
    path : str or Path
    cycle_deg : float
        720 or 360. [deg]
    checker : Checker, optional
        Problems are added to it (else an :class:`EngineSpecError` is raised).

    Returns
    -------
    PressureTable or None
        Crank angle [deg] and absolute pressure [Pa], with the file (None on a problem).
    """
    from crankbase.validation import MAX_ITEM_PROBLEMS, MAX_SPEC_BYTES, magnitude_problem

    c = checker if checker is not None else Checker()
    path = Path(path)
    name = path.name
    key = "pressure.file"
    angle = p = None
    try:
        if path.stat().st_size > MAX_SPEC_BYTES:
            raise ValueError(f"{path.stat().st_size:,} bytes; at most {MAX_SPEC_BYTES:,} "
                             f"are read")
        with open(path, encoding="utf-8-sig", newline="") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        c.add(key, f"cannot read {name}: {getattr(exc, 'strerror', None) or exc}")
        text = None
    lines = []
    if text is not None:
        lines = [(n, ln) for n, ln in enumerate(text.splitlines(), start=1)
                 if ln.strip() and not ln.lstrip().startswith("#")]
        if not lines:
            c.add(key, f"{name} is empty")
    if lines:
        hline, htext = lines[0]
        seps = [s for s in (",", ";", "\t") if s in htext]
        shown = {",": "','", ";": "';'", "\t": "tab"}
        if len(seps) > 1:
            c.add(key, f"{name} line {hline}: the header uses more than one separator "
                       f"({', '.join(shown[s] for s in seps)}); use one of them")
        elif not seps:
            c.add(key, f"{name} line {hline}: the header {htext.strip()!r} has one column; "
                       f"it needs angle_deg and one of {', '.join(PRESSURE_UNITS)}, "
                       f"separated by ',' or ';' or a tab")
        else:
            sep = seps[0]
            rows = list(csv.reader([ln for _, ln in lines], delimiter=sep))
            header = [h.strip() for h in rows[0]]
            units = [k for k in PRESSURE_UNITS if k in header]
            if "angle_deg" not in header or len(units) != 1:
                what = ("no pressure column" if not units else
                        "more than one pressure column (" + ", ".join(units) + ")")
                if "angle_deg" not in header:
                    what = "no angle_deg column" + ("" if units else " and " + what)
                c.add(key, f"{name} line {hline}: {what}; the header needs angle_deg and "
                           f"exactly one of {', '.join(PRESSURE_UNITS)}; got "
                           f"{', '.join(header)}")
            else:
                angle, p = _read_pressure_rows(c, key, name, sep, header, units[0],
                                               rows[1:], [n for n, _ in lines[1:]],
                                               cycle_deg, MAX_ITEM_PROBLEMS,
                                               magnitude_problem)
    if checker is None:
        c.raise_if_any()
    if angle is None:
        return None
    return PressureTable(tuple(angle.tolist()), tuple(p.tolist()), path.resolve())


def _read_pressure_rows(c, key, name, sep, header, unit, rows, numbers, cycle_deg,
                        max_shown, magnitude_problem):
    """The data rows of a pressure CSV (see :func:`read_pressure_csv`)."""
    from crankbase.validation import MAX_ROWS

    if len(rows) > MAX_ROWS:
        c.add(key, f"{name} has {len(rows):,} data rows; at most {MAX_ROWS:,} are read")
        return None, None
    ia, ip = header.index("angle_deg"), header.index(unit)
    comma_sep = sep == ","
    # decimal mark of the whole file (';' or tab separated): '.' or ',', never both
    marks, problems = {}, []
    if not comma_sep:
        for line, r in zip(numbers, rows):
            for i in (ia, ip):
                v = r[i].strip() if i < len(r) else ""
                if "." in v and "," in v:
                    problems.append(f"{name} line {line}: {header[i]} {v!r} has both '.' and "
                                    f"','; write numbers without thousands separators")
                    continue
                for m in (".", ","):
                    if m in v:
                        marks.setdefault(m, (line, v))
    if len(marks) == 2:
        (l1, v1), (l2, v2) = marks["."], marks[","]
        problems.append(f"{name}: decimal marks are mixed ({v1!r} on line {l1}, {v2!r} on "
                        f"line {l2}); use '.' or ',' throughout")
    if problems:
        for msg in problems[:max_shown]:
            c.add(key, msg)
        if len(problems) > max_shown:
            c.add(key, f"{name}: ... and {len(problems) - max_shown:,} more problems")
        return None, None
    decimal_comma = not comma_sep and "," in marks
    a_list, p_list, where = [], [], []
    nfields = len(header)
    for line, r in zip(numbers, rows):
        fields = [x.strip() for x in r]
        if len(fields) != nfields:
            text = sep.join(r)
            if len(fields) > nfields and comma_sep:
                why = (f"{len(fields)} fields but the header has {nfields}: decimal commas "
                       f"in a comma-separated file? {text!r} cannot be split into "
                       f"{', '.join(header)} without guessing; use '.' as the decimal mark "
                       f"or ';' as the separator")
            else:
                why = (f"{len(fields)} fields but the header has {nfields} "
                       f"({', '.join(header)}): {text!r}")
            problems.append(f"{name} line {line}: {why}")
            continue
        vals = []
        for i, col in ((ia, "angle_deg"), (ip, unit)):
            v = fields[i]
            if decimal_comma and v.count(",") == 1:
                v = v.replace(",", ".")
            try:
                x = float(v)
                why = magnitude_problem(x)
            except ValueError:
                why = "is not a number"
            if why:
                problems.append(f"{name} line {line}: {col} {fields[i]!r} {why}")
                vals = None
                break
            vals.append(x)
        if vals is None:
            continue
        if vals[1] < 0:
            problems.append(f"{name} line {line}: {unit} {fields[ip]} is negative "
                            f"(pressures are absolute)")
            continue
        a_list.append(vals[0])
        p_list.append(vals[1] * PRESSURE_UNITS[unit])
        where.append(line)
    for msg in problems[:max_shown]:
        c.add(key, msg)
    if len(problems) > max_shown:
        c.add(key, f"{name}: ... and {len(problems) - max_shown:,} more lines with problems")
    if problems:
        return None, None

    def at(i):
        return f"{key} {name}" if i is None else f"{key} {name} line {where[i]}"
    return _check_pressure_points(c, a_list, p_list, cycle_deg, at, unit=unit)


def _check_rounded_peak(c, cyc, lam, k):
    """The real (rounded) diagram lies inside the theoretical one: its peak
    peak_factor·pz must not rise above the expansion line at the peak angle, and must be
    the maximum (the line where the rounding rejoins it must be lower)."""
    a = 360.0 + cyc.peak_after_tdc_deg
    line = float(sharp_cycle_pressure([a], cyc, lam, k=k)[0])
    peak = cyc.peak_factor * cyc.pz
    if peak > line:
        c.add("pressure.cycle.peak_factor",
              f"the rounded peak peak_factor·pz = {peak / 1e6:.4g} MPa at {a:g}° lies above "
              f"the expansion line there ({line / 1e6:.4g} MPa); lower peak_factor or "
              f"peak_after_tdc_deg")
        return
    join = a + JOIN_AFTER_PEAK_DEG
    after = float(sharp_cycle_pressure([join], cyc, lam, k=k)[0])
    if after >= peak:
        c.add("pressure.cycle.peak_factor",
              f"the expansion line at {join:g}° ({after / 1e6:.4g} MPa), where the rounded "
              f"curve rejoins it, is not below the rounded peak ({peak / 1e6:.4g} MPa): the "
              f"isobaric part (ρ) is too long for the rounding; raise peak_factor or "
              f"peak_after_tdc_deg")


def _cycle(c, cy, strokes):
    path = "pressure.cycle"
    c.unknown(cy, _CYCLE_KEYS, path)
    kind = c.choice(cy, "kind", ("otto", "diesel"), path)
    if strokes != 4:
        c.add(path, "a computed diagram is available for four-stroke engines only; "
                    "give a pressure table for a two-stroke engine")
    eps = c.number(cy, "compression_ratio", path, gt=1)
    pa = c.number(cy, "pa_MPa", path, gt=0, divisor=True)
    pr = c.number(cy, "pr_MPa", path, gt=0, divisor=True)
    n1 = c.number(cy, "n1", path, gt=1, lt=2)
    n2 = c.number(cy, "n2", path, gt=1, lt=2)
    if "pz_MPa" in cy and "lambda_z" in cy:
        c.add(f"{path}.pz_MPa", "give either pz_MPa or lambda_z, not both")
        pz = lz = None
    elif "lambda_z" in cy:
        lz = c.number(cy, "lambda_z", path, ge=1)
        pz = None
    else:
        pz = c.number(cy, "pz_MPa", path, gt=0, what="pz [MPa] (or lambda_z = pz/pc)")
        lz = None
    if kind == "diesel":
        rho = c.number(cy, "rho", path, ge=1, what="the pre-expansion ratio ρ")
    else:
        if "rho" in cy:
            c.add(f"{path}.rho", "only used with kind = \"diesel\"")
        rho = 1.0
    rounding = c.choice(cy, "rounding", (True, False), path, required=False, default=True)
    d = ROUNDING_DEFAULTS
    # at least 1°: the rounding curves span these angles (a near-zero span is a division
    # by ~0 in the Hermite segments)
    opts = {k: c.number(cy, k, path, required=False, default=v, ge=1, lt=90)
            for k, v in d.items() if k not in ("pc_factor", "peak_factor")}
    opts["pc_factor"] = c.number(cy, "pc_factor", path, required=False,
                                 default=d["pc_factor"], ge=1, le=2)
    opts["peak_factor"] = c.number(cy, "peak_factor", path, required=False,
                                   default=d["peak_factor"], gt=0, le=1)
    opts["advance_deg"] = c.number(cy, "advance_deg", path, required=False, gt=0, lt=90)
    if None in (kind, eps, pa, pr, n1, n2, rho) or (pz is None and lz is None) \
            or None in (v for k, v in opts.items() if k != "advance_deg"):
        return None
    cyc = CycleSpec(kind=kind, compression_ratio=eps, pa=pa * 1e6, pr=pr * 1e6, n1=n1,
                    n2=n2, pz_input=None if pz is None else pz * 1e6, lambda_z_input=lz,
                    rho=rho, rounding=rounding, **opts)
    if pz is not None and cyc.pz < cyc.pc:
        c.add(f"{path}.pz_MPa", f"got {pz:g}; must be >= the compression pressure "
                                f"pc = pa·ε^n1 = {cyc.pc / 1e6:.4g} MPa")
        return None
    if kind == "diesel" and rho >= eps:
        c.add(f"{path}.rho", f"got {rho:g}; must be < compression_ratio {eps:g}")
        return None
    if rounding and (360 + opts["peak_after_tdc_deg"] + JOIN_AFTER_PEAK_DEG
                     > 540 - opts["exhaust_opening_deg"]):
        c.add(f"{path}.exhaust_opening_deg", "the combustion rounding (peak_after_tdc_deg "
              f"+ {JOIN_AFTER_PEAK_DEG:g}°) and the exhaust rounding overlap; reduce them")
        return None
    if rounding and opts["peak_factor"] * cyc.pz < opts["pc_factor"] * cyc.pc:
        c.add(f"{path}.peak_factor", "the rounded peak peak_factor·pz must not be below "
                                     "pc_factor·pc")
        return None
    return cyc
