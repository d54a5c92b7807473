"""ShaftModel (spindle/shaft/model.py): the reduction against the full model, the outputs against direct solutions
of the same equations, the input and parameter-file checks.

Shaft: the default (spindle/shaft/params/rabreau_b7214c.toml) on seats of 2e8 N/m radially, 5e7 N/m axially,
1e5 N.m/rad in tilt and 2000 N.s/m of radial damping: a B7214C pair's order of magnitude.
Tolerances: the reduction keeps 12 fixed-interface modes; its error on the first six frequencies is a few 1e-4
(Craig-Bampton converges from above with the fourth power of the ratio of the frequency to the first dropped
mode's), asserted within 1e-3. Where both sides solve one system (static compliance with the tool tip in the
interface, receptance from the modes against a direct solve) they agree to rounding, 1e-9.
"""

import math
import subprocess
import sys

import numpy as np
import pytest

from bearing_fmu_common.paramfile import ParameterError
from spindle.shaft import ShaftInputError, ShaftModel
from spindle.shaft.declarations import K_START
from spindle.shaft.model import WHIRL_AXIAL, WHIRL_BACKWARD, WHIRL_FORWARD, WHIRL_NONE, full_matrices
from tests.cases import shaft_beams as sb

OMEGA = 20000.0 * math.pi / 30.0
K_SEATS = np.array([sb.seat_matrix(2e8, 5e7, 1e5)] * 2)
C_SEATS = np.array([np.diag([2000.0, 2000.0, 0.0, 0.0, 0.0])] * 2)


@pytest.fixture(scope="module")
def models():
    return ShaftModel(), ShaftModel(modes=None)


@pytest.mark.parametrize("omega", [0.0, OMEGA])
def test_reduction_keeps_the_first_six_modes(models, omega):
    reduced, full = (m.evaluate(omega, K_SEATS, C_SEATS) for m in models)
    assert reduced["frequencies"] == pytest.approx(full["frequencies"], rel=1e-3)
    assert reduced["frequencies"].min() >= full["frequencies"].min()  # the reduction only stiffens
    assert np.array_equal(reduced["whirl"], full["whirl"])
    assert reduced["damping_ratios"] == pytest.approx(full["damping_ratios"], rel=1e-2)
    assert reduced["critical_speeds"] == pytest.approx(full["critical_speeds"], rel=1e-3)
    assert reduced["compliance_radial"] == pytest.approx(full["compliance_radial"], rel=1e-9)
    assert reduced["peak_compliance"] == pytest.approx(full["peak_compliance"], rel=1e-2)


def test_whirl_at_speed_and_at_rest(models):
    at_rest = models[0].evaluate(0.0, K_SEATS, C_SEATS)
    spinning = models[0].evaluate(OMEGA, K_SEATS, C_SEATS)
    assert set(at_rest["whirl"]) <= {WHIRL_NONE, WHIRL_AXIAL}
    bending = spinning["whirl"][spinning["whirl"] != WHIRL_AXIAL]
    assert list(bending[:2]) == [WHIRL_BACKWARD, WHIRL_FORWARD]  # the gyroscopic split of the first pair
    f = spinning["frequencies"][spinning["whirl"] != WHIRL_AXIAL]
    f0 = at_rest["frequencies"][at_rest["whirl"] != WHIRL_AXIAL]
    assert f[0] < f0[0] < f[1]


def test_static_compliance_is_the_full_models(models):
    K, M, G = full_matrices(models[1].shaft)
    sf = models[1].shaft
    for node, Ks in zip(sf.seat_nodes, K_SEATS):
        K[5 * node : 5 * node + 5, 5 * node : 5 * node + 5] += Ks
    F = np.zeros((K.shape[0], 2))
    F[5 * sf.tip_node, 0] = 1.0
    F[5 * sf.tip_node + 2, 1] = 1.0
    u = np.linalg.solve(K, F)
    out = models[0].evaluate(OMEGA, K_SEATS, C_SEATS)
    assert out["compliance_radial"] == pytest.approx(u[5 * sf.tip_node, 0], rel=1e-9)
    assert out["compliance_axial"] == pytest.approx(u[5 * sf.tip_node + 2, 1], rel=1e-9)


def test_receptance_from_the_modes_is_the_direct_solve(models):
    model = models[0]
    K, C = model.matrices(K_SEATS, C_SEATS)
    D = C + OMEGA * model._G
    lam, V = model._state_eig(K, D)
    out = model.evaluate(OMEGA, K_SEATS, C_SEATS)
    for w in (10.0, 2.0 * math.pi * out["peak_frequency"], 2.0 * math.pi * 1500.0):
        direct = np.linalg.solve(K - w * w * model._M + 1j * w * D, np.eye(K.shape[0])[:, model._tip])
        assert model.receptance(lam, V, [w])[0] == pytest.approx(direct[model._tip], rel=1e-9)
    grid = 2.0 * math.pi * np.linspace(50.0, 3000.0, 3000)
    assert out["peak_compliance"] >= np.abs(model.receptance(lam, V, grid)).max() * (1.0 - 1e-6)


def test_critical_speeds_are_where_a_forward_frequency_equals_the_speed(models):
    model = models[0]
    speeds = model.critical_speeds(K_SEATS, C_SEATS)
    for speed in speeds:
        out = model.evaluate(speed, K_SEATS, C_SEATS, critical_speeds=False)
        forward = 2.0 * math.pi * out["frequencies"][out["whirl"] == WHIRL_FORWARD]
        assert np.min(np.abs(forward - speed)) <= 1e-3 * speed


@pytest.mark.parametrize("damping", [0.0, 2000.0, 5000.0])
def test_critical_speeds_from_the_projection_are_the_whole_problems(models, monkeypatch, damping):
    """On a bearing's damping the critical speeds come from the synchronous problem projected on the lowest undamped
    modes, each root refined on the whole model: equal to the whole eigen-solution's roots to rounding (1e-9), and
    that eigen-solution is not needed."""
    model = models[0]
    for K_seats in (K_SEATS, np.array([K_START] * 2), np.array([sb.seat_matrix(2e8, 5e7, 1e5, 2e7)] * 2)):
        K, C = model.matrices(K_seats, C_SEATS * damping / 2000.0)
        whole = model._synchronous_speeds(K, C, 2)
        with monkeypatch.context() as patch:
            patch.setattr(model, "_synchronous_speeds", None)  # calling it fails
            assert model.critical_speeds(K_seats, C_SEATS * damping / 2000.0) == pytest.approx(whole, rel=1e-9)


def test_seats_pinned_by_their_damping_take_the_whole_eigen_solution(models):
    """Seats damped so heavily that they pin the shaft: the undamped modes do not represent its shapes, the
    projection is not trusted and the critical speeds are the whole synchronous eigen-solution's."""
    model = models[0]
    K, C = model.matrices(K_SEATS, C_SEATS * 1e8 / 2000.0)
    assert model._projected_speeds(K, C, 2) is None
    assert np.array_equal(model.critical_speeds(K_SEATS, C_SEATS * 1e8 / 2000.0), model._synchronous_speeds(K, C, 2))


def test_inputs_are_refused_with_their_range(models):
    model = models[0]
    with pytest.raises(ShaftInputError, match=r"omega = -1.0 rad/s is outside the allowed range \[0, 10000\]"):
        model.evaluate(-1.0, K_SEATS)
    with pytest.raises(ShaftInputError, match=r"K_seats: shape \(1, 5, 5\), expected \(2, 5, 5\)"):
        model.evaluate(0.0, K_SEATS[:1])
    bad = K_SEATS.copy()
    bad[1, 2, 2] = -1.0
    with pytest.raises(ShaftInputError, match=r"K_seats\[1\]\[2,2\] = -1.0 is outside the allowed range \[0, 1e\+13\]"):
        model.evaluate(0.0, bad)
    bad[1, 2, 2] = math.nan
    with pytest.raises(ShaftInputError, match=r"K_seats\[1\]\[2,2\] = nan .*rear_bearing"):
        model.evaluate(0.0, bad)


def test_a_seat_between_nodes_is_refused(tmp_path):
    path = sb.shaft_file(tmp_path / "off.toml", [(1.0, 0.05, 0.0, 4)], seats=(0.3,), tip=0.0)
    with pytest.raises(ParameterError, match=r"seat 'seat\[0\]' at z = 0.3 m is on no node \(nearest node at 0.25 m\)"):
        ShaftModel(path)


CHILD = """
import sys
sys.modules["scipy"] = None  # as in a host without scipy: importing it raises ImportError (numba copes)
sys.modules["ross"] = None  # a test-only dependency: the model must not need it
import numpy as np
from spindle.shaft import ShaftModel
out = ShaftModel().evaluate(1000.0, np.array([np.diag([2e8, 2e8, 5e7, 0.0, 0.0])] * 2))
print(out["frequencies"][0], out["critical_speeds"][0])
"""


def test_the_model_runs_without_scipy_and_ross():
    """An FMU host may have numpy and numba only (docs/fmu_runtime.md): the whole call, kernels compiled or loaded
    from the cache included, runs with scipy and ross unimportable."""
    proc = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-2000:]
    frequency, critical = (float(v) for v in proc.stdout.split())
    assert 400.0 < frequency < 500.0 and critical > 2.0 * math.pi * frequency
