"""Twin of bearing_fmu.kernels.loaddist: Stribeck / Sjovall radial load distribution.

Harris & Kotzalas (2006), Essential Concepts, ch. 7. A ball at azimuth psi is compressed by
delta_psi = delta_r cos(psi) - P_d/2 and carries Q = K (delta_psi)_+^1.5. With
eps = (1 - P_d/(2 delta_r))/2 the distribution is Q_psi = Q_max [1 - (1 - cos psi)/(2 eps)]^1.5,
the loaded arc is |psi| <= psi_l with cos(psi_l) = 1 - 2 eps, and for a continuum of Z balls
F_r = Z/(2 pi) int K (delta_psi)_+^1.5 cos(psi) dpsi = Z J_r(eps) Q_max. The integrals are taken
with scipy.integrate.quad over the loaded arc (the (psi_l - psi)^1.5 end point is handled by
QUADPACK's extrapolation) and the radial shift by scipy.optimize.brentq.
"""
import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

QUAD_OPTS = dict(epsabs=0.0, epsrel=1e-13, limit=200)


def gauss_legendre(n):
    """(nodes, weights) of n-point Gauss-Legendre on [-1, 1], ascending nodes (numpy.polynomial)."""
    return np.polynomial.legendre.leggauss(n)


def loaded_half_angle(eps):
    """psi_l: the Stribeck bracket 1 - (1 - cos psi)/(2 eps) vanishes at cos psi = 1 - 2 eps;
    no ball loaded for eps <= 0, all for eps >= 1."""
    if eps <= 0.0:
        return 0.0
    if eps >= 1.0:
        return math.pi
    return math.acos(1.0 - 2.0 * eps)


def radial_integral(eps):
    """J_r(eps) = 1/(2 pi) int_{-psi_l}^{psi_l} [1 - (1 - cos psi)/(2 eps)]^1.5 cos psi dpsi."""
    psi_l = loaded_half_angle(eps)
    if psi_l == 0.0:
        return 0.0

    def integrand(psi):
        base = 1.0 - (1.0 - math.cos(psi)) / (2.0 * eps)
        return max(base, 0.0) ** 1.5 * math.cos(psi)

    value, _ = quad(integrand, -psi_l, psi_l, **QUAD_OPTS)
    return value / (2.0 * math.pi)


def load_parameter(delta_r, Pd):
    """eps = (1 - P_d/(2 delta_r))/2; at delta_r = 0 its limit delta_r -> 0+:
    +inf with preload, 1/2 without clearance, -inf with clearance."""
    if delta_r > 0.0:
        return 0.5 * (1.0 - Pd / (2.0 * delta_r))
    if Pd < 0.0:
        return math.inf
    if Pd == 0.0:
        return 0.5
    return -math.inf


def stribeck_load(psi, Q_max, eps):
    """Q_psi = Q_max [1 - (1 - cos psi)/(2 eps)]_+^1.5."""
    base = 1.0 - (1.0 - math.cos(psi)) / (2.0 * eps)
    return Q_max * max(base, 0.0) ** 1.5


def _loaded_arc(delta_r, Pd):
    """Half-angle of the arc where delta_r cos psi > P_d/2 (0: no ball loaded, pi: all loaded)."""
    if delta_r - Pd / 2.0 <= 0.0:      # not even the ball at psi = 0 is compressed
        return 0.0
    if -delta_r - Pd / 2.0 > 0.0:      # even the ball at psi = pi is compressed
        return math.pi
    return math.acos(Pd / (2.0 * delta_r))


def _radial_force(delta_r, Pd, K, Z):
    psi_l = _loaded_arc(delta_r, Pd)
    if psi_l == 0.0:
        return 0.0
    value, _ = quad(lambda psi: K * max(delta_r * math.cos(psi) - Pd / 2.0, 0.0) ** 1.5 * math.cos(psi),
                    -psi_l, psi_l, **QUAD_OPTS)
    return Z * value / (2.0 * math.pi)


def radial_force_and_slope(delta_r, Pd, K, Z):
    """(F_r, dF_r/d delta_r) of Z balls (continuum) at the inner-ring shift delta_r >= 0.

    F_r = Z/(2 pi) int K (delta_r cos psi - P_d/2)_+^1.5 cos psi dpsi; the slope is the integral of
    the delta_r-derivative, 1.5 K (.)_+^0.5 cos^2 psi (Leibniz: the integrand vanishes at the arc ends).
    """
    psi_l = _loaded_arc(delta_r, Pd)
    if psi_l == 0.0:
        return 0.0, 0.0

    def compression(psi):
        return max(delta_r * math.cos(psi) - Pd / 2.0, 0.0)

    slope, _ = quad(lambda psi: 1.5 * K * compression(psi) ** 0.5 * math.cos(psi) ** 2,
                    -psi_l, psi_l, **QUAD_OPTS)
    return _radial_force(delta_r, Pd, K, Z), Z * slope / (2.0 * math.pi)


def solve_radial_shift(F_r, Pd, K, Z):
    """delta_r with F_r(delta_r) = F_r, by brentq on the quad force; F_r = 0 -> P_d/2 with clearance
    (balls just touching, the kernel's documented choice in the zero-force interval), 0 otherwise."""
    lo = max(Pd / 2.0, 0.0)
    if F_r <= 0.0:
        return lo
    hi = lo + 1e-9
    while _radial_force(hi, Pd, K, Z) < F_r:
        hi *= 2.0
    return brentq(lambda d: _radial_force(d, Pd, K, Z) - F_r, lo, hi,
                  xtol=1e-300, rtol=8.9e-16, maxiter=500)
