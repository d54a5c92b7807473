"""Timing helpers for the benchmarks: medians over repeats, never asserted in tests (targets: docs/architecture.md, performance budget)."""

import json
import math
import statistics
import time
from pathlib import Path

REPORTS = Path(__file__).resolve().parent.parent / "docs" / "reports"


def median_time(fn, *args, number=1000, repeats=15):
    """Median wall time per call (s) of fn(*args) over `repeats` batches of `number` calls."""
    fn(*args)  # warm-up (compilation, caches)
    samples = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(number):
            fn(*args)
        samples.append((time.perf_counter() - t0) / number)
    return statistics.median(samples)


def interleaved_medians(calls, repeats, clock=time.perf_counter):
    """Median time (s, on `clock`) of each zero-argument callable in `calls` (dict name -> callable).

    The calls run in turn, `repeats` rounds of one call each, so every median draws its samples from the same
    stretch of time: on this shared machine the speed of a core changes within a fraction of a second (other
    users, frequency), and timings taken one after the other in short windows differ by up to 2x between runs."""
    for fn in calls.values():
        fn()  # warm-up (compilation, caches)
    samples = {name: [] for name in calls}
    for _ in range(repeats):
        for name, fn in calls.items():
            t0 = clock()
            fn()
            samples[name].append(clock() - t0)
    return {name: statistics.median(s) for name, s in samples.items()}


def machine_speed(seconds=0.5):
    """Median wall time (s) of a fixed reference workload (a pure-Python floating-point loop of about 1.5 ms),
    sampled for `seconds`: how fast this shared machine runs at the moment, independent of the product's code
    (benchmarks/report.py takes its spread over a run as part of the timing noise band)."""
    samples = []
    t_end = time.perf_counter() + seconds
    while not samples or time.perf_counter() < t_end:
        t0 = time.perf_counter()
        reference_workload()
        samples.append(time.perf_counter() - t0)
    return statistics.median(samples)


def reference_workload():
    acc = 0.0
    for i in range(1, 5001):
        acc += math.sqrt(i) * math.exp(-1e-5 * i) + math.log(i)
    return acc


def core_contention(seconds=0.5):
    """Wall time over this process's CPU time while it runs the reference workload for `seconds`: about 1 when it
    has a core to itself, about n when n runnable processes share its core. machine_speed's median of short
    samples does not see this (a sample fits between two preemptions); a timing taken meanwhile can."""
    w0, c0 = time.perf_counter(), time.process_time()
    while time.perf_counter() - w0 < seconds:
        reference_workload()
    return (time.perf_counter() - w0) / max(time.process_time() - c0, 1e-9)


METRICS = REPORTS / "metrics.json"


def forget(benchmark):
    """Drop a benchmark's recorded metrics (before it runs again, so no stale entry survives)."""
    if METRICS.exists():
        metrics = json.loads(METRICS.read_text())
        metrics.pop(benchmark, None)
        METRICS.write_text(json.dumps(metrics, indent=1) + "\n")


def record(benchmark, key, value, unit, *, kind, target=None, note="", side_by_side=False):
    """Keep a headline number of a benchmark for docs/report.md (benchmarks/report.py) in docs/reports/metrics.json.

    kind: "error" (against a reference; deterministic: a second run must reproduce it to 1e-12 relative),
    "difference" (between two solutions of the product, e.g. two fidelities; deterministic too), "timing" (a median,
    reproduced within the noise band the report states) or "count". target: the budget (judged with the run's noise, benchmarks/verdicts.py), from
    docs/architecture.md's performance budget or the acceptance criteria; None when the number has none.
    side_by_side: a ratio of two timings measured interleaved in one run (judged without the run's noise factor,
    benchmarks/verdicts.py)."""
    metrics = json.loads(METRICS.read_text()) if METRICS.exists() else {}
    metrics.setdefault(benchmark, {})[key] = dict(
        value=float(value),
        unit=unit,
        kind=kind,
        target=None if target is None else float(target),
        note=note,
        side_by_side=side_by_side,
    )
    REPORTS.mkdir(parents=True, exist_ok=True)
    METRICS.write_text(json.dumps(metrics, indent=1) + "\n")


def rotated_batches(calls, repeats):
    """Wall times (s) of `repeats` calls of each zero-argument callable in the list `calls`, one list per callable,
    after a warm-up call of each. Every repeat calls each once, the order rotated by one each repeat, so a slow
    phase of the shared machine hits all of them alike."""
    for fn in calls:
        fn()  # warm-up (compilation, caches)
    times = [[] for _ in calls]
    for r in range(repeats):
        for k in [*range(r % len(calls), len(calls)), *range(r % len(calls))]:
            t0 = time.perf_counter()
            calls[k]()
            times[k].append(time.perf_counter() - t0)
    return times
