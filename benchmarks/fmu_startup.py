"""FMU start-up and step cost against the performance budget of docs/architecture.md (warm-cache
instantiate + first doStep <= 2 s; quasi-static doStep <= 1 ms; doStep with every output read <= 1.3 x
the compiled kernels of the same solve).

Each start-up run is a fresh process with its own numba cache directory (BEARING_FMU_CACHE):
the first run starts on an empty directory (the FMU's compiled code is loaded); the following runs
find it filled. Reported: medians of instantiate + first doStep inside the process, whole-process wall, the
cost of a doStep with every output read, and the kernel calls of those same steps replayed alone
(benchmarks/kernel_replay.py).
Run: python -m benchmarks.fmu_startup -> docs/reports/fmu_startup.md
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .render import cli, metric

ROOT = Path(__file__).resolve().parent.parent
# FMU -> (name of the varied input, its base value, the other inputs held): a realistic co-simulation
# step changes the inputs slightly, so the quasi-static solver warm-starts from the previous step
CASES = {
    "BearingAnalytic": ("omega", 500.0, {"F_y": 3000.0}),
    "Bearing": ("F_z", 800.0, {"omega": 1047.2, "F_y": 200.0}),
    "BearingDisp": ("z", 20e-6, {"omega": 1047.2, "x": 2e-6}),
}
STEP_TARGET_US = {"Bearing": 1000.0, "BearingDisp": 1000.0}  # quasi-static doStep <= 1 ms
STARTUP_TARGET_S = 2.0  # warm-cache instantiate + initialise + first doStep
KERNEL_RATIO_TARGET = {"Bearing": 1.3}  # doStep + all outputs / kernels of the same solve
CHILD = r"""
import json, shutil, sys, time
t0 = time.perf_counter()
import numba, numpy  # the importing interpreter's own packages (a master has them loaded)
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
path, varied, base, held = sys.argv[1], sys.argv[2], float(sys.argv[3]), json.loads(sys.argv[4])
md = read_model_description(path)
unzip = extract(path)
vr = {v.name: v.valueReference for v in md.modelVariables}
t1 = time.perf_counter()
fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName="b")
fmu.instantiate()
fmu.setupExperiment(startTime=0.0)
fmu.enterInitializationMode()
fmu.exitInitializationMode()
fmu.setReal([vr[k] for k in held], list(held.values()))
fmu.setReal([vr[varied]], [base])
fmu.doStep(0.0, 0.1)
t2 = time.perf_counter()
outs = [v.valueReference for v in md.modelVariables if v.causality == "output" and v.type == "Real"]
ints = [v.valueReference for v in md.modelVariables if v.causality == "output" and v.type == "Integer"]
n = 2000
def steps():
    for i in range(n):
        fmu.setReal([vr[varied]], [base * (1.0 + 1e-3 * (i % 20))])
        fmu.doStep(0.1 + i * 0.1, 0.1)
        fmu.getReal(outs)
        fmu.getInteger(ints)
# the same steps as a master that resolved its variables once calls them (spindle.cosim.master): the FMU's
# fmi2SetReal/fmi2DoStep/fmi2GetReal/fmi2GetInteger with preallocated ctypes arrays, no per-call conversion
from fmpy.fmi2 import fmi2Integer, fmi2Real, fmi2ValueReference
ref_in, val_in = (fmi2ValueReference * 1)(vr[varied]), (fmi2Real * 1)()
ref_out, val_out = (fmi2ValueReference * len(outs))(*outs), (fmi2Real * len(outs))()
ref_int, val_int = (fmi2ValueReference * len(ints))(*ints), (fmi2Integer * len(ints))()
def steps_batched():
    c = fmu.component
    for i in range(n):
        val_in[0] = base * (1.0 + 1e-3 * (i % 20))
        fmu.fmi2SetReal(c, ref_in, 1, val_in)
        fmu.fmi2DoStep(c, 0.1 + i * 0.1, 0.1, 1)
        fmu.fmi2GetReal(c, ref_out, len(outs), val_out)
        fmu.fmi2GetInteger(c, ref_int, len(ints), val_int)
state = fmu.getFMUstate()
# the kernel calls of these steps, recorded once from the same state, then replayed alone
sys.path.append(sys.argv[5])
from benchmarks.kernel_replay import BEARING_PACKAGES, KernelRecorder, replay_time
with KernelRecorder(BEARING_PACKAGES) as recorder:
    steps()
# rounds of (fmpy steps, batched steps, replay), each from the same state: the three draw on the same
# stretch of time (this shared machine's speed drifts by up to 1.5x within a minute); medians over rounds
walls, cpus, batched, kernels = [], [], [], []
for _ in range(5):
    fmu.setFMUstate(state)
    t3, c3 = time.perf_counter(), time.process_time()
    steps()
    walls.append((time.perf_counter() - t3) / n)
    cpus.append((time.process_time() - c3) / n)
    fmu.setFMUstate(state)
    c5 = time.process_time()
    steps_batched()
    batched.append((time.process_time() - c5) / n)
    kernels.append(replay_time(recorder.calls, repeats=1) / n)
median = lambda values: sorted(values)[len(values) // 2]
fmu.freeFMUstate(state)
fmu.terminate(); fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
print(json.dumps({"startup": t2 - t1, "imports": t1 - t0, "step_all_outputs": median(walls),
                  "step_cpu": median(cpus), "step_cpu_batched": median(batched), "kernels": median(kernels),
                  "ratio": median([c / k for c, k in zip(cpus, kernels)]),
                  "ratio_batched": median([b / k for b, k in zip(batched, kernels)])}))
"""


def run_once(name, cache_dir):
    varied, base, held = CASES[name]
    env = dict(os.environ, BEARING_FMU_CACHE=str(cache_dir))
    command = [sys.executable, "-c", CHILD, str(ROOT / "fmus" / f"{name}.fmu"), varied, str(base), json.dumps(held)]
    t0 = time.perf_counter()
    proc = subprocess.run([*command, str(ROOT)], capture_output=True, text=True, env=env, check=True)
    return json.loads(proc.stdout.strip().splitlines()[-1]) | {"wall": time.perf_counter() - t0}


def measure(warm_runs=7):
    rows, summary, metrics = [], [], []
    for name in CASES:
        with tempfile.TemporaryDirectory(prefix="bearing_fmu_cache_") as cache:
            cold = run_once(name, cache)
            warm = [run_once(name, cache) for _ in range(warm_runs)]
        med = {k: statistics.median(r[k] for r in warm) for k in warm[0]}  # the ratios: medians of each run's own
        target = STEP_TARGET_US.get(name)
        for run, r in (
            ("first start (empty numba cache: the FMU's compiled code is loaded)", cold),
            (f"warm cache, median of {warm_runs}", med),
        ):
            rows.append([name, run, r["startup"], r["wall"], *(1e6 * r[k] for k in COLUMNS), r["ratio"],
                         r["ratio_batched"], target])  # fmt: skip
        summary.append([name, med["startup"], STARTUP_TARGET_S, 1e6 * med["step_all_outputs"], target,
                        med["ratio_batched"], med["ratio"], KERNEL_RATIO_TARGET.get(name)])  # fmt: skip
        metrics += [
            metric(f"{name}: warm start-up", med["startup"], "s", "timing", target=STARTUP_TARGET_S),
            *([metric(f"{name}: doStep + all outputs", med["step_all_outputs"], "s", "timing", 1e-6 * target)]
              if target else []),
            metric(f"{name}: doStep + all outputs / kernels", med["ratio"], "1", "timing",
                   note="fmpy convenience calls"),
            metric(f"{name}: doStep + all outputs, batched / kernels", med["ratio_batched"], "1", "timing",
                   KERNEL_RATIO_TARGET.get(name), side_by_side=True, note="the master's preallocated FMI calls"),
        ]  # fmt: skip
    return dict(
        name="fmu_startup",
        title="FMU start-up and step cost",
        about=__doc__.split("Run:")[0],
        blocks=[
            dict(text=METHOD),
            dict(table=dict(columns=RUN_COLUMNS, formats=RUN_FORMATS, rows=rows)),
            dict(table=dict(caption=SUMMARY, columns=SUMMARY_COLUMNS, formats=SUMMARY_FORMATS, rows=summary)),
        ],
        metrics=metrics,
    )


COLUMNS = ("step_all_outputs", "step_cpu", "step_cpu_batched", "kernels")
RUN_COLUMNS = (
    "FMU|run|start-up (s)|whole process (s)|doStep + read all outputs, wall (us)|the same, CPU (us)|batched, CPU (us)"
    "|kernels alone, CPU (us)|ratio (CPU)|ratio batched (CPU)|step target (us)"
).split("|")
RUN_FORMATS = [None, None, "{:.3f}", "{:.2f}", *["{:.0f}"] * 4, "{:.2f}", "{:.2f}", "{:.0f}"]
SUMMARY = "Warm medians against the targets (doStep: wall time; the ratios: CPU time, median over the warm runs of \
each run's own ratio):"
SUMMARY_COLUMNS = (
    "FMU|warm start-up (s)|target (s)|doStep + all outputs (us)|target (us)|batched / kernels"
    "|fmpy convenience calls / kernels|target"
).split("|")
SUMMARY_FORMATS = [None, "{:.3f}", "{:g}", "{:.0f}", "{:.0f}", "{:.2f}", "{:.2f}", "{:g}"]
METHOD = """Host: fmpy FMU2Slave; 'start-up' = instantiate + initialise + first doStep. Step cost: 2000 doSteps, each \
with one input changed by up to 2 % (the solver warm-starts), reading every output. Kernels: the same 2000 steps from \
the same FMU state with every kernel call recorded, those calls replayed alone on fresh copies of their arguments \
(`benchmarks/kernel_replay.py`): the compiled cost of the same solves. Five rounds of (steps, batched steps, replay), \
each from the same state, so that the three share the machine's state; medians over the rounds, ratios per round. Two \
hosts: fmpy's convenience calls (`setReal`, `doStep`, `getReal`, `getInteger`: each builds its ctypes arrays from \
Python lists) and the way `spindle.cosim.master` calls the FMU once its variables are resolved (the same four FMI \
functions on preallocated ctypes arrays: 'batched'). The ratios are of CPU times measured in the same process \
(`time.process_time`, which other processes on the shared cores do not lengthen); the wall times are given for the \
step target. For the analytic kernel, which takes a few microseconds, the fixed cost of four FMI calls per step (fmpy \
ctypes, the FMI layer's C-to-Python dispatch) is a large part of a step."""


def main(argv=None):
    cli(measure, "fmu_startup")


if __name__ == "__main__":
    main()
