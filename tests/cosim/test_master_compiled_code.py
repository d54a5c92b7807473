"""The master runs the product's FMUs on the compiled code they ship, and imports no physics for them
(docs/fmu_runtime.md, "Compiled code" and "The master").

The master talks FMI only: importing it loads nothing of bearing_fmu, nor numba or scipy (the first FMU loads what
it needs), and a bearing FMU then runs on the
bearing_fmu it carries (its copy in the cache), not on the source tree's. The thermal FMU's entry script runs
on the host's own `spindle.thermal` (the master is part of that package), under the jit policy the first
FMU brought; each kernel is looked up under the key of the source tree it comes from, so with an empty numba
cache nothing may compile (the thermal kernels compiled, 17 of them and about 4 s of set-up here, when they
were looked up under the bearing FMU's key)."""

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CHILD = """
import json, sys
from dataclasses import replace
from spindle.cosim.master import run
from spindle.cosim.runfile import load_run
before = sorted(m for m in sys.modules if m.split(".")[0] in ("bearing_fmu", "bearing_fmu_common", "numba", "scipy"))
spec = load_run("runs/closed_loop_spring.toml")
result = run(replace(spec, stop=spec.start + 20 * spec.step))
print(json.dumps({"before": before, "bearing_fmu": sys.modules["bearing_fmu"].__file__, "steps": result.n_steps}))
"""


def test_a_closed_loop_with_an_empty_cache_compiles_nothing_and_runs_on_the_fmus_packages(tmp_path):
    cache = tmp_path / "cache"
    env = dict(os.environ, BEARING_FMU_CACHE=str(cache))
    env.pop("NUMBA_CACHE_DIR", None)
    proc = subprocess.run(
        [sys.executable, "-c", CHILD], cwd=ROOT, env=env, capture_output=True, text=True, check=False, timeout=600
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    compiled = sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*.nbc"))
    assert compiled == []
    result = json.loads(proc.stdout.strip().splitlines()[-1])
    assert result["steps"] == 20
    assert result["before"] == []  # importing the master loads nothing of the product's physics, nor numba or scipy
    assert Path(result["bearing_fmu"]).is_relative_to(cache)  # the FMU's own copy, not the source tree
