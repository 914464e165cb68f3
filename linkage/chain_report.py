"""The report of a chain (any linkage of class II groups): CSV files, the workbook, the
figures and the summary's lines.

Columns are named after the spec's joints and links (:mod:`linkage.chain_analysis`);
their symbols in the workbook and the plots are built from the name (``v_E_m_s`` → VE,
m/s; ``omega_lever_rad_s`` → ω lever, rad/s; ``R_crank_block_N`` → R crank→block, N),
the units in the report's language; the words are the catalogue's (``linkage.chain.*``
in ``crankbase/locale/<lang>/linkage.po``).  matplotlib and openpyxl are imported inside
the functions.
"""
from __future__ import annotations

import math

import numpy as np

from crankbase.output import paused_gc

__all__ = ["chain_column_label", "write_chain_csvs", "write_chain_workbook",
           "chain_figures", "chain_summary_rows", "plot_chain_plan", "plot_chain_moment",
           "plot_output_motion", "CHAIN_PLOTS"]

#: File stems of the chain's figures (``<name>_<stem>.png``).
CHAIN_PLOTS = ("plan", "driving_moment", "output_motion")

_GREEK = {"theta": "θ", "omega": "ω", "eps": "ε", "mu": "μ"}
_POINT = {"x": "x{}", "y": "y{}", "vx": "V{}x", "vy": "V{}y", "v": "V{}", "ax": "a{}x",
          "ay": "a{}y", "a": "a{}"}


def chain_column_label(col: str, lang: str = "en"):
    """(symbol, unit) of a chain table column in ``lang``: ``x_B_m`` → ("xB", "m"),
    ``omega_lever_rad_s`` → ("ω lever", "rad/s"), ``R_crank_block_N`` →
    ("R crank→block", "N"); Mур, Fпс, Mпс as :func:`linkage.report.column_label`."""
    from .report import COLUMN_UNITS, column_label, unit_suffix, unit_text

    if col in ("position", "phi_deg", "M_drive_Nm", "F_res_N", "M_res_Nm"):
        return column_label(col, lang)
    split = unit_suffix(col)
    if split is None:
        return col, ""
    body, unit = split
    head, _, rest = body.partition("_")
    if head in _POINT and unit.startswith("m"):
        name = rest.replace("_", " ")
        sym = _POINT[head].format(name if len(name) == 1 else f" {name} ").strip()
    elif head in _GREEK:
        sym = f"{_GREEK[head]} {rest.replace('_', '–')}"
    elif head in ("Rx", "Ry", "R", "Rn", "Rt", "Mp"):
        sym = f"{head} {rest.replace('_', '→', 1).replace('_', ' ')}"
    elif head in ("s", "vrel", "arel", "acor", "acorx", "acory"):
        sym = f"{head} {rest.replace('_', '/')}"
    else:
        sym = body
    return sym, unit_text(COLUMN_UNITS[unit], lang)


def write_chain_csvs(result, folder):
    """``kinematics.csv`` and ``forces.csv`` of a chain analysis into ``folder``."""
    from pathlib import Path

    from crankbase.output import write_csv

    folder = Path(folder)
    write_csv(result.kinematics, folder / "kinematics.csv")
    write_csv(result.forces, folder / "forces.csv")


def chain_summary_rows(result, lang="ru") -> list:
    """The lines of the cycle's summary in ``lang``: the structure formula, the mobility,
    the output's stroke or swing, the strokes' crank angles and K, the least transmission
    angle of every group."""
    from crankbase.texts import texts

    t = texts(lang)
    sm = result.summary
    W, n, p5, p4 = sm.mobility
    rows = [t("linkage.chain.summary.structure", formula=sm.structure),
            t("linkage.chain.summary.mobility", W=W, n=n, p5=p5, p4=p4)]
    if sm.has_extremes:
        if sm.output_kind == "slider":
            rows.append(t("linkage.chain.summary.stroke", link=sm.output, H=sm.travel,
                          start=sm.start, end=sm.end))
        else:
            rows.append(t("linkage.chain.summary.swing", link=sm.output, psi=sm.travel,
                          start=sm.start, end=sm.end))
        rows.append(t("linkage.chain.summary.strokes", a=sm.phi_working_start_deg,
                      b=sm.phi_working_end_deg, work=sm.working_crank_angle_deg,
                      idle=sm.idle_crank_angle_deg, K=sm.time_ratio))
    else:
        rows.append(t("linkage.chain.summary.no_extremes", link=sm.output))
    for key, (mu, phi) in sm.mu_min_deg.items():
        rows.append(t("linkage.chain.summary.mu_min", group=key.replace("_", "–"),
                      mu=mu, phi=phi))
    return rows


@paused_gc()            # thousands of cells: no collection scans them
def write_chain_workbook(result, path, lang="ru"):
    """The workbook of a chain: the summary, the kinematics and the forces (each table's
    header: the symbol and unit in ``lang`` over the CSV column name)."""
    from crankbase import workbook as wbk
    from crankbase.texts import texts

    t = texts(lang)
    wb = wbk.new_workbook()
    ws = wb.active
    ws.title = t("linkage.chain.sheet.summary")
    ws.cell(1, 1, t("linkage.chain.sheet.title", name=result.spec.name)).font = \
        wbk.font(bold=True, size=13)
    for i, line in enumerate(chain_summary_rows(result, lang), start=3):
        ws.cell(i, 1, line)
    for key, df in (("kinematics", result.kinematics), ("forces", result.forces)):
        ws = wb.create_sheet(t(f"linkage.chain.sheet.{key}"))
        labels = []
        for c in df.columns:
            sym, unit = chain_column_label(c, lang)
            labels.append(f"{sym}, {unit}" if unit else sym)
        row = wbk.header_rows(ws, 1, labels, list(df.columns))
        for i, rec in enumerate(df.itertuples(index=False), start=row):
            for j, v in enumerate(rec, start=1):
                if v is None or (isinstance(v, float) and not math.isfinite(v)):
                    continue
                ws.cell(i, j, int(v) if j == 1 else float(v))
        ws.freeze_panes = ws.cell(row, 3)
        wbk.page_setup(ws, title_rows=f"1:{row - 1}")
    wbk.finish(wb)
    wbk.save(wb, path)
    return path


# ----------------------------------------------------------------------------- figures


def link_segments(mech, res):
    """Per link, the names (or global arrays) of the points its drawing joins, from its
    origin: ``[(link, origin Vec, [Vec ...])]``."""
    out = []
    d = mech.driver
    extra = {ln: [res.point(p).z for p in mech.links[ln].points] for ln in mech.link_names}
    out.append((d.link, res.point(d.pivot).z, [res.point(d.joint).z] + extra[d.link]))
    for grp in mech.groups:
        a, b = grp.links
        la, lb = res.links[a], res.links[b]
        if grp.kind == "RRR":
            out.append((a, la.origin.z, [res.point(grp.joints[1]).z] + extra[a]))
            out.append((b, lb.origin.z, [res.point(grp.joints[1]).z] + extra[b]))
        elif grp.kind == "RRP":
            out.append((a, la.origin.z, [res.point(grp.joints[1]).z] + extra[a]))
            out.append((b, lb.origin.z, extra[b]))
        elif grp.kind == "RPR":
            out.append((a, la.origin.z, extra[a]))
            out.append((b, lb.origin.z, [la.origin.z] + extra[b]))
        elif grp.kind == "RPP":          # the yoke's slot, 1.2 cranks either side of A
            half = la.e * (1.2 * d.length)
            out.append((a, la.origin.z, extra[a]))
            out.append((b, la.origin.z - half, [la.origin.z + half] + extra[b]))
        else:
            out.append((a, la.origin.z, extra[a]))
            out.append((b, lb.origin.z, extra[b]))
    return out


_segments = link_segments


def slider_outlines(mech, res):
    """(centre, direction) of every block and slider drawn as a small rectangle."""
    out = []
    for grp in mech.groups:
        a, b = grp.links
        if grp.kind == "RRP":
            out.append((res.links[b].origin.z, res.links[b].e))
        elif grp.kind in ("RPR", "RPP"):
            out.append((res.links[a].origin.z, res.links[a].e))
        elif grp.kind == "PRP":
            out += [(res.links[a].origin.z, res.links[a].e), (res.links[b].origin.z,
                                                                res.links[b].e)]
    return out


def plot_chain_plan(result, ax=None, lang="en"):
    """The plan of positions: every link drawn at each position of ``result`` (position 1
    bold with the joints named, the others thin; the positions numbered at the crank
    pin), the frame's joints and the guides on the frame."""
    from crankbase.plot_texts import plot_fonts
    from crankbase.texts import texts
    from matplotlib.figure import Figure

    t = texts(lang)
    plot_fonts(lang)
    if ax is None:
        fig = Figure(figsize=(9.0, 7.5), layout="tight")
        ax = fig.add_subplot()
    mech, res = result.spec.mechanism, result.motion
    segs = link_segments(mech, res)
    n = len(res.phi)
    span = []
    for _, o, pts in segs:
        for p in [o] + pts:
            span.append(np.asarray(p, complex) * np.ones(n))
    allz = np.concatenate(span)
    size = float(np.nanmax(np.abs(allz - np.nanmean(allz)))) or 1.0
    for k in range(n):
        first = k == 0
        lw, col = (2.2, "C0") if first else (0.8, "0.6")
        for _, o, pts in segs:       # a link: its origin and points, a closed outline
            ring = [complex(np.asarray(p, complex).reshape(-1)[k if np.size(p) > 1 else 0])
                    for p in [o] + pts]
            if len(ring) > 2:
                ring.append(ring[0])
            if len(ring) > 1:
                ax.plot([q.real for q in ring], [q.imag for q in ring], color=col, lw=lw,
                        zorder=3 if first else 2)
        for c, e in slider_outlines(mech, res):
            zc = complex(np.asarray(c, complex).reshape(-1)[k if np.size(c) > 1 else 0])
            ze = complex(np.asarray(e, complex).reshape(-1)[k if np.size(e) > 1 else 0])
            w = 0.05 * size
            corners = [zc + ze * complex(sx * w, sy * 0.5 * w)
                       for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1), (-1, -1))]
            ax.plot([q.real for q in corners], [q.imag for q in corners], color=col,
                    lw=lw, zorder=4 if first else 2)
    for grp in mech.groups:            # guides on the frame
        gds = [grp.guide] if grp.kind in ("RRP", "RPP") else \
            list(grp.guides) if grp.kind == "PRP" else []
        for gd in gds:
            if gd.link != "frame":
                continue
            u = complex(math.cos(gd.angle), math.sin(gd.angle))
            p0 = complex(gd.point) + gd.offset * 1j * u
            s = np.real((allz - p0) * np.conj(u))
            s0, s1 = float(np.nanmin(s)) - 0.1 * size, float(np.nanmax(s)) + 0.1 * size
            ax.plot([(p0 + s0 * u).real, (p0 + s1 * u).real],
                    [(p0 + s0 * u).imag, (p0 + s1 * u).imag], color="k", lw=0.8, ls="-.")
    names = [mech.driver.joint] + [j for j in res.joints if j not in mech.frame
                                   and j != mech.driver.joint]
    for ln in mech.link_names:
        names += list(mech.links[ln].points)
    joints = {j: complex(np.asarray(res.point(j).z, complex).reshape(-1)[0])
              for j in dict.fromkeys(names)}
    for z in joints.values():
        ax.plot(z.real, z.imag, "o", ms=4, color="k", zorder=5)
    for z in mech.frame.values():
        ax.plot(z.real, z.imag, "^", ms=10, mfc="white", color="k", zorder=5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(t("linkage.chain.plot.x"))
    ax.set_ylabel(t("linkage.chain.plot.y"))
    ax.set_title(t("linkage.chain.plot.plan", name=result.spec.name,
                   formula=result.summary.structure))
    ax.grid(True, lw=0.3)
    _plan_labels(ax, result, joints)
    return ax


def _plan_labels(ax, result, joints):
    """The joints' names at position 1 and the position numbers at the crank pin, each
    where no link or other label crosses it (:mod:`crankbase.plot_labels`)."""
    from crankbase.plot_labels import fixed_axes_obstacles, label_points, place_label

    fig = ax.figure
    tr, obs = fixed_axes_obstacles(ax)
    mech = result.spec.mechanism
    zc = complex(mech.frame[mech.driver.pivot])
    centre = tr([(zc.real, zc.imag)])[0]
    allz = list(joints.values()) + list(mech.frame.values())
    mid = tr([(np.mean([z.real for z in allz]), np.mean([z.imag for z in allz]))])[0]
    for name, z in list(mech.frame.items()) + list(joints.items()):
        p = tr([(z.real, z.imag)])[0]
        place_label(ax, obs, p, name, normal=tuple(p - mid), fontsize=10, weight="bold")
    k = result.kinematics
    if not (k["position"].notna().all() and len(k)):
        return
    A = mech.driver.joint
    pts = tr(np.column_stack([k[f"x_{A}_m"], k[f"y_{A}_m"]]))
    texts = [str(int(v)) for v in k["position"]]
    placed, _ = label_points(ax, obs, pts, texts, pts - centre, list(range(len(texts))),
                             merge_px=7 * fig.dpi / 72, fontsize=7, color="0.3")
    for lab in placed:
        if lab.get_text().split("/")[0] == texts[0]:
            lab.set_color("C0")


def plot_chain_moment(full, ax=None, lang="en"):
    """Mур(φ) over the full turn."""
    from crankbase.plot_texts import plot_fonts
    from crankbase.texts import texts
    from matplotlib.figure import Figure

    from .report import column_label

    t = texts(lang)
    plot_fonts(lang)
    if ax is None:
        ax = Figure(figsize=(8.0, 5.0)).add_subplot()
    F = full.forces
    sym, unit = column_label("M_drive_Nm", lang)
    ax.plot(F["phi_deg"], F["M_drive_Nm"], color="C3")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set_xlabel(t("linkage.chain.plot.phi"))
    ax.set_ylabel(f"{sym}, {unit}")
    ax.set_xlim(0, 360)
    ax.set_title(t("linkage.chain.plot.moment", name=full.spec.name))
    ax.grid(True, lw=0.3)
    return ax


def plot_output_motion(full, fig=None, lang="en"):
    """The output link's motion diagrams over the full turn: its position (s or θ), its
    velocity (v or ω) and acceleration (a or ε), one above the other."""
    from crankbase.plot_texts import plot_fonts
    from crankbase.texts import texts
    from matplotlib.figure import Figure

    from .chain_analysis import output_motion

    t = texts(lang)
    plot_fonts(lang)
    if fig is None:
        fig = Figure(figsize=(8.0, 8.0))
    axes = fig.subplots(3, 1, sharex=True)
    c, r, a = output_motion(full.motion, full.spec.output)
    phi = full.kinematics["phi_deg"]
    slider = full.spec.output_kind == "slider"
    if slider:
        cols = (f"s_{full.spec.output}_m", f"v_{full.spec.output}_m_s",
                f"a_{full.spec.output}_m_s2")
        data = (c, r, a)
    else:
        cols = (f"theta_{full.spec.output}_deg", f"omega_{full.spec.output}_rad_s",
                f"eps_{full.spec.output}_rad_s2")
        data = (np.degrees(np.unwrap(c)), r, a)
    for ax, col, y, colour in zip(axes, cols, data, ("C0", "C1", "C2")):
        sym, unit = chain_column_label(col, lang)
        ax.plot(phi, y, color=colour)
        ax.set_ylabel(f"{sym}, {unit}")
        ax.grid(True, lw=0.3)
        ax.axhline(0.0, color="k", lw=0.5)
    axes[-1].set_xlabel(t("linkage.chain.plot.phi"))
    axes[-1].set_xlim(0, 360)
    axes[0].set_title(t("linkage.chain.plot.output", link=full.spec.output,
                        name=full.spec.name))
    fig.tight_layout()
    return fig


def chain_figures(result, full, lang="en") -> dict:
    """Every figure of a chain report by its file stem (:data:`CHAIN_PLOTS`)."""
    plan = plot_chain_plan(result, lang=lang).figure
    moment = plot_chain_moment(full, lang=lang).figure
    moment.tight_layout()
    return {"plan": plan, "driving_moment": moment,
            "output_motion": plot_output_motion(full, lang=lang)}
