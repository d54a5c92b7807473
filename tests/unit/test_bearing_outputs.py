"""kernels.bearing_outputs against its twin (tests/reference/ref_bearing_outputs.py), on random ball sets
and on a quasi-static solution, and the facade's outputs against the declarations.

Tolerance: the kernel sums the weighted cage speed in ball order, the twin with math.fsum (exactly
rounded); with Z <= 30 positive terms the two differ by at most a few units in the last place, so
1e-13 relative is ample. Every other value is a copy or the same three-term formula: equal to 1e-15.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.kernels import bearing_outputs as bo
from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.kernels import jones_harris
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.reference import ref_bearing_outputs as rb


def test_every_public_kernel_has_a_twin_and_the_codes_match():
    kernels = [n for n, f in vars(bo).items() if hasattr(f, "py_func") and f.py_func.__module__ == bo.__name__]
    assert kernels and all(callable(getattr(rb, n, None)) for n in kernels), kernels
    for name in (
        "SRC_OUT",
        "SRC_D",
        "SRC_F",
        "SRC_K",
        "SRC_BALL_SET",
        "BS_ALPHA_I",
        "BS_CAGE",
        "BS_MU_REQ_I",
        "BS_MU_REQ_O",
        "BS_SIZE",
    ):
        assert getattr(bo, name) == getattr(rb, name), name
    for name in ("BQ_Q_I", "BQ_Q_O", "BQ_A_I", "BQ_A_O", "BQ_BETA", "BQ_W_M", "BQ_W_R", "BQ_MU_REQ_I", "BQ_MU_REQ_O"):
        assert getattr(jones_harris, name) == getattr(rb, name), name


def random_balls(rng, Z, inner_loaded):
    balls = np.zeros((jones_harris.BQ_SIZE, Z))
    balls[jones_harris.BQ_Q_I] = rng.uniform(0.0, 900.0, Z) * (rng.uniform(size=Z) < 0.7) if inner_loaded else 0.0
    balls[jones_harris.BQ_Q_O] = rng.uniform(0.0, 1200.0, Z)
    balls[jones_harris.BQ_A_I] = rng.uniform(0.0, 0.6, Z)
    balls[jones_harris.BQ_A_O] = rng.uniform(0.0, 0.6, Z)
    balls[jones_harris.BQ_BETA] = rng.uniform(-0.5, 0.5, Z)
    balls[jones_harris.BQ_W_M] = rng.uniform(400.0, 460.0, Z)
    balls[jones_harris.BQ_W_R] = rng.uniform(-4000.0, -3000.0, Z)
    balls[jones_harris.BQ_MU_REQ_I] = rng.uniform(0.0, 0.1, Z)
    balls[jones_harris.BQ_MU_REQ_O] = rng.uniform(0.0, 0.1, Z)
    return balls


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    Z=st.integers(1, 30),
    inner=st.booleans(),
    omega=st.sampled_from([-1047.2, 0.0, 523.6]),
)
def test_summary_random(seed, Z, inner, omega):
    balls = random_balls(np.random.default_rng(seed), Z, inner)
    got, ref = np.zeros(bo.BS_SIZE), np.zeros(bo.BS_SIZE)
    bo.ball_set_summary(balls, omega, 7, got)
    rb.ball_set_summary(balls, omega, 7, ref)
    for k in range(bo.BS_SIZE):
        # the cage speed is a weighted mean (sums in ball order vs exactly rounded), and the frequencies from it
        rtol = 1e-13 if k in (bo.BS_CAGE, bo.BS_FTF, bo.BS_BPFO, bo.BS_BPFI) else 1e-15
        assert got[k] == pytest.approx(ref[k], rel=rtol, abs=0.0), k


def test_first_of_equal_loads_is_the_most_loaded():
    balls = random_balls(np.random.default_rng(1), 6, True)
    balls[jones_harris.BQ_Q_I] = [0.0, 5.0, 5.0, 1.0, 0.0, 5.0]
    summary = np.zeros(bo.BS_SIZE)
    bo.ball_set_summary(balls, 1.0, 0, summary)
    assert summary[bo.BS_ALPHA_I] == balls[jones_harris.BQ_A_I, 1]


@pytest.mark.parametrize("scene_file", ["quasi_static.toml", "quasi_static_displacement.toml"])
def test_facade_outputs_equal_the_twin_fill(scene_file):
    """The facade's output array is the twin's fill of the same solver and contact arrays; a NaN in a
    source array is reported at its slot."""
    model = QuasiStaticModel(scene=Scene.from_toml(SCENES_DIR / scene_file))
    inputs = {"omega": 1047.2, "F_y": 300.0, "F_z": 800.0, "y": 2e-6, "z": 20e-6}  # radial on the line of ball 1
    got = model.evaluate(**{k: v for k, v in inputs.items() if k in model.input_names})
    ref = np.zeros(len(model.outputs))
    bad = rb.quasi_static_outputs(
        model.balls,
        1047.2,
        model.status[1],
        model.out,
        model.d,
        model.F,
        model.K.reshape(-1),
        model._trunc,
        model._source,
        model._index,
        np.zeros(bo.BS_SIZE),
        ref,
    )
    assert bad == -1
    for k, name in enumerate(model.output_names):
        if model.outputs[k].source[0] == "life":  # filled after this kernel (tests/unit/test_rating_life_option.py)
            continue
        rtol = 1e-13 if name in ("omega_cage", "FTF", "BPFO", "BPFI") else 0.0  # the cage speed and its uses
        assert got[name] == pytest.approx(ref[k], rel=rtol, abs=0.0), name
    out = model.out.copy()
    out[ck.CO_LAMBDA_I] = math.nan
    values = np.zeros(len(model.outputs))
    args = (model.balls, 1.0, 3, out, model.d, model.F, model.K.reshape(-1), model._trunc, model._source, model._index)
    k_nan = model.output_names.index("Lambda_inner")
    assert bo.quasi_static_outputs(*args, np.zeros(bo.BS_SIZE), values) == k_nan
    assert rb.quasi_static_outputs(*args, np.zeros(bo.BS_SIZE), values.copy()) == k_nan
