"""The cage of Guessasma & Machado (2018) and Farah et al. (2020): Z PA66 cage balls between the steel
balls, guided on the pitch circle.

Guessasma & Machado (2018) and Farah et al. (2020) replace the cage by Z small PA66 balls (radius
R_z) that sit between the steel balls and run between two coaxial toruses. Their contacts are
frictionless and critically damped; the steel ball - cage ball law is Hertz sphere-sphere,
Q = (4/3) E* sqrt(R_eq) delta^1.5 with 1/E* = (1 - nu^2)/E + (1 - nu_c^2)/E_c and
R_eq = R_b R_z/(R_b + R_z) (Johnson 1985, Contact Mechanics, eq. 4.22; the two papers' printed
variants disagree with each other and with Hertz, so Hertz is used).

The papers give neither the toruses' dimensions nor their contact law. Here the two toruses are the
walls of the toroidal channel they bound: a cage ball touches them when its centre leaves the
channel's centre circle (the balls' pitch circle at rest) by more than a radial play; the approach
is that distance minus the play and the normal points from the circle to the cage-ball centre.
Its stiffness is Hertz sphere-on-plane (R_eq = R_z, steel/PA66 E*): an estimate, the channel
only has to hold the cage balls on the pitch circle. Critical damping of a contact of tangent
stiffness k = 1.5 K sqrt(delta) and reduced mass m_eff is c = 2 zeta sqrt(k m_eff), zeta = 1.
"""

import math

from bearing_fmu_common.jit import kernel


@kernel(inline="always")
def damped_hertz(K, c0, delta, v_approach):
    """Normal force (N, >= 0) of a damped Hertz contact: K delta^1.5 + c v_approach, K (N/m^1.5), delta (m),
    v_approach (m/s, > 0 closing). The damping c = 2 zeta sqrt(k m_eff) of the tangent stiffness
    k = 1.5 K sqrt(delta) is c0 delta^(1/4), c0 = 2 zeta sqrt(1.5 K m_eff) (critical for zeta = 1)."""
    root = math.sqrt(delta)
    f = K * delta * root + c0 * math.sqrt(root) * v_approach
    return f if f > 0.0 else 0.0


@kernel(inline="always")
def ball_cage_contact(dx, dy, dz, dvx, dvy, dvz, R_sum, K, c0):
    """Force (N) on the cage ball of its contact with a steel ball: (dx, dy, dz) = cage-ball centre - ball
    centre (m), (dvx, dvy, dvz) = ball velocity - cage-ball velocity (m/s), R_sum = R_b + R_z (m), K and c0
    as damped_hertz. The steel ball gets the opposite force. Returns (fx, fy, fz); zero when open (most of the
    time: the pockets have play)."""
    d2 = dx * dx + dy * dy + dz * dz
    if d2 >= R_sum * R_sum or d2 == 0.0:
        return 0.0, 0.0, 0.0
    dist = math.sqrt(d2)
    delta = R_sum - dist
    inv = 1.0 / dist
    nx = dx * inv  # from the steel ball to the cage ball
    ny = dy * inv
    nz = dz * inv
    f = damped_hertz(K, c0, delta, dvx * nx + dvy * ny + dvz * nz)
    return f * nx, f * ny, f * nz


@kernel(inline="always")
def cage_guide_contact(px, py, pz, vx, vy, vz, r_guide, z_guide, gap, K, c0):
    """Force (N) on a cage ball at (px, py, pz) (m) moving at v (m/s) from its guide channel (centre circle of
    radius r_guide at height z_guide, radial play gap, m; K and c0 as damped_hertz). Returns (fx, fy, fz)."""
    r = math.sqrt(px * px + py * py)
    if r == 0.0:
        return 0.0, 0.0, 0.0
    # as contact_law.groove_approach: the offset from the circle, (p_xy (r - r_guide)/r, dz), normalised with
    # one division
    radial = r - r_guide
    sz = pz - z_guide
    dist = math.sqrt(radial * radial + sz * sz)
    delta = dist - gap
    if delta <= 0.0:
        return 0.0, 0.0, 0.0
    inv = 1.0 / (r * dist)
    nx = px * radial * inv
    ny = py * radial * inv
    nz = sz * r * inv
    f = damped_hertz(K, c0, delta, vx * nx + vy * ny + vz * nz)
    return -f * nx, -f * ny, -f * nz
