"""The shaft's seats in the bearings' frames (spindle/shaft/model.py seat_frame, seat_stiffness; docs/shaft.md).

A bearing FMU's K is in its own frame, whose z axis is the bearing's thrust direction; a seat's `bearing_axis` says
whether that axis points along the shaft's z (nose to rear) or against it, and a bearing against it is the mirror
image z -> -z of one along it. The checks are physical:
- an angular-contact bearing acts on the shaft at its pressure centre, where the contact lines meet the axis, at
  a = K[1,5] / K[1,1] on the shaft's z from the seat; in the X (face-to-face) arrangement the pressure centres lie
  between the two bearings, in the O (back-to-back) arrangement outside them, which gives the O pair the larger
  tilting stiffness and the smaller radial compliance at the nose (Harris & Kotzalas 2006, Essential Concepts of
  Bearing Technology, ch. 1 and 8: the effective spread of duplex pairs; the reason spindle noses carry O pairs);
- a floating outer ring (preload by springs or an actuator) takes no axial force: the condensed seat's force has
  no z component for any motion and equals the bearing's force at the ring's relative displacement.
Tolerances: rounding (1e-9 relative) where both sides are the same linear algebra; the arrangement checks are
inequalities between configurations that differ by centimetres of spread.
"""

import numpy as np
import pytest

from bearing_fmu_common.paramfile import ParameterError
from spindle.shaft import ShaftModel
from spindle.shaft.declarations import K_START
from spindle.shaft.params import shaft_path

K_B7214C = np.array([K_START, K_START])  # a B7214C's K in its own frame at 10 000 rpm, 500 N radial, 800 N axial
C_SEATS = np.array([np.diag([2000.0, 2000.0, 0.0, 0.0, 0.0])] * 2)


def shaft_with_axes(tmp_path, front, rear):
    """The default shaft with its seats' bearing_axis set to `front` and `rear`."""
    text = shaft_path("rabreau_b7214c").read_text()
    for seat, axis in (("front_bearing", front), ("rear_bearing", rear)):
        for old in ("-z", "+z"):
            text = text.replace(f'"{seat}"\nbearing_axis = "{old}"', f'"{seat}"\nbearing_axis = "{axis}"')
    path = tmp_path / f"shaft_{front}_{rear}.toml".replace("+", "p").replace("-", "m")
    path.write_text(text)
    return str(path)


def pressure_centres(model):
    """Axial positions (m) where the seats' bearings act on the shaft: seat node + K'[1,5] / K'[1,1]."""
    K = model.seat_stiffness(K_B7214C)
    z = model.shaft.z[list(model.shaft.seat_nodes)]
    return z + K[:, 0, 4] / K[:, 0, 0]


def test_the_default_shaft_is_an_x_pair():
    model = ShaftModel()
    assert model.shaft.seat_axes == (-1, 1)
    front, rear = model.shaft.z[list(model.shaft.seat_nodes)]
    c_front, c_rear = pressure_centres(model)
    assert front < c_front < c_rear < rear  # X: the pressure centres between the bearings


def test_o_pair_has_the_wider_spread_and_the_stiffer_nose(tmp_path):
    x_pair = ShaftModel(shaft_with_axes(tmp_path, "-z", "+z"))
    o_pair = ShaftModel(shaft_with_axes(tmp_path, "+z", "-z"))
    front, rear = o_pair.shaft.z[list(o_pair.shaft.seat_nodes)]
    c_front, c_rear = pressure_centres(o_pair)
    assert c_front < front and rear < c_rear  # O: outside the bearings
    x_out = x_pair.evaluate(0.0, K_B7214C, C_SEATS, critical_speeds=False)
    o_out = o_pair.evaluate(0.0, K_B7214C, C_SEATS, critical_speeds=False)
    assert o_out["compliance_radial"] < 0.8 * x_out["compliance_radial"]
    # the axial compliance does not depend on which way the pair faces (to the coupling terms' rounding)
    assert o_out["compliance_axial"] == pytest.approx(x_out["compliance_axial"], rel=0.05)


def test_mirroring_is_its_own_inverse_and_keeps_the_diagonal():
    model = ShaftModel()
    once = model.seat_frame(K_B7214C)
    np.testing.assert_array_equal(np.diagonal(once, axis1=1, axis2=2), np.diagonal(K_B7214C, axis1=1, axis2=2))
    np.testing.assert_array_equal(once[1], K_B7214C[1])  # the rear bearing's axis is the shaft's
    assert once[0, 0, 4] == -K_B7214C[0, 0, 4] and once[0, 0, 1] == K_B7214C[0, 0, 1]
    np.testing.assert_array_equal(model.seat_frame(once), K_B7214C)


def test_a_floating_seat_takes_no_axial_force():
    model = ShaftModel(floating=(False, True))
    condensed = model.seat_stiffness(K_B7214C)
    K = model.seat_frame(K_B7214C)[1]
    rng = np.random.default_rng(1)
    for d in rng.normal(size=(5, 5)) * np.array([1e-6, 1e-6, 1e-6, 1e-5, 1e-5]):
        force = condensed[1] @ d
        u = K[2] @ d / K[2, 2]  # the outer ring's axial motion that leaves it in balance
        relative = d - u * np.eye(5)[2]
        assert abs(force[2]) <= 1e-9 * np.max(np.abs(K @ d))
        np.testing.assert_allclose(force, K @ relative, rtol=1e-9, atol=1e-9 * np.max(np.abs(K @ d)))
    np.testing.assert_array_equal(condensed[0], model.seat_frame(K_B7214C)[0])  # the located seat unchanged


def test_a_floating_rear_bearing_leaves_the_axial_load_to_the_front_one():
    held = ShaftModel().evaluate(0.0, K_B7214C, C_SEATS, critical_speeds=False)
    floating = ShaftModel(floating=(False, True)).evaluate(0.0, K_B7214C, C_SEATS, critical_speeds=False)
    # two equal bearings in parallel against one: about twice the axial compliance (the shaft's own is small)
    assert 1.8 < floating["compliance_axial"] / held["compliance_axial"] < 2.1
    assert floating["compliance_radial"] == pytest.approx(held["compliance_radial"], rel=0.05)


def test_bad_bearing_axis_and_floating_count_are_refused(tmp_path):
    path = shaft_with_axes(tmp_path, "z", "+z")
    with pytest.raises(ParameterError, match=r"seat 'front_bearing': bearing_axis = 'z' is not allowed; allowed"):
        ShaftModel(str(path))
    with pytest.raises(ValueError, match=r"floating: 1 values, expected one per seat"):
        ShaftModel(floating=(True,))
