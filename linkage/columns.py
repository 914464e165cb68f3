"""Column names of the linkage tables and the reported points (:func:`linkage.analyze`,
:func:`linkage.analysis.solve_columns`, the reports)."""
from __future__ import annotations

from .course import course_of
from .spec import LINK_NUMBER, MechanismSpec

__all__ = ["point_names", "kinematics_columns", "force_columns", "derived_kinematics_columns",
           "derived_force_columns"]


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


def kinematics_columns(spec: MechanismSpec, course_tables=True):
    """Names of the kinematics table's columns, in order (with the course tables'
    magnitudes at the end unless ``course_tables`` is False)."""
    cols = ["position", "phi_deg", "theta3_deg", "omega3_rad_s", "eps3_rad_s2"]
    cols += course_of(spec).output_columns
    for p in point_names(spec):
        cols += [f"{p}_x_m", f"{p}_y_m", f"{p}_vx_m_s", f"{p}_vy_m_s",
                 f"{p}_ax_m_s2", f"{p}_ay_m_s2"]
    cols += ["mu_deg"]
    return cols + (derived_kinematics_columns(spec) if course_tables else [])


def derived_kinematics_columns(spec: MechanismSpec):
    """The course tables' magnitudes appended to the kinematics table (see
    :mod:`linkage.derived`): speed and acceleration of every point, and the relative
    motion of B about A (and about C for a crank-rocker)."""
    pts = list(point_names(spec))
    rel = [r[0] for r in course_of(spec).relative]
    cols = [f"{p}_v_m_s" for p in pts] + [f"{p}_a_m_s2" for p in pts]
    cols += [f"v_{r}_m_s" for r in rel]
    for r in rel:
        cols += [f"a_{r}_n_m_s2", f"a_{r}_t_m_s2", f"a_{r}_m_s2"]
    return cols


def force_columns(spec: MechanismSpec, course_tables=True):
    """Names of the force table's columns, in order (with the force inputs and reaction
    magnitudes at the end unless ``course_tables`` is False)."""
    cols = ["position", "phi_deg", "R12_x_N", "R12_y_N", "R23_x_N", "R23_y_N",
            "R43_x_N", "R43_y_N", "R14_x_N", "R14_y_N", "M_drive_Nm", "R23_n_N", "R23_t_N"]
    course = course_of(spec)
    cols += [c for c, _ in course.frame_pair] + [course.resistance_column]
    return cols + (derived_force_columns(spec) if course_tables else [])


def derived_force_columns(spec: MechanismSpec):
    """The force inputs and reaction magnitudes appended to the force table (see
    :mod:`linkage.derived`): per link i its weight ``Gi_N``, d'Alembert inertia force
    ``Fui_x_N``, ``Fui_y_N``, ``Fui_N`` and (rotating links) inertia moment ``Mui_Nm``;
    then ``R12_N``, ``R23_N``, ``R43_N``, ``R14_N``."""
    cols = []
    for lname in spec.link_names:
        i = LINK_NUMBER[lname]
        cols += [f"G{i}_N", f"Fu{i}_x_N", f"Fu{i}_y_N", f"Fu{i}_N"]
        if lname != "slider":
            cols += [f"Mu{i}_Nm"]
    return cols + ["R12_N", "R23_N", "R43_N", "R14_N"]
