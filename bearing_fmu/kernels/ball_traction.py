"""Ball kinematics from the lubricant's traction: the quasi-static race control "traction" (docs/quasistatic.md, 2).

No race-control hypothesis: a ball's orbital speed w_m and its angular velocity W follow from its steady force and
moment balance with the tangential forces the film transmits, as in the quasi-static skidding analyses of
high-speed ball bearings (Harris 1971, J. Lubr. Technol. 93(1) 17-24, ball motion in thrust-loaded angular-contact
bearings with Coulomb and viscous surface friction; Gupta's ADORE in its steady limit, Gupta 1984, Advanced
Dynamics of Rolling Elements, Springer). The contact law is the DEM's (kernels.ball_dynamics.contacts), so that the
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

from .ehl import film_parameter, film_share, film_slip_speed, film_thickness, friction_coefficient
from .torque import heathcote_force, houpert_rolling_force, hysteresis_force, spin_moment

# layout of the traction block (at the offset the quasi-static array gives it): per race, inner then outer
TR_A1 = 0  # semi-major axis of the contact ellipse at 1 N (m): a = TR_A1 Q^(1/3)
TR_B1 = 1  # semi-minor axis at 1 N (m)
TR_EE = 2  # complete elliptic integral of the second kind of the contact (-)
TR_RX = 3  # reduced radius along the rolling direction (m)
TR_RY = 4  # reduced radius across it (m)
TR_K = 5  # ellipticity a/b (-)
TR_F = 6  # groove conformity r/D (-)
TR_SIGMA = 7  # composite roughness (m)
TR_STRIDE = 8
TR_MU_LIM = 2 * TR_STRIDE  # limiting traction coefficient of the film (-)
TR_S0 = TR_MU_LIM + 1  # slide-to-roll ratio of the traction curve's knee (-)
TR_ETA = TR_MU_LIM + 2  # viscosity at the oil temperature (Pa.s), set at each evaluation
TR_XI = TR_MU_LIM + 3  # pressure-viscosity coefficient at the oil temperature (1/Pa), set at each evaluation
TR_E_RED = TR_MU_LIM + 4  # reduced modulus (Pa)
TR_ALPHA_H = TR_MU_LIM + 5  # hysteresis loss factor (-)
TR_FILM = TR_MU_LIM + 6  # film formula code (kernels.ehl)
TR_SIZE = TR_MU_LIM + 7

# the kinematic state of a ball, y = (w_m, W_a, W_r, W_t) (rad/s); per contact outputs of traction_eval's out
TE_R = 0  # four residuals (N): orbit force, then the (a, r, t) moments over D/2
TE_FTAU_I = 4  # in-plane (transverse) traction force on the ball at the inner contact (N), along (cos a_i, -sin a_i)
TE_FTAU_O = 5  # the same at the outer contact (N), along (-cos a_o, sin a_o)
TE_P_I = 6  # power of the inner contact's traction against its sliding (W)
TE_P_O = 7
TE_U_I = 8  # entrainment speed of the inner contact (m/s)
TE_U_O = 9
TE_MU_I = 10  # traction coefficient the inner contact transmits, |F| / Q (-)
TE_MU_O = 11
TE_SIZE = 12

V_REG = 1e-3  # m/s: the resistances' directions are regularised below it (the DEM's, models.dem.packing)
_TOL = 1e-12  # residual of the ball's kinematics relative to its contact loads
_MAXIT = 60
_TRIES = 30  # step halvings of the line search
_FILM_ROUNDS = 6  # Newton solves with the film terms of the last solution, at most
# finite-difference step relative to the speed (kinematics), in rad (angles) or relative to the load: small against
# the spin regularisation w_reg = V_REG / (D/2) ~ 0.1 rad/s, across which a spin near 0 (outer-race control) curves
# the residual (1e-7 put 1e-3 of error into the derivatives there), large against the residuals' rounding
_H_FD = 1e-9


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
TT_A = 0  # semi-major axis of the contact ellipse (m)
TT_Q = 1  # load (N)
TT_HYST = 2  # half the hysteresis force (N)
TT_HEATH = 3  # half the Heathcote force per unit friction coefficient (N)
TT_SPIN = 4  # pivoting moment per unit friction coefficient (N.m)
TT_C_R = 5  # Houpert's EHL rolling force at u = 1 m/s (N); it grows as u^0.656
TT_PHI = 6  # the film's share of the tangential force (-)
TT_MU = 7  # mu(Lambda) of the papers (-): Houpert's sliding terms
TT_SIZE = 8


@kernel(inline="always")
def _load_terms(race, Q, D, tr, terms):
    """The contact's terms that follow its load Q (N) alone into terms[race] (TT_A .. TT_C_R)."""
    o = TR_STRIDE * race
    q3 = Q ** (1.0 / 3.0)
    a = tr[o + TR_A1] * q3
    Rx = tr[o + TR_RX]
    terms[race, TT_A] = a
    terms[race, TT_Q] = Q
    terms[race, TT_HYST] = 0.5 * hysteresis_force(Q, tr[o + TR_B1] * q3, Rx, tr[TR_ALPHA_H])
    terms[race, TT_HEATH] = 0.5 * heathcote_force(Q, a, Rx, tr[o + TR_F], D, 1.0)
    terms[race, TT_SPIN] = spin_moment(Q, a, tr[o + TR_EE], 1.0)
    terms[race, TT_C_R] = houpert_rolling_force(Q, 1.0, Rx, tr[o + TR_RY], tr[TR_E_RED], tr[TR_ETA], tr[TR_XI])


@kernel(inline="always")
def _film(race, u, tr, terms):
    """The contact's film terms at entrainment speed u (m/s) into terms[race] (TT_PHI, TT_MU): the film share and
    mu(Lambda) of its minimum film (the scene's formula); returns True when they changed (beyond 1e-12)."""
    o = TR_STRIDE * race
    Q = terms[race, TT_Q]
    h_min = film_thickness(int(tr[TR_FILM]), tr[TR_ETA], tr[TR_XI], tr[TR_E_RED], u, Q, tr[o + TR_RX], tr[o + TR_RY],
                           tr[o + TR_K])[1]  # fmt: skip
    lam = film_parameter(h_min, tr[o + TR_SIGMA])
    phi = film_share(lam)
    mu = friction_coefficient(lam)
    changed = abs(phi - terms[race, TT_PHI]) > 1e-12 or abs(mu - terms[race, TT_MU]) > 1e-12 * mu
    terms[race, TT_PHI] = phi
    terms[race, TT_MU] = mu
    return changed


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
    terms = np.empty((2, TT_SIZE))
    _terms_at(y, a_i, a_o, Q_i, Q_o, omega, D, dm, tr, terms)
    _residual(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out)


@kernel
def rolling_start(a_i, a_o, omega, D, dm, y):
    """Outer-race-control kinematics (Jones: tan beta = sin a_o / (cos a_o + D/d_m)) as y (rad/s): the start of the
    traction solve where no earlier solution of the ball is at hand."""
    gp = D / dm
    beta = math.atan2(math.sin(a_o), math.cos(a_o) + gp)
    n_o = (1.0 - gp * math.cos(a_i)) * math.cos(a_o - beta)
    w_m = omega * n_o / ((1.0 + gp * math.cos(a_o)) * math.cos(a_i - beta) + n_o)
    w_R = -w_m * (1.0 + gp * math.cos(a_o)) / (gp * math.cos(a_o - beta))
    y[0] = w_m
    y[1] = w_m + w_R * math.cos(beta)
    y[2] = -w_R * math.sin(beta)
    y[3] = 0.0


@kernel
def _jacobian(y, p, omega, D, dm, J, tr, terms, base, work, Dy):
    """Forward differences of every output of _residual (terms held) in y (rad/s) into Dy (TE_SIZE x 4), its first
    four rows the residuals' Jacobian; base: out at y; work: TE_SIZE."""
    h = _H_FD * abs(omega)
    z = y.copy()
    for c in range(4):
        z[c] = y[c] + h
        _residual(z, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, terms, work)
        for r in range(TE_SIZE):
            Dy[r, c] = (work[r] - base[r]) / h
        z[c] = y[c]


@kernel
def _solve4(A, b, x):
    """x = A[:4, :4]^-1 b for the first four rows of A by Gaussian elimination with partial pivoting (A, b copied);
    False if singular."""
    M = A[:4, :4].copy()
    r = b.copy()
    for k in range(4):
        piv = k
        for i in range(k + 1, 4):
            if abs(M[i, k]) > abs(M[piv, k]):
                piv = i
        if M[piv, k] == 0.0 or not math.isfinite(M[piv, k]):
            return False
        if piv != k:
            for c in range(4):
                M[k, c], M[piv, c] = M[piv, c], M[k, c]
            r[k], r[piv] = r[piv], r[k]
        for i in range(k + 1, 4):
            f = M[i, k] / M[k, k]
            for c in range(k, 4):
                M[i, c] -= f * M[k, c]
            r[i] -= f * r[k]
    for k in range(3, -1, -1):
        s = r[k]
        for c in range(k + 1, 4):
            s -= M[k, c] * x[c]
        x[k] = s / M[k, k]
    return True


@kernel
def _norm(out):
    return math.sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3])


@kernel
def _marquardt(y, p, omega, D, dm, J, tr, terms, Dy, out, res, trial, work):
    """A step (J^T J + lam I) s = -J^T r with lam from 1e-6 to 1e6 of J^T J's mean diagonal, the first that lowers the
    residual res (N) into trial and work (its evaluation); False if none does."""
    A = np.empty((4, 4))
    g = np.empty(4)
    step = np.empty(4)
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
        B = A.copy()
        for r in range(4):
            B[r, r] += lam
        if _solve4(B, g, step):
            for c in range(4):
                trial[c] = y[c] + step[c]
            _residual(trial, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, terms, work)
            if _norm(work) < res:
                return True
        lam *= 10.0
    return False


@kernel
def _newton(y, p, omega, D, dm, J, tr, terms, out, Dy):
    """Damped Newton on the kinematics y (rad/s) with the tribology terms held; out and Dy at the last iterate.
    True when converged: residual at most _TOL (Q_i + Q_o), or a step below 1e-14 omega."""
    work = np.empty(TE_SIZE)
    step = np.empty(4)
    trial = np.empty(4)
    neg = np.empty(4)
    scale = _TOL * (p[2] + p[3])
    _residual(y, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, terms, out)
    res = _norm(out)
    for _ in range(_MAXIT):
        _jacobian(y, p, omega, D, dm, J, tr, terms, out, work, Dy)
        if res <= scale:
            return True
        for r in range(4):
            neg[r] = -out[TE_R + r]
        if not _solve4(Dy, neg, step):
            return False
        lam = 1.0
        descent = False
        for _t in range(_TRIES):
            for c in range(4):
                trial[c] = y[c] + lam * step[c]
            _residual(trial, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, terms, work)
            if _norm(work) < res:
                descent = True
                break
            lam *= 0.5
        if not descent:
            # the Newton step does not lower the residual (past a kink of the slip speed's max, the traction's slope
            # changes by orders): Levenberg-Marquardt steps, from Newton's towards the steepest descent
            lam = 0.0
            descent = _marquardt(y, p, omega, D, dm, J, tr, terms, Dy, out, res, trial, work)
        if not descent:
            return res <= 1e3 * scale  # no descent left: converged to rounding, or stalled
        small = True
        for c in range(4):
            small = small and abs(trial[c] - y[c]) <= 1e-14 * abs(omega)
        y[:] = trial
        out[:] = work
        res = _norm(out)
        if small:
            _jacobian(y, p, omega, D, dm, J, tr, terms, out, work, Dy)
            return True
    return False


@kernel
def solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy):
    """The ball's kinematics y (rad/s, start and solution) for the contacts (a_i, a_o, Q_i, Q_o); terms (2 x TT_SIZE)
    holds the contacts' terms, out (TE_*) the evaluation at the solution and Dy (TE_SIZE x 4) its derivatives in y
    with the contacts' film (Lambda and what follows from it) held. True when converged.

    The film of a contact follows its entrainment speed, which the kinematics change only by the balls' slip:
    Newton runs with the film terms of its start held, and again from its solution with those of the solution until
    they no longer change (in a full film at once: the film share and mu(Lambda) are then constants)."""
    p = np.array([a_i, a_o, Q_i, Q_o])
    _terms_at(y, a_i, a_o, Q_i, Q_o, omega, D, dm, tr, terms)
    for _ in range(_FILM_ROUNDS):
        if not _newton(y, p, omega, D, dm, J, tr, terms, out, Dy):
            return False
        if not _films_at(y, a_i, a_o, omega, D, dm, tr, terms):
            return True
    return False


@kernel
def parameter_derivatives(y, p, omega, D, dm, J, tr, terms, out, Dy, dout, dydp):
    """Total derivatives of every output of the solved kinematics (TE_*; y by the implicit function theorem) in the
    contacts p = (a_i, a_o, Q_i, Q_o) (rad, rad, N, N) into dout (TE_SIZE x 4), and of the orbital speed in row
    TE_R (its residual row is 0 at a solution). terms, out, Dy: solve_traction's at y. Forward differences in p with
    steps _H_FD (angles, rad) and _H_FD Q (loads), the film terms following the loads. dydp (4 x 4): dy/dp."""
    work = np.empty(TE_SIZE)
    col = np.empty(4)
    dy = np.empty(4)
    saved = np.empty(TT_SIZE)
    q = p.copy()
    for c in range(4):
        h = _H_FD if c < 2 else _H_FD * p[c]
        q[c] = p[c] + h
        if c >= 2:  # a load's terms, the film's with them; the angles move the film by u alone, which Dy holds
            race = c - 2
            for k in range(TT_SIZE):
                saved[k] = terms[race, k]
            _load_terms(race, q[c], D, tr, terms)
            _film(race, out[TE_U_I + race], tr, terms)  # at the entrainment speed of the solution
        _residual(y, q[0], q[1], q[2], q[3], omega, D, dm, J, tr, terms, work)
        if c >= 2:
            for k in range(TT_SIZE):
                terms[race, k] = saved[k]
        q[c] = p[c]
        for r in range(TE_SIZE):
            dout[r, c] = (work[r] - out[r]) / h
        for r in range(4):
            col[r] = -dout[TE_R + r, c]
        if not _solve4(Dy, col, dy):
            dy[:] = 0.0
        for k in range(4):
            dydp[k, c] = dy[k]
        for r in range(TE_SIZE):
            for k in range(4):
                dout[r, c] += Dy[r, k] * dy[k]
        dout[TE_R, c] = dy[0]  # d w_m / dp


@kernel
def solve_from_rolling(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy):
    """solve_traction from outer-race control, the last resort where a warm start stalls: directly, and if that
    stalls too, along a traction curve softened by 1000, 100 and 10 times its knee (a continuation: each solution
    the start of the next, the curve's steep knee reached last). Arguments and result as solve_traction."""
    rolling_start(a_i, a_o, omega, D, dm, y)
    if solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy):
        return True
    rolling_start(a_i, a_o, omega, D, dm, y)
    soft = tr.copy()
    for factor in (1000.0, 100.0, 10.0):
        soft[TR_S0] = factor * tr[TR_S0]
        if not solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, soft, terms, out, Dy):
            return False
    return solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy)
