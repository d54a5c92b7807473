"""kernels.capacitance against its twin tests/reference/ref_capacitance.py.

Closed forms: RTOL = 1e-12 (measured: exact or within 2 ulp). The outside-Hertz capacitance is a quadrature
(a geometric grid of the confocal coordinate, closed forms in the angle) against the twin's adaptive scipy
quadrature of Johnson's gap: RTOL_OUTSIDE = 1e-2, measured at most 3.3e-3 over the grid below (the trapezoid
in the confocal coordinate, 16 nodes a decade; 2.1e-3 at 24, 6.4e-4 at 48) and 4.6e-3 over 14 random contacts.
The twin uses the CODATA 2018 vacuum permittivity, the value the kernel documents; scipy.constants carries
CODATA 2022, 6.8e-10 relative higher, which is checked separately so that this revision does not hide in the
tolerance.
"""

import functools
import math

import numpy as np
import pytest
import scipy.constants
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import capacitance as ck
from bearing_fmu.kernels import lubricant as lk
from tests.reference import ref_capacitance as rc
from tests.reference import ref_hertz as rh
from tests.unit._compare import assert_close

RTOL = 1e-12
RTOL_OUTSIDE = 1e-2
FAST = settings(max_examples=50, deadline=None)
# finite, normal floats: subnormal inputs (< 2.2e-308) have no physical meaning and lose precision
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
K_CM = lk.clausius_mossotti_constant(2.2, 870.0)
H_FLOOR = 10e-9


def test_constants():
    assert ck.EPSILON_0 == rc.epsilon_0
    assert abs(rc.epsilon_0 - scipy.constants.epsilon_0) <= 1e-9 * scipy.constants.epsilon_0  # CODATA 2018 vs 2022
    assert (ck.PRESSURE_MAX, ck.PRESSURE_MEAN) == (rc.PRESSURE_MAX, rc.PRESSURE_MEAN)


@pytest.mark.parametrize("choice", [ck.PRESSURE_MAX, ck.PRESSURE_MEAN])
@pytest.mark.parametrize("p_max", [0.0, 1e8, 0.34e9, 2.17e9, 4.2e9])
def test_contact_permittivity_on_grid(choice, p_max):
    eps_r = ck.contact_permittivity(K_CM, 870.0, p_max, choice)
    assert_close(eps_r, rc.contact_permittivity(K_CM, 870.0, p_max, choice), RTOL, f"eps_r({p_max}, {choice})")
    if p_max == 0.0:
        assert eps_r == pytest.approx(2.2, rel=1e-14, abs=0)  # ambient calibration point
    else:
        assert eps_r > 2.2
        if choice == ck.PRESSURE_MEAN:  # the mean pressure compresses less
            assert eps_r < ck.contact_permittivity(K_CM, 870.0, p_max, ck.PRESSURE_MAX)


@pytest.mark.parametrize("h_c", [math.inf, 1e-5, 1e-6, 2e-7, H_FLOOR, 5e-9, 0.0])
@pytest.mark.parametrize("a, b", [(0.0, 0.0), (0.0, 2e-4), (1.9e-3, 2.0e-4), (6e-4, 5e-4)])
def test_contact_capacitance_on_grid(h_c, a, b):
    got = ck.contact_capacitance(2.3, a, b, h_c, H_FLOOR)
    assert_close(got, rc.contact_capacitance(2.3, a, b, h_c, H_FLOOR), RTOL, f"C(a={a}, b={b}, h={h_c})")
    if a * b == 0.0 or h_c == math.inf:
        assert got == 0.0  # open contact
    elif h_c <= H_FLOOR:  # film below the floor: bounded by the floor
        assert got == ck.contact_capacitance(2.3, a, b, H_FLOOR, H_FLOOR) > 0.0
    else:
        assert got == pytest.approx(8.8541878128e-12 * 2.3 * math.pi * a * b / h_c, rel=1e-14, abs=0)


def test_ball_and_bearing_capacitance_on_grid():
    Ci = np.array([40e-12, 0.0, 12e-12, 3e-12, 0.0])
    Co = np.array([60e-12, 8e-12, 0.0, 5e-12, 0.0])
    for ci, co in zip(Ci, Co):
        got = ck.ball_capacitance(ci, co)
        assert_close(got, rc.ball_capacitance(ci, co), RTOL, f"ball({ci}, {co})")
        assert (got == 0.0) == (ci == 0.0 or co == 0.0)  # a ball off either ring contributes nothing
    assert ck.ball_capacitance(40e-12, 60e-12) == pytest.approx(24e-12, rel=1e-14, abs=0)  # series
    for background in (0.0, 30e-12):
        total = ck.bearing_capacitance(Ci, Co, background)
        assert_close(total, rc.bearing_capacitance(Ci, Co, background), RTOL, f"bearing, background {background}")
    assert ck.bearing_capacitance(Ci[:0], Co[:0], 30e-12) == 30e-12  # no ball


@FAST
@given(
    p_max=floats(0.0, 5e9),
    choice=st.sampled_from([0, 1]),
    eps_r0=floats(1.8, 3.0),
    rho0=floats(800.0, 900.0),
    a=floats(1e-5, 5e-3),
    b=floats(1e-5, 5e-4),
    log_h=floats(-9.5, -5.0),
    log_floor=floats(-9.0, -7.0),
)
def test_contact_random(p_max, choice, eps_r0, rho0, a, b, log_h, log_floor):
    K = lk.clausius_mossotti_constant(eps_r0, rho0)
    eps_r = ck.contact_permittivity(K, rho0, p_max, choice)
    assert_close(eps_r, rc.contact_permittivity(K, rho0, p_max, choice), RTOL, "eps_r")
    h, floor = 10.0**log_h, 10.0**log_floor
    assert_close(
        ck.contact_capacitance(eps_r, a, b, h, floor), rc.contact_capacitance(eps_r, a, b, h, floor), RTOL, "C contact"
    )


@FAST
@given(
    C=st.lists(
        st.tuples(st.one_of(st.just(0.0), floats(1e-13, 1e-9)), st.one_of(st.just(0.0), floats(1e-13, 1e-9))),
        min_size=1,
        max_size=40,
    ),
    background=floats(0.0, 1e-10),
)
def test_bearing_random(C, background):
    Ci = np.array([c[0] for c in C])
    Co = np.array([c[1] for c in C])
    assert_close(
        ck.bearing_capacitance(Ci, Co, background), rc.bearing_capacitance(Ci, Co, background), RTOL, "bearing"
    )


def test_compiled_kernels_are_current():
    """contact_permittivity calls kernels of lubricant.py; numba's cache=True checks only the caller's
    own file, so a changed callee can leave stale compiled code (delete bearing_fmu/kernels/__pycache__)."""
    for choice in (ck.PRESSURE_MAX, ck.PRESSURE_MEAN):
        for p in (0.0, 1e9, 3e9):
            assert ck.contact_permittivity(K_CM, 870.0, p, choice) == ck.contact_permittivity.py_func(
                K_CM, 870.0, p, choice
            )


D_6208 = 0.0127  # ball diameter (m), pitch diameter 0.06 m, conformity 0.52 (the 6208 of bearing_fmu/params)
E_STEEL = rh.reduced_modulus(208e9, 0.3, 208e9, 0.3)
# (Rx, Ry) (m): 6208 inner race, outer race (conformity 0.53), ball on a flat (circular contact), ball on a
# slightly curved surface
RADII = {
    "inner": (D_6208 / 2 * (0.06 - D_6208) / 0.06, 0.52 * D_6208 / (2 * 0.52 - 1)),
    "outer": (D_6208 / 2 * (0.06 + D_6208) / 0.06, 0.53 * D_6208 / (2 * 0.53 - 1)),
    "flat": (D_6208 / 2, D_6208 / 2),
    "near_flat": (D_6208 / 2, 1.05 * D_6208 / 2),  # nearly circular: rings cut by the bound take the Gauss rule
}


def _hertz(Q, radii):
    Rx, Ry = RADII[radii]
    a, b, delta, p = rh.hertz_contact(Q, Rx, Ry, E_STEEL, *rh.hertz_coefficients_exact(Rx, Ry))
    return a, b, delta, p


@pytest.mark.parametrize("radii", sorted(RADII))
@pytest.mark.parametrize("Q, h_c, h_oil", [(1000.0, 0.3e-6, 10e-6), (50.0, 1e-6, 3e-6), (3000.0, 0.05e-6, 40e-6)])
def test_outside_hertz_capacitance_against_twin(radii, Q, h_c, h_oil):
    a, b, delta, p = _hertz(Q, radii)
    # the twin's gap reproduces the Hertz curvatures and approach it was built from (Johnson's closed form)
    _, cx, cy, approach = rc.hertz_gap_terms(a, b, p, E_STEEL)
    assert_close((1 / (2 * cx), 1 / (2 * cy), approach), (*RADII[radii], delta), 1e-12, "Hertz terms of the gap")
    args = (2.2, a, b, p, E_STEEL, h_c, h_oil, H_FLOOR)
    assert_close(ck.outside_hertz_capacitance(*args), rc.outside_hertz_capacitance(*args), RTOL_OUTSIDE, str(args))


def test_outside_hertz_capacitance_open_or_dry():
    a, b, _, p = _hertz(1000.0, "inner")
    assert ck.outside_hertz_capacitance(2.2, 0.0, 0.0, 0.0, E_STEEL, 1e-7, 1e-5, H_FLOOR) == 0.0  # open contact
    assert ck.outside_hertz_capacitance(2.2, a, b, p, E_STEEL, math.inf, 1e-5, H_FLOOR) == 0.0  # no film
    assert ck.outside_hertz_capacitance(2.2, a, b, p, E_STEEL, 2e-5, 1e-5, H_FLOOR) == 0.0  # no oil beyond h_c
    # a film below the floor is the floor, as in the Hertz zone
    assert ck.outside_hertz_capacitance(2.2, a, b, p, E_STEEL, 1e-9, 1e-5, H_FLOOR) == ck.outside_hertz_capacitance(
        2.2, a, b, p, E_STEEL, H_FLOOR, 1e-5, H_FLOOR
    )


@pytest.mark.parametrize("radii", ["inner", "outer"])
def test_outside_hertz_capacitance_far_field(radii):
    """Far from the contact the gap is h = h_c + q - delta with the rigid q = x^2/(2 Rx) + y^2/(2 Ry) (the elastic
    displacement decays like 1/distance) and the oil is in full film on the inlet side, a layer h_c thin on the
    outlet side. The integral of dA / (q - q0) over the elliptic annulus between two levels of q is
    2 pi sqrt(Rx Ry) ln of the ratio of q - q0 (dA = 2 pi sqrt(Rx Ry) dq), so doubling the oil's gap increase H
    adds eps_0 (eps_r + 1)/2 2 pi sqrt(Rx Ry) ln 2, whatever the load. At 200 N, H from 20 to 40 um, the
    displacement at the bound is about 5 % of the gap there and the outlet's h_c/h term 1e-3: 2 % tolerance."""
    a, b, _, p = _hertz(200.0, radii)
    Rx, Ry = RADII[radii]
    h_c = 0.1e-6

    def C(H):
        return ck.outside_hertz_capacitance(2.2, a, b, p, E_STEEL, h_c, h_c + H, H_FLOOR)

    slope = 8.8541878128e-12 * (2.2 + 1.0) / 2 * 2 * math.pi * math.sqrt(Rx * Ry)
    assert C(40e-6) - C(20e-6) == pytest.approx(slope * math.log(2.0), rel=0.02, abs=0)
    # and it grows with the oil and with eps_r
    assert 0.0 < C(5e-6) < C(20e-6) < C(40e-6)
    assert ck.outside_hertz_capacitance(2.3, a, b, p, E_STEEL, h_c, 10e-6, H_FLOOR) > C(10e-6 - h_c)


@pytest.mark.parametrize("h_oil", [0.0, 10e-6])
@pytest.mark.parametrize("choice", [ck.PRESSURE_MAX, ck.PRESSURE_MEAN])
def test_lubricated_contact_capacitance_against_twin(choice, h_oil):
    a, b, _, p = _hertz(800.0, "outer")
    args = (K_CM, 870.0, p, choice, a, b, 0.2e-6, H_FLOOR, E_STEEL, h_oil)
    got = ck.lubricated_contact_capacitance(*args)
    assert_close(got, rc.lubricated_contact_capacitance(*args), RTOL if h_oil == 0.0 else RTOL_OUTSIDE, str(args))
    hertz = ck.contact_capacitance(ck.contact_permittivity(K_CM, 870.0, p, choice), a, b, 0.2e-6, H_FLOOR)
    if h_oil == 0.0:  # the Hertz zone alone, bit for bit
        assert got == hertz
    else:  # plus the gap around it, at the ambient permittivity (2.2 at the calibration density)
        assert got - hertz == pytest.approx(
            ck.outside_hertz_capacitance(2.2, a, b, p, E_STEEL, 0.2e-6, h_oil, H_FLOOR), rel=1e-12, abs=0
        )


@settings(max_examples=12, deadline=None, derandomize=True)
@given(
    log_rx=floats(-3.0, -1.5),
    log_ratio=floats(-1.3, 1.6),
    log_q=floats(0.0, 4.0),
    log_hc=floats(-8.3, -5.7),
    log_oil=floats(0.01, 2.5),
)
def test_outside_hertz_capacitance_random(log_rx, log_ratio, log_q, log_hc, log_oil):
    """Any contact (R_y/R_x from 0.05 to 40, so k = a/b on both sides of 1), load, film and oil gap (up to 50 um)."""
    Rx = 10.0**log_rx
    Ry = Rx * 10.0**log_ratio
    a, b, _, p = rh.hertz_contact(10.0**log_q, Rx, Ry, E_STEEL, *rh.hertz_coefficients_exact(Rx, Ry))
    h_c = 10.0**log_hc
    args = (2.2, a, b, p, E_STEEL, h_c, min(h_c * 10.0**log_oil, 50e-6), H_FLOOR)
    assert_close(ck.outside_hertz_capacitance(*args), rc.outside_hertz_capacitance(*args), RTOL_OUTSIDE, str(args))
