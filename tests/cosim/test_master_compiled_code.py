"""The master runs the product's FMUs on the compiled code they ship (docs/fmu_runtime.md, "Compiled code").

The master imports the product itself, so the FMUs' entry scripts run on the host's modules; with an empty
numba cache nothing may compile (a compile of the thermal network's kernels cost about 30 s of set-up when
the thermal FMU's modules and the bearing FMU's jit policy came from different copies)."""

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CHILD = """
from dataclasses import replace
from spindle.cosim.master import run
from spindle.cosim.runfile import load_run
spec = load_run("runs/closed_loop_spring.toml")
result = run(replace(spec, stop=spec.start + 20 * spec.step))
print(result.wall_time)
"""


def test_a_closed_loop_with_an_empty_cache_compiles_nothing(tmp_path):
    env = dict(os.environ, BEARING_FMU_CACHE=str(tmp_path / "cache"))
    env.pop("NUMBA_CACHE_DIR", None)
    proc = subprocess.run(
        [sys.executable, "-c", CHILD], cwd=ROOT, env=env, capture_output=True, text=True, check=False, timeout=600
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    compiled = sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*.nbc"))
    assert compiled == []
