"""One Newton on a ball's position and its traction kinematics together (the race control from traction).

The ball's equilibrium under the race control "traction" (kernels.jones_harris.ball_equilibrium) nests two
solves: the ball's position X = (X1, X2) (m) by Newton, and at every trial position the kinematics
y = (w_m, W_a, W_r, W_t) (rad/s) converged by their own Newton (kernels.ball_traction.solve_traction). Here the
six unknowns are those of one Newton: each iteration evaluates the contacts and the film's traction once and
steps X and y together, with the Jacobian of both residuals in both. It is an accelerator and decides nothing:
its solution is the start of the nested solve: the ball's Newton evaluates it once, finds its residual within
tolerance, and takes the kinematics' residuals and partials from the coupled Newton's last evaluation (they are
the nested solve's at that point, converged to the same tolerance) for the derivatives the ring's stiffness
condenses. Where it does not converge, the nested solve starts from the start it had.

Residuals (N): the ball's force balance in its (axial, radial) plane (kernels.jones_harris._ball_eval, with
Mg_i = -F_tau,i and Mg_o = -F_tau,o, the film's in-plane traction forces, and F_c = m d_m w_m^2 / 2), then the
kinematics' four (kernels.ball_traction.TE_R). Their film terms are those of each iterate's entrainment speeds
and are held in the derivatives, as the nested solve holds them; the load terms follow the loads.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel

from .ball_traction import TE_FTAU_I, TE_FTAU_O, TE_R, _residual_d, _terms_at
from .elimination import gauss_solve

_MAXIT = 12  # a warm start converges in 2-3; one that needs more is left to the nested solve
_TRIES = 8  # step halvings of the line search
_KIN_TOL = 1e-12  # the kinematics' residual relative to the contact loads (kernels.ball_traction._TOL)


@kernel(inline="always")
def hertz_load(delta, K):
    """A point contact's load K delta^1.5 (N) at the approach delta (m; open at delta <= 0) and its derivative in
    delta (N/m), of the Hertz constant K (N/m^1.5)."""
    if delta > 0.0:
        sq = math.sqrt(delta)
        return K * delta * sq, 1.5 * K * sq
    return 0.0, 0.0


@kernel(inline="always")
def ball_contacts(X1, X2, A1, A2, r_i, r_o, K_i, K_o):
    """The contacts of a ball at X = (X1, X2) (m) with the inner curvature centre at (A1, A2) (m): (L_o, so, co,
    L_i, si, ci, Q_o, dQ_o, Q_i, dQ_i): the distances to the outer and inner curvature centres (m), the sines and
    cosines of the contact angles, the loads (N) and their derivatives in the approaches (N/m); r_i, r_o (m) the
    groove radii less D/2, K_i, K_o (N/m^1.5) the Hertz constants."""
    L_o = math.hypot(X1, X2)
    V1 = A1 - X1
    V2 = A2 - X2
    L_i = math.hypot(V1, V2)
    d_o = L_o - r_o
    d_i = L_i - r_i
    Q_o, dQ_o = hertz_load(d_o, K_o)
    Q_i, dQ_i = hertz_load(d_i, K_i)
    return L_o, X1 / L_o, X2 / L_o, L_i, V1 / L_i, V2 / L_i, Q_o, dQ_o, Q_i, dQ_i


@kernel(inline="always")
def _evaluate(z, ball, tr, terms, out, Dy, Dp, p, R, G):
    """Residuals R (6, N) at z = (X1, X2, y) and, when G is given, their Jacobian into G[:, :6] (6 x 7). False where a
    contact is open (no traction kinematics there: the nested solve decides). ball = (A1, A2, r_i, r_o, K_i, K_o,
    omega, D, dm, J, fc): the curvature-centre offset (m), the groove radii less D/2 (m), the Hertz constants, the
    speed (rad/s), the ball's diameter and pitch diameter (m), its moment of inertia (kg.m^2) and its centrifugal
    force over w_m^2 (N.s^2, 0 without the centrifugal force)."""
    A1, A2, r_i, r_o, K_i, K_o, omega, D, dm, J, fc = ball
    L_o, so, co, L_i, si, ci, Q_o, dQ_o, Q_i, dQ_i = ball_contacts(z[0], z[1], A1, A2, r_i, r_o, K_i, K_o)
    if Q_i <= 0.0 or Q_o <= 0.0:
        return False
    y = z[2:]
    p[0] = math.atan2(A1 - z[0], A2 - z[1])
    p[1] = math.atan2(z[0], z[1])
    p[2] = Q_i
    p[3] = Q_o
    _terms_at(y, p[0], p[1], Q_i, Q_o, omega, D, dm, tr, terms)
    _residual_d(y, p, omega, D, dm, J, tr, terms, out, Dy, Dp)
    Mgi = -out[TE_FTAU_I]
    Mgo = -out[TE_FTAU_O]
    R[0] = Q_i * si - Mgi * ci - Q_o * so + Mgo * co
    R[1] = Q_i * ci + Mgi * si - Q_o * co + fc * z[2] * z[2] - Mgo * so
    for k in range(4):
        R[2 + k] = out[TE_R + k]
    # p = (a_i, a_o, Q_i, Q_o) in X: rows d/dX1, d/dX2
    dp = ((-ci / L_i, co / L_o, -dQ_i * si, dQ_o * so), (si / L_i, -so / L_o, -dQ_i * ci, dQ_o * co))
    # the force rows' partials in p with the traction forces held, and in (Mg_i, Mg_o)
    r_p = ((Q_i * ci + Mgi * si, -Q_o * co - Mgo * so, si, -so), (-Q_i * si + Mgi * ci, Q_o * so - Mgo * co, ci, -co))
    r_mg = ((-ci, co), (si, -so))
    for b in range(2):
        for c in range(4):  # y: through the traction forces, and F_c
            G[b, 2 + c] = -r_mg[b][0] * Dy[TE_FTAU_I, c] - r_mg[b][1] * Dy[TE_FTAU_O, c]
        for m in range(2):
            s = 0.0
            for k in range(4):
                s += (r_p[b][k] - r_mg[b][0] * Dp[TE_FTAU_I, k] - r_mg[b][1] * Dp[TE_FTAU_O, k]) * dp[m][k]
            G[b, m] = s
    G[1, 2] += 2.0 * fc * z[2]
    for r in range(4):
        for c in range(4):
            G[2 + r, 2 + c] = Dy[TE_R + r, c]
        for m in range(2):
            G[2 + r, m] = Dp[TE_R + r, 0] * dp[m][0] + Dp[TE_R + r, 1] * dp[m][1]
            G[2 + r, m] += Dp[TE_R + r, 2] * dp[m][2] + Dp[TE_R + r, 3] * dp[m][3]
    return True


@kernel(inline="always")
def _norm6(R):
    return math.sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2] + R[3] * R[3] + R[4] * R[4] + R[5] * R[5])


@kernel
def coupled_newton(x, y, ball, f_scale, ball_rtol, tr, terms, out, Dy, Dp, p, cw):
    """Damped Newton on the ball's position x (2, m) and kinematics y (4, rad/s) together, both updated in place
    when it converges and left as they were when it does not. Converged: the force residual at most
    ball_rtol (Q_i + Q_o + f_scale) (N; f_scale the ball Newton's bearing-level and centrifugal loads) and the
    kinematics' at most 1e-12 (Q_i + Q_o). ball: _evaluate's; tr, terms, out, Dy, Dp, p: the traction block and
    the nested solve's work (kernels.jones_harris.traction_work), p the contacts (a_i, a_o, Q_i, Q_o) of the last
    evaluation; cw its own work (coupled_work). Returns True when converged."""
    z, zt, R, Rt, G, fresh = cw
    fresh[0] = 0.0
    z[0] = x[0]
    z[1] = x[1]
    for k in range(4):
        z[2 + k] = y[k]
    if not _evaluate(z, ball, tr, terms, out, Dy, Dp, p, R, G):
        return False
    cap = 0.1 * (ball[2] + ball[3])  # the ball Newton's: a tenth of the groove clearance
    res = _norm6(R)
    for _ in range(_MAXIT):
        loads = p[2] + p[3]
        kin = math.sqrt(R[2] * R[2] + R[3] * R[3] + R[4] * R[4] + R[5] * R[5])
        if math.hypot(R[0], R[1]) <= ball_rtol * (loads + f_scale) and kin <= _KIN_TOL * loads:
            x[0] = z[0]
            x[1] = z[1]
            for k in range(4):
                y[k] = z[2 + k]
            fresh[0] = 1.0
            return True
        for r in range(6):
            G[r, 6] = -R[r]
        if not gauss_solve(G, 6, 7):
            return False
        step = math.hypot(G[0, 6], G[1, 6])
        lam = min(1.0, cap / step) if step > 0.0 else 1.0
        descent = False
        for _t in range(_TRIES):
            for k in range(6):
                zt[k] = z[k] + lam * G[k, 6]
            if _evaluate(zt, ball, tr, terms, out, Dy, Dp, p, Rt, G) and _norm6(Rt) < res:
                descent = True
                break
            lam *= 0.5
        if not descent:
            return False
        z[:] = zt
        R[:] = Rt
        res = _norm6(R)
    return False


@kernel
def coupled_work():
    """Work arrays of coupled_newton: the iterate and a trial (6), their residuals (6), the Jacobian with the
    right-hand side (6 x 7), and a flag (1) set when it has converged, its last evaluation (the traction's outputs
    and partials in the nested solve's arrays) being that of its solution, cleared by the next evaluation of the
    ball (kernels.jones_harris._traction_grad), which takes that evaluation instead of solving again."""
    return np.empty(6), np.empty(6), np.empty(6), np.empty(6), np.empty((6, 7)), np.zeros(1)
