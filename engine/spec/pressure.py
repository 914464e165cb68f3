"""The indicator diagram given as a table: inline in ``[pressure]`` or a CSV file.

:func:`read_pressure_csv` reads a CSV (the separator from the header, the decimal mark of
the whole file, nothing guessed); :func:`check_pressure_points` checks the points of
either source (inside the cycle, sorted, finite, absolute).  Every problem is recorded at
once, naming the key or the file and line.
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from crankbase.errors import Text, os_reason
from crankbase.schema import SpecReader

from ..indicator import PressureTable
from ..schema import PRESSURE, PRESSURE_UNITS

__all__ = ["read_pressure_csv", "check_pressure_points", "inline_pressure",
           "PRESSURE_UNITS"]


def check_pressure_points(c, angle, p, cycle_deg, where, unit="p_Pa"):
    """Validate a tabulated diagram; ``where(i)`` names row i.  Returns arrays or None.

    ``p`` is in Pa; messages give pressures in the user's ``unit`` (a key of
    :data:`PRESSURE_UNITS`).  Points must lie in [0, cycle), sorted, without repeats; a
    last row at the cycle end equal to the first row (720° = 0°) is accepted and dropped.
    """
    f = PRESSURE_UNITS[unit]
    n0 = len(c.problems)
    if len(angle) != len(p):
        c.add(where(None), Text("errors.engine.pressure.angle_and_pressure",
                                {"n": len(angle), "n2": len(p)}))
        return None, None
    for i, (a, q) in enumerate(zip(angle, p)):
        if not (math.isfinite(a) and math.isfinite(q)):
            c.add(where(i), Text("errors.engine.pressure.angle_and_pressure_2",
                                 {"a": a, "q": q / f}))
        elif q < 0:
            c.add(where(i), Text("errors.engine.pressure.negative_pressures_absolute",
                                 {"unit": unit, "q": q / f}))
    if len(c.problems) > n0:
        return None, None
    if len(angle) >= 2 and angle[-1] == cycle_deg and angle[0] == 0.0:
        if p[-1] != p[0]:
            c.add(where(len(angle) - 1), Text("errors.engine.pressure.end_row_at",
                                              {"cycle_deg": cycle_deg, "unit": unit,
                                               "value": p[-1] / f, "value2": p[0] / f}))
            return None, None
        angle, p = angle[:-1], p[:-1]
    if len(angle) < 2:
        c.add(where(None), Text("errors.engine.pressure.needs_at_least", {"n": len(angle)}))
        return None, None
    for i, a in enumerate(angle):
        if not 0 <= a < cycle_deg:
            c.add(where(i), Text("errors.engine.pressure.angle_outside_cycle",
                                 {"a": a, "cycle_deg": cycle_deg}))
        elif i and a <= angle[i - 1]:
            word = Text("errors.engine.pressure.repeated" if a == angle[i - 1]
                        else "errors.engine.pressure.not_sorted")
            c.add(where(i), Text("errors.engine.pressure.angle_angles_increase",
                                 {"a": a, "word": word}))
    if len(c.problems) > n0:
        return None, None
    return np.asarray(angle, float), np.asarray(p, float)


def inline_pressure(c, pr, cycle_deg):
    """The inline diagram of ``[pressure]`` (``angle_deg`` with one of the pressure
    lists) as ``(angle [deg], p [Pa])`` arrays, or ``(None, None)`` on a problem (recorded
    in the :class:`~crankbase.schema.SpecReader` ``c``)."""
    units = [k for k in PRESSURE_UNITS if k in pr]
    angle = c.get(pr, PRESSURE, "angle_deg")
    if not units:
        c.add("pressure", Text("errors.engine.pressure.inline_data_need",
                               {"items": ", ".join(PRESSURE_UNITS)}))
        return None, None
    if len(units) > 1:
        c.add("pressure", Text("errors.engine.pressure.give_one_pressure",
                               {"items": ", ".join(units)}))
        return None, None
    key = units[0]
    vals = c.get(pr, PRESSURE, key)
    if angle is None or vals is None:
        return None, None
    p = [v * PRESSURE_UNITS[key] for v in vals]

    def where(i):
        return f"pressure.{key}" if i is None else f"pressure.{key}[{i}]"
    return check_pressure_points(c, list(angle), p, cycle_deg, where, unit=key)


def read_pressure_csv(path, cycle_deg, checker=None):
    """Read an indicator diagram from CSV: header row with ``angle_deg`` and one of
    ``p_MPa``, ``p_bar``, ``p_kPa``, ``p_Pa``; lines starting with ``#`` are comments;
    other columns are ignored.

    The field separator is taken from the header: ``,`` (then the decimal mark must be
    ``.``), ``;`` or a tab (then the decimal mark may be ``.`` or ``,``, one of them for the
    whole file).  Nothing is guessed: a row with more or fewer fields than the header
    (e.g. decimal commas in a comma-separated file: ``0,0,1015``), a header with two
    kinds of separator, a file mixing decimal marks, or a number with both marks
    (``1.015,5``) is refused naming the line and what is ambiguous; no field is ever
    dropped.  Every problem of the file is reported at once (the first
    :data:`~crankbase.validation.MAX_ITEM_PROBLEMS` lines one by one, then a count), with
    values in the file's own unit.

    Parameters
    ----------
    path : str or Path
    cycle_deg : float
        720 or 360. [deg]
    checker : Checker, optional
        Problems are added to it (else an :class:`~engine.EngineSpecError` is raised).

    Returns
    -------
    PressureTable or None
        Crank angle [deg] and absolute pressure [Pa], with the file (None on a problem).
    """
    from crankbase.validation import MAX_ITEM_PROBLEMS, MAX_SPEC_BYTES, magnitude_text

    c = checker if checker is not None else SpecReader()
    path = Path(path)
    name = path.name
    key = "pressure.file"
    angle = p = None
    try:
        if path.stat().st_size > MAX_SPEC_BYTES:
            raise ValueError(f"{path.stat().st_size:,} bytes; at most {MAX_SPEC_BYTES:,} "
                             f"are read")
        with open(path, encoding="utf-8-sig", newline="") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        c.add(key, Text("errors.engine.pressure.cannot_read",
                        {"name": name, "value": os_reason(exc)}))
        text = None
    lines = []
    if text is not None:
        lines = [(n, ln) for n, ln in enumerate(text.splitlines(), start=1)
                 if ln.strip() and not ln.lstrip().startswith("#")]
        if not lines:
            c.add(key, Text("errors.engine.pressure.empty", {"name": name}))
    if lines:
        hline, htext = lines[0]
        seps = [s for s in (",", ";", "\t") if s in htext]
        shown = {",": "','", ";": "';'", "\t": "tab"}
        if len(seps) > 1:
            c.add(key, Text("errors.engine.pressure.line_header_uses",
                            {"name": name, "hline": hline,
                             "items": ', '.join(shown[s] for s in seps)}))
        elif not seps:
            c.add(key, Text("errors.engine.pressure.line_header_has",
                            {"name": name, "hline": hline, "value": htext.strip(),
                             "items": ', '.join(PRESSURE_UNITS)}))
        else:
            sep = seps[0]
            rows = list(csv.reader([ln for _, ln in lines], delimiter=sep))
            header = [h.strip() for h in rows[0]]
            units = [k for k in PRESSURE_UNITS if k in header]
            if "angle_deg" not in header or len(units) != 1:
                what = (Text("errors.engine.pressure.no_column") if not units else
                        Text("errors.engine.pressure.columns", {"items": ", ".join(units)}))
                if "angle_deg" not in header:
                    what = (Text("errors.engine.pressure.no_angle") if units else
                            Text("errors.engine.pressure.no_angle_and", {"what": what}))
                c.add(key, Text("errors.engine.pressure.line_header_needs",
                                {"name": name, "hline": hline, "what": what,
                                 "items": ', '.join(PRESSURE_UNITS), "items2": ', '.join(header)}))
            else:
                angle, p = _read_pressure_rows(c, key, name, sep, header, units[0],
                                               rows[1:], [n for n, _ in lines[1:]],
                                               cycle_deg, MAX_ITEM_PROBLEMS,
                                               magnitude_text)
    if checker is None:
        from .model import EngineSpecError

        c.raise_if_any(EngineSpecError)
    if angle is None:
        return None
    return PressureTable(tuple(angle.tolist()), tuple(p.tolist()), path.resolve())


def _read_pressure_rows(c, key, name, sep, header, unit, rows, numbers, cycle_deg,
                        max_shown, magnitude_problem):
    """The data rows of a pressure CSV (see :func:`read_pressure_csv`)."""
    from crankbase.validation import MAX_ROWS

    if len(rows) > MAX_ROWS:
        c.add(key, Text("errors.engine.pressure.has_data_rows",
                        {"name": name, "n": len(rows), "MAX_ROWS": MAX_ROWS}))
        return None, None
    ia, ip = header.index("angle_deg"), header.index(unit)
    comma_sep = sep == ","
    # decimal mark of the whole file (';' or tab separated): '.' or ',', never both
    marks, problems = {}, []
    if not comma_sep:
        for line, r in zip(numbers, rows):
            for i in (ia, ip):
                v = r[i].strip() if i < len(r) else ""
                if "." in v and "," in v:
                    problems.append(Text("errors.engine.pressure.both_marks",
                                         {"name": name, "line": line, "col": header[i],
                                          "value": v}))
                    continue
                for m in (".", ","):
                    if m in v:
                        marks.setdefault(m, (line, v))
    if len(marks) == 2:
        (l1, v1), (l2, v2) = marks["."], marks[","]
        problems.append(Text("errors.engine.pressure.mixed_marks",
                             {"name": name, "v1": v1, "l1": l1, "v2": v2, "l2": l2}))
    if problems:
        for msg in problems[:max_shown]:
            c.add(key, msg)
        if len(problems) > max_shown:
            c.add(key, Text("errors.engine.pressure.and_more_problems",
                            {"name": name, "value": len(problems) - max_shown}))
        return None, None
    decimal_comma = not comma_sep and "," in marks
    a_list, p_list, where = [], [], []
    nfields = len(header)
    for line, r in zip(numbers, rows):
        fields = [x.strip() for x in r]
        if len(fields) != nfields:
            text = sep.join(r)
            if len(fields) > nfields and comma_sep:
                why = Text("errors.engine.pressure.fields_commas",
                           {"n": len(fields), "nh": nfields, "text": text,
                            "header": ", ".join(header)})
            else:
                why = Text("errors.engine.pressure.fields",
                           {"n": len(fields), "nh": nfields, "text": text,
                            "header": ", ".join(header)})
            problems.append(Text("errors.engine.pressure.line",
                                 {"name": name, "line": line, "why": why}))
            continue
        vals = []
        for i, col in ((ia, "angle_deg"), (ip, unit)):
            v = fields[i]
            if decimal_comma and v.count(",") == 1:
                v = v.replace(",", ".")
            try:
                x = float(v)
                why = magnitude_problem(x)
            except ValueError:
                why = Text("errors.engine.pressure.not_number")
            if why:
                problems.append(Text("errors.engine.pressure.line_value",
                                     {"name": name, "line": line, "col": col,
                                      "value": fields[i], "why": why}))
                vals = None
                break
            vals.append(x)
        if vals is None:
            continue
        if vals[1] < 0:
            problems.append(Text("errors.engine.pressure.line_negative",
                                 {"name": name, "line": line, "unit": unit,
                                  "value": fields[ip]}))
            continue
        a_list.append(vals[0])
        p_list.append(vals[1] * PRESSURE_UNITS[unit])
        where.append(line)
    for msg in problems[:max_shown]:
        c.add(key, msg)
    if len(problems) > max_shown:
        c.add(key, Text("errors.engine.pressure.and_more_lines",
                        {"name": name, "value": len(problems) - max_shown}))
    if problems:
        return None, None

    def at(i):
        return Text("errors.engine.pressure.at", {"key": key, "name": name}) if i is None \
            else Text("errors.engine.pressure.at_line",
                      {"key": key, "name": name, "line": where[i]})
    return check_pressure_points(c, a_list, p_list, cycle_deg, at, unit=unit)
