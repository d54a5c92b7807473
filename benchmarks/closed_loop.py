"""Closed-loop demo timing and plausibility against the performance budget of docs/architecture.md (two
bearings + thermal spindle, one hour simulated at H = 1 s, <= 10 s wall with a warm numba cache; a
co-simulation step <= 1.5 x the compiled kernels it calls, replayed alone: benchmarks/kernel_replay.py).

runs/closed_loop_spring.toml as it is (B7214C pair in X arrangement, 800 N spring preload, 10 000 rpm,
Gauss-Seidel, H = 1 s, 3600 s) run RUNS times in this process through spindle.cosim.master.run: the first run
loads the numba cache from disk and is reported on its own, the others give the medians (stepping =
RunResult.wall_time, set-up = RunResult.setup_time: extraction, instantiation, initialisation). The whole
command `python -m spindle.cli run runs/closed_loop_spring.toml --no-plot` is also timed once in a fresh
process (imports included): what a user waits for.
Physics at t = 3600 s: energy balance (P_in vs P_out, and the stored-energy rate), temperature rises
T - 293.15 K of every recorded spindle temperature, their change over the last 10 minutes, the steady
state of the network with the final heat held (SpindleThermalModel.steady_state) and the same run at
H = 10 s (a near-steady state has almost no coupling error). No measured curve exists (Rabreau et al.
2018 do not tabulate theirs): the outer-ring rise is set against a plausibility band only.
Run: python -m benchmarks.closed_loop -> docs/reports/closed_loop.md and .png
"""

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from spindle.cosim.master import run
from spindle.cosim.runfile import load_run
from spindle.thermal.model import SpindleThermalModel

from .kernel_replay import KernelRecorder, kernel_names, replay_time
from .render import cli, metric

ROOT = Path(__file__).resolve().parent.parent
RUN = ROOT / "runs" / "closed_loop_spring.toml"
RUNS = 4  # the first warms the cache; medians over the other three
PAIRS = 15  # closed-loop runs each followed by a replay of its kernels (CPU time); the ratio of one pair
# varies with the shared machine's speed phases, so the median needs more than a handful
TARGET = 10.0  # s, docs/architecture.md (performance budget)
T_AMBIENT = 293.15  # K
OMEGA = 1047.1975511965977
SETTLE = 600.0  # s, "last 10 minutes"
FLOOR_RATIO_TARGET = 1.5  # closed-loop step / replayed-kernel floor (docs/architecture.md, performance budget)
RABREAU_MODEL_VS_RIG = 0.12  # relative temperature difference of Rabreau et al. (2018)'s model and rig


def cli_wall():
    """Wall time of the whole `spindle run` command in a fresh process (s), and its exit code."""
    with tempfile.TemporaryDirectory() as out:
        t0 = time.perf_counter()
        command = [sys.executable, "-m", "spindle.cli", "run", str(RUN), "--no-plot", "--out", out]
        proc = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
        return time.perf_counter() - t0, proc.returncode


def timing():
    """Blocks and metrics of the timing against the targets: RUNS runs, the kernel floor, the whole command."""
    n = load_run(RUN).n_steps
    results = [run(load_run(RUN)) for _ in range(RUNS)]
    for r in results:
        if r.status != "ok":
            raise RuntimeError(f"{r.status}: {r.message}")
    first, warm = results[0], results[1:]
    step, setup = statistics.median(r.wall_time for r in warm), statistics.median(r.setup_time for r in warm)
    total = statistics.median(r.wall_time + r.setup_time for r in warm)
    with KernelRecorder() as recorder:  # the same run once more, every kernel call recorded
        run(load_run(RUN))
    pairs = []  # (CPU time per step of a run, of the replayed kernels right after it): same conditions
    for _ in range(PAIRS):
        pairs.append((run(load_run(RUN)).cpu_time / n, replay_time(recorder.calls, repeats=1) / n))
    cpu, floor = statistics.median(p[0] for p in pairs), statistics.median(p[1] for p in pairs)
    ratio = statistics.median(p[0] / p[1] for p in pairs)
    cli_wall()  # fills the numba cache of the FMUs' own bundled sources, which a fresh process uses
    cli_time, cli_code = cli_wall()
    rows = [
        ["first in the process (loads the numba cache)", first.wall_time, first.setup_time,
         first.wall_time + first.setup_time, 1e3 * first.wall_time / n, (first.wall_time + first.setup_time) / TARGET],
        [f"warm, median of {RUNS - 1}", step, setup, total, 1e3 * step / n, total / TARGET],
        [f"whole command `python -m spindle.cli run runs/closed_loop_spring.toml --no-plot` in a fresh process "
         f"(imports, CSV; one run after one that warmed its numba cache, exit code {cli_code})", None, None, cli_time,
         None, cli_time / TARGET],
    ]  # fmt: skip
    met = total <= TARGET and cli_time <= TARGET
    values = dict(n=n, runs=RUNS, warm=", ".join(f"{r.wall_time:.3f}" for r in warm), step=1e3 * step / n,
                  verdict="met" if met else "missed", total=total, cli=cli_time, target=TARGET, pairs=PAIRS,
                  calls=len(recorder.calls), cpu=1e3 * cpu, floor=1e3 * floor, ratio=ratio, share=floor / cpu,
                  ratio_target=FLOOR_RATIO_TARGET, list=", ".join(f"{a / b:.2f}" for a, b in pairs),
                  kernels=", ".join(f"{k} {v}" for k, v in kernel_names(recorder.calls).items()))  # fmt: skip
    columns = ["run", "stepping (s)", "set-up (s)", "stepping + set-up (s)", "per step (ms)", f"vs target {TARGET:g} s"]
    blocks = [
        dict(table=dict(caption="## Timing against the target", columns=columns, formats=[None] + ["{:.3f}"] * 5,
                        rows=rows)),
        dict(text=STEP_TEXT, values=values),
        dict(text=FLOOR_TEXT, values=values),
    ]  # fmt: skip
    metrics = [
        metric("closed-loop step / replayed-kernel floor", ratio, "1", "timing", FLOOR_RATIO_TARGET, side_by_side=True),
        metric("1 h at H = 1 s, warm (stepping + set-up)", total, "s", "timing", target=TARGET),
    ]
    return blocks, metrics, results[-1].columns


STEP_TEXT = """Individual warm runs (stepping, s): {warm}. Per step ({step:.2f} ms, {n} steps per run): two bearing \
doSteps (quasi-static solve at 10 000 rpm, docs/reports/fmu_startup.md), one spindle doStep (exact exponential update \
of the network) and the transfers of the connections through fmpy. **Target {verdict}: {total:.2f} s warm, {cli:.1f} s \
for the whole command, target {target:g} s.**"""

FLOOR_TEXT = """## Step cost against the compiled-kernel floor

The same run once more with every kernel call recorded (`benchmarks/kernel_replay.py`), then those {calls} calls \
(the few made at initialisation included) replayed alone, in order, on fresh copies of their arguments: the cost of \
the run with no Python between the kernels. {pairs} pairs of a run and a replay right after it, medians, both in \
this process's CPU time (`RunResult.cpu_time`, `time.process_time`), which other processes do not lengthen.

| | CPU time per step (ms) |
|---|---|
| closed-loop step (stepping only) | {cpu:.3f} |
| replayed kernels (floor) | {floor:.3f} |
| step / floor (median of the pairs' ratios) | **{ratio:.2f}** (target <= {ratio_target}) |
| the pairs' ratios | {list} |

Kernel calls per run: {kernels}. The compiled kernels are {share:.0%} of a step; the rest is the FMU layer (the \
FMI layer's C-to-Python calls and the slaves' getters and setters, the facades' input checks and output tables) \
and the master's fmpy calls."""


def measure():
    timing_blocks, metrics, c = timing()
    coarse = run(load_run(RUN, {"run.step": 10.0})).columns
    return dict(
        name="closed_loop",
        title="Closed loop: one hour at H = 1 s and its physics at t = 3600 s",
        about=__doc__.split("Run:")[0],
        blocks=timing_blocks + physics(c, coarse) + [dict(figure=figure(c))],
        metrics=metrics,
    )


def physics(c, coarse):
    """Blocks of the energy balance and the temperatures at the end of the run."""
    t, temps = c["time"], [k for k in c if k.startswith("spindle.T_")]
    k_settle = int(np.argmin(np.abs(t - (t[-1] - SETTLE))))
    k_prev = int(np.argmin(np.abs(t - (t[-1] - 60.0))))
    model = SpindleThermalModel("b7214c_x_pair")  # steady state with the final heat inputs held
    heat = {f"Q_{ring}_ring_{i}": c[f"bearing_{i}.Q_{ring}_ring"][-1] for i in (1, 2) for ring in ("inner", "outer")}
    ss = model.steady_state(omega=OMEGA, T_ambient=T_AMBIENT, T_coolant=T_AMBIENT, P_motor=0.0, **heat)
    tau = model.time_constants(OMEGA)
    P_in, P_out, E = c["spindle.P_in"][-1], c["spindle.P_out"][-1], c["spindle.E_stored"]
    dEdt = (E[-1] - E[k_prev]) / (t[-1] - t[k_prev])
    energy = [
        ["P_in (heat of both bearings, W)", P_in],
        ["P_out (heat into coolant and ambient, W)", P_out],
        ["(P_in - P_out) / P_in (%)", 100 * (P_in - P_out) / P_in],
        ["dE_stored/dt over the last 60 s (W)", dEdt],
        ["P_in - P_out - dE_stored/dt (W)", P_in - P_out - dEdt],
        *[[f"bearing_{i} loss P_loss (W)", c[f"bearing_{i}.P_loss"][-1]] for i in (1, 2)],
        *[[f"bearing_{i} torque (N.m)", c[f"bearing_{i}.torque"][-1]] for i in (1, 2)],
    ]
    rows = []
    for name in temps:
        T, T_ss = c[name], ss[name.split(".", 1)[1]]
        rate = (T[-1] - T[k_prev]) / (t[-1] - t[k_prev]) * 60.0
        rows.append([name.split(".", 1)[1], T[-1], T[-1] - T_AMBIENT, T[-1] - T[k_settle], rate, T_ss, T_ss - T[-1],
                     coarse[name][-1] - T[-1]])  # fmt: skip
    T_or = c["spindle.T_outer_ring_1"]
    rise, last = T_or[-1] - T_AMBIENT, T_or[-1] - T_or[k_settle]
    change = max(abs(c[k][-1] - c[k][k_settle]) for k in temps)
    values = dict(
        storage=(P_in - P_out) / P_in, tau0=tau[0] / 60, tau1=tau[1] / 60, closure=abs(P_in - P_out - dEdt),
        last=last, last_share=last / rise, change=change, hours=3600.0 / tau[0], rise=rise,
        remaining=ss["T_outer_ring_1"] - T_or[-1], coupling=max(abs(coarse[k][-1] - c[k][-1]) for k in temps),
        rise_2=c["spindle.T_outer_ring_2"][-1] - T_AMBIENT, band=RABREAU_MODEL_VS_RIG,
        low=(1 - RABREAU_MODEL_VS_RIG) * rise, high=(1 + RABREAU_MODEL_VS_RIG) * rise,
        settled="practically settled after one hour" if change < 0.01 * rise else "not settled after one hour",
    )  # fmt: skip
    return [
        dict(table=dict(caption="## Energy balance at t = 3600 s", columns=["quantity", "value"],
                        formats=[None, "{:.4g}"], rows=energy)),
        dict(text=ENERGY_TEXT, values=values),
        dict(table=dict(caption=TEMPERATURE_TEXT, columns=TEMPERATURE_COLUMNS, rows=rows,
                        formats=[None, "{:.2f}", "{:.2f}", "{:.3f}", "{:.4f}", "{:.2f}", "{:.2f}", "{:+.4f}"])),
        dict(text=SETTLING_TEXT, values=values),
    ]  # fmt: skip


ENERGY_TEXT = """After one hour {storage:.2%} of the heat still goes into storage (mostly housing and shaft: the \
slowest time constants of the network at 10 000 rpm are {tau0:.1f} and {tau1:.1f} min); the stored-energy rate \
closes the balance to {closure:.2g} W (the difference is the 60 s difference quotient against the instantaneous \
powers)."""

TEMPERATURE_TEXT = """## Temperature rises at t = 3600 s and settling

Rise = T(3600 s) - 293.15 K. Last 10 min = T(3600 s) - T(3000 s). Steady state = \
`SpindleThermalModel('b7214c_x_pair').steady_state(...)` with the bearings' final heat inputs held (the heat still \
falls slowly as the oil warms, so the coupled steady state is slightly lower). H = 10 s: the same run at H = 10 s \
minus this one at t = 3600 s."""

TEMPERATURE_COLUMNS = ["temperature", "T (K)", "rise (K)", "change, last 10 min (K)", "rate at the end (K/min)",
                       "steady state, final heat (K)", "remaining (K)", "H = 10 s minus H = 1 s (K)"]  # fmt: skip

SETTLING_TEXT = """- Settling: over the last 10 minutes the outer ring rises by {last:.2f} K ({last_share:.2%} of its \
rise); every node changes by at most {change:.2g} K in that time: {settled} ({hours:.1f} of the slowest time \
constants). Holding the final heat, the network would end {remaining:.3f} K above the 1 h value at the outer ring.
- Co-simulation step: at t = 3600 s the run at H = 10 s differs from H = 1 s by at most {coupling:.1e} K (the \
coupling error of the transient, docs/reports/cosim_error.md, has died out).
- Magnitude: outer-ring rise {rise:.1f} K after one hour (bearing 2: {rise_2:.1f} K); Rabreau et al. (2018) report \
rises of tens of K at 10 000 rpm and a difference of {band:.0%} in temperature between their model and their rig. \
With no measured curve (theirs are not tabulated) that is a plausibility statement only: a band of that width \
around this rise is {low:.1f}-{high:.1f} K. The network's capacities and conductances are estimates \
(spindle/thermal/params/b7214c_x_pair.toml), so this is a consistency check of the loop, not a validation."""


def figure(c, stride=10):
    """Temperature rises and powers over the run (every `stride`-th sample)."""
    minutes = list(c["time"][::stride] / 60.0)
    rises = [dict(x=minutes, y=list(c[k][::stride] - T_AMBIENT), label=k.split(".", 1)[1], style="-")
             for k in c if k.startswith("spindle.T_")]  # fmt: skip
    powers = [dict(x=minutes, y=list(c[f"spindle.{k}"][::stride]), label=label, style="-")
              for k, label in (("P_in", "P_in (bearing heat)"), ("P_out", "P_out (to coolant + ambient)"))]  # fmt: skip
    return dict(
        file="closed_loop.png",
        caption="temperatures and powers",
        title="closed_loop_spring.toml, H = 1 s: temperature rises and energy balance",
        size=(12, 4.5),
        panels=[
            dict(xlabel="time (min)", ylabel="T - 293.15 K (K)", series=rises),
            dict(xlabel="time (min)", ylabel="W", series=powers, ylim=[0, 1.1 * float(np.max(c["spindle.P_in"][5:]))]),
        ],
    )


def main(argv=None):
    cli(measure, "closed_loop")


if __name__ == "__main__":
    main()
