"""Co-simulation of FMUs: the fmpy master (``master``), run files (``runfile``), the libcosim
cross-check (``libcosim_master``), Dask sweeps (``sweep``) and result plots (``plots``).

The master talks to the models only through FMI: it imports no physics.
"""
