"""EHL film thickness, film parameter, lubrication regime, friction coefficient and normal damping.

Dimensionless groups on Rx (Hamrock & Dowson 1977):
  U = eta u / (E' Rx),  G = xi E',  W = Q / (E' Rx^2).
Film formulas (smooth surfaces, isothermal, fully flooded), all as h / Rx:
- Hamrock & Dowson (1977), ASME J. Lubr. Technol. 99, 264:
    H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)),
    H_c   = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k));
- Masjedi & Khonsari (2015), Tribol. Int. 82, 228 (smooth part; Farah 2020 eqs. 6 and 9):
    H_min = 1.637 U^(0.711 k^-0.023) G^(0.65 k^-0.045) W^(-0.09 k^-0.15) (1 - 0.974 exp(-0.676 k)),
    H_c   = 3.672 U^(0.663 k^-0.025) G^(0.502 k^-0.064) W^(-0.045 k^-0.18) (1 - 0.573 exp(-0.74 k));
- Chittenden, Dowson, Dunn & Taylor (1985), Proc. R. Soc. A 397 (Wheeler 2016 thesis eq. 2.2-4),
  entrainment along x, valid for either ellipse orientation:
    H_c   = 4.31 U^0.68 G^0.49 W^-0.073 (1 - exp(-1.23 (Ry/Rx)^(2/3))),
    H_min = 3.68 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.67 (Ry/Rx)^(2/3))).
k is the ellipticity a_y / b_x of the Hertz contact.
"""

import math

from bearing_fmu_common.jit import kernel

FILM_HAMROCK_DOWSON = 0
FILM_MASJEDI_KHONSARI = 1
FILM_CHITTENDEN = 2

REGIME_BOUNDARY = 0
REGIME_MIXED = 1
REGIME_FULL_FILM = 2


@kernel
def dimensionless_groups(eta, xi, E_red, u, Q, Rx):
    """(U, G, W) (-) for viscosity eta (Pa.s), pressure-viscosity xi (1/Pa), E' (Pa),
    entrainment speed u (m/s, magnitude used), load Q (N) and radius Rx (m)."""
    return eta * abs(u) / (E_red * Rx), xi * E_red, Q / (E_red * Rx * Rx)


@kernel
def film_hamrock_dowson(U, G, W, k):
    """Hamrock-Dowson (H_c, H_min) = (h_c/Rx, h_min/Rx) (-)."""
    h_min = 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1.0 - math.exp(-0.68 * k))
    h_c = 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1.0 - 0.61 * math.exp(-0.73 * k))
    return h_c, h_min


@kernel
def film_masjedi_khonsari(U, G, W, k):
    """Masjedi-Khonsari smooth-surface (H_c, H_min) (-)."""
    h_min = (
        1.637
        * U ** (0.711 * k**-0.023)
        * G ** (0.65 * k**-0.045)
        * W ** (-0.09 * k**-0.15)
        * (1.0 - 0.974 * math.exp(-0.676 * k))
    )
    h_c = (
        3.672
        * U ** (0.663 * k**-0.025)
        * G ** (0.502 * k**-0.064)
        * W ** (-0.045 * k**-0.18)
        * (1.0 - 0.573 * math.exp(-0.74 * k))
    )
    return h_c, h_min


@kernel
def film_chittenden(U, G, W, Ry_over_Rx):
    """Chittenden et al. (H_c, H_min) (-) for entrainment along x."""
    base = U**0.68 * G**0.49 * W**-0.073
    r = Ry_over_Rx ** (2.0 / 3.0)
    return 4.31 * base * (1.0 - math.exp(-1.23 * r)), 3.68 * base * (1.0 - math.exp(-0.67 * r))


@kernel
def film_thickness(formula, eta, xi, E_red, u, Q, Rx, Ry, k):
    """Central and minimum film thickness (h_c, h_min) in m of one contact.

    formula: FILM_HAMROCK_DOWSON | FILM_MASJEDI_KHONSARI | FILM_CHITTENDEN. A contact at rest (u = 0)
    has no film (0, 0); an open contact (Q <= 0) has no film constraint (inf, inf).
    """
    if Q <= 0.0:
        return math.inf, math.inf
    if u == 0.0 or eta <= 0.0:
        return 0.0, 0.0
    U, G, W = dimensionless_groups(eta, xi, E_red, u, Q, Rx)
    if formula == FILM_MASJEDI_KHONSARI:
        hc, hm = film_masjedi_khonsari(U, G, W, k)
    elif formula == FILM_CHITTENDEN:
        hc, hm = film_chittenden(U, G, W, Ry / Rx)
    else:
        hc, hm = film_hamrock_dowson(U, G, W, k)
    return hc * Rx, hm * Rx


@kernel
def film_parameter(h_min, sigma):
    """Film parameter Lambda = h_min / sigma (-); sigma (m) composite roughness.

    No film (h_min = 0, e.g. at rest) gives 0 (boundary, no division by zero) even on ideally smooth
    surfaces; a film on ideally smooth surfaces (sigma = 0) gives inf.
    """
    if h_min <= 0.0:
        return 0.0
    if sigma <= 0.0:
        return math.inf
    return h_min / sigma


@kernel
def lubrication_regime(lam):
    """Regime code: 0 boundary (Lambda <= 1), 1 mixed (1 < Lambda <= 3), 2 full film (Lambda > 3)."""
    if lam <= 1.0:
        return REGIME_BOUNDARY
    if lam <= 3.0:
        return REGIME_MIXED
    return REGIME_FULL_FILM


@kernel
def friction_coefficient(lam):
    """Coulomb coefficient mu(Lambda) (-): 0.1 for Lambda <= 1, linear to 0.01 on ]1, 3], 0.01 above
    (Guessasma & Machado 2018, section 2.3)."""
    if lam <= 1.0:
        return 0.1
    if lam <= 3.0:
        return 0.1 - 0.045 * (lam - 1.0)
    return 0.01


@kernel
def traction_coefficient(lam, limit):
    """Coulomb limit of the DEM's tangential force (-): the papers' mu(Lambda) (friction_coefficient) for
    limit <= 0; otherwise 0.1 for Lambda <= 1, linear to `limit` on ]1, 3] and `limit` above: a full film that
    carries up to the lubricant's limiting traction coefficient instead of the papers' 0.01."""
    if limit <= 0.0:
        return friction_coefficient(lam)
    if lam <= 1.0:
        return 0.1
    if lam <= 3.0:
        return 0.1 + 0.5 * (limit - 0.1) * (lam - 1.0)
    return limit


SPIN_SLIP = 8.0 / (3.0 * math.pi)  # film_slip_speed: linearised traction of a saturated spinning Hertz circle


@kernel
def film_share(lam):
    """Share (-) of a contact's tangential force carried by the film: 0 for Lambda <= 1 (asperities carry
    the load), linear to 1 on ]1, 3] (the ramp of friction_coefficient), 1 above (full film)."""
    if lam <= 1.0:
        return 0.0
    if lam <= 3.0:
        return 0.5 * (lam - 1.0)
    return 1.0


@kernel
def film_traction_coefficient(srr, mu_lim, s_0):
    """Traction coefficient (-) of an EHL film at slide-to-roll ratio srr (-): mu_lim (1 - exp(-srr / s_0)).

    The limiting-shear-stress law of Bair & Winer (1979, J. Lubr. Technol. 101(3) 258-265),
    tau = tau_L (1 - exp(-eta gamma_dot / tau_L)), taken over the whole contact: the film's shear rate is the
    sliding speed over the film, gamma_dot = srr u / h, so the curve rises linearly at small slip (a viscous
    film: a damper, slope mu_lim / s_0) and saturates at the limiting traction coefficient mu_lim = tau_L / p
    (lubricant file). s_0 (-) is the slide-to-roll ratio where the linear part meets the limit."""
    return -mu_lim * math.expm1(-srr / s_0)


@kernel
def film_slip_speed(s_0, u, spin, a_major):
    """Sliding speed (m/s) that scales a contact's traction curve mu_lim (1 - exp(-v_t / v_s)) in the sliding
    speed v_t of its centre: the creep scale s_0 u (u entrainment speed, m/s), or, where the contact spins at
    `spin` (rad/s) relative to the race, (8 / (3 pi)) |spin| a (a: semi-major axis, m) if larger.

    Why: across a spinning contact the surfaces already slide at |spin| r, saturating the traction locally; a
    small uniform slip v_t then changes the net force only by dF/dv_t = (1/(2 |spin|)) integral(tau_L / r dA)
    (the component of the local unit slip direction along v_t averages 1/2 over the angle); with tau_L = mu_lim p
    and the Hertz pressure of a circle of radius a this is F_max 3 pi / (8 a |spin|), F_max = mu_lim Q (the
    spin creep of rolling contacts, Johnson 1985, Contact Mechanics, ch. 8). A contact that pivots therefore
    grips a transverse slip far less than one that rolls: the race without spin controls the ball."""
    return max(s_0 * u, SPIN_SLIP * abs(spin) * a_major)


@kernel
def normal_damping(lam, Q, alpha_e, eta, a_major, R_ball, h_min):
    """Normal damping C_n(Lambda) (N.s/m) of one contact (Guessasma & Machado 2018, eqs. 4-5, Table 2).

    C_hyst = 1.5 alpha_e K_n delta = 1.5 alpha_e Q (K_n delta is the elastic force Q, N; alpha_e in s/m);
    C_fluid = (3 pi eta a / sqrt 2) (R_b / h_min)^1.5 (a: semi-major axis, m; R_b: ball radius, m).
    Boundary: C_hyst; mixed: series (C_hyst^-1 + C_fluid^-1)^-1 (the text's 'parallel' is its
    formula's series combination, docs/decisions.md); full film: C_fluid.
    """
    c_hyst = 1.5 * alpha_e * Q
    regime = lubrication_regime(lam)
    if regime == REGIME_BOUNDARY or h_min <= 0.0:
        return c_hyst
    ratio = R_ball / h_min
    c_fluid = 3.0 * math.pi * eta * a_major / math.sqrt(2.0) * ratio * math.sqrt(ratio)  # x^1.5: sqrt, not pow
    if regime == REGIME_FULL_FILM:
        return c_fluid
    return c_hyst * c_fluid / (c_hyst + c_fluid)
