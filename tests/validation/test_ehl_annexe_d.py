"""The numerical EHL solver (models.ehl_numerical.solve_contact) against the thesis' Annexe D
(tests/validation/data/thesis_annexe_d_ehl.csv: 55 elliptical contacts, lubricant 2 at 313 K, modified WLF
viscosity, Murnaghan density, E' = 230.77 GPa), and its grid convergence.

Tolerances (docs/ehl_solver.md, Validation): h_c and h_min within 5 % of the thesis for k >= 1 and 10 % for
k < 1, on the grid of level 2 (161 x 129 nodes), whose discretisation error is about 1 % (grid study below).
The default suite runs a subset of the light-load series (benchmarks/reference_cases/ehl_annexe_d.py, which the
report's reference table renders as well); the whole table is marked slow (tests/_markers.py).
"""

import math

import pytest

from bearing_fmu.models import ehl_numerical as en
from benchmarks.ehl_solver import E_RED, ETA0, FLUID, cases
from benchmarks.reference_cases import ehl_annexe_d, outside

CASES = {c["n"]: c for c in cases()}


def _check(n):
    solution, comparisons = ehl_annexe_d.case_comparisons(n)
    assert solution.converged, (
        f"case {n}: not converged (last change {solution.change:.1e} after {solution.cycles} cycles)"
    )
    assert not outside(comparisons), outside(comparisons)


@pytest.mark.parametrize("n", ehl_annexe_d.SUBSET)
def test_subset_matches_annexe_d(n):
    _check(n)


@pytest.mark.parametrize("n", sorted(CASES))
def test_every_case_matches_annexe_d(n):
    _check(n)


def test_grid_convergence_is_second_order_and_level_2_within_2_percent():
    """Case 6 (k = 1, 120 N, 2 m/s) on the grids of levels 0, 1, 2 (dX = 0.125, 0.0625, 0.03125): measured
    h_c 268.9, 305.5, 314.9 nm and h_min 156.4, 174.7, 179.6 nm, observed orders 1.95 and 1.91, Richardson
    estimates 318.2 and 181.4 nm, so level 2 is 1.0 % thin on both. The test asserts an order between 1.5 and
    2.5, level 2 within 2 % of the Richardson estimate, and that estimate within 5 % of the thesis."""
    c = CASES[6]
    sols = [
        en.solve_contact(
            c["Rx_mm"] * 1e-3, c["Ry_mm"] * 1e-3, c["w_N"], c["ue_m_s"], E_RED, ETA0, FLUID, finest=l, coarsest=0
        )
        for l in (0, 1, 2)
    ]
    assert all(s.converged for s in sols)
    for attr, want in (("h_c", c["hc_nm"]), ("h_min", c["hm_nm"])):
        h = [getattr(s, attr) * 1e9 for s in sols]
        ratio = (h[1] - h[0]) / (h[2] - h[1])
        order = math.log2(ratio)
        assert 1.5 <= order <= 2.5, f"{attr}: {h}, order {order:.2f}"
        extrapolated = h[2] + (h[2] - h[1]) / (ratio - 1.0)
        assert abs(h[2] - extrapolated) <= 0.02 * extrapolated, f"{attr}: {h}, Richardson {extrapolated:.1f}"
        assert abs(extrapolated - want) <= 0.05 * want, f"{attr}: Richardson {extrapolated:.1f} vs thesis {want}"
