"""Scene options that are off are null submodels: their work is not done and their output slots are not written.

The options reach the kernels as integer codes in the parameter arrays (CP_TORQUE, QS_STIFFNESS) or as blocks
embedded in them (models.blocks: the capacitance's CAP_*, the lubrication method's LM_*, whose "off" is the null
block). Each test
- pre-fills the outputs with a NaN sentinel: the slots of an option that is off stay NaN, every other
  slot equals (bit for bit) the run with the option on;
- counts the work: the kernel's own source (``py_func``), and that of the kernels it calls on the way to the
  option's work (PYTHON_CHAIN), runs as Python against counting wrappers of the jitted callees that do the
  option's work (numba compiles calls to its module globals, so only the Python run can be counted), and the
  callees are not called when the option is off.
"""

import math
from collections import Counter
from dataclasses import replace

import numpy as np
import pytest

from bearing_fmu.kernels import ball_traction as bt
from bearing_fmu.kernels import capacitance as cap
from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import ehl_contact, jones_harris, radial_bearing
from bearing_fmu.kernels import lubrication as lm
from bearing_fmu.kernels.ball_dynamics import state as ds
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.blocks import capacitance_block
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.lubrication import Lubrication, lubrication_block
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

RPM = 2.0 * math.pi / 60.0
OMEGA = 10000 * RPM
T_OIL = 323.15
LOADS = np.array([1000.0, 0.0, 800.0, 0.0, 0.0])
CAPACITANCE_OUT = (ck.CO_C_BEARING,)
LOSS_OUT = (ck.CO_P_LOSS, ck.CO_Q_INNER_RING, ck.CO_Q_OUTER_RING, ck.CO_TORQUE) + tuple(
    ck.CO_P_EHL + t for t in range(4)
)
DRAG_OUT = (ck.CO_P_DRAG, ck.CO_TORQUE_DRAG)  # the lubrication method's drag: part of the loss submodel
LUBRICATION_OUT = (ck.CO_PHI_ISH_I, ck.CO_PHI_ISH_O, ck.CO_PHI_RS_I, ck.CO_PHI_RS_O)
CP_CAP_ON = ck.CP_CAPACITANCE_BLOCK + cap.CAP_ON  # the capacitance block's switch in the contact array


def counting(monkeypatch, module, names, calls):
    """Replace module.<name> by a wrapper that counts its calls and calls the jitted original."""
    for name in names:
        original = getattr(module, name)

        def wrapper(*args, _name=name, _original=original):
            calls[_name] += 1
            return _original(*args)

        monkeypatch.setattr(module, name, wrapper)


# the kernels a fidelity's contact kernel calls on its way to the counted work, by the module whose name calls them
PYTHON_CHAIN = {
    ck: ("_start_sums", "_contact", "_contact_loss", "lubricated_contact", "oil_state"),
    radial_bearing: ("_ball_contacts", "_race_contact", "lubricated_contact", "oil_state"),
}


def counting_in_python(monkeypatch, module, names, calls):
    """Run module's contact kernels down to the counted work as Python (PYTHON_CHAIN), and count the calls of names
    where they are made: in module or in kernels.ehl_contact (the lubricated contact of both static fidelities)."""
    for name in PYTHON_CHAIN[module]:
        monkeypatch.setattr(module, name, getattr(module, name).py_func)
    for name in names:
        owner = module if hasattr(module, name) else ehl_contact
        counting(monkeypatch, owner, (name,), calls)


@pytest.fixture(scope="module")
def solved():
    """A solved B7214C at 10 000 rpm with every option on (an oil bath: film factors and drag): (model, balls)."""
    scene = Scene(
        name="all_on",
        fidelity="quasi_static",
        gyroscopic=True,
        torque=True,
        stiffness=True,
        capacitance=True,
        lubrication="oil_bath",
    )
    m = QuasiStaticModel("B7214C", "iso_vg68_mineral", scene)
    m.evaluate(omega=OMEGA, T_oil=T_OIL, **dict(zip(("F_x", "F_y", "F_z", "M_x", "M_y"), LOADS)))
    return m, m.balls.copy()


def contacts_run(m, balls, cp, kernel=None):
    out = np.full(ck.CO_SIZE, np.nan)
    per_contact = np.full((ck.PC_SIZE, balls.shape[1]), np.nan)
    (kernel or ck.contact_outputs)(OMEGA, T_OIL, cp, m.lubricant.array, balls, out, per_contact, np.zeros(4))
    return out, per_contact


def with_code(array, slot, value):
    array = array.copy()
    array[slot] = value
    return array


@pytest.mark.parametrize(
    "option, out_slots, rows, work",
    [
        (CP_CAP_ON, CAPACITANCE_OUT, (ck.PC_C_I, ck.PC_C_O), ("lubricated_contact_capacitance",)),
        (
            ck.CP_TORQUE,
            LOSS_OUT + DRAG_OUT,
            (ck.PC_P_I, ck.PC_P_O),
            ("contact_losses", "friction_coefficient", "ball_drag_power"),
        ),
    ],
    ids=["capacitance", "torque"],
)
def test_contact_submodel_off_skips_its_work(solved, monkeypatch, option, out_slots, rows, work):
    m, balls = solved
    on_out, on_pc = contacts_run(m, balls, with_code(m.cp, option, 1.0))
    off_out, off_pc = contacts_run(m, balls, with_code(m.cp, option, 0.0))
    assert not (np.any(np.isnan(on_out)) or np.any(np.isnan(on_pc)))  # every slot written
    assert np.all(np.isnan(off_out[list(out_slots)])) and np.all(np.isnan(off_pc[list(rows)]))
    others = [k for k in range(ck.CO_SIZE) if k not in out_slots]
    kept = [r for r in range(ck.PC_SIZE) if r not in rows]
    assert np.array_equal(off_out[others], on_out[others]) and np.array_equal(off_pc[kept], on_pc[kept])
    for code, expect_work in ((0.0, False), (1.0, True)):
        calls = Counter()
        counting_in_python(monkeypatch, ck, work, calls)
        out, _ = contacts_run(m, balls, with_code(m.cp, option, code), ck.contact_outputs.py_func)
        assert (sum(calls.values()) > 0) == expect_work, (code, calls)
        if expect_work:
            assert np.array_equal(out, on_out)  # the Python run of the source computes what the kernel does
        monkeypatch.undo()


def test_flooded_method_skips_its_work(solved, monkeypatch):
    """The flooded method is the null lubrication block: the oil bath's contact array with its block replaced by the
    flooded one (all 0) gives exactly the flooded model's outputs, leaves the method's slots unwritten and calls
    none of its kernels."""
    m, balls = solved
    flooded = QuasiStaticModel("B7214C", "iso_vg68_mineral", replace(m.scene, lubrication="flooded"))
    block = lubrication_block(flooded.lubrication_numbers)
    assert not block.any() and block.size == lm.LM_SIZE
    off_cp = m.cp.copy()
    off_cp[ck.CP_LUBRICATION_BLOCK : ck.CP_LUBRICATION_BLOCK + lm.LM_SIZE] = block
    off_out, off_pc = contacts_run(m, balls, off_cp)
    ref_out, ref_pc = contacts_run(flooded, balls, flooded.cp)
    assert np.array_equal(off_out, ref_out, equal_nan=True) and np.array_equal(off_pc, ref_pc)
    assert np.all(np.isnan(off_out[list(LUBRICATION_OUT + DRAG_OUT)]))
    work = ("film_factors", "rolling_force_factor", "temperature_viscosity_coefficient", "ball_drag_power")
    for cp, expect_work in ((off_cp, False), (m.cp, True)):
        calls = Counter()
        counting_in_python(monkeypatch, ck, work, calls)
        contacts_run(m, balls, cp, ck.contact_outputs.py_func)
        assert (sum(calls.values()) > 0) == expect_work, calls
        monkeypatch.undo()


def solve(m, qs, control=None, d0=None):
    Z = m.bearing.Z
    d = np.zeros(5) if d0 is None else d0.copy()
    X, F = np.zeros((2, Z)), np.zeros(5)
    K = np.full((5, 5), np.nan)
    balls = np.full((jones_harris.BQ_SIZE, Z), np.nan)
    control = m.control if control is None else control
    status = jones_harris.solve_quasistatic(LOADS, control, d, qs, 0.0, OMEGA, X, F, K, balls)
    assert status[0] == jones_harris.QS_OK
    return d, X, F, K, balls


@pytest.mark.parametrize("control", [(1, 1, 1, 1, 1), (0, 0, 0, 0, 0), (1, 1, 0, 1, 1)], ids=["load", "disp", "axial"])
def test_stiffness_off_leaves_K_untouched(solved, control):
    m, _ = solved
    control = np.array(control, float)
    d0 = np.array([2e-6, 0.0, 10e-6, 0.0, 1e-5])  # the imposed values of displacement-controlled DOFs
    on = solve(m, with_code(m.qs, jones_harris.QS_STIFFNESS, 1.0), control, d0)
    off = solve(m, with_code(m.qs, jones_harris.QS_STIFFNESS, 0.0), control, d0)
    assert np.all(np.isfinite(on[3])) and np.all(np.isnan(off[3]))
    for a, b in zip(on[:3] + on[4:], off[:3] + off[4:]):  # d, X, F, balls: identical
        assert np.array_equal(a, b)


@pytest.fixture
def python_newton(monkeypatch):
    """Run solve_quasistatic's Newton loop as Python, counting ring_loads (with its jacobian flag) and ball_outputs."""
    calls = Counter()
    for name in ("ring_loads", "ball_outputs"):
        original = getattr(jones_harris, name)

        def wrapper(*args, _name=name, _original=original):
            calls[_name] += 1
            if _name == "ring_loads":
                calls[f"jacobian={bool(args[8])}"] += 1  # ring_loads(..., contact, jacobian, f_load)
            return _original(*args)

        monkeypatch.setattr(jones_harris, name, wrapper)
    monkeypatch.setattr(jones_harris, "_global_newton", jones_harris._global_newton.py_func)
    monkeypatch.setattr(jones_harris, "_newton_start", jones_harris._newton_start.py_func)
    monkeypatch.setattr(jones_harris, "_loads_residual_at", jones_harris._loads_residual_at.py_func)
    return calls


def test_stiffness_off_without_load_control_assembles_no_jacobian(solved, python_newton):
    m, _ = solved
    d = np.array([2e-6, 0.0, 10e-6, 0.0, 1e-5])
    control = np.zeros(5)
    for code in (0.0, 1.0):
        python_newton.clear()
        Z = m.bearing.Z
        args = (d.copy(), with_code(m.qs, jones_harris.QS_STIFFNESS, code), 0.0, OMEGA, np.zeros((2, Z)), np.zeros(5))
        jones_harris.solve_quasistatic.py_func(
            LOADS, control, *args, np.zeros((5, 5)), np.zeros((jones_harris.BQ_SIZE, Z))
        )
        assert python_newton["ring_loads"] == 1
        assert python_newton[f"jacobian={code > 0.5}"] == 1, python_newton


def test_per_ball_outputs_computed_once_after_convergence(solved, python_newton):
    m, _ = solved
    Z = m.bearing.Z
    d, X, F, K, balls = (
        np.zeros(5),
        np.zeros((2, Z)),
        np.zeros(5),
        np.zeros((5, 5)),
        np.zeros((jones_harris.BQ_SIZE, Z)),
    )
    status, iterations, _ = jones_harris.solve_quasistatic.py_func(
        LOADS, m.control, d, m.qs, 0.0, OMEGA, X, F, K, balls
    )
    assert status == jones_harris.QS_OK and iterations >= 3
    assert python_newton["ring_loads"] >= iterations + 1  # one load evaluation per iteration at least
    assert python_newton["ball_outputs"] == 1
    # and they are those of the solution: the compiled solve from the same start gives the same rows
    reference = solve(m, m.qs, m.control)
    assert np.array_equal(balls, reference[4]) and np.array_equal(d, reference[0])


def test_analytic_capacitance_off_skips_its_work(monkeypatch):
    on = AnalyticModel("6208", "guessasma_oil", Scene(capacitance=True, lubrication="oil_bath"))
    off = AnalyticModel("6208", "guessasma_oil", Scene(capacitance=False, lubrication="oil_bath"))
    cap_on = radial_bearing.B_CAPACITANCE_BLOCK + cap.CAP_ON
    assert on.brg[cap_on] == 1.0 and off.brg[cap_on] == 0.0

    def run(m, kernel=radial_bearing.analytic_bearing):
        out = np.full(radial_bearing.O_SIZE, np.nan)
        ball = np.full((8, m.bearing.Z), np.nan)
        kernel(700.0, 3000.0, 313.0, m.brg, m.lubricant.array, m.nodes, m.weights, out, ball)
        return out, ball

    on_out, on_ball = run(on)
    off_out, off_ball = run(off)
    assert not (np.any(np.isnan(on_out)) or np.any(np.isnan(on_ball)))  # all written (unloaded: Lambda = inf)
    assert np.isnan(off_out[radial_bearing.O_C_BEARING]) and np.all(np.isnan(off_ball[6:8]))
    others = [k for k in range(radial_bearing.O_SIZE) if k != radial_bearing.O_C_BEARING]
    assert np.array_equal(off_out[others], on_out[others]) and np.array_equal(off_ball[:6], on_ball[:6])
    for m, expect_work in ((off, False), (on, True)):
        calls = Counter()
        counting_in_python(monkeypatch, radial_bearing, ("lubricated_contact_capacitance", "ball_capacitance"), calls)
        run(m, radial_bearing.analytic_bearing.py_func)
        assert (sum(calls.values()) > 0) == expect_work, calls
        monkeypatch.undo()


def test_facade_packs_the_option_codes():
    for flags in ((True, True, True), (False, False, False), (True, False, True)):
        cap, tor, stf = flags
        scene = Scene(name="codes", fidelity="quasi_static", capacitance=cap, torque=tor, stiffness=stf)
        m = QuasiStaticModel("6208", "iso_vg68_mineral", scene)
        assert (m.cp[CP_CAP_ON], m.cp[ck.CP_TORQUE], m.qs[jones_harris.QS_STIFFNESS]) == tuple(map(float, flags))


@pytest.mark.parametrize("region", ["hertz", "lubricated"])
def test_capacitance_region_packs_the_oil_gap_and_hertz_skips_the_outside_term(monkeypatch, region):
    """capacitance_region = 'hertz' packs oil gap 0 in every fidelity's array, and a 0 oil gap computes no
    outside-Hertz term; 'lubricated' packs the scene's oil_gap (m) and computes it."""
    scene = dict(capacitance_region=region, oil_gap=7e-6)
    expect = 7e-6 if region == "lubricated" else 0.0
    gap = cap.CAP_OIL_GAP
    analytic = AnalyticModel("6208", "guessasma_oil", Scene(**scene))
    assert analytic.brg[radial_bearing.B_CAPACITANCE_BLOCK + gap] == expect
    qs = QuasiStaticModel("6208", "iso_vg68_mineral", Scene(name="q", fidelity="quasi_static", **scene))
    assert qs.cp[ck.CP_CAPACITANCE_BLOCK + gap] == expect
    dem = DemModel("6208", "guessasma_oil", scene=Scene(name="d", fidelity="dem", **scene))
    assert dem.par[ds.P_CAPACITANCE_BLOCK + gap] == expect
    calls = Counter()
    counting(monkeypatch, cap, ("outside_hertz_capacitance",), calls)
    C = cap.lubricated_contact_capacitance.py_func(1.5e-4, 870.0, 1.9e9, 0, 1.5e-3, 1.6e-4, 3e-7, 1e-8, 2.3e11, expect)
    assert C > 0.0 and calls["outside_hertz_capacitance"] == (1 if expect else 0)


def test_analytic_flooded_method_skips_its_work(monkeypatch):
    """The analytic fidelity's flooded method is the null lubrication block too: the oil bath's bearing array with
    the flooded block gives the flooded model's outputs bit for bit, leaves the method's outputs unwritten and calls
    none of its kernels."""
    bath = AnalyticModel("6208", "guessasma_oil", Scene(lubrication="oil_bath"))
    flooded = AnalyticModel("6208", "guessasma_oil", Scene())
    off_brg = bath.brg.copy()
    start = radial_bearing.B_LUBRICATION_BLOCK
    off_brg[start : start + lm.LM_SIZE] = lubrication_block(flooded.lubrication_numbers)
    assert np.array_equal(off_brg, flooded.brg)

    def run(brg, kernel=radial_bearing.analytic_bearing):
        out = np.full(radial_bearing.O_SIZE, np.nan)
        ball = np.full((8, bath.bearing.Z), np.nan)
        kernel(700.0, 3000.0, 313.0, brg, bath.lubricant.array, bath.nodes, bath.weights, out, ball)
        return out, ball

    method_out = [radial_bearing.O_P_DRAG, radial_bearing.O_TORQUE_DRAG]
    method_out += list(range(radial_bearing.O_PHI_ISH_I, radial_bearing.O_PHI_RS_O + 1))
    assert np.all(np.isnan(run(off_brg)[0][method_out])) and not np.any(np.isnan(run(bath.brg)[0][method_out]))
    work = ("film_factors", "temperature_viscosity_coefficient", "ball_drag_power")
    for brg, expect_work in ((off_brg, False), (bath.brg, True)):
        calls = Counter()
        counting_in_python(monkeypatch, radial_bearing, work, calls)
        run(brg, radial_bearing.analytic_bearing.py_func)
        assert (sum(calls.values()) > 0) == expect_work, calls
        monkeypatch.undo()


def embedded(array, offset, size):
    return array[offset : offset + size]


def test_every_fidelity_embeds_the_blocks_its_options_pack():
    """Each facade writes the blocks of models.blocks at its kernel's offsets: the packing function's block with the
    option on, the null block (all 0) with it off (flooded lubrication, capacitance off, film correction 'none')."""
    on = dict(lubrication="oil_bath", capacitance=True, capacitance_region="lubricated", oil_gap=5e-6)
    off = dict(lubrication="flooded", capacitance=False)
    for options in (on, off):
        analytic = AnalyticModel("6208", "guessasma_oil", Scene(**options))
        qs = QuasiStaticModel("6208", "iso_vg68_mineral", Scene(name="q", fidelity="quasi_static", **options))
        dem_options = dict(options, lubrication="flooded")  # the DEM has no lubrication method (scene refuses one)
        dem = DemModel("6208", "guessasma_oil", scene=Scene(name="d", fidelity="dem", **dem_options))
        lubrication = Lubrication(analytic.scene, analytic.bearing.D, analytic.bearing.dm)
        blocks = (
            (analytic.brg, radial_bearing.B_LUBRICATION_BLOCK, lubrication_block(lubrication)),
            (analytic.brg, radial_bearing.B_CAPACITANCE_BLOCK, capacitance_block(analytic.scene)),
            (qs.cp, ck.CP_LUBRICATION_BLOCK, lubrication_block(qs.lubrication_numbers, qs.scene.torque)),
            (qs.cp, ck.CP_CAPACITANCE_BLOCK, capacitance_block(qs.scene)),
            (dem.par, ds.P_CAPACITANCE_BLOCK, capacitance_block(dem.scene)),
        )
        for array, offset, block in blocks:
            assert np.array_equal(embedded(array, offset, block.size), block)
            assert block.any() == (options is on)
        for array, offset in ((analytic.brg, radial_bearing.B_FILM_TABLE), (qs.cp, ck.CP_FILM_TABLE)):
            assert not array[offset:].any()  # film correction 'none': the null table
        assert not dem.par[ds.P_FILM_TABLE :].any()


def test_capacitance_off_is_the_null_block_that_skips_its_work(solved, monkeypatch):
    """The contact array of a scene without capacitance holds the null block (all 0, even the background and the oil
    gap), and with it the contacts compute no capacitance and write none."""
    m, balls = solved
    off = QuasiStaticModel("B7214C", "iso_vg68_mineral", replace(m.scene, capacitance=False))
    assert not embedded(off.cp, ck.CP_CAPACITANCE_BLOCK, cap.CAP_SIZE).any()
    out, per_contact = contacts_run(off, balls, off.cp)
    assert np.isnan(out[ck.CO_C_BEARING]) and np.all(np.isnan(per_contact[[ck.PC_C_I, ck.PC_C_O]]))
    calls = Counter()
    counting_in_python(monkeypatch, ck, ("lubricated_contact_capacitance", "ball_capacitance"), calls)
    contacts_run(off, balls, off.cp, ck.contact_outputs.py_func)
    assert sum(calls.values()) == 0, calls


def test_a_race_control_hypothesis_is_the_null_traction_block(solved, monkeypatch):
    """A race-control hypothesis packs the null traction block (all 0) and its ring loads never build the work of
    the traction kinematics (traction_work, which hands the block to them); the race control "traction" packs the
    block and builds it."""
    m, _ = solved
    traction = QuasiStaticModel("B7214C", "iso_vg68_mineral", m.scene, race_control="traction")
    traction.evaluate(omega=OMEGA, T_oil=T_OIL, **dict(zip(("F_x", "F_y", "F_z", "M_x", "M_y"), LOADS)))
    assert m.race_control != "traction" and not embedded(m.qs, jones_harris.QS_TRACTION, bt.TR_SIZE).any()
    assert embedded(traction.qs, jones_harris.QS_TRACTION, bt.TR_SIZE).any()
    Z = m.bearing.Z
    for model, expect_work in ((m, False), (traction, True)):
        calls = Counter()
        counting(monkeypatch, jones_harris, ("traction_work",), calls)
        F, K, contact = np.zeros(5), np.zeros((5, 5)), np.zeros((jones_harris.CS_SIZE, Z))
        jones_harris.ring_loads.py_func(model.d.copy(), model.qs, 0.0, OMEGA, model.X.copy(), F, K, contact, False)
        assert (calls["traction_work"] > 0) == expect_work, calls
        assert np.all(np.isfinite(F)) and F[2] != 0.0
        monkeypatch.undo()
