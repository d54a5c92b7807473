"""Variable declarations and the input error shared by every model and FMU.

Each input and output of a model is declared once, as a `Variable` (FMI name, SI unit, description,
the scene option that enables it, where its value comes from, its start value). The facades fill
their output arrays in declaration order, the FMU classes register their FMI variables from the same
declarations and the variable lists of the documentation (fmus/<Name>.md, README) are generated from
them, so a Python model, its FMU and their documentation cannot drift apart.
"""

from dataclasses import dataclass

import numpy as np


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

    def enabled(self, scene):
        """True if this variable exists in `scene` (its option is on and the scene's drive is listed)."""
        if self.option and not getattr(scene, self.option):
            return False
        return not self.drives or getattr(scene, "drive", None) in self.drives

    def start_in(self, scene):
        """Start value in `scene` (outputs: None, they start from the model at the start inputs)."""
        return getattr(scene, self.name) if self.start is None else self.start


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
