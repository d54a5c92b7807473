"""Stability cases in load and clearance: from zero load (balls losing contact, the ring free in its
clearance, a singular stiffness) to contact pressures beyond 4 GPa, and from large negative (preload) to
large positive clearance.

Outcomes: stable and finite, with the ISO 76 pressure warning above 4.2 GPa; an InputError naming the
cause, its value and the allowed range beyond the material limit (6 GPa) or the geometric clearance
limits |P_d| <= A = (f_i + f_o - 1) D; a SolverError naming the inputs and the physical reason where the
quasi-static equilibrium is not found (large free contact angles under a mostly radial load: a ball beyond
the centre of curvature of its inner groove, docs/quasistatic.md section 3) -- never a NaN.
"""

import math

import numpy as np
import pytest

from bearing_fmu import AnalyticModel, InputError, QuasiStaticModel, Scene, SolverError
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.params import clearance_limits

QS_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")  # the scene of Bearing.fmu
LOADS = {"6208": dict(F_x=3000.0, F_z=500.0), "B7214C": dict(F_x=3000.0, F_z=500.0)}


def finite(outputs):
    return all(np.all(np.isfinite(np.asarray(v, dtype=float))) for v in outputs.values())


def groove(bearing):
    return clearance_limits(bearing.D, bearing.f_i, bearing.f_o)[1]


@pytest.mark.parametrize("bearing", ["6208", "B7214C"])
def test_zero_load_gives_a_finite_centred_unloaded_bearing(bearing):
    """Case: quasi-static fidelity with every load zero at 500 rad/s, after a loaded solve (the balls
    lose contact; with clearance the ring is free). Outcome: converged and finite; the ring at the
    documented position for zero load (docs/quasistatic.md: centred in the free directions), the same
    as from a fresh model (history-independent); no inner contact load; the stiffness finite and zero in
    the directions no loaded contact resists (singular, reported as such, not inverted)."""
    loaded = QuasiStaticModel(bearing, scene=QS_SCENE)
    loaded.evaluate(omega=500.0, **LOADS[bearing])
    after = dict(loaded.evaluate(omega=500.0))
    fresh = dict(QuasiStaticModel(bearing, scene=QS_SCENE).evaluate(omega=500.0))
    assert finite(after)
    for name in ("x", "y", "z"):  # m: the documented position, whatever the history
        assert after[name] == pytest.approx(fresh[name], abs=1e-12), name
    for name in ("Q_max_outer", "torque"):  # ball equilibria from other warm starts: equal to 1e-9
        assert after[name] == pytest.approx(fresh[name], rel=1e-9), name
    assert after["Q_max_inner"] == 0.0
    K = loaded.K  # the full 5 x 5 matrix (the scene exposes part of it)
    assert np.all(np.isfinite(K)) and abs(np.linalg.det(K)) == 0.0


def test_analytic_zero_load_has_no_loaded_ball():
    """Case: analytic 6208 at 500 rad/s with F_y = 0. Outcome: finite outputs, no loaded ball, no inner
    contact load, the outer contacts carrying the centrifugal force alone."""
    out = AnalyticModel("6208").evaluate(omega=500.0, F_y=0.0, T_oil=313.15)
    assert finite(out)
    assert out["n_loaded"] == 0 and out["Q_max_inner"] == 0.0 and out["Q_max_outer"] > 0.0


@pytest.mark.parametrize("fidelity", ["analytic", "quasi_static"])
def test_pressure_beyond_iso_76_is_computed_with_a_warning(fidelity):
    """Case: 6208 under 30 kN radial (p_max about 4.7 GPa, beyond the ISO 76 static criterion 4.2 GPa).
    Outcome: computed (finite, converged) with a warning naming p_max and the 4.2 GPa limit."""
    if fidelity == "analytic":
        model = AnalyticModel("6208")
        out = model.evaluate(omega=500.0, F_y=30000.0, T_oil=313.15)
    else:
        model = QuasiStaticModel("6208", scene=QS_SCENE)
        out = model.evaluate(omega=500.0, F_x=30000.0)
        assert model.status[0] == 0
    assert finite(out)
    assert out["p_max"] > 4.2e9
    assert any("4.2 GPa" in w and "p_max" in w for w in model.warnings)


@pytest.mark.parametrize("fidelity", ["analytic", "quasi_static"])
def test_load_beyond_the_material_limit_is_refused(fidelity):
    """Case: 6208 under 1 MN radial (p_max far beyond 6 GPa). Outcome: InputError naming the load, its
    value and the allowed range (or the 6 GPa limit it breaks); the model keeps its last result."""
    if fidelity == "analytic":
        model = AnalyticModel("6208")
        call = lambda: model.evaluate(omega=500.0, F_y=1e6, T_oil=313.15)  # noqa: E731
        name = "F_y"
    else:
        model = QuasiStaticModel("6208", scene=QS_SCENE)
        call = lambda: model.evaluate(omega=500.0, F_x=1e6)  # noqa: E731
        name = "F_x"
    with pytest.raises(InputError) as info:
        call()
    message = str(info.value)
    assert name in message and "6.0 GPa" in message


@pytest.mark.parametrize("bearing", ["6208", "B7214C"])
@pytest.mark.parametrize("share", [-0.5, -0.1, 0.1, 0.5])
def test_large_clearance_or_interference_converges(bearing, share):
    """Case: quasi-static fidelity with diametral clearance P_d = share x A (A = (f_i + f_o - 1) D, the
    geometric limit; -0.5 A is a heavy interference, +0.5 A a free contact angle of 41.4 deg,
    cos alpha_0 = 1 - P_d / (2 A), beyond the catalogues' 40 deg) under 3 kN radial + 500 N axial at 500 rad/s. Outcome:
    converged, finite, loads balanced to the scene tolerance; the interference -0.5 A passes 4.2 GPa and
    carries the ISO 76 warning. Shoulders (the files' estimates): at +0.5 A the balls the thrust carries run to
    about 60 deg, past both estimated shoulders of the 6208 (52 deg) and the B7214C's inner one (60.7 deg), and
    at -0.5 A the B7214C's inner ellipses, wide at 5.2 GPa, pass its low back shoulder (36 deg): reported in
    truncation_inner/outer with a truncation warning; at +-0.1 A every contact stays within its shoulders. At +0.5 A
    outer-race control asks a traction coefficient of 0.13 (6208) and 0.084 (B7214C) of the outer contacts, above the
    oil's 0.06: warned (mu_required_outer), and only where the outputs say so."""
    A = groove(QuasiStaticModel(bearing, scene=QS_SCENE).bearing)
    model = QuasiStaticModel(bearing, scene=QS_SCENE, Pd=share * A)
    out = model.evaluate(omega=500.0, **LOADS[bearing])
    assert finite(out) and model.status[0] == 0
    assert model.status[2] <= 1e-8 * 3000.0
    assert (out["p_max"] > 4.2e9) == (share == -0.5)
    assert any("ISO 76" in w for w in model.warnings) == (share == -0.5)
    truncated = out["truncation_inner"] > 0.0 or out["truncation_outer"] > 0.0
    assert any("truncated" in w for w in model.warnings) == truncated
    friction = max(out["mu_required_inner"], out["mu_required_outer"]) > model.lubricant.traction_limit
    assert any("traction coefficient" in w for w in model.warnings) == friction == (share == 0.5)
    assert all("ISO 76" in w or "truncated" in w or "traction coefficient" in w for w in model.warnings)
    assert truncated == (share == 0.5 or (share == -0.5 and bearing == "B7214C"))


@pytest.mark.parametrize("bearing", ["6208", "B7214C"])
def test_clearance_outside_the_geometric_limits_is_refused(bearing):
    """Case: P_d = +-1.01 A. Outcome: InputError naming Pd, its value and the allowed range [-A, A]."""
    A = groove(QuasiStaticModel(bearing, scene=QS_SCENE).bearing)
    for Pd in (1.01 * A, -1.01 * A):
        with pytest.raises(InputError) as info:
            QuasiStaticModel(bearing, scene=QS_SCENE, Pd=Pd)
        assert f"Pd = {Pd} m" in str(info.value) and "allowed range" in str(info.value)


@pytest.mark.parametrize("bearing", ["6208", "B7214C"])
def test_interference_at_the_geometric_limit_is_refused_by_pressure(bearing):
    """Case: P_d = -A (the balls squeezed by the whole groove clearance). Outcome: InputError naming
    p_max and the 6 GPa material limit (the interference alone overloads every ball)."""
    A = groove(QuasiStaticModel(bearing, scene=QS_SCENE).bearing)
    model = QuasiStaticModel(bearing, scene=QS_SCENE, Pd=-A)
    with pytest.raises(InputError) as info:
        model.evaluate(omega=500.0, **LOADS[bearing])
    assert "p_max" in str(info.value) and "6.0 GPa" in str(info.value)


@pytest.mark.parametrize("bearing", ["6208", "B7214C"])
def test_clearance_near_the_geometric_limit_converges_or_says_so(bearing):
    """Case: P_d = 0.95 A and A (free contact angles 58 and 60 deg) under 3 kN radial + 500 N axial.
    Outcome: either converged and finite, or a SolverError whose message names the speed and every load
    (measured: the 6208 converges at A, through the last-resort damped Newton in 562 bearing evaluations; at
    0.95 A, and the B7214C at both, the solve ends with a ball beyond the centre of curvature of its inner
    groove and the SolverError names that physical reason, docs/quasistatic.md section 3) -- never a NaN or
    a hang (the iteration cap of the scene bounds the work)."""
    A = groove(QuasiStaticModel(bearing, scene=QS_SCENE).bearing)
    for share in (0.95, 1.0):
        model = QuasiStaticModel(bearing, scene=QS_SCENE, Pd=share * A)
        try:
            out = model.evaluate(omega=500.0, **LOADS[bearing])
        except SolverError as error:
            message = str(error)
            assert all(f"{k} = " in message for k in ("omega", "F_x", "F_y", "F_z")), message
        else:
            assert finite(out) and model.status[0] == 0
            assert math.isfinite(out["alpha_inner"])
