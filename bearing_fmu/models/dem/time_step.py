"""The DEM's time step: the stability limit of the stiffest contact pair at a call's loads, the automatic step drawn
from it (and from the balls' and the ring's damping), the steps of a call and its tribology refresh interval."""

import math

import numpy as np

from ...kernels.ball_dynamics import state as s
from ...kernels.ball_dynamics.monitor import critical_time_step, damping_step_ratio
from ...kernels.ball_dynamics.outputs import contact_loads
from ...kernels.ehl import friction_coefficient, normal_damping
from ...kernels.geometry import rolling_kinematics
from ...kernels.lubricant import lubricant_state
from .monitor import DAMPING_PLAN

SAFETY = 0.5  # default time step over the stability limit of the stiffest pair (docs/reports/dem_steps.md)
MU_BOUNDARY = friction_coefficient(0.0)  # mu(Lambda) of the boundary regime (0.1), before any contact
# an automatic step that the monitor stops is halved and the call repeated, at most this often (16x smaller)
AUTO_STEP_HALVINGS = 4


def stable_time_step(bearing, par, balls, ring, trib, Q, F_x, F_y, F_z, omega, include_state, M_x, M_y):
    """DemModel.stable_time_step (s) of the state (balls, ring, trib) at loads F_x, F_y, F_z (N), M_x, M_y (N.m) and
    speed omega (rad/s); Q (2, Z) takes the contact loads (N) of the estimate."""
    contact_loads(balls, ring, par, Q)
    if not include_state:
        Q[:] = 0.0
    estimate = estimated_load(bearing, par, F_x, F_y, F_z, omega, M_x, M_y)
    Q_i = np.maximum(Q[0], estimate)
    Q_o = np.maximum(Q[1], estimate)
    C = trib[s.T_C_N]
    loaded = trib[s.T_Q] > 0.0
    mu = float(trib[s.T_MU][loaded].max()) if loaded.any() else MU_BOUNDARY
    return critical_time_step(par, Q_i, Q_o, C[0], C[1], mu * max(Q_i.max(), Q_o.max()))


def estimated_load(bearing, par, F_x, F_y, F_z, omega, M_x, M_y):
    """The contact load (N) of stable_time_step's estimate at loads F_x, F_y, F_z (N), M_x, M_y (N.m) and speed
    omega (rad/s): Stribeck's 5 F_r / Z, F_a / (Z sin alpha) with alpha >= 5 deg, 2 M / (Z rho_i sin alpha) for a
    moment, plus the centrifugal force."""
    b = bearing
    alpha = max(par[s.P_ALPHA0], math.radians(5.0))
    cage_speed = rolling_kinematics(abs(omega), b.D, b.dm, par[s.P_ALPHA0])[0]
    F_c = 0.5 * par[s.P_M_BALL] * b.dm * cage_speed**2
    axial = abs(F_z) + 2.0 * math.hypot(M_x, M_y) / par[s.P_RHO_I]
    return 5.0 * math.hypot(F_x, F_y) / b.Z + axial / (b.Z * math.sin(alpha)) + F_c


def film_damping_step(par, lub, T_oil, Q):
    """A step (s) that keeps (c_i + c_o) dt / m at DAMPING_PLAN for the largest normal damping a contact of load Q
    (N) can take at the oil temperature T_oil (K), whatever its film becomes: the boundary's 1.5 alpha_e Q or the
    full film's squeeze damping at its thinnest, Lambda = 3 (kernels.ehl.normal_damping: it falls as the film
    thickens, and a mixed film's is below both)."""
    eta = lubricant_state(T_oil, lub)[0]
    c_max = 1.5 * par[s.P_ALPHA_E] * Q
    for race in (0, 1):
        delta = (Q / par[s.P_KH_I + race]) ** (2.0 / 3.0)
        a = par[s.P_HA_I + s.P_HERTZ_SCALE_STRIDE * race] * math.sqrt(delta)
        h_min = 3.0 * par[s.P_SIGMA_I + race]
        # Lambda = inf selects the full film's formula, taken at the film of Lambda = 3 (its supremum)
        c_max = max(c_max, normal_damping(math.inf, Q, par[s.P_ALPHA_E], eta, a, 0.5 * par[s.P_D], h_min))
    return DAMPING_PLAN * par[s.P_M_BALL] / (2.0 * c_max) if c_max > 0.0 else math.inf


def automatic_time_step(stable, safety, par, trib):
    """DemModel.automatic_time_step (s) from the stability limit `stable` (s) of the call's inputs, the factor
    safety, the parameters par and the tribology trib of the last refresh."""
    dt = safety * stable
    p = par
    # the ring on its support: an explicit spring-mass (2 / omega_n) and damper (c / m) like a contact's
    support = max(p[s.P_K_SUPPORT] / p[s.P_M_RING], p[s.P_KT_SUPPORT] / p[s.P_I_RING])  # omega_n^2 (1/s^2)
    if support > 0.0:
        dt = min(dt, safety * 2.0 / math.sqrt(support))
    ratio = damping_step_ratio(trib, p, 1.0)[0]  # largest c / m (1/s)
    ratio = max(ratio, *(p[slot] / p[s.P_M_RING] for slot in s.RING_DAMPERS), p[s.P_CT_SUPPORT] / p[s.P_I_RING])
    return min(dt, DAMPING_PLAN / ratio) if ratio > 0.0 else dt


def step_count(interval, dt):
    """Steps of at most dt (s) that make up interval (s): at least one, and none added by a rounding of the ratio."""
    return max(1, math.ceil(interval / dt * (1.0 - 1e-12)))


def retry_step_count(interval, n_steps, dt):
    """Steps for a call of interval (s) that the monitor stopped at n_steps steps: twice as many, or as many as the
    step dt (s) that the stopped state needs asks for, at most 16 times as many (a blown-up state's loads are no
    guide)."""
    needed = math.ceil(interval / dt * (1.0 - 1e-12))
    return max(2 * n_steps, min(needed, 16 * n_steps))


def refresh_steps(refresh_fixed, refresh_interval, dt):
    """The tribology refresh interval in steps of dt (s): refresh_fixed if given, else at least every
    refresh_interval (s) of simulated time."""
    # floor, with a guard so that a ratio that is a whole number in exact arithmetic stays one (a round() would
    # flip at x.5 with the last bits of dt, and a master that hands step sizes differing in the last bits would
    # then take other steps)
    return refresh_fixed or max(1, math.floor(refresh_interval / dt * (1.0 + 1e-9)))
