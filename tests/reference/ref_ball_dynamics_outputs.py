"""Twin of bearing_fmu.kernels.ball_dynamics.outputs: contact loads, contact angles and bearing-level outputs.

Written from the definitions with vector algebra (the groove-torus contact of ref_ball_dynamics_integrator, Hertz
Q = K_h delta^1.5), sharing only the array layout (the kernel's slot constants):
- contact angle: angle of the contact normal from the plane normal to the bearing axis z, atan2(|n_z|, |n_radial|);
- cage speed: mean change of the balls' orbital angles over the interval; ball speeds of the most loaded
  ball (inner race, or the outer one when no inner contact is loaded), in the fixed frame and relative to
  the cage;
- films over the contacts loaded now and at the last refresh (the only ones with a film): smallest Lambda
  and h_min per race, h_c of the most loaded of them, zero film without any; the regime of the smaller
  Lambda; largest SRR and Hertz pressure of a loaded contact;
- capacitance: balls loaded on both races in parallel, each the series of its two contacts, plus background;
- averaged: power = energy dissipated over the interval / interval, capacitance = its integral over the
  steps / interval; else the power of the last step and the capacitance now; torque = power / |omega|;
  cage slip against the pure-rolling cage speed of the loaded balls at their current contacts and spin axes.
"""

import math

import numpy as np

from bearing_fmu.kernels.ball_dynamics import state as s
from tests.reference import ref_capacitance, ref_ehl, ref_truncation
from tests.reference.ref_ball_dynamics_integrator import groove_contact, race_centre
from tests.reference.ref_ball_dynamics_monitor import kinetic_energy

KERNEL_MODULE = "bearing_fmu.kernels.ball_dynamics.outputs"


def _contacts(balls, ring, par):
    """Per race and ball: (delta (m), normal n) of the ball-race contact."""
    result = []
    for race in range(2):
        centre, rho, axis = race_centre(race, ring, par)
        rg = par[s.P_RG_I + race]
        result.append(
            [groove_contact(balls[s.B_X : s.B_X + 3, j], centre, rho, rg, axis) for j in range(balls.shape[1])]
        )
    return result


def contact_loads(balls, ring, par):
    """Normal loads Q[race, ball] (N), 0 where the contact is open or its approach is at most LOADED_APPROACH."""
    return np.array(
        [
            [par[s.P_KH_I + race] * d**1.5 if d > s.LOADED_APPROACH else 0.0 for d, _ in row]
            for race, row in enumerate(_contacts(balls, ring, par))
        ]
    )


def contact_angles(balls, ring, par):
    """Contact angles alpha[race, ball] (rad) of the contact normals from the radial plane, 0 where open."""
    return np.array(
        [
            [math.atan2(abs(n[2]), math.hypot(n[0], n[1])) if d > s.LOADED_APPROACH else 0.0 for d, n in row]
            for row in _contacts(balls, ring, par)
        ]
    )


def pure_rolling_cage_speed(balls, ring, par, omega, Q):
    """Mean over the balls loaded on both races of the orbital speed w_c at which the ball, spinning about its
    current axis e (unit of w - w_orbit z) at some w_R, rolls without sliding in the orbit direction t at both
    contact centres: solve the 2x2 linear system for (w_c, w_R) with numpy."""
    if omega == 0.0:
        return 0.0
    D = par[s.P_D]
    speeds = []
    for j in np.flatnonzero((Q > 0.0).all(axis=0)):
        p = balls[s.B_X : s.B_X + 3, j]
        v = balls[s.B_VX : s.B_VX + 3, j]
        w_orbit = (p[0] * v[1] - p[1] * v[0]) / (p[0] ** 2 + p[1] ** 2)
        e = balls[s.B_WX : s.B_WX + 3, j] - w_orbit * np.array([0.0, 0.0, 1.0])
        if not np.any(e):
            continue
        e = e / np.linalg.norm(e)
        t = np.cross([0.0, 0.0, 1.0], p)
        t = t / np.linalg.norm(t)
        rows, rhs = [], []
        for race in range(2):
            centre, rho, axis = race_centre(race, ring, par)
            _, n = groove_contact(p, centre, rho, par[s.P_RG_I + race], axis)
            r_c = 0.5 * D * n
            # ball surface: w_c z x (p + r_c) + w_R e x r_c; race surface: Omega a x (p + r_c - ring centre), the
            # inner race turning about its (tilted) axis a
            rows.append([np.dot(np.cross([0.0, 0.0, 1.0], p + r_c), t), np.dot(np.cross(e, r_c), t)])
            Omega = omega if race == 0 else 0.0
            rhs.append(Omega * np.dot(np.cross(axis, p + r_c - centre), t))
        A = np.array(rows)
        if np.linalg.det(A) != 0.0:
            speeds.append(np.linalg.solve(A, np.array(rhs))[0])
    return float(np.mean(speeds)) if speeds else 0.0


def bearing_outputs(balls, cage, ring, trib, par, acc, omega, interval, orbit0, c_background, averaged):
    """Bearing-level outputs out[O_*] at inner-ring speed omega (rad/s) after an interval (s)."""
    Z = balls.shape[1]
    Q = contact_loads(balls, ring, par)
    alpha = contact_angles(balls, ring, par)
    out = np.zeros(s.O_SIZE)
    loaded = Q > 0.0
    with_film = loaded & (trib[s.T_Q] > 0.0)
    for race in range(2):
        out[s.O_QMAX_I + race] = Q[race].max()
        if with_film[race].any():
            out[s.O_LAMBDA_I + race] = trib[s.T_LAMBDA, race][with_film[race]].min()
            out[s.O_HMIN_I + race] = trib[s.T_H_MIN, race][with_film[race]].min()
            out[s.O_HC_I + race] = trib[s.T_H_C, race, int(np.argmax(np.where(with_film[race], Q[race], -1.0)))]
    if loaded.any():
        out[s.O_SRR_MAX] = max(trib[s.T_SRR][loaded].max(), 0.0)
        out[s.O_PMAX] = max(trib[s.T_P_MAX][loaded].max(), 0.0)
    out[s.O_REGIME] = ref_ehl.lubrication_regime(min(out[s.O_LAMBDA_I], out[s.O_LAMBDA_O]))
    j = int(np.argmax(Q[0])) if loaded[0].any() else int(np.argmax(Q[1]))
    both = loaded[0] & loaded[1]
    out[s.O_N_LOADED] = both.sum()
    if averaged and interval > 0.0:  # the capacitance integrated over the steps, per unit time
        out[s.O_C_BEARING] = c_background + acc[s.A_CAP] / interval
    else:  # balls loaded on both races now, with the capacitances of the last refresh
        out[s.O_C_BEARING] = c_background + sum(
            ref_capacitance.ball_capacitance(trib[s.T_CAP, 0, k], trib[s.T_CAP, 1, k]) for k in range(Z) if both[k]
        )
    omega_cage = (balls[s.B_ORBIT].sum() - orbit0) / (Z * interval) if interval > 0.0 else 0.0
    out[s.O_OMEGA_CAGE] = omega_cage
    w = balls[s.B_WX : s.B_WX + 3, j]
    out[s.O_OMEGA_BALL] = math.copysign(np.linalg.norm(w), omega) if omega != 0.0 else np.linalg.norm(w)
    out[s.O_OMEGA_BALL_REL] = np.linalg.norm(w - np.array([0.0, 0.0, omega_cage]))
    out[s.O_ALPHA_I] = alpha[0, j]
    out[s.O_ALPHA_O] = alpha[1, j]
    if not averaged:  # the power of the last step
        out[s.O_Q_INNER_RING] = acc[s.A_POWER_I]
        out[s.O_Q_OUTER_RING] = acc[s.A_POWER_O]
    elif interval > 0.0:  # energy over the interval / interval
        out[s.O_Q_INNER_RING] = acc[s.A_DISS_I] / interval
        out[s.O_Q_OUTER_RING] = acc[s.A_DISS_O] / interval
    out[s.O_P_LOSS] = out[s.O_Q_INNER_RING] + out[s.O_Q_OUTER_RING]
    out[s.O_TORQUE] = out[s.O_P_LOSS] / abs(omega) if omega != 0.0 else 0.0
    pure = pure_rolling_cage_speed(balls, ring, par, omega, Q)
    out[s.O_CAGE_SLIP] = 1.0 - omega_cage / pure if pure != 0.0 else 0.0
    out[s.O_KINETIC] = kinetic_energy(balls, cage, ring, par)
    return out


TWINS = {
    "contact_loads": contact_loads,
    "contact_angles": contact_angles,
    "bearing_outputs": bearing_outputs,
    "pure_rolling_cage_speed": pure_rolling_cage_speed,
}


def signed_contact_angles(balls, ring, par):
    """Signed contact angles alpha[race, ball] (rad) as the quasi-static fidelity measures them: the contact
    direction (inner: ball centre to groove-curvature centre, -n; outer: centre to ball centre, n) split into its
    axial component and its component along the outward radial unit vector at the ball, whether open or not."""
    alpha = np.zeros((2, balls.shape[1]))
    for race in range(2):
        centre, rho, axis = race_centre(race, ring, par)
        for j in range(balls.shape[1]):
            p = balls[s.B_X : s.B_X + 3, j]
            d = p - centre
            across = d - np.dot(d, axis) * axis
            e_r = across / np.linalg.norm(across)
            groove_centre = centre + rho * e_r  # the curvature centre in the ball's plane
            direction = groove_centre - p if race == 0 else p - groove_centre
            alpha[race, j] = math.atan2(float(np.dot(direction, axis)), float(np.dot(direction, e_r)))
    return alpha


def shoulder_truncation(balls, ring, par, tp):
    """kernels.truncation TR_* of the current state: loads and signed angles as above, the truncation twin."""
    tr = np.zeros(4)
    ref_truncation.race_truncation(
        contact_loads(balls, ring, par), 0, signed_contact_angles(balls, ring, par), 0, tp, tr
    )
    return tr


TWINS["signed_contact_angles"] = signed_contact_angles
TWINS["shoulder_truncation"] = shoulder_truncation
