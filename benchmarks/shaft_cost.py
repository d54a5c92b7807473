"""Cost of one call of the shaft model (spindle.shaft.ShaftModel) on the default 40-element shaft: the seats' new 5x5
stiffness and damping assembled into the reduced matrices, the state-space eigen-solution and every output (six
frequencies with whirl and damping, static compliance, the tool tip's receptance peak), with and without the
synchronous critical speeds (a second, complex eigen-solution); the same for the model without reduction for
comparison. Medians over repeated calls, each with a perturbed stiffness (no caching can serve it). Target: <= 2 ms
per call (docs/shaft.md). Prints; writes nothing.
Run: python -m benchmarks.shaft_cost [calls]
"""

import math
import os
import sys
import time

import numpy as np

from spindle.shaft import ShaftModel

OMEGA = 10000.0 * math.pi / 30.0
K_SEAT = np.diag([2.0e8, 2.0e8, 5.0e7, 1.0e5, 1.0e5])
C_SEAT = np.diag([2000.0, 2000.0, 500.0, 0.0, 0.0])


def median_call(model, calls, **options):
    """Median seconds of model.evaluate over `calls` calls with a stiffness changed by up to 1 % each time."""
    rng = np.random.default_rng(1)
    C = np.array([C_SEAT, C_SEAT])
    times = []
    for _ in range(calls):
        K = np.array([K_SEAT, K_SEAT]) * (1.0 + 0.01 * rng.random((2, 5, 5)))
        start = time.perf_counter()
        model.evaluate(OMEGA, K, C, **options)
        times.append(time.perf_counter() - start)
    return float(np.median(times)), float(np.percentile(times, 90))


def main(calls=200):
    reduced = ShaftModel()
    full = ShaftModel(modes=None)
    elements = reduced.shaft.elements.shape[0]
    print(f"shaft '{reduced.shaft.name}': {elements} elements, {full.n_dofs} dof; reduced to {reduced.n_dofs} dof")
    print(f"BLAS threads: OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}")
    median_call(reduced, 20)  # warm-up: kernels compiled or loaded from the cache
    rows = [
        ("reduced, outputs without critical speeds", reduced, calls, {"critical_speeds": False}),
        ("reduced, all outputs with critical speeds", reduced, calls, {}),
        ("full, outputs without critical speeds", full, max(calls // 20, 5), {"critical_speeds": False}),
    ]
    for label, model, n, options in rows:
        median, p90 = median_call(model, n, **options)
        verdict = "meets" if median <= 2e-3 else "misses"
        print(f"{label:45s} median {median * 1e3:8.3f} ms  p90 {p90 * 1e3:8.3f} ms  ({n} calls; {verdict} 2 ms)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
