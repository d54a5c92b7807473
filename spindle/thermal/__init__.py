"""Lumped thermal network of a spindle: kernels (``network``), facade (``model``), FMU slave (``fmu``).

Public API: ``SpindleThermalModel``, ``load_spindle``, ``network_path`` (from ``spindle.thermal.model``).
"""
