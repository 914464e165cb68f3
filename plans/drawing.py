"""Drawings of the plans at true scale (matplotlib, object-oriented API, headless) and the
drawing sheet (A1 or A3 landscape, ГОСТ 2.104 form 1 title block).

Only consumes :class:`plans.model.PositionPlans`; the lines and texts come from
:mod:`plans.layout`, so the PDF and the DXF (:mod:`plans.dxf`) of a sheet are the same.
A figure is sized in millimetres (``figsize`` = mm/25.4) with one axes filling it and
data limits equal to its size in mm: 1 mm of a plan is 1 mm of paper when the SVG or PDF
is printed at 100 %.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .errors import PlanError, Problem
from .errors import Text as Words
from .layout import (CAP_EM, FONT, H_LABEL, H_POINT, S_MAIN, S_THIN, Arrow, Block, Circle,
                     Line, Sheet, Text, arrow_parts, diagram_block, lever_block,
                     positions_block, text_width)

__all__ = ["position_blocks", "position_figure", "layout_sheets", "sheet_figure",
           "render_items", "SHEETS", "FORMATS", "title_fields", "TITLE_KEYS",
           "frame_items", "fit_format", "fit_plans", "layout_fitted", "block_fits",
           "MIN_LONGEST_MM", "MIN_ARROW_MM"]

PT = 72.0 / 25.4            # points per mm
#: Sheet sizes, landscape (ГОСТ 2.301). [mm]
SHEETS = {"A1": (841.0, 594.0), "A3": (420.0, 297.0)}
#: The main formats of ГОСТ 2.301 (short side, long side). [mm]
FORMATS = {"A4": (210.0, 297.0), "A3": (297.0, 420.0), "A2": (420.0, 594.0),
           "A1": (594.0, 841.0)}
#: The frame's margins (ГОСТ 2.104: 20 mm at the binding edge, 5 mm elsewhere) and the
#: title block (form 1). [mm]
FRAME_LEFT, FRAME_OTHER = 20.0, 5.0
TITLE_BLOCK = (185.0, 55.0)
#: Widths of the lines of each layer. [mm]
WIDTH = {"FRAME": S_MAIN, "MAIN": S_MAIN, "VECTORS": S_MAIN, "LEVER": S_MAIN,
         "THIN": S_THIN, "DASHED": S_THIN, "TITLE": S_THIN, "TEXT": S_THIN}
DASH = (4.0, 1.5)           # mm, ГОСТ 2.303 dashed thin line
#: Keys of the spec's ``[drawing]`` table (the title block fields).
TITLE_KEYS = ("designation", "title", "material", "letter", "mass", "scale", "organization",
              "developer", "checker", "tech_control", "norm_control", "approver", "date")
GAP = 8.0                   # mm between diagrams


def title_fields(spec):
    """The title block's fields from the spec's ``[drawing]`` table (blank when not
    given; graph 1, the name, defaults to the mechanism's name).

    Raises
    ------
    PlanError
        Unknown keys or values that are not strings or numbers.
    """
    raw = dict(spec.raw.get("drawing", {}) or {})
    problems = []
    out = {k: "" for k in TITLE_KEYS}
    for k, v in raw.items():
        if k not in TITLE_KEYS:
            problems.append(f"drawing.{k}: unknown key; valid: {', '.join(TITLE_KEYS)}")
        elif not isinstance(v, (str, int, float)) or isinstance(v, bool):
            problems.append(f"drawing.{k}: got {v!r}; must be a text")
        else:
            out[k] = str(v)
    if problems:
        raise PlanError(problems)
    if not out["title"]:
        out["title"] = spec.name
    return out


# ------------------------------------------------------------------------- rendering


def render_items(ax, items):
    """Draw layout items (mm coordinates) on a matplotlib Axes whose data unit is 1 mm."""
    import numpy as np
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle as MCircle
    from matplotlib.patches import Polygon

    # a line is added as the Line2D ``ax.plot`` makes of it (the same properties and
    # data, its colour given, so no property cycle): plot's parsing of its arguments
    # cost more than the line.  Lines and patches are added as ``add_line`` and
    # ``add_patch`` add them (the same clip path, transform and, for a line, the
    # label ``_child<n>``) but the axes' data limits are updated once, at the end,
    # with every item's extent (the lines' end points, the arrow heads' corners, the
    # circles' boxes): ``add_patch`` found a patch's extent from its Bézier segments,
    # one by one, a twentieth of a sheet's cost, for the limits of axes whose limits
    # are set (a sheet, a plan)
    n = sum(len(group) for group in (ax.lines, ax.patches, ax.texts, ax.collections,
                                     ax.images, ax.tables, ax.artists))   # its children
    extent = []

    def add(artist, *points):
        nonlocal n
        if isinstance(artist, Line2D) and not artist.get_label():
            artist.set_label(f"_child{n}")
        ax.add_artist(artist)
        n += 1
        extent.extend(points)

    for it in items:
        if isinstance(it, Line):
            lw = WIDTH.get(it.layer, S_THIN) * PT
            kw = {}
            if it.layer == "DASHED":
                kw["dashes"] = (DASH[0] * PT / lw, DASH[1] * PT / lw)
            add(Line2D(np.array([it.p1.real, it.p2.real]), np.array([it.p1.imag, it.p2.imag]),
                       color="k", lw=lw, solid_capstyle="butt", **kw), it.p1, it.p2)
        elif isinstance(it, Arrow):
            head = arrow_parts(it.p1, it.p2)
            if head is None:
                continue
            lw = WIDTH.get(it.layer, S_MAIN) * PT
            tip, left, right = head
            base = (left + right) / 2
            add(Line2D(np.array([it.p1.real, base.real]), np.array([it.p1.imag, base.imag]),
                       color="k", lw=lw, solid_capstyle="butt"), it.p1, base)
            add(Polygon([(z.real, z.imag) for z in head], closed=True, facecolor="k",
                        edgecolor="k", lw=0.1 * PT), *head)
        elif isinstance(it, Text):
            va = {"bottom": "baseline", "center": "center", "top": "top"}[it.va]
            ax.text(it.at.real, it.at.imag, it.text, fontsize=it.height / CAP_EM * PT,
                    ha=it.ha, va=va, family=FONT, color="k")
            n += 1
        elif isinstance(it, Circle):
            c, r = it.center, it.r
            add(MCircle((c.real, c.imag), r, facecolor="k" if it.filled else "white",
                        edgecolor="k", lw=WIDTH.get(it.layer, S_THIN) * PT, zorder=3),
                c - r - 1j * r, c + r + 1j * r)
    if extent:
        z = np.asarray(extent, complex)
        ax.update_datalim(np.column_stack([z.real, z.imag]))


def _mm_figure(width, height):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width / 25.4, height / 25.4))
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, width)
    ax.set_ylim(0, height)
    ax.set_axis_off()
    return fig, ax


def position_blocks(pp, lang="ru"):
    """The diagrams of a position, in the course project's order: five for a four-bar or
    a crank-slider; a chain's the plans it has, its lever after the acceleration plan."""
    if pp.kind == "chain" or pp.lever is None:
        out = [diagram_block(pp, kind, lang) for kind in pp.plans]
        if pp.lever is not None:
            out.insert(list(pp.plans).index("acceleration") + 1, lever_block(pp, lang))
        return out
    return [diagram_block(pp, "velocity", lang), diagram_block(pp, "acceleration", lang),
            lever_block(pp, lang), diagram_block(pp, "force_dyad", lang),
            diagram_block(pp, "force_crank", lang)]


# ----------------------------------------------------------------- fitting the sheet

#: The coarsest sensible drawing of a plan: its longest vector at least this long. [mm]
MIN_LONGEST_MM = 30.0
#: The coarsest sensible force scale of Zhukovsky's lever: its largest force arrow at
#: least this long. [mm]
MIN_ARROW_MM = 10.0


def _field(size):
    """The working field of a ``size`` sheet inside its frame, GAP from it, and the title
    block's left and top edges: ``(x0, y0, x1, y1, tb_left, tb_top)``. [mm]"""
    W, H = SHEETS[size]
    return (FRAME_LEFT + GAP, FRAME_OTHER + GAP, W - FRAME_OTHER - GAP,
            H - FRAME_OTHER - GAP, W - FRAME_OTHER - TITLE_BLOCK[0],
            FRAME_OTHER + TITLE_BLOCK[1])


def block_fits(b, size):
    """Does block ``b`` (:class:`plans.layout.Block`) fit the field of a ``size`` sheet,
    beside or above the title block (clear of it by GAP as :func:`_pack` places it: its
    corner holds a GAP too)?"""
    x0, y0, x1, y1, tb_left, tb_top = _field(size)
    if b.width > x1 - x0 or b.height > y1 - y0:
        return False
    return b.height <= y1 - tb_top - 2 * GAP or b.width <= tb_left - 2 * GAP - x0


def _next_scale(mu):
    """The next coarser round scale after ``mu`` (:data:`plans.model.ROUND_MANTISSAS`)."""
    from .model import round_scale

    return round_scale(mu * 1.001, 1.0)


def _series(mu, limit):
    """Round scales from ``mu`` (itself first) while they are at most ``limit``."""
    out = [mu]
    while True:
        mu = _next_scale(mu)
        if mu > limit * (1 + 1e-12):
            return out
        out.append(mu)


def _longest(vectors):
    return max([v.length_mm for v in vectors] + [0.0])


def _rebuild(result, pp, scales):
    """Position ``pp`` built again at ``scales`` (the others the textbook's defaults), its
    ``fixed`` kept: the caller's scales stay the caller's."""
    from .chain_model import build_chain_plans
    from .model import build_plans

    if pp.position is not None:
        where = [pp.position]
    else:                                  # an explicit crank angle: its 1-based row
        phi = result.kinematics["phi_deg"].to_numpy(float)
        where = [int(np.flatnonzero(np.abs(phi - pp.phi_deg) < 1e-9)[0]) + 1]
    build = build_chain_plans if pp.kind == "chain" else build_plans
    new, = build(result, where, scales=scales)
    return replace(new, fixed=pp.fixed)


def _given(pp):
    """The caller's fixed scales of ``pp`` as a ``scales`` dict of the build."""
    out = {}
    for k in pp.fixed:
        if k == "lever":
            out[k] = pp.lever.scale
        elif k == "lever_velocity":
            out[k] = pp.lever.plan_scale
        elif k in pp.plans:
            out[k] = pp.plans[k].scale
        elif k == "force_dyad":            # a chain: every group's polygon
            out[k] = next(p.scale for n, p in pp.plans.items()
                          if n.startswith("force_") and n != "force_crank")
    return out


def _is_fixed(pp, kind):
    return kind in pp.fixed or (pp.kind == "chain" and "force_dyad" in pp.fixed
                                and kind.startswith("force_") and kind != "force_crank")


def _fit_position(result, pp, size, lang):
    """``pp`` with every diagram at the largest round scale at which it fits the field
    of a ``size`` sheet (a diagram that fits keeps its scale; the caller's fixed scales
    are kept), and its blocks in ``lang``.  A plan is made coarser, one round step at a
    time, while its longest vector stays :data:`MIN_LONGEST_MM` long; the lever first
    at its force scale (the largest arrow down to :data:`MIN_ARROW_MM`), then on a
    coarser copy of the velocity plan (its own μV, printed on the sheet).  What still
    does not fit is left as it is (:func:`layout_sheets` names it)."""
    blocks = position_blocks(pp, lang)
    if all(block_fits(b, size) for b in blocks):
        return pp, blocks
    scales = _given(pp)
    for kind in list(pp.plans):
        if block_fits(diagram_block(pp, kind, lang), size) or _is_fixed(pp, kind):
            continue
        mu0 = pp.plans[kind].scale
        top = mu0 * _longest(pp.plans[kind].vectors) / MIN_LONGEST_MM
        for mu in _series(mu0, top)[1:]:
            trial = _rebuild(result, pp, {**scales, kind: mu})
            if block_fits(diagram_block(trial, kind, lang), size):
                pp, scales[kind] = trial, mu
                break
    if pp.lever is not None and not block_fits(lever_block(pp, lang), size):
        pp = _fit_lever(result, pp, scales, size, lang)
    return pp, position_blocks(pp, lang)


def _fit_lever(result, pp, scales, size, lang):
    """The lever of ``pp`` at the largest turned plan, then the largest force scale, at
    which it fits (see :func:`_fit_position`); ``pp`` unchanged when none does."""
    mu_v0 = pp.lever.plan_scale or pp.plans["velocity"].scale
    segs = [abs(s[2] - s[1]) for s in pp.lever.segments] + [0.0]
    plan_scales = ([mu_v0] if "lever_velocity" in pp.fixed else
                   _series(mu_v0, mu_v0 * max(segs) / MIN_LONGEST_MM))
    for mu_v in plan_scales:
        base = dict(scales)
        if mu_v != mu_v0:
            base["lever_velocity"] = mu_v
        trial = _rebuild(result, pp, base) if base != scales else pp
        if "lever" in pp.fixed:
            if block_fits(lever_block(trial, lang), size):
                return trial
            continue
        mu_f0 = trial.lever.scale
        forces = _series(mu_f0, mu_f0 * _longest(trial.lever.arrows()) / MIN_ARROW_MM)
        # the coarsest force scale first: when even it does not fit, the next plan scale
        if not block_fits(lever_block(_rebuild(result, pp, {**base, "lever": forces[-1]})
                                 if len(forces) > 1 else trial, lang), size):
            continue
        for mu_f in forces:
            t = trial if mu_f == mu_f0 else _rebuild(result, pp, {**base, "lever": mu_f})
            if block_fits(lever_block(t, lang), size):
                return t
    return pp


def fit_plans(result, plans, size="A1", lang="ru"):
    """The plans of ``plans`` made to fit a ``size`` sheet: each diagram that does not
    fit the sheet's field (beside or above the title block) is built again at the
    largest round scale at which it fits (the plans one round step at a time, the
    lever at its force scale, then on a coarser copy of the velocity plan); the rest,
    and the scales the caller fixed, stay as they are (the same objects).  The printed
    scale of a diagram is the one it is drawn at.

    Parameters
    ----------
    result : linkage.AnalysisResult or linkage.chain_analysis.ChainAnalysis
    plans : list of PositionPlans
        From :func:`plans.build_plans` or :func:`plans.build_chain_plans`.
    size : {"A1", "A3"}
    lang : str
        The language of the drawing (its texts are part of each diagram's size).

    Returns
    -------
    list of PositionPlans
    """
    return [pp for pp, _ in _fit(result, plans, size, lang)]


def _fit(result, plans, size, lang):
    return [_fit_position(result, pp, size, lang) for pp in plans]


def _pack(blocks, x0, y0, x1, y1, corner=None, gap=GAP):
    """Place blocks in the field (x0, y0)–(x1, y1), each at the top-most, then left-most
    free spot, clear of the others by ``gap`` and of the lower right ``corner`` = (x, y)
    region (the title block).  Blocks are tried in their order; one that does not fit is
    left for the next sheet while later ones may still fill the gaps.  Returns
    [(block, offset)] and the blocks left over."""
    rects = []
    placed = []
    left_over = []
    if corner is not None:
        rects.append((corner[0], y0 - gap, x1 + gap, corner[1]))
    for b in blocks:
        xs = sorted({x0} | {r[2] + gap for r in rects})
        ys = sorted({y1} | {r[1] - gap for r in rects}, reverse=True)
        spot = None
        for top in ys:
            for left in xs:
                r = (left, top - b.height, left + b.width, top)
                if r[2] > x1 + 1e-9 or r[1] < y0 - 1e-9:
                    continue
                if any(not (r[2] + gap <= q[0] + 1e-9 or q[2] + gap <= r[0] + 1e-9
                            or r[3] + gap <= q[1] + 1e-9 or q[3] + gap <= r[1] + 1e-9)
                       for q in rects):
                    continue
                spot = r
                break
            if spot:
                break
        if spot is None:
            left_over.append(b)
            continue
        rects.append(spot)
        placed.append((b, complex(spot[0] - b.bbox[0], spot[3] - b.bbox[3])))
    return placed, left_over


def position_figure(pp, lang="ru", max_width=560.0):
    """One figure with all plans of a position at true scale (1 plan mm = 1 paper mm).

    Returns
    -------
    matplotlib.figure.Figure
        Its size in inches is its size in mm / 25.4.
    """
    blocks = position_blocks(pp, lang)
    width = max(max_width, max(b.width for b in blocks) + 2 * GAP)
    total_h = sum(b.height for b in blocks) + GAP * (len(blocks) + 1)
    placed, rest = _pack(blocks, GAP, 0.0, width - GAP, total_h - GAP)
    assert not rest
    items = []
    for b, dz in placed:
        items += b.moved(dz)
    xs0 = min(b.bbox[0] + dz.real for b, dz in placed)
    ys0 = min(b.bbox[1] + dz.imag for b, dz in placed)
    xs1 = max(b.bbox[2] + dz.real for b, dz in placed)
    ys1 = max(b.bbox[3] + dz.imag for b, dz in placed)
    shift = complex(GAP - xs0, GAP - ys0)
    W, H = xs1 - xs0 + 2 * GAP, ys1 - ys0 + 2 * GAP
    fig, ax = _mm_figure(W, H)
    render_items(ax, Block(items, (0, 0, W, H)).moved(shift))
    return fig


# ----------------------------------------------------------------------------- sheets


def _title_block_items(x0, y0, fields, number, count, lang):
    """ГОСТ 2.104 form 1 (185 × 55 mm), lower left corner at (x0, y0)."""
    items = []
    z0 = complex(x0, y0)

    def ln(xa, ya, xb, yb, layer="FRAME"):
        items.append(Line(z0 + complex(xa, ya), z0 + complex(xb, yb), layer))

    def tx(x, y, s, h=H_LABEL, ha="center", cell=None):
        """A text in a cell ``cell`` mm wide: smaller (never below 1.8 mm, the smallest
        height of ГОСТ 2.304) when it would not fit."""
        if s:
            if cell is not None:
                w = text_width(s, h)
                if w > cell - 1.0:
                    h = max(1.8, h * (cell - 1.0) / w)
            items.append(Text(z0 + complex(x, y), s, h, "TEXT", ha, "center"))

    ln(0, 0, 185, 0)
    ln(0, 55, 185, 55)
    ln(0, 0, 0, 55)
    ln(185, 0, 185, 55)
    for x in (17, 23 + 17, 55, 65):
        ln(x, 0, x, 55)
    ln(7, 30, 7, 55)
    ln(0, 30, 65, 30)
    ln(0, 35, 65, 35)
    for y in (5, 10, 15, 20, 25, 40, 45, 50):
        ln(0, y, 65, y, "THIN")
    ln(65, 40, 185, 40)
    ln(65, 15, 185, 15)
    ln(135, 0, 135, 40)
    ln(135, 35, 185, 35)
    ln(135, 20, 185, 20)
    ln(150, 20, 150, 40)
    ln(167, 20, 167, 40)
    ln(155, 15, 155, 20)
    ln(140, 20, 140, 35, "THIN")
    ln(145, 20, 145, 35, "THIN")
    from .layout import plan_words
    w = plan_words(lang)["tb"]
    heads = [w["rev"], w["sheet"], w["doc"], w["sign"], w["date"]]
    for (xa, xb), s in zip(((0, 7), (7, 17), (17, 40), (40, 55), (55, 65)), heads):
        tx((xa + xb) / 2, 32.5, s, cell=xb - xa)
    roles = [w["drawn"], w["checked"], w["tech"], "", w["norm"], w["approved"]]
    names = [fields["developer"], fields["checker"], fields["tech_control"], "",
             fields["norm_control"], fields["approver"]]
    for k, (role, name) in enumerate(zip(roles, names)):
        y = 27.5 - 5 * k
        tx(1, y, role, ha="left", cell=17)
        tx(18, y, name, ha="left", cell=23)
        if k == 0 and fields["date"]:
            tx(60, y, fields["date"], h=H_LABEL, cell=10)
    tx(125, 47.5, fields["designation"], h=7.0, cell=120)
    tx(100, 27.5, fields["title"], h=5.0, cell=70)
    tx(100, 7.5, fields["material"], h=5.0, cell=70)
    for (xa, xb), s in zip(((135, 150), (150, 167), (167, 185)),
                           (w["letter"], w["mass"], w["scale"])):
        tx((xa + xb) / 2, 37.5, s, cell=xb - xa)
    tx(142.5, 27.5, fields["letter"], h=H_POINT, cell=15)
    tx(158.5, 27.5, fields["mass"], h=H_POINT, cell=17)
    tx(176, 27.5, fields["scale"], h=H_POINT, cell=18)
    tx(136, 17.5, w["sheet_n"].format(n=number), ha="left", cell=19)
    tx(156, 17.5, w["sheets_n"].format(n=count), ha="left", cell=29)
    tx(160, 7.5, fields["organization"], h=H_POINT, cell=50)
    return items


def layout_sheets(result, plans, lang="ru", size="A1", fields=None):
    """Lay out the plan of positions and the chosen plans on as many sheets as needed
    (:func:`layout_fitted`, the sheets alone)."""
    return layout_fitted(result, plans, lang, size, fields)[0]


def layout_fitted(result, plans, lang="ru", size="A1", fields=None):
    """Lay out the plan of positions and the chosen plans on as many sheets as needed,
    each diagram at the largest round scale at which it fits the field
    (:func:`fit_plans`: a diagram that fits at its scale keeps it).

    Parameters
    ----------
    result : linkage.AnalysisResult
    plans : list of PositionPlans
    lang : {"ru", "en"}
    size : {"A1", "A3"}
        Landscape sheet (ГОСТ 2.301): A1 841 × 594 mm, A3 420 × 297 mm.
    fields : dict, optional
        Title block fields (:func:`title_fields`).

    Returns
    -------
    sheets : list of Sheet
        With the frame (ГОСТ 2.104: 20 mm on the left, 5 mm elsewhere), the title block
        185 × 55 mm in the lower right corner, and the diagrams packed in rows without
        overlap (at least 8 mm apart, clear of the title block).
    plans : list of PositionPlans
        The plans as drawn (:func:`fit_plans`).

    Raises
    ------
    PlanError
        A diagram larger than the sheet's working field even at the coarsest sensible
        scale (its longest vector :data:`MIN_LONGEST_MM`, the lever's largest force
        :data:`MIN_ARROW_MM`), or at a scale the caller fixed: choose A1 or a coarser
        scale.
    """
    if size not in SHEETS:
        raise PlanError(Problem("size", Words("errors.plans.drawing.valid",
                                              {"size": size, "items": ', '.join(SHEETS)})))
    W, H = SHEETS[size]
    fields = fields or title_fields(result.spec)
    fitted = _fit(result, plans, size, lang)
    plans = [pp for pp, _ in fitted]
    chosen = []
    K = result.kinematics
    for pp in plans:
        hit = [i for i in range(len(K)) if abs(K["phi_deg"].iat[i] - pp.phi_deg) < 1e-9]
        chosen += hit[:1]
    if getattr(result, "motion", None) is not None:          # a chain
        from .layout import chain_positions_block

        blocks = [chain_positions_block(result, chosen, lang, longest_mm=0.3 * W)]
    else:
        blocks = [positions_block(result, chosen, lang, longest_mm=0.3 * W)]
    per = [b for _, b in fitted]
    for group in per:
        blocks += group
    x0, y0, x1, y1, tb_left, tb_top = _field(size)
    too_big = [b.title for b in blocks if not block_fits(b, size)]
    if too_big:
        raise PlanError([Problem("size", Words("errors.plans.drawing.does_not_fit",
                                               {"size": size, "t": t, "x1": x1 - x0,
                                                "y1": y1 - y0})) for t in too_big])
    # a teacher grades one position at a time: a sheet holds one position's diagrams, or
    # two positions side by side, each in its half (the plan of positions joins the
    # first); a position too large for one sheet goes on as many of its own as it needs
    corner = (tb_left - GAP, tb_top + GAP)
    xm = (x0 + x1) / 2
    sheets = []

    def pack(group, xa, xb):
        return _pack(group, xa, y0, xb, y1, corner)

    def fits_in(group, xa, xb):
        return not pack(group, xa, xb)[1]

    def make(parts):
        """A sheet of ``parts`` [(blocks, x from, x to)]; returns the blocks left over."""
        sh = Sheet(W, H)
        left = []
        for group, xa, xb in parts:
            placed, rest = pack(group, xa, xb)
            if not placed:   # pragma: no cover - guarded by too_big
                raise PlanError(Problem("size", Words("errors.plans.drawing.cannot_place",
                                                      {"size": size,
                                                       "title": rest[0].title})))
            for b, dz in placed:
                sh.items += b.moved(dz)
                sh.blocks.append(b.key)
            left += rest
        sheets.append(sh)
        return left

    pending = blocks[:1]                               # the plan of positions
    k = 0
    while k < len(plans):
        mine = per[k]
        nxt = per[k + 1] if k + 1 < len(per) else []
        if fits_in(pending + mine, x0, x1):
            if nxt and fits_in(pending + mine, x0, xm) and fits_in(nxt, xm, x1):
                make([(pending + mine, x0, xm), (nxt, xm, x1)])
                k += 2
            else:
                make([(pending + mine, x0, x1)])
                k += 1
            pending = []
        elif pending:                                  # the plan of positions alone
            while pending:
                pending = make([(pending, x0, x1)])
        else:                                          # one position over several sheets
            rest = mine
            while rest:
                rest = make([(rest, x0, x1)])
            k += 1
    while pending:
        pending = make([(pending, x0, x1)])
    for k, sh in enumerate(sheets):
        sh.number, sh.count = k + 1, len(sheets)
        sh.items = frame_items(W, H, fields, sh.number, sh.count, lang) + sh.items
    return sheets, plans


def frame_items(W, H, fields, number=1, count=1, lang="ru"):
    """The sheet's edge (thin), its frame (ГОСТ 2.104: 20 mm from the left edge, 5 mm
    from the others) and the title block (form 1, 185 × 55 mm, lower right corner) of a
    ``W`` × ``H`` mm sheet, as layout items."""
    frame = [Line(0j, complex(W, 0), "THIN"), Line(complex(W, 0), complex(W, H), "THIN"),
             Line(complex(W, H), complex(0, H), "THIN"), Line(complex(0, H), 0j, "THIN")]
    fx0, fy0, fx1, fy1 = FRAME_LEFT, FRAME_OTHER, W - FRAME_OTHER, H - FRAME_OTHER
    frame += [Line(complex(fx0, fy0), complex(fx1, fy0), "FRAME"),
              Line(complex(fx1, fy0), complex(fx1, fy1), "FRAME"),
              Line(complex(fx1, fy1), complex(fx0, fy1), "FRAME"),
              Line(complex(fx0, fy1), complex(fx0, fy0), "FRAME")]
    return frame + _title_block_items(fx1 - TITLE_BLOCK[0], fy0, fields, number, count,
                                      lang)


def fit_format(width, height, gap=GAP):
    """The smallest ГОСТ 2.301 format (A4 … A1, portrait or landscape) whose frame holds a
    ``width`` × ``height`` mm drawing above the title block: ``(name, W, H)``.

    Raises
    ------
    PlanError
        The drawing is larger than A1's field.
    """
    for name, (a, b) in FORMATS.items():
        for W, H in ((a, b), (b, a)):
            if (width <= W - FRAME_LEFT - FRAME_OTHER - 2 * gap
                    and height <= H - 2 * FRAME_OTHER - TITLE_BLOCK[1] - 2 * gap):
                return name, W, H
    raise PlanError(Problem("size", Words("errors.plans.drawing.too_large",
                                          {"width": width, "height": height})))


def sheet_figure(sheet):
    """A sheet as a matplotlib Figure of exactly its size (A1: 841 × 594 mm)."""
    fig, ax = _mm_figure(sheet.width, sheet.height)
    render_items(ax, sheet.items)
    return fig


def check_no_overlap(items, pad=0.0):
    """Pairs of texts whose boxes overlap (for the tests and a self-check)."""
    from .layout import boxes_overlap, text_box

    texts = [t for t in items if isinstance(t, Text)]
    boxes = [text_box(t) for t in texts]
    out = []
    for a in range(len(boxes)):
        for b in range(a + 1, len(boxes)):
            if boxes_overlap(boxes[a], boxes[b], pad):
                out.append((texts[a].text, texts[b].text))
    return out

