"""The engine spec: read, validate (every problem at once) and derive SI quantities.

A spec is a TOML file (or an equivalent dict) with the tables ``[engine]``, ``[masses]``,
``[pressure]`` (exactly one source of the indicator diagram) and ``[table]``.  Every key is
documented in :func:`load_spec`; unknown keys are errors.  Inside, everything is SI
(m, kg, s, Pa, rad); degrees, mm, MPa and rpm appear only in the spec.

References
----------
.. [1] Колчин А. И., Демидов В. П. Расчёт автомобильных и тракторных двигателей.
   М.: Высшая школа, 2008 (§ "Кинематика", "Динамика": the dynamic model with mj and
   mш.к, mш.п ≈ 0.275 mш, masses per unit piston area).
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from crankbase.errors import Problem, SpecError
from crankbase.validation import Checker, read_toml

__all__ = ["EngineSpec", "CycleSpec", "EngineSpecError", "load_spec",
           "PRESSURE_UNITS", "read_pressure_csv"]

#: Pressure column names accepted in a CSV (and inline) and their factor to Pa.
PRESSURE_UNITS = {"p_MPa": 1e6, "p_bar": 1e5, "p_kPa": 1e3, "p_Pa": 1.0}

#: Default share of the rod mass taken as reciprocating (small end), mш.п / mш [1].
ROD_SMALL_END_FRACTION = 0.275


class EngineSpecError(SpecError):
    """An engine spec is invalid (a :class:`crankbase.errors.SpecError`, so a ValueError)."""


@dataclass(frozen=True)
class CycleSpec:
    """Thermal-calculation data for a computed indicator diagram (``[pressure.cycle]``).

    Pressures in Pa, angles in degrees.  See :mod:`engine.indicator` for the model.
    """

    kind: str                      # "otto" or "diesel"
    compression_ratio: float       # ε [-]
    pa: float                      # pressure at the end of intake [Pa]
    pr: float                      # residual-gas (exhaust) pressure [Pa]
    n1: float                      # compression polytropic index [-]
    n2: float                      # expansion polytropic index [-]
    pz: float                      # maximum pressure of the thermal calculation [Pa]
    rho: float                     # pre-expansion ratio ρ (1 for otto) [-]
    rounding: bool                 # round the diagram by the textbook rules
    advance_deg: float             # ignition (otto) or injection (diesel) advance [deg]
    pc_factor: float               # pc'' = pc_factor · pc at TDC [-]
    peak_factor: float             # real peak pzд = peak_factor · pz [-]
    peak_after_tdc_deg: float      # angle of the real peak after TDC [deg]
    exhaust_opening_deg: float     # exhaust valve opening before BDC [deg]
    intake_opening_deg: float      # intake valve opening before TDC [deg]
    exhaust_closing_deg: float     # exhaust valve closing after TDC [deg]

    @property
    def pc(self) -> float:
        """Pressure at the end of compression pc = pa·ε^n1. [Pa]"""
        return self.pa * self.compression_ratio ** self.n1

    @property
    def lambda_z(self) -> float:
        """Pressure-rise ratio λ = pz/pc. [-]"""
        return self.pz / self.pc


@dataclass(frozen=True)
class EngineSpec:
    """A validated engine spec with its derived quantities, SI inside.

    Attributes
    ----------
    name : str
    strokes : int
        4 (cycle 0…720°, α = 0 at the TDC that starts intake) or 2 (0…360°).
    bore, stroke : float
        Cylinder bore D and piston stroke S. [m]
    R, L, lam : float
        Crank radius R = S/2 [m], rod length Lш [m], λ = R/Lш [-].
    speed_rpm, omega : float
        Crankshaft speed n [rpm] and ω = πn/30 [rad/s].
    p0 : float
        Crankcase pressure. [Pa]
    acceleration : str
        "two-term" (j = Rω²(cos α + λ cos 2α)) or "exact" (from the RRP dyad).
    mj, m_rod_rot, m_crank_rot : float
        Reciprocating mass, rotating part of the rod mш.к, crank rotating mass mк
        (None when not given). [kg]
    mass_source : dict
        The masses as given (key → value), for the report.
    pressure_source : str
        "inline", "file" or "cycle".
    pressure_file : Path or None
    angle_deg, p : ndarray or None
        Tabulated indicator diagram (inline or CSV): crank angle [deg], absolute
        pressure [Pa].
    cycle : CycleSpec or None
    step_deg, extra_angles_deg, force_scale : float, tuple, float
        Table rows every ``step_deg``, extra rows, μP [N/mm].
    compression_ratio : float or None
        ε, when known (from ``[engine]`` or ``[pressure.cycle]``).
    cylinders : int
        Number of cylinders (informative; the table is for one cylinder).
    """

    name: str
    strokes: int
    bore: float
    stroke: float
    R: float
    L: float
    lam: float
    speed_rpm: float
    omega: float
    p0: float
    acceleration: str
    mj: float
    m_rod_rot: float
    m_crank_rot: float | None
    mass_source: dict
    pressure_source: str
    pressure_file: Path | None
    angle_deg: np.ndarray | None
    p: np.ndarray | None
    cycle: CycleSpec | None
    step_deg: float
    extra_angles_deg: tuple
    force_scale: float
    compression_ratio: float | None = None
    cylinders: int = 1
    source_path: Path | None = None
    raw: dict = field(default_factory=dict, repr=False)
    table_form: str = "seed"       # Table 2 in the seed's form (mm|N) or Kolchin's (MPa)

    @property
    def cycle_deg(self) -> float:
        """Length of the cycle in crank degrees: 720 (four-stroke) or 360. [deg]"""
        return 720.0 if self.strokes == 4 else 360.0

    @property
    def area(self) -> float:
        """Piston area Fп = πD²/4. [m²]"""
        return math.pi * self.bore ** 2 / 4.0

    @property
    def Vh(self) -> float:
        """Displacement of one cylinder Vh = Fп·S. [m³]"""
        return self.area * self.stroke

    @property
    def Vc(self) -> float | None:
        """Clearance volume Vc = Vh/(ε − 1), when ε is known. [m³]"""
        if self.compression_ratio is None:
            return None
        return self.Vh / (self.compression_ratio - 1.0)

    @property
    def Kr(self) -> float:
        """Centrifugal force of the rod's rotating part Kr.ш = −mш.к·R·ω². [N]"""
        return -self.m_rod_rot * self.R * self.omega ** 2

    @property
    def piston_speed_mean(self) -> float:
        """Mean piston speed vп.ср = S·n/30. [m/s]"""
        return self.stroke * self.speed_rpm / 30.0

    def with_step(self, step_deg: float) -> "EngineSpec":
        """A copy with another table step (the CLI's ``--step``); validated."""
        if not (isinstance(step_deg, (int, float)) and math.isfinite(step_deg)
                and 0 < step_deg <= self.cycle_deg):
            raise EngineSpecError(Problem(
                "--step", f"got {step_deg!r}; must be > 0 and <= {self.cycle_deg:g}"))
        from dataclasses import replace
        return replace(self, step_deg=float(step_deg))


# ----------------------------------------------------------------------------- loader

_ENGINE_KEYS = ("name", "strokes", "cylinders", "bore_mm", "stroke_mm", "rod_ratio",
                "rod_length_mm", "speed_rpm", "crankcase_MPa", "acceleration",
                "compression_ratio")
_MASS_DIRECT = ("reciprocating_kg", "rod_rotating_kg")
_MASS_PARTS = ("piston_group_kg", "rod_kg")
_MASS_AREA = ("piston_group_kg_m2", "rod_kg_m2")
_MASS_KEYS = _MASS_DIRECT + _MASS_PARTS + _MASS_AREA + ("rod_small_end_fraction",
                                                        "crank_rotating_kg")
_PRESSURE_KEYS = ("angle_deg", *PRESSURE_UNITS, "file", "cycle")
_CYCLE_KEYS = ("kind", "compression_ratio", "pa_MPa", "pr_MPa", "n1", "n2", "pz_MPa",
               "lambda_z", "rho", "rounding", "advance_deg", "pc_factor", "peak_factor",
               "peak_after_tdc_deg", "exhaust_opening_deg", "intake_opening_deg",
               "exhaust_closing_deg")
_TABLE_KEYS = ("step_deg", "extra_angles_deg", "force_scale_N_per_mm", "form")

#: The rounded combustion curve meets the expansion polytrope this far after the peak. [deg]
JOIN_AFTER_PEAK_DEG = 20.0

#: Rounding defaults (Kolchin & Demidov, "Скругление индикаторной диаграммы").
CYCLE_DEFAULTS = {
    "otto": dict(advance_deg=30.0, pc_factor=1.2, peak_factor=0.85, peak_after_tdc_deg=12.0,
                 exhaust_opening_deg=50.0, intake_opening_deg=20.0,
                 exhaust_closing_deg=20.0),
    "diesel": dict(advance_deg=20.0, pc_factor=1.2, peak_factor=0.85,
                   peak_after_tdc_deg=12.0, exhaust_opening_deg=50.0,
                   intake_opening_deg=20.0, exhaust_closing_deg=20.0),
}


def load_spec(path_or_dict, base_dir=None) -> EngineSpec:
    """Read and validate an engine spec; return an :class:`EngineSpec` (SI inside).

    Parameters
    ----------
    path_or_dict : str, Path or dict
        A TOML file, or the same content as a dict.
    base_dir : str or Path, optional
        Folder against which ``[pressure] file`` is resolved when a dict is given
        (default: the current folder).  For a file, its own folder is used.

    Returns
    -------
    EngineSpec

    Raises
    ------
    EngineSpecError
        Listing *every* problem, each with its key path (or CSV file and row).

    Notes
    -----
    ``[engine]``: ``name`` (str), ``strokes`` (4 or 2, default 4), ``cylinders`` (default 1,
    informative), ``bore_mm`` > 0, ``stroke_mm`` > 0, exactly one of ``rod_ratio``
    (0 < λ < 1) and ``rod_length_mm`` (> stroke/2), ``speed_rpm`` > 0, ``crankcase_MPa``
    (p0 ≥ 0, default 0.1), ``acceleration`` ("two-term", default, or "exact"),
    ``compression_ratio`` (ε > 1, optional: sets Vc for the p–V plot).

    ``[masses]``, exactly one way: ``reciprocating_kg`` and ``rod_rotating_kg`` (mj,
    mш.к); or ``piston_group_kg`` and ``rod_kg``; or per unit piston area
    ``piston_group_kg_m2`` and ``rod_kg_m2``; with the parts, ``rod_small_end_fraction``
    (default 0.275) gives mш.п = f·mш, mш.к = (1 − f)·mш, mj = mп + mш.п [1]_.
    ``crank_rotating_kg`` (mк) is optional.

    ``[pressure]``, exactly one source: inline ``angle_deg`` with one of ``p_MPa``,
    ``p_bar``, ``p_kPa``, ``p_Pa`` (absolute); ``file`` (a CSV with a header row holding
    ``angle_deg`` and one of those pressure columns); or ``[pressure.cycle]``.

    ``[table]``: ``step_deg`` (default 30), ``extra_angles_deg`` (default none),
    ``force_scale_N_per_mm`` (μP > 0, required), ``form`` ("seed": forces in mm and N,
    the default; "kolchin": specific forces in MPa with the coefficient columns).
    """
    data, file_dir = read_toml(path_or_dict)
    if not isinstance(path_or_dict, dict):
        base = file_dir
        source_path = Path(path_or_dict).resolve()
    else:
        base = Path(base_dir) if base_dir is not None else Path.cwd()
        source_path = None
    c = Checker()
    c.unknown(data, ("engine", "masses", "pressure", "table"))

    # ---- [engine]
    e = c.table(data, "engine")
    c.unknown(e, _ENGINE_KEYS, "engine")
    name = c.string(e, "name", "engine", required=False, default="engine")
    if name is not None and not name.strip():
        c.add("engine.name", "must not be empty")
    strokes = c.choice(e, "strokes", (4, 2), "engine", required=False, default=4)
    cylinders = c.number(e, "cylinders", "engine", required=False, default=1, ge=1,
                         integer=True)
    bore = c.number(e, "bore_mm", "engine", gt=0, what="the cylinder bore D [mm]")
    stroke = c.number(e, "stroke_mm", "engine", gt=0, what="the piston stroke S [mm]")
    speed = c.number(e, "speed_rpm", "engine", gt=0, what="the crankshaft speed [rpm]")
    p0 = c.number(e, "crankcase_MPa", "engine", required=False, default=0.1, ge=0)
    accel = c.choice(e, "acceleration", ("two-term", "exact"), "engine", required=False,
                     default="two-term")
    eps_engine = c.number(e, "compression_ratio", "engine", required=False, gt=1)
    has_ratio, has_len = "rod_ratio" in e, "rod_length_mm" in e
    lam = L_mm = None
    if has_ratio and has_len:
        c.add("engine.rod_ratio", "give either rod_ratio or rod_length_mm, not both")
    elif not has_ratio and not has_len:
        c.add("engine.rod_ratio", "missing; give rod_ratio (λ = R/Lш, 0 < λ < 1) "
                                  "or rod_length_mm")
    elif has_ratio:
        lam = c.number(e, "rod_ratio", "engine", gt=0, lt=1)
    else:
        L_mm = c.number(e, "rod_length_mm", "engine", gt=0)
        if L_mm is not None and stroke is not None and not L_mm > stroke / 2:
            c.add("engine.rod_length_mm",
                  f"got {L_mm:g}; must be > the crank radius stroke_mm/2 = {stroke / 2:g}")
            L_mm = None

    # ---- [masses]
    m = c.table(data, "masses")
    c.unknown(m, _MASS_KEYS, "masses")
    mj = m_rot = None
    groups = [g for g in (_MASS_DIRECT, _MASS_PARTS, _MASS_AREA) if any(k in m for k in g)]
    if "masses" in data and isinstance(m, dict):
        if not groups:
            c.add("masses", "no masses given; give reciprocating_kg and rod_rotating_kg, "
                            "or piston_group_kg and rod_kg, or piston_group_kg_m2 and "
                            "rod_kg_m2")
        elif len(groups) > 1:
            c.add("masses", "give the masses one way only: "
                  + " / ".join(" + ".join(g) for g in groups) + " were all given")
    frac = c.number(m, "rod_small_end_fraction", "masses", required=False,
                    default=ROD_SMALL_END_FRACTION, ge=0, le=1)
    m_crank = c.number(m, "crank_rotating_kg", "masses", required=False, ge=0)
    area = math.pi * (bore / 1000.0) ** 2 / 4.0 if bore else None
    if len(groups) == 1:
        g = groups[0]
        a = c.number(m, g[0], "masses", ge=0)
        b = c.number(m, g[1], "masses", ge=0)
        if g is _MASS_DIRECT:
            if "rod_small_end_fraction" in m:
                c.add("masses.rod_small_end_fraction",
                      "only used with piston_group_kg/rod_kg or the per-area masses")
            mj, m_rot = a, b
        elif a is not None and b is not None and frac is not None:
            scale = 1.0 if g is _MASS_PARTS else area
            if scale is not None:
                mj = (a + frac * b) * scale
                m_rot = (1.0 - frac) * b * scale

    # ---- [pressure]
    pr = c.table(data, "pressure")
    c.unknown(pr, _PRESSURE_KEYS, "pressure")
    sources = []
    if "angle_deg" in pr or any(k in pr for k in PRESSURE_UNITS):
        sources.append("inline")
    if "file" in pr:
        sources.append("file")
    if "cycle" in pr:
        sources.append("cycle")
    cycle_deg = 720.0 if strokes == 4 else 360.0
    angle = p = cycle = pfile = None
    if "pressure" in data and isinstance(pr, dict):
        if not sources:
            c.add("pressure", "no pressure source; give angle_deg with p_MPa (inline), "
                              "file = \"...csv\", or a [pressure.cycle] table")
        elif len(sources) > 1:
            c.add("pressure", "give exactly one pressure source; got "
                  + " and ".join(sources))
    if sources == ["inline"]:
        angle, p = _inline_pressure(c, pr, cycle_deg)
    elif sources == ["file"]:
        fname = c.string(pr, "file", "pressure")
        if fname is not None:
            pfile = (base / fname) if not Path(fname).is_absolute() else Path(fname)
            if not pfile.is_file():
                c.add("pressure.file", f"file {str(pfile)!r} does not exist")
            else:
                angle, p = read_pressure_csv(pfile, cycle_deg, c)
    elif sources == ["cycle"]:
        cycle = _cycle(c, c.table(pr, "cycle", "pressure"), strokes)

    eps = eps_engine
    if cycle is not None:
        if eps_engine is not None and eps_engine != cycle.compression_ratio:
            c.add("engine.compression_ratio",
                  f"got {eps_engine:g} but pressure.cycle.compression_ratio is "
                  f"{cycle.compression_ratio:g}; give it once")
        eps = cycle.compression_ratio

    # ---- [table]
    t = c.table(data, "table")
    c.unknown(t, _TABLE_KEYS, "table")
    step = c.number(t, "step_deg", "table", required=False, default=30.0, gt=0,
                    le=cycle_deg)
    extra = c.numbers(t, "extra_angles_deg", "table", required=False, default=[], ge=0)
    for i, x in enumerate(extra or []):
        if x > cycle_deg:
            c.add(f"table.extra_angles_deg[{i}]", f"got {x:g}; must be <= {cycle_deg:g}")
    mu = c.number(t, "force_scale_N_per_mm", "table", gt=0,
                  what="the force scale μP [N/mm]")
    form = c.choice(t, "form", ("seed", "kolchin"), "table", required=False,
                    default="seed")

    if cycle is not None and cycle.rounding and not c.problems:
        _check_rounded_peak(c, cycle, lam if lam is not None else stroke / 2.0 / L_mm)
    if c.problems:
        raise EngineSpecError(c.problems)

    R = stroke / 2000.0
    if lam is not None:
        L = R / lam
    else:
        L = L_mm / 1000.0
        lam = R / L
    return EngineSpec(
        name=name.strip(), strokes=int(strokes), bore=bore / 1000.0, stroke=stroke / 1000.0,
        R=R, L=L, lam=lam, speed_rpm=speed, omega=math.pi * speed / 30.0, p0=p0 * 1e6,
        acceleration=accel, mj=float(mj), m_rod_rot=float(m_rot), m_crank_rot=m_crank,
        mass_source={k: m[k] for k in m}, pressure_source=sources[0],
        pressure_file=pfile.resolve() if pfile is not None else None,
        angle_deg=angle, p=p, cycle=cycle, step_deg=step,
        extra_angles_deg=tuple(sorted(set(extra or []))), force_scale=mu,
        compression_ratio=eps, cylinders=int(cylinders), source_path=source_path,
        raw=data, table_form=form)


def _check_pressure_points(c, angle, p, cycle_deg, where):
    """Validate a tabulated diagram; ``where(i)`` names row i.  Returns arrays or None.

    Points must lie in [0, cycle), sorted, without repeats; a last row at the cycle end
    equal to the first row (720° = 0°) is accepted and dropped.
    """
    n0 = len(c.problems)
    if len(angle) != len(p):
        c.add(where(None), f"angle and pressure lists differ in length "
                           f"({len(angle)} and {len(p)})")
        return None, None
    for i, (a, q) in enumerate(zip(angle, p)):
        if not (math.isfinite(a) and math.isfinite(q)):
            c.add(where(i), f"angle {a!r} and pressure {q!r} must be finite numbers")
        elif q < 0:
            c.add(where(i), f"pressure {q:g} Pa is negative (pressures are absolute)")
    if len(c.problems) > n0:
        return None, None
    if len(angle) >= 2 and angle[-1] == cycle_deg and angle[0] == 0.0:
        if p[-1] != p[0]:
            c.add(where(len(angle) - 1), f"the end row at {cycle_deg:g}° must repeat the "
                                         f"row at 0° (got {p[-1]:g} and {p[0]:g} Pa)")
            return None, None
        angle, p = angle[:-1], p[:-1]
    if len(angle) < 2:
        c.add(where(None), f"needs at least two distinct points, got {len(angle)}")
        return None, None
    for i, a in enumerate(angle):
        if not 0 <= a < cycle_deg:
            c.add(where(i), f"angle {a:g}° is outside the cycle [0, {cycle_deg:g})")
        elif i and a <= angle[i - 1]:
            word = "repeated" if a == angle[i - 1] else "not sorted"
            c.add(where(i), f"angle {a:g}° is {word} (angles must increase)")
    if len(c.problems) > n0:
        return None, None
    return np.asarray(angle, float), np.asarray(p, float)


def _inline_pressure(c, pr, cycle_deg):
    units = [k for k in PRESSURE_UNITS if k in pr]
    angle = c.numbers(pr, "angle_deg", "pressure")
    if not units:
        c.add("pressure", "inline data need one of " + ", ".join(PRESSURE_UNITS)
              + " beside angle_deg")
        return None, None
    if len(units) > 1:
        c.add("pressure", "give one pressure list, got " + ", ".join(units))
        return None, None
    key = units[0]
    vals = c.numbers(pr, key, "pressure")
    if angle is None or vals is None:
        return None, None
    p = [v * PRESSURE_UNITS[key] for v in vals]

    def where(i):
        return f"pressure.{key}" if i is None else f"pressure.{key}[{i}]"
    return _check_pressure_points(c, list(angle), p, cycle_deg, where)


def read_pressure_csv(path, cycle_deg, checker=None):
    """Read an indicator diagram from CSV: header row with ``angle_deg`` and one of
    ``p_MPa``, ``p_bar``, ``p_kPa``, ``p_Pa``; lines starting with ``#`` are comments;
    other columns are ignored.

    Parameters
    ----------
    path : str or Path
    cycle_deg : float
        720 or 360. [deg]
    checker : Checker, optional
        Problems are added to it (else an :class:`EngineSpecError` is raised).

    Returns
    -------
    angle_deg, p : ndarray
        Crank angle [deg] and absolute pressure [Pa] (None, None on a problem).
    """
    c = checker if checker is not None else Checker()
    path = Path(path)
    name = path.name
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            rows = [(n, r) for n, r in enumerate(csv.reader(f), start=1)
                    if r and any(x.strip() for x in r) and not r[0].lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as exc:
        c.add("pressure.file", f"cannot read {name}: {exc}")
        rows = None
    angle = p = None
    if rows is not None:
        if not rows:
            c.add("pressure.file", f"{name} is empty")
        else:
            hline, header = rows[0]
            header = [h.strip() for h in header]
            units = [k for k in PRESSURE_UNITS if k in header]
            if "angle_deg" not in header or len(units) != 1:
                what = ("no pressure column" if not units else
                        "more than one pressure column (" + ", ".join(units) + ")")
                if "angle_deg" not in header:
                    what = "no angle_deg column" + ("" if units else " and " + what)
                c.add("pressure.file", f"{name} line {hline}: {what}; the header needs "
                      "angle_deg and exactly one of " + ", ".join(PRESSURE_UNITS)
                      + f"; got {', '.join(header)}")
            else:
                ia, ip = header.index("angle_deg"), header.index(units[0])
                factor = PRESSURE_UNITS[units[0]]
                a_list, p_list, lines = [], [], []
                n0 = len(c.problems)
                for line, r in rows[1:]:
                    try:
                        a_list.append(float(r[ia]))
                        p_list.append(float(r[ip]) * factor)
                        lines.append(line)
                    except (ValueError, IndexError):
                        c.add("pressure.file", f"{name} line {line}: not two numbers in "
                              f"angle_deg and {units[0]}: {','.join(r)!r}")
                if len(c.problems) == n0:
                    def where(i):
                        if i is None:
                            return f"pressure.file {name}"
                        return f"pressure.file {name} line {lines[i]}"
                    angle, p = _check_pressure_points(c, a_list, p_list, cycle_deg, where)
    if checker is None:
        c.raise_if_any()
    return angle, p


def _check_rounded_peak(c, cyc, lam):
    """The real (rounded) diagram lies inside the theoretical one: its peak
    peak_factor·pz must not rise above the expansion line at the peak angle, and must be
    the maximum (the line where the rounding rejoins it must be lower)."""
    from .indicator import sharp_cycle_pressure

    a = 360.0 + cyc.peak_after_tdc_deg
    line = float(sharp_cycle_pressure([a], cyc, lam)[0])
    peak = cyc.peak_factor * cyc.pz
    if peak > line:
        c.add("pressure.cycle.peak_factor",
              f"the rounded peak peak_factor·pz = {peak / 1e6:.4g} MPa at {a:g}° lies above "
              f"the expansion line there ({line / 1e6:.4g} MPa); lower peak_factor or "
              f"peak_after_tdc_deg")
        return
    join = a + JOIN_AFTER_PEAK_DEG
    after = float(sharp_cycle_pressure([join], cyc, lam)[0])
    if after >= peak:
        c.add("pressure.cycle.peak_factor",
              f"the expansion line at {join:g}° ({after / 1e6:.4g} MPa), where the rounded "
              f"curve rejoins it, is not below the rounded peak ({peak / 1e6:.4g} MPa): the "
              f"isobaric part (ρ) is too long for the rounding; raise peak_factor or "
              f"peak_after_tdc_deg")


def _cycle(c, cy, strokes):
    path = "pressure.cycle"
    c.unknown(cy, _CYCLE_KEYS, path)
    kind = c.choice(cy, "kind", ("otto", "diesel"), path)
    if strokes != 4:
        c.add(path, "a computed diagram is available for four-stroke engines only; "
                    "give a pressure table for a two-stroke engine")
    eps = c.number(cy, "compression_ratio", path, gt=1)
    pa = c.number(cy, "pa_MPa", path, gt=0)
    pr = c.number(cy, "pr_MPa", path, gt=0)
    n1 = c.number(cy, "n1", path, gt=1, lt=2)
    n2 = c.number(cy, "n2", path, gt=1, lt=2)
    if "pz_MPa" in cy and "lambda_z" in cy:
        c.add(f"{path}.pz_MPa", "give either pz_MPa or lambda_z, not both")
        pz = lz = None
    elif "lambda_z" in cy:
        lz = c.number(cy, "lambda_z", path, ge=1)
        pz = None
    else:
        pz = c.number(cy, "pz_MPa", path, gt=0, what="pz [MPa] (or lambda_z = pz/pc)")
        lz = None
    if kind == "diesel":
        rho = c.number(cy, "rho", path, ge=1, what="the pre-expansion ratio ρ")
    else:
        if "rho" in cy:
            c.add(f"{path}.rho", "only used with kind = \"diesel\"")
        rho = 1.0
    rounding = c.choice(cy, "rounding", (True, False), path, required=False, default=True)
    d = CYCLE_DEFAULTS.get(kind or "otto")
    opts = {k: c.number(cy, k, path, required=False, default=v, gt=0, lt=90)
            for k, v in d.items() if k not in ("pc_factor", "peak_factor")}
    opts["pc_factor"] = c.number(cy, "pc_factor", path, required=False,
                                 default=d["pc_factor"], ge=1, le=2)
    opts["peak_factor"] = c.number(cy, "peak_factor", path, required=False,
                                   default=d["peak_factor"], gt=0, le=1)
    if None in (kind, eps, pa, pr, n1, n2, rho) or (pz is None and lz is None) \
            or None in opts.values():
        return None
    pc = pa * eps ** n1
    if pz is None:
        pz = lz * pc
    elif pz < pc:
        c.add(f"{path}.pz_MPa", f"got {pz:g}; must be >= the compression pressure "
                                f"pc = pa·ε^n1 = {pc:.4g} MPa")
        return None
    if kind == "diesel" and rho >= eps:
        c.add(f"{path}.rho", f"got {rho:g}; must be < compression_ratio {eps:g}")
        return None
    if rounding and (360 + opts["peak_after_tdc_deg"] + JOIN_AFTER_PEAK_DEG
                     > 540 - opts["exhaust_opening_deg"]):
        c.add(f"{path}.exhaust_opening_deg", "the combustion rounding (peak_after_tdc_deg "
              f"+ {JOIN_AFTER_PEAK_DEG:g}°) and the exhaust rounding overlap; reduce them")
        return None
    if opts["peak_factor"] * pz < opts["pc_factor"] * pc and rounding:
        c.add(f"{path}.peak_factor", "the rounded peak peak_factor·pz must not be below "
                                     "pc_factor·pc")
        return None
    return CycleSpec(kind=kind, compression_ratio=eps, pa=pa * 1e6, pr=pr * 1e6, n1=n1,
                     n2=n2, pz=pz * 1e6, rho=rho, rounding=rounding, **opts)
