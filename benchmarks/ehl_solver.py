"""Numerical EHL solver against the thesis' Annexe D (55 elliptical cases, lubricant 2 at 313 K, modified WLF
viscosity and Murnaghan density) and its time per case; writes docs/reports/ehl_solver.md.

    python -m benchmarks.ehl_solver [--level 2] [--cases 1,6,...] [--out docs/reports/ehl_solver.md]

Each row: the thesis' h_c, h_min, hm_centre, hm_lateral, the solver's, their relative differences, the
convergence record and the wall time of the solve (one core, compiled kernels cached).
"""

import argparse
import csv
import statistics
import time
from pathlib import Path

from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.models import ehl_numerical as en

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "validation" / "data" / "thesis_annexe_d_ehl.csv"
E_RED = 230.77e9  # Pa, the thesis' reduced modulus (csv header)
ETA0 = 0.00795  # Pa.s, lubricant 2 at 313 K
# lubricant 2 of the thesis: modified WLF (mu_G, T_g0, A1, A2, b1, b2, C1, C2) and Murnaghan (T_R, a_v, beta_K,
# K_MM, K'), as bearing_fmu/params/lubricants/thesis_turbine_oil.toml [lubricant_2_wlf] and [density]
WLF_2 = (1e12, 189.95, 188.86, 0.7190e-9, 8.2e-9, -0.5278, 16.09, 17.38)
MURN = (298.0, 7.734e-4, 6.090e-3, 9.234e9, 10.545)
FLUID = en.fluid_array(es.VISC_WLF, es.DENS_MURNAGHAN, ETA0, 0.0, 313.0, WLF_2, MURN)


def cases():
    """The csv rows as dicts of floats, numbered 1..55 in file order."""
    with open(DATA) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return [{key: float(v) for key, v in r.items()} | {"n": i + 1} for i, r in enumerate(rows)]


def solve(case, level=2):
    t = time.perf_counter()
    sol = en.solve_contact(
        case["Rx_mm"] * 1e-3, case["Ry_mm"] * 1e-3, case["w_N"], case["ue_m_s"], E_RED, ETA0, FLUID, finest=level
    )
    return sol, time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--level", type=int, default=2)
    ap.add_argument("--cases", default="")
    ap.add_argument("--out", default=str(ROOT / "docs" / "reports" / "ehl_solver.md"))
    args = ap.parse_args()
    chosen = {int(c) for c in args.cases.split(",") if c}
    rows, times = [], []
    for c in cases():
        if chosen and c["n"] not in chosen:
            continue
        sol, dt = solve(c, args.level)
        times.append(dt)
        d = [
            (sol.h_c * 1e9 - c["hc_nm"]) / c["hc_nm"],
            (sol.h_min * 1e9 - c["hm_nm"]) / c["hm_nm"],
        ]
        line = (
            f"| {c['n']} | {c['w_N']:.0f} | {c['ue_m_s']:g} | {c['k']:g} | {c['hc_nm']:g} | {sol.h_c * 1e9:.1f} | "
            f"{100 * d[0]:+.1f} | {c['hm_nm']:g} | {sol.h_min * 1e9:.1f} | {100 * d[1]:+.1f} | "
            f"{c['hm_centre_nm']:g} / {c['hm_lateral_nm']:g} | {sol.hm_centre * 1e9:.1f} / {sol.hm_lateral * 1e9:.1f} | "
            f"{'yes' if sol.converged else 'NO'} {sol.cycles} | {sol.change:.1e} | {dt:.1f} |"
        )
        print(line, flush=True)
        rows.append(line)
    nx = 40 * 2**args.level + 1
    ny = 32 * 2**args.level + 1
    head = [
        "# Numerical EHL solver against the thesis' Annexe D",
        "",
        f"`python -m benchmarks.ehl_solver --level {args.level}`: grid {nx} x {ny} on X in [-3.5, 1.5], |Y| <= 2 "
        "(Hertz units), FAS V-cycles from the grid of level 1 (docs/ehl_solver.md). Differences are "
        "(solver - thesis) / thesis. Times: wall clock per solve on one core of the 2-core machine, kernels "
        f"compiled and cached. Median {statistics.median(times):.1f} s, worst {max(times):.1f} s over {len(times)} cases.",
        "",
        "| case | w N | u_e m/s | k | h_c thesis nm | h_c nm | diff % | h_min thesis nm | h_min nm | diff % | "
        "hm centre / lateral thesis nm | solver nm | converged, cycles | last change | s |",
        "|" + "---|" * 15,
    ]
    Path(args.out).write_text("\n".join(head + rows) + "\n")


if __name__ == "__main__":
    main()
