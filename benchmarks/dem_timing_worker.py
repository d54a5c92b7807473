"""One source tree's DEM in a process of its own, timed on command (benchmarks.dem_timing.side_by_side).

Run with the tree's root as the working directory and on PYTHONPATH (so `bearing_fmu` is that tree's): it builds
the 6208 in steady rolling and answers each line on stdin, `<refresh> <steps> <dt>`, with the thread's CPU time and
the wall time (s) of one advance() over `steps` steps of dt (s) with the tribology refreshed every `refresh` steps;
a blank line ends it. Only the model's public API (DemModel, advance, dt_fixed, refresh_fixed) is used, so it runs
on any tree that has them; it imports nothing of the driver's tree (benchmarks.dem_timing imports steady_model).
"""

import sys
import time

from bearing_fmu.models.dem import DemModel

OMEGA = 500.0
F_R = 3000.0


def steady_model():
    """The 6208 at 3 kN after the validation's start-up: 2 ms at rest, 5 ms ramp to 500 rad/s, run to 30 ms."""
    model = DemModel("6208", "guessasma_oil")
    model.advance(2e-3, omega=0.0, F_y=F_R)
    for k in range(1, 21):
        model.advance(2e-3 + 5e-3 * k / 20, omega=OMEGA * k / 20, F_y=F_R)
    model.advance(0.03, omega=OMEGA, F_y=F_R)
    return model


def main():
    model = steady_model()
    print(f"ready {model.dt!r}", flush=True)
    for line in sys.stdin:
        if not line.strip():
            break
        refresh, steps, dt = line.split()
        model.refresh_fixed, model.dt_fixed = int(refresh), float(dt)
        t_end = model.time + int(steps) * float(dt)
        c0, t0 = time.thread_time(), time.perf_counter()
        model.advance(t_end, omega=OMEGA, F_y=F_R)
        c1, t1 = time.thread_time(), time.perf_counter()
        print(f"{c1 - c0!r} {t1 - t0!r}", flush=True)


if __name__ == "__main__":
    main()
