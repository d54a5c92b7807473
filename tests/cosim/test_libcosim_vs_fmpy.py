"""The closed loop under two independent masters (the cross-check of docs/architecture.md, master): the spring
closed loop of runs/closed_loop_spring.toml (bearing_1, bearing_2, spindle; speed ramp from rest as
input schedules), Jacobi, H = 1 s, 120 s,
under spindle.cosim.libcosim_master.run_libcosim (libcosim 0.11.2's fixed-step algorithm) and under
spindle.cosim.master (algorithm 'jacobi') agrees to 1e-6 relative on temperatures, torques and clearance
changes.

Why they can agree exactly: both masters run the same FMU code in this interpreter, so the results
differ only if the masters hand different values to the FMUs or call them in a different order.
spindle/cosim/libcosim_master.py documents libcosim's initialisation (N rounds of set/read in
initialisation mode, connected inputs hold the sources' initialisation-mode outputs at exit, then
the outputs read after exit are transferred before step 1). Our pythonfmu FMUs compute their outputs
only at instantiation, at exitInitializationMode and in doStep, so the initialisation-mode outputs
are the start values, which is exactly what spindle.cosim.master's Jacobi initialisation gives every
connected input; the steps are the same Jacobi exchange. So the issue's 1e-6 is met with margin
(measured: bit for bit), and the test also asserts the exact equality: any difference would reveal
a transport or ordering difference between the masters.
"""

import numpy as np
import pytest

pytest.importorskip("libcosimpy", reason="libcosimpy not installed (optional extra 'cosim')")

from spindle.cosim.libcosim_master import run_libcosim  # noqa: E402
from spindle.cosim.master import run  # noqa: E402
from spindle.cosim.runfile import load_run  # noqa: E402
from tests.conftest import ROOT  # noqa: E402
from tests.cosim.test_closed_loop import SPRING, TEMPERATURES  # noqa: E402

COMPARED = [
    *TEMPERATURES,
    "bearing_1.torque",
    "bearing_2.torque",
    "spindle.dPd_thermal_1",
    "spindle.dPd_thermal_2",
]


def relative_difference(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = np.maximum(np.abs(a), np.abs(b))
    return np.where(a == b, 0.0, np.abs(a - b) / np.where(scale > 0.0, scale, 1.0))


def test_closed_loop_libcosim_equals_fmpy_master(closed_loop_fmus):
    # the bearings flooded: the test is of the masters, not of the lubrication method (whose torque need not fall
    # as the oil warms: a thinner oil also relieves its starvation and inlet shear heating)
    flooded = {"bearing_1.lubrication": "flooded", "bearing_2.lubrication": "flooded"}
    spec = load_run(SPRING, {**flooded, "run.algorithm": "jacobi", "run.stop": 120.0})
    assert spec.step == 1.0 and spec.n_steps == 120
    fmpy_result = run(spec)
    system = system_of(spec)
    record = [name for name in fmpy_result.columns if name != "time"]
    assert set(COMPARED) <= set(record)
    libcosim_result = run_libcosim(system, spec.step, spec.stop, record)

    np.testing.assert_array_equal(libcosim_result["time"], fmpy_result.columns["time"])
    worst = {
        name: float(np.max(relative_difference(libcosim_result[name], fmpy_result.columns[name]))) for name in record
    }
    for name in COMPARED:
        assert worst[name] <= 1e-6, (name, worst[name])  # the acceptance
    for name in record:
        np.testing.assert_array_equal(libcosim_result[name], fmpy_result.columns[name], err_msg=name)
    # the loop did something in 120 s: the oil warmed and the torque at full speed (from the step
    # starting at t = 2 s, recorded at t = 3 s) fell with the viscosity
    assert fmpy_result.columns["spindle.T_oil_1"][-1] > fmpy_result.columns["spindle.T_oil_1"][0] + 10.0
    assert fmpy_result.columns["bearing_1.torque"][-1] < fmpy_result.columns["bearing_1.torque"][3]


# -- input schedules and DEM bearings ----------------------------------------------------------------
def system_of(spec):
    """The run of a RunSpec as run_libcosim's system (schedules passed as the run file's Schedule objects)."""
    return {
        "instances": {
            name: {"fmu": inst.fmu, "parameters": inst.parameters, "inputs": inst.inputs, "schedules": inst.schedules}
            for name, inst in spec.instances.items()
        },
        "connections": list(spec.connections),
    }


def assert_masters_agree(spec, record, bit_for_bit=True):
    """fmpy master (Jacobi) and libcosim on the same spec: every recorded column within 1e-9 relative (the
    acceptance). bit_for_bit: also exactly equal, as for FMUs that do not use the communication point's
    value (see the module docstring: same FMU code, same values, same order)."""
    fmpy_result = run(spec)
    libcosim_result = run_libcosim(system_of(spec), spec.step, spec.stop, record)
    # libcosim's n H from integer nanoseconds and the fmpy master's n * H may differ in the last bit
    np.testing.assert_allclose(libcosim_result["time"], fmpy_result.columns["time"], rtol=1e-15, atol=0.0)
    for name in record:
        assert np.max(relative_difference(libcosim_result[name], fmpy_result.columns[name])) <= 1e-9, name
        if bit_for_bit:
            np.testing.assert_array_equal(libcosim_result[name], fmpy_result.columns[name], err_msg=name)
    return fmpy_result


def test_scheduled_input_under_libcosim_is_sampled_at_the_start_of_each_step(clock_fmu, tmp_path):
    """The clock FMU (x += u h) with u(t) = 10 t up to 1 s, H = 0.25 s: libcosim's override manipulator
    gives the FMU u(t_n) for step n, as the fmpy master does: x(2 s) = 0.25 (0 + 2.5 + 5 + 7.5 + 4 x 10)."""
    from spindle.cosim.runfile import parse_run

    doc = {
        "run": {"stop": 2.0, "step": 0.25, "algorithm": "jacobi", "record": ["c.u", "c.x", "c.t_start"]},
        "fmus": {"clock": str(clock_fmu)},
        "instances": {"c": {"fmu": "clock", "schedules": {"u": [[0.0, 0.0], [1.0, 10.0]]}}},
    }
    result = assert_masters_agree(parse_run(doc, tmp_path / "r.toml"), ["c.u", "c.x", "c.t_start"])
    assert result.columns["c.x"][-1] == 13.75


def test_dem_fmu_alone_libcosim_equals_fmpy_master(tmp_path):
    """BearingDEM.fmu alone (6208, 3 kN radial) run up from rest to 300 rad/s in 20 ms at H = 1 ms, then held to
    0.5 s, Jacobi: the same outputs under libcosim and the fmpy master, bit for bit. libcosim counts time in
    integer nanoseconds and hands fmi2DoStep step sizes that differ from 0.001 s in the last bits for some steps
    (the clock FMU summing h over ten 1 ms steps gets 0.01 under libcosim and 0.010000000000000002 under the fmpy
    master); the DEM rounds the communication step to 1 ps before dividing it into its own time steps, so both
    masters' steps are the same (without the rounding the results differed by 2e-13 after 30 ms and by 2e-3 in z
    after 0.5 s: the ball dynamics amplify a last-bit difference)."""
    from spindle.cosim.runfile import parse_run
    from tests.conftest import _fmu

    record = ["dem.omega", "dem.torque", "dem.P_loss", "dem.x", "dem.omega_cage", "dem.Q_inner_ring", "dem.K[1,1]"]
    doc = {
        "run": {"stop": 0.5, "step": 1e-3, "algorithm": "jacobi", "record": record},
        "fmus": {"dem": str(_fmu("BearingDEM", "dem.toml"))},
        "instances": {
            "dem": {"fmu": "dem", "inputs": {"F_y": 3000.0}, "schedules": {"omega": [[0.0, 0.0], [0.02, 300.0]]}}
        },
    }
    result = assert_masters_agree(parse_run(doc, tmp_path / "r.toml"), record)
    assert result.columns["dem.omega_cage"][-1] > 100.0  # rad/s: the cage follows the ramp


def test_dem_startup_in_the_loop_libcosim_equals_fmpy_master():
    """runs/startup_dem.toml (two DEM bearings and the thermal spindle, speed ramp) shortened to 0.5 s,
    Jacobi, H = 10 ms: the same results under libcosim and the fmpy master, bit for bit (the DEM's communication
    step on a 1 ps grid, see the test above)."""
    from tests.conftest import _fmu, _thermal_fmu

    _fmu("BearingDEM", "dem.toml"), _thermal_fmu("SpindleThermal")
    spec = load_run(ROOT / "runs" / "startup_dem.toml", {"run.algorithm": "jacobi", "run.stop": 0.5})
    record = list(dict.fromkeys(list(spec.record) + [source for source, _ in spec.connections]))
    result = assert_masters_agree(spec, record)
    assert result.columns["spindle.T_inner_ring_1"][-1] > result.columns["spindle.T_inner_ring_1"][0]
