"""The seeds' cage: Z PA66 cage balls between the steel balls, guided on the pitch circle.

Guessasma & Machado (2018) and Farah et al. (2020) replace the cage by Z small PA66 balls (radius
R_z) that sit between the steel balls and run between two coaxial toruses. Their contacts are
frictionless and critically damped; the steel ball - cage ball law is Hertz sphere-sphere,
Q = (4/3) E* sqrt(R_eq) delta^1.5 with 1/E* = (1 - nu^2)/E + (1 - nu_c^2)/E_c and
R_eq = R_b R_z/(R_b + R_z) (Johnson 1985, Contact Mechanics, eq. 4.22; the seeds' two printed
variants disagree with each other and with Hertz, so Hertz is used).

The seeds give neither the toruses' dimensions nor their contact law. Here the two toruses are the
walls of the toroidal channel they bound: a cage ball touches them when its centre leaves the
channel's centre circle (the balls' pitch circle at rest) by more than a radial play; the approach
is that distance minus the play and the normal points from the circle to the cage-ball centre.
Its stiffness is Hertz sphere-on-plane (R_eq = R_z, steel/PA66 E*): an estimate, the channel
only has to hold the cage balls on the pitch circle. Critical damping of a contact of tangent
stiffness k = 1.5 K sqrt(delta) and reduced mass m_eff is c = 2 zeta sqrt(k m_eff), zeta = 1.
"""
import math

from bearing_fmu_common.jit import kernel

from .state import (B_X, C_X, P_GUIDE_GAP, P_K_CB, P_K_GUIDE, P_M_BALL, P_M_CAGE, P_R_GUIDE, P_Z_GUIDE, P_ZETA_CAGE,
                    W_FB, W_FC, W_VB, W_VC)


@kernel
def damped_hertz(K, delta, zeta, m_eff, v_approach):
    """Normal force (N, >= 0) of a critically damped Hertz contact: K delta^1.5 + c v_approach with
    c = 2 zeta sqrt(1.5 K sqrt(delta) m_eff); K (N/m^1.5), delta (m), m_eff (kg), v_approach (m/s,
    > 0 closing)."""
    root = math.sqrt(delta)
    c = 2.0 * zeta * math.sqrt(1.5 * K * root * m_eff)
    f = K * delta * root + c * v_approach
    return f if f > 0.0 else 0.0


@kernel
def ball_cage_contact(j, k, balls, cage, par, work, R_sum):
    """Contact of steel ball j with cage ball k; forces added to work (N). R_sum = R_b + R_z (m).
    Returns the contact load (N, 0 if open)."""
    dx = cage[C_X, k] - balls[B_X, j]
    dy = cage[C_X + 1, k] - balls[B_X + 1, j]
    dz = cage[C_X + 2, k] - balls[B_X + 2, j]
    dist = math.sqrt(dx * dx + dy * dy + dz * dz)
    delta = R_sum - dist
    if delta <= 0.0 or dist == 0.0:
        return 0.0
    nx = dx / dist  # from the steel ball to the cage ball
    ny = dy / dist
    nz = dz / dist
    v_app = ((work[W_VB, j] - work[W_VC, k]) * nx + (work[W_VB + 1, j] - work[W_VC + 1, k]) * ny
             + (work[W_VB + 2, j] - work[W_VC + 2, k]) * nz)
    m_b = par[P_M_BALL]
    m_c = par[P_M_CAGE]
    f = damped_hertz(par[P_K_CB], delta, par[P_ZETA_CAGE], m_b * m_c / (m_b + m_c), v_app)
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
    R = par[P_R_GUIDE]
    sx = px - R * px / r
    sy = py - R * py / r
    sz = cage[C_X + 2, k] - par[P_Z_GUIDE]
    dist = math.sqrt(sx * sx + sy * sy + sz * sz)
    delta = dist - par[P_GUIDE_GAP]
    if delta <= 0.0:
        return 0.0
    nx = sx / dist
    ny = sy / dist
    nz = sz / dist
    v_app = work[W_VC, k] * nx + work[W_VC + 1, k] * ny + work[W_VC + 2, k] * nz
    f = damped_hertz(par[P_K_GUIDE], delta, par[P_ZETA_CAGE], par[P_M_CAGE], v_app)
    work[W_FC, k] -= f * nx
    work[W_FC + 1, k] -= f * ny
    work[W_FC + 2, k] -= f * nz
    return f
