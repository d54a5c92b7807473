"""Quasi-static fidelity against the textbook thrust-load case of the 218 angular-contact ball bearing (Hamrock &
Anderson, NASA RP-1105, 1983, thrust load; Hamrock & Dowson, NASA TM-81691, 1981, ch. 3): the sources' closed form,
solved independently of the model, against the model's five-DOF solution. The case, what is and is not compared
and the tolerances (1e-13 rad on the angles, 1e-12 relative on the rest): tests/cases/thrust_218.py,
which the report's reference table renders as well.
"""

import pytest

from tests.cases import outside, thrust_218
from tests.cases.thrust_218 import THRUST_LOADS, model


@pytest.fixture(scope="module", params=["exact", "approximate"])
def bearing(request):
    return request.param, model(request.param)


@pytest.mark.parametrize("F_a", THRUST_LOADS)
def test_218_thrust_contact_angle_ball_load_deflection_and_stiffness(bearing, F_a):
    """Contact angles beta, ball loads Q = F_a/(Z sin beta), axial deflection delta_a and axial stiffness
    K[3,3] = dF_a/d(delta_a) of the sources' thrust-load closed form, 500 to 8000 lbf. Our z is the sources'
    delta_a: z = 0 where the balls touch at the free contact angle (docs/quasistatic.md section 1); our K is the
    condensed analytic stiffness of the five DOF, not a difference quotient. Tolerances: module docstring."""
    hertz, qs = bearing
    comparisons = thrust_218.load_comparisons(qs, hertz, F_a)
    assert len(comparisons) == 6
    assert not outside(comparisons), outside(comparisons)
