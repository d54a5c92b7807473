"""Variable declarations and the input error shared by every model and FMU.

A model declares each input and output once as a `Variable` (FMI name, SI unit, description); the
FMU classes register FMI variables from these declarations, so a Python model and its FMU cannot
drift apart.
"""

from dataclasses import dataclass


class InputError(ValueError):
    """An input or parameter value is outside its allowed range (message names it and the range)."""


@dataclass(frozen=True)
class Variable:
    name: str  # FMI variable name
    unit: str  # SI unit ('1' for dimensionless)
    description: str
    kind: str = "real"  # 'real' | 'integer'
