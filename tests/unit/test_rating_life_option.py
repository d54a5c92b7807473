"""The scene option `life`: off, the rating-life work is not done and its outputs do not exist; on, the
facades' L10, L10_h, L10r, L10r_h are the twin's lives of the solved bearing (ring loads and contact loads).
Also the option `spring_constant` (quasi-static load distribution with the ISO/TS 16281 spring constant)."""

import math
from collections import Counter

import numpy as np
import pytest

from bearing_fmu.kernels import jones_harris
from bearing_fmu.kernels import rating_life as rl
from bearing_fmu.kernels.geometry import free_contact_angle
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene, SceneError
from tests.reference import ref_rating_life as ref
from tests.unit._compare import rel_err

LIFE = ("L10", "L10_h", "L10r", "L10r_h")
OMEGA = 800.0  # rad/s


def quasi_static(bearing, **options):
    return QuasiStaticModel(bearing, "iso_vg68_mineral", Scene(name="q", fidelity="quasi_static", **options))


@pytest.fixture
def counted(monkeypatch):
    """Count the calls of the rating-life kernel (the facades call it through the module)."""
    calls = Counter()
    original = rl.rating_life

    def wrapper(*args):
        calls["rating_life"] += 1
        return original(*args)

    monkeypatch.setattr(rl, "rating_life", wrapper)
    return calls


@pytest.mark.parametrize("fidelity", ["analytic", "quasi_static"])
def test_life_off_is_not_computed_nor_exposed(counted, fidelity):
    for life in (False, True):
        if fidelity == "analytic":
            m = AnalyticModel("6208", "guessasma_oil", Scene(life=life))
            result = m.evaluate(OMEGA, 3000.0, 320.0)
        else:
            m = quasi_static("6208", life=life)
            result = m.evaluate(omega=OMEGA, F_x=3000.0, F_z=300.0)
        assert all((name in result) == life for name in LIFE)
        assert counted["rating_life"] == (1 if life else 0)
        counted.clear()


def test_other_outputs_unchanged_by_the_option():
    off = quasi_static("B7214C").evaluate(omega=OMEGA, F_x=2000.0, F_z=800.0, M_y=20.0)
    on = quasi_static("B7214C", life=True).evaluate(omega=OMEGA, F_x=2000.0, F_z=800.0, M_y=20.0)
    assert {k: v for k, v in on.items() if k not in LIFE} == off


@pytest.mark.parametrize(
    "bearing, loads",
    [
        ("6208", {"F_x": 4000.0}),
        ("6208", {"F_x": 3000.0, "F_y": -1000.0, "F_z": 1500.0}),
        ("B7214C", {"F_x": 5000.0, "F_z": 1000.0}),
        ("B7214C", {"F_z": 2000.0, "M_x": 40.0}),
    ],
)
def test_quasi_static_lives_are_the_twins_of_the_solution(bearing, loads):
    m = quasi_static(bearing, life=True, gyroscopic=True)
    result = m.evaluate(omega=OMEGA, **loads)
    b = m.bearing
    lp = np.zeros(rl.LP_SIZE)
    alpha = free_contact_angle(b.D, b.f_i, b.f_o, b.Pd) if b.kind == "angular_contact" else 0.0  # the file's
    ref.rating_parameters(b.kind == "angular_contact", b.Z, b.D, b.dm, b.f_i, b.f_o, alpha, lp)
    lp[[rl.LP_C_0R, rl.LP_F_0]] = m._life_parameters[[rl.LP_C_0R, rl.LP_F_0]]  # ISO 76 table (twinned elsewhere)
    out = np.zeros(rl.LO_SIZE)
    F = m.F
    ref.rating_life(
        m.balls[jones_harris.BQ_Q_I], m.balls[jones_harris.BQ_Q_O], math.hypot(F[0], F[1]), abs(F[2]), OMEGA, lp, out
    )
    assert rel_err([result[name] for name in LIFE], out) < 1e-10
    # the ring loads the balls carry are the applied ones
    assert math.hypot(F[0], F[1]) == pytest.approx(math.hypot(loads.get("F_x", 0.0), loads.get("F_y", 0.0)), abs=1e-6)


def test_analytic_lives_are_the_twins_of_the_solution():
    m = AnalyticModel("6208", "guessasma_oil", Scene(life=True))
    result = m.evaluate(OMEGA, -3500.0, 320.0)
    b = m.bearing
    lp = m._life_parameters.copy()
    ref.rating_parameters(False, b.Z, b.D, b.dm, b.f_i, b.f_o, 0.0, lp)
    lp[[rl.LP_C_0R, rl.LP_F_0]] = m._life_parameters[[rl.LP_C_0R, rl.LP_F_0]]
    out = np.zeros(rl.LO_SIZE)
    ref.rating_life(m.ball[0], m.ball[1], 3500.0, 0.0, OMEGA, lp, out)
    assert rel_err([result[name] for name in LIFE], out) < 1e-10


def test_ratings_are_the_designs_whatever_the_mounted_clearance():
    """A preload through Pd (free contact angle 0) changes the load distribution, not the bearing's ratings:
    they stay those of its nominal 15 deg."""
    scene = Scene(name="q", fidelity="quasi_static", life=True)
    nominal = QuasiStaticModel("B7214C", "iso_vg68_mineral", scene)
    preloaded = QuasiStaticModel("B7214C", "iso_vg68_mineral", scene, Pd=-5e-6)
    assert np.array_equal(preloaded._life_parameters, nominal._life_parameters)
    assert nominal._life_parameters[rl.LP_ALPHA_DEG] == pytest.approx(15.0, abs=1e-3)
    a = nominal.evaluate(omega=OMEGA, F_z=800.0, F_y=200.0)
    b = preloaded.evaluate(omega=OMEGA, F_z=800.0, F_y=200.0)
    assert a["L10"] == pytest.approx(b["L10"], rel=1e-9) and a["L10r"] != b["L10r"]


def test_scene_refuses_life_and_spring_constant_where_they_do_not_apply():
    with pytest.raises(SceneError, match="life = true needs"):
        Scene(name="d", fidelity="dem", life=True).validate()
    with pytest.raises(SceneError, match="spring_constant = 'iso_ts_16281' needs"):
        Scene(spring_constant="iso_ts_16281").validate()
    with pytest.raises(SceneError, match="spring_constant = 'palmgren'"):
        Scene(name="q", fidelity="quasi_static", spring_constant="palmgren").validate()


def test_iso_spring_constant_scales_the_contact_stiffness_only():
    """With the ISO/TS 16281 spring constant the contact constants are 1.48/1.48096 of exact Hertz (-0.065 %):
    loads, displacements and lives of a bearing with clearance move by less than 0.1 %."""
    loads = {"F_x": 3000.0, "F_z": 500.0}
    hertz = quasi_static("B7214C", life=True)
    iso = quasi_static("B7214C", life=True, spring_constant="iso_ts_16281")
    ratio = 1.48 / (math.pi * math.sqrt(2.0) / 3.0)
    assert iso.qs[jones_harris.QS_K_I] / hertz.qs[jones_harris.QS_K_I] == pytest.approx(ratio, rel=1e-12)
    assert iso.qs[jones_harris.QS_K_O] / hertz.qs[jones_harris.QS_K_O] == pytest.approx(ratio, rel=1e-12)
    a = hertz.evaluate(omega=OMEGA, **loads)
    b = iso.evaluate(omega=OMEGA, **loads)
    for name in ("x", "z", "Q_max_inner", "Q_max_outer", *LIFE):
        assert abs(b[name] / a[name] - 1.0) < 1e-3, name
    assert a["z"] != b["z"] and a["L10r"] != b["L10r"]  # the option acts
