"""kernels.ehl_solver and the discrete contact of models.ehl_numerical against tests/reference/ref_ehl_solver.py,
and the elastic part against the Hertz solution.

Tolerances:
- fluid ratios, film: closed forms, RTOL = 1e-12 (measured <= 1.4e-15);
- rectangle influences: the kernel's antiderivative u ln(v + r) + v ln(u + r) against Johnson's eq. 3.25
  (four logarithms of quotients, which lose digits where a quotient is close to 1): RTOL = 1e-12, measured
  4.7e-13; against a 400 x 400 midpoint quadrature of 1/r over the cell from two cells away (the integrand is
  smooth there): the midpoint rule's error (h^2 / 24) |f''| / f is about 1e-7 (measured <= 2.9e-7),
  tolerance 1e-6;
- FFT deflection against direct summation over every cell: both in double precision, relative to the
  largest deflection 1e-11 (measured <= 1.1e-15);
- Reynolds residual: the twin's whole-array fluxes sum in another order; relative to the largest flux term
  of the field 1e-11 (measured <= 9.3e-15).
- Hertz: the discrete deflection of the Hertz pressure plus the gap's geometry must be flat over the
  contact and equal the Hertz approach delta (kernels.hertz, Johnson 1985 eq. 3.65 family): a second-order
  discretisation of the exact integral, measured 0.020 % (k = 1) and 0.023 % (k = 0.2, 5) of delta on a
  129 x 129 grid of the box [-1.5, 1.5]^2 over r^2 < 0.95; tolerance 0.1 % of delta.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.kernels import lubricant as lk
from bearing_fmu.models import ehl_numerical as en
from tests.reference import ref_ehl_solver as rs
from tests.unit._compare import assert_close

RTOL = 1e-12
E_RED = 210e9 / (1.0 - 0.3**2)
# lubricant 2 of the Wheeler (2016) thesis, Tables 2.1-3 (WLF, Murnaghan) at 313 K
WLF_2 = (1e12, 189.95, 188.86, 0.7190e-9, 8.2e-9, -0.5278, 16.09, 17.38)
MURN = (298.0, 7.734e-4, 6.090e-3, 9.234e9, 10.545)
FLUIDS = {
    "barus_incompressible": en.fluid_array(es.VISC_BARUS, es.DENS_INCOMPRESSIBLE, 0.00795, 20.2e-9),
    "roelands_dowson_higginson": en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, 0.00795, 20.2e-9),
    "wlf_murnaghan": en.fluid_array(es.VISC_WLF, es.DENS_MURNAGHAN, 0.00795, 0.0, 313.0, WLF_2, MURN),
}


@pytest.mark.parametrize("name", sorted(FLUIDS))
def test_fluid_ratios_match_twin(name):
    fluid = FLUIDS[name]
    for p in np.concatenate([[0.0], np.geomspace(1e5, 4e9, 60)]):
        assert_close(es.viscosity_ratio(p, fluid), rs.viscosity_ratio(p, fluid), RTOL, f"{name} eta p={p}")
        assert_close(es.density_ratio(p, fluid), rs.density_ratio(p, fluid), RTOL, f"{name} rho p={p}")
    Phi = np.linspace(-0.5, 3.0, 48).reshape(6, 8)
    got = (np.empty_like(Phi), np.empty_like(Phi))
    want = (np.empty_like(Phi), np.empty_like(Phi))
    es.fluid_fields(Phi, 1.5e9, fluid, *got)
    rs.fluid_fields(Phi, 1.5e9, fluid, *want)
    assert_close(got[0], want[0], RTOL, "rho_r field")
    assert_close(got[1], want[1], RTOL, "eta_r field")


def test_wlf_and_murnaghan_ratios_agree_with_the_lubricant_kernels():
    """The solver's ratios are the lubricant module's laws divided by their value at p = 0 (up to the cap)."""
    fluid = FLUIDS["wlf_murnaghan"]
    for p in (1e7, 3e8, 1e9, 2e9):
        mu = [lk.wlf_viscosity(q, 313.0, *WLF_2) for q in (p, 0.0)]
        assert_close(es.viscosity_ratio(p, fluid), min(mu[0] / mu[1], es.ETA_RATIO_MAX), 1e-12, f"WLF p={p}")
        rho = [lk.murnaghan_density(q, 313.0, 872.0, *MURN) for q in (p, 0.0)]
        assert_close(es.density_ratio(p, fluid), rho[0] / rho[1], 1e-12, f"Murnaghan p={p}")
    # past the glass singularity of lubricant 2 at 313 K (~3.1 GPa) the ratio is the cap, not inf or NaN
    assert es.viscosity_ratio(3.5e9, fluid) == es.ETA_RATIO_MAX


def test_rectangle_influence_matches_johnson_and_quadrature():
    dx, dy = 2e-6, 7e-6
    got = es.rectangle_influence(9, 7, dx, dy)
    assert_close(got, rs.rectangle_influence(9, 7, dx, dy), RTOL, "Johnson 3.25")
    n = 400
    xs = (np.arange(n) + 0.5) / n * dx - 0.5 * dx
    ys = (np.arange(n) + 0.5) / n * dy - 0.5 * dy
    for m, q in ((2, 0), (0, 2), (3, 4), (8, 6)):
        r = np.hypot(m * dx - xs[:, None], q * dy - ys[None, :])
        quad = np.sum(1.0 / r) * (dx / n) * (dy / n)
        assert_close(got[m, q], quad, 1e-6, f"quadrature ({m}, {q})")


def _grid(Rx, Ry, nx=41, ny=33, **kw):
    return en.ContactGrid(Rx, Ry, 800.0, 2.0, E_RED, 0.00795, FLUIDS["wlf_murnaghan"], en.Domain(nx=nx, ny=ny, **kw))


@pytest.mark.parametrize("Rx, Ry", [(0.08, 0.08), (0.02892, 0.345), (0.345, 0.02892)])
def test_fft_deflection_equals_direct_summation(Rx, Ry):
    g = _grid(Rx, Ry)
    rng = np.random.default_rng(3)
    P = g.hertz_pressure() * (1.0 + 0.3 * rng.random((g.nx, g.ny)))
    got = g.deflection(P)
    want = rs.deflection_direct(P, g.kern, g.c_w)
    assert np.max(np.abs(got - want)) <= 1e-11 * np.max(np.abs(want))


@pytest.mark.parametrize("Rx, Ry", [(0.08, 0.08), (0.02892, 0.345), (0.345, 0.02892)])
def test_hertz_pressure_gives_the_hertz_approach(Rx, Ry):
    """W + X^2/2 + curv_y Y^2/2 of the Hertz pressure is -delta Rx / b^2 over the whole contact."""
    g = _grid(Rx, Ry, nx=129, ny=129, x_in=-1.5, x_out=1.5, y_half=1.5)
    Xg, Yg = np.meshgrid(g.X, g.Y, indexing="ij")
    gap = g.deflection(g.hertz_pressure()) + 0.5 * Xg**2 + 0.5 * g.curv_y * Yg**2
    inside = Xg**2 + Yg**2 < 0.95
    delta = g.delta / g.scale_h
    assert np.max(np.abs(gap[inside] - delta)) <= 0.001 * delta


def test_film_matches_twin():
    g = _grid(0.0394, 0.2)
    W = g.deflection(g.hertz_pressure())
    got, want = np.empty_like(W), np.empty_like(W)
    es.film(-0.3, g.X, g.Y, g.curv_y, W, got)
    rs.film(-0.3, g.X, g.Y, g.curv_y, W, want)
    assert_close(got, want, RTOL, "film")


@pytest.mark.parametrize("Rx, Ry", [(0.08, 0.08), (0.02892, 0.345), (0.345, 0.02892)])
def test_reynolds_residual_matches_twin(Rx, Ry):
    """A state with a pressurised contact, a cavitated outlet (Phi < 0) and the thesis' WLF/Murnaghan oil."""
    g = _grid(Rx, Ry)
    Xg, Yg = np.meshgrid(g.X, g.Y, indexing="ij")
    Phi = g.hertz_pressure() * 1.05 + 0.02 * np.exp(-((Xg + 1.3) ** 2) - Yg**2)
    Phi[(Xg > 0.9) & (np.abs(Yg) < 1.2)] = -0.3 * np.sin(3.0 * Xg[(Xg > 0.9) & (np.abs(Yg) < 1.2)]) ** 2
    Phi[0, :] = Phi[-1, :] = Phi[:, 0] = Phi[:, -1] = 0.0
    H0 = -g.delta / g.scale_h + 0.05
    R, load_error, H, rho_r, eta_r = g.residual(Phi, H0)
    assert np.all(H[1:-1, 1:-1] > 0.0)
    got, want = np.empty_like(R), np.empty_like(R)
    es.reynolds_residual(Phi, H, rho_r, eta_r, g.lam, g.k, g.dX, g.dY, got)
    rs.reynolds_residual(Phi, H, rho_r, eta_r, g.lam, g.k, g.dX, g.dY, want)
    assert np.array_equal(got, R)  # the facade's residual is the kernel's
    scale = np.max(np.abs(rho_r * H)) / g.dX
    assert np.max(np.abs(got - want)) <= 1e-11 * scale
    assert abs(load_error) < 0.2 and math.isfinite(load_error)


def _sweep_state(Ry):
    """A relaxation test's state on a 21 x 17 grid of the thesis' oil at 800 N, Rx = 0.08 m and Ry (m): a
    perturbed Hertz pressure with an inlet bump and a cavitated exit, its film (closed gaps at 0) and fluid
    ratios, a non-zero FAS right-hand side and the deflection kernel. Returns (grid, P, H, rho_r, eta_r, F, Kc)."""
    g = en.ContactGrid(0.08, Ry, 800.0, 2.0, E_RED, 0.00795, FLUIDS["wlf_murnaghan"], en.Domain(-2.0, 1.5, 1.6, 21, 17))
    Xg, Yg = np.meshgrid(g.X, g.Y, indexing="ij")
    P0 = g.hertz_pressure() * (1.0 + 0.05 * np.sin(5.0 * Xg) * np.cos(3.0 * Yg)) + 0.02 * np.exp(-((Xg + 1.4) ** 2))
    P0[(Xg > 0.9)] = 0.0
    P0[0, :] = P0[-1, :] = P0[:, 0] = P0[:, -1] = 0.0
    _, _, H, rho_r, eta_r = g.residual(P0, -g.delta / g.scale_h + 0.03)
    F = 1e-3 * np.cos(2.0 * Xg) * np.sin(Yg)
    return g, P0, np.maximum(H, 0.0), rho_r, eta_r, F, g.c_w * g.kern


def test_relaxation_sweep_matches_twin():
    """One sweep on a 21 x 17 grid of the thesis' oil at 800 N: Gauss-Seidel nodes (inlet, sides), Jacobi
    distributive nodes (high pressure, eps small), cavitated nodes and a non-zero FAS right-hand side.
    Both update the same nodes in the same order; the twin's residuals are whole-array sums in another
    order: P agrees to 1e-12 of max P (measured <= 1e-15)."""
    g, P0, H, rho_r, eta_r, F, Kc = _sweep_state(0.08)
    got, want = P0.copy(), P0.copy()
    delta = np.empty_like(P0)
    g_rho = np.empty_like(P0)
    es.density_log_slopes(P0, g.p_h, g.fluid, g_rho)
    args = (H, rho_r, eta_r, g_rho, g.lam, g.k, g.dX, g.dY, Kc, 0.3, 0.6, 0.2, math.inf)
    c_got = es.relaxation_sweep(got, F, *args, delta)
    c_want = rs.relaxation_sweep(want, F, *args, np.empty_like(P0))
    jacobi = int(np.count_nonzero(delta))
    assert 0 < jacobi < (g.nx - 2) * (g.ny - 2)  # both kinds of update took place
    assert np.any((got == 0.0)[1:-1, 1:-1])  # and cavitated nodes
    assert np.max(np.abs(got - want)) <= 1e-12 * np.max(want)
    assert_close(c_got, c_want, 1e-12, "largest change")
    assert c_got > 0.0


@pytest.mark.parametrize("density", [False, True])
def test_line_relaxation_matches_twin(density):
    """A line sweep and then the point and Jacobi distributive sweep that completes it (xi_lines finite) on the
    grid of test_relaxation_sweep_matches_twin with Ry = 9 Rx (k = 4.2, the lines run along X): runs of line
    nodes broken by Jacobi distributive and point Gauss-Seidel nodes, cavitated nodes and the boundary. The
    kernel solves each run by the Thomas algorithm, the twin by a dense numpy solve, both with the same
    residuals in the same row order: P agrees to 1e-12 of max P (measured <= 1e-15). With and without the
    density's part of the derivative."""
    g, P0, H, rho_r, eta_r, F, Kc = _sweep_state(0.08 * 9.0)
    g_rho = np.zeros_like(P0)
    if density:
        es.density_log_slopes(P0, g.p_h, g.fluid, g_rho)
    # nodes of all four kinds: Jacobi distributive (eps kmax < 0.3), point Gauss-Seidel (0.3-3 or next to a
    # cavitated node), lines (>= 3 with the star pressurised) and cavitated
    xi_lines = 3.0
    xi = rho_r * H**3 / (eta_r * g.lam) * max(1.0, 1.0 / g.k**2) / g.dX**2
    star = np.minimum.reduce([P0[1:-1, 1:-1], P0[2:, 1:-1], P0[:-2, 1:-1], P0[1:-1, 2:], P0[1:-1, :-2]]) > 0.0
    kinds = [xi[1:-1, 1:-1] < 0.3, (xi[1:-1, 1:-1] >= 0.3) & (xi[1:-1, 1:-1] < xi_lines), xi[1:-1, 1:-1] >= xi_lines]
    assert all(np.count_nonzero(star & kind) > 0 for kind in kinds), [np.count_nonzero(star & kind) for kind in kinds]
    line_args = (H, rho_r, eta_r, g.lam, g.k, g.dX, g.dY, Kc, g_rho, xi_lines, 0.6)
    got, want = P0.copy(), P0.copy()
    c_got = es.line_gauss_seidel(got, F, *line_args, np.empty((4, g.nx)))
    c_want = rs.line_gauss_seidel(want, F, *line_args, None)
    moved = (got != P0)[1:-1, 1:-1]
    assert 0 < np.count_nonzero(moved) < (g.nx - 2) * (g.ny - 2)  # some nodes on lines, others not
    assert np.max(np.abs(got - want)) <= 1e-12 * np.max(want)
    assert_close(c_got, c_want, 1e-12, "largest change of the lines")
    args = (H, rho_r, eta_r, g_rho, g.lam, g.k, g.dX, g.dY, Kc, 0.3, 0.6, 0.2, xi_lines)
    delta = np.empty_like(P0)
    c_got = es.relaxation_sweep(got, F, *args, delta)
    c_want = rs.relaxation_sweep(want, F, *args, np.empty_like(P0))
    assert np.count_nonzero(delta) > 0  # Jacobi distributive nodes took part
    assert np.max(np.abs(got - want)) <= 1e-12 * np.max(want)
    assert_close(c_got, c_want, 1e-12, "largest change of the point sweep")


@pytest.mark.parametrize("name", sorted(FLUIDS))
def test_fluid_log_slopes_match_twin(name):
    """The kernel's central differences (step 1e-6 (P + 1)) against the twin's Richardson-extrapolated ones
    (steps 1e-3, 5e-4): both approximate d ln(ratio)/dP to about 1e-9 of its size; tolerance 1e-6 relative
    to the largest slope of the field (measured <= 2e-8). Pressures up to 1.5 GPa (p_h = 0.5 GPa): below the
    viscosity cap of every law, whose edge the twin's wider steps would straddle."""
    fluid = FLUIDS[name]
    P = np.concatenate([[0.0, 1e-4], np.linspace(0.05, 3.0, 46)]).reshape(6, 8)
    got = (np.empty_like(P), np.empty_like(P))
    want = (np.empty_like(P), np.empty_like(P))
    es.fluid_log_slopes(P, 0.5e9, fluid, *got)
    rs.fluid_log_slopes(P, 0.5e9, fluid, *want)
    for a, b, what in ((got[0], want[0], "rho"), (got[1], want[1], "eta")):
        assert np.max(np.abs(a - b)) <= 1e-6 * max(np.max(np.abs(b)), 1e-300), what


@pytest.mark.parametrize("name", sorted(FLUIDS))
def test_density_log_slopes_match_twin(name):
    """The kernel's closed-form d ln(rho_r)/dP against the twin's Richardson-extrapolated differences of its own
    law (about 1e-9 of the slope's size, test_fluid_log_slopes_match_twin): tolerance 1e-6 relative to the
    largest slope of the field; incompressible: exactly 0."""
    fluid = FLUIDS[name]
    P = np.concatenate([[0.0, 1e-4], np.linspace(0.05, 3.0, 46)]).reshape(6, 8)
    got, want = np.empty_like(P), np.empty_like(P)
    es.density_log_slopes(P, 0.5e9, fluid, got)
    rs.density_log_slopes(P, 0.5e9, fluid, want)
    assert np.max(np.abs(got - want)) <= 1e-6 * max(np.max(np.abs(want)), 1e-300)
    if name.endswith("incompressible"):
        assert not np.any(got)


@pytest.mark.parametrize("Rx, Ry", [(0.08, 0.08), (0.02892, 0.345), (0.345, 0.02892)])
def test_newton_jacobian_matches_finite_differences_of_the_twin(Rx, Ry):
    """Analytic Jacobian (kernel) against central differences of the twin's residual on a 21 x 17 grid of
    the thesis' oil at 800 N (wet nodes: P > 0 of a perturbed Hertz field, film opened by +0.05). The
    differences carry O(d^2) truncation and 1e-10 / d rounding (d = 1e-6 P); tolerance 1e-6 of the largest
    entry of the Jacobian (measured <= 3.5e-9)."""
    g = en.ContactGrid(Rx, Ry, 800.0, 2.0, E_RED, 0.00795, FLUIDS["wlf_murnaghan"], en.Domain(-2.0, 1.5, 1.6, 21, 17))
    Xg, Yg = np.meshgrid(g.X, g.Y, indexing="ij")
    P = g.hertz_pressure() * (1.0 + 0.05 * np.sin(5.0 * Xg) * np.cos(3.0 * Yg)) + 0.02 * np.exp(-((Xg + 1.4) ** 2))
    P[Xg > 0.9] = 0.0
    P[0, :] = P[-1, :] = P[:, 0] = P[:, -1] = 0.0
    H0 = -g.delta / g.scale_h + 0.05
    _, _, H, rho_r, eta_r = g.residual(P, H0)
    g_rho, g_eta = np.empty_like(P), np.empty_like(P)
    es.fluid_log_slopes(P, g.p_h, g.fluid, g_rho, g_eta)
    wi, wj = np.nonzero(P > 0.0)
    widx = np.full(P.shape, -1, np.int64)
    widx[wi, wj] = np.arange(len(wi))
    got = np.zeros((len(wi) + 1, len(wi) + 1))
    want = np.zeros_like(got)
    args = (P, H, rho_r, eta_r, g_rho, g_eta, g.lam, g.k, g.dX, g.dY, g.c_w * g.kern, wi, wj, widx)
    es.newton_jacobian(*args, got)
    rs.newton_jacobian(*args, want)
    assert np.max(np.abs(got - want)) <= 1e-6 * np.max(np.abs(want))


@pytest.mark.parametrize("load, u_e, Rx, Ry", [(120.0, 2.0, 0.08, 0.08), (2500.0, 2.0, 0.02892, 0.345)])
def test_newton_solves_the_coarsest_grid_up_to_the_heaviest_annexe_d_load(load, u_e, Rx, Ry):
    """Annexe D cases 6 (k = 1, 120 N, M = 54) and 45 (k = 5.03, 2500 N, M = 4016) on the 41 x 33 grid of
    level 0 from the Hertz pressure: the semismooth Newton (models.ehl_numerical.newton, Jacobian dense through
    the deflection, H0 an unknown) brings the merit (rms of min(P, -R/d) and the load error) below 1e-10 in
    at most 12 steps (measured 5 and 7, the last ones quadratic: 1.3e-6 -> 4.6e-11, 1.3e-7 -> 1.1e-8 ->
    4.4e-14). Point relaxation with H0 relaxed from the load error, the solver before, did not converge on
    this grid at M >= 360 (docs/ehl_solver.md)."""
    fluid = FLUIDS["wlf_murnaghan"]
    (g,) = en.grid_hierarchy(Rx, Ry, load, u_e, E_RED, 0.00795, fluid, finest=0, coarsest=0)
    P = g.hertz_pressure()
    P *= en.LOAD / (g.dX * g.dY * P.sum())
    H0 = -g.delta / g.scale_h + 0.1
    L = en._Level(g, en.SolverSettings())
    H0, merit = en.newton(L, P, np.zeros_like(P), en.LOAD, H0, 12)
    assert merit < 1e-10
    assert abs(g.dX * g.dY * P.sum() - en.LOAD) < 1e-9 and np.all(P >= 0.0)


def test_a_solution_with_a_negative_film_is_not_converged():
    """A ball of Rx = Ry = 12.7 mm at 2 kN (p_H = 3.2 GPa), 2 m/s, lubricant 2 at 313 K, solved on the 41 x 33
    grid of level 0 alone: Newton meets its merit (below 1e-8, the single-grid criterion) on a film closed over
    most of the contact (h_min about -485 nm: the grid's spacing is 20 times the inlet layer of this ~0.1 um
    film), which the discrete Reynolds equation admits (a closed gap carries no Poiseuille flow and a negative
    Couette flux). A negative gap is not a lubricated contact: the Solution must say not converged, and why."""
    fluid = FLUIDS["wlf_murnaghan"]
    sol = en.solve_contact(12.7e-3, 12.7e-3, 2000.0, 2.0, E_RED, 0.00795, fluid, finest=0)
    assert sol.history[0][2] < 1e-8  # Newton itself converged
    assert sol.h_min < 0.0
    assert not sol.converged
    assert sol.reason.startswith("negative film")


def test_contact_box_grows_only_beyond_the_annexe_d_films():
    """contact_box: films up to H_c = 0.35 (Hertz units; Annexe D reaches 0.27) keep the boxes of s <= 1 (the
    formula the Annexe D validation was made with), thicker films get an inlet of at least 1.5 (m* - 1) past the
    Hertz edge (Hamrock and Dowson's starvation boundary m* = 1 + 3.06 H_c^0.58), up to BOX_GROWTH_MAX."""
    for H_c in (0.02, 0.1, 0.16, 0.27, 0.35):
        assert en.contact_box(H_c)[0] >= -3.5 - 1e-12
    for H_c in (0.5, 1.0, 2.3, 5.0):
        x_in = en.contact_box(H_c)[0]
        assert -1.0 - x_in >= 1.5 * 3.06 * H_c**0.58 - 1e-9, (H_c, x_in)
    assert en.contact_box(100.0)[0] == en.contact_box(1000.0)[0]


def test_film_estimate_is_hamrock_dowson_or_the_rigid_regimes_film():
    """film_estimate: Hamrock-Dowson's central film where it is the largest (an Annexe D contact), the rigid
    regimes' (Hamrock and Dowson 1981) at a light, fast contact (M = 5, L = 20, k = 9), where it is larger."""
    from bearing_fmu.kernels import ehl

    Rx, Ry = 0.08, 0.08
    U, G, W = 8.6e-12, 5000.0, 1e-7
    k = 1.0
    assert en.film_estimate(U, G, W, k, Rx, Ry) == ehl.film_hamrock_dowson(U, G, W, k)[0]
    U, G, W = 1e-9, 4000.0, 1e-7  # M = W (2U)^-3/4 = 3.3, L = G (2U)^1/4 = 27
    a_r = Ry / Rx
    phi = 1.0 / (1.0 + 2.0 / (3.0 * a_r))
    rigid_iso = 128.0 * a_r * phi**2 * (0.131 * math.atan(0.5 * a_r) + 1.683) ** 2 * (U / W) ** 2
    assert en.film_estimate(U, G, W, k, Rx, Ry) >= rigid_iso
    assert en.film_estimate(U, G, W, k, Rx, Ry) > ehl.film_hamrock_dowson(U, G, W, k)[0]


def test_film_level_is_the_coarsest_level_that_resolves_the_film():
    """film_level (docs/ehl_solver.md, Heavy contacts): the films of the light and moderate contacts stay on level 3,
    the default the Annexe D validation was made with; a thinner film gets the coarsest level whose X spacing on its
    box is at most RESOLVING_SPACING times the film, the next coarser level's being larger; below what the finest
    level resolves, the finest. The level never rises with the film."""

    def spacing(H_c, level):
        x_in, x_out, _ = en.contact_box(H_c)
        return (x_out - x_in) / (40 * 2**level)

    films = np.geomspace(1e-4, 10.0, 200)
    levels = [en.film_level(H_c) for H_c in films]
    assert all(a >= b for a, b in zip(levels, levels[1:])), "a thicker film got a finer level"
    assert levels[-1] == en.COARSEST_RESOLVING_LEVEL and levels[0] == en.FINEST_LEVEL
    for H_c, level in zip(films, levels):
        if level < en.FINEST_LEVEL:
            assert spacing(H_c, level) <= en.RESOLVING_SPACING * H_c
        if level > en.COARSEST_RESOLVING_LEVEL:
            assert spacing(H_c, level - 1) > en.RESOLVING_SPACING * H_c
    assert en.film_level(0.16) == 3  # Annexe D's light loads (H_c ~ 0.16, case 6)


def test_the_coarse_pressure_is_full_weighting_inside_the_wet_zone_and_injection_next_to_cavitation():
    """restrict_pressure (the FAS coarse grid's pressure, docs/ehl_solver.md, Fine grids): without full weighting the
    fine pressure at every other node; with it the full-weighting average (1/16 of the 3 x 3 stencil 1 2 1 / 2 4 2 /
    1 2 1) wherever the coarse node's nine fine nodes are wet, and still the injected value next to a cavitated
    node, so the coarse free boundary stays where the fine grid has it."""
    rng = np.random.default_rng(3)
    P = rng.uniform(0.5, 1.5, (9, 9))
    P[0, :] = P[-1, :] = P[:, 0] = P[:, -1] = 0.0
    P[5, 6] = 0.0  # a cavitated node: the coarse node (3, 3) at fine (6, 6) is its neighbour
    assert np.array_equal(en.restrict_pressure(P, False), P[::2, ::2])
    Pc = en.restrict_pressure(P, True)
    weights = np.outer([1.0, 2.0, 1.0], [1.0, 2.0, 1.0]) / 16.0
    assert Pc[1, 1] == pytest.approx(np.sum(weights * P[1:4, 1:4]), rel=1e-12)
    assert Pc[1, 1] != P[2, 2]
    assert Pc[3, 3] == P[6, 6]  # next to the cavitated node: injection
    assert Pc[1, 3] == pytest.approx(np.sum(weights * P[1:4, 5:8]), rel=1e-12)  # two nodes from the cavitated one
    assert np.all(Pc[0, :] == 0.0) and np.all(Pc[:, 0] == 0.0)
