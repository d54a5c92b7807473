"""The numerical EHL solver (models.ehl_numerical.solve_contact) at vanishing entrainment speed against the dry
Hertz contact: the pressure must tend to p_H sqrt(1 - (x/b)^2 - (y/a)^2).

Reference: Hertz's solution for the elliptic contact as Johnson writes it (Contact Mechanics, 1985, section
4.2, with the elliptic pressure of section 3.4, eqs. 3.63-3.64; E* = E'/2, the gap A x^2 + B y^2,
A = 1/(2 Rx), B = 1/(2 Ry); Hamrock, Fundamentals of Fluid Film Lubrication, ch. 4, in E'): the eccentricity
e from B/A = ((a/b)^2 E(e) - K(e)) / (K(e) - E(e)) for the major semi-axis along the smaller curvature, the
major semi-axis from the load P = (2/3) pi p0 a b and A = p0 b (K - E) / (E* e^2 a^2), and for the circle
a = (3 P Rx / (4 E*))^(1/3). Computed here with scipy's complete elliptic integrals and a root finder, not
through kernels.hertz (Hamrock and Dowson's form of the same theory, which the solver uses): the two routes
agree to 1e-9 (test_johnson_reference_agrees_with_the_hertz_kernel).

Cases: Annexe D cases 6 (k = 1, Rx = Ry = 80 mm) and 1 (k = 5.03, Rx = 28.92 mm, Ry = 345 mm, entrainment
along x), 120 N, lubricant 2 at 313 K (the solver's validation fluid), default grid (level 3), at u_e = 2,
0.2, 0.02 and 0.005 m/s (U = 8.6e-13 to 2.2e-15 for case 6, 2.4e-12 to 6.0e-15 for case 1).

What holds, and why not everywhere (docs/ehl_solver.md, Dry limit):
- The largest |p - p_Hertz| over all nodes falls at every step of speed (asserted: strictly decreasing).
  It sits at the inlet edge, at the first node outside the Hertz ellipse: the inlet pressure builds over a
  layer of width ~ H_c^(2/3) where the gap of the dry contact is of the size of the film, and the EHL
  pressure departs there from the Hertz one by ~ H_c^(1/3) (measured exponent 0.32-0.36). At 0.005 m/s it is
  still 8-9 % of p_H; 1 % would need H_c ~ 5e-6 (Hertz units), an inlet layer 1/30 of the grid spacing
  (0.0094 b), which no grid of the solver resolves and where its discrete problem closes the gap. So the 1 %
  of the acceptance is asserted on what the grid resolves, at the smallest speed:
- peak pressure within 1 % of p_H (measured -0.07 %, +0.04 %);
- load (dX dY sum p) within 1 % of the applied load (measured ~1e-6: the solver's load balance, checked
  here against the independent a, b, p_H);
- the semi-axes of the pressure field (least-squares fit of p^2 = p0^2 (1 - x^2 / b^2) over |x| < 0.8 b on
  the centre line, and likewise in y) within 1 % of Hertz's (measured <= 0.14 %);
- |p - p_Hertz| within 1 % of p_H on every node of the central region r = sqrt((x/b)^2 + (y/a)^2) <= 0.8
  (measured 0.41 % and 0.70 %); toward the edge the inlet and exit layers reach in (r <= 0.9: 0.98 %
  and 0.70 %; r <= 0.95: 2.3 % and 1.3 %).
The tolerance is the acceptance's 1 %, compared node by node on the grid (dX = dY = 0.0094 b at the smallest
speed). The elastic discretisation alone is far inside it (the discrete deflection of the exact Hertz pressure
is flat to 0.02 % of the approach, tests/unit/test_ehl_solver.py); the grid shows through the film instead:
each row of nodes takes its film from its own discrete inlet, where the nodes step along the Hertz edge, and
with the inlet layer about two nodes wide at 0.005 m/s the film differs from row to row by up to ~10 % of
H_c, which the pressure follows in streaks along x (k = 1: -0.7 % along y = 0.56 a, the largest central
deviation; at 0.02 m/s 0.40 %, at 2 mm/s, where the solver stops after 80 cycles unconverged, 1.25 %). The
smallest speed is therefore the one where the inlet layer is thin and still about a node or two wide.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearing_fmu.kernels.hertz import hertz_coefficients_exact, hertz_contact
from bearing_fmu.models import ehl_numerical as en
from tests.cases.ehl_annexe_d import E_RED, ETA0, FLUID

SPEEDS = (2.0, 0.2, 0.02, 0.005)  # m/s, entrainment speed, decreasing
LOAD_N = 120.0
GEOMETRIES = {"k=1": (0.08, 0.08), "k=5": (0.02892, 0.345)}  # Rx, Ry (m): Annexe D cases 6 and 1
CENTRAL = 0.8  # r = sqrt((x/b)^2 + (y/a)^2) of the central region


def johnson_hertz(Rx, Ry, load, E_red):
    """(b, a, p0): Hertz semi-axes along x and y (m) and maximum pressure (Pa) of the gap x^2/(2 Rx) +
    y^2/(2 Ry) under the load (N), E_red = E' = 2 E* (Johnson 1985, section 4.2 and eqs. 3.63-3.64)."""
    E_star = 0.5 * E_red
    A, B = 0.5 / Rx, 0.5 / Ry
    if A == B:
        a = (3.0 * load * Rx / (4.0 * E_star)) ** (1.0 / 3.0)
        return a, a, 3.0 * load / (2.0 * math.pi * a * a)
    small, large = min(A, B), max(A, B)  # the major semi-axis lies along the smaller curvature

    def ratio(m):  # large / small curvature of an ellipse of eccentricity e, m = e^2
        return (ellipe(m) / (1.0 - m) - ellipk(m)) / (ellipk(m) - ellipe(m)) - large / small

    m = brentq(ratio, 1e-12, 1.0 - 1e-15, xtol=1e-16, rtol=1e-15)
    major = (3.0 * load * (ellipk(m) - ellipe(m)) / (2.0 * math.pi * small * E_star * m)) ** (1.0 / 3.0)
    minor = major * math.sqrt(1.0 - m)
    p0 = 3.0 * load / (2.0 * math.pi * major * minor)
    return (minor, major, p0) if A > B else (major, minor, p0)


@pytest.mark.parametrize("Rx, Ry", [(0.08, 0.08), (0.02892, 0.345), (0.345, 0.02892), (0.0394, 0.2)])
def test_johnson_reference_agrees_with_the_hertz_kernel(Rx, Ry):
    """Johnson's form (scipy) and Hamrock-Dowson's (kernels.hertz) of Hertz's solution: two routes to the same
    exact values, both double precision with root finders to ~1e-15; tolerance 1e-9 relative."""
    b, a, p0 = johnson_hertz(Rx, Ry, LOAD_N, E_RED)
    k, ell_E, ell_K = hertz_coefficients_exact(Rx, Ry)
    a_k, b_k, _, p_k = hertz_contact(LOAD_N, Rx, Ry, E_RED, k, ell_E, ell_K)
    for got, want in ((b, b_k), (a, a_k), (p0, p_k)):
        assert abs(got - want) <= 1e-9 * want


def _deviations(solution, b, a, p0):
    """Measures of one solution against the Hertz field (b, a, p0): dict of relative values."""
    g = solution.grid
    x = g.X[:, None] * g.b  # node coordinates (m)
    y = g.Y[None, :] * g.a
    r2 = (x / b) ** 2 + (y / a) ** 2
    p = solution.P * g.p_h
    dev = np.abs(p - p0 * np.sqrt(np.maximum(1.0 - r2, 0.0))) / p0
    ic = int(np.argmin(np.abs(g.X)))
    jc = int(np.argmin(np.abs(g.Y)))
    fits = []
    for coord, line, semi in ((x[:, 0], p[:, jc], b), (y[0, :], p[ic, :], a)):
        sel = np.abs(coord) < CENTRAL * semi
        slope, intercept = np.polyfit(coord[sel] ** 2, line[sel] ** 2, 1)
        fits.append(math.sqrt(-intercept / slope) / semi - 1.0)
    i, j = np.unravel_index(np.argmax(dev), dev.shape)
    return {
        "max": dev.max(),
        "at": (round(float(x[i, 0] / b), 3), round(float(y[0, j] / a), 3)),
        "central": dev[r2 <= CENTRAL**2].max(),
        "peak": p.max() / p0 - 1.0,
        "load": p.sum() * g.dX * g.b * g.dY * g.a / LOAD_N - 1.0,
        "b": fits[0],
        "a": fits[1],
        "h_c": solution.h_c / g.scale_h,
        "dX_over_b": g.dX * g.b / b,
    }


@pytest.mark.parametrize("name", sorted(GEOMETRIES))
def test_pressure_tends_to_hertz_as_the_speed_vanishes(name):
    Rx, Ry = GEOMETRIES[name]
    b, a, p0 = johnson_hertz(Rx, Ry, LOAD_N, E_RED)
    rows = []
    for u_e in SPEEDS:
        solution = en.solve_contact(Rx, Ry, LOAD_N, u_e, E_RED, ETA0, FLUID)
        assert solution.converged, f"{name}, u_e {u_e}: not converged after {solution.cycles} cycles"
        rows.append(_deviations(solution, b, a, p0))
    table = "\n".join(f"u_e {u} m/s: {r}" for u, r in zip(SPEEDS, rows))
    print(f"{name}\n{table}")  # the measured values, with pytest -s
    largest = [r["max"] for r in rows]
    assert all(later < earlier for earlier, later in zip(largest, largest[1:])), table
    last = rows[-1]
    for key in ("peak", "load", "b", "a", "central"):
        assert abs(last[key]) <= 0.01, f"{key}\n{table}"
