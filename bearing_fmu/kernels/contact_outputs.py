"""Contact outputs of a quasi-static solution: Hertz, EHL film, regime, capacitance, losses.

Takes the per-ball loads and kinematics of kernels.jones_harris and evaluates every ball-race
contact. The contact geometry (R_x, R_y, ellipticity, elliptic integrals) is that of the free
contact angle, as in the solver's Hertz constants (docs/quasistatic.md); rolling and spin speeds
are those of the operating angles and the race-control hypothesis.

Losses per contact (kernels.torque, Houpert 1999 components): EHL rolling resistance, elastic
hysteresis, Heathcote (curvature) sliding with mu(Lambda), and pivoting with the contact's spin
speed. Heat goes to the ring of the contact (the ball is adiabatic at steady state: it passes its
heat to the rings). Torque = total power / |omega|; at rest it is 0 (no rolling, no power).
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .capacitance import CAP_BACKGROUND, CAP_ON, CAP_SIZE, ball_capacitance
from .ehl import friction_coefficient, lubrication_regime
from .ehl_contact import METHOD_CAPACITANCE, METHOD_LUBRICATED, contact_method, lubricated_contact, oil_state
from .film_correction import FT_SIZE
from .jones_harris import BQ_P_SLIP_I, BQ_Q_I, BQ_Q_O, BQ_SPIN_I, BQ_SPIN_O, BQ_U_I, BQ_U_O, BQ_W_M
from .lubrication import (
    LM_DRAG,
    LM_DRAG_AREA,
    LM_DRAG_X,
    LM_ON,
    LM_SIZE,
    LM_THERMAL,
    ball_drag_power,
    mixture,
    rolling_force_factor,
)
from .torque import TL_EHL, TL_SIZE, contact_losses

# layout of the contact parameter array (built by the model)
_CP_SLOTS = Layout()
CP_RX_I = _CP_SLOTS.slot()
CP_RY_I = _CP_SLOTS.slot()
CP_K_I = _CP_SLOTS.slot()  # ellipticity a_y/b_x (-)
CP_EE_I = _CP_SLOTS.slot()  # elliptic integral E (-)
CP_KK_I = _CP_SLOTS.slot()  # elliptic integral K (-)
CP_RX_O = _CP_SLOTS.slot()
CP_RY_O = _CP_SLOTS.slot()
CP_K_O = _CP_SLOTS.slot()
CP_EE_O = _CP_SLOTS.slot()
CP_KK_O = _CP_SLOTS.slot()
CP_E_RED = _CP_SLOTS.slot()  # reduced modulus (Pa)
CP_SIGMA_I = _CP_SLOTS.slot()  # composite roughness (m)
CP_SIGMA_O = _CP_SLOTS.slot()
CP_FILM = _CP_SLOTS.slot()  # film formula code
CP_ALPHA_H = _CP_SLOTS.slot()  # hysteresis loss factor (-)
CP_F_I = _CP_SLOTS.slot()  # inner conformity (-)
CP_F_O = _CP_SLOTS.slot()
CP_D = _CP_SLOTS.slot()  # ball diameter (m)
CP_TORQUE = _CP_SLOTS.slot()  # 1 = loss (torque and heat) submodel on; 0 = null submodel (its slots are not written)
CP_DM = _CP_SLOTS.slot()  # pitch diameter (m)
# capacitance submodel (kernels.capacitance layout, CAP_SIZE slots; CAP_ON 0 = off: CO_C_BEARING, PC_C_* not written)
CP_CAPACITANCE_BLOCK = _CP_SLOTS.slot(CAP_SIZE)
# lubrication method (kernels.lubrication layout, LM_SIZE slots; LM_ON 0 = flooded: CO_PHI_*, CO_*_DRAG not written)
CP_LUBRICATION_BLOCK = _CP_SLOTS.slot(LM_SIZE)
# film correction table (kernels.film_correction layout, FT_SIZE slots; its FT_ON 0 = off)
CP_FILM_TABLE = _CP_SLOTS.slot(FT_SIZE)
CP_SIZE = _CP_SLOTS.size

# layout of the output array
_CO_SLOTS = Layout()
CO_LAMBDA_I = _CO_SLOTS.slot()
CO_LAMBDA_O = _CO_SLOTS.slot()
CO_HMIN_I = _CO_SLOTS.slot()
CO_HMIN_O = _CO_SLOTS.slot()
CO_REGIME = _CO_SLOTS.slot()
CO_C_BEARING = _CO_SLOTS.slot()
CO_QMAX_I = _CO_SLOTS.slot()
CO_QMAX_O = _CO_SLOTS.slot()
CO_PMAX = _CO_SLOTS.slot()
CO_N_LOADED = _CO_SLOTS.slot()
CO_P_LOSS = _CO_SLOTS.slot()
CO_Q_INNER_RING = _CO_SLOTS.slot()
CO_Q_OUTER_RING = _CO_SLOTS.slot()
CO_TORQUE = _CO_SLOTS.slot()
CO_P_EHL = _CO_SLOTS.slot(4)  # 4 components follow in kernels.torque TL_* order
CO_ETA = _CO_SLOTS.slot()
CO_XI = _CO_SLOTS.slot()
CO_HC_I = _CO_SLOTS.slot()  # central film thickness of the most loaded inner contact (m; 0 if none)
CO_HC_O = _CO_SLOTS.slot()  # ... outer contact
CO_P_DRAG = _CO_SLOTS.slot()  # drag power of the balls (W), part of CO_P_LOSS, half to each ring
CO_TORQUE_DRAG = _CO_SLOTS.slot()  # its torque CO_P_DRAG/|omega| (N.m)
CO_PHI_ISH_I = _CO_SLOTS.slot()  # film factors of the most loaded inner contact (-): inlet shear heating ...
CO_PHI_ISH_O = _CO_SLOTS.slot()  # ... outer contact
CO_PHI_RS_I = _CO_SLOTS.slot()  # ... starvation (central film), inner
CO_PHI_RS_O = _CO_SLOTS.slot()  # ... outer
CO_SIZE = _CO_SLOTS.size

# the slots of kernels.ehl_contact.contact_method's constants in the contact parameter array
_METHOD_SLOTS = (CP_E_RED, CP_FILM, CP_LUBRICATION_BLOCK, CP_CAPACITANCE_BLOCK)
# sums started at 0 whatever the options, and those of the loss submodel (with its TL_SIZE components at CO_P_EHL)
_SUMS = (CO_QMAX_I, CO_QMAX_O, CO_PMAX, CO_N_LOADED, CO_HC_I, CO_HC_O)
_LOSS_SUMS = (CO_Q_INNER_RING, CO_Q_OUTER_RING)
# the races' minima over their loaded contacts, started at inf (0 at the end on a race without any)
_MINIMA = (CO_LAMBDA_I, CO_LAMBDA_O, CO_HMIN_I, CO_HMIN_O)

# rows of the per-contact array
_PC_SLOTS = Layout()
PC_HMIN_I = _PC_SLOTS.slot()
PC_HMIN_O = _PC_SLOTS.slot()
PC_LAMBDA_I = _PC_SLOTS.slot()
PC_LAMBDA_O = _PC_SLOTS.slot()
PC_P_I = _PC_SLOTS.slot()  # loss of the inner contact (W)
PC_P_O = _PC_SLOTS.slot()
PC_C_I = _PC_SLOTS.slot()  # capacitance (F)
PC_C_O = _PC_SLOTS.slot()
PC_SIZE = _PC_SLOTS.size


@kernel
def contact_outputs(omega, T_oil, cp, lub, balls, out, per_contact, losses):
    """Evaluate all contacts of a solved bearing.

    omega: inner-ring speed (rad/s); T_oil: oil temperature (K); cp: CP_* array; lub: lubricant
    array; balls: per-ball rows of kernels.jones_harris (BQ_*); out: CO_* outputs (filled);
    per_contact: float64[PC_SIZE, Z] (filled); losses: float64[TL_SIZE] work array.
    The capacitance and loss submodels run only when the capacitance block's CAP_ON / cp[CP_TORQUE] is set; a
    submodel that is off does none of its work and leaves its slots of out and per_contact untouched
    (capacitance: CO_C_BEARING, PC_C_*; losses: CO_P_LOSS, CO_Q_*_RING, CO_TORQUE, CO_P_EHL.., PC_P_*).
    """
    Z = balls.shape[1]
    torque = cp[CP_TORQUE] > 0.5
    method = contact_method(cp, _METHOD_SLOTS)
    film_table = cp[CP_FILM_TABLE:]
    capacitance = method[METHOD_CAPACITANCE]
    lm = CP_LUBRICATION_BLOCK
    oil = oil_state(T_oil, lub, method[METHOD_LUBRICATED], cp[lm + LM_THERMAL] > 0.5, capacitance)
    eta, xi, rho0 = oil[0], oil[1], oil[2]
    _start_sums(cp, out)
    for j in range(Z):
        for race in range(2):
            _contact(j, race, balls, cp, oil, method, film_table, out, per_contact, losses)
        if balls[BQ_Q_I, j] > 0.0 and balls[BQ_Q_O, j] > 0.0:
            out[CO_N_LOADED] += 1.0
        if capacitance:
            out[CO_C_BEARING] += ball_capacitance(per_contact[PC_C_I, j], per_contact[PC_C_O, j])
    # a race without any loaded contact reports 0 film (as the analytic fidelity, docs/decisions.md)
    for race in range(2):
        if not out[CO_QMAX_I + race] > 0.0:
            out[CO_LAMBDA_I + race] = 0.0
            out[CO_HMIN_I + race] = 0.0
    out[CO_REGIME] = lubrication_regime(min(out[CO_LAMBDA_I], out[CO_LAMBDA_O]))
    if torque and cp[lm + LM_DRAG] > 0.5:  # the drag heats the oil, which passes it to both rings: half each
        rho_e, eta_e = mixture(cp[lm + LM_DRAG_X], rho0, eta)
        P_drag = 0.0
        for j in range(Z):
            v = 0.5 * cp[CP_DM] * balls[BQ_W_M, j]
            P_drag += ball_drag_power(v, cp[CP_D], rho_e, eta_e, cp[lm + LM_DRAG_AREA])
        out[CO_P_DRAG] = P_drag
        out[CO_TORQUE_DRAG] = P_drag / abs(omega) if omega != 0.0 else 0.0
        out[CO_Q_INNER_RING] += 0.5 * P_drag
        out[CO_Q_OUTER_RING] += 0.5 * P_drag
    if torque:
        out[CO_P_LOSS] = out[CO_Q_INNER_RING] + out[CO_Q_OUTER_RING]
        out[CO_TORQUE] = out[CO_P_LOSS] / abs(omega) if omega != 0.0 else 0.0
    out[CO_ETA] = eta
    out[CO_XI] = xi


@kernel(inline="always")  # see _contact
def _start_sums(cp, out):
    """The starting values of the sums and extremes that the contacts add to (those of a submodel that is off are
    left untouched): 0, the minima of the races at inf, the film factors at 1 and the capacitance at the
    background's."""
    for k in _SUMS:
        out[k] = 0.0
    for k in _MINIMA:
        out[k] = math.inf
    if cp[CP_TORQUE] > 0.5:
        for k in _LOSS_SUMS:
            out[k] = 0.0
        for t in range(TL_SIZE):
            out[CO_P_EHL + t] = 0.0
    if cp[CP_CAPACITANCE_BLOCK + CAP_ON] > 0.5:
        out[CO_C_BEARING] = cp[CP_CAPACITANCE_BLOCK + CAP_BACKGROUND]
    if cp[CP_LUBRICATION_BLOCK + LM_ON] > 0.5:
        for k in range(CO_PHI_ISH_I, CO_PHI_RS_O + 1):
            out[k] = 1.0


@kernel(inline="always")  # as kernels.ehl_contact's, for the time of a call per contact
def _contact(j, race, balls, cp, oil, method, film_table, out, per_contact, losses):
    """Ball j's contact with race 0 (inner) or 1 (outer): its film, Lambda, loss and capacitance into per_contact,
    its share of the race's sums and extremes into out (the races' slots are neighbours: CO_<name>_I + race)."""
    o = 5 * race  # inner at CP_RX_I.., outer at CP_RX_O..
    Q = balls[BQ_Q_I + race, j]
    u = balls[BQ_U_I, j] if race == 0 else balls[BQ_U_O, j]
    shape = (cp[CP_RX_I + o], cp[CP_RY_I + o], cp[CP_K_I + o], cp[CP_EE_I + o], cp[CP_KK_I + o], cp[CP_SIGMA_I + race])
    a, b, p, hc, hm, lam, C, phi_t, phi_c = lubricated_contact(Q, u, race, shape, oil, method, film_table)
    P = 0.0
    if Q > 0.0:
        if cp[CP_TORQUE] > 0.5:
            P = _contact_loss(j, race, balls, cp, oil, method, shape, a, b, lam, phi_t, phi_c, out, losses)
        out[CO_PMAX] = max(out[CO_PMAX], p)
        if Q > out[CO_QMAX_I + race]:  # the central film of the most loaded contact (first of equals)
            out[CO_QMAX_I + race] = Q
            out[CO_HC_I + race] = hc
            if method[METHOD_LUBRICATED]:
                out[CO_PHI_ISH_I + race] = phi_t
                out[CO_PHI_RS_I + race] = phi_c
        out[CO_LAMBDA_I + race] = min(out[CO_LAMBDA_I + race], lam)
        out[CO_HMIN_I + race] = min(out[CO_HMIN_I + race], hm)
    per_contact[PC_HMIN_I + race, j] = hm
    per_contact[PC_LAMBDA_I + race, j] = lam
    if cp[CP_TORQUE] > 0.5:
        per_contact[PC_P_I + race, j] = P
    if method[METHOD_CAPACITANCE]:
        per_contact[PC_C_I + race, j] = C


@kernel(inline="always")  # see _contact
def _contact_loss(j, race, balls, cp, oil, method, shape, a, b, lam, phi_t, phi_c, out, losses):
    """The loss (W) of ball j's loaded contact with the race (Houpert's components, kernels.torque, into losses and
    summed into out[CO_P_EHL..]; with the sliding's) and the heat it gives its ring (out[CO_Q_*_RING])."""
    u = balls[BQ_U_I, j] if race == 0 else balls[BQ_U_O, j]
    spin = balls[BQ_SPIN_I, j] if race == 0 else balls[BQ_SPIN_O, j]
    Q = balls[BQ_Q_I + race, j]
    Rx, Ry, _, ell_E, _, _ = shape
    eta, xi = oil[0], oil[1]
    mu = friction_coefficient(lam)
    f = cp[CP_F_I + race]
    P = contact_losses(Q, u, spin, Rx, Ry, a, b, ell_E, f, cp[CP_D], cp[CP_E_RED], eta, xi, mu, cp[CP_ALPHA_H], losses)
    if method[METHOD_LUBRICATED]:  # the EHL rolling force follows the central film (kernels.lubrication)
        f_R = rolling_force_factor(phi_t, phi_c)
        P -= (1.0 - f_R) * losses[TL_EHL]
        losses[TL_EHL] *= f_R
    for t in range(TL_SIZE):
        out[CO_P_EHL + t] += losses[t]
    # the film's traction against the balls' sliding (race control "traction"; 0 under a hypothesis, whose
    # kinematics roll without slip): in the contact's loss, not in a component
    P += balls[BQ_P_SLIP_I + race, j]
    out[CO_Q_INNER_RING + race] += P
    return P
