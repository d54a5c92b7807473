"""Twin of bearing_fmu.kernels.ball_dynamics.monitor: the time-step limit and the kinetic energy, in plain Python.

Written from the definitions (linearised Hertz contacts, velocity-Verlet stability of an oscillator):
- a ball squeezed between its races has the tangent stiffness dQ/d(delta) = 1.5 K_h^(2/3) Q^(1/3) per contact
  (Q = K_h delta^1.5); its tangential springs have k_t = ratio K_h delta^0.5 = ratio K_h^(2/3) Q^(1/3), and a
  force at the surface of a solid sphere (I = m D^2/10) accelerates the surface by (1/m + (D/2)^2/I) = 3.5/m;
- velocity Verlet is stable below 2/omega; with a damping force taken at the predicted velocity the bound is
  found here numerically from the step's amplification matrix; a cage ball touches one ball at a time.
"""

import math

import numpy as np

from bearing_fmu.kernels.ball_dynamics import state as s

KERNEL_MODULE = "bearing_fmu.kernels.ball_dynamics.monitor"


def _spectral_radius(h, zeta):
    """Largest |eigenvalue| of one step, dt = h/omega, of x'' = -omega^2 x - 2 zeta omega x' with the damping at
    the predicted velocity, on the state (x, v/omega, a/omega^2): x1 = x + v h + a h^2/2, v* = v + a h,
    a1 = -x1 - 2 zeta v*, v1 = v + (a + a1) h/2."""
    x1 = np.array([1.0, h, 0.5 * h * h])
    v_star = np.array([0.0, 1.0, h])
    a1 = -x1 - 2.0 * zeta * v_star
    v1 = np.array([0.0, 1.0, 0.5 * h]) + 0.5 * h * a1
    return max(abs(np.linalg.eigvals(np.array([x1, v1, a1]))))


def damped_limit(omega, zeta):
    """Stability limit (s) found numerically: the largest h = omega dt with spectral radius <= 1, by bisection."""
    low, high = 0.0, 2.0  # stable at 0+, unstable at 2 for any zeta >= 0 ... checked below
    if _spectral_radius(high, zeta) <= 1.0 + 1e-12:
        high = 4.0
    for _ in range(80):
        mid = 0.5 * (low + high)
        if _spectral_radius(mid, zeta) <= 1.0 + 1e-12:
            low = mid
        else:
            high = mid
    return low / omega


def critical_time_step(par, Q_inner, Q_outer, C_inner, C_outer, Q_cage):
    """Stability limit (s) of the stiffest oscillator at the ball-race loads Q_inner, Q_outer (N, per ball) with
    their normal damping C_inner, C_outer (N.s/m), and the largest ball - cage-ball load Q_cage (N); inf when
    nothing is loaded. A ball squeezed between its loaded races: stiffness k = sum 1.5 K_h^(2/3) Q^(1/3), damping
    c = sum of their C, limit from the spectral radius above; the tangential spring, lengthened by the
    predicted velocity v + a dt each step: the amplification matrix of (xi, v/omega) is
    [[1 - h^2, h], [-h (2 - h^2)/2, 1 - h^2/2]], h = omega dt, which keeps both eigenvalues inside the unit
    circle while 1 + trace + det = 4 - 2 h^2 > 0: sqrt(2)/omega. A cage ball against one ball (the pocket play):
    stiffness k, reduced mass m_eff, damping c = 2 zeta_c sqrt(k m_eff) (critical for zeta_c = 1)."""
    m = par[s.P_M_BALL]
    limits = [math.inf]
    for q_i, q_o, c_i, c_o in zip(Q_inner, Q_outer, C_inner, C_outer):
        loaded = [(K, q, c) for K, q, c in ((par[s.P_KH_I], q_i, c_i), (par[s.P_KH_O], q_o, c_o)) if q > 0.0]
        k_squeeze = sum(1.5 * K ** (2 / 3) * q ** (1 / 3) for K, q, _ in loaded)
        if k_squeeze > 0.0:
            c = sum(c for _, _, c in loaded)
            omega = math.sqrt(k_squeeze / m)
            k_tangential = k_squeeze / 1.5 * par[s.P_KT_RATIO]
            limits += [
                damped_limit(omega, c / (2.0 * math.sqrt(k_squeeze * m))),
                math.sqrt(2.0) / math.sqrt(k_tangential * 3.5 / m),
            ]
    dt = min(limits)
    if Q_cage > 0.0:
        k_cage = 1.5 * par[s.P_K_CB] ** (2 / 3) * Q_cage ** (1 / 3)
        m_eff = 1.0 / (1.0 / m + 1.0 / par[s.P_M_CAGE])
        c = 2.0 * par[s.P_ZETA_CAGE] * math.sqrt(k_cage * m_eff)
        dt = min(dt, damped_limit(math.sqrt(k_cage / m_eff), c / (2.0 * math.sqrt(k_cage * m_eff))))
    return dt


def kinetic_energy(balls, cage, ring, par):
    """Kinetic energy (J) of the balls (translation, rotation), cage balls and the inner ring's translation and
    tilt rates (its turning about its axis is an input, left out)."""
    v = balls[s.B_VX : s.B_VX + 3]
    w = balls[s.B_WX : s.B_WX + 3]
    vc = cage[s.C_VX : s.C_VX + 3]
    vr = ring[s.R_VX : s.R_VX + 3]
    tilt_rates = ring[s.R_VTH : s.R_VTH + 2]
    return 0.5 * (
        par[s.P_M_BALL] * np.sum(v * v)
        + par[s.P_I_BALL] * np.sum(w * w)
        + par[s.P_M_CAGE] * np.sum(vc * vc)
        + par[s.P_M_RING] * np.dot(vr, vr)
        + par[s.P_I_RING] * np.dot(tilt_rates, tilt_rates)
    )


def damping_step_ratio(trib, par, dt):
    """(max over balls of (sum of the loaded contacts' C_n) dt / m, that ball or -1)."""
    loaded = trib[s.T_Q] > 0.0
    ratios = np.where(loaded, trib[s.T_C_N], 0.0).sum(axis=0) * dt / par[s.P_M_BALL]
    if not (ratios > 0.0).any():
        return 0.0, -1
    return float(ratios.max()), int(np.argmax(ratios))


TWINS = {
    "critical_time_step": critical_time_step,
    "kinetic_energy": kinetic_energy,
    "damped_limit": damped_limit,
    "damping_step_ratio": damping_step_ratio,
}
