"""Named slots of the DEM state, parameter, per-contact and output arrays (structure of arrays).

Every array is float64 (int64 for the counters) and owned by the facade, so that it can be saved and
restored as a whole (FMU state, rollback). Row-major ``[row, ball]`` layouts keep one quantity of all
balls contiguous.

Frames and signs: fixed frame with z along the bearing axis; the outer ring is fixed, the inner ring
turns about its own axis at omega (rad/s, prescribed), translates (x, y, z) and tilts (theta_x, theta_y: the
rotation vector (theta_x, theta_y, 0) about the centre of its groove-curvature-centre circle, right-handed about x
and y as the quasi-static fidelity's). Azimuth psi is measured from x toward y;
a load F_x > 0 on the inner ring loads the ball at psi = 0. Ball 1 (index 0) starts on +y, the line of F_y
(docs/conventions.md).
"""

from ..film_correction import FT_SIZE

# ---- steel balls: float64[B_SIZE, Z] ------------------------------------------------------------
B_X = 0  # centre position x, y, z (m)
B_VX = 3  # centre velocity (m/s)
B_WX = 6  # angular velocity (rad/s); spheres carry no orientation state
B_AX = 9  # acceleration of the last step (m/s^2), velocity Verlet
B_ALX = 12  # angular acceleration of the last step (rad/s^2)
B_ORBIT = 15  # orbital angle about z, unwrapped (rad): its change over an interval gives the cage speed
B_SIZE = 16

# ---- cage balls (frictionless, so no rotation): float64[C_SIZE, Z] ------------------------------
C_X = 0  # centre position (m)
C_VX = 3  # velocity (m/s)
C_AX = 6  # acceleration of the last step (m/s^2)
C_SIZE = 9

# ---- inner ring: float64[R_SIZE] -----------------------------------------------------------------
R_X = 0  # displacement x, y, z of its centre, that of its groove-curvature-centre circle (m; quasi-static zero)
R_VX = 3  # velocity (m/s)
R_AX = 6  # acceleration of the last step (m/s^2)
R_TIME = 9  # simulated time (s)
R_TH = 10  # tilts theta_x, theta_y about the centre (rad): the ring's axis is z turned by (theta_x, theta_y, 0)
R_VTH = 12  # tilt rates (rad/s): the ring's angular velocity across its axis (small tilts)
R_ATH = 14  # tilt accelerations of the last step (rad/s^2)
R_SIZE = 16

# ---- tangential springs: float64[S_SIZE, Z], spring elongation vectors in the fixed frame (m) ----
S_INNER = 0  # x, y, z of the inner contact's spring
S_OUTER = 3  # x, y, z of the outer contact's spring
S_SIZE = 6
S_STRIDE = S_OUTER - S_INNER  # inner -> outer block

# ---- per-contact tribology, refreshed every N steps: float64[T_SIZE, 2, Z] (race 0 inner, 1 outer)
T_MU = 0  # largest tangential force over F_n (-): (1 - phi) mu_boundary + phi mu_lim, or the Coulomb override's cap
T_C_N = 1  # normal damping C_n(Lambda) at the refresh load (N.s/m); boundary regime recomputes it
T_REGIME = 2  # 0 boundary, 1 mixed, 2 full film
T_F_ROLL = 3  # rolling resistance per surface F_R + (F_h + F_H)/2 (N), applied as a moment on the ball
T_M_SPIN = 4  # pivoting (spin) friction moment (N.m)
T_P_FILM = 5  # Houpert power loss of the contact (W)
T_Q = 6  # normal load at the refresh (N)
T_A = 7  # Hertz semi-axis across the rolling direction (m)
T_B = 8  # Hertz semi-axis along the rolling direction (m)
T_P_MAX = 9  # Hertz maximum pressure (Pa)
T_U = 10  # entrainment speed (m/s)
T_SRR = 11  # slide-to-roll ratio |u_ball - u_race| / u (-)
T_SPIN = 12  # spin speed of the ball relative to the race about the normal (rad/s)
T_H_MIN = 13  # minimum film thickness (m, inf if open)
T_H_C = 14  # central film thickness (m, inf if open)
T_LAMBDA = 15  # film parameter (-)
T_CAP = 16  # capacitance (F)
T_PHI = 17  # share of the tangential force carried by the film, ehl.film_share (-; 0 with the Coulomb override)
T_SLIP = 18  # 1 / (s_0 u): the film's traction is mu_lim (1 - exp(-|v_t| T_SLIP)) (s/m)
T_SIZE = 19

# ---- counters: int64[K_SIZE + 2 Z] ---------------------------------------------------------------
K_STEP = 0  # steps taken since the start (selects the tribology refresh steps)
K_SIZE = 1  # followed by the chatter counter of each contact: K_SIZE + race * Z + ball

# ---- parameters: float64[P_SIZE] (built by the facade) -------------------------------------------
P_Z = 0  # number of balls (-)
P_D = 1  # ball diameter (m)
P_M_BALL = 2  # ball mass (kg)
P_I_BALL = 3  # ball moment of inertia m D^2 / 10 (kg.m^2)
P_RHO_I = 4  # radius of the inner groove-curvature-centre circle (m)
P_Z_I = 5  # its axial position relative to the inner ring's origin (m)
P_RHO_O = 6  # radius of the outer groove-curvature-centre circle (m)
P_Z_O = 7  # its axial position (m)
P_RG_I = 8  # (f_i - 1/2) D: distance ball centre - curvature centre at touching (m)
P_RG_O = 9  # (f_o - 1/2) D (m)
P_KH_I = 10  # Hertz constant of Q = K delta^1.5, inner (N/m^1.5)
P_KH_O = 11  # outer
P_RX_I = 12  # reduced radii (m), ellipticity a_y/b_x (-), elliptic integrals E, K (-), inner ...
P_RY_I = 13
P_K_I = 14
P_EE_I = 15
P_KK_I = 16
P_RX_O = 17  # ... and outer (same order)
P_RY_O = 18
P_K_O = 19
P_EE_O = 20
P_KK_O = 21
P_E_RED = 22  # Hamrock's reduced modulus E' of the ball-race pair (Pa)
P_SIGMA_I = 23  # composite roughness (m)
P_SIGMA_O = 24
P_FILM = 25  # film formula code (kernels.ehl FILM_*)
P_PRESSURE = 26  # permittivity pressure code (kernels.capacitance PRESSURE_*)
P_H_FLOOR = 27  # capacitance film floor (m)
P_ALPHA_H = 28  # hysteresis loss factor (-)
P_F_I = 29  # groove conformities (-)
P_F_O = 30
P_ALPHA_E = 31  # hysteretic damping constant alpha_e (s/m)
P_KT_RATIO = 32  # tangential over secant normal stiffness (-)
P_V_REG = 33  # regularisation speed of the resistances' directions (m/s)
P_M_CAGE = 34  # cage-ball mass (kg)
P_R_CAGE = 35  # cage-ball radius (m)
P_K_CB = 36  # Hertz constant steel ball - cage ball (N/m^1.5)
P_K_GUIDE = 37  # Hertz constant cage ball - guide channel (N/m^1.5)
P_R_GUIDE = 38  # radius of the guide channel's centre circle (m)
P_Z_GUIDE = 39  # its axial position (m)
P_GUIDE_GAP = 40  # radial play of a cage ball in the channel (m)
P_ZETA_CAGE = 41  # damping ratio of the cage contacts (-), 1 = critical (Guessasma & Machado 2018)
P_M_RING = 42  # inner-ring mass (kg)
P_REFRESH = 43  # tribology refresh interval (steps)
P_DELTA_LIM_I = 44  # physical penetration limit of a ball-race contact (m), inner
P_DELTA_LIM_O = 45  # outer
P_CHATTER = 46  # consecutive slipping direction reversals that count as chatter (-)
P_DM = 47  # pitch diameter (m)
P_ALPHA0 = 48  # free contact angle (rad), for the pure-rolling reference speeds
P_C_CB = 49  # damping constant of the ball - cage-ball contact 2 zeta sqrt(1.5 K m_eff) (N.s/m^1.25)
P_C_GUIDE = 50  # the same for the cage ball - guide contact
P_HA_I = 51  # Hertz scaling of the inner contact (Q = K_h delta^1.5, so Q^(1/3) = K_h^(1/3) delta^(1/2)):
P_HB_I = 52  #   a_y = P_HA sqrt(delta), b_x = P_HB sqrt(delta) (m^0.5), p_max = P_HP sqrt(delta) (Pa/m^0.5)
P_HP_I = 53
P_HA_O = 54  # the same for the outer contact
P_HB_O = 55
P_HP_O = 56
P_HERTZ_SCALE_STRIDE = P_HA_O - P_HA_I  # inner -> outer block of the Hertz scaling
P_CAPACITANCE = 57  # 1: compute the contact capacitances; 0: the scene turned them off (not computed, 0)
P_DAMPING_STOP = 58  # largest (c_i + c_o) dt / m of a ball at a refresh before the monitor stops (-)
P_TRACTION = 59  # Coulomb override: the full-film cap of a spring-only tangential law (-); 0 = the EHL traction curve
P_MU_LIM = 60  # limiting traction coefficient of the lubricant's film (-), the traction curve's plateau
P_S_TRACTION = 61  # slide-to-roll ratio s_0 where the traction curve's linear part meets mu_lim (-)
P_FILM_RATE = 62  # slip a newton removes from a ball's two contacts in a step, over dt / m_ball (-): 2 x 3.5
P_I_RING = 63  # inner-ring moment of inertia about a diameter through its centre (kg.m^2)
P_IP_RING = 64  # about its axis (kg.m^2): the gyroscopic moment of a tilting ring that turns at omega
P_K_SUPPORT = 65  # stiffness of the inner ring's support across the axis (x, y), to its rest position (N/m)
P_C_SUPPORT = 66  # viscous damping of the support in x, y (N.s/m); none along the axis
P_KT_SUPPORT = 67  # the support's tilt stiffness (N.m/rad): P_K_SUPPORT spread over the pitch circle, k (d_m/2)^2/2
P_CT_SUPPORT = 68  # and its tilt damping (N.m.s/rad), c (d_m/2)^2/2
P_OIL_GAP = 69  # oil-availability gap (m) of the capacitance outside the Hertz zones; 0 = Hertz zones only
P_FILM_TABLE = 70  # film correction table (kernels.film_correction layout, FT_SIZE slots; its FT_ON 0 = off)
P_SIZE = P_FILM_TABLE + FT_SIZE

# a ball-race contact counts as loaded in the outputs (loads, pressure, films, angles, n_loaded) when its approach
# exceeds this (m): the rounding of the positions (~1e-18 m) leaves approaches of 1e-18-1e-15 m on contacts that
# carry nothing (loads of 1e-16 N, Hertz pressures of kPa); 1 pm is a load of about 1e-8 N
LOADED_APPROACH = 1e-12

# ---- outputs of advance(): float64[O_SIZE] --------------------------------------------------------
O_OMEGA_CAGE = 0  # cage speed: mean orbital angular speed of the balls (rad/s)
O_OMEGA_BALL = 1  # angular speed of the most loaded ball in the fixed frame (rad/s, sign of omega)
O_OMEGA_BALL_REL = 2  # its angular speed relative to the cage (rad/s, magnitude)
O_QMAX_I = 3  # largest inner contact load (N)
O_QMAX_O = 4  # largest outer contact load (N)
O_PMAX = 5  # largest Hertz pressure at the last refresh (Pa)
O_LAMBDA_I = 6  # film parameter, minimum over loaded inner contacts (-, 0 if none)
O_LAMBDA_O = 7
O_HMIN_I = 8  # minimum film thickness over loaded inner contacts (m, 0 if none)
O_HMIN_O = 9
O_HC_I = 10  # central film thickness of the most loaded inner contact (m)
O_HC_O = 11
O_REGIME = 12  # regime of the worst contact
O_C_BEARING = 13  # capacitance (F)
O_N_LOADED = 14  # balls loaded on both races
O_P_LOSS = 15  # power dissipated in the contacts, mean over the interval (W)
O_Q_INNER_RING = 16  # of which in the inner contacts (W)
O_Q_OUTER_RING = 17  # of which in the outer contacts (W)
O_TORQUE = 18  # P_loss / |omega| (N.m)
O_CAGE_SLIP = 19  # 1 - omega_cage / (pure-rolling cage speed) (-)
O_SRR_MAX = 20  # largest slide-to-roll ratio of a loaded contact (-)
O_KINETIC = 21  # kinetic energy of all bodies (J)
O_ALPHA_I = 22  # contact angle of the most loaded ball's inner contact (rad)
O_ALPHA_O = 23  # and of its outer contact (rad)
O_X = 24  # inner-ring displacement x, y, z (m) and tilts theta_x, theta_y (rad): at the end of the interval, or their
#   means (averaged state outputs), 5 entries
O_SIZE = 29

# ---- status of advance(): int64[ST_SIZE] ----------------------------------------------------------
ST_CODE = 0  # one of the STATUS_* codes
ST_STEP = 1  # steps done in the call before it stopped
ST_INDEX = 2  # ball (or contact: race * Z + ball) where the problem was found, -1 if global
ST_SIZE = 3

STATUS_OK = 0
STATUS_NOT_FINITE = 1  # a NaN or inf appeared in the forces
STATUS_PENETRATION = 2  # a ball-race penetration passed its physical limit
STATUS_ENERGY = 3  # kinetic energy passed the bound set by the inputs (growth without input)
STATUS_CHATTER = 4  # a tangential spring reversed while slipping on consecutive steps
STATUS_DAMPING = 5  # a ball's normal damping grew beyond what the step integrates (a full film at low speed)
STATUS_WHIRL = 6  # set by the facade, not the kernel: the inner ring whirls (models.dem.whirl); the run goes on

# ---- work arrays of one force evaluation: float64[W_SIZE, Z] -------------------------------------
W_FB = 0  # force on each ball (N), 3 rows
W_MB = 3  # moment on each ball (N.m), 3 rows
W_FC = 6  # force on each cage ball (N), 3 rows
W_VB = 9  # predicted ball velocity (m/s), 3 rows
W_WB = 12  # predicted ball angular velocity (rad/s), 3 rows
W_VC = 15  # predicted cage-ball velocity (m/s), 3 rows
W_ORBIT = 18  # orbital angular speed of each ball about z from the predicted velocity (rad/s)
W_LOADED = 19  # races on which each ball is loaded in the current step (0, 1, 2)
W_CAP_BALL = 20  # each ball's capacitance at the last refresh, inner and outer contact in series (F)
W_DISS = 21  # tangential force on each ball that dissipates at its contacts (N), 3 rows per race (inner 21-23)
W_ARM = 27  # contact point from the ball's centre (m), 3 rows per race (inner 27-29)
W_GEOM = 33  # approach (m) and unit normal of each ball-race contact (contacts.groove_approach), 4 rows per race
W_SIZE = 41

# ---- scalar work of one step: float64[A_SIZE] -----------------------------------------------------
A_FR = 0  # force on the inner ring (N), 3 entries
A_VR = 3  # predicted inner-ring velocity (m/s), 3 entries
A_DISS_I = 6  # energy dissipated in the inner contacts during the call (J)
A_DISS_O = 7  # in the outer contacts (J)
A_POWER_I = 8  # power dissipated in the inner contacts in the last step (W, Houpert film losses included)
A_POWER_O = 9  # in the outer contacts (W)
A_CAP = 10  # bearing capacitance (without the background) integrated over the call's steps (F.s)
A_MR = 11  # moment on the inner ring about its centre (N.m), x, y, z
A_WR = 14  # predicted tilt rates of the inner ring (rad/s), 2 entries
A_XT = 16  # inner-ring displacement x, y, z (m.s) and tilts (rad.s) integrated over the call's steps, 5 entries
A_SAMPLES = 21  # tribology refreshes in the call: the samples of the sums below
A_S_QMAX_I = 22  # sums over those refreshes of: the largest inner contact load (N) ...
A_S_QMAX_O = 23  # ... outer (N)
A_S_PMAX = 24  # ... the largest Hertz pressure of a loaded contact (Pa)
A_S_LAMBDA_I = 25  # ... the smallest inner film parameter of a loaded contact (-, 0 with none)
A_S_LAMBDA_O = 26
A_S_HMIN_I = 27  # ... the smallest inner minimum film (m, 0 with none)
A_S_HMIN_O = 28
A_S_HC_I = 29  # ... the central film of the most loaded inner contact (m, 0 with none)
A_S_HC_O = 30
A_RING_SQ = 31  # the ring's x^2, y^2 (m^2.s), theta_x^2, theta_y^2 (rad^2.s), vx^2 + vy^2 (m^2/s) and tilt rates
#   squared (rad^2/s) integrated over the call's steps, 6 entries: the orbit watch's variances (models.dem.whirl)
A_SIZE = 37
