"""The film formulas times a table of numerical / formula film ratios (models.film_table, docs/film_correction.md).

For an isothermal Newtonian point contact of fixed ellipticity the dimensionless film depends on two Moes
parameters only, M = W (2U)^(-3/4) and L = G (2U)^(1/4) (Moes 1992; Venner & Lubrecht 2000, Multilevel Methods
in Lubrication), U, G, W the groups of kernels.ehl. A race of a bearing has one ellipticity, so the ratio of
the numerical film to a formula's is a function of (M, L) per race. The table's axes are ln(M L^3) = ln(W G^3),
which does not depend on the speed (a load axis), and ln L (speed and oil temperature): a bearing's contacts fill
nearly a rectangle there, where in (ln M, ln L) they fill a parallelogram. FT_NM x FT_NL nodes uniform in the two,
interpolated bilinearly; a contact outside the nodes takes the ratio of the nearest edge (clamped).

Layout of the table array (float64[FT_SIZE]):
  FT_ON: 1 = correction on; 0 = off (nothing else is read, the formula's film is returned as it is)
  per race r (0 inner, 1 outer), from FT_RACE + r FT_RACE_STRIDE:
    FT_LN_WG0, FT_D_LN_WG, FT_LN_L0, FT_D_LN_L: first node and node spacing in ln(W G^3) and ln L
    FT_RATIOS: ratio[formula code of kernels.ehl, film (0 central, 1 minimum), i_M, i_L], C order
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .ehl import dimensionless_groups, film_thickness

FT_NM = 9  # nodes in ln(W G^3)
FT_NL = 4  # nodes in ln L
FT_N_FORMULAS = 3  # FILM_HAMROCK_DOWSON, FILM_MASJEDI_KHONSARI, FILM_CHITTENDEN
_FT_RACE_SLOTS = Layout()  # one race's table
FT_LN_WG0 = _FT_RACE_SLOTS.slot()
FT_D_LN_WG = _FT_RACE_SLOTS.slot()
FT_LN_L0 = _FT_RACE_SLOTS.slot()
FT_D_LN_L = _FT_RACE_SLOTS.slot()
FT_RATIOS = _FT_RACE_SLOTS.slot(FT_N_FORMULAS * 2 * FT_NM * FT_NL)
FT_RACE_STRIDE = _FT_RACE_SLOTS.size
_FT_SLOTS = Layout()
FT_ON = _FT_SLOTS.slot()
FT_RACE = _FT_SLOTS.slot(2 * FT_RACE_STRIDE)  # the races' tables, inner then outer
FT_SIZE = _FT_SLOTS.size


@kernel
def _cell(x, x0, dx, n):
    """(cell index, fraction in the cell) of x on the n nodes x0 + i dx, clamped to the first and last node."""
    t = (x - x0) / dx
    if t <= 0.0:
        return 0, 0.0
    if t >= n - 1:
        return n - 2, 1.0
    i = int(t)
    return i, t - i


@kernel
def film_ratios(table, race, formula, U, G, W):
    """(central, minimum) ratio numerical / formula (-) of race 0 (inner) or 1 (outer) at the groups U, G, W (-):
    bilinear in (ln(W G^3), ln L) between the table's nodes, the edge's value outside them."""
    base = FT_RACE + race * FT_RACE_STRIDE
    ln_g = math.log(G)
    i, s = _cell(math.log(W) + 3.0 * ln_g, table[base + FT_LN_WG0], table[base + FT_D_LN_WG], FT_NM)
    j, t = _cell(ln_g + 0.25 * math.log(2.0 * U), table[base + FT_LN_L0], table[base + FT_D_LN_L], FT_NL)
    ratios = base + FT_RATIOS + formula * 2 * FT_NM * FT_NL
    out_c = 0.0
    out_m = 0.0
    for film in range(2):
        at = ratios + film * FT_NM * FT_NL + i * FT_NL + j
        low = (1.0 - t) * table[at] + t * table[at + 1]
        high = (1.0 - t) * table[at + FT_NL] + t * table[at + FT_NL + 1]
        r = (1.0 - s) * low + s * high
        if film == 0:
            out_c = r
        else:
            out_m = r
    return out_c, out_m


@kernel
def corrected_film_thickness(formula, eta, xi, E_red, u, Q, Rx, Ry, k, table, race):
    """kernels.ehl.film_thickness (h_c, h_min in m) times the table's ratios when table[FT_ON] is set; a contact
    without a finite positive film (at rest, open) keeps the formula's (0, 0) or (inf, inf)."""
    h_c, h_min = film_thickness(formula, eta, xi, E_red, u, Q, Rx, Ry, k)
    if table[FT_ON] < 0.5 or not 0.0 < h_min < math.inf:
        return h_c, h_min
    U, G, W = dimensionless_groups(eta, xi, E_red, u, Q, Rx)
    r_c, r_m = film_ratios(table, race, formula, U, G, W)
    return h_c * r_c, h_min * r_m
