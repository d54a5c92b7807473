"""The two race contacts of a bearing as the facades pack them: the free contact angle, the reduced radii,
the Hertz coefficients and modulus, and the contact terms the quasi-static (kernels.contacts CP_*) and DEM
(kernels.ball_dynamics.state P_*) parameter arrays share under the same slot names."""

import math
from typing import NamedTuple

from ..kernels.geometry import curvature_radii, free_contact_angle
from ..kernels.hertz import hertz_coefficients_approx, hertz_coefficients_exact, reduced_modulus
from ..kernels.torque import ALPHA_HYSTERESIS_STEEL
from ..scene import FILM_FORMULAS, PERMITTIVITY_PRESSURES


class RaceContacts(NamedTuple):
    alpha0: float  # rad, free contact angle of the clearance P_d (0 for P_d <= 0)
    Rx_i: float  # m, reduced radii of the inner contact (rolling direction, across the groove)
    Ry_i: float
    Rx_o: float  # m, the same of the outer contact
    Ry_o: float
    ci: tuple  # Hertz coefficients (k, E, K) of the inner contact (kernels.hertz)
    co: tuple  # and of the outer one
    E_red: float  # Pa, reduced modulus of ball and rings


def race_contacts(bearing, scene, Pd):
    """RaceContacts of `bearing` at the diametral clearance Pd (m), with the scene's Hertz coefficients
    (exact or Hamrock-Brewe)."""
    b = bearing
    alpha0 = free_contact_angle(b.D, b.f_i, b.f_o, Pd) if Pd > 0.0 else 0.0
    Rx_i, Ry_i, Rx_o, Ry_o = curvature_radii(b.D, b.dm, b.f_i, b.f_o, alpha0)
    coefficients = hertz_coefficients_exact if scene.hertz == "exact" else hertz_coefficients_approx
    E_red = reduced_modulus(b.ball.E, b.ball.nu, b.ring.E, b.ring.nu)
    return RaceContacts(alpha0, Rx_i, Ry_i, Rx_o, Ry_o, coefficients(Rx_i, Ry_i), coefficients(Rx_o, Ry_o), E_red)


def contact_terms(bearing, scene, rc):
    """Slot name (without its array's prefix) -> value of the contact terms both fidelities' arrays hold:
    radii (m), Hertz coefficients, reduced modulus (Pa), composite roughness (m), film and permittivity
    options (codes), film floor (m), hysteresis factor, conformities."""
    b = bearing
    return {
        "RX_I": rc.Rx_i,
        "RY_I": rc.Ry_i,
        "K_I": rc.ci[0],
        "EE_I": rc.ci[1],
        "KK_I": rc.ci[2],
        "RX_O": rc.Rx_o,
        "RY_O": rc.Ry_o,
        "K_O": rc.co[0],
        "EE_O": rc.co[1],
        "KK_O": rc.co[2],
        "E_RED": rc.E_red,
        "SIGMA_I": scene.roughness_factor * math.hypot(b.Ra_inner, b.Ra_ball),
        "SIGMA_O": scene.roughness_factor * math.hypot(b.Ra_outer, b.Ra_ball),
        "FILM": FILM_FORMULAS[scene.film],
        "PRESSURE": PERMITTIVITY_PRESSURES[scene.permittivity_pressure],
        "H_FLOOR": scene.film_floor,
        "ALPHA_H": ALPHA_HYSTERESIS_STEEL,
        "F_I": b.f_i,
        "F_O": b.f_o,
    }


def pack(array, slots, prefix, terms):
    """array[slots.<prefix><name>] = value for each term (slots: the module that names the array's slots)."""
    for name, value in terms.items():
        array[getattr(slots, prefix + name)] = value
