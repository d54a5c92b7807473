"""Build every FMU: the bearing FMUs (one per scene, bearing_fmu.build), SpindleThermal.fmu, SpindleShaft.fmu and
SpindleShaftTransient.fmu.

SpindleThermal.fmu and SpindleShaft.fmu bundle `bearing_fmu_common` and one copy of `spindle`'s FMU models: the
thermal model with the networks and the bearing catalogue (the thermal model reads bearing files with
bearing_fmu_common.bearing_file), the shaft model with its catalogue (SPINDLE_BUNDLE), never the bearing model;
next to each go the network or shaft it was built with, a reference result (the Python model's response,
regression data for users) and its variable list (<Name>.md, generated from its declarations).

`python -m spindle.all_fmus readme` rewrites the FMU variable block of README.md (between the markers
README_BEGIN and README_END) from the same declarations; tests/fmu/test_variable_docs.py fails when
README.md or a committed fmus/<Name>.md is out of date.
"""

import argparse
import math
from pathlib import Path

from bearing_fmu import build as bearing_build
from bearing_fmu.bundle import runtime_bundle
from bearing_fmu.fidelities import FIDELITIES
from bearing_fmu.fmu_files import add_documentation

from .shaft.declarations import SEAT_DAMPING, transient_parameter_declarations
from .shaft.declarations import parameter_declarations as shaft_parameter_declarations
from .shaft.fmu import SpindleShaft, SpindleShaftTransient
from .shaft.params import DEFAULT_SHAFT, shaft_path
from .shaft.stepper import ShaftStepper
from .shaft.transient_stepper import TransientStepper
from .thermal.declarations import parameter_declarations
from .thermal.fmu import SpindleThermal
from .thermal.model import DEFAULT_SPINDLE, SpindleThermalModel, network_path

SPINDLE_DIR = Path(__file__).resolve().parent
DEFAULT_OUT = bearing_build.DEFAULT_OUT
README = SPINDLE_DIR.parent / "README.md"
README_BEGIN = "<!-- variables:begin -->"
README_END = "<!-- variables:end -->"

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


REFERENCE_STEP, REFERENCE_STOP = 60.0, 3600.0  # s


def reference_rows(spindle=DEFAULT_SPINDLE, axial_float=None, step=REFERENCE_STEP, stop=REFERENCE_STOP):
    """The reference result (rows of time and outputs, from the initialisation on) and its constant inputs."""
    model = SpindleThermalModel(spindle, axial_float=axial_float)
    inputs = reference_inputs(model)
    model.initialize(**inputs)
    rows = [{"time": 0.0, **model.outputs_values()}]
    for n in range(int(round(stop / step))):
        model.step(step, **inputs)
        rows.append({"time": (n + 1) * step, **model.outputs_values()})
    return rows, inputs


def compile_runs(network, axial_float, step=60.0):
    """The simulate_fmu runs that compile the thermal FMU's kernels at build (bearing_fmu.compiled_code):
    ten steps with the start values, then ten with the reference inputs."""
    inputs = reference_inputs(SpindleThermalModel(network, axial_float=axial_float))
    options = {"stop_time": 10 * step, "output_interval": step}
    return [
        {"options": options},
        {"options": options, "inputs": [{"time": 0.0, **inputs}, {"time": 10 * step, **inputs}]},
    ]


# thermal FMUs: name -> the network whose inputs/outputs it exposes. The fixed-preload network adds
# the axial-float inputs (axial reaction and stiffness of each bearing), which a spring-preloaded
# spindle does not need (what a scene does not need is not exposed: docs/architecture.md, scenes).
THERMAL_FMUS = {"SpindleThermal": (DEFAULT_SPINDLE, False), "SpindleThermalFixed": (DEFAULT_SPINDLE, True)}
# What a thermal or shaft FMU carries: the modules of the shared package and of the FMU models of `spindle` (the
# thermal model and the shaft model; not the rest of `spindle`: the master, the command line), the networks, the
# bearing catalogue they name (spindle.thermal.model.BEARING_CATALOGUES) and the shaft catalogue. Both carry the same
# copy of `spindle`, as every FMU carries the same bearing_fmu_common: a process keeps one module per name, so in a
# host that loads both (the warm-up system) the second FMU finds its own files in the copy the first one put in
# place. No bearing model: the host needs numpy and numba only, not scipy (docs/fmu_runtime.md).
SPINDLE_BUNDLE = runtime_bundle(
    ((bearing_build.COMMON_DIR, "bearing_fmu_common"), (SPINDLE_DIR, "spindle")),
    ("spindle.thermal.fmu", "spindle.shaft.fmu", *bearing_build.RUNTIME_ENTRIES),
    ("spindle/thermal/params", "spindle/shaft/params"),
) + ((bearing_build.PACKAGE_DIR / "params" / "bearings", "spindle/thermal/bearings"),)
THERMAL_BUNDLE = SPINDLE_BUNDLE


def build_thermal_fmu(name, network, axial_float, out_dir=DEFAULT_OUT):
    """Build the thermal FMU `name` exposing `network` (a catalogue name: the start value of `spindle` and of the
    network's main dimensions), with the axial-float inputs or not."""
    path = bearing_build.build_python_fmu(
        name,
        "spindle.thermal.fmu",
        "SpindleThermal",
        out_dir,
        bundle=THERMAL_BUNDLE,
        body=f"default_network = {network!r}\n    axial_float = {axial_float!r}",
        runs=compile_runs(network, axial_float),
        experiment=(REFERENCE_STOP, REFERENCE_STEP),
    )
    rows, inputs = reference_rows(network, axial_float)
    computed = bearing_build.csv_text(rows, lambda v: repr(float(v)))
    markdown = bearing_build.variables_markdown(*thermal_variables(name, (network, axial_float)))
    bearing_build.write_if_changed(Path(out_dir) / f"{name}_network.toml", network_path(network).read_text())
    reference = bearing_build.write_reference_if_changed(Path(out_dir) / f"{name}_ref.csv", computed)
    bearing_build.write_if_changed(Path(out_dir) / f"{name}.md", markdown)
    held = [{"time": 0.0, **inputs}, {"time": REFERENCE_STOP, **inputs}]  # constant over the experiment
    in_csv = bearing_build.csv_text(held, lambda v: repr(float(v)))
    add_documentation(path, name, markdown, in_csv, reference, REFERENCE_STOP, REFERENCE_STEP)
    return path


SHAFT_FMU = "SpindleShaft"
SHAFT_BUNDLE = SPINDLE_BUNDLE  # the same copy of `spindle` as the thermal FMUs
# reference experiment of the shaft FMU: the start values (the Bearing.fmu reference K at both seats, 2000 N.s/m)
# at 10 000 rpm, held for one second at 0.25 s steps (the outputs follow the inputs without history)
SHAFT_STEP, SHAFT_STOP = 0.25, 1.0  # s


def shaft_reference_inputs(shaft=DEFAULT_SHAFT):
    """The shaft FMU's constant reference inputs: its start values at the reference speed."""
    return {v.name: v.start for v in ShaftStepper(shaft).inputs} | {"omega": REFERENCE_OMEGA}


def shaft_reference_rows(shaft=DEFAULT_SHAFT, step=SHAFT_STEP, stop=SHAFT_STOP):
    """The shaft FMU's reference result (rows of time and outputs) from the Python model, and its constant inputs."""
    stepper = ShaftStepper(shaft)
    inputs = shaft_reference_inputs(shaft)
    u = list(inputs.values())
    rows = [{"time": n * step, **stepper.outputs_values(u)} for n in range(int(round(stop / step)) + 1)]
    return rows, inputs


TRANSIENT_FMU = "SpindleShaftTransient"
# reference experiment of the time-domain shaft FMU: its start values (the seats' reactions 0, the Bearing.fmu
# reference K at both seats, the seats' own damping) at the reference speed with TRANSIENT_TIP_FORCE on the tool tip,
# 20 steps of 0.5 ms. Unconnected, a seat's reaction stays 0 and its K acts within each step only, so the shaft drifts
# on its seats' damping: regression data of the integration, not a bearing-supported response (runs/ couples bearings)
TRANSIENT_STEP, TRANSIENT_STOP = 5e-4, 1e-2  # s
TRANSIENT_TIP_FORCE = {"F_x_tip": 10.0}  # N


def transient_reference_inputs(shaft=DEFAULT_SHAFT):
    """The time-domain shaft FMU's constant reference inputs."""
    stepper = TransientStepper(shaft)
    return {v.name: v.start for v in stepper.inputs} | {"omega": REFERENCE_OMEGA} | TRANSIENT_TIP_FORCE


def transient_reference_rows(shaft=DEFAULT_SHAFT, step=TRANSIENT_STEP, stop=TRANSIENT_STOP):
    """The time-domain shaft FMU's reference result (rows of time and outputs, from the initialisation on) with its
    parameters' start values, and its constant inputs."""
    stepper = TransientStepper(shaft)
    parameters = {v.name: v.start for v in transient_parameter_declarations(shaft, stepper.model.shaft.seat_names)}
    damping = [[parameters[f"c_{kind}_{s}"] for kind, *_ in SEAT_DAMPING] for s in (1, 2)]
    stepper.configure(parameters["substeps"], damping, parameters["implicit_coupling"], parameters["newmark_gamma"])
    inputs = transient_reference_inputs(shaft)
    u = list(inputs.values())
    names = [v.name for v in stepper.outputs]
    rows = [{"time": 0.0, **dict(zip(names, stepper.start(u), strict=True))}]
    for n in range(int(round(stop / step))):
        rows.append({"time": (n + 1) * step, **dict(zip(names, stepper.step(step, u), strict=True))})
    return rows, inputs


# shaft FMUs: name -> (slave class name in spindle.shaft.fmu, reference rows, reference experiment (stop, step))
SHAFT_FMUS = {
    SHAFT_FMU: ("SpindleShaft", shaft_reference_rows, (SHAFT_STOP, SHAFT_STEP)),
    TRANSIENT_FMU: ("SpindleShaftTransient", transient_reference_rows, (TRANSIENT_STOP, TRANSIENT_STEP)),
}


def shaft_kind(name):
    """The shaft FMU of SHAFT_FMUS that the FMU `name` is: itself, or the generic one of a configured FMU
    `<Name>_<configuration>`."""
    return name.split("_", 1)[0]


def shaft_reference_inputs_of(name, shaft=DEFAULT_SHAFT):
    """The constant reference inputs of the shaft FMU `name` (spindle check; a configured one's too)."""
    return transient_reference_inputs(shaft) if shaft_kind(name) == TRANSIENT_FMU else shaft_reference_inputs(shaft)


def build_shaft_fmu(out_dir=DEFAULT_OUT, shaft=DEFAULT_SHAFT, name=SHAFT_FMU):
    """Build the shaft FMU `name` (SHAFT_FMUS, or `<Name>_<configuration>` for a configured one) exposing the seats
    of `shaft` (a catalogue name: the start value of `shaft` and of the numeric shaft_data.* parameters)."""
    class_name, reference_rows_of, (stop, step) = SHAFT_FMUS[shaft_kind(name)]
    rows, inputs = reference_rows_of(shaft)
    held = [{"time": 0.0, **inputs}, {"time": stop, **inputs}]
    in_csv = bearing_build.csv_text(held, lambda v: repr(float(v)))
    path = bearing_build.build_python_fmu(
        name,
        "spindle.shaft.fmu",
        class_name,
        out_dir,
        bundle=SHAFT_BUNDLE,
        body=f"default_shaft = {shaft!r}",
        runs=[{"options": {"stop_time": stop, "output_interval": step}}],
        experiment=(stop, step),
    )
    computed = bearing_build.csv_text(rows, lambda v: repr(float(v)))
    markdown = bearing_build.variables_markdown(*shaft_variables(name, shaft))
    bearing_build.write_if_changed(Path(out_dir) / f"{name}_shaft.toml", shaft_path(shaft).read_text())
    reference = bearing_build.write_reference_if_changed(Path(out_dir) / f"{name}_ref.csv", computed)
    bearing_build.write_if_changed(Path(out_dir) / f"{name}.md", markdown)
    add_documentation(path, name, markdown, in_csv, reference, stop, step)
    return path


def shaft_variables(name=SHAFT_FMU, shaft=DEFAULT_SHAFT):
    """variables_markdown() arguments of the shaft FMU `name` (a configured one's too) built with `shaft`."""
    if shaft_kind(name) == TRANSIENT_FMU:
        stepper = TransientStepper(shaft)
        declare, slave = transient_parameter_declarations, SpindleShaftTransient
        connect = (
            "connect each bearing FMU's `F_x` ... `M_y` and `K[i,j]` to its seat's `F_x_<seat>` ... `M_y_<seat>` and "
            "`K_<seat>[i,j]`, and the seat's `x_<seat>` ... `theta_y_<seat>` to the bearing's `x` ... `theta_y`"
        )
    else:
        stepper = ShaftStepper(shaft)
        declare, slave = shaft_parameter_declarations, SpindleShaft
        connect = "connect each seat's `K_<seat>[i,j]` to its bearing FMU's `K[i,j]`"
    seats = ", ".join(f"{k} `{s}`" for k, s in enumerate(stepper.model.shaft.seat_names, start=1))
    about = [
        f"Shaft `{shaft}` (`{name}_shaft.toml`), seats {seats}: {connect}. Reference result of the Python model: "
        f"`{name}_ref.csv`. Variables declared in `spindle/shaft/declarations.py`; SI units."
    ]
    parameters = declare(shaft, stepper.model.shaft.seat_names)
    return name, slave.description, about, parameters, stepper.inputs, stepper.outputs


def thermal_variables(name, built=None):
    """variables_markdown() arguments of the thermal FMU `name`, built with `built` = (network, axial_float)
    (default: THERMAL_FMUS[name])."""
    network, axial_float = built or THERMAL_FMUS[name]
    model = SpindleThermalModel(network, axial_float=axial_float)
    about = [
        f"Network `{network}` (`{name}_network.toml`), axial-float inputs "
        f"{'on (fixed-preload pair)' if axial_float else 'off (spring preload)'}. Reference result of the "
        f"Python model: `{name}_ref.csv`. Variables declared in `spindle/thermal/declarations.py`; SI units."
    ]
    return (
        name,
        SpindleThermal.description,
        about,
        parameter_declarations(network, model.net),
        model.inputs,
        model.outputs,
    )


def all_variables():
    """variables_markdown() arguments of every FMU, bearing scenes first."""
    out = [bearing_build.scene_variables(f) for f in bearing_build.scene_files()]
    return out + [thermal_variables(name) for name in THERMAL_FMUS] + [shaft_variables(name) for name in SHAFT_FMUS]


def _names(variables, units=True):
    """`a` (unit), `b` ..., with the 25 stiffness entries K[i,j] shown once and each group of structured names
    (`bearing_data.*`: the numeric bearing parameters) once, with its size."""
    shown = []
    for v in variables:
        if v.name.startswith("K") and v.name.endswith("]"):  # K[i,j] of a bearing, K_<seat>[i,j] of a shaft seat
            head = v.name.split("[")[0]
            if v.name == f"{head}[1,1]":
                shown.append(f"`{head}[i,j]` (i, j = 1..5)")
            continue
        if "." in v.name:
            group = v.name.split(".")[0]
            size = sum(1 for w in variables if w.name.startswith(f"{group}."))
            if not any(s.startswith(f"`{group}.*`") for s in shown):
                shown.append(f"`{group}.*` ({size})")
            continue
        shown.append(f"`{v.name}`" + (f" ({v.unit})" if units and v.unit not in ("", "1") else ""))
    return ", ".join(shown)


def _summary(name, scene):
    """A few words on what the FMU models: its fidelity's summary (with its drive), or its network options."""
    if scene:
        return FIDELITIES[scene[0].fidelity].summary(scene[0])
    if name == SHAFT_FMU:
        return "rotor finite-element shaft on bearing seats"
    if name == TRANSIENT_FMU:
        return "rotor finite-element shaft in time, on bearings driven by displacement"
    return "thermal spindle" + (", axial float of a fixed-preload pair" if THERMAL_FMUS[name][1] else "")


def readme_block():
    """The README's FMU variable block: one row per FMU with its inputs, outputs and parameters, linking
    to its full variable list fmus/<Name>.md."""
    lines = [
        README_BEGIN,
        "<!-- generated by `python -m spindle.all_fmus readme` from the variable declarations; do not edit -->",
        "",
        "| FMU | model | inputs | outputs | parameters |",
        "|---|---|---|---|---|",
    ]
    for name, _, _, parameters, inputs, outputs, *scene in all_variables():
        lines.append(
            f"| [`{name}.fmu`](fmus/{name}.md) | {_summary(name, scene)} | {_names(inputs)} "
            f"| {_names(outputs, units=False)} | {_names(parameters)} |"
        )
    lines += ["", bearing_build.COMMA_NAMES_NOTE, README_END]
    return "\n".join(lines)


def update_readme(path=README):
    """Replace the block between README_BEGIN and README_END of the README with readme_block()."""
    text = Path(path).read_text()
    head, rest = text.split(README_BEGIN, 1)
    tail = rest.split(README_END, 1)[1]
    bearing_build.write_if_changed(path, head + readme_block() + tail)


def write_variable_docs(out_dir=DEFAULT_OUT):
    """fmus/<Name>.md of every FMU, without building the FMUs."""
    for arguments in all_variables():
        bearing_build.write_if_changed(
            Path(out_dir) / f"{arguments[0]}.md", bearing_build.variables_markdown(*arguments)
        )


def build_all(out_dir=DEFAULT_OUT):
    """Build every FMU into out_dir; returns their paths."""
    paths = [bearing_build.build_fmu(scene, out_dir) for scene in bearing_build.scene_files()]
    paths += [build_thermal_fmu(name, network, axial, out_dir) for name, (network, axial) in THERMAL_FMUS.items()]
    return paths + [build_shaft_fmu(out_dir, name=name) for name in SHAFT_FMUS]


def main(argv=None):
    parser = argparse.ArgumentParser(description="Variable lists generated from the declarations.")
    parser.add_argument("what", choices=["readme", "docs"], help="readme: README.md's block; docs: fmus/<Name>.md")
    args = parser.parse_args(argv)
    if args.what == "readme":
        update_readme()
    else:
        write_variable_docs()


if __name__ == "__main__":
    main()
