"""The fidelity ladder: the difference between the analytic, quasi-static and DEM fidelities, against wall time.

Not an error against an independent reference (that is benchmarks/reference_table.py): each fidelity is compared
with another solution of the product, and each row states the boundary condition of the ring in its solution.

Grid, ISO VG68 mineral oil. 6208: speed 100 / 500 / 1700 rad/s x radial load 0.75 / 3 / 7.5 kN x diametral
clearance 0 / +25 um x oil temperature 40 / 70 C (36 points). B7214C (quasi-static and DEM: the analytic fidelity
is for radially loaded deep-groove bearings), at 500 and at 1047 rad/s: 800 N axial at 40 C (the middle point),
2 kN radial + 3 kN axial at 40 C, and each axis with the others at the middle point: axial load 400 / 3000 N, oil
temperature 70 C, fixed preload 400 / 800 / 1600 N under the 2 kN radial load (16 points). A single bearing's
preload is in the product an axial load (a spring preload: the axial-load points) or BearingFixed.fmu's F_preload
(a fixed preload: the inner ring held axially at the approach that carries F_preload at rest).

Comparison solutions, the best available for each quantity:
- static equilibrium (ring displacement, Q_max, contact angle, stiffness diagonal, a fixed preload's axial
  reaction) and what is computed from it with the same formulas (film, capacitance, Houpert torque): the
  quasi-static solution with the boundary condition of the fidelity compared. The DEM's inner ring is free in x, y,
  z and both tilts like Bearing.fmu's (under a fixed preload it carries the axial reaction of BearingFixed.fmu's
  solution); the analytic fidelity's ring does not tilt: it is compared with the quasi-static solution with the
  tilts held at zero. For the 6208 under a radial load tilt does not couple (contacts in the mid-plane); for a
  single angular-contact bearing under a combined load it does, strongly: the rows of the free ring against the
  tilt-held one (under a fixed preload: tilts and axial position held) show by how much, a difference of boundary
  condition, not an error;
- dynamics (cage speed): the DEM at a fine time step (a quarter of the default).

Wall time per operating point: analytic one evaluation, quasi-static a cold solve (fresh model) and a warm one
(after a 1 % load change), DEM the protocol to a steady state at the default settings (2 ms settling under the
load, 5 ms speed ramp, running until the cage speed averaged over 10 ms changes by less than 0.1 % from one window
to the next (at most 3 s), means over the next 10 ms).

Race control over speed: under thrust at speed a race-control hypothesis can ask more traction of the contacts than
the oil carries. The 218 angular-contact bearing of the textbook thrust cases (40 deg, 8.9 kN, the Guessasma oil:
constant viscosity, limiting traction coefficient 0.06) at 3 000-15 000 rpm and the B7214C (800 N, ISO VG68) at
3 000, 10 000 and 15 000 rpm: the quasi-static fidelity with outer-race control (the default) and with the race
control from traction against the DEM's steady state (means over 0.281-0.300 s after a 10 ms ramp), with the
traction coefficient outer-race control requires (mu_required) and the warm solve's wall time.

Run: python -m benchmarks.fidelity_ladder: docs/reports/fidelity_ladder.md and .png.
"""

import itertools
import math
import statistics
import time
from typing import NamedTuple

import numpy as np

from bearing_fmu import AnalyticModel, QuasiStaticModel, Scene, load_bearing
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.dem import DemModel, DemUnstableError
from tests.cases.race_control import B218, RACE_COMPARED, RACE_SCENE, dem_steady

from .render import cli, metric

LUBRICANT = "iso_vg68_mineral"
QS_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")  # the scene of Bearing.fmu
DISPLACEMENT_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static_displacement.toml")  # of BearingDisp.fmu
FIXED_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static_fixed_preload.toml")  # of BearingFixed.fmu
T40, T70 = 313.15, 343.15  # K
GRID_6208 = dict(omega=(100.0, 500.0, 1700.0), F_r=(750.0, 3000.0, 7500.0), Pd=(0.0, 25e-6), T_oil=(T40, T70))


class Point(NamedTuple):
    bearing: str
    omega: float  # rad/s
    F_r: float  # N, radial load on y, the line of ball 1 (docs/conventions.md)
    F_z: float  # N, axial load (0 under a fixed preload: the axial position is held)
    Pd: float | None  # m, diametral clearance (None: the bearing file's)
    T_oil: float  # K
    F_preload: float = 0.0  # N, fixed preload (BearingFixed.fmu's F_preload); 0: load-driven


def points():
    for omega, F_r, Pd, T_oil in itertools.product(*GRID_6208.values()):
        yield Point("6208", omega, F_r, 0.0, Pd, T_oil)
    for omega in (500.0, 1047.2):
        yield from (Point("B7214C", omega, 0.0, F_z, None, T40) for F_z in (400.0, 800.0, 3000.0))
        yield Point("B7214C", omega, 2000.0, 3000.0, None, T40)
        yield Point("B7214C", omega, 0.0, 800.0, None, T70)
        yield from (Point("B7214C", omega, 2000.0, 0.0, None, T40, F_p) for F_p in (400.0, 800.0, 1600.0))


QUANTITIES = (  # (output, label, kind): kind 'static' -> quasi-static reference, 'dynamic' -> fine DEM
    ("y", "y radial displacement", "static"),
    ("z", "z axial displacement", "static"),
    ("F_z", "F_z axial reaction (fixed preload)", "static"),
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
FIXED_RING = "fixed preload: quasi-static, ring free but its axial position (BearingFixed.fmu)"
FIXED_DEM = "fixed preload: DEM"
HELD, FIXED_HELD = "quasi-static, tilts held", "quasi-static, tilts and axial position held"
FREE = "inner ring free in x, y, z and both tilts under the loads"
BOUNDARY = {  # the boundary condition of the ring in each solution compared
    "analytic": "inner ring displaced along the radial load only (continuous-ball load integral)",
    FREE_RING: FREE,
    FIXED_RING: "inner ring held axially at the approach of F_preload at rest, free in x, y and both tilts",
    FIXED_DEM: f"{FREE}; axially the reaction of BearingFixed.fmu's solution",
    "quasi-static, warm": "as Bearing.fmu: inner ring free in 5 DOF; re-solve after a 1 % load change",
    "quasi-static, cold": "as Bearing.fmu: inner ring free in 5 DOF; fresh model",
    **dict.fromkeys(("DEM", "DEM, default dt", "DEM, dt / 4"), FREE),
}
REFERENCES = {  # the solution each fidelity's static quantities are compared with: (row key, its name)
    "analytic": ("held", HELD),
    FREE_RING: ("held", HELD),
    "DEM": ("qs", FREE_RING),
    FIXED_RING: ("held", FIXED_HELD),
    FIXED_DEM: ("qs", FIXED_RING),
}
SETTLE, RAMP, STEADY, WINDOW, PARTS = 2e-3, 5e-3, 0.030, 0.010, 5  # s, s, s, s, -
STEADY_CHANGE, MAX_TIME = 1e-3, 3.0  # -, s
PANELS = (("y", "ring displacement y"), ("Q_max_inner", "Q_max inner"), ("h_min_outer", "h_min outer"))
PANELS += (("torque", "torque"),)
FLOOR = 1e-7  # a difference below it is drawn at it (log axes)
RUNS = (("stop", "default time step"), ("fine_stop", "dt / 4"))  # the DEM runs of a point (monitor stops)
MISSING = "–"


def stiffness_diagonal(K):
    """The radial (along the load, y) and axial (z) stiffness of a 5 x 5 matrix K (numpy, 0-based), named as the
    FMUs name them (1-based: K[2,2] = dF_y/dy, K[3,3] = dF_z/dz)."""
    return {"K[2,2]": float(K[1, 1]), "K[3,3]": float(K[2, 2])}


def analytic_point(p):
    """Outputs and wall time (s) of one analytic evaluation (None where the fidelity does not apply)."""
    if p.bearing != "6208" or p.F_z:
        return None, None
    model = AnalyticModel(p.bearing, LUBRICANT, Pd=p.Pd)
    model.evaluate(omega=p.omega, F_y=p.F_r, T_oil=p.T_oil)  # compile / warm
    t0 = time.perf_counter()
    out = model.evaluate(omega=p.omega, F_y=p.F_r, T_oil=p.T_oil)
    return dict(out, alpha_inner=0.0, x=0.0, z=0.0), time.perf_counter() - t0


def quasi_static_point(p):
    """Outputs (the ring free in all 5 DOF, as Bearing.fmu; under a fixed preload in all but z, as
    BearingFixed.fmu), cold-solve wall time (s) and warm-solve wall time (s, re-solve after a 1 % load change)."""
    scene = FIXED_SCENE if p.F_preload else QS_SCENE
    loads = dict(F_y=p.F_r) if p.F_preload else dict(F_y=p.F_r, F_z=p.F_z)
    t0 = time.perf_counter()
    model = QuasiStaticModel(p.bearing, LUBRICANT, scene=scene, Pd=p.Pd, F_preload=p.F_preload)
    out = model.evaluate(omega=p.omega, T_oil=p.T_oil, **loads)
    cold = time.perf_counter() - t0
    model.evaluate(omega=p.omega, T_oil=p.T_oil, **{k: 1.01 * v for k, v in loads.items()})
    t0 = time.perf_counter()
    out = model.evaluate(omega=p.omega, T_oil=p.T_oil, **loads)
    warm = time.perf_counter() - t0
    held = dict(z=model.z0) if p.F_preload else {}  # the axial position a fixed preload holds
    return dict(out, **held, **stiffness_diagonal(model.K)), cold, warm


def quasi_static_tilts_held(p, start):
    """The quasi-static equilibrium with the ring's tilts held at zero (the analytic fidelity's ring does not
    tilt): the displacement-driven model at theta = 0, with Newton on (x, y, z) (on (x, y) under a
    fixed preload, z held at its assembly approach) until the reactions equal the applied loads to 1e-9 of the
    load. `start`: the quasi-static outputs (first guess)."""
    model = QuasiStaticModel(p.bearing, LUBRICANT, scene=DISPLACEMENT_SCENE, Pd=p.Pd)
    free = 2 if p.F_preload else 3
    target = np.array([0.0, p.F_r, p.F_z])[:free]
    d = np.array([start["x"], start["y"], start["z"]])
    for _ in range(50):
        out = model.evaluate(omega=p.omega, x=d[0], y=d[1], z=d[2], theta_x=0.0, theta_y=0.0, T_oil=p.T_oil)
        residual = target - np.array([out["F_x"], out["F_y"], out["F_z"]])[:free]
        if np.max(np.abs(residual)) <= 1e-9 * np.max(np.abs(target)):
            return dict(out, x=d[0], y=d[1], z=d[2], **stiffness_diagonal(model.K))
        d[:free] += np.linalg.solve(model.K[:free, :free], residual)
    raise RuntimeError(f"tilt-held quasi-static reference did not converge at {p}")


def dem_point(p, F_z, dt=None):
    """Steady means of the DEM outputs after the start-up protocol under the radial load and the axial load F_z
    (N), its wall time (s), the time step used (s) and the monitor's message if the first attempt stopped (then the
    run is repeated at the time step the message names, as a user would)."""
    try:
        return (*dem_run(p, F_z, dt), None)
    except DemUnstableError as error:
        message = str(error)
        suggested = float(message.split("use dt <= ")[1].split(" s")[0])
        return (*dem_run(p, F_z, suggested), message)


def dem_run(p, F_z, dt):
    t0 = time.perf_counter()
    model = DemModel(p.bearing, LUBRICANT, Pd=p.Pd, dt=dt)
    loads = dict(F_y=p.F_r, F_z=F_z, T_oil=p.T_oil)
    model.advance(SETTLE, omega=0.0, **loads)
    for k in range(1, 21):
        model.advance(SETTLE + RAMP * k / 20, omega=p.omega * k / 20, **loads)
    model.advance(STEADY, omega=p.omega, **loads)
    # steady when the cage speed averaged over a window changes by less than STEADY_CHANGE from the previous
    # window (light loads with a thick film take up to a second to roll up: the traction is small)
    previous = model.advance(model.time + WINDOW, omega=p.omega, **loads)["omega_cage"]
    while model.time < MAX_TIME:
        current = model.advance(model.time + WINDOW, omega=p.omega, **loads)["omega_cage"]
        if abs(current - previous) <= STEADY_CHANGE * abs(current):
            break
        previous = current
    steady_from = model.time
    samples = []
    for k in range(1, PARTS + 1):
        out = model.advance(steady_from + WINDOW * k / PARTS, omega=p.omega, **loads)
        samples.append(dict(out, **stiffness_diagonal(model.stiffness_matrix())))
    wall = time.perf_counter() - t0
    means = {key: float(np.mean([s[key] for s in samples])) for key in samples[0]}
    return dict(means, steady_from=steady_from), wall, model.dt


def run():
    rows = []
    for p in points():
        analytic, t_analytic = analytic_point(p)
        qs, t_qs_cold, t_qs_warm = quasi_static_point(p)
        held = quasi_static_tilts_held(p, qs)
        F_a = qs["F_z"] if p.F_preload else p.F_z  # the axial load the DEM carries
        dem, t_dem, dt_default, stop = dem_point(p, F_a)
        fine, t_fine, _, fine_stop = dem_point(p, F_a, dt=0.25 * dt_default)
        times = dict(analytic=t_analytic, qs_cold=t_qs_cold, qs_warm=t_qs_warm, dem=t_dem, dem_fine=t_fine)
        rows.append(dict(point=p, F_a=F_a, analytic=analytic, qs=qs, held=held, dem=dem, fine=fine, time=times))
        rows[-1].update(stop=stop, fine_stop=fine_stop)
        print(p, f"DEM {t_dem:.2f} s, fine {t_fine:.2f} s", flush=True)
    return rows


def relative_error(value, reference):
    """|value - reference| / |reference|; for a zero reference the absolute value is returned as is."""
    return abs(value - reference) / abs(reference) if reference else abs(value)


def errors(rows):
    """{(fidelity, quantity): [relative differences over the points where both exist]} from the comparison
    solutions."""
    table = {}
    for row in rows:
        p = row["point"]
        fidelities = (FIXED_RING, FIXED_DEM) if p.F_preload else ("analytic", FREE_RING, "DEM")
        for name, _, kind in QUANTITIES:
            unloaded = (name == "y" and p.F_r == 0.0) or (name == "z" and p.F_z == 0.0 and not p.F_preload)
            if unloaded or (name == "alpha_inner" and p.bearing == "6208"):
                continue  # zero by symmetry in every fidelity (or not modelled): no information
            for fidelity in fidelities:
                outputs = row["dem" if "DEM" in fidelity else "analytic" if fidelity == "analytic" else "qs"]
                reference = row["fine" if kind == "dynamic" else REFERENCES[fidelity][0]]
                if outputs is None or name not in outputs or (name == "z" and fidelity == FIXED_RING):
                    continue  # not an output, or held by both solutions
                table.setdefault((fidelity, name), []).append(relative_error(outputs[name], reference[name]))
    return table


def ladder(rows):
    """Per fidelity: the median wall time per operating point (s) and, per panel quantity, the largest relative
    difference from the tilt-held quasi-static solution over the 6208 points (where every fidelity applies)."""
    deep = [r for r in rows if r["point"].bearing == "6208"]
    entries = {
        "analytic": ("analytic", "analytic"),
        "quasi-static, warm": ("qs", "qs_warm"),
        "quasi-static, cold": ("qs", "qs_cold"),
        "DEM, default dt": ("dem", "dem"),
        "DEM, dt / 4": ("fine", "dem_fine"),
    }
    result = {}
    for name, (outputs, timing) in entries.items():
        errs = {}
        for quantity, _ in PANELS:
            values = [relative_error(r[outputs][quantity], r["held"][quantity]) for r in deep if quantity in r[outputs]]
            errs[quantity] = max(values) if values else None
        result[name] = (statistics.median(r["time"][timing] for r in deep), errs)
    return result


def pareto(cost, error):
    """Names on the Pareto front of (cost, error): no other entry is both cheaper and at least as accurate."""
    front, best = [], math.inf
    for name in sorted(cost, key=lambda n: (cost[n], error[n])):
        if error[name] < best:
            front.append(name)
            best = error[name]
    return front


def fronts_and_figure(entries):
    """The Pareto front per panel quantity and the figure spec (one colour per fidelity in every panel)."""
    fronts, panels = {}, []
    axes = dict(xlabel="wall time per operating point (s)", ylabel=f"relative difference from {HELD}")
    for quantity, label in PANELS:
        cost = {n: c for n, (c, e) in entries.items() if e[quantity] is not None}
        error = {n: max(entries[n][1][quantity], FLOOR) for n in cost}
        fronts[quantity] = front = pareto(cost, error)
        series = [
            dict(x=[cost.get(n)] * (n in cost), y=[error.get(n)] * (n in cost), label=n, style="o") for n in entries
        ]
        series.append(dict(x=[cost[n] for n in front], y=[error[n] for n in front], label="Pareto front", style="k--"))
        panels.append(dict(axes, title=f"{label} (max over the 6208 grid)", xscale="log", yscale="log", series=series))
    title = f"Fidelity ladder (differences below {FLOOR:g} drawn at {FLOOR:g})"
    return fronts, dict(file="fidelity_ladder.png", caption="difference against wall time", title=title, panels=panels)


def difference_table(table):
    rows = []
    for name, label, kind in QUANTITIES:
        for fidelity in ("analytic", FREE_RING, "DEM", FIXED_RING, FIXED_DEM):
            values = table.get((fidelity, name))
            reference = "DEM, dt / 4" if kind == "dynamic" else REFERENCES[fidelity][1]
            if values:
                rows.append([label, reference, fidelity, BOUNDARY[fidelity], len(values)])
                rows[-1] += [statistics.median(values), max(values)]
    columns = ["quantity", "compared with", "fidelity", "its boundary condition", "points", "median", "max"]
    formats = [None, None, None, None, "{:d}", "{:.3g}", "{:.3g}"]
    caption = "Differences from the comparison solutions (relative, over the grid):"
    return dict(caption=caption, columns=columns, formats=formats, rows=rows)


def ladder_table(entries, fronts):
    rows = []
    for name, (cost, errs) in entries.items():
        cells = [MISSING if errs[q] is None else f"{errs[q]:.3g}" + " (front)" * (name in fronts[q]) for q, _ in PANELS]
        rows.append([name, BOUNDARY[name], cost, *cells])
    columns = ["fidelity", "boundary condition", "wall time (s)", *(label for _, label in PANELS)]
    caption = (
        "Difference against wall time on the 6208 grid, where every fidelity applies (wall time: median per "
        "operating point; difference: the largest relative one over the grid from the quasi-static solution with "
        "tilts held, there the same as the free ring's; (front): on the Pareto front of the quantity):"
    )
    return dict(caption=caption, columns=columns, formats=[None, None, "{:.3g}"] + [None] * len(PANELS), rows=rows)


def per_point_table(rows):
    lines = []
    for r in rows:
        p, a, qs, dem = r["point"], r["analytic"], r["qs"], r["dem"]
        analytic = MISSING if a is None else f"{a['Q_max_inner']:.4g}"
        lines.append([p.bearing, p.omega, p.F_r, r["F_a"], p.F_preload or None, p.Pd and p.Pd * 1e6, p.T_oil])
        lines[-1] += [f"{analytic} / {qs['Q_max_inner']:.4g} / {dem['Q_max_inner']:.4g}"]
        lines[-1] += [f"{qs['torque']:.3g} / {dem['torque']:.3g}", f"{qs['omega_cage']:.4g} / {dem['omega_cage']:.4g}"]
        lines[-1] += [r["fine"]["omega_cage"], dem["steady_from"], r["time"]["dem"]]
    columns = ["bearing", "omega (rad/s)", "F_r (N)", "F_a (N)", "fixed preload (N)", "P_d (um; –: file)", "T_oil (K)"]
    columns += ["Q_max in: analytic / QS / DEM (N)", "torque: QS / DEM (N.m)", "cage: QS / DEM (rad/s)"]
    columns += ["cage: DEM dt / 4 (rad/s)", "DEM steady from (s)", "DEM wall (s)"]
    formats = [None, "{:g}", "{:g}", "{:.4g}", "{:g}", "{:g}", "{:g}", None, None, None, "{:.4g}", "{:.3f}", "{:.2f}"]
    caption = (
        "Per point (F_a: the axial load; under a fixed preload the axial reaction of BearingFixed.fmu's solution, "
        "which the DEM carries):"
    )
    return dict(caption=caption, columns=columns, formats=formats, rows=lines)


def stops_block(rows):
    stops = [[str(tuple(r["point"])), run, r[key]] for r in rows for key, run in RUNS if r[key]]
    caption = "Monitor stops (each run repeated at the time step the message names):"
    table = dict(caption=caption, columns=["point", "run", "monitor's message"], rows=stops)
    return dict(table=table) if stops else dict(text="Monitor stops: none, every DEM run ran at its first time step.")


def dem_note(rows):
    """The DEM's Q_max against the quasi-static one over the 6208 grid, with the half pitch that explains it."""
    deep = [r for r in rows if r["point"].bearing == "6208"]
    q = [r["dem"]["Q_max_inner"] / r["qs"]["Q_max_inner"] - 1.0 for r in deep]
    y = [relative_error(r["dem"]["y"], r["qs"]["y"]) for r in deep]
    half_pitch = 180.0 / load_bearing("6208").Z
    values = dict(half_pitch=half_pitch, hertz=math.cos(math.radians(half_pitch)) ** 1.5)
    values.update(q_low=min(q), q_high=max(q), y_max=max(y))
    return dict(
        text="Contact angles of the 6208 are zero by symmetry in every fidelity (pure radial load) and are left out; "
        "the angle rows are the B7214C points. The DEM's Q_max is the largest contact load at each sampled instant, "
        "averaged over the samples: the balls move, and between two passes of a ball over the load line the "
        "largest load is that of a ball up to half a pitch away ({half_pitch:.0f} deg for the 6208; Hertz "
        "cos^1.5 of it = {hertz:.2f} of the peak), while the quasi-static solution has ball 1 on the load line. "
        "Over the 6208 grid the DEM's Q_max lies {q_low:+.1%} to {q_high:+.1%} from the quasi-static solution's, "
        "its ring displacement y within {y_max:.2%}.",
        values=values,
    )


# (bearing, lubricant, rpm, thrust N, the DEM's path: None = from rest, or the speed it comes from)
RACE_CASES = (
    *((B218, "guessasma_oil", rpm, 8900.0, None) for rpm in (3000.0, 5000.0, 8000.0, 12000.0, 15000.0)),
    (B218, "guessasma_oil", 15000.0, 8900.0, 12000.0),
    *(("B7214C", LUBRICANT, rpm, 800.0, None) for rpm in (3000.0, 10000.0, 15000.0)),
)


def quasi_static_race(bearing, lubricant, rpm, F_z, race_control):
    """The quasi-static outputs at rpm under F_z (N) (a cold solve) and the median wall time (s) of a warm solve (1 %
    load change)."""
    model = QuasiStaticModel(bearing, lubricant, scene=RACE_SCENE, race_control=race_control)
    omega = rpm * math.pi / 30.0
    out = model.evaluate(omega=omega, F_z=F_z)
    times = []
    for k in range(7):
        start = time.perf_counter()
        model.evaluate(omega=omega, F_z=F_z * (1.01 if k % 2 == 0 else 1.0))
        times.append(time.perf_counter() - start)
    return out, statistics.median(times)


def race_control_block():
    """Table of the race controls against the DEM over speed."""
    rows, worst, skid = [], {}, {}
    for bearing, lubricant, rpm, F_z, via in RACE_CASES:
        dem, dem_time = dem_steady(bearing, lubricant, rpm, F_z, via)
        name = ("218" if bearing == B218 else bearing) + ("" if via is None else f", DEM via {via:.0f} rpm")
        for control in ("outer", "traction"):
            out, warm = quasi_static_race(bearing, lubricant, rpm, F_z, control)
            diff = [out[key] / dem[key] - 1.0 for key in RACE_COMPARED]
            worst[control] = max(worst.get(control, 0.0), *(abs(d) for d in diff))
            if bearing == B218 and rpm in (8000.0, 12000.0):  # where outer-race control asks more than the oil gives
                skid[control] = max(skid.get(control, 0.0), *(abs(d) for d in diff))
            mu = max(out["mu_required_inner"], out["mu_required_outer"]) if control == "outer" else None
            rows.append([name, rpm, control, *(100.0 * d for d in diff), mu, 1e3 * warm, dem_time])
    columns = ["bearing", "n (rpm)", "race control", "cage (%)", "torque (%)", "Q_max i (%)", "Q_max o (%)",
               "alpha i (%)", "alpha o (%)", "mu_required", "warm solve (ms)", "DEM run (s)"]  # fmt: skip
    formats = ["{}", "{:.0f}", "{}"] + ["{:+.2f}"] * 6 + ["{:.4f}", "{:.3f}", "{:.1f}"]
    caption = (
        "Race control over speed: quasi-static (cold solves) against the DEM's steady state (difference in %), the DEM "
        "ramped from rest in 10 ms unless it comes from another speed; mu_required the largest traction coefficient "
        "outer-race control asks of a contact (both oils carry 0.06). The 218 at 15 000 rpm has two steady states: the "
        "DEM ramped from rest stays outer-race controlled, the DEM coming from 12 000 rpm keeps the balls' skid of "
        "8 000-12 000 rpm (cage 6.5 % faster). The traction solution's cold start lands on the skid (the row of the "
        "DEM via 12 000 rpm); the traction equations have several solutions there (docs/quasistatic.md, section 2)."
    )
    metrics = [metric(f"race control {c}: max relative difference to the DEM, 218 at 8 000-12 000 rpm", v, "1",
                      "difference") for c, v in skid.items()]  # fmt: skip
    metrics += [metric(f"race control {c}: max relative difference to the DEM over every row (two states at 15 000 "
                       "rpm)", v, "1", "difference") for c, v in worst.items()]  # fmt: skip
    return dict(table=dict(caption=caption, columns=columns, formats=formats, rows=rows)), metrics


def measure():
    rows = run()
    table, entries = errors(rows), ladder(rows)
    fronts, figure = fronts_and_figure(entries)
    count = dict(total=len(rows), b7214c=sum(r["point"].bearing == "B7214C" for r in rows))
    count.update(preload=sum(bool(r["point"].F_preload) for r in rows))
    metrics = [metric(f"{f}: max relative difference of {q}", max(v), "1", "difference") for (f, q), v in table.items()]
    metrics += [metric(f"{n}: wall time per operating point", c, "s", "timing") for n, (c, _) in entries.items()]
    race_block, race_metrics = race_control_block()
    metrics += race_metrics
    blocks = [
        dict(
            text="{total} operating points, {b7214c} of them of the B7214C ({preload} under a fixed preload).",
            values=count,
        ),
        dict(table=difference_table(table)),
        dem_note(rows),
        dict(table=ladder_table(entries, fronts)),
        dict(figure=figure),
        dict(table=per_point_table(rows)),
        stops_block(rows),
        race_block,
    ]
    title = "Fidelity ladder: difference between the analytic, quasi-static and DEM fidelities"
    about = __doc__.split("\n", 2)[2].split("Run:")[0]
    return dict(name="fidelity_ladder", title=title, about=about, blocks=blocks, metrics=metrics)


def main(argv=None):
    cli(measure, "fidelity_ladder")


if __name__ == "__main__":
    main()
