"""bearing_fmu: numba-jitted ball-bearing model packaged as FMI 2.0 co-simulation FMUs.

Layers (SPEC 2): kernels (pure, jitted) <- model (facade) <- fmu (thin pythonfmu slave) <- build.
"""

__version__ = "0.1.0"
