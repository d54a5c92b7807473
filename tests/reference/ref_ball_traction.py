"""Twin of bearing_fmu.kernels.ball_traction: a ball's steady kinematics from the film's traction, in 3-D vectors.

Written from docs/quasistatic.md ("Race control from traction") in inertial vectors, not from the kernel's
components: the ball's centre at (d_m/2) e_r moving at w_m e_a x r_c; its surface at a contact point c at
v_c + W x (c - r_c); the race's at w_race e_a x c; the sliding velocity is their difference projected on the contact
plane, the traction F = -|F|(v) v/|v| with |F| = Q ((1 - phi) mu_b + phi mu_lim)(1 - exp(-|v|/v_s)); the rolling
resistance opposes the ball's angular velocity relative to the orbiting frame (normal part removed), the pivoting
moment its spin relative to the race, both regularised by sqrt(w^2 + w_reg^2); the gyroscopic moment is
w_m e_a x (J W). Residual: the orbit component of the force sum and the moment sum minus dH/dt, solved with
scipy's hybrid Powell root finder (scipy.optimize.root). The film and Houpert's forces come from the twins of
kernels.ehl and kernels.torque.
"""

import math

import numpy as np
from scipy.optimize import root

from tests.reference import ref_ehl, ref_torque

TR_STRIDE = 8
E_A = np.array([0.0, 0.0, 1.0])  # bearing axis; the ball's plane is x (radial) - z (axial), the orbit along +y
E_R = np.array([1.0, 0.0, 0.0])
E_T = np.array([0.0, 1.0, 0.0])
V_REG = 1e-3  # m/s
SPIN_SLIP = 8.0 / (3.0 * math.pi)


def _contact_vectors(a, outer, D, dm):
    """Unit vector from the ball's centre to the contact and the contact point (from the bearing axis)."""
    sign = 1.0 if outer else -1.0
    n = sign * (math.sin(a) * E_A + math.cos(a) * E_R)
    return n, 0.5 * dm * E_R + 0.5 * D * n


def contact(race, a, Q, y, omega, D, dm, tr):
    """Force (N) and moment about the ball's centre (N.m) of one contact on the ball, with (power (W), u (m/s))."""
    w_m = y[0]
    W = y[2] * E_R + y[3] * E_T + y[1] * E_A
    n, c = _contact_vectors(a, race == 1, D, dm)
    w_race = omega if race == 0 else 0.0
    centre = 0.5 * dm * E_R
    v_ball = np.cross(w_m * E_A, centre) + np.cross(W, c - centre)
    v_race = np.cross(w_race * E_A, c)
    tangential = lambda v: v - np.dot(v, n) * n  # noqa: E731
    s = tangential(v_ball - v_race)
    # entrainment: both surfaces relative to the frame orbiting at w_m
    u = 0.5 * np.linalg.norm(tangential(v_ball - np.cross(w_m * E_A, c) + v_race - np.cross(w_m * E_A, c)))
    spin = np.dot(W - w_race * E_A, n)
    o = TR_STRIDE * race
    a_y, b_x = tr[o + 0] * Q ** (1 / 3), tr[o + 1] * Q ** (1 / 3)
    Rx, Ry, k, f, sigma = tr[o + 3], tr[o + 4], tr[o + 5], tr[o + 6], tr[o + 7]
    mu_lim, s_0, eta, xi, E_red, alpha_h, film = tr[16:23]
    h_min = ref_ehl.film_thickness(int(film), eta, xi, E_red, u, Q, Rx, Ry, k)[1]
    lam = ref_ehl.film_parameter(h_min, sigma)
    phi = min(max((lam - 1.0) / 2.0, 0.0), 1.0)
    mu = ref_ehl.friction_coefficient(lam)
    v_s = max(s_0 * u, SPIN_SLIP * abs(spin) * a_y)
    v = np.linalg.norm(s)
    magnitude = Q * ((1 - phi) * ref_ehl.friction_coefficient(0.0) + phi * mu_lim) * (-math.expm1(-v / v_s))
    F = -magnitude * s / v if v > 0 else np.zeros(3)
    f_roll = ref_torque.houpert_rolling_force(Q, u, Rx, Ry, E_red, eta, xi) + 0.5 * (
        ref_torque.hysteresis_force(Q, b_x, Rx, alpha_h) + ref_torque.heathcote_force(Q, a_y, Rx, f, D, mu)
    )
    w_reg = V_REG / (0.5 * D)
    q = tangential(W - w_m * E_A)
    M_roll = -f_roll * 0.5 * D * q / math.sqrt(q @ q + w_reg**2)
    M_spin = -ref_torque.spin_moment(Q, a_y, tr[o + 2], mu) * spin / math.sqrt(spin**2 + w_reg**2) * n
    M = np.cross(c - centre, F) + M_roll + M_spin
    return F, M, magnitude * v, u, n


def residual(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr):
    """(orbit force, moments minus dH/dt over D/2) (N), the kernel's order: (t, a, r, t) components."""
    Fi, Mi = contact(0, a_i, Q_i, y, omega, D, dm, tr)[:2]
    Fo, Mo = contact(1, a_o, Q_o, y, omega, D, dm, tr)[:2]
    W = y[2] * E_R + y[3] * E_T + y[1] * E_A
    dH = np.cross(y[0] * E_A, J * W)
    M = (Mi + Mo - dH) / (0.5 * D)
    return np.array([np.dot(Fi + Fo, E_T), M[2], M[0], M[1]])


def traction_eval(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr):
    """Residuals and contact outputs as the kernel's TE_* order (list)."""
    Fi, _, Pi, ui, ni = contact(0, a_i, Q_i, y, omega, D, dm, tr)
    Fo, _, Po, uo, no = contact(1, a_o, Q_o, y, omega, D, dm, tr)
    # in-plane traction along the kernel's tau = (-u_r, u_a) in (a, r) components of u = n
    tau_i = -ni[0] * E_A + ni[2] * E_R
    tau_o = -no[0] * E_A + no[2] * E_R
    r = residual(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr)
    mu_i = np.linalg.norm(Fi) / Q_i
    mu_o = np.linalg.norm(Fo) / Q_o
    return list(r) + [Fi @ tau_i, Fo @ tau_o, Pi, Po, ui, uo, mu_i, mu_o]


def rolling_start(a_i, a_o, omega, D, dm):
    """Outer-race control (Harris & Kotzalas 2006, vol. 2 ch. 1): zero outer spin, rolling at both contacts."""
    g = D / dm
    beta = math.atan(math.sin(a_o) / (math.cos(a_o) + g))
    w_m = omega / (
        1.0 + (1.0 + g * math.cos(a_o)) * math.cos(a_i - beta) / ((1.0 - g * math.cos(a_i)) * math.cos(a_o - beta))
    )
    w_R = -w_m * (1.0 + g * math.cos(a_o)) / (g * math.cos(a_o - beta))
    return np.array([w_m, w_m + w_R * math.cos(beta), -w_R * math.sin(beta), 0.0])


def solve_traction(a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, start=None):
    """The kinematics y (rad/s) from the residual's root, started at outer-race control (or `start`)."""
    y0 = rolling_start(a_i, a_o, omega, D, dm) if start is None else np.asarray(start, float)
    sol = root(
        lambda z: residual(z * omega, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr) / (Q_i + Q_o),
        y0 / omega,
        method="hybr",
        options={"xtol": 1e-14},
    )
    y = sol.x * omega
    # converged when the residual is at rounding of the loads (hybr may stop short of xtol there and say so)
    return y, bool(np.abs(residual(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr)).max() <= 1e-9 * (Q_i + Q_o))


def parameter_derivatives(a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, y, h=1e-5):
    """d(w_m, F_tau_i, F_tau_o)/d(a_i, a_o, Q_i, Q_o) by central differences of re-solved kinematics (3 x 4)."""
    p = np.array([a_i, a_o, Q_i, Q_o], float)
    out = np.zeros((3, 4))
    for c in range(4):
        step = h if c < 2 else h * p[c]
        values = []
        for sgn in (1.0, -1.0):
            q = p.copy()
            q[c] += sgn * step
            z, ok = solve_traction(*q, omega, D, dm, J, tr, start=y)
            assert ok
            te = traction_eval(z, *q, omega, D, dm, J, tr)
            values.append(np.array([z[0], te[4], te[5]]))
        out[:, c] = (values[0] - values[1]) / (2.0 * step)
    return out


KERNEL_MODULE = "bearing_fmu.kernels.ball_traction"
TWINS = {
    "traction_eval": traction_eval,
    "rolling_start": rolling_start,
    "solve_traction": solve_traction,
    "parameter_derivatives": parameter_derivatives,
}
