"""FMI helpers shared by the slave classes: SI units in modelDescription, parameters, inputs, outputs.

pythonfmu 0.7 writes no units; FMI 2.0 wants a `unit` attribute on each Real and the unit defined
in <UnitDefinitions> by its SI base-unit exponents.
"""

from xml.etree.ElementTree import Element, SubElement

from pythonfmu import Boolean, Fmi2Causality, Fmi2Initial, Fmi2Variability, Integer, Real, String

# SI base-unit exponents (FMI 2.0 BaseUnit attributes) of the units the FMUs use
BASE_UNITS = {
    "1": {},
    "m": {"m": 1},
    "rad": {"rad": 1},
    "rad/s": {"rad": 1, "s": -1},
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
    "N/m": {"kg": 1, "s": -2},
}


class UnitReal(Real):
    """pythonfmu Real with an FMI `unit` attribute."""

    def __init__(self, name, unit, **kwargs):
        super().__init__(name, **kwargs)
        self.unit = unit

    def to_xml(self):
        node = super().to_xml()
        node.find("Real").set("unit", self.unit)
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


def parameter(name, start, description, unit=None):
    """A fixed parameter variable (Real with unit, Boolean for a bool start, or String when unit is None)."""
    kwargs = dict(
        causality=Fmi2Causality.parameter,
        variability=Fmi2Variability.fixed,
        initial=Fmi2Initial.exact,
        start=start,
        description=description,
    )
    if isinstance(start, bool):
        return Boolean(name, **kwargs)
    if unit is None:
        return String(name, **kwargs)
    return UnitReal(name, unit, **kwargs)


def input_variable(name, unit, start, description):
    return UnitReal(
        name,
        unit,
        causality=Fmi2Causality.input,
        variability=Fmi2Variability.continuous,
        start=start,
        description=description,
    )


def output_variable(name, unit, description, integer=False, getter=None, setter=None):
    """Output declared initial=exact (computed at initialisation), so `fmpy validate` is clean (SPEC 3)."""
    kwargs = dict(
        causality=Fmi2Causality.output, initial=Fmi2Initial.exact, description=description, getter=getter, setter=setter
    )
    if integer:
        return Integer(name, variability=Fmi2Variability.discrete, **kwargs)
    return UnitReal(name, unit, variability=Fmi2Variability.continuous, **kwargs)
