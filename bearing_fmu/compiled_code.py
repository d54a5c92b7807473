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

numba's cache entries are per Python version (their file names carry it: ``*.py311.nbi``) and per numba
version, so the runs are made once with the build's interpreter and once with each interpreter named in
$BEARING_FMU_KERNEL_PYTHONS (os.pathsep-separated; each with numpy, numba and fmpy, one per Python
version: bearing_fmu_common.runtime.host_pythons makes them), all into the same directory of the FMU;
target.json lists the Python and numba versions it holds (``builds``). A host with another combination
compiles at first use, with a message (bearing_fmu_common.jit.compiled_code_note).
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
KERNEL_PYTHONS_ENV = "BEARING_FMU_KERNEL_PYTHONS"  # more interpreters to compile the kernels with
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
import numba
from bearing_fmu_common import jit
print("TARGET " + json.dumps(jit.codegen_description()))
print("BUILD " + json.dumps(["%d.%d" % sys.version_info[:2], numba.__version__]))
"""


def build_cache_dir():
    """The numba cache of the portable builds, kept between builds."""
    return cache_base().absolute() / "portable"


def kernel_pythons():
    """The interpreters the kernels are compiled with: this one, then those of $BEARING_FMU_KERNEL_PYTHONS."""
    extra = [p for p in os.environ.get(KERNEL_PYTHONS_ENV, "").split(os.pathsep) if p.strip()]
    return [sys.executable, *extra]


def _run(fmu_path, runs, env, python=sys.executable):
    """(codegen description, (Python version, numba version), cache files loaded, cache files saved) of one
    child run."""
    proc = subprocess.run(
        [str(python), "-c", CHILD, str(fmu_path), json.dumps(runs)], env=env, capture_output=True, text=True
    )
    if proc.returncode != 0:
        name = Path(fmu_path).name
        raise RuntimeError(f"compiling the kernels of {name} with {python} failed:\n{proc.stderr[-4000:]}")
    magic, build, loaded, saved = None, None, set(), set()
    for line in proc.stdout.splitlines():
        if line.startswith("TARGET "):
            magic = json.loads(line[len("TARGET ") :])
        elif line.startswith("BUILD "):
            build = tuple(json.loads(line[len("BUILD ") :]))
        elif match := _CACHE_LINE.match(line):
            (saved if match.group(1) == "saved to" else loaded).add(Path(ast.literal_eval(match.group(2))))
    return magic, build, loaded, saved


def compile_portable(fmu_path, runs, build_cache=None, python=sys.executable):
    """Run the FMU in a child process of `python` with numba targeting the generic CPU; returns (codegen
    description, (Python version, numba version), the cache files under build_cache/numba that a run with
    every kernel already compiled loads: what the FMU needs, the same whatever the build cache held before)."""
    build_cache = Path(build_cache or build_cache_dir())
    dropped = ("NUMBA_CACHE_DIR", "NUMBA_CPU_FEATURES") + (() if python == sys.executable else ("PYTHONPATH",))
    env = {k: v for k, v in os.environ.items() if k not in dropped}  # another Python: not this one's path
    env.update(BEARING_FMU_CACHE=str(build_cache), NUMBA_CPU_NAME=PORTABLE_CPU, NUMBA_DEBUG_CACHE="1")
    magic, build, loaded, saved = _run(fmu_path, runs, env, python)
    if saved:  # something was compiled: the callees were saved beside their callers; ask a warm run
        magic, build, loaded, saved = _run(fmu_path, runs, env, python)
    if magic is None or magic[1] != PORTABLE_CPU or saved:
        raise RuntimeError(f"the kernels of {Path(fmu_path).name} were not all compiled for the {PORTABLE_CPU} CPU")
    numba_dir = (build_cache / "numba").resolve()
    used = {p.resolve() for p in loaded}
    return magic, build, sorted(p.relative_to(numba_dir) for p in used if p.is_relative_to(numba_dir) and p.is_file())


def add_compiled_code(fmu_path, runs, build_cache=None, pythons=None):
    """Compile the FMU's kernels for the generic CPU (running `runs`) with each of `pythons` (default:
    kernel_pythons()) and add them to the FMU."""
    build_cache = Path(build_cache or build_cache_dir())
    magics, builds, used = set(), {}, set()
    for python in pythons or kernel_pythons():
        magic, (version, numba_version), files = compile_portable(fmu_path, runs, build_cache, python)
        if version in builds:
            raise RuntimeError(f"{python}: a second interpreter of Python {version} in {KERNEL_PYTHONS_ENV}")
        magics.add(tuple(magic))
        builds[version] = numba_version
        used.update(files)
    if len(magics) != 1:  # one target.json describes every entry
        raise RuntimeError(f"the interpreters compiled for different targets: {sorted(magics)}")
    with zipfile.ZipFile(fmu_path, "a", zipfile.ZIP_DEFLATED) as fmu:
        prefix = f"resources/{COMPILED_DIR}"
        fmu.writestr(f"{prefix}/{TARGET_FILE}", json.dumps({"magic": magics.pop(), "builds": builds}) + "\n")
        for relative in sorted(used):
            fmu.write(build_cache / "numba" / relative, f"{prefix}/{relative.as_posix()}")
    return fmu_path
