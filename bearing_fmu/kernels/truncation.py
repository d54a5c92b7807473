"""Truncation of the contact ellipse by the groove shoulders (docs/quasistatic.md section 8).

A ball-race contact lies on the groove, a circle of radius r = f D about the groove-curvature centre in
the ball's (axial, radial) plane. Its contact angle alpha is the direction of the contact normal seen
from that centre, measured from the radial plane; positive toward the race's thrust-side shoulder (the
side a ball presses under a thrust +z on the inner ring: the high shoulder of an angular-contact ring).
The Hertz contact ellipse's semi-major axis a lies in that plane, across the rolling direction, in the
plane tangent to the groove at the contact centre.

Each shoulder (land) of a ring ends the groove at the shoulder angle phi, seen from the same centre:
  inner ring: cos phi = (rho_i - d_s/2) / r_i,  outer ring: cos phi = (d_s/2 - rho_o) / r_o,
rho the radius of the groove-curvature-centre circle, d_s the land diameter (the groove point at angle
phi from the groove bottom lies at radius rho -+ r cos phi; with h the shoulder height above the groove
bottom, cos phi = 1 - h/(f D), the relation of Harris & Kotzalas' shoulder-height check, docs/decisions.md).
The shoulder edge lies at s = r sin(phi - alpha) from the contact centre, measured along the tangent
plane, where the ellipse's semi-major axis runs; the ellipse passes the edge when a > s, i.e. when
alpha + arcsin(a/r) > phi (arcsin(a/r): the angle the semi-major axis subtends at the groove centre).
The truncated fraction is the part of the major axis beyond the edge in units of a:
  t = (a - s) / a = 1 - r sin(phi - alpha) / a,  clipped to [0, 2]
(0: the ellipse ends at or before the edge; 1: the contact centre sits on the edge, half the ellipse is
cut off; 2: the whole ellipse lies beyond it). The other shoulder (alpha negative side) is the same with
-alpha and its own angle. An edge more than 90 deg from the contact centre is as far as the groove reaches
along the tangent plane: s = +-r.
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

# truncation parameters of one bearing, float64[TP_SIZE]: per race (inner at 0, outer at TP_STRIDE)
_TP_SLOTS = Layout()
TP_A1 = _TP_SLOTS.slot()  # semi-major axis of the contact at 1 N (m): a = TP_A1 Q^(1/3) (Hertz)
TP_R = _TP_SLOTS.slot()  # groove radius f D (m)
TP_THRUST = _TP_SLOTS.slot()  # angle of the thrust-side shoulder edge from the groove centre (rad, > 0)
TP_BACK = _TP_SLOTS.slot()  # angle of the other shoulder's edge (rad, > 0, on the side of negative contact angles)
TP_STRIDE = _TP_SLOTS.slot(4)
TP_SIZE = _TP_SLOTS.size

# truncation outputs, float64[TR_SIZE]
_TR_SLOTS = Layout()
TR_INNER = _TR_SLOTS.slot()  # truncated fraction of the most truncated loaded inner contact (-, 0 if none)
TR_OUTER = _TR_SLOTS.slot()  # ... outer contact
TR_BALL_INNER = _TR_SLOTS.slot()  # its ball index (-1 if no contact is truncated)
TR_BALL_OUTER = _TR_SLOTS.slot()
TR_SIZE = _TR_SLOTS.size

T_MAX = 2.0  # the whole ellipse beyond the shoulder


@kernel
def shoulder_angle(centre_radius, groove_radius, shoulder_diameter, race):
    """Angle (rad, in [0, pi]) of a shoulder's edge from the radial line through the groove-curvature centre:
    centre_radius rho (m) of the centre circle, groove_radius r = f D (m), land diameter d_s (m), race 0 inner
    (the groove below the centre: cos phi = (rho - d_s/2)/r), 1 outer (above it: cos phi = (d_s/2 - rho)/r).
    A land at or below the groove bottom gives 0 (no shoulder), one beyond the centre's level pi/2 or more."""
    depth = centre_radius - 0.5 * shoulder_diameter if race == 0 else 0.5 * shoulder_diameter - centre_radius
    return math.acos(min(1.0, max(-1.0, depth / groove_radius)))


@kernel
def truncated_fraction(a, r, alpha, thrust, back):
    """Fraction of the semi-major axis a (m, > 0) beyond the nearer-passed shoulder edge (-, in [0, 2]) of a
    contact at angle alpha (rad) on a groove of radius r (m) with shoulder edges at +thrust and -back (rad)."""
    worst = 0.0
    for edge in (thrust - alpha, back + alpha):  # angular distance from the contact centre to each edge
        # the groove reaches no further than r along the tangent plane, 90 deg away (either way)
        reach = r * math.sin(min(0.5 * math.pi, max(-0.5 * math.pi, edge)))
        worst = max(worst, 1.0 - reach / a)
    return min(worst, T_MAX)


@kernel
def race_truncation(loads, load_row, angles, angle_row, tp, tr):
    """Fill tr[TR_*] with the most truncated loaded contact of each race.

    loads[load_row + race, j]: contact load (N) of ball j on race 0 (inner) or 1 (outer), > 0 if loaded;
    angles[angle_row + race, j]: its signed contact angle (rad, positive toward the thrust-side shoulder);
    tp: TP_* parameters. An open contact (load <= 0) is never truncated."""
    for race in range(2):
        o = TP_STRIDE * race
        a1, r, thrust, back = tp[o + TP_A1], tp[o + TP_R], tp[o + TP_THRUST], tp[o + TP_BACK]
        worst = 0.0
        ball = -1
        for j in range(loads.shape[1]):
            Q = loads[load_row + race, j]
            if Q > 0.0:
                t = truncated_fraction(a1 * Q ** (1.0 / 3.0), r, angles[angle_row + race, j], thrust, back)
                if t > worst:
                    worst = t
                    ball = j
        tr[TR_INNER + race] = worst
        tr[TR_BALL_INNER + race] = ball
