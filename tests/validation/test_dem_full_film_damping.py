"""The DEM's step against the squeeze damping of a full film at low speed.

B7214C with iso_vg68_mineral at 293 K (cold oil), 800 N axial, run up from rest at 523.6 rad/s^2 (the spindle
rig's 0 -> 10 000 rpm in 2 s). Near 6 rad/s the film parameter of the contacts passes 3 and the normal damping
jumps from the mixed value (series with the hysteretic 1.5 alpha_e Q, ~20 N.s/m) to the fluid value of Guessasma
& Machado (2018, eq. 5), (3 pi eta a / sqrt 2)(R_b / h_min)^1.5 ~ 7500 N.s/m: the balls become overdamped
(damping ratio ~4). Measured: (c_i + c_o) dt / m up to 0.43 integrates the interval's dissipation correctly,
0.48 and above gives a spurious one (1.1 N.m instead of 0.095 N.m at dt = 1 us; 5.3 N.m at 1.35 us).
"""

import math

import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import DemModel, DemUnstableError

RAMP = 1047.1975511965977 / 2.0  # rad/s^2
T_COLD = 293.15


@pytest.fixture(scope="module")
def before_full_film():
    """The state at 10 ms (5.2 rad/s, mixed film), reached with the automatic step."""
    model = DemModel("B7214C", "iso_vg68_mineral")
    model.advance(0.01, omega=RAMP * 0.01, F_z=800.0, T_oil=T_COLD)
    assert (model.trib[s.T_REGIME] < 2).all()
    return model.get_state()


def _interval(state, **kwargs):
    model = DemModel("B7214C", "iso_vg68_mineral", **kwargs)
    model.set_state(state)
    out = model.advance(0.02, omega=RAMP * 0.02, F_z=800.0, T_oil=T_COLD)
    return model, out


def test_automatic_step_follows_the_film_into_full_film(before_full_film):
    """The automatic step is planned from the mixed film (5.4 us); the contacts enter full film within the
    10 ms call, the monitor stops it and the call is repeated with the step the full film needs. Its torque
    equals that of a fixed 0.25 us step within 0.5 % (the two integrate the same overdamped balls with
    different steps), and every contact ends in full film."""
    model, out = _interval(before_full_film)
    assert model.step_halvings >= 1
    assert (model.trib[s.T_REGIME][model.trib[s.T_Q] > 0.0] == 2).all()
    _, reference = _interval(before_full_film, dt=0.25e-6)
    print(f"torque {out['torque']:.5f} N.m (dt {model.dt:.3g} s) vs {reference['torque']:.5f} N.m (0.25 us)")
    assert out["torque"] == pytest.approx(reference["torque"], rel=5e-3)
    assert 0.05 < out["torque"] < 0.2


def test_a_fixed_step_too_large_for_the_full_film_is_stopped(before_full_film):
    """The papers' 1 us: (c_i + c_o) dt / m reaches 0.46 when the film turns full; the monitor stops with the
    cause, the ball and a step that works (it gave a spurious 1.1 N.m before the check)."""
    with pytest.raises(DemUnstableError, match=r"normal damping is beyond .* use dt <= ") as info:
        _interval(before_full_film, dt=1e-6)
    suggested = float(str(info.value).split("use dt <= ")[1].split(" s")[0])
    assert suggested < 0.7e-6
    _, out = _interval(before_full_film, dt=suggested)
    assert math.isfinite(out["torque"]) and 0.05 < out["torque"] < 0.2
