"""Memory of the co-simulation master: flat in run length and in the number of FMU instances.

1. Run length: the closed-loop demo (runs/closed_loop_spring.toml: two Bearing.fmu + SpindleThermal.fmu)
   at a 10 ms communication step, in a fresh process per recording mode, RSS sampled every 0.5 s by a
   thread. The slope of RSS over simulated time (least squares over the second half of the run, after
   the start-up) projects the RSS of a 24 h run at 10 ms (8.64 million steps):
   - `csv`: every step streamed to a CSV file (what `spindle run` does);
   - `arrays`: recorded every 1 s into preallocated arrays (Master.run(record_interval=1.0)).
2. Instances: three blocks of 1000 instantiate / initialise / terminate / free cycles of Bearing.fmu in
   one fmpy host (the FMU extracted once), RSS after 20 warm-up cycles and after each block. A leak
   grows RSS by the same amount in every block; a one-time cost (allocator arenas, caches filled on
   first use) only in the first.
Targets (docs/architecture.md): RSS of the 24 h run within 200 MB of its start; 1000 cycles < 5 MB.

    python -m benchmarks.master_memory [--seconds 600] [--cycles 1000]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

from .render import cli, metric

ROOT = Path(__file__).resolve().parent.parent
DEMO = ROOT / "runs" / "closed_loop_spring.toml"
BEARING_FMU = ROOT / "fmus" / "Bearing.fmu"
STEP = 0.01  # s, communication step of the projected run
DAY = 86400.0  # s, length of the projected run
PAGE = os.sysconf("SC_PAGE_SIZE")
WARM_UP = 20  # create/free cycles before the first RSS sample


def rss_mb():
    """Resident set size of this process (MB, 1e6 bytes) from /proc/self/statm."""
    with open("/proc/self/statm") as fh:
        return int(fh.read().split()[1]) * PAGE / 1e6


def sample_rss(samples, done, interval=0.5):
    """Append (wall time s, RSS MB) to samples every `interval` seconds until `done` is set."""
    t0 = time.perf_counter()
    while not done.is_set():
        samples.append((time.perf_counter() - t0, rss_mb()))
        done.wait(interval)


def child_run(mode, seconds):
    """One demo run of `seconds` simulated at STEP; prints JSON: RSS samples against simulated time."""
    from spindle.cosim.master import Master
    from spindle.cosim.runfile import load_run

    spec = load_run(str(DEMO), {"run.stop": seconds, "run.step": STEP})
    with tempfile.TemporaryDirectory(prefix="master_memory_") as tmp, Master(spec) as master:
        samples, done = [], threading.Event()
        sampler = threading.Thread(target=sample_rss, args=(samples, done), daemon=True)
        start_rss = rss_mb()
        sampler.start()
        t0 = time.perf_counter()
        result = master.run(csv_path=Path(tmp) / "run.csv") if mode == "csv" else master.run(record_interval=1.0)
        wall = time.perf_counter() - t0
        done.set()
        sampler.join()
    # wall time -> simulated time: the stepping is uniform, so scale by the stepping share of the call
    setup = wall - result.wall_time
    samples = [(max(0.0, (w - setup) / result.wall_time) * seconds, r) for w, r in samples]
    print(json.dumps({"start_rss": start_rss, "samples": samples, "rows": result.n_rows, "steps": result.n_steps}))


def child_cycles(cycles, blocks=3):
    """`blocks` blocks of `cycles` create/free cycles of Bearing.fmu; prints JSON: RSS after the warm-up
    and after each block, and the seconds per cycle."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    md, unzip = read_model_description(str(BEARING_FMU)), extract(str(BEARING_FMU))

    def cycle(k):
        slave = FMU2Slave(
            guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName=f"b{k}"
        )
        slave.instantiate()
        slave.setupExperiment(startTime=0.0)
        slave.enterInitializationMode()
        slave.exitInitializationMode()
        slave.doStep(0.0, 0.01)
        slave.terminate()
        slave.freeInstance()

    for k in range(WARM_UP):
        cycle(k)
    rss, t0 = [rss_mb()], time.perf_counter()
    for block in range(blocks):
        for k in range(cycles):
            cycle(WARM_UP + block * cycles + k)
        rss.append(rss_mb())
    print(json.dumps({"rss": rss, "seconds": (time.perf_counter() - t0) / (blocks * cycles)}))


def in_child(*args):
    command = [sys.executable, "-m", "benchmarks.master_memory", "--child", *map(str, args)]
    proc = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"{args} exited {proc.returncode}: {proc.stderr[-2000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def slope_per_hour(samples):
    """Least-squares slope (MB per simulated hour) of RSS over the second half of the run."""
    t, r = np.array(samples).T
    half = t >= 0.5 * t[-1]
    return float(np.polyfit(t[half], r[half], 1)[0]) * 3600.0


def measure(seconds=600.0, cycles=1000):
    runs = []
    for mode, label in (("csv", "every step streamed to CSV"), ("arrays", "every 1 s into preallocated arrays")):
        out = in_child(mode, seconds)
        rss, slope = [r for _, r in out["samples"]], slope_per_hour(out["samples"])
        projected = rss[-1] + slope * (DAY - seconds) / 3600.0 - out["start_rss"]
        runs.append([label, out["start_rss"], max(rss), rss[-1], slope, projected, out["rows"]])
    blocks = in_child("cycles", cycles)
    rss = blocks["rss"]
    growth = [b - a for a, b in zip(rss, rss[1:])]
    cycle_rows = [[k + 1, f"{k * cycles + 1}-{(k + 1) * cycles}", rss[k + 1], g] for k, g in enumerate(growth)]
    values = dict(seconds=seconds, steps=round(seconds / STEP), step=1e3 * STEP, day_steps=DAY / STEP, cycles=cycles,
                  warm_up=WARM_UP, warm_rss=rss[0], per_cycle=blocks["seconds"])  # fmt: skip
    return dict(
        name="master_memory",
        title="Master memory: flat in run length and in instance count",
        about=__doc__.split("\n", 2)[2].split("    python -m")[0],
        blocks=[
            dict(text=RUN_LENGTH, values=values),
            dict(table=dict(columns=RUN_COLUMNS, formats=[None, *["{:.1f}"] * 3, "{:.2f}", "{:.1f}", None], rows=runs)),
            dict(text=INSTANCES, values=values),
            dict(table=dict(columns=CYCLE_COLUMNS, formats=[None, None, "{:.1f}", "{:.2f}"], rows=cycle_rows)),
        ],
        metrics=[
            *(metric(f"{r[0]}: RSS growth projected to 24 h at 10 ms", r[5], "MB", "resource", 200.0) for r in runs),
            metric(f"first {cycles} create/free cycles: RSS growth", growth[0], "MB", "resource", target=5.0),
        ],
    )


RUN_COLUMNS = "recording|RSS at start (MB)|peak (MB)|end (MB)|slope (MB per simulated hour)|projected 24 h growth \
(MB)|rows".split("|")
CYCLE_COLUMNS = ["block", "cycles", "RSS after the block (MB)", "growth in the block (MB)"]
RUN_LENGTH = """## Run length: closed-loop demo at {step:g} ms, {seconds:g} s simulated ({steps} steps)

RSS from just before `Master.run` (the FMUs instantiated) to its end; the projection adds slope x (24 h - run \
length) to the last sample. Arrays are preallocated for the recorded rows (8 bytes per recorded value): every step \
of a day would be {day_steps:.3g} rows, so a day at every step is streamed to CSV or recorded at an interval."""

INSTANCES = """## Instances: create/free cycles of Bearing.fmu in one fmpy host

Each cycle: instantiate, setupExperiment, enter/exit initialisation, one doStep, terminate, freeInstance. RSS \
after {warm_up} warm-up cycles: {warm_rss:.1f} MB; {per_cycle:.3f} s per cycle."""


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=600.0, help="simulated seconds per run at 10 ms")
    parser.add_argument("--cycles", type=int, default=1000)
    parser.add_argument("--child", nargs="+", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if not args.child:
        cli(measure, "master_memory", seconds=args.seconds, cycles=args.cycles)
    elif args.child[0] == "cycles":
        child_cycles(int(args.child[1]))
    else:
        child_run(args.child[0], float(args.child[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
