"""kernels.rating_life against its twin tests/reference/ref_rating_life.py, and the checks of its tables."""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import rating_life as rl
from tests.reference import ref_rating_life as ref
from tests.unit._compare import rel_err

RAD = math.pi / 180.0
# (Z, D, dm, f_i, f_o, alpha): a 6208 (Guessasma 2018), the B7214C estimate, a 40 deg bearing, a large ball
GEOMETRIES = (
    (9, 12.6e-3, 60.6e-3, 0.52, 0.52, 0.0),
    (17, 15.875e-3, 97.5e-3, 0.52, 0.53, 15.0 * RAD),
    (14, 11.0e-3, 60.0e-3, 0.515, 0.525, 40.0 * RAD),
    (12, 30.0e-3, 200.0e-3, 0.52, 0.53, 25.0 * RAD),
)
ANGULAR = (0.0, 1.0, 1.0, 1.0)
GAMMAS = np.linspace(0.0, 0.45, 91)
LOAD_RATIOS = (0.05, 0.172, 0.3, 1.0, 2.5, 6.89, 9.0)
ALPHAS_DEG = (0.0, 10.0, 15.0, 17.5, 20.0, 22.0, 30.0, 45.0)


def parameters(k):
    lp, lp_twin = np.zeros(rl.LP_SIZE), np.zeros(rl.LP_SIZE)
    rl.rating_parameters(ANGULAR[k], *GEOMETRIES[k], lp)
    ref.rating_parameters(ANGULAR[k], *GEOMETRIES[k], lp_twin)
    return lp, lp_twin


def test_tables_and_ratings_match_twin():
    for g in GAMMAS:
        assert rel_err(rl.iso281_fc(g), ref.iso281_fc(g)) < 1e-13
        assert (
            rel_err(
                rl._interpolate(g, rl.RADIAL_LOAD_RATIO, rl.RADIAL_Y),
                ref._interpolate(g, rl.RADIAL_LOAD_RATIO, rl.RADIAL_Y),
            )
            < 1e-13
        )
    for D in (1e-3, 12.6e-3, 25.4e-3, 25.5e-3, 40e-3):
        assert rel_err(rl._ball_size_term(D), ref._ball_size_term(D)) < 1e-13
    for geometry in GEOMETRIES:
        assert (
            rel_err(
                rl.iso281_dynamic_rating(*geometry[:2], geometry[2], geometry[5]),
                ref.iso281_dynamic_rating(*geometry[:2], geometry[2], geometry[5]),
            )
            < 1e-13
        )
        assert rel_err(rl.contact_ratings(*geometry), ref.contact_ratings(*geometry)) < 1e-13
    for k in range(len(GEOMETRIES)):
        lp, lp_twin = parameters(k)
        own = [i for i in range(rl.LP_SIZE) if i not in (rl.LP_C_0R, rl.LP_F_0)]
        assert rel_err(lp[own], lp_twin[own]) < 1e-12
        # ISO 76's f_0 and C_0r: the kernel's table against the twin's definition (0.45 %, kernels/torque.py)
        assert rel_err(lp[[rl.LP_C_0R, rl.LP_F_0]], lp_twin[[rl.LP_C_0R, rl.LP_F_0]]) < 4.5e-3


def test_factors_and_equivalent_load_match_twin():
    for ratio in LOAD_RATIOS:
        assert rel_err(rl.iso281_factors(0.0, 0.0, ratio), ref.iso281_factors(False, 0.0, ratio)) < 1e-13
        for alpha in ALPHAS_DEG:
            assert rel_err(rl.iso281_factors(1.0, alpha, ratio), ref.iso281_factors(True, alpha, ratio)) < 1e-13
    for k in range(len(GEOMETRIES)):
        lp, _ = parameters(k)
        for F_r, F_a in ((1000.0, 0.0), (1000.0, 100.0), (1000.0, 900.0), (0.0, 2000.0), (300.0, 5000.0)):
            assert rel_err(rl.equivalent_dynamic_load(F_r, F_a, lp), ref.equivalent_dynamic_load(F_r, F_a, lp)) < 1e-13


def test_lives_match_twin():
    rng = np.random.default_rng(3)
    for k in range(len(GEOMETRIES)):
        lp, _ = parameters(k)
        Z = GEOMETRIES[k][0]
        for scale in (0.0, 10.0, 3000.0):
            Q_i = np.clip(rng.normal(scale, scale, Z), 0.0, None)
            Q_o = Q_i + 0.1 * scale
            for w in (rl.EXPONENT_ROTATING, rl.EXPONENT_STATIONARY):
                assert rel_err(rl.equivalent_contact_load(Q_i, w), ref.equivalent_contact_load(Q_i, w)) < 1e-13
            for omega in (0.0, -50.0, 1047.0):
                out, out_twin = np.zeros(rl.LO_SIZE), np.zeros(rl.LO_SIZE)
                F_r, F_a = 0.5 * Q_i.sum(), 0.2 * Q_i.sum()
                rl.rating_life(Q_i, Q_o, F_r, F_a, omega, lp, out)
                ref.rating_life(Q_i, Q_o, F_r, F_a, omega, lp, out_twin)
                assert rel_err(out, out_twin) < 1e-12, (k, scale, omega)
    for rating, load in ((1e4, 0.0), (1e4, 1.0), (1e4, 1e-9), (3e4, 5e3)):
        assert rel_err(rl.life_revolutions(rating, load, 3.0), ref.life_revolutions(rating, load, 3.0)) < 1e-13
    for L_i, L_e in ((1e9, 1e9), (1e9, 1e12), (rl.LIFE_INFINITE, 2e8)):
        assert rel_err(rl.combined_life(L_i, L_e), ref.combined_life(L_i, L_e)) < 1e-13
    for revolutions, omega in ((1e9, 0.0), (1e9, 100.0), (1e9, -100.0), (rl.LIFE_INFINITE, 5.0), (1e29, 1e-6)):
        assert rel_err(rl.life_hours(revolutions, omega), ref.life_hours(revolutions, omega)) < 1e-13


def test_spring_constant_matches_twin_and_exact_hertz():
    """The ISO/TS 16281 form is exact Hertz with 1.48 for pi sqrt(2)/3 = 1.48096 (docs/rating_life.md)."""
    from bearing_fmu.kernels.hertz import hertz_coefficients_exact, hertz_stiffness

    for Rx, Ry in ((5.0e-3, 0.16), (7.5e-3, 0.11), (1e-3, 1e-3)):
        coeff = hertz_coefficients_exact(Rx, Ry)
        c = rl.iso16281_spring_constant(Rx, Ry, 2.3e11, *coeff)
        assert rel_err(c, ref.iso16281_spring_constant(Rx, Ry, 2.3e11, *coeff)) < 1e-13
        exact = hertz_stiffness(Rx, Ry, 2.3e11, *coeff)
        assert c / exact == pytest.approx(1.48 / (math.pi * math.sqrt(2.0) / 3.0), rel=1e-12)


def test_fc_table_has_the_lundberg_palmgren_shape():
    """The transcribed f_c column is one constant times the Lundberg-Palmgren shape of equal conformities
    (Harris & Kotzalas 2006; the f_c formula behind ISO 281, ISO/TR 1281-1):
    [1 + (1.04 ((1 - g)/(1 + g))^1.72)^(10/3)]^-0.3 g^0.3 (1 - g)^1.39 / (1 + g)^(1/3).
    Tolerance 0.3 %: the entries are printed to 0.1 on 29-60 (rounding up to 0.17 %), a misread digit
    (e.g. 58.2 for 58.8) moves an entry by 1 % or more."""
    g = np.arange(1, len(rl.FC_TABLE) + 1) * rl.FC_GAMMA_STEP
    shape = (
        (1 + (1.04 * ((1 - g) / (1 + g)) ** 1.72) ** (10 / 3)) ** -0.3 * g**0.3 * (1 - g) ** 1.39 / (1 + g) ** (1 / 3)
    )
    ratio = np.array(rl.FC_TABLE) / shape
    assert np.all(np.abs(ratio / np.median(ratio) - 1.0) < 3e-3), ratio


def test_table_3_rows_are_monotonic_and_continuous():
    """e grows and Y falls with the load ratio and the angle (ISO 281 Table 3); X F_r + Y F_a meets F_r at
    F_a/F_r = e to within the table's rounding (X + Y e = 1 within 1 %: e and Y are printed to two and three digits)."""
    for ratios, e, Y, X in (
        (rl.RADIAL_LOAD_RATIO, rl.RADIAL_E, rl.RADIAL_Y, rl.RADIAL_X),
        (rl.AC15_LOAD_RATIO, rl.AC15_E, rl.AC15_Y, rl.AC15_X),
    ):
        assert np.all(np.diff(ratios) > 0) and np.all(np.diff(e) >= 0) and np.all(np.diff(Y) <= 0)
        assert np.all(np.abs(X + np.array(Y) * np.array(e) - 1.0) < 0.01)
    assert np.all(np.abs(np.array(rl.AC_X) + np.array(rl.AC_Y) * np.array(rl.AC_E) - 1.0) < 0.01)


def test_reference_life_of_equal_loads_is_the_race_combination():
    """All balls equally loaded (pure axial load): Q_ei = Q_ee = Q and L10r = (L_i^-e + L_e^-e)^(-1/e) with
    L = (Q_c/Q)^3 10^6, e = 10/9, written out here."""
    lp, _ = parameters(1)
    Q = np.full(17, 400.0)
    out = np.zeros(rl.LO_SIZE)
    rl.rating_life(Q, Q, 0.0, 17 * 400.0 * math.sin(15 * RAD), 300.0, lp, out)
    L_i = 1e6 * (lp[rl.LP_Q_CI] / 400.0) ** 3
    L_e = 1e6 * (lp[rl.LP_Q_CE] / 400.0) ** 3
    assert out[rl.LO_L10R] == pytest.approx((L_i ** (-10 / 9) + L_e ** (-10 / 9)) ** -0.9, rel=1e-12)
    assert out[rl.LO_L10R_H] == pytest.approx(out[rl.LO_L10R] / (300.0 / (2 * math.pi)) / 3600.0, rel=1e-12)


def test_unloaded_or_resting_bearing_reports_the_infinite_life():
    lp, _ = parameters(0)
    out = np.zeros(rl.LO_SIZE)
    rl.rating_life(np.zeros(9), np.zeros(9), 0.0, 0.0, 100.0, lp, out)
    assert np.all(out == rl.LIFE_INFINITE)
    rl.rating_life(np.full(9, 100.0), np.full(9, 100.0), 500.0, 0.0, 0.0, lp, out)
    assert out[rl.LO_L10] < rl.LIFE_INFINITE and out[rl.LO_L10_H] == rl.LIFE_INFINITE
    assert out[rl.LO_L10R] < rl.LIFE_INFINITE and out[rl.LO_L10R_H] == rl.LIFE_INFINITE
