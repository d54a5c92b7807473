"""spindle: the lumped thermal spindle and the co-simulation of spindle and bearings.

- ``spindle.thermal``: the thermal network (kernels, facade, FMU slave, parameter files).
- ``spindle.cosim``: the fmpy co-simulation master, run files, the libcosim cross-check, sweeps, plots.
- ``spindle.all_fmus``: builds every FMU; ``spindle.cli``: the ``spindle`` command.
"""
