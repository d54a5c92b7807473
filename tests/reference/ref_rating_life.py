"""Twin of bearing_fmu.kernels.rating_life: ISO 281 basic rating life and ISO/TS 16281-style reference life.

Written from the formulas (ISO 281:2007 clause 5; Lundberg-Palmgren contact ratings and race lives as in
ISO/TS 16281 and Harris & Kotzalas 2006), not from the kernel: the tables are read with numpy.interp, the
sums with numpy, the Hertz bracket from the curvature sum. The tables themselves (f_c, X, Y, e) are the
kernel's: the twin checks how they are used; tests/unit/test_rating_life.py checks the f_c table against
the Lundberg-Palmgren shape.
"""

import math

import numpy as np

from bearing_fmu.kernels import rating_life as rl
from tests.reference.ref_torque import iso76_f0, iso76_static_rating

FC_GAMMA = np.arange(1, len(rl.FC_TABLE) + 1) * 0.01


def _interpolate(x, xs, ys):
    """np.interp: linear, clamped to the end values."""
    return float(np.interp(x, xs, ys))


def iso281_fc(gamma):
    """f_c (N/mm^1.8) from ISO 281 Table 2 at gamma."""
    return float(np.interp(gamma, FC_GAMMA, rl.FC_TABLE))


def _ball_size_term(D):
    """D_w^1.8 up to 25.4 mm, 3.647 D_w^1.4 above (D_w in mm)."""
    d = D * 1e3
    return d**1.8 if d <= 25.4 else 3.647 * d**1.4


def iso281_dynamic_rating(Z, D, dm, alpha):
    """C_r = b_m f_c (cos alpha)^0.7 Z^(2/3) D_w^1.8 (N), one row."""
    c = math.cos(alpha)
    return 1.3 * iso281_fc(D * c / dm) * c**0.7 * Z ** (2.0 / 3.0) * _ball_size_term(D)


def iso281_factors(angular, alpha_deg, load_ratio):
    """(X, Y, e) for F_a/F_r > e: radial-contact row, or the rows of 0 (radial contact), 15, 20, ..., 45 deg
    interpolated in the angle."""
    if not angular:
        return (
            rl.RADIAL_X,
            _interpolate(load_ratio, rl.RADIAL_LOAD_RATIO, rl.RADIAL_Y),
            _interpolate(load_ratio, rl.RADIAL_LOAD_RATIO, rl.RADIAL_E),
        )
    angles = (0.0, 15.0, *rl.AC_ALPHA)
    radial_Y = _interpolate(load_ratio, rl.RADIAL_LOAD_RATIO, rl.RADIAL_Y)
    radial_e = _interpolate(load_ratio, rl.RADIAL_LOAD_RATIO, rl.RADIAL_E)
    X = np.interp(alpha_deg, angles, (rl.RADIAL_X, rl.AC15_X, *rl.AC_X))
    Y = np.interp(alpha_deg, angles, (radial_Y, _interpolate(load_ratio, rl.AC15_LOAD_RATIO, rl.AC15_Y), *rl.AC_Y))
    e = np.interp(alpha_deg, angles, (radial_e, _interpolate(load_ratio, rl.AC15_LOAD_RATIO, rl.AC15_E), *rl.AC_E))
    return float(X), float(Y), float(e)


def equivalent_dynamic_load(F_r, F_a, lp):
    """P = F_r if F_a/F_r <= e else X F_r + Y F_a."""
    if F_a <= 0.0:
        return F_r
    X, Y, e = iso281_factors(lp[rl.LP_ANGULAR] > 0.5, lp[rl.LP_ALPHA_DEG], lp[rl.LP_F_0] * F_a / lp[rl.LP_C_0R])
    return F_r if F_a <= e * F_r else X * F_r + Y * F_a


def contact_ratings(Z, D, dm, f_i, f_o, alpha):
    """Q_c = 93.2 b_m (2f/(2f-1))^0.41 (1 -/+ g)^1.39 (1 +/- g)^(-1/3) (g/cos a)^0.3 D_w^1.8 Z^(-1/3) (N)."""
    g = D * math.cos(alpha) / dm

    def rating(f, sign):
        return (
            93.2
            * 1.3
            * (2.0 * f / (2.0 * f - 1.0)) ** 0.41
            * (1.0 - sign * g) ** 1.39
            * (1.0 + sign * g) ** (-1.0 / 3.0)
            * (g / math.cos(alpha)) ** 0.3
            * _ball_size_term(D)
            / Z ** (1.0 / 3.0)
        )

    return rating(f_i, 1.0), rating(f_o, -1.0)


def equivalent_contact_load(Q, exponent):
    """Power mean of the contact loads (unloaded balls count as 0)."""
    Q = np.clip(np.asarray(Q, dtype=float), 0.0, None)
    return float(np.mean(Q**exponent) ** (1.0 / exponent))


def life_revolutions(rating, load, exponent):
    """1e6 (rating/load)^p revolutions, capped."""
    return rl.LIFE_INFINITE if load <= 0.0 else min(1e6 * (rating / load) ** exponent, rl.LIFE_INFINITE)


def combined_life(L_i, L_e):
    """Weibull combination of two race lives, slope 10/9; an infinite race life (the cap) counts as infinite."""
    finite = [L for L in (L_i, L_e) if L < rl.LIFE_INFINITE]
    if not finite:
        return rl.LIFE_INFINITE
    return min(sum(L ** (-10.0 / 9.0) for L in finite) ** (-0.9), rl.LIFE_INFINITE)


def life_hours(revolutions, omega):
    """Revolutions / (n rpm x 60), capped; at rest the cap."""
    if omega == 0.0 or revolutions >= rl.LIFE_INFINITE:
        return rl.LIFE_INFINITE
    rpm = abs(omega) * 60.0 / (2.0 * math.pi)
    return min(revolutions / (60.0 * rpm), rl.LIFE_INFINITE)


def rating_parameters(angular, Z, D, dm, f_i, f_o, alpha, lp):
    lp[rl.LP_C_R] = iso281_dynamic_rating(Z, D, dm, alpha)
    lp[rl.LP_C_0R] = iso76_static_rating(Z, D, dm, alpha)
    lp[rl.LP_F_0] = iso76_f0(D * math.cos(alpha) / dm)
    lp[rl.LP_ANGULAR] = angular
    lp[rl.LP_ALPHA_DEG] = alpha * 180.0 / math.pi
    lp[rl.LP_Q_CI], lp[rl.LP_Q_CE] = contact_ratings(Z, D, dm, f_i, f_o, alpha)


def rating_life(Q_inner, Q_outer, F_r, F_a, omega, lp, out):
    P = equivalent_dynamic_load(F_r, F_a, lp)
    out[rl.LO_L10] = life_revolutions(lp[rl.LP_C_R], P, 3.0)
    L_i = life_revolutions(lp[rl.LP_Q_CI], equivalent_contact_load(Q_inner, 3.0), 3.0)
    L_e = life_revolutions(lp[rl.LP_Q_CE], equivalent_contact_load(Q_outer, 10.0 / 3.0), 3.0)
    out[rl.LO_L10R] = combined_life(L_i, L_e)
    out[rl.LO_L10_H] = life_hours(out[rl.LO_L10], omega)
    out[rl.LO_L10R_H] = life_hours(out[rl.LO_L10R], omega)


def iso16281_spring_constant(Rx, Ry, E_red, k_yx, ell_E, ell_K):
    """1.48 E' (K (sum rho / (k^2 E))^(1/3))^(-3/2)."""
    k = max(k_yx, 1.0 / k_yx)
    return 1.48 * E_red * (ell_K * ((1.0 / Rx + 1.0 / Ry) / (k**2 * ell_E)) ** (1.0 / 3.0)) ** -1.5


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.rating_life"
TWINS = {
    "_interpolate": _interpolate,
    "iso281_fc": iso281_fc,
    "_ball_size_term": _ball_size_term,
    "iso281_dynamic_rating": iso281_dynamic_rating,
    "iso281_factors": iso281_factors,
    "equivalent_dynamic_load": equivalent_dynamic_load,
    "contact_ratings": contact_ratings,
    "equivalent_contact_load": equivalent_contact_load,
    "life_revolutions": life_revolutions,
    "combined_life": combined_life,
    "life_hours": life_hours,
    "rating_parameters": rating_parameters,
    "rating_life": rating_life,
    "iso16281_spring_constant": iso16281_spring_constant,
}
