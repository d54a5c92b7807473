"""Time per DEM step (6208, 9 balls + 9 cage balls) and simulated time against wall time (targets of the
product: <= 1.2 us per step with the multirate tribology, <= 2 us with every per-contact quantity every step,
1 ms simulated <= 0.5 ms wall at the default time step), with a profile of where the time goes.

Operating point: the 6208 of Guessasma & Machado (2018), P_d = 0, F_r = 3 kN, 500 rad/s, guessasma_oil, steady rolling after the
start-up of the validation (2 ms at rest, 5 ms ramp, run to 30 ms). Each figure is the median over
REPEATS calls of advance() of STEPS steps each: one Python call per interval, so the per-call overhead
(input checks, outputs) is spread over STEPS steps. The machine is shared by several users: the CPU
time of the benchmark's thread (time.thread_time) measures the kernel's own cost; the wall time, which
includes the waits for a core, is reported beside it with the load average.
Run: python -m benchmarks.dem_timing [--base REV | --base-tree DIR] -> docs/reports/dem_timing.md
"""

import argparse
import io
import math
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np

from bearing_fmu.kernels.ball_dynamics import integrator as dyn
from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import REFRESH_INTERVAL, T_OIL_DEFAULT, DemModel

from .dem_timing_worker import F_R, OMEGA, steady_model
from .render import cli, metric

STEPS = 2000
REPEATS = 41
NEVER = 10**9  # a refresh interval longer than any run: contact law only
# the reference kernel timed beside this tree's: the DEM before the EHL traction curve, the rigid cage, the ring's
# tilts and its support (the state whose cost the product's targets were first measured on)
BASE_REV = "651f166"
ROOT = Path(__file__).resolve().parent.parent
WORKER = Path(__file__).resolve().parent / "dem_timing_worker.py"


def per_simulated_ms(model, repeats=REPEATS, dt=None):
    """(CPU, wall) medians (ms) to advance 1 ms of simulated time in one call, default refresh, at dt (s;
    None = the default time step)."""
    model.refresh_fixed, model.dt_fixed = None, dt
    cpu, wall = [], []
    for _ in range(repeats):
        c0, t0 = time.thread_time(), time.perf_counter()
        model.advance(model.time + 1e-3, omega=OMEGA, F_y=F_R)
        cpu.append((time.thread_time() - c0) * 1e3)
        wall.append((time.perf_counter() - t0) * 1e3)
    return statistics.median(cpu), statistics.median(wall)


class TreeWorker:
    """A process that runs one source tree's DEM (benchmarks/dem_timing_worker.py) and times advance() on
    command, so that two trees, each with its own `bearing_fmu`, are timed in one run."""

    def __init__(self, tree):
        env = dict(os.environ, PYTHONPATH=str(tree))
        # -c with the tree as the working directory: sys.path[0] is the tree, nothing of this one
        self.process = subprocess.Popen([sys.executable, "-c", WORKER.read_text()], cwd=tree, env=env,
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)  # fmt: skip

    def ready(self):
        """The worker's default time step (s), once its model is in steady rolling."""
        line = self.process.stdout.readline().split()
        if not line or line[0] != "ready":
            raise RuntimeError(f"DEM worker failed to start (exit {self.process.wait()})")
        return float(line[1])

    def advance(self, refresh, steps, dt):
        """(CPU, wall) time (s) of one advance() over `steps` steps of dt with a refresh every `refresh` steps."""
        self.process.stdin.write(f"{refresh} {steps} {dt!r}\n")
        self.process.stdin.flush()
        cpu, wall = self.process.stdout.readline().split()
        return float(cpu), float(wall)

    def close(self):
        self.process.stdin.write("\n")
        self.process.stdin.flush()
        self.process.wait()


def materialise(rev, into):
    """Extract the DEM's packages (bearing_fmu, bearing_fmu_common) of git revision rev of this repository into
    the directory into; returns it."""
    command = ["git", "-C", str(ROOT), "archive", "--format=tar", rev, "bearing_fmu", "bearing_fmu_common"]
    archive = subprocess.run(command, capture_output=True, check=True).stdout
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        if hasattr(tarfile, "data_filter"):
            tar.extractall(into, filter="data")
        else:  # Python without extraction filters: the archive is this repository's own
            tar.extractall(into)
    return Path(into)


def side_by_side(base_tree, configurations, steps=STEPS, repeats=REPEATS):
    """Per-step times (us) of this tree and of base_tree, each in a worker process, for each refresh interval of
    `configurations`, at this tree's default time step. The two trees take turns call by call (A B B A ...), so
    both medians draw on the same stretch of the shared machine's time. Returns (dt, {refresh: {"current": (CPU
    median, CPU min, wall median), "base": (...)}})."""
    workers = {"current": TreeWorker(ROOT), "base": TreeWorker(base_tree)}
    try:
        dt = workers["current"].ready()
        workers["base"].ready()
        results = {}
        for refresh in configurations:
            samples = {name: ([], []) for name in workers}
            for worker in workers.values():
                worker.advance(refresh, steps, dt)  # warm-up: the refresh phase, caches
            for r in range(repeats):
                order = ("current", "base") if r % 2 == 0 else ("base", "current")
                for name in order:
                    cpu, wall = workers[name].advance(refresh, steps, dt)
                    samples[name][0].append(cpu / steps * 1e6)
                    samples[name][1].append(wall / steps * 1e6)
            results[refresh] = {
                name: (statistics.median(cpu), min(cpu), statistics.median(wall))
                for name, (cpu, wall) in samples.items()
            }
    finally:
        for worker in workers.values():
            worker.close()
    return dt, results


def per_step_of_advance(model, dt, refresh, n=20000, runs=9):
    """Median CPU time (us) per step of the product's kernel advance (kernels.ball_dynamics.integrator.advance, the
    call DemModel.advance makes) over n steps of dt (s), the tribology refreshed every `refresh` steps, on copies of
    the model's state (each run goes on from where the last one stopped; a first call of one step compiles)."""
    m = {k: v.copy() for k, v in model.get_state().items() if isinstance(v, np.ndarray)}
    par = model.par.copy()
    par[s.P_REFRESH] = refresh
    state, params = tuple(m[k] for k in s.STATE_GROUP), (par, model.lubricant.array)
    status = np.zeros(s.ST_SIZE, dtype=np.int64)
    space = (model._work.copy(), model._acc.copy(), status)
    loads = (0.0, F_R, 0.0, 0.0, 0.0)

    def run(steps):
        dyn.advance(state, params, (steps, dt, OMEGA, OMEGA, loads, T_OIL_DEFAULT, math.inf), space)
        if status[s.ST_CODE] != s.STATUS_OK:  # a stopped run would time fewer steps than it divides by
            raise RuntimeError(f"the monitor stopped the timed run (status {status[s.ST_CODE]})")

    run(1)
    samples = []
    for _ in range(runs):
        c0 = time.thread_time()
        run(n)
        samples.append((time.thread_time() - c0) / n * 1e6)
    return statistics.median(samples)


def profile(model, dt):
    """Time (us) per step of the product's step with the tribology frozen and refreshed every step at the time
    step dt (s), and what a refresh adds (their difference)."""
    frozen, every = per_step_of_advance(model, dt, NEVER), per_step_of_advance(model, dt, 1)
    return [
        ("one step, tribology frozen (predictor, 18 ball-race and 27 cage contacts, corrector, the call's sums and "
         "checks)", frozen),
        ("one step with a tribology refresh", every),
        ("the refresh of 18 contacts (Hertz, film, Lambda, mu, C_n, Houpert, capacitance, the monitor's energy and "
         "damping checks): the difference", every - frozen),
    ]  # fmt: skip


def measure(base=BASE_REV, base_tree=None):
    with tempfile.TemporaryDirectory(prefix="dem-timing-base-") as scratch:
        tree = Path(base_tree) if base_tree else materialise(base, scratch)
        dt_probe = DemModel("6208", "guessasma_oil").automatic_time_step(F_y=F_R, omega=OMEGA)
        default_refresh = max(1, math.floor(REFRESH_INTERVAL / dt_probe * (1.0 + 1e-9)))  # DemModel's own rule
        configurations = (1, 10, default_refresh, NEVER)
        default_dt, timings = side_by_side(tree, configurations)
    model = steady_model()
    real_time, real_time_4us = per_simulated_ms(model), per_simulated_ms(model, dt=4e-6)
    model.dt_fixed = None
    names = {
        1: ("tribology every step", "<= 2"),
        10: ("tribology every 10 steps (multirate)", "<= 1.2"),
        default_refresh: (
            f"tribology every {default_refresh} steps (default: every {REFRESH_INTERVAL * 1e6:g} us)",
            "",
        ),
        NEVER: ("contact law only (no refresh during the run)", ""),
    }
    rows = []
    for refresh in configurations:
        cur, ref = timings[refresh]["current"], timings[refresh]["base"]
        rows.append([names[refresh][0], *cur, ref[0], cur[0] / ref[0], names[refresh][1]])
    real = dict(steps_per_ms=1e-3 / default_dt, cpu=real_time[0], wall=real_time[1], target=0.5, steps_4us=1e-3 / 4e-6,
                cpu_4us=real_time_4us[0], wall_4us=real_time_4us[1])  # fmt: skip
    every, multirate = timings[1]["current"], timings[10]["current"]
    return dict(
        name="dem_timing",
        title="DEM timing (6208, 9 balls + 9 cage balls)",
        about=__doc__.split("Run:")[0],
        blocks=page(base_tree or base, default_dt, rows, real, profile(model, default_dt), default_refresh),
        metrics=[
            metric("step, tribology every step (CPU median)", 1e-6 * every[0], "s", "timing", target=2e-6),
            metric(
                "step, multirate tribology every 10 steps (CPU median)",
                1e-6 * multirate[0],
                "s",
                "timing",
                target=1.2e-6,
            ),
            metric("1 ms simulated at the default dt (wall)", 1e-3 * real_time[1], "s", "timing", target=0.5e-3),
        ],  # fmt: skip
    )


def page(base, dt, rows, real, parts, refresh):
    columns = ["configuration", "CPU median (us/step)", "CPU min (us/step)", "wall median (us/step)",
               "reference CPU median (us/step)", "ratio (CPU medians)", "target"]  # fmt: skip
    return [
        dict(
            text="Steady rolling at {omega:g} rad/s, F_r = {F_r:g} N, default time step {dt:.2f} us. Medians over "
            "{repeats} calls of advance() of {steps} steps each; CPU = the thread's CPU time (the kernel's own cost; "
            "its minimum is the best estimate of an uncontended core, the median still carries the other users' "
            "cache and hyper-thread pressure), wall = elapsed time (includes waiting for a core).",
            values=dict(omega=OMEGA, F_r=F_R, dt=dt * 1e6, repeats=REPEATS, steps=STEPS),
        ),
        dict(
            text="Beside it, in the same run, the reference kernel ({base}: the DEM before the EHL traction curve, "
            "the rigid cage, the ring's tilts and its support) at the same operating point and time step: each tree "
            "runs in a process of its own (benchmarks/dem_timing_worker.py) and the two take turns call by call, so "
            "that both medians draw on the same stretch of the machine's time.",
            values=dict(base=base),
        ),
        dict(table=dict(columns=columns, formats=[None] + ["{:.2f}"] * 5 + [None], rows=rows)),
        dict(
            text="1 ms simulated at the default dt ({steps_per_ms:.0f} steps, default refresh) in one call: CPU "
            "{cpu:.3f} ms, wall {wall:.3f} ms (target <= {target:g} ms). At dt = 4 us ({steps_4us:.0f} steps): CPU "
            "{cpu_4us:.3f} ms, wall {wall_4us:.3f} ms.",
            values=real,
        ),
        dict(text="## Where the time goes (CPU time per step of the product's kernel, on copies of the steady state)"),
        dict(table=dict(columns=["part", "CPU (us)"], formats=[None, "{:.3f}"], rows=parts)),
        dict(
            text="Each row times the kernel advance() of kernels.ball_dynamics.integrator (the call DemModel.advance "
            "makes, without its input checks and outputs) over 20 000 steps at the default time step, median of 9 "
            "runs: with the tribology frozen (no refresh during the run) and with a refresh before every step. Their "
            "difference is what a refresh costs; at the default interval a step pays 1/{refresh} of it.",
            values=dict(refresh=refresh),
        ),
    ]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", default=BASE_REV, help="git revision of the reference kernel (default %(default)s)")
    parser.add_argument("--base-tree", help="a source tree of the reference instead (its bearing_fmu is timed)")
    args = parser.parse_args(argv)
    cli(measure, "dem_timing", base=args.base, base_tree=args.base_tree)


if __name__ == "__main__":
    main()
