"""The numerical EHL solver converges everywhere in the operating box it is documented for, and its convergence does
not hinge on a digit of the input (models.ehl_numerical.solve_contact, docs/ehl_solver.md, Operating box).

The box is the film table's (models.film_table, docs/film_correction.md): contact loads of Hertz pressure P_H_RANGE
(1-4.2 GPa), entrainment speeds U_E_RANGE (0.5-20 m/s), oil temperatures of the lubricant's range, within Moes
M <= M_CAP (30000) and L <= L_CAP (20), where the table's nodes are solved and the solver is said to converge. The
coarse sweep takes each range's ends and geometric middle (1, 2.05, 4.2 GPa; 0.5, 3.16, 20 m/s) at 313.15 and
353.15 K (iso_vg68_mineral: at its range's ends, 273 and 393 K, most of these points fall outside M <= 30000 or
L <= 20) on both races of the 6208 (k = 9.37, 7.25) and of the B7214C (k = 9.03, 5.86), each contact on the grid
level its film needs (film_level, what `spindle film` and the table use): 44 of the 72 points are inside the box,
19 of them on level 4. By point relaxation the 6208's outer contact at 353.15 K, 20 m/s, 1 GPa (M = 277; L = 11.7 with
the fluid's alpha* at p_h, below the former lines threshold of 12) ran 120 cycles with h_c and the load error
alternating from cycle to cycle, where its neighbours converged in 6-28 cycles; by lines (LINES_MIN_L = 11) it
converges in 11.

The second test is the 6208 at 3 kN radial (`spindle film 6208 --lubricant guessasma_oil --Fx 3000`, its documented
operating point at 1700 rad/s, Moes L = 32 at k = 9.37, lines): with the lines' Gauss-Seidel factor 0.4, 2 of 9
speeds from 1650 to 1750 rad/s did not converge (the inner contact at 1725 rad/s, the outer at 1737.5 rad/s, bursts
of h_min for 120 cycles) where their neighbours converged in 18-94 cycles; with 0.3 (LINES_OMEGA_GS) they converge.
Asserted at each point: converged by the solver's criterion, with a positive film below h_c. Minutes of solves,
with the solver's long studies (`make test-ehl-full`).
"""

import math

import pytest

from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import ehl, jones_harris
from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.kernels.hertz import hertz_contact
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models import ehl_numerical as en
from bearing_fmu.models import film_table as ft
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import load_bearing, load_lubricant

TEMPERATURES = (313.15, 353.15)  # K


def _spans(low, high):
    """The ends and the geometric middle of a range."""
    return (low, math.sqrt(low * high), high)


def _box_contacts():
    """(name, solve_contact arguments) of every point of the coarse sweep inside the box."""
    lubricant = load_lubricant("iso_vg68_mineral")
    contacts = []
    for bearing in ("6208", "B7214C"):
        races, E_red = ft.race_geometry(load_bearing(bearing))
        for race, (Rx, Ry, c) in zip(("inner", "outer"), races, strict=True):
            p_1N = hertz_contact(1.0, Rx, Ry, E_red, *c)[3]
            for T in TEMPERATURES:
                eta, xi, _ = lubricant_state(T, lubricant.array)
                fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
                for u in _spans(*ft.U_E_RANGE):
                    for p_h in _spans(*ft.P_H_RANGE):
                        Q = (p_h / p_1N) ** 3
                        U, G, W = ehl.dimensionless_groups(eta, xi, E_red, u, Q, Rx)
                        if W * (2.0 * U) ** -0.75 <= ft.M_CAP and G * (2.0 * U) ** 0.25 <= ft.L_CAP:
                            name = f"{bearing}-{race}-{T:g}K-{u:.3g}mps-{p_h / 1e9:.3g}GPa"
                            contacts.append((name, (Rx, Ry, Q, u, E_red, eta, fluid)))
    return contacts


BOX = _box_contacts()


def _assert_converged(solution):
    assert solution.converged, (solution.reason, solution.cycles, solution.h_c, solution.h_min)
    assert 0.0 < solution.h_min < solution.h_c, (solution.h_min, solution.h_c)


def test_the_sweep_covers_the_box():
    """44 of the 72 points are inside the box (the docstring's count), on levels 3 and 4."""
    assert len(BOX) == 44
    assert {en.resolving_level(*args) for _, args in BOX} == {3, 4}


@pytest.mark.parametrize("contact", [args for _, args in BOX], ids=[name for name, _ in BOX])
def test_every_contact_of_the_operating_box_converges_on_its_level(contact):
    _assert_converged(en.solve_contact(*contact, finest=None))


def _6208_contacts(omega):
    """The most loaded inner and outer contacts of the 6208 at 3 kN radial along x and omega (rad/s), guessasma_oil
    at 313.15 K, as `spindle film` takes them (models.film_check)."""
    model = QuasiStaticModel("6208", "guessasma_oil")
    model.evaluate(omega=omega, T_oil=313.15, F_x=3000.0)
    eta, xi, _ = lubricant_state(313.15, model.lubricant.array)
    fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
    contacts = []
    for race in (0, 1):
        loads = model.balls[jones_harris.BQ_Q_I + race]
        ball = int(loads.argmax())
        Rx, Ry = model.cp[ck.CP_RX_I + 5 * race], model.cp[ck.CP_RY_I + 5 * race]
        u = float(model.balls[jones_harris.BQ_U_I + race, ball])
        contacts.append((Rx, Ry, float(loads[ball]), u, model.cp[ck.CP_E_RED], eta, fluid))
    return contacts


@pytest.mark.parametrize("omega", [1650.0 + 12.5 * n for n in range(9)] + [1700.02])
def test_the_6208_at_3_kN_converges_at_every_speed_near_1700_rad_s(omega):
    for contact in _6208_contacts(omega):
        _assert_converged(en.solve_contact(*contact, finest=None))
