"""Every key of an engine spec file, declared once (:mod:`crankbase.schema`).

Units as written in the file and their factor to SI, ranges, defaults and whether a key
is required; the words (labels, help, symbols) are in the ``spec`` catalogue under
``spec.<table>.<key>``.  :mod:`engine.spec.loading` reads every table through this schema
and adds the checks that join several keys (exactly one rod length, one way of giving the
masses, one pressure source ...).
"""
from __future__ import annotations

from crankbase.schema import MAX_CYLINDERS, ArrayOfTables, Key, Schema, Table

from .dieselrk import DIESEL_RK_TDC_DEG

#: Half-angle of the arc each load wears, as in the textbooks (:mod:`engine.bearings.wear`,
#: which uses it; here so that reading a spec imports no bearing module). [deg]
DEFAULT_HALF_ANGLE_DEG = 60.0

__all__ = ["SCHEMA", "ENGINE", "MASSES", "PRESSURE", "CYCLE", "TABLE", "FLYWHEEL",
           "BALANCE", "COUNTERWEIGHT", "BEARINGS", "ROD", "ARRANGEMENTS",
           "COUNTERWEIGHT_DESIGNS", "TABLE_FORMS", "PRESSURE_UNITS", "ROD_MODELS",
           "ROD_SMALL_END_FRACTION", "ROUNDING_DEFAULTS", "MASS_WAYS", "TORSION",
           "TORSION_MASSES", "TORSION_DAMPERS", "TORSION_SCHEMA", "MAX_TORSION_MASSES"]

#: Crank-train arrangements.
ARRANGEMENTS = ("inline", "vee", "boxer")
#: Automatic counterweight designs ([balance] counterweights).
COUNTERWEIGHT_DESIGNS = ("none", "throws", "throws+first_order")
#: Forms of Table 2 in the report ([table] form, --form).
TABLE_FORMS = ("seed", "kolchin")
#: Pressure column names accepted in a CSV (and inline) and their factor to Pa.
PRESSURE_UNITS = {"p_MPa": 1e6, "p_bar": 1e5, "p_kPa": 1e3, "p_Pa": 1.0}
#: Models of the connecting rod ([rod] model).
ROD_MODELS = ("two-mass", "rigid")
#: Default share of the rod mass taken as reciprocating (small end), mш.п / mш
#: (Kolchin & Demidov, "Динамика кривошипно-шатунного механизма").
ROD_SMALL_END_FRACTION = 0.275
#: Rounding defaults (Kolchin & Demidov, "Скругление индикаторной диаграммы"); the
#: advance depends on the kind and is resolved by :attr:`engine.CycleSpec.advance`.
ROUNDING_DEFAULTS = dict(pc_factor=1.2, peak_factor=0.85, peak_after_tdc_deg=12.0,
                         exhaust_opening_deg=50.0, intake_opening_deg=20.0,
                         exhaust_closing_deg=20.0)
#: The mass inputs, by the way they are given (exactly one way per spec).
MASS_WAYS = {
    "direct": ("reciprocating_kg", "rod_rotating_kg"),
    "parts": ("piston_group_kg", "rod_kg"),
    "per_area": ("piston_group_kg_m2", "rod_kg_m2"),
}

MM = dict(unit="mm", si=1e-3)

ENGINE = Table("engine", (
    Key("name", "name", default="engine"),
    Key("strokes", "choice", choices=(4, 2), default=4),
    Key("cylinders", "integer", ge=1, le=MAX_CYLINDERS, default=1, symbol=True),
    Key("bore_mm", gt=0, divisor=True, required=True, symbol=True, **MM),
    Key("stroke_mm", gt=0, divisor=True, required=True, symbol=True, **MM),
    Key("rod_ratio", gt=0, lt=1, divisor=True, required="cond", symbol=True),
    Key("rod_length_mm", gt=0, divisor=True, required="cond", symbol=True, **MM),
    Key("speed_rpm", gt=0, unit="rpm", required=True, symbol=True),
    Key("crankcase_MPa", ge=0, default=0.1, unit="MPa", si=1e6, symbol=True),
    Key("acceleration", "choice", choices=("two-term", "exact"), default="two-term"),
    Key("compression_ratio", gt=1, symbol=True),
    Key("pin_offset_mm", default=0.0, symbol=True, **MM),
    Key("arrangement", "choice", choices=ARRANGEMENTS, default="inline"),
    Key("vee_angle_deg", gt=0, lt=180, unit="°", required="cond", symbol=True),
    Key("firing_order", "numbers", max_length=MAX_CYLINDERS),
    Key("cylinder_spacing_mm", gt=0, **MM),
    Key("bank_offset_mm", default=0.0, **MM),
    Key("cylinder_positions_mm", "numbers", max_length=MAX_CYLINDERS, **MM),
    Key("throw_angles_deg", "numbers", unit="°", max_length=MAX_CYLINDERS),
    Key("mechanical_efficiency", gt=0, le=1, symbol=True),
), required=True)

MASSES = Table("masses", (
    Key("reciprocating_kg", ge=0, unit="kg", required="cond", symbol=True),
    Key("rod_rotating_kg", ge=0, unit="kg", required="cond", symbol=True),
    Key("piston_group_kg", ge=0, unit="kg", required="cond", symbol=True),
    Key("rod_kg", ge=0, unit="kg", required="cond", symbol=True),
    Key("piston_group_kg_m2", ge=0, unit="kg/m²", required="cond", symbol=True),
    Key("rod_kg_m2", ge=0, unit="kg/m²", required="cond", symbol=True),
    Key("rod_small_end_fraction", ge=0, le=1, default=ROD_SMALL_END_FRACTION),
    Key("crank_rotating_kg", ge=0, unit="kg", symbol=True),
), required=True)

CYCLE = Table("pressure.cycle", (
    Key("kind", "choice", choices=("otto", "diesel"), required=True),
    Key("compression_ratio", gt=1, required=True, symbol=True),
    Key("pa_MPa", gt=0, divisor=True, unit="MPa", si=1e6, required=True, symbol=True),
    Key("pr_MPa", gt=0, divisor=True, unit="MPa", si=1e6, required=True, symbol=True),
    Key("n1", gt=1, lt=2, required=True, symbol=True),
    Key("n2", gt=1, lt=2, required=True, symbol=True),
    Key("pz_MPa", gt=0, unit="MPa", si=1e6, required="cond", symbol=True),
    Key("lambda_z", ge=1, required="cond", symbol=True),
    Key("rho", ge=1, required="cond", symbol=True),
    Key("rounding", "bool", default=True),
    Key("advance_deg", gt=0, lt=90, unit="°", shown_default="30 (otto), 20 (diesel)"),
    Key("pc_factor", ge=1, le=2, default=ROUNDING_DEFAULTS["pc_factor"]),
    Key("peak_factor", gt=0, le=1, default=ROUNDING_DEFAULTS["peak_factor"]),
    # at least 1°: the rounding curves span these angles (a near-zero span is a division
    # by ~0 in the Hermite segments)
    Key("peak_after_tdc_deg", ge=1, lt=90, unit="°",
        default=ROUNDING_DEFAULTS["peak_after_tdc_deg"]),
    Key("exhaust_opening_deg", ge=1, lt=90, unit="°",
        default=ROUNDING_DEFAULTS["exhaust_opening_deg"]),
    Key("intake_opening_deg", ge=1, lt=90, unit="°",
        default=ROUNDING_DEFAULTS["intake_opening_deg"]),
    Key("exhaust_closing_deg", ge=1, lt=90, unit="°",
        default=ROUNDING_DEFAULTS["exhaust_closing_deg"]),
))

PRESSURE = Table("pressure", (
    Key("angle_deg", "numbers", unit="°", required="cond"),
    Key("p_MPa", "numbers", unit="MPa", si=1e6, required="cond"),
    Key("p_bar", "numbers", unit="bar", si=1e5, required="cond"),
    Key("p_kPa", "numbers", unit="kPa", si=1e3, required="cond"),
    Key("p_Pa", "numbers", unit="Pa", required="cond"),
    Key("file", "path", required="cond"),
    Key("firing_tdc_deg", unit="°", default=DIESEL_RK_TDC_DEG),
    CYCLE,
), required=True)

TABLE = Table("table", (
    Key("step_deg", gt=0, divisor=True, unit="°", default=30.0, shown_default="30"),
    Key("extra_angles_deg", "numbers", ge=0, unit="°", default=()),
    Key("force_scale_N_per_mm", gt=0, unit="N/mm", required=True, symbol=True),
    Key("form", "choice", choices=TABLE_FORMS, default="seed"),
), required=True)

FLYWHEEL = Table("flywheel", (
    Key("delta", gt=0, le=1, symbol=True),
    Key("share", gt=0, le=1, default=0.85),
    Key("mean_diameter_mm", gt=0, symbol=True, **MM),
))

COUNTERWEIGHT = ArrayOfTables("balance.counterweight", (
    Key("z_mm", required=True, **MM),
    Key("mr_kg_mm", ge=0, unit="kg·mm", si=1e-3, required=True),
    Key("angle_deg", unit="°", required=True),
), max_items=2 * MAX_CYLINDERS + 2)

BALANCE = Table("balance", (
    Key("counterweights", "choice", choices=COUNTERWEIGHT_DESIGNS, default="none"),
    COUNTERWEIGHT,
))

BEARINGS = Table("bearings", (
    Key("wear_half_angle_deg", gt=0, le=180, unit="°", default=DEFAULT_HALF_ANGLE_DEG),
    Key("journal_positions_mm", "numbers", length=2, **MM),
    Key("counterweight_kg_mm", ge=0, unit="kg·mm", si=1e-3, default=0.0),
    Key("counterweight_angle_deg", ge=-360, le=360, unit="°", default=180.0),
))

ROD = Table("rod", (
    Key("model", "choice", choices=ROD_MODELS, default="two-mass"),
    Key("inertia_kg_m2", gt=0, unit="kg·m²", required="cond", symbol=True),
    Key("mass_kg", gt=0, unit="kg", symbol=True),
    Key("cg_from_big_end_mm", gt=0, symbol=True, **MM),
))

#: Most masses of a torsional chain (``[torsion]``): every throw of the largest engine
#: (:data:`~crankbase.schema.MAX_CYLINDERS`) and a few more (damper, gears, flywheel,
#: the load); the count sizes the eigenproblem, so it is bounded before anything is built.
MAX_TORSION_MASSES = 64
_MAX_SECTIONS = MAX_TORSION_MASSES - 1

#: Extra masses beside the throws (``masses = [{ name, J_kgm2, before | after }]``):
#: ``before``/``after`` is a throw number (1 … the engine's throws) or ``"first"`` /
#: ``"last"``; the loader reads these two keys itself (a number or a word).
TORSION_MASSES = ArrayOfTables("torsion.masses", (
    Key("name", "name", required=True),
    Key("J_kgm2", gt=0, unit="kg·m²", required=True),
    Key("before", "string", required="cond"),
    Key("after", "string", required="cond"),
), max_items=MAX_TORSION_MASSES)

#: Absolute viscous dampers at named masses (``dampers = [{ at, c_Nms_rad }]``).
TORSION_DAMPERS = ArrayOfTables("torsion.dampers", (
    Key("at", "string", required=True),
    Key("c_Nms_rad", gt=0, unit="N·m·s/rad", required=True),
), max_items=MAX_TORSION_MASSES)

TORSION = Table("torsion", (
    Key("throw_J_kgm2", ge=0, unit="kg·m²", required="cond", symbol=True),
    Key("inertias_kgm2", "numbers", gt=0, unit="kg·m²", required="cond",
        max_length=MAX_TORSION_MASSES, min_length=2),
    Key("stiffnesses_Nm_rad", "numbers", gt=0, unit="N·m/rad", required=True,
        max_length=_MAX_SECTIONS, min_length=1),
    Key("names", "names", max_length=MAX_TORSION_MASSES),
    Key("throws", "numbers", ge=0, max_length=MAX_TORSION_MASSES),
    Key("damping_ratio", ge=0, lt=1, default=0.02, symbol=True),
    Key("speed_range_rpm", "numbers", gt=0, length=2, unit="rpm", required="cond"),
    Key("speed_step_rpm", gt=0, unit="rpm", default=10.0, shown_default="10"),
    Key("orders_max", gt=0, le=48, default=12.0, shown_default="12"),
    Key("shaft_diameters_mm", "numbers", gt=0, max_length=_MAX_SECTIONS, **MM),
    Key("holzer_trial_rad_s", "numbers", gt=0, unit="rad/s", default=(), max_length=50),
    TORSION_MASSES,
    TORSION_DAMPERS,
))

#: The engine spec file (``crankdyn engine``; with ``[dynamics]`` also ``crankdyn
#: dynamics``, whose table the dynamics schema declares).
SCHEMA = Schema("engine", (ENGINE, MASSES, PRESSURE, TABLE, FLYWHEEL, BALANCE, BEARINGS,
                           ROD, TORSION))

#: A torsional chain on its own (``crankdyn torsion``): ``name`` and ``[torsion]`` (the
#: by-hand chain), the same ``[torsion]`` table as the engine's.
TORSION_SCHEMA = Schema("torsion", (TORSION,), extra=("name",))
