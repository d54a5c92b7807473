"""The scene option `lubrication` in the models: validation, null submodel, bookkeeping and trends.

Sources of the trends: Hamrock & Dowson 1977 (a fixed inlet layer starves more as the flooded film, i.e. the
speed, grows), Gupta et al. 1992 (the thermal reduction grows with the thermal loading beta eta u^2 / k_f), the
drag of a sphere at Re > 1000 (~ v^3, power). Exact relations are checked exactly.
"""

import math
from dataclasses import replace

import pytest

from bearing_fmu import AnalyticModel, QuasiStaticModel, Scene
from bearing_fmu.scene import SceneError

RPM = math.pi / 30.0
QS = Scene.from_toml("bearing_fmu/scenes/quasi_static.toml")


def test_scene_refuses_bad_values():
    with pytest.raises(SceneError, match="lubrication = 'mist'"):
        Scene(lubrication="mist").validate()
    with pytest.raises(SceneError, match=r"oil_level = 0.5 needs lubrication in \['oil_bath'\]"):
        Scene(lubrication="oil_jet", oil_level=0.5).validate()
    with pytest.raises(SceneError, match=r"inlet_oil_layer = 1.0 m: allowed \[1e-08, 0.01\] m"):
        Scene(lubrication="grease", inlet_oil_layer=1.0).validate()
    with pytest.raises(SceneError, match="not in the DEM yet"):
        Scene(fidelity="dem", lubrication="oil_air").validate()
    with pytest.raises(SceneError, match="cavity_oil_fraction"):
        Scene.from_dict({"lubrication": "oil_air", "cavity_oil_fraction": 2.0})


def test_flooded_has_no_method_outputs():
    names = QuasiStaticModel("6208", "iso_vg68_mineral", QS).output_names
    assert not {"phi_ish_inner", "phi_rs_inner", "torque_drag", "P_drag"} & set(names)
    names = QuasiStaticModel("6208", "iso_vg68_mineral", replace(QS, lubrication="grease")).output_names
    assert {"phi_ish_inner", "phi_rs_outer"} <= set(names) and "torque_drag" not in names
    names = AnalyticModel("6208", "iso_vg68_mineral", Scene(lubrication="oil_bath")).output_names
    assert {"phi_ish_inner", "torque_drag", "P_drag"} <= set(names)


def test_drag_is_in_torque_and_ring_heat():
    m = QuasiStaticModel("6208", "iso_vg68_mineral", replace(QS, lubrication="oil_bath", oil_level=1.0))
    r = m.evaluate(omega=6000 * RPM, F_y=3000.0)
    assert r["P_drag"] > 0.0
    assert r["torque_drag"] == r["P_drag"] / (6000 * RPM)
    assert r["P_loss"] == pytest.approx(r["Q_inner_ring"] + r["Q_outer_ring"], rel=1e-15)
    assert r["torque"] == pytest.approx(r["P_loss"] / (6000 * RPM), rel=1e-15)
    flooded = QuasiStaticModel("6208", "iso_vg68_mineral", QS).evaluate(omega=6000 * RPM, F_y=3000.0)
    assert r["Lambda_inner"] < flooded["Lambda_inner"]  # the thermal factor thins the film


def test_starvation_grows_with_speed():
    m = AnalyticModel("6208", "iso_vg68_mineral", Scene(lubrication="oil_air"))
    phis = [m.evaluate(n * RPM, 3000.0, 313.15)["phi_rs_inner"] for n in (1000, 3000, 10000)]
    ish = [m.evaluate(n * RPM, 3000.0, 313.15)["phi_ish_inner"] for n in (1000, 3000, 10000)]
    assert 1.0 >= phis[0] > phis[1] > phis[2] > 0.0
    assert 1.0 > ish[0] > ish[1] > ish[2] > 0.0


def test_bath_drag_grows_with_level_and_speed():
    def drag(level, n):
        return AnalyticModel("6208", "iso_vg68_mineral", Scene(lubrication="oil_bath", oil_level=level)).evaluate(
            n * RPM, 3000.0, 313.15
        )["P_drag"]

    assert drag(0.0, 3000) == 0.0
    assert 0.0 < drag(0.5, 3000) < drag(1.0, 3000) < drag(3.0, 3000)
    # Newton's regime (Re > 1000 at these speeds): power ~ v^3
    assert drag(1.0, 10000) / drag(1.0, 5000) == pytest.approx(8.0, rel=0.02)
