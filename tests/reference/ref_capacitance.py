"""Twin of bearing_fmu.kernels.capacitance: contact, ball and bearing capacitance.

Farah et al. (2020), eqs. 8, 10-12: parallel-plate capacitor over the Hertz ellipse,
C = eps_0 eps_r(p) A / h_c with A = pi a b; eps_r from Clausius-Mossotti at the Dowson-Higginson
density at the Hertz pressure (max, or mean = 2/3 max); inner and outer contacts of a ball in
series, balls in parallel; a ball without contact on either ring contributes nothing.
"""

import math

from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import elliprd, elliprf

from . import ref_lubricant

# Vacuum permittivity, CODATA 2018 (the value the kernel documents). scipy.constants.epsilon_0 is
# CODATA 2022 (8.8541878188e-12 F/m), 6.8e-10 relative higher; the unit test checks the two agree to
# that revision so that the capacitance comparisons can stay at closed-form precision.
epsilon_0 = 8.8541878128e-12  # F/m

PRESSURE_MAX = 0  # same codes as kernels.capacitance (checked by the unit test)
PRESSURE_MEAN = 1


def contact_permittivity(K_cm, rho0, p_max, pressure_choice):
    """eps_r at the maximum Hertz pressure, or at the mean pressure Q/(pi a b) = (2/3) p_max."""
    p = p_max if pressure_choice == PRESSURE_MAX else 2.0 * p_max / 3.0
    rho = ref_lubricant.dowson_higginson_density(rho0, p)
    return ref_lubricant.permittivity_from_density(K_cm, rho)


def contact_capacitance(eps_r, a, b, h_c, h_floor):
    """eps_0 eps_r pi a b / h with h = max(h_c, h_floor); open contact (no area or h_c = inf) -> 0."""
    area = math.pi * a * b
    if area == 0.0 or math.isinf(h_c):
        return 0.0
    h = max(h_c, h_floor)
    return epsilon_0 * eps_r * area / h


def ball_capacitance(C_inner, C_outer):
    """Series: 1/C = 1/C_i + 1/C_o; 0 if either contact is open (no conduction path)."""
    if C_inner == 0.0 or C_outer == 0.0:
        return 0.0
    return 1.0 / (1.0 / C_inner + 1.0 / C_outer)


def bearing_capacitance(C_inner, C_outer, C_background):
    """Balls in parallel plus the background term."""
    return C_background + sum(ball_capacitance(ci, co) for ci, co in zip(C_inner, C_outer))


def hertz_gap_terms(a, b, p_max, E_red):
    """(c, 1/(2 Rx), 1/(2 Ry), delta) of the Hertz contact with semi-axes a (y), b (x) and maximum pressure p_max.

    The pressure p_max sqrt(1 - x^2/b^2 - y^2/a^2) displaces the two surfaces together by (Johnson 1985, section
    3.4, the potential of an ellipsoid; Boussinesq with 1/E* = 2/E')
      u(x, y) = c int_lam^inf [1 - x^2/(b^2+w) - y^2/(a^2+w)] dw / sqrt(w (a^2+w) (b^2+w)),  c = p_max a b / E',
    lam = 0 inside the ellipse, else the positive root of x^2/(b^2+lam) + y^2/(a^2+lam) = 1. Inside, u =
    delta - x^2/(2 Rx) - y^2/(2 Ry) (the surfaces conform), which gives the approach and the curvatures, here in
    Carlson's symmetric integrals: int_0^inf dw/sqrt(w (w+a^2)(w+b^2)) = 2 R_F(a^2, b^2, 0),
    int_0^inf dw/((w+b^2)^1.5 sqrt(w (w+a^2))) = (2/3) R_D(a^2, 0, b^2).
    """
    c = p_max * a * b / E_red
    a2, b2 = a * a, b * b
    return c, c * 2.0 / 3.0 * elliprd(a2, 0.0, b2), c * 2.0 / 3.0 * elliprd(b2, 0.0, a2), c * 2.0 * elliprf(a2, b2, 0.0)


def hertz_gap(x, y, a, b, p_max, E_red):
    """Separation g (m) of the Hertz-loaded surfaces at (x, y) (x rolling, y across): x^2/(2 Rx) + y^2/(2 Ry)
    - delta + u(x, y), u in Carlson's integrals shifted to lam (w = lam + t); 0 inside the ellipse."""
    if (x / b) ** 2 + (y / a) ** 2 <= 1.0:
        return 0.0
    c, cx, cy, delta = hertz_gap_terms(a, b, p_max, E_red)
    a2, b2 = a * a, b * b
    # lam^2 + lam (a^2 + b^2 - x^2 - y^2) + a^2 b^2 - x^2 a^2 - y^2 b^2 = 0, positive root
    p = a2 + b2 - x * x - y * y
    q = a2 * b2 - x * x * a2 - y * y * b2
    lam = max(0.0, 0.5 * (-p + math.sqrt(max(0.0, p * p - 4.0 * q))))  # (rounding on the ellipse's edge)
    u = c * (
        2.0 * elliprf(lam + a2, lam + b2, lam)
        - x * x * 2.0 / 3.0 * elliprd(lam + a2, lam, lam + b2)
        - y * y * 2.0 / 3.0 * elliprd(lam + b2, lam, lam + a2)
    )
    return x * x * cx + y * y * cy - delta + u


def outside_hertz_capacitance(eps_r, a, b, p_max, E_red, h_c, h_oil, h_floor):
    """Brute force: eps_0 times the integral over the plane outside the Hertz ellipse where h_c + g <= h_oil of
    eps_r / h on the inlet side (x < 0, oil) and (1 + (eps_r - 1) h_c / h) / h on the outlet side (x > 0,
    cavitated: oil streamers a fraction h_c/h of the gap, air between), h = h_c + g(x, y), h_c bounded below by
    h_floor; g from hertz_gap. Adaptive scipy quadrature in the ellipse's polar coordinates x = b rho cos psi,
    y = a rho sin psi (area a b rho d rho d psi), rho - 1 = exp(v) (the edge layer resolved), the outer bound
    rho_max(psi) by brentq on h = h_oil; one quadrant of each half, doubled (the gap is even in x and y)."""
    if a <= 0.0 or b <= 0.0 or p_max <= 0.0 or math.isinf(h_c):
        return 0.0
    h0 = max(h_c, h_floor)
    if h_oil <= h0:
        return 0.0

    def gap(rho, psi):
        return h0 + hertz_gap(b * rho * math.cos(psi), a * rho * math.sin(psi), a, b, p_max, E_red)

    def rho_max(psi):
        hi = 2.0
        while gap(hi, psi) < h_oil:
            hi *= 2.0
        return brentq(lambda r: gap(r, psi) - h_oil, 1.0, hi, xtol=1e-14, rtol=1e-13)

    def quadrant(weight):
        def inner(psi):
            v_hi = math.log(rho_max(psi) - 1.0)

            def f(v):
                rho = 1.0 + math.exp(v)
                return weight(gap(rho, psi)) * a * b * rho * math.exp(v)

            return quad(f, math.log(1e-10), v_hi, epsabs=0.0, epsrel=1e-9, limit=200)[0]

        return quad(inner, 0.0, 0.5 * math.pi, epsabs=0.0, epsrel=1e-8, limit=200)[0]

    inlet = quadrant(lambda h: eps_r / h)
    outlet = quadrant(lambda h: (1.0 + (eps_r - 1.0) * h0 / h) / h)
    return epsilon_0 * 2.0 * (inlet + outlet)


def lubricated_contact_capacitance(
    K_cm, rho0, p_max, pressure_choice, a, b, h_c, h_floor, E_red, h_oil, outside=outside_hertz_capacitance
):
    """The Hertz zone (eps_r at the contact pressure) plus, for h_oil > 0, the oil-filled gap around it (eps_r at
    ambient pressure, p = 0). outside: the outside-Hertz term, by default this module's brute force (a fraction of
    a second a contact); the assembly twins pass assembly_outside (see there)."""
    C = contact_capacitance(contact_permittivity(K_cm, rho0, p_max, pressure_choice), a, b, h_c, h_floor)
    if h_oil > 0.0:
        C += outside(contact_permittivity(K_cm, rho0, 0.0, PRESSURE_MAX), a, b, p_max, E_red, h_c, h_oil, h_floor)
    return C


def assembly_outside(*args):
    """The outside-Hertz term as the assembly twins (ref_radial_bearing, ref_contact_outputs,
    ref_ball_dynamics_integrator) take it: the kernel's value. They twin which contacts count and how (series,
    parallel, the eps_r of each region); the term itself is compared with outside_hertz_capacitance above in
    tests/unit/test_capacitance.py, and the brute force, run for every contact of every refresh, would make the
    assembly comparisons minutes long."""
    from bearing_fmu.kernels.capacitance import outside_hertz_capacitance as kernel

    return kernel(*args)


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.capacitance"
TWINS = {
    "contact_permittivity": contact_permittivity,
    "contact_capacitance": contact_capacitance,
    "ball_capacitance": ball_capacitance,
    "bearing_capacitance": bearing_capacitance,
    "outside_hertz_capacitance": outside_hertz_capacitance,
    "lubricated_contact_capacitance": lubricated_contact_capacitance,
}
