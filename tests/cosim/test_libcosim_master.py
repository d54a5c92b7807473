"""spindle.cosim.libcosim_master: the libcosim (libcosimpy) master against an fmpy loop of the same algorithm.

The FMUs run the same code under both masters, so every recorded value must agree to 1e-12 (in
practice bit for bit): a difference would be a transport bug (wrong variable, type, order or timing).
The fmpy loop `fmpy_jacobi` below is libcosim's fixed-step algorithm as documented in
spindle/cosim/libcosim_master.py (Jacobi; connected inputs initialised by N read/set rounds in
initialisation mode, then from the sources' outputs after exitInitializationMode).

The libcosim runs are in-process: libcosim calls the pythonfmu FMUs from its worker thread, which
takes the GIL, and run_libcosim destroys the execution before returning. 30 consecutive fresh
processes exited 0 when this was written; `test_fresh_processes_exit_0` keeps checking a few.
"""

import os
import re
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("libcosimpy", reason="libcosimpy not installed (optional extra 'cosim')")

from fmpy import extract, read_model_description  # noqa: E402
from fmpy.fmi2 import FMU2Slave  # noqa: E402

from spindle.cosim.libcosim_master import LibcosimError, cross_check, libcosim_version, run_libcosim  # noqa: E402
from tests.cosim.conftest import build_test_fmu  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


# -- the same algorithm with fmpy --------------------------------------------------------------
class _Instance:
    def __init__(self, name, path):
        self.md = read_model_description(str(path))
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.unzip = extract(str(path))
        self.fmu = FMU2Slave(
            guid=self.md.guid,
            unzipDirectory=self.unzip,
            instanceName=name,
            modelIdentifier=self.md.coSimulation.modelIdentifier,
        )
        self.fmu.instantiate()

    def get(self, name):
        var = self.vars[name]
        return getattr(self.fmu, f"get{var.type}")([var.valueReference])[0]

    def set(self, name, value):
        var = self.vars[name]
        value = value.decode() if isinstance(value, bytes) else value
        getattr(self.fmu, f"set{var.type}")([var.valueReference], [value])

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
        shutil.rmtree(self.unzip, ignore_errors=True)


def fmpy_jacobi(system, step, stop, record):
    """libcosim's fixed-step algorithm, re-implemented with fmpy (see the module docstring)."""
    inst = {name: _Instance(name, spec["fmu"]) for name, spec in system["instances"].items()}
    conns = [(s.split(".", 1), t.split(".", 1)) for s, t in system.get("connections", [])]

    def transfer():  # Jacobi: read every source, then set every target
        values = [inst[si].get(sv) for (si, sv), _ in conns]
        for ((_, _), (ti, tv)), value in zip(conns, values):
            inst[ti].set(tv, value)

    def row(t):
        return (t, *[inst[i].get(v) for i, v in (n.split(".", 1) for n in record)])

    try:
        for name, spec in system["instances"].items():
            inst[name].fmu.setupExperiment(startTime=0.0)
            inst[name].fmu.enterInitializationMode()
            for key, value in {**spec.get("parameters", {}), **spec.get("inputs", {})}.items():
                inst[name].set(key, value)
        for _ in range(len(inst)):
            transfer()
        for i in inst.values():
            i.fmu.exitInitializationMode()
        rows = [row(0.0)]
        transfer()
        ticks = round(step * 1e9)
        for n in range(round(stop / step)):
            for i in inst.values():
                i.fmu.doStep(n * ticks / 1e9, step)
            rows.append(row((n + 1) * ticks / 1e9))
            transfer()
    finally:
        for i in inst.values():
            i.close()
    return {name: np.array([r[k] for r in rows], dtype=float) for k, name in enumerate(["time", *record])}


def assert_same(result, reference, names, rtol=1e-12):
    for name in ["time", *names]:
        a, b = np.asarray(result[name], float), np.asarray(reference[name], float)
        assert a.shape == b.shape, name
        np.testing.assert_allclose(a, b, rtol=rtol, atol=0, err_msg=name)


# -- fixtures ----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def probe_fmu(tmp_path_factory):
    """ProbeSlave.fmu built from tests/cosim/probe_slave.py."""
    return build_test_fmu("probe_slave.py", "ProbeSlave", tmp_path_factory)


ANALYTIC_OUTPUTS = [
    "Lambda_inner",
    "Lambda_outer",
    "h_min_inner",
    "h_min_outer",
    "C_bearing",
    "Q_max_inner",
    "p_max",
    "omega_cage",
    "omega_ball",
    "y",
    "epsilon",
    "regime",
    "n_loaded",
]


# -- tests -------------------------------------------------------------------------------------
def test_version():
    assert libcosim_version() == "0.11.2"  # the algorithm notes in spindle/cosim/libcosim_master.py are for it


def test_analytic_fmu_same_as_fmpy(analytic_fmu):
    system = {
        "instances": {
            "b": {
                "fmu": str(analytic_fmu),
                "parameters": {"bearing": "6208", "lubricant": "guessasma_oil", "Pd": 0.0},
                "inputs": {"omega": 500.0, "F_y": 3000.0, "T_oil": 313.15},
            }
        }
    }
    record = [f"b.{o}" for o in ANALYTIC_OUTPUTS] + ["b.omega"]
    result = run_libcosim(system, 0.1, 0.5, record)
    assert result["time"].tolist() == pytest.approx([0.0, 0.1, 0.2, 0.3, 0.4, 0.5], abs=1e-15)
    assert result["b.omega_cage"][0] == pytest.approx(198.0198, rel=1e-6)  # 6208 pure-rolling cage speed
    assert result["b.regime"].dtype.kind == "i"
    assert_same(result, fmpy_jacobi(system, 0.1, 0.5, record), record)


def test_parameters_of_every_type_reach_the_fmu(bearing_fmu):
    """Bearing.fmu: String bearing/lubricant/race_control, Boolean Pd_from_file, Real Pd and inputs."""
    base = {"bearing": "B7214C", "lubricant": "iso_vg68_mineral"}
    inputs = {"omega": 1047.2, "F_z": 800.0, "F_y": 200.0}
    record = ["b.torque", "b.Q_max_inner", "b.alpha_inner", "b.Lambda_inner", "b.n_loaded"]
    changed = {**base, "race_control": "hybrid", "Pd_from_file": False, "Pd": -5e-6}
    system = {"instances": {"b": {"fmu": str(bearing_fmu), "parameters": changed, "inputs": inputs}}}
    result = run_libcosim(system, 1.0, 3.0, record)
    assert_same(result, fmpy_jacobi(system, 1.0, 3.0, record), record)
    default = fmpy_jacobi(
        {"instances": {"b": {"fmu": str(bearing_fmu), "parameters": base, "inputs": inputs}}}, 1.0, 3.0, record
    )
    assert result["b.torque"][-1] != default["b.torque"][-1]  # the String/Boolean/Real parameters took effect


def test_coupled_instances_jacobi_same_as_fmpy(analytic_fmu):
    """A's cage speed drives B; B's ball load loads A. Connected inputs start from the sources'
    initialisation-mode outputs (A's initial F_y = 3000 is overwritten by B's Q_max_inner at
    instantiation, 0) and then lag their sources by one step (Jacobi)."""
    fmu = str(analytic_fmu)
    system = {
        "instances": {
            "A": {"fmu": fmu, "inputs": {"omega": 500.0, "F_y": 3000.0}},
            "B": {"fmu": fmu, "inputs": {"F_y": 2000.0}},
        },
        "connections": [("A.omega_cage", "B.omega"), ("B.Q_max_inner", "A.F_y")],
    }
    record = [
        "A.F_y",
        "A.Q_max_inner",
        "A.omega_cage",
        "A.Lambda_inner",
        "B.omega",
        "B.omega_cage",
        "B.Q_max_inner",
        "B.Lambda_inner",
        "B.C_bearing",
    ]
    result = run_libcosim(system, 0.5, 3.0, record)
    assert_same(result, fmpy_jacobi(system, 0.5, 3.0, record), record)
    assert result["A.F_y"][0] == 0.0 and result["B.omega"][0] == 0.0
    np.testing.assert_array_equal(result["B.omega"][1:], result["A.omega_cage"][:-1])  # one-step lag
    np.testing.assert_array_equal(result["A.F_y"][1:], result["B.Q_max_inner"][:-1])
    _, errors = cross_check(system, 0.5, 3.0, record, fmpy_jacobi(system, 0.5, 3.0, record), rtol=1e-12)
    assert max(errors.values()) <= 1e-12


def test_algorithm_semantics_with_probe(probe_fmu):
    """Pins the algorithm the module docstring describes (y = u + 1 live; x += u*H; u starts at 7)."""
    p = str(probe_fmu)
    names = ("u", "y", "x", "n_set", "n_set_init", "n_set_inst")
    # loop A <-> B, A.u given 10: init rounds (N = 2) set A.u 10 -> 8 -> 12 and B.u 11 -> 9;
    # after exit: transfer B.u := 13, A.u := 10; steps are Jacobi
    loop = {
        "instances": {"A": {"fmu": p, "inputs": {"u": 10.0}}, "B": {"fmu": p}},
        "connections": [("A.y", "B.u"), ("B.y", "A.u")],
    }
    record = [f"{i}.{n}" for i in "AB" for n in names]
    r = run_libcosim(loop, 0.5, 1.5, record)
    assert r["A.u"].tolist() == [12.0, 10.0, 14.0, 12.0]
    assert r["B.u"].tolist() == [9.0, 13.0, 11.0, 15.0]
    assert r["A.x"].tolist() == [0.0, 5.0, 12.0, 18.0]
    assert r["A.n_set_inst"].tolist() == [0, 0, 0, 0]  # nothing set before enterInitializationMode
    assert r["A.n_set_init"][0] == 3 and r["B.n_set_init"][0] == 2  # initial value + N rounds
    assert_same(r, fmpy_jacobi(loop, 0.5, 1.5, record), record)
    # chain A -> B -> C: the N = 3 rounds carry A's initial value through the chain before t = 0
    chain = {
        "instances": {"A": {"fmu": p, "inputs": {"u": 10.0}}, "B": {"fmu": p}, "C": {"fmu": p}},
        "connections": [("A.y", "B.u"), ("B.y", "C.u")],
    }
    record = [f"{i}.{n}" for i in "ABC" for n in names]
    r = run_libcosim(chain, 0.5, 1.0, record)
    assert r["C.u"].tolist() == [12.0, 12.0, 12.0] and r["C.n_set_init"][0] == 3
    assert_same(r, fmpy_jacobi(chain, 0.5, 1.0, record), record)


def test_errors_name_instance_and_variable(analytic_fmu):
    fmu = str(analytic_fmu)
    with pytest.raises(LibcosimError, match=r"b\.nope: no such variable"):
        run_libcosim({"instances": {"b": {"fmu": fmu, "inputs": {"nope": 1.0}}}}, 0.1, 0.2, ["b.y"])
    with pytest.raises(LibcosimError, match=r"c\.y: no such instance"):
        run_libcosim({"instances": {"b": {"fmu": fmu}}}, 0.1, 0.2, ["c.y"])
    for source, refusal in (("b.regime", "types differ"), ("b.omega", "cannot connect")):
        two = {"instances": {"b": {"fmu": fmu}, "c": {"fmu": fmu}}, "connections": [(source, "c.omega")]}
        with pytest.raises(LibcosimError, match=rf"{re.escape(source)} -> c\.omega: {refusal}"):
            run_libcosim(two, 0.1, 0.2, ["b.y"])
    with pytest.raises(LibcosimError, match=r"b\.omega: Real value expected"):
        run_libcosim({"instances": {"b": {"fmu": fmu, "inputs": {"omega": "100"}}}}, 0.1, 0.2, ["b.y"])
    with pytest.raises(LibcosimError, match="whole number"):
        run_libcosim({"instances": {"b": {"fmu": fmu}}}, 0.1, 0.25, ["b.y"])
    # bad input: the FMU answers fmi2Discard with a logged message; the step fails, the host survives
    with pytest.raises(LibcosimError, match="b: Step not complete"):
        run_libcosim({"instances": {"b": {"fmu": fmu, "inputs": {"T_oil": -5.0, "omega": 100.0}}}}, 0.1, 0.2, ["b.y"])
    assert run_libcosim({"instances": {"b": {"fmu": fmu}}}, 0.1, 0.1, ["b.y"]).shape == (2,)


def test_fresh_processes_exit_0(analytic_fmu, tmp_path):
    """A script that runs pythonfmu FMUs under libcosim exits 0 (no abort at exit), with a
    plain return from the script, i.e. no os._exit workaround, and leaves no libcosim extraction (in a
    temporary directory of its own: the shared one may hold other processes' extractions)."""
    own_tmp = tmp_path / "tmp"
    own_tmp.mkdir()
    env = {**os.environ, "TMPDIR": str(own_tmp)}
    script = textwrap.dedent(f"""
        import sys
        sys.path.insert(0, {str(ROOT)!r})
        from spindle.cosim.libcosim_master import run_libcosim
        r = run_libcosim({{"instances": {{"b": {{"fmu": {str(analytic_fmu)!r}, "inputs": {{"omega": 500.0}}}}}}}},
                         0.1, 0.3, ["b.omega_cage"])
        print(r["b.omega_cage"][-1])
    """)
    for _ in range(3):
        proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120, env=env)
        assert proc.returncode == 0, (proc.returncode, proc.stderr[-2000:])
        assert float(proc.stdout.split()[-1]) == pytest.approx(198.0198, rel=1e-6)
    assert list(own_tmp.glob("libcosim_*")) == []
