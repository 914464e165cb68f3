"""Reports of a linkage analysis: CSV tables and the Excel workbook, in Russian or English.

Reports only consume an :class:`~linkage.analysis.AnalysisResult`; they compute no
physics.  The workbook has the sheets inputs (spec values and the cycle geometry),
positions, velocities, accelerations, loads (weights, inertia forces and moments,
resistance), forces (reactions, driving moment) -- one row per position, the CSV columns
regrouped -- and extremes (the two extreme positions); the sheet titles, labels, units
and symbols are in the report's language (``lang="ru"``: «Исходные данные»,
«Положения» …).  Every table sheet has three header rows: the textbook symbol, the unit,
and the CSV column name -- the third row is the same in both languages, so
``crankdyn check`` reads a Russian and an English workbook alike.  Numbers are stored at
full precision (number formats only change how they are shown).

Symbols (:func:`column_label`, the one place they are made)
-----------------------------------------------------------
Both languages share the Latin/Greek symbols of the kinematics (φ, θ3, ω3, ε3, VB, VBA,
aB, aBAⁿ, aBAᵗ, xE …) and of the reactions (R12, R23n, R23t, R14n, N14, M14, Gi).
They differ only where the Russian textbook (Artobolevsky; seed 000) uses Cyrillic
indices; the English set is the one the project's other English outputs use (the plots
of :mod:`linkage.plots` and :mod:`dynamics.plots`: M_b; the plan labels of
:mod:`plans.model`: Fb, Mr, Fr, Fi₃, Mi₃).  The symbols that differ are the catalogue's
(``linkage.symbol.<column>`` and the inertia index ``linkage.symbol.inertia_index`` of
``linkage.po``), so a language chooses its own by filling those keys:

=====================  ============  ==========  =================================
CSV column             ru            en          quantity
=====================  ============  ==========  =================================
``position``           №             No.         position number
``M_drive_Nm``         Mур           Mb          balancing (driving) moment on the crank
``M_res_Nm``           Mпс           Mr          useful-resistance moment on the rocker
``F_res_N``            Fпс           Fr          useful-resistance force on the slider
``Fu3_N``, ``Fu3_x_N`` Fи3, Fи3x     Fi3, Fi3x   d'Alembert inertia force of link 3
``Mu3_Nm``             Mи3           Mi3         inertia moment of link 3
=====================  ============  ==========  =================================

Units: SI in both, written м, м/с, м/с², рад/с, рад/с², Н, Н·м, кг, кг·м² in Russian.
"""
from __future__ import annotations

import copy

import math
import re

import numpy as np

from crankbase.errors import Text
from crankbase.output import paused_gc
from crankbase.texts import OFFERED, REFERENCE
from crankbase.tolerances import SAME_ANGLE_DEG

from .course import course_of

__all__ = ["column_label", "unit_text", "COLUMN_UNITS", "unit_suffix", "kind_text", "warning_text",
           "write_csvs", "write_workbook",
           "sheet_columns", "force_sheet_columns", "summary_lines", "text", "LANGS"]

#: Report languages.
LANGS = OFFERED              # every offered language (crankbase.texts.languages)

#: The unit suffixes of the CSV column names (the linkage's, the chain's, the dynamics')
#: → the unit (international spelling, a key of :data:`crankbase.texts.UNITS`, spelled in
#: the report's language by :meth:`crankbase.texts.Texts.unit`): ``v_E_m_s`` is in m/s.
#: The one column-suffix table; a name ends with one of them after ``_``, the longest
#: that fits (``omega_rad_s`` is in rad/s, not in s).
COLUMN_UNITS = {"m": "m", "m_s": "m/s", "m_s2": "m/s²", "deg": "°", "rad": "rad",
                "rad_s": "rad/s", "rad_s2": "rad/s²", "N": "N", "Nm": "N·m",
                "kgm2": "kg·m²", "J": "J", "s": "s"}


def unit_suffix(col: str):
    """``(name, suffix)`` of a CSV column name ending in ``_<suffix>`` of
    :data:`COLUMN_UNITS`, the longest that fits (``omega_rad_s`` → ``("omega", "rad_s")``,
    not ``s``), the name before it not empty; None when no suffix of the table ends it.
    The one rule of the linkage's, the chain's and the dynamics' column heads."""
    for suffix in sorted(COLUMN_UNITS, key=len, reverse=True):
        if col.endswith("_" + suffix) and len(col) > len(suffix) + 1:
            return col[:-len(suffix) - 1], suffix
    return None


_SIMPLE = {
    "position": (None, ""), "phi_deg": ("φ", "°"), "theta3_deg": ("θ3", "°"),
    "theta4_deg": ("θ4", "°"), "omega3_rad_s": ("ω3", "rad/s"), "omega4_rad_s": ("ω4", "rad/s"),
    "eps3_rad_s2": ("ε3", "rad/s²"), "eps4_rad_s2": ("ε4", "rad/s²"), "s4_m": ("s4", "m"),
    "v4_m_s": ("v4", "m/s"), "a4_m_s2": ("a4", "m/s²"), "mu_deg": ("μ", "°"),
    "M_drive_Nm": (None, "N·m"), "M_res_Nm": (None, "N·m"), "F_res_N": (None, "N"),
    "M14_Nm": ("M14", "N·m"), "N14_N": ("N14", "N"), "label": ("", ""),
    "R23_n_N": ("R23n", "N"), "R23_t_N": ("R23t", "N"), "R14_n_N": ("R14n", "N"),
    "R14_t_N": ("R14t", "N"),
}
#: A symbol ``None`` of :data:`_SIMPLE` is the catalogue's ``linkage.symbol.<column>``
#: (the textbooks differ: module doc); the index letter of the inertia force and moment
#: (Fи3, Mи3 in the Russian textbook's symbols, Fi3, Mi3 in the Latin ones) is
#: ``linkage.symbol.inertia_index``.


def unit_text(unit: str, lang: str = "en") -> str:
    """An SI unit as written in the report's language (``"N·m"`` → ``"Н·м"`` in ru)."""
    from crankbase.texts import texts

    _check_lang(lang)
    return texts(lang).unit(unit)


def column_label(col: str, lang: str = "en"):
    """Textbook symbol and unit of a table column in the report's language, e.g.
    ``"B_vx_m_s"`` → ("VBx", "m/s") in en, ("VBx", "м/с") in ru; ``"M_drive_Nm"`` →
    ("Mb", "N·m") in en, ("Mур", "Н·м") in ru (the symbol table: module docstring).
    An unknown column is its own symbol, without a unit."""
    from crankbase.texts import texts

    _check_lang(lang)
    sym, unit = _column_symbol(col, texts(lang))
    return sym, unit_text(unit, lang)


def _column_symbol(col, t):
    """``(symbol, unit)`` of a column: the symbol in the language of ``t`` (its
    catalogue's ``linkage.symbol.*`` where the textbooks differ), the unit a key of
    :data:`crankbase.texts.UNITS`."""
    if col in _SIMPLE:
        sym, unit = _SIMPLE[col]
        return (t(f"linkage.symbol.{col}") if sym is None else sym), unit
    m = re.fullmatch(r"R(\d\d)_([xy])_N", col)
    if m:
        return f"R{m.group(1)}{m.group(2)}", "N"
    m = re.fullmatch(r"(R\d\d|G\d)_N", col)
    if m:
        return m.group(1), "N"
    m = re.fullmatch(r"Fu(\d)(_[xy])?_N", col)
    if m:
        return f"F{t('linkage.symbol.inertia_index')}{m.group(1)}{(m.group(2) or '')[1:]}", "N"
    m = re.fullmatch(r"Mu(\d)_Nm", col)
    if m:
        return f"M{t('linkage.symbol.inertia_index')}{m.group(1)}", "N·m"
    m = re.fullmatch(r"v_(\w\w)_m_s", col)
    if m:
        return f"V{m.group(1)}", "m/s"
    m = re.fullmatch(r"a_(\w\w)(_[nt])?_m_s2", col)
    if m:
        sup = {"_n": "ⁿ", "_t": "ᵗ"}.get(m.group(2), "")
        return f"a{m.group(1)}{sup}", "m/s²"
    m = re.fullmatch(r"(.+?)_(v|a)_(m_s|m_s2)", col)
    if m:
        p, q, unit = m.groups()
        return f"{'V' if q == 'v' else 'a'}{p}", COLUMN_UNITS[unit]
    m = re.fullmatch(r"(.+?)_(x|y|vx|vy|ax|ay)_(m|m_s|m_s2)", col)
    if m:
        p, q, unit = m.groups()
        sym = {"x": f"x{p}", "y": f"y{p}", "vx": f"V{p}x", "vy": f"V{p}y",
               "ax": f"a{p}x", "ay": f"a{p}y"}[q]
        return sym, COLUMN_UNITS[unit]
    return col, ""


def _check_lang(lang):
    if lang not in LANGS:
        raise ValueError(f"lang: got {lang!r}; one of {', '.join(LANGS)}")


def sheet_columns(kinematics_cols):
    """Split the kinematics columns into the positions, velocities and accelerations sheets:
    on the last two, the link rates first, then the course table's magnitudes (speeds of
    the points, relative motion of B), then the x/y components."""
    head = ["position", "phi_deg"]
    pos, vel, acc = list(head), [], []
    for c in kinematics_cols:
        if c in head:
            continue
        if c.endswith("_m_s") or c in ("omega3_rad_s", "omega4_rad_s"):
            vel.append(c)
        elif c.endswith("_m_s2") or c in ("eps3_rad_s2", "eps4_rad_s2"):
            acc.append(c)
        else:
            pos.append(c)

    def order(c):
        return 2 if re.search(r"_(vx|vy|ax|ay)_m_s2?$", c) else \
            1 if re.search(r"_(v_m_s|a_m_s2)$", c) or c.startswith(("v_B", "a_B")) else 0
    return pos, head + sorted(vel, key=order), head + sorted(acc, key=order)


def force_sheet_columns(force_cols):
    """Split the force columns into the loads sheet (weights, inertia forces and moments,
    useful resistance: the inputs of the kinetostatics) and the forces sheet (reactions
    and the driving moment)."""
    head = ["position", "phi_deg"]
    loads = [c for c in force_cols
             if re.fullmatch(r"(G\d|Fu\d(_[xy])?)_N|Mu\d_Nm|M_res_Nm|F_res_N", c)]
    rest = [c for c in force_cols if c not in head and c not in loads]
    return head + loads, head + rest


def write_csvs(result, folder):
    """Write ``kinematics.csv`` and ``forces.csv`` (comma, '.', header, full precision)."""
    from crankbase.output import write_csv

    write_csv(result.kinematics, folder / "kinematics.csv")
    write_csv(result.forces, folder / "forces.csv")


#: The workbook's words (crankbase.workbook.words): sheet names, headers, conventions;
#: in the catalogue crankbase/locale/<lang>/sheet.po under ``sheet.linkage.*`` (the
#: terminal's words and the cycle geometry's: ``linkage.*`` of linkage.po).
_SHEET_SHAPE = {'conv': ('tuple', 7),
                'conventions': 'str',
                'cycle_head': ('tuple', 3),
                'ext_head': ('tuple', 3),
                'ext_labels': ('dict', ('working start', 'working end')),
                'extreme': 'str',
                'sheets': ('dict',
                           ('inputs', 'positions', 'velocities', 'accelerations', 'loads',
                            'forces', 'extremes')),
                'spec_head': ('tuple', 4),
                'title': 'str',
                'warning': 'str'}


def _sheet_words(lang):
    """The workbook's words in ``lang`` (:data:`_SHEET_SHAPE`)."""
    from crankbase.workbook import words

    _check_lang(lang)
    return words(lang, "sheet.linkage", _SHEET_SHAPE)


class _Sheet(dict):
    def __missing__(self, lang):
        self[lang] = _sheet_words(lang)
        return self[lang]


_SHEET = _Sheet()


def text(lang: str) -> dict:
    """The workbook's texts in ``lang`` ("ru" or "en"): sheet titles, labels, conventions,
    from the catalogue (``sheet.linkage.*``)."""
    return _SHEET[lang]


def summary_lines(result, lang: str = "ru"):
    """The cycle geometry as (label, value, unit) rows for the inputs sheet and the
    terminal, in the report's language (the Grashof type in words of that language;
    words from the catalogue ``linkage.po``)."""
    from crankbase.texts import texts

    _check_lang(lang)
    t = texts(lang)

    def c(key):
        return t(f"linkage.cycle.{key}")

    def u(unit):
        return unit_text(unit, lang)

    s = result.summary
    course = course_of(s)
    rows = [(c(course.type_key), grashof_text(s.grashof, lang), "")]
    if s.has_extremes:
        rows += [(c("phi_ws"), s.phi_working_start_deg, "°"),
                 (c("phi_we"), s.phi_working_end_deg, "°"),
                 (c("phi_w"), s.working_crank_angle_deg, "°"),
                 (c("phi_i"), s.idle_crank_angle_deg, "°"),
                 (c("K"), s.time_ratio, "")]
        unit = u("°") if course.angular else u("m")       # the output's swing or stroke
        rows += [(c(key), getattr(s, name), unit)
                 for key, name in zip(course.summary_keys, course.summary_fields)]
    rows += [(c("mu"), s.mu_min_deg, "°"),
             (c("mu_phi"), s.mu_min_phi_deg, "°")]
    if s.singular_phi_deg:
        rows.append((c("singular"), ", ".join(f"{a:.6g}" for a in s.singular_phi_deg), "°"))
    return rows


#: The Grashof types and rotatability (linkage.fourbar) → their catalogue keys.
_GRASHOF_KEYS = {"crank-rocker": "crank_rocker", "double-crank": "double_crank",
                 "double-rocker": "double_rocker", "change-point": "change_point",
                 "non-Grashof": "non_grashof", "rotatable": "rotatable",
                 "non-rotatable": "non_rotatable"}


def grashof_text(grashof, lang: str = "ru") -> str:
    """The Grashof type (or a crank-slider's rotatability) in words of ``lang``; an
    unknown one as it is."""
    from crankbase.texts import texts

    key = _GRASHOF_KEYS.get(str(grashof))
    return texts(lang)(f"linkage.grashof.{key}") if key else str(grashof)


#: The analysis' warnings (linkage.analysis, in English) → catalogue keys.
_WARNINGS = (
    (re.compile(r"change-point mechanism: singular position\(s\) at crank angle (.+?) "
                r"\(links collinear; the output's motion is indeterminate there\)"),
     "linkage.warning.change_point"),
    (re.compile(r"requested crank angles include a singular position; its velocities, "
                r"accelerations and forces are not finite"),
     "linkage.warning.singular_requested"),
)


def warning_text(message, lang: str = "ru") -> str:
    """An analysis warning (:attr:`AnalysisResult.warnings`) in the report's language;
    a message without a translation is returned as it is."""
    from crankbase.texts import texts

    message = str(message)
    if lang == REFERENCE:                 # the analysis writes its warnings in English
        return message
    _check_lang(lang)
    for pattern, key in _WARNINGS:
        m = pattern.fullmatch(message)
        if m:
            return texts(lang)(key, angles=m.group(1)) if m.groups() else texts(lang)(key)
    return message


def kind_text(kind: str, lang: str = "ru") -> str:
    """The mechanism's kind in words (``"crank-rocker"`` → «кривошипно-коромысловый
    механизм» in ru)."""
    from crankbase.texts import texts

    _check_lang(lang)
    key = {"crank-rocker": "crank_rocker", "crank-slider": "crank_slider",
           "chain": "chain"}.get(kind)
    return texts(lang)(f"linkage.kind.{key}") if key else kind


def _spec_rows(raw, prefix=""):
    """Flatten the spec as given into (key path, value) rows."""
    rows = []
    for key, value in raw.items():
        path = f"{prefix}.{key}" if prefix else key
        if isinstance(value, dict):
            rows += _spec_rows(value, path)
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for i, item in enumerate(value):
                rows += _spec_rows(item, f"{path}[{i}]")
        else:
            if isinstance(value, (list, tuple)):
                value = ", ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in value)
            rows.append((path, value))
    return rows


#: Spec keys whose meaning the inputs sheet gives (``linkage.key.<key>`` in linkage.po).
_KEY_MEANINGS = frozenset((
    "kind", "name", "crank", "coupler", "rocker", "ground", "ground_angle_deg", "offset",
    "assembly", "omega_rad_s", "epsilon_rad_s2", "gravity_m_s2", "mass_kg", "inertia_kg_m2",
    "cg", "points", "link", "at", "force_N", "moment_Nm", "resistance_Nm", "resistance_N",
    "stroke", "start_deg", "start_m", "span_deg", "span_m", "from_fraction", "to_fraction",
    "positions", "crank_angles_deg", "working_stroke"))
#: Links named inside a meaning ("масса кривошипа m2"): ``linkage.link_of.<link>``.
_LINKS_OF = frozenset(("crank", "coupler", "rocker", "slider"))
#: The spec's word values explained beside them (not in English, where the value is the
#: word): ``linkage.value.<value>`` with ``-`` as ``_``.
_VALUES = frozenset(("crank-rocker", "crank-slider", "crank", "coupler", "rocker", "slider",
                     "working", "idle", "both", "ccw", "cw", "away", "toward"))


def _key_meaning(key, value, lang):
    """The meaning of a spec key in the report's language ('' when not known), from the
    catalogue (``linkage.key.*``, ``linkage.link_of.*``, ``linkage.value.*``)."""
    from crankbase.texts import texts

    t = texts(lang)
    parts = [re.sub(r"\[\d+\]$", "", p) for p in key.split(".")]
    if parts[0] == "drawing":
        return t("linkage.key.drawing")
    last = parts[-1]
    link, point = None, None
    if parts[0] == "links" and len(parts) >= 3:
        link = parts[1]
        if parts[2] == "points":
            last, point = "points", parts[-1]
    if last not in _KEY_MEANINGS:
        return ""
    from .spec import LINK_NUMBER

    of = t(f"linkage.link_of.{link}") if link in _LINKS_OF else (link or "")
    out = t(f"linkage.key.{last}", link=of, point=point or "", n=LINK_NUMBER.get(link, ""))
    out = re.sub(r"\s+", " ", out).strip()
    if lang != REFERENCE and isinstance(value, str) and value in _VALUES:
        out = t("linkage.value.explained", meaning=out,
                value=t(f"linkage.value.{value.replace('-', '_')}"))
    return out


@paused_gc()            # thousands of cells: no collection scans them
def write_workbook(result, path, lang: str = "ru"):
    """Write the Excel workbook of a linkage analysis (atomically) in ``lang``.

    Parameters
    ----------
    result : linkage.analysis.AnalysisResult
    path : str or Path
        The ``.xlsx`` to write.
    lang : {"ru", "en"}
        Language of the sheet titles, labels, units and symbols (module docstring); the
        numbers and the CSV-name header row are the same in both.

    Raises :class:`crankbase.output.OutputError` if a table holds a non-finite number outside
    the rows of singular positions of a change-point mechanism (those are left empty
    and flagged).
    """
    from openpyxl import Workbook
    from openpyxl.styles import Alignment, Border, Font, PatternFill, Side
    from openpyxl.utils import get_column_letter

    t = _SHEET[lang]
    wb = Workbook()
    bold = Font(bold=True)
    grey = Font(italic=True, size=8, color="808080")
    head_fill = PatternFill("solid", fgColor="DDEBF7")
    thin = Side(style="thin", color="999999")
    box = Border(left=thin, right=thin, top=thin, bottom=thin)
    center = Alignment(horizontal="center", vertical="center", wrap_text=True)
    wrap = Alignment(wrap_text=True, vertical="top")
    from crankbase.workbook import CellStyles

    styles = CellStyles(wb)         # each style above looked up once

    # -- inputs (portrait A4: A spec key / label, B value, C unit, D meaning)
    ws = wb.active
    ws.title = t["sheets"]["inputs"]
    widths = dict(A=34, B=20, C=9, D=39)
    for letter, w in widths.items():
        ws.column_dimensions[letter].width = w

    def fit(row, col_widths):
        """Row height for the wrapped texts of ``row`` (12.75 pt a line)."""
        lines = 1
        for c, w in zip(ws[row], col_widths):
            if isinstance(c.value, str):
                lines = max(lines, _wrapped_lines(c.value, w))
        if lines > 1:
            ws.row_dimensions[row].height = _LINE_PT * lines + 2

    def merged(row, lines_text):
        """One text across A:D, wrapped."""
        ws.cell(row, 1, lines_text).alignment = wrap
        ws.merge_cells(start_row=row, start_column=1, end_row=row, end_column=4)
        fit(row, [sum(widths.values())])

    spec = result.spec
    ws["A1"] = t["title"].format(name=spec.name, kind=kind_text(spec.kind, lang))
    ws["A1"].font = Font(bold=True, size=12)
    ws.merge_cells("A1:D1")
    ws["A1"].alignment = wrap
    fit(1, [sum(widths.values()) / 1.3])
    ws.append([])
    ws.append(list(t["spec_head"]))
    for c in ws[3]:
        styles(c, font=bold, fill=head_fill, alignment=wrap)
    from .schema import CHAIN_SCHEMA, SCHEMA

    schema = CHAIN_SCHEMA if spec.kind == "chain" else SCHEMA
    for key, value in _spec_rows(dict(spec.raw)):
        ws.append([key, value, unit_text(_spec_unit(key, schema), lang),
                   _key_meaning(key, value, lang)])
        for c in ws[ws.max_row]:
            styles(c, alignment=wrap)
        fit(ws.max_row, widths.values())
    ws.append([])
    ws.append(list(t["cycle_head"]))
    for c in ws[ws.max_row][:3]:
        styles(c, font=bold, fill=head_fill)
    for label, value, unit in summary_lines(result, lang):
        ws.append([label, value, unit])
        ws.cell(ws.max_row, 1).alignment = wrap
        ws.cell(ws.max_row, 2).alignment = Alignment(vertical="top", horizontal=(
            "right" if isinstance(value, float) else "left"), wrap_text=True)
        ws.cell(ws.max_row, 3).alignment = wrap
        if isinstance(value, float):
            ws.cell(ws.max_row, 2).number_format = "0.0000"
        fit(ws.max_row, widths.values())
    if result.warnings:
        ws.append([])
        for w in result.warnings:
            ws.append([t["warning"], warning_text(w, lang)])
            ws.cell(ws.max_row, 1).font = Font(bold=True, color="C00000")
            ws.cell(ws.max_row, 1).alignment = wrap
            ws.cell(ws.max_row, 2).alignment = wrap
            ws.merge_cells(start_row=ws.max_row, start_column=2, end_row=ws.max_row,
                           end_column=4)
            fit(ws.max_row, [widths["A"], widths["B"] + widths["C"] + widths["D"]])
    ws.append([])
    ws.append([t["conventions"]])
    ws.cell(ws.max_row, 1).font = bold
    for line in t["conv"]:
        ws.append([line])
        merged(ws.max_row, line)

    pos_cols, vel_cols, acc_cols = sheet_columns(list(result.kinematics.columns))
    load_cols, force_cols = force_sheet_columns(list(result.forces.columns))
    tables = [("positions", result.kinematics, pos_cols),
              ("velocities", result.kinematics, vel_cols),
              ("accelerations", result.kinematics, acc_cols),
              ("loads", result.forces, load_cols),
              ("forces", result.forces, force_cols)]
    if result.extremes is not None:
        tables.append(("extremes", result.extremes, list(result.extremes.columns)))
    for key, df, cols in tables:
        ws = wb.create_sheet(t["sheets"][key])
        if key == "extremes":
            _extremes_sheet(ws, df, cols, lang, bold, grey, head_fill, box, center, styles)
            continue
        for j, col in enumerate(cols, start=1):
            sym, unit = column_label(col, lang)
            for i, txt in enumerate((sym, unit, col), start=1):
                cell = styles(ws.cell(i, j, txt), alignment=center, border=box,
                              font=grey if i == 3 else bold)
                if i < 3:
                    styles(cell, fill=head_fill)
            ws.column_dimensions[get_column_letter(j)].width = max(11, len(col) + 2)
        for j, col in enumerate(cols, start=1):
            values = _cell_values(df[col])
            fmt = _number_format(col, values)
            proto = None
            for i, value in enumerate(values, start=4):
                cell = ws.cell(i, j, value)
                if proto is None:      # style one cell, share its style array with the rest
                    cell.border = box  # (setting styles cell by cell costs ~10 ms a row)
                    cell.number_format = fmt
                    proto = cell._style
                else:
                    cell._style = copy.copy(proto)
        ws.freeze_panes = "C4" if "phi_deg" in cols else "B4"
        ws.print_title_rows = "1:3"
        if "phi_deg" in cols:
            ws.print_title_cols = "A:B"      # position and φ repeated on every page
        width = sum(ws.column_dimensions[get_column_letter(j)].width
                    for j in range(1, len(cols) + 1))
        _page_setup(ws, landscape=True, pages_wide=math.ceil(width / _WIDTH_PER_PAGE))
    _page_setup(wb.worksheets[0], landscape=False)
    _check_finite_tables(result)
    from crankbase.workbook import finish, save

    finish(wb, fixed={wb.worksheets[0].title: widths})
    save(wb, path)


def __getattr__(name):
    """``CONVENTIONS``: the conventions printed on the English inputs sheet (the words of
    every language: ``sheet.linkage.conv.*`` of the catalogue)."""
    if name == "CONVENTIONS":          # read from the catalogue when first asked
        return _SHEET["en"]["conv"]
    raise AttributeError(name)


#: Width of a Cyrillic and of another character of wrapped text in Excel column-width
#: units (one '0'; Cyrillic letters are wider than the average Latin text, measured on
#: LibreOffice's rendering with a margin for word breaks), and the height of a line [pt],
#: for the row heights of wrapped labels.
_CHAR_WIDTH = {"cyrillic": 1.0, "other": 0.88}
_LINE_PT = 12.75


def _text_width(s: str) -> float:
    """Estimated printed width of a text in Excel column-width units."""
    cyr = sum(1 for ch in s if "\u0400" <= ch <= "\u04ff")
    return cyr * _CHAR_WIDTH["cyrillic"] + (len(s) - cyr) * _CHAR_WIDTH["other"]


def _wrapped_lines(s: str, width: float) -> int:
    """Lines a wrapped text takes in a column ``width`` units wide: words are put on a
    line while they fit (a word longer than a line is broken), as a spreadsheet does."""
    lines = 0
    for para in s.split("\n"):
        lines += 1
        used = 0.0
        for word in para.split(" "):
            w = _text_width(word)
            if used and used + _CHAR_WIDTH["other"] + w > width:
                lines += 1
                used = 0.0
            elif used:
                used += _CHAR_WIDTH["other"]
            if w > width:                      # broken inside the word
                lines += math.ceil(w / width) - 1
                w = w % width
            used += w
    return lines

#: Width of a value column of the extremes sheet ("крайнее положение 1" on one line).
_EXTREME_WIDTH = 22

#: Column width (Excel units) printed on one landscape A4 page: at most ~70 % scale,
#: so the numbers stay readable (a wider sheet prints on more pages, titles repeated).
_WIDTH_PER_PAGE = 190


def _extremes_sheet(ws, df, cols, lang, bold, grey, head_fill, box, center, styles):
    """The extreme positions, one quantity per row (quantity, unit, CSV key, one value
    column per extreme position): two positions of ~100 quantities print as a readable
    portrait list instead of a strip 100 columns wide."""
    from openpyxl.styles import Alignment

    t = _SHEET[lang]
    heads = list(t["ext_head"]) + [t["extreme"].format(i=i + 1) for i in range(len(df))]
    for j, txt in enumerate(heads, start=1):
        styles(ws.cell(1, j, txt), font=bold, fill=head_fill, border=box, alignment=center)
    ws.row_dimensions[1].height = 30
    right = Alignment(horizontal="right", wrap_text=True)
    middle = Alignment(horizontal="center", vertical="center", wrap_text=True)
    for i, col in enumerate(cols, start=2):
        sym, unit = column_label(col, lang)
        values = _cell_values(df[col])
        if col == "label":
            values = [t["ext_labels"].get(v, v) for v in values]
        fmt = _number_format(col, values)
        for j, v in enumerate([sym, unit, col] + values, start=1):
            c = styles(ws.cell(i, j, v), border=box)
            if j == 3:
                styles(c, font=grey)
            if j > 3:
                styles(c, number_format=fmt, alignment=right)
        if col == "label":                   # the stroke's name: centred, wrapped
            if max(_text_width(str(v)) for v in values) > _EXTREME_WIDTH:
                ws.row_dimensions[i].height = 2 * _LINE_PT + 4
            for j in range(4, 4 + len(values)):
                styles(ws.cell(i, j), alignment=middle)
    ws.column_dimensions["A"].width = 14
    ws.column_dimensions["B"].width = 9
    ws.column_dimensions["C"].width = 22
    for j in range(len(df)):
        ws.column_dimensions[chr(ord("D") + j)].width = _EXTREME_WIDTH
    ws.freeze_panes = "D2"
    ws.print_title_rows = "1:1"
    _page_setup(ws, landscape=False)


def _spec_unit(key, schema):
    """The unit of the spec key at path ``key`` as the inputs sheet shows it, the one
    spec schema's (:meth:`crankbase.schema.Schema.key_of`, :attr:`~crankbase.schema.Key.unit`;
    '' for a word, a count or a key outside the schema such as ``[drawing]``'s)."""
    k = schema.key_of(key)
    return k.unit if k is not None else ""


def _page_setup(ws, landscape, pages_wide=1):
    """Print on A4, ``pages_wide`` pages wide, as many tall as needed."""
    ws.page_setup.orientation = "landscape" if landscape else "portrait"
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.fitToWidth = max(1, int(pages_wide))
    ws.page_setup.fitToHeight = 0
    ws.sheet_properties.pageSetUpPr.fitToPage = True


def _number_format(col, values):
    """One display format per column (the stored value keeps full precision)."""
    if col == "position":
        return "0"
    if col.endswith("_deg"):
        return "0.00"
    big = max((abs(v) for v in values if isinstance(v, float)), default=0.0)
    return "0.00" if big >= 100 else "0.000" if big >= 1 else "0.0000"


def _cell_values(series):
    """Python values for openpyxl: floats, ints, strings; missing or non-finite → None."""
    if series.dtype.kind == "f":
        return [float(v) if math.isfinite(v) else None for v in series.to_numpy()]
    return [None if v is None or v is getattr(series.dtype, "na_value", None)
            or (isinstance(v, float) and not math.isfinite(v))
            else (v.item() if hasattr(v, "item") else v)
            for v in series.astype(object).where(series.notna(), None)]


def _check_finite_tables(result):
    """Refuse to write non-finite values except on flagged singular positions."""
    from crankbase.output import OutputError

    sing = result.summary.singular_phi_deg
    for name, df in (("kinematics", result.kinematics), ("forces", result.forces)):
        num = df.drop(columns=["position"]).to_numpy(dtype=float)
        bad_rows = np.flatnonzero(~np.isfinite(num).all(axis=1))
        for r in bad_rows:
            phi = float(df["phi_deg"].iat[r])
            if not any(abs((phi - a + 180.0) % 360.0 - 180.0) < SAME_ANGLE_DEG for a in sing):
                raise OutputError(Text("errors.linkage.report.row_not_finite",
                                       {"name": name, "r": r + 1, "phi": phi}))
