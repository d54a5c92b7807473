"""Declared ranges (bearing_fmu_common.variables.Variable min/max) and the checks that use them.

The FMUs write the declared range as FMI min/max (tests/fmu/test_fuzz.py checks the built FMUs); here: the
models refuse what is outside it, narrowed by the limits of the bearing, with a message naming the input,
its value and the allowed range, and accept what is inside.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels.hertz import hertz_contact
from bearing_fmu.kernels.radial_bearing import (
    B_E_RED,
    B_EE_I,
    B_EE_O,
    B_K_I,
    B_K_O,
    B_KK_I,
    B_KK_O,
    B_RX_I,
    B_RX_O,
    B_RY_I,
    B_RY_O,
)
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.declarations import OMEGA, T_OIL
from bearing_fmu.models.limits import P_MAX_ERROR
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu_common.variables import InputError, InputLimits, Variable
from spindle.thermal.model import SpindleThermalModel

SPEED = Variable("omega", "rad/s", "test speed", min=-100.0, max=100.0, limits="test bound")


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, 100.5, -1e30])
def test_check_refuses_nan_inf_and_values_outside_with_name_value_and_range(value):
    with pytest.raises(InputError) as err:
        SPEED.check(value)
    assert str(err.value) == f"omega = {value} rad/s is outside the allowed range [-100, 100] rad/s (test bound)"


def test_check_narrows_to_a_run_time_limit_and_says_why():
    SPEED.check(-100.0)
    SPEED.check(100.0)
    with pytest.raises(
        InputError, match=r"omega = 60.0 rad/s is outside the allowed range \[-50, 50\] rad/s \(d_m n\)"
    ):
        SPEED.check(60.0, -50.0, 50.0, "d_m n")
    with pytest.raises(InputError, match=r"allowed range \[-100, 100\]"):  # never wider than declared
        SPEED.check(150.0, -1e9, 1e9, "wider")


def test_check_choice():
    race = Variable("race_control", "", "t", "string", choices=("outer", "inner"))
    race.check_choice("inner")
    with pytest.raises(InputError, match=r"race_control = '' is not allowed: allowed values 'outer', 'inner'"):
        race.check_choice("")
    name = Variable("bearing", "", "t", "string")
    name.check_choice("6208")
    with pytest.raises(InputError, match="bearing = '' is not allowed"):
        name.check_choice("")


def test_input_limits_name_the_first_bad_input():
    limits = InputLimits((SPEED, T_OIL), {"omega": (-10.0, 10.0, "d_m n")})
    limits.check((10.0, 313.15))
    with pytest.raises(InputError, match=r"omega = 11.0 rad/s .* \[-10, 10\] rad/s \(d_m n\)"):
        limits.check((11.0, math.nan))
    with pytest.raises(InputError, match=r"T_oil = nan K is outside the allowed range \[233.15, 473.15\] K"):
        limits.check((0.0, math.nan))


def test_analytic_load_limit_is_the_material_limit_with_the_load_on_every_ball():
    """Q = load_limit / Z on one ball gives p_max = 6 GPa on the worse contact (Hertz kernel, 1e-9)."""
    model = AnalyticModel("6208")
    brg, Z = model.brg, model.bearing.Z
    Q = model.load_limit / Z
    p = [
        hertz_contact(Q, brg[rx], brg[ry], brg[B_E_RED], brg[k], brg[ee], brg[kk])[3]
        for rx, ry, k, ee, kk in ((B_RX_I, B_RY_I, B_K_I, B_EE_I, B_KK_I), (B_RX_O, B_RY_O, B_K_O, B_EE_O, B_KK_O))
    ]
    assert max(p) == pytest.approx(P_MAX_ERROR, rel=1e-9)
    with pytest.raises(InputError, match=r"F_y = 1e\+30 N is outside the allowed range .*\(the material limit"):
        model.update((500.0, 1e30, 313.15))
    with pytest.raises(InputError, match=r"omega = 200000.0 rad/s is outside the allowed range"):
        model.update((2e5, 3000.0, 313.15))
    assert OMEGA.max == 1e5


def test_quasi_static_refuses_an_empty_race_control_and_defaults_only_for_none():
    with pytest.raises(InputError, match=r"race_control = '' is not allowed"):
        QuasiStaticModel(race_control="")
    assert QuasiStaticModel(race_control=None).race_control == "outer"  # the default scene's


def test_thermal_axial_force_beyond_the_declared_range_is_refused():
    model = SpindleThermalModel(axial_float=True)
    model.initialize(T_ambient=293.15, T_coolant=293.15)
    with pytest.raises(InputError, match=r"F_axial_1 = 1e\+30 N is outside the allowed range \[-1e\+08, 1e\+08\] N"):
        model.advance(1.0, F_axial_1=1e30, K_axial_1=2e8, K_axial_2=2e8)


def test_thermal_axial_float_beyond_a_millimetre_is_refused_and_the_state_kept():
    """In range but absurd together: 1 kN out of balance on 1 N/m of stiffness would float the shaft 500 m."""
    model = SpindleThermalModel(axial_float=True)
    model.initialize(T_ambient=293.15, T_coolant=293.15)
    model.advance(1.0, F_axial_1=1000.0, F_axial_2=1000.0, K_axial_1=2e8, K_axial_2=2e8)
    before = (model.T.copy(), model.s, model.time, model.values.copy())
    with pytest.raises(InputError, match=r"axial float s = 500.0 m, outside the allowed range \[-0.001, 0.001\] m"):
        model.advance(1.0, F_axial_1=0.0, F_axial_2=1000.0, K_axial_1=1.0, K_axial_2=1.0)
    assert np.array_equal(model.T, before[0]) and model.s == before[1] and model.time == before[2]
    assert np.array_equal(model.values, before[3])


@pytest.mark.parametrize("T_initial", [math.nan, -math.inf, -300.0, 1e-300, 149.9, 1000.1])
def test_thermal_initial_temperature_outside_its_range_is_refused(T_initial):
    with pytest.raises(InputError, match=rf"T_initial = {T_initial} K is outside the allowed range \[150, 1000\] K"):
        SpindleThermalModel(T_initial=T_initial)


def test_thermal_initial_temperature_at_its_bounds_is_used():
    for T_initial in (150.0, 1000.0):
        model = SpindleThermalModel(T_initial=T_initial)
        model.initialize(T_ambient=293.15, T_coolant=293.15)
        assert np.all(model.T == T_initial)
