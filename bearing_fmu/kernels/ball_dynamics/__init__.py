"""DEM (ball dynamics) kernels: Z steel balls, Z cage balls, a translating inner ring with prescribed
rotation and a fixed outer ring (Guessasma & Machado 2018; Farah et al. 2020).

Modules: state (named slots of every array), contacts (ball-race torus geometry and forces), cage
(cage balls and their guide), tribology (per-contact film, regime, friction, damping, capacitance and
Houpert resistances, refreshed every N steps), integrator (velocity Verlet, advance), monitor
(stability limit, energy), outputs (bearing-level outputs).
"""
