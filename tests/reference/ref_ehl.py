"""Twin of bearing_fmu.kernels.ehl: EHL film, film parameter, regime, friction and damping.

Dimensionless groups on Rx (Hamrock & Dowson 1977): U = eta |u| / (E' Rx), G = xi E', W = Q / (E' Rx^2).
Film formulas as h / Rx, written out from the papers' expressions:
- Hamrock & Dowson (1977), ASME J. Lubr. Technol. 99, 264-276:
    H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^(-0.68 k)),  H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k));
- Masjedi & Khonsari (2015), Tribol. Int. 82, 228 (smooth surfaces; Farah 2020 eqs. 6 and 9):
    H_min = 1.637 U^(0.711 k^-0.023) G^(0.65 k^-0.045) W^(-0.09 k^-0.15) (1 - 0.974 e^(-0.676 k)),
    H_c   = 3.672 U^(0.663 k^-0.025) G^(0.502 k^-0.064) W^(-0.045 k^-0.18) (1 - 0.573 e^(-0.74 k));
- Chittenden, Dowson, Dunn & Taylor (1985) (Wheeler 2016 thesis eq. 2.2-4), entrainment along x:
    H_c = 4.31 U^0.68 G^0.49 W^-0.073 (1 - e^(-1.23 (Ry/Rx)^(2/3))),
    H_min = 3.68 U^0.68 G^0.49 W^-0.073 (1 - e^(-0.67 (Ry/Rx)^(2/3))).
Guessasma & Machado (2018): Lambda = h_min / sigma; regimes boundary (<= 1), mixed (]1, 3]), full
film (> 3); mu(Lambda) 0.1 -> 0.01 linear on ]1, 3]; damping eqs. 4-5 (series for mixed:
the text's 'parallel' is its formula's series combination).
"""

import math

import numpy as np

HAMROCK_DOWSON = 0  # same codes as kernels.ehl.FILM_* (checked by the unit test)
MASJEDI_KHONSARI = 1
CHITTENDEN = 2


def dimensionless_groups(eta, xi, E_red, u, Q, Rx):
    """(U, G, W) with the entrainment speed taken in magnitude."""
    U = eta * abs(u) / (E_red * Rx)
    G = xi * E_red
    W = Q / (E_red * Rx**2)
    return U, G, W


def film_hamrock_dowson(U, G, W, k):
    """(H_c, H_min) of Hamrock & Dowson (1977)."""
    H_c = 2.69 * U**0.67 * G**0.53 * W ** (-0.067) * (1.0 - 0.61 * math.exp(-0.73 * k))
    H_min = 3.63 * U**0.68 * G**0.49 * W ** (-0.073) * (1.0 - math.exp(-0.68 * k))
    return H_c, H_min


def film_masjedi_khonsari(U, G, W, k):
    """(H_c, H_min) of Masjedi & Khonsari (2015), smooth surfaces."""
    H_c = (
        3.672
        * U ** (0.663 * k ** (-0.025))
        * G ** (0.502 * k ** (-0.064))
        * W ** (-0.045 * k ** (-0.18))
        * (1.0 - 0.573 * math.exp(-0.74 * k))
    )
    H_min = (
        1.637
        * U ** (0.711 * k ** (-0.023))
        * G ** (0.65 * k ** (-0.045))
        * W ** (-0.09 * k ** (-0.15))
        * (1.0 - 0.974 * math.exp(-0.676 * k))
    )
    return H_c, H_min


def film_chittenden(U, G, W, Ry_over_Rx):
    """(H_c, H_min) of Chittenden et al. (1985), entrainment along x."""
    H_c = 4.31 * U**0.68 * G**0.49 * W ** (-0.073) * (1.0 - math.exp(-1.23 * Ry_over_Rx ** (2.0 / 3.0)))
    H_min = 3.68 * U**0.68 * G**0.49 * W ** (-0.073) * (1.0 - math.exp(-0.67 * Ry_over_Rx ** (2.0 / 3.0)))
    return H_c, H_min


def film_thickness(formula, eta, xi, E_red, u, Q, Rx, Ry, k):
    """(h_c, h_min) in m. An open contact (Q <= 0) has no film constraint: (inf, inf).

    No special case for rest: with u = 0 (or eta = 0) U = 0 and every formula gives 0 by itself.
    """
    if Q <= 0.0:
        return math.inf, math.inf
    U, G, W = dimensionless_groups(eta, xi, E_red, u, Q, Rx)
    if formula == HAMROCK_DOWSON:
        H_c, H_min = film_hamrock_dowson(U, G, W, k)
    elif formula == MASJEDI_KHONSARI:
        H_c, H_min = film_masjedi_khonsari(U, G, W, k)
    elif formula == CHITTENDEN:
        H_c, H_min = film_chittenden(U, G, W, Ry / Rx)
    else:
        raise ValueError(f"unknown film formula code {formula}")
    return H_c * Rx, H_min * Rx


def film_parameter(h_min, sigma):
    """Lambda = h_min / sigma. sigma = 0: inf for a real film; a zero film gives 0 (zero
    speed gives zero film and Lambda = 0, boundary), whatever the roughness."""
    if h_min == 0.0:
        return 0.0
    if sigma == 0.0:
        return math.inf
    return h_min / sigma


def lubrication_regime(lam):
    """0 boundary (Lambda <= 1), 1 mixed (1 < Lambda <= 3), 2 full film (Lambda > 3)."""
    if lam > 3.0:
        return 2
    if lam > 1.0:
        return 1
    return 0


def friction_coefficient(lam):
    """mu = 0.1 up to Lambda = 1, straight line to 0.01 at Lambda = 3, 0.01 beyond (np.interp clamps)."""
    return float(np.interp(lam, [1.0, 3.0], [0.1, 0.01]))


def traction_coefficient(lam, limit):
    """The papers' mu(Lambda) for limit <= 0; else 0.1 up to Lambda = 1, straight line to `limit` at 3, `limit`
    beyond."""
    if limit <= 0.0:
        return friction_coefficient(lam)
    return float(np.interp(lam, [1.0, 3.0], [0.1, limit]))


def film_share(lam):
    """0 up to Lambda = 1, straight line to 1 at Lambda = 3, 1 beyond (np.interp clamps)."""
    return float(np.interp(lam, [1.0, 3.0], [0.0, 1.0]))


def film_traction_coefficient(srr, mu_lim, s_0):
    """Bair & Winer's tau = tau_L (1 - exp(-eta gamma_dot / tau_L)) over the contact: mu_lim (1 - e^(-srr/s_0))."""
    return mu_lim * (1.0 - math.exp(-srr / s_0))


def film_slip_speed(s_0, u, spin, a_major):
    """max(s_0 u, (8 / (3 pi)) |spin| a): the creep scale or the linearised traction of a saturated spinning circle,
    whose net force per unit slip is (1/(2|spin|)) int(mu_lim p / r dA) = mu_lim Q 3 pi / (8 a |spin|)."""
    return max(s_0 * u, 8.0 / (3.0 * math.pi) * abs(spin) * a_major)


def normal_damping(lam, Q, alpha_e, eta, a_major, R_ball, h_min):
    """C_n (N s/m). Hysteretic C_h = 1.5 alpha_e K_n delta with K_n = Q/delta (secant), so C_h =
    1.5 alpha_e Q; fluid C_f = (3 pi eta a / sqrt 2)(R_b/h_min)^1.5. Boundary (or no film): C_h;
    full film: C_f; mixed: the two in series, 1/C = 1/C_h + 1/C_f."""
    K_n_delta = Q
    C_h = 1.5 * alpha_e * K_n_delta
    regime = lubrication_regime(lam)
    if regime == 0 or h_min <= 0.0:
        return C_h
    C_f = 3.0 * math.pi * eta * a_major / math.sqrt(2.0) * (R_ball / h_min) ** 1.5
    if regime == 2:
        return C_f
    return 1.0 / (1.0 / C_h + 1.0 / C_f)


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.ehl"
TWINS = {
    "dimensionless_groups": dimensionless_groups,
    "film_hamrock_dowson": film_hamrock_dowson,
    "film_masjedi_khonsari": film_masjedi_khonsari,
    "film_chittenden": film_chittenden,
    "film_thickness": film_thickness,
    "film_parameter": film_parameter,
    "lubrication_regime": lubrication_regime,
    "friction_coefficient": friction_coefficient,
    "traction_coefficient": traction_coefficient,
    "film_share": film_share,
    "film_traction_coefficient": film_traction_coefficient,
    "film_slip_speed": film_slip_speed,
    "normal_damping": normal_damping,
}
