"""kernels.film_correction against its twin tests/reference/ref_film_correction.py, and the table's packing and
cache (models.film_table) without solving: a table of made-up ratios stands for a built one.

Tolerance RTOL = 1e-12: logs, products and a bilinear interpolation on both sides."""

import dataclasses
import json
import math

import numpy as np
import pytest

from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import ehl, radial_bearing
from bearing_fmu.kernels import film_correction as fc
from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models import film_table as ft
from bearing_fmu.models import film_table_build as ftb
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import load_bearing, load_lubricant
from bearing_fmu.scene import Scene
from spindle.cli import main
from tests.reference import ref_film_correction as rf
from tests.unit._compare import assert_close

RTOL = 1e-12
E_STEEL = 210e9 / (1.0 - 0.3**2)
# 6208 inner contact with iso_vg68_mineral near 313 K (the film table's example)
CONTACT = dict(eta=0.059, xi=1.78e-8, E_red=E_STEEL, Rx=4.99e-3, Ry=0.1638, k=9.37)


def made_up_table(seed=1):
    """A table that is on, with axes around CONTACT's and random ratios in [0.6, 1.4]."""
    rng = np.random.default_rng(seed)
    table = np.zeros(fc.FT_SIZE)
    table[fc.FT_ON] = 1.0
    for race in range(2):
        base = fc.FT_RACE + race * fc.FT_RACE_STRIDE
        table[base + fc.FT_LN_WG0] = 13.0 + race
        table[base + fc.FT_D_LN_WG] = 1.6
        table[base + fc.FT_LN_L0] = 1.4
        table[base + fc.FT_D_LN_L] = 1.0
        table[base + fc.FT_RATIOS : base + fc.FT_RACE_STRIDE] = rng.uniform(0.6, 1.4, fc.FT_RACE_STRIDE - fc.FT_RATIOS)
    return table


def test_layout_matches_twin():
    assert (fc.FT_NM, fc.FT_NL, fc.FT_N_FORMULAS) == (rf.NM, rf.NL, rf.N_FORMULAS)
    assert fc.FT_RACE_STRIDE == 4 + rf.N_FORMULAS * 2 * rf.NM * rf.NL


@pytest.mark.parametrize("formula", [ehl.FILM_HAMROCK_DOWSON, ehl.FILM_MASJEDI_KHONSARI, ehl.FILM_CHITTENDEN])
def test_corrected_film_matches_twin_inside_and_outside_the_nodes(formula):
    """Speeds 0.01-100 m/s and loads 1 N-100 kN reach past every edge of the made-up nodes (clamped there)."""
    table = made_up_table()
    rng = np.random.default_rng(formula)
    c = CONTACT
    for _ in range(200):
        u, Q, race = 10.0 ** rng.uniform(-2, 2), 10.0 ** rng.uniform(0, 5), int(rng.integers(2))
        args = (formula, c["eta"], c["xi"], c["E_red"], u, Q, c["Rx"], c["Ry"], c["k"], table, race)
        assert_close(fc.corrected_film_thickness(*args), rf.corrected_film_thickness(*args), rtol=RTOL)
        groups = ehl.dimensionless_groups(c["eta"], c["xi"], c["E_red"], u, Q, c["Rx"])
        assert_close(
            fc.film_ratios(table, race, formula, *groups), rf.film_ratios(table, race, formula, *groups), rtol=RTOL
        )


def test_ratio_at_a_node_is_the_node_value():
    table = made_up_table()
    race, formula, i, j = 1, ehl.FILM_MASJEDI_KHONSARI, 3, 2
    base = fc.FT_RACE + race * fc.FT_RACE_STRIDE
    x = table[base + fc.FT_LN_WG0] + i * table[base + fc.FT_D_LN_WG]  # ln(W G^3)
    y = table[base + fc.FT_LN_L0] + j * table[base + fc.FT_D_LN_L]  # ln L
    G = 4000.0
    W = math.exp(x) / G**3
    U = 0.5 * (math.exp(y) / G) ** 4
    at = base + fc.FT_RATIOS + formula * 2 * fc.FT_NM * fc.FT_NL + i * fc.FT_NL + j
    expected = (table[at], table[at + fc.FT_NM * fc.FT_NL])
    assert_close(fc.film_ratios(table, race, formula, U, G, W), expected, rtol=1e-9)


def test_off_table_and_filmless_contacts_keep_the_formula():
    c = CONTACT
    off = np.zeros(fc.FT_SIZE)
    on = made_up_table()
    for u, Q in ((5.0, 1000.0), (0.0, 1000.0), (5.0, 0.0)):
        plain = ehl.film_thickness(0, c["eta"], c["xi"], c["E_red"], u, Q, c["Rx"], c["Ry"], c["k"])
        table = off if u > 0.0 and Q > 0.0 else on
        got = fc.corrected_film_thickness(0, c["eta"], c["xi"], c["E_red"], u, Q, c["Rx"], c["Ry"], c["k"], table, 0)
        assert got == plain


def test_node_point_gives_the_node_moes_parameters():
    lub = load_lubricant("iso_vg68_mineral")
    races, E_red = ft.race_geometry(load_bearing("6208"))
    Rx = races[0][0]
    for M, L in ((20.0, 60.0), (800.0, 12.0), (3000.0, 4.5)):
        T, u, Q = ftb.node_point(M, L, Rx, E_red, lub, ft.temperature_range(lub))
        eta, xi, _ = lubricant_state(T, lub.array)
        x, y = ftb.table_axes(eta, xi, E_red, u, Q, Rx)
        assert_close((x - 3.0 * y, y), (math.log(M), math.log(L)), rtol=1e-9)
        assert ft.temperature_range(lub)[0] <= T <= ft.temperature_range(lub)[1]


def write_made_up_table(b, lub, path=None):
    """Write made-up_table() as the table of bearing b with lubricant lub, into the cache (or to `path`); returns its
    array."""
    array = made_up_table()
    races = []
    for race in range(2):
        base = fc.FT_RACE + race * fc.FT_RACE_STRIDE
        head = array[base : base + fc.FT_RATIOS]
        ratios = array[base + fc.FT_RATIOS : base + fc.FT_RACE_STRIDE].reshape(3, 2, fc.FT_NM, fc.FT_NL)
        races.append(ft.RaceTable(1e-3, 1e-1, 9.0, *head, ratios.tolist(), []))
    table = ft.FilmTable(b.name, lub.name, ft.table_key(b, lub), (273.15, 393.15), 1.0, races)
    path = path or ft.table_path(b, lub)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(dataclasses.asdict(table)))
    return array


def test_table_is_read_back_from_the_cache_and_missing_one_names_the_command(tmp_path, monkeypatch):
    monkeypatch.setenv("BEARING_FMU_CACHE", str(tmp_path))
    b, lub = load_bearing("6208"), load_lubricant("iso_vg68_mineral")
    with pytest.raises(ft.FilmTableMissing, match="spindle film-table 6208 --lubricant iso_vg68_mineral"):
        ft.film_table_array(b, lub, "table")
    assert not ft.film_table_array(b, lub, "none").any()
    array = write_made_up_table(b, lub)
    assert np.array_equal(ft.film_table_array(b, lub, "table"), array)


CORRECTED = Scene(name="corrected", fidelity="quasi_static", film_correction="table")


def test_a_model_given_the_tables_an_fmu_carries_reads_only_those(tmp_path, monkeypatch):
    """An FMU's models read the film tables it carries (a directory of files named by models.film_table.carried_name)
    and never the cache of the machine they run on: the carried B7214C table is used with the cache empty; the 6306,
    whose table is in the cache but not carried, is refused naming what the FMU carries, the parameters and the
    commands; outside an FMU (no directory given) the cache's table serves."""
    monkeypatch.setenv("BEARING_FMU_CACHE", str(tmp_path / "cache"))
    carried = tmp_path / "film_tables"
    b, lub = load_bearing("B7214C"), load_lubricant("iso_vg68_mineral")
    array = write_made_up_table(b, lub, carried / ft.carried_name(b, lub))
    assert np.array_equal(QuasiStaticModel(b, lub, CORRECTED, film_tables=carried).cp[ck.CP_FILM_TABLE :], array)
    other = load_bearing("6306")
    write_made_up_table(other, lub)
    assert np.array_equal(QuasiStaticModel(other, lub, CORRECTED).cp[ck.CP_FILM_TABLE :], array)
    with pytest.raises(ft.FilmTableMissing) as refused:
        QuasiStaticModel(other, lub, CORRECTED, film_tables=carried)
    message = str(refused.value)
    assert "carries the film tables of B7214C with iso_vg68_mineral, not of bearing '6306'" in message
    assert "parameters bearing and lubricant" in message and "spindle film-table 6306" in message


def test_the_fmu_hands_its_models_the_tables_in_its_resources(tmp_path, monkeypatch):
    """A bearing FMU's models get resources/film_tables: the table there serves (the cache is empty), and a bearing it
    carries no table of is refused at initialisation (fmi2Error) with the model's message."""
    from bearing_fmu.fmu import BearingQuasiStatic

    monkeypatch.setenv("BEARING_FMU_CACHE", str(tmp_path / "cache"))
    b, lub = load_bearing("B7214C"), load_lubricant("iso_vg68_mineral")
    array = write_made_up_table(b, lub, tmp_path / ft.CARRIED_DIR / ft.carried_name(b, lub))
    corrected = type("CorrectedBearing", (BearingQuasiStatic,), {"scene": CORRECTED})
    slave = corrected(instance_name="corrected", resources=str(tmp_path))
    assert slave.exit_initialization_mode() is True
    assert np.array_equal(slave._model.cp[ck.CP_FILM_TABLE :], array)
    other = corrected(instance_name="other", resources=str(tmp_path))
    other.bearing = "6306"
    assert other.exit_initialization_mode() is False
    assert any("carries the film tables of B7214C" in m.msg for m in other.log_queue)


FIDELITIES = (
    (AnalyticModel, "analytic", lambda m: m.brg[radial_bearing.B_FILM_TABLE :]),
    (QuasiStaticModel, "quasi_static", lambda m: m.cp[ck.CP_FILM_TABLE :]),
    (DemModel, "dem", lambda m: m.par[s.P_FILM_TABLE :]),
)


@pytest.mark.parametrize("model, fidelity, table_of", FIDELITIES, ids=[f[1] for f in FIDELITIES])
def test_every_fidelity_reads_the_table_of_its_scene(model, fidelity, table_of, tmp_path, monkeypatch):
    """The scene option on: the model's kernel array carries the cached table, or the model is refused naming the
    command; off (the default): the table slots are off and no table is looked for."""
    monkeypatch.setenv("BEARING_FMU_CACHE", str(tmp_path))
    b, lub = load_bearing("6208"), load_lubricant("iso_vg68_mineral")
    on = Scene(name="corrected", fidelity=fidelity, film_correction="table")
    with pytest.raises(ft.FilmTableMissing, match="spindle film-table 6208"):
        model(b, lub, on)
    assert not table_of(model(b, lub, Scene(name="plain", fidelity=fidelity))).any()
    array = write_made_up_table(b, lub)
    assert np.array_equal(table_of(model(b, lub, on)), array)


def test_film_table_command_builds_and_names_the_file(tmp_path, monkeypatch, capsys):
    """`spindle film-table` passes bearing, lubricant and --jobs to the build (here one that writes the made-up
    table instead of solving) and prints where the table went."""
    monkeypatch.setenv("BEARING_FMU_CACHE", str(tmp_path))
    calls = []

    def build(bearing, lubricant, jobs, log):
        calls.append((bearing, lubricant, jobs, log))
        b, lub = load_bearing(bearing), load_lubricant(lubricant)
        write_made_up_table(b, lub)
        return ft.load_film_table(b, lub)

    monkeypatch.setattr(ftb, "build_film_table", build)
    assert main(["film-table", "6208", "--lubricant", "iso_vg68_mineral", "--jobs", "2"]) == 0
    assert calls == [("6208", "iso_vg68_mineral", 2, True)]
    path = ft.table_path(load_bearing("6208"), load_lubricant("iso_vg68_mineral"))
    assert str(path) in capsys.readouterr().out and path.is_file()
