"""The shaft model's Timoshenko elements against the closed forms of uniform steel beams (shaft_beams.py), every
degree of freedom kept (modes=None: the element is checked, not the reduction; tests/unit/test_shaft_model.py checks
the reduction against this full model).

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
- Slender beam on elastic supports, two seats of k = 100 and 1000 E I / L^3 radially (2.6 and 26 kN/m), against
  the roots of the Euler-Bernoulli beam's frequency determinant with translational springs at both ends (w'' = 0,
  E I w''' = -k w at one end, +k w at the other: the boundary terms of the beam's and springs' energy;
  shaft_beams.py), solved by brentq: the first three modes, the rigid beam's bounce and rocking bent by its
  flexibility and the first bending mode; the same 0.5 %. Measured: -0.002, -0.003, -0.006 % at 100;
  -0.003, -0.010, -0.016 % at 1000.
Supports are seats with 1e12 N/m radially (pinned: no moment stiffness) and axially at one end: 1e9 times the
beams' E I / L^3, a frequency error below 1e-8.

The references' own uncertainty: the closed forms are evaluated in double precision (1e-15), but for the free-free
beam's roots, printed to nine digits (half a unit of the last digit, doubled by the square), and for the
spring-supported beam's, solved to 1e-14.
"""

import tempfile
from pathlib import Path

import numpy as np

from spindle.shaft import ShaftModel
from spindle.shaft.model import WHIRL_AXIAL

from . import shaft_beams as sb
from .comparison import Comparison, ReferenceCase, half_unit

RIGID = 1.0e12  # N/m
TOLERANCE = 5e-3  # relative: the grounds are in the module docstring
ROUNDING = 1e-15  # relative: a closed form evaluated in double precision
MODES = (1, 2, 3)
SLENDER = (4.0, 0.02)  # m: length, diameter
STUBBY = (0.5, 0.1)  # m
HOLLOW_BORE = 0.06  # m
SPRING_KAPPAS = (100.0, 1000.0)  # k L^3 / (E I) of the elastic supports: bounce and rocking below the first bending
ROOT_TOLERANCE = 1e-14  # relative: brentq's tolerance on the frequency determinant's roots


def bending_frequencies(path, seats):
    """(the distinct bending frequencies (Hz) at rest, the model's outputs): the x and y modes of an axisymmetric
    beam coincide, so every other frequency is kept."""
    out = ShaftModel(path, modes=None).evaluate(0.0, seats, critical_speeds=False)
    f = out["frequencies"][out["whirl"] != WHIRL_AXIAL]
    return f[0::2], out


def pinned_file(directory, L, d_o, d_i=0.0):
    """A shaft file of a uniform beam on two seats at its ends, and those seats (pinned: no moment stiffness)."""
    path = sb.shaft_file(Path(directory) / "pinned.toml", [(L, d_o, d_i, 40)], seats=(0.0, L), tip=L / 2)
    return path, np.array([sb.seat_matrix(RIGID, RIGID), sb.seat_matrix(RIGID)])


def spring_supported_frequencies(L, d_o, k):
    """The bending frequencies (Hz) of a uniform beam on two seats at its ends, each k (N/m) radially (no moment
    stiffness; rigid axially at one end)."""
    with tempfile.TemporaryDirectory() as directory:
        path = sb.shaft_file(Path(directory) / "springs.toml", [(L, d_o, 0.0, 40)], seats=(0.0, L), tip=L / 2)
        return bending_frequencies(path, np.array([sb.seat_matrix(k, RIGID), sb.seat_matrix(k)]))[0]


def free_file(directory, L, d_o):
    """A shaft file of a uniform beam without seats."""
    return sb.shaft_file(Path(directory) / "free.toml", [(L, d_o, 0.0, 40)], tip=0.0), np.zeros((0, 5, 5))


def pinned_frequencies(L, d_o, d_i=0.0):
    with tempfile.TemporaryDirectory() as directory:
        return bending_frequencies(*pinned_file(directory, L, d_o, d_i))[0]


def free_beam():
    """(the free-free slender beam's bending frequencies (Hz), the model's outputs)."""
    with tempfile.TemporaryDirectory() as directory:
        return bending_frequencies(*free_file(directory, *SLENDER))


def free_free_uncertainty(n):
    """The relative uncertainty of f_n ~ (beta_n L)^2 from the root printed to nine digits."""
    root = f"{sb.FREE_FREE_BETA_L[n - 1]:.9g}"
    return 2.0 * half_unit(root) / float(root)


def comparisons(label, measured, reference, uncertainty):
    return [
        Comparison(f"{label}, mode {n} (Hz)", float(f), ref, u, TOLERANCE)
        for n, f, ref, u in zip(MODES, measured, reference, uncertainty)
    ]


def compare():
    L, d = SLENDER
    rounding = [ROUNDING] * len(MODES)
    out = comparisons(
        "slender pinned, Euler-Bernoulli",
        pinned_frequencies(L, d),
        [sb.euler_bernoulli_pinned(n, L, d) for n in MODES],
        rounding,
    )
    out += comparisons(
        "slender free, Euler-Bernoulli",
        free_beam()[0],
        [sb.euler_bernoulli_free(n, L, d) for n in MODES],
        [free_free_uncertainty(n) for n in MODES],
    )
    _, I, _ = sb.section_properties(d)
    for kappa in SPRING_KAPPAS:
        k = kappa * sb.E * I / L**3
        reference = sb.euler_bernoulli_spring_supported(len(MODES), L, d, k)
        label = f"slender on springs k L^3 / E I = {kappa:g}, Euler-Bernoulli"
        out += comparisons(label, spring_supported_frequencies(L, d, k), reference, [ROOT_TOLERANCE] * len(MODES))
    L, d = STUBBY
    for label, d_i in (("stubby pinned, Timoshenko", 0.0), ("stubby hollow pinned, Timoshenko", HOLLOW_BORE)):
        reference = [sb.timoshenko_pinned(n, L, d, d_i) for n in MODES]
        out += comparisons(label, pinned_frequencies(L, d, d_i), reference, rounding)
    return out


def evaluation():
    """One evaluation of the full (unreduced) stubby beam at rest, as compared."""
    with tempfile.TemporaryDirectory() as directory:
        path, seats = pinned_file(directory, *STUBBY)
        model = ShaftModel(path, modes=None)  # reads the file once
    return lambda: model.evaluate(0.0, seats, critical_speeds=False)


CASE = ReferenceCase(
    "shaft_closed_form",
    "spindle shaft",
    "bending frequencies of uniform beams, slender and stubby, solid and hollow",
    "Blevins (1979) Table 8-1 (Euler-Bernoulli); Timoshenko (1921), Han, Benaroya & Wei (1999) (simply supported)",
    compare,
    evaluation,
)
