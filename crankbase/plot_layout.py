"""A figure's layout (constrained, tight) run without drawing the figure.

``Figure.savefig`` of a figure with a layout engine draws it twice: a draw with every
drawing call disabled, only to run the layout, then the draw into the file.  And
``Figure.draw_without_rendering``, used to know the final axes box before placing labels,
is a whole draw for the same layout.  :func:`run_layout` runs the layout as that first
draw does it (the axes' aspect applied, then the engine, texts measured by the renderer of
the output format at the dpi that saving sets) and nothing else; :func:`save_laid_out` saves a
figure that way: the layout once, the figure drawn once, the same pixels and the same
vector coordinates as ``fig.savefig``.  Only placement: nothing here computes physics.

matplotlib is imported by the callers (this module is imported from the plot and output
code only, when a figure exists).
"""
from __future__ import annotations

__all__ = ["run_layout", "save_laid_out", "layout_dpi", "VECTOR_FORMATS"]

#: Formats whose backend draws at 72 dpi (one point a unit): saving one sets the figure's
#: dpi to 72 before its layout runs, whatever ``dpi`` savefig was given.
VECTOR_FORMATS = ("svg", "pdf")


def layout_dpi(fmt: str, dpi: float) -> float:
    """The dpi at which ``fig.savefig(format=fmt, dpi=dpi)`` runs the layout: 72 for a
    vector format (:data:`VECTOR_FORMATS`), ``dpi`` for PNG."""
    return 72 if fmt in VECTOR_FORMATS else dpi


def _agg_canvas(fig):
    """Whether ``fig``'s canvas is matplotlib's Agg canvas or the bare one of a new
    ``Figure`` (what :func:`run_layout` mimics: savefig switches either to the canvas of
    the format)."""
    from matplotlib.backend_bases import FigureCanvasBase
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    return type(fig.canvas) in (FigureCanvasBase, FigureCanvasAgg)


def run_layout(fig, dpi=None, fmt="png") -> bool:
    """Run ``fig``'s layout engine as ``Figure.draw`` does when ``fig`` is saved as
    ``fmt``, without drawing: the figure at ``dpi`` (default: its own; 72 for a vector
    format, :func:`layout_dpi`), the texts measured by the renderer of that format (Agg
    for PNG, the SVG or PDF renderer for those: savefig's layout of a vector file measures
    with it), each axes' aspect (and locator, secondary axes' too) applied first.  The
    figure's canvas and dpi are left as they were.  Returns False (and does nothing) for a
    figure without a layout engine or without axes, which ``Figure.draw`` lays out
    neither."""
    from matplotlib.backend_bases import get_registered_canvas_class

    engine = fig.get_layout_engine()
    if engine is None or not fig.axes:
        return False
    canvas, old_dpi = fig.canvas, fig.dpi
    try:
        if dpi is not None:
            fig.dpi = layout_dpi(fmt, dpi)
        if not hasattr(canvas, f"print_{fmt}"):       # as savefig: the format's canvas
            get_registered_canvas_class(fmt)(fig)     # (attaches itself to fig)
        renderer = fig._get_renderer()
        for ax in fig.axes:                           # as Figure._get_draw_artists
            locator = ax.get_axes_locator()
            ax.apply_aspect(locator(ax, renderer) if locator else None)
            for child in ax.get_children():
                if hasattr(child, "apply_aspect"):
                    locator = child.get_axes_locator()
                    child.apply_aspect(locator(child, renderer) if locator else None)
        try:
            engine.execute(fig)
        except ValueError:                            # as Figure.draw: a figure too small
            pass
    finally:
        if fig.canvas is not canvas:
            fig.set_canvas(canvas)
        if fig.dpi != old_dpi:
            fig.dpi = old_dpi
    return True


def _tight_box(fig, engine, pad_inches, extra_artists):
    """The box ``bbox_inches="tight"`` crops to (in inches), as savefig finds it: the
    figure's tight box measured by the renderer of the canvas and dpi in place, padded by
    ``pad_inches`` ("layout": the constrained layout's pads)."""
    import matplotlib
    from matplotlib.layout_engine import ConstrainedLayoutEngine

    box = fig.get_tightbbox(fig._get_renderer(), bbox_extra_artists=extra_artists)
    if isinstance(engine, ConstrainedLayoutEngine) and pad_inches == "layout":
        w_pad, h_pad = engine.get()["w_pad"], engine.get()["h_pad"]
    else:
        if pad_inches in (None, "layout"):
            pad_inches = matplotlib.rcParams["savefig.pad_inches"]
        w_pad = h_pad = pad_inches
    return box.padded(w_pad, h_pad)


def save_laid_out(fig, path, fmt: str, dpi: float, **kwargs) -> None:
    """``fig.savefig(path, format=fmt, dpi=dpi, **kwargs)`` with the layout run once by
    :func:`run_layout` at the dpi saving lays out at (:func:`layout_dpi`) and the figure
    then saved without its layout engine: savefig draws it once instead of twice.  A PNG
    cropped ``bbox_inches="tight"`` has its crop measured right after that layout (savefig
    measures it after its first draw) and given to savefig as a box.  The same file as
    ``fig.savefig``'s (the same pixels; SVG and PDF the same but for their date and
    random ids), and the figure keeps its engine.  Where that is not known to hold (no
    layout engine, a crop to a given box, a cropped SVG or PDF (measured without that
    draw, a legend moves by 1e-6 pt), another canvas than Agg, a format other than PNG,
    SVG or PDF) this is plain ``fig.savefig``."""
    import matplotlib
    from matplotlib.backend_bases import get_registered_canvas_class

    engine = fig.get_layout_engine()
    bbox = kwargs.pop("bbox_inches", matplotlib.rcParams["savefig.bbox"])
    plain = (engine is None or not fig.axes or not isinstance(dpi, (int, float))
             or fmt not in ("png", *VECTOR_FORMATS) or bbox not in (None, "tight")
             or (bbox == "tight" and fmt != "png")
             or not _agg_canvas(fig) or getattr(fig, "_layout_engine", None) is not engine)
    if plain:
        fig.savefig(path, format=fmt, dpi=dpi, bbox_inches=bbox, **kwargs)
        return
    canvas = fig.canvas
    try:
        # the format's canvas for the layout and the save, as savefig switches to it for
        # both: one Agg renderer measures every text once (its measures are cached by
        # renderer)
        if not hasattr(canvas, f"print_{fmt}"):
            get_registered_canvas_class(fmt)(fig)
        run_layout(fig, dpi, fmt)
        if bbox == "tight":
            old_dpi = fig.dpi
            fig.dpi = layout_dpi(fmt, dpi)
            try:
                bbox = _tight_box(fig, engine, kwargs.pop("pad_inches", None),
                                  kwargs.pop("bbox_extra_artists", None))
            finally:
                fig.dpi = old_dpi
        # No engine while saving (what savefig does itself after its first draw):
        # savefig skips that draw (and with a box, not "tight", its measuring draw).
        # matplotlib has no public setter for "no engine"; "none" leaves a placeholder
        # engine, for which savefig would still draw twice.
        fig._layout_engine = None
        fig.savefig(path, format=fmt, dpi=dpi, bbox_inches=bbox, **kwargs)
    finally:
        fig.set_layout_engine(engine)
        if fig.canvas is not canvas:
            fig.set_canvas(canvas)
