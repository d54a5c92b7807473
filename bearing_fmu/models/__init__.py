"""One facade per bearing fidelity, and the declarations and input checks they share.

- ``analytic.AnalyticModel``: radially loaded deep-groove bearing, closed-form load distribution.
- ``quasi_static.QuasiStaticModel``: Jones/Harris 5-DOF equilibrium with per-ball equilibrium.
- ``pair``: X/O duplex pairs built from two quasi-static bearings (spring or fixed preload).
- ``variables``: input checks and limits shared by the fidelities.

A facade packs a bearing file, a lubricant file and a scene into kernel arrays once, checks every
input (InputError names the input, its value and the allowed range) and returns SI outputs.
"""
