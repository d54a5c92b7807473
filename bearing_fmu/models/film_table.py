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

models.film_table_build solves the nodes (`spindle film-table BEARING --lubricant OIL`) and writes the table as JSON
into the cache directory of the compiled kernels (bearing_fmu_common.jit.cache_base()/film_tables), named by bearing,
lubricant and a key of everything the ratios depend on (geometry, materials, the lubricant's packed parameters and
temperature range, the settings here and the sources of the solver and the formulas), so an edit to any of them asks
for a new build. `film_table_array(bearing, lubricant, correction)` reads it for a model and raises
FilmTableMissing, naming the command, when there is none.

An FMU does not read the cache of the machine it runs on: it carries the tables it was built with in
resources/film_tables (carried_name: bearing, lubricant and a key of the table's content; the build checked the
code's part of the key), and its models read only those (`film_table_array(..., carried=directory)`). This module
reads tables; it imports neither the numerical solver nor its kernels, which an FMU does not carry.
"""

import hashlib
import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from bearing_fmu_common.jit import cache_base
from bearing_fmu_common.variables import InputError

from ..kernels import ehl
from ..kernels import film_correction as fc
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
CARRIED_DIR = "film_tables"  # an FMU's resources/ directory of the tables it carries


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


def table_content(bearing, lubricant):
    """What the table's ratios depend on besides the code: races, materials, lubricant, node settings."""
    races, E_red = race_geometry(bearing)
    content = {
        "version": TABLE_VERSION,
        "races": [(Rx, Ry, list(c)) for Rx, Ry, c in races],
        "E_red": E_red,
        "lubricant": list(lubricant.array),
        "T_range": temperature_range(lubricant),
        "settings": (P_H_RANGE, U_E_RANGE, M_CAP, L_CAP, fc.FT_NM, fc.FT_NL),
    }
    return content


def table_key(bearing, lubricant):
    """SHA-256 (hex) of everything the table's ratios depend on: its content and the sources of the solver and
    the formulas."""
    digest = hashlib.sha256(json.dumps(table_content(bearing, lubricant)).encode())
    for name in SOURCES:
        digest.update((PACKAGE / name).read_bytes())
    return digest.hexdigest()


def table_path(bearing, lubricant):
    """Where the table of this bearing and lubricant is cached."""
    return cache_base() / "film_tables" / f"{bearing.name}_{lubricant.name}_{table_key(bearing, lubricant)[:16]}.json"


def loaded(bearing, lubricant):
    """The bearing and lubricant of names, files or objects."""
    from ..params import load_bearing, load_lubricant

    return load_bearing(bearing), load_lubricant(lubricant)


def carried_name(bearing, lubricant):
    """File name of the table an FMU carries (resources/film_tables): bearing, lubricant and a key of the table's
    content. The code's part of the cache key is not in it: the FMU carries the code it was built with."""
    content = hashlib.sha256(json.dumps(table_content(bearing, lubricant)).encode()).hexdigest()
    return f"{bearing.name}_{lubricant.name}_{content[:16]}.json"


def _read(path):
    data = json.loads(Path(path).read_text())
    data["races"] = [RaceTable(**race) for race in data["races"]]
    return FilmTable(**data)


def _carried_pairs(carried):
    """'bearing with lubricant' of each table in the directory `carried`."""
    pairs = (json.loads(p.read_text()) for p in sorted(Path(carried).glob("*.json")))
    return [f"{d['bearing']} with {d['lubricant']}" for d in pairs]


def load_film_table(bearing, lubricant, carried=None):
    """The table of bearing and lubricant (names, files or objects): from the directory `carried` (an FMU's
    resources/film_tables) if given, else from the cache; FilmTableMissing if there is none."""
    b, lub = loaded(bearing, lubricant)
    if carried is None:
        path = table_path(b, lub)
        if not path.is_file():
            raise FilmTableMissing(
                f"film_correction = 'table' needs the film table of bearing '{b.name}' with lubricant '{lub.name}' "
                f"({path} does not exist): build it with `spindle film-table {b.name} --lubricant {lub.name}`"
            )
        return _read(path)
    path = Path(carried) / carried_name(b, lub)
    if not path.is_file():
        pairs = ", ".join(_carried_pairs(carried)) or "none"
        raise FilmTableMissing(
            f"film_correction = 'table': this FMU carries the film tables of {pairs}, not of bearing '{b.name}' with "
            f"lubricant '{lub.name}' (parameters bearing and lubricant, or their numeric values): build that table "
            f"(`spindle film-table {b.name} --lubricant {lub.name}`) and an FMU that starts with this bearing and "
            "lubricant, which then carries it"
        )
    return _read(path)


def film_table_array(bearing, lubricant, correction, carried=None):
    """The kernels' table array of a scene's film_correction: 'none' an array that is off, 'table' the table's
    (load_film_table: from `carried`, an FMU's own tables, else the cache)."""
    if correction == "none":
        return np.zeros(fc.FT_SIZE)
    return load_film_table(bearing, lubricant, carried).array()
