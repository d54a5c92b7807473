"""Numerical EHL solver against the thesis' Annexe D (55 elliptical cases, lubricant 2 at 313 K, modified WLF
viscosity and Murnaghan density), on each grid level asked for, beside the closed-form film formulas
(benchmarks.ehl_film_table) as error against run time.

Each case: the thesis' h_c, h_min, hm_centre, hm_lateral, the solver's, their relative differences, the
convergence record and the wall time of the solve (one core: BLAS limited to one thread, compiled kernels
cached). A grid study (`--study`) solves each chosen case on every level of `--study-levels` instead, with the
observed order and the Richardson estimate of h_c and h_min from the three finest levels.

    python -m benchmarks.ehl_solver [--levels 1,2,3] [--cases 1,6,...]      -> docs/reports/ehl_solver.md, .png
    python -m benchmarks.ehl_solver --study 6,28 [--study-levels 1,2,3,4] [--bearing-study]
                                                                            -> docs/reports/ehl_grid_study.md

With --bearing-study the grid study adds the wide bearing contacts of large Moes L (tests/cases/ehl_bearing_contacts)
on levels 3, 4 and 5.
"""

import os

# one core: the dense LU of the coarse-grid Newton must not spread over cores that other work is using (set
# before numpy loads OpenBLAS)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import math  # noqa: E402
import statistics  # noqa: E402

import numpy as np  # noqa: E402

from bearing_fmu.models import ehl_numerical as en  # noqa: E402
from tests.cases.ehl_annexe_d import FLUID, LEVEL, cases, richardson, solve  # noqa: E402
from tests.cases.ehl_bearing_contacts import CONTACTS, LUBRICANT, inner_contact  # noqa: E402

from .render import cli, metric  # noqa: E402

TOLERANCE = {True: 5.0, False: 10.0}  # % of the validation (tests/validation/test_ehl_annexe_d.py), k >= 1 / k < 1
GROUPS = (("k >= 1", True, "s"), ("k < 1", False, "o"))  # (label, wide, marker)


def _diff(got_m, want_nm):
    return 100.0 * (got_m * 1e9 - want_nm) / want_nm


def grid_size(level):
    g = en.grid_hierarchy(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, FLUID, level, level)[0]
    return f"{g.nx} x {g.ny}"


def run_case(c, level):
    """A case solved on the level: its row of the level's table (the differences at 7 and 10, the time last)."""
    load = os.getloadavg()[0]
    sol, dt = solve(c, level)
    print(f"level {level} case {c['n']}: {sol.h_c * 1e9:.1f} nm {sol.h_min * 1e9:.1f} nm {dt:.1f} s", flush=True)
    return load, [c["n"], c["w_N"], c["ue_m_s"], c["k"], c["M"], c["hc_nm"], sol.h_c * 1e9, _diff(sol.h_c, c["hc_nm"]),
                  c["hm_nm"], sol.h_min * 1e9, _diff(sol.h_min, c["hm_nm"]),
                  f"{c['hm_centre_nm']:g} / {c['hm_lateral_nm']:g}", f"{sol.hm_centre * 1e9:.1f} / "
                  f"{sol.hm_lateral * 1e9:.1f}", f"{'yes' if sol.converged else 'NO'} {sol.cycles}", sol.change,
                  sol.residual, dt]  # fmt: skip


def summary_rows(runs):
    """Per level and group of k: cases, converged, within tolerance, mean |difference| of h_c and h_min, times."""
    rows = []
    for level, table in runs.items():
        for label, wide, _ in GROUPS:
            sel = [r for r in table if (r[3] >= 1.0) == wide]
            if sel:
                counts = [len(sel), sum(r[13].startswith("yes") for r in sel), sum(within(r) for r in sel)]
                mean = [statistics.mean(abs(r[q]) for r in sel) for q in (7, 10)]
                times = [r[-1] for r in sel]
                rows.append([level, grid_size(level), label, *counts, *mean, statistics.median(times), max(times)])
    return rows


def pareto(rows):
    """Error against run time: the solver per level (the summary rows) and the film formulas."""
    from . import ehl_film_table as ft

    formula_cases = ft.load_cases()
    wide = np.array([c["k"] >= 1.0 for c in formula_cases])
    errs, per_call = ft.errors(formula_cases), ft.times_per_call(n=2000, repeats=31)
    panels = []
    for q, label in ((0, "h_c"), (1, "h_min")):
        series = [dict(x=[per_call[name]], y=[100 * float(np.mean(np.abs(errs[name][q][wide == is_wide])))],
                       style=marker, label=f"{name}, {group}")
                  for group, is_wide, marker in GROUPS for name in ft.FORMULAS]  # fmt: skip
        for group, _, marker in GROUPS:
            if sel := [r for r in rows if r[2] == group]:
                series.append(dict(x=[r[8] for r in sel], y=[r[6 + q] for r in sel], style="k" + marker + "-",
                                   label=f"numerical, {group}", annotate=[f"L{r[0]}" for r in sel]))  # fmt: skip
        panels.append(dict(title=f"{label}: error vs run time, Annexe D", xlabel="run time per contact (s)",
                           ylabel=f"mean |{label} - thesis| / thesis (%)", xscale="log", yscale="log",
                           series=series))  # fmt: skip
    return dict(file="ehl_pareto.png", caption="error against run time: solver levels and film formulas",
                size=(11, 4.6), panels=panels)  # fmt: skip


CASE_COLUMNS = ["case", "w N", "u_e m/s", "k", "M", "h_c thesis nm", "h_c nm", "diff %", "h_min thesis nm", "h_min nm",
                "diff %", "hm centre / lateral thesis nm", "solver nm", "converged, cycles", "last change", "residual",
                "s"]  # fmt: skip
CASE_FORMATS = "{} {:.0f} {:g} {:g} {:g} {:g} {:.1f} {:+.1f} {:g} {:.1f} {:+.1f} {} {} {} {:.1e} {:.1e} {:.1f}".split()
SUMMARY_COLUMNS = ["level", "grid", "cases", "n", "converged", "within tolerance", "mean abs h_c diff %",
                   "mean abs h_min diff %", "median s", "worst s"]  # fmt: skip
SUMMARY_FORMATS = ["{}"] * 6 + ["{:.2f}"] * 2 + ["{:.1f}"] * 2
INTRO = (
    "Grid levels: {levels}, on the box of each contact (`contact_box`: X in [-3.5, 1.5], |Y| <= 2 in Hertz units for "
    "the light loads, shrunk down to 0.6 of it where the inlet the film needs is short); FAS V-cycles with a "
    "semismooth Newton solve on level 0 (docs/ehl_solver.md); level {default} is the default. Differences are "
    "(solver - thesis) / thesis; last change is the spread of h_c, h_min over the last cycles; residual the rms "
    "complementarity residual / rms Couette term. Within tolerance: h_c and h_min within {tol_wide:g} % for k >= 1, "
    "{tol_slender:g} % for k < 1 (the validation's). Times: wall clock per solve on one core (BLAS on one thread), "
    "kernels compiled and cached; 1-minute load average {lo:.2f}-{hi:.2f} at the starts of the solves."
)


def measure(levels=(LEVEL,), chosen=(), study=(), study_levels=(1, 2, 3, 4), bearing_study=False):
    """The solver on the levels (all cases, or those chosen); with study, the grid study of those cases instead (and
    of the bearing contacts with bearing_study)."""
    if study:
        return grid_study(study, study_levels, bearing_study)
    runs, loads = {}, []
    for level in levels:
        solved = [run_case(c, level) for c in cases() if not chosen or c["n"] in chosen]
        loads += [load for load, _ in solved]
        runs[level] = [row for _, row in solved]
    rows = summary_rows(runs)
    values = dict(levels=", ".join(map(str, levels)), default=LEVEL, tol_wide=TOLERANCE[True],
                  tol_slender=TOLERANCE[False], lo=min(loads), hi=max(loads))  # fmt: skip
    caption = "Error against run time per level and group of cases."
    summary = dict(caption=caption, columns=SUMMARY_COLUMNS, formats=SUMMARY_FORMATS, rows=rows)
    blocks = [{"text": INTRO, "values": values}, {"table": summary}, {"figure": pareto(rows)}]
    blocks += [{"table": {"caption": f"Level {level}, grid {grid_size(level)}, per case.", "columns": CASE_COLUMNS,
                          "formats": CASE_FORMATS, "rows": table}} for level, table in runs.items()]  # fmt: skip
    title = "Numerical EHL solver against the thesis' Annexe D"
    return dict(name="ehl_solver", title=title, about=__doc__.split("\n\n")[1], blocks=blocks, metrics=metrics(runs))


MEDIAN_TARGET, WORST_TARGET = 5.0, 30.0  # s per Annexe D case on one core at the default level (docs/ehl_solver.md)


def metrics(runs):
    """Per level: cases converged and within tolerance (counts), median and worst time per case (the default level's
    against its targets)."""
    out = []
    for level, table in runs.items():
        times = [r[-1] for r in table]
        wide = [r for r in table if r[3] >= 1.0]
        default = level == LEVEL and len(table) == len(cases())
        out += [
            metric(f"level {level}: cases converged", sum(r[13].startswith("yes") for r in table), "1", "count"),
            metric(f"level {level}: cases within tolerance", sum(within(r) for r in table), "1", "count"),
            metric(f"level {level}: wide contacts within tolerance", sum(within(r) for r in wide), "1", "count"),
            metric(f"level {level}: median time per case", statistics.median(times), "s", "timing",
                   target=MEDIAN_TARGET if default else None),
            metric(f"level {level}: worst time per case", max(times), "s", "timing",
                   target=WORST_TARGET if default else None),
        ]  # fmt: skip
    return out


def within(row):
    """A case's h_c and h_min both within the validation's tolerance of the thesis'."""
    return max(abs(row[7]), abs(row[10])) <= TOLERANCE[row[3] >= 1.0]


def study_row(c, levels):
    sols = [solve(c, level)[0] for level in levels]
    row = [c["n"], c["k"], c["M"]]
    for attr, want in (("h_c", c["hc_nm"]), ("h_min", c["hm_nm"])):
        h = [getattr(s, attr) * 1e9 for s in sols]
        order, est = richardson(h)
        default = h[levels.index(LEVEL)] if LEVEL in levels else math.nan
        row += [" / ".join(f"{v:.1f}" for v in h), order, est, 100.0 * (default - est) / est, want]
        row.append(100.0 * (est - want) / want)
    print(row, flush=True)
    return row + [" ".join("y" if s.converged else "n" for s in sols)]


BEARING_LEVELS = (3, 4, 5)


def bearing_row(bearing, M, L):
    """A bearing contact on BEARING_LEVELS: its node, the films per level, their orders, Richardson estimates and the
    errors of levels 3 and 4 against them, cycles and convergence."""
    args, (T, u, Q) = inner_contact(bearing, M, L)
    sols = [en.solve_contact(*args, finest=level) for level in BEARING_LEVELS]
    row = [f"{bearing} inner", M, L, T, u, Q]
    for attr in ("h_c", "h_min"):
        h = [getattr(s, attr) * 1e9 for s in sols]
        order, est = richardson(h)
        row += [" / ".join(f"{v:.1f}" for v in h), order, est, 100.0 * (h[0] - est) / est, 100.0 * (h[1] - est) / est]
    row.append(" / ".join(f"{'y' if s.converged else 'n'} {s.cycles}" for s in sols))
    print(row, flush=True)
    return row


def bearing_study():
    """The blocks and metrics of the bearing contacts' grid study."""
    films = "per level nm|order|Richardson nm|level 3 error %|level 4 error %".split("|")
    columns = ["contact", "M", "L", "T K", "u_e m/s", "Q N"] + [f"{q} {c}" for q in ("h_c", "h_min") for c in films]
    columns.append("converged, cycles per level")
    formats = "{} {:g} {:g} {:.1f} {:.3g} {:.0f}".split() + "{} {:.2f} {:.1f} {:+.2f} {:+.2f}".split() * 2 + ["{}"]
    rows = [bearing_row(*contact) for contact in CONTACTS]
    text = (
        f"Wide bearing contacts of large Moes L (k = 9.03 and 9.37, {LUBRICANT}, Roelands and Dowson-Higginson through "
        "the oil's viscosity and pressure-viscosity coefficient, film-table nodes: the oil temperature and speed of "
        "the node's L, the load of its M) on levels 3, 4 and 5; Richardson estimate and order from the three."
    )
    blocks = [{"text": text}, {"table": {"columns": columns, "formats": formats, "rows": rows}}]
    found = [metric(f"{r[0]} M = {r[1]:g}, L = {r[2]:g}: level {LEVEL} {q} error vs Richardson", r[i] / 100.0, "1",
                    "error") for r in rows for q, i in (("h_c", 9), ("h_min", 14))]  # fmt: skip
    return blocks, found


def grid_study(chosen, levels, bearings=False):
    films = f"per level nm|order|Richardson nm|level {LEVEL} error %|thesis nm|Richardson vs thesis %".split("|")
    columns = ["case", "k", "M"] + [f"{q} {c}" for q in ("h_c", "h_min") for c in films] + ["converged"]
    formats = "{} {:g} {:g}".split() + "{} {:.2f} {:.1f} {:+.1f} {:g} {:+.1f}".split() * 2 + ["{}"]
    rows = [study_row(c, list(levels)) for c in cases() if c["n"] in chosen]
    values = dict(cases=",".join(map(str, chosen)), levels=",".join(map(str, levels)), default=LEVEL,
                  more=" --bearing-study" if bearings else "")  # fmt: skip
    text = "`python -m benchmarks.ehl_solver --study {cases} --study-levels {levels}{more}`; the default level is {default}."
    blocks = [{"text": text, "values": values},
              {"table": {"columns": columns, "formats": formats, "rows": rows}}]  # fmt: skip
    title = "Grid convergence of the numerical EHL solver (Annexe D cases)"
    about = (
        "Each case on the grids of several levels of its box (each level halves the spacing). Order: observed from "
        "the three finest; Richardson: the finest extrapolated with it (with order 2 where the observed one is "
        "outside 1-3); the default level's error: the default grid against that estimate."
    )
    # the default grid's discretisation error of each case against its Richardson estimate (columns 6 and 12)
    found = [metric(f"case {r[0]}: level {LEVEL} {q} error vs Richardson", r[i] / 100.0, "1", "error")
             for r in rows for q, i in (("h_c", 6), ("h_min", 12)) if LEVEL in levels]  # fmt: skip
    if bearings:
        more, more_metrics = bearing_study()
        blocks += more
        found += more_metrics
        title = "Grid convergence of the numerical EHL solver (Annexe D cases and bearing contacts)"
    return dict(name="ehl_grid_study", title=title, about=about, blocks=blocks, metrics=found)


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--levels", default=str(LEVEL), help="grid levels of the table runs, e.g. 1,2,3")
    ap.add_argument("--cases", default="", help="cases (1..55) to solve; all by default")
    ap.add_argument("--study", default="", help="cases of a grid study (on --study-levels)")
    ap.add_argument("--study-levels", default="1,2,3,4")
    ap.add_argument("--bearing-study", action="store_true", help="the grid study adds the bearing contacts, levels 3-5")
    parsed = vars(ap.parse_args(argv))
    bearings = parsed.pop("bearing_study")
    args = {k: tuple(int(v) for v in text.split(",") if v) for k, text in parsed.items()}
    cli(measure, "ehl_solver", levels=args["levels"], chosen=args["cases"], study=args["study"],
        study_levels=args["study_levels"], bearing_study=bearings)  # fmt: skip


if __name__ == "__main__":
    main()
