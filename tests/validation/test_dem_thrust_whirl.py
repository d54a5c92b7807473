"""A bearing under pure thrust settles to the axisymmetric solution: no self-excited whirl of the inner ring.

The 218 angular-contact bearing of the textbook thrust cases (40 deg, 16 balls; tests/validation/data/
angular_218_textbook.toml), 8.9 kN thrust, iso_vg68_mineral at 313 K. After 0.1 s at speed a radial load of 2 % of
the thrust for 2 ms kicks the ring (1-2 um); the orbit radius sqrt(x^2 + y^2) of its centre is then followed.
With the papers' Coulomb law at mu(Lambda) = 0.01 in full film the orbit never decays (2.1 um at 5 000 rpm,
7.4 um at 8 000 rpm with the ring held against tilting, 0.3 s after the kick): the balls slide at the Coulomb
limit, which does not damp. With the EHL traction curve and the ring free in five degrees of freedom, the ring
alone (its support_damping = 0) still whirls from 8 000 rpm (about 200 um with milliradians of wobble); on the
default support (1000 N.s/m, the shaft it sits on: docs/dem.md, Ring support) it decays. Asserted, 0.3 s after
the kick (the largest radius over the last 5 ms):
- 3 000, 5 000 and 12 000 rpm: below 1 % of the axial deflection at speed;
- 8 000 rpm: below 0.1 um. There the axial deflection itself passes through zero as the centrifugal force turns
  the contact angles (z = -2 um with the ring held, tens of um free), so 1 % of it is not a measure.
"""

import math

import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import DemModel

BEARING = "tests/validation/data/angular_218_textbook.toml"
THRUST = 8900.0  # N


def orbit_after_a_kick(rpm, traction_limit=0.0, support_damping=None):
    """(largest orbit radius over 0.395-0.4 s, axial displacement) in m, kicked at 0.1-0.102 s."""
    omega = rpm * math.pi / 30.0
    model = DemModel(BEARING, "iso_vg68_mineral", traction_limit=traction_limit, support_damping=support_damping)
    model.advance(2e-3, omega=0.0, F_z=THRUST)
    for k in range(1, 21):
        model.advance(2e-3 + 10e-3 * k / 20, omega=omega * k / 20, F_z=THRUST)
    model.advance(0.1, omega=omega, F_z=THRUST)
    model.advance(0.102, omega=omega, F_z=THRUST, F_x=0.02 * THRUST)
    model.advance(0.395, omega=omega, F_z=THRUST)
    radius = 0.0
    for k in range(1, 51):
        model.advance(0.395 + 1e-4 * k, omega=omega, F_z=THRUST)
        radius = max(radius, math.hypot(model.ring[s.R_X], model.ring[s.R_X + 1]))
    return radius, model.ring[s.R_X + 2]


@pytest.mark.parametrize("rpm", [3000.0, 5000.0, 12000.0])
def test_orbit_decays_below_one_percent_of_the_axial_deflection(rpm):
    """218, 8.9 kN thrust, 3 000, 5 000 and 12 000 rpm, kicked radially: 0.3 s later the ring's orbit is below 1 %
    of its axial deflection (docs/dem.md, Ring support, gives the measured values)."""
    radius, z = orbit_after_a_kick(rpm)
    print(f"218 at {rpm:.0f} rpm: orbit {radius * 1e6:.4f} um, z {z * 1e6:.2f} um")
    assert radius < 0.01 * abs(z)


def test_orbit_at_8000_rpm_stays_below_a_tenth_of_a_micrometre():
    """218, 8.9 kN thrust, 8 000 rpm, kicked radially: 0.3 s later the ring's orbit is below 0.1 um (the papers'
    Coulomb law whirled at 7.4 um), the axial deflection there being too small for a 1 % criterion."""
    radius, z = orbit_after_a_kick(8000.0)
    print(f"218 at 8000 rpm: orbit {radius * 1e6:.4f} um, z {z * 1e6:.2f} um")
    assert radius < 0.1e-6


def test_the_ring_alone_whirls_where_its_support_holds_it():
    """Why the ring has a support: the same kick at 8 000 rpm with support_damping = 0 (the ring held by the balls
    alone) grows into a whirl of more than 10 um (measured about 170-200 um and 3-4 mrad of wobble), where the
    default support leaves below 0.1 um (the test above). A self-excited motion of the free ring, not of the
    integration (the tilt growth rate is the same at half the step: docs/dem.md, Ring support)."""
    radius, z = orbit_after_a_kick(8000.0, support_damping=0.0)
    print(f"218 at 8000 rpm, no support: orbit {radius * 1e6:.1f} um, z {z * 1e6:.2f} um")
    assert radius > 10e-6
