"""Table 2 in the textbook's own forms, from a computed force table.

Two forms carry the same numbers:

- ``"seed"`` — the course manual (seed 003, its Table 2): α, β, every force both in mm of
  the drawing (÷ μP) and in N, Mкр, Ψ;
- ``"kolchin"`` — Колчин & Демидов (2008, § "Динамика", the force table): α, β, the
  specific forces per unit piston area in MPa (Δpг, pj, p, pN, pS, pK, pT) beside the
  trigonometric coefficients tg β, 1/cos β, cos(α+β)/cos β, sin(α+β)/cos β that turn p
  into them, then T, K, Rшш [N], Mкр [N·m] and Ψ.

The coefficients are computed here from α and the rod angle β of the table (β from the
RRP dyad's kinematics); the specific forces are the table's forces divided by the piston
area Fп.  So pN = p·tg β, pS = p/cos β, pK = p·cos(α+β)/cos β and pT = p·sin(α+β)/cos β
hold to rounding for the central mechanism: an independent check of the dyad's K, T, N,
Sш, made in the tests.  No plotting or workbook code here.
"""
from __future__ import annotations

import numpy as np

__all__ = ["FORMS", "coefficients", "specific_forces", "table2", "table2_columns",
           "FORCE_PAIRS"]

#: The two textbook forms of Table 2.
FORMS = ("seed", "kolchin")

#: Forces shown in mm and N in the seed's form, in its order (force-table columns).
FORCE_PAIRS = ("dPg_N", "Pj_N", "P_N", "S_N", "N_N", "K_N", "T_N", "R_N")


def coefficients(alpha_deg, beta_deg):
    """The trigonometric coefficients of the force table.

    Parameters
    ----------
    alpha_deg : array_like
        Crank angle from TDC. [deg]
    beta_deg : array_like
        Angle of the rod from the cylinder axis (+ for 0 < α < 180°). [deg]

    Returns
    -------
    dict of ndarray
        ``tg_beta`` tg β, ``inv_cos_beta`` 1/cos β, ``K_coef`` cos(α+β)/cos β,
        ``T_coef`` sin(α+β)/cos β. [-]  (Колчин & Демидов 2008, § "Силы, действующие в
        КШМ": N = p·tg β, S = p/cos β, K = p·cos(φ+β)/cos β, T = p·sin(φ+β)/cos β.)
    """
    a = np.radians(np.asarray(alpha_deg, float))
    b = np.radians(np.asarray(beta_deg, float))
    cb = np.cos(b)
    return dict(tg_beta=np.tan(b), inv_cos_beta=1.0 / cb, K_coef=np.cos(a + b) / cb,
                T_coef=np.sin(a + b) / cb)


def specific_forces(table, area):
    """Forces per unit piston area (Kolchin's specific forces).

    Parameters
    ----------
    table : pandas.DataFrame
        A force table (:func:`engine.force_table`).
    area : float
        Piston area Fп. [m²]

    Returns
    -------
    dict of ndarray
        ``dPg_MPa`` Δpг, ``Pj_MPa`` pj, ``P_MPa`` p, ``N_MPa`` pN, ``S_MPa`` pS,
        ``K_MPa`` pK, ``T_MPa`` pT. [MPa]
    """
    return {f"{c[:-2]}_MPa": table[c].to_numpy() / area * 1e-6
            for c in ("dPg_N", "Pj_N", "P_N", "N_N", "S_N", "K_N", "T_N")}


def table2_columns(form, lang="en"):
    """The column keys of Table 2 in ``form``, in order (ASCII names with units)."""
    if form == "seed":
        cols = ["alpha_deg", "beta_deg"]
        for f in FORCE_PAIRS:
            cols += [f[:-2] + "_mm", f]
        return cols + ["M_Nm", "psi_deg"]
    if form == "kolchin":
        return ["alpha_deg", "beta_deg", "dPg_MPa", "Pj_MPa", "P_MPa", "tg_beta", "N_MPa",
                "inv_cos_beta", "S_MPa", "K_coef", "K_MPa", "T_coef", "T_MPa", "T_N",
                "K_N", "R_N", "M_Nm", "psi_deg"]
    raise ValueError(f"table form: got {form!r}; valid: {', '.join(FORMS)}")


def table2(table, spec, settings, form=None):
    """Table 2 of ``table`` in a textbook ``form`` (see the module docstring).

    Parameters
    ----------
    table : pandas.DataFrame
        From :func:`engine.force_table`.
    spec : EngineSpec
        For the piston area.
    settings : TableSettings
        For μP (``force_scale`` [N/mm]) and the default ``form``.
    form : {"seed", "kolchin"}, optional
        Overrides ``settings.form``.

    Returns
    -------
    pandas.DataFrame
        Columns :func:`table2_columns`: forces ``*_mm`` [mm of the drawing], ``*_N`` [N],
        ``*_MPa`` [MPa], coefficients [-], ``M_Nm`` [N·m], angles [deg].
    """
    import pandas as pd

    form = settings.form if form is None else form
    cols = table2_columns(form)
    data = {c: table[c].to_numpy() for c in table.columns}
    for f in FORCE_PAIRS:
        data[f[:-2] + "_mm"] = table[f].to_numpy() / settings.force_scale
    data.update(coefficients(table["alpha_deg"], table["beta_deg"]))
    data.update(specific_forces(table, spec.area))
    return pd.DataFrame({c: data[c] for c in cols}, columns=cols)
