"""Slow, obviously correct plain-Python twins of the numba kernels (after stumpy's naive
reference versions).

One module per kernel module (ref_<module>.py), one function per public kernel, same name and, where
the kernel takes a quadrature rule, the same arguments without it. The twins are written from the
textbook formulas, not from the kernels: closed forms are written out directly, complete elliptic
integrals come from scipy.special, roots from scipy.optimize.brentq and integrals from
scipy.integrate.quad. They are for tests only: never import them from the package.
"""
