"""The drawing sheet as DXF (ezdxf), in real millimetres, one layer per kind of line.

Layers (ГОСТ 2.303 line kinds; lineweights in 1/100 mm):

========  ===========================================  ==========
layer     what                                         lineweight
========  ===========================================  ==========
FRAME     the sheet's frame and the title block's      70 (S = 0.7 mm)
          main lines
MAIN      links of the chosen positions (plan of       70
          positions)
VECTORS   the vectors of the plans (one LINE each,     70
          with a SOLID arrowhead)
LEVER     force arrows of the Zhukovsky lever          70
THIN      thin lines: other positions, the lever's     30 (S/2.3)
          turned plan, the title block's thin lines
DASHED    the crank circle (dashed thin line)          30
TEXT      every text (style GOST: ISOCPEUR font,       25
          height = capital height, ГОСТ 2.304)
========  ===========================================  ==========

Each vector's LINE carries its name ``<position>:<plan>:<segment>`` as XDATA of the
application ``CRANKDYN``, so a CAD user (and the tests) can match it with ``plans.csv``.

A sheet of the same inputs is the same bytes, in every run and under every
``PYTHONHASHSEED`` (:func:`dxf_bytes`): ezdxf would stamp the time of each save and fresh
random GUIDs, and list the CLASSES of the entity types in use in the order of a ``set``.
Here the dates (``$TDCREATE``, ``$TDUCREATE``, ``$TDUPDATE``, ``$TDUUPDATE`` and ezdxf's own
created/written marks) are ezdxf's fixed date, 2000-01-01 (its documented option
``write_fixed_meta_data_for_testing``, set only while a sheet is written), the classes are
sorted by name, and ``$FINGERPRINTGUID`` / ``$VERSIONGUID`` are name-based UUIDs (RFC 4122
version 5) of the drawing's content: equal for equal drawings, different for different
ones.
"""
from __future__ import annotations

import hashlib
import io
import re
import threading
import uuid

from .layout import Arrow, Circle, Line, Text, arrow_parts

__all__ = ["sheet_dxf", "write_dxf", "dxf_bytes", "LAYERS", "APPID", "FIXED_DATE"]

APPID = "CRANKDYN"
LAYERS = {"FRAME": 70, "MAIN": 70, "VECTORS": 70, "LEVER": 70, "THIN": 30, "DASHED": 30,
          "TEXT": 25}


#: The text style and font of a text with Chinese characters (GB/T 14691 lettering is
#: set in a CJK font; SimHei ships with every Chinese Windows and AutoCAD substitutes
#: its own CJK font where it is missing); other texts keep the GOST style.
CJK_STYLE = "GOST_CJK"
CJK_FONT = "simhei.ttf"
CJK_TEXT = re.compile("[\u3000-\u303f\u3400-\u4dbf\u4e00-\u9fff\uff00-\uffef]")


def sheet_dxf(sheet, names=None):
    """An ezdxf document of a sheet (A1/A3 landscape, $INSUNITS = mm, limits = the sheet).

    Parameters
    ----------
    sheet : plans.layout.Sheet
    names : dict, optional
        Arrow name → the name stored as XDATA (default: the arrow's own name).
    """
    import ezdxf

    doc = ezdxf.new("R2010", setup=True, units=4)       # 4 = millimetres
    doc.header["$MEASUREMENT"] = 1                       # metric
    doc.appids.add(APPID)
    for name, lw in LAYERS.items():
        layer = doc.layers.add(name, color=7)
        layer.dxf.lineweight = lw
        if name == "DASHED":
            layer.dxf.linetype = "DASHED"
    doc.styles.add("GOST", font="isocpeur.ttf")
    cjk = any(isinstance(it, Text) and CJK_TEXT.search(it.text) for it in sheet.items)
    if cjk:     # a Chinese sheet: a text style whose font has the CJK glyphs
        doc.styles.add(CJK_STYLE, font=CJK_FONT)
    msp = doc.modelspace()
    msp.reset_limits((0.0, 0.0), (sheet.width, sheet.height))
    msp.reset_extents((0.0, 0.0, 0.0), (sheet.width, sheet.height, 0.0))
    align = {("left", "bottom"): "BOTTOM_LEFT", ("center", "bottom"): "BOTTOM_CENTER",
             ("right", "bottom"): "BOTTOM_RIGHT", ("left", "center"): "MIDDLE_LEFT",
             ("center", "center"): "MIDDLE_CENTER", ("right", "center"): "MIDDLE_RIGHT",
             ("left", "top"): "TOP_LEFT", ("center", "top"): "TOP_CENTER",
             ("right", "top"): "TOP_RIGHT"}
    for it in sheet.items:
        if isinstance(it, Line):
            msp.add_line((it.p1.real, it.p1.imag), (it.p2.real, it.p2.imag),
                         dxfattribs={"layer": it.layer})
        elif isinstance(it, Arrow):
            head = arrow_parts(it.p1, it.p2)
            if head is None:
                continue
            line = msp.add_line((it.p1.real, it.p1.imag), (it.p2.real, it.p2.imag),
                                dxfattribs={"layer": it.layer})
            if it.name:
                line.set_xdata(APPID, [(1000, (names or {}).get(it.name, it.name))])
            tip, left, right = head
            msp.add_solid([(tip.real, tip.imag), (left.real, left.imag),
                           (right.real, right.imag)], dxfattribs={"layer": it.layer})
        elif isinstance(it, Text):
            style = CJK_STYLE if cjk and CJK_TEXT.search(it.text) else "GOST"
            t = msp.add_text(it.text, height=it.height,
                             dxfattribs={"layer": "TEXT", "style": style})
            t.set_placement((it.at.real, it.at.imag), align=_align(align[(it.ha, it.va)]))
        elif isinstance(it, Circle):
            msp.add_circle((it.center.real, it.center.imag), it.r,
                           dxfattribs={"layer": it.layer})
    return doc


def _align(name):
    from ezdxf.enums import TextEntityAlignment

    return getattr(TextEntityAlignment, name)


#: The creation and update date of every sheet written (ezdxf's fixed date; ISO 8601).
FIXED_DATE = "2000-01-01T00:00:00+00:00"

#: ezdxf's fixed metadata (its option ``write_fixed_meta_data_for_testing``) is a global
#: of the process: one writer at a time sets and restores it.
_FIXED_META = threading.Lock()

#: Namespace of the name-based GUIDs of the drawings (uuid5 of the URL of the project).
_GUID_NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "https://crankdyn/plans/dxf")


def dxf_bytes(sheet) -> bytes:
    """The DXF file of a sheet (:func:`sheet_dxf`) as bytes, the same for the same sheet in
    every run and hash seed (module docstring)."""
    import ezdxf
    from ezdxf.document import CONST_GUID, CONST_MARKER_STRING, CREATED_BY_EZDXF

    doc = sheet_dxf(sheet)
    doc.ezdxf_metadata()[CREATED_BY_EZDXF] = f"{ezdxf.__version__} @ {FIXED_DATE}"
    doc.commit_pending_changes()
    doc.classes.add_required_classes(doc.dxfversion)     # in the order of a set: sort them
    doc.classes.classes = dict(sorted(doc.classes.classes.items()))
    stream = io.StringIO()
    with _FIXED_META:
        before = ezdxf.options.write_fixed_meta_data_for_testing
        ezdxf.options.write_fixed_meta_data_for_testing = True
        try:
            doc.write(stream)
        finally:
            ezdxf.options.write_fixed_meta_data_for_testing = before
    text = stream.getvalue().replace(CONST_MARKER_STRING,
                                     f"{ezdxf.__version__} @ {FIXED_DATE}")
    digest = hashlib.sha256(text.encode("utf-8")).hexdigest()
    for var in ("$FINGERPRINTGUID", "$VERSIONGUID"):
        tag = f"{var}\n  2\n{CONST_GUID}\n"
        if text.count(tag) != 1:
            raise RuntimeError(f"ezdxf wrote {var} not as expected: {text.count(tag)} times")
        guid = uuid.uuid5(_GUID_NAMESPACE, f"{var}:{digest}")
        text = text.replace(tag, f"{var}\n  2\n{{{str(guid).upper()}}}\n")
    return doc.encode(text)


def write_dxf(sheet, path):
    """Write :func:`dxf_bytes` of ``sheet`` to ``path`` (the caller makes it atomic)."""
    from pathlib import Path

    Path(path).write_bytes(dxf_bytes(sheet))
