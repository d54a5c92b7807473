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
from numba import njit

from bearing_fmu.kernels.ball_dynamics import integrator as dyn
from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.kernels.ball_dynamics.cage import ball_cage_contact, cage_guide_contact
from bearing_fmu.kernels.ball_dynamics.contact_law import ball_race_contact, groove_approach
from bearing_fmu.kernels.ball_dynamics.tribology import TC_SIZE, race_circle, refresh_tribology, tribology_constants
from bearing_fmu.kernels.lubricant import LUB_EPS_R0, LUB_RHO_REF, clausius_mossotti_constant, lubricant_state
from bearing_fmu.models.dem import REFRESH_INTERVAL, DemModel

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


@njit
def _race_contacts(n, balls, ring, spring, trib, par, work, acc, dt):
    """n passes of the 18 ball-race contact laws (contacts.groove_approach, contacts.ball_race_contact) on one state,
    results summed (the state is not written: every pass sees the same contacts)."""
    total = 0.0
    steps = (0.5 * par[s.P_D], par[s.P_ALPHA_E], par[s.P_KT_RATIO], 4.0 * dt / par[s.P_I_BALL],
             2.0 * par[s.P_V_REG] / par[s.P_D], dt)  # fmt: skip
    kappa = par[s.P_FILM_RATE] * dt / par[s.P_M_BALL]
    for _ in range(n):
        for race in range(2):
            cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
            frame = (OMEGA, acc[s.A_VR], acc[s.A_VR + 1], acc[s.A_VR + 2], cx, cy, cz, par[s.P_KH_I + race], ax, ay,
                     az, acc[s.A_WR], acc[s.A_WR + 1])  # fmt: skip
            row = 3 * race
            geo = s.W_GEOM + 4 * race
            for j in range(balls.shape[1]):
                delta, nx, ny, nz = groove_approach(
                    balls[s.B_X, j], balls[s.B_X + 1, j], balls[s.B_X + 2, j], cx, cy, cz, ax, ay, az, rho,
                    par[s.P_RG_I + race],
                )  # fmt: skip
                work[geo, j] = delta
                work[geo + 1, j] = nx
                work[geo + 2, j] = ny
                work[geo + 3, j] = nz
            for j in range(balls.shape[1]):
                result = ball_race_contact(
                    race, (work[geo, j], work[geo + 1, j], work[geo + 2, j], work[geo + 3, j]), balls[s.B_X, j],
                    balls[s.B_X + 1, j], balls[s.B_X + 2, j], work[s.W_VB, j], work[s.W_VB + 1, j],
                    work[s.W_VB + 2, j], work[s.W_WB, j], work[s.W_WB + 1, j], work[s.W_WB + 2, j], work[s.W_ORBIT, j],
                    spring[row, j], spring[row + 1, j], spring[row + 2, j], trib[s.T_MU, race, j],
                    int(trib[s.T_REGIME, race, j]), trib[s.T_C_N, race, j], trib[s.T_F_ROLL, race, j],
                    trib[s.T_M_SPIN, race, j], (trib[s.T_PHI, race, j], trib[s.T_SLIP, race, j], par[s.P_MU_LIM], kappa),
                    frame, steps,
                )  # fmt: skip
                total += result[1] + result[4] + result[12]
    return total


@njit
def _cage_contacts(n, balls, cage, par, work):
    """n passes of the 18 ball - cage-ball and 9 guide contact laws (cage.*) on one state, results summed."""
    total = 0.0
    Z = balls.shape[1]
    R_sum = 0.5 * par[s.P_D] + par[s.P_R_CAGE]
    for _ in range(n):
        for k in range(Z):
            for side in range(2):
                j = (k + side) % Z
                f = ball_cage_contact(
                    cage[s.C_X, k] - balls[s.B_X, j], cage[s.C_X + 1, k] - balls[s.B_X + 1, j],
                    cage[s.C_X + 2, k] - balls[s.B_X + 2, j], work[s.W_VB, j] - work[s.W_VC, k],
                    work[s.W_VB + 1, j] - work[s.W_VC + 1, k], work[s.W_VB + 2, j] - work[s.W_VC + 2, k],
                    R_sum, par[s.P_K_CB], par[s.P_C_CB],
                )  # fmt: skip
                total += f[0]
            f = cage_guide_contact(
                cage[s.C_X, k], cage[s.C_X + 1, k], cage[s.C_X + 2, k], work[s.W_VC, k], work[s.W_VC + 1, k],
                work[s.W_VC + 2, k], par[s.P_R_GUIDE], par[s.P_Z_GUIDE], par[s.P_GUIDE_GAP], par[s.P_K_GUIDE],
                par[s.P_C_GUIDE],
            )  # fmt: skip
            total += f[0]
    return total


# verlet_step is inlined into its caller and compiled with the caller's error model: advance's (numpy), as here
@njit(error_model="numpy")
def _steps(n, balls, cage, ring, spring, trib, counters, par, work, acc, dt):
    """n Verlet steps from the state (the tribology frozen: the contact law only)."""
    for _ in range(n):
        dyn.verlet_step(balls, cage, ring, spring, trib, counters, par, OMEGA, 0.0, F_R, 0.0, 0.0, 0.0, dt, work, acc)


@njit
def _refreshes(n, balls, ring, par, trib, lub):
    eta, xi, rho0 = lubricant_state(313.15, lub)
    K_cm = clausius_mossotti_constant(lub[LUB_EPS_R0], lub[LUB_RHO_REF])
    tc = np.empty((TC_SIZE, 2))
    tribology_constants(par, eta, xi, tc)
    geo = np.empty((4, balls.shape[1]))
    for _ in range(n):
        refresh_tribology(OMEGA, eta, xi, K_cm, rho0, balls, ring, par, trib, tc, geo)


def profile(model, n=20000):
    """Time (us) of one pass of each part of a step on copies of a steady state (median of 9 runs of n)."""
    m = {k: v.copy() for k, v in model.get_state().items() if isinstance(v, np.ndarray)}
    work, acc, par = model._work.copy(), model._acc.copy(), model.par
    dt = model.dt
    state = (m["balls"], m["cage"], m["ring"], m["spring"], m["trib"], m["counters"], par, work, acc, dt)
    parts = {
        "one Verlet step (predictor, 18 ball-race and 27 cage contacts, corrector; the function advance calls)": (
            _steps, state),
        "of which the 18 ball-race contact laws (normal, damping, tangential spring, resistances)": (
            _race_contacts, (m["balls"], m["ring"], m["spring"], m["trib"], par, work, acc, dt)),
        "of which the 9 cage balls (18 ball - cage-ball pairs, 9 guide contacts)": (
            _cage_contacts, (m["balls"], m["cage"], par, work)),
        "tribology refresh of 18 contacts (Hertz, film, Lambda, mu, C_n, Houpert, capacitance)": (
            _refreshes, (m["balls"], m["ring"], par, m["trib"], model.lubricant.array)),
    }  # fmt: skip
    rows = []
    for name, (fn, args) in parts.items():
        fn(1, *args)
        samples = []
        for _ in range(9):
            c0 = time.thread_time()
            fn(n, *args)
            samples.append((time.thread_time() - c0) / n * 1e6)
        rows.append((name, statistics.median(samples)))
    return rows


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
        blocks=page(base_tree or base, default_dt, rows, real, profile(model), default_refresh),
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
        dict(text="## Where the time goes (CPU time of one pass each, jitted loops over copies of the steady state)"),
        dict(table=dict(columns=["part", "CPU (us)"], formats=[None, "{:.3f}"], rows=parts)),
        dict(
            text="The Verlet step is the function advance() calls once per step (run here with the tribology frozen); "
            "the two contact rows are the contact laws alone, called on one state from a jitted loop (what the step "
            "adds to them: reading and writing the state arrays, the predictor and corrector of the bodies, the "
            "orbital-angle bookkeeping and the monitor's checks). A refresh at the default interval costs "
            "1/{refresh} of its row per step.",
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
