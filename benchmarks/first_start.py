"""First start of the FMUs on a fresh machine: the first fmpy.simulate_fmu in a new process with an
empty user cache, then a later start in another new process on the cache the first one left.

Each repeat gets its own empty cache (BEARING_FMU_CACHE, XDG_CACHE_HOME and HOME point into a new
temporary directory), so nothing compiled by an earlier run or by the test suite is reused: what a
first start does not compile comes from the FMU itself (docs/fmu_runtime.md, compiled code in the FMU).
Reported: the median over the repeats of the whole process (interpreter start, imports, extraction,
instantiation, the simulation) and of simulate_fmu alone, target <= 5 s for Bearing.fmu.
Run: python -m benchmarks.first_start [--repeats N] [--fmu-dir DIR] [NAME ...] -> docs/reports/first_start.md
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

from .common import machine, record, write_report

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


def fresh_env(cache_home):
    """The environment of a fresh machine's user: every cache location inside cache_home (empty)."""
    env = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "BEARING_FMU_CACHE")}
    env.update(HOME=str(cache_home), XDG_CACHE_HOME=str(Path(cache_home) / ".cache"))
    return env


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


def measure(name, fmu_dir=FMU_DIR, repeats=REPEATS, python=sys.executable):
    """Medians over `repeats` fresh caches of the first and of a later start of fmu_dir/<name>.fmu."""
    first, later = [], []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory(prefix="first_start_") as home:
            env = fresh_env(home)
            first.append(start(Path(fmu_dir) / f"{name}.fmu", CASES[name], env, python))
            later.append(start(Path(fmu_dir) / f"{name}.fmu", CASES[name], env, python))
    return {
        "first_wall": statistics.median(r[0] for r in first),
        "first_cpu": statistics.median(r[1] for r in first),
        "first_simulate": statistics.median(r[2] for r in first),
        "later_wall": statistics.median(r[0] for r in later),
        "later_cpu": statistics.median(r[1] for r in later),
        "later_simulate": statistics.median(r[2] for r in later),
        "first_all": [round(r[0], 2) for r in first],
    }


def report(results, repeats, load_before, load_after):
    lines = [
        "# First start of the FMUs",
        "",
        "First `fmpy.simulate_fmu` of each FMU in a new process whose user cache is empty (`HOME`,",
        "`XDG_CACHE_HOME` and `BEARING_FMU_CACHE` in a new temporary directory), then a later start: a",
        "second new process on the cache the first left. Medians of "
        f"{repeats} fresh caches. Process = interpreter start, `import fmpy`, extraction, instantiation and",
        "the run; its CPU time (user + system, all threads) is about the wall time on an idle machine (this one",
        "is shared); simulate = `simulate_fmu` alone (wall). Runs: "
        + ", ".join(f"{n} {c['stop_time']:g} s at {c['output_interval']:g} s steps" for n, c in CASES.items())
        + ".",
        "",
        f"Machine: {machine()}, {os.cpu_count()} cores shared with other jobs; load average "
        f"{load_before} before, {load_after} after.",
        "",
        "| FMU | first start: process wall (s) | its CPU time (s) | simulate_fmu (s) "
        "| later start: process wall (s) | its CPU time (s) | simulate_fmu (s) | first starts, wall (s) | target |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, r in results.items():
        target = f"<= {TARGET_S[name]:g} s" if name in TARGET_S else ""
        record(
            "first_start",
            f"{name}: first start, process wall",
            r["first_wall"],
            "s",
            kind="timing",
            target=TARGET_S.get(name),
        )
        record("first_start", f"{name}: first start, process CPU", r["first_cpu"], "s", kind="timing")
        lines.append(
            f"| {name} | {r['first_wall']:.2f} | {r['first_cpu']:.2f} | {r['first_simulate']:.2f} "
            f"| {r['later_wall']:.2f} | {r['later_cpu']:.2f} | {r['later_simulate']:.2f} "
            f"| {', '.join(map(str, r['first_all']))} | {target} |"
        )
    lines += [
        "",
        "Nothing is compiled at a first start (the FMU's compiled code is loaded), so first and later starts take",
        "the same time: importing numba and numpy, numba's target initialisation, loading the compiled code. The",
        "target (<= 5 s) is for a process that has a core to itself, which its CPU time measures; the wall time",
        "here is that of a process sharing 2 cores with the other jobs of the load average.",
        "",
        "Before the FMUs carried compiled code (same benchmark, same machine), the first start of Bearing.fmu "
        + BEFORE,
        "",
        "The 'first start' rows of `fmu_startup.md` (an empty numba cache) took 28.83 s for Bearing.fmu at load",
        "average 1.05 before the FMUs carried compiled code; now they load it instead of compiling.",
        "",
        "A host Python with only fmpy, numpy, numba and scipy installed (a fresh virtual environment; "
        "`--python VENV/bin/python`): " + MINIMAL_HOST,
        "",
        "The portable code's kernel speed against code compiled for this CPU: `docs/fmu_runtime.md`.",
        "Reproduce: `python -m benchmarks.first_start` (after `make fmus`).",
        "",
    ]
    return "\n".join(lines)


# the same benchmark on the FMUs as built before they carried compiled code (every kernel compiled at the
# first start), medians of 3 fresh caches at load average 11.7
# the same benchmark run with --python of a fresh virtual environment holding only fmpy, numpy, numba and
# scipy (pip install fmpy numpy numba scipy): nothing of this project installed, 5 fresh caches
MINIMAL_HOST = "first start of Bearing.fmu 1.49 s of CPU time, 11.57 s wall (load average 11.5); later start 1.49 s CPU, 13.1 s wall."
BEFORE = (
    "took 195.7 s of wall time and 30.5 s of CPU time (later start 9.0 s wall, 1.31 s CPU); "
    "an earlier run of 5 at load average 5-8: 77.9 s wall."
)


def loadavg():
    return Path("/proc/loadavg").read_text().split()[0] if Path("/proc/loadavg").is_file() else "n/a"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=REPEATS)
    parser.add_argument("--fmu-dir", default=str(FMU_DIR))
    parser.add_argument("--python", default=sys.executable, help="host interpreter (e.g. a venv with fmpy only)")
    parser.add_argument("--no-report", action="store_true", help="print the numbers, keep the report")
    parser.add_argument("names", nargs="*", default=list(CASES))
    args = parser.parse_args(argv)
    load_before = loadavg()
    results = {}
    for name in args.names:
        results[name] = measure(name, args.fmu_dir, args.repeats, args.python)
        print(name, json.dumps(results[name]), flush=True)
    if not args.no_report:
        write_report("first_start.md", report(results, args.repeats, load_before, loadavg()))


if __name__ == "__main__":
    main()
