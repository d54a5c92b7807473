"""The numeric parameters' declared ranges are the ranges the product accepts, and a refusal inside them names the
FMU parameters it comes from (the models' side of tests/fmu/test_fuzz.py::test_fuzz_inside, without an FMU build).

- Every end of the declared range of a bearing_data.*, lubricant_data.* and network dimension parameter is a value
  some set takes: with the default set, or with the companions listed here (a 10 m pitch circle for a 9.99 m bore).
  A lubricant law's constant may be 0 only as the constant of a law not chosen (its start value in an FMU that
  starts with another law), so its 0 is checked with another law chosen.
- A refusal of a value inside the range names the parameter that was set, with its value, in FMU names.
"""

import pytest

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.declarations import ANALYTIC_PARAMETERS
from bearing_fmu.models.file_parameters import (
    BEARING_QUANTITIES,
    LUBRICANT_QUANTITIES,
    bearing_from_values,
    bearing_values,
    lubricant_from_values,
    lubricant_values,
)
from bearing_fmu.models.limits import InputError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import ParameterError, catalogue, clearance_for_angle
from bearing_fmu.scene import Scene
from spindle.thermal.declarations import dimension_declarations
from spindle.thermal.model import load_spindle, with_dimensions

B6208 = bearing_values("6208")
GUESSASMA = lubricant_values("guessasma_oil")
# the smallest bearing the ranges allow: 0.1 mm balls on a 0.5 mm pitch circle, its lands and rings estimated
SMALLEST = {"bearing_data.D": 1e-4, "bearing_data.d_m": 5e-4, "bearing_data.Z": 3, "bearing_data.Pd": 0.0}
SMALLEST |= {f"bearing_data.{name}": 0.0 for name in ("bore", "outer_diameter", "width", "cage_ball_radius")}
SMALLEST |= {f"bearing_data.shoulder_{ring}{side}": 0.0 for ring in ("inner", "outer") for side in ("", "_back")}
# the largest pitch circle with balls that leave a 9.99 m bore and inner lands room; one just inside 10 m for the outer
# ring's 10 m lands and diameter
LARGEST = {**SMALLEST, "bearing_data.d_m": 10.0, "bearing_data.D": 0.02}
OUTER_10 = {**SMALLEST, "bearing_data.d_m": 9.99, "bearing_data.D": 0.02}
COMPANIONS = {  # (parameter, end) -> the other values a set at that end takes (beyond the default set's)
    ("bearing_data.D", 1e-4): SMALLEST,
    ("bearing_data.d_m", 5e-4): SMALLEST,
    ("bearing_data.D", 1.0): {**LARGEST, "bearing_data.D": 1.0},
    ("bearing_data.Pd", -0.01): {**LARGEST, "bearing_data.D": 1.0},
    ("bearing_data.Pd", 0.01): {**LARGEST, "bearing_data.D": 1.0, "bearing_data.alpha0": 0.0},
    ("bearing_data.alpha0", 1.0471975511965976): {**SMALLEST, "bearing_data.Pd": None},
    ("bearing_data.d_m", 10.0): LARGEST,
    ("bearing_data.bore", 9.99): {**LARGEST, "bearing_data.D": 0.005},
    ("bearing_data.shoulder_inner", 9.99): LARGEST,
    ("bearing_data.shoulder_inner_back", 9.99): LARGEST,
    ("bearing_data.shoulder_outer", 10.0): OUTER_10,
    ("bearing_data.shoulder_outer_back", 10.0): OUTER_10,
    ("bearing_data.outer_diameter", 10.0): {**OUTER_10, "bearing_data.D": 0.005},
    ("bearing_data.Ra_inner", 0.0): {"bearing_data.Ra_ball": 1e-7},  # a rough ball: the contact's sigma > 0
    ("bearing_data.Ra_outer", 0.0): {"bearing_data.Ra_ball": 1e-7},
    ("bearing_data.width", 10.0): LARGEST,
    ("bearing_data.cage_ball_radius", 1.0): {**LARGEST, "bearing_data.Z": 3},
    ("bearing_data.Z", 200): LARGEST,
    ("bearing_data.f_i", 0.501): {"bearing_data.Pd": 0.0},
    ("bearing_data.f_o", 0.501): {"bearing_data.Pd": 0.0},
}


def ends(quantities):
    """(name, end) of every Real and Integer quantity: both ends of its declared range."""
    return [(q.variable.name, end) for q in quantities for end in (q.variable.min, q.variable.max)]


def with_companions(base, name, end):
    values = {**base, **COMPANIONS.get((name, end), {}), name: end}
    return {key: value for key, value in values.items() if value is not None or key != "bearing_data.Pd"}


@pytest.mark.parametrize("name,end", ends(BEARING_QUANTITIES))
def test_every_declared_end_of_a_bearing_parameter_is_a_bearing(name, end):
    """The 6208 with this one value at a declared end (and the companions that end needs) is accepted as a bearing:
    bearing_from_values raises ParameterError, failing the test, for a value it refuses."""
    values = with_companions(B6208, name, end)
    if values.get("bearing_data.Pd") is None:  # the clearance of the contact angle (the file's rule)
        D, f_i, f_o = (values[f"bearing_data.{k}"] for k in ("D", "f_i", "f_o"))
        values["bearing_data.Pd"] = clearance_for_angle(D, f_i, f_o, values["bearing_data.alpha0"])
    bearing_from_values(values)


OILS = [lubricant_values(name) for name in catalogue("lubricants")]
# the Walther law's two points in order: T_1 < T_2 and nu_2 < nu_1
LUBRICANT_COMPANIONS = {
    ("lubricant_data.T_1", 699.0): {"lubricant_data.T_2": 700.0},
    ("lubricant_data.nu_2", 0.999): {"lubricant_data.nu_1": 1.0},
}
RANGES = ({}, {"lubricant_data.T_low": 250.0, "lubricant_data.T_high": 700.0})  # a data range: both ends or none


@pytest.mark.parametrize("name,end", ends(LUBRICANT_QUANTITIES))
def test_every_declared_end_of_a_lubricant_parameter_is_a_lubricant(name, end):
    """Some catalogue oil with this one value changed (and a data range given or not) is a lubricant; a law's
    constant is changed in an oil with that law, but for its 0, the constant of a law not chosen."""
    law = next(q.used_when for q in LUBRICANT_QUANTITIES if q.variable.name == name)
    in_use = law and end != 0.0  # a constant's other values are those of its law, chosen
    refusals = []
    for oil in (oil for oil in OILS if not in_use or oil[law[0]] == law[1]):
        for data_range in RANGES:
            try:
                lubricant_from_values({**oil, **data_range, **LUBRICANT_COMPANIONS.get((name, end), {}), name: end})
                return
            except ParameterError as exc:
                refusals.append(str(exc))
    pytest.fail("\n".join(refusals))


NETWORK = load_spindle("b7214c_x_pair")
DIMENSIONS = {v.name: v.start for v in dimension_declarations(NETWORK)[1:]}
NETWORK_COMPANIONS = {  # (dimension, end) -> the other dimensions of a bearing at that end
    ("D", 1e-4): {"Pd": 0.0},
    ("D", 1.0): {"d_m": 5.0, "bore": 1.0},
    ("d_m", 5e-4): {"D": 1e-4, "bore": 5e-5, "Pd": 0.0},
    ("bore", 9.99): {"d_m": 10.0, "D": 0.005},
    ("Pd", -0.01): {"D": 1.0, "d_m": 5.0, "bore": 1.0},
    ("Pd", 0.01): {"D": 1.0, "d_m": 5.0, "bore": 1.0},
}


@pytest.mark.parametrize("var", dimension_declarations(NETWORK)[1:], ids=lambda v: v.name)
def test_every_declared_end_of_a_network_dimension_is_a_network(var):
    """The rig's network with this dimension at each declared end is accepted: with_dimensions raises, failing the
    test, for a value it refuses."""
    for end in (var.min, var.max):
        values = dict(DIMENSIONS)
        if var.name.startswith("bearing_"):
            prefix, short = var.name.split(".")
            values |= {f"{prefix}.{k}": v for k, v in NETWORK_COMPANIONS.get((short, end), {}).items()}
        with_dimensions(NETWORK, {**values, var.name: end})


@pytest.mark.parametrize(
    "values,words",
    [
        (  # a ball the given lands do not fit
            {"bearing_data.D": 1e-4},
            ("bearing_data.shoulder_inner = 0.05304 m", "bearing_data.D = 0.0001 m", "bearing_data.d_m = 0.0606 m"),
        ),
        (  # a clearance past the groove's: the values the groove clearance comes from
            {"bearing_data.Pd": 0.01},
            ("bearing_data.Pd = 0.01 m", "bearing_data.f_i = 0.52", "bearing_data.D = 0.0126 m", "60 deg"),
        ),
        (  # a ball that changes the free contact angle of the clearance away from the nominal angle
            {"bearing_data.D": 0.01, "bearing_data.kind": 1, "bearing_data.alpha0": 0.2618, "bearing_data.Pd": 5.4e-5},
            ("bearing_data.alpha0 = 0.2618 rad", "bearing_data.D = 0.01 m", "bearing_data.f_o = 0.52"),
        ),
    ],
)
def test_a_bearing_refusal_names_the_parameters_it_comes_from(values, words):
    with pytest.raises(ParameterError) as info:
        bearing_from_values({**B6208, **values})
    assert all(word in str(info.value) for word in words), str(info.value)


@pytest.mark.parametrize(
    "values,words",
    [
        ({"lubricant_data.viscosity_model": 1}, ("lubricant_data.nu_1 = 0.0", "lubricant_data.viscosity_model = 1")),
        ({"lubricant_data.density_model": 1}, ("lubricant_data.rho_R = 0.0", "lubricant_data.density_model = 1")),
        ({"lubricant_data.pressure_viscosity_model": 2}, ("lubricant_data.pressure_viscosity_model = 2 ('wlf')",)),
        ({"lubricant_data.T_high": 400.0}, ("lubricant_data.T_low = 0.0 (not given)",)),  # half a data range
    ],
)
def test_a_law_chosen_without_its_constants_is_refused_naming_the_choice(values, words):
    with pytest.raises(ParameterError) as info:
        lubricant_from_values({**GUESSASMA, **values})
    assert all(word in str(info.value) for word in words), str(info.value)


def test_a_clearance_beyond_the_groove_names_the_bearing():
    with pytest.raises(InputError, match=r"Pd = 0.01 m \(set\) .* D = 0.0126 m of bearing '6208'"):
        AnalyticModel("6208", Pd=0.01)


def test_a_preload_beyond_the_material_limit_names_the_bearing():
    """The declared 1e8 N is the static bound of every bearing; the refusal names the bearing whose limit is lower."""
    scene = Scene.from_toml(SCENES_DIR / "quasi_static_fixed_preload.toml")
    with pytest.raises(InputError, match=r"F_preload = 100000000.0 N .* material limit of bearing 'B7214C': p_max"):
        QuasiStaticModel("B7214C", scene=scene, F_preload=1e8)


def test_the_analytic_fmu_declares_the_deep_groove_bearing_it_models():
    """Kind 1 (angular contact) and a contact angle above 0 are never modelled by the analytic fidelity: its FMU
    declares both [0, 0], with the reason."""
    declared = {v.name: v for v in ANALYTIC_PARAMETERS}
    for name in ("bearing_data.kind", "bearing_data.alpha0"):
        assert (declared[name].min, declared[name].max) == (0, 0)
        assert "deep-groove" in declared[name].limits
