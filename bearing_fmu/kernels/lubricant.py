"""Lubricant properties: viscosity-temperature, pressure-viscosity, density and permittivity (docs/parameters.md).

SI units: T in K, p in Pa, kinematic viscosity nu in m^2/s, dynamic viscosity in Pa.s.
Temperature models are selected by integer codes (never by module state):
  VISCOSITY_CONSTANT, VISCOSITY_WALTHER (ASTM D341), VISCOSITY_WLF (modified WLF, Bair);
  PIEZO_CONSTANT, PIEZO_GOLD (alpha = s nu^t), PIEZO_WLF (alpha* of the WLF law).
The per-lubricant numbers travel in one float64 array ``lub`` whose layout is fixed by
``LUB_*`` indices below (built by bearing_fmu.params.lubricant_array).
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

VISCOSITY_CONSTANT = 0
VISCOSITY_WALTHER = 1
VISCOSITY_WLF = 2

PIEZO_CONSTANT = 0
PIEZO_GOLD = 1
PIEZO_WLF = 2

DENSITY_LINEAR = 0
DENSITY_MURNAGHAN = 1

# layout of the lubricant parameter array
_LUB_SLOTS = Layout()
LUB_VISC_MODEL = _LUB_SLOTS.slot()
LUB_ETA_CONST = _LUB_SLOTS.slot()  # Pa.s
LUB_WALTHER_A = _LUB_SLOTS.slot()  # -
LUB_WALTHER_B = _LUB_SLOTS.slot()  # -
LUB_PIEZO_MODEL = _LUB_SLOTS.slot()
LUB_XI_CONST = _LUB_SLOTS.slot()  # 1/Pa
LUB_GOLD_S = _LUB_SLOTS.slot()  # 1/Pa
LUB_GOLD_T = _LUB_SLOTS.slot()  # -
LUB_DENS_MODEL = _LUB_SLOTS.slot()
LUB_RHO_REF = _LUB_SLOTS.slot()  # kg/m^3
LUB_T_REF = _LUB_SLOTS.slot()  # K
LUB_EXPANSION = _LUB_SLOTS.slot()  # 1/K
LUB_EPS_R0 = _LUB_SLOTS.slot()  # -
LUB_WLF_MU_G = _LUB_SLOTS.slot()  # Pa.s
LUB_WLF_TG0 = _LUB_SLOTS.slot()  # K
LUB_WLF_A1 = _LUB_SLOTS.slot()  # K
LUB_WLF_A2 = _LUB_SLOTS.slot()  # 1/Pa
LUB_WLF_B1 = _LUB_SLOTS.slot()  # 1/Pa
LUB_WLF_B2 = _LUB_SLOTS.slot()  # -
LUB_WLF_C1 = _LUB_SLOTS.slot()  # -
LUB_WLF_C2 = _LUB_SLOTS.slot()  # K
LUB_MURN_BETA_K = _LUB_SLOTS.slot()  # 1/K
LUB_MURN_K_MM = _LUB_SLOTS.slot()  # Pa
LUB_MURN_K_PRIME = _LUB_SLOTS.slot()  # -
LUB_SIZE = _LUB_SLOTS.size

KELVIN_OFFSET = 273.15


@kernel
def walther_constants(nu1, T1, nu2, T2):
    """ASTM D341 (Walther) constants (A, B) from two kinematic viscosities nu (m^2/s) at T (K).

    log10(log10(nu_cSt + 0.7)) = A - B log10(T); valid for nu >= 2 mm^2/s.
    """
    z1 = math.log10(math.log10(nu1 * 1e6 + 0.7))
    z2 = math.log10(math.log10(nu2 * 1e6 + 0.7))
    B = (z1 - z2) / (math.log10(T2) - math.log10(T1))
    A = z1 + B * math.log10(T1)
    return A, B


@kernel
def walther_viscosity(T, A, B):
    """Kinematic viscosity (m^2/s) at T (K) from ASTM D341 constants."""
    return (10.0 ** (10.0 ** (A - B * math.log10(T))) - 0.7) * 1e-6


@kernel
def density_linear(T, rho_ref, T_ref, expansion):
    """Density (kg/m^3) at p = 0: rho_ref / (1 + a (T - T_ref)), a the volumetric expansion (1/K)."""
    return rho_ref / (1.0 + expansion * (T - T_ref))


@kernel
def murnaghan_density(p, T, rho_R, T_R, a_v, beta_K, K_MM, K_prime):
    """Murnaghan equation of state (Wheeler 2016 thesis eqs. 2.1-7, 2.1-8): density (kg/m^3) at p (Pa), T (K)."""
    rho_0 = rho_R / (1.0 + a_v * (T - T_R))
    K_M = K_MM * math.exp(-beta_K * T)
    return rho_0 * (1.0 + K_prime / K_M * p) ** (1.0 / K_prime)


@kernel
def wlf_viscosity(p, T, mu_G, T_g0, A1, A2, b1, b2, C1, C2):
    """Modified WLF viscosity (Pa.s) at p (Pa), T (K) (Bair; Wheeler 2016 thesis eq. 2.1-9).

    T_g(p) = T_g0 + A1 ln(1 + A2 p);  F(p) = (1 + b1 p)^b2;
    mu = mu_G exp[-2.303 C1 (T - T_g) F / (C2 + (T - T_g) F)].
    """
    Tg = T_g0 + A1 * math.log(1.0 + A2 * p)
    F = (1.0 + b1 * p) ** b2
    dT = (T - Tg) * F
    return mu_G * math.exp(-2.303 * C1 * dT / (C2 + dT))


@kernel
def wlf_ratio(p, T, mu0, mu_G, T_g0, A1, A2, b1, b2, C1, C2):
    """mu(0)/mu(p) (-) of the modified WLF law; 0 past the law's glass singularity
    C2 + (T - T_g) F = 0, where the viscosity diverges (the fluid is glassy)."""
    Tg = T_g0 + A1 * math.log(1.0 + A2 * p)
    dT = (T - Tg) * (1.0 + b1 * p) ** b2
    if C2 + dT <= 0.0:
        return 0.0
    return mu0 / (mu_G * math.exp(-2.303 * C1 * dT / (C2 + dT)))


@kernel
def wlf_alpha_star(T, mu_G, T_g0, A1, A2, b1, b2, C1, C2):
    """Reciprocal asymptotic isoviscous pressure-viscosity coefficient alpha* (1/Pa) of the WLF law.

    alpha* = [int_0^inf mu(0)/mu(p) dp]^-1 (Blok; Bair 2007, High Pressure Rheology, ch. 9).
    Composite Simpson in 2 MPa panels (about 25 per e-fold for alpha* ~ 2e-8 1/Pa) until the
    integrand falls below 1e-15; beyond the glass singularity the integrand is 0.
    """
    mu0 = wlf_viscosity(0.0, T, mu_G, T_g0, A1, A2, b1, b2, C1, C2)
    dp = 2e6
    total = 0.0
    p = 0.0
    f0 = 1.0
    for _ in range(100000):
        f1 = wlf_ratio(p + dp, T, mu0, mu_G, T_g0, A1, A2, b1, b2, C1, C2)
        f2 = wlf_ratio(p + 2.0 * dp, T, mu0, mu_G, T_g0, A1, A2, b1, b2, C1, C2)
        total += dp / 3.0 * (f0 + 4.0 * f1 + f2)
        if f2 < 1e-15:
            break
        p += 2.0 * dp
        f0 = f2
    return 1.0 / total


@kernel
def gold_pressure_viscosity(nu, s, t):
    """Pressure-viscosity coefficient (1/Pa) alpha = s (nu / 1 mm^2/s)^t (Gold et al. 2001); nu in m^2/s."""
    return s * (nu * 1e6) ** t


@kernel
def dowson_higginson_density(rho0, p):
    """Dowson-Higginson density (kg/m^3) at pressure p (Pa): rho0 (0.59e9 + 1.34 p) / (0.59e9 + p)."""
    return rho0 * (0.59e9 + 1.34 * p) / (0.59e9 + p)


@kernel
def clausius_mossotti_constant(eps_r0, rho0):
    """Clausius-Mossotti constant K (m^3/kg) = (eps_r0 - 1) / ((eps_r0 + 2) rho0)."""
    return (eps_r0 - 1.0) / ((eps_r0 + 2.0) * rho0)


@kernel
def permittivity_from_density(K_cm, rho):
    """Relative permittivity (-) eps_r = (1 + 2 K rho) / (1 - K rho) (Clausius-Mossotti)."""
    return (1.0 + 2.0 * K_cm * rho) / (1.0 - K_cm * rho)


@kernel
def wlf_constants(lub):
    """The WLF law's constants (mu_G, T_g0, A1, A2, b1, b2, C1, C2) in the lubricant array, in the order of
    wlf_viscosity's and wlf_alpha_star's arguments."""
    return (lub[LUB_WLF_MU_G], lub[LUB_WLF_TG0], lub[LUB_WLF_A1], lub[LUB_WLF_A2], lub[LUB_WLF_B1], lub[LUB_WLF_B2],
            lub[LUB_WLF_C1], lub[LUB_WLF_C2])  # fmt: skip


@kernel
def lubricant_state(T, lub):
    """Ambient-pressure state of the lubricant at temperature T (K).

    Returns (eta, xi, rho0): dynamic viscosity (Pa.s), pressure-viscosity coefficient (1/Pa) and
    density (kg/m^3) at p = 0.
    """
    if int(lub[LUB_DENS_MODEL]) == DENSITY_MURNAGHAN:
        rho0 = murnaghan_density(
            0.0,
            T,
            lub[LUB_RHO_REF],
            lub[LUB_T_REF],
            lub[LUB_EXPANSION],
            lub[LUB_MURN_BETA_K],
            lub[LUB_MURN_K_MM],
            lub[LUB_MURN_K_PRIME],
        )
    else:
        rho0 = density_linear(T, lub[LUB_RHO_REF], lub[LUB_T_REF], lub[LUB_EXPANSION])
    visc = int(lub[LUB_VISC_MODEL])
    if visc == VISCOSITY_WALTHER:
        nu = walther_viscosity(T, lub[LUB_WALTHER_A], lub[LUB_WALTHER_B])
        eta = nu * rho0
    elif visc == VISCOSITY_WLF:
        eta = wlf_viscosity(0.0, T, *wlf_constants(lub))
        nu = eta / rho0
    else:
        eta = lub[LUB_ETA_CONST]
        nu = eta / rho0
    piezo = int(lub[LUB_PIEZO_MODEL])
    if piezo == PIEZO_GOLD:
        xi = gold_pressure_viscosity(nu, lub[LUB_GOLD_S], lub[LUB_GOLD_T])
    elif piezo == PIEZO_WLF:
        xi = wlf_alpha_star(T, *wlf_constants(lub))
    else:
        xi = lub[LUB_XI_CONST]
    return eta, xi, rho0
