"""Cost of each scene option: what a warm co-simulation step of the kernels costs with the option on and off.

An option that is off is a null submodel in the kernels (its work is not done, tests/unit/
test_scene_options_skip_work.py), so its cost is the difference of the step times. One step = the work
of one FMU doStep in compiled code: for the quasi-static fidelity, solve_quasistatic warm-started from
the solution at loads (or imposed displacements) 1 % different, then contact_outputs; for the analytic
fidelity, analytic_bearing. The variants of a case differ only in the option codes of the parameter
arrays and are timed side by side, in interleaved batches (order rotated each repeat).
Run: python -m benchmarks.option_cost -> docs/reports/option_cost.md (OPTION_COST_REPEATS sets the repeats)
"""

import math
import os
import statistics
import time
from functools import partial

import numpy as np

from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import jones_harris, radial_bearing
from bearing_fmu.kernels.capacitance import CAP_ON
from bearing_fmu.kernels.torque import TL_SIZE
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.quasi_static import DOF_NAMES, LOAD_NAMES, QuasiStaticModel
from bearing_fmu.scene import Scene
from bearing_fmu_common.jit import kernel

from .common import rotated_batches
from .render import cli

RPM = 2.0 * math.pi / 60.0
T_OIL = 313.15
BATCH = 0.02  # s: steps per batch chosen so that a batch lasts about this long (scheduler noise << batch)
COLUMNS = ["case", "variant", "median (us)", "fastest (us)", "cost, fastest batches", "cost, median of paired ratios"]
REPEATS = int(os.environ.get("OPTION_COST_REPEATS", 31))
# variant -> (capacitance, torque, stiffness) codes
VARIANTS = {
    "all off": (0.0, 0.0, 0.0),
    "capacitance": (1.0, 0.0, 0.0),
    "torque": (0.0, 1.0, 0.0),
    "stiffness": (0.0, 0.0, 1.0),
    "all on": (1.0, 1.0, 1.0),
}


@kernel
def _repeat_step(n, F_applied, control, d0, X0, qs, omega, T_oil, cp, lub, d, X, F, K, balls, out, pc, losses):
    """n warm steps: state copied in, solve, contact outputs (what a doStep computes)."""
    s = 0
    for _ in range(n):
        d[:] = d0
        X[:, :] = X0
        s += jones_harris.solve_quasistatic(F_applied, control, d, qs, 0.0, omega, X, F, K, balls)[0]
        ck.contact_outputs(omega, T_oil, cp, lub, balls, out, pc, losses)
    return s


@kernel
def _repeat_analytic(n, omega, F_r, T_oil, brg, lub, nodes, weights, out, ball):
    for _ in range(n):
        radial_bearing.analytic_bearing(omega, F_r, T_oil, brg, lub, nodes, weights, out, ball)


def interleaved(fns):
    """Time per step of each fn(n) (n steps) over REPEATS interleaved batches, after a warm-up: for each fn
    (median, minimum, median over the repeats of its batch time / the first fn's batch time of the same
    repeat). The ratio pairs batches run a few ms apart, so a slow phase of the machine cancels out."""
    for fn in fns:
        fn(10)  # warm-up (compilation)
    t0 = time.perf_counter()
    fns[0](10)
    n = max(10, int(BATCH / max((time.perf_counter() - t0) / 10, 1e-9)))
    times = [[t / n for t in ts] for ts in rotated_batches([partial(fn, n) for fn in fns], REPEATS)]
    return [(statistics.median(t), min(t), statistics.median(a / b for a, b in zip(t, times[0]))) for t in times]


CASES = (  # label, bearing, drive, rpm, inputs, gyroscopic
    ("B7214C, load drive, rest, F_z = 800 N + F_y = 1 kN", "B7214C", "load", 0.0, {"F_z": 800.0, "F_y": 1000.0},
     False),
    ("B7214C, load drive, 10 000 rpm ORCG, F_z = 800 N + F_y = 1 kN", "B7214C", "load", 10000.0,
     {"F_z": 800.0, "F_y": 1000.0}, True),
    ("B7214C, displacement drive, 10 000 rpm ORCG, z = 20 um, x = 2 um", "B7214C", "displacement", 10000.0,
     {"z": 20e-6, "x": 2e-6}, True),
    ("6208, load drive, 3 000 rpm ORCG, F_y = 3 kN", "6208", "load", 3000.0, {"F_y": 3000.0}, True),
)  # fmt: skip


def quasi_static_steps(label, bearing, drive, rpm, inputs, gyroscopic):
    """fn(n) of n warm steps for each variant; the warm start is the solution at inputs 1 % different."""
    options = dict(capacitance=True, torque=True, stiffness=True)
    scene = Scene(name="option_cost", fidelity="quasi_static", drive=drive, gyroscopic=gyroscopic, **options)
    m, omega = QuasiStaticModel(bearing, "iso_vg68_mineral", scene), rpm * RPM
    m.evaluate(omega=omega, T_oil=T_OIL, **{k: 1.01 * v for k, v in inputs.items()})
    F_applied = np.array([inputs.get(n, 0.0) if m.control[i] else 0.0 for i, n in enumerate(LOAD_NAMES)])
    d_imposed = np.array([0.0 if m.control[i] else inputs.get(n, 0.0) for i, n in enumerate(DOF_NAMES)])
    d0, X0, Z = np.where(m.control > 0.5, m.d, d_imposed), m.X.copy(), m.bearing.Z  # a step imposes new displacements
    fns = []
    for codes in VARIANTS.values():
        qs, cp = m.qs.copy(), m.cp.copy()
        cp[ck.CP_CAPACITANCE_BLOCK + CAP_ON], cp[ck.CP_TORQUE], qs[jones_harris.QS_STIFFNESS] = codes
        work = (np.zeros(5), np.zeros_like(X0), np.zeros(5), np.zeros((5, 5)), np.zeros((jones_harris.BQ_SIZE, Z)))
        outs = (np.zeros(ck.CO_SIZE), np.zeros((ck.PC_SIZE, Z)), np.zeros(TL_SIZE))
        args = (F_applied, m.control, d0, X0, qs, omega, T_OIL, cp, m.lubricant.array, *work, *outs)
        assert _repeat_step(1, *args) == 0, f"{label}: solver failed"
        fns.append(lambda n, args=args: _repeat_step(n, *args))
    return fns


def analytic_cost():
    """(off, on) timings of analytic_bearing (interleaved()), 6208 with clearance at 700 rad/s, 3 kN."""
    fns = []
    for capacitance in (False, True):
        m = AnalyticModel("6208", "guessasma_oil", Scene(capacitance=capacitance), Pd=10e-6)
        out, ball = np.zeros(radial_bearing.O_SIZE), np.zeros((8, m.bearing.Z))
        args = (700.0, 3000.0, T_OIL, m.brg, m.lubricant.array, m.nodes, m.weights, out, ball)
        fns.append(lambda n, args=args: _repeat_analytic(n, *args))
    return interleaved(fns)


def measure():
    rows = []
    for case in CASES:
        times = interleaved(quasi_static_steps(*case))
        rows += [[case[0], name, *row(t, times[0])] for name, t in zip(VARIANTS, times)]
    off, on = analytic_cost()
    label = "6208 analytic, P_d = 10 um, 700 rad/s, F_y = 3 kN, guessasma_oil"
    rows += [[label, "capacitance off", *row(off, off)], [label, "capacitance on", *row(on, off)]]
    return dict(
        name="option_cost",
        title="Cost of each scene option",
        about=__doc__.split("\n", 2)[2].split("Run:")[0],
        blocks=[
            dict(
                text="Times per warm step over {repeats} interleaved batches (about {batch:.0f} ms each) of a numba "
                "loop of steps. Cost against the first variant of the case: from the fastest batches (the least "
                "disturbed), and the median of the ratios of batches of the same repeat. Quasi-static: lubricant "
                "iso_vg68_mineral, T_oil = {T_oil:g} K, exact Hertz, centrifugal on.",
                values=dict(repeats=REPEATS, batch=1e3 * BATCH, T_oil=T_OIL),
            ),
            dict(
                table=dict(columns=COLUMNS, formats=[None, None, "{:.2f}", "{:.2f}", "{:+.1%}", "{:+.1%}"], rows=rows)
            ),
            dict(text=OPTIONS, values=dict(noise=max(r[2] / r[3] for r in rows))),
        ],
        metrics=[],
    )


def row(t, off):
    """Median and fastest batch (us), the cost against `off` from the fastest batches and the paired ratios."""
    return [1e6 * t[0], 1e6 * t[1], t[1] / off[1] - 1.0, t[2] - 1.0]


OPTIONS = """When on, **capacitance** adds the lubricant permittivity and the capacitance of every loaded contact; \
**torque** the Houpert loss components of every loaded contact, the friction coefficient, ring heats and the torque; \
**stiffness** the 5x5 stiffness output: under load control it is the Newton matrix of the solve, assembled anyway, \
so the option costs only the copy to the output; with displacement drive the solve needs no Newton matrix and the \
option adds its assembly. The per-ball outputs are not an option: they are computed once per solve.

Noise: the largest median / fastest ratio of a batch time above is {noise:.2f}; where it is well above 1 the \
machine was busy and differences of that order are not the options' cost."""


def main(argv=None):
    cli(measure, "option_cost")


if __name__ == "__main__":
    main()
