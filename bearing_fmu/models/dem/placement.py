"""Where the DEM's bodies start: each ball at rest in its groove pair, each cage ball half a pitch ahead of its ball
on the guide circle, the inner ring centred, nothing moving."""

import math

from ...kernels.ball_dynamics import state as s
from ...kernels.geometry import ball_direction, free_contact_angle


def ball_rest_position(bearing, Pd, K_inner, K_outer):
    """(radius, z) in m of a ball at rest: on the line from the outer to the inner curvature centre,
    touching the outer groove (with clearance) or sharing the interference as two Hertz contacts of
    constants K_inner, K_outer (N/m^1.5) under one load (preload); Pd the diametral clearance (m)."""
    b = bearing
    D = b.D
    alpha0 = free_contact_angle(D, b.f_i, b.f_o, Pd) if Pd > 0.0 else 0.0
    A = (b.f_i + b.f_o - 1.0) * D
    ax = A * math.sin(alpha0) if b.kind == "angular_contact" else 0.0
    rad = A - 0.5 * Pd
    rho_o = 0.5 * b.dm + (b.f_i - 0.5) * D * math.cos(alpha0) - rad
    L = math.hypot(ax, rad)
    r_o = (b.f_o - 0.5) * D
    interference = A - L
    if interference > 0.0:  # preload: equal loads, delta_o / delta_i = (K_i / K_o)^(2/3)
        share = 1.0 / (1.0 + (K_outer / K_inner) ** (2.0 / 3.0))
        r_o -= interference * share
    return rho_o + r_o * rad / L, r_o * ax / L


def place_bodies(balls, cage, ring, spring, trib, counters, par, rest):
    """Reset the state arrays to the bodies at rest: the balls at `rest` (ball_rest_position), ball 1 on +y
    (docs/conventions.md), the cage balls on the guide circle of par, the ring centred, springs and counters zero."""
    Z = balls.shape[1]
    for arr in (balls, cage, spring, trib):
        arr[...] = 0.0
    ring[:] = 0.0
    counters[:] = 0
    for j in range(Z):
        r, z = rest
        c, sn = ball_direction(j, Z)  # ball 1 on +y (docs/conventions.md)
        balls[s.B_X : s.B_X + 3, j] = (r * c, r * sn, z)
        c, sn = ball_direction(j + 0.5, Z)  # the cage ball half a pitch ahead
        R = par[s.P_R_GUIDE]
        cage[s.C_X : s.C_X + 3, j] = (R * c, R * sn, par[s.P_Z_GUIDE])
