"""The typed result of a dynamics run (:class:`DynamicsReport`), apart from the study
module so that :func:`dynamics.spec.run_job` and :mod:`dynamics.study` both use it without
importing each other."""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["DynamicsReport", "MOTION_COLUMNS"]

#: The motion table's columns, in order (a linkage adds its own after them).
MOTION_COLUMNS = ["phi_deg", "J_red_kgm2", "dJ_red_dphi_kgm2", "M_drive_Nm", "M_resist_Nm",
                  "omega_rad_s", "eps_rad_s2", "t_s", "phi_rad", "W_J", "E_J"]


@dataclass
class DynamicsReport:
    """Everything one dynamics run computed (nothing written).

    Also read as the mapping the plots and the workbook take (``report["motion"]``,
    ``report.get("startup")``: the keys ``model``, ``motion``, ``flywheel``, ``startup``,
    ``forces``), as :func:`dynamics.spec.run_job` returned before.

    Attributes
    ----------
    name : str
        The spec's name.
    kind : {"machine", "linkage", "engine"}
    driving : {"constant", "table", "motor"}
    model : dynamics.reduced.ReducedModel
    motion : dynamics.motion.MotionResult
    flywheel : FlywheelResult or None
        With a required δ.
    startup : StartupResult or None
        With a motor.
    forces : pandas.DataFrame or None
        Under the true motion (linkage; engine cylinder 1).
    settings : dynamics.spec.DynamicsSettings
    source : str or None
        The spec file.
    notes : tuple of str
        What the run assumed (``"delta_from_flywheel"``, ``"no_flywheel"``).
    """

    name: str
    kind: str
    driving: str
    model: object
    motion: object
    flywheel: object = None
    startup: object = None
    forces: object = None
    settings: object = None
    source: str | None = None
    notes: tuple = ()

    _KEYS = ("model", "motion", "flywheel", "startup", "forces")

    def __getitem__(self, key):
        if key not in self._KEYS:
            raise KeyError(key)
        return getattr(self, key)

    def get(self, key, default=None):
        return getattr(self, key) if key in self._KEYS else default

    def keys(self):
        return list(self._KEYS)

    def __contains__(self, key):
        return key in self._KEYS

    @property
    def stem(self) -> str:
        """File stem of every output (the name, :func:`crankbase.output.safe_name`)."""
        from crankbase.output import safe_name

        return safe_name(self.name, "machine")

    def tables(self) -> dict:
        """The CSV tables by file name: ``<stem>_motion.csv`` (columns in the documented
        order), ``<stem>_forces_true_motion.csv`` (linkage, engine), ``<stem>_startup.csv``
        (motor): what :func:`write_report` writes, bit for bit."""
        table = self.motion.table
        extra = [c for c in table.columns if c not in MOTION_COLUMNS]
        out = {"motion.csv": table[MOTION_COLUMNS + extra]}
        if self.forces is not None:
            out["forces_true_motion.csv"] = self.forces
        if self.startup is not None:
            out["startup.csv"] = self.startup.table
        return {f"{self.stem}_{k}": v for k, v in out.items()}
