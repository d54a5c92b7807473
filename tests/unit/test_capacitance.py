"""kernels.capacitance against its twin tests/reference/ref_capacitance.py.

Closed forms only: RTOL = 1e-12 (measured: exact or within 2 ulp). The twin uses the CODATA 2018
vacuum permittivity, the value the kernel documents; scipy.constants carries CODATA 2022, 6.8e-10
relative higher, which is checked separately so that this revision does not hide in the tolerance.
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
from tests.unit._compare import assert_close

RTOL = 1e-12
FAST = settings(max_examples=50, deadline=None)
# finite, normal floats: subnormal inputs (< 2.2e-308) have no physical meaning and lose precision
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
K_CM = lk.clausius_mossotti_constant(2.2, 870.0)
H_FLOOR = 10e-9


def test_every_public_kernel_has_a_twin():
    kernels = [
        n
        for n, f in vars(ck).items()
        if hasattr(f, "py_func") and f.py_func.__module__ == ck.__name__ and not n.startswith("_")
    ]
    assert kernels and all(callable(getattr(rc, n, None)) for n in kernels), kernels


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
