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

from .capacitance import CAP_BACKGROUND, CAP_SIZE, ball_capacitance
from .ehl import lubrication_regime
from .ehl_contact import METHOD_CAPACITANCE, METHOD_LUBRICATED, contact_method, lubricated_contact, oil_state
from .film_correction import FT_SIZE
from .geometry import centrifugal_force, pass_frequencies, rolling_kinematics
from .hertz import hertz_stiffness, series_stiffness
from .loaddist import load_parameter, solve_radial_shift
from .lubrication import LM_DRAG, LM_DRAG_AREA, LM_DRAG_X, LM_SIZE, LM_THERMAL, ball_drag_power, mixture

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
B_CENTRIFUGAL = _B_SLOTS.slot()  # 1 = centrifugal load on, 0 = off
B_TOL = _B_SLOTS.slot()  # relative tolerance of the radial equilibrium (-)
# capacitance submodel (kernels.capacitance layout, CAP_SIZE slots; its CAP_ON 0 = off: O_C_BEARING and the ball
# rows C_i, C_o not written)
B_CAPACITANCE_BLOCK = _B_SLOTS.slot(CAP_SIZE)
# lubrication method (kernels.lubrication layout, LM_SIZE slots; its LM_ON 0 = flooded: O_PHI_*, O_*_DRAG not written)
B_LUBRICATION_BLOCK = _B_SLOTS.slot(LM_SIZE)
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

# the slots of kernels.ehl_contact.contact_method's constants in the bearing array
_METHOD_SLOTS = (B_E_RED, B_FILM, B_LUBRICATION_BLOCK, B_CAPACITANCE_BLOCK)

# the races' summaries of _ball_contacts: minima over the loaded contacts, maxima and counts
_MINIMA = (O_LAMBDA_I, O_LAMBDA_O, O_HMIN_I, O_HMIN_O, O_HC_I, O_HC_O)
_MAXIMA = (O_QMAX_I, O_QMAX_O, O_PMAX, O_N_LOADED)


@kernel
def analytic_bearing(omega, F_r, T_oil, brg, lub, nodes, weights, out, ball):
    """Evaluate the analytic bearing model.

    omega: inner-ring speed (rad/s); F_r: radial load (N, >= 0); T_oil: oil temperature (K);
    brg: bearing array (B_* layout); lub: lubricant array (kernels.lubricant LUB_* layout);
    nodes, weights: Gauss-Legendre rule; out: float64[O_SIZE] (filled); ball: float64[8, Z] work
    array filled per ball with rows Q_i, Q_o (N), h_min_i, h_min_o (m), Lambda_i, Lambda_o (-),
    C_i, C_o (F). With the capacitance block off (CAP_ON = 0) the submodel is null: no permittivity or
    capacitance is computed and out[O_C_BEARING] and the rows C_i, C_o are left untouched.
    """
    Z = int(brg[B_Z])
    D = brg[B_D]
    dm = brg[B_DM]
    Pd = brg[B_PD]
    E_red = brg[B_E_RED]
    method = contact_method(brg, _METHOD_SLOTS)
    lm = B_LUBRICATION_BLOCK
    oil = oil_state(T_oil, lub, method[METHOD_LUBRICATED], brg[lm + LM_THERMAL] > 0.5, method[METHOD_CAPACITANCE])
    w_cage, w_ball_rel, w_ball_fixed, u = rolling_kinematics(omega, D, dm, 0.0)
    F_c = 0.0
    if brg[B_CENTRIFUGAL] > 0.5:
        F_c = centrifugal_force(brg[B_M_BALL], dm, w_cage)

    K_i = hertz_stiffness(brg[B_RX_I], brg[B_RY_I], E_red, brg[B_K_I], brg[B_EE_I], brg[B_KK_I])
    K_o = hertz_stiffness(brg[B_RX_O], brg[B_RY_O], E_red, brg[B_K_O], brg[B_EE_O], brg[B_KK_O])
    K = series_stiffness(K_i, K_o)
    delta_r, iters = solve_radial_shift(F_r, Pd, K, Z, nodes, weights, brg[B_TOL])
    _ball_contacts(delta_r, K, F_c, u, brg, oil, method, brg[B_FILM_TABLE:], out, ball)

    eta, xi, rho0 = oil[0], oil[1], oil[2]
    out[O_OMEGA_CAGE] = w_cage
    out[O_OMEGA_BALL] = w_ball_fixed
    out[O_DELTA_R] = delta_r
    out[O_EPS] = load_parameter(delta_r, Pd)
    out[O_ETA] = eta
    out[O_XI] = xi
    out[O_ITER] = iters
    out[O_OMEGA_BALL_CAGE] = abs(w_ball_rel)
    out[O_FTF], out[O_BPFO], out[O_BPFI], out[O_BSF] = pass_frequencies(omega, w_cage, w_ball_rel, Z)
    if brg[lm + LM_DRAG] > 0.5:  # every ball orbits at the cage speed
        rho_e, eta_e = mixture(brg[lm + LM_DRAG_X], rho0, eta)
        P_drag = Z * ball_drag_power(0.5 * dm * w_cage, D, rho_e, eta_e, brg[lm + LM_DRAG_AREA])
        out[O_P_DRAG] = P_drag
        out[O_TORQUE_DRAG] = P_drag / abs(omega) if omega != 0.0 else 0.0


@kernel
def _ball_contacts(delta_r, K, F_c, u, brg, oil, method, film_table, out, ball):
    """Every ball's two contacts with the inner ring shifted by delta_r (m) (Hertz constant K of both contacts in
    series, N/m^1.5; centrifugal force F_c, N; entrainment speed u, m/s): the ball rows (analytic_bearing) and the
    races' summaries in out: O_LAMBDA_*, O_HMIN_*, O_HC_* (minimum over the loaded contacts, 0 on a race without
    any), O_QMAX_*, O_PMAX, O_N_LOADED, O_REGIME, the film factors O_PHI_* of ball 0 (the most loaded) with the
    lubrication method and O_C_BEARING with the capacitance submodel."""
    Z = int(brg[B_Z])
    Pd = brg[B_PD]
    capacitance = method[METHOD_CAPACITANCE]
    shape_i = (brg[B_RX_I], brg[B_RY_I], brg[B_K_I], brg[B_EE_I], brg[B_KK_I], brg[B_SIGMA_I])
    shape_o = (brg[B_RX_O], brg[B_RY_O], brg[B_K_O], brg[B_EE_O], brg[B_KK_O], brg[B_SIGMA_O])
    for k in _MINIMA:
        out[k] = math.inf
    for k in _MAXIMA:
        out[k] = 0.0
    if method[METHOD_LUBRICATED]:
        for k in range(O_PHI_ISH_I, O_PHI_RS_O + 1):
            out[k] = 1.0
    if capacitance:
        out[O_C_BEARING] = brg[B_CAPACITANCE_BLOCK + CAP_BACKGROUND]
    # cos(2 pi j / Z) is not exactly 0 at 90 deg: a compression below this is rounding, not contact
    d_zero = 1e-12 * (abs(delta_r) + abs(Pd))
    for j in range(Z):
        psi = 2.0 * math.pi * min(j, Z - j) / Z  # mirror balls get bit-identical angles
        d = delta_r * math.cos(psi) - 0.5 * Pd
        Q_i = K * d**1.5 if d > d_zero else 0.0
        Q_o = Q_i + F_c
        _race_contact(j, 0, Q_i, u, shape_i, oil, method, film_table, out, ball)
        _race_contact(j, 1, Q_o, u, shape_o, oil, method, film_table, out, ball)
        if Q_i > 0.0 and Q_o > 0.0:
            out[O_N_LOADED] += 1.0
        if capacitance:
            out[O_C_BEARING] += ball_capacitance(ball[6, j], ball[7, j])
    # a race without any loaded contact reports 0 film (documented: no EHL contact to speak of)
    for race in range(2):
        if not out[O_QMAX_I + race] > 0.0:
            out[O_LAMBDA_I + race] = 0.0
            out[O_HMIN_I + race] = 0.0
            out[O_HC_I + race] = 0.0
    out[O_REGIME] = lubrication_regime(min(out[O_LAMBDA_I], out[O_LAMBDA_O]))


@kernel
def _race_contact(j, race, Q, u, shape, oil, method, film_table, out, ball):
    """Ball j's contact with race 0 (inner) or 1 (outer) under the load Q (N): its load, h_min, Lambda and
    capacitance into the ball rows, its share of the race's summaries into out (the races' slots of each
    summary are neighbours: O_<name>_I + race)."""
    a, b, p, hc, hm, lam, C, phi_t, phi_c = lubricated_contact(Q, u, race, shape, oil, method, film_table)
    if Q > 0.0:
        out[O_LAMBDA_I + race] = min(out[O_LAMBDA_I + race], lam)
        out[O_HMIN_I + race] = min(out[O_HMIN_I + race], hm)
        out[O_HC_I + race] = min(out[O_HC_I + race], hc)
        if j == 0 and method[METHOD_LUBRICATED]:  # ball 0 is the most loaded
            out[O_PHI_ISH_I + race] = phi_t
            out[O_PHI_RS_I + race] = phi_c
    out[O_PMAX] = max(out[O_PMAX], p)
    out[O_QMAX_I + race] = max(out[O_QMAX_I + race], Q)
    ball[race, j] = Q  # rows Q_i, Q_o; h_min_i, h_min_o; Lambda_i, Lambda_o; C_i, C_o
    ball[2 + race, j] = hm
    ball[4 + race, j] = lam
    if method[METHOD_CAPACITANCE]:
        ball[6 + race, j] = C
