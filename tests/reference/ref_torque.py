"""Twin of bearing_fmu.kernels.torque: contact friction losses (Houpert) and Palmgren, from first principles.

Written from the formulas of docs/houpert_torque.md, not from the kernel. Where the kernel uses a
closed form derived from an integral over the Hertz ellipse, this twin integrates numerically with
scipy over the ellipse, with the Hertz pressure p = (3Q/(2 pi a b)) sqrt(1 - x^2/b^2 - y^2/a^2)
(x rolling direction, semi-axis b; y transverse, semi-axis a):
- hysteresis: alpha_h int_{x>0} p x dA / Rx (Tabor; Johnson 1985 ch. 9);
- Heathcote: sliding speed (u/Rx)(c^2 - y^2)/(2 R_c), R_c = 2 f D/(2f + 1); c found by brentq from
  a zero net tangential force int p sign(c^2 - y^2) dA = 0; force = int mu p |v_s| dA / u;
- spin: int mu p r dA, with the minor semi-axis recovered from ell_E = E(m), m = 1 - (b/a)^2;
- ISO 76 f0: from its definition, a Hertz pressure of 4200 MPa at the centre of the governing contact
  (inner groove 0.52 D, outer 0.53 D, E = 207 GPa, nu = 0.3) with Stribeck's Q_max = 5 C0/(Z cos alpha),
  so f0 = Q_max / (5 D^2) in N/mm^2 (ISO/TR 10657 background; E, nu and the factor 5 unverified,
  confirmed by the agreement with the table).
Houpert's rolling force and the Palmgren formulas are closed forms, written out in their printed units.
"""

import math

from scipy.integrate import dblquad
from scipy.optimize import brentq
from scipy.special import ellipe

from tests.reference import ref_hertz

TL_EHL, TL_HYST, TL_HEATHCOTE, TL_SPIN, TL_SIZE = 0, 1, 2, 3, 4
DEEP_GROOVE, ANGULAR_CONTACT = 0, 1
OIL_MIST, OIL_BATH, OIL_JET = 0, 1, 2
QUAD_RTOL = 1e-10  # requested accuracy of every 2D quadrature, relative to the caller's scale

# Palmgren f0 (Harris; unverified, docs/decisions.md) by (kind, lubrication).
PALMGREN_F0 = {
    (DEEP_GROOVE, OIL_MIST): 1.0,
    (DEEP_GROOVE, OIL_BATH): 2.0,
    (DEEP_GROOVE, OIL_JET): 4.0,
    (ANGULAR_CONTACT, OIL_MIST): 1.7,
    (ANGULAR_CONTACT, OIL_BATH): 3.3,
    (ANGULAR_CONTACT, OIL_JET): 6.6,
}
# Palmgren f1 = z (P0/C0)^y: (z, y) by kind.
PALMGREN_F1 = {DEEP_GROOVE: (0.0005, 0.55), ANGULAR_CONTACT: (0.001, 0.33)}


def hertz_pressure(x, y, Q, a, b):
    """Hertz pressure (Pa) at (x, y) of an ellipse with semi-axes b (along x) and a (along y)."""
    s = 1.0 - (x / b) ** 2 - (y / a) ** 2
    return 1.5 * Q / (math.pi * a * b) * math.sqrt(s) if s > 0.0 else 0.0


def _over_half_ellipse(func, a, b, y0, y1, scale):
    """int_{y0}^{y1} int_{0}^{x_edge(y)} func(x, y) dx dy, x_edge = b sqrt(1 - y^2/a^2).

    scale: magnitude of the whole integral; the absolute tolerance QUAD_RTOL * scale stops QUADPACK
    from chasing relative accuracy on the vanishing slivers near y = a (roundoff warnings)."""
    return dblquad(
        func,
        y0,
        y1,
        0.0,
        lambda y: b * math.sqrt(max(0.0, 1.0 - (y / a) ** 2)),
        epsabs=QUAD_RTOL * scale,
        epsrel=QUAD_RTOL,
    )[0]


def houpert_rolling_force(Q, u_mean, Rx, Ry, E_red, eta, xi):
    """F_R (N) = 2.765 E' Rx^2 (Ry/Rx)^0.35 U^0.656 W^0.466 G^0.022, U on the mean speed, written
    dimensionally. No special cases beyond an open contact: u = 0 gives 0 from the power law."""
    if Q <= 0.0:
        return 0.0
    return (
        2.765
        * E_red
        * Rx**2
        * (Ry / Rx) ** 0.35
        * (eta * abs(u_mean) / (E_red * Rx)) ** 0.656
        * (Q / (E_red * Rx**2)) ** 0.466
        * (xi * E_red) ** 0.022
    )


def bh2010_rolling_force(Q, u_mean, Rx, Ry, E_red, eta, xi):
    """Biboulet & Houpert 2010 Part 2 eq. 29 in its own notation (note 2.2): U = 2 eta u_m/(E' Rx),
    kappa = b/a (exact Hertz), beta = (4/pi) E(e)/(1 + Rx/Ry):
    F = E' Rx^2 1.544 beta^(1/3) kappa^-0.577 U^0.656 W^0.466 G^0.022. Not a kernel: cross-check only."""
    k_yx, ell_E, _ = ref_hertz.hertz_coefficients_exact(Rx, Ry)
    kappa = 1.0 / k_yx
    beta = 4.0 / math.pi * ell_E / (1.0 + Rx / Ry)
    U = 2.0 * eta * abs(u_mean) / (E_red * Rx)
    return (
        E_red
        * Rx**2
        * 1.544
        * beta ** (1.0 / 3.0)
        * kappa**-0.577
        * U**0.656
        * (Q / (E_red * Rx**2)) ** 0.466
        * (xi * E_red) ** 0.022
    )


def hysteresis_force(Q, b_x, Rx, alpha_h):
    """alpha_h int_{x>0} p x dA / Rx by 2D quadrature (any a: the moment does not depend on it)."""
    if Q <= 0.0:
        return 0.0
    a = 10.0 * b_x
    m = 2.0 * _over_half_ellipse(lambda x, y: hertz_pressure(x, y, Q, a, b_x) * x, a, b_x, 0.0, a, Q * b_x)
    return alpha_h * m / Rx


def heathcote_band(Q, a, b):
    """Half-width c (m) of the rolling bands: brentq on the net tangential force int p sign(c^2 - y^2) dA."""

    def net(c):
        inside = _over_half_ellipse(lambda x, y: hertz_pressure(x, y, Q, a, b), a, b, 0.0, c, Q)
        outside = _over_half_ellipse(lambda x, y: hertz_pressure(x, y, Q, a, b), a, b, c, a, Q)
        return inside - outside

    return brentq(net, 1e-6 * a, (1.0 - 1e-6) * a, xtol=1e-15 * a, rtol=1e-14)


def heathcote_force(Q, a_y, Rx, f, D, mu, b_x=None):
    """Sliding power over u (N): int mu p |v_s| dA / u, v_s = (u/Rx)(c^2 - y^2)/(2 R_c).
    The minor axis does not enter the result (b_x defaults to a_y/10; the test checks this)."""
    if Q <= 0.0:
        return 0.0
    b = a_y / 10.0 if b_x is None else b_x
    R_c = 2.0 * f * D / (2.0 * f + 1.0)
    c = heathcote_band(Q, a_y, b)

    def power_over_u(x, y):
        return mu * hertz_pressure(x, y, Q, a_y, b) * abs(c * c - y * y) / (2.0 * R_c * Rx)

    scale = mu * Q * a_y**2 / (R_c * Rx)
    return 4.0 * (
        _over_half_ellipse(power_over_u, a_y, b, 0.0, c, scale)
        + _over_half_ellipse(power_over_u, a_y, b, c, a_y, scale)
    )


def minor_over_major(ell_E):
    """b/a = sqrt(1 - m) of the ellipse whose E(m) is ell_E (brentq on scipy.special.ellipe)."""
    if ell_E >= math.pi / 2.0:
        return 1.0
    m = brentq(lambda m: ellipe(m) - ell_E, 0.0, 1.0, xtol=1e-16, rtol=1e-15)
    return math.sqrt(1.0 - m)


def spin_moment(Q, a_y, ell_E, mu):
    """int mu p r dA (N.m) over the ellipse, r = sqrt(x^2 + y^2), four quadrants by symmetry."""
    if Q <= 0.0:
        return 0.0
    b = a_y * minor_over_major(ell_E)
    return 4.0 * _over_half_ellipse(
        lambda x, y: mu * hertz_pressure(x, y, Q, a_y, b) * math.hypot(x, y), a_y, b, 0.0, a_y, mu * Q * a_y
    )


def contact_losses(Q, u_mean, omega_spin, Rx, Ry, a_y, b_x, ell_E, f, D, E_red, eta, xi, mu, alpha_h, out):
    """Powers (W): EHL 2 F_R |u| (Biboulet & Houpert 2010), hysteresis, Heathcote, spin; returns the sum."""
    u = abs(u_mean)
    out[TL_EHL] = 2.0 * houpert_rolling_force(Q, u_mean, Rx, Ry, E_red, eta, xi) * u
    out[TL_HYST] = hysteresis_force(Q, b_x, Rx, alpha_h) * u
    out[TL_HEATHCOTE] = heathcote_force(Q, a_y, Rx, f, D, mu, b_x) * u
    out[TL_SPIN] = spin_moment(Q, a_y, ell_E, mu) * abs(omega_spin)
    return float(sum(out[:TL_SIZE]))


def palmgren_f0(kind, lubrication):
    """Table lookup; unknown codes raise ValueError."""
    try:
        return PALMGREN_F0[(kind, lubrication)]
    except KeyError:
        raise ValueError(f"unknown Palmgren kind/lubrication {kind}/{lubrication}") from None


def palmgren_viscous_torque(f0, nu_cSt, n_rpm, dm):
    """M0 in Harris's units (N.mm with dm in mm), converted to N.m."""
    dm_mm = dm * 1e3
    nn = nu_cSt * abs(n_rpm)
    m0_nmm = 1e-7 * f0 * nn ** (2.0 / 3.0) * dm_mm**3 if nn >= 2000.0 else 160e-7 * f0 * dm_mm**3
    return m0_nmm * 1e-3


def palmgren_load_torque(f1, P1, dm):
    """M1 = f1 P1 dm computed in N.mm (dm in mm), converted to N.m."""
    return f1 * P1 * (dm * 1e3) * 1e-3


def palmgren_f1(kind, P0, C0):
    """f1 = z (P0/C0)^y."""
    if kind not in PALMGREN_F1:
        raise ValueError(f"unknown Palmgren kind {kind}")
    z, y = PALMGREN_F1[kind]
    return z * (P0 / C0) ** y if P0 > 0.0 else 0.0


def palmgren_equivalent_load(kind, F_r, F_a, alpha):
    """P1 = max(expression, F_r): deep groove min(0.9 cot alpha, 3.3) F_a - 0.1 F_r (Harris, capped by
    Schaeffler's 3.3 for small angles and alpha = 0), angular contact F_a - 0.1 F_r."""
    fr, fa = abs(F_r), abs(F_a)
    if kind == DEEP_GROOVE:
        coef = 3.3 if math.tan(alpha) <= 0.9 / 3.3 else 0.9 / math.tan(alpha)
        return max(coef * fa - 0.1 * fr, fr)
    if kind == ANGULAR_CONTACT:
        return max(fa - 0.1 * fr, fr)
    raise ValueError(f"unknown Palmgren kind {kind}")


def _q_at_pressure(Rx, Ry, p_max, E_red):
    """Load (N) giving the Hertz maximum pressure p_max (Pa), by brentq on the twin Hertz model."""
    k, ell_E, ell_K = ref_hertz.hertz_coefficients_exact(Rx, Ry)
    return brentq(
        lambda Q: ref_hertz.hertz_contact(Q, Rx, Ry, E_red, k, ell_E, ell_K)[3] - p_max,
        1e-6,
        1e12,
        xtol=1e-12,
        rtol=1e-14,
    )


def iso76_f0(gamma):
    """f0 (N/mm^2) from the definition of C0 (module docstring), for D = 1 mm."""
    E_red = 207e9 / (1.0 - 0.3**2)
    D = 1e-3
    Ry_i = 1.0 / (2.0 / D - 1.0 / (0.52 * D))  # ball and groove of radius 0.52 D
    Ry_o = 1.0 / (2.0 / D - 1.0 / (0.53 * D))
    q_i = _q_at_pressure(0.5 * D * (1.0 - gamma), Ry_i, 4200e6, E_red)
    q_o = _q_at_pressure(0.5 * D * (1.0 + gamma), Ry_o, 4200e6, E_red)
    return min(q_i, q_o) / 5.0 / (D * 1e3) ** 2


def iso76_static_rating(Z, D, dm, alpha):
    """C0 (N) = f0 Z D_w^2 cos(alpha) with D_w in mm (single row)."""
    return iso76_f0(D * math.cos(alpha) / dm) * Z * (D * 1e3) ** 2 * math.cos(alpha)


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.torque"
TWINS = {
    "houpert_rolling_force": houpert_rolling_force,
    "hysteresis_force": hysteresis_force,
    "heathcote_force": heathcote_force,
    "spin_moment": spin_moment,
    "contact_losses": contact_losses,
    "palmgren_f0": palmgren_f0,
    "palmgren_viscous_torque": palmgren_viscous_torque,
    "palmgren_load_torque": palmgren_load_torque,
    "palmgren_f1": palmgren_f1,
    "palmgren_equivalent_load": palmgren_equivalent_load,
    "iso76_f0": iso76_f0,
    "iso76_static_rating": iso76_static_rating,
}
