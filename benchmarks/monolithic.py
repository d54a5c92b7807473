"""Fine monolithic reference of the closed thermo-mechanical loop: both models in one loop.

The co-simulation couples the models only at communication points (each FMU holds its inputs over
a step H). The reference instead advances the coupled system with a second-order scheme and a
small step h, iterating the coupling inside the step:
  1. heat P_n from the bearings at the temperatures T_n; predictor T* = thermal step from T_n
     with P_n held (exact exponential integration of the linear network);
  2. heat P* from the bearings at T* (oil temperature and clearance change of T*);
  3. corrector: the thermal step from T_n again with the mean heat (P_n + P*)/2 held.
This is Heun's method on the coupling with the network integrated exactly; its error is O(h^2)
(benchmarks/cosim_error.py checks it by halving h). The quasi-static bearings are algebraic (no state
of their own beyond the solver's warm start), so nothing else needs integrating.

Same physics and parameters as runs/closed_loop_spring.toml: Bearing.fmu's scene, B7214C,
iso_vg68_mineral, oil-air lubrication, outer race control, F_z = 800 N each, 10 000 rpm, network b7214c_x_pair.
"""

import math
import time as wallclock

import numpy as np

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from spindle.thermal.model import SpindleThermalModel

OMEGA = 10000.0 * 2.0 * math.pi / 60.0  # rad/s
F_PRELOAD = 800.0  # N, spring preload (each bearing)
T_AMBIENT = 293.15  # K (also the coolant)
TRACKED = tuple(f"T_{node}_{k}" for k in (1, 2) for node in ("inner_ring", "outer_ring", "oil")) + (
    "T_shaft",
    "T_housing",
)


class Monolithic:
    """The two bearings and the spindle network advanced together (spring preload, constant speed)."""

    def __init__(
        self, spindle="b7214c_x_pair", race_control="outer", omega=OMEGA, F_z=F_PRELOAD, lubrication="oil_air"
    ):
        scene = Scene.from_toml(SCENES_DIR / "quasi_static.toml")
        self.bearings = [
            QuasiStaticModel("B7214C", "iso_vg68_mineral", scene, race_control=race_control, lubrication=lubrication)
            for _ in range(2)
        ]
        self.spindle = SpindleThermalModel(spindle)
        self.omega, self.F_z = omega, F_z
        self.fixed = {"omega": omega, "T_ambient": T_AMBIENT, "T_coolant": T_AMBIENT, "P_motor": 0.0}
        out = self.spindle.initialize(**self.fixed)
        self.thermal_out = out
        self.bearing_out = self._bearings(out)

    def _bearings(self, thermal):
        """Bearing outputs for the temperatures and clearance changes of `thermal`."""
        return [
            b.evaluate(
                omega=self.omega, F_z=self.F_z, T_oil=thermal[f"T_oil_{k}"], dPd_thermal=thermal[f"dPd_thermal_{k}"]
            )
            for k, b in enumerate(self.bearings, start=1)
        ]

    @staticmethod
    def _heat(bearing_out, weight=1.0, into=None):
        into = {} if into is None else into
        for k, out in enumerate(bearing_out, start=1):
            for ring in ("inner", "outer"):
                key = f"Q_{ring}_ring_{k}"
                into[key] = into.get(key, 0.0) + weight * out[f"Q_{ring}_ring"]
        return into

    def step(self, h):
        start = self.spindle.get_state()
        heat_n = self._heat(self.bearing_out)
        predicted = self.spindle.step(h, **self.fixed, **heat_n)
        heat_star = self._heat(self._bearings(predicted))
        self.spindle.set_state(start)
        mean = {k: 0.5 * (heat_n[k] + heat_star[k]) for k in heat_n}
        self.thermal_out = self.spindle.step(h, **self.fixed, **mean)
        self.bearing_out = self._bearings(self.thermal_out)

    def record(self):
        row = {name: self.thermal_out[name] for name in TRACKED}
        row.update(P_in=self.thermal_out["P_in"], P_out=self.thermal_out["P_out"])
        for k, out in enumerate(self.bearing_out, start=1):
            row[f"torque_{k}"] = out["torque"]
        return row


def reference(stop, h, every, **kwargs):
    """Trajectory of the monolithic model from 0 to stop (s) with step h, recorded every `every` s
    (a multiple of h). Returns (times, dict name -> array, wall time in s)."""
    per = int(round(every / h))
    n = int(round(stop / h))
    model = Monolithic(**kwargs)
    rows, times = [model.record()], [0.0]
    t0 = wallclock.perf_counter()
    for i in range(1, n + 1):
        model.step(h)
        if i % per == 0:
            rows.append(model.record())
            times.append(i * h)
    wall = wallclock.perf_counter() - t0
    return np.array(times), {k: np.array([r[k] for r in rows]) for k in rows[0]}, wall
