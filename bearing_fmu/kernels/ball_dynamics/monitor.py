"""Stability monitor and time-step limit of the DEM.

Explicit integration of stiff contacts is stable below 2/omega_n of the stiffest oscillator; the
tangential spring, lengthened by the predicted velocity, only below sqrt(2)/omega_t (critical_time_step),
beyond which it chatters against its Coulomb limit (docs/reports/dem_error.md). critical_time_step
estimates the limit from the contact loads; the monitor stops a run on a non-finite force, a
penetration beyond the physical limit, kinetic energy beyond the bound of the inputs, or chatter.
"""

import math

from bearing_fmu_common.jit import kernel

from .state import (
    B_VX,
    B_WX,
    C_VX,
    P_I_BALL,
    P_K_CB,
    P_KH_I,
    P_KH_O,
    P_KT_RATIO,
    P_M_BALL,
    P_M_CAGE,
    P_M_RING,
    P_ZETA_CAGE,
    R_VX,
)


@kernel
def critical_time_step(par, Q_inner, Q_outer, Q_cage):
    """Stability limit (s) of velocity Verlet for the stiffest contact pair at the given loads (N).

    Q_inner, Q_outer: float64[Z] ball-race loads; Q_cage: largest ball - cage-ball load.
    - ball squeezed between its two races: omega^2 = (k_i + k_o)/m with the tangent stiffnesses
      k = 1.5 K_h^(2/3) Q^(1/3) (Hertz, Q = K_h delta^1.5);
    - tangential springs of the same ball: k_t = ratio K_h^(2/3) Q^(1/3) per contact; a force at
      the surface moves it at 1/m + (D/2)^2/I = 3.5/m per newton (solid sphere), omega_t^2 = 3.5 k_t/m.
      The spring is lengthened by the predicted velocity v* = v_n + a_n dt (not integrated from positions),
      xi' = xi + v* dt: for F = -k xi this step has trace 2 - 1.5 h^2 and determinant 1 - h^2/2
      (h = omega_t dt), whose eigenvalue passes -1 at h = sqrt(2): the limit is sqrt(2)/omega_t, not
      2/omega_t. Beyond it the slip velocity alternates sign every step (chatter against the Coulomb cap);
    - cage ball between two steel balls, critically damped (ratio zeta): the damped explicit limit
      (2/omega)(sqrt(1 + zeta^2) - zeta), omega^2 = 2 k/m_cage.
    Returns the smallest of 2/omega (squeeze), sqrt(2)/omega_t (springs) and the damped cage limit; inf when
    nothing is loaded.
    """
    m = par[P_M_BALL]
    s_max = 0.0  # largest K_i^(2/3) Q_i^(1/3) + K_o^(2/3) Q_o^(1/3) of a ball
    ki_c = par[P_KH_I] ** (2.0 / 3.0)
    ko_c = par[P_KH_O] ** (2.0 / 3.0)
    for j in range(Q_inner.shape[0]):
        si = ki_c * max(Q_inner[j], 0.0) ** (1.0 / 3.0)
        so = ko_c * max(Q_outer[j], 0.0) ** (1.0 / 3.0)
        s_max = max(s_max, si + so)
    dt = math.inf
    if s_max > 0.0:
        dt = min(2.0 / math.sqrt(1.5 * s_max / m), math.sqrt(2.0) / math.sqrt(3.5 * par[P_KT_RATIO] * s_max / m))
    if Q_cage > 0.0:
        k_c = 1.5 * par[P_K_CB] ** (2.0 / 3.0) * Q_cage ** (1.0 / 3.0)
        zeta = par[P_ZETA_CAGE]
        dt_c = 2.0 / math.sqrt(2.0 * k_c / par[P_M_CAGE]) * (math.sqrt(1.0 + zeta * zeta) - zeta)
        dt = min(dt, dt_c)
    return dt


@kernel
def kinetic_energy(balls, cage, ring, par):
    """Kinetic energy (J) of the balls (translation and rotation), cage balls and inner-ring translation
    (the ring's prescribed rotation is left out: it is an input)."""
    e = 0.0
    for j in range(balls.shape[1]):
        v2 = balls[B_VX, j] ** 2 + balls[B_VX + 1, j] ** 2 + balls[B_VX + 2, j] ** 2
        w2 = balls[B_WX, j] ** 2 + balls[B_WX + 1, j] ** 2 + balls[B_WX + 2, j] ** 2
        c2 = cage[C_VX, j] ** 2 + cage[C_VX + 1, j] ** 2 + cage[C_VX + 2, j] ** 2
        e += 0.5 * (par[P_M_BALL] * v2 + par[P_I_BALL] * w2 + par[P_M_CAGE] * c2)
    e += 0.5 * par[P_M_RING] * (ring[R_VX] ** 2 + ring[R_VX + 1] ** 2 + ring[R_VX + 2] ** 2)
    return e
