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
_H_FD = 1e-7  # finite-difference step relative to the speed (kinematics) or to the parameter (angles, loads)


@kernel(inline="always")
def _contact(race, ua, ur, Q, w_m, Wa, Wr, Wt, w_race, D, dm, tr):
    """Traction force and resistance moments of one contact on the ball (see the module docstring).

    (ua, ur): unit vector from the ball's centre to the contact; Q (N) its load; w_race (rad/s) the race's speed.
    Returns (F_t, F_tau, M_a, M_r, M_t, P, u, mu): force along the orbit and along tau = (-ur, ua) (N), the moment
    of the force and the resistances about the ball's centre (N.m), the traction's power against the sliding (W),
    the entrainment speed (m/s) and the transmitted coefficient |F|/Q (-)."""
    half = 0.5 * D
    o = TR_STRIDE * race
    rho = 0.5 * dm + half * ur  # radius of the contact point
    # sliding of the ball's surface over the race's at the contact centre, along e_t and tau
    s_t = w_m * 0.5 * dm + half * (Wa * ur - Wr * ua) - w_race * rho
    s_tau = half * Wt
    spin = (Wa - w_race) * ua + Wr * ur
    # entrainment: both surfaces relative to the frame that orbits with the ball
    u_t = half * ((Wa - w_m) * ur - Wr * ua) + (w_race - w_m) * rho
    u = 0.5 * math.sqrt(u_t * u_t + s_tau * s_tau)
    q3 = Q ** (1.0 / 3.0)
    a = tr[o + TR_A1] * q3
    b = tr[o + TR_B1] * q3
    Rx = tr[o + TR_RX]
    Ry = tr[o + TR_RY]
    eta = tr[TR_ETA]
    xi = tr[TR_XI]
    E_red = tr[TR_E_RED]
    h_min = film_thickness(int(tr[TR_FILM]), eta, xi, E_red, u, Q, Rx, Ry, tr[o + TR_K])[1]
    lam = film_parameter(h_min, tr[o + TR_SIGMA])
    phi = film_share(lam)
    mu = friction_coefficient(lam)  # the papers' mu(Lambda): Houpert's sliding terms, and the boundary share
    mu_b = friction_coefficient(0.0)
    v_s = max(film_slip_speed(tr[TR_S0], u, spin, a), 1e-12)
    v = math.sqrt(s_t * s_t + s_tau * s_tau)
    cap = Q * ((1.0 - phi) * mu_b + phi * tr[TR_MU_LIM])
    x = v / v_s
    # F(v)/v = cap (1 - exp(-x)) / v, by its series where x is small (no 0/0 at v = 0)
    g = cap * (1.0 - x * (0.5 - x / 6.0)) / v_s if x < 1e-5 else -cap * math.expm1(-x) / v
    F_t = -g * s_t
    F_tau = -g * s_tau
    # resistances: rolling relative to the orbiting frame, spin relative to the race
    f_roll = houpert_rolling_force(Q, u, Rx, Ry, E_red, eta, xi)
    f_roll += 0.5 * (hysteresis_force(Q, b, Rx, tr[TR_ALPHA_H]) + heathcote_force(Q, a, Rx, tr[o + TR_F], D, mu))
    qa = Wa - w_m
    qr = Wr
    qn = qa * ua + qr * ur
    qa -= qn * ua
    qr -= qn * ur
    # directions regularised below the DEM's speed V_REG at the ball's surface (a smooth form, so that the steady
    # solution has derivatives where a spin passes through 0, as the outer one does under outer-race control)
    w_reg = V_REG / half
    m_roll = f_roll * half / math.sqrt(qa * qa + qr * qr + Wt * Wt + w_reg * w_reg)
    m_s = spin_moment(Q, a, tr[o + TR_EE], mu)
    m_spin = m_s / math.sqrt(spin * spin + w_reg * w_reg)
    # moment of the traction at half D (ua, ur): (D/2) u x (F_t e_t + F_tau tau) = (D/2) (-F_t tau + F_tau e_t)
    M_a = half * F_t * ur - m_roll * qa - m_spin * spin * ua
    M_r = -half * F_t * ua - m_roll * qr - m_spin * spin * ur
    M_t = half * F_tau - m_roll * Wt
    return F_t, F_tau, M_a, M_r, M_t, g * v * v, u, g * v / Q


@kernel
def traction_eval(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, out):
    """Residuals of the ball's kinematics y = (w_m, W_a, W_r, W_t) (rad/s) and its contact outputs into out (TE_*).

    a_i, a_o (rad), Q_i, Q_o (N > 0): the contacts; omega (rad/s) the inner race's speed; D, dm (m); J (kg.m^2)
    the ball's moment of inertia; tr: the traction block (TR_*)."""
    w_m, Wa, Wr, Wt = y[0], y[1], y[2], y[3]
    Fti, Fai, Mai, Mri, Mti, Pi, ui, mui = _contact(
        0, -math.sin(a_i), -math.cos(a_i), Q_i, w_m, Wa, Wr, Wt, omega, D, dm, tr
    )
    Fto, Fao, Mao, Mro, Mto, Po, uo, muo = _contact(
        1, math.sin(a_o), math.cos(a_o), Q_o, w_m, Wa, Wr, Wt, 0.0, D, dm, tr
    )
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
    out[TE_MU_I] = mui
    out[TE_MU_O] = muo


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
def _jacobian(y, p, omega, D, dm, J, tr, base, work, Dy):
    """Forward differences of every output of traction_eval in y (rad/s) into Dy (TE_SIZE x 4), its first four rows
    the residuals' Jacobian; base: out at y; work: TE_SIZE."""
    h = _H_FD * abs(omega)
    z = y.copy()
    for c in range(4):
        z[c] = y[c] + h
        traction_eval(z, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, work)
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
def _marquardt(y, p, omega, D, dm, J, tr, Dy, out, res, trial, work):
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
            traction_eval(trial, p[0], p[1], p[2], p[3], omega, D, dm, J, tr, work)
            if _norm(work) < res:
                return True
        lam *= 10.0
    return False


@kernel
def solve_traction(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, out, Dy):
    """Damped Newton on the ball's kinematics y (rad/s, start and solution) for the contacts (a_i, a_o, Q_i, Q_o);
    out (TE_*) holds the evaluation at the solution and Dy (TE_SIZE x 4) its derivatives in y. True when converged:
    residual at most _TOL (Q_i + Q_o), or a step below 1e-14 omega."""
    p = np.array([a_i, a_o, Q_i, Q_o])
    work = np.empty(TE_SIZE)
    step = np.empty(4)
    trial = np.empty(4)
    neg = np.empty(4)
    scale = _TOL * (Q_i + Q_o)
    traction_eval(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, out)
    res = _norm(out)
    for _ in range(_MAXIT):
        _jacobian(y, p, omega, D, dm, J, tr, out, work, Dy)
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
            traction_eval(trial, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, work)
            if _norm(work) < res:
                descent = True
                break
            lam *= 0.5
        if not descent:
            # the Newton step does not lower the residual (past a kink of the slip speed's max, the traction's slope
            # changes by orders): Levenberg-Marquardt steps, from Newton's towards the steepest descent
            descent = _marquardt(y, p, omega, D, dm, J, tr, Dy, out, res, trial, work)
        if not descent:
            return res <= 1e3 * scale  # no descent left: converged to rounding, or stalled
        y[:] = trial
        out[:] = work
        res = _norm(out)
        if lam * max(abs(step[0]), abs(step[1]), abs(step[2]), abs(step[3])) <= 1e-14 * abs(omega):
            _jacobian(y, p, omega, D, dm, J, tr, out, work, Dy)
            return True
    return False


@kernel
def parameter_derivatives(y, p, omega, D, dm, J, tr, out, Dy, dout):
    """Total derivatives of every output of the solved kinematics (TE_*; y by the implicit function theorem) in the
    contacts p = (a_i, a_o, Q_i, Q_o) (rad, rad, N, N) into dout (TE_SIZE x 4), and of the orbital speed in row
    TE_R (its residual row is 0 at a solution). out, Dy: solve_traction's at y. Central differences in p with
    steps _H_FD (angles, rad) and _H_FD Q (loads)."""
    work = np.empty(TE_SIZE)
    work2 = np.empty(TE_SIZE)
    col = np.empty(4)
    dy = np.empty(4)
    q = p.copy()
    for c in range(4):
        h = _H_FD if c < 2 else _H_FD * p[c]
        q[c] = p[c] + h
        traction_eval(y, q[0], q[1], q[2], q[3], omega, D, dm, J, tr, work)
        q[c] = p[c] - h
        traction_eval(y, q[0], q[1], q[2], q[3], omega, D, dm, J, tr, work2)
        q[c] = p[c]
        for r in range(TE_SIZE):
            dout[r, c] = (work[r] - work2[r]) / (2.0 * h)
        for r in range(4):
            col[r] = -dout[TE_R + r, c]
        if not _solve4(Dy, col, dy):
            dy[:] = 0.0
        for r in range(TE_SIZE):
            for k in range(4):
                dout[r, c] += Dy[r, k] * dy[k]
        dout[TE_R, c] = dy[0]  # d w_m / dp
