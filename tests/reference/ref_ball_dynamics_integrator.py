"""Twin of bearing_fmu.kernels.ball_dynamics: one DEM step (contacts, forces, velocity Verlet) in plain numpy.

Written from the model definition (Guessasma & Machado 2018; Farah et al. 2020; Houpert), not from the
kernel: every body is a 3-vector, every contact is evaluated with vector algebra (np.cross, np.dot,
np.linalg.norm). It shares only the array layout (the kernel's slot constants), so that a state can
be handed to both. The model:
- groove = torus: the nearest point q of the groove-curvature-centre circle to the ball centre p,
  approach delta = |p - q| - (f - 1/2) D, normal n = (p - q)/|p - q|, contact point p + (D/2) n; the inner
  ring's circle is centred on the ring's centre c (its translation plus (0, 0, z_i)) in the plane normal to its
  axis a = R e_z, R the exact rotation by the rotation vector (theta_x, theta_y, 0) (Rodrigues' formula);
- inner ring: translation and tilts (theta_x, theta_y), velocity Verlet as the balls; its angular velocity
  omega a + (theta_x', theta_y', 0); it takes the opposite of every inner contact's force at the contact
  point and the opposite of the contact's resistance moments on the ball; its tilts follow
  I_d theta'' = (M - (M.a) a)_xy - I_p omega (theta' x a)_xy (the drive holds the moment along a; the
  gyroscopic moment of a turning ring whose axis turns), M the applied moments plus the contacts' about c;
- normal force Q + C_n v_n >= 0, Q = K_h delta^1.5 (Hertz), C_n from the last refresh except in the
  boundary regime where C_n = 1.5 alpha_e Q (Guessasma eq. 4 with K_n delta = Q);
- tangential force: the asperities' spring xi (projected on the tangent plane, xi += v_t dt, F_t = -k_t xi
  with k_t = ratio K_h delta^0.5, capped at mu F_n minus the film's share, xi rescaled to the cap, reset when
  the contact opens; absent in a full film) plus the film's EHL traction phi mu_lim F_n (1 - e^(-|v_t|/v_s))
  against v_t, evaluated linearly implicitly (the Coulomb override: the spring alone, capped at mu F_n);
- rolling-resistance moment -M_r q/max(|q|, w_reg, 4 M_r dt/I) with M_r = F_roll (D/2) and q the
  ball's angular velocity relative to its orbiting frame, tangential part; spin moment
  -M_s s/max(|s|, w_reg, 4 M_s dt/I) n, s the spin relative to the race; F_roll = F_R + (F_h + F_H)/2
  (Houpert EHL force on each surface, hysteresis and Heathcote halved), M_s = (3/8) mu Q a E (Jones);
- cage ball between balls k and k + 1, Hertz sphere-sphere with critical damping, frictionless; guide
  channel around the pitch circle (distance from the circle minus the play), critically damped; the cage
  rigid in rotation: each element's torque about z replaced by the mean (the difference as a tangential force);
- velocity Verlet with the velocity predictor v + a dt for the forces; omega linear over the call;
- tribology refreshed at the start of every N-th step: Hertz, entrainment u = |u_b + u_r|/2 of the
  surface velocities relative to the orbiting contact frame, film, Lambda, mu, C_n, capacitance.
The closed-form Houpert pieces (hysteresis (3/16) alpha_h b Q/Rx, Heathcote C_H mu Q a^2/(R_c Rx),
spin (3/8) mu Q a E) are written out here; their quadrature twins are checked in test_torque.
"""

import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from bearing_fmu.kernels import capacitance as capk  # layout constants (CAP_*) only
from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.kernels.lubricant import LUB_EPS_R0, LUB_RHO_REF
from tests.reference import ref_ball_dynamics_contact_law as contacts
from tests.reference import ref_capacitance, ref_ehl, ref_film_correction, ref_hertz, ref_lubricant, ref_torque
from tests.reference.ref_ball_dynamics_contact_law import Z_AXIS, groove_contact

# Heathcote constant C_H = 3I/8: rolling bands at +-c (zero net traction of w(y) ~ 1 - y^2), then
# I = 2 int_0^1 (1 - s^2)|c^2 - s^2| ds (Johnson 1985 ch. 8).
_BAND = brentq(
    lambda c: quad(lambda y: 1 - y * y, 0, c)[0] - quad(lambda y: 1 - y * y, c, 1)[0], 0.01, 0.99, xtol=1e-15
)
HEATHCOTE_C = (
    3.0 / 8.0 * 2.0 * quad(lambda y: (1 - y * y) * abs(_BAND**2 - y * y), 0, 1, points=[_BAND], epsabs=1e-15)[0]
)


def ring_axis(ring):
    """Unit axis of the inner ring: e_z turned by the rotation vector (theta_x, theta_y, 0) (Rodrigues)."""
    theta = np.array([ring[s.R_TH], ring[s.R_TH + 1], 0.0])
    t = np.linalg.norm(theta)
    if t == 0.0:
        return Z_AXIS.copy()
    k = theta / t
    return Z_AXIS * math.cos(t) + np.cross(k, Z_AXIS) * math.sin(t) + k * np.dot(k, Z_AXIS) * (1.0 - math.cos(t))


def race_centre(race, ring, par):
    """(centre (m), radius (m), unit axis) of a race's groove-curvature-centre circle."""
    if race == 0:
        return ring[s.R_X : s.R_X + 3] + np.array([0.0, 0.0, par[s.P_Z_I]]), par[s.P_RHO_I], ring_axis(ring)
    return np.array([0.0, 0.0, par[s.P_Z_O]]), par[s.P_RHO_O], Z_AXIS


def race_rotation(race, ring, omega, tilt_rates):
    """Angular velocity (rad/s) of a race: omega about the inner ring's axis plus its tilt rates; 0 (outer)."""
    if race == 0:
        return omega * ring_axis(ring) + np.array([tilt_rates[0], tilt_rates[1], 0.0])
    return np.zeros(3)


def hertz_of(race, par):
    o = 5 * race
    return (par[s.P_RX_I + o], par[s.P_RY_I + o], par[s.P_K_I + o], par[s.P_EE_I + o], par[s.P_KK_I + o])


def orbit_speed(p, v):
    return (p[0] * v[1] - p[1] * v[0]) / (p[0] ** 2 + p[1] ** 2)


def refresh(st, par, lub, omega, T_oil):
    """Per-contact tribology from the state (the kernel's trib rows)."""
    eta, xi, rho0 = ref_lubricant.lubricant_state(T_oil, lub)
    K_cm = ref_lubricant.clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF])
    balls, ring, trib = st["balls"], st["ring"], st["trib"]
    D = par[s.P_D]
    E_red = par[s.P_E_RED]
    for race in range(2):
        centre, rho, axis = race_centre(race, ring, par)
        W = race_rotation(race, ring, omega, ring[s.R_VTH : s.R_VTH + 2])
        Rx, Ry, k, ell_E, ell_K = hertz_of(race, par)
        for j in range(balls.shape[1]):
            p = balls[s.B_X : s.B_X + 3, j]
            v = balls[s.B_VX : s.B_VX + 3, j]
            w = balls[s.B_WX : s.B_WX + 3, j]
            delta, n = groove_contact(p, centre, rho, par[s.P_RG_I + race], axis)
            trib[:, race, j] = 0.0
            if delta <= 0.0:
                trib[s.T_MU, race, j] = 0.1
                trib[s.T_H_MIN, race, j] = math.inf
                trib[s.T_H_C, race, j] = math.inf
                continue
            Q = par[s.P_KH_I + race] * delta**1.5
            a, b, _, p_max = ref_hertz.hertz_contact(Q, Rx, Ry, E_red, k, ell_E, ell_K)
            w_orb = orbit_speed(p, v)
            u_b = np.cross(w - w_orb * Z_AXIS, 0.5 * D * n)
            r = p + 0.5 * D * n - centre
            u_r = np.cross(W - w_orb * Z_AXIS, r)
            if race == 0:
                u_r = u_r + ring[s.R_VX : s.R_VX + 3]
            u_b = u_b - np.dot(u_b, n) * n
            u_r = u_r - np.dot(u_r, n) * n
            u = 0.5 * np.linalg.norm(u_b + u_r)
            spin = np.dot(w - W, n)
            h_c, h_min = ref_film_correction.corrected_film_thickness(
                int(par[s.P_FILM]), eta, xi, E_red, u, Q, Rx, Ry, k, par[s.P_FILM_TABLE :], race
            )
            lam = ref_ehl.film_parameter(h_min, par[s.P_SIGMA_I + race])
            mu = ref_ehl.friction_coefficient(lam)
            f = par[s.P_F_I + race]
            F_R = ref_torque.houpert_rolling_force(Q, u, Rx, Ry, E_red, eta, xi)
            F_h = 3.0 / 16.0 * par[s.P_ALPHA_H] * b * Q / Rx
            R_c = 2.0 * f * D / (2.0 * f + 1.0)
            F_H = HEATHCOTE_C * mu * Q * a * a / (R_c * Rx)
            M_s = 3.0 / 8.0 * mu * Q * a * ell_E
            if par[s.P_TRACTION] > 0.0:  # the Coulomb override: a spring alone
                trib[s.T_MU, race, j] = ref_ehl.traction_coefficient(lam, par[s.P_TRACTION])
            else:  # asperities' spring at mu(0) for 1 - phi, the film's EHL traction curve for phi
                phi = ref_ehl.film_share(lam)
                trib[s.T_PHI, race, j] = phi
                trib[s.T_MU, race, j] = (1.0 - phi) * ref_ehl.friction_coefficient(0.0) + phi * par[s.P_MU_LIM]
                v_s = max(par[s.P_S_TRACTION] * u, 8.0 / (3.0 * math.pi) * abs(spin) * a)
                trib[s.T_SLIP, race, j] = 1.0 / v_s if v_s > 0.0 else 0.0
            trib[s.T_C_N, race, j] = ref_ehl.normal_damping(lam, Q, par[s.P_ALPHA_E], eta, a, 0.5 * D, h_min)
            trib[s.T_REGIME, race, j] = ref_ehl.lubrication_regime(lam)
            trib[s.T_F_ROLL, race, j] = F_R + 0.5 * (F_h + F_H)
            trib[s.T_M_SPIN, race, j] = M_s
            trib[s.T_P_FILM, race, j] = (2.0 * F_R + F_h + F_H) * u + M_s * abs(spin)
            trib[s.T_Q, race, j] = Q
            trib[s.T_A, race, j] = a
            trib[s.T_B, race, j] = b
            trib[s.T_P_MAX, race, j] = p_max
            trib[s.T_U, race, j] = u
            trib[s.T_SRR, race, j] = np.linalg.norm(u_b - u_r) / u if u > 0.0 else 0.0
            trib[s.T_SPIN, race, j] = spin
            trib[s.T_H_MIN, race, j] = h_min
            trib[s.T_H_C, race, j] = h_c
            trib[s.T_LAMBDA, race, j] = lam
            if par[s.P_CAPACITANCE_BLOCK + capk.CAP_ON]:
                trib[s.T_CAP, race, j] = ref_capacitance.lubricated_contact_capacitance(
                    K_cm,
                    rho0,
                    p_max,
                    int(par[s.P_CAPACITANCE_BLOCK + capk.CAP_PRESSURE]),
                    a,
                    b,
                    h_c,
                    par[s.P_CAPACITANCE_BLOCK + capk.CAP_H_FLOOR],
                    par[s.P_E_RED],
                    par[s.P_CAPACITANCE_BLOCK + capk.CAP_OIL_GAP],
                    outside=ref_capacitance.assembly_outside,
                )


def damped_hertz(K, delta, zeta, m_eff, v_app):
    c = 2.0 * zeta * math.sqrt(1.5 * K * math.sqrt(delta) * m_eff)
    return max(K * delta**1.5 + c * v_app, 0.0)


def forces(st, par, omega, F_ring, vel, dt):
    """Forces (N) and moments (N.m) on every body at the current positions with the predicted velocities
    vel = (v_balls, w_balls, v_cage, v_ring, tilt rates of the ring); F_ring = (F_x, F_y, F_z, M_x, M_y) applied
    to the ring; updates springs, chatter counters and dissipation.
    Returns (f_ball, m_ball, f_cage, f_ring, m_ring (about the ring's centre, 3 components), power dissipated per
    race by the normal damping, [(race, ball, D, contact point from the ball's centre) of each contact whose
    tangential force D dissipates (a slipping spring's and the film's traction)]: step() books D's power at the
    velocities the step ends with)."""
    balls, cage, ring, spring, trib, counters = (st[k] for k in ("balls", "cage", "ring", "spring", "trib", "counters"))
    v_b, w_b, v_c, v_r, tilt_rates = vel
    Z = balls.shape[1]
    D = par[s.P_D]
    f_ball = np.zeros((3, Z))
    m_ball = np.zeros((3, Z))
    f_cage = np.zeros((3, Z))
    f_ring = np.array(F_ring[:3], dtype=float)
    m_ring = np.array([F_ring[3], F_ring[4], 0.0])
    power = np.zeros(2)
    slips = []
    w_reg = par[s.P_V_REG] / (0.5 * D)
    for race in range(2):
        centre, rho, axis = race_centre(race, ring, par)
        W = race_rotation(race, ring, omega, tilt_rates)
        for j in range(Z):
            p = balls[s.B_X : s.B_X + 3, j]
            rows = slice(3 * race, 3 * race + 3)
            kc = s.K_SIZE + race * Z + j
            delta, n = groove_contact(p, centre, rho, par[s.P_RG_I + race], axis)
            if delta <= 0.0:
                spring[rows, j] = 0.0
                counters[kc] = 0
                continue
            tribology = (
                trib[s.T_MU, race, j],
                trib[s.T_PHI, race, j],
                trib[s.T_SLIP, race, j],
                int(trib[s.T_REGIME, race, j]),
                trib[s.T_C_N, race, j],
                trib[s.T_F_ROLL, race, j],
                trib[s.T_M_SPIN, race, j],
            )
            law = dict(
                K_h=par[s.P_KH_I + race],
                D=D,
                alpha_e=par[s.P_ALPHA_E],
                kt_ratio=par[s.P_KT_RATIO],
                mu_lim=par[s.P_MU_LIM],
                kappa=par[s.P_FILM_RATE] * dt / par[s.P_M_BALL],
                w_reg=w_reg,
                rate=par[s.P_I_BALL] / (4.0 * dt) if dt > 0.0 else math.inf,  # dt = 0: the state's accelerations
            )
            w_orbit = orbit_speed(p, v_b[:, j])
            c = contacts.ball_race_contact(
                race, delta, n, p, v_b[:, j], w_b[:, j], w_orbit, spring[rows, j], tribology, (W, v_r, centre), law, dt
            )
            spring[rows, j] = c["spring"]
            counters[kc] = counters[kc] + 1 if c["reversed"] else 0
            if c["dissipating"].any():
                slips.append((race, j, c["dissipating"], c["r_c"]))
            f_ball[:, j] += c["force"]
            m_ball[:, j] += c["moment"]
            if race == 0:  # the race takes the opposite force at the contact point and the opposite moments
                f_ring -= c["force"]
                m_ring -= np.cross(p + c["r_c"] - centre, c["force"]) + c["resistances"]
            power[race] += c["damping"]
    R_sum = 0.5 * D + par[s.P_R_CAGE]
    m_b, m_c = par[s.P_M_BALL], par[s.P_M_CAGE]
    for k in range(Z):
        for j in (k, (k + 1) % Z):
            d = cage[s.C_X : s.C_X + 3, k] - balls[s.B_X : s.B_X + 3, j]
            dist = np.linalg.norm(d)
            if dist < R_sum:
                n = d / dist
                f = damped_hertz(
                    par[s.P_K_CB],
                    R_sum - dist,
                    par[s.P_ZETA_CAGE],
                    m_b * m_c / (m_b + m_c),
                    np.dot(v_b[:, j] - v_c[:, k], n),
                )
                f_cage[:, k] += f * n
                f_ball[:, j] -= f * n
        pc = cage[s.C_X : s.C_X + 3, k]
        R = par[s.P_R_GUIDE]
        q = np.array([R * pc[0], R * pc[1], 0.0]) / math.hypot(pc[0], pc[1]) + np.array([0.0, 0.0, par[s.P_Z_GUIDE]])
        dist = np.linalg.norm(pc - q)
        if dist > par[s.P_GUIDE_GAP]:
            n = (pc - q) / dist
            f = damped_hertz(par[s.P_K_GUIDE], dist - par[s.P_GUIDE_GAP], par[s.P_ZETA_CAGE], m_c, np.dot(v_c[:, k], n))
            f_cage[:, k] -= f * n
    # the cage is rigid in rotation: every element carries the mean torque about z as a tangential force
    torque = np.array([np.cross(cage[s.C_X : s.C_X + 3, k], f_cage[:, k])[2] for k in range(Z)])
    for k in range(Z):
        p = cage[s.C_X : s.C_X + 3, k]
        tangent = np.cross(Z_AXIS, p)
        tangent[2] = 0.0
        f_cage[:, k] += (torque.mean() - torque[k]) / np.dot(tangent, tangent) * tangent
    return f_ball, m_ball, f_cage, f_ring, m_ring, power, slips


def slip_power(st, par, omega, slips):
    """Power (W) per race of the dissipating tangential forces D at the velocities of the state (the end of a step):
    -D . (velocity of the ball's surface - velocity of the race's surface) at each contact point."""
    balls, ring = st["balls"], st["ring"]
    power = np.zeros(2)
    for race, j, D, r_c in slips:
        point = balls[s.B_X : s.B_X + 3, j] + r_c
        v_ball = balls[s.B_VX : s.B_VX + 3, j] + np.cross(balls[s.B_WX : s.B_WX + 3, j], r_c)
        centre, _, _ = race_centre(race, ring, par)
        W = race_rotation(race, ring, omega, ring[s.R_VTH : s.R_VTH + 2])
        v_race = ring[s.R_VX : s.R_VX + 3] + np.cross(W, point - centre) if race == 0 else np.zeros(3)
        power[race] -= np.dot(D, v_ball - v_race)
    return power


def tilt_acceleration(ring, par, omega, m_ring, tilt_rates):
    """(theta_x'', theta_y'') (rad/s^2): the moment across the ring's axis plus the gyroscopic moment
    -I_p omega (theta' x a) and the support's moment -k_t theta - c_t theta', over the moment of inertia about a
    diameter."""
    a = ring_axis(ring)
    across = m_ring - np.dot(m_ring, a) * a
    gyroscopic = -par[s.P_IP_RING] * omega * np.cross(np.array([tilt_rates[0], tilt_rates[1], 0.0]), a)
    support = -par[s.P_KT_SUPPORT] * ring[s.R_TH : s.R_TH + 2] - par[s.P_CT_SUPPORT] * np.asarray(tilt_rates)
    return ((across + gyroscopic)[:2] + support) / par[s.P_I_RING]


def ring_acceleration(ring, par, f_ring, velocity):
    """(x'', y'', z'') (m/s^2): the contacts' and the applied force plus the support's -k x - c v across the axis
    (x, y) and its axial damper's -c_z v_z along it (z), over the mass."""
    support = -par[s.P_K_SUPPORT] * ring[s.R_X : s.R_X + 3] - par[s.P_C_SUPPORT] * velocity
    support[2] = -par[s.P_C_SUPPORT_AXIAL] * velocity[2]
    return (f_ring + support) / par[s.P_M_RING]


def path_point(par, fraction):
    """The prescribed ring's (x, y, z, theta_x, theta_y), their rates and accelerations at `fraction` of the call's
    path (par[P_PATH]: values and rates at its start, then at its end, over par[P_PATH_T] s): the cubic polynomial
    in time through both ends' values and rates, its coefficients solved from the 4 x 4 system of those conditions."""
    T = par[s.P_PATH_T]
    path = par[s.P_PATH : s.P_PATH + 20].reshape(4, 5)
    system = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [1.0, T, T * T, T**3], [0.0, 1.0, 2 * T, 3 * T * T]])
    c = np.linalg.solve(system, path)  # c[k] multiplies t^k, one column per degree of freedom
    t = fraction * T
    value = c[0] + c[1] * t + c[2] * t * t + c[3] * t**3
    rate = c[1] + 2 * c[2] * t + 3 * c[3] * t * t
    return value, rate, 2 * c[2] + 6 * c[3] * t


def step(st, par, omega, F_ring, dt, fraction=1.0):
    """One velocity-Verlet step at inner-ring speed omega (rad/s, end of the step); a prescribed ring
    (par[P_DRIVE]) is put on its path at `fraction` of the call instead. Returns (the power dissipated per race
    (W), the load that holds the ring: F_ring less the contacts' force and moment on it)."""
    balls, cage, ring = st["balls"], st["cage"], st["ring"]
    x, v, a = (balls[r : r + 3] for r in (s.B_X, s.B_VX, s.B_AX))
    w, alpha = balls[s.B_WX : s.B_WX + 3], balls[s.B_ALX : s.B_ALX + 3]
    angle_before = np.arctan2(x[1], x[0])
    x += v * dt + 0.5 * a * dt * dt
    balls[s.B_ORBIT] += np.angle(np.exp(1j * (np.arctan2(x[1], x[0]) - angle_before)))
    xc, vc, ac = (cage[r : r + 3] for r in (s.C_X, s.C_VX, s.C_AX))
    xc += vc * dt + 0.5 * ac * dt * dt
    xr, vr, ar = (ring[r : r + 3] for r in (s.R_X, s.R_VX, s.R_AX))
    xr += vr * dt + 0.5 * ar * dt * dt
    th, vth, ath = (ring[r : r + 2] for r in (s.R_TH, s.R_VTH, s.R_ATH))
    th += vth * dt + 0.5 * ath * dt * dt
    prescribed = par[s.P_DRIVE] != 0.0
    if prescribed:
        value, rate, acceleration = path_point(par, fraction)
        xr[...], vr[...], ar[...] = value[:3], rate[:3], acceleration[:3]
        th[...], vth[...], ath[...] = value[3:], rate[3:], acceleration[3:]
        vel = (v + a * dt, w + alpha * dt, vc + ac * dt, vr.copy(), vth.copy())
    else:
        vel = (v + a * dt, w + alpha * dt, vc + ac * dt, vr + ar * dt, vth + ath * dt)
    f_b, m_b, f_c, f_r, m_r, power, slips = forces(st, par, omega, F_ring, vel, dt)
    reaction = np.asarray(F_ring, dtype=float) - np.concatenate((f_r, m_r[:2]))
    new = (
        f_b / par[s.P_M_BALL],
        m_b / par[s.P_I_BALL],
        f_c / par[s.P_M_CAGE],
        ring_acceleration(ring, par, f_r, vel[3]),
        tilt_acceleration(ring, par, omega, m_r, vel[4]),
    )
    pairs = ((v, a, new[0]), (w, alpha, new[1]), (vc, ac, new[2]))
    if not prescribed:
        pairs += ((vr, ar, new[3]), (vth, ath, new[4]))
    for vel_now, acc_now, acc_new in pairs:
        vel_now += 0.5 * (acc_now + acc_new) * dt
        acc_now[...] = acc_new
    ring[s.R_TIME] += dt
    st["counters"][s.K_STEP] += 1
    # velocity Verlet pairs the step's forces with the velocities it ends with (the kernel's
    # integrator.slip_power_correction says why the predicted ones are not used)
    return power + slip_power(st, par, omega, slips), reaction


def initialise_accelerations(st, par, lub, omega, F_ring, T_oil):
    """Tribology and accelerations of a state at rest in time: forces at the current velocities, no step
    (the springs keep their lengths)."""
    refresh(st, par, lub, omega, T_oil)
    balls, cage, ring = st["balls"], st["cage"], st["ring"]
    saved = st["spring"].copy()
    prescribed = par[s.P_DRIVE] != 0.0
    if prescribed:  # on its path's start
        value, rate, acceleration = path_point(par, 0.0)
        for rows, k in ((slice(s.R_X, s.R_X + 3), slice(0, 3)), (slice(s.R_TH, s.R_TH + 2), slice(3, 5))):
            ring[rows] = value[k]
        ring[s.R_VX : s.R_VX + 3], ring[s.R_VTH : s.R_VTH + 2] = rate[:3], rate[3:]
        ring[s.R_AX : s.R_AX + 3], ring[s.R_ATH : s.R_ATH + 2] = acceleration[:3], acceleration[3:]
    vel = tuple(a[r : r + 3].copy() for a, r in ((balls, s.B_VX), (balls, s.B_WX), (cage, s.C_VX), (ring, s.R_VX)))
    vel += (ring[s.R_VTH : s.R_VTH + 2].copy(),)
    f_b, m_b, f_c, f_r, m_r, _, _ = forces(st, par, omega, F_ring, vel, 0.0)
    st["spring"][...] = saved
    balls[s.B_AX : s.B_AX + 3] = f_b / par[s.P_M_BALL]
    balls[s.B_ALX : s.B_ALX + 3] = m_b / par[s.P_I_BALL]
    cage[s.C_AX : s.C_AX + 3] = f_c / par[s.P_M_CAGE]
    if not prescribed:
        ring[s.R_AX : s.R_AX + 3] = ring_acceleration(ring, par, f_r, vel[3])
        ring[s.R_ATH : s.R_ATH + 2] = tilt_acceleration(ring, par, omega, m_r, vel[4])


def step_capacitance(st, par):
    """Bearing capacitance (F, no background) in the current state: the balls loaded on both races now, each with
    its two contacts' capacitances of the last refresh in series."""
    total = 0.0
    for j in range(st["balls"].shape[1]):
        p = st["balls"][s.B_X : s.B_X + 3, j]
        loaded = []
        for race in (0, 1):
            centre, rho, axis = race_centre(race, st["ring"], par)
            loaded.append(groove_contact(p, centre, rho, par[s.P_RG_I + race], axis)[0] > 0.0)
        if all(loaded):
            total += ref_capacitance.ball_capacitance(st["trib"][s.T_CAP, 0, j], st["trib"][s.T_CAP, 1, j])
    return total


def refresh_sample(trib):
    """One refresh's sample of the averaged state outputs, in the order of acc[A_S_QMAX_I:A_SIZE]: largest load per
    race, largest Hertz pressure, smallest Lambda and h_min per race and h_c of the most loaded contact (0 where a
    race has no loaded contact)."""
    loaded = trib[s.T_Q] > 0.0
    sample = {}
    for race in range(2):
        q = np.where(loaded[race], trib[s.T_Q, race], 0.0)
        any_ = loaded[race].any()
        sample[("qmax", race)] = q.max()
        sample[("lam", race)] = trib[s.T_LAMBDA, race][loaded[race]].min() if any_ else 0.0
        sample[("hmin", race)] = trib[s.T_H_MIN, race][loaded[race]].min() if any_ else 0.0
        sample[("hc", race)] = trib[s.T_H_C, race, int(np.argmax(q))] if any_ else 0.0
    p_max = trib[s.T_P_MAX][loaded].max() if loaded.any() else 0.0
    return np.array(
        [sample[("qmax", 0)], sample[("qmax", 1)], p_max]
        + [sample[(name, race)] for name in ("lam", "hmin", "hc") for race in range(2)]
    )


def advance(st, par, lub, n_steps, dt, omega0, omega1, F_ring, T_oil):
    """n_steps steps (omega linear from omega0 to omega1); returns (energy dissipated per race (J), power
    dissipated per race in the last step (W), capacitance of every step integrated over time (F.s), the averaged
    state outputs' sums in the layout of acc[A_XT:A_SIZE]: the ring's displacement and tilts integrated over the steps,
    the number of refreshes and the sums of their samples, then the orbit watch's integrals of the squares of x, y,
    theta_x, theta_y and of |v_xy|^2 and |theta'|^2, then the load that holds a prescribed ring integrated over the
    steps (0 for a ring the loads move))."""
    refresh_every = int(par[s.P_REFRESH])
    energy = np.zeros(2)
    last = np.zeros(2)
    capacitance = 0.0
    position = np.zeros(5)
    samples = np.zeros(9)
    squares = np.zeros(6)
    reaction = np.zeros(5)
    count = 0
    for n in range(n_steps):
        if st["counters"][s.K_STEP] % refresh_every == 0:
            refresh(st, par, lub, omega0 + (omega1 - omega0) * n / n_steps, T_oil)
            samples += refresh_sample(st["trib"])
            count += 1
        last, held = step(st, par, omega0 + (omega1 - omega0) * (n + 1) / n_steps, F_ring, dt, (n + 1) / n_steps)
        last = last + st["trib"][s.T_P_FILM].sum(axis=1)
        if par[s.P_DRIVE] != 0.0:
            reaction += held * dt
        energy += last * dt
        capacitance += step_capacitance(st, par) * dt
        position += np.concatenate((st["ring"][s.R_X : s.R_X + 3], st["ring"][s.R_TH : s.R_TH + 2])) * dt
        ring = st["ring"]
        v_xy, rates = ring[s.R_VX : s.R_VX + 2], ring[s.R_VTH : s.R_VTH + 2]
        across = np.concatenate((ring[s.R_X : s.R_X + 2], ring[s.R_TH : s.R_TH + 2]))
        squares += np.concatenate((across**2, [v_xy @ v_xy, rates @ rates])) * dt
    return energy, last, capacitance, np.concatenate((position, [count], samples, squares, reaction))


KERNEL_MODULE = "bearing_fmu.kernels.ball_dynamics.integrator"
TWINS = {"advance": advance, "initialise_accelerations": initialise_accelerations}
