"""The FMUs in fmpy hosts on every supported Python (3.10-3.13) and in native hosts that start each of them
(docs/fmu_runtime.md, "Which Python").

Each Python gets a virtual environment with only numpy, numba and fmpy (bearing_fmu_common.runtime.host_pythons:
numba and fmpy at this run's versions, numpy at most this run's: Python 3.10 has no wheel of the newest). The
FMUs are built here, into a temporary directory, with their kernels compiled by each of those interpreters
(BEARING_FMU_KERNEL_PYTHONS), as `make fmus-python-hosts` builds them. In a fresh process per Python and FMU,
with an empty user cache:
- Bearing.fmu, BearingDEM.fmu and SpindleThermal.fmu run their reference experiments, compile nothing (the
  FMU's kernels for that Python are loaded: no entry is written to the user cache) and give the outputs of
  Python 3.11 to 1e-12 relative to each output's largest magnitude: the same kernels compiled by the same
  numba for the same generic CPU, so only another code path could make them differ;
- a native host (the C importer) with BEARING_FMU_PYTHON naming that environment's python starts that
  interpreter in the process and gives the outputs of fmpy on it;
- an FMU that carries kernels for the build's Python only says, on another Python, that it compiles them at
  first use, then how long that took, and gives the same outputs.

Marked `python_hosts` (tests/_markers.py): making the environments takes minutes of pip the first time, and
the build compiles every kernel once per Python (`make test-python-hosts`); `make test` leaves them out.
"""

import json
import os
import sys
from pathlib import Path

import numpy as np
import pytest

from bearing_fmu import build as bearing_build
from bearing_fmu.compiled_code import KERNEL_PYTHONS_ENV
from bearing_fmu_common.runtime.host_pythons import SUPPORTED, HostPythonError, host_python
from spindle import all_fmus
from tests._processes import run_in_host
from tests.fmu.test_native_runtime import Unpacked, importer  # noqa: F401 (the importer fixture)

VERSIONS = [f"{major}.{minor}" for major, minor in SUPPORTED]
REFERENCE = "3.11"  # the Python the others are compared with
# the outputs agree to this, relative to each output's largest magnitude over the run
RTOL = 1e-12

CHILD = r"""
import json, sys
import numpy as np
import fmpy
path, run = sys.argv[1], json.loads(sys.argv[2])
options = dict(run["options"])
rows = run.get("inputs")
if rows:
    names = list(rows[0])
    options["input"] = np.array([tuple(r[n] for n in names) for r in rows], dtype=[(n, float) for n in names])
result = fmpy.simulate_fmu(path, **options)
print("RESULT " + json.dumps({"names": list(result.dtype.names), "rows": [list(map(float, r)) for r in result]}))
"""


@pytest.fixture(scope="module")
def pythons():
    """{"3.X": python of that version's environment}; a version that cannot be had here is skipped."""
    found = {}
    for version in VERSIONS:
        try:
            found[version] = host_python(tuple(int(x) for x in version.split(".")))
        except HostPythonError as error:
            pytest.skip(f"Python {version}: {error}")
    return found


def _build(out_dir, kernel_pythons):
    """Bearing, BearingDEM, SpindleThermal and BearingAnalytic built into out_dir with kernels compiled by this
    interpreter and `kernel_pythons`."""
    saved = os.environ.get(KERNEL_PYTHONS_ENV)
    os.environ[KERNEL_PYTHONS_ENV] = os.pathsep.join(str(p) for p in kernel_pythons)
    try:
        paths = {
            name: bearing_build.build_fmu(bearing_build.SCENES_DIR / scene, out_dir)
            for name, scene in (("Bearing", "quasi_static.toml"), ("BearingDEM", "dem.toml"))
        }
        network, axial_float = all_fmus.THERMAL_FMUS["SpindleThermal"]
        paths["SpindleThermal"] = all_fmus.build_thermal_fmu("SpindleThermal", network, axial_float, out_dir)
    finally:
        if saved is None:
            os.environ.pop(KERNEL_PYTHONS_ENV)
        else:
            os.environ[KERNEL_PYTHONS_ENV] = saved
    return paths


@pytest.fixture(scope="module")
def fmus(pythons, tmp_path_factory):
    """The FMUs with kernels for every supported Python."""
    others = [p for v, p in pythons.items() if v != f"{sys.version_info[0]}.{sys.version_info[1]}"]
    return _build(tmp_path_factory.mktemp("python_hosts_fmus"), others)


def experiment(name):
    """The reference experiment of FMU `name` as a CHILD run: {"options": simulate_fmu keywords, "inputs": rows}."""
    if name == "SpindleThermal":
        network, axial_float = all_fmus.THERMAL_FMUS[name]
        inputs = all_fmus.reference_inputs(all_fmus.SpindleThermalModel(network, axial_float=axial_float))
        stop, step = all_fmus.REFERENCE_STOP, all_fmus.REFERENCE_STEP
        return {
            "options": {"stop_time": stop, "output_interval": step},
            "inputs": [{"time": 0.0, **inputs}, {"time": stop, **inputs}],
        }
    scene = bearing_build.Scene.from_toml(
        bearing_build.SCENES_DIR / ("quasi_static.toml" if name == "Bearing" else "dem.toml")
    )
    return bearing_build.compile_runs(scene)[1]


def run_fmpy(python, fmu, cache):
    """(outputs: names and rows, the index files written to the user cache, stdout) of the FMU's reference
    experiment through fmpy on `python`, in a fresh process with the user cache `cache`."""
    result, stdout = run_in_host(python, ["-c", CHILD, fmu, json.dumps(experiment(Path(fmu).stem))], cache, 1800)
    compiled = sorted(p.name for p in (Path(cache) / "numba").rglob("*.nbi"))
    return result, compiled, stdout


def max_relative_difference(a, b):
    """Largest |a - b| of each output over the run, relative to the output's largest magnitude in b."""
    x, y = np.array(a["rows"]), np.array(b["rows"])
    assert a["names"] == b["names"] and x.shape == y.shape
    scale = np.maximum(np.abs(y).max(axis=0), 1e-300)
    return dict(zip(a["names"], (np.abs(x - y).max(axis=0) / scale).tolist(), strict=True))


@pytest.mark.parametrize("name", ["Bearing", "BearingDEM", "SpindleThermal"])
def test_fmpy_hosts_on_every_python_give_the_same_outputs_without_compiling(name, pythons, fmus, tmp_path):
    results = {}
    for version, python in pythons.items():
        results[version], compiled, stdout = run_fmpy(python, fmus[name], tmp_path / version)
        assert compiled == [], f"Python {version} compiled {compiled}:\n{stdout[-2000:]}"
        assert "compile them" not in stdout
    reference = results[REFERENCE]
    assert len(reference["rows"]) > 10
    for version, result in results.items():
        differences = max_relative_difference(result, reference)
        print(f"{name} Python {version} vs {REFERENCE}: largest relative difference {max(differences.values()):.3g}")
        assert all(d <= RTOL for d in differences.values()), {k: d for k, d in differences.items() if d > RTOL}


NATIVE_OUTPUTS = ["z", "torque", "Lambda_inner", "K[3,3]"]
NATIVE_INPUTS = {"omega": 1047.0, "F_z": 800.0, "F_x": 200.0}


def test_native_hosts_start_every_python_with_the_same_outputs(pythons, fmus, importer, tmp_path):  # noqa: F811
    """The C importer with BEARING_FMU_PYTHON naming each environment's python: that interpreter is started in
    the process (two instantiate/free cycles, a serialised state round trip) and the outputs agree."""
    fmu = Unpacked(fmus["Bearing"])
    values = {}
    try:
        for version, python in pythons.items():
            extra = {"BEARING_FMU_PYTHON": str(python), "BEARING_FMU_CACHE": str(tmp_path / version)}
            rc, values[version], stderr = fmu.run(importer, NATIVE_INPUTS, NATIVE_OUTPUTS, runs=2, extra=extra)
            assert rc == 0, f"Python {version}: {stderr[-3000:]}"
            assert sorted(values[version]) == sorted(NATIVE_OUTPUTS)
            compiled = sorted(p.name for p in (tmp_path / version).rglob("*.nbi"))
            assert compiled == [], f"Python {version} compiled {compiled}"
    finally:
        fmu.remove()
    for version in pythons:
        for output in NATIVE_OUTPUTS:
            a, b = values[version][output], values[REFERENCE][output]
            assert abs(a - b) <= RTOL * abs(b), (version, output, a, b)


def test_a_python_without_the_fmus_kernels_compiles_them_and_says_so(pythons, tmp_path):
    """BearingAnalytic.fmu with kernels for the build's Python only, on another Python: a warning at
    instantiation, the compile time after, and the outputs of the build's Python."""
    other = next(v for v in VERSIONS if v != f"{sys.version_info[0]}.{sys.version_info[1]}")
    saved = os.environ.pop(KERNEL_PYTHONS_ENV, None)
    try:
        fmu = bearing_build.build_fmu(bearing_build.SCENES_DIR / "analytic.toml", tmp_path / "fmus")
    finally:
        if saved is not None:
            os.environ[KERNEL_PYTHONS_ENV] = saved
    run = {"options": {"stop_time": 1.0, "output_interval": 0.1, "start_values": {"omega": 500.0, "F_y": 3000.0}}}
    outputs = {}
    for version, python in ((other, pythons[other]), ("build", sys.executable)):
        outputs[version], stdout = run_in_host(python, ["-c", CHILD, fmu, json.dumps(run)], tmp_path / version, None)
        if version == other:
            assert f"this host runs Python {other} with numba" in stdout, stdout
            assert "so the first steps compile them" in stdout
            assert "compiled kernels for" in stdout and "s (wall time) in this call" in stdout
        else:
            assert "compile" not in stdout, stdout
    differences = max_relative_difference(outputs[other], outputs["build"])
    assert all(d <= RTOL for d in differences.values()), differences
