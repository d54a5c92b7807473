"""BearingAnalytic.fmu behaves as a well-made FMI 2.0 co-simulation FMU (docs/architecture.md, FMUs).

- fmpy.validate_fmu finds no problem; every variable has a description, every Real a unit;
- fmpy simulate_fmu (with output_interval) and a hand-written FMU2Slave loop equal the Python
  model to 1e-12 relative (same kernels in the same interpreter: only the FMI round trip and the
  float formatting of the inputs could differ, and neither may);
- bad inputs give a logged message naming the input and its range and fmi2Discard, the host
  survives and a corrected input recovers; '%' in a message cannot crash the host;
- FMU state get/set/serialise round trip is exact;
- 30 consecutive fresh-process simulations all exit 0 (no scipy/numba crash at interpreter teardown).
"""

from contextlib import ExitStack

import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

from bearing_fmu.models.analytic import AnalyticModel
from tests.fmu.harness import assert_variables_documented, close, opened, probe, refused_steps

OUTPUTS = [
    "Lambda_inner",
    "Lambda_outer",
    "h_min_inner",
    "h_min_outer",
    "regime",
    "C_bearing",
    "Q_max_inner",
    "Q_max_outer",
    "p_max",
    "omega_cage",
    "omega_ball",
    "n_loaded",
    "y",
    "epsilon",
]


def test_validate_fmu_is_clean(analytic_fmu):
    for path in sorted(analytic_fmu.parent.glob("*.fmu")):
        assert validate_fmu(str(path)) == [], path


def test_model_description_units_and_descriptions(analytic_fmu):
    md = read_model_description(str(analytic_fmu))
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    names = {v.name for v in md.modelVariables}
    assert set(OUTPUTS) <= names and {"omega", "F_y", "T_oil", "bearing", "lubricant", "Pd_from_file", "Pd"} <= names
    assert_variables_documented(md)


def _ramp():
    t = np.linspace(0.0, 2.0, 21)
    return t, 800.0 * t, 1000.0 + 1500.0 * t


def test_simulate_fmu_equals_python_model(analytic_fmu):
    t, omega, load = _ramp()
    signals = np.array(
        [(a, b, c, 333.15) for a, b, c in zip(t, omega, load)],
        dtype=[("time", float), ("omega", float), ("F_y", float), ("T_oil", float)],
    )
    res = simulate_fmu(str(analytic_fmu), stop_time=2.0, output_interval=0.1, input=signals, output=OUTPUTS)
    model = AnalyticModel()
    assert len(res) == 21
    for row in res:
        # outputs at t_n come from the step [t_(n-1), t_n] with the inputs held at t_(n-1)
        # (zero-order hold of the master); row 0 holds the initialisation with the inputs at t = 0
        n = max(int(round(row["time"] / 0.1)) - 1, 0)
        ref = model.evaluate(omega[n], load[n], 333.15)
        for name in OUTPUTS:
            assert close(float(row[name]), float(ref[name])), (row["time"], name, row[name], ref[name])


def test_hand_written_loop_equals_python_model(analytic_fmu):
    model = AnalyticModel("6208", "guessasma_oil", Pd=5e-6)
    with opened(analytic_fmu, "loop", {"Pd_from_file": False, "Pd": 5e-6}) as (fmu, vr):
        real_out = [n for n in OUTPUTS if n not in ("regime", "n_loaded")]
        for n, (w, F, T) in enumerate(
            [
                (0.0, 0.0, 313.15),
                (10.0, 10.0, 300.0),
                (-500.0, 3000.0, 313.15),
                (1700.0, 7500.0, 350.0),
                (3000.0, 500.0, 400.0),
            ]
        ):
            fmu.setReal([vr["omega"], vr["F_y"], vr["T_oil"]], [w, F, T])
            fmu.doStep(n * 0.5, 0.5)
            got = dict(zip(real_out, fmu.getReal([vr[k] for k in real_out])))
            got.update(zip(["regime", "n_loaded"], fmu.getInteger([vr["regime"], vr["n_loaded"]])))
            ref = model.evaluate(w, F, T)
            for name in OUTPUTS:
                assert close(got[name], ref[name]), (w, F, T, name, got[name], ref[name])


def test_state_round_trip_is_exact(analytic_fmu):
    with opened(analytic_fmu, "state") as (fmu, vr):
        real_out = [vr[n] for n in OUTPUTS if n not in ("regime", "n_loaded")]
        fmu.setReal([vr["omega"], vr["F_y"]], [500.0, 3000.0])
        fmu.doStep(0.0, 1.0)
        saved_values = fmu.getReal(real_out)
        state = fmu.getFMUstate()
        blob = fmu.serializeFMUstate(state)
        fmu.setReal([vr["omega"], vr["F_y"]], [1200.0, 6000.0])
        fmu.doStep(1.0, 1.0)
        assert fmu.getReal(real_out) != saved_values
        fmu.setFMUstate(state)
        assert fmu.getReal(real_out) == saved_values
        assert fmu.getReal([vr["omega"], vr["F_y"]]) == [500.0, 3000.0]
        fmu.setReal([vr["omega"]], [50.0])
        fmu.setFMUstate(fmu.deSerializeFMUstate(blob))
        assert fmu.getReal(real_out) == saved_values
        fmu.doStep(1.0, 1.0)  # stepping from the restored state reproduces the saved result
        assert fmu.getReal(real_out) == saved_values
        fmu.freeFMUstate(state)


def test_bad_inputs_are_reported_and_host_survives(analytic_fmu):
    report = probe(analytic_fmu, "bad_inputs")
    refused_steps(report, 0)
    texts = [m["message"] for m in report["messages"]]
    assert any("omega = nan" in t and "allowed range" in t for t in texts)
    assert any("T_oil = 0.0 K" in t and "[233.15, 473.15] K" in t for t in texts)
    assert any("F_y = inf" in t for t in texts)
    assert any("material limit" in t for t in texts)
    assert all(m["status"] == 2 for m in report["messages"])  # logged with the status the step returned
    assert len(texts) == len(set(texts)) == len(report["results"]) - 1  # one message per refused step


def test_unknown_bearing_is_reported(analytic_fmu):
    report = probe(analytic_fmu, "unknown_bearing")
    assert report["init_status"] == 3  # fmi2Error from fmi2ExitInitializationMode
    assert report["status"] == 3  # the error state: no step until fmi2Reset
    assert report["recovered"] == 0  # reset and initialised with a catalogue bearing
    assert any("unknown bearing 'no_such_bearing'" in m["message"] for m in report["messages"])


def test_percent_in_message_cannot_crash_host(analytic_fmu):
    """The FMI logger takes a printf format: the FMU's layer escapes '%' to '%%' (docs/fmu_runtime.md)."""
    report = probe(analytic_fmu, "percent_in_name")
    assert report["init_status"] == 3 and report["status"] == 3
    assert any("100%%_bearing_%%s_%%d" in m["message"] for m in report["messages"])


def test_thirty_fresh_processes_exit_cleanly(analytic_fmu):
    for _ in range(30):
        report = probe(analytic_fmu, "simulate")
        assert report["status"] == 0
        assert 2.12 <= report["Lambda_outer"] <= 2.15


def test_many_instances_in_one_process(analytic_fmu):
    """Ten sequential and three simultaneous instances in one process (a closed loop holds several
    bearings). Guards the workaround for pythonfmu 0.7's extra Py_DECREF of the slave module's
    namespace at each fmi2Instantiate (docs/decisions.md), which broke the third instance."""
    for n in range(10):
        with opened(analytic_fmu, f"seq{n}"):
            pass
    with ExitStack() as stack:
        group = [stack.enter_context(opened(analytic_fmu, f"par{n}")) for n in range(3)]
        for n, (fmu, vr) in enumerate(group):
            fmu.setReal([vr["omega"], vr["F_y"]], [100.0 * (n + 1), 3000.0])
            fmu.doStep(0.0, 1.0)
        lambdas = [fmu.getReal([vr["Lambda_outer"]])[0] for fmu, vr in group]
    assert lambdas[0] < lambdas[1] < lambdas[2]  # each instance keeps its own inputs


def test_same_clearance_and_q_max_in_both_fmus_and_models(analytic_fmu, bearing_fmu):
    """One clearance rule: a deep-groove bearing with clearance (6306, P_d = 12.5 um in its file) under
    3 kN radial at rest gives through BearingAnalytic.fmu and Bearing.fmu, with their default parameters,
    exactly the Q_max of the Python models, which both use the file's clearance. The two fidelities agree
    within 2 %: the analytic one integrates a continuous ball distribution (docs/decisions.md), the
    quasi-static one sums the 8 discrete balls (1.1 % apart here; the FMU's old Pd = 0 override gave
    4.5 %)."""
    from bearing_fmu.build import SCENES_DIR
    from bearing_fmu.models.quasi_static import QuasiStaticModel
    from bearing_fmu.scene import Scene

    analytic = AnalyticModel("6306", "guessasma_oil")
    quasi = QuasiStaticModel("6306", scene=Scene.from_toml(SCENES_DIR / "quasi_static.toml"))
    assert analytic.Pd == quasi.Pd == analytic.bearing.Pd > 0.0
    q_analytic = analytic.evaluate(0.0, 3000.0, 313.15)["Q_max_inner"]
    quasi.evaluate()  # the FMU's history: its defaults at construction
    q_quasi = quasi.evaluate(F_y=3000.0)["Q_max_inner"]
    with opened(analytic_fmu, "a", {"bearing": "6306", "lubricant": "guessasma_oil"}) as (fmu, vr):
        fmu.setReal([vr["F_y"]], [3000.0])
        fmu.doStep(0.0, 0.1)
        assert fmu.getReal([vr["Q_max_inner"]])[0] == q_analytic
    with opened(bearing_fmu, "q", {"bearing": "6306"}) as (fmu, vr):
        fmu.setReal([vr["F_y"]], [3000.0])
        fmu.doStep(0.0, 0.1)
        assert fmu.getReal([vr["Q_max_inner"]])[0] == q_quasi
    assert abs(q_analytic / q_quasi - 1.0) <= 0.02
