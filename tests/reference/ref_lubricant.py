"""Twin of bearing_fmu.kernels.lubricant: viscosity, pressure-viscosity, density, permittivity.

- ASTM D341 (Walther): log10(log10(nu_cSt + 0.7)) = A - B log10(T), T in K; the constants from two
  points by solving the 2x2 linear system (numpy.linalg.solve).
- Modified WLF (Bair; Wheeler 2016 thesis eq. 2.1-9): T_g = T_g0 + A1 ln(1 + A2 p), F = (1 + b1 p)^b2,
  mu = mu_G exp[-2.303 C1 (T - T_g) F / (C2 + (T - T_g) F)]; the law holds up to its glass
  singularity C2 + (T - T_g) F = 0, beyond which mu(0)/mu(p) is taken as 0 (glassy: no flow).
- alpha* = [int_0^inf mu(0)/mu(p) dp]^-1 (Blok) with scipy.integrate.quad (see wlf_alpha_star).
- Murnaghan (thesis eqs. 2.1-7, 2.1-8), linear thermal expansion, Gold et al. (2001) alpha = s nu^t,
  Dowson-Higginson density, Clausius-Mossotti permittivity (docs/parameters.md).
"""

import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from bearing_fmu.kernels import lubricant as lk  # layout constants (LUB_*) and model codes only

# the lubricant array's slots of the WLF parameters, in the order wlf_viscosity and its relatives take them
WLF_INDEX = (
    lk.LUB_WLF_MU_G,
    lk.LUB_WLF_TG0,
    lk.LUB_WLF_A1,
    lk.LUB_WLF_A2,
    lk.LUB_WLF_B1,
    lk.LUB_WLF_B2,
    lk.LUB_WLF_C1,
    lk.LUB_WLF_C2,
)


def walther_constants(nu1, T1, nu2, T2):
    """(A, B) of ASTM D341 through (T1, nu1) and (T2, nu2); nu in m^2/s (the law is in cSt)."""
    z = [math.log10(math.log10(nu * 1e6 + 0.7)) for nu in (nu1, nu2)]
    matrix = np.array([[1.0, -math.log10(T1)], [1.0, -math.log10(T2)]])
    A, B = np.linalg.solve(matrix, np.array(z))
    return float(A), float(B)


def walther_viscosity(T, A, B):
    """nu (m^2/s) = (10^(10^(A - B log10 T)) - 0.7) cSt."""
    z = A - B * math.log10(T)
    try:
        nu_cst = 10.0 ** (10.0**z) - 0.7
    except OverflowError:  # beyond the float range (far extrapolation to the cold side)
        return math.inf
    return nu_cst * 1e-6


def density_linear(T, rho_ref, T_ref, expansion):
    """rho = rho_ref / (1 + a (T - T_ref))."""
    return rho_ref / (1.0 + expansion * (T - T_ref))


def murnaghan_density(p, T, rho_R, T_R, a_v, beta_K, K_MM, K_prime):
    """rho = rho_0(T) (1 + K' p / K_M)^(1/K'), rho_0 = rho_R / (1 + a_v (T - T_R)), K_M = K_MM e^(-beta_K T)."""
    rho_0 = rho_R / (1.0 + a_v * (T - T_R))
    K_M = K_MM * math.exp(-beta_K * T)
    return rho_0 * (1.0 + K_prime * p / K_M) ** (1.0 / K_prime)


def _wlf_exponent(p, T, T_g0, A1, A2, b1, b2, C1, C2):
    """(ln(mu/mu_G), C2 + (T - T_g) F): the exponent of the WLF law and its denominator."""
    T_g = float(T_g0) + float(A1) * math.log(1.0 + float(A2) * p)
    F = (1.0 + float(b1) * p) ** float(b2)
    x = (T - T_g) * F
    denominator = float(C2) + x
    if denominator == 0.0:
        return math.inf, 0.0
    return -2.303 * float(C1) * x / denominator, denominator


def wlf_viscosity(p, T, mu_G, T_g0, A1, A2, b1, b2, C1, C2):
    """mu(p, T) (Pa s) of the modified WLF law (inf where it overflows, next to the glass singularity)."""
    exponent, _ = _wlf_exponent(p, T, T_g0, A1, A2, b1, b2, C1, C2)
    if exponent > 709.0:
        return math.inf
    return mu_G * math.exp(exponent)


def wlf_ratio(p, T, mu0, mu_G, T_g0, A1, A2, b1, b2, C1, C2):
    """mu0 / mu(p, T); 0 at and beyond the glass singularity (denominator C2 + (T - T_g) F <= 0)."""
    exponent, denominator = _wlf_exponent(p, T, T_g0, A1, A2, b1, b2, C1, C2)
    if denominator <= 0.0:
        return 0.0
    return mu0 / mu_G * math.exp(-exponent)


def wlf_glass_pressure(T, T_g0, A1, A2, b1, b2, C1, C2, p_max=1e11):
    """First pressure of [0, p_max] where the WLF law turns singular (C2 + (T - T_g) F = 0), or
    p_max if it stays regular there: scan on a log grid, then brentq."""

    def denominator(p):
        return _wlf_exponent(p, T, T_g0, A1, A2, b1, b2, C1, C2)[1]

    grid = np.concatenate(([0.0], np.logspace(5, math.log10(p_max), 2000)))
    for lo, hi in zip(grid[:-1], grid[1:]):
        if denominator(hi) <= 0.0:
            return brentq(denominator, lo, hi, xtol=1e-300, rtol=8.9e-16)
    return p_max


def wlf_alpha_star(T, mu_G, T_g0, A1, A2, b1, b2, C1, C2):
    """alpha* = 1 / int_0^inf mu(0)/mu(p) dp (1/Pa), by scipy.integrate.quad.

    The integrand is mu(0)/mu(p) up to the glass singularity and 0 beyond it. Where the law has no
    singularity (hot oil) mu(p) tends back to mu_G as (T - T_g) F -> 0, so mu(0)/mu(p) levels off at
    mu(0)/mu_G (~1e-14) and the improper integral does not strictly converge: the integral is cut at
    100 GPa, 30-100 times the contact pressures of interest, where the cut-off part is < 1e-3 Pa
    out of ~5e7 Pa (relative 2e-11). The range is split by decades so that quad resolves the
    exponential decay near 0.
    """
    mu0 = wlf_viscosity(0.0, T, mu_G, T_g0, A1, A2, b1, b2, C1, C2)
    p_end = wlf_glass_pressure(T, T_g0, A1, A2, b1, b2, C1, C2)
    edges = [0.0] + [e for e in (1e7, 1e8, 1e9, 1e10) if e < p_end] + [p_end]
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        value, _ = quad(
            wlf_ratio, lo, hi, args=(T, mu0, mu_G, T_g0, A1, A2, b1, b2, C1, C2), epsabs=0.0, epsrel=1e-13, limit=400
        )
        total += value
    return 1.0 / total


def gold_pressure_viscosity(nu, s, t):
    """alpha = s (nu / (1 mm^2/s))^t (1/Pa)."""
    nu_mm2_per_s = nu / 1e-6
    return s * nu_mm2_per_s**t


def dowson_higginson_density(rho0, p):
    """Dowson-Higginson: rho = rho0 (0.59 GPa + 1.34 p) / (0.59 GPa + p), p in Pa."""
    return rho0 * (5.9e8 + 1.34 * p) / (5.9e8 + p)


def clausius_mossotti_constant(eps_r0, rho0):
    """K from (eps - 1)/(eps + 2) = K rho at the ambient state."""
    return (eps_r0 - 1.0) / (eps_r0 + 2.0) / rho0


def permittivity_from_density(K_cm, rho):
    """eps_r solving (eps - 1)/(eps + 2) = K rho."""
    x = K_cm * rho
    return (1.0 + 2.0 * x) / (1.0 - x)


def lubricant_state(T, lub):
    """(eta, xi, rho0) at temperature T and p = 0, from the lubricant array (LUB_* layout)."""
    if int(lub[lk.LUB_DENS_MODEL]) == lk.DENSITY_MURNAGHAN:
        rho0 = murnaghan_density(
            0.0,
            T,
            lub[lk.LUB_RHO_REF],
            lub[lk.LUB_T_REF],
            lub[lk.LUB_EXPANSION],
            lub[lk.LUB_MURN_BETA_K],
            lub[lk.LUB_MURN_K_MM],
            lub[lk.LUB_MURN_K_PRIME],
        )
    else:
        rho0 = density_linear(T, lub[lk.LUB_RHO_REF], lub[lk.LUB_T_REF], lub[lk.LUB_EXPANSION])
    wlf = [lub[i] for i in WLF_INDEX]
    model = int(lub[lk.LUB_VISC_MODEL])
    if model == lk.VISCOSITY_WALTHER:
        nu = walther_viscosity(T, lub[lk.LUB_WALTHER_A], lub[lk.LUB_WALTHER_B])
        eta = nu * rho0
    elif model == lk.VISCOSITY_WLF:
        eta = wlf_viscosity(0.0, T, *wlf)
        nu = eta / rho0
    elif model == lk.VISCOSITY_CONSTANT:
        eta = lub[lk.LUB_ETA_CONST]
        nu = eta / rho0
    else:
        raise ValueError(f"unknown viscosity model {model}")
    piezo = int(lub[lk.LUB_PIEZO_MODEL])
    if piezo == lk.PIEZO_GOLD:
        xi = gold_pressure_viscosity(nu, lub[lk.LUB_GOLD_S], lub[lk.LUB_GOLD_T])
    elif piezo == lk.PIEZO_WLF:
        xi = wlf_alpha_star(T, *wlf)
    elif piezo == lk.PIEZO_CONSTANT:
        xi = lub[lk.LUB_XI_CONST]
    else:
        raise ValueError(f"unknown pressure-viscosity model {piezo}")
    return eta, xi, rho0


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.lubricant"
TWINS = {
    "walther_constants": walther_constants,
    "walther_viscosity": walther_viscosity,
    "density_linear": density_linear,
    "murnaghan_density": murnaghan_density,
    "wlf_viscosity": wlf_viscosity,
    "wlf_ratio": wlf_ratio,
    "wlf_alpha_star": wlf_alpha_star,
    "gold_pressure_viscosity": gold_pressure_viscosity,
    "dowson_higginson_density": dowson_higginson_density,
    "clausius_mossotti_constant": clausius_mossotti_constant,
    "permittivity_from_density": permittivity_from_density,
    "lubricant_state": lubricant_state,
}
