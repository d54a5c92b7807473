"""Scene validation, parameter-file validation and the facade's input checks (scenes: docs/architecture.md;
parameter files: docs/parameters.md)."""

import math

import pytest

from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.limits import InputError
from bearing_fmu.params import ParameterError, catalogue, load_bearing, load_lubricant
from bearing_fmu.scene import Scene, SceneError
from tests.conftest import ROOT


def test_scene_reports_every_problem_at_once():
    with pytest.raises(SceneError) as info:
        Scene(fidelity="fem", film="nope", hertz="rough", roughness_factor=5.0).validate()
    text = str(info.value)
    for word in ("fidelity", "film", "hertz", "roughness_factor"):
        assert word in text


@pytest.mark.parametrize(
    "options, word",
    [
        ({"capacitance_region": "everywhere"}, "capacitance_region = 'everywhere': allowed"),
        ({"capacitance_region": "lubricated", "capacitance": False}, "needs capacitance = true"),
        ({"oil_gap": 0.0}, "oil_gap"),
        ({"oil_gap": 60e-6}, "oil_gap"),
    ],
)
def test_capacitance_region_options_are_checked(options, word):
    with pytest.raises(SceneError, match=word):
        Scene(**options).validate()
    Scene(capacitance_region="lubricated", oil_gap=50e-6).validate()  # the largest oil gap, in every fidelity
    Scene(name="d", fidelity="dem", capacitance_region="lubricated", oil_gap=1e-6).validate()


@pytest.mark.parametrize(
    "option, word",
    [
        ({"gyroscopic": True}, "gyroscopic"),
        ({"torque": True}, "torque"),
        ({"thermal_inputs": True}, "thermal_inputs"),
        ({"drive": "fixed_axial"}, "not a DEM drive"),
        ({"centrifugal": False}, "centrifugal"),
    ],
)
def test_dem_scene_rejects_quasi_static_options(option, word):
    with pytest.raises(SceneError, match=word):
        Scene(name="d", fidelity="dem", **option).validate()


def test_dem_scene_takes_the_physics_options():
    scene = Scene(name="d", fidelity="dem", film="chittenden", hertz="approximate", capacitance=False).validate()
    assert scene.fidelity == "dem"
    assert Scene(name="d", fidelity="dem", drive="displacement").validate().drive == "displacement"


def test_dem_scene_takes_the_stiffness_option():
    """The DEM's K[i,j] come from the contact tangent stiffnesses (docs/dem.md, Stiffness)."""
    assert Scene(name="d", fidelity="dem", stiffness=True).validate().stiffness


def test_each_facade_requires_its_fidelity():
    from bearing_fmu.models.dem import DemModel
    from bearing_fmu.models.quasi_static import QuasiStaticModel

    with pytest.raises(InputError, match="DemModel needs 'dem'"):
        DemModel(scene=Scene(name="q", fidelity="quasi_static"))
    with pytest.raises(InputError, match="QuasiStaticModel needs 'quasi_static'"):
        QuasiStaticModel(scene=Scene(name="d", fidelity="dem"))


def test_scene_rejects_unknown_options():
    with pytest.raises(SceneError, match="unknown scene option"):
        Scene.from_dict({"films": "hamrock_dowson"})


def test_capacitance_off_removes_its_output():
    on = AnalyticModel(scene=Scene())
    off = AnalyticModel(scene=Scene(capacitance=False))
    assert "C_bearing" in {v.name for v in on.outputs}
    assert "C_bearing" not in {v.name for v in off.outputs}
    assert "C_bearing" not in off.evaluate(500.0, 3000.0, 313.15)
    shared = set(off.evaluate(500.0, 3000.0, 313.15))
    assert shared <= set(on.evaluate(500.0, 3000.0, 313.15))


def test_every_catalogue_entry_loads():
    assert {"6208", "6306", "B7214C"} <= set(catalogue("bearings"))
    for name in catalogue("bearings"):
        assert load_bearing(name).Z >= 3
    for name in catalogue("lubricants"):
        assert load_lubricant(name).array.shape == (24,)


def _write(tmp_path, text):
    path = tmp_path / "b.toml"
    path.write_text(text)
    return path


BASE = (
    __import__("pathlib").Path(__file__).resolve().parents[2] / "bearing_fmu" / "params" / "bearings" / "6208.toml"
).read_text()


def _edited_6208_is_refused(tmp_path, old, new, match):
    """The 6208's bearing file with `old` (which it holds) replaced by `new` is refused with a ParameterError
    whose message matches `match`."""
    assert old in BASE
    with pytest.raises(ParameterError, match=match):
        load_bearing(_write(tmp_path, BASE.replace(old, new)))


def test_missing_key_is_named(tmp_path):
    line = 'n_balls             = { value = 9, unit = "-", source = "Guessasma 2018 section 2: Z = 9" }\n'
    _edited_6208_is_refused(tmp_path, line, "", "missing key 'geometry.n_balls'")


def test_out_of_range_value_names_key_and_range(tmp_path):
    _edited_6208_is_refused(
        tmp_path,
        "inner_conformity    = { value = 0.52",
        "inner_conformity    = { value = 0.45",
        r"'geometry.inner_conformity' = 0.45 - is outside the allowed range \]0.5, 1.0\]",
    )


def test_wrong_unit_is_named(tmp_path):
    _edited_6208_is_refused(
        tmp_path,
        'ball_diameter       = { value = 12.6e-3, unit = "m"',
        'ball_diameter       = { value = 12.6e-3, unit = "mm"',
        "'geometry.ball_diameter' has unit 'mm', expected 'm'",
    )


def test_cage_mass_is_shared_by_the_dem_cage_balls(tmp_path):
    """cage.mass (kg, the whole cage) gives each of the Z DEM cage balls m/Z; without it the cage balls are solid
    balls of the cage material (the 6208 of the papers); a non-positive mass is refused with its range."""
    from bearing_fmu.kernels.ball_dynamics import state as s
    from bearing_fmu.models.dem import DemModel

    assert load_bearing("B7214C").cage_mass == 14e-3 and load_bearing("6208").cage_mass == 0.0
    assert DemModel("B7214C", "iso_vg68_mineral").par[s.P_M_CAGE] == pytest.approx(14e-3 / 17, rel=1e-15)
    solid = 1140.0 * 4.0 / 3.0 * math.pi * 4.19e-3**3  # PA66, R_z of Guessasma 2018 Table 1
    assert DemModel("6208", "guessasma_oil").par[s.P_M_CAGE] == pytest.approx(solid, rel=1e-12)
    _edited_6208_is_refused(
        tmp_path,
        "[cage]\n",
        '[cage]\nmass = { value = 0.0, unit = "kg", source = "test" }\n',
        r"'cage.mass' = 0.0 kg is outside the allowed range \]0.0, 1000.0\]",
    )


def _numeric(name="6208", **changes):
    """The bearing_data.* values of a catalogue bearing with `changes` (short names: Ra_inner, Z, ...)."""
    from bearing_fmu.models.file_parameters import B, bearing_values

    values = bearing_values(name)
    values.update({B + key: value for key, value in changes.items()})
    return values


@pytest.mark.parametrize("race", ["inner", "outer"])
def test_a_race_without_composite_roughness_is_refused_by_every_fidelity(tmp_path, race):
    """Lambda = h_min / sigma needs sigma = 1.25 sqrt(Ra_race^2 + Ra_ball^2) > 0 on each race: the 6208 (ball_Ra 0)
    with a race's Ra 0 is refused by the bearing file's reader, as a file and as the FMU's numeric parameters (named
    as such), and by each facade given such a Bearing made by hand (unchecked, the DEM would report Lambda = inf, or
    shrink its step without end); the B7214C, whose balls are rough, takes a smooth race."""
    from dataclasses import replace

    from bearing_fmu.models.dem import DemModel
    from bearing_fmu.models.file_parameters import bearing_from_values
    from bearing_fmu.models.quasi_static import QuasiStaticModel

    key = f"Ra_{race}"
    allowed = rf"\(allowed: bearing_data.{key} in \]0, 0.0001\] m, or bearing_data.Ra_ball in \]0, 0.0001\] m\)"
    with pytest.raises(
        ParameterError, match=rf"bearing_data.{key} = 0.0 m and bearing_data.Ra_ball = 0.0 m .*{allowed}"
    ):
        bearing_from_values(_numeric(**{key: 0.0}))
    _edited_6208_is_refused(
        tmp_path,
        f"{race}_race_Ra = {{ value = 0.3e-6",
        f"{race}_race_Ra = {{ value = 0.0",
        rf"'surface.{race}_race_Ra' = 0.0 m and 'surface.ball_Ra' = 0.0 m",
    )
    smooth = replace(load_bearing("6208"), **{key: 0.0})
    for facade in (AnalyticModel, QuasiStaticModel, DemModel):
        with pytest.raises(ParameterError, match=rf"'surface.{race}_race_Ra' = 0.0 m"):
            facade(smooth, "guessasma_oil")
    assert bearing_from_values(_numeric("B7214C", **{key: 0.0})).Ra_ball > 0.0


def test_cage_balls_that_overlap_the_balls_are_refused_naming_z_and_the_radius():
    """The 6208's cage balls (R_z = 4.19 mm) fit between its 9 balls: d_m sin(pi / 18) - D/2 = 4.223 mm. With 10
    balls only 3.180 mm fits (overlapping cage balls would push the balls: 2.3 kN on an outer contact under 1 kN);
    with 15, 34 um. Either is refused naming Z and the radius with what fits; a radius that fits, or none (the DEM's
    estimate from the pockets), is taken."""
    from bearing_fmu.kernels.ball_dynamics import state as s
    from bearing_fmu.models.dem import DemModel
    from bearing_fmu.models.file_parameters import bearing_from_values
    from bearing_fmu.params import cage_ball_room

    assert cage_ball_room(12.6e-3, 60.6e-3, 9) == pytest.approx(4.2231e-3, abs=1e-7)
    for Z, room in ((10, "0.00317993"), (15, "3.44249e-05")):
        with pytest.raises(
            ParameterError,
            match=rf"bearing_data.cage_ball_radius = 0.00419 m and bearing_data.Z = {Z} overlap: .* at most {room} m",
        ):
            bearing_from_values(_numeric(Z=Z))
    assert bearing_from_values(_numeric(Z=10, cage_ball_radius=3.1e-3)).cage_ball_radius == 3.1e-3
    estimated = DemModel(bearing_from_values(_numeric(Z=10, cage_ball_radius=0.0)), "guessasma_oil")
    assert 0.0 < estimated.par[s.P_R_CAGE] < cage_ball_room(12.6e-3, 60.6e-3, 10)


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"bore": 0.048}, r"bearing_data.bore = 0.048 m leaves the inner ring no material under its groove: allowed "
         r"below the inner groove bottom d_m - D - max\(P_d, 0\)/2 = 0.048 m"),
        ({"outer_diameter": 0.07}, r"bearing_data.outer_diameter = 0.07 m leaves the outer ring no material under its "
         r"groove: allowed above the outer groove bottom d_m \+ D \+ max\(P_d, 0\)/2 = 0.0732 m"),
        ({"bore": 0.09, "outer_diameter": 0.08}, r"bearing_data.bore = 0.09 m leaves the inner ring"),
        ({"width": 0.01}, r"bearing_data.width = 0.01 m is narrower than the inner ring's groove between its lands: "
         r"allowed from 0.0103289 m"),
    ],
)  # fmt: skip
def test_ring_sections_and_width_are_checked_for_every_fidelity(tmp_path, changes, message):
    """Each ring keeps material under its groove (bore below d_m - D, outer diameter above d_m + D, so the bore is
    below the outer diameter) and is as wide as its groove between the lands the shoulder truncation uses (the
    6208's estimated lands 53.04 mm, 0.2 D above the groove bottom: 2 sqrt(h (2 f D - h)) = 10.33 mm): the numeric
    parameters and a file are refused naming the value and the allowed bound, by the reader every fidelity uses;
    the catalogue's dimensions are taken."""
    from bearing_fmu.models.dem import DemModel
    from bearing_fmu.models.file_parameters import bearing_from_values
    from bearing_fmu.models.quasi_static import QuasiStaticModel

    with pytest.raises(ParameterError, match=message):
        bearing_from_values(_numeric(**changes))
    text = BASE
    for key, value in changes.items():
        line = next(line for line in BASE.splitlines() if line.startswith(key + " "))
        text = text.replace(line, f'{key} = {{ value = {value!r}, unit = "m", source = "test" }}')
    path = _write(tmp_path, text)
    for facade in (AnalyticModel, QuasiStaticModel, DemModel):
        with pytest.raises(ParameterError, match=rf"'geometry.{next(iter(changes))}' = "):
            facade(path, "guessasma_oil")
    for name in catalogue("bearings"):
        b = bearing_from_values(_numeric(name))
        assert b.bore < b.dm - b.D and b.outer_diameter > b.dm + b.D


def test_unknown_catalogue_name_lists_choices():
    with pytest.raises(ParameterError, match="unknown bearing 'xyz'.*6208"):
        load_bearing("xyz")


def test_analytic_fidelity_refuses_angular_contact():
    with pytest.raises(InputError, match="deep-groove"):
        AnalyticModel("B7214C", "iso_vg68_mineral")


@pytest.mark.parametrize(
    "omega, F_y, T_oil, word",
    [
        (math.nan, 100.0, 313.0, "omega"),
        (1e6, 100.0, 313.0, "omega"),
        (10.0, math.inf, 313.0, "F_y"),
        (10.0, 100.0, 0.0, "T_oil"),
        (10.0, 100.0, math.nan, "T_oil"),
        (10.0, 1e8, 313.0, "material limit"),
    ],
)
def test_bad_inputs_name_input_and_range(omega, F_y, T_oil, word):
    with pytest.raises(InputError, match=word):
        AnalyticModel().evaluate(omega, F_y, T_oil)


def test_overload_warning_above_iso76_limit():
    m = AnalyticModel()
    out = m.evaluate(100.0, 40000.0, 313.15)
    assert 4.2e9 < out["p_max"] <= 6e9
    assert m.warnings and "ISO 76" in m.warnings[0]


@pytest.mark.parametrize("omega, F_y", [(0.0, 0.0), (0.0, 3000.0), (1e-9, 1e-9), (-500.0, 3000.0), (6900.0, 100.0)])
@pytest.mark.parametrize("Pd", [-50e-6, 0.0, 50e-6])
def test_edge_inputs_give_finite_outputs(omega, F_y, Pd):
    """Zero speed (no film: Lambda = 0, boundary), zero load with clearance/preload, reversal and the
    speed limit all give finite outputs (never a silent NaN)."""
    out = AnalyticModel(Pd=Pd).evaluate(omega, F_y, 313.15)
    assert all(math.isfinite(v) for v in out.values())
    if omega == 0.0:
        assert out["Lambda_inner"] == 0.0 and out["Lambda_outer"] == 0.0 and out["regime"] == 0


# A file given for the wrong parameter, or a path that is no file, is named as such (not "missing key" or
# "unknown bearing"): the message names the parameter, the value and the kind of file it is.
BEARING_FILE = "bearing_fmu/params/bearings/B7214C.toml"
LUBRICANT_FILE = "bearing_fmu/params/lubricants/iso_vg68_mineral.toml"
SPINDLE_FILE = "spindle/thermal/params/b7214c_x_pair.toml"


@pytest.mark.parametrize(
    ("loader", "given", "message"),
    [
        ("bearing", LUBRICANT_FILE, "bearing = '.*iso_vg68_mineral.toml' is a lubricant file, not a bearing file"),
        ("bearing", SPINDLE_FILE, "bearing = '.*b7214c_x_pair.toml' is a spindle network file, not a bearing file"),
        ("lubricant", BEARING_FILE, "lubricant = '.*B7214C.toml' is a bearing file, not a lubricant file"),
        ("spindle", BEARING_FILE, "spindle = '.*B7214C.toml' is a bearing file, not a spindle network file"),
        ("spindle", LUBRICANT_FILE, "spindle = '.*iso_vg68_mineral.toml' is a lubricant file, not a spindle network"),
    ],
)
def test_a_file_of_another_kind_is_named_as_such(loader, given, message):
    from bearing_fmu.params import load_bearing, load_lubricant
    from spindle.thermal.model import load_spindle

    load = {"bearing": load_bearing, "lubricant": load_lubricant, "spindle": load_spindle}[loader]
    with pytest.raises(ParameterError, match=message):
        load(ROOT / given)


@pytest.mark.parametrize("loader", ["bearing", "lubricant", "spindle"])
def test_a_toml_path_that_is_no_file_is_file_not_found(loader, tmp_path):
    from bearing_fmu.params import load_bearing, load_lubricant
    from spindle.thermal.model import load_spindle

    load = {"bearing": load_bearing, "lubricant": load_lubricant, "spindle": load_spindle}[loader]
    missing = tmp_path / "my_set.toml"
    with pytest.raises(ParameterError, match=f"^{loader} = '{missing}': file not found"):
        load(missing)
    folder = tmp_path / "a_folder.toml"
    folder.mkdir()
    with pytest.raises(ParameterError, match=f"^{loader} = '{folder}': is not a file"):
        load(folder)
