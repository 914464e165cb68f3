"""Tables and files of the ККМ-φ0 synthesis: the paper's Table 1, the chosen mechanism,
the workbook and the spec TOML.

Everything here only arranges numbers computed by :mod:`linkage.synthesis`; pandas and
openpyxl are imported inside the functions that need them.  Every file is written
atomically (:func:`crankbase.output.atomic_path`): a crash never leaves half a file.
"""
from __future__ import annotations

import math
import re

import numpy as np

from crankbase.errors import Text
from crankbase.tolerances import ROUNDOFF_RTOL

from . import synthesis as syn

__all__ = ["table1", "mechanism_table", "format_deg_min", "summary_lines", "written_line",
           "grashof_text", "method_text", "toml_header", "write_workbook", "dumps_toml",
           "write_toml"]


def format_deg_min(deg) -> str:
    """An angle in degrees and whole minutes, as the paper prints it: ``46°16′``.

    Parameters
    ----------
    deg : float
        Angle. [deg]
    """
    deg = float(deg)
    if not math.isfinite(deg):
        return str(deg)
    sign = "−" if deg < 0 else ""
    total = round(abs(deg) * 60.0)
    return f"{sign}{total // 60}°{total % 60:02d}′"


def table1(phi0_deg=30.0, l1=None, step=0.05):
    """The paper's Table 1 for any φ0: where the family meets Kolchin's boundary line.

    Parameters
    ----------
    phi0_deg : float
        Crank angle where μ = 90°. [deg]
    l1 : sequence of float, optional
        Crank lengths of the rows; default: multiples of ``step`` below λ1max, then λ1max
        (for φ0 = 30°: 0.05, 0.10, 0.15, 0.1896, the paper's rows). [-]
    step : float
        Spacing of the default crank lengths. [-]

    Returns
    -------
    pandas.DataFrame
        Columns ``l1``, ``l2``, ``l3`` (relative lengths) and ``mu_min_deg`` (0: these
        mechanisms have a dead position).  Two rows per λ1, the larger λ2 first, as in the
        paper; one row where they coincide (λ1max).

    References
    ----------
    .. [1] Sereda (2016), Table 1 and eq. (9)–(10).
    """
    import pandas as pd

    top = syn.l1_max(phi0_deg)
    if l1 is None:
        if not (isinstance(step, (int, float)) and math.isfinite(step) and step > 0):
            raise syn.SynthesisError([syn.Problem(
                "step", Text("errors.linkage.synthesis_report.positive_number",
                             {"step": step}))])
        k = np.arange(1, int(math.floor(top / step * (1 - ROUNDOFF_RTOL))) + 1)
        l1 = np.append(np.round(k * step, 12), top)
    l1 = np.atleast_1d(np.asarray(l1, dtype=float))
    pts = syn.kolchin_line_points(l1, phi0_deg)
    rows = []
    for lam, p in zip(l1, pts):
        rows.append((lam, p[0, 0], p[0, 1]))
        if p[0, 0] != p[1, 0]:
            rows.append((lam, p[1, 0], p[1, 1]))
    df = pd.DataFrame(rows, columns=["l1", "l2", "l3"])
    # μmin = 0 on the boundary by construction (the paper: a dead position)
    df["mu_min_deg"] = 0.0
    return df


def mechanism_table(design, ground_m=None):
    """The chosen mechanism as a one-row DataFrame.

    Parameters
    ----------
    design : linkage.synthesis.Design
    ground_m : float, optional
        Ground length; adds the absolute lengths. [m]

    Returns
    -------
    pandas.DataFrame
        ``phi0_deg, l1, l2, l3, mu_min_deg, mu_min_at_deg, mu_at_phi0_deg, grashof,
        method`` and, with ``ground_m``, ``ground_m, crank_m, coupler_m, rocker_m``.
    """
    import pandas as pd

    row = design.as_dict()
    if ground_m is not None:
        crank, coupler, rocker, ground = design.lengths_m(ground_m)
        row.update(ground_m=ground, crank_m=crank, coupler_m=coupler, rocker_m=rocker)
    return pd.DataFrame([row])


#: Words of the terminal summary, the workbook and the spec header: (ru, en).  The
#: numbers are formatted once and put into the words of either language.
# the workbook's own words (titles, sheet names): sheet.synth.* of crankbase/locale/*/sheet.po;
# the family's name, the header rows and labels, the spec TOML's comment: synth.* of synth.po

#: The Grashof types (linkage.fourbar.GrashofType values) → catalogue keys (synth.po).
_GRASHOF = {"crank-rocker": "crank_rocker", "double-crank": "double_crank",
            "double-rocker": "double_rocker", "change-point": "change_point",
            "non-Grashof": "non_grashof"}

#: The design tasks (linkage.synthesis's Design.method) → catalogue keys (synth.po).
_METHOD = {"given": "given", "given l2, l3": "given_l2_l3", "given l1, l2 = l3": "given_l1"}
_MU_METHOD = re.compile(r"^given l2 and mu_min >= (\S+) deg"
                        r"(?:, l1 rounded down to a multiple of (\S+))?$")


def _texts(lang):
    """The :class:`crankbase.texts.Texts` of an offered ``lang`` (else a ValueError)."""
    from crankbase.texts import OFFERED, texts

    if lang not in OFFERED:
        raise ValueError(f"lang: got {lang!r}; one of {', '.join(OFFERED)}")
    return texts(lang)


def _rows(n: int, lang) -> str:
    """``n`` rows in words (plural forms of the language: 1 строка, 2 строки, 5 строк)."""
    return _texts(lang).n("common.rows", n)


def grashof_text(grashof, lang="en") -> str:
    """The Grashof type in words of ``lang``.

    Parameters
    ----------
    grashof : linkage.fourbar.GrashofType or str
    lang : {"en", "ru"}
    """
    t = _texts(lang)
    key = _GRASHOF.get(str(grashof))
    return t(f"synth.grashof.{key}") if key else str(grashof)


def method_text(method, lang="en") -> str:
    """The design task (:attr:`linkage.synthesis.Design.method`) in words of ``lang``;
    the numbers in it are copied as they are (the same text in both languages).  An
    unknown task is returned unchanged."""
    t = _texts(lang)
    if method in _METHOD:
        return t(f"synth.method.{_METHOD[method]}")
    m = _MU_METHOD.match(str(method))
    if m is None:
        return str(method)
    text = t("synth.method.mu_min", mu=m.group(1))
    if m.group(2) is not None:
        text += t("synth.method.step", step=m.group(2))
    return text


def summary_lines(region, table, design=None, ground_m=None, lang="en") -> list[str]:
    """The terminal summary of a synthesis, wholly in ``lang`` (ru: the paper's Russian
    terms; en: no Cyrillic letter, the family named KKM-φ0).  Every number is formatted
    once, the same in both languages; the words are the catalogue's (``synth.po``).

    Parameters
    ----------
    region : linkage.synthesis.ExistenceRegion
    table : pandas.DataFrame
        Table 1 (:func:`table1`); only its number of rows is printed.
    design : linkage.synthesis.Design, optional
        The chosen mechanism.
    ground_m : float, optional
        Adds the absolute lengths. [m]
    lang : {"en", "ru"}
    """
    t = _texts(lang)
    n = {"phi0": f"{region.phi0_deg:g}", "l1max": f"{region.l1_max:.4f}",
         "dx": f"{region.d[0]:.4f}", "dy": f"{region.d[1]:.4f}",
         "rows": _rows(len(table), lang)}
    n["kkm"] = t("synth.summary.kkm", phi0=n["phi0"])
    out = [t("synth.summary.region", **n)]
    if design is None:
        return out
    d = design
    out += [t("synth.summary.design", kkm=n["kkm"], phi0=f"{d.phi0_deg:g}",
              method=method_text(d.method, lang)),
            f"  λ1 = {d.l1:.4f}   λ2 = {d.l2:.4f}   λ3 = {d.l3:.4f}   (λ0 = 1)",
            t("synth.summary.mu", mu=f"{d.mu_min_deg:.4f}", dm=format_deg_min(d.mu_min_deg),
              at=f"{d.mu_min_at_deg:g}", mu0=f"{d.mu_at_phi0_deg:.9g}"),
            t("synth.summary.grashof", t=grashof_text(d.grashof, lang))]
    if ground_m is not None:
        crank, coupler, rocker, ground = d.lengths_m(ground_m)
        out.append(t("synth.summary.lengths", l1=f"{crank:.6g}", l2=f"{coupler:.6g}",
                     l3=f"{rocker:.6g}", l0=f"{ground:.6g}"))
    return out


def written_line(out, files, lang="en") -> str:
    """The last line of the terminal summary: the folder and the files written."""
    return _texts(lang)("synth.summary.written", out=out, files=", ".join(files))


def toml_header(design, lang="en") -> str:
    """The comment lines over the spec TOML that ``crankdyn synth --ground`` writes.

    The lengths are written in their shortest round-trip form (``repr``), as in the spec.
    """
    t = _texts(lang)
    d = design
    return t("synth.toml.header", kkm=t("synth.summary.kkm", phi0=f"{d.phi0_deg:g}"),
             phi0=f"{d.phi0_deg:g}", l1=repr(d.l1), l2=repr(d.l2), l3=repr(d.l3),
             mu=f"{d.mu_min_deg:.6g}")


# --------------------------------------------------------------------------- workbook
#: Table 1's columns (the CSV's), in order.
_T1_COLUMNS = ("l1", "l2", "l3", "mu_min_deg")


def header_language(lang) -> str:
    """The language of the workbook's first header row and first column: the course
    seed's Russian in a Russian or an English workbook (the seed's bilingual layout), the
    report's own in any other (Chinese); the second row and column are the CSV column
    names, in every language.  The catalogue says which (``synth.book.header_language``)."""
    return _texts(lang)("synth.book.header_language")


#: Values of the mechanism sheet that are words, and their translation.
_MECH_WORDS = {"grashof": grashof_text, "method": method_text}


def write_workbook(path, table, phi0_deg, mechanism=None, lang="en") -> None:
    """Write Table 1 (and the chosen mechanism) to an .xlsx workbook, atomically.

    Parameters
    ----------
    path : str or Path
        Target file.
    table : pandas.DataFrame
        From :func:`table1`.
    phi0_deg : float
        For the titles. [deg]
    mechanism : pandas.DataFrame, optional
        From :func:`mechanism_table`; written to a second sheet.
    lang : {"en", "ru"}
        Language of the titles, the sheet names (ru ``Таблица 1``, ``Механизм``; en
        ``table1``, ``mechanism``) and the values that are words (Grashof type, design
        task).  The header rows are the same in ru and en: the seed's Russian over the
        CSV column names; in zh Chinese over the CSV column names
        (:func:`header_language`; the words are ``synth.book.*`` in synth.po).

    Notes
    -----
    Table 1 sheet: row 1 the title, row 2 the headers in words, row 3 the column names of
    the CSV, data from row 4.  Mechanism sheet: row 1 the title, row 2 the headers, then
    one quantity per row: its label in words, its CSV column name, its value.
    """
    from openpyxl import Workbook
    from openpyxl.styles import Alignment, Font

    from crankbase.output import ensure_finite

    kkm = _texts(lang)("synth.summary.kkm", phi0=f"{phi0_deg:g}")
    ensure_finite(table, "Table 1")
    if mechanism is not None:
        ensure_finite(mechanism, "mechanism")
    wb = Workbook()
    ws = wb.active
    from crankbase.texts import texts

    tx = texts(lang)
    ws.title = tx("sheet.synth.t1_sheet")
    ws.append([tx("sheet.synth.t1_title", kkm=kkm)])
    ws["A1"].font = Font(bold=True)
    ws["A1"].alignment = Alignment(wrap_text=True, vertical="top")
    ws.merge_cells("A1:D1")                    # the title wraps over the four columns
    ws.row_dimensions[1].height = 32
    th = texts(header_language(lang))
    ws.append([th(f"synth.book.t1.{c}") for c in _T1_COLUMNS])
    ws.append(list(_T1_COLUMNS))
    for cell in (*ws[2], *ws[3]):
        cell.font = Font(bold=True)
        cell.alignment = Alignment(horizontal="center")
    for row in table[["l1", "l2", "l3", "mu_min_deg"]].itertuples(index=False):
        ws.append([float(v) for v in row])
    for r in ws.iter_rows(min_row=4, max_col=3):
        for cell in r:
            cell.number_format = "0.0000"
    for col, width in zip("ABCD", (14, 14, 14, 12)):
        ws.column_dimensions[col].width = width
    sheets = [(ws, "1:3")]
    if mechanism is not None:
        wm = wb.create_sheet(tx("sheet.synth.mech_sheet"))
        wm.append([tx("sheet.synth.mech_title", kkm=kkm)])
        wm["A1"].font = Font(bold=True)
        wm.append([th("synth.book.quantity"), th("synth.book.csv_name"),
                   tx("sheet.synth.value")])
        for cell in wm[2]:
            cell.font = Font(bold=True)
        width_c = 44
        for key, value in mechanism.iloc[0].items():
            label = th(f"synth.book.mech.{key}") if th.has(f"synth.book.mech.{key}") else key
            v = value.item() if hasattr(value, "item") else value
            if key in _MECH_WORDS:
                v = _MECH_WORDS[key](v, lang)
            wm.append([label, key, v])
            if isinstance(v, str) and len(v) > width_c:
                c = wm.cell(wm.max_row, 3)
                c.alignment = Alignment(wrap_text=True, vertical="top")
                lines = -(-len(v) * 105 // (100 * width_c))          # ceil(len·1.05/width)
                wm.row_dimensions[wm.max_row].height = 15 * lines
                for cell in wm[wm.max_row][:2]:
                    cell.alignment = Alignment(vertical="top")
        wm.column_dimensions["A"].width = 36
        wm.column_dimensions["B"].width = 18
        wm.column_dimensions["C"].width = width_c
        sheets.append((wm, "1:2"))
    # print: A4 portrait, one page wide, header rows repeated on every page
    for sheet, titles in sheets:
        sheet.page_setup.paperSize = sheet.PAPERSIZE_A4
        sheet.page_setup.orientation = "portrait"
        sheet.sheet_properties.pageSetUpPr.fitToPage = True
        sheet.page_setup.fitToWidth = 1
        sheet.page_setup.fitToHeight = 0
        sheet.print_title_rows = titles
    from crankbase.workbook import finish, save

    finish(wb)
    save(wb, path)


# --------------------------------------------------------------------------- TOML
_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k) -> str:
    k = str(k)
    return k if _BARE.match(k) else _string(k)


def _string(s: str) -> str:
    out = ['"']
    for ch in s:
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _value(v, where) -> str:
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        v = float(v)
        if not math.isfinite(v):
            raise ValueError(f"{where}: {v!r} cannot be written to TOML (not finite)")
        r = repr(v)
        return r if any(ch in r for ch in ".en") else r + ".0"
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, (list, tuple, np.ndarray)):
        items = [v_ for v_ in v]
        if any(isinstance(x, dict) for x in items):
            raise ValueError(f"{where}: an array of tables is only allowed at table level")
        return "[" + ", ".join(_value(x, f"{where}[{i}]") for i, x in enumerate(items)) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x, f'{where}.{k}')}"
                                for k, x in v.items()) + " }"
    raise ValueError(f"{where}: cannot write a {type(v).__name__} to TOML")


def _is_table_array(v) -> bool:
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _emit(table, path, lines):
    scalars = [(k, v) for k, v in table.items()
               if not isinstance(v, dict) and not _is_table_array(v)]
    for k, v in scalars:
        lines.append(f"{_key(k)} = {_value(v, '.'.join(path + [str(k)]))}")
    for k, v in table.items():
        if isinstance(v, dict):
            sub = path + [_key(k)]
            lines.append("")
            lines.append("[" + ".".join(sub) + "]")
            _emit(v, sub, lines)
    for k, v in table.items():
        if _is_table_array(v):
            sub = path + [_key(k)]
            for item in v:
                lines.append("")
                lines.append("[[" + ".".join(sub) + "]]")
                _emit(item, sub, lines)


def dumps_toml(data: dict, header: str = "") -> str:
    """A small TOML writer for spec dicts: tables, arrays of tables, strings, booleans,
    integers, finite floats (shortest round-trip form), arrays and inline tables.

    Parameters
    ----------
    data : dict
        Nested dict (as :func:`linkage.synthesis.to_spec` returns).
    header : str
        Comment lines put at the top (each prefixed with ``# ``).
    """
    lines = [f"# {h}" if h else "#" for h in header.splitlines()] if header else []
    body: list[str] = []
    _emit(data, [], body)
    while body and body[0] == "":
        body.pop(0)
    if lines and body:
        lines.append("")
    return "\n".join(lines + body) + "\n"


def write_toml(data: dict, path, header: str = "") -> None:
    """Write ``data`` as TOML (:func:`dumps_toml`), atomically, UTF-8."""
    from crankbase.output import atomic_path

    text = dumps_toml(data, header)
    with atomic_path(path) as tmp:
        with open(tmp, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
