"""The fidelity ladder: the difference between the analytic, quasi-static and DEM fidelities, against wall time.

Not an error against an independent reference (that is benchmarks/reference_table.py): each fidelity is compared
with another solution of the product, and each row states the boundary condition of the ring in its solution.

Grid (6208, ISO VG68 mineral oil): speed 100 / 500 / 1700 rad/s x radial load 0.75 / 3 / 7.5 kN x
diametral clearance 0 / +25 um x oil temperature 40 / 70 C (36 points); and the B7214C under 800 N and
3 kN axial (+ 2 kN radial) at 500 and 1047 rad/s (4 points, quasi-static and DEM: the analytic fidelity
is for radially loaded deep-groove bearings).

Comparison solutions, the best available for each quantity:
- static equilibrium (ring displacement, Q_max, contact angle, stiffness diagonal) and the quantities
  computed from it with the same formulas (film h_min, Lambda, capacitance, Houpert torque): the
  quasi-static fidelity with the ring's tilts held at zero, because the DEM's inner ring translates but
  does not tilt (as if the shaft's other bearing held it). For the 6208 under a pure radial load tilt does
  not couple (contacts in the mid-plane); for a single angular-contact bearing under a combined load it
  does, strongly: Bearing.fmu's ring, free in all five DOF, then tilts and moves several times further
  (the rows of the free ring show by how much) (its own accuracy against textbook and standard cases is in the validation
  tests; its film formula's error against the thesis' full EHL solutions is docs/reports/ehl_film_errors.md);
- dynamics (cage speed, DEM torque): the DEM at a fine time step (a quarter of the default).

Wall time per operating point: analytic one evaluation, quasi-static a cold solve (fresh model) and a warm
one (after a neighbouring point), DEM the protocol to a steady state at the default settings (2 ms settling
under the load, 5 ms speed ramp, running until the cage speed averaged over 10 ms changes by less than 0.1 %
from one window to the next (at most 3 s), means over the next 10 ms).

Run: python -m benchmarks.fidelity_ladder (about 2 min). Writes docs/reports/fidelity_ladder.md and .png.
"""

import itertools
import json
import math
import os
import statistics
import time

import numpy as np

from bearing_fmu import AnalyticModel, QuasiStaticModel, Scene
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.dem import DemModel, DemUnstableError

from .common import REPORTS, machine, record, write_report

LUBRICANT = "iso_vg68_mineral"
QS_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")  # the scene of Bearing.fmu
DISPLACEMENT_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static_displacement.toml")  # of BearingDisp.fmu
GRID_6208 = dict(omega=(100.0, 500.0, 1700.0), F_r=(750.0, 3000.0, 7500.0), Pd=(0.0, 25e-6), T_oil=(313.15, 343.15))
GRID_B7214C = (  # (omega rad/s, F_y N, F_z N); radial loads on y, the line of ball 1 (docs/conventions.md)
    (500.0, 0.0, 800.0),
    (500.0, 2000.0, 3000.0),
    (1047.2, 0.0, 800.0),
    (1047.2, 2000.0, 3000.0),
)
QUANTITIES = (  # (output, label, kind): kind 'static' -> quasi-static reference, 'dynamic' -> fine DEM
    ("y", "y radial displacement", "static"),
    ("z", "z axial displacement", "static"),
    ("Q_max_inner", "Q_max inner", "static"),
    ("alpha_inner", "contact angle inner", "static"),
    ("K[2,2]", "K[2,2] radial stiffness dF_y/dy (along the load)", "static"),
    ("K[3,3]", "K[3,3] axial stiffness dF_z/dz", "static"),
    ("h_min_outer", "h_min outer", "static"),
    ("Lambda_outer", "Lambda outer", "static"),
    ("C_bearing", "capacitance", "static"),
    ("torque", "friction torque", "static"),
    ("omega_cage", "cage speed", "dynamic"),
)
FREE_RING = "quasi-static, ring free in 5 DOF (Bearing.fmu)"
TRANSLATING = "inner ring translates in x, y, z under the loads, tilts held at zero"
BOUNDARY = {  # the boundary condition of the ring in each solution compared
    "analytic": "inner ring displaced along the radial load only (continuous-ball load integral)",
    FREE_RING: "inner ring free in x, y, z and both tilts under the loads",
    "quasi-static, warm": "as Bearing.fmu: inner ring free in 5 DOF; re-solve after a 1 % load change",
    "quasi-static, cold": "as Bearing.fmu: inner ring free in 5 DOF; fresh model",
    "DEM": TRANSLATING,
    "DEM, default dt": TRANSLATING,
    "DEM, dt / 4": TRANSLATING,
    "quasi-static, tilts held": TRANSLATING,
}
SETTLE, RAMP, STEADY, WINDOW, PARTS = 2e-3, 5e-3, 0.030, 0.010, 5  # s, s, s, s, -
STEADY_CHANGE, MAX_TIME = 1e-3, 3.0  # -, s


def stiffness_diagonal(K):
    """The radial (along the load, y) and axial (z) stiffness of a 5 x 5 matrix K (numpy, 0-based), named as the
    FMUs name them (1-based: K[2,2] = dF_y/dy, K[3,3] = dF_z/dz)."""
    return {"K[2,2]": float(K[1, 1]), "K[3,3]": float(K[2, 2])}


def analytic_point(bearing, omega, F_r, F_z, Pd, T_oil):
    """Outputs and wall time (s) of one analytic evaluation (None where the fidelity does not apply)."""
    if bearing != "6208" or F_z:
        return None, None
    model = AnalyticModel(bearing, LUBRICANT, Pd=Pd)
    model.evaluate(omega=omega, F_y=F_r, T_oil=T_oil)  # compile / warm
    t0 = time.perf_counter()
    out = model.evaluate(omega=omega, F_y=F_r, T_oil=T_oil)
    return dict(out, alpha_inner=0.0, x=0.0, z=0.0), time.perf_counter() - t0


def quasi_static_point(bearing, omega, F_r, F_z, Pd, T_oil):
    """Outputs (load drive: the ring free in all 5 DOF, as Bearing.fmu), cold-solve wall time (s) and warm-solve
    wall time (s, re-solve after a 1 % load change)."""
    t0 = time.perf_counter()
    model = QuasiStaticModel(bearing, LUBRICANT, scene=QS_SCENE, Pd=Pd)
    out = model.evaluate(omega=omega, F_y=F_r, F_z=F_z, T_oil=T_oil)
    cold = time.perf_counter() - t0
    model.evaluate(omega=omega, F_y=1.01 * F_r, F_z=1.01 * F_z, T_oil=T_oil)
    t0 = time.perf_counter()
    out = model.evaluate(omega=omega, F_y=F_r, F_z=F_z, T_oil=T_oil)
    warm = time.perf_counter() - t0
    return dict(out, **stiffness_diagonal(model.K)), cold, warm


def quasi_static_tilt_locked(bearing, omega, F_r, F_z, Pd, T_oil, start):
    """The quasi-static equilibrium with the ring's tilts held at zero, the DEM's boundary condition (its inner
    ring translates only): the displacement-driven model at theta = 0, with Newton on (x, y, z) until the
    reactions equal the applied loads to 1e-9 of the load. `start`: the load-driven outputs (first guess)."""
    model = QuasiStaticModel(bearing, LUBRICANT, scene=DISPLACEMENT_SCENE, Pd=Pd)
    target = np.array([0.0, F_r, F_z])
    d = np.array([start["x"], start["y"], start["z"]])
    for _ in range(50):
        out = model.evaluate(omega=omega, x=d[0], y=d[1], z=d[2], theta_x=0.0, theta_y=0.0, T_oil=T_oil)
        residual = target - np.array([out["F_x"], out["F_y"], out["F_z"]])
        if np.max(np.abs(residual)) <= 1e-9 * np.max(np.abs(target)):
            return dict(out, x=d[0], y=d[1], z=d[2], **stiffness_diagonal(model.K))
        d = d + np.linalg.solve(model.K[:3, :3], residual)
    raise RuntimeError(f"tilt-locked quasi-static reference did not converge at {bearing, omega, F_r, F_z}")


def dem_point(bearing, omega, F_r, F_z, Pd, T_oil, dt=None):
    """Steady means of the DEM outputs after the start-up protocol, its wall time (s), the time step used (s)
    and the monitor's message if the first attempt stopped (then the run is repeated at the time step the
    message names, as a user would)."""
    try:
        return (*_dem_run(bearing, omega, F_r, F_z, Pd, T_oil, dt), None)
    except DemUnstableError as error:
        message = str(error)
        suggested = float(message.split("use dt <= ")[1].split(" s")[0])
        return (*_dem_run(bearing, omega, F_r, F_z, Pd, T_oil, suggested), message)


def _dem_run(bearing, omega, F_r, F_z, Pd, T_oil, dt):
    t0 = time.perf_counter()
    model = DemModel(bearing, LUBRICANT, Pd=Pd, dt=dt)
    loads = dict(F_y=F_r, F_z=F_z, T_oil=T_oil)
    model.advance(SETTLE, omega=0.0, **loads)
    for k in range(1, 21):
        model.advance(SETTLE + RAMP * k / 20, omega=omega * k / 20, **loads)
    model.advance(STEADY, omega=omega, **loads)
    # steady when the cage speed averaged over a window changes by less than STEADY_CHANGE from the previous
    # window (light loads with a thick film take up to a second to roll up: the traction is small)
    previous = model.advance(model.time + WINDOW, omega=omega, **loads)["omega_cage"]
    while model.time < MAX_TIME:
        current = model.advance(model.time + WINDOW, omega=omega, **loads)["omega_cage"]
        if abs(current - previous) <= STEADY_CHANGE * abs(current):
            break
        previous = current
    steady_from = model.time
    samples = []
    for k in range(1, PARTS + 1):
        out = model.advance(steady_from + WINDOW * k / PARTS, omega=omega, **loads)
        K = model.stiffness_matrix()
        samples.append(dict(out, **stiffness_diagonal(K)))
    wall = time.perf_counter() - t0
    means = {key: float(np.mean([s[key] for s in samples])) for key in samples[0]}
    return dict(means, steady_from=steady_from), wall, model.dt


def points():
    for omega, F_r, Pd, T_oil in itertools.product(*GRID_6208.values()):
        yield ("6208", omega, F_r, 0.0, Pd, T_oil)
    for omega, F_y, F_z in GRID_B7214C:
        yield ("B7214C", omega, F_y, F_z, None, 313.15)


def relative_error(value, reference):
    """|value - reference| / |reference|; for a zero reference the absolute value is returned as is."""
    if reference == 0.0:
        return abs(value)
    return abs(value - reference) / abs(reference)


def run():
    rows = []
    for point in points():
        analytic, t_analytic = analytic_point(*point)
        qs, t_qs_cold, t_qs_warm = quasi_static_point(*point)
        locked = quasi_static_tilt_locked(*point, qs)
        dem, t_dem, dt_default, stop = dem_point(*point)
        fine, t_fine, _, fine_stop = dem_point(*point, dt=0.25 * dt_default)
        rows.append(
            dict(
                point=point,
                analytic=analytic,
                qs=qs,
                locked=locked,
                dem=dem,
                fine=fine,
                time=dict(analytic=t_analytic, qs_cold=t_qs_cold, qs_warm=t_qs_warm, dem=t_dem, dem_fine=t_fine),
                dt=dt_default,
                stop=stop,
                fine_stop=fine_stop,
            )
        )
        print(point, f"DEM {t_dem:.2f} s, fine {t_fine:.2f} s")
    return rows


def errors(rows):
    """{(fidelity, quantity): [relative differences over the points where both exist]} from the comparison
    solutions."""
    table = {}
    for row in rows:
        for name, _, kind in QUANTITIES:
            reference = row["fine" if kind == "dynamic" else "locked"][name]
            candidates = {"DEM": row["dem"], "analytic": row["analytic"], FREE_RING: row["qs"]}
            for fidelity, outputs in candidates.items():
                if outputs is None or name not in outputs:
                    continue
                bearing, _, F_r, F_z = row["point"][:4]
                unloaded = (name == "y" and F_r == 0.0) or (name == "z" and F_z == 0.0)
                if unloaded or (name == "alpha_inner" and bearing == "6208"):
                    continue  # zero by symmetry in every fidelity (or not modelled): no information
                table.setdefault((fidelity, name), []).append(relative_error(outputs[name], reference))
    return table


PANELS = (
    ("y", "ring displacement y"),
    ("Q_max_inner", "Q_max inner"),
    ("h_min_outer", "h_min outer"),
    ("torque", "torque"),
)


def ladder(rows):
    """Per fidelity: the median wall time per operating point (s) and, per panel quantity, the largest relative
    difference from the tilt-held quasi-static solution over the 6208 points (where every fidelity applies)."""
    deep = [r for r in rows if r["point"][0] == "6208"]
    entries = {
        "analytic": ("analytic", "analytic"),
        "quasi-static, warm": ("qs", "qs_warm"),
        "quasi-static, cold": ("qs", "qs_cold"),
        "DEM, default dt": ("dem", "dem"),
        "DEM, dt / 4": ("fine", "dem_fine"),
    }
    result = {}
    for name, (outputs, timing) in entries.items():
        errors = {}
        for quantity, _ in PANELS:
            values = [
                relative_error(r[outputs][quantity], r["locked"][quantity]) for r in deep if quantity in r[outputs]
            ]
            errors[quantity] = max(values) if values else None
        result[name] = (statistics.median(r["time"][timing] for r in deep), errors)
    return result


def plot(entries, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    floor = 1e-7
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5))
    colours = dict(zip(entries, plt.rcParams["axes.prop_cycle"].by_key()["color"]))  # one per fidelity, every panel
    fronts = {}
    for ax, (quantity, label) in zip(axes.flat, PANELS):
        cost = {n: c for n, (c, e) in entries.items() if e[quantity] is not None}
        error = {n: max(entries[n][1][quantity], floor) for n in cost}
        for name in cost:
            ax.loglog(cost[name], error[name], "o", color=colours[name], label=name)
        front = pareto(cost, error)
        fronts[quantity] = front
        ax.loglog([cost[n] for n in front], [error[n] for n in front], "k--", lw=1, label="Pareto front")
        ax.set_title(f"{label} (max over the 6208 grid)", fontsize=9)
        ax.set_xlabel("wall time per operating point (s)", fontsize=8)
        ax.set_ylabel("relative difference from quasi-static, tilts held", fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle(f"Fidelity ladder (differences below {floor:g} drawn at {floor:g})", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fronts


def pareto(cost, error):
    """Names on the Pareto front of (cost, error): no other entry is both cheaper and at least as accurate."""
    names = sorted(cost, key=lambda n: (cost[n], error[n]))
    front, best = [], math.inf
    for name in names:
        if error[name] < best:
            front.append(name)
            best = error[name]
    return front


def fmt(x):
    return "-" if x is None else f"{x:.3g}"


def report(rows, table, entries, fronts, seconds):
    load = os.getloadavg()[0]
    n_6208 = sum(1 for r in rows if r["point"][0] == "6208")
    lines = [
        "# Fidelity ladder: difference between the analytic, quasi-static and DEM fidelities",
        "",
        f"Generated by `python -m benchmarks.fidelity_ladder` on {machine()} (2 cores); load average {load:.2f} "
        f"at the start; {seconds:.0f} s in total. {len(rows)} operating points.",
        "",
        __doc__.split("\n", 2)[2].split("Run:")[0].strip(),
        "",
        "## Differences from the comparison solutions (relative; over the grid)",
        "",
        "| quantity | compared with | fidelity | its boundary condition | points | median | max |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, label, kind in QUANTITIES:
        reference = "DEM, dt / 4" if kind == "dynamic" else "quasi-static, tilts held"
        for fidelity in ("analytic", FREE_RING, "DEM"):
            values = table.get((fidelity, name))
            if values:
                lines.append(
                    f"| {label} | {reference} | {fidelity} | {BOUNDARY[fidelity]} | {len(values)} | "
                    f"{statistics.median(values):.3g} | {max(values):.3g} |"
                )
    lines += [
        "",
        "Contact angles of the 6208 are zero by symmetry in every fidelity (pure radial load) and are left out;",
        "the angle rows are the B7214C points. The DEM's Q_max is the largest contact load at each sampled instant,",
        "averaged over the samples: the balls move, and between two passes of a ball over the load line the",
        "largest load is that of a ball up to half a pitch away (6208: 20 deg, Hertz cos^1.5(20 deg) = 0.91 of the",
        "peak), while the quasi-static solution has ball 1 on the load line: the DEM's Q_max lies 2-8 % below it",
        "although the ring displacement, which the balls' positions hardly change, agrees within 1 %. The B7214C",
        "at 1047 rad/s (10 000 rpm) differs more: there the DEM's balls slide and carry part of the gyroscopic",
        "moment themselves, so their contact angles and the ring's axial position lie between the quasi-static",
        "race-control hypotheses (docs/dem.md, B7214C at 10 000 rpm).",
        "",
        "## Difference against wall time (6208 grid: every fidelity applies)",
        "",
        f"Wall time: median per operating point; difference: the largest relative difference over the {n_6208} points",
        "from the quasi-static solution with tilts held (for the 6208 the same as the load-driven quasi-static",
        "solution).",
        "",
        "| fidelity | boundary condition | wall time (s) | " + " | ".join(label for _, label in PANELS) + " |",
        "|---|---|---|" + "---|" * len(PANELS),
    ]
    for name, (cost, errs) in entries.items():
        cells = []
        for quantity, _ in PANELS:
            mark = " (front)" if name in fronts[quantity] else ""
            cells.append("-" if errs[quantity] is None else f"{errs[quantity]:.3g}{mark}")
        lines.append(f"| {name} | {BOUNDARY[name]} | {cost:.3g} | " + " | ".join(cells) + " |")
    lines += [
        "",
        "![difference against wall time](fidelity_ladder.png)",
        "",
        "## Per point",
        "",
        "| bearing | omega (rad/s) | F_r (N) | F_a (N) | P_d (um) | T_oil (K) | Q_max in: analytic / QS / DEM (N) | "
        "torque: QS / DEM (N.m) | cage: QS / DEM / fine (rad/s) | DEM steady from (s) | DEM wall (s) |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        b, omega, F_r, F_z, Pd, T = r["point"]
        a = r["analytic"]
        lines.append(
            f"| {b} | {omega:g} | {F_r:g} | {F_z:g} | {'file' if Pd is None else f'{Pd * 1e6:g}'} | {T:g} | "
            f"{fmt(a['Q_max_inner'] if a else None)} / {r['qs']['Q_max_inner']:.4g} / {r['dem']['Q_max_inner']:.4g} | "
            f"{r['qs']['torque']:.3g} / {r['dem']['torque']:.3g} | "
            f"{r['qs']['omega_cage']:.4g} / {r['dem']['omega_cage']:.4g} / {r['fine']['omega_cage']:.4g} | "
            f"{r['dem']['steady_from']:.3f} | {r['time']['dem']:.2f} |"
        )
    lines += monitor_stops(rows, "stop", "Monitor stops at the default time step", "the default time step")
    lines += monitor_stops(rows, "fine_stop", "Monitor stops of the comparison run at dt / 4", "a quarter of it")
    return "\n".join(lines) + "\n"


def monitor_stops(rows, key, title, step):
    """Section listing the points where the DEM run `key` ('stop' or 'fine_stop') was stopped by the monitor."""
    stops = [r for r in rows if r[key]]
    lines = ["", f"## {title}", ""]
    if not stops:
        lines.append(f"None: every point ran at {step}.")
    for r in stops:
        lines.append(f"- {r['point']}: {r[key]} (repeated at the named time step)")
    return lines


def main():
    t0 = time.perf_counter()
    rows = run()
    table = errors(rows)
    (REPORTS / "fidelity_ladder.json").write_text(json.dumps(rows, indent=1, default=float))
    entries = ladder(rows)
    for (fidelity, quantity), values in table.items():
        key = f"{fidelity}: max relative difference of {quantity}"
        record("fidelity_ladder", key, max(values), "1", kind="difference")
    for name, (cost, _) in entries.items():
        record("fidelity_ladder", f"{name}: wall time per operating point", cost, "s", kind="timing")
    fronts = plot(entries, REPORTS / "fidelity_ladder.png")
    write_report("fidelity_ladder.md", report(rows, table, entries, fronts, time.perf_counter() - t0))
    return rows, table


if __name__ == "__main__":
    main()
