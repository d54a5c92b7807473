"""The corrected film (scene option film_correction = 'table') against fresh numerical EHL solutions at random
contact operating points of the 6208 and the B7214C with iso_vg68_mineral; writes docs/reports/film_correction.md.

Each bearing's table must have been built (`spindle film-table BEARING --lubricant iso_vg68_mineral`); its build time
is the one the table records. Random points, per bearing and race (seeded): oil temperature uniform over the
lubricant's range, entrainment speed and Hertz pressure log-uniform over the table's U_E_RANGE and P_H_RANGE
(models.film_table), the load from the pressure. At each, the Hamrock-Dowson film as the fidelities compute it,
uncorrected and corrected (kernels.film_correction, the kernel the fidelities call), against the solver as the
table's nodes are solved (models.film_table_build.solve_numerical: on the grid level the contact's film needs, 3 to 5,
the next finer where that one does not converge), with the fluid of models.film_check. The errors are those of the
table (the (M, L) reduction and the interpolation) against that solver, not the solver's own discretisation (within
about 2 % on the level chosen, docs/ehl_solver.md, Heavy contacts).

A table not yet in the cache is built first (its build time is then this run's).
Run: python -m benchmarks.film_correction [--points 16] [--clamped 4] [--jobs 2]
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core per solve (the coarse Newton's LU)

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402
from collections import Counter  # noqa: E402
from concurrent.futures import ProcessPoolExecutor  # noqa: E402

import numpy as np  # noqa: E402

from bearing_fmu.kernels import ehl  # noqa: E402
from bearing_fmu.kernels.film_correction import corrected_film_thickness  # noqa: E402
from bearing_fmu.kernels.hertz import hertz_contact  # noqa: E402
from bearing_fmu.kernels.lubricant import lubricant_state  # noqa: E402
from bearing_fmu.models import ehl_numerical as en  # noqa: E402
from bearing_fmu.models import film_table as ft  # noqa: E402
from bearing_fmu.models import film_table_build as ftb  # noqa: E402
from bearing_fmu.params import load_bearing, load_lubricant  # noqa: E402

from .render import cli, metric  # noqa: E402

BEARINGS = ("6208", "B7214C")
LUBRICANT = "iso_vg68_mineral"
TARGET = 0.03  # |error| of h_c and h_min for k >= 1
STUDIED_M = 3000.0  # the results' split: the heaviest M of the Annexe D grid study (docs/ehl_solver.md)
LEVELS = tuple(range(en.COARSEST_RESOLVING_LEVEL, en.FINEST_LEVEL + 1))  # the grid levels film_level chooses from
CLAMPED = 3.0  # the contacts beyond the table are drawn with M_CAP < M <= CLAMPED M_CAP


def _draw(rng, races, E_red, lubricant):
    """One random contact of the operating box: (race, T K, u m/s, Q N, M, L)."""
    race = int(rng.integers(2))
    Rx, Ry, c = races[race]
    T = rng.uniform(*ft.temperature_range(lubricant))
    u = math.exp(rng.uniform(*np.log(ft.U_E_RANGE)))
    p_h = math.exp(rng.uniform(*np.log(ft.P_H_RANGE)))
    Q = (p_h / hertz_contact(1.0, Rx, Ry, E_red, *c)[3]) ** 3
    eta, xi, _ = lubricant_state(T, lubricant.array)
    U, G, W = ehl.dimensionless_groups(eta, xi, E_red, u, Q, Rx)
    return race, T, u, Q, W * (2.0 * U) ** -0.75, G * (2.0 * U) ** 0.25


def random_points(bearing, lubricant, n_inside, n_clamped, seed):
    """Random contacts of the operating box (oil temperature uniform, speed and Hertz pressure log-uniform), kept
    (by rejection) n_inside within the table's range and n_clamped with M_CAP < M <= CLAMPED M_CAP and L <= L_CAP
    (the solver gives no reference beyond L_CAP); and the shares of the box beyond M_CAP and beyond L_CAP."""
    rng = np.random.default_rng(seed)
    races, E_red = ft.race_geometry(bearing)
    inside, clamped, drawn, beyond_m, beyond_l = [], [], 0, 0, 0
    while len(inside) < n_inside or len(clamped) < n_clamped:
        race, T, u, Q, M, L = _draw(rng, races, E_red, lubricant)
        drawn += 1
        beyond_m += M > ft.M_CAP
        beyond_l += L > ft.L_CAP
        if L > ft.L_CAP:
            continue
        if M <= ft.M_CAP and len(inside) < n_inside:
            inside.append((race, T, u, Q))
        elif ft.M_CAP < M <= CLAMPED * ft.M_CAP and len(clamped) < n_clamped:
            clamped.append((race, T, u, Q))
    share = [_draw(rng, races, E_red, lubricant)[4:] for _ in range(20000)]
    shares = dict(beyond_M=sum(M > ft.M_CAP for M, _ in share) / len(share),
                  beyond_L=sum(L > ft.L_CAP for _, L in share) / len(share),
                  inside=sum(M <= ft.M_CAP and L <= ft.L_CAP for M, L in share) / len(share))  # fmt: skip
    return inside + clamped, shares


def evaluate(args):
    """One random contact: formula, corrected and numerical films and the contact's M, L."""
    bearing_name, race, T, u, Q, table = args
    bearing, lubricant = load_bearing(bearing_name), load_lubricant(LUBRICANT)
    races, E_red = ft.race_geometry(bearing)
    Rx, Ry, c = races[race]
    eta, xi, _ = lubricant_state(T, lubricant.array)
    U, G, W = ehl.dimensionless_groups(eta, xi, E_red, u, Q, Rx)
    film = (ehl.FILM_HAMROCK_DOWSON, eta, xi, E_red, u, Q, Rx, Ry, c[0])
    formula = ehl.film_thickness(*film)
    corrected = corrected_film_thickness(*film, table, race)
    start = time.perf_counter()
    solution, level = ftb.solve_numerical(Rx, Ry, Q, u, E_red, eta, xi)
    return dict(bearing=bearing_name, race=race, T=T, u=u, Q=Q, k=c[0], M=W * (2.0 * U) ** -0.75,
                L=G * (2.0 * U) ** 0.25, formula=formula, corrected=corrected,
                numerical=(solution.h_c, solution.h_min), converged=bool(solution.converged), level=level,
                seconds=time.perf_counter() - start)  # fmt: skip


def table_record(name, lubricant, n_points, n_clamped, seed):
    """A bearing's table (built if not cached) as plain data, and its random contacts."""
    try:
        table = ft.load_film_table(name, LUBRICANT)
    except ft.FilmTableMissing:
        table = ftb.build_film_table(name, LUBRICANT, jobs=2)
    record = dict(
        seconds=table.seconds,
        nodes=sum(len(r.nodes) for r in table.races),
        distinct=sum(len({(n["M"], n["L"]) for n in r.nodes}) for r in table.races),
        late=sum(not n["converged"] for r in table.races for n in r.nodes),
        levels=Counter(n["level"] for r in table.races for n in {(n["M"], n["L"]): n for n in r.nodes}.values()),
        races=[dict(k=r.k, M=[n["M"] for n in r.nodes], L=[n["L"] for n in r.nodes]) for r in table.races],
    )
    points, record["box"] = random_points(load_bearing(name), lubricant, n_points, n_clamped, seed)
    return record, [(name, *point, table.array()) for point in points]


def measure(n_points=16, n_clamped=4, jobs=2, seed=2026):
    lubricant = load_lubricant(LUBRICANT)
    tables, contacts = {}, []
    for i, name in enumerate(BEARINGS):
        tables[name], points = table_record(name, lubricant, n_points, n_clamped, seed + i)
        contacts += points
    with ProcessPoolExecutor(jobs) as pool:
        rows = list(pool.map(evaluate, contacts))
    ranges = (
        ("M <= {studied:g}", lambda M: M <= STUDIED_M),
        ("{studied:g} < M <= {cap:g}", lambda M: STUDIED_M < M <= ft.M_CAP),
        ("M > {cap:g} (clamped)", lambda M: M > ft.M_CAP),
    )
    labels = dict(studied=STUDIED_M, cap=ft.M_CAP)
    return dict(
        name="film_correction",
        title="Corrected film against fresh numerical EHL solutions",
        about=__doc__.split("\n\n", 1)[1].split("Run:")[0],
        blocks=[
            box_text(),
            dict(table=tables_table(tables)),
            dict(text="Errors against the numerical film, max / mean |error| in %."),
            dict(table=summary_table(rows, tables, ranges, labels)),
            *target_texts(rows, ranges[:2], labels),
            dict(table=contacts_table(rows)),
            dict(
                text="Numerical solves: median {median:.1f} s, worst {worst:.1f} s.",
                values=dict(
                    median=float(np.median([r["seconds"] for r in rows])), worst=max(r["seconds"] for r in rows)
                ),
            ),
        ],
        metrics=[m for label, within in ranges[:2] for m in range_metrics(rows, label.format(**labels), within)],
    )


def box_text():
    return dict(
        text="Lubricant {lubricant}; film formula Hamrock-Dowson. Random contacts per race: oil temperature uniform "
        "over the lubricant's range, u_e log-uniform in {u0:g}-{u1:g} m/s, Hertz pressure log-uniform in "
        "{p0:g}-{p1:g} GPa (the operating box), kept within the table's range (M <= {cap:g}, L <= {lcap:g}) and, "
        "listed apart, with {cap:g} < M <= {clamp:g} (the table clamps them to its ratios at M = {cap:g}); beyond "
        "L = {lcap:g} the table has no nodes (the solver diverges at the heavy contacts there). Reference: the "
        "numerical solver as the table's nodes are solved (on the grid level the contact's film needs, 3 to 5, the "
        "next finer where that one does not converge); its own discretisation error, within about 2 % on the level "
        "chosen (docs/ehl_solver.md, Heavy contacts), is not in these numbers.",
        values=dict(
            lubricant=LUBRICANT, u0=ft.U_E_RANGE[0], u1=ft.U_E_RANGE[1], p0=ft.P_H_RANGE[0] / 1e9,
            p1=ft.P_H_RANGE[1] / 1e9, cap=ft.M_CAP, lcap=ft.L_CAP, clamp=CLAMPED * ft.M_CAP,
        ),
    )  # fmt: skip


def tables_table(tables):
    rows = []
    for name, t in tables.items():
        races = "; ".join(
            f"{('inner', 'outer')[i]}: k = {r['k']:.2f}, M {min(r['M']):.3g}-{max(r['M']):.4g}, "
            f"L {min(r['L']):.3g}-{max(r['L']):.3g}"
            for i, r in enumerate(t["races"])
        )
        box = t["box"]
        shares = f"{100 * box['inside']:.0f} % / {100 * box['beyond_M']:.0f} % / {100 * box['beyond_L']:.0f} %"
        levels = " / ".join(str(t["levels"].get(level, 0)) for level in LEVELS)
        rows.append([name, t["seconds"], f"{t['nodes']} ({t['distinct']})", levels, t["late"], races, shares])
    return dict(
        columns=["bearing", "build (s)", "nodes (distinct solves)",
                 "distinct solves on level " + " / ".join(map(str, LEVELS)), "not converged",
                 "race: k, M and L of the nodes", "operating box: within the table / M beyond / L beyond"],
        formats=[None, "{:.0f}", None, None, "{:d}", None, None],
        rows=rows,
    )  # fmt: skip


def _errors(row, which):
    n = row["numerical"]
    return [row[which][f] / n[f] - 1.0 for f in (0, 1)]


def _summary(rows, which):
    """[max |e_c|, mean |e_c|, max |e_min|, mean |e_min|] over rows, in %."""
    e = 100.0 * np.abs([_errors(r, which) for r in rows])
    return [f"{e[:, 0].max():.1f} / {e[:, 0].mean():.1f}", f"{e[:, 1].max():.1f} / {e[:, 1].mean():.1f}"]


def summary_table(rows, tables, ranges, labels):
    lines = []
    for label, within in ranges:
        for name in (*tables, "both"):
            chosen = [r for r in rows if within(r["M"]) and name in (r["bearing"], "both")]
            cells = _summary(chosen, "formula") + _summary(chosen, "corrected") if chosen else [None] * 4
            lines.append([f"{name}, {label.format(**labels)}", len(chosen), *cells])
    return dict(
        columns=["contacts", "n", "formula h_c", "formula h_min", "corrected h_c", "corrected h_min"],
        formats=[None, "{:d}", None, None, None, None],
        rows=lines,
    )


def largest_corrected_error(rows, within):
    """(largest |error| of the corrected h_c and h_min over the contacts with k >= 1 in the range, their number)."""
    chosen = [r for r in rows if within(r["M"]) and r["k"] >= 1.0]
    return max((max(abs(e) for e in _errors(r, "corrected")) for r in chosen), default=math.nan), len(chosen)


def target_texts(rows, ranges, labels):
    texts = []
    for label, within in ranges:
        worst, n = largest_corrected_error(rows, within)
        texts.append(
            dict(
                text="Target |error| <= {target:g} % on h_c and h_min for k >= 1, {label}: **{verdict}** (largest "
                "corrected error {worst:.1f} % over {n} contacts).",
                values=dict(target=100 * TARGET, label=label.format(**labels), worst=100 * worst, n=n,
                            verdict="met" if worst <= TARGET else "not met"),
            )
        )  # fmt: skip
    return texts


def range_metrics(rows, label, within):
    worst, _ = largest_corrected_error(rows, within)
    return [metric(f"corrected film, {label}: largest |error| (k >= 1)", worst, "1", "error")]


def contacts_table(rows):
    lines = []
    for r in sorted(rows, key=lambda r: (r["bearing"], r["race"], r["M"])):
        n, f, c = r["numerical"], _errors(r, "formula"), _errors(r, "corrected")
        lines.append([
            r["bearing"], ("inner", "outer")[r["race"]], r["T"], r["u"], r["Q"],
            f"{r['M']:.4g}" + (" (clamped)" if r["M"] > ft.M_CAP else ""), r["L"],
            f"{n[0] * 1e9:.1f} / {n[1] * 1e9:.1f}" + ("" if r["converged"] else " (not converged)"), r["level"],
            f"{100 * f[0]:+.1f}, {100 * f[1]:+.1f}", f"{100 * c[0]:+.1f}, {100 * c[1]:+.1f}", r["seconds"],
        ])  # fmt: skip
    return dict(
        columns=["bearing", "race", "T (K)", "u_e (m/s)", "Q (N)", "M", "L", "numerical h_c / h_min (nm)", "level",
                 "formula h_c, h_min (%)", "corrected h_c, h_min (%)", "solve (s)"],
        formats=[None, None, "{:.0f}", "{:.2f}", "{:.0f}", None, "{:.3g}", None, "{:d}", None, None, "{:.1f}"],
        rows=lines,
    )  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=16, help="random contacts per bearing within the table")
    parser.add_argument("--clamped", type=int, default=4, help="and beyond M_CAP (clamped)")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args(argv)
    cli(measure, "film_correction", n_points=args.points, n_clamped=args.clamped, jobs=args.jobs)


if __name__ == "__main__":
    main()
