"""Shoulder truncation of the contact ellipse (kernels.truncation, docs/quasistatic.md section 8): kernels against
their plain-geometry twins, the shoulders of the bearing files, and the outputs and warnings of the three facades."""

import math
from pathlib import Path

import numpy as np
import pytest

from bearing_fmu.kernels import truncation as tk
from bearing_fmu.kernels.ball_dynamics import outputs as dyn_outputs
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import ParameterError, load_bearing, shoulder_estimate
from bearing_fmu.scene import Scene
from tests.reference import ref_ball_dynamics_outputs as ref_outputs
from tests.reference import ref_truncation as rt

CATALOGUE = Path(__file__).resolve().parents[2] / "bearing_fmu" / "params" / "bearings"
BEARING_218 = Path(__file__).resolve().parents[1] / "validation" / "data" / "angular_218_textbook.toml"
RNG = np.random.default_rng(20240611)


def test_shoulder_angle_matches_twin():
    """Both rings, lands from below the groove bottom to beyond the centre's level: the closed form against the
    twin's root of the groove point at the land radius (brentq to 1e-15 rad)."""
    r = 6.552e-3
    for race, rho in ((0, 30.3e-3 + 0.252e-3), (1, 30.3e-3 - 0.252e-3)):
        bottom = rho - r if race == 0 else rho + r
        for h in np.linspace(-0.5e-3, 8e-3, 41):  # land height above the groove bottom (m)
            d_s = 2.0 * (bottom + h if race == 0 else bottom - h)
            got = tk.shoulder_angle(rho, r, d_s, race)
            assert got == pytest.approx(rt.shoulder_angle(rho, r, d_s, race), abs=1e-12), (race, h)


def test_truncated_fraction_matches_twin():
    """Random contacts: semi-major axes from nothing to 0.9 r, angles on either side of either edge, edges from
    the groove bottom to past 90 deg (where the groove ends 90 deg along): the kernel's closed form against the
    twin's extreme of the groove arc along the tangent (bounded search to 1e-13 rad: agreement to 1e-9)."""
    r = 11.63e-3
    zeros = 0
    for _ in range(400):
        a = r * RNG.uniform(0.01, 0.9)
        thrust, back = RNG.uniform(0.0, 2.0, 2)
        alpha = RNG.uniform(-1.8, 1.8)
        got = tk.truncated_fraction(a, r, alpha, thrust, back)
        assert got == pytest.approx(rt.truncated_fraction(a, r, alpha, thrust, back), abs=1e-9), (a, alpha)
        zeros += got == 0.0
    assert 50 < zeros < 350  # both within the shoulders and truncated cases were drawn


def test_race_truncation_matches_twin():
    """Random ball sets with open contacts and equal loads: largest fraction per race and its ball (first of
    equals; -1 and 0 without truncation)."""
    tp = np.array([1.7e-4, 11.63e-3, 1.06, 0.65, 1.7e-4, 11.63e-3, 1.06, 0.65])
    for case in range(30):
        Z = 12
        balls = np.zeros((4, Z))
        balls[0:2] = RNG.uniform(-500.0, 20000.0, (2, Z))
        balls[2:4] = RNG.uniform(-0.5, 1.1, (2, Z))
        if case % 3 == 0:
            balls[0, 3:5] = balls[0, 1]  # equal loads at equal angles: the first wins
            balls[2, 3:5] = balls[2, 1]
        got, ref = np.zeros(tk.TR_SIZE), np.zeros(tk.TR_SIZE)
        tk.race_truncation(balls, 0, balls, 2, tp, got)
        rt.race_truncation(balls, 0, balls, 2, tp, ref)
        np.testing.assert_allclose(got[:2], ref[:2], atol=1e-9)
        assert list(got[2:]) == list(ref[2:]), case
    tr = np.zeros(tk.TR_SIZE)
    tk.race_truncation(np.zeros((2, 5)), 0, np.full((2, 5), 1.5), 0, tp, tr)  # open contacts: never truncated
    assert list(tr) == [0.0, 0.0, -1.0, -1.0]


def test_dem_signed_angles_and_truncation_match_twin():
    """The DEM's signed contact angles (as the quasi-static fidelity measures them) and its truncation kernel
    against the twins' vector algebra, in a loaded 6208 state (3 kN radial, 300 N axial, 5 ms from rest: the balls
    have settled on their loaded contacts; at 2 ms one still swings through the radial plane) with low artificial
    shoulders
    (0.3 rad inner, 0.2 rad outer) so that loaded contacts are truncated; the catalogue 6208 itself stays within
    its shoulders (exactly 0). The ring is held against tilting (a free 6208 ring tilts under this combined load and
    tips the least loaded contacts past the radial plane), so every loaded ball leans toward the thrust."""
    model = DemModel(ring_inertia=1e3)
    model.evaluate(5e-3, omega=100.0, F_y=3000.0, F_z=300.0)
    alpha = np.zeros((2, 9))
    dyn_outputs.signed_contact_angles(model.balls, model.ring, model.par, alpha)
    ref_alpha = ref_outputs.signed_contact_angles(model.balls, model.ring, model.par)
    np.testing.assert_allclose(alpha, ref_alpha, atol=1e-12)
    assert (alpha[:, model._Q[0] > 0.0] > 0.0).all()  # F_z > 0 presses the loaded balls toward +z at both races
    assert model.as_dict()["truncation_inner"] == 0.0 and model.as_dict()["truncation_outer"] == 0.0
    tp = model._truncation_parameters.copy()
    tp[[tk.TP_THRUST, tk.TP_BACK]] = 0.3
    tp[[tk.TP_STRIDE + tk.TP_THRUST, tk.TP_STRIDE + tk.TP_BACK]] = 0.2
    tr = np.zeros(tk.TR_SIZE)
    dyn_outputs.shoulder_truncation(model.balls, model.ring, model.par, tp, np.zeros((2, 9)), alpha, tr)
    ref = ref_outputs.shoulder_truncation(model.balls, model.ring, model.par, tp)
    np.testing.assert_allclose(tr[:2], ref[:2], atol=1e-9)
    assert list(tr[2:]) == list(ref[2:]) and tr[0] > 0.0 and tr[1] > 0.0


# -- bearing files ---------------------------------------------------------------------------------
def test_catalogue_files_give_their_shoulders():
    """Every catalogue bearing and the 218 test file give their land diameters (deep-groove rings: the two of the
    thrust side, the back side the same; angular contact: all four), each between the groove bottom and the
    pitch circle."""
    for path in [*CATALOGUE.glob("*.toml"), BEARING_218]:
        b = load_bearing(path)
        expected = (
            () if b.kind == "angular_contact" else ("inner_back_shoulder_diameter", "outer_back_shoulder_diameter")
        )
        assert b.shoulders_estimated == expected, b.name
        assert b.dm - b.D < b.shoulder_inner_back <= b.shoulder_inner < b.dm, b.name
        assert b.dm < b.shoulder_outer <= b.shoulder_outer_back < b.dm + b.D, b.name


def _without_shoulders(tmp_path, source, replace=None):
    lines = [line for line in source.read_text().splitlines() if "shoulder_diameter" not in line]
    if replace:
        at = next(k for k, line in enumerate(lines) if line.startswith("width"))
        lines.insert(at + 1, replace)
    path = tmp_path / "bearing.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_file_without_shoulders_gets_the_documented_estimates(tmp_path):
    """docs/parameters.md (shoulders): a deep-groove ring 0.2 D above (inner) or below (outer) the groove bottom
    d_m -+ D on both sides; an angular-contact ring's thrust side where its groove is 60 deg from the bottom,
    f D (1 - cos 60 deg), its other side 0.1 D; every key listed as estimated."""
    b = load_bearing(_without_shoulders(tmp_path, CATALOGUE / "6208.toml"))
    assert b.shoulder_inner == b.shoulder_inner_back == pytest.approx(60.6e-3 - 12.6e-3 + 2 * 0.2 * 12.6e-3, rel=1e-14)
    assert b.shoulder_outer == b.shoulder_outer_back == pytest.approx(60.6e-3 + 12.6e-3 - 2 * 0.2 * 12.6e-3, rel=1e-14)
    assert len(b.shoulders_estimated) == 4
    b = load_bearing(_without_shoulders(tmp_path, BEARING_218))
    D, dm, f = 22.23e-3, 125.3e-3, 0.5232
    assert b.shoulder_inner == pytest.approx(dm - D + 2 * f * D * 0.5, rel=1e-14)
    assert b.shoulder_outer == pytest.approx(dm + D - 2 * f * D * 0.5, rel=1e-14)
    assert b.shoulder_inner_back == pytest.approx(dm - D + 0.2 * D, rel=1e-14)
    assert b.shoulder_outer_back == pytest.approx(dm + D - 0.2 * D, rel=1e-14)
    assert shoulder_estimate("angular_contact", D, dm, f, "inner", "thrust") == b.shoulder_inner
    # the files' estimated values are these estimates, rounded to 0.01 mm
    full = load_bearing(BEARING_218)
    for key in ("shoulder_inner", "shoulder_outer", "shoulder_inner_back", "shoulder_outer_back"):
        assert getattr(full, key) == pytest.approx(getattr(b, key), abs=0.5e-5), key


@pytest.mark.parametrize(
    "line, words",
    [
        ('inner_shoulder_diameter = { value = 0.048, unit = "m", source = "t" }', "]0.048, 0.0606["),
        ('outer_shoulder_diameter = { value = 0.0606, unit = "m", source = "t" }', "]0.0606, 0.0732["),
        ('outer_back_shoulder_diameter = { value = 0.08, unit = "m", source = "t" }', "]0.0606, 0.0732["),
        ('inner_shoulder_diameter = { value = 50.0, unit = "mm", source = "t" }', "expected 'm'"),
    ],
)
def test_a_shoulder_outside_the_groove_is_refused(tmp_path, line, words):
    """A land at or below the groove bottom, at or beyond the pitch circle, or in the wrong unit: ParameterError
    naming the file, the key, its value and the allowed range."""
    key = line.split()[0]
    with pytest.raises(ParameterError, match=key) as info:
        load_bearing(_without_shoulders(tmp_path, CATALOGUE / "6208.toml", line))
    assert words in str(info.value)


# -- facades ---------------------------------------------------------------------------------------
def test_bearings_within_their_shoulders_give_exactly_zero():
    """The catalogue bearings in ordinary service stay within their shoulders: truncation exactly 0 on both races
    and no warning, in every fidelity (analytic 6208 at 3 kN radial; quasi-static B7214C at 800 N thrust and
    10 000 rpm, 6208 at 3 kN radial; DEM 6208 at 3 kN radial after 2 ms)."""
    cases = []
    analytic = AnalyticModel()
    cases.append((analytic.evaluate(500.0, 3000.0, 313.15), analytic.warnings))
    qs = QuasiStaticModel()
    cases.append((qs.evaluate(omega=1047.2, F_z=800.0), qs.warnings))
    qs = QuasiStaticModel("6208", "guessasma_oil")
    cases.append((qs.evaluate(omega=500.0, F_y=3000.0), qs.warnings))
    dem = DemModel()
    cases.append((dem.evaluate(2e-3, omega=100.0, F_y=3000.0), dem.warnings))
    for out, warnings in cases:
        assert out["truncation_inner"] == 0.0 and out["truncation_outer"] == 0.0
        assert not any("truncated" in w for w in warnings)


def test_quasi_static_warns_on_entry_and_keeps_it_in_its_state():
    """The 218 (40 deg, estimated 60 deg shoulders) at 12 000 rpm under 2 kN thrust: the inner ellipse passes the
    thrust-side shoulder. The warning comes at the entry only, not at the next evaluations in truncation, again
    after the bearing left truncation (at rest); the state (FMU get/set) carries each race's truncated fraction at
    its last warning (0.9 x the speed truncates less: no new warning)."""
    scene = Scene(name="qs", fidelity="quasi_static", centrifugal=True, gyroscopic=True)
    qs = QuasiStaticModel(str(BEARING_218), "iso_vg68_mineral", scene)
    fast = 12000.0 * math.pi / 30.0
    warned = []
    for omega in (fast, fast, 0.9 * fast, 0.0, fast):
        out = qs.evaluate(omega=omega, F_z=2000.0)
        warned.append(sum("truncated by the inner ring's thrust-side shoulder" in w for w in qs.warnings))
        assert (out["truncation_inner"] > 0.0) == (omega > 0.0)
    assert warned == [1, 0, 0, 0, 1]
    message = next(w for w in qs.warnings if "truncated" in w)
    assert "inner contact at 59.4 deg" in message and "edge at 60.7 deg" in message
    state = qs.get_state()
    assert state["truncated"][0] == pytest.approx(out["truncation_inner"]) and state["truncated"][1] == 0.0
    qs.evaluate(omega=0.0, F_z=2000.0)
    qs.set_state(state)  # back in truncation: no new entry
    qs.evaluate(omega=fast, F_z=2000.0)
    assert not any("truncated" in w for w in qs.warnings)
