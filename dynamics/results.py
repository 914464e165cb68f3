"""The typed result of a dynamics run (:class:`DynamicsReport`), apart from the study
module so that :func:`dynamics.spec.run_job` and :mod:`dynamics.study` both use it without
importing each other; and the reduced model (:class:`ReducedModel`, also
``dynamics.reduced.ReducedModel``), apart from :mod:`dynamics.reduced` so that
:mod:`dynamics.chain_model` builds it without an import circle."""
from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

__all__ = ["DynamicsReport", "MOTION_COLUMNS", "ReducedModel"]

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


@dataclass
class ReducedModel:
    """Reduced quantities of a machine over one period, on a uniform grid.

    Attributes
    ----------
    name : str
    phi : ndarray
        Angle turned by the main shaft in its direction of rotation, ``0 … period``
        inclusive (the last point repeats the first one a period later), increasing;
        uniform for a linkage or an engine, with the diagrams' breakpoints added for a
        machine. [rad]
    J_kgm2 : ndarray
        Reduced moment of inertia J_red(φ) (without an added flywheel). [kg·m²]
    dJ_dphi_kgm2 : ndarray
        dJ_red/dφ. [kg·m²/rad]
    M_drive_Nm, M_resist_Nm : ndarray
        Reduced driving moment (+ in the direction of rotation) and reduced resisting
        moment (+ against it). [N·m]
    W_drive_J, W_resist_J : ndarray
        Their work from φ = 0: ∫M dφ (exact for piecewise-linear diagrams). [J]
    period : float
        [rad]
    omega_nominal : float or None
        The machine's nominal (mean) speed if its spec gives one. [rad/s]
    phi0_deg : float
        The crank angle of the mechanism at φ = 0 (absolute, ccw from +x), for a linkage;
        0 otherwise. [deg]
    rotation : int
        +1 (ccw) or −1: absolute crank angle = phi0_deg + rotation·φ.
    source : object
        What the model was built from (a linkage spec, a machine spec).
    """

    name: str
    phi: np.ndarray
    J_kgm2: np.ndarray
    dJ_dphi_kgm2: np.ndarray
    M_drive_Nm: np.ndarray
    M_resist_Nm: np.ndarray
    W_drive_J: np.ndarray
    W_resist_J: np.ndarray
    period: float
    omega_nominal: float | None = None
    phi0_deg: float = 0.0
    rotation: int = 1
    source: object = None
    extra: dict = field(default_factory=dict)

    @property
    def phi_deg(self):
        """Absolute crank angle of every grid point (for a linkage; φ in degrees for a
        machine), not wrapped. [deg]"""
        return self.phi0_deg + self.rotation * np.degrees(self.phi)

    @property
    def W_net_J(self):
        """∫(M_d − M_c)dφ from φ = 0. [J]"""
        return self.W_drive_J - self.W_resist_J

    def with_drive(self, M_drive_Nm, W_drive_J):
        return replace(self, M_drive_Nm=np.asarray(M_drive_Nm, float) + 0 * self.phi,
                       W_drive_J=np.asarray(W_drive_J, float) + 0 * self.phi)

    def with_constant_drive(self):
        """The same machine with the constant moment that makes the cycle steady.

        Returns ``(model, M_const)``.  Normally a constant driving moment
        M_d = (∫M_c dφ − ∫M_d,given dφ)/period is added to the given driving moments; a
        machine given by its driving moments only (an engine's turning-moment diagram)
        gets a constant *resisting* moment ∫M_d dφ/period instead (``M_const`` is then
        returned negative: it is the drive's deficit)."""
        extra = (self.W_resist_J[-1] - self.W_drive_J[-1]) / self.period
        if not np.any(self.M_resist_Nm) and not np.any(self.W_resist_J) and extra < 0:
            return replace(self, M_resist_Nm=self.M_resist_Nm - extra,
                           W_resist_J=self.W_resist_J - extra * self.phi), float(extra)
        return self.with_drive(self.M_drive_Nm + extra, self.W_drive_J + extra * self.phi), \
            float(extra)
