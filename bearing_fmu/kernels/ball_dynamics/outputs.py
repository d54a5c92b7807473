"""Bearing-level outputs of the DEM state, with the names and meanings of the quasi-static fidelity.

Computed once per call of advance() (a recording interval), not every step. Loads come from the
current approaches; film, regime and capacitance from the last tribology refresh, over the contacts loaded
both now and at that refresh (a contact that closed since has no film yet: the refresh wrote Lambda = 0 and
h_min = inf for it while it was open, which would report a boundary regime the contact does not have); power
from the
energy dissipated in the contacts over the interval (Houpert film losses, normal damping and
tangential slip), so the torque P_loss/|omega| emerges from the dynamics.
"""

import math

from bearing_fmu_common.jit import kernel

from ..capacitance import ball_capacitance
from ..ehl import lubrication_regime
from ..truncation import race_truncation
from .contact_law import groove_approach
from .monitor import kinetic_energy
from .state import (
    A_CAP,
    A_DISS_I,
    A_DISS_O,
    A_POWER_I,
    A_POWER_O,
    B_ORBIT,
    B_VX,
    B_WX,
    B_X,
    LOADED_APPROACH,
    O_ALPHA_I,
    O_ALPHA_O,
    O_C_BEARING,
    O_CAGE_SLIP,
    O_HC_I,
    O_HMIN_I,
    O_KINETIC,
    O_LAMBDA_I,
    O_LAMBDA_O,
    O_N_LOADED,
    O_OMEGA_BALL,
    O_OMEGA_BALL_REL,
    O_OMEGA_CAGE,
    O_P_LOSS,
    O_PMAX,
    O_Q_INNER_RING,
    O_Q_OUTER_RING,
    O_QMAX_I,
    O_REGIME,
    O_SIZE,
    O_SRR_MAX,
    O_TORQUE,
    P_D,
    P_KH_I,
    P_RG_I,
    T_CAP,
    T_H_C,
    T_H_MIN,
    T_LAMBDA,
    T_P_MAX,
    T_Q,
    T_SRR,
)
from .tribology import race_circle


@kernel
def contact_loads(balls, ring, par, Q):
    """Current normal loads (N) of every ball-race contact into Q[race, ball] (0 when open or touching with an
    approach below LOADED_APPROACH, a rounding-level contact)."""
    for race in range(2):
        cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
        for j in range(balls.shape[1]):
            delta, _, _, _ = groove_approach(
                balls[B_X, j], balls[B_X + 1, j], balls[B_X + 2, j], cx, cy, cz, ax, ay, az, rho, par[P_RG_I + race]
            )
            Q[race, j] = par[P_KH_I + race] * delta * math.sqrt(delta) if delta > LOADED_APPROACH else 0.0


@kernel
def contact_angles(balls, ring, par, alpha):
    """Contact angles (rad) of every ball-race contact into alpha[race, ball]: the angle of the contact
    normal from the radial plane (0 for a deep-groove bearing under radial load); 0 when open. The plane normal to
    the bearing axis z, for both races (the quasi-static fidelity's angles; a tilted inner ring's own radial plane
    differs by the tilt, milliradians)."""
    for race in range(2):
        cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
        for j in range(balls.shape[1]):
            delta, nx, ny, nz = groove_approach(
                balls[B_X, j], balls[B_X + 1, j], balls[B_X + 2, j], cx, cy, cz, ax, ay, az, rho, par[P_RG_I + race]
            )
            alpha[race, j] = math.atan2(abs(nz), math.sqrt(nx * nx + ny * ny)) if delta > LOADED_APPROACH else 0.0


@kernel(inline="always")  # called once per output evaluation from bearing_outputs: no array-passing call
def pure_rolling_cage_speed(balls, ring, par, omega, Q):
    """Cage speed (rad/s) at which the balls loaded on both races (Q[race, ball] > 0, N) would roll without
    sliding in the rolling direction at either contact centre, at their current contact points and with their
    current spin axes, the inner race turning at omega about its current (tilted) axis a; the mean over those
    balls, 0 when none (or at rest).

    Per ball at p with unit spin axis e (its angular velocity relative to its orbit, w - w_orbit z), orbit
    direction t = z x p / |p|, contact offsets r_k = (D/2) n_k: the ball surface moves at w_c (z x (p + r_k)).t +
    w_R (e x r_k).t in the rolling direction, the inner race at omega (z x (p + r_i - c)).t (c its centre), the
    outer one not at all; zero slip at both gives w_c = omega b_i g_o / (a_i g_o - a_o g_i) with
    a_k = (z x (p + r_k)).t, b_i = (a x (p + r_i - c)).t, g_k = (e x r_k).t. A radial bearing (n = -+ radial,
    e = z) gives omega (1 - gamma) / 2 (Harris & Kotzalas 2006, vol. 1, ch. 8)."""
    half_d = 0.5 * par[P_D]
    total = 0.0
    count = 0
    for j in range(balls.shape[1]):
        if omega == 0.0 or Q[0, j] <= 0.0 or Q[1, j] <= 0.0:
            continue
        px = balls[B_X, j]
        py = balls[B_X + 1, j]
        pz = balls[B_X + 2, j]
        r2 = px * px + py * py
        w_orbit = (px * balls[B_VX + 1, j] - py * balls[B_VX, j]) / r2
        ex = balls[B_WX, j]
        ey = balls[B_WX + 1, j]
        ez = balls[B_WX + 2, j] - w_orbit
        w = math.sqrt(ex * ex + ey * ey + ez * ez)
        if w == 0.0:
            continue
        ex /= w
        ey /= w
        ez /= w
        r = math.sqrt(r2)
        tx = -py / r
        ty = px / r
        a_i = a_o = g_i = g_o = b_i = 0.0
        for race in range(2):
            cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
            _, nx, ny, nz = groove_approach(px, py, pz, cx, cy, cz, ax, ay, az, rho, par[P_RG_I + race])
            rx = half_d * nx
            ry = half_d * ny
            rz = half_d * nz
            # (z x v).t = -v_y t_x + v_x t_y
            a_k = -(py + ry) * tx + (px + rx) * ty
            g_k = (ey * rz - ez * ry) * tx + (ez * rx - ex * rz) * ty
            if race == 0:
                a_i, g_i = a_k, g_k
                lx = px + rx - cx
                ly = py + ry - cy
                lz = pz + rz - cz
                b_i = (ay * lz - az * ly) * tx + (az * lx - ax * lz) * ty
            else:
                a_o, g_o = a_k, g_k
        den = a_i * g_o - a_o * g_i
        if den != 0.0:
            total += omega * b_i * g_o / den
            count += 1
    return total / count if count > 0 else 0.0


@kernel
def signed_contact_angles(balls, ring, par, alpha):
    """Signed contact angles (rad) of every ball-race contact into alpha[race, ball], as the quasi-static fidelity
    measures them (docs/quasistatic.md section 1): the direction from the ball centre to the inner groove-curvature
    centre, and from the outer one to the ball centre, from the radial plane; positive toward +z at the inner
    contact and -z at the outer one's centre, i.e. toward each ring's thrust-side shoulder; radial and axial
    are those of each ring's own axis (the inner ring's tilts turn its groove)."""
    for race in range(2):
        cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
        for j in range(balls.shape[1]):
            dx = balls[B_X, j] - cx
            dy = balls[B_X + 1, j] - cy
            dz = balls[B_X + 2, j] - cz
            axial = dx * ax + dy * ay + dz * az  # along the ring's (possibly tilted) axis
            rx = dx - axial * ax
            ry = dy - axial * ay
            rz = dz - axial * az
            radial = math.sqrt(rx * rx + ry * ry + rz * rz) - rho  # ball centre beyond the centre circle (m)
            alpha[race, j] = math.atan2(-axial, -radial) if race == 0 else math.atan2(axial, radial)


@kernel
def shoulder_truncation(balls, ring, par, tp, Q, alpha, tr):
    """Fill tr[TR_*] (kernels.truncation) with the most truncated loaded contact of each race in the current
    state; tp: the TP_* shoulder parameters. Q, alpha: float64[2, Z] work arrays (receive the current contact
    loads and signed contact angles)."""
    contact_loads(balls, ring, par, Q)
    signed_contact_angles(balls, ring, par, alpha)
    race_truncation(Q, 0, alpha, 0, tp, tr)


@kernel
def bearing_outputs(balls, cage, ring, trib, par, acc, omega, interval, orbit0, c_background, averaged, Q, alpha, out):
    """Fill out[O_*] for inner-ring speed omega (rad/s) after an interval (s) of advance().

    averaged: True gives the power outputs (P_loss, Q_inner_ring, Q_outer_ring, torque) and the capacitance as
    means over the interval's steps (the energy dissipated, the capacitance integrated over time, divided by
    the interval); False gives their values at its last step (the power of the last step, the capacitance of
    the balls loaded at the end). The other outputs are end values in both cases (omega_cage: the mean orbital
    speed over the interval).

    orbit0: sum of the balls' orbital angles (rad) at the start of the interval: the cage speed is their mean
    change over the interval (the instantaneous orbital speeds fluctuate with the cage-ball contacts).
    Q, alpha: float64[2, Z] work arrays (receive the current contact loads and angles); c_background (F) is
    added to the capacitance (0 by default). Film outputs (Lambda, h_min: minima; h_c: of the most loaded contact)
    come from the contacts loaded now and at the last refresh; races without such a contact report zero film
    (as the quasi-static fidelity for an unloaded race).
    """
    Z = balls.shape[1]
    for k in range(O_SIZE):
        out[k] = 0.0
    contact_loads(balls, ring, par, Q)
    contact_angles(balls, ring, par, alpha)
    j_max = 0
    orbit = 0.0
    for race in range(2):
        lam_min = math.inf
        h_min = math.inf
        q_max = 0.0
        q_film = 0.0  # largest load among the contacts with a film (loaded now and at the last refresh)
        h_c = 0.0
        for j in range(Z):
            q = Q[race, j]
            if q > 0.0:
                out[O_SRR_MAX] = max(out[O_SRR_MAX], trib[T_SRR, race, j])
                out[O_PMAX] = max(out[O_PMAX], trib[T_P_MAX, race, j])
                if trib[T_Q, race, j] > 0.0:
                    lam_min = min(lam_min, trib[T_LAMBDA, race, j])
                    h_min = min(h_min, trib[T_H_MIN, race, j])
                    if q > q_film:
                        q_film = q
                        h_c = trib[T_H_C, race, j]
            if q > q_max:
                q_max = q
                if race == 0:
                    j_max = j
        film = q_film > 0.0
        out[O_QMAX_I + race] = q_max
        out[O_LAMBDA_I + race] = lam_min if film else 0.0
        out[O_HMIN_I + race] = h_min if film else 0.0
        out[O_HC_I + race] = h_c
    out[O_REGIME] = lubrication_regime(min(out[O_LAMBDA_I], out[O_LAMBDA_O]))
    if out[O_QMAX_I] == 0.0:  # no inner contact: report the most loaded outer one
        for j in range(Z):
            if Q[1, j] > Q[1, j_max]:
                j_max = j
    c_total = c_background
    for j in range(Z):
        orbit += balls[B_ORBIT, j]
        if Q[0, j] > 0.0 and Q[1, j] > 0.0:
            out[O_N_LOADED] += 1.0
            c_total += ball_capacitance(trib[T_CAP, 0, j], trib[T_CAP, 1, j])
    omega_cage = (orbit - orbit0) / (Z * interval) if interval > 0.0 else 0.0
    out[O_OMEGA_CAGE] = omega_cage
    wx = balls[B_WX, j_max]
    wy = balls[B_WX + 1, j_max]
    wz = balls[B_WX + 2, j_max]
    w = math.sqrt(wx * wx + wy * wy + wz * wz)
    out[O_OMEGA_BALL] = math.copysign(w, omega) if omega != 0.0 else w
    out[O_OMEGA_BALL_REL] = math.sqrt(wx * wx + wy * wy + (wz - omega_cage) ** 2)
    out[O_C_BEARING] = c_background + acc[A_CAP] / interval if averaged and interval > 0.0 else c_total
    out[O_ALPHA_I] = alpha[0, j_max]
    out[O_ALPHA_O] = alpha[1, j_max]
    if not averaged:
        out[O_Q_INNER_RING] = acc[A_POWER_I]
        out[O_Q_OUTER_RING] = acc[A_POWER_O]
    elif interval > 0.0:
        out[O_Q_INNER_RING] = acc[A_DISS_I] / interval
        out[O_Q_OUTER_RING] = acc[A_DISS_O] / interval
    out[O_P_LOSS] = out[O_Q_INNER_RING] + out[O_Q_OUTER_RING]
    out[O_TORQUE] = out[O_P_LOSS] / abs(omega) if omega != 0.0 else 0.0
    pure = pure_rolling_cage_speed(balls, ring, par, omega, Q)
    out[O_CAGE_SLIP] = 1.0 - omega_cage / pure if pure != 0.0 else 0.0
    out[O_KINETIC] = kinetic_energy(balls, cage, ring, par)
