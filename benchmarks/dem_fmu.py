"""BearingDEM.fmu through fmpy: the 6208 operating point of the DEM validation and the cost of a doStep.

Operating point (Guessasma & Machado 2018, section 3.1; tests/validation/test_dem_6208.py): 6208,
P_d = 0, F_r = 3 kN, 500 rad/s, guessasma_oil at 40 C, default time step and tribology refresh.
Protocol as the validation test, in communication steps of H = 1 ms: 2 ms at rest under the load,
speed ramp to 500 rad/s over 5 ms (the FMU ramps linearly inside each step), steady running to 30 ms,
then the means of omega_cage and Lambda_outer over the 10 steps to 40 ms (acceptance: omega_cage
within 1 % of 198.0 rad/s, Lambda_outer in 2.05-2.25).

Cost: wall time of one step of 1 ms simulated in steady running, including the FMI transfers a master
makes (setReal of the 6 inputs, fmi2DoStep, getReal/getInteger of every output); median over the steps
from 10 to 40 ms of REPEATS runs (target <= 0.6 ms). For comparison, the same steps of the Python DemModel
alone (DemModel.update, the call inside the FMU's doStep), with and without the stiffness outputs.
Run: python -m benchmarks.dem_fmu -> docs/reports/dem_fmu.md
"""

import statistics
import time
from dataclasses import replace

from fmpy import read_model_description

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.dem import DemModel
from bearing_fmu.scene import Scene
from tests.fmu.harness import opened

from .common import REPORTS
from .render import cli, metric

FMU = REPORTS.parent.parent / "fmus" / "BearingDEM.fmu"
H = 1e-3  # s, communication step
OMEGA, F_R = 500.0, 3000.0
INTEGERS = ("regime", "n_loaded", "monitor_status")
INPUTS = ("omega", "F_x", "F_y", "F_z", "T_oil", "dPd_thermal")
TARGET_MS = 0.6
KEY = "doStep of 1 ms simulated incl. FMI transfers (wall median)"
REPEATS = 5


def schedule():
    """(omega, F_y) of each 1 ms step: 2 at rest, 5 ramp steps, 33 steady (to 40 ms)."""
    steps = [(0.0, F_R)] * 2 + [(OMEGA * k / 5, F_R) for k in range(1, 6)]
    return steps + [(OMEGA, F_R)] * 33


def run_fmu():
    md = read_model_description(str(FMU))
    reals = [v.name for v in md.modelVariables if v.causality == "output" and v.name not in INTEGERS]
    rows, walls = [], []
    with opened(FMU, "bench") as (fmu, vr):
        inputs, real_vrs, int_vrs = ([vr[n] for n in names] for names in (INPUTS, reals, INTEGERS))
        for n, (omega, F_y) in enumerate(schedule()):
            t0 = time.perf_counter()
            fmu.setReal(inputs, [omega, 0.0, F_y, 0.0, 313.15, 0.0])
            fmu.doStep(n * H, H)
            values = fmu.getReal(real_vrs)
            fmu.getInteger(int_vrs)
            walls.append(time.perf_counter() - t0)
            rows.append(dict(zip(reals, values)))
    return rows, walls, len(reals) + len(INTEGERS)


def run_model(stiffness=True):
    scene = Scene.from_toml(SCENES_DIR / "dem.toml")
    model = DemModel(scene=replace(scene, stiffness=stiffness))
    walls = []
    for omega, F_y in schedule():
        t0 = time.perf_counter()
        model.update([omega, 0.0, F_y, 0.0, 0.0, 0.0, 313.15, 0.0], H)
        walls.append(time.perf_counter() - t0)
    return walls


def measure():
    fmu_walls, model_walls, bare_walls = [], [], []
    for _ in range(REPEATS):  # the steps from 10 ms on: steady running
        rows, walls, outputs = run_fmu()
        fmu_walls, model_walls = fmu_walls + walls[10:], model_walls + run_model()[10:]
        bare_walls += run_model(stiffness=False)[10:]
    mean = {q: statistics.mean(r[q] for r in rows[30:]) for q in ("omega_cage", "Lambda_outer", "torque")}
    fmu, model, bare = (1e3 * statistics.median(w) for w in (fmu_walls, model_walls, bare_walls))
    costs = [
        ["FMU: setReal inputs + doStep + get every output", fmu, 1e3 * min(fmu_walls)],
        ["DemModel.update alone (the call inside doStep)", model, 1e3 * min(model_walls)],
        ["DemModel.update without the stiffness outputs (scene option off)", bare, 1e3 * min(bare_walls)],
    ]
    text = (
        "Means over 30-40 ms: `omega_cage` {cage:.3f} rad/s ({off:+.2f} % from 198.0; acceptance: within 1 %), "
        "`Lambda_outer` {lam:.4f} (acceptance: 2.05-2.25), `torque` {torque:.5f} N.m (the validation test compares "
        "it with the quasi-static Houpert torque)."
    )
    values = dict(cage=mean["omega_cage"], off=100.0 * (mean["omega_cage"] / 198.0 - 1.0), lam=mean["Lambda_outer"],
                  torque=mean["torque"])  # fmt: skip
    cost = (
        "Target: doStep of 1 ms simulated <= {target:g} ms wall including the FMI transfers: {verdict}. FMU minus "
        "model: {transfers:+.3f} ms (FMI transfers of the {inputs} inputs and {outputs} outputs, pythonfmu's call "
        "path); the stiffness outputs (kernels/ball_dynamics/stiffness.py, once per step) cost the difference of the "
        "last two rows, {stiffness:+.3f} ms; the rest is the integration itself (docs/reports/dem_timing.md: the "
        "cost per DEM step and the number of steps per simulated ms)."
    )
    cost_values = dict(target=TARGET_MS, verdict="met" if fmu <= TARGET_MS else "not met", transfers=fmu - model,
                       inputs=len(INPUTS), outputs=outputs, stiffness=model - bare)  # fmt: skip
    columns = [f"cost of one 1 ms step in steady running (10-40 ms, {REPEATS} runs)", "median (ms wall)", "min"]
    return dict(
        name="dem_fmu",
        title="BearingDEM.fmu: the 6208 operating point and the cost of a doStep",
        about=__doc__.split("\n", 2)[2].split("Run:")[0],
        blocks=[
            dict(text=text, values=values),
            dict(table=dict(columns=columns, formats=[None, "{:.3f}", "{:.3f}"], rows=costs)),
            dict(text=cost, values=cost_values),
        ],
        metrics=[metric(KEY, 1e-3 * fmu, "s", "timing", target=1e-3 * TARGET_MS)],
    )


def main(argv=None):
    cli(measure, "dem_fmu")


if __name__ == "__main__":
    main()
