"""Wide bearing contacts of large Moes L for the numerical EHL solver's fine grids (docs/ehl_solver.md, Fine grids):
the inner races of the 6208 (k = 9.37) and the B7214C (k = 9.03) with iso_vg68_mineral at film-table nodes
(models.film_table_build.node_point: the oil temperature and speed of the node's L, the load of its M), as the film
table solves them (Roelands viscosity and Dowson-Higginson density through the oil's eta and alpha).

CONTACTS are the grid study's (benchmarks.ehl_solver --bearing-study, docs/reports/ehl_grid_study.md); the first two
are the contacts whose levels 4 and 5 did not converge with point relaxation (the B7214C's) or with the lines'
coarse-grid bursts (the 6208's), tests/validation/test_ehl_fine_grids.py.
"""

from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models import ehl_numerical as en
from bearing_fmu.models import film_table as ft
from bearing_fmu.models import film_table_build as ftb
from bearing_fmu.params import load_bearing, load_lubricant

LUBRICANT = "iso_vg68_mineral"
# (bearing, Moes M, Moes L) of inner-race contacts; L with the oil's alpha at the node's temperature
CONTACTS = (
    ("B7214C", 13600.0, 18.0),
    ("6208", 2500.0, 23.0),
    ("6208", 18543.0, 20.0),
    ("B7214C", 1000.0, 12.0),
    ("6208", 30000.0, 12.0),
    ("B7214C", 5000.0, 25.0),
)


def inner_contact(bearing, M, L):
    """(solve_contact arguments in SI, (T K, u_e m/s, Q N)) of the bearing's inner race at the film-table node of
    Moes (M, L)."""
    lubricant = load_lubricant(LUBRICANT)
    races, E_red = ft.race_geometry(load_bearing(bearing))
    Rx, Ry, _ = races[0]
    T, u, Q = ftb.node_point(M, L, Rx, E_red, lubricant, ft.temperature_range(lubricant))
    eta, xi, _ = lubricant_state(T, lubricant.array)
    fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
    return (Rx, Ry, Q, u, E_red, eta, fluid), (T, u, Q)
