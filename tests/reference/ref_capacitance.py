"""Twin of bearing_fmu.kernels.capacitance: contact, ball and bearing capacitance.

Farah et al. (2020), eqs. 8, 10-12: parallel-plate capacitor over the Hertz ellipse,
C = eps_0 eps_r(p) A / h_c with A = pi a b; eps_r from Clausius-Mossotti at the Dowson-Higginson
density at the Hertz pressure (max, or mean = 2/3 max); inner and outer contacts of a ball in
series, balls in parallel; a ball without contact on either ring contributes nothing.
"""

import math

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


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.capacitance"
TWINS = {
    "contact_permittivity": contact_permittivity,
    "contact_capacitance": contact_capacitance,
    "ball_capacitance": ball_capacitance,
    "bearing_capacitance": bearing_capacitance,
}
