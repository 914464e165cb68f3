"""The terminal summary of an engine report, in the report's language.

Every word comes from the text layer (:mod:`crankbase.texts`, ``engine.po``): a Russian
summary speaks in the textbook's symbols (pг, Mкр.ср, Rшш, χ) and holds no English word,
an English one holds no Cyrillic letter.  Numbers are formatted by the templates, so a
translation controls the word order.

Examples
--------
>>> import engine
>>> from crankbase.resources import example_path
>>> report = engine.run_study(engine.load(example_path("petrol_vaz2106.toml")))
>>> print(summary_lines(report, "en")[2])
  P max                   13905 N    at alpha = 372.5 deg
"""
from __future__ import annotations

from crankbase.texts import texts

__all__ = ["summary_lines", "summary_text", "cylinder_lines", "whole_engine_lines",
           "bearing_lines", "written_line"]


def summary_lines(report, lang: str = "ru", written=None) -> list[str]:
    """The terminal summary of an :class:`~engine.study.EngineReport`: the cylinder, the
    whole engine, the bearings (when computed) and, given the
    :class:`~engine.study.ReportFiles` of :func:`engine.write_report`, what was written."""
    lines = cylinder_lines(report.cylinder, lang) + whole_engine_lines(report.whole, lang)
    if report.bearings is not None:
        lines += bearing_lines(report.bearings.analysis, report.bearings.pin_wear, lang)
    if getattr(report, "torsion", None) is not None:       # [torsion]
        from torsion.summary import summary_lines as torsion_lines

        lines += torsion_lines(report.torsion, lang)
    if written is not None:
        lines.append(written_line(written, lang))
    return lines


def summary_text(report, lang: str = "ru", written=None) -> str:
    """:func:`summary_lines` joined by newlines."""
    return "\n".join(summary_lines(report, lang, written))


def cylinder_lines(result, lang: str = "ru") -> list[str]:
    """The summary of one cylinder (an :class:`~engine.EngineResult`): the engine, the
    peak pressure and pi, the largest P and T, the mean torque, Rшш and χ."""
    t = texts(lang)
    spec, s = result.spec, result.summary
    P, T, R = s.P_N, s.T_N, s.R_N
    accel = {"two-term": t("engine.summary.acceleration_two_term"),
             "exact": t("engine.summary.acceleration_exact")}.get(spec.acceleration,
                                                                   spec.acceleration)
    chi = f"{s.chi:.3f}" if s.chi == s.chi else t("engine.summary.chi_undefined")
    return [
        t("engine.summary.engine", name=spec.name, strokes=spec.strokes,
          bore_mm=spec.bore * 1e3, stroke_mm=spec.stroke * 1e3, lam=spec.lam,
          speed_rpm=spec.speed_rpm, acceleration=accel),
        t("engine.summary.peak_pressure", p_max=s.p_max_MPa, alpha=s.alpha_p_max_deg,
          pi=s.pi_MPa),
        t("engine.summary.P_max", P=P.max, alpha=P.alpha_max_deg),
        t("engine.summary.T_max", T=T.max, alpha=T.alpha_max_deg),
        t("engine.summary.M_mean", M=s.M_mean_Nm),
        t("engine.summary.R_max", R=R.max, alpha=R.alpha_max_deg, R_mean=s.R_mean_N, chi=chi),
    ]


def whole_engine_lines(whole, lang: str = "ru") -> list[str]:
    """The summary of the whole engine (an :class:`~engine.EngineTrainResult`): layout,
    total torque and its uniformity, Mi/Me/Ni/Ne, Lизб and the flywheel, the balance and
    the counterweights."""
    t = texts(lang)
    ws, lay = whole.summary, whole.layout
    arrangement = {"inline": t("engine.summary.inline"), "vee": t("engine.summary.vee"),
                   "boxer": t("engine.summary.boxer")}.get(whole.train.arrangement,
                                                           whole.train.arrangement)
    crankshaft = {"given": t("engine.summary.throws_given"),
                  "default for even firing": t("engine.summary.throws_default")
                  }.get(lay.crankshaft, lay.crankshaft)
    lines = [
        t("engine.summary.layout", n=lay.n, arrangement=arrangement,
          order="-".join(map(str, lay.firing_order)),
          throws=", ".join(f"{x:g}" for x in lay.throw_angles_deg), crankshaft=crankshaft,
          uneven="" if lay.even_firing else t("engine.summary.uneven_firing")),
        t("engine.summary.total_torque", M_mean=ws.M_mean_Nm, M_max=ws.M_max_Nm,
          alpha_max=ws.alpha_M_max_deg, M_min=ws.M_min_Nm, alpha_min=ws.alpha_M_min_deg,
          mu=ws.mu),
        t("engine.summary.indicated", Mi=ws.Mi_Nm, diff_pct=ws.diff_pct, Ni=ws.Ni_kW,
          effective="" if ws.Me_Nm is None else
          t("engine.summary.effective", Me=ws.Me_Nm, Ne=ws.Ne_kW)),
        t("engine.summary.excess_work", L=ws.L_excess_J,
          flywheel="" if ws.flywheel is None else
          t("engine.summary.J0", J0=ws.flywheel.J0_kgm2, delta=ws.flywheel.delta,
            mD2=ws.flywheel.mD2_kgm2)),
    ]
    amp = whole.balance_amplitudes.set_index("part")
    orders = {"1": t("engine.summary.order_1"), "2": t("engine.summary.order_2"),
              "r": t("engine.summary.order_rotating")}
    unbalanced = ", ".join(orders[p] for p in ("1", "2", "r")
                           if not (amp.loc[p, "F_balanced"] and amp.loc[p, "M_balanced"]))
    lines.append(t.n("engine.summary.balance", len(ws.counterweights),
                     F=amp.loc["after", "F_max_N"], M=amp.loc["after", "M_max_Nm"],
                     unbalanced=unbalanced or t("common.none")))
    fw = ws.flywheel if ws.flywheel is not None and ws.flywheel.mass_kg is not None \
        else None
    if fw is not None:
        lines.append(t("engine.summary.flywheel", J=fw.J_flywheel_kgm2, share=fw.share,
                       D_mm=fw.diameter_m * 1e3, m=fw.mass_kg, v=fw.rim_speed_m_s))
    lines += [t("engine.summary.counterweight", mr=cw.mr * 1e3, angle=cw.angle_deg,
                z=cw.z * 1e3) for cw in ws.counterweights]
    return lines


def bearing_lines(analysis, pin_wear, lang: str = "ru") -> list[str]:
    """The summary of a bearing analysis (its crank-pin wear diagrams ``pin_wear``): the
    most loaded crank pin and main journal, the journal torques, the oil holes, the rigid
    rod against the two-mass one, and the notes."""
    from ..bearings.analysis import NOTE_NO_PISTON_MASS

    t = texts(lang)
    L = analysis.loads
    kp, jm, jt = L.most_loaded_pin, L.most_loaded_journal, L.most_twisted_journal
    ps, js, ts = L.pin_stats[kp - 1], L.journal_stats[jm - 1], L.torque_stats[jt - 1]
    lines = [
        t("engine.summary.crank_pins", k=kp, max=ps.max_N, alpha=ps.alpha_max_deg,
          mean=ps.mean_N, chi=ps.chi,
          holes=", ".join(f"{w.oil_hole_deg:g}" for w in pin_wear)),
        t("engine.summary.main_journals", k=jm, max=js.max_N, mean=js.mean_N, chi=js.chi,
          holes=", ".join(f"{w.oil_hole_deg:g}" for w in analysis.journal_wear)),
        t("engine.summary.journal_torques", k=jt, max=ts["max_Nm"], min=ts["min_Nm"],
          half=analysis.options.wear_half_angle_deg)]
    if analysis.rod_comparison is not None:
        ext = analysis.rod_comparison.extremes
        lines.append(t("engine.summary.rigid_rod",
                       dT_min=ext["dT_N"][2], dT_max=ext["dT_N"][0],
                       dM_min=ext["dM_Nm"][2], dM_max=ext["dM_Nm"][0],
                       dR_min=ext["dR_N"][2], dR_max=ext["dR_N"][0]))
    notes = {NOTE_NO_PISTON_MASS: t("engine.summary.note_no_piston_mass")}
    lines += [t("engine.summary.note", note=notes.get(n, n)) for n in analysis.notes]
    return lines


def written_line(written, lang: str = "ru") -> str:
    """What :func:`engine.write_report` wrote (its :class:`~engine.study.ReportFiles`):
    every table and the workbook by name, the number of figures and their formats, the
    drawing-scale PDFs by name, and the folder."""
    t = texts(lang)
    names = [p.name for p in written.tables] + [written.workbook.name]
    if written.plot_count:                       # none when written with formats=()
        names.append(t.n("engine.summary.plots", written.plot_count,
                         formats=", ".join(f.upper() for f in written.formats)))
    names += [p.name for p in written.drawings]
    if getattr(written, "torsion", ()):
        names.append(t.n("torsion.summary.files", len(written.torsion)))
    return t("common.wrote", files=", ".join(names), folder=str(written.folder))
