"""numba-jitted physics kernels: pure functions of float64 scalars/arrays, SI units (layers: docs/architecture.md).

Kernels import nothing of the package but other kernels; options arrive as integer codes.
Every kernel has a plain-Python twin in tests/reference/ and a test comparing them.
"""
