"""Outside-Hertz capacitance against the published closed-form gap around a circular Hertz contact.

Source: Johnson 1985, Contact Mechanics, section 3.4: the normal displacement of the Hertz pressure
p0 (1 - r^2/a^2)^(1/2) outside the loaded circle (r > a) is u = (1 - nu^2)/E p0/(2a) [(2a^2 - r^2) asin(a/r)
+ a (r^2 - a^2)^(1/2)]; with the approach delta = a^2/R and the undeformed gap r^2/(2R) the separation of
the loaded sphere and flat is
  g(r) = (1/(pi R)) [a (r^2 - a^2)^(1/2) - (2a^2 - r^2) acos(a/r)]
(the same expression is the Hertz separation used in the DMT/Maugis adhesion models). For a circular
contact the capacitance of the gap is then a one-dimensional integral over r, computed here with scipy:
  C = eps_0 int_a^r_oil 2 pi r [ (eps_r/2) / h + (1 + (eps_r - 1) h_c / h) / (2 h) ] dr,  h = h_c + g(r),
inlet half in oil, cavitated outlet half with streamers (the model's assumptions, docs/decisions.md);
r_oil where h = oil_gap. The kernel works on the elliptical form in confocal coordinates with its own
quadrature; for a circle its gap coefficients must reproduce this g(r).

Tolerance 1 %: the kernel's quadrature error (trapezoid in the confocal coordinate, 16 nodes a decade);
measured +0.004 %, +0.17 %, +0.27 % on the three cases below.
"""

import math

import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from bearing_fmu.kernels.capacitance import EPSILON_0, outside_hertz_capacitance
from bearing_fmu.kernels.hertz import hertz_coefficients_exact, hertz_contact, reduced_modulus

R_BALL = 6.35e-3  # m: a 1/2 in ball on a flat (R_x = R_y)
E_RED = reduced_modulus(208e9, 0.3, 208e9, 0.3)
EPS_R = 2.2
TOL = 0.01


def separation(r, a, R):
    """Johnson's gap (m) between a sphere of radius R and a flat pressed to the contact radius a, at r > a."""
    return (a * math.sqrt(r * r - a * a) - (2 * a * a - r * r) * math.acos(a / r)) / (math.pi * R)


@pytest.mark.parametrize("Q, h_c, oil_gap", [(20.0, 0.5e-6, 5e-6), (500.0, 0.2e-6, 10e-6), (2000.0, 50e-9, 30e-6)])
def test_circular_contact_against_closed_form_gap(Q, h_c, oil_gap):
    a, b, delta, p = hertz_contact(Q, R_BALL, R_BALL, E_RED, *hertz_coefficients_exact(R_BALL, R_BALL))
    assert a == pytest.approx(b, rel=1e-9, abs=0) and delta == pytest.approx(a * a / R_BALL, rel=1e-9, abs=0)

    def h(r):
        return h_c + separation(r, a, R_BALL)

    r_oil = brentq(lambda r: h(r) - oil_gap, a * (1 + 1e-12), 10 * math.sqrt(2 * R_BALL * oil_gap) + a)

    def integrand(v):  # r = a (1 + exp(v)): resolves the edge layer where g ~ h_c
        r = a * (1.0 + math.exp(v))
        hr = h(r)
        return 2 * math.pi * r * (0.5 * EPS_R / hr + 0.5 * (1 + (EPS_R - 1) * h_c / hr) / hr) * a * math.exp(v)

    expected = EPSILON_0 * quad(integrand, math.log(1e-12), math.log(r_oil / a - 1), epsrel=1e-10, limit=200)[0]
    got = outside_hertz_capacitance(EPS_R, a, b, p, E_RED, h_c, oil_gap, 1e-8)
    assert got == pytest.approx(expected, rel=TOL, abs=0), f"{got * 1e12:.4f} pF vs {expected * 1e12:.4f} pF"
