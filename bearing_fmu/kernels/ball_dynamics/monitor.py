"""Stability monitor and time-step limit of the DEM.

Explicit integration of stiff contacts is stable below 2/omega_n of the stiffest oscillator; the
tangential spring, lengthened by the predicted velocity, only below sqrt(2)/omega_t (critical_time_step),
beyond which it chatters against its Coulomb limit (docs/reports/dem_steps.md). critical_time_step
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
    P_I_RING,
    P_K_CB,
    P_KH_I,
    P_KH_O,
    P_KT_RATIO,
    P_M_BALL,
    P_M_CAGE,
    P_M_RING,
    P_ZETA_CAGE,
    R_VTH,
    R_VX,
    T_C_N,
    T_Q,
)


@kernel(inline="always")
def damped_limit(omega, zeta):
    """Stability limit (s) of this integrator for an oscillator of natural frequency omega (rad/s) and damping
    ratio zeta whose damping force is evaluated with the predicted velocity v* = v_n + a_n dt:
    (2/omega)(sqrt(1 + 4 zeta^2) - 2 zeta). (The amplification matrix of (x, v, a) has an eigenvalue -1 at
    h = omega dt with h^2/4 + 2 zeta h - 1 = 0 (h = 2 for zeta = 0); the central-difference bound
    (2/omega)(sqrt(1 + zeta^2) - zeta) overestimates it, by 1.75x at zeta = 1.) Written as
    (2/omega) / (sqrt(1 + 4 zeta^2) + 2 zeta), the same value without the cancellation that gives 0 for a heavily
    overdamped pair (zeta ~ 1e8 and beyond: a contact touching with a rounding-level load), where it tends to
    m / c."""
    return 2.0 / omega / (math.sqrt(1.0 + 4.0 * zeta * zeta) + 2.0 * zeta)


@kernel
def critical_time_step(par, Q_inner, Q_outer, C_inner, C_outer, Q_cage):
    """Stability limit (s) of velocity Verlet for the stiffest contact pair at the given loads (N).

    Q_inner, Q_outer: float64[Z] ball-race loads; C_inner, C_outer: float64[Z] their normal damping (N.s/m,
    C_n(Lambda) of the last tribology refresh); Q_cage: largest ball - cage-ball load.
    - ball squeezed between its two races: omega^2 = (k_i + k_o)/m with the tangent stiffnesses
      k = 1.5 K_h^(2/3) Q^(1/3) (Hertz, Q = K_h delta^1.5), damping ratio zeta = (c_i + c_o)/(2 sqrt(k m))
      of its loaded contacts (a full film's squeeze damping can make it overdamped at low speed), limit
      damped_limit(omega, zeta);
    - tangential springs of the same ball: k_t = ratio K_h^(2/3) Q^(1/3) per contact; a force at
      the surface moves it at 1/m + (D/2)^2/I = 3.5/m per newton (solid sphere), omega_t^2 = 3.5 k_t/m.
      The spring is lengthened by the predicted velocity v* = v_n + a_n dt (not integrated from positions),
      xi' = xi + v* dt: for F = -k xi this step has trace 2 - 1.5 h^2 and determinant 1 - h^2/2
      (h = omega_t dt), whose eigenvalue passes -1 at h = sqrt(2): the limit is sqrt(2)/omega_t, not
      2/omega_t. Beyond it the slip velocity alternates sign every step (chatter against the Coulomb cap);
    - cage ball against a steel ball: omega^2 = k/m_eff with the reduced mass m_eff, damping ratio zeta_c
      (critical, c = 2 zeta_c sqrt(k m_eff)); limit damped_limit(omega, zeta_c). The pocket play lets a cage
      ball touch one steel ball at a time: a cage ball jammed between both (omega^2 = 2 k/m_cage, zeta =
      sqrt(2 m_eff/m_cage) zeta_c) would need about half of it, which the monitor catches (the facade's
      automatic step then repeats the call with half the step).
    Returns the smallest of the three; inf when nothing is loaded.
    """
    m = par[P_M_BALL]
    ki_c = 1.5 * par[P_KH_I] ** (2.0 / 3.0)
    ko_c = 1.5 * par[P_KH_O] ** (2.0 / 3.0)
    tangential = par[P_KT_RATIO] / 1.5 * 3.5  # omega_t^2 m / k_squeeze
    dt = math.inf
    for j in range(Q_inner.shape[0]):
        k = 0.0
        c = 0.0
        if Q_inner[j] > 0.0:
            k += ki_c * Q_inner[j] ** (1.0 / 3.0)
            c += C_inner[j]
        if Q_outer[j] > 0.0:
            k += ko_c * Q_outer[j] ** (1.0 / 3.0)
            c += C_outer[j]
        if k > 0.0:
            omega = math.sqrt(k / m)
            zeta = c / (2.0 * math.sqrt(k * m))
            dt = min(dt, damped_limit(omega, zeta), math.sqrt(2.0) / (omega * math.sqrt(tangential)))
    if Q_cage > 0.0:
        k_c = 1.5 * par[P_K_CB] ** (2.0 / 3.0) * Q_cage ** (1.0 / 3.0)
        m_eff = m * par[P_M_CAGE] / (m + par[P_M_CAGE])
        dt = min(dt, damped_limit(math.sqrt(k_c / m_eff), par[P_ZETA_CAGE]))
    return dt


@kernel(inline="always")  # called once per refresh from advance: no array-passing call
def kinetic_energy(balls, cage, ring, par):
    """Kinetic energy (J) of the balls (translation and rotation), cage balls and inner-ring translation and tilt
    rates (the ring's prescribed rotation about its axis is left out: it is an input)."""
    e = 0.0
    for j in range(balls.shape[1]):
        v2 = balls[B_VX, j] ** 2 + balls[B_VX + 1, j] ** 2 + balls[B_VX + 2, j] ** 2
        w2 = balls[B_WX, j] ** 2 + balls[B_WX + 1, j] ** 2 + balls[B_WX + 2, j] ** 2
        c2 = cage[C_VX, j] ** 2 + cage[C_VX + 1, j] ** 2 + cage[C_VX + 2, j] ** 2
        e += 0.5 * (par[P_M_BALL] * v2 + par[P_I_BALL] * w2 + par[P_M_CAGE] * c2)
    e += 0.5 * par[P_M_RING] * (ring[R_VX] ** 2 + ring[R_VX + 1] ** 2 + ring[R_VX + 2] ** 2)
    e += 0.5 * par[P_I_RING] * (ring[R_VTH] ** 2 + ring[R_VTH + 1] ** 2)
    return e


@kernel(inline="always")  # called once per refresh from advance: no array-passing call
def damping_step_ratio(trib, par, dt):
    """Largest (c_i + c_o) dt / m over the balls, and its ball: the normal damping (N.s/m, of the loaded
    contacts at the last tribology refresh) of a ball times the step dt (s) over its mass. A pure damper
    integrated with the predicted velocity is stable below 1; the overdamped squeeze film of a full film at low
    speed (C_n of thousands of N.s/m) integrates correctly up to about 0.43 and gives a spurious dissipation
    from about 0.48 (B7214C at 10 rad/s, docs/dem.md): the monitor stops above par[P_DAMPING_STOP]."""
    worst = 0.0
    at = -1
    scale = dt / par[P_M_BALL]
    for j in range(trib.shape[2]):
        c = 0.0
        if trib[T_Q, 0, j] > 0.0:
            c += trib[T_C_N, 0, j]
        if trib[T_Q, 1, j] > 0.0:
            c += trib[T_C_N, 1, j]
        if c * scale > worst:
            worst = c * scale
            at = j
    return worst, at
