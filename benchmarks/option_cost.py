"""Cost of each scene option: what a warm co-simulation step of the kernels costs with the option on and off.

An option that is off is a null submodel in the kernels (its work is not done, tests/unit/
test_scene_options_skip_work.py), so its cost is the difference of the step times. One step = the work
of one FMU doStep in compiled code: for the quasi-static fidelity, solve_quasistatic warm-started from
the solution at loads (or imposed displacements) 1 % different, then contact_outputs; for the analytic
fidelity, analytic_bearing. The variants of a case differ only in the option codes of the parameter
arrays; they are timed side by side in one run, in interleaved batches (order rotated each repeat, so a
slow phase of the shared machine hits all alike), and the tables give the medians.
Run: python -m benchmarks.option_cost -> docs/reports/option_cost.md
"""

import math
import os
import statistics
import time

import numpy as np

from bearing_fmu.kernels import contacts as ck
from bearing_fmu.kernels import jones_harris as qk
from bearing_fmu.kernels import radial_bearing as ak
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.quasi_static import DOF_NAMES, LOAD_NAMES, QuasiStaticModel
from bearing_fmu.scene import Scene
from bearing_fmu_common.jit import kernel

from .common import machine, write_report

RPM = 2.0 * math.pi / 60.0
T_OIL = 313.15
BATCH = 0.02  # s: steps per batch chosen so that a batch lasts about this long (scheduler noise << batch)
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
        s += qk.solve_quasistatic(F_applied, control, d, qs, 0.0, omega, X, F, K, balls)[0]
        ck.contact_outputs(omega, T_oil, cp, lub, balls, out, pc, losses)
    return s


@kernel
def _repeat_analytic(n, omega, F_r, T_oil, brg, lub, nodes, weights, out, ball):
    for _ in range(n):
        ak.analytic_bearing(omega, F_r, T_oil, brg, lub, nodes, weights, out, ball)


def interleaved(fns):
    """Time per step of each fn(n) (n steps) over REPEATS interleaved batches, after a warm-up: for each fn
    (median, minimum, median over the repeats of its batch time / the first fn's batch time of the same
    repeat). The ratio pairs batches run a few ms apart, so a slow phase of the machine cancels out."""
    for fn in fns:
        fn(10)  # warm-up (compilation)
    t0 = time.perf_counter()
    fns[0](10)
    n = max(10, int(BATCH / max((time.perf_counter() - t0) / 10, 1e-9)))
    times = [[] for _ in fns]
    for r in range(REPEATS):
        order = list(range(len(fns)))
        order = order[r % len(order) :] + order[: r % len(order)]
        for k in order:
            t0 = time.perf_counter()
            fns[k](n)
            times[k].append((time.perf_counter() - t0) / n)
    return [(statistics.median(t), min(t), statistics.median(a / b for a, b in zip(t, times[0]))) for t in times]


class QuasiStaticCase:
    """One bearing, drive, speed and inputs; the warm start is the solution at inputs 1 % different."""

    def __init__(self, label, bearing, drive, rpm, inputs, gyroscopic=True):
        self.label = label
        scene = Scene(
            name="option_cost",
            fidelity="quasi_static",
            drive=drive,
            gyroscopic=gyroscopic,
            capacitance=True,
            torque=True,
            stiffness=True,
        )
        self.model = m = QuasiStaticModel(bearing, "iso_vg68_mineral", scene)
        self.omega = rpm * RPM
        near = {k: 1.01 * v for k, v in inputs.items()}
        m.evaluate(omega=self.omega, T_oil=T_OIL, **near)
        self.d0, self.X0 = m.d.copy(), m.X.copy()
        self.F_applied = np.array([inputs.get(n, 0.0) if m.control[i] else 0.0 for i, n in enumerate(LOAD_NAMES)])
        self.d_imposed = np.array([0.0 if m.control[i] else inputs.get(n, 0.0) for i, n in enumerate(DOF_NAMES)])
        self.d0 = np.where(m.control > 0.5, self.d0, self.d_imposed)  # a step imposes the new displacements

    def step(self, codes):
        m = self.model
        qs, cp = m.qs.copy(), m.cp.copy()
        cp[ck.CP_CAPACITANCE], cp[ck.CP_TORQUE], qs[qk.QS_STIFFNESS] = codes
        Z = m.bearing.Z
        work = (np.zeros(5), np.zeros((2, Z)), np.zeros(5), np.zeros((5, 5)), np.zeros((qk.BQ_SIZE, Z)))
        outs = (np.zeros(ck.CO_SIZE), np.zeros((ck.PC_SIZE, Z)), np.zeros(4))
        args = (self.F_applied, m.control, self.d0, self.X0, qs, self.omega, T_OIL, cp, m.lubricant.array)
        assert _repeat_step(1, *args, *work, *outs) == 0, f"{self.label}: solver failed"
        return lambda n: _repeat_step(n, *args, *work, *outs)


def quasi_static_cases():
    return [
        QuasiStaticCase("B7214C, load drive, rest, F_z = 800 N + F_y = 1 kN", "B7214C", "load", 0.0,
                        {"F_z": 800.0, "F_y": 1000.0}, gyroscopic=False),
        QuasiStaticCase("B7214C, load drive, 10 000 rpm ORCG, F_z = 800 N + F_y = 1 kN", "B7214C", "load",
                        10000.0, {"F_z": 800.0, "F_y": 1000.0}),
        QuasiStaticCase("B7214C, displacement drive, 10 000 rpm ORCG, z = 20 um, x = 2 um", "B7214C",
                        "displacement", 10000.0, {"z": 20e-6, "x": 2e-6}),
        QuasiStaticCase("6208, load drive, 3 000 rpm ORCG, F_y = 3 kN", "6208", "load", 3000.0, {"F_y": 3000.0}),
    ]  # fmt: skip


def analytic_cost():
    """(off, on) median time per analytic_bearing call (s), 6208 with clearance at 700 rad/s, 3 kN."""
    fns = []
    for capacitance in (False, True):
        m = AnalyticModel("6208", "guessasma_oil", Scene(capacitance=capacitance), Pd=10e-6)
        out, ball = np.zeros(ak.O_SIZE), np.zeros((8, m.bearing.Z))
        args = (700.0, 3000.0, T_OIL, m.brg, m.lubricant.array, m.nodes, m.weights, out, ball)
        fns.append(lambda n, args=args: _repeat_analytic(n, *args))
    return interleaved(fns)


def us(t):
    return f"{1e6 * t:.2f}"


def cost(variant, off):
    """The option's cost: from the fastest batches (the least disturbed), then the median of the paired ratios."""
    return f"{100 * (variant[1] / off[1] - 1):+.1f} % ({100 * (variant[2] - 1):+.1f} %)"


def main():
    load_before = os.getloadavg()[0]
    rows = []
    for case in quasi_static_cases():
        times = dict(zip(VARIANTS, interleaved([case.step(codes) for codes in VARIANTS.values()])))
        rows.append((case, times))
    a_off, a_on = analytic_cost()
    noise = max([t[0] / t[1] for _, times in rows for t in times.values()] + [a_off[0] / a_off[1], a_on[0] / a_on[1]])

    lines = [
        "# Cost of each scene option",
        "",
        f"Generated by `python -m benchmarks.option_cost` on {machine()} (2 cores, shared). A scene option "
        "that is off is a null submodel in the kernels: its work is not done and its output slots are not "
        "written (tests/unit/test_scene_options_skip_work.py). Times are per warm step of the compiled "
        f"kernels over {REPEATS} interleaved batches of a numba loop of steps (about {1e3 * BATCH:.0f} ms per "
        "batch), divided by the number of steps: median [fastest batch]. The cost of an option is given "
        "against 'all off' from the fastest batches (the least disturbed by other jobs on this shared "
        "machine), and in brackets as the median over the repeats of the ratio of its batch to the 'all off' "
        "batch of the same repeat (batches a few ms apart, so a slow phase of the machine cancels out). "
        "A quasi-static step = `solve_quasistatic` warm-started from the solution at inputs 1 % "
        "different, then `contact_outputs`; lubricant iso_vg68_mineral, T_oil = 313.15 K, exact Hertz, "
        "centrifugal on. The variants of a row differ only in the option codes (CP_CAPACITANCE, CP_TORQUE, "
        "QS_STIFFNESS) and are timed side by side in one run.",
        "",
        "## Quasi-static fidelity",
        "",
        "| case | all off (us) | + capacitance | + torque | + stiffness | all on |",
        "|---|---|---|---|---|---|",
    ]
    for case, t in rows:
        off = t["all off"]
        cells = [f"{us(off[0])} [{us(off[1])}]"]
        for name in ("capacitance", "torque", "stiffness", "all on"):
            v = t[name]
            cells.append(f"{us(v[0])} [{us(v[1])}]: {cost(v, off)}")
        lines.append(f"| {case.label} | " + " | ".join(cells) + " |")
    lines += [
        "",
        "What each option does when on:",
        "",
        "- **capacitance**: lubricant permittivity (Clausius-Mossotti at the Dowson-Higginson density) and "
        "the capacitance of every loaded contact, balls in series and parallel.",
        "- **torque**: the Houpert loss components (EHL rolling, hysteresis, Heathcote sliding, spin) of every "
        "loaded contact, the friction coefficient from the film parameter, ring heats and the torque.",
        "- **stiffness**: the 5x5 stiffness output. Under load control every DOF's stiffness is the Newton "
        "matrix of the solve and is assembled anyway, so the option costs only the copy to the output; with "
        "displacement drive the solve needs no Newton matrix and the option adds its assembly to the one "
        "load evaluation. Differences of a few % in either direction are below the resolution of this "
        "measurement on a shared machine.",
        "- Not an option: the per-ball outputs (kinematics, spin and rolling speeds, needed by the film, "
        "loss and output kernels) are computed once per solve, after convergence.",
        "",
        "## Analytic fidelity",
        "",
        "| case | capacitance off (us) | capacitance on |",
        "|---|---|---|",
        f"| 6208, P_d = 10 um, 700 rad/s, F_y = 3 kN, guessasma_oil | {us(a_off[0])} [{us(a_off[1])}] | "
        f"{us(a_on[0])} [{us(a_on[1])}]: {cost(a_on, a_off)} |",
        "",
        f"Noise: the largest median / minimum ratio of a batch time above is {noise:.2f}; where it is well "
        "above 1 the machine was busy and differences of that order are not the options' cost.",
        f"Machine load (1-min load average) at start / end of the run: {load_before:.2f} / "
        f"{os.getloadavg()[0]:.2f} on 2 cores.",
    ]
    write_report("option_cost.md", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
