"""Build a film correction table: solve its nodes with the numerical EHL solver (models.film_table says what the table
is, where it is kept and how a model reads it; docs/film_correction.md).

Offline only: the command line (`spindle film-table BEARING --lubricant OIL`) and the FMU build run it; an FMU carries
the tables it was built with, not this module or the solver.
"""

import json
import math
import os
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import asdict

import numpy as np

from ..kernels import ehl
from ..kernels import ehl_solver as es
from ..kernels import film_correction as fc
from ..kernels.hertz import hertz_contact
from ..kernels.lubricant import lubricant_state
from .film_table import (
    FORMULAS,
    L_CAP,
    M_CAP,
    P_H_RANGE,
    U_E_RANGE,
    FilmTable,
    RaceTable,
    loaded,
    race_geometry,
    table_key,
    table_path,
    temperature_range,
)


def table_axes(eta, xi, E_red, u, Q, Rx):
    """(ln(W G^3), ln L) of a contact (the table's axes, kernels.film_correction)."""
    U, G, W = ehl.dimensionless_groups(eta, xi, E_red, u, Q, Rx)
    return math.log(W * G**3), math.log(G * (2.0 * U) ** 0.25)


def node_ranges(Rx, Ry, c, E_red, lubricant, T_range):
    """(low, high) of ln(W G^3) and of ln L of a race over the corners of the load, speed and temperature ranges,
    L at most L_CAP."""
    p_1N = hertz_contact(1.0, Rx, Ry, E_red, *c)[3]
    loads = [(p / p_1N) ** 3 for p in P_H_RANGE]  # p_h ~ Q^(1/3)
    corners = []
    for T in T_range:
        eta, xi, _ = lubricant_state(T, lubricant.array)
        corners += [table_axes(eta, xi, E_red, u, Q, Rx) for u in U_E_RANGE for Q in loads]
    xs, ys = zip(*corners, strict=True)
    return (min(xs), max(xs)), (min(ys), min(max(ys), math.log(L_CAP)))


def node_point(M, L, Rx, E_red, lubricant, T_range):
    """(T K, u m/s, Q N) of the Moes parameters (M, L): T where L is reached at the middle speed (bisection,
    clamped to the range; L falls with T), u giving L at T, Q giving M."""
    u_mid = math.sqrt(U_E_RANGE[0] * U_E_RANGE[1])
    low, high = T_range
    for _ in range(60):
        T = 0.5 * (low + high)
        eta, xi, _ = lubricant_state(T, lubricant.array)
        if table_axes(eta, xi, E_red, u_mid, 1.0, Rx)[1] > math.log(L):
            low = T
        else:
            high = T
    eta, xi, _ = lubricant_state(T, lubricant.array)
    U = 0.5 * (L / (xi * E_red)) ** 4
    W = M * (2.0 * U) ** 0.75
    return T, U * E_red * Rx / eta, W * E_red * Rx * Rx


def solve_numerical(Rx, Ry, Q, u, E_red, eta, xi, level=None):
    """(Solution, grid level) of the numerical solver for a contact (SI, the fluid of models.film_check: Roelands
    and Dowson-Higginson through eta (Pa.s) and xi (1/Pa)) on `level`, by default the level its film needs
    (models.ehl_numerical.film_level: level 3 at light and moderate loads, 4-5 at heavy ones, whose films level 3
    leaves up to 30 % thin), or on the next finer grid where that one does not converge (B7214C's outer race at
    M = 30000, L = 11.2 on level 3: h_min 0.3 nm, not converged; docs/ehl_solver.md, Thin films), up to
    ehl_numerical.FINEST_LEVEL."""
    # imported here, not with this module: the numerical solver needs scipy, which an FMU's host need not have
    # (the facades import this module for film_table_array, whose correction 'none' needs no solver)
    from . import ehl_numerical as en

    fluid = en.fluid_array(es.VISC_ROELANDS, es.DENS_DOWSON_HIGGINSON, eta, xi)
    if level is None:
        level = en.resolving_level(Rx, Ry, Q, u, E_red, eta, fluid)
    solution = en.solve_contact(Rx, Ry, Q, u, E_red, eta, fluid, finest=level)
    if solution.converged or level >= en.FINEST_LEVEL:
        return solution, level
    return en.solve_contact(Rx, Ry, Q, u, E_red, eta, fluid, finest=level + 1), level + 1


def solve_node(args):
    """One node: the numerical films and each formula's, as a dict (a top-level function for process pools)."""
    M, L, Rx, Ry, k, E_red, lubricant, T_range, log = args
    T, u, Q = node_point(M, L, Rx, E_red, lubricant, T_range)
    eta, xi, _ = lubricant_state(T, lubricant.array)
    start = time.perf_counter()
    solution, solved_on = solve_numerical(Rx, Ry, Q, u, E_red, eta, xi)
    seconds = time.perf_counter() - start
    formulas = [ehl.film_thickness(code, eta, xi, E_red, u, Q, Rx, Ry, k) for code in FORMULAS]
    node = dict(M=M, L=L, T=T, u=u, Q=Q, h_c=solution.h_c, h_min=solution.h_min, converged=bool(solution.converged),
                level=solved_on, seconds=seconds, formulas=formulas)  # fmt: skip
    if log:
        print(f"  node M = {M:.4g}, L = {L:.4g} (T = {T:.1f} K, u = {u:.3g} m/s, Q = {Q:.4g} N): h_c = "
              f"{solution.h_c * 1e9:.1f} nm, h_min = {solution.h_min * 1e9:.1f} nm, level {solved_on}, "
              f"{'converged' if solution.converged else 'NOT converged'}, {seconds:.1f} s", flush=True)  # fmt: skip
    return node


def _race_table(Rx, Ry, c, E_red, lubricant, T_range, pool, log):
    (x0, x1), (y0, y1) = node_ranges(Rx, Ry, c, E_red, lubricant, T_range)
    d_x = (x1 - x0) / (fc.FT_NM - 1)
    d_y = (y1 - y0) / (fc.FT_NL - 1)
    Q_max = (P_H_RANGE[1] / hertz_contact(1.0, Rx, Ry, E_red, *c)[3]) ** 3
    jobs = []
    for i in range(fc.FT_NM):
        for j in range(fc.FT_NL):
            x, y = x0 + i * d_x, y0 + j * d_y
            M = min(math.exp(x - 3.0 * y), M_CAP)  # M L^3 = W G^3
            Q = node_point(M, math.exp(y), Rx, E_red, lubricant, T_range)[2]
            M *= min(1.0, Q_max / Q)  # at the node's L (and so its T and u), Q ~ M
            jobs.append((M, math.exp(y), Rx, Ry, c[0], E_red, lubricant, T_range, log))
    # nodes capped at M_CAP or the load limit repeat the same (M, L): each distinct one is solved once
    distinct = {job[:2]: job for job in jobs}
    solved = dict(zip(distinct, pool.map(solve_node, distinct.values()), strict=True))
    nodes = [solved[job[:2]] for job in jobs]
    ratios = np.empty((len(FORMULAS), 2, fc.FT_NM, fc.FT_NL))
    for n, node in enumerate(nodes):
        if not 0.0 < node["h_min"] <= node["h_c"] < math.inf:
            raise RuntimeError(f"film table node M = {node['M']:.3g}, L = {node['L']:.3g}: no positive film")
        for f, (h_c, h_min) in enumerate(node["formulas"]):
            ratios[f, 0, n // fc.FT_NL, n % fc.FT_NL] = node["h_c"] / h_c
            ratios[f, 1, n // fc.FT_NL, n % fc.FT_NL] = node["h_min"] / h_min
    return RaceTable(Rx, Ry, c[0], x0, d_x, y0, d_y, ratios.tolist(), nodes)


def build_film_table(bearing, lubricant, jobs=1, log=False):
    """Solve every node of both races (jobs processes; log: print each node as it is solved), write the table into
    the cache and return it."""
    b, lub = loaded(bearing, lubricant)
    T_range = temperature_range(lub)
    races, E_red = race_geometry(b)
    start = time.perf_counter()
    with ProcessPoolExecutor(jobs) as pool:
        tables = [_race_table(Rx, Ry, c, E_red, lub, T_range, pool, log) for Rx, Ry, c in races]
    table = FilmTable(b.name, lub.name, table_key(b, lub), T_range, time.perf_counter() - start, tables)
    path = table_path(b, lub)
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_suffix(f".{os.getpid()}.tmp")
    partial.write_text(json.dumps(asdict(table), indent=1))
    partial.replace(path)  # atomic: a model never reads a half-written table
    return table
