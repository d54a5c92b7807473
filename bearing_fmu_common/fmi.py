"""FMI helpers shared by the slave classes: SI units in modelDescription, variables registered from
declarations and read by precomputed index, the model structure.

pythonfmu 0.7 writes no units; FMI 2.0 wants a `unit` attribute on each Real and the unit defined
in <UnitDefinitions> by its SI base-unit exponents. pythonfmu lists the outputs in
<ModelStructure><Outputs> without dependencies, which FMI reads as "depends on every input": a master
that sorts a coupled system (OMSimulator) then finds algebraic loops that do not exist. The outputs of
these FMUs change only in fmi2DoStep, so each declares `dependencies=""`, and they are computed at
initialisation (initial="calculated", listed in <InitialUnknowns>). They are computed in
fmi2ExitInitializationMode: in Initialization Mode an output reads the value it had when the instance was
created, whatever input is set, so <InitialUnknowns> declares `dependencies=""` too (without it OMSimulator
reported an algebraic loop of size 8/32 at the initialisation of the closed loop and iterated it).
"""

from operator import itemgetter
from xml.etree.ElementTree import Element, SubElement

from pythonfmu import Boolean, Fmi2Causality, Fmi2Initial, Fmi2Slave, Fmi2Variability, Integer, Real, String
from pythonfmu.enums import Fmi2Status

# SI base-unit exponents (FMI 2.0 BaseUnit attributes) of the units the FMUs use
BASE_UNITS = {
    "1": {},
    "m": {"m": 1},
    "rad": {"rad": 1},
    "rad/s": {"rad": 1, "s": -1},
    "m/s": {"m": 1, "s": -1},
    "N": {"kg": 1, "m": 1, "s": -2},
    "N.m": {"kg": 1, "m": 2, "s": -2},
    "Pa": {"kg": 1, "m": -1, "s": -2},
    "K": {"K": 1},
    "W": {"kg": 1, "m": 2, "s": -3},
    "J": {"kg": 1, "m": 2, "s": -2},
    "W/K": {"kg": 1, "m": 2, "s": -3, "K": -1},
    "J/K": {"kg": 1, "m": 2, "s": -2, "K": -1},
    "F": {"kg": -1, "m": -2, "s": 4, "A": 2},
    "s": {"s": 1},
    "Hz": {"s": -1},
    "N/m": {"kg": 1, "s": -2},
    "N.s/m": {"kg": 1, "s": -1},
    "N.m.s/rad": {"kg": 1, "m": 2, "s": -1, "rad": -1},
    "m/N": {"kg": -1, "s": 2},
    "h": {"s": 1, "factor": 3600},  # hour: rating lives in hours, as catalogues give them
    "kg": {"kg": 1},
    "kg/m^3": {"kg": 1, "m": -3},
    "kg.m^2": {"kg": 1, "m": 2},
    "Pa.s": {"kg": 1, "m": -1, "s": -1},
    "m^2/s": {"m": 2, "s": -1},
    "1/Pa": {"kg": -1, "m": 1, "s": 2},
    "1/K": {"K": -1},
}


class UnitReal(Real):
    """pythonfmu Real with an FMI `unit` attribute and, for inputs and parameters, the declared allowed
    range as `min`/`max` (bearing_fmu_common.variables.Variable) and, for inputs, a `nominal`."""

    def __init__(self, name, unit, minimum=None, maximum=None, nominal=None, **kwargs):
        super().__init__(name, **kwargs)
        self.unit = unit
        self.minimum, self.maximum, self.nominal = minimum, maximum, nominal

    def to_xml(self):
        node = super().to_xml()
        real = node.find("Real")
        real.set("unit", self.unit)
        for key, value in (("nominal", self.nominal), ("min", self.minimum), ("max", self.maximum)):
            if value is not None:
                real.set(key, repr(float(value)))  # the shortest text that reads back as the same number
        return node


class RangedInteger(Integer):
    """pythonfmu Integer with the declared allowed range as FMI `min`/`max` (a count or an enumeration code)."""

    def __init__(self, name, minimum=None, maximum=None, **kwargs):
        super().__init__(name, **kwargs)
        self.minimum, self.maximum = minimum, maximum

    def to_xml(self):
        node = super().to_xml()
        integer = node.find("Integer")
        for key, value in (("min", self.minimum), ("max", self.maximum)):
            if value is not None:
                integer.set(key, str(int(value)))
        return node


def add_unit_definitions(root: Element, variables):
    """Insert <UnitDefinitions> for the units used by `variables` after <CoSimulation>."""
    used = sorted({v.unit for v in variables if isinstance(v, UnitReal)})
    if not used:
        return root
    defs = Element("UnitDefinitions")
    for unit in used:
        u = SubElement(defs, "Unit", {"name": unit})
        SubElement(u, "BaseUnit", {k: str(e) for k, e in BASE_UNITS[unit].items()})
    position = list(root).index(root.find("CoSimulation")) + 1
    root.insert(position, defs)
    return root


def _fields(causality, variability, description, getter, setter, **more):
    """pythonfmu's keywords of a declared variable: its causality and variability, its description, how the slave
    reads and writes its value (getter/setter; None: the slave's attribute of that name) and `more`."""
    return dict(
        causality=causality, variability=variability, description=description, getter=getter, setter=setter, **more
    )


def parameter(name, start, description, unit=None, minimum=None, maximum=None, integer=False, getter=None, setter=None):
    """A fixed parameter variable (Real with unit and allowed range, Boolean for a bool start, Integer with
    its range when `integer`, or String when unit is None). getter/setter: how the slave reads and writes
    its value (None: the slave's attribute of that name)."""
    kwargs = _fields(
        Fmi2Causality.parameter,
        Fmi2Variability.fixed,
        description,
        getter,
        setter,
        initial=Fmi2Initial.exact,
        start=start,
    )
    if isinstance(start, bool):
        return Boolean(name, **kwargs)
    if integer:
        return RangedInteger(name, minimum, maximum, **kwargs)
    if unit is None:
        return String(name, **kwargs)
    return UnitReal(name, unit, minimum, maximum, **kwargs)


def input_variable(name, unit, start, description, getter=None, setter=None, minimum=None, maximum=None, nominal=None):
    """A continuous Real input with its unit, allowed range and typical magnitude."""
    kwargs = _fields(Fmi2Causality.input, Fmi2Variability.continuous, description, getter, setter, start=start)
    return UnitReal(name, unit, minimum, maximum, nominal, **kwargs)


def output_variable(name, unit, description, integer=False, getter=None, setter=None):
    """Output declared initial=calculated: the slave computes it at initialisation from the parameters
    and the inputs set in initialisation mode (so it has no start value)."""
    variability = Fmi2Variability.discrete if integer else Fmi2Variability.continuous
    kwargs = _fields(Fmi2Causality.output, variability, description, getter, setter, initial=Fmi2Initial.calculated)
    if integer:
        return Integer(name, **kwargs)
    return UnitReal(name, unit, **kwargs)


def declare_structure(root: Element):
    """Rewrite <ModelStructure>: every output in <Outputs> with dependencies="" (it changes only in
    fmi2DoStep: no direct feedthrough from an input) and in <InitialUnknowns> with dependencies="" (computed
    from the inputs and parameters in fmi2ExitInitializationMode: in Initialization Mode it depends on none)."""
    variables = root.find("ModelVariables")
    outputs = [str(i + 1) for i, v in enumerate(variables) if v.get("causality") == "output"]
    structure = root.find("ModelStructure")
    for child in list(structure):
        structure.remove(child)
    if outputs:
        SubElement(structure, "Outputs").extend(Element("Unknown", index=i, dependencies="") for i in outputs)
        SubElement(structure, "InitialUnknowns").extend(Element("Unknown", index=i, dependencies="") for i in outputs)
    return root


def declared_parameter(var, slave, scene=None):
    """The FMI parameter of a declaration (bearing_fmu_common.variables.Variable) with its start in `scene`,
    kept as the attribute of `slave` named like it (also a structured name such as 'bearing_data.D', which
    pythonfmu would otherwise look up as an attribute path)."""
    start = var.start_in(scene)
    setattr(slave, var.name, start)
    return parameter(
        var.name,
        start,
        var.description,
        var.unit or None,
        var.min,
        var.max,
        integer=var.kind == "integer",
        getter=lambda: getattr(slave, var.name),
        setter=lambda value: setattr(slave, var.name, value),
    )


def check_parameters(slave, declarations):
    """Raise InputError (bearing_fmu_common.variables) naming the first parameter of `declarations` whose
    value on `slave` is outside its declared range (Real) or not one of its allowed values (String), also
    when the model would not use it (Pd with Pd_from_file = true): a value outside the declared range is
    never accepted."""
    for var in declarations:
        value = getattr(slave, var.name)
        if var.kind in ("real", "integer"):
            var.check(value)
        elif var.kind == "string":
            var.check_choice(value)


class DeclaredSlave(Fmi2Slave):
    """An Fmi2Slave whose inputs and outputs are registered from declarations and kept in two lists in
    declaration order: self._u (inputs, handed to the model as they are) and self._y (outputs, replaced
    by the model's values after each successful step). getReal/getInteger/setReal of those variables
    go by precomputed value-reference -> index tables, not through one Python getter per variable;
    parameters and any other variable take pythonfmu's general path."""

    def register_declared(self, inputs, outputs):
        self._u = [float(var.start) for var in inputs]
        self._y = [0.0] * len(outputs)
        self._input_slot, self._real_slot, self._integer_slot = {}, {}, {}
        self._readers = {}  # tuple of Real value references -> reader (see _reader)
        for k, var in enumerate(inputs):
            fmi_var = input_variable(
                var.name,
                var.unit,
                var.start,
                var.description,
                getter=lambda k=k: self._u[k],
                setter=lambda value, k=k: self._u.__setitem__(k, value),
                minimum=var.min,
                maximum=var.max,
                nominal=var.typical(),
            )
            self.register_variable(fmi_var)
            self._input_slot[fmi_var.value_reference] = k
        for k, var in enumerate(outputs):
            integer = var.kind == "integer"
            fmi_var = output_variable(
                var.name,
                var.unit,
                var.description,
                integer,
                getter=lambda k=k: self._y[k],
                setter=lambda value, k=k: self._y.__setitem__(k, value),
            )
            self.register_variable(fmi_var)
            (self._integer_slot if integer else self._real_slot)[fmi_var.value_reference] = k

    def _guarded(self, action, status=Fmi2Status.error, note=""):
        """Run action(); on an exception log its message (with the FMI status that the calling function returns,
        and `note` appended) and return False: the host never sees an exception."""
        try:
            action()
            return True
        except Exception as exc:  # logged as the model's own message, not a traceback
            self.log(f"{self.instance_name}: {exc}{note}", status)
            return False

    def _initialised(self, build, start):
        """fmi2ExitInitializationMode's result: build() makes the model for the parameters (a refusal: False, i.e.
        fmi2Error), then start() computes the outputs from the inputs set so far; a bad input is logged once as a
        warning (fmi2Warning returned) and refused by the first doStep unless corrected. self._ready says whether
        the parameters were accepted."""
        self._ready = self._guarded(build)
        if not self._ready:
            return False
        if not self._guarded(start, Fmi2Status.warning, " (refused at the first doStep unless corrected)"):
            return Fmi2Status.warning
        return True

    def _stepped(self, step):
        """fmi2DoStep's result: step() run, a refusal logged and returned as False (fmi2Discard); an instance whose
        parameters were refused at initialisation refuses every step."""
        if not self._ready:
            self.log(f"{self.instance_name}: not initialised (see the error at initialisation)", Fmi2Status.discard)
            return False
        return self._guarded(step, Fmi2Status.discard)

    def to_xml(self, model_options=None):
        root = add_unit_definitions(super().to_xml(model_options or {}), self.vars.values())
        return declare_structure(root)

    def _reader(self, vrs, slots):
        """A function y -> [y[slot] for the value references vrs], cached per tuple of references (a
        master asks for the same list every step); KeyError if one of them is not in `slots`."""
        key = tuple(vrs)
        reader = self._readers.get(key)
        if reader is None:
            indices = [slots[vr] for vr in vrs]
            if len(indices) == 1:
                k = indices[0]
                reader = lambda y: [y[k]]
            else:
                pick = itemgetter(*indices)
                reader = lambda y: list(pick(y))
            self._readers[key] = reader
        return reader

    def get_real(self, vrs):
        try:
            return self._reader(vrs, self._real_slot)(self._y)
        except KeyError:  # not only Real outputs: the general path
            return super().get_real(vrs)

    def get_integer(self, vrs):
        y, slot = self._y, self._integer_slot
        try:
            return [int(y[slot[vr]]) for vr in vrs]
        except KeyError:
            return super().get_integer(vrs)

    def set_real(self, vrs, values):
        u, slot = self._u, self._input_slot
        try:
            for vr, value in zip(vrs, values):
                u[slot[vr]] = value
        except KeyError:  # a parameter among them: the general path sets every variable again
            super().set_real(vrs, values)
