"""Stability monitor and time-step limit of the DEM.

Explicit integration of stiff contacts is stable below 2/omega_n of the stiffest oscillator; the
tangential spring chatters against its Coulomb limit below that (the 6208 at 3 kN, 500 rad/s goes
unstable at about 9 us and chatters from about 7 us, docs/reports/dem_error.md). critical_time_step
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
      the surface moves it at 1/m + (D/2)^2/I = 3.5/m per newton (solid sphere);
    - cage ball between two steel balls, critically damped (ratio zeta): the damped explicit limit
      (2/omega)(sqrt(1 + zeta^2) - zeta), omega^2 = 2 k/m_cage.
    Returns 2/omega_max (with the damped cage factor); inf when nothing is loaded.
    """
    m = par[P_M_BALL]
    w2_max = 0.0
    ki_c = par[P_KH_I] ** (2.0 / 3.0)
    ko_c = par[P_KH_O] ** (2.0 / 3.0)
    for j in range(Q_inner.shape[0]):
        si = ki_c * max(Q_inner[j], 0.0) ** (1.0 / 3.0)
        so = ko_c * max(Q_outer[j], 0.0) ** (1.0 / 3.0)
        w2_max = max(w2_max, 1.5 * (si + so) / m, 3.5 * par[P_KT_RATIO] * (si + so) / m)
    dt = 2.0 / math.sqrt(w2_max) if w2_max > 0.0 else math.inf
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
