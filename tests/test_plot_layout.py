"""crankbase.plot_layout: a figure with a layout engine is laid out and drawn once per
saved file, and the file is the one ``fig.savefig`` writes (PNG pixels, SVG and PDF
text with a fixed date and id salt)."""
from __future__ import annotations

import io

import matplotlib
import numpy as np
import pytest
from matplotlib.figure import Figure

from crankbase.output import save_figure
from crankbase.plot_layout import layout_dpi, run_layout, save_laid_out

#: Fixed date and ids: two saves of one drawing give the same bytes.
FIXED = {"svg.hashsalt": "crankdyn", "svg.fonttype": "none"}
META = {"svg": {"Date": None}, "pdf": {"CreationDate": None}, "png": {}}


def _figure(layout="constrained"):
    """Two rows with long tick labels, a twin axis, a secondary axis, a legend, a title
    and a suptitle: every margin constrained layout measures, in text sizes that differ
    between the Agg renderer at 110 dpi and the vector renderers at 72."""
    fig = Figure(figsize=(6.2, 4.4), layout=layout)
    a, b = fig.subplots(2, 1)
    x = np.linspace(0.0, 720.0, 181)
    a.plot(x, 1e4 * np.sin(np.radians(x)), label="$M_{кр}$, Н·м")
    a.set_ylabel("крутящий момент $M$, Н·м")
    a.legend(loc="upper right")
    a.set_title("α, °")
    twin = a.twinx()
    twin.plot(x, np.cos(np.radians(x)), "r")
    twin.set_ylabel("ω, рад/с")
    b.plot(x, x ** 1.5)
    b.secondary_xaxis("top", functions=(lambda v: v / 360.0, lambda v: v * 360.0))
    b.set_xlabel("угол поворота кривошипа φ, °")
    fig.suptitle("Диаграмма Виттенбауэра")
    return fig


def _saved(fig, fmt, save):
    buf = io.BytesIO()
    with matplotlib.rc_context(FIXED):
        save(fig, buf, fmt)
    return buf.getvalue()


def _plain(fig, buf, fmt, **kw):
    fig.savefig(buf, format=fmt, dpi=110, metadata=META[fmt], **kw)


def _once(fig, buf, fmt, **kw):
    save_laid_out(fig, buf, fmt, 110, metadata=META[fmt], **kw)




def _pixels(data):
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(data)).convert("RGBA"))


@pytest.mark.parametrize("layout", ["constrained", "compressed", "tight"])
def test_same_files_as_savefig(layout):
    # two equal figures, each saved PNG, SVG, PDF in turn (the order of a report: each
    # save starts where the one before left the axes)
    plain, once = _figure(layout), _figure(layout)
    for fmt in ("png", "svg", "pdf", "png"):
        a, b = _saved(plain, fmt, _plain), _saved(once, fmt, _once)
        if fmt == "png":
            assert np.array_equal(_pixels(a), _pixels(b))
        else:
            assert a == b, fmt
    assert once.get_layout_engine() is not None          # the engine stays
    assert type(once.get_layout_engine()) is type(plain.get_layout_engine())


@pytest.mark.parametrize("pad", [0.15, "layout"])
def test_same_crops_as_savefig(pad):
    # bbox_inches="tight" (the synthesis figures): the box measured after the layout
    plain, once = _figure(), _figure()
    crop = {"bbox_inches": "tight", "pad_inches": pad}
    for fmt in ("png", "svg", "pdf"):
        a = _saved(plain, fmt, lambda f, b, m: _plain(f, b, m, **crop))
        b = _saved(once, fmt, lambda f, b, m: _once(f, b, m, **crop))
        if fmt == "png":
            assert _pixels(a).shape == _pixels(b).shape
            if pad != "layout":     # a crop indeed (the layout's pads: the whole figure)
                assert _pixels(a).shape != _pixels(_saved(_figure(), fmt, _plain)).shape
            assert np.array_equal(_pixels(a), _pixels(b))
        else:                       # cropped vector files: savefig's own way
            assert a == b, fmt


def test_vector_layout_is_measured_by_the_vector_renderer():
    # savefig lays out an SVG at 72 dpi with the SVG renderer's text sizes: an Agg
    # measure at 72 dpi moves the axes (this is what the test above guards)
    ref = _figure()
    _saved(ref, "svg", _plain)
    boxes = [ax.get_position().bounds for ax in ref.axes]
    fig = _figure()
    run_layout(fig, 110, "svg")
    assert [ax.get_position().bounds for ax in fig.axes] == boxes
    agg = _figure()
    run_layout(agg, 72, "png")
    assert [ax.get_position().bounds for ax in agg.axes] != boxes
    assert layout_dpi("svg", 110) == layout_dpi("pdf", 300) == 72
    assert layout_dpi("png", 110) == 110


def test_drawn_once_per_file(tmp_path):
    # a draw event per Figure.draw: savefig draws a figure with a layout engine twice
    # (the first draw only to lay it out), save_figure once
    fig = _figure()
    draws = []
    fig.canvas.mpl_connect("draw_event", lambda event: draws.append(event))
    fig.savefig(tmp_path / "a.png", dpi=110)
    assert len(draws) == 2
    draws.clear()
    save_figure(fig, tmp_path / "b", formats=("png", "svg"))
    assert len(draws) == 2
    draws.clear()
    save_figure(fig, tmp_path / "c", formats=("png",), tight=True)   # a crop too
    assert len(draws) == 1


def test_run_layout_leaves_canvas_and_dpi():
    fig = _figure()
    canvas, dpi = fig.canvas, fig.dpi
    before = [ax.get_position().bounds for ax in fig.axes]
    assert run_layout(fig, 150, "pdf")
    assert fig.canvas is canvas and fig.dpi == dpi
    assert [ax.get_position().bounds for ax in fig.axes] != before     # laid out
    bare = Figure()
    assert not run_layout(bare)                    # no axes: nothing to lay out
    fixed = Figure(figsize=(4, 3))
    fixed.add_subplot()
    assert not run_layout(fixed)                   # no layout engine
