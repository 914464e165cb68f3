"""The terminal summary of a torsional-vibration report, in the report's language.

Every word comes from the text layer (``torsion.po``); numbers are formatted by the
templates, plural forms by gettext's rule of the language.

Examples
--------
>>> from crankbase.resources import example_path
>>> from torsion.study import load, run_study
>>> report = run_study(load(example_path("torsion_three_rotor.toml")))
>>> print(summary_lines(report, "en")[1])
  first natural frequency f1 = 170.69 Hz (1072.5 rad/s), nodes at 1.77 (1-2)
"""
from __future__ import annotations

import numpy as np

from crankbase.texts import texts

__all__ = ["summary_lines", "worst_critical"]


def worst_critical(report):
    """The critical speed in range that the engine excites most: the row of the
    critical-speed table with the largest ``sum_relative_amplitude`` × |M_k| at that
    speed, M_k one cylinder's torque harmonic of the order (gas as in the indicator
    diagram, inertia scaled by (n/n_ref)²): the modal work of the order per cycle, up to
    the mode's scale.  None when there is none."""
    cs = report.critical
    if cs is None or len(cs) == 0:
        return None
    gas, inertia = report.harmonics["gas"], report.harmonics["inertia"]
    index = {round(float(k), 6): i for i, k in enumerate(gas.order)}
    weight = []
    for r in cs.itertuples():
        i = index.get(round(float(r.order), 6))
        Mk = 0.0 if i is None else abs(gas.complex_Nm[i] + inertia.complex_Nm[i]
                                       * (r.speed_rpm / report.speed_ref_rpm) ** 2)
        weight.append(r.sum_relative_amplitude * Mk)
    return cs.iloc[int(np.argmax(weight))]


def _nodes(nodes, names) -> str:
    """Node positions in mass units with the section each lies in: ``6.60 (throw6-flywheel)``."""
    out = []
    for x in np.asarray(nodes, float):
        i = min(max(int(np.floor(x)), 1), len(names) - 1)
        out.append(f"{x:.2f} ({names[i - 1]}-{names[i]})")
    return ", ".join(out)


def summary_lines(report, lang: str = "ru", written=None) -> list[str]:
    """The summary of a :class:`~torsion.study.TorsionReport`: the chain, the first
    natural frequency, then (with an engine) the harmonic series' error, the critical
    speeds (the worst named) and the largest vibration torque; given the
    :class:`~torsion.study.TorsionFiles` written, what was written."""
    t = texts(lang)
    ch, m = report.chain, report.modes
    lines = [t("torsion.summary.chain", name=report.study.name,
               masses=t.n("torsion.summary.masses", ch.n),
               J=float(np.sum(ch.J)))]
    if len(m.f_Hz):
        lines.append(t("torsion.summary.first", f=float(m.f_Hz[0]),
                       omega=float(m.omega_rad_s[0]), nodes=_nodes(m.nodes[0], ch.names) or "—"))
        if len(m.f_Hz) > 1:
            lines.append(t("torsion.summary.others", freqs=", ".join(
                f"{f:.2f}" for f in m.f_Hz[1:6])))
    for note in report.notes:
        lines.append("  " + note.render(lang))
    if report.response is not None:
        h = report.harmonics["total"]
        lines.append(t("torsion.summary.series", order=float(np.max(h.order)),
                       speed=report.speed_ref_rpm,
                       err=100.0 * h.reconstruction_rms_Nm / h.rms_Nm if h.rms_Nm else 0.0))
        cs = report.critical
        lo, hi = report.study.inputs.speed_range_rpm
        n_major = int(cs["major"].sum()) if len(cs) else 0
        lines.append(t("torsion.summary.criticals", count=t.n("torsion.summary.speeds",
                                                               len(cs)),
                       lo=lo, hi=hi, major=n_major))
        w = worst_critical(report)
        if w is not None:
            lines.append(t("torsion.summary.worst", speed=float(w.speed_rpm),
                           mode=int(w["mode"]), order=float(w.order),
                           kind=t("torsion.summary.major") if bool(w.major)
                           else t("torsion.summary.minor"),
                           beta=float(w.sum_relative_amplitude)))
        r = report.response
        speed, sec, M = r.worst
        lines.append(t("torsion.summary.torque", M=float(M), section=ch.section_names[int(sec)],
                       speed=float(speed)))
        if r.stress_MPa is not None:
            i = int(np.argmax(np.max(r.stress_MPa, axis=0)))
            j = int(np.argmax(r.stress_MPa[:, i]))
            lines.append(t("torsion.summary.stress", tau=float(r.stress_MPa[j, i]),
                           section=ch.section_names[i], speed=float(r.speeds_rpm[j])))
    if written is not None:
        lines.append(t("common.wrote", files=t.n("common.files", len(written)),
                       folder=str(written.folder)))
    return lines
