"""kernels.loaddist against its twin tests/reference/ref_loaddist.py (quad + brentq).

The kernel integrates with n = 48 Gauss-Legendre points on the loaded arc (the model's rule).
Tolerances, from the error of that rule, then checked against measurements (600 J_r cases with
eps in [1e-12, 1e6], 1500 force cases, 300 solves with F_r in [1e-3, 1e5] N):
- Gauss-Legendre on an integrand that vanishes like (psi_l - psi)^beta at the arc end converges as
  n^-(2 beta + 2). Force and J_r: beta = 1.5, 48^-5 = 3.9e-9; tolerance RTOL_GL = 1e-8
  (2.5 x 48^-5); measured 1.5e-9 for 1e-4 < eps < 100. Slope: beta = 0.5, 48^-3 = 9.0e-6;
  RTOL_SLOPE = 2e-5 (2.5 x 48^-3); measured 1.8e-6 (1.0e-5 at extreme eps). The slope only drives
  Newton steps in solve_radial_shift, it does not enter the solution.
- Conditioning of the printed integrand, added to both: for tiny eps the kernel forms 1 - cos psi
  and arccos(1 - 2 eps) (relative error ~ eps_mach/eps), for eps >> 1 (heavy preload, delta_r << |P_d|)
  the integral is a small difference of node terms whose sum of magnitudes is ~2 eps times the
  result, each carrying a few roundings (cos, power, products: ~4 eps_mach). Tolerance
  + 8 eps_mach (eps + 1/eps); measured at most 0.014 of that term for J_r and F_r (J_r at eps = 1e-12:
  9.0e-6) and 0.14 for the radial shift. The twin avoids both (half-angle and integrated-by-parts
  forms, checked below).
- Radial shift: F_r grows at least like delta_r (preload) and like delta_r^1.5 otherwise, so delta_r
  inherits at most the force error: RTOL_GL + conditioning again; measured 6.0e-9 for 1e-3 <= F_r.
- Gauss-Legendre rule itself: nodes and weights against numpy.polynomial.legendre.leggauss to
  1e-14 absolute (leggauss's own accuracy: it and scipy.special.roots_legendre differ by up to
  2e-11 relative at the smallest end weights; measured kernel-leggauss 4.4e-15 absolute), plus
  exactness on monomials of degree <= 2n - 1 to 1e-13 (measured 4e-14).
- loaded_half_angle and the Stribeck load are closed forms: 1e-12 + eps_mach (eps + 1/eps)
  (arccos(1 - 2 eps), 1 - cos psi); at the edge of the loaded zone Q -> 0 and only an absolute
  error Q_max (4 eps_mach/eps)^1.5 is meaningful.
"""

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import loaddist as ld
from tests.reference import ref_loaddist as rl
from tests.unit._compare import assert_close, rel_err

N_GAUSS = 48
NODES, WEIGHTS = ld.gauss_legendre(N_GAUSS)
RTOL = 1e-12
RTOL_GL = 2.5 * N_GAUSS**-5.0  # 9.8e-9
RTOL_SLOPE = 2.5 * N_GAUSS**-3.0  # 2.3e-5
EPS = np.finfo(float).eps
FAST = settings(max_examples=50, deadline=None)
# finite, normal floats: subnormal inputs (< 2.2e-308) have no physical meaning and lose precision
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
K_6208 = 8.6e9  # N/m^1.5, order of the 6208 inner + outer contacts in series


def conditioning(eps):
    """Round-off bound of the printed integrand: 8 eps_mach (eps + 1/eps) (see module docstring)."""
    eps = abs(eps)
    return 8.0 * EPS * (eps + 1.0 / eps) if 0.0 < eps < math.inf else 0.0


@pytest.mark.parametrize("n", [1, 2, 3, 5, 10, 20, 48, 64, 100])
def test_gauss_legendre(n):
    x, w = ld.gauss_legendre(n)
    order = np.argsort(x)
    xr, wr = rl.gauss_legendre(n)
    assert np.max(np.abs(x[order] - xr)) <= 1e-14
    assert np.max(np.abs(w[order] - wr)) <= 1e-14
    # defining property: exact for every polynomial of degree <= 2n - 1
    for j in range(n):
        exact = 2.0 / (2 * j + 1)
        assert abs(np.sum(w * x ** (2 * j)) - exact) <= 1e-13 * exact
        assert abs(np.sum(w * x ** (2 * j + 1))) <= 1e-14


@pytest.mark.parametrize("eps", [-1.0, 0.0, 1e-9, 0.01, 0.25, 0.5, 0.9, 1.0, 1.5, math.inf])
def test_loaded_half_angle(eps):
    assert_close(ld.loaded_half_angle(eps), rl.loaded_half_angle(eps), RTOL + conditioning(eps), f"psi_l({eps})")
    assert ld.loaded_half_angle(0.5) == pytest.approx(math.pi / 2.0, rel=1e-15, abs=0)


def test_twin_rewritings_match_printed_forms():
    """The twin's integrated-by-parts forms equal the printed integrals where those are well conditioned."""
    for eps in (0.01, 0.1, 0.5, 0.9, 1.0, 2.0, 10.0):
        assert rl.radial_integral(eps) == pytest.approx(rl.radial_integral_direct(eps), rel=1e-11, abs=0)
    for delta_r, Pd in ((1e-5, 0.0), (1e-5, 1e-5), (3e-5, 12e-6), (1e-5, -1e-5), (1e-6, -30e-6)):
        force, slope = rl.radial_force_and_slope(delta_r, Pd, K_6208, 9)
        assert force == pytest.approx(rl.radial_force_direct(delta_r, Pd, K_6208, 9), rel=1e-11, abs=0)
        h = 1e-4 * delta_r  # central difference, truncation ~ (h/delta_r)^2
        fd = (
            rl.radial_force_and_slope(delta_r + h, Pd, K_6208, 9)[0]
            - rl.radial_force_and_slope(delta_r - h, Pd, K_6208, 9)[0]
        ) / (2.0 * h)
        assert slope == pytest.approx(fd, rel=1e-7, abs=0)


@pytest.mark.parametrize("eps", [1e-9, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999, 1.0, 1.001, 1.5, 3.0, 100.0])
def test_radial_integral_on_grid(eps):
    assert_close(
        ld.radial_integral(eps, NODES, WEIGHTS), rl.radial_integral(eps), RTOL_GL + conditioning(eps), f"J_r({eps})"
    )


@FAST
@given(log_eps=floats(-9.0, 4.0))
def test_radial_integral_random(log_eps):
    eps = 10.0**log_eps
    assert_close(
        ld.radial_integral(eps, NODES, WEIGHTS), rl.radial_integral(eps), RTOL_GL + conditioning(eps), f"J_r({eps})"
    )


def test_radial_integral_edges_and_seed_value():
    # eps <= 0: no ball loaded (the kernel's domain is eps > 0; eps = 0 itself divides by zero)
    assert ld.radial_integral(-0.5, NODES, WEIGHTS) == 0.0 == rl.radial_integral(-0.5)
    # eps -> inf: every ball equally loaded, no net radial force
    assert abs(ld.radial_integral(math.inf, NODES, WEIGHTS)) <= 1e-15 and rl.radial_integral(math.inf) == 0.0
    # Harris & Kotzalas (2006): J_r(0.5) = 0.2288, and Q_max = 1457 N for the 6208 at F_r = 3000 N, P_d = 0
    J = ld.radial_integral(0.5, NODES, WEIGHTS)
    assert J == pytest.approx(0.2288, abs=5e-5)
    assert 3000.0 / (9 * J) == pytest.approx(1457.0, abs=0.5)


@pytest.mark.parametrize("delta_r, Pd, eps", [(1e-5, 0.0, 0.5), (2e-5, -10e-6, 0.625), (2e-5, 12.6e-6, 0.3425)])
def test_stribeck_load_is_the_compression_law(delta_r, Pd, eps):
    """Q_max [1 - (1 - cos psi)/(2 eps)]^1.5 == K (delta_r cos psi - P_d/2)_+^1.5 with Q_max at psi = 0."""
    assert ld.load_parameter(delta_r, Pd) == pytest.approx(eps, rel=1e-12, abs=0)
    Q_max = K_6208 * (delta_r - Pd / 2.0) ** 1.5
    for psi in np.linspace(-math.pi, math.pi, 37):
        q = ld.stribeck_load(psi, Q_max, eps)
        # at the edge of the loaded zone (here psi = +-90 deg at eps = 0.5) the bracket is a difference of
        # nearly equal numbers: its absolute error ~ eps_mach/eps gives Q errors ~ Q_max (eps_mach/eps)^1.5
        assert_close(
            q,
            rl.stribeck_load(psi, Q_max, eps),
            RTOL + conditioning(eps),
            f"Q({psi})",
            atol=Q_max * (4.0 * EPS / eps) ** 1.5,
        )
        law = K_6208 * max(delta_r * math.cos(psi) - Pd / 2.0, 0.0) ** 1.5
        assert q == pytest.approx(law, rel=1e-9, abs=1e-9 * Q_max)


@FAST
@given(delta_r=floats(1e-9, 1e-4), Pd=floats(-50e-6, 50e-6))
def test_load_parameter_random(delta_r, Pd):
    assert_close(ld.load_parameter(delta_r, Pd), rl.load_parameter(delta_r, Pd), RTOL, "eps")


def test_load_parameter_at_zero_shift_with_preload():
    assert ld.load_parameter(0.0, -10e-6) == math.inf == rl.load_parameter(0.0, -10e-6)


@pytest.mark.parametrize("Pd", [0.0, 12.6e-6])
def test_load_parameter_at_zero_shift_without_preload(Pd):
    assert ld.load_parameter(0.0, Pd) == rl.load_parameter(0.0, Pd)


@pytest.mark.parametrize("Pd", [-20e-6, -1e-6, 0.0, 1e-6, 12.6e-6])
@pytest.mark.parametrize("delta_r", [1e-7, 1e-6, 5e-6, 2e-5, 1e-4])
def test_radial_force_and_slope_on_grid(Pd, delta_r):
    got = ld.radial_force_and_slope(delta_r, Pd, K_6208, 9, NODES, WEIGHTS)
    want = rl.radial_force_and_slope(delta_r, Pd, K_6208, 9)
    cond = conditioning(rl.load_parameter(delta_r, Pd))
    if want[0] == 0.0:  # no ball reaches the outer race (delta_r <= P_d/2)
        assert got == (0.0, 0.0)
        return
    assert_close(got[0], want[0], RTOL_GL + cond, "F_r")
    assert_close(got[1], want[1], RTOL_SLOPE + cond, "dF_r/d delta_r")


@FAST
@given(log_delta=floats(-9.0, -4.0), Pd=floats(-50e-6, 50e-6), log_k=floats(9.0, 11.0), Z=st.integers(3, 40))
def test_radial_force_and_slope_random(log_delta, Pd, log_k, Z):
    delta_r, K = 10.0**log_delta, 10.0**log_k
    got = ld.radial_force_and_slope(delta_r, Pd, K, Z, NODES, WEIGHTS)
    want = rl.radial_force_and_slope(delta_r, Pd, K, Z)
    cond = conditioning(rl.load_parameter(delta_r, Pd))
    assert_close(got[0], want[0], RTOL_GL + cond, "F_r")
    assert_close(got[1], want[1], RTOL_SLOPE + cond, "dF_r/d delta_r")


def test_radial_force_at_centre():
    # zero clearance or clearance at delta_r = 0: no ball loaded
    for Pd in (0.0, 12.6e-6):
        assert ld.radial_force_and_slope(0.0, Pd, K_6208, 9, NODES, WEIGHTS) == (0.0, 0.0)
        assert rl.radial_force_and_slope(0.0, Pd, K_6208, 9) == (0.0, 0.0)
    # preload, centred ring: every ball equally compressed, no net force
    assert ld.radial_force_and_slope(0.0, -20e-6, K_6208, 9, NODES, WEIGHTS)[0] == 0.0
    assert rl.radial_force_and_slope(0.0, -20e-6, K_6208, 9)[0] == 0.0


def test_radial_slope_at_centre_with_preload():
    Pd = -20e-6
    expected = 0.75 * 9 * K_6208 * math.sqrt(-Pd / 2.0)
    assert rl.radial_force_and_slope(0.0, Pd, K_6208, 9)[1] == pytest.approx(expected, rel=1e-12, abs=0)
    assert ld.radial_force_and_slope(0.0, Pd, K_6208, 9, NODES, WEIGHTS)[1] == pytest.approx(
        expected, rel=RTOL_SLOPE, abs=0
    )


@pytest.mark.parametrize("Pd", [-25e-6, -12.6e-6, 0.0, 12.6e-6, 40e-6])
@pytest.mark.parametrize("F_r", [1.0, 100.0, 3000.0, 20000.0])
def test_solve_radial_shift_on_grid(Pd, F_r):
    delta_r, iters = ld.solve_radial_shift(F_r, Pd, K_6208, 9, NODES, WEIGHTS, 1e-12)
    want = rl.solve_radial_shift(F_r, Pd, K_6208, 9)
    assert_close(delta_r, want, RTOL_GL + conditioning(rl.load_parameter(want, Pd)), f"delta_r(F_r={F_r}, Pd={Pd})")
    assert 1 <= iters < 200  # converged, not stopped by the iteration cap
    # the kernel's own force at its solution is F_r to its tolerance
    assert ld.radial_force_and_slope(delta_r, Pd, K_6208, 9, NODES, WEIGHTS)[0] == pytest.approx(F_r, rel=1e-11, abs=0)


@FAST
@given(log_f=floats(-3.0, 5.0), Pd=floats(-50e-6, 50e-6), log_k=floats(9.0, 11.0), Z=st.integers(3, 40))
def test_solve_radial_shift_random(log_f, Pd, log_k, Z):
    F_r, K = 10.0**log_f, 10.0**log_k
    delta_r, iters = ld.solve_radial_shift(F_r, Pd, K, Z, NODES, WEIGHTS, 1e-14)
    want = rl.solve_radial_shift(F_r, Pd, K, Z)
    assert_close(delta_r, want, RTOL_GL + conditioning(rl.load_parameter(want, Pd)), "delta_r")
    assert iters < 200 or F_r < 1.0  # light loads with preload may reach the cap, see below


def test_solve_radial_shift_without_load():
    """F_r = 0: with clearance the ring rests at P_d/2 (balls just touching, eps = 0); with preload it
    stays centred (eps = inf); no iteration either way."""
    for Pd, expected in ((12.6e-6, 6.3e-6), (0.0, 0.0), (-12.6e-6, 0.0)):
        delta_r, iters = ld.solve_radial_shift(0.0, Pd, K_6208, 9, NODES, WEIGHTS, 1e-12)
        assert (delta_r, iters) == (expected, 0)
        assert rl.solve_radial_shift(0.0, Pd, K_6208, 9) == expected
    assert ld.load_parameter(6.3e-6, 12.6e-6) == 0.0
    assert ld.load_parameter(0.0, -12.6e-6) == math.inf


def test_eps_at_or_above_one_loads_every_ball():
    """Preload heavy enough that even the ball at psi = pi stays compressed: psi_l = pi."""
    Pd = -25e-6
    delta_r, _ = ld.solve_radial_shift(1000.0, Pd, K_6208, 9, NODES, WEIGHTS, 1e-12)
    eps = ld.load_parameter(delta_r, Pd)
    assert eps >= 1.0 and delta_r * -1.0 - Pd / 2.0 > 0.0
    assert ld.loaded_half_angle(eps) == math.pi
    J = ld.radial_integral(eps, NODES, WEIGHTS)
    assert rel_err(J, rl.radial_integral(eps)) <= RTOL_GL + conditioning(eps)


def test_light_load_with_preload_converges():
    delta_r, iters = ld.solve_radial_shift(1e-9, -12e-6, K_6208, 9, NODES, WEIGHTS, 1e-12)
    assert abs(delta_r - rl.solve_radial_shift(1e-9, -12e-6, K_6208, 9)) <= 1e-20
    assert iters < 200
