"""One automatic check of a figure's words: nothing overlaps, nothing is cut (issue #23).

:func:`figure_problems` lays a figure out as Agg draws it (:func:`drawn`: no file, no
pixels) and measures, in display pixels,

* every visible text (titles, axis labels, tick labels, legend texts, annotations, texts
  of drawings) against every other text: their boxes must not overlap;
* every text against the figure's edge: its box must lie inside the figure (a text
  drawn clipped by its axes must lie inside the clip box);
* every text against the drawn lines of its figure: the curves and straight lines of the
  axes (``Line2D``), arrows (``FancyArrowPatch``), the edges of drawn shapes and line
  collections, and the axes' own frame lines: the lines are sampled along their display
  paths (every pixel or so) and no sample may fall inside a text's box.

A ``margin_px`` lets a box touch what it does not cover (the ink of a glyph does not
fill its box).  :func:`marker_problems` checks the lone marks (a line drawn as markers
only: "the largest" circle, critical speeds): each must be drawn whole, neither cut by
its axes' clip box (a mark at the axes' edge shows half a circle) nor by the figure's
edge.  Line collections with ``gid="paper-grid"`` (the millimetre grid of the
drawings, drawn under everything, like the grid lines of the axes) are background, not
lines.  This is a test tool (tests import it), not part of the library.
"""
from __future__ import annotations

import contextlib

import numpy as np

__all__ = ["figure_problems", "marker_problems", "texts_of", "line_samples", "drawn"]

BACKGROUND_GIDS = {"paper-grid"}


def texts_of(fig, renderer):
    """``[(label, Bbox, Text)]`` of every visible, non-empty text the figure draws."""
    from matplotlib.text import Annotation, Text

    out = []
    seen = set()

    def add(t, where):
        if id(t) in seen or not t.get_visible() or not t.get_text().strip():
            return
        seen.add(id(t))
        if t.axes is not None and not t.axes.get_visible():
            return
        bb = Text.get_window_extent(t, renderer)
        if bb.width <= 0 or bb.height <= 0:
            return
        out.append((f"{where}: {t.get_text()!r}", bb, t))

    for ax in fig.axes:
        if not ax.get_visible():
            continue
        for axis in (ax.xaxis, ax.yaxis):
            if not ax.axison or not axis.get_visible():
                continue
            for tick in axis._update_ticks():            # the ticks Agg draws
                for lab in (tick.label1, tick.label2):
                    if lab.get_visible():
                        add(lab, "tick")
            add(axis.label, "axis label")
            add(axis.offsetText, "offset")
        for t in (ax.title, ax._left_title, ax._right_title):
            add(t, "title")
        for t in ax.texts:
            add(t, "annotation" if isinstance(t, Annotation) else "text")
        leg = ax.get_legend()
        if leg is not None and leg.get_visible():
            for t in leg.get_texts():
                add(t, "legend")
            if leg.get_title().get_text():
                add(leg.get_title(), "legend title")
    for t in fig.texts:
        add(t, "figure text")
    for leg in fig.legends:
        for t in leg.get_texts():
            add(t, "figure legend")
    if getattr(fig, "_suptitle", None) is not None:
        add(fig._suptitle, "suptitle")
    return out


def _resample(xy, step):
    """Points along the polyline ``xy`` at most ``step`` px apart (a non-finite point
    breaks the line, as it does when drawn)."""
    xy = np.asarray(xy, float).reshape(-1, 2)
    bad = ~np.all(np.isfinite(xy), axis=1)
    if bad.any():
        parts = np.split(xy, np.flatnonzero(bad))
        parts = [_resample(p[np.all(np.isfinite(p), axis=1)], step) for p in parts]
        parts = [p for p in parts if len(p)]
        return np.concatenate(parts) if parts else np.empty((0, 2))
    if len(xy) < 2:
        return xy
    seg = np.hypot(*np.diff(xy, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    if s[-1] == 0:
        return xy[:1]
    n = int(min(max(np.ceil(s[-1] / step) + 1, len(xy)), 200000))
    t = np.linspace(0.0, s[-1], n)
    return np.column_stack([np.interp(t, s, xy[:, 0]), np.interp(t, s, xy[:, 1])])


def _path_points(path, transform, step):
    """Display points along a path (each sub-path sampled separately; curves as their
    polygons)."""
    if path.codes is None and transform.is_affine:
        # what transform_path and to_polygons give for a plain polyline under an affine
        # transform (no curves to flatten, no sub-paths): its transformed vertices
        return _resample(transform.transform(path.vertices), step)
    pts = []
    path = transform.transform_path(path)
    for poly in path.to_polygons(closed_only=False):
        pts.append(_resample(poly, step))
    return np.concatenate(pts) if pts else np.empty((0, 2))


def _clip(points, artist):
    """The points inside the artist's clip box (what Agg draws of a clipped line)."""
    box = artist.get_clip_box() if artist.get_clip_on() else None
    if box is None or not len(points):
        return points
    x, y = points[:, 0], points[:, 1]
    return points[(x >= box.x0 - 0.5) & (x <= box.x1 + 0.5) & (y >= box.y0 - 0.5)
                  & (y <= box.y1 + 0.5)]


def _line_parts(fig):
    """``(label, paths, transform, clipper)`` of every drawn line of the figure, in the
    order :func:`line_samples` lists them (``clipper``: the artist whose clip box cuts
    the line, None for arrows and the axes' frame)."""
    from matplotlib.collections import LineCollection
    from matplotlib.text import Annotation

    for ax in fig.axes:
        if not ax.get_visible():
            continue
        for line in ax.lines:
            if not line.get_visible() or line.get_linestyle() in ("None", "", " ", "none"):
                continue
            if line.get_alpha() == 0 or line.get_linewidth() <= 0:
                continue
            yield f"line {line.get_label()!r}", (line.get_path(),), line.get_transform(), line
        for p in ax.patches:
            if not p.get_visible() or p.get_linewidth() <= 0:
                continue
            ec = p.get_edgecolor()
            if ec is None or ec[3] == 0:
                continue
            yield f"{type(p).__name__} edge", (p.get_path(),), p.get_transform(), p
        for t in ax.texts:
            if isinstance(t, Annotation) and t.arrow_patch is not None and t.get_visible():
                ap = t.arrow_patch
                yield f"arrow of {t.get_text()!r}", (ap.get_path(),), ap.get_transform(), None
        for c in ax.collections:
            if not isinstance(c, LineCollection) or not c.get_visible():
                continue
            if c.get_gid() in BACKGROUND_GIDS:
                continue
            paths = c.get_paths()
            if len(paths):
                yield "line collection", paths, c.get_transform(), c
        if ax.axison:
            for name, sp in ax.spines.items():
                if sp.get_visible():
                    yield f"axes frame ({name})", (sp.get_path(),), sp.get_transform(), None


def _samples(paths, transform, clipper, step):
    """Display points along the paths (what Agg draws of them: cut by the clipper's clip
    box)."""
    pts = [_path_points(p, transform, step) for p in paths]
    pts = pts[0] if len(pts) == 1 else np.concatenate(pts)
    return pts if clipper is None else _clip(pts, clipper)


def _vertex_extent(paths, transform):
    """``(x0, y0, x1, y1)`` in display pixels holding every sample :func:`_samples` can
    give of the paths under an affine ``transform`` (their transformed vertices'
    extent: a polyline's samples lie on its segments, a curve's polygon inside its
    control points' hull, and an affine map keeps both), None when no vertex is finite
    (no sample), NotImplemented for a non-affine transform (a polar axes' curve bends
    between its vertices)."""
    if not transform.is_affine:
        return NotImplemented
    v = paths[0].vertices if len(paths) == 1 else np.concatenate([p.vertices for p in paths])
    xy = transform.transform(np.asarray(v, float).reshape(-1, 2))
    xy = xy[np.isfinite(xy).all(axis=1)]
    if not len(xy):
        return None
    (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
    return x0, y0, x1, y1


def line_samples(fig, step=1.0):
    """``[(label, points)]``: display points along every drawn line of the figure."""
    return [(label, _samples(paths, tr, clipper, step))
            for label, paths, tr, clipper in _line_parts(fig)]


#: Agg renderers by (width px, height px, dpi), reused from figure to figure (see
#: :func:`drawn`); a few sizes kept (an A1 sheet's canvas is 30 MB).
_RENDERERS = {}


#: Text layouts by everything they depend on (see :func:`_layouts_once`), kept from
#: figure to figure (the sheets of a mechanism repeat their labels, the tick labels of
#: the figures of a report their numbers).
_LAYOUTS = {}


@contextlib.contextmanager
def _layouts_once():
    """Within it, a text's layout (``Text._get_layout``: its box and lines relative to
    its anchor, what ``draw`` and ``get_window_extent`` compute) is computed once for
    every distinct text, font, alignment, rotation, dpi, renderer type and text settings
    (matplotlib's ``text.*``, ``font.*`` and ``mathtext.*`` rcParams), and read back the
    next time (a figure check asks for it three times: the draw, the axes' tight boxes
    and :func:`texts_of`; a tick label of the same text and font on another axes or
    figure is the same layout).  The layout depends on nothing else (not on where the
    text is: an Agg renderer measures a text by its font and dpi alone); a wrapped text
    (laid out by its position) is computed each time."""
    from matplotlib import rcParams
    from matplotlib.text import Text

    real = Text._get_layout
    if len(_LAYOUTS) > 200000:
        _LAYOUTS.clear()
    settings = tuple((k, repr(rcParams[k])) for k in sorted(rcParams)
                     if k.startswith(("text.", "font.", "mathtext.")))

    def get_layout(self, renderer):
        if self.get_wrap():
            return real(self, renderer)
        fp = self._fontproperties
        key = (self._text, tuple(fp.get_family()), fp.get_style(), fp.get_variant(),
               fp.get_weight(), fp.get_stretch(), fp.get_size(), fp.get_file(),
               fp.get_math_fontfamily(), self.get_usetex(),
               self._parse_math, self._linespacing, self._multialignment,
               self._horizontalalignment, self._verticalalignment, self.get_rotation(),
               self.get_rotation_mode(), self.get_figure(root=True).dpi,
               type(renderer), renderer.dpi, settings)
        hit = _LAYOUTS.get(key)
        if hit is None:
            hit = _LAYOUTS[key] = real(self, renderer)
        return hit

    Text._get_layout = get_layout
    try:
        yield
    finally:
        Text._get_layout = real


def drawn(fig):
    """Lay ``fig`` out as Agg draws it, without rasterising it: the figure is drawn with
    an Agg renderer whose ``draw_*`` calls do nothing (matplotlib's
    ``Figure.draw_without_rendering``, with the renderer kept), so every tick, text
    position, legend place and layout is the one a saved PNG shows (the same text
    metrics), at about half the cost of a real draw.  Returns the renderer.

    The renderer of a figure of the same size in pixels and dpi is reused: a
    ``RendererAgg`` allocates and clears its whole canvas when made (35 ms for an A1
    sheet), and a renderer whose drawing calls did nothing is still blank, so the
    next figure is laid out by an identical one (what ``FigureCanvasAgg.get_renderer``
    does for one canvas drawn twice)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg

    canvas = FigureCanvasAgg(fig)
    w, h = canvas.get_width_height(physical=True)
    key = (w, h, fig.dpi)
    renderer = _RENDERERS.pop(key, None) or RendererAgg(w, h, fig.dpi)
    _RENDERERS[key] = renderer                          # the newest last
    while len(_RENDERERS) > 4:
        del _RENDERERS[next(iter(_RENDERERS))]
    canvas.renderer, canvas._lastKey = renderer, key    # canvas.get_renderer() is it
    with renderer._draw_disabled(), _lines_not_drawn(), _texts_not_drawn():
        fig.draw(renderer)
    return renderer


@contextlib.contextmanager
def _lines_not_drawn():
    """Within it, ``Line2D.draw`` (curves, tick marks, legend handles) does nothing but
    mark the line drawn: with the renderer's drawing switched off it only prepares the
    line's display path for the renderer, which no check reads (:func:`line_samples`
    transforms each line's own path) and which places no text (tick labels, legends,
    annotations and layout engines are placed by their own draw and extents).  A tenth
    of a figure's layout for a drawing sheet of a thousand lines."""
    from matplotlib.lines import Line2D

    real = Line2D.draw

    def draw(self, renderer):
        self.stale = False

    Line2D.draw = draw
    try:
        yield
    finally:
        Line2D.draw = real


@contextlib.contextmanager
def _texts_not_drawn():
    """Within it, ``Text.draw`` does nothing but what it leaves behind: the text's
    renderer kept and the text marked drawn.  With the renderer's drawing switched off
    it only lays the text out again (its box and lines, read anew by every extent) and
    hands its glyphs to a renderer that draws nothing; a text's place is set before it
    is drawn (tick labels by their axis, legend texts by their box) and an annotation
    places its arrow in its own ``draw`` (still run: ``Annotation.draw`` calls
    ``Text.draw`` after it), so no extent a check reads changes.  (The box patch of a
    text with ``bbox`` is not placed: no check reads it.)"""
    from matplotlib.text import Text

    real = Text.draw

    def draw(self, renderer):
        if renderer is not None:
            self._renderer = renderer
        self.stale = False

    Text.draw = draw
    try:
        yield
    finally:
        Text.draw = real


def _inside(points, bb, m):
    x, y = points[:, 0], points[:, 1]
    return (x > bb.x0 + m) & (x < bb.x1 - m) & (y > bb.y0 + m) & (y < bb.y1 - m)


def figure_problems(fig, margin_px=1.5, line_margin_px=2.0, edge=True):
    """Every overlap and cut of ``fig``'s texts, as readable strings (empty: clean).

    Parameters
    ----------
    margin_px : float
        Two text boxes may overlap by this much (their glyphs' ink does not fill them).
    line_margin_px : float
        A line may enter a text box by this much at its border.
    edge : bool
        Check the texts against the figure's edge (False for a figure saved with a tight
        bounding box, whose edge is its content's).
    """
    with _layouts_once():
        r = drawn(fig)
        texts = texts_of(fig, r)
    problems = []
    W, H = fig.bbox.width, fig.bbox.height
    m = margin_px
    # every text's box as one row (x0, y0, x1, y1): the pairs compared at once
    boxes = np.array([[bb.x0, bb.y0, bb.x1, bb.y1] for _, bb, _ in texts],
                     float).reshape(-1, 4)
    wide = np.minimum.outer(boxes[:, 2], boxes[:, 2]) - np.maximum.outer(boxes[:, 0],
                                                                          boxes[:, 0])
    high = np.minimum.outer(boxes[:, 3], boxes[:, 3]) - np.maximum.outer(boxes[:, 1],
                                                                          boxes[:, 1])
    hit = np.tril((wide > m) & (high > m), k=-1)     # row i, column j < i
    for i, (name, bb, t) in enumerate(texts):
        if edge and (bb.x0 < -0.5 or bb.y0 < -0.5 or bb.x1 > W + 0.5 or bb.y1 > H + 0.5):
            problems.append(f"cut by the figure's edge: {name}")
        if t.get_clip_on() and t.get_clip_box() is not None:
            cb = t.get_clip_box()
            if bb.x0 < cb.x0 - m or bb.x1 > cb.x1 + m or bb.y0 < cb.y0 - m or bb.y1 > cb.y1 + m:
                problems.append(f"cut by its axes: {name}")
        for j in np.flatnonzero(hit[i]):
            problems.append(f"overlap: {name} and {texts[j][0]}")
    lm = line_margin_px

    def apart(x0, y0, x1, y1):                         # the extent meets no box
        return ((x1 <= boxes[:, 0] + lm) | (x0 >= boxes[:, 2] - lm)
                | (y1 <= boxes[:, 1] + lm) | (y0 >= boxes[:, 3] - lm)).all()

    for lname, paths, tr, clipper in _line_parts(fig):
        # a line whose vertices' extent meets no text box has no sample inside one: it
        # is not sampled (most of a drawing's thousand lines)
        ext = _vertex_extent(paths, tr)
        if ext is None or (ext is not NotImplemented and apart(*ext)):
            continue
        pts = _samples(paths, tr, clipper, 1.0)
        if not len(pts) or np.isnan(pts).all(axis=0).any():
            continue                                   # no sample can be inside a box
        (x0, y0), (x1, y1) = np.nanmin(pts, axis=0), np.nanmax(pts, axis=0)
        near = np.flatnonzero(~((x1 <= boxes[:, 0] + lm) | (x0 >= boxes[:, 2] - lm)
                                | (y1 <= boxes[:, 1] + lm) | (y0 >= boxes[:, 3] - lm)))
        for k in near:                                 # the line's extent meets the box
            name, bb, _ = texts[k]
            n = int(_inside(pts, bb, lm).sum())
            if n:
                problems.append(f"crossed: {name} by {lname} ({n} px)")
    return problems


_NO_MARKER = (None, "None", "none", "", " ")


def marker_problems(fig, margin_px=0.5, edge=True, draw=True):
    """Every lone mark of ``fig`` (a ``Line2D`` with markers and no line) that is not
    drawn whole, as readable strings (empty: clean).

    A mark's extent is its marker size plus its edge width (points → pixels); a clipped
    mark (``clip_on``, the default) must lie inside its clip box (the axes), every mark
    inside the figure (``edge``: False for a figure saved with a tight bounding box).
    ``margin_px`` lets the extent touch the border.  ``draw=False``: the figure has
    just been laid out (:func:`figure_problems` did) and is not changed since.
    """
    if draw:
        drawn(fig)
    W, H = fig.bbox.width, fig.bbox.height
    m = margin_px
    problems = []
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        for line in ax.lines:
            if (not line.get_visible() or line.get_marker() in _NO_MARKER
                    or line.get_linestyle() not in _NO_MARKER):
                continue
            r = (line.get_markersize() + line.get_markeredgewidth()) * fig.dpi / 72.0 / 2.0
            xy = line.get_transform().transform(np.asarray(line.get_xydata(), float))
            xy = xy[np.all(np.isfinite(xy), axis=1)]
            box = line.get_clip_box() if line.get_clip_on() else None
            for x, y in xy:
                where = f"mark {line.get_label()!r} at ({x:.0f}, {y:.0f}) px"
                if box is not None and (x - r < box.x0 - m or x + r > box.x1 + m
                                        or y - r < box.y0 - m or y + r > box.y1 + m):
                    problems.append(f"mark cut by its axes: {where}")
                if edge and (x - r < -m or x + r > W + m or y - r < -m or y + r > H + m):
                    problems.append(f"mark cut by the figure's edge: {where}")
    return problems
