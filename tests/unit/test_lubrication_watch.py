"""What a lubrication method cannot do is said (bearing_fmu.models.lubrication.LubricationWatch).

- A method with inlet shear heating and an oil of constant viscosity (guessasma_oil: eta = 0.04 Pa.s at every
  temperature) reduces no film: beta = -d ln(eta)/dT = 0, phi_ish = 1 (docs/lubrication_method.md, section 1). Said
  once, at the first evaluation at speed.
- An oil bath or oil jet with the default 20 um inlet layer leaves the 6208 fully flooded (phi_rs = 1.000) at every
  speed of the SKF comparison, where SKF's empirical factor gives 0.63-0.955 (docs/reports/lubrication_skf.md). Said
  once per entry into that state, in the analytic and the quasi-static fidelity; oil-air (2 um, starved: phi_rs
  0.79-0.94) and the flooded method say nothing.
"""

import math
from dataclasses import replace

import pytest

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

RPM = math.pi / 30.0
CONSTANT = "whose viscosity is constant"
FLOODED = "fills every loaded inlet"


def quasi_static(lubricant, method, **scene):
    base = Scene.from_toml(SCENES_DIR / "quasi_static.toml")
    return QuasiStaticModel("6208", lubricant, replace(base, lubrication=method, **scene))


def said(model, rpm):
    model.evaluate(omega=rpm * RPM, F_y=3000.0, T_oil=313.15)
    return model.warnings


@pytest.mark.parametrize("method", ["oil_jet", "oil_bath"])
def test_constant_viscosity_and_a_flooded_inlet_are_said_once(method):
    """guessasma_oil, oil jet or bath, 6208 at 3 kN: at rest nothing (no inlet is fed); at 955 rpm both warnings,
    naming the method, the lubricant and the layer; at 9549 rpm (phi_rs still 1) nothing more."""
    model = quasi_static("guessasma_oil", method)
    assert said(model, 0.0) == []
    first = said(model, 955.0)
    assert len(first) == 2
    assert CONSTANT in first[0] and f"'{method}'" in first[0] and "'guessasma_oil'" in first[0]
    assert FLOODED in first[1] and "20 um" in first[1] and "phi_rs = 1" in first[1]
    assert model.values[model.output_names.index("phi_rs_inner")] == 1.0
    assert said(model, 9549.0) == []


def test_a_starved_method_and_a_viscosity_law_say_nothing_of_it():
    """iso_vg68_mineral (Walther viscosity law: beta > 0, phi_ish 0.48-0.94) with oil_air (2 um: phi_rs < 1): no
    lubrication warning; with oil_jet only the flooded inlet is said; flooded says nothing."""
    assert not any(CONSTANT in w or FLOODED in w for w in said(quasi_static("iso_vg68_mineral", "oil_air"), 9549.0))
    jet = said(quasi_static("iso_vg68_mineral", "oil_jet"), 9549.0)
    assert [FLOODED in w for w in jet if CONSTANT in w or FLOODED in w] == [True]
    assert said(quasi_static("guessasma_oil", "flooded"), 9549.0) == []


def test_the_flooded_inlet_is_said_again_after_the_contacts_starved():
    """Once per entry: with a 5 um inlet layer the 6208 runs flooded at 955 rpm (said), starved at 9549 rpm
    (phi_rs 0.96 inner, 0.92 outer: nothing said) and flooded again at 955 rpm (said again)."""
    model = quasi_static("iso_vg68_mineral", "oil_jet", inlet_oil_layer=5e-6)
    entries = []
    for rpm in (955.0, 9549.0, 955.0):
        told = [w for w in said(model, rpm) if FLOODED in w]
        phi = model.values[model.output_names.index("phi_rs_inner")]
        entries.append((len(told), phi == 1.0))
    assert entries == [(1, True), (0, False), (1, True)]


def test_the_analytic_fidelity_says_it_too():
    base = Scene.from_toml(SCENES_DIR / "analytic.toml")
    model = AnalyticModel("6208", "guessasma_oil", replace(base, lubrication="oil_jet"))
    told = said(model, 955.0)
    assert any(CONSTANT in w for w in told) and any(FLOODED in w for w in told)
