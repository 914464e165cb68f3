"""Collision-free text labels for point markers on a plot (matplotlib, headless).

Used by the polar load diagram and the linkage plan of positions to label the crank
angle α at its points: each label is measured with the figure's renderer, tried at offsets along the curve's normal (both
sides, several distances, then rotated directions) and put at the first place where its
box clears every label already placed, every marker and every arrow; a label that finds
no free place is left out ("thinned"), and points that fall on the same spot share one
label ("240/600").  Nothing here computes physics; it only places text.

matplotlib is imported by the caller (this module is imported from the plot modules
only).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from .plot_layout import run_layout

__all__ = ["Obstacles", "add_axes_lines", "fixed_axes_obstacles", "renderer_of", "text_size", "place_label",
           "label_points", "frozen_frame", "segment_hits_box"]


def renderer_of(fig):
    """The Agg renderer of ``fig`` (attaching an Agg canvas to a bare ``Figure``)."""
    if not hasattr(fig.canvas, "get_renderer"):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        FigureCanvasAgg(fig)
    return fig.canvas.get_renderer()


#: Sizes measured by :func:`text_size`, by everything a size depends on (kept from
#: figure to figure: the α labels "0" … "690" of every polar diagram of a report).
_SIZES = {}


def _font_settings():
    """The rcParams a text's size depends on (``font.*``, ``text.*``, ``mathtext.*``),
    as a key."""
    from matplotlib import rcParams

    return tuple(repr(rcParams[k]) for k in _font_keys())


@lru_cache(maxsize=1)
def _font_keys():
    """The names of the rcParams ``font.*``, ``text.*`` and ``mathtext.*`` (a fixed
    set: matplotlib's)."""
    from matplotlib import rcParams

    return tuple(sorted(k for k in rcParams if k.startswith(("font.", "text.", "mathtext."))))


def text_size(fig, text, **kw):
    """(width, height) of ``text`` in display pixels as the renderer draws it.

    A size is measured once for every text, text properties, dpi, canvas type and font
    settings (rcParams) and read back the next time (the measure depends on nothing
    else: the text is laid out at the figure's origin)."""
    r = renderer_of(fig)
    key = (text, tuple(sorted((k, repr(v)) for k, v in kw.items())), fig.dpi,
           type(r), r.dpi, _font_settings())
    size = _SIZES.get(key)
    if size is None:
        t = fig.text(0, 0, text, **kw)
        bb = t.get_window_extent(r)
        t.remove()
        if len(_SIZES) > 20000:
            _SIZES.clear()
        size = _SIZES[key] = (bb.width, bb.height)
    return size


def _overlap(a, b):
    """Axis-aligned boxes (x0, y0, x1, y1) intersect (touching counts as apart)."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def segment_hits_box(p, q, box, parallel_tol=0.0):
    """The segment p–q crosses or lies in the box (x0, y0, x1, y1) (Liang–Barsky
    clipping); a direction component of at most ``parallel_tol`` counts as parallel to
    that edge.  The one clipping test of the figure labels and the plans sheets."""
    x0, y0, x1, y1 = box
    dx, dy = q[0] - p[0], q[1] - p[1]
    t0, t1 = 0.0, 1.0
    for pk, qk in ((-dx, p[0] - x0), (dx, x1 - p[0]), (-dy, p[1] - y0), (dy, y1 - p[1])):
        if abs(pk) <= parallel_tol:
            if qk < 0:
                return False
            continue
        t = qk / pk
        if pk < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


@dataclass
class Obstacles:
    """What a label must not cover, in display pixels: boxes (markers, placed labels),
    segments (arrows), the frame it must stay inside, and a polyline it should avoid
    (the curve itself: a soft cost, not a hard rule)."""

    frame: tuple
    boxes: list = field(default_factory=list)
    segments: list = field(default_factory=list)
    curve: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))
    #: Lines no label may cross (the curve itself when ``curve_hard``, axis lines …),
    #: resampled like the curve.
    lines: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))
    curve_hard: bool = True

    def add_marker(self, xy, size_px):
        h = 0.5 * size_px
        self.boxes.append((xy[0] - h, xy[1] - h, xy[0] + h, xy[1] + h))

    def add_segment(self, p, q):
        self.segments.append((tuple(p), tuple(q)))

    def free(self, box, pad):
        b = (box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad)
        f = self.frame
        if b[0] < f[0] or b[1] < f[1] or b[2] > f[2] or b[3] > f[3]:
            return False
        if any(_overlap(b, o) for o in self.boxes):
            return False
        if any(segment_hits_box(p, q, b) for p, q in self.segments):
            return False
        if len(self.lines) and _count_inside(self.lines, b):
            return False
        return not (self.curve_hard and self.curve_cost(b))

    def free_many(self, boxes, pad):
        """:meth:`free` of every row (x0, y0, x1, y1) of ``boxes`` at once (numpy): the
        same comparisons and the same floating-point operations, a boolean array."""
        boxes = np.asarray(boxes, float).reshape(-1, 4)
        b = [boxes[:, 0] - pad, boxes[:, 1] - pad, boxes[:, 2] + pad, boxes[:, 3] + pad]
        f = self.frame
        ok = ~((b[0] < f[0]) | (b[1] < f[1]) | (b[2] > f[2]) | (b[3] > f[3]))
        c = [v[:, None] for v in b]                     # candidates × obstacles
        if self.boxes:
            o = np.asarray(self.boxes, float).reshape(-1, 4)
            ok &= ~((c[0] < o[:, 2]) & (o[:, 0] < c[2]) & (c[1] < o[:, 3])
                    & (o[:, 1] < c[3])).any(axis=1)
        if self.segments:
            ok &= ~_segments_hit_boxes(self.segments, c)
        for pts, hard in ((self.lines, True), (self.curve, self.curve_hard)):
            if hard and len(pts):
                ok &= _counts_inside(pts, b) == 0
        return ok

    def add_line(self, xy_px, step_px=1.0):
        """A polyline no label may cross (an axis line, another curve)."""
        pts = _resample(xy_px, step_px)
        self.lines = np.concatenate([self.lines, pts]) if len(self.lines) else pts

    def set_curve(self, xy_px, step_px=2.0):
        """The polyline to avoid, resampled so that its vertices lie at most ``step_px``
        apart (a fast stretch of the curve, few vertices far apart, still counts where
        it crosses a box)."""
        self.curve = _resample(xy_px, step_px)

    def curve_cost(self, box):
        """Number of the curve's (resampled) vertices inside ``box``."""
        return _count_inside(self.curve, box) if len(self.curve) else 0


def _resample(xy_px, step_px):
    """The polyline with vertices at most ``step_px`` apart."""
    xy = np.asarray(xy_px, float).reshape(-1, 2)
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    if len(xy) < 2:
        return xy
    seg = np.hypot(*np.diff(xy, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    t = np.linspace(0.0, s[-1], max(int(np.ceil(s[-1] / step_px)) + 1, len(xy)))
    return np.column_stack([np.interp(t, s, xy[:, 0]), np.interp(t, s, xy[:, 1])])


def _count_inside(c, box):
    inside = ((c[:, 0] > box[0]) & (c[:, 0] < box[2]) & (c[:, 1] > box[1])
              & (c[:, 1] < box[3]))
    return int(inside.sum())


def _counts_inside(c, boxes):
    """:func:`_count_inside` of each box, ``boxes`` the four arrays (x0, y0, x1, y1):
    only the points inside the boxes' union are compared box by box."""
    x0, y0, x1, y1 = (np.asarray(v, float) for v in boxes)
    out = np.zeros(len(x0), int)
    if not len(c) or not len(x0):
        return out
    near = c[(c[:, 0] > x0.min()) & (c[:, 0] < x1.max()) & (c[:, 1] > y0.min())
             & (c[:, 1] < y1.max())]
    if len(near):
        px, py = near[:, 0], near[:, 1]
        out += ((px > x0[:, None]) & (px < x1[:, None]) & (py > y0[:, None])
                & (py < y1[:, None])).sum(axis=1)
    return out


def _segments_hit_boxes(segments, boxes):
    """:func:`segment_hits_box` (``parallel_tol`` 0) of every segment against every box,
    ``boxes`` the four columns (x0, y0, x1, y1) as (n, 1) arrays: True where a box is hit
    by any segment.  The same operations, all at once."""
    seg = np.asarray(segments, float).reshape(-1, 4)
    px, py = seg[:, 0], seg[:, 1]
    dx, dy = seg[:, 2] - px, seg[:, 3] - py
    x0, y0, x1, y1 = boxes
    shape = np.broadcast_shapes(x0.shape, px.shape)
    t0, t1 = np.zeros(shape), np.ones(shape)
    out = np.zeros(shape, bool)
    with np.errstate(divide="ignore", invalid="ignore"):    # the flat ones are masked
        for pk, qk in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
            flat = np.abs(pk) <= 0.0
            out |= flat & (qk < 0)
            t = qk / pk
            t0 = np.where(~flat & (pk < 0), np.maximum(t0, t), t0)
            t1 = np.where(~flat & (pk > 0), np.minimum(t1, t), t1)
    return (~out & (t0 <= t1)).any(axis=1)


def _box_at(anchor, direction, size, gap):
    """Box of a text of ``size`` whose nearest edge is ``gap`` px from ``anchor`` along
    the unit ``direction``: the box centre lies on the ray, pushed out by the half-extent
    of the box in that direction."""
    w, h = size
    ux, uy = direction
    half = 0.5 * (w * abs(ux) + h * abs(uy))
    cx, cy = anchor[0] + ux * (gap + half), anchor[1] + uy * (gap + half)
    return (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)


def _boxes_at(anchor, directions, size, gaps):
    """:func:`_box_at` of every row of ``directions`` (n × 2) with its ``gaps`` (n), as
    rows (x0, y0, x1, y1): the same operations."""
    w, h = size
    ux, uy = directions[:, 0], directions[:, 1]
    half = 0.5 * (w * np.abs(ux) + h * np.abs(uy))
    cx, cy = anchor[0] + ux * (gaps + half), anchor[1] + uy * (gaps + half)
    return np.column_stack([cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2])


#: Gaps [pt] tried when none of the given ones leaves a free place.
_FAR = (4, 8, 14, 22, 32, 46, 64, 90)


def place_label(ax, obstacles, anchor_px, text, normal=(0.0, 1.0), gaps_pt=(3, 6, 10, 15),
                pad_px=1.5, curve_weight=4.0, gid=None, far=True, **text_kw):
    """Put ``text`` near the display point ``anchor_px`` where it covers nothing.

    Directions tried: ±``normal`` first, then turned by ±30°, ±60°, ±90°, ±135°; gaps
    ``gaps_pt`` points from the anchor.  Among the places whose box (padded by
    ``pad_px``) clears every obstacle, the one with the least cost (curve points covered
    × ``curve_weight`` + gap + turn) wins.  The label is drawn centred on its box and its
    box is added to the obstacles.  With ``far``, a label that finds no free place
    near is tried farther out (to 90 pt) before it is left out.

    Returns
    -------
    matplotlib.text.Text or None
        None when no free place exists (the label is thinned out).
    """
    fig = ax.figure
    size = text_size(fig, text, **text_kw)
    px_per_pt = fig.dpi / 72.0
    n = np.asarray(normal, float)
    n = n / (np.hypot(*n) or 1.0)
    best = None
    # every place at once (Obstacles.free_many), then the costs of the free ones in the
    # order they are tried: the first of the least cost wins
    tried = []
    for turn in (0, 30, -30, 60, -60, 90, -90, 135, -135, 180):
        for side in (1.0, -1.0):
            c, s = np.cos(np.radians(turn)), np.sin(np.radians(turn))
            d = side * np.array([c * n[0] - s * n[1], s * n[0] + c * n[1]])
            tried += [(turn, side, gap, d) for gap in gaps_pt]
    boxes = _boxes_at(anchor_px, np.array([t[3] for t in tried]), size,
                      np.array([t[2] * px_per_pt for t in tried], float))
    for k in np.flatnonzero(obstacles.free_many(boxes, pad_px)):
        turn, side, gap, _ = tried[k]
        box = tuple(boxes[k])
        cost = (curve_weight * obstacles.curve_cost(box) + gap
                + abs(turn) / 30.0 + (0 if side > 0 else 0.5))
        if best is None or cost < best[0]:
            best = (cost, box)
    if best is None and far and max(gaps_pt) < _FAR[-1]:
        # nowhere near: try farther out before giving up
        return place_label(ax, obstacles, anchor_px, text, normal, _FAR, pad_px,
                           curve_weight, gid, far=False, **text_kw)
    if best is None:
        return None
    box = best[1]
    inv = ax.transData.inverted()
    centre = inv.transform(((box[0] + box[2]) / 2, (box[1] + box[3]) / 2))
    t = ax.text(centre[0], centre[1], text, ha="center", va="center", gid=gid, **text_kw)
    obstacles.boxes.append(box)
    return t


def label_points(ax, obstacles, xy_px, texts, normals, order, merge_px=3.0, **kw):
    """Label many points: points closer than ``merge_px`` share one label (texts joined
    by "/"), labels are placed in ``order`` (most important first) by :func:`place_label`.

    Returns
    -------
    (placed, thinned) : list of Text, list of str
    """
    xy_px = np.asarray(xy_px, float)
    groups, taken = [], np.zeros(len(xy_px), bool)
    for i in order:
        if taken[i]:
            continue
        near = np.flatnonzero(np.hypot(*(xy_px - xy_px[i]).T) < merge_px)
        near = [j for j in near if not taken[j]]
        taken[near] = True
        groups.append((i, sorted(near)))
    placed, thinned = [], []
    for n, (i, members) in enumerate(groups):
        text = "/".join(texts[j] for j in members)
        # the first (most important) label is looked for farther out too
        t = place_label(ax, obstacles, xy_px[i], text, normals[i], far=n == 0, **kw)
        (placed.append(t) if t is not None else thinned.append(text))
    return placed, thinned


def add_axes_lines(obstacles, ax, to_px=None):
    """Add every line of ``ax`` to ``obstacles``: its segments (when it has a line style)
    and its finite markers (at their size in pixels, plus one); ``to_px`` the data → display
    transform (default ``ax.transData.transform``).  Returns ``obstacles``."""
    import numpy as np

    to_px = ax.transData.transform if to_px is None else to_px
    dpi = ax.figure.dpi
    for line in ax.lines:
        xy = to_px(line.get_xydata())
        if line.get_linestyle() not in ("None", "none", "", " "):
            obstacles.add_line(xy)
        if line.get_marker() not in (None, "None", "none", ""):
            for p in xy:
                if np.all(np.isfinite(p)):
                    obstacles.add_marker(p, line.get_markersize() * dpi / 72 + 1)
    return obstacles


def frozen_frame(ax):
    """Fix the axes' limits where they are now (autoscaled, aspect applied) so that the
    labels placed next keep their place, and return ``(to_px, obstacles)``: the data →
    display transform and an :class:`Obstacles` whose frame is the axes' box.  The one
    preamble of every label placement."""
    renderer_of(ax.figure)
    ax.autoscale_view()
    ax.apply_aspect()
    ax.set_xlim(ax.get_xlim())
    ax.set_ylim(ax.get_ylim())
    ax.set_autoscale_on(False)
    bb = ax.get_window_extent()
    return ax.transData.transform, Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))


def fixed_axes_obstacles(ax):
    """Fix ``ax`` as it will be saved — the final axes box (after a layout engine), the
    aspect, the limits (autoscale off, so labels added later do not move them) — and
    return ``(to_px, obstacles)``: its data → display transform and :class:`Obstacles`
    framed by the axes' box holding every line of the axes (:func:`add_axes_lines`).
    The first step of placing labels on a finished plot."""
    fig = ax.figure
    renderer_of(fig)
    run_layout(fig)            # the final axes box (a layout engine's), nothing drawn
    ax.apply_aspect()
    ax.set_xlim(ax.get_xlim())
    ax.set_ylim(ax.get_ylim())
    ax.set_autoscale_on(False)
    to_px = ax.transData.transform
    bb = ax.get_window_extent()
    obs = Obstacles(frame=(bb.x0, bb.y0, bb.x1, bb.y1))
    add_axes_lines(obs, ax, to_px)
    return to_px, obs
