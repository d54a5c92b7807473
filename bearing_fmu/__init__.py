"""bearing_fmu: numba-jitted ball-bearing model packaged as FMI 2.0 co-simulation FMUs.

Layers, each importing only the ones below it: ``kernels`` (pure jitted functions, SI units)
<- ``models`` (one facade per fidelity) <- ``fmu`` (thin pythonfmu slaves) <- ``build``.

Public API (imported on first use, so ``import bearing_fmu`` stays cheap)::

    from bearing_fmu import AnalyticModel, QuasiStaticModel, PairAssembly, solve_pair, Scene
    from bearing_fmu import load_bearing, load_lubricant, InputError, SolverError, ParameterError
"""

__version__ = "0.1.0"

_PUBLIC = {
    "AnalyticModel": "bearing_fmu.models.analytic",
    "QuasiStaticModel": "bearing_fmu.models.quasi_static",
    "SolverError": "bearing_fmu.models.quasi_static",
    "PairAssembly": "bearing_fmu.models.pair",
    "solve_pair": "bearing_fmu.models.pair",
    "InputError": "bearing_fmu.models.limits",
    "Scene": "bearing_fmu.scene",
    "SceneError": "bearing_fmu.scene",
    "load_bearing": "bearing_fmu.params",
    "load_lubricant": "bearing_fmu.params",
    "ParameterError": "bearing_fmu.params",
}
__all__ = ["__version__", *_PUBLIC]


def __getattr__(name):
    if name in _PUBLIC:
        import importlib

        return getattr(importlib.import_module(_PUBLIC[name]), name)
    raise AttributeError(f"module 'bearing_fmu' has no attribute {name!r}")
