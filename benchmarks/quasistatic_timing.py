"""Time per solve of the quasi-static model against the performance budget (docs/architecture.md: solve
<= 100 us at rest, <= 500 us at 10 000 rpm with centrifugal and gyroscopic effects, warm, 9-20 balls;
Jacobian <= 50 % extra; the race control from traction <= 3 x outer-race control on the same case, warm).

- kernels.jones_harris.solve_quasistatic, cold (d and X zeroed before each call) and warm (d and X
  copied before each call from the solution at a load 1 % different: what a co-simulation step sees);
- one ring_loads evaluation (ball equilibria + loads + condensed 5x5 Jacobian: the cost of one
  Newton iteration) against the same evaluation without the Jacobian assembly (jacobian=False), and
  bearing_loads (ring_loads + the per-ball outputs, which the solver computes once per solve);
- QuasiStaticModel.evaluate (input checks + solve + film, capacitance, Houpert torque + output dict).
Kernel figures are medians of 15 batches of a numba loop of N calls divided by N (no Python dispatch);
the facade figures are medians of 15 batches of Python calls.
Run: python -m benchmarks.quasistatic_timing -> docs/reports/quasistatic_timing.md
"""

import math
import statistics

import numpy as np

from bearing_fmu.kernels import ball_traction as bt
from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import jones_harris
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models.quasi_static import LOAD_NAMES, QuasiStaticModel
from bearing_fmu.scene import Scene
from bearing_fmu_common.jit import kernel

from .common import median_time, rotated_batches
from .render import cli, metric

RPM = 2.0 * math.pi / 60.0
T_OIL = 313.15
TARGET_REST = 100e-6
TARGET_SPEED = 500e-6
TARGET_JACOBIAN = 0.50
TARGET_TRACTION = 3.0  # warm solve of the race control "traction" over outer-race control's, same case
N_SOLVE = 200  # calls per batch inside the numba loop
N_LOADS = 2000


def scene(gyroscopic):
    return Scene(
        name="qs_timing", fidelity="quasi_static", centrifugal=True, gyroscopic=gyroscopic, torque=True, stiffness=True
    )


# numba drivers: N calls, the state copied in before each
@kernel
def _repeat_solve(n, F_applied, control, d0, X0, qs, dPd, omega, d, X, F, K, balls):
    r = (0, 0, 0.0)
    for _ in range(n):
        d[:] = d0
        X[:, :] = X0
        r = jones_harris.solve_quasistatic(F_applied, control, d, qs, dPd, omega, X, F, K, balls)
    return r


@kernel
def _repeat_loads(n, d, X0, qs, dPd, omega, X, F, K, balls):
    s = 0
    for _ in range(n):
        X[:, :] = X0
        s += jones_harris.bearing_loads(d, qs, dPd, omega, X, F, K, balls)
    return s


@kernel
def _repeat_ring_loads(n, d, X0, qs, dPd, omega, X, F, K, contact, jacobian):
    s = 0
    for _ in range(n):
        X[:, :] = X0
        s += jones_harris.ring_loads(d, qs, dPd, omega, X, F, K, contact, jacobian)
    return s


class Case:
    """One bearing, race control, speed and load; the solutions at the load and at 1.01 x the load."""

    def __init__(self, label, bearing, loads, rpm, race="outer", gyroscopic=False):
        self.label, self.rpm = label, rpm
        self.model = QuasiStaticModel(bearing, "iso_vg68_mineral", scene(gyroscopic), race_control=race)
        self.race = race
        self.Z, self.omega, self.F = self.model.bearing.Z, rpm * RPM, np.array([loads.get(n, 0.0) for n in LOAD_NAMES])
        self.work = (np.zeros(5), self.X0(), np.zeros(5), np.zeros((5, 5)), np.zeros((jones_harris.BQ_SIZE, self.Z)))
        if race == "traction":  # the film's traction at the oil temperature, as the facade sets it
            eta, xi, _ = lubricant_state(T_OIL, self.model.lubricant.array)
            self.model.qs[jones_harris.QS_TRACTION + bt.TR_ETA] = eta
            self.model.qs[jones_harris.QS_TRACTION + bt.TR_XI] = xi
        # neighbour solution (load 1 % higher), then the solution itself, both from a cold start (traction: from the
        # outer-race-controlled solution, as the facade starts it when its own cold start stalls)
        self.d_near, self.X_near, _ = self.solve(1.01 * self.F, *self.start())
        self.d_sol, _, self.cold_status = self.solve(self.F, *self.start())
        self.warm_status = self.solve(self.F, self.d_near, self.X_near)[2]

    def X0(self):
        return np.zeros((jones_harris.X_SIZE, self.Z))

    def start(self):
        """The cold start (d, X): zeros."""
        return np.zeros(5), self.X0()

    def solve(self, F, d0, X0):
        d, X, Fo, K, balls = self.work
        d[:], X[:] = d0, X0
        status = jones_harris.solve_quasistatic(
            F, self.model.control, d, self.model.qs, 0.0, self.omega, X, Fo, K, balls
        )
        if status[0] != jones_harris.QS_OK:
            raise RuntimeError(f"{self.label}: solver status {status} for F = {F}")
        return d.copy(), X.copy(), status

    def time_solve(self, d0, X0):
        """(median, minimum) time per solve over 15 batches of N_SOLVE solves."""
        d, X, Fo, K, balls = self.work
        args = (N_SOLVE, self.F, self.model.control, d0, X0, self.model.qs, 0.0, self.omega, d, X, Fo, K, balls)
        t = rotated_batches([lambda: _repeat_solve(*args)], 15)[0]
        return statistics.median(t) / N_SOLVE, min(t) / N_SOLVE

    def time_loads(self):
        """One Newton iteration near convergence (d = solution, X from the 1 % neighbour), with and without the
        Jacobian assembly and with the per-ball outputs, in interleaved batches: the three medians per call and
        the Jacobian's extra cost (median of the batch-by-batch ratio - 1, ratio of the fastest batches - 1)."""
        _, X, Fo, K, balls = self.work
        qs, om = self.model.qs, self.omega
        contact = np.zeros((jones_harris.CS_SIZE, self.Z))
        args = (self.d_sol, self.X_near, qs, 0.0, om, X, Fo, K)
        full, no_k, with_balls = rotated_batches(
            [
                lambda: _repeat_ring_loads(N_LOADS, *args, contact, True),
                lambda: _repeat_ring_loads(N_LOADS, *args, contact, False),
                lambda: _repeat_loads(N_LOADS, *args, balls),
            ],
            31,
        )
        extra = (statistics.median([a / b - 1.0 for a, b in zip(full, no_k)]), min(full) / min(no_k) - 1.0)
        F = {True: np.zeros(5), False: np.zeros(5)}  # the same loads with and without the Jacobian
        for jacobian, loads in F.items():
            X[:] = self.X_near
            jones_harris.ring_loads(self.d_sol, qs, 0.0, om, X, loads, K, contact, jacobian)
        assert np.array_equal(F[True], F[False]), F
        return (*(statistics.median(t) / N_LOADS for t in (full, no_k, with_balls)), extra)


def cases():
    axial, combined, speed = {"F_z": 800.0}, {"F_z": 800.0, "F_y": 1000.0}, 10000.0
    return [
        Case("6208 (Z = 9), rest, F_y = 3 kN", "6208", {"F_y": 3000.0}, 0.0),
        Case("6208 (Z = 9), rest, F_y = 3 kN + F_z = 1 kN", "6208", {"F_y": 3000.0, "F_z": 1000.0}, 0.0),
        Case("B7214C (Z = 17), rest, F_z = 800 N", "B7214C", axial, 0.0),
        Case("B7214C (Z = 17), rest, F_z = 800 N + F_y = 1 kN", "B7214C", combined, 0.0),
        Case("B7214C, 10 000 rpm, ORCG (outer + gyro), F_z = 800 N", "B7214C", axial, speed, "outer", True),
        Case("B7214C, 10 000 rpm, ORCG, F_z = 800 N + F_y = 1 kN", "B7214C", combined, speed, "outer", True),
        Case("B7214C, 10 000 rpm, hybrid + gyro, F_z = 800 N", "B7214C", axial, speed, "hybrid", True),
        Case("B7214C, 10 000 rpm, hybrid + gyro, F_z = 800 N + F_y = 1 kN", "B7214C", combined, speed, "hybrid", True),
        Case("B7214C, 10 000 rpm, traction, F_z = 800 N", "B7214C", axial, speed, "traction", True),
        Case("B7214C, 10 000 rpm, traction, F_z = 800 N + F_y = 1 kN", "B7214C", combined, speed, "traction", True),
    ]


def facade_times(case):
    """QuasiStaticModel.evaluate at the case's inputs: state at the solution (repeat of the same step)
    and state reset to the 1 % neighbour before each call (a co-simulation step)."""
    m, inputs = case.model, {n: float(v) for n, v in zip(LOAD_NAMES, case.F) if v} | dict(omega=case.omega, T_oil=T_OIL)

    def reset_only():
        m.d[:], m.X[:] = case.d_near, case.X_near

    def step():
        reset_only()
        return m.evaluate(**inputs)

    t_step, t_reset = median_time(step, number=300), median_time(reset_only, number=300)
    step()
    iters_step = m.status[1]
    t_same = median_time(lambda: m.evaluate(**inputs), number=300)
    iters_same = m.status[1]
    contacts = (case.omega, T_OIL, m.cp, m.lubricant.array, m.balls, m.out, m.per_contact, m._losses)
    t_contacts = median_time(ck.contact_outputs, *contacts, number=2000)
    return t_step - t_reset, iters_step, t_same, iters_same, t_contacts, t_reset


def measure():
    all_cases = cases()
    solves = [(c, c.time_solve(*c.start()), c.time_solve(c.d_near, c.X_near)) for c in all_cases]
    loads = [(c, *c.time_loads()) for c in all_cases]
    facade = [(c, *facade_times(c)) for c in all_cases if c.rpm > 0.0]
    target_rows, metrics = targets(solves, loads)
    solve_rows = [
        [c.label, *(1e6 * t for t in cold), c.cold_status[1], *(1e6 * t for t in warm), c.warm_status[1]]
        + [1e6 * target(c), warm[0] / target(c)]
        for c, cold, warm in solves
    ]
    return dict(
        name="quasistatic_timing",
        title="Quasi-static solver timing (medians)",
        about=__doc__.split("Run:")[0],
        blocks=[
            dict(text=SETUP, values=dict(n_solve=N_SOLVE, n_loads=N_LOADS, tolerance=scene(False).tolerance)),
            table(
                "target|measured median, worst case of the tables below|minimum of the batches|unit|case"
                "|median / target",
                "|{:.1f}|{:.1f}|||{:.3f}",
                target_rows,
                "## Targets (performance budget, docs/architecture.md) against the measured medians",
            ),
            cold_starts(solves),
            table(
                "case|cold|cold, minimum|iterations|warm|warm, minimum|iterations|warm target|warm / target",
                "|{:.1f}|{:.1f}|{}|{:.1f}|{:.1f}|{}|{:.0f}|{:.3f}",
                solve_rows,
                "## solve_quasistatic\n\nTimes per solve (us): median over 15 batches and minimum of the batches.",
            ),
            dict(text=NEWTON, values=dict(n_loads=N_LOADS)),
            table(
                "case|ring_loads with K (us)|without K assembly (us)|Jacobian extra|fastest batches"
                "|bearing_loads: with K + per-ball outputs (us)",
                "|{:.2f}|{:.2f}|{:+.1%}|{:+.1%}|{:.2f}",
                [[c.label, 1e6 * f, 1e6 * n, x[0], x[1], 1e6 * b] for c, f, n, b, x in loads],
            ),
            per_ball(loads),
            table(
                "case|step (us)|iterations|repeat (us)|iterations|contact_outputs (us)",
                "|{:.1f}|{}|{:.1f}|{}|{:.1f}",
                [[c.label, 1e6 * a, i, 1e6 * b, k, 1e6 * co] for c, a, i, b, k, co, _ in facade],
                FACADE,
            ),
            dict(
                text="Reset of d and X from Python, subtracted above: {reset:.1f} us. The largest median / minimum "
                "ratio of a solve row above is {noise:.2f} (other jobs share the machine); where the two differ "
                "much, the minimum is the uncontended figure and the median the one a busy machine gives.",
                values=dict(reset=1e6 * facade[0][6], noise=max(t[0] / t[1] for _, *ts in solves for t in ts)),
            ),
        ],
        metrics=metrics,
    )


def table(columns, formats, rows, caption=None):
    """A table block from "|"-separated column names and formats (an empty format: the value as it is)."""
    return dict(table=dict(caption=caption, columns=columns.split("|"), formats=[f or None for f in formats.split("|")],
                           rows=rows))  # fmt: skip


def targets(solves, loads):
    """Rows of the targets table and the metrics: the worst case of each target."""
    rows, metrics = [], []
    for what, moving, budget in (
        ("warm solve at rest <= 100 us", False, TARGET_REST),
        ("warm solve at 10 000 rpm, centrifugal + gyroscopic <= 500 us", True, TARGET_SPEED),
    ):
        c, _, warm = max(
            (r for r in solves if (r[0].rpm > 0.0) == moving and r[0].race != "traction"), key=lambda r: r[2][0]
        )
        rows.append([what, 1e6 * warm[0], 1e6 * warm[1], "us", c.label, warm[0] / budget])
        metrics.append(metric(what, warm[0], "s", "timing", target=budget, note=c.label))
    # the race control from traction against outer-race control on the same bearing and loads, warm: the worst case
    outer = {(c.F.tobytes(), c.omega): warm for c, _, warm in solves if c.race == "outer" and c.rpm > 0.0}
    ratios = [
        (warm[0] / outer[c.F.tobytes(), c.omega][0], warm[1] / outer[c.F.tobytes(), c.omega][1], c)
        for c, _, warm in solves
        if c.race == "traction"
    ]
    if ratios:
        median, fastest, c = max(ratios, key=lambda r: r[0])
        what = "warm solve, race control traction <= 3 x outer-race control"
        rows.append([what, median, fastest, "x", c.label, median / TARGET_TRACTION])
        metrics.append(metric(what, median, "1", "timing", TARGET_TRACTION, side_by_side=True, note=c.label))
    c, *_, extra = max(loads, key=lambda x: x[4][0])
    rows.append(["Jacobian <= 50 % extra", 100 * extra[0], 100 * extra[1], "%", c.label, extra[0] / TARGET_JACOBIAN])
    metrics.append(metric("Jacobian extra", extra[0], "1", "timing", TARGET_JACOBIAN, side_by_side=True, note=c.label))
    return rows, metrics


def target(case):
    return TARGET_REST if case.rpm == 0.0 else TARGET_SPEED


def cold_starts(solves):
    """The slowest cold start at rest and at speed against the warm target."""
    values = {}
    for key, moving in (("rest", False), ("speed", True)):
        c, cold, _ = max((r for r in solves if (r[0].rpm > 0.0) == moving), key=lambda r: r[1][0])
        values |= {key: 1e6 * cold[0], f"{key}_case": c.label, f"{key}_ratio": cold[0] / target(c)}
        values[f"{key}_verdict"] = "inside" if cold[0] <= target(c) else "above"
    return dict(
        text="Cold starts (not the target's case): slowest at rest {rest:.1f} us ({rest_case}), {rest_ratio:.3f} x "
        "the warm target, {rest_verdict} it; at 10 000 rpm {speed:.1f} us ({speed_case}), {speed_ratio:.3f} x the "
        "warm target, {speed_verdict} it. The Jacobian target row is the cost of assembling K inside one load "
        "evaluation (section below), worst case over the table; values within a few % of zero, negative ones "
        "included, are below the resolution of this measurement.",
        values=values,
    )


def per_ball(loads):
    share = [(c.rpm > 0.0, max(0.0, b / f - 1.0)) for c, f, n, b, x in loads]  # noise can go < 0
    rest, speed = [x for moving, x in share if not moving], [x for moving, x in share if moving]
    return dict(
        text="The per-ball outputs would add {rest_min:.0%}-{rest_max:.0%} to every load evaluation at rest and "
        "{speed_min:.0%}-{speed_max:.0%} at 10 000 rpm; the solver computes them once per solve, after "
        "convergence, not at every iteration and backtracking step.",
        values=dict(rest_min=min(rest), rest_max=max(rest), speed_min=min(speed), speed_max=max(speed)),
    )


SETUP = """Kernel figures: median over 15 batches of a numba loop of {n_solve} solves (or {n_loads} load \
evaluations) divided by the count, after a warm-up call that compiles (no Python dispatch). Facade figures: median \
over 15 batches of 300 Python calls. Scene: centrifugal on, exact Hertz, tolerance {tolerance:g}, lubricant \
iso_vg68_mineral, T_oil = 313.15 K. **cold**: d = 0 and X = 0 copied in before each call (the facade's fallback \
after a failed warm start); **warm**: d and X copied in before each call from the solution at every applied load \
x 1.01 (one co-simulation step); iterations: bearing evaluations after the first (one per Newton iteration plus \
one per cut line-search step)."""

NEWTON = """## Cost of one Newton iteration and of the Jacobian

`ring_loads` = per ball: ball equilibrium (at speed a 2-unknown Newton on the ball position, warm from X), ring \
loads and, with `jacobian`, the condensed 5x5 stiffness: one Newton iteration, at the solution d with X copied in \
from the 1 % neighbour (loads with and without the Jacobian checked bit-identical). `bearing_loads` adds the \
per-ball outputs (kinematics, spin and rolling speeds). 31 interleaved batches of {n_loads} calls: batch medians; \
'Jacobian extra' = median of the batch-by-batch ratio minus 1 (and the ratio of the fastest batches minus 1).

The global solve is a Newton iteration on the 5 loads with K as its matrix, so exposing K as an output costs \
nothing beyond the solve (with displacement drive there is no Newton matrix and the stiffness option adds the \
assembly: docs/reports/option_cost.md). 'without K assembly' removes only the 5x5 accumulation per ball, not the \
per-ball partials and the 2x2 condensation inside `ball_equilibrium`/`_ball_eval`, which are bounded above by the \
whole per-ball cost. A forward-difference Jacobian of the 5 DOFs would need 5 more load evaluations."""

FACADE = """## QuasiStaticModel.evaluate at 10 000 rpm (warm)

Input checks, solve, film/Lambda/regime, capacitance, Houpert torque and heat, output dict. 'step' = state (d, X) \
reset to the 1 % neighbour before each call (the reset's own time, measured alone, is subtracted); 'repeat' = the \
same inputs again, state at the solution. `contact_outputs` = the film, capacitance and torque kernel alone."""


def main(argv=None):
    cli(measure, "quasistatic_timing")


if __name__ == "__main__":
    main()
