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
2018 do not tabulate theirs): the outer-ring rise is set against a plausibility band only (tens of K after Rabreau et al. 2018).
Run: python -m benchmarks.closed_loop -> docs/reports/closed_loop.md and .png
"""

import os
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

from .common import REPORTS, machine, record, write_report
from .kernel_replay import KernelRecorder, kernel_names, replay_time

ROOT = Path(__file__).resolve().parent.parent
RUN = ROOT / "runs" / "closed_loop_spring.toml"
RUNS = 4  # the first warms the cache; medians over the other three
PAIRS = 15  # closed-loop runs each followed by a replay of its kernels (CPU time); the ratio of one pair
# varies 1.4-2.3 with the shared machine's speed phases, so the median needs more than a handful
TARGET = 10.0  # s, docs/architecture.md (performance budget)
T_AMBIENT = 293.15  # K
OMEGA = 1047.1975511965977
SETTLE = 600.0  # s, "last 10 minutes"
FLOOR_RATIO_TARGET = 1.5  # closed-loop step / replayed-kernel floor (docs/architecture.md, performance budget)
# the same measurement on the FMU layer before it was thinned (per-call output dicts, per-variable getters,
# name look-ups in the master every step): this benchmark run on that code, CPU times, load average 4 to 6
BEFORE = "a step of 0.593 ms of CPU time against a floor of 0.154 ms: 3.86 x (kernels 26 % of a step)"
# and once thinned, before the thermal step became two kernel calls and the FMI layer stopped building a method
# name, an argument tuple and a value-reference list per call: this benchmark on that code, load average 1.06
PREVIOUS = "0.331 ms against 0.207 ms: 1.60 x (pairs 1.47, 1.76, 1.30, 1.66, 1.60)"


def cli_wall():
    """Wall time of the whole `spindle run` command in a fresh process (s), and its exit code."""
    with tempfile.TemporaryDirectory() as out:
        t0 = time.perf_counter()
        proc = subprocess.run(
            [sys.executable, "-m", "spindle.cli", "run", str(RUN), "--no-plot", "--out", out],
            cwd=ROOT,
            capture_output=True,
            text=True,
        )
        return time.perf_counter() - t0, proc.returncode


def main():
    t_start = time.perf_counter()
    load_before = os.getloadavg()[0]
    spec = load_run(RUN)
    results = [run(load_run(RUN)) for _ in range(RUNS)]
    for r in results:
        if r.status != "ok":
            raise RuntimeError(f"{r.status}: {r.message}")
    first, warm = results[0], results[1:]
    step_med = statistics.median(r.wall_time for r in warm)
    setup_med = statistics.median(r.setup_time for r in warm)
    total_med = statistics.median(r.wall_time + r.setup_time for r in warm)
    n = spec.n_steps
    with KernelRecorder() as recorder:  # the same run once more, every kernel call recorded
        run(load_run(RUN))
    pairs = []  # (CPU time per step of a run, of the replayed kernels right after it): same conditions
    for _ in range(PAIRS):
        pairs.append((run(load_run(RUN)).cpu_time / n, replay_time(recorder.calls, repeats=1) / n))
    step = statistics.median(p[0] for p in pairs)
    floor = statistics.median(p[1] for p in pairs)
    ratio = statistics.median(p[0] / p[1] for p in pairs)
    record(
        "closed_loop",
        "closed-loop step / replayed-kernel floor",
        ratio,
        "1",
        kind="timing",
        target=FLOOR_RATIO_TARGET,
        side_by_side=True,
    )
    record("closed_loop", "1 h at H = 1 s, warm (stepping + set-up)", total_med, "s", kind="timing", target=TARGET)
    cli_wall()  # fills the numba cache of the FMUs' own bundled sources, which a fresh process uses
    cli_time, cli_code = cli_wall()
    coarse = run(load_run(RUN, {"run.step": 10.0}))

    c = results[-1].columns
    t = c["time"]
    temps = [k for k in c if k.startswith("spindle.T_")]
    k_end = len(t) - 1
    k_settle = int(np.argmin(np.abs(t - (t[-1] - SETTLE))))
    k_prev = int(np.argmin(np.abs(t - (t[-1] - 60.0))))

    # steady state of the network with the final heat inputs held
    model = SpindleThermalModel("b7214c_x_pair")
    heat = {
        "Q_inner_ring_1": c["bearing_1.Q_inner_ring"][-1],
        "Q_outer_ring_1": c["bearing_1.Q_outer_ring"][-1],
        "Q_inner_ring_2": c["bearing_2.Q_inner_ring"][-1],
        "Q_outer_ring_2": c["bearing_2.Q_outer_ring"][-1],
    }
    ss = model.steady_state(omega=OMEGA, T_ambient=T_AMBIENT, T_coolant=T_AMBIENT, P_motor=0.0, **heat)
    tau = model.time_constants(OMEGA)

    lines = [
        "# Closed loop: one hour at H = 1 s and its physics at t = 3600 s",
        "",
        f"Generated by `python -m benchmarks.closed_loop` on {machine()} (2 cores); load average "
        f"{load_before:.2f} at the start. Whole benchmark: {time.perf_counter() - t_start:.0f} s.",
        "",
        "Run: `runs/closed_loop_spring.toml` unchanged: two B7214C in X arrangement, 800 N spring preload, "
        "10 000 rpm, ISO VG68 oil-air, spindle network `b7214c_x_pair`, Gauss-Seidel, **H = 1 s, 3600 s "
        f"({n} steps)**, through `spindle.cosim.master.run(load_run(path))`, {RUNS} times in one process. The "
        "first run loads the compiled kernels from the numba cache on disk (warm on-disk cache: the FMUs "
        "were run before; a first-ever compile is ~20 s, docs/reports/fmu_startup.md) and is reported on "
        f"its own; the medians are over the other {RUNS - 1}. Stepping = `RunResult.wall_time`; set-up = "
        "`RunResult.setup_time` (extraction of the FMUs, instantiation, initialisation).",
        "",
        "## Timing against the target",
        "",
        "| run | stepping (s) | set-up (s) | stepping + set-up (s) | per step (ms) | vs target 10 s |",
        "|---|---|---|---|---|---|",
        f"| first in the process (loads the numba cache) | {first.wall_time:.3f} | {first.setup_time:.3f} | "
        f"{first.wall_time + first.setup_time:.3f} | {1e3 * first.wall_time / n:.3f} | "
        f"{(first.wall_time + first.setup_time) / TARGET:.3f} |",
        f"| warm, median of {RUNS - 1} | {step_med:.3f} | {setup_med:.3f} | {total_med:.3f} | "
        f"{1e3 * step_med / n:.3f} | {total_med / TARGET:.3f} |",
        f"| whole command `python -m spindle.cli run runs/closed_loop_spring.toml --no-plot` in a fresh "
        f"process (imports, CSV; one run after one that warmed its numba cache, exit code {cli_code}) "
        f"| - | - | {cli_time:.2f} | - | "
        f"{cli_time / TARGET:.3f} |",
        "",
        f"Individual warm runs (stepping, s): {', '.join(f'{r.wall_time:.3f}' for r in warm)}. "
        f"Per step ({1e3 * step_med / n:.2f} ms): two bearing doSteps (quasi-static solve at 10 000 rpm, "
        "docs/reports/fmu_startup.md), one spindle doStep (exact exponential update of the "
        "8-node network) and the transfers of 8 connections through fmpy.",
        f"**Target met: {total_med:.2f} s <= {TARGET:g} s warm, {cli_time:.1f} s for the whole command.**"
        if total_med <= TARGET and cli_time <= TARGET
        else f"**Target missed: {total_med:.2f} s warm, {cli_time:.1f} s for the whole command, target {TARGET:g} s.**",
        "",
        "## Step cost against the compiled-kernel floor",
        "",
        "The same run once more with every kernel call recorded (`benchmarks/kernel_replay.py`: each numba "
        "kernel the facades call, with its array arguments copied before the call), then those "
        f"{len(recorder.calls)} calls replayed alone, in order, on fresh copies: the cost of the "
        f"run with no Python between the kernels; {PAIRS} pairs of a run and a replay right after it, medians. "
        "The few calls made at initialisation are included (they make the floor slightly larger). Both "
        "are this process's CPU time (`RunResult.cpu_time`, "
        "`time.process_time`), which other processes on the 2 shared cores do not lengthen; the wall "
        f"time per step above was {1e3 * step_med / n:.3f} ms.",
        "",
        "| | CPU time per step (ms) |",
        "|---|---|",
        f"| closed-loop step (stepping only) | {1e3 * step:.3f} |",
        f"| replayed kernels (floor) | {1e3 * floor:.3f} |",
        f"| step / floor (median of the pairs' ratios) | **{ratio:.2f}** (target <= {FLOOR_RATIO_TARGET}) |",
        f"| the pairs' ratios | {', '.join(f'{a / b:.2f}' for a, b in pairs)} |",
        "",
        f"Kernel calls per run: {', '.join(f'{k} {v}' for k, v in kernel_names(recorder.calls).items())}. "
        f"The compiled kernels are {100 * floor / step:.0f} % of a step; the rest is the FMU layer "
        "(the FMI layer's C-to-Python calls and the slaves' getters and setters, the facades' input checks and output tables) and the master's "
        "fmpy calls. Before the FMU layer was thinned (outputs in a preallocated array read by "
        "precomputed index, input and output tables built once, the master's value references resolved "
        f"once and transferred in batches), the same measurement gave {BEFORE}. With the thermal step still "
        "nine kernel calls with Python between them (input dicts, output slots filled one by one) and the "
        "FMI layer calling the slaves by method-name strings with a new value-reference list per call, it "
        f"gave {PREVIOUS}; the thermal step is now two kernel calls (spindle.thermal.network.exponential_update "
        "and network_outputs), which also takes its dispatch cost out of the floor.",
        "",
    ]

    # energy balance
    P_in, P_out = c["spindle.P_in"][-1], c["spindle.P_out"][-1]
    E = c["spindle.E_stored"]
    dEdt = (E[k_end] - E[k_prev]) / (t[k_end] - t[k_prev])
    lines += [
        "## Energy balance at t = 3600 s",
        "",
        "| quantity | value |",
        "|---|---|",
        f"| P_in (heat of both bearings, W) | {P_in:.2f} |",
        f"| P_out (heat into coolant and ambient, W) | {P_out:.2f} |",
        f"| (P_in - P_out) / P_in | {100 * (P_in - P_out) / P_in:.2f} % |",
        f"| dE_stored/dt over the last 60 s (W) | {dEdt:.2f} |",
        f"| P_in - P_out - dE_stored/dt (W) | {P_in - P_out - dEdt:+.3f} |",
        f"| bearing_1 / bearing_2 loss P_loss (W) | {c['bearing_1.P_loss'][-1]:.2f} / "
        f"{c['bearing_2.P_loss'][-1]:.2f} |",
        f"| bearing_1 / bearing_2 torque (N.m) | {c['bearing_1.torque'][-1]:.4f} / {c['bearing_2.torque'][-1]:.4f} |",
        "",
        f"After one hour {100 * (P_in - P_out) / P_in:.2f} % of the heat still goes into storage (mostly "
        f"housing and shaft: the slowest time constants of the network at 10 000 rpm are "
        f"{tau[0] / 60:.1f} and {tau[1] / 60:.1f} min); the stored-energy rate closes the balance to "
        f"{abs(P_in - P_out - dEdt):.2g} W (the difference is the 60 s difference quotient against the "
        "instantaneous powers).",
        "",
    ]

    # temperature rises and settling
    lines += [
        "## Temperature rises at t = 3600 s and settling",
        "",
        "Rise = T(3600 s) - 293.15 K. Last 10 min = T(3600 s) - T(3000 s). Steady state = "
        "`SpindleThermalModel('b7214c_x_pair').steady_state(...)` with the bearings' final heat inputs "
        "held (the heat still falls slowly as the oil warms, so the coupled steady state is slightly "
        "lower). H = 10 s: the same run at H = 10 s minus this one at t = 3600 s.",
        "",
        "| temperature | T (K) | rise (K) | change, last 10 min (K) | rate at the end (K/min) | "
        "steady state, final heat (K) | remaining (K) | H = 10 s minus H = 1 s (K) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for name in temps:
        short = name.split(".", 1)[1]
        T = c[name]
        rate = (T[k_end] - T[k_prev]) / (t[k_end] - t[k_prev]) * 60.0
        T_ss = ss[short]
        lines.append(
            f"| {short} | {T[-1]:.2f} | {T[-1] - T_AMBIENT:.2f} | {T[-1] - T[k_settle]:.3f} | {rate:.4f} | "
            f"{T_ss:.2f} | {T_ss - T[-1]:.2f} | {coarse.columns[name][-1] - T[-1]:+.4f} |"
        )
    rise_or = c["spindle.T_outer_ring_1"][-1] - T_AMBIENT
    last_or = c["spindle.T_outer_ring_1"][-1] - c["spindle.T_outer_ring_1"][k_settle]
    lines += [
        "",
        f"- Settling: over the last 10 minutes the outer ring rises by {last_or:.2f} K "
        f"({100 * last_or / rise_or:.2f} % of its rise); every node changes by less than "
        f"{max(c[k][-1] - c[k][k_settle] for k in temps):.2g} K in that time: "
        + (
            "practically settled after one hour (about 5.5 of the slowest time constants). "
            if max(abs(c[k][-1] - c[k][k_settle]) for k in temps) < 0.01 * rise_or
            else "not settled after one hour. "
        )
        + "Holding the final heat, the network would end "
        f"{ss['T_outer_ring_1'] - c['spindle.T_outer_ring_1'][-1]:.3f} K above the 1 h value at the outer "
        "ring.",
        f"- Co-simulation step: at t = 3600 s the run at H = 10 s differs from H = 1 s by at most "
        f"{max(abs(coarse.columns[k][-1] - c[k][-1]) for k in temps):.1e} K (the coupling error of the "
        "transient has died out; it was tens of K at t = 10 s for H = 10 s, docs/reports/cosim_error.md).",
        f"- Magnitude: outer-ring rise {rise_or:.1f} K after one hour "
        f"(bearing 2: {c['spindle.T_outer_ring_2'][-1] - T_AMBIENT:.1f} K), i.e. **tens of K**, the magnitude "
        "Rabreau et al. (2018) report at 10 000 rpm. They state that their model and their rig "
        "differ by ~12 % in temperature; with no measured curve (theirs are not tabulated) that is a "
        "plausibility statement only: a ±12 % band around this rise is "
        f"{0.88 * rise_or:.1f}-{1.12 * rise_or:.1f} K. The network's capacities and conductances are "
        "estimates (spindle/thermal/params/b7214c_x_pair.toml, tuned for 'a few tens of K' from ~1 kW), so this "
        "is a consistency check of the loop, not a validation.",
        "",
        "![temperatures and powers](closed_loop.png)",
    ]
    plot(c)
    write_report("closed_loop.md", "\n".join(lines) + "\n")


def plot(c):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.5))
    minutes = c["time"] / 60.0
    for name in c:
        if name.startswith("spindle.T_"):
            a1.plot(minutes, c[name] - T_AMBIENT, label=name.split(".", 1)[1])
    a1.set_xlabel("time (min)")
    a1.set_ylabel("T - 293.15 K (K)")
    a1.legend(fontsize=8)
    a1.grid(True, alpha=0.3)
    a2.plot(minutes, c["spindle.P_in"], label="P_in (bearing heat)")
    a2.plot(minutes, c["spindle.P_out"], label="P_out (to coolant + ambient)")
    a2.set_xlabel("time (min)")
    a2.set_ylabel("W")
    a2.set_ylim(0, 1.1 * np.max(c["spindle.P_in"][5:]))
    a2.legend()
    a2.grid(True, alpha=0.3)
    fig.suptitle("closed_loop_spring.toml, H = 1 s: temperature rises and energy balance")
    fig.tight_layout()
    fig.savefig(REPORTS / "closed_loop.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
