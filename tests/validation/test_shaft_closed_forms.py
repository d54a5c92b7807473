"""The shaft model's Timoshenko elements against the closed forms of uniform steel beams: the case, its references
and its tolerance of 0.5 % with their grounds are in tests/cases/shaft_closed_form.py (the report's first table
shows the same comparisons)."""

import numpy as np
import pytest

from tests.cases import outside
from tests.cases import shaft_beams as sb
from tests.cases import shaft_closed_form as case

pytestmark = pytest.mark.validation


def test_uniform_beams_match_their_closed_forms():
    comparisons = case.compare()
    assert len(comparisons) == 18
    assert not outside(comparisons)


def test_the_free_beams_rigid_modes_are_not_reported():
    _, out = case.free_beam()
    # two translations and two tilts have no strain energy (the axial translation's roots are real): passed over
    assert out["rigid_modes"] >= 4
    assert np.isnan(out["compliance_radial"]) and np.isnan(out["compliance_axial"])


@pytest.mark.parametrize("d_i", [0.0, case.HOLLOW_BORE])
def test_the_stubby_beams_need_shear_and_rotary_inertia(d_i):
    L, d = case.STUBBY
    timoshenko = [sb.timoshenko_pinned(n, L, d, d_i) for n in case.MODES]
    euler = [sb.euler_bernoulli_pinned(n, L, d, d_i) for n in case.MODES]
    assert all(e > 1.04 * t for e, t in zip(euler, timoshenko))  # Euler-Bernoulli 4.7-34 % too high
