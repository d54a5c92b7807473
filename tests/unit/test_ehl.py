"""kernels.ehl against its twin tests/reference/ref_ehl.py.

All quantities are closed forms (power laws, exponentials, piecewise-linear maps): tolerance
RTOL = 1e-12. Measured max discrepancy over 3000 random cases (U in [1e-14, 1e-8], G in
[1e3, 1e4], W in [1e-8, 1e-3], k in [0.1, 20]): film formulas 5.8e-16, dimensionless groups
4.3e-16, friction 1.4e-15, damping 3.8e-16; regimes are integers and must be equal.
"""

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import ehl as ek
from tests.reference import ref_ehl as re_
from tests.unit._compare import assert_close

RTOL = 1e-12
FAST = settings(max_examples=50, deadline=None)
# finite, normal floats: subnormal inputs (< 2.2e-308) have no physical meaning and lose precision
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
E_STEEL = 210e9 / (1.0 - 0.3**2)
FORMULAS = [ek.FILM_HAMROCK_DOWSON, ek.FILM_MASJEDI_KHONSARI, ek.FILM_CHITTENDEN]
# 6208 inner contact at psi = 0, omega = 500 rad/s, F_r = 3 kN, Guessasma oil (Guessasma & Machado 2018)
SEED = dict(eta=0.04, xi=2.3e-8, E_red=E_STEEL, u=6.1, Q=1457.0, Rx=4.99e-3, Ry=0.1638, k=10.7)


def test_option_codes_match_twin():
    assert (ek.FILM_HAMROCK_DOWSON, ek.FILM_MASJEDI_KHONSARI, ek.FILM_CHITTENDEN) == (
        re_.HAMROCK_DOWSON,
        re_.MASJEDI_KHONSARI,
        re_.CHITTENDEN,
    )
    assert (ek.REGIME_BOUNDARY, ek.REGIME_MIXED, ek.REGIME_FULL_FILM) == (0, 1, 2)


@FAST
@given(log_u=floats(-14.0, -8.0), G=floats(1000.0, 10000.0), log_w=floats(-8.0, -3.0), log_k=floats(-1.0, 1.3))
def test_film_formulas_random(log_u, G, log_w, log_k):
    U, W, k = 10.0**log_u, 10.0**log_w, 10.0**log_k
    assert_close(ek.film_hamrock_dowson(U, G, W, k), re_.film_hamrock_dowson(U, G, W, k), RTOL, "HD")
    assert_close(ek.film_masjedi_khonsari(U, G, W, k), re_.film_masjedi_khonsari(U, G, W, k), RTOL, "MK")
    assert_close(ek.film_chittenden(U, G, W, k), re_.film_chittenden(U, G, W, k), RTOL, "Chittenden")


@pytest.mark.parametrize("k", [0.1, 0.5, 1.0, 2.0, 10.7, 20.0])
def test_film_formulas_on_grid(k):
    """Slender (k < 1), circular (k = 1) and wide contacts."""
    for U, G, W in [(1e-12, 4900.0, 1e-6), (1e-11, 5000.0, 2.5e-4), (3e-10, 2000.0, 1e-7)]:
        assert_close(ek.film_hamrock_dowson(U, G, W, k), re_.film_hamrock_dowson(U, G, W, k), RTOL, "HD")
        assert_close(ek.film_masjedi_khonsari(U, G, W, k), re_.film_masjedi_khonsari(U, G, W, k), RTOL, "MK")
        assert_close(ek.film_chittenden(U, G, W, k), re_.film_chittenden(U, G, W, k), RTOL, "Chittenden")


def test_hamrock_dowson_exponents():
    """Guessasma & Machado (2018) check: dlog Lambda / dlog Q = -0.073 and dlog Lambda / dlog omega = 0.68 (h_min)."""
    U, G, W, k = 1e-11, 4900.0, 1e-6, 10.7
    h = ek.film_hamrock_dowson(U, G, W, k)[1]
    assert math.log(ek.film_hamrock_dowson(U, G, 2 * W, k)[1] / h) / math.log(2) == pytest.approx(
        -0.073, rel=1e-12, abs=0
    )
    assert math.log(ek.film_hamrock_dowson(2 * U, G, W, k)[1] / h) / math.log(2) == pytest.approx(
        0.68, rel=1e-12, abs=0
    )


@pytest.mark.parametrize("formula", FORMULAS)
@pytest.mark.parametrize("u", [-6.1, -0.01, 0.0, 1e-6, 0.01, 6.1, 40.0])
@pytest.mark.parametrize("Q", [-5.0, 0.0, 1e-3, 100.0, 1457.0, 2e4])
def test_film_thickness_on_grid(formula, u, Q):
    args = (SEED["eta"], SEED["xi"], SEED["E_red"], u, Q, SEED["Rx"], SEED["Ry"], SEED["k"])
    got = ek.film_thickness(formula, *args)
    assert_close(got, re_.film_thickness(formula, *args), RTOL, f"film code {formula}")
    if Q <= 0.0:
        assert got == (math.inf, math.inf)  # open contact: no film constraint
    elif u == 0.0:
        assert got == (0.0, 0.0)  # at rest: no film
    else:
        assert got[0] > 0.0 and got[1] > 0.0
        # entrainment direction does not matter, only its magnitude
        args_rev = args[:3] + (-u,) + args[4:]
        assert ek.film_thickness(formula, *args_rev) == got


@FAST
@given(
    formula=st.sampled_from(FORMULAS),
    log_eta=floats(-3.0, 0.0),
    xi=floats(5e-9, 3e-8),
    u=floats(-30.0, 30.0),
    log_q=floats(-2.0, 4.5),
    log_rx=floats(-3.5, -2.0),
    log_ratio=floats(-1.0, 1.5),
    log_k=floats(-1.0, 1.3),
)
def test_film_thickness_random(formula, log_eta, xi, u, log_q, log_rx, log_ratio, log_k):
    Rx = 10.0**log_rx
    args = (10.0**log_eta, xi, E_STEEL, u, 10.0**log_q, Rx, Rx * 10.0**log_ratio, 10.0**log_k)
    assert_close(ek.film_thickness(formula, *args), re_.film_thickness(formula, *args), RTOL, f"film {formula}")
    assert_close(ek.dimensionless_groups(*args[:6]), re_.dimensionless_groups(*args[:6]), RTOL, "U, G, W")


def test_zero_speed_gives_boundary_regime():
    """Zero speed -> zero film, Lambda = 0, boundary regime, mu = 0.1, hysteretic damping."""
    for formula in FORMULAS:
        hc, hm = ek.film_thickness(formula, 0.04, 2.3e-8, E_STEEL, 0.0, 1457.0, 4.99e-3, 0.1638, 10.7)
        assert (
            (hc, hm)
            == (0.0, 0.0)
            == re_.film_thickness(formula, 0.04, 2.3e-8, E_STEEL, 0.0, 1457.0, 4.99e-3, 0.1638, 10.7)
        )
        lam = ek.film_parameter(hm, 0.375e-6)
        assert lam == 0.0 == re_.film_parameter(hm, 0.375e-6)
        assert ek.lubrication_regime(lam) == ek.REGIME_BOUNDARY == re_.lubrication_regime(lam)
        assert ek.friction_coefficient(lam) == 0.1 == re_.friction_coefficient(lam)
        assert ek.normal_damping(lam, 1457.0, 0.08, 0.04, 1.9e-3, 6.3e-3, hm) == pytest.approx(
            1.5 * 0.08 * 1457.0, rel=1e-15, abs=0
        )


@pytest.mark.parametrize(
    "lam", [0.0, 0.5, 1.0, np.nextafter(1.0, 2.0), 1.5, 2.0, 2.999, 3.0, np.nextafter(3.0, 4.0), 5.0, 100.0, math.inf]
)
def test_regime_friction_damping_on_grid(lam):
    assert ek.lubrication_regime(lam) == re_.lubrication_regime(lam)
    assert_close(ek.friction_coefficient(lam), re_.friction_coefficient(lam), RTOL, f"mu({lam})")
    h_min = lam * 0.375e-6 if math.isfinite(lam) else 1e-5
    for Q in (1.0, 1457.0):
        args = (lam, Q, 0.08, 0.04, 1.9e-3, 6.3e-3, h_min)
        assert_close(ek.normal_damping(*args), re_.normal_damping(*args), RTOL, f"C_n({lam}, {Q})")


def test_regime_boundaries_and_friction_ramp():
    assert [ek.lubrication_regime(x) for x in (1.0, 1.0 + 1e-12, 3.0, 3.0 + 1e-12)] == [0, 1, 1, 2]
    assert ek.friction_coefficient(1.0) == 0.1 and ek.friction_coefficient(3.0) == pytest.approx(0.01, rel=1e-14, abs=0)
    assert ek.friction_coefficient(2.0) == pytest.approx(0.055, rel=1e-14, abs=0)  # linear on ]1, 3]
    assert ek.friction_coefficient(math.inf) == 0.01


def test_traction_limit_replaces_the_full_film_friction():
    """limit 0: the papers' mu(Lambda) exactly; limit 0.05: 0.1 up to Lambda = 1, linear to 0.05 at 3, 0.05 above;
    against the twin (np.interp) over the whole range."""
    for lam in (0.0, 0.5, 1.0, 1.7, 2.0, 3.0, 3.5, 100.0, math.inf):
        assert ek.traction_coefficient(lam, 0.0) == ek.friction_coefficient(lam)
        for limit in (0.0, 0.01, 0.05, 0.1):
            assert_close(ek.traction_coefficient(lam, limit), re_.traction_coefficient(lam, limit), RTOL, "mu_t")
    assert ek.traction_coefficient(2.0, 0.05) == pytest.approx(0.075, rel=1e-14, abs=0)
    assert ek.traction_coefficient(3.0, 0.05) == pytest.approx(0.05, rel=1e-14, abs=0)
    assert ek.traction_coefficient(7.0, 0.05) == 0.05 and ek.traction_coefficient(0.9, 0.05) == 0.1


def test_film_traction_curve_share_and_slip_speed_match_their_twins():
    """The tangential law's film pieces against their twins (np.interp, plain exp, max) over their range, and the
    curve's defining points: Bair & Winer's tau_L (1 - exp(-gamma_dot eta / tau_L)) over the contact gives
    mu_lim (1 - 1/e) at srr = s_0 and mu_lim at large slip; the share is 0 up to Lambda = 1, 1/2 at 2, 1 from 3."""
    for lam in (0.0, 0.5, 1.0, 1.7, 2.0, 3.0, 3.5, math.inf):
        assert_close(ek.film_share(lam), re_.film_share(lam), RTOL, "phi")
    assert (ek.film_share(1.0), ek.film_share(2.0), ek.film_share(3.0)) == (0.0, 0.5, 1.0)
    for srr in (0.0, 1e-4, 1e-3, 0.01, 0.3, 2.0):
        for mu_lim, s_0 in ((0.06, 0.001), (0.045, 0.01)):
            got = ek.film_traction_coefficient(srr, mu_lim, s_0)
            assert_close(got, re_.film_traction_coefficient(srr, mu_lim, s_0), RTOL, "mu_film")
    assert ek.film_traction_coefficient(0.001, 0.06, 0.001) == pytest.approx(0.06 * (1.0 - math.exp(-1.0)), rel=1e-14)
    assert ek.film_traction_coefficient(1.0, 0.06, 0.001) == pytest.approx(0.06, rel=1e-14)
    for spin in (-2000.0, -1.0, 0.0, 300.0, 5000.0):
        for u in (0.5, 25.0):
            got = ek.film_slip_speed(0.001, u, spin, 8e-4)
            assert_close(got, re_.film_slip_speed(0.001, u, spin, 8e-4), RTOL, "v_s")


def test_mixed_damping_is_the_series_combination():
    lam, Q, h = 2.0, 1457.0, 0.75e-6
    c_h = 1.5 * 0.08 * Q
    c_f = ek.normal_damping(4.0, Q, 0.08, 0.04, 1.9e-3, 6.3e-3, h)  # full film at the same film thickness
    mixed = ek.normal_damping(lam, Q, 0.08, 0.04, 1.9e-3, 6.3e-3, h)
    assert mixed == pytest.approx(1.0 / (1.0 / c_h + 1.0 / c_f), rel=1e-14, abs=0)
    assert mixed < min(c_h, c_f)


@FAST
@given(lam=floats(0.0, 10.0), log_sigma=floats(-8.0, -6.0), log_q=floats(-1.0, 4.5), log_eta=floats(-3.0, 0.0))
def test_film_parameter_regime_friction_damping_random(lam, log_sigma, log_q, log_eta):
    sigma = 10.0**log_sigma
    h_min = lam * sigma
    assert_close(ek.film_parameter(h_min, sigma), re_.film_parameter(h_min, sigma), RTOL, "Lambda")
    L = ek.film_parameter(h_min, sigma)
    assert ek.lubrication_regime(L) == re_.lubrication_regime(L)
    assert_close(ek.friction_coefficient(L), re_.friction_coefficient(L), RTOL, "mu")
    args = (L, 10.0**log_q, 0.08, 10.0**log_eta, 1.9e-3, 6.3e-3, h_min)
    assert_close(ek.normal_damping(*args), re_.normal_damping(*args), RTOL, "C_n")


def test_smooth_surfaces_with_a_film():
    """sigma = 0 with a real film: the film parameter is unbounded (full film)."""
    assert ek.film_parameter(1e-7, 0.0) == math.inf == re_.film_parameter(1e-7, 0.0)
    assert ek.lubrication_regime(math.inf) == ek.REGIME_FULL_FILM


def test_smooth_surfaces_at_rest():
    assert ek.film_parameter(0.0, 0.0) == re_.film_parameter(0.0, 0.0) == 0.0
