"""The shaft model's Timoshenko elements against the closed forms of uniform steel beams (tests/cases/shaft_beams.py),
every degree of freedom kept (modes=None: the element is checked, not the reduction; test_shaft_model.py checks the
reduction against this full model).

- Slender beam (L = 4 m, d = 20 mm, L/d = 200), 40 elements, pinned-pinned and free-free, against Euler-Bernoulli:
  f_n = (lambda_n / L)^2 sqrt(E I / (rho A)) / 2 pi, lambda_n = n pi (pinned) or the roots 4.730, 7.853, 10.996 of
  cos(x) cosh(x) = 1 (free; Blevins 1979, Table 8-1). The Timoshenko beam lies below Euler-Bernoulli by about
  (n pi r_g / L)^2 (1 + E / kappa G) / 2 (r_g = d / 4): 0.03 % for the third mode here; with the discretisation
  error of 40 cubic elements (1e-6 for the third mode) far below, 0.5 % leaves the rest of the margin to a wrong
  matrix entry, which moves a frequency by percents. Measured: pinned -0.003, -0.012, -0.027 %; free -0.007,
  -0.019, -0.037 %.
- Stubby beam (L = 0.5 m, d = 100 mm, L/d = 5; and hollow, d_i = 60 mm), pinned-pinned, against the lower root of
  Timoshenko's frequency equation of the simply supported beam (Timoshenko 1921; Han, Benaroya & Wei 1999, the
  hinged-hinged case), with the model's own shear coefficient (Cowper 1966): exact for this theory, so the 0.5 %
  covers the discretisation only. Here Euler-Bernoulli is 4.7, 17 and 34 % too high: shear and rotary inertia are
  in. Measured: solid -0.013, -0.024, +0.004 %; hollow -0.009, +0.003, +0.071 %.
Supports are seats with 1e12 N/m radially (pinned: no moment stiffness) and axially at one end: 1e9 times the
beams' E I / L^3, a frequency error below 1e-8.
"""

import numpy as np
import pytest

from spindle.shaft import ShaftModel
from spindle.shaft.model import WHIRL_AXIAL
from tests.cases import shaft_beams as sb

pytestmark = pytest.mark.validation
RIGID = 1.0e12  # N/m


def bending_frequencies(path, seats):
    """The distinct bending frequencies (Hz) at rest: the x and y modes of an axisymmetric beam coincide."""
    model = ShaftModel(path, modes=None)
    out = model.evaluate(0.0, seats, critical_speeds=False)
    f = out["frequencies"][out["whirl"] != WHIRL_AXIAL]
    pairs = 2 * (f.size // 2)
    assert np.allclose(f[0:pairs:2], f[1:pairs:2], rtol=1e-8)  # each a pair
    return f[0::2], out


def pinned(tmp_path, L, d_o, d_i=0.0):
    path = sb.shaft_file(tmp_path / "pinned.toml", [(L, d_o, d_i, 40)], seats=(0.0, L), tip=L / 2)
    return bending_frequencies(path, np.array([sb.seat_matrix(RIGID, RIGID), sb.seat_matrix(RIGID)]))[0]


def test_slender_pinned_beam_is_euler_bernoulli(tmp_path):
    f = pinned(tmp_path, 4.0, 0.02)
    reference = [sb.euler_bernoulli_pinned(n, 4.0, 0.02) for n in (1, 2, 3)]
    assert f[:3] == pytest.approx(reference, rel=5e-3)


def test_slender_free_beam_is_euler_bernoulli_and_its_rigid_modes_are_not_reported(tmp_path):
    path = sb.shaft_file(tmp_path / "free.toml", [(4.0, 0.02, 0.0, 40)], tip=0.0)
    f, out = bending_frequencies(path, np.zeros((0, 5, 5)))
    reference = [sb.euler_bernoulli_free(n, 4.0, 0.02) for n in (1, 2, 3)]
    assert f[:3] == pytest.approx(reference, rel=5e-3)
    # two translations and two tilts have no strain energy (the axial translation's roots are real): passed over
    assert out["rigid_modes"] >= 4
    assert np.isnan(out["compliance_radial"]) and np.isnan(out["compliance_axial"])


@pytest.mark.parametrize("d_i", [0.0, 0.06])
def test_stubby_pinned_beam_is_timoshenko(tmp_path, d_i):
    f = pinned(tmp_path, 0.5, 0.1, d_i)
    reference = [sb.timoshenko_pinned(n, 0.5, 0.1, d_i) for n in (1, 2, 3)]
    assert f[:3] == pytest.approx(reference, rel=5e-3)
    euler = [sb.euler_bernoulli_pinned(n, 0.5, 0.1, d_i) for n in (1, 2, 3)]
    assert all(e > 1.04 * t for e, t in zip(euler, reference))  # the case needs shear and rotary inertia
