"""Rating life of a ball bearing: ISO 281 basic rating life and the ISO/TS 16281 reference rating life.

Basic rating life (ISO 281:2007, clause 5, radial ball bearings): the basic dynamic radial load rating
C_r = b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.8 (D_w <= 25.4 mm; 3.647 b_m f_c (i cos alpha)^0.7 Z^(2/3)
D_w^1.4 above, D_w in mm, C_r in N), the dynamic equivalent radial load P = X F_r + Y F_a (Table 3: X, Y
and e by f_0 F_a / C_0r, C_0r and f_0 from ISO 76, kernels.torque) and L10 = (C_r/P)^3 in 10^6
revolutions. C_a (thrust ball bearings, alpha > 45 deg) does not apply to the radial bearings modelled.

Reference rating life in the manner of ISO/TS 16281:2008 (Lundberg-Palmgren theory on the computed
contact loads, Harris & Kotzalas 2006, *Advanced Concepts of Bearing Technology*, ch. on fatigue life):
- basic dynamic load rating of one contact, inner (upper signs) and outer race (lower signs),
  Q_c = A b_m (2f/(2f - 1))^0.41 (1 -/+ gamma)^1.39 / (1 +/- gamma)^(1/3) (gamma/cos alpha)^0.3
  D_w^1.8 Z^(-1/3) (N, D_w in mm; the D_w > 25.4 mm branch of ISO 281 carried over), A = 93.2 N/mm^1.8;
- dynamic equivalent contact loads from the per-ball loads Q_j: the race that rotates relative to the load
  (the inner race: inner ring turning, load fixed) Q_ei = (sum Q_ij^3 / Z)^(1/3); the race that is
  stationary relative to the load (outer) Q_ee = (sum Q_ej^(10/3) / Z)^(3/10);
- race lives L_i = (Q_ci/Q_ei)^3, L_e = (Q_ce/Q_ee)^3 (10^6 rev) and the bearing's
  L10r = (L_i^(-e) + L_e^(-e))^(-1/e), e = 10/9 (Weibull slope of ball bearings).
The constants A, b_m and the f_c, X, Y, e tables could not be checked against the printed standards:
docs/decisions.md (unverified sources) says how each was cross-checked, docs/rating_life.md shows the
validation. The standard's own spring constant for the load distribution (ISO/TS 16281, point contact) is
iso16281_spring_constant(), a scene option of the quasi-static fidelity.

Units: SI in and out (m, N, rad/s); lives in revolutions and hours. A life beyond LIFE_INFINITE (no load,
or at rest for hours) is reported as LIFE_INFINITE.
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .torque import iso76_f0, iso76_static_rating

LIFE_INFINITE = 1e30  # rev or h: an unloaded bearing (or, in hours, one at rest) does not fatigue
MATERIAL_FACTOR = 1.3  # b_m of radial and angular-contact groove ball bearings, ISO 281:2007 Table 1
LARGE_BALL = 25.4e-3  # m, above it C_r ~ 3.647 D_w^1.4 (ISO 281:2007, 5.1.1; 3.647 = 25.4^0.4 to 4 digits)
CONTACT_RATING_CONSTANT = 93.2  # A, N/mm^1.8: Lundberg-Palmgren 98.07 x reduction 0.95 (UNVERIFIED)
WEIBULL_SLOPE = 10.0 / 9.0  # e of ball bearings (ISO/TS 16281, Lundberg-Palmgren)
EXPONENT_ROTATING = 3.0  # equivalent load of the race rotating relative to the load
EXPONENT_STATIONARY = 10.0 / 3.0  # ... of the race stationary relative to the load
SPRING_CONSTANT_ISO = 1.48  # ISO/TS 16281 point-contact spring constant factor (exact Hertz: pi sqrt(2)/3)

# ISO 281:2007 Table 2, f_c of single-row radial contact groove ball bearings and single- and double-row
# angular contact groove ball bearings, at gamma = D_w cos(alpha)/D_pw = 0.01, 0.02, ..., 0.40 (linear
# interpolation in between, clamped outside). UNVERIFIED (docs/decisions.md): transcribed, not read from
# the standard; every entry is 38.2 x the Lundberg-Palmgren shape of equal conformities within 0.3 %
# (tests/unit/test_rating_life.py), which a misprinted entry would break.
FC_GAMMA_STEP = 0.01
FC_TABLE = (
    29.1,
    35.8,
    40.3,
    43.8,
    46.7,
    49.1,
    51.1,
    52.8,
    54.3,
    55.5,
    56.6,
    57.5,
    58.2,
    58.8,
    59.3,
    59.6,
    59.8,
    59.9,
    60.0,
    59.9,
    59.8,
    59.6,
    59.3,
    59.0,
    58.6,
    58.2,
    57.7,
    57.1,
    56.6,
    56.0,
    55.3,
    54.6,
    53.9,
    53.2,
    52.4,
    51.7,
    50.9,
    50.0,
    49.2,
    48.4,
)

# ISO 281:2007 Table 3, single-row bearings, F_a/F_r > e (X = 1, Y = 0 below e). UNVERIFIED (docs/decisions.md).
# Radial contact groove ball bearings, by f_0 F_a / C_0r:
RADIAL_LOAD_RATIO = (0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89)
RADIAL_E = (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44)
RADIAL_Y = (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00)
RADIAL_X = 0.56
# angular contact groove ball bearings, alpha = 15 deg, by f_0 F_a / C_0r:
AC15_LOAD_RATIO = (0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35, 7.14)
AC15_E = (0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56)
AC15_Y = (1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00)
AC15_X = 0.44
# angular contact groove ball bearings, alpha = 20, 25, ..., 45 deg (factors independent of the load):
AC_ALPHA = (20.0, 25.0, 30.0, 35.0, 40.0, 45.0)  # deg
AC_E = (0.57, 0.68, 0.80, 0.95, 1.14, 1.34)
AC_X = (0.43, 0.41, 0.39, 0.37, 0.35, 0.33)
AC_Y = (1.00, 0.87, 0.76, 0.66, 0.57, 0.50)
AC_ALPHA_MIN = 15.0  # deg: below, the radial-contact row (0 deg) and the 15 deg row are interpolated in the angle
# (an approximation: ISO 281's 5 and 10 deg rows are not carried; docs/rating_life.md)

# layout of the life parameter array (built by the facades with rating_parameters())
_LP_SLOTS = Layout()
LP_C_R = _LP_SLOTS.slot()  # basic dynamic radial load rating C_r (N)
LP_C_0R = _LP_SLOTS.slot()  # basic static radial load rating C_0r (N), ISO 76
LP_F_0 = _LP_SLOTS.slot()  # ISO 76 factor f_0 (-)
LP_ANGULAR = _LP_SLOTS.slot()  # 1 = angular contact (Table 3 by contact angle), 0 = radial contact groove bearing
LP_ALPHA_DEG = _LP_SLOTS.slot()  # nominal contact angle (deg)
LP_Q_CI = _LP_SLOTS.slot()  # basic dynamic load rating of an inner contact (N)
LP_Q_CE = _LP_SLOTS.slot()  # ... of an outer contact (N)
LP_SIZE = _LP_SLOTS.size

# layout of the life output array
_LO_SLOTS = Layout()
LO_L10 = _LO_SLOTS.slot()  # basic rating life (rev)
LO_L10_H = _LO_SLOTS.slot()  # ... in hours at the current speed (h)
LO_L10R = _LO_SLOTS.slot()  # reference rating life (rev)
LO_L10R_H = _LO_SLOTS.slot()  # ... in hours (h)
LO_SIZE = _LO_SLOTS.size


@kernel
def _interpolate(x, xs, ys):
    """Piecewise-linear y(x) through (xs, ys), xs increasing; clamped to the end values outside."""
    n = len(xs)
    if x <= xs[0]:
        return ys[0]
    if x >= xs[n - 1]:
        return ys[n - 1]
    i = 0
    while xs[i + 1] < x:
        i += 1
    t = (x - xs[i]) / (xs[i + 1] - xs[i])
    return (1.0 - t) * ys[i] + t * ys[i + 1]


@kernel
def iso281_fc(gamma):
    """ISO 281 factor f_c (N/mm^1.8) at gamma = D_w cos(alpha)/D_pw (-), Table 2 (FC_TABLE), linear
    interpolation, gamma clamped to the table's [0.01, 0.40]."""
    g = min(max(gamma, FC_GAMMA_STEP), FC_GAMMA_STEP * len(FC_TABLE)) / FC_GAMMA_STEP - 1.0
    i = min(int(g), len(FC_TABLE) - 2)
    t = g - i
    return (1.0 - t) * FC_TABLE[i] + t * FC_TABLE[i + 1]


@kernel
def _ball_size_term(D):
    """D_w^1.8 (D_w <= 25.4 mm) or 3.647 D_w^1.4 (larger balls), D_w in mm, for ball diameter D (m)."""
    d = D * 1e3
    if D <= LARGE_BALL:
        return d**1.8
    return 3.647 * d**1.4


@kernel
def iso281_dynamic_rating(Z, D, dm, alpha):
    """Basic dynamic radial load rating C_r (N) of a single-row radial or angular-contact groove ball bearing,
    ISO 281:2007 5.1.1, for Z balls of diameter D (m) on pitch diameter dm (m) at nominal contact angle alpha
    (rad)."""
    c = math.cos(alpha)
    return MATERIAL_FACTOR * iso281_fc(D * c / dm) * c**0.7 * Z ** (2.0 / 3.0) * _ball_size_term(D)


@kernel
def iso281_factors(angular, alpha_deg, load_ratio):
    """ISO 281:2007 Table 3 factors (X, Y, e) of a single-row bearing with F_a/F_r > e.

    angular: 1 = angular contact (nominal angle alpha_deg, 0-45 deg), 0 = radial contact groove bearing;
    load_ratio = f_0 F_a / C_0r (-). Between 15 and 20 deg the 15 deg row (at this load ratio) and the 20 deg
    row are interpolated linearly in the angle, as between the tabulated angles above; below 15 deg the
    radial-contact row and the 15 deg row (AC_ALPHA_MIN)."""
    e0 = _interpolate(load_ratio, RADIAL_LOAD_RATIO, RADIAL_E)
    y0 = _interpolate(load_ratio, RADIAL_LOAD_RATIO, RADIAL_Y)
    if angular < 0.5:
        return RADIAL_X, y0, e0
    e15 = _interpolate(load_ratio, AC15_LOAD_RATIO, AC15_E)
    y15 = _interpolate(load_ratio, AC15_LOAD_RATIO, AC15_Y)
    if alpha_deg < AC_ALPHA_MIN:
        t = max(alpha_deg, 0.0) / AC_ALPHA_MIN
        return (1.0 - t) * RADIAL_X + t * AC15_X, (1.0 - t) * y0 + t * y15, (1.0 - t) * e0 + t * e15
    if alpha_deg <= AC_ALPHA[0]:
        t = (alpha_deg - AC_ALPHA_MIN) / (AC_ALPHA[0] - AC_ALPHA_MIN)
        return (1.0 - t) * AC15_X + t * AC_X[0], (1.0 - t) * y15 + t * AC_Y[0], (1.0 - t) * e15 + t * AC_E[0]
    return (
        _interpolate(alpha_deg, AC_ALPHA, AC_X),
        _interpolate(alpha_deg, AC_ALPHA, AC_Y),
        _interpolate(alpha_deg, AC_ALPHA, AC_E),
    )


@kernel
def equivalent_dynamic_load(F_r, F_a, lp):
    """Dynamic equivalent radial load P (N) for radial load F_r >= 0 and axial load F_a >= 0 (N), ISO 281:2007
    5.2: P = F_r for F_a/F_r <= e, else X F_r + Y F_a (iso281_factors); lp: LP_* array."""
    if F_a <= 0.0:
        return F_r
    X, Y, e = iso281_factors(lp[LP_ANGULAR], lp[LP_ALPHA_DEG], lp[LP_F_0] * F_a / lp[LP_C_0R])
    if F_a <= e * F_r:
        return F_r
    return X * F_r + Y * F_a


@kernel
def contact_ratings(Z, D, dm, f_i, f_o, alpha):
    """Basic dynamic load ratings (Q_ci, Q_ce) in N of one inner and one outer ball-race contact (module
    docstring: Lundberg-Palmgren in the form of ISO/TS 16281, with ISO 281's b_m); Z balls of diameter D (m),
    pitch diameter dm (m), conformities f_i, f_o (-), contact angle alpha (rad)."""
    g = D * math.cos(alpha) / dm
    common = (
        CONTACT_RATING_CONSTANT
        * MATERIAL_FACTOR
        * (D / dm) ** 0.3  # (gamma / cos alpha)^0.3
        * _ball_size_term(D)
        * Z ** (-1.0 / 3.0)
    )
    q_i = common * (2.0 * f_i / (2.0 * f_i - 1.0)) ** 0.41 * (1.0 - g) ** 1.39 / (1.0 + g) ** (1.0 / 3.0)
    q_e = common * (2.0 * f_o / (2.0 * f_o - 1.0)) ** 0.41 * (1.0 + g) ** 1.39 / (1.0 - g) ** (1.0 / 3.0)
    return q_i, q_e


@kernel
def equivalent_contact_load(Q, exponent):
    """Dynamic equivalent load (N) of a race from its per-ball contact loads Q (N): (sum Q^w / Z)^(1/w),
    w = EXPONENT_ROTATING for the race rotating relative to the load, EXPONENT_STATIONARY otherwise."""
    total = 0.0
    for q in Q:
        if q > 0.0:
            total += q**exponent
    return (total / len(Q)) ** (1.0 / exponent)


@kernel
def life_revolutions(rating, load, exponent):
    """(rating/load)^exponent x 10^6 revolutions, LIFE_INFINITE for no load or beyond it."""
    if load <= 0.0:
        return LIFE_INFINITE
    return min(1e6 * (rating / load) ** exponent, LIFE_INFINITE)


@kernel
def combined_life(L_i, L_e):
    """Bearing life (rev) from the race lives (rev): (L_i^-e + L_e^-e)^(-1/e), e = WEIBULL_SLOPE; a race at
    LIFE_INFINITE (unloaded) adds no failure probability."""
    e = WEIBULL_SLOPE
    total = 0.0
    for L in (L_i, L_e):
        if L < LIFE_INFINITE:
            total += L ** (-e)
    if total == 0.0:
        return LIFE_INFINITE
    return min(total ** (-1.0 / e), LIFE_INFINITE)


@kernel
def life_hours(revolutions, omega):
    """Hours (h) to run `revolutions` at inner-ring speed omega (rad/s); LIFE_INFINITE at rest or beyond."""
    if omega == 0.0 or revolutions >= LIFE_INFINITE:
        return LIFE_INFINITE
    return min(revolutions * 2.0 * math.pi / abs(omega) / 3600.0, LIFE_INFINITE)


@kernel
def rating_parameters(angular, Z, D, dm, f_i, f_o, alpha, lp):
    """Fill the LP_* array of a bearing: angular (1 angular contact, 0 deep groove), Z balls of diameter D (m),
    pitch diameter dm (m), conformities f_i, f_o, nominal contact angle alpha (rad; 0 for deep groove)."""
    lp[LP_C_R] = iso281_dynamic_rating(Z, D, dm, alpha)
    lp[LP_C_0R] = iso76_static_rating(Z, D, dm, alpha)
    lp[LP_F_0] = iso76_f0(D * math.cos(alpha) / dm)
    lp[LP_ANGULAR] = angular
    lp[LP_ALPHA_DEG] = math.degrees(alpha)
    lp[LP_Q_CI], lp[LP_Q_CE] = contact_ratings(Z, D, dm, f_i, f_o, alpha)


@kernel
def rating_life(Q_inner, Q_outer, F_r, F_a, omega, lp, out):
    """Fill out[LO_*]: basic rating life from the ring loads and reference rating life from the contact loads.

    Q_inner, Q_outer: contact loads of each ball on the inner and outer race (N); F_r, F_a: radial and axial
    load the balls carry (N, >= 0); omega: inner-ring speed (rad/s, outer ring fixed, load fixed in space);
    lp: LP_* array (rating_parameters)."""
    P = equivalent_dynamic_load(F_r, F_a, lp)
    out[LO_L10] = life_revolutions(lp[LP_C_R], P, 3.0)
    Q_ei = equivalent_contact_load(Q_inner, EXPONENT_ROTATING)
    Q_ee = equivalent_contact_load(Q_outer, EXPONENT_STATIONARY)
    L_i = life_revolutions(lp[LP_Q_CI], Q_ei, 3.0)
    L_e = life_revolutions(lp[LP_Q_CE], Q_ee, 3.0)
    out[LO_L10R] = combined_life(L_i, L_e)
    out[LO_L10_H] = life_hours(out[LO_L10], omega)
    out[LO_L10R_H] = life_hours(out[LO_L10R], omega)


@kernel
def iso16281_spring_constant(Rx, Ry, E_red, k_yx, ell_E, ell_K):
    """Load-deflection constant (N/m^1.5) of one contact in the form of ISO/TS 16281 (point contact):
    c = 1.48 E' [K (sum rho / (k^2 E))^(1/3)]^(-3/2), sum rho = 1/Rx + 1/Ry (1/m), E' reduced modulus (Pa),
    k ellipticity, E and K the complete elliptic integrals of the contact. Two contacts in series add their
    brackets. The exact Hertz constant (kernels.hertz.hertz_stiffness) has pi sqrt(2)/3 = 1.48096 for 1.48."""
    k = k_yx if k_yx >= 1.0 else 1.0 / k_yx
    bracket = ell_K * ((1.0 / Rx + 1.0 / Ry) / (k * k * ell_E)) ** (1.0 / 3.0)
    return SPRING_CONSTANT_ISO * E_red * bracket**-1.5
