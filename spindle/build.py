"""Build every FMU: the bearing FMUs (one per scene, bearing_fmu.build) and SpindleThermal.fmu.

SpindleThermal.fmu bundles the `spindle` and `bearing_fmu` packages (the thermal slave uses the
FMI helpers of bearing_fmu); next to it go the network it was built with and a reference result
(the Python model's step response, regression data for users).
"""

import csv
import math
import shutil
from pathlib import Path

from bearing_fmu import build as bearing_build

from .thermal.model import DEFAULT_SPINDLE, SpindleThermalModel, network_path

SPINDLE_DIR = Path(__file__).resolve().parent
DEFAULT_OUT = bearing_build.DEFAULT_OUT

# reference experiment: both bearings at 10 000 rpm, 300 W into each inner ring, 200 W into each
# outer ring, 20 C coolant and ambient, one hour at 60 s steps
REFERENCE_OMEGA = 10000.0 * 2.0 * math.pi / 60.0


def reference_inputs(model):
    inputs = {v.name: 0.0 for v in model.inputs}
    inputs.update(omega=REFERENCE_OMEGA, T_ambient=293.15, T_coolant=293.15)
    for name in inputs:
        if name.startswith("Q_inner_ring_"):
            inputs[name] = 300.0
        elif name.startswith("Q_outer_ring_"):
            inputs[name] = 200.0
    return inputs


def write_reference(path, spindle=DEFAULT_SPINDLE, axial_float=None, step=60.0, stop=3600.0):
    model = SpindleThermalModel(spindle, axial_float=axial_float)
    inputs = reference_inputs(model)
    model.initialize(**inputs)
    rows = [{"time": 0.0, **model.outputs_values()}]
    for n in range(int(round(stop / step))):
        model.step(step, **inputs)
        rows.append({"time": (n + 1) * step, **model.outputs_values()})
    with open(path, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: repr(float(v)) for k, v in row.items()})


# thermal FMUs: name -> the network whose inputs/outputs it exposes. The fixed-preload network adds
# the axial-float inputs (axial reaction and stiffness of each bearing), which a spring-preloaded
# spindle does not need (SPEC 5.2: what a scene does not need is not exposed).
THERMAL_FMUS = {"SpindleThermal": (DEFAULT_SPINDLE, False), "SpindleThermalFixed": (DEFAULT_SPINDLE, True)}


def build_thermal_fmu(name, network, axial_float, out_dir=DEFAULT_OUT):
    path = bearing_build.build_python_fmu(
        name,
        "spindle.thermal.fmu",
        "SpindleThermal",
        out_dir,
        package_dirs=(bearing_build.PACKAGE_DIR, bearing_build.COMMON_DIR, SPINDLE_DIR),
        body=f"default_network = {network!r}\n    axial_float = {axial_float!r}",
    )
    shutil.copy2(network_path(network), Path(out_dir) / f"{name}_network.toml")
    write_reference(Path(out_dir) / f"{name}_ref.csv", network, axial_float)
    return path


def build_all(out_dir=DEFAULT_OUT):
    """Build every FMU into out_dir; returns their paths."""
    paths = [bearing_build.build_fmu(scene, out_dir) for scene in bearing_build.scene_files()]
    paths += [build_thermal_fmu(name, network, axial, out_dir) for name, (network, axial) in THERMAL_FMUS.items()]
    return paths
