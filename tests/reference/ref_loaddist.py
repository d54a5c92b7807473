"""Twin of bearing_fmu.kernels.loaddist: Stribeck / Sjovall radial load distribution.

Harris & Kotzalas (2006), Essential Concepts, ch. 7. A ball at azimuth psi is compressed by
delta_psi = delta_r cos(psi) - P_d/2 and carries Q = K (delta_psi)_+^1.5. With
eps = (1 - P_d/(2 delta_r))/2 the distribution is Q_psi = Q_max [1 - (1 - cos psi)/(2 eps)]^1.5,
the loaded arc is |psi| <= psi_l with cos(psi_l) = 1 - 2 eps, and for a continuum of Z balls
F_r = Z/(2 pi) int K (delta_psi)_+^1.5 cos(psi) dpsi = Z J_r(eps) Q_max. The integrals are taken
with scipy.integrate.quad over the loaded arc (the algebraic end point is handled by QUADPACK's
extrapolation) and the radial shift by scipy.optimize.brentq.

Three rewritings keep the twin accurate where the printed forms lose digits (each is checked
against the printed form by the unit tests): 1 - cos psi = 2 sin^2(psi/2) (tiny eps, light loads
with clearance); the loaded half-angle from sin^2(psi_l/2) = eps; and integration by parts of
int g cos psi = -int g' sin psi (boundary terms vanish), whose integrand is positive, for
eps >> 1 (heavy preload, J_r ~ 3/(8 eps)) where the printed integral is a small difference.
"""

import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

# integrands and integrals are O(1) after scaling; 1e-12 is 4 orders below the kernel error (1e-8)
QUAD_OPTS = dict(epsabs=1e-14, epsrel=1e-12, limit=200)
# the printed (cancelling) forms, kept to check the integrated-by-parts ones, reach less
DIRECT_OPTS = dict(epsabs=1e-13, epsrel=1e-11, limit=200)


def gauss_legendre(n):
    """(nodes, weights) of n-point Gauss-Legendre on [-1, 1], ascending nodes (numpy.polynomial)."""
    return np.polynomial.legendre.leggauss(n)


def loaded_half_angle(eps):
    """psi_l: the Stribeck bracket 1 - (1 - cos psi)/(2 eps) vanishes where 1 - cos psi = 2 eps,
    i.e. sin^2(psi/2) = eps (half-angle form, accurate also for tiny eps); no ball loaded for
    eps <= 0, all for eps >= 1."""
    if eps <= 0.0:
        return 0.0
    if eps >= 1.0:
        return math.pi
    return 2.0 * math.asin(math.sqrt(eps))


def radial_integral_direct(eps):
    """J_r(eps) = 1/(2 pi) int_{-psi_l}^{psi_l} [1 - (1 - cos psi)/(2 eps)]^1.5 cos psi dpsi, as printed.

    For eps >> 1 the integral is a small difference of O(1) contributions (J_r ~ 3/(8 eps)) and
    loses about log10(eps) digits: radial_integral uses the equivalent form without cancellation.
    """
    return _arc_integral(loaded_half_angle(eps), _ring_base(eps), _cos_weight(1.5), lambda: 1.0, DIRECT_OPTS)


def radial_integral(eps):
    """J_r(eps), integrated by parts so that the integrand is positive:

    with g = [1 - (1 - cos psi)/(2 eps)]^1.5, g' = -(3/(4 eps)) [.]^0.5 sin psi, and g sin psi = 0 at
    both ends of the loaded arc (g = 0 there, or psi = +-pi), int g cos = -int g' sin, so
      J_r = 1/(2 pi) (3/(4 eps)) int_{-psi_l}^{psi_l} [1 - (1 - cos psi)/(2 eps)]_+^0.5 sin^2 psi dpsi.
    1 - cos psi is written 2 sin^2(psi/2) (accurate for tiny eps); the arc is mapped to
    t = psi/psi_l in [-1, 1]. The unit tests check this against radial_integral_direct.
    """
    return _arc_integral(loaded_half_angle(eps), _ring_base(eps), _sin2_weight, lambda: 3.0 / (4.0 * eps), QUAD_OPTS)


def _ring_base(eps):
    """psi -> 1 - (1 - cos psi)/(2 eps), written 1 - sin^2(psi/2)/eps."""
    return lambda psi: 1.0 - math.sin(psi / 2.0) ** 2 / eps


def _cos_weight(exponent):
    """(psi, base) -> base^exponent cos psi: the integrand as printed."""
    return lambda psi, base: base**exponent * math.cos(psi)


def _sin2_weight(psi, base):
    """base^0.5 sin^2 psi: the integrand after integration by parts."""
    return base**0.5 * math.sin(psi) ** 2


def _arc_integral(psi_l, base, weight, factor, opts):
    """factor()/(2 pi) int_{-psi_l}^{psi_l} weight(psi, max(base(psi), 0)) dpsi, by quad with opts on
    t = psi/psi_l in [-1, 1]; 0 on an empty arc (psi_l = 0: factor is not evaluated)."""
    if psi_l == 0.0:
        return 0.0

    def integrand(t):
        psi = psi_l * t
        return weight(psi, max(base(psi), 0.0))

    value, _ = quad(integrand, -1.0, 1.0, **opts)
    return factor() * value * psi_l / (2.0 * math.pi)


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
    """Q_psi = Q_max [1 - (1 - cos psi)/(2 eps)]_+^1.5 (1 - cos psi = 2 sin^2(psi/2))."""
    base = 1.0 - math.sin(psi / 2.0) ** 2 / eps
    return Q_max * max(base, 0.0) ** 1.5


def _compression(psi, delta_r, Pd):
    """delta_r cos psi - P_d/2 written (delta_r - P_d/2) - 2 delta_r sin^2(psi/2): the first
    difference is exact when delta_r is close to P_d/2 (Sterbenz), the rest has no cancellation."""
    return (delta_r - Pd / 2.0) - 2.0 * delta_r * math.sin(psi / 2.0) ** 2


def _loaded_arc(delta_r, Pd):
    """Half-angle of the arc where delta_r cos psi > P_d/2 (0: no ball loaded, pi: all loaded):
    sin^2(psi_l/2) = (delta_r - P_d/2) / (2 delta_r)."""
    if delta_r - Pd / 2.0 <= 0.0:  # not even the ball at psi = 0 is compressed
        return 0.0
    if -delta_r - Pd / 2.0 > 0.0:  # even the ball at psi = pi is compressed
        return math.pi
    return 2.0 * math.asin(math.sqrt((delta_r - Pd / 2.0) / (2.0 * delta_r)))


def radial_force_direct(delta_r, Pd, K, Z):
    """F_r = Z/(2 pi) int K (delta_r cos psi - P_d/2)_+^1.5 cos psi dpsi as printed, by quad on
    t = psi/psi_l in [-1, 1] with the compression scaled by its peak delta_r - P_d/2. With preload
    and delta_r << |P_d| it is a small difference of large terms (see _radial_force)."""
    peak = delta_r - Pd / 2.0
    base = _peak_base(delta_r, Pd, peak)
    return _arc_integral(_loaded_arc(delta_r, Pd), base, _cos_weight(1.5), lambda: Z * K * peak**1.5, DIRECT_OPTS)


def _radial_force(delta_r, Pd, K, Z):
    """F_r integrated by parts (c = delta_r cos psi - P_d/2, dc/dpsi = -delta_r sin psi, c^1.5 sin psi
    = 0 at both arc ends): int c^1.5 cos psi = 1.5 delta_r int c_+^0.5 sin^2 psi, a positive integrand."""
    peak = delta_r - Pd / 2.0

    def factor():  # evaluated only on a loaded arc (peak > 0)
        return Z * K * 1.5 * delta_r * peak**0.5

    return _arc_integral(_loaded_arc(delta_r, Pd), _peak_base(delta_r, Pd, peak), _sin2_weight, factor, QUAD_OPTS)


def _peak_base(delta_r, Pd, peak):
    """psi -> the compression relative to its peak, (delta_r cos psi - P_d/2) / peak."""
    return lambda psi: _compression(psi, delta_r, Pd) / peak


def radial_force_and_slope(delta_r, Pd, K, Z):
    """(F_r, dF_r/d delta_r) of Z balls (continuum) at the inner-ring shift delta_r >= 0.

    F_r = Z/(2 pi) int K (delta_r cos psi - P_d/2)_+^1.5 cos psi dpsi; the slope is the integral of
    the delta_r-derivative, 1.5 K (.)_+^0.5 cos^2 psi (Leibniz: the integrand vanishes at the arc ends).
    """
    psi_l = _loaded_arc(delta_r, Pd)
    if psi_l == 0.0:
        return 0.0, 0.0
    peak = delta_r - Pd / 2.0

    def integrand(t):
        psi = psi_l * t
        return max(_compression(psi, delta_r, Pd) / peak, 0.0) ** 0.5 * math.cos(psi) ** 2

    value, _ = quad(integrand, -1.0, 1.0, **QUAD_OPTS)
    slope = 1.5 * Z * K * peak**0.5 * value * psi_l / (2.0 * math.pi)
    return _radial_force(delta_r, Pd, K, Z), slope


def solve_radial_shift(F_r, Pd, K, Z):
    """delta_r with F_r(delta_r) = F_r, by brentq on the quad force; F_r = 0 -> P_d/2 with clearance
    (balls just touching, the kernel's documented choice in the zero-force interval), 0 otherwise."""
    lo = max(Pd / 2.0, 0.0)
    if F_r <= 0.0:
        return lo
    # bracket: F_r(delta_r) <= Z K (delta_r - P_d/2)^1.5, so the root lies beyond lo + step; widen
    # the step by doubling until the force is reached
    step = (F_r / (Z * K)) ** (2.0 / 3.0)
    while _radial_force(lo + step, Pd, K, Z) < F_r:
        step *= 2.0
    return brentq(lambda d: _radial_force(d, Pd, K, Z) - F_r, lo, lo + step, xtol=1e-300, rtol=8.9e-16, maxiter=5000)


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.loaddist"
TWINS = {
    "gauss_legendre": gauss_legendre,
    "loaded_half_angle": loaded_half_angle,
    "radial_integral": radial_integral,
    "load_parameter": load_parameter,
    "stribeck_load": stribeck_load,
    "radial_force_and_slope": radial_force_and_slope,
    "solve_radial_shift": solve_radial_shift,
}
