"""Twin of bearing_fmu.kernels.lubrication: the film factors and the ball drag of a lubrication method.

Written from the sources (docs/lubrication_method.md), not from the kernel: the Hertz inlet gap is the integral
of its slope sqrt(x^2 - b^2)/Rx outside the contact (Johnson 1985, Contact Mechanics, ch. 4: the surfaces of a
Hertz line contact separate with that slope), by quadrature; the meniscus is found by brentq; the drag is
(1/2) C_D rho A v^2 times v with C_D of the sphere (Schiller-Naumann, Newton's 0.44); the temperature-viscosity
coefficient is the derivative of ln(eta) by a five-point difference of the twin oil state.
"""

import math
from decimal import Decimal

from scipy.integrate import quad
from scipy.optimize import brentq

from . import ref_lubricant

AIR_DENSITY = 1.2
AIR_VISCOSITY = 1.8e-5


def temperature_viscosity_coefficient(T, lub):
    """-d ln(eta)/dT (1/K): five-point central difference with h = 0.25 K of ln(eta) of ref_lubricant, summed as the
    differences across T (8 [ln eta(T + h) - ln eta(T - h)] - [ln eta(T + 2h) - ln eta(T - 2h)]) / 12h: exactly 0 for
    a constant viscosity, where a sum in another order leaves a rounding residue (4e-16 1/K) that the thermal
    loading's L^0.64 turns into a film factor 1e-6 below 1."""
    h = 0.25

    def ln_eta(t):
        return math.log(ref_lubricant.lubricant_state(t, lub)[0])

    d = (8 * (ln_eta(T + h) - ln_eta(T - h)) - (ln_eta(T + 2 * h) - ln_eta(T - 2 * h))) / (12 * h)
    return -d


def thermal_loading(beta, eta, u, k_f):
    return beta * eta * u**2 / k_f


def inlet_shear_heating_factor(L, p_h, E_red):
    """Gupta et al. 1992, pure rolling: (1 - 13.2 (p_h/E') L^0.42)/(1 + 0.213 L^0.64), numerator >= 0."""
    if L <= 0.0:
        return 1.0
    return max(1.0 - 13.2 * p_h / E_red * L**0.42, 0.0) / (1.0 + 0.213 * L**0.64)


def hertz_inlet_gap(X, b, Rx):
    """Gap at |x| = X b: integral from b to X b of sqrt(x^2 - b^2)/Rx dx, by quadrature in x = b cosh(t) (the
    integrand b^2 sinh(t)^2 / Rx is smooth where the slope's square root is not)."""
    if X <= 1.0:
        return 0.0
    value, _ = quad(lambda t: math.sinh(t) ** 2, 0.0, math.acosh(X), epsabs=0.0, epsrel=1e-13)
    return b * b / Rx * value


def critical_inlet_distance(H, Rx, b, c, e):
    return 1.0 + c * ((Rx / b) ** 2 * H) ** e


def starvation_factor(m, m_star, exponent):
    if m >= m_star:
        return 1.0
    if m <= 1.0:
        return 0.0
    return ((m - 1.0) / (m_star - 1.0)) ** exponent


def inlet_meniscus(h_c, m_star, m_cap, Rx, b, h_oil):
    """The root of h_c phi_c(m) + g(m) = h_oil in ]1, m_cap] by brentq; m_cap when the layer fills the gap there."""

    def f(m):
        return h_c * starvation_factor(m, m_star, 0.29) + hertz_inlet_gap(m, b, Rx) - h_oil

    if f(m_cap) <= 0.0:
        return m_cap
    return brentq(f, 1.0, m_cap, xtol=1e-15, rtol=1e-15, maxiter=500)


def film_factors(h_c, h_min, u, p_h, b, Rx, E_red, eta, beta, k_f, thermal, h_oil):
    if not (0.0 < h_c < math.inf):
        return 1.0, 1.0, 1.0
    phi_t = inlet_shear_heating_factor(thermal_loading(beta, eta, u, k_f), p_h, E_red) if thermal > 0.5 else 1.0
    if h_oil == math.inf or phi_t <= 0.0:
        return phi_t, 1.0, 1.0
    m_c = critical_inlet_distance(phi_t * h_c / Rx, Rx, b, 3.06, 0.58)
    m_m = critical_inlet_distance(phi_t * h_min / Rx, Rx, b, 3.34, 0.56)
    m = inlet_meniscus(phi_t * h_c, m_c, max(m_c, m_m), Rx, b, h_oil)
    return phi_t, starvation_factor(m, m_c, 0.29), starvation_factor(m, m_m, 0.25)


def rolling_force_factor(phi_ish, phi_rs_c):
    return (phi_ish * phi_rs_c) ** (0.656 / 0.67)


def ball_drag_power(v, D, rho_e, eta_e, area_fraction):
    """F |v|, F = (1/2) C_D(Re) rho_e (pi D^2/4) area_fraction v^2, C_D = Schiller & Naumann's 24/Re (1 + 0.15
    Re^0.687) up to Re = 1000, 0.44 above, evaluated in
    decimal arithmetic (28 significant digits, exponents far beyond float64's): at Re -> 0 the float C_D = 24/Re
    overflows to inf while v^2 underflows to 0 (their product NaN); the result is rounded to a float once
    (0.0 where the power is below the smallest float)."""
    if v == 0.0 or area_fraction <= 0.0 or rho_e <= 0.0:
        return 0.0
    s, D, rho, eta, f = (Decimal(x) for x in (abs(v), D, rho_e, eta_e, area_fraction))
    Re = rho * s * D / eta
    C_D = Decimal(24) / Re * (1 + Decimal("0.15") * Re ** Decimal("0.687")) if Re <= 1000 else Decimal("0.44")
    F = C_D * rho * Decimal(math.pi) * D * D / 8 * f * s * s
    return float(F * s)


def mixture(X, rho_oil, eta_oil):
    if X >= 1.0:
        return rho_oil, eta_oil
    return X * rho_oil + (1.0 - X) * AIR_DENSITY, X * eta_oil + (1.0 - X) * AIR_VISCOSITY


# the kernels this module twins (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.lubrication"
TWINS = {
    "temperature_viscosity_coefficient": temperature_viscosity_coefficient,
    "thermal_loading": thermal_loading,
    "inlet_shear_heating_factor": inlet_shear_heating_factor,
    "hertz_inlet_gap": hertz_inlet_gap,
    "critical_inlet_distance": critical_inlet_distance,
    "starvation_factor": starvation_factor,
    "inlet_meniscus": inlet_meniscus,
    "film_factors": film_factors,
    "rolling_force_factor": rolling_force_factor,
    "ball_drag_power": ball_drag_power,
    "mixture": mixture,
}
