"""The film formulas against the numerical EHL solver at the product's own contacts (bearing_fmu.models.film_check).

Operating points: the 6208 of Guessasma & Machado (2018) and Farah et al. (2020) with their oil (3 kN at 100, 500
and 1700 rad/s, the ends and the middle of Guessasma's speed range; 5 kN at 500 rad/s, Farah's second load) and
the B7214C of the Rabreau et al. (2018) spindle rig under its 800 N preload at 10 000 rpm with iso_vg68_mineral at
313 K. At each, the most loaded inner and outer contacts of the quasi-static fidelity, solved numerically on the
grid level each contact's film needs (models.ehl_numerical.film_level: within about 2 % of the grid-converged
film); the three film formulas' h_c and h_min against it, with Lambda and the regime each implies.
The numerical solution is isothermal and Newtonian with Roelands' viscosity and Dowson and Higginson's density
through the oil's viscosity and pressure-viscosity coefficient at the oil temperature, as the formulas are.
Run: python -m benchmarks.film_check -> docs/reports/film_check.md
"""

import math
import os

from bearing_fmu.models.film_check import FORMULAS, film_check

from .render import cli, metric

FILMS = ("h_c", "h_min")
POINTS = (
    ("6208", "guessasma_oil", 313.15, 100.0, {"F_y": 3000.0}),
    ("6208", "guessasma_oil", 313.15, 500.0, {"F_y": 3000.0}),
    ("6208", "guessasma_oil", 313.15, 1700.0, {"F_y": 3000.0}),
    ("6208", "guessasma_oil", 313.15, 500.0, {"F_y": 5000.0}),
    ("B7214C", "iso_vg68_mineral", 313.15, 10000.0 * math.pi / 30.0, {"F_z": 800.0}),
)


def _point(bearing, omega, loads, race):
    forces = ", ".join(f"{name} = {value:g} N" for name, value in loads.items())
    return f"{bearing}, {forces}, {omega:.0f} rad/s, {race}"


def row(point, c):
    """A table row of one contact, and its metrics (each formula's h_c and h_min error against the numerical; left
    out where the numerical film did not converge, as `spindle film` leaves them out)."""
    n = c.numerical
    if n is None:
        return [point, c.load, None, None, None, "no positive film on the solver's grid"] + [None] * 4, []
    numerical = f"{n.h_c * 1e9:.1f} / {n.h_min * 1e9:.1f}, {n.lam:.2f}, {n.regime} (level {c.level})"
    numerical += "" if c.converged else f" (not converged: {c.reason})"
    cells = [point, c.load, c.u_e, c.k, c.p_h / 1e9, numerical]
    metrics = []
    if not c.converged:
        return cells + ["left out"] * len(c.formulas) + [c.seconds], metrics
    for name, f in c.formulas.items():
        cells.append(f"{100 * (f.h_c / n.h_c - 1):+.1f}, {100 * (f.h_min / n.h_min - 1):+.1f}, {f.regime}")
        metrics += [metric(f"{point}: {name} {q}", getattr(f, q) / getattr(n, q) - 1.0, "1", "error") for q in FILMS]
    return cells + [c.seconds], metrics


COLUMNS = [
    "operating point, contact",
    "Q (N)",
    "u_e (m/s)",
    "k",
    "p_h (GPa)",
    "numerical h_c / h_min (nm), Lambda, regime",
]
TEXT = (
    "`spindle film` gives the same comparison at any operating point (docs/ehl_solver.md). Load average "
    "{before:.1f} before the run, {after:.1f} after."
)


def measure():
    rows, metrics, load = [], [], os.getloadavg()[0]
    for bearing, lubricant, T_oil, omega, loads in POINTS:
        for c in film_check(bearing, lubricant, omega, loads, T_oil):
            cells, ms = row(_point(bearing, omega, loads, c.race), c)
            rows, metrics = rows + [cells], metrics + ms
    columns = COLUMNS + [f"{name}: h_c, h_min vs numerical (%), regime" for name in FORMULAS] + ["solve (s)"]
    formats = ["{}", "{:.0f}", "{:.2f}", "{:.2f}", "{:.2f}"] + ["{}"] * (1 + len(FORMULAS)) + ["{:.1f}"]
    values = dict(before=load, after=os.getloadavg()[0])
    blocks = [{"text": TEXT, "values": values}, {"table": dict(columns=columns, formats=formats, rows=rows)}]
    title = "Film formulas against the numerical EHL solver at the product's contacts"
    about = __doc__.split("\n\n")[1].split("Run:")[0]
    return dict(name="film_check", title=title, about=about, blocks=blocks, metrics=metrics)


def main(argv=None):
    cli(measure, "film_check")


if __name__ == "__main__":
    main()
