"""Twin of bearing_fmu.kernels.ball_dynamics.monitor: the time-step limit and the kinetic energy, in plain Python.

Written from the definitions (linearised Hertz contacts, velocity-Verlet stability of an oscillator):
- a ball squeezed between its races has the tangent stiffness dQ/d(delta) = 1.5 K_h^(2/3) Q^(1/3) per contact
  (Q = K_h delta^1.5); its tangential springs have k_t = ratio K_h delta^0.5 = ratio K_h^(2/3) Q^(1/3), and a
  force at the surface of a solid sphere (I = m D^2/10) accelerates the surface by (1/m + (D/2)^2/I) = 3.5/m;
- velocity Verlet is stable below 2/omega; with a damping ratio zeta the bound becomes
  (2/omega)(sqrt(1 + zeta^2) - zeta); a cage ball between two balls sees twice the contact stiffness.
"""

import math

import numpy as np

from bearing_fmu.kernels.ball_dynamics import state as s

KERNEL_MODULE = "bearing_fmu.kernels.ball_dynamics.monitor"


def critical_time_step(par, Q_inner, Q_outer, Q_cage):
    """Stability limit (s) of the stiffest oscillator at the ball-race loads Q_inner, Q_outer (N, per ball) and
    the largest ball - cage-ball load Q_cage (N); inf when nothing is loaded. Velocity Verlet of a position
    spring: 2/omega; the tangential spring, lengthened by the predicted velocity v + a dt each step: the
    amplification matrix of (xi, v/omega) is [[1 - h^2, h], [-h (2 - h^2)/2, 1 - h^2/2]], h = omega dt,
    which keeps both eigenvalues inside the unit circle while 1 + trace + det = 4 - 2 h^2 > 0: sqrt(2)/omega."""
    m = par[s.P_M_BALL]
    limits = [math.inf]
    for q_i, q_o in zip(Q_inner, Q_outer):
        k_squeeze = sum(
            1.5 * K ** (2 / 3) * max(q, 0.0) ** (1 / 3) for K, q in ((par[s.P_KH_I], q_i), (par[s.P_KH_O], q_o))
        )
        if k_squeeze > 0.0:
            k_tangential = k_squeeze / 1.5 * par[s.P_KT_RATIO]
            limits += [2.0 / math.sqrt(k_squeeze / m), math.sqrt(2.0) / math.sqrt(k_tangential * 3.5 / m)]
    dt = min(limits)
    if Q_cage > 0.0:
        k_cage = 1.5 * par[s.P_K_CB] ** (2 / 3) * Q_cage ** (1 / 3)
        zeta = par[s.P_ZETA_CAGE]
        dt = min(dt, 2.0 / math.sqrt(2.0 * k_cage / par[s.P_M_CAGE]) * (math.sqrt(1.0 + zeta**2) - zeta))
    return dt


def kinetic_energy(balls, cage, ring, par):
    """Kinetic energy (J) of the balls (translation, rotation), cage balls and the inner ring's translation."""
    v = balls[s.B_VX : s.B_VX + 3]
    w = balls[s.B_WX : s.B_WX + 3]
    vc = cage[s.C_VX : s.C_VX + 3]
    vr = ring[s.R_VX : s.R_VX + 3]
    return 0.5 * (
        par[s.P_M_BALL] * np.sum(v * v)
        + par[s.P_I_BALL] * np.sum(w * w)
        + par[s.P_M_CAGE] * np.sum(vc * vc)
        + par[s.P_M_RING] * np.dot(vr, vr)
    )


TWINS = {"critical_time_step": critical_time_step, "kinetic_energy": kinetic_energy}
