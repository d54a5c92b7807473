"""A run file's coupled system as an SSP 1.0 package (System Structure and Parameterization, Modelica
Association, SSP 1.0, 2019) for other co-simulation masters: libcosim, ecos and OMSimulator run it as written
(README, "The closed loop in other co-simulation masters").

The package (.ssp, a zip archive) holds:
- SystemStructure.ssd: one ssd:Component per instance (source resources/<FMU file>), its connectors
  (connected inputs and outputs, constant inputs, parameters; FMI types from the FMU's modelDescription),
  its parameters and constant inputs as an inline ssv:ParameterSet (ssd:ParameterBindings) named
  PARAMETER_SET in every component, one ssd:Connection per run-file connection, the system's OMSimulator
  annotation (oms:FixedStepMaster with the communication step: OMSimulator refuses a system without a
  system type), and an ssd:DefaultExperiment with the start and stop time and the communication step (as the
  Open Simulation Platform annotation osp:FixedStepAlgorithm, which libcosim reads; ecos takes the step from
  its caller);
- resources/<FMU file>: each FMU file once, whatever the number of its instances.

Parameter values: numeric only where the FMU allows it. A String parameter set to the FMU's start value is
not written (the FMU runs it anyway); the bearing, lubricant, race control and lubrication method (Strings)
are written as the numeric parameters that carry them (bearing_from_file = false and bearing_data.*,
lubricant_from_file = false and lubricant_data.*, race_control_mode, lubrication_mode; docs/parameters.md,
"Numeric parameters"), which give the same
results bit for bit. OMSimulator imports no String value (it logs an error for each ssv:String and runs the
FMU's start value), ecos applies a parameter set by its name across all components (one name for all:
PARAMETER_SET). Any other String that differs from the FMU's start value is written as a String and named in
the export's notes: a master without String values runs the start value; a configured FMU (spindle build
--config) makes it the start value.

Which algorithm: SSP 1.0 describes the system, not the master algorithm. libcosim's, ecos's and
OMSimulator's fixed-step masters exchange Jacobi-style; the project's master with `algorithm = "jacobi"`
gives the same result in each, to the bit (tests/cosim/test_ssp.py, tests/cosim/test_ssp_masters.py),
Gauss-Seidel differs by O(step). fmpy's simulate_ssp cannot run a package (README, "The closed loop in other
co-simulation masters").

Refused parameters are found before anything is written: the export initialises every instance with its
parameters and inputs through the project's master first (spindle.cosim.master.Master) and raises its
MasterError, with the FMU's message, if an FMU refuses. libcosim 0.11 would instead end the whole process
on the fmi2Error of fmi2ExitInitializationMode (an exception thrown on its worker thread that it does
not catch; docs/fmu_runtime.md).
"""

import zipfile
from pathlib import Path
from xml.etree import ElementTree as ET

from .master import Master, MasterError
from .numeric import SWITCHES, numeric_parameters
from .runfile import split_name

SSD = "http://ssp-standard.org/SSP1/SystemStructureDescription"
SSC = "http://ssp-standard.org/SSP1/SystemStructureCommon"
SSV = "http://ssp-standard.org/SSP1/SystemStructureParameterValues"
OSP = "http://opensimulationplatform.com/SSP/OSPAnnotations"
OMS = "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd"
# OMSimulator and ecos read the elements by their prefixed names (pugixml): the prefixes are part of the format
for _prefix, _uri in (("ssd", SSD), ("ssc", SSC), ("ssv", SSV), ("osp", OSP), ("oms", OMS)):
    ET.register_namespace(_prefix, _uri)
PARAMETER_SET = "parameters"  # the name of every component's parameter set (ecos applies a set by its name)

# FMI type -> SSP type element (an FMI enumeration travels as its integer value)
SSP_TYPES = {"Real": "Real", "Integer": "Integer", "Enumeration": "Integer", "Boolean": "Boolean", "String": "String"}


def _value_text(kind, value):
    """A parameter value as SSP writes it (xs:double, xs:int, xs:boolean, xs:string)."""
    if kind == "Real":
        return repr(float(value))
    if kind == "Boolean":
        return "true" if value else "false"
    if kind == "String":
        return str(value)
    return str(int(value))


def component_values(spec, variables, notes=None):
    """instance -> {variable: value} that the package carries: the run file's parameters and constant inputs,
    a String parameter at the FMU's start value left out, the bearing, lubricant, race control and lubrication
    method (Strings) replaced by the numeric parameters that carry them where the FMU has these and the run
    file does not set their switch itself (module docstring). variables[instance][name]: the FMI variable. A
    String that stays is named in `notes` (a list, appended to)."""
    out = {}
    for name in spec.order:
        inst, declared = spec.instances[name], variables[name]
        values = {**inst.parameters, **inst.inputs}
        strings = {key: value for key, value in values.items() if declared[key].type == "String"}
        choices = {
            key: value
            for key, value in strings.items()
            if value != declared[key].start
            and key in SWITCHES
            and SWITCHES[key] in declared
            and SWITCHES[key] not in values
        }
        numeric = numeric_parameters(choices)
        kept = {}
        for key, value in values.items():
            if key in choices or (key in strings and value == declared[key].start):
                continue
            kept[key] = value
            if key in strings and notes is not None:
                notes.append(
                    f"{name}.{key} = {value!r} is written as a String: a master that imports no String values "
                    f"(OMSimulator) runs the FMU's start value {declared[key].start!r}; a configured FMU "
                    "(spindle build --config) makes it the start value"
                )
        out[name] = {**numeric, **kept}
    return out


def system_structure(spec, variables, sources, values=None):
    """The SystemStructure.ssd element tree of a RunSpec. variables[instance][name]: the FMI variable
    (fmpy ModelVariable); sources[instance]: the FMU's path inside the package; values[instance]: the
    parameter values to write (default: component_values)."""
    values_of = component_values(spec, variables) if values is None else values
    root = ET.Element(f"{{{SSD}}}SystemStructureDescription", name=Path(spec.path).stem, version="1.0")
    system = ET.SubElement(root, f"{{{SSD}}}System", name="system", description=spec.description or "")
    elements = ET.SubElement(system, f"{{{SSD}}}Elements")
    connected = {name: set() for name in spec.order}
    for source, target in spec.connections:
        for qualified in (source, target):
            instance, variable = split_name(qualified)
            connected[instance].add(variable)
    for name in spec.order:
        values = values_of[name]
        component = ET.SubElement(
            elements, f"{{{SSD}}}Component", name=name, type="application/x-fmu-sharedlibrary", source=sources[name]
        )
        connectors = ET.SubElement(component, f"{{{SSD}}}Connectors")
        for variable in sorted(connected[name] | set(values)):
            v = variables[name][variable]
            connector = ET.SubElement(connectors, f"{{{SSD}}}Connector", name=variable, kind=v.causality)
            ET.SubElement(connector, f"{{{SSC}}}{SSP_TYPES[v.type]}")
        if values:
            bindings = ET.SubElement(component, f"{{{SSD}}}ParameterBindings")
            binding = ET.SubElement(bindings, f"{{{SSD}}}ParameterBinding")
            holder = ET.SubElement(binding, f"{{{SSD}}}ParameterValues")
            parameter_set = ET.SubElement(holder, f"{{{SSV}}}ParameterSet", version="1.0", name=PARAMETER_SET)
            parameters = ET.SubElement(parameter_set, f"{{{SSV}}}Parameters")
            for variable, value in values.items():
                kind = variables[name][variable].type
                parameter = ET.SubElement(parameters, f"{{{SSV}}}Parameter", name=variable)
                ET.SubElement(parameter, f"{{{SSV}}}{SSP_TYPES[kind]}", value=_value_text(kind, value))
    connections = ET.SubElement(system, f"{{{SSD}}}Connections")
    for source, target in spec.connections:
        (s_inst, s_var), (t_inst, t_var) = split_name(source), split_name(target)
        ET.SubElement(
            connections,
            f"{{{SSD}}}Connection",
            startElement=s_inst,
            startConnector=s_var,
            endElement=t_inst,
            endConnector=t_var,
        )
    # OMSimulator's system type (a weakly coupled system stepped by its fixed-step master): without it
    # OMSimulator cannot create the system
    system_annotations = ET.SubElement(system, f"{{{SSD}}}Annotations")
    oms = ET.SubElement(system_annotations, f"{{{SSC}}}Annotation", type="org.openmodelica")
    information = ET.SubElement(ET.SubElement(oms, f"{{{OMS}}}Annotations"), f"{{{OMS}}}SimulationInformation")
    ET.SubElement(information, f"{{{OMS}}}FixedStepMaster", description="oms-ma", stepSize=repr(float(spec.step)))
    experiment = ET.SubElement(
        root, f"{{{SSD}}}DefaultExperiment", startTime=repr(float(spec.start)), stopTime=repr(float(spec.stop))
    )
    annotations = ET.SubElement(experiment, f"{{{SSD}}}Annotations")
    annotation = ET.SubElement(annotations, f"{{{SSC}}}Annotation", type="com.opensimulationplatform")
    algorithm = ET.SubElement(annotation, f"{{{OSP}}}Algorithm")
    ET.SubElement(algorithm, f"{{{OSP}}}FixedStepAlgorithm", baseStepSize=repr(float(spec.step)))
    return ET.ElementTree(root)


def export_ssp(spec, path, notes=None):
    """Write the RunSpec's system (FMUs, connections, parameters and constant inputs, start, stop and
    step) as an SSP 1.0 package at `path` (.ssp). Every instance is first initialised through the
    project's master: a refused parameter raises MasterError (with the FMU's message) and nothing is
    written. Input schedules are refused (SSP 1.0 carries constant values only): hold such an input
    constant with an override (`--set bearing_1.omega=1047.2`) to export the system. A String parameter
    written as a String (component_values) is named in `notes` (a list, appended to). Returns the path."""
    with Master(spec) as master:
        master._initialise()  # the FMUs' own checks of every parameter and input, before any file is written
        variables = {name: inst.variables for name, inst in master.instances.items()}
    scheduled = [f"{name}.{key}" for name in spec.order for key in spec.instances[name].schedules]
    if scheduled:
        raise MasterError(
            f"input schedules {', '.join(scheduled)}: an SSP 1.0 package carries constant values only; hold "
            f"each at a constant with an override (e.g. --set {scheduled[0]}=<value>) to export the system"
        )
    files, sources = {}, {}
    for name in spec.order:
        fmu = Path(spec.instances[name].fmu)
        if fmu not in files:  # each FMU file once; a second file of the same name gets a suffix
            stem, taken = fmu.stem, set(files.values())
            entry, k = f"resources/{fmu.name}", 2
            while entry in taken:
                entry, k = f"resources/{stem}_{k}.fmu", k + 1
            files[fmu] = entry
        sources[name] = files[fmu]
    try:
        values = component_values(spec, variables, notes)
    except ValueError as exc:
        raise MasterError(str(exc)) from None
    tree = system_structure(spec, variables, sources, values)
    ET.indent(tree)
    path = Path(path)
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("SystemStructure.ssd", ET.tostring(tree.getroot(), encoding="utf-8", xml_declaration=True))
        for fmu, entry in files.items():
            archive.write(fmu, entry, compress_type=zipfile.ZIP_STORED)  # an FMU is already a zip archive
    return path


def run_ssp_in_libcosim(path, step, stop, record):
    """Load the SSP package at `path` into libcosim (libcosimpy) and run it from its start to `stop` (s)
    at the fixed step `step` (s), recording `record` ('instance.variable', Real or Integer). Returns a
    numpy structured array as spindle.cosim.libcosim_master.run_libcosim does (row 0: after
    initialisation); raises LibcosimError on any failure."""
    import numpy as np

    from .libcosim_master import NANOSECONDS, LibcosimError, _Run, _ticks

    n_steps = round(stop / step)
    count = n_steps + 1
    run = _Run(step, samples=count, ssp=path)
    try:
        columns = run.observe(record)
        run.step(n_steps)
        out = np.zeros(count, dtype=[("time", float)] + [(name, float) for name, *_ in columns])
        for name, index, reference, kind in columns:
            values, steps, _ = run.samples(index, reference, kind, count)
            if not np.array_equal(steps, np.arange(count)):
                raise LibcosimError(f"{name}: observer samples are not at steps 0..{n_steps}")
            out[name] = values
        out["time"] = np.arange(count) * _ticks(step, "step") / NANOSECONDS
        return out
    finally:
        run.close()
