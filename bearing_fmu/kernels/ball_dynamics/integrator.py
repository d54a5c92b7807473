"""Velocity-Verlet integration of the DEM and advance(): all steps of an interval in one jitted call.

Velocity Verlet (Guessasma & Machado 2018, eq. 10) with the velocity-dependent forces (normal
damping, tangential spring increments, resistance directions) evaluated with the first-order
predictor v* = v_n + a_n dt at the new positions:
  x_{n+1} = x_n + v_n dt + a_n dt^2/2,  a_{n+1} = F(x_{n+1}, v*)/m,  v_{n+1} = v_n + (a_n + a_{n+1}) dt/2,
and the same for the ball angular velocities (spheres: I dw/dt = M, no gyroscopic term) and the
inner-ring translation. The inner ring's rotation is prescribed: omega goes linearly from omega0 to
omega1 over the call (a ramp is a sequence of calls). The tribology (film, Lambda, mu, C_n,
capacitance, Houpert resistances) is refreshed from the state at the start of every N-th step.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel

from ..lubricant import LUB_EPS_R0, clausius_mossotti_constant, lubricant_state
from .cage import ball_cage_contact, cage_guide_contact
from .contacts import ball_race_contact
from .monitor import kinetic_energy
from .state import (
    A_DISS_I,
    A_DISS_O,
    A_FR,
    A_VR,
    B_ALX,
    B_AX,
    B_ORBIT,
    B_VX,
    B_WX,
    B_X,
    C_AX,
    C_VX,
    C_X,
    K_STEP,
    P_CHATTER,
    P_D,
    P_DELTA_LIM_I,
    P_I_BALL,
    P_KH_I,
    P_M_BALL,
    P_M_CAGE,
    P_M_RING,
    P_R_CAGE,
    P_REFRESH,
    P_RG_I,
    P_V_REG,
    R_AX,
    R_TIME,
    R_VX,
    R_X,
    ST_CODE,
    ST_INDEX,
    ST_STEP,
    STATUS_CHATTER,
    STATUS_ENERGY,
    STATUS_NOT_FINITE,
    STATUS_OK,
    STATUS_PENETRATION,
    T_P_FILM,
    W_FB,
    W_FC,
    W_MB,
    W_ORBIT,
    W_VB,
    W_VC,
    W_WB,
)
from .tribology import TC_SIZE, race_circle, refresh_contact, tribology_constants


@kernel
def compute_forces(balls, cage, ring, spring, trib, counters, par, omega, F_x, F_y, F_z, work, acc, dt):
    """Forces and moments at the current positions with the predicted velocities in work/acc.

    Fills work[W_FB..], work[W_MB..], work[W_FC..] (N, N.m) and acc[A_FR..] (N, applied loads F_x,
    F_y, F_z included). Returns (worst penetration ratio, its contact, longest chatter, its contact,
    sum of the force components): the last is non-finite as soon as any force is.
    """
    Z = balls.shape[1]
    for r in range(W_FB, W_FC + 3):
        for j in range(Z):
            work[r, j] = 0.0
    acc[A_FR] = F_x
    acc[A_FR + 1] = F_y
    acc[A_FR + 2] = F_z
    worst_pen = 0.0
    worst_pen_at = -1
    worst_chat = 0
    worst_chat_at = -1
    R_sum = 0.5 * par[P_D] + par[P_R_CAGE]
    rate_inv = 4.0 * dt / par[P_I_BALL]
    w_reg = 2.0 * par[P_V_REG] / par[P_D]
    for race in range(2):
        cx, cy, cz, rho = race_circle(race, ring, par)
        inv_lim = 1.0 / par[P_DELTA_LIM_I + race]
        for j in range(Z):
            pen, chat = ball_race_contact(
                race,
                j,
                omega,
                rho,
                cx,
                cy,
                cz,
                par[P_RG_I + race],
                par[P_KH_I + race],
                inv_lim,
                rate_inv,
                w_reg,
                balls,
                ring,
                spring,
                trib,
                counters,
                par,
                work,
                acc,
                dt,
            )
            if pen > worst_pen:
                worst_pen = pen
                worst_pen_at = race * Z + j
            if chat > worst_chat:
                worst_chat = chat
                worst_chat_at = race * Z + j
    for k in range(Z):
        # cage ball k sits between steel balls k and k + 1
        ball_cage_contact(k, k, balls, cage, par, work, R_sum)
        ball_cage_contact((k + 1) % Z, k, balls, cage, par, work, R_sum)
        cage_guide_contact(k, cage, par, work)
    # a NaN or inf anywhere (positions, velocities, springs) reaches the contact forces within a step;
    # the moments follow from the same quantities
    total = acc[A_FR] + acc[A_FR + 1] + acc[A_FR + 2]
    for j in range(Z):
        total += work[W_FB, j] + work[W_FB + 1, j] + work[W_FB + 2, j] + work[W_FC, j] + work[W_FC + 1, j]
        total += work[W_FC + 2, j]
    return worst_pen, worst_pen_at, worst_chat, worst_chat_at, total


@kernel
def refresh_tribology(omega, eta, xi, K_cm, rho0, balls, ring, par, trib, tc):
    """Refresh the tribology of every ball-race contact from the current state (tc: tribology_constants)."""
    for race in range(2):
        for j in range(balls.shape[1]):
            refresh_contact(race, j, omega, eta, xi, K_cm, rho0, balls, ring, par, trib, tc)


@kernel
def verlet_step(balls, cage, ring, spring, trib, counters, par, omega, F_x, F_y, F_z, dt, work, acc):
    """One velocity-Verlet step of every body (see the module docstring). Returns compute_forces' tuple."""
    Z = balls.shape[1]
    h = 0.5 * dt * dt
    for j in range(Z):
        x0 = balls[B_X, j]
        y0 = balls[B_X + 1, j]
        for i in range(3):
            a = balls[B_AX + i, j]
            v = balls[B_VX + i, j]
            balls[B_X + i, j] += v * dt + a * h
            work[W_VB + i, j] = v + a * dt
            work[W_WB + i, j] = balls[B_WX + i, j] + balls[B_ALX + i, j] * dt
            a = cage[C_AX + i, j]
            v = cage[C_VX + i, j]
            cage[C_X + i, j] += v * dt + a * h
            work[W_VC + i, j] = v + a * dt
        # orbital angle: the step's rotation is tiny, so atan(cross/dot) = cross/dot to O(angle^3)
        x1 = balls[B_X, j]
        y1 = balls[B_X + 1, j]
        balls[B_ORBIT, j] += (x0 * y1 - y0 * x1) / (x0 * x1 + y0 * y1)
        # orbital speed of the contact frame, for the rolling resistance
        work[W_ORBIT, j] = (x1 * work[W_VB + 1, j] - y1 * work[W_VB, j]) / (x1 * x1 + y1 * y1)
    for i in range(3):
        ring[R_X + i] += ring[R_VX + i] * dt + ring[R_AX + i] * h
        acc[A_VR + i] = ring[R_VX + i] + ring[R_AX + i] * dt
    result = compute_forces(balls, cage, ring, spring, trib, counters, par, omega, F_x, F_y, F_z, work, acc, dt)
    half = 0.5 * dt
    inv_m = 1.0 / par[P_M_BALL]
    inv_i = 1.0 / par[P_I_BALL]
    inv_c = 1.0 / par[P_M_CAGE]
    for j in range(Z):
        for i in range(3):
            a = work[W_FB + i, j] * inv_m
            balls[B_VX + i, j] += (balls[B_AX + i, j] + a) * half
            balls[B_AX + i, j] = a
            a = work[W_MB + i, j] * inv_i
            balls[B_WX + i, j] += (balls[B_ALX + i, j] + a) * half
            balls[B_ALX + i, j] = a
            a = work[W_FC + i, j] * inv_c
            cage[C_VX + i, j] += (cage[C_AX + i, j] + a) * half
            cage[C_AX + i, j] = a
    inv_r = 1.0 / par[P_M_RING]
    for i in range(3):
        a = acc[A_FR + i] * inv_r
        ring[R_VX + i] += (ring[R_AX + i] + a) * half
        ring[R_AX + i] = a
    ring[R_TIME] += dt
    counters[K_STEP] += 1
    return result


@kernel
def initialise_accelerations(
    balls, cage, ring, spring, trib, counters, par, lub, omega, F_x, F_y, F_z, T_oil, work, acc
):
    """Tribology and accelerations of a new state (the a_n that the first Verlet step needs), without
    moving anything: call once after the facade sets positions and velocities."""
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], rho0)
    tc = np.empty((TC_SIZE, 2))
    tribology_constants(par, eta, xi, tc)
    refresh_tribology(omega, eta, xi, K_cm, rho0, balls, ring, par, trib, tc)
    Z = balls.shape[1]
    saved = spring.copy()
    for j in range(Z):
        for i in range(3):
            work[W_VB + i, j] = balls[B_VX + i, j]
            work[W_WB + i, j] = balls[B_WX + i, j]
            work[W_VC + i, j] = cage[C_VX + i, j]
        x = balls[B_X, j]
        y = balls[B_X + 1, j]
        work[W_ORBIT, j] = (x * work[W_VB + 1, j] - y * work[W_VB, j]) / (x * x + y * y)
    for i in range(3):
        acc[A_VR + i] = ring[R_VX + i]
    compute_forces(balls, cage, ring, spring, trib, counters, par, omega, F_x, F_y, F_z, work, acc, 0.0)
    spring[:, :] = saved  # a zero-length step leaves the springs as they were
    for j in range(Z):
        for i in range(3):
            balls[B_AX + i, j] = work[W_FB + i, j] / par[P_M_BALL]
            balls[B_ALX + i, j] = work[W_MB + i, j] / par[P_I_BALL]
            cage[C_AX + i, j] = work[W_FC + i, j] / par[P_M_CAGE]
    for i in range(3):
        ring[R_AX + i] = acc[A_FR + i] / par[P_M_RING]


@kernel
def advance(
    balls,
    cage,
    ring,
    spring,
    trib,
    counters,
    par,
    lub,
    n_steps,
    dt,
    omega0,
    omega1,
    F_x,
    F_y,
    F_z,
    T_oil,
    energy_limit,
    work,
    acc,
    status,
):
    """Run n_steps steps of dt (s) with the inner-ring speed going linearly from omega0 to omega1 (rad/s),
    constant loads F_x, F_y, F_z (N) on the inner ring and oil temperature T_oil (K).

    Stops early with status[ST_CODE] != STATUS_OK (monitor) after the offending step; status[ST_STEP]
    holds the steps done, status[ST_INDEX] the ball or contact (race * Z + ball). energy_limit (J)
    bounds the kinetic energy (checked at each tribology refresh). acc[A_DISS_I], acc[A_DISS_O]
    receive the energy (J) dissipated in the inner and outer contacts during the call.
    """
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], rho0)
    tc = np.empty((TC_SIZE, 2))
    tribology_constants(par, eta, xi, tc)
    Z = balls.shape[1]
    refresh = max(int(par[P_REFRESH]), 1)
    chatter_limit = int(par[P_CHATTER])
    acc[A_DISS_I] = 0.0
    acc[A_DISS_O] = 0.0
    status[ST_CODE] = STATUS_OK
    status[ST_STEP] = 0
    status[ST_INDEX] = -1
    # the film's own losses (Houpert) per race, constant between two refreshes
    film_i = 0.0
    film_o = 0.0
    for j in range(Z):
        film_i += trib[T_P_FILM, 0, j]
        film_o += trib[T_P_FILM, 1, j]
    d_omega = (omega1 - omega0) / n_steps
    # steps until the next refresh (the phase carries over between calls through the step counter)
    countdown = (refresh - counters[K_STEP] % refresh) % refresh
    for n in range(n_steps):
        if countdown == 0:
            countdown = refresh
            refresh_tribology(omega0 + d_omega * n, eta, xi, K_cm, rho0, balls, ring, par, trib, tc)
            film_i = 0.0
            film_o = 0.0
            for j in range(Z):
                film_i += trib[T_P_FILM, 0, j]
                film_o += trib[T_P_FILM, 1, j]
            if kinetic_energy(balls, cage, ring, par) > energy_limit:
                status[ST_CODE] = STATUS_ENERGY
                status[ST_STEP] = n
                return
        countdown -= 1
        omega = omega0 + d_omega * (n + 1)
        pen, pen_at, chat, chat_at, total = verlet_step(
            balls, cage, ring, spring, trib, counters, par, omega, F_x, F_y, F_z, dt, work, acc
        )
        acc[A_DISS_I] += film_i * dt
        acc[A_DISS_O] += film_o * dt
        status[ST_STEP] = n + 1
        if not math.isfinite(total):
            status[ST_CODE] = STATUS_NOT_FINITE
            return
        if pen > 1.0:
            status[ST_CODE] = STATUS_PENETRATION
            status[ST_INDEX] = pen_at
            return
        if chat >= chatter_limit:
            status[ST_CODE] = STATUS_CHATTER
            status[ST_INDEX] = chat_at
            return
