"""Every race-control hypothesis says what friction it assumes (models.friction, outputs mu_required_*).

The 218 angular-contact bearing of the textbook thrust cases (40 deg, 16 balls) under 8.9 kN with the Guessasma oil
(limiting traction coefficient 0.06): outer-race control holds the balls' gyroscopic moments with the outer contacts'
friction alone, F = |Q_i sin a_i - Q_o sin a_o| / cos a_o from the axial balance of a ball (docs/quasistatic.md,
section 2), which at 8 000 rpm is 0.077-0.078 of Q_o: above what the oil carries.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import jones_harris
from bearing_fmu.models.limits import InputError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

B218 = "tests/validation/data/angular_218_textbook.toml"
SCENE = Scene(name="friction", fidelity="quasi_static", gyroscopic=True)
RPM = math.pi / 30.0


def test_required_coefficient_is_the_friction_of_the_ball_balance():
    """Under outer-race control mu_required_outer is the largest |Q_i sin a_i - Q_o sin a_o| / (Q_o cos a_o) of the
    balls (the axial balance, to rounding: 1e-9), the inner one 0; at 8 000 rpm it is above 0.06 (0.0775)."""
    m = QuasiStaticModel(B218, "guessasma_oil", scene=SCENE, race_control="outer")
    out = m.evaluate(omega=8000 * RPM, F_z=8900.0)
    b = m.balls
    demand = np.abs(
        b[jones_harris.BQ_Q_I] * np.sin(b[jones_harris.BQ_A_I])
        - b[jones_harris.BQ_Q_O] * np.sin(b[jones_harris.BQ_A_O])
    )
    expected = (demand / (b[jones_harris.BQ_Q_O] * np.cos(b[jones_harris.BQ_A_O]))).max()
    assert out["mu_required_outer"] == pytest.approx(expected, rel=1e-9)
    assert out["mu_required_inner"] == 0.0
    assert 0.077 < out["mu_required_outer"] < 0.078


def test_a_hypothesis_warns_once_on_entry_above_the_limit_and_traction_never():
    """5 000 rpm: 0.040, no warning; 8 000 rpm: a warning naming the race control, the contact, the value, the limit
    and race_control = 'traction'; 8 100 rpm, still above: no second warning; back to 5 000 and to 8 000: warned again.
    The traction race control asks nothing (0) and never warns."""
    m = QuasiStaticModel(B218, "guessasma_oil", scene=SCENE, race_control="outer")
    said = []
    for rpm in (5000.0, 8000.0, 8100.0, 5000.0, 8000.0):
        m.evaluate(omega=rpm * RPM, F_z=8900.0)
        said.append([w for w in m.warnings if "traction coefficient" in w])
    assert [len(w) for w in said] == [0, 1, 0, 0, 1]
    for text in ("race control 'outer'", "outer contact", "0.07755", "0.06", "race_control = 'traction'"):
        assert text in said[1][0], text
    t = QuasiStaticModel(B218, "guessasma_oil", scene=SCENE, race_control="traction")
    out = t.evaluate(omega=8000 * RPM, F_z=8900.0)
    assert out["mu_required_inner"] == out["mu_required_outer"] == 0.0
    assert not [w for w in t.warnings if "traction coefficient" in w]


@pytest.mark.parametrize("F_z", [200.0, 400.0])
def test_inner_race_control_with_every_inner_contact_open_is_refused(F_z):
    """B7214C at 10 000 rpm under 200 and 400 N: inner-race control opens every inner contact (the thrust would be
    carried by the friction of the gyroscopic moment alone): refused, naming the race control and the inputs; the
    model's state is unchanged, so 800 N still solves from it."""
    m = QuasiStaticModel("B7214C", "iso_vg68_mineral", scene=SCENE, race_control="inner")
    m.evaluate(omega=10000 * RPM, F_z=800.0)
    d = m.d.copy()
    with pytest.raises(InputError, match=r"race control 'inner'.*no ball touches the inner race.*F_z = "):
        m.evaluate(omega=10000 * RPM, F_z=F_z)
    assert np.array_equal(m.d, d)
    assert m.evaluate(omega=10000 * RPM, F_z=800.0)["Q_max_inner"] > 0.0


def test_inner_race_control_asking_more_than_any_friction_is_refused():
    """218 at 8 000 rpm under 3 kN: inner-race control asks 1.16 of an inner contact, friction carrying the load
    (models.friction.MU_IMPOSSIBLE = 1): refused with the value; at 4 kN it asks 0.67 and is only warned of."""
    m = QuasiStaticModel(B218, "guessasma_oil", scene=SCENE, race_control="inner")
    assert m.evaluate(omega=8000 * RPM, F_z=4000.0)["mu_required_inner"] == pytest.approx(0.672, abs=1e-3)
    with pytest.raises(InputError, match=r"race control 'inner': it asks a traction coefficient of 1\.16"):
        m.evaluate(omega=8000 * RPM, F_z=3000.0)


def test_a_jump_of_the_contact_angle_under_a_small_input_step_is_warned():
    """FrictionWatch on two solutions whose most loaded ball's inner angle differs by 22 deg: warned when the inputs
    changed by 1.5 % (670 N after 660 N), not when they changed by half (a large input step, not a jump)."""
    from bearing_fmu.models.friction import FrictionWatch

    def balls(alpha_deg):
        b = np.zeros((jones_harris.BQ_SIZE, 3))
        b[jones_harris.BQ_Q_I] = (10.0, 20.0, 10.0)
        b[jones_harris.BQ_A_I] = math.radians(alpha_deg)
        return b

    watch = FrictionWatch("inner", 0.06, "oil")

    def said(alpha_deg, F_z):
        return watch.warnings((0.0, 0.0), math.radians(alpha_deg), balls(alpha_deg), [1047.2, F_z])

    assert said(32.9, 660.0) == []
    jump = said(55.2, 670.0)
    assert len(jump) == 1 and "32.9 deg to 55.2 deg" in jump[0]
    assert said(32.9, 335.0) == []
