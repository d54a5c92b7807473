"""modelDescription.xml as tools expect it, and what every FMU carries beside its model:

- `fmpy.validate_fmu` finds no problem;
- every output declares `dependencies=""` in ModelStructure/Outputs (it changes only in fmi2DoStep: no
  algebraic loop through it) and is listed in InitialUnknowns with `dependencies=""` (computed in
  fmi2ExitInitializationMode: in Initialization Mode it depends on no input), `initial="calculated"` without
  a start value;
- a DefaultExperiment equal to the build's reference experiment, a `nominal` on every Real input, the
  product's version, licence and copyright;
- documentation/index.html (the variable list of fmus/<Name>.md) and the reference result in the FMI
  cross-check layout (<Name>_in.csv, <Name>_ref.csv, <Name>_ref.opt) inside the FMU; fmpy fed with
  <Name>_in.csv reproduces <Name>_ref.csv (algebraic and thermal FMUs), and simulates every FMU with its
  DefaultExperiment alone.
"""

import csv
import io
import math
import shutil
import tomllib
import zipfile
from xml.etree import ElementTree

import numpy as np
import pytest
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi2 import FMU2Slave
from fmpy.validation import validate_fmu

import bearing_fmu
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.fidelities import FIDELITIES
from bearing_fmu.scene import Scene
from bearing_fmu_common.variables import TYPICAL_MAGNITUDE
from spindle.all_fmus import all_variables
from spindle.check import NOT_COMPARED, compare
from tests.conftest import CONFIGURED as CONFIGURED_KINDS
from tests.conftest import ROOT, _fmu

BEARINGS = {
    "BearingAnalytic": "analytic.toml",
    "Bearing": "quasi_static.toml",
    "BearingDisp": "quasi_static_displacement.toml",
    "BearingFixed": "quasi_static_fixed_preload.toml",
    "BearingDEM": "dem.toml",
    "BearingDEMDisp": "dem_displacement.toml",
}
THERMAL = {"SpindleThermal": "spindle_thermal_fmu", "SpindleThermalFixed": "spindle_thermal_fixed_fmu"}
CONFIGURED = [f"{name}_B7214C" for name in CONFIGURED_KINDS]  # `spindle build --config configs/rabreau_rig.toml`
ALL = sorted(BEARINGS) + sorted(THERMAL)
DECLARED_INPUTS = {name: inputs for name, _, _, _, inputs, *_ in all_variables()}


@pytest.fixture
def fmu(request):
    name = request.param
    if name in CONFIGURED:
        return request.getfixturevalue("configured_fmus")[name]
    return _fmu(name, BEARINGS[name]) if name in BEARINGS else request.getfixturevalue(THERMAL[name])


def expected_experiment(name):
    """(stop time, step) of the reference experiment, from the build's definition of it (a configured FMU,
    <Name>_<configuration>, has its generic FMU's experiment)."""
    name = name.split("_")[0]
    if name in THERMAL:
        return 3600.0, 60.0
    with open(SCENES_DIR / BEARINGS[name], "rb") as fh:
        scene = Scene.from_dict(tomllib.load(fh)["scene"])
    fidelity = FIDELITIES[scene.fidelity]
    rows, step = fidelity.reference_inputs(scene), fidelity.reference_step
    return rows[-1].get("time", len(rows) * step), step  # without times: one step per point, from 0


@pytest.mark.parametrize("fmu", ALL + CONFIGURED, indirect=True)
def test_model_description_as_tools_expect(fmu):
    assert validate_fmu(str(fmu)) == []
    root = ElementTree.fromstring(zipfile.ZipFile(fmu).read("modelDescription.xml"))
    variables = list(root.find("ModelVariables"))
    outputs = [str(i + 1) for i, v in enumerate(variables) if v.get("causality") == "output"]
    assert outputs
    structure = root.find("ModelStructure")
    assert [(u.get("index"), u.get("dependencies")) for u in structure.find("Outputs")] == [(i, "") for i in outputs]
    assert [(u.get("index"), u.get("dependencies")) for u in structure.find("InitialUnknowns")] == [
        (i, "") for i in outputs
    ]
    # an input's nominal: its declared one (the rates of a prescribed ring), else its unit's typical magnitude
    declared = {v.name: v.nominal for v in DECLARED_INPUTS[root.get("modelName").split("_")[0]] if v.nominal}
    for v in variables:
        if v.get("causality") == "output":
            assert v.get("initial") == "calculated" and v[0].get("start") is None, v.get("name")
        if v.get("causality") == "input" and v[0].tag == "Real":
            typical = declared.get(v.get("name"), TYPICAL_MAGNITUDE.get(v[0].get("unit")))
            assert float(v[0].get("nominal")) == typical > 0, v.get("name")
    stop, step = expected_experiment(root.get("modelName"))
    experiment = root.find("DefaultExperiment").attrib
    assert float(experiment["startTime"]) == 0.0
    assert math.isclose(float(experiment["stopTime"]), stop) and float(experiment["stepSize"]) == step
    with open(ROOT / "pyproject.toml", "rb") as fh:
        assert root.get("license") == tomllib.load(fh)["project"]["license"]["text"]
    assert root.get("version") == bearing_fmu.__version__
    assert root.get("copyright").startswith("Copyright")


@pytest.mark.parametrize("fmu", ALL + CONFIGURED, indirect=True)
def test_documentation_and_reference_are_inside_the_fmu(fmu):
    name = fmu.name[:-4]
    with zipfile.ZipFile(fmu) as z:
        page = z.read("documentation/index.html").decode()
        files = set(z.namelist())
        options = z.read(f"documentation/{name}_ref.opt").decode()
    assert {f"documentation/{name}_in.csv", f"documentation/{name}_ref.csv"} <= files
    assert f"<title>{name}</title>" in page
    rows = [line for line in fmu.with_suffix(".md").read_text().splitlines() if line.startswith("| `")]
    for line in rows:  # every variable of fmus/<Name>.md, in a row of the page's table
        variable = line.split("`")[1]
        assert f"<tr><td><code>{variable}</code></td>" in page, variable
    assert page.count("<tr><td>") == len(rows)
    stop, step = expected_experiment(name)
    assert options.splitlines()[:3] == ["StartTime, 0.0", f"StopTime, {stop!r}", f"StepSize, {step!r}"]


def crosscheck(fmu, name):
    """The FMU's cross-check files: (inputs as fmpy's structured array, reference {column: array}, stop, step)."""
    with zipfile.ZipFile(fmu) as z:
        tables = [
            list(csv.reader(io.StringIO(z.read(f"documentation/{name}{s}").decode()))) for s in ("_in.csv", "_ref.csv")
        ]
        options = dict(line.split(", ") for line in z.read(f"documentation/{name}_ref.opt").decode().splitlines())
    (ih, *irows), (rh, *rrows) = tables
    signal = np.array([tuple(float(x) for x in r) for r in irows], dtype=[(n, float) for n in ih])
    reference = {n: np.array([float(r[j]) for r in rrows]) for j, n in enumerate(rh)}
    return signal, reference, float(options["StopTime"]), float(options["StepSize"])


@pytest.mark.parametrize("fmu", ["BearingAnalytic", "Bearing", "SpindleThermal"], indirect=True)
def test_fmpy_fed_with_the_inputs_file_reproduces_the_reference_file(fmu):
    """As a cross-check tool runs it: simulate_fmu with <Name>_in.csv and <Name>_ref.opt's step; every output
    column of <Name>_ref.csv within spindle check's tolerance (the solver's iteration count excepted)."""
    signal, reference, stop, step = crosscheck(fmu, fmu.name[:-4])
    names = [n for n in reference if n != "time" and n not in NOT_COMPARED]
    result = simulate_fmu(str(fmu), stop_time=stop, output_interval=step, input=signal, output=names)
    assert np.allclose(result["time"], reference["time"])
    worst, differences = compare({n: result[n] for n in names}, reference, names)
    assert differences == [], differences[:5]


def replay(fmu, signal, stop, step):
    """The FMU run as the cross-check reads its files: initialised with the first row at t = 0; before each
    step from t, the last row whose time is t or earlier (rows of equal time are an event: the later one
    holds from t on); outputs after initialisation and after each step, as {name: array} with `time`."""
    md = read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outputs = [v for v in md.modelVariables if v.causality == "output"]
    names = [n for n in signal.dtype.names if n != "time"]
    unzip = extract(str(fmu))
    slave = FMU2Slave(guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier)

    def read(t):
        values = {v.name: (slave.getReal if v.type == "Real" else slave.getInteger)([vr[v.name]])[0] for v in outputs}
        return {"time": t, **values}

    try:
        slave.instantiate()
        slave.setupExperiment(startTime=0.0)
        slave.enterInitializationMode()
        slave.setReal([vr[n] for n in names], [float(signal[0][n]) for n in names])
        slave.exitInitializationMode()
        rows, n_steps = [read(0.0)], int(round(stop / step))
        for k in range(n_steps):
            t = k * step
            row = signal[np.nonzero(signal["time"] <= t + 1e-9 * step)[0][-1]]
            slave.setReal([vr[n] for n in names], [float(row[n]) for n in names])
            slave.doStep(t, step)
            rows.append(read((k + 1) * step))
        slave.terminate()
    finally:
        slave.freeInstance()
        shutil.rmtree(unzip, ignore_errors=True)
    return {n: np.array([r[n] for r in rows]) for n in rows[0]}


@pytest.mark.parametrize("fmu", ALL + CONFIGURED, indirect=True)
def test_the_fmu_reproduces_its_crosscheck_reference(fmu):
    """Every FMU, the DEM's event at t = 0 included (its experiment starts from the start values and its
    first step takes the first row: fmpy 0.3.32's simulate_fmu takes no event at the start time)."""
    signal, reference, stop, step = crosscheck(fmu, fmu.name[:-4])
    got = replay(fmu, signal, stop, step)
    at = [int(np.argmin(np.abs(got["time"] - t))) for t in reference["time"]]
    assert np.allclose(got["time"][at], reference["time"], rtol=0, atol=1e-9 * step)
    names = [n for n in reference if n != "time" and n not in NOT_COMPARED]
    worst, differences = compare({n: got[n][at] for n in names}, reference, names)
    assert differences == [], differences[:5]


@pytest.mark.parametrize("fmu", ALL + CONFIGURED, indirect=True)
def test_fmpy_simulates_with_the_default_experiment(fmu):
    md = read_model_description(str(fmu))
    result = simulate_fmu(str(fmu))  # stop time and output interval from DefaultExperiment
    assert math.isclose(result["time"][-1], float(md.defaultExperiment.stopTime))
    assert math.isclose(result["time"][1] - result["time"][0], float(md.defaultExperiment.stepSize))
    assert all(np.all(np.isfinite(result[n])) for n in result.dtype.names)
