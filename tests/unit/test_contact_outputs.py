"""kernels.contact_outputs.contact_outputs against its twin tests/reference/ref_contact_outputs.py.

contact_outputs produces every film, capacitance, torque and heat output of the quasi-static fidelity
(Bearing.fmu). The per-ball inputs come from solved bearings (QuasiStaticModel), so the contacts see
real load, rolling and spin distributions: unloaded balls, rest, both race controls, several scenes.

Tolerances (relative), from the twins the contact twin is built on:
- RTOL = 1e-12 for the oil state, Hertz pressure, film thickness and parameter, and capacitance: closed
  forms in kernel and twin (tests/unit/test_lubricant.py, test_hertz.py, test_ehl.py, test_capacitance.py
  pin each at 1e-12); the power laws of the film formulas (exponents below 1) do not amplify the
  rounding of their inputs. Measured over the cases below: 7.1e-16.
- QUAD_RTOL = 1e-9 for the losses, ring heats and torque: the loss twins integrate the Hertz pressure
  by 2D quadrature at 1e-10 of the integral's scale (tests/unit/test_torque.py uses the same bound).
  Sums over the contacts of positive terms keep the relative bound. Measured over the cases below: 1.2e-13.
- CAP_RTOL = 1e-9 for the capacitance with the oil around the contacts (scene capacitance_region =
  'lubricated'): kernel and twin take the same outside-Hertz kernel, but its quadrature places its cut points
  with acos and square roots of differences, which amplify the last-bit differences of the two sides' Hertz
  sizes. Measured: 8.2e-12.
- METHOD_RTOL = 1e-6 with a lubrication method: the meniscus (Illinois in the kernel, brentq on a quadrature
  gap in the twin) agrees to 1e-9 in m - 1 (test_lubrication.py); films, Lambda, mu and losses follow it.
- Loads, ball counts and regimes are equal: the loads are copied, the counts and regimes integers.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import contact_outputs as ck
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.reference import ref_contact_outputs as rc
from tests.unit._compare import assert_close
from tests.unit.test_film_correction import made_up_table

RTOL = 1e-12
QUAD_RTOL = 1e-9
CAP_RTOL = 1e-9
RPM = 2.0 * math.pi / 60.0
LOSSES = (ck.CO_P_LOSS, ck.CO_Q_INNER_RING, ck.CO_Q_OUTER_RING, ck.CO_TORQUE) + tuple(ck.CO_P_EHL + t for t in range(4))
# the lubrication method's starvation (Illinois against brentq, tests/unit/test_lubrication.py) and what follows it
METHOD_RTOL = 1e-6
EXACT = (ck.CO_QMAX_I, ck.CO_QMAX_O, ck.CO_N_LOADED, ck.CO_REGIME)

# (label, bearing, scene options, inputs)
CASES = [
    ("B7214C ORCG 10k, combined", "B7214C", dict(gyroscopic=True), dict(omega=10000 * RPM, F_z=800.0, F_x=1000.0)),
    ("B7214C hybrid 6k, mean pressure, background, torque off", "B7214C", dict(gyroscopic=True, race_control="hybrid",
     permittivity_pressure="mean", background_capacitance=30e-12, torque=False), dict(omega=6000 * RPM, F_z=800.0,
     M_y=20.0)),
    ("6208 radial 3k, unloaded balls, Chittenden, capacitance off", "6208", dict(film="chittenden", capacitance=False),
     dict(omega=3000 * RPM, F_x=3000.0)),
    ("6208 at rest", "6208", dict(), dict(omega=0.0, F_x=2000.0, F_z=300.0)),
    ("6208 lubricated region", "6208", dict(capacitance_region="lubricated", oil_gap=5e-6),
     dict(omega=3000 * RPM, F_x=3000.0, F_z=200.0)),
    ("6208 inner race control, Masjedi-Khonsari, hot", "6208", dict(race_control="inner", film="masjedi_khonsari"),
     dict(omega=-2000 * RPM, F_x=1500.0, T_oil=353.15)),
    ("6208 oil bath 9k", "6208", dict(lubrication="oil_bath", oil_level=1.0), dict(omega=9000 * RPM, F_x=3000.0)),
    ("B7214C oil-air 10k", "B7214C", dict(gyroscopic=True, lubrication="oil_air"),
     dict(omega=10000 * RPM, F_z=800.0)),
    ("B7214C grease 3k, torque off", "B7214C", dict(lubrication="grease", torque=False),
     dict(omega=3000 * RPM, F_z=1500.0)),
    ("6208 oil jet at rest", "6208", dict(lubrication="oil_jet"), dict(omega=0.0, F_x=2000.0)),
]  # fmt: skip


@pytest.mark.parametrize("label, bearing, options, inputs", CASES, ids=[c[0] for c in CASES])
def test_contact_outputs_match_twin(label, bearing, options, inputs):
    scene = Scene(name="contacts", fidelity="quasi_static", **{"torque": True, **options})
    m = QuasiStaticModel(bearing, "iso_vg68_mineral", scene)
    inputs = {"T_oil": 323.15, **inputs}
    m.evaluate(**inputs)
    compare_with_twin(label, m, scene, inputs)


FILM_TABLE_CASES = CASES[:3] + CASES[6:8]  # with the lubrication method flooded, oil bath and oil-air


@pytest.mark.parametrize("label, bearing, options, inputs", FILM_TABLE_CASES, ids=[c[0] for c in FILM_TABLE_CASES])
def test_contact_outputs_with_a_film_table_match_twin(label, bearing, options, inputs):
    """The film correction on (a table of made-up ratios in the contact array): films, and what depends on them
    (Lambda, regime, capacitance, the losses through mu(Lambda)), as the twin corrects them; with a lubrication
    method its inlet-heating and starvation factors multiply the corrected film."""
    scene = Scene(name="contacts", fidelity="quasi_static", **{"torque": True, **options})
    m = QuasiStaticModel(bearing, "iso_vg68_mineral", scene)
    inputs = {"T_oil": 323.15, **inputs}
    m.evaluate(**inputs)
    plain = m.out[ck.CO_HC_I]
    m.cp[ck.CP_FILM_TABLE :] = made_up_table()
    compare_with_twin(label + ", film table", m, scene, inputs)
    out = np.zeros(ck.CO_SIZE)
    ck.contact_outputs(inputs["omega"], inputs["T_oil"], m.cp, m.lubricant.array, m.balls, out,
                       np.zeros((ck.PC_SIZE, m.bearing.Z)), np.zeros(4))  # fmt: skip
    assert out[ck.CO_HC_I] != plain  # the table is read


def compare_with_twin(label, m, scene, inputs):
    """contact_outputs of the solved model m against the twin, slot by slot."""
    Z = m.bearing.Z
    out = np.full(ck.CO_SIZE, np.nan)
    per_contact = np.full((ck.PC_SIZE, Z), np.nan)
    ck.contact_outputs(
        inputs["omega"], inputs["T_oil"], m.cp, m.lubricant.array, m.balls, out, per_contact, np.zeros(4)
    )
    ref, ref_pc = rc.contact_outputs(inputs["omega"], inputs["T_oil"], m.cp, m.lubricant.array, m.balls)
    cap_tol = CAP_RTOL if scene.capacitance_region == "lubricated" else RTOL
    # a submodel that is off leaves exactly the slots the twin leaves NaN
    assert np.array_equal(np.isnan(out), np.isnan(ref)) and np.array_equal(np.isnan(per_contact), np.isnan(ref_pc))
    for k in range(ck.CO_SIZE):
        if math.isnan(ref[k]):
            continue
        if k in EXACT:
            assert out[k] == ref[k], f"{label}: slot {k}"
        else:
            tol = QUAD_RTOL if k in LOSSES else (cap_tol if k == ck.CO_C_BEARING else RTOL)
            assert_close(out[k], ref[k], max(tol, METHOD_RTOL) if scene.lubricated else tol, f"{label}: slot {k}")
    for row in range(ck.PC_SIZE):
        if not math.isnan(ref_pc[row, 0]):
            tol = QUAD_RTOL if row in (ck.PC_P_I, ck.PC_P_O) else (cap_tol if row in (ck.PC_C_I, ck.PC_C_O) else RTOL)
            tol = max(tol, METHOD_RTOL) if scene.lubricated else tol
            assert_close(per_contact[row], ref_pc[row], tol, f"{label}: per-contact row {row}")
    loaded = m.balls[0] > 0.0
    assert np.any(loaded)
    if "unloaded" in label:
        assert not np.all(loaded)
    if inputs["omega"] == 0.0 and scene.torque:
        assert out[ck.CO_TORQUE] == 0.0
