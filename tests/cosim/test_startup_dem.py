"""The start-up runs with DEM bearings in the closed thermal loop (runs/startup_dem.toml: the spring-preloaded
B7214C X pair of runs/closed_loop_spring.toml at the DEM fidelity with the thermal spindle, 0 -> 10 000 rpm
in 2 s), short variants of 0.2 s and less; the 10 s run and its comparison with quasi-static bearings are
benchmarks/dem_closed_loop.py."""

import numpy as np
import pytest

from spindle import cli
from spindle.cosim.runfile import load_run
from tests.conftest import _fmu, _thermal_fmu
from tests.cosim.test_master import GridMaster, replay

STARTUP_DEM = cli.RUNS / "startup_dem.toml"
RAMP_RATE = 1047.1975511965977 / 2.0  # rad/s^2: 10 000 rpm in 2 s


@pytest.fixture(scope="module")
def startup_fmus():
    return _fmu("BearingDEM", "dem.toml"), _thermal_fmu("SpindleThermal")


def test_short_startup_runs_from_rest_and_writes_csv_and_png(startup_fmus, tmp_path, capsys):
    """`spindle run runs/startup_dem.toml` shortened to 0.2 s exits 0 with CSV + PNG. From rest the balls
    settle under the 800 N preload; the speed follows the ramp (the bearings get its value at the end of
    each 10 ms step and move their speed to it over the step), the friction torque and the heat rise with
    it, and the heat warms the inner rings of the spindle."""
    code = cli.main(["run", str(STARTUP_DEM), "--set", "run.stop=0.2", "--out", str(tmp_path)])
    assert code == cli.EXIT_OK, capsys.readouterr().err
    assert (tmp_path / "startup_dem.png").stat().st_size > 0
    rows = np.genfromtxt(tmp_path / "startup_dem.csv", delimiter=",", skip_header=1)
    header = (tmp_path / "startup_dem.csv").read_text().splitlines()[0].split(",")
    col = {name.split(" [")[0].strip('"'): rows[:, k] for k, name in enumerate(header)}
    t = col["time"]
    assert t[-1] == pytest.approx(0.2) and len(t) == 21
    np.testing.assert_allclose(col["bearing_1.omega"], RAMP_RATE * t, rtol=1e-12, atol=0.0)
    assert col["bearing_1.torque"][-1] > 0.1  # N.m
    assert np.all(np.diff(col["bearing_1.P_loss"][3:]) > 0.0)  # heat grows with the speed
    assert col["spindle.T_inner_ring_1"][-1] > col["spindle.T_inner_ring_1"][0]
    assert 0.2 < col["bearing_1.alpha_outer"][-1] < 0.35  # rad: about the 15 deg nominal angle of the B7214C


@pytest.mark.parametrize("algorithm", ["gauss_seidel", "jacobi"])
def test_rollback_with_dem_bearings_in_the_loop_equals_a_plain_run_on_the_accepted_grid(algorithm, startup_fmus):
    """Step rejection and rollback with two DEM instances and the thermal spindle during the ramp: a step
    in which the inner ring 1 warms by more than 50 uK (from 40 ms on: the heat grows with the
    speed) is rejected, every FMU state restored and the
    step redone in halves. The run equals a plain run (no rollback) stepping the accepted sub-steps, bit for
    bit, in either algorithm: a rejected attempt leaves no trace in the DEM, thermal or master state, and the
    halves get the scheduled speed at their own start."""
    overrides = {"run.stop": 0.06, "run.algorithm": algorithm}
    spec = load_run(
        STARTUP_DEM,
        {**overrides, "run.rollback": True, "run.max_change": {"spindle.T_inner_ring_1": 5e-5}, "run.max_halvings": 3},
    )
    with GridMaster(spec) as master:
        result = master.run()
        grid = master.accepted_grid()
    assert result.status == "ok" and result.rejected_steps > 0
    assert min(h for _, h in grid) < spec.step and max(h for _, h in grid) == spec.step  # some halved, some not
    _, every = replay(load_run(STARTUP_DEM, overrides), grid)
    # the communication points among the sub-step ends (H = 10 ms is not a binary fraction: tolerant match)
    ends = [0] + [
        k + 1 for k, (t, h) in enumerate(grid) if abs((t + h) / spec.step - round((t + h) / spec.step)) < 1e-6
    ]
    assert len(ends) == spec.n_steps + 1
    for name in spec.record:
        assert np.array_equal(result.columns[name], every[name][ends]), name
