"""kernels.lubrication (film factors and ball drag of the lubrication method) against its twin and its sources.

Twin comparisons (tests/reference/ref_lubrication.py), tolerances:
- closed forms (thermal loading and factor, m*, starvation factor, rolling-force factor, mixture): RTOL = 1e-12;
- the Hertz inlet gap: the kernel's closed form against the quadrature of its slope (epsrel 1e-13): 1e-10;
- the meniscus: kernel Illinois to 1e-13 of m against brentq to 1e-15 with the quadrature gap: 1e-9 in m - 1
  (the factors ((m-1)/(m*-1))^0.29 carry that relative error times 0.29);
- temperature-viscosity coefficient: five-point central differences of ln(eta), the kernel's at h = 0.5 K, the
  twin's at 0.25 K: truncation (h^4/30) |d^5 ln(eta)/dT^5| and rounding 1e-16/(h beta) ~ 1e-14, both far below 1e-7;
- drag: the kernel writes (1/2) C_D rho A v^3 as (1/2) (C_D Re) eta A v^2 / D: 1e-12.
Source checks (physics, not code): Stokes' drag 3 pi eta D v and Newton's 0.44; the starvation factor's end
points; Gupta's thermal factor within 20 % of Murch & Wilson's 3.94/(3.94 + L^0.62) for L <= 5 (two independent
fits of thermal EHL solutions, pure rolling; they differ by 6 % at L = 0.5, 16 % at L = 5); the immersed frontal
area of a ball in an oil bath from geometry.
"""

import functools
import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import lubrication as lk
from bearing_fmu.models.lubrication import immersed_area_fraction
from bearing_fmu.params import load_lubricant
from tests.reference import ref_lubrication as rl
from tests.unit._compare import assert_close

RTOL = 1e-12
FAST = settings(max_examples=60, deadline=None)
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
E_RED = 2.3e11


@FAST
@given(beta=floats(0.0, 0.1), eta=floats(1e-3, 1.0), u=floats(0.0, 50.0), p_h=floats(3e8, 3e9))
def test_thermal_factor_matches_twin(beta, eta, u, p_h):
    L = lk.thermal_loading(beta, eta, u, 0.13)
    assert_close(L, rl.thermal_loading(beta, eta, u, 0.13), RTOL, "L")
    assert_close(lk.inlet_shear_heating_factor(L, p_h, E_RED), rl.inlet_shear_heating_factor(L, p_h, E_RED), RTOL, "")


@pytest.mark.parametrize("lubricant", ["iso_vg68_mineral", "pao_vg48", "thesis_turbine_oil"])
@pytest.mark.parametrize("T", [233.15, 313.15, 373.15, 473.15])
def test_temperature_viscosity_coefficient_matches_twin(lubricant, T):
    lub = load_lubricant(lubricant).array
    assert_close(lk.temperature_viscosity_coefficient(T, lub), rl.temperature_viscosity_coefficient(T, lub), 1e-7, "")


def test_constant_viscosity_oil_has_no_thermal_reduction():
    """guessasma_oil gives eta as a constant (Guessasma & Machado 2018): beta = 0, L = 0, phi_ish = 1."""
    lub = load_lubricant("guessasma_oil").array
    assert lk.temperature_viscosity_coefficient(313.15, lub) == 0.0
    assert lk.inlet_shear_heating_factor(0.0, 2e9, E_RED) == 1.0


@pytest.mark.parametrize("L", [0.1, 0.5, 1.0, 2.0, 5.0])
def test_gupta_near_murch_wilson(L):
    gupta = lk.inlet_shear_heating_factor(L, 0.008 * E_RED, E_RED)
    murch_wilson = 3.94 / (3.94 + L**0.62)
    assert abs(gupta / murch_wilson - 1.0) < 0.2


@FAST
@given(X=floats(1.0, 30.0), b=floats(1e-5, 1e-3), Rx=floats(1e-3, 5e-2))
def test_inlet_gap_matches_quadrature_of_its_slope(X, b, Rx):
    assert_close(lk.hertz_inlet_gap(X, b, Rx), rl.hertz_inlet_gap(X, b, Rx), 1e-10, "g")
    # far from the contact the gap tends to x^2/(2 Rx) (the undeformed parabola) minus a logarithmic term
    if X > 20.0:
        assert lk.hertz_inlet_gap(X, b, Rx) < (X * b) ** 2 / (2.0 * Rx)


def test_starvation_factor_ends():
    """Hamrock & Dowson 1977: fully flooded at m >= m*, no film with the meniscus at the contact edge (m = 1)."""
    assert lk.starvation_factor(3.0, 2.0, 0.29) == 1.0
    assert lk.starvation_factor(1.0, 2.0, 0.29) == 0.0
    assert lk.starvation_factor(1.5, 2.0, 0.29) == pytest.approx(0.5**0.29, rel=RTOL)
    m = np.linspace(1.0, 3.0, 41)
    assert np.all(np.diff([lk.starvation_factor(x, 2.5, 0.25) for x in m]) >= 0.0)
    for x in m:
        assert_close(lk.starvation_factor(x, 2.5, 0.29), rl.starvation_factor(x, 2.5, 0.29), RTOL, "phi_rs")


# (h_c, h_min, u, p_h, b, Rx, eta, beta, thermal, h_oil): contacts of a 6208 and a B7214C at 1e3-1e4 rpm
CONTACTS = [
    (3.1e-7, 2.3e-7, 1.8, 1.9e9, 1.8e-4, 5.0e-3, 0.06, 0.04, 1.0, 2e-6),
    (1.5e-6, 1.0e-6, 18.0, 1.9e9, 1.8e-4, 5.0e-3, 0.06, 0.04, 1.0, 2e-6),
    (1.5e-6, 1.0e-6, 18.0, 1.9e9, 1.8e-4, 5.0e-3, 0.06, 0.04, 0.0, 1e-6),
    (1.5e-6, 1.0e-6, 18.0, 1.9e9, 1.8e-4, 5.0e-3, 0.06, 0.04, 1.0, 20e-6),
    (1.5e-6, 1.0e-6, 18.0, 1.9e9, 1.8e-4, 5.0e-3, 0.06, 0.04, 1.0, math.inf),
    (9.0e-7, 6.0e-7, 14.0, 1.2e9, 1.3e-4, 7.5e-3, 0.03, 0.03, 1.0, 5e-7),
]


@pytest.mark.parametrize("contact", CONTACTS)
def test_film_factors_match_twin(contact):
    h_c, h_min, u, p_h, b, Rx, eta, beta, thermal, h_oil = contact
    args = (h_c, h_min, u, p_h, b, Rx, E_RED, eta, beta, 0.13, thermal, h_oil)
    got, ref = lk.film_factors(*args), rl.film_factors(*args)
    assert_close(got[0], ref[0], RTOL, "phi_ish")
    for k in (1, 2):
        assert_close(got[k], ref[k], 1e-9, f"phi_rs {k}")
    assert 0.0 < got[1] <= 1.0 and 0.0 < got[2] <= 1.0
    assert_close(lk.rolling_force_factor(got[0], got[1]), rl.rolling_force_factor(ref[0], ref[1]), 1e-9, "F_R")


@FAST
@given(h_c=floats(1e-8, 3e-6), b=floats(5e-5, 5e-4), Rx=floats(2e-3, 2e-2), h_oil=floats(1e-8, 5e-5))
def test_meniscus_matches_twin(h_c, b, Rx, h_oil):
    m_star = lk.critical_inlet_distance(h_c / Rx, Rx, b, 3.06, 0.58)
    assert_close(m_star, rl.critical_inlet_distance(h_c / Rx, Rx, b, 3.06, 0.58), RTOL, "m*")
    m_cap = 1.2 * m_star
    m = lk.inlet_meniscus(h_c, m_star, m_cap, Rx, b, h_oil)
    m_ref = rl.inlet_meniscus(h_c, m_star, m_cap, Rx, b, h_oil)
    assert abs(m - m_ref) <= 1e-9 * (m_ref - 1.0) + 1e-14, (m, m_ref)
    if m < m_cap:  # the layer fills the gap at the meniscus
        gap = h_c * lk.starvation_factor(m, m_star, 0.29) + lk.hertz_inlet_gap(m, b, Rx)
        assert gap == pytest.approx(h_oil, rel=1e-9)


def test_more_oil_less_starvation():
    h_c, h_min, u, p_h, b, Rx = 1.5e-6, 1.0e-6, 18.0, 1.9e9, 1.8e-4, 5.0e-3
    phis = [lk.film_factors(h_c, h_min, u, p_h, b, Rx, E_RED, 0.06, 0.04, 0.13, 0.0, h)[1] for h in (1e-7, 1e-6, 3e-6)]
    assert phis[0] < phis[1] < phis[2] <= 1.0
    assert lk.film_factors(h_c, h_min, u, p_h, b, Rx, E_RED, 0.06, 0.04, 0.13, 0.0, 1e-3) == (1.0, 1.0, 1.0)


@FAST
@given(v=floats(-40.0, 40.0), D=floats(2e-3, 5e-2), rho=floats(1.0, 1000.0), eta=floats(1e-5, 0.5), f=floats(0, 1))
@example(v=2.2250738585072014e-308, D=0.03125, rho=1.0, eta=0.5, f=1.0)  # power below the smallest float: 0.0
def test_drag_matches_twin(v, D, rho, eta, f):
    """atol 1e-290 W: speeds of 1e-150 m/s give powers in the subnormal range, where the relative rounding is
    that of a few significant bits (found by hypothesis: v = 6e-159 m/s, 5.2e-318 W, 1.3e-5 apart). The twin
    works in decimal arithmetic: at the smallest normal speed its float C_D overflowed and v^2 underflowed
    (NaN, found by hypothesis), while the kernel's C_D Re form gives the power's underflow to 0.0."""
    got, ref = lk.ball_drag_power(v, D, rho, eta, f), rl.ball_drag_power(v, D, rho, eta, f)
    assert_close(got, ref, RTOL, "P", atol=1e-290)


def test_drag_limits():
    """Stokes (Re -> 0): F = 3 pi eta D v; Newton (Re > 1000): F = 0.44 (1/2) rho (pi D^2/4) v^2."""
    D, v = 0.01, 1e-4
    Re = 870.0 * v * D / 1.0  # Schiller-Naumann's correction to Stokes is 0.15 Re^0.687 (1.2e-3 here)
    stokes = 3.0 * math.pi * 1.0 * D * v * v
    assert lk.ball_drag_power(v, D, 870.0, 1.0, 1.0) == pytest.approx(stokes, rel=1.01 * 0.15 * Re**0.687)
    v = 20.0
    newton = 0.44 * 0.5 * 870.0 * math.pi * D * D / 4.0 * v * v * v
    assert lk.ball_drag_power(v, D, 870.0, 0.01, 1.0) == pytest.approx(newton, rel=RTOL)
    assert lk.ball_drag_power(0.0, D, 870.0, 0.01, 1.0) == 0.0


def test_mixture_matches_twin():
    for X in (0.0, 1e-4, 0.01, 0.5, 1.0):
        got, ref = lk.mixture(X, 860.0, 0.05), rl.mixture(X, 860.0, 0.05)
        assert_close(got[0], ref[0], RTOL, "rho") and assert_close(got[1], ref[1], RTOL, "eta")
    assert lk.mixture(1.0, 860.0, 0.05) == (860.0, 0.05)


def test_immersed_area_fraction_geometry():
    """Level 0: dry; the bearing's centre line (H = (d_m + D)/2): half the orbit, by symmetry; above the top: 1."""
    D, dm = 0.0127, 0.06
    assert immersed_area_fraction(0.0, D, dm) == 0.0
    assert immersed_area_fraction(0.5 * (dm + D), D, dm) == pytest.approx(0.5, abs=1e-6)
    assert immersed_area_fraction(dm + D, D, dm) == 1.0
    levels = np.linspace(0.0, dm + D, 30)
    assert np.all(np.diff([immersed_area_fraction(h, D, dm) for h in levels]) > 0.0)
