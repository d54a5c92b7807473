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

from bearing_fmu_common.layout import Layout

from ..capacitance import CAP_SIZE
from ..film_correction import FT_SIZE

# ---- steel balls: float64[B_SIZE, Z] ------------------------------------------------------------
_B_SLOTS = Layout()
B_X = _B_SLOTS.slot(3)  # centre position x, y, z (m)
B_VX = _B_SLOTS.slot(3)  # centre velocity (m/s)
B_WX = _B_SLOTS.slot(3)  # angular velocity (rad/s); spheres carry no orientation state
B_AX = _B_SLOTS.slot(3)  # acceleration of the last step (m/s^2), velocity Verlet
B_ALX = _B_SLOTS.slot(3)  # angular acceleration of the last step (rad/s^2)
B_ORBIT = _B_SLOTS.slot()  # orbital angle about z, unwrapped (rad): its change over an interval gives the cage speed
B_SIZE = _B_SLOTS.size

# ---- cage balls (frictionless, so no rotation): float64[C_SIZE, Z] ------------------------------
_C_SLOTS = Layout()
C_X = _C_SLOTS.slot(3)  # centre position (m)
C_VX = _C_SLOTS.slot(3)  # velocity (m/s)
C_AX = _C_SLOTS.slot(3)  # acceleration of the last step (m/s^2)
C_SIZE = _C_SLOTS.size

# ---- inner ring: float64[R_SIZE] -----------------------------------------------------------------
_R_SLOTS = Layout()
# displacement x, y, z of its centre, that of its groove-curvature-centre circle (m; quasi-static zero)
R_X = _R_SLOTS.slot(3)
R_VX = _R_SLOTS.slot(3)  # velocity (m/s)
R_AX = _R_SLOTS.slot(3)  # acceleration of the last step (m/s^2)
R_TIME = _R_SLOTS.slot()  # simulated time (s)
# tilts theta_x, theta_y about the centre (rad): the ring's axis is z turned by (theta_x, theta_y, 0)
R_TH = _R_SLOTS.slot(2)
R_VTH = _R_SLOTS.slot(2)  # tilt rates (rad/s): the ring's angular velocity across its axis (small tilts)
R_ATH = _R_SLOTS.slot(2)  # tilt accelerations of the last step (rad/s^2)
R_SIZE = _R_SLOTS.size

# ---- tangential springs: float64[S_SIZE, Z], spring elongation vectors in the fixed frame (m) ----
_S_SLOTS = Layout()
S_INNER = _S_SLOTS.slot(3)  # x, y, z of the inner contact's spring
S_OUTER = _S_SLOTS.slot(3)  # x, y, z of the outer contact's spring
S_SIZE = _S_SLOTS.size
S_STRIDE = S_OUTER - S_INNER  # inner -> outer block

# ---- per-contact tribology, refreshed every N steps: float64[T_SIZE, 2, Z] (race 0 inner, 1 outer)
_T_SLOTS = Layout()
# largest tangential force over F_n (-): (1 - phi) mu_boundary + phi mu_lim, or the Coulomb override's cap
T_MU = _T_SLOTS.slot()
T_C_N = _T_SLOTS.slot()  # normal damping C_n(Lambda) at the refresh load (N.s/m); boundary regime recomputes it
T_REGIME = _T_SLOTS.slot()  # 0 boundary, 1 mixed, 2 full film
T_F_ROLL = _T_SLOTS.slot()  # rolling resistance per surface F_R + (F_h + F_H)/2 (N), applied as a moment on the ball
T_M_SPIN = _T_SLOTS.slot()  # pivoting (spin) friction moment (N.m)
T_P_FILM = _T_SLOTS.slot()  # Houpert power loss of the contact (W)
T_Q = _T_SLOTS.slot()  # normal load at the refresh (N)
T_A = _T_SLOTS.slot()  # Hertz semi-axis across the rolling direction (m)
T_B = _T_SLOTS.slot()  # Hertz semi-axis along the rolling direction (m)
T_P_MAX = _T_SLOTS.slot()  # Hertz maximum pressure (Pa)
T_U = _T_SLOTS.slot()  # entrainment speed (m/s)
T_SRR = _T_SLOTS.slot()  # slide-to-roll ratio |u_ball - u_race| / u (-)
T_SPIN = _T_SLOTS.slot()  # spin speed of the ball relative to the race about the normal (rad/s)
T_H_MIN = _T_SLOTS.slot()  # minimum film thickness (m, inf if open)
T_H_C = _T_SLOTS.slot()  # central film thickness (m, inf if open)
T_LAMBDA = _T_SLOTS.slot()  # film parameter (-)
T_CAP = _T_SLOTS.slot()  # capacitance (F)
# share of the tangential force carried by the film, ehl.film_share (-; 0 with the Coulomb override)
T_PHI = _T_SLOTS.slot()
T_SLIP = _T_SLOTS.slot()  # 1 / (s_0 u): the film's traction is mu_lim (1 - exp(-|v_t| T_SLIP)) (s/m)
T_SIZE = _T_SLOTS.size

# ---- counters: int64[K_SIZE + 2 Z] ---------------------------------------------------------------
_K_SLOTS = Layout()
K_STEP = _K_SLOTS.slot()  # steps taken since the start (selects the tribology refresh steps)
K_SIZE = _K_SLOTS.size  # followed by the chatter counter of each contact: K_SIZE + race * Z + ball

# ---- parameters: float64[P_SIZE] (built by the facade) -------------------------------------------
_P_SLOTS = Layout()
P_Z = _P_SLOTS.slot()  # number of balls (-)
P_D = _P_SLOTS.slot()  # ball diameter (m)
P_M_BALL = _P_SLOTS.slot()  # ball mass (kg)
P_I_BALL = _P_SLOTS.slot()  # ball moment of inertia m D^2 / 10 (kg.m^2)
P_RHO_I = _P_SLOTS.slot()  # radius of the inner groove-curvature-centre circle (m)
P_Z_I = _P_SLOTS.slot()  # its axial position relative to the inner ring's origin (m)
P_RHO_O = _P_SLOTS.slot()  # radius of the outer groove-curvature-centre circle (m)
P_Z_O = _P_SLOTS.slot()  # its axial position (m)
P_RG_I = _P_SLOTS.slot()  # (f_i - 1/2) D: distance ball centre - curvature centre at touching (m)
P_RG_O = _P_SLOTS.slot()  # (f_o - 1/2) D (m)
P_KH_I = _P_SLOTS.slot()  # Hertz constant of Q = K delta^1.5, inner (N/m^1.5)
P_KH_O = _P_SLOTS.slot()  # outer
P_RX_I = _P_SLOTS.slot()  # reduced radii (m), ellipticity a_y/b_x (-), elliptic integrals E, K (-), inner ...
P_RY_I = _P_SLOTS.slot()
P_K_I = _P_SLOTS.slot()
P_EE_I = _P_SLOTS.slot()
P_KK_I = _P_SLOTS.slot()
P_RX_O = _P_SLOTS.slot()  # ... and outer (same order)
P_RY_O = _P_SLOTS.slot()
P_K_O = _P_SLOTS.slot()
P_EE_O = _P_SLOTS.slot()
P_KK_O = _P_SLOTS.slot()
P_E_RED = _P_SLOTS.slot()  # Hamrock's reduced modulus E' of the ball-race pair (Pa)
P_SIGMA_I = _P_SLOTS.slot()  # composite roughness (m)
P_SIGMA_O = _P_SLOTS.slot()
P_FILM = _P_SLOTS.slot()  # film formula code (kernels.ehl FILM_*)
P_ALPHA_H = _P_SLOTS.slot()  # hysteresis loss factor (-)
P_F_I = _P_SLOTS.slot()  # groove conformities (-)
P_F_O = _P_SLOTS.slot()
P_ALPHA_E = _P_SLOTS.slot()  # hysteretic damping constant alpha_e (s/m)
P_KT_RATIO = _P_SLOTS.slot()  # tangential over secant normal stiffness (-)
P_V_REG = _P_SLOTS.slot()  # regularisation speed of the resistances' directions (m/s)
P_M_CAGE = _P_SLOTS.slot()  # cage-ball mass (kg)
P_R_CAGE = _P_SLOTS.slot()  # cage-ball radius (m)
P_K_CB = _P_SLOTS.slot()  # Hertz constant steel ball - cage ball (N/m^1.5)
P_K_GUIDE = _P_SLOTS.slot()  # Hertz constant cage ball - guide channel (N/m^1.5)
P_R_GUIDE = _P_SLOTS.slot()  # radius of the guide channel's centre circle (m)
P_Z_GUIDE = _P_SLOTS.slot()  # its axial position (m)
P_GUIDE_GAP = _P_SLOTS.slot()  # radial play of a cage ball in the channel (m)
P_ZETA_CAGE = _P_SLOTS.slot()  # damping ratio of the cage contacts (-), 1 = critical (Guessasma & Machado 2018)
P_M_RING = _P_SLOTS.slot()  # inner-ring mass (kg)
P_REFRESH = _P_SLOTS.slot()  # tribology refresh interval (steps)
P_DELTA_LIM_I = _P_SLOTS.slot()  # physical penetration limit of a ball-race contact (m), inner
P_DELTA_LIM_O = _P_SLOTS.slot()  # outer
P_CHATTER = _P_SLOTS.slot()  # consecutive slipping direction reversals that count as chatter (-)
P_DM = _P_SLOTS.slot()  # pitch diameter (m)
P_ALPHA0 = _P_SLOTS.slot()  # free contact angle (rad), for the pure-rolling reference speeds
P_C_CB = _P_SLOTS.slot()  # damping constant of the ball - cage-ball contact 2 zeta sqrt(1.5 K m_eff) (N.s/m^1.25)
P_C_GUIDE = _P_SLOTS.slot()  # the same for the cage ball - guide contact
P_HA_I = _P_SLOTS.slot()  # Hertz scaling of the inner contact (Q = K_h delta^1.5, so Q^(1/3) = K_h^(1/3) delta^(1/2)):
#   a_y = P_HA sqrt(delta), b_x = P_HB sqrt(delta) (m^0.5), p_max = P_HP sqrt(delta) (Pa/m^0.5)
P_HB_I = _P_SLOTS.slot()
P_HP_I = _P_SLOTS.slot()
P_HA_O = _P_SLOTS.slot()  # the same for the outer contact
P_HB_O = _P_SLOTS.slot()
P_HP_O = _P_SLOTS.slot()
P_DAMPING_STOP = _P_SLOTS.slot()  # largest (c_i + c_o) dt / m of a ball at a refresh before the monitor stops (-)
# Coulomb override: the full-film cap of a spring-only tangential law (-); 0 = the EHL traction curve
P_TRACTION = _P_SLOTS.slot()
P_MU_LIM = _P_SLOTS.slot()  # limiting traction coefficient of the lubricant's film (-), the traction curve's plateau
P_S_TRACTION = _P_SLOTS.slot()  # slide-to-roll ratio s_0 where the traction curve's linear part meets mu_lim (-)
# slip a newton removes from a ball's two contacts in a step, over dt / m_ball (-): 2 x 3.5
P_FILM_RATE = _P_SLOTS.slot()
P_I_RING = _P_SLOTS.slot()  # inner-ring moment of inertia about a diameter through its centre (kg.m^2)
P_IP_RING = _P_SLOTS.slot()  # about its axis (kg.m^2): the gyroscopic moment of a tilting ring that turns at omega
# stiffness of the inner ring's support across the axis (x, y), to its rest position (N/m)
P_K_SUPPORT = _P_SLOTS.slot()
P_C_SUPPORT = _P_SLOTS.slot()  # viscous damping of the support in x, y (N.s/m)
P_C_SUPPORT_AXIAL = _P_SLOTS.slot()  # and along the axis, z (N.s/m); 0 = none, the bearing alone holds the ring
# the support's tilt stiffness (N.m/rad): P_K_SUPPORT spread over the pitch circle, k (d_m/2)^2/2
P_KT_SUPPORT = _P_SLOTS.slot()
P_CT_SUPPORT = _P_SLOTS.slot()  # and its tilt damping (N.m.s/rad), c (d_m/2)^2/2
# the dampers on the ring's translations (N.s/m): the automatic step keeps each one's c / m within its plan, as a
# contact's (models.dem.time_step)
RING_DAMPERS = (P_C_SUPPORT, P_C_SUPPORT_AXIAL)
# how the inner ring moves across and along its axis: 0 = integrated under the loads and its support; 1 = prescribed,
#   it follows P_PATH over the call (the shaft holds it: no support, no loads; integrator.follow_path)
P_DRIVE = _P_SLOTS.slot()
P_PATH_T = _P_SLOTS.slot()  # duration of the call's path (s), written by the facade at each call
# the call's path: displacement x, y, z (m), tilts theta_x, theta_y (rad) at its start, their rates (m/s, rad/s) at
#   its start, the displacement and tilts at its end and their rates at its end: 4 x 5 entries
P_PATH = _P_SLOTS.slot(20)
# capacitance submodel (kernels.capacitance layout, CAP_SIZE slots; its CAP_ON 0 = off: no contact capacitance is
# computed, they stay 0)
P_CAPACITANCE_BLOCK = _P_SLOTS.slot(CAP_SIZE)
# film correction table (kernels.film_correction layout, FT_SIZE slots; its FT_ON 0 = off), the last block: the
# kernels read it as par[P_FILM_TABLE:]
P_FILM_TABLE = _P_SLOTS.slot(FT_SIZE)
P_SIZE = _P_SLOTS.size
P_HERTZ_SCALE_STRIDE = P_HA_O - P_HA_I  # inner -> outer block of the Hertz scaling

# a ball-race contact counts as loaded in the outputs (loads, pressure, films, angles, n_loaded) when its approach
# exceeds this (m): the rounding of the positions (~1e-18 m) leaves approaches of 1e-18-1e-15 m on contacts that
# carry nothing (loads of 1e-16 N, Hertz pressures of kPa); 1 pm is a load of about 1e-8 N
LOADED_APPROACH = 1e-12

# ---- outputs of advance(): float64[O_SIZE] --------------------------------------------------------
_O_SLOTS = Layout()
O_OMEGA_CAGE = _O_SLOTS.slot()  # cage speed: mean orbital angular speed of the balls (rad/s)
O_OMEGA_BALL = _O_SLOTS.slot()  # angular speed of the most loaded ball in the fixed frame (rad/s, sign of omega)
O_OMEGA_BALL_REL = _O_SLOTS.slot()  # its angular speed relative to the cage (rad/s, magnitude)
O_QMAX_I = _O_SLOTS.slot()  # largest inner contact load (N)
O_QMAX_O = _O_SLOTS.slot()  # largest outer contact load (N)
O_PMAX = _O_SLOTS.slot()  # largest Hertz pressure at the last refresh (Pa)
O_LAMBDA_I = _O_SLOTS.slot()  # film parameter, minimum over loaded inner contacts (-, 0 if none)
O_LAMBDA_O = _O_SLOTS.slot()
O_HMIN_I = _O_SLOTS.slot()  # minimum film thickness over loaded inner contacts (m, 0 if none)
O_HMIN_O = _O_SLOTS.slot()
O_HC_I = _O_SLOTS.slot()  # central film thickness of the most loaded inner contact (m)
O_HC_O = _O_SLOTS.slot()
O_REGIME = _O_SLOTS.slot()  # regime of the worst contact
O_C_BEARING = _O_SLOTS.slot()  # capacitance (F)
O_N_LOADED = _O_SLOTS.slot()  # balls loaded on both races
O_P_LOSS = _O_SLOTS.slot()  # power dissipated in the contacts, mean over the interval (W)
O_Q_INNER_RING = _O_SLOTS.slot()  # of which in the inner contacts (W)
O_Q_OUTER_RING = _O_SLOTS.slot()  # of which in the outer contacts (W)
O_TORQUE = _O_SLOTS.slot()  # P_loss / |omega| (N.m)
O_CAGE_SLIP = _O_SLOTS.slot()  # 1 - omega_cage / (pure-rolling cage speed) (-)
O_SRR_MAX = _O_SLOTS.slot()  # largest slide-to-roll ratio of a loaded contact (-)
O_KINETIC = _O_SLOTS.slot()  # kinetic energy of all bodies (J)
O_ALPHA_I = _O_SLOTS.slot()  # contact angle of the most loaded ball's inner contact (rad)
O_ALPHA_O = _O_SLOTS.slot()  # and of its outer contact (rad)
# inner-ring displacement x, y, z (m) and tilts theta_x, theta_y (rad): at the end of the interval, or their
#   means (averaged state outputs), 5 entries
O_X = _O_SLOTS.slot(5)
O_SIZE = _O_SLOTS.size

# ---- status of advance(): int64[ST_SIZE] ----------------------------------------------------------
_ST_SLOTS = Layout()
ST_CODE = _ST_SLOTS.slot()  # one of the STATUS_* codes
ST_STEP = _ST_SLOTS.slot()  # steps done in the call before it stopped
ST_INDEX = _ST_SLOTS.slot()  # ball (or contact: race * Z + ball) where the problem was found, -1 if global
ST_SIZE = _ST_SLOTS.size

STATUS_OK = 0
STATUS_NOT_FINITE = 1  # a NaN or inf appeared in the forces
STATUS_PENETRATION = 2  # a ball-race penetration passed its physical limit
STATUS_ENERGY = 3  # kinetic energy passed the bound set by the inputs (growth without input)
STATUS_CHATTER = 4  # a tangential spring reversed while slipping on consecutive steps
STATUS_DAMPING = 5  # a ball's normal damping grew beyond what the step integrates (a full film at low speed)
STATUS_WHIRL = 6  # set by the facade, not the kernel: the inner ring whirls (models.dem.whirl); the run goes on

# ---- work arrays of one force evaluation: float64[W_SIZE, Z] -------------------------------------
_W_SLOTS = Layout()
W_FB = _W_SLOTS.slot(3)  # force on each ball (N), 3 rows
W_MB = _W_SLOTS.slot(3)  # moment on each ball (N.m), 3 rows
W_FC = _W_SLOTS.slot(3)  # force on each cage ball (N), 3 rows
W_VB = _W_SLOTS.slot(3)  # predicted ball velocity (m/s), 3 rows
W_WB = _W_SLOTS.slot(3)  # predicted ball angular velocity (rad/s), 3 rows
W_VC = _W_SLOTS.slot(3)  # predicted cage-ball velocity (m/s), 3 rows
W_ORBIT = _W_SLOTS.slot()  # orbital angular speed of each ball about z from the predicted velocity (rad/s)
W_LOADED = _W_SLOTS.slot()  # races on which each ball is loaded in the current step (0, 1, 2)
W_CAP_BALL = _W_SLOTS.slot()  # each ball's capacitance at the last refresh, inner and outer contact in series (F)
# tangential force on each ball that dissipates at its contacts (N), 3 rows per race (inner first)
W_DISS = _W_SLOTS.slot(6)
W_ARM = _W_SLOTS.slot(6)  # contact point from the ball's centre (m), 3 rows per race (inner first)
# approach (m) and unit normal of each ball-race contact (contact_law.groove_approach), 4 rows per race
W_GEOM = _W_SLOTS.slot(8)
W_SIZE = _W_SLOTS.size

# ---- scalar work of one step: float64[A_SIZE] -----------------------------------------------------
_A_SLOTS = Layout()
A_FR = _A_SLOTS.slot(3)  # force on the inner ring (N), 3 entries
A_VR = _A_SLOTS.slot(3)  # predicted inner-ring velocity (m/s), 3 entries
A_DISS_I = _A_SLOTS.slot()  # energy dissipated in the inner contacts during the call (J)
A_DISS_O = _A_SLOTS.slot()  # in the outer contacts (J)
A_POWER_I = _A_SLOTS.slot()  # power dissipated in the inner contacts in the last step (W, Houpert film losses included)
A_POWER_O = _A_SLOTS.slot()  # in the outer contacts (W)
A_CAP = _A_SLOTS.slot()  # bearing capacitance (without the background) integrated over the call's steps (F.s)
A_MR = _A_SLOTS.slot(3)  # moment on the inner ring about its centre (N.m), x, y, z
A_WR = _A_SLOTS.slot(2)  # predicted tilt rates of the inner ring (rad/s), 2 entries
# inner-ring displacement x, y, z (m.s) and tilts (rad.s) integrated over the call's steps, 5 entries
A_XT = _A_SLOTS.slot(5)
A_SAMPLES = _A_SLOTS.slot()  # tribology refreshes in the call: the samples of the sums below
A_S_QMAX_I = _A_SLOTS.slot()  # sums over those refreshes of: the largest inner contact load (N) ...
A_S_QMAX_O = _A_SLOTS.slot()  # ... outer (N)
A_S_PMAX = _A_SLOTS.slot()  # ... the largest Hertz pressure of a loaded contact (Pa)
A_S_LAMBDA_I = _A_SLOTS.slot()  # ... the smallest inner film parameter of a loaded contact (-, 0 with none)
A_S_LAMBDA_O = _A_SLOTS.slot()
A_S_HMIN_I = _A_SLOTS.slot()  # ... the smallest inner minimum film (m, 0 with none)
A_S_HMIN_O = _A_SLOTS.slot()
A_S_HC_I = _A_SLOTS.slot()  # ... the central film of the most loaded inner contact (m, 0 with none)
A_S_HC_O = _A_SLOTS.slot()
# the ring's x^2, y^2 (m^2.s), theta_x^2, theta_y^2 (rad^2.s), vx^2 + vy^2 (m^2/s) and tilt rates
#   squared (rad^2/s) integrated over the call's steps, 6 entries: the orbit watch's variances (models.dem.whirl)
A_RING_SQ = _A_SLOTS.slot(6)
# with a prescribed ring (P_DRIVE): the load on the inner ring that holds it on its path, minus the balls' force and
#   moment on it (N; N.m about its centre), F_x, F_y, F_z, M_x, M_y integrated over the call's steps (N.s, N.m.s)
A_REACTION = _A_SLOTS.slot(5)
A_SIZE = _A_SLOTS.size

# ---- the argument groups of the integrator's kernels (integrator.advance, initialise_accelerations) ---------
# Plain tuples in these orders; each kernel unpacks them into named locals:
#   state = (balls, cage, ring, spring, trib, counters): the state arrays above, owned by the facade
#   params = (par, lub): the parameter array (P_*) and the lubricant's (kernels.lubricant)
#   loads = (F_x, F_y, F_z, M_x, M_y): forces (N) and moments (N.m, about its centre) on the inner ring
#   call = (n_steps, dt, omega0, omega1, loads, T_oil, energy_limit): n_steps steps of dt (s), the inner ring's
#       speed from omega0 to omega1 (rad/s), loads, oil temperature T_oil (K), the kinetic energy's bound (J)
#   space = (work, acc, status): float64[W_SIZE, Z], float64[A_SIZE] (scratch and the call's sums), int64[ST_SIZE]
# Not namedtuples: numba takes them too, but its dispatcher types each one about 0.7 us slower than a plain tuple
# (it reads the fields' names at every call), which made a facade call of advance (about 100 us) 7 us slower.
STATE_GROUP = ("balls", "cage", "ring", "spring", "trib", "counters")  # the names of state's arrays, in order
