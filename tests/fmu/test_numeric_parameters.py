"""Numeric parameters for the bearing, lubricant, race control and network, and configured FMUs.

- A generic FMU with bearing_from_file (lubricant_from_file) false and the numeric parameters set to the
  B7214C's (the VG68 oil's) file values gives the same outputs, bit for bit, as the same FMU given the file by
  name, whatever the String then says (the switch decides): Bearing.fmu (quasi-static) and a short
  BearingDEM.fmu run; race_control_mode against the String race_control, lubrication_mode against the String
  lubrication; SpindleThermal.fmu with the network's
  main dimensions of another bearing against a network file naming that bearing.
- A configured FMU (`spindle build --config configs/rabreau_rig.toml`) run with no parameter set gives the
  outputs of the generic FMU given the configuration's Strings, and so does it with the switches false.
- Bad numeric values are refused at initialisation (fmi2Error) with a message naming the parameter, its value
  and what is allowed.
The configured FMUs' modelDescription and reference files: tests/fmu/test_model_description.py.
"""

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.fmi1 import FMICallException

from bearing_fmu.models.file_parameters import bearing_values, lubricant_values
from bearing_fmu.params import load_bearing
from spindle.thermal.declarations import dimension_rows
from spindle.thermal.model import CATALOGUE as NETWORKS
from spindle.thermal.model import load_spindle
from tests.conftest import _fmu
from tests.fmu.fuzz import Host

OMEGA = 1047.1975511965977  # rad/s, 10 000 rpm
QS_INPUTS = {"omega": OMEGA, "F_z": 800.0, "F_x": 300.0, "T_oil": 323.15}
DEM_INPUTS = {"omega": 300.0, "F_z": 800.0, "F_x": 200.0, "T_oil": 323.15}
B7214C = {"bearing_from_file": False, **bearing_values("B7214C")}
VG68 = {"lubricant_from_file": False, **lubricant_values("iso_vg68_mineral")}


@pytest.fixture(scope="module")
def dem_fmu():
    return _fmu("BearingDEM", "dem.toml")


def run(path, start_values, stop, step):
    """The outputs of an fmpy run from t = 0 with these start values (parameters and held inputs)."""
    return simulate_fmu(str(path), stop_time=stop, output_interval=step, start_values=start_values)


def assert_same_outputs(a, b):
    assert a.dtype.names == b.dtype.names
    different = [name for name in a.dtype.names if not np.array_equal(a[name], b[name])]
    assert different == []


def test_numeric_b7214c_and_vg68_equal_their_files_in_the_quasi_static_fmu(bearing_fmu):
    by_file = run(bearing_fmu, {"bearing": "B7214C", "lubricant": "iso_vg68_mineral", **QS_INPUTS}, 0.3, 0.1)
    # the Strings name another bearing and oil: with the switches false they are not used
    numeric = run(
        bearing_fmu, {"bearing": "6208", "lubricant": "guessasma_oil", **B7214C, **VG68, **QS_INPUTS}, 0.3, 0.1
    )
    assert_same_outputs(by_file, numeric)
    assert by_file["n_loaded"][-1] == 17 and by_file["torque"][-1] > 0.0  # the B7214C's 17 balls, running


def test_numeric_bearing_changes_the_result_when_it_differs_from_the_file(bearing_fmu):
    """The numeric values are used: a larger clearance gives another contact angle than the file's."""
    by_file = run(bearing_fmu, QS_INPUTS, 0.1, 0.1)
    wider = run(bearing_fmu, {**B7214C, "bearing_data.Pd": 80e-6, "bearing_data.alpha0": 0.3184, **QS_INPUTS}, 0.1, 0.1)
    assert wider["alpha_inner"][-1] != by_file["alpha_inner"][-1]


@pytest.mark.parametrize(
    ("string", "value", "decoy", "code", "other_code", "output"),
    [
        ("race_control", "hybrid", "inner", 2, 0, "omega_ball_cage"),
        ("lubrication", "oil_air", "grease", 3, 0, "torque"),
    ],
)
def test_mode_integer_equals_its_string(bearing_fmu, string, value, decoy, code, other_code, output):
    """race_control_mode, lubrication_mode: the Integer wins over the String (set to another choice) and gives
    the outputs of the String naming its choice; another code changes the result."""
    by_string = run(bearing_fmu, {string: value, **QS_INPUTS}, 0.2, 0.1)
    by_number = run(bearing_fmu, {string: decoy, f"{string}_mode": code, **QS_INPUTS}, 0.2, 0.1)
    assert_same_outputs(by_string, by_number)
    other = run(bearing_fmu, {f"{string}_mode": other_code, **QS_INPUTS}, 0.2, 0.1)
    assert other[output][-1] != by_number[output][-1]


def test_numeric_b7214c_and_vg68_equal_their_files_in_the_dem_fmu(dem_fmu):
    """BearingDEM.fmu's defaults are the 6208 and the Guessasma oil: the numeric values set are the B7214C's."""
    step = 0.5e-3
    by_file = run(dem_fmu, {"bearing": "B7214C", "lubricant": "iso_vg68_mineral", **DEM_INPUTS}, 4 * step, step)
    numeric = run(dem_fmu, {**B7214C, **VG68, **DEM_INPUTS}, 4 * step, step)
    assert_same_outputs(by_file, numeric)
    assert by_file["n_loaded"][-1] > 9  # not the default 6208 (9 balls)


def test_network_dimensions_of_another_bearing_equal_a_network_file_naming_it(spindle_thermal_fmu, tmp_path):
    """The default network with both bearings' main dimensions set to the 6306's equals a network file whose
    [[bearing]] entries name the 6306 (the nodes and links stay the file's)."""
    text = (NETWORKS / "b7214c_x_pair.toml").read_text()
    assert text.count('bearing = "B7214C"') == 2
    network = tmp_path / "x_pair_6306.toml"
    network.write_text(text.replace('bearing = "B7214C"', 'bearing = "6306"'))
    b = load_bearing("6306")
    ring = {"D": b.D, "d_m": b.dm, "Pd": b.Pd, "bore": b.bore, "E_ring": b.ring.E, "nu_ring": b.ring.nu}
    ring["rho_ring"] = b.ring.rho
    values = {f"bearing_{k}.{name}": value for k in (1, 2) for name, value in ring.items()}
    inputs = {"omega": OMEGA, "Q_inner_ring_1": 300.0, "Q_outer_ring_1": 200.0, "Q_inner_ring_2": 250.0}
    by_file = run(spindle_thermal_fmu, {"spindle": str(network), **inputs}, 600.0, 60.0)
    numeric = run(spindle_thermal_fmu, {"network_from_file": False, **values, **inputs}, 600.0, 60.0)
    assert_same_outputs(by_file, numeric)
    default = run(spindle_thermal_fmu, inputs, 600.0, 60.0)
    assert default["dPd_thermal_1"][-1] != numeric["dPd_thermal_1"][-1]  # the 6306's rings, not the B7214C's


def test_network_dimensions_start_at_the_network_files_values(spindle_thermal_fmu):
    inputs = {"omega": OMEGA, "Q_inner_ring_1": 300.0, "Q_outer_ring_2": 200.0}
    values = {name: value for name, *_, value in dimension_rows(load_spindle("b7214c_x_pair"))}
    by_file = run(spindle_thermal_fmu, inputs, 300.0, 60.0)
    numeric = run(spindle_thermal_fmu, {"network_from_file": False, **values, **inputs}, 300.0, 60.0)
    assert_same_outputs(by_file, numeric)


@pytest.mark.parametrize("switches", [{}, {"bearing_from_file": False, "lubricant_from_file": False}])
def test_configured_dem_fmu_without_parameters_runs_the_configured_bearing(configured_fmus, dem_fmu, switches):
    step = 0.5e-3
    generic = run(dem_fmu, {"bearing": "B7214C", "lubricant": "iso_vg68_mineral", **DEM_INPUTS}, 4 * step, step)
    configured = run(configured_fmus["BearingDEM_B7214C"], {**switches, **DEM_INPUTS}, 4 * step, step)
    assert_same_outputs(generic, configured)


@pytest.mark.parametrize("switches", [{}, {"bearing_from_file": False, "lubricant_from_file": False}])
def test_configured_quasi_static_fmu_without_parameters_runs_the_configured_bearing(
    configured_fmus, bearing_fmu, switches
):
    strings = {"bearing": "B7214C", "lubricant": "iso_vg68_mineral", "race_control": "outer"}
    generic = run(bearing_fmu, {**strings, **QS_INPUTS}, 0.2, 0.1)
    configured = run(configured_fmus["Bearing_B7214C"], {**switches, **QS_INPUTS}, 0.2, 0.1)
    assert_same_outputs(generic, configured)


def test_configured_thermal_fmu_without_parameters_runs_the_configured_network(configured_fmus, spindle_thermal_fmu):
    inputs = {"omega": OMEGA, "Q_inner_ring_1": 300.0, "Q_outer_ring_1": 200.0}
    generic = run(spindle_thermal_fmu, {"spindle": "b7214c_x_pair", **inputs}, 300.0, 60.0)
    configured = run(configured_fmus["SpindleThermal_B7214C"], {"network_from_file": False, **inputs}, 300.0, 60.0)
    assert_same_outputs(generic, configured)


def refusal(path, parameters):
    """(status of fmi2ExitInitializationMode, error messages) with these parameters set."""
    host = Host(str(path))
    fmu = host.instance()
    for name, value in parameters.items():
        var = next(v for v in host.md.modelVariables if v.name == name)
        {"Real": fmu.setReal, "Integer": fmu.setInteger, "Boolean": fmu.setBoolean}[var.type](
            [var.valueReference], [value]
        )
    try:
        fmu.exitInitializationMode()
        status = 0
    except FMICallException as exc:
        status = exc.status
    fmu.freeInstance()
    return status, [text for level, text in host.messages if level >= 3]


@pytest.mark.parametrize(
    "fixture,parameters,message",
    [
        (
            "bearing_fmu",
            {"bearing_data.nu_ball": 0.7},
            "bearing_data.nu_ball = 0.7 is outside the allowed range [0, 0.5]",
        ),
        (
            "bearing_fmu",
            {"bearing_from_file": False, "bearing_data.d_m": 0.01},
            "bearing_data.d_m = 0.01 m must exceed the ball diameter bearing_data.D = 0.015875 m",
        ),
        (
            "bearing_fmu",
            {"bearing_from_file": False, "bearing_data.D": 0.0},
            "bearing_data.D = 0.0 m is outside the allowed range [0.0001, 1] m",
        ),
        (
            "bearing_fmu",
            {"bearing_from_file": False, "bearing_data.Z": 40},
            "bearing_data.Z = 40 balls of bearing_data.D = 0.015875 m do not fit on the pitch circle",
        ),
        (
            "bearing_fmu",
            {"bearing_from_file": False, "bearing_data.Pd": 1e-4},
            "bearing_data.alpha0 = 0.2618 rad (15.000 deg) and bearing_data.Pd = 0.0001 m",
        ),
        ("bearing_fmu", {"race_control_mode": 4}, "race_control_mode = 4 is outside the allowed range [-1, 3]"),
        ("bearing_fmu", {"lubrication_mode": 5}, "lubrication_mode = 5 is outside the allowed range [-1, 4]"),
        (
            "bearing_fmu",
            {"lubricant_from_file": False, "lubricant_data.nu_1": 0.0},
            "lubricant_data.nu_1 = 0.0 m^2/s is outside the allowed range [2e-06, 1.0]",
        ),
        (
            "dem_fmu",
            {"lubricant_from_file": False, "lubricant_data.viscosity_model": 1},
            "lubricant_data.nu_1 = 0.0 m^2/s is outside the allowed range [2e-06, 1.0]",
        ),
        (
            "dem_fmu",
            {"bearing_from_file": False, "bearing_data.Ra_outer": 0.0},
            "bearing_data.Ra_outer = 0.0 m and bearing_data.Ra_ball = 0.0 m give the outer contacts no roughness",
        ),
        (
            "dem_fmu",
            {"bearing_from_file": False, "bearing_data.Z": 10},
            "bearing_data.cage_ball_radius = 0.00419 m and bearing_data.Z = 10 overlap",
        ),
        (
            "bearing_fmu",
            {"bearing_from_file": False, "bearing_data.bore": 0.1, "bearing_data.outer_diameter": 0.09},
            "bearing_data.bore = 0.1 m leaves the inner ring no material under its groove: allowed below",
        ),
        (
            "spindle_thermal_fmu",
            {"network_from_file": False, "bearing_1.bore": 0.09},
            "bearing_1.bore = 0.09 m leaves the inner ring no material under its groove: allowed below",
        ),
        (
            "spindle_thermal_fmu",
            {"bearing_1.E_ring": 1e6},
            "bearing_1.E_ring = 1000000.0 Pa is outside the allowed range [1e+10, 1e+12] Pa",
        ),
        (
            "spindle_thermal_fmu",
            {"network_from_file": False, "bearing_1.Pd": 0.01},
            "bearing_1.Pd = 0.01 m is outside the allowed range [-0.0007938, 0.0007938] m",
        ),
        (
            "spindle_thermal_fmu",
            {"axial.spacing": 11.0},
            "axial.spacing = 11.0 m is outside the allowed range [0.001, 10] m",
        ),
    ],
)
def test_bad_numeric_values_are_refused_naming_the_parameter(request, fixture, parameters, message):
    status, errors = refusal(request.getfixturevalue(fixture), parameters)
    assert status == 3  # fmi2Error from fmi2ExitInitializationMode
    assert any(message in text for text in errors), errors


def refusal_messages(path, parameters, inputs, step):
    """The FMU's names and the error messages of a run: `parameters` set in initialisation mode, then, if
    fmi2ExitInitializationMode accepts them, `inputs` set and one fmi2DoStep of `step` (s)."""
    host = Host(str(path))
    fmu = host.instance()
    by_name = {v.name: v for v in host.md.modelVariables}
    for name, value in parameters.items():
        var = by_name[name]
        {"Real": fmu.setReal, "Integer": fmu.setInteger, "Boolean": fmu.setBoolean}[var.type](
            [var.valueReference], [value]
        )
    if host.call(fmu.exitInitializationMode) == 0:
        fmu.setReal([by_name[name].valueReference for name in inputs], list(inputs.values()))
        host.call(fmu.doStep, 0.0, step)
    fmu.freeInstance()
    return set(by_name), [text for level, text in host.messages if level >= 2]


@pytest.mark.parametrize(
    "fixture,parameters,inputs,step,message",
    [
        (  # the Walther law's order of its two points
            "bearing_fmu",
            {"lubricant_from_file": False, "lubricant_data.T_1": 400.0},
            {},
            0.1,
            "lubricant_data.T_1 = 400.0 K, lubricant_data.T_2 = 373.15 K",
        ),
        (  # half a temperature range
            "analytic_fmu",
            {"lubricant_from_file": False, "lubricant_data.T_low": 350.0},
            {},
            0.1,
            "lubricant_data.T_low = 350.0 K and lubricant_data.T_high = 0.0 (not given) are not allowed",
        ),
        (  # balls that do not fit on the pitch circle
            "dem_fmu",
            {"bearing_from_file": False, "bearing_data.Z": 23},
            {},
            1e-4,
            "bearing_data.Z = 23 balls of bearing_data.D = 0.0126 m do not fit on the pitch circle of "
            "bearing_data.d_m = 0.0606 m: allowed at most 15 balls",
        ),
        (  # a bearing the analytic fidelity does not model
            "analytic_fmu",
            {"bearing_from_file": False, "bearing_data.kind": 1},
            {},
            0.1,
            "bearing_data.kind = 1 is outside the allowed range [0, 0] (the analytic fidelity models radially loaded "
            "deep-groove bearings",
        ),
        (  # a DEM step inside the declared range [0, 1e-5] s but too small to count its steps
            "dem_fmu",
            {"dt": 1e-300},
            {},
            1e-4,
            "dt = 1e-300 s is outside the allowed range [1e-09, 1e-05] s",
        ),
        (  # a ring growth refused during a step: the rings' parameters that made it
            "spindle_thermal_fmu",
            {"network_from_file": False, "bearing_1.d_m": 1.0},
            {"omega": OMEGA, "Q_inner_ring_1": 300.0},
            60.0,
            "of the rings of bearing_1.D = 0.015875 m, bearing_1.d_m = 1.0 m, bearing_1.bore = 0.07 m",
        ),
    ],
)
def test_a_refusal_names_the_fmu_variables_that_made_it(request, fixture, parameters, inputs, step, message):
    """A parameter the model's own checks refuse (a file reader's check on the numeric values, the fidelity's,
    the step count, a step's result): every error names a variable of the FMU with its value ("name = value"),
    the parameter set among them; none names only a file key or a short name."""
    names, errors = refusal_messages(request.getfixturevalue(fixture), parameters, inputs, step)
    assert any(message in text for text in errors), errors
    sequence = "is not allowed in state"  # the call-sequence refusals that follow a failed initialisation
    for text in (e for e in errors if sequence not in e):
        assert any(f"{name} = " in text for name in names), text
