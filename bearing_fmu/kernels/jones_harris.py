"""Quasi-static 5-DOF ball-bearing model (Jones 1960 / Harris & Kotzalas 2006; docs/quasistatic.md).

Outer ring fixed, inner ring displaced by d = (x, y, z, theta_x, theta_y) (m, m, m, rad, rad) and
rotating at omega (rad/s). Ball j sits at azimuth psi_j = pi/2 + 2 pi j / Z from the x axis toward y
(geometry.ball_direction: ball 1 on +y, the line of F_y; docs/conventions.md).

Per ball, in its (axial, radial) plane, A = (A1, A2) is the inner groove-curvature centre seen
from the outer one and X = (X1, X2) the ball centre seen from the outer one (the ball unknowns):
  A1 = A1_0 + z + Rr_i (theta_x sin psi - theta_y cos psi),  A2 = A2_0 + x cos psi + y sin psi,
  A1_0 = A sin(alpha0) for an angular-contact bearing (z = 0 where the balls just touch), 0 for a
  deep-groove one; A2_0 = A - (P_d + dP_d)/2; A = (f_i + f_o - 1) D; Rr_i = d_m/2 + (f_i - 1/2) D cos alpha0.
Contacts: delta_o = |X| - (f_o - 1/2) D, delta_i = |A - X| - (f_i - 1/2) D, Q = K delta^1.5 with the
Hertz constants K of the contacts at the free contact angle (Harris' practice: their change with
the operating angle is below 1 %); contact angles from the directions of X and A - X.
Ball equilibrium (Harris & Kotzalas 2006 vol. 2 eqs. 3.xx; Rabreau 2018 with its sign slip fixed,
docs/quasistatic.md): with the gyroscopic moment M_g = J w_R w_m sin(beta) (J = m D^2/10, signed as
Harris: w_R < 0 for omega > 0) shared by lam_i + lam_o = 2,
  Q_i sin a_i - Q_o sin a_o + (M_g/D)(lam_o cos a_o - lam_i cos a_i) = 0
  Q_i cos a_i - Q_o cos a_o + F_c - (M_g/D)(lam_o sin a_o - lam_i sin a_i) = 0,  F_c = m d_m w_m^2 / 2.
The pitch angle beta comes from the race-control law (outer: tan beta = sin a_o/(cos a_o + g),
inner: tan beta = sin a_i/(cos a_i - g), hybrid: Rabreau's law with S = (1 + g cos a_o)/(1 - g cos a_i),
g = D/d_m); w_m and w_R follow from rolling without slip at both contact centres.
Ring load of a ball: g_z = Q_i sin a_i - lam_i (M_g/D) cos a_i, g_r = Q_i cos a_i + lam_i (M_g/D) sin a_i,
and the friction couple m_g = lam_i f_i M_g; the applied loads are
  (F_x, F_y, F_z, M_x, M_y)
    = sum_j [g_r cos psi, g_r sin psi, g_z, (Rr_i g_z + m_g) sin psi, -(Rr_i g_z + m_g) cos psi].
Stiffness K = dF/dd (5x5) by the chain rule with the ball equilibrium condensed (dX/dA from the
implicit function theorem). Derivatives are analytic; those of the kinematic factors
(beta, w_m, w_R -> F_c, M_g) w.r.t. (a_i, a_o, C) use the complex step, exact to rounding.
"""

import cmath
import math

import numpy as np

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .ball_coupled_newton import ball_contacts, coupled_newton, coupled_work
from .ball_traction import (
    TE_FTAU_I,
    TE_FTAU_O,
    TE_P_I,
    TE_P_O,
    TE_R,
    TE_SIZE,
    TE_U_I,
    TE_U_O,
    TR_SIZE,
    TT_SIZE,
    implicit_derivatives,
    rolling_start,
    solve_from_rolling,
    solve_traction_with,
    solve_work,
    traction_eval,
)
from .elimination import gauss_solve
from .geometry import ball_direction

# layout of the quasi-static bearing array (built by bearing_fmu.models.analytic)
_QS_SLOTS = Layout()
QS_Z = _QS_SLOTS.slot()  # number of balls (-)
QS_D = _QS_SLOTS.slot()  # ball diameter (m)
QS_DM = _QS_SLOTS.slot()  # pitch diameter (m)
QS_FI = _QS_SLOTS.slot()  # inner groove conformity r_i/D (-)
QS_FO = _QS_SLOTS.slot()  # outer groove conformity r_o/D (-)
QS_PD = _QS_SLOTS.slot()  # nominal diametral clearance (m), negative = interference
# 1 = angular-contact (z = 0 where balls touch at alpha0), 0 = deep groove (z = 0 centred)
QS_ANGULAR = _QS_SLOTS.slot()
QS_K_I = _QS_SLOTS.slot()  # inner Hertz constant (N/m^1.5)
QS_K_O = _QS_SLOTS.slot()  # outer Hertz constant (N/m^1.5)
QS_M_BALL = _QS_SLOTS.slot()  # ball mass (kg)
QS_RACE = _QS_SLOTS.slot()  # race control code (RACE_*)
QS_CENTRIFUGAL = _QS_SLOTS.slot()  # 1 = centrifugal force on
QS_GYROSCOPIC = _QS_SLOTS.slot()  # 1 = gyroscopic moment on
QS_C_HYB = _QS_SLOTS.slot()  # hybrid law: a_i E_i / (a_o E_o) at equal loads (-), C = this (Q_i/Q_o)^(4/3)
QS_TOL = _QS_SLOTS.slot()  # relative tolerance of the global equilibrium (-)
QS_MAXIT = _QS_SLOTS.slot()  # iteration cap of the global Newton (-)
# 1 = fill the stiffness output K; 0 = null submodel: K untouched, assembled only as Newton matrix
QS_STIFFNESS = _QS_SLOTS.slot()
# start of the traction block (kernels.ball_traction TR_*), read by RACE_TRACTION only
QS_TRACTION = _QS_SLOTS.slot(TR_SIZE)
QS_SIZE = _QS_SLOTS.size

RACE_OUTER = 0
RACE_INNER = 1
RACE_HYBRID = 2  # hybrid pitch angle, gyroscopic moment shared in proportion to the spin moments
# Other readings of the hybrid model's moment share (Rabreau's Table 1 is lost), for sensitivity
# studies only (tests/validation/test_quasistatic_literature.py); every code >= RACE_HYBRID is hybrid:
RACE_HYBRID_OUTER_SPLIT = 3  # lam_i = 0, lam_o = 2 (the outer race takes it all, as in ORC)
RACE_HYBRID_INNER_SPLIT = 4  # lam_i = 2, lam_o = 0 (the inner race takes it all, as in IRC)
RACE_HYBRID_EQUAL_SPLIT = 5  # lam_i = lam_o = 1 (Harris without race control; unverified, docs/decisions.md)
RACE_HYBRID_CONTROLLING = 6  # all of it on the race with the larger spin moment (Jones' criterion)
RACE_TRACTION = 7  # no hypothesis: kinematics from the balls' force and moment balance with the film's traction

# rows of the ball state X (X_SIZE, Z): the ball centre seen from the outer groove-curvature centre, then the
# kinematics y = (w_m, W_a, W_r, W_t) (rad/s) of RACE_TRACTION (kernels.ball_traction), warm start and solution
_X_SLOTS = Layout()
X_POSITION = _X_SLOTS.slot(2)  # the ball centre (m): axial, radial
X_Y = _X_SLOTS.slot(4)
X_SIZE = _X_SLOTS.size

# rows of the per-ball output array
_BQ_SLOTS = Layout()
BQ_Q_I = _BQ_SLOTS.slot()  # inner contact load (N)
BQ_Q_O = _BQ_SLOTS.slot()  # outer contact load (N)
BQ_A_I = _BQ_SLOTS.slot()  # inner contact angle (rad)
BQ_A_O = _BQ_SLOTS.slot()  # outer contact angle (rad)
BQ_BETA = _BQ_SLOTS.slot()  # pitch angle of the ball spin axis (rad)
BQ_W_M = _BQ_SLOTS.slot()  # orbital (cage) speed of the ball (rad/s)
BQ_W_R = _BQ_SLOTS.slot()  # ball spin speed relative to the cage (rad/s, Harris sign)
BQ_F_C = _BQ_SLOTS.slot()  # centrifugal force (N)
BQ_M_G = _BQ_SLOTS.slot()  # gyroscopic moment (N.m, Harris sign)
BQ_X1 = _BQ_SLOTS.slot()  # ball centre, axial, from the outer groove centre (m)
BQ_X2 = _BQ_SLOTS.slot()  # ball centre, radial, from the outer groove centre (m)
BQ_LAM_I = _BQ_SLOTS.slot()  # share of the gyroscopic moment taken by the inner race (-)
BQ_SPIN_I = _BQ_SLOTS.slot()  # spin speed at the inner contact (rad/s)
BQ_SPIN_O = _BQ_SLOTS.slot()  # spin speed at the outer contact (rad/s)
BQ_U_I = _BQ_SLOTS.slot()  # rolling (entrainment) speed at the inner contact (m/s)
BQ_U_O = _BQ_SLOTS.slot()  # rolling (entrainment) speed at the outer contact (m/s)
# power of the traction against the sliding at the inner contact (W; RACE_TRACTION, else 0)
BQ_P_SLIP_I = _BQ_SLOTS.slot()
BQ_P_SLIP_O = _BQ_SLOTS.slot()
# traction coefficient a race-control hypothesis asks of the inner contact, |lam_i M_g/D| / Q_i (-)
BQ_MU_REQ_I = _BQ_SLOTS.slot()
# ... of the outer contact (-); 0 under RACE_TRACTION (its forces are the traction curve's)
BQ_MU_REQ_O = _BQ_SLOTS.slot()
BQ_SIZE = _BQ_SLOTS.size

# rows of the per-ball contact state that the load evaluation keeps for the per-ball outputs
_CS_SLOTS = Layout()
CS_Q_I = _CS_SLOTS.slot()  # inner contact load (N)
CS_Q_O = _CS_SLOTS.slot()  # outer contact load (N)
CS_A_I = _CS_SLOTS.slot()  # inner contact angle (rad)
CS_A_O = _CS_SLOTS.slot()  # outer contact angle (rad)
CS_C = _CS_SLOTS.slot()  # hybrid spin-moment ratio (-)
CS_SIZE = _CS_SLOTS.size

# status codes of the solver
QS_OK = 0
QS_NOT_CONVERGED = 1  # iteration cap reached
QS_BALL_NOT_CONVERGED = 2  # a ball equilibrium failed
QS_NOT_FINITE = 3  # NaN or inf appeared

# slots of the ball evaluation w (_ball_eval): residual r of the ball's force balance, ring load g and
# friction couple m_g of the ball on the inner ring, their partial derivatives w.r.t. the ball position X
# and the curvature-centre offset A (2x2 blocks, row-major), contact loads, angles, hybrid ratio
_EV_SLOTS = Layout()
EV_R1 = _EV_SLOTS.slot()  # axial residual (N)
EV_R2 = _EV_SLOTS.slot()  # radial residual (N)
EV_GZ = _EV_SLOTS.slot()  # axial ring load g_z (N)
EV_GR = _EV_SLOTS.slot()  # radial ring load g_r (N)
EV_MG = _EV_SLOTS.slot()  # friction couple m_g (N.m)
EV_DR1_DX1 = _EV_SLOTS.slot()  # dr/dX (N/m)
EV_DR1_DX2 = _EV_SLOTS.slot()
EV_DR2_DX1 = _EV_SLOTS.slot()
EV_DR2_DX2 = _EV_SLOTS.slot()
EV_DR1_DA1 = _EV_SLOTS.slot()  # dr/dA (N/m)
EV_DR1_DA2 = _EV_SLOTS.slot()
EV_DR2_DA1 = _EV_SLOTS.slot()
EV_DR2_DA2 = _EV_SLOTS.slot()
EV_DGZ_DX1 = _EV_SLOTS.slot()  # dg/dX (N/m)
EV_DGZ_DX2 = _EV_SLOTS.slot()
EV_DGR_DX1 = _EV_SLOTS.slot()
EV_DGR_DX2 = _EV_SLOTS.slot()
EV_DGZ_DA1 = _EV_SLOTS.slot()  # dg/dA (N/m)
EV_DGZ_DA2 = _EV_SLOTS.slot()
EV_DGR_DA1 = _EV_SLOTS.slot()
EV_DGR_DA2 = _EV_SLOTS.slot()
EV_DM_DX1 = _EV_SLOTS.slot()  # dm_g/dX (N)
EV_DM_DX2 = _EV_SLOTS.slot()
EV_DM_DA1 = _EV_SLOTS.slot()  # dm_g/dA (N)
EV_DM_DA2 = _EV_SLOTS.slot()
EV_Q_I = _EV_SLOTS.slot()  # inner contact load (N)
EV_Q_O = _EV_SLOTS.slot()  # outer contact load (N)
EV_A_I = _EV_SLOTS.slot()  # inner contact angle (rad)
EV_A_O = _EV_SLOTS.slot()  # outer contact angle (rad)
EV_C = _EV_SLOTS.slot()  # hybrid spin-moment ratio (-)
EV_SIZE = _EV_SLOTS.size

# slots of a solved ball (ball_equilibrium's cond): ring load, friction couple and their derivatives
# w.r.t. A with the ball position condensed out, then the contact state
_BE_SLOTS = Layout()
BE_GZ = _BE_SLOTS.slot()  # axial ring load g_z (N)
BE_GR = _BE_SLOTS.slot()  # radial ring load g_r (N)
BE_MG = _BE_SLOTS.slot()  # friction couple m_g (N.m)
BE_DGZ_DA1 = _BE_SLOTS.slot()  # dg/dA (N/m), row-major
BE_DGZ_DA2 = _BE_SLOTS.slot()
BE_DGR_DA1 = _BE_SLOTS.slot()
BE_DGR_DA2 = _BE_SLOTS.slot()
BE_DM_DA1 = _BE_SLOTS.slot()  # dm_g/dA (N)
BE_DM_DA2 = _BE_SLOTS.slot()
BE_Q_I = _BE_SLOTS.slot()  # inner contact load (N)
BE_Q_O = _BE_SLOTS.slot()  # outer contact load (N)
BE_A_I = _BE_SLOTS.slot()  # inner contact angle (rad)
BE_A_O = _BE_SLOTS.slot()  # outer contact angle (rad)
BE_C = _BE_SLOTS.slot()  # hybrid spin-moment ratio (-)
BE_SIZE = _BE_SLOTS.size

# rows and columns of the kinematic partials kg (_kin_grad)
_KG_ROWS = Layout()
KG_FC = _KG_ROWS.slot()  # centrifugal force F_c (N)
KG_MGO = _KG_ROWS.slot()  # lam_o M_g / D (N)
KG_MGI = _KG_ROWS.slot()  # lam_i M_g / D (N)
_KG_SLOTS = Layout()
KG_VALUE = _KG_SLOTS.slot()
KG_DAI = _KG_SLOTS.slot()  # d/da_i
KG_DAO = _KG_SLOTS.slot()  # d/da_o
KG_DC = _KG_SLOTS.slot()  # d/dC (RACE_TRACTION: d/dQ_i)
KG_DQO = _KG_SLOTS.slot()  # d/dQ_o (RACE_TRACTION only; 0 for the hypotheses)
KG_SIZE = _KG_SLOTS.size

_H_CSTEP = 1e-30  # complex-step increment: exact derivatives, no subtraction error
_BALL_MAXIT = 60
_BALL_RTOL = 1e-13  # ball residual relative to its loads plus the bearing-level load per ball (_ball_newton)
_BALL_TRIES = 8  # step halvings of the ball line search (down to 1/128): bounds the cost of a bad start
_TR_RADIUS = 0.05  # first trust radius of the global solve, in groove clearances A: the full Newton step inside it
_TR_COLLAPSE = 1e-12  # trust radius (in A) below which the region has collapsed on a discontinuity of the loads
_LOADS_TRIES = 12  # step halvings of the last-resort damped Newton (down to 1/2048)
_TR_ACCEPT = 1e-4  # a trial is taken when the unbalanced load does at least this share of the predicted work
_F_FLOOR = 1e-3  # N: load scale of a bearing with no applied load (global and ball convergence tests)


def line_search(residual_at):
    """The damping of the ball's Newton iteration (_ball_newton) and of the global last resort (_damped_newton):
    a kernel search(x, step, res, tries, args) -> (lam, residual) that tries x + lam step for lam = 1, 1/2, 1/4, ...
    (`tries` times) until the residual norm residual_at(x, lam, step, args) falls below res, and takes the
    full step when none does (a plateau where no contact carries load: the norm is flat there). The
    evaluation of the returned step is the last one made, so its side effects (work arrays) are current.

    residual_at is a kernel; the search is built once per residual, which it holds as a constant: passed
    as an argument instead, a kernel would make every caller uncacheable (numba treats it as a dynamic
    global)."""

    @kernel
    def search(x, step, res, tries, args):
        lam = 1.0
        for _ in range(tries):
            trial = residual_at(x, lam, step, args)
            if trial < res:
                return lam, trial
            lam *= 0.5
        return 1.0, residual_at(x, 1.0, step, args)

    return search


@kernel
def qs_geometry(qs, dPd):
    """(A, r_i, r_o, A1_0, A2_0, Rr_i, alpha0) in m, m, m, m, m, m, rad for thermal clearance change dPd (m)."""
    D = qs[QS_D]
    A = (qs[QS_FI] + qs[QS_FO] - 1.0) * D
    Pd = qs[QS_PD]
    alpha0 = 0.0
    if Pd > 0.0:
        alpha0 = math.acos(max(-1.0, 1.0 - Pd / (2.0 * A)))
    A1_0 = A * math.sin(alpha0) if qs[QS_ANGULAR] > 0.5 else 0.0
    A2_0 = A - 0.5 * (Pd + dPd)
    Rr_i = 0.5 * qs[QS_DM] + (qs[QS_FI] - 0.5) * D * math.cos(alpha0)
    return A, (qs[QS_FI] - 0.5) * D, (qs[QS_FO] - 0.5) * D, A1_0, A2_0, Rr_i, alpha0


@kernel
def hybrid_inner_share(C, race):
    """Share lam_i (-) of the gyroscopic moment taken by the inner race under hybrid kinematics, for the
    spin-moment ratio C = Q_i a_i E_i / (Q_o a_o E_o) (-); lam_o = 2 - lam_i. Complex-safe.

    RACE_HYBRID shares the moment in proportion to the spin moments, lam_i = 2C/(1+C): continuous, and
    the same blend of outer (C -> 0) and inner (C -> inf) control that the hybrid pitch-angle law makes.
    The other codes are sensitivity readings; RACE_HYBRID_CONTROLLING jumps at C = 1, where the loads
    jump and Newton can fail (tests/validation/test_quasistatic_literature.py).
    """
    if race == RACE_HYBRID_OUTER_SPLIT:
        return 0.0 * C
    if race == RACE_HYBRID_INNER_SPLIT:
        return 2.0 + 0.0 * C
    if race == RACE_HYBRID_EQUAL_SPLIT:
        return 1.0 + 0.0 * C
    if race == RACE_HYBRID_CONTROLLING:
        return (2.0 if C.real > 1.0 else 0.0) + 0.0 * C
    return 2.0 * C / (1.0 + C)


@kernel
def kinematics(a_i, a_o, C, omega, gp, dm, D, m_ball, race, centrifugal, gyroscopic):
    """Race-control kinematics of one ball (complex-safe: also called with complex arguments).

    a_i, a_o: contact angles (rad); C: hybrid spin-moment ratio (-); omega: inner-ring speed (rad/s);
    gp = D/d_m. Returns (F_c (N), lam_o M_g/D (N), lam_i M_g/D (N), w_m (rad/s), w_R (rad/s), beta (rad)).
    """
    ci = cmath.cos(a_i)
    si = cmath.sin(a_i)
    co = cmath.cos(a_o)
    so = cmath.sin(a_o)
    one = 1.0 + 0.0 * C  # complex 1 carrying the type
    if race == RACE_OUTER:
        tan_beta = so / (co + gp)
        lam_o = 2.0 * one
        lam_i = 0.0 * one
    elif race == RACE_INNER:
        tan_beta = si / (ci - gp)
        lam_o = 0.0 * one
        lam_i = 2.0 * one
    else:
        S = (1.0 + gp * co) / (1.0 - gp * ci)  # Rabreau's S with its lost gamma restored (docs/quasistatic.md)
        Ah = gp * C * (cmath.cos(a_i - a_o) - S)
        tan_beta = (C * (S + 1.0) * si + 2.0 * so) / (C * (S + 1.0) * ci + 2.0 * (co + gp) + Ah)
        lam_i = hybrid_inner_share(C, race)
        lam_o = 2.0 - lam_i
    beta = cmath.atan(tan_beta)
    n_o = (1.0 - gp * ci) * cmath.cos(a_o - beta)
    w_m = omega * n_o / ((1.0 + gp * co) * cmath.cos(a_i - beta) + n_o)
    w_R = -w_m * (1.0 + gp * co) / (gp * cmath.cos(a_o - beta))
    F_c = 0.5 * m_ball * dm * w_m * w_m if centrifugal else 0.0 * one
    Mg_D = 0.1 * m_ball * D * w_R * w_m * cmath.sin(beta) if gyroscopic else 0.0 * one  # M_g / D
    return F_c, lam_o * Mg_D, lam_i * Mg_D, w_m, w_R, beta


@kernel
def _kin_grad(a_i, a_o, C, omega, gp, dm, D, m_ball, race, cen, gyro, g):
    """Values and partials of (F_c, Mg_o, Mg_i) w.r.t. (a_i, a_o, C) by complex step into g[KG_*, KG_*].

    Rows KG_FC (F_c), KG_MGO (lam_o M_g/D), KG_MGI (lam_i M_g/D); columns KG_VALUE, then the partials
    KG_DAI, KG_DAO, KG_DC."""
    h = _H_CSTEP
    r = kinematics(complex(a_i, h), complex(a_o, 0.0), complex(C, 0.0), omega, gp, dm, D, m_ball, race, cen, gyro)
    for k in range(3):
        g[k, KG_VALUE] = r[k].real
        g[k, KG_DAI] = r[k].imag / h
    r = kinematics(complex(a_i, 0.0), complex(a_o, h), complex(C, 0.0), omega, gp, dm, D, m_ball, race, cen, gyro)
    for k in range(3):
        g[k, KG_DAO] = r[k].imag / h
    if race >= RACE_HYBRID:
        r = kinematics(complex(a_i, 0.0), complex(a_o, 0.0), complex(C, h), omega, gp, dm, D, m_ball, race, cen, gyro)
        for k in range(3):
            g[k, KG_DC] = r[k].imag / h
    else:
        for k in range(3):
            g[k, KG_DC] = 0.0
    for k in range(3):
        g[k, KG_DQO] = 0.0


# inlined (as _ball_residual_at): a call boundary increfs and decrefs every work array of tw, atomic operations that
# took a quarter of a traction solve
@kernel(inline="always")
def _traction_grad(a_i, a_o, Q_i, Q_o, omega, dm, D, m_ball, cen, tw, g):
    """RACE_TRACTION's kinematic terms (F_c, Mg_o, Mg_i) as _kin_grad gives a hypothesis' (rows KG_*), solved from
    the film's traction for the contacts (a_i, a_o, Q_i, Q_o) (kernels.ball_traction), with their partials in a_i,
    a_o, Q_i (column KG_DC) and Q_o (KG_DQO). Mg_o, Mg_i are minus the in-plane traction forces (this kernel's sign
    of lam M_g / D). tw = (tr, y, out, Dy, dout, terms, dydp, p, ws, cw) (traction_work): the traction block, y (4,
    rad/s) the ball's kinematics, warm start and solution, the solver's work (ws; cw the coupled Newton's, whose flag
    cw[5] says its last evaluation is current), and the derivatives dy/dp at the last
    contacts p of the same ball (p[2] = 0: none), from which the next solve of the ball starts. A solve that does
    not converge gives NaN. Where the coupled Newton (kernels.ball_coupled_newton) has just converged at these
    contacts, its last evaluation (out, Dy, dout and terms, at y) is the solve's, verified there to the same
    tolerance, and is taken as it is."""
    tr, y, out, Dy, dout, terms, dydp, p, ws, cw = tw
    J = 0.1 * m_ball * D * D  # the ball's own balance: its gyroscopic moment whatever the hypotheses' option
    y0, y1, y2, y3 = y[0], y[1], y[2], y[3]
    fresh = cw[5]
    coupled = fresh[0] > 0.0 and ws[0][0] == a_i and ws[0][1] == a_o and ws[0][2] == Q_i and ws[0][3] == Q_o
    fresh[0] = 0.0
    predicted = p[2] > 0.0 and not coupled
    if predicted:  # the ball's last solution moved along its derivatives to these contacts (first order)
        dp = (a_i - p[0], a_o - p[1], Q_i - p[2], Q_o - p[3])
        for k in range(4):
            y[k] += dydp[k, 0] * dp[0] + dydp[k, 1] * dp[1] + dydp[k, 2] * dp[2] + dydp[k, 3] * dp[3]
    p[0] = a_i
    p[1] = a_o
    p[2] = Q_i
    p[3] = Q_o
    solved = coupled or solve_traction_with(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, dout, ws)
    if not solved and predicted:  # a prediction over a long step can land where Newton stalls: from the last solution
        y[0], y[1], y[2], y[3] = y0, y1, y2, y3
        solved = solve_traction_with(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, dout, ws)
    if not solved:
        solved = solve_from_rolling(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, dout)
    if not solved:  # NaN, which the ball's Newton refuses; the next solve of the ball starts from its last solution
        y[0], y[1], y[2], y[3] = y0, y1, y2, y3
        p[2] = 0.0
        for k in range(3):
            for c in range(KG_SIZE):
                g[k, c] = math.nan
        return
    implicit_derivatives(Dy, dout, dydp, ws[4])  # the solve left the partials at its solution in Dy and dout
    cols = (KG_DAI, KG_DAO, KG_DC, KG_DQO)
    fc = 0.5 * m_ball * dm if cen else 0.0
    g[KG_FC, KG_VALUE] = fc * y[0] * y[0]
    g[KG_MGO, KG_VALUE] = -out[TE_FTAU_O]
    g[KG_MGI, KG_VALUE] = -out[TE_FTAU_I]
    for c in range(4):
        g[KG_FC, cols[c]] = 2.0 * fc * y[0] * dout[TE_R, c]
        g[KG_MGO, cols[c]] = -dout[TE_FTAU_O, c]
        g[KG_MGI, cols[c]] = -dout[TE_FTAU_I, c]


@kernel
def _ball_eval(X1, X2, ball, kg, w, tw):
    """Ball residual, ring load and their derivatives at ball position X = (X1, X2) (m) into w (EV_*).

    ball = (A1, A2, r_i, r_o, K_i, K_o, f_i, omega, gp, dm, D, m_ball, race, cen, gyro, c_hyb): the
    curvature-centre offset A (m) and the ball's constants (ball_equilibrium); kg: float64[3, KG_SIZE] work;
    tw: RACE_TRACTION's block and work (traction_work), None for a hypothesis (numba then compiles this function
    without the traction branch).
    """
    A1, A2, r_i, r_o, K_i, K_o, f_i, omega, gp, dm, D, m_ball, race, cen, gyro, c_hyb = ball
    L_o, so, co, L_i, si, ci, Q_o, dQ_o, Q_i, dQ_i = ball_contacts(X1, X2, A1, A2, r_i, r_o, K_i, K_o)
    a_o = math.atan2(X1, X2)
    a_i = math.atan2(A1 - X1, A2 - X2)
    # gradients of the contact angles and loads: (d/dX1, d/dX2) and (d/dA1, d/dA2)
    dao_X1 = co / L_o
    dao_X2 = -so / L_o
    dai_A1 = ci / L_i
    dai_A2 = -si / L_i
    # the inner angle the kinematics take, a_k, and its gradients: a_i, except for an open inner contact
    # whose ball lies beyond the inner curvature centre (cos a_i <= 0, at a clearance of the order of the
    # groove's), where w_m's denominator vanishes at a_i = pi; such a ball rolls on its outer contact's angle
    a_k, dak_X1, dak_X2, dak_A1, dak_A2 = a_i, -dai_A1, -dai_A2, dai_A1, dai_A2
    if ci <= 0.0 and Q_i <= 0.0:
        a_k, dak_X1, dak_X2, dak_A1, dak_A2 = a_o, dao_X1, dao_X2, 0.0, 0.0
    dQo_X1 = dQ_o * so
    dQo_X2 = dQ_o * co
    dQi_A1 = dQ_i * si
    dQi_A2 = dQ_i * ci
    # hybrid spin-moment ratio C = c_hyb (Q_i/Q_o)^(4/3) (a ~ Q^(1/3)), capped where Q_o vanishes
    C = 0.0
    dC_Qi = 0.0
    dC_Qo = 0.0
    if race >= RACE_HYBRID and Q_i > 0.0:
        if Q_o > 0.0 and Q_i < 1e6 * Q_o:
            C = c_hyb * (Q_i / Q_o) ** (4.0 / 3.0)
            dC_Qi = 4.0 / 3.0 * C / Q_i
            dC_Qo = -4.0 / 3.0 * C / Q_o
        else:
            C = c_hyb * 1e8
    dC_X1 = -dC_Qi * dQi_A1 + dC_Qo * dQo_X1
    dC_X2 = -dC_Qi * dQi_A2 + dC_Qo * dQo_X2
    dC_A1 = dC_Qi * dQi_A1
    dC_A2 = dC_Qi * dQi_A2
    traction = False
    if tw is not None:
        if Q_i > 0.0 and Q_o > 0.0:
            # the kinematics of the film's traction depend on both loads: C stands for Q_i, KG_DQO carries Q_o
            _traction_grad(a_i, a_o, Q_i, Q_o, omega, dm, D, m_ball, cen, tw, kg)
            dC_X1 = -dQi_A1
            dC_X2 = -dQi_A2
            dC_A1 = dQi_A1
            dC_A2 = dQi_A2
            traction = True
    if not traction:
        # a ball that touches one race only has no traction to roll it: it keeps outer-race kinematics
        _kin_grad(a_k, a_o, C, omega, gp, dm, D, m_ball, RACE_OUTER if race == RACE_TRACTION else race, cen, gyro, kg)
    F_c = kg[KG_FC, KG_VALUE]
    Mgo = kg[KG_MGO, KG_VALUE]
    Mgi = kg[KG_MGI, KG_VALUE]
    # total derivatives of the kinematic terms: d/dX = p_ak dak_X + p_ao dao_X + p_C dC_X
    dak = (dak_X1, dak_X2, dak_A1, dak_A2)
    dFc_X1, dFc_X2, dFc_A1, dFc_A2 = _chain(kg, KG_FC, dak, dao_X1, dao_X2, dC_X1, dC_X2, dC_A1, dC_A2)
    dMo_X1, dMo_X2, dMo_A1, dMo_A2 = _chain(kg, KG_MGO, dak, dao_X1, dao_X2, dC_X1, dC_X2, dC_A1, dC_A2)
    dMi_X1, dMi_X2, dMi_A1, dMi_A2 = _chain(kg, KG_MGI, dak, dao_X1, dao_X2, dC_X1, dC_X2, dC_A1, dC_A2)
    # the outer load's part (RACE_TRACTION; X only)
    dFc_X1 += kg[KG_FC, KG_DQO] * dQo_X1
    dFc_X2 += kg[KG_FC, KG_DQO] * dQo_X2
    dMo_X1 += kg[KG_MGO, KG_DQO] * dQo_X1
    dMo_X2 += kg[KG_MGO, KG_DQO] * dQo_X2
    dMi_X1 += kg[KG_MGI, KG_DQO] * dQo_X1
    dMi_X2 += kg[KG_MGI, KG_DQO] * dQo_X2
    # n = (sin a, cos a), t = (cos a, -sin a); dn/da = t, dt/da = -n
    # ring load g = Q_i n_i - Mgi t_i;  dg = n_i dQ_i + (Q_i t_i + Mgi n_i) da_i - t_i dMgi
    gz = Q_i * si - Mgi * ci
    gr = Q_i * ci + Mgi * si
    pz = Q_i * ci + Mgi * si  # (Q_i t_i + Mgi n_i), axial component
    pr = -Q_i * si + Mgi * ci
    dgz_A1 = si * dQi_A1 + pz * dai_A1 - ci * dMi_A1
    dgz_A2 = si * dQi_A2 + pz * dai_A2 - ci * dMi_A2
    dgr_A1 = ci * dQi_A1 + pr * dai_A1 + si * dMi_A1
    dgr_A2 = ci * dQi_A2 + pr * dai_A2 + si * dMi_A2
    dgz_X1 = -si * dQi_A1 - pz * dai_A1 - ci * dMi_X1
    dgz_X2 = -si * dQi_A2 - pz * dai_A2 - ci * dMi_X2
    dgr_X1 = -ci * dQi_A1 - pr * dai_A1 + si * dMi_X1
    dgr_X2 = -ci * dQi_A2 - pr * dai_A2 + si * dMi_X2
    # residual r = g - Q_o n_o + F_c e_r + Mgo t_o
    # d(-Q_o n_o + Mgo t_o) = -n_o dQ_o - (Q_o t_o + Mgo n_o) da_o + t_o dMgo
    qz = Q_o * co + Mgo * so
    qr = -Q_o * so + Mgo * co
    w[EV_R1] = gz - Q_o * so + Mgo * co
    w[EV_R2] = gr - Q_o * co + F_c - Mgo * so
    w[EV_DR1_DX1] = dgz_X1 - so * dQo_X1 - qz * dao_X1 + co * dMo_X1
    w[EV_DR1_DX2] = dgz_X2 - so * dQo_X2 - qz * dao_X2 + co * dMo_X2
    w[EV_DR2_DX1] = dgr_X1 - co * dQo_X1 - qr * dao_X1 - so * dMo_X1 + dFc_X1
    w[EV_DR2_DX2] = dgr_X2 - co * dQo_X2 - qr * dao_X2 - so * dMo_X2 + dFc_X2
    w[EV_DR1_DA1] = dgz_A1 + co * dMo_A1
    w[EV_DR1_DA2] = dgz_A2 + co * dMo_A2
    w[EV_DR2_DA1] = dgr_A1 - so * dMo_A1 + dFc_A1
    w[EV_DR2_DA2] = dgr_A2 - so * dMo_A2 + dFc_A2
    w[EV_GZ] = gz
    w[EV_GR] = gr
    w[EV_MG] = f_i * D * Mgi
    w[EV_DGZ_DX1] = dgz_X1
    w[EV_DGZ_DX2] = dgz_X2
    w[EV_DGR_DX1] = dgr_X1
    w[EV_DGR_DX2] = dgr_X2
    w[EV_DGZ_DA1] = dgz_A1
    w[EV_DGZ_DA2] = dgz_A2
    w[EV_DGR_DA1] = dgr_A1
    w[EV_DGR_DA2] = dgr_A2
    w[EV_DM_DX1] = f_i * D * dMi_X1
    w[EV_DM_DX2] = f_i * D * dMi_X2
    w[EV_DM_DA1] = f_i * D * dMi_A1
    w[EV_DM_DA2] = f_i * D * dMi_A2
    w[EV_Q_I] = Q_i
    w[EV_Q_O] = Q_o
    w[EV_A_I] = a_i
    w[EV_A_O] = a_o
    w[EV_C] = C


@kernel(inline="always")
def _chain(kg, row, dak, dao_X1, dao_X2, dC_X1, dC_X2, dC_A1, dC_A2):
    """Total derivatives (d/dX1, d/dX2, d/dA1, d/dA2) of the kinematic term kg[row] through the kinematics'
    inner angle a_k (dak: its gradient (d/dX1, d/dX2, d/dA1, d/dA2)), a_o (depends on X only) and C."""
    p_ak = kg[row, KG_DAI]
    p_ao = kg[row, KG_DAO]
    p_C = kg[row, KG_DC]
    return (
        p_ak * dak[0] + p_ao * dao_X1 + p_C * dC_X1,
        p_ak * dak[1] + p_ao * dao_X2 + p_C * dC_X2,
        p_ak * dak[2] + p_C * dC_A1,
        p_ak * dak[3] + p_C * dC_A2,
    )


@kernel
def ball_equilibrium(A1, A2, X, j, qs, geo, omega, kg, w, cond, tw=None):
    """Solve one ball's equilibrium for curvature-centre offset (A1, A2) (m); warm start from X[:, j].

    geo = (r_i, r_o, K_series, f_ball) with K_series the Hertz constant of both contacts in series and
    f_ball (N) the bearing-level load per ball of the convergence test (_ball_newton); tw: RACE_TRACTION's block
    and work (traction_work), None for a hypothesis. RACE_TRACTION keeps the ball's kinematics over omega in
    X[X_Y:, j].
    Fills X[:, j] and cond (BE_*): ring load, friction couple, their derivatives w.r.t. A with the ball
    position condensed, contact loads, angles and the hybrid ratio; kg, w: work arrays of _ball_eval.
    Returns 0 (converged), 1 (unloaded ball), 2 (not converged).
    """
    r_i, r_o, K_s, f_ball = geo
    race = int(qs[QS_RACE])
    cen = qs[QS_CENTRIFUGAL] > 0.5 and omega != 0.0
    gyro = (qs[QS_GYROSCOPIC] > 0.5 or race == RACE_TRACTION) and omega != 0.0
    for k in range(BE_SIZE):
        cond[k] = 0.0
    if not (cen or gyro):
        return _static_ball(A1, A2, X, j, r_i, r_o, K_s, qs[QS_K_I], qs[QS_K_O], cond)
    F_c0 = 0.0
    if cen:
        dm = qs[QS_DM]
        F_c0 = 0.5 * qs[QS_M_BALL] * dm * (0.5 * omega * (1.0 - qs[QS_D] / dm)) ** 2  # for the start only
    if math.hypot(A1, A2) - r_i - r_o <= 0.0 and F_c0 <= 0.0:
        return _unloaded_ball(A1, A2, X, j, r_o, cond)
    x = X[:, j]  # the Newton iterates in place: X[:, j] is the start and the solution
    _ball_start(A1, A2, x, r_i, r_o, qs[QS_K_I], qs[QS_K_O], F_c0)
    D = qs[QS_D]
    dm = qs[QS_DM]
    if tw is not None:  # the kinematics' warm start: the last solution at this speed, or rolling
        y = tw[1]
        tw[7][2] = 0.0  # no derivatives of this ball yet
        if 0.0 < X[X_Y, j] < 1.0:
            for k in range(4):
                y[k] = X[X_Y + k, j] * omega
        else:
            rolling_start(math.atan2(A1, A2), math.atan2(A1, A2), omega, D, dm, y)
        # the position and the kinematics by one Newton; the nested solve below then verifies the result in one
        # evaluation (or starts from x and y as they were, where the coupled Newton did not converge)
        fc = 0.5 * qs[QS_M_BALL] * dm if cen else 0.0
        coupled = (A1, A2, r_i, r_o, qs[QS_K_I], qs[QS_K_O], omega, D, dm, 0.1 * qs[QS_M_BALL] * D * D, fc)
        f_scale = abs(F_c0) + f_ball
        coupled_newton(x, y, coupled, f_scale, _BALL_RTOL, tw[0], tw[5], tw[2], tw[3], tw[4], tw[8][0], tw[9])
    ball = (A1, A2, r_i, r_o, qs[QS_K_I], qs[QS_K_O], qs[QS_FI], omega, D / dm, dm, D, qs[QS_M_BALL],
            race, cen, gyro, qs[QS_C_HYB])  # fmt: skip
    status = _ball_newton(x, ball, F_c0, f_ball, kg, w, tw)
    if status == 2 and (x[0] != 0.0 or x[1] != 0.0):
        # a warm start far from this solution (the ball floated in its clearance at the last solve and sits
        # where the damped steps crawl): once more from the cold start
        x[0] = 0.0
        x[1] = 0.0
        _ball_start(A1, A2, x, r_i, r_o, qs[QS_K_I], qs[QS_K_O], F_c0)
        status = _ball_newton(x, ball, F_c0, f_ball, kg, w, tw)
    if tw is not None:
        for k in range(4):
            X[X_Y + k, j] = tw[1][k] / omega
    if not _condense(w, cond):
        return 2
    if w[EV_Q_I] <= 0.0 and w[EV_Q_O] <= 0.0:
        return 1
    return status


@kernel
def traction_work(qs):
    """RACE_TRACTION's traction block and the work arrays of its ball kinematics (tr, y, out, Dy, dout, terms, dydp,
    p, ws: kernels.ball_traction, _traction_grad; cw: kernels.ball_coupled_newton)."""
    return (
        qs[QS_TRACTION:],
        np.zeros(4),
        np.zeros(TE_SIZE),
        np.zeros((TE_SIZE, 4)),
        np.zeros((TE_SIZE, 4)),
        np.zeros((2, TT_SIZE)),
        np.zeros((4, 4)),
        np.zeros(4),
        solve_work(),
        coupled_work(),
    )


@kernel
def _unloaded_ball(A1, A2, X, j, r_o, cond):
    """A ball touching neither race: resting on the outer groove along the line of centres; returns 1."""
    L = math.hypot(A1, A2)
    X[0, j] = A1 / L * r_o
    X[1, j] = A2 / L * r_o
    cond[BE_A_I] = math.atan2(A1, A2)
    cond[BE_A_O] = cond[BE_A_I]
    return 1


@kernel
def _static_ball(A1, A2, X, j, r_i, r_o, K_s, K_i, K_o, cond):
    """Ball at rest (no centrifugal force, no gyroscopic moment): both contacts in series along the line
    of centres, an exact closed form; fills X[:, j] and cond as ball_equilibrium. Returns 0 or 1 (unloaded)."""
    L = math.hypot(A1, A2)
    n1 = A1 / L
    n2 = A2 / L
    delta = L - r_i - r_o
    if delta <= 0.0:
        return _unloaded_ball(A1, A2, X, j, r_o, cond)
    sq = math.sqrt(delta)
    Q = K_s * delta * sq
    dQ = 1.5 * K_s * sq
    d_o = delta / (1.0 + (K_o / K_i) ** (2.0 / 3.0))
    X[0, j] = n1 * (r_o + d_o)
    X[1, j] = n2 * (r_o + d_o)
    geo_t = Q / L
    cond[BE_GZ] = Q * n1
    cond[BE_GR] = Q * n2
    cond[BE_DGZ_DA1] = dQ * n1 * n1 + geo_t * (1.0 - n1 * n1)
    cond[BE_DGZ_DA2] = (dQ - geo_t) * n1 * n2
    cond[BE_DGR_DA1] = cond[BE_DGZ_DA2]
    cond[BE_DGR_DA2] = dQ * n2 * n2 + geo_t * (1.0 - n2 * n2)
    cond[BE_Q_I] = Q
    cond[BE_Q_O] = Q
    cond[BE_A_I] = math.atan2(A1, A2)
    cond[BE_A_O] = cond[BE_A_I]
    return 0


@kernel
def _ball_start(A1, A2, x, r_i, r_o, K_i, K_o, F_c0):
    """Start of the ball Newton in x (2, m): kept when it is a plausible ball position (warm start), else
    the static split of the approach plus the centrifugal outer deflection, or the ball resting on the
    outer race under the centrifugal force F_c0 (N).

    Plausible means pressed into the outer race (|x| > r_o: a solved ball always is, by its centrifugal
    force or by a loaded inner contact) and, when the races squeeze the ball (approach delta > 0), into
    the inner race as well. A warm start that touches one race only (a ball that was unloaded at the last
    solve and floats in its clearance) leaves Newton with the stiffness of one contact and a residual of
    the other's sign: the damped steps crawl (tens of iterations of 1/32 steps), so such a start is
    replaced."""
    L = math.hypot(A1, A2)
    delta = L - r_i - r_o
    if x[1] > 0.0 and math.hypot(x[0], x[1]) > r_o and (delta <= 0.0 or math.hypot(A1 - x[0], A2 - x[1]) > r_i):
        return
    if delta > 0.0:
        d_o = delta / (1.0 + (K_o / K_i) ** (2.0 / 3.0)) + (F_c0 / K_o) ** (2.0 / 3.0)
        x[0] = A1 / L * (r_o + d_o)
        x[1] = A2 / L * (r_o + d_o)
    else:
        x[0] = 0.0
        x[1] = r_o + (F_c0 / K_o) ** (2.0 / 3.0)


@kernel(inline="always")  # see _traction_grad
def _ball_residual_at(x, lam, step, args):
    """Evaluate the ball at x + lam step (m) into its work array; returns the residual norm (N)."""
    ball, kg, w, tw = args
    _ball_eval(x[0] + lam * step[0], x[1] + lam * step[1], ball, kg, w, tw)
    return math.hypot(w[EV_R1], w[EV_R2])


@kernel
def _ball_newton(x, ball, F_c0, f_ball, kg, w, tw):
    """Damped Newton on the ball position x (2, m, updated in place) from its start; w holds the
    evaluation at the final x. Returns 0 (converged) or 2 (not converged: iteration cap or singular dr/dX).

    Converged when |r| <= _BALL_RTOL (Q_i + Q_o + |F_c0| + f_ball): f_ball (N) is the bearing-level load
    per ball, so that a nearly unloaded ball (at low speed its loads are the tiny centrifugal force, and
    rounding in its position alone gives a residual far above 1e-13 of them) is judged against the loads
    that the global equilibrium balances, not against its own."""
    r_i, r_o, D = ball[2], ball[3], ball[10]  # layout of `ball`: _ball_eval
    _ball_eval(x[0], x[1], ball, kg, w, tw)
    res = math.hypot(w[EV_R1], w[EV_R2])
    for _ in range(_BALL_MAXIT):
        scale = w[EV_Q_I] + w[EV_Q_O] + abs(F_c0) + f_ball + 1e-300
        if res <= _BALL_RTOL * scale:
            return 0
        det = w[EV_DR1_DX1] * w[EV_DR2_DX2] - w[EV_DR1_DX2] * w[EV_DR2_DX1]
        if det == 0.0 or not math.isfinite(det):
            return 2
        s1 = -(w[EV_DR2_DX2] * w[EV_R1] - w[EV_DR1_DX2] * w[EV_R2]) / det
        s2 = -(-w[EV_DR2_DX1] * w[EV_R1] + w[EV_DR1_DX1] * w[EV_R2]) / det
        # cap the step at a tenth of the groove clearance
        cap = 0.1 * (r_i + r_o)
        norm = math.hypot(s1, s2)
        if norm > cap:
            s1 *= cap / norm
            s2 *= cap / norm
        if norm < 1e-15 * D:
            return 0
        lam, res = _ball_line_search(x, (s1, s2), res, _BALL_TRIES, (ball, kg, w, tw))
        x[0] += lam * s1
        x[1] += lam * s2
    return 2


@kernel
def _condense(w, cond):
    """Ball position condensed out of the derivatives at the evaluation w: dX/dA = -(dr/dX)^-1 dr/dA and
    the total dg/dA = dg/dA + dg/dX dX/dA (likewise dm/dA) into cond, with the loads and angles.
    Returns False when dr/dX is singular."""
    det = w[EV_DR1_DX1] * w[EV_DR2_DX2] - w[EV_DR1_DX2] * w[EV_DR2_DX1]
    if det == 0.0 or not math.isfinite(det):
        return False
    i00 = w[EV_DR2_DX2] / det
    i01 = -w[EV_DR1_DX2] / det
    i10 = -w[EV_DR2_DX1] / det
    i11 = w[EV_DR1_DX1] / det
    x_a00 = -(i00 * w[EV_DR1_DA1] + i01 * w[EV_DR2_DA1])
    x_a01 = -(i00 * w[EV_DR1_DA2] + i01 * w[EV_DR2_DA2])
    x_a10 = -(i10 * w[EV_DR1_DA1] + i11 * w[EV_DR2_DA1])
    x_a11 = -(i10 * w[EV_DR1_DA2] + i11 * w[EV_DR2_DA2])
    cond[BE_GZ] = w[EV_GZ]
    cond[BE_GR] = w[EV_GR]
    cond[BE_MG] = w[EV_MG]
    cond[BE_DGZ_DA1] = w[EV_DGZ_DA1] + w[EV_DGZ_DX1] * x_a00 + w[EV_DGZ_DX2] * x_a10
    cond[BE_DGZ_DA2] = w[EV_DGZ_DA2] + w[EV_DGZ_DX1] * x_a01 + w[EV_DGZ_DX2] * x_a11
    cond[BE_DGR_DA1] = w[EV_DGR_DA1] + w[EV_DGR_DX1] * x_a00 + w[EV_DGR_DX2] * x_a10
    cond[BE_DGR_DA2] = w[EV_DGR_DA2] + w[EV_DGR_DX1] * x_a01 + w[EV_DGR_DX2] * x_a11
    cond[BE_DM_DA1] = w[EV_DM_DA1] + w[EV_DM_DX1] * x_a00 + w[EV_DM_DX2] * x_a10
    cond[BE_DM_DA2] = w[EV_DM_DA2] + w[EV_DM_DX1] * x_a01 + w[EV_DM_DX2] * x_a11
    cond[BE_Q_I] = w[EV_Q_I]
    cond[BE_Q_O] = w[EV_Q_O]
    cond[BE_A_I] = w[EV_A_I]
    cond[BE_A_O] = w[EV_A_O]
    cond[BE_C] = w[EV_C]
    return True


@kernel
def bearing_loads(d, qs, dPd, omega, X, F, K, balls):
    """Displacement-controlled evaluation: loads F (5, N and N.m) and stiffness K = dF/dd (5x5)
    for inner-ring displacements d (5, m and rad), clearance change dPd (m), speed omega (rad/s).

    X (2, Z): ball positions, used as warm start and updated; balls (BQ_SIZE, Z): per-ball outputs.
    Returns the worst ball status (0 all converged or unloaded, 2 a ball did not converge).
    """
    contact = np.empty((CS_SIZE, int(qs[QS_Z])))
    worst = ring_loads(d, qs, dPd, omega, X, F, K, contact, True)
    ball_outputs(omega, qs, X, contact, balls)
    return worst


@kernel
def ring_loads(d, qs, dPd, omega, X, F, K, contact, jacobian, f_load=0.0):
    """Loads F (5, N and N.m) on the inner ring at displacements d (5, m and rad), and K = dF/dd (5x5)
    when `jacobian` (otherwise K is not touched); clearance change dPd (m), speed omega (rad/s).
    f_load (N): the bearing-level load (largest applied load; at least _F_FLOOR), whose share per ball
    sets the force scale of the ball convergence test.

    X (2, Z): ball positions, warm start and updated; contact (CS_SIZE, Z): per-ball contact state
    (filled), from which ball_outputs derives the per-ball outputs once the solve has converged.
    Returns the worst ball status (0 all converged or unloaded, 2 a ball did not converge).
    """
    if int(qs[QS_RACE]) == RACE_TRACTION and omega != 0.0:
        return _ring_loads(d, qs, dPd, omega, X, F, K, contact, jacobian, f_load, traction_work(qs))
    return _ring_loads(d, qs, dPd, omega, X, F, K, contact, jacobian, f_load, None)


@kernel
def _ring_loads(d, qs, dPd, omega, X, F, K, contact, jacobian, f_load, tw):
    """ring_loads with RACE_TRACTION's block and work tw (traction_work), or None: numba compiles it once for the
    hypotheses, without the traction branches, and once for the race control from traction."""
    Z = int(qs[QS_Z])
    A, r_i, r_o, A1_0, A2_0, Rr, alpha0 = qs_geometry(qs, dPd)
    K_s = (qs[QS_K_I] ** (-2.0 / 3.0) + qs[QS_K_O] ** (-2.0 / 3.0)) ** -1.5
    geo = (r_i, r_o, K_s, max(f_load, _F_FLOOR) / Z)
    kg = np.empty((3, KG_SIZE))
    w = np.empty(EV_SIZE)
    cond = np.empty(BE_SIZE)
    for i in range(5):
        F[i] = 0.0
    if jacobian:
        for i in range(5):
            for k in range(5):
                K[i, k] = 0.0
    worst = 0
    for j in range(Z):
        cp, sp = ball_direction(j, Z)
        A1 = A1_0 + d[2] + Rr * (d[3] * sp - d[4] * cp)
        A2 = A2_0 + d[0] * cp + d[1] * sp
        status = ball_equilibrium(A1, A2, X, j, qs, geo, omega, kg, w, cond, tw)
        if status == 2:
            worst = 2
        gz = cond[BE_GZ]
        gr = cond[BE_GR]
        mg = cond[BE_MG]
        mom = Rr * gz + mg
        F[0] += gr * cp
        F[1] += gr * sp
        F[2] += gz
        F[3] += mom * sp
        F[4] -= mom * cp
        if jacobian:
            # T = dA/dd: rows A1 -> (0, 0, 1, Rr sp, -Rr cp), A2 -> (cp, sp, 0, 0, 0)
            t1 = (0.0, 0.0, 1.0, Rr * sp, -Rr * cp)
            t2 = (cp, sp, 0.0, 0.0, 0.0)
            em = (0.0, 0.0, 0.0, sp, -cp)
            # dF/dd = T^T (dg/dA) T + e_m (dm/dA) T
            for a in range(5):
                row_z = cond[BE_DGZ_DA1] * t1[a] + cond[BE_DGZ_DA2] * t2[a]  # d g_z / dd_a
                row_r = cond[BE_DGR_DA1] * t1[a] + cond[BE_DGR_DA2] * t2[a]  # d g_r / dd_a
                row_m = cond[BE_DM_DA1] * t1[a] + cond[BE_DM_DA2] * t2[a]  # d m_g / dd_a
                for i in range(5):
                    K[i, a] += t1[i] * row_z + t2[i] * row_r + em[i] * row_m
        contact[CS_Q_I, j] = cond[BE_Q_I]
        contact[CS_Q_O, j] = cond[BE_Q_O]
        contact[CS_A_I, j] = cond[BE_A_I]
        contact[CS_A_O, j] = cond[BE_A_O]
        contact[CS_C, j] = cond[BE_C]
    return worst


@kernel
def ball_outputs(omega, qs, X, contact, balls):
    """Per-ball loads, angles and kinematics (spin and rolling speeds at both contacts) from the
    contact state of ring_loads and the ball positions X (m) at speed omega (rad/s); fills balls."""
    D = qs[QS_D]
    dm = qs[QS_DM]
    gp = D / dm
    race = int(qs[QS_RACE])
    cen = qs[QS_CENTRIFUGAL] > 0.5 and omega != 0.0
    gyro = qs[QS_GYROSCOPIC] > 0.5 and omega != 0.0
    for j in range(contact.shape[1]):
        a_i = contact[CS_A_I, j]
        a_o = contact[CS_A_O, j]
        C = contact[CS_C, j]
        a_k = a_o if contact[CS_Q_I, j] <= 0.0 and math.cos(a_i) <= 0.0 else a_i  # as in _ball_eval
        F_c, Mgo, Mgi, w_m, w_R, beta = kinematics(
            complex(a_k, 0.0),
            complex(a_o, 0.0),
            complex(C, 0.0),
            omega,
            gp,
            dm,
            D,
            qs[QS_M_BALL],
            RACE_OUTER if race == RACE_TRACTION else race,
            cen,
            gyro,
        )
        F_c = F_c.real
        w_m = w_m.real
        w_R = w_R.real
        beta = beta.real
        Mg = (Mgo.real + Mgi.real) * D * 0.5  # lam_o + lam_i = 2
        lam_i = 0.0
        if race == RACE_INNER:
            lam_i = 2.0
        elif race >= RACE_HYBRID:
            lam_i = hybrid_inner_share(C, race)
        u_i = abs(omega - w_m) * 0.5 * dm * (1.0 - gp * math.cos(a_i))
        u_o = abs(w_m) * 0.5 * dm * (1.0 + gp * math.cos(a_o))
        p_i = 0.0
        p_o = 0.0
        # the friction a hypothesis asks of each contact: its share of the gyroscopic moment, the only tangential
        # force of its ball balance
        Q_i = contact[CS_Q_I, j]
        Q_o = contact[CS_Q_O, j]
        balls[BQ_MU_REQ_I, j] = abs(Mgi.real) / Q_i if Q_i > 0.0 and race != RACE_TRACTION else 0.0
        balls[BQ_MU_REQ_O, j] = abs(Mgo.real) / Q_o if Q_o > 0.0 and race != RACE_TRACTION else 0.0
        if race == RACE_TRACTION and omega != 0.0 and Q_i > 0.0 and Q_o > 0.0:
            w_m, w_R, beta, Mg, lam_i, u_i, u_o, p_i, p_o = _traction_ball(omega, qs, X, contact, j)
            F_c = 0.5 * qs[QS_M_BALL] * dm * w_m * w_m if cen else 0.0
        balls[BQ_Q_I, j] = contact[CS_Q_I, j]
        balls[BQ_Q_O, j] = contact[CS_Q_O, j]
        balls[BQ_A_I, j] = a_i
        balls[BQ_A_O, j] = a_o
        balls[BQ_BETA, j] = beta
        balls[BQ_W_M, j] = w_m
        balls[BQ_W_R, j] = w_R
        balls[BQ_F_C, j] = F_c
        balls[BQ_M_G, j] = Mg
        balls[BQ_X1, j] = X[0, j]
        balls[BQ_X2, j] = X[1, j]
        balls[BQ_LAM_I, j] = lam_i
        # spin = (ball - race) angular velocity along the contact normal, in the cage frame (docs/quasistatic.md)
        balls[BQ_SPIN_O, j] = w_R * math.sin(a_o - beta) + w_m * math.sin(a_o)
        balls[BQ_SPIN_I, j] = -w_R * math.sin(a_i - beta) + (omega - w_m) * math.sin(a_i)
        balls[BQ_U_O, j] = u_o
        balls[BQ_U_I, j] = u_i
        balls[BQ_P_SLIP_I, j] = p_i
        balls[BQ_P_SLIP_O, j] = p_o


@kernel
def _traction_ball(omega, qs, X, contact, j):
    """Per-ball outputs of RACE_TRACTION from the kinematics y = X[X_Y:, j] omega (rad/s) of the solution:
    (w_m, w_R, beta, M_g, lam_i, u_i, u_o, P_slip_i, P_slip_o) in ball_outputs' units and signs (w_R the spin
    relative to the cage about the axis (cos beta, -sin beta), negative for omega > 0), for a ball loaded on both
    races (a ball on one race keeps outer-race kinematics, _ball_eval)."""
    D = qs[QS_D]
    dm = qs[QS_DM]
    w_m = X[X_Y, j] * omega
    rel_a = X[X_Y + 1, j] * omega - w_m
    rel_r = X[X_Y + 2, j] * omega
    w_R = -math.copysign(math.hypot(rel_a, rel_r), omega)
    beta = math.atan2(-rel_r / w_R, rel_a / w_R) if w_R != 0.0 else 0.0
    Mg = 0.1 * qs[QS_M_BALL] * D * D * w_R * w_m * math.sin(beta)
    Q_i = contact[CS_Q_I, j]
    Q_o = contact[CS_Q_O, j]
    a_i = contact[CS_A_I, j]
    a_o = contact[CS_A_O, j]
    te = np.empty(TE_SIZE)
    y = np.empty(4)
    for k in range(4):
        y[k] = X[X_Y + k, j] * omega
    J = 0.1 * qs[QS_M_BALL] * D * D
    traction_eval(y, a_i, a_o, Q_i, Q_o, omega, D, dm, J, qs[QS_TRACTION:], te)
    # the inner race's share of the in-plane traction (lam_i + lam_o = 2)
    f_i = -te[TE_FTAU_I]
    f_sum = f_i - te[TE_FTAU_O]
    lam_i = 2.0 * f_i / f_sum if f_sum != 0.0 else 0.0
    return w_m, w_R, beta, Mg, lam_i, te[TE_U_I], te[TE_U_O], te[TE_P_I], te[TE_P_O]


@kernel
def solve_quasistatic(F_applied, control, d, qs, dPd, omega, X, F, K, balls):
    """Global equilibrium by trust-region Newton with the analytic Jacobian (_global_newton).

    F_applied (5): loads (N, N.m) on the load-controlled DOFs; control (5): 1 = load-controlled,
    0 = displacement-controlled (d holds the imposed value); d (5, m and rad): warm start, solution
    on return; F: reactions at the solution (N, N.m); X (X_SIZE, Z, or 2 rows for the hypotheses): ball states,
    warm start and solution; RACE_TRACTION from a cold X starts from the outer-race-controlled solution. Filled
    once, at the solution: balls (BQ_SIZE, Z) per-ball outputs, and K (5x5) the stiffness dF/dd when
    qs[QS_STIFFNESS] is set (otherwise K is not touched).
    Returns (status, iterations, residual): status QS_* code, residual = max scaled load error (N).
    """
    idx = np.empty(5, np.int64)
    n = 0
    for i in range(5):
        if control[i] > 0.5:
            idx[n] = i
            n += 1
    stiffness = qs[QS_STIFFNESS] > 0.5
    J = np.empty((5, 5))  # Newton matrix: the stiffness of the current iterate
    contact = np.empty((CS_SIZE, int(qs[QS_Z])))
    it = 0
    if int(qs[QS_RACE]) == RACE_TRACTION and omega != 0.0 and _cold(X):
        # the film's traction from a cold start: far from rolling, the balls' kinematics stall or need continuation at
        # every trial of the ring's Newton; the outer-race-controlled bearing is the start instead (each ball's
        # traction kinematics then start from rolling at its contacts)
        rolling = qs.copy()
        rolling[QS_RACE] = RACE_OUTER
        d_cold = d.copy()
        status, it, res = _global_newton(F_applied, idx, n, d, rolling, dPd, omega, X, F, J, contact, n > 0)
        if status != QS_OK:  # the traction solve from the cold start itself
            d[:] = d_cold
            X[:, :] = 0.0
    d_start = d.copy()
    X_start = X.copy()
    status, more, res = _global_newton(F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, stiffness or n > 0)
    it += more
    if status != QS_OK and n > 0:
        d[:] = d_start
        X[:, :] = X_start
        status, more, res = _damped_newton(F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, True)
        it += more + 1
    ball_outputs(omega, qs, X, contact, balls)
    if stiffness:
        K[:, :] = J
    return status, it, res


@kernel
def _cold(X):
    """No ball has traction kinematics yet (X[X_Y] = w_m / omega, in ]0, 1[ once solved)."""
    for j in range(X.shape[1]):
        if 0.0 < X[X_Y, j] < 1.0:
            return False
    return True


@kernel
def _newton_settings(qs, dPd):
    """(A (m), tolerance, iteration cap, DOF scales (rotations as arc lengths at Rr, moments as forces), the
    stiffness floor that regularises a bearing with no loaded ball) of the ring's Newton solvers."""
    A, r_i, r_o, A1_0, A2_0, Rr, alpha0 = qs_geometry(qs, dPd)
    scale = np.array([1.0, 1.0, 1.0, Rr, Rr])
    K_s = (qs[QS_K_I] ** (-2.0 / 3.0) + qs[QS_K_O] ** (-2.0 / 3.0)) ** -1.5
    return A, qs[QS_TOL], int(qs[QS_MAXIT]), scale, 1e-6 * K_s * math.sqrt(1e-3 * qs[QS_D])


@kernel
def _newton_start(F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, jacobian, scale, d_try):
    """The first evaluation of the ring's Newton solvers at d (from the free-ring start when it applies):
    returns (X_try, status, f_ref, loads, ball_status, res): the trial ball states, the worst ball status of the
    last evaluation with the count of evaluations after the first (status[0], status[1]), the bearing-level load
    scale, the arguments of _loads_residual_at, the ball status and the scaled residual at d."""
    A1_0 = qs_geometry(qs, dPd)[3]
    X_try = X.copy()
    status = np.zeros(2, np.int64)
    f_ref = _F_FLOOR
    for i in range(n):
        f_ref = max(f_ref, abs(F_applied[idx[i]]) / scale[idx[i]])
    loads = (F_applied, idx, n, scale, qs, dPd, omega, X, X_try, d_try, F, J, contact, jacobian, status, f_ref)
    ball_status = ring_loads(d, qs, dPd, omega, X, F, J, contact, jacobian, f_ref)
    if n > 0 and _free_ring_start(F_applied, idx, n, A1_0, d, contact):
        ball_status = ring_loads(d, qs, dPd, omega, X, F, J, contact, jacobian, f_ref)
        status[1] += 1
    res = _residual_norm(F_applied, F, idx, n, scale)
    return X_try, status, f_ref, loads, ball_status, res


@kernel
def _global_newton(F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, jacobian):
    """Trust-region Newton on the loads of the n load-controlled DOFs idx[:n] (solve_quasistatic's loop;
    docs/quasistatic.md section 3).

    Each iteration tries the Newton step first and takes it whole when it lies inside the trust region;
    otherwise a dogleg step (_dogleg) between the Newton step and the steepest descent of the ring's
    potential energy (the unbalanced load itself). A trial is taken when the unbalanced load does at least
    _TR_ACCEPT of the work the quadratic model predicts along it (at rest: the potential energy falls), or
    when it lowers the largest load error (plain damped Newton's rule, so that the globalisation changes
    nothing where Newton converges); otherwise the region shrinks and the iteration tries again. A region
    that collapses (_TR_COLLAPSE) sits on a discontinuity of the loads: the Newton step, capped at the
    first radius, crosses it. J (5x5) is assembled at every evaluation
    when `jacobian` (needed whenever n > 0). On success the last evaluation is that of the returned d, so
    F, J, contact and X belong to the solution; a failed solve leaves them at its last trial."""
    A, tol, maxit, scale, k_floor = _newton_settings(qs, dPd)
    radius = _TR_RADIUS * A  # trust radius (m, scaled DOFs); the first trial is the full Newton step inside it
    Kr = np.empty((5, 6))  # the Newton system (_newton_system), then the Newton step in its column n
    Ks = np.empty((5, 5))  # symmetric part of the regularised Newton matrix: the curvature of the model
    g = np.empty(5)  # scaled unbalanced load at the iterate (N): minus the gradient of the potential energy
    Rw = np.empty(5)  # Newton step (m, scaled DOFs)
    p = np.empty(5)  # trial step (m, scaled DOFs)
    step = np.empty(5)
    d_try = np.empty(5)
    X_try, status, f_ref, loads, ball_status, res = _newton_start(
        F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, jacobian, scale, d_try
    )
    for it in range(maxit + 1):
        end = _iteration_end(res, tol, f_ref, contact, n, ball_status)
        if end >= 0:
            return end, status[1], res
        if it == maxit:
            break
        _newton_system(F_applied, F, J, idx, n, scale, k_floor, Kr)
        for a in range(n):
            g[a] = Kr[a, n]
            for b in range(n):
                Ks[a, b] = 0.5 * (Kr[a, b] + Kr[b, a])
        if not gauss_solve(Kr, n, n + 1):
            return QS_NOT_FINITE, it, res
        for a in range(n):
            Rw[a] = Kr[a, n]
        if _max_abs(Rw, n) < 1e-15 * A:
            return (QS_BALL_NOT_CONVERGED if ball_status == 2 else QS_OK), status[1], res
        accepted = False
        while radius >= _TR_COLLAPSE * A:
            predicted = _dogleg(Rw, g, Ks, n, radius, p)
            _full_step(p, 1.0, idx, n, scale, step)
            trial = _loads_residual_at(d, 1.0, step, loads)  # d_try, X_try, F, J, contact: at the trial
            # work of the unbalanced load along the step (trapezoidal rule): at rest the decrease of the
            # potential energy, to third order in the step; the model predicts it exactly when K is constant
            work = 0.0
            length = 0.0
            for a in range(n):
                ia = idx[a]
                work += 0.5 * (g[a] + (F_applied[ia] - F[ia]) / scale[ia]) * p[a]
                length += p[a] * p[a]
            length = math.sqrt(length)
            ratio = work / predicted
            if not (ratio >= 0.25 and math.isfinite(trial)):
                radius = 0.25 * length
            elif ratio > 0.75 and length >= 0.99 * radius:
                radius = min(2.0 * radius, A)
            if (ratio > _TR_ACCEPT or trial < res) and math.isfinite(trial):
                accepted = True
                break
        if not accepted:
            # the region collapsed on a discontinuity of the loads (a ball state that jumps between branches,
            # docs/quasistatic.md section 3): step across it with the Newton step, capped at the first radius,
            # and start afresh from there
            f = min(1.0, _TR_RADIUS * A / math.sqrt(_sum_squares(Rw, n)))
            _full_step(Rw, f, idx, n, scale, step)
            trial = _loads_residual_at(d, 1.0, step, loads)
            radius = _TR_RADIUS * A
        res = trial
        for a in range(5):
            d[a] = d_try[a]
        X[:, :] = X_try
        ball_status = status[0]
    return QS_NOT_CONVERGED, status[1], res


@kernel(inline="always")
def _iteration_end(res, tol, f_ref, contact, n, ball_status):
    """How the ring's Newton solvers end at an iterate of scaled residual res (N): QS_NOT_FINITE, QS_OK (or
    QS_BALL_NOT_CONVERGED when a ball did not converge) once res is within tol of the larger of the load scale f_ref
    and the mean ball load, or with no load-controlled DOF (n = 0); -1 to go on."""
    if not math.isfinite(res):
        return QS_NOT_FINITE
    if res <= tol * max(f_ref, _mean_ball_load(contact)) or n == 0:
        return QS_BALL_NOT_CONVERGED if ball_status == 2 else QS_OK
    return -1


@kernel(inline="always")
def _newton_system(F_applied, F, J, idx, n, scale, k_floor, Kr):
    """The ring's Newton system on the n load-controlled DOFs idx[:n], in scaled DOFs (rotations as arc lengths,
    moments as forces: scale), into Kr[:n, :n + 1] (kernels.elimination's layout): the stiffness (N/m), its diagonal
    raised by 1e-12 of its largest entry and the floor k_floor (N/m) so that a ring with no loaded ball still has a
    step, and in column n the unbalanced load (N)."""
    kmax = 0.0
    for a in range(n):
        kmax = max(kmax, J[idx[a], idx[a]] / (scale[idx[a]] ** 2))
    for a in range(n):
        ia = idx[a]
        Kr[a, n] = (F_applied[ia] - F[ia]) / scale[ia]
        for b in range(n):
            ib = idx[b]
            Kr[a, b] = J[ia, ib] / (scale[ia] * scale[ib])
        Kr[a, a] += 1e-12 * kmax + k_floor


@kernel(inline="always")
def _full_step(p, f, idx, n, scale, step):
    """The step of the five DOFs (m and rad) from f times the step p[:n] of the n load-controlled DOFs idx[:n] in
    scaled DOFs (m; scale as in _newton_system); 0 on the displacement-controlled DOFs."""
    for a in range(5):
        step[a] = 0.0
    for a in range(n):
        step[idx[a]] = f * p[a] / scale[idx[a]]


@kernel(inline="always")
def _max_abs(v, n):
    """The largest |v[:n]|."""
    big = 0.0
    for a in range(n):
        big = max(big, abs(v[a]))
    return big


@kernel
def _damped_newton(F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, jacobian):
    """Damped Newton on the loads of the n load-controlled DOFs idx[:n]: solve_quasistatic's last resort when
    the trust region (_global_newton) fails. The step is capped at 0.05 A and backtracked on the largest load
    error, and taken whole when no cut lowers it: on a discontinuity of the loads (a hybrid moment share that
    jumps, a ball state that jumps between branches) this sometimes lands where the trust region stops.

    J (5x5) is assembled at every evaluation when `jacobian` (needed whenever n > 0); the last
    evaluation is always that of the returned d, so F, J, contact and X belong to the solution."""
    A, tol, maxit, scale, k_floor = _newton_settings(qs, dPd)
    step_cap = 0.05 * A
    Kr = np.empty((5, 6))  # the Newton system (_newton_system), then the Newton step in its column n
    Rw = np.empty(5)
    step = np.empty(5)
    d_try = np.empty(5)
    X_try, status, f_ref, loads, ball_status, res = _newton_start(
        F_applied, idx, n, d, qs, dPd, omega, X, F, J, contact, jacobian, scale, d_try
    )
    for it in range(maxit + 1):
        end = _iteration_end(res, tol, f_ref, contact, n, ball_status)
        if end >= 0:
            return end, status[1], res
        if it == maxit:
            break
        _newton_system(F_applied, F, J, idx, n, scale, k_floor, Kr)
        if not gauss_solve(Kr, n, n + 1):
            return QS_NOT_FINITE, it, res
        for a in range(n):
            Rw[a] = Kr[a, n]
        big = _max_abs(Rw, n)
        if big < 1e-15 * A:
            return (QS_BALL_NOT_CONVERGED if ball_status == 2 else QS_OK), status[1], res
        f = 1.0 if big <= step_cap else step_cap / big
        _full_step(Rw, f, idx, n, scale, step)
        _, res = _loads_line_search(d, step, res, _LOADS_TRIES, loads)  # d_try, X_try, F, J, contact: at the step
        for a in range(5):
            d[a] = d_try[a]
        X[:, :] = X_try
        ball_status = status[0]
    return QS_NOT_CONVERGED, status[1], res


@kernel
def _dogleg(newton, g, Ks, n, radius, p):
    """Dogleg step p[:n] (m, scaled DOFs) of the trust region of the given radius (m) for the model
    m(p) = -g.p + p.Ks.p / 2 of the potential energy (g: scaled unbalanced load, N; Ks: symmetric
    curvature, N/m; newton: the Newton step, m). Returns the model's predicted decrease -m(p) > 0 (N.m).

    The Newton step when it lies inside the region; otherwise the point where the path from the Cauchy
    point (the model's minimum along g) to the Newton step leaves the region, or the boundary along g
    when the Cauchy point already lies outside it (Nocedal & Wright 2006, Numerical Optimization,
    section 4.1). Where that path does not decrease the model (a Newton matrix that is not positive
    definite, at speed), the step is the Cauchy point itself, which always does."""
    gg = 0.0
    nn = 0.0
    for a in range(n):
        gg += g[a] * g[a]
        nn += newton[a] * newton[a]
    gKg = 0.0
    for a in range(n):
        for b in range(n):
            gKg += g[a] * Ks[a, b] * g[b]
    g_norm = math.sqrt(gg)
    # the Cauchy point's distance along g (m): the model's minimum, or the boundary
    t_c = radius if gKg <= 0.0 else min(radius, g_norm * gg / gKg)
    if nn <= radius * radius:
        for a in range(n):
            p[a] = newton[a]
    elif t_c >= radius:
        for a in range(n):
            p[a] = radius * g[a] / g_norm
    else:
        # p = c + s (newton - c) with |p| = radius, c the Cauchy point, 0 < s < 1
        cc = 0.0
        cv = 0.0
        vv = 0.0
        for a in range(n):
            c = t_c * g[a] / g_norm
            v = newton[a] - c
            cc += c * c
            cv += c * v
            vv += v * v
        s = (-cv + math.sqrt(max(cv * cv - vv * (cc - radius * radius), 0.0))) / vv
        for a in range(n):
            c = t_c * g[a] / g_norm
            p[a] = c + s * (newton[a] - c)
    predicted = _model_decrease(g, Ks, n, p)
    if predicted > 0.0:
        return predicted
    for a in range(n):
        p[a] = t_c * g[a] / g_norm
    return _model_decrease(g, Ks, n, p)


@kernel(inline="always")
def _sum_squares(v, n):
    """Sum of the squares of v[:n]."""
    s = 0.0
    for a in range(n):
        s += v[a] * v[a]
    return s


@kernel(inline="always")
def _model_decrease(g, Ks, n, p):
    """Decrease g.p - p.Ks.p / 2 (N.m) of the quadratic model of the potential energy over the step p."""
    lin = 0.0
    quad = 0.0
    for a in range(n):
        lin += g[a] * p[a]
        for b in range(n):
            quad += p[a] * Ks[a, b] * p[b]
    return lin - 0.5 * quad


@kernel
def _free_ring_start(F_applied, idx, n, A1_0, d, contact):
    """Where the Newton on the n load-controlled DOFs idx[:n] starts when the ring is free in its
    clearance (docs/quasistatic.md section 3); contact: the contact state at the warm start d.
    Returns True when d was changed (the caller evaluates again).

    Under zero load every position inside the clearance balances the load, and Newton would stop
    wherever the warm start left it (a result that depends on the load history). With all applied loads
    zero, the DOFs start (and, if no ball is squeezed there, stay) at the centre of the clearance: no
    radial shift, no tilt, z = -A1_0 = -A sin(alpha0) for an angular-contact bearing (midway in its end
    play), z = 0 for a deep-groove one. Under a load with no inner contact loaded at the warm start (the
    ring still at that centre, say), they start instead at d = 0, where the balls touch at the free
    contact angle: the flat plateau of a free ring is not crossed step by step."""
    zero = True
    for a in range(n):
        zero = zero and F_applied[idx[a]] == 0.0
    if not zero:
        for j in range(contact.shape[1]):
            if contact[CS_Q_I, j] > 0.0:
                return False
    changed = False
    for a in range(n):
        i = idx[a]
        target = -A1_0 if (zero and i == 2) else 0.0
        changed = changed or d[i] != target
        d[i] = target
    return changed


@kernel
def _loads_residual_at(d, lam, step, loads):
    """Evaluate the bearing at d + lam step into d_try, X_try (from X), F, J, contact and the status of
    `loads` (_global_newton), counting the evaluation; returns the load residual norm (N): one trial of
    the trust-region iteration."""
    F_applied, idx, n, scale, qs, dPd, omega, X, X_try, d_try, F, J, contact, jacobian, status, f_ref = loads
    for a in range(5):
        d_try[a] = d[a] + lam * step[a]
    X_try[:, :] = X
    status[0] = ring_loads(d_try, qs, dPd, omega, X_try, F, J, contact, jacobian, f_ref)
    status[1] += 1
    return _residual_norm(F_applied, F, idx, n, scale)


_ball_line_search = line_search(_ball_residual_at)
_loads_line_search = line_search(_loads_residual_at)


@kernel
def _residual_norm(F_applied, F, idx, n, scale):
    """Largest load error over the load-controlled DOFs, moments scaled to forces (N)."""
    r = 0.0
    for a in range(n):
        i = idx[a]
        r = max(r, abs(F_applied[i] - F[i]) / scale[i])
    return r


@kernel
def _mean_ball_load(contact):
    """Mean inner contact load (N) of a contact state (CS_*): the load scale of a preloaded bearing
    under zero external load."""
    Z = contact.shape[1]
    s = 0.0
    for j in range(Z):
        s += contact[CS_Q_I, j]
    return s / Z
