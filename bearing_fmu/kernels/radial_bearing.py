"""The `analytic` bearing fidelity: one pure function from (speed, radial load, oil state) to outputs.

Deep-groove bearing (contact angle 0), outer ring fixed, radial load F_r on the +y axis (the input F_y):
1. Sjovall distribution with clearance (loaddist): inner-ring shift delta_r from F_r, ball loads
   Q_i(psi_j) = K (delta_r cos psi_j - P_d/2)_+^1.5 with K the inner and outer Hertz contacts in
   series, psi_j = 2 pi j / Z measured here from the load line: ball 0 (ball 1) on +y, the frame of every
   fidelity (geometry.BALL_1_AZIMUTH, docs/conventions.md), the most loaded configuration;
2. centrifugal load superposed on the outer contacts, Q_o = Q_i + F_c (first-order: the extra
   outer deflection is not fed back into delta_r; the quasi-static fidelity resolves it);
3. Hertz per contact, EHL film (formula code), film parameter, regime, capacitance.
All contacts roll purely at the entrainment speed u = omega d_m (1 - gamma^2)/4; the cage and ball speeds
and the defect frequencies (FTF, BPFO, BPFI, BSF) are those of pure rolling.
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .capacitance import ball_capacitance, lubricated_contact_capacitance
from .ehl import film_parameter, lubrication_regime
from .film_correction import FT_SIZE, corrected_film_thickness
from .geometry import centrifugal_force, pass_frequencies, rolling_kinematics
from .hertz import hertz_contact, hertz_stiffness, series_stiffness
from .loaddist import load_parameter, solve_radial_shift
from .lubricant import LUB_EPS_R0, LUB_RHO_REF, clausius_mossotti_constant, lubricant_state
from .lubrication import ball_drag_power, film_factors, mixture, temperature_viscosity_coefficient

# layout of the bearing parameter array (built by bearing_fmu.models.analytic)
_B_SLOTS = Layout()
B_Z = _B_SLOTS.slot()  # number of balls (-)
B_D = _B_SLOTS.slot()  # ball diameter (m)
B_DM = _B_SLOTS.slot()  # pitch diameter (m)
B_PD = _B_SLOTS.slot()  # diametral clearance (m)
B_RX_I = _B_SLOTS.slot()  # inner contact Rx (m)
B_RY_I = _B_SLOTS.slot()  # inner contact Ry (m)
B_RX_O = _B_SLOTS.slot()  # outer contact Rx (m)
B_RY_O = _B_SLOTS.slot()  # outer contact Ry (m)
B_K_I = _B_SLOTS.slot()  # inner ellipticity a_y/b_x (-)
B_EE_I = _B_SLOTS.slot()  # inner elliptic integral E (-)
B_KK_I = _B_SLOTS.slot()  # inner elliptic integral K (-)
B_K_O = _B_SLOTS.slot()
B_EE_O = _B_SLOTS.slot()
B_KK_O = _B_SLOTS.slot()
B_E_RED = _B_SLOTS.slot()  # reduced modulus E' (Pa)
B_M_BALL = _B_SLOTS.slot()  # ball mass (kg)
B_SIGMA_I = _B_SLOTS.slot()  # composite roughness, inner contact (m)
B_SIGMA_O = _B_SLOTS.slot()  # composite roughness, outer contact (m)
B_FILM = _B_SLOTS.slot()  # film formula code (kernels.ehl)
B_PRESSURE = _B_SLOTS.slot()  # permittivity pressure choice (kernels.capacitance)
B_H_FLOOR = _B_SLOTS.slot()  # film floor for capacitance (m)
B_C_BACKGROUND = _B_SLOTS.slot()  # background capacitance (F)
B_CENTRIFUGAL = _B_SLOTS.slot()  # 1 = centrifugal load on, 0 = off
B_TOL = _B_SLOTS.slot()  # relative tolerance of the radial equilibrium (-)
# 1 = capacitance submodel on; 0 = null submodel (O_C_BEARING and ball rows C_i, C_o not written)
B_CAPACITANCE = _B_SLOTS.slot()
B_OIL_GAP = _B_SLOTS.slot()  # oil-availability gap (m) of the capacitance outside the Hertz zones; 0 = Hertz zones only
# lubrication method (kernels.lubrication, models.lubrication); B_LUBRICATED = 0 (flooded): none of it is read
B_LUBRICATED = _B_SLOTS.slot()  # 1 = film factors on (O_PHI_* written)
B_THERMAL = _B_SLOTS.slot()  # 1 = inlet shear heating factor on
B_H_OIL = _B_SLOTS.slot()  # inlet oil layer (m; inf = no starvation)
B_K_OIL = _B_SLOTS.slot()  # oil thermal conductivity (W/(m K))
B_DRAG = _B_SLOTS.slot()  # 1 = drag of the balls on (O_P_DRAG, O_TORQUE_DRAG written)
B_DRAG_X = _B_SLOTS.slot()  # oil-volume fraction of the fluid the balls move through (-)
B_DRAG_AREA = _B_SLOTS.slot()  # time-mean part of a ball's frontal area in it (-)
# film correction table (kernels.film_correction layout, FT_SIZE slots; its FT_ON 0 = off)
B_FILM_TABLE = _B_SLOTS.slot(FT_SIZE)
B_SIZE = _B_SLOTS.size

# layout of the output array
_O_SLOTS = Layout()
O_LAMBDA_I = _O_SLOTS.slot()
O_LAMBDA_O = _O_SLOTS.slot()
O_HMIN_I = _O_SLOTS.slot()
O_HMIN_O = _O_SLOTS.slot()
O_REGIME = _O_SLOTS.slot()
O_C_BEARING = _O_SLOTS.slot()
O_QMAX_I = _O_SLOTS.slot()
O_QMAX_O = _O_SLOTS.slot()
O_PMAX = _O_SLOTS.slot()
O_OMEGA_CAGE = _O_SLOTS.slot()
O_OMEGA_BALL = _O_SLOTS.slot()
O_N_LOADED = _O_SLOTS.slot()
O_DELTA_R = _O_SLOTS.slot()
O_EPS = _O_SLOTS.slot()
O_HC_I = _O_SLOTS.slot()
O_HC_O = _O_SLOTS.slot()
O_ETA = _O_SLOTS.slot()
O_XI = _O_SLOTS.slot()
O_ITER = _O_SLOTS.slot()
O_OMEGA_BALL_CAGE = _O_SLOTS.slot()  # ball angular speed relative to the cage (rad/s, magnitude)
O_FTF = _O_SLOTS.slot()  # defect frequencies (Hz): fundamental train (cage)
O_BPFO = _O_SLOTS.slot()  # ball pass, outer race
O_BPFI = _O_SLOTS.slot()  # ball pass, inner race
O_BSF = _O_SLOTS.slot()  # ball spin
O_P_DRAG = _O_SLOTS.slot()  # drag power of the balls (W)
O_TORQUE_DRAG = _O_SLOTS.slot()  # its torque O_P_DRAG/|omega| (N.m)
O_PHI_ISH_I = _O_SLOTS.slot()  # film factors of the most loaded inner contact (ball 1, -): inlet shear heating ...
O_PHI_ISH_O = _O_SLOTS.slot()  # ... outer contact
O_PHI_RS_I = _O_SLOTS.slot()  # ... starvation (central film), inner
O_PHI_RS_O = _O_SLOTS.slot()  # ... outer
O_SIZE = _O_SLOTS.size


@kernel
def analytic_bearing(omega, F_r, T_oil, brg, lub, nodes, weights, out, ball):
    """Evaluate the analytic bearing model.

    omega: inner-ring speed (rad/s); F_r: radial load (N, >= 0); T_oil: oil temperature (K);
    brg: bearing array (B_* layout); lub: lubricant array (kernels.lubricant LUB_* layout);
    nodes, weights: Gauss-Legendre rule; out: float64[O_SIZE] (filled); ball: float64[8, Z] work
    array filled per ball with rows Q_i, Q_o (N), h_min_i, h_min_o (m), Lambda_i, Lambda_o (-),
    C_i, C_o (F). With brg[B_CAPACITANCE] = 0 the capacitance submodel is null: no permittivity or
    capacitance is computed and out[O_C_BEARING] and the rows C_i, C_o are left untouched.
    """
    Z = int(brg[B_Z])
    D = brg[B_D]
    dm = brg[B_DM]
    Pd = brg[B_PD]
    E_red = brg[B_E_RED]
    Rx_i = brg[B_RX_I]
    Ry_i = brg[B_RY_I]
    Rx_o = brg[B_RX_O]
    Ry_o = brg[B_RY_O]

    capacitance = brg[B_CAPACITANCE] > 0.5
    lubricated = brg[B_LUBRICATED] > 0.5
    film = int(brg[B_FILM])
    film_table = brg[B_FILM_TABLE:]
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    beta = 0.0
    if lubricated and brg[B_THERMAL] > 0.5:
        beta = temperature_viscosity_coefficient(T_oil, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF]) if capacitance else 0.0
    w_cage, w_ball_rel, w_ball_fixed, u = rolling_kinematics(omega, D, dm, 0.0)
    F_c = 0.0
    if brg[B_CENTRIFUGAL] > 0.5:
        F_c = centrifugal_force(brg[B_M_BALL], dm, w_cage)

    K_i = hertz_stiffness(Rx_i, Ry_i, E_red, brg[B_K_I], brg[B_EE_I], brg[B_KK_I])
    K_o = hertz_stiffness(Rx_o, Ry_o, E_red, brg[B_K_O], brg[B_EE_O], brg[B_KK_O])
    K = series_stiffness(K_i, K_o)
    delta_r, iters = solve_radial_shift(F_r, Pd, K, Z, nodes, weights, brg[B_TOL])

    if lubricated:
        for k in range(O_PHI_ISH_I, O_PHI_RS_O + 1):
            out[k] = 1.0
    loaded_i = False
    loaded_o = False
    # cos(2 pi j / Z) is not exactly 0 at 90 deg: a compression below this is rounding, not contact
    d_zero = 1e-12 * (abs(delta_r) + abs(Pd))
    lam_i = math.inf
    lam_o = math.inf
    hmin_i = math.inf
    hmin_o = math.inf
    hc_i_min = math.inf
    hc_o_min = math.inf
    p_max = 0.0
    q_max_i = 0.0
    q_max_o = 0.0
    n_loaded = 0
    c_total = brg[B_C_BACKGROUND]
    for j in range(Z):
        psi = 2.0 * math.pi * min(j, Z - j) / Z  # mirror balls get bit-identical angles
        d = delta_r * math.cos(psi) - 0.5 * Pd
        Q_i = K * d**1.5 if d > d_zero else 0.0
        Q_o = Q_i + F_c
        a_i, b_i, _, p_i = hertz_contact(Q_i, Rx_i, Ry_i, E_red, brg[B_K_I], brg[B_EE_I], brg[B_KK_I])
        a_o, b_o, _, p_o = hertz_contact(Q_o, Rx_o, Ry_o, E_red, brg[B_K_O], brg[B_EE_O], brg[B_KK_O])
        hc_i, hm_i = corrected_film_thickness(film, eta, xi, E_red, u, Q_i, Rx_i, Ry_i, brg[B_K_I], film_table, 0)
        hc_o, hm_o = corrected_film_thickness(film, eta, xi, E_red, u, Q_o, Rx_o, Ry_o, brg[B_K_O], film_table, 1)
        if lubricated:  # the method's film factors (kernels.lubrication); ball 0 is the most loaded
            k_f, thermal, h_oil = brg[B_K_OIL], brg[B_THERMAL], brg[B_H_OIL]
            if Q_i > 0.0:
                t_i, c_i, m_i = film_factors(hc_i, hm_i, abs(u), p_i, b_i, Rx_i, E_red, eta, beta, k_f, thermal, h_oil)
                hc_i *= t_i * c_i
                hm_i *= t_i * m_i
                if j == 0:
                    out[O_PHI_ISH_I], out[O_PHI_RS_I] = t_i, c_i
            if Q_o > 0.0:
                t_o, c_o, m_o = film_factors(hc_o, hm_o, abs(u), p_o, b_o, Rx_o, E_red, eta, beta, k_f, thermal, h_oil)
                hc_o *= t_o * c_o
                hm_o *= t_o * m_o
                if j == 0:
                    out[O_PHI_ISH_O], out[O_PHI_RS_O] = t_o, c_o
        L_i = film_parameter(hm_i, brg[B_SIGMA_I])
        L_o = film_parameter(hm_o, brg[B_SIGMA_O])
        C_i = 0.0
        C_o = 0.0
        if Q_i > 0.0:
            loaded_i = True
            if capacitance:
                C_i = lubricated_contact_capacitance(
                    K_cm, rho0, p_i, int(brg[B_PRESSURE]), a_i, b_i, hc_i, brg[B_H_FLOOR], E_red, brg[B_OIL_GAP]
                )
            lam_i = min(lam_i, L_i)
            hmin_i = min(hmin_i, hm_i)
            hc_i_min = min(hc_i_min, hc_i)
        if Q_o > 0.0:
            loaded_o = True
            if capacitance:
                C_o = lubricated_contact_capacitance(
                    K_cm, rho0, p_o, int(brg[B_PRESSURE]), a_o, b_o, hc_o, brg[B_H_FLOOR], E_red, brg[B_OIL_GAP]
                )
            lam_o = min(lam_o, L_o)
            hmin_o = min(hmin_o, hm_o)
            hc_o_min = min(hc_o_min, hc_o)
        if Q_i > 0.0 and Q_o > 0.0:
            n_loaded += 1
        if capacitance:
            c_total += ball_capacitance(C_i, C_o)
            ball[6, j] = C_i
            ball[7, j] = C_o
        p_max = max(p_max, p_i, p_o)
        q_max_i = max(q_max_i, Q_i)
        q_max_o = max(q_max_o, Q_o)
        ball[0, j] = Q_i
        ball[1, j] = Q_o
        ball[2, j] = hm_i
        ball[3, j] = hm_o
        ball[4, j] = L_i
        ball[5, j] = L_o

    # a race without any loaded contact reports 0 film (documented: no EHL contact to speak of)
    if not loaded_i:
        lam_i = 0.0
        hmin_i = 0.0
        hc_i_min = 0.0
    if not loaded_o:
        lam_o = 0.0
        hmin_o = 0.0
        hc_o_min = 0.0
    out[O_LAMBDA_I] = lam_i
    out[O_LAMBDA_O] = lam_o
    out[O_HMIN_I] = hmin_i
    out[O_HMIN_O] = hmin_o
    out[O_REGIME] = lubrication_regime(min(lam_i, lam_o))
    if capacitance:
        out[O_C_BEARING] = c_total
    out[O_QMAX_I] = q_max_i
    out[O_QMAX_O] = q_max_o
    out[O_PMAX] = p_max
    out[O_OMEGA_CAGE] = w_cage
    out[O_OMEGA_BALL] = w_ball_fixed
    out[O_N_LOADED] = n_loaded
    out[O_DELTA_R] = delta_r
    out[O_EPS] = load_parameter(delta_r, Pd)
    out[O_HC_I] = hc_i_min
    out[O_HC_O] = hc_o_min
    out[O_ETA] = eta
    out[O_XI] = xi
    out[O_ITER] = iters
    out[O_OMEGA_BALL_CAGE] = abs(w_ball_rel)
    out[O_FTF], out[O_BPFO], out[O_BPFI], out[O_BSF] = pass_frequencies(omega, w_cage, w_ball_rel, Z)
    if brg[B_DRAG] > 0.5:  # every ball orbits at the cage speed
        rho_e, eta_e = mixture(brg[B_DRAG_X], rho0, eta)
        P_drag = Z * ball_drag_power(0.5 * dm * w_cage, D, rho_e, eta_e, brg[B_DRAG_AREA])
        out[O_P_DRAG] = P_drag
        out[O_TORQUE_DRAG] = P_drag / abs(omega) if omega != 0.0 else 0.0
