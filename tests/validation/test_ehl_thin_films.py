"""The numerical EHL solver (models.ehl_numerical.solve_contact) on thin films at high Hertz pressure, where a
reference solver (EHL-FBNS under Octave) failed: its film stayed pinned at its 1 nm floor. Lubricant 2 of the
thesis at 313 K (tests.cases.ehl_annexe_d.FLUID), entrainment along x:
- circular: Rx = Ry = 12.7 mm, 2 kN, 2 m/s (p_H = 3.17 GPa, M = 8988, L = 8.5);
- slender: Rx = 80 mm, Ry = 10 mm, 500 N, 1 m/s (k = 0.256, p_H = 1.31 GPa, M = 379, L = 4.5).

The default grid (level 3) must converge on both with a positive film, and its h_c must lie within the
tolerance of the Richardson estimate of the grid study of levels 2, 3, 4 (docs/ehl_solver.md, Thin films):

| contact | h_c levels 2 / 3 / 4 nm | order | Richardson | level 3 | tolerance |
|---|---|---|---|---|---|
| circular | 46.7 / 84.3 / 95.3 | 1.77 | 99.8 | -15.6 % | 18 % |
| slender | 80.9 / 95.1 / 98.8 | 1.91 | 100.2 | -5.1 % | 7 % |

The tolerance is the level-3 discretisation error the study measures (the inlet layer of these films is 2-3
level-3 nodes wide) plus about 2 %: 1e-3 for the iteration (the criterion) and the uncertainty of the estimate (with
order 2 instead of the observed one it moves by 0.9 % and 0.1 %). The circular contact's level 2 is not a
converged solution (its discrete film closes at the side, h_min = -21 nm, and the solver says so); its h_c
still enters the estimate as the discrete solution of that grid. Each solve takes 20-50 s (tests/_markers.py).
"""

import pytest

from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.models import ehl_numerical as en
from tests.cases.ehl_annexe_d import E_RED, ETA0, FLUID

# name: (Rx m, Ry m, load N, u_e m/s, Richardson estimate of h_c nm, tolerance)
CASES = {
    "circular": (12.7e-3, 12.7e-3, 2000.0, 2.0, 99.8, 0.18),
    "slender": (80e-3, 10e-3, 500.0, 1.0, 100.2, 0.07),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_thin_film_converges_on_the_default_grid_with_a_positive_film(name):
    Rx, Ry, load, u_e, h_c_estimate, tolerance = CASES[name]
    sol = en.solve_contact(Rx, Ry, load, u_e, E_RED, ETA0, FLUID)
    assert sol.converged, f"{name}: {sol.reason} (last change {sol.change:.1e} after {sol.cycles} cycles)"
    assert sol.h_min > 0.0, f"{name}: h_min {sol.h_min * 1e9:.1f} nm"
    h_c = sol.h_c * 1e9
    assert abs(h_c - h_c_estimate) <= tolerance * h_c_estimate, f"{name}: h_c {h_c:.1f} nm, estimate {h_c_estimate}"


# name: (the level film_level picks, Richardson estimate of h_c and of h_min from levels 4, 5, 6, nm)
RESOLVED = {"circular": (5, 99.26, 21.10), "slender": (4, 100.17, 8.97)}


@pytest.mark.parametrize("name", sorted(RESOLVED))
def test_a_thin_film_is_solved_on_the_level_its_film_needs(name):
    """The level models.ehl_numerical.film_level picks for these films (the coarsest from 3 whose X spacing is at most
    0.35 times the estimated central film, up to level 5: level 5 for the circular contact, whose film wants level 6,
    and level 4 for the slender one) is within 2 % on h_c and 5 % on h_min of the Richardson estimate of levels 4-6,
    the accuracy the rule is stated with (docs/ehl_solver.md, Thin films: the level a thin film needs). Measured
    (levels 3 / 4 / 5 / 6, nm):

    | contact | h_c | order | estimate | h_min | order | estimate |
    |---|---|---|---|---|---|---|
    | circular | 84.25 / 95.27 / 97.90 / 98.80 | 1.55 | 99.26 | 11.53 / 18.28 / 20.51 / 20.97 | 2.27 | 21.10 |
    | slender | 95.07 / 98.85 / 99.80 / 100.07 | 1.83 | 100.17 | 7.56 / 8.55 / 8.43 / 8.83 | - | 8.97 |

    The picked level is -1.4 / -2.8 % (circular) and -1.3 / -4.7 % (slender) off. The slender's h_min is not monotone
    over the levels (its side lobes' slow oscillation of 0.1-0.2 nm, and level 6 did not meet the criterion in 120
    cycles), so its estimate takes order 2 (tests.cases.ehl_annexe_d.richardson); its level 4 is 3.2 % below level
    6's value. Level 6 took 20 and 32 minutes and is not run here; the picked levels take 1-3 minutes (ehl_full)."""
    Rx, Ry, load, u_e, *_ = CASES[name]
    level, h_c_estimate, h_min_estimate = RESOLVED[name]
    assert en.resolving_level(Rx, Ry, load, u_e, E_RED, ETA0, FLUID) == level
    sol = en.solve_contact(Rx, Ry, load, u_e, E_RED, ETA0, FLUID, finest=None)
    assert sol.converged, f"{name}: {sol.reason} (last change {sol.change:.1e} after {sol.cycles} cycles)"
    h_c, h_min = sol.h_c * 1e9, sol.h_min * 1e9
    assert abs(h_c / h_c_estimate - 1.0) <= 0.02, f"{name}: h_c {h_c:.2f} nm, estimate {h_c_estimate}"
    assert abs(h_min / h_min_estimate - 1.0) <= 0.05, f"{name}: h_min {h_min:.2f} nm, estimate {h_min_estimate}"


def test_a_table_node_whose_level_does_not_converge_is_solved_on_the_next_finer_one():
    """The film table's heaviest node of the B7214C's outer race (k = 5.86, iso_vg68_mineral at 329.6 K, 3.16 m/s,
    16.17 kN: M = 30000, L = 11.2, p_h ~ 4.2 GPa): on level 3 the side film closes (measured h_min 0.3 nm after 120
    cycles, not converged), which as a table ratio would have made the corrected h_min ~0.001 of the formula's
    around that node. models.film_table_build.solve_numerical asked for level 3 then solves it on level 4, where it
    converges (measured 46 cycles, h_c 266.1 nm, h_min 234.0 nm, ~60-80 s). Asserted: level 3 alone does not
    converge, the fallback is level 4 and converges with 0 < h_min < h_c, and its h_min is within the 30 % the
    formulas' h_min ratios span at the table's converged heavy nodes (0.7-1.0) of Hamrock-Dowson's (a positive film
    that is a solution, not a closed gap). Without a level the table solves this node on level 5, the level its film
    needs (models.ehl_numerical.film_level: estimated film 0.011 Hertz units), which is asserted too."""
    from bearing_fmu.kernels import ehl
    from bearing_fmu.kernels.lubricant import lubricant_state
    from bearing_fmu.models import film_table as ft
    from bearing_fmu.models import film_table_build as ftb
    from bearing_fmu.params import load_bearing, load_lubricant

    races, E_red = ft.race_geometry(load_bearing("B7214C"))
    Rx, Ry, c = races[1]
    eta, xi, _ = lubricant_state(329.6, load_lubricant("iso_vg68_mineral").array)
    Q, u = 1.617e4, 3.16
    fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
    assert en.resolving_level(Rx, Ry, Q, u, E_red, eta, fluid) == 5
    solution, level = ftb.solve_numerical(Rx, Ry, Q, u, E_red, eta, xi, level=3)
    assert level == 4, "level 3 converged: the fallback is not exercised by this contact any more"
    assert solution.converged, solution.reason
    assert 0.0 < solution.h_min < solution.h_c
    h_min_formula = ehl.film_thickness(ehl.FILM_HAMROCK_DOWSON, eta, xi, E_red, u, Q, Rx, Ry, c[0])[1]
    assert 0.7 <= solution.h_min / h_min_formula <= 1.3, solution.h_min / h_min_formula
