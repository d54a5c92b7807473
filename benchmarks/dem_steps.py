"""DEM time step and tribology refresh against error and cost at three operating points, and in three transients.

Steady operating points (POINTS): the 6208 of Guessasma & Machado (2018) at 3 kN, 500 rad/s; the B7214C of the
spindle rig at 10 000 rpm under 800 N of thrust; the same bearing with cold oil (293 K) at 16 rad/s, where the
squeeze damping of the full film, not the contact stiffness, limits the step. At each, the fixed steps are
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

measure() returns everything as a dict; render() writes docs/reports/dem_steps.md and .png from it.
Run: python -m benchmarks.dem_steps
"""

import math
import os
import re
import time

import numpy as np

from bearing_fmu.models.dem import REFRESH_INTERVAL, SAFETY, DemModel, DemUnstableError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

from .common import REPORTS, forget, machine, record, write_report

POINTS = {
    "6208, 3 kN, 500 rad/s": dict(
        bearing="6208", lubricant="guessasma_oil", T_oil=313.15, loads={"F_y": 3000.0}, omega=500.0, ramp=5e-3, settle=30e-3
    ),
    "B7214C, 800 N thrust, 10 000 rpm": dict(
        bearing="B7214C", lubricant="iso_vg68_mineral", T_oil=313.15, loads={"F_z": 800.0}, omega=1047.1975511965977,
        ramp=10e-3, settle=0.3,
    ),
    "B7214C, 800 N thrust, cold oil (293 K), 16 rad/s": dict(
        bearing="B7214C", lubricant="iso_vg68_mineral", T_oil=293.15, loads={"F_z": 800.0}, omega=16.0, ramp=30e-3,
        settle=60e-3,
    ),
}  # fmt: skip
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


def warm(point, **settings):
    """A DemModel of the point in steady rolling: 2 ms at rest, a ramp to the speed, held to point['settle']."""
    model = DemModel(point["bearing"], point["lubricant"], **settings)
    held = dict(point["loads"], T_oil=point["T_oil"])
    model.advance(2e-3, omega=0.0, **held)
    for k in range(1, 21):
        model.advance(2e-3 + point["ramp"] * k / 20, omega=point["omega"] * k / 20, **held)
    model.advance(point["settle"], omega=point["omega"], **held)
    return model


def monitor_cause(exc):
    """The cause the monitor names in a DemUnstableError's message (the clause before its advice on dt)."""
    match = re.search(r"\d: (.*?)\. dt = ", str(exc))
    return match.group(1) if match else str(exc)


def refresh_steps(label, dt):
    """The refresh interval in steps of a REFRESHES label at step dt (s)."""
    if label == "every step":
        return 1
    if label == "every 100 steps":
        return 100
    return max(1, math.floor(REFRESH_INTERVAL / dt * (1.0 + 1e-9)))


def steady_run(model, start, point, dt, refresh):
    """(means of STEADY over the last AVERAGE_OVER of RUN_TIME, CPU ms per simulated ms) of one fixed setting
    from the state `start`; (None, cause) when the monitor stops it."""
    model.set_state(start)
    model.dt_fixed, model.refresh_fixed = dt, refresh
    held = dict(point["loads"], T_oil=point["T_oil"], omega=point["omega"])
    t0, n = model.time, round(RUN_TIME / 1e-3)
    samples = []
    c0 = time.thread_time()
    try:
        for k in range(1, n + 1):
            samples.append(model.advance(t0 + k * 1e-3, **held))
    except DemUnstableError as exc:
        return None, monitor_cause(exc)
    cpu = (time.thread_time() - c0) / (RUN_TIME * 1e3) * 1e3
    last = samples[-round(AVERAGE_OVER / 1e-3) :]
    return {q: float(np.mean([s[q] for s in last])) for q in STEADY}, cpu


def steady_point(name, point):
    """The step study of one operating point: its automatic step and stiffness limit, the reference and every
    (factor, refresh) run."""
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
            errors = None if means is None else {q: abs(means[q] / reference[q] - 1.0) for q in STEADY}
            rows.append(dict(factor=factor, refresh=label, dt=dt, cpu=cpu if means else None, errors=errors,
                             stopped=None if means else cpu))  # fmt: skip
    return dict(name=name, automatic=automatic, stiffness_limit=stiffness, reference=reference, reference_cpu=ref_cpu,
                rows=rows)  # fmt: skip


def transient_inputs(kind, t):
    """(omega rad/s, F_y N) of a transient at time t (s) after its start."""
    if kind == "start-up from rest":
        return min(max(t - 2e-3, 0.0) / 5e-3, 1.0) * 500.0, 3000.0
    if kind == "load step 3 -> 6 kN":
        return 500.0, 6000.0
    return 500.0 + 500.0 * min(t / 1e-3, 1.0), 3000.0


TRANSIENTS = {"start-up from rest": 15e-3, "load step 3 -> 6 kN": 5e-3, "speed step 500 -> 1000 rad/s in 1 ms": 5e-3}


def trajectory(kind, start, settings):
    """Samples of TRAJECTORY every SAMPLE over the transient from the state `start` (None: from rest) with the
    DemModel settings; returns (dict of arrays, CPU ms per simulated ms) or (None, cause) if the monitor stops."""
    model = DemModel("6208", "guessasma_oil", **settings)
    if start is not None:
        model.set_state(start)
    t0, duration = model.time, TRANSIENTS[kind]
    n = round(duration / SAMPLE)
    rows = []
    c0 = time.thread_time()
    try:
        for k in range(1, n + 1):
            omega, F_y = transient_inputs(kind, k * SAMPLE)
            rows.append(model.advance(t0 + k * SAMPLE, omega=omega, F_y=F_y))
    except DemUnstableError as exc:
        return None, monitor_cause(exc)
    cpu = (time.thread_time() - c0) / (duration * 1e3) * 1e3
    return {q: np.array([r[q] for r in rows]) for q in TRAJECTORY}, cpu


def quasi_static_trajectory(kind):
    """The quasi-static fidelity (torque on) at the transient's inputs at every sample time."""
    model = QuasiStaticModel(
        "6208", "guessasma_oil", scene=Scene(name="qs", fidelity="quasi_static", centrifugal=True, gyroscopic=True,
                                             torque=True, stiffness=False),
    )  # fmt: skip
    n = round(TRANSIENTS[kind] / SAMPLE)
    rows = []
    for k in range(1, n + 1):
        omega, F_y = transient_inputs(kind, k * SAMPLE)
        rows.append(model.evaluate(omega=omega, F_y=F_y))
    return {q: np.array([r[q] for r in rows]) for q in TRAJECTORY}


def trajectory_errors(x, ref):
    """Per quantity (largest, mean): max |x - x_ref| / max |x_ref| over the samples, and |mean x - mean x_ref| /
    max |x_ref| (for the torque: the error of the energy dissipated over the transient); None for a reference that
    stays 0."""
    errors = {}
    for q in TRAJECTORY:
        scale = float(np.max(np.abs(ref[q])))
        if scale == 0.0:
            errors[q] = None
            continue
        errors[q] = (float(np.max(np.abs(x[q] - ref[q]))) / scale, abs(float(np.mean(x[q]) - np.mean(ref[q]))) / scale)
    return errors


def transient(kind, steady_state):
    """One transient: the reference, every TRANSIENT_SETTINGS run and the quasi-static fidelity against it."""
    start = None if kind == "start-up from rest" else steady_state
    reference, ref_cpu = trajectory(kind, start, TRANSIENT_REFERENCE)
    rows = []
    for label, settings in TRANSIENT_SETTINGS:
        x, cpu = trajectory(kind, start, settings)
        rows.append(dict(setting=label, cpu=cpu if x else None, errors=trajectory_errors(x, reference) if x else None,
                         stopped=None if x else cpu))  # fmt: skip
    qs = quasi_static_trajectory(kind)
    return dict(kind=kind, reference_cpu=ref_cpu, rows=rows, quasi_static=trajectory_errors(qs, reference),
                reference={q: reference[q].tolist() for q in TRAJECTORY}, qs={q: qs[q].tolist() for q in TRAJECTORY})  # fmt: skip


def measure():
    """Everything the report shows, as plain data."""
    load_before = os.getloadavg()[0]
    points = [steady_point(name, point) for name, point in POINTS.items()]
    steady_6208 = warm(POINTS["6208, 3 kN, 500 rad/s"]).get_state()
    transients = [transient(kind, steady_6208) for kind in TRANSIENTS]
    return dict(machine=machine(), load=(load_before, os.getloadavg()[0]), default_safety=SAFETY, points=points,
                transients=transients)  # fmt: skip


def _fmt(value):
    return "" if value is None else f"{value:.1e}"


def _pair(errors):
    return "" if errors is None else f"{errors[0]:.1e} / {errors[1]:.1e}"


def _point_table(p):
    lines = [
        f"### {p['name']}",
        "",
        f"Automatic step {p['automatic'] * 1e6:.3g} us (stability limit of the stiffest pair {p['stiffness_limit'] * 1e6:.3g}"
        f" us); reference {REF_FACTOR * p['automatic'] * 1e6:.3g} us with tribology every step ({p['reference_cpu']:.3g}"
        " ms CPU per simulated ms).",
        "",
        "| dt (x automatic) | dt (us) | refresh | CPU (ms/ms) | largest error | " + " | ".join(STEADY) + " |",
        "|---|---|---|---|---|" + "---|" * len(STEADY),
    ]
    for r in p["rows"]:
        head = f"| {r['factor']:g} | {r['dt'] * 1e6:.3g} | {r['refresh']} |"
        if r["errors"] is None:
            lines.append(head + f" stopped by the monitor: {r['stopped']} |" + " |" * (len(STEADY) + 1))
            continue
        errors = r["errors"]
        cells = " | ".join(_fmt(errors[q]) for q in STEADY)
        lines.append(head + f" {r['cpu']:.3g} | {_fmt(max(errors.values()))} | {cells} |")
    return lines + [""]


def _transient_table(t):
    lines = [
        f"### {t['kind']}",
        "",
        f"Reference: dt = {TRANSIENT_REFERENCE['dt'] * 1e6:g} us, tribology every step ({t['reference_cpu']:.3g} ms CPU "
        f"per simulated ms); samples every {SAMPLE * 1e3:g} ms (outputs averaged over each). Errors: largest over the "
        "samples of |x - x_ref| / max |x_ref|, then (after the slash) the error of the mean over the transient, "
        "|mean x - mean x_ref| / max |x_ref| (for the torque, of the energy dissipated).",
        "",
        "| setting | CPU (ms/ms) | " + " | ".join(TRAJECTORY) + " |",
        "|---|---|" + "---|" * len(TRAJECTORY),
    ]
    for r in t["rows"]:
        if r["errors"] is None:
            lines.append(f"| {r['setting']} | stopped by the monitor: {r['stopped']} |" + " |" * len(TRAJECTORY))
            continue
        lines.append(
            f"| {r['setting']} | {r['cpu']:.3g} | " + " | ".join(_pair(r["errors"][q]) for q in TRAJECTORY) + " |"
        )
    qs = t["quasi_static"]
    lines.append("| quasi-static fidelity driven in time | | " + " | ".join(_pair(qs[q]) for q in TRAJECTORY) + " |")
    return lines + [""]


def stable_factors(data):
    """Per step factor: stable at every point with every refresh, and the largest steady error there."""
    verdict = {}
    for factor in FACTORS:
        rows = [r for p in data["points"] for r in p["rows"] if r["factor"] == factor]
        stable = all(r["errors"] is not None for r in rows)
        worst = max((max(r["errors"].values()) for r in rows if r["errors"]), default=None)
        verdict[factor] = (stable, worst)
    return verdict


def _summary(data):
    verdict = stable_factors(data)
    lines = ["| dt (x automatic) | stable at the three points, every refresh | largest steady error |", "|---|---|---|"]
    for factor, (stable, worst) in verdict.items():
        mark = " (the default)" if factor == 1.0 else ""
        lines.append(f"| {factor:g}{mark} | {'yes' if stable else 'no'} | {_fmt(worst)} |")
    return lines + [""]


def render(data):
    """docs/reports/dem_steps.md and .png from measure()'s dict."""
    lines = [
        "# DEM time step and tribology refresh: three operating points and three transients",
        "",
        f"Generated by `python -m benchmarks.dem_steps` on {data['machine']} (load average {data['load'][0]:.1f} "
        f"before, {data['load'][1]:.1f} after; CPU = the thread's CPU time per simulated ms). Steps are fractions of "
        f"each point's own automatic step (safety {data['default_safety']:g} x the stability limit, or less where the"
        f" film's damping asks); errors are relative to a reference at {REF_FACTOR:g} x that step with tribology every "
        "step (benchmarks/dem_steps.py says how each is measured).",
        "",
        "## Larger steps than the automatic one",
        "",
        *_summary(data),
        "## Steady operating points",
        "",
    ]
    for p in data["points"]:
        lines += _point_table(p)
    lines += ["## Transients (6208, guessasma_oil, 313 K)", ""]
    for t in data["transients"]:
        lines += _transient_table(t)
    write_report("dem_steps.md", "\n".join(lines) + "\n")
    _figure(data).savefig(REPORTS / "dem_steps.png", dpi=110)


def _figure(data):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(data["points"]) + 1, figsize=(5 * (len(data["points"]) + 1), 4.2))
    markers = dict(zip(REFRESHES, ("o", "s", "^")))
    for ax, p in zip(axes, data["points"]):
        for label in REFRESHES:
            rows = [r for r in p["rows"] if r["refresh"] == label and r["errors"]]
            ax.loglog([r["cpu"] for r in rows], [max(r["errors"].values()) for r in rows], markers[label] + "-",
                      label=f"refresh {label}")  # fmt: skip
            for r in rows:
                ax.annotate(f"{r['factor']:g}", (r["cpu"], max(r["errors"].values())), fontsize=7)
        ax.set_title(p["name"], fontsize=9)
        ax.set_xlabel("CPU per simulated ms (ms)")
        ax.set_ylabel("largest relative error of the steady outputs")
        ax.legend(fontsize=7)
    ax = axes[-1]
    start = data["transients"][0]
    t = np.arange(1, len(start["reference"]["torque"]) + 1) * SAMPLE * 1e3
    ax.plot(t, start["reference"]["torque"], "k-", label="DEM, fine-step reference")
    ax.plot(t, start["qs"]["torque"], "r--", label="quasi-static driven in time")
    ax.set_title("start-up from rest (6208): torque", fontsize=9)
    ax.set_xlabel("time (ms)")
    ax.set_ylabel("torque (N.m)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def record_headlines(data):
    """The report's numbers (docs/report.md) in docs/reports/metrics.json: per operating point the default's largest
    steady error and cost and the largest stable step; per transient the default's error of the dissipated energy
    and of the worst sample, and the quasi-static fidelity's difference from the DEM reference."""
    forget("dem_steps")
    for p in data["points"]:
        default = next(r for r in p["rows"] if r["factor"] == 1.0 and r["refresh"] == "every 40 us")
        record("dem_steps", f"{p['name']}, default: largest steady error", max(default["errors"].values()), "1",
               kind="error")  # fmt: skip
        record("dem_steps", f"{p['name']}, default: CPU ms per simulated ms", default["cpu"], "1", kind="timing")
        stable = [r["factor"] for r in p["rows"] if r["errors"] is not None]
        record("dem_steps", f"{p['name']}: largest step run without a monitor stop (x automatic)", max(stable), "1",
               kind="count")  # fmt: skip
    for t in data["transients"]:
        default = t["rows"][0]["errors"]["torque"]
        record("dem_steps", f"{t['kind']}, default: energy (mean torque) error", default[1], "1", kind="error")
        record("dem_steps", f"{t['kind']}, default: torque error at the worst sample", default[0], "1", kind="error")
        record("dem_steps", f"{t['kind']}, quasi-static driven in time: torque at the worst sample",
               t["quasi_static"]["torque"][0], "1", kind="difference")  # fmt: skip


def main():
    data = measure()
    render(data)
    record_headlines(data)


if __name__ == "__main__":
    main()
