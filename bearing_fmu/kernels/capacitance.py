"""Electrical capacitance of lubricated ball-race contacts and of the bearing (Farah et al.; docs/decisions.md).

Farah et al. (2020), eqs. 8, 10-12: parallel-plate capacitor over the Hertz ellipse,
  C = eps_0 eps_r(p) pi a b / h_c,
eps_r from Clausius-Mossotti at the Dowson-Higginson density at the contact pressure;
per ball the inner and outer contacts in series; the balls in parallel (insulating cage).
A ball that has lost contact with either ring contributes nothing (Farah: only balls in the
loaded zone count).
"""

from bearing_fmu_common.jit import kernel

from .lubricant import dowson_higginson_density, permittivity_from_density

EPSILON_0 = 8.8541878128e-12  # F/m, vacuum permittivity (CODATA 2018)

PRESSURE_MAX = 0  # eps_r evaluated at the Hertz maximum pressure (default, Farah)
PRESSURE_MEAN = 1  # eps_r evaluated at the mean Hertz pressure (2/3 p_max)


@kernel
def contact_permittivity(K_cm, rho0, p_max, pressure_choice):
    """Relative permittivity (-) of the film at the Hertz maximum (or mean) pressure p_max (Pa)."""
    p = p_max if pressure_choice == PRESSURE_MAX else p_max * (2.0 / 3.0)
    return permittivity_from_density(K_cm, dowson_higginson_density(rho0, p))


@kernel
def contact_capacitance(eps_r, a, b, h_c, h_floor):
    """Parallel-plate capacitance (F) of one contact: eps_0 eps_r pi a b / max(h_c, h_floor).

    a, b: Hertz semi-axes (m); h_c: central film thickness (m). An open contact (a b = 0 or
    h_c = inf) gives 0. h_floor (m) bounds the capacitance when the film vanishes (rest, boundary
    regime), where the real contact turns resistive and the plate model loses meaning.
    """
    area = 3.141592653589793 * a * b
    if area <= 0.0:
        return 0.0
    h = h_c if h_c > h_floor else h_floor
    return EPSILON_0 * eps_r * area / h


@kernel
def ball_capacitance(C_inner, C_outer):
    """Capacitance (F) of one ball: inner and outer contacts in series; 0 if either contact is open."""
    if C_inner <= 0.0 or C_outer <= 0.0:
        return 0.0
    return C_inner * C_outer / (C_inner + C_outer)


@kernel
def bearing_capacitance(C_inner, C_outer, C_background):
    """Bearing capacitance (F): balls in parallel plus an optional background term (F, 0 by default)."""
    total = C_background
    for j in range(C_inner.shape[0]):
        total += ball_capacitance(C_inner[j], C_outer[j])
    return total
