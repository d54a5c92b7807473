"""Twin of bearing_fmu.kernels.hertz: Hertz point contact, exact and Hamrock-Brewe.

Exact solution (Johnson 1985, Contact Mechanics, eqs. 3.63-3.64; Hamrock & Dowson 1981, ch. 3;
Harris & Kotzalas 2006, ch. 6): with the ellipticity k = major/minor >= 1, m = 1 - 1/k^2 and the
complete elliptic integrals K(m), E(m) (scipy.special.ellipk / ellipe, which take the parameter
m = e^2), k solves  Ry/Rx = (k^2 E(m) - K(m)) / (K(m) - E(m))  (for Ry >= Rx; otherwise solve with
the radii swapped and invert k), here by scipy.optimize.brentq on the cancellation-free Carlson
form of the same relation (see hertz_ratio). Contact size, approach and pressure:
  a = (6 k^2 E Q R / (pi E'))^(1/3),  b = (6 E Q R / (pi k E'))^(1/3),
  delta = K [ (9 / (2 E R)) (Q / (pi k E'))^2 ]^(1/3),  p_max = 3 Q / (2 pi a b),
with R = 1 / (1/Rx + 1/Ry). Hamrock & Brewe (1983): k = alpha^(2/pi), E = 1 + q/alpha,
K = pi/2 + q ln alpha, q = pi/2 - 1 (Guessasma 2018 and Farah 2020 print 1 + q ln alpha: a typesetting error,
docs/decisions.md).
"""

import math

from scipy.optimize import brentq
from scipy.special import ellipe, ellipk, elliprd


def reduced_modulus(E1, nu1, E2, nu2):
    """E' from 2/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2."""
    return 1.0 / (0.5 * ((1.0 - nu1**2) / E1 + (1.0 - nu2**2) / E2))


def elliptic_integrals(m):
    """(K(m), E(m)) from scipy.special (parameter m = e^2)."""
    return float(ellipk(m)), float(ellipe(m))


def hertz_ratio_textbook(k):
    """Ry/Rx = (k^2 E(m) - K(m)) / (K(m) - E(m)), m = 1 - 1/k^2, as printed (k > 1).

    Ill-conditioned at both ends: numerator and denominator vanish like m as k -> 1 (about
    log10(1/m) digits lost: 6e-9 relative at Ry/Rx = 1 + 1e-9), and for large k the rounding of
    m = 1 - 1/k^2 perturbs 1 - m, on which K depends logarithmically (3e-11 at k = 1000).
    The solve therefore uses hertz_ratio; the unit tests tie the two together in between.
    """
    m = 1.0 - 1.0 / k**2
    K = ellipk(m)
    E = ellipe(m)
    return (k**2 * E - K) / (K - E)


def hertz_ratio(k):
    """The same Hertz relation in Carlson's symmetric form, well conditioned for every k >= 1.

    With q = 1 - m = 1/k^2 (DLMF 19.25.1): K = R_F(0, q, 1), K - E = (m/3) R_D(0, q, 1) and
    E - q K = (m q / 3) R_D(0, 1, q), hence k^2 E - K = (E - q K)/q = (m/3) R_D(0, 1, q) and
    Ry/Rx = R_D(0, 1, q) / R_D(0, q, 1)  (= 1 at k = 1): no difference of nearly equal numbers,
    and q = 1/k^2 is passed without forming 1 - m.
    """
    q = 1.0 / k**2
    return float(elliprd(0.0, 1.0, q) / elliprd(0.0, q, 1.0))


def ellipticity_exact(Rx, Ry):
    """Exact major/minor ellipticity k >= 1 of the contact, by brentq on the Hertz relation."""
    ratio = max(Rx, Ry) / min(Rx, Ry)
    if ratio == 1.0:
        return 1.0
    # k lies in ]1, ratio]: the Hertz ellipse is less elongated than the gap (k ~ ratio^(2/pi))
    return brentq(lambda k: hertz_ratio(k) - ratio, 1.0, ratio, xtol=1e-300, rtol=8.9e-16, maxiter=500)


def hertz_coefficients_exact(Rx, Ry):
    """(k_yx, E, K): k_yx = a_y / b_x (> 1 when Ry > Rx), elliptic integrals at m = 1 - 1/k^2."""
    k = ellipticity_exact(Rx, Ry)
    K, E = elliptic_integrals(1.0 - 1.0 / k**2)
    k_yx = k if Ry >= Rx else 1.0 / k
    return k_yx, E, K


def hertz_coefficients_approx(Rx, Ry):
    """Hamrock-Brewe (k_yx, E, K)."""
    alpha = max(Rx, Ry) / min(Rx, Ry)
    q = math.pi / 2.0 - 1.0
    k = alpha ** (2.0 / math.pi)
    E = 1.0 + q / alpha
    K = math.pi / 2.0 + q * math.log(alpha)
    k_yx = k if Ry >= Rx else 1.0 / k
    return k_yx, E, K


def hertz_contact(Q, Rx, Ry, E_red, k_yx, ell_E, ell_K):
    """(a_y, b_x, delta, p_max) under load Q; open contact (Q <= 0) -> zeros.

    The major semi-axis lies along the larger reduced radius: along y if k_yx >= 1, along x otherwise.
    """
    if Q <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    R = 1.0 / (1.0 / Rx + 1.0 / Ry)
    k = max(k_yx, 1.0 / k_yx)
    major = (6.0 * k**2 * ell_E * Q * R / (math.pi * E_red)) ** (1.0 / 3.0)
    minor = (6.0 * ell_E * Q * R / (math.pi * k * E_red)) ** (1.0 / 3.0)
    delta = ell_K * ((9.0 / (2.0 * ell_E * R)) * (Q / (math.pi * k * E_red)) ** 2) ** (1.0 / 3.0)
    p_max = 3.0 * Q / (2.0 * math.pi * major * minor)
    if k_yx >= 1.0:
        return major, minor, delta, p_max
    return minor, major, delta, p_max


def hertz_stiffness(Rx, Ry, E_red, k_yx, ell_E, ell_K):
    """K_h of Q = K_h delta^1.5, read off the contact solution at Q = 1 N (delta ~ Q^(2/3) exactly)."""
    delta = hertz_contact(1.0, Rx, Ry, E_red, k_yx, ell_E, ell_K)[2]
    return 1.0 / delta**1.5


def series_stiffness(K1, K2):
    """K of two contacts in series: same load Q = 1 N, approaches add, K = Q / (d1 + d2)^1.5."""
    d1 = (1.0 / K1) ** (2.0 / 3.0)
    d2 = (1.0 / K2) ** (2.0 / 3.0)
    return 1.0 / (d1 + d2) ** 1.5


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.hertz"
TWINS = {
    "reduced_modulus": reduced_modulus,
    "elliptic_integrals": elliptic_integrals,
    "hertz_coefficients_exact": hertz_coefficients_exact,
    "hertz_coefficients_approx": hertz_coefficients_approx,
    "hertz_contact": hertz_contact,
    "hertz_stiffness": hertz_stiffness,
    "series_stiffness": series_stiffness,
}
