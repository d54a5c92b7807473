"""Steady operating points of the DEM and the start-up that reaches them: the 6208 of Guessasma & Machado (2018) at
3 kN, 500 rad/s; the B7214C of the spindle rig at 10 000 rpm under 800 N of thrust; the same bearing with cold oil
(293 K) at 16 rad/s, where the squeeze damping of the full film, not the contact stiffness, limits the step. The DEM
validation tests start from them, and the step study (benchmarks.dem_steps) measures the time step and the tribology
refresh at each.
"""

from bearing_fmu.models.dem import DemModel

POINTS = {
    "6208, 3 kN, 500 rad/s": dict(
        bearing="6208", lubricant="guessasma_oil", T_oil=313.15, loads={"F_y": 3000.0}, omega=500.0, ramp=5e-3,
        settle=30e-3,
    ),
    "B7214C, 800 N thrust, 10 000 rpm": dict(
        bearing="B7214C", lubricant="iso_vg68_mineral", T_oil=313.15, loads={"F_z": 800.0}, omega=1047.1975511965977,
        ramp=10e-3, settle=0.3,
    ),
    "B7214C, 800 N thrust, cold oil (293 K), 16 rad/s": dict(
        bearing="B7214C", lubricant="iso_vg68_mineral", T_oil=293.15, loads={"F_z": 800.0}, omega=16.0, ramp=30e-3,
        settle=60e-3,
    ),
}  # fmt: skip


def warm(point, **settings):
    """A DemModel of the point in steady rolling: 2 ms at rest, a ramp to the speed, held to point['settle']."""
    model = DemModel(point["bearing"], point["lubricant"], **settings)
    held = dict(point["loads"], T_oil=point["T_oil"])
    model.advance(2e-3, omega=0.0, **held)
    for k in range(1, 21):
        model.advance(2e-3 + point["ramp"] * k / 20, omega=point["omega"] * k / 20, **held)
    model.advance(point["settle"], omega=point["omega"], **held)
    return model
