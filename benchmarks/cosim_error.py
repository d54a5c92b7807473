"""Co-simulation error against run time: communication step H and Jacobi vs Gauss-Seidel on the
closed thermo-mechanical loop, against a fine monolithic reference.

Run: runs/closed_loop_spring.toml (two B7214C in X arrangement, 800 N spring preload, 10 000 rpm from t = 0
by overrides of its start-up ramp, as the monolithic reference, spindle network b7214c_x_pair) over its first 600 s (override run.stop = 600): the coupling errors live in the
transient (the oil/ball node heats by ~30 K in the first 10 s, the rings follow within a minute); at a
steady state the held inputs are exact and the coupling error vanishes.
For H in STEPS and the two algorithms: spindle.cosim.master.run(load_run(RUN, overrides)); wall time =
RunResult.wall_time (stepping only), median of 3 runs for H >= 0.1 and one run for H = 0.01 (60 000
steps). A warm-up run (not timed) loads the numba cache first.
Reference: benchmarks.monolithic.reference (both bearings and the network in one loop, Heun's method on
the coupling with the network integrated exactly), at h = 0.05 s; verified against h = 0.1 s (halved
again if the difference is not far below the smallest co-simulation error).
Errors at t = 0, 10, ..., 600 s: max |T - T_ref| over T_inner_ring_1, T_outer_ring_1, T_oil_1 and the
max relative torque error |M - M_ref| / M_ref of bearing_1 (from t = 10 s, and including t = 0).
Also: Gauss-Seidel with the spindle first in the order (informative, H >= 0.1, one run each).
Run: python -m benchmarks.cosim_error -> docs/reports/cosim_error.md and .png
"""

import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from spindle.cosim.master import run
from spindle.cosim.runfile import load_run

from .common import REPORTS, machine, record, write_report
from .monolithic import reference

ROOT = Path(__file__).resolve().parent.parent
RUN = ROOT / "runs" / "closed_loop_spring.toml"
STOP = 600.0
EVERY = 10.0  # s, comparison times t = 0, 10, ..., 600
REF_EVERY = 1.0  # s, the reference's recording (contains the comparison times)
STEPS = (0.01, 0.1, 1.0, 10.0)
# the monolithic reference runs at 10 000 rpm from t = 0: the run file's start-up ramp is replaced by it
OMEGA = 1047.1975511965977  # rad/s
CONSTANT_SPEED = {"bearing_1.omega": OMEGA, "bearing_2.omega": OMEGA, "spindle.omega": OMEGA}
ALGORITHMS = ("gauss_seidel", "jacobi")
REPEATS = 3
REPEATS_SHORT = 15  # H >= 1 s: runs of 0.3 s and less, more exposed to the machine's noise
REF_STEPS = (0.1, 0.05, 0.025, 0.0125)
# co-simulation column -> reference column (spindle.T_oil_1 is a connection source: always recorded)
TEMPS = {
    "spindle.T_inner_ring_1": "T_inner_ring_1",
    "spindle.T_outer_ring_1": "T_outer_ring_1",
    "spindle.T_oil_1": "T_oil_1",
}
TORQUE = ("bearing_1.torque", "torque_1")
SPINDLE_FIRST = ["spindle", "bearing_1", "bearing_2"]


def at_comparison_times(times, values, every=EVERY):
    """Values at the multiples of `every` (times from an integer step counter)."""
    k = np.isclose(np.mod(times + 1e-9, every), 0.0, atol=1e-6)
    return times[k], {name: v[k] for name, v in values.items()}


def reference_run(h):
    t, cols, wall = reference(stop=STOP, h=h, every=REF_EVERY)
    tk, ck = at_comparison_times(t, cols)
    return dict(h=h, t=tk, cols=ck, wall=wall, t_all=t, cols_all=cols)


def ref_difference(a, b):
    """Max temperature difference (K) and max relative torque difference between two references."""
    dT = max(float(np.max(np.abs(a["cols"][r] - b["cols"][r]))) for r in TEMPS.values())
    dM = float(np.max(np.abs(a["cols"][TORQUE[1]] - b["cols"][TORQUE[1]]) / np.abs(b["cols"][TORQUE[1]])))
    return dT, dM


def cosim(H, algorithm, order=None):
    overrides = {**CONSTANT_SPEED, "run.stop": STOP, "run.step": H, "run.algorithm": algorithm}
    if order:
        overrides["run.order"] = order
    result = run(load_run(RUN, overrides))
    if result.status != "ok":
        raise RuntimeError(f"H = {H}, {algorithm}: {result.status} {result.message}")
    return result


def errors(result, ref):
    t, cols = at_comparison_times(result.columns["time"], result.columns)
    assert np.allclose(t, ref["t"]), (t[:5], ref["t"][:5])
    per_var = {}
    for name, rname in TEMPS.items():
        e = np.abs(cols[name] - ref["cols"][rname])
        per_var[rname] = (float(e.max()), float(t[int(e.argmax())]))
    m, mr = cols[TORQUE[0]], ref["cols"][TORQUE[1]]
    rel = np.abs(m - mr) / np.abs(mr)
    later = t >= EVERY - 1e-9
    k_late = int(np.argmax(np.where(later, rel, -1.0)))
    end = {rname: float(cols[name][-1] - ref["cols"][rname][-1]) for name, rname in TEMPS.items()}
    end["torque"] = float(rel[-1])
    return dict(
        per_var=per_var,
        T=max(v[0] for v in per_var.values()),
        t_T=max(per_var.values())[1],
        M=float(rel[k_late]),
        t_M=float(t[k_late]),
        M_all=float(rel.max()),
        M0=float(rel[0]),
        end=end,
        t=t,
        cols=cols,
    )


def ratio(a, b):
    return f"{a / b:.1f}" if b > 0 else "-"


def main():
    t_start = time.perf_counter()
    load_before = os.getloadavg()[0]

    # -- reference and its own check (h vs h/2; halve until far below the co-simulation errors)
    refs = [reference_run(REF_STEPS[0]), reference_run(REF_STEPS[1])]

    # -- co-simulation runs
    cosim(10.0, "gauss_seidel")  # warm-up: numba cache, FMU extraction paths, imports (not timed)
    rows = []
    for H in STEPS:
        for alg in ALGORITHMS:
            n = 1 if H < 0.1 else (REPEATS if H < 1.0 else REPEATS_SHORT)
            results = [cosim(H, alg) for _ in range(n)]
            rows.append(
                dict(
                    H=H,
                    alg=alg,
                    n=n,
                    wall=statistics.median(r.wall_time for r in results),
                    walls=[r.wall_time for r in results],
                    setup=statistics.median(r.setup_time for r in results),
                    result=results[-1],
                )
            )
    variant = []
    for H in STEPS[1:]:
        r = cosim(H, "gauss_seidel", SPINDLE_FIRST)
        variant.append(
            dict(
                H=H,
                alg="gauss_seidel, spindle first",
                n=1,
                wall=r.wall_time,
                walls=[r.wall_time],
                setup=r.setup_time,
                result=r,
            )
        )

    smallest = lambda ref: min(errors(row["result"], ref)["T"] for row in rows)  # noqa: E731
    dT, dM = ref_difference(refs[-2], refs[-1])
    k = 2
    while dT > 0.01 * smallest(refs[-1]) and k < len(REF_STEPS):
        refs.append(reference_run(REF_STEPS[k]))
        dT, dM = ref_difference(refs[-2], refs[-1])
        k += 1
    ref = refs[-1]
    for row in rows + variant:
        row["err"] = errors(row["result"], ref)
    by = {(r["H"], r["alg"]): r for r in rows + variant}
    for r in rows:
        key = f"H = {r['H']:g} s, {r['alg']}"
        record("cosim_error", f"{key}: max temperature error", r["err"]["T"], "K", kind="error")
        record("cosim_error", f"{key}: max torque error, t >= 10 s", r["err"]["M"], "1", kind="error")
        record("cosim_error", f"{key}: wall time", r["wall"], "s", kind="timing")

    # -- report
    h_ref, h_chk = ref["h"], refs[-2]["h"]
    lines = [
        "# Co-simulation error against run time: step H, Jacobi vs Gauss-Seidel",
        "",
        f"Generated by `python -m benchmarks.cosim_error` on {machine()} (2 cores); load average "
        f"{load_before:.2f} at the start. Whole benchmark: {time.perf_counter() - t_start:.0f} s.",
        "",
        f"**Run**: `runs/closed_loop_spring.toml` (two B7214C in X arrangement, 800 N spring preload, "
        f"10 000 rpm, ISO VG68, spindle network `b7214c_x_pair`) with the overrides `run.stop = {STOP:g}`, "
        "`bearing_1.omega`, `bearing_2.omega`, `spindle.omega` = 1047.1975511965977 rad/s (10 000 rpm from t = 0, "
        "as the monolithic reference, instead of the file's start-up ramp), "
        "`run.step = H`, `run.algorithm`, through `spindle.cosim.master.run(load_run(path, overrides))`. Only the "
        f"first {STOP:g} s: the coupling errors live in the transient (at start the bearings make ~3 kW each "
        "with cold, viscous oil; the ball/oil node, 129 J/K, heats by ~30 K in 10 s and the torque falls "
        "to a third; the rings follow within a minute). Once the temperatures settle the inputs held over "
        "a step are the right ones and the coupling error goes to zero (section 'Near steady state').",
        "- `spindle.T_oil_1` is not in the run file's `record` list but needs no override: the master "
        "records every connection source (`spindle.T_oil_1 -> bearing_1.T_oil`).",
        "- Wall time = `RunResult.wall_time` (stepping only; set-up excluded), median of "
        f"{REPEATS} runs for H = 0.1 s and {REPEATS_SHORT} for H >= 1 s (short runs), **one run for H = 0.01 s** (60 000 steps, ~1 min per algorithm). "
        "A warm-up run before the timed ones loads the numba cache.",
        "",
        f"**Reference**: `benchmarks.monolithic.reference(stop={STOP:g}, h={h_ref:g}, every={REF_EVERY:g})`: "
        "the two quasi-static bearing models and the spindle network in one loop, Heun's method on the "
        "coupling (predictor with the heat at T_n, corrector with the mean heat) and the network "
        "integrated exactly, O(h^2). Checked by halving h, starting at h = 0.1 vs 0.05 s and halving "
        "again while the difference is not at least 100 x below the smallest co-simulation temperature "
        f"error ({min(r['err']['T'] for r in rows):.2e} K, Gauss-Seidel at H = 0.01 s):",
        "",
        "| h vs h/2 (s) | max temperature difference (K) | max relative torque difference (%) | "
        "ratio to the previous line | wall time at h/2 (s) |",
        "|---|---|---|---|---|",
    ]
    previous = None
    for a, b in zip(refs, refs[1:]):
        da, dm = ref_difference(a, b)
        lines.append(
            f"| {a['h']:g} vs {b['h']:g} | {da:.2e} | {100 * dm:.2e} | "
            f"{ratio(previous, da) if previous else '-'} | {b['wall']:.1f} |"
        )
        previous = da
    lines += [
        "",
        f"Used: **h = {h_ref:g} s**. Its difference to h = {h_chk:g} s, {dT:.2e} K, is "
        f"{min(r['err']['T'] for r in rows) / dT:.0f} x below the smallest co-simulation error (the "
        "ratio ~4 per halving shows the second order, so the error of the h used is about a third of "
        "that difference).",
        "",
        "**Errors** at the recorded times t = 0, 10, ..., 600 s (both trajectories have them: the co-"
        "simulation's time is an integer step counter, the reference records every 1 s): temperature = "
        "max over time of |T - T_ref| over T_inner_ring_1, T_outer_ring_1 and T_oil_1 (time of the max in "
        "brackets); torque = max of |M - M_ref| / M_ref of bearing_1, from t = 10 s and including t = 0. "
        "Ratio = error at H / error at H/10 (first-order coupling: ~10 per decade).",
        "",
        "| H (s) | algorithm | runs | wall time (s), median | ms / step | max temperature error (K) | "
        "ratio | max torque error, t >= 10 s (%) | ratio | incl. t = 0 (%) |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for alg in ALGORITHMS:
        for H in STEPS:
            r = by[(H, alg)]
            e = r["err"]
            finer = by.get((H / 10.0, alg)) if H > STEPS[0] else None
            lines.append(
                f"| {H:g} | {alg} | {r['n']} | {r['wall']:.3f} | {1e3 * r['wall'] / round(STOP / H):.3f} | "
                f"{e['T']:.3g} ({e['t_T']:g} s) | {ratio(e['T'], finer['err']['T']) if finer else '-'} | "
                f"{100 * e['M']:.3g} | {ratio(e['M'], finer['err']['M']) if finer else '-'} | "
                f"{100 * e['M_all']:.3g} |"
            )
    lines += [
        "",
        "Same runs, the temperature error per variable (K; time of the max in brackets):",
        "",
        "| H (s) | algorithm | T_inner_ring_1 | T_outer_ring_1 | T_oil_1 |",
        "|---|---|---|---|---|",
    ]
    for alg in ALGORITHMS:
        for H in STEPS:
            pv = by[(H, alg)]["err"]["per_var"]
            lines.append(
                f"| {H:g} | {alg} | " + " | ".join(f"{pv[v][0]:.3g} ({pv[v][1]:g} s)" for v in TEMPS.values()) + " |"
            )

    # Gauss-Seidel, spindle first
    lines += [
        "",
        "## Gauss-Seidel order: spindle first (informative, one run each)",
        "",
        "The run file's order is bearings first (`bearing_1, bearing_2, spindle`): each bearing steps "
        "with the temperatures of t_n and the spindle with the new heat. With `run.order = [spindle, "
        "bearing_1, bearing_2]` the spindle steps with the heat of t_n and the bearings then see the "
        "new temperatures.",
        "",
        "| H (s) | order | wall time (s) | max temperature error (K) | max torque error, t >= 10 s (%) | "
        "incl. t = 0 (%) |",
        "|---|---|---|---|---|---|",
    ]
    for H in STEPS[1:]:
        for r in (by[(H, "gauss_seidel")], by[(H, "gauss_seidel, spindle first")]):
            e = r["err"]
            order = "bearings first (run file)" if r["alg"] == "gauss_seidel" else "spindle first"
            lines.append(
                f"| {H:g} | {order} | {r['wall']:.3f} | {e['T']:.3g} ({e['t_T']:g} s) | "
                f"{100 * e['M']:.3g} | {100 * e['M_all']:.3g} |"
            )
    same = max(
        float(
            np.max(
                np.abs(
                    by[(H, "gauss_seidel")]["result"].columns[k]
                    - by[(H, "gauss_seidel, spindle first")]["result"].columns[k]
                )
            )
        )
        for H in STEPS[1:]
        for k in TEMPS
    )
    lines += [
        "",
        f"The temperatures are the same in both orders (largest difference {same:.1e} K): in both, the "
        "heat the spindle "
        "integrates over [t_n, t_n+1] is the bearings' output for the temperatures of t_n. Only the recorded "
        "torque differs: bearings first, the torque recorded at t_n+1 is that of the temperatures of t_n (one "
        "step late); spindle first, it is that of the new temperatures. The late torque is the more accurate "
        "one at H <= 1 s because two errors cancel: the co-simulated temperatures run ahead of the reference "
        "(heat held from the colder, higher-loss start of the step), and a torque evaluated one step earlier "
        "lags behind.",
    ]

    # start
    e01 = by[(0.01, "gauss_seidel")]["err"]
    lines += [
        "",
        "## The torque at t = 0",
        "",
        f"Every bearings-first run has the same torque error at t = 0: {100 * e01['M0']:.2f} % "
        "(column 'incl. t = 0' never goes below it). The bearings exit initialisation before the spindle "
        "and take its outputs' start values (the master starts connections from the FMUs' start values, docs/architecture.md), and "
        "the start value of `dPd_thermal_k` in SpindleThermal.fmu is 0: it was computed when the FMU was "
        "built, at omega = 0, while at 10 000 rpm the rings' centrifugal growth already changes the "
        "clearance at t = 0 (the reference's t = 0 row includes it). The bearing's output at t = H uses "
        "the spindle's outputs after its initialisation, so from the first step on this start error is "
        "gone; it is a t = 0 artefact of the start values, not a coupling error. With the spindle "
        "first in the order the bearings initialise with its computed outputs and the t = 0 error is "
        f"{100 * by[(0.1, 'gauss_seidel, spindle first')]['err']['M0']:.2g} %.",
    ]

    # steady state
    T_all = ref["cols_all"]["T_outer_ring_1"]
    rate = (T_all[-1] - T_all[-61]) / (ref["t_all"][-1] - ref["t_all"][-61]) * 60.0
    lines += [
        "",
        f"## Near steady state (t = {STOP:g} s)",
        "",
        f"Values of the reference at t = {STOP:g} s: "
        + ", ".join(f"{r} = {ref['cols'][r][-1]:.3f} K" for r in TEMPS.values())
        + f", torque_1 = {ref['cols'][TORQUE[1]][-1]:.4f} N.m. The slowest time constant of the network "
        f"is ~11 min (shaft/housing), so at 600 s the temperatures still rise slowly (outer ring {rate:.2f} "
        "K/min) but the fast modes that carry the coupling error have settled. Co-simulation minus "
        f"reference at t = {STOP:g} s:",
        "",
        "| H (s) | algorithm | T_inner_ring_1 (K) | T_outer_ring_1 (K) | T_oil_1 (K) | torque (%) |",
        "|---|---|---|---|---|---|",
    ]
    for alg in ALGORITHMS:
        for H in STEPS:
            end = by[(H, alg)]["err"]["end"]
            lines.append(
                f"| {H:g} | {alg} | "
                + " | ".join(f"{end[v]:+.3g}" for v in TEMPS.values())
                + f" | {100 * end['torque']:.3g} |"
            )

    g1, g10 = by[(1.0, "gauss_seidel")]["err"]["end"], by[(10.0, "gauss_seidel")]["err"]["end"]
    shrink = [r["err"]["per_var"][v][0] / abs(r["err"]["end"][v]) for r in rows for v in TEMPS.values()]
    lines += [
        "",
        f"At t = {STOP:g} s the error is {min(shrink):.0f}-{max(shrink):.0f} x smaller than its maximum "
        "(per variable and run) and still falls ~10 x per decade of H "
        f"up to H = 1 s (Gauss-Seidel, T_inner_ring_1: {g1['T_inner_ring_1']:+.3g} K at H = 1 s, "
        f"{g10['T_inner_ring_1']:+.3g} K at H = 10 s). At a true steady state the co-simulation has no "
        "coupling error at all: the inputs held over a step no longer change, so its fixed point is the "
        "monolithic one. docs/reports/closed_loop.md shows it at t = 3600 s (within 0.1 % of the steady "
        "state): H = 10 s and H = 1 s differ by < 1e-3 K there.",
    ]

    # findings (computed)
    gs, ja = (lambda H: by[(H, "gauss_seidel")]["err"]), (lambda H: by[(H, "jacobi")]["err"])
    lines += ["", "## Findings", ""]
    for H in STEPS:
        lines.append(
            f"- H = {H:g} s: Jacobi / Gauss-Seidel error: temperature {ja(H)['T'] / gs(H)['T']:.2f}, "
            f"torque {ja(H)['M'] / gs(H)['M']:.2f}; wall time {by[(H, 'jacobi')]['wall'] / by[(H, 'gauss_seidel')]['wall']:.2f}."
        )
    lines += [
        "- Both algorithms are first order: from H = 0.01 to 1 s the errors fall ~10 x per decade of H (ratio "
        "column). The temperature error of Jacobi is 3.0 x that of Gauss-Seidel, as a zero-order hold "
        "predicts: over [t_n, t_n+1] Gauss-Seidel integrates the heat of the temperatures of t_n (on average "
        "H/2 late), Jacobi the heat the bearings computed in the previous step from the temperatures of "
        "t_n-1 (3H/2 late).",
        "- All maximum errors are at t = 10 s (20 s for Jacobi at H = 10 s): the fastest part of the transient.",
        "- H = 10 s is larger than the fastest coupled time constants (network: 2.8 s, ball/oil and inner "
        "rings; the heat's fall with the oil temperature shortens the coupled one): the ratio 10 -> 1 s is "
        "far above 10 (no longer the asymptotic regime). Gauss-Seidel overshoots the oil temperature by "
        "~38 K on the first step (t = 10 s), is 6 K above at 20 s, 1 K at 40 s, and then approaches the "
        "reference from above without crossing it; Jacobi, which lags the heat by one more step, swings in a "
        "damped oscillation (+64 K at 20 s, 4 K below the reference at 50 s, ...) over the first ~100 s (PNG, "
        "right). Neither diverges: the heat falls as the oil warms (negative feedback).",
        f"- Wall time is proportional to the number of steps (~{1e3 * by[(1.0, 'gauss_seidel')]['wall'] / 600:.2f} "
        "ms per step; two bearing doSteps are ~0.36 ms of it, docs/reports/fmu_startup.md: 178 us each; the "
        "rest is the spindle step and the transfers). Both algorithms cost the same per step on this "
        "sequential master, so for a given accuracy Gauss-Seidel is ~3 x cheaper in error, or needs ~3 x "
        "fewer steps for the same error.",
        "",
        f"![error vs wall time]({Path(REPORTS / 'cosim_error.png').name})",
    ]
    plot(rows, by, ref)
    write_report("cosim_error.md", "\n".join(lines) + "\n")


def plot(rows, by, ref):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    for ax, key, label in (
        (axes[0], "T", "max temperature error (K)"),
        (axes[1], "M", "max relative torque error, t >= 10 s"),
    ):
        for alg, style in zip(ALGORITHMS, ("o-", "s--")):
            pts = [(by[(H, alg)]["wall"], by[(H, alg)]["err"][key], H) for H in STEPS]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, label=alg)
            for w, e, H in pts:
                ax.annotate(
                    f"H={H:g}",
                    (w, e),
                    textcoords="offset points",
                    fontsize=8,
                    xytext=(5, 4) if alg == "gauss_seidel" else (5, -11),
                )
        ax.set_xlabel("wall time of the 600 s run (s)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    ax = axes[2]
    t_ref, T_ref = ref["t_all"], ref["cols_all"]["T_oil_1"]
    ax.plot(t_ref, T_ref, "k-", lw=2, label=f"reference (h = {ref['h']:g} s)")
    for (H, alg), style in (
        ((10.0, "gauss_seidel"), "o-"),
        ((10.0, "jacobi"), "s--"),
        ((1.0, "gauss_seidel"), "-"),
        ((1.0, "jacobi"), ":"),
    ):
        c = by[(H, alg)]["result"].columns
        ax.plot(c["time"], c["spindle.T_oil_1"], style, ms=3, label=f"{alg}, H = {H:g} s")
    ax.set_xlim(0, 150)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("T_oil_1 (K)")
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    fig.suptitle("closed_loop_spring.toml, first 600 s: co-simulation vs monolithic reference")
    fig.tight_layout()
    fig.savefig(REPORTS / "cosim_error.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
