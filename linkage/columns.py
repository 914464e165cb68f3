"""Column names of the linkage tables and the reported points (shared by the group-routine
reference :func:`linkage.analysis.solve_columns` and the fused :mod:`linkage.kernel`)."""
from __future__ import annotations

from .spec import LINK_NUMBER, MechanismSpec

__all__ = ["point_names", "kinematics_columns", "force_columns"]


def point_names(spec: MechanismSpec):
    """Reported points: name → (link name, local coordinates) in report order."""
    out = {"A": ("crank", complex(spec.crank, 0.0)),
           "B": ("coupler", complex(spec.coupler, 0.0))}
    for lname in spec.link_names:
        out[f"S{LINK_NUMBER[lname]}"] = (lname, spec.links[lname].cg)
    for lname in spec.link_names:
        for pname, local in spec.links[lname].points.items():
            out[pname] = (lname, local)
    return out


def kinematics_columns(spec: MechanismSpec):
    """Names of the kinematics table's columns, in order."""
    cols = ["position", "phi_deg", "theta3_deg", "omega3_rad_s", "eps3_rad_s2"]
    if spec.kind == "crank-rocker":
        cols += ["theta4_deg", "omega4_rad_s", "eps4_rad_s2"]
    else:
        cols += ["s4_m", "v4_m_s", "a4_m_s2"]
    for p in point_names(spec):
        cols += [f"{p}_x_m", f"{p}_y_m", f"{p}_vx_m_s", f"{p}_vy_m_s",
                 f"{p}_ax_m_s2", f"{p}_ay_m_s2"]
    cols += ["mu_deg"]
    return cols


def force_columns(spec: MechanismSpec):
    """Names of the force table's columns, in order."""
    cols = ["position", "phi_deg", "R12_x_N", "R12_y_N", "R23_x_N", "R23_y_N",
            "R43_x_N", "R43_y_N", "R14_x_N", "R14_y_N", "M_drive_Nm", "R23_n_N", "R23_t_N"]
    if spec.kind == "crank-rocker":
        cols += ["R14_n_N", "R14_t_N", "M_res_Nm"]
    else:
        cols += ["N14_N", "M14_Nm", "F_res_N"]
    return cols
