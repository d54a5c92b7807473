"""kernels.hertz against its twin tests/reference/ref_hertz.py.

Tolerances (measured max discrepancy over 2000 random cases, Ry/Rx in [1e-3, 1e3], Q in
[1e-3, 1e5] N, E' in [1e9, 5e11] Pa):
- RTOL = 1e-12 for the closed forms (reduced modulus, Hamrock-Brewe, contact size / approach /
  pressure, stiffness, series stiffness: measured <= 2e-15) and for the elliptic integrals (AGM
  against scipy.special: 8e-16) and the exact coefficients away from the circular case
  (|Ry/Rx - 1| >= 1e-4: 4.1e-14; the kernel's bisection on ln k stops at 1e-15).
- Exact coefficients near the circular case: the kernel solves the printed relation
  (k^2 E - K)/(K - E) = Ry/Rx whose numerator and denominator both vanish like m = 1 - 1/k^2,
  so each evaluation carries an absolute error ~ eps/m and k inherits a relative error ~ eps/|Ry/Rx - 1|
  (the twin uses the cancellation-free Carlson form). Tolerance RTOL + 4 eps/|Ry/Rx - 1|; measured
  8.4e-9 at Ry/Rx = 1 + 1e-8 (bound 8.9e-8), 1.8e-11 at 1 + 1e-6 (bound 8.9e-10). Ball-race contacts
  have Ry/Rx ~ 10-30, where this does not matter; the kernel returns the circle k = 1 for
  Ry/Rx <= 1 + 1e-12 (error <= 2/3 x 1e-12, inside RTOL).
"""

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import hertz as hk
from tests.reference import ref_hertz as rh
from tests.unit._compare import assert_close

RTOL = 1e-12
EPS = np.finfo(float).eps
FAST = settings(max_examples=50, deadline=None)
# finite, normal floats: subnormal inputs (< 2.2e-308) have no physical meaning and lose precision
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
E_STEEL = 210e9 / (1.0 - 0.3**2)  # E' steel on steel, E = 210 GPa, nu = 0.3

RATIOS = [1e-3, 0.01, 0.0707, 0.5, 0.9, 1.0 - 1e-4, 1.0, 1.0 + 1e-4, 1.1, 2.0, 10.0, 14.2, 27.6, 100.0, 1e3]
NEAR_ONE = [1.0 + d for d in (1e-13, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, -1e-8, -1e-6, -1e-5)]
LOADS = [-1.0, 0.0, 1e-6, 1.0, 1457.0, 1e5]

log_ratios = floats(-3.0, 3.0)
log_radii = floats(-4.0, -1.0)
log_loads = floats(-3.0, 5.0)
moduli = floats(1e9, 5e11)


def coef_tol(ratio):
    d = abs(ratio - 1.0)
    return RTOL + (4.0 * EPS / d if d > 0.0 else 0.0)


def test_reduced_modulus():
    assert hk.reduced_modulus(210e9, 0.3, 210e9, 0.3) == pytest.approx(E_STEEL, rel=1e-15, abs=0)
    for args in [(210e9, 0.3, 210e9, 0.3), (210e9, 0.3, 3.3e9, 0.41), (310e9, 0.26, 210e9, 0.3), (1e6, 0.0, 1e13, 0.5)]:
        assert_close(hk.reduced_modulus(*args), rh.reduced_modulus(*args), RTOL, f"E' {args}")


@pytest.mark.parametrize("m", [0.0, 1e-12, 1e-6, 0.1, 0.5, 0.9, 0.99, 0.999999, 1.0 - 1e-12])
def test_elliptic_integrals(m):
    assert_close(hk.elliptic_integrals(m), rh.elliptic_integrals(m), RTOL, f"K, E at m={m}")


def test_twin_hertz_relation_matches_printed_form():
    """The twin solves the Carlson form; it must be the printed relation where that is well conditioned."""
    for k in (1.05, 1.1, 1.5, 2.0, 3.0, 5.0, 10.0):
        assert rh.hertz_ratio(k) == pytest.approx(rh.hertz_ratio_textbook(k), rel=1e-14, abs=0)
    assert rh.hertz_ratio(1.0) == 1.0


@pytest.mark.parametrize("ratio", RATIOS + NEAR_ONE)
def test_exact_coefficients_on_grid(ratio):
    Rx = 3.7e-3
    got = hk.hertz_coefficients_exact(Rx, ratio * Rx)
    want = rh.hertz_coefficients_exact(Rx, ratio * Rx)
    assert_close(got, want, coef_tol(ratio), f"exact (k, E, K) at Ry/Rx = {ratio}")
    # slender (Ry < Rx) contacts have k_yx < 1, circular ones k = 1 exactly
    assert (got[0] < 1.0) == (ratio < 1.0 - 1e-12)
    if ratio == 1.0:
        assert got == (1.0, math.pi / 2.0, math.pi / 2.0)


@FAST
@given(log_rx=log_radii, log_ratio=log_ratios)
def test_exact_coefficients_random(log_rx, log_ratio):
    Rx, ratio = 10.0**log_rx, 10.0**log_ratio
    assert_close(
        hk.hertz_coefficients_exact(Rx, ratio * Rx),
        rh.hertz_coefficients_exact(Rx, ratio * Rx),
        coef_tol(ratio),
        f"exact at Ry/Rx = {ratio}",
    )


@pytest.mark.parametrize("ratio", RATIOS)
def test_approx_coefficients(ratio):
    Rx = 3.7e-3
    assert_close(
        hk.hertz_coefficients_approx(Rx, ratio * Rx),
        rh.hertz_coefficients_approx(Rx, ratio * Rx),
        RTOL,
        f"approx at Ry/Rx = {ratio}",
    )


@pytest.mark.parametrize("ratio", [0.0707, 0.5, 1.0, 14.2, 27.6])
@pytest.mark.parametrize("Q", LOADS)
@pytest.mark.parametrize("solution", ["exact", "approx"])
def test_contact_and_stiffness_on_grid(ratio, Q, solution):
    Rx = 4.99e-3
    Ry = ratio * Rx
    coeff = rh.hertz_coefficients_exact(Rx, Ry) if solution == "exact" else rh.hertz_coefficients_approx(Rx, Ry)
    got = hk.hertz_contact(Q, Rx, Ry, E_STEEL, *coeff)
    assert_close(got, rh.hertz_contact(Q, Rx, Ry, E_STEEL, *coeff), RTOL, f"contact Q={Q}")
    if Q <= 0.0:
        assert got == (0.0, 0.0, 0.0, 0.0)  # open contact
    else:
        a_y, b_x, delta, p_max = got
        assert (a_y > b_x) == (ratio > 1.0) and (a_y == pytest.approx(b_x, rel=1e-14, abs=0)) == (ratio == 1.0)
        K_h = hk.hertz_stiffness(Rx, Ry, E_STEEL, *coeff)
        assert_close(K_h, rh.hertz_stiffness(Rx, Ry, E_STEEL, *coeff), RTOL, "K_h")
        assert K_h * delta**1.5 == pytest.approx(Q, rel=1e-13, abs=0)  # Q = K_h delta^1.5


@FAST
@given(log_rx=log_radii, log_ratio=log_ratios, log_q=log_loads, E_red=moduli)
def test_contact_random(log_rx, log_ratio, log_q, E_red):
    Rx = 10.0**log_rx
    Ry = Rx * 10.0**log_ratio
    Q = 10.0**log_q
    coeff = rh.hertz_coefficients_exact(Rx, Ry)
    assert_close(
        hk.hertz_contact(Q, Rx, Ry, E_red, *coeff), rh.hertz_contact(Q, Rx, Ry, E_red, *coeff), RTOL, "contact"
    )
    assert_close(hk.hertz_stiffness(Rx, Ry, E_red, *coeff), rh.hertz_stiffness(Rx, Ry, E_red, *coeff), RTOL, "K_h")
    approx = rh.hertz_coefficients_approx(Rx, Ry)
    assert_close(
        hk.hertz_contact(Q, Rx, Ry, E_red, *approx),
        rh.hertz_contact(Q, Rx, Ry, E_red, *approx),
        RTOL,
        "contact (approx coefficients)",
    )


def test_slender_contact_is_the_wide_one_turned():
    """Swapping Rx and Ry swaps the semi-axes and leaves approach and pressure unchanged."""
    Rx, Ry, Q = 4.99e-3, 0.35e-3, 800.0
    wide = hk.hertz_contact(Q, Ry, Rx, E_STEEL, *hk.hertz_coefficients_exact(Ry, Rx))
    slender = hk.hertz_contact(Q, Rx, Ry, E_STEEL, *hk.hertz_coefficients_exact(Rx, Ry))
    assert slender[0] < slender[1]
    assert_close(slender, (wide[1], wide[0], wide[2], wide[3]), 1e-14, "slender vs wide")


def test_circular_contact_matches_johnson():
    """k = 1: sphere of radius r on a flat, Johnson (1985) eqs. 4.22-4.23 with E* = E'/2:
    a = (3 Q r / (4 E*))^(1/3), delta = a^2 / r, p0 = 3 Q / (2 pi a^2)."""
    r, Q = 6.3e-3, 1000.0
    E_star = E_STEEL / 2.0
    a, b, delta, p0 = hk.hertz_contact(Q, r, r, E_STEEL, *hk.hertz_coefficients_exact(r, r))
    a_j = (3.0 * Q * r / (4.0 * E_star)) ** (1.0 / 3.0)
    assert a == b == pytest.approx(a_j, rel=1e-14, abs=0)
    assert delta == pytest.approx(a_j**2 / r, rel=1e-14, abs=0)
    assert p0 == pytest.approx(3.0 * Q / (2.0 * math.pi * a_j**2), rel=1e-14, abs=0)


@FAST
@given(log_k1=floats(8.0, 12.0), log_k2=floats(8.0, 12.0), log_q=log_loads)
def test_series_stiffness(log_k1, log_k2, log_q):
    K1, K2, Q = 10.0**log_k1, 10.0**log_k2, 10.0**log_q
    K = hk.series_stiffness(K1, K2)
    assert_close(K, rh.series_stiffness(K1, K2), RTOL, "series")
    # the same load on both contacts: the approaches add
    assert (Q / K) ** (2.0 / 3.0) == pytest.approx((Q / K1) ** (2.0 / 3.0) + (Q / K2) ** (2.0 / 3.0), rel=1e-13, abs=0)
