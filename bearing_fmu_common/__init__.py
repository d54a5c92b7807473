"""What the bearing and the thermal-spindle FMUs share: the jit policy of every kernel, the FMI
variable helpers and the variable declarations.

Each FMU bundles this package beside its own (``bearing_fmu`` or ``spindle``) and never the other
one. The name is unique on purpose: pythonfmu FMUs run in the importing interpreter, where two FMUs
that ship a module of the same name share one copy of it.
"""
