"""One lubricated ball-race contact as the static fidelities evaluate it: Hertz, EHL film, film factors, Λ, capacitance.

The analytic fidelity (kernels.radial_bearing) and the quasi-static one (kernels.contact_outputs) evaluate each
contact from its load and entrainment speed by the same steps; they are written once here so that both fidelities
give the same contact for the same load (docs/quasistatic.md, docs/lubrication_method.md):
1. Hertz contact (kernels.hertz) of the race's contact geometry;
2. the fully flooded isothermal film (kernels.film_correction: the formula, times the numerical solver's ratio
   where the film table is on);
3. the lubrication method's inlet shear heating and starvation factors on a loaded contact (kernels.lubrication);
4. the film parameter Λ (kernels.ehl) and, on a loaded contact with the capacitance submodel on, its capacitance
   (kernels.capacitance).
Each fidelity packs its own parameter array, which embeds the film correction, lubrication method and capacitance
blocks at offsets of its own; it hands over the constants these steps read as tuples (SI units).
"""

from bearing_fmu_common.jit import kernel

from .capacitance import CAP_H_FLOOR, CAP_OIL_GAP, CAP_ON, CAP_PRESSURE, lubricated_contact_capacitance
from .ehl import film_parameter
from .film_correction import corrected_film_thickness
from .hertz import hertz_contact
from .lubricant import LUB_EPS_R0, LUB_RHO_REF, clausius_mossotti_constant, lubricant_state
from .lubrication import LM_H_OIL, LM_K_OIL, LM_ON, LM_THERMAL, film_factors, temperature_viscosity_coefficient

# The kernels here are inlined into their callers: called once per contact with their tuples they would cost the
# quasi-static contact outputs about 40 % more time. The film table travels beside the tuples, not in one: an array
# inside a tuple unpacked per contact cost the quasi-static contact outputs another 2 %.

# where lubricated_contact's `method` holds the submodel switches its callers read as well
METHOD_LUBRICATED = 2
METHOD_CAPACITANCE = 6


@kernel(inline="always")
def oil_state(T_oil, lub, lubricated, thermal, capacitance):
    """(eta, xi, rho0, beta, K_cm) of the oil at T_oil (K): viscosity (Pa.s), pressure-viscosity coefficient (1/Pa),
    density (kg/m^3), temperature-viscosity coefficient (1/K; 0 unless the lubrication method (lubricated) heats the
    inlet (thermal)) and Clausius-Mossotti constant (m^3/kg; 0 without the capacitance submodel, which alone reads
    it): the submodels that are off cost nothing."""
    eta, xi, rho0 = lubricant_state(T_oil, lub)
    beta = 0.0
    if lubricated and thermal:
        beta = temperature_viscosity_coefficient(T_oil, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF]) if capacitance else 0.0
    return eta, xi, rho0, beta, K_cm


@kernel(inline="always")
def contact_method(arr, slots):
    """lubricated_contact's `method` from a fidelity's parameter array arr, in which slots gives the index of E_red
    and of the film formula code, then the offsets of the blocks the fidelity embeds: the lubrication method
    (kernels.lubrication LM_*) and the capacitance submodel (kernels.capacitance CAP_*). The film correction table
    (kernels.film_correction FT_*) is the caller's slice of arr from its offset to the end."""
    e_red, film, lm, cap = slots
    return (arr[e_red], int(arr[film]), arr[lm + LM_ON] > 0.5, arr[lm + LM_K_OIL], arr[lm + LM_THERMAL],
            arr[lm + LM_H_OIL], arr[cap + CAP_ON] > 0.5, int(arr[cap + CAP_PRESSURE]), arr[cap + CAP_H_FLOOR],
            arr[cap + CAP_OIL_GAP])  # fmt: skip


@kernel(inline="always")
def lubricated_contact(Q, u, race, shape, oil, method, film_table):
    """One contact under the load Q (N) at the entrainment speed u (m/s) of race 0 (inner) or 1 (outer).

    shape = (Rx, Ry, k, E, K, sigma): radii (m), ellipticity and elliptic integrals (-), composite roughness (m) of
    the race's contact; oil = oil_state(...); method = (E_red (Pa), film formula code, lubricated, k_oil (W/(m K)),
    thermal (1 = inlet heating on), h_oil (m), capacitance, permittivity pressure choice, capacitance film floor (m),
    oil-availability gap (m)), lubricated and capacitance booleans; film_table: the film correction table
    (kernels.film_correction FT_*).
    Returns (a, b, p, h_c, h_min, Lambda, C, phi_t, phi_c): Hertz semi-axes (m) and pressure (Pa), the films (m)
    with the method's factors, the film parameter (-), the capacitance (F; 0 on an unloaded contact or without the
    submodel) and the inlet heating and starvation factors of the central film (-; 1 on an unloaded contact or
    without the method)."""
    Rx, Ry, k, ell_E, ell_K, sigma = shape
    eta, xi, rho0, beta, K_cm = oil
    E_red, film, lubricated, k_oil, thermal, h_oil, capacitance, pressure, h_floor, oil_gap = method
    a, b, _, p = hertz_contact(Q, Rx, Ry, E_red, k, ell_E, ell_K)
    hc, hm = corrected_film_thickness(film, eta, xi, E_red, u, Q, Rx, Ry, k, film_table, race)
    phi_t = 1.0
    phi_c = 1.0
    if lubricated and Q > 0.0:
        phi_t, phi_c, phi_m = film_factors(hc, hm, abs(u), p, b, Rx, E_red, eta, beta, k_oil, thermal, h_oil)
        hc *= phi_t * phi_c
        hm *= phi_t * phi_m
    lam = film_parameter(hm, sigma)
    C = 0.0
    if capacitance and Q > 0.0:
        C = lubricated_contact_capacitance(K_cm, rho0, p, pressure, a, b, hc, h_floor, E_red, oil_gap)
    return a, b, p, hc, hm, lam, C, phi_t, phi_c
