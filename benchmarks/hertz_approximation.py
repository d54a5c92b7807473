"""Hamrock-Brewe approximate Hertz solution vs the exact one (elliptic integrals): error table and
time per call (an error-vs-run-time report).

Reference: the exact solution of bearing_fmu.kernels.hertz (validated against the thesis cases,
tests/validation/test_hertz_thesis.py). Steel on steel, Q = 1000 N, Rx = 5 mm.
Run: python -m benchmarks.hertz_approximation -> docs/reports/hertz_approximation.md
"""

from bearing_fmu.kernels.hertz import hertz_coefficients_approx as approx
from bearing_fmu.kernels.hertz import hertz_coefficients_exact as exact
from bearing_fmu.kernels.hertz import hertz_contact, reduced_modulus

from .common import interleaved_medians
from .render import cli, metric

CALLS = 200  # calls from Python per timed sample (about 1.5 ms for the exact coefficients, 35 us for the others)
REPEATS = 1001  # samples per function, interleaved: about 2 s in all
RATIOS = [0.2, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 8.0, 12.0, 20.0, 30.0, 50.0, 75.0, 100.0]
Q, RX, RY = 1000.0, 5e-3, 0.05  # RY: the geometry timed
E = reduced_modulus(210e9, 0.3, 210e9, 0.3)
COLUMNS = ["Ry/Rx", "k error %", "a_y error %", "b_x error %", "delta error %", "p_max error %"]
STEPS = {  # what is timed: label, function, arguments
    "exact": ("exact coefficients (k, E, K by bisection + AGM)", exact, (RX, RY)),
    "approx": ("approximate coefficients (Hamrock-Brewe)", approx, (RX, RY)),
    "contact": ("contact size/deflection/pressure given coefficients", hertz_contact,
                (Q, RX, RY, E, *exact(RX, RY))),
}  # fmt: skip


def errors(r):
    """Relative errors of k, a_y, b_x, delta and p_max at Ry/Rx = r."""
    ce, ca = exact(RX, RX * r), approx(RX, RX * r)
    ex, ap = hertz_contact(Q, RX, RX * r, E, *ce), hertz_contact(Q, RX, RX * r, E, *ca)
    return [ca[0] / ce[0] - 1] + [y / x - 1 for x, y in zip(ex, ap)]


def measure():
    rows = [[r] + [100 * e for e in errors(r)] for r in RATIOS]
    worst = max(abs(e) for row in rows for e in row[1:]) / 100
    batches = {k: (lambda f=f, a=a: [f(*a) for _ in range(CALLS)]) for k, (_, f, a) in STEPS.items()}
    t = {k: v / CALLS for k, v in interleaved_medians(batches, REPEATS).items()}
    values = dict(worst=100 * worst, lo=RATIOS[0], hi=RATIOS[-1])
    blocks = [
        {"table": {"columns": COLUMNS, "formats": ["{:g}"] + ["{:+.2f}"] * 5, "rows": rows}},
        {"text": "Largest error: {worst:.1f} % (over {lo:g} <= Ry/Rx <= {hi:g}).", "values": values},
        {"table": {"columns": ["step", "time per call from Python (us, median)"], "formats": ["{}", "{:.2f}"],
                   "rows": [[label, 1e6 * t[k]] for k, (label, _, _) in STEPS.items()]}},
        {"text": "The coefficients depend only on the geometry (Ry/Rx); the models compute them once at set-up, so "
                 "the exact solution costs nothing per step and is the default. The approximation errs by up to "
                 "{worst:.1f} %: use it only where the geometry changes every call.", "values": values},
    ]  # fmt: skip
    metrics = [metric("largest relative error of the approximation", worst, "1", "error")]
    metrics += [metric(f"{k} coefficients per call", t[k[:6]], "s", "timing") for k in ("exact", "approximate")]
    about = __doc__.split("\n\n")[1].split("Run:")[0]
    title = "Hertz contact: Hamrock-Brewe approximation vs exact solution"
    return dict(name="hertz_approximation", title=title, about=about, blocks=blocks, metrics=metrics)


def main(argv=None):
    cli(measure, "hertz_approximation")


if __name__ == "__main__":
    main()
