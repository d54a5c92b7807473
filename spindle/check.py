"""`spindle check FMU`: simulate an FMU with its reference experiment and compare with <Name>_ref.csv.

Every FMU ships with a reference result of the Python model it wraps (`fmus/<Name>_ref.csv`, written by
`spindle build`) and the files that define its experiment: `<Name>_scene.toml` for a bearing FMU,
`<Name>_network.toml` for a thermal one. The check runs the FMU through FMI only (fmpy), in the same
sequence the reference was computed in, and compares every output column of the reference:

- bearing FMUs (analytic, quasi-static): one doStep per reference row with that row's inputs (the scene's
  speed ramp, bearing_fmu.build.reference_inputs); the first row is the initialisation;
- the DEM bearing FMU: the scene's input script, one doStep per row, ending at the row's time;
- thermal FMUs: the constant inputs of spindle.all_fmus.reference_inputs, stepped at the reference's time step.

Tolerance: |FMU - reference| <= RTOL * max(|reference|, |FMU|) + ATOL_SCALE * RTOL * max |reference
column|. The FMU runs the same model code as the reference, so the only differences are those of the
solver's warm-start history (the FMU evaluates its default inputs at construction and at initialisation;
the reference model starts cold), which the solvers' tolerance (1e-10 relative on the quasi-static
equilibrium) bounds far below RTOL; the column term absorbs round-off noise of quantities that are zero
by symmetry (e.g. off-diagonal stiffness terms, ~1e-16 of the diagonal). The quasi-static solver's
iteration count (`iterations`) is not compared: it is the part of the history that shows (the FMU's
first row takes 9 iterations from its warm start where the cold reference takes 8).
"""

import math
import shutil
import tomllib
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace

import numpy as np

RTOL = 1e-6  # relative tolerance on every output
ATOL_SCALE = 1e-3  # absolute floor: ATOL_SCALE * RTOL * the column's largest magnitude
# outputs that describe the solver's work, not the physics: they depend on the warm-start history
NOT_COMPARED = {"iterations"}


@dataclass
class CheckResult:
    """Outcome of one FMU's check: `differences` lists one line per differing output (empty = passed)."""

    fmu: str
    rows: int
    outputs: int
    worst: float  # largest |difference| / tolerance over all outputs and rows (<= 1 passes)
    differences: list

    @property
    def passed(self):
        return not self.differences


def reference_table(path):
    """The reference CSV as (column names, {name: float array}); names such as K[1,2] quoted or not (a
    native master may leave them unquoted)."""
    import csv

    from .cosim.master import header_names

    with open(path, newline="") as fh:
        reader = csv.reader(fh)
        names = header_names(next(reader))
        rows = np.array([[float(v) for v in row] for row in reader], dtype=float)
    return names, {n: rows[:, k] for k, n in enumerate(names)}


def experiment(fmu_path, model_name):
    """The reference experiment of an FMU from the files next to it: (input dicts, one per point, the
    communication step ending at each point (s), whether the reference has the initialisation's point).
    Point 0 is the state after initialisation (its step is 0; inputs None: the start values).
    Thermal and shaft FMUs: (None, None, True), their experiment comes from the reference's time column."""
    folder = Path(fmu_path).resolve().parent
    scene_file, network_file = folder / f"{model_name}_scene.toml", folder / f"{model_name}_network.toml"
    if (folder / f"{model_name}_shaft.toml").is_file():
        return None, None, True
    if scene_file.is_file():
        from bearing_fmu.build import reference_inputs
        from bearing_fmu.scene import Scene

        with open(scene_file, "rb") as fh:
            rows = reference_inputs(Scene.from_dict(tomllib.load(fh)["scene"]))
        if "time" in rows[0]:  # a dynamic model: every row is one step ending at its time, from t = 0
            times = [0.0] + [row["time"] for row in rows]
            inputs = [{k: v for k, v in row.items() if k != "time"} for row in rows]
            return [None, *inputs], [0.0, *np.diff(times)], False
        return rows, [0.0] + [1.0] * (len(rows) - 1), True  # a static model: the step length does not matter
    if network_file.is_file():
        return None, None, True
    raise FileNotFoundError(
        f"{fmu_path}: none of {scene_file.name}, {network_file.name}, {model_name}_shaft.toml next to it"
    )


def simulate(fmu_path, inputs, steps):
    """Run the FMU (default parameters): initialise with inputs[0] (None: the start values), then one
    doStep of steps[k] with inputs[k] per further row; the outputs after each row as {name: array}."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    md = read_model_description(str(fmu_path))
    variables = {v.name: v for v in md.modelVariables}
    outputs = [v for v in md.modelVariables if v.causality == "output"]
    unzip = extract(str(fmu_path))
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier)

    def set_inputs(values):
        for name, value in (values or {}).items():
            v = variables[name]
            if v.type == "Real":
                fmu.setReal([v.valueReference], [float(value)])
            else:
                fmu.setInteger([v.valueReference], [int(value)])

    def read():
        out = {}
        for v in outputs:
            getter = fmu.getReal if v.type == "Real" else fmu.getInteger
            out[v.name] = float(getter([v.valueReference])[0])
        return out

    try:
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        set_inputs(inputs[0])
        fmu.exitInitializationMode()
        rows, t = [read()], 0.0
        for values, h in zip(inputs[1:], steps[1:]):
            set_inputs(values)
            fmu.doStep(t, h)
            t += h
            rows.append(read())
        fmu.terminate()
    finally:
        fmu.freeInstance()
        shutil.rmtree(unzip, ignore_errors=True)
    return {v.name: np.array([row[v.name] for row in rows]) for v in outputs}


def compare(got, reference, names):
    """(worst |difference| / tolerance, one line per output outside the tolerance naming it, its first
    differing row and both values)."""
    worst, differences = 0.0, []
    for name in names:
        ref, fmu = reference[name], got[name]
        floor = ATOL_SCALE * RTOL * float(np.max(np.abs(ref)))
        tolerance = RTOL * np.maximum(np.abs(ref), np.abs(fmu)) + floor
        excess = np.abs(fmu - ref) / np.where(tolerance > 0.0, tolerance, math.inf)
        excess[(fmu == ref)] = 0.0
        excess[~np.isfinite(fmu) & np.isfinite(ref)] = math.inf
        worst = max(worst, float(np.max(excess)))
        bad = np.flatnonzero(~(excess <= 1.0))
        if bad.size:
            k = int(bad[0])
            differences.append(
                f"{name}: row {k + 1} of {len(ref)}: FMU {fmu[k]!r}, reference {ref[k]!r} "
                f"(tolerance {float(tolerance[k]):.3g}; {bad.size} row(s) differ)"
            )
    return worst, differences


def check_fmu(fmu_path, reference_csv=None):
    """Simulate the FMU with its reference experiment and compare with its reference CSV (default:
    <modelName>_ref.csv next to the FMU). Returns a CheckResult."""
    from fmpy import read_model_description

    md = read_model_description(str(fmu_path))
    name = md.modelName
    folder = Path(fmu_path).resolve().parent
    reference_csv = Path(reference_csv) if reference_csv else folder / f"{name}_ref.csv"
    columns, reference = reference_table(reference_csv)
    output_names = {v.name for v in md.modelVariables if v.causality == "output"}
    compared = [c for c in columns if c in output_names and c not in NOT_COMPARED]
    inputs, steps, initial = experiment(fmu_path, name)
    if inputs is None:  # thermal or shaft FMU: constant reference inputs, the reference's own time step
        from spindle.all_fmus import reference_inputs, shaft_reference_inputs_of

        shaft_file = folder / f"{name}_shaft.toml"
        model = SimpleNamespace(inputs=[v for v in md.modelVariables if v.causality == "input"])
        constant = shaft_reference_inputs_of(name, shaft_file) if shaft_file.is_file() else reference_inputs(model)
        times = reference["time"]
        inputs = [constant] * len(times)
        steps = [0.0, *np.diff(times)]
    n_rows = len(inputs) - (not initial)
    if n_rows != len(reference[columns[0]]):
        raise ValueError(f"{reference_csv}: {len(reference[columns[0]])} rows, the experiment has {n_rows}")
    got = simulate(fmu_path, inputs, steps)
    if not initial:
        got = {k: v[1:] for k, v in got.items()}
    worst, differences = compare(got, reference, compared)
    return CheckResult(Path(fmu_path).name, n_rows, len(compared), worst, differences)
