"""The kernel recorder of the benchmarks (benchmarks/kernel_replay.py), whose replayed calls are the compiled floor the
facades' and FMUs' step times are judged against: it must see every kernel call a step makes, whether the facade
calls the kernel through its module or by a name imported into its own, and put the kernels back afterwards."""

import numpy as np

from bearing_fmu.kernels import jones_harris
from bearing_fmu.models import quasi_static
from bearing_fmu.models.quasi_static import QuasiStaticModel
from benchmarks.kernel_replay import BEARING_PACKAGES, KernelRecorder, kernel_names, replay_time


def test_the_recorder_sees_kernels_called_through_their_module_and_by_imported_name():
    """The quasi-static step under traction race control calls jones_harris.solve_quasistatic through its module and
    lubricant_state by the name quasi_static imported; both are recorded, the replay runs them, and both names are
    the original dispatchers again after the block."""
    model = QuasiStaticModel("B7214C", "iso_vg68_mineral", race_control="traction")
    inputs = dict(omega=1047.2, F_z=800.0, T_oil=313.15)
    model.evaluate(**inputs)  # compiled before recording
    solve, lubricant_state = jones_harris.solve_quasistatic, quasi_static.lubricant_state
    with KernelRecorder(BEARING_PACKAGES) as recorder:
        model.evaluate(**inputs)
    names = kernel_names(recorder.calls)
    assert names.get("solve_quasistatic", 0) >= 1, names
    assert names.get("lubricant_state", 0) == 1, names
    assert jones_harris.solve_quasistatic is solve and quasi_static.lubricant_state is lubricant_state
    assert replay_time(recorder.calls, repeats=1) > 0.0
    assert np.isfinite(model.balls).all()
