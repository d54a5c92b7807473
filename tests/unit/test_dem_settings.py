"""The DEM's numeric settings declared once (bearing_fmu.models.dem_settings): each setting of the table is a DemModel
keyword, a BearingDEM parameter with its unit, range and default, read from params/dem_model.toml, checked against
its range and packed where the kernel reads it."""

import math
import tomllib

import numpy as np
import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.declarations import DEM_PARAMETERS
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.dem_settings import DEFAULTS, DEM_SETTINGS, pitch_lever
from bearing_fmu.models.limits import InputError
from bearing_fmu.params import CATALOGUE

FILE = tomllib.loads((CATALOGUE / "dem_model.toml").read_text())
BY_NAME = {setting.name: setting for setting in DEM_SETTINGS}


def file_value(key):
    node = FILE
    for part in key.split("."):
        node = node[part]
    return node


def test_the_table_holds_the_support_and_the_traction_limit():
    assert {"traction_limit", "support_stiffness", "support_damping", "support_mass"} <= set(BY_NAME)


@pytest.mark.parametrize("setting", DEM_SETTINGS, ids=lambda setting: setting.name)
def test_each_setting_is_an_fmu_parameter_with_its_unit_range_and_the_files_default(setting):
    entry = file_value(setting.key)
    assert "source" in entry and entry["unit"] == ("-" if setting.unit == "1" else setting.unit)
    assert DEFAULTS[setting.name] == entry["value"]
    parameters = [v for v in DEM_PARAMETERS if v.name == setting.name]
    assert len(parameters) == 1
    (parameter,) = parameters
    assert (parameter.unit, parameter.start, parameter.min, parameter.max) == (
        setting.unit,
        entry["value"],
        setting.low,
        setting.high,
    )
    assert parameter.description == setting.description


def test_the_defaults_are_the_models_and_a_given_value_reaches_its_slot():
    """Absent or None, a setting takes the file's default; given, its value is what the kernel reads."""
    model = DemModel(support_damping=None)
    assert model.settings == DEFAULTS
    given = {"traction_limit": 0.05, "support_stiffness": 2e8, "support_damping": 250.0, "support_mass": 4.0}
    changed = DemModel(**given)
    assert {name: changed.settings[name] for name in given} == given
    for name, value in given.items():
        if BY_NAME[name].slot:
            assert changed.par[getattr(s, BY_NAME[name].slot)] == value, name
    # the derived ones: the shaft's modal mass moves with the ring, the support spread over the pitch circle
    assert changed.par[s.P_M_RING] == model.par[s.P_M_RING] + 4.0
    lever = pitch_lever(model.bearing.dm)
    assert changed.par[s.P_I_RING] == model.par[s.P_I_RING] + lever * 4.0
    assert changed.par[s.P_KT_SUPPORT] == lever * 2e8 and changed.par[s.P_CT_SUPPORT] == lever * 250.0


@pytest.mark.parametrize("setting", DEM_SETTINGS, ids=lambda setting: setting.name)
@pytest.mark.parametrize("side", ["below", "above", "nan"])
def test_a_setting_outside_its_range_is_refused_naming_it_its_value_unit_and_range(setting, side):
    value = {"below": setting.low - 1.0, "above": setting.high * 2.0 + 1.0, "nan": math.nan}[side]
    unit = "" if setting.unit == "1" else f" {setting.unit}"
    expected = f"{setting.name} = {value}{unit} is outside the allowed range [{setting.low:g}, {setting.high:g}]"
    with pytest.raises(InputError) as refused:
        DemModel(**{setting.name: value})
    assert str(refused.value).startswith(expected)


def test_an_unknown_setting_is_refused_as_an_unknown_keyword():
    with pytest.raises(TypeError, match="support_dampin"):
        DemModel(support_dampin=300.0)


def axial_swing(**settings):
    """Standard deviation (m) of a 6208's axial displacement z over 1-2 ms after a 300 N axial load step at rest,
    sampled every 10 us, and its mean (m)."""
    model = DemModel(**settings)
    z = [model.advance(k * 10e-6, omega=0.0, F_z=300.0)["z"] for k in range(1, 201)]
    late = np.array(z[100:])
    return float(late.std()), float(late.mean())


def test_axial_support_damping_damps_the_rings_axial_oscillation():
    """The ring of a 6208 thrown at its balls by an axial load step swings axially for milliseconds on the contacts'
    hysteretic damping alone (by default the support has no axial damper: a std of about 20 um over 1-2 ms);
    support_axial_damping = 1000 N.s/m on the ring's 0.078 kg settles it within a millisecond (about 0.1 um)."""
    free, _ = axial_swing()
    damped, z_damped = axial_swing(support_axial_damping=1000.0)
    assert free > 5e-6
    assert damped < 0.02 * free
    assert z_damped > 0.0  # pushed along +z, resting on its balls


def test_support_axial_damping_is_an_fmu_parameter_with_its_range():
    (parameter,) = [v for v in DEM_PARAMETERS if v.name == "support_axial_damping"]
    assert (parameter.unit, parameter.start, parameter.min, parameter.max) == ("N.s/m", 0.0, 0.0, 1e6)
    assert DemModel(support_axial_damping=2e3).par[s.P_C_SUPPORT_AXIAL] == 2e3
