"""The numerical EHL solver (models.ehl_numerical.solve_contact) against the full numerical solutions of
Wheeler (2016), Annexe D (tests/validation/data/thesis_annexe_d_ehl.csv: elliptical contacts, lubricant 2 at 313 K,
modified WLF viscosity, Murnaghan density, E' = 230.77 GPa): the subset the default test suite runs.

Tolerances (docs/ehl_solver.md, Validation): h_c and h_min within 5 % of the thesis for k >= 1 and 10 % for k < 1,
on the solver's default grid (level 3), whose discretisation error is within 2 % at these light loads
(docs/reports/ehl_grid_study.md). The thesis prints the films to the nanometre: its uncertainty is half a
nanometre.
"""

import csv

from benchmarks.ehl_solver import DATA, cases, solve

from .comparison import ReferenceCase, printed_comparison

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
