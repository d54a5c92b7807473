"""Twin of bearing_fmu.kernels.film_correction: the film formulas times a table of ratios.

Written from the Moes parameters M = W (2U)^(-3/4), L = G (2U)^(1/4) (Venner & Lubrecht 2000): the table's axes
are ln(M L^3) and ln L; the ratio is the bilinear interpolant of the four nodes around the contact, with the
contact's coordinates first clipped to the nodes' span (numpy), the film that of the twin of kernels.ehl.
"""

import math

import numpy as np

from tests.reference import ref_ehl

NM = 9  # nodes along ln(M L^3), as kernels.film_correction.FT_NM (checked by the unit test)
NL = 4
N_FORMULAS = 3


def _race_block(table, race):
    stride = 4 + N_FORMULAS * 2 * NM * NL
    start = 1 + race * stride
    return table[start : start + 4], np.asarray(table[start + 4 : start + stride]).reshape(N_FORMULAS, 2, NM, NL)


def _bilinear(values, x_nodes, y_nodes, x, y):
    x = float(np.clip(x, x_nodes[0], x_nodes[-1]))
    y = float(np.clip(y, y_nodes[0], y_nodes[-1]))
    i = min(int(np.searchsorted(x_nodes, x, side="right")) - 1, len(x_nodes) - 2)
    j = min(int(np.searchsorted(y_nodes, y, side="right")) - 1, len(y_nodes) - 2)
    s = (x - x_nodes[i]) / (x_nodes[i + 1] - x_nodes[i])
    t = (y - y_nodes[j]) / (y_nodes[j + 1] - y_nodes[j])
    corners = values[i : i + 2, j : j + 2]
    weights = np.outer([1.0 - s, s], [1.0 - t, t])
    return float((corners * weights).sum())


def film_ratios(table, race, formula, U, G, W):
    """(central, minimum) ratio numerical / formula at the groups U, G, W."""
    (x0, dx, y0, dy), ratios = _race_block(table, race)
    M = W * (2.0 * U) ** -0.75
    L = G * (2.0 * U) ** 0.25
    x_nodes = x0 + dx * np.arange(NM)
    y_nodes = y0 + dy * np.arange(NL)
    x, y = math.log(M * L**3), math.log(L)
    return tuple(_bilinear(ratios[formula, film], x_nodes, y_nodes, x, y) for film in (0, 1))


def corrected_film_thickness(formula, eta, xi, E_red, u, Q, Rx, Ry, k, table, race):
    """The formula's (h_c, h_min) in m, times the table's ratios when the table is on and the film finite."""
    h_c, h_min = ref_ehl.film_thickness(formula, eta, xi, E_red, u, Q, Rx, Ry, k)
    if table[0] < 0.5 or not 0.0 < h_min < math.inf:
        return h_c, h_min
    r_c, r_m = film_ratios(table, race, formula, *ref_ehl.dimensionless_groups(eta, xi, E_red, u, Q, Rx))
    return h_c * r_c, h_min * r_m


KERNEL_MODULE = "bearing_fmu.kernels.film_correction"
TWINS = {"film_ratios": film_ratios, "corrected_film_thickness": corrected_film_thickness}
