"""kernels.geometry against its twin tests/reference/ref_geometry.py (+ kinematic checks).

Tolerances (measured max discrepancy on 3000 random geometries in the hypothesis domains below):
- RTOL = 1e-12 for all closed forms. gamma, kinematics, frequencies, mass, centrifugal force agree
  to 4e-16 (a few ulp). The twin's curvature radii go through the curvature sum 2/D - 1/(f D),
  which cancels by a factor 1/(2f - 1) (<= 100 for f >= 0.505): <= 100 x 2.2e-16 ~ 2e-14;
  measured 1.8e-14 (7e-14 with f >= 0.501). 1e-12 leaves an order of magnitude.
- Free contact angle and endplay: the kernel evaluates arccos(1 - x), x = P_d/(2A), whose
  relative condition number is about 1/(4x) for small x (rounding of 1 - x is eps/2); the twin uses
  the well-conditioned half-angle form 2 asin(sqrt(P_d/(4A))). Tolerance 1e-12 + eps/x
  (4 x the conditioning bound); measured 1.8e-13 over |P_d| <= 0.02 D.
"""

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import geometry as gk
from tests.reference import ref_geometry as rg
from tests.unit._compare import assert_close

RTOL = 1e-12
EPS = np.finfo(float).eps
FAST = settings(max_examples=50, deadline=None)
# finite, normal floats: subnormal inputs (< 2.2e-308) have no physical meaning and lose precision
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)

# 6208 of Guessasma & Machado (2018, Table 1) and two other shapes: (D, d_m, f_i, f_o)
GEOMETRIES = [
    (12.6e-3, 60.6e-3, 0.52, 0.52),
    (12.7e-3, 51e-3, 0.515, 0.525),
    (15.875e-3, 97.5e-3, 0.52, 0.53),
    (2e-3, 40e-3, 0.501, 0.6),
]
ANGLES = [0.0, 0.26, 0.7, 1.2]

diameters = floats(1e-3, 50e-3)
pitch_ratios = floats(1.5, 20.0)
conformities = floats(0.505, 0.6)
angles = floats(0.0, 1.2)
speeds = floats(-3000.0, 3000.0)


def angle_tol(D, f_i, f_o, Pd):
    x = Pd / (2.0 * (f_i + f_o - 1.0) * D)
    return RTOL + (EPS / x if x > 0.0 else 0.0)


@pytest.mark.parametrize("D, dm, f_i, f_o", GEOMETRIES)
@pytest.mark.parametrize("alpha", ANGLES)
def test_closed_forms_on_grid(D, dm, f_i, f_o, alpha):
    assert_close(gk.gamma_ratio(D, dm, alpha), rg.gamma_ratio(D, dm, alpha), RTOL, "gamma")
    assert_close(gk.curvature_radii(D, dm, f_i, f_o, alpha), rg.curvature_radii(D, dm, f_i, f_o, alpha), RTOL, "radii")
    for omega in (-1000.0, -1.0, 0.0, 1.0, 500.0, 3000.0):
        assert_close(
            gk.rolling_kinematics(omega, D, dm, alpha), rg.rolling_kinematics(omega, D, dm, alpha), RTOL, "kinematics"
        )
        assert_close(
            gk.defect_frequencies(omega, D, dm, alpha, 9),
            rg.defect_frequencies(omega, D, dm, alpha, 9),
            RTOL,
            "frequencies",
        )
    for Pd in (-0.02 * D, -1e-6, 0.0, 1e-9, 1e-6, 12.6e-6, 0.02 * D):
        tol = angle_tol(D, f_i, f_o, Pd)
        assert_close(gk.free_contact_angle(D, f_i, f_o, Pd), rg.free_contact_angle(D, f_i, f_o, Pd), tol, "alpha0")
        assert_close(gk.free_endplay(D, f_i, f_o, Pd), rg.free_endplay(D, f_i, f_o, Pd), tol, "endplay")


@FAST
@given(
    D=diameters,
    ratio=pitch_ratios,
    f_i=conformities,
    f_o=conformities,
    alpha=angles,
    omega=speeds,
    Z=st.integers(3, 60),
    pd_frac=floats(-0.02, 0.02),
    rho=floats(1000.0, 16000.0),
)
def test_closed_forms_random(D, ratio, f_i, f_o, alpha, omega, Z, pd_frac, rho):
    dm = ratio * D
    Pd = pd_frac * D
    assert_close(gk.gamma_ratio(D, dm, alpha), rg.gamma_ratio(D, dm, alpha), RTOL, "gamma")
    assert_close(gk.curvature_radii(D, dm, f_i, f_o, alpha), rg.curvature_radii(D, dm, f_i, f_o, alpha), RTOL, "radii")
    tol = angle_tol(D, f_i, f_o, Pd)
    assert_close(gk.free_contact_angle(D, f_i, f_o, Pd), rg.free_contact_angle(D, f_i, f_o, Pd), tol, "alpha0")
    assert_close(gk.free_endplay(D, f_i, f_o, Pd), rg.free_endplay(D, f_i, f_o, Pd), tol, "endplay")
    assert_close(gk.rolling_kinematics(omega, D, dm, alpha), rg.rolling_kinematics(omega, D, dm, alpha), RTOL, "kin")
    assert_close(
        gk.defect_frequencies(omega, D, dm, alpha, Z),
        rg.defect_frequencies(omega, D, dm, alpha, Z),
        RTOL,
        "frequencies",
    )
    m = gk.ball_mass(D, rho)
    assert_close(m, rg.ball_mass(D, rho), RTOL, "mass")
    w_c = gk.rolling_kinematics(omega, D, dm, alpha)[0]
    assert_close(gk.centrifugal_force(m, dm, w_c), rg.centrifugal_force(m, dm, w_c), RTOL, "F_c")


def test_no_clearance_or_preload_gives_zero_angle_and_endplay():
    D, f = 12.6e-3, 0.52
    for Pd in (0.0, -1e-9, -12.6e-6):
        assert gk.free_contact_angle(D, f, f, Pd) == 0.0 == rg.free_contact_angle(D, f, f, Pd)
        assert gk.free_endplay(D, f, f, Pd) == 0.0 == rg.free_endplay(D, f, f, Pd)
    # clearance beyond 4A (grooves cannot hold the ball): the angle saturates at pi, no endplay
    A = (2 * f - 1) * D
    assert gk.free_contact_angle(D, f, f, 5 * A) == math.pi == rg.free_contact_angle(D, f, f, 5 * A)


def test_endplay_matches_the_clearance_geometry():
    """P_e = 2A sin(alpha0) and P_d = 2A(1 - cos alpha0): the two clearances of one free contact angle."""
    D, f_i, f_o, Pd = 12.6e-3, 0.52, 0.52, 12.6e-6
    A = (f_i + f_o - 1.0) * D
    a0 = gk.free_contact_angle(D, f_i, f_o, Pd)
    assert a0 == pytest.approx(rg.free_contact_angle(D, f_i, f_o, Pd), rel=angle_tol(D, f_i, f_o, Pd), abs=0)
    assert 2.0 * A * (1.0 - math.cos(a0)) == pytest.approx(Pd, rel=1e-9, abs=0)
    assert gk.free_endplay(D, f_i, f_o, Pd) == pytest.approx(2.0 * A * math.sin(a0), rel=1e-12, abs=0)


@pytest.mark.parametrize("D, dm, f_i, f_o", GEOMETRIES)
@pytest.mark.parametrize("omega", [500.0, -500.0, 1e-3])
def test_pure_rolling_has_no_slip_at_either_race(D, dm, f_i, f_o, omega):
    """alpha = 0: the kernel's speeds roll without slip on the fixed outer and the turning inner race.

    Ball spin Omega_B (same sign convention as omega) = -omega_ball_fixed (the kernel counts the
    fixed-frame spin in the sense opposite to the cage). Surface speeds, tangential, +omega sense:
    outer contact v_c + Omega_B D/2 = 0; inner contact v_c - Omega_B D/2 = omega (d_m - D)/2.
    """
    w_c, w_rel, w_fixed, u = gk.rolling_kinematics(omega, D, dm, 0.0)
    v_c = w_c * dm / 2.0
    Omega_B = -w_fixed
    scale = abs(omega) * dm
    assert abs(v_c + Omega_B * D / 2.0) <= 1e-14 * scale
    assert abs(v_c - Omega_B * D / 2.0 - omega * (dm - D) / 2.0) <= 1e-14 * scale
    # relative to the cage the ball turns at Omega_B - w_c, opposite to the cage
    assert abs((Omega_B - w_c) + w_rel) <= 1e-14 * scale / D
    # entrainment: ring speed in the cage frame, the same at both contacts
    assert u == pytest.approx((omega - w_c) * (dm - D) / 2.0, rel=1e-13, abs=0)
    assert u == pytest.approx(w_c * (dm + D) / 2.0, rel=1e-13, abs=0)


def test_negative_speed_reverses_every_kinematic_quantity():
    D, dm = 12.6e-3, 60.6e-3
    for alpha in ANGLES:
        fwd = gk.rolling_kinematics(500.0, D, dm, alpha)
        back = gk.rolling_kinematics(-500.0, D, dm, alpha)
        assert all(b == -f and f > 0.0 for f, b in zip(fwd, back))
        assert_close(back, rg.rolling_kinematics(-500.0, D, dm, alpha), RTOL, "kinematics at -omega")
        freq_f = gk.defect_frequencies(500.0, D, dm, alpha, 9)
        freq_b = gk.defect_frequencies(-500.0, D, dm, alpha, 9)
        assert all(b == -f for f, b in zip(freq_f, freq_b))
        # centrifugal force is even in the speed
        m = gk.ball_mass(D, 7850.0)
        assert gk.centrifugal_force(m, dm, back[0]) == gk.centrifugal_force(m, dm, fwd[0]) > 0.0


def test_seed_6208_speeds():
    """omega = 500 rad/s -> ball 952.38 rad/s fixed frame, 1150.4 rad/s relative to the cage,
    cage 198.0 rad/s (Guessasma 2018); the printed digits bound the tolerance."""
    w_c, w_rel, w_fixed, u = gk.rolling_kinematics(500.0, 12.6e-3, 60.6e-3, 0.0)
    assert w_fixed == pytest.approx(952.38, abs=0.005)
    assert w_rel == pytest.approx(1150.4, abs=0.05)
    assert w_c == pytest.approx(198.0, abs=0.05)
    assert u == pytest.approx(500.0 * 60.6e-3 * (1.0 - (12.6 / 60.6) ** 2) / 4.0, rel=1e-14, abs=0)


@FAST
@given(
    omega=floats(min_value=-5000.0, max_value=5000.0),
    cage=floats(min_value=-3000.0, max_value=3000.0),
    ball=floats(min_value=-20000.0, max_value=20000.0),
    Z=st.integers(min_value=3, max_value=40),
)
def test_pass_frequencies_twin(omega, cage, ball, Z):
    """Frequencies from solved speeds (any slip, either sense) against the twin; closed forms: RTOL."""
    assert_close(gk.pass_frequencies(omega, cage, ball, Z), rg.pass_frequencies(omega, cage, ball, Z), RTOL, "freq")


def test_pass_frequencies_in_pure_rolling_are_the_defect_frequencies():
    """Fed the pure-rolling speeds, the frequencies from speeds are the catalogue closed forms (magnitudes:
    a frequency has no sense), for both senses of rotation and every contact angle."""
    D, dm, Z = 12.6e-3, 60.6e-3, 9
    for omega in (500.0, -500.0):
        for alpha in ANGLES:
            cage, ball_rel, _, _ = gk.rolling_kinematics(omega, D, dm, alpha)
            closed = [abs(f) for f in gk.defect_frequencies(omega, D, dm, alpha, Z)]
            assert_close(gk.pass_frequencies(omega, cage, ball_rel, Z), closed, RTOL, "pure rolling")


def test_ball_direction_twin_and_convention():
    """Ball 0 exactly on +y, the others counter-clockwise (toward -x first) every 2 pi / Z; against the twin
    to 2 ulp of a unit vector (the twin adds pi/2 in floating point: abs 1e-15)."""
    for Z in (7, 8, 9, 16):
        assert gk.ball_direction(0, Z) == (-0.0, 1.0)
        for j in range(Z):
            c, s = gk.ball_direction(j, Z)
            assert_close((c, s), rg.ball_direction(j, Z), 0.0, f"ball {j} of {Z}", atol=1e-15)
    # a quarter of the balls on: +y, -x, -y, +x in turn for Z = 8
    quarter = [tuple(round(v) for v in gk.ball_direction(j, 8)) for j in (0, 2, 4, 6)]
    assert quarter == [(0, 1), (-1, 0), (0, -1), (1, 0)]
