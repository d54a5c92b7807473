"""First start of the FMUs on a fresh machine: the first fmpy.simulate_fmu in a new process with an
empty user cache, then a later start in another new process on the cache the first one left.

Each repeat gets its own empty cache (BEARING_FMU_CACHE, XDG_CACHE_HOME and HOME point into a new
temporary directory), so nothing compiled by an earlier run or by the test suite is reused: what a
first start does not compile comes from the FMU itself (docs/fmu_runtime.md, compiled code in the FMU).
Reported: the median over the repeats of the whole process (interpreter start, imports, extraction,
instantiation, the simulation) and of simulate_fmu alone, target <= 5 s for Bearing.fmu.
Run: python -m benchmarks.first_start [--repeats N] [--fmu-dir DIR] [--python PYTHON] [NAME ...]
-> docs/reports/first_start.md
"""

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .render import cli, metric

ROOT = Path(__file__).resolve().parent.parent
FMU_DIR = ROOT / "fmus"
# FMU -> simulate_fmu arguments of a short run at its usual communication step (s) with its start values
CASES = {
    "Bearing": {"stop_time": 1.0, "output_interval": 0.1},
    "BearingAnalytic": {"stop_time": 1.0, "output_interval": 0.1},
    "BearingDEM": {"stop_time": 2e-3, "output_interval": 0.5e-3},
    "SpindleThermal": {"stop_time": 600.0, "output_interval": 60.0},
}
TARGET_S = {"Bearing": 5.0}
REPEATS = 5

CHILD = r"""
import json, sys, time
t0 = time.perf_counter()
import fmpy
t1 = time.perf_counter()
result = fmpy.simulate_fmu(sys.argv[1], **json.loads(sys.argv[2]))
t2 = time.perf_counter()
assert len(result) > 1, "the FMU stopped at its first step"
print(json.dumps({"import": t1 - t0, "simulate": t2 - t1}))
"""


def _children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def start(fmu, case, env, python=sys.executable):
    """One new process simulating fmu: (whole process wall s, its CPU time s, simulate_fmu wall s)."""
    t0, c0 = time.perf_counter(), _children_cpu()
    out = subprocess.run(
        [python, "-c", CHILD, str(fmu), json.dumps(case)], env=env, capture_output=True, text=True, check=False
    )
    wall, cpu = time.perf_counter() - t0, _children_cpu() - c0
    if out.returncode != 0:
        raise RuntimeError(f"{fmu.name}: exit {out.returncode}\n{out.stderr[-3000:]}")
    return wall, cpu, json.loads(out.stdout.strip().splitlines()[-1])["simulate"]


def starts(name, fmu_dir, repeats, python):
    """Medians over `repeats` fresh caches of the first and of a later start of fmu_dir/<name>.fmu."""
    fmu, first, later = Path(fmu_dir) / f"{name}.fmu", [], []
    keep = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "BEARING_FMU_CACHE")}
    for _ in range(repeats):
        with tempfile.TemporaryDirectory(prefix="first_start_") as home:  # every cache location inside it
            env = dict(keep, HOME=home, XDG_CACHE_HOME=str(Path(home) / ".cache"))
            first.append(start(fmu, CASES[name], env, python))
            later.append(start(fmu, CASES[name], env, python))
    medians = [statistics.median(r[k] for r in runs) for runs in (first, later) for k in range(3)]
    return [name, *medians, ", ".join(f"{r[0]:.2f}" for r in first), TARGET_S.get(name)]


def measure(repeats=REPEATS, fmu_dir=FMU_DIR, python=sys.executable, names=tuple(CASES)):
    rows = []
    for name in names:
        rows.append(starts(name, fmu_dir, repeats, python))
        print(*rows[-1], flush=True)
    runs = ", ".join(
        f"{n} {c['stop_time']:g} s at {c['output_interval']:g} s steps" for n, c in CASES.items() if n in names
    )
    return dict(
        name="first_start",
        title="First start of the FMUs",
        about=__doc__.split("Run:")[0],
        blocks=[
            dict(text=METHOD, values=dict(repeats=repeats, runs=runs)),
            dict(table=dict(columns=COLUMNS, formats=[None, *["{:.2f}"] * 6, None, "<= {:g}"], rows=rows)),
            dict(text=READING, values=dict(target=TARGET_S["Bearing"])),
        ],
        metrics=[
            m
            for name, wall, cpu, *_, target in rows
            for m in (
                metric(f"{name}: first start, process wall", wall, "s", "timing", target=target),
                metric(f"{name}: first start, process CPU", cpu, "s", "timing"),
            )
        ],
    )


COLUMNS = (
    "FMU|first start: process wall (s)|its CPU time (s)|simulate_fmu (s)|later start: process wall (s)"
    "|its CPU time (s)|simulate_fmu (s)|first starts, wall (s)|target (s)"
).split("|")
METHOD = """Medians of {repeats} fresh caches; a later start is a second new process on the cache the first \
left. The process's CPU time is user + system, all threads; simulate = `simulate_fmu` alone (wall). Runs: {runs}."""

READING = """Nothing is compiled at a first start (the FMU's compiled code is loaded): a start is importing numba \
and numpy, numba's target initialisation and loading the compiled code. The target (<= {target:g} s for \
Bearing.fmu) is for a process that has a core to itself, which its CPU time measures; the wall time is that of a \
process sharing the machine's cores with the other jobs of the load average. A host Python with only fmpy, numpy, \
numba and scipy installed (a fresh virtual environment) is measured with `--python VENV/bin/python`; the portable \
code's kernel speed against code compiled for this CPU: `docs/fmu_runtime.md`."""


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=REPEATS)
    parser.add_argument("--fmu-dir", default=str(FMU_DIR))
    parser.add_argument("--python", default=sys.executable, help="host interpreter (e.g. a venv with fmpy only)")
    parser.add_argument("--no-report", action="store_true", help="print the numbers, keep the report")
    parser.add_argument("names", nargs="*", default=list(CASES))
    args = parser.parse_args(argv)
    options = dict(repeats=args.repeats, fmu_dir=args.fmu_dir, python=args.python, names=args.names)
    measure(**options) if args.no_report else cli(measure, "first_start", **options)


if __name__ == "__main__":
    main()
