"""The numerical EHL solver (models.ehl_numerical.solve_contact) against the full numerical solutions of
Wheeler (2016), Annexe D (tests/validation/data/thesis_annexe_d_ehl.csv: elliptical contacts, lubricant 2 at 313 K,
modified WLF viscosity, Murnaghan density, E' = 230.77 GPa): the subset the default test suite runs.

Tolerances (docs/ehl_solver.md, Validation): h_c and h_min within 5 % of the thesis for k >= 1 and 10 % for k < 1,
on the solver's default grid (level 3), whose discretisation error is within 2 % at these light loads
(docs/reports/ehl_grid_study.md). The thesis prints the films to the nanometre: its uncertainty is half a
nanometre.

The thesis' lubricant 2 and contact data (FLUID, E_RED, ETA0), the csv's rows (cases), one solve on a grid level
(solve) and the Richardson extrapolation of a grid study (richardson) are here too: the EHL validation tests and the
solver's benchmarks (benchmarks.ehl_solver, benchmarks.ehl_fields) share them.
"""

import csv
import math
import time

from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.models import ehl_numerical as en

from .comparison import DATA as SOURCES
from .comparison import ReferenceCase, printed_comparison

DATA = SOURCES / "thesis_annexe_d_ehl.csv"
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


def contact_args(case):
    """solve_contact's arguments (Rx, Ry, load, u_e, E', eta0, fluid; SI) of a case (a row of cases())."""
    return case["Rx_mm"] * 1e-3, case["Ry_mm"] * 1e-3, case["w_N"], case["ue_m_s"], E_RED, ETA0, FLUID


def solve(case, level=LEVEL):
    """(solution, wall time in s) of a case (a row of cases()) on the grid of the level."""
    t = time.perf_counter()
    sol = en.solve_contact(*contact_args(case), finest=level)
    return sol, time.perf_counter() - t


def richardson(h):
    """(observed order, estimate) from films h on three grids each twice as fine: order log2 of the ratio of
    successive differences; the estimate extrapolates the finest with that order (2 if it is not between 1
    and 3, i.e. the grids are not yet in the asymptotic range or the differences change sign)."""
    d1, d2 = h[-2] - h[-3], h[-1] - h[-2]
    order = math.log2(d1 / d2) if d1 * d2 > 0.0 else float("nan")
    p = order if 1.0 <= order <= 3.0 else 2.0
    return order, h[-1] + d2 / (2.0**p - 1.0)


SUBSET = (4, 6)  # w = 120 N, u_e = 2 m/s, k = 1.98 and 1.00
CASES = {c["n"]: c for c in cases()}


def printed_films(n):
    """(h_c, h_min) of case n as the csv prints them (nm)."""
    with open(DATA) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return rows[n - 1]["hc_nm"], rows[n - 1]["hm_nm"]


def case_comparisons(n):
    """(solution, [h_c, h_min comparisons]) of Annexe D case n on the solver's default grid."""
    case = CASES[n]
    solution, _ = solve(case)
    tolerance = 0.05 if case["k"] >= 1.0 else 0.10
    printed_hc, printed_hm = printed_films(n)
    return solution, [
        printed_comparison(f"case {n} (k = {case['k']:g}) h_c (nm)", solution.h_c * 1e9, printed_hc, tolerance),
        printed_comparison(f"case {n} (k = {case['k']:g}) h_min (nm)", solution.h_min * 1e9, printed_hm, tolerance),
    ]


def compare():
    return [c for n in SUBSET for c in case_comparisons(n)[1]]


CASE = ReferenceCase(
    "ehl_solver_annexe_d",
    "numerical EHL solver",
    "central and minimum film of full EHL solutions",
    "Wheeler (2016) thesis, Annexe D (cases 4 and 6)",
    compare,
    lambda: lambda: solve(CASES[SUBSET[-1]]),
)
