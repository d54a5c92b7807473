"""How docs/report.md judges its numbers: a timing against its target given the run's noise, and an error of one
run against the same error of the previous run.

Timing: a median measured on a shared machine varies from run to run. The run's noise factor is the largest of
TIMING_NOISE (the scatter of a median between two runs in the same machine state), the spread (largest over
smallest) of the machine's own speed over the run (a fixed pure-Python workload timed before each benchmark,
benchmarks.common.machine_speed) and the largest core contention measured before a benchmark (wall over CPU time
of the same workload, benchmarks.common.core_contention: other users' processes sharing the cores). A target counts as met only when the median lies below target / noise factor,
as missed above target x noise factor, and as within noise between. A ratio of two timings measured side by side
in one run (interleaved, so both see the same machine state) is compared with its target directly.

Repeatability: errors and counts are deterministic; floating-point sums can still differ in the last digits
between runs (other BLAS kernels, another order of summation), so a repeated error counts as reproduced within a
relative tolerance REPEAT_RTOL, not by bit equality.
"""

TIMING_NOISE = 1.30  # a second run's timing medians are expected within this factor of the first's (same machine
# state), or within the factor by which the machine's own speed varied over the two runs where that is larger
REPEAT_RTOL = 1e-12
MET, WITHIN_NOISE, MISSED = "met", "within noise", "missed"
DETERMINISTIC = ("error", "difference", "count")  # kinds of metric a second run must repeat to REPEAT_RTOL


def speed_spread(runs, machine_key):
    """Largest over smallest reference-workload time recorded in the metrics of `runs` (1.0 without any)."""
    speeds = [m["value"] for run in runs for m in run.get(machine_key, {}).values()]
    return max(speeds) / min(speeds) if speeds else 1.0


def largest_contention(runs, contention_key):
    """Largest core contention (wall / CPU time of the reference workload) recorded in `runs` (1.0 without any)."""
    return max((m["value"] for run in runs for m in run.get(contention_key, {}).values()), default=1.0)


def noise_factor(metrics, machine_key, contention_key):
    """(noise factor of the run, spread of the machine's speed over it, largest core contention measured in it)."""
    spread = speed_spread([metrics], machine_key)
    contention = largest_contention([metrics], contention_key)
    return max(TIMING_NOISE, spread, contention), spread, contention


def timing_verdict(m, noise):
    """MET, WITHIN_NOISE or MISSED for a recorded metric m with a target."""
    if m["kind"] != "timing" or m.get("side_by_side", False):
        return MET if m["value"] <= m["target"] else MISSED
    if m["value"] <= m["target"] / noise:
        return MET
    return MISSED if m["value"] > m["target"] * noise else WITHIN_NOISE


def repeated(old, new, rtol=REPEAT_RTOL):
    """True if a deterministic value of the previous run (old) is reproduced by this run's (new) within rtol."""
    return old == new or abs(new - old) <= rtol * max(abs(old), abs(new))
