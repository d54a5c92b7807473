"""Timing helpers for the benchmarks: medians over repeats, never asserted in tests (targets: docs/architecture.md, performance budget)."""

import platform
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


def machine():
    return f"{platform.processor() or platform.machine()}, Python {platform.python_version()}"


def write_report(name, text):
    REPORTS.mkdir(parents=True, exist_ok=True)
    path = REPORTS / name
    path.write_text(text)
    print(f"wrote {path}")
    return path
