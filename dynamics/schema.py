"""Every key of the dynamics and rotor spec files, declared once
(:mod:`crankbase.schema`); the words are in the ``spec`` catalogue.
"""
from __future__ import annotations

from dataclasses import dataclass

from crankbase.schema import ArrayOfTables, Key, Schema, Table

__all__ = ["SCHEMA", "SCHEMAS", "ROTOR_SCHEMA", "DYNAMICS", "MACHINE", "ELEMENT", "MOMENT",
           "ROTOR", "ROTOR_MASS", "DRIVINGS", "LINKAGE_BALANCE"]

#: How the machine is driven ([dynamics] driving).
DRIVINGS = ("constant", "table", "motor")
#: Most grid intervals over the period ([dynamics] steps).
MAX_STEPS = 200_000

DYNAMICS = Table("dynamics", (
    Key("driving", "choice", choices=DRIVINGS, default="constant"),
    Key("phi_deg", "numbers", min_length=1, unit="°", required="cond", symbol=True),
    Key("M_Nm", "numbers", min_length=1, unit="N·m", required="cond", symbol=True),
    Key("motor_start_torque_Nm", gt=0, unit="N·m", required="cond", symbol=True),
    Key("motor_sync_speed_rad_s", gt=0, unit="rad/s", required="cond", symbol=True),
    Key("delta", gt=0, lt=1, symbol=True),
    Key("flywheel_kgm2", ge=0, unit="kg·m²", symbol=True),
    Key("omega_mean_rad_s", gt=0, unit="rad/s", symbol=True),
    Key("steps", "integer", ge=36, le=MAX_STEPS, shown_default="spec.default.steps"),
    Key("J_engine_extra_kgm2", ge=0, unit="kg·m²", default=0.0),
))

ELEMENT = ArrayOfTables("machine.element", (
    Key("J_kgm2", ge=0, unit="kg·m²", required="cond", symbol=True),
    Key("speed_ratio", required="cond"),
    Key("m_kg", ge=0, unit="kg", required="cond", symbol=True),
    Key("velocity_ratio_m", unit="m", required="cond"),
))

MOMENT = ArrayOfTables("machine.moment", (
    Key("role", "choice", choices=("drive", "resist"), required=True),
    Key("phi_deg", "numbers", min_length=1, unit="°", required=True, symbol=True),
    Key("M_Nm", "numbers", min_length=1, unit="N·m", required=True, symbol=True),
), required=True, min_items=1)

MACHINE = Table("machine", (
    Key("name", "string", default="machine"),
    Key("J_red_kgm2", gt=0, unit="kg·m²", required="cond", default=0.0, symbol=True),
    Key("omega_mean_rad_s", gt=0, unit="rad/s", symbol=True),
    Key("period_deg", gt=0, unit="°", default=360.0),
    ELEMENT,
    MOMENT,
), required=True)

ROTOR_MASS = ArrayOfTables("rotor.mass", (
    Key("mr_gmm", ge=0, unit="g·mm", required="cond"),
    Key("m_g", ge=0, unit="g", required="cond"),
    Key("r_mm", ge=0, unit="mm", required="cond"),
    Key("angle_deg", unit="°", required=True),
    Key("z_mm", unit="mm", required="cond"),
), required=True, min_items=1)

ROTOR = Table("rotor", (
    Key("name", "string", default="rotor"),
    Key("planes_mm", "numbers", min_length=1, unit="mm", required=True),
    Key("correction_radius_mm", gt=0, unit="mm"),
    ROTOR_MASS,
), required=True)

#: ``[balance]`` of a linkage spec (``crankdyn balance LINKAGE.toml``, read by
#: :func:`dynamics.shaking.mechanism_balance`, which names a key given for another kind of
#: mechanism): a crank-rocker's two counterweight radii, a crank-slider's balanced share
#: and radius, a chain's crank counterweight radius.  Declared for the forms (the web's
#: balance page); the reference of the linkage spec tells it in words.
@dataclass(frozen=True)
class _WordsTable(Table):
    """A table whose words are under another path of the catalogue (``[balance]`` of a
    linkage is not the engine's ``[balance]``: ``spec.linkage_balance.*``)."""

    words: str = ""

    @property
    def text_path(self) -> str:
        return self.words or super().text_path


LINKAGE_BALANCE = _WordsTable("balance", (
    Key("fraction", ge=0, le=1, default=0.0),
    Key("radius_m", gt=0, unit="m"),
    Key("radius_crank_m", gt=0, unit="m"),
    Key("radius_rocker_m", gt=0, unit="m"),
), words="linkage_balance")

#: The dynamics spec file (``crankdyn dynamics``): ``[machine]`` + ``[dynamics]``, or a
#: linkage or engine spec with ``[dynamics]``.
SCHEMA = Schema("dynamics", (DYNAMICS, MACHINE))
#: The rotor spec file (``crankdyn balance``).
ROTOR_SCHEMA = Schema("rotor", (ROTOR,))
#: Both, in the order of the README.
SCHEMAS = (SCHEMA, ROTOR_SCHEMA)
