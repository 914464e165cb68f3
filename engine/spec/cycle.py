"""The indicator diagram computed from the thermal calculation: ``[pressure.cycle]``.

:func:`read_cycle` reads the table through the schema (:data:`engine.schema.CYCLE`) and
checks what joins its keys (pz above pc, ρ below ε, the roundings apart);
:func:`check_rounded_peak` checks the rounded peak against the expansion line once the
rod ratio is known.
"""
from __future__ import annotations

from crankbase.errors import Text
from ..indicator import JOIN_AFTER_PEAK_DEG, CycleSpec, sharp_cycle_pressure
from ..schema import CYCLE, ROUNDING_DEFAULTS

__all__ = ["read_cycle", "check_rounded_peak"]


def check_rounded_peak(c, cyc, lam, k):
    """The real (rounded) diagram lies inside the theoretical one: its peak
    peak_factor·pz must not rise above the expansion line at the peak angle, and must be
    the maximum (the line where the rounding rejoins it must be lower)."""
    a = 360.0 + cyc.peak_after_tdc_deg
    line = float(sharp_cycle_pressure([a], cyc, lam, k=k)[0])
    peak = cyc.peak_factor * cyc.pz
    if peak > line:
        c.add("pressure.cycle.peak_factor",
              Text("errors.engine.cycle.rounded_peak_peak",
                   {"peak": peak / 1e6, "a": a, "line": line / 1e6}))
        return
    join = a + JOIN_AFTER_PEAK_DEG
    after = float(sharp_cycle_pressure([join], cyc, lam, k=k)[0])
    if after >= peak:
        c.add("pressure.cycle.peak_factor",
              Text("errors.engine.cycle.expansion_line_at",
                   {"join": join, "after": after / 1e6, "peak": peak / 1e6}))


def read_cycle(c, cy, strokes):
    """A :class:`~engine.CycleSpec` from the ``[pressure.cycle]`` dict ``cy`` (None on a
    problem, recorded in the :class:`~crankbase.schema.SpecReader` ``c``)."""
    path = "pressure.cycle"

    def get(key, **kw):
        return c.get(cy, CYCLE, key, **kw)

    kind = get("kind")
    if strokes != 4:
        c.add(path, Text("errors.engine.cycle.computed_diagram_available"))
    eps = get("compression_ratio")
    pa = get("pa_MPa")
    pr = get("pr_MPa")
    n1 = get("n1")
    n2 = get("n2")
    if "pz_MPa" in cy and "lambda_z" in cy:
        c.add(f"{path}.pz_MPa", Text("errors.engine.cycle.give_either_pz"))
        pz = lz = None
    elif "lambda_z" in cy:
        lz = get("lambda_z", required=True)
        pz = None
    else:
        pz = get("pz_MPa", required=True)
        lz = None
    if kind == "diesel":
        rho = get("rho", required=True)
    else:
        if "rho" in cy:
            c.add(f"{path}.rho", Text("errors.engine.cycle.only_used_with"))
        rho = 1.0
    rounding = get("rounding")
    opts = {k: get(k) for k in ROUNDING_DEFAULTS}
    opts["advance_deg"] = get("advance_deg")
    if None in (kind, eps, pa, pr, n1, n2, rho) or (pz is None and lz is None) \
            or None in (v for k, v in opts.items() if k != "advance_deg"):
        return None
    cyc = CycleSpec(kind=kind, compression_ratio=eps, pa=pa * 1e6, pr=pr * 1e6, n1=n1,
                    n2=n2, pz_input=None if pz is None else pz * 1e6, lambda_z_input=lz,
                    rho=rho, rounding=rounding, **opts)
    if pz is not None and cyc.pz < cyc.pc:
        c.add(f"{path}.pz_MPa", Text("errors.engine.cycle.compression_pressure_pc",
                                     {"pz": pz, "value": cyc.pc / 1e6}))
        return None
    if kind == "diesel" and rho >= eps:
        c.add(f"{path}.rho", Text("errors.engine.cycle.compression_ratio",
                                  {"rho": rho, "eps": eps}))
        return None
    if rounding and (360 + opts["peak_after_tdc_deg"] + JOIN_AFTER_PEAK_DEG
                     > 540 - opts["exhaust_opening_deg"]):
        c.add(f"{path}.exhaust_opening_deg", Text("errors.engine.cycle.combustion_rounding_peak",
                                                  {"JOIN_AFTER_PEAK_DEG": JOIN_AFTER_PEAK_DEG}))
        return None
    if rounding and opts["peak_factor"] * cyc.pz < opts["pc_factor"] * cyc.pc:
        c.add(f"{path}.peak_factor", Text("errors.engine.cycle.rounded_peak_peak_2"))
        return None
    return cyc
