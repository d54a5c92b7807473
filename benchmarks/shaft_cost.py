"""Cost of one call of the shaft model (spindle.shaft.ShaftModel) on the default 40-element shaft: the seats' new 5x5
stiffness and damping assembled into the reduced matrices, the state-space eigen-solution and every output (six
frequencies with whirl and damping, static compliance, the tool tip's receptance peak), with and without the
synchronous critical speeds; one step of SpindleShaft.fmu's model (spindle.shaft.stepper.ShaftStepper: the FMU's flat
inputs checked, every output, the critical speeds included since the seats change); the model without reduction for
comparison. Medians of CPU time (and wall time) over repeated calls, each with a perturbed stiffness (no caching can
serve it). Target: <= 2 ms per step (docs/shaft.md). Prints; writes nothing.
Run: python -m benchmarks.shaft_cost [calls]
"""

import math
import os
import sys
import time

import numpy as np

from spindle.shaft import ShaftModel
from spindle.shaft.stepper import ShaftStepper

OMEGA = 10000.0 * math.pi / 30.0
K_SEAT = np.diag([2.0e8, 2.0e8, 5.0e7, 1.0e5, 1.0e5])
C_SEAT = np.diag([2000.0, 2000.0, 500.0, 0.0, 0.0])


def medians(call, arguments):
    """(median CPU s, median wall s, 90th percentile of CPU s) of call(a) over the arguments."""
    cpu, wall = [], []
    for a in arguments:
        start_cpu, start_wall = time.process_time(), time.perf_counter()
        call(a)
        cpu.append(time.process_time() - start_cpu)
        wall.append(time.perf_counter() - start_wall)
    return float(np.median(cpu)), float(np.median(wall)), float(np.percentile(cpu, 90))


def model_calls(model, calls, **options):
    """Medians of model.evaluate over `calls` calls with a stiffness changed by up to 1 % each time."""
    rng = np.random.default_rng(1)
    C = np.array([C_SEAT, C_SEAT])
    seats = [np.array([K_SEAT, K_SEAT]) * (1.0 + 0.01 * rng.random((2, 5, 5))) for _ in range(calls)]
    return medians(lambda K: model.evaluate(OMEGA, K, C, **options), seats)


def step_calls(calls):
    """Medians of ShaftStepper.evaluate (an FMU step) from its start inputs, every input changed by up to 1 % each
    step (the seats change, so every step computes the critical speeds)."""
    stepper = ShaftStepper()
    start = np.array([v.start for v in stepper.inputs], dtype=float)
    start[0] = OMEGA
    rng = np.random.default_rng(1)
    inputs = [list(start * (1.0 + 0.01 * rng.random(start.size))) for _ in range(calls)]
    stepper.evaluate(inputs[0])
    return medians(stepper.evaluate, inputs)


def main(calls=200):
    reduced = ShaftModel()
    full = ShaftModel(modes=None)
    elements = reduced.shaft.elements.shape[0]
    print(f"shaft '{reduced.shaft.name}': {elements} elements, {full.n_dofs} dof; reduced to {reduced.n_dofs} dof")
    print(f"BLAS threads: OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}")
    model_calls(reduced, 20)  # warm-up: kernels compiled or loaded from the cache
    rows = [
        ("reduced, outputs without critical speeds", lambda: model_calls(reduced, calls, critical_speeds=False)),
        ("reduced, all outputs with critical speeds", lambda: model_calls(reduced, calls)),
        ("FMU step, seats changed, all outputs", lambda: step_calls(calls)),
        (
            "full, outputs without critical speeds",
            lambda: model_calls(full, max(calls // 20, 5), critical_speeds=False),
        ),
    ]
    for label, run in rows:
        cpu, wall, p90 = run()
        verdict = "meets" if cpu <= 2e-3 else "misses"
        print(
            f"{label:42s} CPU median {cpu * 1e3:8.3f} ms  p90 {p90 * 1e3:8.3f} ms  wall median {wall * 1e3:8.3f} ms  "
            f"({verdict} 2 ms)"
        )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
