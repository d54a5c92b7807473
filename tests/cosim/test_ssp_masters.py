"""The exported SSP packages in other co-simulation masters: libcosim, ecos (ecospy) and OMSimulator run
`spindle export-ssp` of runs/closed_loop_spring.toml, runs/startup_dem.toml and runs/warmup_modes.toml (the loop with
the shaft FMU taking both bearings' 25 K[i,j]) unchanged, and give what `spindle run` gives with the Jacobi exchange
(README, "The closed loop in other co-simulation masters").

The run files are exported at constant speed (10 000 rpm: SSP 1.0 carries no schedule), for their whole
length (3600 s at 1 s; 10 s at 10 ms; 3600 s at 1 s). The bearing FMUs get the B7214C and iso_vg68_mineral by numeric
parameters (BearingDEM.fmu starts at the 6208 and another oil) or by their start values (Bearing.fmu starts
at the B7214C pair's set): no String value is in the packages.

Expectation: the same numbers. Every master steps the same FMU code on the same Python, numpy and numba, and
each of them exchanges Jacobi-style with the initialisation outputs handed to the connected inputs, as
`spindle run --set run.algorithm=jacobi` does. The acceptance is 1e-9 relative for closed_loop_spring and
warmup_modes; for
startup_dem it is the DEM's reproducibility, and that is exact: the DEM runs of the project's master and of
each of the three masters (other processes, other hosts) give the same bits at every one of its 1000 steps,
so the test asserts equality. ecos's and OMSimulator's clocks add the step at each step (10 s after 1000 steps
of 0.01 s is 1.7e-13 s off the grid k h), which the FMUs' 1 ps communication grid absorbs; OMSimulator is
given the stop time its clock reaches (omsimulator_stop_time).

Measured here (2-core machine): libcosim, ecos and OMSimulator equal `spindle run` in every recorded variable
at every step for closed_loop_spring and startup_dem (largest relative difference 0), libcosim and ecos for
warmup_modes within the asserted 1e-9 (OMSimulator not at hand for it); no error line in ecos's or OMSimulator's log, no
algebraic loop reported by OMSimulator; the six tests take about 2 minutes with the environment made.

Marked `ssp_masters` (tests/_markers.py): the first run makes a virtual environment under /tmp with pip
(ecospy and the TBB runtime it needs, numpy, numba and scipy at this run's versions; a minute with pip's
cache), which also is the Python OMSimulator's FMUs start (BEARING_FMU_PYTHON); `make test-ssp-masters`,
left out of `make test`. OMSimulator is taken from the environment variable OMSIMULATOR or the PATH (its
PyPI package downloads the binary from the OpenModelica build server at install time; README gives the
commands that build it from source); without it its tests are skipped, saying so.
"""

import json
import os
import shutil
import subprocess
from importlib.metadata import version
from pathlib import Path

import numpy as np
import pytest

from spindle.cosim.master import run
from spindle.cosim.runfile import load_run
from spindle.cosim.ssp import PARAMETER_SET, export_ssp, run_ssp_in_libcosim
from tests.conftest import ROOT, _fmu, pip_environment

SPEED = 1047.1975511965977  # rad/s: 10 000 rpm
AT_SPEED = {f"{name}.omega": SPEED for name in ("bearing_1", "bearing_2", "spindle")}
AT_SPEED_SHAFT = {**AT_SPEED, "shaft.omega": SPEED}
RUNS = ("closed_loop_spring", "startup_dem", "warmup_modes")
TOLERANCE = {"closed_loop_spring": 1e-9, "startup_dem": 0.0, "warmup_modes": 1e-9}  # relative; startup_dem: the DEM's
# reproducibility
PINS = ("ecospy==0.7.2", "tbb==2023.2.0", *(f"{p}=={version(p)}" for p in ("numpy", "numba", "scipy")))

ECOS_CHILD = r"""
import ctypes, glob, json, os, sys
# libecosc.so needs libtbb.so.12, which the tbb package puts in the environment's lib/ (not on the loader's path)
for lib in glob.glob(os.path.join(sys.prefix, "lib", "libtbb.so.12")):
    ctypes.CDLL(lib, mode=ctypes.RTLD_GLOBAL)
from ecospy import EcosLib, EcosSimulation
EcosLib.set_log_level("debug")
path, step, stop, parameter_set, names = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5:]
sim = EcosSimulation(ssp_path=path, step_size=step)
if not sim.init(parameter_set=parameter_set):
    sys.exit("init failed: " + EcosLib.get_last_error())
ids = [name.replace(".", "::", 1) for name in names]  # ecos names a variable instance::variable
def value(i):
    try:
        return sim.get_real(i)
    except Exception:  # an Integer output (the shaft's whirl)
        return float(sim.get_integer(i))
rows = [[sim.get_time()] + [value(i) for i in ids]]
for _ in range(round(stop / step)):
    sim.step(1)
    rows.append([sim.get_time()] + [value(i) for i in ids])
sim.terminate()
print("RESULT " + json.dumps(rows), flush=True)
"""


@pytest.fixture(scope="module")
def ssp_python():
    """python of a virtual environment with ecospy (and the TBB runtime it loads), numpy, numba and scipy (this
    run's versions), kept under /tmp between runs (a marker file says it is complete)."""
    return pip_environment("ssp-masters", PINS)


@pytest.fixture(scope="module")
def exported(closed_loop_fmus, spindle_shaft_fmu, tmp_path_factory):
    """run name -> (RunSpec, package, the project's Jacobi master's columns) of the run files at constant speed."""
    _fmu("BearingDEM", "dem.toml")
    out = {}
    for name in RUNS:
        speed = AT_SPEED_SHAFT if name == "warmup_modes" else AT_SPEED
        spec = load_run(ROOT / "runs" / f"{name}.toml", {**speed, "run.algorithm": "jacobi"})
        package = export_ssp(spec, tmp_path_factory.mktemp(name) / f"{name}.ssp")
        result = run(spec)
        assert result.status == "ok", result.message
        out[name] = spec, package, result.columns
    return out


def _host_env(cache):
    """The environment of a master's process: no PYTHONPATH (the FMUs run on the code they carry), a fresh
    numba cache."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NUMBA_CACHE_DIR")}
    env["BEARING_FMU_CACHE"] = str(cache)
    return env


def _largest_difference(rows, names, columns):
    """name -> largest relative difference over the steps between a master's rows (time first) and `columns`."""
    out = {}
    for k, name in enumerate(names, start=1):
        a, b = rows[:, k], np.asarray(columns[name])
        scale = np.maximum(np.abs(a), np.abs(b))
        out[name] = float(np.max(np.where(scale > 0, np.abs(a - b) / np.where(scale > 0, scale, 1.0), 0.0)))
    return out


def _error_lines(log):
    """The error lines of a master's log: ecos's `[error]`/`[critical]`, OMSimulator's `error:`, an exception."""
    marks = ("[error]", "[critical]", "error:", "exception")
    return [line for line in log.splitlines() if any(mark in line.lower() for mark in marks)]


def omsimulator_stop_time(spec):
    """The stop time to give OMSimulator for the run's steps: its clock adds the step at each step (1000 steps of
    0.01 s end at 9.99999999999983 s), so a stop time of 10 s asks for a last step of 1.7e-13 s, which the FMUs
    refuse (their communication steps are on a 1 ps grid)."""
    time = spec.start
    for _ in range(round((spec.stop - spec.start) / spec.step)):
        time += spec.step
    return time


@pytest.mark.parametrize("name", RUNS)
def test_ecos_runs_the_package_as_spindle_run(name, exported, ssp_python, tmp_path):
    """ecos loads the package, applies its one parameter set to all its components and steps it to the stop
    time: every recorded variable equals `spindle run`'s (Jacobi) at every step; no error in its log."""
    spec, package, columns = exported[name]
    names = [n for n in columns if n != "time"]
    proc = subprocess.run(
        [str(ssp_python), "-c", ECOS_CHILD, str(package), repr(spec.step), repr(spec.stop), PARAMETER_SET, *names],
        capture_output=True,
        text=True,
        env=_host_env(tmp_path / "cache"),
        cwd=tmp_path,
        timeout=1800,
    )
    log = "\n".join(line for line in (proc.stdout + proc.stderr).splitlines() if not line.startswith("RESULT "))
    assert proc.returncode == 0, log[-3000:]
    assert f"Parameterset '{PARAMETER_SET}' applied to {len(spec.instances)} instances" in log
    assert _error_lines(log) == []
    rows = np.array(json.loads(next(line for line in proc.stdout.splitlines() if line.startswith("RESULT "))[7:]))
    assert rows.shape == (len(columns["time"]), len(names) + 1)
    np.testing.assert_allclose(rows[:, 0], columns["time"], rtol=1e-12, atol=0.0)
    worst = _largest_difference(rows, names, columns)
    assert max(worst.values()) <= TOLERANCE[name], {k: v for k, v in worst.items() if v > TOLERANCE[name]}
    # the loop did something: the inner ring warmed
    assert columns["spindle.T_inner_ring_1"][-1] > columns["spindle.T_inner_ring_1"][0] + 5.0


@pytest.mark.parametrize("name", RUNS)
def test_libcosim_runs_the_package_as_spindle_run(name, exported):
    """libcosim (libcosimpy, in this process) loads the package with CosimExecution.from_ssp_file and steps it
    to the stop time: every recorded variable equals `spindle run`'s (Jacobi) at every step."""
    pytest.importorskip("libcosimpy", reason="libcosimpy not installed (optional extra 'cosim')")
    spec, package, columns = exported[name]
    names = [n for n in columns if n != "time"]
    out = run_ssp_in_libcosim(package, spec.step, spec.stop, names)
    rows = np.column_stack([out["time"], *(out[n] for n in names)])
    np.testing.assert_allclose(rows[:, 0], columns["time"], rtol=1e-12, atol=0.0)
    worst = _largest_difference(rows, names, columns)
    assert max(worst.values()) <= TOLERANCE[name], {k: v for k, v in worst.items() if v > TOLERANCE[name]}


def _omsimulator_rows(path, prefix, names):
    """Rows (time, then `names`) of an OMSimulator result file (MATLAB v4, the Modelica result layout: names
    and dataInfo per variable, constants in data_1, trajectories in data_2 with time first), one row per
    communication point: OMSimulator writes a point twice (before and after its events), the last is kept."""
    from scipy.io import loadmat

    mat = loadmat(path, chars_as_strings=False)
    listed = ["".join(mat["name"][:, j]).rstrip() for j in range(mat["name"].shape[1])]
    info, data = mat["dataInfo"], {1: mat["data_1"], 2: mat["data_2"]}
    columns = []
    for name in ["time", *(prefix + n for n in names)]:
        j = listed.index(name)
        matrix, index = int(info[0, j]) or 2, int(info[1, j])
        values = np.sign(index) * data[matrix][abs(index) - 1]
        columns.append(np.broadcast_to(values, data[2][0].shape) if matrix == 1 else values)
    table = np.column_stack(columns)
    last = np.append(np.diff(table[:, 0]) > 0, True)
    return table[last]


def _omsimulator():
    """The OMSimulator command-line program: $OMSIMULATOR, else OMSimulator on the PATH, else None."""
    return os.environ.get("OMSIMULATOR") or shutil.which("OMSimulator")


@pytest.mark.parametrize("name", RUNS)
def test_omsimulator_runs_the_package_as_spindle_run(name, exported, ssp_python, tmp_path):
    """OMSimulator (a native host: the FMUs start the environment's Python, BEARING_FMU_PYTHON) imports the
    package with its fixed-step master at the package's step and runs it to the stop time given on its command
    line: every recorded variable equals `spindle run`'s (Jacobi) at every step; no error line and no algebraic
    loop in its log."""
    program = _omsimulator()
    if program is None:
        pytest.skip("no OMSimulator program ($OMSIMULATOR or the PATH): README gives the commands that build it")
    spec, package, columns = exported[name]
    result = tmp_path / "result.mat"  # doubles (its .csv writes 12 digits)
    env = {**_host_env(tmp_path / "cache"), "BEARING_FMU_PYTHON": str(ssp_python)}
    proc = subprocess.run(
        [
            program,
            f"--stopTime={omsimulator_stop_time(spec)!r}",
            f"--resultFile={result}",
            f"--tempDir={tmp_path}",
            str(package),
        ],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        timeout=1800,
    )
    log = proc.stdout + proc.stderr
    assert proc.returncode == 0, log[-3000:]
    assert _error_lines(log) == [] and "warning" not in log and "Alg. loop" not in log, log[-3000:]
    names = [n for n in columns if n != "time"]
    rows = _omsimulator_rows(result, f"{Path(spec.path).stem}.system.", names)  # model: the SSD name
    assert rows.shape == (len(columns["time"]), len(names) + 1)
    np.testing.assert_allclose(rows[:, 0], columns["time"], rtol=1e-12, atol=0.0)
    worst = _largest_difference(rows, names, columns)
    assert max(worst.values()) <= TOLERANCE[name], {k: v for k, v in worst.items() if v > TOLERANCE[name]}
