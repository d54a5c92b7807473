"""spindle.cosim.master and spindle.cosim.runfile: the fmpy co-simulation master (docs/architecture.md, master).

Expectations come from the master's documented algorithm (spindle/cosim/master.py docstring) and, for
the coupled runs, from the Python models driven by hand with the same algorithm: the FMUs run the
same model code in this interpreter, so a master that transfers the right values at the right
moments reproduces a hand-written co-simulation of the models bit for bit (no tolerance: any
difference is a transport or ordering error). Only documented, exact properties are asserted here;
the physics of the closed loop is in test_closed_loop.py.

ClockSlave.fmu (tests/cosim/clock_slave.py) shows the doStep times and step sizes the master
uses and refuses steps on demand. Some tests drive Master's own stepping methods (_initialise,
_macro_step, _values) to replay a given time grid: that is the definition of "the same run on that
grid", which no run file can express.
"""

import csv
import math

import numpy as np
import pytest

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from spindle.cosim.master import Master, MasterError, read_csv, run
from spindle.cosim.runfile import RunFileError, parse_run
from spindle.thermal.model import SpindleThermalModel

OMEGA = 1047.1975511965977  # rad/s, 10 000 rpm (runs/closed_loop_spring.toml)
BEARING_INPUTS = {"omega": OMEGA, "F_z": 800.0}
SPINDLE_INPUTS = {"omega": OMEGA, "T_ambient": 293.15, "T_coolant": 293.15, "P_motor": 0.0}
LOOP = [
    ("bearing_1.Q_inner_ring", "spindle.Q_inner_ring_1"),
    ("bearing_1.Q_outer_ring", "spindle.Q_outer_ring_1"),
    ("spindle.T_oil_1", "bearing_1.T_oil"),
    ("spindle.dPd_thermal_1", "bearing_1.dPd_thermal"),
]
RECORD = [
    "spindle.Q_inner_ring_1",
    "spindle.Q_outer_ring_1",
    "bearing_1.T_oil",
    "bearing_1.dPd_thermal",
    "bearing_1.torque",
    "bearing_1.z",
    "bearing_1.alpha_outer",
    "spindle.T_inner_ring_1",
    "spindle.T_outer_ring_1",
    "spindle.T_shaft",
    "spindle.T_housing",
    "spindle.P_out",
    "spindle.E_stored",
]


def loop_doc(bearing, spindle, **run):
    """One bearing (Bearing.fmu) and the spindle (SpindleThermal.fmu) in a closed thermal loop: the
    bearing's ring heats go to the spindle, the spindle's oil temperature and clearance change go
    back (bearing 2's heat inputs stay 0)."""
    return {
        "run": {"stop": 40.0, "step": 5.0, "order": ["bearing_1", "spindle"], "record": list(RECORD), **run},
        "fmus": {"bearing": str(bearing), "spindle": str(spindle)},
        "instances": {
            "bearing_1": {"fmu": "bearing", "inputs": dict(BEARING_INPUTS)},
            "spindle": {"fmu": "spindle", "inputs": dict(SPINDLE_INPUTS)},
        },
        "connections": [{"from": s, "to": t} for s, t in LOOP],
    }


def spec_of(doc, overrides=None):
    return parse_run(doc, "/nonexistent/test_run.toml", overrides)  # FMU paths in the docs are absolute


# -- run-file errors ---------------------------------------------------------------------------
def _unknown_instance(doc):
    doc["connections"][0]["from"] = "bearing_9.Q_inner_ring"


def _twice(doc):
    doc["connections"].append({"from": "bearing_1.Q_outer_ring", "to": "spindle.Q_inner_ring_1"})


def _two_problems(doc):
    doc["run"]["algorithm"] = "newton"
    doc["run"]["stop"] = 41.0


@pytest.mark.parametrize(
    "mutate,message",
    [
        (
            _unknown_instance,
            r"connection \('bearing_9\.Q_inner_ring', 'spindle\.Q_inner_ring_1'\): "
            r"unknown instance 'bearing_9'",
        ),
        (
            lambda d: d["run"].update(algorithm="newton"),
            r"run\.algorithm = 'newton': allowed \['gauss_seidel', 'jacobi'\]",
        ),
        (
            lambda d: d["run"].update(stop=41.0),
            r"run\.stop - run\.start = 41\.0 s is not a whole number of steps of 5\.0 s",
        ),
        (_twice, r"input spindle\.Q_inner_ring_1 is connected twice"),
        (lambda d: d["run"].update(stpo=10.0), r"\[run\]: unknown key\(s\) \['stpo'\]"),
        (lambda d: d.update(instance={}), r"the run file: unknown key\(s\) \['instance'\]"),
        (
            lambda d: d["instances"]["spindle"].update(fmu="spindel"),
            r"instance spindle: fmu = 'spindel' is not in \[fmus\]",
        ),
        (lambda d: d["run"].update(order=["bearing_1"]), r"run\.order = \['bearing_1'\] must list every instance once"),
        (
            lambda d: d["run"]["record"].append("spindle_T_shaft"),
            r"'spindle_T_shaft' must be written 'instance\.variable'",
        ),
        (lambda d: d["run"].update(max_change={"spindle.T_shaft": 1.0}), r"run\.max_change needs run\.rollback = true"),
        (_two_problems, r"run\.algorithm = 'newton'.*; run\.stop - run\.start = 41\.0 s"),  # every problem at once
    ],
)
def test_run_file_errors_name_the_key(mutate, message, bearing_fmu, spindle_thermal_fmu):
    doc = loop_doc(bearing_fmu, spindle_thermal_fmu)
    spec_of(doc)  # the unmodified document is valid
    mutate(doc)
    with pytest.raises(RunFileError, match=message):
        spec_of(doc)


def test_an_array_connection_is_one_per_element(bearing_fmu, spindle_thermal_fmu, spindle_shaft_fmu):
    """shape = [5, 5] connects K[i,j] to K_1[i,j] for i, j in 1..5 (FMI's structured names, indices from 1)."""
    doc = {
        "run": {"stop": 10.0, "step": 5.0},
        "fmus": {"bearing": str(bearing_fmu), "shaft": str(spindle_shaft_fmu)},
        "instances": {"bearing_1": {"fmu": "bearing"}, "shaft": {"fmu": "shaft"}},
        "connections": [{"from": "bearing_1.K", "to": "shaft.K_1", "shape": [5, 5]}],
    }
    pairs = spec_of(doc).connections
    assert len(pairs) == 25 and pairs[0] == ("bearing_1.K[1,1]", "shaft.K_1[1,1]")
    assert pairs[7] == ("bearing_1.K[2,3]", "shaft.K_1[2,3]") and pairs[-1] == ("bearing_1.K[5,5]", "shaft.K_1[5,5]")
    doc["connections"][0]["shape"] = [5, 0]
    with pytest.raises(RunFileError, match=r"bearing_1\.K -> shaft\.K_1: shape = \[5, 0\]; allowed \[n\] or"):
        spec_of(doc)


def test_bad_override_names_the_key(bearing_fmu, spindle_thermal_fmu):
    with pytest.raises(RunFileError, match=r"override 'bearing_9\.F_z'.*instances: \['bearing_1', 'spindle'\]"):
        spec_of(loop_doc(bearing_fmu, spindle_thermal_fmu), {"bearing_9.F_z": 1.0})


@pytest.mark.parametrize(
    "source,target,message",
    [
        ("bearing_1.Q_inner_ring", "bearing_1.torque", r"bearing_1\.torque is a output, not an input"),
        ("bearing_1.omega", "spindle.Q_inner_ring_2", r"bearing_1\.omega is a input, not an output"),
        ("bearing_1.Q_inner_ring", "spindle.nope", r"spindle: no variable 'nope'"),
    ],
)
def test_connection_errors_name_the_variable(source, target, message, bearing_fmu, spindle_thermal_fmu):
    """Causality is only known from the modelDescription: the master checks it when it wires the run
    (before any step), and frees what it instantiated."""
    doc = loop_doc(bearing_fmu, spindle_thermal_fmu)
    doc["connections"].append({"from": source, "to": target})
    with pytest.raises(MasterError, match=message):
        Master(spec_of(doc))


# -- Gauss-Seidel and Jacobi, derived from the models --------------------------------------------
def hand_cosimulation(algorithm, step, n_steps):
    """The master's documented algorithm applied by hand to the Python models of the two FMUs.

    FMU life cycle (bearing_fmu/fmu.py, spindle/thermal/fmu.py): at instantiation each FMU computes its outputs
    from the input start values (these are the 'start values' a master reads in initialisation mode);
    at exitInitializationMode the bearing evaluates its inputs again (same model object: its solver
    warm-starts from the previous solution, so the order of evaluations matters to the last bit) and
    the spindle builds a fresh model initialised with its inputs; each doStep evaluates the bearing /
    steps the spindle with the inputs held.
    Master (spindle/cosim/master.py): Gauss-Seidel exits in `order` (bearing first, with the spindle's start
    values; then the spindle with the bearing's outputs after its exit); each step the bearing takes
    the spindle's outputs of t_n, the spindle the bearing's outputs of t_(n+1). Jacobi gives every
    connected input its source's start value, exits all; each step every instance takes the outputs
    of t_n."""
    bearing = QuasiStaticModel(scene=Scene.from_toml(SCENES_DIR / "quasi_static.toml"))
    b_in = {v.name: v.start for v in bearing.inputs}
    b_start = bearing.evaluate(**b_in)  # instantiation
    probe = SpindleThermalModel(axial_float=False)
    s_in = {v.name: v.start for v in probe.inputs}
    s_start = probe.initialize(**s_in)  # instantiation

    def to_bearing(s_out):
        b_in.update(T_oil=s_out["T_oil_1"], dPd_thermal=s_out["dPd_thermal_1"])

    def to_spindle(b_out):
        s_in.update(Q_inner_ring_1=b_out["Q_inner_ring"], Q_outer_ring_1=b_out["Q_outer_ring"])

    b_in.update(BEARING_INPUTS)
    s_in.update(SPINDLE_INPUTS)
    to_bearing(s_start)  # both algorithms: spindle start values
    b_out = bearing.evaluate(**b_in)  # bearing exits initialisation
    to_spindle(b_out if algorithm == "gauss_seidel" else b_start)
    spindle = SpindleThermalModel(axial_float=False)
    s_out = spindle.initialize(**s_in)  # spindle exits initialisation

    def row():
        values = {f"bearing_1.{k}": v for k, v in {**b_in, **b_out}.items()}
        values.update({f"spindle.{k}": v for k, v in {**s_in, **s_out}.items()})
        return {name: values[name] for name in RECORD}

    rows = [row()]
    for _ in range(n_steps):
        if algorithm == "jacobi":
            to_bearing(s_out)
            to_spindle(b_out)
            b_out = bearing.evaluate(**b_in)
            s_out = spindle.step(step, **s_in)
        else:
            to_bearing(s_out)
            b_out = bearing.evaluate(**b_in)
            to_spindle(b_out)
            s_out = spindle.step(step, **s_in)
        rows.append(row())
    return {name: np.array([r[name] for r in rows]) for name in RECORD}


@pytest.fixture(scope="module")
def gs_and_jacobi(bearing_fmu, spindle_thermal_fmu):
    doc = loop_doc(bearing_fmu, spindle_thermal_fmu)
    return {alg: run(spec_of(doc, {"run.algorithm": alg})) for alg in ("gauss_seidel", "jacobi")}


@pytest.mark.parametrize("algorithm", ["gauss_seidel", "jacobi"])
def test_master_equals_hand_cosimulation_of_the_models(algorithm, gs_and_jacobi):
    result = gs_and_jacobi[algorithm]
    expected = hand_cosimulation(algorithm, 5.0, 8)
    assert result.status == "ok" and result.rejected_steps == 0
    for name in RECORD:
        np.testing.assert_array_equal(result.columns[name], expected[name], err_msg=name)


def test_jacobi_heat_input_lags_one_step_more_than_gauss_seidel(gs_and_jacobi):
    """Order [bearing_1, spindle]. A recorded input at t_(n+1) is the value its FMU used in step n.
    Gauss-Seidel: the spindle steps with the bearing's heat of t_(n+1) (computed just before it in
    the same step); Jacobi: with the heat of t_n, one step older. The bearing comes first, so under
    both it sees the spindle's oil temperature of t_n."""
    gs, jac = gs_and_jacobi["gauss_seidel"].columns, gs_and_jacobi["jacobi"].columns
    for c in (gs, jac):
        assert np.all(np.diff(c["bearing_1.Q_inner_ring"]) != 0.0)  # the heat changes every step
        np.testing.assert_array_equal(c["bearing_1.T_oil"][1:], c["spindle.T_oil_1"][:-1])
    np.testing.assert_array_equal(gs["spindle.Q_inner_ring_1"][1:], gs["bearing_1.Q_inner_ring"][1:])
    np.testing.assert_array_equal(jac["spindle.Q_inner_ring_1"][1:], jac["bearing_1.Q_inner_ring"][:-1])
    np.testing.assert_array_equal(gs["spindle.Q_outer_ring_1"][1:], gs["bearing_1.Q_outer_ring"][1:])
    np.testing.assert_array_equal(jac["spindle.Q_outer_ring_1"][1:], jac["bearing_1.Q_outer_ring"][:-1])
    # initialisation: Gauss-Seidel hands the bearing's initialised heat to the spindle before it
    # exits; Jacobi hands it the start value (the bearing at rest: no heat)
    assert gs["spindle.Q_inner_ring_1"][0] == gs["bearing_1.Q_inner_ring"][0] > 0.0
    assert jac["spindle.Q_inner_ring_1"][0] == 0.0
    assert gs["spindle.T_inner_ring_1"][-1] != jac["spindle.T_inner_ring_1"][-1]


# -- time ----------------------------------------------------------------------------------------
def clock_doc(clock, **run):
    return {
        "run": {
            "start": 0.0,
            "stop": 3.0,
            "step": 0.1,
            "record": ["c.t_start", "c.t_end", "c.n_steps", "c.n_calls", "c.x"],
            **run,
        },
        "fmus": {"clock": str(clock)},
        "instances": {"c": {"fmu": "clock", "inputs": {"u": 1.0}}},
    }


@pytest.mark.parametrize("start", [0.0, 1.0])
def test_time_is_start_plus_n_h_from_an_integer_counter(start, clock_fmu):
    """t_n = start + n H from an integer step counter. Checked on the recorded times and on the
    currentCommunicationPoint each doStep receives: both are exactly start + n*H in floating point,
    which accumulating H would not give (the last assertion shows the difference exists)."""
    H, n = 0.1, 30
    result = run(spec_of(clock_doc(clock_fmu, start=start, stop=start + n * H)))
    expected = start + np.arange(n + 1) * H
    np.testing.assert_array_equal(result.columns["time"], expected)
    np.testing.assert_array_equal(result.columns["c.t_start"][1:], expected[:-1])  # step k starts at t_k
    assert result.columns["c.n_steps"][-1] == n
    accumulated = start + np.cumsum(np.full(n, H))
    assert np.any(accumulated != expected[1:])


# -- limits ----------------------------------------------------------------------------------------
def test_limit_stops_the_run_with_its_message(spindle_thermal_fmu):
    """The spindle alone with 1.5 kW into each inner ring: the run stops at the first communication
    point where T_inner_ring_1 exceeds 100 C, found by stepping the model with the same inputs; the
    rows up to and including that point are kept."""
    H, T_max = 10.0, 373.15
    heat = {"Q_inner_ring_1": 1500.0, "Q_inner_ring_2": 1500.0}
    doc = {
        "run": {"stop": 3600.0, "step": H, "record": ["spindle.T_inner_ring_1"]},
        "fmus": {"spindle": str(spindle_thermal_fmu)},
        "instances": {"spindle": {"fmu": "spindle", "inputs": {**SPINDLE_INPUTS, **heat}}},
        "limits": [
            {"variable": "spindle.T_housing", "max": 1000.0, "message": "never reached"},
            {"variable": "spindle.T_inner_ring_1", "max": T_max, "message": "inner ring too hot"},
        ],
    }
    model = SpindleThermalModel(axial_float=False)
    inputs = {v.name: v.start for v in model.inputs}
    inputs.update(SPINDLE_INPUTS, **heat)
    temperatures = [model.initialize(**inputs)["T_inner_ring_1"]]
    while temperatures[-1] <= T_max:
        temperatures.append(model.step(H, **inputs)["T_inner_ring_1"])
    n_stop = len(temperatures) - 1
    assert 1 < n_stop < 360  # the limit is reached within the run, after some steps

    result = run(spec_of(doc))
    assert result.status == "limit"
    assert result.message == (
        f"t = {n_stop * H:.6g} s: spindle.T_inner_ring_1 = {temperatures[-1]:.6g} "
        f"left [-inf, {T_max:.6g}]: inner ring too hot"
    )
    np.testing.assert_array_equal(result.columns["time"], np.arange(n_stop + 1) * H)
    np.testing.assert_array_equal(result.columns["spindle.T_inner_ring_1"], temperatures)


# -- refused steps ---------------------------------------------------------------------------------
def _run_refused(doc, match):
    """Running the run file `doc` raises a MasterError whose message matches the regular expression `match`."""
    with pytest.raises(MasterError, match=match):
        run(spec_of(doc))


def unknown_spindle_doc(spindle_thermal_fmu):
    """A run file of the thermal FMU with a spindle name it does not know: its initialisation fails."""
    return {
        "run": {"stop": 2.0, "step": 1.0},
        "fmus": {"spindle": str(spindle_thermal_fmu)},
        "instances": {"spindle": {"fmu": "spindle", "parameters": {"spindle": "no_such_spindle"}}},
    }


def test_refused_step_raises_with_the_fmu_log(spindle_thermal_fmu):
    """-1 MW into an inner ring is an admissible input (|Q| <= 1e7 W) but would cool the ring below
    0 K within the step: the spindle refuses the step (spindle/thermal/model.py) and the master's error
    names the instance, the call and carries the FMU's own message."""
    doc = {
        "run": {"stop": 2.0, "step": 1.0},
        "fmus": {"spindle": str(spindle_thermal_fmu)},
        "instances": {"spindle": {"fmu": "spindle", "inputs": {**SPINDLE_INPUTS, "Q_inner_ring_1": -1e6}}},
    }
    _run_refused(
        doc,
        r"spindle: doStep at t = 0 s, h = 1 s returned (Discard|Error): "
        r"\[Discard\] spindle: node \w+ would reach T = -[0-9.e+]+ K "
        r"\(non-physical\)",
    )


def test_refused_step_message_keeps_percent(clock_fmu):
    """pythonfmu logs printf formats ('%' sent as '%%'); the master shows the text as written."""
    doc = clock_doc(clock_fmu)
    doc["instances"]["c"]["parameters"] = {"fail_at": 0.5}
    _run_refused(
        doc,
        r"c: doStep at t = 0\.5 s, h = 0\.1 s returned Discard: "
        r"\[Error\] c: t = 0\.5 s >= fail_at: refused \(100% sure\)$",
    )


def test_initialisation_failure_raises_with_the_fmu_log(spindle_thermal_fmu):
    doc = unknown_spindle_doc(spindle_thermal_fmu)
    _run_refused(
        doc,
        r"spindle: initialisation failed: \[Error\] spindle: unknown spindle "
        r"'no_such_spindle'",
    )


def test_after_an_fmi_error_the_master_frees_the_instance_without_terminate(spindle_thermal_fmu):
    """FMI 2.0 allows only fmi2FreeInstance (or fmi2Reset) after a call returned fmi2Error: a master whose FMU
    failed its initialisation frees it without fmi2Terminate, so the FMU logs no call-sequence error."""
    doc = unknown_spindle_doc(spindle_thermal_fmu)
    master = Master(spec_of(doc))
    instance = master.instances["spindle"]
    with pytest.raises(MasterError, match="initialisation failed"):
        master.run()
    master.close()
    assert instance.failed
    assert instance.log and not [line for line in instance.log if "fmi2Terminate" in line]


def test_rollback_gives_up_after_max_halvings_with_the_reason(clock_fmu):
    doc = clock_doc(clock_fmu, rollback=True, max_halvings=2)
    doc["instances"]["c"]["parameters"] = {"fail_at": 0.5}
    _run_refused(
        doc,
        r"step at t = 0\.5 s rejected after 2 halvings \(h = 0\.025 s\): "
        r"c: doStep .* refused \(100% sure\)",
    )


# -- rollback ----------------------------------------------------------------------------------------
class GridMaster(Master):
    """Master that records every (t, h) it steps and the max_change verdict on it."""

    def __init__(self, spec):
        self.attempts, self.verdicts = [], []
        super().__init__(spec)

    def _macro_step(self, t, h):
        self.attempts.append((t, h))
        super()._macro_step(t, h)

    def _too_big_change(self, before):
        reason = super()._too_big_change(before)
        self.verdicts.append(reason is None)
        return reason

    def accepted_grid(self):
        assert len(self.attempts) == len(self.verdicts)
        return [a for a, ok in zip(self.attempts, self.verdicts) if ok]


def replay(spec, grid):
    """A plain (no rollback) run of `spec` stepping the given (t, h) grid: the recorded values at the
    points t + h that are multiples of spec.step, and at every grid point."""
    with Master(spec) as master:
        master._initialise()
        rows = [master._values()]
        every = [rows[0]]
        for t, h in grid:
            master._macro_step(t, h)
            every.append(master._values())
            n = (t + h - spec.start) / spec.step
            if n == round(n):
                rows.append(every[-1])
    return ({q: np.array([r[q] for r in rows]) for q in rows[0]}, {q: np.array([r[q] for r in every]) for q in rows[0]})


@pytest.mark.parametrize("algorithm", ["gauss_seidel", "jacobi"])
def test_rollback_equals_a_plain_run_on_the_accepted_grid(algorithm, bearing_fmu, spindle_thermal_fmu):
    """max_change = 2 K on the oil temperature at H = 5 s: the first steps of the warm-up change it by
    far more (tens of K), so they are rejected, restored and redone in halves (more than once at the
    start); later steps pass whole. What is exactly true: the run equals a plain run stepping the
    accepted sub-steps, bit for bit, for either algorithm, because setFMUstate restores each FMU
    completely (the bearing's warm-start solver state included, test_bearing_quasistatic_fmu) and the
    master restores its output cache. A rejected attempt leaves no trace."""
    doc = loop_doc(
        bearing_fmu,
        spindle_thermal_fmu,
        algorithm=algorithm,
        rollback=True,
        max_change={"spindle.T_oil_1": 2.0},
        max_halvings=6,
    )
    spec = spec_of(doc)
    with GridMaster(spec) as master:
        result = master.run()
        grid = master.accepted_grid()
    steps = [h for _, h in grid]
    assert result.status == "ok" and result.rejected_steps > 0
    assert result.rejected_steps == len(master.attempts) - len(grid)
    assert min(steps) < 2.5 and max(steps) == 5.0  # some steps halved (some twice), some whole
    assert sum(steps) == spec.stop
    plain, every = replay(
        spec_of(loop_doc(bearing_fmu, spindle_thermal_fmu, algorithm=algorithm, record=RECORD + ["spindle.T_oil_1"])),
        grid,
    )
    for name in RECORD + ["spindle.T_oil_1"]:
        np.testing.assert_array_equal(result.columns[name], plain[name], err_msg=name)
    assert np.max(np.abs(np.diff(every["spindle.T_oil_1"]))) <= 2.0  # every accepted sub-step obeys max_change


@pytest.mark.parametrize("algorithm", ["gauss_seidel", "jacobi"])
def test_rollback_halving_every_step_equals_the_run_at_half_the_step(
    algorithm, bearing_fmu, spindle_thermal_fmu, clock_fmu
):
    """A clock instance that refuses steps longer than H/2 makes the master halve every step exactly
    once: the coupled run then equals the plain run at H/2 read at the multiples of H, bit for bit
    (both algorithms: the halves re-exchange the coupling variables at t + H/2 exactly as the run at
    H/2 does). It differs from the run at H (the coupling variables are held for H there)."""

    def doc(step, h_max, rollback):
        d = loop_doc(
            bearing_fmu,
            spindle_thermal_fmu,
            algorithm=algorithm,
            step=step,
            rollback=rollback,
            max_halvings=1,
            order=["bearing_1", "spindle", "c"],
        )
        d["fmus"]["clock"] = str(clock_fmu)
        d["instances"]["c"] = {"fmu": "clock", "parameters": {"h_max": h_max}}
        d["run"]["record"] += ["c.n_steps", "c.n_calls", "c.t_start"]
        return spec_of(d)

    halved = run(doc(5.0, 2.5, True))
    at_half = run(doc(2.5, 2.5, False))
    whole = run(doc(5.0, 5.0, False))
    assert halved.rejected_steps == 8
    assert halved.columns["c.n_calls"][-1] == 3 * 8 and halved.columns["c.n_steps"][-1] == 16
    np.testing.assert_array_equal(halved.columns["c.t_start"][1:], np.arange(8) * 5.0 + 2.5)
    for name in RECORD:
        np.testing.assert_array_equal(halved.columns[name], at_half.columns[name][::2], err_msg=name)
    assert halved.columns["spindle.T_inner_ring_1"][-1] != whole.columns["spindle.T_inner_ring_1"][-1]


def test_rollback_on_max_change_alone_every_step_halved_once(spindle_thermal_fmu):
    """The spindle alone with 1 kW held into an inner ring, H = 2 s, max_change 1500 J on E_stored.
    Energy balance: dE = P_in h - (heat that left through the boundaries), so a whole step stores at
    most 2000 J and a half step at most 1000 J: every half step passes, and every whole step is
    rejected while less than 500 J leave per step, i.e. while P_out < 250 W (checked on the run at
    H/2). So each step is halved exactly once and the run equals the one at H/2, bit for bit.
    With inputs held, the exponential integrator is exact, so the temperatures of the runs at H and
    H/2 agree too, but only to rounding: 1e-12 relative bounds 60 steps of the 8-mode update with a
    few ulps each (measured: 9e-15). P_out = sum G (T - T_b) is not compared that way: the difference
    T - T_b (under 1 K early on, for T ~ 300 K) amplifies the same rounding ~300 times."""
    doc = {
        "run": {"stop": 120.0, "step": 2.0, "record": ["spindle.T_inner_ring_1", "spindle.T_housing", "spindle.P_out"]},
        "fmus": {"spindle": str(spindle_thermal_fmu)},
        "instances": {"spindle": {"fmu": "spindle", "inputs": {**SPINDLE_INPUTS, "Q_inner_ring_1": 1000.0}}},
    }
    at_half = run(spec_of(doc, {"run.step": 1.0}))
    assert np.all(at_half.columns["spindle.P_out"] < 250.0)
    halved = run(spec_of(doc, {"run.rollback": True, "run.max_change": {"spindle.E_stored": 1500.0}}))
    whole = run(spec_of(doc))
    assert halved.rejected_steps == 60
    for name, values in at_half.columns.items():
        np.testing.assert_array_equal(halved.columns[name], values[::2], err_msg=name)
        if name.startswith("spindle.T_"):
            np.testing.assert_allclose(whole.columns[name], values[::2], rtol=1e-12, atol=0.0, err_msg=name)


# -- CSV -------------------------------------------------------------------------------------------
def test_csv_header_units_quoting_and_round_trip(tmp_path, bearing_fmu, spindle_thermal_fmu):
    doc = loop_doc(bearing_fmu, spindle_thermal_fmu, stop=15.0)
    doc["run"]["record"] += ["bearing_1.K[3,3]", "bearing_1.n_loaded", "bearing_1.C_bearing"]
    result = run(spec_of(doc))
    path = tmp_path / "run.csv"
    result.write_csv(path)
    text = path.read_text()
    assert '"bearing_1.K[3,3] [N/m]"' in text.splitlines()[0]  # a name with a comma is quoted
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    header = rows[0]
    assert header[0] == "time [s]"
    units = dict(h.rsplit(" [", 1) for h in header)
    assert units["spindle.T_inner_ring_1"] == "K]" and units["bearing_1.torque"] == "N.m]"
    assert units["bearing_1.C_bearing"] == "F]" and units["bearing_1.n_loaded"] == "1]"
    assert units["bearing_1.K[3,3]"] == "N/m]"
    names = list(result.columns)
    assert [h.rsplit(" [", 1)[0] for h in header] == names
    assert len(rows) == 1 + len(result.columns["time"]) == 1 + 4
    for k, name in enumerate(names):
        values = np.array([float(r[k]) for r in rows[1:]])
        np.testing.assert_array_equal(values, result.columns[name], err_msg=name)  # repr round-trips
    assert math.isfinite(result.columns["bearing_1.K[3,3]"][-1]) and result.columns["bearing_1.K[3,3]"][-1] > 0


# -- recording: interval, arrays or a streamed CSV --------------------------------------------------
def test_record_interval_keeps_every_kth_point_and_the_last(clock_fmu):
    """record_interval = 4 H over 30 steps records t = 0, 4H, ..., 28H and the last point 30H; the values
    are those of the run recorded at every step, at the same points (recording does not change the run)."""
    spec = spec_of(clock_doc(clock_fmu))  # 30 steps of 0.1 s
    every = run(spec).columns
    sparse = run(spec, record_interval=0.4)
    rows = [*range(0, 30, 4), 30]
    assert sparse.n_rows == len(rows) and sparse.n_steps == 30
    for name, values in every.items():
        np.testing.assert_array_equal(sparse.columns[name], values[rows], err_msg=name)


def test_record_interval_must_be_a_multiple_of_the_step(clock_fmu):
    with pytest.raises(MasterError, match="record interval 0.25 s is not a whole multiple of the step 0.1 s"):
        run(spec_of(clock_doc(clock_fmu)), record_interval=0.25)


def test_streamed_csv_equals_the_recorded_columns_and_keeps_none_in_memory(tmp_path, clock_fmu):
    """csv_path streams the rows as the run goes: the file holds exactly the rows (repr floats round-trip)
    and units of the in-memory recording, the result keeps no columns, and write_csv copies the file."""
    spec = spec_of(clock_doc(clock_fmu))
    in_memory = run(spec, record_interval=0.2)
    streamed = run(spec, record_interval=0.2, csv_path=tmp_path / "run.csv")
    assert streamed.columns == {} and streamed.n_rows == in_memory.n_rows == 16
    columns, units = read_csv(tmp_path / "run.csv")
    assert list(columns) == list(in_memory.columns) and units == in_memory.units
    for name, values in in_memory.columns.items():
        np.testing.assert_array_equal(columns[name], values, err_msg=name)
    in_memory.write_csv(tmp_path / "memory.csv")
    streamed.write_csv(tmp_path / "copy.csv")
    assert (tmp_path / "copy.csv").read_bytes() == (tmp_path / "memory.csv").read_bytes()


def test_a_csv_with_unquoted_structured_names_reads_into_the_right_columns(tmp_path):
    """Some native masters write FMI structured names such as K[1,2] unquoted into a CSV header; the product's
    readers (read_csv, spindle check's reference_table) join the halves a plain CSV reader makes of them, so
    every later column keeps its values."""
    from spindle.check import reference_table

    path = tmp_path / "native.csv"
    path.write_text("time,K[1,1],K[1,2],torque\n0,1.5,2.5,3.5\n1,4.5,5.5,6.5\n")
    names, table = reference_table(path)
    assert names == ["time", "K[1,1]", "K[1,2]", "torque"]
    np.testing.assert_array_equal(table["K[1,2]"], [2.5, 5.5])
    np.testing.assert_array_equal(table["torque"], [3.5, 6.5])
    path.write_text("time [s],b.K[3,3] [N/m],b.torque [N.m]\n0,7.0,8.0\n")
    columns, units = read_csv(path)
    assert list(columns) == ["time", "b.K[3,3]", "b.torque"] and units["b.K[3,3]"] == "N/m"
    np.testing.assert_array_equal(columns["b.torque"], [8.0])
