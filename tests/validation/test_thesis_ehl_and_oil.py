"""Dimensionless EHL groups of the thesis' 55 numerical cases and its turbine-oil laws.

Source: Wheeler (2016) thesis, Annexe D (tests/validation/data/thesis_annexe_d_ehl.csv): lubricant 2
at 313 K, mu0 = 0.00795 Pa.s, G = 4671, steel-steel E' = 210 GPa / (1 - 0.3^2) = 230.77 GPa.
U, W built on Rx (thesis list of symbols); Moes M = W (2U)^-3/4, L = G (2U)^1/4 (Moes 1992 as
cited in thesis section 2.2; the printed values fit the 2U convention, docs/thesis_hertz_cases.md).
Tolerance 1 %: the CSV prints U, W to 3 digits (<= 0.5 % rounding) and M, L
to 3 digits.
"""

import csv

import pytest

from bearing_fmu.kernels.ehl import dimensionless_groups
from bearing_fmu.kernels.hertz import reduced_modulus
from tests.cases import lubricant_and_rating

ETA0 = 0.00795  # Pa.s, thesis Table 2.2-1
G_PRINTED = 4671.0  # thesis Annexe D header


def _rows(path):
    with open(path) as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def test_all_55_cases_present(annexe_d_path):
    assert len(_rows(annexe_d_path)) == 55


def test_dimensionless_groups_reproduce_annexe_d(annexe_d_path):
    E_red = reduced_modulus(210e9, 0.3, 210e9, 0.3)
    assert E_red == pytest.approx(230.77e9, rel=1e-5)
    xi = G_PRINTED / E_red
    for row in _rows(annexe_d_path):
        Rx = float(row["Rx_mm"]) * 1e-3
        U, G, W = dimensionless_groups(ETA0, xi, E_red, float(row["ue_m_s"]), float(row["w_N"]), Rx)
        M = W * (2 * U) ** -0.75
        L = G * (2 * U) ** 0.25
        for name, ours in (("U", U), ("W", W), ("M", M), ("L", L)):
            assert ours == pytest.approx(float(row[name]), rel=0.01), (row["case"], row["k"], name)


@pytest.mark.parametrize("index", range(3), ids=["mu0", "alpha_star", "rho0"])
def test_lubricant_2_at_313K(index):
    """Modified WLF law and Murnaghan density with the thesis' lubricant-2 constants (Tables 2.1-3) against the
    values the thesis quotes at 313 K (Table 2.2-1): mu0 0.00795 Pa.s within 0.5 % (measured 0.3 % apart),
    rho0 863 kg/m^3 within 0.2 %, alpha* 20.2 GPa^-1 within 1.5 % (measured 20.4: a known discrepancy, stated,
    not hidden). Tolerances and their grounds: tests/cases/lubricant_and_rating.py."""
    comparison = lubricant_and_rating.lubricant_comparisons()[index]
    assert comparison.within, comparison
