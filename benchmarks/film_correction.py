"""The corrected film (scene option film_correction = 'table') against fresh numerical EHL solutions at random
contact operating points of the 6208 and the B7214C with iso_vg68_mineral; writes docs/reports/film_correction.md.

Each bearing's table must have been built (`spindle film-table BEARING --lubricant iso_vg68_mineral`); its build time
is the one the table records. Random points, per bearing and race (seeded): oil temperature uniform over the
lubricant's range, entrainment speed and Hertz pressure log-uniform over the table's U_E_RANGE and P_H_RANGE
(models.film_table), the load from the pressure. At each, the Hamrock-Dowson film as the fidelities compute it,
uncorrected and corrected (kernels.film_correction, the kernel the fidelities call), against the solver on the grid
of the table's nodes (level 3), with the fluid of models.film_check. The errors are those of the table (the
(M, L) reduction and the interpolation) against that solver, not the solver's own discretisation (about 2 % on
level 3, docs/ehl_solver.md).

measure() returns the data as a dict (also written to docs/reports/film_correction.json); render() writes the table.
Run: python -m benchmarks.film_correction [--points 12] [--jobs 2] [--render-only]
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core per solve (the coarse Newton's LU)

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
from concurrent.futures import ProcessPoolExecutor  # noqa: E402

import numpy as np  # noqa: E402

from bearing_fmu.kernels import ehl  # noqa: E402
from bearing_fmu.kernels import ehl_solver as es  # noqa: E402
from bearing_fmu.kernels.film_correction import corrected_film_thickness  # noqa: E402
from bearing_fmu.kernels.hertz import hertz_contact  # noqa: E402
from bearing_fmu.kernels.lubricant import lubricant_state  # noqa: E402
from bearing_fmu.models import ehl_numerical as en  # noqa: E402
from bearing_fmu.models import film_table as ft  # noqa: E402
from bearing_fmu.params import load_bearing, load_lubricant  # noqa: E402

from .common import REPORTS, machine, write_report  # noqa: E402

BEARINGS = ("6208", "B7214C")
LUBRICANT = "iso_vg68_mineral"
TARGET = 0.03  # |error| of h_c and h_min for k >= 1
STUDIED_M = 3000.0  # heaviest M of the solver's grid study (docs/ehl_solver.md)
CLAMPED = 3.0  # the contacts beyond the table are drawn with M_CAP < M <= CLAMPED M_CAP
DATA = REPORTS / "film_correction.json"


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
    fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
    start = time.perf_counter()
    solution = en.solve_contact(Rx, Ry, Q, u, E_red, eta, fluid, finest=ft.LEVEL)
    return dict(bearing=bearing_name, race=race, T=T, u=u, Q=Q, k=c[0], M=W * (2.0 * U) ** -0.75,
                L=G * (2.0 * U) ** 0.25, formula=formula, corrected=corrected,
                numerical=(solution.h_c, solution.h_min), converged=bool(solution.converged),
                seconds=time.perf_counter() - start)  # fmt: skip


def measure(n_points=16, n_clamped=4, jobs=2, seed=2026):
    """Every bearing's table record and its random contacts, as plain data."""
    load = os.getloadavg()[0]
    lubricant = load_lubricant(LUBRICANT)
    tables, jobs_list = {}, []
    for i, name in enumerate(BEARINGS):
        table = ft.load_film_table(name, LUBRICANT)
        tables[name] = dict(seconds=table.seconds, level=table.level, T_range=table.T_range,
                            nodes=sum(len(r.nodes) for r in table.races),
                            distinct=sum(len({(n["M"], n["L"]) for n in r.nodes}) for r in table.races),
                            late=sum(not n["converged"] for r in table.races for n in r.nodes),
                            races=[dict(k=r.k, M=(min(n["M"] for n in r.nodes), max(n["M"] for n in r.nodes)),
                                        L=(min(n["L"] for n in r.nodes), max(n["L"] for n in r.nodes)))
                                   for r in table.races])  # fmt: skip
        array = table.array()
        points, tables[name]["box"] = random_points(load_bearing(name), lubricant, n_points, n_clamped, seed + i)
        jobs_list += [(name, *point, array) for point in points]
    with ProcessPoolExecutor(jobs) as pool:
        rows = list(pool.map(evaluate, jobs_list))
    return dict(machine=machine(), load=(load, os.getloadavg()[0]), tables=tables, rows=rows, m_cap=ft.M_CAP,
                l_cap=ft.L_CAP, clamped=CLAMPED, p_h=ft.P_H_RANGE, u_e=ft.U_E_RANGE)  # fmt: skip


def _errors(row, which):
    n = row["numerical"]
    return [row[which][f] / n[f] - 1.0 for f in (0, 1)]


def _summary(rows, which):
    """(max |e_c|, mean |e_c|, max |e_min|, mean |e_min|) over rows."""
    if not rows:
        return None
    e = np.abs([_errors(r, which) for r in rows])
    return e[:, 0].max(), e[:, 0].mean(), e[:, 1].max(), e[:, 1].mean()


def _summary_line(label, rows):
    cells = [label, str(len(rows))]
    for which in ("formula", "corrected"):
        s = _summary(rows, which)
        cells += (
            ["" for _ in range(2)]
            if s is None
            else [f"{100 * s[0]:.1f} / {100 * s[1]:.1f}", f"{100 * s[2]:.1f} / {100 * s[3]:.1f}"]
        )
    return "| " + " | ".join(cells) + " |"


def render(data):
    """docs/reports/film_correction.md from measure()'s dict."""
    cap = data["m_cap"]
    lines = [
        "# Corrected film against fresh numerical EHL solutions",
        "",
        f"Generated by `python -m benchmarks.film_correction` on {data['machine']} (load average {data['load'][0]:.1f} "
        f"before, {data['load'][1]:.1f} after). Lubricant {LUBRICANT}; film formula Hamrock-Dowson; random contacts "
        f"per race with the oil temperature uniform over the lubricant's range, u_e log-uniform in "
        f"{data['u_e'][0]:g}-{data['u_e'][1]:g} m/s and the Hertz pressure log-uniform in "
        f"{data['p_h'][0] / 1e9:g}-{data['p_h'][1] / 1e9:g} GPa (the operating box), kept within the table's range "
        f"(M <= {cap:g}, L <= {data['l_cap']:g}) and, listed apart, with {cap:g} < M <= {data['clamped'] * cap:g} (the table "
        f"clamps them to its ratios at M = {cap:g}); beyond L = {data['l_cap']:g} the solver diverges and gives no "
        "reference. Reference: the numerical solver on grid level 3 (the level of the table's nodes; its own "
        f"discretisation error, about 2 % up to M ~ {STUDIED_M:g} and not measured beyond, is not in these numbers).",
        "",
        "## Tables",
        "",
        "| bearing | build (s) | nodes (distinct solves) | not converged | race: k, M range, L range of the nodes "
        "| operating box: within the table / M beyond / L beyond |",
        "|---|---|---|---|---|---|",
    ]
    for name, t in data["tables"].items():
        races = "; ".join(
            f"{'inner' if i == 0 else 'outer'}: k = {r['k']:.2f}, M {r['M'][0]:.3g}-{r['M'][1]:.4g}, "
            f"L {r['L'][0]:.3g}-{r['L'][1]:.3g}"
            for i, r in enumerate(t["races"])
        )
        box = t["box"]
        shares = f"{100 * box['inside']:.0f} % / {100 * box['beyond_M']:.0f} % / {100 * box['beyond_L']:.0f} %"
        lines.append(
            f"| {name} | {t['seconds']:.0f} | {t['nodes']} ({t['distinct']}) | {t['late']} | {races} | {shares} |"
        )
    rows = data["rows"]
    # the solver's grid study reaches M ~ 3000 (docs/ehl_solver.md): the heavier contacts are reported apart
    ranges = [
        (f"M <= {STUDIED_M:g}", lambda M: M <= STUDIED_M),
        (f"{STUDIED_M:g} < M <= {cap:g}", lambda M: STUDIED_M < M <= cap),
        (f"M > {cap:g} (clamped)", lambda M: M > cap),
    ]
    lines += [
        "",
        "## Summary",
        "",
        "Errors against the numerical film, max / mean |error| in %.",
        "",
        "| contacts | n | formula h_c | formula h_min | corrected h_c | corrected h_min |",
        "|---|---|---|---|---|---|",
    ]
    for label, within in ranges:
        for name in data["tables"]:
            lines.append(
                _summary_line(f"{name}, {label}", [r for r in rows if r["bearing"] == name and within(r["M"])])
            )
        lines.append(_summary_line(f"both, {label}", [r for r in rows if within(r["M"])]))
    lines.append("")
    for label, within in ranges[:2]:
        met = [r for r in rows if within(r["M"]) and r["k"] >= 1.0]
        worst = max((max(abs(e) for e in _errors(r, "corrected")) for r in met), default=math.nan)
        verdict = "met" if worst <= TARGET else "not met"
        lines.append(
            f"Target |error| <= {100 * TARGET:g} % on h_c and h_min for k >= 1, {label}: **{verdict}** (largest "
            f"corrected error {100 * worst:.1f} % over {len(met)} contacts)."
        )
    lines += [
        "",
        "## Every contact",
        "",
        "| bearing | race | T (K) | u_e (m/s) | Q (N) | M | L | numerical h_c / h_min (nm) | formula h_c, h_min (%) "
        "| corrected h_c, h_min (%) | solve (s) |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in sorted(rows, key=lambda r: (r["bearing"], r["race"], r["M"])):
        n = r["numerical"]
        f, c = _errors(r, "formula"), _errors(r, "corrected")
        flag = "" if r["converged"] else " (not converged)"
        lines.append(
            f"| {r['bearing']} | {'inner' if r['race'] == 0 else 'outer'} | {r['T']:.0f} | {r['u']:.2f} | "
            f"{r['Q']:.0f} | {r['M']:.4g}{' (clamped)' if r['M'] > cap else ''} | {r['L']:.3g} | "
            f"{n[0] * 1e9:.1f} / {n[1] * 1e9:.1f}{flag} | {100 * f[0]:+.1f}, {100 * f[1]:+.1f} | "
            f"{100 * c[0]:+.1f}, {100 * c[1]:+.1f} | {r['seconds']:.1f} |"
        )
    seconds = [r["seconds"] for r in rows]
    lines += ["", f"Numerical solves: median {statistics.median(seconds):.1f} s, worst {max(seconds):.1f} s."]
    write_report("film_correction.md", "\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=16, help="random contacts per bearing within the table")
    parser.add_argument("--clamped", type=int, default=4, help="and beyond M_CAP (clamped)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--render-only", action="store_true", help="render the table from the saved data")
    args = parser.parse_args()
    if not args.render_only:
        data = measure(args.points, args.clamped, args.jobs)
        DATA.write_text(json.dumps(data, indent=1) + "\n")
    render(json.loads(DATA.read_text()))


if __name__ == "__main__":
    main()
