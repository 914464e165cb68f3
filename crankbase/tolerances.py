"""Named numerical tolerances: one constant each, with the reason it has the value it has.

Every comparison with a tolerance in the calculation packages uses one of these, so a
maintainer can see at one place how close is "equal" and why.
"""
from __future__ import annotations

#: Relative slack that only absorbs floating-point round-off (a few ulps of a sum of
#: lengths, an angle range of exactly 2π, a count of steps that is an exact integer).
ROUNDOFF_RTOL = 1e-12

#: Relative margin of the Grashof / rotatability inequalities within which a mechanism
#: counts as a change-point (folding) one: lengths read from a spec in mm with ~10
#: significant digits agree to about this, and the synthesis region boundary uses it too.
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

#: Relative tolerance of `crankdyn check` on a student's table: a graphical plan or a
#: diagram drawn by hand on millimetre paper is good to a few per cent.
CHECK_RTOL = 0.02

#: Absolute tolerance of `crankdyn check`, as a fraction of the largest magnitude in the
#: column: a value near a zero crossing (T at α = 0) is judged against its column's scale.
CHECK_ATOL_OF_SCALE = 0.005
