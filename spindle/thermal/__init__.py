"""Lumped thermal network of a spindle: kernels (``network``), facade (``model``), FMU slave (``fmu``).

Public API (imported on first use, so ``import spindle.thermal`` stays cheap)::

    from spindle.thermal import SpindleThermalModel, SpindleInputError, load_spindle, network_path
"""

_PUBLIC = {
    "SpindleThermalModel": "spindle.thermal.model",
    "SpindleInputError": "spindle.thermal.model",
    "load_spindle": "spindle.thermal.model",
    "network_path": "spindle.thermal.model",
}
__all__ = list(_PUBLIC)


def __getattr__(name):
    if name in _PUBLIC:
        import importlib

        return getattr(importlib.import_module(_PUBLIC[name]), name)
    raise AttributeError(f"module 'spindle.thermal' has no attribute {name!r}")
