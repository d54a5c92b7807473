"""Numerical EHL solver against the thesis' Annexe D (55 elliptical cases, lubricant 2 at 313 K, modified WLF
viscosity and Murnaghan density) and its time per case; writes docs/reports/ehl_solver.md.

    python -m benchmarks.ehl_solver [--level 3] [--cases 1,6,...] [--out docs/reports/ehl_solver.md]
    python -m benchmarks.ehl_solver --study 6,28 --levels 1,2,3,4 [--out docs/reports/ehl_grid_study.md]
    python -m benchmarks.ehl_solver --pareto 1,2,3   (after a table run per level: docs/reports/ehl_pareto.png)

Each row: the thesis' h_c, h_min, hm_centre, hm_lateral, the solver's, their relative differences, the
convergence record and the wall time of the solve (one core: BLAS limited to one thread, compiled kernels
cached), with the load average of the machine over the run. `--study` solves each case on every level and
gives the observed order and the Richardson estimate of h_c and h_min from the three finest levels.
"""

import os

# one core: the dense LU of the coarse-grid Newton must not spread over cores that other work is using (set
# before numpy loads OpenBLAS)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import csv  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from bearing_fmu.kernels import ehl_solver as es  # noqa: E402
from bearing_fmu.models import ehl_numerical as en  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "validation" / "data" / "thesis_annexe_d_ehl.csv"
E_RED = 230.77e9  # Pa, the thesis' reduced modulus (csv header)
ETA0 = 0.00795  # Pa.s, lubricant 2 at 313 K
# lubricant 2 of the thesis: modified WLF (mu_G, T_g0, A1, A2, b1, b2, C1, C2) and Murnaghan (T_R, a_v, beta_K,
# K_MM, K'), as bearing_fmu/params/lubricants/thesis_turbine_oil.toml [lubricant_2_wlf] and [density]
WLF_2 = (1e12, 189.95, 188.86, 0.7190e-9, 8.2e-9, -0.5278, 16.09, 17.38)
MURN = (298.0, 7.734e-4, 6.090e-3, 9.234e9, 10.545)
FLUID = en.fluid_array(es.VISC_WLF, es.DENS_MURNAGHAN, ETA0, 0.0, 313.0, WLF_2, MURN)
LEVEL = 3  # the default grid (docs/ehl_solver.md, Grid convergence)


def cases():
    """The csv rows as dicts of floats, numbered 1..55 in file order."""
    with open(DATA) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return [{key: float(v) for key, v in r.items()} | {"n": i + 1} for i, r in enumerate(rows)]


def solve(case, level=LEVEL):
    t = time.perf_counter()
    sol = en.solve_contact(
        case["Rx_mm"] * 1e-3, case["Ry_mm"] * 1e-3, case["w_N"], case["ue_m_s"], E_RED, ETA0, FLUID, finest=level
    )
    return sol, time.perf_counter() - t


def _diff(got_m, want_nm):
    return 100.0 * (got_m * 1e9 - want_nm) / want_nm


def _row(c, sol, dt):
    return (
        f"| {c['n']} | {c['w_N']:.0f} | {c['ue_m_s']:g} | {c['k']:g} | {c['M']:g} | {c['hc_nm']:g} | "
        f"{sol.h_c * 1e9:.1f} | {_diff(sol.h_c, c['hc_nm']):+.1f} | {c['hm_nm']:g} | {sol.h_min * 1e9:.1f} | "
        f"{_diff(sol.h_min, c['hm_nm']):+.1f} | {c['hm_centre_nm']:g} / {c['hm_lateral_nm']:g} | "
        f"{sol.hm_centre * 1e9:.1f} / {sol.hm_lateral * 1e9:.1f} | {'yes' if sol.converged else 'NO'} {sol.cycles} | "
        f"{sol.change:.1e} | {sol.residual:.1e} | {dt:.1f} |"
    )


def _within(c, sol):
    """The validation tolerance of tests/validation/test_ehl_annexe_d.py: 5 % for k >= 1, 10 % for k < 1."""
    tol = 5.0 if c["k"] >= 1.0 else 10.0
    return abs(_diff(sol.h_c, c["hc_nm"])) <= tol and abs(_diff(sol.h_min, c["hm_nm"])) <= tol


def table(chosen, level, out):
    rows, times, loads, n_conv, n_within, record = [], [], [], 0, 0, []
    for c in cases():
        if chosen and c["n"] not in chosen:
            continue
        loads.append(os.getloadavg()[0])
        sol, dt = solve(c, level)
        times.append(dt)
        n_conv += sol.converged
        n_within += _within(c, sol)
        rows.append(_row(c, sol, dt))
        record.append(
            {"n": c["n"], "k": c["k"], "converged": bool(sol.converged), "s": dt, "load": loads[-1]}
            | {"h_c": _diff(sol.h_c, c["hc_nm"]), "h_min": _diff(sol.h_min, c["hm_nm"])}
        )
        print(rows[-1], f"load {loads[-1]:.2f}", flush=True)
    g = en.grid_hierarchy(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, FLUID, level, level)[0]
    head = [
        "# Numerical EHL solver against the thesis' Annexe D",
        "",
        f"`python -m benchmarks.ehl_solver --level {level}`: grid {g.nx} x {g.ny} of level {level} on the box of "
        "each contact (`contact_box`: X in [-3.5, 1.5], |Y| <= 2 in Hertz units for the light loads, shrunk down "
        "to 0.6 of it where the inlet the film needs is short); FAS V-cycles with a semismooth Newton solve on "
        "level 0 (docs/ehl_solver.md). Differences are (solver - thesis) / thesis; last change is the spread of "
        "h_c, h_min over the last 4 cycles; residual the rms complementarity residual / rms Couette term. "
        "Times: wall clock per solve on one core (BLAS on one thread) of the shared 2-core machine, kernels "
        "compiled and cached.",
        "",
        f"{len(times)} cases: {n_conv} converged, {n_within} with h_c and h_min within the validation tolerance "
        f"(5 % for k >= 1, 10 % for k < 1). Median {statistics.median(times):.1f} s, worst {max(times):.1f} s; "
        f"1-minute load average {min(loads):.2f}-{max(loads):.2f} over the run (2 cores).",
        "",
        "| case | w N | u_e m/s | k | M | h_c thesis nm | h_c nm | diff % | h_min thesis nm | h_min nm | diff % | "
        "hm centre / lateral thesis nm | solver nm | converged, cycles | last change | residual | s |",
        "|" + "---|" * 17,
    ]
    Path(out).write_text("\n".join(head + rows) + "\n")
    Path(out).with_suffix(".json").write_text(json.dumps(record, indent=0) + "\n")


def _table_path(level):
    name = "ehl_solver.md" if level == LEVEL else f"ehl_solver_level{level}.md"
    return ROOT / "docs" / "reports" / name


def pareto(levels, out):
    """Error against the thesis vs run time: the solver on each level (mean |error| over the cases of its
    table run, median time per case) and the three closed-form film formulas (benchmarks.ehl_film_table)."""
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from benchmarks import ehl_film_table as ft

    formula_cases = ft.load_cases()
    wide = np.array([c["k"] >= 1.0 for c in formula_cases])
    errs = ft.errors(formula_cases)
    per_call = ft.times_per_call(n=2000, repeats=31)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, q, label in ((axes[0], 0, "h_c"), (axes[1], 1, "h_min")):
        for group, mask, marker in (("k >= 1", wide, "s"), ("k < 1", ~wide, "o")):
            for name in ft.FORMULAS:
                e = 100 * np.mean(np.abs(errs[name][q][mask]))
                ax.loglog(per_call[name], e, marker, mfc="none", label=f"{name}, {group}")
            pts = []
            for level in levels:
                rec = json.loads(_table_path(level).with_suffix(".json").read_text())
                sel = [r for r in rec if (r["k"] >= 1.0) == (group == "k >= 1")]
                pts.append((statistics.median(r["s"] for r in sel), statistics.mean(abs(r[label]) for r in sel)))
            ax.loglog(*zip(*pts), marker + "-", color="k", label=f"numerical, levels {levels[0]}-{levels[-1]}, {group}")
            for level, (t, e) in zip(levels, pts):
                ax.annotate(f"L{level}", (t, e), fontsize=8)
        ax.set_xlabel("run time per contact (s)")
        ax.set_ylabel(f"mean |{label} - thesis| / thesis (%)")
        ax.set_title(f"{label}: error vs run time, Annexe D")
    axes[1].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"wrote {out}")


def richardson(h):
    """(observed order, estimate) from films h on three grids each twice as fine: order log2 of the ratio of
    successive differences; the estimate extrapolates the finest with that order (2 if it is not between 1
    and 3, i.e. the grids are not yet in the asymptotic range or the differences change sign)."""
    d1, d2 = h[-2] - h[-3], h[-1] - h[-2]
    order = math.log2(d1 / d2) if d1 * d2 > 0.0 else float("nan")
    p = order if 1.0 <= order <= 3.0 else 2.0
    return order, h[-1] + d2 / (2.0**p - 1.0)


def study(chosen, levels, out):
    rows = []
    for c in cases():
        if c["n"] not in chosen:
            continue
        sols = []
        for level in levels:
            load = os.getloadavg()[0]
            sol, dt = solve(c, level)
            sols.append(sol)
            print(
                c["n"], level, f"{sol.h_c * 1e9:.1f} {sol.h_min * 1e9:.1f} {sol.converged} {dt:.1f} s load {load:.2f}"
            )
        cells = []
        for attr, want in (("h_c", c["hc_nm"]), ("h_min", c["hm_nm"])):
            h = [getattr(s, attr) * 1e9 for s in sols]
            order, est = richardson(h)
            default = h[levels.index(LEVEL)] if LEVEL in levels else math.nan
            cells.append(
                f"{' / '.join(f'{v:.1f}' for v in h)} | {order:.2f} | {est:.1f} | {100.0 * (default - est) / est:+.1f} | "
                f"{want:g} | {100.0 * (est - want) / want:+.1f}"
            )
        conv = " ".join("y" if s.converged else "n" for s in sols)
        rows.append(f"| {c['n']} | {c['k']:g} | {c['M']:g} | " + " | ".join(cells) + f" | {conv} |")
    head = [
        "# Grid convergence of the numerical EHL solver (Annexe D cases)",
        "",
        f"`python -m benchmarks.ehl_solver --study {','.join(str(n) for n in sorted(chosen))} --levels "
        f"{','.join(str(v) for v in levels)}`: each case on the grids of levels {levels[0]}-{levels[-1]} of its box "
        "(each level halves the spacing). Order: observed from the three finest; Richardson: the finest "
        f"extrapolated with it (2 where it is outside 1-3); level {LEVEL} error: the default grid against that estimate.",
        "",
        f"| case | k | M | h_c nm per level | order | Richardson nm | level {LEVEL} error % | thesis nm | Richardson vs thesis "
        f"% | h_min nm per level | order | Richardson nm | level {LEVEL} error % | thesis nm | Richardson vs thesis % "
        "| converged |",
        "|" + "---|" * 16,
    ]
    Path(out).write_text("\n".join(head + rows) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--level", type=int, default=LEVEL)
    ap.add_argument("--cases", default="")
    ap.add_argument("--study", default="", help="cases of a grid study (with --levels)")
    ap.add_argument("--levels", default="1,2,3,4")
    ap.add_argument("--pareto", default="", help="levels whose table runs go into docs/reports/ehl_pareto.png")
    ap.add_argument("--out", default="")
    args = ap.parse_args()
    if args.pareto:
        pareto([int(v) for v in args.pareto.split(",")], args.out or str(ROOT / "docs" / "reports" / "ehl_pareto.png"))
        return
    if args.study:
        chosen = {int(c) for c in args.study.split(",")}
        levels = [int(v) for v in args.levels.split(",")]
        study(chosen, levels, args.out or str(ROOT / "docs" / "reports" / "ehl_grid_study.md"))
        return
    chosen = {int(c) for c in args.cases.split(",") if c}
    table(chosen, args.level, args.out or str(_table_path(args.level)))


if __name__ == "__main__":
    main()
