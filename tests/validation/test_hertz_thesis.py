"""Exact Hertz solution against the contact sizes and pressures published in Wheeler (2016).

The case, its source rows, exclusions and tolerance (0.5 % on top of the rounding of the printed value):
tests/cases/hertz_thesis.py, which the report's reference table renders as well.
The Hamrock-Brewe approximation is not validated here: its error against the exact solution is
measured and reported by benchmarks/hertz_approximation.py (docs/reports/hertz_approximation.md).
"""

import pytest

from tests.cases import hertz_thesis, outside
from tests.cases.hertz_thesis import CASES, TORUS


def test_enough_cases():
    """Jerotrib, ellipticity-study and torus-on-plane rows are all present."""
    assert len(CASES) >= 45
    assert sum(TORUS in r["notes"] for r in CASES) == 8


@pytest.mark.parametrize("row", CASES, ids=[r["case_id"] for r in CASES])
def test_exact_hertz_matches_thesis(row):
    comparisons = hertz_thesis.row_comparisons(row)
    assert comparisons  # every usable row is checked on at least one published quantity
    assert not outside(comparisons), outside(comparisons)
