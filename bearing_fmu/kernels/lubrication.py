"""Lubrication method: starved and thermally reduced EHL film, and the drag of the balls in the oil.

docs/lubrication_method.md gives the sources, the choices and the comparison with the SKF model. SI units.
The scene's lubrication method (models.lubrication.lubrication_block) is a block of LM_SIZE numbers that each
fidelity's parameter array embeds at one offset; the flooded method (the isothermal, fully flooded contact without
drag) is the null block, all 0, with which none of these kernels is called.

Layout of the method's block (float64[LM_SIZE]):
  LM_ON: 1 = a method other than flooded (film factors on); 0 = flooded: nothing else is read
  LM_THERMAL: 1 = inlet shear heating factor on
  LM_H_OIL: inlet oil layer (m; inf = no starvation)
  LM_K_OIL: oil thermal conductivity (W/(m K))
  LM_DRAG: 1 = drag of the balls on (with the loss submodel)
  LM_DRAG_X: oil-volume fraction of the fluid the balls move through (-)
  LM_DRAG_AREA: time-mean part of a ball's frontal area in it (-)

Film factors of one contact (multiplying the flooded Hamrock-Dowson film of kernels.ehl):
- inlet shear heating, phi_ish: the thermal reduction factor of Gupta, Cheng, Zhu, Forster & Schrand (1992,
  Tribol. Trans. 35(2) 269-274, as restated by Harris & Kotzalas 2007, Essential Concepts, ch. 4; memory,
  unverified) in pure rolling (slide-to-roll ratio 0):
      phi_ish = (1 - 13.2 (p_h/E') L^0.42) / (1 + 0.213 L^0.64),  L = beta eta u^2 / k_f,
  beta = -d ln(eta)/dT the temperature-viscosity coefficient (1/K) at the oil temperature, eta (Pa.s), u the
  mean entrainment speed (m/s), k_f the oil's thermal conductivity (W/(m K)), p_h the Hertz pressure (Pa).
  The numerator is held at >= 0 (the fit's range: L up to ~100, p_h/E' ~ 0.01).
- starvation, phi_rs: Hamrock & Dowson (1977, J. Lubr. Technol. 99(1) 15-23; Hamrock & Dowson 1981, Ball
  Bearing Lubrication, ch. 9): an inlet meniscus at m b from the contact centre (b the semi-axis along the
  rolling direction) starves the contact when m < m*:
      m*_c = 1 + 3.06 ((Rx/b)^2 H_c)^0.58,     H_c,s = H_c ((m - 1)/(m*_c - 1))^0.29,
      m*_min = 1 + 3.34 ((Rx/b)^2 H_min)^0.56, H_min,s = H_min ((m - 1)/(m*_min - 1))^0.25,
  H = h/Rx the flooded films. The meniscus sits where the gap, starved central film plus the Hertz gap outside
  the contact (line contact along the centre line, Johnson 1985, Contact Mechanics, eq. 4.4x, memory):
      g(X) = (b^2 / (2 Rx)) (X sqrt(X^2 - 1) - ln(X + sqrt(X^2 - 1))),  X = |x|/b >= 1,
  is filled by the oil layer h_oil (both surfaces) that the method leaves on the track ahead of the contact
  (Wedeven, Evans & Cameron 1971, Wear 18, 301: the inlet layer sets the meniscus): h_c phi_c(m) + g(m) = h_oil.
The EHL rolling force F_R (kernels.torque) follows the central film as an effective inlet viscosity would:
F_R ~ U^0.656 and h_c ~ U^0.67 give the factor (phi_ish phi_rs,c)^(0.656/0.67).

Drag of the balls (Harris & Kotzalas 2007, Advanced Concepts, ch. 'Friction' / ball drag, memory, unverified):
each ball moving at its orbital speed v = |w_m| d_m / 2 through a fluid of density rho_e and viscosity eta_e
loses F v with F = (1/2) C_D rho_e A v^2, A = pi D^2 / 4 times the part of its frontal area in the fluid;
C_D(Re) of a sphere, Re = rho_e v D / eta_e: Schiller & Naumann (1933) 24/Re (1 + 0.15 Re^0.687) up to
Re = 1000, 0.44 above (Clift, Grace & Weber 1978, Bubbles, Drops and Particles, Table 5.2).
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .lubricant import lubricant_state
from .roots import illinois_update

# lubrication method codes (models.lubrication.METHODS)
METHOD_FLOODED = 0
METHOD_OIL_BATH = 1
METHOD_OIL_JET = 2
METHOD_OIL_AIR = 3
METHOD_GREASE = 4

# the method's block (layout in the module docstring) and the constants of its terms: the film factors ...
_LM_SLOTS = Layout()
LM_ON = _LM_SLOTS.slot()
LM_THERMAL = _LM_SLOTS.slot()
LM_H_OIL = _LM_SLOTS.slot()
LM_K_OIL = _LM_SLOTS.slot()
F_R_FILM_EXPONENT = 0.656 / 0.67  # F_R ~ U^0.656 (Houpert), h_c ~ U^0.67 (Hamrock-Dowson): effective viscosity
BETA_STEP = 0.5  # K: step of the central difference of ln(eta) in T
# ... and the drag of the balls
LM_DRAG = _LM_SLOTS.slot()
LM_DRAG_X = _LM_SLOTS.slot()
LM_DRAG_AREA = _LM_SLOTS.slot()
REYNOLDS_NEWTON = 1000.0  # sphere drag: Schiller-Naumann below, Newton's regime (C_D = 0.44) above
LM_SIZE = _LM_SLOTS.size


@kernel
def temperature_viscosity_coefficient(T, lub):
    """beta = -d ln(eta)/dT (1/K) of the lubricant array `lub` at T (K): five-point central difference of ln(eta)
    with the step 0.5 K (truncation (h^4/30) |d^5 ln(eta)/dT^5|, below 1e-8 of beta for the catalogue's oils)."""
    h = BETA_STEP
    f2 = math.log(lubricant_state(T + 2.0 * h, lub)[0]) - math.log(lubricant_state(T - 2.0 * h, lub)[0])
    f1 = math.log(lubricant_state(T + h, lub)[0]) - math.log(lubricant_state(T - h, lub)[0])
    return -(8.0 * f1 - f2) / (12.0 * h)


@kernel
def thermal_loading(beta, eta, u, k_f):
    """Thermal loading number L = beta eta u^2 / k_f (-): beta (1/K), eta (Pa.s), u entrainment speed (m/s),
    k_f thermal conductivity (W/(m K))."""
    return beta * eta * u * u / k_f


@kernel
def inlet_shear_heating_factor(L, p_h, E_red):
    """Thermal (inlet shear heating) film factor phi_ish (-) of Gupta et al. 1992 in pure rolling, L thermal
    loading (-), p_h Hertz pressure (Pa), E_red Hamrock's E' (Pa); 1 at L = 0, the numerator held at >= 0."""
    if L <= 0.0:
        return 1.0
    num = 1.0 - 13.2 * (p_h / E_red) * L**0.42
    return max(num, 0.0) / (1.0 + 0.213 * L**0.64)


@kernel
def hertz_inlet_gap(X, b, Rx):
    """Gap (m) between the surfaces at X = |x|/b >= 1 outside a Hertz contact of semi-width b (m) and radius Rx
    (m) in the rolling direction (line contact, on the centre line); 0 for X <= 1. X s - ln(X + s) = X s -
    asinh(s), s = sqrt(X^2 - 1), cancels near the edge: below s = 0.01 its series (2/3) s^3 - (1/5) s^5 +
    (3/28) s^7 (next term -(5/72) s^9: 1e-13 of the sum)."""
    if X <= 1.0:
        return 0.0
    s = math.sqrt((X - 1.0) * (X + 1.0))
    if s < 0.01:
        s2 = s * s
        return 0.5 * b * b / Rx * s * s2 * (2.0 / 3.0 - s2 * (0.2 - s2 * 3.0 / 28.0))
    return 0.5 * b * b / Rx * (X * s - math.asinh(s))


@kernel
def critical_inlet_distance(H, Rx, b, c, e):
    """Hamrock-Dowson fully flooded inlet distance m* = 1 + c ((Rx/b)^2 H)^e (-): H the flooded film over Rx
    (-), c, e = 3.06, 0.58 (central film) or 3.34, 0.56 (minimum film)."""
    r = Rx / b
    return 1.0 + c * (r * r * H) ** e


@kernel
def starvation_factor(m, m_star, exponent):
    """Hamrock-Dowson starved-film factor ((m - 1)/(m* - 1))^exponent (-), 1 for m >= m*, 0 for m <= 1."""
    if m >= m_star:
        return 1.0
    if m <= 1.0:
        return 0.0
    return ((m - 1.0) / (m_star - 1.0)) ** exponent


@kernel
def inlet_meniscus(h_c, m_star, m_cap, Rx, b, h_oil):
    """Inlet distance m (-, in units of b from the contact centre) where the oil layer h_oil (m) fills the gap,
    h_c phi_c(m) + g(m) = h_oil, searched in ]1, m_cap]: h_c the flooded central film (m), m_star its fully
    flooded inlet distance, phi_c the Hamrock-Dowson central-film factor (1 beyond m_star), g the Hertz gap
    (hertz_inlet_gap), m_cap >= m_star the distance beyond which nothing changes (the larger m* of the two films).
    Returns m_cap when the layer fills the gap there. The left side rises with m: one root, found by the Illinois
    false position."""
    f_hi = h_c * starvation_factor(m_cap, m_star, 0.29) + hertz_inlet_gap(m_cap, b, Rx) - h_oil
    if f_hi <= 0.0:
        return m_cap
    lo = 1.0
    hi = m_cap
    f_lo = -h_oil
    side = 0
    m = hi
    for _ in range(200):
        m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        f = h_c * starvation_factor(m, m_star, 0.29) + hertz_inlet_gap(m, b, Rx) - h_oil
        if f == 0.0 or hi - lo <= 1e-13 * hi:
            break
        lo, f_lo, hi, f_hi, side = illinois_update(m, f, lo, f_lo, hi, f_hi, side)  # (f = 0 stopped the search above)
    return m


@kernel
def film_factors(h_c, h_min, u, p_h, b, Rx, E_red, eta, beta, k_f, thermal, h_oil):
    """(phi_ish, phi_rs_c, phi_rs_min) (-) of one loaded, rolling contact with the flooded films h_c, h_min (m).

    u entrainment speed (m/s), p_h Hertz pressure (Pa), b semi-axis along the rolling direction (m), Rx (m),
    E_red (Pa), eta (Pa.s), beta (1/K), k_f (W/(m K)); thermal: inlet shear heating on (> 0.5); h_oil inlet oil
    layer (m, inf = no starvation). The starvation acts on the thermally reduced films. A contact without film
    (h_c <= 0: at rest) or open (h_c = inf) has the factors 1."""
    phi_t = 1.0
    if not (h_c > 0.0 and h_c < math.inf):
        return 1.0, 1.0, 1.0
    if thermal > 0.5:
        phi_t = inlet_shear_heating_factor(thermal_loading(beta, eta, u, k_f), p_h, E_red)
    if not h_oil < math.inf or phi_t <= 0.0:
        return phi_t, 1.0, 1.0
    hc = phi_t * h_c
    m_star_c = critical_inlet_distance(hc / Rx, Rx, b, 3.06, 0.58)
    m_star_min = critical_inlet_distance(phi_t * h_min / Rx, Rx, b, 3.34, 0.56)
    m = inlet_meniscus(hc, m_star_c, max(m_star_c, m_star_min), Rx, b, h_oil)
    return phi_t, starvation_factor(m, m_star_c, 0.29), starvation_factor(m, m_star_min, 0.25)


@kernel
def rolling_force_factor(phi_ish, phi_rs_c):
    """Factor (-) of the EHL rolling force F_R: (phi_ish phi_rs_c)^(0.656/0.67) (module docstring)."""
    return (phi_ish * phi_rs_c) ** F_R_FILM_EXPONENT


@kernel
def ball_drag_power(v, D, rho_e, eta_e, area_fraction):
    """Power (W) one ball loses moving at speed v (m/s, sign ignored) through a fluid of density rho_e (kg/m^3)
    and viscosity eta_e (Pa.s) with the part area_fraction (-) of its frontal area pi D^2/4 in the fluid:
    F |v|, F = (1/2) C_D(Re) rho_e A_f v^2, Re = rho_e |v| D / eta_e. 0 at rest or without fluid."""
    s = abs(v)
    if s == 0.0 or area_fraction <= 0.0 or rho_e <= 0.0:
        return 0.0
    Re = rho_e * s * D / eta_e
    # C_D Re is finite at Re -> 0 (Stokes): write the force as (1/2) (C_D Re) eta_e s A / D
    if Re <= REYNOLDS_NEWTON:
        cd_re = 24.0 * (1.0 + 0.15 * Re**0.687)
    else:
        cd_re = 0.44 * Re
    A = 0.25 * math.pi * D * D * area_fraction
    return 0.5 * cd_re * eta_e * A * s * s / D


# Air at 20 C and 1 atm (density from the ideal gas, viscosity of dry air; standard tables, e.g. VDI Heat
# Atlas): the gas of the oil-air and jet mixtures, held constant (60 C gives 1.06 kg/m^3 and 2.0e-5 Pa.s).
AIR_DENSITY = 1.2  # kg/m^3
AIR_VISCOSITY = 1.8e-5  # Pa.s


@kernel
def mixture(X, rho_oil, eta_oil):
    """(rho_e, eta_e) of an oil-air mixture with the oil volume fraction X (-): both weighted by volume, the
    viscosity as well (a plain mixture rule; Harris & Kotzalas 2007 use an effective density and viscosity of
    the oil-air mixture, memory); X = 1 is the oil itself bit for bit."""
    if X >= 1.0:
        return rho_oil, eta_oil
    return X * rho_oil + (1.0 - X) * AIR_DENSITY, X * eta_oil + (1.0 - X) * AIR_VISCOSITY
