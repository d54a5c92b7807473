"""The film check (bearing_fmu.models.film_check, `spindle film`) takes the contacts the quasi-static fidelity
reports and solves exactly those numerically."""

import math

from bearing_fmu.models.film_check import film_check, format_film_check
from bearing_fmu.models.quasi_static import QuasiStaticModel
from spindle.cli import main


def test_formulas_are_the_quasi_static_films_of_the_most_loaded_contacts():
    """6208, guessasma_oil, 3 kN radial at 500 rad/s (the seeds' operating point): the Hamrock-Dowson entry of the
    check is the film the quasi-static fidelity outputs for its most loaded inner and outer contacts (h_c_inner,
    h_c_outer, h_min_inner, h_min_outer, Lambda_*), to rounding: the check looks at the user's own contacts. The
    numerical solve runs on the coarsest grid (level 0) to keep the test short; its films are only required
    to exist (finite, positive), their accuracy is the solver's validation (tests/validation/test_ehl_annexe_d.py)."""
    outputs = QuasiStaticModel("6208", "guessasma_oil").evaluate(omega=500.0, F_y=3000.0)
    checks = film_check("6208", "guessasma_oil", 500.0, {"F_y": 3000.0}, finest=0)
    assert [c.race for c in checks] == ["inner", "outer"]
    for c in checks:
        hd = c.formulas["hamrock_dowson"]
        assert math.isclose(hd.h_c, outputs[f"h_c_{c.race}"], rel_tol=1e-12)
        assert math.isclose(hd.h_min, outputs[f"h_min_{c.race}"], rel_tol=1e-12)
        assert math.isclose(hd.lam, outputs[f"Lambda_{c.race}"], rel_tol=1e-12)
        assert 0.0 < c.numerical.h_min <= c.numerical.h_c < math.inf
        assert math.isclose(c.numerical.lam, c.numerical.h_min / c.sigma, rel_tol=1e-12)
    table = format_film_check(checks)
    assert "inner contact" in table and "outer contact" in table and "hamrock_dowson" in table


def test_command_prints_both_contacts(capsys):
    """`spindle film` on the B7214C under 800 N of thrust at 3000 rpm prints the operating point and a row per
    method for both contacts (coarsest grid, for time)."""
    rc = main(["film", "B7214C", "--lubricant", "iso_vg68_mineral", "--speed", "3000", "--Fz", "800", "--level", "0"])
    out = capsys.readouterr().out
    assert rc == 0
    assert "3000 rpm" in out and "F_z" in out
    rows = [line.split()[0] for line in out.splitlines() if line.startswith("  ")]
    assert rows.count("numerical") == 2 and rows.count("chittenden") == 2
