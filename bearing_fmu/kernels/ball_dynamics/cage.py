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

from .state import (
    B_X,
    C_X,
    P_C_CB,
    P_C_GUIDE,
    P_GUIDE_GAP,
    P_K_CB,
    P_K_GUIDE,
    P_R_GUIDE,
    P_Z_GUIDE,
    W_FB,
    W_FC,
    W_VB,
    W_VC,
)


@kernel
def damped_hertz(K, c0, delta, v_approach):
    """Normal force (N, >= 0) of a damped Hertz contact: K delta^1.5 + c v_approach, K (N/m^1.5), delta (m),
    v_approach (m/s, > 0 closing). The damping c = 2 zeta sqrt(k m_eff) of the tangent stiffness
    k = 1.5 K sqrt(delta) is c0 delta^(1/4), c0 = 2 zeta sqrt(1.5 K m_eff) (critical for zeta = 1)."""
    root = math.sqrt(delta)
    f = K * delta * root + c0 * math.sqrt(root) * v_approach
    return f if f > 0.0 else 0.0


@kernel
def ball_cage_contact(j, k, balls, cage, par, work, R_sum):
    """Contact of steel ball j with cage ball k; forces added to work (N). R_sum = R_b + R_z (m).
    Returns the contact load (N, 0 if open)."""
    dx = cage[C_X, k] - balls[B_X, j]
    dy = cage[C_X + 1, k] - balls[B_X + 1, j]
    dz = cage[C_X + 2, k] - balls[B_X + 2, j]
    d2 = dx * dx + dy * dy + dz * dz
    if d2 >= R_sum * R_sum or d2 == 0.0:  # open (most of the time: the pockets have play)
        return 0.0
    dist = math.sqrt(d2)
    delta = R_sum - dist
    inv = 1.0 / dist
    nx = dx * inv  # from the steel ball to the cage ball
    ny = dy * inv
    nz = dz * inv
    v_app = (
        (work[W_VB, j] - work[W_VC, k]) * nx
        + (work[W_VB + 1, j] - work[W_VC + 1, k]) * ny
        + (work[W_VB + 2, j] - work[W_VC + 2, k]) * nz
    )
    f = damped_hertz(par[P_K_CB], par[P_C_CB], delta, v_app)
    work[W_FC, k] += f * nx
    work[W_FC + 1, k] += f * ny
    work[W_FC + 2, k] += f * nz
    work[W_FB, j] -= f * nx
    work[W_FB + 1, j] -= f * ny
    work[W_FB + 2, j] -= f * nz
    return f


@kernel
def cage_guide_contact(k, cage, par, work):
    """Contact of cage ball k with its guide channel; force added to work (N). Returns the load (N)."""
    px = cage[C_X, k]
    py = cage[C_X + 1, k]
    r = math.sqrt(px * px + py * py)
    if r == 0.0:
        return 0.0
    scale = 1.0 - par[P_R_GUIDE] / r
    sx = px * scale
    sy = py * scale
    sz = cage[C_X + 2, k] - par[P_Z_GUIDE]
    dist = math.sqrt(sx * sx + sy * sy + sz * sz)
    delta = dist - par[P_GUIDE_GAP]
    if delta <= 0.0:
        return 0.0
    inv = 1.0 / dist
    nx = sx * inv
    ny = sy * inv
    nz = sz * inv
    v_app = work[W_VC, k] * nx + work[W_VC + 1, k] * ny + work[W_VC + 2, k] * nz
    f = damped_hertz(par[P_K_GUIDE], par[P_C_GUIDE], delta, v_app)
    work[W_FC, k] -= f * nx
    work[W_FC + 1, k] -= f * ny
    work[W_FC + 2, k] -= f * nz
    return f
