"""The film correction table of a bearing and lubricant: numerical / formula film ratios (docs/film_correction.md).

Per race (one ellipticity k each) the ratio of the numerical EHL film (models.ehl_numerical, the fluid of
models.film_check: Roelands and Dowson-Higginson through the oil's eta and alpha at the oil temperature) to each film
formula of kernels.ehl, at FT_NM x FT_NL nodes uniform in (ln(W G^3), ln L), functions of the Moes parameters M and
L (kernels.film_correction). The nodes span what the bearing and the oil give: contact loads of Hertz pressure
P_H_RANGE, entrainment speeds U_E_RANGE, oil temperatures of the lubricant file's [temperature_range]
(TEMPERATURE_RANGE without one), within L <= L_CAP and M <= M_CAP, the range where the solver converges
(docs/ehl_solver.md): the nodes' L stops at L_CAP (cold oil at high speed is beyond it) and a node whose M exceeds
M_CAP is solved at M_CAP and the same L (hot oil at low speed, heavy loads), so contacts beyond either take the
ratios of that edge. A node is solved at a physical point of the oil: the temperature where its L is reached at the
middle speed (clamped to the range), the speed giving L at that temperature, the load giving its M; a node whose
load would exceed the range's largest Hertz pressure (the rectangle's heavy, cold and fast corner, outside the
operating box) is solved at that load and its L (at M = 30000, L = 20 the solver did not converge, h_min half the
neighbours'). Each node is solved on the grid level its film needs (solve_numerical), so the ratios carry about the
same discretisation error, ~2 %, from the light nodes to the heavy ones.

`build_film_table(bearing, lubricant)` solves the nodes (`spindle film-table BEARING --lubricant OIL`) and writes
the table as JSON into the cache directory of the compiled kernels (bearing_fmu_common.jit.cache_base()/film_tables),
named by bearing, lubricant and a key of everything the ratios depend on (geometry, materials, the lubricant's
packed parameters and temperature range, the settings here and the sources of the solver and the formulas), so an
edit to any of them asks for a new build. `film_table_array(bearing, lubricant)` reads it for a model and raises
FilmTableMissing, naming the command, when there is none.
"""

import hashlib
import json
import math
import os
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from bearing_fmu_common.jit import cache_base
from bearing_fmu_common.variables import InputError

from ..kernels import ehl
from ..kernels import ehl_solver as es
from ..kernels import film_correction as fc
from ..kernels.hertz import hertz_contact
from ..kernels.lubricant import lubricant_state
from ..scene import Scene
from .race_contacts import race_contacts

# 2: a node the default grid does not converge is solved on the next finer one; 3: each node on the level its film
# needs (models.ehl_numerical.film_level), not on level 3 throughout
TABLE_VERSION = 3
P_H_RANGE = (1.0e9, 4.2e9)  # Pa: contact loads from a light contact to the ISO 76 static limit
U_E_RANGE = (0.5, 20.0)  # m/s: entrainment speeds
TEMPERATURE_RANGE = (293.15, 373.15)  # K: oil temperatures when the lubricant file gives no range
# largest M of the nodes: the heaviest of them (M = 30000 at the smallest L, p_h ~ 1.5 GPa, H_c ~ 0.005 Hertz
# units) already ask for a grid finer than ehl_numerical.FINEST_LEVEL by its spacing rule, and are solved on that
# finest level (docs/ehl_solver.md, Heavy contacts)
M_CAP = 30000.0
# largest L of the nodes: Annexe D spans L ~ 6-20; beyond it the solver converges at the light contacts (lines,
# docs/ehl_solver.md) but its cycles diverge at the heavy ones (M >= 15000 at L = 25, p_h >= 4.5 GPa), which
# the rectangle of nodes would reach
L_CAP = 20.0
FORMULAS = (ehl.FILM_HAMROCK_DOWSON, ehl.FILM_MASJEDI_KHONSARI, ehl.FILM_CHITTENDEN)
SOURCES = ("kernels/ehl_solver.py", "models/ehl_numerical.py", "kernels/ehl.py", "kernels/film_correction.py")
PACKAGE = Path(__file__).resolve().parent.parent


class FilmTableMissing(InputError):
    """The scene asks for the film correction and the bearing and lubricant have no table yet."""


@dataclass
class RaceTable:
    """One race's nodes: Rx, Ry (m), k (-), ln(W G^3) and ln L of the first node and spacings,
    ratios[formula][film][i][j] (film 0 central, 1 minimum) and each node's solve (M, L as solved, T K, u m/s, Q N,
    h_c, h_min m, converged, seconds)."""

    Rx: float
    Ry: float
    k: float
    ln_WG0: float
    d_ln_WG: float
    ln_L0: float
    d_ln_L: float
    ratios: list = field(default_factory=list)
    nodes: list = field(default_factory=list)


@dataclass
class FilmTable:
    """A bearing and lubricant's table: its key, the settings it was built with, build time (s) and both races."""

    bearing: str
    lubricant: str
    key: str
    T_range: tuple
    seconds: float
    races: list

    def array(self):
        """The kernels' table array (kernels.film_correction layout), correction on."""
        table = np.zeros(fc.FT_SIZE)
        table[fc.FT_ON] = 1.0
        for race, rt in enumerate(self.races):
            base = fc.FT_RACE + race * fc.FT_RACE_STRIDE
            table[base + fc.FT_LN_WG0] = rt.ln_WG0
            table[base + fc.FT_D_LN_WG] = rt.d_ln_WG
            table[base + fc.FT_LN_L0] = rt.ln_L0
            table[base + fc.FT_D_LN_L] = rt.d_ln_L
            table[base + fc.FT_RATIOS : base + fc.FT_RACE_STRIDE] = np.asarray(rt.ratios).ravel()
        return table


def temperature_range(lubricant):
    """The oil temperatures (K) the table spans: the lubricant file's range, else TEMPERATURE_RANGE."""
    return (lubricant.T_low, lubricant.T_high) if lubricant.T_low is not None else TEMPERATURE_RANGE


def race_geometry(bearing):
    """((Rx, Ry, k) inner, (Rx, Ry, k) outer) in m, m, - and E' (Pa) at the file's clearance (exact Hertz)."""
    rc = race_contacts(bearing, Scene(), bearing.Pd)
    return ((rc.Rx_i, rc.Ry_i, rc.ci), (rc.Rx_o, rc.Ry_o, rc.co)), rc.E_red


def table_key(bearing, lubricant):
    """SHA-256 (hex) of everything the table's ratios depend on."""
    races, E_red = race_geometry(bearing)
    content = {
        "version": TABLE_VERSION,
        "races": [(Rx, Ry, list(c)) for Rx, Ry, c in races],
        "E_red": E_red,
        "lubricant": list(lubricant.array),
        "T_range": temperature_range(lubricant),
        "settings": (P_H_RANGE, U_E_RANGE, M_CAP, L_CAP, fc.FT_NM, fc.FT_NL),
    }
    digest = hashlib.sha256(json.dumps(content).encode())
    for name in SOURCES:
        digest.update((PACKAGE / name).read_bytes())
    return digest.hexdigest()


def table_path(bearing, lubricant):
    """Where the table of this bearing and lubricant is cached."""
    return cache_base() / "film_tables" / f"{bearing.name}_{lubricant.name}_{table_key(bearing, lubricant)[:16]}.json"


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


def loaded(bearing, lubricant):
    """The bearing and lubricant of names, files or objects."""
    from ..params import load_bearing, load_lubricant

    return load_bearing(bearing), load_lubricant(lubricant)


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


def load_film_table(bearing, lubricant):
    """The cached table of bearing and lubricant (names, files or objects); FilmTableMissing if not built."""
    b, lub = loaded(bearing, lubricant)
    path = table_path(b, lub)
    if not path.is_file():
        raise FilmTableMissing(
            f"film_correction = 'table' needs the film table of bearing '{b.name}' with lubricant '{lub.name}' "
            f"({path} does not exist): build it with `spindle film-table {b.name} --lubricant {lub.name}`"
        )
    data = json.loads(path.read_text())
    data["races"] = [RaceTable(**race) for race in data["races"]]
    return FilmTable(**data)


def film_table_array(bearing, lubricant, correction):
    """The kernels' table array of a scene's film_correction: 'none' an array that is off, 'table' the cached
    table's."""
    if correction == "none":
        return np.zeros(fc.FT_SIZE)
    return load_film_table(bearing, lubricant).array()
