"""Stribeck / Sjovall radial load distribution of a radially loaded ball bearing with clearance.

Harris & Kotzalas (2006), Essential Concepts, ch. 7; Guessasma & Machado (2018) App. A:
  delta_psi = delta_r cos(psi) - P_d/2,   Q_psi = K (delta_psi)_+^(3/2),
  Q_psi = Q_max [1 - (1 - cos psi) / (2 eps)]^(3/2),  eps = (1 - P_d / (2 delta_r)) / 2,
  F_r = Z J_r(eps) Q_max,  J_r(eps) = 1/(2 pi) int [1 - (1 - cos psi)/(2 eps)]^(3/2) cos psi dpsi.
K is the load-deflection constant of the inner and outer contacts in series (N/m^1.5).
The integrals use Gauss-Legendre quadrature on the loaded arc; nodes come from
``gauss_legendre`` (computed once at model set-up).
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel


@kernel
def gauss_legendre(n):
    """Nodes and weights (arrays of n floats) of n-point Gauss-Legendre quadrature on [-1, 1]."""
    x = np.empty(n)
    w = np.empty(n)
    for i in range(n):
        z = math.cos(math.pi * (i + 0.75) / (n + 0.5))
        for _ in range(100):
            p1 = 1.0
            p2 = 0.0
            for j in range(1, n + 1):
                p3 = p2
                p2 = p1
                p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j
            dp = n * (z * p1 - p2) / (z * z - 1.0)
            dz = p1 / dp
            z -= dz
            if abs(dz) < 1e-16:
                break
        x[i] = z
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp)
    return x, w


@kernel
def loaded_half_angle(eps):
    """Half-angle psi_l (rad) of the loaded zone for load parameter eps (all balls loaded if eps >= 1)."""
    if eps >= 1.0:
        return math.pi
    if eps <= 0.0:
        return 0.0
    return math.acos(1.0 - 2.0 * eps)


@kernel
def radial_integral(eps, nodes, weights):
    """Sjovall radial integral J_r(eps) (-) for load parameter eps (0 for eps <= 0: no ball loaded)."""
    if eps <= 0.0:
        return 0.0
    psi_l = loaded_half_angle(eps)
    total = 0.0
    for i in range(nodes.shape[0]):
        psi = 0.5 * psi_l * (nodes[i] + 1.0)
        base = 1.0 - (1.0 - math.cos(psi)) / (2.0 * eps)
        if base > 0.0:
            total += weights[i] * base**1.5 * math.cos(psi)
    # symmetric arc [-psi_l, psi_l] -> 2 x [0, psi_l]; Jacobian psi_l / 2; 1/(2 pi) prefactor
    return total * psi_l / (2.0 * math.pi)


@kernel
def load_parameter(delta_r, Pd):
    """Load parameter eps = (1 - P_d/(2 delta_r))/2 (-).

    Limits at delta_r -> 0+: 1/2 without clearance (for any shift), +inf with preload, -inf with
    clearance (never reached by the model: with clearance the ring rests at delta_r = P_d/2, eps = 0).
    """
    if Pd == 0.0:
        return 0.5
    if delta_r <= 0.0:
        return math.inf if Pd < 0.0 else -math.inf
    return 0.5 * (1.0 - Pd / (2.0 * delta_r))


@kernel
def stribeck_load(psi, Q_max, eps):
    """Ball load Q(psi) (N) of the Sjovall distribution with maximum Q_max (N) and load parameter eps."""
    base = 1.0 - (1.0 - math.cos(psi)) / (2.0 * eps)
    if base <= 0.0:
        return 0.0
    return Q_max * base**1.5


@kernel
def radial_force_and_slope(delta_r, Pd, K, Z, nodes, weights):
    """Radial force F_r (N) carried by Z balls at inner-ring shift delta_r (m), and dF_r/d(delta_r) (N/m).

    Continuous-ball (integral) form: F_r = Z/(2 pi) int K (delta_r cos psi - P_d/2)_+^1.5 cos psi dpsi.
    """
    if delta_r <= 0.0:
        if Pd >= 0.0:
            return 0.0, 0.0  # no ball compressed
        psi_l = math.pi  # centred preloaded ring: every ball compressed
    else:
        c = Pd / (2.0 * delta_r)
        if c >= 1.0:
            return 0.0, 0.0
        psi_l = math.pi if c <= -1.0 else math.acos(c)
    force = 0.0
    slope = 0.0
    for i in range(nodes.shape[0]):
        psi = 0.5 * psi_l * (nodes[i] + 1.0)
        cp = math.cos(psi)
        d = delta_r * cp - 0.5 * Pd
        if d > 0.0:
            sd = math.sqrt(d)
            force += weights[i] * d * sd * cp
            slope += weights[i] * 1.5 * sd * cp * cp
    scale = Z * K * psi_l / (2.0 * math.pi)
    if delta_r <= 0.0:
        force = 0.0  # centred ring: the ball forces cancel exactly by symmetry
    return force * scale, slope * scale


@kernel
def solve_radial_shift(F_r, Pd, K, Z, nodes, weights, tol):
    """Inner-ring radial shift delta_r (m) carrying the radial load F_r >= 0 (N); safeguarded Newton.

    Returns (delta_r, iterations). With clearance (P_d > 0) and F_r = 0 the ring sits at P_d/2
    (balls just touching); with preload (P_d < 0) and F_r = 0 it is centred (0).
    """
    lo = max(0.5 * Pd, 0.0)
    if F_r <= 0.0:
        return lo, 0
    # upper bracket: all load on one ball is a bound (F_r <= K (delta_r - Pd/2)^1.5 x Z)
    hi = lo + (F_r / K) ** (2.0 / 3.0) + abs(Pd)
    while radial_force_and_slope(hi, Pd, K, Z, nodes, weights)[0] < F_r:
        hi *= 2.0
    # with preload the balls' forces cancel around the ring: the residual cannot be resolved below
    # the rounding of that internal force (a few eps x Z K |P_d/2|^1.5), so the tolerance has that floor
    f_tol = max(tol * F_r, 8.0 * 2.220446049250313e-16 * Z * K * abs(0.5 * Pd) ** 1.5)
    x = 0.5 * (lo + hi)
    for it in range(1, 200):
        f, df = radial_force_and_slope(x, Pd, K, Z, nodes, weights)
        r = f - F_r
        if r > 0.0:
            hi = x
        else:
            lo = x
        if abs(r) <= f_tol or hi - lo <= 1e-15 * hi:
            return x, it
        x_new = x - r / df if df > 0.0 else 0.5 * (lo + hi)
        if not (lo < x_new < hi):
            x_new = 0.5 * (lo + hi)
        x = x_new
    return x, 200
