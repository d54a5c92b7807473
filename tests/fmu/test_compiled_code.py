"""Each FMU ships its kernels compiled for the generic CPU of its platform (bearing_fmu/compiled_code.py,
docs/fmu_runtime.md "Compiled code"): a first start with an empty user cache loads them and compiles
nothing, wherever the FMU is extracted; the FMU's copy of its packages in a shared cache follows the umask.
"""

import json
import os
import sys
import zipfile
from pathlib import Path

import pytest

from bearing_fmu.compiled_code import COMPILED_DIR
from bearing_fmu_common.jit import PORTABLE_CPU, TARGET_FILE
from tests._processes import run_checked

# fixture -> a short simulate_fmu run with the start values
RUNS = {
    "analytic_fmu": {"stop_time": 1.0, "output_interval": 0.1},
    "bearing_fmu": {"stop_time": 1.0, "output_interval": 0.1},
    "spindle_thermal_fmu": {"stop_time": 600.0, "output_interval": 60.0},
}
CHILD = "import fmpy, json, sys\nassert len(fmpy.simulate_fmu(sys.argv[1], **json.loads(sys.argv[2]))) > 1\n"


def fresh_start(fmu, run, home, umask=None):
    """stdout of a first simulate_fmu in a new process whose caches are all under the empty `home`, with
    numba's cache log on."""
    env = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "BEARING_FMU_CACHE", "NUMBA_CPU_NAME")}
    env.update(HOME=str(home), XDG_CACHE_HOME=str(Path(home) / ".cache"), NUMBA_DEBUG_CACHE="1")
    return run_checked([sys.executable, "-c", CHILD, fmu, json.dumps(run)], env, umask=umask).stdout


@pytest.mark.parametrize("fixture", sorted(RUNS))
def test_fmu_ships_generic_code(fixture, request):
    with zipfile.ZipFile(request.getfixturevalue(fixture)) as fmu:
        names = fmu.namelist()
        magic = json.loads(fmu.read(f"resources/{COMPILED_DIR}/{TARGET_FILE}"))["magic"]
    assert magic[1:] == [PORTABLE_CPU, ""]  # the baseline CPU, no optional features
    assert any(n.endswith(".nbi") for n in names) and any(n.endswith(".nbc") for n in names)


@pytest.mark.parametrize("fixture", sorted(RUNS))
def test_first_start_with_an_empty_cache_compiles_nothing(fixture, request, tmp_path):
    log = fresh_start(request.getfixturevalue(fixture), RUNS[fixture], tmp_path)
    loaded = [line for line in log.splitlines() if line.startswith("[cache] data loaded from")]
    assert loaded and all(f"/{COMPILED_DIR}/" in line for line in loaded)
    assert "data saved to" not in log  # no kernel compiled


def test_the_packages_copy_in_a_shared_cache_follows_the_umask(analytic_fmu, tmp_path):
    fresh_start(analytic_fmu, RUNS["analytic_fmu"], tmp_path, umask=0o002)
    base = tmp_path / ".cache" / "bearing_fmu"
    copies = [p for p in base.iterdir() if (p / "bearing_fmu" / "__init__.py").is_file()]
    assert len(copies) == 1
    for path in (copies[0], copies[0] / "bearing_fmu", copies[0] / "bearing_fmu_common"):
        assert path.stat().st_mode & 0o777 == 0o775, path
    assert not list(base.glob(".staging-*"))
