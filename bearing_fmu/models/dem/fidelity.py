"""The DEM fidelity's contract (models.fidelity): its facade, FMU parameters and reference experiment."""

from ..declarations import DEM_PARAMETERS
from ..fidelity import Fidelity
from .model import DemModel

REFERENCE_STEP = 0.5e-3  # s, communication step of the DEM reference experiment


def reference_inputs(scene=None):
    """The DEM reference experiment, one dict per communication point (time = end of the step, s): the 6208
    at 3 kN radial, 40 C, speed ramp 0 -> 500 rad/s over 5 ms, steady to 6 ms, then a load step to 4 kN
    held to 8 ms (a step of 0.5 ms). Each row's inputs hold over the step that ends at its time."""
    rows = []
    for n in range(1, 17):
        t = n * REFERENCE_STEP
        omega = 500.0 * min(t / 5e-3, 1.0)
        rows.append({"time": t, "omega": omega, "F_x": 3000.0 if t <= 6e-3 else 4000.0, "T_oil": 313.15})
    return rows


FIDELITY = Fidelity(
    name="dem",
    model=DemModel,
    parameters=DEM_PARAMETERS,
    choices=("bearing", "lubricant"),
    reference_step=REFERENCE_STEP,
    reference_inputs=reference_inputs,
    summary=lambda scene: "DEM (ball dynamics) bearing, loads in, displacements out",
)
