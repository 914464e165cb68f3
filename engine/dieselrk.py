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
            c.add(key, f"cannot read {name}: {exc}")
            text = None
    except OSError as exc:
        c.add(key, f"cannot read {name}: {exc}")
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
        where = (f"; line {near[-1]} reads {lines[near[-1] - 1].strip()!r}"
                 if near and near[-1] <= len(lines) else "")
        c.add(key, f"{name}: no column header found (a line 'Fi Pc Tc V ...' naming the "
                   f"crank angle Fi and the cylinder pressure Pc [bar]){where}; is this a "
                   "Diesel-RK .ind export?")
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
            c.add(key, f"{name}: more bad rows after line {n - 1} not listed")
            break
        if len(tok) != len(cols):
            c.add(key, f"{name} line {n}: {len(tok)} values, the header has "
                       f"{len(cols)} columns ({' '.join(cols)}); truncated or damaged row")
            continue
        try:
            vals = [float(t) for t in tok]
        except ValueError:
            c.add(key, f"{name} line {n}: not a number in {lines[n - 1].strip()!r}")
            continue
        if not all(math.isfinite(v) for v in (vals[0], vals[ip])):
            c.add(key, f"{name} line {n}: Fi and Pc must be finite numbers")
            continue
        rows.append(n)
        numbers.append(vals)
    if len(c.problems) > n0:
        return None, None
    if len(rows) < 3:
        c.add(key, f"{name}: {len(rows)} data rows after the header on line {hdr}; a "
                   "whole cycle is needed")
        return None, None
    data = np.array(numbers)
    fi, p = data[:, 0], data[:, ip] * BAR
    step = np.diff(fi)
    bad = np.nonzero(step <= 0)[0]
    if len(bad):
        i = bad[0] + 1
        c.add(key, f"{name} line {rows[i]}: Fi = {fi[i]:g} does not increase "
                   f"(previous row {fi[i - 1]:g})")
        return None, None
    neg = np.nonzero(p < 0)[0]
    if len(neg):
        c.add(key, f"{name} line {rows[neg[0]]}: pressure {p[neg[0]] / BAR:g} bar is "
                   "negative (Pc is absolute)")
        return None, None
    span = fi[-1] - fi[0]
    tol = 1e-9 * cycle_deg
    if span < cycle_deg - tol:
        c.add(key, f"{name} line {rows[-1]}: the data end at Fi = {fi[-1]:g}, "
                   f"{span:g}° after the first row (Fi = {fi[0]:g}); a whole cycle of "
                   f"{cycle_deg:g}° is needed (truncated file?)")
        return None, None
    if span > cycle_deg + tol:
        c.add(key, f"{name} line {rows[-1]}: the data span {span:g}° (Fi = {fi[0]:g} … "
                   f"{fi[-1]:g}), more than one cycle of {cycle_deg:g}°; is "
                   "[engine] strokes right?")
        return None, None
    if abs(p[-1] - p[0]) > _END_ROW_RTOL * max(p[0], p[-1]) + 0.005 * BAR:
        c.add(key, f"{name} line {rows[-1]}: the last row (Fi = {fi[-1]:g}) ends the "
                   f"cycle but its pressure {p[-1] / BAR:g} bar differs from the first "
                   f"row's {p[0] / BAR:g} bar")
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
    if off > row + 1e-9:
        c.add("pressure.firing_tdc_deg",
              f"{name}: the cylinder volume V is least at Fi = {fi[i]:g} (line {lines[i]}), "
              f"not at the firing TDC Fi = {tdc:g} or {tdc:g} ± 360; give the file's "
              "firing TDC as firing_tdc_deg")
        return False
    if cycle_deg > 360.0:
        k = int(np.argmax(p))
        d = abs(((fi[k] - tdc) + 360.0) % 720.0 - 360.0)
        if d > 90.0:
            c.add("pressure.firing_tdc_deg",
                  f"{name}: the pressure peak ({p[k] / BAR:g} bar at Fi = {fi[k]:g}, line "
                  f"{lines[k]}) is {d:g}° from the firing TDC Fi = {tdc:g}: that is the "
                  "gas-exchange TDC; give firing_tdc_deg of the other TDC")
            return False
    return True
