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

from .capacitance import ball_capacitance, lubricated_contact_capacitance
from .ehl import film_parameter, friction_coefficient, lubrication_regime
from .film_correction import FT_SIZE, corrected_film_thickness
from .hertz import hertz_contact
from .jones_harris import BQ_P_SLIP_I, BQ_Q_I, BQ_Q_O, BQ_SPIN_I, BQ_SPIN_O, BQ_U_I, BQ_U_O, BQ_W_M
from .lubricant import LUB_EPS_R0, LUB_RHO_REF, clausius_mossotti_constant, lubricant_state
from .lubrication import ball_drag_power, film_factors, mixture, rolling_force_factor, temperature_viscosity_coefficient
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
CP_PRESSURE = _CP_SLOTS.slot()
CP_H_FLOOR = _CP_SLOTS.slot()  # capacitance film floor (m)
CP_C_BACKGROUND = _CP_SLOTS.slot()
CP_ALPHA_H = _CP_SLOTS.slot()  # hysteresis loss factor (-)
CP_F_I = _CP_SLOTS.slot()  # inner conformity (-)
CP_F_O = _CP_SLOTS.slot()
CP_D = _CP_SLOTS.slot()  # ball diameter (m)
CP_CAPACITANCE = _CP_SLOTS.slot()  # 1 = capacitance submodel on; 0 = null submodel (its slots are not written)
CP_TORQUE = _CP_SLOTS.slot()  # 1 = loss (torque and heat) submodel on; 0 = null submodel (its slots are not written)
# oil-availability gap (m) of the capacitance outside the Hertz zones; 0 = Hertz zones only
CP_OIL_GAP = _CP_SLOTS.slot()
# lubrication method (kernels.lubrication, models.lubrication); CP_LUBRICATED = 0 (flooded): none of it is read
CP_LUBRICATED = _CP_SLOTS.slot()  # 1 = film factors on (CO_PHI_* written); 0 = flooded, isothermal
CP_THERMAL = _CP_SLOTS.slot()  # 1 = inlet shear heating factor on
CP_H_OIL = _CP_SLOTS.slot()  # inlet oil layer (m; inf = no starvation)
CP_K_OIL = _CP_SLOTS.slot()  # oil thermal conductivity (W/(m K))
CP_DRAG = _CP_SLOTS.slot()  # 1 = drag of the balls on (with CP_TORQUE; CO_P_DRAG, CO_TORQUE_DRAG written)
CP_DRAG_X = _CP_SLOTS.slot()  # oil-volume fraction of the fluid the balls move through (-)
CP_DRAG_AREA = _CP_SLOTS.slot()  # time-mean part of a ball's frontal area in it (-)
CP_DM = _CP_SLOTS.slot()  # pitch diameter (m)
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
# sums started at 0 whatever the options, and those of the loss submodel (with its TL_SIZE components at CO_P_EHL)
_SUMS = (CO_QMAX_I, CO_QMAX_O, CO_PMAX, CO_N_LOADED, CO_HC_I, CO_HC_O)
_LOSS_SUMS = (CO_Q_INNER_RING, CO_Q_OUTER_RING)

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
    The capacitance and loss submodels run only when cp[CP_CAPACITANCE] / cp[CP_TORQUE] is set; a
    submodel that is off does none of its work and leaves its slots of out and per_contact untouched
    (capacitance: CO_C_BEARING, PC_C_*; losses: CO_P_LOSS, CO_Q_*_RING, CO_TORQUE, CO_P_EHL.., PC_P_*).
    """
    Z = balls.shape[1]
    capacitance = cp[CP_CAPACITANCE] > 0.5
    torque = cp[CP_TORQUE] > 0.5
    lubricated = cp[CP_LUBRICATED] > 0.5
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    beta = 0.0
    if lubricated and cp[CP_THERMAL] > 0.5:
        beta = temperature_viscosity_coefficient(T_oil, lub)
    phi_t = 1.0
    phi_c = 1.0
    phi_m = 1.0
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF]) if capacitance else 0.0
    E_red = cp[CP_E_RED]
    film = int(cp[CP_FILM])
    film_table = cp[CP_FILM_TABLE:]
    lam_i = math.inf
    lam_o = math.inf
    hmin_i = math.inf
    hmin_o = math.inf
    loaded_i = False
    loaded_o = False
    for k in _SUMS:
        out[k] = 0.0
    if torque:
        for k in _LOSS_SUMS:
            out[k] = 0.0
        for t in range(TL_SIZE):
            out[CO_P_EHL + t] = 0.0
    if capacitance:
        out[CO_C_BEARING] = cp[CP_C_BACKGROUND]
    if lubricated:
        for k in range(CO_PHI_ISH_I, CO_PHI_RS_O + 1):
            out[k] = 1.0
    for j in range(Z):
        for race in range(2):
            o = 5 * race  # inner at CP_RX_I.., outer at CP_RX_O..
            Q = balls[BQ_Q_I + race, j]
            u = balls[BQ_U_I, j] if race == 0 else balls[BQ_U_O, j]
            Rx = cp[CP_RX_I + o]
            Ry = cp[CP_RY_I + o]
            k = cp[CP_K_I + o]
            a, b, _, p = hertz_contact(Q, Rx, Ry, E_red, k, cp[CP_EE_I + o], cp[CP_KK_I + o])
            # the fully flooded isothermal film (the formula, times the numerical solver's ratio where the film
            # table is on), then the lubrication method's inlet heating and starvation factors
            hc, hm = corrected_film_thickness(film, eta, xi, E_red, u, Q, Rx, Ry, k, film_table, race)
            if lubricated and Q > 0.0:
                phi_t, phi_c, phi_m = film_factors(
                    hc, hm, abs(u), p, b, Rx, E_red, eta, beta, cp[CP_K_OIL], cp[CP_THERMAL], cp[CP_H_OIL]
                )
                hc *= phi_t * phi_c
                hm *= phi_t * phi_m
            lam = film_parameter(hm, cp[CP_SIGMA_I + race])
            C = 0.0
            P = 0.0
            if Q > 0.0:
                if capacitance:
                    C = lubricated_contact_capacitance(
                        K_cm, rho0, p, int(cp[CP_PRESSURE]), a, b, hc, cp[CP_H_FLOOR], E_red, cp[CP_OIL_GAP]
                    )
                if torque:
                    spin = balls[BQ_SPIN_I, j] if race == 0 else balls[BQ_SPIN_O, j]
                    mu = friction_coefficient(lam)
                    f = cp[CP_F_I + race]
                    P = contact_losses(
                        Q,
                        u,
                        spin,
                        Rx,
                        Ry,
                        a,
                        b,
                        cp[CP_EE_I + o],
                        f,
                        cp[CP_D],
                        E_red,
                        eta,
                        xi,
                        mu,
                        cp[CP_ALPHA_H],
                        losses,
                    )
                    if lubricated:  # the EHL rolling force follows the central film (kernels.lubrication)
                        f_R = rolling_force_factor(phi_t, phi_c)
                        P -= (1.0 - f_R) * losses[TL_EHL]
                        losses[TL_EHL] *= f_R
                    for t in range(TL_SIZE):
                        out[CO_P_EHL + t] += losses[t]
                    # the film's traction against the balls' sliding (race control "traction"; 0 under a
                    # hypothesis, whose kinematics roll without slip): in the contact's loss, not in a component
                    P += balls[BQ_P_SLIP_I + race, j]
                    out[CO_Q_INNER_RING + race] += P
                out[CO_PMAX] = max(out[CO_PMAX], p)
                if Q > out[CO_QMAX_I + race]:  # the central film of the most loaded contact (first of equals)
                    out[CO_QMAX_I + race] = Q
                    out[CO_HC_I + race] = hc
                    if lubricated:
                        out[CO_PHI_ISH_I + race] = phi_t
                        out[CO_PHI_RS_I + race] = phi_c
                if race == 0:
                    loaded_i = True
                    lam_i = min(lam_i, lam)
                    hmin_i = min(hmin_i, hm)
                else:
                    loaded_o = True
                    lam_o = min(lam_o, lam)
                    hmin_o = min(hmin_o, hm)
            per_contact[PC_HMIN_I + race, j] = hm
            per_contact[PC_LAMBDA_I + race, j] = lam
            if torque:
                per_contact[PC_P_I + race, j] = P
            if capacitance:
                per_contact[PC_C_I + race, j] = C
        if balls[BQ_Q_I, j] > 0.0 and balls[BQ_Q_O, j] > 0.0:
            out[CO_N_LOADED] += 1.0
        if capacitance:
            out[CO_C_BEARING] += ball_capacitance(per_contact[PC_C_I, j], per_contact[PC_C_O, j])
    # a race without any loaded contact reports 0 film (as the analytic fidelity, docs/decisions.md)
    out[CO_LAMBDA_I] = lam_i if loaded_i else 0.0
    out[CO_LAMBDA_O] = lam_o if loaded_o else 0.0
    out[CO_HMIN_I] = hmin_i if loaded_i else 0.0
    out[CO_HMIN_O] = hmin_o if loaded_o else 0.0
    out[CO_REGIME] = lubrication_regime(min(out[CO_LAMBDA_I], out[CO_LAMBDA_O]))
    if torque and cp[CP_DRAG] > 0.5:  # the drag heats the oil, which passes it to both rings: half each
        rho_e, eta_e = mixture(cp[CP_DRAG_X], rho0, eta)
        P_drag = 0.0
        for j in range(Z):
            v = 0.5 * cp[CP_DM] * balls[BQ_W_M, j]
            P_drag += ball_drag_power(v, cp[CP_D], rho_e, eta_e, cp[CP_DRAG_AREA])
        out[CO_P_DRAG] = P_drag
        out[CO_TORQUE_DRAG] = P_drag / abs(omega) if omega != 0.0 else 0.0
        out[CO_Q_INNER_RING] += 0.5 * P_drag
        out[CO_Q_OUTER_RING] += 0.5 * P_drag
    if torque:
        out[CO_P_LOSS] = out[CO_Q_INNER_RING] + out[CO_Q_OUTER_RING]
        out[CO_TORQUE] = out[CO_P_LOSS] / abs(omega) if omega != 0.0 else 0.0
    out[CO_ETA] = eta
    out[CO_XI] = xi
