"""DEM time step and tribology refresh against error and cost at three operating points, and in three transients.

Steady operating points (POINTS, tests/cases/dem_points.py): the 6208 of Guessasma & Machado (2018) at 3 kN,
500 rad/s; the B7214C of the spindle rig at 10 000 rpm under 800 N of thrust; the same bearing with cold oil (293 K)
at 16 rad/s, where the squeeze damping of the full film, not the contact stiffness, limits the step. At each, the fixed steps are
multiples (FACTORS) of the point's own automatic step (DemModel.automatic_time_step: safety x the stability limit of
the stiffest contact pair, and at most DAMPING_PLAN m / c of the most damped ball), with the tribology refreshed
every step, at the default interval (40 us) and every 100 steps; the reference is REF_FACTOR of that step with
every-step tribology. Error = |mean - reference| / reference of the
outputs' means over the last AVERAGE_OVER ms of RUN_TIME; runs above the limit show where the monitor stops.

Transients (TRANSIENTS, on the 6208): start-up from rest, a load step (3 -> 6 kN) and a speed step (500 ->
1000 rad/s in 1 ms). Each setting's trajectory of torque, cage speed, ring displacement y and outer film h_min
against the fine-step reference: max |x - x_ref| over the samples / max |x_ref|; and the quasi-static fidelity
driven in time through the same inputs (what a model without dynamics answers). Cost: CPU time of the thread per
simulated ms (time.thread_time; the machine is shared, its load average is recorded).

Run: python -m benchmarks.dem_steps -> docs/reports/dem_steps.md and .png
"""

import math
import re
import time

import numpy as np

from bearing_fmu.models.dem import REFRESH_INTERVAL, SAFETY, DemModel, DemUnstableError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.cases.dem_points import POINTS, warm

from .render import cli, metric

FACTORS = (0.25, 0.5, 1.0, 1.3, 1.6, 2.0, 2.5, 3.0)
REFRESHES = ("every step", "every 40 us", "every 100 steps")
REF_FACTOR = 0.1
RUN_TIME = 6e-3
AVERAGE_OVER = 4e-3
STEADY = ("Q_max_outer", "h_min_outer", "omega_cage", "C_bearing", "torque")
TRAJECTORY = ("torque", "omega_cage", "y", "h_min_outer")
# transient settings: (label, DemModel keyword arguments)
TRANSIENT_SETTINGS = (
    (f"default (safety {SAFETY:g}, refresh every {REFRESH_INTERVAL * 1e6:g} us)", {}),
    ("safety 0.8", {"safety": 0.8}),
    ("default dt, tribology every step", {"refresh": 1}),
    ("dt = 1 us, tribology every step (the papers')", {"dt": 1e-6, "refresh": 1}),
    ("default dt, refresh every 100 steps", {"refresh": 100}),
)
TRANSIENT_REFERENCE = {"dt": 0.1e-6, "refresh": 1}
SAMPLE = 0.1e-3  # s between trajectory samples


def monitor_cause(exc):
    """The cause the monitor names in a DemUnstableError's message (the clause before its advice on dt)."""
    match = re.search(r"\d: (.*?)\. dt = ", str(exc))
    return match.group(1) if match else str(exc)


def refresh_steps(label, dt):
    """The refresh interval in steps of a REFRESHES label at step dt (s); every 40 us by DemModel's own rule."""
    fixed = {"every step": 1, "every 100 steps": 100}
    return fixed.get(label) or max(1, math.floor(REFRESH_INTERVAL / dt * (1.0 + 1e-9)))


def steady_run(model, start, point, dt, refresh):
    """(means of STEADY over the last AVERAGE_OVER of RUN_TIME, CPU ms per simulated ms) of one fixed setting
    from the state `start`; (None, cause) when the monitor stops it."""
    model.set_state(start)
    model.dt_fixed, model.refresh_fixed = dt, refresh
    held = dict(point["loads"], T_oil=point["T_oil"], omega=point["omega"])
    samples, t0, c0 = [], model.time, time.thread_time()
    try:
        for k in range(1, round(RUN_TIME / 1e-3) + 1):
            samples.append(model.advance(t0 + k * 1e-3, **held))
    except DemUnstableError as exc:
        return None, monitor_cause(exc)
    cpu = (time.thread_time() - c0) / (RUN_TIME * 1e3) * 1e3
    last = samples[-round(AVERAGE_OVER / 1e-3) :]
    return {q: float(np.mean([s[q] for s in last])) for q in STEADY}, cpu


def stopped(cause, cells):
    return [f"stopped by the monitor: {cause}"] + [None] * cells


def steady_point(name, point):
    """The step study of one operating point: its automatic step and stiffness limit, the reference's cost and
    a table row per (factor, refresh): factor, dt (us), refresh, CPU, largest error, the error of each of STEADY."""
    model = warm(point)
    start = model.get_state()
    automatic = model.automatic_time_step(omega=point["omega"], **point["loads"])
    stiffness = model.stable_time_step(omega=point["omega"], **point["loads"])
    reference, ref_cpu = steady_run(model, start, point, REF_FACTOR * automatic, 1)
    rows = []
    for factor in FACTORS:
        for label in REFRESHES:
            dt = factor * automatic
            means, cpu = steady_run(model, start, point, dt, refresh_steps(label, dt))
            if means is None:
                rows.append([factor, dt * 1e6, label, *stopped(cpu, len(STEADY) + 1)])
                continue
            errors = [abs(means[q] / reference[q] - 1.0) for q in STEADY]
            rows.append([factor, dt * 1e6, label, cpu, max(errors), *errors])
    return dict(name=name, automatic=automatic, stiffness_limit=stiffness, reference_cpu=ref_cpu, rows=rows)


def transient_inputs(kind, t):
    """(omega rad/s, F_y N) of a transient at time t (s) after its start."""
    if kind == "start-up from rest":
        return min(max(t - 2e-3, 0.0) / 5e-3, 1.0) * 500.0, 3000.0
    if kind == "load step 3 -> 6 kN":
        return 500.0, 6000.0
    return 500.0 + 500.0 * min(t / 1e-3, 1.0), 3000.0


TRANSIENTS = {"start-up from rest": 15e-3, "load step 3 -> 6 kN": 5e-3, "speed step 500 -> 1000 rad/s in 1 ms": 5e-3}


def sampled(kind, evaluate):
    """evaluate(t, omega, F_y) at each sample time t (s from the start) of the transient: arrays of TRAJECTORY."""
    rows = []
    for k in range(1, round(TRANSIENTS[kind] / SAMPLE) + 1):
        rows.append(evaluate(k * SAMPLE, *transient_inputs(kind, k * SAMPLE)))
    return {q: np.array([r[q] for r in rows]) for q in TRAJECTORY}


def trajectory(kind, start, settings):
    """Samples of TRAJECTORY every SAMPLE over the transient from the state `start` (None: from rest) with the
    DemModel settings; returns (dict of arrays, CPU ms per simulated ms) or (None, cause) if the monitor stops."""
    model = DemModel("6208", "guessasma_oil", **settings)
    if start is not None:
        model.set_state(start)
    t0, c0 = model.time, time.thread_time()
    try:
        x = sampled(kind, lambda t, omega, F_y: model.advance(t0 + t, omega=omega, F_y=F_y))
    except DemUnstableError as exc:
        return None, monitor_cause(exc)
    return x, (time.thread_time() - c0) / (TRANSIENTS[kind] * 1e3) * 1e3


def quasi_static_trajectory(kind):
    """The quasi-static fidelity (torque on) at the transient's inputs at every sample time."""
    scene = Scene(name="qs", fidelity="quasi_static", centrifugal=True, gyroscopic=True, torque=True, stiffness=False)
    model = QuasiStaticModel("6208", "guessasma_oil", scene=scene)
    return sampled(kind, lambda t, omega, F_y: model.evaluate(omega=omega, F_y=F_y))


def trajectory_errors(x, ref):
    """Per quantity (largest, mean): max |x - x_ref| / max |x_ref| over the samples, and |mean x - mean x_ref| /
    max |x_ref| (for the torque: the error of the energy dissipated over the transient); None for a reference that
    stays 0."""
    scales = {q: float(np.max(np.abs(ref[q]))) for q in TRAJECTORY}
    return {
        q: (float(np.max(np.abs(x[q] - ref[q]))) / scale, abs(float(np.mean(x[q]) - np.mean(ref[q]))) / scale)
        if scale > 0.0
        else None
        for q, scale in scales.items()
    }


def pair(errors):
    return None if errors is None else f"{errors[0]:.1e} / {errors[1]:.1e}"


def transient(kind, steady_state):
    """One transient: the reference's cost, a table row per TRANSIENT_SETTINGS run and one of the quasi-static
    fidelity (setting, CPU, the errors of each of TRAJECTORY), the default's and the quasi-static fidelity's
    torque errors, and the torque trajectories of the reference and of the quasi-static fidelity."""
    start = None if kind == "start-up from rest" else steady_state
    reference, ref_cpu = trajectory(kind, start, TRANSIENT_REFERENCE)
    rows, torque = [], {}
    for label, settings in TRANSIENT_SETTINGS:
        x, cpu = trajectory(kind, start, settings)
        if x is None:
            rows.append([label, *stopped(cpu, len(TRAJECTORY))])
            continue
        errors = trajectory_errors(x, reference)
        rows.append([label, cpu, *map(pair, errors.values())])
        torque[label] = errors["torque"]
    qs = quasi_static_trajectory(kind)
    qs_errors = trajectory_errors(qs, reference)
    rows.append(["quasi-static fidelity driven in time", None, *map(pair, qs_errors.values())])
    default = torque[TRANSIENT_SETTINGS[0][0]]
    return dict(kind=kind, reference_cpu=ref_cpu, rows=rows, default=default, quasi_static=qs_errors["torque"],
                reference=reference["torque"].tolist(), qs=qs["torque"].tolist())  # fmt: skip


def measure():
    points = [steady_point(name, point) for name, point in POINTS.items()]
    steady_6208 = warm(POINTS["6208, 3 kN, 500 rad/s"]).get_state()
    transients = [transient(kind, steady_6208) for kind in TRANSIENTS]
    intro = (
        "CPU = the thread's CPU time per simulated ms. Steps are fractions of each point's own automatic step (safety "
        "{safety:g} x the stability limit, or less where the film's damping asks); errors are relative to a reference "
        "at {ref:g} x that step with tribology every step. Step factors (FACTORS): {factors}; means over the last "
        "{average:g} ms of {run:g} ms."
    )
    values = dict(safety=SAFETY, ref=REF_FACTOR, factors=", ".join(f"{f:g}" for f in FACTORS),
                  average=AVERAGE_OVER * 1e3, run=RUN_TIME * 1e3)  # fmt: skip
    blocks = [
        dict(text=intro, values=values),
        dict(text="## Larger steps than the automatic one"),
        dict(table=summary_table(points)),
        dict(text="## Steady operating points"),
    ]
    for p in points:
        blocks += point_blocks(p)
    blocks.append(dict(text="## Transients (6208, guessasma_oil, 313 K)"))
    for t in transients:
        blocks += transient_blocks(t)
    blocks.append(dict(figure=figure(points, transients[0])))
    return dict(
        name="dem_steps",
        title="DEM time step and tribology refresh: three operating points and three transients",
        about=__doc__.split("\n", 2)[2].split("Run:")[0],
        blocks=blocks,
        metrics=headlines(points, transients),
    )


def summary_table(points):
    """Per step factor: stable at every point with every refresh, and the largest steady error there."""
    rows = []
    for factor in FACTORS:
        runs = [r for p in points for r in p["rows"] if r[0] == factor]
        worst = max((r[4] for r in runs if r[4] is not None), default=None)
        stable = "yes" if all(r[4] is not None for r in runs) else "no"
        rows.append([f"{factor:g}" + (" (the default)" if factor == 1.0 else ""), stable, worst])
    columns = ["dt (x automatic)", "stable at the three points, every refresh", "largest steady error"]
    return dict(columns=columns, formats=[None, None, "{:.1e}"], rows=rows)


def section(heading, text, values, columns, formats, rows):
    table = dict(columns=columns, formats=formats, rows=rows)
    return [dict(text="### {heading}", values=dict(heading=heading)), dict(text=text, values=values), dict(table=table)]


def point_blocks(p):
    text = (
        "Automatic step {automatic:.3g} us (stability limit of the stiffest pair {limit:.3g} us); reference "
        "{reference:.3g} us with tribology every step ({cpu:.3g} ms CPU per simulated ms)."
    )
    values = dict(automatic=p["automatic"] * 1e6, limit=p["stiffness_limit"] * 1e6,
                  reference=REF_FACTOR * p["automatic"] * 1e6, cpu=p["reference_cpu"])  # fmt: skip
    columns = ["dt (x automatic)", "dt (us)", "refresh", "CPU (ms/ms)", "largest error", *STEADY]
    formats = ["{:g}", "{:.3g}", None, "{:.3g}"] + ["{:.1e}"] * (len(STEADY) + 1)
    return section(p["name"], text, values, columns, formats, p["rows"])


def transient_blocks(t):
    text = (
        "Reference: dt = {dt:g} us, tribology every step ({cpu:.3g} ms CPU per simulated ms); samples every "
        "{sample:g} ms (outputs averaged over each). Errors: largest over the samples of |x - x_ref| / max |x_ref|, "
        "then (after the slash) the error of the mean over the transient, |mean x - mean x_ref| / max |x_ref| (for "
        "the torque, of the energy dissipated)."
    )
    values = dict(dt=TRANSIENT_REFERENCE["dt"] * 1e6, cpu=t["reference_cpu"], sample=SAMPLE * 1e3)
    formats = [None, "{:.3g}"] + [None] * len(TRAJECTORY)
    return section(t["kind"], text, values, ["setting", "CPU (ms/ms)", *TRAJECTORY], formats, t["rows"])


def figure(points, start):
    panels = []
    for p in points:
        series = []
        for label, style in zip(REFRESHES, ("o-", "s-", "^-")):
            rows = [r for r in p["rows"] if r[2] == label and r[4] is not None]
            series.append(dict(x=[r[3] for r in rows], y=[r[4] for r in rows], style=style, label=f"refresh {label}",
                               annotate=[f"{r[0]:g}" for r in rows]))  # fmt: skip
        panels.append(dict(title=p["name"], xlabel="CPU per simulated ms (ms)", xscale="log", yscale="log",
                           ylabel="largest relative error of the steady outputs", series=series))  # fmt: skip
    t = [(k + 1) * SAMPLE * 1e3 for k in range(len(start["reference"]))]
    series = [dict(x=t, y=start["reference"], style="k-", label="DEM, fine-step reference"),
              dict(x=t, y=start["qs"], style="r--", label="quasi-static driven in time")]  # fmt: skip
    panels.append(dict(title="start-up from rest (6208): torque", xlabel="time (ms)", ylabel="torque (N.m)",
                       series=series))  # fmt: skip
    return dict(file="dem_steps.png", caption="error against cost; start-up torque", panels=panels,
                columns=len(panels), size=(5.0 * len(panels), 4.2))  # fmt: skip


def headlines(points, transients):
    """Per operating point the default's largest steady error and cost and the largest stable step; per transient
    the default's error of the dissipated energy and of the worst sample, and the quasi-static fidelity's
    difference from the DEM reference."""
    metrics = []
    for p in points:
        default = next(r for r in p["rows"] if r[0] == 1.0 and r[2] == "every 40 us")
        stable = max(r[0] for r in p["rows"] if r[4] is not None)
        metrics += [
            metric(f"{p['name']}, default: largest steady error", default[4], "1", "error"),
            metric(f"{p['name']}, default: CPU ms per simulated ms", default[3], "1", "timing"),
            metric(f"{p['name']}: largest step run without a monitor stop (x automatic)", stable, "1", "count"),
        ]
    for t in transients:
        qs = t["quasi_static"]
        metrics += [
            metric(f"{t['kind']}, default: energy (mean torque) error", t["default"][1], "1", "error"),
            metric(f"{t['kind']}, default: torque error at the worst sample", t["default"][0], "1", "error"),
            metric(f"{t['kind']}, quasi-static driven in time: torque at the worst sample", qs[0], "1", "difference"),
        ]
    return metrics


def main(argv=None):
    cli(measure, "dem_steps")


if __name__ == "__main__":
    main()
