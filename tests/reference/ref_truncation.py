"""Twin of bearing_fmu.kernels.truncation: the shoulder truncation of a contact ellipse, by plane geometry.

Written from the definitions, not from the kernel's closed forms: in the ball's (axial, radial) plane the groove
is the circle of radius r about the groove-curvature centre C; points are 2-vectors (axial, radial) from C.
- shoulder angle: the groove point whose radius from the bearing axis equals the land radius, found by root
  finding (scipy brentq) along the groove from its bottom;
- truncated fraction: the contact centre P = C + r n(alpha) (n pointing from C to the groove surface), the
  tangent t at P across the rolling direction; the Hertz major axis is the segment P +- a t. The groove between
  the contact centre and a shoulder edge reaches along t at most max (X - P).t over that arc (scipy
  minimize_scalar, bounded); the part of the segment beyond that reach, in units of a, clipped to [0, 2];
- per race: the largest fraction over the loaded contacts and its ball (the first of equals).
"""

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

KERNEL_MODULE = "bearing_fmu.kernels.truncation"
TR_INNER, TR_OUTER, TR_BALL_INNER, TR_BALL_OUTER = 0, 1, 2, 3
TP_A1, TP_R, TP_THRUST, TP_BACK, TP_STRIDE = 0, 1, 2, 3, 4


def _groove_point(r, phi, race):
    """(axial, radial) of the groove point at angle phi from the groove bottom, from C: the inner groove lies
    radially inside its centre, the outer one outside."""
    return np.array([r * math.sin(phi), -r * math.cos(phi) if race == 0 else r * math.cos(phi)])


def shoulder_angle(centre_radius, groove_radius, shoulder_diameter, race):
    """The angle from the groove bottom at which the groove reaches the land radius (0: land at or below the
    bottom)."""

    def height(phi):  # radius of the groove point from the bearing axis, less the land radius
        return centre_radius + _groove_point(groove_radius, phi, race)[1] - 0.5 * shoulder_diameter

    bottom, top = height(0.0), height(math.pi)
    if (bottom >= 0.0) if race == 0 else (bottom <= 0.0):  # the land at or below the groove bottom
        return 0.0
    if bottom * top > 0.0:  # the groove never reaches the land: the edge is the groove's far end
        return math.pi
    return brentq(height, 0.0, math.pi, xtol=1e-15, rtol=8.9e-16)


def _along(r, P, t, phi):
    """Distance (m) along the tangent t from the contact centre P of the groove point at angle phi."""
    return float(np.dot(_groove_point(r, phi, 0) - P, t))


def _extreme(r, P, t, low, high, largest):
    """Largest (or smallest) _along over the groove arc [low, high] (rad): bounded search and both ends."""
    sign = -1.0 if largest else 1.0
    res = minimize_scalar(
        lambda phi: sign * _along(r, P, t, phi), bounds=(low, high), method="bounded", options={"xatol": 1e-13}
    )
    values = (sign * res.fun, _along(r, P, t, low), _along(r, P, t, high))
    return max(values) if largest else min(values)


def truncated_fraction(a, r, alpha, thrust, back):
    """Fraction of the major axis (in semi-axes a) beyond the shoulder edges at +thrust and -back (rad). The
    distances along the tangent do not depend on the ring: the inner ring's groove is used for both."""
    P = _groove_point(r, alpha, 0)
    fractions = []
    for edge_angle, side in ((thrust, 1.0), (-back, -1.0)):
        t = side * np.array([math.cos(alpha), math.sin(alpha)])  # tangent toward the edge's side
        low, high = sorted((alpha, edge_angle))
        if side * (edge_angle - alpha) >= 0.0:  # the edge ahead: the farthest the groove reaches before it
            s = _extreme(r, P, t, low, high, largest=True) if high > low else 0.0
        else:  # the contact centre already past the edge: the groove ends this far behind the centre
            s = _extreme(r, P, t, low, high, largest=False)
        fractions.append((a - s) / a)
    return min(max(0.0, *fractions), 2.0)


def race_truncation(loads, load_row, angles, angle_row, tp, tr):
    """Per race: the largest truncated fraction over the loaded contacts, and its ball (first of equals; -1)."""
    for race in range(2):
        o = TP_STRIDE * race
        found = []
        for j in range(loads.shape[1]):
            Q = loads[load_row + race, j]
            if Q > 0.0:
                a = tp[o + TP_A1] * Q ** (1.0 / 3.0)
                t = truncated_fraction(a, tp[o + TP_R], angles[angle_row + race, j], tp[o + TP_THRUST], tp[o + TP_BACK])
                if t > 0.0:
                    found.append((t, -j))
        t, minus_j = max(found) if found else (0.0, 1)
        tr[TR_INNER + race] = t
        tr[TR_BALL_INNER + race] = -minus_j


TWINS = {
    "shoulder_angle": shoulder_angle,
    "truncated_fraction": truncated_fraction,
    "race_truncation": race_truncation,
}
