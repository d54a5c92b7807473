"""The race control of the quasi-static fidelity against the DEM's steady state: the DEM's outputs averaged in steady
rolling under thrust, the scene of the quasi-static solutions compared with them and the outputs compared. The
validation test of the race control "traction" (tests/validation/test_traction_race_control.py) asserts on them and
the fidelity ladder (benchmarks.fidelity_ladder) tabulates them over speed.
"""

import math
import time

import numpy as np

from bearing_fmu.models.dem import DemModel
from bearing_fmu.scene import Scene

B218 = "tests/validation/data/angular_218_textbook.toml"  # the textbook's 218 (40 deg, 16 balls)
RACE_SCENE = Scene(name="traction", fidelity="quasi_static", torque=True, gyroscopic=True)
RACE_COMPARED = ("omega_cage", "torque", "Q_max_inner", "Q_max_outer", "alpha_inner", "alpha_outer")


def dem_steady(bearing, lubricant, rpm, F_z, via=None):
    """The DEM's outputs under the thrust F_z (N) at rpm, averaged over 20 samples at 0.281-0.300 s after a 10 ms speed
    ramp from rest; with `via` (rpm), ramped to `via` in 10 ms, held there to 0.15 s, ramped to rpm over 0.1 s and
    averaged over 0.451-0.470 s (where the steady state depends on the path); and the wall time (s) of the run."""
    start = time.perf_counter()
    omega = rpm * math.pi / 30.0
    first = omega if via is None else via * math.pi / 30.0
    model = DemModel(bearing, lubricant)
    model.advance(2e-3, omega=0.0, F_z=F_z)
    for k in range(1, 21):
        model.advance(2e-3 + 10e-3 * k / 20, omega=first * k / 20, F_z=F_z)
    t = 0.28
    if via is not None:
        model.advance(0.15, omega=first, F_z=F_z)
        for k in range(1, 21):
            model.advance(0.15 + 0.1 * k / 20, omega=first + (omega - first) * k / 20, F_z=F_z)
        t = 0.45
    model.advance(t, omega=omega, F_z=F_z)
    samples = [model.advance(t + 1e-3 * k, omega=omega, F_z=F_z) for k in range(1, 21)]
    return {key: float(np.mean([o[key] for o in samples])) for key in RACE_COMPARED}, time.perf_counter() - start
