"""The thermal FMUs run in a host that has only fmpy, numpy and numba (README, "Using the FMU";
docs/fmu_runtime.md): no scipy, no bearing_fmu.

A fresh virtual environment under /tmp gets exactly those three packages, at the versions of this test
run (so the FMU's compiled code applies as in the full environment), from pip. Each thermal FMU runs its
reference experiment (heat into every ring at 10 000 rpm, 20 minutes in 60 s steps) there and in this
environment, each in a fresh process; the outputs agree to 1e-12 relative: the same model code runs on
the same numpy and numba in both, so only a different code path (a library present in one host only)
could make them differ, and 1e-12 leaves room for nothing but that. The FMU carries no module of the
bearing model. Without the fix the bare host aborted at instantiation ("Fatal Python error: BLAS wrapper
returned with an error", exit 134: numba's np.dot needs scipy's BLAS).

Marked `bare_host` (tests/_markers.py): setting up the environment takes about a minute with pip's cache
(`make test-bare-host`); the default `make test` leaves it out.
"""

import json
import sys
import zipfile
from importlib.metadata import version

import numpy as np
import pytest

from spindle.all_fmus import reference_inputs
from spindle.thermal.model import SpindleThermalModel
from tests._processes import run_in_host
from tests.conftest import pip_environment

PACKAGES = ("fmpy", "numpy", "numba")
STEP, STOP = 60.0, 1200.0  # s
CHILD = r"""
import json, sys
import numpy as np
from fmpy import simulate_fmu
path, inputs, step, stop = sys.argv[1], json.loads(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
names = list(inputs)
dtype = [("time", float)] + [(n, float) for n in names]
rows = np.array([(0.0, *inputs.values()), (stop, *inputs.values())], dtype=dtype)
result = simulate_fmu(path, stop_time=stop, output_interval=step, input=rows)
try:
    import scipy  # noqa: F401
    has_scipy = True
except ImportError:
    has_scipy = False
try:
    import bearing_fmu  # noqa: F401
    has_bearing_fmu = True
except ImportError:
    has_bearing_fmu = False
print("RESULT " + json.dumps({"names": list(result.dtype.names), "rows": [list(map(float, r)) for r in result],
                               "scipy": has_scipy, "bearing_fmu": has_bearing_fmu}))
"""


@pytest.fixture(scope="module")
def bare_python():
    """python of a virtual environment with only fmpy, numpy and numba (this run's versions), kept under /tmp
    between runs (a marker file says it is complete)."""
    return pip_environment("bare-host", [f"{p}=={version(p)}" for p in PACKAGES])


def _run(python, fmu, inputs, cache):
    return run_in_host(python, ["-c", CHILD, fmu, json.dumps(inputs), STEP, STOP], cache, timeout=600)[0]


@pytest.mark.parametrize(
    ("fixture", "axial_float"), [("spindle_thermal_fmu", False), ("spindle_thermal_fixed_fmu", True)]
)
def test_thermal_fmu_runs_in_a_host_with_only_fmpy_numpy_numba(fixture, axial_float, bare_python, request, tmp_path):
    fmu = request.getfixturevalue(fixture)
    inputs = reference_inputs(SpindleThermalModel(axial_float=axial_float))
    bare = _run(bare_python, fmu, inputs, tmp_path / "bare")
    full = _run(sys.executable, fmu, inputs, tmp_path / "full")
    assert not bare["scipy"] and not bare["bearing_fmu"]  # the bare host really lacks them
    assert full["scipy"]  # and the reference host has scipy
    assert bare["names"] == full["names"]
    a, b = np.array(bare["rows"]), np.array(full["rows"])
    assert a.shape == b.shape == (int(STOP / STEP) + 1, len(full["names"]))
    assert np.ptp(b[:, full["names"].index("T_inner_ring_1")]) > 1.0  # the rings did heat up (K)
    scale = np.maximum(np.abs(b).max(axis=0), 1e-300)
    assert np.all(np.abs(a - b) <= 1e-12 * scale), np.abs(a - b).max(axis=0) / scale


@pytest.mark.parametrize("fixture", ["spindle_thermal_fmu", "spindle_thermal_fixed_fmu"])
def test_thermal_fmu_carries_no_bearing_model(fixture, request):
    with zipfile.ZipFile(request.getfixturevalue(fixture)) as archive:
        modules = [n for n in archive.namelist() if n.endswith(".py")]
    assert not [n for n in modules if n.startswith("resources/bearing_fmu/")]
    assert {"resources/spindle/thermal/model.py", "resources/bearing_fmu_common/bearing_file.py"} <= set(modules)
    assert not [n for n in modules if n.startswith(("resources/spindle/cosim/", "resources/spindle/cli.py"))]
