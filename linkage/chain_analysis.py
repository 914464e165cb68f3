"""The analysis of a chain spec: the course tables of any linkage of class II groups.

:func:`analyze_chain` (called by :func:`linkage.analyze` for a
:class:`~linkage.chain_spec.ChainSpec`) solves the chain (:func:`linkage.chain.solve`)
at the plan of positions, applies the loads (forces, moments, the useful resistance on
the output link), runs the kinetostatics group by group (:func:`linkage.chain.kinetostatics`)
and returns the tables, the extremes of the output link, its stroke or swing, the time
ratio K and the transmission angle of every group.

Column names (ASCII, the unit last, the spec's own joint and link names):

* ``x_B_m``, ``y_B_m``, ``vx_B_m_s``, ``vy_B_m_s``, ``v_B_m_s``, ``ax_B_m_s2``,
  ``ay_B_m_s2``, ``a_B_m_s2``: every moving joint, every named point of a link and the
  centre of mass of each link with mass (``S_<link>``);
* ``theta_<link>_deg``, ``omega_<link>_rad_s``, ``eps_<link>_rad_s2``: every moving link;
* ``s_<slider>_m``, ``v_<slider>_m_s``, ``a_<slider>_m_s2``: a slider's position,
  velocity and acceleration along its guide (relative to the guide's link when the guide
  moves); ``s_<block>_<lever>_m``, ``vrel_<block>_<lever>_m_s``,
  ``arel_<block>_<lever>_m_s2``: the block's relative sliding in an RPR's slot, and the
  Coriolis acceleration ``acor_<block>_<lever>_m_s2`` (magnitude 2·|ω·v_rel|) with its
  components ``acorx_…``, ``acory_…``;
* ``mu_<link>_<link>_deg``: the transmission angle of each group (named after its two
  links), 0° to 90° (:func:`transmission_angles`);
* forces: ``Rx_<i>_<j>_N``, ``Ry_<i>_<j>_N``, ``R_<i>_<j>_N`` the force of link i on link
  j (``frame`` the frame) in every pair, ``Rn_…``, ``Rt_…`` its components along and
  across link j where the group gives them, ``Mp_<i>_<j>_Nm`` the couple of a prismatic
  pair; ``F_res_N`` or ``M_res_Nm`` the useful resistance; ``M_drive_Nm`` Mур.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from crankbase.errors import Problem, SpecError, Text
from crankbase.tolerances import AT_REST_RTOL

from . import chain as ch
from . import groups as g
from .loads import StrokeCycle, resistance, resistance_window

#: Degrees per radian and radians per degree: ``x * _DEG`` is ``np.degrees(x)`` bit for
#: bit (numpy's own ``x * (180/π)``), without its slower generic loop; likewise ``_RAD``.
_DEG = 180.0 / math.pi
_RAD = math.pi / 180.0

__all__ = ["ChainAnalysis", "ChainSummary", "analyze_chain", "transmission_angles",
           "output_motion", "output_extremes", "bisect_rate", "chain_loads", "reaction_tags"]


def reaction_tags(reactions):
    """``[(tag, reaction), ...]``: each pair's reaction once (the force of link i on link
    j; its opposite, j on i, left out), tagged ``"<i>_<j>"`` as the force columns name it
    (``Rx_<tag>_N`` …), with ``_<joint>`` added (``_P`` for a prismatic pair) when two
    pairs join the same two links.  The one naming rule of the chain's reaction columns."""
    out, seen, tags = [], set(), set()
    for (i, j), r in list(reactions.items()):
        if frozenset((i, j)) in seen and (j, i) in reactions:
            continue
        seen.add(frozenset((i, j)))
        tag = f"{i}_{j}"
        if tag in tags:
            tag += f"_{r.joint or 'P'}"
        tags.add(tag)
        out.append((tag, r))
    return out


@dataclass
class ChainSummary:
    """The cycle of a chain: structure, output extremes, time ratio, transmission angles.

    Attributes
    ----------
    structure : str
        ``I(0,1) → II RPR(2,3) → II RRP(4,5)``.
    mobility : tuple
        (W, n, p5, p4) by Chebyshev's formula.
    output, output_kind : str
        The output link and ``"slider"`` or ``"rocker"``.
    phi_working_start_deg, phi_working_end_deg : float or None
        Crank angles of the output's extremes where the working stroke starts and ends.
    working_crank_angle_deg, idle_crank_angle_deg, time_ratio : float or None
        Crank rotation in each stroke and K = φwork/φidle.
    start, end, travel : float or None
        Output coordinate at the start and end of the working stroke (m, or deg for a
        rocker) and the stroke (m) or swing (deg).
    mu_min_deg : dict
        Group (its two links joined by "_") → (minimum transmission angle over a full
        turn [deg], crank angle there [deg]).
    """

    structure: str
    mobility: tuple
    output: str
    output_kind: str
    rotation: str
    phi_working_start_deg: float | None = None
    phi_working_end_deg: float | None = None
    working_crank_angle_deg: float | None = None
    idle_crank_angle_deg: float | None = None
    time_ratio: float | None = None
    start: float | None = None
    end: float | None = None
    travel: float | None = None
    mu_min_deg: dict = field(default_factory=dict)

    @property
    def has_extremes(self) -> bool:
        return self.phi_working_start_deg is not None


@dataclass
class ChainAnalysis:
    """Result of :func:`analyze_chain` (what :func:`linkage.analyze` returns for a chain).

    Attributes
    ----------
    spec : ChainSpec
    kinematics, forces : pandas.DataFrame
        One row per position (columns: the module's docstring).
    summary : ChainSummary
    phi : ndarray
        The crank angles of the rows. [rad]
    motion : linkage.chain.ChainResult
        Every joint's and link's motion as arrays (kept from the tables when they are one
        chunk of :data:`linkage.groups.CHUNK` positions, else solved again on first use).
    reactions : linkage.chain.ChainForces
        Every pair's reaction and Mур (likewise).
    loads : tuple
        (forces, moments): link → [(force, global point)], link → [moment], as applied
        (likewise).
    extremes : None
        (The chain's extremes are in :attr:`summary`.)
    warnings : list of str
    """

    spec: object
    kinematics: object
    forces: object
    summary: ChainSummary
    phi: np.ndarray
    extremes: object = None
    warnings: list = field(default_factory=list)
    _whole: tuple | None = field(default=None, repr=False, compare=False)
    chain = True

    def _solved(self):
        if self._whole is None:               # the same routine as the tables' chunks
            self._whole = _solve_positions(self.spec, self.summary, self.phi)[:3]
        return self._whole

    @property
    def motion(self):
        return self._solved()[0]

    @property
    def reactions(self):
        return self._solved()[1]

    @property
    def loads(self):
        return self._solved()[2]


# ----------------------------------------------------------------------------- output


def output_motion(res: ch.ChainResult, output: str):
    """(coordinate, rate, acceleration) of the output link: a slider's position along its
    frame guide [m, m/s, m/s²], or a rocker's angle [rad, rad/s, rad/s²]."""
    mech = res.mech
    for grp, s in zip(mech.groups, res.solutions):
        if grp.links[1] == output and grp.kind in ("RRP", "RPP") and grp.guide.link == ch.FRAME:
            if grp.kind == "RRP":
                return _arr(s.s, res), _arr(s.v, res), _arr(s.a, res)
            return _arr(s.s_guide, res), _arr(s.v_guide, res), _arr(s.a_guide, res)
    lk = res.links[output]
    return _arr(lk.theta, res), _arr(lk.omega, res), _arr(lk.eps, res)


def _arr(x, res):
    return np.broadcast_to(np.asarray(x, float), res.phi.shape)


#: Levels of the bisection tree :func:`output_extremes` evaluates per solve of the chain.
BISECT_LEVELS = 8


def output_extremes(mech, output, rotation=1, n=720):
    """Crank angles [rad] where the output link's rate is zero (its extreme positions)
    and the coordinate there: ``(phi_min, c_min, phi_max, c_max)``, or None when the
    output never stops (it turns fully).  Sign changes of the rate on ``n`` positions,
    each refined by bisection to round-off (:func:`bisect_rate`)."""
    phi = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    c, r, _ = output_motion(ch.solve(mech, phi, float(rotation), 0.0), output)
    r1 = np.roll(r, -1)
    idx = np.nonzero((r > 0) & (r1 <= 0) | (r < 0) & (r1 >= 0))[0]
    if len(idx) < 2:
        return None
    lo = phi[idx]

    def rate(x):
        return output_motion(ch.solve(mech, x, float(rotation), 0.0, check=False), output)[1]

    lo, hi = bisect_rate(rate, lo, lo + 2.0 * math.pi / n, r[idx])
    z = np.mod(0.5 * (lo + hi), 2.0 * math.pi)
    cz, _, _ = output_motion(ch.solve(mech, z, float(rotation), 0.0, check=False), output)
    if output_kind_of(mech, output) == "rocker":             # angles about the middle
        ref = cz[0]
        cz = ref + np.angle(np.exp(1j * (cz - ref)))
    i_min, i_max = int(np.argmin(cz)), int(np.argmax(cz))
    return float(z[i_min]), float(cz[i_min]), float(z[i_max]), float(cz[i_max])


def bisect_rate(rate, lo, hi, r_lo, steps=60, levels=None):
    """Brackets ``[lo, hi]`` (float arrays) of sign changes of ``rate`` (a vectorised
    function of the crank angle, elementwise: a value does not depend on the other
    angles of the call), ``r_lo`` the rate at ``lo``, each halved ``steps`` times or
    until it stops changing (``lo``, ``hi`` adjacent floats): the final ``(lo, hi)``.

    The bisection's result bit for bit, ``mid = 0.5·(lo + hi)``, ``lo = mid`` where the
    rate there has the sign of ``r_lo``, else ``hi = mid``, with ``levels`` steps
    (:data:`BISECT_LEVELS`) per call of ``rate``: the call evaluates the whole tree of
    the next ``levels`` midpoints of every bracket (2^levels − 1 each, the same floats
    the steps would compute on every path), then the steps walk down it.  About 6 calls
    for the 45 steps to adjacent floats instead of 45 (a call of the chain costs about
    the same for 2 angles or 500)."""
    levels = BISECT_LEVELS if levels is None else levels
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    m = len(lo)
    rows = np.arange(m)
    sign = np.sign(r_lo)[:, None]
    left = steps
    while left > 0:
        d = min(levels, left)
        left -= d
        L, H, mids = lo[:, None], hi[:, None], []
        for k in range(d):                  # the tree: 2^k brackets at level k
            M = 0.5 * (L + H)
            mids.append(M)
            if k + 1 < d:                   # children 2j (L, M) and 2j + 1 (M, H)
                L2, H2 = np.empty((m, 2 * M.shape[1])), np.empty((m, 2 * M.shape[1]))
                L2[:, 0::2], L2[:, 1::2], H2[:, 0::2], H2[:, 1::2] = L, M, M, H
                L, H = L2, H2
        mids = np.concatenate(mids, axis=1)  # per bracket: level k, node j at 2^k − 1 + j
        same = np.sign(rate(mids.ravel()).reshape(m, -1)) == sign
        j = np.zeros(m, np.intp)
        for k in range(d):                  # the steps, down the tree
            h = j + ((1 << k) - 1)
            s, mid = same[rows, h], mids[rows, h]
            lo2, hi2 = np.where(s, mid, lo), np.where(s, hi, mid)
            if np.array_equal(lo2, lo) and np.array_equal(hi2, hi):
                return lo, hi    # a fixed point (~45 steps: lo, hi adjacent floats): every
            lo, hi = lo2, hi2    # later step would repeat it, the same mid and signs
            j = 2 * j + s
    return lo, hi


def output_kind_of(mech, output):
    from .chain_spec import output_kind

    return output_kind(mech, output)


# ----------------------------------------------------------------------- transmission


def transmission_angles(res: ch.ChainResult) -> dict:
    """The transmission angle μ of every group at every position [rad], 0 to π/2 (the
    angle between the force the group's driving pair transmits and the velocity of the
    point it drives; 90° is best):

    * RRR: between its two bars, folded: μ = asin|e₂ × e₃|;
    * RRP: between the rod and the normal to the guide: μ = asin|e₂ · u|;
    * RPR: between the slot and the lever's radius CA: μ = asin|e · (A − C)/|A − C||;
    * PRP, RPP: between the normal to the first slot or guide and the other:
      μ = asin|u₁ × u₂|.

    Keyed by the group's two links joined by "_"."""
    out = {}
    for grp, s in zip(res.mech.groups, res.solutions):
        key = "_".join(grp.links)
        with np.errstate(invalid="ignore", divide="ignore"):
            if grp.kind == "RRR":
                x = g.cross(s.link3.e, s.link4.e)
            elif grp.kind == "RRP":
                x = g.dot(s.link3.e, s.link4.e)
            elif grp.kind == "RPR":
                d = s.block.origin.z - s.lever.origin.z
                x = _fresh(np.divide, g.dot(s.lever.e, d), _modulus(d))
            elif grp.kind == "PRP":
                x = g.cross(s.link2.e, s.link3.e)
            else:
                x = g.cross(s.block.e, s.yoke.e)
            t = np.abs(np.asarray(x, float))        # a fresh array (or a scalar)
            mu = np.arcsin(_fresh(np.minimum, t, 1.0), out=t) if type(t) is np.ndarray \
                else np.arcsin(np.minimum(t, 1.0))
            # a constant angle (two fixed guides) as an array over the positions
            out[key] = mu if mu.shape == res.phi.shape else mu * np.ones(res.phi.shape)
    return out


def _fresh(op, t, u):
    """``op(t, u)``, written into ``t`` when it is a float array made for this call (and
    ``u`` a float or an array of its shape): the same operation, the same bits, one
    temporary fewer."""
    if type(t) is np.ndarray and t.dtype == float and t.ndim and (
            type(u) is float or type(u) is np.ndarray and u.shape == t.shape):
        return op(t, u, out=t)
    return op(t, u)


def _modulus(v):
    """``np.abs(v)`` of a :class:`~linkage.groups.Vec` (numpy's modulus of the complex
    array x + iy, the same bits) without the complex arithmetic of its conversion: the
    components copied into a complex array."""
    x, y = np.asarray(v.x, float), np.asarray(v.y, float)
    z = np.empty(np.broadcast_shapes(x.shape, y.shape), complex)
    z.real, z.imag = x, y
    return np.abs(z)


# ----------------------------------------------------------------------------- loads


def chain_loads(spec, res: ch.ChainResult, summary: ChainSummary | None):
    """Forces and moments of the spec on every link at the positions of ``res``:
    ``(forces, moments, resistance)`` — link → [(force, global point)], link → [moment],
    and the resistance array (+ along the guide, or + ccw) or None."""
    forces, moments = {}, {}
    res_total = None
    coord = rate = None
    kind = spec.output_kind
    for ld in spec.loads:
        lk = res.links[ld.link]
        if ld.kind == "force":
            forces.setdefault(ld.link, []).append((g.Vec.of(ld.force), lk.point(ld.at).z))
        elif ld.kind == "moment":
            moments.setdefault(ld.link, []).append(ld.moment)
        else:
            if coord is None:
                coord, rate, _ = output_motion(res, spec.output)
            cyc = _cycle(spec, summary)
            if kind == "rocker" and cyc.start_working is not None:
                coord = np.angle(np.exp(1j * coord))
            start, end = resistance_window(ld, cyc)
            r = resistance(ld.resistance, ld.stroke, end, rate, coord, cyc, start)
            res_total = r if res_total is None else res_total + r
            if kind == "slider":
                forces.setdefault(ld.link, []).append((lk.e * r, lk.origin.z))
            else:
                moments.setdefault(ld.link, []).append(r)
    return forces, moments, res_total


def _cycle(spec, summary):
    rocker = spec.output_kind == "rocker"
    at_rest = AT_REST_RTOL * abs(spec.omega) * (1.0 if rocker else spec.crank)
    if summary is None or not summary.has_extremes:
        return StrokeCycle(1, None, None, rocker, at_rest)
    sign = 1 if spec.working_stroke in ("away", "ccw") else -1
    s0, s1 = summary.start, summary.end
    if rocker:
        s0, s1 = math.radians(s0), math.radians(s1)
        s0, s1 = (float(np.angle(np.exp(1j * x))) for x in (s0, s1))
    return StrokeCycle(sign, s0, s1, rocker, at_rest)


# ----------------------------------------------------------------------------- summary


def _summary(spec) -> ChainSummary:
    mech = spec.mechanism
    rot = 1 if spec.omega > 0 else -1
    sm = ChainSummary(ch.structure_formula(mech, kinds=True), ch.mobility(mech), spec.output,
                      spec.output_kind,
                      "ccw" if spec.omega > 0 else "cw" if spec.omega < 0 else "none (statics)")
    full = ch.solve(mech, np.radians(np.arange(0.0, 360.0, 0.25)), 1.0, 0.0)
    for key, mu in transmission_angles(full).items():
        i = int(np.nanargmin(mu))
        sm.mu_min_deg[key] = (float(np.degrees(mu[i])), float(np.degrees(full.phi[i])))
    if spec.omega == 0:
        return sm
    ext = output_extremes(mech, spec.output, rot)
    if ext is None:
        return sm
    p_min, c_min, p_max, c_max = ext
    if spec.working_stroke in ("away", "ccw"):
        p0, c0, p1, c1 = p_min, c_min, p_max, c_max
    else:
        p0, c0, p1, c1 = p_max, c_max, p_min, c_min
    work = math.degrees((rot * (p1 - p0)) % (2.0 * math.pi))
    rocker = spec.output_kind == "rocker"
    conv = math.degrees if rocker else float
    sm.phi_working_start_deg = math.degrees(p0) % 360.0
    sm.phi_working_end_deg = math.degrees(p1) % 360.0
    sm.working_crank_angle_deg = work
    sm.idle_crank_angle_deg = 360.0 - work
    sm.time_ratio = work / (360.0 - work)
    sm.start, sm.end = conv(c0), conv(c1)
    sm.travel = abs(conv(c1) - conv(c0))
    return sm


# ----------------------------------------------------------------------------- tables


def _point_columns(name, pm, cols):
    z, v, a = pm.z, pm.v, pm.a
    cols[f"x_{name}_m"] = z.x
    cols[f"y_{name}_m"] = z.y
    cols[f"vx_{name}_m_s"] = v.x
    cols[f"vy_{name}_m_s"] = v.y
    if cols.course:
        np.hypot(v.x, v.y, out=cols.out(f"v_{name}_m_s"))
    cols[f"ax_{name}_m_s2"] = a.x
    cols[f"ay_{name}_m_s2"] = a.y
    if cols.course:
        np.hypot(a.x, a.y, out=cols.out(f"a_{name}_m_s2"))


def _slide_columns(grp, s, cols):
    if grp.kind == "RRP":
        sl = grp.links[1]
        cols[f"s_{sl}_m"], cols[f"v_{sl}_m_s"], cols[f"a_{sl}_m_s2"] = s.s, s.v, s.a
    elif grp.kind == "RPR":
        k = "_".join(grp.links)
        cols[f"s_{k}_m"], cols[f"vrel_{k}_m_s"], cols[f"arel_{k}_m_s2"] = s.s, s.v_rel, s.a_rel
        cols[f"acorx_{k}_m_s2"], cols[f"acory_{k}_m_s2"] = s.coriolis.x, s.coriolis.y
        if cols.course:
            np.hypot(s.coriolis.x, s.coriolis.y, out=cols.out(f"acor_{k}_m_s2"))
    elif grp.kind == "PRP":
        a, b = grp.links
        cols[f"s_{a}_m"], cols[f"v_{a}_m_s"], cols[f"a_{a}_m_s2"] = s.s1, s.v1, s.a1
        cols[f"s_{b}_m"], cols[f"v_{b}_m_s"], cols[f"a_{b}_m_s2"] = s.s2, s.v2, s.a2
    elif grp.kind == "RPP":
        a, b = grp.links
        k = "_".join(grp.links)
        cols[f"s_{k}_m"], cols[f"vrel_{k}_m_s"], cols[f"arel_{k}_m_s2"] = \
            s.s_slot, s.v_slot, s.a_slot
        cols[f"s_{b}_m"], cols[f"v_{b}_m_s"], cols[f"a_{b}_m_s2"] = \
            s.s_guide, s.v_guide, s.a_guide


def new_joints(grp) -> tuple:
    """The joints a group defines: the inner joint B of an RRR, RRP or PRP, none of an
    RPR or RPP (their block sits on a joint already solved)."""
    if grp.kind in ("RRR", "RRP"):
        return (grp.joints[1],)
    return (grp.joints[0],) if grp.kind == "PRP" else ()


class _Sink:
    """The columns of one chunk of positions, by name, in the order written: fresh arrays
    (the first chunk, which tells the names).  ``course``: also the course tables'
    magnitudes (|v|, |a|, |a_cor|, |R|)."""

    def __init__(self, n, course=True):
        self.n, self.course, self.cols = n, course, {}

    def __contains__(self, name):
        return name in self.cols

    def __setitem__(self, name, value):
        self.out(name)[...] = value

    def out(self, name):
        """The array that column ``name`` of this chunk is written into."""
        row = self.cols[name] = np.empty(self.n)
        return row


class _RowSink(_Sink):
    """The columns of every later chunk: the rows of the two preallocated blocks (``cols``:
    column name → the chunk's slice of its row, in the order of the first chunk), written
    in place; a scalar value (ω of a link turning steadily) fills its slice."""

    def __init__(self, n, course, rows):
        self.n, self.course, self.cols = n, course, rows

    def __setitem__(self, name, value):
        row = self.cols[name]
        if value is not row:                  # (a point computed into its rows: there)
            row[...] = value

    def out(self, name):
        return self.cols[name]


def _point_rows(K, p):
    """The six rows (x, y, vx, vy, ax, ay) of point ``p`` in ``K`` (:class:`_RowSink`)."""
    c = K.cols
    return (c[f"x_{p}_m"], c[f"y_{p}_m"], c[f"vx_{p}_m_s"], c[f"vy_{p}_m_s"],
            c[f"ax_{p}_m_s2"], c[f"ay_{p}_m_s2"])


def _solve_into(spec, phi, names, K):
    """:func:`linkage.chain.solve` at ``phi`` with the crank pin and the links' named
    points of ``names`` computed straight into their rows of ``K`` (as each link is
    solved), then the centres of mass of the links with mass (before the loads and the
    kinetostatics ask for them; :meth:`linkage.groups.LinkMotion.point` keeps them): one
    copy fewer per such column, the same bits.  A joint a group solves is copied."""
    mech = spec.mechanism
    res = ch.solve(mech, phi, spec.omega, spec.epsilon,
                   out={p: _point_rows(K, p) for p in names})
    for ln in mech.link_names:
        lk = mech.links[ln]
        if lk.mass:
            res.links[ln].point(lk.cg, _point_rows(K, f"S_{ln}"))
    return res


def _solve_positions(spec, summary, phi, into=None):
    """The chain at crank angles ``phi`` [rad]: motion, loads, kinetostatics:
    ``(motion, reactions, (forces, moments), resistance)``.  ``into``: (point names,
    :class:`_RowSink`) whose rows the points are computed into (:func:`_solve_into`)."""
    if into is None:
        res = ch.solve(spec.mechanism, phi, spec.omega, spec.epsilon)
    else:
        res = _solve_into(spec, phi, *into)
    forces, moments, r = chain_loads(spec, res, summary)
    cf = ch.kinetostatics(res, forces, moments, spec.gravity)
    return res, cf, (forces, moments), r


def _point_names(mech):
    """The moving joints and the links' named points, in the order of the columns: the
    crank pin and the crank's points, then each group's links' points and new joints."""
    names = [mech.driver.joint] + list(mech.links[mech.driver.link].points)
    for grp in mech.groups:
        for ln in grp.links:
            names += [p for p in mech.links[ln].points if p not in names]
        names += [j for j in new_joints(grp) if j not in names]
    return names


def _columns(spec, res, cf, res_force, K, F, names):
    """One chunk's kinematics columns into ``K`` and force columns into ``F``
    (:class:`_Sink`), in the order of the tables; ``names``: :func:`_point_names`."""
    mech = spec.mechanism
    np.multiply(res.phi, _DEG, out=K.out("phi_deg"))
    for j in names:
        _point_columns(j, res.point(j), K)
    for ln in mech.link_names:
        lk = mech.links[ln]
        if lk.mass:
            _point_columns(f"S_{ln}", res.links[ln].point(lk.cg), K)
    for ln in mech.link_names:
        np.multiply(res.links[ln].theta, _DEG, out=K.out(f"theta_{ln}_deg"))
        lm = res.links[ln]                   # a float ω, ε fills its column
        K[f"omega_{ln}_rad_s"] = lm.omega
        K[f"eps_{ln}_rad_s2"] = lm.eps
    for grp, s in zip(mech.groups, res.solutions):
        _slide_columns(grp, s, K)
    for key, mu in transmission_angles(res).items():
        np.multiply(mu, _DEG, out=K.out(f"mu_{key}_deg"))
    F["phi_deg"] = K.cols["phi_deg"]
    for tag, r in reaction_tags(cf.reactions):
        F[f"Rx_{tag}_N"], F[f"Ry_{tag}_N"] = r.force.x, r.force.y
        if F.course:
            np.hypot(r.force.x, r.force.y, out=F.out(f"R_{tag}_N"))
        if r.n is not None:
            F[f"Rn_{tag}_N"], F[f"Rt_{tag}_N"] = r.n, r.t
        if r.couple is not None:
            F[f"Mp_{tag}_Nm"] = r.couple
    if res_force is not None:
        F["F_res_N" if spec.output_kind == "slider" else "M_res_Nm"] = res_force
    F["M_drive_Nm"] = cf.M_drive


def _tables(spec, summary, phi, positions, course_tables=True):
    """The kinematics and force DataFrames at crank angles ``phi`` [rad], as the
    four-bar's (:func:`linkage.analysis._table`): the chain solved chunk by chunk
    (:data:`linkage.groups.CHUNK` positions), each chunk's columns written straight into
    two preallocated float blocks (columns × positions) that become the frames' storage
    without a copy.  Also returns ``(motion, reactions, loads)`` of the whole ``phi`` when
    it is one chunk, else None."""
    import pandas as pd

    n = len(phi)
    whole = None
    names = _point_names(spec.mechanism)
    for a in range(0, max(n, 1), g.CHUNK):
        b = min(n, a + g.CHUNK)
        if a:
            K = _RowSink(b - a, course_tables, {c: row[a:b] for c, row in zip(kcols, kblock)})
            F = _RowSink(b - a, course_tables, {c: row[a:b] for c, row in zip(fcols, fblock)})
            res, cf, loads, r = _solve_positions(spec, summary, phi[a:b], (names, K))
            _columns(spec, res, cf, r, K, F, names)
            del res, cf, loads, r, K, F   # (below)
            continue
        res, cf, loads, r = _solve_positions(spec, summary, phi[a:b])
        K, F = _Sink(b, course_tables), _Sink(b, course_tables)   # the first chunk names
        _columns(spec, res, cf, r, K, F, names)                    # the columns
        kcols, fcols = list(K.cols), list(F.cols)
        kblock, fblock = g.column_block(len(kcols), n), g.column_block(len(fcols), n)
        for block, sink in ((kblock, K), (fblock, F)):
            for row, v in zip(block, sink.cols.values()):
                row[:b] = v
        if b == n:
            whole = (res, cf, loads)
        # a chunk's arrays are dropped before the next chunk is solved: its hundreds of
        # temporaries then reuse their memory, still in the cache, rather than more of
        # the heap (about 3 % of the shaper's analyze at 1,000,000 positions)
        del res, cf, loads, r, K, F
    if positions is None:
        pos = pd.arrays.IntegerArray(np.zeros(n, np.int64), np.ones(n, bool))
    else:
        pos = pd.array(positions, dtype="Int64")
    kin = pd.DataFrame(kblock.T, columns=kcols, copy=False)     # the block is the storage
    frc = pd.DataFrame(fblock.T, columns=fcols, copy=False)
    pos = pd.Series(pos, index=kin.index, copy=False)  # one array, shared copy-on-write
    kin.insert(0, "position", pos)
    frc.insert(0, "position", pos)
    return kin, frc, whole


def analyze_chain(spec, crank_angles_deg=None, *, course_tables=True) -> ChainAnalysis:
    """Kinematics and kinetostatics of a chain spec at its plan of positions (position 1
    at the start of the working stroke, then every 360°/N in the direction of rotation),
    its ``crank_angles_deg`` or the ``crank_angles_deg`` given here [deg].

    ``course_tables=False`` leaves out the magnitudes ``v_P_m_s``, ``a_P_m_s2``,
    ``acor_…_m_s2`` and ``R_i_j_N`` (their components stay; large sweeps).  The tables
    are built chunk by chunk (:data:`linkage.groups.CHUNK` positions) into two
    preallocated blocks, the storage of the two DataFrames.

    Raises
    ------
    SpecError
        ``positions`` where the output link has no extremes.
    AssemblyError
        A group that cannot be assembled, or passes a dead position, in the cycle.
    """
    mech = spec.mechanism
    if spec.omega != 0:
        ch.check_cycle(mech)
    summary = _summary(spec)
    rot = 1 if spec.omega >= 0 else -1
    positions = None
    if crank_angles_deg is not None:
        phi = np.atleast_1d(np.asarray(crank_angles_deg, float)) * _RAD
    elif spec.crank_angles_deg is not None:
        phi = np.radians(np.asarray(spec.crank_angles_deg, float))
    else:
        if not summary.has_extremes:
            raise SpecError([Problem("analysis.positions",
                                     Text("errors.linkage.analysis.no_extremes"))])
        n = spec.positions
        phi = np.mod(math.radians(summary.phi_working_start_deg)
                     + rot * np.arange(n) * (2.0 * math.pi / n), 2.0 * math.pi)
        positions = np.arange(1, n + 1)
    kin, frc, whole = _tables(spec, summary, phi, positions, course_tables)
    return ChainAnalysis(spec, kin, frc, summary, phi, _whole=whole)


def full_turn_chain(spec, step_deg=1.0) -> ChainAnalysis:
    """The chain over a full turn from 0° at ``step_deg`` (the plots)."""
    return analyze_chain(spec, np.arange(0.0, 360.0 + 0.5 * step_deg, step_deg))
