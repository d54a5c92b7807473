"""Friction losses of a ball-race contact (Houpert model) and the Palmgren cross-check (docs/houpert_torque.md).

SI units throughout. Sources, conventions and the 6208 check are in docs/houpert_torque.md (the
"note"); section numbers below refer to it. x is the rolling direction, y the transverse one;
a_y, b_x are the Hertz semi-axes along y and x (a_y the major one for a ball-race contact),
E_red is Hamrock's E' = E/(1 - nu^2) for steel on steel (kernels.hertz).

Per contact (note sections 2 and 4):
- EHL rolling force, Houpert 1987 (ASME J. Tribol. 109:363) as printed by Rabreau 2018 and
  restated by Biboulet & Houpert 2010 Part 2 eq. 29:
    F_R = 2.765 E' Rx^2 k^0.35 U^0.656 W^0.466 G^0.022,
  k = Ry/Rx (radius ratio, not the ellipticity), U = eta |u_mean| / (E' Rx) with u_mean the mean
  entrainment speed (u1 + u2)/2, W = Q/(E' Rx^2), G = xi E'. It is a starved-inlet fit (note 2.2).
- Elastic hysteresis (Tabor; Johnson 1985, Contact Mechanics, ch. 9, memory): F_h = (3/16) alpha_h b Q / Rx.
- Heathcote (differential) sliding from the groove curvature: F_H = C_H mu Q a^2 / (R_c Rx), C_H = 3I/8.
- Pivoting (spin) moment, Jones 1959 / Harris (memory): M_s = (3/8) mu Q a E(e).
Powers (W): EHL 2 F_R |u| (Biboulet & Houpert 2010 Part 1, conclusion: the rolling force acts on
both surfaces; a power F_R u would be half of it, docs/houpert_torque.md), hysteresis F_h |u|, Heathcote F_H |u|,
spin M_s |omega_spin|.

Bearing-level cross-check (note 4d): Palmgren 1959, Ball and Roller Bearing Engineering, 3rd ed.,
pp. 34-41, tables as in Harris, Rolling Bearing Analysis (memory, estimated), M = M0 + M1, and the
ISO 76 static rating C0 that enters f1.
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

# Indices of the per-contact power array filled by contact_losses.
_TL_SLOTS = Layout()
TL_EHL = _TL_SLOTS.slot()
TL_HYST = _TL_SLOTS.slot()
TL_HEATHCOTE = _TL_SLOTS.slot()
TL_SPIN = _TL_SLOTS.slot()
TL_SIZE = _TL_SLOTS.size

# Hysteresis loss factor of bearing steel. ESTIMATED (Harris, Rolling Bearing Analysis; unverified, see the
# unverified-sources table of docs/decisions.md).
ALPHA_HYSTERESIS_STEEL = 0.007

# Heathcote constant (note 4b). Rolling bands at y = +-c a where the line load
# w(y) = (3Q/4a)(1 - y^2/a^2) gives zero net tangential force: 2 int_0^c (1 - s^2) ds = 2/3, i.e.
# c^3 - 3c + 1 = 0, whose root in (0, 1) is 2 cos(4 pi/9) = 0.347296...
# I = 2 int_0^1 (1 - s^2)|c^2 - s^2| ds = 2 (2 G(c) - G(1)), G(s) = c^2 s - (1 + c^2) s^3/3 + s^5/5,
# = 0.2148565..., and C_H = 3I/8 = 0.0805712 (the note's 0.0806 rounded; Johnson's "~0.08").
HEATHCOTE_BAND = 2.0 * math.cos(4.0 * math.pi / 9.0)
_c2 = HEATHCOTE_BAND * HEATHCOTE_BAND


def _heathcote_primitive(s):
    return _c2 * s - (1.0 + _c2) * s**3 / 3.0 + s**5 / 5.0


HEATHCOTE_INTEGRAL = 2.0 * (2.0 * _heathcote_primitive(HEATHCOTE_BAND) - _heathcote_primitive(1.0))
HEATHCOTE_CONSTANT = 3.0 * HEATHCOTE_INTEGRAL / 8.0

# Palmgren option codes.
PALMGREN_DEEP_GROOVE = 0
PALMGREN_ANGULAR_CONTACT = 1
LUB_OIL_MIST = 0
LUB_OIL_BATH = 1
LUB_OIL_JET = 2  # also oil bath with a vertical shaft
# Palmgren's f0 (-): a row per bearing kind (PALMGREN_* order), a column per lubrication (LUB_OIL_* order)
PALMGREN_F0 = ((1.0, 2.0, 4.0), (1.7, 3.3, 6.6))

# ISO 76:2006 Table 1, f0 (N/mm^2) of radial and angular-contact groove ball bearings at
# gamma = D cos(alpha)/d_m = 0.00, 0.01, ..., 0.40, linear interpolation in between. UNVERIFIED
# (docs/decisions.md, unverified sources): no copy of the standard was at hand. Every entry agrees
# within 0.45 % with f0 = Q_max/(5 D^2) for a Hertz pressure of 4200 MPa on the governing contact
# (inner groove 0.52 D, outer 0.53 D, E = 207 GPa, nu = 0.3, Stribeck factor 5), which the twin
# computes; all round to the table's digit except gamma = 0.13 (15.6 here, 15.65 from Hertz).
ISO76_F0 = (
    14.7,
    14.9,
    15.1,
    15.3,
    15.5,
    15.7,
    15.9,
    16.1,
    16.3,
    16.5,
    16.4,
    16.1,
    15.9,
    15.6,
    15.4,
    15.2,
    14.9,
    14.7,
    14.4,
    14.2,
    14.0,
    13.7,
    13.5,
    13.2,
    13.0,
    12.8,
    12.5,
    12.3,
    12.1,
    11.8,
    11.6,
    11.4,
    11.2,
    10.9,
    10.7,
    10.5,
    10.3,
    10.0,
    9.8,
    9.6,
    9.4,
)
ISO76_GAMMA_STEP = 0.01
ISO76_GAMMA_MAX = 0.40


@kernel
def houpert_rolling_force(Q, u_mean, Rx, Ry, E_red, eta, xi):
    """EHL (hydrodynamic) rolling force F_R (N) of one contact, Houpert 1987 (note 2.3).

    Q load (N), u_mean mean entrainment speed (m/s, sign ignored), Rx, Ry reduced radii (m),
    E_red Hamrock's E' (Pa), eta viscosity (Pa.s), xi pressure-viscosity coefficient (1/Pa).
    F_R = 2.765 E' Rx^2 (Ry/Rx)^0.35 U^0.656 W^0.466 G^0.022 (Houpert 1987 via Rabreau 2018 and
    Biboulet & Houpert 2010 Part 2 eq. 29). An open contact (Q <= 0) or no entrainment gives 0.
    """
    if Q <= 0.0 or u_mean == 0.0 or eta <= 0.0:
        return 0.0
    U = eta * abs(u_mean) / (E_red * Rx)
    W = Q / (E_red * Rx * Rx)
    G = xi * E_red
    return 2.765 * E_red * Rx * Rx * (Ry / Rx) ** 0.35 * U**0.656 * W**0.466 * G**0.022


@kernel
def hysteresis_force(Q, b_x, Rx, alpha_h):
    """Elastic-hysteresis rolling force F_h = (3/16) alpha_h b_x Q / Rx (N) (note 4a).

    Tabor's model (Johnson 1985, Contact Mechanics, ch. 9, memory): the resisting moment is alpha_h
    times the moment of the pressure on the leading half of the ellipse, int_{x>0} p x dA = 3 Q b/16,
    turned into a force at the rolling radius Rx. Q (N), b_x semi-axis along the rolling direction
    (m), Rx (m), alpha_h loss factor (-). Q <= 0 gives 0.
    """
    if Q <= 0.0:
        return 0.0
    return 0.1875 * alpha_h * b_x * Q / Rx


@kernel
def heathcote_force(Q, a_y, Rx, f, D, mu):
    """Heathcote (differential-sliding) force F_H = C_H mu Q a_y^2 / (R_c Rx) (N) (note 4b).

    The deformed contact is curved across the rolling direction with radius R_c = 2 f D/(2f + 1)
    (Harris's form, memory), so the sliding speed is (u/Rx)(c^2 - y^2)/(2 R_c) with rolling bands at
    y = +-c a_y; C_H = 3I/8 = HEATHCOTE_CONSTANT = 0.0805712 (derivation above; Johnson 1985 ch. 8,
    memory). F_H is the sliding power over |u|. Q (N), a_y transverse semi-axis (m), Rx (m),
    f groove conformity r/D (-), D ball diameter (m), mu friction coefficient (-). Valid without
    spin (alpha = 0); with spin the two slidings do not add linearly (note 4b). Q <= 0 gives 0.
    """
    if Q <= 0.0:
        return 0.0
    R_c = 2.0 * f * D / (2.0 * f + 1.0)
    return HEATHCOTE_CONSTANT * mu * Q * a_y * a_y / (R_c * Rx)


@kernel
def spin_moment(Q, a_y, ell_E, mu):
    """Pivoting (spin) friction moment M_s = (3/8) mu Q a_y ell_E (N.m) (note 4c).

    Integral of mu p r over the Hertz ellipse (Jones 1959 / Harris, memory; Houpert's fit in
    Balan 2015 eqs. 10-11 agrees within 0.3 %). Q (N), a_y semi-major axis (m), ell_E complete
    elliptic integral of the second kind of the contact (-, pi/2 for a circle), mu (-).
    Q <= 0 gives 0.
    """
    if Q <= 0.0:
        return 0.0
    return 0.375 * mu * Q * a_y * ell_E


@kernel
def contact_losses(Q, u_mean, omega_spin, Rx, Ry, a_y, b_x, ell_E, f, D, E_red, eta, xi, mu, alpha_h, out):
    """Power losses (W) of one contact written into out[TL_EHL..TL_SPIN]; returns their sum (W).

    EHL rolling 2 F_R |u_mean| (Biboulet & Houpert 2010 Part 1), hysteresis F_h |u_mean|,
    Heathcote F_H |u_mean|, spin M_s |omega_spin|. Arguments as in the single kernels; omega_spin
    spin speed of the ball relative to the race about the contact normal (rad/s); out a float64
    array of length >= TL_SIZE. An open contact (Q <= 0) loses nothing.
    """
    u = abs(u_mean)
    out[TL_EHL] = 2.0 * houpert_rolling_force(Q, u_mean, Rx, Ry, E_red, eta, xi) * u
    out[TL_HYST] = hysteresis_force(Q, b_x, Rx, alpha_h) * u
    out[TL_HEATHCOTE] = heathcote_force(Q, a_y, Rx, f, D, mu) * u
    out[TL_SPIN] = spin_moment(Q, a_y, ell_E, mu) * abs(omega_spin)
    return out[TL_EHL] + out[TL_HYST] + out[TL_HEATHCOTE] + out[TL_SPIN]


@kernel
def palmgren_f0(kind, lubrication):
    """Palmgren lubrication factor f0 (-) (Harris; ESTIMATED and unverified, docs/decisions.md; note 4d).

    kind: PALMGREN_DEEP_GROOVE (oil mist 1, oil bath 2, jet or vertical-shaft bath 4) or
    PALMGREN_ANGULAR_CONTACT single row (1.7, 3.3, 6.6; low confidence). lubrication: LUB_OIL_MIST,
    LUB_OIL_BATH, LUB_OIL_JET. Grease (0.7-2 deep groove, ~2 angular) is a range, not offered.
    """
    if 0 <= kind < len(PALMGREN_F0) and 0 <= lubrication < len(PALMGREN_F0[0]):
        return PALMGREN_F0[kind][lubrication]
    raise ValueError("palmgren_f0: unknown bearing kind or lubrication code")


@kernel
def palmgren_viscous_torque(f0, nu_cSt, n_rpm, dm):
    """Palmgren load-independent (viscous) torque M0 (N.m) (Palmgren 1959; Harris; note 4d).

    Printed form M0 = 1e-7 f0 (nu n)^(2/3) dm^3 (N.mm, nu in cSt = mm^2/s, n in rpm, dm in mm) for
    nu n >= 2000, and M0 = 160e-7 f0 dm^3 below; in SI (dm in m) 0.1 f0 (nu n)^(2/3) dm^3 and
    16 f0 dm^3. The printed 160 (not 2000^(2/3) = 158.74) is kept: a 0.79 % step at nu n = 2000.
    The low-speed branch is a floor of the running torque and applies down to n = 0. Sign of n ignored.
    """
    nn = nu_cSt * abs(n_rpm)
    if nn >= 2000.0:
        return 0.1 * f0 * nn ** (2.0 / 3.0) * dm**3
    return 16.0 * f0 * dm**3


@kernel
def palmgren_load_torque(f1, P1, dm):
    """Palmgren load-dependent torque M1 = f1 P1 dm (N.m): f1 (-), P1 (N), pitch diameter dm (m)."""
    return f1 * P1 * dm


@kernel
def palmgren_f1(kind, P0, C0):
    """Palmgren load factor f1 = z (P0/C0)^y (-) (Harris; ESTIMATED and unverified, docs/decisions.md; note 4d).

    Deep groove z = 0.0005 (middle of 0.0004-0.0006), y = 0.55; angular contact z = 0.001,
    y = 0.33. P0 static equivalent load (N), C0 basic static rating (N). P0 <= 0 gives 0.
    """
    if kind == PALMGREN_DEEP_GROOVE:
        z, y = 0.0005, 0.55
    elif kind == PALMGREN_ANGULAR_CONTACT:
        z, y = 0.001, 0.33
    else:
        raise ValueError("palmgren_f1: unknown bearing kind code")
    if P0 <= 0.0:
        return 0.0
    return z * (P0 / C0) ** y


@kernel
def palmgren_equivalent_load(kind, F_r, F_a, alpha):
    """Palmgren load P1 (N) for M1 from radial F_r and axial F_a loads (N), contact angle alpha (rad).

    Harris (memory, ESTIMATED; note 4d), the larger of the expression and F_r:
    deep groove 0.9 F_a cot(alpha) - 0.1 F_r; single-row angular contact F_a - 0.1 F_r.
    Decision for deep groove: the coefficient is min(0.9 cot alpha, 3.3). 0.9 cot alpha diverges as
    alpha -> 0, while under axial load the working angle is set by the clearance; Schaeffler's
    3.3 F_a - 0.1 F_r (= 0.9 cot 15.3 deg) covers alpha = 0 and caps small angles, continuously.
    Load signs are ignored (magnitudes).
    """
    fr = abs(F_r)
    fa = abs(F_a)
    if kind == PALMGREN_DEEP_GROOVE:
        s = math.sin(alpha)
        coef = 3.3
        if 0.9 * math.cos(alpha) < 3.3 * s:  # 0.9 cot(alpha) < 3.3 without dividing by sin(0)
            coef = 0.9 * math.cos(alpha) / s
        p = coef * fa - 0.1 * fr
    elif kind == PALMGREN_ANGULAR_CONTACT:
        p = fa - 0.1 * fr
    else:
        raise ValueError("palmgren_equivalent_load: unknown bearing kind code")
    return max(p, fr)


@kernel
def iso76_f0(gamma):
    """ISO 76 factor f0 (N/mm^2) of radial/angular-contact groove ball bearings at
    gamma = D cos(alpha)/d_m (-): Table 1 (ISO76_F0, unverified, see above), linear interpolation;
    gamma is clamped to the table's [0, 0.40]."""
    g = min(max(gamma, 0.0), ISO76_GAMMA_MAX) / ISO76_GAMMA_STEP
    i = min(int(g), len(ISO76_F0) - 2)
    t = g - i
    return (1.0 - t) * ISO76_F0[i] + t * ISO76_F0[i + 1]


@kernel
def iso76_static_rating(Z, D, dm, alpha):
    """Basic static radial rating C0 (N) of a single-row radial or angular-contact ball bearing, ISO 76.

    ISO 76 writes C0 = f0 i Z D_w^2 cos(alpha) with D_w in mm, C0 in N, f0 in N/mm^2; here D and dm
    are in m, so C0 = 1e6 f0 Z D^2 cos(alpha) (i = 1 row). Z number of balls, alpha contact angle (rad).
    """
    c = math.cos(alpha)
    return 1.0e6 * iso76_f0(D * c / dm) * Z * D * D * c
