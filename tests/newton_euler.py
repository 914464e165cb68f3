"""Independent reference solutions for the linkage tests (a helper module, not a test file).

Nothing here imports :mod:`linkage`.  It reads a spec dict of the TOML shape (issue 2,
section 3) and computes, at given crank angles:

* the positions by the law of cosines (crank-rocker: the angle at A of the triangle A-B-C;
  crank-slider: the rod's inclination from the offset), polished by Newton iterations on
  the loop-closure equation ``A + l2·e^{iθ3} − C − l3·e^{iθ4} = 0`` (or
  ``A + l2·e^{iθ3} − (s + i·e)·u = 0``);
* velocities and accelerations from the loop-closure Jacobian (the time derivatives of the
  closure equation, one real 2×2 solve each);
* the useful resistance from the stroke, span and direction of motion (the extreme
  positions by the law of cosines on the extended and folded crank–coupler lines);
* all reactions and the driving moment from ONE global linear system per position: three
  equilibrium equations per moving link (ΣFx, ΣFy, ΣM about the global origin O), with
  d'Alembert inertia ``−m·a_S``, ``−J_S·ε`` and weight ``−m·g·j``; unknowns: both components
  of every joint reaction (R12 at O, R23 at A, R43 at B, and R14 at C for a rocker), for a
  slider the guide's normal force and its couple, and the driving moment.  Solved with
  :func:`numpy.linalg.solve`, batched over positions.

It returns the same column names as ``linkage.analyze`` so the tests can compare them one
by one.  Also here: small shared checks the identity and property tests use (equilibrium
from the tables, virtual power from the tables).
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["Model", "reference", "equilibrium_residuals", "virtual_power_terms",
           "rel_err", "wrap_deg"]

LINKS = {"crank-rocker": ("crank", "coupler", "rocker"),
         "crank-slider": ("crank", "coupler", "slider")}
NUMBER = {"crank": 2, "coupler": 3, "rocker": 4, "slider": 4}


def _cross(a, b):
    return a.real * b.imag - a.imag * b.real


def wrap_deg(x):
    """Wrap angles in degrees to (−180, 180]."""
    return -((-np.asarray(x, float) + 180.0) % 360.0 - 180.0)


def rel_err(a, b, scale=None):
    """max |a − b| / scale (scale defaults to max |b|, at least 1e-300)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if scale is None:
        scale = np.max(np.abs(b))
    return float(np.max(np.abs(a - b)) / max(scale, 1e-300))


class _Body:
    """Planar motion of a rigid link: origin (z, v, a), angle θ, ω, ε (arrays)."""

    def __init__(self, z, v, a, theta, omega, eps):
        self.z, self.v, self.a = z, v, a
        self.theta, self.omega, self.eps = theta, omega, eps

    def at(self, local):
        """(z, v, a) of the point with local coordinates ``local`` (complex)."""
        r = local * np.exp(1j * self.theta)
        return (self.z + r, self.v + 1j * self.omega * r,
                self.a + (1j * self.eps - self.omega ** 2) * r)


class Model:
    """A crank-rocker or crank-slider read from a TOML-shaped dict (no defaults beyond the
    contract's: mass 0, inertia 0, g = 9.81, ε = 0, assembly 1, offset 0, ground angle 0;
    the centre of mass defaults to mid-length of a bar and the pin B of a slider)."""

    def __init__(self, data):
        m = data["mechanism"]
        self.kind = m["kind"]
        self.l1 = float(m["crank"])
        self.l2 = float(m["coupler"])
        self.l3 = float(m.get("rocker", 0.0) or 0.0)
        self.l0 = float(m.get("ground", 0.0) or 0.0)
        self.gamma = math.radians(float(m.get("ground_angle_deg", 0.0)))
        self.offset = float(m.get("offset", 0.0))
        self.asm = int(m.get("assembly", 1))
        self.w2 = float(m["omega_rad_s"])
        self.e2 = float(m.get("epsilon_rad_s2", 0.0))
        self.g = float(m.get("gravity_m_s2", 9.81))
        self.u = complex(math.cos(self.gamma), math.sin(self.gamma))
        self.names = LINKS[self.kind]
        length = {"crank": self.l1, "coupler": self.l2, "rocker": self.l3, "slider": 0.0}
        self.mass, self.J, self.cg, self.points = {}, {}, {}, {}
        links = data.get("links", {})
        for n in self.names:
            t = links.get(n, {})
            self.mass[n] = float(t.get("mass_kg", 0.0))
            self.J[n] = float(t.get("inertia_kg_m2", 0.0))
            cg = t.get("cg", [length[n] / 2.0, 0.0])
            self.cg[n] = complex(cg[0], cg[1])
            for p, xy in t.get("points", {}).items():
                self.points[p] = (n, complex(xy[0], xy[1]))
        self.loads = list(data.get("load", []))
        a = data.get("analysis", {})
        self.working = a.get("working_stroke")

    # ------------------------------------------------------------------ kinematics
    def kinematics(self, phi):
        """Bodies of the three moving links at crank angles ``phi`` [rad]."""
        phi = np.asarray(phi, float)
        w2, e2 = self.w2, self.e2
        zA = self.l1 * np.exp(1j * phi)
        vA = 1j * w2 * zA
        aA = (1j * e2 - w2 * w2) * zA
        zero = np.zeros_like(zA)
        crank = _Body(zero, zero, zero, phi, np.full(phi.shape, w2), np.full(phi.shape, e2))
        l2 = self.l2
        if self.kind == "crank-rocker":
            l3 = self.l3
            zC = self.l0 * self.u
            d = zC - zA
            D = np.abs(d)
            # law of cosines in triangle A-B-C: angle at A between A->C and A->B
            cosA = (l2 * l2 + D * D - l3 * l3) / (2 * l2 * D)
            t3 = np.angle(d) + self.asm * np.arccos(np.clip(cosA, -1.0, 1.0))
            t4 = np.angle(zA + l2 * np.exp(1j * t3) - zC)
            for _ in range(4):  # Newton polish on loop closure
                f = zA + l2 * np.exp(1j * t3) - zC - l3 * np.exp(1j * t4)
                j1, j2 = 1j * l2 * np.exp(1j * t3), -1j * l3 * np.exp(1j * t4)
                det = _cross(j1, j2)
                t3 = t3 - _cross(f, j2) / det
                t4 = t4 - _cross(j1, f) / det
            e3, e4 = np.exp(1j * t3), np.exp(1j * t4)
            J = self._jac(1j * l2 * e3, -1j * l3 * e4)
            w3, w4 = self._solve(J, -vA)
            rhs = -aA + w3 ** 2 * l2 * e3 - w4 ** 2 * l3 * e4
            a3, a4 = self._solve(J, rhs)
            coupler = _Body(zA, vA, aA, t3, w3, a3)
            out = _Body(zC + zero, zero, zero, t4, w4, a4)
            extra = {}
        else:
            u, e = self.u, self.offset
            Ag = zA * u.conjugate()  # crank pin in guide coordinates
            sb = (e - Ag.imag) / l2
            tp = np.arcsin(np.clip(sb, -1.0, 1.0))
            if self.asm < 0:
                tp = math.pi - tp
            t3 = tp + self.gamma
            s = Ag.real + l2 * np.cos(tp)
            for _ in range(4):
                f = zA + l2 * np.exp(1j * t3) - (s + 1j * e) * u
                j1, j2 = 1j * l2 * np.exp(1j * t3), -u + zero
                det = _cross(j1, j2)
                t3 = t3 - _cross(f, j2) / det
                s = s - _cross(j1, f) / det
            e3 = np.exp(1j * t3)
            J = self._jac(1j * l2 * e3, -u + zero)
            w3, v = self._solve(J, -vA)
            a3, acc = self._solve(J, -aA + w3 ** 2 * l2 * e3)
            zB = (s + 1j * e) * u
            coupler = _Body(zA, vA, aA, t3, w3, a3)
            out = _Body(zB, v * u, acc * u, np.full(phi.shape, self.gamma), zero.real,
                        zero.real)
            extra = {"s": s, "v": v, "a": acc}
        bodies = {"crank": crank, "coupler": coupler, self.names[2]: out}
        return bodies, extra

    @staticmethod
    def _jac(c1, c2):
        """Real 2×2 Jacobians (n, 2, 2) of x1·c1 + x2·c2 (complex columns)."""
        c1, c2 = np.broadcast_arrays(c1, c2)
        J = np.empty(c1.shape + (2, 2))
        J[..., 0, 0], J[..., 1, 0] = c1.real, c1.imag
        J[..., 0, 1], J[..., 1, 1] = c2.real, c2.imag
        return J

    @staticmethod
    def _solve(J, rhs):
        b = np.stack([rhs.real, rhs.imag], axis=-1)[..., None]
        x = np.linalg.solve(J, b)[..., 0]
        return x[..., 0], x[..., 1]

    # ------------------------------------------------------------------ extremes
    def extreme_outputs(self):
        """Output coordinate (θ4 [rad] or s [m]) at the working-stroke start and end."""
        l0, l1, l2, l3 = self.l0, self.l1, self.l2, self.l3
        if self.kind == "crank-rocker":
            vals = []
            for d in (l1 + l2, l2 - l1):  # B at distance d from O: extended, folded
                # angle at C in triangle O-C-B, B on the assembly side of the line O-C
                cosC = (l0 * l0 + l3 * l3 - d * d) / (2 * l0 * l3)
                ang = math.acos(max(-1.0, min(1.0, cosC)))
                # the ray C->O has direction gamma + pi; B turns from it by -/+ ang
                vals.append(self._rocker_side_angle(ang))
            ext, fold = vals
            ccw_start = ext if wrap_deg(math.degrees(fold - ext)) > 0 else fold
            other = fold if ccw_start == ext else ext
            return (ccw_start, other) if self.working == "ccw" else (other, ccw_start)
        e = self.offset
        s_ext = self.asm * math.sqrt((l1 + l2) ** 2 - e * e)
        s_fold = self.asm * math.sqrt((l2 - l1) ** 2 - e * e)
        return (s_fold, s_ext) if self.working == "away" else (s_ext, s_fold)

    def _rocker_side_angle(self, ang):
        """Rocker angle θ4 of a B whose angle at C (from C->O) is ``ang``, on the side
        the assembly branch gives (found by assembling once at a test crank angle)."""
        cands = [self.gamma + math.pi + s * ang for s in (1, -1)]
        # which side of the line O-C does the branch put B on?  (sign of cross(OC, CB))
        bodies, _ = self.kinematics(np.array([self.gamma + math.pi / 2]))
        t4 = float(bodies["rocker"].theta[0])
        side = math.copysign(1.0, math.sin(t4 - self.gamma))
        return [c for c in cands if math.copysign(1.0, math.sin(c - self.gamma)) == side][0]

    def _stroke_phases(self, phi, bodies, extra):
        """Where each crank angle lies in the cycle, judged from the crank angle alone:
        +1 strictly inside the working stroke, −1 strictly inside the idle stroke, 0 at
        (within 1e-9 rad of) an extreme position, where the output stands still.  The
        strokes are the crank-angle intervals between the two extreme crank angles, which
        put crank and coupler on one line through O (|OB| = l1 + l2 or l2 − l1)."""
        ends = []
        for c in self.extreme_outputs():
            zB = (self.l0 * self.u + self.l3 * np.exp(1j * c) if self.kind == "crank-rocker"
                  else (c + 1j * self.offset) * self.u)
            folded = abs(abs(zB) - (self.l2 - self.l1)) < abs(abs(zB) - (self.l1 + self.l2))
            ends.append(np.angle(zB) + (math.pi if folded else 0.0))
        turn = 1.0 if self.w2 > 0 else -1.0
        into = np.mod(turn * (phi - ends[0]), 2 * math.pi)          # crank turn since start
        span = np.mod(turn * (ends[1] - ends[0]), 2 * math.pi)      # working-stroke turn
        near = (np.minimum(into, 2 * math.pi - into) < 1e-9) | (np.abs(into - span) < 1e-9)
        return np.where(near, 0, np.where(into < span, 1, -1))

    def resistance(self, bodies, extra, load):
        """Resistance value per position: moment on the rocker [N·m] or force along the
        guide on the slider [N], + ccw / + along the guide direction.

        The working stroke is known here as an interval of crank angles; in it the output
        moves in its working direction, so a resistance opposing the motion is the
        magnitude times minus that direction, and the opposite in the idle stroke."""
        size = float(load.get("resistance_Nm", load.get("resistance_N", 0.0)))
        phi = bodies["crank"].theta
        if self.kind == "crank-rocker":
            coord = bodies["rocker"].theta
            forward = 1.0 if (self.working or "ccw") == "ccw" else -1.0
            reach = math.radians(load["span_deg"]) if "span_deg" in load else math.inf
        else:
            coord = extra["s"]
            forward = float(self.asm) if (self.working or "away") == "away" else -float(self.asm)
            reach = load.get("span_m", math.inf)
        phase = self._stroke_phases(phi, bodies, extra)
        wanted = load.get("stroke", "working") if self.working else "both"
        on = {"working": phase == 1, "idle": phase == -1, "both": phase != 0}[wanted]
        if math.isfinite(reach):
            first = self.extreme_outputs()
            origin = np.where(phase == 1, first[0], first[1])
            gone = coord - origin
            if self.kind == "crank-rocker":
                gone = np.angle(np.exp(1j * gone))
            on = on & (np.abs(gone) <= reach * (1 + 1e-12))
        return np.where(on, -forward * phase * size, 0.0)

    # ------------------------------------------------------------------ kinetostatics
    def solve(self, phi):
        """Kinematics and the global Newton–Euler solve at crank angles ``phi`` [rad].

        Returns a dict of column name → array (names as in ``linkage.analyze``)."""
        phi = np.atleast_1d(np.asarray(phi, float))
        n = len(phi)
        bodies, extra = self.kinematics(phi)
        names = self.names
        out_name = names[2]
        # known loads per body: force F and moment about the origin M
        F = {k: np.zeros(n, complex) for k in names}
        M = {k: np.zeros(n) for k in names}
        res_total = np.zeros(n)
        for ld in self.loads:
            link = ld.get("link")
            if "force_N" in ld:
                f = complex(*ld["force_N"])
                z, _, _ = bodies[link].at(complex(*ld.get("at", [0.0, 0.0])))
                F[link] += f
                M[link] += _cross(z, f + 0 * z)
            elif "moment_Nm" in ld:
                M[link] += float(ld["moment_Nm"])
            else:
                val = self.resistance(bodies, extra, ld)
                res_total += val
                if self.kind == "crank-rocker":
                    M["rocker"] += val
                else:
                    fz = val * self.u
                    F["slider"] += fz
                    M["slider"] += _cross(bodies["slider"].z, fz)
        inertia = {}
        for k in names:
            zS, _, aS = bodies[k].at(self.cg[k])
            f = -self.mass[k] * aS - 1j * self.mass[k] * self.g
            F[k] += f
            M[k] += _cross(zS, f) - self.J[k] * bodies[k].eps
            inertia[k] = (-self.mass[k] * aS, -self.J[k] * bodies[k].eps + 0 * phi)
        zA = bodies["coupler"].z
        zB = bodies["coupler"].at(complex(self.l2, 0.0))[0]
        zO = np.zeros(n, complex)
        # unknowns: R12x R12y R23x R23y R43x R43y | rocker: R14x R14y | slider: N M14 | Md
        K = np.zeros((n, 9, 9))
        row = {"crank": 0, "coupler": 3, out_name: 6}

        def force(col, on, by, z):
            """Unknown force (columns col, col+1) of body ``by`` on body ``on`` at z."""
            for body, sgn in ((on, 1.0), (by, -1.0)):
                if body is None:
                    continue
                r = row[body]
                K[:, r, col] += sgn
                K[:, r + 1, col + 1] += sgn
                K[:, r + 2, col] += sgn * -z.imag       # (z × F)_z = x·Fy − y·Fx
                K[:, r + 2, col + 1] += sgn * z.real

        force(0, "crank", None, zO)          # R12 at O
        force(2, "coupler", "crank", zA)     # R23 at A
        force(4, "coupler", out_name, zB)    # R43 at B
        if self.kind == "crank-rocker":
            force(6, "rocker", None, self.l0 * self.u + zO)  # R14 at C
        else:
            iu = 1j * self.u
            r = row["slider"]
            K[:, r, 6], K[:, r + 1, 6] = iu.real, iu.imag     # N·iu at B
            K[:, r + 2, 6] = _cross(zB, iu + 0 * zB)
            K[:, r + 2, 7] = 1.0                                # couple M14
        K[:, 2, 8] = 1.0                                        # driving moment on the crank
        rhs = np.zeros((n, 9))
        for k in names:
            r = row[k]
            rhs[:, r], rhs[:, r + 1], rhs[:, r + 2] = -F[k].real, -F[k].imag, -M[k]
        x = np.linalg.solve(K, rhs[..., None])[..., 0]
        R12 = x[:, 0] + 1j * x[:, 1]
        R23 = x[:, 2] + 1j * x[:, 3]
        R43 = x[:, 4] + 1j * x[:, 5]
        e3 = np.exp(1j * bodies["coupler"].theta)
        col = {"phi_deg": np.degrees(phi),
               "R12_x_N": R12.real, "R12_y_N": R12.imag,
               "R23_x_N": R23.real, "R23_y_N": R23.imag,
               "R43_x_N": R43.real, "R43_y_N": R43.imag,
               "M_drive_Nm": x[:, 8],
               "R23_n_N": R23.real * e3.real + R23.imag * e3.imag,
               "R23_t_N": _cross(e3, R23)}
        if self.kind == "crank-rocker":
            R14 = x[:, 6] + 1j * x[:, 7]
            e4 = np.exp(1j * bodies["rocker"].theta)
            col.update({"R14_x_N": R14.real, "R14_y_N": R14.imag,
                        "R14_n_N": R14.real * e4.real + R14.imag * e4.imag,
                        "R14_t_N": _cross(e4, R14), "M_res_Nm": res_total})
        else:
            R14 = x[:, 6] * 1j * self.u
            col.update({"R14_x_N": R14.real, "R14_y_N": R14.imag, "N14_N": x[:, 6],
                        "M14_Nm": x[:, 7], "F_res_N": res_total})
        for name, R in (("R12", R12), ("R23", R23), ("R43", R43), ("R14", R14)):
            col[f"{name}_N"] = np.abs(R)
        for k in names:
            i, (fu, mu) = NUMBER[k], inertia[k]
            col.update({f"G{i}_N": self.mass[k] * self.g + 0 * phi, f"Fu{i}_x_N": fu.real,
                        f"Fu{i}_y_N": fu.imag, f"Fu{i}_N": np.abs(fu)})
            if k != "slider":
                col[f"Mu{i}_Nm"] = mu
        # kinematics columns
        c3, c4 = bodies["coupler"], bodies[out_name]
        col.update({"theta3_deg": np.degrees(c3.theta), "omega3_rad_s": c3.omega,
                    "eps3_rad_s2": c3.eps})
        if self.kind == "crank-rocker":
            col.update({"theta4_deg": np.degrees(c4.theta), "omega4_rad_s": c4.omega,
                        "eps4_rad_s2": c4.eps})
            d = c3.theta - c4.theta  # acute angle between the lines of AB and CB
            mu = np.arctan2(np.abs(np.sin(d)), np.abs(np.cos(d)))
        else:
            col.update({"s4_m": extra["s"], "v4_m_s": extra["v"], "a4_m_s2": extra["a"]})
            d = c3.theta - self.gamma  # 90° minus the acute angle rod-guide
            mu = np.arctan2(np.abs(np.cos(d)), np.abs(np.sin(d)))
        col["mu_deg"] = np.degrees(mu)
        pts = {"A": ("crank", complex(self.l1, 0)), "B": ("coupler", complex(self.l2, 0))}
        for k in names:
            pts[f"S{NUMBER[k]}"] = (k, self.cg[k])
        pts.update(self.points)
        for p, (k, local) in pts.items():
            z, v, a = bodies[k].at(local)
            col.update({f"{p}_x_m": z.real, f"{p}_y_m": z.imag, f"{p}_vx_m_s": v.real,
                        f"{p}_vy_m_s": v.imag, f"{p}_ax_m_s2": a.real,
                        f"{p}_ay_m_s2": a.imag, f"{p}_v_m_s": np.abs(v),
                        f"{p}_a_m_s2": np.abs(a)})
        # relative motion of B about A (and C): vector differences, and the normal and
        # tangential parts of the relative acceleration by projection on the link
        zA, vA, aA = bodies["crank"].at(complex(self.l1, 0))
        zB, vB, aB = bodies["coupler"].at(complex(self.l2, 0))
        rel = [("BA", zB - zA, vB - vA, aB - aA)]
        if self.kind == "crank-rocker":
            zC = self.l0 * self.u + 0 * zB
            rel.append(("BC", zB - zC, vB, aB))
        for name, r, v, a in rel:
            e = r / np.abs(r)
            col[f"v_{name}_m_s"] = np.abs(v)
            col[f"a_{name}_n_m_s2"] = -(a.real * e.real + a.imag * e.imag)
            col[f"a_{name}_t_m_s2"] = np.abs(_cross(e, a))
            col[f"a_{name}_m_s2"] = np.abs(a)
        return col


def reference(data, phi_deg):
    """Columns of the independent solution at crank angles ``phi_deg`` [deg]."""
    return Model(data).solve(np.radians(np.asarray(phi_deg, float)))


# ---------------------------------------------------------------- shared table checks


def _vec(df, name, suffix=("_x_N", "_y_N")):
    return df[name + suffix[0]].to_numpy(float) + 1j * df[name + suffix[1]].to_numpy(float)


def _point(kin, p, what):
    sx, sy = {"z": ("_x_m", "_y_m"), "v": ("_vx_m_s", "_vy_m_s"),
              "a": ("_ax_m_s2", "_ay_m_s2")}[what]
    return kin[p + sx].to_numpy(float) + 1j * kin[p + sy].to_numpy(float)


def link_loads(data, kin, frc):
    """Known loads per link from the tables and the spec dict: ``{link: (F, M_O)}``,
    force [N] and moment about the origin O [N·m], inertia and weight included.

    Point loads must sit at named extra points of their link (the tests put them there)
    so that their positions come from the kinematics table."""
    md = Model(data)
    n = len(kin)
    F = {k: np.zeros(n, complex) for k in md.names}
    M = {k: np.zeros(n) for k in md.names}
    omega = _omegas(md, kin)
    eps = _eps(md, kin)
    for ld in md.loads:
        k = ld["link"]
        if "force_N" in ld:
            p = _named_point(md, k, ld.get("at", [0.0, 0.0]))
            f = complex(*ld["force_N"])
            F[k] += f
            M[k] += _cross(_point(kin, p, "z"), f + np.zeros(n))
        elif "moment_Nm" in ld:
            M[k] += float(ld["moment_Nm"])
    if md.kind == "crank-rocker":
        M["rocker"] += frc["M_res_Nm"].to_numpy(float)
    else:
        f = frc["F_res_N"].to_numpy(float) * md.u
        F["slider"] += f
        M["slider"] += _cross(_point(kin, "B", "z"), f)
    for k in md.names:
        S = f"S{NUMBER[k]}"
        zS, aS = _point(kin, S, "z"), _point(kin, S, "a")
        f = -md.mass[k] * aS - 1j * md.mass[k] * md.g
        F[k] += f
        M[k] += _cross(zS, f) - md.J[k] * eps[k]
    del omega
    return F, M


def _named_point(md, link, at):
    at = complex(*at)
    for p, (k, local) in md.points.items():
        if k == link and abs(local - at) < 1e-15:
            return p
    raise AssertionError(f"tests must name the point {at} of {link} in links.{link}.points")


def _omegas(md, kin):
    w = {"crank": np.full(len(kin), md.w2), "coupler": kin["omega3_rad_s"].to_numpy(float)}
    w[md.names[2]] = (kin["omega4_rad_s"].to_numpy(float) if md.kind == "crank-rocker"
                      else np.zeros(len(kin)))
    return w


def _eps(md, kin):
    e = {"crank": np.full(len(kin), md.e2), "coupler": kin["eps3_rad_s2"].to_numpy(float)}
    e[md.names[2]] = (kin["eps4_rad_s2"].to_numpy(float) if md.kind == "crank-rocker"
                      else np.zeros(len(kin)))
    return e


def equilibrium_residuals(data, kin, frc):
    """Residuals of every link's equilibrium built from the reported reactions.

    Returns ``(residuals, scale)``: a dict ``"<link> Fx|Fy|M"`` → array [N or N·m], and a
    force scale [N] (the largest load or reaction).  The reactions used: on the crank
    R12 at O, R32 = −R23 at A and M_drive; on the coupler R23 at A and R43 at B; on the
    output link R34 = −R43 at B and R14 (at C for a rocker; at B with the couple M14 for a
    slider)."""
    md = Model(data)
    F, M = link_loads(data, kin, frc)
    zA, zB = _point(kin, "A", "z"), _point(kin, "B", "z")
    R12, R23, R43, R14 = (_vec(frc, r) for r in ("R12", "R23", "R43", "R14"))
    Md = frc["M_drive_Nm"].to_numpy(float)
    res = {}
    fcr = F["crank"] + R12 - R23
    mcr = M["crank"] + _cross(zA, -R23) + Md
    fco = F["coupler"] + R23 + R43
    mco = M["coupler"] + _cross(zA, R23) + _cross(zB, R43)
    k = md.names[2]
    if md.kind == "crank-rocker":
        zC = md.l0 * md.u
        fou = F[k] - R43 + R14
        mou = M[k] + _cross(zB, -R43) + _cross(zC + 0 * zB, R14)
    else:
        fou = F[k] - R43 + R14
        mou = M[k] + _cross(zB, -R43) + _cross(zB, R14) + frc["M14_Nm"].to_numpy(float)
    for name, f, m in (("crank", fcr, mcr), ("coupler", fco, mco), (k, fou, mou)):
        res[f"{name} Fx"], res[f"{name} Fy"], res[f"{name} M"] = f.real, f.imag, m
    scale = max(np.max(np.abs(v)) for v in (R12, R23, R43, R14, *F.values()))
    return res, scale


def virtual_power_terms(data, kin, frc):
    """The terms of the virtual-power balance, from the tables and the spec dict [W]:

    ``M_drive·ω2 + Σ(F_ext·v) + Σ(M_ext·ω) + P_resistance − Σ(m·aS·vS + JS·ε·ω)
    − Σ(m·g·vS,y)``, as a dict name → array (their sum must be 0)."""
    md = Model(data)
    n = len(kin)
    w, e = _omegas(md, kin), _eps(md, kin)
    t = {"drive": frc["M_drive_Nm"].to_numpy(float) * md.w2}
    for i, ld in enumerate(md.loads):
        k = ld["link"]
        if "force_N" in ld:
            p = _named_point(md, k, ld.get("at", [0.0, 0.0]))
            v = _point(kin, p, "v")
            f = complex(*ld["force_N"])
            t[f"force{i}"] = f.real * v.real + f.imag * v.imag
        elif "moment_Nm" in ld:
            t[f"moment{i}"] = float(ld["moment_Nm"]) * w[k]
    if md.kind == "crank-rocker":
        t["resistance"] = frc["M_res_Nm"].to_numpy(float) * w["rocker"]
    else:
        t["resistance"] = frc["F_res_N"].to_numpy(float) * kin["v4_m_s"].to_numpy(float)
    for k in md.names:
        S = f"S{NUMBER[k]}"
        vS, aS = _point(kin, S, "v"), _point(kin, S, "a")
        t[f"inertia {k}"] = -(md.mass[k] * (aS.real * vS.real + aS.imag * vS.imag)
                              + md.J[k] * e[k] * w[k])
        t[f"weight {k}"] = -md.mass[k] * md.g * vS.imag
    del n
    return t


# ---------------------------------------------------------------- example specs (dicts)

EXAMPLES = __import__("pathlib").Path(__file__).resolve().parents[1] / "examples"


def ratchet_data():
    """examples/ratchet.toml as a dict (seed 000, OC = 0.54 m)."""
    import tomllib
    with open(EXAMPLES / "ratchet.toml", "rb") as f:
        return tomllib.load(f)


def loaded_rocker(ground_angle_deg=20.0, assembly=1, omega=17.0, eps=3.0,
                  working="ccw"):
    """The ratchet drive with every kind of load: point forces on all three links (at
    named points), moments, resistance with a span, ε ≠ 0, a turned ground line."""
    d = ratchet_data()
    m = d["mechanism"]
    m.update(ground_angle_deg=ground_angle_deg, assembly=assembly, omega_rad_s=omega,
             epsilon_rad_s2=eps)
    d["links"]["crank"].update(inertia_kg_m2=0.05, cg=[0.08, 0.006],
                               points={"Q": [0.1, -0.03]})
    d["links"]["coupler"]["cg"] = [0.24, -0.015]
    d["links"]["coupler"]["points"] = {"E": [0.365, 0.0], "P": [0.3, 0.02]}
    d["links"]["rocker"].update(cg=[0.14, 0.01], points={"K": [0.2, -0.04]})
    d["load"] = d["load"] + [
        {"link": "coupler", "at": [0.3, 0.02], "force_N": [300.0, -150.0]},
        {"link": "crank", "at": [0.1, -0.03], "force_N": [-50.0, 80.0]},
        {"link": "rocker", "at": [0.2, -0.04], "force_N": [-400.0, 250.0]},
        {"link": "rocker", "moment_Nm": 120.0},
        {"link": "coupler", "moment_Nm": -35.0},
        {"link": "crank", "moment_Nm": 10.0}]
    d["analysis"] = {"positions": 12, "working_stroke": working}
    return d


def loaded_slider(assembly=1, working="away", offset=0.012, guide_deg=75.0, omega=-150.0,
                  eps=40.0):
    """An offset crank-slider on a turned guide with masses, inertias, point forces at
    named points, moments and a stroke-limited resistance."""
    return {
        "mechanism": {"kind": "crank-slider", "name": "test-slider", "crank": 0.05,
                      "coupler": 0.2, "ground_angle_deg": guide_deg, "offset": offset,
                      "assembly": assembly, "omega_rad_s": omega, "epsilon_rad_s2": eps,
                      "gravity_m_s2": 9.81},
        "links": {
            "crank": {"mass_kg": 2.0, "inertia_kg_m2": 0.003, "cg": [0.02, 0.004],
                      "points": {"Q": [0.03, -0.01]}},
            "coupler": {"mass_kg": 1.1, "inertia_kg_m2": 0.006, "cg": [0.07, -0.003],
                        "points": {"P": [0.1, 0.01]}},
            "slider": {"mass_kg": 0.8, "inertia_kg_m2": 0.001, "cg": [0.01, 0.005],
                       "points": {"K": [0.02, -0.01]}}},
        "load": [
            {"link": "slider", "at": [0.02, -0.01], "force_N": [-3000.0, 500.0]},
            {"link": "coupler", "at": [0.1, 0.01], "force_N": [100.0, 50.0]},
            {"link": "crank", "at": [0.03, -0.01], "force_N": [20.0, -70.0]},
            {"link": "slider", "moment_Nm": 7.0},
            {"link": "coupler", "moment_Nm": -3.0},
            {"link": "slider", "resistance_N": 900.0, "stroke": "working", "span_m": 0.06}],
        "analysis": {"positions": 24, "working_stroke": working}}
