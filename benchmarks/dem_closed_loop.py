"""Start-up of the spindle with DEM bearings against the same run with quasi-static bearings, and the wall time
of the DEM run.

Runs: runs/startup_dem.toml (two B7214C at the DEM fidelity, BearingDEM.fmu) and runs/startup_qs.toml (the
same at the quasi-static fidelity, Bearing.fmu, with the DEM's flooded contacts instead of the file's oil-air):
800 N spring preload, iso_vg68_mineral, thermal spindle
b7214c_x_pair, 0 -> 10 000 rpm in 2 s (input schedule), 10 s, H = 10 ms Gauss-Seidel (step study:
docs/reports/dem_closed_loop_steps.md). Each is run `runs` times in this process through
spindle.cosim.master.run(load_run(path)); wall time = the master's stepping time (set-up excluded), CPU
time = this process's CPU time over the stepping (not lengthened by other users of the machine); medians.
The differences between the fidelities are taken from the last run of each: at chosen times (step means
for torque and heat, end-of-step values for temperatures and contact angle) and over the run (energy
dissipated, largest temperature difference).

Run: python -m benchmarks.dem_closed_loop [--runs N] [--stop S] -> docs/reports/dem_closed_loop.md and .png
"""

import argparse
import os
import statistics

import numpy as np

from spindle.cosim.master import run
from spindle.cosim.runfile import load_run

from .common import REPORTS
from .render import cli, metric

DEM_RUN = REPORTS.parent.parent / "runs" / "startup_dem.toml"
QS_RUN = REPORTS.parent.parent / "runs" / "startup_qs.toml"
# the quasi-static run with the DEM's lubrication: the DEM's contacts are flooded (it has no other method), while the
# run file states the rig's oil-air; compared as they are, the difference would be the method's, not the fidelity's
FLOODED = {"bearing_1.lubrication": "flooded", "bearing_2.lubrication": "flooded"}
TIMES = (0.1, 0.5, 1.0, 2.0, 5.0, 10.0)  # s
QUANTITIES = [  # (column, label, unit, scale to the unit)
    ("bearing_1.torque", "torque, bearing 1", "N.m", 1.0),
    ("bearing_1.P_loss", "heat P_loss, bearing 1", "W", 1.0),
    ("bearing_1.alpha_outer", "outer contact angle, bearing 1", "deg", 180.0 / np.pi),
    ("spindle.T_inner_ring_1", "inner ring 1", "C", None),
    ("spindle.T_outer_ring_1", "outer ring 1", "C", None),
    ("spindle.T_shaft", "shaft", "C", None),
]


def value(result, name, scale):
    column = np.asarray(result.columns[name], float)
    return column - 273.15 if scale is None else column * scale


def timed_runs(path, n, overrides):
    results, load = [], [os.getloadavg()[0]]
    for _ in range(n):
        results.append(run(load_run(path, overrides)))
        load.append(os.getloadavg()[0])
    return results, load


def measure(runs=3, stop=None):
    """stop (s): shorter runs, a smoke test (no metrics recorded)."""
    overrides = {} if stop is None else {"run.stop": stop}
    dem, dem_load = timed_runs(DEM_RUN, runs, overrides)
    qs, qs_load = timed_runs(QS_RUN, runs, {**overrides, **FLOODED})
    d, q = dem[-1], qs[-1]
    assert d.status == q.status == "ok", (d.message, q.message)
    spec = load_run(DEM_RUN, overrides)
    simulated = spec.stop - spec.start
    (wall, cpu), (qs_wall, qs_cpu) = ([statistics.median(getattr(r, k) for r in rs) for k in ("wall_time", "cpu_time")]
                                      for rs in (dem, qs))  # fmt: skip
    cost = [
        [f"DEM, {runs} runs", f"{wall:.1f}", f"{cpu:.1f}", f"{wall / simulated:.2f}", load_range(dem_load)],
        [f"quasi-static, {runs} runs", f"{qs_wall:.2f}", f"{qs_cpu:.2f}", f"{qs_wall / simulated:.3f}",
         load_range(qs_load)],
    ]  # fmt: skip
    columns = ["run", "wall median (s)", "CPU median (s)", "wall per simulated s (both bearings)",
               "load average (1 min) during the runs"]  # fmt: skip
    metrics = [
        metric(f"runs/startup_dem.toml, {simulated:g} s simulated (wall)", wall, "s", "timing", target=60.0),
        metric("wall per simulated second, both DEM bearings", wall / simulated, "1", "timing", target=1.0),
    ]
    met = wall <= 60.0 and wall / simulated <= 1.0
    blocks = [
        dict(text="## Cost"),
        dict(table=dict(columns=columns, rows=cost)),
        dict(
            text="Targets for the DEM run: <= {wall_target:g} s wall, <= {rate_target:g} s wall per simulated second "
            "of both DEM bearings together: {verdict}. The CPU time is the cost on an uncontended core (wall/CPU "
            "shows the share of a core the run got on the shared machine); it is the DEM integration of the two "
            "bearings at the automatic time step (docs/reports/dem_timing.md has the cost per DEM step for the 6208).",
            values=dict(wall_target=60.0, rate_target=1.0, verdict="met" if met else "not met"),
        ),
    ]  # fmt: skip
    return dict(
        name="dem_closed_loop",
        title="Start-up with DEM bearings in the thermal loop, against quasi-static bearings",
        about=__doc__.split("\n", 3)[3].split("Run:")[0],
        blocks=blocks + differences(d, q, spec) + [dict(figure=figure(d, q))],
        metrics=metrics if stop is None else [],
    )


def load_range(load):
    return f"{min(load):.1f}-{max(load):.1f}"


def differences(d, q, spec):
    """The blocks comparing the last DEM run d with the last quasi-static run q."""
    t, simulated = d.columns["time"], spec.stop - spec.start
    times = [x for x in TIMES if x <= spec.stop]
    at = [int(np.flatnonzero(np.isclose(t, x, rtol=0, atol=1e-9))[0]) for x in times]
    rows = []
    for name, label, unit, scale in QUANTITIES:
        vd, vq = value(d, name, scale), value(q, name, scale)
        digits = 7 if scale is None else 4  # temperatures: mK changes on 20 C
        rows.append(
            [f"{label} ({unit})"] + [f"{vd[k]:.{digits}g} / {vq[k]:.{digits}g} / {vd[k] - vq[k]:+.3g}" for k in at]
        )
    both = (d, q)
    energy = [sum(float(np.sum(r.columns[f"bearing_{i}.P_loss"][1:])) * spec.step for i in (1, 2)) for r in both]
    held = t >= 2.0 + 1e-9
    torque = [float(np.mean(r.columns["bearing_1.torque"][held])) for r in both]
    alpha = [float(np.mean(r.columns["bearing_1.alpha_outer"][held])) * 180.0 / np.pi for r in both]
    temps = [n for n in d.columns if n.startswith("spindle.T_")]
    worst = max(temps, key=lambda n: np.max(np.abs(d.columns[n] - q.columns[n])))
    P_d, P_q = (np.asarray(r.columns["bearing_1.P_loss"]) for r in both)
    heat_gap = [abs(P_d[k] / P_q[k] - 1.0) for k in at]
    k_max = int(np.argmax(P_d))
    run_rows = [
        [f"energy dissipated by both bearings over {simulated:g} s (J)", f"{energy[0]:.1f}", f"{energy[1]:.1f}",
         f"{energy[0] / energy[1] - 1:+.1%}"],
        [f"mean torque of bearing 1 at 10 000 rpm (2-{simulated:g} s, N.m)", f"{torque[0]:.4f}", f"{torque[1]:.4f}",
         f"{torque[0] / torque[1] - 1:+.1%}"],
        ["mean outer contact angle of bearing 1 at 10 000 rpm (deg)", f"{alpha[0]:.3f}", f"{alpha[1]:.3f}",
         f"{alpha[0] / alpha[1] - 1:+.2%}"],
        [f"largest temperature difference over the run: {worst} (K)",
         f"{np.max(np.abs(d.columns[worst] - q.columns[worst])):.4g}", None, None],
    ]  # fmt: skip
    T_inner = value(d, "spindle.T_inner_ring_1", None)
    reading = dict(
        warming=T_inner[-1] - T_inner[0], simulated=simulated, P_max=P_d[k_max], t_max=t[k_max],
        energy=energy[0] / energy[1] - 1, heat_gap=max(heat_gap), t_gap=times[int(np.argmax(heat_gap))],
        alpha=alpha[0] / alpha[1] - 1, torque=torque[0] / torque[1] - 1,
    )  # fmt: skip
    return [
        dict(text="## Differences between the fidelities"),
        dict(
            text="Torque and heat are the means over the communication step ending at the time shown (both FMUs: the "
            "DEM from the energy dissipated in the contacts, the quasi-static model from its Houpert losses at the "
            "step's end state); temperatures and contact angle at that time. DEM - QS = difference."
        ),
        dict(table=dict(columns=["quantity"] + [f"t = {x:g} s: DEM / QS / DEM - QS" for x in times], rows=rows)),
        dict(text="Over the run:"),
        dict(table=dict(columns=["quantity", "DEM", "QS", "DEM / QS - 1"], rows=run_rows)),
        dict(
            text="Reading: the inner ring of bearing 1 warms by {warming:.1f} K in {simulated:g} s; the heat of bearing "
            "1 peaks at {P_max:.0f} W (DEM, t = {t_max:g} s). The energy the two fidelities dissipate over the run "
            "differs by {energy:+.1%} (DEM / QS - 1); the heat of bearing 1 by at most {heat_gap:.1%} at the times of "
            "the table (t = {t_gap:g} s). At 10 000 rpm the mean torque of bearing 1 differs by {torque:+.1%} and the "
            "mean outer contact angle by {alpha:+.2%}; docs/dem.md compares the two fidelities for the single "
            "bearing at the same point (the DEM's friction need not hold the whole gyroscopic moment the quasi-"
            "static outer-race control hypothesis assumes).",
            values=reading,
        ),
    ]


def figure(d, q):
    panels = []
    for name, label, unit, scale in QUANTITIES[:4]:
        runs = ((d, "-", "DEM"), (q, "--", "quasi-static"))
        series = [dict(x=r.columns["time"].tolist(), y=value(r, name, scale).tolist(), style=style, label=who)
                  for r, style, who in runs]  # fmt: skip
        panels.append(dict(xlabel="time (s)", ylabel=f"{label} ({unit})", series=series))
    title = "startup_dem.toml vs startup_qs.toml: 0 -> 10 000 rpm in 2 s, H = 10 ms, Gauss-Seidel"
    return dict(file="dem_closed_loop.png", caption="DEM and quasi-static start-up", title=title, panels=panels,
                size=(11, 7))  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--stop", type=float, default=None, help="s, shorter runs (smoke test)")
    args = parser.parse_args(argv)
    cli(measure, "dem_closed_loop", runs=args.runs, stop=args.stop)


if __name__ == "__main__":
    main()
