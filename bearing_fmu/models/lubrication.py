"""The scene's lubrication method turned into the numbers the kernels read (kernels.lubrication).

docs/lubrication_method.md gives the physics and the sources. Each method sets four things:
- inlet shear heating (the thermal film factor phi_ish) on or off;
- the inlet oil layer h_oil (m, both surfaces) that the method leaves on the track ahead of a contact and from
  which the Hamrock-Dowson starvation follows (inf: none);
- the drag of the balls: the oil-volume fraction X of the fluid they move through and the part of their
  frontal area in it (oil bath: oil, X = 1, the time-mean immersed part from the oil level; oil jet and oil-air:
  the cavity's oil-air mixture, whole ball);
- the oil's thermal conductivity k_f of the thermal loading number.
The flooded method is today's model: isothermal, fully flooded, no drag; nothing of this is computed.
"""

import math

import numpy as np

from ..kernels.lubricant import LUB_VISC_MODEL, VISCOSITY_CONSTANT
from ..kernels.lubrication import (
    LM_DRAG,
    LM_DRAG_AREA,
    LM_DRAG_X,
    LM_H_OIL,
    LM_K_OIL,
    LM_ON,
    LM_SIZE,
    LM_THERMAL,
    METHOD_FLOODED,
    METHOD_GREASE,
    METHOD_OIL_AIR,
    METHOD_OIL_BATH,
    METHOD_OIL_JET,
)
from ..scene import DRAG_METHODS

METHOD_CODES = {
    "flooded": METHOD_FLOODED,
    "oil_bath": METHOD_OIL_BATH,
    "oil_jet": METHOD_OIL_JET,
    "oil_air": METHOD_OIL_AIR,
    "grease": METHOD_GREASE,
}

# Thermal conductivity of mineral and PAO base oils at 40-100 C: 0.12-0.15 W/(m K) (ESTIMATED: e.g. the
# VDI Heat Atlas' mineral-oil data and Larsson & Andersson 2000, Lubricant thermal conductivity and heat
# capacity under high pressure, Proc. IMechE J 214: 0.13-0.14 W/(m K) at ambient pressure; memory, unverified).
# The lubricant files carry no conductivity: this one value serves every oil.
OIL_THERMAL_CONDUCTIVITY = 0.13  # W/(m K)

# Method defaults (ESTIMATED, docs/lubrication_method.md section 3): none is fitted to the SKF model.
# inlet_oil_layer (m): a full inlet of these bearings needs the gap at m*, h_c + g(m*), some 2-8 um at
# 10^3-10^4 rpm (6208 and B7214C, VG46-68): bath and jet put far more than that on the track (20 um: starved
# only at the highest speeds and viscosities); oil-air (a few hundredths to tenths of a gram of oil an hour)
# and grease (bled oil) leave layers of the order of the film itself (2 and 1 um).
# oil_level (ball diameters above the lowest point of the outer raceway): 0.5, the centre of the lowest ball at
# rest, the level the bearing makers recommend for an oil bath (SKF, Schaeffler lubrication guides; unverified).
# cavity_oil_fraction (-): oil-volume fraction of the cavity the balls move through: jet 1 % (Parker 1984,
# NASA TP-2275, relates it to the jet flow; order 0.1-1 % for usual flows, memory, unverified), oil-air 1e-4
# (mostly air: 0.1 g/h of oil in an air flow of order 1e-4 m^3/s).
METHODS = {
    "flooded": {"thermal": False, "inlet_oil_layer": math.inf, "oil_level": None, "cavity_oil_fraction": None},
    "oil_bath": {"thermal": True, "inlet_oil_layer": 20e-6, "oil_level": 0.5, "cavity_oil_fraction": None},
    "oil_jet": {"thermal": True, "inlet_oil_layer": 20e-6, "oil_level": None, "cavity_oil_fraction": 0.01},
    "oil_air": {"thermal": True, "inlet_oil_layer": 2e-6, "oil_level": None, "cavity_oil_fraction": 1e-4},
    "grease": {"thermal": True, "inlet_oil_layer": 1e-6, "oil_level": None, "cavity_oil_fraction": None},
}


class Lubrication:
    """The method's numbers for one bearing (m, -): thermal (bool), h_oil, drag (bool), X, area_fraction, k_f."""

    def __init__(self, scene, D, dm):
        method = scene.lubrication
        defaults = METHODS[method]
        self.method = method
        self.code = METHOD_CODES[method]
        self.thermal = defaults["thermal"]
        layer = scene.inlet_oil_layer
        self.h_oil = defaults["inlet_oil_layer"] if layer is None else float(layer)
        self.drag = method in DRAG_METHODS
        self.k_f = OIL_THERMAL_CONDUCTIVITY
        self.X = 0.0
        self.area_fraction = 0.0
        if method == "oil_bath":
            level = defaults["oil_level"] if scene.oil_level is None else float(scene.oil_level)
            self.level = level
            self.X = 1.0
            self.area_fraction = immersed_area_fraction(level * D, D, dm)
        elif self.drag:
            x = scene.cavity_oil_fraction
            self.X = defaults["cavity_oil_fraction"] if x is None else float(x)
            self.area_fraction = 1.0

    @property
    def on(self):
        return self.code != METHOD_FLOODED


class LubricationWatch:
    """What the scene's lubrication method cannot do at the current state, told as warnings (an FMU logs them as
    fmi2Warning):
    - a method with inlet shear heating and an oil of constant viscosity (a lubricant file that gives one
      viscosity, e.g. guessasma_oil): beta = -d ln(eta)/dT = 0, so no film is reduced (phi_ish = 1); once, at the
      first evaluation at speed;
    - an oil bath or oil jet whose inlet layer fills every loaded inlet at speed (phi_rs = 1 on both races): the
      contacts run fully flooded. The starvation follows Hamrock & Dowson's inlet distance with a constant inlet
      layer (20 um by default, estimated), which leaves these bearings flooded at every speed tried, where the SKF
      friction model's empirical factor for bath and jet starves them at speed (docs/lubrication_method.md,
      section 4). Once per entry into that state."""

    SPEED = 1e-9  # rad/s: below it the bearing stands and no inlet is fed

    def __init__(self, lubrication, lubricant):
        self.method = lubrication.method if lubrication.on else None
        self.thermal = lubrication.on and lubrication.thermal
        self.h_oil = lubrication.h_oil
        self.name = lubricant.name
        self.constant = int(lubricant.array[LUB_VISC_MODEL]) == VISCOSITY_CONSTANT
        self.told_constant = False
        self.flooded = False

    def warnings(self, omega, phi_rs):
        """[] or the warnings of an evaluation at inner-ring speed omega (rad/s) whose most loaded contacts have the
        starvation factors phi_rs = (inner, outer) (-)."""
        if self.method is None or abs(omega) < self.SPEED:
            return []
        told = []
        if self.thermal and self.constant and not self.told_constant:
            self.told_constant = True
            told.append(
                f"lubrication = '{self.method}' with lubricant '{self.name}', whose viscosity is constant: no inlet "
                "shear heating (phi_ish = 1; the thermal reduction needs the viscosity's temperature coefficient "
                "-d ln(eta)/dT). Give a lubricant with a viscosity law in temperature for it "
                "(docs/lubrication_method.md)"
            )
        flooded = self.method in ("oil_bath", "oil_jet") and min(phi_rs) >= 1.0
        if flooded and not self.flooded:
            told.append(
                f"lubrication = '{self.method}': the inlet oil layer of {self.h_oil * 1e6:.3g} um fills every loaded "
                f"inlet at {abs(omega) * 30.0 / math.pi:.5g} rpm (phi_rs = 1 on both races), so the contacts run "
                "fully flooded. The SKF friction model's empirical starvation factor for bath and jet (K_rs = 3e-8) "
                "starves such contacts at speed (phi_rs 0.63 on a 6208 at 9 549 rpm in a 68 mm^2/s oil, "
                "docs/reports/lubrication_skf.md): film and torque here are those of a flooded inlet; a thinner "
                "inlet_oil_layer starves them (docs/lubrication_method.md, section 4)"
            )
        self.flooded = flooded
        return told


def immersed_area_fraction(H, D, dm, points=3600):
    """Time-mean part (-) of a ball's frontal area below the oil level H (m, above the lowest point of the outer
    raceway) over one orbit of its centre (radius dm/2): at orbit angle psi from the bottom the ball's lowest
    point is (dm/2)(1 - cos psi) above it, the depth s = H - that, clipped to [0, D], and the frontal circle's
    part below a chord at depth s is (theta - sin theta)/(2 pi), theta = 2 acos(1 - 2 s/D). Mean over points
    equal angles (midpoint rule; the integrand is continuous)."""
    psi = (np.arange(points) + 0.5) * (2.0 * np.pi / points)
    s = np.clip(H - 0.5 * dm * (1.0 - np.cos(psi)), 0.0, D)
    theta = 2.0 * np.arccos(1.0 - 2.0 * s / D)
    return float(np.mean((theta - np.sin(theta)) / (2.0 * np.pi)))


def lubrication_block(lubrication, losses=True):
    """The method's block (kernels.lubrication LM_* layout, float64[LM_SIZE]) that a fidelity's parameter array
    embeds; the drag only with the losses submodel on (`losses`). The flooded method is the null block, all 0:
    nothing of the method is computed."""
    lub = lubrication
    block = np.zeros(LM_SIZE)
    if not lub.on:
        return block
    block[LM_ON] = 1.0
    block[LM_THERMAL] = 1.0 if lub.thermal else 0.0
    block[LM_H_OIL] = lub.h_oil
    block[LM_K_OIL] = lub.k_f
    block[LM_DRAG] = 1.0 if lub.drag and losses else 0.0
    block[LM_DRAG_X] = lub.X
    block[LM_DRAG_AREA] = lub.area_fraction
    return block
