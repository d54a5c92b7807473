"""Per-contact tribology of the DEM, refreshed every N steps (multirate).

From the instantaneous load and kinematics of each ball-race contact: Hertz semi-axes and pressure
(kernels.hertz), entrainment speed and slide-to-roll ratio, film thickness (kernels.ehl, the scene's
formula), film parameter, regime, mu(Lambda) and C_n(Lambda) (Guessasma & Machado 2018), capacitance
(Farah et al. 2020, kernels.capacitance) and the Houpert resistances (kernels.torque). Between two
refreshes the contact law uses these values (the boundary damping follows the load every step).

Power laws on the fast path (the prototype of this kernel measured them 2x faster fused): with
ln u and ln delta of the contact, the Hamrock-Dowson films and Houpert's rolling force are
exp(c + p ln u + q ln delta), the constants c per race and per lubricant state coming from
tribology_constants(); Q = K_h delta^1.5 makes W's exponent 1.5 q. They are the formulas of
kernels.ehl.film_thickness (Hamrock-Dowson) and kernels.torque.houpert_rolling_force written in logs
(the unit tests check them against those kernels to rounding); the other film formulas call
kernels.ehl.film_thickness itself.

Kinematics at a contact, in the frame that turns with the ball's orbit about z (angular speed
w_orbit): the ball surface moves at u_b = (w - w_orbit z) x (D/2) n, the race surface at
u_r = (W - w_orbit z) x r (r from the ring centre to the contact point, W the race's angular velocity: omega about
its tilted axis plus the tilt rates) + ring velocity; entrainment u = |u_b + u_r|/2 (tangential parts),
SRR = |u_b - u_r|/u. Spin: (w - W).n.
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from ..capacitance import CAP_H_FLOOR, CAP_OIL_GAP, CAP_ON, CAP_PRESSURE, lubricated_contact_capacitance
from ..ehl import (
    FILM_HAMROCK_DOWSON,
    dimensionless_groups,
    film_parameter,
    film_share,
    film_slip_speed,
    film_thickness,
    friction_coefficient,
    lubrication_regime,
    normal_damping,
    traction_coefficient,
)
from ..film_correction import FT_ON, film_ratios
from ..torque import heathcote_force, hysteresis_force, spin_moment
from .contact_law import groove_approach
from .state import (
    A_S_HC_I,
    A_S_HMIN_I,
    A_S_LAMBDA_I,
    A_S_PMAX,
    A_S_QMAX_I,
    A_SAMPLES,
    B_VX,
    B_WX,
    B_X,
    P_ALPHA_E,
    P_ALPHA_H,
    P_CAPACITANCE_BLOCK,
    P_D,
    P_E_RED,
    P_EE_I,
    P_F_I,
    P_FILM,
    P_FILM_TABLE,
    P_HA_I,
    P_HB_I,
    P_HERTZ_SCALE_STRIDE,
    P_HP_I,
    P_K_I,
    P_KH_I,
    P_MU_LIM,
    P_RG_I,
    P_RHO_I,
    P_RHO_O,
    P_RX_I,
    P_RX_O,
    P_RY_I,
    P_S_TRACTION,
    P_SIGMA_I,
    P_TRACTION,
    P_Z_I,
    R_TH,
    R_VTH,
    R_VX,
    R_X,
    T_A,
    T_B,
    T_C_N,
    T_CAP,
    T_F_ROLL,
    T_H_C,
    T_H_MIN,
    T_LAMBDA,
    T_M_SPIN,
    T_MU,
    T_P_FILM,
    T_P_MAX,
    T_PHI,
    T_Q,
    T_REGIME,
    T_SIZE,
    T_SLIP,
    T_SPIN,
    T_SRR,
    T_U,
)

# The refresh loop reads and writes the arrays in one function body: a numba function that receives arrays
# increments and decrements their reference counts at each call (atomic operations), which a call per contact
# would pay 18 times per refresh.

# rows of the per-race constants of the power laws (tribology_constants)
_TC_SLOTS = Layout()
TC_LN_HMIN = _TC_SLOTS.slot()  # ln h_min = TC_LN_HMIN + 0.68 ln u - 0.073 * 1.5 ln delta (Hamrock-Dowson)
TC_LN_HC = _TC_SLOTS.slot()  # ln h_c = TC_LN_HC + 0.67 ln u - 0.067 * 1.5 ln delta
TC_LN_FR = _TC_SLOTS.slot()  # ln F_R = TC_LN_FR + 0.656 ln u + 0.466 * 1.5 ln delta (Houpert)
TC_SIZE = _TC_SLOTS.size

# offset between the inner and the outer block of contact parameters (P_*_I -> P_*_O)
RACE_STRIDE_HERTZ = P_RX_O - P_RX_I  # P_RX_I .. P_KK_I -> P_RX_O .. P_KK_O
RACE_STRIDE_GEOM = P_RHO_O - P_RHO_I  # P_RHO_I, P_Z_I -> P_RHO_O, P_Z_O


@kernel(inline="always")
def ring_axis(theta_x, theta_y):
    """Unit axis (ax, ay, az) of the inner ring tilted by (theta_x, theta_y) (rad): z turned exactly by the rotation
    vector (theta_x, theta_y, 0), i.e. (theta_y, -theta_x, 0) sin(t)/t + z cos(t) with t its length; (theta_y,
    -theta_x, 1) to first order, the quasi-static fidelity's small tilts."""
    t2 = theta_x * theta_x + theta_y * theta_y
    if t2 < 1e-8:  # sin(t)/t and cos(t) by their series, exact to rounding below t = 1e-4
        sinc = 1.0 - t2 / 6.0
        cos = 1.0 - 0.5 * t2
    else:
        t = math.sqrt(t2)
        sinc = math.sin(t) / t
        cos = math.cos(t)
    return theta_y * sinc, -theta_x * sinc, cos


@kernel(inline="always")
def race_circle(race, ring, par):
    """Curvature-centre circle of a race: (cx, cy, cz, ax, ay, az, rho), centre (m), unit axis (-) and radius (m);
    race 0 inner: centred on the ring's centre, in the plane normal to its tilted axis."""
    g = RACE_STRIDE_GEOM * race
    if race == 0:
        ax, ay, az = ring_axis(ring[R_TH], ring[R_TH + 1])
        return ring[R_X], ring[R_X + 1], ring[R_X + 2] + par[P_Z_I], ax, ay, az, par[P_RHO_I]
    return 0.0, 0.0, par[P_Z_I + g], 0.0, 0.0, 1.0, par[P_RHO_I + g]


@kernel
def tribology_constants(par, eta, xi, tc):
    """Fill tc[TC_*, race] for viscosity eta (Pa.s) and pressure-viscosity xi (1/Pa) (> 0).

    With U = eta u/(E' Rx), G = xi E', W = Q/(E' Rx^2), Q = K_h delta^1.5 (SI):
    h_min = 3.63 Rx (1 - e^(-0.68 k)) U^0.68 G^0.49 W^-0.073, h_c = 2.69 Rx (1 - 0.61 e^(-0.73 k))
    U^0.67 G^0.53 W^-0.067 (Hamrock & Dowson 1977), F_R = 2.765 E' Rx^2 (Ry/Rx)^0.35 U^0.656 W^0.466 G^0.022
    (Houpert 1987); everything but u and delta goes into the constants.
    """
    E_red = par[P_E_RED]
    ln_G = math.log(xi * E_red)
    for race in range(2):
        h = RACE_STRIDE_HERTZ * race
        Rx = par[P_RX_I + h]
        Ry = par[P_RY_I + h]
        k = par[P_K_I + h]
        ln_U = math.log(eta / (E_red * Rx))  # U / u
        ln_W = math.log(par[P_KH_I + race] / (E_red * Rx * Rx))  # W / delta^1.5
        tc[TC_LN_HMIN, race] = (
            math.log(3.63 * Rx * (1.0 - math.exp(-0.68 * k))) + 0.68 * ln_U + 0.49 * ln_G - 0.073 * ln_W
        )
        tc[TC_LN_HC, race] = (
            math.log(2.69 * Rx * (1.0 - 0.61 * math.exp(-0.73 * k))) + 0.67 * ln_U + 0.53 * ln_G - 0.067 * ln_W
        )
        tc[TC_LN_FR, race] = (
            math.log(2.765 * E_red * Rx * Rx) + 0.35 * math.log(Ry / Rx) + 0.656 * ln_U + 0.466 * ln_W + 0.022 * ln_G
        )


# refresh_tribology's pieces: scalar functions inlined into its contact loop (inline="always"), which keeps reading
# and writing the arrays itself.
@kernel(inline="always")
def surface_speeds(p, v_xy, w, n, c, w_race, v_race, half_d):
    """(u, slide, spin): the entrainment speed u = |u_b + u_r|/2 and the sliding speed |u_b - u_r| (m/s) of the
    tangential surface velocities, and the spin (w - W).n (rad/s) of a contact with unit normal n = (nx, ny, nz), in
    the frame that turns with the ball's orbit about z (module docstring).

    p = (px, py, pz): the ball's centre (m); v_xy = (vx, vy): its velocity across the axis (m/s); w = (wx, wy, wz):
    its angular velocity (rad/s); c: the race's curvature-centre circle's centre (m); w_race = W, the race's angular
    velocity (rad/s), v_race its centre's velocity (m/s); half_d = D/2 (m)."""
    px, py, pz = p
    vx, vy = v_xy
    wx, wy, wz = w
    nx, ny, nz = n
    cx, cy, cz = c
    wrx, wry, wrz = w_race
    ring_vx, ring_vy, ring_vz = v_race
    w_orbit = (px * vy - py * vx) / (px * px + py * py)
    # ball surface relative to the orbiting contact frame
    qz = wz - w_orbit
    ubx = half_d * (wy * nz - qz * ny)
    uby = half_d * (qz * nx - wx * nz)
    ubz = half_d * (wx * ny - wy * nx)
    # race surface relative to the same frame (the race turns about the ring centre, which moves)
    rx = px + half_d * nx - cx
    ry = py + half_d * ny - cy
    rz = pz + half_d * nz - cz
    s = wrz - w_orbit
    urx = wry * rz - s * ry + ring_vx
    ury = s * rx - wrx * rz + ring_vy
    urz = wrx * ry - wry * rx + ring_vz
    # tangential parts
    un = urx * nx + ury * ny + urz * nz
    urx -= un * nx
    ury -= un * ny
    urz -= un * nz
    un = ubx * nx + uby * ny + ubz * nz
    ubx -= un * nx
    uby -= un * ny
    ubz -= un * nz
    sx = ubx + urx
    sy = uby + ury
    sz = ubz + urz
    u = 0.5 * math.sqrt(sx * sx + sy * sy + sz * sz)
    sx = ubx - urx
    sy = uby - ury
    sz = ubz - urz
    slide = math.sqrt(sx * sx + sy * sy + sz * sz)
    spin = (wx - wrx) * nx + (wy - wry) * ny + (wz - wrz) * nz
    return u, slide, spin


@kernel(inline="always")
def film_and_rolling(u, delta, Q, eta, xi, E_red, contact, film, film_table, race, ln_fr, ln_hmin, ln_hc):
    """(F_R, h_c, h_min): Houpert's EHL rolling force (N) and the central and minimum films (m) of a contact at
    entrainment speed u (m/s), approach delta (m) and load Q (N); contact = (Rx, Ry, k) (m, m, -); film: the
    scene's formula code, film_table: its correction table (film_correction, FT_ON off: none); ln_fr, ln_hmin,
    ln_hc: the race's power-law constants (tribology_constants). No entrainment: no film, no EHL rolling force (as
    the kernels of ehl and torque)."""
    Rx, Ry, k = contact
    if not (u > 0.0 and eta > 0.0):
        return 0.0, 0.0, 0.0
    ln_u = math.log(u)
    ln_d = math.log(delta)
    F_R = math.exp(ln_fr + 0.656 * ln_u + 0.699 * ln_d)
    if film == FILM_HAMROCK_DOWSON:
        h_min = math.exp(ln_hmin + 0.68 * ln_u - 0.1095 * ln_d)
        h_c = math.exp(ln_hc + 0.67 * ln_u - 0.1005 * ln_d)
    else:
        h_c, h_min = film_thickness(film, eta, xi, E_red, u, Q, Rx, Ry, k)
    if film_table[FT_ON] > 0.5:  # the scene's film correction: the numerical / formula ratios of the film table
        U, G, W = dimensionless_groups(eta, xi, E_red, u, Q, Rx)
        r_c, r_min = film_ratios(film_table, race, film, U, G, W)
        h_c *= r_c
        h_min *= r_min
    return F_R, h_c, h_min


@kernel(inline="always")
def tangential_law(lam, traction, mu_boundary, mu_lim, s_0, u, spin, a):
    """(mu, phi, slip) of the contact law's tangential force at film parameter lam: the asperities' share (1 - phi)
    a Coulomb spring at the boundary mu, the film's share phi the EHL traction curve of the sliding speed
    (contact_law.ball_race_contact) with slip = 1/v_s (s/m); the Coulomb override (traction > 0) keeps a spring
    alone, capped at the ramp to its full-film value."""
    if traction > 0.0:
        return traction_coefficient(lam, traction), 0.0, 0.0
    phi = film_share(lam)
    # the sliding speed that sets the curve's slope: the creep scale s_0 u, or, in a contact that spins, the spin's
    # own sliding across the ellipse (SPIN_SLIP |spin| a, ehl.film_slip_speed)
    v_s = film_slip_speed(s_0, u, spin, a)
    slip = 1.0 / v_s if v_s > 0.0 else 0.0  # (0: no entrainment, or one that underflows)
    return (1.0 - phi) * mu_boundary + phi * mu_lim, phi, slip


@kernel
def refresh_tribology(omega, eta, xi, K_cm, rho0, balls, ring, par, trib, tc, geo):
    """Recompute trib[:, race, ball] of every ball-race contact from the current state (positions and
    velocities at a step).

    omega: inner-ring speed (rad/s); eta (Pa.s), xi (1/Pa), K_cm (m^3/kg), rho0 (kg/m^3): lubricant
    state; tc: its power-law constants (tribology_constants); geo: float64[4, Z], scratch for the contacts' approaches
    and normals.
    """
    E_red = par[P_E_RED]
    D = par[P_D]
    half_d = 0.5 * D
    film = int(par[P_FILM])
    film_table = par[P_FILM_TABLE:]
    cb = P_CAPACITANCE_BLOCK
    capacitance = par[cb + CAP_ON] > 0.5
    pressure = int(par[cb + CAP_PRESSURE])
    traction = par[P_TRACTION]
    mu_lim = par[P_MU_LIM]
    s_0 = par[P_S_TRACTION]
    mu_boundary = friction_coefficient(0.0)
    for race in range(2):
        h = RACE_STRIDE_HERTZ * race
        cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
        rg = par[P_RG_I + race]
        K_h = par[P_KH_I + race]
        Rx = par[P_RX_I + h]
        ell_E = par[P_EE_I + h]
        contact = (Rx, par[P_RY_I + h], par[P_K_I + h])
        scale_a = par[P_HA_I + P_HERTZ_SCALE_STRIDE * race]
        scale_b = par[P_HB_I + P_HERTZ_SCALE_STRIDE * race]
        scale_p = par[P_HP_I + P_HERTZ_SCALE_STRIDE * race]
        sigma = par[P_SIGMA_I + race]
        f_groove = par[P_F_I + race]
        # the race's angular velocity: omega about its (tilted) axis plus the tilt rates; the outer race is fixed
        w_race = (
            omega * ax + ring[R_VTH] if race == 0 else 0.0,
            omega * ay + ring[R_VTH + 1] if race == 0 else 0.0,
            omega * az if race == 0 else 0.0,
        )
        v_race = (
            ring[R_VX] if race == 0 else 0.0,
            ring[R_VX + 1] if race == 0 else 0.0,
            ring[R_VX + 2] if race == 0 else 0.0,
        )
        ln_fr = tc[TC_LN_FR, race]
        ln_hmin = tc[TC_LN_HMIN, race]
        ln_hc = tc[TC_LN_HC, race]
        # the approaches and normals first, in a loop of their own: each is a chain of two square roots and a
        # division that the processor overlaps between the balls in a short loop, not inside the long one below
        for j in range(balls.shape[1]):
            delta, nx, ny, nz = groove_approach(
                balls[B_X, j], balls[B_X + 1, j], balls[B_X + 2, j], cx, cy, cz, ax, ay, az, rho, rg
            )
            geo[0, j] = delta
            geo[1, j] = nx
            geo[2, j] = ny
            geo[3, j] = nz
        for j in range(balls.shape[1]):
            delta = geo[0, j]
            if delta <= 0.0:
                for t in range(T_SIZE):
                    trib[t, race, j] = 0.0
                trib[T_MU, race, j] = friction_coefficient(0.0)
                trib[T_H_MIN, race, j] = math.inf
                trib[T_H_C, race, j] = math.inf
                continue
            root = math.sqrt(delta)
            Q = K_h * delta * root
            # Hertz semi-axes and pressure grow as Q^(1/3) = K_h^(1/3) delta^(1/2): scaled from kernels.hertz at 1 N
            a = scale_a * root
            b = scale_b * root
            p_max = scale_p * root
            u, slide, spin = surface_speeds(
                (balls[B_X, j], balls[B_X + 1, j], balls[B_X + 2, j]),
                (balls[B_VX, j], balls[B_VX + 1, j]),
                (balls[B_WX, j], balls[B_WX + 1, j], balls[B_WX + 2, j]),
                (geo[1, j], geo[2, j], geo[3, j]),
                (cx, cy, cz),
                w_race,
                v_race,
                half_d,
            )
            F_R, h_c, h_min = film_and_rolling(
                u, delta, Q, eta, xi, E_red, contact, film, film_table, race, ln_fr, ln_hmin, ln_hc
            )
            lam = film_parameter(h_min, sigma)
            mu = friction_coefficient(lam)  # the papers' mu(Lambda): the Houpert sliding terms below
            mu_t, phi, slip = tangential_law(lam, traction, mu_boundary, mu_lim, s_0, u, spin, a)
            trib[T_MU, race, j] = mu_t
            trib[T_PHI, race, j] = phi
            trib[T_SLIP, race, j] = slip
            trib[T_C_N, race, j] = normal_damping(lam, Q, par[P_ALPHA_E], eta, a, half_d, h_min)
            trib[T_REGIME, race, j] = lubrication_regime(lam)
            # Houpert forces (F_R above, the others from kernels.torque); the contact's power as
            # kernels.torque.contact_losses defines it:
            # EHL 2 F_R u (both surfaces), hysteresis F_h u, Heathcote F_H u, spin M_s |spin|
            F_hh = hysteresis_force(Q, b, Rx, par[P_ALPHA_H]) + heathcote_force(Q, a, Rx, f_groove, D, mu)
            M_s = spin_moment(Q, a, ell_E, mu)
            # per surface: F_R on each, hysteresis and Heathcote split evenly
            trib[T_F_ROLL, race, j] = F_R + 0.5 * F_hh
            trib[T_M_SPIN, race, j] = M_s
            trib[T_P_FILM, race, j] = (2.0 * F_R + F_hh) * u + M_s * abs(spin)
            trib[T_Q, race, j] = Q
            trib[T_A, race, j] = a
            trib[T_B, race, j] = b
            trib[T_P_MAX, race, j] = p_max
            trib[T_U, race, j] = u
            trib[T_SRR, race, j] = slide / u if u > 0.0 else 0.0
            trib[T_SPIN, race, j] = spin
            trib[T_H_MIN, race, j] = h_min
            trib[T_H_C, race, j] = h_c
            trib[T_LAMBDA, race, j] = lam
            if capacitance:
                trib[T_CAP, race, j] = lubricated_contact_capacitance(
                    K_cm, rho0, p_max, pressure, a, b, h_c, par[cb + CAP_H_FLOOR], E_red, par[cb + CAP_OIL_GAP]
                )
            else:
                trib[T_CAP, race, j] = 0.0


# What advance takes from each refresh, inlined into it.
@kernel(inline="always")  # called once per refresh from advance: no array-passing call
def film_losses(trib):
    """(inner, outer): the film's own losses (W, Houpert) summed over each race's contacts, constant between two
    refreshes."""
    film_i = 0.0
    film_o = 0.0
    for j in range(trib.shape[2]):
        film_i += trib[T_P_FILM, 0, j]
        film_o += trib[T_P_FILM, 1, j]
    return film_i, film_o


@kernel(inline="always")  # called once per refresh from advance: no array-passing call
def sample_refresh(trib, acc):
    """Add this refresh's loads, pressure and films to the sums acc[A_S_*] (one sample, acc[A_SAMPLES] += 1): per
    race the largest load, the smallest Lambda and h_min and the central film of the most loaded contact among
    the loaded ones (0 without one), and the largest Hertz pressure; their means over a call are the averaged
    state outputs (models.dem, averaged_state)."""
    p_max = 0.0
    for race in range(2):
        q_max = 0.0
        lam = math.inf
        h_min = math.inf
        h_c = 0.0
        for j in range(trib.shape[2]):
            q = trib[T_Q, race, j]
            if q > 0.0:
                p_max = max(p_max, trib[T_P_MAX, race, j])
                lam = min(lam, trib[T_LAMBDA, race, j])
                h_min = min(h_min, trib[T_H_MIN, race, j])
                if q > q_max:
                    q_max = q
                    h_c = trib[T_H_C, race, j]
        acc[A_S_QMAX_I + race] += q_max
        if q_max > 0.0:
            acc[A_S_LAMBDA_I + race] += lam
            acc[A_S_HMIN_I + race] += h_min
            acc[A_S_HC_I + race] += h_c
    acc[A_S_PMAX] += p_max
    acc[A_SAMPLES] += 1.0
