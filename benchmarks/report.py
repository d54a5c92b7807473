"""make report (python -m benchmarks.report): run the reference cases, the accuracy and timing suites and the stability suite,
write docs/report.md.

Each benchmark writes its own report into docs/reports/ and records its headline numbers (errors, timings with
their targets) in docs/reports/metrics.json (benchmarks.common.record). This module runs them, runs every
stability case of tests/stability/cases.py (slow ones included) and assembles docs/report.md: first the error of
each fidelity against independent references (benchmarks/reference_table.py, the cases the validation tests
assert on), then the differences between fidelities, one section per knob with its reference and its
error-against-time table, the timing targets beside the measured medians with the run's noise, the stability
cases with their outcomes, the defaults and why, and a comparison with the previous run (errors must repeat to
1e-12 relative, timings within the stated noise band; benchmarks/verdicts.py).

    python -m benchmarks.report [--reuse] [--only NAME ...]

--reuse assembles docs/report.md from the reports and metrics already written (no benchmark is run; the
stability cases are run, they take a few minutes);
--only runs the named benchmarks (module names) before assembling.
"""

import argparse
import importlib
import json
import math
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree
from pathlib import Path

from . import reference_table, render
from .common import METRICS, REPORTS, core_contention, forget, machine_speed, record
from .verdicts import (
    DETERMINISTIC,
    MET,
    MISSED,
    REPEAT_RTOL,
    TIMING_NOISE,
    WITHIN_NOISE,
    largest_contention,
    noise_factor,
    repeated,
    speed_spread,
    timing_verdict,
)

ROOT = REPORTS.parent.parent
REPORT = ROOT / "docs" / "report.md"
PREVIOUS = REPORTS / "metrics.previous.json"
MACHINE = "machine"  # metrics entry: the reference workload's time before each benchmark (common.machine_speed)
CONTENTION = "contention"  # metrics entry: wall / CPU time of the workload before each benchmark (core_contention)

# The knobs in the order of the report.
KNOBS = (  # (benchmark, its reference); the title and figures come from the benchmark's result
    (
        "fidelity_ladder",
        "the quasi-static solution with the boundary condition of the fidelity compared (static quantities): the ring free in five DOF for the DEM (as Bearing.fmu's; under a fixed preload BearingFixed.fmu's), its tilts held for the analytic fidelity; the DEM at dt/4 (dynamics). Each row states its ring's boundary condition; the rows of the free ring against the tilt-held one are a difference of boundary condition, not an error",
    ),
    ("ehl_film_table", "the 55 full numerical EHL solutions of Wheeler (2016), Annexe D"),
    ("hertz_approximation", "exact Hertz (elliptic integrals)"),
    ("solver_tolerance", "the same solve at tolerance 1e-14"),
    (
        "dem_steps",
        "the DEM at a tenth of each point's automatic step with every quantity refreshed every step (steady points), at 0.1 us (transients); the quasi-static fidelity driven in time beside it",
    ),
    (
        "film_check",
        "the numerical EHL solver (docs/ehl_solver.md) at the most loaded inner and outer contact of each operating point: the 6208 at the seeds' points and the B7214C at 10 000 rpm",
    ),
    ("ehl_solver", "the 55 full numerical EHL solutions of Wheeler (2016), Annexe D, and the solver's own finer grids"),
    ("ehl_grid_study", "the Richardson estimate from the solver's three finest grids, and the thesis' values"),
    ("ehl_fields", "the thesis' figures of the same cases (shape)"),
    ("film_correction", "the numerical EHL solver at random contacts of the 6208 and the B7214C"),
    (
        "lubrication_skf",
        "the SKF friction model (benchmarks/skf_friction.py: rolling, sliding, inlet shear heating, replenishment and drag terms), trends and ratios, not fitted",
    ),
    ("outside_hertz_capacitance", "the Hertz-zone plate capacitance of the same contacts"),
    ("cosim_error", "a monolithic Heun integration of the same loop at a fine step (its refinement check on the page)"),
    ("dem_closed_loop_steps", "the same coupled start-up at H = 0.05 ms, Gauss-Seidel"),
    ("warmup_modes", "the same warm-up with the shaft's modes solved at every step (tolerance 0)"),
    (
        "shaft_dem",
        "the same shaft on quasi-static bearings (runs/shaft_transient_qs.toml), on its nonlinear static equilibrium",
    ),
)
REFERENCES = "reference_table"  # run first: the report's first table
# The timing benchmarks (their targets are recorded with the metrics).
TIMINGS = (
    "kernel_timing",
    "option_cost",
    "quasistatic_timing",
    "quasistatic_low_speed",
    "fmu_startup",
    "closed_loop",
    "dem_timing",
    "dem_fmu",
    "dem_closed_loop",
    "first_start",
    "master_memory",
)
BENCHMARK_OPTIONS = {"dem_closed_loop": {"runs": 1}}  # keyword arguments of a measure(), where not its defaults
# The product's defaults and the benchmark each was chosen from, where that benchmark's result does not state the
# default itself (a result's "defaults" entries, benchmarks/render.py, come first). No measured number here: the
# benchmark's page has them.
DEFAULTS = (
    (
        "film formula",
        "Hamrock-Dowson",
        "ehl_film_table",
        "the seeds' formula; its error against the numerical solutions is measured there",
    ),
    ("Hertz solution", "exact", "hertz_approximation", "computed once per geometry at set-up: costs nothing per step"),
    (
        "DEM time step",
        "0.5 x the stability limit",
        "dem_steps",
        "accurate at the three points and in the transients, and below the 6208's chatter onset by that margin "
        "(docs/dem.md, Choice of the defaults)",
    ),
    (
        "DEM tribology refresh",
        "at least every 40 us",
        "dem_steps",
        "about half the cost of every-step tribology in steady rolling; the transients' lag is measured there",
    ),
    (
        "co-simulation step (quasi-static loop)",
        "H = 1 s, Gauss-Seidel",
        "cosim_error",
        "the temperatures' error of the cold start-up against the run time of each step is tabulated there",
    ),
    (
        "shaft FMU tolerance in the warm-up runs",
        "1e-2",
        "warmup_modes",
        "the modes lag by about half of it and the compliances by about it, well inside the +-2 % band the warm-up "
        "is judged by, and the loop with the shaft then costs under 1.5 x the loop without it",
    ),
    (
        "co-simulation step (DEM loop)",
        "H = 10 ms, Gauss-Seidel, speed set for the end of each step",
        "dem_closed_loop_steps",
        "the heat's and temperatures' error against H = 0.05 ms is tabulated there",
    ),
)
# A benchmark whose report file is named otherwise than the benchmark
REPORT_FILES = {}


# results made by another module's measure(): name -> (module, its options, the command that makes it alone)
GRID_STUDY_CASES = (6, 11, 14, 17, 20, 28, 33, 44, 47)  # a light, a heavy and a slender case of each kind
VARIANTS = {
    "ehl_grid_study": (
        "ehl_solver",
        dict(study=GRID_STUDY_CASES, bearing_study=True),
        "python -m benchmarks.ehl_solver --study " + ",".join(map(str, GRID_STUDY_CASES)) + " --bearing-study",
    ),
}


def run_benchmarks(names):
    """Run each benchmark's measure() and write its result (page, figures, metrics); returns {name: wall seconds}."""
    seconds = {}
    forget(MACHINE)
    forget(CONTENTION)
    for name in names:
        module_name, options, command = VARIANTS.get(name, (name, BENCHMARK_OPTIONS.get(name, {}), None))
        module = importlib.import_module(f"benchmarks.{module_name}")
        record(MACHINE, f"reference workload before {name}", machine_speed(), "s", kind="machine")
        record(CONTENTION, f"wall / CPU before {name}", core_contention(), "1", kind="machine")
        t0 = time.perf_counter()
        print(f"== {name}", flush=True)
        forget(name)
        render.cli(module.measure, name, command, **options)
        seconds[name] = time.perf_counter() - t0
    return seconds


def run_stability():
    """Run every test of the stability cases (slow ones included) in one pytest process; returns
    {(path, function): (outcome, seconds)} with outcome 'passed', 'failed', 'error' or 'skipped'."""
    sys.path.insert(0, str(ROOT))
    from tests.stability.cases import CASES

    targets = sorted({f"{path}::{name}" for _, _, path, name in CASES})
    with tempfile.TemporaryDirectory() as folder:
        junit = Path(folder) / "stability.xml"
        subprocess.run(
            [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", f"--junitxml={junit}", *targets],
            cwd=ROOT,
            check=False,
        )
        tree = ElementTree.parse(junit)
    results = {}
    for case in tree.iter("testcase"):
        path = case.get("classname", "").replace(".", "/") + ".py"
        function = case.get("name", "").split("[")[0]
        outcome = "passed"
        for child in case:
            if child.tag in ("failure", "error", "skipped"):
                outcome = {"failure": "failed"}.get(child.tag, child.tag)
        old = results.get((path, function), ("passed", 0.0))
        worst = old[0] if old[0] != "passed" else outcome
        results[(path, function)] = (worst, old[1] + float(case.get("time", 0.0)))
    return results


def outcome_of(path, function):
    """The 'Outcome:' part of a test's docstring (the expected outcome it asserts)."""
    import ast

    tree = ast.parse((ROOT / path).read_text())
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name == function:
            text = " ".join((ast.get_docstring(node) or "").split())
            return text.split("Outcome:", 1)[1].strip() if "Outcome:" in text else text
    return "(test not found)"


def fmt(value, unit):
    if unit == "s":
        for scale, name in ((1.0, "s"), (1e-3, "ms"), (1e-6, "us"), (1e-9, "ns")):
            if abs(value) >= scale or name == "ns":
                return f"{value / scale:.3g} {name}"
    if unit in ("1", ""):
        return f"{value:.3g}"
    return f"{value:.3g} {unit}"


def knob_section(metrics, name, reference):
    result = render.last_result(name) or {}
    lines = [f"### {result.get('title', name)}", "", f"Reference: {reference}. Full report: {link(name)}.", ""]
    entries = metrics.get(name)
    if not entries:
        return lines + ["**Not measured in this run.**", ""]
    rows = [[key, fmt(m["value"], m["unit"]), m["kind"]] for key, m in entries.items()]
    lines += render.table(dict(columns=["measure", "value", "kind"], rows=rows)) + [""]
    figures = [b["figure"] for b in result.get("blocks", []) if "figure" in b]
    return lines + [f"![{f.get('caption', f['file'])}](reports/{f['file']})\n" for f in figures]


def timing_rows(metrics, noise):
    """[(benchmark, metric name, metric, ratio to target, verdict)] of every metric with a target."""
    rows = []
    for name in TIMINGS + tuple(k[0] for k in KNOBS):
        for key, m in metrics.get(name, {}).items():
            if m["target"] is None:
                continue
            ratio = m["value"] / m["target"] if m["target"] else (0.0 if m["value"] == 0 else float("inf"))
            rows.append((name, key, m, ratio, timing_verdict(m, noise)))
    return rows


def timing_section(metrics):
    noise, spread, contention = noise_factor(metrics, MACHINE, CONTENTION)
    rows = timing_rows(metrics, noise)
    lines = [
        f"Noise factor of this run: x{noise:.2f}, the largest of x{TIMING_NOISE:.2f} (the scatter of a median between "
        f"two runs in the same machine state), x{spread:.2f} (the spread of the machine's own speed over this run) "
        f"and x{contention:.2f} (the largest wall / CPU time of a reference workload before a benchmark: how far "
        "other users' work on the shared cores slowed a process down). A target is met when the median lies below target / noise factor, missed above target x noise "
        "factor, and within noise between; a ratio of two timings measured side by side in one run is compared "
        "with its target directly (benchmarks/verdicts.py).",
        "",
        "| benchmark | measure | target | measured (median) | measured / target | verdict |",
        "|---|---|---|---|---|---|",
    ]
    for name, key, m, ratio, verdict in rows:
        shown = {MET: "met", WITHIN_NOISE: "within noise", MISSED: "**missed**"}[verdict]
        side = " (side by side)" if m.get("side_by_side") else ""
        lines.append(
            f"| {name} | {key}{side} | {fmt(m['target'], m['unit'])} | {fmt(m['value'], m['unit'])} | {ratio:.2f} | "
            f"{shown} |"
        )
    counts = {v: sum(1 for r in rows if r[4] == v) for v in (MET, WITHIN_NOISE, MISSED)}
    lines += [
        "",
        f"Of {len(rows)} targets: {counts[MET]} met, {counts[WITHIN_NOISE]} within noise, {counts[MISSED]} missed.",
        "",
    ]
    open_rows = [(name, key, verdict) for name, key, _, _, verdict in rows if verdict != MET]
    if open_rows:
        lines += ["Targets not met beyond the noise; each benchmark's page measures where its time goes:", ""]
        for name, key, verdict in open_rows:
            lines.append(f"- {name}, {key} ({verdict}): {link(name)}")
        lines.append("")
    absent = [name for name in TIMINGS if name not in metrics]
    if absent:
        lines += [f"Not measured in this run: {', '.join(absent)}.", ""]
    return lines


def stability_section(results):
    sys.path.insert(0, str(ROOT))
    from tests.stability.cases import CASES

    lines = ["| case | fidelities | expected outcome (asserted) | test | result |", "|---|---|---|---|---|"]
    for case, fidelities, path, function in CASES:
        outcome, seconds = results.get((path, function), ("not run", 0.0))
        lines.append(
            f"| {case} | {fidelities} | {outcome_of(path, function).replace('|', '&#124;')} | `{path}::{function}` | "
            f"{outcome} "
            f"({seconds:.1f} s) |"
        )
    passed = sum(1 for o, _ in results.values() if o == "passed")
    lines += ["", f"{passed} of {len(results)} stability tests passed.", ""]
    return lines


def compare_runs(metrics, previous, rerun):
    """(errors and counts repeated to REPEAT_RTOL, of which bit for bit, those that differ, timing ratios new/old)
    over the benchmarks run this time."""
    same, exact, differ, ratios = 0, 0, [], []
    for name, entries in metrics.items():
        if name not in rerun:
            continue
        for key, m in entries.items():
            old = previous.get(name, {}).get(key)
            if old is None:
                continue
            if m["kind"] in DETERMINISTIC:
                if repeated(old["value"], m["value"]):
                    same += 1
                    exact += old["value"] == m["value"]
                else:
                    differ.append(f"{name}: {key} ({old['value']!r} then {m['value']!r})")
            elif old["value"] > 0.0:
                ratios.append((m["value"] / old["value"], name, key))
    return same, exact, differ, ratios


def reproduction_section(metrics, previous, rerun):
    """Compare the benchmarks run this time (rerun: their names) with the previous run's values."""
    if not previous or not rerun:
        return ["No benchmark was run again this time: nothing to compare (`make report` runs them all).", ""]
    same, exact, differ, ratios = compare_runs(metrics, previous, rerun)
    lines = [
        f"Errors and counts: {same} repeated within {REPEAT_RTOL:g} relative ({exact} of them bit for bit), "
        f"{len(differ)} differ" + (": " + "; ".join(differ) if differ else "") + ".",
        "",
    ]
    if ratios:
        deviations = sorted(abs(r - 1.0) for r, _, _ in ratios)
        worst = max(ratios, key=lambda r: abs(math.log(r[0])))
        machine = speed_spread([metrics, previous], MACHINE)
        contention = largest_contention([metrics, previous], CONTENTION)
        band = max(TIMING_NOISE, machine, contention)
        outside = [r for r in ratios if not 1.0 / band <= r[0] <= band]
        lines += [
            f"Timings: {len(ratios)} medians compared; median deviation {100 * statistics.median(deviations):.1f} %, "
            f"largest x{worst[0]:.2f} ({worst[1]}: {worst[2]}).",
            "",
            f"Noise band: within a factor {band:.2f} of the previous run, the largest of {TIMING_NOISE:.2f} (the "
            f"same machine state), {machine:.2f}, the spread of the machine's own speed over the two runs (a "
            "fixed pure-Python workload timed before each benchmark, `benchmarks.common.machine_speed`), and "
            f"{contention:.2f}, the largest core contention measured in either run (`benchmarks.common."
            "core_contention`). "
            + (
                f"{len(outside)} outside: "
                + "; ".join(f"{n}: {k} (x{r:.2f})" for r, n, k in sorted(outside, key=lambda o: -abs(math.log(o[0]))))
                if outside
                else "All within."
            ),
            "",
        ]
    return lines


def reference_section(measured_now):
    """The reference table (benchmarks/reference_table.py) from docs/reports/reference_table.json."""
    if not reference_table.TABLE.exists():
        return ["**Not measured yet** (`python -m benchmarks.reference_table`).", ""]
    note = [] if measured_now else ["Measured in an earlier run (the reference table was not run this time).", ""]
    return note + reference_table.render(json.loads(reference_table.TABLE.read_text()))


def default_rows():
    """The defaults stated by the benchmarks' results (their why with the measured numbers), then DEFAULTS."""
    rows, stated = [], set()
    for name in [k[0] for k in KNOBS] + list(TIMINGS):
        result = render.last_result(name) or {}
        for d in result.get("defaults", []):
            rows.append([d["setting"], d["default"], link(name), render.fill({"text": d["why"], **d})])
            stated.add(d["setting"])
    for setting, default, source, why in DEFAULTS:
        if setting not in stated:
            rows.append([setting, default, link(source), why])
    return rows


def link(name):
    file = REPORT_FILES.get(name, name)
    return f"[reports/{file}.md](reports/{file}.md)"


def assemble(seconds, stability, previous, total):
    metrics = json.loads(METRICS.read_text()) if METRICS.exists() else {}
    load = os.getloadavg()
    lines = [
        "# Error against run time, timing and stability",
        "",
        f"Generated by `make report` on {platform.machine()}, Python {platform.python_version()}, "
        f"{os.cpu_count()} cores; load average {load[0]:.2f} / {load[1]:.2f} / {load[2]:.2f} at the end; "
        f"{total / 60:.1f} min in total"
        + (" (" + ", ".join(f"{n} {s:.0f} s" for n, s in seconds.items()) + ")" if seconds else "")
        + ".",
        "",
        "Section 1 gives the error of each fidelity against independent references (literature, standards,",
        "published tables), measured by the functions the validation tests assert on. Section 2 gives the",
        "differences between fidelities and settings, each against a named numerical reference of the product",
        "itself; every timing is a median measured on this machine. The benchmarks' own reports (docs/reports/)",
        "hold the full tables and the method of each measurement. The README section 'Choosing fidelity and",
        "step' gives the summary an engineer needs.",
        "",
        "## 1. Error against independent references, per fidelity",
        "",
    ]
    lines += reference_section(REFERENCES in seconds)
    lines += ["## 2. Difference between fidelities and settings, against run time", ""]
    for knob in KNOBS:
        lines += knob_section(metrics, *knob)
    lines += ["## 3. Timing against the performance budget", ""]
    lines += timing_section(metrics)
    lines += ["## 4. Defaults and why", ""]
    lines += render.table(dict(columns=["setting", "default", "chosen from", "why"], rows=default_rows()))
    lines += ["", "## 5. Stability suite", ""]
    lines += stability_section(stability)
    lines += ["## 6. Reproducibility: this run against the previous one", ""]
    lines += [f"Benchmarks run this time: {', '.join(seconds) or 'none'}.", ""]
    lines += reproduction_section(metrics, previous, set(seconds))
    REPORT.write_text("\n".join(lines) + "\n")
    print(f"wrote {REPORT}")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m benchmarks.report", description=__doc__.split("\n")[0])
    parser.add_argument("--reuse", action="store_true", help="assemble from the reports already written")
    parser.add_argument("--only", nargs="+", metavar="NAME", help="run only these benchmarks")
    args = parser.parse_args(argv)
    t0 = time.perf_counter()
    previous = json.loads(METRICS.read_text()) if METRICS.exists() else {}
    seconds, stability = {}, {}
    if not args.reuse:
        if METRICS.exists():
            shutil.copy(METRICS, PREVIOUS)
        everything = [REFERENCES] + [k[0] for k in KNOBS] + [t for t in TIMINGS if t not in [k[0] for k in KNOBS]]
        names = args.only or everything
        available = [n for n in names if (Path(__file__).parent / f"{VARIANTS.get(n, (n,))[0]}.py").exists()]
        seconds = run_benchmarks(available)
    elif PREVIOUS.exists():
        previous = json.loads(PREVIOUS.read_text())
    stability = run_stability()  # a few minutes, not timing-sensitive: run with --reuse too
    assemble(seconds, stability, previous, time.perf_counter() - t0)


if __name__ == "__main__":
    main()
