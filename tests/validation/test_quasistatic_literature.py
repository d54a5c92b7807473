"""Quasi-static fidelity against the literature (model: docs/quasistatic.md).

- Load parameter eps vs clearance: Guessasma et al. 2018 App. A and Farah et al. 2020 App. A.
- Rabreau et al. 2018 Figs. 4-5 (qualitative): the three kinematic models agree at rest and differ at
  10 000 rpm; the outer contact angle falls and the axial stiffness changes with speed.
- Rolling kinematics of the 6208 (Guessasma 2018 section 3.1): cage and ball speeds of pure rolling.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import jones_harris
from bearing_fmu.models.limits import InputError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from tests.cases import guessasma_6208, outside

T_OIL = 313.15
RPM = 2.0 * math.pi / 60.0


def scene(**options):
    return guessasma_6208.quasi_static_scene(**options)


@pytest.mark.parametrize("F_r, Pd, printed", guessasma_6208.EPS_PUBLISHED)
def test_load_parameter_vs_clearance(F_r, Pd, printed):
    """eps = (1 - P_d/(2 delta_r))/2 from the solver's radial displacement delta_r = y at omega ~ 0
    (1e-3 rad/s: speed effects ~1e-12 of the loads) against Guessasma App. A (3 kN) and Farah App. A (5 kN).
    Tolerance 1 %: the papers print 2-3 digits from a 9-ball DEM at 1 rad/s; this is the same 9-ball discrete
    bearing, so the remaining difference is their rounding and their dynamic solution
    (tests/cases/guessasma_6208.py)."""
    (comparison,) = guessasma_6208.eps_comparisons(guessasma_6208.quasi_static_eps, [(F_r, Pd, printed)])
    assert comparison.within, comparison


def test_pure_rolling_kinematics_6208():
    """Guessasma 2018 section 3.1 (ball speed; the cage speed follows from pure rolling): omega =
    500 rad/s, P_d = 0, F_r = 3 kN, contact angle 0: cage 198.02 rad/s, ball 952.38 rad/s in the fixed
    frame (printed to 5 digits: 1e-4)."""
    comparisons = guessasma_6208.rolling_comparisons()
    assert not outside(comparisons), outside(comparisons)


MODELS = {"ORC": ("outer", False), "ORCG": ("outer", True), "HT": ("hybrid", True)}


def rabreau_state(label, omega, F_a, hybrid_split="spin_moments"):
    race, gyro = MODELS[label]
    model = QuasiStaticModel(
        "B7214C", "iso_vg68_mineral", scene(gyroscopic=gyro), race_control=race, hybrid_split=hybrid_split
    )
    return model.evaluate(omega=omega, F_z=F_a, T_oil=T_OIL)


@pytest.mark.parametrize("F_a", [200.0, 800.0, 3500.0])
def test_rabreau_models_agree_at_rest(F_a):
    """Rabreau 2018 section 2.3: 'The three models are perfectly in agreement for a static state
    (0 rpm)' -- at rest neither centrifugal force nor gyroscopic moment exists, so the contact angle
    and axial stiffness of ORC, ORCG and HT must be identical (to rounding, 1e-12)."""
    ref = rabreau_state("ORC", 0.0, F_a)
    for label in ("ORCG", "HT"):
        out = rabreau_state(label, 0.0, F_a)
        assert out["alpha_outer"] == pytest.approx(ref["alpha_outer"], rel=1e-12)
        assert out["K[3,3]"] == pytest.approx(ref["K[3,3]"], rel=1e-12)


def test_rabreau_models_differ_at_speed():
    """Rabreau 2018 Figs. 4-5 (qualitative; curves not tabulated, B7214C internal geometry
    estimated): at 10 000 rpm centrifugal force lowers the outer contact angle below its rest value
    for all models; the gyroscopic moment (ORCG) lowers it further; the models' axial stiffnesses
    differ by more than 5 % ('noticeable variations between models')."""
    rest = rabreau_state("ORC", 0.0, 800.0)
    speed = {label: rabreau_state(label, 10000 * RPM, 800.0) for label in MODELS}
    for out in speed.values():
        assert out["alpha_outer"] < rest["alpha_outer"] - math.radians(2.0)
        assert out["alpha_inner"] > rest["alpha_inner"] + math.radians(2.0)
    assert speed["ORCG"]["alpha_outer"] < speed["ORC"]["alpha_outer"]
    k = np.array([out["K[3,3]"] for out in speed.values()])
    assert (k.max() - k.min()) / k.max() > 0.05


def test_rabreau_torque_spread_of_the_three_models():
    """Rabreau 2018 section 6: at 10 000 rpm and 800 N 'all of the BB torque models predict almost
    the same level of the friction torque (matching within 2 %)'. NOT reproduced: ORC vs ORCG agree
    within 1 %, but HT is 3.7 % below ORC. the test below finds the cause:
    the share of the gyroscopic moment HT gives the inner race (lam_i = 2C/(1+C) = 0.52, our choice,
    Rabreau's Table 1 missing from our copy of the paper), not the estimated geometry (8 geometries:
    2.9-4.0 %). This test pins the measured spread (2-5 %) so that a change is noticed; it does not claim
    the 2 %."""
    torque = {label: rabreau_state(label, 10000 * RPM, 800.0)["torque"] for label in MODELS}
    assert torque["ORCG"] == pytest.approx(torque["ORC"], rel=0.01)
    spread = (max(torque.values()) - min(torque.values())) / max(torque.values())
    assert 0.02 < spread < 0.05


def test_rabreau_two_percent_needs_the_moment_on_the_outer_race():
    """The sensitivity behind the test above: with the
    hybrid pitch angle but the whole gyroscopic moment on the outer race (hybrid_split 'outer',
    lam_i = 0) the three torques agree within Rabreau's 2 % (we get 1.6 %); with Harris' equal
    split (lam_i = 1) they spread further (5.8 %). The spread grows with lam_i, so the default
    (lam_i = 0.52) lies between. Bounds: Rabreau's 2 % and the default's measured 3.7 %."""

    def spread(split):
        torque = [rabreau_state(label, 10000 * RPM, 800.0, split)["torque"] for label in MODELS]
        return (max(torque) - min(torque)) / max(torque)

    outer, default, equal = spread("outer"), spread("spin_moments"), spread("equal")
    assert outer < 0.02
    assert outer < default < equal


def test_controlling_race_split_is_discontinuous_in_speed():
    """Why the 'controlling_race' reading (Jones' criterion of Rabreau section 2.2: the race with the
    larger spin moment takes the whole gyroscopic moment), which would meet the 2 %, is not the model's:
    at 800 N the B7214C switches from inner to outer at about 3665 rpm. There (a) both fixed shares are
    consistent with the criterion at once -- at 3664 rpm the lam_i = 0 state has C < 1 and the
    lam_i = 2 state has C > 1: two equilibria (report: 3661.13-3666.40 rpm); (b) the axial stiffness
    jumps by more than 5 % (report: -11 %) between 3660 and 3700 rpm, where the continuous default
    changes it by less than 1 % (report: -0.34 %)."""

    def state(split, rpm):
        model = QuasiStaticModel("B7214C", "iso_vg68_mineral", scene(), race_control="hybrid", hybrid_split=split)
        out = model.evaluate(omega=rpm * RPM, F_z=800.0, T_oil=T_OIL)
        Q_i, Q_o = model.balls[jones_harris.BQ_Q_I, 0], model.balls[jones_harris.BQ_Q_O, 0]
        return out, model.qs[jones_harris.QS_C_HYB] * (Q_i / Q_o) ** (4.0 / 3.0)

    assert state("outer", 3664.0)[1] < 1.0 < state("inner", 3664.0)[1]
    for split, low, high in (("controlling_race", 0.05, math.inf), ("spin_moments", 0.0, 0.01)):
        k_before = state(split, 3660.0)[0]["K[3,3]"]
        k_after = state(split, 3700.0)[0]["K[3,3]"]
        assert low < abs(k_after / k_before - 1.0) < high


def test_unknown_hybrid_split_is_rejected():
    with pytest.raises(InputError, match="hybrid_split = 'sideways'.*spin_moments"):
        QuasiStaticModel("B7214C", "iso_vg68_mineral", scene(), race_control="hybrid", hybrid_split="sideways")
