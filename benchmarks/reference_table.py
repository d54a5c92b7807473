"""Error against independent references, per fidelity: the report's first table.

Each reference case of tests/cases (the literature and standard cases the validation tests assert
on) is compared here once more, by the same function, and its cost per evaluation is measured: the median wall
time of one evaluation of the fidelity at the case's point, repeated (at least 5 repeats and 0.5 s for a fast
evaluation, 3 for one of a second or more), with the machine's load average at the time. Each case's worst
deviation is an error (a second run must repeat it), its cost a timing.

Run: python -m benchmarks.reference_table: docs/reports/reference_table.md and .json (what the report renders).
"""

import os
import statistics
import time

from tests.cases import CASES, worst

from .common import REPORTS
from .render import cli, metric, page

TABLE = REPORTS / "reference_table.json"  # the result as render.write writes it
MIN_REPEATS, MIN_SECONDS, SLOW_REPEATS, SLOW = 5, 0.5, 3, 1.0  # -, s, -, s


def cost_per_evaluation(evaluate):
    """(median wall time s, repeats) of evaluate() after one warm-up call."""
    t0 = time.perf_counter()
    evaluate()  # warm-up: compilation, caches
    repeats, least = (SLOW_REPEATS, 0.0) if time.perf_counter() - t0 >= SLOW else (MIN_REPEATS, MIN_SECONDS)
    samples, start = [], time.perf_counter()
    while len(samples) < repeats or time.perf_counter() - start < least:
        t0 = time.perf_counter()
        evaluate()
        samples.append(time.perf_counter() - t0)
    return statistics.median(samples), len(samples)


def measure_case(case):
    """The case's comparisons summarised by the worst one (closest to or beyond its tolerance), and its cost."""
    print(f"-- {case.name}", flush=True)
    comparisons = case.compare()
    w = worst(comparisons)
    seconds, repeats = cost_per_evaluation(case.evaluation())
    row = {key: getattr(case, key) for key in ("name", "fidelity", "reference", "source")}
    row.update(points=len(comparisons), within=int(sum(bool(c.within) for c in comparisons)), worst=w.quantity)
    row.update({key: float(getattr(w, key)) for key in ("deviation", "uncertainty", "tolerance")})
    row.update(largest_deviation=float(max(abs(c.deviation) for c in comparisons)), cost=seconds, repeats=repeats)
    return dict(row, load=os.getloadavg()[0])


def seconds(value):
    for scale, name in ((1.0, "s"), (1e-3, "ms"), (1e-6, "us")):
        if value >= scale:
            return f"{value / scale:.3g} {name}"
    return f"{value / 1e-9:.3g} ns"


def result(rows):
    """The result dict (benchmarks/render.py) of the cases' rows (measure_case of each)."""
    table = dict(
        columns=["fidelity", "reference", "source", "points", "worst point", "deviation", "reference's uncertainty"]
        + ["tolerance", "within", "cost per evaluation"],
        formats=[None, None, None, "{:d}", None, "{:+.2e}", "{:.2e}", "{:.2e}", None, None],
        rows=[
            [r[k] for k in ("fidelity", "reference", "source", "points", "worst", "deviation", "uncertainty")]
            + [r["tolerance"], f"{r['within']} of {r['points']}"]
            + [f"{seconds(r['cost'])} (median of {r['repeats']}, load {r['load']:.1f})"]
            for r in rows
        ],
    )
    metrics = [metric(f"{r['name']}: largest relative deviation", r["largest_deviation"], "1", "error") for r in rows]
    metrics += [metric(f"{r['name']}: cost per evaluation", r["cost"], "s", "timing") for r in rows]
    note = (
        "Deviation: (product - reference) / |reference| at the case's worst point, the one closest to (or beyond) "
        "its tolerance; the reference's uncertainty and the tolerance are those of that point, relative. Cost: one "
        "evaluation of the fidelity at the case's point (the DEM: the whole run the case compares, from a fresh "
        "model). Cases and sources: `tests/cases/`; the validation tests assert on the same functions."
    )
    title, about = "Error against independent references, per fidelity", __doc__.split("\n", 2)[2].split("Run:")[0]
    blocks = [dict(table=table), dict(text=note)]
    return dict(name="reference_table", title=title, about=about, blocks=blocks, metrics=metrics, cases=rows)


def measure(cases=None):
    return result([measure_case(case) for case in (CASES if cases is None else cases).values()])


def render(data):
    """Markdown lines of the table and its note: data = a result (docs/reports/reference_table.json) or, as
    earlier runs wrote that file, the list of the cases' rows."""
    return page(data if isinstance(data, dict) else result(data))


def main(argv=None):
    cli(measure, "reference_table")


if __name__ == "__main__":
    main()
