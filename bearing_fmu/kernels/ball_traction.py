"""Ball kinematics from the lubricant's traction: the quasi-static race control "traction" (docs/quasistatic.md, 2).

No race-control hypothesis: a ball's orbital speed w_m and its angular velocity W follow from its steady force and
moment balance with the tangential forces the film transmits, as in the quasi-static skidding analyses of
high-speed ball bearings (Harris 1971, J. Lubr. Technol. 93(1) 17-24, ball motion in thrust-loaded angular-contact
bearings with Coulomb and viscous surface friction; Gupta's ADORE in its steady limit, Gupta 1984, Advanced
Dynamics of Rolling Elements, Springer). The contact law is the DEM's (kernels.ball_dynamics.contact_law), so that the
two fidelities describe one bearing:
- tangential force at the contact centre against the sliding velocity s (ball surface minus race surface),
  |F| = Q ((1 - phi) mu_b + phi mu_lim)(1 - exp(-|s| / v_s)): the film's share phi (ehl.film_share) of the EHL
  traction curve (ehl.film_traction_coefficient) and the asperities' share at the boundary coefficient mu_b, the
  latter with the film's knee (in steady sliding the DEM's Coulomb spring sits at its cap; below the knee it
  sticks, which a steady state cannot tell from a steep curve). v_s = max(s_0 u, (8 / 3 pi) |spin| a)
  (ehl.film_slip_speed): the spin's sliding across the ellipse is the integral over the contact of the
  saturated spinning Hertz contact linearised in the centre's slip (Johnson 1985, Contact Mechanics, ch. 8);
- Houpert's resistances as moments on the ball: (F_R + (F_h + F_H)/2)(D/2) against its rolling relative to the
  orbiting contact frame, and the pivoting moment M_s against its spin relative to the race (kernels.torque).

Frame of a ball (right-handed): e_r radial outward, e_t along the orbit, e_a along the bearing axis; the contact
angles in the ball's (axial, radial) plane as in kernels.jones_harris. The unit vector from the ball's centre to
its outer contact is (sin a_o, cos a_o), to its inner contact -(sin a_i, cos a_i) ((a, r) components). The ball's
centre runs on the pitch circle d_m/2 at w_m; its angular velocity is W = (W_a, W_r, W_t) (inertial); the inner
race turns at omega, the outer one is fixed. In steady state W is constant in the orbiting frame, so the contact
moments equal dH/dt = J w_m e_a x W = J w_m (W_r e_t - W_t e_r), J = m D^2 / 10. Four equations in
y = (w_m, W_a, W_r, W_t): the forces along the orbit sum to zero (no cage force, no drag: the cage speed is the
balls' mean orbital speed) and the three moment components balance. The in-plane traction forces they leave then
enter the ball's force balance in kernels.jones_harris in place of a hypothesis' share lam M_g / D of the
gyroscopic moment; Mg_o = -F_tau,o and Mg_i = -F_tau,i in that kernel's sign.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .ehl import (
    FILM_MASJEDI_KHONSARI,
    SPIN_SLIP,
    film_parameter,
    film_share,
    film_slip_speed,
    film_thickness,
    friction_coefficient,
)
from .elimination import gauss_solve
from .torque import heathcote_force, houpert_rolling_force, hysteresis_force, spin_moment

# layout of the traction block (at the offset the quasi-static array gives it): per race, inner then outer
_TR_RACE_SLOTS = Layout()  # one race's block
TR_A1 = _TR_RACE_SLOTS.slot()  # semi-major axis of the contact ellipse at 1 N (m): a = TR_A1 Q^(1/3)
TR_B1 = _TR_RACE_SLOTS.slot()  # semi-minor axis at 1 N (m)
TR_EE = _TR_RACE_SLOTS.slot()  # complete elliptic integral of the second kind of the contact (-)
TR_RX = _TR_RACE_SLOTS.slot()  # reduced radius along the rolling direction (m)
TR_RY = _TR_RACE_SLOTS.slot()  # reduced radius across it (m)
TR_K = _TR_RACE_SLOTS.slot()  # ellipticity a/b (-)
TR_F = _TR_RACE_SLOTS.slot()  # groove conformity r/D (-)
TR_SIGMA = _TR_RACE_SLOTS.slot()  # composite roughness (m)
TR_STRIDE = _TR_RACE_SLOTS.size
_TR_SLOTS = Layout()
_TR_SLOTS.slot(2 * TR_STRIDE)  # the races' blocks, inner then outer, from 0
TR_MU_LIM = _TR_SLOTS.slot()  # limiting traction coefficient of the film (-)
TR_S0 = _TR_SLOTS.slot()  # slide-to-roll ratio of the traction curve's knee (-)
TR_ETA = _TR_SLOTS.slot()  # viscosity at the oil temperature (Pa.s), set at each evaluation
TR_XI = _TR_SLOTS.slot()  # pressure-viscosity coefficient at the oil temperature (1/Pa), set at each evaluation
TR_E_RED = _TR_SLOTS.slot()  # reduced modulus (Pa)
TR_ALPHA_H = _TR_SLOTS.slot()  # hysteresis loss factor (-)
TR_FILM = _TR_SLOTS.slot()  # film formula code (kernels.ehl)
TR_SIZE = _TR_SLOTS.size

# the kinematic state of a ball, y = (w_m, W_a, W_r, W_t) (rad/s); per contact outputs of traction_eval's out
_TE_SLOTS = Layout()
TE_R = _TE_SLOTS.slot(4)  # four residuals (N): orbit force, then the (a, r, t) moments over D/2
# in-plane (transverse) traction force on the ball at the inner contact (N), along (cos a_i, -sin a_i)
TE_FTAU_I = _TE_SLOTS.slot()
TE_FTAU_O = _TE_SLOTS.slot()  # the same at the outer contact (N), along (-cos a_o, sin a_o)
TE_P_I = _TE_SLOTS.slot()  # power of the inner contact's traction against its sliding (W)
TE_P_O = _TE_SLOTS.slot()
TE_U_I = _TE_SLOTS.slot()  # entrainment speed of the inner contact (m/s)
TE_U_O = _TE_SLOTS.slot()
TE_MU_I = _TE_SLOTS.slot()  # traction coefficient the inner contact transmits, |F| / Q (-)
TE_MU_O = _TE_SLOTS.slot()
TE_SIZE = _TE_SLOTS.size

V_REG = 1e-3  # m/s: the resistances' directions are regularised below it (the DEM's, models.dem.packing)
_TOL = 1e-12  # residual of the ball's kinematics relative to its contact loads
_MAXIT = 60
_TRIES = 30  # step halvings of the line search
_FILM_ROUNDS = 6  # Newton solves with the film terms of the last solution, at most


@kernel(inline="always")
def _surfaces(ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm):
    """Kinematics of one contact: (s_t, s_tau, spin, u, q_a, q_r): the sliding of the ball's surface over the race's
    at the contact centre along e_t and tau = (-ur, ua) (m/s), the spin relative to the race (rad/s), the entrainment
    speed (m/s, both surfaces relative to the frame that orbits with the ball) and the in-plane part of the ball's
    angular velocity relative to that frame, normal part removed (rad/s). (ua, ur): unit vector from the ball's
    centre to the contact; w_race (rad/s) the race's speed."""
    half = 0.5 * D
    rho = 0.5 * dm + half * ur  # radius of the contact point
    roll = half * (Wa * ur - Wr * ua)
    s_t = w_m * 0.5 * dm + roll - w_race * rho
    s_tau = half * Wt
    spin = (Wa - w_race) * ua + Wr * ur
    u_t = roll - w_m * half * ur + (w_race - w_m) * rho
    qa = Wa - w_m
    qr = Wr
    qn = qa * ua + qr * ur
    return s_t, s_tau, spin, 0.5 * math.sqrt(u_t * u_t + s_tau * s_tau), qa - qn * ua, qr - qn * ur


# columns of a contact's terms (a row per race): the load's, held through a solve, and the film's (_film)
_TT_SLOTS = Layout()
TT_A = _TT_SLOTS.slot()  # semi-major axis of the contact ellipse (m)
TT_Q = _TT_SLOTS.slot()  # load (N)
TT_HYST = _TT_SLOTS.slot()  # half the hysteresis force (N)
TT_HEATH = _TT_SLOTS.slot()  # half the Heathcote force per unit friction coefficient (N)
TT_SPIN = _TT_SLOTS.slot()  # pivoting moment per unit friction coefficient (N.m)
TT_C_R = _TT_SLOTS.slot()  # Houpert's EHL rolling force at u = 1 m/s (N); it grows as u^0.656
TT_PHI = _TT_SLOTS.slot()  # the film's share of the tangential force (-)
TT_MU = _TT_SLOTS.slot()  # mu(Lambda) of the papers (-): Houpert's sliding terms
TT_DPHI = _TT_SLOTS.slot()  # d phi / dQ at the film's entrainment speed (1/N)
TT_DMU = _TT_SLOTS.slot()  # d mu / dQ at the film's entrainment speed (1/N)
# Lambda of the film last evaluated (-), at the entrainment speed TT_U_FILM (m/s) and load TT_Q_FILM (N)
TT_LAM = _TT_SLOTS.slot()
TT_U_FILM = _TT_SLOTS.slot()
TT_Q_FILM = _TT_SLOTS.slot()
TT_C_R1 = _TT_SLOTS.slot()  # Houpert's EHL rolling force at u = 1 m/s and Q = 1 N (N), once per traction block
TT_SIZE = _TT_SLOTS.size
# exponents of the load terms in Q (N): a ~ Q^(1/3) (Hertz), the hysteresis force ~ b Q, Heathcote's ~ Q a^2, the
# pivoting moment ~ Q a (kernels.torque), Houpert's EHL rolling force ~ W^0.466 (torque.houpert_rolling_force)
_E_A = 1.0 / 3.0
_E_HYST = 4.0 / 3.0
_E_HEATH = 5.0 / 3.0
_E_SPIN = 4.0 / 3.0
_E_C_R = 0.466


@kernel(inline="always")
def _load_terms(race, Q, D, tr, terms):
    """The contact's terms that follow its load Q (N) alone into terms[race] (TT_A .. TT_C_R). Houpert's rolling force
    is its value at 1 N (TT_C_R1, evaluated once for the traction block tr) times Q^0.466, its power of the load."""
    o = TR_STRIDE * race
    ln_q = math.log(Q)
    q3 = math.exp(ln_q / 3.0)  # Q^(1/3)
    a = tr[o + TR_A1] * q3
    Rx = tr[o + TR_RX]
    terms[race, TT_A] = a
    terms[race, TT_Q] = Q
    terms[race, TT_HYST] = 0.5 * hysteresis_force(Q, tr[o + TR_B1] * q3, Rx, tr[TR_ALPHA_H])
    terms[race, TT_HEATH] = 0.5 * heathcote_force(Q, a, Rx, tr[o + TR_F], D, 1.0)
    terms[race, TT_SPIN] = spin_moment(Q, a, tr[o + TR_EE], 1.0)
    if terms[race, TT_C_R1] == 0.0:
        terms[race, TT_C_R1] = houpert_rolling_force(1.0, 1.0, Rx, tr[o + TR_RY], tr[TR_E_RED], tr[TR_ETA], tr[TR_XI])
    terms[race, TT_C_R] = terms[race, TT_C_R1] * math.exp(_E_C_R * ln_q)


@kernel(inline="always")
def _film(race, u, tr, terms):
    """The contact's film terms at entrainment speed u (m/s) into terms[race] (TT_PHI, TT_MU): the film share and
    mu(Lambda) of its minimum film (the scene's formula); returns True when they changed (beyond 1e-12).

    Both are flat for Lambda <= 1 and Lambda > 3. Every film formula has Lambda ~ u^e_u Q^e_Q with 0 < e_u < 0.72 and
    -0.1 < e_Q < 0 (ellipticity k >= 1): within 1 % of the entrainment speed and 5 % of the load of the film last
    evaluated (TT_LAM, TT_U_FILM, TT_Q_FILM), Lambda stays within 1.3 % of its value, so a film that was 3 % inside a
    flat stretch keeps its terms, unchanged, without evaluating the film. terms is therefore tied to one traction
    block tr (its viscosity, roughness and radii): zero TT_LAM and TT_C_R1 when tr changes."""
    o = TR_STRIDE * race
    Q = terms[race, TT_Q]
    lam = terms[race, TT_LAM]
    if (lam > 1.03 * 3.0 or lam < 1.0 / 1.03) and u > 0.0:
        if abs(u - terms[race, TT_U_FILM]) <= 0.01 * u and abs(Q - terms[race, TT_Q_FILM]) <= 0.05 * Q:
            return False
    h_min = film_thickness(int(tr[TR_FILM]), tr[TR_ETA], tr[TR_XI], tr[TR_E_RED], u, Q, tr[o + TR_RX], tr[o + TR_RY],
                           tr[o + TR_K])[1]  # fmt: skip
    lam = film_parameter(h_min, tr[o + TR_SIGMA])
    terms[race, TT_LAM] = lam
    terms[race, TT_U_FILM] = u
    terms[race, TT_Q_FILM] = Q
    phi = film_share(lam)
    mu = friction_coefficient(lam)
    changed = abs(phi - terms[race, TT_PHI]) > 1e-12 or abs(mu - terms[race, TT_MU]) > 1e-12 * mu
    terms[race, TT_PHI] = phi
    terms[race, TT_MU] = mu
    # their derivatives in the load at this entrainment speed (parameter_derivatives): Lambda ~ h_min ~ Q^e, and on
    # ]1, 3] film_share rises as (Lambda - 1)/2 and friction_coefficient falls as 0.045 (Lambda - 1); flat elsewhere
    dlam = 0.0
    if 1.0 < lam <= 3.0:
        dlam = _film_load_exponent(int(tr[TR_FILM]), tr[o + TR_K]) * lam / Q
    terms[race, TT_DPHI] = 0.5 * dlam
    terms[race, TT_DMU] = -0.045 * dlam
    return changed


@kernel(inline="always")
def _film_load_exponent(formula, k):
    """Exponent e of h_min ~ Q^e at a given entrainment speed in kernels.ehl.film_thickness (its W exponent):
    -0.073 (Hamrock-Dowson, Chittenden), -0.09 k^-0.15 (Masjedi-Khonsari, k the ellipticity)."""
    if formula == FILM_MASJEDI_KHONSARI:
        return -0.09 * k**-0.15
    return -0.073


@kernel(inline="always")
def _contact(race, ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm, s_0, mu_lim, terms):
    """Traction force and resistance moments of one contact on the ball (see the module docstring), with its terms
    (TT_*). Returns (F_t, F_tau, M_a, M_r, M_t, P, u, F): force along the orbit and along tau (N), the moment
    of the force and the resistances about the ball's centre (N.m), the traction's power against the sliding (W),
    the entrainment speed (m/s) and the traction's magnitude (N)."""
    half = 0.5 * D
    s_t, s_tau, spin, u, qa, qr = _surfaces(ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm)
    a = terms[race, TT_A]
    phi = terms[race, TT_PHI]
    mu = terms[race, TT_MU]
    cap = terms[race, TT_Q] * ((1.0 - phi) * friction_coefficient(0.0) + phi * mu_lim)
    v_s = max(film_slip_speed(s_0, u, spin, a), 1e-12)
    v = math.sqrt(s_t * s_t + s_tau * s_tau)
    x = v / v_s
    # F(v)/v = cap (1 - exp(-x)) / v, by its series where x is small (no 0/0 at v = 0)
    g = cap * (1.0 - x * (0.5 - x / 6.0)) / v_s if x < 1e-5 else -cap * math.expm1(-x) / v
    F_t = -g * s_t
    F_tau = -g * s_tau
    # resistances: rolling relative to the orbiting frame, spin relative to the race; their directions regularised
    # below the DEM's speed V_REG at the ball's surface (a smooth form, so that the steady solution has derivatives
    # where a spin passes through 0, as the outer one does under outer-race control)
    f_roll = terms[race, TT_HYST] + mu * terms[race, TT_HEATH]
    if u > 0.0:
        f_roll += terms[race, TT_C_R] * math.exp(0.656 * math.log(u))
    w_reg = V_REG / half
    m_roll = f_roll * half / math.sqrt(qa * qa + qr * qr + Wt * Wt + w_reg * w_reg)
    m_spin = mu * terms[race, TT_SPIN] / math.sqrt(spin * spin + w_reg * w_reg)
    # moment of the traction at half D (ua, ur): (D/2) u x (F_t e_t + F_tau tau) = (D/2) (-F_t tau + F_tau e_t)
    M_a = half * F_t * ur - m_roll * qa - m_spin * spin * ua
    M_r = -half * F_t * ua - m_roll * qr - m_spin * spin * ur
    M_t = half * F_tau - m_roll * Wt
    return F_t, F_tau, M_a, M_r, M_t, g * v * v, u, g * v


@kernel
def _residual(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out):
    """traction_eval with the contacts' terms given (TT_*)."""
    w_m, Wa, Wr, Wt = y[0], y[1], y[2], y[3]
    s_0 = tr[TR_S0]
    mu_lim = tr[TR_MU_LIM]
    si = math.sin(a_i)
    ci = math.cos(a_i)
    so = math.sin(a_o)
    co = math.cos(a_o)
    Fti, Fai, Mai, Mri, Mti, Pi, ui, Fi = _contact(0, -si, -ci, w_m, Wa, Wr, Wt, omega, D, dm, s_0, mu_lim, terms)
    Fto, Fao, Mao, Mro, Mto, Po, uo, Fo = _contact(1, so, co, w_m, Wa, Wr, Wt, 0.0, D, dm, s_0, mu_lim, terms)
    half = 0.5 * D
    out[TE_R] = Fti + Fto
    out[TE_R + 1] = (Mai + Mao) / half
    out[TE_R + 2] = (Mri + Mro + J * w_m * Wt) / half
    out[TE_R + 3] = (Mti + Mto - J * w_m * Wr) / half
    out[TE_FTAU_I] = Fai
    out[TE_FTAU_O] = Fao
    out[TE_P_I] = Pi
    out[TE_P_O] = Po
    out[TE_U_I] = ui
    out[TE_U_O] = uo
    out[TE_MU_I] = Fi / Q_i
    out[TE_MU_O] = Fo / Q_o


# Gradients of a contact (6-tuples): in the kinematics y = (w_m, W_a, W_r, W_t), then in the contact's own angle
# (rad) and load (N); the film terms are held in y and the angle (as in the Newton solve), and follow the load.
@kernel(inline="always")
def _lin(a, x, b, z):
    """a x + b z of two gradients."""
    return (
        a * x[0] + b * z[0],
        a * x[1] + b * z[1],
        a * x[2] + b * z[2],
        a * x[3] + b * z[3],
        a * x[4] + b * z[4],
        a * x[5] + b * z[5],
    )


@kernel(inline="always")
def _unit(k, s):
    """The gradient s along direction k alone."""
    return (
        s if k == 0 else 0.0,
        s if k == 1 else 0.0,
        s if k == 2 else 0.0,
        s if k == 3 else 0.0,
        s if k == 4 else 0.0,
        s if k == 5 else 0.0,
    )


@kernel(inline="always")
def _surfaces_grad(ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm, u_t, u):
    """Gradients of _surfaces' (s_t, s_tau, spin, u, q_a, q_r); u_t the entrainment's orbital component (m/s), u the
    entrainment speed. With the contact's angle the unit vector turns as d(ua, ur)/da = (ur, -ua)."""
    half = 0.5 * D
    rho = 0.5 * dm + half * ur
    droll = -half * (Wa * ua + Wr * ur)  # d roll / da
    gs_t = (0.5 * dm, half * ur, -half * ua, 0.0, droll + w_race * half * ua, 0.0)
    gs_tau = (0.0, 0.0, 0.0, half, 0.0, 0.0)
    gspin = (0.0, ua, ur, 0.0, (Wa - w_race) * ur - Wr * ua, 0.0)
    gu_t = (-half * ur - rho, half * ur, -half * ua, 0.0, droll + half * ua * (2.0 * w_m - w_race), 0.0)
    qa = Wa - w_m
    qn = qa * ua + Wr * ur
    dqn = qa * ur - Wr * ua  # d q_n / da
    gqa = (ua * ua - 1.0, 1.0 - ua * ua, -ur * ua, 0.0, -dqn * ua - qn * ur, 0.0)
    gqr = (ur * ua, -ur * ua, 1.0 - ur * ur, 0.0, -dqn * ur + qn * ua, 0.0)
    gu = _lin(0.25 * u_t / u, gu_t, 0.25 * half * Wt / u, gs_tau) if u > 0.0 else _unit(0, 0.0)
    return gs_t, gs_tau, gspin, gu, gqa, gqr


@kernel(inline="always")
def _contact_d(race, ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm, s_0, mu_lim, terms):
    """_contact's outputs (F_t, F_tau, M_a, M_r, M_t, P, u, F) and their gradients (same order, 6-tuples each)."""
    half = 0.5 * D
    s_t, s_tau, spin, u, qa, qr = _surfaces(ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm)
    u_t = half * (Wa * ur - Wr * ua) - w_m * half * ur + (w_race - w_m) * (0.5 * dm + half * ur)
    gs_t, gs_tau, gspin, gu, gqa, gqr = _surfaces_grad(ua, ur, w_m, Wa, Wr, Wt, w_race, D, dm, u_t, u)
    gua = _unit(4, ur)
    gur = _unit(4, -ua)
    a = terms[race, TT_A]
    Q = terms[race, TT_Q]
    phi = terms[race, TT_PHI]
    mu = terms[race, TT_MU]
    mu_b = friction_coefficient(0.0)
    cap = Q * ((1.0 - phi) * mu_b + phi * mu_lim)
    gcap = _unit(5, (1.0 - phi) * mu_b + phi * mu_lim + Q * (mu_lim - mu_b) * terms[race, TT_DPHI])
    gmu = _unit(5, terms[race, TT_DMU])
    slip = film_slip_speed(s_0, u, spin, a)
    v_s = max(slip, 1e-12)
    if slip < 1e-12:
        gv_s = _unit(0, 0.0)
    elif s_0 * u >= SPIN_SLIP * abs(spin) * a:  # film_slip_speed's max
        gv_s = _lin(s_0, gu, 0.0, gu)
    else:
        gv_s = _lin(SPIN_SLIP * math.copysign(a, spin), gspin, SPIN_SLIP * abs(spin) * _E_A * a / Q, _unit(5, 1.0))
    v = math.sqrt(s_t * s_t + s_tau * s_tau)
    x = v / v_s
    em = math.expm1(-x)
    g = cap * (1.0 - x * (0.5 - x / 6.0)) / v_s if x < 1e-5 else -cap * em / v
    # g = cap E(x) / v_s, E(x) = (1 - exp(-x)) / x, by its series where x is small
    if x < 1e-3:
        E = 1.0 - x * (0.5 - x * (1.0 / 6.0 - x / 24.0))
        dE = -0.5 + x * (1.0 / 3.0 - x * (0.125 - x / 30.0))
    else:
        E = -em / x
        dE = ((1.0 + em) * (1.0 + x) - 1.0) / (x * x)
    gv = _lin(s_t / v, gs_t, s_tau / v, gs_tau) if v > 0.0 else _unit(0, 0.0)
    gx = _lin(1.0 / v_s, gv, -x / v_s, gv_s)
    gg = _lin(E / v_s, gcap, cap * dE / v_s, gx)
    gg = _lin(1.0, gg, -g / v_s, gv_s)
    F_t = -g * s_t
    F_tau = -g * s_tau
    gF_t = _lin(-s_t, gg, -g, gs_t)
    gF_tau = _lin(-s_tau, gg, -g, gs_tau)
    f_roll = terms[race, TT_HYST] + mu * terms[race, TT_HEATH]
    df_roll = _E_HYST * terms[race, TT_HYST] / Q + mu * _E_HEATH * terms[race, TT_HEATH] / Q
    gf_roll = _lin(df_roll, _unit(5, 1.0), terms[race, TT_HEATH], gmu)
    if u > 0.0:
        rolling = terms[race, TT_C_R] * math.exp(0.656 * math.log(u))
        f_roll += rolling
        gf_roll = _lin(1.0, gf_roll, 0.656 * rolling / u, gu)
        gf_roll = _lin(1.0, gf_roll, _E_C_R * rolling / Q, _unit(5, 1.0))
    w_reg = V_REG / half
    n_roll = math.sqrt(qa * qa + qr * qr + Wt * Wt + w_reg * w_reg)
    m_roll = f_roll * half / n_roll
    gn = _lin(qa, gqa, qr, gqr)
    gn = _lin(1.0, gn, Wt, _unit(3, 1.0))
    gm_roll = _lin(half / n_roll, gf_roll, -m_roll / (n_roll * n_roll), gn)
    n_spin = math.sqrt(spin * spin + w_reg * w_reg)
    m_spin = mu * terms[race, TT_SPIN] / n_spin
    gm_spin = _lin(
        terms[race, TT_SPIN] / n_spin, gmu, mu * _E_SPIN * terms[race, TT_SPIN] / (Q * n_spin), _unit(5, 1.0)
    )
    gm_spin = _lin(1.0, gm_spin, -m_spin * spin / (n_spin * n_spin), gspin)
    # moments (_contact): M_a = half F_t ur - m_roll q_a - m_spin spin ua, M_r = -half F_t ua - m_roll q_r -
    # m_spin spin ur, M_t = half F_tau - m_roll W_t
    M_a = half * F_t * ur - m_roll * qa - m_spin * spin * ua
    M_r = -half * F_t * ua - m_roll * qr - m_spin * spin * ur
    M_t = half * F_tau - m_roll * Wt
    gsp = _lin(spin, gm_spin, m_spin, gspin)  # d(m_spin spin)
    gM_a = _lin(half * ur, gF_t, half * F_t, gur)
    gM_a = _lin(1.0, gM_a, -qa, gm_roll)
    gM_a = _lin(1.0, gM_a, -m_roll, gqa)
    gM_a = _lin(1.0, gM_a, -ua, gsp)
    gM_a = _lin(1.0, gM_a, -m_spin * spin, gua)
    gM_r = _lin(-half * ua, gF_t, -half * F_t, gua)
    gM_r = _lin(1.0, gM_r, -qr, gm_roll)
    gM_r = _lin(1.0, gM_r, -m_roll, gqr)
    gM_r = _lin(1.0, gM_r, -ur, gsp)
    gM_r = _lin(1.0, gM_r, -m_spin * spin, gur)
    gM_t = _lin(half, gF_tau, -Wt, gm_roll)
    gM_t = _lin(1.0, gM_t, -m_roll, _unit(3, 1.0))
    gF = _lin(v, gg, g, gv)
    gP = _lin(v * v, gg, 2.0 * g * v, gv)
    return (F_t, F_tau, M_a, M_r, M_t, g * v * v, u, g * v), (gF_t, gF_tau, gM_a, gM_r, gM_t, gP, gu, gF)


@kernel(inline="always")
def _p_column(Dp, c, g, k, race, half, Q):
    """Column c of _residual_d's partials in p: direction k of the gradients g of the contact on race (0 inner)."""
    Dp[TE_R, c] = g[0][k]
    Dp[TE_R + 1, c] = g[2][k] / half
    Dp[TE_R + 2, c] = g[3][k] / half
    Dp[TE_R + 3, c] = g[4][k] / half
    Dp[TE_FTAU_I + race, c] = g[1][k]
    Dp[TE_FTAU_O - race, c] = 0.0
    Dp[TE_P_I + race, c] = g[5][k]
    Dp[TE_P_O - race, c] = 0.0
    Dp[TE_U_I + race, c] = g[6][k]
    Dp[TE_U_O - race, c] = 0.0
    Dp[TE_MU_I + race, c] = g[7][k] / Q
    Dp[TE_MU_O - race, c] = 0.0


@kernel
def _residual_d(y, p, omega, D, dm, J, tr, terms, out, Dy, Dp):
    """_residual at y (rad/s) and the contacts p = (a_i, a_o, Q_i, Q_o) into out, with the partials of every output
    in y into Dy (TE_SIZE x 4; the film terms held, as Newton holds them) and in p into Dp (TE_SIZE x 4; y and the
    entrainment speeds of the films held, the film terms following the loads): closed forms of each term."""
    w_m, Wa, Wr, Wt = y[0], y[1], y[2], y[3]
    s_0 = tr[TR_S0]
    mu_lim = tr[TR_MU_LIM]
    si = math.sin(p[0])
    ci = math.cos(p[0])
    so = math.sin(p[1])
    co = math.cos(p[1])
    vi, gi = _contact_d(0, -si, -ci, w_m, Wa, Wr, Wt, omega, D, dm, s_0, mu_lim, terms)
    vo, go = _contact_d(1, so, co, w_m, Wa, Wr, Wt, 0.0, D, dm, s_0, mu_lim, terms)
    half = 0.5 * D
    Q_i = p[2]
    Q_o = p[3]
    out[TE_R] = vi[0] + vo[0]
    out[TE_R + 1] = (vi[2] + vo[2]) / half
    out[TE_R + 2] = (vi[3] + vo[3] + J * w_m * Wt) / half
    out[TE_R + 3] = (vi[4] + vo[4] - J * w_m * Wr) / half
    out[TE_FTAU_I] = vi[1]
    out[TE_FTAU_O] = vo[1]
    out[TE_P_I] = vi[5]
    out[TE_P_O] = vo[5]
    out[TE_U_I] = vi[6]
    out[TE_U_O] = vo[6]
    out[TE_MU_I] = vi[7] / Q_i
    out[TE_MU_O] = vo[7] / Q_o
    for c in range(4):
        Dy[TE_R, c] = gi[0][c] + go[0][c]
        Dy[TE_R + 1, c] = (gi[2][c] + go[2][c]) / half
        Dy[TE_R + 2, c] = (gi[3][c] + go[3][c]) / half
        Dy[TE_R + 3, c] = (gi[4][c] + go[4][c]) / half
        Dy[TE_FTAU_I, c] = gi[1][c]
        Dy[TE_FTAU_O, c] = go[1][c]
        Dy[TE_P_I, c] = gi[5][c]
        Dy[TE_P_O, c] = go[5][c]
        Dy[TE_U_I, c] = gi[6][c]
        Dy[TE_U_O, c] = go[6][c]
        Dy[TE_MU_I, c] = gi[7][c] / Q_i
        Dy[TE_MU_O, c] = go[7][c] / Q_o
    # the gyroscopic moment J w_m (W_t, -W_r) over D/2
    Dy[TE_R + 2, 0] += J * Wt / half
    Dy[TE_R + 2, 3] += J * w_m / half
    Dy[TE_R + 3, 0] -= J * Wr / half
    Dy[TE_R + 3, 2] -= J * w_m / half
    # p: a_i and Q_i move the inner contact alone (its directions 4 and 5), a_o and Q_o the outer one
    _p_column(Dp, 0, gi, 4, 0, half, Q_i)
    _p_column(Dp, 1, go, 4, 1, half, Q_o)
    _p_column(Dp, 2, gi, 5, 0, half, Q_i)
    _p_column(Dp, 3, go, 5, 1, half, Q_o)
    Dp[TE_MU_I, 2] -= out[TE_MU_I] / Q_i
    Dp[TE_MU_O, 3] -= out[TE_MU_O] / Q_o


@kernel
def _films_at(y, a_i, a_o, omega, D, dm, tr, terms):
    """Both contacts' film terms at the entrainment speeds of the kinematics y (rad/s); True if any changed."""
    u_i = _surfaces(-math.sin(a_i), -math.cos(a_i), y[0], y[1], y[2], y[3], omega, D, dm)[3]
    u_o = _surfaces(math.sin(a_o), math.cos(a_o), y[0], y[1], y[2], y[3], 0.0, D, dm)[3]
    changed_i = _film(0, u_i, tr, terms)
    changed_o = _film(1, u_o, tr, terms)
    return changed_i or changed_o


@kernel
def _terms_at(y, a_i, a_o, Q_i, Q_o, omega, D, dm, tr, terms):
    """Every term of both contacts (TT_SIZE each) at the loads and the kinematics y (rad/s) into terms."""
    _load_terms(0, Q_i, D, tr, terms)
    _load_terms(1, Q_o, D, tr, terms)
    _films_at(y, a_i, a_o, omega, D, dm, tr, terms)


@kernel
def traction_eval(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, out):
    """Residuals of the ball's kinematics y = (w_m, W_a, W_r, W_t) (rad/s) and its contact outputs into out (TE_*).

    a_i, a_o (rad), Q_i, Q_o (N > 0): the contacts; omega (rad/s) the inner race's speed; D, dm (m); J (kg.m^2)
    the ball's moment of inertia; tr: the traction block (TR_*)."""
    terms = np.zeros((2, TT_SIZE))  # zeros: no film (TT_LAM) or rolling force (TT_C_R1) evaluated yet
    _terms_at(y, a_i, a_o, Q_i, Q_o, omega, D, dm, tr, terms)
    _residual(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out)


@kernel
def rolling_start(a_i, a_o, omega, D, dm, y):
    """Outer-race-control kinematics (Jones: tan beta = sin a_o / (cos a_o + D/d_m)) as y (rad/s): the start of the
    traction solve where no earlier solution of the ball is at hand. NaN where the law has no rolling solution (a
    ball turned beyond its inner groove's centre, a_i near 180 deg, can make a denominator 0): the solve then fails,
    and the caller refuses the state for its reason, instead of a division by zero ending the solve."""
    gp = D / dm
    beta = math.atan2(math.sin(a_o), math.cos(a_o) + gp)
    n_o = (1.0 - gp * math.cos(a_i)) * math.cos(a_o - beta)
    den_m = (1.0 + gp * math.cos(a_o)) * math.cos(a_i - beta) + n_o
    den_r = gp * math.cos(a_o - beta)
    if den_m == 0.0 or den_r == 0.0:
        y[:] = math.nan
        return
    w_m = omega * n_o / den_m
    w_R = -w_m * (1.0 + gp * math.cos(a_o)) / den_r
    y[0] = w_m
    y[1] = w_m + w_R * math.cos(beta)
    y[2] = -w_R * math.sin(beta)
    y[3] = 0.0


@kernel
def _solve4(A, M, n):
    """Solve A[:4, :4] X = B for the n right-hand sides B in M[:, 4 : 4 + n] (M: 4 x (4 + n) work, A copied into
    its first four columns) by Gaussian elimination with partial pivoting; X replaces B. False if singular."""
    for r in range(4):
        for c in range(4):
            M[r, c] = A[r, c]
    return gauss_solve(M, 4, 4 + n)


@kernel
def _norm(out):
    return math.sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3])


@kernel
def _marquardt(y, p, omega, D, dm, J, tr, terms, Dy, out, res, trial, work, M):
    """A step (J^T J + lam I) s = -J^T r with lam from 1e-6 to 1e6 of J^T J's mean diagonal, the first that lowers the
    residual res (N) into trial and work (its evaluation); False if none does. M: _solve4's work (4 x 5)."""
    A = np.empty((4, 4))
    g = np.empty(4)
    mean = 0.0
    for r in range(4):
        g[r] = 0.0
        for c in range(4):
            A[r, c] = 0.0
            for k in range(4):
                A[r, c] += Dy[k, r] * Dy[k, c]
            g[r] -= Dy[c, r] * out[TE_R + c]
        mean += 0.25 * A[r, r]
    lam = 1e-6 * mean
    for _ in range(13):
        for r in range(4):
            M[r, 4] = g[r]
            A[r, r] += lam
        solved = _solve4(A, M, 1)
        for r in range(4):
            A[r, r] -= lam
        if solved:
            for c in range(4):
                trial[c] = y[c] + M[c, 4]
            _residual(trial, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, terms, work)
            if _norm(work) < res:
                return True
        lam *= 10.0
    return False


@kernel
def _newton(y, p, omega, D, dm, J, tr, terms, out, Dy, Dp, ws):
    """Damped Newton on the kinematics y (rad/s) with the tribology terms held; out, Dy and Dp (_residual_d) at the
    last iterate. True when converged: residual at most _TOL (Q_i + Q_o), or a step below 1e-14 omega. ws:
    solve_work. Trials are evaluated with their partials, so that the accepted one leaves them for
    parameter_derivatives."""
    work, Dy_t, Dp_t, M, trial = ws[1], ws[2], ws[3], ws[4], ws[5]
    scale = _TOL * (p[2] + p[3])
    _residual_d(y, p, omega, D, dm, J, tr, terms, out, Dy, Dp)
    res = _norm(out)
    for _ in range(_MAXIT):
        if res <= scale:
            return True
        for r in range(4):
            M[r, 4] = -out[TE_R + r]
        if not _solve4(Dy, M, 1):
            return False
        lam = 1.0
        descent = False
        for _t in range(_TRIES):
            for c in range(4):
                trial[c] = y[c] + lam * M[c, 4]
            _residual_d(trial, p, omega, D, dm, J, tr, terms, work, Dy_t, Dp_t)
            if _norm(work) < res:
                descent = True
                break
            lam *= 0.5
        if not descent:
            # the Newton step does not lower the residual (past a kink of the slip speed's max, the traction's slope
            # changes by orders): Levenberg-Marquardt steps, from Newton's towards the steepest descent
            descent = _marquardt(y, p, omega, D, dm, J, tr, terms, Dy, out, res, trial, work, M)
            if descent:
                _residual_d(trial, p, omega, D, dm, J, tr, terms, work, Dy_t, Dp_t)
        if not descent:
            return res <= 1e3 * scale  # no descent left: converged to rounding, or stalled
        small = True
        for c in range(4):
            small = small and abs(trial[c] - y[c]) <= 1e-14 * abs(omega)
        y[:] = trial
        out[:] = work
        Dy[:, :] = Dy_t
        Dp[:, :] = Dp_t
        res = _norm(out)
        if small:
            return True
    return False


@kernel
def solve_work():
    """Work arrays of a traction solve (solve_traction_with): the contacts p (4), a trial's evaluation, its partials
    in y and in p, the elimination's matrix (4 x 8) and the trial kinematics."""
    return (np.empty(4), np.empty(TE_SIZE), np.empty((TE_SIZE, 4)), np.empty((TE_SIZE, 4)), np.empty((4, 8)),
            np.empty(4))  # fmt: skip


@kernel
def solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp):
    """The ball's kinematics y (rad/s, start and solution) for the contacts (a_i, a_o, Q_i, Q_o); terms (2 x TT_SIZE)
    holds the contacts' terms (zeros at first, then kept between solves with the same traction block tr), out (TE_*)
    the evaluation at the solution, Dy and Dp (TE_SIZE x 4) its partials in y (the film held) and in the contacts
    (_residual_d; with the film terms of the last Newton round, which the solution's differ from by 1e-12 at most).
    True when converged.

    The film of a contact follows its entrainment speed, which the kinematics change only by the balls' slip:
    Newton runs with the film terms of its start held, and again from its solution with those of the solution until
    they no longer change (in a full film at once: the film share and mu(Lambda) are then constants)."""
    return solve_traction_with(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp, solve_work())


@kernel
def solve_traction_with(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp, ws):
    """solve_traction with its work arrays ws (solve_work)."""
    p = ws[0]
    p[0] = a_i
    p[1] = a_o
    p[2] = Q_i
    p[3] = Q_o
    _terms_at(y, a_i, a_o, Q_i, Q_o, omega, D, dm, tr, terms)
    for _ in range(_FILM_ROUNDS):
        if not _newton(y, p, omega, D, dm, J, tr, terms, out, Dy, Dp, ws):
            return False
        if not _films_at(y, a_i, a_o, omega, D, dm, tr, terms):
            return True
    return False


@kernel
def parameter_derivatives(y, p, omega, D, dm, J, tr, terms, out, Dy, dout, dydp):
    """Total derivatives of every output of the solved kinematics (TE_*; y by the implicit function theorem) in the
    contacts p = (a_i, a_o, Q_i, Q_o) (rad, rad, N, N) into dout (TE_SIZE x 4), and of the orbital speed in row
    TE_R (its residual row is 0 at a solution). terms: solve_traction's at y; out and Dy (TE_SIZE x 4, the partials
    in y with the film held) are evaluated here at y. The partials in p are closed forms (_residual_d), the film
    terms following the loads at the solution's entrainment speeds. dydp (4 x 4): dy/dp."""
    _residual_d(y, p, omega, D, dm, J, tr, terms, out, Dy, dout)
    implicit_derivatives(Dy, dout, dydp, np.empty((4, 8)))


@kernel
def implicit_derivatives(Dy, dout, dydp, M):
    """parameter_derivatives from the partials Dy (in y) and dout (in p, on entry) of _residual_d at a solution:
    dy/dp = -(dR/dy)^-1 dR/dp into dydp, dout + Dy dy/dp into dout, d w_m / dp in its row TE_R. M: 4 x 8 work."""
    for c in range(4):
        for r in range(4):
            M[r, 4 + c] = -dout[TE_R + r, c]
    if not _solve4(Dy, M, 4):
        M[:, 4:] = 0.0
    for c in range(4):
        for k in range(4):
            dydp[k, c] = M[k, 4 + c]
        for r in range(TE_SIZE):
            for k in range(4):
                dout[r, c] += Dy[r, k] * M[k, 4 + c]
        dout[TE_R, c] = M[0, 4 + c]  # d w_m / dp


@kernel
def solve_from_rolling(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp):
    """solve_traction from outer-race control, the last resort where a warm start stalls: directly, and if that
    stalls too, along a traction curve softened by 1000, 100 and 10 times its knee (a continuation: each solution
    the start of the next, the curve's steep knee reached last). Arguments and result as solve_traction."""
    rolling_start(a_i, a_o, omega, D, dm, y)
    if solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp):
        return True
    rolling_start(a_i, a_o, omega, D, dm, y)
    soft = tr.copy()
    for factor in (1000.0, 100.0, 10.0):
        soft[TR_S0] = factor * tr[TR_S0]
        if not solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, soft, terms, out, Dy, Dp):
            return False
    return solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp)
