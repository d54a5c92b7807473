"""The DEM's contact-model constants live in a parameter file with units and sources (params/dem_model.toml), as
the bearings and oils do: the papers' values (Farah et al. 2020: PA66 cage E = 3.3 GPa, nu = 0.41; Guessasma &
Machado 2018: alpha_e = 0.08 s/m, K_t = 2/3 K_n, the cage balls' pocket play 0.0026 D) reach the model, and a bad
value is refused naming the key."""

import math

import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import DemModel
from bearing_fmu.params import CATALOGUE, ParameterError, load_dem_constants


def test_the_papers_values_reach_the_model():
    constants = load_dem_constants()
    assert (constants.cage_E, constants.cage_nu, constants.alpha_e) == (3.3e9, 0.41, 0.08)
    assert constants.kt_ratio == pytest.approx(2.0 / 3.0, rel=1e-15)
    model = DemModel("B7214C", "iso_vg68_mineral")  # its bearing file has no [material.cage]
    assert model.par[s.P_ALPHA_E] == constants.alpha_e and model.par[s.P_KT_RATIO] == constants.kt_ratio
    # the cage elements' Hertz constant from PA66 and steel: K = 4/3 E* sqrt(R_eq)
    b = model.bearing
    E_star = 1.0 / ((1.0 - b.ball.nu**2) / b.ball.E + (1.0 - constants.cage_nu**2) / constants.cage_E)
    R = model.par[s.P_R_CAGE]
    R_eq = 0.5 * b.D * R / (0.5 * b.D + R)
    assert model.par[s.P_K_CB] == pytest.approx(4.0 / 3.0 * E_star * math.sqrt(R_eq), rel=1e-14)
    # its cage balls fill the pocket between two balls but for the 6208's play, 0.0026 D
    assert constants.cage_pocket_play == 0.0026
    pitch = model.par[s.P_R_GUIDE]
    play = pitch * 2.0 * math.sin(0.5 * math.pi / b.Z) - 0.5 * b.D - R
    assert play == pytest.approx(constants.cage_pocket_play * b.D, rel=1e-9)
    assert DemModel("6208", "guessasma_oil", kt_ratio=1.0).par[s.P_KT_RATIO] == 1.0  # the argument still wins


def test_a_value_outside_its_range_is_refused(tmp_path):
    text = (CATALOGUE / "dem_model.toml").read_text().replace("value = 0.08,", "value = -1.0,")
    path = tmp_path / "dem_model.toml"
    path.write_text(text)
    with pytest.raises(ParameterError, match=r"'contact.alpha_e' = -1.0 s/m is outside the allowed range"):
        load_dem_constants(path)
