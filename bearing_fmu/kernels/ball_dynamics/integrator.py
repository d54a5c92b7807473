"""Velocity-Verlet integration of the DEM and advance(): all steps of an interval in one jitted call.

Velocity Verlet (Guessasma & Machado 2018, eq. 10) with the velocity-dependent forces (normal
damping, tangential spring increments, resistance directions) evaluated with the first-order
predictor v* = v_n + a_n dt at the new positions:
  x_{n+1} = x_n + v_n dt + a_n dt^2/2,  a_{n+1} = F(x_{n+1}, v*)/m,  v_{n+1} = v_n + (a_n + a_{n+1}) dt/2,
and the same for the ball angular velocities (spheres: I dw/dt = M, no gyroscopic term) and the
inner-ring translation and tilts. The inner ring's rotation about its axis is prescribed: omega goes linearly
from omega0 to omega1 over the call (a ramp is a sequence of calls). Its tilts (small rotations about x and y
through its centre) follow I_d dtheta_rate/dt = M_perp + gyroscopic moment: M_perp the part across the ring's
axis of the applied moments and of the contacts' moments about the centre (the drive holds the part along
the axis), the gyroscopic moment -I_p omega (theta_rate x a) of a ring turning at omega whose axis a turns at the
tilt rates (taken, as the damping, at the predicted rates). Or the ring's displacement and tilts are prescribed
(par[P_DRIVE]): they follow a cubic through the values and rates the caller gives at both ends of the call, and the
call integrates the load that holds the ring on that path. The tribology (film, Lambda, mu, C_n,
capacitance, Houpert resistances) is refreshed from the state at the start of every N-th step.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel

from ..capacitance import CAP_ON, ball_capacitance
from ..lubricant import LUB_EPS_R0, LUB_RHO_REF, clausius_mossotti_constant, lubricant_state
from .cage import ball_cage_contact, cage_guide_contact
from .contact_law import ball_race_contact, groove_approach
from .monitor import damping_step_ratio, kinetic_energy
from .state import (
    A_CAP,
    A_DISS_I,
    A_DISS_O,
    A_FR,
    A_MR,
    A_POWER_I,
    A_POWER_O,
    A_REACTION,
    A_RING_SQ,
    A_SIZE,
    A_VR,
    A_WR,
    A_XT,
    B_ALX,
    B_AX,
    B_ORBIT,
    B_VX,
    B_WX,
    B_X,
    C_AX,
    C_VX,
    C_X,
    K_SIZE,
    K_STEP,
    P_ALPHA_E,
    P_C_CB,
    P_C_GUIDE,
    P_C_SUPPORT,
    P_C_SUPPORT_AXIAL,
    P_CAPACITANCE_BLOCK,
    P_CHATTER,
    P_CT_SUPPORT,
    P_D,
    P_DAMPING_STOP,
    P_DELTA_LIM_I,
    P_DRIVE,
    P_FILM_RATE,
    P_GUIDE_GAP,
    P_I_BALL,
    P_I_RING,
    P_IP_RING,
    P_K_CB,
    P_K_GUIDE,
    P_K_SUPPORT,
    P_KH_I,
    P_KT_RATIO,
    P_KT_SUPPORT,
    P_M_BALL,
    P_M_CAGE,
    P_M_RING,
    P_MU_LIM,
    P_PATH,
    P_PATH_T,
    P_R_CAGE,
    P_R_GUIDE,
    P_REFRESH,
    P_RG_I,
    P_V_REG,
    P_Z_GUIDE,
    R_ATH,
    R_AX,
    R_TH,
    R_TIME,
    R_VTH,
    R_VX,
    R_X,
    S_INNER,
    S_STRIDE,
    ST_CODE,
    ST_INDEX,
    ST_STEP,
    STATUS_CHATTER,
    STATUS_DAMPING,
    STATUS_ENERGY,
    STATUS_NOT_FINITE,
    STATUS_OK,
    STATUS_PENETRATION,
    T_C_N,
    T_CAP,
    T_F_ROLL,
    T_M_SPIN,
    T_MU,
    T_PHI,
    T_REGIME,
    T_SLIP,
    W_ARM,
    W_CAP_BALL,
    W_DISS,
    W_FB,
    W_FC,
    W_GEOM,
    W_LOADED,
    W_MB,
    W_ORBIT,
    W_VB,
    W_VC,
    W_WB,
)
from .tribology import (
    TC_SIZE,
    film_losses,
    race_circle,
    refresh_tribology,
    ring_axis,
    sample_refresh,
    tribology_constants,
)


@kernel(inline="always")  # called once per refresh from advance: no array-passing call
def ball_capacitances(trib, work):
    """work[W_CAP_BALL, j] = capacitance (F) of ball j from the last refresh: its two contacts in series."""
    for j in range(trib.shape[2]):
        work[W_CAP_BALL, j] = ball_capacitance(trib[T_CAP, 0, j], trib[T_CAP, 1, j])


@kernel(inline="always")  # called once per step from verlet_step: no array-passing call
def rigid_cage_torque(cage, work):
    """Share the torque about the bearing axis of the forces on the Z cage elements (work[W_FC], N) equally among
    them: the cage is one rigid ring whose pockets turn together, so each element carries the mean torque
    T = mean(x F_y - y F_x) (N.m) and turns at the cage's one angular acceleration; the radial and axial forces
    stay each element's own (its guide holds it on the pitch circle). Elements that could turn on their own
    would give the train of balls and cage elements relative modes a real cage does not have (a healthy 6205
    then showed a line at about BPFO/5 as large as BPFO, docs/dem.md)."""
    Z = cage.shape[1]
    mean = 0.0
    for k in range(Z):
        mean += cage[C_X, k] * work[W_FC + 1, k] - cage[C_X + 1, k] * work[W_FC, k]
    mean /= Z
    for k in range(Z):
        x = cage[C_X, k]
        y = cage[C_X + 1, k]
        # (T_mean - T_k) / r^2 along (-y, x): the tangential force whose torque is T_mean
        d = (mean - (x * work[W_FC + 1, k] - y * work[W_FC, k])) / (x * x + y * y)
        work[W_FC, k] -= d * y
        work[W_FC + 1, k] += d * x


@kernel(inline="always")
def slip_power_correction(Dx, Dy, Dz, rx, ry, rz, dvx, dvy, dvz, dwx, dwy, dwz, dsx, dsy, dsz):
    """Correction (W) to the power of one contact's dissipating tangential force (Dx, Dy, Dz) (N, on the ball, at
    the contact point (rx, ry, rz) from its centre, m), booked at the predicted velocities, for the slip velocity the
    step ends with: -D . (dv + dw x r - ds), dv (m/s) and dw (rad/s) the changes of the ball's velocity and angular
    velocity from the predicted ones to the step's end, ds (m/s) that of the race surface at the contact point.

    Why: velocity Verlet pairs the force of step n+1 with the velocities v(n+1) in its energy balance. The
    predicted velocities v* = v(n) + a(n) dt carry, at a stiff film traction (slope dF/dv up to ~1e4 N.s/m), an
    oscillation from step to step that v(n+1) does not: the forces and the motion converge with the step, but
    the film's power booked at v* came out 20 % of the whole loss too high on the 6208 at 6 kN, 500 rad/s at the
    default step (docs/dem.md, Choice of the defaults)."""
    ux = dvx + dwy * rz - dwz * ry - dsx
    uy = dvy + dwz * rx - dwx * rz - dsy
    uz = dvz + dwx * ry - dwy * rx - dsz
    return -(Dx * ux + Dy * uy + Dz * uz)


# The step in pieces, one per phase (predictor, approaches, ball-race contacts, cage contacts, correctors). Each
# is inlined into verlet_step (inline="always": numba splices its body into the caller before compiling), so the
# step stays one function body to the compiler: no call that passes the state arrays (two atomic reference-count
# updates per array) and the caller's error model. They are compiled with the step's error model too, for a
# direct call.
@kernel(error_model="numpy", inline="always")
def predict(balls, cage, ring, work, acc, dt):
    """Predictor of a step of dt (s): the new positions x + v dt + a dt^2/2 of the balls, cage balls and ring (its
    translation and tilts), the predicted velocities v + a dt (work[W_VB], work[W_WB], work[W_VC]; acc[A_VR],
    acc[A_WR]), the balls' orbital angles and orbital speeds (work[W_ORBIT]); clears the force sums and the loaded
    counts the contacts fill."""
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
            work[W_FB + i, j] = 0.0
            work[W_MB + i, j] = 0.0
            work[W_FC + i, j] = 0.0
        work[W_LOADED, j] = 0.0
        # orbital angle: the step's rotation is tiny, so atan(cross/dot) = cross/dot to O(angle^3)
        x1 = balls[B_X, j]
        y1 = balls[B_X + 1, j]
        balls[B_ORBIT, j] += (x0 * y1 - y0 * x1) / (x0 * x1 + y0 * y1)
        # orbital speed of the contact frame, for the rolling resistance
        work[W_ORBIT, j] = (x1 * work[W_VB + 1, j] - y1 * work[W_VB, j]) / (x1 * x1 + y1 * y1)
    for i in range(3):
        ring[R_X + i] += ring[R_VX + i] * dt + ring[R_AX + i] * h
        acc[A_VR + i] = ring[R_VX + i] + ring[R_AX + i] * dt
    for i in range(2):
        ring[R_TH + i] += ring[R_VTH + i] * dt + ring[R_ATH + i] * h
        acc[A_WR + i] = ring[R_VTH + i] + ring[R_ATH + i] * dt


@kernel(error_model="numpy", inline="always")
def race_approaches(balls, ring, par, work):
    """work[W_GEOM + 4 race .. + 3, j] = approach (m) and unit normal of ball j in the inner (race 0) and the outer
    (race 1) groove (contact_law.groove_approach), in a loop of their own before the contact laws
    (contact_law.ball_race_contact says why)."""
    cxi, cyi, czi, axi, ayi, azi, rhoi = race_circle(0, ring, par)
    cxo, cyo, czo, axo, ayo, azo, rhoo = race_circle(1, ring, par)
    rgi = par[P_RG_I]
    rgo = par[P_RG_I + 1]
    for j in range(balls.shape[1]):
        px = balls[B_X, j]
        py = balls[B_X + 1, j]
        pz = balls[B_X + 2, j]
        delta, nx, ny, nz = groove_approach(px, py, pz, cxi, cyi, czi, axi, ayi, azi, rhoi, rgi)
        work[W_GEOM, j] = delta
        work[W_GEOM + 1, j] = nx
        work[W_GEOM + 2, j] = ny
        work[W_GEOM + 3, j] = nz
        delta, nx, ny, nz = groove_approach(px, py, pz, cxo, cyo, czo, axo, ayo, azo, rhoo, rgo)
        work[W_GEOM + 4, j] = delta
        work[W_GEOM + 5, j] = nx
        work[W_GEOM + 6, j] = ny
        work[W_GEOM + 7, j] = nz


@kernel(error_model="numpy", inline="always")
def ball_race_forces(state, par, omega, loads, dt, work, acc):
    """The 2 Z ball-race contacts at the predicted state (contact_law.ball_race_contact, approaches from
    race_approaches): the forces and moments on the balls added to work[W_FB], work[W_MB], the springs and chatter
    counters updated, each contact's dissipating force and arm in work[W_DISS], work[W_ARM], each ball's loaded
    races counted in work[W_LOADED], the power (W) dissipated in each race's contacts in acc[A_POWER_I + race].

    Returns (worst penetration ratio, its contact, longest chatter, its contact, the ring's force (N) and moment
    (N.m, about its centre) x, y, z: the loads and the opposite of the inner contacts').

    state, par, loads, work and acc as advance's."""
    balls, _, ring, spring, trib, counters = state
    Z = balls.shape[1]
    # the ring's force and moment are summed in locals, not in acc: a store to an array that may alias the state
    # arrays would be reloaded and stored again at every contact
    fr_x, fr_y, fr_z, mr_x, mr_y = loads
    mr_z = 0.0
    worst_pen = 0.0
    worst_pen_at = -1
    worst_chat = 0
    worst_chat_at = -1
    steps = (
        0.5 * par[P_D],
        par[P_ALPHA_E],
        par[P_KT_RATIO],
        4.0 * dt / par[P_I_BALL],
        2.0 * par[P_V_REG] / par[P_D],
        dt,
    )
    mu_lim = par[P_MU_LIM]
    kappa = par[P_FILM_RATE] * dt / par[P_M_BALL]  # slip (m/s) a newton removes from a ball's contacts in a step
    for race in range(2):
        cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
        frame = (
            omega, acc[A_VR], acc[A_VR + 1], acc[A_VR + 2], cx, cy, cz, par[P_KH_I + race], ax, ay, az, acc[A_WR],
            acc[A_WR + 1],
        )  # fmt: skip
        inv_lim = 1.0 / par[P_DELTA_LIM_I + race]
        row = S_INNER + S_STRIDE * race
        power = 0.0
        geo = W_GEOM + 4 * race
        for j in range(Z):
            delta, fx, fy, fz, mx, my, mz, sx, sy, sz, slipping, reversed_, p, dtx, dty, dtz, rcx, rcy, rcz = (
                ball_race_contact(
                    race,
                    (work[geo, j], work[geo + 1, j], work[geo + 2, j], work[geo + 3, j]),
                    (
                        (balls[B_X, j], balls[B_X + 1, j], balls[B_X + 2, j]),
                        (work[W_VB, j], work[W_VB + 1, j], work[W_VB + 2, j]),
                        (work[W_WB, j], work[W_WB + 1, j], work[W_WB + 2, j]),
                        work[W_ORBIT, j],
                    ),
                    (spring[row, j], spring[row + 1, j], spring[row + 2, j]),
                    (trib[T_MU, race, j], int(trib[T_REGIME, race, j]), trib[T_C_N, race, j], trib[T_F_ROLL, race, j],
                     trib[T_M_SPIN, race, j]),
                    (trib[T_PHI, race, j], trib[T_SLIP, race, j], mu_lim, kappa),
                    frame,
                    steps,
                )
            )  # fmt: skip
            spring[row, j] = sx
            spring[row + 1, j] = sy
            spring[row + 2, j] = sz
            d = 3 * race
            work[W_DISS + d, j] = dtx
            work[W_DISS + d + 1, j] = dty
            work[W_DISS + d + 2, j] = dtz
            work[W_ARM + d, j] = rcx
            work[W_ARM + d + 1, j] = rcy
            work[W_ARM + d + 2, j] = rcz
            kc = K_SIZE + race * Z + j
            if delta <= 0.0:  # open: the chatter count starts again at the next touch
                counters[kc] = 0
                continue
            if reversed_:
                counters[kc] += 1
            else:
                counters[kc] = 0
            work[W_FB, j] += fx
            work[W_FB + 1, j] += fy
            work[W_FB + 2, j] += fz
            work[W_MB, j] += mx
            work[W_MB + 1, j] += my
            work[W_MB + 2, j] += mz
            if race == 0:
                fr_x -= fx
                fr_y -= fy
                fr_z -= fz
                # the ring takes the opposite of the contact's force and of its moment on the ball: about the ring's
                # centre, -((p - c) x f + m) (the ball and the race touch through forces along common lines)
                lx = balls[B_X, j] - cx
                ly = balls[B_X + 1, j] - cy
                lz = balls[B_X + 2, j] - cz
                mr_x -= ly * fz - lz * fy + mx
                mr_y -= lz * fx - lx * fz + my
                mr_z -= lx * fy - ly * fx + mz
            power += p
            work[W_LOADED, j] += 1.0
            pen = delta * inv_lim
            if pen > worst_pen:
                worst_pen = pen
                worst_pen_at = race * Z + j
            if counters[kc] > worst_chat:
                worst_chat = counters[kc]
                worst_chat_at = race * Z + j
        acc[A_POWER_I + race] = power
    return worst_pen, worst_pen_at, worst_chat, worst_chat_at, fr_x, fr_y, fr_z, mr_x, mr_y, mr_z


@kernel(error_model="numpy", inline="always")
def cage_forces(balls, cage, par, work):
    """The forces on the cage balls (work[W_FC]) and their opposites on the steel balls (work[W_FB]): each cage
    ball against the two steel balls around it (cage.ball_cage_contact) and against its channel
    (cage.cage_guide_contact), at the predicted velocities."""
    Z = balls.shape[1]
    R_sum = 0.5 * par[P_D] + par[P_R_CAGE]
    K_cb = par[P_K_CB]
    c_cb = par[P_C_CB]
    r_guide = par[P_R_GUIDE]
    z_guide = par[P_Z_GUIDE]
    gap = par[P_GUIDE_GAP]
    K_guide = par[P_K_GUIDE]
    c_guide = par[P_C_GUIDE]
    for k in range(Z):
        ckx = cage[C_X, k]
        cky = cage[C_X + 1, k]
        ckz = cage[C_X + 2, k]
        vx = work[W_VC, k]
        vy = work[W_VC + 1, k]
        vz = work[W_VC + 2, k]
        for side in range(2):  # cage ball k sits between steel balls k and k + 1
            j = k + side
            if j == Z:  # (not j % Z: an integer division costs tens of cycles)
                j = 0
            fx, fy, fz = ball_cage_contact(
                ckx - balls[B_X, j],
                cky - balls[B_X + 1, j],
                ckz - balls[B_X + 2, j],
                work[W_VB, j] - vx,
                work[W_VB + 1, j] - vy,
                work[W_VB + 2, j] - vz,
                R_sum,
                K_cb,
                c_cb,
            )
            work[W_FC, k] += fx
            work[W_FC + 1, k] += fy
            work[W_FC + 2, k] += fz
            work[W_FB, j] -= fx
            work[W_FB + 1, j] -= fy
            work[W_FB + 2, j] -= fz
        fx, fy, fz = cage_guide_contact(ckx, cky, ckz, vx, vy, vz, r_guide, z_guide, gap, K_guide, c_guide)
        work[W_FC, k] += fx
        work[W_FC + 1, k] += fy
        work[W_FC + 2, k] += fz


@kernel(error_model="numpy", inline="always")
def follow_path(ring, par, s, acc):
    """The prescribed inner ring (par[P_DRIVE] = 1) at the fraction s (0 at the call's start, 1 at its end) of its
    path: displacement, tilts, their rates (also as the predicted ones, acc[A_VR], acc[A_WR]) and accelerations on
    the cubic Hermite curve through the path's ends (par[P_PATH], the start's and the end's values and rates, over
    par[P_PATH_T] s). The cubic takes the rates the caller gives at both ends, so the ring's velocity, which the
    contacts' damping and traction see, is continuous from one call to the next; at s = 1 its weights are exactly
    (0, 0, 1, 0): the call ends on the given end values."""
    T = par[P_PATH_T]
    s2 = s * s
    s3 = s2 * s
    h00 = 2.0 * s3 - 3.0 * s2 + 1.0
    h10 = s3 - 2.0 * s2 + s
    h01 = 3.0 * s2 - 2.0 * s3
    h11 = s3 - s2
    d00 = (6.0 * s2 - 6.0 * s) / T
    d10 = 3.0 * s2 - 4.0 * s + 1.0
    d11 = 3.0 * s2 - 2.0 * s
    e00 = (12.0 * s - 6.0) / (T * T)
    e10 = (6.0 * s - 4.0) / T
    e11 = (6.0 * s - 2.0) / T
    for k in range(5):
        x0 = par[P_PATH + k]
        r0 = par[P_PATH + 5 + k]
        x1 = par[P_PATH + 10 + k]
        r1 = par[P_PATH + 15 + k]
        x = h00 * x0 + h10 * T * r0 + h01 * x1 + h11 * T * r1
        v = d00 * (x0 - x1) + d10 * r0 + d11 * r1
        a = e00 * (x0 - x1) + e10 * r0 + e11 * r1
        if k < 3:
            ring[R_X + k] = x
            ring[R_VX + k] = v
            ring[R_AX + k] = a
            acc[A_VR + k] = v
        else:
            ring[R_TH + k - 3] = x
            ring[R_VTH + k - 3] = v
            ring[R_ATH + k - 3] = a
            acc[A_WR + k - 3] = v


@kernel(error_model="numpy", inline="always")
def correct_ring(ring, par, omega, dt, acc):
    """Corrector of the inner ring: its new accelerations and velocities in translation and tilt from the contacts'
    force acc[A_FR] and moment acc[A_MR] (with the loads), its support and, in the tilts, its gyroscopic moment."""
    half = 0.5 * dt
    # the ring's support (the shaft it sits on): across the axis a spring to its rest position and a damper on the
    # predicted velocity in x and y; along it a damper of its own, none by default (the bearing alone holds the
    # ring axially; 0 adds no term, so the free ring's arithmetic stays as it is)
    inv_r = 1.0 / par[P_M_RING]
    k_s = par[P_K_SUPPORT]
    c_s = par[P_C_SUPPORT]
    c_z = par[P_C_SUPPORT_AXIAL]
    for i in range(3):
        a = acc[A_FR + i]
        if i < 2:
            a -= k_s * ring[R_X + i] + c_s * acc[A_VR + i]
        elif c_z != 0.0:
            a -= c_z * acc[A_VR + 2]
        a *= inv_r
        ring[R_VX + i] += (ring[R_AX + i] + a) * half
        ring[R_AX + i] = a
    # tilts: the moment across the ring's axis (the drive holds the part along it) and the gyroscopic moment of the
    # turning ring whose axis turns at the (predicted) tilt rates
    ax, ay, az = ring_axis(ring[R_TH], ring[R_TH + 1])
    m_axial = acc[A_MR] * ax + acc[A_MR + 1] * ay + acc[A_MR + 2] * az
    spin_inertia = par[P_IP_RING] * omega * az  # -I_p omega (theta' x a) across the axis
    inv_d = 1.0 / par[P_I_RING]
    kt_s = par[P_KT_SUPPORT]
    ct_s = par[P_CT_SUPPORT]
    a = acc[A_MR] - m_axial * ax - spin_inertia * acc[A_WR + 1] - kt_s * ring[R_TH] - ct_s * acc[A_WR]
    a *= inv_d
    ring[R_VTH] += (ring[R_ATH] + a) * half
    ring[R_ATH] = a
    a = acc[A_MR + 1] - m_axial * ay + spin_inertia * acc[A_WR] - kt_s * ring[R_TH + 1] - ct_s * acc[A_WR + 1]
    a *= inv_d
    ring[R_VTH + 1] += (ring[R_ATH + 1] + a) * half
    ring[R_ATH + 1] = a


@kernel(error_model="numpy", inline="always")
def correct_balls(balls, cage, ring, par, dt, work, acc, total):
    """Corrector of the balls and cage balls (new accelerations and velocities from work[W_FB], work[W_MB],
    work[W_FC]), after the ring's (correct_ring), and the contacts' slip power at the velocities the step ends with
    added to acc[A_POWER_I], acc[A_POWER_O] (slip_power_correction, in the balls' loop). Returns total plus every
    force component on the balls and cage balls: non-finite as soon as one is."""
    half = 0.5 * dt
    # the inner race's surface velocity changes with the ring's translation and tilt rates (its speed is given)
    dvrx = ring[R_VX] - acc[A_VR]
    dvry = ring[R_VX + 1] - acc[A_VR + 1]
    dvrz = ring[R_VX + 2] - acc[A_VR + 2]
    dwrx = ring[R_VTH] - acc[A_WR]
    dwry = ring[R_VTH + 1] - acc[A_WR + 1]
    cx, cy, cz, _, _, _, _ = race_circle(0, ring, par)
    correction_i = 0.0
    correction_o = 0.0
    inv_m = 1.0 / par[P_M_BALL]
    inv_i = 1.0 / par[P_I_BALL]
    inv_c = 1.0 / par[P_M_CAGE]
    for j in range(balls.shape[1]):
        for i in range(3):
            f = work[W_FB + i, j]
            f_c = work[W_FC + i, j]
            total += f + f_c
            a = f * inv_m
            balls[B_VX + i, j] += (balls[B_AX + i, j] + a) * half
            balls[B_AX + i, j] = a
            a = work[W_MB + i, j] * inv_i
            balls[B_WX + i, j] += (balls[B_ALX + i, j] + a) * half
            balls[B_ALX + i, j] = a
            a = f_c * inv_c
            cage[C_VX + i, j] += (cage[C_AX + i, j] + a) * half
            cage[C_AX + i, j] = a
        dwx = balls[B_WX, j] - work[W_WB, j]
        dwy = balls[B_WX + 1, j] - work[W_WB + 1, j]
        dwz = balls[B_WX + 2, j] - work[W_WB + 2, j]
        dvx = balls[B_VX, j] - work[W_VB, j]
        dvy = balls[B_VX + 1, j] - work[W_VB + 1, j]
        dvz = balls[B_VX + 2, j] - work[W_VB + 2, j]
        Dx = work[W_DISS, j]
        Dy = work[W_DISS + 1, j]
        Dz = work[W_DISS + 2, j]
        if Dx != 0.0 or Dy != 0.0 or Dz != 0.0:
            rx = work[W_ARM, j]
            ry = work[W_ARM + 1, j]
            rz = work[W_ARM + 2, j]
            lx = balls[B_X, j] + rx - cx
            ly = balls[B_X + 1, j] + ry - cy
            lz = balls[B_X + 2, j] + rz - cz
            # the race surface: the ring's translation and (tilt rates, 0) x l at the contact point
            correction_i += slip_power_correction(
                Dx, Dy, Dz, rx, ry, rz, dvx, dvy, dvz, dwx, dwy, dwz, dvrx + dwry * lz, dvry - dwrx * lz,
                dvrz + dwrx * ly - dwry * lx,
            )  # fmt: skip
        Dx = work[W_DISS + 3, j]
        Dy = work[W_DISS + 4, j]
        Dz = work[W_DISS + 5, j]
        if Dx != 0.0 or Dy != 0.0 or Dz != 0.0:
            correction_o += slip_power_correction(
                Dx, Dy, Dz, work[W_ARM + 3, j], work[W_ARM + 4, j], work[W_ARM + 5, j], dvx, dvy, dvz, dwx, dwy, dwz,
                0.0, 0.0, 0.0,
            )  # fmt: skip
    acc[A_POWER_I] += correction_i
    acc[A_POWER_O] += correction_o
    return total


# error_model="numpy": a division by zero gives inf or NaN, which the monitor stops as a non-finite force, instead
# of a ZeroDivisionError; no division here can meet a zero divisor in a valid state (the contacts guard theirs), and
# without a check and an exception path per division (26 of them) the step runs about 10 % faster. Inlined into its
# callers (which take the same error model: the inlined code is compiled with the caller's): a call that passes the
# nine state arrays costs two atomic reference-count updates per array, about 5 % of a step.
@kernel(error_model="numpy", inline="always")
def verlet_step(state, par, omega, loads, dt, work, acc, s, prescribed):
    """One velocity-Verlet step of every body of state (see the module docstring) at inner-ring speed omega
    (rad/s) and loads (F_x, F_y, F_z (N), M_x, M_y (N.m, about its centre)) on the inner ring; state, par, work
    and acc as advance's. A prescribed ring (prescribed, par[P_DRIVE] != 0) is put at the fraction s of its path at
    the step's end (follow_path) instead of being predicted and corrected; advance passes prescribed as a constant,
    so that the load-driven step is compiled without the switch.

    The forces at the new positions with the predicted velocities: the 2 Z ball-race contacts
    (ball_race_forces) and the cage balls (cage_forces, the cage's torque shared by rigid_cage_torque), then the
    new accelerations and velocities (correct_ring, correct_balls). The phases are functions inlined into this
    one body: a numba call that passes arrays costs two atomic reference-count updates per array. Returns (worst
    penetration ratio, its contact, longest chatter, its contact, sum of the force components): the last is
    non-finite as soon as any force is.
    """
    balls, cage, ring, _, _, counters = state
    predict(balls, cage, ring, work, acc, dt)
    if prescribed:
        follow_path(ring, par, s, acc)
    race_approaches(balls, ring, par, work)
    worst_pen, worst_pen_at, worst_chat, worst_chat_at, fr_x, fr_y, fr_z, mr_x, mr_y, mr_z = ball_race_forces(
        state, par, omega, loads, dt, work, acc
    )
    acc[A_FR] = fr_x
    acc[A_FR + 1] = fr_y
    acc[A_FR + 2] = fr_z
    acc[A_MR] = mr_x
    acc[A_MR + 1] = mr_y
    acc[A_MR + 2] = mr_z
    cage_forces(balls, cage, par, work)
    rigid_cage_torque(cage, work)
    if not prescribed:
        correct_ring(ring, par, omega, dt, acc)
    # a NaN or inf anywhere (positions, velocities, springs) reaches the contact forces within a step; the moments
    # follow from the same quantities. The sum only feeds the finiteness check, so it is taken in the loop that
    # reads the forces anyway, in an order that keeps the additions' chain short.
    total = correct_balls(balls, cage, ring, par, dt, work, acc, fr_x + fr_y + fr_z + mr_x + mr_y)
    ring[R_TIME] += dt
    counters[K_STEP] += 1
    return worst_pen, worst_pen_at, worst_chat, worst_chat_at, total


@kernel(error_model="numpy")  # (verlet_step is inlined: its error model)
def initialise_accelerations(state, params, omega, loads, T_oil, space):
    """Tribology and accelerations of a new state (the a_n that the first Verlet step needs), without
    moving anything: call once after the facade sets positions and velocities. Inner-ring speed omega (rad/s),
    loads (F_x, F_y, F_z (N), M_x, M_y (N.m)), oil temperature T_oil (K); state, params and space as advance's
    (space's status is not used)."""
    balls, _, ring, spring, trib, counters = state
    par, lub = params
    work, acc, _ = space
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF])
    tc = np.empty((TC_SIZE, 2))
    tribology_constants(par, eta, xi, tc)
    refresh_tribology(omega, eta, xi, K_cm, rho0, balls, ring, par, trib, tc, np.empty((4, balls.shape[1])))
    # a step of zero length: positions and velocities stay, the accelerations become those of the forces
    saved = spring.copy()
    verlet_step(state, par, omega, loads, 0.0, work, acc, 0.0, par[P_DRIVE] != 0.0)
    spring[:, :] = saved  # (the springs' projection on the tangent planes waits for the first real step)
    counters[K_STEP] -= 1  # not a step: the refresh phase stays


# advance's set-up, inlined into it (inline="always": no call that passes arrays). The per-step integrals and the
# monitor's checks stay in advance's loop: in a function of their own, inlined all the same, the step took 2 % longer.
@kernel(inline="always")
def start_call(acc, status):
    """Clear what a call of advance integrates (dissipated energies, capacitance, the averaged state outputs'
    integrals and sums) and its status."""
    acc[A_DISS_I] = 0.0
    acc[A_DISS_O] = 0.0
    acc[A_CAP] = 0.0
    for k in range(A_XT, A_SIZE):  # the averaged state outputs' integrals and sums
        acc[k] = 0.0
    status[ST_CODE] = STATUS_OK
    status[ST_STEP] = 0
    status[ST_INDEX] = -1


# advance's body, inlined into two kernels with prescribed a constant: the load-driven loop is then compiled without
# the prescribed ring's branches, which in the loop cost it 4 %. (Both inlined into advance itself, the function
# twice as long, the load-driven call took half as long again.)
@kernel(error_model="numpy", inline="always")
def run_call(state, params, call, space, prescribed):
    """advance's call, the inner ring prescribed (prescribed, a constant) or load-driven."""
    balls, cage, ring, _, trib, counters = state
    par, lub = params
    n_steps, dt, omega0, omega1, loads, T_oil, energy_limit = call
    work, acc, status = space
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF])
    tc = np.empty((TC_SIZE, 2))
    tribology_constants(par, eta, xi, tc)
    Z = balls.shape[1]
    geo = np.empty((4, Z))  # refresh_tribology's scratch
    refresh = max(int(par[P_REFRESH]), 1)
    chatter_limit = int(par[P_CHATTER])
    damping_stop = par[P_DAMPING_STOP]
    capacitance = par[P_CAPACITANCE_BLOCK + CAP_ON] > 0.5
    start_call(acc, status)
    film_i, film_o = film_losses(trib)
    ball_capacitances(trib, work)
    d_omega = (omega1 - omega0) / n_steps
    # steps until the next refresh (the phase carries over between calls through the step counter)
    countdown = (refresh - counters[K_STEP] % refresh) % refresh
    for n in range(n_steps):
        if countdown == 0:
            countdown = refresh
            refresh_tribology(omega0 + d_omega * n, eta, xi, K_cm, rho0, balls, ring, par, trib, tc, geo)
            film_i, film_o = film_losses(trib)
            ball_capacitances(trib, work)
            sample_refresh(trib, acc)
            if kinetic_energy(balls, cage, ring, par) > energy_limit:
                status[ST_CODE] = STATUS_ENERGY
                status[ST_STEP] = n
                return
            ratio, at = damping_step_ratio(trib, par, dt)
            if ratio > damping_stop:
                status[ST_CODE] = STATUS_DAMPING
                status[ST_STEP] = n
                status[ST_INDEX] = at
                return
        countdown -= 1
        omega = omega0 + d_omega * (n + 1)
        s = (n + 1) / n_steps if prescribed else 0.0
        pen, pen_at, chat, chat_at, total = verlet_step(state, par, omega, loads, dt, work, acc, s, prescribed)
        power_i = acc[A_POWER_I] + film_i
        power_o = acc[A_POWER_O] + film_o
        acc[A_POWER_I] = power_i
        acc[A_POWER_O] = power_o
        acc[A_DISS_I] += power_i * dt
        acc[A_DISS_O] += power_o * dt
        acc[A_XT] += ring[R_X] * dt
        acc[A_XT + 1] += ring[R_X + 1] * dt
        acc[A_XT + 2] += ring[R_X + 2] * dt
        acc[A_XT + 3] += ring[R_TH] * dt
        acc[A_XT + 4] += ring[R_TH + 1] * dt
        # second moments of the ring's motion across its axis: the orbit watch's variances over a window
        acc[A_RING_SQ] += ring[R_X] * ring[R_X] * dt
        acc[A_RING_SQ + 1] += ring[R_X + 1] * ring[R_X + 1] * dt
        acc[A_RING_SQ + 2] += ring[R_TH] * ring[R_TH] * dt
        acc[A_RING_SQ + 3] += ring[R_TH + 1] * ring[R_TH + 1] * dt
        acc[A_RING_SQ + 4] += (ring[R_VX] * ring[R_VX] + ring[R_VX + 1] * ring[R_VX + 1]) * dt
        acc[A_RING_SQ + 5] += (ring[R_VTH] * ring[R_VTH] + ring[R_VTH + 1] * ring[R_VTH + 1]) * dt
        if prescribed:  # the load that holds the ring on its path: the loads less the ring's force and moment
            F_x, F_y, F_z, M_x, M_y = loads
            acc[A_REACTION] += (F_x - acc[A_FR]) * dt
            acc[A_REACTION + 1] += (F_y - acc[A_FR + 1]) * dt
            acc[A_REACTION + 2] += (F_z - acc[A_FR + 2]) * dt
            acc[A_REACTION + 3] += (M_x - acc[A_MR]) * dt
            acc[A_REACTION + 4] += (M_y - acc[A_MR + 1]) * dt
        if capacitance:  # the balls loaded on both races in this step, in parallel
            c = 0.0
            for j in range(Z):
                if work[W_LOADED, j] == 2.0:
                    c += work[W_CAP_BALL, j]
            acc[A_CAP] += c * dt
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


@kernel(error_model="numpy")  # (verlet_step is inlined: its error model)
def load_driven_call(state, params, call, space):
    """advance's call with the inner ring under its loads and support."""
    run_call(state, params, call, space, False)


@kernel(error_model="numpy")  # (verlet_step is inlined: its error model)
def prescribed_call(state, params, call, space):
    """advance's call with the inner ring on the path of par[P_PATH]."""
    run_call(state, params, call, space, True)


# one call per advance (not per step): its reference counts cost nothing measurable
@kernel(error_model="numpy")
def advance(state, params, call, space):
    """Run n_steps steps of dt (s) with the inner-ring speed going linearly from omega0 to omega1
    (rad/s), constant loads F_x, F_y, F_z (N) and M_x, M_y (N.m, about its centre) on the inner ring and oil
    temperature T_oil (K).

    The arguments are four tuples (kernels.ball_dynamics.state, "argument groups"): state = (balls, cage, ring,
    spring, trib, counters), the state arrays; params = (par, lub), the parameter and lubricant arrays; call =
    (n_steps, dt, omega0, omega1, loads, T_oil, energy_limit) with loads = (F_x, F_y, F_z, M_x, M_y); space =
    (work, acc, status), the scratch, the call's sums and the monitor's verdict.

    Stops early with status[ST_CODE] != STATUS_OK (monitor) after the offending step; status[ST_STEP]
    holds the steps done, status[ST_INDEX] the ball or contact (race * Z + ball). energy_limit (J)
    bounds the kinetic energy and par[P_DAMPING_STOP] the damping ratio of a step (monitor.damping_step_ratio),
    both checked at each tribology refresh. acc[A_DISS_I], acc[A_DISS_O]
    receive the energy (J) dissipated in the inner and outer contacts during the call, acc[A_POWER_I],
    acc[A_POWER_O] the power (W) of the last step, and acc[A_CAP] the bearing capacitance of every step (the
    loaded balls' capacitances at the last refresh, without a background term) integrated over the call (F.s).
    With par[P_DRIVE] = 1 the inner ring follows the path of par[P_PATH] over the call (follow_path: its support and
    the loads move it no more) and acc[A_REACTION] receives the load that holds it there integrated over the call.
    """
    if params[0][P_DRIVE] != 0.0:
        prescribed_call(state, params, call, space)
    else:
        load_driven_call(state, params, call, space)
