"""Drawing primitives of the plans in millimetres of paper, shared by the matplotlib
renderer (:mod:`plans.drawing`) and the DXF writer (:mod:`plans.dxf`), so the PDF and the
DXF of a sheet hold the same lines and texts.

Line kinds and text heights follow the Russian drafting standards:

* ГОСТ 2.303-68: solid main line S = 0.5…1.4 mm (here :data:`S_MAIN` = 0.7 mm on A1 and
  A3 alike), solid thin line S/3…S/2 (:data:`S_THIN` = 0.3 mm), dashed thin line with
  dashes of 2…8 mm and gaps of 1…2 mm (here 4 mm and 1.5 mm).
* ГОСТ 2.304-81: text heights from the series 2.5, 3.5, 5, 7, 10, 14 mm (the height of
  capitals).  The standard's type B font is not shipped with matplotlib; the drawings use
  DejaVu Sans with its capital height (0.729 em) set to the standard's height, and the
  DXF names the CAD font ISOCPEUR (the usual stand-in for type B, with Cyrillic).

Vectors are main lines with a filled arrowhead (4 mm long, 1.3 mm wide: shorter on short
vectors, 0.45 of their length but not below 1.8 mm); lines of the plan of positions and
the lever's arms are thin lines.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache

__all__ = ["Line", "Arrow", "Text", "Circle", "Block", "diagram_block", "lever_block",
           "positions_block", "text_width", "S_MAIN", "S_THIN", "CAP_EM", "H_LABEL",
           "H_POINT", "H_TITLE"]

S_MAIN = 0.7     # mm, ГОСТ 2.303 solid main line
S_THIN = 0.3     # mm, ГОСТ 2.303 solid thin line (≈ S/2.3)
CAP_EM = 0.729   # DejaVu Sans capital height / em
H_LABEL = 2.5    # mm, vector labels (ГОСТ 2.304 series)
H_POINT = 3.5    # mm, point letters
H_TITLE = 5.0    # mm, diagram titles
ARROW_L = 4.0
ARROW_W = 1.3
ARROW_MIN = 1.8  # mm, the shortest arrowhead of a vector at least that long
FONT = "DejaVu Sans"


@dataclass
class Line:
    p1: complex
    p2: complex
    layer: str = "THIN"          # MAIN, THIN, DASHED, FRAME, TITLE


@dataclass
class Arrow:
    """A vector: a main line from p1 to p2 with an arrowhead at p2."""
    p1: complex
    p2: complex
    layer: str = "VECTORS"
    name: str = ""               # ``<plan>:<segment>`` for the vectors of plans.csv


@dataclass
class Text:
    at: complex
    text: str
    height: float = H_LABEL
    layer: str = "TEXT"
    ha: str = "center"           # left, center, right
    va: str = "center"           # bottom, center, top


@dataclass
class Circle:
    center: complex
    r: float
    layer: str = "THIN"
    filled: bool = False


@dataclass
class Block:
    """A laid-out diagram: items in local mm coordinates, bbox (x0, y0, x1, y1)."""
    items: list
    bbox: tuple
    title: str = ""
    key: str = ""

    @property
    def width(self):
        return self.bbox[2] - self.bbox[0]

    @property
    def height(self):
        return self.bbox[3] - self.bbox[1]

    def moved(self, dz):
        out = []
        for it in self.items:
            if isinstance(it, (Line, Arrow)):
                out.append(type(it)(it.p1 + dz, it.p2 + dz, *[getattr(it, f) for f in
                                   ("layer", "name") if hasattr(it, f)]))
            elif isinstance(it, Text):
                out.append(Text(it.at + dz, it.text, it.height, it.layer, it.ha, it.va))
            elif isinstance(it, Circle):
                out.append(Circle(it.center + dz, it.r, it.layer, it.filled))
        return out


@lru_cache(maxsize=4096)
def text_width(text: str, height: float) -> float:
    """Width of ``text`` at capital height ``height`` in DejaVu Sans. [mm]"""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    if not text:
        return 0.0
    tp = TextPath((0, 0), text, size=height / CAP_EM, prop=FontProperties(family=FONT))
    return max(_path_x1(tp), 0.0) + 0.1 * height


def _path_x1(path):
    """``path.get_extents().x1``, the same number, without evaluating every curve of the
    path: matplotlib's ``Path.get_extents`` evaluates each Bézier segment at its ends
    and at its interior extrema (about 50 µs a segment, thousands in a line of text).
    The largest x is the largest end of a segment unless a curve's control points reach
    it; only those curves (within a margin far above rounding) are evaluated, by the same
    code (``BezierSegment``), so the result is the same float."""
    import numpy as np
    from matplotlib.bezier import BezierSegment
    from matplotlib.path import Path

    codes = path.codes
    if codes is None or not np.isin(codes, (Path.CURVE3, Path.CURVE4)).any():
        return path.get_extents().x1                # matplotlib's own straight-line case
    segments = []                                   # (start, verts, code), as
    first = prev = None                             # Path.iter_bezier walks them
    for verts, code in path.iter_segments():
        if code == Path.STOP:
            break
        if code == Path.MOVETO:
            first = verts
        segments.append((prev, verts, code))
        prev = verts[-2:]
    # the ends of every segment (a MOVETO's point; a line's or curve's start and end;
    # CLOSEPOLY closes to the first point)
    ends = [v[0] for start, verts, code in segments
            for v in ((verts,) if code == Path.MOVETO else
                      (start, first) if code == Path.CLOSEPOLY else
                      (start, verts[-2:]))]
    x1 = max(ends)
    tol = 1e-6 * (1.0 + float(np.abs(path.vertices).max()))
    for start, verts, code in segments:
        if code in (Path.CURVE3, Path.CURVE4) and max(start[0], *verts[::2]) >= x1 - tol:
            pts = [start, verts[:2], verts[2:]] if code == Path.CURVE3 else \
                [start, verts[:2], verts[2:4], verts[4:]]
            curve = BezierSegment(np.array(pts))
            _, dzeros = curve.axis_aligned_extrema()
            x1 = max(x1, float(curve([0, *dzeros, 1])[:, 0].max()))
    return x1


def text_box(t: Text):
    """Bounding box (x0, y0, x1, y1) of a text on the sheet. [mm]"""
    w = text_width(t.text, t.height)
    h = t.height * 1.25
    x = t.at.real - {"left": 0.0, "center": w / 2, "right": w}[t.ha]
    y = t.at.imag - {"bottom": 0.0, "center": h / 2, "top": h}[t.va]
    return (x, y - 0.15 * t.height, x + w, y + h)


def boxes_overlap(a, b, pad=0.4):
    """True when the boxes ``a`` and ``b`` (x0, y0, x1, y1) come closer than ``pad``. [mm]"""
    return not (a[2] + pad <= b[0] or b[2] + pad <= a[0] or a[3] + pad <= b[1]
                or b[3] + pad <= a[1])


def _seg_hits_box(p1, p2, box, pad=0.3):
    """Does the segment p1–p2 (complex, mm) cross the box grown by ``pad``?  (Liang–
    Barsky, :func:`crankbase.plot_labels.segment_hits_box`; 1e-9 mm of slope is none.)"""
    from crankbase.plot_labels import segment_hits_box

    return segment_hits_box((p1.real, p1.imag), (p2.real, p2.imag),
                            (box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad),
                            parallel_tol=1e-9)


class _Scores:
    """The conflicts of label boxes with the placed boxes and the lines, all at once
    (numpy): ``1000 × (boxes it overlaps, :func:`boxes_overlap`) + (segments that cross
    it, :func:`_seg_hits_box`)``, the same tests and the same floating-point operations
    as those functions, one box or segment at a time.  Called with one box (x0, y0, x1,
    y1) it returns that box's score; :meth:`many` scores the rows of an array of boxes at
    once (candidates × boxes and candidates × segments)."""

    def __init__(self, boxes, segments, pad=0.4, seg_pad=0.3, parallel_tol=1e-9):
        import numpy as np

        self.b = np.array(boxes, float).reshape(-1, 4)
        seg = np.array(segments, complex).reshape(-1, 2)
        self.px, self.py = seg[:, 0].real, seg[:, 0].imag
        self.dx, self.dy = seg[:, 1].real - self.px, seg[:, 1].imag - self.py
        self.pad, self.seg_pad, self.tol = pad, seg_pad, parallel_tol

    def __call__(self, box) -> int:
        import numpy as np

        return int(self.many(np.array([box], float))[0])

    def many(self, boxes):
        """The scores of the rows (x0, y0, x1, y1) of ``boxes``, an integer array."""
        import numpy as np

        boxes = np.asarray(boxes, float).reshape(-1, 4)
        c = [boxes[:, k:k + 1] for k in range(4)]         # columns: candidates × 1
        b, pad = self.b, self.pad
        over = ~((c[2] + pad <= b[:, 0]) | (b[:, 2] + pad <= c[0])
                 | (c[3] + pad <= b[:, 1]) | (b[:, 3] + pad <= c[1]))
        g = self.seg_pad
        x0, y0, x1, y1 = c[0] - g, c[1] - g, c[2] + g, c[3] + g
        px, py, dx, dy = self.px, self.py, self.dx, self.dy
        shape = (len(boxes), len(px))
        t0 = np.zeros(shape)
        t1 = np.ones(shape)
        out = np.zeros(shape, bool)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # flat ones masked
            for pk, qk in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
                flat = np.abs(pk) <= self.tol
                out |= flat & (qk < 0)
                t = qk / pk
                t0 = np.where(~flat & (pk < 0), np.maximum(t0, t), t0)
                t1 = np.where(~flat & (pk > 0), np.minimum(t1, t), t1)
        hits = ~out & (t0 <= t1)
        return over.sum(axis=1) * 1000 + hits.sum(axis=1)


def _text_boxes(at, text, height, ha="center", va="center"):
    """:func:`text_box` of ``Text(z, text, height, ha=ha, va=va)`` for every ``z`` of
    the complex array ``at``, as rows (x0, y0, x1, y1): the same operations. [mm]"""
    import numpy as np

    w = text_width(text, height)
    h = height * 1.25
    x = at.real - {"left": 0.0, "center": w / 2, "right": w}[ha]
    y = at.imag - {"bottom": 0.0, "center": h / 2, "top": h}[va]
    return np.column_stack([x, y - 0.15 * height, x + w, y + h])


class _Placer:
    """Greedy placement of labels: the first candidate that overlaps no placed label and
    crosses no line; else the one with the fewest conflicts (the first of those).  When
    no candidate is free, the first six are looked around farther out too.  Every
    candidate of a label is scored at once (:meth:`_Scores.many`)."""

    def __init__(self, segments):
        self.segments = list(segments)
        self.boxes = []

    def place(self, candidates, text, height):
        import numpy as np

        candidates = list(candidates)
        scores = _Scores(self.boxes, self.segments)
        at = np.array(candidates, complex)
        boxes = _text_boxes(at, text, height)
        score = scores.many(boxes)
        if score.min() > 0:
            # nothing free near: look around the first candidates, farther out (a thin
            # polygon near a dead position leaves no room beside its vectors)
            more = [c + r * complex(math.cos(math.radians(k)), math.sin(math.radians(k)))
                    for c in candidates[:6] for r in (4.0, 8.0, 12.0, 18.0)
                    for k in range(0, 360, 30)]
            candidates += more
            at = np.array(more, complex)
            boxes = np.concatenate([boxes, _text_boxes(at, text, height)])
            score = np.concatenate([score, scores.many(boxes[len(score):])])
        k = int(np.argmin(score))           # the first zero, else the first of the fewest
        self.boxes.append(tuple(float(v) for v in boxes[k]))
        return Text(candidates[k], text, height)


def arrow_parts(p1, p2):
    """Arrowhead triangle (3 points) of a vector p1→p2, or None for a null vector."""
    d = p2 - p1
    L = abs(d)
    if L < 1e-6:
        return None
    u = d / L
    # 4 mm, 0.45 of a short vector, but at least ARROW_MIN mm (or the whole vector) so
    # that the head of a short force arrow drawn to scale stays visible
    hl = min(ARROW_L, max(0.45 * L, min(L, ARROW_MIN)))
    hw = ARROW_W * hl / ARROW_L
    base = p2 - u * hl
    return (p2, base + 1j * u * hw / 2, base - 1j * u * hw / 2)


def _label_candidates(p1, p2, dists=(2.2, 4.0, 6.5, 9.5, 13.0, 17.0)):
    d = p2 - p1
    L = abs(d)
    u = d / L if L > 0 else 1.0
    n = 1j * u
    out = []
    for f in (0.5, 0.35, 0.65, 0.2, 0.8):
        m = p1 + f * d
        for dist in dists:
            out += [m + n * dist, m - n * dist]
    return out


def _point_candidates(z, r=3.0):
    """Spots around a point: 8 directions at r, 2r, 3r and 4r."""
    return [z + f * r * complex(math.cos(math.radians(k)), math.sin(math.radians(k)))
            for f in (1, 2, 3, 4) for k in (45, 135, 225, 315, 90, 270, 0, 180)]


_QUANTITY_RU = {"V_A": "VA", "V_B": "VB", "V_BA": "VBA", "a_A": "aA", "a_B": "aB",
                "a_BA": "aBA", "a_BA_n": "aⁿBA", "a_BA_t": "aᵗBA", "a_BC_n": "aⁿBC",
                "a_BC_t": "aᵗBC", "a_AO_n": "aⁿAO", "a_AO_t": "aᵗAO"}


def vector_label(v, lang):
    """Label of a vector on the drawing: the quantity it stands for (VA, aⁿBA, R₂₃ᵗ …)."""
    if v.plan.startswith("force"):
        return v.label(lang)
    q = v.quantity
    if q in _QUANTITY_RU:
        return _QUANTITY_RU[q]
    kind, point = q.split("_", 1)               # V_S3, a_E; a chain's a_ED_n, a_A3A2_k
    sup = ""
    if point[-2:] in ("_n", "_t", "_k", "_r"):
        point, sup = point[:-2], {"n": "ⁿ", "t": "ᵗ", "k": "ᵏ", "r": "ʳ"}[point[-1]]
    return kind + sup + point.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def plan_words(lang):
    """The words of the plans drawings in ``lang`` (``plot.plans.*``)."""
    from crankbase.plot_texts import plot_words

    return plot_words(lang, "plans")


def fmt(x, lang, digits=4):
    """A number for the drawing: up to ``digits`` significant digits, with the decimal
    sign of ``lang``'s catalogue (a comma in Russian: :meth:`crankbase.texts.Texts.number`)."""
    from crankbase.texts import texts

    return texts(lang).number(f"{x:.{digits}g}")


def _symbols(lang):
    """The :class:`crankbase.texts.Texts` of ``lang``: its symbol set and decimal sign."""
    from crankbase.texts import texts

    return texts(lang)


def _where(pp, lang):
    if pp.position is not None:
        return plan_words(lang)["where"].format(n=pp.position)
    return f"φ = {fmt(pp.phi_deg, lang)}°"


def _titled(items, bbox, title_lines, key):
    """Put the title lines above the bbox; return a Block with the grown bbox."""
    x0, y0, x1, y1 = bbox
    y = y1 + 3.0
    for k, (line, h) in enumerate(reversed(title_lines)):
        items.append(Text(complex((x0 + x1) / 2, y), line, h, "TEXT", "center", "bottom"))
        w = text_width(line, h)
        x0 = min(x0, (bbox[0] + bbox[2]) / 2 - w / 2)
        x1 = max(x1, (bbox[0] + bbox[2]) / 2 + w / 2)
        y += h * 1.6
    name = ", ".join(t for t, _ in title_lines[:2])
    return Block(items, (x0 - 2, y0 - 2, x1 + 2, y + 1), name, key)


def _items_bbox(items):
    xs, ys = [], []
    for it in items:
        if isinstance(it, (Line, Arrow)):
            xs += [it.p1.real, it.p2.real]
            ys += [it.p1.imag, it.p2.imag]
        elif isinstance(it, Text):
            b = text_box(it)
            xs += [b[0], b[2]]
            ys += [b[1], b[3]]
        elif isinstance(it, Circle):
            xs += [it.center.real - it.r, it.center.real + it.r]
            ys += [it.center.imag - it.r, it.center.imag + it.r]
    return min(xs), min(ys), max(xs), max(ys)


def diagram_block(pp, kind, lang="ru") -> Block:
    """A plan (velocity, acceleration, a force polygon) of one position as a Block: every
    vector an arrow at the plan's scale, labelled with its quantity; the points of the
    kinematic plans lettered; title and scale above."""
    plan = pp.plans[kind]
    items = []
    segs = []
    for v in plan.vectors:
        layer = "VECTORS"
        items.append(Arrow(v.start, v.end, layer, f"{pp.tag}:{kind}:{v.name}"))
        segs.append((v.start, v.end))
    placer = _Placer(segs)
    # the pole and the points (kinematic plans)
    if kind in ("velocity", "acceleration"):
        items.append(Circle(0j, 0.6, "VECTORS", True))
        for name, z in plan.points.items():
            lab = _symbols(lang).symbol(*plan.point_labels[name])
            t = placer.place(_point_candidates(z), lab, H_POINT)
            items.append(t)
    for v in plan.vectors:
        if v.length_mm < 1e-6:
            continue
        lab = vector_label(v, lang)
        items.append(placer.place(_label_candidates(v.start, v.end), lab, H_LABEL))
    bbox = _items_bbox(items)
    w = plan_words(lang)
    if kind in w["title"]:
        title, mu, unit = w["title"][kind], w["mu"][kind], w["unit"][kind]
    else:                                   # a chain's group: force_<i>_<j>
        title = w["title"]["force_group"].format(links=",".join(kind.split("_")[1:]))
        mu, unit = w["mu"]["force_dyad"], w["unit"]["force_dyad"]
    lines = [(title, H_TITLE),
             (f"{_where(pp, lang)}, {mu} = {fmt(plan.scale, lang)} {unit}", H_POINT)]
    if kind.startswith("force") and _degenerate(plan.vectors):
        lines.append((w["degenerate"], H_LABEL))
    return _titled(items, bbox, lines, f"{pp.tag}:{kind}")


def _degenerate(vectors, ratio=0.06):
    """A force polygon near a dead position: its vectors' extent across is under
    ``ratio`` of its extent along (a sliver whose labels crowd along one line)."""
    import numpy as np

    z = np.array([p for v in vectors for p in (v.start, v.end)], complex)
    if len(z) < 2:
        return False
    z = z - z.mean()
    # principal directions of the points: the extents along and across
    m = np.array([[np.mean(z.real ** 2), np.mean(z.real * z.imag)],
                  [np.mean(z.real * z.imag), np.mean(z.imag ** 2)]])
    _, vec = np.linalg.eigh(m)
    along = z * complex(vec[0, 1], -vec[1, 1])
    return float(np.ptp(along.imag)) < ratio * max(float(np.ptp(along.real)), 1e-9)


def lever_block(pp, lang="ru") -> Block:
    """Zhukovsky's lever: the velocity plan turned 90° clockwise (thin lines), every load
    as an arrow from its point at the lever's force scale μF (``|F|/μF`` mm, stated under
    the title), the balancing force Fур at a, and the balancing moment and force from the
    lever beside the kinetostatic ones."""
    L = pp.lever
    items = []
    segs = []
    for name, p1, p2, lru, len_ in L.segments:
        items.append(Line(p1, p2, "THIN"))
        segs.append((p1, p2))
    items.append(Circle(0j, 0.6, "VECTORS", True))
    arrows = [v for v in L.arrows() if v.length_mm >= 1e-6]
    for v in arrows:
        items.append(Arrow(v.start, v.end, "LEVER", f"{pp.tag}:lever:{v.name}"))
        segs.append((v.start, v.end))
    placer = _Placer(segs)
    vplan = pp.plans["velocity"]
    for name, z in L.points.items():
        lab = _symbols(lang).symbol(*vplan.point_labels[name])
        items.append(placer.place(_point_candidates(z), lab, H_POINT))
    for v in arrows:
        p1, p2 = v.start, v.end
        # beyond the tip, beside the arrow, then around its point (short arrows drawn to
        # scale sit among the lines of the plan)
        cands = ([p2 + (p2 - p1) / abs(p2 - p1) * 3.0] + _label_candidates(p1, p2)
                 + _point_candidates(p1, 4.0) + _point_candidates(p1, 9.0))
        items.append(placer.place(cands, v.label(lang), H_LABEL))
    bbox = _items_bbox(items)
    x0, y0, x1, y1 = bbox
    w = plan_words(lang)
    d = f"{L.difference_percent:.2e}"
    res = [w["lever_M"].format(M=fmt(L.M_lever_Nm, lang, 6),
                               F=fmt(L.balancing_force_N, lang, 6)),
           w["kinetostatic_M"].format(M=fmt(L.M_kinetostatic_Nm, lang, 6),
                                      F=fmt(L.F_kinetostatic_N, lang, 6)),
           w["difference"].format(d=_symbols(lang).number(d))]
    y = y0 - 3.0
    for line in res:
        items.append(Text(complex(x0, y), line, H_LABEL, "TEXT", "left", "top"))
        y -= H_LABEL * 1.7
    bbox = _items_bbox(items)
    title, mu, unit, note = w["title"]["lever"], w["mu"]["lever"], w["unit"]["lever"], \
        w["turned"]
    scales = f"{mu} = {fmt(L.scale, lang)} {unit}"
    mu_v = L.plan_scale
    if mu_v is not None and mu_v != pp.plans["velocity"].scale:
        # drawn on a coarser copy of the velocity plan (to fit the sheet): its μV too
        scales = (f"{w['mu']['velocity']} = {fmt(mu_v, lang)} {w['unit']['velocity']}, "
                  + scales)
    return _titled(items, bbox, [(title, H_TITLE),
                                 (f"{_where(pp, lang)}, {scales}", H_POINT),
                                 (note, H_LABEL)], f"{pp.tag}:lever")


def positions_block(result, chosen, lang="ru", longest_mm=220.0) -> Block:
    """The plan of positions: the mechanism at every analysed position (thin lines, the
    positions numbered at the crank pin) and at the chosen ones (main lines), at the round
    length scale μl that keeps the drawing within ``longest_mm``."""
    import numpy as np

    from linkage.course import course_of

    from .model import round_scale

    spec = result.spec
    K = result.kinematics
    A = K["A_x_m"].to_numpy() + 1j * K["A_y_m"].to_numpy()
    B = K["B_x_m"].to_numpy() + 1j * K["B_y_m"].to_numpy()
    pts = np.concatenate([A, B, [0j]])
    C = None
    if course_of(spec).angular:            # the rocker's pivot C on the frame
        C = spec.ground * complex(math.cos(spec.ground_angle), math.sin(spec.ground_angle))
        pts = np.append(pts, C)
    extent = max(np.ptp(pts.real), np.ptp(pts.imag))
    mu = round_scale(extent, longest_mm)
    items = []
    chosen_rows = set(chosen)
    pos = K["position"]
    segs = []
    for i in range(len(K)):
        layer = "MAIN" if i in chosen_rows else "THIN"
        zA, zB = A[i] / mu, B[i] / mu
        items.append(Line(0j, zA, layer))
        items.append(Line(zA, zB, layer))
        segs += [(0j, zA), (zA, zB)]
        if C is not None:
            items.append(Line(C / mu, zB, layer))
            segs.append((C / mu, zB))
        else:
            u = complex(math.cos(spec.ground_angle), math.sin(spec.ground_angle))
            w, h = 8.0, 5.0
            corners = [zB + u * (sx * w / 2) + 1j * u * (sy * h / 2)
                       for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            for k in range(4):
                items.append(Line(corners[k], corners[(k + 1) % 4], layer))
        items.append(Circle(zA, 0.8, layer))
        items.append(Circle(zB, 0.8, layer))
    # crank circle, ground pivots, guide line
    r = spec.crank / mu
    n = 72
    for k in range(n):
        a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        items.append(Line(r * complex(math.cos(a0), math.sin(a0)),
                          r * complex(math.cos(a1), math.sin(a1)), "DASHED"))
        segs.append((items[-1].p1, items[-1].p2))      # no number on the crank circle
    for z, name in [(0j, "O")] + ([(C / mu, "C")] if C is not None else []):
        items.append(Circle(z, 1.2, "MAIN"))
        items.append(Line(z - 3 - 3j, z + 3 - 3j, "MAIN"))
        for k in range(4):
            items.append(Line(z - 3 + 1.5 * k - 3j, z - 4.5 + 1.5 * k - 4.5j, "THIN"))
    if C is None:
        u = complex(math.cos(spec.ground_angle), math.sin(spec.ground_angle))
        s = (B - 0) / mu
        proj = (s * u.conjugate()).real
        off = (s * u.conjugate()).imag.mean()
        for side in (-3.0, 3.0):
            p1 = (proj.min() - 8 + 1j * (off + side)) * u
            p2 = (proj.max() + 8 + 1j * (off + side)) * u
            items.append(Line(p1, p2, "THIN"))
    placer = _Placer(segs)
    for i in range(len(K)):
        lab = str(pos.iat[i]) if pos.notna().iat[i] else str(i + 1)
        zA = A[i] / mu
        out = zA / abs(zA) if abs(zA) > 0 else 1
        items.append(placer.place([zA + out * d for d in (3.5, 5.5, 8.0)]
                                  + _point_candidates(zA, 4.0), lab, H_POINT))
    for z, name in [(0j, "O")] + ([(C / mu, "C")] if C is not None else []):
        items.append(placer.place([z - 6 + 2j, z + 6 + 2j, z - 6 - 1j, z + 6 - 1j], name,
                                  H_POINT))
    bbox = _items_bbox(items)
    w = plan_words(lang)
    title, mul, unit = w["title"]["positions"], w["mu"]["positions"], w["unit"]["positions"]
    return _titled(items, bbox, [(title, H_TITLE), (f"{mul} = {fmt(mu, lang)} {unit}", H_POINT)],
                   "positions")


def chain_positions_block(result, chosen, lang="ru", longest_mm=220.0) -> Block:
    """The plan of positions of a chain (:mod:`linkage.chain`): every link at every
    analysed position (thin lines), at the chosen rows (main lines, the joints lettered),
    the blocks and sliders as small rectangles, the frame's joints hatched, the positions
    numbered at the crank pin; at the round length scale μl that keeps it within
    ``longest_mm``."""
    import numpy as np

    from linkage.chain_report import link_segments, slider_outlines

    from .model import round_scale

    mech, res = result.spec.mechanism, result.motion
    n = len(res.phi)

    def at(z, k):
        z = np.asarray(z, complex) if not hasattr(z, "x") else (
            np.broadcast_to(np.asarray(z.x, float), (n,))
            + 1j * np.broadcast_to(np.asarray(z.y, float), (n,)))
        return complex(np.broadcast_to(z, (n,))[k])

    segs_all = link_segments(mech, res)
    zs = [at(p, k) for _, o, pts in segs_all for p in [o] + pts for k in range(n)]
    zs += list(mech.frame.values())
    zs = np.array(zs, complex)
    extent = max(np.ptp(zs.real), np.ptp(zs.imag)) or 1.0
    mu = round_scale(extent, longest_mm)
    items, segs = [], []
    chosen = set(chosen)
    pos = result.kinematics["position"]
    for k in range(n):
        layer = "MAIN" if k in chosen else "THIN"
        for _, o, pts in segs_all:
            ring = [at(p, k) / mu for p in [o] + pts]
            if len(ring) > 2:
                ring.append(ring[0])
            for z1, z2 in zip(ring[:-1], ring[1:]):
                if abs(z2 - z1) > 1e-9:
                    items.append(Line(z1, z2, layer))
                    segs.append((z1, z2))
        for c, e in slider_outlines(mech, res):
            zc, ze = at(c, k) / mu, at(e, k)
            ze = ze / abs(ze) if abs(ze) else 1
            corners = [zc + ze * complex(sx * 4.0, sy * 2.5)
                       for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            for j in range(4):
                items.append(Line(corners[j], corners[(j + 1) % 4], layer))
                segs.append((corners[j], corners[(j + 1) % 4]))
        items.append(Circle(at(res.point(mech.driver.joint).z, k) / mu, 0.8, layer))
    for name, z in mech.frame.items():
        z = complex(z) / mu
        items.append(Circle(z, 1.2, "MAIN"))
        items.append(Line(z - 3 - 3j, z + 3 - 3j, "MAIN"))
        for j in range(4):
            items.append(Line(z - 3 + 1.5 * j - 3j, z - 4.5 + 1.5 * j - 4.5j, "THIN"))
        segs.append((z - 3 - 3j, z + 3 - 3j))
    placer = _Placer(segs)
    zO = complex(mech.frame[mech.driver.pivot]) / mu
    for k in range(n):
        lab = str(pos.iat[k]) if pos.notna().iat[k] else str(k + 1)
        zA = at(res.point(mech.driver.joint).z, k) / mu
        out = (zA - zO) / abs(zA - zO) if abs(zA - zO) > 0 else 1
        items.append(placer.place([zA + out * d for d in (3.5, 5.5, 8.0)]
                                  + _point_candidates(zA, 4.0), lab, H_POINT))
    for name, z in mech.frame.items():
        z = complex(z) / mu
        items.append(placer.place([z - 6 + 2j, z + 6 + 2j, z - 6 - 1j, z + 6 - 1j], name,
                                  H_POINT))
    first = min(chosen) if chosen else 0
    names = [j for j in res.joints if j not in mech.frame]
    for ln in mech.link_names:
        names += [p for p in mech.links[ln].points if p not in names]
    for j in dict.fromkeys(names):
        z = at(res.point(j).z, first) / mu
        items.append(placer.place(_point_candidates(z, 3.5), j, H_POINT))
    bbox = _items_bbox(items)
    w = plan_words(lang)
    title, mul, unit = w["title"]["positions"], w["mu"]["positions"], w["unit"]["positions"]
    return _titled(items, bbox, [(title, H_TITLE), (f"{mul} = {fmt(mu, lang)} {unit}", H_POINT)],
                   "positions")


@dataclass
class Sheet:
    """One drawing sheet: its size, the placed items and the fields of the title block."""
    width: float
    height: float
    items: list = field(default_factory=list)
    number: int = 1
    count: int = 1
    #: Keys of the diagrams on the sheet (``"<tag>:velocity"``, ``"positions"`` …).
    blocks: list = field(default_factory=list)
