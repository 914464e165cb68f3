"""Reader of the indicator-diagram export of Diesel-RK (``*.ind``).

The format, as Diesel-RK writes it (a raw export, e.g. ``6DNK70x280.ind`` in the public
repository staneuski/dualFuelEngine, ``etc/DRK2Py/``; the same table without the
preamble in staneuski/crankshaft, ``conrodForces/example.ind``):

.. code-block:: text

     Legend
     2020-02-24 13-50-14 "6DNK70-280-Diesel" ||| Режим: #1 : Ne_max ...
     Файл : 6DNK70x280.ind
     ...
     Comment
     Fi          Угол поворота коленчатого вала, [град.]
     Pc          Давление в цилиндре, [бар]
     Tc          Температура в цилиндре, [К]
     V           Объем цилиндра, [куб. м]
     ...
    Names
    Fi        Pc        Tc        V         Alf_w     P_1ring   G_bb      P_pist    x
    Arrays
     180.0      2.98     394.8     1.15453       207.7   1.5737      0.54144E-03    0.000  0.20000E+26
     181.0      ...

* an optional free-text preamble (``Legend`` … ``Comment`` with one line per column and
  its unit), then an optional ``Names`` line;
* the header line of column names, whitespace-separated, the first ``Fi`` (crank angle,
  degrees) and among them ``Pc`` (cylinder pressure, bar, absolute) and ``V`` (cylinder
  volume); then the line ``Arrays``;
* one row per crank angle, whitespace-separated numbers (Fortran ``E`` notation allowed),
  one per column; a blank line may end the file (CRLF line ends occur).

Crank angle origin: Diesel-RK counts Fi with the firing TDC at 360° and writes one cycle
from the BDC before it: Fi = 180 … 900 for a four-stroke engine (both example files) and
180 … 540 for a two-stroke one; the last row repeats the first.  crankdyn's α has the
firing TDC at 360° (four-stroke: α = 0 at the TDC that starts intake; two-stroke: 360° ≡
0°), so α = (Fi − Fi_TDC + 360) mod cycle with Fi_TDC = 360 by default
(``[pressure] firing_tdc_deg`` for another origin).  When a ``V`` column is present the
origin is checked: the volume must be least at the firing TDC (± one row), and for a
four-stroke engine the pressure peak must lie within 90° of it rather than of the
gas-exchange TDC.  The volume's unit is not relied on (the raw export above writes
1.15 "m³" for a 280-mm bore), so the file is not checked against the spec's bore and
stroke.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from crankbase.errors import Text, os_reason
from crankbase.tolerances import SAME_ANGLE_DEG
from crankbase.validation import Checker

__all__ = ["read_ind", "DIESEL_RK_TDC_DEG", "BAR"]

#: Crank angle of the firing TDC in Diesel-RK's scale. [deg]
DIESEL_RK_TDC_DEG = 360.0
#: One bar in Pa (Diesel-RK writes Pc in bar).
BAR = 1e5
#: Repeated end row: the last row may repeat the first within this relative difference
#: (the file prints pressures to 3 significant digits).
_END_ROW_RTOL = 1e-6
#: Bad rows listed before the reader stops (a wrong file would list every line).
_MAX_ROW_PROBLEMS = 5


def read_ind(path, cycle_deg, firing_tdc_deg=DIESEL_RK_TDC_DEG, checker=None,
             key="pressure.file"):
    """Read a Diesel-RK ``.ind`` indicator diagram.

    Parameters
    ----------
    path : str or Path
    cycle_deg : float
        720 (four-stroke) or 360. [deg]
    firing_tdc_deg : float
        Fi of the firing TDC in the file (Diesel-RK: 360). [deg]
    checker : Checker, optional
        Problems are added to it (else a :class:`crankbase.errors.SpecError` is raised).
    key : str
        Key path named in the problems.

    Returns
    -------
    angle_deg, p : ndarray or None
        crankdyn's α in [0, cycle), sorted, and the absolute pressure [Pa]; (None, None)
        when a problem was found.
    """
    c = checker if checker is not None else Checker()
    path = Path(path)
    name = path.name
    n0 = len(c.problems)
    try:
        text = path.read_text(encoding="utf-8-sig", errors="strict")
    except UnicodeDecodeError:
        try:
            text = path.read_text(encoding="cp1251")      # Diesel-RK on Windows
        except (OSError, UnicodeDecodeError) as exc:
            c.add(key, Text("errors.engine.dieselrk.cannot_read",
                            {"name": name, "exc": os_reason(exc)}))
            text = None
    except OSError as exc:
        c.add(key, Text("errors.engine.dieselrk.cannot_read",
                        {"name": name, "exc": os_reason(exc)}))
        text = None
    out = (None, None)
    if text is not None:
        out = _parse(c, key, name, text.splitlines(), cycle_deg, firing_tdc_deg)
    if len(c.problems) > n0:
        out = (None, None)
    if checker is None:
        c.raise_if_any()
    return out


def _parse(c, key, name, lines, cycle_deg, tdc):
    n0 = len(c.problems)
    # the header: the first line starting with "Fi" that names a Pc column (the preamble's
    # "Comment" section also has a line starting with "Fi", describing it)
    starts = [n for n, line in enumerate(lines, start=1) if line.split()[:1] == ["Fi"]]
    named = [n for n in starts if "Pc" in lines[n - 1].split()]
    after_names = [n + 1 for n, line in enumerate(lines, start=1)
                   if line.strip() == "Names" and n < len(lines)]
    if not named:
        near = (after_names or starts)
        where = (Text("errors.engine.dieselrk.line_reads",
                      {"line": near[-1], "text": lines[near[-1] - 1].strip()})
                 if near and near[-1] <= len(lines) else "")
        c.add(key, Text("errors.engine.dieselrk.no_column_header", {"name": name, "where": where}))
        return None, None
    hdr = named[0]
    cols = lines[hdr - 1].split()
    ip, iv = cols.index("Pc"), (cols.index("V") if "V" in cols else None)
    rows, numbers = [], []
    for n in range(hdr + 1, len(lines) + 1):
        tok = lines[n - 1].split()
        if not tok or (n == hdr + 1 and tok == ["Arrays"]):
            continue
        if len(c.problems) - n0 >= _MAX_ROW_PROBLEMS:
            c.add(key, Text("errors.engine.dieselrk.more_bad_rows", {"name": name, "n": n - 1}))
            break
        if len(tok) != len(cols):
            c.add(key, Text("errors.engine.dieselrk.line_values_header",
                            {"name": name, "n": n, "n2": len(tok), "n3": len(cols),
                             "items": ' '.join(cols)}))
            continue
        try:
            vals = [float(t) for t in tok]
        except ValueError:
            c.add(key, Text("errors.engine.dieselrk.line_not_number",
                            {"name": name, "n": n, "value": lines[n - 1].strip()}))
            continue
        if not all(math.isfinite(v) for v in (vals[0], vals[ip])):
            c.add(key, Text("errors.engine.dieselrk.line_fi_and", {"name": name, "n": n}))
            continue
        rows.append(n)
        numbers.append(vals)
    if len(c.problems) > n0:
        return None, None
    if len(rows) < 3:
        c.add(key, Text("errors.engine.dieselrk.data_rows_after",
                        {"name": name, "n": len(rows), "hdr": hdr}))
        return None, None
    data = np.array(numbers)
    fi, p = data[:, 0], data[:, ip] * BAR
    step = np.diff(fi)
    bad = np.nonzero(step <= 0)[0]
    if len(bad):
        i = bad[0] + 1
        c.add(key, Text("errors.engine.dieselrk.line_fi_does",
                        {"name": name, "value": rows[i], "value2": fi[i], "value3": fi[i - 1]}))
        return None, None
    neg = np.nonzero(p < 0)[0]
    if len(neg):
        c.add(key, Text("errors.engine.dieselrk.line_pressure_bar",
                        {"name": name, "value": rows[neg[0]], "value2": p[neg[0]] / BAR}))
        return None, None
    span = fi[-1] - fi[0]
    tol = SAME_ANGLE_DEG
    if span < cycle_deg - tol:
        c.add(key, Text("errors.engine.dieselrk.line_data_end",
                        {"name": name, "value": rows[-1], "value2": fi[-1], "span": span,
                         "value3": fi[0], "cycle_deg": cycle_deg}))
        return None, None
    if span > cycle_deg + tol:
        c.add(key, Text("errors.engine.dieselrk.line_data_span",
                        {"name": name, "value": rows[-1], "span": span, "value2": fi[0],
                         "value3": fi[-1], "cycle_deg": cycle_deg}))
        return None, None
    if abs(p[-1] - p[0]) > _END_ROW_RTOL * max(p[0], p[-1]) + 0.005 * BAR:
        c.add(key, Text("errors.engine.dieselrk.line_last_row",
                        {"name": name, "value": rows[-1], "value2": fi[-1], "value3": p[-1] / BAR,
                         "value4": p[0] / BAR}))
        return None, None
    fi, p, lines_used = fi[:-1], p[:-1], rows[:-1]
    if iv is not None:
        V = data[:-1, iv]
        if not _origin_ok(c, key, name, fi, p, V, lines_used, cycle_deg, tdc):
            return None, None
    alpha = np.mod(fi - tdc + 360.0, cycle_deg)
    order = np.argsort(alpha, kind="stable")
    return alpha[order], p[order]


def _origin_ok(c, key, name, fi, p, V, lines, cycle_deg, tdc):
    """The volume is least at the firing TDC (mod 360°, within one row) and, four-stroke,
    the pressure peak is nearer the firing TDC than the gas-exchange TDC."""
    i = int(np.argmin(V))
    row = float(np.max(np.diff(fi)))
    off = abs(((fi[i] - tdc) + 180.0) % 360.0 - 180.0)
    if off > row + SAME_ANGLE_DEG:
        c.add("pressure.firing_tdc_deg",
              Text("errors.engine.dieselrk.cylinder_volume_v",
                   {"name": name, "value": fi[i], "value2": lines[i], "tdc": tdc}))
        return False
    if cycle_deg > 360.0:
        k = int(np.argmax(p))
        d = abs(((fi[k] - tdc) + 360.0) % 720.0 - 360.0)
        if d > 90.0:
            c.add("pressure.firing_tdc_deg",
                  Text("errors.engine.dieselrk.pressure_peak_bar",
                       {"name": name, "value": p[k] / BAR, "value2": fi[k], "value3": lines[k],
                        "d": d, "tdc": tdc}))
            return False
    return True
