"""Bearing files give an angular-contact bearing by its nominal contact angle, its diametral clearance or
both (docs/parameters.md): one rule, cos alpha0 = 1 - P_d / (2 A), A = (f_i + f_o - 1) D (Harris &
Kotzalas 2006, vol. 1, free contact angle), derives the other; the clearance limits follow from the
geometry (|P_d| <= A: free angle up to 60 deg), not from a fraction of D."""

import math
import re

import pytest

from bearing_fmu import AnalyticModel, ParameterError, QuasiStaticModel, Scene, load_bearing
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.limits import InputError
from bearing_fmu.params import clearance_for_angle

CATALOGUE = load_bearing("B7214C").path
SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")


def bearing_file(tmp_path, name, clearance=None, angle=None, kind="angular_contact", source=CATALOGUE):
    """A copy of a catalogue bearing file with the clearance and contact-angle lines replaced (None: left out)."""
    text = open(source).read()
    text = re.sub(r'kind = "[a-z_]+"', f'kind = "{kind}"', text)
    lines = []
    for line in text.splitlines():
        if line.startswith("diametral_clearance") or line.startswith("contact_angle"):
            continue
        lines.append(line)
        if line.startswith("n_balls"):
            if clearance is not None:
                lines.append(f'diametral_clearance = {{ value = {clearance!r}, unit = "m", source = "test" }}')
            if angle is not None:
                lines.append(f'contact_angle = {{ value = {angle!r}, unit = "rad", source = "test" }}')
    path = tmp_path / f"{name}.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_40_degree_bearing_by_angle_equals_by_clearance(tmp_path):
    """A 40 deg angular-contact bearing (above the old 0.02 D cap on P_d, ~36-38 deg) given by its
    nominal angle and by the equivalent clearance: the same P_d and bit-identical quasi-static results
    under axial + radial load at 6000 rpm."""
    b = load_bearing("B7214C")
    alpha = math.radians(40.0)
    Pd = clearance_for_angle(b.D, b.f_i, b.f_o, alpha)
    assert Pd > 0.02 * b.D  # refused before
    by_angle = load_bearing(bearing_file(tmp_path, "by_angle", angle=alpha))
    by_clearance = load_bearing(bearing_file(tmp_path, "by_clearance", clearance=Pd))
    assert by_angle.Pd == Pd
    assert by_clearance.alpha0 == pytest.approx(alpha, abs=1e-12)
    inputs = dict(omega=6000.0 * 2.0 * math.pi / 60.0, F_z=2000.0, F_x=1000.0)
    r_angle = QuasiStaticModel(by_angle.path, scene=SCENE).evaluate(**inputs)
    r_clear = QuasiStaticModel(by_clearance.path, scene=SCENE).evaluate(**inputs)
    assert r_angle == r_clear
    light = QuasiStaticModel(by_angle.path, scene=SCENE).evaluate(F_z=10.0)  # at rest, a light thrust
    assert math.radians(40.0) < light["alpha_inner"] < math.radians(40.5)  # the contact sits at ~40 deg


def test_inconsistent_angle_and_clearance_refused_with_both_values(tmp_path):
    path = bearing_file(tmp_path, "inconsistent", clearance=54.09e-6, angle=math.radians(40.0))
    with pytest.raises(ParameterError) as err:
        load_bearing(path)
    message = str(err.value)
    assert "5.409e-05 m" in message and "40.000 deg" in message and "15.0" in message


def test_file_needs_a_clearance_or_an_angle(tmp_path):
    with pytest.raises(ParameterError, match="diametral_clearance.*contact_angle"):
        load_bearing(bearing_file(tmp_path, "neither"))


def test_clearance_beyond_the_geometry_refused_with_the_value_read(tmp_path):
    """P_d above A = (f_i + f_o - 1) D (free angle above 60 deg) is refused by the file loader; a model
    parameter beyond it names the value set; the message never prints None."""
    b = load_bearing("B7214C")
    A = (b.f_i + b.f_o - 1.0) * b.D
    with pytest.raises(ParameterError, match="diametral_clearance"):
        load_bearing(bearing_file(tmp_path, "wide", clearance=1.01 * A))
    with pytest.raises(InputError) as err:
        QuasiStaticModel("B7214C", scene=SCENE, Pd=1.01 * A)
    assert f"Pd = {1.01 * A} m (set)" in str(err.value) and "None" not in str(err.value)
    QuasiStaticModel("B7214C", scene=SCENE, Pd=0.99 * A)  # 58 deg: accepted


def test_deep_groove_file_with_clearance_and_nominal_angle_zero(tmp_path):
    """A deep-groove file's contact angle 0 is its nominal (radial) angle: any clearance goes with it, and
    both fidelities take the file's clearance (the analytic model is for contact angle 0 only)."""
    b = load_bearing("6306")
    assert b.Pd > 0.0 and b.alpha0 == 0.0
    assert AnalyticModel("6306").Pd == b.Pd == QuasiStaticModel("6306").Pd
