"""Twin of bearing_fmu.kernels.ball_dynamics.contact_law: the DEM's ball-race contact law, one contact, in 3-vectors.

Written from the model (module docstring of the kernel; Guessasma & Machado 2018; Farah et al. 2020; Cundall &
Strack 1979; Houpert's resistances), with np.dot, np.cross and np.linalg.norm, and used by the step's twin
(ref_ball_dynamics_integrator.forces), so that the law is written once on this side too:
- groove = torus: the nearest point q of the groove-curvature-centre circle to the ball centre p, approach
  delta = |p - q| - (f - 1/2) D, normal n = (p - q)/|p - q|;
- normal force Q + C_n v_n >= 0, Q = K_h delta^1.5, C_n = 1.5 alpha_e Q in the boundary regime, else the refresh's;
- tangential force: the asperities' spring xi (old spring projected on the tangent plane, plus v_t dt; F = -k_t xi,
  k_t = ratio K_h delta^0.5) capped at mu F_n less the film's plateau, the spring rescaled to the cap; absent in a
  full film; plus the film's traction phi mu_lim F_n (1 - e^(-|v_t| s)) against v_t, linearly implicit:
  F / (1 + kappa dF/dv);
- moments on the ball: the tangential force's at the contact point (D/2) n, the rolling resistance
  -M_r q / max(|q|, w_reg, M_r / rate) (q the ball's angular velocity relative to its orbiting frame, tangential
  part; M_r = F_roll D/2) and the pivoting moment -M_s s / max(|s|, w_reg, M_s / rate) n (s the spin relative to the
  race), rate = I / (4 dt).
"""

import math

import numpy as np

from bearing_fmu.kernels.ehl import REGIME_BOUNDARY

Z_AXIS = np.array([0.0, 0.0, 1.0])


def groove_contact(p, centre, rho, rg, axis=Z_AXIS):
    """(delta, n) of a ball centre p (m) against the circle (centre (m), radius rho (m), unit normal axis); rg =
    (f - 1/2) D (m)."""
    d = p - centre
    radial = d - np.dot(d, axis) * axis
    q = centre + rho * radial / np.linalg.norm(radial)
    gap = p - q
    dist = np.linalg.norm(gap)
    return dist - rg, gap / dist


def groove_approach(px, py, pz, cx, cy, cz, ax, ay, az, rho, rg):
    """groove_contact in the kernel's scalar form: (delta, nx, ny, nz)."""
    delta, n = groove_contact(np.array([px, py, pz]), np.array([cx, cy, cz]), rho, rg, np.array([ax, ay, az]))
    return delta, n[0], n[1], n[2]


def contact_damping(regime, c_frozen, alpha_e, Q):
    """C_n (N.s/m): 1.5 alpha_e Q in the boundary regime (Guessasma 2018 eq. 4 with K_n delta = Q), else c_frozen."""
    return 1.5 * alpha_e * Q if regime == REGIME_BOUNDARY else c_frozen


def tangential_spring(old, n, v_t, dt, k_t, cap):
    """(new spring (m), force on the ball (N), slipping, reversed) of the Cundall-Strack spring: the old spring on
    the tangent plane, lengthened by v_t dt, F = -k_t xi, capped at cap (N) with the spring rescaled to the cap;
    reversed when a slipping spring points against the old one."""
    old = old - np.dot(old, n) * n
    xi = old + v_t * dt
    force = -k_t * xi
    slipping = bool(np.linalg.norm(force) > cap)
    if slipping:
        force = force * cap / np.linalg.norm(force)
        xi = -force / k_t
    return xi, force, slipping, slipping and bool(np.dot(xi, old) < 0.0)


def ball_race_contact(race, delta, n, p, v, w, w_orbit, old, tribology, ring, law, dt):
    """The contact of a ball with one race (race 0 inner, 1 outer), as a dict of 3-vectors and scalars.

    delta (m), n: approach and normal (groove_contact); p, v, w: the ball's centre (m), velocity (m/s) and angular
    velocity (rad/s); w_orbit (rad/s) its orbital speed; old (m) the contact's spring. tribology = (mu, phi, slip
    (s/m), regime, c_frozen (N.s/m), f_roll (N), m_spin (N.m)) of the last refresh; ring = (W (rad/s), v_ring (m/s),
    centre (m)) the inner race's angular velocity, translation and groove-circle centre (ignored for the outer race,
    which is fixed); law = dict(K_h (N/m^1.5), D (m), alpha_e (s/m), kt_ratio, mu_lim, kappa (s/kg), w_reg (rad/s),
    rate (N.m.s)). Keys: force, moment (on the ball, about its centre), resistances (their part of the moment),
    spring, slipping, reversed, damping (W, the normal damper's power), dissipating (N, the tangential force whose
    power is the slip's), r_c (m, contact point from the ball's centre), power (W: damping - dissipating . v_t).
    """
    zero = np.zeros(3)
    if delta <= 0.0:
        return dict(force=zero, moment=zero, resistances=zero, spring=zero, slipping=False, reversed=False,
                    damping=0.0, dissipating=zero, r_c=zero, power=0.0)  # fmt: skip
    mu, phi, slip, regime, c_frozen, f_roll, m_spin = tribology
    W, v_ring, centre = ring if race == 0 else (zero, zero, zero)
    K_h, D = law["K_h"], law["D"]
    Q = K_h * delta**1.5
    r_c = 0.5 * D * n
    v_rel = v + np.cross(w, r_c) - (v_ring + np.cross(W, p + r_c - centre) if race == 0 else zero)
    v_n = np.dot(v_rel, n)
    v_t = v_rel - v_n * n
    c_n = contact_damping(regime, c_frozen, law["alpha_e"], Q)
    F_n = max(Q + c_n * v_n, 0.0)
    F_film = phi * law["mu_lim"] * F_n
    if phi < 1.0:
        k_t = law["kt_ratio"] * K_h * math.sqrt(delta)
        xi, F_t, slipping, reversed_ = tangential_spring(old, n, v_t, dt, k_t, max(mu * F_n - F_film, 0.0))
    else:  # a full film: no elastic stick
        xi, F_t, slipping, reversed_ = zero, zero, False, False
    dissipating = F_t.copy() if slipping else zero
    speed = np.linalg.norm(v_t)
    if F_film > 0.0 and speed > 0.0:
        e = math.exp(-speed * slip)
        f = F_film * (1.0 - e) / (1.0 + law["kappa"] * F_film * slip * e)
        F_t = F_t - f * v_t / speed
        dissipating = dissipating - f * v_t / speed
    q = w - w_orbit * Z_AXIS
    q = q - np.dot(q, n) * n
    spin = np.dot(w - W, n)
    M_roll = f_roll * 0.5 * D
    rate = law["rate"]
    resistances = (
        -M_roll * q / max(np.linalg.norm(q), law["w_reg"], M_roll / rate)
        - m_spin * spin / max(abs(spin), law["w_reg"], m_spin / rate) * n
    )
    damping = c_n * v_n**2 if F_n > 0.0 else 0.0
    return dict(force=-F_n * n + F_t, moment=np.cross(r_c, F_t) + resistances, resistances=resistances, spring=xi,
                slipping=slipping, reversed=reversed_, damping=damping, dissipating=dissipating, r_c=r_c,
                power=damping - np.dot(dissipating, v_t))  # fmt: skip


KERNEL_MODULE = "bearing_fmu.kernels.ball_dynamics.contact_law"
TWINS = {
    "groove_approach": groove_approach,
    "contact_damping": contact_damping,
    "tangential_spring": tangential_spring,
    "ball_race_contact": ball_race_contact,
}
