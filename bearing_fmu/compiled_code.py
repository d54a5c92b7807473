"""Put an FMU's kernels, compiled for its platform's generic CPU, into the FMU (FMU build step).

A fresh process runs the built FMU through fmpy with numba targeting the ``generic`` CPU (x86-64:
the baseline instruction set every x86-64 processor has) and its numba cache in a build cache directory
kept between builds ($BEARING_FMU_CACHE or ~/.cache/bearing_fmu, ``portable/``), so a kernel shared by
several FMUs is compiled once. The cache entries a run with everything compiled loads (the kernels the
FMU calls, each with its callees linked in) go into the FMU under
resources/numba_portable/<hash of the kernel sources>/, with target.json naming numba's description of
the code (target triple, CPU, features); the FMU's entry script registers that directory with the jit
policy (bearing_fmu_common.jit.add_compiled_dir). Why generic and not this machine's CPU, and what it
costs: docs/fmu_runtime.md, "Compiled code".
"""

import ast
import json
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

from bearing_fmu_common.jit import PORTABLE_CPU, TARGET_FILE, cache_base

COMPILED_DIR = "numba_portable"  # in the FMU's resources/
_CACHE_LINE = re.compile(r"^\[cache\] (?:index|data) (loaded from|saved to) (.+)$")

# runs each experiment of argv[2] ({"options": simulate_fmu keywords, "inputs": rows with "time"}) on the
# FMU argv[1], then prints the codegen description of the compiled code
CHILD = r"""
import json, sys
import numpy as np
import fmpy
path, runs = sys.argv[1], json.loads(sys.argv[2])
for run in runs:
    options = dict(run["options"])
    rows = run.get("inputs")
    if rows:
        names = list(rows[0])
        options["input"] = np.array([tuple(r[n] for n in names) for r in rows], dtype=[(n, float) for n in names])
    fmpy.simulate_fmu(path, **options)
from bearing_fmu_common import jit
print("TARGET " + json.dumps(jit.codegen_description()))
"""


def build_cache_dir():
    """The numba cache of the portable builds, kept between builds."""
    return cache_base().absolute() / "portable"


def _run(fmu_path, runs, env):
    """(codegen description, cache files loaded, cache files saved) of one child run."""
    proc = subprocess.run(
        [sys.executable, "-c", CHILD, str(fmu_path), json.dumps(runs)], env=env, capture_output=True, text=True
    )
    if proc.returncode != 0:
        raise RuntimeError(f"compiling the kernels of {Path(fmu_path).name} failed:\n{proc.stderr[-4000:]}")
    magic, loaded, saved = None, set(), set()
    for line in proc.stdout.splitlines():
        if line.startswith("TARGET "):
            magic = json.loads(line[len("TARGET ") :])
        elif match := _CACHE_LINE.match(line):
            (saved if match.group(1) == "saved to" else loaded).add(Path(ast.literal_eval(match.group(2))))
    return magic, loaded, saved


def compile_portable(fmu_path, runs, build_cache=None):
    """Run the FMU in a child process with numba targeting the generic CPU; returns (codegen description,
    the cache files under build_cache/numba that a run with every kernel already compiled loads: what the
    FMU needs, the same whatever the build cache held before)."""
    build_cache = Path(build_cache or build_cache_dir())
    env = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "NUMBA_CPU_FEATURES")}
    env.update(BEARING_FMU_CACHE=str(build_cache), NUMBA_CPU_NAME=PORTABLE_CPU, NUMBA_DEBUG_CACHE="1")
    magic, loaded, saved = _run(fmu_path, runs, env)
    if saved:  # something was compiled: the callees were saved beside their callers; ask a warm run
        magic, loaded, saved = _run(fmu_path, runs, env)
    if magic is None or magic[1] != PORTABLE_CPU or saved:
        raise RuntimeError(f"the kernels of {Path(fmu_path).name} were not all compiled for the {PORTABLE_CPU} CPU")
    numba_dir = (build_cache / "numba").resolve()
    used = {p.resolve() for p in loaded}
    return magic, sorted(p.relative_to(numba_dir) for p in used if p.is_relative_to(numba_dir) and p.is_file())


def add_compiled_code(fmu_path, runs, build_cache=None):
    """Compile the FMU's kernels for the generic CPU (running `runs`) and add them to the FMU."""
    build_cache = Path(build_cache or build_cache_dir())
    magic, used = compile_portable(fmu_path, runs, build_cache)
    with zipfile.ZipFile(fmu_path, "a", zipfile.ZIP_DEFLATED) as fmu:
        prefix = f"resources/{COMPILED_DIR}"
        fmu.writestr(f"{prefix}/{TARGET_FILE}", json.dumps({"magic": magic}) + "\n")
        for relative in used:
            fmu.write(build_cache / "numba" / relative, f"{prefix}/{relative.as_posix()}")
    return fmu_path
