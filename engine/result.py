"""Typed results of the engine calculations (python-control style: compute → result →
``plot_*(result, ax=None, lang=...)``).  Tables are pandas DataFrames; summaries are typed
fields.  Nothing here computes physics."""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:                       # annotations only: no pandas import at run time
    import pandas as pd

    from .spec import EngineSpec, TableSettings

__all__ = ["Extreme", "EngineSummary", "EngineResult"]


@dataclass(frozen=True)
class Extreme:
    """The largest and the smallest value of a quantity over the cycle, with their angles.

    Attributes
    ----------
    max, min : float
        Values, in the unit of their column. [N or N·m]
    alpha_max_deg, alpha_min_deg : float
        Angles where they occur (the first one on a tie). [deg]
    """

    max: float
    alpha_max_deg: float
    min: float
    alpha_min_deg: float


@dataclass(frozen=True)
class EngineSummary:
    """Extremes and cycle means of one cylinder's force table (:func:`engine.summarize`).

    The extremes are named after their table columns: P, Sш, N, K, T, Mкр, Rшш.
    """

    P_N: Extreme
    S_N: Extreme
    N_N: Extreme
    K_N: Extreme
    T_N: Extreme
    M_Nm: Extreme
    R_N: Extreme
    p_max_MPa: float           #: peak gas pressure [MPa]
    alpha_p_max_deg: float     #: its angle [deg]
    M_mean_Nm: float           #: Mкр.ср, cycle mean torque of one cylinder [N·m]
    R_mean_N: float            #: Rшш.ср, cycle mean crank-pin load [N]
    chi: float                 #: χ = Rшш,max/Rшш,ср [-]
    pi_MPa: float              #: indicated mean pressure of the diagram [MPa]
    power_i_kW: float          #: indicated power of one cylinder [kW]
    pi_theory_MPa: float | None  #: p′i of the unrounded computed diagram [MPa]

    def extreme(self, column: str) -> Extreme:
        """The :class:`Extreme` of a table column ("P_N", …, "R_N")."""
        return getattr(self, column)


@dataclass(frozen=True)
class EngineResult:
    """One cylinder's force table with its fine curves and summary (:func:`engine.analyze`).

    Attributes
    ----------
    spec : EngineSpec
    settings : TableSettings
    table : pandas.DataFrame
        The force table at the settings' rows (columns :data:`engine.COLUMNS`).
    curves : pandas.DataFrame
        The same columns on the fine grid (plots, extremes).
    summary : EngineSummary
    """

    spec: EngineSpec
    settings: TableSettings
    table: pd.DataFrame
    curves: pd.DataFrame
    summary: EngineSummary
