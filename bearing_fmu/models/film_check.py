"""The film at a bearing's own contacts: the product's film formulas against the numerical EHL solver.

`film_check(bearing, lubricant, omega, loads, T_oil)` solves the quasi-static operating point (the quasi-static
fidelity with its defaults), takes its most loaded inner and its most loaded outer contact and returns, for each,
the central and minimum film of every formula of kernels.ehl and of the numerical solver (models.ehl_numerical),
with the film parameter Lambda = h_min / sigma and the lubrication regime each implies (kernels.ehl). So a user
sees, at the contacts of their own operating point, how far the fitted formula that every fidelity uses is from
the solution of the equations it was fitted to.

The numerical solution takes the fluid the formulas describe: the lubricant's viscosity eta and pressure-viscosity
coefficient alpha at the oil temperature (kernels.lubricant.lubricant_state), Roelands' pressure-viscosity law
through that alpha and Dowson and Higginson's density, the laws of Hamrock and Dowson's own numerical solutions
(J. Lubr. Technol. 98(2), 1976, 223-229), isothermal and Newtonian as the formulas are. Units SI.
"""

import math
import time
from dataclasses import dataclass, field

from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import ehl, jones_harris
from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.kernels.lubricant import lubricant_state

from . import ehl_numerical as en
from .film_table_build import solve_numerical
from .quasi_static import QuasiStaticModel

FORMULAS = {
    "hamrock_dowson": ehl.FILM_HAMROCK_DOWSON,
    "masjedi_khonsari": ehl.FILM_MASJEDI_KHONSARI,
    "chittenden": ehl.FILM_CHITTENDEN,
}
REGIMES = {ehl.REGIME_BOUNDARY: "boundary", ehl.REGIME_MIXED: "mixed", ehl.REGIME_FULL_FILM: "full film"}
RACES = ("inner", "outer")


@dataclass
class Film:
    """One film estimate of a contact: central and minimum film (m), film parameter (-) and regime."""

    h_c: float
    h_min: float
    lam: float
    regime: str


@dataclass
class ContactFilm:
    """The most loaded contact of a race at the operating point and its film by each method."""

    race: str
    ball: int  # index of the ball (0 = the first ball of the quasi-static model)
    load: float  # N
    u_e: float  # entrainment speed (m/s)
    Rx: float  # reduced radius along the entrainment (m)
    Ry: float  # across it (m)
    k: float  # ellipticity a / b (-)
    p_h: float  # Hertz maximum pressure (Pa)
    sigma: float  # composite roughness (m)
    formulas: dict = field(default_factory=dict)  # formula name -> Film
    numerical: Film = None  # None: the solver found no positive film on its grid (a finer level is needed)
    converged: bool = False
    reason: str = ""  # why the numerical film is not converged ("" when it is)
    level: int = 0  # grid level of the numerical solve (models.ehl_numerical.grid_hierarchy)
    seconds: float = 0.0  # wall time of the numerical solve (s), both levels where the first did not converge


def _film(h_c, h_min, sigma):
    lam = ehl.film_parameter(h_min, sigma)
    return Film(h_c, h_min, lam, REGIMES[ehl.lubrication_regime(lam)])


def film_check(bearing, lubricant, omega, loads, T_oil=313.15, finest=None):
    """The most loaded inner and outer contacts of `bearing` (name or file) with `lubricant` at inner-ring speed
    omega (rad/s), loads = dict of the quasi-static inputs (F_x, F_y, F_z in N, M_x, M_y in N.m) and oil
    temperature T_oil (K), each with its film by every formula and by the numerical solver on grid level `finest`,
    by default the level each contact's film needs (models.ehl_numerical.film_level, docs/ehl_solver.md: within
    ~2 % of the grid-converged film), or the next finer where that one does not converge, as the film table's nodes
    are solved (models.film_table_build.solve_numerical). Returns [ContactFilm inner, ContactFilm outer]; a race
    without a loaded contact is left out."""
    model = QuasiStaticModel(bearing, lubricant)
    model.evaluate(omega=omega, T_oil=T_oil, **loads)
    eta, xi, _ = lubricant_state(T_oil, model.lubricant.array)
    cp = model.cp
    E_red = cp[ck.CP_E_RED]
    fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
    checks = []
    for race, name in enumerate(RACES):
        loads_race = model.balls[jones_harris.BQ_Q_I + race]
        ball = int(loads_race.argmax())
        Q = float(loads_race[ball])
        if Q <= 0.0:
            continue
        o = 5 * race
        Rx, Ry, k = cp[ck.CP_RX_I + o], cp[ck.CP_RY_I + o], cp[ck.CP_K_I + o]
        u = float(model.balls[jones_harris.BQ_U_I + race, ball])
        sigma = cp[ck.CP_SIGMA_I + race]
        check = ContactFilm(name, ball, Q, u, Rx, Ry, k, 0.0, sigma)
        for formula, code in FORMULAS.items():
            check.formulas[formula] = _film(*ehl.film_thickness(code, eta, xi, E_red, u, Q, Rx, Ry, k), sigma)
        start = time.perf_counter()
        if finest is None:  # the level the film needs, or the next finer where that one does not converge
            solution, check.level = solve_numerical(Rx, Ry, Q, u, E_red, eta, xi)
        else:
            solution, check.level = en.solve_contact(Rx, Ry, Q, u, E_red, eta, fluid, finest=finest), finest
        check.seconds = time.perf_counter() - start
        check.p_h = solution.grid.p_h
        # a film that closes (h <= 0) is no solution: the grid does not resolve this contact's film
        resolved = 0.0 < solution.h_min <= solution.h_c < math.inf
        check.numerical = _film(solution.h_c, solution.h_min, sigma) if resolved else None
        check.converged = solution.converged and resolved
        if not resolved:
            check.reason = "no positive film on this grid: solve on a finer level"
        elif not solution.converged:
            check.reason = solution.reason or "not converged"
        checks.append(check)
    return checks


def format_film_check(checks):
    """The film check as a plain-text table (films in nm, differences against the numerical solution in %; left out
    where the numerical film is not converged, whose reason is printed). A race without a loaded contact is said."""
    lines = []
    for race in RACES:
        if not any(c.race == race for c in checks):
            lines.append(f"{race} race: no loaded contact at this operating point (left out)")
    for c in checks:
        lines.append(
            f"{c.race} contact, ball {c.ball}: Q = {c.load:.1f} N, u_e = {c.u_e:.3f} m/s, k = {c.k:.3f}, "
            f"p_h = {c.p_h / 1e9:.3f} GPa, sigma = {c.sigma * 1e9:.1f} nm; numerical solve "
            f"on grid level {c.level} {'converged' if c.converged else 'NOT converged'} in {c.seconds:.1f} s"
        )
        if not c.converged:
            lines.append(f"  not converged: {c.reason}; the differences against it are left out")
        lines.append(
            f"  {'method':<18} {'h_c nm':>9} {'vs num.':>8} {'h_min nm':>9} {'vs num.':>8} {'Lambda':>7}  regime"
        )
        n = c.numerical
        if n is None:
            lines.append("  numerical          no positive film on this grid: solve on a finer level")
        rows = ([] if n is None else [("numerical", n)]) + list(c.formulas.items())
        compared = n is not None and c.converged
        for method, f in rows:
            d_c = f"{100.0 * (f.h_c / n.h_c - 1.0):+.1f} %" if compared and f is not n else ""
            d_m = f"{100.0 * (f.h_min / n.h_min - 1.0):+.1f} %" if compared and f is not n else ""
            lam = f"{f.lam:.2f}" if math.isfinite(f.lam) else "inf"
            lines.append(
                f"  {method:<18} {f.h_c * 1e9:>9.1f} {d_c:>8} {f.h_min * 1e9:>9.1f} {d_m:>8} {lam:>7}  {f.regime}"
            )
    return "\n".join(lines)
