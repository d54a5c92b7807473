"""spindle.cosim.ssp: the run file's system as an SSP 1.0 package that libcosim loads and runs.

Expectation: the same result as the project's master with the same algorithm and step, to the bit. Both
masters run the same FMU code in this interpreter, libcosim's fixed-step algorithm is a Jacobi exchange
whose initialisation hands every connected input its source's initialisation-mode output, which is what
spindle.cosim.master's Jacobi initialisation does (tests/cosim/test_libcosim_vs_fmpy.py, which builds the
same system through libcosim's API instead of a package). So any difference would be a value the package
carries wrongly (a parameter, an input, a connection, the step); the acceptance is 1e-9 relative and the
test also asserts exact equality.
"""

import zipfile
from xml.etree import ElementTree as ET

import numpy as np
import pytest

pytest.importorskip("libcosimpy", reason="libcosimpy not installed (optional extra 'cosim')")

from spindle.cli import main  # noqa: E402
from spindle.cosim.master import MasterError, run  # noqa: E402
from spindle.cosim.runfile import load_run  # noqa: E402
from spindle.cosim.ssp import OMS, PARAMETER_SET, SSC, SSD, SSV, export_ssp, run_ssp_in_libcosim  # noqa: E402
from tests.conftest import ROOT  # noqa: E402

SPRING = ROOT / "runs" / "closed_loop_spring.toml"
# the demo runs up from rest by an input schedule, which SSP 1.0 cannot carry: exported at constant speed
AT_SPEED = {f"{name}.omega": 1047.1975511965977 for name in ("bearing_1", "bearing_2", "spindle")}


def test_package_runs_in_libcosim_equal_to_the_jacobi_master(closed_loop_fmus, tmp_path):
    spec = load_run(SPRING, {**AT_SPEED, "run.algorithm": "jacobi", "run.stop": 30.0})
    package = export_ssp(spec, tmp_path / "loop.ssp")
    master = run(spec)
    record = [name for name in master.columns if name != "time"]
    libcosim = run_ssp_in_libcosim(package, spec.step, spec.stop, record)
    np.testing.assert_array_equal(libcosim["time"], master.columns["time"])
    for name in record:
        a, b = libcosim[name], master.columns[name]
        scale = np.maximum(np.abs(a), np.abs(b))
        assert np.all(np.abs(a - b) <= 1e-9 * scale), name  # the acceptance
        np.testing.assert_array_equal(a, b, err_msg=name)
    # the loop did something: the inner rings warmed by more than 5 K in 30 s
    assert master.columns["spindle.T_inner_ring_1"][-1] > master.columns["spindle.T_inner_ring_1"][0] + 5.0


def test_input_schedules_are_refused_with_the_way_to_hold_them(closed_loop_fmus, tmp_path):
    """SSP 1.0 has no time tables: a run file with a schedule is refused, naming the scheduled inputs and the
    override that holds them constant; nothing is written."""
    with pytest.raises(MasterError) as info:
        export_ssp(load_run(SPRING), tmp_path / "loop.ssp")
    assert "bearing_1.omega" in str(info.value) and "--set" in str(info.value)
    assert not (tmp_path / "loop.ssp").exists()


def test_package_holds_each_fmu_once_the_components_values_and_connections(closed_loop_fmus, tmp_path):
    spec = load_run(SPRING, AT_SPEED)
    package = export_ssp(spec, tmp_path / "loop.ssp")
    with zipfile.ZipFile(package) as archive:
        assert sorted(archive.namelist()) == [
            "SystemStructure.ssd",
            "resources/Bearing.fmu",
            "resources/SpindleThermal.fmu",
        ]
        assert archive.read("resources/Bearing.fmu") == (ROOT / "fmus" / "Bearing.fmu").read_bytes()
        root = ET.fromstring(archive.read("SystemStructure.ssd"))
    assert root.get("version") == "1.0"
    components = {c.get("name"): c for c in root.iter(f"{{{SSD}}}Component")}
    assert list(components) == ["bearing_1", "bearing_2", "spindle"]
    assert components["bearing_2"].get("source") == "resources/Bearing.fmu"
    values = {
        p.get("name"): p[0].get("value") for p in components["spindle"].iter(f"{{{SSV}}}Parameter")
    }  # the run file's parameters and constant inputs, as written there; the network is the FMU's start value
    assert values == {"omega": "1047.1975511965977", "T_ambient": "293.15", "T_coolant": "293.15", "P_motor": "0.0"}
    # one parameter set name in every component (ecos applies a set by its name across all components)
    assert {s.get("name") for s in root.iter(f"{{{SSV}}}ParameterSet")} == {PARAMETER_SET}
    # OMSimulator's system type: its fixed-step master at the communication step
    master = root.find(f"{{{SSD}}}System/{{{SSD}}}Annotations/{{{SSC}}}Annotation")
    assert master.get("type") == "org.openmodelica"
    fixed = next(master.iter(f"{{{OMS}}}FixedStepMaster"))
    assert (fixed.get("description"), fixed.get("stepSize")) == ("oms-ma", "1.0")
    connections = [
        (f"{c.get('startElement')}.{c.get('startConnector')}", f"{c.get('endElement')}.{c.get('endConnector')}")
        for c in root.iter(f"{{{SSD}}}Connection")
    ]
    assert connections == list(spec.connections) and len(connections) == 8
    experiment = root.find(f"{{{SSD}}}DefaultExperiment")
    assert (experiment.get("startTime"), experiment.get("stopTime")) == ("0.0", "3600.0")
    assert (
        next(experiment.iter("{http://opensimulationplatform.com/SSP/OSPAnnotations}FixedStepAlgorithm")).get(
            "baseStepSize"
        )
        == "1.0"
    )


def test_refused_parameter_is_reported_before_anything_is_written(closed_loop_fmus, tmp_path, capsys):
    """A misspelled bearing name would end a libcosim process at initialisation; the export finds it first
    with the FMU's own message and writes no package (exit code 1 from the command line)."""
    out = tmp_path / "bad.ssp"
    spec = load_run(SPRING, {"bearing_2.bearing": "B7214X"})
    with pytest.raises(MasterError, match="bearing_2: initialisation failed: .*B7214X"):
        export_ssp(spec, out)
    assert not out.exists()
    assert main(["export-ssp", str(SPRING), "--set", "bearing_2.bearing=B7214X", "--out", str(out)]) == 1
    assert "B7214X" in capsys.readouterr().err and not out.exists()


def _parameters(root, component):
    """name -> (SSV type, value text) of a component's parameter set."""
    element = next(c for c in root.iter(f"{{{SSD}}}Component") if c.get("name") == component)
    return {p.get("name"): (p[0].tag.split("}")[1], p[0].get("value")) for p in element.iter(f"{{{SSV}}}Parameter")}


def test_strings_travel_as_numeric_parameters_or_stay_with_a_note(closed_loop_fmus, tmp_path):
    """A String at the FMU's start value is left out; the bearing, lubricant, race control and lubrication method
    become the numeric
    parameters that carry them (a master without String values, OMSimulator, gets the same set); a String
    without a numeric counterpart stays, named in the notes."""
    from bearing_fmu.models.file_parameters import lubricant_values

    overrides = {**AT_SPEED, "bearing_2.race_control": "inner", "bearing_2.lubricant": "pao_vg48"}
    spec = load_run(SPRING, {**overrides, "spindle.integrator": "implicit_euler"})
    notes = []
    with zipfile.ZipFile(export_ssp(spec, tmp_path / "loop.ssp", notes)) as archive:
        root = ET.fromstring(archive.read("SystemStructure.ssd"))
    # Bearing.fmu starts at the run file's B7214C, iso_vg68_mineral, outer, and at flooded: the run file's
    # oil_air travels as lubrication_mode 3 (LUBRICATION_METHODS order)
    assert _parameters(root, "bearing_1") == {
        "F_z": ("Real", "800.0"),
        "omega": ("Real", "1047.1975511965977"),
        "lubrication_mode": ("Integer", "3"),
    }
    second = _parameters(root, "bearing_2")
    assert second.pop("race_control_mode") == ("Integer", "1")
    assert second.pop("lubrication_mode") == ("Integer", "3")
    assert second.pop("lubricant_from_file") == ("Boolean", "false")
    assert {name: float(value) for name, (_, value) in second.items() if name.startswith("lubricant_data.")} == (
        lubricant_values("pao_vg48")
    )
    assert "String" not in {kind for kind, _ in second.values()}
    assert _parameters(root, "spindle")["integrator"] == ("String", "implicit_euler")
    assert len(notes) == 1 and notes[0].startswith("spindle.integrator = 'implicit_euler' is written as a String")


def test_dem_package_with_numeric_bearing_runs_in_libcosim_equal_to_the_jacobi_master(tmp_path):
    """runs/startup_dem.toml at constant speed: BearingDEM.fmu starts at the 6208 and another oil, so the package
    carries the B7214C and iso_vg68_mineral as numeric parameters (no String); libcosim runs it equal to the
    project's Jacobi master, which sets the Strings: the two ways of giving the bearing agree to the bit."""
    from tests.conftest import _fmu, _thermal_fmu

    _fmu("BearingDEM", "dem.toml"), _thermal_fmu("SpindleThermal")
    spec = load_run(ROOT / "runs" / "startup_dem.toml", {**AT_SPEED, "run.algorithm": "jacobi", "run.stop": 0.05})
    package = export_ssp(spec, tmp_path / "dem.ssp")
    with zipfile.ZipFile(package) as archive:
        root = ET.fromstring(archive.read("SystemStructure.ssd"))
    first = _parameters(root, "bearing_1")
    assert first["bearing_from_file"] == first["lubricant_from_file"] == ("Boolean", "false")
    assert first["bearing_data.Z"][0] == "Integer" and "String" not in {kind for kind, _ in first.values()}
    master = run(spec)
    record = [name for name in master.columns if name != "time"]
    libcosim = run_ssp_in_libcosim(package, spec.step, spec.stop, record)
    for name in record:
        np.testing.assert_array_equal(libcosim[name], master.columns[name], err_msg=name)
    assert master.columns["bearing_1.torque"][-1] > 1.0  # N.m: the B7214C pair at 10 000 rpm


def test_fmpy_simulate_ssp_cannot_run_the_package(closed_loop_fmus, tmp_path, capfd):
    """fmpy's simulate_ssp (fmpy 0.3) is no master for the package, for reasons of its own (README, "The closed
    loop in other co-simulation masters"): it pairs every input connector with a connection, so a constant input
    (F_z, omega: a connector with its value in the parameter set) ends it in get_connections; it applies no
    parameter binding of the package (only a parameter_set argument); and with those two worked around (the
    constant inputs' connectors removed, the bindings passed as parameter_set) it steps the FMUs with every
    connected input at 0.0, not at its source's initialisation value: a 0 K oil temperature, which the bearing
    refuses (fmi2Discard) at the first step."""
    from fmpy.fmi1 import FMICallException
    from fmpy.ssp.simulation import simulate_ssp
    from fmpy.ssp.ssd import Parameter, ParameterSet

    package = export_ssp(load_run(SPRING, {**AT_SPEED, "run.stop": 3.0}), tmp_path / "loop.ssp")
    with pytest.raises(UnboundLocalError, match="start_p"):
        simulate_ssp(str(package), stop_time=3.0, step_size=1.0)
    with zipfile.ZipFile(package) as archive:
        root = ET.fromstring(archive.read("SystemStructure.ssd"))
        files = {name: archive.read(name) for name in archive.namelist()}
    connected = {(c.get("endElement"), c.get("endConnector")) for c in root.iter(f"{{{SSD}}}Connection")}
    parameter_set = ParameterSet(name=PARAMETER_SET)
    for component in root.iter(f"{{{SSD}}}Component"):
        connectors = component.find(f"{{{SSD}}}Connectors")
        for connector in list(connectors):
            if connector.get("kind") == "input" and (component.get("name"), connector.get("name")) not in connected:
                connectors.remove(connector)
        for p in component.iter(f"{{{SSV}}}Parameter"):
            # this package carries Real values and the Integer lubrication_mode (the run file's oil_air)
            kind = p[0].tag.split("}")[1]
            assert kind in ("Real", "Integer")
            name = f"{component.get('name')}.{p.get('name')}"
            value = float(p[0].get("value")) if kind == "Real" else int(p[0].get("value"))
            parameter_set.parameters.append(Parameter(name=name, type=kind, value=value))
    files["SystemStructure.ssd"] = ET.tostring(root, encoding="utf-8", xml_declaration=True)
    with zipfile.ZipFile(tmp_path / "connected.ssp", "w") as archive:
        for name, data in files.items():
            archive.writestr(name, data)
    with pytest.raises(FMICallException, match="fmi2DoStep failed with status 2"):
        simulate_ssp(str(tmp_path / "connected.ssp"), stop_time=3.0, step_size=1.0, parameter_set=parameter_set)
    assert "bearing_1: T_oil = 0.0 K is outside the allowed range" in capfd.readouterr().out
