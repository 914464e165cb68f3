"""Characteristic points of the indicator diagram and its fullness.

The points of Kolchin & Demidov (2008, § "Построение индикаторных диаграмм",
"Скругление индикаторной диаграммы"): r (TDC, start of intake), a (BDC, end of intake),
c′ (ignition / injection, 360° − θ), c (end of compression of the unrounded diagram, pc),
c″ (TDC on the rounded diagram, pc″ = pc_factor·pc), zд (the real peak), b′ (exhaust valve
opening, 540° − the opening angle), b″ (BDC on the rounded blow-down).  The angles come
from the spec; the plots read the pressure of the points that lie on the diagram off the
computed table (:func:`engine.force_table`), and draw c (and z of an unrounded Otto
diagram) at its pressure from the thermal calculation.
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["DiagramPoint", "characteristic_points", "fullness"]


@dataclass(frozen=True)
class DiagramPoint:
    """A named point: ``alpha_deg`` [deg]; ``p`` [Pa] when it is a point of the thermal
    calculation off the drawn curve, else None (read it off the curve)."""

    name_ru: str
    name_en: str
    alpha_deg: float
    p: float | None = None


def characteristic_points(spec, table=None):
    """The characteristic points of ``spec``'s indicator diagram, in crank-angle order.

    Parameters
    ----------
    spec : EngineSpec
    table : pandas.DataFrame, optional
        A force table; for a tabulated diagram its peak gives zд.

    Returns
    -------
    list of DiagramPoint
    """
    pts = [DiagramPoint("r", "r", 0.0), DiagramPoint("a", "a", 180.0)]
    cyc = spec.cycle
    if cyc is not None and cyc.rounding:
        pts += [DiagramPoint("c′", "c′", 360.0 - cyc.advance),
                DiagramPoint("c", "c", 360.0, cyc.pc),
                DiagramPoint("c″", "c″", 360.0),
                DiagramPoint("zд", "z,real", 360.0 + cyc.peak_after_tdc_deg),
                DiagramPoint("b′", "b′", 540.0 - cyc.exhaust_opening_deg),
                DiagramPoint("b″", "b″", 540.0)]
    elif cyc is not None:
        pts += [DiagramPoint("c", "c", 360.0, cyc.pc)]
        if cyc.kind == "otto":
            pts += [DiagramPoint("z", "z", 360.0, cyc.pz)]
        pts += [DiagramPoint("b", "b", 540.0)]
    elif table is not None and spec.strokes == 4:
        a = table["alpha_deg"].to_numpy()
        i = int(table["p_gas_MPa"].to_numpy().argmax())
        pts += [DiagramPoint("zд", "z,real", float(a[i])), DiagramPoint("b″", "b″", 540.0)]
    if spec.strokes == 2:
        pts = [p for p in pts if p.alpha_deg <= 360.0]
    return sorted(pts, key=lambda p: (p.alpha_deg, p.p is None))


def fullness(summary):
    """Fullness of the rounded diagram φп = pi/p′i (Kolchin & Demidov 2008: 0.92–0.97),
    or None when the unrounded p′i is not known (a tabulated diagram). [-]"""
    pt = summary.pi_theory_MPa
    return None if not pt else summary.pi_MPa / pt
