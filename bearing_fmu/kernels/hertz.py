"""Hertz point contact: exact (complete elliptic integrals) and Hamrock-Brewe approximate.

SI units. Conventions (Hamrock & Dowson 1981, ch. 3):
- x is the rolling/entrainment direction, y the transverse one. Rx, Ry are the reduced radii of
  curvature of the gap (1/Rx = 1/R1x + 1/R2x, concave radii negative before reduction).
- ``k_yx`` = a_y / b_x: semi-axis along y over semi-axis along x (> 1 for a ball-race contact).
- E_red is Hamrock's E' = 2 / [(1-nu1^2)/E1 + (1-nu2^2)/E2] (= E/(1-nu^2) steel on steel).

The contact size uses the ellipticity k (major/minor, >= 1), the complete elliptic integral of the
second kind E(m) and of the first kind K(m), m = 1 - 1/k^2 (Hamrock & Dowson 1981, ch. 3;
Harris & Kotzalas 2006, ch. 6):
  a = (6 k^2 E Q R / (pi E'))^(1/3),  b = (6 E Q R / (pi k E'))^(1/3),
  delta = K [ (9 / (2 E R)) (Q / (pi k E'))^2 ]^(1/3),  p_max = 3 Q / (2 pi a b),
with R = Rx Ry / (Rx + Ry).  The exact k solves Ry/Rx = (k^2 E - K) / (K - E)
(Johnson 1985, Contact Mechanics, eqs. 3.63-3.64).  Hamrock & Brewe (1983): k = alpha^(2/pi),
E = 1 + q/alpha, K = pi/2 + q ln(alpha), q = pi/2 - 1, alpha = Ry/Rx >= 1 (Guessasma 2018 and
Farah 2020 print 1 + q ln alpha: a typesetting error, docs/decisions.md).
"""

import math

from bearing_fmu_common.jit import kernel

HALF_PI = 0.5 * math.pi
Q_HB = HALF_PI - 1.0


@kernel
def reduced_modulus(E1, nu1, E2, nu2):
    """Hamrock's reduced modulus E' (Pa) of two elastic bodies (E in Pa, nu dimensionless)."""
    return 2.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2)


@kernel
def elliptic_integrals(m):
    """Complete elliptic integrals (K(m), E(m)) of parameter m = e^2 in [0, 1), by the AGM.

    Converges quadratically; accurate to machine precision (checked against scipy.special).
    """
    a = 1.0
    b = math.sqrt(1.0 - m)
    c2_sum = 0.5 * m  # sum of 2^(n-1) c_n^2 with c_0^2 = m
    power = 0.5
    for _ in range(40):
        c = 0.5 * (a - b)
        if abs(c) < 1e-17 * a:
            break
        a_next = 0.5 * (a + b)
        b = math.sqrt(a * b)
        a = a_next
        power *= 2.0
        c2_sum += power * c * c
    K = HALF_PI / a
    return K, K * (1.0 - c2_sum)


@kernel
def _radius_ratio_of_ellipticity(k):
    """Ry/Rx produced by an ellipticity k >= 1 (exact Hertz relation)."""
    if k <= 1.0:
        return 1.0
    m = 1.0 - 1.0 / (k * k)
    K, E = elliptic_integrals(m)
    return (k * k * E - K) / (K - E)


@kernel
def _ellipticity_exact_major(alpha):
    """Exact ellipticity k >= 1 for a curvature ratio alpha = R_long/R_short >= 1 (bisection on ln k)."""
    if alpha <= 1.0 + 1e-12:
        return 1.0
    lo = 0.0
    hi = math.log(alpha) + 1.0  # k < alpha for alpha > 1
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if _radius_ratio_of_ellipticity(math.exp(mid)) < alpha:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-15:
            break
    return math.exp(0.5 * (lo + hi))


@kernel
def hertz_coefficients_exact(Rx, Ry):
    """Exact Hertz coefficients for reduced radii Rx, Ry (m).

    Returns (k_yx, ell_E, ell_K): k_yx = a_y/b_x (-), and the complete elliptic integrals of the
    second and first kind (-) at the ellipticity of the contact.
    """
    alpha = Ry / Rx
    flip = alpha < 1.0
    if flip:
        alpha = 1.0 / alpha
    k = _ellipticity_exact_major(alpha)
    if k == 1.0:
        return 1.0, HALF_PI, HALF_PI
    K, E = elliptic_integrals(1.0 - 1.0 / (k * k))
    if flip:
        k = 1.0 / k
    return k, E, K


@kernel
def hertz_coefficients_approx(Rx, Ry):
    """Hamrock-Brewe approximate coefficients (k_yx, ell_E, ell_K), same meaning as the exact ones."""
    alpha = Ry / Rx
    flip = alpha < 1.0
    if flip:
        alpha = 1.0 / alpha
    k = alpha ** (2.0 / math.pi)
    E = 1.0 + Q_HB / alpha
    K = HALF_PI + Q_HB * math.log(alpha)
    if flip:
        k = 1.0 / k
    return k, E, K


@kernel
def hertz_contact(Q, Rx, Ry, E_red, k_yx, ell_E, ell_K):
    """Hertz contact under normal load Q (N).

    Returns (a_y, b_x, delta, p_max): semi-axes along y and x (m), normal approach (m), maximum
    pressure (Pa). Q <= 0 gives an open contact (all zeros).
    """
    if Q <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    R = Rx * Ry / (Rx + Ry)
    k = k_yx if k_yx >= 1.0 else 1.0 / k_yx
    major = (6.0 * k * k * ell_E * Q * R / (math.pi * E_red)) ** (1.0 / 3.0)
    minor = (6.0 * ell_E * Q * R / (math.pi * k * E_red)) ** (1.0 / 3.0)
    t = Q / (math.pi * k * E_red)
    delta = ell_K * (4.5 / (ell_E * R) * t * t) ** (1.0 / 3.0)
    if major * minor <= 0.0:
        return 0.0, 0.0, 0.0, 0.0  # a load so small (< ~1e-300 N) that the contact area underflows
    p_max = 1.5 * Q / (math.pi * major * minor)
    if k_yx >= 1.0:
        return major, minor, delta, p_max
    return minor, major, delta, p_max


@kernel
def hertz_stiffness(Rx, Ry, E_red, k_yx, ell_E, ell_K):
    """Load-deflection constant K_h (N/m^1.5) of Q = K_h delta^1.5 (secant stiffness K_h delta^0.5)."""
    R = Rx * Ry / (Rx + Ry)
    k = k_yx if k_yx >= 1.0 else 1.0 / k_yx
    return math.pi * k * E_red * math.sqrt(2.0 * ell_E * R / (9.0 * ell_K**3))


@kernel
def series_stiffness(K1, K2):
    """Load-deflection constant (N/m^1.5) of two Hertz contacts in series (same load, approaches add)."""
    return (K1 ** (-2.0 / 3.0) + K2 ** (-2.0 / 3.0)) ** -1.5
