"""A step beyond the DEM's measured accurate range is named to the user (DemModel.warnings, fmi2Warning in the FMU).

docs/reports/dem_steps.md: up to 1.3 x the automatic step every output of the three operating points was within
1e-3 of a 10x finer step; at 1.6 x the 6208 at 3 kN, 500 rad/s ran without a monitor stop with a torque tens of
percent too high. The warning is given once per model, for a fixed step or a safety factor above the default."""

import pytest

from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.dem.time_step import ACCURATE_STEP_FACTOR


@pytest.fixture(scope="module")
def rolling():
    """The 6208 under 3 kN at 500 rad/s after a 5 ms ramp (the validation's start-up, shortened)."""
    model = DemModel("6208", "guessasma_oil")
    model.advance(2e-3, omega=0.0, F_y=3000.0)
    model.advance(7e-3, omega=500.0, F_y=3000.0)
    model.advance(10e-3, omega=500.0, F_y=3000.0)
    return model.get_state(), model.automatic_time_step(F_y=3000.0, omega=500.0)


def _model(state, **settings):
    model = DemModel("6208", "guessasma_oil", **settings)
    model.set_state(state)
    return model


def _step_warnings(model):
    return [w for w in model.warnings if "automatic step" in w]


def test_a_fixed_step_beyond_the_accurate_range_is_warned_once(rolling):
    state, automatic = rolling
    model = _model(state, dt=1.6 * automatic)
    model.advance(model.time + 0.2e-3, omega=500.0, F_y=3000.0)
    (warning,) = _step_warnings(model)
    assert "fixed step" in warning and f"{ACCURATE_STEP_FACTOR:g} x" in warning and "dt = 0" in warning
    model.advance(model.time + 0.2e-3, omega=500.0, F_y=3000.0)
    assert _step_warnings(model) == []


def test_steps_within_the_accurate_range_are_not_warned(rolling):
    state, automatic = rolling
    for settings in ({}, {"dt": automatic}, {"dt": 1.2 * automatic}, {"safety": 0.6}):
        model = _model(state, **settings)
        model.advance(model.time + 0.2e-3, omega=500.0, F_y=3000.0)
        assert _step_warnings(model) == [], settings


def test_a_safety_factor_beyond_the_accurate_range_is_warned(rolling):
    state, _ = rolling
    model = _model(state, safety=0.8)
    model.advance(model.time + 0.2e-3, omega=500.0, F_y=3000.0)
    (warning,) = _step_warnings(model)
    assert "safety factor above 0.5" in warning
