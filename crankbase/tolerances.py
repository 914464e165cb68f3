"""Named numerical tolerances: one constant each, with the reason it has the value it has.

Every comparison with a tolerance in the calculation packages uses one of these, so a
maintainer can see at one place how close is "equal" and why.
"""
from __future__ import annotations

#: Relative slack that only absorbs floating-point round-off (a few ulps of a sum of
#: lengths, an angle range of exactly 2π, a count of steps that is an exact integer).
ROUNDOFF_RTOL = 1e-12


def snap_roundoff(values, scale):
    """Set every entry of the float array ``values`` with |x| ≤ ROUNDOFF_RTOL·``scale`` to
    exactly 0.0 (−0.0 too), in place, and return it.

    For result tables: a quantity that is exactly zero (the piston speed at TDC, β at
    α = 0, a balanced free force) comes out of the arithmetic as a residue of about
    1e-16 of the operands (−2e-32 m/s, −0.0°); below 1e-12 of the quantity's own scale
    (``scale``: a number, or one per column of a 2-D ``values``, broadcast over the rows)
    such a value carries no information, and a report should say 0.
    """
    import numpy as np

    values[np.abs(values) <= ROUNDOFF_RTOL * np.asarray(scale, float)] = 0.0
    return values

def format_snapped(value, fmt: str, scale=0.0) -> str:
    """``value`` formatted by ``fmt`` (``".2f"``) for a report, never as a negative zero:
    round-off below ROUNDOFF_RTOL·``scale`` is snapped to 0 (:func:`snap_roundoff`), and a
    value that the format rounds to zero is written without its sign ("0.00", not
    "-0.00", for a massless mechanism's −1e-17 N·m)."""
    import numpy as np

    x = float(snap_roundoff(np.array([float(value)]), scale)[0])
    text = format(x, fmt)
    if text.startswith("-") and not any(c in "123456789" for c in text.split("e")[0]):
        text = text[1:]
    return text


#: Relative margin of the Grashof / rotatability inequalities within which a mechanism
#: counts as a change-point (folding) one: lengths read from a spec in mm with ~10
#: significant digits agree to about this.  The one rule that uses it is
#: linkage.fourbar.rotatability_margin (distance to the boundary over √2·ground), called by
#: grashof, the mechanisms' check_rotatable and the synthesis region.
ROTATABILITY_RTOL = 1e-9

#: A link rate (ω of the output, slider speed) below this fraction of its scale counts as
#: at rest: separates the working and idle strokes at the extreme positions, where the
#: computed rate is round-off (~1e-16 of the scale) rather than an exact zero.
AT_REST_RTOL = 1e-9

#: Two crank angles closer than this [rad] are the same position (a requested angle that
#: coincides with a singular one computed in closed form).
SAME_ANGLE_RAD = 1e-9

#: Two angles in degrees closer than this [deg] are the same (angles read from a report,
#: rounded to ~10 significant digits).
SAME_ANGLE_DEG = 1e-6

#: Relative distance at which an assembled point counts as on its target when a closed-form
#: extreme position is confirmed against the assembly branch (the closed form goes through
#: a square root, which loses about half the digits near a double root).
ASSEMBLY_CHECK_RTOL = 1e-7

#: A quadratic's leading coefficient (an O(1) difference of squares of lengths relative to
#: the ground) below this is zero: solving it as a quadratic would divide round-off by
#: round-off, so the equation is solved as the linear one it has become.
DEGENERATE_QUADRATIC_ATOL = 1e-15

#: Step of the central difference that gives the slope of a polytrope p(α) at a rounding
#: knot of the indicator diagram [deg]: small against the 10–50° rounding zones, large
#: enough that the difference of pressures keeps ~8 significant digits.
POLYTROPE_SLOPE_STEP_DEG = 1e-4

#: A free force (moment) of an engine below this fraction of its largest possible inertia
#: force (times the crankshaft length) counts as balanced: an exact cancellation leaves
#: round-off of ~1e-15 of it, while a real residue (e.g. λ³ harmonics) is >= 1e-4.
BALANCED_RTOL = 1e-9

#: A load's contact point this close to the end of a wear arc counts as inside it [deg]:
#: the arc's ends belong to it, and contact angles from atan2 plus a shift of 180° carry
#: ~1e-13° of round-off (engine.bearings.wear).
WEAR_ARC_EDGE_DEG = 1e-9

#: Wear values within this fraction of the profile's range of its minimum tie for the
#: direction of least wear (equal sums of the same loads differ by round-off only).
WEAR_TIE_RTOL = 1e-9

#: A cylinder's phase must agree with its bank angle and throw, φ ≡ γ − τ (mod 360°),
#: within this [deg]: the layout's angles are sums of degrees given to ~1e-12.
PHASE_MATCH_DEG = 1e-6

#: Relative tolerance of `crankdyn check` on a student's table: a graphical plan or a
#: diagram drawn by hand on millimetre paper is good to a few per cent.
CHECK_RTOL = 0.02

#: Absolute tolerance of `crankdyn check`, as a fraction of the largest magnitude in the
#: column: a value near a zero crossing (T at α = 0) is judged against its column's scale.
#: With CHECK_RTOL a value may be off by 2.2 % of itself at its column's peak and by 2.6 %
#: at a third of the peak, so a 3 % error of any value above a third of its column's
#: largest magnitude is caught: 0.03·|x| > atol + rtol·|x| for |x| >= max/3 needs
#: atol < max/300 (issue 23: at 0.5 % a +3 % error of Sш at 390° passed).
CHECK_ATOL_OF_SCALE = 0.002
