"""Variable declarations and the input error shared by every model and FMU.

Each input and output of a model is declared once, as a `Variable` (FMI name, SI unit, description,
the scene option that enables it, where its value comes from, its start value). The facades fill
their output arrays in declaration order, the FMU classes register their FMI variables from the same
declarations and the variable lists of the documentation (fmus/<Name>.md, README) are generated from
them, so a Python model, its FMU and their documentation cannot drift apart.

A Real input or parameter declares its allowed range once (`min`, `max`, and `limits`: why these
bounds): the FMU writes them as min/max into modelDescription.xml and the models refuse anything
outside them with `Variable.check`, so the declared range and the check are the same numbers. Where a
model's limit depends on another parameter (the d_m n speed limit, the material load limit, the groove
clearance of the bearing), the declaration holds the widest static bound and the model narrows it at
run time (`check(value, low, high, why)`); the message then states the narrower range. A String
parameter may list its allowed values (`choices`).
"""

from dataclasses import dataclass

import numpy as np

# Order of magnitude of a typical value of a Real input by unit (FMI `nominal`, used by masters to scale
# tolerances): spindle speeds of 1e3-1e4 rpm, bearing loads of kN, moments of N.m to tens of N.m,
# ring displacements and clearance changes of micrometres, tilts of milliradians, temperatures about
# 300 K, ring heat of tens to hundreds of watts, axial stiffness of 1e8 N/m. A declaration's `nominal`
# takes precedence.
TYPICAL_MAGNITUDE = {"rad/s": 1e3, "N": 1e3, "N.m": 10.0, "m": 1e-5, "rad": 1e-3, "K": 300.0, "W": 100.0}
TYPICAL_MAGNITUDE |= {"N/m": 1e8, "1": 1.0}

# Static bounds shared by the bearing and the thermal FMUs (declared ranges of speed and load inputs)
OMEGA_MAX = 1e5  # rad/s (~955 000 rpm): d_m n = 4e6 mm.rpm is reached below it by any bearing with d_m >= 5 mm
LOAD_MAX = 1e8  # N: far beyond any ball bearing (the largest slewing ball bearings: C0 of order 1e7 N)
# |thermal/centrifugal change| of a bearing's clearance or axial position (m): spindle bearings see micrometres; the
# bearing FMUs' dPd_thermal and dz_thermal inputs and the thermal FMU's outputs feeding them stay within it
THERMAL_SHIFT_MAX = 1e-3


class InputError(ValueError):
    """An input or parameter value is outside its allowed range (message names it and the range)."""


@dataclass(frozen=True)
class Variable:
    name: str  # FMI variable name
    unit: str  # SI unit ('1' for dimensionless)
    description: str
    kind: str = "real"  # 'real' | 'integer' | 'boolean' | 'string' (the last two: parameters)
    option: str = ""  # scene option (a boolean attribute of the scene) that enables it; '' = always there
    drives: tuple = ()  # scene drives in which it exists; () = every drive
    source: tuple = ()  # (array, index): the value is array[index] of the facade; () = computed by the facade
    start: object = 0.0  # start value of an input or parameter; None = the scene's attribute of that name
    min: float = None  # allowed range of a Real input or parameter (FMI min/max); None = not declared
    max: float = None
    limits: str = ""  # why these bounds (shown in the documentation and in refusals)
    choices: tuple = ()  # allowed values of a String parameter; () = any (e.g. a catalogue name or path)
    nominal: float = None  # typical magnitude of a Real input (FMI nominal); None = TYPICAL_MAGNITUDE[unit]

    def enabled(self, scene):
        """True if this variable exists in `scene` (its option is on and the scene's drive is listed)."""
        if self.option and not getattr(scene, self.option):
            return False
        return not self.drives or getattr(scene, "drive", None) in self.drives

    def bounds(self, low=None, high=None):
        """The allowed range (lo, hi): the declared [min, max], narrowed to [low, high] where given."""
        return (self.min if low is None else max(low, self.min), self.max if high is None else min(high, self.max))

    def range_text(self, low=None, high=None):
        """The allowed range as text, e.g. '[-100000, 100000] rad/s' (low/high: narrower run-time bounds)."""
        low, high = self.bounds(low, high)
        unit = "" if self.unit in ("", "1") else f" {self.unit}"
        return f"[{low:.6g}, {high:.6g}]{unit}"

    def check(self, value, low=None, high=None, why=""):
        """Raise InputError unless value is a finite number within the declared range [min, max], narrowed
        to [low, high] when given (a limit that depends on other parameters; `why` says which). The
        message names the variable, its value and the allowed range."""
        lo, hi = self.bounds(low, high)
        if lo <= value <= hi:  # False for NaN
            return
        reason = why or self.limits
        unit = "" if self.unit in ("", "1") else f" {self.unit}"
        raise InputError(
            f"{self.name} = {value}{unit} is outside the allowed range {self.range_text(low, high)}"
            + (f" ({reason})" if reason else "")
        )

    def check_choice(self, value):
        """Raise InputError unless the String value is one of `choices` (any non-empty value without them)."""
        if (value in self.choices) if self.choices else bool(value):
            return
        allowed = ", ".join(repr(c) for c in self.choices) if self.choices else "a non-empty name or path"
        raise InputError(f"{self.name} = {value!r} is not allowed: allowed values {allowed}")

    def typical(self):
        """The order of magnitude of a typical value (FMI `nominal` of a Real input)."""
        if self.nominal is not None:
            return self.nominal
        if self.unit not in TYPICAL_MAGNITUDE:
            raise KeyError(f"{self.name}: no typical magnitude for unit {self.unit!r}: declare its nominal")
        return TYPICAL_MAGNITUDE[self.unit]

    def start_in(self, scene):
        """Start value in `scene` (outputs: None, they start from the model at the start inputs)."""
        return getattr(scene, self.name) if self.start is None else self.start


class InputLimits:
    """The allowed range of each input of a model, precomputed: the declared range narrowed by the limits
    that depend on the model's parameters (narrowed: name -> (low, high, why)), so that checking the inputs
    of a step costs one comparison per input; a refusal is raised by Variable.check (its message)."""

    def __init__(self, variables, narrowed=None):
        narrowed = narrowed or {}
        self._rows = {}
        for k, var in enumerate(variables):
            low, high, why = narrowed.get(var.name, (None, None, ""))
            self._rows[k] = (var, low, high, why)
        self._fast = tuple((k, *var.bounds(low, high)) for k, (var, low, high, _) in self._rows.items())

    def check(self, u):
        """Raise InputError naming the first input of u (values in the variables' order) outside its range."""
        for k, lo, hi in self._fast:
            if not lo <= u[k] <= hi:  # True for NaN
                var, low, high, why = self._rows[k]
                var.check(u[k], low, high, why)


def select(declarations, scene):
    """The declarations that exist in `scene`, in declaration order."""
    return tuple(v for v in declarations if v.enabled(scene))


def gather_plan(variables, arrays):
    """Copy plan from source arrays into an output array ordered like `variables`.

    arrays: name -> 1-D array (views are fine) named by the variables' `source`. Returns a list of
    (source array, source indices, destination indices) so that a facade fills its outputs with one
    fancy-indexed copy per source array: ``values[dst] = src[idx]``."""
    by_array = {}
    for slot, var in enumerate(variables):
        if var.source:
            array, index = var.source
            by_array.setdefault(array, ([], []))
            by_array[array][0].append(index)
            by_array[array][1].append(slot)
    return [(arrays[name], np.array(src), np.array(dst)) for name, (src, dst) in by_array.items()]


def outputs_as_dict(variables, values):
    """Outputs as a dict name -> SI value: `values` (a 1-D array ordered like `variables`) as floats, the
    integer variables' as int."""
    return {v.name: int(x) if v.kind == "integer" else x for v, x in zip(variables, values.tolist())}
